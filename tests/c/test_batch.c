/* SPDX-License-Identifier: MIT */
/* test_batch.c: the batch calls against the single calls, bit for bit: the
 * stability vectors (tests/stability/vectors.h) and random scenes (every
 * orbit class, and points packed around the shadow's edges, where the
 * batch's certain-region tests decide) in the precision of the build, every
 * outputs mask (a mask changes no requested output, the fields it leaves
 * out are 0); hostile rows (NaN, zero, below the surface) get the single
 * call's status in their row and leave the other rows computed; hostile
 * arrays (NULL, n < 0, misaligned, overlapping, unknown mask bits, invalid
 * model or camera) get the documented batch status in every row. */
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
#include "../stability/vectors.h"

#ifdef OI_SINGLE_PRECISION
#define VEC(name) name##_f
#else
#define VEC(name) name##_d
#endif
#define NELEM(a) (sizeof(a) / sizeof((a)[0]))

#define NRAND 6000
#define AU 149597870.7
#define RE 6378.137

static oi_real sun[3 * NRAND], pt[3 * NRAND];
static oi_scene scenes[NRAND];
static oi_shadow one_sh[NRAND], bat_sh[NRAND];
static oi_illum one_il[NRAND], bat_il[NRAND];
#ifndef OI_NO_EXPOSURE
static oi_exposure one_ex[NRAND], bat_ex[NRAND];
#endif
static int one_st[NRAND], bat_st[NRAND];

static int same_bits(oi_real a, oi_real b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

static void expect_field(oi_real want, oi_real got, const char *what, long row, unsigned mask)
{
    if (!same_bits(want, got)) {
        print_error("%s row %ld mask %u: single %.17g batch %.17g\n", what, row, mask,
                    (double)want, (double)got);
        fail();
    }
}

/* Compare the batch's shadow rows with the single call's under mask. */
static void compare_shadows(long n, unsigned mask, const oi_model *model)
{
    long i;
    const oi_real z = (oi_real)0;
    for (i = 0; i < n; i++) {
        const oi_shadow *a = &one_sh[i], *b = &bat_sh[i];
        int want_st = one_st[i];
        /* without the atmosphere the single call's warning cannot arise */
        if (!(mask & OI_BATCH_ATMOSPHERE) && want_st > 0) want_st = OI_OK;
        if (want_st != bat_st[i]) {
            print_error("status row %ld mask %u: single %d batch %d\n", i, mask, one_st[i],
                        bat_st[i]);
            fail();
        }
        expect_field(a->fraction, b->fraction, "fraction", i, mask);
        check_int(a->region, b->region, "region");
        expect_field(mask & OI_BATCH_FRACTION_LD ? a->fraction_ld : z, b->fraction_ld,
                     "fraction_ld", i, mask);
        expect_field(mask & OI_BATCH_ATMOSPHERE ? a->fraction_atm : z, b->fraction_atm,
                     "fraction_atm", i, mask);
        if (mask & OI_BATCH_GEOMETRY) {
            expect_field(a->sun_radius_rad, b->sun_radius_rad, "sun_radius_rad", i, mask);
            expect_field(a->earth_radius_rad, b->earth_radius_rad, "earth_radius_rad", i, mask);
            expect_field(a->separation_rad, b->separation_rad, "separation_rad", i, mask);
            expect_field(a->sun_distance_km, b->sun_distance_km, "sun_distance_km", i, mask);
        } else {
            expect_field(z, b->sun_radius_rad + b->earth_radius_rad + b->separation_rad +
                                b->sun_distance_km, "geometry left out", i, mask);
        }
    }
    (void)model;
}

/* Every mask over rows 0..n-1 of sun/pt, with model. Returns how many rows
 * were in the penumbra (so that a test can require the edges were reached). */
static long check_sun_rows(long n, const oi_model *model)
{
    unsigned mask;
    long i, pen = 0;
    for (i = 0; i < n; i++) {
        one_st[i] = oi_sun_fraction(sun + 3 * i, pt + 3 * i, model, &one_sh[i]);
        pen += one_sh[i].region == OI_SHADOW_PENUMBRA;
    }
    for (mask = 0; mask <= OI_BATCH_ALL; mask++) {
        int bad, want_bad = 0;
        memset(bat_sh, 0x5a, sizeof bat_sh); /* garbage: every field must be written */
        bad = oi_sun_fraction_batch(n, sun, pt, model, mask, bat_sh, bat_st);
        for (i = 0; i < n; i++) want_bad += one_st[i] < 0;
        check_int(want_bad, bad, "rows in error");
        compare_shadows(n, mask, model);
    }
    return pen;
}

static void test_sun_stability_vectors(void **state)
{
    const stab_vec *v = VEC(stab_shadow);
    long n = (long)NELEM(VEC(stab_shadow)), i;
    int k;
    oi_model geo;
    (void)state;
    for (i = 0; i < n; i++)
        for (k = 0; k < 3; k++) {
            sun[3 * i + k] = (oi_real)v[i].in[k];
            pt[3 * i + k] = (oi_real)v[i].in[3 + k];
        }
    memset(&geo, 0, sizeof geo);
    geo.no_atmosphere = 1;
    (void)check_sun_rows(n, &geo);
    (void)check_sun_rows(n, NULL);
#ifndef OI_NO_LIMB_DARKENING
    geo.limb_darkening = OI_LIMB_DARKENED;
    (void)check_sun_rows(n, &geo);
#endif
}

/* A Sun at about 1 AU in a random direction; s_hat its unit vector. */
static void random_sun(uint64_t *rng, double s[3], double s_hat[3])
{
    double d;
    int k;
    random_unit(rng, s_hat);
    d = AU * (0.983 + 0.034 * lcg01(rng));
    for (k = 0; k < 3; k++) s[k] = d * s_hat[k];
}

/* Row i: a random Sun and a point; every third row anywhere (LEO to beyond
 * GEO), one in three across the penumbra (the lit/penumbra/umbra edges
 * and the certain tests' margins), the others behind the Earth within 1.3
 * times the penumbra's outer radius plus 400 km. all_edges: every row across
 * the penumbra (the rows the batch cannot decide from cosines). */
static void random_sun_rows_of(long n, uint64_t seed, int all_edges)
{
    uint64_t rng = seed;
    long i;
    for (i = 0; i < n; i++) {
        double s[3], sh[3], p[3], u[3], w[3], nu;
        const long kind = all_edges ? 1 : i % 3;
        int k;
        random_sun(&rng, s, sh);
        if (kind == 0) {
            double z = 2 * lcg01(&rng) - 1, a = 2 * OI_PI * lcg01(&rng), r = sqrt(1 - z * z);
            double d = RE * (1.0 + 0.001 + 10.0 * lcg01(&rng) * lcg01(&rng));
            p[0] = d * r * cos(a);
            p[1] = d * r * sin(a);
            p[2] = d * z;
        } else {
            double zb = RE * (0.2 + 8.0 * lcg01(&rng)), outer, rho, ang;
            outer = RE + zb * (RE + 696000.0) / AU;
            if (kind == 1) /* across the penumbra, 250 km to spare on each side (5 km
                            * and a fifth of its width with all_edges) */
                rho = RE + zb * RE / AU +
                      (2 * lcg01(&rng) - 1) * (all_edges ? 1.2 * zb * 696000.0 / AU + 5.0
                                                         : 1.5 * zb * 696000.0 / AU + 250.0);
            else
                rho = (1.3 * outer + 400.0) * sqrt(lcg01(&rng));
            ang = 2 * OI_PI * lcg01(&rng);
            /* u, w: a basis of the plane normal to the Sun's direction */
            u[0] = -sh[1];
            u[1] = sh[0];
            u[2] = 0;
            nu = sqrt(u[0] * u[0] + u[1] * u[1]);
            if (nu < 1e-9) {
                u[0] = 1;
                u[1] = 0;
                nu = 1;
            }
            for (k = 0; k < 3; k++) u[k] /= nu;
            w[0] = sh[1] * u[2] - sh[2] * u[1];
            w[1] = sh[2] * u[0] - sh[0] * u[2];
            w[2] = sh[0] * u[1] - sh[1] * u[0];
            for (k = 0; k < 3; k++) p[k] = -zb * sh[k] + rho * (cos(ang) * u[k] + sin(ang) * w[k]);
        }
        for (k = 0; k < 3; k++) {
            sun[3 * i + k] = (oi_real)s[k];
            pt[3 * i + k] = (oi_real)p[k];
        }
    }
}

static void random_sun_rows(long n, uint64_t seed)
{
    random_sun_rows_of(n, seed, 0);
}

/* Rows nearly all in the penumbra, in blocks of every length the batch
 * meets (whole blocks of rows, then a tail), in the precision of the build
 * and for every disc and shape: the penumbra rows computed in the batch must
 * be the single call's bits. */
static void test_sun_penumbra_heavy(void **state)
{
    static const long lengths[] = {NRAND, NRAND - 7, 33, 31, 1};
    oi_model geo;
    size_t j;
    (void)state;
    for (j = 0; j < NELEM(lengths); j++) {
        long pen;
        random_sun_rows_of(lengths[j], 777 + (uint64_t)j, 1);
        memset(&geo, 0, sizeof geo);
        geo.no_atmosphere = 1;
        pen = check_sun_rows(lengths[j], &geo);
        /* most rows in the penumbra (else the case proves little) */
        if (lengths[j] > 100) assert_true(pen > lengths[j] / 2);
        (void)check_sun_rows(lengths[j], NULL);
#ifndef OI_NO_LIMB_DARKENING
        geo.limb_darkening = OI_LIMB_DARKENED;
        (void)check_sun_rows(lengths[j], &geo);
#endif
#ifndef OI_NO_OBLATE
        memset(&geo, 0, sizeof geo);
        geo.no_atmosphere = 1;
        geo.earth_shape = OI_EARTH_WGS84;
        (void)check_sun_rows(lengths[j], &geo);
#endif
    }
}

static void test_sun_random(void **state)
{
    oi_model geo;
    long pen;
    (void)state;
    random_sun_rows(NRAND, 12345);
    memset(&geo, 0, sizeof geo);
    geo.no_atmosphere = 1;
    pen = check_sun_rows(NRAND, &geo);
    /* the edges were reached (else the comparison proves little) */
    assert_true(pen > NRAND / 20);
    (void)check_sun_rows(NRAND, NULL);
#ifndef OI_NO_LIMB_DARKENING
    geo.limb_darkening = OI_LIMB_DARKENED;
    (void)check_sun_rows(NRAND, &geo);
#endif
#ifndef OI_NO_OBLATE
    /* the ellipsoid without the atmosphere: the umbra decided from cosines
     * must be the ellipsoid's (its silhouette is smaller than the
     * equatorial sphere's towards the poles) */
    memset(&geo, 0, sizeof geo);
    geo.no_atmosphere = 1;
    geo.earth_shape = OI_EARTH_WGS84;
    (void)check_sun_rows(NRAND, &geo);
#endif
}

/* Scenes from the Sun rows: Moon, observer, terms and albedos varied. */
static void random_scenes(long n, uint64_t seed)
{
    uint64_t rng = seed;
    long i;
    random_sun_rows(n, seed + 1);
    for (i = 0; i < n; i++) {
        oi_scene *s = &scenes[i];
        double a = 2 * OI_PI * lcg01(&rng), d = 384400.0 * (0.95 + 0.1 * lcg01(&rng));
        double ob = RE + 400 + 35000 * lcg01(&rng), b = 2 * OI_PI * lcg01(&rng);
        int k;
        oi_scene_defaults(s);
        for (k = 0; k < 3; k++) {
            s->sun_km[k] = sun[3 * i + k];
            s->target_km[k] = pt[3 * i + k];
        }
        set3(s->moon_km, d * cos(a), d * sin(a), 0.1 * d * (lcg01(&rng) - 0.5));
        /* observers near the target half the time (Earth in view, occulted) */
        if (i % 2)
            set3(s->observer_km, (double)s->target_km[0] + 500 * cos(b),
                 (double)s->target_km[1] + 500 * sin(b), (double)s->target_km[2] + 100);
        else
            set3(s->observer_km, ob * cos(b), ob * sin(b), 0.3 * ob * (lcg01(&rng) - 0.5));
        s->has_observer = i % 7 != 0;
        s->terms = (unsigned)(1 + i % OI_TERM_ALL);
#ifdef OI_NO_MOON
        s->terms &= ~OI_TERM_MOON;
#endif
        s->earth_albedo = (oi_real)(0.1 + 0.5 * lcg01(&rng));
        s->target_albedo = (oi_real)(0.05 + 0.9 * lcg01(&rng));
        s->target_radius_m = (oi_real)(0.1 + 50 * lcg01(&rng));
    }
}

/* Scenes 0..n-1 from the stability vectors (Sun, target, observer; the
 * Sun and the Earth's terms); returns n. */
static long stability_scenes(void)
{
    const stab_vec *v = VEC(stab_illum);
    const long n = (long)NELEM(VEC(stab_illum));
    long i;
    for (i = 0; i < n; i++) {
        oi_scene *s = &scenes[i];
        oi_scene_defaults(s);
        set3(s->sun_km, v[i].in[0], v[i].in[1], v[i].in[2]);
        set3(s->target_km, v[i].in[3], v[i].in[4], v[i].in[5]);
        set3(s->observer_km, v[i].in[6], v[i].in[7], v[i].in[8]);
        s->has_observer = 1;
        s->terms = OI_TERM_SUN | OI_TERM_EARTH;
    }
    return n;
}

/* Rows 0..n-1 of the single calls (one_st, one) and of the batch (bat_st,
 * bat), records of `size` bytes: the same statuses, the same bytes. */
static void expect_same_rows(long n, const void *one, const void *bat, size_t size,
                             const char *what)
{
    long i;
    for (i = 0; i < n; i++) {
        check_int(one_st[i], bat_st[i], what);
        if (memcmp((const unsigned char *)one + (size_t)i * size,
                   (const unsigned char *)bat + (size_t)i * size, size) != 0) {
            print_error("%s: row %ld differs\n", what, i);
            fail();
        }
    }
}

/* Rows 2..4 of the scenes made hostile: a NaN albedo, an albedo above 1,
 * unknown terms. */
static void spoil_scene_rows(void)
{
    scenes[2].target_albedo = (oi_real)NAN;
    scenes[3].earth_albedo = (oi_real)2;
    scenes[4].terms = 1u << 9;
}

/* The batch's statuses in those rows. */
static void expect_spoiled_statuses(void)
{
    check_int(OI_ERR_NONFINITE, bat_st[2], "NaN albedo row");
    check_int(OI_ERR_ALBEDO, bat_st[3], "albedo row");
    check_int(OI_ERR_TERMS, bat_st[4], "terms row");
}

static void check_illum_rows(long n, const oi_model *model)
{
    long i;
    int bad, want_bad = 0;
    for (i = 0; i < n; i++) {
        one_st[i] = oi_illuminate(&scenes[i], model, &one_il[i]);
        want_bad += one_st[i] < 0;
    }
    memset(bat_il, 0x5a, sizeof bat_il);
    bad = oi_illuminate_batch(n, scenes, model, bat_il, bat_st);
    check_int(want_bad, bad, "illuminate rows in error");
    expect_same_rows(n, one_il, bat_il, sizeof *one_il, "illuminate");
}

static void test_illuminate_stability_and_random(void **state)
{
    const long n = stability_scenes();
    oi_model m;
    (void)state;
    check_illum_rows(n, NULL);
    memset(&m, 0, sizeof m);
    m.no_atmosphere = 1;
    m.earth_model = OI_EARTH_LAMBERT;
    check_illum_rows(n, &m);
    random_scenes(NRAND, 777);
    check_illum_rows(NRAND, NULL);
    check_illum_rows(NRAND, &m);
}

/* The single call's row as oi_illuminate_batch_outputs must give it under
 * mask: the single call's (without OI_BATCH_OBSERVER: of the scene without
 * observer, once the observer's own checks passed), the fields left out 0. */
static int expected_outputs(const oi_scene *s, const oi_model *model, unsigned mask,
                            int one_status, const oi_illum *one, oi_illum *want)
{
    int st = one_status;
    *want = *one;
    if (!(mask & OI_BATCH_OBSERVER) && s->has_observer &&
        (st >= 0 || st == OI_ERR_OBSERVER_AT_TARGET)) {
        oi_scene alone = *s;
        alone.has_observer = 0;
        st = oi_illuminate(&alone, model, want);
    }
    if (st < 0) return st;
    if (!(mask & OI_BATCH_FRACTION_LD)) want->shadow.fraction_ld = 0;
    if (!(mask & OI_BATCH_GEOMETRY)) {
        want->shadow.sun_radius_rad = want->shadow.earth_radius_rad = 0;
        want->shadow.separation_rad = want->shadow.sun_distance_km = 0;
    }
    if (!(mask & OI_BATCH_DIRECTIONS)) {
        memset(want->dir_sun, 0, sizeof want->dir_sun);
        memset(want->dir_earth, 0, sizeof want->dir_earth);
        memset(want->dir_moon, 0, sizeof want->dir_moon);
        memset(want->dir_sky, 0, sizeof want->dir_sky);
    }
    return st;
}

/* Every outputs mask of oi_illuminate_batch_outputs over scenes 0..n-1,
 * against the single calls. Returns the rows answered without the shadow's
 * angles' being needed by the single call's region (lit or umbra), so that
 * a test can require the certain-region path was taken. */
static long check_illum_outputs(long n, const oi_model *model)
{
    static oi_illum want;
    unsigned mask;
    long i, certain = 0;
    for (i = 0; i < n; i++) {
        one_st[i] = oi_illuminate(&scenes[i], model, &one_il[i]);
        certain += one_st[i] >= 0 && one_il[i].shadow.region != OI_SHADOW_PENUMBRA;
    }
    for (mask = 0; mask <= OI_BATCH_SCENE_ALL; mask++) {
        int bad, want_bad = 0;
        memset(bat_il, 0x5a, sizeof bat_il); /* garbage: every field must be written */
        bad = oi_illuminate_batch_outputs(n, scenes, model, mask, bat_il, bat_st);
        for (i = 0; i < n; i++) {
            const int st = expected_outputs(&scenes[i], model, mask, one_st[i], &one_il[i], &want);
            want_bad += st < 0;
            if (st != bat_st[i]) {
                print_error("outputs status row %ld mask %u: single %d batch %d\n", i, mask, st,
                            bat_st[i]);
                fail();
            }
            if (st < 0) memset(&want, 0, sizeof want);
            if (memcmp(&want, &bat_il[i], sizeof want) != 0) {
                const oi_real *a = (const oi_real *)(const void *)&want;
                const oi_real *b = (const oi_real *)(const void *)&bat_il[i];
                size_t k;
                for (k = 0; k < sizeof want / sizeof *a; k++)
                    if (!same_bits(a[k], b[k]))
                        print_error("outputs row %ld mask %u: word %u single %.17g batch %.17g\n",
                                    i, mask, (unsigned)k, (double)a[k], (double)b[k]);
                fail();
            }
        }
        check_int(want_bad, bad, "outputs rows in error");
    }
    return certain;
}

/* Half the rows of random_scenes with the Moon near the line from the
 * target to the Sun (solar eclipses by the Moon, alone and with the
 * Earth's shadow), so that its occultation's path is taken. */
static void moon_in_front(long n, uint64_t seed)
{
    uint64_t rng = seed;
    long i;
    for (i = 0; i < n; i += 2) {
        oi_scene *s = &scenes[i];
        double u[3], d = 0, r = 384400.0 * (0.95 + 0.1 * lcg01(&rng));
        int k;
        for (k = 0; k < 3; k++) {
            u[k] = (double)s->sun_km[k] - (double)s->target_km[k];
            d += u[k] * u[k];
        }
        d = sqrt(d);
        for (k = 0; k < 3; k++)
            s->moon_km[k] = (oi_real)((double)s->target_km[k] + r * u[k] / d +
                                      3000.0 * (lcg01(&rng) - 0.5));
        s->has_moon = (int)(i % 4 == 0);
    }
}

static void test_illuminate_outputs(void **state)
{
    const long n = stability_scenes();
    long certain;
    oi_model m;
    (void)state;
    (void)check_illum_outputs(n, NULL);
    random_scenes(NRAND / 2, 4711);
    moon_in_front(NRAND / 2, 5);
    certain = check_illum_outputs(NRAND / 2, NULL);
    assert_true(certain > NRAND / 8);
    memset(&m, 0, sizeof m);
    m.no_atmosphere = 1;
    m.earth_model = OI_EARTH_LAMBERT;
    (void)check_illum_outputs(NRAND / 2, &m);
#ifndef OI_NO_LIMB_DARKENING
    m.limb_darkening = OI_LIMB_DARKENED;
    (void)check_illum_outputs(NRAND / 2, &m);
#endif
#ifndef OI_NO_OBLATE
    memset(&m, 0, sizeof m);
    m.earth_shape = OI_EARTH_WGS84;
    (void)check_illum_outputs(NRAND / 2, &m);
    m.no_atmosphere = 1;
    (void)check_illum_outputs(NRAND / 2, &m);
#endif
    /* hostile rows: each the single call's status, the others computed */
    random_scenes(40, 17);
    spoil_scene_rows();
    scenes[5].has_observer = 1;
    scenes[5].observer_km[1] = (oi_real)NAN;
    scenes[6].has_observer = 1;
    memcpy(scenes[6].observer_km, scenes[6].target_km, sizeof scenes[6].observer_km);
    (void)check_illum_outputs(40, NULL);
    expect_spoiled_statuses();
    check_int(OI_ERR_NONFINITE, bat_st[5], "outputs NaN observer row");
    check_int(OI_ERR_OBSERVER_AT_TARGET, bat_st[6], "observer at target, mask all");
}

static void test_earthshine(void **state)
{
    static oi_real th[NRAND], h[NRAND], phi1[NRAND], psi1[NRAND], phi[NRAND], psi[NRAND];
    uint64_t rng = 99;
    long i;
    int bad, want_bad = 0;
    oi_model lam;
    (void)state;
    for (i = 0; i < NRAND; i++) {
        th[i] = (oi_real)(OI_PI * lcg01(&rng));
        h[i] = (oi_real)(pow(10.0, -3 + 9 * lcg01(&rng)));
        if (i % 97 == 0) h[i] = (oi_real)NAN;
        if (i % 89 == 0) h[i] = (oi_real)-1;
        one_st[i] = oi_earthshine(th[i], h[i], NULL, &phi1[i], &psi1[i]);
        want_bad += one_st[i] < 0;
    }
    bad = oi_earthshine_batch(NRAND, th, h, NULL, phi, psi, bat_st);
    check_int(want_bad, bad, "earthshine rows in error");
    for (i = 0; i < NRAND; i++) {
        check_int(one_st[i], bat_st[i], "earthshine status");
        expect_field(phi1[i], phi[i], "phi", i, 0);
        expect_field(psi1[i], psi[i], "psi", i, 0);
    }
    /* psi not wanted: phi the same */
    memset(phi, 0, sizeof phi);
    (void)oi_earthshine_batch(NRAND, th, h, NULL, phi, NULL, bat_st);
    for (i = 0; i < NRAND; i++) expect_field(phi1[i], phi[i], "phi (no psi)", i, 0);
    memset(&lam, 0, sizeof lam);
    lam.earth_model = OI_EARTH_LAMBERT;
    for (i = 0; i < NRAND; i++) one_st[i] = oi_earthshine(th[i], h[i], &lam, &phi1[i], &psi1[i]);
    (void)oi_earthshine_batch(NRAND, th, h, &lam, phi, psi, bat_st);
    for (i = 0; i < NRAND; i++) {
        check_int(one_st[i], bat_st[i], "earthshine lambert status");
        expect_field(phi1[i], phi[i], "phi lambert", i, 0);
    }
}

#ifndef OI_NO_EXPOSURE
static void test_expose(void **state)
{
    static oi_expose_in in[NRAND];
    const oi_camera *cam = oi_camera_builtin(0);
    oi_expose_goal goal = {OI_R(0.4), OI_R(7.0), 0u, 0u, 0};
    uint64_t rng = 5;
    long i;
    int bad, want_bad = 0;
    (void)state;
    for (i = 0; i < NRAND; i++) {
        in[i].flux_w_m2 = (oi_real)pow(10.0, -25 + 25 * lcg01(&rng));
        in[i].background_w_m2_sr = (oi_real)(i % 3 ? 0.0 : 10 * lcg01(&rng));
        in[i].flags = (unsigned)(i % 5 ? 0 : OI_FLAG_PENUMBRA);
        if (i % 101 == 0) in[i].flux_w_m2 = (oi_real)NAN;
        if (i % 103 == 0) in[i].flags = 1u << 20;
        one_st[i] = oi_expose(cam, &in[i], &goal, &one_ex[i]);
        want_bad += one_st[i] < 0;
    }
    memset(bat_ex, 0x5a, sizeof bat_ex);
    bad = oi_expose_batch(NRAND, cam, in, &goal, bat_ex, bat_st);
    check_int(want_bad, bad, "expose rows in error");
    expect_same_rows(NRAND, one_ex, bat_ex, sizeof *one_ex, "expose");
    /* oi_expose_scene over the illuminated random scenes (rows without
     * observer: OI_ERR_NULL in their row) */
    random_scenes(NRAND, 31);
    (void)oi_illuminate_batch(NRAND, scenes, NULL, bat_il, bat_st);
    want_bad = 0;
    for (i = 0; i < NRAND; i++) {
        one_st[i] = oi_expose_scene(cam, &scenes[i], &bat_il[i], NULL, NULL, &one_ex[i]);
        want_bad += one_st[i] < 0;
    }
    memset(bat_ex, 0x5a, sizeof bat_ex);
    bad = oi_expose_scene_batch(NRAND, cam, scenes, bat_il, NULL, NULL, bat_ex, bat_st);
    check_int(want_bad, bad, "expose_scene rows in error");
    expect_same_rows(NRAND, one_ex, bat_ex, sizeof *one_ex, "expose_scene");
    for (i = 0; i < NRAND; i += 7) check_int(OI_ERR_NULL, bat_st[i], "no observer");
}
#endif

/* Hostile rows among good ones: each row's status is the single call's,
 * the good rows computed. */
static void test_hostile_rows(void **state)
{
    long i, n = 40, good;
    (void)state;
    random_sun_rows(n, 4242);
    pt[3 * 1 + 0] = (oi_real)NAN;
    sun[3 * 2 + 2] = (oi_real)INFINITY;
    pt[3 * 3 + 0] = pt[3 * 3 + 1] = pt[3 * 3 + 2] = 0;
    set3(pt + 3 * 4, 100.0, 0.0, 0.0);                /* below the surface */
    set3(sun + 3 * 5, 1000.0, 0.0, 0.0);              /* the Sun touching the Earth */
    set3(pt + 3 * 6, (double)sun[18], (double)sun[19], (double)sun[20]); /* in the Sun */
    assert_int_equal(check_sun_rows(n, NULL) >= 0, 1);
    check_int(OI_ERR_NONFINITE, bat_st[1], "NaN row");
    check_int(OI_ERR_NONFINITE, bat_st[2], "inf row");
    check_int(OI_ERR_ZERO_VECTOR, bat_st[3], "zero row");
    check_int(OI_ERR_BELOW_SURFACE, bat_st[4], "below row");
    check_int(OI_ERR_GEOMETRY, bat_st[5], "Sun at the Earth");
    check_int(OI_ERR_GEOMETRY, bat_st[6], "point in the Sun");
    /* (some random rows lie below the surface: their status is the single
     * call's too) */
    good = 0;
    for (i = 7; i < n; i++) good += bat_st[i] >= 0;
    assert_true(good > (n - 7) / 2);
    /* the same in scenes */
    random_scenes(n, 17);
    spoil_scene_rows();
    check_illum_rows(n, NULL);
    expect_spoiled_statuses();
}

static void expect_all(int want, long n, const int *st, const char *what)
{
    long i;
    for (i = 0; i < n; i++) check_int(want, st[i], what);
}

/* Hostile arrays: documented batch statuses in every row. */
static void test_hostile_arrays(void **state)
{
    static oi_real buf[3 * 64 + 1];
    static unsigned char raw[sizeof(oi_shadow) * 9 + 1];
    long n = 8, i;
    oi_model bad_model;
    (void)state;
    random_sun_rows(n, 9);
    /* n = 0: nothing, NULL allowed */
    check_int(0, oi_sun_fraction_batch(0, NULL, NULL, NULL, 0, NULL, NULL), "n = 0");
    check_int(0, oi_illuminate_batch(0, NULL, NULL, NULL, NULL), "n = 0 illuminate");
    check_int(0, oi_earthshine_batch(0, NULL, NULL, NULL, NULL, NULL, NULL), "n = 0 es");
    /* n < 0 */
    bat_st[0] = 12345;
    check_int(OI_ERR_INPUT, oi_sun_fraction_batch(-1, sun, pt, NULL, 0, bat_sh, bat_st), "n<0");
    /* n beyond OI_BATCH_MAX: refused, nothing written (the arrays are not that long) */
    check_int(OI_ERR_INPUT,
              oi_sun_fraction_batch(OI_BATCH_MAX + 1, sun, pt, NULL, 0, bat_sh, bat_st), "n big");
    check_int(OI_ERR_INPUT, oi_illuminate_batch(OI_BATCH_MAX + 1, scenes, NULL, bat_il, bat_st),
              "n big illuminate");
    check_int(OI_ERR_INPUT,
              oi_earthshine_batch(OI_BATCH_MAX + 1, pt, pt, NULL, buf, NULL, bat_st), "n big es");
    check_int(12345, bat_st[0], "status untouched");
    /* NULL arrays */
    check_int(OI_ERR_NULL, oi_sun_fraction_batch(n, NULL, pt, NULL, 0, bat_sh, bat_st), "NULL");
    expect_all(OI_ERR_NULL, n, bat_st, "NULL rows");
    check_int(OI_ERR_NULL, oi_illuminate_batch(n, scenes, NULL, NULL, bat_st), "NULL out");
    expect_all(OI_ERR_NULL, n, bat_st, "NULL out rows");
    check_int(OI_ERR_NULL, oi_earthshine_batch(n, pt, NULL, NULL, buf, NULL, bat_st), "NULL h");
    /* unknown mask bits */
    check_int(OI_ERR_FLAGS, oi_sun_fraction_batch(n, sun, pt, NULL, 8u, bat_sh, bat_st), "mask");
    expect_all(OI_ERR_FLAGS, n, bat_st, "mask rows");
    /* overlap: out over the inputs, status over out */
    memcpy(buf, pt, 3 * (size_t)n * sizeof *buf);
    check_int(OI_ERR_INPUT,
              oi_sun_fraction_batch(n, sun, buf, NULL, 0, (oi_shadow *)(void *)buf, bat_st),
              "out over input");
    expect_all(OI_ERR_INPUT, n, bat_st, "overlap rows");
    check_int(OI_ERR_INPUT,
              oi_sun_fraction_batch(n, sun, pt, NULL, 0, bat_sh, (int *)(void *)&bat_sh[1]),
              "status over out");
    check_int(OI_ERR_INPUT, oi_earthshine_batch(n, buf, buf + 16, NULL, buf + 4, NULL, bat_st),
              "phi over theta");
    /* in place is an overlap too; adjacent arrays are not */
    check_int(0, oi_earthshine_batch(n, buf, buf + 8, NULL, buf + 16, buf + 24, bat_st) >= 0
                     ? 0 : 1, "adjacent arrays");
    /* misaligned output */
    check_int(OI_ERR_INPUT,
              oi_sun_fraction_batch(n, sun, pt, NULL, 0, (oi_shadow *)(void *)(raw + 1), bat_st),
              "misaligned");
    expect_all(OI_ERR_INPUT, n, bat_st, "misaligned rows");
    /* invalid model: every row its status, outputs zeroed */
    memset(&bad_model, 0, sizeof bad_model);
    bad_model.tsi_w_m2 = (oi_real)-1;
    memset(bat_sh, 0x5a, sizeof bat_sh);
    check_int(OI_ERR_MODEL, oi_sun_fraction_batch(n, sun, pt, &bad_model, 0, bat_sh, bat_st),
              "model");
    expect_all(OI_ERR_MODEL, n, bat_st, "model rows");
    for (i = 0; i < n; i++) expect_field(0, bat_sh[i].fraction, "zeroed", i, 0);
    random_scenes(n, 3);
    check_int(OI_ERR_MODEL, oi_illuminate_batch(n, scenes, &bad_model, bat_il, bat_st), "model");
    expect_all(OI_ERR_MODEL, n, bat_st, "model rows illuminate");
    check_int(OI_ERR_MODEL,
              oi_illuminate_batch_outputs(n, scenes, &bad_model, 0, bat_il, bat_st), "model");
    expect_all(OI_ERR_MODEL, n, bat_st, "model rows outputs");
    for (i = 0; i < n; i++) expect_field(0, bat_il[i].e_sun, "outputs zeroed", i, 0);
    /* outputs batch: n = 0, n too big, NULL, unknown bits, overlap, misaligned */
    check_int(0, oi_illuminate_batch_outputs(0, NULL, NULL, 0, NULL, NULL), "n = 0 outputs");
    bat_st[0] = 12345;
    check_int(OI_ERR_INPUT, oi_illuminate_batch_outputs(-1, scenes, NULL, 0, bat_il, bat_st),
              "n<0 outputs");
    check_int(OI_ERR_INPUT,
              oi_illuminate_batch_outputs(OI_BATCH_MAX + 1, scenes, NULL, 0, bat_il, bat_st),
              "n big outputs");
    check_int(12345, bat_st[0], "outputs status untouched");
    check_int(OI_ERR_NULL, oi_illuminate_batch_outputs(n, NULL, NULL, 0, bat_il, bat_st),
              "NULL scenes");
    expect_all(OI_ERR_NULL, n, bat_st, "NULL scenes rows");
    check_int(OI_ERR_FLAGS,
              oi_illuminate_batch_outputs(n, scenes, NULL, OI_BATCH_SCENE_ALL + 1u, bat_il, bat_st),
              "outputs mask");
    expect_all(OI_ERR_FLAGS, n, bat_st, "outputs mask rows");
    check_int(OI_ERR_INPUT,
              oi_illuminate_batch_outputs(n, scenes, NULL, 0, (oi_illum *)(void *)&scenes[1],
                                          bat_st),
              "outputs over scenes");
    expect_all(OI_ERR_INPUT, n, bat_st, "outputs overlap rows");
    check_int(OI_ERR_INPUT,
              oi_illuminate_batch_outputs(n, scenes, NULL, 0, bat_il,
                                          (int *)(void *)((unsigned char *)bat_st + 1)),
              "outputs misaligned status");
    bad_model.tsi_w_m2 = 0;
    bad_model.sun_radius_km = (oi_real)-5;
    check_int(OI_ERR_RADIUS, oi_earthshine_batch(n, pt, pt + n, &bad_model, buf, NULL, bat_st),
              "radius");
#ifndef OI_NO_EXPOSURE
    {
        static oi_expose_in in[8];
        oi_camera cam = *oi_camera_builtin(0);
        cam.n_times = 0;
        check_int(OI_ERR_CAMERA, oi_expose_batch(n, &cam, in, NULL, bat_ex, bat_st), "camera");
        expect_all(OI_ERR_CAMERA, n, bat_st, "camera rows");
        check_int(OI_ERR_CAMERA,
                  oi_expose_scene_batch(n, &cam, scenes, bat_il, NULL, NULL, bat_ex, bat_st),
                  "camera scene");
        check_int(OI_ERR_NULL, oi_expose_batch(n, NULL, in, NULL, bat_ex, bat_st), "no camera");
    }
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sun_stability_vectors),
        cmocka_unit_test(test_sun_random),
        cmocka_unit_test(test_sun_penumbra_heavy),
        cmocka_unit_test(test_illuminate_stability_and_random),
        cmocka_unit_test(test_illuminate_outputs),
        cmocka_unit_test(test_earthshine),
#ifndef OI_NO_EXPOSURE
        cmocka_unit_test(test_expose),
#endif
        cmocka_unit_test(test_hostile_rows),
        cmocka_unit_test(test_hostile_arrays),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
