/* SPDX-License-Identifier: MIT */
/* test_phase.c: oi_lambert_phase against mpmath references at the exact input
 * values (ref_phase.h, from tests/ref/gen_refs.py), near 0 and pi included;
 * energy conservation of the Lambert sphere by independent quadrature; and
 * oi_angle against closed forms at tiny and near-pi angles. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "orbillum.h"
#include "ref_phase.h"

#ifdef OI_SINGLE_PRECISION
#define PHASE_REL 1e-5     /* the accuracy goal of oi_lambert_phase */
#define ANGLE_ABS 4e-7     /* a few float epsilon */
#define EPS ((double)FLT_EPSILON)
#else
#define PHASE_REL 1e-12
#define ANGLE_ABS 1e-15
#define EPS DBL_EPSILON
#endif

static const double PI = 3.14159265358979323846;

static int check_rel(double want, double got, double rel, double abs_floor, const char *what,
                     double x)
{
    double err = fabs(got - want);
    if (!isfinite(got) || !(err <= rel * fabs(want) + abs_floor)) {
        print_error("%s(x=%a): want %.17g got %.17g rel err %.3g\n", what, x, want, got,
                    want != 0 ? err / fabs(want) : err);
        return 1;
    }
    return 0;
}

/* every reference point, relative error; the worst one is printed */
static void test_phase_vs_mpmath(void **state)
{
    size_t i, n = sizeof ref_phase / sizeof ref_phase[0];
    int bad = 0;
    double worst = 0, worst_x = 0;
    (void)state;
    for (i = 0; i < n; ++i) {
        double x = ref_phase[i].x, want = ref_phase[i].want;
        double got = (double)oi_lambert_phase((oi_real)x);
        double rel = want != 0 ? fabs(got - want) / want : fabs(got);
        /* a zero reference (x >= pi) must give exactly zero */
        if (want == 0) {
            if (got != 0) {
                print_error("p(%a): want 0 got %.17g\n", x, got);
                ++bad;
            }
            continue;
        }
        bad += check_rel(want, got, PHASE_REL, 0, "p", x);
        if (rel > worst) {
            worst = rel;
            worst_x = x;
        }
    }
    print_message("oi_lambert_phase: %zu points, worst relative error %.3g at x = %.17g\n", n,
                  worst, worst_x);
    assert_int_equal(bad, 0);
}

static void test_phase_special(void **state)
{
    (void)state;
    assert_true(oi_lambert_phase((oi_real)0) == (oi_real)2 / (oi_real)3);
    assert_true(oi_lambert_phase((oi_real)-1) == (oi_real)2 / (oi_real)3);
    assert_true(oi_lambert_phase((oi_real)4) == (oi_real)0);
    assert_true(oi_lambert_phase((oi_real)INFINITY) == (oi_real)0);
    assert_true(oi_lambert_phase((oi_real)-INFINITY) == (oi_real)2 / (oi_real)3);
    assert_true(oi_lambert_phase((oi_real)NAN) == (oi_real)0);
    assert_true(oi_lambert_phase((oi_real)-0.0) == (oi_real)2 / (oi_real)3);
}

/* p is non-increasing on [0, pi] (p' = -2/(3 pi) (pi - x) sin x <= 0) */
static void test_phase_monotonic(void **state)
{
    int i;
    oi_real prev = oi_lambert_phase((oi_real)0);
    (void)state;
    for (i = 1; i <= 100000; ++i) {
        oi_real x = (oi_real)(PI * i / 100000.0);
        oi_real p = oi_lambert_phase(x);
        if (p > prev) {
            print_error("p not monotonic at x=%.17g: %.17g > %.17g\n", (double)x, (double)p,
                        (double)prev);
            fail();
        }
        prev = p;
    }
}

/*
 * Energy conservation: a sphere of radius a, albedo A under irradiance E
 * sends F(xi) = E A a^2 p(xi) / d^2 to distance d; over the sphere of radius
 * d the total is E A a^2 * 2 pi * int_0^pi p(xi) sin xi dxi, which must be
 * the intercepted-and-reflected power E A pi a^2, i.e. the integral is 1/2.
 * Composite Gauss-Legendre (5 points per panel, 200 panels), computed here.
 */
static void test_phase_energy(void **state)
{
    static const double gx[5] = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                 0.5384693101056831, 0.9061798459386640};
    static const double gw[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                 0.4786286704993665, 0.2369268850561891};
    int k, j, panels = 200;
    double h = PI / panels, sum = 0;
    (void)state;
    for (k = 0; k < panels; ++k) {
        double mid = (k + 0.5) * h;
        for (j = 0; j < 5; ++j) {
            double x = mid + 0.5 * h * gx[j];
            sum += 0.5 * h * gw[j] * (double)oi_lambert_phase((oi_real)x) * sin(x);
        }
    }
#ifdef OI_SINGLE_PRECISION
    assert_true(check_rel(0.5, sum, 2e-6, 0, "int p sin", 0) == 0);
#else
    assert_true(check_rel(0.5, sum, 1e-13, 0, "int p sin", 0) == 0);
#endif
}

/* ---------------------------------------------------------------- oi_angle */

static void angle_case(double ax, double ay, double az, double bx, double by, double bz,
                       double want, double tol)
{
    oi_real a[3], b[3];
    double got;
    a[0] = (oi_real)ax;
    a[1] = (oi_real)ay;
    a[2] = (oi_real)az;
    b[0] = (oi_real)bx;
    b[1] = (oi_real)by;
    b[2] = (oi_real)bz;
    got = (double)oi_angle(a, b);
    if (!(fabs(got - want) <= tol)) {
        print_error("angle: want %.17g got %.17g\n", want, got);
        fail();
    }
}

static void test_angle(void **state)
{
    double t;
    (void)state;
    /* exact configurations */
    angle_case(1, 0, 0, 1, 0, 0, 0, 0);
    angle_case(1, 0, 0, -1, 0, 0, PI, ANGLE_ABS);
    angle_case(1, 0, 0, 0, 1, 0, PI / 2, ANGLE_ABS);
    angle_case(0, 0, 3, 0, 5, 5, PI / 4, ANGLE_ABS);
    /* small angles: (1, t, 0) vs (1, 0, 0) is atan(t) exactly (the input is
     * exact); the acos form would give 0 below t ~ 1e-8 in double */
    for (t = 1e-3; t > 1e-30; t *= 1e-3) {
        oi_real tt = (oi_real)t;
        double want = atan((double)tt);
        angle_case(1, (double)tt, 0, 1, 0, 0, want, 4 * EPS * want);
        /* near pi: (-1, t, 0) vs (1, 0, 0) is pi - atan(t) */
        angle_case(-1, (double)tt, 0, 1, 0, 0, PI - want, ANGLE_ABS);
    }
    /* scale invariance and extreme magnitudes */
    angle_case(1e-30, 0, 0, 0, 1e30, 0, PI / 2, ANGLE_ABS);
#ifndef OI_SINGLE_PRECISION
    angle_case(1e300, 1e300, 0, 1e-300, 0, 0, PI / 4, ANGLE_ABS);
    angle_case(4.9e-324, 0, 0, 0, 4.9e-324, 0, PI / 2, ANGLE_ABS);
    angle_case(1.7e308, 1.7e308, 1.7e308, -1.7e308, -1.7e308, -1.7e308, PI, ANGLE_ABS);
#else
    angle_case(1e30, 1e30, 0, 1e-30, 0, 0, PI / 4, ANGLE_ABS);
    angle_case(1.4e-45, 0, 0, 0, 1.4e-45, 0, PI / 2, ANGLE_ABS);
    angle_case(3e38, 3e38, 3e38, -3e38, -3e38, -3e38, PI, ANGLE_ABS);
#endif
    /* zero or non-finite vectors give 0 */
    angle_case(0, 0, 0, 1, 0, 0, 0, 0);
    angle_case(1, 0, 0, -0.0, 0, 0, 0, 0);
    angle_case(NAN, 0, 0, 1, 0, 0, 0, 0);
    angle_case(INFINITY, 0, 0, 1, 0, 0, 0, 0);
    assert_true(oi_angle(NULL, NULL) == (oi_real)0);
}

/* the Sun at 1 AU and a LEO target, in the working precision: the angle at
 * the Earth between them, against the same computed in long double from the
 * (exact) working-precision inputs */
static void test_angle_large_components(void **state)
{
    oi_real s[3] = {(oi_real)1.4959787e8, (oi_real)-2.3e6, (oi_real)1.1e5};
    oi_real p[3] = {(oi_real)-6000.5, (oi_real)3000.25, (oi_real)1200.125};
    long double ls[3], lp[3], c[3], dot, cr;
    int i;
    (void)state;
    for (i = 0; i < 3; ++i) {
        ls[i] = (long double)s[i];
        lp[i] = (long double)p[i];
    }
    c[0] = ls[1] * lp[2] - ls[2] * lp[1];
    c[1] = ls[2] * lp[0] - ls[0] * lp[2];
    c[2] = ls[0] * lp[1] - ls[1] * lp[0];
    dot = ls[0] * lp[0] + ls[1] * lp[1] + ls[2] * lp[2];
    cr = sqrtl(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    angle_case((double)s[0], (double)s[1], (double)s[2], (double)p[0], (double)p[1],
               (double)p[2], (double)atan2l(cr, dot), ANGLE_ABS);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_phase_vs_mpmath),
        cmocka_unit_test(test_phase_special),
        cmocka_unit_test(test_phase_monotonic),
        cmocka_unit_test(test_phase_energy),
        cmocka_unit_test(test_angle),
        cmocka_unit_test(test_angle_large_components),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
