/* SPDX-License-Identifier: MIT */
/* model.c: defaults and validation of oi_model, and oi_scene_defaults. */
#include "oi_internal.h"

/* The default model (every other field zero: the default options). */
static const oi_model default_model = {
    .tsi_w_m2 = (oi_real)OI_TSI_W_M2,
    .au_km = (oi_real)OI_AU_KM,
    .sun_radius_km = (oi_real)OI_SUN_RADIUS_KM,
    .earth_radius_km = (oi_real)OI_EARTH_RADIUS_KM,
    .moon_radius_km = (oi_real)OI_MOON_RADIUS_KM,
    .moon_albedo = (oi_real)OI_MOON_ALBEDO_DEFAULT,
};

/* Replace a zero constant by its default; reject negative, non-finite, or
 * outside [lo, hi] (the bounds keep every intermediate finite). */
static int resolve_positive(oi_real given, oi_real fallback, oi_real lo, oi_real hi,
                            oi_real *out)
{
    if (!OI_ISFINITE(given) || given < (oi_real)0) return -1;
    *out = given > (oi_real)0 ? given : fallback;
    return *out < lo || *out > hi ? -1 : 0;
}

int oi__model_resolve(const oi_model *in, oi_model *out)
{
    const oi_model def = default_model;
    *out = def;
    if (in == NULL) return OI_OK;

    const oi_real r_lo = (oi_real)OI_MODEL_RADIUS_MIN, r_hi = (oi_real)OI_MODEL_RADIUS_MAX;
    if (resolve_positive(in->sun_radius_km, def.sun_radius_km, r_lo, r_hi, &out->sun_radius_km) ||
        resolve_positive(in->earth_radius_km, def.earth_radius_km, r_lo, r_hi,
                         &out->earth_radius_km) ||
        resolve_positive(in->moon_radius_km, def.moon_radius_km, r_lo, r_hi,
                         &out->moon_radius_km)) {
        *out = def;
        return OI_ISFINITE(in->sun_radius_km) && OI_ISFINITE(in->earth_radius_km) &&
                       OI_ISFINITE(in->moon_radius_km)
                   ? OI_ERR_RADIUS
                   : OI_ERR_MODEL;
    }
    if (resolve_positive(in->tsi_w_m2, def.tsi_w_m2, (oi_real)OI_MODEL_TSI_MIN, (oi_real)OI_MODEL_TSI_MAX,
                         &out->tsi_w_m2) ||
        resolve_positive(in->au_km, def.au_km, (oi_real)OI_MODEL_AU_MIN, (oi_real)OI_MODEL_AU_MAX,
                         &out->au_km) ||
        resolve_positive(in->moon_albedo, def.moon_albedo, (oi_real)0, (oi_real)1,
                         &out->moon_albedo) ||
        (in->earth_model != OI_EARTH_TABLE && in->earth_model != OI_EARTH_LAMBERT) ||
        (in->moon_model != OI_MOON_PHASE_LAW && in->moon_model != OI_MOON_LAMBERT) ||
        (in->limb_darkening != OI_LIMB_UNIFORM && in->limb_darkening != OI_LIMB_DARKENED)
#ifdef OI_NO_LIMB_DARKENING
        /* the limb-darkened disc is compiled out (include/oi_config.h) */
        || in->limb_darkening == OI_LIMB_DARKENED
#endif
    ) {
        *out = def;
        return OI_ERR_MODEL;
    }
    out->earth_model = in->earth_model;
    out->moon_model = in->moon_model;
    out->limb_darkening = in->limb_darkening;
    out->no_atmosphere = in->no_atmosphere != 0;
    out->earth_table = in->earth_table;
    return OI_OK;
}

void oi_scene_defaults(oi_scene *scene)
{
    if (scene == NULL) return;
    memset(scene, 0, sizeof *scene);
    scene->terms = OI_TERM_SUN | OI_TERM_EARTH;
#ifndef OI_NO_MOON
    scene->terms |= OI_TERM_MOON;
#endif
    scene->earth_albedo = (oi_real)OI_EARTH_ALBEDO_DEFAULT;
    scene->target_albedo = (oi_real)OI_TARGET_ALBEDO_DEFAULT;
    scene->target_radius_m = (oi_real)OI_TARGET_RADIUS_M_DEFAULT;
}
