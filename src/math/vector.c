/* SPDX-License-Identifier: MIT */
/*
 * vector.c: the out-of-line copies of the scaled norm and of the finiteness
 * test of src/oi_vector.h, called by the files that define
 * OI_VECTOR_OUT_OF_LINE (the Sun-only build: src/shadow/sun_fraction.c,
 * src/sources/phase.c) instead of an inline copy at each call (the Sun-only build
 * under 4 KiB of flash; docs/performance.md). Same results as the inline
 * ones.
 */
#include "math/math_internal.h"

/*
 * oi__norm_outline: Euclidean norm of a 3-vector without overflow or
 * underflow (the body of oi__norm_inline, src/oi_vector.h).
 *
 * Given:
 *   a   oi_real[3]  vector (any values)
 * Returned (function value):
 *       oi_real     |a| = m sqrt((a/m).(a/m)), m the largest |component|;
 *                   0 for the zero vector; m itself when m is not finite.
 * Notes:
 *  1. The scaling puts the sum of squares in [1, 3]: no intermediate
 *     overflows or underflows for any finite input. Same bits as the inline
 *     copy.
 */
oi_real oi__norm_outline(const oi_real a[3])
{
    return oi__norm_inline(a);
}

/*
 * oi__finite3_outline: are all three components finite? (the same answer
 * as oi__finite3_inline, src/oi_vector.h)
 *
 * Given:
 *   a   oi_real[3]  vector
 * Returned (function value):
 *       int         1 when no component is infinite or NaN, else 0
 */
int oi__finite3_outline(const oi_real a[3])
{
    /* |x| < inf by the quiet comparison (no FE_INVALID for an infinity or a
     * NaN, where x - x raised it), the three joined without branches: the
     * answer of oi__finite3_inline */
    return isless(OI_FABS(a[0]), (oi_real)INFINITY) & isless(OI_FABS(a[1]), (oi_real)INFINITY) &
           isless(OI_FABS(a[2]), (oi_real)INFINITY);
}

/*
 * oi__unit_tiny: the unit vector of a vector of subnormal norm n (> 0):
 * a / m, m its largest |component| (quotients of exact values, correctly
 * rounded, the largest 1), then that over its norm (src/oi_vector.h,
 * oi__unit_scaled). Returns n.
 */
oi_real oi__unit_tiny(const oi_real a[3], oi_real n, oi_real out[3])
{
    oi_real m = OI_FABS(a[0]), t = OI_FABS(a[1]), b[3];
    if (t > m) m = t;
    t = OI_FABS(a[2]);
    if (t > m) m = t;
    b[0] = a[0] / m;
    b[1] = a[1] / m;
    b[2] = a[2] / m;
    (void)oi__divide3(b, OI_SQRT(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]), out);
    return n;
}
