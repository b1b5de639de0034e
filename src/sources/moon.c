/* SPDX-License-Identifier: MIT */
/* moon.c: the empirical lunar phase law. */
#include "sources/sources_internal.h"

#ifndef OI_NO_MOON

/*
 * oi_moon_phase_law: the Moon's brightness relative to full Moon.
 *
 * Given:
 *   alpha  oi_real  the Moon's phase angle (radians): the angle at the Moon
 *                   between the Sun and the observer
 * Returned (function value):
 *          oi_real  I(alpha)/I(0) = 10^(-0.4 (0.026 a + 4e-9 a^4)), a = |alpha|
 *                   in degrees, clamped to [0, 180]; in [2.8e-4, 1].
 * Notes:
 *  1. Krisciunas & Schaefer (1991) give the law with |alpha| (the sign of a
 *     phase angle only tells waxing from waning); a negative alpha is read
 *     as its magnitude, then clamped to [0, pi]. A NaN gives 0 (no light).
 *  2. Validity: the law is Krisciunas & Schaefer's empirical fit to Allen's
 *     tabulated lunar magnitudes; this project treats it as reliable up to
 *     about 150 degrees (a thin crescent a few days from new Moon).
 *     Beyond 150 degrees this function keeps the same polynomial
 *     (an extrapolation, not a measurement): it stays positive, finite and
 *     strictly decreasing up to 180 degrees, where it is 10^(-3.55) = 2.8e-4
 *     (8.88 mag below full). At such angles the Moon is within ~30 degrees
 *     of the Sun, and its light on a target is negligible next to
 *     earthshine; no warning is raised.
 *  3. The opposition surge near alpha = 0 is not modelled (the fit is
 *     linear in |alpha| there).
 *  4. Relative error against the formula evaluated in mpmath: a few
 *     epsilon (one exp of an argument up to 8.2).
 * References:
 *   Krisciunas, K. & Schaefer, B.E. 1991, PASP 103, 1033, eq. 20.
 *   Allen, C.W. 1976, Astrophysical Quantities, 3rd ed., sec. 66.
 */
oi_real oi_moon_phase_law(oi_real alpha)
{
    /* 0.4 ln 10 */
    const oi_real k = OI_R(0.92103403719761827361);
    oi_real a, mag;
    if (alpha != alpha) return (oi_real)0;
    a = OI_FABS(alpha);
    if (a > OI_PI_R) a = OI_PI_R;
    a *= (oi_real)OI_DEG_PER_RAD;
    mag = OI_R(0.026) * a + OI_R(4e-9) * ((a * a) * (a * a));
    return OI_EXP(-k * mag);
}

#endif /* OI_NO_MOON */
