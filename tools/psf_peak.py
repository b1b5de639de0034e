#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""psf_peak.py: the brightest-pixel fraction of a point source from the optics.

The PSF is the diffraction pattern of an unobstructed circular pupil of
diameter D at focal length f (the Airy pattern), averaged over the band
with the photon spectrum of the 5772 K Sun (flat QE), convolved with a
Gaussian of standard deviation sigma for defocus and pointing jitter
(stated per camera), and integrated over one square pixel of pitch p.
The fraction of the source's light in the pixel whose centre is at offset
(x0, y0) pixels from the source is

    P(x0, y0) = integral over the frequency plane of
                OTF(rho) G(rho) sinc(fx) sinc(fy) cos(2 pi (fx x0 + fy y0))

(f in cycles per pixel): the transform of the PSF times that of the
pixel (sinc(u) = sin(pi u) / (pi u)), at the offset. The diffraction OTF of
the pupil is (2/pi)(acos v - v sqrt(1 - v^2)), v = rho / rho_c,
rho_c = p / (lambda f / D) (J. W. Goodman, Introduction to Fourier Optics,
3rd ed., 2005, Sect. 6.3), zero beyond the cut-off; the Gaussian's is
G(rho) = exp(-2 pi^2 sigma^2 rho^2). The integral is taken in polar
coordinates: Gauss-Legendre in rho, the trapezoid rule in the angle (exact
to rounding for a periodic, band-limited integrand).

"centred": the source at a pixel's centre (x0 = y0 = 0), the best case and
the convention of oi_camera.psf_peak_fraction; "worst": at a pixel's
corner (x0 = y0 = 1/2), where four pixels share it equally.

Usage: tools/psf_peak.py  prints the built-in cameras' values (docs/camera.md,
"Optics"); tests/python/test_psf_peak.py checks the method against closed
forms and a direct quadrature of the Airy pattern.
"""
import math

import numpy as np

H, C, K_B, T_SUN = 6.62607015e-34, 299792458.0, 1.380649e-23, 5772.0


def otf_diffraction(v):
    """The incoherent OTF of a circular pupil at normalised frequency v."""
    v = np.clip(v, 0.0, 1.0)
    return (2.0 / math.pi) * (np.arccos(v) - v * np.sqrt(1.0 - v * v))


def band_weights(lo_m, hi_m, n=16):
    """Gauss-Legendre wavelengths over [lo, hi] and weights proportional to
    the photon spectrum of a 5772 K blackbody (photons per unit wavelength),
    summing to 1."""
    x, w = np.polynomial.legendre.leggauss(n)
    lam = 0.5 * (hi_m - lo_m) * x + 0.5 * (hi_m + lo_m)
    b = 2.0 * H * C ** 2 / lam ** 5 / np.expm1(H * C / (lam * K_B * T_SUN))
    photons = b * lam / (H * C)
    wt = w * photons
    return lam, wt / wt.sum()


def pixel_fraction(x0, y0, sigma_px, cutoff_px=None, n_rho=400, n_theta=256):
    """Fraction of a point source in the pixel centred (x0, y0) pixels away.

    sigma_px: the Gaussian blur (pixels), >= 0; cutoff_px: the diffraction
    cut-off rho_c (cycles per pixel), None for no diffraction (then sigma_px
    must be > 0)."""
    if cutoff_px is None:
        if not sigma_px > 0:
            raise ValueError("a Gaussian-only PSF needs sigma > 0")
        rho_max = 9.0 / (2.0 * math.pi * sigma_px) * math.sqrt(2.0)  # G < e^-81
    else:
        rho_max = cutoff_px
        if sigma_px > 0:
            rho_max = min(rho_max, 9.0 / (2.0 * math.pi * sigma_px) * math.sqrt(2.0))
    # the sinc terms oscillate once per unit frequency: enough nodes per unit
    n_rho = max(n_rho, int(40 * rho_max) + 40)
    xr, wr = np.polynomial.legendre.leggauss(n_rho)
    rho = 0.5 * rho_max * (xr + 1.0)
    wr = 0.5 * rho_max * wr
    n_theta = max(n_theta, int(16 * rho_max) + 64)
    th = 2.0 * math.pi * np.arange(n_theta) / n_theta
    R, T = np.meshgrid(rho, th, indexing="ij")
    fx, fy = R * np.cos(T), R * np.sin(T)
    mtf = np.exp(-2.0 * math.pi ** 2 * sigma_px ** 2 * R ** 2)
    if cutoff_px is not None:
        mtf = mtf * otf_diffraction(R / cutoff_px)
    integrand = mtf * np.sinc(fx) * np.sinc(fy) * np.cos(2.0 * math.pi * (fx * x0 + fy * y0))
    return float(np.sum(integrand.sum(axis=1) * (2.0 * math.pi / n_theta) * rho * wr))


def camera_fraction(aperture_m, focal_m, pitch_m, sigma_px, band=(400e-9, 900e-9), where="centred"):
    """The band-averaged brightest-pixel fraction of a camera."""
    x0 = 0.0 if where == "centred" else 0.5
    lam, wt = band_weights(*band)
    total = 0.0
    for lm, w in zip(lam, wt):
        cutoff = pitch_m * aperture_m / (lm * focal_m)
        total += w * pixel_fraction(x0, x0, sigma_px, cutoff)
    return total


# The built-in cameras' optics (src/camera/camera_builtin.c) and the stated blur:
# sigma in pixels of the Gaussian for defocus, aberrations and jitter.
CAMERAS = {
    # star tracker: a deliberate defocus spreading a star over about 3 x 3
    # pixels for sub-pixel centroids (Liebe 2002: a PSF a few pixels wide);
    # sigma 1.0 px (FWHM 2.4 px), assumption
    "star-tracker": dict(aperture_m=0.0292, focal_m=0.035, pitch_m=5.5e-6, sigma_px=1.0),
    # 15 cm f/5.88 telescope: the Airy core (FWHM 3.6 um at 600 nm) is a
    # quarter of a 13 um pixel; optics, focus and jitter blur of sigma 1.0
    # px (3.0 arcsec, FWHM 2.4 px, 7.2 arcsec), assumption for a small
    # space telescope of this class
    "telescope-15cm": dict(aperture_m=0.15, focal_m=0.882, pitch_m=13e-6, sigma_px=1.0),
}


def main():
    print("camera           sigma_px  diffraction-only centred  centred  worst (corner)  "
          "worst/centred mag")
    for name, p in CAMERAS.items():
        diff = camera_fraction(p["aperture_m"], p["focal_m"], p["pitch_m"], 0.0)
        cen = camera_fraction(p["aperture_m"], p["focal_m"], p["pitch_m"], p["sigma_px"])
        worst = camera_fraction(p["aperture_m"], p["focal_m"], p["pitch_m"], p["sigma_px"],
                                where="worst")
        print(f"{name:16s} {p['sigma_px']:8.2f}  {diff:24.4f}  {cen:7.4f}  {worst:14.4f}  "
              f"{-2.5 * math.log10(worst / cen):17.2f}")


if __name__ == "__main__":
    main()
