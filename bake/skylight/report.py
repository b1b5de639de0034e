# SPDX-License-Identifier: MIT
"""The numbers of docs/skylight.md: the scattered sunlight in the LEO umbra against
the refracted sunlight and a full Moon, and how far the camera background's sky share
is from the radiance along the actual line of sight.

    python -m bake.skylight.report     (needs build/oi-plan: make all)

1. A target at 400 km (and 800 km) swept through the shadow edge in the Sun-Earth plane,
   through the planner (build/oi-plan, terms sun+earth+moon+sky, a nearly full Moon, 4.5 deg
   from opposition, outside the Earth's shadow): e_sun (the refracted sunlight in the
   umbra), e_earth, e_moon, e_sky.
2. The background's sky share (oi_expose_scene Note 3b: the mean radiance e_sky / Omega
   of the atmosphere seen from the observer) against the radiance along the line of
   sight, by the single-scattering quadrature's own radiance.

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


def umbra_sweep(root=None):
    import os
    import subprocess
    root = root or os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    plan = os.path.join(root, "build", "oi-plan")
    if not os.path.exists(plan):
        print("(build/oi-plan missing: make all)")
        return
    rows = ["id,sun_x,sun_y,sun_z,moon_x,moon_y,moon_z,target_x,target_y,target_z,terms"]
    for h in (400.0, 800.0):
        r = 6378.137 + h
        for th in (100.0, 105.0, 108.0, 110.0, 111.0, 112.0, 114.0, 116.0, 120.0, 130.0, 180.0):
            t = math.radians(th)
            rows.append("%g/%g,1.496e8,0,0,-383230,0,30000,%.9g,%.9g,0,sun+earth+moon+sky" % (
                h, th, r * math.cos(t), r * math.sin(t)))
    out = subprocess.run([plan, "--csv", "-"], input="\n".join(rows) + "\n", text=True,
                         capture_output=True, check=False).stdout.splitlines()
    head = out[0].split(",")
    col = {k: head.index(k) for k in ("id", "e_sun", "e_earth", "e_moon", "e_sky")}
    print("h_km/theta_deg   e_sun(refracted)  e_earth    e_moon     e_sky     e_sky/e_moon")
    for line in out[1:]:
        f = line.split(",")
        es, ee, em, ek = (float(f[col[k]]) for k in ("e_sun", "e_earth", "e_moon", "e_sky"))
        print("%-15s %10.3e %10.3e %10.3e %10.3e %10.3g" % (f[col["id"]], es, ee, em, ek,
                                                         ek / em if em > 0 else float("nan")))


def run(n=4000, seed=3):
    med = Medium()
    ss = single.SingleScattering(med)
    rng = np.random.Generator(np.random.PCG64(seed))
    print("lines through the limb ring: L_line / (E_sky / Omega_ring)")
    print("h_obs_km theta_deg  median  p10    p90   within_x3")
    for h, th_deg in CASES:
        r = med.R + h
        th = math.radians(th_deg)
        e, _ = ss.irradiance(th, r)
        a_top = math.asin(med.r_top / r)
        a_fl = math.asin(med.r_floor / r)
        # the runtime's estimate: e_sky / Omega over the limb ring, applied to lines
        # through the ring (between the floor's horizon and the top's)
        omega = 2 * math.pi * (math.cos(a_fl) - math.cos(a_top))
        cos_nu = math.cos(a_fl) - rng.random(n) * (math.cos(a_fl) - math.cos(a_top))
        nu = np.arccos(cos_nu)
        az = math.pi * rng.random(n)
        L = ss.radiance(th, r, nu, az)

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
    umbra_sweep()
    run()
