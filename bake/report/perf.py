# SPDX-License-Identifier: MIT
"""Report section "Performance": error against cost for earthshine.

`section(outdir) -> str` (called by bake/report/__main__.py):

1. runs `make bench` (bench/run_bench.py: ns and callgrind instructions per
   call of the C runtime, and the baker's quadrature per call), reads
   build/bench/bench.json;
2. sweeps the table resolution (0.25x .. 1.5x the default grid of
   bake/config/default.json) and two interpolation schemes of the same grid,
   Catmull-Rom (the runtime's, bake.earthshine.lookup) and bilinear (written here),
   and one storage variant (16-bit integers with a float32 scale per altitude
   row, interpolated with Catmull-Rom),
   measuring each against the quadrature with bake.earthshine.measure's test points
   (bake.earthshine.measure.sample_points) and error measure (goal_score: relative error
   where phi >= 1% of phi(0, h), absolute in units of phi(0, h) elsewhere);
3. draws the Pareto plot (error against ns per call and against table
   bytes) and writes the table of points.

Costs: ns and instructions are measured for the compiled runtime (the default
table and the analytic Lambert model) and for the Python quadrature; a
lookup's instruction count does not depend on the grid's resolution (same
code, same 16 taps), so the resolution sweep is plotted against bytes.
"""
from __future__ import annotations

import json
import math
import os
import subprocess
from pathlib import Path

import numpy as np

from ..earthshine import grid, lookup, measure
from ..earthshine import reference as ref

ROOT = Path(__file__).resolve().parent.parent.parent
SCALES = (0.25, 0.5, 0.75, 1.0, 1.5)
# Other grids measured with the same points (lit, term, alt): the default
# with more theta nodes and the same altitude rows.
EXTRA_GRIDS = ((2, 65, 122),)


def _run_bench():
    build = os.environ.get("BUILDDIR", "build")
    subprocess.run(["make", "-s", "bench", "BUILDDIR=" + build], cwd=ROOT, check=True,
                   stdout=subprocess.DEVNULL)
    with open(ROOT / build / "bench" / "bench.json") as f:
        return json.load(f)


def _sweep(cache: Path):
    """Compute the sweep (every run: the report states what this run computed)
    and write it to `cache` as a data file next to the plot."""
    cfg = json.loads((ROOT / "bake" / "config" / "default.json").read_text())
    g = cfg["grid"]
    r = cfg.get("radius_km", ref.R_EARTH_KM)
    w_min = float(grid.w_from_h(cfg["h_min_km"], r))
    order = int(cfg.get("reference_order", 32))
    # test points and reference once, on the default grid's sampling
    extra = {k: g[k] for k in ("term_k0", "term_kp") if k in g}
    spec0 = grid.TableSpec(g["n_lit"], g["n_term"], g["n_alt"], w_min, 0.5 * math.pi, **extra)
    theta, w = measure.sample_points(spec0, 2000, seed=12345)
    x = np.cos(w)
    phi_ref, psi_ref = grid.reference_chunked(theta, x, order, "perf: reference")
    phi0, _ = grid.reference_chunked(np.zeros_like(x), x, order, "perf: phi(0,x)")
    rows = []
    grids = []
    for s in SCALES:
        # a lit segment of <= 3 nodes is exact by design (format 4): keep it
        n_lit = g["n_lit"] if g["n_lit"] <= 3 else max(2, round(g["n_lit"] * s))
        grids.append((s, n_lit, max(3, round(g["n_term"] * s)), max(3, round(g["n_alt"] * s))))
    for n_lit, n_term, n_alt in EXTRA_GRIDS:
        if (n_lit, n_term, n_alt) != (g["n_lit"], g["n_term"], g["n_alt"]):
            grids.append((None, n_lit, n_term, n_alt))
    for s, n_lit, n_term, n_alt in grids:
        spec = grid.TableSpec(n_lit, n_term, n_alt, w_min, 0.5 * math.pi, **extra)
        q, psi = grid.node_values(spec, order=order)
        q32 = q.astype(np.float32).astype(np.float64)
        psi32 = psi.astype(np.float32).astype(np.float64)
        phi_cr, psi_cr = lookup.lookup(spec, q32, psi32, theta, x)
        # the baker's own bilinear variant of its lookup (same coordinates)
        phi_bl, psi_bl = lookup.lookup(spec, q32, psi32, theta, x, kind="linear")

        # 16-bit storage: q and psi as uint16 with one float32 scale per
        # altitude row (the row maximum): half the bytes of float32
        def q16(a):
            scale = np.abs(a).max(axis=1, keepdims=True).astype(np.float32).astype(np.float64)
            scale[scale == 0] = 1.0
            return np.round(a / scale * 65535.0) / 65535.0 * scale
        phi_16, psi_16 = lookup.lookup(spec, q16(q), q16(psi), theta, x)
        schemes = (("catmull-rom", phi_cr, psi_cr), ("bilinear", phi_bl, psi_bl),
                   ("catmull-rom-u16", phi_16, psi_16))
        if s is None:  # an extra grid: the runtime's scheme only
            schemes = schemes[:1]
        for scheme, approx, psi_approx in schemes:
            score, big = lookup.goal_score(approx, phi_ref, phi0)
            with np.errstate(divide="ignore", invalid="ignore"):
                rel = np.where(big, np.abs(approx - phi_ref) / phi_ref, 0.0)
            psi_err = float(np.where(big, np.abs(psi_approx - psi_ref), 0.0).max())
            nbytes = spec.bytes() if scheme != "catmull-rom-u16" else spec.bytes() // 2 + 2 * 4 * spec.n_alt
            rows.append(dict(scheme=scheme, scale=s, n_lit=spec.n_lit, n_term=spec.n_term,
                             n_alt=spec.n_alt, bytes=nbytes, max_rel_err=float(rel.max()),
                             max_score=float(score.max()), max_psi_err=psi_err))
    lam = x * x * ref.lambert_phase(theta)
    score, big = lookup.goal_score(lam, phi_ref, phi0)
    with np.errstate(divide="ignore", invalid="ignore"):
        rel = np.where(big, np.abs(lam - phi_ref) / phi_ref, 0.0)
    rows.append(dict(scheme="lambert", scale=0, bytes=0, max_rel_err=float(rel.max()),
                     max_score=float(score.max())))
    out = dict(rows=rows, n_points=int(theta.size), default=g,
               psi_goal=float(cfg.get("psi_goal_rad", 1e-3)))
    cache.write_text(json.dumps(out, indent=1))
    return out


def _val(bench, name):
    d = bench.get(name)
    try:
        return float(d["value"]) if d else None
    except (TypeError, ValueError):
        return None


def section(outdir) -> str:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    bench = _run_bench()
    sw = _sweep(outdir / "perf_sweep.json")
    rows = sw["rows"]

    ns_tab = _val(bench, "bench.double.earthshine.ns_median")
    ins_tab = _val(bench, "bench.double.earthshine.instructions")
    ns_lam = _val(bench, "bench.double.earthshine_lambert.ns_median")
    ins_lam = _val(bench, "bench.double.earthshine_lambert.instructions")
    ns_quad = _val(bench, "bench.quadrature.phi_psi_reference.ns_median")
    default = next(r for r in rows if r["scheme"] == "catmull-rom" and r["scale"] == 1.0)
    lam = next(r for r in rows if r["scheme"] == "lambert")
    psi_goal = sw.get("psi_goal", 1e-3)

    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    # (a) error against ns per call: what was measured
    pts = []
    if ns_tab:
        pts.append(("table (default, C)", ns_tab, default["max_rel_err"], "o"))
    if ns_lam:
        pts.append(("Lambert far field (C)", ns_lam, lam["max_rel_err"], "s"))
    if ns_quad:
        pts.append(("quadrature (Python, per call)", ns_quad, 1e-12, "^"))
    for name, t, e, m in pts:
        ax[0].loglog([t], [max(e, 1e-13)], m, ms=9, label=name)
    ax[0].set_xlabel("ns per call (host, median)")
    ax[0].set_ylabel("max relative error of phi")
    ax[0].set_title("error against run time")
    ax[0].grid(True, which="both", alpha=0.3)
    ax[0].legend(fontsize=8)
    # (b) error against table bytes: the resolution sweep
    for scheme, m in (("catmull-rom", "o-"), ("bilinear", "s--"), ("catmull-rom-u16", "d:")):
        rr = sorted((r for r in rows if r["scheme"] == scheme), key=lambda r: r["bytes"])
        ax[1].loglog([r["bytes"] / 1024 for r in rr], [r["max_rel_err"] for r in rr], m, label=scheme)
    ax[1].loglog([default["bytes"] / 1024], [default["max_rel_err"]], "k*", ms=14, label="default")
    ax[1].axhline(1e-3, color="gray", lw=0.8, ls=":")
    ax[1].axhline(lam["max_rel_err"], color="C3", lw=0.8, ls="-.", label="Lambert (0 bytes)")
    ax[1].set_xlabel("table size (KiB, float32 phi/x^2 and psi)")
    ax[1].set_ylabel("max relative error of phi")
    ax[1].set_title("error against table size")
    ax[1].grid(True, which="both", alpha=0.3)
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    png = outdir / "perf_pareto.png"
    fig.savefig(png, dpi=110)
    plt.close(fig)

    def f(v, fmt):
        return fmt % v if v is not None else "n/a"

    lines = [
        "## Performance: error against cost",
        "",
        "Measured by `make bench` (bench/run_bench.py) in this run: median ns per call on this "
        "machine and instructions per call from `valgrind --tool=callgrind` (difference of two run "
        "lengths). Errors against the deterministic quadrature `bake.earthshine.reference` at %d test points "
        "between the nodes (bake.earthshine.measure.sample_points); relative error where phi >= 1%% of "
        "phi(0, h). See docs/performance.md for the goals and the flight target." % sw["n_points"],
        "",
        "![Pareto](%s)" % png,
        "",
        "| method | ns/call | instructions/call | table bytes | max rel. error |",
        "|---|---|---|---|---|",
        "| baked table, Catmull-Rom, default grid %dx(%d+%d) (C, double) | %s | %s | %d | %.2e |" % (
            default["n_alt"], default["n_lit"], default["n_term"], f(ns_tab, "%.1f"),
            f(ins_tab, "%.0f"), default["bytes"], default["max_rel_err"]),
        "| the same table, single-precision build (C, float) | %s | %s | %d | %s on the bench scenes (double: %s) |" % (
            f(_val(bench, "bench.float.earthshine.ns_median"), "%.1f"),
            f(_val(bench, "bench.float.earthshine.instructions"), "%.0f"), default["bytes"],
            f(_val(bench, "bench.float.earthshine.max_rel_err_vs_quadrature"), "%.2e"),
            f(_val(bench, "bench.double.earthshine.max_rel_err_vs_quadrature"), "%.2e")),
        "| analytic Lambert far field (C, double) | %s | %s | 0 | %.2e |" % (
            f(ns_lam, "%.1f"), f(ins_lam, "%.0f"), lam["max_rel_err"]),
        "| quadrature bake.earthshine.reference (Python, one call) | %s | n/a | 0 | < 1e-12 (bake/earthshine/reference.py) |" % (
            f(ns_quad, "%.0f")),
        "| same quadrature at the table's accuracy (order %s per axis) | %s | n/a | 0 | <= the table's, on the bench scenes |" % (
            f(_val(bench, "bench.quadrature.matched_accuracy.order"), "%.0f"),
            f(_val(bench, "bench.quadrature.matched_accuracy.ns_median"), "%.0f")),
        "",
        "Resolution sweep (same coordinates as the runtime table; float32 nodes):",
        "",
        "| scheme | grid (alt x (lit+term)) | bytes | max rel. error | goal score (<= 1 meets 1e-3) | max psi error (rad; goal %.0e) |" % psi_goal,
        "|---|---|---|---|---|---|",
    ]
    for r in rows:
        if r["scheme"] == "lambert":
            continue
        lines.append("| %s%s | %dx(%d+%d) | %d | %.2e | %.3g | %.2e |" % (
            r["scheme"], " (default)" if r is default else
            (" (extra grid)" if r["scale"] is None else " x%.2f" % r["scale"]),
            r["n_alt"], r["n_lit"], r["n_term"], r["bytes"], r["max_rel_err"], r["max_score"],
            r["max_psi_err"]))

    def meets(r):
        # both goals: phi (score) and psi
        return r["max_score"] <= 1.0 and r["max_psi_err"] <= psi_goal

    cr = sorted((r for r in rows if r["scheme"] == "catmull-rom"), key=lambda r: r["bytes"])
    meeting = [r for r in cr if meets(r)]
    bl_meeting = [r for r in rows if r["scheme"] == "bilinear" and meets(r)]
    u16_meeting = sorted((r for r in rows if r["scheme"] == "catmull-rom-u16" and meets(r)),
                         key=lambda r: r["bytes"])
    smallest = meeting[0] if meeting else None
    lines += [""]
    if smallest is not None:
        lines.append(
            "Smallest Catmull-Rom grid of the sweep meeting both goals (phi: score <= 1; psi within "
            "the psi goal): %d bytes; the default (%d bytes, score %.2f) %s. Bilinear interpolation of the "
            "same grids %s. The Lambert model costs no flash and %.0f instructions, but its error "
            "(%.2g relative, worst over the test points) rules it out where the finite distance matters; the quadrature is exact and %s times slower "
            "than the table. Pick a coarser grid if the mission accepts more error: bytes fall with "
            "the square of the scale, the cost per call does not change." % (
                smallest["bytes"], default["bytes"], default["max_score"],
                "is that grid" if smallest is default else
                "keeps a margin of %.1fx on the goal, at %d more bytes than the smallest grid that meets "
                "it" % (1.0 / max(default["max_score"], 1e-30), default["bytes"] - smallest["bytes"]),
                "meets it at no resolution tried" if not bl_meeting else
                "meets it from %d bytes" % min(r["bytes"] for r in bl_meeting),
                ins_lam or float("nan"), lam["max_rel_err"],
                f(ns_quad / ns_tab if (ns_quad and ns_tab) else None, "%.0f")))
    else:
        lines.append("No grid of the sweep meets both goals.")
    lines += ["", "Why this default: it is the grid with the altitude rows that the psi goal needs (the psi "
              "error comes from the altitude direction and does not change with the theta nodes) and "
              "the fewest theta nodes that keep about a 2x margin on the phi goal, so that the full runtime "
              "with both tables fits 96 KiB of flash on every Cortex-M configuration (docs/performance.md, "
              "docs/earthshine-table.md)."]
    if u16_meeting:
        lines += ["", "Stored as 16-bit integers with one scale per altitude row (catmull-rom-u16), the "
                  "smallest grid meeting both goals takes %d bytes (score %.2f): a way to "
                  "a smaller flash budget. Not the default: "
                  "the runtime reads float32 (include/oi_table.h)." % (
                      u16_meeting[0]["bytes"], u16_meeting[0]["max_score"])]
    else:
        lines += ["", "16-bit storage with one scale per altitude row meets both goals at no resolution tried."]
    return "\n".join(lines) + "\n"
