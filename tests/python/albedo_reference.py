# SPDX-License-Identifier: MIT
"""Brute-force earthshine under a non-uniform albedo field, for the tests.

Independent of the runtime's cubature (src/sources/earthshine_albedo.c: Gauss rules
in the emission angle and the azimuth about the nadir, 8 x 32 nodes): here
the surface integral over the central angle alpha from the sub-target point
(composite 8-point Gauss on 96 panels, graded towards the nadir by an
exponential map of the target's altitude) and an adaptive outer quadrature
(scipy quad) over the azimuth beta, of the radiance of a Lambertian Earth
a(p) E0 cos(i) / pi seen from the target, cos(e) / d^2 dA. The albedo fields
are written out here again from their definitions (Knocke, Ries & Tapley
1988; the bilinear map of include/orbillum.h), vectorised.
"""
import math

import numpy as np
from scipy import integrate

KNOCKE_T0_JD = 2444960.5
_GX, _GW = np.polynomial.legendre.leggauss(8)
PANELS = 96


def knocke(epoch_jd):
    """a(p) of the Knocke model at an epoch, p unit vectors (3, n), z the rotation axis."""
    a1 = 0.10 * math.cos(2.0 * math.pi * (epoch_jd - KNOCKE_T0_JD) / 365.25)

    def field(p):
        z = p[2]
        return 0.34 + a1 * z + 0.29 * 0.5 * (3.0 * z * z - 1.0)
    return field


def uniform(value=1.0):
    return lambda p: np.full(p.shape[1], value)


def bilinear_map(grid, rotation_rad):
    """a(p) of a latitude-longitude grid (rows north to south, cells east from
    Greenwich), bilinear between cell centres, periodic in longitude."""
    grid = np.asarray(grid, dtype=np.float64)
    n_lat, n_lon = grid.shape
    c, s = math.cos(rotation_rad), math.sin(rotation_rad)

    def field(p):
        xe, ye = c * p[0] + s * p[1], -s * p[0] + c * p[1]
        colat = np.arctan2(np.hypot(xe, ye), p[2])
        fi = np.clip(colat / math.pi * n_lat - 0.5, 0.0, n_lat - 1.0)
        i0 = np.minimum(fi.astype(int), n_lat - 1)
        i1 = np.minimum(i0 + 1, n_lat - 1)
        ti = fi - i0
        lon = np.mod(np.arctan2(ye, xe), 2.0 * math.pi)
        fj = lon / (2.0 * math.pi) * n_lon - 0.5
        j0 = np.floor(fj)
        tj = fj - j0
        j0 = np.mod(j0.astype(int), n_lon)
        j1 = np.mod(j0 + 1, n_lon)
        top = (1 - tj) * grid[i0, j0] + tj * grid[i0, j1]
        bot = (1 - tj) * grid[i1, j0] + tj * grid[i1, j1]
        return (1 - ti) * top + ti * bot
    return field


def _frame(sun, target):
    r = np.asarray(target, float)
    rn = float(np.linalg.norm(r))
    r_hat = r / rn
    s_hat = np.asarray(sun, float) / np.linalg.norm(sun)
    t = s_hat - np.dot(s_hat, r_hat) * r_hat
    if np.linalg.norm(t) < 1e-9:
        t = np.cross(r_hat, [1.0, 0.0, 0.0] if abs(r_hat[0]) < 0.7 else [0.0, 1.0, 0.0])
    t = t - np.dot(t, r_hat) * r_hat
    ex = t / np.linalg.norm(t)
    ey = np.cross(r_hat, ex)
    return rn, r_hat, s_hat, ex, ey


def lambert_phase(xi):
    return (np.sin(xi) + (math.pi - xi) * np.cos(xi)) / math.pi


def earthshine(sun, target, field, radius_km=6378.137, obs_hat=None, epsrel=1e-9, panels=PANELS,
               beta_panels=None):
    """(E, V, F): scalar irradiance per unit solar irradiance at the Earth, the
    vector irradiance (towards where the light comes from) and, with obs_hat,
    the Lambertian sphere's flux sum of L p(xi) dOmega (else None). panels:
    the Gauss panels in alpha; beta_panels: instead of the adaptive outer
    quadrature, composite 8-point Gauss on that many equal azimuth panels
    (for fields with a kink every degree, where quad runs out of
    subdivisions)."""
    rn, r_hat, s_hat, ex, ey = _frame(sun, target)
    R = radius_km
    w = math.acos(R / rn)
    scale = max(rn - R, 1e-9) / R  # angular size of the nadir's peak

    def lit(beta):
        # the terminator along the great circle: A cos(a) + B sin(a) = 0
        A = float(np.dot(r_hat, s_hat))
        B = float(np.dot(math.cos(beta) * ex + math.sin(beta) * ey, s_hat))
        root = math.atan2(A, -B) % math.pi
        lo, hi = 0.0, w
        if root < w:
            if A >= 0:
                hi = root
            else:
                lo = root
        elif A < 0:
            return None
        return (lo, hi) if hi > lo else None

    def nodes(lo, hi):
        # panels uniform in tau, alpha = lo + (hi - lo) (e^{q tau} - 1) / (e^q - 1)
        q = math.log1p((hi - lo) / scale) if lo == 0.0 else 0.0
        edges = np.linspace(0.0, 1.0, panels + 1)
        mid = 0.5 * (edges[1:] + edges[:-1])[:, None]
        half = 0.5 * (edges[1] - edges[0])
        tau = (mid + half * _GX[None, :]).ravel()
        wt = np.tile(half * _GW, panels)
        if q > 1e-6:
            g = np.expm1(q * tau) / math.expm1(q)
            dg = q * np.exp(q * tau) / math.expm1(q)
        else:
            g, dg = tau, np.ones_like(tau)
        return lo + (hi - lo) * g, wt * (hi - lo) * dg

    def inner(beta, what):
        b = lit(beta)
        if b is None:
            return np.zeros(5) if what is None else 0.0
        alpha, wa = nodes(*b)
        u = math.cos(beta) * ex + math.sin(beta) * ey
        p = np.cos(alpha)[None, :] * r_hat[:, None] + np.sin(alpha)[None, :] * u[:, None]
        ci = np.maximum(s_hat @ p, 0.0)
        to_t = rn * r_hat[:, None] - R * p
        d = np.linalg.norm(to_t, axis=0)
        ce = np.maximum(np.sum(to_t * p, axis=0) / d, 0.0)
        k = wa * field(p) * ci * ce / (math.pi * d * d) * R * R * np.sin(alpha)
        if what is None:  # every sum
            om = -to_t / d
            ph = (np.sum(k * lambert_phase(np.arccos(np.clip(obs_hat @ om, -1.0, 1.0))))
                  if obs_hat is not None else 0.0)
            return np.array([np.sum(k), *(om @ k), ph])
        if what == 0:
            return float(np.sum(k))
        om = -to_t / d
        if what <= 3:
            return float(np.sum(k * om[what - 1]))
        xi = np.arccos(np.clip(obs_hat @ om, -1.0, 1.0))
        return float(np.sum(k * lambert_phase(xi)))

    def outer(what):
        val, _ = integrate.quad(inner, -math.pi, math.pi, args=(what,), epsabs=0.0,
                                epsrel=epsrel, limit=400)
        return val

    if beta_panels is not None:
        # every sum at once, azimuth by azimuth
        edges = np.linspace(-math.pi, math.pi, beta_panels + 1)
        half = 0.5 * (edges[1] - edges[0])
        tot = np.zeros(5)
        for b0 in 0.5 * (edges[1:] + edges[:-1]):
            for gx, gw in zip(_GX, _GW):
                tot += half * gw * inner(b0 + half * gx, None)
        return tot[0], tot[1:4], (tot[4] if obs_hat is not None else None)

    E = outer(0)
    V = np.array([outer(1), outer(2), outer(3)])
    F = outer(4) if obs_hat is not None else None
    return E, V, F
