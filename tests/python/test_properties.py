# SPDX-License-Identifier: MIT
"""Property tests: hypothesis on the runtime through tests/python/_oi_ctypes.py
(the binding's ctypes mirror over build/libori_test.so), and on the baker's geometry.

- rotation invariance: rotating every input position leaves every scalar
  output of oi_illuminate unchanged (and rotates the direction outputs);
- scale behaviour: e_sun |sun - target|^2, e_earth |sun|^2 and
  e_moon |sun - moon|^2 do not depend on the Sun's distance (lit geometry);
- monotonicity: earthshine falls with altitude at fixed theta where physics
  demands it (theta <= 85 deg: the reference phi of bake/reference.py rises
  with altitude in a band of heights from theta ~ 87 deg on, because climbing
  shows more of the lit side; measured in test_reference_monotone_domain), and
  the Sun fraction grows monotonically across the penumbra as the point moves
  away from the shadow axis;
- the baker's ray tracer (bake/shells.py) is rotation invariant.
"""
import math
import os

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, example, given, settings
from hypothesis import strategies as st

import _oi_ctypes as oi

AU = 149597870.7
R_E = 6378.137
R_S = 695700.0
SETTINGS = settings(max_examples=int(os.environ.get("PROP_EXAMPLES", "150")), deadline=None,
                    suppress_health_check=[HealthCheck.too_slow])



@st.composite
def unit_vectors(draw):
    v = np.array([draw(st.floats(-1, 1)) for _ in range(3)])
    n = np.linalg.norm(v)
    assume(n > 0.1)
    return v / n


@st.composite
def rotations(draw):
    q = np.array([draw(st.floats(-1, 1)) for _ in range(4)])
    n = np.linalg.norm(q)
    assume(n > 0.1)
    w, x, y, z = q / n
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


@st.composite
def scenes(draw):
    sun = draw(unit_vectors())
    sun = sun * AU * draw(st.floats(0.983, 1.017))
    h = 10 ** draw(st.floats(-3, 6))
    target = draw(unit_vectors()) * (R_E + h)
    moon = draw(unit_vectors()) * draw(st.floats(356000, 407000))
    offset = draw(unit_vectors()) * 10 ** draw(st.floats(-1, 4))
    observer = target + offset
    assume(np.linalg.norm(observer) > R_E + 1)
    return sun, target, moon, observer


def close(a, b, rel, abs_):
    return abs(a - b) <= abs_ + rel * max(abs(a), abs(b))


# tolerance per output: relative, absolute. Rotation perturbs positions by
# rounding (~1e-16 relative), which every output amplifies by its condition
# number: 1e-9 relative leaves a margin of 1e6 for the ill-conditioned edges.
def tol(name):
    if name in ("mag_v",):
        return 0, 1e-8
    if "phase" in name or name.endswith("_rad") or name in ("earth_theta", "earth_psi"):
        return 1e-9, 1e-12
    if name.startswith("shadow.fraction") or name == "moon_sun_fraction":
        return 1e-9, 1e-12
    if name == "earth_h_km":
        return 1e-12, 1e-9
    # earthshine near theta = pi is a steep function of the angle (night side):
    # absolute tolerance, 1e-12 of the largest value (phi <= 2, E0 <= 1410)
    if name == "earth_phi":
        return 1e-9, 2e-12
    if name == "e_earth":
        return 1e-9, 0.3 * 1410 * 2e-12
    return 1e-9, 1e-300


@SETTINGS
@given(scenes(), rotations(), st.sampled_from([0, 1]))
# on the Sun-Earth axis (theta 0) the Earth's light is symmetric about the
# zenith and the sphere's cubature must sit the same way towards the observer
# whatever the frame (a mirror turn here once moved flux_earth by 1.5e-5)
@example(scene=(np.array([1.49597871e+08, 0.0, 0.0]), np.array([7378.137, 0.0, 0.0]),
                np.array([0.0, 0.0, 356000.0]), np.array([7378.137, 0.0, 1.0])),
         rot=np.array([[-1.0, 0.0, 0.0], [0.0, 2.220446049250313e-16, 1.0],
                       [0.0, 1.0, 2.220446049250313e-16]]),
         earth_model=0)
# at 100,000 km exactly, where a cubature rule switched by altitude once
# stepped flux_earth by 3.2e-3 between the two sides of the rounding
@example(scene=(np.array([0.0, 0.0, 1.49597871e+08]), np.array([0.0, 0.0, 106378.137]),
                np.array([0.0, 0.0, 356000.0]), np.array([0.0, 0.0, 106379.137])),
         rot=np.array([[-1.0, 0.0, 0.0], [0.0, 2.220446049250313e-16, 1.0],
                       [0.0, 1.0, 2.220446049250313e-16]]),
         earth_model=0)
# the terminator through the sub-target point (theta = pi/2): the lit arc's
# acos once stepped by 4.4e-8 as cos(theta)'s rounding crossed 0
@example(scene=(np.array([0.0, 0.0, 1.49597871e+08]), np.array([0.0, 7378.137, 4.12792897e-219]),
                np.array([0.0, 0.0, 356000.0]), np.array([0.0, 7378.137, 1.0])),
         rot=np.array([[-1.0, 0.0, 0.0], [0.0, 15.0 / 17.0, 8.0 / 17.0],
                       [0.0, 8.0 / 17.0, -15.0 / 17.0]]),
         earth_model=0)
# on the anti-Sun axis in the umbra, where the refracted light reaches it: the
# tilt's direction, normal to the axis, is rounding noise in a turned frame
# (dir_sun once moved by 1.5e-7 rad, the psi table's code nearest 0)
@example(scene=(np.array([1.49597871e+08, 0.0, 0.0]), np.array([-322605.90301684, 0.0, 0.0]),
                np.array([0.0, 0.0, 356000.0]), np.array([-322605.90301684, 0.0, 1.0])),
         rot=np.array([[-0.6, 0.8, 0.0], [0.8, 0.6, 0.0], [0.0, 0.0, -1.0]]),
         earth_model=0)
@example(scene=(np.array([1.49597871e+08, 0.0, 0.0]), np.array([-322605.90301684, 0.0, 0.0]),
                np.array([0.0, 0.0, 356000.0]), np.array([-322605.90301684, 0.0, 1.0])),
         rot=np.array([[-0.6, 0.0, 0.8], [0.0, -1.0, 0.0], [0.8, 0.0, 0.6]]),
         earth_model=0)
def test_rotation_invariance(scene, rot, earth_model):
    sun, target, moon, observer = scene
    m = oi.model(earth_model=earth_model)
    st0, a = oi.illuminate(sun, target, moon, observer, m=m)
    st1, b = oi.illuminate(rot @ sun, rot @ target, rot @ moon, rot @ observer, m=m)
    # the status is invariant too, except that a warning may flip where the
    # point sits within rounding of a table's range (e.g. the atmosphere
    # table's z = 0 plane through the terminator)
    assert st0 == st1 or (st0 >= 0 and st1 >= 0), (st0, st1)
    assume(st0 >= 0)
    # a flux reflected at a phase angle near pi (p ~ t^3) is ill-conditioned:
    # its tolerance is absolute, 1e-9 of the largest flux that source could
    # send (phase angle 0)
    geo = 0.2 * (1e-3 / a.range_km) ** 2 * (2.0 / 3.0)
    flux_tol = {n: geo * (1e-9 * max(getattr(a, "e_" + n[5:]), getattr(b, "e_" + n[5:])) +
                          tol("e_" + n[5:])[1])
                for n in ("flux_sun", "flux_earth", "flux_moon")}
    flux_tol["flux_obs"] = sum(flux_tol.values())
    # the rotated positions carry rounding of ~u |position|: seen from the
    # observer, directions move by up to ~u |position| / range
    u = 2.0 ** -53
    lever = 64 * u * max(np.linalg.norm(target), np.linalg.norm(observer)) / a.range_km
    # the altitude h = |r| - R carries that rounding too (8 u |r| absolute): near the surface
    # it is a large part of h, and phi and psi move with it by their slope in h
    dh = 8 * u * np.linalg.norm(target)
    h_slope = {}
    if a.earth_h_km > 2 * dh:
        _, phi_lo, psi_lo = oi.earthshine(a.earth_theta, a.earth_h_km - dh, m)
        _, phi_hi, psi_hi = oi.earthshine(a.earth_theta, a.earth_h_km + dh, m)
        h_slope = {"earth_psi": abs(psi_hi - psi_lo), "earth_phi": abs(phi_hi - phi_lo)}
    for name in oi.SCALAR_OUTPUTS:
        va, vb = oi.get(a, name), oi.get(b, name)
        assert math.isfinite(va) and math.isfinite(vb)
        r, ab = tol(name)
        if name.startswith("phase_"):
            ab += lever
        if name == "range_km":
            r += lever
        if name in flux_tol:
            ab = max(ab, flux_tol[name])
        ab += h_slope.get(name, 0.0)
        if name == "mag_v":
            # from the flux's tolerance
            f, tf = min(a.flux_obs, b.flux_obs), flux_tol["flux_obs"] + 1e-9 * a.flux_obs
            ab = 99.0 if f <= tf else max(ab, 2.5 * math.log10((f + tf) / (f - tf)))
        assert close(va, vb, r, ab), (name, va, vb)
    assert a.shadow.region == b.shadow.region or close(
        a.shadow.fraction, b.shadow.fraction, 1e-9, 1e-12)
    for d in ("dir_sun", "dir_earth", "dir_moon"):
        da = rot @ np.array(getattr(a, d)[:])
        db = np.array(getattr(b, d)[:])
        assert np.all(np.abs(da - db) <= 1e-9), (d, da, db)


@SETTINGS
@given(unit_vectors(), unit_vectors(), st.floats(0, 6), st.floats(0.5, 2.0),
       st.floats(356000, 407000))
def test_irradiance_scales_with_sun_distance(sdir, tdir, logh, k, moon_r):
    # target on the day side (angle to the Sun < 80 deg): fully lit at any
    # Sun distance
    assume(float(np.dot(sdir, tdir)) > math.cos(math.radians(80)))
    target = tdir * (R_E + 10 ** logh)
    moon = sdir * moon_r  # on the Sun's line: lit, never in the shadow
    # ... unless it hides part of the Sun from the target (within 2 deg of it
    # seen from there: the Moon occults the Sun): then on the other side
    to_moon = moon - target
    if np.dot(to_moon, sdir) > np.linalg.norm(to_moon) * math.cos(math.radians(2)):
        moon = -moon
    # a target inside or at the Moon is refused (OI_ERR_GEOMETRY): not this property's case
    assume(float(np.linalg.norm(moon - target)) > 2 * 1737.4)
    m = oi.model(earth_model=oi.EARTH_LAMBERT)
    res = []
    for f in (1.0, k):
        sun = sdir * AU * f
        s, il = oi.illuminate(sun, target, moon, None, m=m)
        assert s >= 0
        assert il.shadow.fraction == 1.0
        res.append((il, sun))
    (a, sa), (b, sb) = res
    ea = a.e_sun * np.linalg.norm(sa - target) ** 2
    eb = b.e_sun * np.linalg.norm(sb - target) ** 2
    assert close(ea, eb, 1e-12, 0), (ea, eb)
    ea = a.e_earth * np.linalg.norm(sa) ** 2
    eb = b.e_earth * np.linalg.norm(sb) ** 2
    assert close(ea, eb, 1e-10, 0), (ea, eb)
    if a.moon_sun_fraction == 1.0 and b.moon_sun_fraction == 1.0:
        ea = a.e_moon * np.linalg.norm(sa - moon) ** 2
        eb = b.e_moon * np.linalg.norm(sb - moon) ** 2
        # the Moon's phase angle changes slightly with the Sun's distance
        assert close(ea, eb, 1e-3, 0), (ea, eb)


def test_reference_monotone_domain():
    """Where physics demands monotonicity: the deterministic reference falls
    with altitude for theta <= 86 deg and rises in a band from 87 deg on."""
    ref = pytest.importorskip("bake.earthshine.reference")
    h = np.geomspace(1e-3, 1e7, 1500)
    for deg, rising in ((0, False), (45, False), (85, False), (86, False), (88, True)):
        phi = ref.phi_reference(np.full_like(h, math.radians(deg)), ref.x_from_h(h))
        assert bool(np.any(np.diff(phi) > 0)) == rising, deg


def table_bottom_km():
    """Lowest altitude of the default earthshine table (status 0 above it),
    by bisection on the status at theta = 0."""
    lo, hi = 1e-3, 1e5
    if oi.earthshine(0.0, lo)[0] == 0:
        return lo
    for _ in range(80):
        mid = math.sqrt(lo * hi)
        if oi.earthshine(0.0, mid)[0] == 0:
            hi = mid
        else:
            lo = mid
    return hi


@SETTINGS
@given(st.floats(0, math.radians(85)), st.floats(-3, 7), st.floats(-3, 7),
       st.sampled_from([0, 1]))
def test_earthshine_falls_with_altitude(theta, lh1, lh2, earth_model):
    h1, h2 = sorted((10 ** lh1, 10 ** lh2))
    assume(h1 < h2)
    if earth_model == oi.EARTH_TABLE:
        # below the table the runtime falls back to the far field: a known
        # discontinuity, test_earthshine_below_table_continuous
        assume(h1 >= table_bottom_km())
    m = oi.model(earth_model=earth_model)
    s1, p1, _ = oi.earthshine(theta, h1, m)
    s2, p2, _ = oi.earthshine(theta, h2, m)
    assert s1 >= 0 and s2 >= 0
    assert p1 >= p2 * (1 - 1e-12), (theta, h1, h2, p1, p2)


def test_earthshine_below_table_continuous():
    """Just below the table's bottom, phi stays within 1 % of the value at
    the bottom, and near the surface at theta = 0 phi approaches 2 (a
    Lambertian plane of unit irradiance and albedo: 2 pi L, L = 1/pi)."""
    hb = table_bottom_km()
    for theta in (0.0, 0.5, 1.0, 1.4):
        _, above, _ = oi.earthshine(theta, hb * 1.0001)
        _, below, _ = oi.earthshine(theta, hb * 0.9999)
        assert abs(below - above) <= 0.01 * above, (theta, hb, below, above)
    _, p, _ = oi.earthshine(0.0, 1e-3)
    assert abs(p - 2.0) <= 0.01


@SETTINGS
@given(st.floats(-3, 6), st.floats(-2.0, 2.0), st.floats(-2.0, 2.0), unit_vectors(),
       st.floats(0.983, 1.017))
def test_sun_fraction_monotonic_across_penumbra(logh, u1, u2, axis, au):
    """A point at fixed distance r moved away from the anti-Sun axis by the
    angle gamma: gamma = re + u rs sweeps the penumbra for u in [-2, 2]."""
    r = R_E + 10 ** logh
    sun = np.array([AU * au, 0.0, 0.0])
    # the plane of motion contains the Sun-Earth axis; axis picks its azimuth
    side = np.array([0.0, axis[1], axis[2]])
    assume(np.linalg.norm(side) > 0.1)
    side /= np.linalg.norm(side)
    re = math.asin(R_E / r)
    rs = R_S / (AU * au)
    fr = []
    for u in sorted((u1, u2)):
        g = max(re + u * rs, 0.0)
        p = r * (-math.cos(g) * np.array([1.0, 0, 0]) + math.sin(g) * side)
        s, sh = oi.sun_fraction(sun, p)
        assert s >= 0  # OI_WARN_TABLE_RANGE: outside the atmosphere table
        assert 0.0 <= sh.fraction <= 1.0 and 0.0 <= sh.fraction_ld <= 1.0
        fr.append(sh)
    assert fr[0].fraction <= fr[1].fraction + 1e-15, (fr[0].fraction, fr[1].fraction)
    assert fr[0].fraction_ld <= fr[1].fraction_ld + 1e-15, (fr[0].fraction_ld, fr[1].fraction_ld)


# ---- the baker's geometry

@settings(max_examples=40, deadline=None)
@given(rotations(), st.integers(0, 2 ** 32 - 1), st.sampled_from(["bare", "exp"]))
def test_shell_tracer_rotation_invariant(rot, seed, kind):
    shells = pytest.importorskip("bake.photon.shells")
    atm = shells.Atmosphere.bare() if kind == "bare" else shells.Atmosphere.exponential(n_shells=12)
    rng = np.random.default_rng(seed)
    n = 64
    # rays from 2 R_E aimed at points near the Earth's limb (grazing and hitting)
    org = rng.normal(size=(n, 3))
    org = 2 * R_E * org / np.linalg.norm(org, axis=1)[:, None]
    aim = rng.normal(size=(n, 3))
    aim = (R_E + rng.uniform(-50, 150, n))[:, None] * aim / np.linalg.norm(aim, axis=1)[:, None]
    d = aim - org
    a = shells.trace(org, d, atm)
    b = shells.trace(org @ rot.T, d @ rot.T, atm)
    # ray outcomes agree except where a ray grazes a boundary within rounding
    same = (a.status == b.status) & (a.n_cross == b.n_cross) & (a.n_tir == b.n_tir)
    assert np.mean(same) >= 0.95
    assert np.allclose(a.path[same], b.path[same], rtol=1e-9, atol=1e-9)
    assert np.allclose(a.tau[same], b.tau[same], rtol=1e-9, atol=1e-12)
    assert np.allclose(a.r_min[same], b.r_min[same], rtol=1e-12, atol=1e-9)
    assert np.allclose((a.pos @ rot.T)[same], b.pos[same], rtol=0, atol=1e-7)
    assert np.allclose((a.dir @ rot.T)[same], b.dir[same], rtol=0, atol=1e-9)


@settings(max_examples=30, deadline=None)
@given(st.floats(0, math.pi), st.floats(-3, 6), st.floats(4, 6))
def test_reference_far_field_and_order(theta, lh1, lh2):
    """bake.earthshine.reference: phi >= 0, psi in [-pi/2, pi/2], and phi tends to the
    Lambert far field (R/r)^2 p(theta): on the day side the relative
    difference is O(x), x = R/r: below 1.0 x for theta < 80 deg and h >= 1e4 km
    (measured max 0.79 x). A ratio test between r and 10 r is not valid: the
    x and x^2 terms can cancel at r (hypothesis found theta = 1.28, h = 1e4 km)."""
    ref = pytest.importorskip("bake.earthshine.reference")
    for lh in (lh1, lh2):
        x = ref.x_from_h(10 ** lh)
        phi, psi = ref.phi_psi_reference(np.array([theta]), np.array([x]))
        assert phi[0] >= 0 and abs(psi[0]) <= math.pi / 2 + 1e-12
    if theta < math.radians(80):
        for r in (R_E + 10 ** lh2, 10 * (R_E + 10 ** lh2)):
            x = np.array([R_E / r])
            phi = ref.phi_reference(np.array([theta]), x)[0]
            err = abs(phi / ref.far_field(np.array([theta]), x)[0] - 1)
            assert err <= 1.0 * x[0] + 1e-12, (err, x[0])


@settings(max_examples=60, deadline=None)
@given(st.one_of(st.sampled_from([0.0, math.pi / 2, math.pi, 1e-300, math.pi - 1e-15,
                                  math.nextafter(math.pi / 2, 0)]),
                 st.floats(0, math.pi)),
       st.one_of(st.sampled_from([1e-9, 1e-6, 1e-3, 1.0, 1e9, 1e15]), st.floats(1e-6, 1e12)))
def test_reference_extreme_inputs_finite(theta, h):
    """The baker's reference quadrature at stiff inputs (1e-9 km to 1e15 km,
    theta exactly 0, pi/2, pi): finite, phi >= 0, psi in [0, pi/2], and phi
    below its subsolar value at that altitude."""
    ref = pytest.importorskip("bake.earthshine.reference")
    x = np.array([ref.x_from_h(h)])
    with np.errstate(all="raise"):
        phi, psi = ref.phi_psi_reference(np.array([theta]), x)
        phi0, _ = ref.phi_psi_reference(np.array([0.0]), x)
    assert np.isfinite(phi[0]) and np.isfinite(psi[0]) and phi[0] >= 0
    assert -1e-12 <= psi[0] <= math.pi / 2 + 1e-12
    assert phi[0] <= phi0[0] * (1 + 1e-12)
