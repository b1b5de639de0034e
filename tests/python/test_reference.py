# SPDX-License-Identifier: MIT
"""The earthshine quadrature reference (bake/earthshine/reference.py) against closed
forms, limits, symmetry, an independent mpmath integration and itself at a
higher order."""

import glob
import math
import os
import re
import sys

import mpmath
import numpy as np
import pytest

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, ROOT)

from bake.earthshine import reference as ref  # noqa: E402

XS = np.array([0.999, 0.98456, 0.9, 0.7, 0.5, 0.2, 0.05, 0.0166, 1e-3])


def test_uniform_sphere_closed_forms():
    """Whole visible cap at radiance 1/pi: scalar 2 (1 - sqrt(1 - x^2)) and
    plate x^2 (view factor of a sphere), from the same integrator."""
    scal, plate = ref.uniform_sphere_reference(XS)
    want_s, want_p = ref.uniform_sphere_closed(XS)
    np.testing.assert_allclose(scal, want_s, rtol=1e-11, atol=0)
    np.testing.assert_allclose(plate, want_p, rtol=1e-11, atol=0)


def test_far_field_limit():
    """phi / x^2 -> p(theta) as x -> 0, the deviation shrinking like x."""
    th = np.linspace(0.0, 2.5, 11)
    e1 = np.abs(ref.phi_reference(th, 1e-3) / (1e-6 * ref.lambert_phase(th)) - 1)
    e2 = np.abs(ref.phi_reference(th, 2e-3) / (4e-6 * ref.lambert_phase(th)) - 1)
    assert e1.max() < 2e-2
    # first order in x: halving x halves the deviation (where it is resolvable)
    m = e2 > 1e-6
    np.testing.assert_allclose(e1[m] / e2[m], 0.5, rtol=0.02)


def test_subsolar_against_1d_mpmath():
    """theta = 0 by a 1-D integral over the nadir angle (third parametrisation)."""
    for x in (0.999, 0.98456, 0.8, 0.3, 0.0166, 1e-3):
        want = float(ref.subsolar_mpmath(x, 30))
        got = float(ref.phi_reference(0.0, x))
        assert abs(got / want - 1) < 1e-12, (x, want, got)


def test_surface_limit():
    """At the surface (x -> 1) the subsolar point sees a hemisphere of radiance
    1/pi: phi -> 2."""
    got = float(ref.phi_reference(0.0, 1 - 1e-7))
    assert abs(got - 2.0) < 2e-3


@pytest.mark.parametrize("theta,x", [(1.6, 0.98456), (1.2, 0.9), (2.0, 0.5), (0.3, 0.3),
                                     (2.9, 0.02)])
def test_against_mpmath_2d(theta, x):
    """Independent polar parametrisation with tanh-sinh (mpmath, 20 digits)."""
    pm, sm = ref.phi_psi_mpmath(theta, x, 20)
    phi, psi = ref.phi_psi_reference(theta, x)
    phi0 = ref.phi_reference(0.0, x)
    assert abs(float(phi) - float(pm)) <= 1e-12 * float(phi0)
    assert abs(float(psi) - float(sm)) <= 1e-11


def test_converged_in_order():
    """Default order agrees with twice the order to 1e-12 relative (so the
    reference is far better than the 1e-9 asked for)."""
    rng = np.random.default_rng(7)
    th = rng.uniform(0, math.pi, 300)
    x = np.cos(rng.uniform(0.1, 1.5707, 300))
    p1, s1 = ref.phi_psi_reference(th, x)
    p2, s2 = ref.phi_psi_reference(th, x, 96, 96)
    p0 = ref.phi_reference(np.zeros_like(x), x, 96, 96)
    assert np.max(np.abs(p1 - p2) / p0) < 1e-12
    assert np.max(np.abs(s1 - s2)[p2 > 1e-6 * p0]) < 1e-10


def test_symmetry_and_support():
    """phi = 0 exactly beyond theta = pi/2 + acos x; psi = 0 at theta = 0;
    phi decreasing in theta; 0 <= psi <= asin x (the limb)."""
    th = np.linspace(0, math.pi, 721)
    for x in XS[1:]:
        phi, psi = ref.phi_psi_reference(th, x)
        dark = th >= math.pi / 2 + math.acos(x)
        assert np.all(phi[dark] == 0)
        assert np.all(phi[~dark][:-1] > 0)
        assert abs(psi[0]) < 1e-14
        assert np.all(np.diff(phi) <= 1e-15 * phi[0])
        assert np.all(psi >= -1e-15) and np.all(psi <= math.asin(x) + 1e-12)


def test_theta_symmetric_in_sun_side():
    """Mirroring the Sun through the Sun-Earth-target plane's normal changes
    nothing: the mpmath path with beta range doubled uses one half only; here
    check the quadrature is even in theta about 0 after clamping."""
    x = 0.9
    a = ref.phi_reference(np.array([0.0, 1e-9]), x)
    assert abs(a[1] / a[0] - 1) < 1e-12


def test_far_field_function():
    """far_field = x^2 p(theta), p(0) = 2/3, the series branch continuous."""
    assert ref.far_field(0.0, 0.5) == pytest.approx(0.25 * 2 / 3, rel=1e-15)
    t = math.pi - 1e-2
    a = ref.lambert_phase(np.array([t - 1e-12, t + 1e-12]))
    assert abs(a[1] / a[0] - 1) < 1e-9


def test_low_altitude_converged():
    """Down to 1 cm the default order agrees with order 160 (the nadir peak
    sits at a panel end of the inner integral: geometric convergence however
    low the point)."""
    R = ref.R_EARTH_KM
    for hk in (1e-5, 1e-3, 1.0, 10.0):
        hr = hk / R
        w = math.atan2(math.sqrt(hr * (2 + hr)), 1.0)
        th = np.array([0.0, 1.2, math.pi / 2 - w, math.pi / 2 - 0.5 * w, math.pi / 2 + 0.3 * w])
        p48, s48 = ref.phi_psi_reference_h(th, hr)
        p160, s160 = ref.phi_psi_reference_h(th, hr, 160, 160)
        phi0 = p160[0]
        assert np.all(np.abs(p48 - p160) <= 1e-10 * p160 + 1e-15 * phi0), hk
        assert np.all(np.abs(s48 - s160) <= 1e-9), hk


def test_low_altitude_against_mpmath():
    """h = 1 m: the independent mpmath path at 25 digits."""
    x = float(ref.x_from_h(1e-3))
    w = math.acos(x)
    for th in (0.7, math.pi / 2 - 0.5 * w):
        pm, sm = ref.phi_psi_mpmath(th, x, 25)
        p, s = ref.phi_psi_reference(th, x)
        assert abs(float(pm) / float(p) - 1) < 1e-10
        assert abs(float(sm) - float(s)) < 1e-10


def test_near_surface_closed_form():
    """Flat-Earth limit with its first correction: the cap wholly lit gives
    phi = cos(theta) phi(0, x) and phi(0, x) = x^2 (2 (1 - w) + O(w^2)) (the
    sky band of the horizon's depression w takes 2w of the flat plane's 2)."""
    R = ref.R_EARTH_KM
    for hk in (1e-5, 1e-3, 0.1):
        hr = hk / R
        w = math.atan2(math.sqrt(hr * (2 + hr)), 1.0)
        x = 1 / (1 + hr)
        th = np.array([0.0, 0.5, 1.3])
        p, _ = ref.phi_psi_reference_h(th, hr)
        want = x * x * 2 * (1 - w) * np.cos(th)
        assert np.all(np.abs(p / want - 1) < 2 * w * w), hk


def test_h_form_matches_x_form():
    """phi_psi_reference_h(theta, h/R) = phi_psi_reference(theta, R/(R+h))
    where 1/x - 1 loses nothing (h >= 100 km)."""
    th = np.array([0.3, 1.5, 1.7])
    for hr in (0.02, 1.0, 30.0):
        a = ref.phi_psi_reference_h(th, hr)
        b = ref.phi_psi_reference(th, 1 / (1 + hr))
        assert np.allclose(a[0], b[0], rtol=1e-12, atol=0) and np.allclose(a[1], b[1], atol=1e-12)


# ----------------------------------------------------------- literals in the runtime

_ARR = re.compile(r"static const oi_real (\w+)\[\w+(?: \+ 1)?\]\[(\d+)\] = \{(.*?)\n\};", re.S)
_VAL = re.compile(r"OI_R\(([-+0-9.eE]+)\)")


def _runtime_arrays():
    """(file, name, rows, comment before it) of every 2-D oi_real array in src/."""
    out = []
    for path in sorted(glob.glob(os.path.join(ROOT, "src", "*", "*.c"))):
        with open(path, encoding="ascii") as f:
            text = f.read()
        for m in _ARR.finditer(text):
            ncol = int(m.group(2))
            vals = [mpmath.mpf(v) for v in _VAL.findall(m.group(3))]
            rows = [vals[k:k + ncol] for k in range(0, len(vals), ncol)]
            out.append((os.path.basename(path), m.group(1), rows, text[max(0, m.start() - 700):m.start()]))
    return out


def _gl8_macros():
    """(file, name, rows, comment) of the 8-point rule's constants OI_GL8_X1..X4,
    OI_GL8_W1..W4 (src/math/math_internal.h; the table oi__gl8 is made of them)."""
    path = os.path.join(ROOT, "src", "math", "math_internal.h")
    with open(path, encoding="ascii") as f:
        text = f.read()

    def val(name):
        m = re.search(r"#define OI_GL8_%s OI_R\(([-+0-9.eE]+)\)" % name, text)
        assert m, ("math_internal.h", "OI_GL8_" + name)
        return mpmath.mpf(m.group(1))

    rows = [[val("X%d" % i), val("W%d" % i)] for i in range(1, 5)]
    return [("math_internal.h", "OI_GL8_*", rows, "Gauss-Legendre")]


def test_runtime_gauss_legendre_literals_match_generator():
    """Every Gauss-Legendre table pasted into src/ (nodes x < 1/2 on [0, 1],
    weights, and where given sin/cos(pi x / 2)), and the 8-point rule's
    constants of src/math/math_internal.h, equal the rule computed here in mpmath to
    the 21 digits written (the generator: tests/ref/shadow.py --gauss N,
    bake/common/quadrature.py)."""
    checked = 0
    with mpmath.workdps(40):
        for fname, name, rows, before in _runtime_arrays() + _gl8_macros():
            if "Gauss-Legendre" not in before:
                continue
            n = 2 * len(rows)
            t, w = [], []
            for k in range(1, n + 1):  # roots of P_n by Newton, at 40 digits
                x = mpmath.cos(mpmath.pi * (k - mpmath.mpf(1) / 4) / (n + mpmath.mpf(1) / 2))
                for _ in range(60):
                    dx = mpmath.legendre(n, x) / mpmath.diff(lambda s: mpmath.legendre(n, s), x)
                    x -= dx
                    if abs(dx) < mpmath.mpf(10) ** -38:
                        break
                dp = mpmath.diff(lambda s: mpmath.legendre(n, s), x)
                t.append(x)
                w.append(1 / ((1 - x * x) * dp * dp))  # weight on [0, 1]
            half = sorted(((1 - x) / 2, wk) for x, wk in zip(t, w))[: n // 2]
            for row, (x01, w01) in zip(rows, half):
                assert abs(row[0] - x01) <= 1e-20 * abs(x01), (fname, name, row[0], x01)
                assert abs(row[1] - w01) <= 1e-20 * abs(w01), (fname, name, row[1], w01)
                if len(row) >= 4:
                    s, c = mpmath.sin(mpmath.pi * x01 / 2), mpmath.cos(mpmath.pi * x01 / 2)
                    assert abs(row[2] - s) <= 1e-20 * abs(s) and abs(row[3] - c) <= 1e-20, (fname, name)
            checked += 1
    assert checked >= 2  # the cap segment's and the limb darkening's rules (both precisions)


def test_runtime_limb_darkening_literals_match_generator():
    """The limb-darkening series table of src/ is c_j A_i / (i + 2j + 2)
    (c_j = binomial(-1/2, j)) of the Neckel & Labs (1994) 559.95 nm
    coefficients the baker uses (bake/atmosphere/rays.py NL94_559)."""
    from fractions import Fraction

    from bake.atmosphere.rays import NL94_559
    A = [Fraction(repr(float(a))) for a in NL94_559]
    tables = [(f, n, rows) for f, n, rows, _ in _runtime_arrays() if n == "ld_coef"]
    assert len(tables) == 1
    _, _, rows = tables[0]
    c = Fraction(1)
    for j, row in enumerate(rows):
        if j:
            c *= Fraction(-1, 2) - (j - 1)
            c /= j
        for i, v in enumerate(row):
            want = c * A[i] / (i + 2 * j + 2)
            assert abs(v - mpmath.mpf(want.numerator) / want.denominator) <= 1e-20 * abs(float(want)) + 1e-30
