/* SPDX-License-Identifier: MIT */
/* test_atan2.c: the runtime's own two-argument arctangent (src/atan2.c)
 * against a higher-precision reference: atan2l (long double: 64-bit or
 * 113-bit significand on the hosts we test on) for the double build, atan2 in
 * double for the float build. Errors in units in the last place of the
 * result's precision. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "orbillum.h"
#include "oi_test_util.h"

oi_real oi__atan2(oi_real y, oi_real x); /* internal, src/atan2.c */

#ifdef OI_SINGLE_PRECISION
#define REF_ATAN2 atan2
#else
#define REF_ATAN2 atan2l
#endif

/* Worst error allowed, in ulp of the exact result. */
#define MAX_ULP 1.0

static uint64_t lcg_state = 0x2545F4914F6CDD1DULL;
static double uniform01(void)
{
    return lcg01(&lcg_state);
}

static double worst_ulp;
static double worst_y, worst_x;

static void check_point(oi_real y, oi_real x)
{
    ref_real want = REF_ATAN2((ref_real)y, (ref_real)x);
    oi_real got = oi__atan2(y, x);
    ref_real err;
    if (want == 0) {
        if (got != 0) {
            print_error("atan2(%.9g, %.9g): want 0 got %.17g\n", (double)y, (double)x, (double)got);
            fail();
        }
        return;
    }
    err = ((ref_real)got - want) / ulp_of(want);
    if (err < 0) err = -err;
    if ((double)err > worst_ulp) {
        worst_ulp = (double)err;
        worst_y = (double)y;
        worst_x = (double)x;
    }
    if (!((double)err <= MAX_ULP)) {
        print_error("atan2(%.17g, %.17g): want %.21Lg got %.17g (%.3g ulp)\n", (double)y,
                    (double)x, (long double)want, (double)got, (double)err);
        fail();
    }
}

/* Random directions in every octant, magnitudes over many decades. */
static void test_random_points(void **state)
{
    int i;
    (void)state;
    worst_ulp = 0;
    for (i = 0; i < 400000; i++) {
        double a = (uniform01() * 2.0 - 1.0) * 3.141592653589793;
        double scale = pow(10.0, uniform01() * 40.0 - 20.0);
        check_point((oi_real)(scale * sin(a)), (oi_real)(scale * cos(a)));
    }
    print_message("oi__atan2 random: worst %.3f ulp at atan2(%.17g, %.17g)\n", worst_ulp, worst_y,
                  worst_x);
}

/* Ratios near the reduction's breakpoints (k/8 +- 1/16, where the nearest
 * node changes) and near the octant boundaries, and tiny / huge ratios. */
static void test_breakpoints(void **state)
{
    int k, j, sx, sy;
    (void)state;
    worst_ulp = 0;
    for (k = 0; k <= 16; k++) {
        double t0 = k / 16.0;
        for (j = -200; j <= 200; j++) {
            double t = t0 + j * 1e-9 * (1 + k);
            if (t <= 0 || t > 1) continue;
            for (sx = -1; sx <= 1; sx += 2)
                for (sy = -1; sy <= 1; sy += 2) {
                    check_point((oi_real)(sy * t), (oi_real)sx);
                    check_point((oi_real)sy, (oi_real)(sx * t));
                }
        }
    }
    for (j = 1; j < 300; j++) {
        double t = pow(10.0, -j * 0.1);
        check_point((oi_real)t, (oi_real)1);
        check_point((oi_real)1, (oi_real)t);
        check_point((oi_real)t, (oi_real)-1);
        check_point((oi_real)-1, (oi_real)-t);
    }
    print_message("oi__atan2 breakpoints: worst %.3f ulp at atan2(%.17g, %.17g)\n", worst_ulp,
                  worst_y, worst_x);
}

/* C99 F.9.1.4 values for zeros and infinities, NaN propagation. */
static void test_special_values(void **state)
{
    const oi_real inf = (oi_real)INFINITY, pi = (oi_real)3.14159265358979323846;
    (void)state;
    assert_true(oi__atan2((oi_real)0, (oi_real)1) == 0);
    assert_true(oi__atan2((oi_real)0, (oi_real)0) == 0);
    assert_true(!signbit(oi__atan2((oi_real)0, (oi_real)0)));
    assert_true(signbit(oi__atan2(-(oi_real)0, (oi_real)2)));
    assert_true(oi__atan2((oi_real)0, -(oi_real)0) == pi);
    assert_true(oi__atan2((oi_real)0, (oi_real)-3) == pi);
    assert_true(oi__atan2(-(oi_real)0, (oi_real)-3) == -pi);
    assert_true(oi__atan2((oi_real)5, (oi_real)0) == pi / 2);
    assert_true(oi__atan2((oi_real)-5, (oi_real)0) == -pi / 2);
    assert_true(oi__atan2((oi_real)1, (oi_real)1) == pi / 4);
    assert_true(oi__atan2(inf, (oi_real)1) == pi / 2);
    assert_true(oi__atan2((oi_real)1, inf) == 0);
    assert_true(oi__atan2((oi_real)1, -inf) == pi);
    assert_true(oi__atan2(inf, inf) == pi / 4);
    assert_true(isnan(oi__atan2((oi_real)NAN, (oi_real)1)));
    assert_true(isnan(oi__atan2((oi_real)1, (oi_real)NAN)));
    /* the largest and smallest normal magnitudes do not overflow t */
#ifdef OI_SINGLE_PRECISION
    check_point(FLT_MAX, (oi_real)1);
    check_point(FLT_MIN, (oi_real)1);
    check_point((oi_real)1, FLT_MAX);
#else
    check_point(DBL_MAX, (oi_real)1);
    check_point(DBL_MIN, (oi_real)1);
    check_point((oi_real)1, DBL_MAX);
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_points),
        cmocka_unit_test(test_breakpoints),
        cmocka_unit_test(test_special_values),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
