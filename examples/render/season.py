# SPDX-License-Identifier: MIT
"""An eclipse season: daily time in the Earth's penumbra and umbra for a case's target.

    python -m examples.render.season --case geo-inspector-eclipse \\
        --start 2006-02-20 --stop 2006-04-20 --step 60 -o season.png

Positions from the scenario generator (GCRS, astropy Sun, sgp4 target), the Sun
fraction from the runtime through the binding (orbillum.sun_fraction, both the
geometric fraction and the one with the atmosphere). Days are UTC days; a day's
umbra time counts the samples with sun_fraction_atm = 0, penumbra those strictly
between 0 and 1 (each sample weighs one step). Element sets propagated for weeks
lose accuracy (a warning says how far from the epoch): the season's shape is set
by the Sun's declination and stays right, the minutes move with the orbit error.
"""
from __future__ import annotations

import argparse
import sys

import numpy as np


def season(case: str, start: str, stop: str, step_s: float):
    from examples.scenarios import scenario as S

    import orbillum

    sc = S.load_case(case)
    t = S.times_utc(start, stop, step_s)
    sun = S.body_gcrs("sun", t)
    tgt = S.propagate_gcrs(sc.target, t, sc.target_label)
    sf = orbillum.sun_fraction(sun, tgt)
    if np.any(sf["status"] < 0):
        i = int(np.argmax(sf["status"] < 0))
        raise ValueError(f"sun_fraction failed at {t[i].isot}: "
                         f"{orbillum.status_name(sf['status'][i])}")
    days, k = np.unique(np.array(t.utc.isot, dtype="U10"), return_inverse=True)
    fa = sf["fraction_atm"]
    f = sf["fraction"]
    w = step_s / 60.0

    def per_day(mask):
        return np.bincount(k, weights=mask.astype(float), minlength=len(days)) * w

    return sc, days, per_day(fa == 0), per_day((fa > 0) & (fa < 1)), per_day(f == 0)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m examples.render.season",
                                description=__doc__.split("\n\n")[0])
    p.add_argument("--case", required=True)
    p.add_argument("--start", required=True)
    p.add_argument("--stop", required=True)
    p.add_argument("--step", type=float, default=60.0, help="seconds (default 60)")
    p.add_argument("-o", "--output", required=True)
    a = p.parse_args(argv)
    import warnings
    warnings.showwarning = lambda m, c, f, l, file=None, line=None: print(
        f"warning: {m}", file=sys.stderr)
    from examples.scenarios import scenario as S
    try:
        sc, days, umbra, pen, umbra_geo = season(a.case, a.start, a.stop, a.step)
    except (S.ScenarioError, ValueError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    x = np.array(days, dtype="datetime64[D]")
    fig, ax = plt.subplots(figsize=(9, 4))
    ax.bar(x, umbra, width=0.9, color="0.3", label="umbra (with atmosphere)")
    ax.bar(x, pen, width=0.9, bottom=umbra, color="0.7", label="penumbra")
    ax.plot(x, umbra_geo, "r_", ms=6, label="geometric umbra (no atmosphere)")
    ax.set_ylabel("minutes per UTC day")
    ax.set_title(f"eclipse season of {sc.target_label} ({a.start[:10]} .. {a.stop[:10]})")
    ax.legend(loc="upper left", fontsize=8)
    fig.autofmt_xdate()
    fig.tight_layout()
    fig.savefig(a.output, dpi=80)
    plt.close(fig)
    print(f"{a.output}: {len(days)} days, longest umbra {umbra.max():.0f} min, "
          f"longest shadow {np.max(umbra + pen):.0f} min", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
