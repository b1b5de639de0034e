/* SPDX-License-Identifier: MIT */
/* phase.c: the Lambertian-sphere phase function and the angle between two
 * vectors. */
/* oi__norm, oi__finite3 out of line: the Sun-only build fits 4 KiB (src/oi_vector.h) */
#define OI_VECTOR_OUT_OF_LINE
#include "sources/sources_internal.h"

/* 2 / (3 pi) */
#define TWO_THIRDS_OVER_PI OI_R(0.21220659078919378103)

/*
 * Series of f(t) = sin t - t cos t = sum_{k>=1} (-1)^(k+1) 2k t^(2k+1) / (2k+1)!
 * written as t^3 * sum_k c_k u^(k-1), u = t^2. Used for t < 1, where the
 * k = 10 term is below 2e-18 relative (see docs/shadow.md).
 */
static oi_real series_sin_minus_tcos(oi_real t)
{
    const oi_real u = t * t;
    /* c_k = (-1)^(k+1) 2k / (2k+1)!, k = 1..9 */
    oi_real s = OI_R(1.4797143443923793491e-16);      /* k=9: 18/19! */
    s = s * u - OI_R(4.4983316069528332211e-14);       /* k=8: 16/17! */
    s = s * u + OI_R(1.0706029224547743066e-11);       /* k=7: 14/15! */
    s = s * u - OI_R(1.9270852604185937519e-09);       /* k=6: 12/13! */
    s = s * u + OI_R(2.5052108385441718775e-07);       /* k=5: 10/11! */
    s = s * u - OI_R(2.2045855379188712522e-05);       /* k=4:  8/9!  */
    s = s * u + OI_R(1.1904761904761904762e-03);       /* k=3:  6/7!  */
    s = s * u - OI_R(3.3333333333333333333e-02);       /* k=2:  4/5!  */
    s = s * u + OI_R(3.3333333333333333333e-01);       /* k=1:  2/3!  */
    return t * u * s;
}

/*
 * oi_lambert_phase: phase function of a Lambertian sphere.
 *
 * Given:
 *   xi     oi_real  phase angle: the angle at the sphere between the
 *                   directions to the source and to the viewer (radians)
 * Returned (function value):
 *          oi_real  p(xi) = 2/(3 pi) ((pi - xi) cos xi + sin xi), in
 *                   [0, 2/3]; p(0) = 2/3, p(pi) = 0.
 * Notes:
 *  1. xi is clamped to [0, pi]; a NaN gives 0 (no light: the safe answer for
 *     a function without status).
 *  2. With t = pi - xi formed exactly (two-part pi, oi__pi_minus),
 *     p = 2/(3 pi) (sin t - t cos t). For t < 1 a series in t is used (the closed form cancels to
 *     ~t^3/3 near xi = pi); elsewhere the closed form, whose terms then do
 *     not cancel by more than a factor ~5.
 *  3. Measured relative error against mpmath (tests/c/test_phase.c, 400+
 *     points including xi within 1e-8 of 0 and pi): see docs/shadow.md.
 *  4. Energy: a sphere of radius a, albedo alpha under irradiance E sends
 *     F = E alpha a^2 p(xi) / d^2 to a viewer at distance d; integrating
 *     F d^2 over all directions gives alpha E pi a^2 (docs/physics.md).
 * References:
 *   Russell, H.N. 1916, ApJ 43, 173 (the Lambert-sphere phase law).
 *   Penney 2009 (seed), sec. II.4, with the normalisation corrected
 *   (docs/physics.md: the errata to its eq. 3.1-3.4).
 */
oi_real oi_lambert_phase(oi_real xi)
{
    return oi__lambert_phase_cs(xi, (oi_real)2, (oi_real)0);
}

/* oi_lambert_phase with cos(xi), sin(xi) given when the caller has them
 * (cos_xi > 1 means "not given": computed here); see src/sources/sources_internal.h. */
oi_real oi__lambert_phase_cs(oi_real xi, oi_real cos_xi, oi_real sin_xi)
{
    oi_real t, f;
    if (xi != xi) return (oi_real)0;              /* NaN */
    if (xi <= (oi_real)0) return (oi_real)2 / (oi_real)3;  /* p(0) = 2/3 */
    t = oi__pi_minus(xi);                         /* pi - xi, one rounding */
    if (!(t > (oi_real)0)) return (oi_real)0;     /* xi >= pi */
    if (t < (oi_real)1) {
        f = series_sin_minus_tcos(t);
    } else {
        if (cos_xi > (oi_real)1) {
            OI_SINCOS(xi, &sin_xi, &cos_xi);
        }
        f = t * cos_xi + sin_xi;
    }
    f *= TWO_THIRDS_OVER_PI;
    return f > (oi_real)0 ? f : (oi_real)0;
}

/*
 * oi_angle: angle between two vectors.
 *
 * Given:
 *   a, b   oi_real[3]  two vectors (any common unit); may be the same array
 * Returned (function value):
 *          oi_real     the angle between them, in [0, pi] (radians);
 *                      0 if either vector is zero or not finite.
 * Notes:
 *  1. Both vectors are scaled to unit length first (so that components near
 *     the overflow or underflow limits cannot overflow the cross product),
 *     then angle = atan2(|a x b|, a . b): accurate near 0 and pi, unlike acos
 *     of the dot product. The absolute error is a few units of the
 *     precision's epsilon, which is the conditioning of the angle with
 *     respect to a relative perturbation of the inputs.
 * References:
 *   Kahan, W. 2006, "How futile are mindless assessments of roundoff in
 *   floating-point computation?" (the angle between two vectors).
 */
oi_real oi_angle(const oi_real a[3], const oi_real b[3])
{
    oi_real ua[3], ub[3], c[3];
    oi_real s;
    if (a == NULL || b == NULL || !oi__finite3(a) || !oi__finite3(b)) return (oi_real)0;
    if (!(oi__unit(a, ua) > (oi_real)0) || !(oi__unit(b, ub) > (oi_real)0)) return (oi_real)0;
    oi__cross(ua, ub, c);
    s = oi__norm(c);
    return OI_ATAN2(s, oi__dot(ua, ub));
}
