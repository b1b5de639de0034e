/* SPDX-License-Identifier: MIT */
/*
 * model_internal.h: private to the runtime (not part of the API):
 * the model layer (src/model/): a model with its defaults resolved, the
 * default tables, statuses and version.
 * A layer calls only the layers below it (docs/architecture.md); this
 * header includes the one below, so a file sees its layer and every lower one.
 */
#ifndef OI_MODEL_INTERNAL_H
#define OI_MODEL_INTERNAL_H

#include "math/math_internal.h"

/*
 * Copy a model with every zero field replaced by its default; NULL means all
 * defaults. Returns OI_OK, OI_ERR_MODEL (non-finite or negative constant,
 * unknown option value, moon_albedo outside [0, 1]) or OI_ERR_RADIUS (a
 * negative radius). On error *out is the default model.
 */
int oi__model_resolve(const oi_model *in, oi_model *out);


/* Solar irradiance tsi (AU / d)^2 (W/m^2 for tsi in W/m^2) at d_km from the
 * Sun, the model's au_km the AU: the one place it is formed. tsi may carry
 * a factor (an albedo): the product is rounded as (tsi q) q, q = au / d. */
static inline oi_real oi__solar_irradiance(oi_real tsi, oi_real au_km, oi_real d_km)
{
    const oi_real q = au_km / d_km;
    return tsi * q * q;
}

/* The check of a caller's atmosphere table (src/model/atm_table_check.c). */
#ifndef OI_NO_ATMOSPHERE
/* 1 when a caller's atmosphere table has the format, kind, sizes and grid
 * constants the lookup can use (include/orbillum.h, oi_model.atm_table),
 * else 0. Called by oi__model_resolve (src/model/model.c). */
int oi__atm_table_valid(const oi_atm_table *t);
#endif

#endif /* OI_MODEL_INTERNAL_H */
