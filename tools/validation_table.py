#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""validation_table.py: limiting magnitudes of the built-in cameras against
published on-orbit figures (docs/camera.md, "Validation").

For each camera, exposure time, sky and sensor temperature: the faintest V
(a solar-coloured point source, centred on a pixel) that is detected, by
bisection in log flux on the runtime (orbillum.expose_flux on a copy of the
built-in camera with that one exposure time and its lowest gain), under
three rules:
  - "SNR 5": the runtime's default rule, SNR 5 in the brightest pixel;
  - "threshold": the runtime's threshold rule, a false-alarm rate of 1e-6
    per pixel met with probability 0.9 (docs/camera.md, "Detection");
  - "matched filter": not in the runtime, computed here from the runtime's
    electrons: SNR 5 of the PSF-weighted sum over 9 x 9 pixels,
    SNR^2 = sum_i (S p_i)^2 / (S p_i + B + R^2), p_i the pixel fractions of
    the Gaussian with the camera's centred peak fraction (the runtime's
    own PSF model, src/camera/trail.c), S the whole PSF's electrons
    (signal_e / psf_peak_fraction), B the background electrons per pixel,
    R the read noise: what a detection that uses the whole PSF reaches.
Prints the Markdown tables docs/camera.md quotes (the second: the star
tracker's limit for a goal snr_min of 5, 20 and 50; the third: the
integrated starlight by galactic latitude); tests/python/
test_validation_table.py checks that the document holds this output.
Usage: .venv/bin/python tools/validation_table.py
"""
import ctypes
import math

import orbillum

L = orbillum.L
LIB = orbillum._lib

PUBLISHED = {
    "telescope-15cm": "19.5-20 (NEOSSat, 100 s)",
    "star-tracker": "4.9-7 (class ratings, 0.1-0.5 s)",
}


def camera_at(name, t, p_fa=0.0, p_d=0.0):
    src = LIB.oi_camera_find(name.encode())
    c = L.oi_camera()
    ctypes.memmove(ctypes.addressof(c), ctypes.addressof(src.contents), ctypes.sizeof(c))
    c.n_times = 1
    c.times_s[0] = t
    c.n_gains = 1
    c.detect_false_alarm = p_fa
    c.detect_probability = p_d
    return c


def mag_of(flux):
    return L.OI_SUN_MAG_V - 2.5 * math.log10(flux / L.OI_TSI_W_M2)


def gaussian_pixels(peak, half=4):
    """Pixel fractions of a centred Gaussian whose centre pixel holds `peak`."""
    lo, hi = 0.05, 20.0  # sigma by bisection: the centre fraction falls with sigma
    for _ in range(200):
        s = 0.5 * (lo + hi)
        if math.erf(1.0 / (2.0 * math.sqrt(2.0) * s)) ** 2 > peak:
            lo = s
        else:
            hi = s
    s = 0.5 * (lo + hi)

    def axis(k):
        return 0.5 * (math.erf((k + 0.5) / (math.sqrt(2.0) * s)) -
                      math.erf((k - 0.5) / (math.sqrt(2.0) * s)))
    return [axis(i) * axis(j) for i in range(-half, half + 1) for j in range(-half, half + 1)]


def detected(rule, cam, flux, bg, temp, pixels):
    r = orbillum.expose_flux(cam, [flux], bg, sensor_temp_c=temp)
    assert r["expose_status"][0] == 0, r["expose_status_name"][0]
    if rule == "snr":
        return r["snr"][0] >= 5.0
    if rule == "threshold":
        return r["detect_margin_mag"][0] >= 0.0
    total = r["signal_e"][0] / cam.psf_peak_fraction
    b = r["background_e"][0] + cam.read_noise_e[0] ** 2
    snr2 = sum((total * p) ** 2 / (total * p + b) for p in pixels)
    return math.sqrt(snr2) >= 5.0


def limit(rule, name, t, bg, temp):
    cam = camera_at(name, t, *((1e-6, 0.9) if rule == "threshold" else (0.0, 0.0)))
    pixels = gaussian_pixels(cam.psf_peak_fraction)
    lo, hi = math.log(1e-30), math.log(1e-3)
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if detected(rule, cam, math.exp(mid), bg, temp, pixels):
            hi = mid
        else:
            lo = mid
    return mag_of(math.exp(hi))


EPS = 84381.406 / 3600.0 * math.pi / 180.0  # IAU 2006 obliquity of J2000, as the runtime's


def galactic_of(v):
    """Galactic (l, b) of an ICRS direction, by the runtime (src/camera/galactic.c)."""
    l, b = L.real(), L.real()
    assert LIB.oi_galactic_from_icrs((L.real * 3)(*v), ctypes.byref(l), ctypes.byref(b)) == 0
    return l.value, b.value


def ecliptic_latitude(v):
    return math.asin(-math.sin(EPS) * v[1] + math.cos(EPS) * v[2])


def sky_at(v, elongation_lon):
    """Zodiacal light plus starlight towards ICRS direction v, the Sun at
    `elongation_lon` of ecliptic longitude from it: (total, starlight alone)."""
    l, b = galactic_of(v)
    beta = ecliptic_latitude(v)
    zodi = LIB.oi_zodiacal_radiance(elongation_lon, beta)
    star = LIB.oi_starlight_radiance(l, b)
    return zodi + star, star


def rows():
    zodi_pole = LIB.oi_zodiacal_radiance(1.0, math.pi / 2)
    zodi_90 = LIB.oi_zodiacal_radiance(math.pi / 2, 0.0)
    nep = (0.0, -math.sin(EPS), math.cos(EPS))  # north ecliptic pole, ICRS
    # the north galactic pole and the galactic centre (l = 0, b = 0) in ICRS,
    # from the Hipparcos definition (pole RA 192.85948, Dec 27.12825 deg;
    # node, at RA of the pole + 90 deg, at l = 32.93192 deg)
    ag, dg, lo = math.radians(192.85948), math.radians(27.12825), math.radians(32.93192)
    ngp = (math.cos(dg) * math.cos(ag), math.cos(dg) * math.sin(ag), math.sin(dg))
    node = (math.cos(ag + math.pi / 2), math.sin(ag + math.pi / 2), 0.0)
    m = (ngp[1] * node[2] - ngp[2] * node[1], ngp[2] * node[0] - ngp[0] * node[2],
         ngp[0] * node[1] - ngp[1] * node[0])
    gc = tuple(node[i] * math.cos(lo) - m[i] * math.sin(lo) for i in range(3))
    sl_pole, _ = sky_at(nep, 1.0)
    sl_ngp, _ = sky_at(ngp, math.pi / 2)
    sl_gc, _ = sky_at(gc, math.pi / 2)
    cases = [
        ("telescope-15cm", 100.0, "black", 0.0, None),
        ("telescope-15cm", 100.0, "zodiacal, ecliptic pole", zodi_pole, None),
        ("telescope-15cm", 100.0, "zodiacal, ecliptic 90 deg from the Sun", zodi_90, None),
        ("telescope-15cm", 100.0, "zodiacal + starlight, ecliptic pole", sl_pole, None),
        ("telescope-15cm", 100.0, "zodiacal + starlight, galactic pole, 90 deg from the Sun",
         sl_ngp, None),
        ("telescope-15cm", 100.0, "zodiacal + starlight, galactic centre, 90 deg from the Sun",
         sl_gc, None),
        ("star-tracker", 0.1, "black", 0.0, None),
        ("star-tracker", 0.1, "zodiacal, ecliptic 90 deg from the Sun", zodi_90, None),
        ("star-tracker", 0.1, "black", 0.0, 45.0),
        ("star-tracker", 0.5, "black", 0.0, None),
        ("star-tracker", 0.5, "zodiacal, ecliptic 90 deg from the Sun", zodi_90, None),
        ("star-tracker", 0.5, "zodiacal + starlight, galactic centre, 90 deg from the Sun",
         sl_gc, None),
        ("star-tracker", 0.5, "black", 0.0, 45.0),
    ]
    out = []
    for name, t, sky, bg, temp in cases:
        cam = LIB.oi_camera_find(name.encode()).contents
        temp_txt = f"{temp:g} C" if temp is not None else f"{cam.dark_ref_temp_c:g} C (reference)"
        out.append((name, t, sky, temp_txt, limit("snr", name, t, bg, temp),
                    limit("threshold", name, t, bg, temp), limit("mf", name, t, bg, temp),
                    PUBLISHED[name]))
    return out


def table():
    lines = ["| camera | time | sky | sensor | SNR 5, brightest pixel | threshold 1e-6, P_d 0.9 "
             "| matched filter, SNR 5 | published |",
             "|---|---|---|---|---|---|---|---|"]
    for name, t, sky, temp, snr, thr, mf, pub in rows():
        lines.append(f"| `{name}` | {t:g} s | {sky} | {temp} | {snr:.2f} | {thr:.2f} | {mf:.2f} "
                     f"| {pub} |")
    return "\n".join(lines)


def snr_goal_limit(name, t, snr_min):
    """The faintest V whose brightest pixel reaches snr_min (the goal's
    snr_min, black sky, the reference temperature)."""
    cam = camera_at(name, t)
    lo, hi = math.log(1e-30), math.log(1e-3)
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        r = orbillum.expose_flux(cam, [math.exp(mid)], 0.0, snr_min=snr_min)
        assert r["expose_status"][0] == 0
        if r["snr"][0] >= snr_min:
            hi = mid
        else:
            lo = mid
    return mag_of(math.exp(hi))


def goal_table():
    """The star tracker's limit for the SNR a tracker's centroid needs."""
    lines = ["| `star-tracker`, black sky | snr_min 5 | snr_min 20 | snr_min 50 |",
             "|---|---|---|---|"]
    for t in (0.1, 0.5):
        v = [snr_goal_limit("star-tracker", t, k) for k in (5.0, 20.0, 50.0)]
        lines.append(f"| {t:g} s | {v[0]:.2f} | {v[1]:.2f} | {v[2]:.2f} |")
    return "\n".join(lines)


S10_SUN_W_M2_SR = 8.9971174530390225e-09  # src/camera/starlight.c
ARCSEC2_SR = (math.pi / 180.0 / 3600.0) ** 2


def starlight_table():
    """The starlight of the runtime (Leinert et al. 1998, Table 35) by
    galactic latitude: mean, least and greatest over the 36 longitudes of
    the table, in S10_sun and as V mag/arcsec^2 of the mean."""
    lines = ["| galactic latitude | mean over longitude (S10_sun) | least - greatest "
             "| mean (W/m^2/sr, as sunlight) | mean (V mag/arcsec^2) |",
             "|---|---|---|---|---|"]
    for b in (-80, -50, -30, -12, 0, 12, 30, 50, 80, 90):
        v = [LIB.oi_starlight_radiance(math.radians(10.0 * j), math.radians(b))
             for j in range(36)]
        mean = sum(v) / len(v)
        mag = L.OI_SUN_MAG_V - 2.5 * math.log10(mean * ARCSEC2_SR / L.OI_TSI_W_M2)
        lines.append(f"| {b:+d} deg | {mean / S10_SUN_W_M2_SR:.1f} | "
                     f"{min(v) / S10_SUN_W_M2_SR:.0f} - {max(v) / S10_SUN_W_M2_SR:.0f} | "
                     f"{mean:.3g} | {mag:.2f} |")
    return "\n".join(lines)


if __name__ == "__main__":
    print(table())
    print()
    print(goal_table())
    print()
    print(starlight_table())
