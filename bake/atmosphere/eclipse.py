# SPDX-License-Identifier: MIT
"""Eclipse observables of the default atmosphere, against published ones.

The numbers of docs/atmosphere.md's table "Eclipse observables", computed from
the ray reference (bake/atmosphere/rays.py, `fraction`; limb-darkened disc,
V band, Sun at 1 AU) with the default profile (bake/atmosphere/profile.py):

* local brightness across the umbra at the Moon's mean distance, in
  magnitudes below unobstructed sunlight (-2.5 log10 F);
* disc-averaged brightness of the totally eclipsed Moon at mid-totality of
  measured eclipses, the Moon's centre gamma equatorial Earth radii from
  the shadow's axis (gamma from Espenak & Meeus 2009, NASA TP-2009-214172),
  in magnitudes below the uneclipsed Moon;
* the umbra's enlargement at the Moon: the radius of the steepest gradient
  of log F (the eye's edge) and of F, minus the geometric umbra's radius;
* the total bending of a ray grazing the surface;
* the shadow-entry height of a LEO satellite: the tangent height of the line
  to the Sun's centre where F = 0.5 and 0.1, at z = 2400 km.

    python -m bake.atmosphere.eclipse      # prints the table (about a minute)
"""
from __future__ import annotations

import numpy as np

from ..common.quadrature import gauss_legendre
from . import profile as ap
from . import rays as ar

R_KM = ap.R_EARTH_KM
MOON_RADIUS_KM = 1737.4
Z_MOON_KM = 384400.0
# mid-totality geometry (gamma) of measured eclipses, Espenak & Meeus 2009
ECLIPSES = (("1990-02-09", -0.4148), ("2007-03-03", 0.3175), ("2015-09-28", -0.3296),
            ("2019-01-21", 0.3684))


def local_magnitudes(rays, rho_km, z=Z_MOON_KM):
    F, _ = ar.fraction(rays, z, np.asarray(rho_km, dtype=float), want_psi=False, n_mu=24)
    return -2.5 * np.log10(np.maximum(F, 1e-30))


def disc_fraction(rays, rho_c, z=Z_MOON_KM, n=12):
    """Mean F over the lunar disc centred rho_c km from the axis (area mean,
    Gauss-Legendre in radius and angle)."""
    x, w = gauss_legendre(n)
    r = 0.5 * MOON_RADIUS_KM * (x + 1.0)
    wr = 0.5 * MOON_RADIUS_KM * w * r
    t = np.pi * (x + 1.0)
    wt = np.pi * w
    pts = np.hypot(rho_c + r[:, None] * np.cos(t)[None, :], r[:, None] * np.sin(t)[None, :])
    F, _ = ar.fraction(rays, z, pts.ravel(), want_psi=False, n_mu=16)
    wts = (wr[:, None] * wt[None, :]).ravel()
    return float(np.sum(F * wts) / np.sum(wts))


def enlargement_km(rays, z=Z_MOON_KM):
    """Radius of the steepest d ln F / d rho in the outer umbra (F > 1e-4,
    within 900 km of the geometric edge) minus the geometric umbra's radius
    (km), and that radius."""
    a = z * ar.SUN_RADIUS_KM / ar.AU_KM
    rc = R_KM * (1 + z / ar.AU_KM)
    umbra = rc - a
    rho = np.linspace(umbra - 900.0, umbra + 900.0, 721)
    F, _ = ar.fraction(rays, z, rho, want_psi=False, n_mu=24)
    g_log = np.gradient(np.log(np.maximum(F, 1e-12)), rho)
    k_log = int(np.argmax(g_log * (F > 1e-4)))
    return rho[k_log] - umbra, umbra


def shadow_entry_km(rays, z=2400.0, levels=(0.5, 0.1)):
    rc = R_KM * (1 + z / ar.AU_KM)
    rho = rc + np.linspace(-60.0, 100.0, 641)
    F, _ = ar.fraction(rays, z, rho, want_psi=False, n_mu=24)
    return [float(rho[np.where(F >= lv)[0][0]] - rc) for lv in levels]


def observables(profile=None, dh_km=0.02):
    profile = profile or ap.us1976()
    rays = ar.make_rays(profile, dh_km=dh_km)
    out = {}
    out["local_rho_km"] = [0.0, 1000.0, 2000.0, 3000.0, 4000.0]
    out["local_mag"] = [float(v) for v in local_magnitudes(rays, out["local_rho_km"])]
    out["eclipses"] = [(name, g, -2.5 * np.log10(disc_fraction(rays, abs(g) * R_KM)))
                       for name, g in ECLIPSES]
    e_log, umbra = enlargement_km(rays)
    out["enlargement_km"] = (float(e_log), float(umbra))
    _, a0, _ = ar.trace(profile, [0.0])
    out["grazing_bending_deg"] = float(np.degrees(a0[0]))
    out["shadow_entry_km"] = shadow_entry_km(rays)
    return out


def main(argv=None):
    import argparse
    import dataclasses
    ap_ = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap_.add_argument("--cloud-fraction", type=float, default=ap.CLOUD_FRACTION)
    ap_.add_argument("--cloud-top-km", type=float, default=ap.CLOUD_TOP_KM)
    args = ap_.parse_args(argv)
    prof = dataclasses.replace(ap.us1976(), cloud_fraction=args.cloud_fraction,
                               cloud_top_km=args.cloud_top_km)
    print("clouds below %g km stop %g of the rays" % (prof.cloud_top_km, prof.cloud_fraction))
    o = observables(prof)
    print("local brightness at %.0f km behind the Earth, mag below sunlight:" % Z_MOON_KM)
    for r, m in zip(o["local_rho_km"], o["local_mag"]):
        print("  rho %6.0f km: %.2f" % (r, m))
    print("disc-averaged, mag below the uneclipsed Moon (Moon at %.0f km):" % Z_MOON_KM)
    for name, g, m in o["eclipses"]:
        print("  %s (gamma %+.4f): %.2f" % (name, g, m))
    e_log, umbra = o["enlargement_km"]
    print("umbra enlargement (steepest log F): %+.0f km, %.2f %% of the geometric %.0f km"
          % (e_log, 100 * e_log / umbra, umbra))
    print("grazing bending %.3f deg" % o["grazing_bending_deg"])
    print("LEO shadow entry (z = 2400 km), F = 0.5 / 0.1 at %.0f / %.0f km" % tuple(o["shadow_entry_km"]))


if __name__ == "__main__":
    main()
