# SPDX-License-Identifier: MIT
"""The planner's albedo models (build/oi-plan --csv, docs/planner.md): the
columns albedo_model, epoch_jd, earth_rotation_deg and --albedo-map FILE.

e_earth of a knocke row is checked against the Knocke field's value under a
10 m high target (a cap 0.1 degree wide: the weighted mean is the value
under it), written out here; a map of one value against the uniform row's
closed-form albedo ratio; bad map files against the exit code 2 and the
file and line named.
"""
import csv
import io
import math
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PLAN = Path(os.environ.get("OI_PLAN", ROOT / "build" / "oi-plan"))
R_E = 6378.137
AU = 149597870.7
COLS = "id,sun_x,sun_y,sun_z,target_x,target_y,target_z"


def run(args, stdin):
    assert PLAN.exists(), f"{PLAN} is not built (make all)"
    p = subprocess.run([str(PLAN)] + list(args), input=stdin.encode(), capture_output=True,
                       timeout=60)
    return p.returncode, p.stdout.decode(), p.stderr.decode()


def rows(text):
    return {r["id"]: r for r in csv.DictReader(io.StringIO(text))}


def knocke(sin_lat, jd):
    a1 = 0.10 * math.cos(2 * math.pi * (jd - 2444960.5) / 365.25)
    return 0.34 + a1 * sin_lat + 0.29 * 0.5 * (3 * sin_lat ** 2 - 1)


def test_knocke_rows_follow_the_field():
    lat = math.radians(50.0)
    r = R_E + 0.01
    tx, tz = r * math.cos(lat), r * math.sin(lat)
    sun = (AU * math.cos(lat + 0.2), 0.0, AU * math.sin(lat + 0.2))
    lines = [COLS + ",albedo_model,epoch_jd,earth_albedo"]
    for i, jd in enumerate((2451545.0, 2451545.0 + 182.6)):
        lines.append(f"k{i},{sun[0]!r},{sun[1]!r},{sun[2]!r},{tx!r},0,{tz!r},knocke,{jd!r},")
        lines.append(f"u{i},{sun[0]!r},{sun[1]!r},{sun[2]!r},{tx!r},0,{tz!r},uniform,,0.5")
    rc, out, err = run(["--csv", "-"], "\n".join(lines) + "\n")
    assert rc == 0, err
    got = rows(out)
    for i, jd in enumerate((2451545.0, 2451545.0 + 182.6)):
        ratio = float(got[f"k{i}"]["e_earth"]) / float(got[f"u{i}"]["e_earth"]) * 0.5
        assert ratio == pytest.approx(knocke(math.sin(lat), jd), abs=2e-5)
    # the seasons move it: northern winter (t0 + 0) brighter than summer
    assert float(got["k0"]["e_earth"]) != float(got["k1"]["e_earth"])


def test_map_of_one_value_is_uniform(tmp_path):
    path = tmp_path / "map.txt"
    path.write_text("# one value\n3 6\n" + "0.25 0.25 0.25 0.25 0.25 0.25\n" * 3)
    lines = [COLS + ",albedo_model,epoch_jd,earth_rotation_deg,earth_albedo",
             f"m,{AU!r},0,0,0,7000,0,map,2451545,123.4,",
             f"u,{AU!r},0,0,0,7000,0,,,,0.25"]
    rc, out, err = run(["--csv", "-", "--albedo-map", str(path)], "\n".join(lines) + "\n")
    assert rc == 0, err
    got = rows(out)
    assert got["m"]["e_earth"] == got["u"]["e_earth"]  # 0.25 is exact in float


def test_uniform_is_the_default():
    base = f"u,{AU!r},0,0,0,7000,0"
    rc1, out1, _ = run(["--csv", "-"], COLS + "\n" + base + "\n")
    rc2, out2, _ = run(["--csv", "-"], COLS + ",albedo_model,epoch_jd\n" + base + ",uniform,\n")
    assert rc1 == rc2 == 0
    assert out1 == out2


@pytest.mark.parametrize("text,line,what", [
    ("2 x\n", 1, "bad n_lon"),
    ("# c\n\n2 3\n0.1 0.2 0.3\n0.1 0.2\n", 5, "too few values"),
    ("2 3\n0.1 0.2 0.3\n0.1 0.2 nan\n", 3, "albedo outside [0, 1]"),
    ("2 3\n0.1 0.2 0.3\n0.1 -0.2 0.3\n", 3, "albedo outside [0, 1]"),
    ("2 3\n0.1 0.2 0.3\n0.1 0.2 0.3 0.4\n", 3, "more values than n_lon"),
    ("2 3\n0.1 0.2 0.3\n0.1 0.2 0.3\n0.1 0.2 0.3\n", 4, "more rows than n_lat"),
    ("2 3\n0.1 0.2 0.3\n", 2, "ends early"),
    ("2 3\n0.1 0.2 abc\n", 2, "not a number"),
    ("2 3\n0.1 0.2 0x0.8p0\n", 2, "not a number"),
    ("0 3\n", 1, "bad n_lat"),
])
def test_bad_map_file_exits_2_naming_file_and_line(tmp_path, text, line, what):
    path = tmp_path / "bad.txt"
    path.write_text(text)
    rc, out, err = run(["--csv", "-", "--albedo-map", str(path)],
                       COLS + f"\nu,{AU!r},0,0,0,7000,0\n")
    assert rc == 2
    assert f"{path}: line {line}:" in err and what in err, err
    assert out == ""


def test_row_errors():
    lines = [COLS + ",albedo_model,epoch_jd,earth_rotation_deg",
             f"a,{AU!r},0,0,0,7000,0,knocke,,",          # epoch missing
             f"b,{AU!r},0,0,0,7000,0,map,2451545,10",    # no --albedo-map
             f"c,{AU!r},0,0,0,7000,0,lambert,,",         # unknown model
             f"d,{AU!r},0,0,0,7000,0,knocke,1e9,",       # epoch out of range
             f"e,{AU!r},0,0,0,7000,0,knocke,nan,",       # epoch NaN
             f"f,{AU!r},0,0,0,7000,0,knocke,2451545,"]   # fine
    rc, out, err = run(["--csv", "-"], "\n".join(lines) + "\n")
    assert rc == 1
    got = rows(out)
    assert [got[k]["status"] for k in "abcdef"] == [
        "ERR_PARSE", "ERR_PARSE", "ERR_PARSE", "ERR_INPUT", "ERR_NONFINITE", "OK"]
    assert "need epoch_jd" in err and "--albedo-map" in err and "uniform, knocke or map" in err


def test_albedo_map_needs_csv(tmp_path):
    rc, _, err = run(["--albedo-map", str(tmp_path / "x.txt")], "")
    assert rc == 2 and "--albedo-map needs --csv" in err
