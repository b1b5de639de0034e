/* SPDX-License-Identifier: MIT */
/* spherical_triangle.c: the half-angle formulas of a spherical triangle from
 * its three sides, in forms without cancellation (oi__half_sines,
 * oi__half_angle; internal, declared in src/math/math_internal.h).
 * References: Todhunter, I. 1886, Spherical Trigonometry, 5th ed. (the
 * half-angle formulas); Kahan, W. 2014, "Miscalculating Area and Angles of a
 * Needle-like Triangle" (ordering of the side sums). */
#include "math/math_internal.h"

/*
 * The sines of the spherical triangle with sides a, b, c (radians, triangle
 * inequalities assumed; rounding beyond them is clamped) used by the
 * half-angle formulas (l'Huilier's family), s = (a + b + c)/2:
 *   hs[0] = sin s, hs[1] = sin(s - a), hs[2] = sin(s - b), hs[3] = sin(s - c),
 * the differences formed in Kahan's order (no cancellation).
 */
void oi__half_sines(oi_real a, oi_real b, oi_real c, oi_real hs[4])
{
    int i;
    hs[0] = oi__sin_0_pi(OI_R(0.5) * (a + (b + c)));
    hs[1] = OI_SIN(OI_R(0.5) * oi__side_excess(a, b, c));
    hs[2] = OI_SIN(OI_R(0.5) * oi__side_excess(b, a, c));
    hs[3] = OI_SIN(OI_R(0.5) * oi__side_excess(c, a, b));
    for (i = 0; i < 4; ++i) hs[i] = hs[i] > (oi_real)0 ? hs[i] : (oi_real)0;
}

/*
 * The angle opposite the side of index i (1: a, 2: b, 3: c) from
 *   tan(A/2) = sqrt( sin(s-b) sin(s-c) / (sin s sin(s-a)) ),
 * or with comp != 0 pi - A from the reciprocal ratio, so that neither A nor
 * pi - A is formed by a cancelling subtraction. A point-like triangle gives
 * A = 0.
 */
oi_real oi__half_angle(const oi_real hs[4], int i, int comp)
{
    oi_real num = OI_SQRT(hs[i == 1 ? 2 : 1]) * OI_SQRT(hs[i == 3 ? 2 : 3]);
    oi_real den = OI_SQRT(hs[0]) * OI_SQRT(hs[i]);
    if (num == (oi_real)0 && den == (oi_real)0) return comp ? OI_PI_R : (oi_real)0;
    return (oi_real)2 * (comp ? OI_ATAN2(den, num) : OI_ATAN2(num, den));
}
