/* SPDX-License-Identifier: MIT */
/*
 * test_starlight.c: the integrated starlight of the camera's sky
 * (OI_SKY_STARLIGHT): oi_starlight_radiance at every node of Leinert et al.
 * 1998, Table 35, typed from the publication, its unit in closed form, the
 * interpolation, the unmapped cells and the poles; oi_galactic_from_icrs
 * against the three angles that define the galactic frame in the ICRS
 * (Hipparcos, ESA SP-1200 Vol. 1, Sect. 1.5.3); the background of
 * oi_expose_scene; hostile inputs. tests/python/test_starlight.py checks
 * the rotation against astropy.
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
#define ANG_TOL 2e-6 /* rad: float rounding of the unit vector and atan2 */
#else
#define REL_TOL 1e-12
#define ANG_TOL 1e-12
#endif

#if !defined(OI_NO_SKY)
static const double PI = 3.14159265358979323846;
static const double DEG = 3.14159265358979323846 / 180.0;

/* Leinert et al. 1998 (A&AS 127, 1), Table 35, S10_sun at 440 nm (Pioneer
 * 10, Toller 1981), by galactic latitude (rows) and longitude 0, 10, ..,
 * 350 deg (columns); 0 where Pioneer did not map the sky. */
static const double LAT[25] = {-80, -70, -60, -50, -40, -30, -24, -20, -16, -12, -8, -4, 0,
                               4,   8,   12,  16,  20,  24,  30,  40,  50,  60,  70,  80};
static const double TABLE35[25][36] = {
    /* -80 */ {34, 32, 30, 32, 29, 33, 35, 31, 28, 34, 31, 26, 26, 30, 27, 26, 27, 30, 33, 32, 28, 26, 26, 27, 27, 27, 28, 29, 28, 29, 29, 25, 25, 28, 28, 30},
    /* -70 */ {32, 28, 33, 35, 39, 32, 32, 34, 35, 31, 24, 34, 33, 30, 30, 36, 33, 32, 32, 32, 30, 30, 32, 30, 26, 26, 33, 29, 26, 25, 32, 29, 29, 31, 34, 35},
    /* -60 */ {39, 41, 41, 39, 37, 35, 41, 46, 36, 33, 35, 35, 32, 34, 35, 35, 43, 34, 36, 34, 31, 30, 33, 36, 37, 38, 33, 38, 42, 45, 42, 40, 38, 35, 36, 32},
    /* -50 */ {45, 48, 49, 43, 47, 49, 39, 46, 41, 43, 39, 37, 36, 41, 45, 42, 40, 44, 40, 45, 42, 39, 43, 38, 38, 40, 41, 40, 39, 44, 43, 50, 48, 38, 45, 51},
    /* -40 */ {56, 68, 53, 57, 63, 56, 57, 63, 46, 46, 48, 44, 48, 45, 41, 46, 47, 46, 51, 50, 56, 48, 52, 46, 42, 47, 52, 55, 58, 55, 68, 58, 62, 59, 61, 58},
    /* -30 */ {78, 87, 76, 77, 80, 88, 68, 71, 64, 60, 65, 73, 53, 67, 64, 57, 60, 61, 67, 65, 70, 74, 69, 57, 63, 66, 85, 81, 213, 68, 73, 78, 74, 85, 81, 82},
    /* -24 */ {99, 111, 96, 89, 90, 88, 91, 84, 81, 87, 80, 74, 83, 84, 78, 81, 69, 77, 67, 77, 97, 122, 91, 79, 91, 86, 113, 95, 87, 94, 94, 97, 103, 101, 108, 114},
    /* -20 */ {120, 133, 124, 105, 101, 124, 105, 94, 103, 105, 93, 95, 108, 97, 95, 78, 84, 79, 53, 90, 119, 122, 109, 109, 106, 101, 115, 119, 116, 107, 103, 116, 135, 130, 133, 156},
    /* -16 */ {190, 176, 176, 123, 111, 131, 142, 112, 113, 109, 120, 125, 114, 124, 116, 115, 73, 60, 73, 105, 130, 141, 121, 131, 139, 136, 143, 146, 128, 140, 112, 166, 176, 176, 180, 204},
    /* -12 */ {320, 204, 221, 143, 145, 186, 187, 162, 163, 148, 151, 157, 158, 144, 129, 135, 104, 63, 103, 117, 139, 130, 144, 208, 169, 163, 197, 169, 194, 197, 156, 196, 242, 234, 228, 281},
    /*  -8 */ {484, 283, 224, 172, 180, 219, 237, 198, 230, 186, 235, 205, 191, 182, 150, 150, 99, 77, 81, 146, 156, 188, 185, 254, 262, 208, 288, 239, 276, 258, 246, 239, 292, 309, 320, 379},
    /*  -4 */ {569, 371, 223, 172, 186, 256, 244, 210, 231, 262, 326, 224, 215, 223, 133, 119, 120, 108, 128, 190, 221, 182, 229, 255, 282, 219, 258, 246, 369, 351, 323, 376, 306, 467, 270, 318},
    /*  +0 */ {290, 275, 182, 100, 122, 151, 187, 275, 219, 221, 247, 177, 199, 174, 132, 125, 148, 195, 180, 182, 209, 251, 278, 272, 342, 302, 239, 177, 338, 634, 354, 446, 248, 314, 289, 278},
    /*  +4 */ {147, 210, 111, 87, 186, 169, 220, 342, 216, 156, 160, 153, 124, 136, 138, 108, 166, 171, 182, 191, 199, 222, 263, 261, 274, 294, 207, 181, 280, 441, 356, 337, 251, 279, 151, 251},
    /*  +8 */ {164, 222, 77, 107, 209, 175, 223, 242, 220, 195, 140, 136, 111, 96, 96, 102, 133, 142, 147, 184, 186, 189, 186, 193, 197, 202, 169, 181, 204, 227, 238, 192, 197, 247, 127, 208},
    /* +12 */ {169, 142, 81, 167, 163, 155, 170, 174, 169, 160, 116, 124, 115, 95, 91, 84, 107, 129, 134, 146, 154, 149, 149, 143, 147, 126, 131, 142, 144, 159, 173, 208, 175, 209, 158, 182},
    /* +16 */ {97, 84, 75, 121, 125, 133, 130, 144, 139, 126, 98, 84, 104, 89, 101, 95, 93, 99, 105, 100, 112, 125, 0, 0, 0, 99, 111, 111, 131, 114, 145, 174, 141, 172, 121, 168},
    /* +20 */ {85, 68, 71, 102, 104, 102, 99, 114, 95, 91, 83, 74, 86, 90, 92, 79, 97, 87, 89, 92, 100, 0, 0, 0, 0, 86, 87, 93, 90, 95, 93, 117, 122, 125, 113, 146},
    /* +24 */ {92, 72, 68, 85, 86, 90, 84, 85, 80, 86, 73, 75, 79, 73, 70, 72, 75, 81, 77, 81, 0, 0, 0, 0, 0, 80, 75, 73, 82, 84, 80, 95, 95, 99, 87, 106},
    /* +30 */ {68, 63, 71, 66, 63, 67, 74, 72, 61, 66, 73, 61, 57, 61, 60, 58, 61, 56, 62, 0, 0, 0, 0, 0, 0, 61, 72, 61, 64, 64, 62, 67, 74, 80, 73, 76},
    /* +40 */ {47, 56, 50, 53, 50, 44, 52, 48, 41, 49, 47, 44, 44, 41, 51, 41, 44, 51, 51, 0, 0, 0, 0, 0, 65, 53, 56, 51, 49, 51, 47, 57, 52, 48, 47, 48},
    /* +50 */ {44, 43, 44, 32, 41, 38, 39, 39, 35, 27, 40, 39, 33, 37, 37, 45, 37, 44, 0, 0, 0, 0, 0, 72, 63, 53, 45, 46, 44, 41, 42, 50, 64, 46, 46, 42},
    /* +60 */ {37, 38, 36, 30, 32, 33, 33, 30, 36, 39, 40, 34, 34, 35, 33, 31, 32, 40, 45, 42, 45, 49, 57, 53, 52, 53, 55, 39, 42, 39, 32, 38, 35, 34, 38, 37},
    /* +70 */ {36, 40, 32, 31, 33, 27, 29, 30, 33, 31, 30, 28, 24, 27, 28, 30, 35, 35, 35, 36, 36, 36, 40, 42, 42, 45, 43, 35, 36, 40, 35, 35, 30, 32, 32, 33},
    /* +80 */ {29, 27, 29, 30, 28, 27, 27, 30, 31, 32, 35, 31, 28, 29, 30, 29, 28, 29, 31, 30, 29, 29, 31, 32, 31, 31, 30, 30, 30, 31, 33, 29, 25, 25, 29, 31}
};

/* One S10_sun: a star of the Sun's spectrum and V = 10 per square degree,
 * as sunlight over the whole spectrum: TSI 10^(-0.4 (10 - V_sun)) per
 * (pi/180)^2 sr, TSI 1361 W/m^2, V_sun -26.74. */
static double unit_w_m2_sr(void)
{
    return 1361.0 * pow(10.0, -0.4 * (10.0 + 26.74)) / (DEG * DEG);
}

static double isl(double l_deg, double b_deg)
{
    return (double)oi_starlight_radiance((oi_real)(l_deg * DEG), (oi_real)(b_deg * DEG));
}

/* Every mapped node, also at l + 360 and l - 360 deg. */
static void test_table_nodes(void **state)
{
    const double unit = unit_w_m2_sr();
    int i, j, n = 0;
    char what[64];
    (void)state;
    for (i = 0; i < 25; i++) {
        for (j = 0; j < 36; j++) {
            if (TABLE35[i][j] == 0) continue;
            snprintf(what, sizeof what, "l %d b %g", 10 * j, LAT[i]);
            check_rel(TABLE35[i][j] * unit, isl(10.0 * j, LAT[i]), REL_TOL, what);
            check_rel(TABLE35[i][j] * unit, isl(10.0 * j + 360.0, LAT[i]), REL_TOL * 10, what);
            check_rel(TABLE35[i][j] * unit, isl(10.0 * j - 360.0, LAT[i]), REL_TOL * 10, what);
            n++;
        }
    }
    check_int(900 - 28, n, "mapped nodes");
    /* the unit against its value in docs/camera.md */
    check_rel(8.9971174530390225e-09, unit, 1e-13, "S10_sun in W/m^2/sr (pow of 10^-14.7)");
}

/* The 28 unmapped cells: the linear interpolation in longitude between the
 * nearest mapped cells of their row, rounded to the nearest unit. */
static void test_unmapped_cells(void **state)
{
    const double unit = unit_w_m2_sr();
    int i, j, n = 0;
    (void)state;
    for (i = 0; i < 25; i++) {
        for (j = 0; j < 36; j++) {
            int a = j, b = j;
            double t, want;
            if (TABLE35[i][j] != 0) continue;
            while (TABLE35[i][a] == 0) a--;
            while (TABLE35[i][b] == 0) b++;
            t = (double)(j - a) / (double)(b - a);
            want = floor(TABLE35[i][a] + t * (TABLE35[i][b] - TABLE35[i][a]) + 0.5);
            check_rel(want * unit, isl(10.0 * j, LAT[i]), REL_TOL, "unmapped cell");
            n++;
        }
    }
    check_int(28, n, "unmapped cells");
}

/* Between nodes: bilinear, so the centre of every cell is the mean of its
 * corners (the cell from 350 deg to 360 deg included); a point a quarter
 * into a cell along one axis is linear. */
static void test_between_nodes(void **state)
{
    const double unit = unit_w_m2_sr();
    int i, j;
    (void)state;
    for (i = 0; i + 1 < 25; i++) {
        for (j = 0; j < 36; j++) {
            const int j1 = (j + 1) % 36;
            double c[4], lm = 10.0 * j + 5.0, bm = 0.5 * (LAT[i] + LAT[i + 1]);
            if (TABLE35[i][j] == 0 || TABLE35[i][j1] == 0 || TABLE35[i + 1][j] == 0 ||
                TABLE35[i + 1][j1] == 0)
                continue;
            c[0] = TABLE35[i][j];
            c[1] = TABLE35[i][j1];
            c[2] = TABLE35[i + 1][j];
            c[3] = TABLE35[i + 1][j1];
            check_rel(0.25 * (c[0] + c[1] + c[2] + c[3]) * unit, isl(lm, bm), REL_TOL * 10,
                      "cell centre");
            check_rel((0.75 * c[0] + 0.25 * c[1]) * unit, isl(10.0 * j + 2.5, LAT[i]),
                      REL_TOL * 10, "along l");
            check_rel((0.75 * c[0] + 0.25 * c[2]) * unit,
                      isl(10.0 * j, LAT[i] + 0.25 * (LAT[i + 1] - LAT[i])), REL_TOL * 10,
                      "along b");
        }
    }
}

/* Beyond |b| = 80 deg: linear to the mean of the 80 deg row at the pole,
 * where every longitude gives the same value. */
static void test_poles(void **state)
{
    const double unit = unit_w_m2_sr();
    double mean_n = 0, mean_s = 0;
    int j;
    (void)state;
    for (j = 0; j < 36; j++) {
        mean_n += TABLE35[24][j] / 36.0;
        mean_s += TABLE35[0][j] / 36.0;
    }
    for (j = 0; j < 36; j++) {
        check_rel(mean_n * unit, isl(10.0 * j + 3.0, 90.0), REL_TOL * 10, "north pole");
        check_rel(mean_s * unit, isl(10.0 * j + 3.0, -90.0), REL_TOL * 10, "south pole");
        check_rel(0.5 * (TABLE35[24][j] + mean_n) * unit, isl(10.0 * j, 85.0), REL_TOL * 10,
                  "b 85");
    }
    check_rel(mean_n * unit, isl(0, 120.0), REL_TOL * 10, "b beyond 90 clamped");
}

/* Galactic axes in ICRS from the Hipparcos definition: the north galactic
 * pole at RA 192.85948, Dec 27.12825 deg; the ascending node of the plane
 * on the equator (RA of the pole + 90 deg) at l = 32.93192 deg. */
static void gal_to_icrs(double l, double b, oi_real v[3])
{
    const double ag = 192.85948 * DEG, dg = 27.12825 * DEG, lo = 32.93192 * DEG;
    const double z[3] = {cos(dg) * cos(ag), cos(dg) * sin(ag), sin(dg)};
    const double nd[3] = {cos(ag + PI / 2), sin(ag + PI / 2), 0};
    double m[3], p[3];
    int k;
    m[0] = z[1] * nd[2] - z[2] * nd[1];
    m[1] = z[2] * nd[0] - z[0] * nd[2];
    m[2] = z[0] * nd[1] - z[1] * nd[0];
    for (k = 0; k < 3; k++)
        p[k] = cos(b) * (nd[k] * cos(l - lo) + m[k] * sin(l - lo)) + sin(b) * z[k];
    set3(v, p[0], p[1], p[2]);
}

static double ang_diff(double a, double b)
{
    double d = fmod(a - b, 2 * PI);
    if (d > PI) d -= 2 * PI;
    if (d < -PI) d += 2 * PI;
    return fabs(d);
}

static void test_galactic_frame(void **state)
{
    oi_real v[3], l, b;
    uint64_t seed = 14;
    int k;
    (void)state;
    /* the pole, the node and the celestial pole (l = 90 + 32.93192 deg) */
    set3(v, cos(27.12825 * DEG) * cos(192.85948 * DEG), cos(27.12825 * DEG) * sin(192.85948 * DEG),
         sin(27.12825 * DEG));
    check_int(OI_OK, oi_galactic_from_icrs(v, &l, &b), "pole status");
    check_close(PI / 2, (double)b, 10 * ANG_TOL + 1e-9, 0, "pole b");
    set3(v, cos(282.85948 * DEG), sin(282.85948 * DEG), 0);
    check_int(OI_OK, oi_galactic_from_icrs(v, &l, &b), "node status");
    check_close(32.93192 * DEG, (double)l, ANG_TOL + 1e-9, 0, "node l");
    check_close(0, (double)b, ANG_TOL + 1e-9, 0, "node b");
    set3(v, 0, 0, 7.0);
    check_int(OI_OK, oi_galactic_from_icrs(v, &l, &b), "NCP status");
    check_close(122.93192 * DEG, (double)l, ANG_TOL + 1e-9, 0, "NCP l");
    check_close(27.12825 * DEG, (double)b, ANG_TOL + 1e-9, 0, "NCP b");
    /* random directions, both ways, any length */
    for (k = 0; k < 2000; k++) {
        double lw = 2 * PI * lcg01(&seed), bw = asin(2 * lcg01(&seed) - 1);
        double s = pow(10.0, 12 * lcg01(&seed) - 6);
        gal_to_icrs(lw, bw, v);
        v[0] *= (oi_real)s;
        v[1] *= (oi_real)s;
        v[2] *= (oi_real)s;
        check_int(OI_OK, oi_galactic_from_icrs(v, &l, &b), "status");
        assert_true(l >= 0 && l < 2 * PI);
        check_close(bw, (double)b, 10 * ANG_TOL + 1e-9, 0, "b");
        if (fabs(bw) < 1.5) check_close(0, ang_diff(lw, (double)l), 40 * ANG_TOL + 1e-9, 0, "l");
    }
}

/* Hostile inputs: NULL, NaN, inf, zero vector, outputs zeroed; the radiance
 * of a non-finite angle is 0, of a huge finite one a table value. */
static void test_hostile(void **state)
{
    oi_real v[3], l = 1, b = 1;
    double r;
    (void)state;
    set3(v, 1, 0, 0);
    check_int(OI_ERR_NULL, oi_galactic_from_icrs(NULL, &l, &b), "NULL dir");
    check_rel(0.0, (double)l, 0, "l zeroed");
    check_int(OI_ERR_NULL, oi_galactic_from_icrs(v, NULL, &b), "NULL l");
    check_int(OI_ERR_NULL, oi_galactic_from_icrs(v, &l, NULL), "NULL b");
    l = b = 1;
    set3(v, 1, NAN, 0);
    check_int(OI_ERR_NONFINITE, oi_galactic_from_icrs(v, &l, &b), "NaN");
    check_rel(0.0, (double)l + (double)b, 0, "zeroed");
    set3(v, INFINITY, 0, 0);
    check_int(OI_ERR_NONFINITE, oi_galactic_from_icrs(v, &l, &b), "inf");
    set3(v, 0, 0, 0);
    check_int(OI_ERR_ZERO_VECTOR, oi_galactic_from_icrs(v, &l, &b), "zero");
    set3(v, 1e-30, 0, 0);
    check_int(OI_OK, oi_galactic_from_icrs(v, &l, &b), "tiny");
    set3(v, 3e38, -3e38, 3e38);
    check_int(OI_OK, oi_galactic_from_icrs(v, &l, &b), "huge");
    check_rel(0.0, (double)oi_starlight_radiance((oi_real)NAN, 0), 0, "NaN l");
    check_rel(0.0, (double)oi_starlight_radiance(0, (oi_real)INFINITY), 0, "inf b");
    check_rel(0.0, (double)oi_starlight_radiance((oi_real)-INFINITY, 0), 0, "-inf l");
    r = (double)oi_starlight_radiance((oi_real)1e30, (oi_real)-1e30);
    assert_true(r >= 24 * unit_w_m2_sr() * (1 - 1e-5) && r <= 634 * unit_w_m2_sr() * (1 + 1e-5));
    r = (double)oi_starlight_radiance((oi_real)-1e-30, 0); /* l just below 360 */
    check_rel(290 * unit_w_m2_sr(), r, 1e-5, "l -0");
}

#ifndef OI_NO_EXPOSURE
static oi_camera sky_camera(void)
{
    oi_camera c = oi_test_camera("starlight");
    return c;
}

/* A GEO observer looking away from the Earth along the ICRS direction of
 * galactic (l, b); the Sun at ICRS (AU, 0, 0). */
static double scene_radiance(double l, double b, unsigned sky, oi_exposure *out)
{
    oi_camera c = sky_camera();
    oi_illum il = oi_test_lit_illum(1e-16);
    oi_real dir[3], sun[3], observer[3], target[3];
    set3(sun, 149597870.7, 0, 0);
    gal_to_icrs(l, b, dir);
    set3(observer, 42164.0 * (double)dir[0], 42164.0 * (double)dir[1], 42164.0 * (double)dir[2]);
    set3(target, observer[0] + 100.0 * (double)dir[0], observer[1] + 100.0 * (double)dir[1],
         observer[2] + 100.0 * (double)dir[2]);
    return oi_test_sky_background(&c, &il, sky, sun, observer, target, out);
}

/* The background: the table at the boresight's galactic coordinates (the
 * plane towards the centre, the LMC's cell, the north galactic pole);
 * added to the zodiacal light; not through the Earth; sky 0 is black. */
static void test_in_scene(void **state)
{
    const double unit = unit_w_m2_sr();
    const double tol = 2e-4; /* the geometry's rounding in single precision */
    double z, both;
    oi_exposure out;
    (void)state;
    check_rel(290 * unit, scene_radiance(0, 0, OI_SKY_STARLIGHT, &out), tol, "l 0 b 0");
    check_rel(213 * unit, scene_radiance(280 * DEG, -30 * DEG, OI_SKY_STARLIGHT, &out), tol,
              "LMC cell");
    check_rel(634 * unit, scene_radiance(290 * DEG, 0, OI_SKY_STARLIGHT, &out), tol, "l 290");
    check_rel(0.0, scene_radiance(0, 0, 0u, &out), 0, "no sky");
    z = scene_radiance(200 * DEG, 45 * DEG, OI_SKY_ZODIACAL, &out);
    both = scene_radiance(200 * DEG, 45 * DEG, OI_SKY_ZODIACAL | OI_SKY_STARLIGHT, &out);
    check_rel(z + isl(200.0, 45.0), both, tol, "zodiacal + starlight");
    assert_true(z > 0);
    /* 1 m^2, (1e-5 rad)^2, 1e19 electrons per joule: 1e9 e-/s per W/m^2/sr */
    check_rel((double)out.background_w_m2_sr * 1e9 * (double)out.exposure_s,
              (double)out.background_e, 1e-4, "background electrons");
}

/* Looking down at the night side: the ray ends on the Earth, no starlight. */
static void test_not_through_earth(void **state)
{
    oi_camera c = sky_camera();
    oi_illum il;
    oi_exposure out;
    (void)state;
    memset(&il, 0, sizeof il);
    il.flux_obs = (oi_real)1e-16;
    check_rel(0.0, oi_test_night_nadir(&c, &il, OI_SKY_STARLIGHT, &out), 0, "night Earth");
}
#endif /* OI_NO_EXPOSURE */
#endif /* OI_NO_SKY */

#if defined(OI_NO_SKY) && !defined(OI_NO_EXPOSURE)
/* Without the sky the starlight bit is unknown. */
static void test_no_sky_bit(void **state)
{
    oi_camera c = oi_test_camera("starlight");
    oi_expose_in in;
    oi_expose_goal goal;
    oi_exposure out;
    (void)state;
    memset(&goal, 0, sizeof goal);
    memset(&in, 0, sizeof in);
    in.flux_w_m2 = (oi_real)1e-12;
    goal.sky = 4u;
    check_int(OI_ERR_FLAGS, oi_expose(&c, &in, &goal, &out), "starlight bit without the sky");
    check_rel(0.0, out.exposure_s, 0, "zeroed");
}
#endif

int main(void)
{
#if !defined(OI_NO_SKY)
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table_nodes),
        cmocka_unit_test(test_unmapped_cells),
        cmocka_unit_test(test_between_nodes),
        cmocka_unit_test(test_poles),
        cmocka_unit_test(test_galactic_frame),
        cmocka_unit_test(test_hostile),
#ifndef OI_NO_EXPOSURE
        cmocka_unit_test(test_in_scene),
        cmocka_unit_test(test_not_through_earth),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
#elif !defined(OI_NO_EXPOSURE)
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_no_sky_bit)};
    return cmocka_run_group_tests(tests, NULL, NULL);
#else
    printf("skip test_starlight: built with OI_NO_SKY and OI_NO_EXPOSURE\n");
    return 0;
#endif
}
