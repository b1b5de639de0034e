# SPDX-License-Identifier: MIT
"""The catalogue planner (python -m orbillum.catalog): element sets, the synthetic
catalogue, the frame, rows equal to build/oi-plan --csv, the same bits whatever
the partitioning, and its command line."""
import io
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.csv as pa_csv
import pyarrow.parquet as pq
import pytest
from sgp4.api import WGS72, Satrec

from orbillum.catalog import block, plan, sky, synthetic, tle

ROOT = Path(__file__).resolve().parents[2]
PLAN = Path(os.environ.get("OI_PLAN", ROOT / "build" / "oi-plan"))
VALLADO = ROOT / "examples" / "scenarios" / "cases" / "vallado2006.tle"
START, STOP = "2026-12-01T00:00:00", "2026-12-01T03:00:00"

OBSERVERS = [
    {"name": "inspector-leo", "epoch": "2026-12-01T00:00:00", "a_km": 6978.0, "ecc": 0.001,
     "incl_deg": 53.0, "raan_deg": 10.0, "argp_deg": 0.0, "mo_deg": 0.0},
    {"name": "inspector-geo", "epoch": "2026-12-01T00:00:00", "a_km": 42164.0, "ecc": 0.0,
     "incl_deg": 0.05, "raan_deg": 0.0, "argp_deg": 0.0, "mo_deg": 100.0},
]


def observers():
    return [tle.from_elements(el, 99000 + i) for i, el in enumerate(OBSERVERS)]


# ------------------------------------------------------------ element sets


def test_checksum_of_published_sets():
    """The modulo-10 checksum reproduces column 69 of published element sets."""
    sets = tle.read(str(VALLADO))
    assert len(sets) >= 3
    for s in sets:
        for ln in (s.line1, s.line2):
            assert tle.checksum(ln) == int(ln[68])


def test_format_set_reads_back_through_sgp4():
    s = tle.format_set("X", 25544, 2026, 335.25, 51.6416, 123.4, 0.0006703, 130.5, 325.0,
                       15.72125391, -3.468e-5)
    sat = Satrec.twoline2rv(s.line1, s.line2, WGS72)
    assert sat.error == 0 and sat.satnum == 25544
    assert math.degrees(sat.inclo) == pytest.approx(51.6416, abs=1e-12)
    assert sat.ecco == pytest.approx(0.0006703, abs=1e-15)
    assert sat.bstar == pytest.approx(-3.468e-5, rel=1e-12)
    assert sat.no_kozai * 1440 / (2 * math.pi) == pytest.approx(15.72125391, abs=1e-12)
    assert (sat.epochyr, sat.epochdays) == (26, pytest.approx(335.25, abs=1e-12))
    assert tle.parse(f"0 X\n{s.line1}\n{s.line2}\n") == [s]


@pytest.mark.parametrize("text, words", [
    ("1 00001U 00000A   26335.00000000  .00000000  00000-0  10487-4 0  9994\n", "without a line 2"),
    ("2 00001  43.0000  25.9269 0000783  55.1353 247.1405 15.03332451    14\n", "without a line 1"),
    ("1 00001U 00000A   26335.00000000  .00000000  00000-0  10487-4 0  9995\n"
     "2 00001  43.0000  25.9269 0000783  55.1353 247.1405 15.03332451    14\n", "checksum"),
    ("1 00001U 00000A   26335.00000000  .00000000  00000-0  10487-4 0  9994\n"
     "2 00002  43.0000  25.9269 0000783  55.1353 247.1405 15.03332451    15\n", "differ"),
    ("1 00001U 00000A\n2 00001  43.0000\n", "too short"),
])
def test_bad_catalogue_text_is_named(text, words):
    with pytest.raises(tle.CatalogueError, match=words):
        tle.parse(text, "cat.3le")


def test_elements_rejected_with_their_name():
    with pytest.raises(tle.CatalogueError, match="a_km = 6000"):
        tle.from_elements(dict(OBSERVERS[0], a_km=6000.0), 1)
    with pytest.raises(tle.CatalogueError, match="missing 'ecc'"):
        tle.from_elements({k: v for k, v in OBSERVERS[0].items() if k != "ecc"}, 1)
    with pytest.raises(tle.CatalogueError, match="unknown key"):
        tle.from_elements(dict(OBSERVERS[0], sma=7000.0), 1)


# --------------------------------------------------------- synthetic catalogue


def test_synthetic_is_seeded_and_propagates_for_a_week():
    a = synthetic.generate(3000, seed=5)
    assert a == synthetic.generate(3000, seed=5)
    assert a != synthetic.generate(3000, seed=6)
    t = sky.epochs("2026-12-01T00:00:00", "2026-12-08T00:00:00", 6 * 3600.0)
    r, _v, err = sky.propagate(sky.satrecs(a), t.utc.jd1, t.utc.jd2, sky.teme_to_gcrs(t))
    assert not err.any()
    radius = np.linalg.norm(r, axis=2)
    assert radius.min() > 6378.0 + 150.0
    cls = np.array([s.name.split()[0][4:] for s in a])
    for c, share in synthetic.SHARES.items():
        # binomial: 4 standard deviations
        sd = math.sqrt(share * (1 - share) / len(a))
        assert abs(np.mean(cls == c) - share) < 4 * sd, c
    geo = radius[cls == "GEO"]
    assert np.all(np.abs(geo - 42164.0) < 1000.0)


def test_sun_synchronous_inclination_matches_published_values():
    """J2 sun-synchronous inclination (Vallado, Fundamentals of Astrodynamics,
    sun-synchronous orbits): 97.4 deg at 500 km, 98.6 deg at 800 km."""
    assert synthetic._sso_incl_deg(np.array(6378.135 + 500.0)) == pytest.approx(97.4, abs=0.05)
    assert synthetic._sso_incl_deg(np.array(6378.135 + 800.0)) == pytest.approx(98.6, abs=0.05)


# ------------------------------------------------------------------ frame


def test_rotation_equals_astropy_transform():
    """TEME -> GCRS as one matrix per epoch equals astropy's per-point transform
    (the scenario generator's) to rounding."""
    sys.path.insert(0, str(ROOT))
    from examples.scenarios import scenario
    sets = tle.read(str(VALLADO))
    t = sky.epochs("2006-06-25T16:00:00", "2006-06-25T18:00:00", 600.0)
    rot = sky.teme_to_gcrs(t)
    assert np.abs(np.einsum("nij,nkj->nik", rot, rot) - np.eye(3)).max() < 1e-15
    r, _v, err = sky.propagate(sky.satrecs(sets), t.utc.jd1, t.utc.jd2, rot)
    for i, s in enumerate(sets):
        ref = scenario.propagate_gcrs(Satrec.twoline2rv(s.line1, s.line2, WGS72), t)
        assert np.abs(r[i] - ref).max() < 1e-8  # km
    sun, moon = sky.bodies(t)
    assert np.array_equal(sun, scenario.body_gcrs("sun", t))
    assert np.array_equal(moon, scenario.body_gcrs("moon", t))


# --------------------------------------------------- rows, partitioning, oi-plan


def _run(objects_per_block, **kw):
    sets = synthetic.generate(40, seed=11)
    s, tables = plan.plan(sets, observers(), START, STOP, 120.0, keep=True,
                          objects_per_block=objects_per_block, progress=False, **kw)
    return s, pa.concat_tables(tables)


def test_same_bits_whatever_the_partitioning():
    s1, whole = _run(40, all_rows=True)
    assert s1.blocks == 1 and whole.num_rows == 40 * 2 * 91
    for per in (1, 7):
        s, t = _run(per, all_rows=True)
        assert s.blocks == math.ceil(40 / per)
        assert t.equals(whole)
    # the visible rows are the all-rows table filtered
    _, vis = _run(7)
    assert vis.equals(whole.filter(whole["visible"]))
    assert 0 < vis.num_rows < whole.num_rows


def test_rows_order_and_visibility_rule():
    _, t = _run(40, all_rows=True)
    d = t.to_pydict()
    key = list(zip(d["object_id"], d["observer"], d["epoch"]))
    obs_rank = {o["name"]: i for i, o in enumerate(OBSERVERS)}
    assert key == sorted(key, key=lambda k: (k[0], obs_rank[k[1]], k[2]))
    mask = np.array(d["flags_mask"])
    vis = np.array(d["visible"])
    expect = ((mask & (64 | 1)) == 0) & (np.array(d["range_km"]) <= 10000.0) & \
        np.array([s.startswith(("OK", "WARN")) for s in d["status"]])
    assert np.array_equal(vis, expect)


def test_rows_equal_the_planner(tmp_path):
    """A sample of rows, fed to build/oi-plan --csv with the scene's vectors the
    catalogue planner used, gives the same numbers, status and flags."""
    _, t = _run(40, all_rows=True, positions=True, camera="telescope-15cm")
    rng = np.random.default_rng(3)
    idx = np.sort(rng.choice(t.num_rows, size=300, replace=False))
    # every visible row too, so the observer's numbers are compared where they matter
    idx = np.union1d(idx, np.nonzero(t["visible"].to_numpy())[0][:300])
    sample = t.take(pa.array(idx))
    cols = ["id"] + list(block.POSITIONS)
    inp = pa.table([pa.array([str(i) for i in range(sample.num_rows)])] +
                   [sample[c] for c in block.POSITIONS], names=cols)
    src = tmp_path / "in.csv"
    buf = io.BytesIO()
    pa_csv.write_csv(inp, buf, pa_csv.WriteOptions(quoting_style="none"))
    src.write_bytes(buf.getvalue())
    r = subprocess.run([str(PLAN), "--csv", str(src), "--camera", "telescope-15cm"],
                       capture_output=True, text=True, check=False)
    assert r.returncode in (0, 1), r.stderr
    lines = r.stdout.splitlines()
    header = lines[0].split(",")
    assert len(lines) == sample.num_rows + 1
    d = sample.to_pydict()
    for k, line in enumerate(lines[1:]):
        f = dict(zip(header, line.split(",")))
        assert f["status"] == d["status"][k]
        assert f["flags"] == d["flags"][k]
        for name in block.NUMBERS:
            assert float(f[name]) == d[name][k], (name, k)


def test_sgp4_failure_rows_are_marked_not_nan():
    """An object that decays within the span: its rows say ERR_SGP4 with zero numbers."""
    s = tle.format_set("DECAYING", 1, 2026, 335.0, 51.6, 0.0, 0.0, 0.0, 0.0, 16.4, 0.05)
    summary, tables = plan.plan([s], observers()[:1], START, "2026-12-03T00:00:00", 3600.0,
                                all_rows=True, keep=True, progress=False)
    t = pa.concat_tables(tables).to_pydict()
    failed = [i for i, st in enumerate(t["status"]) if st == block.STATUS_SGP4]
    assert failed and summary.sgp4_failures == len(failed)
    for name in block.NUMBERS + ("range_km",):
        col = np.array(t[name])
        assert np.all(np.isfinite(col)) and np.all(col[failed] == 0.0)
    assert not any(t["visible"][i] for i in failed)


def test_files_hold_the_rows(tmp_path):
    pqf, csvf = tmp_path / "p.parquet", tmp_path / "p.csv"
    _, t = _run(9)
    plan.plan(synthetic.generate(40, seed=11), observers(), START, STOP, 120.0,
              objects_per_block=13, parquet=str(pqf), csv=str(csvf), progress=False)
    assert pq.read_table(pqf).equals(t)
    back = pa_csv.read_csv(csvf)
    for name in block.NUMBERS:  # the CSV numbers read back to the same doubles
        assert np.array_equal(back[name].to_numpy(), t[name].to_numpy())


# --------------------------------------------------------------- command line


def _cli(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "orbillum.catalog", *args],
                          capture_output=True, text=True, check=False, cwd=cwd)


def test_command_line_runs_and_reports(tmp_path):
    obs = tmp_path / "obs.json"
    import json
    obs.write_text(json.dumps(OBSERVERS))
    out = tmp_path / "plan.parquet"
    r = _cli("--synthetic", "40", "--seed", "11", "--observer-elements", str(obs),
             "--start", START, "--stop", STOP, "--step", "120", "-o", str(out))
    assert r.returncode == 0, r.stderr
    assert "scenes per CPU-second" in r.stderr
    _, t = _run(None)
    got = pq.read_table(out)
    assert got.equals(t)


@pytest.mark.parametrize("extra, words", [
    (["--step", "0"], "step must be"),
    (["--camera", "no-such-camera"], "no built-in camera"),
    (["--workers", "2", "--scheduler", "tcp://127.0.0.1:1"], "--scheduler and --workers"),
    (["--csv", "/no/such/folder/x.csv"], "does not exist"),
    (["--max-range-km", "-1"], "max range"),
])
def test_command_line_refuses_bad_input(tmp_path, extra, words):
    sets = tmp_path / "cat.3le"
    with open(sets, "w") as f:
        tle.write(synthetic.generate(3, seed=1), f)
    args = [str(sets), "--observers", str(sets), "--start", START, "--stop", STOP]
    if "--csv" not in extra:
        args += ["-o", str(tmp_path / "x.parquet")]
    r = _cli(*args, *extra)
    assert r.returncode == 2 and words in r.stderr, r.stderr
