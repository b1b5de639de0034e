# SPDX-License-Identifier: MIT
"""Plot of a planned pass from the planner's output (build/oi-plan --csv).

    python -m examples.render.pass_plot INPUT.csv PLAN.csv -o pass.png

INPUT.csv is the planner's input (for the observer-target range and the camera
name), PLAN.csv its output. Panels against time: irradiance at the target per
source; the Sun fraction with and without the atmosphere; the apparent V
magnitude; the suggested exposure and gain; the SNR. Shaded: umbra (dark grey),
penumbra (light grey), and one coloured strip per warning flag.
"""
from __future__ import annotations

import argparse
import sys

import numpy as np

from .common import floats, flag_sets, intervals, read_csv, times, vec

FLAG_COLORS = {
    "sun_exclusion": "#d62728", "earth_in_fov": "#1f77b4", "too_faint": "#9467bd",
    "saturated": "#ff7f0e", "occulted": "#8c564b", "eclipsed": "#444444",
    "penumbra": "#aaaaaa",
}


def plot_pass(inp: dict, plan: dict, out_png: str, title: str = "") -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.dates as mdates
    import matplotlib.pyplot as plt

    n = len(plan["id"])
    t = times(plan["id"])
    x = t if t is not None else np.arange(n)
    ok = np.array([s == "OK" or s.startswith("WARN") for s in plan["status"]])
    f = floats(plan["sun_fraction"], 0.0)
    fa = floats(plan.get("sun_fraction_atm", plan["sun_fraction"]), 0.0)
    flags = flag_sets(plan.get("flags", [""] * n))
    umbra = ok & (fa <= 0.0)
    pen = ok & (fa > 0.0) & (fa < 1.0)

    fig, ax = plt.subplots(6, 1, figsize=(10, 12.5), sharex=True,
                           gridspec_kw={"height_ratios": [0.45, 1.3, 0.9, 1, 1, 1]})
    strip, a_e, a_f, a_m, a_x, a_s = ax

    def shade(a):
        for s, e in intervals(umbra):
            a.axvspan(x[s], x[min(e, n - 1)], color="0.35", alpha=0.25, lw=0)
        for s, e in intervals(pen):
            a.axvspan(x[s], x[min(e, n - 1)], color="0.6", alpha=0.2, lw=0)

    # warnings strip: one row per flag present
    present = [k for k in FLAG_COLORS if any(k in fs for fs in flags)]
    bad = ~ok
    rows = present + (["bad row"] if bad.any() else [])
    for j, k in enumerate(rows):
        m = bad if k == "bad row" else np.array([k in fs for fs in flags])
        for s, e in intervals(m):
            strip.axvspan(x[s], x[min(e, n - 1)], ymin=j / max(len(rows), 1),
                          ymax=(j + 1) / max(len(rows), 1),
                          color=FLAG_COLORS.get(k, "k"), lw=0)
    strip.set_yticks([(j + 0.5) / max(len(rows), 1) for j in range(len(rows))])
    strip.set_yticklabels(rows, fontsize=7)
    strip.set_ylim(0, 1)
    strip.set_title(title or "pass plan", fontsize=11)
    if not rows:
        strip.text(0.5, 0.5, "no warnings", transform=strip.transAxes, ha="center",
                   va="center", fontsize=8)

    for key, lab, c in (("e_sun", "Sun", "#e6a700"), ("e_earth", "Earth", "#1f77b4"),
                        ("e_moon", "Moon", "#2ca02c")):
        v = floats(plan[key], 0.0)
        a_e.plot(x, np.where(v > 0, v, np.nan), color=c, label=lab)
    a_e.set_yscale("log")
    a_e.set_ylabel("irradiance at\ntarget (W/m$^2$)")
    a_e.legend(loc="best", fontsize=8)

    a_f.plot(x, f, color="k", label="geometric (uniform disc)")
    a_f.plot(x, fa, color="#d62728", ls="--", label="with atmosphere")
    a_f.set_ylim(-0.05, 1.05)
    a_f.set_ylabel("Sun fraction")
    a_f.legend(loc="best", fontsize=8)

    mag = floats(plan["mag_v"])
    mag = np.where(mag >= 98.0, np.nan, mag)  # OI_MAG_DARK
    a_m.plot(x, mag, color="k")
    a_m.invert_yaxis()
    a_m.set_ylabel("V magnitude")
    rng = None
    ti, ob = vec(inp, "target"), vec(inp, "observer")
    if ti is not None and ob is not None and len(ti) == n:
        rng = np.linalg.norm(ti - ob, axis=1)
        a_r = a_m.twinx()
        a_r.plot(x, rng, color="0.6", lw=0.8)
        a_r.set_ylabel("range (km)", color="0.5")

    ex = floats(plan.get("exposure_s", [""] * n))
    a_x.step(x, np.where(ex > 0, ex, np.nan), where="mid", color="k", label="exposure")
    a_x.set_yscale("log")
    a_x.set_ylabel("exposure (s)")
    g = floats(plan.get("gain", [""] * n))
    if np.isfinite(g).any():
        a_g = a_x.twinx()
        a_g.step(x, g, where="mid", color="#ff7f0e", lw=0.8)
        a_g.set_ylabel("gain", color="#ff7f0e")

    snr = floats(plan.get("snr", [""] * n))
    a_s.plot(x, np.where(snr > 0, snr, np.nan), color="k")
    a_s.set_yscale("log")
    a_s.set_ylabel("SNR (brightest px)")
    cam = inp.get("camera", [""])[0] if "camera" in inp else ""
    if cam:
        a_s.text(0.01, 0.95, f"camera: {cam}", transform=a_s.transAxes, va="top", fontsize=8)

    for a in (strip, a_e, a_f, a_m, a_x, a_s):
        shade(a)
    if t is not None:
        a_s.xaxis.set_major_formatter(mdates.DateFormatter("%H:%M"))
        a_s.set_xlabel(f"UTC, {str(t[0])[:10]}   (grey: umbra / penumbra)")
    else:
        a_s.set_xlabel("row")
    fig.tight_layout()
    fig.savefig(out_png, dpi=80)
    plt.close(fig)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m examples.render.pass_plot",
                                description=__doc__.split("\n\n")[0])
    p.add_argument("input", help="the planner's input CSV")
    p.add_argument("plan", help="the planner's output CSV (build/oi-plan --csv INPUT)")
    p.add_argument("-o", "--output", required=True, help="PNG file")
    p.add_argument("--title", default="")
    a = p.parse_args(argv)
    inp, plan = read_csv(a.input), read_csv(a.plan)
    for k in ("id", "status", "sun_fraction", "e_sun", "e_earth", "e_moon", "mag_v"):
        if k not in plan:
            print(f"error: {a.plan}: no column {k!r}: is it the planner's output?",
                  file=sys.stderr)
            return 2
    plot_pass(inp, plan, a.output, a.title or a.input)
    print(a.output, file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
