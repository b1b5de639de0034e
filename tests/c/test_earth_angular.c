/* SPDX-License-Identifier: MIT */
/* test_earth_angular.c: a Lambertian sphere's flux under earthshine
 * (oi_earthshine_sphere, oi_illuminate) against closed forms written here:
 * the far field (a point Earth at the nadir, F = (R/r)^2 p(theta) p(xi)), the
 * mean-direction option (phi p(xi)), the mirror symmetry, the case the mean
 * direction gets wrong (the observer above a target over the sub-solar
 * point), the compile-time option that removes the table, hostile inputs;
 * and the default cubature against the quadrature over the visible sunlit
 * Earth (tests/c/ref_sphere.h, no table) in units of the goal. More random
 * points: tests/python/test_earth_angular.py. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "orbillum.h"
#include "oi_test_util.h"
#include "ref_sphere.h"

static const double PI = 3.14159265358979323846;
static const double R = 6378.137;

#ifdef OI_SINGLE_PRECISION
#define REL_TOL 3e-5
#else
#define REL_TOL 1e-12
#endif

/* without the earthshine table phi is the Lambert far field, with its warning */
#ifdef OI_NO_EARTH_TABLE
#define ST_EARTH OI_WARN_TABLE_RANGE
#else
#define ST_EARTH OI_OK
#endif

#if defined(OI_NO_EARTH_ANGULAR) || defined(OI_NO_EARTH_TABLE)
#define HAVE_MOMENTS 0
#else
#define HAVE_MOMENTS 1
#endif

static double phase_ref(double xi)
{
    return 2.0 / (3.0 * PI) * ((PI - xi) * cos(xi) + sin(xi));
}

static double sphere(double theta, double h, double ox, double oy, double oz, int reflection,
                     int *status)
{
    oi_model m;
    oi_real o[3], f = (oi_real)-1;
    memset(&m, 0, sizeof m);
    m.earth_reflection = reflection;
    set3(o, ox, oy, oz);
    *status = oi_earthshine_sphere((oi_real)theta, (oi_real)h, o, &m, &f);
    return (double)f;
}

static void test_far_field_closed_form(void **state)
{
    /* 1e7 km: the visible Earth is 0.04 deg wide, a point at the nadir to
     * 1e-6; its light is phi = x^2 p(theta) */
    const double h = 1e7, x = R / (R + h);
    const double thetas[3] = {0.2, 1.4, 2.6}, angles[3] = {0.3, 1.6, 2.8};
    int i, j, st;
    (void)state;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            const double a = angles[j];
            const double f = sphere(thetas[i], h, sin(a), 0.0, cos(a), OI_EARTH_REFLECT_MOMENTS, &st);
            const double want = x * x * phase_ref(thetas[i]) * phase_ref(PI - a);
            check_int(ST_EARTH, st, "status");
            check_close(want, f, 1e-4 * x * x * phase_ref(thetas[i]) * (2.0 / 3.0), 1e-2,
                        "far-field sphere flux");
        }
}

static void test_mean_direction_option(void **state)
{
    const double theta = 1.1, h = 800.0;
    oi_real phi, psi;
    int st;
    double f, dx, dz, xi;
    (void)state;
    assert_int_equal(oi_earthshine((oi_real)theta, (oi_real)h, NULL, &phi, &psi), ST_EARTH);
    f = sphere(theta, h, 0.6, 0.0, 0.8, OI_EARTH_REFLECT_MEAN, &st);
    check_int(ST_EARTH, st, "status");
    dx = sin((double)psi);
    dz = -cos((double)psi);
    xi = acos(0.6 * dx + 0.8 * dz);
    check_rel((double)phi * phase_ref(xi), f, REL_TOL * 10, "phi p(xi)");
}

static void test_subsolar_zenith_observer(void **state)
{
    /* over the sub-solar point the mean direction is the nadir: nothing goes
     * up; the real Earth lights the sphere's sides */
    int st;
    double mean, moments;
    (void)state;
    mean = sphere(0.0, 500.0, 0.0, 0.0, 1.0, OI_EARTH_REFLECT_MEAN, &st);
    check_int(ST_EARTH, st, "status");
    moments = sphere(0.0, 500.0, 0.0, 0.0, 1.0, OI_EARTH_REFLECT_MOMENTS, &st);
    check_int(ST_EARTH, st, "status");
    assert_true(mean <= 1e-6);
    if (HAVE_MOMENTS)
        assert_true(moments > 0.01);
    else
        assert_true(moments == mean);
}

static void test_mirror_symmetry(void **state)
{
    int st;
    (void)state;
    check_rel(sphere(1.7, 3000.0, 0.2, 0.5, -0.3, 0, &st), sphere(1.7, 3000.0, 0.2, -0.5, -0.3, 0, &st),
              REL_TOL, "y -> -y");
}

static void test_illuminate_matches(void **state)
{
    oi_scene s;
    oi_illum out;
    int st;
    double f, scale;
    (void)state;
    oi_scene_defaults(&s);
    set3(s.sun_km, 1.496e8, 0, 0);
    set3(s.target_km, R + 500.0, 0, 0);
    set3(s.observer_km, R + 1000.0, 0, 0);
    s.has_observer = 1;
    s.terms = OI_TERM_EARTH;
    assert_int_equal(oi_illuminate(&s, NULL, &out), ST_EARTH);
    f = sphere(0.0, 500.0, 0.0, 0.0, 1.0, 0, &st);
    scale = (double)s.earth_albedo * 1361.0 * (149597870.7 / 1.496e8) * (149597870.7 / 1.496e8) *
            (double)s.target_albedo * pow((double)s.target_radius_m / 500e3, 2);
    check_rel(f * scale, (double)out.flux_earth, REL_TOL * 100, "flux_earth");
}

/* On the Sun-Earth axis the Sun-Earth-target plane is undefined: the sphere's
 * flux towards a horizontal observer must not depend on how the scene is
 * turned (the frame once degenerated there: x along the zenith, o = 0), and
 * equals oi_earthshine_sphere's at theta = 0 (its light is symmetric about
 * the zenith, so any horizontal direction does). */
static void test_sun_earth_axis_frame(void **state)
{
    static const double turn[3][3][3] = {
        {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
        {{-1, 0, 0}, {0, 2.220446049250313e-16, 1}, {0, 1, 2.220446049250313e-16}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}};
    const double sun[3] = {1.0578e8, 0, 1.0578e8}, tgt[3] = {11581.0917359, 0, 11581.0917359};
    const double obs[3] = {11581.0917359, 1.0, 11581.0917359};
    double flux[3], ref, scale, r = sqrt(2.0) * 11581.0917359;
    int k, i, j, st;
    (void)state;
    for (k = 0; k < 3; k++) {
        oi_scene s;
        oi_illum out;
        oi_scene_defaults(&s);
        for (i = 0; i < 3; i++) {
            double a = 0, b = 0, c = 0;
            for (j = 0; j < 3; j++) {
                a += turn[k][i][j] * sun[j];
                b += turn[k][i][j] * tgt[j];
                c += turn[k][i][j] * obs[j];
            }
            s.sun_km[i] = (oi_real)a;
            s.target_km[i] = (oi_real)b;
            s.observer_km[i] = (oi_real)c;
        }
        s.has_observer = 1;
        s.terms = OI_TERM_EARTH;
        assert_true(oi_illuminate(&s, NULL, &out) >= 0);
        flux[k] = (double)out.flux_earth;
        assert_true(flux[k] > 0.0);
    }
    check_rel(flux[1], flux[0], REL_TOL * 100, "turned scene");
    check_rel(flux[2], flux[0], REL_TOL * 100, "turned scene");
    if (!HAVE_MOMENTS) return;
    ref = sphere(0.0, r - R, 1.0, 0.0, 0.0, 0, &st);
    scale = 0.3 * 1361.0 * pow(149597870.7 / (sqrt(2.0) * 1.0578e8), 2) * 0.2 * pow(1.0 / 1e3, 2);
    check_rel(ref * scale, flux[0], REL_TOL * 1000, "oi_earthshine_sphere at theta = 0");
}

static void test_hostile(void **state)
{
    oi_real o[3], f;
    oi_model m;
    (void)state;
    set3(o, 0, 0, 1);
    f = 5;
    assert_int_equal(oi_earthshine_sphere(1, 500, NULL, NULL, &f), OI_ERR_NULL);
    assert_true(f == 0);
    assert_int_equal(oi_earthshine_sphere(1, 500, o, NULL, NULL), OI_ERR_NULL);
    set3(o, NAN, 0, 1);
    f = 5;
    assert_int_equal(oi_earthshine_sphere(1, 500, o, NULL, &f), OI_ERR_NONFINITE);
    assert_true(f == 0);
    set3(o, 0, 0, 0);
    f = 5;
    assert_int_equal(oi_earthshine_sphere(1, 500, o, NULL, &f), OI_ERR_ZERO_VECTOR);
    assert_true(f == 0);
    set3(o, 0, 0, 1);
    f = 5;
    assert_int_equal(oi_earthshine_sphere(1, -2, o, NULL, &f), OI_ERR_BELOW_SURFACE);
    assert_true(f == 0);
    memset(&m, 0, sizeof m);
    m.earth_reflection = 3;
    f = 5;
    assert_int_equal(oi_earthshine_sphere(1, 500, o, &m, &f), OI_ERR_MODEL);
    assert_true(f == 0);
}

/* The goal in its units (1 meets it): 1 % where the quadrature's flux
 * exceeds 1 % of its maximum over directions, 1e-4 of that maximum
 * elsewhere; the same test in both precisions. */
static void test_cubature_against_quadrature(void **state)
{
    size_t i, j;
    double worst = 0.0;
    (void)state;
    for (i = 0; i < sizeof sphere_refs / sizeof sphere_refs[0]; i++) {
        const sphere_ref *r = &sphere_refs[i];
        for (j = 0; j < 12; j++) {
            int st;
            const double f = sphere(r->theta, r->h_km, r->obs[j][0], r->obs[j][1], r->obs[j][2],
                                    OI_EARTH_REFLECT_MOMENTS, &st);
            const double want = HAVE_MOMENTS ? r->flux[j] : f;
            double score;
            check_int(ST_EARTH, st, "status");
            if (want > 0.01 * r->fmax)
                score = fabs(f / want - 1.0) / 0.01;
            else
                score = fabs(f - want) / r->fmax / 1e-4;
            if (score > worst) worst = score;
            if (score > 1.0)
                fprintf(stderr, "theta %.6f h %.3f obs %zu: %.9g want %.9g (%.3g goal units)\n",
                        r->theta, r->h_km, j, f, want, score);
        }
    }
    fprintf(stderr, "sphere cubature: max %.3g goal units\n", worst);
    assert_true(worst <= 1.0);
}

static void test_default_table(void **state)
{
    const oi_earth_angular_table *t = oi_earth_angular_default();
    (void)state;
    if (!HAVE_MOMENTS) {
        assert_null(t);
        return;
    }
    assert_non_null(t);
    assert_int_equal(t->format, OI_ANGULAR_FORMAT);
    assert_int_equal(t->kind, OI_TABLE_KIND_EARTH_ANGULAR);
    assert_true(t->l_max <= OI_ANGULAR_L_MAX && t->l_max % 2 == 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_far_field_closed_form),
        cmocka_unit_test(test_mean_direction_option),
        cmocka_unit_test(test_subsolar_zenith_observer),
        cmocka_unit_test(test_mirror_symmetry),
        cmocka_unit_test(test_illuminate_matches),
        cmocka_unit_test(test_sun_earth_axis_frame),
        cmocka_unit_test(test_hostile),
        cmocka_unit_test(test_default_table),
        cmocka_unit_test(test_cubature_against_quadrature),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
