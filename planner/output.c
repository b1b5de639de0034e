/* SPDX-License-Identifier: MIT */
/* output.c: CSV and table output of the planner (see output.h); the rows'
 * text, which needs no stdio, is in output_text.c. */
#include "output.h"
#include "numtext.h"

#include <string.h>

void out_csv_header(FILE *fp)
{
    fputs(plan_csv_header, fp);
    fputc('\n', fp);
}

/* A field, quoted (RFC 4180) when it holds a separator, quote or line end
 * or starts/ends with a blank (which a reader would trim). */
static void put_field(FILE *fp, const char *s)
{
    size_t n = strlen(s);
    int quote = n > 0 && (s[0] == ' ' || s[0] == '\t' || s[n - 1] == ' ' || s[n - 1] == '\t');
    const char *p;
    for (p = s; *p && !quote; p++) {
        if (*p == ',' || *p == '"' || *p == '\n' || *p == '\r') quote = 1;
    }
    if (!quote) {
        fputs(s, fp);
        return;
    }
    fputc('"', fp);
    for (p = s; *p; p++) {
        if (*p == '"') fputc('"', fp);
        fputc(*p, fp);
    }
    fputc('"', fp);
}

void out_csv_fields(FILE *fp, const char *id, const char *status_name, int has_numbers,
                    int has_observer, unsigned flags, const oi_illum *il, const oi_exposure *ex)
{
    char line[OUT_CSV_LINE_MAX];
    size_t n = out_csv_text(line, id, status_name, has_numbers, has_observer, flags, il, ex);
    if (n == 0) { /* an id to quote or a long one, or a status that is no library name */
        put_field(fp, id);
        fputc(',', fp);
        fputs(status_name, fp);
        n = out_csv_numbers(line, has_numbers, has_numbers && has_observer, flags, il, ex);
    }
    (void)fwrite(line, 1, n, fp);
}

void out_table_header(FILE *fp)
{
    fprintf(fp, "%7s %6s %9s %9s %9s %8s %7s %6s %9s %5s %8s  %s\n", "t", "sun", "E_sun",
            "E_earth", "E_moon", "range", "sun_ang", "mag_V", "exposure", "gain", "SNR",
            "flags");
    fprintf(fp, "%7s %6s %9s %9s %9s %8s %7s %6s %9s %5s %8s\n", "[min]", "[frac]", "[W/m2]",
            "[W/m2]", "[W/m2]", "[km]", "[deg]", "", "[s]", "", "");
}

void out_table_row(FILE *fp, double t_s, double range_km, const plan_row *row)
{
    const oi_illum *il = &row->illum;
    char flags[160];
    if (!row->has_numbers) {
        fprintf(fp, "%7.2f  %s\n", t_s / 60.0, row->status_name);
        return;
    }
    out_flags(row->flags, flags, sizeof flags);
    fprintf(fp, "%7.2f %6.3f %9.4g %9.4g %9.3g %8.3f %7.1f %6.2f %9.3g %5.2g %8.4g  %s\n",
            t_s / 60.0, (double)il->shadow.fraction_atm, (double)il->e_sun,
            (double)il->e_earth, (double)il->e_moon, range_km,
            (double)row->expo.sun_angle_rad * OUT_RAD_TO_DEG, (double)il->mag_v,
            (double)row->expo.exposure_s, (double)row->expo.gain, (double)row->expo.snr,
            flags);
}
