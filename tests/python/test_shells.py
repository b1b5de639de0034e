# SPDX-License-Identifier: MIT
"""Shell tracer (bake/photon/shells.py) against closed forms: Snell's law, total
internal reflection, single-shell chords, Bouguer's invariant n r sin z,
the Lambertian direction distribution."""
import numpy as np
import pytest

from bake.photon.shells import (ESCAPED, HIT_EARTH, TRAPPED, Atmosphere, lambert_directions,
                         orthonormal_basis, refract, trace)


def _angle(a, b):
    return np.arctan2(np.linalg.norm(np.cross(a, b), axis=-1), np.sum(a * b, axis=-1))


def test_refract_snell_closed_form():
    rng = np.random.default_rng(1)
    m = 2000
    nf = np.tile([0.0, 0.0, 1.0], (m, 1))
    inc = rng.uniform(0.0, np.pi / 2 * 0.999, m)
    az = rng.uniform(0, 2 * np.pi, m)
    d = np.stack([np.sin(inc) * np.cos(az), np.sin(inc) * np.sin(az), -np.cos(inc)], 1)
    n1, n2 = 1.0, 1.33
    out, tir = refract(d, nf, n1, n2)
    assert not tir.any()
    t = _angle(out, -nf)
    np.testing.assert_allclose(np.sin(t), n1 / n2 * np.sin(inc), rtol=0, atol=1e-14)
    # refracted ray stays in the plane of incidence (same azimuth)
    np.testing.assert_allclose(np.cross(np.cross(d, nf), np.cross(out, nf)), 0.0, atol=1e-14)
    np.testing.assert_allclose(np.linalg.norm(out, axis=1), 1.0, atol=1e-14)


def test_refract_total_internal_reflection():
    n1, n2 = 1.5, 1.0
    crit = np.arcsin(n2 / n1)
    inc = np.array([crit - 1e-6, crit + 1e-6, 1.2, 1.5])
    d = np.stack([np.sin(inc), np.zeros(4), -np.cos(inc)], 1)
    out, tir = refract(d, np.tile([0.0, 0.0, 1.0], (4, 1)), n1, n2)
    assert list(tir) == [False, True, True, True]
    mirror = d * np.array([1.0, 1.0, -1.0])
    np.testing.assert_allclose(out[1:], mirror[1:], atol=1e-14)
    # just below the critical angle the transmitted ray grazes the surface
    assert abs(out[0, 2]) < 2e-3 and out[0, 2] < 0


def test_single_shell_chord_closed_form():
    # Earth radius 1, one shell of index n up to radius 2; rays from +z with
    # impact parameter b between 1 n... miss the Earth when b/n > 1.
    R, B1, n = 1.0, 2.0, 1.25
    atm = Atmosphere(R, [B1], [n])
    b = np.array([1.3, 1.5, 1.9, 1.999])
    o = np.stack([b, np.zeros(4), np.full(4, 10.0)], 1)
    res = trace(o, np.tile([0.0, 0.0, -1.0], (4, 1)), atm)
    assert np.all(res.status == ESCAPED) and np.all(res.n_cross == 2)
    z_out = np.arcsin(b / B1)
    z_in = np.arcsin(b / (n * B1))
    dev = _angle(res.dir, np.tile([0.0, 0.0, -1.0], (4, 1)))
    np.testing.assert_allclose(dev, 2 * (z_out - z_in), rtol=1e-12)
    np.testing.assert_allclose(res.path, 2 * np.sqrt(B1**2 - (b / n) ** 2), rtol=1e-12)
    np.testing.assert_allclose(res.r_min, b / n, rtol=1e-12)
    # bent towards the axis (x decreasing)
    assert np.all(res.dir[:, 0] < 0)


def test_single_shell_hits_earth_and_extinction():
    R, B1, n, k = 1.0, 2.0, 1.25, 0.3
    atm = Atmosphere(R, [B1], [n], extinction=[k])
    b = np.array([0.0, 0.5, 1.2])  # b/n < 1: hits
    o = np.stack([b, np.zeros(3), np.full(3, 10.0)], 1)
    res = trace(o, np.tile([0.0, 0.0, -1.0], (3, 1)), atm)
    assert np.all(res.status == HIT_EARTH)
    # straight chord inside the shell from B1 down to R with sin z = b/(n r)
    s = b / n
    length = np.sqrt(B1**2 - s**2) - np.sqrt(R**2 - s**2)
    np.testing.assert_allclose(res.path, length, rtol=1e-12)
    np.testing.assert_allclose(res.tau, k * length, rtol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(res.pos, axis=1), R, rtol=1e-15)
    # zenith angle at the surface: sin z = b / (n R)
    z = _angle(-res.dir, res.pos)
    np.testing.assert_allclose(np.sin(z), b / (n * R), atol=1e-12)


@pytest.mark.parametrize("z0_deg, expect_tir", [(40.0, False), (52.0, False), (54.5, True), (70.0, True), (85.0, True)])
def test_tir_from_the_ground(z0_deg, expect_tir):
    # A ray leaving the ground inside a dense shell: at the shell top
    # sin z1 = R sin z0 / B1; TIR iff n sin z1 > 1. Reflected rays land again at
    # central angle 2 (z0 - z1) with zenith angle z0.
    R, B1, n = 1.0, 1.2, 1.5
    atm = Atmosphere(R, [B1], [n])
    z0 = np.radians(z0_deg)
    o = np.array([[0.0, 0.0, R]])
    d = np.array([[np.sin(z0), 0.0, np.cos(z0)]])
    res = trace(o, d, atm)
    z1 = np.arcsin(R * np.sin(z0) / B1)
    assert (n * np.sin(z1) > 1.0) == expect_tir
    if expect_tir:
        assert res.status[0] == HIT_EARTH and res.n_tir[0] == 1 and res.n_cross[0] == 0
        c = _angle(res.pos, o)[0]
        assert abs(c - 2 * (z0 - z1)) < 1e-12, f"want {2*(z0-z1)!r} got {c!r}"
        z_land = _angle(-res.dir, res.pos)[0]
        assert abs(z_land - z0) < 1e-12
    else:
        assert res.status[0] == ESCAPED and res.n_tir[0] == 0 and res.n_cross[0] == 1
        # Snell at the top: sin z_out = n sin z1
        z_out = _angle(res.dir, res.pos)[0]
        assert abs(np.sin(z_out) - n * np.sin(z1)) < 1e-12


def test_tir_from_outside_a_rarer_shell():
    # a shell of index < 1 reflects grazing rays coming from the vacuum
    atm = Atmosphere(1.0, [2.0], [0.8])
    o = np.array([[1.95, 0.0, 10.0]])  # sin z at B1 = 0.975 > 0.8
    res = trace(o, np.array([[0.0, 0.0, -1.0]]), atm)
    assert res.status[0] == ESCAPED and res.n_tir[0] == 1 and res.n_cross[0] == 0
    assert res.dir[0, 2] > 0 or res.dir[0, 0] > 0


def test_whispering_gallery_is_trapped_not_looping_forever():
    atm = Atmosphere(1.0, [1.1, 2.0], [1.0, 2.0])
    o = np.array([[1.9, 0.0, 0.0]])
    res = trace(o, np.array([[0.0, 1.0, 0.0]]), atm, max_steps=50)
    assert res.status[0] == TRAPPED and res.n_tir[0] >= 49


def test_bouguer_invariant_and_symmetry_exponential():
    atm = Atmosphere.exponential(n_shells=40)
    R = atm.earth_radius
    rng = np.random.default_rng(7)
    m = 4000
    b = R + rng.uniform(-200.0, 120.0, m)
    o = np.stack([b, np.zeros(m), np.full(m, 2e4)], 1)
    res = trace(o, np.tile([0.0, 0.0, -1.0], (m, 1)), atm)
    esc = res.status == ESCAPED
    hit = res.status == HIT_EARTH
    # invariant: b = |p x d| in the vacuum after leaving
    bout = np.linalg.norm(np.cross(res.pos[esc], res.dir[esc]), axis=1)
    np.testing.assert_allclose(bout, b[esc], rtol=1e-11)
    # at the ground: n1 R sin z = b
    z = _angle(-res.dir[hit], res.pos[hit])
    np.testing.assert_allclose(atm.indices[0] * R * np.sin(z), b[hit], rtol=1e-10)
    # hits iff b < n1 R (no ducting: n r increases with r)
    np.testing.assert_array_equal(hit, b < atm.indices[0] * R)
    # escaped rays that entered cross each boundary twice
    entered = esc & (b < atm.outer_radius)
    assert np.all(res.n_cross[entered] % 2 == 0)
    assert np.all(res.n_cross[esc & (b > atm.outer_radius)] == 0)
    # grazing bending: between 1 and 1.4 degrees (docs/physics.md: ~1.1-1.2 deg)
    graze = esc & (b < atm.indices[0] * R + 0.5)
    dev = np.degrees(_angle(res.dir[graze], np.array([0.0, 0.0, -1.0])))
    assert dev.size and np.all((dev > 1.0) & (dev < 1.4)), dev


def test_bare_earth_hit_point():
    atm = Atmosphere.bare(1.0)
    b = np.array([0.0, 0.3, 0.99, 1.01])
    o = np.stack([b, np.zeros(4), np.full(4, 5.0)], 1)
    res = trace(o, np.tile([0.0, 0.0, -1.0], (4, 1)), atm)
    assert list(res.status) == [HIT_EARTH, HIT_EARTH, HIT_EARTH, ESCAPED]
    np.testing.assert_allclose(res.pos[:3, 2], np.sqrt(1 - b[:3] ** 2), rtol=1e-14)
    assert res.n_cross.sum() == 0 and res.path.sum() == 0.0
    assert abs(res.r_min[3] - 1.01) < 1e-14


def test_region_of_and_validation():
    atm = Atmosphere(1.0, [1.5, 2.0], [1.1, 1.05])
    np.testing.assert_array_equal(atm.region_of([0.5, 1.0, 1.2, 1.5, 1.9, 2.0, 3.0]),
                                  [0, 1, 1, 2, 2, 3, 3])
    with pytest.raises(ValueError):
        Atmosphere(1.0, [2.0, 1.5], [1.0, 1.0])
    with pytest.raises(ValueError):
        trace(np.zeros((1, 3)), np.array([[1.0, 0, 0]]), atm)


def test_lambert_directions_cosine_law():
    rng = np.random.default_rng(3)
    m = 200000
    nrm = rng.normal(size=(m, 3))
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
    d = lambert_directions(nrm, rng)
    c = np.sum(d * nrm, axis=1)
    assert np.all(c >= 0)
    # cos e has cdf c^2: mean 2/3, P(c < 0.5) = 1/4 (5 sigma bounds)
    assert abs(c.mean() - 2 / 3) < 5 * np.sqrt(1 / 18 / m)
    assert abs(np.mean(c < 0.5) - 0.25) < 5 * np.sqrt(0.25 * 0.75 / m)
    t1, t2 = orthonormal_basis(nrm)
    for a, bb in ((t1, t2), (t1, nrm), (t2, nrm)):
        np.testing.assert_allclose(np.sum(a * bb, axis=1), 0.0, atol=1e-14)
