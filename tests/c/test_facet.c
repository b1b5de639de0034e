/* SPDX-License-Identifier: MIT */
/* test_facet.c: targets with shape (oi_shape, oi_facet_brdf,
 * oi_earthshine_plate, oi_illuminate with a shape, OI_FLAG_GLINT) against
 * closed forms written here: the Sun-lit Lambertian plate, the far-field
 * plate under a point Earth, the mean-direction option; the BRDF's
 * reciprocity and energy conservation (a quadrature over the hemisphere);
 * rotation invariance; the built-in shapes' totals; hostile facets and
 * quaternions. The cubature against an independent quadrature at random
 * points: tests/python/test_facets.py. */
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

#ifndef OI_NO_FACETS

static const double PI = 3.14159265358979323846;

/* without the earthshine table the Earth's light is the Lambert far field,
 * with its warning */
#ifdef OI_NO_EARTH_TABLE
#define ST_EARTH OI_WARN_TABLE_RANGE
#else
#define ST_EARTH OI_OK
#endif

#ifdef OI_SINGLE_PRECISION
#define REL_TOL 2e-5
#else
#define REL_TOL 1e-12
#endif

/* A LEO scene: Sun along +x, target at 7000 km on +y, observer 1000 km
 * away; only the terms asked for. */
static void leo_scene(oi_scene *s, unsigned terms)
{
    oi_scene_defaults(s);
    set3(s->sun_km, 1.495978707e8, 0.0, 0.0);
    set3(s->target_km, 0.0, 7000.0, 0.0);
    set3(s->observer_km, 600.0, 7000.0, 800.0);
    s->has_observer = 1;
    s->terms = terms;
    s->target_albedo = (oi_real)0.3;
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* q v q* in double (the test's own rotation). */
static void rotate_ref(const double q[4], const double v[3], double out[3])
{
    double t[3], c[3];
    const double u[3] = {q[1], q[2], q[3]};
    t[0] = 2 * (u[1] * v[2] - u[2] * v[1]);
    t[1] = 2 * (u[2] * v[0] - u[0] * v[2]);
    t[2] = 2 * (u[0] * v[1] - u[1] * v[0]);
    c[0] = u[1] * t[2] - u[2] * t[1];
    c[1] = u[2] * t[0] - u[0] * t[2];
    c[2] = u[0] * t[1] - u[1] * t[0];
    out[0] = v[0] + q[0] * t[0] + c[0];
    out[1] = v[1] + q[0] * t[1] + c[1];
    out[2] = v[2] + q[0] * t[2] + c[2];
}

/* Sun-lit Lambertian plate, closed form: F = E cos(i) (albedo / pi) A cos(o) / d^2,
 * for the built-in plate turned by several attitudes. */
static void test_sunlit_plate_closed_form(void **state)
{
    const oi_shape *plate = oi_shape_find("plate");
    const double qs[4][4] = {{0, 0, 0, 0},
                             {0.9238795325112867, 0.0, 0.3826834323650898, 0.0},
                             {0.5, 0.5, -0.5, 0.5},
                             {0.2, -0.4, 0.6, 0.6633249580710799}};
    int k, i;
    (void)state;
    assert_non_null(plate);
    for (k = 0; k < 4; k++) {
        oi_scene s;
        oi_illum il;
        double q[4], n[3], z[3] = {0, 0, 1}, u_sun[3], u_obs[3], d, ci, co, want;
        leo_scene(&s, OI_TERM_SUN);
        s.shape = plate;
        for (i = 0; i < 4; i++) s.attitude_q[i] = (oi_real)qs[k][i];
        check_int(OI_OK, oi_illuminate(&s, NULL, &il), "status");
        if (k == 0) {
            q[0] = 1;
            q[1] = q[2] = q[3] = 0;
        } else {
            for (i = 0; i < 4; i++) q[i] = qs[k][i];
        }
        rotate_ref(q, z, n);
        for (i = 0; i < 3; i++) {
            u_sun[i] = (double)s.sun_km[i] - (double)s.target_km[i];
            u_obs[i] = (double)s.observer_km[i] - (double)s.target_km[i];
        }
        d = sqrt(dot3(u_sun, u_sun));
        for (i = 0; i < 3; i++) u_sun[i] /= d;
        d = sqrt(dot3(u_obs, u_obs));
        for (i = 0; i < 3; i++) u_obs[i] /= d;
        ci = dot3(n, u_sun);
        co = dot3(n, u_obs);
        want = (ci > 0 && co > 0) ? (double)il.e_sun * ci * 0.3 / PI * 1.0 * co /
                                        (d * 1000.0 * d * 1000.0)
                                  : 0.0;
        check_close(want, (double)il.flux_sun, 1e-300, REL_TOL * 10, "plate flux_sun");
        check_close(want, (double)il.flux_obs, 1e-300, REL_TOL * 10, "plate flux_obs");
        check_close(0.0, (double)il.flux_specular, 0.0, 0.0, "plate has no specular part");
    }
}

/* Moonlight on a plate: the same closed form with e_moon and dir_moon (the
 * Moon a point source), and the Sun's term off. */
static void test_moonlit_plate_closed_form(void **state)
{
#ifndef OI_NO_MOON
    oi_scene s;
    oi_illum il;
    double u_obs[3], d, ci, co, want; /* the plate's normal is +z */
    int i;
    (void)state;
    leo_scene(&s, OI_TERM_MOON);
    set3(s.moon_km, 100000.0, 250000.0, 280000.0);
    s.shape = oi_shape_find("plate");
    check_int(OI_OK, oi_illuminate(&s, NULL, &il), "status");
    assert_true(il.e_moon > 0);
    for (i = 0; i < 3; i++) u_obs[i] = (double)s.observer_km[i] - (double)s.target_km[i];
    d = sqrt(dot3(u_obs, u_obs));
    ci = (double)il.dir_moon[2];
    co = u_obs[2] / d;
    want = (double)il.e_moon * ci * 0.3 / PI * co / (d * 1000.0 * d * 1000.0);
    assert_true(ci > 0 && co > 0);
    check_close(want, (double)il.flux_moon, 1e-300, REL_TOL * 10, "plate flux_moon");
    check_close(0.0, (double)il.flux_sun, 0.0, 0.0, "no Sun term");
    check_close(want, (double)il.flux_obs, 1e-300, REL_TOL * 10, "plate flux_obs");
#else
    (void)state;
#endif
}

/* Far field: the Earth a point at the nadir, plate irradiance (R/r)^2
 * p(theta) max(0, -n_z) (the Lambert sphere's phase function p). */
static void test_plate_far_field(void **state)
{
    const double R = 6378.137, h = 1e9, r = R + h;
    const double thetas[3] = {0.0, 1.0, 2.5};
    const double normals[3][3] = {{0, 0, -1}, {0.6, 0, -0.8}, {0, 0.8, -0.6}};
    int a, b;
    (void)state;
    for (a = 0; a < 3; a++)
        for (b = 0; b < 3; b++) {
            oi_real nrm[3], e = (oi_real)-1;
            const double t = thetas[a];
            const double p = 2.0 / (3.0 * PI) * ((PI - t) * cos(t) + sin(t));
            set3(nrm, normals[b][0], normals[b][1], normals[b][2]);
            check_int(ST_EARTH, oi_earthshine_plate((oi_real)t, (oi_real)h, nrm, NULL, &e),
                      "status");
            /* the Earth's angular radius 6e-6 rad: relative corrections of
             * that order */
            check_rel((R / r) * (R / r) * p * -normals[b][2], (double)e, 1e-4, "far-field plate");
        }
}

/* OI_EARTH_REFLECT_MEAN: phi max(0, n . d), d = (sin psi, 0, -cos psi). */
static void test_plate_mean_direction(void **state)
{
    oi_model m;
    oi_real phi, psi, nrm[3], e;
    const double n[3] = {0.3, -0.2, -0.9327379053088815};
    (void)state;
    memset(&m, 0, sizeof m);
    m.earth_reflection = OI_EARTH_REFLECT_MEAN;
    check_int(ST_EARTH, oi_earthshine((oi_real)1.2, (oi_real)500, &m, &phi, &psi), "phi");
    set3(nrm, n[0], n[1], n[2]);
    check_int(ST_EARTH, oi_earthshine_plate((oi_real)1.2, (oi_real)500, nrm, &m, &e), "status");
    check_rel((double)phi * (n[0] * sin((double)psi) - n[2] * cos((double)psi)), (double)e,
              REL_TOL * 10, "mean direction plate");
    /* a face turned away from the mean direction gets nothing */
    set3(nrm, 0, 0, 1);
    check_int(ST_EARTH, oi_earthshine_plate((oi_real)1.2, (oi_real)500, nrm, &m, &e), "status");
    check_close(0.0, (double)e, 0.0, 0.0, "zenith-facing plate, mean direction");
}

/* Closed forms of the cubature: a nadir plate over a fully lit cap at theta
 * = 0 is the vector irradiance of a uniformly lit Lambertian disc seen...
 * here the simpler exact check: a horizontal plate (normal along +-y, the
 * mirror plane's normal) gets the same from both sides, and the upward face
 * of a target above the whole cap gets nothing. */
static void test_plate_symmetries(void **state)
{
    oi_real a[3], b[3], ea, eb;
    (void)state;
    set3(a, 0.3, 0.5, -0.2);
    set3(b, 0.3, -0.5, -0.2);
    check_int(ST_EARTH, oi_earthshine_plate((oi_real)1.3, (oi_real)700, a, NULL, &ea), "a");
    check_int(ST_EARTH, oi_earthshine_plate((oi_real)1.3, (oi_real)700, b, NULL, &eb), "b");
    check_rel((double)ea, (double)eb, REL_TOL * 100, "mirror symmetry");
    set3(a, 0.0, 0.0, 1.0);
    check_int(ST_EARTH, oi_earthshine_plate((oi_real)0.5, (oi_real)700, a, NULL, &ea), "up");
    check_close(0.0, (double)ea, 0.0, 0.0, "the zenith face sees no Earth");
    /* the night side: no lit Earth in view */
    set3(a, 0.0, 0.0, -1.0);
    check_int(ST_EARTH, oi_earthshine_plate((oi_real)3.0, (oi_real)700, a, NULL, &ea), "night");
    check_close(0.0, (double)ea, 0.0, 0.0, "night side");
}

/* Reciprocity f(a, b) = f(b, a) and the Phong lobe's peak. */
static void test_brdf_reciprocity(void **state)
{
    uint64_t seed = 12345;
    oi_facet f;
    int k;
    (void)state;
    memset(&f, 0, sizeof f);
    set3(f.normal, 0.1, -0.2, 1.0);
    f.area_m2 = 1;
    f.albedo_diffuse = (oi_real)0.2;
    f.albedo_specular = (oi_real)0.7;
    f.shininess = (oi_real)50;
    for (k = 0; k < 200; k++) {
        oi_real a[3], b[3], fab, fba;
        set3(a, lcg01(&seed) - 0.5, lcg01(&seed) - 0.5, lcg01(&seed));
        set3(b, lcg01(&seed) - 0.5, lcg01(&seed) - 0.5, lcg01(&seed));
        fab = oi_facet_brdf(&f, a, b);
        fba = oi_facet_brdf(&f, b, a);
        check_close((double)fab, (double)fba, 1e-300, REL_TOL * 100, "reciprocity");
    }
    {
        /* at the mirror direction: albedo_d / pi + albedo_s (n + 2) / (2 pi) */
        oi_real a[3], b[3];
        set3(f.normal, 0, 0, 1);
        set3(a, 0.6, 0, 0.8);
        set3(b, -0.6, 0, 0.8);
        check_rel(0.2 / PI + 0.7 * 52.0 / (2 * PI), (double)oi_facet_brdf(&f, a, b),
                  REL_TOL * 10, "peak");
        set3(b, -0.6, 0, -0.8);
        check_close(0.0, (double)oi_facet_brdf(&f, a, b), 0.0, 0.0, "observer behind");
        f.two_sided = 1;
        set3(a, 0.6, 0, -0.8);
        set3(b, -0.6, 0, -0.8);
        check_rel(0.2 / PI + 0.7 * 52.0 / (2 * PI), (double)oi_facet_brdf(&f, a, b),
                  REL_TOL * 10, "two-sided back face");
    }
}

/* Energy: the directional albedo int f cos(o) dOmega over the hemisphere is
 * at most albedo_diffuse + albedo_specular at every incidence, and equals it
 * at normal incidence (midpoint rule in cos(o) and azimuth, fine enough
 * for shininess up to 100 to 2e-3). */
static void test_brdf_energy(void **state)
{
    const double shin[4] = {0.0, 3.0, 30.0, 100.0};
    const double inc[5] = {0.0, 0.5, 1.0, 1.3, 1.55};
    const int nu = 1500, nphi = 600;
    int a, b, i, j;
    (void)state;
    for (a = 0; a < 4; a++)
        for (b = 0; b < 5; b++) {
            oi_facet f;
            oi_real in[3];
            double sum = 0;
            memset(&f, 0, sizeof f);
            set3(f.normal, 0, 0, 1);
            f.area_m2 = 1;
            f.albedo_diffuse = (oi_real)0.25;
            f.albedo_specular = (oi_real)0.75;
            f.shininess = (oi_real)shin[a];
            set3(in, sin(inc[b]), 0, cos(inc[b]));
            for (i = 0; i < nu; i++) {
                const double mu = (i + 0.5) / nu, st = sqrt(1 - mu * mu);
                for (j = 0; j < nphi; j++) {
                    const double ph = 2 * PI * (j + 0.5) / nphi;
                    oi_real out[3];
                    set3(out, st * cos(ph), st * sin(ph), mu);
                    /* dOmega = dmu dphi */
                    sum += (double)oi_facet_brdf(&f, in, out) * mu;
                }
            }
            sum *= (1.0 / nu) * (2 * PI / nphi);
            if (!(sum <= 1.0 + 2e-3)) {
                print_error("shininess %g incidence %g: albedo %.6f > 1\n", shin[a], inc[b], sum);
                fail();
            }
            if (b == 0) check_close(1.0, sum, 2e-3, 0.0, "albedo at normal incidence");
        }
}

/* Rotating every position and the attitude together changes no scalar output. */
static void test_rotation_invariance(void **state)
{
    const double q[4] = {0.7, 0.1, -0.5, 0.5};
    const double qn = sqrt(0.49 + 0.01 + 0.25 + 0.25);
    const double att[4] = {0.9, 0.3, 0.1, -0.3};
    const double an = sqrt(0.81 + 0.09 + 0.01 + 0.09);
    int k, i;
    (void)state;
    for (k = 0; k < 3; k++) {
        oi_scene s, t;
        oi_illum a, b;
        double rq[4], aq[4], prod[4], v[3], w[3];
        leo_scene(&s, OI_TERM_SUN | OI_TERM_EARTH);
        set3(s.sun_km, 1.2e8, 0.5e8, 0.7e8);
        s.shape = oi_shape_builtin(k);
        for (i = 0; i < 4; i++) {
            rq[i] = q[i] / qn;
            aq[i] = att[i] / an;
            s.attitude_q[i] = (oi_real)aq[i];
        }
        t = s;
        /* positions rotated by rq, attitude rq * aq */
        for (i = 0; i < 3; i++) v[i] = (double)s.sun_km[i];
        rotate_ref(rq, v, w);
        set3(t.sun_km, w[0], w[1], w[2]);
        for (i = 0; i < 3; i++) v[i] = (double)s.target_km[i];
        rotate_ref(rq, v, w);
        set3(t.target_km, w[0], w[1], w[2]);
        for (i = 0; i < 3; i++) v[i] = (double)s.observer_km[i];
        rotate_ref(rq, v, w);
        set3(t.observer_km, w[0], w[1], w[2]);
        prod[0] = rq[0] * aq[0] - rq[1] * aq[1] - rq[2] * aq[2] - rq[3] * aq[3];
        prod[1] = rq[0] * aq[1] + rq[1] * aq[0] + rq[2] * aq[3] - rq[3] * aq[2];
        prod[2] = rq[0] * aq[2] - rq[1] * aq[3] + rq[2] * aq[0] + rq[3] * aq[1];
        prod[3] = rq[0] * aq[3] + rq[1] * aq[2] - rq[2] * aq[1] + rq[3] * aq[0];
        for (i = 0; i < 4; i++) t.attitude_q[i] = (oi_real)prod[i];
        check_int(ST_EARTH, oi_illuminate(&s, NULL, &a), "s");
        check_int(ST_EARTH, oi_illuminate(&t, NULL, &b), "t");
        assert_true(a.flux_obs > 0);
#ifdef OI_SINGLE_PRECISION
        check_rel((double)a.flux_sun, (double)b.flux_sun, 2e-4, "flux_sun");
        check_rel((double)a.flux_earth, (double)b.flux_earth, 2e-3, "flux_earth");
        check_close((double)a.flux_specular, (double)b.flux_specular, 1e-4 * a.flux_obs, 2e-3,
                    "flux_specular");
#else
        check_rel((double)a.flux_sun, (double)b.flux_sun, 1e-9, "flux_sun");
        check_rel((double)a.flux_earth, (double)b.flux_earth, 1e-9, "flux_earth");
        check_close((double)a.flux_specular, (double)b.flux_specular, 1e-12 * a.flux_obs, 1e-9,
                    "flux_specular");
#endif
    }
}

/* The built-in shapes: names, checks, totals of their documented dimensions. */
static void test_builtin_shapes(void **state)
{
    const char *names[3] = {"plate", "box-wing", "cylinder"};
    const double area[3] = {1.0, 24.0 + 48.0, 12 * 2 * PI * 1.95 / 12 * 11.0 + 2 * PI * 1.95 * 1.95};
    int k;
    unsigned i;
    (void)state;
    for (k = 0; k < 3; k++) {
        const oi_shape *s = oi_shape_builtin(k);
        double sum = 0;
        assert_non_null(s);
        assert_ptr_equal(s, oi_shape_find(names[k]));
        assert_string_equal(s->name, names[k]);
        check_int(OI_OK, oi_shape_check(s), "check");
        for (i = 0; i < s->n_facets; i++) sum += (double)s->facets[i].area_m2;
        check_rel(area[k], sum, 1e-4, "total area");
    }
    assert_null(oi_shape_builtin(3));
    assert_null(oi_shape_builtin(-1));
    assert_null(oi_shape_find("sphere"));
    assert_null(oi_shape_find("Plate"));
    assert_null(oi_shape_find("plate "));
    assert_null(oi_shape_find(NULL));
    assert_int_equal(1, oi_shape_find("plate")->diffuse_from_scene);
}

static int zeroed(const oi_illum *il)
{
    const unsigned char *p = (const unsigned char *)il;
    size_t i;
    for (i = 0; i < sizeof *il; i++)
        if (p[i] != 0) return 0;
    return 1;
}

/* Hostile facets and quaternions: OI_ERR_SHAPE and zeroed outputs. */
static void test_hostile(void **state)
{
    oi_facet bad[12];
    oi_shape sh;
    oi_scene s;
    oi_illum il;
    int k;
    const double qbad[4][4] = {{NAN, 0, 0, 0}, {1.00001, 0, 0, 0}, {0.5, 0.5, 0.5, 0.4},
                               {INFINITY, 0, 0, 0}};
    (void)state;
    for (k = 0; k < 12; k++) {
        memset(&bad[k], 0, sizeof bad[k]);
        set3(bad[k].normal, 0, 0, 1);
        bad[k].area_m2 = 1;
        bad[k].albedo_diffuse = (oi_real)0.5;
    }
    set3(bad[0].normal, 0, 0, 0);
    bad[1].normal[1] = (oi_real)NAN;
    bad[2].area_m2 = -1;
    bad[3].area_m2 = 0;
    bad[4].albedo_diffuse = (oi_real)1.5;
    bad[5].albedo_specular = (oi_real)-0.1;
    bad[6].albedo_specular = (oi_real)0.6; /* 0.5 + 0.6 > 1 */
    bad[7].shininess = (oi_real)-1;
    bad[8].shininess = (oi_real)NAN;
    bad[9].albedo_diffuse = (oi_real)NAN;
    bad[10].normal[0] = (oi_real)INFINITY;
    bad[11].area_m2 = (oi_real)2e8;
    for (k = 0; k < 12; k++) {
        sh.facets = &bad[k];
        sh.n_facets = 1;
        sh.diffuse_from_scene = 0;
        sh.name = NULL;
        check_int(OI_ERR_SHAPE, oi_shape_check(&sh), "check");
        leo_scene(&s, OI_TERM_SUN | OI_TERM_EARTH);
        s.shape = &sh;
        memset(&il, 0x5a, sizeof il);
        check_int(OI_ERR_SHAPE, oi_illuminate(&s, NULL, &il), "illuminate");
        assert_true(zeroed(&il));
    }
    /* counts and NULL facets */
    sh.facets = &bad[11];
    sh.n_facets = 0;
    check_int(OI_ERR_SHAPE, oi_shape_check(&sh), "n 0");
    sh.n_facets = OI_FACETS_MAX + 1;
    check_int(OI_ERR_SHAPE, oi_shape_check(&sh), "n max + 1");
    sh.facets = NULL;
    sh.n_facets = 1;
    check_int(OI_ERR_NULL, oi_shape_check(&sh), "NULL facets");
    check_int(OI_ERR_NULL, oi_shape_check(NULL), "NULL shape");
    leo_scene(&s, OI_TERM_SUN | OI_TERM_EARTH);
    s.shape = &sh;
    check_int(OI_ERR_SHAPE, oi_illuminate(&s, NULL, &il), "NULL facets in a scene");
    assert_true(zeroed(&il));
    /* quaternions */
    for (k = 0; k < 4; k++) {
        int i;
        leo_scene(&s, OI_TERM_SUN | OI_TERM_EARTH);
        s.shape = oi_shape_find("box-wing");
        for (i = 0; i < 4; i++) s.attitude_q[i] = (oi_real)qbad[k][i];
        memset(&il, 0x5a, sizeof il);
        check_int(OI_ERR_SHAPE, oi_illuminate(&s, NULL, &il), "quaternion");
        assert_true(zeroed(&il));
    }
    /* a quaternion off by less than 1e-6 is normalised */
    leo_scene(&s, OI_TERM_SUN);
    s.shape = oi_shape_find("plate");
    s.attitude_q[0] = (oi_real)(1.0 + 5e-7);
    check_int(OI_OK, oi_illuminate(&s, NULL, &il), "near-unit quaternion");
    /* diffuse_from_scene: target_albedo plus a specular albedo above 1 */
    bad[11].area_m2 = 1;
    bad[11].albedo_specular = (oi_real)0.8;
    sh.facets = &bad[11];
    sh.n_facets = 1;
    sh.diffuse_from_scene = 1;
    bad[11].albedo_diffuse = (oi_real)5; /* replaced: not checked */
    check_int(OI_OK, oi_shape_check(&sh), "from scene");
    leo_scene(&s, OI_TERM_SUN);
    s.shape = &sh;
    s.target_albedo = (oi_real)0.3;
    check_int(OI_ERR_SHAPE, oi_illuminate(&s, NULL, &il), "0.3 + 0.8 > 1");
    s.target_albedo = (oi_real)0.2;
    check_int(OI_OK, oi_illuminate(&s, NULL, &il), "0.2 + 0.8 = 1");
    /* oi_earthshine_plate's own statuses */
    {
        oi_real n[3], e = 1;
        set3(n, 0, 0, 0);
        check_int(OI_ERR_ZERO_VECTOR, oi_earthshine_plate(1, 500, n, NULL, &e), "zero normal");
        check_close(0.0, (double)e, 0.0, 0.0, "zeroed");
        set3(n, 0, NAN, 0);
        check_int(OI_ERR_NONFINITE, oi_earthshine_plate(1, 500, n, NULL, &e), "NaN normal");
        set3(n, 0, 0, -1);
        check_int(OI_ERR_NULL, oi_earthshine_plate(1, 500, NULL, NULL, &e), "NULL normal");
        check_int(OI_ERR_NULL, oi_earthshine_plate(1, 500, n, NULL, NULL), "NULL out");
        check_int(OI_ERR_BELOW_SURFACE, oi_earthshine_plate(1, -1, n, NULL, &e), "below");
        check_int(OI_ERR_NONFINITE, oi_earthshine_plate(NAN, 500, n, NULL, &e), "NaN theta");
    }
    /* the BRDF of hostile input is 0 */
    {
        oi_facet f = bad[0];
        oi_real a[3], b[3];
        set3(a, 0, 0, 1);
        set3(b, 0, 0, 1);
        check_close(0.0, (double)oi_facet_brdf(&f, a, b), 0.0, 0.0, "zero normal brdf");
        check_close(0.0, (double)oi_facet_brdf(NULL, a, b), 0.0, 0.0, "NULL brdf");
    }
}

#ifndef OI_NO_EXPOSURE
/* A mirror-like facet turned to reflect the Sun to the observer glints; the
 * Lambertian plate never does. */
static void test_glint_flag(void **state)
{
    oi_facet mirror;
    oi_shape sh;
    oi_scene s;
    oi_illum il;
    oi_exposure ex;
    double u_sun[3], u_obs[3], h[3], n;
    int i;
    (void)state;
    leo_scene(&s, OI_TERM_SUN | OI_TERM_EARTH);
    for (i = 0; i < 3; i++) {
        u_sun[i] = (double)s.sun_km[i] - (double)s.target_km[i];
        u_obs[i] = (double)s.observer_km[i] - (double)s.target_km[i];
    }
    n = sqrt(dot3(u_sun, u_sun));
    for (i = 0; i < 3; i++) u_sun[i] /= n;
    n = sqrt(dot3(u_obs, u_obs));
    for (i = 0; i < 3; i++) u_obs[i] /= n;
    for (i = 0; i < 3; i++) h[i] = u_sun[i] + u_obs[i];
    memset(&mirror, 0, sizeof mirror);
    set3(mirror.normal, h[0], h[1], h[2]);
    mirror.area_m2 = 1;
    mirror.albedo_diffuse = (oi_real)0.1;
    mirror.albedo_specular = (oi_real)0.5;
    mirror.shininess = (oi_real)100;
    sh.facets = &mirror;
    sh.n_facets = 1;
    sh.diffuse_from_scene = 0;
    sh.name = "mirror";
    s.shape = &sh;
    check_int(ST_EARTH, oi_illuminate(&s, NULL, &il), "illuminate");
    assert_true(il.flux_specular > 0.5 * il.flux_obs);
    check_int(OI_OK, oi_expose_scene(oi_camera_builtin(0), &s, &il, NULL, NULL, &ex), "expose");
    assert_true((ex.flags & OI_FLAG_GLINT) != 0u);
    assert_string_equal("glint", oi_flag_name(OI_FLAG_GLINT));
    s.shape = oi_shape_find("plate");
    check_int(ST_EARTH, oi_illuminate(&s, NULL, &il), "plate");
    check_int(OI_OK, oi_expose_scene(oi_camera_builtin(0), &s, &il, NULL, NULL, &ex), "expose");
    assert_true((ex.flags & OI_FLAG_GLINT) == 0u);
    /* the sphere: never */
    s.shape = NULL;
    check_int(ST_EARTH, oi_illuminate(&s, NULL, &il), "sphere");
    check_close(0.0, (double)il.flux_specular, 0.0, 0.0, "sphere specular");
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sunlit_plate_closed_form),
        cmocka_unit_test(test_moonlit_plate_closed_form),
        cmocka_unit_test(test_plate_far_field),
        cmocka_unit_test(test_plate_mean_direction),
        cmocka_unit_test(test_plate_symmetries),
        cmocka_unit_test(test_brdf_reciprocity),
        cmocka_unit_test(test_brdf_energy),
        cmocka_unit_test(test_rotation_invariance),
        cmocka_unit_test(test_builtin_shapes),
        cmocka_unit_test(test_hostile),
#ifndef OI_NO_EXPOSURE
        cmocka_unit_test(test_glint_flag),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

#else /* OI_NO_FACETS */

/* Without facets a scene with a shape is refused. */
static void test_shape_refused(void **state)
{
    oi_scene s;
    oi_illum il;
    static const int dummy = 0;
    (void)state;
    oi_scene_defaults(&s);
    set3(s.sun_km, 1.495978707e8, 0.0, 0.0);
    set3(s.target_km, 0.0, 7000.0, 0.0);
    s.terms = OI_TERM_SUN;
    s.shape = (const struct oi_shape *)(const void *)&dummy;
    check_int(OI_ERR_SHAPE, oi_illuminate(&s, NULL, &il), "shape without facets");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shape_refused),
    };
    printf("skip test_facet: OI_NO_FACETS (only the refusal is tested)\n");
    return cmocka_run_group_tests(tests, NULL, NULL);
}

#endif /* OI_NO_FACETS */
