# SPDX-License-Identifier: MIT
"""The earthshine table's lookup, the Python mirror of the runtime's (src/): the
same coordinates and Catmull-Rom interpolation, and the error in units of the goal.

interp:    Catmull-Rom (cubic convolution, a = -1/2) in v and in w, per segment,
           ghost nodes by linear extrapolation (f[-1] = 2 f[0] - f[1]) at every
           segment end, so no stencil crosses the kink of the theta map
           (quadratic below a surface row w = 0).
"""

import math

import numpy as np

from .grid import HALF_PI, term_k, term_t  # noqa: F401

def _cr_weights(f):
    f2 = f * f
    f3 = f2 * f
    return (0.5 * (-f3 + 2 * f2 - f), 0.5 * (3 * f3 - 5 * f2 + 2),
            0.5 * (-3 * f3 + 4 * f2 + f), 0.5 * (f3 - f2))


def _segment_interp(tab, fv, fw, kind="cubic", surface=False):
    """Catmull-Rom on one segment tab[n_alt, n] at fractional indices (fv along
    theta, fw along altitude), ghosts by linear extrapolation; kind="linear":
    bilinear (for the comparison in the report). surface: the first row is
    w = 0, its ghost row by quadratic extrapolation."""
    n_alt, n = tab.shape
    if kind == "linear":
        i = np.clip(np.floor(fv).astype(int), 0, n - 2)
        a = fv - i
        j = np.clip(np.floor(fw).astype(int), 0, n_alt - 2)
        b = fw - j
        return ((1 - a) * (1 - b) * tab[j, i] + a * (1 - b) * tab[j, i + 1]
                + (1 - a) * b * tab[j + 1, i] + a * b * tab[j + 1, i + 1])
    T = np.pad(tab, 1, mode="reflect", reflect_type="odd")  # ghost = 2 f0 - f1
    if surface and n_alt >= 3:
        # the row w = 0: quadratic extrapolation (q = 2w - 2w^2 + ... at the
        # lit edge: the linear ghost cost 7x the goal at h ~ 150 m)
        T[0, :] = 3.0 * T[1, :] - 3.0 * T[2, :] + T[3, :]
    i = np.clip(np.floor(fv).astype(int), 0, n - 2)
    a = fv - i
    j = np.clip(np.floor(fw).astype(int), 0, n_alt - 2)
    b = fw - j
    wa = _cr_weights(a)
    wb = _cr_weights(b)
    out = np.zeros(np.shape(fv))
    for p in range(4):
        row = np.zeros(np.shape(fv))
        for k in range(4):
            row = row + wb[k] * T[j + k, i + p]
        out = out + wa[p] * row
    return out


def lookup(spec, q_tab, psi_tab, theta, x, kind="cubic"):
    """Interpolated (phi, psi) at (theta, x) inside the altitude range of the
    table: the numpy mirror of the runtime's lookup (double precision)."""
    theta = np.clip(np.asarray(theta, dtype=float), 0.0, math.pi)
    x = np.asarray(x, dtype=float)
    theta, x = np.broadcast_arrays(theta, x)
    w = np.arctan2(np.sqrt((1.0 - x) * (1.0 + x)), x)
    fw = (w - spec.w_min) / (spec.w_max - spec.w_min) * (spec.n_alt - 1)
    tb = HALF_PI - w
    lit = theta <= tb
    with np.errstate(divide="ignore", invalid="ignore"):
        v_lit = np.where(tb > 0, theta / np.where(tb > 0, tb, 1.0), 0.0)
        m = np.clip((theta - HALF_PI) / w, -1.0, 1.0)
        v_term = 0.5 * (term_t(m, term_k(spec, x)) + 1.0)
    fl = np.clip(v_lit, 0, 1) * (spec.n_lit - 1)
    ft = np.clip(v_term, 0, 1) * (spec.n_term - 1)
    sf = spec.w_min == 0.0
    q_lit = _segment_interp(q_tab[:, :spec.n_lit], fl, fw, kind, sf) * np.cos(theta)
    q_term = _segment_interp(q_tab[:, spec.n_lit:], ft, fw, kind, sf) * w
    g_lit = _segment_interp(psi_tab[:, :spec.n_lit], fl, fw, kind, sf) * w
    p_lit = np.arctan2(g_lit * np.sin(theta), np.cos(theta))
    p_term = _segment_interp(psi_tab[:, spec.n_lit:], ft, fw, kind, sf)
    q = np.where(lit, q_lit, q_term)
    ps = np.where(lit, p_lit, p_term)
    dark = theta >= HALF_PI + w
    phi = np.where(dark, 0.0, np.maximum(q, 0.0) * x * x)
    ps = np.where(phi > 0, np.clip(ps, 0.0, np.arcsin(np.clip(x, 0, 1))), 0.0)
    return phi, ps


def goal_score(approx, phi, phi0, rel_goal=1e-3, abs_frac=None, big_frac=0.01):
    """Error in units of the goal: relative error / rel_goal where phi >= big_frac
    phi0, absolute error / (abs_frac phi0) elsewhere (abs_frac = rel_goal * big_frac
    by default: 1e-5 for the default goal). <= 1 meets the goal."""
    if abs_frac is None:
        abs_frac = rel_goal * big_frac
    big = phi >= big_frac * phi0
    err = np.abs(approx - phi)
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(big, err / (rel_goal * np.where(big, phi, 1.0)), err / (abs_frac * phi0))
    return s, big
