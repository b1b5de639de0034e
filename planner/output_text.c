/* SPDX-License-Identifier: MIT */
/* output_text.c: the text of the planner's CSV rows (see output.h): what
 * oi-plan --csv prints for a row, formed in a buffer, without stdio (the
 * viewer's WebAssembly module compiles it too). */
#include "output.h"
#include "numtext.h"

#include <string.h>

const char plan_csv_header[] =
    "id,status,sun_fraction,sun_fraction_atm,e_sun,e_earth,e_moon,earth_theta_deg,"
    "earth_h_km,flux_obs,mag_v,exposure_s,gain,snr,flags,detect_margin_mag,e_sky";

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

size_t out_csv_numbers(char *line, int num, int obs, unsigned flags, const oi_illum *il,
                       const oi_exposure *ex)
{
    size_t n = 0;
    n += put_num(line + n, num, (double)il->shadow.fraction);
    n += put_num(line + n, num, (double)il->shadow.fraction_atm);
    n += put_num(line + n, num, (double)il->e_sun);
    n += put_num(line + n, num, (double)il->e_earth);
    n += put_num(line + n, num, (double)il->e_moon);
    n += put_num(line + n, num, (double)il->earth_theta * OUT_RAD_TO_DEG);
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
    return n + out_csv_numbers(line + n, has_numbers, has_numbers && has_observer, flags, il, ex);
}
