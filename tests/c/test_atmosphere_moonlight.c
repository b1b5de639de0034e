/* SPDX-License-Identifier: MIT */
/*
 * test_atmosphere_moonlight.c: the Moon's light through the atmosphere near
 * the Earth's limb seen from a target (src/shadow/atmosphere_moonlight.c, through
 * oi__moon_disc_visible and oi_illuminate).
 *
 * References: the ring quadrature against a brute-force 2-D sum over the
 * Moon's disc (a different algorithm: a fine polar grid on the disc, each
 * point's line of sight and tangent height formed from vectors); the limits
 * (the disc clear of the atmosphere: the solid fraction exactly; behind the
 * Earth: 0); monotonic as the Moon sets. The optical depth itself is checked
 * against the ray reference in tests/python/test_atm.py.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdio.h>
#include <string.h>
#include <math.h>

#include "oi_internal.h"

#if !defined(OI_NO_ATMOSPHERE) && !defined(OI_NO_MOON)

/* internal, src/shadow/atmosphere_moonlight.c (for tests) */
oi_real oi__atm_los_transmission(oi_real h);

#define R_E 6378.137
#define R_M 1737.4

/* A target at (0, -dp, 0) looking at the Moon in the x-y plane at angle sep
 * from the Earth's centre direction (+y), distance dm. */
static void moon_at(double dp, double sep, double dm, oi_real pt[3], oi_real u[3],
                    oi_real moon[3])
{
    pt[0] = (oi_real)0;
    pt[1] = (oi_real)-dp;
    pt[2] = (oi_real)0;
    u[0] = (oi_real)sin(sep);
    u[1] = (oi_real)cos(sep);
    u[2] = (oi_real)0;
    moon[0] = (oi_real)(dm * sin(sep));
    moon[1] = (oi_real)(-dp + dm * cos(sep));
    moon[2] = (oi_real)0;
}

/* Brute force: the Moon's disc on a polar grid (n_r x n_a cells, area
 * weights), each point's direction from the target, its angle th from the
 * Earth's centre, the tangent height dp sin th - R (0 if th < 90 deg and
 * the line meets the Earth). */
static double brute(double dp, double sep, double dm)
{
    const int n_r = 400, n_a = 720;
    const double rm = asin(R_M / dm);
    double num = 0.0, den = 0.0;
    int i, j;
    for (i = 0; i < n_r; ++i) {
        const double rr = rm * (i + 0.5) / n_r; /* angular offset from the Moon's centre */
        for (j = 0; j < n_a; ++j) {
            const double a = 2.0 * 3.14159265358979323846 * (j + 0.5) / n_a;
            /* direction: rotate the Moon's direction by rr towards azimuth a */
            const double c = cos(rr), s = sin(rr);
            const double d[3] = {c * sin(sep) + s * cos(a) * cos(sep),
                                 c * cos(sep) - s * cos(a) * sin(sep), s * sin(a)};
            const double cth = d[1]; /* Earth's centre along +y */
            const double th = acos(cth > 1.0 ? 1.0 : cth);
            const double w = sin(rr);
            double t = 0.0;
            if (th < 0.5 * 3.14159265358979323846)
                t = (double)oi__atm_los_transmission((oi_real)(dp * sin(th) - R_E));
            else
                t = 1.0;
            num += w * t;
            den += w;
        }
    }
    return num / den;
}

static void test_against_brute_force(void **state)
{
    oi_model m;
    const double dm = 384400.0, dps[3] = {6878.137, 26578.137, 42164.0};
    double worst = 0.0;
    int k, i, bad = 0;
    (void)state;
    assert_int_equal(oi__model_resolve(NULL, &m), OI_OK);
    for (k = 0; k < 3; ++k) {
        const double dp = dps[k];
        const double re = asin(R_E / dp), rm = asin(R_M / dm);
        const double top = asin((R_E + 100.0) / dp);
        for (i = 0; i <= 10; ++i) {
            /* from the Moon half behind the solid Earth to clear of the air */
            const double sep = re + (top - re + 2.0 * rm) * (double)i / 10.0 - 0.5 * rm;
            oi_real pt[3], u[3], moon[3];
            double got, want;
            moon_at(dp, sep, dm, pt, u, moon);
            got = (double)oi__moon_disc_visible(pt, u, (oi_real)dm, &m);
            want = brute(dp, sep, dm);
            if (fabs(got - want) > worst) worst = fabs(got - want);
            if (fabs(got - want) > 2e-3) {
                printf("dp %.0f sep %.6f: ring %.6f brute %.6f\n", dp, sep, got, want);
                bad++;
            }
        }
    }
    printf("moonlight through the limb: ring quadrature vs 2-D sum, max |d| %.2g\n", worst);
    assert_int_equal(bad, 0);
}

static void test_limits_and_monotonic(void **state)
{
    oi_model m, none;
    const double dm = 384400.0, dp = 6878.137;
    const double re = asin(R_E / dp), rm = asin(R_M / dm), top = asin((R_E + 100.0) / dp);
    oi_real pt[3], u[3], moon[3];
    double prev = -1.0, sep, dip = 0.0;
    (void)state;
    assert_int_equal(oi__model_resolve(NULL, &m), OI_OK);
    none = m;
    none.no_atmosphere = 1;
    /* clear of the atmosphere: 1 exactly; behind the Earth: 0 */
    moon_at(dp, top + rm * 1.01, dm, pt, u, moon);
    assert_true(oi__moon_disc_visible(pt, u, (oi_real)dm, &m) == (oi_real)1);
    moon_at(dp, re - rm * 1.01, dm, pt, u, moon);
    assert_true(oi__moon_disc_visible(pt, u, (oi_real)dm, &m) == (oi_real)0);
    /* rising: below the solid Earth's fraction, and not decreasing */
    for (sep = re - rm; sep <= top + rm; sep += (top - re + 2.0 * rm) / 400.0) {
        double v, vs;
        moon_at(dp, sep, dm, pt, u, moon);
        v = (double)oi__moon_disc_visible(pt, u, (oi_real)dm, &m);
        vs = (double)oi__moon_disc_visible(pt, u, (oi_real)dm, &none);
        assert_true(v <= vs);
        if (prev - v > dip) dip = prev - v;
        prev = v;
    }
    /* monotonic to within the quadrature's own error (7e-5 against the
     * brute-force sum above): the pieces' ends cross the Moon's edge */
    printf("rising Moon from 500 km: largest dip %.2g\n", dip);
    assert_true(dip < 5e-5); /* float: the rounding of the angles adds ~1e-5 */
    /* the Moon's centre on the solid limb: the air dims what the Earth leaves */
    moon_at(dp, re, dm, pt, u, moon);
    printf("Moon's centre on the limb from 500 km: visible %.4f (solid Earth alone %.4f)\n",
           (double)oi__moon_disc_visible(pt, u, (oi_real)dm, &m),
           (double)oi__moon_disc_visible(pt, u, (oi_real)dm, &none));
}

/* Through oi_illuminate: e_moon follows moon_disc_visible; the case
 * (the Earth exactly between target and Moon) stays 0. */
static void test_public(void **state)
{
    oi_scene s;
    oi_illum out;
    (void)state;
    memset(&s, 0, sizeof s);
    s.sun_km[0] = (oi_real)1.495978707e8;
    s.target_km[1] = (oi_real)-7000;
    s.moon_km[1] = (oi_real)384400;
    s.observer_km[1] = (oi_real)-7100;
    s.target_radius_m = (oi_real)1;
    s.target_albedo = (oi_real)0.2;
    s.terms = OI_TERM_MOON;
    assert_true(oi_illuminate(&s, NULL, &out) >= 0);
    assert_true(out.moon_disc_visible == 0 && out.e_moon == 0);
}

/* oi_illuminate's moon_disc_visible is oi__moon_disc_visible's, bit for
 * bit, on both sides of where illuminate.c decides the Moon certainly clear
 * of the Earth and its air without the arctangents (1 exactly): the Moon
 * stepped from half behind the solid Earth to well clear, finely across
 * that test's margin, from four distances, with the air and without. */
static void test_public_as_internal(void **state)
{
    const double dm = 384400.0, dps[4] = {6878.137, 26578.137, 42164.0, 200000.0};
    int k, i, air, clear = 0, shaded = 0;
    (void)state;
    for (air = 0; air < 2; ++air)
        for (k = 0; k < 4; ++k) {
            const double dp = dps[k], re = asin(R_E / dp), rm = asin(R_M / dm);
            const double top = asin((R_E + 100.0) / dp), edge = top + rm + 1e-4;
            oi_model model, m;
            oi_scene s;
            oi_illum out;
            oi_real pt[3], u[3], moon[3], to_target[3], dir[3];
            double sep;
            oi_scene_defaults(&s);
            memset(&model, 0, sizeof model);
            model.no_atmosphere = air ? 0 : 1;
            assert_int_equal(oi__model_resolve(&model, &m), OI_OK);
            for (i = 0; i <= 260; ++i) {
                /* 200 steps to twice the edge, then 60 within 1e-5 of it */
                sep = i <= 200 ? re - 0.5 * rm + (2.0 * edge - re) * (double)i / 200.0
                               : edge + 1e-5 * ((double)(i - 230) / 30.0);
                moon_at(dp, sep, dm, pt, u, moon);
                s.sun_km[0] = (oi_real)1.495978707e8;
                memcpy(s.target_km, pt, sizeof pt);
                memcpy(s.moon_km, moon, sizeof moon);
                s.terms = OI_TERM_MOON;
                assert_true(oi_illuminate(&s, &model, &out) >= 0);
                /* moon_term's direction and distance, by its operations */
                oi__sub(pt, moon, to_target);
                (void)oi__unit(to_target, dir);
                dir[0] = -dir[0];
                dir[1] = -dir[1];
                dir[2] = -dir[2];
                if (out.moon_disc_visible !=
                    oi__moon_disc_visible(pt, dir, oi__norm(to_target), &m))
                    fail_msg("dp %.0f sep %.9f air %d: oi_illuminate %.9g", dp, sep, air,
                             (double)out.moon_disc_visible);
                if (out.moon_disc_visible == (oi_real)1) clear++;
                else shaded++;
            }
        }
    /* both sides reached */
    assert_true(clear > 100 && shaded > 100);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_against_brute_force),
        cmocka_unit_test(test_limits_and_monotonic),
        cmocka_unit_test(test_public),
        cmocka_unit_test(test_public_as_internal),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

#else
int main(void)
{
    return 0;
}
#endif
