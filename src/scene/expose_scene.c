/* SPDX-License-Identifier: MIT */
/*
 * expose_scene.c: oi_expose_scene, the exposure choice from a scene and its
 * illumination: the geometric flags (Sun exclusion, Earth in the field,
 * occultation, eclipse), the background where the boresight meets the
 * Earth, the sky's (Moon, zodiacal light, starlight), and the resolved
 * target's bound on the brightest pixel; the choice itself is oi_expose's (src/camera/expose.c). The contract is in
 * include/orbillum.h; docs/camera.md explains the model.
 */
#include "scene/scene_internal.h"

#ifndef OI_NO_EXPOSURE

/* What the steps share: the model's constants, the observer's distance and
 * the boresight. */
typedef struct {
    oi_real re, au, tsi; /* Earth radius (km), AU (km), TSI (W/m^2) */
    oi_real rm, moon_albedo; /* Moon radius (km) and Lambert albedo */
    oi_real r_obs;       /* |observer| (km) */
    oi_real range;       /* |target - observer| (km) */
    oi_real b[3];        /* boresight target - observer (km) */
    oi_real bh[3];       /* its unit vector */
    int shape;           /* oi_model.earth_shape */
} scene_geom;

/* The model constants oi_expose_scene needs (oi__model_resolve's status);
 * out of line (OI_NOINLINE) so that its copy of the model is not in the frame
 * of oi_expose_scene, which is live during the choice as well. */
static OI_NOINLINE int scene_model(const oi_model *model, oi_real *re, oi_real *au, oi_real *tsi,
                                   oi_real moon[2], int *shape)
{
    oi_model m;
    int st = oi__model_resolve(model, &m);
    *shape = m.earth_shape;
    *re = m.earth_radius_km;
    *au = m.au_km;
    *tsi = m.tsi_w_m2;
    moon[0] = m.moon_radius_km;
    moon[1] = m.moon_albedo;
    return st;
}

/* Largest accepted velocity component (km/s): the speed of light, far above
 * any orbit's (and a bound that keeps differences finite in single
 * precision). */
#define SPEED_MAX_KM_S OI_R(299792.458)

static int speed_ok(const oi_real v[3])
{
    return OI_FABS(v[0]) <= SPEED_MAX_KM_S && OI_FABS(v[1]) <= SPEED_MAX_KM_S &&
           OI_FABS(v[2]) <= SPEED_MAX_KM_S;
}

/* Largest angular rate handed to oi_expose (rad/s, its limit): a faster
 * target is smeared over the whole field at any exposure anyway. */
#define RATE_MAX_RAD_S OI_R(1e3)

/* The target's angular rate seen by the observer (docs/camera.md,
 * "Motion"): the relative velocity across the line of sight over the
 * range, |(v_t - v_o) x bh| / range; 0 at rest. */
static OI_NOINLINE oi_real angular_rate(const oi_scene *scene, const scene_geom *g)
{
    oi_real v[3], c[3], w;
    oi__sub(scene->target_vel_km_s, scene->observer_vel_km_s, v);
    oi__cross(v, g->bh, c);
    w = oi__norm(c) / g->range;
    return w < RATE_MAX_RAD_S ? w : RATE_MAX_RAD_S;
}

/* The inputs checked in the order of the statuses of the contract, and the
 * boresight formed. b: the batch's set-up (the model's constants, the model
 * and the camera already valid), or NULL (the single call: both checked
 * here). */
static OI_NOINLINE int check_scene(const oi_camera *camera, const oi_scene *scene, const oi_illum *illum,
                       const oi_model *model, int use_moon, const oi__expose_scene_batch *b,
                       scene_geom *g)
{
    oi_real r_tgt, re, au, tsi, moon[2]; /* locals: g's address does not leave this file */
    int st, shape = OI_EARTH_SPHERE;
    if (!scene->has_observer) return OI_ERR_NULL;
    if (b != NULL) { /* the batch's, resolved once */
        re = b->re;
        au = b->au;
        tsi = b->tsi;
        moon[0] = b->rm;
        moon[1] = b->moon_albedo;
        shape = b->shape;
    } else if (model == NULL) { /* the default model (src/model/model.c), without a copy */
        re = (oi_real)OI_EARTH_RADIUS_KM;
        au = (oi_real)OI_AU_KM;
        tsi = (oi_real)OI_TSI_W_M2;
        moon[0] = (oi_real)OI_MOON_RADIUS_KM;
        moon[1] = (oi_real)OI_MOON_ALBEDO_DEFAULT;
    } else {
        st = scene_model(model, &re, &au, &tsi, moon, &shape);
        if (st != OI_OK) return st;
    }
    g->re = re;
    g->shape = shape;
    g->au = au;
    g->tsi = tsi;
    g->rm = moon[0];
    g->moon_albedo = moon[1];
    if (!oi__finite3(scene->sun_km) || !oi__finite3(scene->target_km) ||
        !oi__finite3(scene->observer_km) || (use_moon && !oi__finite3(scene->moon_km))) {
        return OI_ERR_NONFINITE;
    }
    if (!oi__in_closed(scene->earth_albedo, 0, OI_R(1.0)) ||
        !oi__in_closed(scene->target_albedo, 0, OI_R(1.0))) { /* quiet: NaN */
        return OI_ERR_ALBEDO;
    }
    if (!OI_ISFINITE(illum->e_sun) || !OI_ISFINITE(illum->e_earth) ||
        !OI_ISFINITE(illum->e_moon) || !OI_ISFINITE(illum->flux_obs) ||
        !OI_ISFINITE(illum->e_sky)) {
        return OI_ERR_NONFINITE;
    }
    if (illum->e_sun < 0 || illum->e_earth < 0 || illum->e_moon < 0 || illum->flux_obs < 0 ||
        illum->e_sky < 0) {
        return OI_ERR_INPUT;
    }
    if (scene->shape != NULL) {
        /* the facets' BRDF peaks bound the resolved radiance (Note 10) */
#ifdef OI_NO_FACETS
        return OI_ERR_SHAPE;
#else
        st = oi__shape_scene_check(scene);
        if (st != OI_OK) return st;
        if (!OI_ISFINITE(illum->flux_specular)) return OI_ERR_NONFINITE;
        if (illum->flux_specular < 0) return OI_ERR_INPUT;
#endif
    }
    if (b == NULL && !oi__camera_valid(camera)) return OI_ERR_CAMERA;
    g->r_obs = oi__norm(scene->observer_km);
    r_tgt = oi__norm(scene->target_km);
    if (g->r_obs == 0 ||
        (scene->sun_km[0] == 0 && scene->sun_km[1] == 0 && scene->sun_km[2] == 0)) {
        return OI_ERR_ZERO_VECTOR;
    }
    if (!oi__finite3(scene->target_vel_km_s) || !oi__finite3(scene->observer_vel_km_s)) {
        return OI_ERR_NONFINITE;
    }
    if (!speed_ok(scene->target_vel_km_s) || !speed_ok(scene->observer_vel_km_s)) {
        return OI_ERR_INPUT;
    }
#ifndef OI_NO_OBLATE
    if (g->shape == OI_EARTH_WGS84) {
        /* inside or on the ellipsoid (src/shadow/oblate.c) */
        if (!oi__oblate_outside(scene->observer_km, g->re) ||
            !oi__oblate_outside(scene->target_km, g->re))
            return OI_ERR_BELOW_SURFACE;
    } else
#endif
    if (!(g->r_obs > g->re) || !(r_tgt > g->re)) return OI_ERR_BELOW_SURFACE;
    oi__sub(scene->target_km, scene->observer_km, g->b);
    g->range = oi__unit(g->b, g->bh);
    if (g->range == 0) return OI_ERR_OBSERVER_AT_TARGET;
    return OI_OK;
}

/* Sun to boresight (Note 1): the angle is an output, so it is the atan2
 * form, by the same operations as oi_angle(sun - observer, b) (bh is its
 * unit vector of b); 0, as there, when a difference overflows or the
 * observer is at the Sun. */
static OI_NOINLINE oi_real sun_angle_of(const oi_scene *scene, const scene_geom *g)
{
    oi_real u[3], d; /* sun - observer, its unit vector, then u x bh */
    oi__sub(scene->sun_km, scene->observer_km, u);
    if (oi__finite3(g->b) && oi__finite3(u) && oi__unit(u, u) > 0) {
        d = oi__dot(u, g->bh);
        oi__cross(u, g->bh, u);
        return OI_ATAN2(oi__norm(u), d);
    }
    return 0;
}

/* Margin, in cosine, of the certain Sun-exclusion test: far beyond the
 * rounding of the cosine below and of the angle sun_angle_of forms (a few
 * epsilon). */
#ifdef OI_SINGLE_PRECISION
#define EXCL_COS_MARGIN OI_R(1e-5)
#else
#define EXCL_COS_MARGIN OI_R(1e-6)
#endif

/* OI_FLAG_SUN_EXCLUSION without the angle (the batch without
 * OI_EXPOSE_SUN_ANGLE): decided from the cosine d of sun_angle_of when it is
 * farther than EXCL_COS_MARGIN from cos_excl = cos(sun_exclusion_rad) (the
 * cosine decreases on [0, pi]), else from the angle itself. d is the cosine
 * only when both vectors are unit (the angle's atan2 form is not affected by
 * their lengths, the cosine is): a vector whose unit form lost digits
 * (subnormal differences) goes to the angle. */
static OI_NOINLINE int sun_excluded(const oi_scene *scene, const scene_geom *g, oi_real cos_excl,
                                    oi_real excl_rad)
{
    oi_real u[3], d;
    oi__sub(scene->sun_km, scene->observer_km, u);
    if (oi__finite3(g->b) && oi__finite3(u) && oi__unit(u, u) > 0 &&
        OI_FABS(oi__dot(u, u) - OI_R(1.0)) < EXCL_COS_MARGIN &&
        OI_FABS(oi__dot(g->bh, g->bh) - OI_R(1.0)) < EXCL_COS_MARGIN) {
        d = oi__dot(u, g->bh);
        if (d > cos_excl + EXCL_COS_MARGIN) return 1;
        if (d < cos_excl - EXCL_COS_MARGIN) return 0;
    }
    return sun_angle_of(scene, g) < excl_rad;
}

/* Earth's disc against the field (Note 2): the flag is the decision
 * gamma - rho < h, gamma the angle from the boresight to the Earth's centre,
 * rho = asin(R/r) the disc's radius, h = fov/2. The sine and cosine of
 * gamma - rho come from unit vectors (cos and sin of gamma as dot and cross
 * products, sin rho = R/r) and the difference formulas, so one atan2 gives
 * gamma - rho where it matters, instead of two angles (docs/camera.md,
 * "Cost of the search"): gamma < rho (sine negative) is on the disc,
 * whatever h; gamma - rho >= pi/2 (cosine not positive) is at least
 * pi/2 >= h away; only in between is the angle computed and compared with h. */
static OI_NOINLINE int earth_in_fov(const oi_scene *scene, const scene_geom *g, oi_real fov_rad)
{
    const oi_real one = OI_R(1.0);
    oi_real sin_rho, cos_rho, cos_g, sin_g, sin_gr, cos_gr;
    oi_real u[3]; /* unit vector of the observer, then u x bh */
    /* an observer inside the sphere of radius re (above the ellipsoid,
     * OI_EARTH_WGS84): the disc taken as the hemisphere below its horizon */
    sin_rho = g->r_obs > g->re ? g->re / g->r_obs : one;
    cos_rho = OI_SQRT((one - sin_rho) * (one + sin_rho));
    u[0] = scene->observer_km[0] / g->r_obs;
    u[1] = scene->observer_km[1] / g->r_obs;
    u[2] = scene->observer_km[2] / g->r_obs;
    cos_g = -oi__dot(u, g->bh);
    oi__cross(u, g->bh, u);
    sin_g = OI_SQRT(oi__dot(u, u)); /* unit vectors: no overflow */
    sin_gr = cos_rho * sin_g - sin_rho * cos_g; /* sin(gamma - rho) */
    cos_gr = cos_rho * cos_g + sin_rho * sin_g; /* cos(gamma - rho) */
    /* (b overflowed, positions near the largest oi_real: gamma was taken as
     * 0, as oi_angle of a non-finite vector would: flag) */
    return !oi__finite3(g->b) || sin_gr < 0 ||
           (cos_gr > 0 && OI_ATAN2(sin_gr, cos_gr) < OI_R(0.5) * fov_rad);
}

/* Where the boresight meets the Earth (Notes 3 and 4): OI_FLAG_OCCULTED when
 * that is before the target, and the Lambertian Earth's radiance there as
 * the background. The ray o + s bh against the sphere |x| = R:
 * s^2 + 2 ob s + c = 0 hits when ob < 0 and ob^2 >= c; the near root
 * c / (-ob + sqrt(ob^2 - c)) avoids cancellation, and
 * ob^2 - c = (-ob - sc)(-ob + sc). */
static OI_NOINLINE oi_real ground_background(const oi_scene *scene, const scene_geom *g, oi_expose_in *in)
{
    oi_real c, sc, ob, s_hit, cos_i, e0;
    oi_real hit[3], sun_hit[3]; /* then their unit vectors, in place */
#ifndef OI_NO_OBLATE
    if (g->shape == OI_EARTH_WGS84) {
        /* the ellipsoid hides the target; the background stays the
         * sphere's (none for an observer inside that sphere) */
        s_hit = oi__oblate_ray_hit(scene->observer_km, g->bh, g->re);
        if (s_hit >= 0 && s_hit < g->range) in->flags |= OI_FLAG_OCCULTED;
        if (!(g->r_obs > g->re)) return s_hit;
    }
#endif
    c = (g->r_obs - g->re) * (g->r_obs + g->re); /* |o|^2 - R^2 > 0 */
    sc = OI_SQRT(c);
    ob = oi__dot(scene->observer_km, g->bh);
    if (!(ob < 0 && -ob >= sc)) return -1; /* the ray misses the Earth */
    s_hit = c / (-ob + OI_SQRT((-ob - sc) * (-ob + sc)));
    hit[0] = scene->observer_km[0] + s_hit * g->bh[0];
    hit[1] = scene->observer_km[1] + s_hit * g->bh[1];
    hit[2] = scene->observer_km[2] + s_hit * g->bh[2];
    if (s_hit < g->range && g->shape != OI_EARTH_WGS84) in->flags |= OI_FLAG_OCCULTED;
    oi__sub(scene->sun_km, hit, sun_hit);
    (void)oi__unit(hit, hit);
    (void)oi__unit(sun_hit, sun_hit);
    cos_i = oi__dot(hit, sun_hit);
    if (cos_i > 0) {
        e0 = oi__solar_irradiance(g->tsi, g->au, oi__norm(scene->sun_km));
        in->background_w_m2_sr = scene->earth_albedo * e0 * cos_i / OI_PI_R;
    }
    return s_hit;
}

/* The Moon (OI_SKY_MOON, docs/camera.md "Sky background"): the flag when
 * its disc, of angular radius atan2(Rm, sqrt(d^2 - Rm^2)) at distance d,
 * comes within fov/2 of the boresight (an observer inside the Moon's sphere
 * sees it everywhere); where the boresight ray meets it, OI_FLAG_OCCULTED
 * when that is before the target, and the radiance of a Lambertian Moon of
 * the model's moon_albedo lit by the fraction of the Sun it sees, as the
 * background when no nearer Earth is in the way (s_earth: the distance to
 * the Earth along the ray, < 0 when missed). Returns 1 when the ray meets
 * the Moon (the zodiacal light is then behind it), else 0. */
static OI_NOINLINE int moon_view(const oi_scene *scene, const oi_illum *illum, const scene_geom *g,
                     oi_real fov_rad, oi_real s_earth, oi_expose_in *in)
{
    oi_real m[3], c[3], d, p, q2, rm2, s_hit, cos_i, e_moon_sun;
    oi_real hit[3], sun_hit[3]; /* hit: outward normal at the hit point */
    int i;
    oi__sub(scene->moon_km, scene->observer_km, m);
    if (!oi__finite3(m)) return 0;
    d = oi__norm(m);
    p = oi__dot(m, g->bh);
    oi__cross(m, g->bh, c);
    q2 = oi__dot(c, c); /* squared distance of the Moon's centre from the ray */
    rm2 = g->rm * g->rm;
    if (!(d > g->rm) ||
        OI_ATAN2(OI_SQRT(q2), p) - OI_ATAN2(g->rm, OI_SQRT((d - g->rm) * (d + g->rm))) <
            OI_R(0.5) * fov_rad) {
        in->flags |= OI_FLAG_MOON_IN_FOV;
    }
    if (!(q2 <= rm2) || !(p > 0 || d <= g->rm)) return 0;
    s_hit = p - OI_SQRT(rm2 - q2);
    if (s_hit < 0) s_hit = 0; /* observer inside the sphere */
    if (s_hit < g->range) in->flags |= OI_FLAG_OCCULTED;
    if (s_earth >= 0 && s_earth <= s_hit) return 1; /* the Earth in front of it */
    for (i = 0; i < 3; i++) {
        hit[i] = (s_hit * g->bh[i] - m[i]) / g->rm;
        sun_hit[i] = scene->sun_km[i] - (scene->observer_km[i] + s_hit * g->bh[i]);
    }
    in->background_w_m2_sr = 0;
    if (oi__unit(sun_hit, sun_hit) > 0 && (cos_i = oi__dot(hit, sun_hit)) > 0) {
        oi__sub(scene->sun_km, scene->moon_km, sun_hit);
        e_moon_sun =
            oi__solar_irradiance(g->tsi, g->au, oi__norm(sun_hit)) * illum->moon_sun_fraction;
        in->background_w_m2_sr = g->moon_albedo * e_moon_sun * cos_i / OI_PI_R;
    }
    return 1;
}

#ifndef OI_NO_SKY
/* Mean obliquity of the ecliptic at J2000 (IAU 2006: 84381.406 arcsec):
 * positions are taken as ICRF/GCRS-aligned (equator and equinox of J2000
 * to within the frame bias, 0.02 arcsec), so the ecliptic is that of J2000;
 * its precession (0.013 deg per year in longitude) is far below the
 * zodiacal table's 5-15 deg grid. */
#define ECL_COS OI_R(0.9174821430652419)
#define ECL_SIN OI_R(0.39777696911260596)

/* Zodiacal light behind the target (OI_SKY_ZODIACAL): the boresight and
 * the Sun seen from the observer in ecliptic coordinates, their longitude
 * difference and the boresight's latitude, into oi_zodiacal_radiance. */
static OI_NOINLINE oi_real zodiacal_background(const oi_scene *scene, const scene_geom *g)
{
    oi_real u[3], bx, by, bz, sx, sy, dl, beta;
    oi__sub(scene->sun_km, scene->observer_km, u);
    if (!oi__finite3(u) || !(oi__unit(u, u) > 0)) return 0;
    bx = g->bh[0];
    by = ECL_COS * g->bh[1] + ECL_SIN * g->bh[2];
    bz = -ECL_SIN * g->bh[1] + ECL_COS * g->bh[2];
    sx = u[0];
    sy = ECL_COS * u[1] + ECL_SIN * u[2];
    dl = OI_ATAN2(OI_FABS(bx * sy - by * sx), bx * sx + by * sy);
    beta = OI_ATAN2(bz, OI_SQRT(bx * bx + by * by));
    return oi_zodiacal_radiance(dl, beta);
}

/* Integrated starlight behind the target (OI_SKY_STARLIGHT): the
 * boresight's galactic longitude and latitude (the ICRS rotation of
 * src/camera/galactic.c) into oi_starlight_radiance. */
static OI_NOINLINE oi_real starlight_background(const scene_geom *g)
{
    oi_real l, b;
    if (oi_galactic_from_icrs(g->bh, &l, &b) != OI_OK) return 0;
    return oi_starlight_radiance(l, b);
}
#endif

#ifndef OI_NO_SKYLIGHT
/* The scattered sunlight's share of the background (Note 3b, OI_TERM_SKY):
 * where the boresight crosses the limb (its closest approach to the Earth's
 * centre ahead, between the sky table's floor and the top of the
 * atmosphere), the mean radiance of the limb seen from the observer,
 * e_sky(observer) / Omega, Omega the solid angle of the ring between the
 * floor's disc and the top's (an estimate: most of e_sky comes from the limb
 * near the shadow; docs/skylight.md measures it). 0 for an observer inside
 * the atmosphere or a boresight that misses the ring. */
/* The sky table of the model and the radii of its top and floor (r[0],
 * r[1]) about the Earth radius check_scene resolved (g->re): 0, or -1
 * without a table. The caller's table is read from the model as given
 * (the resolution copies the pointer); a frame of its own (make stack). */
static OI_NOINLINE int sky_radii(const oi_model *model, const scene_geom *g,
                                 const oi_sky_table **t, oi_real r[2])
{
    if (model == NULL)
        *t = oi_sky_table_default();
    else if (oi__sky_table_of(model, t) < 0)
        return -1;
    if (*t == NULL) return -1;
    r[0] = g->re + (*t)->top_km;
    r[1] = g->re + (*t)->floor_km;
    return 0;
}

/* The angle between the Sun and the observer seen from the Earth's centre,
 * and the Sun's distance (km). A frame of its own: the unit vectors are not
 * live during the sky table's lookup (make stack). */
static OI_NOINLINE oi_real sun_observer_angle(const oi_scene *scene, oi_real *d_sun)
{
    oi_real s_hat[3], o_hat[3], c[3];
    *d_sun = oi__unit(scene->sun_km, s_hat);
    (void)oi__unit(scene->observer_km, o_hat);
    oi__cross(s_hat, o_hat, c);
    return OI_ATAN2(oi__norm(c), oi__dot(s_hat, o_hat));
}

static OI_NOINLINE oi_real sky_background(const oi_scene *scene, const oi_model *model,
                                          const scene_geom *g)
{
    const oi_sky_table *t;
    oi_real r[2], top, fl, ob, b2, theta, e, psi, st, sf, ct, cf, d_sun;
    /* without an atmosphere the limb holds no scattered light */
    if (model != NULL && model->no_atmosphere) return 0;
    if (sky_radii(model, g, &t, r) < 0) return 0;
    top = r[0];
    fl = r[1];
    if (!(g->r_obs > top) || !(fl < top)) return 0;
    ob = oi__dot(scene->observer_km, g->bh);
    b2 = (g->r_obs - ob) * (g->r_obs + ob); /* squared closest approach (|ob| <= r_obs) */
    if (!(ob < 0) || b2 >= top * top || b2 <= fl * fl) return 0;
    theta = sun_observer_angle(scene, &d_sun);
    (void)oi__sky_lookup(t, theta, g->r_obs, &e, &psi);
    st = top / g->r_obs;
    sf = fl / g->r_obs;
    ct = OI_SQRT(((oi_real)1 - st) * ((oi_real)1 + st));
    cf = OI_SQRT(((oi_real)1 - sf) * ((oi_real)1 + sf));
    /* Omega = 2 pi (cos a_f - cos a_t) = 2 pi (st^2 - sf^2) / (cf + ct) */
    return oi__solar_irradiance(g->tsi, g->au, d_sun) * e * (cf + ct) /
           (OI_R(2.0) * OI_PI_R * (st - sf) * (st + sf));
}
#endif

/* Resolved target (Note 5): the brightest pixel sees at most the radiance
 * albedo * sum(E) / pi over its solid angle. */
static OI_NOINLINE void limit_resolved(const oi_camera *camera, const oi_scene *scene, const oi_illum *illum,
                           oi_expose_in *in)
{
    oi_real ifov = camera->pixel_pitch_m / camera->focal_length_m;
    oi_real peak = scene->target_albedo, cap;
#ifndef OI_NO_FACETS
    if (scene->shape != NULL) peak = oi__shape_peak(scene);
#endif
    cap = peak * (illum->e_sun + illum->e_earth + illum->e_moon + illum->e_sky) /
          OI_PI_R * (ifov * ifov) / camera->psf_peak_fraction;
    if (in->flux_w_m2 > cap) {
        in->flux_w_m2 = cap;
        in->flags |= OI_FLAG_RESOLVED;
    }
}

/* Eclipse flags of the target's shadow region (Note 6). */
static unsigned region_flags(int region)
{
    if (region == OI_SHADOW_UMBRA) return OI_FLAG_ECLIPSED;
    if (region == OI_SHADOW_PENUMBRA || region == OI_SHADOW_ANNULAR) return OI_FLAG_PENUMBRA;
    return 0u;
}

/* The batch's set-up of oi_expose_scene_batch_outputs (src/batch/expose_batch.c):
 * the model's constants (its status), the camera's check (OI_ERR_CAMERA),
 * the plan of the choice, the cosine of the Sun exclusion. */
int oi__expose_scene_setup(const oi_camera *camera, const oi_model *model,
                           const oi_expose_goal *goal, unsigned outputs,
                           oi__expose_scene_batch *b)
{
    oi_real moon[2];
    int st = scene_model(model, &b->re, &b->au, &b->tsi, moon, &b->shape); /* NULL: defaults */
    if (st != OI_OK) return st;
    b->rm = moon[0];
    b->moon_albedo = moon[1];
    if (!oi__camera_valid(camera)) return OI_ERR_CAMERA;
    oi__expose_plan_make(camera, goal, &b->plan);
    b->cos_excl = OI_COS(camera->sun_exclusion_rad);
    b->outputs = outputs;
    return OI_OK;
}

/* What the row's OI_EXPOSE_* outputs need computed. */
#define NEED_CHOICE (OI_EXPOSE_SETTING | OI_EXPOSE_FAINT | OI_EXPOSE_DETECT)

/* One row of oi_expose_scene: b NULL for the single call (every output,
 * the model, the camera and the goal checked here), else the batch's
 * set-up. out is zeroed. */
int oi__expose_scene_row(const oi_camera *camera, const oi_scene *scene, const oi_illum *illum,
                         const oi_model *model, const oi_expose_goal *goal,
                         const oi__expose_scene_batch *b, oi_exposure *out)
{
    oi_expose_in in;
    scene_geom g;
    oi_real sun_angle = 0, s_earth;
    int st, use_moon, moon_hit = 0, lit_ground, excluded;
    const unsigned sky = goal != NULL ? goal->sky : 0u;
    const unsigned outputs = b != NULL ? b->outputs : (unsigned)OI_EXPOSE_ALL;

    /* the Moon's position is read only with OI_TERM_MOON (as oi_illuminate) */
#ifndef OI_NO_MOON
    use_moon = (sky & OI_SKY_MOON) != 0u && (scene->terms & OI_TERM_MOON) != 0u;
#else
    use_moon = 0; /* no Moon in this build: goal->sky cannot ask for it (OI_ERR_FLAGS) */
#endif
    st = check_scene(camera, scene, illum, model, use_moon, b, &g);
    if (st != OI_OK) return st;

    in.flux_w_m2 = illum->flux_obs;
    in.background_w_m2_sr = 0;
    in.flags = 0;
    in.rate_rad_s = (outputs & (NEED_CHOICE | OI_EXPOSE_RATE)) != 0u ? angular_rate(scene, &g) : 0;
    if ((outputs & OI_EXPOSE_SUN_ANGLE) != 0u) {
        sun_angle = sun_angle_of(scene, &g);
        excluded = sun_angle < camera->sun_exclusion_rad;
    } else {
        excluded = sun_excluded(scene, &g, b->cos_excl, camera->sun_exclusion_rad);
    }
    if (excluded) in.flags |= OI_FLAG_SUN_EXCLUSION;
    if (earth_in_fov(scene, &g, camera->fov_rad)) in.flags |= OI_FLAG_EARTH_IN_FOV;
    s_earth = ground_background(scene, &g, &in);
    lit_ground = s_earth >= 0 && in.background_w_m2_sr > 0;
    if (use_moon) moon_hit = moon_view(scene, illum, &g, camera->fov_rad, s_earth, &in);
    /* the sky's terms only where the background is an output or the choice's */
    if ((outputs & (NEED_CHOICE | OI_EXPOSE_BACKGROUND)) != 0u) {
#ifndef OI_NO_SKY
        if ((sky & OI_SKY_ZODIACAL) != 0u && s_earth < 0 && !moon_hit) {
            in.background_w_m2_sr = zodiacal_background(scene, &g);
        }
        if ((sky & OI_SKY_STARLIGHT) != 0u && s_earth < 0 && !moon_hit) {
            in.background_w_m2_sr += starlight_background(&g);
        }
#endif
#ifndef OI_NO_SKYLIGHT
        if ((scene->terms & OI_TERM_SKY) != 0u && !lit_ground && !moon_hit)
            in.background_w_m2_sr += sky_background(scene, model, &g);
#endif
    }
    (void)moon_hit;
    (void)lit_ground;
    if (in.flags & OI_FLAG_OCCULTED) in.flux_w_m2 = 0;
    limit_resolved(camera, scene, illum, &in);
    /* a glint: the specular lobes carry most of the (unoccluded) flux */
    if (scene->shape != NULL && in.flux_w_m2 > 0 &&
        illum->flux_specular > OI_R(0.5) * illum->flux_obs)
        in.flags |= OI_FLAG_GLINT;
    in.flags |= region_flags(illum->shadow.region);
    if (illum->sun_moon_hidden > (oi_real)0) in.flags |= OI_FLAG_MOON_SHADOW;

    st = oi__expose_planned(camera, b != NULL ? &b->plan : NULL, goal, &in,
                            oi__expose_need(outputs), out);
    if (st < 0) return st;
    out->sun_angle_rad = sun_angle;
    return st;
}

/* oi_expose_scene: the contract is in include/orbillum.h. */
int oi_expose_scene(const oi_camera *camera, const oi_scene *scene,
                    const oi_illum *illum, const oi_model *model,
                    const oi_expose_goal *goal, oi_exposure *out)
{
    if (out == NULL) return OI_ERR_NULL;
    memset(out, 0, sizeof *out);
    if (camera == NULL || scene == NULL || illum == NULL) return OI_ERR_NULL;
    return oi__expose_scene_row(camera, scene, illum, model, goal, NULL, out);
}

#endif /* OI_NO_EXPOSURE */
