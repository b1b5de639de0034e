/* SPDX-License-Identifier: MIT */
/* test_albedo.c: the albedo models of oi_illuminate (oi_model.albedo_model):
 * a map of one value is the uniform model bit for bit, the Knocke field's
 * weighted mean against closed forms (a small cap: the sub-target value; a
 * far target above the pole: the moments of z^2 dz), continuity across the
 * cap's lit edge and the terminator, the direction's tilt, and hostile
 * inputs with their documented statuses and zeroed outputs. The quadrature
 * references are in tests/python/test_albedo_models.py. */
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

#define R_E 6378.137
#define SUN_KM 1.496e8
#define J2000 2451545.0
#define KNOCKE_T0 2444960.5

/* computed: OK, or the table-range warning of a build without the
 * earthshine table (the Lambert far field; the albedo's mean is the same) */
#define check_ok(st, what) check_int(1, (st) == OI_OK || (st) == OI_WARN_TABLE_RANGE, what)

#ifndef OI_NO_ALBEDO_MODELS

/* Sun in the x-z plane at latitude sun_lat; target at angle theta from it
 * towards +z's side turned by spin about the Sun's direction, altitude h. */
static void scene_at(oi_scene *s, double sun_lat, double theta, double spin, double h)
{
    const double sx = cos(sun_lat), sz = sin(sun_lat);
    const double ax = -sz, az = sx; /* normal to the Sun in the x-z plane */
    /* k = cos(spin) a + sin(spin) (s x a); s x a = (0, -1, 0) here */
    const double kx = cos(spin) * ax, ky = -sin(spin), kz = cos(spin) * az;
    const double r = R_E + h;
    oi_scene_defaults(s);
    s->terms = OI_TERM_SUN | OI_TERM_EARTH;
    set3(s->sun_km, sx * SUN_KM, 0.0, sz * SUN_KM);
    set3(s->target_km, r * (cos(theta) * sx + sin(theta) * kx), r * sin(theta) * ky,
         r * (cos(theta) * sz + sin(theta) * kz));
    s->epoch_jd = (oi_real)J2000;
}

static void add_observer(oi_scene *s)
{
    s->has_observer = 1;
    set3(s->observer_km, (double)s->target_km[0] + 300.0, (double)s->target_km[1] - 800.0,
         (double)s->target_km[2] + 500.0);
}

static void check_zeroed(const oi_illum *out, const char *what)
{
    oi_illum zero;
    memset(&zero, 0, sizeof zero);
    if (memcmp(&zero, out, sizeof zero) != 0) {
        print_error("%s: outputs not zeroed\n", what);
        fail();
    }
}

/* a map holding one value everywhere gives the uniform model, bit for bit */
static void test_one_value_map_is_uniform(void **state)
{
    static const float map[3 * 5] = {0.3125f, 0.3125f, 0.3125f, 0.3125f, 0.3125f,
                                     0.3125f, 0.3125f, 0.3125f, 0.3125f, 0.3125f,
                                     0.3125f, 0.3125f, 0.3125f, 0.3125f, 0.3125f};
    const double thetas[] = {0.0, 0.7, 1.4, 1.5708, 1.75, 2.5};
    const double heights[] = {0.5, 400.0, 36000.0, 384400.0};
    oi_model m, u;
    unsigned i, j;
    (void)state;
    memset(&m, 0, sizeof m);
    memset(&u, 0, sizeof u);
    m.albedo_model = OI_ALBEDO_MAP;
    m.albedo_map = map;
    m.albedo_map_n_lat = 3;
    m.albedo_map_n_lon = 5;
    for (i = 0; i < sizeof thetas / sizeof thetas[0]; i++)
        for (j = 0; j < sizeof heights / sizeof heights[0]; j++) {
            oi_scene s;
            oi_illum a, b;
            scene_at(&s, 0.3, thetas[i], 0.4, heights[j]);
            add_observer(&s);
            s.earth_albedo = (oi_real)0.3125;
            s.earth_rotation_rad = (oi_real)2.0;
            check_int(oi_illuminate(&s, &u, &a), oi_illuminate(&s, &m, &b), "status");
            if (memcmp(&a, &b, sizeof a) != 0) {
                print_error("theta %g h %g: one-value map differs from uniform "
                            "(e_earth %.17g vs %.17g)\n",
                            thetas[i], heights[j], (double)b.e_earth, (double)a.e_earth);
                fail();
            }
        }
}

/* Knocke's a(phi, t) written out from Knocke, Ries & Tapley 1988 */
static double knocke(double sin_lat, double jd)
{
    const double a1 = 0.10 * cos(2.0 * 3.14159265358979323846 * (jd - KNOCKE_T0) / 365.25);
    return 0.34 + a1 * sin_lat + 0.29 * 0.5 * (3.0 * sin_lat * sin_lat - 1.0);
}

/* a 10 m high target sees a cap 0.1 degree wide: the mean is the value
 * under it (to a2 w^2 ~ 1e-6) */
static void test_knocke_small_cap(void **state)
{
    const double jds[] = {KNOCKE_T0, KNOCKE_T0 + 365.25 / 2.0, J2000 + 100.0};
    const double lats[] = {-1.2, -0.5, 0.0, 0.5236, 1.3};
    oi_model m;
    unsigned i, j;
    (void)state;
    memset(&m, 0, sizeof m);
    m.albedo_model = OI_ALBEDO_KNOCKE;
    for (i = 0; i < sizeof jds / sizeof jds[0]; i++)
        for (j = 0; j < sizeof lats / sizeof lats[0]; j++) {
            oi_scene s;
            oi_illum out;
            /* the Sun over the target's latitude plus 0.3 rad */
            scene_at(&s, lats[j] + 0.3, 0.3, 0.0, 0.01);
            s.epoch_jd = (oi_real)jds[i];
            check_ok(oi_illuminate(&s, &m, &out), "status");
            check_close(knocke((double)s.target_km[2] / (R_E + 0.01), jds[i]),
                        (double)out.earth_albedo_eff, 2e-5, 0.0, "small-cap mean albedo");
        }
}

/* A far target above the north pole with the Sun behind it: the weights
 * cos(i) cos(e) dA -> z^2 dz (z = sin latitude), so the mean is
 * a0 + 3/4 a1 + 2/5 a2 (to the cap's R/r) */
static void test_knocke_far_pole(void **state)
{
    const double h = 1.0e8;
    oi_model m;
    oi_scene s;
    oi_illum out;
    double a1 = 0.10 * cos(2.0 * 3.14159265358979323846 * (J2000 + 10.0 - KNOCKE_T0) / 365.25);
    (void)state;
    memset(&m, 0, sizeof m);
    m.albedo_model = OI_ALBEDO_KNOCKE;
    scene_at(&s, 1.5707963267948966, 0.0, 0.0, h);
    s.epoch_jd = (oi_real)(J2000 + 10.0);
    check_ok(oi_illuminate(&s, &m, &out), "status");
    check_close(0.34 + 0.75 * a1 + 0.4 * 0.29, (double)out.earth_albedo_eff, 1e-5, 0.0,
                "far polar mean albedo");
}

/* brighter towards the north (a1 > 0 at t0): the light comes from further
 * north than the uniform sphere's */
static void test_knocke_direction_tilts(void **state)
{
    oi_model m, u;
    oi_scene s;
    oi_illum a, b;
    (void)state;
    memset(&m, 0, sizeof m);
    memset(&u, 0, sizeof u);
    m.albedo_model = OI_ALBEDO_KNOCKE;
    scene_at(&s, 0.0, 0.0, 0.0, 5000.0);
    s.epoch_jd = (oi_real)KNOCKE_T0;
    check_ok(oi_illuminate(&s, &u, &a), "uniform");
    check_ok(oi_illuminate(&s, &m, &b), "knocke");
    if (!(b.dir_earth[2] > a.dir_earth[2] + (oi_real)1e-3)) {
        print_error("dir_earth z: knocke %g, uniform %g\n", (double)b.dir_earth[2],
                    (double)a.dir_earth[2]);
        fail();
    }
    check_close(1.0, (double)oi_angle(b.dir_earth, b.dir_earth) + 1.0, 1e-6, 0.0, "unit");
}

/* continuity: across the cap's lit edge (theta = pi/2 - w, where the
 * cubature changes its azimuth rule) and towards the far edge of the
 * terminator (theta -> pi/2 + w, e_earth -> 0) */
static void test_continuity(void **state)
{
    static const float map[4 * 8] = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f, 0.7f, 0.8f,
                                     0.8f, 0.7f, 0.6f, 0.5f, 0.4f, 0.3f, 0.2f, 0.1f,
                                     0.3f, 0.3f, 0.6f, 0.6f, 0.3f, 0.3f, 0.6f, 0.6f,
                                     0.9f, 0.1f, 0.9f, 0.1f, 0.9f, 0.1f, 0.9f, 0.1f};
    const double heights[] = {50.0, 800.0, 20000.0};
    const int models[] = {OI_ALBEDO_KNOCKE, OI_ALBEDO_MAP};
#ifdef OI_SINGLE_PRECISION
    const double eps = 1e-4, tol = 3e-3; /* theta moves by 2e-4: e_earth by ~tan(theta) 2e-4 */
#else
    const double eps = 1e-7, tol = 1e-4; /* the two azimuth rules differ by their error */
#endif
    unsigned i, k;
    (void)state;
    for (k = 0; k < 2; k++)
        for (i = 0; i < sizeof heights / sizeof heights[0]; i++) {
            oi_model m;
            oi_scene s;
            oi_illum lo, hi;
            const double w = acos(R_E / (R_E + heights[i]));
            double th, prev = 1e300;
            memset(&m, 0, sizeof m);
            m.albedo_model = models[k];
            m.albedo_map = map;
            m.albedo_map_n_lat = 4;
            m.albedo_map_n_lon = 8;
            scene_at(&s, 0.2, 0.5 * 3.14159265358979323846 - w - eps, 0.9, heights[i]);
            check_ok(oi_illuminate(&s, &m, &lo), "inside");
            scene_at(&s, 0.2, 0.5 * 3.14159265358979323846 - w + eps, 0.9, heights[i]);
            check_ok(oi_illuminate(&s, &m, &hi), "outside");
            check_close((double)lo.e_earth / (double)lo.earth_albedo_eff, (double)hi.e_earth / (double)hi.earth_albedo_eff, 0.0, tol, "lit edge e_earth per unit mean albedo (the uniform table)");
            printf("lit edge h %g model %d: mean albedo jumps by %.2e relative\n", heights[i],
                   models[k], fabs((double)hi.earth_albedo_eff / (double)lo.earth_albedo_eff - 1.0));
            check_close((double)lo.earth_albedo_eff, (double)hi.earth_albedo_eff, 0.0, tol,
                        "lit edge mean albedo");
            /* across the terminator to the far edge: the mean albedo moves
             * by small steps (no jump where the lit region shrinks to a
             * sliver), e_earth falls to the uniform table's floor (its
             * absolute error, 1e-5 of the sub-solar value) */
            prev = (double)lo.earth_albedo_eff;
            for (th = 0.5 * 3.14159265358979323846 - w;
                 th < 0.5 * 3.14159265358979323846 + w; th += 0.02 * w) {
                oi_illum out;
                scene_at(&s, 0.2, th, 0.9, heights[i]);
                check_int(1, oi_illuminate(&s, &m, &out) >= 0, "terminator");
                if (!(fabs((double)out.earth_albedo_eff - prev) < 0.03)) {
                    print_error("h %g theta %g: mean albedo jumps from %g to %g\n", heights[i],
                                th, prev, (double)out.earth_albedo_eff);
                    fail();
                }
                prev = (double)out.earth_albedo_eff;
#ifndef OI_NO_EARTH_TABLE
                /* (without the table the Lambert far field does not vanish there) */
                if (th > 0.5 * 3.14159265358979323846 + 0.98 * w &&
                    !((double)out.e_earth < 2e-5 * (double)lo.e_earth / cos(0.5 * 3.14159265358979323846 - w)))
                    print_error("h %g theta %g: e_earth %g near the far edge\n", heights[i], th,
                                (double)out.e_earth), fail();
#endif
            }
        }
}

static int run(const oi_model *m, const oi_scene *s, oi_illum *out)
{
    int st;
    memset(out, 0x5a, sizeof *out); /* every output must be written */
    st = oi_illuminate(s, m, out);
    if (st < 0) check_zeroed(out, oi_status_name(st));
    return st;
}

static void test_hostile_inputs(void **state)
{
    float map[2 * 4] = {0.2f, 0.2f, 0.2f, 0.2f, 0.2f, 0.2f, 0.2f, 0.2f};
    const float bad[] = {1.5f, -0.1f, 1.0000001f, 0.0f};
    oi_model m;
    oi_scene s;
    oi_illum out;
    unsigned i;
    (void)state;
    memset(&m, 0, sizeof m);
    m.albedo_model = OI_ALBEDO_MAP;
    m.albedo_map = map;
    m.albedo_map_n_lat = 2;
    m.albedo_map_n_lon = 4;
    scene_at(&s, 0.0, 0.2, 0.0, 3000.0);
    check_ok(run(&m, &s, &out), "good map");
    /* a cell the cubature reads: every cell of a 2 x 4 map from 3000 km */
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        map[5] = bad[i];
        if (bad[i] == 0.0f) map[5] = (float)NAN;
        check_int(OI_ERR_ALBEDO, run(&m, &s, &out), "bad map value");
    }
    map[5] = 0.2f;
    s.earth_rotation_rad = (oi_real)NAN;
    check_int(OI_ERR_NONFINITE, run(&m, &s, &out), "rotation NaN");
    s.earth_rotation_rad = (oi_real)INFINITY;
    check_int(OI_ERR_NONFINITE, run(&m, &s, &out), "rotation inf");
    s.earth_rotation_rad = (oi_real)(2.0 * OI_EARTH_ROTATION_MAX_RAD);
    check_int(OI_ERR_INPUT, run(&m, &s, &out), "rotation too large");
    s.earth_rotation_rad = (oi_real)-3.0;
    check_ok(run(&m, &s, &out), "negative rotation");
    /* the map's description */
    m.albedo_map = NULL;
    check_int(OI_ERR_MODEL, run(&m, &s, &out), "NULL map");
    m.albedo_map = map;
    m.albedo_map_n_lat = 0;
    check_int(OI_ERR_MODEL, run(&m, &s, &out), "no rows");
    m.albedo_map_n_lat = 2;
    m.albedo_map_n_lon = OI_ALBEDO_MAP_MAX_DIM + 1;
    check_int(OI_ERR_MODEL, run(&m, &s, &out), "too many columns");
    m.albedo_map_n_lon = -4;
    check_int(OI_ERR_MODEL, run(&m, &s, &out), "negative columns");
    m.albedo_map_n_lon = 4;
    m.albedo_model = 3;
    check_int(OI_ERR_MODEL, run(&m, &s, &out), "unknown model");
    m.albedo_model = -1;
    check_int(OI_ERR_MODEL, run(&m, &s, &out), "negative model");
    /* Knocke's epoch */
    m.albedo_model = OI_ALBEDO_KNOCKE;
    s.epoch_jd = (oi_real)NAN;
    check_int(OI_ERR_NONFINITE, run(&m, &s, &out), "epoch NaN");
    s.epoch_jd = (oi_real)(OI_EPOCH_JD_MIN - 1.0);
    check_int(OI_ERR_INPUT, run(&m, &s, &out), "epoch before range");
    s.epoch_jd = (oi_real)(OI_EPOCH_JD_MAX + 1.0);
    check_int(OI_ERR_INPUT, run(&m, &s, &out), "epoch after range");
    s.epoch_jd = (oi_real)0;
    check_int(OI_ERR_INPUT, run(&m, &s, &out), "epoch not given");
    /* not read without the Earth's term */
    s.terms = OI_TERM_SUN;
    s.epoch_jd = (oi_real)NAN;
    check_ok(run(&m, &s, &out), "epoch unread without the Earth");
    check_int(0, out.earth_albedo_eff != (oi_real)0, "no mean albedo without the Earth");
    /* the map does not read the epoch, Knocke not the rotation */
    s.terms = OI_TERM_SUN | OI_TERM_EARTH;
    s.epoch_jd = (oi_real)J2000;
    s.earth_rotation_rad = (oi_real)NAN;
    check_ok(run(&m, &s, &out), "knocke ignores the rotation");
    m.albedo_model = OI_ALBEDO_MAP;
    s.earth_rotation_rad = (oi_real)0;
    s.epoch_jd = (oi_real)NAN;
    check_ok(run(&m, &s, &out), "the map ignores the epoch");
}

/* the batch: each row the single call's, bit for bit; a bad albedo model is
 * the batch's error (every row's status) */
static void test_batch(void **state)
{
    static const float map[2 * 3] = {0.1f, 0.5f, 0.9f, 0.3f, 0.3f, 0.7f};
    oi_scene s[3];
    oi_illum out[3], one;
    int status[3], i;
    oi_model m;
    (void)state;
    memset(&m, 0, sizeof m);
    m.albedo_model = OI_ALBEDO_MAP;
    m.albedo_map = map;
    m.albedo_map_n_lat = 2;
    m.albedo_map_n_lon = 3;
    for (i = 0; i < 3; i++) {
        scene_at(&s[i], 0.3 * i, 0.4 + 0.5 * i, 0.2, 500.0 + 9000.0 * i);
        add_observer(&s[i]);
        s[i].earth_rotation_rad = (oi_real)(0.7 * i);
    }
    check_int(0, oi_illuminate_batch(3, s, &m, out, status), "batch");
    for (i = 0; i < 3; i++) {
        check_int(status[i], oi_illuminate(&s[i], &m, &one), "row status");
        if (memcmp(&one, &out[i], sizeof one) != 0) {
            print_error("row %d differs from the single call\n", i);
            fail();
        }
    }
    m.albedo_map_n_lon = 0;
    check_int(OI_ERR_MODEL, oi_illuminate_batch(3, s, &m, out, status), "bad map");
    check_int(OI_ERR_MODEL, status[2], "row status of a bad map");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_one_value_map_is_uniform),
        cmocka_unit_test(test_batch),
        cmocka_unit_test(test_knocke_small_cap),
        cmocka_unit_test(test_knocke_far_pole),
        cmocka_unit_test(test_knocke_direction_tilts),
        cmocka_unit_test(test_continuity),
        cmocka_unit_test(test_hostile_inputs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

#else /* OI_NO_ALBEDO_MODELS */

/* compiled out: every model but the uniform one is refused */
static void test_refused(void **state)
{
    oi_model m;
    oi_scene s;
    oi_illum out;
    (void)state;
    memset(&m, 0, sizeof m);
    oi_scene_defaults(&s);
    set3(s.sun_km, SUN_KM, 0.0, 0.0);
    set3(s.target_km, R_E + 500.0, 0.0, 0.0);
    s.terms = OI_TERM_SUN | OI_TERM_EARTH;
    check_ok(oi_illuminate(&s, &m, &out), "uniform");
    m.albedo_model = OI_ALBEDO_KNOCKE;
    s.epoch_jd = (oi_real)J2000;
    check_int(OI_ERR_MODEL, oi_illuminate(&s, &m, &out), "knocke compiled out");
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_refused)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
#endif
