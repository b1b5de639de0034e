/* SPDX-License-Identifier: MIT */
/* test_degenerate.c: inputs at the edge of what the contract accepts give
 * the contract's answer: an attitude quaternion whose squared
 * norm underflows is OI_ERR_SHAPE (not the identity), a facet normal of
 * subnormal length is normalised correctly (not to (0.5, 0.5, 0.5)), an
 * observer at the target is OI_ERR_OBSERVER_AT_TARGET without a division by
 * zero, and in single precision an observer 1 m from a target at 42,000 km,
 * whose position rounds onto the target's, is that error too. */
#define _GNU_SOURCE /* feenableexcept (glibc) */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "orbillum.h"
#include "oi_test_util.h"

#define HARMFUL (FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW)
#ifdef OI_SINGLE_PRECISION
#define EPS 1.1920929e-7
#else
#define EPS 2.220446049250313e-16
#endif

static void traps_on(void)
{
#if defined(__GLIBC__) && (defined(__x86_64__) || defined(__i386__))
    (void)feenableexcept(HARMFUL);
#endif
    feclearexcept(FE_ALL_EXCEPT);
}

static void traps_off(void)
{
#if defined(__GLIBC__) && (defined(__x86_64__) || defined(__i386__))
    (void)fedisableexcept(HARMFUL);
#endif
    check_int(0, fetestexcept(HARMFUL), "harmful flags raised");
    feclearexcept(FE_ALL_EXCEPT);
}

#ifndef OI_NO_FACETS
/* A lit facet target seen at 10 km: the Sun along +x, the observer off
 * the x axis, so that a facet of normal (1, 1, 1) is lit and seen. */
static void facet_scene(oi_scene *s, const oi_shape *sh)
{
    oi_scene_defaults(s);
    s->terms = OI_TERM_SUN;
    s->sun_km[0] = (oi_real)1.496e8;
    s->target_km[0] = 7000;
    s->observer_km[0] = 7006;
    s->observer_km[1] = 6;
    s->observer_km[2] = 5;
    s->has_observer = 1;
    s->shape = sh;
}

static void test_quaternion_underflow_refused(void **state)
{
    oi_facet f;
    oi_shape sh;
    oi_scene s;
    oi_illum il;
    /* a component whose square underflows in the build's precision */
#ifdef OI_SINGLE_PRECISION
    const oi_real tiny = (oi_real)1e-30;
#else
    const oi_real tiny = (oi_real)1e-300;
#endif
    (void)state;
    memset(&f, 0, sizeof f);
    f.normal[0] = f.normal[1] = f.normal[2] = 1;
    f.area_m2 = 1;
    f.albedo_diffuse = (oi_real)0.5;
    memset(&sh, 0, sizeof sh);
    sh.facets = &f;
    sh.n_facets = 1;
    facet_scene(&s, &sh);
    traps_on();
    check_int(OI_OK, oi_illuminate(&s, NULL, &il), "all zero: the identity");
    s.attitude_q[0] = tiny;
    check_int(OI_ERR_SHAPE, oi_illuminate(&s, NULL, &il), "(tiny, 0, 0, 0)");
    s.attitude_q[0] = 0;
    s.attitude_q[3] = -tiny;
    check_int(OI_ERR_SHAPE, oi_illuminate(&s, NULL, &il), "(0, 0, 0, -tiny)");
    s.attitude_q[3] = (oi_real)1e30; /* its square would overflow */
    check_int(OI_ERR_SHAPE, oi_illuminate(&s, NULL, &il), "(0, 0, 0, 1e30)");
    s.attitude_q[0] = (oi_real)-0.0;
    s.attitude_q[3] = (oi_real)-0.0;
    check_int(OI_OK, oi_illuminate(&s, NULL, &il), "negative zeros: the identity");
    traps_off();
}

/* A facet of normal (d, d, d), d subnormal, lights and is seen as the one
 * of normal (1, 1, 1): the same flux to a few ulp. */
static void test_subnormal_normal(void **state)
{
    oi_facet f;
    oi_shape sh;
    oi_scene s;
    oi_illum unit, tiny;
    oi_real e_unit, e_tiny;
    const oi_real to_s[3] = {1, 0, 0}, to_o[3] = {(oi_real)0.6, (oi_real)0.6, (oi_real)0.5};
    oi_real b_unit, b_tiny;
    int k, st_unit;
#ifdef OI_SINGLE_PRECISION
    const oi_real ds[3] = {(oi_real)1.4e-45, (oi_real)3e-42, (oi_real)1e-39};
#else
    const oi_real ds[3] = {(oi_real)4.9e-324, (oi_real)1e-315, (oi_real)2e-310};
#endif
    (void)state;
    memset(&f, 0, sizeof f);
    f.normal[0] = f.normal[1] = f.normal[2] = 1;
    f.area_m2 = 1;
    f.albedo_diffuse = (oi_real)0.5;
    memset(&sh, 0, sizeof sh);
    sh.facets = &f;
    sh.n_facets = 1;
    facet_scene(&s, &sh);
    check_int(OI_OK, oi_illuminate(&s, NULL, &unit), "unit normal");
    assert_true(unit.flux_obs > 0);
    b_unit = oi_facet_brdf(&f, to_s, to_o);
    st_unit = oi_earthshine_plate((oi_real)0.5, 500, f.normal, NULL, &e_unit);
    check_int(1, st_unit >= 0, "plate (a warning where an option leaves the table out)");
    for (k = 0; k < 3; k++) {
        f.normal[0] = f.normal[1] = f.normal[2] = ds[k];
        assert_true(f.normal[0] > 0);
        check_int(OI_OK, oi_shape_check(&sh), "shape check");
        check_int(OI_OK, oi_illuminate(&s, NULL, &tiny), "subnormal normal");
        check_rel(unit.flux_obs, tiny.flux_obs, 8 * EPS, "flux");
        b_tiny = oi_facet_brdf(&f, to_s, to_o);
        check_rel(b_unit, b_tiny, 8 * EPS, "brdf");
        check_int(st_unit, oi_earthshine_plate((oi_real)0.5, 500, f.normal, NULL, &e_tiny), "plate");
        check_rel(e_unit, e_tiny, 8 * EPS, "plate irradiance");
    }
}

#endif /* OI_NO_FACETS */

/* The observer exactly at the target: the error, no trap, in both
 * precisions; oi_expose_scene the same. */
static void test_observer_at_target(void **state)
{
    oi_scene s;
    oi_illum il;
#ifndef OI_NO_EXPOSURE
    oi_exposure e;
#endif
    int st = 0;
    (void)state;
    oi_scene_defaults(&s);
    s.terms = OI_TERM_SUN | OI_TERM_EARTH;
    s.sun_km[0] = (oi_real)1.496e8;
    s.target_km[1] = 42000;
    s.observer_km[1] = 42000;
    s.has_observer = 1;
    traps_on();
    check_int(OI_ERR_OBSERVER_AT_TARGET, oi_illuminate(&s, NULL, &il), "oi_illuminate");
    check_int(1, oi_illuminate_batch(1, &s, NULL, &il, &st), "oi_illuminate_batch");
    check_int(OI_ERR_OBSERVER_AT_TARGET, st, "oi_illuminate_batch row");
#ifndef OI_NO_EXPOSURE
    memset(&il, 0, sizeof il);
    check_int(OI_ERR_OBSERVER_AT_TARGET,
              oi_expose_scene(oi_camera_builtin(0), &s, &il, NULL, NULL, &e), "oi_expose_scene");
#endif
    traps_off();
}

/* An observer 1 m from a target at 42,000 km, the target of radius 0.5 m.
 * Double: computed, range 1 m. Single precision: 42,000.001 km rounds to
 * 42,000 (the spacing of floats there is 3.9 m): the positions given are
 * equal, and the answer is the contract's for them,
 * OI_ERR_OBSERVER_AT_TARGET (never a trap, never a flux from a range of 0). */
static void test_observer_one_metre_at_geo(void **state)
{
    oi_scene s;
    oi_illum il;
#ifndef OI_NO_EXPOSURE
    oi_exposure e;
#endif
    int st;
    (void)state;
    oi_scene_defaults(&s);
    s.terms = OI_TERM_SUN | OI_TERM_EARTH;
    s.sun_km[0] = (oi_real)1.496e8;
    s.target_km[1] = 42000;
    s.observer_km[1] = (oi_real)42000.001;
    s.target_radius_m = (oi_real)0.5;
    s.has_observer = 1;
    traps_on();
    st = oi_illuminate(&s, NULL, &il);
#ifdef OI_SINGLE_PRECISION
    assert_true(s.observer_km[1] == s.target_km[1]);
    check_int(OI_ERR_OBSERVER_AT_TARGET, st, "single: rounds onto the target");
#ifndef OI_NO_EXPOSURE
    check_int(OI_ERR_OBSERVER_AT_TARGET,
              oi_expose_scene(oi_camera_builtin(0), &s, &il, NULL, NULL, &e), "oi_expose_scene");
#endif
#else
    /* computed (a warning, not an error, where an option leaves a table out) */
    check_int(1, st >= 0, "double: 1 m");
    check_rel(s.observer_km[1] - s.target_km[1], il.range_km, 4 * EPS, "range (the difference, exact)");
    check_rel(1e-3, il.range_km, 1e-8, "range, 1 m");
    assert_true(il.flux_obs > 0);
#ifndef OI_NO_EXPOSURE
    check_int(OI_OK, oi_expose_scene(oi_camera_builtin(0), &s, &il, NULL, NULL, &e),
              "oi_expose_scene");
#endif
#endif
    traps_off();
}

/* A Sun at the largest oi_real beside a point at 2.8e7 km: the batch's
 * certain-region test leaves the row to the full call, which refuses it
 * (sun - point would overflow, found from the halves), so the batch row has
 * the single call's status (found by fuzz_batch). */
static void test_batch_far_sun(void **state)
{
#ifdef OI_SINGLE_PRECISION
    const oi_real big = FLT_MAX;
#else
    const oi_real big = DBL_MAX;
#endif
    const oi_real sun[3] = {big, (oi_real)-2e7, (oi_real)-2e7};
    const oi_real pt[3] = {(oi_real)1e-6, (oi_real)-2e7, (oi_real)-2e7};
    oi_shadow one, row;
    int st = 99, single;
    (void)state;
    single = oi_sun_fraction(sun, pt, NULL, &one);
    (void)oi_sun_fraction_batch(1, sun, pt, NULL, OI_BATCH_FRACTION_LD, &row, &st);
    check_int(single, st, "batch row status as the single call's");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
#ifndef OI_NO_FACETS
        cmocka_unit_test(test_quaternion_underflow_refused),
        cmocka_unit_test(test_subnormal_normal),
#endif
        cmocka_unit_test(test_observer_at_target),
        cmocka_unit_test(test_observer_one_metre_at_geo),
        cmocka_unit_test(test_batch_far_sun),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
