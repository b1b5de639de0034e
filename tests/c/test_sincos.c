/* SPDX-License-Identifier: MIT */
/* test_sincos.c: the runtime's own sine and cosine (src/math/sincos.c) against a
 * higher-precision reference: sinl/cosl (long double: 64-bit or 113-bit
 * significand on the hosts we test on) for the double build, sin/cos in
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

oi_real oi__sin(oi_real x); /* internal, src/math/sincos.c */
oi_real oi__cos(oi_real x);
void oi__sincos(oi_real x, oi_real *s, oi_real *c);

#ifdef OI_SINGLE_PRECISION
#define REF_SIN sin
#define REF_COS cos
#define NEXT_UP(x) nextafterf((x), INFINITY)
#define NEXT_DOWN(x) nextafterf((x), -INFINITY)
/* pi/2 to 64 bits, for the nearest working-precision values to k pi/2 */
#define HALF_PI_REF 1.5707963267948966
/* beyond the exact range: the angle off by at most |x| 2^-24 (2 pi rounded) */
#define FOLD_REL 0x1p-24
#else
#define REF_SIN sinl
#define REF_COS cosl
#define NEXT_UP(x) nextafter((x), INFINITY)
#define NEXT_DOWN(x) nextafter((x), -INFINITY)
#define HALF_PI_REF 1.570796326794896619231321691639751442L
#define FOLD_REL 0x1p-52
#endif

/* Worst error allowed, in ulp of the exact result. */
#define MAX_ULP 1.0

static uint64_t lcg_state = 0x9E3779B97F4A7C15ULL;
static double uniform01(void)
{
    return lcg01(&lcg_state);
}

static double worst_ulp;
static double worst_x;
static const char *worst_fn;

static void check_one(const char *fn, oi_real x, oi_real got, ref_real want)
{
    ref_real err;
    if (want == 0) {
        if (got != 0) {
            print_error("%s(%.17g): want 0 got %.17g\n", fn, (double)x, (double)got);
            fail();
        }
        return;
    }
    err = ((ref_real)got - want) / ulp_of(want);
    if (err < 0) err = -err;
    if ((double)err > worst_ulp) {
        worst_ulp = (double)err;
        worst_x = (double)x;
        worst_fn = fn;
    }
    if (!((double)err <= MAX_ULP)) {
        print_error("%s(%.17g): want %.17g got %.17g (%.3g ulp)\n", fn, (double)x, (double)want,
                    (double)got, (double)err);
        fail();
    }
}

static void check_point(oi_real x)
{
    check_one("sin", x, oi__sin(x), REF_SIN((ref_real)x));
    check_one("cos", x, oi__cos(x), REF_COS((ref_real)x));
}

static void report(const char *what)
{
    print_message("oi__sin/oi__cos %s: worst %.3f ulp (%s at %.17g)\n", what, worst_ulp,
                  worst_fn ? worst_fn : "-", worst_x);
}

static void random_range(double half_width, int n)
{
    int i;
    for (i = 0; i < n; i++) check_point((oi_real)((uniform01() * 2.0 - 1.0) * half_width));
}

static void test_random_8(void **state)
{
    (void)state;
    worst_ulp = 0;
    random_range(8.0, 300000);
    report("random |x| <= 8");
}

static void test_random_1e3(void **state)
{
    (void)state;
    worst_ulp = 0;
    random_range(1e3, 200000);
    report("random |x| <= 1e3");
}

static void test_random_1e6(void **state)
{
    (void)state;
    worst_ulp = 0;
    random_range(1e6, 200000);
    report("random |x| <= 1e6");
}

/* The hard cases of the reduction: the nearest working-precision values to
 * k pi/2 (and their neighbours), where x - k pi/2 cancels to a few bits. */
static void test_near_multiples(void **state)
{
    long k;
    int j;
    (void)state;
    worst_ulp = 0;
    for (k = -100000; k <= 100000; k++) {
        oi_real x = (oi_real)((ref_real)k * HALF_PI_REF), lo = x, hi = x;
        check_point(x);
        for (j = 0; j < 2; j++) {
            lo = NEXT_DOWN(lo);
            hi = NEXT_UP(hi);
            check_point(lo);
            check_point(hi);
        }
    }
    /* the largest k of the exact range and the multiples of pi/4 (quadrant
     * boundaries of the reduction) */
    for (k = 1048000; k < 1048576; k++) check_point((oi_real)((ref_real)k * HALF_PI_REF));
    for (k = -4000; k <= 4000; k++) {
        oi_real x = (oi_real)((ref_real)k * HALF_PI_REF * 0.5 + 0.25 * HALF_PI_REF);
        check_point(x);
        check_point(NEXT_UP(x));
        check_point(NEXT_DOWN(x));
    }
    report("near k pi/2 and k pi/4");
}

/* Tiny and subnormal x: sin x = x (to the last bit), cos x = 1; and the
 * decades around the small-argument cut. */
static void test_tiny(void **state)
{
    int j;
    (void)state;
    worst_ulp = 0;
    for (j = 0; j < 400; j++) {
        double t = pow(2.0, -0.25 * j);
        check_point((oi_real)t);
        check_point((oi_real)-t);
    }
#ifdef OI_SINGLE_PRECISION
    assert_true(oi__sin(FLT_MIN) == FLT_MIN);
    assert_true(oi__sin(0x1p-149f) == 0x1p-149f);
    assert_true(oi__sin(-0x1p-20f) == -0x1p-20f);
#else
    assert_true(oi__sin(DBL_MIN) == DBL_MIN);
    assert_true(oi__sin(0x1p-1074) == 0x1p-1074);
    assert_true(oi__sin(-0x1p-40) == -0x1p-40);
#endif
    assert_true(oi__cos((oi_real)1e-30) == 1);
    report("tiny");
}

/* Beyond the exact range (|x| > 2^20 pi/2): finite, in [-1, 1], and within
 * the documented bound (the angle off by |x| FOLD_REL). */
static void test_beyond_range(void **state)
{
    int i;
    (void)state;
    for (i = 0; i < 20000; i++) {
        double mag = pow(10.0, 6.3 + uniform01() * 6.0), sgn = uniform01() < 0.5 ? -1.0 : 1.0;
        oi_real x = (oi_real)(sgn * mag), s = oi__sin(x), c = oi__cos(x);
        double ds = fabs((double)s - (double)REF_SIN((ref_real)x));
        double dc = fabs((double)c - (double)REF_COS((ref_real)x));
        double bound = fabs((double)x) * FOLD_REL + 4.0 * ldexp(1.0, -MANT_BITS);
        if (!(s >= -1 && s <= 1 && c >= -1 && c <= 1) || !(ds <= bound) || !(dc <= bound)) {
            print_error("x = %.17g: sin want %.17g got %.17g, cos want %.17g got %.17g, bound %.3g\n",
                        (double)x, (double)REF_SIN((ref_real)x), (double)s,
                        (double)REF_COS((ref_real)x), (double)c, bound);
            fail();
        }
    }
    /* the fold is x mod (2 pi rounded) exactly: the same bits as the libm's
     * (exact) fmod followed by the reduction */
    for (i = 0; i < 20000; i++) {
        double mag = pow(10.0, 6.3 + uniform01() * 30.0), sgn = uniform01() < 0.5 ? -1.0 : 1.0;
        oi_real x = (oi_real)(sgn * mag);
#ifdef OI_SINGLE_PRECISION
        oi_real m = fmodf(x, (oi_real)6.283185307179586);
#else
        oi_real m = fmod(x, 6.283185307179586);
#endif
        if (!(oi__sin(x) == oi__sin(m) && oi__cos(x) == oi__cos(m))) {
            print_error("x = %.17g: want sin %.17g cos %.17g (fmod) got %.17g %.17g\n", (double)x,
                        (double)oi__sin(m), (double)oi__cos(m), (double)oi__sin(x), (double)oi__cos(x));
            fail();
        }
    }
    /* the largest finite values */
#ifdef OI_SINGLE_PRECISION
    {
        const oi_real big[] = {FLT_MAX, -FLT_MAX, 0x1p100f, 1647099.0f, 1647097.0f};
#else
    {
        const oi_real big[] = {DBL_MAX, -DBL_MAX, 0x1p1000, 1647099.0, 1647097.0};
#endif
        size_t j;
        for (j = 0; j < sizeof big / sizeof big[0]; j++) {
            oi_real s = oi__sin(big[j]), c = oi__cos(big[j]);
            assert_true(s >= -1 && s <= 1);
            assert_true(c >= -1 && c <= 1);
        }
    }
}

/* C99 F.9.1.5/F.9.1.6: signed zero, NaN and infinities. */
static void test_special_values(void **state)
{
    const oi_real inf = (oi_real)INFINITY;
    (void)state;
    assert_true(oi__sin((oi_real)0) == 0 && !signbit(oi__sin((oi_real)0)));
    assert_true(oi__sin(-(oi_real)0) == 0 && signbit(oi__sin(-(oi_real)0)));
    assert_true(oi__cos((oi_real)0) == 1);
    assert_true(oi__cos(-(oi_real)0) == 1);
    assert_true(isnan(oi__sin((oi_real)NAN)));
    assert_true(isnan(oi__cos((oi_real)NAN)));
    assert_true(isnan(oi__sin(inf)));
    assert_true(isnan(oi__sin(-inf)));
    assert_true(isnan(oi__cos(inf)));
    assert_true(isnan(oi__cos(-inf)));
    /* odd and even */
    {
        int i;
        for (i = 0; i < 2000; i++) {
            oi_real x = (oi_real)(uniform01() * 100.0);
            assert_true(oi__sin(-x) == -oi__sin(x));
            assert_true(oi__cos(-x) == oi__cos(x));
        }
    }
}

/* oi__sincos gives oi__sin's and oi__cos's bits (one shared reduction). */
static void test_sincos_pair(void **state)
{
    int i;
    const oi_real special[] = {(oi_real)0, -(oi_real)0, (oi_real)1e-30, (oi_real)2e6, (oi_real)INFINITY,
                               (oi_real)NAN};
    (void)state;
    for (i = 0; i < 100000; i++) {
        oi_real x = (oi_real)((uniform01() * 2.0 - 1.0) * pow(10.0, uniform01() * 8.0 - 2.0)), s, c;
        oi__sincos(x, &s, &c);
        if (!(s == oi__sin(x) && c == oi__cos(x))) {
            print_error("sincos(%.17g): want %.17g %.17g got %.17g %.17g\n", (double)x,
                        (double)oi__sin(x), (double)oi__cos(x), (double)s, (double)c);
            fail();
        }
    }
    for (i = 0; i < (int)(sizeof special / sizeof special[0]); i++) {
        oi_real s, c;
        oi__sincos(special[i], &s, &c);
        if (isnan(oi__sin(special[i]))) {
            assert_true(isnan(s) && isnan(c));
        } else {
            assert_true(s == oi__sin(special[i]) && c == oi__cos(special[i]));
            assert_true(signbit(s) == signbit(oi__sin(special[i])));
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_8),       cmocka_unit_test(test_random_1e3),
        cmocka_unit_test(test_random_1e6),     cmocka_unit_test(test_near_multiples),
        cmocka_unit_test(test_tiny),           cmocka_unit_test(test_beyond_range),
        cmocka_unit_test(test_special_values), cmocka_unit_test(test_sincos_pair),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
