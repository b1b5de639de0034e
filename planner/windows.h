/* SPDX-License-Identifier: MIT */
/* windows.h: observation windows over a sequence of planned rows (the
 * batch's --summary): runs of consecutive rows where the target can be
 * photographed (full sunlight, Sun outside the exclusion angle, not behind
 * the Earth, no saturated flag, not too faint, SNR at the goal), and the
 * pass's best view (windows_print: never an eclipsed, occulted or too-faint
 * row). */
#ifndef OI_PLAN_WINDOWS_H
#define OI_PLAN_WINDOWS_H

#include <stdio.h>

#include "output.h"

typedef struct window {
    char *first, *last, *best;   /* ids (copies) */
    unsigned long rows;
    double best_snr, best_mag, best_exposure, best_gain;
} window;

typedef struct window_list {
    window *w;
    size_t n, cap;
    int open;                    /* the last window is still growing */
    unsigned long rows, good;
    double snr_goal;
    window fallback;             /* the best view without an observable row: best, best_*
                                    (neither eclipsed, occulted nor too faint) */
    unsigned fallback_flags;     /* its flags */
} window_list;

void windows_init(window_list *l, double snr_goal);
/* Nonzero when the row is a good observation. */
int windows_good(const plan_row *row, double snr_goal);
/* Add one row (in order); returns -1 when out of memory. */
int windows_add(window_list *l, const char *id, const plan_row *row);
void windows_print(const window_list *l, FILE *fp);
void windows_free(window_list *l);

#endif
