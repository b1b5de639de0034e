# SPDX-License-Identifier: MIT
"""Prints the total band's shadow levels against the SOLAARS fit (docs/atmosphere.md).

Along beta = 0 circular passes at 490 km, GPS (20,200 km) and GEO (35,786 km):
the height of the straight Sun-centre line above the equatorial radius where
the fraction of unobstructed sunlight first reaches 10 %, 50 % and 90 %
coming out of the umbra, for

  * the SOLAARS fit (Robertson 2015; bake/atmosphere/solaars.py, the
    published coefficients evaluated by our own code);
  * the runtime (the Python binding, oi_sun_fraction's fraction_atm), both
    bands and both disc models;
  * the ray reference (bake/atmosphere/rays.py) of the total band with one
    piece of physics switched at a time (clouds, aerosol, refraction, limb
    darkening, the spectrum), which measures what each moves.

    python tools/solaars_compare.py            # everything (~3 min)
    python tools/solaars_compare.py --quick    # the SOLAARS fit and the runtime only

Needs the binding (`make binding`).
"""
from __future__ import annotations

import argparse
import dataclasses
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

from bake.atmosphere import profile as ap  # noqa: E402
from bake.atmosphere import rays as ar  # noqa: E402
from bake.atmosphere import solaars  # noqa: E402
from bake.common.constants import AU_KM  # noqa: E402

PASSES = (("490 km", 490.0), ("GPS", 20200.0), ("GEO", 35786.0))


def runtime_fraction(band, disc):
    import orbillum
    model = {"band": band, "limb_darkening": disc}

    def f(z, rho):
        pts = np.stack([-np.asarray(z), np.asarray(rho), np.zeros_like(z)], axis=1)
        return orbillum.sun_fraction([AU_KM, 0.0, 0.0], pts, model=model)["fraction_atm"]
    return f


def reference_fraction(rays, law):
    def f(z, rho):
        return float(ar.fraction(rays, z, [rho], law=law, want_psi=False)[0][0])
    return f


def fmt(levels):
    return " / ".join("%+6.1f" % levels[k] if levels[k] is not None else "   -  "
                      for k in solaars.LEVELS)


def total_rays(**changes):
    prof = ap.us1976(band="total")
    if "t_sun_k" in changes:
        t = changes.pop("t_sun_k")
        lam, w = ap.band_weights("total", t)
        prof = dataclasses.replace(prof, **changes)
        rays = ar.make_rays(prof)
        # the same columns, another spectrum's weights
        tau = prof.species_weights(lam).T @ rays.columns
        rays.transmission = (w @ np.exp(-tau)) * ar.cloud_transmission(prof, rays.h0)
        return rays
    return ar.make_rays(dataclasses.replace(prof, **changes))


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true", help="the fit and the runtime only")
    a = p.parse_args(argv)

    print("# Heights (km) of the Sun-centre line above the equatorial radius (6378.137 km)")
    print("# where the fraction reaches 10 / 50 / 90 %, beta = 0 passes, Sun at 1 AU")
    print("| model | " + " | ".join(n for n, _ in PASSES) + " |")
    print("|---|" + "---|" * len(PASSES))
    rows = [("SOLAARS fit (Robertson 2015)", solaars.solaars_fraction)]
    for band in ("total", "V"):
        for disc in ("uniform", "darkened"):
            rows.append(("runtime, %s band, %s disc" % (band, "uniform" if disc == "uniform"
                                                          else "limb-darkened"),
                         runtime_fraction(band, disc)))
    for name, fn in rows:
        print("| %s | %s |" % (name, " | ".join(fmt(solaars.pass_levels(fn, h)) for _, h in PASSES)))
    if a.quick:
        return 0

    # the ray reference, total band, one switch at a time (limb-darkened disc:
    # the table's own; the uniform disc as a switch)
    cases = [
        ("reference: default (clouds 0.68 below 10 km, Eddington disc)", {}, ar.EDDINGTON),
        ("  uniform disc", {}, ar.UNIFORM),
        ("  Neckel & Labs 559.95 nm disc", {}, ar.NL94_559),
        ("  clear sky (cloud_fraction 0)", {"cloud_fraction": 0.0}, ar.EDDINGTON),
        ("  opaque deck (cloud_fraction 1)", {"cloud_fraction": 1.0}, ar.EDDINGTON),
        ("  no aerosol", {"aer_trop_tau": 0.0, "aer_strat_tau": 0.0}, ar.EDDINGTON),
        ("  5500 K black body", {"t_sun_k": 5500.0}, ar.EDDINGTON),
        ("  6000 K black body", {"t_sun_k": 6000.0}, ar.EDDINGTON),
        ("  V band (same disc)", "V", ar.EDDINGTON),
        ("  no refraction (straight rays, same extinction)", "straight", ar.EDDINGTON),
    ]
    for name, changes, law in cases:
        if changes == "V":
            rays = ar.make_rays(ap.us1976())
        elif changes == "straight":
            rays = total_rays()
            rays.alpha = np.zeros_like(rays.alpha)
        else:
            rays = total_rays(**changes)
        fn = reference_fraction(rays, law)
        cells = []
        for _, h in PASSES:
            lev = {k: solaars.bisect_level(fn, h, k) for k in solaars.LEVELS}
            cells.append(fmt(lev))
        print("| %s | %s |" % (name, " | ".join(cells)), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
