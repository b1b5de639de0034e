# SPDX-License-Identifier: MIT
"""The atmosphere table's measured error: the lookup (bake/atmosphere/window.py)
against the ray reference at random off-grid points (fixed seed), figures
rounded to 4 significant digits (the provenance must not depend on libm's last
bits)."""

import numpy as np

from ..common.emit import round_sig
from ..common.progress import Progress
from . import rays as rays_mod
from .window import D_MAX, D_MIN, NT, Z_MAX, Z_MIN, Window, lookup

MEASURE_SEED = 1


def measure(rays, q, psi, alpha_c, h_c, n=400, seed=MEASURE_SEED, progress=False,
            law=rays_mod.NL94_559):
    """Errors of the lookup against the reference at random off-grid points
    (fixed seed): z log-uniform, rho uniform in the window, d uniform."""
    rng = np.random.default_rng(seed)
    zs = Z_MIN * (Z_MAX / Z_MIN) ** rng.uniform(0, 1, n)
    ds = rng.uniform(D_MIN, D_MAX, n)
    ts = rng.uniform(0, 1, n)
    out = []
    bar = Progress(n, "atmosphere: measure", progress)
    for m in range(n):
        nodes = Window(zs[m], ds[m], alpha_c, h_c).nodes()
        rho = np.interp(ts[m] * (NT - 1), np.arange(NT), nodes)
        F, p = rays_mod.fraction(rays, zs[m], [rho], d_sun=ds[m], law=law)
        Fl, pl, st = lookup(q, psi, alpha_c, h_c, zs[m], rho, ds[m])
        if st == 1:
            Fl, pl = rays_mod.fraction(None, zs[m], [rho], d_sun=ds[m], law=law)
            Fl, pl = Fl[0], pl[0]
        out.append((zs[m], rho, ds[m], F[0], Fl, p[0], pl))
        bar.step()
    a = np.array(out)
    F, Fl = a[:, 3], a[:, 4]
    abs_err = np.abs(Fl - F)
    big = F > 1e-4
    rel = np.abs(Fl[big] - F[big]) / F[big]
    w = F > 1e-3
    psi_err = np.abs(a[w, 6] - a[w, 5])
    # rounded: the text of the provenance must not depend on libm's last bits
    r = round_sig
    return {
        "n_points": int(n),
        "max_abs_error": r(abs_err.max()),
        "rms_abs_error": r(np.sqrt(np.mean(abs_err ** 2))),
        "max_rel_error_F_gt_1e-4": r(rel.max()) if rel.size else 0.0,
        "max_psi_error_rad_F_gt_1e-3": r(psi_err.max()) if psi_err.size else 0.0,
    }, a
