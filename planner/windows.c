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
                   OI_FLAG_OCCULTED | OI_FLAG_SATURATED | OI_FLAG_TOO_FAINT |
                   OI_FLAG_BACKGROUND_SATURATED | OI_FLAG_MOON_SHADOW;
    return row->has_numbers && row->has_observer && !(row->flags & bad) &&
           (double)row->expo.snr >= snr_goal;
}

/* A row the best view may fall back on when no row is observable: computed,
 * with an observer, and neither eclipsed, occulted nor too faint. */
static int windows_fallback(const plan_row *row)
{
    unsigned dark = OI_FLAG_ECLIPSED | OI_FLAG_OCCULTED | OI_FLAG_TOO_FAINT;
    return row->has_numbers && row->has_observer && !(row->flags & dark);
}

int windows_add(window_list *l, const char *id, const plan_row *row)
{
    window *w;
    l->rows++;
    if (!windows_good(row, l->snr_goal)) {
        l->open = 0;
        if (windows_fallback(row) &&
            (l->fallback.best == NULL || (double)row->expo.snr > l->fallback.best_snr)) {
            l->fallback.best_snr = (double)row->expo.snr;
            l->fallback.best_mag = (double)row->illum.mag_v;
            l->fallback.best_exposure = (double)row->expo.exposure_s;
            l->fallback.best_gain = (double)row->expo.gain;
            l->fallback_flags = row->flags;
            if (replace(&l->fallback.best, id)) return -1;
        }
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

/* The best view of the pass: the observable row of highest SNR (the first
 * of equals); without one, the highest-SNR row that is neither eclipsed,
 * occulted nor too faint, with its flags; never an eclipsed, occulted or
 * too-faint row: with only those, none. */
static void best_view_print(const window_list *l, FILE *fp)
{
    const window *b = NULL;
    size_t i;
    char flags[160];
    for (i = 0; i < l->n; i++)
        if (b == NULL || l->w[i].best_snr > b->best_snr) b = &l->w[i];
    if (b != NULL) {
        fprintf(fp, "  best view: %s (SNR %.4g, mag_V %.2f, exposure %.3g s, gain %.3g)\n",
                b->best, b->best_snr, b->best_mag, b->best_exposure, b->best_gain);
    } else if (l->fallback.best != NULL) {
        out_flags(l->fallback_flags, flags, sizeof flags);
        fprintf(fp, "  best view: none observable; the best row neither eclipsed, occulted nor "
                    "too faint: %s (SNR %.4g, mag_V %.2f, exposure %.3g s, gain %.3g, flags %s)\n",
                l->fallback.best, l->fallback.best_snr, l->fallback.best_mag,
                l->fallback.best_exposure, l->fallback.best_gain, flags[0] ? flags : "none");
    } else {
        fprintf(fp, "  best view: none (every row eclipsed, occulted, too faint, failed or "
                    "without an observer)\n");
    }
}

void windows_print(const window_list *l, FILE *fp)
{
    size_t i;
    fprintf(fp, "oi-plan: observation windows (target in full sunlight, Sun outside the "
                "exclusion angle, not behind the Earth, not saturated, not too faint, "
                "SNR >= %g):\n",
            l->snr_goal);
    if (l->n == 0) {
        fprintf(fp, "  none (%lu rows)\n", l->rows);
        best_view_print(l, fp);
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
    best_view_print(l, fp);
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
    free(l->fallback.best);
    memset(l, 0, sizeof *l);
}
