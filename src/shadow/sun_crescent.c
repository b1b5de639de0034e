/* SPDX-License-Identifier: MIT */
/* sun_crescent.c: the single call's copy of the penumbra's branch-free
 * crescent (src/shadow/sun_crescent.h), out of line so that oi_sun_fraction's frame
 * does not hold it (make stack). */
#include "shadow/sun_crescent.h"

#ifdef OI_CRESCENT_KERNEL
/* oi__crescent_row for one row; *in_domain as there (1: the result is the
 * fraction). */
oi_real oi__crescent_fraction(const oi_real sun_km[3], const oi_real point_km[3],
                              oi_real re_km, oi_real rs_km, int *in_domain)
{
    oi_real ok;
    const oi_real f = oi__crescent_row(sun_km[0], sun_km[1], sun_km[2], point_km[0], point_km[1],
                                       point_km[2], re_km, rs_km, &ok);
    *in_domain = ok != (oi_real)0;
    return f;
}
#else
typedef int oi__crescent_double_only; /* ISO C: a translation unit is not empty */
#endif
