# SPDX-License-Identifier: MIT
"""Generate tests/c/ref_earthshine.h: earthshine reference values for the C
tests (tests/c/test_earthshine.c), from the quadrature reference
(bake/earthshine/reference.py, order 64, independent of the tables and of the
runtime's interpolation), spot-checked here against the mpmath path.

    python tests/ref/generate.py earthshine      # writes tests/c/ref_earthshine.h

The quadrature runs in double (numpy): its last bits depend on the machine's
libm and SIMD paths, so phi, psi and phi0 are written with REF_DIGITS
significant digits, psi first rounded to PSI_ABS rad (at theta = 0 it is
roundoff noise around 0); far below the tests' tolerances, far above those
bits. Inputs and the mpmath far-field values are exact.

Points are chosen off the table nodes: random (fixed seed) theta and log-
uniform altitude from 100 km to 1e6 km, a dense set around the terminator at
low altitude, LEO / GEO / lunar distance / Sun-Earth L2, huge altitudes; near
the surface (es_low: 1 m, 1 km, 10 km, 50 km, 99 km and more, random 1 m to
100 km); and points below the LEO scene table (far field expected, computed
here in mpmath).
"""

import math

import numpy as np

from common import c_sig_real, cli, write

from bake.earthshine import reference as ref  # noqa: E402

OUT = "tests/c/ref_earthshine.h"
R = ref.R_EARTH_KM
ORDER = 64
REF_DIGITS = 12
PSI_ABS = 1e-14


def _points():
    rng = np.random.default_rng(20261122)
    th, h = [], []
    # random over the whole domain (theta, log h)
    n = 80
    th += list(rng.uniform(0.0, math.pi, n))
    h += list(10 ** rng.uniform(2.0, 6.0, n))
    # terminator band at low altitude: theta in pi/2 +- w
    for hk in (101.3, 157.0, 233.0, 412.0, 777.0, 1503.0, 5123.0):
        w = math.atan2(math.sqrt(hk * (2 * R + hk)), R)
        for f in (-0.93, -0.61, -0.27, -0.05, 0.013, 0.07, 0.19, 0.33, 0.52, 0.71, 0.86, 0.97):
            th.append(math.pi / 2 + f * w)
            h.append(hk)
    # where the default table is worst: the terminator crossing the nadir
    # just above 100 km (theta slightly above 90 deg)
    for k in range(24):
        hk = 100.0 + 40.0 * rng.uniform()
        th.append(math.pi / 2 + rng.uniform(0.0, 0.02))
        h.append(hk)
    # named altitudes (ISS, SSO, GPS, GEO, lunar, Sun-Earth L2, far)
    for hk in (408.0, 786.0, 20200.0, 35786.0, 384400.0, 1.5e6, 1e9):
        for t in (0.0, 0.4, 1.1, 1.6, 2.2, 2.9, math.pi):
            th.append(t)
            h.append(hk)
    return np.array(th), np.array(h)


def _low_points():
    """Near the surface (the default table's range below 100 km): named
    altitudes 1 m, 1 km, 10 km, 50 km, 99 km and a few more, theta over the
    lit side, around the 1% contour (cos theta ~ 0.005-0.05) and across the
    terminator band pi/2 +- w; plus random log-uniform altitudes 1 m-100 km."""
    rng = np.random.default_rng(20261123)
    th, h = [], []
    for hk in (0.001, 0.0037, 0.01, 0.1, 1.0, 3.3, 10.0, 27.0, 50.0, 99.0):
        w = math.atan2(math.sqrt(hk * (2 * R + hk)), R)
        for t in (0.0, 0.5, 1.2, 1.5):
            th.append(t)
            h.append(hk)
        for c in (0.05, 0.02, 0.011):
            th.append(math.acos(c))
            h.append(hk)
        for f in (-0.97, -0.7, -0.4, -0.13, -0.02, 0.0, 0.011, 0.09, 0.3, 0.6, 0.9):
            th.append(math.pi / 2 + f * w)
            h.append(hk)
    n = 60
    hh = 10 ** rng.uniform(-3.0, 2.0, n)
    for hk in hh:
        w = math.atan2(math.sqrt(hk * (2 * R + hk)), R)
        th.append(math.pi / 2 + w * rng.uniform(-1.0, 1.0))
        h.append(hk)
    th += list(rng.uniform(0.0, math.pi / 2, n))
    h += list(10 ** rng.uniform(-3.0, 2.0, n))
    return np.array(th), np.array(h)


def _far_field_mp(theta, h):
    import mpmath as mp

    with mp.workdps(30):
        x = mp.mpf(R) / (mp.mpf(R) + mp.mpf(h))
        t = mp.mpf(theta)
        return float(x * x * 2 / (3 * mp.pi) * ((mp.pi - t) * mp.cos(t) + mp.sin(t)))


def generate(root, argv=()):
    th, h = _points()
    x = R / (R + h)
    phi, psi = ref.phi_psi_reference(th, x, ORDER, ORDER)
    phi0 = ref.phi_reference(np.zeros_like(x), x, ORDER, ORDER)
    # spot check the quadrature against mpmath (a different parametrisation)
    for k in (0, 7, 13, 85, 90, 101, 140):
        pm, sm = ref.phi_psi_mpmath(th[k], x[k], 25)
        assert abs(float(pm) - phi[k]) <= 1e-12 * max(float(phi0[k]), 1e-300), k
        assert abs(float(sm) - psi[k]) <= 1e-10, k
    # near the surface: the reference with the altitude given exactly
    # (phi_psi_reference_h, no cancellation in 1/x - 1)
    th_l, h_l = _low_points()
    phi_l, psi_l = ref.phi_psi_reference_h(th_l, h_l / R, ORDER, ORDER)
    phi0_l = ref.phi_psi_reference_h(np.zeros_like(h_l), h_l / R, ORDER, ORDER)[0]
    for k in (0, 5, 40, 80, 150):  # mpmath spot checks (lit side, low altitude)
        pm, sm = ref.phi_psi_mpmath(th_l[k], R / (R + h_l[k]), 25)
        assert abs(float(pm) - phi_l[k]) <= 1e-9 * float(phi0_l[k]), (k, float(pm), phi_l[k])
    # below a table (the LEO scene table, 200-2000 km): far field and warning;
    # theta outside [0, pi]
    below = [(0.3, 50.0), (1.2, 99.0), (2.0, 10.0)]
    clamped = [(-0.5, 500.0, 0.0), (4.0, 500.0, math.pi), (-1e-3, 35786.0, 0.0)]

    lines = []
    lines.append("/* SPDX-License-Identifier: MIT */")
    lines.append("/* GENERATED by `python tests/ref/generate.py earthshine` (tests/ref/earthshine.py): do not edit.")
    lines.append(" * Earthshine reference values from bake/earthshine/reference.py (Gauss-Legendre order %d," % ORDER)
    lines.append(" * relative accuracy < 1e-12, spot-checked against mpmath at 25 digits), R = %.3f km," % R)
    lines.append(" * printed with %d significant digits (theta, h exact)." % REF_DIGITS)
    lines.append(" * phi0 = phi(0, x) at the same altitude (the goal's scale). */")
    lines.append("#ifndef REF_EARTHSHINE_H\n#define REF_EARTHSHINE_H\n")
    lines.append("typedef struct es_ref {\n    double theta, h_km, phi, psi, phi0;\n} es_ref;\n")
    lines.append("static const es_ref es_refs[] = {")
    for a, b, c, d, e in zip(th, h, phi, psi, phi0):
        lines.append("    {%.17g, %.17g, %s, %s, %s}," % (a, b, sig(c), sig_psi(d), sig(e)))
    lines.append("};\n")
    lines.append("/* near the surface, 1 m .. 100 km (phi_psi_reference_h, altitude exact) */")
    lines.append("static const es_ref es_low[] = {")
    for a, b, c, d, e in zip(th_l, h_l, phi_l, psi_l, phi0_l):
        lines.append("    {%.17g, %.17g, %s, %s, %s}," % (a, b, sig(c), sig_psi(d), sig(e)))
    lines.append("};\n")
    lines.append("/* below the LEO scene table: far field x^2 p(theta) (mpmath), OI_WARN_TABLE_RANGE */")
    lines.append("static const es_ref es_below[] = {")
    for a, b in below:
        lines.append("    {%.17g, %.17g, %.17g, 0.0, 0.0}," % (a, b, _far_field_mp(a, b)))
    lines.append("};\n")
    lines.append("/* theta outside [0, pi] is clamped: {theta, h, theta clamped, ., .} */")
    lines.append("static const es_ref es_clamped[] = {")
    for a, b, c in clamped:
        lines.append("    {%.17g, %.17g, %.17g, 0.0, 0.0}," % (a, b, c))
    lines.append("};\n")
    lines.append("#endif /* REF_EARTHSHINE_H */")
    return [write(root, OUT, "\n".join(lines) + "\n")]


def sig_psi(v):
    return sig(round(float(v) / PSI_ABS) * PSI_ABS)


def sig(v):
    return c_sig_real(v, REF_DIGITS)


if __name__ == "__main__":
    raise SystemExit(cli([OUT], generate, __doc__))
