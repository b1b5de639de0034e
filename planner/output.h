/* SPDX-License-Identifier: MIT */
/* output.h: how the planner writes its results: the batch CSV (header, one
 * row per input row, numbers with %.17g, fields quoted when needed) and the
 * human-readable table of the built-in scenario. */
#ifndef OI_PLAN_OUTPUT_H
#define OI_PLAN_OUTPUT_H

#include <stdio.h>

#include "numtext.h"
#include "orbillum.h"

/* Everything one output row needs. */
typedef struct plan_row {
    int status;              /* library status of the row (or a planner code) */
    const char *status_name; /* printed status */
    int has_numbers;         /* 0: the row failed, numbers are left empty */
    int has_observer;        /* 0: flux_obs .. snr are left empty */
    oi_illum illum;
    oi_exposure expo;
    unsigned flags;          /* OI_FLAG_* */
} plan_row;

/* The exact CSV header of the batch interface (without newline). */
extern const char plan_csv_header[];

void out_csv_header(FILE *fp);
/* Longest id copied into a row's text; a longer one (or one to quote) is
 * written on its own first (out_csv_fields). */
#define OUT_ID_INLINE_MAX 256
/* Bytes out_csv_text may write: the id, the status (a library name), 14
 * numbers, the flags (out_flags' 160). */
#define OUT_CSV_LINE_MAX (OUT_ID_INLINE_MAX + 64 + 14 * NUM_TEXT_MAX + 160 + 8)
/* One CSV row from its parts (id quoted when it holds a comma, quote or
 * line break, or starts or ends with a blank): status name, has_numbers,
 * has_observer and flags as in plan_row, the numbers from il and ex (not
 * printed where the row leaves them empty). */
void out_csv_fields(FILE *fp, const char *id, const char *status_name, int has_numbers,
                    int has_observer, unsigned flags, const oi_illum *il, const oi_exposure *ex);
/* The text out_csv_fields writes, at line (OUT_CSV_LINE_MAX bytes):
 * returns its length, or 0 (nothing written) for a row whose id must be
 * written on its own (quoted, or longer than OUT_ID_INLINE_MAX) or whose
 * status is no library name: out_csv_fields writes those. */
size_t out_csv_text(char *line, const char *id, const char *status_name, int has_numbers,
                    int has_observer, unsigned flags, const oi_illum *il, const oi_exposure *ex);
/* The row's numbers and flags, from the first number's comma to the
 * newline, at line (OUT_CSV_LINE_MAX bytes): num and obs say whether the
 * illumination's and the observer's numbers are printed (empty fields
 * else); returns the length. */
size_t out_csv_numbers(char *line, int num, int obs, unsigned flags, const oi_illum *il,
                       const oi_exposure *ex);
/* Degrees per radian, as the CSV's earth_theta_deg is printed. */
#define OUT_RAD_TO_DEG (180.0 / 3.14159265358979323846)
/* Flag names joined by '+' into buf (empty string for none). */
void out_flags(unsigned flags, char *buf, size_t size);

/* Human-readable table (built-in scenario). */
void out_table_header(FILE *fp);
void out_table_row(FILE *fp, double t_s, double range_km, const plan_row *row);

#endif
