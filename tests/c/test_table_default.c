/* SPDX-License-Identifier: MIT */
/*
 * test_table_default.c: a program that defines oi_earth_table_default and
 * oi_atm_table_default itself (returning NULL) links and runs without the
 * library's defaults (src/model/earth_table_default.c, src/model/atm_table_default.c are
 * archive members pulled only for an undefined symbol), and the NULL default
 * behaves as the header says: earthshine the Lambert far field with
 * OI_WARN_TABLE_RANGE, a caller's table still used; the atmosphere adds
 * nothing (fraction_atm is the geometric fraction, status OI_OK).
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "orbillum.h"
#include "oi_earth_leo.h"
#include "ref_atmosphere.h"

const oi_earth_table *oi_earth_table_default(void)
{
    return NULL;
}

const oi_atm_table *oi_atm_table_default(void)
{
    return NULL;
}

/* (R/r)^2 p(theta), the Lambert far field, in double */
static double lambert_far(double theta, double h_km)
{
    const double pi = 3.14159265358979323846, x = 6378.137 / (6378.137 + h_km);
    return x * x * 2.0 / (3.0 * pi) * ((pi - theta) * cos(theta) + sin(theta));
}

static void test_earthshine_without_default(void **state)
{
    const double h[3] = {1.0, 500.0, 36000.0}, th[3] = {0.1, 1.2, 2.0};
    oi_model m;
    int i;
    (void)state;
    for (i = 0; i < 3; ++i) {
        oi_real phi, psi;
        const double want = lambert_far(th[i], h[i]);
        assert_int_equal(oi_earthshine((oi_real)th[i], (oi_real)h[i], NULL, &phi, &psi),
                         OI_WARN_TABLE_RANGE);
        if (!(fabs((double)phi - want) <= 1e-6 * want + 1e-12)) {
            printf("theta %g h %g: want %.17g got %.17g\n", th[i], h[i], want, (double)phi);
            fail();
        }
        assert_true(psi == (oi_real)0);
    }
    /* a caller's table is used inside its range (200 .. 2000 km) */
    memset(&m, 0, sizeof m);
    m.earth_table = &oi_earth_leo;
    {
        oi_real phi, psi;
        assert_int_equal(oi_earthshine(OI_R(0.3), OI_R(500.0), &m, &phi, &psi), OI_OK);
        assert_true(phi > (oi_real)0 && psi > (oi_real)0);
        assert_int_equal(oi_earthshine(OI_R(0.3), OI_R(5000.0), &m, &phi, &psi),
                         OI_WARN_TABLE_RANGE);
    }
}

/* Every reference point of the atmosphere (in and near the shadow): no
 * table, so fraction_atm is the geometric fraction of the model's disc. */
static void test_atmosphere_without_default(void **state)
{
    oi_model m;
    int i, k, in_shadow = 0;
    (void)state;
    memset(&m, 0, sizeof m);
    for (k = 0; k < 2; ++k) {
        m.limb_darkening = k == 0 ? OI_LIMB_UNIFORM : OI_LIMB_DARKENED;
#ifdef OI_NO_LIMB_DARKENING
        if (k == 1) break;
#endif
        for (i = 0; i < REF_ATM_N; ++i) {
            oi_real sun[3], pt[3];
            oi_shadow sh;
            int j;
            for (j = 0; j < 3; ++j) {
                sun[j] = (oi_real)ref_atm_cases[i].sun[j];
                pt[j] = (oi_real)ref_atm_cases[i].point[j];
            }
            assert_int_equal(oi_sun_fraction(sun, pt, &m, &sh), OI_OK);
            assert_true(sh.fraction_atm == (k == 0 ? sh.fraction : sh.fraction_ld));
            if (sh.fraction < (oi_real)1) in_shadow++;
        }
    }
    assert_true(in_shadow > 0); /* the points do test the shadow */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_earthshine_without_default),
        cmocka_unit_test(test_atmosphere_without_default),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
