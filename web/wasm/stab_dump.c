/* SPDX-License-Identifier: MIT */
/*
 * stab_dump.c: every double-precision stability vector (tests/stability/
 * vectors.h) through the runtime, printed as the bit patterns of the
 * outputs. Built twice, natively and for wasm32 (run under node's WASI), by
 * `make test-wasm`: the two dumps must be identical (tests/browser/
 * test_wasm.mjs compares them and names any output that differs).
 * Line: table index status region bits0 bits1 ...
 */
#include <stdio.h>
#include <string.h>

#include "orbillum.h"
#include "stability/vectors.h"
#include "stability/evaluators.h"

/* The table's phi and psi at the vector's (theta, h). */
static int ev_earth_table(const double *in, double *got, int *region)
{
    oi_real phi, psi;
    int st = oi_earthshine((oi_real)in[0], (oi_real)in[1], NULL, &phi, &psi);
    (void)region;
    got[0] = (double)phi;
    got[1] = (double)psi;
    return st;
}

typedef int (*eval_fn)(const double *in, double *got, int *region);

static void bits(double x)
{
    unsigned long long u;
    memcpy(&u, &x, sizeof u);
    printf(" %016llx", u);
}

static void dump(const char *name, const stab_vec *v, size_t n, int nout, eval_fn f)
{
    size_t i;
    for (i = 0; i < n; i++) {
        double got[STAB_MAX_OUT];
        int region = -1, k, st;
        memset(got, 0, sizeof got);
        st = f(v[i].in, got, &region);
        printf("%s %lu %d %d", name, (unsigned long)i, st, region);
        for (k = 0; k < nout; k++) bits(got[k]);
        printf("\n");
    }
}

#define DUMP(name, nout, f) dump(#name, stab_##name##_d, \
                                 sizeof stab_##name##_d / sizeof stab_##name##_d[0], nout, f)

int main(void)
{
    DUMP(phase, 1, ev_phase);
    DUMP(moon, 1, ev_moon);
    DUMP(angle, 1, ev_angle);
    DUMP(overlap, 1, ev_overlap);
    DUMP(shadow, 6, ev_shadow);
    DUMP(magnitude, 1, ev_magnitude);
    DUMP(earth_lambert, 1, ev_earth_lambert);
    DUMP(illum, 7, ev_illum);
    DUMP(earth_table, 2, ev_earth_table);
    DUMP(camera, 5, ev_camera);
    return 0;
}
