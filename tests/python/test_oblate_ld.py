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
