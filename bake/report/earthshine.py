# SPDX-License-Identifier: MIT
"""Report section on the earthshine table (called by bake/report/__main__.py).

section(outdir) -> markdown, and PNGs written into outdir:
  table_image.png        the seed's Fig. 7 redone: phi(theta, h) of the shipped table
  table_curves.png       the seed's Fig. 11 redone: curve shapes at several altitudes
  table_error_bytes.png  interpolation error against resolution and bytes
  table_farfield.png     error of the far-field model against altitude
Every number comes from code run here (reference quadrature, table lookup).
"""

import math
import os
import time

import numpy as np

from ..earthshine import grid, lookup, measure
from ..earthshine import reference as ref

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TABLE = "oi_earth_diffuse"


def _load_default():
    from ..earthshine import table as emit

    spec, q, psi, side, _ = emit.load(os.path.join(ROOT, "tables"), TABLE)
    return spec, q.astype(float), psi.astype(float), side


def _fig_image(spec, q, psi, path, plt):
    th = np.linspace(0, math.pi, 361)
    h = np.logspace(-3, 6, 361)  # 1 m .. 1e6 km
    TH, H = np.meshgrid(th, h)
    x = ref.x_from_h(H)
    phi, ps = lookup.lookup(spec, q, psi, TH, x)
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    with np.errstate(divide="ignore"):
        im = ax[0].pcolormesh(np.degrees(th), h, np.log10(np.maximum(phi, 1e-12)), shading="auto",
                              vmin=-8, vmax=0.4, cmap="magma")
    fig.colorbar(im, ax=ax[0], label="log10 phi")
    ax[0].plot(np.degrees(math.pi / 2 + np.arccos(ref.x_from_h(h))), h, "c--", lw=1,
               label="theta = 90 deg + acos(R/r): phi = 0 beyond")
    im2 = ax[1].pcolormesh(np.degrees(th), h, np.degrees(ps), shading="auto", cmap="viridis")
    fig.colorbar(im2, ax=ax[1], label="psi (deg)")
    for a, t in zip(ax, ("phi(theta, h) per unit albedo and solar irradiance",
                         "mean incidence direction psi (from nadir)")):
        a.set_yscale("log")
        a.set_xlabel("theta (deg)")
        a.set_ylabel("altitude h (km)")
        a.set_title(t, fontsize=10)
    ax[0].legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _fig_curves(path, plt):
    th = np.linspace(0, math.pi, 721)
    alts = [0.001, 10.0, 100.0, 400.0, 2000.0, 20200.0, 35786.0, 384400.0]
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    rows = []
    for hk in alts:
        x = float(ref.x_from_h(hk))
        phi, psi = ref.phi_psi_reference(th, x, 32, 32)
        ax[0].plot(np.degrees(th), phi / phi[0], label="h = %g km" % hk)
        ax[1].plot(np.degrees(th), np.degrees(psi), label="h = %g km" % hk)
        rows.append((hk, phi[0], phi[0] / (x * x * 2 / 3)))
    p = ref.lambert_phase(th)
    ax[0].plot(np.degrees(th), p / p[0], "k--", label="far field p(theta)/p(0)")
    ax[0].set_ylabel("phi(theta, h) / phi(0, h)")
    ax[1].set_ylabel("psi (deg)")
    for a in ax:
        a.set_xlabel("theta (deg)")
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return rows


def _error_vs_bytes(path, plt, quick=False):
    w_lo = 0.0  # from the surface (format 4: two lit columns are exact)
    sizes = [(2, 17, 32), (2, 33, 48), (2, 49, 64), (2, 65, 96), (2, 65, 122), (2, 97, 160)]
    if quick:
        sizes = sizes[:3]
    res = {"cubic": [], "linear": []}
    for n_lit, n_term, n_alt in sizes:
        spec = grid.TableSpec(n_lit, n_term, n_alt, w_lo, math.pi / 2)
        t0 = time.monotonic()
        q, psi = grid.node_values(spec, order=32, progress=False)
        t_bake = time.monotonic() - t0
        q32, p32 = q.astype(np.float32), psi.astype(np.float32)
        for kind in res:
            m = measure.measure(spec, q32, p32, n_random=800, order=32, progress=False, seed=777, kind=kind)
            res[kind].append((spec.bytes(), m["max_rel_err"], m["max_score"], m["max_psi_err_rad"],
                              (n_lit, n_term, n_alt), t_bake))
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    for kind, mk in (("cubic", "o-"), ("linear", "s--")):
        b = [r[0] / 1024 for r in res[kind]]
        ax.loglog(b, [r[2] for r in res[kind]], mk, label="%s: max error / goal" % (
            "Catmull-Rom" if kind == "cubic" else "bilinear"))
    ax.axhline(1.0, color="r", lw=0.8, label="goal")
    ax.axvline(64, color="k", lw=0.8, ls=":", label="64 KiB budget")
    ax.set_xlabel("payload (KiB, phi and psi as float32)")
    ax.set_ylabel("max error in units of the goal")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return res


def _farfield(path, plt):
    hs = np.logspace(2, 7.5, 23)
    th = np.linspace(0, math.pi, 1441)
    out = []
    for hk in hs:
        x = float(ref.x_from_h(hk))
        phi = ref.phi_reference(th, x, 32, 32)
        s, big = lookup.goal_score(ref.far_field(th, x), phi, phi[0])
        out.append((hk, s.max()))
    fig, ax = plt.subplots(figsize=(6.5, 4.0))
    ax.loglog([o[0] for o in out], [o[1] for o in out], "o-")
    ax.axhline(1.0, color="r", lw=0.8)
    ax.axvline(384400, color="k", ls=":", lw=0.8, label="Moon")
    ax.set_xlabel("altitude (km)")
    ax.set_ylabel("far field x^2 p(theta): max error / goal")
    ax.grid(alpha=0.3, which="both")
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return out


BAND_EDGES_KM = [0.0, 0.01, 0.1, 1.0, 10.0, 30.0, 100.0, 1000.0, 1e5, math.inf]


def bands(spec, q, psi, n_random=4000, seed=12345):
    """Max error / goal and psi error by altitude band, at the bake's
    measurement points (measure.sample_points). Returns markdown rows."""
    theta, w = measure.sample_points(spec, n_random, seed, True)
    x = np.cos(w)
    phi_r, psi_r = grid.reference_chunked(theta, x, 32, "bands", False)
    phi0, _ = grid.reference_chunked(np.zeros_like(x), x, 32, "bands", False)
    phi_i, psi_i = lookup.lookup(spec, q.astype(float), psi.astype(float), theta, x)
    s, big = lookup.goal_score(phi_i, phi_r, phi0)
    dpsi = np.where(big, np.abs(psi_i - psi_r), 0.0)
    h = ref.h_from_x(x)
    rows = ["| altitude (km) | points | max error / goal | psi error (rad) | worst at m = (theta - 90 deg)/w |",
            "|---|---|---|---|---|"]
    for a, b in zip(BAND_EDGES_KM[:-1], BAND_EDGES_KM[1:]):
        m = (h >= a) & (h < b)
        if m.any():
            k = int(np.argmax(np.where(m, s, -1.0)))
            rows.append("| %g - %g | %d | %.3f | %.2e | %.3f |" % (
                a, b, int(m.sum()), s[m].max(), dpsi[m].max(), (theta[k] - math.pi / 2) / w[k]))
    return rows


def section(outdir, quick=False):
    """Markdown of the table section; PNGs into outdir."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    os.makedirs(outdir, exist_ok=True)
    spec, q, psi, side = _load_default()
    _fig_image(spec, q, psi, os.path.join(outdir, "table_image.png"), plt)
    rows = _fig_curves(os.path.join(outdir, "table_curves.png"), plt)
    res = _error_vs_bytes(os.path.join(outdir, "table_error_bytes.png"), plt, quick)
    ff = _farfield(os.path.join(outdir, "table_farfield.png"), plt)

    t0 = time.monotonic()
    m = measure.measure(spec, q.astype(np.float32), psi.astype(np.float32), n_random=3000, order=32,
                     progress=False, seed=2024)
    t_meas = time.monotonic() - t0
    hmin, hmax = spec.h_range_km()
    ff_ok = [o[0] for o in ff if o[1] <= 1.0]

    def img(name):  # bake/report/__main__.py rewrites outdir/ into report/
        return os.path.join(str(outdir), name)

    L = []
    L.append("## Earthshine table (no atmosphere)\n")
    L.append("Design: docs/earthshine-table.md. Reference: bake/earthshine/reference.py (quadrature, "
             "< 1e-11 relative at the bake's order, checked against mpmath and closed forms).\n")
    L.append("Shipped table `%s`: %d+%d theta nodes x %d altitude nodes, %d bytes (phi and psi, "
             "float32), altitude %s to %s.\n" % (
                 TABLE, spec.n_lit, spec.n_term, spec.n_alt, spec.bytes(),
                 "the surface (measured from 1 m)" if hmin == 0 else "%.0f km" % hmin,
                 "infinity" if hmax == math.inf else "%.0f km" % hmax))
    L.append("Measured now at %d points between the nodes (seed 2024, not the bake's), in %.1f s:\n" % (
        m["n_points"], t_meas))
    L.append("| quantity | measured | goal |\n|---|---|---|")
    L.append("| max relative error of phi where phi >= 1%% phi(0,x) | %.3e | 1e-3 |" % m["max_rel_err"])
    L.append("| max absolute error / phi(0,x) elsewhere | %.3e | 1e-5 |" % m["max_abs_err_frac"])
    L.append("| max error in units of the goal (whole domain) | %.3f | <= 1 |" % m["max_score"])
    L.append("| same, terminator band theta = 90 deg +- acos(R/r) | %.3f | <= 1 |" % m["max_score_terminator"])
    L.append("| max psi error where phi >= 1%% phi(0,x) (rad) | %.3e | 1e-3 |" % m["max_psi_err_rad"])
    L.append("| worst point | theta = %.4f rad, h = %.4g km | |" % (m["worst_theta"], m["worst_h_km"]))
    L.append("| payload bytes | %d | <= 65536 |\n" % spec.bytes())
    L.append("By altitude band (the bake's measurement points):\n")
    L.extend(bands(spec, q, psi))
    L.append("")
    L.append("![table image](%s)\n" % img("table_image.png"))
    L.append("*Seed Fig. 7 redone*: the table's phi and psi over theta and log altitude "
             "(the seed tabulated uniform in h; here w = acos(R/r)).\n")
    L.append("![curves](%s)\n" % img("table_curves.png"))
    L.append("*Seed Fig. 11 redone*: curve shapes phi(theta)/phi(0) at several altitudes, and the "
             "mean direction psi. Subsolar values:\n")
    L.append("| h (km) | phi(0, h) | phi(0,h) / ((R/r)^2 p(0)) |\n|---|---|---|")
    for hk, p0, ratio in rows:
        L.append("| %g | %.6e | %.5f |" % (hk, p0, ratio))
    L.append("\n![error vs bytes](%s)\n" % img("table_error_bytes.png"))
    L.append("Interpolation error against resolution and bytes, the surface (1 m) to infinity "
             "(800 random points per segment plus every cell centre):\n")
    L.append("| grid (lit+term x alt) | bytes | Catmull-Rom max rel err | CR error/goal | "
             "bilinear max rel err | bilinear error/goal | node bake (s) |\n|---|---|---|---|---|---|---|")
    for rc, rl in zip(res["cubic"], res["linear"]):
        L.append("| %d+%d x %d | %d | %.2e | %.3f | %.2e | %.3f | %.1f |" % (
            rc[4][0], rc[4][1], rc[4][2], rc[0], rc[1], rc[2], rl[1], rl[2], rc[5]))
    L.append("\n![far field](%s)\n" % img("table_farfield.png"))
    L.append("Far-field Lambert model x^2 p(theta) against the reference, max error in units of "
             "the goal over theta: %s. It stays outside the goal to %s, so the table runs to "
             "infinity (its last node is x = 0, where q = p(theta) exactly) and the far field is "
             "used only outside a scene table's altitude band or by request.\n" % (
                 ", ".join("%.3g km: %.3g" % o for o in ff[::4]),
                 ("%.3g km" % ff_ok[0]) if ff_ok else "beyond %.3g km" % ff[-1][0]))
    return "\n".join(L) + "\n"


if __name__ == "__main__":
    import sys

    if "--bands" in sys.argv:  # only the per-band error table of the default table
        sp, qq, pp, _ = _load_default()
        print("\n".join(bands(sp, qq, pp)))
        sys.exit(0)
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "report_table")
    print(section(out, quick="--quick" in sys.argv))
