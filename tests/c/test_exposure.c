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

static void check_rel(double want, double got, double rel, const char *what)
{
    double err = fabs(got - want);
    if (!(err <= rel * fabs(want) + 1e-300)) {
        print_error("%s: want %.17g got %.17g rel err %.3g\n", what, want, got,
                    want != 0 ? err / fabs(want) : err);
        fail();
    }
}

static void check_int(long want, long got, const char *what)
{
    if (want != got) {
        print_error("%s: want %ld got %ld\n", what, want, got);
        fail();
    }
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
    check_int(2, out.time_index, "time index");
    check_int(2, out.gain_index, "gain index");
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
    oi_expose_goal goal = {(oi_real)0.05, (oi_real)200};
    oi_exposure out;
    (void)state;
    check_int(OI_OK, oi_expose(&c, &in, &goal, &out), "status");
    check_int(1, out.time_index, "time index");
    check_int(2, out.gain_index, "gain index");
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
    check_int(0, out.time_index, "time index");
    check_int(0, out.gain_index, "gain index");
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
    check_int(3, out.time_index, "time index");
    check_int(2, out.gain_index, "gain index");
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
    check_int(0, out.time_index, "time index");
    check_int(0, out.gain_index, "gain index");
    check_rel(0.0, out.snr, 0, "snr");
    check_int(OI_FLAG_TOO_FAINT, (long)out.flags, "flags");
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
    check_int(2, out.time_index, "time index");
    check_int(2, out.gain_index, "gain index");
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
    in.flags = 1u << 10;
    check_int(OI_ERR_TERMS, oi_expose(&c, &in, NULL, &out), "unknown bit");
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
    expect_status(OI_ERR_MAGNITUDE, &c, &in, NULL, "flux negative");
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
    expect_status(OI_ERR_MAGNITUDE, &c, &in, NULL, "background negative");
    in = input(1e-15, 2e8);
    expect_status(OI_ERR_MAGNITUDE, &c, &in, NULL, "background too bright");
    in = input(1e-15, 0);
    goal.fill = (oi_real)1.5;
    goal.snr_min = 0;
    expect_status(OI_ERR_CAMERA, &c, &in, &goal, "goal fill 1.5");
    goal.fill = (oi_real)-0.5;
    expect_status(OI_ERR_CAMERA, &c, &in, &goal, "goal fill negative");
    goal.fill = (oi_real)NAN;
    expect_status(OI_ERR_CAMERA, &c, &in, &goal, "goal fill NaN");
    goal.fill = 0;
    goal.snr_min = -1;
    expect_status(OI_ERR_CAMERA, &c, &in, &goal, "goal snr negative");
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
    }
    assert_true(i >= 2 && i <= 8);
    assert_null(oi_camera_builtin(i));
    assert_null(oi_camera_find(NULL));
    assert_null(oi_camera_find(""));
    assert_null(oi_camera_find("Star-tracker"));
    assert_null(oi_camera_find("star-tracke"));
    assert_null(oi_camera_find("star-trackerx"));

    /* The 15 cm telescope on a V = 10 star: F = 1361 10^(-0.4 (10 + 26.74)),
     * S = F pi 0.075^2 0.70 0.5356 0.75 / 3.1825e-19 0.25 (values written
     * out from the camera's documented sources). */
    tel = oi_camera_find("telescope-15cm");
    assert_non_null(tel);
    in = input(TSI * pow(10.0, -0.4 * (10.0 + 26.74)), 0);
    check_int(OI_OK, oi_expose(tel, &in, NULL, &out), "telescope status");
    area = PI * 0.075 * 0.075;
    s_rate = in.flux_w_m2 * area * 0.70 * 0.5356 * 0.75 / 3.1825e-19 * 0.25;
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
    assert_string_equal(oi_flag_name(OI_FLAG_PENUMBRA), "penumbra");
    assert_string_equal(oi_flag_name(OI_FLAG_OCCULTED), "occulted");
    assert_string_equal(oi_flag_name(OI_FLAG_RESOLVED), "resolved");
    assert_null(oi_flag_name(0));
    assert_null(oi_flag_name(OI_FLAG_SUN_EXCLUSION | OI_FLAG_ECLIPSED));
    assert_null(oi_flag_name(256u));
}
#endif /* OI_NO_EXPOSURE */

static void test_status_names(void **state)
{
    (void)state;
    assert_string_equal(oi_status_name(OI_OK), "OK");
    assert_string_equal(oi_status_name(OI_WARN_TABLE_RANGE), "WARN_TABLE_RANGE");
    assert_string_equal(oi_status_name(OI_ERR_NULL), "ERR_NULL");
    assert_string_equal(oi_status_name(OI_ERR_NONFINITE), "ERR_NONFINITE");
    assert_string_equal(oi_status_name(OI_ERR_ZERO_VECTOR), "ERR_ZERO_VECTOR");
    assert_string_equal(oi_status_name(OI_ERR_BELOW_SURFACE), "ERR_BELOW_SURFACE");
    assert_string_equal(oi_status_name(OI_ERR_OBSERVER_AT_TARGET), "ERR_OBSERVER_AT_TARGET");
    assert_string_equal(oi_status_name(OI_ERR_ALBEDO), "ERR_ALBEDO");
    assert_string_equal(oi_status_name(OI_ERR_RADIUS), "ERR_RADIUS");
    assert_string_equal(oi_status_name(OI_ERR_MODEL), "ERR_MODEL");
    assert_string_equal(oi_status_name(OI_ERR_CAMERA), "ERR_CAMERA");
    assert_string_equal(oi_status_name(OI_ERR_MAGNITUDE), "ERR_MAGNITUDE");
    assert_string_equal(oi_status_name(OI_ERR_TERMS), "ERR_TERMS");
    assert_string_equal(oi_status_name(OI_ERR_GEOMETRY), "ERR_GEOMETRY");
    assert_string_equal(oi_status_name(42), "UNKNOWN");
    assert_string_equal(oi_status_name(-999), "UNKNOWN");
}

/* ---------------------------------------------------------------- scene */
#ifndef OI_NO_EXPOSURE

static void set3(oi_real v[3], double x, double y, double z)
{
    v[0] = (oi_real)x;
    v[1] = (oi_real)y;
    v[2] = (oi_real)z;
}

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
    expect_scene_status(OI_ERR_MAGNITUDE, &c, &base, &il, NULL, "e_earth negative");
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

#endif /* OI_NO_EXPOSURE */

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_status_names),
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
        cmocka_unit_test(test_scene_occulted),
        cmocka_unit_test(test_scene_sun_and_earth_angles),
        cmocka_unit_test(test_scene_resolved_target),
        cmocka_unit_test(test_scene_shadow_flags),
        cmocka_unit_test(test_scene_errors),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
