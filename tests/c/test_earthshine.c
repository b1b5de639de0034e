/* SPDX-License-Identifier: MIT */
/* test_earthshine.c: oi_earthshine (table lookup, far field, error paths)
 * against the quadrature reference values in ref_earthshine.h (written by
 * the reference generators of tests/ref; points off the table nodes,
 * independent of the tables and of the runtime's interpolation), closed forms written here, and a
 * hand-made table whose interpolant is known exactly. */
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
#include "oi_earth_leo.h"
#include "ref_earthshine.h"
#include "oi_earth_diffuse.h"

/* The model of the tests that read the default table oi_earth_diffuse:
 * NULL when it is the library's default; otherwise (OI_NO_EARTH_TABLE: no
 * default; -DOI_EARTH_TABLE_DEFAULT=another table) those tests pass
 * oi_earth_diffuse as a caller's table: the same lookup
 * (test_default_same_as_caller_table shows it bit for bit where it is the
 * default) and the same expected values. */
static oi_model def_model_storage;
static const oi_model *def_model(void)
{
    if (oi_earth_table_default() == &oi_earth_diffuse) return NULL;
    def_model_storage.earth_table = &oi_earth_diffuse;
    return &def_model_storage;
}
#define DEF (def_model())

/* m with its earthshine table left to the default oi_earth_diffuse (see
 * def_model) */
static void use_default_table(oi_model *m)
{
    if (oi_earth_table_default() != &oi_earth_diffuse) m->earth_table = &oi_earth_diffuse;
}

/* The accuracy goal of the default table: relative error <= 1e-3 where phi >= 1% of the
 * subsolar value phi0 at that altitude, absolute error <= 1e-5 phi0 elsewhere;
 * psi within 1e-3 rad where phi >= 1% phi0. In single precision the inputs
 * theta and h are rounded to float (theta by up to 1.9e-7 rad): near the
 * terminator d(ln phi)/d(theta) reaches ~100, hence an extra 5e-5 relative. */
#define GOAL_REL 1e-3
#define GOAL_ABS 1e-5
#define GOAL_PSI 1e-3
#ifdef OI_SINGLE_PRECISION
#define SLACK_REL 5e-5
#define EXACT_REL 2e-5
#else
#define SLACK_REL 0.0
#define EXACT_REL 1e-12
#endif

static const double PI = 3.14159265358979323846;
static const double RE = 6378.137;

static int check_goal(const char *what, const es_ref *r, double phi, double psi)
{
    double err = fabs(phi - r->phi);
    double tol;
    int ok = 1;
    if (r->phi >= 0.01 * r->phi0) {
        tol = (GOAL_REL + SLACK_REL) * r->phi;
        if (fabs(psi - r->psi) > GOAL_PSI + SLACK_REL) {
            print_error("%s psi theta=%.17g h=%.17g: want %.17g got %.17g\n", what, r->theta,
                        r->h_km, r->psi, psi);
            ok = 0;
        }
    } else {
        tol = GOAL_ABS * r->phi0 + SLACK_REL * r->phi;
    }
    if (!(err <= tol)) {
        print_error("%s phi theta=%.17g h=%.17g: want %.17g got %.17g (err %.3g, tol %.3g)\n",
                    what, r->theta, r->h_km, r->phi, phi, err, tol);
        ok = 0;
    }
    return ok;
}

static void check_close_rel(const char *what, double want, double got, double rel)
{
    if (!(fabs(got - want) <= rel * fabs(want) + 1e-300)) {
        print_error("%s: want %.17g got %.17g\n", what, want, got);
        fail();
    }
}

static double phase_ref(double t)
{
    return 2.0 / (3.0 * PI) * ((PI - t) * cos(t) + sin(t));
}

static void test_reference_points(void **state)
{
    size_t k, n = sizeof es_refs / sizeof es_refs[0];
    int bad = 0;
    (void)state;
    for (k = 0; k < n; k++) {
        oi_real phi = -1, psi = -1;
        int st = oi_earthshine((oi_real)es_refs[k].theta, (oi_real)es_refs[k].h_km, DEF, &phi, &psi);
        if (st != OI_OK) {
            print_error("status %d at theta=%.17g h=%.17g\n", st, es_refs[k].theta, es_refs[k].h_km);
            bad++;
            continue;
        }
        if (!check_goal("default table", &es_refs[k], (double)phi, (double)psi)) bad++;
    }
    assert_int_equal(bad, 0);
}

/* Below a table's altitude range (here the LEO scene table, 200-2000 km; the
 * default table reaches down to the surface): the far field with a warning. */
static void test_below_table_far_field(void **state)
{
    size_t k;
    oi_model m;
    (void)state;
    memset(&m, 0, sizeof m);
    m.earth_table = &oi_earth_leo;
    for (k = 0; k < sizeof es_below / sizeof es_below[0]; k++) {
        oi_real phi = -1, psi = -1;
        int st = oi_earthshine((oi_real)es_below[k].theta, (oi_real)es_below[k].h_km, &m, &phi, &psi);
        assert_int_equal(st, OI_WARN_TABLE_RANGE);
        check_close_rel("far field below the table", es_below[k].phi, (double)phi, EXACT_REL);
        assert_true(psi == 0);
    }
}

/* Near the surface (1 m .. 99 km) the default table answers with OI_OK and
 * meets the goal at the reference points of es_low. */
static void test_low_altitude(void **state)
{
    size_t k, n = sizeof es_low / sizeof es_low[0];
    int bad = 0;
    (void)state;
    for (k = 0; k < n; k++) {
        oi_real phi = -1, psi = -1;
        int st = oi_earthshine((oi_real)es_low[k].theta, (oi_real)es_low[k].h_km, DEF, &phi, &psi);
        if (st != OI_OK) {
            print_error("status %d at theta=%.17g h=%.17g\n", st, es_low[k].theta, es_low[k].h_km);
            bad++;
            continue;
        }
        if (!check_goal("default table, low altitude", &es_low[k], (double)phi, (double)psi)) bad++;
    }
    assert_int_equal(bad, 0);
}

/* The near-surface closed form: while the visible cap is wholly lit,
 * phi = cos(theta) phi(0, x) exactly, and phi(0, x) = x^2 (2 (1 - w) + O(w^2))
 * (a flat Lambertian plane gives 2 cos(theta); the sky band of the horizon's
 * depression w takes 2w): at 1 mm (w = 1.8e-5) the O(w^2) term is < 1e-9. */
static void test_flat_plane_limit(void **state)
{
    static const double hs[] = {1e-6, 3e-6, 1e-5};
    static const double th[] = {0.0, 0.3, 1.0, 1.4, 1.55};
    size_t a, b;
    (void)state;
    for (a = 0; a < sizeof hs / sizeof hs[0]; a++) {
        double w = atan2(sqrt(hs[a] * (2 * RE + hs[a])), RE);
        double x = RE / (RE + hs[a]);
        for (b = 0; b < sizeof th / sizeof th[0]; b++) {
            oi_real phi = -1, psi = -1;
            double want = x * x * 2.0 * (1.0 - w) * cos(th[b]);
            assert_int_equal(oi_earthshine((oi_real)th[b], (oi_real)hs[a], DEF, &phi, &psi), OI_OK);
            check_close_rel("flat-plane limit", want, (double)phi, GOAL_REL);
            assert_true(psi >= 0 && (double)psi < 1e-3);
        }
    }
}

static void test_theta_clamped(void **state)
{
    size_t k;
    (void)state;
    for (k = 0; k < sizeof es_clamped / sizeof es_clamped[0]; k++) {
        oi_real p1, s1, p2, s2;
        int st1 = oi_earthshine((oi_real)es_clamped[k].theta, (oi_real)es_clamped[k].h_km, DEF, &p1, &s1);
        int st2 = oi_earthshine((oi_real)es_clamped[k].phi, (oi_real)es_clamped[k].h_km, DEF, &p2, &s2);
        assert_int_equal(st1, st2);
        assert_true(p1 == p2 && s1 == s2);
    }
}

/* Beyond theta = pi/2 + w no lit point is visible: phi = 0 exactly. */
static void test_dark_side_exact_zero(void **state)
{
    static const double hs[] = {100.0, 400.0, 35786.0, 384400.0};
    size_t k;
    (void)state;
    for (k = 0; k < sizeof hs / sizeof hs[0]; k++) {
        double w = atan2(sqrt(hs[k] * (2 * RE + hs[k])), RE);
        oi_real phi = -1, psi = -1;
        assert_int_equal(oi_earthshine((oi_real)(PI / 2 + w + 1e-3), (oi_real)hs[k], DEF, &phi, &psi), OI_OK);
        assert_true(phi == 0 && psi == 0);
        assert_int_equal(oi_earthshine((oi_real)PI, (oi_real)hs[k], DEF, &phi, &psi), OI_OK);
        assert_true(phi == 0 && psi == 0);
    }
}

/* Far field chosen explicitly: OI_OK, (R/r)^2 p(theta), psi = 0. */
static void test_lambert_model(void **state)
{
    static const double th[] = {0.0, 0.7, 1.9, 3.0};
    oi_model m;
    size_t k;
    (void)state;
    memset(&m, 0, sizeof m);
    m.earth_model = OI_EARTH_LAMBERT;
    for (k = 0; k < sizeof th / sizeof th[0]; k++) {
        oi_real phi, psi;
        double x = RE / (RE + 1000.0);
        assert_int_equal(oi_earthshine((oi_real)th[k], OI_R(1000.0), &m, &phi, &psi), OI_OK);
        check_close_rel("explicit Lambert", x * x * phase_ref(th[k]), (double)phi, EXACT_REL);
        assert_true(psi == 0);
    }
}

/* Everywhere: phi >= 0, 0 <= psi <= asin(R/r) (the limb), status OK. */
static void test_sweep_bounds(void **state)
{
    int i, j;
    (void)state;
    for (j = 0; j <= 110; j++) {
        double h = 1e-3 * pow(10.0, j / 10.0); /* 1 m .. 1e8 km */
        double x = RE / (RE + h);
        for (i = 0; i <= 400; i++) {
            oi_real phi = -1, psi = -1;
            double th = PI * i / 400.0;
            assert_int_equal(oi_earthshine((oi_real)th, (oi_real)h, DEF, &phi, &psi), OI_OK);
            assert_true(phi >= 0 && psi >= 0);
            assert_true((double)psi <= asin(x) * (1 + 1e-6) + 1e-7);
            assert_true((double)phi <= 2.0 * x * x + 1e-12); /* q <= 2 (at the surface) */
        }
    }
}

/* The table is scale-free: (theta, h, R) and (theta, 2h, 2R) agree. */
static void test_radius_scaling(void **state)
{
    oi_model m;
    oi_real p1, s1, p2, s2;
    (void)state;
    memset(&m, 0, sizeof m);
    m.earth_radius_km = (oi_real)(2 * RE);
    use_default_table(&m);
    assert_int_equal(oi_earthshine(OI_R(1.3), OI_R(700.0), DEF, &p1, &s1), OI_OK);
    assert_int_equal(oi_earthshine(OI_R(1.3), OI_R(1400.0), &m, &p2, &s2), OI_OK);
    check_close_rel("scale-free phi", (double)p1, (double)p2, EXACT_REL * 10);
    check_close_rel("scale-free psi", (double)s1, (double)s2, EXACT_REL * 10);
}

/* A hand-made table, values linear in the node coordinates: Catmull-Rom with
 * linearly extrapolated ghosts reproduces them exactly, so (format 4) the lit
 * segment gives phi = x^2 cos(theta) (a + b v + c s) and psi = atan2(G w
 * sin(theta), cos(theta)) with G / w = 0.02 v, the terminator segment
 * phi = x^2 w (a + b v + c s), with v, s the fractional grid positions
 * computed here. */
static const float hand_q[3 * 7] = {
    /* s = 0 */ 1.0f, 1.5f, 2.0f, /* term */ 2.0f, 3.0f, 4.0f, 5.0f,
    /* s = .5*/ 1.5f, 2.0f, 2.5f, 2.5f, 3.5f, 4.5f, 5.5f,
    /* s = 1 */ 2.0f, 2.5f, 3.0f, 3.0f, 4.0f, 5.0f, 6.0f,
};
static const float hand_psi[3 * 7] = {
    0.0f, 0.01f, 0.02f, 0.02f, 0.03f, 0.04f, 0.05f,
    0.0f, 0.01f, 0.02f, 0.02f, 0.03f, 0.04f, 0.05f,
    0.0f, 0.01f, 0.02f, 0.02f, 0.03f, 0.04f, 0.05f,
};

static void test_hand_table(void **state)
{
    oi_earth_table t;
    oi_model m;
    static const double hs[] = {800.0, 1500.0, 3333.0};
    static const double fr[] = {0.1, 0.5, 0.9};
    size_t a, b;
    (void)state;
    memset(&t, 0, sizeof t);
    t.format = OI_TABLE_FORMAT;
    t.n_lit = 3;
    t.n_term = 4;
    t.n_alt = 3;
    t.w_min = atan2(sqrt(700.0 * (2 * RE + 700.0)), RE);
    t.w_max = atan2(sqrt(4000.0 * (2 * RE + 4000.0)), RE);
    t.q = hand_q;
    t.psi = hand_psi;
    memset(&m, 0, sizeof m);
    m.earth_table = &t;
    for (a = 0; a < 3; a++) {
        double h = hs[a];
        double w = atan2(sqrt(h * (2 * RE + h)), RE);
        double s = (w - t.w_min) / (t.w_max - t.w_min); /* 0..1 over 2 cells */
        double x = RE / (RE + h);
        for (b = 0; b < 3; b++) {
            oi_real phi, psi;
            /* lit segment: v in [0, 1] over 2 cells; q = 1 + v + s */
            double th = fr[b] * (PI / 2 - w);
            assert_int_equal(oi_earthshine((oi_real)th, (oi_real)h, &m, &phi, &psi), OI_OK);
            check_close_rel("hand table lit", x * x * cos(th) * (1.0 + fr[b] + s), (double)phi,
                      EXACT_REL * 10);
            check_close_rel("hand table lit psi", atan2((double)0.02f * fr[b] * w * sin(th), cos(th)),
                      (double)psi, EXACT_REL * 10);
            /* terminator segment: v over 3 cells; q / w = 2 + 3 v + s */
            th = PI / 2 - w + 2 * w * fr[b];
            assert_int_equal(oi_earthshine((oi_real)th, (oi_real)h, &m, &phi, &psi), OI_OK);
            check_close_rel("hand table term", x * x * w * (2.0 + 3 * fr[b] + s), (double)phi,
                      EXACT_REL * 100);
        }
    }
    /* graded terminator map: theta = pi/2 + w sinh(k t)/sinh(k), k = k0 x^kp,
     * v = (t + 1)/2; q stays linear in v */
    t.term_k0 = 2.0;
    t.term_kp = 1.5;
    for (a = 0; a < 3; a++) {
        double h = hs[a];
        double w = atan2(sqrt(h * (2 * RE + h)), RE);
        double s = (w - t.w_min) / (t.w_max - t.w_min);
        double x = RE / (RE + h);
        double k = 2.0 * pow(x, 1.5);
        for (b = 0; b < 3; b++) {
            oi_real phi, psi;
            double tt = 2 * fr[b] - 1;
            double th = PI / 2 + w * sinh(k * tt) / sinh(k);
            assert_int_equal(oi_earthshine((oi_real)th, (oi_real)h, &m, &phi, &psi), OI_OK);
            check_close_rel("hand table graded term", x * x * w * (2.0 + 3 * fr[b] + s), (double)phi,
                      EXACT_REL * 100);
        }
    }
    t.term_k0 = 0.0;
    t.term_kp = 0.0;
    /* outside the table's altitudes: far field and a warning */
    {
        oi_real phi, psi;
        double x = RE / (RE + 500.0);
        assert_int_equal(oi_earthshine(OI_R(0.5), OI_R(500.0), &m, &phi, &psi), OI_WARN_TABLE_RANGE);
        check_close_rel("hand table below", x * x * phase_ref(0.5), (double)phi, EXACT_REL);
        x = RE / (RE + 5000.0);
        assert_int_equal(oi_earthshine(OI_R(0.5), OI_R(5000.0), &m, &phi, &psi), OI_WARN_TABLE_RANGE);
        check_close_rel("hand table above", x * x * phase_ref(0.5), (double)phi, EXACT_REL);
    }
    /* a table of another format, or with a bad grid, is a model error */
    {
        oi_real phi = 1, psi = 1;
        t.format = OI_TABLE_FORMAT + 1;
        assert_int_equal(oi_earthshine(OI_R(0.5), OI_R(1000.0), &m, &phi, &psi), OI_ERR_MODEL);
        assert_true(phi == 0 && psi == 0);
        t.format = OI_TABLE_FORMAT;
        t.n_alt = 1;
        assert_int_equal(oi_earthshine(OI_R(0.5), OI_R(1000.0), &m, &phi, &psi), OI_ERR_MODEL);
        t.n_alt = 3;
        t.w_max = 2.0;
        assert_int_equal(oi_earthshine(OI_R(0.5), OI_R(1000.0), &m, &phi, &psi), OI_ERR_MODEL);
        t.w_max = t.w_min;
        assert_int_equal(oi_earthshine(OI_R(0.5), OI_R(1000.0), &m, &phi, &psi), OI_ERR_MODEL);
        t.w_max = 1.0;
        t.term_k0 = -1.0;
        assert_int_equal(oi_earthshine(OI_R(0.5), OI_R(1000.0), &m, &phi, &psi), OI_ERR_MODEL);
        t.term_k0 = 0.0;
        t.q = NULL;
        assert_int_equal(oi_earthshine(OI_R(0.5), OI_R(1000.0), &m, &phi, &psi), OI_ERR_MODEL);
    }
}

/* A hand-made table from the surface (w_min = 0): its ghost row below w = 0
 * is extrapolated quadratically, so values quadratic in the altitude index
 * are reproduced exactly in the first cells. q0 = 1 + s^2 / 8 (lit),
 * q / w = 2 + s^2 / 8 (terminator), s = w / (w_max / 3). */
static const float surf_q[4 * 4] = {
    1.0f, 1.0f, 2.0f, 2.0f,
    1.125f, 1.125f, 2.125f, 2.125f,
    1.5f, 1.5f, 2.5f, 2.5f,
    2.125f, 2.125f, 3.125f, 3.125f,
};
static const float surf_psi[4 * 4] = {0};

static void test_surface_row_table(void **state)
{
    oi_earth_table t;
    oi_model m;
    static const double hs[] = {0.001, 1.0, 50.0, 150.0};
    size_t a;
    (void)state;
    memset(&t, 0, sizeof t);
    t.format = OI_TABLE_FORMAT;
    t.n_lit = 2;
    t.n_term = 2;
    t.n_alt = 4;
    t.w_min = 0.0;
    t.w_max = atan2(sqrt(4000.0 * (2 * RE + 4000.0)), RE);
    t.q = surf_q;
    t.psi = surf_psi;
    memset(&m, 0, sizeof m);
    m.earth_table = &t;
    for (a = 0; a < sizeof hs / sizeof hs[0]; a++) {
        double h = hs[a];
        double w = atan2(sqrt(h * (2 * RE + h)), RE);
        double s = w / (t.w_max / 3.0);
        double x = RE / (RE + h);
        double th = 0.4 * (PI / 2 - w);
        oi_real phi, psi;
        assert_int_equal(oi_earthshine((oi_real)th, (oi_real)h, &m, &phi, &psi), OI_OK);
        check_close_rel("surface table lit", x * x * cos(th) * (1.0 + 0.125 * s * s), (double)phi,
                  EXACT_REL * 10);
        th = PI / 2 + 0.3 * w;
        assert_int_equal(oi_earthshine((oi_real)th, (oi_real)h, &m, &phi, &psi), OI_OK);
        check_close_rel("surface table term", x * x * w * (2.0 + 0.125 * s * s), (double)phi,
                  EXACT_REL * 100);
    }
    {
        oi_real phi = 1, psi = 1;
        t.n_alt = 2; /* a surface row needs 3 rows for its ghost */
        assert_int_equal(oi_earthshine(OI_R(0.5), OI_R(100.0), &m, &phi, &psi), OI_ERR_MODEL);
        t.n_alt = 4;
        t.w_min = -0.1;
        assert_int_equal(oi_earthshine(OI_R(0.5), OI_R(100.0), &m, &phi, &psi), OI_ERR_MODEL);
    }
}

/* The LEO scene table (bake/config/scene_leo.json) through the same code:
 * within its band it meets the goal at the reference points; outside it the
 * far field is used with a warning. */
static void test_scene_table_leo(void **state)
{
    oi_model m;
    size_t k, n = sizeof es_refs / sizeof es_refs[0], used = 0;
    int bad = 0;
    (void)state;
    memset(&m, 0, sizeof m);
    m.earth_table = &oi_earth_leo;
    for (k = 0; k < n; k++) {
        oi_real phi, psi;
        int st;
        if (es_refs[k].h_km < 200.0 || es_refs[k].h_km > 2000.0) continue;
        st = oi_earthshine((oi_real)es_refs[k].theta, (oi_real)es_refs[k].h_km, &m, &phi, &psi);
        used++;
        if (st != OI_OK || !check_goal("LEO table", &es_refs[k], (double)phi, (double)psi)) bad++;
    }
    assert_int_equal(bad, 0);
    assert_true(used >= 30);
    {
        oi_real phi, psi;
        assert_int_equal(oi_earthshine(OI_R(1.0), OI_R(150.0), &m, &phi, &psi), OI_WARN_TABLE_RANGE);
        assert_int_equal(oi_earthshine(OI_R(1.0), OI_R(2500.0), &m, &phi, &psi), OI_WARN_TABLE_RANGE);
    }
}

static void test_errors(void **state)
{
    oi_real phi, psi;
    oi_model m;
    (void)state;
    phi = psi = 7;
    assert_int_equal(oi_earthshine(OI_R(1.0), OI_R(500.0), NULL, NULL, &psi), OI_ERR_NULL);
    assert_true(psi == 0);
    assert_int_equal(oi_earthshine(OI_R(1.0), OI_R(500.0), DEF, &phi, NULL), OI_ERR_NULL);
    assert_true(phi == 0);
    phi = psi = 7;
    assert_int_equal(oi_earthshine((oi_real)NAN, OI_R(500.0), DEF, &phi, &psi), OI_ERR_NONFINITE);
    assert_true(phi == 0 && psi == 0);
    phi = psi = 7;
    assert_int_equal(oi_earthshine(OI_R(1.0), (oi_real)NAN, DEF, &phi, &psi), OI_ERR_NONFINITE);
    assert_true(phi == 0 && psi == 0);
    assert_int_equal(oi_earthshine((oi_real)INFINITY, OI_R(500.0), DEF, &phi, &psi), OI_ERR_NONFINITE);
    assert_int_equal(oi_earthshine(OI_R(1.0), (oi_real)INFINITY, DEF, &phi, &psi), OI_ERR_NONFINITE);
    phi = psi = 7;
    assert_int_equal(oi_earthshine(OI_R(1.0), OI_R(0.0), DEF, &phi, &psi), OI_ERR_BELOW_SURFACE);
    assert_true(phi == 0 && psi == 0);
    assert_int_equal(oi_earthshine(OI_R(1.0), OI_R(-10.0), DEF, &phi, &psi), OI_ERR_BELOW_SURFACE);
    memset(&m, 0, sizeof m);
    m.earth_model = 7;
    phi = psi = 7;
    assert_int_equal(oi_earthshine(OI_R(1.0), OI_R(500.0), &m, &phi, &psi), OI_ERR_MODEL);
    assert_true(phi == 0 && psi == 0);
    memset(&m, 0, sizeof m);
    m.earth_radius_km = OI_R(-1.0);
    assert_int_equal(oi_earthshine(OI_R(1.0), OI_R(500.0), &m, &phi, &psi), OI_ERR_RADIUS);
    m.earth_radius_km = (oi_real)NAN;
    assert_int_equal(oi_earthshine(OI_R(1.0), OI_R(500.0), &m, &phi, &psi), OI_ERR_MODEL);
}

/* Huge finite altitudes stay finite (no overflow in sqrt(h (2R + h))). */
static void test_huge_altitude(void **state)
{
    oi_real phi = -1, psi = -1;
    (void)state;
#ifdef OI_SINGLE_PRECISION
    const oi_real h = 3e38f;
#else
    const oi_real h = 1e300;
#endif
    assert_int_equal(oi_earthshine(OI_R(0.5), h, DEF, &phi, &psi), OI_OK);
    assert_true(phi >= 0 && (double)phi < 1e-20 && psi == 0);
}

/* ---- Agreement with a straightforward lookup. old_* (the reference lookup)
 * does separate q and psi interpolations, atan2 for w and psi, pow for the
 * terminator map, sinh by two exponentials: a different code path from the
 * runtime's shared-stencil lookup, which must agree to within rounding. */
#include "oi_port.h"

#ifdef OI_SINGLE_PRECISION
#define OLD_EDGE_TOL OI_R(1e-3)
#define OLD_ASINH_SERIES OI_R(0.125)
#define ULP_EPS 1.1920928955078125e-07
#else
#define OLD_EDGE_TOL OI_R(1e-9)
#define OLD_ASINH_SERIES OI_R(0.01)
#define ULP_EPS 2.220446049250313e-16
#endif

static void old_cr_weights(oi_real f, oi_real wt[4])
{
    const oi_real f2 = f * f;
    const oi_real f3 = f2 * f;
    wt[0] = OI_R(0.5) * (-f3 + OI_R(2.0) * f2 - f);
    wt[1] = OI_R(0.5) * (OI_R(3.0) * f3 - OI_R(5.0) * f2 + OI_R(2.0));
    wt[2] = OI_R(0.5) * (OI_R(-3.0) * f3 + OI_R(4.0) * f2 + f);
    wt[3] = OI_R(0.5) * (f3 - f2);
}

static oi_real old_seg_value(const float *row, int n, int c)
{
    if (c < 0) return OI_R(2.0) * (oi_real)row[0] - (oi_real)row[1];
    if (c >= n) return OI_R(2.0) * (oi_real)row[n - 1] - (oi_real)row[n - 2];
    return (oi_real)row[c];
}

static oi_real old_seg_row(const float *row, int n, int i, const oi_real wa[4])
{
    return wa[0] * old_seg_value(row, n, i - 1) + wa[1] * old_seg_value(row, n, i) +
           wa[2] * old_seg_value(row, n, i + 1) + wa[3] * old_seg_value(row, n, i + 2);
}

static int old_cell_of(oi_real f, int n, oi_real *frac)
{
    int i;
    if (f < (oi_real)0) f = (oi_real)0;
    if (f > (oi_real)(n - 1)) f = (oi_real)(n - 1);
    i = (int)OI_FLOOR(f);
    if (i > n - 2) i = n - 2;
    *frac = f - (oi_real)i;
    return i;
}

static oi_real old_seg_interp(const float *base, int ld, int off, int n, int n_alt,
                              int surface, oi_real fv, oi_real fw)
{
    oi_real wa[4], wb[4], r[4] = {0, 0, 0, 0}, fa, fb;
    int i = old_cell_of(fv, n, &fa);
    int j = old_cell_of(fw, n_alt, &fb);
    int k;
    old_cr_weights(fa, wa);
    old_cr_weights(fb, wb);
    for (k = 0; k < 4; k++) {
        int jj = j - 1 + k;
        if (jj >= 0 && jj < n_alt) r[k] = old_seg_row(base + (size_t)jj * (size_t)ld + (size_t)off, n, i, wa);
    }
    if (j - 1 < 0) {
        if (surface && n_alt >= 3) r[0] = OI_R(3.0) * (r[1] - r[2]) + r[3];
        else r[0] = OI_R(2.0) * r[1] - r[2];
    }
    if (j + 2 >= n_alt) r[3] = OI_R(2.0) * r[2] - r[1];
    return wb[0] * r[0] + wb[1] * r[1] + wb[2] * r[2] + wb[3] * r[3];
}

static oi_real old_asinh(oi_real z)
{
    const oi_real a = OI_FABS(z);
    oi_real r;
    if (a < OLD_ASINH_SERIES) {
        const oi_real z2 = z * z;
        return z * (OI_R(1.0) + z2 * (OI_R(-1.0) / OI_R(6.0) +
                    z2 * (OI_R(3.0) / OI_R(40.0) +
                    z2 * (OI_R(-15.0) / OI_R(336.0) + z2 * (OI_R(105.0) / OI_R(3456.0))))));
    }
    r = OI_LOG(a + OI_SQRT(a * a + OI_R(1.0)));
    return z < (oi_real)0 ? -r : r;
}

static oi_real old_sinh(oi_real k)
{
    if (k < OI_R(0.5)) {
        const oi_real k2 = k * k;
        return k * (OI_R(1.0) + k2 / OI_R(6.0) * (OI_R(1.0) + k2 / OI_R(20.0) *
                    (OI_R(1.0) + k2 / OI_R(42.0) * (OI_R(1.0) + k2 / OI_R(72.0) *
                    (OI_R(1.0) + k2 / OI_R(110.0) * (OI_R(1.0) + k2 / OI_R(156.0)))))));
    }
    return OI_R(0.5) * (OI_EXP(k) - OI_EXP(-k));
}

/* *noise (not in the old code): the rounding noise of t in units of epsilon.
 * asinh(z) = log(a + sqrt(a^2 + 1)) (a = |z| >= the series limit) rounds
 * its argument v ~ 1 + a to ~2 epsilon absolute: 2 / asinh(a) relative, so
 * one ulp of z (here from the new code's x^8 by squaring) can move t by that
 * much: up to ~200 ulp at a = 0.01. */
static oi_real old_term_t(oi_real m, oi_real x, const oi_earth_table *t, double *noise)
{
    oi_real k, z;
    *noise = 0;
    if (t->term_k0 <= 0.0) return m;
    k = (oi_real)t->term_k0 * OI_POW(x, (oi_real)t->term_kp);
    if (k < OI_R(1e-4)) return m;
    z = m * old_sinh(k);
    if (OI_FABS(z) >= OLD_ASINH_SERIES) *noise = 2.0 / fabs((double)old_asinh(z));
    return old_asinh(z) / k;
}

/* The old lookup for a valid table t, radius R, h > 0 (OI_OK cases only;
 * returns 0 outside the table's range). dw and dt (in units of the
 * precision's epsilon, 0 for the verbatim old code) perturb its coordinates
 * w and t relatively: they measure how sensitive its result is to rounding
 * in them. */
static int old_lookup(oi_real theta, oi_real h_km, oi_real R, const oi_earth_table *t,
                      double dw, double dt, oi_real *phi, oi_real *psi, double *t_noise)
{
    const oi_real half_pi = (oi_real)(0.5 * OI_PI);
    oi_real x, w, s, tb;
    *phi = 0;
    *psi = 0;
    *t_noise = 0;
    if (theta < (oi_real)0) theta = (oi_real)0;
    if (theta > OI_PI_R) theta = OI_PI_R;
    x = R / (R + h_km);
    s = OI_SQRT(h_km) * OI_SQRT(OI_R(2.0) * R + h_km);
    w = OI_ATAN2(s, R);
    w *= (oi_real)(1.0 + dw * ULP_EPS);
    {
        const oi_real w_min = (oi_real)t->w_min;
        const oi_real w_max = (oi_real)t->w_max;
        const oi_real cells = (oi_real)(t->n_alt - 1);
        const oi_real fw = (w - w_min) / (w_max - w_min) * cells;
        if (fw >= -OLD_EDGE_TOL && fw <= cells + OLD_EDGE_TOL) {
            const int ld = t->n_lit + t->n_term;
            const int surf = t->w_min == 0.0;
            oi_real q, p, fv;
            if (theta >= half_pi + w) return 1;
            tb = half_pi - w;
            if (theta <= tb && tb > (oi_real)0) {
                const int n = t->n_lit;
                const oi_real ct = OI_COS(theta);
                fv = theta / tb * (oi_real)(n - 1);
                q = old_seg_interp(t->q, ld, 0, n, t->n_alt, surf, fv, fw) * ct;
                p = old_seg_interp(t->psi, ld, 0, n, t->n_alt, surf, fv, fw) * w;
                p = OI_ATAN2(p * OI_SIN(theta), ct);
            } else {
                const int n = t->n_term;
                oi_real mm = (theta - half_pi) / w;
                if (mm > OI_R(1.0)) mm = OI_R(1.0);
                if (mm < OI_R(-1.0)) mm = OI_R(-1.0);
                fv = OI_R(0.5) * (old_term_t(mm, x, t, t_noise) * (oi_real)(1.0 + dt * ULP_EPS) + OI_R(1.0)) *
                     (oi_real)(n - 1);
                q = old_seg_interp(t->q, ld, t->n_lit, n, t->n_alt, surf, fv, fw) * w;
                p = old_seg_interp(t->psi, ld, t->n_lit, n, t->n_alt, surf, fv, fw);
            }
            if (q < (oi_real)0) q = (oi_real)0;
            if (p < (oi_real)0) p = (oi_real)0;
            if (p > tb) p = tb;
            *phi = q * x * x;
            *psi = *phi > (oi_real)0 ? p : (oi_real)0;
            return 1;
        }
    }
    return 0;
}


/* Tolerance of the agreement: 8 ulp of the old value, plus the old code's
 * own spread when its coordinates w and t move by the rounding the new
 * code's cheaper forms may add (atan(s / R) for atan2(s, R): 2 ulp of w; x^8
 * by squaring, one exponential: 8 ulp of t, plus the old asinh's own noise,
 * see old_term_t). The spread matters where the result is ill-conditioned in
 * its coordinates: at the dark edge of the terminator (phi ~ 1e-9 phi0,
 * summed from node values ~1e5 times larger) and near w = pi/2 (x = cos w:
 * one ulp of w moves psi ~ x by tan(w) ulp). */
static double agree_tol(oi_real th, oi_real h, oi_real R, const oi_earth_table *t, int which,
                        double old, double t_noise)
{
    const double dws[2] = {2.0, -2.0}, dts[2] = {8.0 + 2.0 * t_noise, -8.0 - 2.0 * t_noise};
    double tol = 8.0 * ULP_EPS * fabs(old);
    int k;
    for (k = 0; k < 4; k++) {
        oi_real p, s;
        double v, tn;
        (void)old_lookup(th, h, R, t, k < 2 ? dws[k] : 0.0, k < 2 ? 0.0 : dts[k - 2], &p, &s, &tn);
        v = which == 0 ? (double)p : (double)s;
        tol += fabs(v - old);
    }
    return tol;
}

/* New lookup (oi_earthshine with model m) against the old one over npts
 * random points, h log-uniform in [hlo, hhi] km, theta uniform in [0, pi]
 * or, for a quarter each, in the terminator band pi/2 +- w and next to its
 * far edge pi/2 + w (the arctangent-free test of src/sources/earthshine_table.c); returns the
 * number of disagreements (printed); *worst = max |new - old| / tol. */
static int agreement(const oi_earth_table *t, const oi_model *m, oi_real R, double hlo,
                     double hhi, int npts, double *worst)
{
    uint64_t st = 20261122u;
    int k, bad = 0;
    *worst = 0;
    for (k = 0; k < npts; k++) {
        const double hd = hlo * pow(hhi / hlo, lcg01(&st));
        const double wd = acos((double)R / ((double)R + hd));
        const double u = lcg01(&st);
        const oi_real h = (oi_real)hd;
        /* a quarter at the far edge of the cap, theta = pi/2 + w (1 +- 10^-12u) */
        const double edge = PI / 2 + wd * (1.0 + (k & 1 ? 1 : -1) * pow(10.0, -12.0 * u));
        const oi_real th = (oi_real)(k % 4 == 3 ? edge : k % 4 == 2 ? PI / 2 + wd * (2 * u - 1) : PI * u);
        oi_real p0, s0, p1, s1;
        double tn;
        int q;
        if (!old_lookup(th, h, R, t, 0.0, 0.0, &p0, &s0, &tn)) continue;
        assert_int_equal(oi_earthshine(th, h, m, &p1, &s1), OI_OK);
        for (q = 0; q < 2; q++) {
            const double want = q == 0 ? (double)p0 : (double)s0;
            const double got = q == 0 ? (double)p1 : (double)s1;
            const double d = fabs(got - want);
            double tol;
            /* psi is set to 0 where phi = 0: at the cap's far edge, where phi
             * is zero in one code and tiny in the other (the phi comparison
             * covers that), psi is not compared */
            if (d == 0 || (q == 1 && (p0 == 0 || p1 == 0))) continue;
            tol = agree_tol(th, h, R, t, q, want, tn);
            if (d / tol > *worst) *worst = d / tol;
            if (!(d <= tol)) {
                if (bad < 10)
                    print_error("%s theta=%.17g h=%.17g: want %.17g got %.17g (tol %.3g)\n",
                                q == 0 ? "phi" : "psi", (double)th, (double)h, want, got, tol);
                bad++;
            }
        }
    }
    return bad;
}

/* The shared-stencil lookup agrees with the reference lookup to
 * rounding: default table (the trusted default), the same table passed as
 * a caller's table (the validated, converted path), the LEO scene table
 * (another grid, w_min > 0) and a model radius other than the default. */
static void test_agrees_with_reference_lookup(void **state)
{
    oi_earth_table copy = oi_earth_diffuse;
    oi_model m;
    double worst;
    (void)state;
    assert_int_equal(agreement(&oi_earth_diffuse, DEF, (oi_real)RE, 1e-3, 1e7, 150000, &worst), 0);
    memset(&m, 0, sizeof m);
    m.earth_table = &copy;
    assert_int_equal(agreement(&copy, &m, (oi_real)RE, 1e-3, 1e7, 30000, &worst), 0);
    m.earth_table = &oi_earth_leo;
    assert_int_equal(agreement(&oi_earth_leo, &m, (oi_real)RE, 150.0, 2500.0, 60000, &worst), 0);
    memset(&m, 0, sizeof m);
    m.earth_radius_km = OI_R(1737.4);
    use_default_table(&m);
    assert_int_equal(agreement(&oi_earth_diffuse, &m, OI_R(1737.4), 1e-3, 1e6, 30000, &worst), 0);
}

/* The default table (oi_earth_table_default, trusted: not checked) and the
 * same table passed as a caller's table (checked) must give the same
 * lookup, bit for bit. */
static void test_default_same_as_caller_table(void **state)
{
    oi_earth_table copy = oi_earth_diffuse;
    oi_model m;
    uint64_t st = 7u;
    int k;
    (void)state;
    if (oi_earth_table_default() != &oi_earth_diffuse) {
        printf("test_default_same_as_caller_table: oi_earth_diffuse is not the default, nothing to "
               "compare\n");
        return;
    }
    assert_true(oi_earth_diffuse.w_min == 0.0 && oi_earth_diffuse.w_max == 1.5707963267948966);
    assert_true(oi_earth_diffuse.term_k0 == 2.0 && oi_earth_diffuse.term_kp == 8.0);
    assert_true(oi_earth_diffuse.kind == 0 || oi_earth_diffuse.kind == OI_TABLE_KIND_EARTHSHINE);
    memset(&m, 0, sizeof m);
    m.earth_table = &copy;
    for (k = 0; k < 50000; k++) {
        const oi_real h = (oi_real)(1e-3 * pow(1e10, lcg01(&st)));
        const oi_real th = (oi_real)(PI * lcg01(&st));
        oi_real p0, s0, p1, s1;
        assert_int_equal(oi_earthshine(th, h, NULL, &p0, &s0), OI_OK);
        assert_int_equal(oi_earthshine(th, h, &m, &p1, &s1), OI_OK);
        if (p0 != p1 || s0 != s1) {
            print_error("theta=%.17g h=%.17g: want %.17g %.17g got %.17g %.17g\n", (double)th,
                        (double)h, (double)p1, (double)s1, (double)p0, (double)s0);
            fail();
        }
    }
}

/* A caller's table is validated field by field (src/sources/earthshine_table.c compares the
 * double fields by their bit patterns): boundaries of every check. */
static void test_table_validation(void **state)
{
    oi_earth_table t;
    oi_model m;
    oi_real phi, psi;
    const double lim = 0.5 * 3.14159265358979323846 * (1.0 + 1e-15);
    (void)state;
    memset(&m, 0, sizeof m);
    m.earth_table = &t;
#define VALID(expect)                                                                          \
    do {                                                                                       \
        phi = psi = 7;                                                                         \
        assert_int_equal(oi_earthshine(OI_R(1.0), OI_R(500.0), &m, &phi, &psi), (expect));     \
        if ((expect) < 0) assert_true(phi == 0 && psi == 0);                                   \
    } while (0)
    t = oi_earth_leo;
    VALID(OI_OK);
    t.w_min = -0.0; /* -0 >= 0 */
    VALID(OI_OK);
    t.w_min = -1e-300;
    VALID(OI_ERR_MODEL);
    t.w_min = NAN;
    VALID(OI_ERR_MODEL);
    t = oi_earth_leo;
    t.w_max = t.w_min; /* w_max > w_min */
    VALID(OI_ERR_MODEL);
    t.w_max = NAN;
    VALID(OI_ERR_MODEL);
    t.w_max = INFINITY;
    VALID(OI_ERR_MODEL);
    t.w_max = -0.5;
    VALID(OI_ERR_MODEL);
    t.w_max = lim; /* <= (pi/2)(1 + 1e-15) */
    VALID(OI_OK);
    t.w_max = nextafter(lim, 2.0);
    VALID(OI_ERR_MODEL);
    t = oi_earth_leo;
    t.w_min = INFINITY;
    VALID(OI_ERR_MODEL);
    t = oi_earth_leo;
    t.term_k0 = 20.0;
    VALID(OI_OK);
    t.term_k0 = nextafter(20.0, 21.0);
    VALID(OI_ERR_MODEL);
    t.term_k0 = -0.0;
    VALID(OI_OK);
    t.term_k0 = -1e-300;
    VALID(OI_ERR_MODEL);
    t.term_k0 = NAN;
    VALID(OI_ERR_MODEL);
    t = oi_earth_leo;
    t.term_kp = 100.0;
    VALID(OI_OK);
    t.term_kp = nextafter(100.0, 101.0);
    VALID(OI_ERR_MODEL);
    t.term_kp = -2.0;
    VALID(OI_ERR_MODEL);
    t.term_kp = INFINITY;
    VALID(OI_ERR_MODEL);
    t = oi_earth_leo;
    t.w_min = 0.0; /* a surface row needs n_alt >= 3 */
    t.n_alt = 2;
    VALID(OI_ERR_MODEL);
    t.n_alt = 3;
    VALID(OI_OK);
    t = oi_earth_leo;
    t.format = OI_TABLE_FORMAT + 1;
    VALID(OI_ERR_MODEL);
#undef VALID
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reference_points),
        cmocka_unit_test(test_below_table_far_field),
        cmocka_unit_test(test_low_altitude),
        cmocka_unit_test(test_flat_plane_limit),
        cmocka_unit_test(test_theta_clamped),
        cmocka_unit_test(test_dark_side_exact_zero),
        cmocka_unit_test(test_lambert_model),
        cmocka_unit_test(test_sweep_bounds),
        cmocka_unit_test(test_radius_scaling),
        cmocka_unit_test(test_hand_table),
        cmocka_unit_test(test_surface_row_table),
        cmocka_unit_test(test_scene_table_leo),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_huge_altitude),
        cmocka_unit_test(test_agrees_with_reference_lookup),
        cmocka_unit_test(test_default_same_as_caller_table),
        cmocka_unit_test(test_table_validation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
