# SPDX-License-Identifier: MIT
"""The Python binding against the C planner on the same rows.

build/oi-plan --csv prints every number with %.17g; the binding calls the same
library functions through ctypes, so each printed value must be identical
(string equality of %.17g), row by row, for real scenario rows (the shipped TLE
cases) and for hostile rows (errors per row, the batch goes on).
"""
import csv
import io
import math
import os
import subprocess
import sys

import numpy as np
import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
PLAN = os.path.join(ROOT, "build", "oi-plan")
sys.path.insert(0, ROOT)

orbillum = pytest.importorskip("orbillum", reason="binding not installed: make binding")

RAD_TO_DEG = 180.0 / math.pi  # as the planner's 180.0 / 3.14159265358979323846


def g17(x):
    x = float(x)
    return "%.17g" % (0.0 if x == 0.0 else x)  # the planner prints -0 as 0


def _plan(rows_csv, tmp_path):
    if not os.path.exists(PLAN):
        pytest.fail(f"{PLAN} is missing: run `make all` first")
    p = tmp_path / "in.csv"
    p.write_text(rows_csv)
    r = subprocess.run([PLAN, "--csv", str(p)], capture_output=True, text=True, timeout=60)
    assert r.returncode in (0, 1), r.stderr
    return list(csv.DictReader(io.StringIO(r.stdout))), r.returncode


def _inputs(rows_csv):
    rows = list(csv.DictReader(io.StringIO(rows_csv)))

    def v(name):
        return np.array([[float(r[f"{name}_{a}"]) for a in "xyz"] for r in rows])

    def s(name):
        return np.array([float(r[name]) for r in rows])

    kw = dict(sun=v("sun"), moon=v("moon"), target=v("target"), observer=v("observer"),
              earth_albedo=s("earth_albedo"), target_albedo=s("target_albedo"),
              target_radius_m=s("target_radius_m"))
    if "terms" in rows[0]:
        kw["terms"] = [r["terms"] or "all" for r in rows]
    return rows, kw


def _compare(rows_csv, camera, tmp_path):
    out, rc = _plan(rows_csv, tmp_path)
    rows, kw = _inputs(rows_csv)
    x = orbillum.expose(camera, **kw)
    assert len(out) == len(rows)
    n_ok = 0
    for i, o in enumerate(out):
        assert o["id"] == rows[i]["id"]
        # the planner's row status: the illumination's (warnings included)
        # unless the exposure failed
        st = x["expose_status"][i] if x["expose_status"][i] < 0 else x["status"][i]
        assert o["status"] == orbillum.status_name(st) == x["row_status_name"][i], i
        if st < 0:
            for k in ("sun_fraction", "e_sun", "flux_obs", "mag_v", "snr"):
                assert o[k] in ("", "0"), (i, k, o[k])
            continue
        n_ok += 1
        want = {
            "sun_fraction": x["sun_fraction"][i], "sun_fraction_atm": x["sun_fraction_atm"][i],
            "e_sun": x["e_sun"][i], "e_earth": x["e_earth"][i], "e_moon": x["e_moon"][i],
            "earth_theta_deg": x["earth_theta"][i] * RAD_TO_DEG,
            "earth_h_km": x["earth_h_km"][i], "flux_obs": x["flux_obs"][i],
            "mag_v": x["mag_v"][i], "exposure_s": x["exposure_s"][i], "gain": x["gain"][i],
            "snr": x["snr"][i],
        }
        for k, w in want.items():
            assert o[k] == g17(w), f"row {i} {k}: want {g17(w)} got {o[k]}"
        assert o["flags"] == x["flag_names"][i], (i, o["flags"], x["flag_names"][i])
    return n_ok, rc


@pytest.fixture(scope="module")
def case_rows():
    S = pytest.importorskip("examples.scenarios.scenario")
    out = {}
    for name in S.list_cases():
        sc = S.load_case(name)
        cols = S.build_rows(sc)
        buf = io.StringIO()
        S.write_csv(cols, buf)
        out[name] = (buf.getvalue(), sc.columns.get("camera", "star-tracker"))
    return out


def test_shipped_cases_equal_planner(case_rows, tmp_path):
    total = 0
    for name, (text, cam) in case_rows.items():
        n_ok, rc = _compare(text, cam, tmp_path)
        assert rc == 0, name
        total += n_ok
    assert total > 1000


HEAD = ("id,sun_x,sun_y,sun_z,moon_x,moon_y,moon_z,target_x,target_y,target_z,"
        "observer_x,observer_y,observer_z,earth_albedo,target_albedo,target_radius_m,terms,"
        "camera\n")
SUN = "-1.2e7,1.3e8,5.8e7"
MOON = "3e5,-2e5,1e5"
BAD_ROWS = [
    ("ok", SUN, MOON, "7000,0,0", "7000,5,0", "0.3,0.2,1", "", ""),
    ("nan_target", SUN, MOON, "nan,0,0", "7000,5,0", "0.3,0.2,1", "", ""),
    ("inf_sun", "inf,0,0", MOON, "7000,0,0", "7000,5,0", "0.3,0.2,1", "", ""),
    ("below", SUN, MOON, "6000,0,0", "7000,5,0", "0.3,0.2,1", "", ""),
    ("obs_below", SUN, MOON, "7000,0,0", "100,0,0", "0.3,0.2,1", "", ""),
    ("at_target", SUN, MOON, "7000,0,0", "7000,0,0", "0.3,0.2,1", "", ""),
    ("zero_sun", "0,0,0", MOON, "7000,0,0", "7000,5,0", "0.3,0.2,1", "", ""),
    ("zero_moon", SUN, "0,0,0", "7000,0,0", "7000,5,0", "0.3,0.2,1", "", ""),
    ("albedo", SUN, MOON, "7000,0,0", "7000,5,0", "1.5,0.2,1", "", ""),
    ("tgt_albedo", SUN, MOON, "7000,0,0", "7000,5,0", "0.3,-0.1,1", "", ""),
    ("radius", SUN, MOON, "7000,0,0", "7000,5,0", "0.3,0.2,-1", "", ""),
    ("sun_only", SUN, MOON, "-7000,0,0", "-7000,5,0", "0.3,0.2,1", "sun", ""),
    ("geo_umbra", "1.496e8,0,0", MOON, "-42164,0,0", "-42164,10,0", "0.3,0.2,2",
     "sun+earth", ""),
    ("grazing_warn", SUN, MOON, "6378.2,0,0", "6378.2,0,10", "0.3,0.2,1", "", ""),
    ("cislunar", SUN, MOON, "3e5,1e5,0", "3e5,1e5,10", "0.3,0.2,1", "sun+earth+moon", ""),
]


def _bad_csv(camera):
    lines = [HEAD]
    for rid, sun, moon, tgt, obs, sc, terms, _ in BAD_ROWS:
        lines.append(f"{rid},{sun},{moon},{tgt},{obs},{sc},{terms},{camera}\n")
    return "".join(lines)


@pytest.mark.parametrize("camera", ["star-tracker", "telescope-15cm"])
def test_hostile_rows_equal_planner(camera, tmp_path):
    n_ok, rc = _compare(_bad_csv(camera), camera, tmp_path)
    assert rc == 1  # some rows had errors, the batch went on
    assert n_ok >= 3


def test_error_statuses_and_failed_outputs():
    _, kw = _inputs(_bad_csv("star-tracker"))
    r = orbillum.illuminate(**kw)
    by = dict(zip([b[0] for b in BAD_ROWS], r["status_name"]))
    assert by["ok"] == "OK"
    assert by["nan_target"] == "ERR_NONFINITE" and by["inf_sun"] == "ERR_NONFINITE"
    assert by["below"] == "ERR_BELOW_SURFACE" and by["obs_below"] == "ERR_BELOW_SURFACE"
    assert by["at_target"] == "ERR_OBSERVER_AT_TARGET"
    assert by["zero_sun"] == "ERR_ZERO_VECTOR" and by["zero_moon"] == "ERR_ZERO_VECTOR"
    assert by["albedo"] == "ERR_ALBEDO" and by["tgt_albedo"] == "ERR_ALBEDO"
    assert by["radius"] == "ERR_RADIUS"
    # 63 m up: the earthshine table reaches the surface since format 4 (no warning)
    assert by["grazing_warn"] == "OK"
    bad = r["status"] < 0
    # a failed row: every float NaN (the C library's 0 reads as a value; the
    # planner leaves the cells empty), every integer 0; the valid rows finite
    for k, v in r.items():
        if k.startswith("status"):
            continue
        v = np.asarray(v)
        if v.dtype.kind == "f":
            assert np.all(np.isnan(v[bad])), k
        else:
            assert np.all(v[bad] == 0), k
        assert np.all(np.isfinite(np.asarray(v[~bad], dtype=float))), k


def test_closed_forms_through_the_binding():
    # far from the Earth with only the Sun term, observer on the Sun side:
    # F = E alb a^2 p(0) / d^2 with p(0) = 2/3 (Lambert sphere, docs/physics.md section 3)
    au = 149597870.7
    sun = np.array([au, 0, 0])
    tgt = np.array([0.0, 4.0e5, 0.0])
    obs = tgt + np.array([1000.0, 0, 0])
    r = orbillum.illuminate(sun, None, tgt, obs, terms="sun", target_albedo=0.5,
                            target_radius_m=10.0)
    assert r["status_name"][0] == "OK"
    d_sun = np.linalg.norm(sun - tgt)
    e = 1361.0 * (au / d_sun) ** 2
    assert abs(r["e_sun"][0] / e - 1) < 1e-13
    xi = math.atan2(np.linalg.norm(np.cross(sun - tgt, obs - tgt)), (sun - tgt) @ (obs - tgt))
    p = 2 / (3 * math.pi) * ((math.pi - xi) * math.cos(xi) + math.sin(xi))
    want = e * 0.5 * (10.0 / 1e6) ** 2 * p
    assert abs(r["flux_obs"][0] / want - 1) < 1e-12, f"want {want:.17g} got {r['flux_obs'][0]:.17g}"
    want_mag = -26.74 - 2.5 * math.log10(want / 1361.0)
    assert abs(r["mag_v"][0] - want_mag) < 1e-12


def test_vectorised_broadcast_and_argument_errors():
    sun = np.array([1.5e8, 0, 0])
    tgt = np.array([[7000.0, 0, 0], [0, 7000.0, 0], [0, 0, 7000.0]])
    r = orbillum.illuminate(sun, None, tgt)
    assert r["status"].shape == (3,) and r["dir_sun"].shape == (3, 3)
    assert np.all(r["flux_obs"] == 0)  # no observer
    with pytest.raises(ValueError, match="shape"):
        orbillum.illuminate(sun, None, np.zeros((3, 2)))
    with pytest.raises(ValueError, match="row counts differ"):
        orbillum.illuminate(np.tile(sun, (2, 1)), None, tgt)
    with pytest.raises(ValueError, match="unknown term"):
        orbillum.illuminate(sun, None, tgt, terms="sun+stars")
    with pytest.raises(ValueError, match="no built-in camera"):
        orbillum.expose("hubble", sun, None, tgt, tgt + 1)
    assert orbillum.terms_mask("sun+moon") == 5 and orbillum.terms_mask("all") == 7
    assert set(orbillum.cameras()) >= {"star-tracker", "telescope-15cm"}


def test_other_entry_points_agree_with_illuminate():
    rows, kw = _inputs(_bad_csv("star-tracker"))
    r = orbillum.illuminate(**kw)
    ok = r["status"] >= 0
    sf = orbillum.sun_fraction(kw["sun"], kw["target"])
    for k in ("fraction", "fraction_atm", "sun_radius_rad", "separation_rad", "region"):
        assert np.array_equal(sf[k][ok], r[f"shadow_{k}"][ok]), k
    e_ok = ok & np.array([orbillum.terms_mask(t) & orbillum.OI_TERM_EARTH != 0
                          for t in kw["terms"]])
    phi, psi, st = orbillum.earthshine(r["earth_theta"][e_ok], r["earth_h_km"][e_ok])
    assert np.array_equal(phi, r["earth_phi"][e_ok]) and np.array_equal(psi, r["earth_psi"][e_ok])
    assert orbillum.lambert_phase(0.0) == pytest.approx(2 / 3, rel=1e-15)
    # math.pi = pi - t with t = sin(math.pi) = 1.2246e-16: p = 2/(3 pi) t^3/3 (series)
    t = math.sin(math.pi)
    assert orbillum.lambert_phase(math.pi) == pytest.approx(2 / (3 * math.pi) * t ** 3 / 3,
                                                            rel=1e-9)
    assert orbillum.moon_phase_law(0.0) == 1.0
    f = r["flux_obs"][ok & (r["flux_obs"] > 0)]
    m = orbillum.magnitude_v(f)
    back, st = orbillum.flux_from_magnitude(m)
    assert np.all(st == 0) and np.allclose(back, f, rtol=1e-13, atol=0)
    _, st = orbillum.flux_from_magnitude([np.nan, 60.0])
    assert [orbillum.status_name(s) for s in st] == ["ERR_MAGNITUDE", "ERR_MAGNITUDE"]
    ex = orbillum.expose_flux("telescope-15cm", [1e-12, 1e-20, 1.0])
    assert "too_faint" in ex["flag_names"][1] and "saturated" in ex["flag_names"][2]
    assert orbillum.flag_names(orbillum.OI_FLAG_SUN_EXCLUSION | orbillum.OI_FLAG_ECLIPSED) == \
        "sun_exclusion+eclipsed"
    with pytest.raises(ValueError, match="unknown model field"):
        orbillum.illuminate(kw["sun"], None, kw["target"], model={"tsi": 1})
    lam = orbillum.illuminate(kw["sun"][0], None, kw["target"][0],
                              model={"earth_model": "lambert"})
    assert lam["status"][0] >= 0


def test_every_status_and_flag_is_exported_under_its_c_name():
    """Each OI_* status and flag of the header (the mirror holds them all,
    test_binding_abi.py) is a name of the package, and the C library names
    it as the header does: oi_status_name drops "OI_", oi_flag_name is the
    lower-case rest after "OI_FLAG_"."""
    statuses = [n for n in orbillum.__all__ if n == "OI_OK" or n.startswith(("OI_WARN_", "OI_ERR_"))]
    flags = [n for n in orbillum.__all__ if n.startswith("OI_FLAG_")]
    assert "OI_ERR_GEOMETRY" in statuses and "OI_FLAG_RESOLVED" in flags
    for n in statuses:
        assert orbillum.status_name(getattr(orbillum, n)) == n[len("OI_"):], n
    for n in flags:
        assert orbillum.flag_names(getattr(orbillum, n)) == n[len("OI_FLAG_"):].lower(), n
    assert len({getattr(orbillum, n) for n in statuses}) == len(statuses), "duplicate status"
