/* SPDX-License-Identifier: MIT */
/* test_fp_exceptions.c: a valid call raises no floating-point exception.
 * Flight software may run with the invalid-operation, division-by-zero and
 * overflow exceptions trapping (or reads their flags as a health check), so
 * the library must not raise them on valid input, including in the values
 * its vectorised blocks compute and then discard (src/fp_quiet.h). Over
 * random scenes (LEO to cislunar; lit, across the shadow's edge and in the
 * umbra; observers 10 to 2,000 km away), each model option (limb darkening,
 * no atmosphere, the WGS-84 Earth, the total band, Knocke's albedo, the
 * reflection options), every public call and batch the scenes reach: the
 * flags are clear after each call, and, where glibc can enable traps, the
 * same calls run with the three exceptions trapping (a trap fails the test
 * with SIGFPE). Then the error paths: every documented error
 * status of every public call, and a sweep of hostile inputs (NaN,
 * infinities, subnormals, 1e12 and 1e13 km), reached with the status
 * checked and no harmful flag, again with the traps on. */
#define _GNU_SOURCE /* feenableexcept (glibc) */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <fenv.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "orbillum.h"
#include "oi_test_util.h"

/* every term the build has (OI_NO_MOON refuses the Moon's) */
/* without the earthshine table the Earth's light is the Lambert far field,
 * with its warning */
#ifdef OI_NO_EARTH_TABLE
#define ST_EARTH OI_WARN_TABLE_RANGE
#else
#define ST_EARTH OI_OK
#endif
#ifdef OI_NO_MOON
#define TERMS_ALL (OI_TERM_SUN | OI_TERM_EARTH)
#else
#define TERMS_ALL OI_TERM_ALL
#endif

#define NSCENES 1200
#define NMODELS 8
#define AU 149597870.7
#define RE 6378.137
#define HARMFUL (FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW)

static oi_scene scenes[NSCENES];
static oi_illum illum[NSCENES];
static oi_shadow shadow[NSCENES];
static oi_real sun[3 * NSCENES], point[3 * NSCENES], theta[NSCENES], h_km[NSCENES];
static oi_real phi[NSCENES], psi[NSCENES];
static int status[NSCENES];
#ifndef OI_NO_EXPOSURE
static oi_exposure exposure[NSCENES];
#endif

/* A unit vector normal to u. */
static void normal_to(const double u[3], double v[3])
{
    double a[3] = {0.0, 0.0, 1.0}, d, n;
    int k;
    if (fabs(u[2]) > 0.9) {
        a[0] = 1.0;
        a[2] = 0.0;
    }
    d = a[0] * u[0] + a[1] * u[1] + a[2] * u[2];
    for (k = 0; k < 3; k++) v[k] = a[k] - d * u[k];
    n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (k = 0; k < 3; k++) v[k] /= n;
}

/* Scene i: the target at 150 km to 400,000 km above the Earth, a third of
 * them lit anywhere, a third within 100 km of the shadow cone's edge, a
 * third inside the umbra's cone; the Sun at 0.983 to 1.017 AU. */
static void make_scenes(void)
{
    uint64_t seed = 20261203u;
    int i, k;
    for (i = 0; i < NSCENES; i++) {
        oi_scene *s = &scenes[i];
        double us[3], um[3], ut[3], uo[3], e[3];
        const double r = RE + 150.0 * exp(lcg01(&seed) * log(400000.0 / 150.0));
        const double d_sun = AU * (0.983 + 0.034 * lcg01(&seed)), d_obs = 10.0 + 1990.0 * lcg01(&seed);
        oi_scene_defaults(s);
        random_unit(&seed, us);
        random_unit(&seed, um);
        random_unit(&seed, ut);
        random_unit(&seed, uo);
        if (i % 3 != 0) {
            /* behind the Earth: x along the anti-Sun axis, the cone's radius
             * there R - x (R_sun - R) / d_sun (umbra) to R + x (R_sun + R) / d_sun */
            const double x = r * (0.2 + 0.8 * lcg01(&seed));
            const double edge = i % 3 == 1 ? RE + x * (695700.0 + RE) / d_sun
                                           : RE - x * (695700.0 - RE) / d_sun;
            double rho = i % 3 == 1 ? edge + 200.0 * (lcg01(&seed) - 0.5) : edge * lcg01(&seed);
            if (rho < 0) rho = 0;
            if (x * x + rho * rho < (RE + 150.0) * (RE + 150.0)) rho = sqrt((RE + 150.0) * (RE + 150.0) - x * x + 1.0);
            normal_to(us, e);
            for (k = 0; k < 3; k++) ut[k] = (-x * us[k] + rho * e[k]) / r;
        }
        for (k = 0; k < 3; k++) {
            s->sun_km[k] = (oi_real)(d_sun * us[k]);
            s->moon_km[k] = (oi_real)((363000.0 + 42000.0 * lcg01(&seed)) * um[k]);
            s->target_km[k] = (oi_real)(r * ut[k]);
            s->observer_km[k] = (oi_real)(r * ut[k] + d_obs * uo[k]);
            sun[3 * i + k] = s->sun_km[k];
            point[3 * i + k] = s->target_km[k];
        }
        if (sqrt((double)(s->observer_km[0] * s->observer_km[0] + s->observer_km[1] * s->observer_km[1] +
                          s->observer_km[2] * s->observer_km[2])) < RE + 100.0) {
            /* keep the observer above the Earth: on the target's far side */
            for (k = 0; k < 3; k++) s->observer_km[k] = (oi_real)(r * ut[k] * (1.0 + d_obs / r));
        }
        s->has_observer = 1;
        s->terms = TERMS_ALL;
        s->epoch_jd = (oi_real)(2461000.5 + 0.37 * i);
        s->earth_rotation_rad = (oi_real)(0.1 * i);
        theta[i] = (oi_real)(3.141592653589793 * lcg01(&seed));
        h_km[i] = (oi_real)(r - RE);
    }
}

static void model_of(int which, oi_model *m)
{
    memset(m, 0, sizeof *m);
    switch (which) {
    case 1: m->limb_darkening = OI_LIMB_DARKENED; break;
    case 2: m->no_atmosphere = 1; break;
    case 3: m->earth_shape = OI_EARTH_WGS84; break;
    case 4: m->band = OI_BAND_TOTAL; break;
    case 5: m->albedo_model = OI_ALBEDO_KNOCKE; break;
    case 6: m->earth_reflection = OI_EARTH_REFLECT_TABLE; break;
    case 7:
        m->earth_reflection = OI_EARTH_REFLECT_MEAN;
        m->limb_darkening = OI_LIMB_DARKENED;
        m->earth_shape = OI_EARTH_WGS84;
        break;
    default: break;
    }
}

static int failures;

/* The harmful flags raised since the last check, reported with the call. */
static void flags_clear(const char *call, int model, int row)
{
    const int f = fetestexcept(HARMFUL);
    if (f != 0) {
        if (failures < 20)
            printf("# %s, model %d, row %d:%s%s%s\n", call, model, row,
                   f & FE_INVALID ? " FE_INVALID" : "", f & FE_DIVBYZERO ? " FE_DIVBYZERO" : "",
                   f & FE_OVERFLOW ? " FE_OVERFLOW" : "");
        failures++;
    }
    feclearexcept(FE_ALL_EXCEPT);
}

/* Every call over every scene and model; returns the count of calls that
 * computed (status >= 0), so that the test sees the scenes reach them. */
static long run_all(void)
{
    long computed = 0;
    int mi, i;
    feclearexcept(FE_ALL_EXCEPT);
    for (mi = 0; mi < NMODELS; mi++) {
        oi_model m;
        model_of(mi, &m);
        for (i = 0; i < NSCENES; i++) {
            oi_illum one;
            oi_shadow sh;
            oi_real e_over_sun, direction_psi, flux;
            const oi_real o[3] = {(oi_real)0.6, (oi_real)0.0, (oi_real)0.8};
            computed += oi_illuminate(&scenes[i], &m, &one) >= 0;
            flags_clear("oi_illuminate", mi, i);
            computed += oi_sun_fraction(scenes[i].sun_km, scenes[i].target_km, &m, &sh) >= 0;
            flags_clear("oi_sun_fraction", mi, i);
            computed += oi_earthshine(theta[i], h_km[i], &m, &e_over_sun, &direction_psi) >= 0;
            flags_clear("oi_earthshine", mi, i);
            computed += oi_earthshine_sphere(theta[i], h_km[i], o, &m, &flux) >= 0;
            flags_clear("oi_earthshine_sphere", mi, i);
#ifndef OI_NO_EXPOSURE
            {
                oi_exposure e;
                computed += oi_expose_scene(oi_camera_builtin(i % 3), &scenes[i], &one, &m, NULL,
                                            &e) >= 0;
                flags_clear("oi_expose_scene", mi, i);
            }
#endif
        }
        (void)oi_illuminate_batch_outputs(NSCENES, scenes, &m, OI_BATCH_SCENE_ALL, illum, status);
        flags_clear("oi_illuminate_batch_outputs (all)", mi, -1);
        (void)oi_illuminate_batch_outputs(NSCENES, scenes, &m, 0u, illum, status);
        flags_clear("oi_illuminate_batch_outputs (0)", mi, -1);
        (void)oi_sun_fraction_batch(NSCENES, sun, point, &m, OI_BATCH_ALL, shadow, status);
        flags_clear("oi_sun_fraction_batch (all)", mi, -1);
        (void)oi_sun_fraction_batch(NSCENES, sun, point, &m, 0u, shadow, status);
        flags_clear("oi_sun_fraction_batch (0)", mi, -1);
        for (i = 0; i < NSCENES; i++) computed += status[i] >= 0;
        (void)oi_earthshine_batch(NSCENES, theta, h_km, &m, phi, psi, status);
        flags_clear("oi_earthshine_batch", mi, -1);
#ifndef OI_NO_EXPOSURE
        (void)oi_illuminate_batch(NSCENES, scenes, &m, illum, status);
        (void)oi_expose_scene_batch(NSCENES, oi_camera_builtin(0), scenes, illum, &m, NULL,
                                    exposure, status);
        flags_clear("oi_expose_scene_batch", mi, -1);
#endif
    }
    return computed;
}

static void test_flags_clear(void **state)
{
    long computed;
    (void)state;
    failures = 0;
    computed = run_all();
    printf("# %ld calls computed, %d raised an exception\n", computed, failures);
    /* most calls compute (a model option left out of the build refuses) */
    assert_true(computed > (long)NSCENES * NMODELS);
    check_int(0, failures, "calls raising FE_INVALID, FE_DIVBYZERO or FE_OVERFLOW");
}

static void test_traps_enabled(void **state)
{
    (void)state;
#if defined(__GLIBC__) && (defined(__x86_64__) || defined(__i386__))
    failures = 0;
    assert_true(feenableexcept(HARMFUL) != -1);
    (void)run_all();
    (void)fedisableexcept(HARMFUL);
    check_int(0, failures, "calls raising an exception with traps enabled");
#else
    printf("# skip traps: feenableexcept needs glibc on x86\n");
#endif
}


/* ---- error paths: every documented error status of every public call,
 * reached (the status checked) with no harmful flag and, in the trapped
 * run, no trap. */

static int error_mismatches;

static void expect_st(int want, int got, const char *what)
{
    const int f = fetestexcept(HARMFUL);
    if (want != got || f != 0) {
        if (error_mismatches < 30)
            printf("# %s: want %s got %s%s%s%s\n", what, oi_status_name(want), oi_status_name(got),
                   f & FE_INVALID ? " FE_INVALID" : "", f & FE_DIVBYZERO ? " FE_DIVBYZERO" : "",
                   f & FE_OVERFLOW ? " FE_OVERFLOW" : "");
        error_mismatches++;
    }
    feclearexcept(FE_ALL_EXCEPT);
}

/* A function of no status: only the flags. */
static void expect_quiet(const char *what)
{
    expect_st(0, 0, what);
}

static void lit_scene(oi_scene *s)
{
    oi_scene_defaults(s);
    s->terms = TERMS_ALL;
    s->sun_km[0] = (oi_real)1.496e8;
    s->moon_km[1] = (oi_real)384400;
    s->target_km[0] = 7000;
    s->observer_km[0] = 7000;
    s->observer_km[1] = 50;
    s->has_observer = 1;
}

static void errors_geometry(void)
{
    const oi_real sun1[3] = {(oi_real)1.496e8, 0, 0}, pt[3] = {7000, 0, 0};
    const oi_real zero[3] = {0, 0, 0}, nan3[3] = {(oi_real)NAN, 0, 0};
#ifdef OI_SINGLE_PRECISION
    const oi_real big_pt[3] = {(oi_real)-3e38, 0, 0}, big_sun[3] = {(oi_real)3e38, 0, 0};
#else
    const oi_real big_pt[3] = {-1.7e308, 0, 0}, big_sun[3] = {1.7e308, 0, 0};
#endif
    const oi_real far_pt[3] = {(oi_real)1e13, 0, 0}, low_pt[3] = {1000, 0, 0};
    const oi_real near_sun[3] = {(oi_real)5e5, 0, 0}, in_sun[3] = {(oi_real)1.4959e8, 0, 0};
    const oi_real o[3] = {0, 0, 1};
    oi_shadow sh;
    oi_model bad_tsi, bad_r, wgs;
    oi_real phi1, psi1, flux, e, l, b;
    (void)far_pt; /* read where the build has the ellipsoid and the sky */
    (void)l;
    (void)b;
    memset(&bad_tsi, 0, sizeof bad_tsi);
    bad_tsi.tsi_w_m2 = -1;
    memset(&bad_r, 0, sizeof bad_r);
    bad_r.earth_radius_km = -1;
    memset(&wgs, 0, sizeof wgs);
    wgs.earth_shape = OI_EARTH_WGS84;
    feclearexcept(FE_ALL_EXCEPT);
    expect_st(OI_ERR_NULL, oi_sun_fraction(NULL, pt, NULL, &sh), "sun_fraction NULL");
    expect_st(OI_ERR_MODEL, oi_sun_fraction(sun1, pt, &bad_tsi, &sh), "sun_fraction model");
    expect_st(OI_ERR_RADIUS, oi_sun_fraction(sun1, pt, &bad_r, &sh), "sun_fraction radius");
    expect_st(OI_ERR_NONFINITE, oi_sun_fraction(sun1, nan3, NULL, &sh), "sun_fraction NaN");
    expect_st(OI_ERR_ZERO_VECTOR, oi_sun_fraction(zero, pt, NULL, &sh), "sun_fraction zero Sun");
    expect_st(OI_ERR_ZERO_VECTOR, oi_sun_fraction(sun1, zero, NULL, &sh), "sun_fraction zero point");
#ifndef OI_NO_OBLATE
    expect_st(OI_ERR_GEOMETRY, oi_sun_fraction(sun1, far_pt, &wgs, &sh), "sun_fraction WGS-84 far");
    expect_st(OI_ERR_BELOW_SURFACE, oi_sun_fraction(sun1, low_pt, &wgs, &sh), "sun_fraction WGS-84 low");
#endif
    expect_st(OI_ERR_BELOW_SURFACE, oi_sun_fraction(sun1, low_pt, NULL, &sh), "sun_fraction below");
    expect_st(OI_ERR_GEOMETRY, oi_sun_fraction(near_sun, pt, NULL, &sh), "sun_fraction Sun at Earth");
    expect_st(OI_ERR_NONFINITE, oi_sun_fraction(big_sun, big_pt, NULL, &sh), "sun_fraction overflow");
    expect_st(OI_ERR_GEOMETRY, oi_sun_fraction(sun1, in_sun, NULL, &sh), "sun_fraction in the Sun");

    expect_st(OI_ERR_NULL, oi_earthshine(1, 500, NULL, NULL, &psi1), "earthshine NULL");
    expect_st(OI_ERR_NONFINITE, oi_earthshine((oi_real)NAN, 500, NULL, &phi1, &psi1), "earthshine NaN");
    expect_st(OI_ERR_NONFINITE, oi_earthshine(1, (oi_real)INFINITY, NULL, &phi1, &psi1), "earthshine inf");
    expect_st(OI_ERR_BELOW_SURFACE, oi_earthshine(1, 0, NULL, &phi1, &psi1), "earthshine h 0");
    expect_st(OI_ERR_BELOW_SURFACE, oi_earthshine(1, -1e30f, NULL, &phi1, &psi1), "earthshine h < 0");
    expect_st(OI_ERR_MODEL, oi_earthshine(1, 500, &bad_tsi, &phi1, &psi1), "earthshine model");
    expect_st(OI_ERR_RADIUS, oi_earthshine(1, 500, &bad_r, &phi1, &psi1), "earthshine radius");
    expect_st(OI_ERR_NULL, oi_earthshine_sphere(1, 500, NULL, NULL, &flux), "es_sphere NULL");
    expect_st(OI_ERR_NONFINITE, oi_earthshine_sphere(1, 500, nan3, NULL, &flux), "es_sphere NaN");
    expect_st(OI_ERR_ZERO_VECTOR, oi_earthshine_sphere(1, 500, zero, NULL, &flux), "es_sphere zero");
    expect_st(OI_ERR_BELOW_SURFACE, oi_earthshine_sphere(1, 0, o, NULL, &flux), "es_sphere h 0");
#ifndef OI_NO_FACETS
    expect_st(OI_ERR_NULL, oi_earthshine_plate(1, 500, NULL, NULL, &e), "plate NULL");
    expect_st(OI_ERR_NONFINITE, oi_earthshine_plate(1, 500, nan3, NULL, &e), "plate NaN");
    expect_st(OI_ERR_ZERO_VECTOR, oi_earthshine_plate(1, 500, zero, NULL, &e), "plate zero");
    expect_st(OI_ERR_NONFINITE, oi_earthshine_plate((oi_real)-INFINITY, 500, o, NULL, &e), "plate inf");
    expect_st(OI_ERR_MODEL, oi_earthshine_plate(1, 500, o, &bad_tsi, &e), "plate model");
#endif
#ifndef OI_NO_SKYLIGHT
    expect_st(OI_ERR_NULL, oi_skylight(1, 500, NULL, NULL, &psi1), "skylight NULL");
    expect_st(OI_ERR_NONFINITE, oi_skylight((oi_real)NAN, 500, NULL, &e, &psi1), "skylight NaN");
    expect_st(OI_ERR_INPUT, oi_skylight(-1, 500, NULL, &e, &psi1), "skylight theta");
    expect_st(OI_ERR_INPUT, oi_skylight(1, -1, NULL, &e, &psi1), "skylight h");
    expect_st(OI_ERR_MODEL, oi_skylight(1, 500, &bad_tsi, &e, &psi1), "skylight model");
    expect_st(OI_ERR_RADIUS, oi_skylight(1, 500, &bad_r, &e, &psi1), "skylight radius");
#endif
#ifndef OI_NO_SKY
    expect_st(OI_ERR_NULL, oi_galactic_from_icrs(NULL, &l, &b), "galactic NULL");
    expect_st(OI_ERR_NONFINITE, oi_galactic_from_icrs(nan3, &l, &b), "galactic NaN");
    expect_st(OI_ERR_ZERO_VECTOR, oi_galactic_from_icrs(zero, &l, &b), "galactic zero");
    (void)oi_zodiacal_radiance((oi_real)NAN, (oi_real)INFINITY);
    expect_quiet("zodiacal NaN");
    (void)oi_starlight_radiance((oi_real)-INFINITY, (oi_real)NAN);
    expect_quiet("starlight NaN");
    (void)oi_zodiacal_radiance((oi_real)3e38, (oi_real)-3e38);
    expect_quiet("zodiacal huge");
    (void)oi_starlight_radiance((oi_real)-3e38, (oi_real)3e38);
    expect_quiet("starlight huge");
#endif
    expect_st(OI_ERR_NULL, oi_flux_from_magnitude(1, NULL, NULL), "flux_from_magnitude NULL");
    expect_st(OI_ERR_MODEL, oi_flux_from_magnitude(1, &bad_tsi, &e), "flux_from_magnitude model");
    expect_st(OI_ERR_MAGNITUDE, oi_flux_from_magnitude((oi_real)NAN, NULL, &e), "magnitude NaN");
    expect_st(OI_ERR_MAGNITUDE, oi_flux_from_magnitude(100, NULL, &e), "magnitude 100");
    expect_st(OI_ERR_MAGNITUDE, oi_flux_from_magnitude((oi_real)-INFINITY, NULL, &e), "magnitude -inf");
    (void)oi_magnitude_v((oi_real)NAN, NULL);
    (void)oi_magnitude_v((oi_real)-1, NULL);
    (void)oi_magnitude_v((oi_real)INFINITY, &bad_tsi);
    (void)oi_magnitude_v((oi_real)3e38, NULL);
    expect_quiet("magnitude_v of NaN, -1, inf, 3e38");
    (void)oi_lambert_phase((oi_real)NAN);
    (void)oi_lambert_phase((oi_real)INFINITY);
    (void)oi_lambert_phase((oi_real)-3e38);
    expect_quiet("lambert_phase");
    (void)oi_angle(nan3, pt);
    (void)oi_angle(zero, pt);
    (void)oi_angle(big_sun, big_pt);
    (void)oi_angle(NULL, pt);
    expect_quiet("oi_angle");
    (void)oi_cap_overlap((oi_real)NAN, 1, 1);
    (void)oi_cap_overlap((oi_real)INFINITY, (oi_real)-INFINITY, (oi_real)3e38);
    expect_quiet("cap_overlap");
#ifndef OI_NO_MOON
    (void)oi_moon_phase_law((oi_real)NAN);
    (void)oi_moon_phase_law((oi_real)-3e38);
    expect_quiet("moon_phase_law");
#endif
    (void)oi_status_name(-1000000);
#ifndef OI_NO_EXPOSURE
    (void)oi_flag_name(0xffffffffu);
#endif
    expect_quiet("names");
}

#ifndef OI_NO_FACETS
static void errors_shapes(void)
{
    oi_facet f, fs[2];
    oi_shape sh;
    const oi_real v[3] = {0, 0, 1}, nanv[3] = {(oi_real)NAN, 0, 1};
    memset(&f, 0, sizeof f);
    f.normal[2] = 1;
    f.area_m2 = 1;
    f.albedo_diffuse = (oi_real)0.5;
    memset(&sh, 0, sizeof sh);
    sh.facets = &f;
    sh.n_facets = 1;
    expect_st(OI_ERR_NULL, oi_shape_check(NULL), "shape_check NULL");
    sh.facets = NULL;
    expect_st(OI_ERR_NULL, oi_shape_check(&sh), "shape_check NULL facets");
    sh.facets = &f;
    sh.n_facets = 0;
    expect_st(OI_ERR_SHAPE, oi_shape_check(&sh), "shape_check no facets");
    sh.n_facets = OI_FACETS_MAX + 1;
    expect_st(OI_ERR_SHAPE, oi_shape_check(&sh), "shape_check too many");
    sh.n_facets = 2;
    fs[0] = f;
    fs[1] = f;
    sh.facets = fs;
    fs[1].normal[2] = (oi_real)NAN;
    expect_st(OI_ERR_SHAPE, oi_shape_check(&sh), "shape_check NaN normal");
    fs[1].normal[2] = 0;
    expect_st(OI_ERR_SHAPE, oi_shape_check(&sh), "shape_check zero normal");
    fs[1].normal[2] = (oi_real)3e38;
    fs[1].normal[1] = (oi_real)-3e38;
    expect_st(OI_OK, oi_shape_check(&sh), "shape_check huge normal");
    fs[1] = f;
    fs[1].area_m2 = (oi_real)-INFINITY;
    expect_st(OI_ERR_SHAPE, oi_shape_check(&sh), "shape_check area");
    fs[1] = f;
    fs[1].albedo_diffuse = (oi_real)NAN;
    expect_st(OI_ERR_SHAPE, oi_shape_check(&sh), "shape_check albedo NaN");
    fs[1] = f;
    fs[1].albedo_specular = (oi_real)0.9;
    expect_st(OI_ERR_SHAPE, oi_shape_check(&sh), "shape_check albedo sum");
    fs[1] = f;
    fs[1].shininess = (oi_real)INFINITY;
    expect_st(OI_ERR_SHAPE, oi_shape_check(&sh), "shape_check shininess");
    fs[1] = f;
    fs[1].normal[2] = (oi_real)NAN;
    (void)oi_facet_brdf(&fs[1], v, v);
    (void)oi_facet_brdf(&f, nanv, v);
    fs[1].normal[2] = (oi_real)3e38;
    (void)oi_facet_brdf(&fs[1], v, v);
    (void)oi_facet_brdf(NULL, v, v);
    expect_quiet("facet_brdf");
}
#endif

static void errors_scene(void)
{
    oi_scene s;
    oi_illum il;
    oi_model bad_tsi, knocke, map;
    static const float nan_map[1] = {NAN};
#ifndef OI_NO_FACETS
    oi_facet f;
    oi_shape sh;
    memset(&f, 0, sizeof f);
    f.normal[2] = 1;
    f.area_m2 = 1;
    f.albedo_diffuse = (oi_real)0.5;
    memset(&sh, 0, sizeof sh);
    sh.facets = &f;
    sh.n_facets = 1;
#endif
    memset(&bad_tsi, 0, sizeof bad_tsi);
    bad_tsi.tsi_w_m2 = (oi_real)NAN;
    memset(&knocke, 0, sizeof knocke);
    knocke.albedo_model = OI_ALBEDO_KNOCKE;
    memset(&map, 0, sizeof map);
    map.albedo_model = OI_ALBEDO_MAP;
    map.albedo_map = nan_map;
    map.albedo_map_n_lat = 1;
    map.albedo_map_n_lon = 1;
    lit_scene(&s);
    expect_st(ST_EARTH, oi_illuminate(&s, NULL, &il), "illuminate valid");
    expect_st(OI_ERR_NULL, oi_illuminate(NULL, NULL, &il), "illuminate NULL");
    expect_st(OI_ERR_MODEL, oi_illuminate(&s, &bad_tsi, &il), "illuminate model");
    s.terms = 16u;
    expect_st(OI_ERR_TERMS, oi_illuminate(&s, NULL, &il), "illuminate terms");
    lit_scene(&s);
    s.target_km[2] = (oi_real)INFINITY;
    expect_st(OI_ERR_NONFINITE, oi_illuminate(&s, NULL, &il), "illuminate inf");
    lit_scene(&s);
    s.target_radius_m = (oi_real)NAN;
    expect_st(OI_ERR_NONFINITE, oi_illuminate(&s, NULL, &il), "illuminate radius NaN");
    lit_scene(&s);
    s.earth_albedo = 2;
    expect_st(OI_ERR_ALBEDO, oi_illuminate(&s, NULL, &il), "illuminate albedo");
    lit_scene(&s);
    s.target_radius_m = 0;
    expect_st(OI_ERR_RADIUS, oi_illuminate(&s, NULL, &il), "illuminate radius 0");
    lit_scene(&s);
    s.target_km[0] = 0;
    expect_st(OI_ERR_ZERO_VECTOR, oi_illuminate(&s, NULL, &il), "illuminate zero target");
    lit_scene(&s);
    s.observer_km[0] = (oi_real)3e38;
    expect_st(OI_ERR_GEOMETRY, oi_illuminate(&s, NULL, &il), "illuminate observer far");
    lit_scene(&s);
    s.target_km[0] = 100;
    expect_st(OI_ERR_BELOW_SURFACE, oi_illuminate(&s, NULL, &il), "illuminate target below");
#ifndef OI_NO_FACETS
    lit_scene(&s);
    s.shape = &sh;
    f.area_m2 = -1;
    expect_st(OI_ERR_SHAPE, oi_illuminate(&s, NULL, &il), "illuminate bad facet");
    f.area_m2 = 1;
#ifdef OI_SINGLE_PRECISION
    s.attitude_q[1] = (oi_real)1e-30; /* its square underflows */
#else
    s.attitude_q[1] = (oi_real)1e-300;
#endif
    expect_st(OI_ERR_SHAPE, oi_illuminate(&s, NULL, &il), "illuminate quaternion tiny");
    s.attitude_q[1] = (oi_real)3e38;
    expect_st(OI_ERR_SHAPE, oi_illuminate(&s, NULL, &il), "illuminate quaternion huge");
    s.attitude_q[1] = (oi_real)NAN;
    expect_st(OI_ERR_SHAPE, oi_illuminate(&s, NULL, &il), "illuminate quaternion NaN");
    s.attitude_q[1] = 0;
    s.observer_km[1] = 0;
    expect_st(OI_ERR_OBSERVER_AT_TARGET, oi_illuminate(&s, NULL, &il), "illuminate shape at target");
#endif
#ifndef OI_NO_ALBEDO_MODELS
    lit_scene(&s);
    s.epoch_jd = (oi_real)NAN;
    expect_st(OI_ERR_NONFINITE, oi_illuminate(&s, &knocke, &il), "illuminate epoch NaN");
    s.epoch_jd = 1;
    expect_st(OI_ERR_INPUT, oi_illuminate(&s, &knocke, &il), "illuminate epoch out");
    lit_scene(&s);
    s.earth_rotation_rad = (oi_real)-INFINITY;
    expect_st(OI_ERR_NONFINITE, oi_illuminate(&s, &map, &il), "illuminate rotation inf");
    s.earth_rotation_rad = (oi_real)1e30;
    expect_st(OI_ERR_INPUT, oi_illuminate(&s, &map, &il), "illuminate rotation out");
    s.earth_rotation_rad = 0;
    expect_st(OI_ERR_ALBEDO, oi_illuminate(&s, &map, &il), "illuminate map NaN");
#endif
    lit_scene(&s);
    s.sun_km[0] = (oi_real)1e5;
    expect_st(OI_ERR_GEOMETRY, oi_illuminate(&s, NULL, &il), "illuminate Sun at Earth");
#ifndef OI_NO_MOON
    lit_scene(&s);
    s.moon_km[0] = 7000;
    s.moon_km[1] = 0;
    expect_st(OI_ERR_GEOMETRY, oi_illuminate(&s, NULL, &il), "illuminate target in the Moon");
    lit_scene(&s);
    s.moon_km[1] = 10;
    expect_st(OI_ERR_BELOW_SURFACE, oi_illuminate(&s, NULL, &il), "illuminate Moon below");
#endif
    lit_scene(&s);
    s.observer_km[1] = 0;
    expect_st(OI_ERR_OBSERVER_AT_TARGET, oi_illuminate(&s, NULL, &il), "illuminate at target");
    s.observer_km[1] = (oi_real)1e-30;
    expect_st(OI_ERR_OBSERVER_AT_TARGET, oi_illuminate(&s, NULL, &il), "illuminate 1e-30 km away");
    s.target_radius_m = (oi_real)3e38;
    s.observer_km[1] = (oi_real)1e-30;
    expect_st(OI_ERR_OBSERVER_AT_TARGET, oi_illuminate(&s, NULL, &il), "illuminate huge radius");
}

#ifndef OI_NO_EXPOSURE
static void errors_exposure(void)
{
    const oi_camera *c0 = oi_camera_builtin(0);
    oi_camera bad = *c0;
    oi_expose_in in, in1;
    oi_expose_goal g;
    oi_exposure e;
    oi_scene s;
    oi_illum il, il1;
    oi_model bad_tsi;
    int st[2];
    memset(&in, 0, sizeof in);
    in.flux_w_m2 = (oi_real)1e-12;
    memset(&g, 0, sizeof g);
    memset(&bad_tsi, 0, sizeof bad_tsi);
    bad_tsi.tsi_w_m2 = -1;
    bad.aperture_m = -1;
    expect_st(OI_OK, oi_expose(c0, &in, NULL, &e), "expose valid");
    expect_st(OI_ERR_NULL, oi_expose(NULL, &in, NULL, &e), "expose NULL");
    expect_st(OI_ERR_CAMERA, oi_expose(&bad, &in, NULL, &e), "expose camera");
    bad = *c0;
    bad.times_s[1] = (oi_real)NAN;
    expect_st(OI_ERR_CAMERA, oi_expose(&bad, &in, NULL, &e), "expose camera time NaN");
    bad = *c0;
    bad.full_well_e = (oi_real)INFINITY;
    expect_st(OI_ERR_CAMERA, oi_expose(&bad, &in, NULL, &e), "expose camera well inf");
    g.fill = 2;
    expect_st(OI_ERR_INPUT, oi_expose(c0, &in, &g, &e), "expose goal fill");
    g.fill = (oi_real)NAN;
    expect_st(OI_ERR_INPUT, oi_expose(c0, &in, &g, &e), "expose goal NaN");
    g.fill = 0;
    g.sky = 1u << 20;
    expect_st(OI_ERR_FLAGS, oi_expose(c0, &in, &g, &e), "expose goal sky");
    g.sky = 0;
    in1 = in;
    in1.flux_w_m2 = (oi_real)NAN;
    expect_st(OI_ERR_NONFINITE, oi_expose(c0, &in1, NULL, &e), "expose flux NaN");
    in1.flux_w_m2 = -1;
    expect_st(OI_ERR_INPUT, oi_expose(c0, &in1, NULL, &e), "expose flux < 0");
    in1.flux_w_m2 = (oi_real)3e38;
    expect_st(OI_ERR_MAGNITUDE, oi_expose(c0, &in1, NULL, &e), "expose flux bright");
    in1 = in;
    in1.background_w_m2_sr = (oi_real)3e38;
    expect_st(OI_ERR_INPUT, oi_expose(c0, &in1, NULL, &e), "expose background");
    in1 = in;
    in1.flags = 1u << 30;
    expect_st(OI_ERR_FLAGS, oi_expose(c0, &in1, NULL, &e), "expose flags");
    in1 = in;
    in1.rate_rad_s = (oi_real)-INFINITY;
    expect_st(OI_ERR_NONFINITE, oi_expose(c0, &in1, NULL, &e), "expose rate inf");
    in1.rate_rad_s = (oi_real)3e38;
    expect_st(OI_ERR_INPUT, oi_expose(c0, &in1, NULL, &e), "expose rate");
    g.has_sensor_temp = 1;
    g.sensor_temp_c = (oi_real)NAN;
    expect_st(OI_ERR_NONFINITE, oi_expose(c0, &in, &g, &e), "expose temperature NaN");
    g.sensor_temp_c = (oi_real)3e38;
    expect_st(OI_ERR_INPUT, oi_expose(c0, &in, &g, &e), "expose temperature");
    g.has_sensor_temp = 0;

    lit_scene(&s);
    s.terms = OI_TERM_SUN | OI_TERM_EARTH;
    expect_st(ST_EARTH, oi_illuminate(&s, NULL, &il), "illuminate for expose_scene");
    expect_st(OI_OK, oi_expose_scene(c0, &s, &il, NULL, NULL, &e), "expose_scene valid");
    s.has_observer = 0;
    expect_st(OI_ERR_NULL, oi_expose_scene(c0, &s, &il, NULL, NULL, &e), "expose_scene no observer");
    s.has_observer = 1;
    expect_st(OI_ERR_MODEL, oi_expose_scene(c0, &s, &il, &bad_tsi, NULL, &e), "expose_scene model");
    s.observer_km[2] = (oi_real)NAN;
    expect_st(OI_ERR_NONFINITE, oi_expose_scene(c0, &s, &il, NULL, NULL, &e), "expose_scene NaN");
    s.observer_km[2] = 0;
    s.target_albedo = -1;
    expect_st(OI_ERR_ALBEDO, oi_expose_scene(c0, &s, &il, NULL, NULL, &e), "expose_scene albedo");
    s.target_albedo = (oi_real)NAN;
    expect_st(OI_ERR_ALBEDO, oi_expose_scene(c0, &s, &il, NULL, NULL, &e), "expose_scene albedo NaN");
    s.target_albedo = (oi_real)0.2;
    il1 = il;
    il1.e_sun = (oi_real)INFINITY;
    expect_st(OI_ERR_NONFINITE, oi_expose_scene(c0, &s, &il1, NULL, NULL, &e), "expose_scene e_sun");
    il1 = il;
    il1.flux_obs = -1;
    expect_st(OI_ERR_INPUT, oi_expose_scene(c0, &s, &il1, NULL, NULL, &e), "expose_scene flux < 0");
    il1 = il;
    il1.flux_obs = (oi_real)3e38;
    il1.e_sun = (oi_real)3e38;
    expect_st(OI_ERR_MAGNITUDE, oi_expose_scene(c0, &s, &il1, NULL, NULL, &e), "expose_scene huge flux");
    bad = *c0;
    bad.fov_rad = (oi_real)NAN;
    expect_st(OI_ERR_CAMERA, oi_expose_scene(&bad, &s, &il, NULL, NULL, &e), "expose_scene camera");
    s.observer_km[0] = s.observer_km[1] = s.observer_km[2] = 0;
    expect_st(OI_ERR_ZERO_VECTOR, oi_expose_scene(c0, &s, &il, NULL, NULL, &e), "expose_scene zero");
    lit_scene(&s);
    s.terms = OI_TERM_SUN | OI_TERM_EARTH;
    s.target_vel_km_s[0] = (oi_real)NAN;
    expect_st(OI_ERR_NONFINITE, oi_expose_scene(c0, &s, &il, NULL, NULL, &e), "expose_scene velocity NaN");
    s.target_vel_km_s[0] = (oi_real)3e38;
    expect_st(OI_ERR_INPUT, oi_expose_scene(c0, &s, &il, NULL, NULL, &e), "expose_scene velocity");
    s.target_vel_km_s[0] = 0;
    s.observer_km[0] = 10;
    expect_st(OI_ERR_BELOW_SURFACE, oi_expose_scene(c0, &s, &il, NULL, NULL, &e), "expose_scene below");
    lit_scene(&s);
    s.terms = OI_TERM_SUN | OI_TERM_EARTH;
    s.observer_km[1] = 0;
    expect_st(OI_ERR_OBSERVER_AT_TARGET, oi_expose_scene(c0, &s, &il, NULL, NULL, &e), "expose_scene at target");
    s.observer_km[1] = 50;
    g.snr_min = -1;
    expect_st(OI_ERR_INPUT, oi_expose_scene(c0, &s, &il, NULL, &g, &e), "expose_scene goal");
    g.snr_min = 0;

    /* the batches' own errors */
    expect_st(OI_ERR_INPUT, oi_expose_batch(-1, c0, &in, NULL, &e, st), "expose_batch n < 0");
    expect_st(OI_ERR_NULL, oi_expose_batch(1, c0, NULL, NULL, &e, st), "expose_batch NULL");
    expect_st(OI_ERR_CAMERA, oi_expose_batch(1, &bad, &in, NULL, &e, st), "expose_batch camera");
    expect_st(OI_ERR_FLAGS, oi_expose_batch_outputs(1, c0, &in, NULL, 1u << 20, &e, st), "expose_batch mask");
    in1 = in;
    in1.flux_w_m2 = (oi_real)NAN;
    expect_st(1, oi_expose_batch(1, c0, &in1, NULL, &e, st), "expose_batch NaN row");
    expect_st(OI_ERR_MODEL, oi_expose_scene_batch(1, c0, &s, &il, &bad_tsi, NULL, &e, st), "expose_scene_batch model");
    s.observer_km[1] = 0;
    expect_st(1, oi_expose_scene_batch(1, c0, &s, &il, NULL, NULL, &e, st), "expose_scene_batch at target");
    expect_st(1, oi_illuminate_batch(1, &s, NULL, &il, st), "illuminate_batch at target");
    expect_st(OI_ERR_MODEL, oi_illuminate_batch(1, &s, &bad_tsi, &il, st), "illuminate_batch model");
    expect_st(OI_ERR_FLAGS, oi_illuminate_batch_outputs(1, &s, NULL, 1u << 20, &il, st), "illuminate_batch mask");
}
#endif

static void errors_batches(void)
{
    const oi_real sun1[6] = {(oi_real)1.496e8, 0, 0, 0, 0, 0}, pt[6] = {7000, 0, 0, (oi_real)NAN, 0, 0};
    const oi_real th[2] = {1, (oi_real)NAN}, hh[2] = {500, -1};
    oi_shadow sh[2];
    oi_real ph[2], ps[2];
    int st[2];
    expect_st(OI_ERR_INPUT, oi_sun_fraction_batch(-1, sun1, pt, NULL, OI_BATCH_ALL, sh, st), "sun_fraction_batch n");
    expect_st(OI_ERR_NULL, oi_sun_fraction_batch(2, NULL, pt, NULL, OI_BATCH_ALL, sh, st), "sun_fraction_batch NULL");
    expect_st(OI_ERR_FLAGS, oi_sun_fraction_batch(2, sun1, pt, NULL, 1u << 20, sh, st), "sun_fraction_batch mask");
    expect_st(1, oi_sun_fraction_batch(2, sun1, pt, NULL, OI_BATCH_ALL, sh, st), "sun_fraction_batch rows");
    expect_st(1, oi_earthshine_batch(2, th, hh, NULL, ph, ps, st), "earthshine_batch rows");
    expect_st(OI_ERR_INPUT, oi_earthshine_batch(2, th, hh, NULL, ph, (oi_real *)th, st), "earthshine_batch overlap");
}

/* Random hostile inputs: each component from a list of edges (zeros, NaN,
 * infinities, subnormals, the largest values, the Earth's radius): any
 * status, never a harmful flag. */
static void hostile_sweep(void)
{
    /* in the build's precision: no conversion of the test's raises a flag */
#ifdef OI_SINGLE_PRECISION
    static const oi_real edges[] = {0.0f, -0.0f, 1.0f, -1.0f, 6378.137f, 6378.138f, 7000.0f,
                                    42164.0f, 1.496e8f, 1e-40f, -1e-40f, 1e-30f, 1e12f, -1e12f,
                                    1e13f, -1e13f, NAN, INFINITY, -INFINITY, 1e13f, 695700.0f,
                                    0.5f};
#else
    static const oi_real edges[] = {0.0, -0.0, 1.0, -1.0, 6378.137, 6378.1370001, 7000.0, 42164.0,
                                    1.496e8, 1e-310, -1e-310, 1e-30, 1e12, -1e12, 1e13, -1e13,
                                    NAN, INFINITY, -INFINITY, 1e13, 695700.0, 0.5};
#endif
    const int ne = (int)(sizeof edges / sizeof edges[0]);
    uint64_t seed = 20261207u;
    int k, i;
    for (k = 0; k < 3000; k++) {
        oi_scene s;
        oi_illum il;
        oi_shadow sh;
        oi_real phi1, psi1, o[3];
        lit_scene(&s);
        for (i = 0; i < 3; i++) {
            if (lcg01(&seed) < 0.3) s.target_km[i] = edges[(int)(lcg01(&seed) * ne)];
            if (lcg01(&seed) < 0.3) s.observer_km[i] = edges[(int)(lcg01(&seed) * ne)];
            if (lcg01(&seed) < 0.2) s.sun_km[i] = edges[(int)(lcg01(&seed) * ne)];
            if (lcg01(&seed) < 0.2) s.moon_km[i] = edges[(int)(lcg01(&seed) * ne)];
            if (lcg01(&seed) < 0.1) s.target_vel_km_s[i] = edges[(int)(lcg01(&seed) * ne)];
            o[i] = edges[(int)(lcg01(&seed) * ne)];
        }
        if (lcg01(&seed) < 0.2) s.target_radius_m = edges[(int)(lcg01(&seed) * ne)];
        if (lcg01(&seed) < 0.1) s.earth_albedo = edges[(int)(lcg01(&seed) * ne)];
        feclearexcept(FE_ALL_EXCEPT);
        (void)oi_illuminate(&s, NULL, &il);
        expect_quiet("hostile oi_illuminate");
        feclearexcept(FE_ALL_EXCEPT);
        (void)oi_sun_fraction(s.sun_km, s.target_km, NULL, &sh);
        expect_quiet("hostile oi_sun_fraction");
        feclearexcept(FE_ALL_EXCEPT);
        (void)oi_earthshine(o[0], o[1], NULL, &phi1, &psi1);
        expect_quiet("hostile oi_earthshine");
        feclearexcept(FE_ALL_EXCEPT);
        (void)oi_earthshine_sphere(o[0], o[1], o, NULL, &phi1);
        expect_quiet("hostile oi_earthshine_sphere");
#ifndef OI_NO_EXPOSURE
        {
            oi_exposure e;
            oi_expose_in in;
            memset(&in, 0, sizeof in);
            in.flux_w_m2 = edges[(int)(lcg01(&seed) * ne)];
            in.background_w_m2_sr = edges[(int)(lcg01(&seed) * ne)];
            in.rate_rad_s = lcg01(&seed) < 0.5 ? 0 : edges[(int)(lcg01(&seed) * ne)];
            feclearexcept(FE_ALL_EXCEPT);
            (void)oi_expose(oi_camera_builtin(k & 1), &in, NULL, &e);
            expect_quiet("hostile oi_expose");
            if (lcg01(&seed) < 0.3) il.e_sun = edges[(int)(lcg01(&seed) * ne)];
            if (lcg01(&seed) < 0.3) il.flux_obs = edges[(int)(lcg01(&seed) * ne)];
            feclearexcept(FE_ALL_EXCEPT);
            (void)oi_expose_scene(oi_camera_builtin(k & 1), &s, &il, NULL, NULL, &e);
            expect_quiet("hostile oi_expose_scene");
        }
#endif
    }
}

static void run_errors(void)
{
    feclearexcept(FE_ALL_EXCEPT);
    errors_geometry();
#ifndef OI_NO_FACETS
    errors_shapes();
#endif
    errors_scene();
#ifndef OI_NO_EXPOSURE
    errors_exposure();
#endif
    errors_batches();
    hostile_sweep();
}

static void test_error_paths(void **state)
{
    (void)state;
    error_mismatches = 0;
    run_errors();
    check_int(0, error_mismatches, "error paths with a wrong status or a harmful flag");
}

static void test_error_paths_trapped(void **state)
{
    (void)state;
#if defined(__GLIBC__) && (defined(__x86_64__) || defined(__i386__))
    error_mismatches = 0;
    assert_true(feenableexcept(HARMFUL) != -1);
    run_errors();
    (void)fedisableexcept(HARMFUL);
    check_int(0, error_mismatches, "error paths with traps enabled");
#else
    printf("# skip traps: feenableexcept needs glibc on x86\n");
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_flags_clear),
        cmocka_unit_test(test_traps_enabled),
        cmocka_unit_test(test_error_paths),
        cmocka_unit_test(test_error_paths_trapped),
    };
    make_scenes();
    return cmocka_run_group_tests(tests, NULL, NULL);
}
