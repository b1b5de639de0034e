# SPDX-License-Identifier: MIT
"""Eclipse observables of the default atmosphere, against published ones.

The numbers of docs/atmosphere.md's table "Eclipse observables", computed from
the ray reference (bake/atmosphere/rays.py, `fraction`; limb-darkened disc,
V band, Sun at 1 AU) with the default profile (bake/atmosphere/profile.py):

* local brightness across the umbra at the Moon's mean distance, in
  magnitudes below unobstructed sunlight (-2.5 log10 F);
* disc-averaged brightness of the totally eclipsed Moon at greatest eclipse
  of measured eclipses, the Moon's centre gamma equatorial Earth radii from
  the shadow's axis (gamma and the time of greatest eclipse from Espenak &
  Meeus 2009, NASA TP-2009-214172), with the Moon and the Sun at their
  distances of that instant (erfa.moon98, Simon et al. 1994; erfa.epv00),
  in magnitudes below the uneclipsed Moon, beside the published measurement
  (a V magnitude converted with the uneclipsed full Moon's V = -12.74 at
  384,400 km and 1 AU, Allen's Astrophysical Quantities, scaled to the
  Moon's and the Sun's distances; a magnitude already reduced to the mean
  distances, as Hernitschek et al. 2008 give theirs, against -12.74 itself);
  and the same with the stratospheric aerosol of a cited record
  (CITED_STRAT: Friberg et al. 2018) instead of the default's;
* the umbra's enlargement at the Moon: the radius of the steepest gradient
  of log F (the eye's edge) and of F, minus the geometric umbra's radius;
* the total bending of a ray grazing the surface;
* the shadow-entry height of a LEO satellite: the tangent height of the line
  to the Sun's centre where F = 0.5 and 0.1, at z = 2400 km.

    python -m bake.atmosphere.eclipse                # prints the table (seconds)
    python -m bake.atmosphere.eclipse --sensitivity  # each piece of the air switched
    python -m bake.atmosphere.eclipse --flight       # what the cited stratosphere moves in
                                                     # flight: shadow levels, entry heights (~1 min)
"""
from __future__ import annotations

import numpy as np

from ..common.quadrature import gauss_legendre
from . import profile as ap
from . import rays as ar

R_KM = ap.R_EARTH_KM
MOON_RADIUS_KM = 1737.4
Z_MOON_KM = 384400.0
MOON_FULL_V = -12.74        # uneclipsed full Moon at 384,400 km and 1 AU (Allen's Astrophysical Quantities)
# Stratospheric aerosol of a cited record: the whole stratosphere's optical
# depth from the tropopause (1.5 PVU) up, 0.008 at 532 nm averaged over
# 2006-2015, ~40 % of it from volcanic eruptions (Friberg et al. 2018, Atmos.
# Chem. Phys. 18, 11149, CALIOP); 0.0076 at 550 nm with the profile's Angstrom
# exponent 1.5. Applied to every eclipse (a decade's mean, not each date's).
CITED_STRAT_TAU = round(0.008 * (550.0 / 532.0) ** -1.5, 4)
CITED_STRAT = dict(aer_strat_tau=CITED_STRAT_TAU)
# The same for each eclipse's month where a global record covers it: NASA
# GISS's global stratospheric optical depth at 550 nm (Sato, Hansen, McCormick
# & Pollack 1993, J. Geophys. Res. 98, 22987, updated; monthly to 2012-09,
# data.giss.nasa.gov/modelforce/strataer). It counts the stratosphere above
# ~15 km where the satellites see it, not the lowermost stratosphere that
# Friberg et al. include, hence about half their decade's mean.
DATE_STRAT_TAU = {"1990-02-09": 0.007, "2007-03-03": 0.004, "2008-02-21": 0.004}
# greatest eclipse (UT: year, month, day, hours) and gamma (Espenak & Meeus
# 2009, NASA TP-2009-214172; eclipsewise.com), and the measured brightness of
# the whole Moon near greatest eclipse: ("V", low, high) V magnitudes as seen,
# ("V_mean_distances", m) a visual magnitude reduced to the mean distances of
# the Moon and the Sun, ("ratio", x) x times fainter than the full Moon, or
# None where none was found; the sources are in docs/atmosphere.md, "Eclipse
# observables".
ECLIPSES = (
    # minimum of the light curve, calibrated photometers, reduced to unit air mass
    # and to standard distances (Hernitschek, Schmidt & Vollmer 2008, Appl. Opt. 47, H62)
    ("1990-02-09", (1990, 2, 9, 19 + 11 / 60), -0.4148, ("V_mean_distances", -3.32)),
    ("2007-03-03", (2007, 3, 3, 23 + 21 / 60), 0.3175, ("V_mean_distances", -1.7)),
    # REA mean -2.8 +- 0.3 (H. C. Vital); reversed binoculars -3.4 (R. Sinnott)
    # and -3.2 (J. Bortle), Sky & Telescope's report of 2008-02-21
    ("2008-02-21", (2008, 2, 21, 3 + 26 / 60), -0.3992, ("V", -3.4, -2.5)),
    # "~50,000 times fainter than the full Moon" at mid-totality (Vital, REA)
    ("2015-09-28", (2015, 9, 28, 2 + 47 / 60), -0.3296, ("ratio", 5e4)),
    # SSP-3 photometer, V = -2.04 at 05:13:30 UT (Schmude 2022, Georgia J. Sci. 80(1), 32)
    ("2019-01-21", (2019, 1, 21, 5 + 12 / 60), 0.3684, ("V", -2.04, -2.04)),
    ("2022-05-16", (2022, 5, 16, 4 + 11 / 60), -0.2532, None),
)


def distances(ut):
    """Geocentric Moon distance (km) and heliocentric Earth distance (km) at
    ut = (year, month, day, hours UT) from ERFA's analytic ephemerides
    (moon98: Simon et al. 1994; epv00); UT for TT (< 2 min: < 20 km)."""
    import erfa
    y, m, d, h = ut
    jd1, jd2 = erfa.cal2jd(y, m, d)
    jd2 = jd2 + h / 24.0
    pv = erfa.moon98(jd1, jd2)
    ph, _ = erfa.epv00(jd1, jd2)
    return (float(np.linalg.norm(pv[0])) * ar.AU_KM,
            float(np.linalg.norm(ph[0])) * ar.AU_KM)


def published_mag_below_full(measured, moon_km, sun_km=ar.AU_KM):
    """(low, high) published magnitudes below the uneclipsed Moon, or None."""
    if measured is None:
        return None
    kind, values = measured[0], measured[1:]
    if kind == "ratio":
        m = 2.5 * np.log10(values[0])
        return (m, m)
    if kind == "V_mean_distances":
        return (values[0] - MOON_FULL_V,) * 2
    if kind != "V":
        raise ValueError("unknown kind of measurement %r" % (kind,))
    v_full = MOON_FULL_V + 5.0 * np.log10(moon_km / Z_MOON_KM) + 5.0 * np.log10(sun_km / ar.AU_KM)
    return tuple(sorted(v - v_full for v in values))


def local_magnitudes(rays, rho_km, z=Z_MOON_KM):
    F, _ = ar.fraction(rays, z, np.asarray(rho_km, dtype=float), want_psi=False, n_mu=24)
    return -2.5 * np.log10(np.maximum(F, 1e-30))


def disc_fraction(rays, rho_c, z=Z_MOON_KM, n=12, d_sun=ar.AU_KM):
    """Mean F over the lunar disc centred rho_c km from the axis (area mean,
    Gauss-Legendre in radius and angle; the Moon's albedo taken uniform and
    its phase law the same as the uneclipsed full Moon's)."""
    x, w = gauss_legendre(n)
    r = 0.5 * MOON_RADIUS_KM * (x + 1.0)
    wr = 0.5 * MOON_RADIUS_KM * w * r
    t = np.pi * (x + 1.0)
    wt = np.pi * w
    pts = np.hypot(rho_c + r[:, None] * np.cos(t)[None, :], r[:, None] * np.sin(t)[None, :])
    F, _ = ar.fraction(rays, z, pts.ravel(), d_sun=d_sun, want_psi=False, n_mu=16)
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


def disc_magnitudes(rays):
    """Per measured eclipse: (name, gamma, Moon km, Sun km, ours at those
    distances, ours at the mean distances, published (low, high) or None)."""
    rows = []
    for name, ut, g, measured in ECLIPSES:
        zm, ds = distances(ut)
        ours = -2.5 * np.log10(disc_fraction(rays, abs(g) * R_KM, z=zm, d_sun=ds))
        mean = -2.5 * np.log10(disc_fraction(rays, abs(g) * R_KM))
        rows.append((name, g, zm, ds, float(ours), float(mean),
                     published_mag_below_full(measured, zm, ds)))
    return rows


# each piece of the default air switched alone (docs/atmosphere.md, "Eclipse observables")
SENSITIVITY = (
    ("default", {}),
    ("no stratospheric aerosol", dict(aer_strat_tau=0.0)),
    ("stratospheric aerosol tau %g (Friberg et al. 2018)" % CITED_STRAT_TAU, CITED_STRAT),
    ("stratospheric aerosol tau 0.01", dict(aer_strat_tau=0.01)),
    ("stratospheric aerosol tau 0.02", dict(aer_strat_tau=0.02)),
    ("the stratospheric aerosol centred at 15 km", dict(aer_strat_peak_km=15.0)),
    ("the same with tau %g" % CITED_STRAT_TAU, dict(aer_strat_peak_km=15.0, **CITED_STRAT)),
    ("the stratospheric aerosol's 1-sigma 6 km (not 4)", dict(aer_strat_sigma_km=6.0)),
    ("no ozone", dict(ozone_du=0.0)),
    ("ozone 350 DU", dict(ozone_du=350.0)),
    ("no boundary-layer aerosol", dict(aer_trop_tau=0.0)),
    ("cloud top 12 km", dict(cloud_top_km=12.0)),
    ("cloud top 14 km", dict(cloud_top_km=14.0)),
    ("opaque clouds (fraction 1)", dict(cloud_fraction=1.0)),
    ("no clouds (fraction 0)", dict(cloud_fraction=0.0)),
)


def sensitivity(dh_km=0.02):
    """Disc magnitudes (at the eclipses' distances) with each piece switched."""
    import dataclasses
    out = []
    for label, kw in SENSITIVITY:
        rays = ar.make_rays(dataclasses.replace(ap.us1976(), **kw), dh_km=dh_km)
        out.append((label, [r[4] for r in disc_magnitudes(rays)]))
    return out


def observables(profile=None, dh_km=0.02):
    import dataclasses
    profile = profile or ap.us1976()
    rays = ar.make_rays(profile, dh_km=dh_km)
    out = {}
    out["local_rho_km"] = [0.0, 1000.0, 2000.0, 3000.0, 4000.0]
    out["local_mag"] = [float(v) for v in local_magnitudes(rays, out["local_rho_km"])]
    out["eclipses"] = disc_magnitudes(rays)
    e_log, umbra = enlargement_km(rays)
    out["enlargement_km"] = (float(e_log), float(umbra))
    _, a0, _ = ar.trace(profile, [0.0])
    out["grazing_bending_deg"] = float(np.degrees(a0[0]))
    out["shadow_entry_km"] = shadow_entry_km(rays)
    cited = ar.make_rays(dataclasses.replace(profile, **CITED_STRAT), dh_km=dh_km)
    out["eclipses_cited_strat"] = disc_magnitudes(cited)
    out["eclipses_date_strat"] = {}
    for tau in sorted(set(DATE_STRAT_TAU.values())):
        rows = disc_magnitudes(ar.make_rays(dataclasses.replace(profile, aer_strat_tau=tau),
                                            dh_km=dh_km))
        for r in rows:
            if DATE_STRAT_TAU.get(r[0]) == tau:
                out["eclipses_date_strat"][r[0]] = r
    return out


PASSES = (("490 km", 490.0), ("GPS", 20200.0), ("GEO", 35786.0))


def flight_levels(changes, band):
    """The ray reference's shadow levels along beta = 0 passes (bake/atmosphere/
    solaars.py's definition, docs/atmosphere.md "The SOLAARS comparison": the
    Sun-centre line's height above the equatorial radius where F reaches 10 /
    50 / 90 %) for the default profile with `changes`, in `band` with the disc of
    that band's table (total: Eddington; V: Neckel & Labs 559.95 nm); and, in V,
    the LEO entry heights of shadow_entry_km."""
    import dataclasses
    from . import solaars
    prof = dataclasses.replace(ap.us1976(band=band), **changes)
    rays = ar.make_rays(prof)
    law = ar.EDDINGTON if band == "total" else ar.NL94_559

    def f(z, rho):
        return float(ar.fraction(rays, z, [rho], law=law, want_psi=False)[0][0])
    levels = [[solaars.bisect_level(f, h, lv) for lv in solaars.LEVELS] for _, h in PASSES]
    return levels, (shadow_entry_km(rays) if band == "V" else None)


def print_flight():
    print("ray reference, heights (km) where F = 10 / 50 / 90 %% along beta = 0 passes: default"
          " (stratospheric aerosol tau %g) and cited stratosphere (tau %g)"
          % (ap.us1976().aer_strat_tau, CITED_STRAT_TAU))
    for band in ("total", "V"):
        for label, changes in (("default", {}), ("cited", CITED_STRAT)):
            levels, entry = flight_levels(changes, band)
            cells = " | ".join("%s %s" % (name, " / ".join("%+.1f" % v for v in lv))
                               for (name, _), lv in zip(PASSES, levels))
            tail = "; LEO entry F = 0.5 / 0.1 at %.2f / %.2f km" % tuple(entry) if entry else ""
            print("  %-5s %-7s %s%s" % (band, label, cells, tail), flush=True)


def main(argv=None):
    import argparse
    import dataclasses
    ap_ = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap_.add_argument("--cloud-fraction", type=float, default=ap.CLOUD_FRACTION)
    ap_.add_argument("--cloud-top-km", type=float, default=ap.CLOUD_TOP_KM)
    ap_.add_argument("--sensitivity", action="store_true",
                     help="disc magnitudes with each piece of the default air switched")
    ap_.add_argument("--flight", action="store_true",
                     help="shadow levels and entry heights, default and cited stratosphere")
    args = ap_.parse_args(argv)
    if args.flight:
        print_flight()
        return
    if args.sensitivity:
        names = [e[0] for e in ECLIPSES]
        print("disc-averaged, mag below the uneclipsed Moon, at each eclipse's distances")
        print("%-56s %s" % ("", " ".join("%10s" % n for n in names)))
        for label, ms in sensitivity():
            print("%-56s %s" % (label, " ".join("%10.2f" % m for m in ms)))
        return
    prof = dataclasses.replace(ap.us1976(), cloud_fraction=args.cloud_fraction,
                               cloud_top_km=args.cloud_top_km)
    print("clouds below %g km stop %g of the rays; cited stratosphere: aerosol tau %g at 550 nm"
          % (prof.cloud_top_km, prof.cloud_fraction, CITED_STRAT_TAU))
    o = observables(prof)
    print("local brightness at %.0f km behind the Earth, mag below sunlight:" % Z_MOON_KM)
    for r, m in zip(o["local_rho_km"], o["local_mag"]):
        print("  rho %6.0f km: %.2f" % (r, m))
    print("disc-averaged, mag below the uneclipsed Moon at greatest eclipse: ours (at the"
          " eclipse's distances; at the mean ones), published, ours - published:")
    for row, cited in zip(o["eclipses"], o["eclipses_cited_strat"]):
        name, g, zm, ds, m, m_mean, pub = row
        if pub is None:
            tail = "published: none found"
        else:
            lo, hi = pub
            mid = 0.5 * (lo + hi)
            span = "%.2f" % lo if hi - lo < 0.005 else "%.2f-%.2f" % (lo, hi)
            tail = "published %s, difference %+.2f (cited stratosphere %+.2f)" % (
                span, m - mid, cited[4] - mid)
        dated = o["eclipses_date_strat"].get(name)
        if dated is not None:
            tail += "; with the month's stratosphere (tau %g) %.2f, difference %+.2f" % (
                DATE_STRAT_TAU[name], dated[4], dated[4] - mid)
        print("  %s (gamma %+.4f, Moon %.0f km, Sun %.4f AU): %.2f (%.2f; cited stratosphere"
              " %.2f); %s" % (name, g, zm, ds / ar.AU_KM, m, m_mean, cited[4], tail))
    diffs = [(r[4] - 0.5 * sum(r[6]), c[4] - 0.5 * sum(c[6]))
             for r, c in zip(o["eclipses"], o["eclipses_cited_strat"]) if r[6] is not None]
    d, dc = np.array(diffs).T
    print("  ours - published over the %d measured: mean %+.2f, rms about the mean %.2f"
          " (cited stratosphere: %+.2f, %.2f)" % (len(d), d.mean(), d.std(), dc.mean(), dc.std()))
    e_log, umbra = o["enlargement_km"]
    print("umbra enlargement (steepest log F): %+.0f km, %.2f %% of the geometric %.0f km"
          % (e_log, 100 * e_log / umbra, umbra))
    print("grazing bending %.3f deg" % o["grazing_bending_deg"])
    print("LEO shadow entry (z = 2400 km), F = 0.5 / 0.1 at %.0f / %.0f km" % tuple(o["shadow_entry_km"]))


if __name__ == "__main__":
    main()
