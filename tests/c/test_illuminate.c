/* SPDX-License-Identifier: MIT */
/* test_illuminate.c: oi_illuminate and the magnitude functions against closed
 * forms written here independently of the library (Lambert sphere, inverse
 * square law, energy bookkeeping), rotation invariance, and every error path. */
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

static const double PI = 3.14159265358979323846;
static const double AU = 149597870.7;
static const double TSI = 1361.0;

/* Lambert phase function, written out here as the reference. */
static double phase_ref(double xi)
{
    return 2.0 / (3.0 * PI) * ((PI - xi) * cos(xi) + sin(xi));
}

/* Target 7000 km from the Earth on the +y axis, Sun on +x at 1 AU: theta = 90 deg,
 * fully lit; observer 100 km from the target towards the Sun. */
static oi_scene lit_scene(void)
{
    oi_scene s;
    oi_scene_defaults(&s);
    set3(s.sun_km, AU, 0, 0);
    set3(s.target_km, 0, 7000, 0);
    set3(s.observer_km, 100, 7000, 0);
    s.has_observer = 1;
    s.terms = OI_TERM_SUN;
    return s;
}

static void test_sun_term_inverse_square(void **state)
{
    oi_scene s = lit_scene();
    oi_illum out;
    double d;
    (void)state;
    assert_int_equal(oi_illuminate(&s, NULL, &out), OI_OK);
    d = sqrt(AU * AU + 7000.0 * 7000.0);
    check_rel(1.0, out.shadow.fraction, 0, "fraction lit");
    check_rel(TSI * (AU / d) * (AU / d), out.e_sun, REL_TOL, "e_sun");
    assert_true(out.e_earth == 0 && out.e_moon == 0);
    check_rel(PI / 2, out.earth_theta, REL_TOL, "theta");
    check_rel(7000.0 - 6378.137, out.earth_h_km, REL_TOL * 20, "h");
}

static void test_reflected_flux_closed_form(void **state)
{
    oi_scene s = lit_scene();
    oi_illum out;
    double e, phase, want;
    (void)state;
    s.target_radius_m = 2.0;
    s.target_albedo = 0.5;
    assert_int_equal(oi_illuminate(&s, NULL, &out), OI_OK);
    e = out.e_sun;
    /* observer direction (1,0,0) from the target, Sun direction (AU, -7000, 0) */
    phase = atan2(7000.0, AU);
    want = e * 0.5 * (2.0 / 100e3) * (2.0 / 100e3) * phase_ref(phase);
    check_rel(phase, out.phase_sun, 1e-6, "phase");
    check_rel(want, out.flux_sun, REL_TOL * 10, "flux_sun");
    check_rel(want, out.flux_obs, REL_TOL * 10, "flux_obs");
    check_rel(-26.74 - 2.5 * log10(want / TSI), out.mag_v, REL_TOL * 10, "mag");
}

static void test_lambert_earth_far_field(void **state)
{
    oi_scene s = lit_scene();
    oi_model m;
    oi_illum out;
    double r = 400000.0, theta = 1.0, x, e0;
    (void)state;
    memset(&m, 0, sizeof m);
    m.earth_model = OI_EARTH_LAMBERT;
    set3(s.target_km, r * cos(theta), r * sin(theta), 0);
    s.terms = OI_TERM_EARTH;
    s.has_observer = 0;
    s.earth_albedo = 0.3;
    assert_true(oi_illuminate(&s, &m, &out) >= 0);
    x = 6378.137 / r;
    e0 = TSI;
    check_rel(0.3 * e0 * x * x * phase_ref(theta), out.e_earth, REL_TOL * 10, "e_earth lambert");
    assert_true(out.e_sun == 0);
    /* direction: the nadir when psi = 0 */
    check_rel(-cos(theta), out.dir_earth[0], REL_TOL * 10, "dir x");
    check_rel(-sin(theta), out.dir_earth[1], REL_TOL * 10, "dir y");
}

#ifndef OI_NO_MOON
static void test_moon_lambert_and_phase_law(void **state)
{
    oi_scene s = lit_scene();
    oi_model m;
    oi_illum out;
    double dm = 384400.0, d_sm, d_tm, alpha, e_sm, want;
    (void)state;
    memset(&m, 0, sizeof m);
    m.moon_model = OI_MOON_LAMBERT;
    m.moon_albedo = 0.12;
    /* Moon at quadrature on +z, target on +y */
    set3(s.moon_km, 0, 0, dm);
    s.terms = OI_TERM_MOON;
    s.has_observer = 0;
    assert_int_equal(oi_illuminate(&s, &m, &out), OI_OK);
    d_sm = sqrt(AU * AU + dm * dm);
    d_tm = sqrt(7000.0 * 7000.0 + dm * dm);
    /* angle at the Moon between (sun - moon) and (target - moon) */
    {
        double a[3] = {AU, 0, -dm}, b[3] = {0, 7000, -dm};
        double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        alpha = acos(dot / (d_sm * d_tm));
    }
    e_sm = TSI * (AU / d_sm) * (AU / d_sm);
    want = e_sm * 0.12 * (1737.4 / d_tm) * (1737.4 / d_tm) * phase_ref(alpha);
    check_rel(1.0, out.moon_sun_fraction, 0, "moon lit");
    check_rel(want, out.e_moon, REL_TOL * 100, "e_moon lambert");

    /* the default phase law at full Moon: V = -12.73 at mean distance */
    memset(&m, 0, sizeof m);
    set3(s.sun_km, AU, 0, 0);
    set3(s.moon_km, -dm, 0, 10000.0); /* behind the Earth but off the shadow */
    set3(s.target_km, -7000.0 * 0.0, 0, 7000.0);
    assert_int_equal(oi_illuminate(&s, &m, &out), OI_OK);
    assert_true(out.e_moon > 0);
    /* magnitude of the Moon as seen from the target: near -12.7 */
    {
        double mag = -26.74 - 2.5 * log10(out.e_moon / TSI);
        assert_true(mag > -12.9 && mag < -12.4);
    }
}

/* The default phase law against its definition written out here: full Moon
 * V = -12.73 at 384,400 km and 1 AU, scaled by both inverse squares and
 * 10^(-0.4 (0.026 a + 4e-9 a^4)), a in degrees (Krisciunas & Schaefer 1991). */
static void test_moon_phase_law_irradiance(void **state)
{
    oi_scene s = lit_scene();
    oi_illum out;
    double dm = 384400.0, moon[3] = {60000.0, 300000.0, 200000.0}, tgt[3] = {0, 7000, 0};
    double sm[3], tm[3], d_sm, d_tm, ca, a_deg, law, want;
    int k;
    (void)state;
    (void)dm;
    set3(s.moon_km, moon[0], moon[1], moon[2]);
    s.terms = OI_TERM_MOON;
    s.has_observer = 0;
    assert_int_equal(oi_illuminate(&s, NULL, &out), OI_OK);
    for (k = 0; k < 3; k++) {
        sm[k] = (k == 0 ? AU : 0.0) - moon[k];
        tm[k] = tgt[k] - moon[k];
    }
    d_sm = sqrt(sm[0] * sm[0] + sm[1] * sm[1] + sm[2] * sm[2]);
    d_tm = sqrt(tm[0] * tm[0] + tm[1] * tm[1] + tm[2] * tm[2]);
    ca = (sm[0] * tm[0] + sm[1] * tm[1] + sm[2] * tm[2]) / (d_sm * d_tm);
    a_deg = acos(ca) * 180.0 / PI; /* well away from 0 and 180: acos is fine */
    law = pow(10.0, -0.4 * (0.026 * a_deg + 4e-9 * pow(a_deg, 4)));
    want = TSI * (AU / d_sm) * (AU / d_sm) * pow(10.0, -0.4 * (-12.73 + 26.74)) *
           (384400.0 / d_tm) * (384400.0 / d_tm) * law;
    check_rel(1.0, out.moon_sun_fraction, 0, "moon lit");
    check_rel(want, out.e_moon, REL_TOL * 100, "e_moon phase law");
}

/* oi_illuminate skips the Moon's shadow computation when the Moon is certainly
 * lit: over Moon positions swept across the Earth's shadow (umbra, penumbra,
 * the atmosphere's reach and beyond) its moon_sun_fraction must equal
 * oi_sun_fraction's fraction_atm at the Moon, bit for bit. */
static void test_moon_fraction_matches_shadow(void **state)
{
    oi_scene s = lit_scene();
    oi_illum out;
    oi_shadow sh;
    int i, j, skipped_region = 0, shadowed = 0;
    (void)state;
    s.terms = OI_TERM_MOON;
    s.has_observer = 0;
    for (i = 0; i < 60; i++) {
        /* distances from 8,000 km to 1.5 million km behind the Earth */
        double dist = 8000.0 * pow(1.5e6 / 8000.0, i / 59.0);
        for (j = -40; j <= 40; j++) {
            /* lateral offsets across the shadow: up to 1.3 x the penumbra's
             * radius there (Earth radius + dist x (R_sun + R_earth) / AU) */
            double pen = 6378.137 + dist * (695700.0 + 6378.137) / AU + 300.0;
            double off = 1.3 * pen * j / 40.0;
            int st;
            set3(s.moon_km, -dist, off, 0.37 * off);
            if (sqrt(dist * dist + 1.1369 * off * off) < 6378.137 + 1737.4 + 10.0) continue;
            st = oi_illuminate(&s, NULL, &out);
            assert_true(st >= 0);
            assert_true(oi_sun_fraction(s.sun_km, s.moon_km, NULL, &sh) >= 0);
            if (out.moon_sun_fraction != sh.fraction_atm) {
                print_error("moon at (%g, %g): want %.17g got %.17g\n", -dist, off,
                            (double)sh.fraction_atm, (double)out.moon_sun_fraction);
                fail();
            }
            if (sh.fraction_atm < 1) shadowed++;
            if (sh.region == OI_SHADOW_LIT) skipped_region++;
        }
    }
    /* the sweep must reach both sides of the shortcut */
    assert_true(shadowed > 100 && skipped_region > 100);
}

/* The reflected flux uses the phase function with the cosine and sine that
 * the angle came from (no trigonometry): over random lit geometries it must
 * agree with the public oi_lambert_phase of the returned phase angle. */
static void test_reflected_flux_matches_phase_function(void **state)
{
    oi_scene s = lit_scene();
    oi_illum out;
    uint64_t r = 12345u;
    int i, n = 0;
    double worst = 0;
    (void)state;
    s.terms = OI_TERM_SUN;
    for (i = 0; i < 3000; i++) {
        double u[3], want, ratio;
        int k;
        for (k = 0; k < 3; k++) u[k] = lcg01(&r) * 2.0 - 1.0;
        /* observer anywhere within 40,000 km of a target on +y */
        set3(s.observer_km, 40000.0 * u[0], 7000.0 + 40000.0 * u[1], 40000.0 * u[2]);
        if (sqrt(pow(40000.0 * u[0], 2) + pow(7000.0 + 40000.0 * u[1], 2) +
                 pow(40000.0 * u[2], 2)) < 6500.0)
            continue;
        assert_int_equal(oi_illuminate(&s, NULL, &out), OI_OK);
        ratio = (double)s.target_radius_m / ((double)out.range_km * 1000.0);
        want = (double)out.e_sun * (double)s.target_albedo * ratio * ratio *
               (double)oi_lambert_phase(out.phase_sun);
        if (want > 0) {
            double rel = fabs((double)out.flux_sun - want) / want;
            if (rel > worst) worst = rel;
        }
        check_rel(want, out.flux_sun, REL_TOL, "flux_sun vs oi_lambert_phase(phase_sun)");
        n++;
    }
    assert_true(n > 2000);
    print_message("reflected flux vs oi_lambert_phase: worst relative difference %.3g\n", worst);
}

/* The Moon at the centre of the umbra: without the atmosphere dark; with
 * it (partial clouds, docs/atmosphere.md) a central eclipse is dim red, not
 * black: the local brightness near the umbra's centre is published as 13-16
 * mag below sunlight (docs/atmosphere.md, "Eclipse observables"). */
static void test_moon_in_umbra_is_dark(void **state)
{
    oi_scene s = lit_scene();
    oi_model none;
    oi_illum out;
    (void)state;
    set3(s.moon_km, -384400.0, 0, 0); /* exactly on the anti-solar axis */
    s.terms = OI_TERM_MOON;
    memset(&none, 0, sizeof none);
    none.no_atmosphere = 1;
    assert_int_equal(oi_illuminate(&s, &none, &out), OI_OK);
    assert_true(out.moon_sun_fraction == 0);
    assert_true(out.e_moon == 0);
#ifndef OI_NO_ATMOSPHERE
    assert_int_equal(oi_illuminate(&s, NULL, &out), OI_OK);
    print_message("central eclipse: the Moon's sunlight %.3g (%.2f mag below)\n",
                  (double)out.moon_sun_fraction, -2.5 * log10((double)out.moon_sun_fraction));
    assert_true((double)out.moon_sun_fraction > pow(10.0, -0.4 * 16.0));
    assert_true((double)out.moon_sun_fraction < pow(10.0, -0.4 * 13.0));
    assert_true(out.e_moon > 0);
#endif
}
#endif

/* oi_illuminate hands earthshine the cosine and sine theta came from: its
 * earth_phi and earth_psi must agree with the public oi_earthshine at the
 * returned theta and altitude, over random targets from 1 km up. */
static void test_earthshine_matches_public_lookup(void **state)
{
    oi_scene s = lit_scene();
    oi_illum out;
    uint64_t r = 777u;
    int i;
    double worst = 0;
    (void)state;
    s.terms = OI_TERM_EARTH;
    s.has_observer = 0;
    for (i = 0; i < 5000; i++) {
        double u[4], rad, len;
        oi_real phi, psi;
        int k;
        for (k = 0; k < 4; k++) u[k] = lcg01(&r);
        rad = 6378.137 + pow(10.0, u[3] * 5.0); /* 1 km .. 1e5 km */
        len = sqrt((u[0] - 0.5) * (u[0] - 0.5) + (u[1] - 0.5) * (u[1] - 0.5) +
                   (u[2] - 0.5) * (u[2] - 0.5));
        if (len < 1e-3) continue;
        set3(s.target_km, rad * (u[0] - 0.5) / len, rad * (u[1] - 0.5) / len,
             rad * (u[2] - 0.5) / len);
        assert_true(oi_illuminate(&s, NULL, &out) >= 0);
        assert_true(oi_earthshine(out.earth_theta, out.earth_h_km, NULL, &phi, &psi) >= 0);
        if (phi > 0) {
            double rel = fabs((double)out.earth_phi - (double)phi) / (double)phi;
            if (rel > worst) worst = rel;
        }
        check_rel((double)phi, out.earth_phi, REL_TOL * 10, "earth_phi vs oi_earthshine");
        assert_true(fabs((double)out.earth_psi - (double)psi) <= REL_TOL * 10);
    }
    print_message("earth_phi vs oi_earthshine: worst relative difference %.3g\n", worst);
}

static void test_target_in_umbra(void **state)
{
    oi_scene s = lit_scene();
    oi_illum out;
    (void)state;
    set3(s.target_km, -7000, 0, 0);
    set3(s.observer_km, -7000, 100, 0);
    s.terms = OI_TERM_SUN | OI_TERM_EARTH;
#ifdef OI_NO_EARTH_TABLE
    /* The Lambert far field sees a lit crescent from any theta below pi (here
     * the double nearest pi): the near-field zero below is the table's. */
    print_message("skip the earthshine part of test_target_in_umbra: OI_NO_EARTH_TABLE\n");
    s.terms = OI_TERM_SUN;
#endif
    assert_true(oi_illuminate(&s, NULL, &out) >= 0);
    assert_int_equal(out.shadow.region, OI_SHADOW_UMBRA);
    assert_true(out.e_sun == 0);
#ifdef OI_NO_EARTH_TABLE
    /* the Lambert far field (R/r)^2 p(theta) at theta = pi to rounding: p of
     * the rounding error of pi, ~(1e-16)^3 in double, far below anything
     * measurable (lit, this scene's e_earth is ~400 W/m^2, flux ~1e-8) */
    assert_true(out.e_earth >= 0 && out.e_earth < 1e-12);
    assert_true(out.flux_obs >= 0 && out.flux_obs < 1e-25);
#else
    assert_true(out.e_earth == 0); /* theta = pi: no lit Earth visible from 622 km */
    assert_true(out.flux_obs == 0);
#endif
    check_rel(99.0, out.mag_v, 0, "dark magnitude");
}

#ifndef OI_NO_ATMOSPHERE
/* Just inside the geometric umbra in LEO, refracted sunlight still arrives,
 * bent towards the Earth by less than the grazing bending (~1.2 deg); with the
 * atmosphere switched off the point is dark. */
static void test_refracted_sunlight_in_umbra(void **state)
{
    oi_scene s = lit_scene();
    oi_model m;
    oi_illum out;
    double a = 67.7 * PI / 180.0, r = 6878.137, geo[3], cosang, n = 0;
    int i;
    (void)state;
    set3(s.sun_km, 1.47e8, 0, 0);
    set3(s.target_km, -r * cos(a), r * sin(a), 0);
    s.has_observer = 0;
    assert_int_equal(oi_illuminate(&s, NULL, &out), OI_OK);
    assert_true(out.shadow.fraction == 0);
    assert_true(out.shadow.fraction_atm > 0 && out.e_sun > 0);
    for (i = 0; i < 3; i++) {
        geo[i] = (double)s.sun_km[i] - (double)s.target_km[i];
        n += geo[i] * geo[i];
    }
    cosang = (geo[0] * out.dir_sun[0] + geo[1] * out.dir_sun[1] + geo[2] * out.dir_sun[2]) / sqrt(n);
    assert_true(cosang < 1.0 - 1e-12);         /* bent ... */
    assert_true(cosang > cos(1.2 * PI / 180)); /* ... by less than the grazing bending */
    memset(&m, 0, sizeof m);
    m.no_atmosphere = 1;
    assert_int_equal(oi_illuminate(&s, &m, &out), OI_OK);
    assert_true(out.e_sun == 0 && out.shadow.fraction_atm == 0);
}
#endif

static void rotate(const oi_real in[3], oi_real out[3])
{
    /* rotation by 0.7 rad about (1,2,3)/sqrt(14) (Rodrigues), in double */
    double k[3] = {1 / sqrt(14.0), 2 / sqrt(14.0), 3 / sqrt(14.0)}, c = cos(0.7), s = sin(0.7);
    double v[3] = {in[0], in[1], in[2]};
    double kv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
    double kxv[3] = {k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]};
    int i;
    for (i = 0; i < 3; i++) out[i] = (oi_real)(v[i] * c + kxv[i] * s + k[i] * kv * (1 - c));
}

static void test_rotation_invariance(void **state)
{
    oi_scene s = lit_scene(), r;
    oi_illum a, b;
    (void)state;
    s.terms = OI_TERM_SUN | OI_TERM_EARTH;
    set3(s.target_km, 3000, 6000, 1000);
    set3(s.observer_km, 3050, 6010, 980);
    r = s;
    rotate(s.sun_km, r.sun_km);
    rotate(s.target_km, r.target_km);
    rotate(s.observer_km, r.observer_km);
    assert_true(oi_illuminate(&s, NULL, &a) >= 0);
    assert_true(oi_illuminate(&r, NULL, &b) >= 0);
#ifdef OI_SINGLE_PRECISION
    check_rel(a.e_earth, b.e_earth, 1e-4, "e_earth rotated");
    check_rel(a.flux_obs, b.flux_obs, 1e-4, "flux rotated");
#else
    check_rel(a.e_earth, b.e_earth, 1e-10, "e_earth rotated");
    check_rel(a.flux_obs, b.flux_obs, 1e-10, "flux rotated");
#endif
}

static void test_magnitude_roundtrip(void **state)
{
    oi_real f;
    (void)state;
    check_rel(-26.74, oi_magnitude_v((oi_real)TSI, NULL), REL_TOL, "sun mag");
    check_rel(-26.74 + 5.0, oi_magnitude_v((oi_real)(TSI / 100.0), NULL), REL_TOL, "5 mag");
    check_rel(99.0, oi_magnitude_v(0, NULL), 0, "dark");
    check_rel(99.0, oi_magnitude_v((oi_real)-1, NULL), 0, "negative");
    check_rel(99.0, oi_magnitude_v((oi_real)NAN, NULL), 0, "nan");
    assert_int_equal(oi_flux_from_magnitude((oi_real)5.0, NULL, &f), OI_OK);
    check_rel(TSI * pow(10.0, -0.4 * (5.0 + 26.74)), f, REL_TOL * 10, "flux of mag 5");
    assert_int_equal(oi_flux_from_magnitude((oi_real)1e30, NULL, &f), OI_ERR_MAGNITUDE);
    assert_true(f == 0);
    assert_int_equal(oi_flux_from_magnitude((oi_real)INFINITY, NULL, &f), OI_ERR_MAGNITUDE);
    assert_int_equal(oi_flux_from_magnitude((oi_real)NAN, NULL, &f), OI_ERR_MAGNITUDE);
    assert_int_equal(oi_flux_from_magnitude(0, NULL, NULL), OI_ERR_NULL);
}

/* Every output of a failed call is zero. */
static void expect_error(const oi_scene *s, const oi_model *m, int want)
{
    oi_illum out;
    const unsigned char *p = (const unsigned char *)&out;
    size_t i;
    memset(&out, 0x5a, sizeof out);
    assert_int_equal(oi_illuminate(s, m, &out), want);
    for (i = 0; i < sizeof out; i++) assert_int_equal(p[i], 0);
}

static void test_error_paths(void **state)
{
    oi_scene s = lit_scene(), bad;
    oi_model m;
    (void)state;
    s.terms = OI_TERM_ALL;
#ifdef OI_NO_MOON
    s.terms = OI_TERM_SUN | OI_TERM_EARTH;
#endif
    set3(s.moon_km, 0, 0, 384400.0);
    assert_int_equal(oi_illuminate(NULL, NULL, NULL), OI_ERR_NULL);
    expect_error(NULL, NULL, OI_ERR_NULL);
    bad = s; bad.target_km[1] = (oi_real)NAN; expect_error(&bad, NULL, OI_ERR_NONFINITE);
    bad = s; bad.sun_km[0] = (oi_real)INFINITY; expect_error(&bad, NULL, OI_ERR_NONFINITE);
    bad = s; bad.observer_km[2] = (oi_real)-INFINITY; expect_error(&bad, NULL, OI_ERR_NONFINITE);
    bad = s; set3(bad.sun_km, 0, 0, 0); expect_error(&bad, NULL, OI_ERR_ZERO_VECTOR);
    bad = s; set3(bad.target_km, 0, 0, 0); expect_error(&bad, NULL, OI_ERR_ZERO_VECTOR);
    bad = s; set3(bad.observer_km, 0, 0, 0); expect_error(&bad, NULL, OI_ERR_ZERO_VECTOR);
    bad = s; set3(bad.target_km, 0, 6378.0, 0); expect_error(&bad, NULL, OI_ERR_BELOW_SURFACE);
    bad = s; set3(bad.observer_km, 0, 6378.137, 0); expect_error(&bad, NULL, OI_ERR_BELOW_SURFACE);
    bad = s; set3(bad.observer_km, 0, 7000.0, 0); expect_error(&bad, NULL, OI_ERR_OBSERVER_AT_TARGET);
    bad = s; bad.observer_km[0] = (oi_real)0.0005; expect_error(&bad, NULL, OI_ERR_OBSERVER_AT_TARGET);
    bad = s; bad.earth_albedo = (oi_real)1.5; expect_error(&bad, NULL, OI_ERR_ALBEDO);
    bad = s; bad.target_albedo = (oi_real)-0.1; expect_error(&bad, NULL, OI_ERR_ALBEDO);
    bad = s; bad.target_albedo = (oi_real)NAN; expect_error(&bad, NULL, OI_ERR_NONFINITE);
    bad = s; bad.target_radius_m = (oi_real)-1; expect_error(&bad, NULL, OI_ERR_RADIUS);
    bad = s; bad.target_radius_m = 0; expect_error(&bad, NULL, OI_ERR_RADIUS);
    bad = s; bad.terms = 16u; /* 8u is OI_TERM_SKY */ expect_error(&bad, NULL, OI_ERR_TERMS);
    memset(&m, 0, sizeof m);
    m.tsi_w_m2 = (oi_real)-5; expect_error(&s, &m, OI_ERR_MODEL);
    memset(&m, 0, sizeof m);
    m.earth_radius_km = (oi_real)-5; expect_error(&s, &m, OI_ERR_RADIUS);
    memset(&m, 0, sizeof m);
    m.earth_model = 7; expect_error(&s, &m, OI_ERR_MODEL);
    memset(&m, 0, sizeof m);
    m.moon_albedo = (oi_real)2; expect_error(&s, &m, OI_ERR_MODEL);
    /* constants whose products overflow, radii too small to mean anything */
    memset(&m, 0, sizeof m);
    m.tsi_w_m2 = (oi_real)3e30; m.au_km = (oi_real)1e9; expect_error(&s, &m, OI_ERR_MODEL);
    memset(&m, 0, sizeof m);
    m.au_km = (oi_real)1e20; expect_error(&s, &m, OI_ERR_MODEL);
    memset(&m, 0, sizeof m);
    m.tsi_w_m2 = (oi_real)1e-30; expect_error(&s, &m, OI_ERR_MODEL);
    memset(&m, 0, sizeof m);
    m.earth_radius_km = (oi_real)1e-30; expect_error(&s, &m, OI_ERR_RADIUS);
    memset(&m, 0, sizeof m);
    m.sun_radius_km = (oi_real)1e30; expect_error(&s, &m, OI_ERR_RADIUS);
    /* positions past OI_POSITION_MAX_KM (differences would overflow) */
    bad = s; set3(bad.observer_km, 1e30, -1e30, 1e30); expect_error(&bad, NULL, OI_ERR_GEOMETRY);
    bad = s; set3(bad.sun_km, 2e12, 0, 0); expect_error(&bad, NULL, OI_ERR_GEOMETRY);
    bad = s; set3(bad.target_km, 0, 2e12, 0); expect_error(&bad, NULL, OI_ERR_GEOMETRY);
#ifndef OI_NO_MOON
    bad = s; set3(bad.moon_km, 0, 3e35, 0); expect_error(&bad, NULL, OI_ERR_GEOMETRY);
#endif
    /* Sun inside the Earth + Sun radii: impossible geometry */
    bad = s; set3(bad.sun_km, 10000.0, 0, 0); expect_error(&bad, NULL, OI_ERR_GEOMETRY);
#ifndef OI_NO_MOON
    bad = s; set3(bad.moon_km, 0, 0, 0); expect_error(&bad, NULL, OI_ERR_ZERO_VECTOR);
    bad = s; bad.moon_km[0] = (oi_real)NAN; expect_error(&bad, NULL, OI_ERR_NONFINITE);
    /* target inside the Moon */
    bad = s; set3(bad.moon_km, 0, 7000.0, 1000.0); bad.has_observer = 0;
    expect_error(&bad, NULL, OI_ERR_GEOMETRY);
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sun_term_inverse_square),
        cmocka_unit_test(test_reflected_flux_closed_form),
        cmocka_unit_test(test_lambert_earth_far_field),
#ifndef OI_NO_MOON
        cmocka_unit_test(test_moon_lambert_and_phase_law),
        cmocka_unit_test(test_moon_in_umbra_is_dark),
        cmocka_unit_test(test_reflected_flux_matches_phase_function),
        cmocka_unit_test(test_moon_phase_law_irradiance),
        cmocka_unit_test(test_moon_fraction_matches_shadow),
#endif
        cmocka_unit_test(test_earthshine_matches_public_lookup),
        cmocka_unit_test(test_target_in_umbra),
#ifndef OI_NO_ATMOSPHERE
        cmocka_unit_test(test_refracted_sunlight_in_umbra),
#endif
        cmocka_unit_test(test_rotation_invariance),
        cmocka_unit_test(test_magnitude_roundtrip),
        cmocka_unit_test(test_error_paths),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
