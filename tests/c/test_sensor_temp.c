/* SPDX-License-Identifier: MIT */
/*
 * test_sensor_temp.c: the dark current at the sensor's temperature
 * (oi_expose_goal.has_sensor_temp, sensor_temp_c; the camera's
 * dark_ref_temp_c, dark_doubling_c, temp_min_c, temp_max_c; docs/camera.md,
 * "Sensor temperature"). The dark electrons against the doubling law
 * evaluated with powl (a different formula from the runtime's exp of
 * ln 2 times the doublings); no temperature and the reference temperature
 * equal to earlier versions bit for bit; the SNR falls as the sensor warms;
 * oi_expose_scene and the batch take it too; hostile temperatures and
 * camera fields get their documented statuses with zeroed outputs.
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

#ifdef OI_SINGLE_PRECISION
#define REL_TOL 4e-6
#else
#define REL_TOL 1e-13
#endif

#ifndef OI_NO_EXPOSURE

/* A one-setting camera (1 s, gain 1, read noise 5 e-) whose dark current is
 * the only background: background_e is the dark current at the temperature. */
static oi_camera camera_of(double dark, double ref, double doubling, double lo, double hi)
{
    oi_camera c = oi_test_camera("temp");
    c.aperture_m = (oi_real)0.1;
    c.dark_current_e_s = (oi_real)dark;
    c.dark_ref_temp_c = (oi_real)ref;
    c.dark_doubling_c = (oi_real)doubling;
    c.temp_min_c = (oi_real)lo;
    c.temp_max_c = (oi_real)hi;
    return c;
}

static oi_expose_goal goal_at(double t)
{
    oi_expose_goal g;
    memset(&g, 0, sizeof g);
    g.has_sensor_temp = 1u;
    g.sensor_temp_c = (oi_real)t;
    return g;
}

static void check_zeroed(const oi_exposure *e, const char *what)
{
    oi_exposure zero;
    memset(&zero, 0, sizeof zero);
    if (memcmp(e, &zero, sizeof zero) != 0) fail_msg("%s: output not zeroed", what);
}

static void test_doubling_law(void **state)
{
    uint64_t rng = 20261202u;
    int i;
    (void)state;
    for (i = 0; i < 2000; i++) {
        double dark = pow(10.0, -2 + 6 * lcg01(&rng));
        double doubling = 1 + 99 * lcg01(&rng);
        double ref = -100 + 200 * lcg01(&rng);
        double lo = ref - doubling * 30 * lcg01(&rng);
        double hi = ref + doubling * 30 * lcg01(&rng);
        oi_camera c;
        oi_expose_goal g;
        oi_expose_in in;
        oi_exposure out;
        long double want;
        double t;
        if (lo < -150) lo = -150;
        if (hi > 150) hi = 150;
        c = camera_of(dark, ref, doubling, lo, hi);
        t = (double)c.temp_min_c + ((double)c.temp_max_c - (double)c.temp_min_c) * lcg01(&rng);
        if (i == 0) t = (double)c.temp_min_c;
        if (i == 1) t = (double)c.temp_max_c;
        g = goal_at(t);
        memset(&in, 0, sizeof in);
        check_int(OI_OK, oi_expose(&c, &in, &g, &out), "status");
        want = (long double)c.dark_current_e_s *
               powl(2.0L, ((long double)g.sensor_temp_c - (long double)c.dark_ref_temp_c) /
                              (long double)c.dark_doubling_c);
        check_rel((double)want, (double)out.background_e, REL_TOL, "dark electrons");
    }
}

/* The star tracker's sensor: 125 e-/s at 25 C, about 8 times that 20 C warmer
 * (three doublings of 6.5 C: 2^(20/6.5) = 8.4). */
static void test_builtin_star_tracker(void **state)
{
    const oi_camera *c = oi_camera_find("star-tracker");
    oi_camera one;
    oi_expose_goal g = goal_at(45.0);
    oi_expose_in in;
    oi_exposure out;
    (void)state;
    one = *c;
    one.n_times = 1;
    one.times_s[0] = 1;
    one.n_gains = 1;
    memset(&in, 0, sizeof in);
    check_int(OI_OK, oi_expose(&one, &in, &g, &out), "status");
    check_rel(125.0 * pow(2.0, 20.0 / 6.5), (double)out.background_e, REL_TOL, "45 C");
    if (!(out.background_e > 8 * 125 && out.background_e < 9 * 125)) fail_msg("not ~8x");
}

/* No temperature (0 flag, NULL goal) and the reference temperature give the
 * electrons of earlier versions to the bit; a warmer sensor lowers the SNR. */
static void test_default_and_monotone(void **state)
{
    int k;
    (void)state;
    for (k = 0; oi_camera_builtin(k) != NULL; k++) {
        const oi_camera *c = oi_camera_builtin(k);
        oi_expose_in in;
        oi_expose_goal none, ref;
        oi_exposure a, b, r;
        double prev_snr = 1e300;
        double t;
        memset(&in, 0, sizeof in);
        in.flux_w_m2 = (oi_real)1e-15;
        in.background_w_m2_sr = (oi_real)1e-6;
        memset(&none, 0, sizeof none);
        none.sensor_temp_c = (oi_real)99; /* not read without the flag */
        ref = goal_at((double)c->dark_ref_temp_c);
        check_int(OI_OK, oi_expose(c, &in, NULL, &a), "NULL goal");
        check_int(OI_OK, oi_expose(c, &in, &none, &b), "flag 0");
        check_int(OI_OK, oi_expose(c, &in, &ref, &r), "reference");
        if (memcmp(&a, &b, sizeof a) != 0 || memcmp(&a, &r, sizeof a) != 0) {
            fail_msg("%s: not bit-identical", c->name);
        }
        for (t = (double)c->temp_min_c; t <= (double)c->temp_max_c; t += 5) {
            oi_expose_goal g = goal_at(t);
            oi_camera one = *c; /* one setting: the SNR at a fixed time */
            one.n_times = 1;
            one.times_s[0] = c->times_s[c->n_times - 1];
            one.n_gains = 1;
            check_int(OI_OK, oi_expose(&one, &in, &g, &a), "sweep");
            if (!((double)a.snr < prev_snr)) fail_msg("%s: SNR not falling at %g C", c->name, t);
            prev_snr = (double)a.snr;
        }
    }
}

/* oi_expose_scene and oi_expose_batch read the same goal field. */
static void test_scene_and_batch(void **state)
{
    const oi_camera *c = oi_camera_find("star-tracker");
    oi_scene sc;
    oi_illum il;
    oi_expose_goal g = goal_at(45.0), bad = goal_at(71.0);
    oi_exposure cold, warm, rows[2];
    oi_expose_in in[2];
    int st[2];
    (void)state;
    oi_scene_defaults(&sc);
    set3(sc.sun_km, 1.495978707e8, 0, 0);
    set3(sc.target_km, 0, 7000, 0);
    set3(sc.observer_km, 0, 7100, 0);
    sc.has_observer = 1;
    sc.terms = OI_TERM_SUN | OI_TERM_EARTH;
    check_int(OI_OK, oi_illuminate(&sc, NULL, &il) >= 0 ? OI_OK : -1, "illuminate");
    check_int(OI_OK, oi_expose_scene(c, &sc, &il, NULL, NULL, &cold), "scene");
    check_int(OI_OK, oi_expose_scene(c, &sc, &il, NULL, &g, &warm), "scene warm");
    if (!(warm.background_e > cold.background_e)) fail_msg("scene: no warmer dark");
    check_int(OI_ERR_INPUT, oi_expose_scene(c, &sc, &il, NULL, &bad, &warm), "scene 71 C");
    check_zeroed(&warm, "scene 71 C");
    memset(in, 0, sizeof in);
    check_int(OI_OK, oi_expose_batch(2, c, in, &g, rows, st), "batch");
    check_int(OI_OK, st[0], "batch row");
    check_rel(125.0 * pow(2.0, 20.0 / 6.5) * (double)rows[0].exposure_s,
              (double)rows[0].background_e, REL_TOL, "batch dark");
}

static void test_hostile_temperature(void **state)
{
    oi_camera c = camera_of(10, 20, 6, -40, 60);
    oi_camera plain = camera_of(10, 0, 0, 0, 0);
    const double nonfinite[] = {(double)NAN, (double)INFINITY, -(double)INFINITY};
    const double outside[] = {-40.001, 60.001, -1e30, 1e30};
    oi_expose_in in;
    oi_exposure out;
    oi_expose_goal g;
    size_t i;
    (void)state;
    memset(&in, 0, sizeof in);
    for (i = 0; i < sizeof nonfinite / sizeof nonfinite[0]; i++) {
        g = goal_at(nonfinite[i]);
        check_int(OI_ERR_NONFINITE, oi_expose(&c, &in, &g, &out), "non-finite");
        check_zeroed(&out, "non-finite");
    }
    for (i = 0; i < sizeof outside / sizeof outside[0]; i++) {
        g = goal_at(outside[i]);
        check_int(OI_ERR_INPUT, oi_expose(&c, &in, &g, &out), "outside the rated range");
        check_zeroed(&out, "outside");
    }
    g = goal_at(0);
    check_int(OI_ERR_INPUT, oi_expose(&plain, &in, &g, &out), "no temperature model");
    check_zeroed(&out, "no model");
    check_int(OI_OK, oi_expose(&plain, &in, NULL, &out), "no model, no temperature");
}

static void test_hostile_camera(void **state)
{
    /* dark, ref, doubling, min, max */
    const double bad[][5] = {
        {10, 20, 0.5, -40, 60},       /* doubling below 1 C */
        {10, 20, 101, -40, 60},       /* above 100 C */
        {10, 20, (double)NAN, -40, 60},
        {10, 20, -6, -40, 60},
        {10, 151, 6, -40, 60},        /* reference beyond 150 C */
        {10, 20, 6, -151, 60},
        {10, 20, 6, -40, 151},
        {10, 20, 6, 60, -40},         /* min above max */
        {10, 20, 6, -40, (double)NAN},
        {10, 20, 1, -40, 60},         /* 60 doublings below the reference */
        {10, 20, 2, -40, 81},         /* 30.5 doublings above it */
        {10, 20, 0, 0, 0},            /* no doubling but a reference */
        {10, 0, 0, -1, 0},
        {10, 0, 0, 0, 1},
    };
    oi_expose_in in;
    oi_exposure out;
    size_t i;
    (void)state;
    memset(&in, 0, sizeof in);
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        oi_camera c = camera_of(bad[i][0], bad[i][1], bad[i][2], bad[i][3], bad[i][4]);
        check_int(OI_ERR_CAMERA, oi_expose(&c, &in, NULL, &out), "camera temperature fields");
        check_zeroed(&out, "camera");
    }
    {
        /* exactly 30 doublings either side is valid */
        oi_camera c = camera_of(10, 0, 2, -60, 60);
        oi_expose_goal g = goal_at(60);
        check_int(OI_OK, oi_expose(&c, &in, &g, &out), "30 doublings");
        check_rel(10.0 * pow(2.0, 30.0), (double)out.background_e, REL_TOL, "2^30");
    }
}
#endif

int main(void)
{
#ifndef OI_NO_EXPOSURE
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_doubling_law),
        cmocka_unit_test(test_builtin_star_tracker),
        cmocka_unit_test(test_default_and_monotone),
        cmocka_unit_test(test_scene_and_batch),
        cmocka_unit_test(test_hostile_temperature),
        cmocka_unit_test(test_hostile_camera),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
#else
    printf("skip test_sensor_temp: built with OI_NO_EXPOSURE\n");
    return 0;
#endif
}
