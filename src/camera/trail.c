/* SPDX-License-Identifier: MIT */
/*
 * trail.c: the brightest pixel of a point source that moves during the
 * exposure: a Gaussian PSF swept along a line, in closed form
 * (docs/camera.md, "Motion").
 */
#include "camera/camera_internal.h"

#ifndef OI_NO_EXPOSURE

#define SQRT2     OI_R(1.4142135623730951)
#define SQRT2PI_INV OI_R(0.3989422804014327) /* 1 / sqrt(2 pi) */
#define TWO_SQRTPI_INV OI_R(1.1283791670955126) /* 2 / sqrt(pi) */
/* Below this trail (pixels) the factor is 1: its exact value is
 * 1 - O(L^2 / sigma^2), within 2e-6 of 1 for sigma >= 0.7 px, and the
 * closed form below loses digits to cancellation there. */
#define TRAIL_MIN_PX OI_R(1e-3)
/* The central fraction per axis is capped below 1 (a PSF no narrower than
 * sigma = 0.1 pixel, erf(3.54) = 1 - 1e-6), so that the Gaussian exists. */
#define Q_MAX OI_R(0.999999)

/*
 * oi__psf_sigma_px: the sigma (pixels) of the Gaussian PSF that puts the
 * fraction p of a point source centred on a pixel into that pixel:
 * p = erf(a)^2 with a = 1 / (2 sqrt(2) sigma). a = erfinv(sqrt(p)) by
 * Newton's method from Winitzki's approximation (relative error < 2e-3),
 * four steps (quadratic convergence: past double precision).
 */
oi_real oi__psf_sigma_px(oi_real p)
{
    const oi_real k = OI_R(0.147);
    oi_real q = OI_SQRT(p), a, l, t;
    int i;
    if (q > Q_MAX) q = Q_MAX;
    l = OI_LOG((OI_R(1.0) - q) * (OI_R(1.0) + q));
    t = OI_R(2.0) / (OI_PI_R * k) + OI_R(0.5) * l;
    a = OI_SQRT(OI_SQRT(t * t - l / k) - t);
    for (i = 0; i < 4; i++) {
        a -= (OI_ERF(a) - q) / (TWO_SQRTPI_INV * OI_EXP(-a * a));
    }
    return OI_R(1.0) / (OI_R(2.0) * SQRT2 * a);
}

/* F(-v) for v >= 0, F(u) = u Phi(u) + phi(u) the integral of the normal
 * distribution function Phi: phi(v) - v Phi(-v). */
static oi_real f_neg(oi_real v)
{
    return SQRT2PI_INV * OI_EXP(OI_R(-0.5) * v * v) - v * OI_R(0.5) * OI_ERFC(v / SQRT2);
}

/*
 * oi__trail_factor: the brightest pixel's share of a point source trailed
 * over L pixels along a pixel row, centred on a pixel, over its share at
 * rest, for a Gaussian PSF of sigma pixels with central fraction q per axis
 * (q = erf(1 / (2 sqrt(2) sigma))). Across the trail nothing changes; along
 * it the pixel collects
 *   g(L) = (1/L) int_{-L/2}^{L/2} [Phi((x + 1/2)/s) - Phi((x - 1/2)/s)] dx
 * which, with F(u) = F(-u) + u, is
 *   g(L) = min(L, 1) / L + (2 s / L) [F(-c1) - F(-|c3|)],
 *   c1 = (L + 1) / (2 s), c3 = (L - 1) / (2 s),
 * free of the cancellation of the four-term form at long trails. The factor
 * is g(L) / q: 1 at L = 0, about 1 / (q L) for L >> 1.
 */
oi_real oi__trail_factor(oi_real sigma, oi_real q, oi_real trail)
{
    oi_real c1, c3, g;
    if (!(trail >= TRAIL_MIN_PX)) return OI_R(1.0);
    c1 = (trail + OI_R(1.0)) / (OI_R(2.0) * sigma);
    c3 = OI_FABS(trail - OI_R(1.0)) / (OI_R(2.0) * sigma);
    g = (trail < OI_R(1.0) ? OI_R(1.0) : OI_R(1.0) / trail) +
        OI_R(2.0) * sigma / trail * (f_neg(c1) - f_neg(c3));
    g /= q;
    return g > OI_R(1.0) ? OI_R(1.0) : g;
}

#endif /* OI_NO_EXPOSURE */
