# SPDX-License-Identifier: MIT
"""Limiting magnitudes of the built-in cameras with the zodiacal light
(docs/camera.md, "Sky background"): the V magnitude at which oi_expose's
chosen setting reaches SNR 5, on a black sky and on the zodiacal light of
Leinert et al. 1998 at the ecliptic pole and at 90 deg from the Sun in the
ecliptic. `pytest -s tests/python/test_sky_limits.py` prints the table that
docs/camera.md quotes.
"""
import math

import numpy as np

import orbillum

L = orbillum.L        # the mirror of the header (constants)
LIB = orbillum._lib   # the loaded runtime, prototypes set
DEG = math.pi / 180.0
ARCSEC2_SR = (DEG / 3600.0) ** 2


def mag_of(flux):
    return L.OI_SUN_MAG_V - 2.5 * math.log10(flux / L.OI_TSI_W_M2)


def limiting_mag(camera, background, snr=5.0):
    """The faintest V at which the chosen exposure reaches `snr`, by
    bisection in log flux on oi_expose itself (the SNR rises with flux)."""
    lo, hi = math.log(1e-30), math.log(1e-6)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        r = orbillum.expose_flux(camera, [math.exp(mid)], background)
        assert r["expose_status"][0] == 0
        if r["snr"][0] >= snr:
            hi = mid
        else:
            lo = mid
    r = orbillum.expose_flux(camera, [math.exp(hi)], background)
    return mag_of(math.exp(hi)), float(r["exposure_s"][0])


def test_zodiacal_surface_brightness():
    """The table's classic anchors in V mag/arcsec^2: the ecliptic pole 23.2,
    the Gegenschein 22.1 (the values usually quoted for them)."""
    pole = LIB.oi_zodiacal_radiance(1.0, math.pi / 2)
    gegen = LIB.oi_zodiacal_radiance(math.pi, 0.0)
    m_pole = mag_of(pole * ARCSEC2_SR)
    m_gegen = mag_of(gegen * ARCSEC2_SR)
    print(f"\nzodiacal light: pole {m_pole:.2f}, Gegenschein {m_gegen:.2f} V mag/arcsec^2")
    assert abs(m_pole - 23.24) < 0.01 and abs(m_gegen - 22.06) < 0.01


def test_limiting_magnitudes():
    rows = []
    skies = [("black", 0.0), ("ecliptic pole", LIB.oi_zodiacal_radiance(1.0, math.pi / 2)),
             ("ecliptic, 90 deg from the Sun", LIB.oi_zodiacal_radiance(math.pi / 2, 0.0))]
    for cam in ("telescope-15cm", "star-tracker"):
        for name, bg in skies:
            m, t = limiting_mag(cam, bg)
            rows.append((cam, name, m, t))
    print()
    for cam, name, m, t in rows:
        print(f"{cam:15s} {name:30s} V = {m:6.2f} at {t:g} s")
    tele = {name: m for cam, name, m, t in rows if cam == "telescope-15cm"}
    # the zodiacal light costs the telescope 0.5-1 mag; black sky 20.4
    assert abs(tele["black"] - 20.4) < 0.1
    assert 0.3 < tele["black"] - tele["ecliptic pole"] < 1.0
    assert tele["ecliptic pole"] > tele["ecliptic, 90 deg from the Sun"]
    for cam, name, m, t in rows:
        assert t == orbillum.expose_flux(cam, [1e-30])["exposure_s"][0]  # the longest time
    assert np.all(np.isfinite([m for _, _, m, _ in rows]))
