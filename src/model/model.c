/* SPDX-License-Identifier: MIT */
/* model.c: defaults and validation of oi_model, and oi_scene_defaults. */
#include "model/model_internal.h"
#include "oi_tables_internal.h"

/* The default model (every other field zero: the default options). */
static const oi_model default_model = {
    .tsi_w_m2 = (oi_real)OI_TSI_W_M2,
    .au_km = (oi_real)OI_AU_KM,
    .sun_radius_km = (oi_real)OI_SUN_RADIUS_KM,
    .earth_radius_km = (oi_real)OI_EARTH_RADIUS_KM,
    .moon_radius_km = (oi_real)OI_MOON_RADIUS_KM,
    .moon_albedo = (oi_real)OI_MOON_ALBEDO_DEFAULT,
};

/* The real-valued fields of oi_model (offsetof), in the order they are
 * checked: the three radii first (their failure is OI_ERR_RADIUS when all
 * three are finite), then tsi_w_m2, au_km, moon_albedo. A zero field takes
 * the default; a negative or non-finite one, or one outside [lo, hi] (the
 * bounds keep every intermediate finite), is rejected. Field i has the
 * bounds bound_lo/hi[i < N_RADII ? 0 : i - N_RADII + 1]. One loop over these
 * tables instead of six unrolled checks: the Sun-only build must fit 4 KiB of
 * flash (docs/performance.md). */
#define N_RADII 3
#define N_FIELDS 6
static const unsigned char field_offset[N_FIELDS] = {
    (unsigned char)offsetof(oi_model, sun_radius_km), (unsigned char)offsetof(oi_model, earth_radius_km),
    (unsigned char)offsetof(oi_model, moon_radius_km), (unsigned char)offsetof(oi_model, tsi_w_m2),
    (unsigned char)offsetof(oi_model, au_km), (unsigned char)offsetof(oi_model, moon_albedo)};
static const oi_real bound_lo[N_FIELDS - N_RADII + 1] = {
    (oi_real)OI_MODEL_RADIUS_MIN, (oi_real)OI_MODEL_TSI_MIN, (oi_real)OI_MODEL_AU_MIN, (oi_real)0};
static const oi_real bound_hi[N_FIELDS - N_RADII + 1] = {
    (oi_real)OI_MODEL_RADIUS_MAX, (oi_real)OI_MODEL_TSI_MAX, (oi_real)OI_MODEL_AU_MAX, (oi_real)1};

/* the field at byte offset off of a model */
#define FIELD(m, off) (*(const oi_real *)(const void *)((const char *)(m) + (off)))

/* The option fields are checked as "0 or 1" in one test: the values must be
 * 0 and 1 (a negative array size stops the build otherwise). */
typedef char model_options_are_0_or_1[(OI_EARTH_TABLE == 0 && OI_EARTH_LAMBERT == 1 &&
                                       OI_MOON_PHASE_LAW == 0 && OI_MOON_LAMBERT == 1 &&
                                       OI_LIMB_UNIFORM == 0 && OI_LIMB_DARKENED == 1 &&
                                       OI_EARTH_REFLECT_MOMENTS == 0 && OI_EARTH_REFLECT_MEAN == 1 &&
                                       OI_EARTH_SPHERE == 0 && OI_EARTH_WGS84 == 1 &&
                                       OI_BAND_V == 0 && OI_BAND_TOTAL == 1)
                                          ? 1
                                          : -1];

int oi__model_resolve(const oi_model *in, oi_model *out)
{
    oi_real v[N_FIELDS];
    unsigned i;
    /* the only copy of the defaults: *out is written again only on success */
    *out = default_model;
    if (in == NULL) return OI_OK;

    for (i = 0; i < N_FIELDS; i++) {
        const unsigned k = i < N_RADII ? 0u : i - N_RADII + 1u;
        const oi_real given = FIELD(in, field_offset[i]);
        v[i] = isgreater(given, (oi_real)0) ? given : FIELD(out, field_offset[i]); /* quiet: NaN */
        if (!OI_ISFINITE(given) || given < (oi_real)0 || v[i] < bound_lo[k] || v[i] > bound_hi[k]) {
            if (i >= N_RADII) return OI_ERR_MODEL;
            /* a radius: OI_ERR_RADIUS when all three are finite (those
             * before i passed their check, so only i on is tested) */
            for (; i < N_RADII; i++)
                if (!OI_ISFINITE(FIELD(in, field_offset[i]))) return OI_ERR_MODEL;
            return OI_ERR_RADIUS;
        }
    }
    /* each option 0 or 1 (see model_options_are_0_or_1) */
    if ((in->earth_model | in->moon_model | in->limb_darkening | in->earth_shape | in->band) & ~1)
        return OI_ERR_MODEL;
    /* earth_reflection also has OI_EARTH_REFLECT_TABLE (2) */
    if (in->earth_reflection < 0 || in->earth_reflection > OI_EARTH_REFLECT_TABLE)
        return OI_ERR_MODEL;
#ifdef OI_NO_LIMB_DARKENING
    /* the limb-darkened disc is compiled out (include/oi_config.h) */
    if (in->limb_darkening == OI_LIMB_DARKENED) return OI_ERR_MODEL;
#endif
#ifdef OI_NO_OBLATE
    /* the ellipsoid is compiled out (include/oi_config.h) */
    if (in->earth_shape == OI_EARTH_WGS84) return OI_ERR_MODEL;
#endif
#ifdef OI_NO_TOTAL_BAND
    /* the total band is compiled out (include/oi_config.h) */
    if (in->band == OI_BAND_TOTAL) return OI_ERR_MODEL;
#endif
#ifndef OI_NO_ATMOSPHERE
    /* a caller's atmosphere table, where it would be used (the default is
     * trusted; the earthshine table is checked by oi_earthshine) */
    if (in->atm_table != NULL && in->no_atmosphere == 0 && in->band == OI_BAND_V &&
        !oi__atm_table_valid(in->atm_table))
        return OI_ERR_MODEL;
#ifndef OI_NO_TOTAL_BAND
    if (in->atm_total_table != NULL && in->no_atmosphere == 0 && in->band == OI_BAND_TOTAL &&
        !oi__atm_table_valid(in->atm_total_table))
        return OI_ERR_MODEL;
#endif
#endif
    for (i = 0; i < N_FIELDS; i++) *(oi_real *)(void *)((char *)out + field_offset[i]) = v[i];
    out->earth_model = in->earth_model;
    out->moon_model = in->moon_model;
    out->limb_darkening = in->limb_darkening;
    out->earth_reflection = in->earth_reflection;
    out->earth_shape = in->earth_shape;
    out->no_atmosphere = in->no_atmosphere != 0;
    out->earth_table = in->earth_table;
    out->atm_table = in->atm_table;
    out->band = in->band;
    out->atm_total_table = in->atm_total_table;
#ifndef OI_NO_SKYLIGHT
    /* a caller's sky table is checked where it is used (src/sources/skylight.c);
     * without the sky light nothing reads it */
    out->sky_table = in->sky_table;
#endif
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
