# SPDX-License-Identifier: MIT
"""The published comparison: the zenith twilight sky seen from the ground, through the
table's atmosphere and scattering (bake.skylight.medium), single scattering, clear sky.

    python -m bake.skylight.twilight          (docs/skylight.md, "Against measurements")

The table's own geometry (a target above 100 km) has no published counterpart that
gives numbers here, but its ingredients (the same densities, cross-sections, phase
functions, aerosol loads, band and Sun transmission columns) also give the zenith
radiance of the twilight sky at a ground observer, which has: the slope of the V-band
twilight brightness against time after sunset measured with the INT Wide Field Camera
on La Palma (ING, "Twilight sky brightness", M. Karami, J. Mendez, C. Benn, 2010-2011
data: log10 B = A - 0.103 T, T in minutes after sunset, 10 < T < 35, the same slope in
U, B, V, r, i, Z).

The observer: La Palma (2,336 m, latitude 28.76 deg N), the clear-sky profile (the
refraction table's, without its cloud deck: the solid Earth is the floor). The zenith
line of sight keeps the Sun's zenith distance Z at every point on it, so

    L = sum_g w_g int [beta_R P_R(Z) + beta_a P_HG(Z)] / (4 pi) exp(-tau_up - tau_sun) dz,

tau_up the vertical optical depth from the observer, tau_sun from the point towards the
Sun (0 light in the solid Earth's geometric shadow). The printed surface brightness uses
the Sun's V = -26.74 (the runtime's OI_SUN_MAG_V). T after sunset is mapped to the
Sun's depression by the spherical-astronomy rate at the site for the Sun's declination
(printed for the equinox and both solstices; sunset: the upper limb at the horizon with
the standard 34' refraction, Z = 90.833 deg).
"""
from __future__ import annotations

import math

import numpy as np

from ..atmosphere import profile as ap
from .medium import Medium, hg_phase, rayleigh_phase
from .single import SunColumns

SITE_KM = 2.336
SITE_LAT_DEG = 28.76
SUN_MAG_V = -26.74
ARCSEC2_SR = (math.pi / 180 / 3600) ** 2
ING_SLOPE_DEX_PER_MIN = 0.103      # published, 10 < T < 35 min
N_Z = 4000


def zenith_radiance(med, sun, zd_rad, h_obs=SITE_KM):
    """Band radiance per unit solar irradiance (sr^-1) at the zenith."""
    z = np.linspace(h_obs, med.profile.top_km, N_Z + 1)
    zm = 0.5 * (z[1:] + z[:-1])
    dz = (z[1] - z[0]) * 1e3
    n = med.species(zm)                                           # (4, N)
    ext = med.ext_w.T @ n                                         # (G, N)
    tau_up = (np.cumsum(ext, axis=1) - 0.5 * ext) * dz
    rho = med.R + zm
    mu = np.full(rho.size, math.cos(zd_rad))
    mu_g = -np.sqrt(np.maximum(0.0, 1.0 - (med.r_floor / rho) ** 2))
    lit = mu > mu_g
    tr = np.zeros_like(ext)
    if np.any(lit):
        tr[:, lit] = sun.transmission(rho[lit], mu[lit])
    c = math.cos(zd_rad)
    sca = (med.sca_w[0][:, None] * n[0][None] * rayleigh_phase(c) +
           (med.sca_w[2][:, None] * n[2][None] + med.sca_w[3][:, None] * n[3][None]) *
           hg_phase(c))
    return float(med.weight @ np.sum(sca * np.exp(-tau_up) * tr, axis=1) * dz / (4 * math.pi))


def depression_rate_deg_per_min(depression_deg, dec_deg, lat_deg=SITE_LAT_DEG):
    """d(depression)/dt of the Sun (deg/min) at the given depression below the horizon."""
    lat, dec = math.radians(lat_deg), math.radians(dec_deg)
    alt = -math.radians(depression_deg)
    cos_h = (math.sin(alt) - math.sin(lat) * math.sin(dec)) / (math.cos(lat) * math.cos(dec))
    sin_h = math.sqrt(max(0.0, 1.0 - cos_h * cos_h))
    # d(alt)/dH = -cos(lat) cos(dec) sin(H) / cos(alt); H at 0.25 deg/min
    return 0.25 * math.cos(lat) * math.cos(dec) * sin_h / math.cos(alt)


def minutes_after_sunset(depression_deg, dec_deg, sunset_dep=0.833):
    """T (min) at which the Sun reaches the depression (integrated rate)."""
    d = np.linspace(sunset_dep, depression_deg, 400)
    rate = np.array([depression_rate_deg_per_min(x, dec_deg) for x in d])
    return float(np.trapezoid(1.0 / rate, d))


def run():
    prof = ap.us1976(cloud_top_km=0.0)
    med = Medium(prof)
    med.h_floor, med.r_floor = 0.0, med.R              # clear sky: the ground is the floor
    sun = SunColumns(med)
    print("zenith twilight sky at La Palma (clear sky, single scattering), V band")
    print("depression_deg  L(sr^-1)    mag/arcsec^2   T_min(equinox, dec +-23.44)")
    deps = np.arange(2.0, 12.01, 1.0)
    mags = []
    for dep in deps:
        L = zenith_radiance(med, sun, math.radians(90.0 + dep))
        mag = SUN_MAG_V - 2.5 * math.log10(L * ARCSEC2_SR) if L > 0 else float("inf")
        mags.append(mag)
        ts = [minutes_after_sunset(dep, d) for d in (0.0, 23.44, -23.44)]
        print("%8.1f      %10.4g  %8.2f      %5.1f %5.1f %5.1f" % (dep, L, mag, *ts))
    print("slope over T = 10..35 min after sunset (dex of radiance per minute):")
    for dec in (0.0, 23.44, -23.44):
        t = np.array([minutes_after_sunset(d, dec) for d in deps])
        logl = -0.4 * np.array(mags)
        sel = (t >= 10) & (t <= 35)
        k = np.polyfit(t[sel], logl[sel], 1)[0] if np.sum(sel) >= 2 else float("nan")
        # fine: interpolate log L at T = 10 and 35
        l10, l35 = np.interp([10.0, 35.0], t, logl)
        m20 = float(np.interp(20.0, t, mags))
        print("  dec %+6.2f: model %.4f (fit %.4f) vs measured %.3f (INT WFC, La Palma);"
              " V(T = 20) %.2f; fall T = 10..35: model %.2f mag, measured %.2f mag" % (
                  dec, (l10 - l35) / 25.0, -k, ING_SLOPE_DEX_PER_MIN, m20,
                  2.5 * (l10 - l35), 2.5 * 25 * ING_SLOPE_DEX_PER_MIN))


if __name__ == "__main__":
    run()
