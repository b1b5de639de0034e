/* SPDX-License-Identifier: MIT */
/* test_flag_rules.c: the exposure flags keep the meanings include/orbillum.h
 * gives them ("Flags with one meaning each"): no result holds two flags the
 * definitions exclude, over random photometric inputs (oi_expose, at rest
 * and moving, both detection rules) and random scenes (oi_expose_scene:
 * lit, eclipsed, occulted, the Earth in the field); and the cases a user found
 * (a full well of the Earth's light called "saturated", SATURATED with
 * TOO_FAINT) give the flags their definitions say. */
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

#ifndef OI_NO_EXPOSURE
#define RE 6378.137
#define AU 149597870.7

static long violations;

/* The rules of one result; what names the case in a message. */
static void check_rules(const oi_exposure *e, const char *what, long k)
{
    const unsigned f = e->flags;
    const char *bad = NULL;
    if ((f & OI_FLAG_SATURATED) && (f & OI_FLAG_TOO_FAINT)) bad = "saturated+too_faint";
    else if ((f & OI_FLAG_SATURATED) && (f & OI_FLAG_BACKGROUND_SATURATED))
        bad = "saturated+background_saturated";
    else if ((f & OI_FLAG_SATURATED) && (f & OI_FLAG_OCCULTED)) bad = "saturated+occulted";
    else if ((f & OI_FLAG_ECLIPSED) && (f & OI_FLAG_PENUMBRA)) bad = "eclipsed+penumbra";
    else if ((f & OI_FLAG_OCCULTED) && !(f & OI_FLAG_TOO_FAINT)) bad = "occulted without too_faint";
    else if ((f & (OI_FLAG_SATURATED | OI_FLAG_BACKGROUND_SATURATED)) && !(e->fill >= 1))
        bad = "a saturated flag with fill < 1";
    else if (!(f & (OI_FLAG_SATURATED | OI_FLAG_BACKGROUND_SATURATED)) && e->fill >= 1)
        bad = "fill >= 1 without a saturated flag";
    else if ((f & OI_FLAG_SATURATED) && !(e->background_e < e->saturation_e))
        bad = "saturated with the background alone filling the well";
    else if (e->signal_e == 0 && !(f & OI_FLAG_TOO_FAINT)) bad = "no signal without too_faint";
    if (bad != NULL) {
        if (violations < 10)
            printf("# %s %ld: %s (flags %u, fill %.6g, background_e %.6g, saturation_e %.6g)\n",
                   what, k, bad, f, (double)e->fill, (double)e->background_e,
                   (double)e->saturation_e);
        violations++;
    }
}

/* A random valid camera: a built-in one with its times, gains, well and
 * detection rule varied. */
static oi_camera random_camera(uint64_t *rng)
{
    oi_camera c = *oi_camera_builtin((int)(lcg01(rng) * 2));
    int i;
    double t = pow(10, -5 + 3 * lcg01(rng));
    c.n_times = 1 + (int)(lcg01(rng) * 6);
    for (i = 0; i < c.n_times; i++) {
        c.times_s[i] = (oi_real)t;
        t *= 1.01 + 9 * lcg01(rng);
    }
    c.n_gains = 1 + (int)(lcg01(rng) * 3);
    for (i = 0; i < c.n_gains; i++) {
        c.gains[i] = (oi_real)(1 + i + lcg01(rng) * 0.5);
        c.read_noise_e[i] = (oi_real)(20 * lcg01(rng));
    }
    c.full_well_e = (oi_real)pow(10, 6 * lcg01(rng) + (lcg01(rng) < 0.1 ? 0 : 2));
    c.dark_current_e_s = (oi_real)(lcg01(rng) < 0.3 ? 0 : pow(10, 6 * lcg01(rng) - 2));
    if (lcg01(rng) < 0.3) {
        c.detect_false_alarm = (oi_real)pow(10, -12 * lcg01(rng) - 1);
        c.detect_probability = (oi_real)(lcg01(rng) < 0.5 ? 0 : 0.5 + 0.49 * lcg01(rng));
    }
    return c;
}

static void test_random_exposures(void **state)
{
    uint64_t rng = 20261207u;
    long k, n_sat = 0, n_bsat = 0, n_faint = 0;
    (void)state;
    violations = 0;
    for (k = 0; k < 40000; k++) {
        oi_camera c = random_camera(&rng);
        oi_expose_in in;
        oi_expose_goal g;
        oi_exposure e;
        memset(&in, 0, sizeof in);
        memset(&g, 0, sizeof g);
        in.flux_w_m2 = (oi_real)(lcg01(&rng) < 0.05 ? 0 : pow(10, -20 + 24 * lcg01(&rng)));
        in.background_w_m2_sr = (oi_real)(lcg01(&rng) < 0.3 ? 0 : pow(10, -10 + 17 * lcg01(&rng)));
        in.rate_rad_s = (oi_real)(lcg01(&rng) < 0.5 ? 0 : pow(10, -7 + 6 * lcg01(&rng)));
        in.flags = lcg01(&rng) < 0.1 ? OI_FLAG_OCCULTED : 0u;
        if (in.flags) in.flux_w_m2 = 0; /* as oi_expose_scene gives it */
        g.snr_min = (oi_real)(lcg01(&rng) < 0.5 ? 0 : pow(10, -1 + 4 * lcg01(&rng)));
        g.fill = (oi_real)(lcg01(&rng) < 0.5 ? 0 : 0.01 + 0.99 * lcg01(&rng));
        check_int(OI_OK, oi_expose(&c, &in, &g, &e), "oi_expose status");
        check_rules(&e, "oi_expose", k);
        n_sat += (e.flags & OI_FLAG_SATURATED) != 0u;
        n_bsat += (e.flags & OI_FLAG_BACKGROUND_SATURATED) != 0u;
        n_faint += (e.flags & OI_FLAG_TOO_FAINT) != 0u;
    }
    printf("# %ld saturated, %ld background_saturated, %ld too_faint of 40000\n", n_sat, n_bsat,
           n_faint);
    assert_true(n_sat > 500 && n_bsat > 500 && n_faint > 500);
    check_int(0, violations, "results breaking the flag rules");
}

/* Random scenes: the target from 300 km to GEO, lit or in the shadow, the
 * observer 1 to 3,000 km away (occulted by the Earth, the Earth in the
 * field), both built-in cameras. */
static void test_random_scenes(void **state)
{
    uint64_t rng = 20261208u;
    long k, n_occ = 0, n_ecl = 0, n_fov = 0, n_bsat = 0;
    (void)state;
    violations = 0;
    for (k = 0; k < 20000; k++) {
        oi_scene s;
        oi_illum il;
        oi_exposure e;
        double us[3], ut[3], uo[3], r = RE + 300.0 + 36000.0 * pow(lcg01(&rng), 2.0);
        double d = pow(10, 3.5 * lcg01(&rng));
        int i, st;
        oi_scene_defaults(&s);
        s.terms = OI_TERM_SUN | OI_TERM_EARTH;
        random_unit(&rng, us);
        random_unit(&rng, ut);
        random_unit(&rng, uo);
        if (lcg01(&rng) < 0.3) /* near the anti-Sun axis: eclipsed or penumbra */
            for (i = 0; i < 3; i++) ut[i] = -us[i] + 0.1 * ut[i];
        {
            const double n = sqrt(ut[0] * ut[0] + ut[1] * ut[1] + ut[2] * ut[2]);
            for (i = 0; i < 3; i++) ut[i] /= n;
        }
        for (i = 0; i < 3; i++) {
            s.sun_km[i] = (oi_real)(AU * us[i]);
            s.target_km[i] = (oi_real)(r * ut[i]);
            s.observer_km[i] = (oi_real)(r * ut[i] + d * uo[i]);
        }
        if (lcg01(&rng) < 0.2) /* across the Earth: occulted */
            for (i = 0; i < 3; i++) s.observer_km[i] = (oi_real)(-(RE + 500.0) * ut[i] + 300.0 * uo[i]);
        s.has_observer = 1;
        if (oi_illuminate(&s, NULL, &il) < 0) continue;
        st = oi_expose_scene(oi_camera_builtin((int)(k & 1)), &s, &il, NULL, NULL, &e);
        if (st < 0) continue;
        check_rules(&e, "oi_expose_scene", k);
        n_occ += (e.flags & OI_FLAG_OCCULTED) != 0u;
        n_ecl += (e.flags & OI_FLAG_ECLIPSED) != 0u;
        n_fov += (e.flags & OI_FLAG_EARTH_IN_FOV) != 0u;
        n_bsat += (e.flags & OI_FLAG_BACKGROUND_SATURATED) != 0u;
    }
    printf("# %ld occulted, %ld eclipsed, %ld earth_in_fov, %ld background_saturated\n", n_occ,
           n_ecl, n_fov, n_bsat);
    assert_true(n_occ > 100 && n_ecl > 100 && n_fov > 100 && n_bsat > 100);
    check_int(0, violations, "scenes breaking the flag rules");
}

/* The sunlit Earth fills a telescope's field: its light alone fills the
 * well at the shortest time, a faint target's does not. Before the rule:
 * "saturated", with an SNR below the goal. */
static void test_earth_fills_the_well(void **state)
{
    const oi_camera *c = oi_camera_find("telescope-15cm");
    oi_expose_in in;
    oi_exposure e;
    (void)state;
    assert_non_null(c);
    memset(&in, 0, sizeof in);
    in.flux_w_m2 = (oi_real)3e-10;       /* about magnitude 4.9 */
    in.background_w_m2_sr = (oi_real)40; /* a sunlit Earth of albedo 0.3 */
    in.flags = OI_FLAG_EARTH_IN_FOV;
    check_int(OI_OK, oi_expose(c, &in, NULL, &e), "status");
    assert_true(e.background_e >= e.saturation_e);
    check_int((long)(OI_FLAG_EARTH_IN_FOV | OI_FLAG_BACKGROUND_SATURATED), (long)e.flags, "flags");
}

/* A target whose light fills the well at the only time but whose SNR
 * there (the well not counted) is below a high goal: too faint, and the
 * full well is then no target's saturation. Before the rule: both. */
static void test_too_faint_never_saturated(void **state)
{
    oi_camera c = *oi_camera_builtin(0);
    oi_expose_in in;
    oi_expose_goal g;
    oi_exposure e;
    (void)state;
    c.n_times = 1;
    c.times_s[0] = (oi_real)1e-3;
    c.n_gains = 1;
    c.gains[0] = 1;
    c.read_noise_e[0] = 13;
    memset(&in, 0, sizeof in);
    memset(&g, 0, sizeof g);
    g.snr_min = (oi_real)1e3; /* beyond any SNR a 13,500 e- well can give */
    in.flux_w_m2 = (oi_real)1e-6;
    check_int(OI_OK, oi_expose(&c, &in, &g, &e), "status");
    assert_true(e.fill >= 1);
    assert_true(e.background_e < e.saturation_e);
    check_int((long)(OI_FLAG_TOO_FAINT | OI_FLAG_BACKGROUND_SATURATED), (long)e.flags, "flags");
    /* the same target with the default goal: detected, and its light is
     * what fills the well */
    check_int(OI_OK, oi_expose(&c, &in, NULL, &e), "status");
    check_int((long)OI_FLAG_SATURATED, (long)e.flags, "flags, default goal");
}

/* No signal is never detected, whatever the detection rule: a camera
 * without noise at all (no read noise, no dark current, no background). */
static void test_no_signal_too_faint(void **state)
{
    oi_camera c = *oi_camera_builtin(0);
    oi_expose_in in;
    oi_exposure e;
    int i;
    (void)state;
    c.dark_current_e_s = 0;
    for (i = 0; i < c.n_gains; i++) c.read_noise_e[i] = 0;
    c.detect_false_alarm = (oi_real)1e-6;
    memset(&in, 0, sizeof in);
    check_int(OI_OK, oi_expose(&c, &in, NULL, &e), "status");
    check_int((long)OI_FLAG_TOO_FAINT, (long)e.flags, "flags at rest");
    in.rate_rad_s = (oi_real)1e-3;
    check_int(OI_OK, oi_expose(&c, &in, NULL, &e), "status");
    assert_true(e.flags & OI_FLAG_TOO_FAINT);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_exposures),
        cmocka_unit_test(test_random_scenes),
        cmocka_unit_test(test_earth_fills_the_well),
        cmocka_unit_test(test_too_faint_never_saturated),
        cmocka_unit_test(test_no_signal_too_faint),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

#else
int main(void)
{
    printf("skip test_flag_rules: OI_NO_EXPOSURE removes the exposure and its flags\n");
    return 0;
}
#endif /* OI_NO_EXPOSURE */
