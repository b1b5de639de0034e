# SPDX-License-Identifier: MIT
"""The angular distribution of earthshine at a point, by a quadrature over the
visible sunlit Earth that uses no table (docs/earthshine-angular.md).

Unit sphere (R = 1), the point T at distance r = 1/x on +z, the Sun along
s = (sin theta, 0, cos theta). A surface point in polar coordinates (a, b)
about the sub-point: n = (sin a cos b, sin a sin b, cos a); visible where
cos a > x (a < w = acos x), lit where n.s > 0, i.e. |b| < b_m(a) in closed
form. Its radiance per unit albedo and unit solar irradiance is n.s / pi, the
solid angle it subtends dOmega = cos(e) dA / d^2, dA = sin a da db.

`nodes` returns the incoming directions omega (unit vectors from T towards
the surface point, in the local frame: z the zenith at T, x towards the Sun's
side, y completing it) and weights L dOmega, for b >= 0 only: the
distribution is symmetric under y -> -y, so every node stands for itself and
its mirror image (`mirrored` unfolds them). The a range is split at the
terminator's tangency |pi/2 - theta| (where b_m stops being analytic) and at
multiples of the altitude (the 1/d^3 peak under the point); Gauss-Legendre
on each piece in a and on [0, b_m] in b.

Everything the runtime's moments stand for is a sum over these nodes:
  phi = sum w                             (scalar irradiance)
  E(N) = sum w max(0, N.omega)            (a flat facet of normal N)
  F(o) = sum w p(acos(o.omega))           (a Lambertian sphere seen from o,
                                           per a^2/d^2 and target albedo)
"""

import numpy as np

from ..common.quadrature import gauss_legendre_01

N_A = 24   # Gauss-Legendre order per a piece
N_B = 32   # order in b


def _pieces(theta, x):
    w = np.arccos(x)
    hr = 1.0 / x - 1.0
    cuts = [0.0, w]
    for c in (hr, 4.0 * hr, 16.0 * hr, abs(0.5 * np.pi - theta)):
        if 0.0 < c < w:
            cuts.append(c)
    cuts = sorted(set(cuts))
    return list(zip(cuts[:-1], cuts[1:]))


def nodes(theta, x, n_a=N_A, n_b=N_B):
    """(omega[k, 3], weight[k]) at one point; weights for b >= 0 (see above)."""
    theta = float(np.clip(theta, 0.0, np.pi))
    x = float(x)
    if not (0.0 < x < 1.0):
        raise ValueError("x = R/r must be in (0, 1)")
    r = 1.0 / x
    st, ct = np.sin(theta), np.cos(theta)
    ta, wa = gauss_legendre_01(n_a)
    tb, wb = gauss_legendre_01(n_b)
    om, wt = [], []
    for a0, a1 in _pieces(theta, x):
        a = a0 + (a1 - a0) * ta
        da = (a1 - a0) * wa
        sa, ca = np.sin(a), np.cos(a)
        with np.errstate(divide="ignore", invalid="ignore"):
            v = np.where(sa * st > 0.0, -ca * ct / (sa * st), np.where(ct > 0, -np.inf, np.inf))
        bm = np.arccos(np.clip(v, -1.0, 1.0))
        b = bm[:, None] * tb[None, :]
        db = bm[:, None] * wb[None, :]
        sa2, ca2 = sa[:, None], ca[:, None]
        px, py, pz = sa2 * np.cos(b), sa2 * np.sin(b), ca2 * np.ones_like(b)
        dx, dy, dz = px, py, pz - r
        d2 = dx * dx + dy * dy + dz * dz
        d = np.sqrt(d2)
        cos_i = np.maximum(px * st + pz * ct, 0.0)
        cos_e = np.maximum(r * ca2 - 1.0, 0.0) / d
        wgt = cos_i / np.pi * cos_e / d2 * sa2 * da[:, None] * db
        om.append(np.stack([dx / d, dy / d, dz / d], axis=-1).reshape(-1, 3))
        wt.append(wgt.ravel())
    return np.concatenate(om), np.concatenate(wt)


def mirrored(omega, weight):
    """The nodes with their mirror images (y -> -y), each with its weight."""
    img = omega * np.array([1.0, -1.0, 1.0])
    return np.concatenate([omega, img]), np.concatenate([weight, weight])


def lambert_phase(t):
    t = np.clip(t, 0.0, np.pi)
    return 2.0 / (3.0 * np.pi) * ((np.pi - t) * np.cos(t) + np.sin(t))


def scalar(theta, x):
    om, w = nodes(theta, x)
    return 2.0 * w.sum()


def plate(theta, x, normal, n_a=N_A, n_b=N_B):
    """Irradiance on a one-sided facet of unit normal(s) (local frame)."""
    om, w = mirrored(*nodes(theta, x, n_a, n_b))
    n = np.atleast_2d(normal)
    return (np.maximum(n @ om.T, 0.0) * w).sum(axis=1)


def sphere(theta, x, obs, n_a=N_A, n_b=N_B):
    """Flux of a Lambertian sphere towards unit direction(s) obs (local frame),
    per unit target albedo and a^2/d^2."""
    om, w = mirrored(*nodes(theta, x, n_a, n_b))
    o = np.atleast_2d(obs)
    c = np.clip(o @ om.T, -1.0, 1.0)
    return (lambert_phase(np.arccos(c)) * w).sum(axis=1)
