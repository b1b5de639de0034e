# SPDX-License-Identifier: MIT
"""The planner's flags keep the meanings of include/orbillum.h ("Flags with one meaning each"):
no row of the golden outputs, of a fresh run on the golden inputs or of a random sweep
holds two flags the definitions exclude; and --summary's best view is never an eclipsed, occulted
or too-faint row (with only such rows: none)."""
import csv
import io
import math
import random
from pathlib import Path

import pytest

from _oi_plan import ROOT, run

GOLDEN = ROOT / "tests" / "golden"
CASES = sorted(p.name[: -len(".in.csv")] for p in GOLDEN.glob("*.in.csv"))
AU = 149597870.7
RE = 6378.137

# pairs never together in one row
EXCLUDED = [("saturated", "too_faint"), ("saturated", "background_saturated"),
            ("saturated", "occulted"), ("eclipsed", "penumbra")]


def broken_rules(flags):
    """The definitions' rules a row's flag text breaks (empty: none)."""
    f = set(flags.split("+")) - {""}
    bad = [f"{a}+{b}" for a, b in EXCLUDED if a in f and b in f]
    if "occulted" in f and "too_faint" not in f:
        bad.append("occulted without too_faint")
    return bad


def rows_of(text):
    return list(csv.DictReader(io.StringIO(text)))


def check_rows(rows, where):
    bad = [(r["id"], r["flags"], broken_rules(r["flags"])) for r in rows if broken_rules(r["flags"])]
    assert not bad, f"{where}: {len(bad)} rows break the flag rules, e.g. {bad[:3]}"


@pytest.mark.parametrize("case", CASES)
def test_golden_rows_obey_the_flag_rules(case):
    check_rows(rows_of((GOLDEN / f"{case}.plan.csv").read_text()), f"golden {case}")
    code, out, err = run(["--csv", str(GOLDEN / f"{case}.in.csv")])
    assert code in (0, 1), err
    check_rows(rows_of(out), f"fresh {case}")


def test_the_earth_filling_the_field_is_no_target_saturation():
    """leo-leo-pass: the telescope's field full of the sunlit Earth; the well is the background's
    (158 rows that were 'saturated' before the rule, 135 of them also too faint)."""
    rows = rows_of((GOLDEN / "leo-leo-pass.plan.csv").read_text())
    bg = [r for r in rows if "background_saturated" in r["flags"].split("+")]
    assert len(bg) >= 150
    assert all("earth_in_fov" in r["flags"] for r in bg)
    assert not [r for r in rows if "saturated" in r["flags"].split("+")]


def random_rows(n, seed):
    rng = random.Random(seed)
    rows = []
    for i in range(n):
        def unit():
            z = rng.uniform(-1, 1)
            a = rng.uniform(0, 2 * math.pi)
            s = math.sqrt(1 - z * z)
            return (s * math.cos(a), s * math.sin(a), z)
        us, ut, uo = unit(), unit(), unit()
        if rng.random() < 0.3:  # near the anti-Sun axis: eclipsed or penumbra
            ut = tuple(-a + 0.1 * b for a, b in zip(us, ut))
            n_ = math.sqrt(sum(a * a for a in ut))
            ut = tuple(a / n_ for a in ut)
        r = RE + 300 + 36000 * rng.random() ** 2
        d = 10 ** (3.5 * rng.random())
        tgt = [r * a for a in ut]
        obs = [t + d * a for t, a in zip(tgt, uo)]
        if rng.random() < 0.2:  # across the Earth: occulted
            obs = [-(RE + 500) * a + 300 * b for a, b in zip(ut, uo)]
        row = dict(id=f"r{i}", sun_x=AU * us[0], sun_y=AU * us[1], sun_z=AU * us[2],
                   target_x=tgt[0], target_y=tgt[1], target_z=tgt[2],
                   observer_x=obs[0], observer_y=obs[1], observer_z=obs[2],
                   camera=rng.choice(["star-tracker", "telescope-15cm"]),
                   target_radius_m=10 ** rng.uniform(-1, 1.5))
        rows.append(row)
    return rows


def table(rows):
    cols = list(rows[0].keys())
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow(cols)
    for r in rows:
        w.writerow([r[c] for c in cols])
    return out.getvalue()


def test_random_sweep_obeys_the_flag_rules():
    code, out, err = run(["--csv", "-"], stdin=table(random_rows(4000, 28)).encode())
    assert code in (0, 1), err
    rows = [r for r in rows_of(out) if r["status"] in ("OK", "WARN_TABLE_RANGE")]
    assert len(rows) > 3000
    seen = set()
    for r in rows:
        seen |= set(r["flags"].split("+"))
    # the sweep reaches every flag the rules speak of
    assert {"saturated", "background_saturated", "too_faint", "occulted", "eclipsed",
            "penumbra", "earth_in_fov"} <= seen, seen
    check_rows(rows, "random sweep")


LIT_OBS = dict(sun_x=AU, sun_y=0, sun_z=0, target_x=0, target_y=7000, target_z=0,
               observer_x=0, observer_y=7010, observer_z=0)
# deep umbra behind the Earth, seen from 10 m: bright in earthshine? no: dark, too faint
DARK_OBS = dict(sun_x=AU, sun_y=0, sun_z=0, target_x=-7000, target_y=0, target_z=0,
                observer_x=-7010, observer_y=0, observer_z=0)
# lit, the Sun inside the exclusion angle (observer on the Sun's side looking away from it)
EXCL_OBS = dict(sun_x=AU, sun_y=0, sun_z=0, target_x=0, target_y=7000, target_z=0,
                observer_x=-10, observer_y=7000, observer_z=0)


def summary(rows):
    cols = ["id", "sun_x", "sun_y", "sun_z", "target_x", "target_y", "target_z",
            "observer_x", "observer_y", "observer_z"]
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow(cols)
    for r in rows:
        w.writerow([r[c] for c in cols])
    code, csv_out, err = run(["--csv", "-", "--summary"], stdin=out.getvalue().encode())
    assert code == 0, err
    best = [line for line in err.splitlines() if "best view" in line]
    assert len(best) == 1, err
    return {r["id"]: r["flags"] for r in rows_of(csv_out)}, best[0]


def test_best_view_is_observable():
    flags, best = summary([dict(DARK_OBS, id="dark0"), dict(LIT_OBS, id="lit1"),
                           dict(DARK_OBS, id="dark2")])
    assert "eclipsed" in flags["dark0"]
    assert "best view: lit1 " in best


def test_best_view_falls_back_but_never_on_an_eclipsed_row():
    flags, best = summary([dict(DARK_OBS, id="dark0"), dict(EXCL_OBS, id="excl1")])
    assert "sun_exclusion" in flags["excl1"] and "eclipsed" not in flags["excl1"]
    assert "none observable" in best and "excl1" in best and "dark0" not in best


def test_best_view_none_when_every_row_is_dark():
    flags, best = summary([dict(DARK_OBS, id="dark0"), dict(DARK_OBS, id="dark1")])
    assert all("eclipsed" in f for f in flags.values())
    assert "best view: none" in best and "dark" not in best
