# SPDX-License-Identifier: MIT
"""Deterministic reference for the diffuse earthshine of a Lambertian Earth.

phi(theta, x): scalar irradiance at a point at distance r = R/x from the centre
of a uniform Lambertian sphere of radius R (unit albedo) lit by parallel
sunlight of unit irradiance, theta the angle at the centre between the Sun and
the point (docs/physics.md, earthshine):

    phi = (1/pi) * integral over {cos i > 0, cos e > 0} of cos(i) cos(e) / d^2 dA

psi(theta, x): direction of the net flux vector (the radiance-weighted mean of
the incoming directions), as an angle from the nadir towards the Sun side.

Method (numpy, vectorised over points)
--------------------------------------
Unit sphere (R = 1), point T = (0, 0, r), Sun s = (sin theta, 0, cos theta).
The sphere is sliced by planes y = const (normal to the Sun-Earth-point plane).
By Archimedes' hat-box theorem the area element in (y, gamma), with
n = (rho sin gamma, y, rho cos gamma), rho = sqrt(1 - y^2), is dA = dy dgamma.
On every slice both boundaries are arcs with closed-form ends:

    visible (cos e > 0):  |gamma| <= a(y) = acos(x / rho)
    lit     (cos i > 0):  gamma >= c = theta - pi/2  (upper end never binding)

and cos i = rho cos(gamma - theta).  With y = ym sin(u), ym = sqrt(1 - x^2),
a(u) = atan2(ym cos u, x) is analytic on [0, pi/2] (the square-root
singularity of a(y) at the limb disappears).  The u range is split exactly at
u_c where a(u_c) = |c| (the corner where terminator and horizon meet), so each
piece is an analytic integrand on a box-like domain.  Each piece is split
at u = pi/4 and each half goes through a sinh map: about u = 0 with the
altitude's scale (the near-singular 1/d^3 peak under low orbits) and about
u = pi/2 with the scale x/ym (far away the limb half-width a(u) turns over on
that scale); gamma goes through a sinh map about the nadir.  Gauss-Legendre
on each piece then converges geometrically.  The inner gamma integral is
split at the nadir into two panels (each with half the nodes), so the 1/d^3
peak sits at a panel end: a single panel across the sinh-mapped range (length
~log(4/w), long near the surface) lost 1.3e-6 at h = 1 m.  With the default
orders (48) the relative error is < 1e-11 from h = 1 cm to infinity (3e-12 at
1 m, < 1e-14 above 1 km; checked by order doubling to 160, against closed
forms and against the independent mpmath path `phi_psi_mpmath`, see
tests/python/test_reference.py).  Order 32 (the bake) gives < 3e-8 at 1 m and
< 3e-14 at 100 km.  Near the surface pass the altitude itself
(phi_psi_reference_h): 1/x - 1 keeps only 9 digits at h = 1 m.

mpmath path: polar coordinates (alpha, beta) around the sub-point, the inner
beta range closed-form from the terminator, tanh-sinh quadrature with
breakpoints at the terminator tangency, at any precision.  A different
parametrisation and a different rule: an independent check.
"""

import numpy as np

from ..common.constants import R_EARTH_KM
from ..common.quadrature import gauss_legendre_01

__all__ = [
    "phi_reference",
    "phi_psi_reference",
    "phi_psi_reference_x",
    "phi_psi_reference_h",
    "uniform_sphere_reference",
    "uniform_sphere_closed",
    "lambert_phase",
    "far_field",
    "phi_psi_mpmath",
    "subsolar_mpmath",
    "x_from_h",
    "h_from_x",
    "R_EARTH_KM",
]


# Default Gauss-Legendre orders (outer u, inner gamma) per piece.
N_OUTER = 48
N_INNER = 48

def _gl(n):
    """Gauss-Legendre nodes and weights on [0, 1]."""
    return gauss_legendre_01(n)


def x_from_h(h_km, radius_km=R_EARTH_KM):
    """x = R / (R + h)."""
    h = np.asarray(h_km, dtype=float)
    return radius_km / (radius_km + h)


def h_from_x(x, radius_km=R_EARTH_KM):
    """h = R (1/x - 1)."""
    x = np.asarray(x, dtype=float)
    return radius_km * (1.0 / x - 1.0)


def lambert_phase(t):
    """Lambert sphere phase function p(t) = 2/(3 pi) ((pi - t) cos t + sin t)."""
    t = np.clip(np.asarray(t, dtype=float), 0.0, np.pi)
    tp = np.pi - t
    direct = 2.0 / (3.0 * np.pi) * ((np.pi - t) * np.cos(t) + np.sin(t))
    # near t = pi: (pi-t) cos t + sin t = tp^3/3 - tp^5/30 + tp^7/840 - ...
    series = 2.0 / (3.0 * np.pi) * (tp**3 / 3.0 - tp**5 / 30.0 + tp**7 / 840.0)
    return np.where(tp < 1e-2, series, direct)


def far_field(theta, x):
    """Far-field Lambert model x^2 p(theta) (what the runtime uses beyond the table)."""
    x = np.asarray(x, dtype=float)
    return x * x * lambert_phase(theta)


def _integrate(theta, x, n_outer, n_inner, uniform=False, h_over_r=None):
    """Core quadrature. Returns (phi, fx, fz) with the flux vector (fx, fz),
    fz measured towards the nadir, all per unit albedo and unit solar irradiance.
    h_over_r (optional, same shape as x): the altitude in Earth radii, used
    instead of 1/x - 1 (no cancellation near the surface: x = 1 - 1.6e-7 at
    h = 1 m leaves 1/x - 1 only 9 correct digits)."""
    theta = np.asarray(theta, dtype=float)
    x = np.asarray(x, dtype=float)
    theta, x = np.broadcast_arrays(theta, x)
    shape = theta.shape
    th = np.clip(theta.ravel(), 0.0, np.pi)
    xx = x.ravel()
    if np.any(~(xx > 0.0)) or np.any(~(xx < 1.0)):
        raise ValueError("x = R/r must be in (0, 1)")
    r = 1.0 / xx
    ym = np.sqrt((1.0 - xx) * (1.0 + xx))
    hr_given = None
    if h_over_r is not None:
        hr_given = np.broadcast_to(np.asarray(h_over_r, dtype=float), shape).ravel()
        if np.any(~(hr_given > 0.0)):
            raise ValueError("h_over_r must be > 0")
        r = 1.0 + hr_given
        ym = np.sqrt(hr_given * (2.0 + hr_given)) / r
    w = np.arctan2(ym, xx)  # acos(x): angular radius of the visible cap
    hr = r - 1.0 if hr_given is None else hr_given  # altitude in Earth radii

    c = th - 0.5 * np.pi
    if uniform:
        u1 = np.zeros_like(th)
        lo1 = np.zeros_like(th)
        w1 = np.zeros_like(th)
        w2 = np.ones_like(th)
    else:
        absc = np.abs(c)
        # u_c: a(u_c) = |c|  <=>  ym cos u_c = x tan|c|
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            arg = xx * np.tan(np.minimum(absc, 0.5 * np.pi - 1e-300)) / np.where(ym > 0, ym, 1.0)
        uc = np.arccos(np.clip(arg, -1.0, 1.0))
        case_a = c <= -w  # visible cap entirely lit
        case_b = c >= w  # visible cap entirely dark
        case_c = (~case_a) & (~case_b) & (c < 0.0)
        case_d = (~case_a) & (~case_b) & (c >= 0.0)
        u1 = np.where(case_a | case_b, 0.0, uc)
        lo1 = c
        w1 = np.where(case_c | case_d, 1.0, 0.0)
        w2 = np.where(case_a | case_c, 1.0, 0.0)

    # sinh-map scales: peak of 1/d^3 has width ~ hr/sqrt(r) in y and gamma
    s0 = hr / np.sqrt(r)
    u0 = s0 / np.maximum(ym, 1e-300)

    tu, wu = _gl(n_outer)
    tg, wg = _gl((n_inner + 1) // 2)  # per panel, two panels

    phi = np.zeros_like(th)
    fx = np.zeros_like(th)
    fz = np.zeros_like(th)

    # Each piece is split at u = pi/4: the lower half is sinh-mapped about
    # u = 0 (the nadir peak, scale u0), the upper half about u = pi/2 (the
    # limb, where a(u) = atan2(ym cos u, x) turns over on the scale x/ym).
    z0 = xx / np.maximum(ym, 1e-300)
    q4 = np.full_like(th, 0.25 * np.pi)
    pieces = []
    for ua, ub, lower_is_c, wt in [(np.zeros_like(th), u1, True, w1),
                                   (u1, np.full_like(th, 0.5 * np.pi), False, w2)]:
        um = np.clip(q4, ua, ub)
        pieces.append((ua, um, lower_is_c, wt, 0.0, 1.0, u0))
        pieces.append((um, ub, lower_is_c, wt, 0.5 * np.pi, -1.0, z0))
    for ua, ub, lower_is_c, wt, centre, sgn, scale in pieces:
        active = (wt > 0) & (ub > ua)
        if not np.any(active):
            continue
        idx = np.nonzero(active)[0]
        sc = scale[idx]
        ta = np.arcsinh(sgn * (ua[idx] - centre) / sc)
        tb = np.arcsinh(sgn * (ub[idx] - centre) / sc)
        t = ta[:, None] + (tb - ta)[:, None] * tu[None, :]
        u = centre + sgn * sc[:, None] * np.sinh(t)
        du = sgn * sc[:, None] * np.cosh(t) * (tb - ta)[:, None] * wu[None, :]
        ym_ = ym[idx][:, None]
        x_ = xx[idx][:, None]
        y = ym_ * np.sin(u)
        dy = ym_ * np.cos(u) * du
        a = np.arctan2(ym_ * np.cos(u), x_)
        ga = (lo1[idx][:, None] if lower_is_c else -a) * np.ones_like(a)
        gb = a
        rho = np.sqrt((1.0 - y) * (1.0 + y))
        g0 = np.sqrt(s0[idx][:, None] ** 2 + y * y)
        sa = np.arcsinh(ga / g0)
        sb = np.arcsinh(gb / g0)
        # two panels split at the nadir (s = 0), where the 1/d^3 peak sits:
        # with the peak at a panel end Gauss-Legendre converges geometrically
        # however long the sinh-mapped range is (~log(4/w), long at low
        # altitude: one panel across it lost 1e-6 at h = 1 m)
        sm = np.clip(0.0, sa, sb)
        s = np.concatenate([sa[..., None] + (sm - sa)[..., None] * tg,
                            sm[..., None] + (sb - sm)[..., None] * tg], axis=-1)
        ds = np.concatenate([(sm - sa)[..., None] * wg, (sb - sm)[..., None] * wg], axis=-1)
        g = g0[..., None] * np.sinh(s)
        dg = g0[..., None] * np.cosh(s) * ds
        rho3 = rho[..., None]
        r3 = r[idx][:, None, None]
        hr3 = hr[idx][:, None, None]
        # 1 - rho cos g, without cancellation
        one_m = (y * y / (1.0 + rho))[..., None] + 2.0 * rho3 * np.sin(0.5 * g) ** 2
        d2 = hr3 * hr3 + 2.0 * r3 * one_m
        d = np.sqrt(d2)
        cos_e_d = hr3 - r3 * one_m  # n.T - 1 = d cos e
        if uniform:
            cos_i = np.ones_like(g)
        else:
            cos_i = rho3 * np.cos(g - th[idx][:, None, None])
            cos_i = np.maximum(cos_i, 0.0)
        base = cos_i * np.maximum(cos_e_d, 0.0) / (d2 * d) * dg * dy[..., None]
        phi[idx] += base.sum(axis=(1, 2))
        fx[idx] += (base * (rho3 * np.sin(g)) / d).sum(axis=(1, 2))
        fz[idx] += (base * (hr3 + one_m) / d).sum(axis=(1, 2))  # r - rho cos g

    k = 2.0 / np.pi  # y symmetry (x2) and radiance = cos i / pi
    return (k * phi).reshape(shape), (k * fx).reshape(shape), (k * fz).reshape(shape)


def phi_psi_reference_x(theta, x, n_outer=N_OUTER, n_inner=N_INNER):
    """phi and psi as functions of (theta, x = R/r); numpy arrays broadcast."""
    phi, fx, fz = _integrate(theta, x, n_outer, n_inner)
    psi = np.where(phi > 0.0, np.arctan2(fx, fz), 0.0)
    return phi, psi


def phi_psi_reference(theta, x, n_outer=N_OUTER, n_inner=N_INNER):
    """Reference phi(theta, x) and psi(theta, x).

    theta: angle at the Earth's centre between Sun and point (rad, clipped to [0, pi]).
    x:     R / r in (0, 1) (r: distance of the point from the Earth's centre).
    Returns (phi, psi): phi per unit albedo and unit solar irradiance;
    psi the mean incidence direction from the nadir towards the Sun side (rad),
    0 where phi = 0.
    """
    return phi_psi_reference_x(theta, x, n_outer, n_inner)


def phi_psi_reference_h(theta, h_over_r, n_outer=N_OUTER, n_inner=N_INNER):
    """phi and psi as functions of (theta, h / R): the same quadrature with the
    altitude given directly (x = 1 / (1 + h/R)), for the last digits near the
    surface (the stability suite's 1e-12 at h = 1 m)."""
    hr = np.asarray(h_over_r, dtype=float)
    theta, hr = np.broadcast_arrays(np.asarray(theta, dtype=float), hr)
    phi, fx, fz = _integrate(theta, 1.0 / (1.0 + hr), n_outer, n_inner, h_over_r=hr)
    psi = np.where(phi > 0.0, np.arctan2(fx, fz), 0.0)
    return phi, psi


def phi_reference(theta, x, n_outer=N_OUTER, n_inner=N_INNER):
    """Reference phi(theta, x); see phi_psi_reference."""
    return phi_psi_reference_x(theta, x, n_outer, n_inner)[0]


def uniform_sphere_reference(x, n_outer=N_OUTER, n_inner=N_INNER):
    """Same quadrature with the whole visible cap at radiance 1/pi.
    Returns (scalar irradiance, plate irradiance facing the centre)."""
    x = np.asarray(x, dtype=float)
    phi, _, fz = _integrate(np.zeros_like(x), x, n_outer, n_inner, uniform=True)
    return phi, fz


def uniform_sphere_closed(x):
    """Closed forms for radiance L = 1/pi: scalar 2 pi L (1 - sqrt(1 - x^2)),
    plate pi L x^2."""
    x = np.asarray(x, dtype=float)
    return 2.0 * (x * x / (1.0 + np.sqrt((1.0 - x) * (1.0 + x)))), x * x


# --------------------------------------------------------------------------- mpmath


def phi_psi_mpmath(theta, x, dps=30):
    """Independent high-precision phi and psi at one point (mpmath, tanh-sinh).

    Polar coordinates (alpha, beta) about the sub-point of the target:
    n = (sin a cos b, sin a sin b, cos a); lit where
    cos b > -cot(a) cot(theta). Returns mpf (phi, psi)."""
    import mpmath as mp

    with mp.workdps(dps):
        th = mp.mpf(theta)
        xx = mp.mpf(x)
        r = 1 / xx
        amax = mp.acos(xx)
        st, ct = mp.sin(th), mp.cos(th)

        def beta_max(a):
            sa, ca = mp.sin(a), mp.cos(a)
            # lit: sa cos b st + ca ct > 0
            if st == 0:
                return mp.pi if ct > 0 else mp.mpf(0)
            v = -ca * ct / (sa * st) if sa != 0 else (-mp.inf if ct > 0 else mp.inf)
            if v <= -1:
                return mp.pi
            if v >= 1:
                return mp.mpf(0)
            return mp.acos(v)

        def inner(a, comp):
            bm = beta_max(a)
            if bm == 0:
                return mp.mpf(0)
            sa, ca = mp.sin(a), mp.cos(a)
            d2 = 1 + r * r - 2 * r * ca
            d = mp.sqrt(d2)
            cos_e_d = r * ca - 1

            def f(b):
                cos_i = sa * mp.cos(b) * st + ca * ct
                base = cos_i * cos_e_d / (d2 * d) * sa
                if comp == 0:
                    return base
                if comp == 1:
                    return base * sa * mp.cos(b) / d
                return base * (r - ca) / d

            return 2 * mp.quad(f, [0, bm])

        # breakpoints: tangency of the terminator with alpha-circles, and the
        # altitude scale near the nadir
        pts = [mp.mpf(0)]
        hr = r - 1
        for p in (hr / 4, hr, 4 * hr, abs(mp.pi / 2 - th)):
            if 0 < p < amax:
                pts.append(p)
        pts = sorted(set(pts)) + [amax]
        out = []
        for comp in range(3):
            out.append(mp.quad(lambda a: inner(a, comp), pts) / mp.pi)
        phi, fx, fz = out
        psi = mp.atan2(fx, fz) if phi > 0 else mp.mpf(0)
        return phi, psi


def subsolar_mpmath(x, dps=30):
    """phi(0, x) by a 1-D integral over the nadir angle eta seen from the
    target (axisymmetric case, a third parametrisation):
    phi = 2 int_0^{asin x} cos(alpha) sin(eta) d eta, alpha = asin(sin eta / x) - eta."""
    import mpmath as mp

    with mp.workdps(dps):
        xx = mp.mpf(x)
        em = mp.asin(xx)

        def f(eta):
            s = mp.sin(eta) / xx
            s = min(s, mp.mpf(1))
            alpha = mp.asin(s) - eta
            return mp.cos(alpha) * mp.sin(eta)

        return 2 * mp.quad(f, [0, em / 2, em])
