/* SPDX-License-Identifier: MIT */
/* test_moon.c: the lunar phase law against mpmath values of Krisciunas &
 * Schaefer (1991) eq. 20 (ref_phase.h), its range, monotonicity and the
 * behaviour beyond its fitted range. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>

#include "orbillum.h"

#ifndef OI_NO_MOON
#define REF_MOON_ONLY
#include "ref_phase.h"

#ifdef OI_SINGLE_PRECISION
#define MOON_REL 2e-6
#else
#define MOON_REL 4e-15
#endif

static const double PI = 3.14159265358979323846;

static void test_moon_vs_mpmath(void **state)
{
    size_t i, n = sizeof ref_moon / sizeof ref_moon[0];
    int bad = 0;
    double worst = 0;
    (void)state;
    for (i = 0; i < n; ++i) {
        double want = ref_moon[i].want;
        double got = (double)oi_moon_phase_law((oi_real)ref_moon[i].x);
        double rel = fabs(got - want) / want;
        if (!(rel <= MOON_REL)) {
            print_error("moon(%a): want %.17g got %.17g rel err %.3g\n", ref_moon[i].x, want,
                        got, rel);
            ++bad;
        }
        if (rel > worst) worst = rel;
    }
    print_message("oi_moon_phase_law: %zu points, worst relative error %.3g\n", n, worst);
    assert_int_equal(bad, 0);
}

/* closed-form values: full Moon 1; 90 deg: 10^(-0.4 (2.34 + 0.26244)) */
static void test_moon_closed_forms(void **state)
{
    double q = pow(10.0, -0.4 * (0.026 * 90.0 + 4e-9 * pow(90.0, 4)));
    double got = (double)oi_moon_phase_law((oi_real)(PI / 2));
    (void)state;
    assert_true(oi_moon_phase_law((oi_real)0) == (oi_real)1);
    if (!(fabs(got - q) <= MOON_REL * 4 * q)) {
        print_error("moon(90 deg): want %.17g got %.17g\n", q, got);
        fail();
    }
}

/* positive, finite, strictly decreasing on [0, pi]; |alpha| and clamping */
static void test_moon_range(void **state)
{
    int i;
    oi_real prev = oi_moon_phase_law((oi_real)0);
    oi_real at_pi = oi_moon_phase_law((oi_real)PI);
    (void)state;
    for (i = 1; i <= 18000; ++i) {
        oi_real a = (oi_real)(PI * i / 18000.0);
        oi_real v = oi_moon_phase_law(a);
        if (!(v > (oi_real)0) || !(v < prev) || !isfinite((double)v)) {
            print_error("moon law not positive decreasing at %.17g: %.17g after %.17g\n",
                        (double)a, (double)v, (double)prev);
            fail();
        }
        prev = v;
    }
    /* 180 deg: 10^(-0.4 (4.68 + 4.19904)) = 2.8085e-4 */
    assert_true(fabs((double)at_pi - pow(10.0, -0.4 * 8.87904)) < 1e-9);
    assert_true(oi_moon_phase_law((oi_real)4) == at_pi);
    assert_true(oi_moon_phase_law((oi_real)INFINITY) == at_pi);
    assert_true(oi_moon_phase_law((oi_real)-INFINITY) == at_pi);
    assert_true(oi_moon_phase_law((oi_real)-0.5) == oi_moon_phase_law((oi_real)0.5));
    assert_true(oi_moon_phase_law((oi_real)NAN) == (oi_real)0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_moon_vs_mpmath),
        cmocka_unit_test(test_moon_closed_forms),
        cmocka_unit_test(test_moon_range),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
#else
#include <stdio.h>
int main(void)
{
    printf("skip test_moon: OI_NO_MOON removes the Moon\n");
    return 0;
}
#endif
