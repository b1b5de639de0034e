# SPDX-License-Identifier: MIT
"""The table emitter: exact float32 round trip through the generated C,
reproducibility, the format check, and that the generated C compiles under the
runtime's strict flags in both precisions and to nothing with OI_NO_EARTH_TABLE."""

import math
import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
sys.path.insert(0, ROOT)

from bake import emit, grid  # noqa: E402

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
        "sha256": emit.payload_sha256(q, psi), "payload_bytes": spec.bytes(),
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
    p = emit.parse_c(c, h)
    np.testing.assert_array_equal(p["arrays"]["oi_earth_testtab_q"], emit.f32(q).ravel())
    np.testing.assert_array_equal(p["arrays"]["oi_earth_testtab_psi"], emit.f32(psi).ravel())
    assert p["defines"]["OI_EARTH_TESTTAB_N_ALT"] == 3
    assert float(p["fields"]["w_max"]) == math.pi / 2
    assert float(p["fields"]["w_min"]) == 0.2
    assert float(p["fields"]["term_k0"]) == spec.term_k0
    assert float(p["fields"]["term_kp"]) == spec.term_kp
    assert "#if OI_TABLE_FORMAT != %d" % emit.TABLE_FORMAT in h


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
    obj = str(tmp_path / "none.o")
    subprocess.run(["cc"] + WARN + inc + ["-DOI_NO_EARTH_TABLE", "-c", src, "-o", obj], check=True)
    out = subprocess.run(["nm", obj], capture_output=True, text=True, check=True).stdout
    assert out.strip() == ""
    # a header of another format refuses to compile
    hdr = (tmp_path / "oi_earth_testtab.h").read_text()
    (tmp_path / "oi_earth_testtab.h").write_text(
        hdr.replace("OI_TABLE_FORMAT != %d" % emit.TABLE_FORMAT, "OI_TABLE_FORMAT != 999"))
    r = subprocess.run(["cc"] + WARN + inc + ["-c", src, "-o", obj], capture_output=True, text=True)
    assert r.returncode != 0 and "regenerate" in r.stderr
