/* SPDX-License-Identifier: MIT */
/*
 * test_motion.c: a target that moves during the exposure (oi_expose_in.
 * rate_rad_s, oi_scene velocities): the trailed peak of a Gaussian PSF
 * against a numerical quadrature of the pixel integral (the PSF's sigma
 * found by bisection, independently of the library's Newton steps), the
 * choice against a brute-force search by the documented rule over
 * one-setting cameras, the trail cap and OI_FLAG_TRAILED, the angular rate
 * of a scene, and the hostile inputs.
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
#define FACTOR_TOL 2e-4
#define REL_TOL 2e-5
#else
#define FACTOR_TOL 1e-7
#define REL_TOL 1e-12
#endif

#ifndef OI_NO_EXPOSURE

/* A camera of IFOV 1e-5 rad, one time, one gain. */
static oi_camera one_setting(double t, double psf_peak)
{
    oi_camera c = oi_test_camera("motion");
    c.psf_peak_fraction = (oi_real)psf_peak;
    c.times_s[0] = (oi_real)t;
    c.read_noise_e[0] = 3;
    return c;
}

/* sigma with erf(1 / (2 sqrt(2) sigma))^2 = p, by bisection on a. */
static double sigma_of(double p)
{
    double lo = 0, hi = 10, q = sqrt(p);
    int i;
    for (i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        if (erf(mid) < q) lo = mid; else hi = mid;
    }
    return 1.0 / (2.0 * sqrt(2.0) * 0.5 * (lo + hi));
}

/* Along the trail, the pixel collects the mean over the trail's positions
 * x of the Gaussian's mass in [x - 1/2, x + 1/2]: composite Simpson. */
static double along_fraction(double sigma, double trail)
{
    const int n = 20000;
    double h = trail / n, sum = 0;
    int i;
    for (i = 0; i <= n; i++) {
        double x = -0.5 * trail + i * h;
        double m = 0.5 * (erf((x + 0.5) / (sqrt(2.0) * sigma)) - erf((x - 0.5) / (sqrt(2.0) * sigma)));
        sum += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) * m;
    }
    return sum * h / 3.0 / trail;
}

static void test_trail_factor_quadrature(void **state)
{
    const double peaks[] = {0.05, 0.25, 0.30, 0.6, 0.95};
    const double trails[] = {0.002, 0.01, 0.3, 0.999, 1.0, 1.001, 2.0, 7.5, 40.0, 1000.0};
    size_t i, j;
    (void)state;
    for (i = 0; i < sizeof peaks / sizeof peaks[0]; i++) {
        double sigma = sigma_of(peaks[i]), q = erf(1.0 / (2.0 * sqrt(2.0) * sigma));
        for (j = 0; j < sizeof trails / sizeof trails[0]; j++) {
            oi_camera c = one_setting(1.0, peaks[i]);
            oi_expose_in in;
            oi_exposure out;
            double want = along_fraction(sigma, trails[j]) / q;
            memset(&in, 0, sizeof in);
            in.flux_w_m2 = (oi_real)1e-14;
            in.rate_rad_s = (oi_real)(trails[j] * 1e-5); /* trails[j] pixels in 1 s */
            check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "status");
            check_rel(trails[j], out.trail_px, REL_TOL * 10, "trail");
            check_close(want, out.trail_factor, 0, FACTOR_TOL, "trail factor");
            check_rel(out.trail_factor * 1e-14 * 1e19 * peaks[i], out.signal_e, 1e-5,
                      "signal");
            check_rel(in.rate_rad_s, out.rate_rad_s, 0, "rate echoed");
        }
    }
}

/* At rest the factor is 1 and the trail 0: the outputs of earlier versions. */
static void test_at_rest(void **state)
{
    oi_camera c = one_setting(1.0, 0.25);
    oi_expose_in in;
    oi_exposure out;
    (void)state;
    memset(&in, 0, sizeof in);
    in.flux_w_m2 = (oi_real)1e-14;
    check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "status");
    check_rel(1.0, out.trail_factor, 0, "factor");
    check_rel(0.0, out.trail_px, 0, "trail");
    check_rel(1e-14 * 1e19 * 0.25, out.signal_e, REL_TOL * 10, "signal");
}

static uint64_t rng = 12345u;

/* The choice for a moving target against the rule, brute force over
 * one-setting cameras (each gives that setting's numbers): among the
 * allowed times (trail <= max_trail_px, at least the shortest), the
 * settings with fill < 1 and fill <= goal, highest SNR, first of equals in
 * (gain, time) order; else the lowest fill; TOO_FAINT when no allowed time
 * reaches the SNR goal at the highest gain. */
static void test_moving_choice_bruteforce(void **state)
{
    int k, n_trailed = 0, n_sat = 0, n_faint = 0, n_inner = 0;
    (void)state;
    for (k = 0; k < 3000; k++) {
        oi_camera c = one_setting(1.0, 0.05 + 0.9 * lcg01(&rng));
        oi_expose_in in;
        oi_exposure got, e;
        int nt = 1 + (int)(lcg01(&rng) * 10), ng = 1 + (int)(lcg01(&rng) * 4), ti, gi, n;
        int found = 0, bt = 0, bg = 0, lt = 0, lg = 0, faint, low_bg_full = 0;
        double best = 0, low = 0, maxsnr = 0, px_s, t = 1e-3 * (1 + lcg01(&rng));
        unsigned want_flags = 0;
        c.n_times = nt;
        for (ti = 0; ti < nt; ti++) {
            c.times_s[ti] = (oi_real)t;
            t *= 1.5 + 3 * lcg01(&rng);
        }
        c.n_gains = ng;
        for (gi = 0; gi < ng; gi++) {
            c.gains[gi] = (oi_real)(1 + gi + lcg01(&rng) * 0.5);
            c.read_noise_e[gi] = (oi_real)(1 + 20 * lcg01(&rng));
        }
        c.full_well_e = (oi_real)pow(10, 3 + 3 * lcg01(&rng));
        c.dark_current_e_s = (oi_real)(lcg01(&rng) < 0.5 ? 0 : pow(10, 4 * lcg01(&rng)));
        c.max_trail_px = (oi_real)(lcg01(&rng) < 0.3 ? 0 : 0.5 + 10 * lcg01(&rng));
        memset(&in, 0, sizeof in);
        in.flux_w_m2 = (oi_real)pow(10, -18 + 8 * lcg01(&rng));
        in.background_w_m2_sr = (oi_real)(lcg01(&rng) < 0.5 ? 0 : pow(10, -8 + 6 * lcg01(&rng)));
        in.rate_rad_s = (oi_real)pow(10, -7 + 6 * lcg01(&rng));
        check_int(OI_OK, oi_expose(&c, &in, NULL, &got), "status");
        /* the allowed times */
        px_s = (double)in.rate_rad_s / 1e-5;
        n = nt;
        if (c.max_trail_px > 0) {
            n = 0;
            while (n < nt && (oi_real)px_s * c.times_s[n] <= c.max_trail_px) n++;
            if (n == 0) {
                n = 1;
                want_flags |= OI_FLAG_TRAILED;
            }
        }
        for (gi = 0; gi < ng; gi++) {
            for (ti = 0; ti < n; ti++) {
                oi_camera one = c;
                one.n_times = 1;
                one.times_s[0] = c.times_s[ti];
                one.n_gains = 1;
                one.gains[0] = c.gains[gi];
                one.read_noise_e[0] = c.read_noise_e[gi];
                one.max_trail_px = 0;
                check_int(OI_OK, oi_expose(&one, &in, NULL, &e), "one setting");
                if (e.fill < 1 && e.fill <= 0.5 && (!found || e.snr > best)) {
                    found = 1;
                    best = e.snr;
                    bt = ti;
                    bg = gi;
                }
                if ((gi == 0 && ti == 0) || e.fill < low) {
                    low = e.fill;
                    low_bg_full = !(e.background_e < e.saturation_e);
                    lt = ti;
                    lg = gi;
                }
                if (gi == ng - 1 && e.snr > maxsnr) maxsnr = e.snr;
            }
        }
        faint = !(maxsnr >= 5);
        if (!found) {
            bt = lt;
            bg = lg;
            /* a full well: the target's, unless the background alone fills
             * it or the target is too faint (include/orbillum.h) */
            if (!(low < 1))
                want_flags |= faint || low_bg_full ? OI_FLAG_BACKGROUND_SATURATED : OI_FLAG_SATURATED;
        }
        if (faint) want_flags |= OI_FLAG_TOO_FAINT;
        check_int(bt, got.time_index, "time index");
        check_int(bg, got.gain_index, "gain index");
        check_int((long)want_flags, (long)got.flags, "flags");
        if (want_flags & OI_FLAG_TRAILED) n_trailed++;
        if (want_flags & OI_FLAG_SATURATED) n_sat++;
        if (want_flags & OI_FLAG_TOO_FAINT) n_faint++;
        if (found && bt < n - 1) n_inner++; /* the best SNR before the longest time */
    }
    /* the cases cover every branch */
    assert_true(n_trailed > 50 && n_sat > 50 && n_faint > 50 && n_inner > 50);
}

/* The cap: 100 pixels/s and a 3-pixel cap allow the times up to 0.03 s; at
 * 1000 pixels/s even 0.01 s trails 10 pixels: the shortest, flagged. */
static void test_trail_cap(void **state)
{
    oi_camera c = one_setting(1.0, 0.25);
    oi_expose_in in;
    oi_exposure out;
    int i;
    (void)state;
    c.n_times = 5;
    for (i = 0; i < 5; i++) c.times_s[i] = (oi_real)(0.01 * pow(3.0, i));
    c.max_trail_px = 3;
    c.full_well_e = (oi_real)1e9;
    memset(&in, 0, sizeof in);
    in.flux_w_m2 = (oi_real)1e-9;
    in.rate_rad_s = (oi_real)(100 * 1e-5);
    check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "status");
    assert_true(out.trail_px <= 3);
    assert_false(out.flags & OI_FLAG_TRAILED);
    assert_true(out.time_index <= 1);
    in.rate_rad_s = (oi_real)(1000 * 1e-5);
    check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "status");
    check_int(0, out.time_index, "shortest");
    assert_true(out.flags & OI_FLAG_TRAILED);
    check_rel(10.0, out.trail_px, 1e-5, "trail");
    c.max_trail_px = 0; /* no cap */
    check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "status");
    assert_false(out.flags & OI_FLAG_TRAILED);
}

/* The scene's rate: |(v_t - v_o) x b| / range; motion along the line of
 * sight does not trail. */
static void test_scene_rate(void **state)
{
    oi_camera c = one_setting(1.0, 0.25);
    oi_scene s;
    oi_illum il;
    oi_exposure out;
    (void)state;
    memset(&il, 0, sizeof il);
    il.flux_obs = (oi_real)1e-14;
    il.e_sun = 1361;
    il.shadow.region = OI_SHADOW_LIT;
    oi_scene_defaults(&s);
    set3(s.sun_km, 0, 1.496e8, 0);
    set3(s.observer_km, 0, 0, 42164);
    set3(s.target_km, 10, 0, 42164); /* 10 km along +x */
    s.has_observer = 1;
    set3(s.target_vel_km_s, 3.0, 0.002, 0);   /* 2 m/s across, 3 km/s along */
    set3(s.observer_vel_km_s, 0, -0.001, 0.004); /* 1 m/s, 4 m/s across */
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, NULL, &out), "status");
    check_rel(sqrt(0.003 * 0.003 + 0.004 * 0.004) / 10.0, out.rate_rad_s, 1e-5, "rate");
    check_rel(out.rate_rad_s * 1.0 / 1e-5, out.trail_px, 1e-5, "trail px");
    set3(s.target_vel_km_s, 3.0, 0, 0);
    set3(s.observer_vel_km_s, 0, 0, 0);
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, NULL, &out), "status");
    check_rel(0.0, out.rate_rad_s, 0, "along the line of sight");
    check_rel(1.0, out.trail_factor, 0, "no trail");
}

static void test_motion_hostile(void **state)
{
    oi_camera c = one_setting(1.0, 0.25);
    oi_expose_in in;
    oi_exposure out;
    oi_scene s;
    oi_illum il;
    (void)state;
    memset(&in, 0, sizeof in);
    in.flux_w_m2 = (oi_real)1e-14;
    in.rate_rad_s = (oi_real)-1e-6;
    check_int(OI_ERR_INPUT, oi_expose(&c, &in, NULL, &out), "negative rate");
    in.rate_rad_s = (oi_real)NAN;
    check_int(OI_ERR_NONFINITE, oi_expose(&c, &in, NULL, &out), "NaN rate");
    in.rate_rad_s = (oi_real)2e3;
    check_int(OI_ERR_INPUT, oi_expose(&c, &in, NULL, &out), "rate too high");
    check_rel(0.0, out.exposure_s + out.trail_px + out.trail_factor, 0, "zeroed");
    in.rate_rad_s = 0;
    c.max_trail_px = -1;
    check_int(OI_ERR_CAMERA, oi_expose(&c, &in, NULL, &out), "negative cap");
    c.max_trail_px = (oi_real)NAN;
    check_int(OI_ERR_CAMERA, oi_expose(&c, &in, NULL, &out), "NaN cap");
    c.max_trail_px = 0;
    memset(&il, 0, sizeof il);
    il.flux_obs = (oi_real)1e-14;
    oi_scene_defaults(&s);
    set3(s.sun_km, 0, 1.496e8, 0);
    set3(s.observer_km, 0, 0, 42164);
    set3(s.target_km, 10, 0, 42164);
    s.has_observer = 1;
    set3(s.target_vel_km_s, (double)NAN, 0, 0);
    check_int(OI_ERR_NONFINITE, oi_expose_scene(&c, &s, &il, NULL, NULL, &out), "NaN velocity");
    set3(s.target_vel_km_s, 0, 0, 0);
    set3(s.observer_vel_km_s, 0, 4e5, 0);
    check_int(OI_ERR_INPUT, oi_expose_scene(&c, &s, &il, NULL, NULL, &out), "faster than light");
    check_rel(0.0, out.exposure_s, 0, "zeroed");
    /* 300 km/s across at 1 m: clamped to 1e3 rad/s, not an error */
    set3(s.observer_vel_km_s, 0, 300, 0);
    set3(s.target_km, 0.001, 0, 42164);
    check_int(OI_OK, oi_expose_scene(&c, &s, &il, NULL, NULL, &out), "fast");
    check_rel(1e3, out.rate_rad_s, 0, "clamped");
}
#endif

int main(void)
{
#ifndef OI_NO_EXPOSURE
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_trail_factor_quadrature),
        cmocka_unit_test(test_at_rest),
        cmocka_unit_test(test_moving_choice_bruteforce),
        cmocka_unit_test(test_trail_cap),
        cmocka_unit_test(test_scene_rate),
        cmocka_unit_test(test_motion_hostile),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
#else
    printf("skip test_motion: built with OI_NO_EXPOSURE\n");
    return 0;
#endif
}
