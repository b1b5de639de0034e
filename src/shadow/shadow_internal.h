/* SPDX-License-Identifier: MIT */
/*
 * shadow_internal.h: private to the runtime (not part of the API):
 * the shadow layer (src/shadow/): the Sun's visible fraction behind the
 * Earth (sphere or WGS-84) and the Moon, limb darkening, the atmosphere's
 * refracted light, the Moon's disc behind the Earth.
 * A layer calls only the layers below it (docs/architecture.md); this
 * header includes the one below, so a file sees its layer and every lower one.
 */
#ifndef OI_SHADOW_INTERNAL_H
#define OI_SHADOW_INTERNAL_H

#include "model/model_internal.h"

/* The region (OI_SHADOW_*) and the visible fractions, uniform *frac and
 * (frac_ld not NULL) limb-darkened *frac_ld, of the solar disc of apparent
 * radius rs behind a nearer disc of radius re, centres sep apart (radians):
 * the Sun behind the Earth or the Moon; with frac_ld NULL any disc behind
 * another (src/shadow/sun_fraction.c). */
int oi__disc_fractions(oi_real rs, oi_real re, oi_real sep, oi_real *frac, oi_real *frac_ld);

#ifndef OI_NO_MOON
/* The Moon's shadow on a point: sh, oi__sun_shadow's result there, gets the
 * fractions with the Moon as a second occulter; *hidden the fraction of the
 * Sun's disc area the Moon covers. OI_OK, or OI_ERR_GEOMETRY for a point in
 * the Moon (src/shadow/moon_occultation.c). */
int oi__moon_shadow(const oi_real sun_km[3], const oi_real moon_km[3],
                    const oi_real point_km[3], const oi_model *m, oi_shadow *sh,
                    oi_real *hidden);

/* The top of the air that dims the Moon's light near the Earth's limb (km
 * above the Earth's radius; src/shadow/atmosphere_moonlight.c): beyond the
 * apparent radius of that sphere oi__moon_disc_visible is the solid Earth's
 * fraction. */
#define OI_MOON_AIR_TOP_KM OI_R(100.0)

/* Fraction of the Moon's disc seen from the point that the Earth does not
 * hide; u_moon the unit vector to the Moon, dm its distance
 * (src/shadow/moon_occultation.c). */
oi_real oi__moon_disc_visible(const oi_real point_km[3], const oi_real u_moon[3], oi_real dm,
                              const oi_model *m);

#ifndef OI_NO_ATMOSPHERE
/* The fraction of the Moon's disc light (apparent radius rm, sep from the
 * Earth's centre of apparent radius re, seen from dp km) through the
 * atmosphere near the limb, in [0, solid] (solid: the solid Earth's
 * visible fraction); src/shadow/atmosphere_moonlight.c. */
oi_real oi__atm_moon_visible(oi_real dp, oi_real re, oi_real rm, oi_real sep, oi_real solid,
                             oi_real r_e);
#endif
#endif

#ifndef OI_NO_LIMB_DARKENING
/* Limb darkening is computed for OI_LD_RS_MIN < r_s <= OI_LD_RS_MAX
 * (docs/shadow.md); elsewhere the uniform disc stands in. */
#define OI_LD_RS_MAX OI_R(0.5)
#define OI_LD_RS_MIN OI_R(1e-15)

/* Visible fraction of the limb-darkened solar disc of radius rs with the
 * Earth's disc of radius re at sep: penumbra with tri the sines of
 * oi__half_sines(rs, re, sep) and pa_s = pi - (the angle at the Sun's
 * centre), or annular with tri = NULL (src/shadow/limb_darkening.c). */
oi_real oi__fraction_limb_darkened(oi_real rs, oi_real re, oi_real sep, oi_real pa_s,
                                   const oi_real *tri);

#ifndef OI_NO_MOON
/* Visible fraction of the limb-darkened solar disc (radius rs) behind two
 * discs at once (radii re, rm, centres de, dm from the Sun's, dem apart)
 * (src/shadow/limb_darkened_union.c). */
oi_real oi__fraction_ld_two(oi_real rs, oi_real re, oi_real de, oi_real rm, oi_real dm,
                            oi_real dem);
#endif
#endif

#ifndef OI_NO_OBLATE
/* The WGS-84 ellipsoid of equatorial radius a, the frame's z axis its
 * rotation axis (oi_model.earth_shape = OI_EARTH_WGS84; src/shadow/oblate.c):
 * 1 when p is outside it; its geocentric radius in the direction of p; the
 * angular radius of its silhouette seen from p along the great circle from
 * the nadir towards the unit direction s; the visible fraction of the
 * uniform disc of unit direction s and apparent radius r seen from p behind
 * it and (mo not NULL) a sphere of unit direction mo and apparent radius rm;
 * frac_ld not NULL: the limb-darkened disc's fraction there (the uniform's
 * with OI_NO_LIMB_DARKENING). */
int oi__oblate_outside(const oi_real p[3], oi_real a);
oi_real oi__oblate_geocentric_radius(const oi_real p[3], oi_real a);
oi_real oi__oblate_radius_towards(const oi_real p[3], oi_real a, const oi_real s[3]);
oi_real oi__oblate_visible(const oi_real s[3], oi_real r, const oi_real p[3], oi_real a,
                           const oi_real mo[3], oi_real rm, oi_real *frac_ld);
/* oi__oblate_visible behind the ellipsoid alone (mo NULL), on less stack. */
oi_real oi__oblate_visible_earth(const oi_real s[3], oi_real r, const oi_real p[3], oi_real a,
                                 oi_real *frac_ld);
/* Distance from o (outside) along the unit direction u to the ellipsoid,
 * or -1 when the ray misses it. */
oi_real oi__oblate_ray_hit(const oi_real o[3], const oi_real u[3], oi_real a);
#endif

/*
 * oi_sun_fraction (src/shadow/sun_fraction.c) for callers that already hold a resolved
 * model (oi__model_resolve) and non-NULL pointers: the model is not
 * validated again. When light_dir is not NULL and the atmosphere is compiled
 * in and enabled, it also returns the unit vector from the point towards
 * where the sunlight comes from on average (refracted light in the shadow;
 * the Sun's direction elsewhere). light_dir is left untouched wherever the
 * light comes straight from the Sun, and when the atmosphere is compiled out
 * or disabled, so the caller sets it to the Sun's direction first.
 */
int oi__sun_shadow(const oi_real sun_km[3], const oi_real point_km[3], const oi_model *resolved,
                   oi_shadow *out, oi_real light_dir[3]);

/* oi__sun_shadow with a choice of outputs (the batch, src/batch/batch.c):
 * OI__WANT_LD forms fraction_ld (else it equals fraction unless the
 * atmosphere or the limb-darkened model needs it), OI__WANT_ATM fraction_atm
 * and its status (else 0, the atmosphere not consulted). Every output formed
 * is the bits of oi__sun_shadow's. */
#define OI__WANT_LD (1u)
#define OI__WANT_ATM (2u)
int oi__sun_shadow_want(const oi_real sun_km[3], const oi_real point_km[3],
                        const oi_model *resolved, unsigned want, oi_shadow *out,
                        oi_real light_dir[3]);

/* The certain regions of the Sun seen from a point (src/shadow/sun_certain.c):
 * OI__ROW_LIT or OI__ROW_UMBRA (asked only with umbra_too) when the point is
 * certainly there, decided from cosines after every check of
 * oi__sun_shadow's geometry passed (its status would be OI_OK, its
 * fractions 1 or 0, the light's direction the Sun's); OI__ROW_UNSURE
 * otherwise. */
/* Margin, in cosine, of the certain-region tests (oi__sun_certain_region and
 * the batch's vectorised copy, src/batch/batch.c): far beyond the rounding
 * of the cosines and of the arctangents the full call forms (a few
 * epsilon). */
#ifdef OI_SINGLE_PRECISION
#define OI__CERTAIN_COS_MARGIN OI_R(1e-5)
#else
#define OI__CERTAIN_COS_MARGIN OI_R(1e-6)
#endif
/* Height above the Earth's surface that any sunlight grazing through the
 * atmosphere stays below (every atmosphere table's top is at most
 * OI_ATM_TOP_MAX_KM = 100 km, checked for a caller's), with a factor 2 to
 * spare: beyond it a point sees the Sun outside the atmosphere's window. */
#define OI__GRAZING_TOP_KM OI_R(200.0)
/* The radius of the sphere whose umbra is certainly the model Earth's: the
 * sphere itself, or the ellipsoid's inner sphere (its polar radius). */
static inline oi_real oi__umbra_radius(const oi_model *m)
{
    if (m->earth_shape == OI_EARTH_WGS84)
        return m->earth_radius_km * (oi_real)(1.0 - 1.0 / OI_WGS84_INV_FLATTENING);
    return m->earth_radius_km;
}
#define OI__ROW_UNSURE (0)
#define OI__ROW_LIT (1)
#define OI__ROW_UMBRA (2)
int oi__sun_certain_region(const oi_real sun[3], const oi_real p[3], const oi_model *m,
                           int umbra_too);

/* 1 when oi__moon_shadow would return OI_OK and leave the shadow as it is
 * (the Moon beyond the Sun, or the two discs certainly apart), so that the
 * shadow's angles it reads need not be formed (src/shadow/moon_occultation.c). */
int oi__moon_shadow_none(const oi_real sun_km[3], const oi_real moon_km[3],
                         const oi_real point_km[3], const oi_model *m);

#ifndef OI_NO_ATMOSPHERE
/*
 * Fraction of unobstructed sunlight reaching point_km with the atmosphere's
 * refraction and extinction (src/shadow/atmosphere.c, baked table), given the
 * geometric fractions frac (uniform disc) and frac_ld (limb-darkened) of the
 * same geometry and a resolved model. dir (may be NULL, in/out): on entry the
 * unit vector from the point to the Sun; replaced by the unit vector towards
 * where the light comes from only where refracted light arrives (inside the
 * table's window with a nonzero fraction), untouched elsewhere. Returns OI_OK
 * or OI_WARN_TABLE_RANGE (geometric fraction returned).
 */
int oi__atm_fraction(const oi_real sun_km[3], const oi_real point_km[3], const oi_model *m,
                     oi_real frac, oi_real frac_ld, oi_real *fraction_atm, oi_real dir[3]);
/* The same with the table's coordinates about a sphere of radius
 * earth_radius_km instead of m->earth_radius_km (the ellipsoid's). */
int oi__atm_fraction_about(const oi_real sun_km[3], const oi_real point_km[3], const oi_model *m,
                           oi_real earth_radius_km, oi_real frac, oi_real frac_ld,
                           oi_real *fraction_atm, oi_real dir[3]);
#endif

#endif /* OI_SHADOW_INTERNAL_H */
