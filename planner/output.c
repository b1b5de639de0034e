/* SPDX-License-Identifier: MIT */
/* output.c: CSV and table output of the planner (see output.h). */
#include "output.h"
#include "numtext.h"

#include <string.h>

const char plan_csv_header[] =
    "id,status,sun_fraction,sun_fraction_atm,e_sun,e_earth,e_moon,earth_theta_deg,"
    "earth_h_km,flux_obs,mag_v,exposure_s,gain,snr,flags,detect_margin_mag,e_sky";

static const double RAD_TO_DEG = 180.0 / 3.14159265358979323846;

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

/* ",%.17g" (negative zero printed as 0), or "," when absent, at line;
 * returns the length (at most NUM_TEXT_MAX). */
static size_t put_num(char *line, int present, double x)
{
    line[0] = ',';
    if (!present) return 1;
    return 1 + num_format17(x + 0.0 == 0.0 ? 0.0 : x, line + 1);
}

void out_flags(unsigned flags, char *buf, size_t size)
{
    unsigned bit;
    size_t len = 0;
    if (size == 0) return;
    buf[0] = '\0';
    for (bit = 1u; bit != 0u && bit <= flags; bit <<= 1) {
        const char *name;
        size_t n;
        if (!(flags & bit)) continue;
        name = oi_flag_name(bit);
        if (name == NULL) name = "unknown";
        n = strlen(name);
        if (len + n + 2 > size) break;
        if (len > 0) buf[len++] = '+';
        memcpy(buf + len, name, n + 1);
        len += n;
    }
}

/* The row's numbers and flags, from the first number's comma to the
 * newline, at line; returns the length. */
static size_t put_numbers(char *line, int num, int obs, unsigned flags, const oi_illum *il,
                          const oi_exposure *ex)
{
    size_t n = 0;
    n += put_num(line + n, num, (double)il->shadow.fraction);
    n += put_num(line + n, num, (double)il->shadow.fraction_atm);
    n += put_num(line + n, num, (double)il->e_sun);
    n += put_num(line + n, num, (double)il->e_earth);
    n += put_num(line + n, num, (double)il->e_moon);
    n += put_num(line + n, num, (double)il->earth_theta * RAD_TO_DEG);
    n += put_num(line + n, num, (double)il->earth_h_km);
    n += put_num(line + n, obs, (double)il->flux_obs);
    n += put_num(line + n, obs, (double)il->mag_v);
    n += put_num(line + n, obs, (double)ex->exposure_s);
    n += put_num(line + n, obs, (double)ex->gain);
    n += put_num(line + n, obs, (double)ex->snr);
    line[n++] = ',';
    if (num) {
        out_flags(flags, line + n, 160);
        n += strlen(line + n);
    }
    n += put_num(line + n, obs, (double)ex->detect_margin_mag);
    n += put_num(line + n, num, (double)il->e_sky);
    line[n++] = '\n';
    return n;
}

/* Whether id goes into the row's text as it is (no quotes, not longer
 * than OUT_ID_INLINE_MAX); *n its length. */
static int id_inline(const char *id, size_t *n)
{
    const size_t k = strcspn(id, ",\"\n\r");
    *n = k;
    return id[k] == '\0' && k <= OUT_ID_INLINE_MAX &&
           !(k > 0 && (id[0] == ' ' || id[0] == '\t' || id[k - 1] == ' ' || id[k - 1] == '\t'));
}

size_t out_csv_text(char *line, const char *id, const char *status_name, int has_numbers,
                    int has_observer, unsigned flags, const oi_illum *il, const oi_exposure *ex)
{
    size_t n, k = strlen(status_name);
    if (k > 63 || !id_inline(id, &n)) return 0;
    memcpy(line, id, n);
    line[n++] = ',';
    memcpy(line + n, status_name, k);
    n += k;
    return n + put_numbers(line + n, has_numbers, has_numbers && has_observer, flags, il, ex);
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
        n = put_numbers(line, has_numbers, has_numbers && has_observer, flags, il, ex);
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
            (double)row->expo.sun_angle_rad * RAD_TO_DEG, (double)il->mag_v,
            (double)row->expo.exposure_s, (double)row->expo.gain, (double)row->expo.snr,
            flags);
}
