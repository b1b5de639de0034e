/* SPDX-License-Identifier: MIT */
/*
 * sun_batch_count.c: oi_sun_fraction_batch (outputs mask 0) alone over
 * points read from stdin, for callgrind to count the batch's own
 * instructions a point without an interpreter around it
 * (docs/performance.md, "The Sun fraction batch's bookkeeping"):
 *
 *   build/bench/bench-double points | valgrind --tool=callgrind \
 *     --toggle-collect=oi_sun_fraction_batch sun-batch-count WHICH N REPS
 *
 * Lines "light sx sy sz px py pz ..." (`bench points`; '#' lines skipped),
 * those whose light is WHICH (lit, penumbra, umbra; lit_umbra: both; all),
 * tiled to N rows; the batch runs REPS times over them: the count divided by
 * N x REPS is the batch's instructions a point.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "orbillum.h"

#define MAX_POINTS 100000

static oi_real given[MAX_POINTS][6];

static int wanted(const char *which, const char *light)
{
    if (strcmp(which, "all") == 0) return 1;
    if (strcmp(which, "lit_umbra") == 0) return strcmp(light, "penumbra") != 0;
    return strcmp(which, light) == 0;
}

int main(int argc, char **argv)
{
    char line[512], light[32];
    long n, i, m = 0;
    int reps, r, k;
    oi_real *sun, *p;
    oi_shadow *out;
    int *status;
    if (argc != 4) {
        fprintf(stderr, "usage: sun-batch-count WHICH N REPS < points\n");
        return 2;
    }
    n = atol(argv[2]);
    reps = atoi(argv[3]);
    while (m < MAX_POINTS && fgets(line, sizeof line, stdin)) {
        double v[6];
        if (line[0] == '#') continue;
        if (sscanf(line, "%31s %lf %lf %lf %lf %lf %lf", light, &v[0], &v[1], &v[2], &v[3], &v[4],
                   &v[5]) != 7 ||
            !wanted(argv[1], light))
            continue;
        for (k = 0; k < 6; k++) given[m][k] = (oi_real)v[k];
        m++;
    }
    if (m == 0 || n <= 0 || reps <= 0) return 2;
    sun = malloc((size_t)n * 3 * sizeof *sun);
    p = malloc((size_t)n * 3 * sizeof *p);
    out = malloc((size_t)n * sizeof *out);
    status = malloc((size_t)n * sizeof *status);
    if (sun == NULL || p == NULL || out == NULL || status == NULL) return 2;
    for (i = 0; i < n; i++)
        for (k = 0; k < 3; k++) {
            sun[3 * i + k] = given[i % m][k];
            p[3 * i + k] = given[i % m][3 + k];
        }
    for (r = 0; r < reps; r++) (void)oi_sun_fraction_batch(n, sun, p, NULL, 0, out, status);
    printf("%s: %ld rows from %ld points, %d calls\n", argv[1], n, m, reps);
    free(sun);
    free(p);
    free(out);
    free(status);
    return 0;
}
