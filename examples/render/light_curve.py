# SPDX-License-Identifier: MIT
"""Light curve of a tumbling target over a shipped pass: its V magnitude against
time as a facet shape spinning about a fixed axis, beside the case's sphere.

    python -m examples.render.light_curve [--case leo-leo-pass] [--shape box-wing]
        [--spin-deg-s 2] [--axis 1 2 3] [--plan build/oi-plan] [--out build/light-curve]

Both curves are the runtime's (orbillum.expose through the binding on the same
rows: the sphere of the case's target_radius_m and target_albedo, and the shape
turned by attitude_q). The attitude (body -> input frame) spins at a constant
rate about a fixed input-frame axis: q(t) = (cos(w t / 2), sin(w t / 2) a) q0,
a the unit axis, q0 the identity, t from the first row; the rate and axis are an
example's choice, not a measured tumble.

Writes into --out:
  CASE-tumbling.csv    the planner's input: the case's rows plus target_shape and
                       q_w, q_x, q_y, q_z (build/oi-plan --csv on it gives the
                       shape's curve; on the case's rows without them, the sphere's)
  CASE-light-curve.csv id, t_s, mag_sphere, mag_shape, flux_shape, flux_specular,
                       flags_shape (magnitude 99 = OI_MAG_DARK: nothing seen)
  CASE-light-curve.png the two curves (Agg), glints marked, the rows where the
                       Earth hides the target shaded (flag occulted: the
                       magnitude is what the target sends, not what is seen)
With --plan the planner is run on CASE-tumbling.csv and on the case's rows
(written as CASE.csv), and the largest difference from the binding's magnitudes
is printed (0: the same library, the same inputs; else exit 1).
"""
from __future__ import annotations

import argparse
import csv
import io
import math
import os
import subprocess
import sys

import numpy as np

from .common import intervals, scene_inputs, times

MAG_DARK = 99.0


def spin_quaternions(t_s: np.ndarray, rate_deg_s: float, axis) -> np.ndarray:
    """(N, 4) unit quaternions (w, x, y, z) of a spin about a fixed axis."""
    a = np.asarray(axis, dtype=float)
    if a.shape != (3,) or not np.linalg.norm(a) > 0:
        raise ValueError(f"--axis: three numbers, not all zero; got {axis!r}")
    a = a / np.linalg.norm(a)
    half = 0.5 * math.radians(rate_deg_s) * np.asarray(t_s, dtype=float)
    return np.column_stack([np.cos(half), np.sin(half)[:, None] * a[None, :]])


def case_rows(case: str) -> dict:
    """The planner's input columns of a shipped case (examples/scenarios)."""
    from examples.scenarios import scenario as S
    sc = S.load_case(case)
    return S.build_rows(sc)


def columns_text(cols: dict) -> str:
    from examples.scenarios import scenario as S
    out = io.StringIO()
    S.write_csv(cols, out)
    return out.getvalue()


def light_curve(cols: dict, shape: str, rate_deg_s: float, axis) -> dict:
    """The two curves from the runtime: dict of arrays (t_s, mag_sphere,
    mag_shape, flux_shape, flux_specular, flags_shape, q)."""
    import orbillum

    ids = cols["id"]
    t = times(ids)
    if t is None:
        raise ValueError("the case's ids are not times")
    t_s = (t - t[0]).astype("timedelta64[ms]").astype(float) / 1e3
    q = spin_quaternions(t_s, rate_deg_s, axis)
    inp = _read_text(columns_text(cols))
    kw = scene_inputs(inp)
    kw.pop("target_shape", None)  # the case's own shape columns, if any, give way to the tumble
    kw.pop("attitude_q", None)
    camera = inp["camera"][0] if "camera" in inp else orbillum.cameras()[0]
    sphere = orbillum.expose(camera, **kw)
    shaped = orbillum.expose(camera, **kw, target_shape=shape, attitude_q=q)
    return {"id": list(ids), "t_s": t_s, "q": q, "mag_sphere": sphere["mag_v"],
            "mag_shape": shaped["mag_v"], "flux_sphere": sphere["flux_obs"],
            "flux_shape": shaped["flux_obs"], "flux_specular": shaped["flux_specular"],
            "flags_shape": list(shaped["flag_names"]), "status_sphere": sphere["row_status_name"],
            "status_shape": shaped["row_status_name"], "camera": camera}


def _read_text(text: str) -> dict:
    rows = list(csv.reader(io.StringIO(text)))
    head = rows[0]
    return {h: [r[k] for r in rows[1:]] for k, h in enumerate(head)}


def tumbling_csv(cols: dict, shape: str, q: np.ndarray) -> str:
    """The case's rows with the shape and its attitude, as planner input."""
    c = dict(cols)
    n = len(c["id"])
    c["target_shape"] = [shape] * n
    for k, name in enumerate(("q_w", "q_x", "q_y", "q_z")):
        c[name] = q[:, k]
    return columns_text(c)


def write_curve(path: str, lc: dict) -> None:
    with open(path, "w", encoding="utf-8", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["id", "t_s", "mag_sphere", "mag_shape", "flux_shape", "flux_specular",
                    "flags_shape"])
        for i, ident in enumerate(lc["id"]):
            w.writerow([ident, "%.17g" % lc["t_s"][i], "%.17g" % lc["mag_sphere"][i],
                        "%.17g" % lc["mag_shape"][i], "%.17g" % lc["flux_shape"][i],
                        "%.17g" % lc["flux_specular"][i], lc["flags_shape"][i]])


def plot(path: str, lc: dict, title: str, shape: str) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t_min = lc["t_s"] / 60.0
    ms = np.where(lc["mag_sphere"] >= MAG_DARK, np.nan, lc["mag_sphere"])
    mb = np.where(lc["mag_shape"] >= MAG_DARK, np.nan, lc["mag_shape"])
    glint = np.array(["glint" in f.split("+") for f in lc["flags_shape"]])
    fig, ax = plt.subplots(2, 1, figsize=(10, 6.5), sharex=True,
                           gridspec_kw={"height_ratios": [3, 1]})
    ax[0].plot(t_min, ms, color="#1f77b4", lw=1.5, label="sphere (the case's radius, albedo)")
    ax[0].plot(t_min, mb, color="#d62728", lw=1.0, label=f"{shape}, tumbling")
    if glint.any():
        ax[0].plot(t_min[glint], mb[glint], "o", ms=3, color="#ff7f0e",
                   label="glint (specular > half the flux)")
    hidden = np.array(["occulted" in f.split("+") for f in lc["flags_shape"]])
    for a in ax:
        for k, (i0, i1) in enumerate(intervals(hidden)):
            a.axvspan(t_min[i0], t_min[min(i1, len(t_min) - 1)], color="#cccccc", lw=0,
                      label="behind the Earth (occulted)" if (k == 0 and a is ax[0]) else None)
    ax[0].invert_yaxis()
    ax[0].set_ylabel("V magnitude")
    ax[0].legend(fontsize=8, loc="best")
    ax[0].grid(alpha=0.3)
    ax[0].set_title(title, fontsize=9)
    frac = np.where(lc["flux_shape"] > 0, lc["flux_specular"] / np.where(
        lc["flux_shape"] > 0, lc["flux_shape"], 1.0), np.nan)
    ax[1].plot(t_min, frac, color="#ff7f0e", lw=1.0)
    ax[1].set_ylim(-0.02, 1.02)
    ax[1].set_ylabel("specular part")
    ax[1].set_xlabel(f"minutes after {lc['id'][0]}")
    ax[1].grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def _planner_mags(plan: str, path: str) -> np.ndarray:
    run = subprocess.run([plan, "--csv", path], capture_output=True, text=True, timeout=300)
    if run.returncode not in (0, 1):
        raise RuntimeError(f"{plan} failed on {path} (exit {run.returncode}): {run.stderr}")
    rows = list(csv.DictReader(io.StringIO(run.stdout)))
    return np.array([float(r["mag_v"]) if r["mag_v"] else np.nan for r in rows])


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m examples.render.light_curve",
                                description="Light curve of a tumbling facet target over a "
                                            "shipped pass, beside the sphere.")
    p.add_argument("--case", default="leo-leo-pass", help="a shipped case (examples/scenarios)")
    p.add_argument("--shape", default="box-wing", help="a built-in shape (default box-wing)")
    p.add_argument("--spin-deg-s", type=float, default=2.0,
                   help="tumble rate, deg/s (default 2)")
    p.add_argument("--axis", type=float, nargs=3, default=(1.0, 2.0, 3.0),
                   help="tumble axis in the input frame (default 1 2 3)")
    p.add_argument("--plan", help="the planner: run it on the same rows and compare")
    p.add_argument("--out", default="build/light-curve", help="output directory")
    a = p.parse_args(argv)

    import orbillum
    if a.shape not in orbillum.shapes() or a.shape == "sphere":
        print(f"error: --shape {a.shape!r}: one of {', '.join(orbillum.shapes()[1:])}",
              file=sys.stderr)
        return 2
    try:
        cols = case_rows(a.case)
        lc = light_curve(cols, a.shape, a.spin_deg_s, a.axis)
    except ValueError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    base = os.path.join(a.out, a.case)
    tumbling = tumbling_csv(cols, a.shape, lc["q"])
    with open(f"{base}-tumbling.csv", "w", encoding="utf-8") as f:
        f.write(tumbling)
    write_curve(f"{base}-light-curve.csv", lc)
    seen_s = lc["mag_sphere"] < MAG_DARK
    seen_b = lc["mag_shape"] < MAG_DARK
    title = (f"{a.case}: {a.shape} tumbling at {a.spin_deg_s:g} deg/s about "
             f"({', '.join('%g' % x for x in a.axis)}) vs the sphere; camera {lc['camera']}")
    plot(f"{base}-light-curve.png", lc, title, a.shape)
    print(f"{base}-light-curve.png: {len(lc['id'])} rows; sphere V "
          f"{np.min(lc['mag_sphere'][seen_s]):.2f} to {np.max(lc['mag_sphere'][seen_s]):.2f}; "
          f"{a.shape} V {np.min(lc['mag_shape'][seen_b]):.2f} to "
          f"{np.max(lc['mag_shape'][seen_b]):.2f} ({int((~seen_b).sum())} rows dark, "
          f"{sum('glint' in f.split('+') for f in lc['flags_shape'])} with glint)",
          file=sys.stderr)
    if a.plan:
        with open(f"{base}.csv", "w", encoding="utf-8") as f:
            f.write(columns_text(cols))
        ms = _planner_mags(a.plan, f"{base}.csv")
        mb = _planner_mags(a.plan, f"{base}-tumbling.csv")
        ds = float(np.nanmax(np.abs(ms - lc["mag_sphere"])))
        db = float(np.nanmax(np.abs(mb - lc["mag_shape"])))
        print(f"planner vs binding: largest |mag_v| difference: sphere {ds:.3g}, "
              f"{a.shape} {db:.3g}", file=sys.stderr)
        if ds != 0.0 or db != 0.0:
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
