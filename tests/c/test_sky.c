/* SPDX-License-Identifier: MIT */
/*
 * test_sky.c: the sky background of oi_expose_scene (oi_expose_goal.sky):
 * the zodiacal light (oi_zodiacal_radiance against Leinert et al. 1998,
 * Table 17, and its unit against the Planck spectrum in closed form), the
 * ecliptic frame (boresights at known ecliptic coordinates of an
 * ICRF-aligned scene), the Moon in the field (flag, its Lambertian surface
 * against the closed form and the published full-Moon brightness,
 * occultation) and the hostile inputs.
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
#include "oi_test_sky.h"

#ifdef OI_SINGLE_PRECISION
#define REL_TOL 2e-5
#else
#define REL_TOL 1e-12
#endif

#if !defined(OI_NO_SKY) && !defined(OI_NO_EXPOSURE)
#ifndef OI_NO_MOON
#define SKY_MOON_BIT OI_SKY_MOON
static const double TSI = 1361.0; /* W m^-2 (Kopp & Lean 2011): the Moon's sky */
#else
#define SKY_MOON_BIT 0u /* no Moon in this build: the bit is unknown */
#endif
static const double PI = 3.14159265358979323846;
static const double AU = 149597870.7;
static const double DEG = 3.14159265358979323846 / 180.0;
/* IAU 2006 mean obliquity of J2000, 84381.406 arcsec */
static const double EPS = 84381.406 / 3600.0 * 3.14159265358979323846 / 180.0;

/* Leinert et al. 1998 (A&AS 127, 1), Table 17, 1e-8 W m^-2 sr^-1 um^-1 at
 * 500 nm; 0 where the paper has no entry (within ~15 deg of the Sun). Typed
 * from the publication, row by row (longitude from the Sun), column by
 * column (ecliptic latitude). */
static const double LON[19] = {0, 5, 10, 15, 20, 25, 30, 35, 40, 45, 60, 75, 90, 105, 120, 135,
                               150, 165, 180};
static const double LAT[11] = {0, 5, 10, 15, 20, 25, 30, 45, 60, 75, 90};
static const double TABLE17[19][11] = {
    {0, 0, 0, 3140, 1610, 985, 640, 275, 150, 100, 77},
    {0, 0, 0, 2940, 1540, 945, 625, 271, 150, 100, 77},
    {0, 0, 4740, 2470, 1370, 865, 590, 264, 148, 100, 77},
    {11500, 6780, 3440, 1860, 1110, 755, 525, 251, 146, 100, 77},
    {6400, 4480, 2410, 1410, 910, 635, 454, 237, 141, 99, 77},
    {3840, 2830, 1730, 1100, 749, 545, 410, 223, 136, 97, 77},
    {2480, 1870, 1220, 845, 615, 467, 365, 207, 131, 95, 77},
    {1650, 1270, 910, 680, 510, 397, 320, 193, 125, 93, 77},
    {1180, 940, 700, 530, 416, 338, 282, 179, 120, 92, 77},
    {910, 730, 555, 442, 356, 292, 250, 166, 116, 90, 77},
    {505, 442, 352, 292, 243, 209, 183, 134, 104, 86, 77},
    {338, 317, 269, 227, 196, 172, 151, 116, 93, 82, 77},
    {259, 251, 225, 193, 166, 147, 132, 104, 86, 79, 77},
    {212, 210, 197, 170, 150, 133, 119, 96, 82, 77, 77},
    {188, 186, 177, 154, 138, 125, 113, 90, 77, 74, 77},
    {179, 178, 166, 147, 134, 122, 110, 90, 77, 73, 77},
    {179, 178, 165, 148, 137, 127, 116, 96, 79, 72, 77},
    {196, 192, 179, 165, 151, 141, 131, 104, 82, 72, 77},
    {230, 212, 195, 178, 163, 148, 134, 105, 83, 72, 77},
};

/* One table unit as a whole-spectrum solar radiance, in closed form: the
 * 5772 K Planck spectrum's fraction per um at 500 nm is
 * pi B_lambda(500 nm) / (sigma T^4) (the integral of B_lambda over lambda is
 * sigma T^4 / pi), so a unit is 1e-8 / that. */
static double unit_w_m2_sr(void)
{
    const double h = 6.62607015e-34, c = 299792458.0, k = 1.380649e-23, T = 5772.0;
    const double sigma = 2.0 * pow(PI, 5) * pow(k, 4) / (15.0 * pow(h, 3) * c * c);
    const double l = 500e-9;
    double b = 2.0 * h * c * c / pow(l, 5) / expm1(h * c / (l * k * T));
    double per_um = PI * b / (sigma * pow(T, 4)) * 1e-6;
    return 1e-8 / per_um;
}

/* Every published node, both signs of both angles, and the longitude
 * modulo 2 pi. */
static void test_zodiacal_table_nodes(void **state)
{
    const double unit = unit_w_m2_sr();
    int i, j, n = 0;
    (void)state;
    for (i = 0; i < 19; i++) {
        for (j = 0; j < 11; j++) {
            double want = TABLE17[i][j] * unit;
            if (TABLE17[i][j] == 0) continue;
            check_rel(want, oi_zodiacal_radiance((oi_real)(LON[i] * DEG), (oi_real)(LAT[j] * DEG)),
                      REL_TOL * 10, "node");
            check_rel(want, oi_zodiacal_radiance((oi_real)(-LON[i] * DEG), (oi_real)(-LAT[j] * DEG)),
                      REL_TOL * 10, "node, negative angles");
            check_rel(want, oi_zodiacal_radiance((oi_real)((LON[i] + 360.0) * DEG),
                                                 (oi_real)(LAT[j] * DEG)),
                      1e-5, "node + 360 deg");
            n++;
        }
    }
    check_int(19 * 11 - 8, n, "published nodes"); /* 8 cells near the Sun are blank */
    /* Table 19 of the same paper, 2.6e-6 W m^-2 sr^-1 um^-1 at 0.5 um for the
     * ecliptic at 90 deg from the Sun, is the 259 of Table 17 to 0.4 % */
    check_rel(2.6e-6 / 1e-8 * unit, oi_zodiacal_radiance((oi_real)(PI / 2), 0), 0.005, "Table 19");
}

/* Between nodes: the centre of a cell is the mean of its four corners
 * (bilinear), in both grid spacings; beyond 90 deg of latitude the pole. */
static void test_zodiacal_between_nodes(void **state)
{
    const double unit = unit_w_m2_sr();
    int i, j;
    (void)state;
    for (i = 3; i < 18; i++) {
        for (j = 0; j < 10; j++) {
            double want = 0.25 * (TABLE17[i][j] + TABLE17[i + 1][j] + TABLE17[i][j + 1] +
                                  TABLE17[i + 1][j + 1]) * unit;
            double dl = 0.5 * (LON[i] + LON[i + 1]) * DEG, b = 0.5 * (LAT[j] + LAT[j + 1]) * DEG;
            check_rel(want, oi_zodiacal_radiance((oi_real)dl, (oi_real)b), 1e-5, "cell centre");
        }
    }
    check_rel(77 * unit, oi_zodiacal_radiance((oi_real)1.0, (oi_real)2.0), 1e-5, "|beta| > 90");
    /* the unpublished cells near the Sun hold the first value of their column */
    check_rel(11500 * unit, oi_zodiacal_radiance(0, 0), 1e-5, "near-Sun fill");
    check_rel(4740 * unit, oi_zodiacal_radiance(0, (oi_real)(10 * DEG)), 1e-5, "fill 10 deg");
    check_rel(0.0, oi_zodiacal_radiance((oi_real)NAN, 0), 0, "NaN");
    check_rel(0.0, oi_zodiacal_radiance(0, (oi_real)INFINITY), 0, "inf");
}

/* A camera whose background rate is radiance * 1e3 e-/s (IFOV 1e-7 rad,
 * A = 1 m^2, k = 1e17 e-/J) and a dark current of 0. */
static oi_camera sky_camera(void)
{
    oi_camera c = oi_test_camera("sky");
    c.pixel_pitch_m = (oi_real)1e-7;
    c.photon_energy_j = (oi_real)1e-17;
    c.full_well_e = (oi_real)1e6;
    c.psf_peak_fraction = 1;
    c.fov_rad = (oi_real)0.02;
    c.n_times = 3;
    c.times_s[1] = 10;
    c.times_s[2] = 100;
    return c;
}

/* Equatorial (ICRF-aligned) vector of ecliptic longitude lon, latitude lat. */
static void ecl_to_eq(double lon, double lat, double d, oi_real v[3])
{
    double x = cos(lat) * cos(lon), y = cos(lat) * sin(lon), z = sin(lat);
    set3(v, d * x, d * (y * cos(EPS) - z * sin(EPS)), d * (y * sin(EPS) + z * cos(EPS)));
}

/* The observer in GEO on the +z (north) side looking away from the Earth at
 * a target 100 km off, along ecliptic (lon, lat); the Sun at ecliptic
 * longitude sun_lon. Returns the background radiance oi_expose_scene used. */
static double scene_radiance(double sun_lon, double lon, double lat, unsigned sky, oi_exposure *out)
{
    oi_camera c = sky_camera();
    oi_illum il = oi_test_lit_illum(1e-16);
    oi_real sun[3], observer[3], dir[3], target[3];
    ecl_to_eq(sun_lon, 0, AU, sun);
    set3(observer, 0, 0, 42164.0);
    ecl_to_eq(lon, lat, 100.0, dir);
    set3(target, observer[0] + dir[0], observer[1] + dir[1], observer[2] + dir[2]);
    return oi_test_sky_background(&c, &il, sky, sun, observer, target, out);
}

/* Ecliptic directions of the boresight (away from the Earth) against the
 * table: the north ecliptic pole (77), the anti-solar point (230, the
 * Gegenschein), 90 deg from the Sun in the ecliptic (259), (60, 45) (134);
 * the background enters the electrons; sky = 0 keeps the black sky. */
static void test_zodiacal_in_scene(void **state)
{
    const double unit = unit_w_m2_sr();
    const double tol = 2e-4; /* the geometry's rounding in single precision */
    oi_exposure out;
    (void)state;
    check_rel(77 * unit, scene_radiance(0.3, 1.0, PI / 2, OI_SKY_ZODIACAL, &out), tol, "pole");
    check_rel(out.background_w_m2_sr * 1e3 * out.exposure_s, out.background_e, REL_TOL * 10,
              "background electrons");
    check_rel(230 * unit, scene_radiance(0.3, 0.3 + PI, 0.0, OI_SKY_ZODIACAL, &out), tol,
              "Gegenschein");
    check_rel(259 * unit, scene_radiance(2.0, 2.0 - PI / 2, 0.0, OI_SKY_ZODIACAL, &out), tol,
              "90 deg east");
    check_rel(259 * unit, scene_radiance(2.0, 2.0 + PI / 2, 0.0, OI_SKY_ZODIACAL, &out), tol,
              "90 deg west");
    check_rel(134 * unit, scene_radiance(-1.0, -1.0 + 60 * DEG, -45 * DEG, OI_SKY_ZODIACAL, &out),
              tol, "60 deg, -45 deg");
    check_rel(0.0, scene_radiance(0.3, 1.0, PI / 2, 0u, &out), 0, "no sky");
    check_rel(0.0, out.background_e, 0, "no sky electrons");
}

/* Looking at the Earth, the zodiacal light is not added (the ray ends on
 * the Earth): the nadir of the night side has a zero background. */
static void test_zodiacal_not_through_earth(void **state)
{
    oi_camera c = sky_camera();
    oi_illum il = oi_test_lit_illum(1e-16);
    oi_exposure out;
    (void)state;
    check_rel(0.0, oi_test_night_nadir(&c, &il, OI_SKY_ZODIACAL | SKY_MOON_BIT, &out), 0,
              "night Earth");
    assert_true(out.flags & OI_FLAG_EARTH_IN_FOV);
}

#ifndef OI_NO_MOON
/* The Moon behind the target, full (Sun behind the observer): the ray
 * through the disc centre meets the sub-solar point, radiance
 * moon_albedo * TSI (AU / |sun - moon|)^2 / pi (closed form), which is the
 * published full Moon's mean surface brightness (V = -12.73 over a disc of
 * 1737.4 km at 384400 km) to 5 %; OI_FLAG_MOON_IN_FOV; the background is
 * used only with OI_SKY_MOON and OI_TERM_MOON. */
static void test_moon_behind_target(void **state)
{
    oi_camera c = sky_camera();
    oi_scene s;
    oi_illum il = oi_test_lit_illum(1e-16);
    oi_expose_goal goal;
    oi_exposure out;
    double dm = 384400.0, sun_d = AU, want, published, omega;
    (void)state;
    memset(&goal, 0, sizeof goal);
    goal.sky = OI_SKY_MOON;
    oi_scene_defaults(&s);
    set3(s.sun_km, -sun_d, 0, 50000.0);
    set3(s.observer_km, 0, 0, 42164.0);
    set3(s.moon_km, dm, 0, 42164.0);
    set3(s.target_km, 100.0, 0, 42164.0);
    s.has_observer = 1;
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, &goal, &out), "status");
    {
        double sm[3] = {-sun_d - dm, 0, 50000.0 - 42164.0};
        double r = sqrt(sm[0] * sm[0] + sm[1] * sm[1] + sm[2] * sm[2]);
        double cos_i = -sm[0] / r;
        want = 0.12 * TSI * (AU / r) * (AU / r) * cos_i / PI;
    }
    check_rel(want, out.background_w_m2_sr, 1e-4, "Lambert Moon");
    omega = PI * pow(1737.4 / 384400.0, 2);
    published = TSI * pow(10.0, -0.4 * (-12.73 + 26.74)) / omega;
    check_rel(published, out.background_w_m2_sr, 0.05, "published full Moon");
    assert_true(out.flags & OI_FLAG_MOON_IN_FOV);
    assert_false(out.flags & OI_FLAG_OCCULTED);
    /* the Moon term off: its position is not read, no flag, black sky */
    s.terms = OI_TERM_SUN | OI_TERM_EARTH;
    set3(s.moon_km, NAN, 0, 0);
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, &goal, &out), "status no term");
    check_rel(0.0, out.background_w_m2_sr, 0, "no Moon term");
    assert_false(out.flags & OI_FLAG_MOON_IN_FOV);
    /* with the term, a NaN Moon is an error with zeroed outputs */
    s.terms = OI_TERM_ALL;
    check_int(OI_ERR_NONFINITE, oi_expose_scene(&c, &s, &il, NULL, &goal, &out), "NaN Moon");
    check_rel(0.0, out.exposure_s, 0, "zeroed");
}

/* The Moon in front of the target: occulted (no signal, too faint); the
 * Moon beside the boresight within the half field: the flag only; beyond
 * it: nothing. The disc's edge is at asin(Rm / d) from its centre. */
static void test_moon_in_front_and_beside(void **state)
{
    oi_camera c = sky_camera();
    oi_scene s;
    oi_illum il = oi_test_lit_illum(1e-12);
    oi_expose_goal goal;
    oi_exposure out;
    double dm = 384400.0, rho = asin(1737.4 / dm), off;
    (void)state;
    memset(&goal, 0, sizeof goal);
    goal.sky = OI_SKY_MOON;
    oi_scene_defaults(&s);
    set3(s.sun_km, 0, AU, 0);
    set3(s.observer_km, 0, 0, 42164.0);
    set3(s.moon_km, dm, 0, 42164.0);
    set3(s.target_km, 2 * dm, 0, 42164.0);
    s.has_observer = 1;
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, &goal, &out), "status");
    assert_true(out.flags & OI_FLAG_OCCULTED);
    assert_true(out.flags & OI_FLAG_TOO_FAINT);
    check_rel(0.0, out.signal_e, 0, "occulted signal");
    /* a quarter Moon: the point under the boresight, (dm - Rm, 0, z), sees
     * the Sun (on +y) at cos i = (dm - Rm) / |sun - point| */
    {
        double px = dm - 1737.4, dz = 42164.0;
        double r_hit = sqrt(px * px + AU * AU + dz * dz), r_moon = sqrt(dm * dm + AU * AU + dz * dz);
        double want = 0.12 * TSI * (AU / r_moon) * (AU / r_moon) * (px / r_hit) / PI;
        check_rel(want, out.background_w_m2_sr, 1e-3, "quarter Moon centre");
    }
    /* beside the boresight: the disc's edge 0.9 and 1.1 half fields away */
    off = rho + 0.9 * 0.01;
    set3(s.target_km, 100.0 * cos(off), 100.0 * sin(off), 42164.0);
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, &goal, &out), "status beside");
    assert_true(out.flags & OI_FLAG_MOON_IN_FOV);
    check_rel(0.0, out.background_w_m2_sr, 0, "beside: no background");
    off = rho + 1.1 * 0.01;
    set3(s.target_km, 100.0 * cos(off), 100.0 * sin(off), 42164.0);
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, &goal, &out), "status outside");
    assert_false(out.flags & OI_FLAG_MOON_IN_FOV);
    /* without OI_SKY_MOON, as before: no flag, no occultation */
    goal.sky = 0;
    set3(s.target_km, 2 * dm, 0, 42164.0);
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, &goal, &out), "status no sky");
    assert_false(out.flags & (OI_FLAG_MOON_IN_FOV | OI_FLAG_OCCULTED));
}

#endif /* OI_NO_MOON */

/* Unknown sky bits: OI_ERR_FLAGS, outputs zeroed, for oi_expose too. */
static void test_sky_hostile(void **state)
{
    oi_camera c = sky_camera();
    oi_expose_in in;
    oi_expose_goal goal;
    oi_exposure out;
    (void)state;
    memset(&goal, 0, sizeof goal);
    memset(&in, 0, sizeof in);
    in.flux_w_m2 = (oi_real)1e-12;
    goal.sky = 8u;
    check_int(OI_ERR_FLAGS, oi_expose(&c, &in, &goal, &out), "unknown sky bit");
#ifdef OI_NO_MOON
    goal.sky = 2u;
    check_int(OI_ERR_FLAGS, oi_expose(&c, &in, &goal, &out), "Moon bit without the Moon");
#endif
    check_rel(0.0, out.exposure_s, 0, "zeroed");
    goal.sky = OI_SKY_ZODIACAL | SKY_MOON_BIT;
    check_int(OI_OK, oi_expose(&c, &in, &goal, &out), "known bits");
    check_int(0, (long)(out.flags & OI_FLAG_MOON_IN_FOV), "no geometry in oi_expose");
    assert_string_equal("moon_in_fov", oi_flag_name(OI_FLAG_MOON_IN_FOV));
}
#endif

int main(void)
{
#if !defined(OI_NO_SKY) && !defined(OI_NO_EXPOSURE)
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_zodiacal_table_nodes),
        cmocka_unit_test(test_zodiacal_between_nodes),
        cmocka_unit_test(test_zodiacal_in_scene),
        cmocka_unit_test(test_zodiacal_not_through_earth),
#ifndef OI_NO_MOON
        cmocka_unit_test(test_moon_behind_target),
        cmocka_unit_test(test_moon_in_front_and_beside),
#endif
        cmocka_unit_test(test_sky_hostile),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
#else
    printf("skip test_sky: built with OI_NO_SKY or OI_NO_EXPOSURE\n");
    return 0;
#endif
}
