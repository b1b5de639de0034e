# SPDX-License-Identifier: MIT
"""How far the camera background's sky share (oi_expose_scene Note 3b: the mean
radiance e_sky / Omega of the atmosphere seen from the observer) is from the radiance
along the actual line of sight, by the single-scattering quadrature's own radiance.

    python -m bake.skylight.background

For observers at a few altitudes and Sun angles, lines of sight drawn uniformly over
the atmosphere's disc (those ending on the sunlit floor left out, as the runtime
does), it prints the distribution of L(line) / (E_sky / Omega): the factor by which
the estimate is off for a boresight at random, and its share of lines within a factor
of 3."""
from __future__ import annotations

import math

import numpy as np

from . import single
from .medium import Medium

CASES = [(400.0, 100.0), (400.0, 112.0), (800.0, 120.0), (35786.0, 100.0), (35786.0, 160.0)]


def run(n=4000, seed=3):
    med = Medium()
    ss = single.SingleScattering(med)
    rng = np.random.Generator(np.random.PCG64(seed))
    print("h_obs_km theta_deg  median  p10    p90   within_x3  (L_line / (E_sky/Omega))")
    for h, th_deg in CASES:
        r = med.R + h
        th = math.radians(th_deg)
        e, _ = ss.irradiance(th, r)
        a_top = math.asin(med.r_top / r)
        omega = 2 * math.pi * (1 - math.cos(a_top))
        cos_nu = 1 - rng.random(n) * (1 - math.cos(a_top))
        nu = np.arccos(cos_nu)
        az = math.pi * rng.random(n)
        L = ss.radiance(th, r, nu, az)
        # lines ending on the sunlit floor are not the sky's (the runtime adds nothing)
        rt2 = (r * np.sin(nu)) ** 2
        tc = r * np.cos(nu)
        hits = rt2 < med.r_floor ** 2
        t_out = tc - np.sqrt(np.maximum(med.r_floor ** 2 - rt2, 0.0))
        s = np.array([math.sin(th), 0.0, math.cos(th)])
        u_s = np.sin(nu) * np.cos(az) * s[0] - np.cos(nu) * s[2]
        lit = hits & (r * s[2] + t_out * u_s > 0)
        keep = ~lit
        if e <= 0 or not np.any(keep):
            print("%8.0f %9.1f  (no scattered light)" % (h, th_deg))
            continue
        ratio = L[keep] / (e / omega)
        pos = ratio[ratio > 0]
        within = np.mean((ratio > 1 / 3) & (ratio < 3))
        print("%8.0f %9.1f  %6.3g %6.3g %6.3g  %5.2f" % (
            h, th_deg, np.median(ratio), np.percentile(ratio, 10), np.percentile(ratio, 90),
            within) + ("" if pos.size == ratio.size else "   (%d%% of lines dark)" % round(
                100 * (1 - pos.size / ratio.size))))


if __name__ == "__main__":
    run()
