# SPDX-License-Identifier: MIT
"""The planner's batch interface (build/oi-plan --csv) on normal and hostile
input: the CSV contract of docs/planner.md (header, columns in any order,
unknown columns ignored, %.17g numbers, statuses, exit codes 0/1/2) and its
usability (messages with line and column, --help, cameras).

Numbers are checked against closed forms written here (inverse-square Sun,
full shadow), never against the planner itself.
"""
import csv
import io
import math

import pytest
from hypothesis import given, settings, HealthCheck
from hypothesis import strategies as st

from _oi_plan import PLAN, run


HEADER = ("id,status,sun_fraction,sun_fraction_atm,e_sun,e_earth,e_moon,earth_theta_deg,"
          "earth_h_km,flux_obs,mag_v,exposure_s,gain,snr,flags,detect_margin_mag,e_sky")
NUMERIC = HEADER.split(",")[2:14] + ["detect_margin_mag", "e_sky"]
FLAG_NAMES = {"sun_exclusion", "earth_in_fov", "eclipsed", "too_faint", "saturated",
              "penumbra", "occulted", "resolved", "moon_in_fov", "trailed", "background_saturated"}
AU = 149597870.7
TSI = 1361.0

# Target 7000 km on +y, Sun on +x (lit, theta = 90 deg); observer 10 km further out.
LIT = dict(sun_x=AU, sun_y=0, sun_z=0, target_x=0, target_y=7000, target_z=0)
LIT_OBS = dict(LIT, observer_x=0, observer_y=7010, observer_z=0)
# Target behind the Earth on the Sun line, 7000 km: deep umbra.
DARK = dict(sun_x=AU, sun_y=0, sun_z=0, target_x=-7000, target_y=0, target_z=0)


def run_csv(text, *extra):
    data = text.encode("utf-8") if isinstance(text, str) else text
    return run(["--csv", "-"] + list(extra), stdin=data)


def table(rows, columns=None):
    """CSV text from dicts (columns in the given order)."""
    if columns is None:
        columns = []
        for r in rows:
            columns += [c for c in r if c not in columns]
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow(columns)
    for r in rows:
        w.writerow([r.get(c, "") for c in columns])
    return out.getvalue()


def parse(out):
    lines = out.splitlines()
    assert lines[0] == HEADER
    rows = list(csv.DictReader(io.StringIO(out)))
    for r in rows:
        assert list(r.keys()) == HEADER.split(",")
    return rows


def check_number_format(row):
    for c in NUMERIC:
        s = row[c]
        if s == "":
            continue
        x = float(s)
        assert math.isfinite(x), (c, s)
        assert "%.17g" % x == s, f"{c}: {s!r} is not %.17g"


# ---------------------------------------------------------------- normal use

def test_help_and_cameras():
    code, out, _ = run(["--help"])
    assert code == 0
    assert "--csv" in out and "examples:" in out and "exit status" in out
    code, out, _ = run(["--list-cameras"])
    assert code == 0
    assert "star-tracker" in out and "telescope-15cm" in out


def test_builtin_scenario():
    code, out, err = run([])
    assert code == 0, err
    assert "[W/m2]" in out and "[min]" in out
    assert "Best observation windows" in out
    assert "eclipsed" in out  # the pass goes through eclipse


def test_builtin_scenario_other_camera_and_step():
    code, out, _ = run(["--camera", "telescope-15cm", "--step", "600"])
    assert code == 0
    assert "telescope-15cm" in out


def test_lit_and_umbra_closed_forms():
    code, out, err = run_csv(table([dict(LIT, id="lit"), dict(DARK, id="dark")]))
    assert code == 0, err
    lit, dark = parse(out)
    for r in (lit, dark):
        assert r["status"] == "OK"
        check_number_format(r)
    d2 = AU ** 2 + 7000.0 ** 2
    assert float(lit["sun_fraction"]) == 1.0
    assert abs(float(lit["e_sun"]) - TSI * AU ** 2 / d2) <= 1e-12 * TSI
    assert abs(float(lit["earth_theta_deg"]) - 90.0) < 1e-9
    assert abs(float(lit["earth_h_km"]) - (7000.0 - 6378.137)) < 1e-9
    assert float(dark["sun_fraction"]) == 0.0 and float(dark["e_sun"]) == 0.0
    assert abs(float(dark["earth_theta_deg"]) - 180.0) < 1e-9
    assert "eclipsed" in dark["flags"].split("+")
    # no observer: observer columns empty; no moon columns: moon term off
    for r in (lit, dark):
        for c in ("flux_obs", "mag_v", "exposure_s", "gain", "snr"):
            assert r[c] == ""
        assert float(r["e_moon"]) == 0.0


def test_observer_columns_and_flags():
    code, out, err = run_csv(table([LIT_OBS]))
    assert code == 0, err
    (r,) = parse(out)
    check_number_format(r)
    for c in ("flux_obs", "mag_v", "exposure_s", "gain", "snr"):
        assert r[c] != ""
    assert float(r["flux_obs"]) > 0
    assert float(r["exposure_s"]) > 0 and float(r["snr"]) >= 0
    # magnitude from the flux, written out here: m = -26.74 - 2.5 log10(F / TSI)
    want = -26.74 - 2.5 * math.log10(float(r["flux_obs"]) / TSI)
    assert abs(float(r["mag_v"]) - want) < 1e-9
    if r["flags"]:
        assert set(r["flags"].split("+")) <= FLAG_NAMES


def test_moon_columns_turn_the_moon_on():
    moon = dict(LIT, moon_x=-384400 * 0.5, moon_y=384400 * 0.866, moon_z=0)
    code, out, err = run_csv(table([moon, dict(moon, terms="sun+earth")]))
    assert code == 0, err
    on, off = parse(out)
    assert float(on["e_moon"]) > 0
    assert float(off["e_moon"]) == 0


def test_terms():
    rows = [dict(LIT, terms="sun"), dict(LIT, terms="earth"), dict(LIT, terms="Sun + Earth"),
            dict(LIT, terms="all")]
    code, out, err = run_csv(table(rows))
    assert code == 0, err
    sun, earth, both, alls = parse(out)
    assert float(sun["e_earth"]) == 0 and float(sun["e_sun"]) > 1000
    assert float(earth["e_sun"]) == 0 and float(earth["e_earth"]) > 0
    assert both["e_sun"] == sun["e_sun"] and both["e_earth"] == earth["e_earth"]
    assert alls["e_sun"] == sun["e_sun"]


def test_atmosphere_off_equals_geometric_fraction():
    rows = [dict(LIT, atmosphere=0), dict(DARK, atmosphere=0),
            dict(LIT, target_x=-6000, target_y=3400, atmosphere=0)]
    code, out, err = run_csv(table(rows))
    assert code == 0, err
    for r in parse(out):
        assert r["sun_fraction_atm"] == r["sun_fraction"]


def test_earth_shape_column():
    """earth_shape: empty and sphere are the default, bit for bit; wgs84 casts the
    ellipsoid's shadow (over the pole its limb is 21 km lower: a point there in
    the sphere's penumbra is lit) and accepts a target between the polar and
    the equatorial radius."""
    # behind the Earth, just above the sphere's shadow edge over the pole
    edge = dict(sun_x=AU, sun_y=0, sun_z=0, target_x=-3000, target_y=0, target_z=6374.0)
    below = dict(LIT, target_x=0, target_y=0, target_z=6360.0)
    rows = [dict(edge), dict(edge, earth_shape="sphere"), dict(edge, earth_shape=""),
            dict(edge, earth_shape="wgs84"), dict(edge, earth_shape="WGS84"),
            dict(below, earth_shape="wgs84"), dict(below)]
    code, out, err = run_csv(table(rows))
    r = parse(out)
    assert r[0]["sun_fraction"] == r[1]["sun_fraction"] == r[2]["sun_fraction"]
    assert float(r[0]["sun_fraction"]) < 1
    assert r[3]["sun_fraction"] == r[4]["sun_fraction"]
    assert float(r[3]["sun_fraction"]) > float(r[0]["sun_fraction"])
    assert r[5]["status"] == "OK"
    assert abs(float(r[5]["earth_h_km"]) - (6360.0 - 6378.137 * (1 - 1 / 298.257223563))) < 1e-6
    assert r[6]["status"] == "ERR_BELOW_SURFACE"
    assert code == 1


def test_column_order_and_unknown_columns():
    rows = [dict(LIT_OBS, id="a"), dict(DARK, id="b")]
    cols = list(LIT_OBS.keys()) + ["id"]
    code, out1, _ = run_csv(table(rows, cols))
    shuffled = ["observer_z", "target_y", "zzz", "sun_z", "id", "target_x", "observer_x",
                "sun_y", "target_z", "observer_y", "sun_x", "comment"]
    code2, out2, err2 = run_csv(table(rows, shuffled))
    assert code == code2 == 0
    assert out1 == out2
    assert "zzz" in err2 and "comment" in err2  # a note about ignored columns
    upper = table(rows, cols).replace("sun_x", "SUN_X", 1)
    assert run_csv(upper)[1] == out1


def test_ids_default_to_row_numbers():
    code, out, _ = run_csv(table([LIT, DARK, LIT]))
    assert code == 0
    assert [r["id"] for r in parse(out)] == ["1", "2", "3"]


def test_sky_column():
    """sky: absent, empty and none are today's dark sky, to the byte; the
    zodiacal light (observer under the target, looking away from the Earth)
    lowers the telescope's SNR; the Moon's flag needs its position."""
    up = dict(LIT, observer_x=0, observer_y=6990, observer_z=0, camera="telescope-15cm")
    rows = [dict(up), dict(up, sky=""), dict(up, sky="none"), dict(up, sky="zodiacal"),
            dict(up, sky="all"), dict(up, sky="Zodiacal + moon")]
    code, out, err = run_csv(table(rows))
    assert code == 0, err
    absent, empty, none, zodi, alls, both = parse(out)
    for r in (empty, none):
        assert r == dict(absent, id=r["id"])
    assert float(zodi["snr"]) < float(absent["snr"])
    assert alls["snr"] == zodi["snr"] == both["snr"]
    # the Moon straight above the target: in the field, and the target is
    # seen against it
    moon = dict(up, moon_x=0, moon_y=384400, moon_z=0)
    code, out, err = run_csv(table([dict(moon, sky="moon"), dict(moon)]))
    assert code == 0, err
    with_moon, without = parse(out)
    assert "moon_in_fov" in with_moon["flags"].split("+")
    assert "moon_in_fov" not in without["flags"].split("+")


def test_detect_margin_column():
    """detect_margin_mag: empty without an observer; with the default SNR
    rule its sign is that of snr - 5 over targets from far above to far
    below the limit (the margin is 2.5 log10 of the signal over the
    smallest signal with SNR 5, and the SNR rises with the signal); an
    occulted target (no signal) gets -100."""
    rows = [dict(LIT, id="noobs")]
    for k, d in enumerate([10, 1e3, 1e4, 1e5, 3e5, 1e6, 3e6, 1e7]):
        rows.append(dict(LIT, id=f"d{k}", observer_x=0, observer_y=7000 + d, observer_z=0,
                         camera="star-tracker"))
    # observer on the far side of the Earth: the Earth hides the target
    rows.append(dict(LIT, id="hidden", observer_x=0, observer_y=-7010, observer_z=0))
    code, out, err = run_csv(table(rows))
    assert code == 0, err
    got = parse(out)
    assert got[0]["detect_margin_mag"] == ""
    signs = set()
    for r in got[1:-1]:
        snr, m = float(r["snr"]), float(r["detect_margin_mag"])
        assert (m > 0) == (snr > 5), (r["id"], snr, m)
        signs.add(m > 0)
    assert signs == {True, False}
    assert "occulted" in got[-1]["flags"] and float(got[-1]["detect_margin_mag"]) == -100


def test_sensor_temp_column():
    """sensor_temp_c: absent, empty and the camera's reference temperature
    (25 C for the star tracker) give the same row to the byte; 20 C warmer
    the dark current is 2^(20/6.5) times larger and the SNR lower; outside
    the rated range (-30 .. 70 C) or NaN the row fails with ERR_INPUT or
    ERR_NONFINITE and empty numbers; text is ERR_PARSE."""
    base = dict(LIT, observer_x=0, observer_y=7000 + 3e5, observer_z=0, camera="star-tracker")
    rows = [dict(base), dict(base, sensor_temp_c=""), dict(base, sensor_temp_c="25"),
            dict(base, sensor_temp_c="45"), dict(base, sensor_temp_c="-30"),
            dict(base, sensor_temp_c="70.5"), dict(base, sensor_temp_c="nan"),
            dict(base, sensor_temp_c="warm")]
    code, out, err = run_csv(table(rows))
    assert code == 1
    absent, empty, ref, warm, cold, hot, nan, text = parse(out)
    assert empty == dict(absent, id=empty["id"]) and ref == dict(absent, id=ref["id"])
    assert float(warm["snr"]) < float(absent["snr"]) < float(cold["snr"])
    assert hot["status"] == "ERR_INPUT" and nan["status"] == "ERR_NONFINITE"
    assert text["status"] == "ERR_PARSE"
    for r in (hot, nan, text):
        assert all(r[c] == "" for c in NUMERIC) and r["flags"] == ""


def test_velocity_columns():
    """Velocities: absent and zero are at rest, to the byte; a target
    crossing the telescope's field at 1 km/s, 1000 km away (1e-3 rad/s,
    67 pixels/s) trails and loses SNR or shortens the exposure; only the
    motion across the line of sight counts; a partial group is an error."""
    up = dict(LIT, observer_x=0, observer_y=6000 + 990, observer_z=0, camera="telescope-15cm")
    up["target_y"] = 6990 + 1000
    rows = [dict(up), dict(up, target_vx=0, target_vy=0, target_vz=0),
            dict(up, target_vx=1.0, target_vy=0, target_vz=0),
            dict(up, target_vx=0, target_vy=1.0, target_vz=0),
            dict(up, observer_vx=-1.0, observer_vy=0, observer_vz=0)]
    code, out, err = run_csv(table(rows))
    assert code == 0, err
    rest, zero, across, along, obs = parse(out)
    assert zero == dict(rest, id=zero["id"])
    assert along == dict(rest, id=along["id"])
    assert float(across["snr"]) < float(rest["snr"])
    assert "trailed" not in rest["flags"]
    assert obs == dict(across, id=obs["id"])
    code, out, err = run_csv(table([dict(up, target_vx=1.0, target_vy="", target_vz=0)]))
    assert code == 1 and parse(out)[0]["status"] == "ERR_PARSE"


def test_camera_column_and_option():
    rows = [dict(LIT_OBS), dict(LIT_OBS, camera="telescope-15cm"), dict(LIT_OBS, camera="nope")]
    code, out, err = run_csv(table(rows))
    assert code == 1
    default, tele, bad = parse(out)
    assert default["status"] == "OK" and tele["status"] == "OK"
    assert default["exposure_s"] != tele["exposure_s"] or default["snr"] != tele["snr"]
    assert bad["status"] == "ERR_CAMERA" and bad["e_sun"] == ""
    assert "unknown camera" in err and "star-tracker" in err
    code, out2, _ = run_csv(table([LIT_OBS]), "--camera", "telescope-15cm")
    assert code == 0 and parse(out2)[0]["snr"] == tele["snr"]
    code, _, err = run_csv(table([LIT_OBS]), "--camera", "nope")
    assert code == 2 and "star-tracker" in err


def test_stdin_and_file_agree(tmp_path):
    text = table([LIT_OBS, DARK])
    f = tmp_path / "in.csv"
    f.write_text(text)
    code, out_file, _ = run(["--csv", str(f)])
    code2, out_stdin, _ = run_csv(text)
    assert code == code2 == 0 and out_file == out_stdin
    code3, out_eq, _ = run([f"--csv={f}"])
    assert code3 == 0 and out_eq == out_file


# ---------------------------------------------------------------- hostile input

def test_missing_required_column():
    text = table([LIT]).replace("target_z", "target_q")
    code, out, err = run_csv(text)
    assert code == 2
    assert out == ""
    assert "target_z" in err and "line 1" in err


def test_partial_vector_group_in_header():
    text = table([dict(LIT, moon_x=1, moon_y=2)])
    code, _, err = run_csv(text)
    assert code == 2 and "moon_z" in err


def test_duplicate_column():
    text = "sun_x,sun_y,sun_z,target_x,target_y,target_z,sun_x\n1,2,3,4,5,6,7\n"
    code, _, err = run_csv(text)
    assert code == 2 and "twice" in err


@pytest.mark.parametrize("text", ["", "\n\n", "  \r\n\t\n"])
def test_no_header(text):
    code, out, err = run_csv(text)
    assert code == 2 and out == "" and "header" in err


def test_unreadable_file(tmp_path):
    code, out, err = run(["--csv", str(tmp_path / "missing.csv")])
    assert code == 2 and "cannot open" in err
    code, _, err = run(["--csv", str(tmp_path)])  # a directory
    assert code == 2


def test_header_only_is_ok():
    code, out, _ = run_csv("sun_x,sun_y,sun_z,target_x,target_y,target_z\n")
    assert code == 0 and out.splitlines() == [HEADER]


def test_bad_number_row_goes_on():
    rows = [dict(LIT, id="good1"), dict(LIT, id="bad", target_y="7e3x"), dict(LIT, id="good2")]
    code, out, err = run_csv(table(rows))
    assert code == 1
    g1, bad, g2 = parse(out)
    assert g1["status"] == "OK" and g2["status"] == "OK"
    assert bad["status"] == "ERR_PARSE"
    assert all(bad[c] == "" for c in NUMERIC) and bad["flags"] == ""
    assert "line 3" in err and "column 5" in err and "target_y" in err and "7e3x" in err


@pytest.mark.parametrize("value", ["nan", "NaN", "inf", "-inf", "1e999"])
def test_nonfinite_values(value):
    code, out, err = run_csv(table([dict(LIT, sun_y=value), LIT]))
    assert code == 1
    bad, good = parse(out)
    assert bad["status"] == "ERR_NONFINITE" and bad["e_sun"] == ""
    assert good["status"] == "OK"


@pytest.mark.parametrize("field,value,status", [
    ("target_x", "", "ERR_PARSE"),
    ("sun_z", "  ", "ERR_PARSE"),
    ("earth_albedo", "1.5", "ERR_ALBEDO"),
    ("target_albedo", "-0.1", "ERR_ALBEDO"),
    ("target_radius_m", "-1", "ERR_RADIUS"),
    ("earth_albedo", "lots", "ERR_PARSE"),
    ("terms", "sun+", "ERR_PARSE"),
    ("terms", "sunlight", "ERR_PARSE"),
    ("terms", "moon", "ERR_PARSE"),       # moon asked for without a position
    ("atmosphere", "2", "ERR_PARSE"),
    ("sky", "stars", "ERR_PARSE"),
    ("earth_shape", "oblate", "ERR_PARSE"),
    ("sky", "zodiacal+", "ERR_PARSE"),
    ("observer_y", "", "ERR_PARSE"),      # two of three observer coordinates
])
def test_bad_fields(field, value, status):
    row = dict(LIT_OBS)
    row[field] = value
    code, out, err = run_csv(table([row]))
    assert code == 1
    (r,) = parse(out)
    assert r["status"] == status, err
    assert r["e_sun"] == ""
    assert "line 2" in err


def test_geometry_errors():
    rows = [dict(LIT, target_y=6000),                                   # below the surface
            dict(LIT_OBS, observer_y=7000),                             # observer at target
            dict(LIT, sun_x=0)]                                         # Sun at the centre
    code, out, _ = run_csv(table(rows))
    assert code == 1
    st = [r["status"] for r in parse(out)]
    assert st[0] == "ERR_BELOW_SURFACE"
    assert st[1] == "ERR_OBSERVER_AT_TARGET"
    assert st[2].startswith("ERR_")


def test_short_and_long_rows():
    head = "sun_x,sun_y,sun_z,target_x,target_y,target_z\n"
    good = f"{AU},0,0,0,7000,0"
    text = head + good + "\n" + f"{AU},0,0,0,7000\n" + good + ",extra,fields\n"
    code, out, err = run_csv(text)
    assert code == 1
    rows = parse(out)
    assert [r["status"] for r in rows] == ["OK", "ERR_PARSE", "OK"]
    assert "line 3" in err and "target_z" in err


def test_crlf_blank_lines_bom_and_quotes():
    lf = table([dict(LIT_OBS, id="x"), dict(DARK, id="y")])
    code, out_lf, _ = run_csv(lf)
    crlf = "\ufeff" + lf.replace("\n", "\r\n\r\n")
    code2, out_crlf, err = run_csv(crlf)
    assert code == code2 == 0, err
    assert out_crlf == out_lf
    quoted = lf.replace(f"{AU}", f'" {AU}"')
    assert run_csv(quoted)[1] == out_lf
    cr_only = lf.replace("\n", "\r")
    assert run_csv(cr_only)[1] == out_lf


def test_quoted_ids_round_trip():
    ids = ['a,b', 'say "hi"', "two\nlines", "plain"]
    code, out, err = run_csv(table([dict(LIT, id=i) for i in ids]))
    assert code == 0, err
    assert [r["id"] for r in parse(out)] == ids
    # blanks: trimmed around unquoted fields, kept inside quotes (and re-quoted)
    text = table([LIT, LIT], ["id"] + list(LIT)).splitlines()
    text[1] = '  unquoted  ' + text[1]
    text[2] = '" quoted "' + text[2]
    code, out, err = run_csv("\n".join(text) + "\n")
    assert code == 0, err
    assert [r["id"] for r in parse(out)] == ["unquoted", " quoted "]


def test_bad_quotes():
    head = "id,sun_x,sun_y,sun_z,target_x,target_y,target_z\n"
    good = f"ok,{AU},0,0,0,7000,0\n"
    text = head + f'"x"y,{AU},0,0,0,7000,0\n' + good + '"never closed,1,2\n'
    code, out, err = run_csv(text)
    assert code == 1
    st = [r["status"] for r in parse(out)]
    assert st == ["ERR_PARSE", "OK", "ERR_PARSE"]
    assert "line 2" in err and "quote" in err


def test_huge_line_is_rejected_and_batch_goes_on():
    head = "id,sun_x,sun_y,sun_z,target_x,target_y,target_z\n"
    huge = "big," + "1" * (2 << 20) + ",0,0,0,7000,0\n"
    good = f"ok,{AU},0,0,0,7000,0\n"
    code, out, err = run_csv(head + good + huge + good)
    assert code == 1
    st = [r["status"] for r in parse(out)]
    assert st == ["OK", "ERR_PARSE", "OK"]
    assert "line 3" in err and "longer" in err


def test_nul_byte():
    text = table([LIT]).encode() + b"1\x002,0,0,0,7000,0\n"
    code, out, _ = run_csv(text)
    assert code == 1
    assert [r["status"] for r in parse(out)] == ["OK", "ERR_PARSE"]


def test_no_progress_when_stderr_is_not_a_terminal():
    rows = [LIT] * 3000
    code, out, err = run_csv(table(rows))
    assert code == 0
    assert len(parse(out)) == 3000
    assert err == ""


@pytest.mark.parametrize("args", [["--bogus"], ["--csv"], ["--step", "abc"], ["--step", "1"],
                                  ["--camera"]])
def test_bad_options(args):
    code, _, err = run(args)
    assert code == 2 and "oi-plan" in err


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.binary(max_size=400))
def test_garbage_never_crashes(data):
    text = b"id,sun_x,sun_y,sun_z,target_x,target_y,target_z\n" + data
    code, out, _ = run_csv(text)
    assert code in (0, 1, 2)
    if code != 2:
        lines = out.splitlines()
        assert lines[0] == HEADER
        for r in csv.DictReader(io.StringIO(out)):
            check_number_format(r)


def test_summary_of_windows():
    dark_obs = dict(DARK, observer_x=-7010, observer_y=0, observer_z=0)
    rows = [dict(LIT_OBS, id="t0"), dict(LIT_OBS, id="t1"), dict(dark_obs, id="t2"),
            dict(LIT_OBS, id="t3"), dict(LIT, id="t4")]
    code, out, err = run_csv(table(rows), "--summary")
    assert code == 0, err
    st = parse(out)
    assert "eclipsed" in st[2]["flags"]
    good = [float(r["snr"]) >= 5 and not (set(r["flags"].split("+")) &
            {"eclipsed", "penumbra", "sun_exclusion", "occulted", "saturated"})
            for r in st[:4]]
    assert good == [True, True, False, True]
    assert "observation windows" in err
    assert "3 of 5 rows observable, in 2 windows" in err
    # the same CSV on stdout with and without --summary
    assert run_csv(table(rows))[1] == out


def test_row_messages_are_capped():
    rows = [dict(LIT, target_y="x")] * 200 + [LIT]
    code, out, err = run_csv(table(rows))
    assert code == 1
    st = [r["status"] for r in parse(out)]
    assert st.count("ERR_PARSE") == 200 and st[-1] == "OK"
    assert err.count("expected a number") == 50
    assert "suppressed" in err and "200 of 201 rows had errors" in err


def _render(columns, rows, quote_mask, pad, eol):
    """CSV text with some fields quoted, unquoted ones padded, a given line end."""
    def cell(c, v, i):
        s = str(v)
        if quote_mask[i % len(quote_mask)] or "," in s or '"' in s:
            return '"' + s.replace('"', '""') + '"'
        return pad + s + pad
    lines = [",".join(cell("", c, i) for i, c in enumerate(columns))]
    for r in rows:
        lines.append(",".join(cell(c, r.get(c, ""), i) for i, c in enumerate(columns)))
    return eol.join(lines) + eol


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(perm=st.permutations(list(LIT_OBS.keys()) + ["id", "note"]),
       quote_mask=st.lists(st.booleans(), min_size=1, max_size=5),
       pad=st.sampled_from(["", " ", "\t"]), eol=st.sampled_from(["\n", "\r\n", "\r"]))
def test_layout_does_not_change_results(perm, quote_mask, pad, eol):
    rows = [dict(LIT_OBS, id="a", note="x, y"), dict(DARK, id="b", note="")]
    canonical = run_csv(table(rows))[1]
    code, out, err = run_csv(_render(perm, rows, quote_mask, pad, eol))
    assert code == 0, err
    assert out == canonical


def test_header_too_long_or_binary():
    code, out, err = run_csv("sun_x," + "x" * (2 << 20) + "\n1\n")
    assert code == 2 and out == "" and "longer" in err
    code, out, err = run_csv("s\0u\0n\0_\0x\0\n".encode("latin-1"))
    assert code == 2 and "UTF-16" in err


def test_moon_occults_the_sun_whatever_the_terms():
    """A GEO target on the Sun-Moon line, the Moon on the far side of its
    orbit: the antumbra, 1 - (r_moon / r_sun)^2 of the Sun left (closed form
    on the sphere: sin((rs - rm)/2) sin((rs + rm)/2) / sin^2(rs/2)); the
    flag moon_shadow without an observer; the same with terms=sun (the Moon's
    position is given); and moonlight cut to 0 by the Earth between the target
    and the Moon."""
    sun = (AU, 0.0, 0.0)
    target = (0.0, 42164.0, 0.0)
    moon = (384400.0, 42164.0 * (1 - 384400.0 / AU), 0.0)
    row = dict(sun_x=sun[0], sun_y=sun[1], sun_z=sun[2], target_x=target[0],
               target_y=target[1], target_z=target[2], moon_x=moon[0], moon_y=moon[1],
               moon_z=moon[2])
    hidden = dict(row, id="hidden", target_x=0.0, target_y=-7000.0, target_z=0.0,
                  moon_x=0.0, moon_y=384400.0, moon_z=0.0)
    code, out, err = run_csv(table([dict(row, id="all"), dict(row, id="sun", terms="sun"),
                                    hidden]))
    assert code == 0, err
    a, s, h = parse(out)
    ds = math.dist(sun, target)
    dm = math.dist(moon, target)
    rs, rm = math.asin(695700.0 / ds), math.asin(1737.4 / dm)
    want = math.sin((rs - rm) / 2) * math.sin((rs + rm) / 2) / math.sin(rs / 2) ** 2
    for r in (a, s):
        assert r["status"] == "OK"
        assert abs(float(r["sun_fraction"]) - want) < 1e-12, (r["sun_fraction"], want)
        assert abs(float(r["e_sun"]) - TSI * (AU / ds) ** 2 * want) < 1e-6 * TSI
        assert "moon_shadow" in r["flags"].split("+")
    assert float(s["e_moon"]) == 0.0
    assert h["status"] == "OK" and float(h["e_moon"]) == 0.0
    assert "moon_shadow" not in h["flags"].split("+")


def test_terms_sky_is_opt_in():
    """`sky` in terms fills e_sky (a target just inside the LEO umbra sees the sunlit
    limb) and adds its reflection to flux_obs; `all` and the default leave it 0."""
    r = 6378.137 + 400.0
    t = math.radians(112.0)
    rows = ["id,sun_x,sun_y,sun_z,target_x,target_y,target_z,observer_x,observer_y,"
            "observer_z,terms"]
    for name, terms in (("sky", "sun+earth+sky"), ("all", "all"), ("none", "")):
        rows.append("%s,1.496e8,0,0,%.9g,%.9g,0,%.9g,%.9g,50,%s" % (
            name, r * math.cos(t), r * math.sin(t), r * math.cos(t), r * math.sin(t), terms))
    code, out, err = run_csv("\n".join(rows) + "\n")
    assert code == 0, err
    got = {d["id"]: d for d in csv.DictReader(io.StringIO(out))}
    assert float(got["sky"]["e_sky"]) > 0.05
    assert float(got["all"]["e_sky"]) == 0 and float(got["none"]["e_sky"]) == 0
    assert float(got["sky"]["flux_obs"]) > float(got["all"]["flux_obs"])


def test_sky_starlight_word():
    """sky: `starlight` adds the integrated starlight to the background (the
    SNR falls, on top of the zodiacal light too); `all` stays zodiacal+moon,
    its numbers unchanged; a misspelt word is a parse error."""
    up = dict(LIT, observer_x=0, observer_y=6990, observer_z=0, camera="telescope-15cm")
    rows = [dict(up, sky="zodiacal"), dict(up, sky="zodiacal+starlight"),
            dict(up, sky="starlight"), dict(up, sky="all"), dict(up)]
    code, out, err = run_csv(table(rows))
    assert code == 0, err
    zodi, both, star, alls, dark = parse(out)
    assert float(both["snr"]) < float(zodi["snr"])
    assert float(star["snr"]) < float(dark["snr"])
    assert alls["snr"] == zodi["snr"]
    code, out, err = run_csv(table([dict(up, sky="starlite")]))
    assert "ERR_PARSE" in out + err
