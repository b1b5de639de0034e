/* SPDX-License-Identifier: MIT */
/* illuminate_terms.h: the terms of oi_illuminate as static functions, for
 * the two units that compose them: oi_illuminate (src/scene/illuminate.c)
 * and the scene batch's oi__illuminate_outputs under an outputs mask
 * (src/scene/illuminate_outputs.c). Each unit inlines the terms as it alone
 * calls them, so the single call's code is not changed by a second caller
 * (make size, make stack). The unit defines SCENE_SUN_TERM(scene, m,
 * outputs, out), the Sun's term scene_terms calls, before it includes
 * this header. */
#ifndef OI_ILLUMINATE_TERMS_H
#define OI_ILLUMINATE_TERMS_H

#include "scene/scene_internal.h"

#ifndef SCENE_SUN_TERM
#error "define SCENE_SUN_TERM before including scene/illuminate_terms.h"
#endif

/* Solar irradiance (W/m^2) at distance d_km from the Sun. */
static oi_real solar_irradiance(const oi_model *m, oi_real d_km)
{
    return oi__solar_irradiance(m->tsi_w_m2, m->au_km, d_km);
}

static int check_scalar(oi_real value, oi_real lo, oi_real hi, int range_error)
{
    if (!OI_ISFINITE(value)) return OI_ERR_NONFINITE;
    if (value < lo || value > hi) return range_error;
    return OI_OK;
}

/* 1 when the scene gives the Moon's position (OI_TERM_MOON or has_moon; never
 * in a build with OI_NO_MOON, where has_moon is ignored). */
static int moon_given(const oi_scene *s)
{
#ifdef OI_NO_MOON
    return (s->terms & OI_TERM_MOON) != 0; /* refused by the terms check */
#else
    return (s->terms & OI_TERM_MOON) != 0 || s->has_moon != 0;
#endif
}

/* Validation of everything in the scene that does not need geometry. Each
 * position's norm is formed once (scaled: any finite input). Its own frame:
 * its registers are not saved under the terms' calls (make stack). */
static OI_NOINLINE int check_scene(const oi_scene *s, const oi_model *m)
{
    int st;
    const int moon = moon_given(s), obs = s->has_observer != 0;
    const oi_real far = (oi_real)OI_POSITION_MAX_KM;
    oi_real n_sun, n_target, n_moon, n_obs;
    unsigned available = OI_TERM_SUN | OI_TERM_EARTH;
#ifndef OI_NO_MOON
    available |= OI_TERM_MOON;
#endif
#ifndef OI_NO_SKYLIGHT
    available |= OI_TERM_SKY;
#endif
    if (s->terms & ~available) return OI_ERR_TERMS;
    if (!oi__finite3(s->sun_km) || !oi__finite3(s->target_km)) return OI_ERR_NONFINITE;
    if (moon && !oi__finite3(s->moon_km)) return OI_ERR_NONFINITE;
    if (obs && !oi__finite3(s->observer_km)) return OI_ERR_NONFINITE;
    st = check_scalar(s->earth_albedo, (oi_real)0, (oi_real)1, OI_ERR_ALBEDO);
    if (st == OI_OK) st = check_scalar(s->target_albedo, (oi_real)0, (oi_real)1, OI_ERR_ALBEDO);
    if (st != OI_OK) return st;
    if (!OI_ISFINITE(s->target_radius_m)) return OI_ERR_NONFINITE;
    if (!(s->target_radius_m > (oi_real)0)) return OI_ERR_RADIUS;
    /* a term that is off counts as a valid position */
    n_sun = oi__norm(s->sun_km);
    n_target = oi__norm(s->target_km);
    n_moon = moon ? oi__norm(s->moon_km) : (oi_real)1;
    n_obs = obs ? oi__norm(s->observer_km) : far;
    if (n_sun == (oi_real)0 || n_target == (oi_real)0 || n_moon == (oi_real)0 ||
        n_obs == (oi_real)0)
        return OI_ERR_ZERO_VECTOR;
    /* Bounded positions keep every difference and square finite. */
    if (n_sun > far || n_target > far || n_moon > far || n_obs > far) return OI_ERR_GEOMETRY;
#ifndef OI_NO_OBLATE
    if (m->earth_shape == OI_EARTH_WGS84) {
        /* inside or on the ellipsoid (src/shadow/oblate.c) */
        if (!oi__oblate_outside(s->target_km, m->earth_radius_km) ||
            (obs && !oi__oblate_outside(s->observer_km, m->earth_radius_km)))
            return OI_ERR_BELOW_SURFACE;
    } else
#endif
    if (n_target <= m->earth_radius_km || n_obs <= m->earth_radius_km)
        return OI_ERR_BELOW_SURFACE;
    /* what the albedo model reads of the scene (model.c refuses the models
     * when they are compiled out) */
    if (s->terms & OI_TERM_EARTH) {
        if (m->albedo_model == OI_ALBEDO_KNOCKE) {
            if (!OI_ISFINITE(s->epoch_jd)) return OI_ERR_NONFINITE;
            if (!(s->epoch_jd >= (oi_real)OI_EPOCH_JD_MIN && s->epoch_jd <= (oi_real)OI_EPOCH_JD_MAX))
                return OI_ERR_INPUT;
        } else if (m->albedo_model == OI_ALBEDO_MAP) {
            if (!OI_ISFINITE(s->earth_rotation_rad)) return OI_ERR_NONFINITE;
            if (OI_FABS(s->earth_rotation_rad) > (oi_real)OI_EARTH_ROTATION_MAX_RAD)
                return OI_ERR_INPUT;
        }
    }
    if (s->shape != NULL) {
#ifdef OI_NO_FACETS
        return OI_ERR_SHAPE;
#else
        return oi__shape_scene_check(s);
#endif
    }
    return OI_OK;
}

/* Mean incidence direction of earthshine: psi from the nadir towards the Sun
 * side, in the Sun-Earth-target plane (r_hat, s_hat: unit vectors from the
 * Earth's centre to the target and to the Sun). */
static void earth_direction(const oi_real r_hat[3], const oi_real s_hat[3], oi_real psi,
                            oi_real dir[3])
{
    oi_real t[3], along, c, s;
    int i;
    along = oi__dot(s_hat, r_hat);
    for (i = 0; i < 3; i++) t[i] = s_hat[i] - along * r_hat[i];
    /* On the Sun-Earth axis the plane is undefined, and psi is 0 by symmetry. */
    if (oi__unit_bounded(t, t) == (oi_real)0) psi = (oi_real)0;
    OI_SINCOS(psi, &s, &c);
    for (i = 0; i < 3; i++) dir[i] = -c * r_hat[i] + s * t[i];
}

#ifndef OI_NO_MOON
/* 10^(-0.4 (OI_MOON_MAG_V_FULL - OI_SUN_MAG_V)) = 10^(-0.4 x 14.01), the full
 * Moon's irradiance over the Sun's (mpmath, 30 digits; checked against pow in
 * tests/c/test_illuminate.c). */
#define MOON_FULL_OVER_SUN OI_R(2.48885731828238908997e-6)

/*
 * 1 when a point is certainly in full sunlight, the atmosphere included:
 * the angle sep between the Sun's centre and the anti-centre of the Earth
 * exceeds the sum of the Sun's apparent radius and that of the Earth
 * enlarged by OI__GRAZING_TOP_KM, by a margin of 1e-6 in cosine (far beyond
 * rounding). Compared as cosines (cos is decreasing on [0, pi], both radii
 * are below asin(0.9) so their sum is below pi): no inverse trigonometry.
 * Then oi__sun_shadow would return the LIT region and a fraction of exactly
 * 1 (the atmosphere's window lies inside the enlarged disc), so the caller
 * may skip it. 0 means "not certain": compute the shadow.
 *   u_sun    unit vector from the point to the Sun, d_sun its distance
 *   point    the point (Earth-centred), d_point its distance
 */
static int certainly_lit(const oi_real u_sun[3], oi_real d_sun, const oi_real point[3],
                         oi_real d_point, const oi_model *m)
{
    oi_real sin_e = (m->earth_radius_km + OI__GRAZING_TOP_KM) / d_point;
    oi_real sin_s = m->sun_radius_km / d_sun;
    oi_real cos_e, cos_s, cos_sep;
    if (!(sin_e < OI_R(0.9)) || !(sin_s < OI_R(0.9))) return 0;
    cos_e = OI_SQRT(((oi_real)1 - sin_e) * ((oi_real)1 + sin_e));
    cos_s = OI_SQRT(((oi_real)1 - sin_s) * ((oi_real)1 + sin_s));
    cos_sep = -oi__dot(u_sun, point) / d_point;
    return cos_sep < cos_e * cos_s - sin_e * sin_s - OI_R(1e-6);
}

/* certainly_lit for the Moon (its own frame, not live during the shadow call). */
static OI_NOINLINE int moon_certainly_lit(const oi_scene *s, const oi_model *m)
{
    oi_real to_sun[3], d_sun;
    oi__sub(s->sun_km, s->moon_km, to_sun);
    d_sun = oi__unit_bounded(to_sun, to_sun);
    /* the Moon at or inside the Sun is not certain: the shadow's own call
     * gives its error (OI_ERR_GEOMETRY), without a division by d_sun = 0 */
    if (!(d_sun > m->sun_radius_km)) return 0;
    return certainly_lit(to_sun, d_sun, s->moon_km, oi__norm_bounded(s->moon_km), m);
}

/* Fraction of sunlight reaching the Moon. Called from oi_illuminate itself
 * with only the shadow's result in its frame: the shadow call's chain is the
 * deepest of oi_illuminate (make stack). */
static OI_NOINLINE int moon_sun_fraction(const oi_scene *s, const oi_model *m,
                                         oi_real *moon_fraction)
{
    oi_shadow moon_shadow;
    int st;
    if (moon_certainly_lit(s, m)) {
        *moon_fraction = (oi_real)1;
        return OI_OK;
    }
    st = oi__sun_shadow(s->sun_km, s->moon_km, m, &moon_shadow, NULL);
    if (st < 0) return st;
    *moon_fraction = moon_shadow.fraction_atm;
    return OI_OK;
}

/* Scalar irradiance of moonlight at the target before the Earth's shadow
 * and hiding (moon_visible_term), and its direction. */
static OI_NOINLINE int moon_term(const oi_scene *s, const oi_model *m, oi_illum *out)
{
    oi_real u_sun[3], to_target[3], d_sun, d_target, alpha, ratio, e_moon;
    oi_real *dir = out->dir_moon;
    oi__sub(s->sun_km, s->moon_km, u_sun);
    d_sun = oi__unit_bounded(u_sun, u_sun);
    oi__sub(s->target_km, s->moon_km, to_target);
    d_target = oi__unit(to_target, dir);
    if (!(d_target > m->moon_radius_km)) return OI_ERR_GEOMETRY;
    alpha = oi__angle_unit(u_sun, dir);
    dir[0] = -dir[0];
    dir[1] = -dir[1];
    dir[2] = -dir[2];
    if (m->moon_model == OI_MOON_LAMBERT) {
        ratio = m->moon_radius_km / d_target;
        e_moon = solar_irradiance(m, d_sun) * m->moon_albedo * ratio * ratio *
                 oi_lambert_phase(alpha);
    } else {
        /* Full Moon at mean distance and 1 AU: V = OI_MOON_MAG_V_FULL; scale by
         * both inverse squares and the phase law (Krisciunas & Schaefer 1991):
         * 10^(-0.4 (V_full - V_sun)) = MOON_FULL_OVER_SUN. */
        ratio = (oi_real)OI_MOON_MEAN_DISTANCE_KM / d_target;
        e_moon = solar_irradiance(m, d_sun) * MOON_FULL_OVER_SUN * ratio * ratio *
                 oi_moon_phase_law(alpha);
    }
    out->e_moon = e_moon; /* times the fractions in moon_visible_term */
    return OI_OK;
}

/* 1 when the Moon's disc seen from the target is certainly clear of the
 * sphere of the Earth and its air (radius R + OI_MOON_AIR_TOP_KM), where
 * oi__moon_disc_visible is exactly 1 (its apparent radii, angle and tests
 * would all say so): the angle sep between the Moon's centre and the
 * Earth's exceeds the sum of their apparent radii rm + rt (each below
 * pi/2) by more than 1e-4 rad, tested on the cosines, cos sep < cos(rm +
 * rt) - 1e-4:
 *   a.b + Rm Rt < sqrt(a^2 - Rm^2) sqrt(b^2 - Rt^2) - 1e-4 |a| |b|
 * (a, b the vectors to the Moon's centre and the Earth's; one dot product
 * and four square roots instead of four arctangents). The margin is far
 * beyond the rounding of either side in both precisions. Not decided for
 * the ellipsoid (its silhouette's margin is its own). */
static int moon_certainly_clear(const oi_scene *s, const oi_model *m)
{
    oi_real a[3], b[3], a2, b2;
    const oi_real rm = m->moon_radius_km, rt = m->earth_radius_km + OI_MOON_AIR_TOP_KM;
    if (m->earth_shape != OI_EARTH_SPHERE) return 0;
    oi__sub(s->moon_km, s->target_km, a);
    b[0] = -s->target_km[0];
    b[1] = -s->target_km[1];
    b[2] = -s->target_km[2];
    a2 = oi__dot(a, a);
    b2 = oi__dot(b, b);
    if (!(a2 > rm * rm) || !(b2 > rt * rt)) return 0;
    return oi__dot(a, b) + rm * rt <
           OI_SQRT(a2 - rm * rm) * OI_SQRT(b2 - rt * rt) - OI_R(1e-4) * OI_SQRT(a2) * OI_SQRT(b2);
}

/* The part of the Moon's disc the Earth's solid body hides from the target
 * (the Earth's shadow on the Moon is in moon_sun_fraction), and e_moon with
 * both fractions: after moon_term, in a frame of its own (the occultation's
 * chain does not carry moon_term's). */
static OI_NOINLINE void moon_visible_term(const oi_scene *s, const oi_model *m, oi_illum *out)
{
    oi_real to_target[3];
    if (moon_certainly_clear(s, m)) {
        out->moon_disc_visible = (oi_real)1;
    } else {
        oi__sub(s->target_km, s->moon_km, to_target);
        out->moon_disc_visible = oi__moon_disc_visible(s->target_km, out->dir_moon,
                                                       oi__norm(to_target), m);
    }
    out->e_moon = out->e_moon * out->moon_sun_fraction * out->moon_disc_visible;
}

/* The Moon's shadow on the target: the shadow's fractions with the Moon as a
 * second occulter, and e_sun with them (its own frame, after sun_term's). */
static OI_NOINLINE int moon_shadow_term(const oi_scene *s, const oi_model *m, oi_illum *out)
{
    int st;
    oi_real before = out->shadow.fraction_atm;
#ifndef OI_NO_OBLATE
    if (m->earth_shape == OI_EARTH_WGS84) {
        if (!oi__oblate_outside(s->moon_km, m->earth_radius_km)) return OI_ERR_BELOW_SURFACE;
    } else
#endif
    if (!(oi__dot(s->moon_km, s->moon_km) > m->earth_radius_km * m->earth_radius_km))
        return OI_ERR_BELOW_SURFACE;
    st = oi__moon_shadow(s->sun_km, s->moon_km, s->target_km, m, &out->shadow,
                         &out->sun_moon_hidden);
    if (st < 0) return st;
    if ((s->terms & OI_TERM_SUN) && out->shadow.fraction_atm != before)
        out->e_sun = solar_irradiance(m, out->shadow.sun_distance_km) * out->shadow.fraction_atm;
    return OI_OK;
}
#endif

/* Flux at the observer from a Lambertian sphere lit by irradiance e from
 * the unit direction dir: F = e albedo a^2 p(xi) / d^2 (obs_hat: unit vector
 * from the target to the observer). */
static oi_real reflected_flux(oi_real e, const oi_real dir[3], const oi_real obs_hat[3],
                              oi_real radius_over_range, oi_real albedo, oi_real *phase)
{
    oi_real c[3], cos_xi, sin_xi;
    oi__cross(dir, obs_hat, c);
    sin_xi = oi__norm_bounded(c);
    cos_xi = oi__dot(dir, obs_hat);
    *phase = OI_ATAN2(sin_xi, cos_xi);
    if (!(e > (oi_real)0)) return (oi_real)0;
    /* dir and obs_hat are unit vectors to rounding: cos and sin of the
     * phase angle to a few ulp, as accurate as OI_COS/OI_SIN of the angle */
    return e * albedo * radius_over_range * radius_over_range *
           oi__lambert_phase_cs(*phase, cos_xi, sin_xi);
}

/* The unit vector from the target to the Sun. */
static OI_NOINLINE void sun_direction(const oi_scene *scene, oi_real dir[3])
{
    oi__sub(scene->sun_km, scene->target_km, dir);
    (void)oi__unit_bounded(dir, dir);
}

/* e_sun from the shadow's fraction and |sun - target| formed as in
 * sun_direction; dir_sun zeroed when the Sun's term is off. */
static OI_NOINLINE void sun_irradiance(const oi_scene *scene, const oi_model *m, oi_illum *out)
{
    oi_real to_sun[3];
    if (!(scene->terms & OI_TERM_SUN)) {
        memset(out->dir_sun, 0, sizeof out->dir_sun);
        return;
    }
    oi__sub(scene->sun_km, scene->target_km, to_sun);
    out->e_sun = solar_irradiance(m, oi__norm_bounded(to_sun)) * out->shadow.fraction_atm;
}

/* The Sun's term and the shadow: e_sun, dir_sun, shadow (its own frame: the
 * shadow call's chain is the deepest of oi_illuminate). The direction is
 * formed in dir_sun itself and the distance again after the shadow, so that
 * nothing of this frame but pointers is live during that call. */
static OI_NOINLINE int sun_term(const oi_scene *scene, const oi_model *m, oi_illum *out)
{
    int st;
    /* the Sun's direction, replaced by the refracted light's mean direction
     * where the atmosphere bends sunlight into the shadow */
    sun_direction(scene, out->dir_sun);
    st = oi__sun_shadow(scene->sun_km, scene->target_km, m, &out->shadow, out->dir_sun);
    if (st >= 0) sun_irradiance(scene, m, out);
    return st;
}

#ifndef OI_NO_ALBEDO_MODELS
/* The albedo job's geometry and field (its own frame). */
static OI_NOINLINE void albedo_job_init(const oi_scene *scene, const oi_model *m,
                                        oi__albedo_job *job)
{
    const oi_real r_target = oi__unit_bounded(scene->target_km, job->r_hat);
    (void)oi__unit_bounded(scene->sun_km, job->s_hat);
    job->x = m->earth_radius_km / r_target;
    oi__albedo_field_init(m, scene, &job->f);
    job->has_obs = 0;
    if (scene->has_observer) {
        oi__sub(scene->observer_km, scene->target_km, job->obs_hat);
        job->has_obs = oi__unit(job->obs_hat, job->obs_hat) > (oi_real)0;
    }
}

/* The albedo field's mean (earth_albedo_eff, then e_earth with it) and its
 * change of dir_earth and of the sphere's shape (*shape_add),
 * src/sources/earthshine_albedo.c. Called after earth_term, in a frame of its own
 * (make stack: the cubature's chain is the deepest of oi_illuminate) that
 * holds the job, the only copy of its inputs and sums under the integrators. */
static OI_NOINLINE int albedo_field_term(const oi_scene *scene, const oi_model *m,
                                         oi_illum *out, oi_real *shape_add)
{
    oi__albedo_job job;
    int st;
    albedo_job_init(scene, m, &job);
    st = oi__albedo_integrate(&job);
    if (st < 0) return st;
    oi__albedo_mean(&job, &out->earth_albedo_eff, out->dir_earth, shape_add);
    out->e_earth = out->earth_albedo_eff * solar_irradiance(m, oi__norm_bounded(scene->sun_km)) *
                   out->earth_phi;
    return OI_OK;
}
#endif

/* theta, h and the Earth's term of the uniform sphere: e_earth, dir_earth,
 * earth_phi, earth_psi, earth_albedo_eff. */
static OI_NOINLINE int earth_term(const oi_scene *scene, const oi_model *m, oi_illum *out)
{
    oi_real s_hat[3], r_hat[3], c[3], cos_theta, sin_theta, phi, psi;
    int st = OI_OK;
    const oi_real d_sun = oi__unit_bounded(scene->sun_km, s_hat);
    const oi_real r_target = oi__unit_bounded(scene->target_km, r_hat);
    oi__cross(s_hat, r_hat, c);
    sin_theta = oi__norm_bounded(c);
    cos_theta = oi__dot(s_hat, r_hat);
    out->earth_theta = OI_ATAN2(sin_theta, cos_theta);
    out->earth_h_km = r_target - m->earth_radius_km;
#ifndef OI_NO_OBLATE
    /* the ellipsoid: the height above its geocentric radius under the target
     * (the earthshine table's sphere of that radius) */
    if (m->earth_shape == OI_EARTH_WGS84)
        out->earth_h_km = r_target - oi__oblate_geocentric_radius(scene->target_km,
                                                                  m->earth_radius_km);
#endif
    if (scene->terms & OI_TERM_EARTH) {
        st = oi__earthshine(out->earth_theta, cos_theta, sin_theta, out->earth_h_km, m, &phi,
                            &psi);
        if (st < 0) return st;
        out->earth_phi = phi;
        out->earth_psi = psi;
        out->earth_albedo_eff = scene->earth_albedo;
        earth_direction(r_hat, s_hat, psi, out->dir_earth);
        out->e_earth = out->earth_albedo_eff * solar_irradiance(m, d_sun) * phi;
    }
    return st;
}

#ifndef OI_NO_SKYLIGHT
/* The scattered sunlight's term: e_sky and dir_sky from the sky table at
 * theta (out->earth_theta) and the target's distance. */
static OI_NOINLINE int sky_term(const oi_scene *scene, const oi_model *m, oi_illum *out)
{
    const oi_sky_table *t;
    oi_real s_hat[3], r_hat[3], e_over_sun, psi;
    int st = oi__sky_table_of(m, &t);
    /* without an atmosphere nothing scatters sunlight (e_sky stays 0) */
    if (st < 0 || t == NULL || m->no_atmosphere) return st;
    {
        const oi_real d_sun = oi__unit_bounded(scene->sun_km, s_hat);
        const oi_real r_target = oi__unit_bounded(scene->target_km, r_hat);
        st = oi__sky_lookup(t, out->earth_theta, r_target, &e_over_sun, &psi);
        out->e_sky = solar_irradiance(m, d_sun) * e_over_sun;
    }
    if (out->e_sky > (oi_real)0) earth_direction(r_hat, s_hat, psi, out->dir_sky);
    return st;
}
#endif

/* The target's radius over its range from the observer (both in metres). */
static oi_real radius_over_range(const oi_scene *scene, const oi_illum *out)
{
    return scene->target_radius_m / (out->range_km * OI_R(1000.0));
}

#if !defined(OI_NO_EARTH_ANGULAR) && !defined(OI_NO_EARTH_TABLE)
/* The observer's direction in the target's local frame (o) and the Sun's
 * angle theta from the zenith (cs: cosine, sine): in a frame of its own, so
 * that the frame's vectors are not on the stack while the cubature runs. */
static OI_NOINLINE void sphere_local(const oi_scene *scene, const oi_real obs_hat[3],
                                     oi_real o[3], oi_real cs[2])
{
    oi_real r_hat[3], s_hat[3], x[3], y[3], c[3];
    oi__local_frame_toward(scene->target_km, scene->sun_km, obs_hat, r_hat, s_hat, x, y);
    oi__cross(s_hat, r_hat, c);
    cs[1] = oi__norm_bounded(c);
    cs[0] = oi__dot(s_hat, r_hat);
    o[0] = oi__dot(obs_hat, x);
    o[1] = oi__dot(obs_hat, y);
    o[2] = oi__dot(obs_hat, r_hat);
}

/* The earthshine a Lambertian sphere sends towards the observer from its
 * angular distribution (the cubature, or the table's moments with
 * OI_EARTH_REFLECT_TABLE: src/sources/earthshine_angular.c), in place of
 * observer_term's flux from the mean direction where the table serves (not
 * below 100 km, nor for a shape, whose facets replace it; phase_earth stays
 * the mean direction's). Called from scene_terms after observer_term, in a
 * frame of its own. */
static OI_NOINLINE void earth_flux_moments(const oi_scene *scene, const oi_model *m,
                                           oi_real shape_add, oi_illum *out)
{
    oi_real obs_hat[3], o[3], cs[2], shape, ratio;
    if (oi__earth_angular_of(m) == NULL || !(out->e_earth > (oi_real)0) || scene->shape != NULL)
        return;
    (void)oi__observer_direction(scene, obs_hat);
    sphere_local(scene, obs_hat, o, cs);
    if (!oi__earth_sphere_shape(m, out->earth_theta, cs[0], cs[1], out->earth_h_km,
                                m->earth_radius_km, o, out->earth_phi, &shape))
        return;
    /* the albedo field's change (0 when uniform), the sum kept non-negative */
    shape += shape_add;
    if (shape < (oi_real)0) shape = (oi_real)0;
    ratio = radius_over_range(scene, out);
    out->flux_earth = out->e_earth * scene->target_albedo * ratio * ratio * shape;
}
#endif

/* What the observer receives from the sphere: range, phase angles, fluxes
 * from each source's direction. */
static OI_NOINLINE int observer_term(const oi_scene *scene, oi_illum *out)
{
    oi_real obs_hat[3], ratio;
    out->range_km = oi__observer_direction(scene, obs_hat);
    /* the observer inside the target's sphere (range 0 included) found
     * before the ratio is formed: no division by zero, no overflow */
    if (!(out->range_km * OI_R(1000.0) > scene->target_radius_m)) return OI_ERR_OBSERVER_AT_TARGET;
    /* radius and range in the same unit */
    ratio = radius_over_range(scene, out);
    if (!(ratio < (oi_real)1)) return OI_ERR_OBSERVER_AT_TARGET;
#ifndef OI_NO_FACETS
    /* a shape's facets send area / range^2: the observer farther than the
     * shape's size, sqrt of its whole area, keeps that at most 1 */
    if (scene->shape != NULL) {
        const oi_real range_m = out->range_km * OI_R(1000.0);
        oi_real area = (oi_real)0;
        unsigned i;
        for (i = 0; i < scene->shape->n_facets && i < (unsigned)OI_FACETS_MAX; i++)
            area += scene->shape->facets[i].area_m2;
        if (!(range_m * range_m > area)) return OI_ERR_OBSERVER_AT_TARGET;
    }
#endif
    out->flux_sun = reflected_flux(out->e_sun, out->dir_sun, obs_hat, ratio,
                                   scene->target_albedo, &out->phase_sun);
    out->flux_earth = reflected_flux(out->e_earth, out->dir_earth, obs_hat, ratio,
                                     scene->target_albedo, &out->phase_earth);
    out->flux_moon = reflected_flux(out->e_moon, out->dir_moon, obs_hat, ratio,
                                    scene->target_albedo, &out->phase_moon);
#ifndef OI_NO_SKYLIGHT
    /* without scattered light dir_sky is zero and so is its phase angle (not
     * atan2 of a signed zero) */
    if (out->e_sky > (oi_real)0)
        out->flux_sky = reflected_flux(out->e_sky, out->dir_sky, obs_hat, ratio,
                                       scene->target_albedo, &out->phase_sky);
#endif
    return OI_OK;
}


/* The scene's terms in their order, once for both callers: oi_illuminate's
 * (oi__illuminate_resolved, every output) and the batch's under an outputs
 * mask (oi__illuminate_outputs, src/scene/illuminate_outputs.c: the Sun's term
 * through sun_term_outputs, the observer's only when asked). out is zeroed
 * first and again on an error. */
static int scene_terms(const oi_scene *scene, const oi_model *m, unsigned outputs, oi_illum *out)
{
    int st, warn = OI_OK;
    oi_real shape_add = (oi_real)0;

    memset(out, 0, sizeof *out);
    st = check_scene(scene, m);
    if (st < 0) return st;

    st = SCENE_SUN_TERM(scene, m, outputs, out);
    if (st < 0) goto fail;
    if (st > 0) warn = st;
#ifndef OI_NO_MOON
    if (moon_given(scene)) {
        st = moon_shadow_term(scene, m, out);
        if (st < 0) goto fail;
    }
#endif
    st = earth_term(scene, m, out);
    if (st < 0) goto fail;
    if (st > 0) warn = st;
#ifndef OI_NO_ALBEDO_MODELS
    if ((scene->terms & OI_TERM_EARTH) && m->albedo_model != OI_ALBEDO_UNIFORM) {
        st = albedo_field_term(scene, m, out, &shape_add);
        if (st < 0) goto fail;
    }
#endif
#ifndef OI_NO_SKYLIGHT
    if (scene->terms & OI_TERM_SKY) {
        st = sky_term(scene, m, out);
        if (st < 0) goto fail;
        if (st > 0) warn = st;
    }
#endif
#ifndef OI_NO_MOON
    if (scene->terms & OI_TERM_MOON) {
        st = moon_sun_fraction(scene, m, &out->moon_sun_fraction);
        if (st < 0) goto fail;
        st = moon_term(scene, m, out);
        if (st < 0) goto fail;
        moon_visible_term(scene, m, out);
    }
#endif
    if (scene->has_observer && (outputs & OI_BATCH_OBSERVER)) {
        st = observer_term(scene, out);
        if (st < 0) goto fail;
#if !defined(OI_NO_EARTH_ANGULAR) && !defined(OI_NO_EARTH_TABLE)
        earth_flux_moments(scene, m, shape_add, out);
#else
        (void)shape_add;
#endif
#ifndef OI_NO_FACETS
        /* a shape's facets replace the sphere's fluxes (the phase angles stay) */
        if (scene->shape != NULL) oi__shape_flux(scene, m, out);
#endif
        out->flux_obs = out->flux_sun + out->flux_earth + out->flux_moon + out->flux_sky;
        out->mag_v = oi__magnitude_v(out->flux_obs, m->tsi_w_m2);
    }
    return warn;

fail:
    memset(out, 0, sizeof *out);
    return st;
}

#endif /* OI_ILLUMINATE_TERMS_H */
