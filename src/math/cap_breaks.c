/* SPDX-License-Identifier: MIT */
/* cap_breaks.c: the break points in the polar angle a about the sub-target
 * point that the cubatures over the visible sunlit cap (the sphere's,
 * src/sources/earthshine_angular.c, and the facets', src/target/facet_earth.c) split their
 * rings at: the horizon, the terminator's tangency and multiples of the
 * altitude (the 1/d^3 peak under the target). */
#include "math/math_internal.h"

int oi__cap_break_add(oi_real *bp, int cap, int n, oi_real x, oi_real a_max)
{
    int i;
    if (!(x > (oi_real)0 && x < a_max) || n >= cap) return n;
    for (i = n; i > 0 && bp[i - 1] > x; i--) bp[i] = bp[i - 1];
    bp[i] = x;
    return n + 1;
}

int oi__cap_breaks_at(oi_real *bp, int cap, oi_real hp, oi_real rp, oi_real theta,
                      oi_real *a_max)
{
    *a_max = OI_ATAN2(OI_SQRT(hp * ((oi_real)1 + rp)), rp);
    bp[0] = (oi_real)0;
    bp[1] = *a_max;
    return oi__cap_break_add(bp, cap, 2, OI_FABS(OI_HALF_PI_R - theta), *a_max);
}

int oi__cap_breaks_start(oi_real *bp, int cap, oi_real hp, oi_real rp, oi_real cos_theta,
                         oi_real sin_theta, oi_real *a_max)
{
    return oi__cap_breaks_at(bp, cap, hp, rp, OI_ATAN2(sin_theta, cos_theta), a_max);
}

int oi__cap_breaks_altitude(oi_real *bp, int cap, int n, int n_geo, oi_real hp, oi_real rp,
                            oi_real a_max)
{
    /* distances 2 h, 8 h, ... while within the inner half of the horizon's */
    oi_real d = OI_R(2.0) * hp;
    int g;
    for (g = 0; g < n_geo && d * d < OI_R(0.5) * hp * ((oi_real)1 + rp); g++) {
        const oi_real x = (d * d - hp * hp) / (OI_R(4.0) * rp);
        n = oi__cap_break_add(bp, cap, n, OI_R(2.0) * OI_ASIN(OI_SQRT(x)), a_max);
        d *= OI_R(4.0);
    }
    return n;
}
