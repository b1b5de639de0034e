/* SPDX-License-Identifier: MIT */
/*
 * test_detect.c: the detection rule of a camera (detect_false_alarm,
 * detect_probability; docs/camera.md, "Detection"). The threshold against
 * the normal quantile found by bisection; the false-alarm and detection
 * rates against a Monte Carlo of noisy pixels (Gaussian noise, the rule's
 * model, and Poisson photon noise with Gaussian read noise at high counts),
 * within 4 binomial standard deviations; the margin; too_faint as "not
 * detectable at the longest exposure"; the SNR rule kept when the fields
 * are 0; hostile camera fields.
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
#define REL_TOL 2e-5
#else
#define REL_TOL 1e-9
#endif

#ifndef OI_NO_EXPOSURE
static const double PI = 3.14159265358979323846;
static uint64_t rng = 20261202u;

/* A one-setting camera: 1 e-/s of signal per 1e-19 W/m^2 ... the rates are
 * flux * 1e19 * 0.25 e-/s (A = 1 m^2, k = 1e19 e-/J, peak 0.25), t = 1 s,
 * read noise 5 e-, dark current giving the background. */
static oi_camera camera_of(double p_fa, double p_d, double dark)
{
    oi_camera c = oi_test_camera("detect");
    c.dark_current_e_s = (oi_real)dark;
    c.detect_false_alarm = (oi_real)p_fa;
    c.detect_probability = (oi_real)p_d;
    return c;
}

static oi_exposure expose_signal(const oi_camera *c, double signal_e)
{
    oi_expose_in in;
    oi_exposure out;
    memset(&in, 0, sizeof in);
    in.flux_w_m2 = (oi_real)(signal_e / (1e19 * 0.25));
    check_int(OI_OK, oi_expose(c, &in, NULL, &out), "status");
    return out;
}

/* z with 1 - Phi(z) = tail, by bisection on erfc. */
static double quantile_upper(double tail)
{
    double lo = 0, hi = 40;
    int i;
    for (i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        if (0.5 * erfc(mid / sqrt(2.0)) > tail) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
}

static double gauss(void)
{
    double u1 = lcg01(&rng), u2 = lcg01(&rng);
    if (u1 < 1e-300) u1 = 1e-300;
    return sqrt(-2.0 * log(u1)) * cos(2.0 * PI * u2);
}

/* Poisson deviate of mean m >= 30: the normal approximation would be the
 * model itself, so a true Poisson by inversion in chunks of 30. */
static double poisson(double m)
{
    double k = 0;
    while (m > 0) {
        double mu = m > 30 ? 30 : m, p = exp(-mu), cdf = p, u = lcg01(&rng);
        int j = 0;
        while (u > cdf && j < 1000) {
            j++;
            p *= mu / j;
            cdf += p;
        }
        k += j;
        m -= mu;
    }
    return k;
}

/* With detect_probability 0.5 the smallest detectable signal is the
 * threshold itself: k sqrt(b + rn^2), k the upper quantile of the false-
 * alarm probability. */
static void test_threshold_is_the_quantile(void **state)
{
    const double pfa[] = {0.3, 1e-3, 1e-6, 1e-9, 1e-15};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof pfa / sizeof pfa[0]; i++) {
        oi_camera c = camera_of(pfa[i], 0.5, 100.0);
        oi_exposure out = expose_signal(&c, 50.0);
        double want = quantile_upper(pfa[i]) * sqrt(100.0 + 25.0);
        check_rel(want, out.signal_min_e, REL_TOL * 100, "threshold");
        check_rel(2.5 * log10(50.0 / want), out.detect_margin_mag, 1e-5, "margin");
    }
}

/* False alarms and detections against noisy frames: N pixels of background
 * only above the threshold, N target pixels at the smallest detectable
 * signal for P_d = 0.9 and at margins -0.5 and +0.3 mag. */
static void check_rate(long hits, long n, double p, const char *what)
{
    double sd = sqrt(n * p * (1 - p));
    if (fabs((double)hits - n * p) > 4 * sd + 1) {
        print_error("%s: %ld of %ld, want %.1f +- %.1f (4 sd)\n", what, hits, n, n * p, 4 * sd);
        fail();
    }
}

static void monte_carlo(double bkg, int poisson_noise)
{
    const long n = 200000;
    const double rn = 5.0, pfa = 1e-3, c = bkg + rn * rn;
    oi_camera c50 = camera_of(pfa, 0.5, bkg), c90 = camera_of(pfa, 0.9, bkg);
    double thr = expose_signal(&c50, 1.0).signal_min_e;
    double smin = expose_signal(&c90, 1.0).signal_min_e;
    const double margins[] = {0.0, -0.5, 0.3};
    long i, hits = 0;
    size_t m;
    for (i = 0; i < n; i++) {
        double x = poisson_noise ? poisson(bkg) - bkg + rn * gauss() : sqrt(c) * gauss();
        if (x > thr) hits++;
    }
    check_rate(hits, n, pfa, "false alarms");
    for (m = 0; m < sizeof margins / sizeof margins[0]; m++) {
        double s = smin * pow(10.0, 0.4 * margins[m]);
        double p = 0.5 * erfc(-(s - thr) / sqrt(2.0 * (s + c)));
        oi_exposure out = expose_signal(&c90, s);
        if (m == 0) check_close(0.9, p, 1e-6, 0, "P_d at the smallest signal");
        check_close(margins[m], out.detect_margin_mag, 1e-4, 0, "margin");
        hits = 0;
        for (i = 0; i < n; i++) {
            double x = poisson_noise ? poisson(s + bkg) - bkg + rn * gauss()
                                     : s + sqrt(s + c) * gauss();
            if (x > thr) hits++;
        }
        check_rate(hits, n, p, "detections");
    }
}

static void test_monte_carlo_gaussian(void **state)
{
    (void)state;
    monte_carlo(400.0, 0);
}

static void test_monte_carlo_poisson(void **state)
{
    (void)state;
    monte_carlo(3000.0, 1);
}

/* too_faint: not detectable at the longest exposure (and highest gain). */
static void test_too_faint_is_not_detectable(void **state)
{
    oi_camera one = camera_of(1e-6, 0.9, 100.0), c;
    double smin = expose_signal(&one, 1.0).signal_min_e;
    oi_exposure out;
    (void)state;
    c = one;
    c.n_times = 3;
    c.times_s[0] = (oi_real)0.01;
    c.times_s[1] = (oi_real)0.1;
    c.times_s[2] = 1;
    out = expose_signal(&c, smin * 1.01);
    assert_false(out.flags & OI_FLAG_TOO_FAINT);
    out = expose_signal(&c, smin * 0.99);
    assert_true(out.flags & OI_FLAG_TOO_FAINT);
    assert_true(out.detect_margin_mag < 0);
    /* a moving target: detectable at an allowed time is enough */
    {
        oi_expose_in in;
        memset(&in, 0, sizeof in);
        in.flux_w_m2 = (oi_real)(smin * 1.01 / (1e19 * 0.25));
        in.rate_rad_s = (oi_real)1e-12;
        check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "moving");
        assert_false(out.flags & OI_FLAG_TOO_FAINT);
        in.flux_w_m2 = (oi_real)(smin * 0.99 / (1e19 * 0.25));
        check_int(OI_OK, oi_expose(&c, &in, NULL, &out), "moving faint");
        assert_true(out.flags & OI_FLAG_TOO_FAINT);
    }
}

/* Fields 0: the SNR rule, signal_min_e from snr = snr_min, and no signal
 * gives OI_DETECT_MARGIN_NONE. */
static void test_snr_rule(void **state)
{
    oi_camera c = camera_of(0, 0, 100.0);
    oi_exposure out = expose_signal(&c, 80.0);
    double cc = 125.0, want = 12.5 + 5.0 * sqrt(6.25 + cc);
    (void)state;
    check_rel(want, out.signal_min_e, REL_TOL * 10, "SNR rule signal");
    check_rel(2.5 * log10(80.0 / want), out.detect_margin_mag, 1e-5, "margin");
    assert_true((out.snr >= 5) == (out.detect_margin_mag >= 0));
    out = expose_signal(&c, 0.0);
    check_rel(OI_DETECT_MARGIN_NONE, out.detect_margin_mag, 0, "no signal");
}

static void test_detect_hostile(void **state)
{
    const double bad_fa[] = {0.5, 0.7, 1e-16, -1e-3, (double)NAN};
    const double bad_pd[] = {0.4, 1.0, -0.5, (double)NAN};
    oi_expose_in in;
    oi_exposure out;
    size_t i;
    (void)state;
    memset(&in, 0, sizeof in);
    for (i = 0; i < sizeof bad_fa / sizeof bad_fa[0]; i++) {
        oi_camera c = camera_of(bad_fa[i], 0.9, 1.0);
        check_int(OI_ERR_CAMERA, oi_expose(&c, &in, NULL, &out), "false alarm");
        check_rel(0.0, out.signal_min_e, 0, "zeroed");
    }
    for (i = 0; i < sizeof bad_pd / sizeof bad_pd[0]; i++) {
        oi_camera c = camera_of(1e-3, bad_pd[i], 1.0);
        check_int(OI_ERR_CAMERA, oi_expose(&c, &in, NULL, &out), "probability");
    }
}
#endif

int main(void)
{
#ifndef OI_NO_EXPOSURE
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_threshold_is_the_quantile),
        cmocka_unit_test(test_monte_carlo_gaussian),
        cmocka_unit_test(test_monte_carlo_poisson),
        cmocka_unit_test(test_too_faint_is_not_detectable),
        cmocka_unit_test(test_snr_rule),
        cmocka_unit_test(test_detect_hostile),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
#else
    printf("skip test_detect: built with OI_NO_EXPOSURE\n");
    return 0;
#endif
}
