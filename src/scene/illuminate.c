/* SPDX-License-Identifier: MIT */
/* illuminate.c: oi_illuminate, light on the target from Sun, Earth and Moon,
 * and the flux the target sends to an observer. */
/* every output: the Sun's term of the single call */
#define SCENE_SUN_TERM(scene, m, outputs, out) ((void)(outputs), sun_term((scene), (m), (out)))
#include "scene/illuminate_terms.h"

/*
 * oi_illuminate: the contract (given, returned, statuses) is in
 * include/orbillum.h.
 * Notes:
 *  1. Sun: e_sun = TSI (AU / |sun - target|)^2 * shadow.fraction_atm, where
 *     fraction_atm is the uniform-disc fraction, or the limb-darkened one with
 *     OI_LIMB_DARKENED, or the atmosphere's when compiled in and enabled;
 *     in the shadow, dir_sun is then the mean direction of the refracted light.
 *  2. Earth: e_earth = earth_albedo * TSI (AU/|sun|)^2 * phi(theta, h).
 *  3. Moon: the Moon is lit by the fraction of the Sun it sees (so it darkens
 *     in the Earth's shadow), and its light is cut by the part of its disc
 *     the Earth hides from the target (oi__moon_disc_visible). Whenever its
 *     position is given (OI_TERM_MOON or has_moon) the Moon also occults the
 *     Sun (oi__moon_shadow: the shadow's fractions and e_sun count it;
 *     sun_moon_hidden). The Moon's shadow test is skipped when the Moon is
 *     certainly in full sunlight (certainly_lit), its occultation when its
 *     disc is certainly apart from the Sun's.
 *  3b. Sky (OI_TERM_SKY): e_sky = TSI (AU/|sun|)^2 (E_sky / E_sun)(theta, r)
 *     from the scattered-sunlight table (src/sources/skylight.c), reflected from its
 *     mean direction (docs/skylight.md).
 *  4. The target is a Lambertian sphere; earthshine is reflected from its
 *     angular distribution (a cubature over the visible sunlit Earth, or
 *     the angular table's moments with OI_EARTH_REFLECT_TABLE, from 100 km up;
 *     docs/earthshine-angular.md), or, with OI_EARTH_REFLECT_MEAN, below
 *     the table or without it, as if it came from its mean incidence
 *     direction (exact in the far field).
 *  5. Cost: the model is resolved and the scene validated once; after that
 *     every position is bounded (OI_POSITION_MAX_KM), so norms skip the
 *     overflow scaling and angles between unit vectors are formed directly
 *     (oi__angle_unit), each unit vector once. docs/performance.md.
 */
int oi_illuminate(const oi_scene *scene, const oi_model *model, oi_illum *out)
{
    oi_model m;
    int st;

    if (out == NULL) return OI_ERR_NULL;
    memset(out, 0, sizeof *out);
    if (scene == NULL) return OI_ERR_NULL;
    st = oi__model_resolve(model, &m);
    if (st == OI_OK) st = oi__albedo_resolve(model, &m);
    if (st < 0) return st;
    return oi__illuminate_resolved(scene, &m, out);
}

/* The albedo model's fields, checked and copied (src/scene/scene_internal.h). Here,
 * not in oi__model_resolve: the functions without an albedo model (the
 * Sun-only build's among them) carry none of it. */
int oi__albedo_resolve(const oi_model *in, oi_model *out)
{
    if (in == NULL) return OI_OK;
#ifdef OI_NO_ALBEDO_MODELS
    (void)out;
    return in->albedo_model == OI_ALBEDO_UNIFORM ? OI_OK : OI_ERR_MODEL; /* oi_config.h */
#else
    if (in->albedo_model != OI_ALBEDO_UNIFORM && in->albedo_model != OI_ALBEDO_KNOCKE &&
        in->albedo_model != OI_ALBEDO_MAP)
        return OI_ERR_MODEL;
    if (in->albedo_model == OI_ALBEDO_MAP &&
        (in->albedo_map == NULL || in->albedo_map_n_lat < 1 ||
         in->albedo_map_n_lat > OI_ALBEDO_MAP_MAX_DIM || in->albedo_map_n_lon < 1 ||
         in->albedo_map_n_lon > OI_ALBEDO_MAP_MAX_DIM))
        return OI_ERR_MODEL;
    out->albedo_model = in->albedo_model;
    out->albedo_map = in->albedo_map;
    out->albedo_map_n_lat = in->albedo_map_n_lat;
    out->albedo_map_n_lon = in->albedo_map_n_lon;
    return OI_OK;
#endif
}

/* oi_illuminate after the model's resolution (the batch calls it once per
 * batch, src/batch/batch.c); out is zeroed here too. */
int oi__illuminate_resolved(const oi_scene *scene, const oi_model *m, oi_illum *out)
{
    return scene_terms(scene, m, OI_BATCH_SCENE_ALL, out);
}
