/* SPDX-License-Identifier: MIT */
/* sun_fraction_want.c: oi__sun_shadow_want, the batch's Sun fraction with a
 * choice of outputs (src/shadow/shadow_internal.h), from the same steps as
 * oi__sun_shadow (src/shadow/sun_fraction_steps.h) in a unit of its own, so
 * that the single call's code is not changed by a second caller of its steps
 * (make size). */
/* as src/shadow/sun_fraction.c: oi__norm, oi__finite3 out of line */
#define OI_VECTOR_OUT_OF_LINE
#include "shadow/sun_fraction_steps.h"

/* oi__sun_shadow for the batch (src/batch/batch.c): the limb-darkened
 * fraction is formed only when it is wanted or the atmosphere's fraction
 * needs it, which the atmosphere (and the limb-darkened model) do: the
 * uniform-disc fraction without the atmosphere skips that integral. Without
 * OI__WANT_ATM the atmosphere is not consulted and fraction_atm is 0. */
int oi__sun_shadow_want(const oi_real sun_km[3], const oi_real point_km[3],
                        const oi_model *resolved, unsigned want, oi_shadow *out,
                        oi_real light_dir[3])
{
    int st, need_ld = (want & OI__WANT_LD) != 0;

    if (want & OI__WANT_ATM) {
#ifndef OI_NO_ATMOSPHERE
        if (!resolved->no_atmosphere) need_ld = 1;
#endif
        if (resolved->limb_darkening == OI_LIMB_DARKENED) need_ld = 1;
    }
    st = shadow_geometric(sun_km, point_km, resolved, need_ld, out);
    if (st < 0) return st;
#ifndef OI_NO_OBLATE
    if (st == GEOMETRIC_WANTS_EXACT)
        oblate_exact(sun_km, point_km, resolved->earth_radius_km, out);
#endif
    return (want & OI__WANT_ATM) ? atmosphere_fraction(sun_km, point_km, resolved, out, light_dir)
                                 : OI_OK;
}
