/* SPDX-License-Identifier: MIT */
/*
 * test_skylight.c: the scattered sunlight (OI_TERM_SKY, oi_skylight, the
 * table oi_sky_vband): the energy bound (never more than the sunlight the
 * atmosphere intercepts), continuity across the terminator, the shadow edge
 * and the table's first row, the light in the LEO umbra against the full
 * Moon's, the term's wiring in oi_illuminate (e_sky, dir_sky, flux_sky in
 * flux_obs) and oi_expose_scene (background share), and the hostile inputs
 * (a caller's broken table, NaN, out-of-range arguments). The values
 * against an independent Monte Carlo are in tests/python/test_skylight.py.
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
#include "oi_test_util.h"

/* without the earthshine table the Earth's light is the Lambert far field,
 * with its warning */
#ifdef OI_NO_EARTH_TABLE
#define ST_EARTH OI_WARN_TABLE_RANGE
#else
#define ST_EARTH OI_OK
#endif

#ifndef OI_NO_SKYLIGHT
static const double PI = 3.14159265358979323846;
static const double AU = 149597870.7;
static const double TSI = 1361.0;
static const double RE = 6378.137;
static const double TOP = 100.0;
static const double DEG = 3.14159265358979323846 / 180.0;

#ifdef OI_SINGLE_PRECISION
#define REL_TOL 2e-5
#else
#define REL_TOL 1e-12
#endif

static double sky(double theta, double h, int *status)
{
    oi_real e = -1, psi = -1;
    int st = oi_skylight((oi_real)theta, (oi_real)h, NULL, &e, &psi);
    if (status != NULL) *status = st;
    return (double)e;
}

/* The outward flux of the scattered light through the sphere of radius r is
 * at least cos(alpha_top) times the sphere's integral of the scalar
 * irradiance (every ray comes within alpha_top = asin(r_top / r) of the
 * nadir), and at most the sunlight the top sphere intercepts, pi r_top^2
 * E_sun. Simpson's rule over theta on 1441 points. */
static void test_energy_bound(void **state)
{
    static const double hs[] = {110.0, 150.0, 400.0, 1000.0, 2000.0, 20000.0, 36000.0, 1e6};
    size_t k;
    int i;
    (void)state;
    for (k = 0; k < sizeof hs / sizeof hs[0]; k++) {
        const double r = RE + hs[k], rt = RE + TOP;
        const int n = 1440;
        double sum = 0, cos_a, ratio;
        for (i = 0; i <= n; i++) {
            const double th = PI * i / n;
            const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
            sum += w * sky(th, hs[k], NULL) * sin(th);
        }
        sum *= PI / n / 3.0;
        cos_a = sqrt(1.0 - (rt / r) * (rt / r));
        ratio = cos_a * 2.0 * PI * r * r * sum / (PI * rt * rt);
        if (!(ratio < 1.0 && ratio > 0.0)) {
            print_error("h %g km: flux bound ratio %g (must lie in (0, 1))\n", hs[k], ratio);
            fail();
        }
    }
}

/* Continuity: on 0.01 degree steps across the terminator (90 deg) and the
 * shadow edge of the orbit (90 + acos(R / r) deg), no step changes E_sky by
 * more than 1 % of the largest value on the scan; the same across the first
 * row (100 km) in altitude. */
static void test_continuity(void **state)
{
    static const double hs[] = {150.0, 400.0, 800.0, 2000.0};
    size_t k;
    int i;
    (void)state;
    for (k = 0; k < sizeof hs / sizeof hs[0]; k++) {
        const double edge = 90.0 + acos(RE / (RE + hs[k])) / DEG;
        double prev = sky(80.0 * DEG, hs[k], NULL), peak = prev, worst = 0;
        for (i = 1; i <= 100 * (int)(edge - 80.0 + 10.0); i++) {
            const double e = sky((80.0 + 0.01 * i) * DEG, hs[k], NULL);
            if (e > peak) peak = e;
            if (fabs(e - prev) > worst) worst = fabs(e - prev);
            prev = e;
        }
        if (!(worst <= 0.01 * peak)) {
            print_error("h %g km: a 0.01 deg step changes E_sky by %g of the peak %g\n", hs[k],
                        worst / peak, peak);
            fail();
        }
    }
    {
        /* altitude: the first row at 100 km, below it the first row's values
         * with OI_WARN_TABLE_RANGE */
        int st;
        const double a = sky(100.0 * DEG, 100.0 + 1e-3, &st);
        const double b = sky(100.0 * DEG, 100.0 - 1e-3, &st);
        check_int(OI_WARN_TABLE_RANGE, st, "below the first row");
        check_close(a, b, 1e-12, 1e-4, "across the first row");
        (void)sky(100.0 * DEG, 100.5, &st);
        check_int(OI_OK, st, "above the first row");
    }
}

/* A LEO target 2 degrees inside the umbra's edge sees more scattered
 * sunlight than a full Moon gives (2.49e-6 of the Sun, Krisciunas & Schaefer
 * 1991's V = -12.73 against the Sun's -26.74), and none deep in the shadow
 * (the anti-solar point at 400 km sees only the Earth's shadowed air). */
static void test_umbra(void **state)
{
    const double edge = 90.0 + acos(RE / (RE + 400.0)) / DEG;
    (void)state;
    if (!(sky((edge + 2.0) * DEG, 400.0, NULL) > 2.49e-6)) {
        print_error("2 deg into the umbra at 400 km: %g of the Sun\n",
                    sky((edge + 2.0) * DEG, 400.0, NULL));
        fail();
    }
    check_close(0.0, sky(PI, 400.0, NULL), 0.0, 0.0, "anti-solar point at 400 km");
}

static void leo_scene(oi_scene *sc, double theta, double h)
{
    oi_scene_defaults(sc);
    set3(sc->sun_km, AU, 0, 0);
    set3(sc->target_km, (RE + h) * cos(theta), (RE + h) * sin(theta), 0);
    set3(sc->observer_km, (RE + h) * cos(theta), (RE + h) * sin(theta), 50.0);
    sc->has_observer = 1;
    sc->terms = OI_TERM_SUN | OI_TERM_EARTH; /* no Moon position */
}

/* oi_illuminate with OI_TERM_SKY: e_sky is the Sun's irradiance at the
 * Earth's distance times oi_skylight, dir_sky the unit vector psi from the
 * nadir towards the Sun, flux_sky the Lambertian sphere's closed form from
 * that direction, and flux_obs the sum of every source's flux. Without the
 * bit every sky field is zero and the other fields are unchanged. */
static void test_illuminate(void **state)
{
    static const double thetas[] = {30.0, 95.0, 108.0, 115.0};
    size_t k;
    (void)state;
    check_int(0, (long)(OI_TERM_ALL & OI_TERM_SKY), "OI_TERM_ALL holds no sky");
    for (k = 0; k < sizeof thetas / sizeof thetas[0]; k++) {
        oi_scene sc;
        oi_illum with, without;
        oi_real e, psi;
        double e0, nadir[3], cos_psi, dd, xi, ratio, a, p;
        int st, i;
        leo_scene(&sc, thetas[k] * DEG, 400.0);
        st = oi_illuminate(&sc, NULL, &without);
        check_int(ST_EARTH, st, "without sky");
        check_close(0.0, (double)without.e_sky, 0, 0, "e_sky off");
        check_close(0.0, (double)without.flux_sky, 0, 0, "flux_sky off");
        sc.terms |= OI_TERM_SKY;
        st = oi_illuminate(&sc, NULL, &with);
        check_int(ST_EARTH, st, "with sky");
        st = oi_skylight((oi_real)(thetas[k] * DEG), (oi_real)400.0, NULL, &e, &psi);
        check_int(OI_OK, st, "oi_skylight");
        e0 = TSI;
        check_close(e0 * (double)e, (double)with.e_sky, 1e-30, 1e-4, "e_sky");
        check_close((double)without.e_earth, (double)with.e_earth, 0, 0, "e_earth unchanged");
        if (with.e_sky > 0) {
            dd = 0;
            for (i = 0; i < 3; i++) dd += (double)with.dir_sky[i] * (double)with.dir_sky[i];
            check_close(1.0, dd, 0, 1e-5, "dir_sky unit");
            nadir[0] = -cos(thetas[k] * DEG);
            nadir[1] = -sin(thetas[k] * DEG);
            nadir[2] = 0;
            cos_psi = 0;
            for (i = 0; i < 3; i++) cos_psi += nadir[i] * (double)with.dir_sky[i];
            check_close(cos((double)psi), cos_psi, 1e-4, 0, "dir_sky at psi from the nadir");
            /* towards the Sun's side: +x */
            if (!((double)with.dir_sky[0] * sin((double)psi) >= -1e-6)) fail();
            /* flux: e a^2 albedo p(xi) / d^2, observer straight above (+z) */
            xi = acos((double)with.dir_sky[2]);
            ratio = 1.0 / 50000.0; /* 1 m at 50 km */
            a = (double)sc.target_albedo;
            p = 2.0 / (3.0 * PI) * (sin(xi) + (PI - xi) * cos(xi));
            check_close((double)with.e_sky * a * ratio * ratio * p, (double)with.flux_sky, 1e-30,
                        1e-4, "flux_sky");
        }
        check_close((double)(with.flux_sun + with.flux_earth + with.flux_moon + with.flux_sky),
                    (double)with.flux_obs, 1e-30, REL_TOL, "flux_obs is the sum");
        {
            /* no atmosphere: nothing scatters, every other output as with the sky off */
            oi_model m;
            oi_illum none, none_off;
            memset(&m, 0, sizeof m);
            m.no_atmosphere = 1;
            check_int(ST_EARTH, oi_illuminate(&sc, &m, &none), "no atmosphere, sky on");
            check_close(0.0, (double)none.e_sky, 0, 0, "no atmosphere: e_sky");
            check_close(0.0, (double)none.flux_sky, 0, 0, "no atmosphere: flux_sky");
            sc.terms &= ~OI_TERM_SKY;
            check_int(ST_EARTH, oi_illuminate(&sc, &m, &none_off), "no atmosphere, sky off");
            check_close((double)none_off.flux_obs, (double)none.flux_obs, 0, 0,
                        "no atmosphere: flux_obs as without the term");
        }
    }
}

/* oi_expose_scene: a boresight from GEO grazing the night limb gains the
 * sky's share with OI_TERM_SKY and none without it; one ending on the
 * sunlit Earth gains nothing. */
#ifndef OI_NO_EXPOSURE
static void test_expose_background(void **state)
{
    const oi_camera *cam = oi_camera_builtin(0);
    oi_scene sc;
    oi_illum il;
    oi_exposure with, without;
    const double r_obs = 42164.0;
    (void)state;
    oi_scene_defaults(&sc);
    set3(sc.sun_km, AU, 0, 0);
    /* observer on the night side; target on the far side of the limb, the
     * line of sight grazing 40 km above the surface */
    set3(sc.observer_km, -r_obs, 0, 0);
    /* the line from (-r, 0) to (r, -y) passes at r y / sqrt(4 r^2 + y^2) from the
     * centre: y = 2 r b / sqrt(r^2 - b^2) for b = R + 40 km */
    set3(sc.target_km, r_obs,
         -2.0 * r_obs * (RE + 40.0) / sqrt(r_obs * r_obs - (RE + 40.0) * (RE + 40.0)), 0);
    sc.has_observer = 1;
    sc.terms = OI_TERM_SUN | OI_TERM_EARTH;
    check_int(ST_EARTH, oi_illuminate(&sc, NULL, &il), "illuminate");
    (void)oi_expose_scene(cam, &sc, &il, NULL, NULL, &without);
    sc.terms |= OI_TERM_SKY;
    check_int(ST_EARTH, oi_illuminate(&sc, NULL, &il), "illuminate with sky");
    (void)oi_expose_scene(cam, &sc, &il, NULL, NULL, &with);
    if (!(with.background_w_m2_sr > without.background_w_m2_sr)) {
        print_error("sky background %g vs %g\n", (double)with.background_w_m2_sr,
                    (double)without.background_w_m2_sr);
        fail();
    }
    {
        /* without the atmosphere the limb adds nothing */
        oi_model m;
        oi_exposure none;
        memset(&m, 0, sizeof m);
        m.no_atmosphere = 1;
        (void)oi_expose_scene(cam, &sc, &il, &m, NULL, &none);
        check_close((double)without.background_w_m2_sr, (double)none.background_w_m2_sr, 0, 0,
                    "no atmosphere: no sky share");
    }
    /* a nadir view of the sunlit Earth: the ground's radiance only */
    set3(sc.observer_km, r_obs, 0, 0);
    set3(sc.target_km, RE + 500.0, 0, 0);
    check_int(ST_EARTH, oi_illuminate(&sc, NULL, &il), "illuminate day");
    (void)oi_expose_scene(cam, &sc, &il, NULL, NULL, &with);
    sc.terms &= ~OI_TERM_SKY;
    (void)oi_expose_scene(cam, &sc, &il, NULL, NULL, &without);
    check_close((double)without.background_w_m2_sr, (double)with.background_w_m2_sr, 0, 0,
                "sunlit ground: no sky share");
}
#endif

/* v = ln(q + q_floor) = 0: q = 1 - q_floor everywhere */
static const float tiny_v[16] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};

static oi_sky_table tiny_table(void)
{
    oi_sky_table t;
    memset(&t, 0, sizeof t);
    t.format = OI_SKY_FORMAT;
    t.kind = OI_TABLE_KIND_SKYLIGHT;
    t.n_theta = 4;
    t.n_alt = 4;
    t.w_min = (oi_real)0.2;
    t.w_max = (oi_real)(PI / 2);
    t.earth_radius_km = (oi_real)RE;
    t.top_km = (oi_real)TOP;
    t.floor_km = (oi_real)10.0;
    t.theta_scale = (oi_real)(3.0 / PI);
    t.w_scale = (oi_real)(3.0 / (PI / 2 - 0.2));
    t.q_floor = (oi_real)1e-9;
    t.v = tiny_v;
    t.psi = tiny_v;
    return t;
}

/* Hostile inputs: every error zeroes the outputs. */
static void test_hostile(void **state)
{
    oi_real e = 5, psi = 5;
    oi_model m;
    oi_sky_table t;
    oi_scene sc;
    oi_illum il;
    (void)state;
    check_int(OI_ERR_NULL, oi_skylight(1, 400, NULL, NULL, &psi), "NULL e");
    check_close(0, (double)psi, 0, 0, "zeroed psi");
    check_int(OI_ERR_NONFINITE, oi_skylight((oi_real)NAN, 400, NULL, &e, &psi), "NaN theta");
    check_close(0, (double)e, 0, 0, "zeroed e");
    check_int(OI_ERR_NONFINITE, oi_skylight(1, (oi_real)INFINITY, NULL, &e, &psi), "inf h");
    check_int(OI_ERR_INPUT, oi_skylight(-0.1f, 400, NULL, &e, &psi), "theta < 0");
    check_int(OI_ERR_INPUT, oi_skylight(3.2f, 400, NULL, &e, &psi), "theta > pi");
    check_int(OI_ERR_INPUT, oi_skylight(1, -1, NULL, &e, &psi), "h < 0");
    check_int(OI_OK, oi_skylight(1, (oi_real)1e30, NULL, &e, &psi), "far away");
    if (!(e >= 0 && e < 1e-12)) fail();
    /* a caller's table: valid, then broken field by field */
    memset(&m, 0, sizeof m);
    t = tiny_table();
    m.sky_table = &t;
    check_int(OI_OK, oi_skylight(1, 400, &m, &e, &psi), "caller's table");
    check_close(pow(RE / (RE + 400.0), 2), (double)e, 0, 1e-5, "constant table: x^2");
    t.format = 99;
    check_int(OI_ERR_MODEL, oi_skylight(1, 400, &m, &e, &psi), "format");
    check_close(0, (double)e, 0, 0, "zeroed");
    t = tiny_table();
    t.n_theta = 3;
    check_int(OI_ERR_MODEL, oi_skylight(1, 400, &m, &e, &psi), "n_theta");
    t = tiny_table();
    t.theta_scale = (oi_real)NAN;
    check_int(OI_ERR_MODEL, oi_skylight(1, 400, &m, &e, &psi), "theta_scale NaN");
    t = tiny_table();
    t.w_max = 2;
    check_int(OI_ERR_MODEL, oi_skylight(1, 400, &m, &e, &psi), "w_max beyond pi/2");
    t = tiny_table();
    t.v = NULL;
    check_int(OI_ERR_MODEL, oi_skylight(1, 400, &m, &e, &psi), "v NULL");
    t = tiny_table();
    t.q_floor = 0;
    check_int(OI_ERR_MODEL, oi_skylight(1, 400, &m, &e, &psi), "q_floor 0");
    /* through oi_illuminate: the broken table zeroes everything */
    leo_scene(&sc, 1.0, 400.0);
    sc.terms |= OI_TERM_SKY;
    check_int(OI_ERR_MODEL, oi_illuminate(&sc, &m, &il), "illuminate, broken table");
    check_close(0, (double)il.e_sun, 0, 0, "zeroed illum");
    /* unknown terms bits are still refused */
    sc.terms = OI_TERM_SKY | 16u;
    check_int(OI_ERR_TERMS, oi_illuminate(&sc, NULL, &il), "unknown bit");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_energy_bound),
        cmocka_unit_test(test_continuity),
        cmocka_unit_test(test_umbra),
        cmocka_unit_test(test_illuminate),
#ifndef OI_NO_EXPOSURE
        cmocka_unit_test(test_expose_background),
#endif
        cmocka_unit_test(test_hostile),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
#else
int main(void)
{
    oi_scene sc;
    oi_illum il;
    oi_scene_defaults(&sc);
    sc.sun_km[0] = (oi_real)1.5e8;
    sc.target_km[0] = (oi_real)7000.0;
    sc.terms = OI_TERM_SUN | 8u; /* OI_TERM_SKY's bit, compiled out */
    if (oi_illuminate(&sc, NULL, &il) != OI_ERR_TERMS) return 1;
    printf("skip test_skylight: built with OI_NO_SKYLIGHT (the sky bit is refused)\n");
    return 0;
}
#endif
