/* SPDX-License-Identifier: MIT */
/* test_occulters.c: the Moon as an occulter of the Sun (alone, and with the
 * Earth at once: three caps) and the Earth hiding the Moon's disc, through
 * oi_illuminate, against mpmath ring quadratures of the exact inputs
 * (ref_occulters.h from tests/ref/occulters.py, a different algorithm from
 * the library's Gauss-Bonnet and cap segments); the Moon's umbra, antumbra
 * and penumbra from a GEO and a lunar-orbit target; monotonicity along
 * passes through the Moon's shadow in both disc models, with and without the
 * atmosphere; the results never outside [0, 1] nor NaN at random
 * alignments; hostile inputs (the target inside the Moon, the Moon inside the
 * Earth, a NaN Moon) get their documented errors with zeroed outputs; the
 * flag OI_FLAG_MOON_SHADOW. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <float.h>
#include <math.h>
#include <string.h>

#include "orbillum.h"
#include "oi_test_util.h"

#ifndef OI_NO_MOON
#include "ref_occulters.h"

/* Tolerances (absolute, on fractions). Double: 1e-9, the bound
 * (measured worst: see docs/shadow.md section 6). Single: the fraction
 * changes by about 1/(2 r_sun) ~ 1e2 per radian of separation, and the
 * separation of two directions formed from float positions at ~4e5 km
 * carries ~1e-7 rad: 1e-5 (the Earth-only bound is 3e-5). */
#ifdef OI_SINGLE_PRECISION
#define FRACTION_TOL 3e-5
#else
#define FRACTION_TOL 1e-9
#endif

/* The limb-darkened fraction with both discs on the Sun: a ring quadrature
 * of its own (8-point Gauss-Legendre panels between the rings where the
 * integrand has kinks), measured 2.6e-8 in double (docs/shadow.md section 9);
 * single precision as the other fractions. */
#ifdef OI_SINGLE_PRECISION
#define BOTH_LD_TOL FRACTION_TOL
#else
#define BOTH_LD_TOL 1e-7
#endif

/* The Moon's visible disc behind the Earth's limb seen from LEO: in single
 * precision the limb's apparent radius has condition tan r_e = 2.2 w.r.t. the
 * float distance, so with the separation it carries ~2.5e-7 rad, times the
 * slope 1/(2 r_moon) = 110 per radian: 3e-5; 1e-4 allowed. */
#ifdef OI_SINGLE_PRECISION
#define VISIBLE_TOL 1e-4
#else
#define VISIBLE_TOL 1e-9
#endif

/* Monotonicity along passes: rounding only (a few epsilon), and in single
 * precision for the lunar-orbit pass the resolution of its float positions:
 * 0.016 km (half an ulp at 384400 km) over 1837 km, times the fraction's
 * slope 1/(2 r_sun) ~ 1e2 per radian: 9e-4. */
#ifdef OI_SINGLE_PRECISION
#define MONO_TOL (4 * (double)FLT_EPSILON)
#define MONO_TOL_LUNAR 2e-3
#else
#define MONO_TOL (4 * DBL_EPSILON)
#define MONO_TOL_LUNAR (4 * DBL_EPSILON)
#endif

/* A computed result: OI_OK, or a warning (OI_WARN_TABLE_RANGE in a build
 * without the earthshine table). */
static void check_ok(int st, const char *what)
{
    if (st < 0) check_int(OI_OK, st, what);
}

static void scene_of(oi_scene *s, const double sun[3], const double moon[3],
                     const double target[3], unsigned terms)
{
    oi_scene_defaults(s);
    set3(s->sun_km, sun[0], sun[1], sun[2]);
    set3(s->moon_km, moon[0], moon[1], moon[2]);
    set3(s->target_km, target[0], target[1], target[2]);
    s->terms = terms;
    s->has_moon = 1;
}

static const oi_model no_atm = {0, 0, 0, 0, 0, 0, 0, 0, 0, 1, NULL, NULL, 0, NULL};

/* The visible fraction of the Sun with the Moon (and the Earth) in front,
 * and the Moon's own share, against the ring quadrature; whatever the terms
 * (the Moon's position is given by has_moon). */
static void test_moon_sun_vs_mpmath(void **state)
{
    size_t i, n = sizeof ref_moon_sun / sizeof ref_moon_sun[0];
    double worst = 0, worst_ld = 0, worst_both = 0;
    (void)state;
    for (i = 0; i < n; ++i) {
        const ref_moon_sun_row *r = &ref_moon_sun[i];
        oi_scene s;
        oi_illum o;
        int st;
        unsigned terms;
        for (terms = OI_TERM_SUN; terms <= OI_TERM_SUN + OI_TERM_EARTH; terms += OI_TERM_EARTH) {
            scene_of(&s, r->sun, r->moon, r->target, terms);
            st = oi_illuminate(&s, &no_atm, &o);
            check_ok(st, r->label);
            check_close(r->fraction, (double)o.shadow.fraction, FRACTION_TOL, 0, r->label);
            check_close(r->moon_hidden, (double)o.sun_moon_hidden, FRACTION_TOL, 0, r->label);
            assert_true(o.shadow.fraction_atm == o.shadow.fraction);
            assert_true(o.shadow.fraction_ld >= (oi_real)0 && o.shadow.fraction_ld <= (oi_real)1);
#ifdef OI_NO_LIMB_DARKENING
            assert_true(o.shadow.fraction_ld == o.shadow.fraction);
#else
            if (!r->both) {
                /* one disc on the Sun: the limb-darkened fraction is exact */
                double e = fabs((double)o.shadow.fraction_ld - r->fraction_ld);
                check_close(r->fraction_ld, (double)o.shadow.fraction_ld, FRACTION_TOL, 0,
                            r->label);
                if (e > worst_ld) worst_ld = e;
            } else {
                /* both: the library's ring quadrature */
                double e = fabs((double)o.shadow.fraction_ld - r->fraction_ld);
                check_close(r->fraction_ld, (double)o.shadow.fraction_ld, BOTH_LD_TOL, 0,
                            r->label);
                if (e > worst_both) worst_both = e;
            }
#endif
            if (fabs((double)o.shadow.fraction - r->fraction) > worst)
                worst = fabs((double)o.shadow.fraction - r->fraction);
        }
    }
    print_message("moon-sun rows: %zu, worst |fraction - ref| = %.3g, |fraction_ld - ref| = %.3g "
                  "(one disc on the Sun), %.3g (both discs)\n", n, worst, worst_ld,
                  worst_both);
}

/* The Earth hiding the Moon's disc: fully, partly, not at all. */
static void test_moon_hidden_vs_mpmath(void **state)
{
    size_t i, n = sizeof ref_moon_hidden / sizeof ref_moon_hidden[0];
    double worst = 0;
    (void)state;
    for (i = 0; i < n; ++i) {
        const ref_moon_hidden_row *r = &ref_moon_hidden[i];
        oi_scene s;
        oi_illum o, lambert;
        oi_model lam = no_atm;
        int st;
        scene_of(&s, r->sun, r->moon, r->target, OI_TERM_ALL);
        st = oi_illuminate(&s, NULL, &o);
        check_ok(st, r->label);
        check_close(r->moon_visible, (double)o.moon_disc_visible, VISIBLE_TOL, 0, r->label);
        if (r->moon_visible == 0.0) assert_true(o.e_moon == (oi_real)0);
        if (r->moon_visible > 0.0) assert_true(o.e_moon > (oi_real)0);
        /* the Lambert Moon: e_moon = E a (R/d)^2 p(alpha) times both fractions */
        lam.moon_model = OI_MOON_LAMBERT;
        lam.moon_albedo = (oi_real)0.12;
        st = oi_illuminate(&s, &lam, &lambert);
        check_ok(st, r->label);
        {
            double ds = sqrt(pow(r->sun[0] - r->moon[0], 2) + pow(r->sun[1] - r->moon[1], 2) +
                             pow(r->sun[2] - r->moon[2], 2));
            double dt = sqrt(pow(r->target[0] - r->moon[0], 2) +
                             pow(r->target[1] - r->moon[1], 2) +
                             pow(r->target[2] - r->moon[2], 2));
            double c = ((r->sun[0] - r->moon[0]) * (r->target[0] - r->moon[0]) +
                        (r->sun[1] - r->moon[1]) * (r->target[1] - r->moon[1]) +
                        (r->sun[2] - r->moon[2]) * (r->target[2] - r->moon[2])) / (ds * dt);
            double alpha = acos(c < 1 ? c : 1);
            double p = 2.0 / (3.0 * 3.14159265358979323846) * ((3.14159265358979323846 - alpha) * cos(alpha) + sin(alpha));
            double e = 1361.0 * pow(149597870.7 / ds, 2) * 0.12 * pow(1737.4 / dt, 2) * p;
            double want = e * (double)lambert.moon_sun_fraction * r->moon_visible;
            check_close(want, (double)lambert.e_moon, e * VISIBLE_TOL, 1e-6, r->label);
        }
        if (fabs((double)o.moon_disc_visible - r->moon_visible) > worst)
            worst = fabs((double)o.moon_disc_visible - r->moon_visible);
    }
    print_message("moon-hidden rows: %zu, worst |visible - ref| = %.3g\n", n, worst);
}

/* The measured case: the Earth exactly between the target and the
 * Moon gives no moonlight at all; the Earth's shadow on the Moon stays. */
static void test_moon_behind_earth(void **state)
{
    oi_scene s;
    oi_illum o;
    (void)state;
    oi_scene_defaults(&s);
    set3(s.sun_km, 149597870.7, 0, 0);
    set3(s.moon_km, 0, 384400, 0);
    set3(s.target_km, 0, -7000, 0);
    s.terms = OI_TERM_ALL;
    assert_true(oi_illuminate(&s, NULL, &o) >= 0);
    assert_true(o.e_moon == (oi_real)0);
    assert_true(o.moon_disc_visible == (oi_real)0);
    assert_true(o.moon_sun_fraction == (oi_real)1);
    /* the Moon in the Earth's shadow: lit by the atmosphere's light only */
    set3(s.moon_km, -384400, 0, 0);
    set3(s.target_km, 0, 42164, 0);
    assert_true(oi_illuminate(&s, NULL, &o) >= 0);
    assert_true(o.moon_disc_visible == (oi_real)1);
    assert_true(o.moon_sun_fraction < (oi_real)1e-3);
}

/* Along a pass of a GEO target through the Moon's shadow (the antumbra and
 * the penumbra), and of a lunar-orbit target through the Moon's umbra: every
 * fraction is non-increasing towards the shadow's axis, in both disc models,
 * with and without the atmosphere. */
static void test_pass_monotonic(void **state)
{
    int model_i, k;
    (void)state;
    for (model_i = 0; model_i < 4; ++model_i) {
        oi_model m;
        double prev[3] = {2, 2, 2};
        memset(&m, 0, sizeof m);
#ifdef OI_NO_LIMB_DARKENING
        if (model_i & 1) continue; /* refused in this build */
#endif
        m.limb_darkening = model_i & 1 ? OI_LIMB_DARKENED : OI_LIMB_UNIFORM;
        m.no_atmosphere = model_i >> 1;
        for (k = -4000; k <= 0; k += 5) {
            oi_scene s;
            oi_illum o;
            oi_scene_defaults(&s);
            set3(s.sun_km, 149597870.7, 0, 0);
            set3(s.target_km, 0, 42164, 0);
            set3(s.moon_km, 384400, 42164 * (1 - 384400 / 149597870.7) + k, 0);
            s.has_moon = 1;
            assert_true(oi_illuminate(&s, &m, &o) >= 0);
            assert_true((double)o.shadow.fraction <= prev[0] + MONO_TOL);
            assert_true((double)o.shadow.fraction_ld <= prev[1] + MONO_TOL);
            assert_true((double)o.shadow.fraction_atm <= prev[2] + MONO_TOL);
            prev[0] = (double)o.shadow.fraction;
            prev[1] = (double)o.shadow.fraction_ld;
            prev[2] = (double)o.shadow.fraction_atm;
        }
        /* the antumbra's centre: 1 - (r_moon / r_sun)^2 to first order */
        assert_true(prev[0] > 0.04 && prev[0] < 0.07);
    }
    {
        /* lunar orbit, 100 km: the Sun sets behind the Moon's limb */
        double prev = 2;
        for (k = 0; k <= 1200; ++k) {
            oi_scene s;
            oi_illum o;
            double h = 1737.4 + 100, rm = asin(1737.4 / h), a = rm - 0.01 + 2e-5 * k;
            oi_scene_defaults(&s);
            set3(s.sun_km, 149597870.7, 0, 0);
            set3(s.moon_km, 0, 384400, 0);
            set3(s.target_km, -h * cos(a), 384400 + h * sin(a), 0);
            s.terms = OI_TERM_SUN;
            s.has_moon = 1;
            assert_true(oi_illuminate(&s, NULL, &o) >= 0);
            if (k > 0) assert_true((double)o.shadow.fraction >= prev - MONO_TOL_LUNAR);
            prev = (double)o.shadow.fraction;
            if (k == 0) assert_true(o.shadow.fraction == (oi_real)0 && o.e_sun == (oi_real)0);
        }
        assert_true(prev == 1.0);
    }
}

/* Random alignments of the Sun, the Moon and the Earth seen from targets
 * near the Moon's and the Earth's shadows: finite results in [0, 1], the
 * three-cap fraction below each one-occulter fraction. */
static void test_random_alignments(void **state)
{
    uint64_t seed = 12345;
    int i;
    (void)state;
    for (i = 0; i < 20000; ++i) {
        oi_scene s;
        oi_illum o;
        int st;
        double r = 6400 + 420000 * lcg01(&seed), th = 0.2 * (lcg01(&seed) - 0.5);
        double mz = 3000 * (lcg01(&seed) - 0.5), my = 3000 * (lcg01(&seed) - 0.5);
        oi_scene_defaults(&s);
        set3(s.sun_km, 149597870.7, 0, 0);
        set3(s.target_km, -r * cos(th), r * sin(th), 0);
        set3(s.moon_km, -r * cos(th) + 384400, r * sin(th) + my, mz);
        if (lcg01(&seed) < 0.5) set3(s.moon_km, -r * cos(th) - 384400, r * sin(th) + my, mz);
        s.terms = OI_TERM_ALL;
        st = oi_illuminate(&s, NULL, &o);
        if (st < 0) {
            check_int(OI_ERR_BELOW_SURFACE, st, "random alignment");
            continue;
        }
        assert_true(o.shadow.fraction >= (oi_real)0 && o.shadow.fraction <= (oi_real)1);
        assert_true(o.shadow.fraction_ld >= (oi_real)0 && o.shadow.fraction_ld <= (oi_real)1);
        assert_true(o.shadow.fraction_atm >= (oi_real)0 && o.shadow.fraction_atm <= (oi_real)1);
        assert_true(o.sun_moon_hidden >= (oi_real)0 && o.sun_moon_hidden <= (oi_real)1);
        assert_true(o.shadow.fraction <= (oi_real)1 - o.sun_moon_hidden + (oi_real)1e-6);
        assert_true(o.e_sun >= (oi_real)0 && o.e_moon >= (oi_real)0);
        assert_true(o.moon_disc_visible >= (oi_real)0 && o.moon_disc_visible <= (oi_real)1);
    }
}

static int all_zero(const oi_illum *o)
{
    static const oi_illum zero;
    return memcmp(o, &zero, sizeof zero) == 0;
}

/* Hostile inputs: documented errors, outputs zeroed. */
static void test_hostile(void **state)
{
    oi_scene s;
    oi_illum o;
    unsigned terms;
    (void)state;
    for (terms = OI_TERM_SUN; terms <= OI_TERM_ALL; terms = terms == OI_TERM_SUN ? OI_TERM_ALL : 99) {
        oi_scene_defaults(&s);
        set3(s.sun_km, 149597870.7, 0, 0);
        set3(s.target_km, 0, 384400 + 1000, 0);
        set3(s.moon_km, 0, 384400, 0);
        s.terms = terms;
        s.has_moon = 1;
        /* the target inside the Moon */
        assert_int_equal(oi_illuminate(&s, NULL, &o), OI_ERR_GEOMETRY);
        assert_true(all_zero(&o));
        /* just inside its surface */
        set3(s.target_km, 0, 384400 + 1737, 0);
        assert_int_equal(oi_illuminate(&s, NULL, &o), OI_ERR_GEOMETRY);
        assert_true(all_zero(&o));
        /* the Moon inside the Earth */
        set3(s.target_km, 0, 42164, 0);
        set3(s.moon_km, 0, 3000, 0);
        assert_int_equal(oi_illuminate(&s, NULL, &o), OI_ERR_BELOW_SURFACE);
        assert_true(all_zero(&o));
        /* a NaN or infinite Moon */
        set3(s.moon_km, NAN, 0, 0);
        assert_int_equal(oi_illuminate(&s, NULL, &o), OI_ERR_NONFINITE);
        assert_true(all_zero(&o));
        set3(s.moon_km, 0, 0, INFINITY);
        assert_int_equal(oi_illuminate(&s, NULL, &o), OI_ERR_NONFINITE);
        /* the Moon at the Earth's centre */
        set3(s.moon_km, 0, 0, 0);
        assert_int_equal(oi_illuminate(&s, NULL, &o), OI_ERR_ZERO_VECTOR);
    }
    /* without has_moon and without OI_TERM_MOON the Moon's position is not read */
    oi_scene_defaults(&s);
    set3(s.sun_km, 149597870.7, 0, 0);
    set3(s.target_km, 0, 42164, 0);
    set3(s.moon_km, NAN, 0, 0);
    s.terms = OI_TERM_SUN;
    assert_true(oi_illuminate(&s, NULL, &o) >= 0);
    assert_true(o.sun_moon_hidden == (oi_real)0);
}

#ifndef OI_NO_EXPOSURE
/* OI_FLAG_MOON_SHADOW from oi_expose_scene, and its name. */
static void test_flag(void **state)
{
    oi_scene s;
    oi_illum o;
    oi_exposure x;
    (void)state;
    assert_string_equal(oi_flag_name(OI_FLAG_MOON_SHADOW), "moon_shadow");
    oi_scene_defaults(&s);
    set3(s.sun_km, 149597870.7, 0, 0);
    set3(s.target_km, 0, 42164, 0);
    set3(s.moon_km, 384400, 42164 * (1 - 384400 / 149597870.7) + 1000, 0);
    set3(s.observer_km, 0, 42164, 10);
    s.has_observer = 1;
    s.has_moon = 1;
    assert_true(oi_illuminate(&s, NULL, &o) >= 0);
    assert_true(o.sun_moon_hidden > (oi_real)0.5);
    assert_int_equal(oi_expose_scene(oi_camera_builtin(0), &s, &o, NULL, NULL, &x), OI_OK);
    assert_true((x.flags & OI_FLAG_MOON_SHADOW) != 0u);
    assert_true((x.flags & (OI_FLAG_ECLIPSED | OI_FLAG_PENUMBRA)) == 0u);
    set3(s.moon_km, -384400, 0, 0);
    assert_true(oi_illuminate(&s, NULL, &o) >= 0);
    assert_int_equal(oi_expose_scene(oi_camera_builtin(0), &s, &o, NULL, NULL, &x), OI_OK);
    assert_true((x.flags & OI_FLAG_MOON_SHADOW) == 0u);
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_moon_sun_vs_mpmath),
        cmocka_unit_test(test_moon_hidden_vs_mpmath),
        cmocka_unit_test(test_moon_behind_earth),
        cmocka_unit_test(test_pass_monotonic),
        cmocka_unit_test(test_random_alignments),
        cmocka_unit_test(test_hostile),
#ifndef OI_NO_EXPOSURE
        cmocka_unit_test(test_flag),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
#else
#include <stdio.h>
int main(void)
{
    printf("skip test_occulters: OI_NO_MOON removes the Moon\n");
    return 0;
}
#endif
