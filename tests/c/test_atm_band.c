/* SPDX-License-Identifier: MIT */
/*
 * test_atm_band.c: the two bands of the atmosphere (oi_model.band: V and
 * the total solar irradiance) through the public API: the model's check of
 * band and of a caller's total-band table, which table each band reads,
 * e_sun following the band, and every fraction monotonic along beta = 0
 * passes in both bands and both disc models. The total band's values
 * against an independent computation (single wavelengths of the ray
 * reference summed by another quadrature) and against SOLAARS are in
 * tests/python/test_atm_band.py.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdio.h>
#include <string.h>
#include <math.h>

#include "orbillum.h"

#define R_EQ_KM 6378.137
#define AU 1.495978707e8

/* The point of a beta = 0 pass of altitude alt_km whose straight Sun-centre
 * line passes h_km above the equatorial radius (Sun on +x). */
static void pass_point(double alt_km, double h_km, oi_real sun[3], oi_real pt[3])
{
    const double r = R_EQ_KM + alt_km, rho = R_EQ_KM + h_km;
    sun[0] = (oi_real)AU;
    sun[1] = sun[2] = (oi_real)0;
    pt[0] = (oi_real)(-sqrt(r * r - rho * rho));
    pt[1] = (oi_real)rho;
    pt[2] = (oi_real)0;
}

static int all_zero(const void *p, size_t n)
{
    size_t j;
    for (j = 0; j < n; ++j)
        if (((const unsigned char *)p)[j] != 0) return 0;
    return 1;
}

/* A band other than OI_BAND_V and OI_BAND_TOTAL is OI_ERR_MODEL with the
 * outputs zeroed, in every call that takes the model. */
static void test_bad_band_is_model_error(void **state)
{
    static const int bad[4] = {2, -1, 3, 1 << 20};
    int k;
    (void)state;
    for (k = 0; k < 4; ++k) {
        oi_model m;
        oi_shadow sh;
        oi_real sun[3], pt[3], phi = (oi_real)1, psi = (oi_real)1;
        memset(&m, 0, sizeof m);
        m.band = bad[k];
        pass_point(490.0, 10.0, sun, pt);
        memset(&sh, 0x55, sizeof sh);
        assert_int_equal(oi_sun_fraction(sun, pt, &m, &sh), OI_ERR_MODEL);
        assert_true(all_zero(&sh, sizeof sh));
        assert_int_equal(oi_earthshine((oi_real)1, (oi_real)500, &m, &phi, &psi), OI_ERR_MODEL);
        assert_true(phi == (oi_real)0 && psi == (oi_real)0);
    }
}

#if !defined(OI_NO_ATMOSPHERE) && !defined(OI_NO_TOTAL_BAND)
#include "oi_atm_total.h"
#include "oi_atm_vband.h"

/* The bands read different tables in the atmosphere's reach and agree
 * where it does not matter: the geometric fractions, the lit side, and
 * with no_atmosphere. At 490 km with the Sun-centre line 10 km above the
 * radius the total band lets through more (infrared light passes the
 * grazing air better): documented 0.256 against 0.069 (docs/atmosphere.md). */
static void test_bands_differ_only_through_the_atmosphere(void **state)
{
    oi_model mv, mt;
    oi_shadow sv, st;
    oi_real sun[3], pt[3];
    (void)state;
    memset(&mv, 0, sizeof mv);
    memset(&mt, 0, sizeof mt);
    mt.band = OI_BAND_TOTAL;
    assert_true(oi_atm_total_default() == &oi_atm_total);
    pass_point(490.0, 10.0, sun, pt);
    assert_int_equal(oi_sun_fraction(sun, pt, &mv, &sv), OI_OK);
    assert_int_equal(oi_sun_fraction(sun, pt, &mt, &st), OI_OK);
    printf("490 km, 10 km: fraction_atm V %.4f, total %.4f (geometric %.4f)\n",
           (double)sv.fraction_atm, (double)st.fraction_atm, (double)sv.fraction);
    assert_true(sv.fraction == st.fraction && sv.fraction_ld == st.fraction_ld);
    assert_true(fabs((double)sv.fraction_atm - 0.0692) < 2e-3);
    assert_true(fabs((double)st.fraction_atm - 0.2560) < 2e-3);
    /* lit: both exactly the geometric fraction */
    pass_point(490.0, 300.0, sun, pt);
    assert_int_equal(oi_sun_fraction(sun, pt, &mt, &st), OI_OK);
    assert_true(st.fraction_atm == st.fraction && st.fraction == (oi_real)1);
    /* no atmosphere: the band does not matter */
    mv.no_atmosphere = mt.no_atmosphere = 1;
    pass_point(490.0, 10.0, sun, pt);
    assert_int_equal(oi_sun_fraction(sun, pt, &mv, &sv), OI_OK);
    assert_int_equal(oi_sun_fraction(sun, pt, &mt, &st), OI_OK);
    assert_true(memcmp(&sv, &st, sizeof sv) == 0 && sv.fraction_atm == sv.fraction);
}

/* A caller's total-band table: the default's copy gives the same numbers;
 * a broken one is OI_ERR_MODEL with band total (zeroed outputs), ignored
 * with band V; a broken V table is ignored with band total. */
static void test_caller_total_table(void **state)
{
    oi_atm_table good = oi_atm_total, bad = oi_atm_total;
    oi_model m;
    oi_shadow s0, s1;
    oi_real sun[3], pt[3];
    (void)state;
    bad.format = OI_ATM_FORMAT + 1;
    pass_point(490.0, 10.0, sun, pt);
    memset(&m, 0, sizeof m);
    m.band = OI_BAND_TOTAL;
    assert_int_equal(oi_sun_fraction(sun, pt, &m, &s0), OI_OK);
    m.atm_total_table = &good;
    assert_int_equal(oi_sun_fraction(sun, pt, &m, &s1), OI_OK);
    assert_true(memcmp(&s0, &s1, sizeof s0) == 0);
    /* the V table given as the total band's: the V numbers */
    m.atm_total_table = &oi_atm_vband;
    assert_int_equal(oi_sun_fraction(sun, pt, &m, &s1), OI_OK);
    assert_true(fabs((double)s1.fraction_atm - 0.0692) < 2e-3);
    m.atm_total_table = &bad;
    memset(&s1, 0x55, sizeof s1);
    assert_int_equal(oi_sun_fraction(sun, pt, &m, &s1), OI_ERR_MODEL);
    assert_true(all_zero(&s1, sizeof s1));
    m.band = OI_BAND_V;
    assert_int_equal(oi_sun_fraction(sun, pt, &m, &s1), OI_OK);
    m.band = OI_BAND_TOTAL;
    m.atm_total_table = NULL;
    m.atm_table = &bad;
    assert_int_equal(oi_sun_fraction(sun, pt, &m, &s1), OI_OK);
    assert_true(memcmp(&s0, &s1, sizeof s0) == 0);
}

/* e_sun follows the band: TSI (AU / d)^2 times the band's fraction_atm. */
static void test_e_sun_follows_band(void **state)
{
    int band;
    (void)state;
    for (band = OI_BAND_V; band <= OI_BAND_TOTAL; ++band) {
        oi_scene s;
        oi_model m;
        oi_illum out;
        oi_shadow sh;
        double d, want;
        oi_scene_defaults(&s);
        s.terms = OI_TERM_SUN;
        pass_point(490.0, 10.0, s.sun_km, s.target_km);
        memset(&m, 0, sizeof m);
        m.band = band;
        assert_int_equal(oi_sun_fraction(s.sun_km, s.target_km, &m, &sh), OI_OK);
        assert_true(oi_illuminate(&s, &m, &out) >= 0);
        d = (double)out.shadow.sun_distance_km;
        want = OI_TSI_W_M2 * (AU / d) * (AU / d) * (double)sh.fraction_atm;
        assert_true(out.shadow.fraction_atm == sh.fraction_atm);
        assert_true(fabs((double)out.e_sun - want) <= 1e-5 * want);
    }
}
#endif

/* Every fraction (fraction, fraction_ld, fraction_atm) falls, never rises,
 * going deeper into the shadow along beta = 0 passes at 490 km, GPS and
 * GEO, in steps of 0.05 km of the Sun-centre line's height, both bands and
 * both disc models (float: the lookup's rounding, 2.2e-6 as measured for
 * the V band in test_atmosphere.c, bounded by 1e-5 here). */
#ifdef OI_SINGLE_PRECISION
#define MONO_TOL 1e-5
#else
#define MONO_TOL 1e-12
#endif
static void test_every_fraction_monotonic_both_bands(void **state)
{
    static const double alt_km[3] = {490.0, 20200.0, 35786.0};
    int band, disc, k, bad = 0;
    (void)state;
    for (band = OI_BAND_V; band <= OI_BAND_TOTAL; ++band) {
#ifdef OI_NO_TOTAL_BAND
        if (band == OI_BAND_TOTAL) continue;
#endif
        for (disc = 0; disc < 2; ++disc) {
#ifdef OI_NO_LIMB_DARKENING
            if (disc) continue;
#endif
            for (k = 0; k < 3; ++k) {
                double prev[3] = {2.0, 2.0, 2.0}, worst[3] = {0.0, 0.0, 0.0}, h;
                oi_model m;
                int n = 0, c;
                memset(&m, 0, sizeof m);
                m.band = band;
                m.limb_darkening = disc ? OI_LIMB_DARKENED : OI_LIMB_UNIFORM;
                for (h = 400.0; h > -400.0 && n < 20000; h -= 0.05, ++n) {
                    oi_real sun[3], pt[3];
                    oi_shadow sh;
                    double f[3];
                    pass_point(alt_km[k], h, sun, pt);
                    if (R_EQ_KM + h >= R_EQ_KM + alt_km[k]) continue;
                    assert_true(oi_sun_fraction(sun, pt, &m, &sh) >= 0);
                    f[0] = (double)sh.fraction;
                    f[1] = (double)sh.fraction_ld;
                    f[2] = (double)sh.fraction_atm;
                    for (c = 0; c < 3; ++c) {
                        assert_true(f[c] >= 0.0 && f[c] <= 1.0);
                        if (f[c] - prev[c] > worst[c]) worst[c] = f[c] - prev[c];
                        prev[c] = f[c];
                    }
                    if (prev[0] == 0.0 && prev[2] == 0.0) break;
                }
                printf("band %s, %s disc, %.0f km: largest rise going deeper %.2g / %.2g / %.2g "
                       "(fraction / fraction_ld / fraction_atm, %d steps)\n",
                       band ? "total" : "V", disc ? "limb-darkened" : "uniform", alt_km[k],
                       worst[0], worst[1], worst[2], n);
                for (c = 0; c < 3; ++c)
                    if (worst[c] > MONO_TOL) bad++;
            }
        }
    }
    assert_int_equal(bad, 0);
}

#if defined(OI_NO_TOTAL_BAND) || defined(OI_NO_ATMOSPHERE)
/* Compiled out: no default table; band total refused (OI_NO_TOTAL_BAND) or
 * the geometric fraction (OI_NO_ATMOSPHERE: no atmosphere in either band). */
static void test_total_band_compiled_out(void **state)
{
    oi_model m;
    oi_shadow sh;
    oi_real sun[3], pt[3];
    (void)state;
    assert_true(oi_atm_total_default() == NULL);
    memset(&m, 0, sizeof m);
    m.band = OI_BAND_TOTAL;
    pass_point(490.0, 10.0, sun, pt);
#ifdef OI_NO_TOTAL_BAND
    memset(&sh, 0x55, sizeof sh);
    assert_int_equal(oi_sun_fraction(sun, pt, &m, &sh), OI_ERR_MODEL);
    assert_true(all_zero(&sh, sizeof sh));
#else
    assert_int_equal(oi_sun_fraction(sun, pt, &m, &sh), OI_OK);
    assert_true(sh.fraction_atm == sh.fraction);
#endif
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bad_band_is_model_error),
#if !defined(OI_NO_ATMOSPHERE) && !defined(OI_NO_TOTAL_BAND)
        cmocka_unit_test(test_bands_differ_only_through_the_atmosphere),
        cmocka_unit_test(test_caller_total_table),
        cmocka_unit_test(test_e_sun_follows_band),
#endif
        cmocka_unit_test(test_every_fraction_monotonic_both_bands),
#if defined(OI_NO_TOTAL_BAND) || defined(OI_NO_ATMOSPHERE)
        cmocka_unit_test(test_total_band_compiled_out),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
