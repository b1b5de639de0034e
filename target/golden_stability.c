/* SPDX-License-Identifier: MIT */
/*
 * golden_stability.c: the stability suite's mpmath vectors
 * (tests/stability/vectors.h, tests/stability/gen_vectors.py) on the
 * target, with the suite's acceptance rule per output
 *     |got - want| <= GOAL |want| + spread
 * (GOAL 1e-12 double / 1e-5 single; spread = the output's conditioning term)
 * and the suite's list of known deviations (tests/c/test_stability.c KNOWN,
 * mirrored here: each entry widens the tolerance of the matching vectors and
 * is counted and printed as KNOWN, not as a failure; -DOI_TARGET_STRICT makes
 * them failures). The shadow vectors are the geometric (conical) shadow, so
 * oi_sun_fraction runs with no_atmosphere set (the refracting atmosphere
 * changes fraction_atm and may warn outside its table). What this adds to the
 * host run: the same vectors through
 * the cross compiler, newlib's libm and the Cortex-M FPU.
 */
#include <string.h>

#include "orbillum.h"
#include "check.h"

#ifdef OI_HAVE_STABILITY_VECTORS
#include "semihost.h"
#include "stability/vectors.h"

#ifdef OI_SINGLE_PRECISION
#define GOAL (1e-5)
#define UNIT_ROUNDOFF (5.9604644775390625e-08)
#define VEC(name) name##_f
#else
#define GOAL (1e-12)
#define UNIT_ROUNDOFF (1.1102230246251565e-16)
#define VEC(name) name##_d
#endif
#define NELEM(a) (sizeof(a) / sizeof((a)[0]))

typedef int (*eval_fn)(const double *in, double *got, int *region);

typedef struct known_issue {
    const char *table, *output, *label;
    double extra_abs_u, extra_rel;
    const char *why;
} known_issue;

/* a sentinel that matches no table, then tests/c/test_stability.c's KNOWN
 * entries, extracted by mk/target.mk into build/cross/stab_known.h (with or
 * without a trailing comma; possibly none) */
static const known_issue KNOWN[] = {
    {"", NULL, "", 0, 0, ""},
#include "stab_known.h"
};

static const known_issue *find_known(const char *table, const char *output, const char *label)
{
#ifdef OI_TARGET_STRICT
    (void)KNOWN;
    (void)table;
    (void)output;
    (void)label;
    return NULL;
#else
    unsigned i;
    for (i = 0; i < NELEM(KNOWN); i++) {
        const known_issue *k = &KNOWN[i];
        if (strcmp(k->table, table) != 0) continue;
        if (k->output != NULL && strcmp(k->output, output) != 0) continue;
        if (strncmp(k->label, label, strlen(k->label)) != 0) continue;
        return k;
    }
    return NULL;
#endif
}

static double dabs(double x) { return x < 0 ? -x : x; }
static int finite(double x) { return x == x && x - x == 0; }

#include "../tests/stability/evaluators.h"


static void run_table(const char *name, const stab_vec *v, unsigned n, int nout,
                      const char *const *outs, eval_fn f)
{
    unsigned i;
    int k;
    for (i = 0; i < n; i++) {
        double got[STAB_MAX_OUT];
        int region = -1;
        int st = f(v[i].in, got, &region);
        if (st != OI_OK) {
            check_int(v[i].label, OI_OK, st);
            continue;
        }
        if (v[i].region >= 0 && v[i].region_sure) {
            if (region != v[i].region && find_known(name, "choice", v[i].label) != NULL)
                note_known();
            else
                check_int(v[i].label, v[i].region, region);
        }
        for (k = 0; k < nout; k++) {
            double want = v[i].want[k], err = dabs(got[k] - want);
            double tol = GOAL * dabs(want) + v[i].spread[k];
            if (finite(got[k]) && err <= tol) {
                check_true(v[i].label, 1);
                continue;
            }
            {
                const known_issue *kn = find_known(name, outs[k], v[i].label);
                if (kn != NULL && finite(got[k]) &&
                    err <= tol + kn->extra_abs_u * UNIT_ROUNDOFF + kn->extra_rel * dabs(want)) {
                    note_known();
                    continue;
                }
            }
            sh_puts("stability ");
            sh_puts(name);
            sh_puts(".");
            sh_puts(outs[k]);
            sh_puts(" ");
            check_real(v[i].label, want, got[k], tol, 0);
        }
    }
}

#define RUN(name, nout, outs, f) run_table(#name, VEC(stab_##name), (unsigned)NELEM(VEC(stab_##name)), nout, outs, f)

void golden_stability(void)
{
    static const char *const o_phase[] = {"p"};
    static const char *const o_angle[] = {"angle"};
    static const char *const o_area[] = {"area"};
    static const char *const o_shadow[] = {"fraction", "sun_radius", "earth_radius",
                                           "separation", "sun_distance", "fraction_ld"};
    static const char *const o_mag[] = {"mag_v"};
    static const char *const o_phi[] = {"phi"};
    static const char *const o_illum[] = {"e_sun", "e_earth", "earth_theta", "earth_h_km",
                                          "flux_sun", "mag_v", "flux_obs"};
    RUN(phase, 1, o_phase, ev_phase);
#ifndef OI_NO_MOON
    {
        static const char *const o_moon[] = {"law"};
        RUN(moon, 1, o_moon, ev_moon);
    }
#endif
    RUN(angle, 1, o_angle, ev_angle);
    RUN(overlap, 1, o_area, ev_overlap);
    RUN(shadow, 6, o_shadow, ev_shadow);
    RUN(magnitude, 1, o_mag, ev_magnitude);
    RUN(earth_lambert, 1, o_phi, ev_earth_lambert);
    RUN(illum, 7, o_illum, ev_illum);
#if !defined(OI_NO_EXPOSURE) && defined(OI_HAVE_STAB_CAMERA)
    {
        static const char *const o_cam[] = {"signal_e", "background_e", "peak_e", "fill", "snr"};
        RUN(camera, 5, o_cam, ev_camera);
    }
#endif
}
#else
void golden_stability(void)
{
}
#endif
