/* SPDX-License-Identifier: MIT */
/*
 * orbillum/scene.h: the scene and its illumination (oi_scene, oi_illum,
 * oi_illuminate), the V magnitude of a flux and its inverse.
 *
 * A section of orbillum.h, the header a program includes (it includes every
 * section); compiles alone, and includes the sections it uses.
 */
#ifndef ORBILLUM_SCENE_H
#define ORBILLUM_SCENE_H

#include "base.h"
#include "model.h"
#include "shadow.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- scene */

typedef struct oi_scene {
    oi_real sun_km[3];       /* Sun position (km) */
    oi_real moon_km[3];      /* Moon position (km); used when OI_TERM_MOON or has_moon
                                is set */
    oi_real target_km[3];    /* target position (km) */
    oi_real observer_km[3];  /* observer position (km); used when has_observer */
    int has_observer;        /* nonzero: compute what the observer receives */
    unsigned terms;          /* OI_TERM_* mask */
    oi_real earth_albedo;    /* [0, 1] */
    oi_real target_albedo;   /* [0, 1] */
    oi_real target_radius_m; /* > 0 */
    int has_moon;            /* nonzero: moon_km is given, whatever the terms: the
                                Moon then occults the Sun (OI_TERM_MOON implies it) */
    oi_real target_vel_km_s[3];   /* target velocity (km/s, the positions' frame); read by
                                     oi_expose_scene only; zero: at rest */
    oi_real observer_vel_km_s[3]; /* observer velocity (km/s), as target_vel_km_s */
    /* The target's shape (oi_shape, docs/shapes.md). The fields stay in a
     * build with OI_NO_FACETS (the struct's layout does not change), where a
     * non-NULL shape gives OI_ERR_SHAPE. */
    const struct oi_shape *shape; /* NULL: the Lambertian sphere of target_radius_m and
                                     target_albedo; else its facets (caller-owned) */
    oi_real attitude_q[4];   /* body frame -> positions' frame, unit quaternion
                                (w, x, y, z), read with a shape only; all four zero:
                                the identity; a norm off 1 by more than 1e-6 (a
                                nonzero quaternion whose squared norm underflows,
                                (1e-300, 0, 0, 0), included), a component above 2
                                or a non-finite one: OI_ERR_SHAPE; else normalised */
    oi_real epoch_jd;        /* Julian date (UTC) of the scene, in [OI_EPOCH_JD_MIN,
                                OI_EPOCH_JD_MAX]; read only by the albedo model
                                OI_ALBEDO_KNOCKE (with OI_TERM_EARTH) */
    oi_real earth_rotation_rad; /* angle of the Greenwich meridian from the frame's x axis
                                   about its z axis (rad, |value| <= OI_EARTH_ROTATION_MAX_RAD);
                                   read only by OI_ALBEDO_MAP (with OI_TERM_EARTH) */
} oi_scene;

/* oi_scene_defaults: fill a scene with the defaults: zero positions, no
 * observer, no shape (the sphere), attitude_q zero (the identity), every
 * term compiled in, albedos OI_EARTH_ALBEDO_DEFAULT /
 * OI_TARGET_ALBEDO_DEFAULT, radius OI_TARGET_RADIUS_M_DEFAULT. A NULL scene
 * is ignored. */
void oi_scene_defaults(oi_scene *scene);

typedef struct oi_illum {
    oi_shadow shadow;        /* the Sun seen from the target */
    oi_real e_sun;           /* scalar irradiance at the target per source (W/m^2) */
    oi_real e_earth;
    oi_real e_moon;
    oi_real dir_sun[3];      /* unit vectors from the target towards where each */
    oi_real dir_earth[3];    /*   source's light comes from (Earth: mean incidence */
    oi_real dir_moon[3];     /*   direction); zero when the term is off */
    oi_real earth_theta;     /* angle at Earth centre, Sun to target (rad) */
    oi_real earth_h_km;      /* target altitude (km) */
    oi_real earth_phi;       /* normalised earthshine phi(theta, h) */
    oi_real earth_psi;       /* its mean direction angle (see oi_earthshine) */
    oi_real moon_sun_fraction; /* fraction of sunlight reaching the Moon */
    /* what the observer receives (zero without observer) */
    oi_real phase_sun;       /* phase angle at the target, per source (rad) */
    oi_real phase_earth;
    oi_real phase_moon;
    oi_real flux_sun;        /* W/m^2 at the observer from the target, per source */
    oi_real flux_earth;
    oi_real flux_moon;
    oi_real flux_obs;        /* their sum */
    oi_real mag_v;           /* apparent V magnitude of the target (OI_MAG_DARK if dark) */
    oi_real range_km;        /* observer to target */
    oi_real sun_moon_hidden; /* fraction of the Sun's disc area the Moon's disc covers
                                seen from the target (0: no Moon position, or apart) */
    oi_real moon_disc_visible; /* fraction of the Moon's disc the Earth does not hide,
                                  seen from the target, the atmosphere's extinction
                                  along the grazing lines of sight included unless
                                  no_atmosphere (with OI_TERM_MOON; else 0) */
    oi_real flux_specular;   /* part of flux_obs from the facets' specular lobes (W/m^2;
                                0 for a sphere) */
    oi_real earth_albedo_eff;  /* the albedo e_earth is formed with: earth_albedo
                                  (OI_ALBEDO_UNIFORM), else the mean of the model's
                                  albedo over the lit visible Earth weighted by its
                                  earthshine, the value under the target where none
                                  is lit (with OI_TERM_EARTH; else 0) */
    /* scattered sunlight (OI_TERM_SKY; zero when the term is off) */
    oi_real e_sky;           /* scalar irradiance at the target (W/m^2) */
    oi_real dir_sky[3];      /* unit vector towards its mean direction */
    oi_real phase_sky;       /* phase angle at the target (rad; with an observer) */
    oi_real flux_sky;        /* W/m^2 at the observer (in flux_obs) */
} oi_illum;

/*
 * oi_illuminate: light on the target from Sun, Earth and Moon, and what the
 * observer sees.
 * Given:   scene  positions (km), terms, albedos, target radius; moon_km is
 *                 read only with OI_TERM_MOON or has_moon, observer_km only
 *                 with has_observer
 *          model  NULL or model constants and options
 * Returned: out   see oi_illum (zeroed on error)
 * Returns: OI_OK; OI_WARN_TABLE_RANGE (earthshine outside its table's range,
 *          or the target beyond the atmosphere table: see oi_earthshine and
 *          oi_sun_fraction); errors (the first found; the scene's own
 *          checks come before the geometry's):
 *          OI_ERR_NULL       scene or out is NULL
 *          OI_ERR_MODEL, OI_ERR_RADIUS  the model is invalid (see oi_model)
 *          OI_ERR_TERMS      terms has bits outside OI_TERM_ALL (or
 *                            OI_TERM_MOON in a build with OI_NO_MOON)
 *          OI_ERR_NONFINITE  a component of a position read NaN or infinite
 *          then earth_albedo, then target_albedo:
 *          OI_ERR_NONFINITE  the albedo NaN or infinite
 *          OI_ERR_ALBEDO     the albedo outside [0, 1]
 *          OI_ERR_NONFINITE  target_radius_m NaN or infinite
 *          OI_ERR_RADIUS     target_radius_m <= 0
 *          OI_ERR_ZERO_VECTOR  a position read is the zero vector
 *          OI_ERR_GEOMETRY   a position read farther than OI_POSITION_MAX_KM
 *          OI_ERR_BELOW_SURFACE  |target| or |observer| <= earth_radius_km
 *          OI_ERR_NONFINITE  with OI_TERM_EARTH: epoch_jd (OI_ALBEDO_KNOCKE)
 *                            or earth_rotation_rad (OI_ALBEDO_MAP) NaN or
 *                            infinite
 *          OI_ERR_INPUT      with OI_TERM_EARTH: epoch_jd outside
 *                            [OI_EPOCH_JD_MIN, OI_EPOCH_JD_MAX] (knocke),
 *                            |earth_rotation_rad| > OI_EARTH_ROTATION_MAX_RAD
 *                            (map)
 *          OI_ERR_SHAPE      scene->shape fails oi_shape_check (its
 *                            OI_ERR_NULL for NULL facets included), the
 *                            scene's target_albedo plus a facet's
 *                            albedo_specular above 1 (diffuse_from_scene),
 *                            or a bad attitude_q (see oi_scene); any shape
 *                            in a build with OI_NO_FACETS
 *          then the Sun seen from the target (oi_sun_fraction's statuses:
 *          OI_ERR_GEOMETRY for a Sun touching the Earth or the target inside
 *          the Sun), the Sun seen from the Moon (the same; the Moon below the
 *          Earth's surface gives OI_ERR_BELOW_SURFACE), and:
 *          OI_ERR_GEOMETRY   the target inside the Moon
 *                            (|target - moon| <= moon_radius_km; with the
 *                            Moon's position given, OI_TERM_MOON or has_moon)
 *          OI_ERR_BELOW_SURFACE  the Moon at or below the Earth's surface
 *                            (its position given)
 *          OI_ERR_OBSERVER_AT_TARGET  the observer inside the target's sphere
 *                            (range <= target_radius_m), or with a shape
 *                            range^2 <= the sum of its facets' areas
 *          OI_ERR_ALBEDO     OI_ALBEDO_MAP: a map value the call reads is NaN
 *                            or outside [0, 1]
 * Notes:   e_sun = TSI (AU / |sun - target|)^2 fraction_atm;
 *          e_earth = earth_albedo TSI (AU / |sun|)^2 phi(theta, h);
 *          e_sky = TSI (AU / |sun|)^2 (E_sky / E_sun)(theta, h) (OI_TERM_SKY,
 *          oi_skylight), reflected as if from its mean direction dir_sky;
 *          e_moon from the lunar phase law (or a Lambert Moon), times the
 *          fraction of the Sun the Moon sees and the fraction of the Moon's
 *          disc the Earth does not hide from the target (moon_disc_visible).
 *          With the Moon's position given (OI_TERM_MOON or has_moon, whatever
 *          the terms) the Moon occults the Sun: shadow.fraction, fraction_ld,
 *          fraction_atm and e_sun count it (shadow.region stays the Earth's;
 *          sun_moon_hidden; docs/shadow.md section 9). The target is a Lambertian
 *          sphere; the flux at the observer is the sum over sources of
 *          e albedo (a / range)^2 p(phase), the Earth's with its angular
 *          distribution instead (model earth_reflection,
 *          oi_earthshine_sphere: e_earth albedo (a / range)^2 S, S = F / phi);
 *          phase_earth stays the angle from the mean direction.
 *          With a shape (scene->shape, docs/shapes.md) the sphere is
 *          replaced by the facets, turned by attitude_q: each facet's flux
 *          from a point source (Sun, Moon) is e cos(i) f cos(o) A / range^2
 *          (f oi_facet_brdf, i and o the angles of source and observer from
 *          its normal); from the Earth the diffuse part uses the facet's
 *          earthshine irradiance (oi_earthshine_plate, the Earth's angular
 *          distribution), the specular part that irradiance as if it came
 *          from the mean direction dir_earth. flux_sun, flux_earth and
 *          flux_moon are the facets' sums per source, flux_specular their
 *          specular part; target_radius_m is then used for the
 *          observer-at-target check only. src/scene/illuminate.c, src/target/facet.c.
 *          Albedo models (model albedo_model; docs/earthshine-albedo.md):
 *          with OI_ALBEDO_KNOCKE or OI_ALBEDO_MAP, e_earth = A TSI (AU /
 *          |sun|)^2 phi, A = earth_albedo_eff the earthshine-weighted mean
 *          albedo over the lit visible Earth, and dir_earth and the sphere's
 *          angular distribution (flux_earth) carry the field's first-order
 *          change, all from a fixed cubature used as a control variate on the
 *          uniform tables (earth_phi, earth_psi stay the uniform sphere's).
 *          src/scene/illuminate.c, src/sources/earthshine_albedo.c.
 */
int oi_illuminate(const oi_scene *scene, const oi_model *model, oi_illum *out);

/* oi_magnitude_v: apparent V magnitude of a flux at the observer (W/m^2):
 * m = OI_SUN_MAG_V - 2.5 log10(F / TSI), TSI the model's (an invalid model
 * means the defaults). Returns OI_MAG_DARK for F <= 0, non-finite F, or
 * magnitudes fainter than OI_MAG_DARK. Relative error a few epsilon. */
oi_real oi_magnitude_v(oi_real flux_w_m2, const oi_model *model);

/* oi_flux_from_magnitude: the inverse of oi_magnitude_v,
 * *flux_w_m2 = TSI 10^(-0.4 (mag_v - OI_SUN_MAG_V)) (W/m^2).
 * Returns: OI_OK; OI_ERR_NULL (flux_w_m2 NULL); OI_ERR_MODEL, OI_ERR_RADIUS
 * (invalid model); OI_ERR_MAGNITUDE (mag_v non-finite or outside
 * [OI_MAG_MIN, OI_MAG_MAX]). On error *flux_w_m2 is 0. */
int oi_flux_from_magnitude(oi_real mag_v, const oi_model *model, oi_real *flux_w_m2);

#ifdef __cplusplus
}
#endif

#endif /* ORBILLUM_SCENE_H */
