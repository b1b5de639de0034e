# SPDX-License-Identifier: MIT
"""The SOLAARS penumbra fit and the shadow levels along a pass.

SOLAARS (Solar radiation pressure with Oblateness and Lower Atmospheric
Absorption, Refraction, and Scattering; R. V. Robertson 2015, PhD
dissertation, Virginia Tech, "Highly Physical Solar Radiation Pressure
Modeling During Penumbra Transitions", pp. 67-75; Robertson et al. 2015,
Celest. Mech. Dyn. Astr. 123, 169) is a total-solar-irradiance model of the
Earth's penumbra, validated on GRACE accelerometer data (~490 km). Its
closed-form fit gives the fraction of unobstructed sunlight from the point's
distance behind the Earth along the anti-Sun axis (z) and from that axis
(rho), both in units of 1000 km:

    F = [1 + a1 + a2 + a1 tanh(a3 (rho - a4)) + a2 tanh(a5 (rho - a6))
         + tanh(a7 (rho - a8))] / [2 (1 + a1 + a2)],

each a_k a function of z with the published coefficients b_kj (ROBERTSON_B
below; numbers of the publication, evaluated here by our own code). The
fit describes the band of rho where the atmosphere matters; outside it
(beyond the 100 km top's shadow) the light is full. Its z axis is scaled
for the Earth's flattening (the point's polar coordinate times a / b), which
does not enter on an equatorial (beta = 0) pass.

`pass_levels` finds, along a beta = 0 circular pass of altitude h (the Sun
in the orbit's plane), the height rho - R_eq of the straight Sun-centre line
above the equatorial radius where a fraction first reaches 10 %, 50 %, 90 %
coming out of the umbra: the numbers of the SOLAARS comparison in
docs/atmosphere.md (`python tools/solaars_compare.py`).
"""
from __future__ import annotations

import numpy as np

from ..common.constants import AU_KM, R_EARTH_KM, SUN_RADIUS_KM

# Robertson (2015), the fit's coefficients b_kj: a1, a3, a5, a7, a8 are
# b_k1 exp(b_k2 z) + b_k3 exp(b_k4 z); a2, a6 are b_k1 z + b_k2; a4 is
# b_k1 z^b_k2 + b_k3 (z in 1000 km).
ROBERTSON_B = {
    1: (0.1715, -0.1423, 0.01061, -0.01443),
    2: (0.008162, 0.3401),
    3: (260.9, -0.4661, 27.81, -0.009437),
    4: (-0.006119, 1.176, 6.385),
    5: (87.56, -0.09188, 19.30, -0.01089),
    6: (0.002047, 6.409),
    7: (61.98, -0.1629, 27.87, -0.02217),
    8: (6.413, -0.0002593, -0.01479, -0.1318),
}

# The published levels at 490 km, beta = 0 (km above the equatorial radius):
# the fit evaluated by `pass_levels(solaars_fraction, 490)` reproduces them.
SOLAARS_490_KM = {0.1: -3.7, 0.5: 22.6, 0.9: 41.5}
LEVELS = (0.1, 0.5, 0.9)


def _two_exp(b, z):
    return b[0] * np.exp(b[1] * z) + b[2] * np.exp(b[3] * z)


def solaars_fraction(z_km, rho_km, d_sun_km=AU_KM):
    """The SOLAARS fit's fraction at distance z_km behind the Earth's centre
    and rho_km from the shadow's axis (arrays broadcast); 1 outside the
    penumbra of a sphere 100 km above the equatorial radius (the model's
    domain), in the planar cone approximation."""
    z_km = np.asarray(z_km, dtype=float)
    rho_km = np.asarray(rho_km, dtype=float)
    reach = (R_EARTH_KM + 100.0) * (1.0 + z_km / d_sun_km) + z_km * SUN_RADIUS_KM / d_sun_km
    z = z_km / 1000.0
    r = rho_km / 1000.0
    b = ROBERTSON_B
    a1, a3, a5, a7, a8 = (_two_exp(b[k], z) for k in (1, 3, 5, 7, 8))
    a2 = b[2][0] * z + b[2][1]
    a6 = b[6][0] * z + b[6][1]
    a4 = b[4][0] * z ** b[4][1] + b[4][2]
    num = (1.0 + a1 + a2 + a1 * np.tanh(a3 * (r - a4)) + a2 * np.tanh(a5 * (r - a6))
           + np.tanh(a7 * (r - a8)))
    return np.where(rho_km >= reach, 1.0, num / (2.0 * (1.0 + a1 + a2)))


def pass_points(alt_km, heights_km, earth_radius_km=R_EARTH_KM):
    """(z, rho) of the points of a beta = 0 circular pass of altitude alt_km
    whose straight Sun-centre line passes heights_km above earth_radius_km."""
    r = earth_radius_km + alt_km
    rho = earth_radius_km + np.asarray(heights_km, dtype=float)
    return np.sqrt(r * r - rho * rho), rho


def pass_levels(fraction_fn, alt_km, levels=LEVELS, h_lo=-250.0, h_hi=250.0, step_km=0.01,
                earth_radius_km=R_EARTH_KM):
    """Heights (km above earth_radius_km) of the Sun-centre line where
    fraction_fn(z, rho) (vectorised) first reaches each level coming out of
    the umbra along a beta = 0 pass of altitude alt_km: scanned every
    step_km from h_lo, linear between the two bracketing points; None where
    the level is not reached below h_hi."""
    h = np.arange(h_lo, h_hi + 0.5 * step_km, step_km)
    z, rho = pass_points(alt_km, h, earth_radius_km)
    f = np.asarray(fraction_fn(z, rho), dtype=float)
    out = {}
    for lev in levels:
        above = np.nonzero(f >= lev)[0]
        if above.size == 0:
            out[lev] = None
            continue
        i = int(above[0])
        if i == 0:
            out[lev] = float(h[0])
            continue
        f0, f1 = f[i - 1], f[i]
        out[lev] = float(h[i - 1] + (lev - f0) / (f1 - f0) * step_km)
    return out


def bisect_level(fraction_at, alt_km, level, h_lo=-250.0, h_hi=250.0, tol_km=0.01,
                 earth_radius_km=R_EARTH_KM):
    """The height where a monotonic fraction_at(z, rho) (scalar) crosses
    level along the pass, by bisection to tol_km (for the costly ray
    reference); None if it is not crossed within [h_lo, h_hi]."""
    def f(hh):
        z, rho = pass_points(alt_km, hh, earth_radius_km)
        return fraction_at(float(z), float(rho))
    lo, hi = h_lo, h_hi
    if f(lo) >= level or f(hi) < level:
        return None
    while hi - lo > tol_km:
        mid = 0.5 * (lo + hi)
        if f(mid) >= level:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)
