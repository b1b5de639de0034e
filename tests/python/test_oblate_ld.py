# SPDX-License-Identifier: MIT
"""The limb-darkened Sun behind the WGS-84 ellipsoid through the binding, along a line
across the ellipsoid's penumbra at GEO (the points of tests/ref/oblate.py's edge_point,
at offsets the C rows do not hold): both fractions non-increasing into the shadow,
exactly 1 and 0 outside it, the limb-darkened one below the uniform one on the dark
side (the limb dimmer than the mean). The values against the mpmath reference:
tests/c/test_oblate.c."""
import sys
from pathlib import Path

import mpmath
import numpy as np

import orbillum

_DPS = mpmath.mp.dps
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "ref"))
import oblate as ref  # noqa: E402  (tests/ref/oblate.py; sets 30 digits on import)

mpmath.mp.dps = _DPS  # the rest of the session keeps its own precision

WGS84 = {"earth_shape": "wgs84", "no_atmosphere": 1}


def test_fraction_ld_monotonic_across_the_penumbra():
    sun = [ref.AU_KM * np.cos(0.3), 0.0, ref.AU_KM * np.sin(0.3)]
    pts = np.array([ref.edge_point(sun, 35786.0, 1.0, off) for off in np.linspace(1.2, -1.2, 801)])
    out = orbillum.sun_fraction(sun, pts, model=WGS84)
    f, fl = out["fraction"], out["fraction_ld"]
    assert np.all(out["status"] >= 0)
    assert np.all(np.diff(fl) <= 4e-16) and np.all(np.diff(f) <= 4e-16)
    assert fl[0] == 1.0 and fl[-1] == 0.0
    thin = (f > 0.0) & (f < 0.2)
    assert np.any(thin) and np.all(fl[thin] <= f[thin])


# Random geometries against a numpy reference independent of the library's chords
# (tests/python/oblate_ld_reference.py; it agrees with tests/ref/oblate.py's
# mpmath reference to 2e-13 below). The library's double-precision fractions are
# within 3.4e-12 of it at these points (Earth alone and with the Moon).
RANDOM_TOL = 1e-10


def _random_geometries(n, seed=20261202):
    """n (sun, point, moon): the Sun at declination within +-23.44 deg and 0.983-1.017 AU,
    the point at an altitude log-uniform in 300 km .. 4e5 km across the ellipsoid's
    penumbra (ref.edge_point, offset -1 .. 1 of the sphere's), the Moon 3.6e5-4e5 km
    from the point within 0.008 rad of the Sun's direction (on or near the Sun's disc)."""
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        dec = np.radians(23.44) * rng.uniform(-1.0, 1.0)
        d = ref.AU_KM * rng.uniform(0.983, 1.017)
        sun = np.array([d * np.cos(dec), 0.0, d * np.sin(dec)])
        alt = float(np.exp(rng.uniform(np.log(300.0), np.log(4e5))))
        p = np.array(ref.edge_point(sun, alt, rng.uniform(0.0, 2 * np.pi), rng.uniform(-1.0, 1.0)))
        s = (sun - p) / np.linalg.norm(sun - p)
        toward = -p - np.dot(-p, s) * s
        toward /= np.linalg.norm(toward)
        a, b = rng.uniform(-0.008, 0.008, 2)
        u = s + a * toward + b * np.cross(s, toward)
        out.append((sun, p, p + rng.uniform(3.6e5, 4.0e5) * u / np.linalg.norm(u)))
    return out


def test_numpy_reference_against_mpmath():
    import oblate_ld_reference as npref
    sun = [ref.AU_KM * np.cos(0.3), 0.0, ref.AU_KM * np.sin(0.3)]
    p = ref.edge_point(sun, 35786.0, 0.7, -0.5)
    fu, fl, err = npref.fractions(sun, p)
    with mpmath.workdps(30):
        want = ref.case(sun, p, None, "d")
    assert 0.1 < fu < 0.9 and err < 1e-12
    assert abs(fu - float(want["frac"])) < 1e-12
    assert abs(fl - float(want["frac_ld"])) < 1e-12


def test_fraction_ld_random_points_against_reference():
    import oblate_ld_reference as npref
    worst = worst_moon = 0.0
    inside = 0
    for sun, p, moon in _random_geometries(8):
        fu, fl, _ = npref.fractions(sun, p)
        fum, flm, _ = npref.fractions(sun, p, moon)
        o = orbillum.sun_fraction(sun, [p], model=WGS84)
        om = orbillum.illuminate(sun, moon, p, terms="sun+moon", model=WGS84)
        assert o["status"][0] >= 0 and om["status"][0] >= 0
        worst = max(worst, abs(o["fraction"][0] - fu), abs(o["fraction_ld"][0] - fl))
        worst_moon = max(worst_moon, abs(om["sun_fraction"][0] - fum),
                         abs(om["sun_fraction_ld"][0] - flm))
        inside += (0.0 < fl < 1.0) + (0.0 < flm < 1.0) + (flm < fl)
    assert inside >= 12  # most points in the penumbra, the Moon hiding more in several
    assert worst < RANDOM_TOL, worst
    assert worst_moon < RANDOM_TOL, worst_moon
