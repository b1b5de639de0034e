# SPDX-License-Identifier: MIT
"""Brute-force earthshine under a non-uniform albedo field, for the tests.

Independent of the runtime's cubature: adaptive quadrature (scipy quad,
nested) over the Earth's surface in the central angle alpha from the
sub-target point and the azimuth beta about it, of the radiance of a
Lambertian Earth a(p) E0 cos(i) / pi seen from the target, cos(e) / d^2 dA.
The albedo fields are written out here again from their definitions
(Knocke, Ries & Tapley 1988; the bilinear map of include/orbillum.h).
"""
import math

import numpy as np
from scipy import integrate

KNOCKE_T0_JD = 2444960.5


def knocke(epoch_jd):
    """a(p) of the Knocke model at an epoch, p a unit vector (z the rotation axis)."""
    a1 = 0.10 * math.cos(2.0 * math.pi * (epoch_jd - KNOCKE_T0_JD) / 365.25)

    def field(p):
        z = p[2]
        return 0.34 + a1 * z + 0.29 * 0.5 * (3.0 * z * z - 1.0)
    return field


def bilinear_map(grid, rotation_rad):
    """a(p) of a latitude-longitude grid (rows north to south, cells east from
    Greenwich), bilinear between cell centres, periodic in longitude."""
    grid = np.asarray(grid, dtype=np.float64)
    n_lat, n_lon = grid.shape
    c, s = math.cos(rotation_rad), math.sin(rotation_rad)

    def field(p):
        xe, ye = c * p[0] + s * p[1], -s * p[0] + c * p[1]
        colat = math.atan2(math.hypot(xe, ye), p[2])
        fi = min(max(colat / math.pi * n_lat - 0.5, 0.0), n_lat - 1.0)
        i0 = min(int(fi), n_lat - 1)
        i1 = min(i0 + 1, n_lat - 1)
        ti = fi - i0
        lon = math.atan2(ye, xe) % (2.0 * math.pi)
        fj = lon / (2.0 * math.pi) * n_lon - 0.5
        j0 = math.floor(fj)
        tj = fj - j0
        j0 %= n_lon
        j1 = (j0 + 1) % n_lon
        top = (1 - tj) * grid[i0, j0] + tj * grid[i0, j1]
        bot = (1 - tj) * grid[i1, j0] + tj * grid[i1, j1]
        return (1 - ti) * top + ti * bot
    return field


def _frame(sun, target):
    r = np.asarray(target, float)
    rn = np.linalg.norm(r)
    r_hat = r / rn
    s_hat = np.asarray(sun, float) / np.linalg.norm(sun)
    t = s_hat - np.dot(s_hat, r_hat) * r_hat
    if np.linalg.norm(t) < 1e-12:
        t = np.cross(r_hat, [1.0, 0.0, 0.0] if abs(r_hat[0]) < 0.7 else [0.0, 1.0, 0.0])
    ex = t / np.linalg.norm(t)
    ey = np.cross(r_hat, ex)
    return rn, r_hat, s_hat, ex, ey


def lambert_phase(xi):
    return (math.sin(xi) + (math.pi - xi) * math.cos(xi)) / math.pi


def earthshine(sun, target, field, radius_km=6378.137, obs_hat=None, epsrel=1e-10):
    """(E, V, F): scalar irradiance per unit solar irradiance at the Earth, the
    vector irradiance (towards where the light comes from) and, with obs_hat,
    the Lambertian sphere's flux shape sum L p(xi) dOmega."""
    rn, r_hat, s_hat, ex, ey = _frame(sun, target)
    R = radius_km
    w = math.acos(R / rn)

    def point(alpha, beta):
        u = math.cos(beta) * ex + math.sin(beta) * ey
        return math.cos(alpha) * r_hat + math.sin(alpha) * u

    def kernel(alpha, beta, what):
        p = point(alpha, beta)
        ci = float(np.dot(p, s_hat))
        if ci <= 0.0:
            return 0.0
        to_t = rn * r_hat - R * p
        d = float(np.linalg.norm(to_t))
        ce = float(np.dot(to_t, p)) / d
        if ce <= 0.0:
            return 0.0
        k = field(p) * ci * ce / (math.pi * d * d) * R * R * math.sin(alpha)
        if what == 0:
            return k
        om = -to_t / d
        if what <= 3:
            return k * om[what - 1]
        xi = math.acos(max(-1.0, min(1.0, float(np.dot(om, obs_hat)))))
        return k * lambert_phase(xi)

    def lit(beta):
        # the terminator along the great circle: cos a cos t + sin a cos b sin t = 0
        A = float(np.dot(r_hat, s_hat))
        B = float(np.dot(math.cos(beta) * ex + math.sin(beta) * ey, s_hat))
        lo, hi = 0.0, w
        root = math.atan2(A, -B)  # the zero of A cos a + B sin a in [0, pi)
        if root < 0:
            root += math.pi
        if root < w:
            if A >= 0:
                hi = root
            else:
                lo = root
        elif A < 0:
            return None
        return lo, hi

    def inner(beta, what):
        b = lit(beta)
        if b is None or b[1] <= b[0]:
            return 0.0
        lo, hi = b
        # resolve the peak at the nadir of a low target
        scale = max(rn - R, 1e-6) / R
        pts = [x for x in (scale, 10 * scale) if lo < x < hi]
        val, _ = integrate.quad(kernel, lo, hi, args=(beta, what), epsabs=0.0, epsrel=epsrel,
                                limit=200, points=pts or None)
        return val

    def outer(what):
        val, _ = integrate.quad(inner, -math.pi, math.pi, args=(what,), epsabs=0.0,
                                epsrel=epsrel, limit=200)
        return val

    E = outer(0)
    V = np.array([outer(1), outer(2), outer(3)])
    F = outer(4) if obs_hat is not None else None
    return E, V, F
