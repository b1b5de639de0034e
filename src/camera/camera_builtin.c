/* SPDX-License-Identifier: MIT */
/*
 * camera_builtin.c: the built-in cameras, as data, and oi_camera_builtin
 * (the look-up by name, oi_camera_find, is in src/camera/camera.c).
 *
 * Each parameter names its source. "Datasheet" values are the sensor
 * maker's typical figures; "assumption" marks a design value chosen for a
 * representative instrument of the class (documented in docs/camera.md).
 * The in-band fraction of sunlight and the mean photon energy are for an
 * unfiltered silicon band 400-900 nm, from a 5772 K Planck spectrum (IAU
 * 2015 Resolution B3 nominal solar effective temperature): fraction of the
 * total 0.5356, band energy / band photon count 3.1825e-19 J. The real
 * ASTM E-490 AM0 spectrum differs from the Planck curve by a few percent in
 * this band; docs/camera.md gives the one-line computation.
 */
#include "camera/camera_internal.h"

#ifndef OI_NO_EXPOSURE

#define BAND_FRACTION_SI_400_900 OI_R(0.5356)
#define PHOTON_ENERGY_SI_400_900 OI_R(3.1825e-19)

static const oi_camera builtin[] = {
    /*
     * 0: "star-tracker": a star-tracker-class camera, CMV4000 CMOS sensor
     * (2048 x 2048, 5.5 um pixels) behind a 35 mm f/1.2 lens.
     * Sensor values: CMOSIS CMV4000 v2 datasheet (v2.13, 2014; ams DS000728).
     * Optics class: Liebe 2002, IEEE Trans. AES 38(2), 587 ("Accuracy
     * performance of star trackers - a tutorial"): apertures of a few cm,
     * fields of 8-25 deg, deliberate defocus over a few pixels.
     */
    {
        "star-tracker",
        OI_R(0.0292),       /* aperture: 35 mm / 1.2 (assumption, f/1.2) */
        OI_R(0.035),        /* focal length (assumption, 35 mm) */
        OI_R(5.5e-6),       /* pixel pitch (datasheet) */
        OI_R(0.80),         /* lens transmission, 6-8 AR-coated elements (assumption) */
        OI_R(0.45),         /* band-mean QE 400-900 nm; datasheet peak QE x FF 0.60 at 550 nm */
        BAND_FRACTION_SI_400_900,
        PHOTON_ENERGY_SI_400_900,
        OI_R(13500.0),      /* full well (datasheet: 13.5 ke-) */
        OI_R(125.0),        /* dark current at 25 C (datasheet: 125 e-/s) */
        OI_R(0.1415),       /* brightest-pixel fraction, source centred: tools/psf_peak.py, the
                               Airy pattern of this pupil over 400-900 nm, with a defocus
                               Gaussian of sigma 1.0 px (assumption: a star spread over about
                               3 x 3 pixels, Liebe 2002), over a 5.5 um pixel; 0.1129 at a
                               pixel's corner */
        OI_R(0.44751311938737), /* diagonal FOV: 2 atan(15.93 mm / 2 / 35 mm) = 25.64 deg */
        OI_R(0.6108652381980153), /* Sun exclusion half-angle 35 deg (assumption, baffle) */
        11,
        { OI_R(1e-5), OI_R(3e-5), OI_R(1e-4), OI_R(3e-4), OI_R(1e-3), OI_R(3e-3),
          OI_R(1e-2), OI_R(3e-2), OI_R(0.1), OI_R(0.3), OI_R(1.0) },
        /* programmable gain x1 .. x1.6 (datasheet PGA steps); read noise
           13 e- at unit gain (datasheet), assumed unchanged at higher gain */
        4,
        { OI_R(1.0), OI_R(1.2), OI_R(1.4), OI_R(1.6) },
        { OI_R(13.0), OI_R(13.0), OI_R(13.0), OI_R(13.0) },
        OI_R(3.0),          /* longest acceptable trail: about 1.2 times the PSF's FWHM (2.4 px
                               for its peak fraction) (assumption) */
        0, 0,               /* detection: the SNR rule of the goal (docs/camera.md) */
        /* sensor temperature: dark current 125 e-/s at 25 C (datasheet); it doubles
           every 6.5 C (assumption: silicon sensors near room temperature double every
           5-9 C, Janesick 2001, Scientific Charge-Coupled Devices, ch. 7); rated
           -30 .. +70 C (assumption, an industrial range) */
        OI_R(25.0), OI_R(6.5), OI_R(-30.0), OI_R(70.0)
    },
    /*
     * 1: "telescope-15cm": a 15 cm space telescope of the NEOSSat / MOST
     * class: 15 cm aperture f/5.88 Maksutov (Wallace et al. 2006, Proc. SPIE
     * 6265, 626526: 15 cm, Sun exclusion 45 deg; Laurin et al. 2008, Proc.
     * SPIE 7010), e2v CCD47-20 frame-transfer CCD (1024 x 1024,
     * 13 um pixels; e2v CCD47-20 datasheet).
     */
    {
        "telescope-15cm",
        OI_R(0.15),         /* aperture (Wallace et al. 2006) */
        OI_R(0.882),        /* focal length: 0.15 m x 5.88 */
        OI_R(13e-6),        /* pixel pitch (CCD47-20 datasheet) */
        OI_R(0.70),         /* catadioptric optics + window (assumption) */
        OI_R(0.75),         /* band-mean QE 400-900 nm, back-illuminated (datasheet curve, est.) */
        BAND_FRACTION_SI_400_900,
        PHOTON_ENERGY_SI_400_900,
        OI_R(100000.0),     /* full well (datasheet peak signal 100 ke-) */
        OI_R(1.0),          /* dark current, passively cooled CCD (assumption) */
        OI_R(0.1361),       /* brightest-pixel fraction, source centred: tools/psf_peak.py, the
                               Airy pattern of the 15 cm f/5.88 pupil over 400-900 nm, with an
                               optics, focus and jitter Gaussian of sigma 1.0 px = 3.0 arcsec
                               (assumption), over a 13 um pixel; 0.1091 at a pixel's corner */
        OI_R(0.021343873284922172), /* diagonal FOV: 1.223 deg (0.865 deg side) */
        OI_R(0.7853981633974483),   /* Sun exclusion 45 deg (Wallace et al. 2006) */
        9,
        { OI_R(0.01), OI_R(0.03), OI_R(0.1), OI_R(0.3), OI_R(1.0), OI_R(3.0),
          OI_R(10.0), OI_R(30.0), OI_R(100.0) },
        /* one conversion gain; read noise 6 e- (datasheet typical at 1 MHz) */
        1,
        { OI_R(1.0) },
        { OI_R(6.0) },
        OI_R(3.0),          /* longest acceptable trail: about 1.2 times the PSF's FWHM (2.5 px
                               for its peak fraction) (assumption) */
        0, 0,               /* detection: the SNR rule of the goal (docs/camera.md) */
        /* sensor temperature: the 1 e-/s above taken at -20 C (assumption); doubling
           6.35 C, e2v's dark-current law for its CCDs, Q/Q(293 K) = 122 T^3
           exp(-6400 / T) (CCD47-20 datasheet), at 253 K; rated -40 .. +20 C
           (assumption) */
        OI_R(-20.0), OI_R(6.35), OI_R(-40.0), OI_R(20.0)
    }
};

#define N_BUILTIN ((int)(sizeof builtin / sizeof builtin[0]))

/*
 * oi_camera_builtin: a built-in camera by index.
 *
 * Given:
 *   index    int   0, 1, ... (0 is the default camera: "star-tracker")
 *
 * Returned (function value):
 *            const oi_camera *  the camera (static, read-only); NULL when
 *                               index is negative or past the last camera.
 *
 * Notes:
 *   1. Iterate with index = 0, 1, ... until NULL to list them.
 *   2. Parameters and their sources: docs/camera.md and this file.
 *
 * References: see the comments of each table entry.
 */
const oi_camera *oi_camera_builtin(int index)
{
    if (index < 0 || index >= N_BUILTIN) return NULL;
    return &builtin[index];
}

#endif /* OI_NO_EXPOSURE */
