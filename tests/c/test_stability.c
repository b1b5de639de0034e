/* SPDX-License-Identifier: MIT */
/*
 * test_stability.c: the stability suite, built per precision.
 *
 * 1. Test vectors from mpmath at 60 digits (tests/stability/gen_vectors.py ->
 *    tests/stability/vectors.h): phase angles within 1e-16..1e-8 of 0 and pi,
 *    collinear Sun-Earth-target on both sides, the umbra and penumbra edges
 *    approached from 1e-12 to 1e-3 rad on both sides and exactly, the axis in
 *    the umbra, the umbra's tip and beyond it, the Sun at 0.983 and 1.017 AU,
 *    altitudes 1 m .. 1e7 km, theta exactly 0, pi/2, pi, the Sun at 1 AU with
 *    a LEO target in single precision. Acceptance, per output:
 *        |got - want| <= GOAL |want| + spread
 *    GOAL = 1e-12 (double) / 1e-5 (single); spread is the conditioning term
 *    (vectors.h: the output's change for one input scaled by 1 +- 16 u, summed
 *    over the inputs), so an ill-conditioned output is bounded by its
 *    condition number and a well-conditioned one by GOAL.
 * 2. Hostile inputs: NaN, +-inf, +-0, subnormals and near-overflow values in
 *    every argument of every public function: a documented status, or finite
 *    outputs inside their physical ranges.
 * Each table prints one "STAB" line per output: the worst relative error over
 * the well-conditioned vectors (kappa <= 10), the worst err/tolerance over all
 * and the largest condition number met; tests/stability/report.py turns them
 * into the table of docs/stability.md.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "orbillum.h"
#include "../stability/vectors.h"

#ifdef OI_SINGLE_PRECISION
#define GOAL 1e-5
#define UNIT_ROUNDOFF 5.9604644775390625e-08 /* 2^-24 */
#define PREC "single"
#define VEC(name) name##_f
#define RMAX FLT_MAX
#define RMIN FLT_MIN
#define RTRUE_MIN (FLT_MIN * FLT_EPSILON)
#else
#define GOAL 1e-12
#define UNIT_ROUNDOFF 1.1102230246251565e-16 /* 2^-53 */
#define PREC "double"
#define VEC(name) name##_d
#define RMAX DBL_MAX
#define RMIN DBL_MIN
#define RTRUE_MIN (DBL_MIN * DBL_EPSILON)
#endif
#define EPS_MULT 16.0 /* as gen_vectors.py */
/* pi rounded up in the precision, plus a few ulps: an upper bound for angles */
#define PI_UP (3.14159265358979323846 * (1 + 8 * UNIT_ROUNDOFF))
#define KAPPA_WELL 10.0
#define NELEM(a) (sizeof(a) / sizeof((a)[0]))

typedef int (*eval_fn)(const double *in, double *got, int *region);

/* ------------------------------------------------------------ evaluators */

#include "../stability/evaluators.h"

/* ------------------------------------------------------------ known issues
 *
 * Deviations found by this suite in code owned by others, reported to the
 * lead (docs/stability.md, "Findings"). Each entry widens the tolerance of the
 * matching vectors by a bound that states what the code achieves today; a
 * vector outside even that bound still fails. They are printed as KNOWN on
 * every run; STAB_STRICT=1 in the environment turns them into failures (the
 * regression test for the fix), and an entry no longer needed prints XPASS.
 */
typedef struct known_issue {
    const char *table;        /* table name */
    const char *output;       /* output name, or NULL for all */
    const char *label;        /* label prefix ("" for all) */
    double extra_abs_u;       /* extra absolute tolerance, in units of u */
    double extra_rel;         /* extra relative tolerance */
    const char *why;
} known_issue;

static const known_issue KNOWN[] = {
    /* No known deviation. The vectors keep guarding, as regressions: a
     * fraction formed as 1 - overlap/cap cancelling near the umbra edge
     * (src/shadow/sun_fraction.c), a coarse limb-darkening quadrature
     * (src/shadow/limb_darkening.c), the overlap of two hemispheres and of caps
     * beyond a hemisphere (src/math/cap_overlap.c), and rate_s = flux * area * k *
     * psf underflowing for the smallest subnormal fluxes when flux * area is
     * formed first (src/camera/expose.c: every SNR 0, the tie-break choosing the
     * shortest time). */
    {"", NULL, "", 0, 0, "no entry: matches no table"}
};

static int strict_mode(void)
{
    const char *e = getenv("STAB_STRICT");
    return e != NULL && e[0] == '1';
}

static const known_issue *find_known(const char *table, const char *output, const char *label)
{
    size_t i;
    if (strict_mode()) return NULL;
    for (i = 0; i < sizeof KNOWN / sizeof KNOWN[0]; i++) {
        const known_issue *k = &KNOWN[i];
        if (strcmp(k->table, table) != 0) continue;
        if (k->output != NULL && strcmp(k->output, output) != 0) continue;
        if (strncmp(k->label, label, strlen(k->label)) != 0) continue;
        return k;
    }
    return NULL;
}

/* ------------------------------------------------------------ driver */

static int run_table(const char *name, const stab_vec *v, size_t n, int nout,
                     const char *const *outs, eval_fn f)
{
    double worst_rel[STAB_MAX_OUT] = {0}, worst_ratio[STAB_MAX_OUT] = {0};
    double max_kappa[STAB_MAX_OUT] = {0};
    size_t n_well[STAB_MAX_OUT] = {0};
    int fails = 0, k;
    int known[STAB_MAX_OUT] = {0};
    size_t i;
    for (i = 0; i < n; i++) {
        double got[STAB_MAX_OUT];
        int region = -1;
        int st = f(v[i].in, got, &region);
        if (st < 0) { /* a warning (e.g. outside the atmosphere table) is a result */
            print_error("%s [%s] %s: status %d (%s)\n", name, PREC, v[i].label, st,
                        oi_status_name(st));
            fails++;
            continue;
        }
        if (v[i].region >= 0 && v[i].region_sure && region != v[i].region) {
            const known_issue *kn = find_known(name, "choice", v[i].label);
            if (kn != NULL) {
                printf("KNOWN %s [%s] %s: region (or choice) want %d got %d (%s)\n", name, PREC,
                       v[i].label, v[i].region, region, kn->why);
            } else {
                print_error("%s [%s] %s: region (or choice) want %d got %d\n", name, PREC,
                            v[i].label, v[i].region, region);
                fails++;
            }
        }
        for (k = 0; k < nout; k++) {
            double want = v[i].want[k], err = fabs(got[k] - want);
            double tol = GOAL * fabs(want) + v[i].spread[k];
            double kappa = want != 0 ? v[i].spread[k] / (EPS_MULT * UNIT_ROUNDOFF * fabs(want)) : 0;
            double ratio = tol > 0 ? err / tol : (err == 0 ? 0 : HUGE_VAL);
            if (!isfinite(got[k]) || !(err <= tol)) {
                const known_issue *kn = find_known(name, outs[k], v[i].label);
                double tol2 = kn ? tol + kn->extra_abs_u * UNIT_ROUNDOFF + kn->extra_rel * fabs(want)
                                 : tol;
                if (kn != NULL && isfinite(got[k]) && err <= tol2) {
                    printf("KNOWN %s.%s [%s] %s: want %.17g got %.17g err %.3g tol %.3g (%s)\n",
                           name, outs[k], PREC, v[i].label, want, got[k], err, tol, kn->why);
                    known[k]++;
                    continue; /* not counted in the worst errors */
                } else {
                    print_error("%s.%s [%s] %s: want %.17g got %.17g err %.3g tol %.3g "
                                "(kappa %.3g)\n",
                                name, outs[k], PREC, v[i].label, want, got[k], err, tol, kappa);
                    fails++;
                }
            }
            if (ratio > worst_ratio[k]) worst_ratio[k] = ratio;
            if (kappa > max_kappa[k]) max_kappa[k] = kappa;
            if (kappa <= KAPPA_WELL && want != 0) {
                double rel = err / fabs(want);
                n_well[k]++;
                if (rel > worst_rel[k]) worst_rel[k] = rel;
            }
        }
    }
    for (k = 0; k < nout; k++)
        printf("STAB | %s.%s | %s | %zu | %zu | %.2e | %.3g | %.2e | %s |\n", name, outs[k], PREC,
               n, n_well[k], worst_rel[k], worst_ratio[k], max_kappa[k],
               fails ? "FAIL" : known[k] ? "known issue" : "ok");
    return fails;
}

#define RUN(name, nout, outs, f) \
    assert_int_equal(run_table(#name, VEC(stab_##name), NELEM(VEC(stab_##name)), nout, outs, f), 0)

static void test_phase(void **state)
{
    static const char *const o[] = {"p"};
    (void)state;
    RUN(phase, 1, o, ev_phase);
}

#ifndef OI_NO_MOON
static void test_moon(void **state)
{
    static const char *const o[] = {"law"};
    (void)state;
    RUN(moon, 1, o, ev_moon);
}
#endif

static void test_angle(void **state)
{
    static const char *const o[] = {"angle"};
    (void)state;
    RUN(angle, 1, o, ev_angle);
}

static void test_overlap(void **state)
{
    static const char *const o[] = {"area"};
    (void)state;
    RUN(overlap, 1, o, ev_overlap);
}

static void test_shadow(void **state)
{
    static const char *const o[] = {"fraction", "sun_radius", "earth_radius",
                                    "separation", "sun_distance", "fraction_ld"};
    (void)state;
#ifdef OI_NO_LIMB_DARKENING
    /* fraction_ld is the uniform disc's here (test_shadow checks that it
     * equals fraction): the limb-darkened references do not apply */
    RUN(shadow, 5, o, ev_shadow);
#else
    RUN(shadow, 6, o, ev_shadow);
#endif
}

static void test_magnitude(void **state)
{
    static const char *const o[] = {"mag_v"};
    (void)state;
    RUN(magnitude, 1, o, ev_magnitude);
}

static void test_earth_lambert(void **state)
{
    static const char *const o[] = {"phi"};
    (void)state;
    RUN(earth_lambert, 1, o, ev_earth_lambert);
}

static void test_illum(void **state)
{
    static const char *const o[] = {"e_sun", "e_earth", "earth_theta", "earth_h_km",
                                    "flux_sun", "mag_v", "flux_obs"};
    (void)state;
    RUN(illum, 7, o, ev_illum);
}

/* ------------------------------------------------------------ earthshine table
 *
 * At grid nodes the lookup returns the stored float32 value: error 1e-6
 * relative (3e-6 in single precision, where the node's coordinates are
 * themselves rounded) plus the conditioning term. Elsewhere the table's
 * documented goal (src/sources/earthshine.c note 2): 1e-3 relative where phi >= 1% of
 * phi(0, h), 1e-5 phi(0, h) absolute elsewhere (+1e-6 relative in single);
 * psi within 1e-6 rad (nodes) / 1e-3 rad (elsewhere) where phi >= 1% phi(0, h).
 * If the table was re-baked on another grid, the node vectors are checked
 * against the goal only (and a note says to rerun gen_vectors.py).
 */
#ifndef OI_NO_EARTH_TABLE
#include "oi_earth_diffuse.h"

static int same_grid(void)
{
    return oi_earth_diffuse.n_lit == STAB_ES_N_LIT && oi_earth_diffuse.n_term == STAB_ES_N_TERM &&
           oi_earth_diffuse.n_alt == STAB_ES_N_ALT && oi_earth_diffuse.w_min == STAB_ES_W_MIN &&
           oi_earth_diffuse.w_max == STAB_ES_W_MAX &&
           /* the terminator map of table format 3 (include/oi_table.h) */
           oi_earth_diffuse.term_k0 == STAB_ES_TERM_K0 &&
           oi_earth_diffuse.term_kp == STAB_ES_TERM_KP;
}

static void test_earth_table(void **state)
{
    const stab_vec *v = VEC(stab_earth_table);
    size_t i, n = NELEM(VEC(stab_earth_table));
    int fails = 0, known = 0, grid = same_grid();
    double worst_node = 0, worst_goal = 0, worst_psi = 0;
#ifdef OI_SINGLE_PRECISION
    const double node_rel = 3e-6, extra_rel = 1e-6;
#else
    const double node_rel = 1e-6, extra_rel = 0;
#endif
    (void)state;
    if (!grid) printf("NOTE earth_table: the table's grid changed: node vectors checked against "
                      "the goal only (rerun tests/stability/gen_vectors.py)\n");
    for (i = 0; i < n; i++) {
        oi_real phi, psi;
        int st = oi_earthshine((oi_real)v[i].in[0], (oi_real)v[i].in[1], NULL, &phi, &psi);
        double want = v[i].want[0], wpsi = v[i].want[1], phi0 = v[i].want[2];
        int node = grid && strncmp(v[i].label, "node", 4) == 0;
        int bright = want >= 0.01 * phi0;
        double err = fabs((double)phi - want), epsi = fabs((double)psi - wpsi), tol, tpsi;
        if (st != OI_OK) {
            const known_issue *kn = find_known("earth_table", "status", v[i].label);
            if (kn != NULL && st == OI_WARN_TABLE_RANGE) {
                printf("KNOWN earth_table [%s] %s: status %s (%s)\n", PREC, v[i].label,
                       oi_status_name(st), kn->why);
                known++;
                continue;
            }
            print_error("earth_table [%s] %s: status %d (%s)\n", PREC, v[i].label, st,
                        oi_status_name(st));
            fails++;
            continue;
        }
        if (node) /* dark nodes (below 1% of phi0): relative to 1% of phi0 */
            tol = node_rel * (bright ? want : 0.01 * phi0) + v[i].spread[0];
        else
            tol = (bright ? 1e-3 * want : 1e-5 * phi0) + extra_rel * want + v[i].spread[0];
        tpsi = (node ? 1e-6 : 1e-3) + v[i].spread[1];
        if (!(err <= tol)) {
            print_error("earth_table.phi [%s] %s: want %.17g got %.17g err %.3g tol %.3g\n", PREC,
                        v[i].label, want, (double)phi, err, tol);
            fails++;
        }
        if (bright && !(epsi <= tpsi)) {
            print_error("earth_table.psi [%s] %s: want %.17g got %.17g err %.3g tol %.3g\n", PREC,
                        v[i].label, wpsi, (double)psi, epsi, tpsi);
            fails++;
        }
        if (node && bright && err / want > worst_node) worst_node = err / want;
        if (!node && err / tol > worst_goal) worst_goal = err / tol;
        if (bright && epsi > worst_psi) worst_psi = epsi;
    }
    printf("STAB | earth_table.phi nodes | %s | %zu | - | %.2e | - | - | %s |\n", PREC, n,
           worst_node, fails ? "FAIL" : known ? "known issue" : "ok");
    printf("STAB | earth_table.phi edges (err/goal) | %s | %zu | - | - | %.3g | - | %s |\n", PREC, n,
           worst_goal, fails ? "FAIL" : known ? "known issue" : "ok");
    printf("STAB | earth_table.psi (rad, abs) | %s | %zu | - | %.2e | - | - | %s |\n", PREC, n,
           worst_psi, fails ? "FAIL" : "ok");
    assert_int_equal(fails, 0);
}
#endif

/* ------------------------------------------------------------ camera signals
 *
 * oi_expose with a test camera (the numbers of gen_vectors.py CAM) from the
 * smallest subnormal flux to 2.7e4 W/m^2 (magnitude -30), backgrounds 0 to
 * 1e4 W/m^2/sr: the chosen time and gain and the flags must be the documented
 * rule's (unless the rule is within rounding of a tie), and the electrons, fill
 * and SNR at that choice must meet the goal.
 */
#ifndef OI_NO_EXPOSURE
static void test_camera_signals(void **state)
{
    static const char *const o[] = {"signal_e", "background_e", "peak_e", "fill", "snr"};
    (void)state;
    RUN(camera, 5, o, ev_camera);
}
#endif

/* ------------------------------------------------------------ hostile inputs */

static const double HOSTILE[] = {0.0, -0.0, RTRUE_MIN, -RTRUE_MIN, RMIN, 1.0, -1.0, 3.2,
                                 1e30, RMAX, -RMAX, RMAX / 4, HUGE_VAL, -HUGE_VAL, NAN};
#define NHOSTILE NELEM(HOSTILE)

static int finite_in(double x, double lo, double hi)
{
    return isfinite(x) && x >= lo && x <= hi;
}

#define CHECK(cond, ...)                       \
    do {                                       \
        if (!(cond)) {                         \
            print_error(__VA_ARGS__);          \
            fails++;                           \
        }                                      \
    } while (0)

static void test_hostile_scalars(void **state)
{
    int fails = 0;
    size_t i, j, k;
    (void)state;
    for (i = 0; i < NHOSTILE; i++) {
        oi_real x = (oi_real)HOSTILE[i];
        double p = (double)oi_lambert_phase(x), m = (double)oi_magnitude_v(x, NULL);
        oi_real f;
        int st;
        CHECK(finite_in(p, 0, 2.0 / 3.0 * (1 + 4 * UNIT_ROUNDOFF)), "oi_lambert_phase(%g) = %g\n",
              (double)x, p);
        CHECK(finite_in(m, -1e4, OI_MAG_DARK), "oi_magnitude_v(%g) = %g\n", (double)x, m);
#ifndef OI_NO_MOON
        {
            double l = (double)oi_moon_phase_law(x);
            CHECK(finite_in(l, 0, 1), "oi_moon_phase_law(%g) = %g\n", (double)x, l);
        }
#endif
        st = oi_flux_from_magnitude(x, NULL, &f);
        CHECK((st == OI_OK && finite_in((double)f, 0, RMAX)) || (st == OI_ERR_MAGNITUDE && f == 0),
              "oi_flux_from_magnitude(%g): status %d flux %g\n", (double)x, st, (double)f);
        for (j = 0; j < NHOSTILE; j++) {
            for (k = 0; k < NHOSTILE; k++) {
                double a = (double)oi_cap_overlap(x, (oi_real)HOSTILE[j], (oi_real)HOSTILE[k]);
                CHECK(finite_in(a, 0, PI_UP * 4), "oi_cap_overlap(%g, %g, %g) = %g\n", (double)x,
                      HOSTILE[j], HOSTILE[k], a);
            }
        }
    }
    assert_int_equal(fails, 0);
}

/* Vectors made of hostile components: each call returns a known status with
 * zeroed outputs, or OK with every output finite and in range. */
static void test_hostile_geometry(void **state)
{
    static const double base_sun[3] = {1.4959787070e8, 0, 0};
    static const double base_pt[3] = {-7000.0, 100.0, 0};
    int fails = 0;
    size_t i, c, w;
    (void)state;
    for (w = 0; w < 2; w++) {          /* which vector gets the hostile value */
        for (c = 0; c < 3; c++) {      /* which component */
            for (i = 0; i < NHOSTILE; i++) {
                oi_real sun[3], pt[3], phi, psi, ang;
                oi_shadow s;
                int st;
                to_r3(base_sun, sun);
                to_r3(base_pt, pt);
                if (w == 0)
                    sun[c] = (oi_real)HOSTILE[i];
                else
                    pt[c] = (oi_real)HOSTILE[i];
                ang = oi_angle(sun, pt);
                CHECK(finite_in((double)ang, 0, PI_UP), "oi_angle: %g\n", (double)ang);
                st = oi_sun_fraction(sun, pt, NULL, &s);
                if (st < 0) {
                    CHECK(s.fraction == 0 && s.sun_distance_km == 0 && s.separation_rad == 0,
                          "oi_sun_fraction: status %d but outputs not zeroed\n", st);
                } else {
                    CHECK(finite_in((double)s.fraction, 0, 1) &&
                              finite_in((double)s.fraction_ld, 0, 1) &&
                              finite_in((double)s.fraction_atm, 0, 1) &&
                              finite_in((double)s.separation_rad, 0, PI_UP) &&
                              finite_in((double)s.sun_distance_km, 0, RMAX) &&
                              finite_in((double)s.sun_radius_rad, 0, PI_UP) &&
                              finite_in((double)s.earth_radius_rad, 0, PI_UP),
                          "oi_sun_fraction(sun %g %g %g, pt %g %g %g): non-finite or out of "
                          "range output (fraction %g)\n",
                          (double)sun[0], (double)sun[1], (double)sun[2], (double)pt[0],
                          (double)pt[1], (double)pt[2], (double)s.fraction);
                }
                st = oi_earthshine((oi_real)HOSTILE[i], (oi_real)400, NULL, &phi, &psi);
                CHECK(st < 0 ? (phi == 0 && psi == 0)
                             : (finite_in((double)phi, 0, 10) && isfinite((double)psi)),
                      "oi_earthshine(theta %g): status %d phi %g psi %g\n", HOSTILE[i], st,
                      (double)phi, (double)psi);
                st = oi_earthshine((oi_real)1, (oi_real)HOSTILE[i], NULL, &phi, &psi);
                CHECK(st < 0 ? (phi == 0 && psi == 0)
                             : (finite_in((double)phi, 0, 10) && isfinite((double)psi)),
                      "oi_earthshine(h %g): status %d phi %g psi %g\n", HOSTILE[i], st,
                      (double)phi, (double)psi);
            }
        }
    }
    assert_int_equal(fails, 0);
}

static int illum_ok(const oi_illum *o)
{
    const oi_real *r[] = {&o->e_sun, &o->e_earth, &o->e_moon, &o->earth_theta, &o->earth_h_km,
                          &o->earth_phi, &o->earth_psi, &o->moon_sun_fraction, &o->phase_sun,
                          &o->phase_earth, &o->phase_moon, &o->flux_sun, &o->flux_earth,
                          &o->flux_moon, &o->flux_obs, &o->mag_v, &o->range_km,
                          &o->shadow.fraction, &o->shadow.fraction_ld, &o->shadow.fraction_atm};
    size_t i;
    for (i = 0; i < NELEM(r); i++)
        if (!isfinite((double)*r[i])) return 0;
    for (i = 0; i < 3; i++)
        if (!isfinite((double)o->dir_sun[i]) || !isfinite((double)o->dir_earth[i]) ||
            !isfinite((double)o->dir_moon[i]))
            return 0;
    return o->e_sun >= 0 && o->e_earth >= 0 && o->e_moon >= 0 && o->flux_obs >= 0 &&
           o->shadow.fraction >= 0 && o->shadow.fraction <= 1 && o->moon_sun_fraction >= 0 &&
           o->moon_sun_fraction <= 1;
}

/* Every scalar and vector field of a scene set to each hostile value. */
static void test_hostile_illuminate(void **state)
{
    int fails = 0;
    size_t i, f;
    (void)state;
    for (f = 0; f < 15; f++) {
        for (i = 0; i < NHOSTILE; i++) {
            oi_scene s;
            oi_illum o;
            oi_real x = (oi_real)HOSTILE[i];
            int st;
            oi_scene_defaults(&s);
            s.sun_km[0] = (oi_real)1.4959787070e8;
            s.sun_km[1] = (oi_real)1e6;
            s.moon_km[1] = (oi_real)384400;
            s.target_km[0] = (oi_real)-7000;
            s.target_km[1] = (oi_real)50;
            s.observer_km[0] = (oi_real)-7000;
            s.observer_km[1] = (oi_real)150;
            s.has_observer = 1;
            if (f < 12) {
                oi_real *v = f < 3 ? s.sun_km : f < 6 ? s.moon_km : f < 9 ? s.target_km : s.observer_km;
                v[f % 3] = x;
            } else if (f == 12) {
                s.earth_albedo = x;
            } else if (f == 13) {
                s.target_albedo = x;
            } else {
                s.target_radius_m = x;
            }
            st = oi_illuminate(&s, NULL, &o);
            if (st < 0) {
                CHECK(o.e_sun == 0 && o.flux_obs == 0 && o.mag_v == 0 && o.shadow.fraction == 0,
                      "oi_illuminate field %zu = %g: status %d, outputs not zeroed\n", f,
                      HOSTILE[i], st);
            } else {
                CHECK(illum_ok(&o),
                      "oi_illuminate field %zu = %g: status %d, non-finite or out-of-range "
                      "output (e_sun %g e_earth %g e_moon %g h %g flux %g mag %g)\n",
                      f, HOSTILE[i], st, (double)o.e_sun, (double)o.e_earth, (double)o.e_moon,
                      (double)o.earth_h_km, (double)o.flux_obs, (double)o.mag_v);
            }
        }
    }
    assert_int_equal(fails, 0);
}

/* Whole vectors scaled to the edge of the range: all components huge (the
 * norm overflows although each component is finite) or tiny. */
static void test_hostile_scaled_vectors(void **state)
{
    static const double scales[] = {RMAX, RMAX / 2, RMAX / 1e3, 1e150, 1e30, RMIN, RTRUE_MIN};
    int fails = 0;
    size_t i, w;
    (void)state;
    for (w = 0; w < 3; w++) {
        for (i = 0; i < NELEM(scales); i++) {
            oi_scene s;
            oi_illum o;
            oi_shadow sh;
            int st;
            oi_real big = (oi_real)scales[i];
            oi_scene_defaults(&s);
            s.sun_km[0] = (oi_real)1.4959787070e8;
            s.target_km[0] = (oi_real)-7000;
            s.target_km[1] = (oi_real)50;
            s.observer_km[0] = (oi_real)-7000;
            s.observer_km[1] = (oi_real)150;
            s.moon_km[1] = (oi_real)384400;
            s.has_observer = 1;
            {
                oi_real *v = w == 0 ? s.sun_km : w == 1 ? s.target_km : s.observer_km;
                v[0] = big;
                v[1] = -big;
                v[2] = big;
            }
            st = oi_illuminate(&s, NULL, &o);
            /* once a KNOWN issue (range_km = inf with OK): fixed by
             * OI_POSITION_MAX_KM in src/scene/illuminate.c */
            CHECK(st < 0 ? (o.e_sun == 0 && o.mag_v == 0) : illum_ok(&o),
                  "oi_illuminate vector %zu scaled %g: status %d e_sun %g e_earth %g h %g flux "
                  "%g mag %g\n",
                  w, scales[i], st, (double)o.e_sun, (double)o.e_earth, (double)o.earth_h_km,
                  (double)o.flux_obs, (double)o.mag_v);
            if (w < 2) {
                st = oi_sun_fraction(s.sun_km, s.target_km, NULL, &sh);
                CHECK(st < 0 ? sh.fraction == 0
                             : (finite_in((double)sh.fraction, 0, 1) &&
                                finite_in((double)sh.sun_distance_km, 0, RMAX)),
                      "oi_sun_fraction vector %zu scaled %g: status %d fraction %g dist %g\n", w,
                      scales[i], st, (double)sh.fraction, (double)sh.sun_distance_km);
            }
        }
    }
    assert_int_equal(fails, 0);
}

#ifndef OI_NO_EXPOSURE
/* Very small and very large camera signals and hostile photometry. */
static void test_hostile_expose(void **state)
{
    static const double fluxes[] = {0.0, -0.0, RTRUE_MIN, RMIN, 1e-30, 1e-20, 1e-15, 1e-9,
                                    1e-3, 1.0, 1361.0, 1e10, 1e30, RMAX / 4, RMAX,
                                    -1e-9, HUGE_VAL, NAN};
    int fails = 0;
    size_t i, j;
    int c;
    (void)state;
    for (c = 0; oi_camera_builtin(c) != NULL; c++) {
        const oi_camera *cam = oi_camera_builtin(c);
        for (i = 0; i < NELEM(fluxes); i++) {
            for (j = 0; j < NELEM(fluxes); j++) {
                oi_expose_in in;
                oi_exposure e;
                int st;
                in.flux_w_m2 = (oi_real)fluxes[i];
                in.background_w_m2_sr = (oi_real)fluxes[j];
                in.flags = 0;
                in.rate_rad_s = 0;
                st = oi_expose(cam, &in, NULL, &e);
                if (st < 0) {
                    CHECK(e.exposure_s == 0 && e.signal_e == 0 && e.snr == 0 && e.flags == 0,
                          "oi_expose(%s, flux %g, bg %g): status %d, outputs not zeroed\n",
                          cam->name, fluxes[i], fluxes[j], st);
                } else {
                    CHECK(finite_in((double)e.signal_e, 0, RMAX) &&
                              finite_in((double)e.background_e, 0, RMAX) &&
                              finite_in((double)e.peak_e, 0, RMAX) &&
                              finite_in((double)e.fill, 0, RMAX) &&
                              finite_in((double)e.snr, 0, RMAX) &&
                              finite_in((double)e.exposure_s, 0, RMAX) &&
                              e.time_index >= 0 && e.time_index < cam->n_times &&
                              e.gain_index >= 0 && e.gain_index < cam->n_gains,
                          "oi_expose(%s, flux %g, bg %g): status %d signal %g bg %g fill %g snr "
                          "%g\n",
                          cam->name, fluxes[i], fluxes[j], st, (double)e.signal_e,
                          (double)e.background_e, (double)e.fill, (double)e.snr);
                }
            }
        }
    }
    assert_int_equal(fails, 0);
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_phase),
#ifndef OI_NO_MOON
        cmocka_unit_test(test_moon),
#endif
        cmocka_unit_test(test_angle),
        cmocka_unit_test(test_overlap),
        cmocka_unit_test(test_shadow),
        cmocka_unit_test(test_magnitude),
        cmocka_unit_test(test_earth_lambert),
        cmocka_unit_test(test_illum),
#ifndef OI_NO_EARTH_TABLE
        cmocka_unit_test(test_earth_table),
#endif
#ifndef OI_NO_EXPOSURE
        cmocka_unit_test(test_camera_signals),
#endif
        cmocka_unit_test(test_hostile_scalars),
        cmocka_unit_test(test_hostile_geometry),
        cmocka_unit_test(test_hostile_illuminate),
        cmocka_unit_test(test_hostile_scaled_vectors),
#ifndef OI_NO_EXPOSURE
        cmocka_unit_test(test_hostile_expose),
#endif
    };
    return cmocka_run_group_tests_name("stability (" PREC ")", tests, NULL, NULL);
}
