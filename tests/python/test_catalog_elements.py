# SPDX-License-Identifier: MIT
"""Element sets in every published form and their checks (orbillum.catalog.elements, tle).

The same public element set (the ISS, 2008) as 3LE and as OMM in JSON, XML and
CSV propagates to the same bits; 9-digit catalogue numbers reach the rows; every
malformed set is one error naming file and line (checksum column blank or not a
digit, a changed digit, ranges, non-ASCII, binary data); element epochs far from
the plan warn, and past the limit their rows are ERR_SGP4."""
import json
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pyarrow as pa
import pytest
from sgp4.api import WGS72, Satrec, SatrecArray

from orbillum.catalog import block, elements, plan, sky, tle

ROOT = Path(__file__).resolve().parents[2]
GP = ROOT / "tests" / "data" / "gp"
OBSERVER = {"name": "inspector-leo", "epoch": "2026-12-01T00:00:00", "a_km": 6978.0,
            "ecc": 0.001, "incl_deg": 53.0, "raan_deg": 10.0, "argp_deg": 0.0, "mo_deg": 0.0}
L1 = "1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927"
L2 = "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537"


def _obs():
    return [tle.from_elements(OBSERVER, 99000)]


@pytest.mark.parametrize("form", ["json", "xml", "csv"])
def test_omm_forms_propagate_as_the_tle(form):
    """OMM fields -> sgp4init give the bits twoline2rv gives for the same set."""
    (ref,) = elements.read(str(GP / "iss-2008.3le"))
    (s,) = elements.read(str(GP / f"iss-2008.{form}"))
    assert (s.name, s.number) == ("ISS (ZARYA)", 25544) and s.mean is not None
    assert s.source.startswith(str(GP / f"iss-2008.{form}:"))
    a, b = sky.satrec(ref), Satrec.twoline2rv(L1, L2, WGS72)
    assert (a.jdsatepoch, a.jdsatepochF) == (b.jdsatepoch, b.jdsatepochF)
    c = sky.satrec(s)
    assert (c.jdsatepoch, c.jdsatepochF) == (b.jdsatepoch, b.jdsatepochF)
    jd = 2454730.0 + np.arange(0.0, 3.0, 0.125)
    e1, r1, v1 = SatrecArray([b]).sgp4(jd, np.zeros_like(jd))
    e2, r2, v2 = SatrecArray([c]).sgp4(jd, np.zeros_like(jd))
    assert not e1.any() and not e2.any()
    assert np.array_equal(r1, r2) and np.array_equal(v1, v2)


def test_nine_digit_catalogue_numbers_reach_the_rows():
    sets = elements.read(str(GP / "synthetic-group.json"))
    assert [s.number for s in sets] == [270000001, 270000002, 270000003]
    assert all(sky.satrec(s).error == 0 for s in sets)
    _, tables = plan.plan(sets, _obs(), "2026-12-01T00:00:00", "2026-12-01T01:00:00", 300.0,
                          all_rows=True, keep=True, progress=False)
    t = pa.concat_tables(tables)
    assert sorted(set(t["object_id"].to_pylist())) == [270000001, 270000002, 270000003]
    assert block.STATUS_SGP4 not in t["status"].to_pylist()


def _tle_error(tmp_path, text, name="cat.3le"):
    p = tmp_path / name
    p.write_bytes(text if isinstance(text, bytes) else text.encode())
    with pytest.raises(tle.CatalogueError) as e:
        elements.read(str(p))
    return str(e.value)


def _with_checksum(line):
    return line[:68] + str(tle.checksum(line))


def test_checksum_column_blank_or_not_a_digit_is_an_error(tmp_path):
    msg = _tle_error(tmp_path, f"ISS\n{L1}\n{L2[:68]}\n")
    assert msg.startswith(f"{tmp_path / 'cat.3le'}:3:") and "column 69 is blank" in msg
    msg = _tle_error(tmp_path, f"ISS\n{L1[:68]}x\n{L2}\n")
    assert ":2:" in msg and "column 69 is 'x'" in msg
    # a changed mean motion: the checksum no longer matches
    changed = L2[:52] + "15.82125391" + L2[63:]
    assert ":3: TLE checksum" in _tle_error(tmp_path, f"ISS\n{L1}\n{changed}\n")


def test_ranges_and_numbers_are_checked(tmp_path):
    bad_incl = _with_checksum(L2[:8] + "200.0000" + L2[16:])
    assert "inclination 200 deg is outside 0-180" in _tle_error(tmp_path, f"{L1}\n{bad_incl}\n")
    bad_mm = _with_checksum(L2[:52] + " 0.00000000" + L2[63:])
    assert "mean motion 0 rev/day is not > 0" in _tle_error(tmp_path, f"{L1}\n{bad_mm}\n")
    not_num = _with_checksum(L2[:26] + "00O6703" + L2[33:])
    msg = _tle_error(tmp_path, f"{L1}\n{not_num}\n")
    assert ":2: TLE line 2, columns 27-33 (eccentricity)" in msg and "not a number" in msg
    rec = json.loads((GP / "iss-2008.json").read_text())[0]
    for key, value, words in (("INCLINATION", 200.0, "inclination 200"),
                              ("ECCENTRICITY", 1.2, "eccentricity 1.2"),
                              ("MEAN_MOTION", -1.0, "mean motion -1"),
                              ("MEAN_MOTION", "fast", "MEAN_MOTION 'fast' is not a number"),
                              ("EPHEMERIS_TYPE", 4, "SGP4-XP"),
                              ("EPOCH", "20 Sept 2008", "not an ISO 8601"),
                              ("NORAD_CAT_ID", 1234567890, "outside 1-999999999")):
        text = "[\n" + json.dumps(rec) + ",\n" + json.dumps(dict(rec, **{key: value})) + "\n]\n"
        msg = _tle_error(tmp_path, text, "gp.json")
        assert msg.startswith(f"{tmp_path / 'gp.json'}:3 (record 2): ") and words in msg, msg
    csv_text = (GP / "iss-2008.csv").read_text().replace(",51.6416,", ",251.6416,")
    assert ":2: inclination 251.642" in _tle_error(tmp_path, csv_text, "gp.csv")
    xml_text = (GP / "iss-2008.xml").read_text().replace(">.0006703<", ">1.5<")
    assert ":6 (segment 1): eccentricity 1.5" in _tle_error(tmp_path, xml_text, "gp.xml")


def test_non_ascii_and_binary_input_name_file_and_line(tmp_path):
    msg = _tle_error(tmp_path, f"ISS\n{L1}\n{L2[:20]}\u00e9{L2[21:]}\n")
    assert msg.startswith(f"{tmp_path / 'cat.3le'}:3:21: non-ASCII character")
    msg = _tle_error(tmp_path, b"ISS\n" + L1.encode() + b"\n\x00\x01\x02\xff\xfe\n")
    assert msg.startswith(f"{tmp_path / 'cat.3le'}:3:1: binary data")
    msg = _tle_error(tmp_path, b"\x89PNG\r\n\x1a\n\x00\x00")
    assert ":1:1: binary data" in msg
    # one line on stderr from the command line, exit 2
    p = tmp_path / "bad.3le"
    p.write_bytes(b"\x89PNG\r\n\x1a\n\x00\x00")
    r = subprocess.run([sys.executable, "-m", "orbillum.catalog", str(p), "--observers",
                        str(GP / "iss-2008.3le"), "--start", "2026-12-01T00:00",
                        "--stop", "2026-12-01T00:10", "-o", str(tmp_path / "x.parquet")],
                       capture_output=True, text=True, check=False)
    assert r.returncode == 2 and r.stderr.count("\n") == 1, r.stderr
    assert f"{p}:1:1: binary data" in r.stderr and "Traceback" not in r.stderr


def test_epochs_far_from_the_plan_warn_and_past_the_limit_are_err_sgp4():
    """Epochs of 1957 and 2056 (the TLE's two-digit years) planned for 2026: ERR_SGP4;
    20 days away: a warning, rows computed."""
    near = tle.format_set("NEAR", 1, 2026, 315.0, 51.6, 10.0, 0.001, 0.0, 0.0, 15.5)
    sets = [near] + [tle.format_set(n, i, y, 300.0, 51.6, 10.0, 0.001, 0.0, 0.0, 15.5)
                     for i, (n, y) in enumerate((("OLD", 1957), ("LATE", 2056)), 2)]
    for s in sets:
        tle.check_lines(s.line1, s.line2, "x", 1)
    assert sky.satrec(sets[1]).jdsatepoch < 2436500 and sky.satrec(sets[2]).jdsatepoch > 2470000
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        s, tables = plan.plan(sets, _obs(), "2026-12-05T00:00:00", "2026-12-05T01:00:00", 600.0,
                              all_rows=True, keep=True, progress=False)
    msgs = [str(x.message) for x in w if issubclass(x.category, elements.EpochWarning)]
    assert len(msgs) == 1 and msgs[0].startswith("3 of 3 element set(s) are more than 14 days")
    assert "(2 set(s) have such rows)" in msgs[0]
    t = pa.concat_tables(tables).to_pydict()
    for oid, st in zip(t["object_id"], t["status"]):
        assert (st == block.STATUS_SGP4) == (oid != 1), (oid, st)
    assert s.sgp4_failures == 2 * 7 and s.old_epochs == 3
    # the limit is an option: 10 days makes NEAR's rows (20 days away) ERR_SGP4 too
    _, tables = plan.plan(sets[:1], _obs(), "2026-12-05T00:00:00", "2026-12-05T00:10:00",
                          600.0, all_rows=True, keep=True, progress=False,
                          epoch_limit_days=10.0, epoch_warn_days=5.0)
    assert set(pa.concat_tables(tables)["status"].to_pylist()) == {block.STATUS_SGP4}
