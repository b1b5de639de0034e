/* SPDX-License-Identifier: MIT */
/*
 * golden_earthshine.c: tests/c/ref_earthshine.h (tests/ref/generate.py earthshine:
 * quadrature to < 1e-12, spot-checked against mpmath) on the target, with the
 * acceptance rule of tests/c/test_earthshine.c: the default table's goal (relative
 * 1e-3 where phi >= 1% of phi0, absolute 1e-5 phi0 elsewhere; psi within
 * 1e-3 rad where phi >= 1% phi0) plus 5e-5 relative in single precision for
 * the rounding of theta and h to float, at the reference points (es_refs) and
 * near the surface (es_low, OI_OK); below the LEO scene table's range the far
 * field exact to 1e-12 (2e-5 float) with OI_WARN_TABLE_RANGE and psi = 0.
 */
#include <stddef.h>
#include <string.h>

#include "orbillum.h"
#include "check.h"

#ifdef OI_HAVE_REF_EARTHSHINE
#include "oi_earth_leo.h"
#include "ref_earthshine.h"

#define GOAL_REL (1e-3)
#define GOAL_ABS (1e-5)
#define GOAL_PSI (1e-3)
#ifdef OI_SINGLE_PRECISION
#define SLACK_REL (5e-5)
#define EXACT_REL (2e-5)
#else
#define SLACK_REL (0.0)
#define EXACT_REL (1e-12)
#endif

static void goal(const es_ref *r, oi_real phi, oi_real psi)
{
    if (r->phi >= 0.01 * r->phi0) {
        check_real("golden ref_earthshine phi", r->phi, (double)phi, 0, GOAL_REL + SLACK_REL);
        check_real("golden ref_earthshine psi", r->psi, (double)psi, GOAL_PSI + SLACK_REL, 0);
    } else {
        check_real("golden ref_earthshine phi (small)", r->phi, (double)phi,
                   GOAL_ABS * r->phi0 + SLACK_REL * r->phi, 0);
    }
}

static void run_points(const char *what, const es_ref *v, unsigned n)
{
    unsigned k;
    for (k = 0; k < n; k++) {
        oi_real phi = -1, psi = -1;
        int st = oi_earthshine((oi_real)v[k].theta, (oi_real)v[k].h_km, NULL, &phi, &psi);
        check_int(what, OI_OK, st);
        goal(&v[k], phi, psi);
    }
}

void golden_earthshine(void)
{
    unsigned k;
    oi_model leo;
    run_points("golden ref_earthshine status", es_refs, (unsigned)(sizeof es_refs / sizeof es_refs[0]));
    run_points("golden es_low status", es_low, (unsigned)(sizeof es_low / sizeof es_low[0]));
    memset(&leo, 0, sizeof leo);
    leo.earth_table = &oi_earth_leo;
    for (k = 0; k < sizeof es_below / sizeof es_below[0]; k++) {
        oi_real phi = -1, psi = -1;
        int st = oi_earthshine((oi_real)es_below[k].theta, (oi_real)es_below[k].h_km, &leo, &phi, &psi);
        check_int("golden es_below status", OI_WARN_TABLE_RANGE, st);
        check_real("golden es_below far field", es_below[k].phi, (double)phi, 0, EXACT_REL);
        check_true("golden es_below psi = 0", psi == 0);
    }
}
#else
void golden_earthshine(void)
{
}
#endif
