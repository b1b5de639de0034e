/* SPDX-License-Identifier: MIT */
/* illuminate_outputs.c: oi__illuminate_outputs, the scene batch's
 * oi_illuminate with an outputs mask (oi_illuminate_batch_outputs,
 * src/batch/batch.c), from the terms of src/scene/illuminate_terms.h, so
 * every term is formed by the single call's own code, and the single call's
 * code is not changed by a second caller of its steps (make size, make
 * stack). What the mask leaves
 * out: the shadow's angles (a target certainly lit, or certainly in the
 * umbra without the atmosphere, is answered from cosines), the
 * limb-darkened integral where the model's sunlight does not need it, and
 * the observer's term. */
#include "scene/scene_internal.h"

/* the Sun's term under the mask (below) */
static int sun_term_outputs(const oi_scene *scene, const oi_model *m, unsigned outputs,
                            oi_illum *out);
#define SCENE_SUN_TERM(scene, m, outputs, out) sun_term_outputs((scene), (m), (outputs), (out))
#include "scene/illuminate_terms.h"

/* 1 when the Moon (if its position is given) certainly leaves the Sun seen
 * from the target alone, so the shadow's angles, which the Moon's
 * occultation reads, need not be formed. */
static int moon_leaves_sun(const oi_scene *s, const oi_model *m)
{
#ifndef OI_NO_MOON
    if (moon_given(s)) return oi__moon_shadow_none(s->sun_km, s->moon_km, s->target_km, m);
#else
    (void)s;
    (void)m;
#endif
    return 1;
}

/* sun_term with the mask: the same e_sun, dir_sun and shadow fields. */
static OI_NOINLINE int sun_term_outputs(const oi_scene *scene, const oi_model *m,
                                        unsigned outputs, oi_illum *out)
{
    oi_real to_sun[3], sun_distance;
    int st = OI__ROW_UNSURE;
    if ((outputs & OI_BATCH_FRACTION_LD) && (outputs & OI_BATCH_GEOMETRY))
        return sun_term(scene, m, out);
    oi__sub(scene->sun_km, scene->target_km, to_sun);
    sun_distance = oi__unit_bounded(to_sun, to_sun);
    if (!(outputs & OI_BATCH_GEOMETRY) && moon_leaves_sun(scene, m)) {
        /* the umbra only without the atmosphere (which lights it) */
#ifndef OI_NO_ATMOSPHERE
        const int umbra_too = m->no_atmosphere != 0;
#else
        const int umbra_too = 1;
#endif
        st = oi__sun_certain_region(scene->sun_km, scene->target_km, m, umbra_too);
    }
    if (st != OI__ROW_UNSURE) {
        /* the full call's fractions there (1 or 0), its region; the light
         * comes straight from the Sun (outside the atmosphere's window, or
         * without the atmosphere) */
        const oi_real f = st == OI__ROW_LIT ? (oi_real)1 : (oi_real)0;
        out->shadow.fraction = f;
        out->shadow.fraction_atm = f;
        if (outputs & OI_BATCH_FRACTION_LD) out->shadow.fraction_ld = f;
        out->shadow.region = st == OI__ROW_LIT ? OI_SHADOW_LIT : OI_SHADOW_UMBRA;
        st = OI_OK;
    } else {
        unsigned want = OI__WANT_ATM;
        if (outputs & OI_BATCH_FRACTION_LD) want |= OI__WANT_LD;
        st = oi__sun_shadow_want(scene->sun_km, scene->target_km, m, want, &out->shadow, to_sun);
        if (st < 0) return st;
    }
    if (scene->terms & OI_TERM_SUN) {
        out->e_sun = solar_irradiance(m, sun_distance) * out->shadow.fraction_atm;
        memcpy(out->dir_sun, to_sun, sizeof to_sun);
    }
    return st;
}

/* The fields the mask leaves out, zeroed (those formed because an asked
 * output needed them). */
static void clear_unasked(unsigned outputs, oi_illum *out)
{
    if (!(outputs & OI_BATCH_FRACTION_LD)) out->shadow.fraction_ld = (oi_real)0;
    if (!(outputs & OI_BATCH_GEOMETRY)) {
        out->shadow.sun_radius_rad = out->shadow.earth_radius_rad = (oi_real)0;
        out->shadow.separation_rad = out->shadow.sun_distance_km = (oi_real)0;
    }
    if (!(outputs & OI_BATCH_DIRECTIONS)) {
        memset(out->dir_sun, 0, sizeof out->dir_sun);
        memset(out->dir_earth, 0, sizeof out->dir_earth);
        memset(out->dir_moon, 0, sizeof out->dir_moon);
        memset(out->dir_sky, 0, sizeof out->dir_sky);
    }
}

/* oi__illuminate_resolved's composition (scene_terms, src/scene/illuminate.c)
 * under the mask (src/scene/scene_internal.h); what was not asked for is cleared. */
int oi__illuminate_outputs(const oi_scene *scene, const oi_model *m, unsigned outputs,
                           oi_illum *out)
{
    const int st = scene_terms(scene, m, outputs, out);
    if (st >= 0) clear_unasked(outputs, out);
    return st;
}
