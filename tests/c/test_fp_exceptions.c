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
 * with SIGFPE). */
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
        s->terms = OI_TERM_ALL;
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_flags_clear),
        cmocka_unit_test(test_traps_enabled),
    };
    make_scenes();
    return cmocka_run_group_tests(tests, NULL, NULL);
}
