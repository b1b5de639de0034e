# SPDX-License-Identifier: MIT
"""Photon mapper (bake/photon/mapping.py): energy conservation, calibration, zero
shells == no atmosphere, agreement with the independent quadrature
(bake.earthshine.reference) within statistical tolerances, convergence order ~N^-1/2."""
import numpy as np
import pytest

from bake.photon.mapping import bake_phi, gather, gather_function, photon_map
from bake.photon.shells import Atmosphere

reference = pytest.importorskip("bake.earthshine.reference")

R = 6378.137


def _p(t):
    return 2 / (3 * np.pi) * ((np.pi - t) * np.cos(t) + np.sin(t))


def test_photon_and_power_budget_bare():
    n = 400_000
    m = photon_map(n, None, seed=3)
    s = m.stats
    # photons conserved
    assert s["n_missed"] + s["n_transmitted"] + s["n_absorbed"] + s["n_trapped_in"] == n
    assert s["n_transmitted"] == 0 and s["n_returned"] == 0
    # power leaving = albedo (1) * power absorbed
    assert s["reflected"] == pytest.approx(s["absorbed"], rel=1e-15)
    # calibration: map integrated over its sphere = reflected power (band area
    # 2 pi rho^2 (cos t_i - cos t_i+1))
    assert np.sum(m.reflected * m.band_area(m.rho)) == pytest.approx(s["reflected"], rel=1e-12)
    # absorbed power = E0 * pi R^2 (geometric cross-section), binomial 5 sigma
    f = (1 / 1.02) ** 2
    frac = s["n_absorbed"] / n
    assert abs(frac - f) < 5 * np.sqrt(f * (1 - f) / n), f"want {f!r} got {frac!r}"
    assert s["absorbed"] == pytest.approx(np.pi * R**2, rel=5 * np.sqrt((1 - f) / f / n))


def test_surface_map_is_cosine_law():
    # bare Earth: exitance per unit albedo = max(cos theta, 0); compare the map
    # with the bin average of cos+ (chi-square like, per-bin Poisson sigma)
    n = 1_000_000
    m = photon_map(n, None, seed=5, n_bins=36, sun_radius_km=0.0)
    e = m.edges
    c = np.cos(e)
    num = 0.5 * (np.sin(np.minimum(e[1:], np.pi / 2)) ** 2 - np.sin(np.minimum(e[:-1], np.pi / 2)) ** 2)
    want = num / (c[:-1] - c[1:])
    sigma = np.where(m.counts > 0, m.surface / np.sqrt(np.maximum(m.counts, 1)), 1e-12)
    z = (m.surface - want) / np.where(want > 0, sigma, 1.0)
    assert np.all(m.surface[e[:-1] >= np.pi / 2] == 0.0)
    lit = want > 0
    assert np.max(np.abs(z[lit])) < 5.0
    # sum of z^2 ~ chi-square with one degree of freedom per lit bin:
    # two-sided 1e-4 quantiles
    from scipy.stats import chi2
    k = int(lit.sum())
    assert chi2.ppf(1e-4, k) < np.sum(z[lit] ** 2) < chi2.ppf(1 - 1e-4, k)


def test_gathering_exact_map_matches_reference():
    # final gathering alone (exact cos+ exitance): deterministic quadrature error
    th = np.radians([0.0, 30.0, 60.0, 85.0, 95.0])
    for x in (0.98, 0.5, 0.05):
        want, wpsi = reference.phi_psi_reference(th, x)
        got, gpsi = gather_function(lambda t: np.maximum(np.cos(t), 0) / np.pi, th, R / x, R,
                                    n_s=128, n_beta=128)
        assert np.max(np.abs(got - want)) <= 1e-4 * want[0], f"want {want} got {got}"
        assert np.max(np.abs(gpsi - wpsi)) < 5e-5


def test_far_field_lambert_limit():
    # far away phi -> x^2 p(theta) (independent of bake.earthshine.reference)
    # corrections are O(x) (0.75 x at theta = 0): test at x = 1e-4 with an
    # absolute tolerance 1e-4 x^2 p(0)
    x = 1e-4
    th = np.radians([0.0, 45.0, 90.0, 135.0, 170.0])
    got, psi = gather_function(lambda t: np.maximum(np.cos(t), 0) / np.pi, th, R / x, R)
    np.testing.assert_allclose(got, x * x * _p(th), rtol=0, atol=1e-4 * x * x * _p(0.0))
    assert np.all(np.abs(psi) < x)


def test_zero_shells_equal_no_atmosphere():
    th = np.radians([0.0, 40.0, 80.0, 100.0])
    x = np.array([0.9, 0.3])[:, None]
    a = bake_phi(th, x, 200_000, seed=11)
    b = bake_phi(th, x, 200_000, seed=11, atm=Atmosphere.bare())
    np.testing.assert_array_equal(a[0], b[0])
    np.testing.assert_array_equal(a[1], b[1])
    # transparent shells (n = 1): the photons follow the same lines; traced
    # through the shells ("surface" gathering) the result equals the bare Earth
    clear = Atmosphere(R, R + np.array([20.0, 50.0, 100.0]), np.ones(3))
    mc = photon_map(200_000, clear, seed=11)
    mb = photon_map(200_000, None, seed=11, disc_margin=1.02 * clear.outer_radius / R)
    np.testing.assert_allclose(mc.surface, mb.surface, rtol=1e-12, atol=0)
    r = R / 0.9
    pc = gather(mc, th, r, mode="surface", n_s=48, n_beta=48)
    pb = gather(mb, th, r, n_s=48, n_beta=48)
    np.testing.assert_allclose(pc[0], pb[0], rtol=1e-6)


def test_determinism():
    th = np.radians([10.0, 70.0])
    a = bake_phi(th, 0.5, 100_000, seed=2)
    b = bake_phi(th, 0.5, 100_000, seed=2)
    assert np.array_equal(a[0], b[0]) and np.array_equal(a[1], b[1])


def test_photon_map_vs_reference_statistical():
    # 3 million photons: relative error at points where phi >= 5% of the
    # subsolar value is dominated by noise of ~1e-3 (measured over seeds in
    # the report); 6e-3 is > 5 sigma. Also psi.
    th = np.radians([0.0, 25.0, 50.0, 75.0, 90.0])
    x = np.array([0.9, 0.5, 0.1])[:, None]
    phi, psi = bake_phi(th, x, 3_000_000, seed=4)
    want, wpsi = reference.phi_psi_reference(th, x)
    sub = want[:, :1]
    big = want >= 0.05 * sub
    rel = np.abs(phi / want - 1)
    assert np.all(rel[big] < 6e-3), f"max rel {rel[big].max()}"
    assert np.all(np.abs(phi - want) < 6e-3 * sub)
    assert np.max(np.abs(psi - wpsi)) < 1e-2


def test_convergence_order_half():
    # error vs photon count: RMS over points and 4 seeds of |phi - ref| / phi(0, x)
    th = np.radians(np.arange(0.0, 121.0, 10.0))
    x = np.array([0.9, 0.5, 0.2])[:, None]
    want = reference.phi_reference(th, x)
    scale = want[:, :1]
    ns = np.array([50_000, 200_000, 800_000])
    err = []
    for n in ns:
        e2 = [np.mean(((bake_phi(th, x, int(n), seed=100 + s, n_s=64, n_beta=64)[0] - want)
                       / scale) ** 2) for s in range(4)]
        err.append(np.sqrt(np.mean(e2)))
    slope = np.polyfit(np.log(ns), np.log(err), 1)[0]
    assert -0.7 < slope < -0.3, f"want -0.5 got {slope!r} (errors {err})"


def test_finite_sun_close_to_parallel_light():
    th = np.radians([0.0, 60.0, 89.0])
    a = bake_phi(th, 0.5, 300_000, seed=9)[0]
    b = photon_map(300_000, None, seed=9, sun_radius_km=0.0)
    bb = gather(b, th, R / 0.5)[0]
    # same random numbers, hit points moved by < 0.27 deg: nearly identical
    np.testing.assert_allclose(a, bb, rtol=3e-3)


def test_atmosphere_budget_and_cross_section():
    atm = Atmosphere.exponential(n_shells=8)
    n = 100_000
    m = photon_map(n, atm, seed=1)
    s = m.stats
    assert s["n_missed"] + s["n_transmitted"] + s["n_absorbed"] + s["n_trapped_in"] == n
    assert s["n_reflected"] + s["n_returned"] + s["n_trapped_out"] == s["n_absorbed"]
    assert s["reflected"] + s["returned"] + s["trapped_out"] == pytest.approx(s["absorbed"])
    assert s["n_transmitted"] > 0
    # refraction widens the Earth's cross-section to pi (n1 R)^2 (Bouguer)
    f = (atm.indices[0] * R / (1.02 * atm.outer_radius)) ** 2
    frac = s["n_absorbed"] / n
    assert abs(frac - f) < 5 * np.sqrt(f * (1 - f) / n)
    # maps integrate back to the powers
    assert np.sum(m.reflected * m.band_area(m.rho)) == pytest.approx(s["reflected"], rel=1e-12)
    assert np.sum(m.transmitted * m.band_area(m.rho)) == pytest.approx(s["transmitted"], rel=1e-12)
    assert np.sum(m.surface * m.band_area(R)) == pytest.approx(s["absorbed"], rel=1e-12)
    # transmitted light leaves behind the limb: between 90 deg and 90 deg plus
    # the top shell's horizon dip acos(R/rho) plus the bending (< 1.5 deg)
    nz = m.transmitted > 0
    hi = np.pi / 2 + np.arccos(R / atm.outer_radius) + np.radians(1.5)
    assert np.all(m.edges[1:][nz] > np.pi / 2) and np.all(m.edges[:-1][nz] < hi)


def test_atmosphere_surface_gathering_close_to_bare():
    # the seed's V: refraction changes diffusely reflected light only slightly
    atm = Atmosphere.exponential(n_shells=8)
    m = photon_map(300_000, atm, seed=1)
    th = np.radians([0.0, 45.0])
    phi, _ = gather(m, th, R / 0.3, mode="surface", n_s=32, n_beta=32)
    want = reference.phi_reference(th, 0.3)
    np.testing.assert_allclose(phi, want, rtol=1.5e-2)


def test_jittered_sampling_stratifies_the_disc():
    # the seed's jittered grid: the fraction of photons inside the Earth's
    # outline is exact to about one row of strata (1/k), far below binomial noise
    n = 250_000
    k = 500
    m = photon_map(n, None, seed=4, sampling="jittered", sun_radius_km=0.0)
    f = (1 / 1.02) ** 2
    frac = m.stats["n_absorbed"] / n
    assert abs(frac - f) < 2.0 / k, f"want {f!r} got {frac!r}"
    assert m.stats["n_absorbed"] + m.stats["n_missed"] == n
    th = np.radians([0.0, 45.0])
    phi, _ = gather(m, th, R / 0.5)
    np.testing.assert_allclose(phi, reference.phi_reference(th, 0.5), rtol=1e-2)
    with pytest.raises(ValueError):
        photon_map(10, None, sampling="sobol")


def test_surface_gathering_conserves_escaping_power():
    # A dense shell (n = 1.05, 100 km): reflected rays steeper than
    # sin z0 = rho / (n R) are totally internally reflected back to the ground
    # (Lambert: a fraction 1 - (rho / (n R))^2 of the reflected power). Far away,
    # the gathered irradiance integrated over a sphere of radius r must equal
    # the power that escaped: this checks the radiance invariance L / n^2 and
    # the apparent ground radius of the traced gathering.
    rho = R + 100.0
    atm = Atmosphere(R, [rho], [1.05])
    m = photon_map(200_000, atm, seed=21)
    s = m.stats
    esc = 1 - (rho / (1.05 * R)) ** 2
    assert abs(s["returned"] / s["absorbed"] - esc) < 5 * np.sqrt(esc * (1 - esc) / s["n_absorbed"])
    r = 1000.0 * R
    xs, ws = np.polynomial.legendre.leggauss(96)
    th = 0.5 * np.pi * (xs + 1)
    phi, _ = gather(m, th, r, mode="surface", n_s=48, n_beta=48)
    power = 2 * np.pi * r * r * np.sum(0.5 * np.pi * ws * phi * np.sin(th))
    assert power == pytest.approx(s["reflected"], rel=3e-3), f"want {s['reflected']!r} got {power!r}"
