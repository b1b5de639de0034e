/* SPDX-License-Identifier: MIT */
/* test_expose_batch.c: oi_expose_batch_outputs and
 * oi_expose_scene_batch_outputs against the single calls, bit for bit, in
 * the precision of the build: every outputs mask (each field asked for is
 * the single call's, each left out is 0, and the status is the single
 * call's), over random scenes (moving and at rest, observers beside the
 * target, the Sun at the exclusion angle's edge, sky backgrounds, cameras
 * with the detection rule and a sensor temperature); hostile rows get their
 * own statuses and leave the others computed; hostile arrays (NULL, n < 0,
 * n = 0, unknown mask bits, misaligned, overlapping, invalid camera or
 * model) get the documented batch status in every row. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "orbillum.h"
#include "oi_test_util.h"

#ifndef OI_NO_EXPOSURE

#define NROWS 3000
#define AU 149597870.7
#define RE 6378.137

static oi_scene scenes[NROWS];
static oi_illum illum[NROWS];
static oi_expose_in ins[NROWS];
static oi_exposure one[NROWS], bat[NROWS];
static int one_st[NROWS], bat_st[NROWS];

static int same_bits(oi_real a, oi_real b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* The field asked for is the single call's; the one left out is 0. */
static void expect_field(int asked, oi_real want, oi_real got, const char *what, long row,
                         unsigned mask)
{
    const oi_real w = asked ? want : (oi_real)0;
    if (!same_bits(w, got)) {
        print_error("%s row %ld mask %u: want %.17g got %.17g\n", what, row, mask, (double)w,
                    (double)got);
        fail();
    }
}

static void expect_int(int asked, long want, long got, const char *what, long row, unsigned mask)
{
    const long w = asked ? want : 0;
    if (w != got) {
        print_error("%s row %ld mask %u: want %ld got %ld\n", what, row, mask, w, got);
        fail();
    }
}

/* Row i of the masked batch against the single call. */
static void compare_row(long i, unsigned m, int scene_call)
{
    const oi_exposure *a = &one[i], *b = &bat[i];
    const int set = (m & OI_EXPOSE_SETTING) != 0u;
    unsigned want_flags = a->flags;
    if (one_st[i] != bat_st[i]) {
        print_error("status row %ld mask %u: single %d batch %d\n", i, m, one_st[i], bat_st[i]);
        fail();
    }
    if (one_st[i] < 0) {
        static const oi_exposure zero;
        if (memcmp(b, &zero, sizeof zero) != 0) {
            print_error("row %ld mask %u: an error row not zeroed\n", i, m);
            fail();
        }
        return;
    }
    if (!set) want_flags &= ~(OI_FLAG_SATURATED | OI_FLAG_BACKGROUND_SATURATED);
    if (!(m & OI_EXPOSE_FAINT)) want_flags &= ~OI_FLAG_TOO_FAINT;
    if (!(m & (OI_EXPOSE_SETTING | OI_EXPOSE_FAINT))) want_flags &= ~OI_FLAG_TRAILED;
    expect_int(1, (long)want_flags, (long)b->flags, "flags", i, m);
    expect_field(set, a->exposure_s, b->exposure_s, "exposure_s", i, m);
    expect_field(set, a->gain, b->gain, "gain", i, m);
    expect_int(set, a->time_index, b->time_index, "time_index", i, m);
    expect_int(set, a->gain_index, b->gain_index, "gain_index", i, m);
    expect_field(set, a->signal_e, b->signal_e, "signal_e", i, m);
    expect_field(set, a->background_e, b->background_e, "background_e", i, m);
    expect_field(set, a->peak_e, b->peak_e, "peak_e", i, m);
    expect_field(set, a->saturation_e, b->saturation_e, "saturation_e", i, m);
    expect_field(set, a->fill, b->fill, "fill", i, m);
    expect_field(set, a->snr, b->snr, "snr", i, m);
    expect_field(set, a->trail_px, b->trail_px, "trail_px", i, m);
    expect_field(set, a->trail_factor, b->trail_factor, "trail_factor", i, m);
    expect_field((m & OI_EXPOSE_DETECT) != 0u, a->signal_min_e, b->signal_min_e, "signal_min_e",
                 i, m);
    expect_field((m & OI_EXPOSE_DETECT) != 0u, a->detect_margin_mag, b->detect_margin_mag,
                 "detect_margin_mag", i, m);
    expect_field(scene_call && (m & OI_EXPOSE_SUN_ANGLE) != 0u, a->sun_angle_rad,
                 b->sun_angle_rad, "sun_angle_rad", i, m);
    expect_field((m & OI_EXPOSE_BACKGROUND) != 0u, a->background_w_m2_sr, b->background_w_m2_sr,
                 "background_w_m2_sr", i, m);
    expect_field((m & OI_EXPOSE_RATE) != 0u, a->rate_rad_s, b->rate_rad_s, "rate_rad_s", i, m);
}

/* A unit vector at angle ang from unit vector s. */
static void dir_at(uint64_t *rng, const double s[3], double ang, double u[3])
{
    double p[3], q[3], n;
    int k;
    random_unit(rng, p);
    q[0] = p[1] * s[2] - p[2] * s[1];
    q[1] = p[2] * s[0] - p[0] * s[2];
    q[2] = p[0] * s[1] - p[1] * s[0];
    n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    for (k = 0; k < 3; k++) u[k] = cos(ang) * s[k] + sin(ang) * q[k] / n;
}

/* n random scenes with their illumination: targets from LEO to GEO,
 * observers beside the target (Earth in the field, occultations) or in
 * their own orbits, a fifth of the boresights within 1e-3 .. 1e-17 of the
 * camera's Sun exclusion angle, half the rows moving. */
static void random_scenes(long n, uint64_t seed, double excl_rad)
{
    uint64_t rng = seed;
    long i;
    int k;
    for (i = 0; i < n; i++) {
        oi_scene *s = &scenes[i];
        double sd[3], t[3], o[3], b[3], md[3], v[3], w[3];
        double rt = RE + 300 + 36000 * lcg01(&rng), ro = RE + 400 + 36000 * lcg01(&rng);
        double range = 100 + 40000 * lcg01(&rng);
        oi_scene_defaults(s);
        random_unit(&rng, sd);
        random_unit(&rng, t);
        random_unit(&rng, md);
        set3(s->sun_km, AU * sd[0], AU * sd[1], AU * sd[2]);
        set3(s->moon_km, 384400 * md[0], 384400 * md[1], 384400 * md[2]);
        set3(s->target_km, rt * t[0], rt * t[1], rt * t[2]);
        if (i % 5 == 1) {
            /* the boresight at the exclusion angle's edge seen from the
             * observer, off by 10^-3 .. 10^-17 rad */
            double off = pow(10.0, -3 - 14 * lcg01(&rng)) * (lcg01(&rng) < 0.5 ? -1 : 1), so[3];
            double rs, rtt;
            random_unit(&rng, o);
            for (k = 0; k < 3; k++) o[k] *= ro;
            for (k = 0; k < 3; k++) so[k] = AU * sd[k] - o[k];
            rs = sqrt(so[0] * so[0] + so[1] * so[1] + so[2] * so[2]);
            for (k = 0; k < 3; k++) so[k] /= rs;
            dir_at(&rng, so, excl_rad + off, b);
            for (k = 0; k < 3; k++) t[k] = o[k] + range * b[k];
            rtt = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
            if (rtt < RE + 300)
                for (k = 0; k < 3; k++) t[k] = o[k] + 100 * b[k];
            set3(s->target_km, t[0], t[1], t[2]);
        } else if (i % 2) {
            random_unit(&rng, b);
            for (k = 0; k < 3; k++) o[k] = rt * t[k] + 500 * b[k];
        } else {
            random_unit(&rng, o);
            for (k = 0; k < 3; k++) o[k] *= ro;
        }
        set3(s->observer_km, o[0], o[1], o[2]);
        s->has_observer = i % 37 != 0;
        s->terms = (unsigned)(1 + i % OI_TERM_ALL);
#ifdef OI_NO_MOON
        s->terms &= ~OI_TERM_MOON;
#endif
        if (i % 2 == 0) {
            random_unit(&rng, v);
            random_unit(&rng, w);
            set3(s->target_vel_km_s, 7.5 * v[0], 7.5 * v[1], 7.5 * v[2]);
            set3(s->observer_vel_km_s, 3 * w[0], 3 * w[1], 3 * w[2]);
        }
        s->earth_albedo = (oi_real)(0.1 + 0.5 * lcg01(&rng));
        s->target_albedo = (oi_real)(0.05 + 0.9 * lcg01(&rng));
        s->target_radius_m = (oi_real)(0.1 + 50 * lcg01(&rng));
        (void)oi_illuminate(s, NULL, &illum[i]);
    }
}

/* Every mask over the scene rows with camera, model and goal. */
static void check_scene_masks(long n, const oi_camera *cam, const oi_model *model,
                              const oi_expose_goal *goal)
{
    unsigned m;
    long i;
    int want_bad = 0, bad;
    for (i = 0; i < n; i++) {
        one_st[i] = oi_expose_scene(cam, &scenes[i], &illum[i], model, goal, &one[i]);
        want_bad += one_st[i] < 0;
    }
    for (m = 0; m <= OI_EXPOSE_ALL; m++) {
        memset(bat, 0x5a, sizeof bat); /* garbage: every field must be written */
        bad = oi_expose_scene_batch_outputs(n, cam, scenes, illum, model, goal, m, bat, bat_st);
        check_int(want_bad, bad, "scene rows in error");
        for (i = 0; i < n; i++) compare_row(i, m, 1);
        if (m == OI_EXPOSE_ALL && memcmp(one, bat, (size_t)n * sizeof *one) != 0) {
            print_error("OI_EXPOSE_ALL: rows differ from the single call's bytes\n");
            fail();
        }
    }
}

/* A camera with the detection rule, a sensor temperature model and a trail
 * limit, from built-in camera 0. */
static oi_camera detect_camera(void)
{
    oi_camera c = *oi_camera_builtin(0);
    c.detect_false_alarm = (oi_real)1e-6;
    c.detect_probability = (oi_real)0.9;
    c.dark_ref_temp_c = 25;
    c.dark_doubling_c = 7;
    c.temp_min_c = -40;
    c.temp_max_c = 60;
    c.max_trail_px = 2;
    return c;
}

static void test_scene_masks(void **state)
{
    const oi_camera *c0 = oi_camera_builtin(0);
    oi_camera cd = detect_camera();
    oi_expose_goal sky;
#ifndef OI_NO_OBLATE
    oi_model wgs84;
#endif
    int k;
    (void)state;
    memset(&sky, 0, sizeof sky);
#ifndef OI_NO_SKY
    sky.sky |= OI_SKY_ZODIACAL | OI_SKY_STARLIGHT;
#endif
#ifndef OI_NO_MOON
    sky.sky |= OI_SKY_MOON;
#endif
    random_scenes(NROWS, 11, (double)c0->sun_exclusion_rad);
    check_scene_masks(NROWS, c0, NULL, NULL);
    check_scene_masks(NROWS, c0, NULL, &sky);
    sky.has_sensor_temp = 1;
    sky.sensor_temp_c = -10;
    sky.fill = (oi_real)0.3;
    check_scene_masks(NROWS, &cd, NULL, &sky);
    /* the goal's sensor temperature outside the camera's range: every row
     * checked before it keeps its own status */
    check_scene_masks(200, c0, NULL, &sky);
#ifndef OI_NO_OBLATE /* without the ellipsoid a WGS-84 model is refused */
    memset(&wgs84, 0, sizeof wgs84);
    wgs84.earth_shape = OI_EARTH_WGS84;
    check_scene_masks(600, &cd, &wgs84, NULL);
#endif
    /* every built-in camera */
    for (k = 1; oi_camera_builtin(k) != NULL; k++) {
        random_scenes(400, 100 + (uint64_t)k, (double)oi_camera_builtin(k)->sun_exclusion_rad);
        check_scene_masks(400, oi_camera_builtin(k), NULL, &sky);
    }
}

/* Rows of oi_expose_in: fluxes over 25 decades, backgrounds, flags, rates,
 * and hostile rows among them. */
static void random_ins(long n, uint64_t seed)
{
    uint64_t rng = seed;
    long i;
    for (i = 0; i < n; i++) {
        ins[i].flux_w_m2 = (oi_real)pow(10.0, -25 + 25 * lcg01(&rng));
        ins[i].background_w_m2_sr = (oi_real)(i % 3 ? 0.0 : 10 * lcg01(&rng));
        ins[i].flags = (unsigned)(i % 5 ? 0 : OI_FLAG_PENUMBRA | OI_FLAG_TOO_FAINT);
        ins[i].rate_rad_s = (oi_real)(i % 2 ? 0.0 : pow(10.0, -6 + 4 * lcg01(&rng)));
        if (i % 101 == 0) ins[i].flux_w_m2 = (oi_real)NAN;
        if (i % 103 == 0) ins[i].flags = 1u << 20;
        if (i % 107 == 0) ins[i].rate_rad_s = (oi_real)-1;
        if (i % 109 == 0) ins[i].background_w_m2_sr = (oi_real)INFINITY;
        if (i % 113 == 0) ins[i].flux_w_m2 = (oi_real)1e5;
    }
}

static void check_in_masks(long n, const oi_camera *cam, const oi_expose_goal *goal)
{
    unsigned m;
    long i;
    int want_bad = 0, bad;
    for (i = 0; i < n; i++) {
        one_st[i] = oi_expose(cam, &ins[i], goal, &one[i]);
        want_bad += one_st[i] < 0;
    }
    for (m = 0; m <= OI_EXPOSE_ALL; m++) {
        memset(bat, 0x5a, sizeof bat);
        bad = oi_expose_batch_outputs(n, cam, ins, goal, m, bat, bat_st);
        check_int(want_bad, bad, "rows in error");
        for (i = 0; i < n; i++) compare_row(i, m, 0);
        if (m == OI_EXPOSE_ALL && memcmp(one, bat, (size_t)n * sizeof *one) != 0) {
            print_error("OI_EXPOSE_ALL: rows differ from oi_expose's bytes\n");
            fail();
        }
    }
}

static void test_in_masks(void **state)
{
    oi_camera cd = detect_camera();
    oi_expose_goal goal = {OI_R(0.4), OI_R(7.0), 0u, 0u, 0};
    oi_expose_goal bad_goal = {OI_R(2.0), 0, 0u, 0u, 0};
    (void)state;
    random_ins(NROWS, 5);
    check_in_masks(NROWS, oi_camera_builtin(0), &goal);
    check_in_masks(NROWS, oi_camera_builtin(0), NULL);
    goal.has_sensor_temp = 1;
    goal.sensor_temp_c = 40;
    check_in_masks(NROWS, &cd, &goal);
    check_in_masks(300, oi_camera_builtin(0), &goal); /* no temperature model */
    check_in_masks(300, oi_camera_builtin(0), &bad_goal);
}

static void expect_all(int want, long n, const char *what)
{
    long i;
    for (i = 0; i < n; i++) check_int(want, bat_st[i], what);
}

static void expect_zeroed(long n, const char *what)
{
    static const oi_exposure zero;
    long i;
    for (i = 0; i < n; i++)
        if (memcmp(&bat[i], &zero, sizeof zero) != 0) {
            print_error("%s: row %ld not zeroed\n", what, i);
            fail();
        }
}

/* Hostile arrays: the documented batch status in every row. */
static void test_hostile_arrays(void **state)
{
    static unsigned char raw[sizeof(oi_exposure) * 9 + 16];
    const oi_camera *c0 = oi_camera_builtin(0);
    oi_camera bad_cam = *c0;
    oi_model bad_model;
    const long n = 8;
    const unsigned all = OI_EXPOSE_ALL;
    (void)state;
    random_scenes(n, 3, (double)c0->sun_exclusion_rad);
    random_ins(n, 3);
    /* n = 0: nothing, NULL allowed */
    check_int(0, oi_expose_batch_outputs(0, NULL, NULL, NULL, 0, NULL, NULL), "n = 0");
    check_int(0, oi_expose_scene_batch_outputs(0, NULL, NULL, NULL, NULL, NULL, 0, NULL, NULL),
              "n = 0 scene");
    /* n < 0 and n too big: nothing written */
    bat_st[0] = 12345;
    check_int(OI_ERR_INPUT, oi_expose_batch_outputs(-1, c0, ins, NULL, all, bat, bat_st), "n<0");
    check_int(OI_ERR_INPUT,
              oi_expose_scene_batch_outputs(-3, c0, scenes, illum, NULL, NULL, all, bat, bat_st),
              "n<0 scene");
    check_int(OI_ERR_INPUT,
              oi_expose_batch_outputs(OI_BATCH_MAX + 1, c0, ins, NULL, all, bat, bat_st), "n big");
    check_int(12345, bat_st[0], "status untouched");
    /* NULL arrays and camera */
    check_int(OI_ERR_NULL, oi_expose_batch_outputs(n, NULL, ins, NULL, all, bat, bat_st),
              "no camera");
    expect_all(OI_ERR_NULL, n, "no camera rows");
    check_int(OI_ERR_NULL, oi_expose_batch_outputs(n, c0, NULL, NULL, all, bat, bat_st), "no in");
    check_int(OI_ERR_NULL,
              oi_expose_scene_batch_outputs(n, c0, scenes, NULL, NULL, NULL, all, bat, bat_st),
              "no illum");
    expect_all(OI_ERR_NULL, n, "no illum rows");
    check_int(OI_ERR_NULL,
              oi_expose_scene_batch_outputs(n, c0, scenes, illum, NULL, NULL, all, NULL, bat_st),
              "no out");
    check_int(OI_ERR_NULL,
              oi_expose_scene_batch_outputs(n, c0, scenes, illum, NULL, NULL, all, bat, NULL),
              "no status");
    /* unknown mask bits: every row OI_ERR_FLAGS, outputs zeroed */
    memset(bat, 0x5a, sizeof bat);
    check_int(OI_ERR_FLAGS, oi_expose_batch_outputs(n, c0, ins, NULL, 64u, bat, bat_st), "mask");
    expect_all(OI_ERR_FLAGS, n, "mask rows");
    expect_zeroed(n, "mask rows");
    memset(bat, 0x5a, sizeof bat);
    check_int(OI_ERR_FLAGS,
              oi_expose_scene_batch_outputs(n, c0, scenes, illum, NULL, NULL, 1u << 31, bat,
                                            bat_st),
              "mask scene");
    expect_all(OI_ERR_FLAGS, n, "mask scene rows");
    expect_zeroed(n, "mask scene rows");
    /* invalid camera and model: every row its status, outputs zeroed; the
     * mask before them, the model before the camera */
    bad_cam.full_well_e = -1;
    memset(&bad_model, 0, sizeof bad_model);
    bad_model.tsi_w_m2 = (oi_real)-1;
    memset(bat, 0x5a, sizeof bat);
    check_int(OI_ERR_CAMERA, oi_expose_batch_outputs(n, &bad_cam, ins, NULL, all, bat, bat_st),
              "camera");
    expect_all(OI_ERR_CAMERA, n, "camera rows");
    expect_zeroed(n, "camera rows");
    check_int(OI_ERR_FLAGS, oi_expose_batch_outputs(n, &bad_cam, ins, NULL, 128u, bat, bat_st),
              "mask before camera");
    memset(bat, 0x5a, sizeof bat);
    check_int(OI_ERR_MODEL,
              oi_expose_scene_batch_outputs(n, &bad_cam, scenes, illum, &bad_model, NULL, all,
                                            bat, bat_st),
              "model before camera");
    expect_all(OI_ERR_MODEL, n, "model rows");
    expect_zeroed(n, "model rows");
    check_int(OI_ERR_CAMERA,
              oi_expose_scene_batch_outputs(n, &bad_cam, scenes, illum, NULL, NULL, all, bat,
                                            bat_st),
              "camera scene");
    expect_all(OI_ERR_CAMERA, n, "camera scene rows");
    /* overlap: out over the input, status over out, out over illum */
    check_int(OI_ERR_INPUT,
              oi_expose_batch_outputs(n, c0, ins, NULL, all, (oi_exposure *)(void *)ins, bat_st),
              "out over in");
    expect_all(OI_ERR_INPUT, n, "overlap rows");
    check_int(OI_ERR_INPUT,
              oi_expose_batch_outputs(n, c0, ins, NULL, all, bat, (int *)(void *)&bat[2]),
              "status over out");
    check_int(OI_ERR_INPUT,
              oi_expose_scene_batch_outputs(n, c0, scenes, illum, NULL, NULL, all,
                                            (oi_exposure *)(void *)illum, bat_st),
              "out over illum");
    /* misaligned output */
    check_int(OI_ERR_INPUT,
              oi_expose_batch_outputs(n, c0, ins, NULL, all, (oi_exposure *)(void *)(raw + 1),
                                      bat_st),
              "misaligned");
    expect_all(OI_ERR_INPUT, n, "misaligned rows");
}

/* Hostile rows among good ones: each row's own status, the rest computed. */
static void test_hostile_rows(void **state)
{
    const oi_camera *c0 = oi_camera_builtin(0);
    const long n = 40;
    long i;
    (void)state;
    random_scenes(n, 77, (double)c0->sun_exclusion_rad);
    scenes[1].target_km[0] = (oi_real)NAN;
    scenes[2].has_observer = 0;
    scenes[3].observer_km[0] = scenes[3].observer_km[1] = scenes[3].observer_km[2] = 0;
    scenes[4].target_albedo = (oi_real)2;
    illum[5].flux_obs = (oi_real)NAN;
    illum[6].e_sun = (oi_real)-1;
    scenes[7].target_vel_km_s[1] = (oi_real)INFINITY;
    scenes[8].observer_km[0] = (oi_real)1000; /* below the surface */
    scenes[8].observer_km[1] = scenes[8].observer_km[2] = 0;
    check_scene_masks(n, c0, NULL, NULL);
    for (i = 1; i <= 8; i++) check_int(1, bat_st[i] < 0, "hostile row in error");
    for (i = 9; i < n; i++)
        if (scenes[i].has_observer) check_int(1, bat_st[i] >= 0, "good row computed");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_scene_masks),
        cmocka_unit_test(test_in_masks),
        cmocka_unit_test(test_hostile_arrays),
        cmocka_unit_test(test_hostile_rows),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

#else
int main(void)
{
    return 0;
}
#endif /* OI_NO_EXPOSURE */
