# SPDX-License-Identifier: MIT
"""The table emitter: exact round trip through the generated C (float32 and
16-bit payloads, fields, provenance strings), reproducibility, the format check,
and that the generated C compiles under the runtime's strict flags in both
precisions and under every compile-time option (a table is left out at link
time, not by the preprocessor)."""

import copy
import json
import math
import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
sys.path.insert(0, ROOT)

from bake.earthshine import grid  # noqa: E402
from bake.earthshine import table as emit  # noqa: E402
from bake.common import emit as cemit  # noqa: E402

WARN = ["-std=c99", "-Wall", "-Wextra", "-Wpedantic", "-Wconversion", "-Wshadow",
        "-Wdouble-promotion", "-Werror"]


def _meta(spec, q, psi):
    return {
        "name": "oi_earth_testtab", "description": "", "generator_version": "test",
        "format": emit.TABLE_FORMAT, "method": "quadrature", "method_detail": "",
        "parameters": {}, "grid": dict(spec.as_dict(), n_values=spec.n_values),
        "h_min_km": 100.0, "h_max_km": math.inf, "radius_km": 6378.137, "rel_goal": 1e-3,
        "measured": {"reference_order": 32, "n_points": 1, "seed": 1, "max_rel_err": 1e-4,
                     "max_abs_err_frac": 1e-6, "max_score": 0.1, "max_psi_err_rad": 1e-4},
        "payload_bytes": spec.bytes(),
    }


@pytest.fixture
def table():
    rng = np.random.default_rng(3)
    spec = grid.TableSpec(4, 5, 3, 0.2, math.pi / 2)
    # awkward values: tiny, huge, subnormal, exact zero, negative zero, integers
    q = rng.lognormal(0, 5, (3, 9))
    q.flat[:6] = [0.0, -0.0, 1.0, 2.0, 1e-40, 3.0e38]
    psi = rng.uniform(0, 1.4, (3, 9))
    return spec, q, psi


def test_round_trip_exact(table):
    spec, q, psi = table
    c, h, j = emit.render("oi_earth_testtab", spec, q, psi, _meta(spec, q, psi))
    p = cemit.parse_c(c)
    np.testing.assert_array_equal(p["arrays"]["oi_earth_testtab_q"], emit.f32(q).ravel())
    np.testing.assert_array_equal(p["arrays"]["oi_earth_testtab_psi"], emit.f32(psi).ravel())
    f = p["structs"]["oi_earth_testtab"]["fields"]
    assert p["structs"]["oi_earth_testtab"]["type"] == "oi_earth_table"
    assert (f["n_lit"], f["n_term"], f["n_alt"]) == (4, 5, 3)
    assert f["w_max"] == math.pi / 2
    assert f["w_min"] == 0.2
    assert f["term_k0"] == spec.term_k0
    assert f["term_kp"] == spec.term_kp
    assert f["kind"] == "OI_TABLE_KIND_EARTHSHINE"
    assert f["info"] == "&oi_earth_testtab_info"
    info = p["structs"]["oi_earth_testtab_info"]["fields"]
    side = json.loads(j)
    assert info["name"] == side["name"] == "oi_earth_testtab"
    assert json.loads(info["parameters"]) == side["parameters"]
    assert info["payload_sha256"] == side["payload_sha256"] == emit.payload_sha256(q, psi)
    assert info["seed"] == side["seed"] == 1
    assert info["max_error"] == side["max_error"] == 0.1
    assert info["goal"] == side["goal"] == 1e-3
    assert info["generator"] == "%s %s" % (side["generator"], side["generator_version"])
    assert "#if OI_TABLE_FORMAT != %d" % emit.TABLE_FORMAT in c
    assert "extern const oi_earth_table oi_earth_testtab;" in h


def test_u16_payload_and_strings():
    """A 16-bit payload, oi_real fields and awkward strings survive the round trip."""
    codes = np.array([0, 1, 65535, 1234, 7], dtype=np.uint16)
    params = {"quote": 'a "b" \\ c', "long": "x" * 200, "n": 3, "f": 0.1}
    t = cemit.Table(
        name="oi_atm_testtab", kind="atmosphere", ctype="oi_atm_table",
        format=("OI_ATM_FORMAT", 3), summary="test table.",
        fields=[("nz", 1, "int"), ("z_min_km", 0.1, "real")],
        arrays=[("q", codes, "u16"), ("psi", codes[::-1], "u16")],
        layout=("format", "kind", "info", "nz", "z_min_km", "q", "psi"),
        generator="test", version="0", parameters=params, seed=5, goal=1e-2, max_error=0.5,
        measured={}, grid={}, provenance=["line"])
    c, h, j = cemit.render(t)
    p = cemit.parse_c(c)
    np.testing.assert_array_equal(p["arrays"]["oi_atm_testtab_q"], codes)
    np.testing.assert_array_equal(p["arrays"]["oi_atm_testtab_psi"], codes[::-1])
    f = p["structs"]["oi_atm_testtab"]["fields"]
    assert f["z_min_km"] == 0.1 and f["nz"] == 1
    info = p["structs"]["oi_atm_testtab_info"]["fields"]
    assert json.loads(info["parameters"]) == params
    assert [a.tolist() for _, a in cemit.payload_of(p, "oi_atm_testtab")] == [
        codes.tolist(), codes[::-1].tolist()]
    bad = copy.copy(t)
    bad.arrays = [("q", np.array([70000]), "u16")]
    with pytest.raises(ValueError):
        cemit.render(bad)


def test_c_float_literals():
    for v in (0.0, 1.0, 2.0, 1e-40, 3.4e38, 0.1, 1.0 / 3.0):
        s = emit.c_float(np.float32(v))
        assert s.endswith("f") and ("." in s or "e" in s)
        assert np.float32(float(s[:-1])) == np.float32(v)
    with pytest.raises(ValueError):
        emit.c_float(float("nan"))


def test_reproducible(table):
    spec, q, psi = table
    a = emit.render("oi_earth_testtab", spec, q, psi, _meta(spec, q, psi))
    b = emit.render("oi_earth_testtab", spec, q.copy(), psi.copy(), _meta(spec, q, psi))
    assert a == b


def test_rejects_nonfinite(table):
    spec, q, psi = table
    q = q.copy()
    q[0, 0] = np.nan
    with pytest.raises(ValueError):
        emit.render("oi_earth_testtab", spec, q, psi, _meta(spec, q, psi))


@pytest.mark.skipif(shutil.which("cc") is None, reason="no C compiler")
def test_generated_c_compiles(table, tmp_path):
    spec, q, psi = table
    emit.write(str(tmp_path), "oi_earth_testtab", spec, q, psi, _meta(spec, q, psi))
    src = str(tmp_path / "oi_earth_testtab.c")
    inc = ["-I" + os.path.join(ROOT, "include"), "-I" + str(tmp_path)]
    for defs in ([], ["-DOI_SINGLE_PRECISION"]):
        obj = str(tmp_path / "t.o")
        subprocess.run(["cc"] + WARN + inc + defs + ["-c", src, "-o", obj], check=True)
        out = subprocess.run(["nm", obj], capture_output=True, text=True, check=True).stdout
        assert "oi_earth_testtab" in out
    # a table is the same under every option: programs leave it out at link time
    for opt in ("-DOI_NO_EARTH_TABLE", "-DOI_NO_ATMOSPHERE"):
        obj = str(tmp_path / "opt.o")
        subprocess.run(["cc"] + WARN + inc + [opt, "-c", src, "-o", obj], check=True)
        out = subprocess.run(["nm", obj], capture_output=True, text=True, check=True).stdout
        assert "oi_earth_testtab_info" in out
    # a table of another format refuses to compile
    (tmp_path / "oi_earth_testtab.c").write_text((tmp_path / "oi_earth_testtab.c").read_text().replace(
        "OI_TABLE_FORMAT != %d" % emit.TABLE_FORMAT, "OI_TABLE_FORMAT != 999"))
    r = subprocess.run(["cc"] + WARN + inc + ["-c", src, "-o", obj], capture_output=True, text=True)
    assert r.returncode != 0 and "regenerate" in r.stderr
