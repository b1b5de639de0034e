/* SPDX-License-Identifier: MIT */
/* test_oblate.c: the WGS-84 ellipsoid as the Earth's occulter
 * (oi_model.earth_shape = OI_EARTH_WGS84): the visible fraction of the Sun
 * behind its elliptic silhouette (alone, and with the Moon) and of the Moon's
 * disc behind it, against mpmath polar quadratures with exact ray-ellipsoid
 * intersections (ref_oblate.h from tests/ref/oblate.py, a different algorithm
 * from the library's gnomonic chords); the regions; monotonicity along a
 * 500 km polar pass; the ellipsoid's inside (OI_ERR_BELOW_SURFACE), its
 * heights and its hiding the target (OI_FLAG_OCCULTED); the sphere default
 * unchanged; the effect on a 500 km polar orbit's eclipse entry, printed
 * (docs/shadow.md section 10). */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "orbillum.h"
#include "oi_test_util.h"

#ifndef OI_NO_OBLATE
#include "ref_oblate.h"

/* Tolerances (absolute, on fractions). Double: 1e-9, the bound the
 * runtime states (measured worst in docs/shadow.md section 10). Single: the
 * silhouette's angular radius carries the rounding of the cone's entries,
 * eps / (2 sin r_e cos r_e) ~ 2 eps at 500 km, times the fraction's slope
 * 1/(2 r_sun) ~ 1e2 per radian: ~3e-5, twice the sphere's, so 1e-4 (1 m
 * above the surface included). */
#ifdef OI_SINGLE_PRECISION
#define FRACTION_TOL 1e-4
#define KM_TOL (8 * 7000 * (double)FLT_EPSILON)
#else
#define FRACTION_TOL 1e-9
#define KM_TOL (1e-9 * 7000)
#endif

/* The Earth and the Moon on the Sun at once: the reference itself is off
 * there, by 3.1e-8 against the exact three caps in the limit of a sphere
 * (its split misses where the two outlines cross inside the disc; the
 * runtime's chords agree with the caps to 1e-14 in that limit,
 * docs/shadow.md section 10), so the runtime is checked to 3e-7 only. */
#ifdef OI_SINGLE_PRECISION
#define BOTH_TOL 1e-4
#else
#define BOTH_TOL 3e-7
#endif

#define A_KM 6378.137
#define PI_D 3.14159265358979323846
#define B_KM (A_KM * (1.0 - 1.0 / OI_WGS84_INV_FLATTENING))

static oi_model wgs84_model(int atmosphere)
{
    oi_model m;
    memset(&m, 0, sizeof m);
    m.earth_shape = OI_EARTH_WGS84;
    m.no_atmosphere = !atmosphere;
    return m;
}

static void test_vs_mpmath(void **state)
{
    size_t i, n = sizeof ref_oblate / sizeof ref_oblate[0];
    double worst = 0, worst_moon = 0, worst_vis = 0, moved = 0, worst_ld = 0, worst_moon_ld = 0;
    double estimate = 0;
    const oi_model m = wgs84_model(0);
    (void)state;
    for (i = 0; i < n; ++i) {
        const ref_oblate_row *r = &ref_oblate[i];
        oi_real sun[3], p[3];
        oi_shadow sh;
        const double tol = FRACTION_TOL;
        int st;
        set3(sun, r->sun[0], r->sun[1], r->sun[2]);
        set3(p, r->target[0], r->target[1], r->target[2]);
        st = oi_sun_fraction(sun, p, &m, &sh);
        check_int(OI_OK, st, r->label);
        check_close(r->fraction, (double)sh.fraction, tol, 0, r->label);
        if (fabs((double)sh.fraction - r->fraction) > worst)
            worst = fabs((double)sh.fraction - r->fraction);
        assert_true(sh.fraction_ld >= (oi_real)0 && sh.fraction_ld <= (oi_real)1);
#ifndef OI_NO_LIMB_DARKENING
        check_close(r->fraction_ld, (double)sh.fraction_ld, tol, 0, r->label);
        if (fabs((double)sh.fraction_ld - r->fraction_ld) > worst_ld)
            worst_ld = fabs((double)sh.fraction_ld - r->fraction_ld);
#endif
        {
            /* the equivalent sphere (the silhouette's radius towards the
             * Sun): how far the ellipsoid moves the uniform fraction, the
             * amount by which the limb-darkened one is moved too */
            oi_model eq = m;
            oi_shadow se;
            eq.earth_shape = OI_EARTH_SPHERE;
            eq.earth_radius_km = (oi_real)(sqrt(r->target[0] * r->target[0] +
                                                r->target[1] * r->target[1] +
                                                r->target[2] * r->target[2]) *
                                           sin((double)sh.earth_radius_rad));
            if (oi_sun_fraction(sun, p, &eq, &se) == OI_OK) {
                /* and how far the limb-darkened fraction estimated by that
                 * move (the sphere's plus the uniform disc's difference)
                 * is from the reference */
                double est = (double)se.fraction_ld + ((double)sh.fraction - (double)se.fraction);
                est = est < 0 ? 0 : est > 1 ? 1 : est;
                if (fabs((double)se.fraction - (double)sh.fraction) > moved)
                    moved = fabs((double)se.fraction - (double)sh.fraction);
                if (fabs(est - r->fraction_ld) > estimate) estimate = fabs(est - r->fraction_ld);
            }
        }
        if (sh.fraction == (oi_real)1) assert_int_equal(sh.region, OI_SHADOW_LIT);
        if (sh.fraction == (oi_real)0) assert_int_equal(sh.region, OI_SHADOW_UMBRA);
        if (sh.region == OI_SHADOW_LIT) assert_true(sh.fraction == (oi_real)1);
        if (sh.region == OI_SHADOW_UMBRA) assert_true(sh.fraction == (oi_real)0);
#ifndef OI_NO_MOON
        if (r->has_moon) {
            oi_scene s;
            oi_illum o;
            oi_scene_defaults(&s);
            set3(s.sun_km, r->sun[0], r->sun[1], r->sun[2]);
            set3(s.target_km, r->target[0], r->target[1], r->target[2]);
            set3(s.moon_km, r->moon[0], r->moon[1], r->moon[2]);
            s.has_moon = 1;
            s.terms = OI_TERM_SUN | OI_TERM_MOON;
            st = oi_illuminate(&s, &m, &o);
            if (st < 0) check_int(OI_OK, st, r->label);
            check_close(r->fraction_moon, (double)o.shadow.fraction, BOTH_TOL, 0, r->label);
#ifndef OI_NO_LIMB_DARKENING
            check_close(r->fraction_moon_ld, (double)o.shadow.fraction_ld, BOTH_TOL, 0, r->label);
            if (fabs((double)o.shadow.fraction_ld - r->fraction_moon_ld) > worst_moon_ld)
                worst_moon_ld = fabs((double)o.shadow.fraction_ld - r->fraction_moon_ld);
#endif
            check_close(r->moon_visible, (double)o.moon_disc_visible, FRACTION_TOL, 0, r->label);
            if (fabs((double)o.shadow.fraction - r->fraction_moon) > worst_moon)
                worst_moon = fabs((double)o.shadow.fraction - r->fraction_moon);
            if (fabs((double)o.moon_disc_visible - r->moon_visible) > worst_vis)
                worst_vis = fabs((double)o.moon_disc_visible - r->moon_visible);
            assert_true(o.shadow.fraction_ld >= (oi_real)0 && o.shadow.fraction_ld <= (oi_real)1);
        }
#endif
    }
    print_message("oblate rows: %zu, worst |fraction - ref| = %.3g (Earth alone), %.3g (with the "
                  "Moon), |moon_disc_visible - ref| = %.3g; the ellipsoid moves the equivalent "
                  "sphere's fraction by up to %.3g\n", n, worst, worst_moon, worst_vis, moved);
    print_message("oblate rows, limb-darkened: worst |fraction_ld - ref| = %.3g (Earth alone), "
                  "%.3g (with the Moon); the equivalent sphere's fraction_ld moved by the uniform "
                  "difference is off the reference by up to %.3g\n", worst_ld, worst_moon_ld,
                  estimate);
}

/* A point on a circular polar orbit of radius r in the x-z plane (the Sun
 * on +x at declination dec rotated about y: beta = 0), at anomaly u from
 * the ascending node on +x. */
static void polar_point(double r, double u, double out[3])
{
    out[0] = r * cos(u);
    out[1] = 0;
    out[2] = r * sin(u);
}

static double fraction_at(const oi_real sun[3], double r, double u, const oi_model *m)
{
    double p[3];
    oi_real q[3];
    oi_shadow sh;
    polar_point(r, u, p);
    set3(q, p[0], p[1], p[2]);
    (void)oi_sun_fraction(sun, q, m, &sh);
    return (double)sh.fraction;
}

/* The anomaly where the fraction crosses 1/2 on the way into the shadow
 * (bisection between u0, lit, and u1, dark). */
static double half_crossing(const oi_real sun[3], double r, double u0, double u1,
                            const oi_model *m)
{
    int k;
    for (k = 0; k < 80; ++k) {
        const double mid = 0.5 * (u0 + u1);
        if (fraction_at(sun, r, mid, m) > 0.5) u0 = mid;
        else u1 = mid;
    }
    return 0.5 * (u0 + u1);
}

/* The fractions never increase going into the shadow along a 500 km polar
 * pass (both discs, Sun at the equinox and the solstice), and the effect of
 * the ellipsoid on the eclipse entry is printed (docs/shadow.md). */
static void test_polar_pass(void **state)
{
    const double r = A_KM + 500.0, mu = 398600.4418; /* km^3/s^2, IERS 2010 */
    const double period = 2 * PI_D * sqrt(r * r * r / mu);
    const double decs[2] = {0.0, 23.44 * PI_D / 180.0};
    const oi_model m = wgs84_model(0);
    oi_model sphere = m;
    int j, k;
    (void)state;
    sphere.earth_shape = OI_EARTH_SPHERE;
    for (j = 0; j < 2; ++j) {
        oi_real sun[3];
        double prev = 2, prev_ld = 2, u_s, u_e, u0 = 0, u1 = PI_D;
        const double au = 149597870.7;
        /* the Sun at declination dec in the orbit's plane (beta = 0) */
        set3(sun, au * cos(decs[j]), 0, au * sin(decs[j]));
        /* from over the sub-solar point towards the night side, over the pole */
        u0 = decs[j];
        u1 = decs[j] + PI_D;
        for (k = 0; k <= 4000; ++k) {
            /* 0.1 rad either side of the sphere's geometric entry */
            const double u = u1 - asin(A_KM / r) - 0.1 + 0.2 * (double)k / 4000.0;
            double p[3];
            oi_real q[3];
            oi_shadow sh;
            polar_point(r, u, p);
            set3(q, p[0], p[1], p[2]);
            assert_int_equal(oi_sun_fraction(sun, q, &m, &sh), OI_OK);
            assert_true((double)sh.fraction <= prev + 4 * (double)FLT_EPSILON);
            assert_true((double)sh.fraction_ld <= prev_ld + 4 * (double)FLT_EPSILON);
            assert_true(sh.fraction >= 0 && sh.fraction <= 1);
            prev = (double)sh.fraction;
            prev_ld = (double)sh.fraction_ld;
        }
        assert_true(prev == 0);
        u_s = half_crossing(sun, r, u0 + 0.5 * PI_D, u1, &sphere);
        u_e = half_crossing(sun, r, u0 + 0.5 * PI_D, u1, &m);
        {
            /* the shadow's edge there: the equivalent sphere's radius (the
             * silhouette's angular radius towards the Sun) */
            double pe[3];
            oi_real q[3];
            oi_shadow sh;
            polar_point(r, u_e, pe);
            set3(q, pe[0], pe[1], pe[2]);
            (void)oi_sun_fraction(sun, q, &m, &sh);
            print_message("500 km polar, beta 0, Sun at declination %.2f deg: half-Sun entry "
                          "%.2f s later on the ellipsoid (%.2f km along the orbit; at latitude "
                          "%.1f deg); the shadow's edge %.2f km inside the sphere's\n",
                          decs[j] * 180.0 / PI_D, (u_e - u_s) / (2 * PI_D) * period,
                          (u_e - u_s) * r, asin(pe[2] / r) * 180.0 / PI_D,
                          A_KM - r * sin((double)sh.earth_radius_rad));
        }
        assert_true(u_e > u_s); /* the ellipsoid's lower limb: later */
    }
}

/* The ellipsoid's inside, its heights, the option's values. */
static void test_inside_and_heights(void **state)
{
    oi_real sun[3], p[3];
    oi_shadow sh;
    oi_model m = wgs84_model(1);
    (void)state;
    set3(sun, 1.496e8, 0, 0);
    /* between the polar and the equatorial radius over the pole: outside the
     * ellipsoid, inside the sphere */
    set3(p, 0, 0, 6360.0);
    assert_int_equal(oi_sun_fraction(sun, p, &m, &sh), OI_OK);
    assert_int_equal(oi_sun_fraction(sun, p, NULL, &sh), OI_ERR_BELOW_SURFACE);
    set3(p, 0, 0, B_KM - 0.001);
    assert_int_equal(oi_sun_fraction(sun, p, &m, &sh), OI_ERR_BELOW_SURFACE);
    assert_true(sh.fraction == 0 && sh.region == 0);
    set3(p, 6378.0, 0, 0);
    assert_int_equal(oi_sun_fraction(sun, p, &m, &sh), OI_ERR_BELOW_SURFACE);
    set3(p, 0, 0, 0);
    assert_int_equal(oi_sun_fraction(sun, p, &m, &sh), OI_ERR_ZERO_VECTOR);
    set3(p, NAN, 0, 7000);
    assert_int_equal(oi_sun_fraction(sun, p, &m, &sh), OI_ERR_NONFINITE);
    m.earth_shape = 2;
    set3(p, 0, 0, 7000);
    assert_int_equal(oi_sun_fraction(sun, p, &m, &sh), OI_ERR_MODEL);
    m.earth_shape = -1;
    assert_int_equal(oi_sun_fraction(sun, p, &m, &sh), OI_ERR_MODEL);
    {
        /* oi_illuminate: the target and the observer, and the height of
         * earthshine over the pole above the polar radius */
        oi_scene s;
        oi_illum o;
        m = wgs84_model(1);
        oi_scene_defaults(&s);
        set3(s.sun_km, 1.496e8, 0, 0);
        set3(s.moon_km, 0, 384400, 0);
        set3(s.target_km, 0, 0, B_KM + 500.0);
        assert_true(oi_illuminate(&s, &m, &o) >= 0);
        check_close(500.0, (double)o.earth_h_km, KM_TOL, 0, "h over the pole");
        set3(s.target_km, 0, 0, B_KM - 1.0);
        assert_int_equal(oi_illuminate(&s, &m, &o), OI_ERR_BELOW_SURFACE);
        assert_true(o.e_sun == 0 && o.e_moon == 0);
        set3(s.target_km, 0, 0, 7000);
        set3(s.observer_km, 0, 0, B_KM - 1.0);
        s.has_observer = 1;
        assert_int_equal(oi_illuminate(&s, &m, &o), OI_ERR_BELOW_SURFACE);
        s.has_observer = 0;
#ifndef OI_NO_MOON
        set3(s.moon_km, 0, 0, B_KM - 1.0);
        assert_int_equal(oi_illuminate(&s, &m, &o), OI_ERR_BELOW_SURFACE);
#endif
    }
}

/* The default sphere and an explicit OI_EARTH_SPHERE give the same bits. */
static void test_sphere_unchanged(void **state)
{
    uint64_t seed = 13;
    int i;
    oi_model sphere;
    (void)state;
    memset(&sphere, 0, sizeof sphere);
    sphere.earth_shape = OI_EARTH_SPHERE;
    for (i = 0; i < 2000; ++i) {
        oi_real sun[3], p[3];
        oi_shadow a, b;
        double r = 6400 + 40000 * lcg01(&seed);
        set3(sun, 1.496e8, 0, 0);
        set3(p, -r * lcg01(&seed), (2 * lcg01(&seed) - 1) * 7000, (2 * lcg01(&seed) - 1) * 7000);
        assert_int_equal(oi_sun_fraction(sun, p, NULL, &a), oi_sun_fraction(sun, p, &sphere, &b));
        assert_memory_equal(&a, &b, sizeof a);
    }
}

/* 20000 random geometries near the ellipsoid's shadow: finite, in [0, 1]. */
static void test_random_bounded(void **state)
{
    uint64_t seed = 7;
    int i;
    const oi_model m = wgs84_model(1);
    (void)state;
    for (i = 0; i < 20000; ++i) {
        oi_real sun[3], p[3];
        oi_shadow sh;
        const double dec = (2 * lcg01(&seed) - 1) * 0.45;
        const double r = 6357.0 + pow(10.0, 6.5 * lcg01(&seed));
        const double th = 2 * PI_D * lcg01(&seed);
        double z = -r * (0.3 + 0.7 * lcg01(&seed)), rho = sqrt(r * r - z * z);
        int st;
        set3(sun, 1.496e8 * cos(dec), 0, 1.496e8 * sin(dec));
        set3(p, z * cos(dec) - rho * cos(th) * sin(dec), rho * sin(th),
             z * sin(dec) + rho * cos(th) * cos(dec));
        st = oi_sun_fraction(sun, p, &m, &sh);
        if (st == OI_ERR_BELOW_SURFACE) continue;
        assert_true(st >= 0);
        assert_true(sh.fraction >= 0 && sh.fraction <= 1);
        assert_true(sh.fraction_ld >= 0 && sh.fraction_ld <= 1);
        assert_true(sh.fraction_atm >= 0 && sh.fraction_atm <= 1);
    }
}

#ifndef OI_NO_EXPOSURE
/* OI_FLAG_OCCULTED from the ellipsoid: a line of sight over the pole
 * between the polar and the equatorial radius. */
static void test_occulted(void **state)
{
    oi_scene s;
    oi_illum o;
    oi_exposure x;
    oi_model m = wgs84_model(1);
    const double zl = B_KM + 8.0; /* the sight line's height over the pole axis */
    (void)state;
    oi_scene_defaults(&s);
    s.terms = OI_TERM_SUN | OI_TERM_EARTH;
    set3(s.sun_km, 0, 1.496e8, 0);
    set3(s.observer_km, -3000, 0, zl);
    set3(s.target_km, 3000, 0, zl);
    s.has_observer = 1;
    assert_true(oi_illuminate(&s, &m, &o) >= 0);
    assert_true(oi_expose_scene(oi_camera_builtin(0), &s, &o, &m, NULL, &x) >= 0);
    assert_true((x.flags & OI_FLAG_OCCULTED) == 0u);
    /* the sphere of the equatorial radius hides it */
    m.earth_shape = OI_EARTH_SPHERE;
    set3(s.observer_km, -3000, 0, A_KM + 10);
    set3(s.target_km, 3000, 0, A_KM + 10);
    assert_true(oi_illuminate(&s, &m, &o) >= 0);
    assert_true(oi_expose_scene(oi_camera_builtin(0), &s, &o, &m, NULL, &x) >= 0);
    assert_true((x.flags & OI_FLAG_OCCULTED) == 0u);
    /* a line through the ellipsoid (8 km below the polar radius) is hidden */
    m.earth_shape = OI_EARTH_WGS84;
    set3(s.observer_km, -7000, 0, B_KM - 8.0);
    set3(s.target_km, 7000, 0, B_KM - 8.0);
    assert_true(oi_illuminate(&s, &m, &o) >= 0);
    assert_true(oi_expose_scene(oi_camera_builtin(0), &s, &o, &m, NULL, &x) >= 0);
    assert_true((x.flags & OI_FLAG_OCCULTED) != 0u);
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_vs_mpmath),
        cmocka_unit_test(test_polar_pass),
        cmocka_unit_test(test_inside_and_heights),
        cmocka_unit_test(test_sphere_unchanged),
        cmocka_unit_test(test_random_bounded),
#ifndef OI_NO_EXPOSURE
        cmocka_unit_test(test_occulted),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
#else
#include <stdio.h>
#include <string.h>
int main(void)
{
    /* the option refuses the ellipsoid */
    oi_model m;
    oi_shadow sh;
    oi_real sun[3] = {(oi_real)1.496e8, 0, 0}, p[3] = {0, 0, (oi_real)7000};
    memset(&m, 0, sizeof m);
    m.earth_shape = OI_EARTH_WGS84;
    if (oi_sun_fraction(sun, p, &m, &sh) != OI_ERR_MODEL) return 1;
    printf("skip test_oblate: OI_NO_OBLATE removes the ellipsoid (OI_ERR_MODEL checked)\n");
    return 0;
}
#endif
