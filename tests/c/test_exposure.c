/* SPDX-License-Identifier: MIT */
/* test_exposure.c: the camera model (oi_expose, oi_expose_scene), the
 * built-in cameras, oi_flag_name and oi_status_name.
 *
 * References are independent of the library: a synthetic camera whose
 * aperture area is 1 m^2 and whose photon energy is 1e-19 J makes every
 * electron count a round number, so the expected choice of time and gain is
 * worked out by hand in the comments; geometry (Sun angle, Earth disc,
 * boresight on the Earth) is recomputed here in double. */
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
#define REL_TOL 2e-5
#else
#define REL_TOL 1e-12
#endif

#ifndef OI_NO_EXPOSURE
static const double PI = 3.14159265358979323846;
static const double AU = 149597870.7;
static const double TSI = 1361.0;
static const double RE = 6378.137;

/* The setting oi_expose chose: its time and gain indices. */
static void expect_setting(const oi_exposure *out, long time_index, long gain_index)
{
    check_int(time_index, out->time_index, "time index");
    check_int(gain_index, out->gain_index, "gain index");
}

/* No light and no noise: the first setting, SNR 0, too faint only. */
static void expect_dark_choice(const oi_exposure *out)
{
    expect_setting(out, 0, 0);
    check_rel(0.0, out->snr, 0, "snr");
    check_int(OI_FLAG_TOO_FAINT, (long)out->flags, "flags");
}

/* Synthetic camera: area 1 m^2, k = 1e19 e-/J, so S = flux * 1e19 e-/s.
 * IFOV = 1e-5 / 1e-2 = 1e-3 rad, so B = radiance * 1e13 e-/s. */
static oi_camera synth(void)
{
    oi_camera c;
    memset(&c, 0, sizeof c);
    c.name = "synthetic";
    c.aperture_m = (oi_real)(2.0 / sqrt(PI));
    c.focal_length_m = (oi_real)1e-2;
    c.pixel_pitch_m = (oi_real)1e-5;
    c.transmission = 1;
    c.quantum_efficiency = 1;
    c.band_fraction = 1;
    c.photon_energy_j = (oi_real)1e-19;
    c.full_well_e = (oi_real)1e4;
    c.dark_current_e_s = 0;
    c.psf_peak_fraction = 1;
    c.fov_rad = (oi_real)0.2;
    c.sun_exclusion_rad = (oi_real)(30.0 * PI / 180.0);
    c.n_times = 4;
    c.times_s[0] = (oi_real)1e-3;
    c.times_s[1] = (oi_real)1e-2;
    c.times_s[2] = (oi_real)0.1;
    c.times_s[3] = (oi_real)1.0;
    c.n_gains = 3;
    c.gains[0] = 1;
    c.gains[1] = 2;
    c.gains[2] = 4;
    c.read_noise_e[0] = 10;
    c.read_noise_e[1] = 5;
    c.read_noise_e[2] = 2;
    return c;
}

static oi_expose_in input(double flux, double radiance)
{
    oi_expose_in in;
    memset(&in, 0, sizeof in);
    in.flux_w_m2 = (oi_real)flux;
    in.background_w_m2_sr = (oi_real)radiance;
    return in;
}

static int all_zero(const void *p, size_t n)
{
    const unsigned char *b = (const unsigned char *)p;
    size_t i;
    for (i = 0; i < n; i++)
        if (b[i] != 0) return 0;
    return 1;
}

/* S = 1e4 e-/s. fill = t g (full well 1e4). Settings with fill <= 0.5:
 * t <= 0.1 at any gain. SNR(t=0.1) = 1000/sqrt(1000 + rn^2): 30.15 (g=1),
 * 31.23 (g=2), 31.56 (g=4): the choice is t = 0.1 s, gain 4, fill 0.4.
 * At t = 1 s, g = 4: SNR = 1e4/sqrt(1e4 + 4) = 99.98: not too faint. */
static void test_choice_best_snr(void **state)
{
    oi_camera c = synth();
    oi_expose_in in = input(1e-15, 0);
    oi_exposure out;
    (void)state;
    check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "status");
    expect_setting(&out, 2, 2);
    check_rel(0.1, out.exposure_s, REL_TOL, "exposure");
    check_rel(4.0, out.gain, 0, "gain");
    check_rel(1000.0, out.signal_e, REL_TOL, "signal");
    check_rel(0.0, out.background_e, 0, "background");
    check_rel(1000.0, out.peak_e, REL_TOL, "peak");
    check_rel(2500.0, out.saturation_e, REL_TOL, "saturation");
    check_rel(0.4, out.fill, REL_TOL, "fill");
    check_rel(1000.0 / sqrt(1004.0), out.snr, REL_TOL, "snr");
    check_int(0, (long)out.flags, "flags");
    check_rel(0.0, out.sun_angle_rad, 0, "sun angle");
}

/* Goal fill 0.05: settings t <= 0.01 (fill 0.04 at g=4). SNR(0.01, g=4) =
 * 100/sqrt(104). snr_min 200 > 99.98: TOO_FAINT. */
static void test_choice_custom_goal(void **state)
{
    oi_camera c = synth();
    oi_expose_in in = input(1e-15, 0);
    oi_expose_goal goal = {(oi_real)0.05, (oi_real)200, 0u, 0u, 0};
    oi_exposure out;
    (void)state;
    check_int(OI_OK, oi_expose(&c, &in, &goal, &out), "status");
    expect_setting(&out, 1, 2);
    check_rel(100.0 / sqrt(104.0), out.snr, REL_TOL, "snr");
    check_int(OI_FLAG_TOO_FAINT, (long)out.flags, "flags");
}

/* Nothing reaches down to the goal: S = 7000 e-/s, one gain, times 1 and
 * 2 s: fills 0.7 and 1.4; the non-saturating 0.7 is taken, no flag. */
static void test_choice_above_goal(void **state)
{
    oi_camera c = synth();
    oi_expose_in in = input(7e-16, 0);
    oi_exposure out;
    (void)state;
    c.n_times = 2;
    c.times_s[0] = 1;
    c.times_s[1] = 2;
    c.n_gains = 1;
    check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "status");
    check_int(0, out.time_index, "time index");
    check_rel(0.7, out.fill, REL_TOL, "fill");
    check_int(0, (long)out.flags, "flags");
    /* two gains, times 1 s: fills 0.7 (g=1) and 1.4 (g=2): lowest fill */
    c.n_times = 1;
    c.n_gains = 2;
    check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "status 2");
    check_int(0, out.gain_index, "gain index");
    check_rel(0.7, out.fill, REL_TOL, "fill 2");
}

/* S = 1e8 e-/s: at 1 ms and gain 1 the pixel holds 1e5 e- > 1e4: every
 * setting saturates: shortest time, lowest gain, SATURATED, fill 10. */
static void test_all_saturate(void **state)
{
    oi_camera c = synth();
    oi_expose_in in = input(1e-11, 0);
    oi_exposure out;
    (void)state;
    check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "status");
    expect_setting(&out, 0, 0);
    check_rel(10.0, out.fill, REL_TOL, "fill");
    check_int(OI_FLAG_SATURATED, (long)out.flags, "flags");
}

/* S = 1 e-/s: every fill is tiny; best SNR at 1 s, gain 4: 1/sqrt(5). */
static void test_too_faint(void **state)
{
    oi_camera c = synth();
    oi_expose_in in = input(1e-19, 0);
    oi_exposure out;
    (void)state;
    check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "status");
    expect_setting(&out, 3, 2);
    check_rel(1.0 / sqrt(5.0), out.snr, REL_TOL, "snr");
    check_int(OI_FLAG_TOO_FAINT, (long)out.flags, "flags");
}

/* No light and no noise at all: every SNR is 0, ties go to the lowest gain
 * and the shortest time; TOO_FAINT. */
static void test_dark_ties(void **state)
{
    oi_camera c = synth();
    oi_expose_in in = input(0, 0);
    oi_exposure out;
    (void)state;
    c.read_noise_e[0] = c.read_noise_e[1] = c.read_noise_e[2] = 0;
    check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "status");
    expect_dark_choice(&out);
}

/* Background: radiance 1e-10 W/m^2/sr -> 1e3 e-/s, dark 100 e-/s: B = 1100.
 * psf 0.5 halves the target only: S = 0.5 * 2e4 = 1e4. fill = 1.11e4 t g / 1e4;
 * fill <= 0.5 needs t g <= 0.45: t = 0.1 with g = 1, 2, 4 (0.111, 0.222,
 * 0.444); SNR = 1000 / sqrt(1000 + 110 + rn^2): g=4 wins. */
static void test_background_and_psf(void **state)
{
    oi_camera c = synth();
    oi_expose_in in = input(2e-15, 1e-10);
    oi_exposure out;
    (void)state;
    c.psf_peak_fraction = (oi_real)0.5;
    c.dark_current_e_s = 100;
    check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "status");
    expect_setting(&out, 2, 2);
    check_rel(1000.0, out.signal_e, REL_TOL, "signal");
    check_rel(110.0, out.background_e, REL_TOL, "background");
    check_rel(1110.0 * 4 / 1e4, out.fill, REL_TOL, "fill");
    check_rel(1000.0 / sqrt(1114.0), out.snr, REL_TOL, "snr");
}

/* Geometric flags are copied; computed ones in the input are ignored;
 * unknown bits are an error. */
static void test_input_flags(void **state)
{
    oi_camera c = synth();
    oi_expose_in in = input(1e-15, 0);
    oi_exposure out;
    (void)state;
    in.flags = OI_FLAG_SUN_EXCLUSION | OI_FLAG_PENUMBRA | OI_FLAG_TOO_FAINT | OI_FLAG_SATURATED;
    check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "status");
    check_int(OI_FLAG_SUN_EXCLUSION | OI_FLAG_PENUMBRA, (long)out.flags, "flags");
    in.flags = OI_FLAG_BACKGROUND_SATURATED << 1; /* the first bit beyond the defined flags */
    check_int(OI_ERR_FLAGS, oi_expose(&c, &in, NULL, &out), "unknown bit");
    assert_true(all_zero(&out, sizeof out));
}

static void expect_camera_error(const oi_camera *c, const char *what)
{
    oi_expose_in in = input(1e-15, 0);
    oi_exposure out;
    memset(&out, 0xff, sizeof out);
    if (oi_expose(c, &in, NULL, &out) != OI_ERR_CAMERA || !all_zero(&out, sizeof out)) {
        print_error("camera field %s accepted or output not zeroed\n", what);
        fail();
    }
}

#define BAD(field, value)                 \
    do {                                  \
        oi_camera c = synth();            \
        c.field = (oi_real)(value);       \
        expect_camera_error(&c, #field " = " #value); \
    } while (0)

static void test_camera_errors(void **state)
{
    (void)state;
    BAD(aperture_m, 0);
    BAD(aperture_m, -1);
    BAD(aperture_m, NAN);
    BAD(aperture_m, 11);
    BAD(focal_length_m, 0);
    BAD(focal_length_m, INFINITY);
    BAD(pixel_pitch_m, 0);
    BAD(pixel_pitch_m, 1e-2);
    BAD(transmission, 0);
    BAD(transmission, 1.5);
    BAD(quantum_efficiency, 0);
    BAD(quantum_efficiency, NAN);
    BAD(band_fraction, -0.1);
    BAD(band_fraction, 1.01);
    BAD(photon_energy_j, 0);
    BAD(photon_energy_j, 1e-10);
    BAD(full_well_e, 0);
    BAD(full_well_e, 1e12);
    BAD(dark_current_e_s, -1);
    BAD(dark_current_e_s, NAN);
    BAD(psf_peak_fraction, 0);
    BAD(psf_peak_fraction, 2);
    BAD(fov_rad, 0);
    BAD(fov_rad, 4);
    BAD(sun_exclusion_rad, -0.1);
    BAD(sun_exclusion_rad, 4);
    BAD(times_s[0], 0);
    BAD(times_s[1], 1e-3);       /* equal to times_s[0]: not ascending */
    BAD(times_s[3], 0.05);       /* below times_s[2] */
    BAD(times_s[3], 1e5);
    BAD(gains[0], 0);
    BAD(gains[2], 1);            /* below gains[1] */
    BAD(gains[2], NAN);
    BAD(read_noise_e[1], -1);
    BAD(read_noise_e[2], INFINITY);
    {
        oi_camera c = synth();
        c.n_times = 0;
        expect_camera_error(&c, "n_times = 0");
        c.n_times = OI_CAMERA_MAX_TIMES + 1;
        expect_camera_error(&c, "n_times too large");
    }
    {
        oi_camera c = synth();
        c.n_gains = 0;
        expect_camera_error(&c, "n_gains = 0");
        c.n_gains = OI_CAMERA_MAX_GAINS + 1;
        expect_camera_error(&c, "n_gains too large");
    }
    {
        /* a negative time past n_times is not read */
        oi_camera c = synth();
        oi_expose_in in = input(1e-15, 0);
        oi_exposure out;
        c.times_s[4] = -1;
        check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "unused slot");
    }
}

static void expect_status(int want, const oi_camera *c, const oi_expose_in *in,
                          const oi_expose_goal *goal, const char *what)
{
    oi_exposure out;
    int st;
    memset(&out, 0xff, sizeof out);
    st = oi_expose(c, in, goal, &out);
    if (st != want || !all_zero(&out, sizeof out)) {
        print_error("%s: want status %d got %d (or output not zeroed)\n", what, want, st);
        fail();
    }
}

static void test_input_errors(void **state)
{
    oi_camera c = synth();
    oi_expose_in in;
    oi_expose_goal goal;
    (void)state;
    in = input(1e-15, 0);
    assert_int_equal(oi_expose(&c, &in, NULL, NULL), OI_ERR_NULL);
    expect_status(OI_ERR_NULL, NULL, &in, NULL, "camera NULL");
    expect_status(OI_ERR_NULL, &c, NULL, NULL, "in NULL");
    in = input(NAN, 0);
    expect_status(OI_ERR_NONFINITE, &c, &in, NULL, "flux NaN");
    in = input(INFINITY, 0);
    expect_status(OI_ERR_NONFINITE, &c, &in, NULL, "flux inf");
    in = input(1e-15, -INFINITY);
    expect_status(OI_ERR_NONFINITE, &c, &in, NULL, "background -inf");
    in = input(-1e-15, 0);
    expect_status(OI_ERR_INPUT, &c, &in, NULL, "flux negative");
    /* magnitude -30 is 1361 * 10^(0.4 * 3.26) = 2.741e4 W/m^2 */
    in = input(2.8e4, 0);
    expect_status(OI_ERR_MAGNITUDE, &c, &in, NULL, "flux brighter than OI_MAG_MIN");
    in = input(2.7e4, 0);
    {
        oi_exposure out;
        check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "flux just below the limit");
        check_int(OI_FLAG_SATURATED, (long)out.flags, "bright flags");
    }
    in = input(1e-15, -1);
    expect_status(OI_ERR_INPUT, &c, &in, NULL, "background negative");
    in = input(1e-15, 2e8);
    expect_status(OI_ERR_INPUT, &c, &in, NULL, "background too bright");
    in = input(1e-15, 0);
    memset(&goal, 0, sizeof goal);
    goal.fill = (oi_real)1.5;
    goal.snr_min = 0;
    expect_status(OI_ERR_INPUT, &c, &in, &goal, "goal fill 1.5");
    goal.fill = (oi_real)-0.5;
    expect_status(OI_ERR_INPUT, &c, &in, &goal, "goal fill negative");
    goal.fill = (oi_real)NAN;
    expect_status(OI_ERR_INPUT, &c, &in, &goal, "goal fill NaN");
    goal.fill = 0;
    goal.snr_min = -1;
    expect_status(OI_ERR_INPUT, &c, &in, &goal, "goal snr negative");
    goal.snr_min = (oi_real)2e6;
    expect_status(OI_ERR_INPUT, &c, &in, &goal, "goal snr above 1e6");
    /* the goal is checked before the photometry, the flags last */
    in = input(-1e-15, 0);
    in.flags = 1u << 12;
    expect_status(OI_ERR_INPUT, &c, &in, &goal, "bad goal and bad flux");
    goal.snr_min = 0;
    expect_status(OI_ERR_INPUT, &c, &in, &goal, "negative flux before unknown flags");
    in = input(1e-15, 0);
    in.flags = OI_FLAG_BACKGROUND_SATURATED << 1; /* the first bit beyond the defined flags */
    expect_status(OI_ERR_FLAGS, &c, &in, &goal, "unknown flag bit");
}

/* ---------------------------------------------------------------- built-ins */

static void test_builtin_cameras(void **state)
{
    int i;
    oi_expose_in in = input(1e-12, 0);
    oi_exposure out;
    double area, s_rate;
    const oi_camera *tel;
    (void)state;
    assert_null(oi_camera_builtin(-1));
    assert_non_null(oi_camera_builtin(0));
    assert_string_equal(oi_camera_builtin(0)->name, "star-tracker");
    for (i = 0; oi_camera_builtin(i) != NULL; i++) {
        const oi_camera *c = oi_camera_builtin(i);
        assert_non_null(c->name);
        assert_ptr_equal(oi_camera_find(c->name), c);
        check_int(OI_OK, oi_expose(c, &in, NULL, &out), c->name);
        {
            /* A copy is not a built-in by address, so it goes through the
             * full camera check (the library skips it for the built-ins
             * themselves): it must pass, with the same result. A copy with
             * one field out of range must fail. */
            oi_camera copy = *c;
            oi_exposure out_copy;
            check_int(OI_OK, oi_expose(&copy, &in, NULL, &out_copy), "copy of a built-in camera");
            assert_memory_equal(&out, &out_copy, sizeof out);
            copy.times_s[copy.n_times - 1] = copy.times_s[0];
            check_int(OI_ERR_CAMERA, oi_expose(&copy, &in, NULL, &out_copy), "broken copy");
        }
    }
    assert_true(i >= 2 && i <= 8);
    assert_null(oi_camera_builtin(i));
    assert_null(oi_camera_find(NULL));
    assert_null(oi_camera_find(""));
    assert_null(oi_camera_find("Star-tracker"));
    assert_null(oi_camera_find("star-tracke"));
    assert_null(oi_camera_find("star-trackerx"));

    /* The 15 cm telescope on a V = 10 star: F = 1361 10^(-0.4 (10 + 26.74)),
     * S = F pi 0.075^2 0.70 0.5356 0.75 / 3.1825e-19 0.1361 (values written
     * out from the camera's documented sources). */
    tel = oi_camera_find("telescope-15cm");
    assert_non_null(tel);
    in = input(TSI * pow(10.0, -0.4 * (10.0 + 26.74)), 0);
    check_int(OI_OK, oi_expose(tel, &in, NULL, &out), "telescope status");
    area = PI * 0.075 * 0.075;
    s_rate = in.flux_w_m2 * area * 0.70 * 0.5356 * 0.75 / 3.1825e-19 * 0.1361;
    check_rel(s_rate * out.exposure_s, out.signal_e, 1e-5, "telescope signal");
    check_rel(1.0 * out.exposure_s, out.background_e, 1e-5, "telescope dark");
}

static void test_flag_names(void **state)
{
    (void)state;
    assert_string_equal(oi_flag_name(OI_FLAG_SUN_EXCLUSION), "sun_exclusion");
    assert_string_equal(oi_flag_name(OI_FLAG_EARTH_IN_FOV), "earth_in_fov");
    assert_string_equal(oi_flag_name(OI_FLAG_ECLIPSED), "eclipsed");
    assert_string_equal(oi_flag_name(OI_FLAG_TOO_FAINT), "too_faint");
    assert_string_equal(oi_flag_name(OI_FLAG_SATURATED), "saturated");
    assert_string_equal(oi_flag_name(OI_FLAG_BACKGROUND_SATURATED), "background_saturated");
    assert_string_equal(oi_flag_name(OI_FLAG_PENUMBRA), "penumbra");
    assert_string_equal(oi_flag_name(OI_FLAG_OCCULTED), "occulted");
    assert_string_equal(oi_flag_name(OI_FLAG_RESOLVED), "resolved");
    assert_string_equal(oi_flag_name(OI_FLAG_MOON_SHADOW), "moon_shadow");
    assert_null(oi_flag_name(0));
    assert_null(oi_flag_name(OI_FLAG_SUN_EXCLUSION | OI_FLAG_ECLIPSED));
    assert_string_equal(oi_flag_name(OI_FLAG_MOON_IN_FOV), "moon_in_fov");
    assert_string_equal(oi_flag_name(OI_FLAG_TRAILED), "trailed");
    assert_string_equal(oi_flag_name(OI_FLAG_GLINT), "glint");
    assert_null(oi_flag_name(OI_FLAG_BACKGROUND_SATURATED << 1));
}
#endif /* OI_NO_EXPOSURE */

/* Every status: its number (fixed forever), its name (scripts match on it). */
static void test_status_names(void **state)
{
    static const struct {
        int code, number;
        const char *name;
    } all[] = {
        {OI_OK, 0, "OK"},
        {OI_WARN_TABLE_RANGE, 1, "WARN_TABLE_RANGE"},
        {OI_ERR_NULL, -1, "ERR_NULL"},
        {OI_ERR_NONFINITE, -2, "ERR_NONFINITE"},
        {OI_ERR_ZERO_VECTOR, -3, "ERR_ZERO_VECTOR"},
        {OI_ERR_BELOW_SURFACE, -4, "ERR_BELOW_SURFACE"},
        {OI_ERR_OBSERVER_AT_TARGET, -5, "ERR_OBSERVER_AT_TARGET"},
        {OI_ERR_ALBEDO, -6, "ERR_ALBEDO"},
        {OI_ERR_RADIUS, -7, "ERR_RADIUS"},
        {OI_ERR_MODEL, -8, "ERR_MODEL"},
        {OI_ERR_CAMERA, -9, "ERR_CAMERA"},
        {OI_ERR_MAGNITUDE, -10, "ERR_MAGNITUDE"},
        {OI_ERR_TERMS, -11, "ERR_TERMS"},
        {OI_ERR_GEOMETRY, -12, "ERR_GEOMETRY"},
        {OI_ERR_INPUT, -13, "ERR_INPUT"},
        {OI_ERR_FLAGS, -14, "ERR_FLAGS"},
        {OI_ERR_SHAPE, -15, "ERR_SHAPE"},
    };
    size_t i, n = sizeof all / sizeof all[0];
    int code, named = 0;
    (void)state;
    for (i = 0; i < n; i++) {
        check_int(all[i].number, all[i].code, all[i].name);
        assert_string_equal(oi_status_name(all[i].code), all[i].name);
    }
    /* no other code in a wide range has a name: the table above is whole */
    for (code = -1000; code <= 1000; code++) {
        if (strcmp(oi_status_name(code), "UNKNOWN") != 0) named++;
    }
    check_int((long)n, named, "named statuses");
    assert_string_equal(oi_status_name(42), "UNKNOWN");
    assert_string_equal(oi_status_name(-999), "UNKNOWN");
}

/* The archive's version is the header's. */
static void test_version(void **state)
{
    (void)state;
    check_int(OI_VERSION, oi_version(), "oi_version() against OI_VERSION");
    check_int(OI_VERSION_MAJOR * 10000L + OI_VERSION_MINOR * 100L + OI_VERSION_PATCH, OI_VERSION,
              "OI_VERSION encoding");
    assert_true(OI_VERSION_MINOR < 100 && OI_VERSION_PATCH < 100);
}

/* ---------------------------------------------------------------- scene */
#ifndef OI_NO_EXPOSURE

static double angle_ref(const double a[3], const double b[3])
{
    double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                   a[0] * b[1] - a[1] * b[0]};
    return atan2(sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]),
                 a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}

static oi_illum lit_illum(double flux)
{
    oi_illum il;
    memset(&il, 0, sizeof il);
    il.flux_obs = (oi_real)flux;
    il.e_sun = (oi_real)TSI;
    il.shadow.region = OI_SHADOW_LIT;
    return il;
}

/* Looking straight down at the sub-solar point: the boresight meets the
 * Earth at (R, 0, 0) where the Sun (on +x) is at the zenith: background
 * radiance 0.3 * 1361 * (1 AU / |sun|)^2 / pi; Earth fills the field. */
static void test_scene_nadir_subsolar(void **state)
{
    oi_camera c = synth();
    oi_scene s;
    oi_illum il = lit_illum(1e-15);
    oi_exposure out;
    double sun_d = 1.01 * AU, radiance, b_rate;
    (void)state;
    /* a finer pixel and bluer photons so that the bright Earth does not
     * saturate: IFOV 1e-7 rad, k = 1e17 e-/J: B = radiance * 1e3 e-/s */
    c.pixel_pitch_m = (oi_real)1e-7;
    c.focal_length_m = 1;
    c.photon_energy_j = (oi_real)1e-17;
    oi_scene_defaults(&s);
    set3(s.sun_km, sun_d, 0, 0);
    set3(s.observer_km, RE + 1000, 0, 0);
    set3(s.target_km, RE + 500, 0, 0);
    s.has_observer = 1;
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, NULL, &out), "status");
    radiance = 0.3 * TSI * (AU / sun_d) * (AU / sun_d) / PI;
    b_rate = radiance * 1e3;
    check_rel(b_rate * out.exposure_s, out.background_e, REL_TOL * 10, "background");
    check_rel(100.0 * out.exposure_s, out.signal_e, REL_TOL * 10, "signal");
    check_rel(PI, out.sun_angle_rad, REL_TOL, "sun angle");
    check_int(OI_FLAG_EARTH_IN_FOV, (long)(out.flags & ~(unsigned)OI_FLAG_TOO_FAINT), "flags");
    /* Sun on the other side: the spot under the boresight is in the night */
    set3(s.sun_km, -sun_d, 0, 0);
    il.shadow.region = OI_SHADOW_UMBRA;
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, NULL, &out), "status night");
    check_rel(0.0, out.background_e, 0, "night background");
    check_rel(0.0, out.sun_angle_rad, REL_TOL, "sun angle night");
    assert_true(out.flags & OI_FLAG_SUN_EXCLUSION);
    assert_true(out.flags & OI_FLAG_ECLIPSED);
}

/* The model's constants reach the background: TSI 1000 W/m^2 and an AU of
 * 1.5e8 km (the Sun at 1.01 x that) scale the radiance of the sub-solar
 * point, 0.3 TSI (AU / d)^2 / pi; an Earth radius of 6000 km puts the
 * observer 4000 km above it (the boresight still meets it). A model equal
 * to the defaults gives exactly the NULL model's result. */
static void test_scene_custom_model(void **state)
{
    oi_camera c = synth();
    oi_scene s;
    oi_illum il = lit_illum(1e-15);
    oi_exposure out, out_null;
    oi_model m;
    double au = 1.5e8, sun_d = 1.01 * au, radiance;
    (void)state;
    c.pixel_pitch_m = (oi_real)1e-7;
    c.focal_length_m = 1;
    c.photon_energy_j = (oi_real)1e-17;
    oi_scene_defaults(&s);
    set3(s.sun_km, sun_d, 0, 0);
    set3(s.observer_km, 10000, 0, 0);
    set3(s.target_km, 9000, 0, 0);
    s.has_observer = 1;
    memset(&m, 0, sizeof m);
    m.tsi_w_m2 = 1000;
    m.au_km = (oi_real)au;
    m.earth_radius_km = 6000;
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, &m, NULL, &out), "status");
    radiance = 0.3 * 1000.0 * (au / sun_d) * (au / sun_d) / PI;
    check_rel(radiance * 1e3 * out.exposure_s, out.background_e, REL_TOL * 10, "background");
    /* all zero fields: the defaults, as NULL */
    memset(&m, 0, sizeof m);
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, &m, NULL, &out), "status zero model");
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, NULL, &out_null), "status NULL model");
    assert_memory_equal(&out, &out_null, sizeof out);
}

/* Boresight through the Earth: the target is hidden; its flux is dropped. */
static void test_scene_occulted(void **state)
{
    oi_camera c = synth();
    oi_scene s;
    oi_illum il = lit_illum(1e-12);
    oi_exposure out;
    (void)state;
    oi_scene_defaults(&s);
    set3(s.sun_km, AU, 0, 0);
    set3(s.observer_km, RE + 500, 0, 0);
    set3(s.target_km, -(RE + 500), 100, 0);
    s.has_observer = 1;
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, NULL, &out), "status");
    assert_true(out.flags & OI_FLAG_OCCULTED);
    assert_true(out.flags & OI_FLAG_TOO_FAINT);
    assert_true(out.flags & OI_FLAG_EARTH_IN_FOV);
    check_rel(0.0, out.signal_e, 0, "signal");
}

/* Observer on +y, boresight +z (dark sky, misses the Earth). The Earth's
 * centre is 90 deg off the boresight and its disc has radius asin(R/r):
 * its edge is 90 - asin(R/r) away; the Sun placed at 20 deg and 40 deg. */
static void test_scene_sun_and_earth_angles(void **state)
{
    oi_camera c = synth();
    oi_scene s;
    oi_illum il = lit_illum(1e-15);
    oi_exposure out;
    double r = RE + 700, sun_d = AU, edge, ang, sun[3], obs[3] = {0, r, 0}, rel[3];
    double bore[3] = {0, 0, 10};
    int k;
    (void)state;
    oi_scene_defaults(&s);
    s.has_observer = 1;
    set3(s.observer_km, 0, r, 0);
    set3(s.target_km, 0, r, 10);
    c.dark_current_e_s = 50;
    for (k = 0; k < 2; k++) {
        double deg = k == 0 ? 20.0 : 40.0;
        sun[0] = sun_d * sin(deg * PI / 180);
        sun[1] = 0;
        sun[2] = sun_d * cos(deg * PI / 180);
        set3(s.sun_km, sun[0], sun[1], sun[2]);
        rel[0] = sun[0] - obs[0];
        rel[1] = sun[1] - obs[1];
        rel[2] = sun[2] - obs[2];
        ang = angle_ref(rel, bore);
        check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, NULL, &out), "status");
        check_rel(ang, out.sun_angle_rad, REL_TOL * 10, "sun angle");
        check_int(k == 0, (out.flags & OI_FLAG_SUN_EXCLUSION) != 0, "exclusion flag");
        check_int(0, (out.flags & OI_FLAG_EARTH_IN_FOV) != 0, "earth flag, narrow field");
        check_rel(50.0 * out.exposure_s, out.background_e, REL_TOL, "dark sky: dark current only");
    }
    edge = PI / 2 - asin(RE / r); /* 0.415 rad */
    c.fov_rad = (oi_real)(2 * edge * 1.01);
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, NULL, &out), "status wide");
    assert_true(out.flags & OI_FLAG_EARTH_IN_FOV);
    c.fov_rad = (oi_real)(2 * edge * 0.99);
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, NULL, &out), "status just narrower");
    assert_false(out.flags & OI_FLAG_EARTH_IN_FOV);
}

/* A target wider than a pixel: the brightest pixel sees at most the
 * radiance albedo * (E_sun + E_earth + E_moon) / pi over the pixel's solid
 * angle. Synthetic camera: IFOV 1e-3 rad, k = 1e19 e-/J, area 1 m^2, psf 0.5:
 * peak rate 0.2 * 1000 / pi * 1e-6 * 1e19 e-/s. A flux below the bound
 * (divided by psf) is left alone. */
static void test_scene_resolved_target(void **state)
{
    oi_camera c = synth();
    oi_scene s;
    oi_illum il = lit_illum(1e-3);
    oi_exposure out;
    double peak_rate = 0.2 * (600.0 + 300.0 + 100.0) / PI * 1e-6 * 1e19;
    (void)state;
    c.psf_peak_fraction = (oi_real)0.5;
    c.full_well_e = (oi_real)1e9;
    c.gains[0] = (oi_real)0.001;  /* saturation 1e12 e- at the lowest gain */
    oi_scene_defaults(&s);
    s.has_observer = 1;
    s.target_albedo = (oi_real)0.2;
    set3(s.sun_km, 0, 0, -AU);
    set3(s.observer_km, 0, RE + 700, 0);
    set3(s.target_km, 0, RE + 700, 1);
    il.e_sun = 600;
    il.e_earth = 300;
    il.e_moon = 100;
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, NULL, &out), "status");
    assert_true(out.flags & OI_FLAG_RESOLVED);
    check_rel(peak_rate * out.exposure_s, out.signal_e, REL_TOL * 10, "capped signal");
    /* just below the bound: unchanged, no flag (flux * psf * 1e19 < peak_rate) */
    il.flux_obs = (oi_real)(0.99 * peak_rate / 1e19 / 0.5);
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, NULL, &out), "status 2");
    assert_false(out.flags & OI_FLAG_RESOLVED);
    check_rel(0.99 * peak_rate * out.exposure_s, out.signal_e, REL_TOL * 10, "signal");
}

static void test_scene_shadow_flags(void **state)
{
    oi_camera c = synth();
    oi_scene s;
    oi_illum il = lit_illum(1e-15);
    oi_exposure out;
    (void)state;
    oi_scene_defaults(&s);
    s.has_observer = 1;
    set3(s.sun_km, 0, 0, -AU);
    set3(s.observer_km, 0, RE + 700, 0);
    set3(s.target_km, 0, RE + 700, 10);
    il.shadow.region = OI_SHADOW_PENUMBRA;
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, NULL, &out), "penumbra");
    check_int(OI_FLAG_PENUMBRA, (long)(out.flags & ~(unsigned)OI_FLAG_TOO_FAINT), "penumbra flag");
    il.shadow.region = OI_SHADOW_ANNULAR;
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, NULL, &out), "annular");
    check_int(OI_FLAG_PENUMBRA, (long)(out.flags & ~(unsigned)OI_FLAG_TOO_FAINT), "annular flag");
    il.shadow.region = OI_SHADOW_UMBRA;
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, NULL, &out), "umbra");
    check_int(OI_FLAG_ECLIPSED, (long)(out.flags & ~(unsigned)OI_FLAG_TOO_FAINT), "umbra flag");
}

static void expect_scene_status(int want, const oi_camera *c, const oi_scene *s,
                                const oi_illum *il, const oi_model *m, const char *what)
{
    oi_exposure out;
    int st;
    memset(&out, 0xff, sizeof out);
    st = oi_expose_scene(c, s, il, m, NULL, &out);
    if (st != want || !all_zero(&out, sizeof out)) {
        print_error("%s: want status %d got %d (or output not zeroed)\n", what, want, st);
        fail();
    }
}

static void test_scene_errors(void **state)
{
    oi_camera c = synth();
    oi_scene base, s;
    oi_illum il = lit_illum(1e-15);
    oi_model m;
    (void)state;
    oi_scene_defaults(&base);
    base.has_observer = 1;
    set3(base.sun_km, AU, 0, 0);
    set3(base.observer_km, 0, RE + 700, 0);
    set3(base.target_km, 0, RE + 700, 10);
    assert_int_equal(oi_expose_scene(&c, &base, &il, NULL, NULL, NULL), OI_ERR_NULL);
    expect_scene_status(OI_ERR_NULL, NULL, &base, &il, NULL, "camera NULL");
    expect_scene_status(OI_ERR_NULL, &c, NULL, &il, NULL, "scene NULL");
    expect_scene_status(OI_ERR_NULL, &c, &base, NULL, NULL, "illum NULL");
    s = base;
    s.has_observer = 0;
    expect_scene_status(OI_ERR_NULL, &c, &s, &il, NULL, "no observer");
    s = base;
    s.observer_km[1] = (oi_real)NAN;
    expect_scene_status(OI_ERR_NONFINITE, &c, &s, &il, NULL, "observer NaN");
    s = base;
    s.sun_km[2] = (oi_real)INFINITY;
    expect_scene_status(OI_ERR_NONFINITE, &c, &s, &il, NULL, "sun inf");
    s = base;
    set3(s.observer_km, 0, 0, 0);
    expect_scene_status(OI_ERR_ZERO_VECTOR, &c, &s, &il, NULL, "observer zero");
    s = base;
    set3(s.sun_km, 0, 0, 0);
    expect_scene_status(OI_ERR_ZERO_VECTOR, &c, &s, &il, NULL, "sun zero");
    s = base;
    set3(s.observer_km, 0, RE - 1, 0);
    expect_scene_status(OI_ERR_BELOW_SURFACE, &c, &s, &il, NULL, "observer below");
    s = base;
    set3(s.target_km, 0, 100, 0);
    expect_scene_status(OI_ERR_BELOW_SURFACE, &c, &s, &il, NULL, "target below");
    s = base;
    memcpy(s.target_km, s.observer_km, sizeof s.target_km);
    expect_scene_status(OI_ERR_OBSERVER_AT_TARGET, &c, &s, &il, NULL, "observer at target");
    s = base;
    s.earth_albedo = (oi_real)1.5;
    expect_scene_status(OI_ERR_ALBEDO, &c, &s, &il, NULL, "albedo");
    s = base;
    s.target_albedo = (oi_real)-0.5;
    expect_scene_status(OI_ERR_ALBEDO, &c, &s, &il, NULL, "target albedo");
    il.e_earth = (oi_real)INFINITY;
    expect_scene_status(OI_ERR_NONFINITE, &c, &base, &il, NULL, "e_earth inf");
    il.e_earth = -1;
    expect_scene_status(OI_ERR_INPUT, &c, &base, &il, NULL, "e_earth negative");
    il = lit_illum(1e-15);
    il.flux_obs = -1;
    expect_scene_status(OI_ERR_INPUT, &c, &base, &il, NULL, "flux_obs negative");
    il = lit_illum(1e-15);
    memset(&m, 0, sizeof m);
    m.tsi_w_m2 = -1;
    expect_scene_status(OI_ERR_MODEL, &c, &base, &il, &m, "model");
    il.flux_obs = (oi_real)NAN;
    expect_scene_status(OI_ERR_NONFINITE, &c, &base, &il, NULL, "flux NaN");
    il = lit_illum(1e-15);
    c.n_times = 0;
    expect_scene_status(OI_ERR_CAMERA, &c, &base, &il, NULL, "camera");
}


/* ------------------------------------------------- the search, brute force */

/* The reference: the brute-force search that oi_expose used before its
 * search was made cheap (kept here, not in the library): every (time, gain)
 * pair evaluated, gains ascending outside, times ascending inside, strict
 * comparisons (the first of equals wins). The photometry is written out
 * again from oi_expose's Note 1 in oi_real, in the same order of operations,
 * so that the two must agree to the bit where the search is right. */
#ifdef OI_SINGLE_PRECISION
#define REF_SQRT sqrtf
#else
#define REF_SQRT sqrt
#endif

static void ref_evaluate(const oi_camera *c, oi_real rate_s, oi_real rate_b, int ti, int gi,
                         oi_exposure *out)
{
    oi_real t = c->times_s[ti], var, rn = c->read_noise_e[gi];
    out->exposure_s = t;
    out->gain = c->gains[gi];
    out->time_index = ti;
    out->gain_index = gi;
    out->signal_e = rate_s * t;
    out->background_e = rate_b * t;
    out->peak_e = out->signal_e + out->background_e;
    out->saturation_e = c->full_well_e / c->gains[gi];
    out->fill = out->peak_e / out->saturation_e;
    var = out->signal_e + out->background_e + rn * rn;
    out->snr = var > 0 ? out->signal_e / REF_SQRT(var) : (oi_real)0;
}

/* Valid inputs only (the random cases below are all valid). */
static void reference_expose_bruteforce(const oi_camera *c, const oi_expose_in *in,
                                        const oi_expose_goal *goal, oi_exposure *out)
{
    oi_real goal_fill = (oi_real)0.5, snr_min = (oi_real)5.0, area, k, ifov, rate_s, rate_b;
    oi_exposure trial, best_goal, best_low;
    int have_goal = 0, have_low = 0, ti, gi, faint;
    unsigned flags;
    if (goal != NULL && goal->fill != 0) goal_fill = goal->fill;
    if (goal != NULL && goal->snr_min != 0) snr_min = goal->snr_min;
    area = (oi_real)OI_PI * (oi_real)0.25 * c->aperture_m * c->aperture_m;
    k = c->transmission * c->band_fraction * c->quantum_efficiency / c->photon_energy_j;
    ifov = c->pixel_pitch_m / c->focal_length_m;
    rate_s = in->flux_w_m2 * (area * k * c->psf_peak_fraction);
    rate_b = in->background_w_m2_sr * area * (ifov * ifov) * k + c->dark_current_e_s;
    memset(&trial, 0, sizeof trial);
    best_goal = trial;
    best_low = trial;
    for (gi = 0; gi < c->n_gains; gi++) {
        for (ti = 0; ti < c->n_times; ti++) {
            ref_evaluate(c, rate_s, rate_b, ti, gi, &trial);
            if (!(trial.fill < 1)) continue;
            if (trial.fill <= goal_fill) {
                if (!have_goal || trial.snr > best_goal.snr) {
                    best_goal = trial;
                    have_goal = 1;
                }
            } else if (!have_low || trial.fill < best_low.fill) {
                best_low = trial;
                have_low = 1;
            }
        }
    }
    flags = in->flags & ~(unsigned)(OI_FLAG_TOO_FAINT | OI_FLAG_SATURATED |
                                    OI_FLAG_BACKGROUND_SATURATED);
    ref_evaluate(c, rate_s, rate_b, c->n_times - 1, c->n_gains - 1, &trial);
    faint = !(rate_s > 0) || trial.snr < snr_min;
    if (faint) flags |= OI_FLAG_TOO_FAINT;
    if (have_goal) {
        *out = best_goal;
    } else if (have_low) {
        *out = best_low;
    } else {
        /* the well full at the lowest fill: the target's, unless the
         * background alone fills it or the target is too faint */
        ref_evaluate(c, rate_s, rate_b, 0, 0, out);
        flags |= faint || !(out->background_e < out->saturation_e) ? OI_FLAG_BACKGROUND_SATURATED
                                                                   : OI_FLAG_SATURATED;
    }
    out->flags = flags;
    out->sun_angle_rad = 0;
}

/* Fixed-seed generator (64-bit LCG, Knuth's MMIX constants; top 53 bits). */
static uint64_t lcg_state;
static double urand(void)
{
    return lcg01(&lcg_state);
}
static double log_uniform(double lo, double hi)
{
    return lo * pow(hi / lo, urand());
}
static int irand(int lo, int hi) /* lo..hi inclusive */
{
    int v = lo + (int)(urand() * (double)(hi - lo + 1));
    return v > hi ? hi : v;
}

/* Distance in units in the last place between two non-negative finite values. */
static long ulp_dist(oi_real a, oi_real b)
{
#ifdef OI_SINGLE_PRECISION
    int32_t ia, ib;
#else
    int64_t ia, ib;
#endif
    memcpy(&ia, &a, sizeof ia);
    memcpy(&ib, &b, sizeof ib);
    return (long)(ia > ib ? ia - ib : ib - ia);
}

static oi_real nextafter_real(oi_real x)
{
#ifdef OI_SINGLE_PRECISION
    return nextafterf(x, INFINITY);
#else
    return nextafter(x, INFINITY);
#endif
}
/* n strictly ascending values in (0, 1e4]: log-uniform, sometimes with
 * neighbours a few ulp apart (the search then scans) or tiny values. */
static void random_ascending(oi_real *v, int n, double lo, double hi, int close)
{
    int i, j;
    double x[OI_CAMERA_MAX_TIMES];
    for (i = 0; i < n; i++) x[i] = log_uniform(lo, hi);
    for (i = 1; i < n; i++) /* insertion sort */
        for (j = i; j > 0 && x[j] < x[j - 1]; j--) {
            double t = x[j];
            x[j] = x[j - 1];
            x[j - 1] = t;
        }
    for (i = 0; i < n; i++) {
        oi_real r = (oi_real)x[i];
        if (i > 0 && close && urand() < 0.5) {
            r = urand() < 0.5 ? nextafter_real(v[i - 1]) : v[i - 1] * (oi_real)(1.0 + 3e-7 * urand());
        }
        if (i > 0 && !(r > v[i - 1])) r = v[i - 1] + v[i - 1] * (oi_real)1e-6;
        if (i > 0 && !(r > v[i - 1])) r = nextafter_real(v[i - 1]);
        v[i] = r;
    }
}

static oi_camera random_camera(void)
{
    oi_camera c;
    int i, rn_mode = irand(0, 4);
    double rn0;
    memset(&c, 0, sizeof c);
    c.name = "random";
    c.aperture_m = (oi_real)log_uniform(1e-3, 10.0);
    c.focal_length_m = (oi_real)log_uniform(1e-3, 1e3);
    c.pixel_pitch_m = (oi_real)log_uniform(1e-7, 1e-3);
    c.transmission = (oi_real)(0.05 + 0.95 * urand());
    c.quantum_efficiency = (oi_real)(0.05 + 0.95 * urand());
    c.band_fraction = (oi_real)(0.05 + 0.95 * urand());
    c.photon_energy_j = (oi_real)log_uniform(1e-20, 1e-17);
    c.full_well_e = (oi_real)log_uniform(1.0, 1e9);
    c.dark_current_e_s = urand() < 0.3 ? 0 : (oi_real)log_uniform(1e-3, 1e6);
    c.psf_peak_fraction = (oi_real)(0.01 + 0.99 * urand());
    c.fov_rad = (oi_real)(0.001 + 3.0 * urand());
    c.sun_exclusion_rad = (oi_real)(3.0 * urand());
    c.n_times = irand(1, OI_CAMERA_MAX_TIMES);
    random_ascending(c.times_s, c.n_times, urand() < 0.1 ? 1e-35 : 1e-6, 1e4, urand() < 0.15);
    c.n_gains = irand(1, OI_CAMERA_MAX_GAINS);
    random_ascending(c.gains, c.n_gains, 1e-3, 1e3, urand() < 0.1);
    rn0 = urand() < 0.1 ? 0.0 : log_uniform(0.1, 100.0);
    for (i = 0; i < c.n_gains; i++) {
        switch (rn_mode) {
        case 0: c.read_noise_e[i] = (oi_real)rn0; break;                       /* equal */
        case 1: c.read_noise_e[i] = (oi_real)(rn0 / (1.0 + i)); break;         /* falling */
        case 2: c.read_noise_e[i] = (oi_real)(rn0 * (1.0 + i)); break;         /* rising */
        case 3: c.read_noise_e[i] = (oi_real)(urand() < 0.3 ? 0.0 : 100.0 * urand()); break;
        default: c.read_noise_e[i] = (oi_real)(i % 2 ? rn0 : 2.0 * rn0); break; /* zig-zag */
        }
    }
    return c;
}

/* The time to fill the pixel to the goal, for a flux chosen around it: the
 * flux that would fill full_well at gain 1 in time t is
 * full_well / (t * area * k * psf). */
static double flux_around(const oi_camera *c)
{
    double area = PI * 0.25 * (double)c->aperture_m * (double)c->aperture_m;
    double k = (double)c->transmission * (double)c->band_fraction *
               (double)c->quantum_efficiency / (double)c->photon_energy_j;
    double t = (double)c->times_s[irand(0, c->n_times - 1)];
    double f = (double)c->full_well_e / (t * area * k * (double)c->psf_peak_fraction);
    /* 20 magnitudes around it (factor 1e4 either way) */
    return f * pow(10.0, -0.4 * (20.0 * urand() - 10.0));
}

/* Rates of the reference (as in reference_expose_bruteforce). */
static void ref_rates(const oi_camera *c, const oi_expose_in *in, oi_real *rate_s, oi_real *rate_b)
{
    oi_real area = (oi_real)OI_PI * (oi_real)0.25 * c->aperture_m * c->aperture_m;
    oi_real k = c->transmission * c->band_fraction * c->quantum_efficiency / c->photon_energy_j;
    oi_real ifov = c->pixel_pitch_m / c->focal_length_m;
    *rate_s = in->flux_w_m2 * (area * k * c->psf_peak_fraction);
    *rate_b = in->background_w_m2_sr * area * (ifov * ifov) * k + c->dark_current_e_s;
}

/* Put the fill of setting (ti, gi) exactly on target (1: the saturation
 * boundary; the goal: the goal boundary) by stepping the flux an ulp at a
 * time from the scaled guess; 1 when it got there. */
static int tune_flux_to_fill(const oi_camera *c, oi_expose_in *in, int ti, int gi, oi_real target)
{
    oi_exposure e;
    oi_real rs, rb, flux0 = in->flux_w_m2;
    double guess;
    int step;
    ref_rates(c, in, &rs, &rb);
    ref_evaluate(c, rs, rb, ti, gi, &e);
    /* rate_s that puts the fill on target: target * saturation / t - rate_b */
    guess = (double)target * (double)e.saturation_e / (double)e.exposure_s - (double)rb;
    if (!(rs > 0) || !(guess > 0)) return 0;
    in->flux_w_m2 = (oi_real)((double)in->flux_w_m2 * guess / (double)rs);
    for (step = 0; step < 64; step++) {
        if (!(in->flux_w_m2 > 0) || !(in->flux_w_m2 < (oi_real)2.74e4)) break;
        ref_rates(c, in, &rs, &rb);
        ref_evaluate(c, rs, rb, ti, gi, &e);
        if (e.fill == target) return 1;
        in->flux_w_m2 = e.fill < target ? nextafter_real(in->flux_w_m2)
#ifdef OI_SINGLE_PRECISION
                                        : nextafterf(in->flux_w_m2, 0);
#else
                                        : nextafter(in->flux_w_m2, 0);
#endif
    }
    in->flux_w_m2 = flux0;
    return 0;
}

static void test_search_matches_bruteforce(void **state)
{
    int n, fails = 0;
    long worst_fill = 0, worst_snr = 0;
    int n_goal = 0, n_low = 0, n_sat = 0, n_faint = 0, n_dark = 0, n_scan_times = 0;
    int n_exact_one = 0, n_exact_goal = 0;
    (void)state;
    lcg_state = 20261122ULL;
    for (n = 0; n < 40000; n++) {
        oi_camera c = random_camera();
        oi_expose_in in;
        oi_expose_goal goal, *gp = NULL;
        oi_exposure got, want;
        double flux, u = urand();
        int st, i;
        memset(&in, 0, sizeof in);
        if (u < 0.03) {
            flux = 0;
        } else if (u < 0.05) {
#ifdef OI_SINGLE_PRECISION
            flux = 1e-42;   /* subnormal flux: the signal is tiny, the search scans */
#else
            flux = 1e-310;
#endif
        } else if (u < 0.06) {
            flux = 2.74e4;
        } else {
            flux = flux_around(&c);
            if (flux > 2.74e4) flux = 2.74e4;
        }
        in.flux_w_m2 = (oi_real)flux;
        in.background_w_m2_sr = urand() < 0.4 ? 0 : (oi_real)log_uniform(1e-12, 1e6);
        in.flags = (unsigned)irand(0, 255);
        u = urand();
        if (u < 0.4) {
            gp = NULL;
        } else {
            goal.fill = u < 0.5 ? 0 : (u < 0.55 ? 1 : (oi_real)(0.01 + 0.99 * urand()));
            goal.snr_min = urand() < 0.3 ? 0 : (oi_real)log_uniform(0.1, 1e4);
            goal.sky = 0u;
            goal.has_sensor_temp = 0u;
            goal.sensor_temp_c = 0;
            gp = &goal;
        }
        /* one case in five: a setting's fill exactly at 1 or at the goal
         * (up to 4 settings tried: an ulp of flux may step over the target) */
        u = urand();
        if (u < 0.2 && in.flux_w_m2 > 0) {
            oi_real target = u < 0.1 ? 1 : (gp != NULL && gp->fill != 0 ? gp->fill : (oi_real)0.5);
            for (i = 0; i < 4; i++) {
                if (tune_flux_to_fill(&c, &in, irand(0, c.n_times - 1), irand(0, c.n_gains - 1), target)) {
                    if (u < 0.1) n_exact_one++; else n_exact_goal++;
                    break;
                }
            }
        }
        for (i = 1; i < c.n_times; i++)
            if (!((double)c.times_s[i] >= (double)c.times_s[i - 1] * (1.0 + 1e-5))) n_scan_times++;
        st = oi_expose(&c, &in, gp, &got);
        if (st != OI_OK) {
            print_error("case %d: status %d\n", n, st);
            fails++;
            continue;
        }
        reference_expose_bruteforce(&c, &in, gp, &want);
        if (got.time_index != want.time_index || got.gain_index != want.gain_index ||
            got.flags != want.flags || got.exposure_s != want.exposure_s || got.gain != want.gain ||
            ulp_dist(got.fill, want.fill) > 4 || ulp_dist(got.snr, want.snr) > 4) {
            if (fails < 10) {
                print_error("case %d: want t%d g%d flags %u fill %.17g snr %.17g got t%d g%d flags %u "
                            "fill %.17g snr %.17g\n",
                            n, want.time_index, want.gain_index, want.flags, (double)want.fill,
                            (double)want.snr, got.time_index, got.gain_index, got.flags,
                            (double)got.fill, (double)got.snr);
            }
            fails++;
        }
        if (ulp_dist(got.fill, want.fill) > worst_fill) worst_fill = ulp_dist(got.fill, want.fill);
        if (ulp_dist(got.snr, want.snr) > worst_snr) worst_snr = ulp_dist(got.snr, want.snr);
        if (want.flags & OI_FLAG_SATURATED) n_sat++;
        else if (want.fill <= (gp && gp->fill != 0 ? gp->fill : (oi_real)0.5)) n_goal++;
        else n_low++;
        if (want.flags & OI_FLAG_TOO_FAINT) n_faint++;
        if (want.signal_e == 0) n_dark++;
    }
    if (fails) {
        print_error("%d of 40000 random cases differ from the brute-force search\n", fails);
        fail();
    }
    /* every branch of the rule was exercised */
    if (n_goal < 10000 || n_low < 400 || n_sat < 400 || n_faint < 1000 || n_dark < 1000 ||
        n_scan_times < 1000 || n_exact_one < 2000 || n_exact_goal < 2000 || worst_fill > 0 ||
        worst_snr > 0) {
        print_error("coverage: goal %d low %d saturated %d too_faint %d dark %d close times %d "
                    "fill exactly 1 %d, exactly the goal %d; worst ulp fill %ld snr %ld\n",
                    n_goal, n_low, n_sat, n_faint, n_dark, n_scan_times, n_exact_one, n_exact_goal,
                    worst_fill, worst_snr);
        fail();
    }
}

/* A positive target rate whose signal rounds to 0 at every time: every SNR
 * is exactly 0 at every gain although the read noise falls with gain; the
 * first setting (shortest time, lowest gain) wins the tie, as in the full
 * search. Synthetic camera: S = flux * 1e19 e-/s, times 1e-30 .. 1e-24 s. */
static void test_search_zero_signal_ties(void **state)
{
    oi_camera c = synth();
    oi_expose_in in;
    oi_exposure got, want;
    (void)state;
#ifdef OI_SINGLE_PRECISION
    in = input(1e-44, 0);  /* S ~ 1e-25 e-/s: S t underflows to 0 */
#else
    in = input(1e-320, 0); /* S ~ 1e-301 e-/s */
#endif
    c.times_s[0] = (oi_real)1e-30;
    c.times_s[1] = (oi_real)1e-28;
    c.times_s[2] = (oi_real)1e-26;
    c.times_s[3] = (oi_real)1e-24;
    check_int(OI_OK, oi_expose(&c, &in, NULL, &got), "status");
    reference_expose_bruteforce(&c, &in, NULL, &want);
    check_int(0, want.time_index, "reference time index");
    check_int(0, want.gain_index, "reference gain index");
    expect_dark_choice(&got);
}

/* The brightest accepted flux is magnitude OI_MAG_MIN = -30 at the nominal
 * TSI: 1361 * 10^(0.4 * 3.26) = 27406.787 W/m^2, computed here with pow. */
static void test_flux_limit(void **state)
{
    oi_camera c = synth();
    oi_expose_in in = input(0, 0);
    oi_exposure out;
    double lim = 1361.0 * pow(10.0, 0.4 * (-26.74 - OI_MAG_MIN));
#ifdef OI_SINGLE_PRECISION
    const double rel = 1e-6;
#else
    const double rel = 1e-13;
#endif
    (void)state;
    in.flux_w_m2 = (oi_real)(lim * (1 - rel));
    check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "just fainter than magnitude -30");
    in.flux_w_m2 = (oi_real)(lim * (1 + rel));
    check_int(OI_ERR_MAGNITUDE, oi_expose(&c, &in, NULL, &out), "just brighter than magnitude -30");
#ifndef OI_SINGLE_PRECISION
    /* the library's own flux of magnitude -30 is accepted */
    check_int(OI_OK, oi_flux_from_magnitude((oi_real)OI_MAG_MIN, NULL, &in.flux_w_m2), "flux of -30");
    check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "oi_flux_from_magnitude(OI_MAG_MIN)");
#endif
}

/* Earth in the field: the flag against gamma - rho < fov/2 in long double
 * from the same (rounded) inputs, for random observers and boresights and
 * for boresights placed just inside and just outside the boundary. Only
 * cases within TOL of the boundary may go either way. */
#ifdef OI_SINGLE_PRECISION
#define FOV_TOL 2e-6L
#else
#define FOV_TOL 1e-13L
#endif
static long double angle_ld(const long double a[3], const long double b[3])
{
    long double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                        a[0] * b[1] - a[1] * b[0]};
    return atan2l(sqrtl(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]),
                  a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}

static void test_scene_earth_in_fov_boundary(void **state)
{
    oi_camera c = synth();
    oi_scene s;
    oi_illum il = lit_illum(1e-15);
    oi_exposure out;
    int n, k, fails = 0, n_in = 0, n_out = 0, n_near = 0;
    (void)state;
    lcg_state = 7ULL;
    oi_scene_defaults(&s);
    s.has_observer = 1;
    set3(s.sun_km, 0, 0, AU);
    for (n = 0; n < 20000; n++) {
        double r = RE * log_uniform(1.01, 100.0), d, gam, dir[3], e1[3], e2[3], ob[3], nrm;
        long double o[3], t[3], bl[3], no[3], g, rho, h, margin;
        int want, got;
        /* observer at a random direction, distance r */
        for (k = 0; k < 3; k++) ob[k] = urand() - 0.5;
        nrm = sqrt(ob[0] * ob[0] + ob[1] * ob[1] + ob[2] * ob[2]);
        for (k = 0; k < 3; k++) ob[k] *= r / nrm;
        c.fov_rad = (oi_real)(urand() < 0.5 ? log_uniform(1e-3, 0.5) : 0.001 + 3.0 * urand());
        /* boresight at angle gam from the direction to the Earth's centre:
         * random, or at the boundary asin(R/r) + fov/2 +- a small margin */
        if (n % 2 == 0) {
            gam = PI * urand();
        } else {
            gam = asin(RE / r) + 0.5 * (double)c.fov_rad +
                  (urand() < 0.5 ? -1.0 : 1.0) * (double)FOV_TOL * log_uniform(2.0, 1e4);
            if (gam > PI) gam = PI;
        }
        /* e1 = unit towards the Earth's centre, e2 perpendicular */
        for (k = 0; k < 3; k++) e1[k] = -ob[k] / r;
        e2[0] = e1[1];
        e2[1] = -e1[0];
        e2[2] = 0;
        nrm = sqrt(e2[0] * e2[0] + e2[1] * e2[1]);
        if (nrm < 1e-6) {
            e2[0] = 1;
            e2[1] = 0;
            nrm = 1;
        }
        for (k = 0; k < 3; k++) e2[k] /= nrm;
        d = 50.0 + 1000.0 * urand();
        for (k = 0; k < 3; k++) dir[k] = cos(gam) * e1[k] + sin(gam) * e2[k];
        set3(s.observer_km, ob[0], ob[1], ob[2]);
        set3(s.target_km, ob[0] + d * dir[0], ob[1] + d * dir[1], ob[2] + d * dir[2]);
        if (oi_expose_scene(&c, &s, &il, NULL, NULL, &out) == OI_ERR_BELOW_SURFACE) continue;
        /* reference from the rounded inputs */
        for (k = 0; k < 3; k++) {
            o[k] = (long double)s.observer_km[k];
            t[k] = (long double)s.target_km[k];
            bl[k] = t[k] - o[k];
            no[k] = -o[k];
        }
        g = angle_ld(no, bl);
        rho = asinl((long double)RE / sqrtl(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]));
        h = 0.5L * (long double)c.fov_rad;
        margin = g - rho - h;
        want = margin < 0;
        got = (out.flags & OI_FLAG_EARTH_IN_FOV) != 0;
        if (fabsl(margin) < FOV_TOL) {
            n_near++;
            continue;
        }
        if (want) n_in++; else n_out++;
        if (want != got) {
            if (fails < 10)
                print_error("case %d: gamma - rho - fov/2 = %.3Lg: want %d got %d\n", n, margin, want, got);
            fails++;
        }
    }
    if (fails || n_in < 3000 || n_out < 3000) {
        print_error("earth_in_fov: %d wrong, %d inside, %d outside, %d within %.1Lg of the boundary\n",
                    fails, n_in, n_out, n_near, FOV_TOL);
        fail();
    }
}

/* sun_angle_rad is oi_angle(sun - observer, target - observer), bit for bit. */
static void test_scene_sun_angle_is_oi_angle(void **state)
{
    oi_camera c = synth();
    oi_scene s;
    oi_illum il = lit_illum(1e-15);
    oi_exposure out;
    oi_real rel[3], b[3];
    int n, k;
    (void)state;
    lcg_state = 99ULL;
    oi_scene_defaults(&s);
    s.has_observer = 1;
    for (n = 0; n < 2000; n++) {
        for (k = 0; k < 3; k++) {
            s.sun_km[k] = (oi_real)(AU * (urand() - 0.5));
            s.observer_km[k] = (oi_real)(3.0 * RE * (urand() - 0.5));
            s.target_km[k] = (oi_real)(s.observer_km[k] + 2000.0 * (urand() - 0.5));
        }
        if (oi_expose_scene(&c, &s, &il, NULL, NULL, &out) != OI_OK) continue;
        for (k = 0; k < 3; k++) {
            rel[k] = s.sun_km[k] - s.observer_km[k];
            b[k] = s.target_km[k] - s.observer_km[k];
        }
        if (out.sun_angle_rad != oi_angle(rel, b)) {
            print_error("case %d: want %.17g got %.17g\n", n, (double)oi_angle(rel, b),
                        (double)out.sun_angle_rad);
            fail();
        }
    }
}

#endif /* OI_NO_EXPOSURE */

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_status_names),
        cmocka_unit_test(test_version),
#ifndef OI_NO_EXPOSURE
        cmocka_unit_test(test_choice_best_snr),
        cmocka_unit_test(test_choice_custom_goal),
        cmocka_unit_test(test_choice_above_goal),
        cmocka_unit_test(test_all_saturate),
        cmocka_unit_test(test_too_faint),
        cmocka_unit_test(test_dark_ties),
        cmocka_unit_test(test_background_and_psf),
        cmocka_unit_test(test_input_flags),
        cmocka_unit_test(test_camera_errors),
        cmocka_unit_test(test_input_errors),
        cmocka_unit_test(test_builtin_cameras),
        cmocka_unit_test(test_flag_names),
        cmocka_unit_test(test_scene_nadir_subsolar),
        cmocka_unit_test(test_scene_custom_model),
        cmocka_unit_test(test_scene_occulted),
        cmocka_unit_test(test_scene_sun_and_earth_angles),
        cmocka_unit_test(test_scene_resolved_target),
        cmocka_unit_test(test_scene_shadow_flags),
        cmocka_unit_test(test_scene_errors),
        cmocka_unit_test(test_search_matches_bruteforce),
        cmocka_unit_test(test_search_zero_signal_ties),
        cmocka_unit_test(test_flux_limit),
        cmocka_unit_test(test_scene_earth_in_fov_boundary),
        cmocka_unit_test(test_scene_sun_angle_is_oi_angle),
#endif
    };
#ifdef OI_NO_EXPOSURE
    printf("skip test_exposure's camera and exposure cases: OI_NO_EXPOSURE removes the camera model\n");
#endif
    return cmocka_run_group_tests(tests, NULL, NULL);
}
