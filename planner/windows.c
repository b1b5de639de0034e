/* SPDX-License-Identifier: MIT */
/* windows.c: observation windows over planned rows (see windows.h). */
#include "windows.h"

#include <stdlib.h>
#include <string.h>

static char *copy(const char *s)
{
    size_t n = strlen(s) + 1;
    char *p = (char *)malloc(n);
    if (p) memcpy(p, s, n);
    return p;
}

static int replace(char **dst, const char *s)
{
    char *p = copy(s);
    if (p == NULL) return -1;
    free(*dst);
    *dst = p;
    return 0;
}

void windows_init(window_list *l, double snr_goal)
{
    memset(l, 0, sizeof *l);
    l->snr_goal = snr_goal;
}

int windows_good(const plan_row *row, double snr_goal)
{
    unsigned bad = OI_FLAG_ECLIPSED | OI_FLAG_PENUMBRA | OI_FLAG_SUN_EXCLUSION |
                   OI_FLAG_OCCULTED | OI_FLAG_SATURATED;
    return row->has_numbers && row->has_observer && !(row->flags & bad) &&
           (double)row->expo.snr >= snr_goal;
}

int windows_add(window_list *l, const char *id, const plan_row *row)
{
    window *w;
    l->rows++;
    if (!windows_good(row, l->snr_goal)) {
        l->open = 0;
        return 0;
    }
    l->good++;
    if (!l->open) {
        if (l->n == l->cap) {
            size_t cap = l->cap ? 2 * l->cap : 16;
            window *p = (window *)realloc(l->w, cap * sizeof *p);
            if (p == NULL) return -1;
            l->w = p;
            l->cap = cap;
        }
        w = &l->w[l->n++];
        memset(w, 0, sizeof *w);
        w->best_snr = -1.0;
        if (replace(&w->first, id)) return -1;
        l->open = 1;
    }
    w = &l->w[l->n - 1];
    w->rows++;
    if (replace(&w->last, id)) return -1;
    if ((double)row->expo.snr > w->best_snr) {
        w->best_snr = (double)row->expo.snr;
        w->best_mag = (double)row->illum.mag_v;
        w->best_exposure = (double)row->expo.exposure_s;
        w->best_gain = (double)row->expo.gain;
        if (replace(&w->best, id)) return -1;
    }
    return 0;
}

void windows_print(const window_list *l, FILE *fp)
{
    size_t i;
    fprintf(fp, "oi-plan: observation windows (target in full sunlight, Sun outside the "
                "exclusion angle, not behind the Earth, not saturated, SNR >= %g):\n",
            l->snr_goal);
    if (l->n == 0) {
        fprintf(fp, "  none (%lu rows)\n", l->rows);
        return;
    }
    fprintf(fp, "  %3s %6s  %-24s %-24s %9s  %-24s %7s %9s %5s\n", "#", "rows", "first id",
            "last id", "best SNR", "at id", "mag_V", "exp [s]", "gain");
    for (i = 0; i < l->n; i++) {
        const window *w = &l->w[i];
        fprintf(fp, "  %3lu %6lu  %-24.24s %-24.24s %9.4g  %-24.24s %7.2f %9.3g %5.3g\n",
                (unsigned long)i + 1, w->rows, w->first, w->last, w->best_snr, w->best,
                w->best_mag, w->best_exposure, w->best_gain);
    }
    fprintf(fp, "  %lu of %lu rows observable, in %lu window%s\n", l->good, l->rows,
            (unsigned long)l->n, l->n == 1 ? "" : "s");
}

void windows_free(window_list *l)
{
    size_t i;
    for (i = 0; i < l->n; i++) {
        free(l->w[i].first);
        free(l->w[i].last);
        free(l->w[i].best);
    }
    free(l->w);
    memset(l, 0, sizeof *l);
}
