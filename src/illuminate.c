/* SPDX-License-Identifier: MIT */
/* illuminate.c: oi_illuminate, light on the target from Sun, Earth and Moon,
 * and the flux the target sends to an observer. */
#include "oi_internal.h"

/* Solar irradiance (W/m^2) at distance d_km from the Sun. */
static oi_real solar_irradiance(const oi_model *m, oi_real d_km)
{
    oi_real q = m->au_km / d_km;
    return m->tsi_w_m2 * q * q;
}

static int check_scalar(oi_real value, oi_real lo, oi_real hi, int range_error)
{
    if (!OI_ISFINITE(value)) return OI_ERR_NONFINITE;
    if (value < lo || value > hi) return range_error;
    return OI_OK;
}

static int too_far(const oi_real v[3])
{
    return oi__norm(v) > (oi_real)OI_POSITION_MAX_KM;
}

/* Validation of everything in the scene that does not need geometry. */
static int check_scene(const oi_scene *s, const oi_model *m)
{
    int st;
    unsigned available = OI_TERM_SUN | OI_TERM_EARTH;
#ifndef OI_NO_MOON
    available |= OI_TERM_MOON;
#endif
    if (s->terms & ~available) return OI_ERR_TERMS;
    if (!oi__finite3(s->sun_km) || !oi__finite3(s->target_km)) return OI_ERR_NONFINITE;
    if ((s->terms & OI_TERM_MOON) && !oi__finite3(s->moon_km)) return OI_ERR_NONFINITE;
    if (s->has_observer && !oi__finite3(s->observer_km)) return OI_ERR_NONFINITE;
    st = check_scalar(s->earth_albedo, (oi_real)0, (oi_real)1, OI_ERR_ALBEDO);
    if (st == OI_OK) st = check_scalar(s->target_albedo, (oi_real)0, (oi_real)1, OI_ERR_ALBEDO);
    if (st != OI_OK) return st;
    if (!OI_ISFINITE(s->target_radius_m)) return OI_ERR_NONFINITE;
    if (!(s->target_radius_m > (oi_real)0)) return OI_ERR_RADIUS;
    if (oi__norm(s->sun_km) == (oi_real)0 || oi__norm(s->target_km) == (oi_real)0)
        return OI_ERR_ZERO_VECTOR;
    if ((s->terms & OI_TERM_MOON) && oi__norm(s->moon_km) == (oi_real)0) return OI_ERR_ZERO_VECTOR;
    if (s->has_observer && oi__norm(s->observer_km) == (oi_real)0) return OI_ERR_ZERO_VECTOR;
    /* Bounded positions keep every difference and square finite. */
    if (too_far(s->sun_km) || too_far(s->target_km) ||
        ((s->terms & OI_TERM_MOON) && too_far(s->moon_km)) ||
        (s->has_observer && too_far(s->observer_km)))
        return OI_ERR_GEOMETRY;
    if (oi__norm(s->target_km) <= m->earth_radius_km) return OI_ERR_BELOW_SURFACE;
    if (s->has_observer && oi__norm(s->observer_km) <= m->earth_radius_km)
        return OI_ERR_BELOW_SURFACE;
    return OI_OK;
}

/* Mean incidence direction of earthshine: psi from the nadir towards the Sun
 * side, in the Sun-Earth-target plane. */
static void earth_direction(const oi_real target[3], const oi_real sun[3], oi_real psi,
                            oi_real dir[3])
{
    oi_real r_hat[3], s_hat[3], t[3], along;
    int i;
    oi__unit(target, r_hat);
    oi__unit(sun, s_hat);
    along = oi__dot(s_hat, r_hat);
    for (i = 0; i < 3; i++) t[i] = s_hat[i] - along * r_hat[i];
    /* On the Sun-Earth axis the plane is undefined, and psi is 0 by symmetry. */
    if (oi__unit(t, t) == (oi_real)0) psi = (oi_real)0;
    for (i = 0; i < 3; i++) dir[i] = -OI_COS(psi) * r_hat[i] + OI_SIN(psi) * t[i];
}

#ifndef OI_NO_MOON
/* Scalar irradiance of moonlight at the target; moon_fraction is the fraction
 * of sunlight reaching the Moon. */
static int moon_irradiance(const oi_scene *s, const oi_model *m, oi_real *e_moon,
                           oi_real dir[3], oi_real *moon_fraction)
{
    oi_shadow moon_shadow;
    oi_real to_sun[3], to_target[3], d_sun, d_target, alpha, ratio;
    int st = oi__sun_shadow(s->sun_km, s->moon_km, m, &moon_shadow, NULL);
    if (st < 0) return st;
    oi__sub(s->sun_km, s->moon_km, to_sun);
    oi__sub(s->target_km, s->moon_km, to_target);
    d_sun = oi__norm(to_sun);
    d_target = oi__unit(to_target, dir);
    if (!(d_target > m->moon_radius_km)) return OI_ERR_GEOMETRY;
    dir[0] = -dir[0];
    dir[1] = -dir[1];
    dir[2] = -dir[2];
    alpha = oi_angle(to_sun, to_target);
    *moon_fraction = moon_shadow.fraction_atm;
    if (m->moon_model == OI_MOON_LAMBERT) {
        ratio = m->moon_radius_km / d_target;
        *e_moon = solar_irradiance(m, d_sun) * m->moon_albedo * ratio * ratio *
                  oi_lambert_phase(alpha);
    } else {
        /* Full Moon at mean distance and 1 AU: V = OI_MOON_MAG_V_FULL; scale by
         * both inverse squares and the phase law (Krisciunas & Schaefer 1991). */
        ratio = (oi_real)OI_MOON_MEAN_DISTANCE_KM / d_target;
        *e_moon = solar_irradiance(m, d_sun) *
                  OI_POW(OI_R(10.0), OI_R(-0.4) * (oi_real)(OI_MOON_MAG_V_FULL - OI_SUN_MAG_V)) *
                  ratio * ratio * oi_moon_phase_law(alpha);
    }
    *e_moon *= *moon_fraction;
    return OI_OK;
}
#endif

/* Flux at the observer from a Lambertian sphere lit by irradiance e from
 * direction dir: F = e albedo a^2 p(xi) / d^2. */
static oi_real reflected_flux(oi_real e, const oi_real dir[3], const oi_real to_observer[3],
                              oi_real radius_over_range, oi_real albedo, oi_real *phase)
{
    *phase = oi_angle(dir, to_observer);
    if (!(e > (oi_real)0)) return (oi_real)0;
    return e * albedo * radius_over_range * radius_over_range * oi_lambert_phase(*phase);
}

/*
 * oi_illuminate: see include/orbillum.h.
 * Notes:
 *  1. Sun: e_sun = TSI (AU / |sun - target|)^2 * shadow.fraction_atm, where
 *     fraction_atm is the uniform-disc fraction, or the limb-darkened one with
 *     OI_LIMB_DARKENED, or the atmosphere's when compiled in and enabled;
 *     in the shadow, dir_sun is then the mean direction of the refracted light.
 *  2. Earth: e_earth = earth_albedo * TSI (AU/|sun|)^2 * phi(theta, h).
 *  3. Moon: the Moon is lit by the fraction of the Sun it sees (so it darkens
 *     in the Earth's shadow). The Moon's own shadow on the target (solar
 *     eclipses by the Moon) is not modelled.
 *  4. The target is a Lambertian sphere; earthshine is reflected as if it came
 *     from its mean incidence direction (exact in the far field).
 */
int oi_illuminate(const oi_scene *scene, const oi_model *model, oi_illum *out)
{
    oi_model m;
    oi_real e0, phi = (oi_real)0, psi = (oi_real)0, to_sun[3], sun_dir[3], sun_distance;
    int st, warn = OI_OK;

    if (out == NULL) return OI_ERR_NULL;
    memset(out, 0, sizeof *out);
    if (scene == NULL) return OI_ERR_NULL;
    st = oi__model_resolve(model, &m);
    if (st < 0) return st;
    st = check_scene(scene, &m);
    if (st < 0) return st;

    /* the Sun's direction, replaced by the refracted light's mean direction
     * where the atmosphere bends sunlight into the shadow */
    oi__sub(scene->sun_km, scene->target_km, to_sun);
    sun_distance = oi__unit(to_sun, sun_dir);
    st = oi__sun_shadow(scene->sun_km, scene->target_km, &m, &out->shadow, sun_dir);
    if (st < 0) goto fail;
    if (st > 0) warn = st;

    out->earth_theta = oi_angle(scene->sun_km, scene->target_km);
    out->earth_h_km = oi__norm(scene->target_km) - m.earth_radius_km;
    e0 = solar_irradiance(&m, oi__norm(scene->sun_km));

    if (scene->terms & OI_TERM_SUN) {
        out->e_sun = solar_irradiance(&m, sun_distance) * out->shadow.fraction_atm;
        memcpy(out->dir_sun, sun_dir, sizeof sun_dir);
    }
    if (scene->terms & OI_TERM_EARTH) {
        st = oi__earthshine(out->earth_theta, out->earth_h_km, &m, &phi, &psi);
        if (st < 0) goto fail;
        if (st > 0) warn = st;
        out->earth_phi = phi;
        out->earth_psi = psi;
        out->e_earth = scene->earth_albedo * e0 * phi;
        earth_direction(scene->target_km, scene->sun_km, psi, out->dir_earth);
    }
#ifndef OI_NO_MOON
    if (scene->terms & OI_TERM_MOON) {
        st = moon_irradiance(scene, &m, &out->e_moon, out->dir_moon, &out->moon_sun_fraction);
        if (st < 0) goto fail;
    }
#endif

    if (scene->has_observer) {
        oi_real to_obs[3], ratio;
        oi__sub(scene->observer_km, scene->target_km, to_obs);
        out->range_km = oi__norm(to_obs);
        /* radius and range in the same unit */
        ratio = scene->target_radius_m / (out->range_km * OI_R(1000.0));
        if (!(ratio < (oi_real)1)) {
            st = OI_ERR_OBSERVER_AT_TARGET;
            goto fail;
        }
        out->flux_sun = reflected_flux(out->e_sun, out->dir_sun, to_obs, ratio,
                                       scene->target_albedo, &out->phase_sun);
        out->flux_earth = reflected_flux(out->e_earth, out->dir_earth, to_obs, ratio,
                                         scene->target_albedo, &out->phase_earth);
        out->flux_moon = reflected_flux(out->e_moon, out->dir_moon, to_obs, ratio,
                                        scene->target_albedo, &out->phase_moon);
        out->flux_obs = out->flux_sun + out->flux_earth + out->flux_moon;
        out->mag_v = oi_magnitude_v(out->flux_obs, &m);
    }
    return warn;

fail:
    memset(out, 0, sizeof *out);
    return st;
}
