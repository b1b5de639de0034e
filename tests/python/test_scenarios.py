# SPDX-License-Identifier: MIT
"""Scenario generator (examples/scenarios): frames, ephemerides, TLE input, CSV contract.

References are independent of astropy's and sgp4's code paths where it matters:
the Sun against the Astronomical Almanac's low-precision formula, the frame
change against the size of precession since J2000, the eclipse against a
cylindrical shadow test.
"""
import csv
import io
import math
import os
import sys

import numpy as np
import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, ROOT)

S = pytest.importorskip("examples.scenarios.scenario",
                        reason="astropy/sgp4 missing: pip install -r requirements.txt")

AU = 149597870.7


def test_offline_settings():
    from astropy.utils import iers
    assert iers.conf.auto_download is False


def _aa_low_precision_sun(jd):
    """Astronomical Almanac (2006, p. C5) low-precision Sun: unit vector in the
    mean equator and equinox of date and distance in AU (0.01 deg, 1950-2050)."""
    n = jd - 2451545.0
    L = math.radians((280.460 + 0.9856474 * n) % 360)
    g = math.radians((357.528 + 0.9856003 * n) % 360)
    lam = L + math.radians(1.915) * math.sin(g) + math.radians(0.020) * math.sin(2 * g)
    eps = math.radians(23.439 - 0.0000004 * n)
    R = 1.00014 - 0.01671 * math.cos(g) - 0.00014 * math.cos(2 * g)
    return np.array([math.cos(lam), math.cos(eps) * math.sin(lam),
                     math.sin(eps) * math.sin(lam)]), R


@pytest.mark.parametrize("iso", ["2006-04-09T20:00:00", "2006-06-25T16:49:00",
                                 "2020-12-21T00:00:00"])
def test_sun_against_almanac(iso):
    t = S.times_utc(iso, iso, 1.0)
    sun = S.body_gcrs("sun", t)[0]
    u_ref, r_ref = _aa_low_precision_sun(t.tt.jd[0])
    r = np.linalg.norm(sun)
    assert abs(r / AU - r_ref) < 2e-4, f"want {r_ref:.17g} got {r / AU:.17g}"
    # GCRS (J2000 axes) vs equinox of date: precession ~50"/yr since 2000 plus
    # the formula's 0.01 deg.
    ang = math.degrees(math.atan2(np.linalg.norm(np.cross(sun / r, u_ref)), sun @ u_ref / r))
    years = abs(t.jyear[0] - 2000.0)
    assert ang < 0.015 + years * 50.3 / 3600 * 1.05, f"angle {ang} deg"


def test_moon_distance_and_geo_radius():
    sc = S.load_case("geo-inspector-eclipse")
    t = S.times_utc(sc.start, sc.stop, 3600.0)
    moon = np.linalg.norm(S.body_gcrs("moon", t), axis=1)
    assert np.all((moon > 356000) & (moon < 407000))
    r = np.linalg.norm(S.propagate_gcrs(sc.target, t), axis=1)
    assert np.all(np.abs(r - 42164.0) < 60.0), r


def test_teme_to_gcrs_is_a_rotation_by_precession():
    sc = S.load_case("leo-inspector")
    t = S.times_utc(sc.start, sc.start, 1.0)
    err, r_teme, _ = sc.target.sgp4_array(t.utc.jd1, t.utc.jd2)
    assert err[0] == 0
    g = S.propagate_gcrs(sc.target, t)[0]
    rt = r_teme[0]
    assert abs(np.linalg.norm(g) / np.linalg.norm(rt) - 1) < 1e-12
    ang = math.degrees(math.atan2(np.linalg.norm(np.cross(g, rt)), g @ rt))
    # 2006.5 - 2000: general precession 6.5 yr x 50.3"/yr = 0.091 deg, projected
    # on the orbit plane: between a third and all of it.
    assert 0.02 < ang < 0.1, ang


def test_geo_case_goes_through_the_shadow():
    sc = S.load_case("geo-inspector-eclipse")
    cols = S.build_rows(sc)
    sun = np.column_stack([cols[f"sun_{a}"] for a in "xyz"])
    tgt = np.column_stack([cols[f"target_{a}"] for a in "xyz"])
    s = sun / np.linalg.norm(sun, axis=1)[:, None]
    along = np.sum(tgt * s, axis=1)
    perp = np.linalg.norm(tgt - along[:, None] * s, axis=1)
    umbra_cyl = (along < 0) & (perp < 6378.137 - 300)  # well inside the shadow cylinder
    lit = (along > 0) | (perp > 6378.137 + 300)
    assert umbra_cyl.sum() >= 20 and lit.sum() >= 500
    rng = np.linalg.norm(tgt - np.column_stack([cols[f"observer_{a}"] for a in "xyz"]), axis=1)
    # 2:1 ellipse: radial a*de = 5.65 km, along-track 2 a de = 11.3 km, cross 3.7 km
    assert 5.0 < rng.min() and rng.max() < 12.5


def test_csv_contract_and_ids():
    sc = S.load_case("leo-leo-pass")
    sc.stop = "2006-06-25T16:39:00"
    cols = S.build_rows(sc)
    buf = io.StringIO()
    n = S.write_csv(cols, buf)
    rows = list(csv.DictReader(io.StringIO(buf.getvalue())))
    assert n == len(rows) == 13
    for k in ("id", "sun_x", "sun_y", "sun_z", "moon_x", "target_x", "observer_z", "camera"):
        assert k in rows[0]
    assert rows[0]["id"] == "2006-06-25T16:38:00Z" and rows[-1]["id"] == "2006-06-25T16:39:00Z"
    assert rows[0]["camera"] == "telescope-15cm"
    # values round-trip exactly (%.17g)
    assert float(rows[3]["target_x"]) == cols["target_x"][3]


def test_elements_orbit_matches_two_body_radius():
    sat = S.satrec_from_elements({"epoch": "2026-03-20T00:00:00", "a_km": 42164.0, "ecc": 0.0,
                                  "incl_deg": 0.0, "raan_deg": 0.0, "argp_deg": 0.0,
                                  "mo_deg": 0.0})
    t = S.times_utc("2026-03-20T00:00:00", "2026-03-20T12:00:00", 3600.0)
    r = np.linalg.norm(S.propagate_gcrs(sat, t), axis=1)
    # SGP4 mean vs osculating radius differs by the J2 short-period terms (< 1 km at GEO)
    assert np.all(np.abs(r - 42164.0) < 2.0), r


def _write(tmp_path, text, name="x.tle"):
    p = tmp_path / name
    p.write_text(text)
    return str(p)


L1 = "1 28057U 03049A   06177.78615833  .00000060  00000-0  35940-4 0  1836"
L2 = "2 28057  98.4283 247.6961 0000884  88.1964 271.9322 14.35478080140550"


def test_tle_reader_errors(tmp_path):
    p = _write(tmp_path, L1 + "\n")
    with pytest.raises(S.ScenarioError, match=r"x.tle:2: expected TLE line 2"):
        S.read_tles(p)
    bad = L1[:68] + str((int(L1[68]) + 1) % 10)
    with pytest.raises(S.ScenarioError, match=r"x.tle:1: TLE checksum"):
        S.read_tles(_write(tmp_path, bad + "\n" + L2 + "\n"))
    other = "2 28058" + L2[7:]
    with pytest.raises(S.ScenarioError, match="catalogue numbers differ"):
        S.read_tles(_write(tmp_path, L1 + "\n" + other + "\n"))
    with pytest.raises(S.ScenarioError, match="no two-line element set"):
        S.read_tles(_write(tmp_path, "# nothing\n"))
    with pytest.raises(S.ScenarioError, match="cannot read"):
        S.read_tles(str(tmp_path / "missing.tle"))


def test_tle_pick_and_names(tmp_path):
    p = _write(tmp_path, "0 MY SAT\n" + L1 + "\n" + L2 + "\nOTHER\n" + L1.replace("28057", "28058")
               [:68] + "7\n" + L2.replace("28057", "28058")[:68] + "1\n")
    tles = S.read_tles(p)
    assert [t.name for t in tles] == ["MY SAT", "OTHER"]
    with pytest.raises(S.ScenarioError, match="holds 2 element sets"):
        S.pick_tle(tles, None, p)
    assert S.pick_tle(tles, "28058", p).name == "OTHER"
    assert S.pick_tle(tles, "my sat", p).name == "MY SAT"


def test_bad_times_and_steps():
    with pytest.raises(S.ScenarioError, match="step must be > 0"):
        S.times_utc("2006-01-01", "2006-01-02", 0)
    with pytest.raises(S.ScenarioError, match="before start"):
        S.times_utc("2006-01-02", "2006-01-01", 60)
    with pytest.raises(S.ScenarioError, match="ISO 8601"):
        S.times_utc("yesterday", "2006-01-01", 60)


def test_cli_writes_file(tmp_path):
    from examples.scenarios.__main__ import main
    out = tmp_path / "o.csv"
    rc = main(["--case", "leo-inspector", "--stop", "2006-06-26T18:01:00", "-o", str(out)])
    assert rc == 0
    rows = list(csv.DictReader(out.open()))
    assert len(rows) == 5 and rows[0]["camera"] == "star-tracker"
    assert main(["--case", "no-such-case"]) == 2


def test_short_tle_line_and_old_elements(tmp_path):
    with pytest.raises(S.ScenarioError, match=r"x.tle:1: .*too short \(\d+ characters, expected 69\) and has no line 2"):
        S.read_tles(_write(tmp_path, L1[:54] + "\n"))
    with pytest.raises(S.ScenarioError, match=r"x.tle:1: TLE line 1 is too short"):
        S.read_tles(_write(tmp_path, L1[:50] + "\n" + L2 + "\n"))
    sat = S.satrec_from_tle(S.read_tles(_write(tmp_path, L1 + "\n" + L2 + "\n"))[0])
    t = S.times_utc("2006-08-01T00:00:00", "2006-08-01T00:01:00", 60.0)
    with pytest.warns(UserWarning, match="35 days from the element epoch"):
        S.propagate_gcrs(sat, t, "x")


def _plan_at(day, tmp_path, capsys):
    """The CLI on mean elements whose epoch is `day`, for two minutes from it:
    (return code, rows, stderr)."""
    from examples.scenarios.__main__ import main
    iso = day.strftime("%Y-%m-%dT%H:%M")
    stop = (day + __import__("datetime").timedelta(minutes=2)).strftime("%Y-%m-%dT%H:%M")
    out = tmp_path / f"{iso[:10]}.csv"
    el = f"epoch={iso},a_km=6878,ecc=0.001,incl_deg=51.6,raan_deg=10,argp_deg=0,mo_deg=0"
    rc = main(["--target-elements", el, "--start", iso, "--stop", stop, "--step", "60",
               "-o", str(out)])
    return rc, list(csv.DictReader(out.open())) if rc == 0 else [], capsys.readouterr().err


@pytest.mark.parametrize("days_ahead", [0, 365])
def test_plans_today_and_a_year_ahead(days_ahead, tmp_path, capsys):
    """Any date plans offline: beyond the shipped Earth-orientation data with
    the documented warning (predictions, then degraded accuracy), never a
    traceback; the target stays on its orbit's radius (two-body, 0.5 %)."""
    import datetime
    day = datetime.datetime.now(datetime.timezone.utc).replace(second=0, microsecond=0)
    day = day + datetime.timedelta(days=days_ahead)
    rc, rows, err = _plan_at(day, tmp_path, capsys)
    assert rc == 0, err
    assert len(rows) == 3
    for r in rows:
        rad = math.sqrt(sum(float(r[f"target_{a}"]) ** 2 for a in "xyz"))
        assert abs(rad / 6878.0 - 1) < 5e-3
        sun = math.sqrt(sum(float(r[f"sun_{a}"]) ** 2 for a in "xyz"))
        assert abs(sun / AU - 1) < 0.02
    measured_end, predicted_end = S.earth_orientation_span()
    mjd = (day - datetime.datetime(1858, 11, 17, tzinfo=datetime.timezone.utc)).days
    if mjd > predicted_end:
        assert "degraded accuracy" in err
    elif mjd > measured_end:
        assert "IERS predictions used" in err
    assert "Traceback" not in err


@pytest.mark.parametrize("args, message", [
    (["--case", "leo-inspector", "--target-tle", "x.tle"], "not both"),
    (["--case", "leo-inspector", "--camera", "hubble"], "not a built-in camera"),
    (["--case", "leo-inspector", "--earth-albedo", "1.5"], "albedo is in"),
    (["--case", "leo-inspector", "--target-albedo", "-0.1"], "albedo is in"),
    (["--case", "leo-inspector", "--step", "0"], "step is > 0"),
    (["--case", "leo-inspector", "-o", "/no/such/folder/x.csv"], "does not exist"),
])
def test_cli_refuses_bad_arguments_before_writing(args, message, capsys):
    from examples.scenarios.__main__ import main
    with pytest.raises(SystemExit) as e:
        main(args)
    assert e.value.code == 2
    assert message in capsys.readouterr().err


def test_tle_reader_is_the_catalogues(tmp_path):
    """The scenarios read TLEs with the catalogue's reader: a short '1 ' line
    that is no line 1 is a name, as in a catalogue."""
    p = _write(tmp_path, "1 WEB\n" + L1 + "\n" + L2 + "\n")
    assert [(t.name, t.line1, t.line2) for t in S.read_tles(p)] == [("1 WEB", L1, L2)]
    assert S._tle_module().parse("1 WEB\n" + L1 + "\n" + L2 + "\n")[0].name == "1 WEB"
