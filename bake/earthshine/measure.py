# SPDX-License-Identifier: MIT
"""The earthshine table's measured error: the lookup against the quadrature
reference at points between the nodes (every cell centre, random points with
a fixed seed, the terminator band)."""

import math

import numpy as np

from . import reference as ref
from .grid import H_MEASURE_MIN_KM, HALF_PI, h_from_w, reference_chunked, term_k, term_m, w_from_h
from .lookup import goal_score, lookup

def sample_points(spec, n_random, seed=12345, refine=True):
    """Test points between the nodes: every cell centre of both segments, random
    points uniform in (v, w) per segment, random points uniform in (theta, w),
    and a dense band around the terminator theta = pi/2 +- w."""
    rng = np.random.default_rng(seed)
    w_n = spec.w_nodes()
    wc = 0.5 * (w_n[:-1] + w_n[1:])
    pts_t, pts_w = [], []

    def add(v, w, seg):
        w = np.asarray(w, dtype=float)
        if seg == 0:
            th = v * (HALF_PI - w)
        else:
            th = HALF_PI + w * term_m(2.0 * np.asarray(v) - 1.0, term_k(spec, np.cos(w)))
        pts_t.append(th.ravel())
        pts_w.append(w.ravel())

    for seg, n in ((0, spec.n_lit), (1, spec.n_term)):
        vn = np.linspace(0, 1, n)
        vc = 0.5 * (vn[:-1] + vn[1:])
        V, W = np.meshgrid(vc, wc, indexing="ij")
        add(V, W, seg)
        add(rng.uniform(0, 1, n_random), rng.uniform(spec.w_min, spec.w_max, n_random), seg)
    # a 5 x 5 sub-grid in every terminator cell around the nadir crossing
    # (v in [0.3, 0.8]) below 1000 km, where the error peaks in small spots
    k_hi = int(np.searchsorted(w_n, w_from_h(1000.0))) if refine else 0
    if k_hi > 0:
        sub = (np.arange(5) + 0.5) / 5
        vn = np.linspace(0, 1, spec.n_term)
        cells_v = np.nonzero((vn[:-1] >= 0.3 - 1.0 / (spec.n_term - 1)) & (vn[1:] <= 0.8 + 1.0 / (spec.n_term - 1)))[0]
        cells_w = np.arange(min(k_hi, spec.n_alt - 1))
        V = (vn[cells_v][:, None] + sub[None, :] * (vn[1] - vn[0])).ravel()
        W = (w_n[cells_w][:, None] + sub[None, :] * (w_n[1] - w_n[0])).ravel()
        VV, WW = np.meshgrid(V, W, indexing="ij")
        add(VV, WW, 1)
    # log-uniform in altitude (denser at the bottom, where the terminator is
    # hardest), theta uniform in the terminator band and over [0, pi]
    h_lo = max(h_from_w(spec.w_min), H_MEASURE_MIN_KM)
    h_hi = min(h_from_w(spec.w_max), 1e7)
    hh = 10 ** rng.uniform(math.log10(h_lo), math.log10(h_hi), n_random)
    wl = np.minimum(np.maximum(w_from_h(hh), spec.w_min), spec.w_max)
    add(rng.uniform(0, 1, n_random), wl, 1)
    pts_t.append(rng.uniform(0, math.pi, n_random))
    pts_w.append(wl)
    # near the surface (tables from below 100 km): 41 altitudes log-uniform
    # from 1 m (or the table's floor) to 100 km, 61 theta each across the
    # terminator segment (m in [-1, 1], jittered) and around the lit side's
    # 1% contour (cos theta ~ 0.005 .. 0.05)
    if h_lo < 100.0:
        hs = np.logspace(math.log10(h_lo), 2.0, 41) * (1.0 + 0.01 * rng.uniform(0, 1, 41))
        for hk in hs:
            wk = float(w_from_h(hk))
            if not (spec.w_min <= wk <= spec.w_max):
                continue
            mm = np.clip(np.linspace(-1.0, 1.0, 41) + rng.uniform(-0.02, 0.02, 41), -1.0, 1.0)
            tl = np.arccos(np.geomspace(0.005, 0.05, 20))
            pts_t.append(np.concatenate([HALF_PI + wk * mm, np.minimum(tl, HALF_PI - wk)]))
            pts_w.append(np.full(61, wk))
    # uniform in (theta, w)
    tt = rng.uniform(0, math.pi, n_random)
    ww = rng.uniform(spec.w_min, spec.w_max, n_random)
    pts_t.append(tt)
    pts_w.append(ww)
    theta = np.concatenate(pts_t)
    w = np.concatenate(pts_w)
    w = np.minimum(w, np.nextafter(HALF_PI, 0.0) - 1e-9)  # x > 0 for the reference
    w = np.maximum(w, w_from_h(H_MEASURE_MIN_KM))  # the measured range starts at 1 m
    return np.clip(theta, 0.0, math.pi), w


def measure(spec, q_tab, psi_tab, n_random=4000, order=32, progress=None, rel_goal=1e-3,
            seed=12345, kind="cubic", refine=True):
    """Maximum interpolation error of the table against the reference at
    points between the nodes. q_tab, psi_tab: the stored (float32) values."""
    theta, w = sample_points(spec, n_random, seed, refine)
    x = np.cos(w)
    phi_ref, psi_ref = reference_chunked(theta, x, order, "measure", progress)
    phi0, _ = reference_chunked(np.zeros_like(x), x, order, "measure phi(0,x)", progress)
    phi_i, psi_i = lookup(spec, q_tab.astype(np.float64), psi_tab.astype(np.float64), theta, x,
                          kind)
    s, big = goal_score(phi_i, phi_ref, phi0, rel_goal=rel_goal)
    with np.errstate(divide="ignore", invalid="ignore"):
        rel = np.where(big, np.abs(phi_i - phi_ref) / phi_ref, 0.0)
    absn = np.where(big, 0.0, np.abs(phi_i - phi_ref) / phi0)
    dpsi = np.where(big, np.abs(psi_i - psi_ref), 0.0)
    k = int(np.argmax(s))
    near_term = np.abs(theta - HALF_PI) <= w
    return dict(
        n_points=int(theta.size),
        max_score=float(s.max()),
        max_rel_err=float(rel.max()),
        max_abs_err_frac=float(absn.max()),
        max_psi_err_rad=float(dpsi.max()),
        max_score_terminator=float(s[near_term].max()) if near_term.any() else 0.0,
        worst_theta=float(theta[k]),
        worst_h_km=float(ref.h_from_x(x[k])),
    )
