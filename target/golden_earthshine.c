/* SPDX-License-Identifier: MIT */
/*
 * golden_earthshine.c: tests/c/ref_earthshine.h (bake/gen_test_vectors.py:
 * quadrature to < 1e-12, spot-checked against mpmath) on the target, with the
 * acceptance rule of tests/c/test_earthshine.c: the issue-3 goal (relative
 * 1e-3 where phi >= 1% of phi0, absolute 1e-5 phi0 elsewhere; psi within
 * 1e-3 rad where phi >= 1% phi0) plus 5e-5 relative in single precision for
 * the rounding of theta and h to float; the far field below the table exact
 * to 1e-12 (2e-5 float) with OI_WARN_TABLE_RANGE and psi = 0.
 */
#include <stddef.h>

#include "orbillum.h"
#include "check.h"

#ifdef OI_HAVE_REF_EARTHSHINE
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

void golden_earthshine(void)
{
    unsigned k;
    for (k = 0; k < sizeof es_refs / sizeof es_refs[0]; k++) {
        const es_ref *r = &es_refs[k];
        oi_real phi = -1, psi = -1;
        int st = oi_earthshine((oi_real)r->theta, (oi_real)r->h_km, NULL, &phi, &psi);
        check_int("golden ref_earthshine status", OI_OK, st);
        if (r->phi >= 0.01 * r->phi0) {
            check_real("golden ref_earthshine phi", r->phi, (double)phi, 0, GOAL_REL + SLACK_REL);
            check_real("golden ref_earthshine psi", r->psi, (double)psi, GOAL_PSI + SLACK_REL, 0);
        } else {
            check_real("golden ref_earthshine phi (small)", r->phi, (double)phi,
                       GOAL_ABS * r->phi0 + SLACK_REL * r->phi, 0);
        }
    }
    for (k = 0; k < sizeof es_below / sizeof es_below[0]; k++) {
        oi_real phi = -1, psi = -1;
        int st = oi_earthshine((oi_real)es_below[k].theta, (oi_real)es_below[k].h_km, NULL, &phi, &psi);
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
