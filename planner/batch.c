/* SPDX-License-Identifier: MIT */
/* batch.c: the batch interface of the planner (see batch.h, docs/planner.md).
 * Columns are matched by name (case-insensitive), in any order; unknown
 * columns are ignored with a note. A row that cannot be parsed or computed
 * gets its status and empty numbers; the batch goes on. */
#define _POSIX_C_SOURCE 200809L /* isatty, fileno: progress only on a terminal */

#include "batch.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "csv_read.h"
#include "numtext.h"
#include "output.h"
#include "shapes.h"
#include "windows.h"

enum column {
    C_ID,
    C_SUN_X, C_SUN_Y, C_SUN_Z,
    C_TARGET_X, C_TARGET_Y, C_TARGET_Z,
    C_MOON_X, C_MOON_Y, C_MOON_Z,
    C_OBSERVER_X, C_OBSERVER_Y, C_OBSERVER_Z,
    C_TERMS, C_EARTH_ALBEDO, C_TARGET_ALBEDO, C_TARGET_RADIUS, C_CAMERA, C_ATMOSPHERE,
    C_SKY,
    C_TARGET_VX, C_TARGET_VY, C_TARGET_VZ,
    C_OBSERVER_VX, C_OBSERVER_VY, C_OBSERVER_VZ,
    C_TARGET_SHAPE, C_Q_W, C_Q_X, C_Q_Y, C_Q_Z, C_EARTH_SHAPE,
    C_ALBEDO_MODEL, C_EPOCH_JD, C_EARTH_ROTATION_DEG,
    C_SENSOR_TEMP,
    C_BAND,
    C_COUNT
};

static const char *const column_name[C_COUNT] = {
    "id",
    "sun_x", "sun_y", "sun_z",
    "target_x", "target_y", "target_z",
    "moon_x", "moon_y", "moon_z",
    "observer_x", "observer_y", "observer_z",
    "terms", "earth_albedo", "target_albedo", "target_radius_m", "camera", "atmosphere",
    "sky",
    "target_vx", "target_vy", "target_vz",
    "observer_vx", "observer_vy", "observer_vz",
    "target_shape", "q_w", "q_x", "q_y", "q_z", "earth_shape",
    "albedo_model", "epoch_jd", "earth_rotation_deg",
    "sensor_temp_c",
    "band"
};

typedef struct batch {
    long col[C_COUNT];        /* field index of each known column, -1 if absent */
    size_t header_fields;
    const oi_camera *default_camera;
    const plan_shapes *shapes; /* --shapes, or NULL */
    const plan_albedo_map *albedo_map; /* --albedo-map, or NULL */
    const char *path;
    oi_scene scene_defaults;  /* oi_scene_defaults, formed once: each row starts from it */
    int warned_extra;
    unsigned long messages;   /* row messages printed so far */
    unsigned long bad;        /* rows with errors */
    char last_camera_name[64]; /* the camera column's last text and its camera */
    const oi_camera *last_camera;
    /* rows read but not yet computed and written (flush_pending) */
    struct pending *pending;
    int flushing;             /* 1 inside flush_pending (its messages do not flush) */
    FILE *out;
    int out_tty;              /* out is a terminal: each row written at once */
    window_list *wins;
    FILE *summary;            /* NULL once the summary is given up */
} batch;

/* Rows are read into a block of up to PENDING_MAX, then the library runs on
 * the block (oi_illuminate_batch_outputs, the model resolved once per run of
 * rows that share it, with only the outputs the CSV needs) and the block is
 * written in input order. Messages keep the order of the rows: before a row
 * prints one, the rows read before it are computed and written. */
#define PENDING_MAX 64

/* Bytes of the block's ids; a longer id is not copied (its row is computed
 * at once). */
#define PENDING_ID_BYTES (1u << 14)

/* Bytes of the block's output text (at least OUT_CSV_LINE_MAX): written
 * with one fwrite when the next row might not fit, and at the block's end. */
#define PENDING_TEXT_BYTES (1u << 15)

/* What the CSV needs of the illumination: the observer's flux and
 * magnitude; not the shadow's angles, the limb-darkened fraction or the
 * directions. */
#define PLAN_OUTPUTS (OI_BATCH_OBSERVER)

/* What the CSV needs of the exposure: the setting (exposure_s, gain, snr,
 * OI_FLAG_SATURATED, OI_FLAG_TRAILED), OI_FLAG_TOO_FAINT and
 * detect_margin_mag; not the Sun's angle (OI_FLAG_SUN_EXCLUSION is then
 * decided from a cosine where it is certain, the same flag), the background
 * or the rate. */
#define PLAN_EXPOSE_OUTPUTS (OI_EXPOSE_SETTING | OI_EXPOSE_FAINT | OI_EXPOSE_DETECT)

/* What a row's output takes besides its numbers (the fields of plan_row
 * but illum and expo, which stay in the block's arrays). */
typedef struct row_state {
    int status;
    const char *status_name;
    int has_numbers;
    int has_observer;
    unsigned flags;
} row_state;

typedef struct pending_row {
    row_state state;          /* status when parsing failed; else filled by the flush */
    oi_model model;
    oi_expose_goal goal;
    const oi_camera *camera;
    unsigned long line;
    const char *id;           /* into ids, or the reader's field (flushed at once) */
    int compute;              /* 1: parsed, to be computed */
} pending_row;

typedef struct pending {
    long n;
    size_t id_used;
    oi_scene scenes[PENDING_MAX];
    oi_illum illum[PENDING_MAX];
    int status[PENDING_MAX];
    oi_exposure expo[PENDING_MAX];
    int expo_status[PENDING_MAX];
    long run[PENDING_MAX];    /* the first row of row i's run of one model (flush_pending) */
    pending_row rows[PENDING_MAX];
    char ids[PENDING_ID_BYTES];
    char text[PENDING_TEXT_BYTES]; /* the block's output rows, written at once */
} pending;

static void flush_pending(batch *b);

/* Output buffer of the batch (bytes). */
#define OUT_BUFFER (1u << 16)

/* Row messages beyond this many are counted, not printed. */
#define MAX_ROW_MESSAGES 50

/* ASCII case-insensitive equality. */
static int same_nocase(const char *a, const char *b)
{
    while (*a && *b) {
        if (tolower((unsigned char)*a) != tolower((unsigned char)*b)) return 0;
        a++;
        b++;
    }
    return *a == *b;
}

/* Report a problem with a row on stderr. */
static void row_error(batch *b, unsigned long line, long field, const char *what,
                      const char *detail)
{
    /* the rows read before it are written first, while messages are printed */
    if (b->messages < MAX_ROW_MESSAGES) flush_pending(b);
    if (++b->messages > MAX_ROW_MESSAGES) {
        if (b->messages == MAX_ROW_MESSAGES + 1) {
            fprintf(stderr, "oi-plan: %s: more row errors; further messages suppressed "
                            "(see the status column)\n", b->path);
        }
        return;
    }
    fprintf(stderr, "oi-plan: %s: line %lu", b->path, line);
    if (field >= 0) fprintf(stderr, ", column %ld", field + 1);
    fprintf(stderr, ": %s", what);
    if (detail) fprintf(stderr, " %s", detail);
    fputc('\n', stderr);
}

/* Map the header; returns 0 or PLAN_EXIT_INPUT after printing why. */
static int read_header(batch *b, csv_reader *r)
{
    size_t i;
    int k, st, missing = 0;
    static const int required[] = {C_SUN_X, C_SUN_Y, C_SUN_Z, C_TARGET_X, C_TARGET_Y, C_TARGET_Z};
    static const int groups[][3] = {{C_MOON_X, C_MOON_Y, C_MOON_Z},
                                    {C_OBSERVER_X, C_OBSERVER_Y, C_OBSERVER_Z},
                                    {C_TARGET_VX, C_TARGET_VY, C_TARGET_VZ},
                                    {C_OBSERVER_VX, C_OBSERVER_VY, C_OBSERVER_VZ}};

    for (k = 0; k < C_COUNT; k++) b->col[k] = -1;
    st = csv_next(r);
    if (st == CSV_END) {
        fprintf(stderr, "oi-plan: %s: empty input: expected a header row naming the columns "
                        "(at least sun_x,sun_y,sun_z,target_x,target_y,target_z)\n", b->path);
        return PLAN_EXIT_INPUT;
    }
    if (st != CSV_RECORD) {
        fprintf(stderr, "oi-plan: %s: line %lu, character %lu: cannot read the header: %s%s\n",
                b->path, r->err_line, r->err_col, csv_result_text(st),
                st == CSV_BAD_BYTE ? " (save the file as UTF-8 or ASCII CSV, not UTF-16)" : "");
        return PLAN_EXIT_INPUT;
    }
    b->header_fields = csv_nfields(r);
    for (i = 0; i < csv_nfields(r); i++) {
        const char *name = csv_field(r, i);
        int found = 0;
        for (k = 0; k < C_COUNT; k++) {
            if (!same_nocase(name, column_name[k])) continue;
            found = 1;
            if (b->col[k] >= 0) {
                fprintf(stderr, "oi-plan: %s: line %lu: column '%s' appears twice "
                                "(columns %ld and %lu)\n",
                        b->path, r->rec_line, column_name[k], b->col[k] + 1,
                        (unsigned long)i + 1);
                return PLAN_EXIT_INPUT;
            }
            b->col[k] = (long)i;
        }
        if (!found) {
            fprintf(stderr, "oi-plan: %s: note: ignoring unknown column %lu '%.60s'\n", b->path,
                    (unsigned long)i + 1, name);
        }
    }
    for (k = 0; k < (int)(sizeof required / sizeof required[0]); k++) {
        if (b->col[required[k]] < 0) {
            fprintf(stderr, "oi-plan: %s: line %lu: missing required column '%s'\n", b->path,
                    r->rec_line, column_name[required[k]]);
            missing = 1;
        }
    }
    for (k = 0; k < (int)(sizeof groups / sizeof groups[0]); k++) {
        int n = (b->col[groups[k][0]] >= 0) + (b->col[groups[k][1]] >= 0) +
                (b->col[groups[k][2]] >= 0);
        if (n != 0 && n != 3) {
            fprintf(stderr, "oi-plan: %s: line %lu: columns %s, %s, %s must come together\n",
                    b->path, r->rec_line, column_name[groups[k][0]], column_name[groups[k][1]],
                    column_name[groups[k][2]]);
            missing = 1;
        }
    }
    {
        int n = 0;
        for (k = C_Q_W; k <= C_Q_Z; k++) n += b->col[k] >= 0;
        if (n != 0 && n != 4) {
            fprintf(stderr, "oi-plan: %s: line %lu: columns q_w, q_x, q_y, q_z must come "
                            "together\n", b->path, r->rec_line);
            missing = 1;
        }
    }
    if (missing) {
        fprintf(stderr, "oi-plan: the header must name at least: "
                        "sun_x,sun_y,sun_z,target_x,target_y,target_z (any order)\n");
        return PLAN_EXIT_INPUT;
    }
    return 0;
}

/* Text of column k in the current record: NULL when the column is absent
 * from the header, "" when empty. *short_row is set when the header has the
 * column but the row is too short. */
static const char *field_of(batch *b, const csv_reader *r, int k, int *short_row)
{
    const char *s;
    if (b->col[k] < 0) return NULL;
    s = csv_field(r, (size_t)b->col[k]);
    if (s == NULL) {
        *short_row = 1;
        return "";
    }
    return s;
}

/* Parse a real; returns 0 and *out, 1 for an empty field, -1 for text that
 * is not a number. NaN and infinities are numbers here (the library then
 * reports ERR_NONFINITE); values out of the double range read as inf. */
static int parse_real(const char *s, size_t avail, double *out)
{
    char *end;
    const char *p = s;
    while (*p == ' ' || *p == '\t') p++;
    if (*p == '\0') return 1;
    /* strtod's double and end, faster (numtext.c); avail: bytes readable at s */
    *out = avail > (size_t)(p - s) ? num_parse_n(p, avail - (size_t)(p - s), &end)
                                   : num_parse(p, &end);
    if (end == p) return -1;
    while (*end == ' ' || *end == '\t') end++;
    return *end == '\0' ? 0 : -1;
}

/* "all" in a terms list: every term whose inputs the row gives. */
#define TERMS_ALL_AVAILABLE (0x100u)

/* Parse a terms list ("sun+earth+moon", "all", "all+sky"; "all" does not
 * include sky, which is opt-in as OI_TERM_SKY is outside OI_TERM_ALL); 0 or -1. */
static int parse_terms(const char *s, unsigned *terms)
{
    char tok[16];
    const char *p = s;
    *terms = 0;
    for (;;) {
        size_t n = 0;
        while (*p == ' ' || *p == '\t') p++;
        while (*p && *p != '+' && *p != ' ' && *p != '\t') {
            if (n + 1 >= sizeof tok) return -1;
            tok[n++] = *p++;
        }
        tok[n] = '\0';
        while (*p == ' ' || *p == '\t') p++;
        if (same_nocase(tok, "sun")) *terms |= OI_TERM_SUN;
        else if (same_nocase(tok, "earth")) *terms |= OI_TERM_EARTH;
        else if (same_nocase(tok, "moon")) *terms |= OI_TERM_MOON;
#ifndef OI_NO_SKYLIGHT
        else if (same_nocase(tok, "sky")) *terms |= OI_TERM_SKY;
#endif
        else if (same_nocase(tok, "all")) *terms |= TERMS_ALL_AVAILABLE;
        else return -1;
        if (*p == '\0') return 0;
        if (*p != '+') return -1;
        p++;
    }
}

/* Parse a sky list ("zodiacal+moon+starlight", "all", "none"; empty: none;
 * "all" is zodiacal+moon, as before starlight existed) into
 * oi_expose_goal.sky; 0 or -1. */
static int parse_sky(const char *s, unsigned *sky)
{
    char tok[16];
    const char *p = s;
    *sky = 0;
    while (*p == ' ' || *p == '\t') p++;
    if (*p == '\0') return 0;
    for (;;) {
        size_t n = 0;
        while (*p == ' ' || *p == '\t') p++;
        while (*p && *p != '+' && *p != ' ' && *p != '\t') {
            if (n + 1 >= sizeof tok) return -1;
            tok[n++] = *p++;
        }
        tok[n] = '\0';
        while (*p == ' ' || *p == '\t') p++;
        if (same_nocase(tok, "none")) {
            /* nothing added */
        } else if (same_nocase(tok, "zodiacal")) *sky |= OI_SKY_ZODIACAL;
        else if (same_nocase(tok, "moon")) *sky |= OI_SKY_MOON;
        else if (same_nocase(tok, "starlight")) *sky |= OI_SKY_STARLIGHT;
        else if (same_nocase(tok, "all")) *sky |= OI_SKY_ZODIACAL | OI_SKY_MOON;
        else return -1;
        if (*p == '\0') return 0;
        if (*p != '+') return -1;
        p++;
    }
}

/* Column k's field as a plain decimal alone (num_parse_plain, then the
 * field's end): 1 with *x, what parse_real gives for it; 0 for any other
 * field (absent, empty, blanks, another form), which parse_real then reads. */
static int plain_field(const batch *b, const csv_reader *r, int k, double *x)
{
    const long c = b->col[k];
    const char *s;
    char *end;
    if (c < 0 || (size_t)c >= csv_nfields(r)) return 0;
    s = csv_field(r, (size_t)c);
    return num_parse_plain(s, csv_record_end(r), x, &end) && *end == '\0';
}

/* Read a group of three coordinates; returns 1 given, 0 all empty or the
 * columns absent, -1 after reporting a parse error. */
static int parse_vec(batch *b, const csv_reader *r, int k0, oi_real v[3], int required)
{
    int i, given = 0, first_empty = -1, short_row = 0;
    double x0, x1, x2;
    if (plain_field(b, r, k0, &x0) && plain_field(b, r, k0 + 1, &x1) &&
        plain_field(b, r, k0 + 2, &x2)) { /* the common row */
        v[0] = (oi_real)x0;
        v[1] = (oi_real)x1;
        v[2] = (oi_real)x2;
        return 1;
    }
    for (i = 0; i < 3; i++) {
        const char *s = field_of(b, r, k0 + i, &short_row);
        double x = 0;
        int st;
        if (s == NULL) return 0;
        st = parse_real(s, csv_field_avail(r, (size_t)b->col[k0 + i]), &x);
        if (st < 0) {
            char detail[96];
            snprintf(detail, sizeof detail, "for %s, got \"%.60s\"", column_name[k0 + i], s);
            row_error(b, r->rec_line, b->col[k0 + i], "expected a number", detail);
            return -1;
        }
        if (st == 1) {
            if (first_empty < 0) first_empty = i;
        } else {
            given++;
        }
        v[i] = (oi_real)x;
    }
    if (given == 3) return 1;
    if (given == 0 && !required) return 0;
    row_error(b, r->rec_line, b->col[k0 + first_empty],
              required ? "empty field for a required column:"
                       : "empty field (give all three coordinates or none):",
              column_name[k0 + first_empty]);
    return -1;
}

/* Optional scalar column: 0 absent or empty (value untouched), 1 given,
 * -1 parse error (reported). */
static int parse_opt(batch *b, const csv_reader *r, int k, double *value)
{
    int sr = 0, st;
    const char *s;
    if (plain_field(b, r, k, value)) return 1;
    s = field_of(b, r, k, &sr);
    if (s == NULL) return 0;
    st = parse_real(s, csv_field_avail(r, (size_t)b->col[k]), value);
    if (st == 1) return 0;
    if (st < 0) {
        char detail[96];
        snprintf(detail, sizeof detail, "for %s, got \"%.60s\"", column_name[k], s);
        row_error(b, r->rec_line, b->col[k], "expected a number", detail);
        return -1;
    }
    return 1;
}

/* Largest |norm - 1| of an attitude quaternion the planner normalises (the
 * library's bound for oi_scene.attitude_q). */
#define Q_NORM_TOLERANCE 1e-6

/* The target's shape and attitude: the target_shape and q_w, q_x, q_y, q_z
 * columns into sc. Returns 0, -1 after a parse error (reported: ERR_PARSE),
 * or OI_ERR_SHAPE after reporting an unknown name or, for a facet shape, a
 * quaternion that is not of unit norm. */
static int parse_target(batch *b, const csv_reader *r, oi_scene *sc)
{
    int short_row = 0, i, given = 0, first_empty = -1;
    double q[4] = {1.0, 0.0, 0.0, 0.0}, norm2 = 0.0;
    const char *s = field_of(b, r, C_TARGET_SHAPE, &short_row);
    if (s != NULL && shapes_lookup(b->shapes, s, &sc->shape) != 0) {
        char names[640], detail[760];
        shapes_names(b->shapes, names, sizeof names);
        snprintf(detail, sizeof detail, "\"%.60s\"; known: %s%s", s, names,
                 b->shapes == NULL ? " (more with --shapes FILE)" : "");
        row_error(b, r->rec_line, b->col[C_TARGET_SHAPE], "unknown target_shape", detail);
        return OI_ERR_SHAPE;
    }
    if (b->col[C_Q_W] < 0) return 0; /* attitude: identity (oi_scene_defaults) */
    for (i = 0; i < 4; i++) {
        double x = 0.0;
        int st = parse_opt(b, r, C_Q_W + i, &x);
        if (st < 0) return -1;
        if (st == 0 && first_empty < 0) first_empty = i;
        if (st == 1) {
            given++;
            q[i] = x;
        }
    }
    if (given == 0) return 0;
    if (given != 4) {
        row_error(b, r->rec_line, b->col[C_Q_W + first_empty],
                  "empty field (give all four of q_w, q_x, q_y, q_z or none):",
                  column_name[C_Q_W + first_empty]);
        return -1;
    }
    for (i = 0; i < 4; i++) norm2 += q[i] * q[i];
    /* as the library: the attitude is read (and checked) with a facet shape only */
    if (sc->shape != NULL && !(fabs(sqrt(norm2) - 1.0) <= Q_NORM_TOLERANCE)) {
        char detail[96];
        snprintf(detail, sizeof detail, "(norm %.17g; off 1 by more than 1e-6)", sqrt(norm2));
        row_error(b, r->rec_line, b->col[C_Q_W], "the attitude quaternion is not a unit one",
                  detail);
        return OI_ERR_SHAPE;
    }
    for (i = 0; i < 4; i++) sc->attitude_q[i] = (oi_real)q[i]; /* the library normalises */
    return 0;
}

/* Build the scene, model, goal and camera of one record, in place in the
 * block's next row (q->n; its id is the caller's). Returns 1 when the row
 * is to be computed, 0 when it failed (row holds its status; a message may
 * have flushed the block, the row is then the block's first). */
static int parse_row(batch *b, const csv_reader *r, row_state *row)
{
    pending *q = b->pending;
    oi_scene *sc;
    oi_model *model;
    oi_expose_goal *goal;
    const oi_camera *cam = b->default_camera;
    int has_moon, st, short_row = 0;
    double x;
    const char *s;
    unsigned terms;

    memset(row, 0, sizeof *row);
    row->status_name = PLAN_STATUS_PARSE;

    if (csv_nfields(r) < b->header_fields) {
        size_t k;
        for (k = 0; k < C_COUNT; k++) {
            if (b->col[k] >= 0 && (size_t)b->col[k] >= csv_nfields(r)) {
                char detail[96];
                snprintf(detail, sizeof detail, "(row has %lu fields, the header %lu): %s",
                         (unsigned long)csv_nfields(r), (unsigned long)b->header_fields,
                         column_name[k]);
                row_error(b, r->rec_line, b->col[k], "missing field", detail);
                return 0;
            }
        }
    } else if (csv_nfields(r) > b->header_fields && !b->warned_extra) {
        flush_pending(b);
        fprintf(stderr, "oi-plan: %s: line %lu: note: row has more fields than the header; "
                        "extra fields ignored (reported once)\n", b->path, r->rec_line);
        b->warned_extra = 1;
    }
    /* the slot, once the note above has flushed the block */
    sc = &q->scenes[q->n];
    model = &q->rows[q->n].model;
    goal = &q->rows[q->n].goal;
    *sc = b->scene_defaults;
    memset(model, 0, sizeof *model); /* bytes: blocks are split where they differ */

    if (parse_vec(b, r, C_SUN_X, sc->sun_km, 1) < 0) return 0;
    if (parse_vec(b, r, C_TARGET_X, sc->target_km, 1) < 0) return 0;
    has_moon = parse_vec(b, r, C_MOON_X, sc->moon_km, 0);
    if (has_moon < 0) return 0;
    sc->has_moon = has_moon; /* the Moon occults the Sun whatever the terms */
    st = parse_vec(b, r, C_OBSERVER_X, sc->observer_km, 0);
    if (st < 0) return 0;
    sc->has_observer = st;
    /* velocities (km/s): absent or empty, at rest (oi_scene_defaults) */
    if (parse_vec(b, r, C_TARGET_VX, sc->target_vel_km_s, 0) < 0) return 0;
    if (parse_vec(b, r, C_OBSERVER_VX, sc->observer_vel_km_s, 0) < 0) return 0;

    terms = OI_TERM_SUN | OI_TERM_EARTH | (has_moon ? OI_TERM_MOON : 0u);
    s = field_of(b, r, C_TERMS, &short_row);
    if (s != NULL && s[0] != '\0') {
        if (parse_terms(s, &terms) != 0) {
            char detail[128];
            snprintf(detail, sizeof detail, "got \"%.60s\"; expected sun, earth, moon, sky "
                                            "joined by '+', or all", s);
            row_error(b, r->rec_line, b->col[C_TERMS], "bad terms:", detail);
            return 0;
        }
        if (terms & TERMS_ALL_AVAILABLE) {
            terms = (terms & ~TERMS_ALL_AVAILABLE) | OI_TERM_SUN | OI_TERM_EARTH |
                    (has_moon ? OI_TERM_MOON : 0u);
        }
        if ((terms & OI_TERM_MOON) && !has_moon) {
            row_error(b, r->rec_line, b->col[C_TERMS],
                      "terms include moon but moon_x, moon_y, moon_z are not given", NULL);
            return 0;
        }
    }
    sc->terms = terms;

    x = (double)sc->earth_albedo;
    if ((st = parse_opt(b, r, C_EARTH_ALBEDO, &x)) < 0) return 0;
    sc->earth_albedo = (oi_real)x;
    x = (double)sc->target_albedo;
    if ((st = parse_opt(b, r, C_TARGET_ALBEDO, &x)) < 0) return 0;
    sc->target_albedo = (oi_real)x;
    x = (double)sc->target_radius_m;
    if ((st = parse_opt(b, r, C_TARGET_RADIUS, &x)) < 0) return 0;
    sc->target_radius_m = (oi_real)x;
    x = 1;
    if ((st = parse_opt(b, r, C_ATMOSPHERE, &x)) < 0) return 0;
    if (x != 0 && x != 1) {
        row_error(b, r->rec_line, b->col[C_ATMOSPHERE],
                  "atmosphere must be 1 (default) or 0 (as if the Earth had none)", NULL);
        return 0;
    }
    model->no_atmosphere = x == 0;

    /* the Earth's shape: sphere (default, also an empty field) or wgs84 */
    s = field_of(b, r, C_EARTH_SHAPE, &short_row);
    if (s != NULL && s[0] != '\0') {
        if (same_nocase(s, "wgs84")) {
            model->earth_shape = OI_EARTH_WGS84;
        } else if (same_nocase(s, "sphere")) {
            model->earth_shape = OI_EARTH_SPHERE;
        } else {
            row_error(b, r->rec_line, b->col[C_EARTH_SHAPE],
                      "earth_shape must be sphere (default) or wgs84; got", s);
            return 0;
        }
    }

    /* the band of sun_fraction_atm and e_sun: V (default, also an empty
     * field) or total (total solar irradiance) */
    s = field_of(b, r, C_BAND, &short_row);
    if (s != NULL && s[0] != '\0') {
        if (same_nocase(s, "total")) {
            model->band = OI_BAND_TOTAL;
        } else if (same_nocase(s, "v")) {
            model->band = OI_BAND_V;
        } else {
            row_error(b, r->rec_line, b->col[C_BAND], "band must be V (default) or total; got", s);
            return 0;
        }
    }

    st = parse_target(b, r, sc);
    if (st == -1) return 0;
    if (st < 0) {
        row->status = st;
        row->status_name = oi_status_name(st);
        return 0;
    }

    /* the albedo model: uniform (default), knocke (needs epoch_jd) or map
     * (needs --albedo-map, epoch_jd and earth_rotation_deg) */
    s = field_of(b, r, C_ALBEDO_MODEL, &short_row);
    if (s != NULL && s[0] != '\0' && !same_nocase(s, "uniform")) {
        int has_epoch, has_rotation;
        double jd = 0, rot = 0;
        if (same_nocase(s, "knocke")) {
            model->albedo_model = OI_ALBEDO_KNOCKE;
        } else if (same_nocase(s, "map")) {
            model->albedo_model = OI_ALBEDO_MAP;
        } else {
            row_error(b, r->rec_line, b->col[C_ALBEDO_MODEL],
                      "albedo_model must be uniform, knocke or map; got", s);
            return 0;
        }
        if ((has_epoch = parse_opt(b, r, C_EPOCH_JD, &jd)) < 0) return 0;
        if ((has_rotation = parse_opt(b, r, C_EARTH_ROTATION_DEG, &rot)) < 0) return 0;
        if (!has_epoch) {
            row_error(b, r->rec_line, b->col[C_ALBEDO_MODEL],
                      "albedo_model knocke and map need epoch_jd (Julian date, UTC)", NULL);
            return 0;
        }
        sc->epoch_jd = (oi_real)jd;
        if (model->albedo_model == OI_ALBEDO_MAP) {
            if (b->albedo_map == NULL) {
                row_error(b, r->rec_line, b->col[C_ALBEDO_MODEL],
                          "albedo_model map needs --albedo-map FILE", NULL);
                return 0;
            }
            if (!has_rotation) {
                row_error(b, r->rec_line, b->col[C_ALBEDO_MODEL],
                          "albedo_model map needs earth_rotation_deg (the Greenwich "
                          "meridian's angle from the frame's x axis)", NULL);
                return 0;
            }
            /* degrees to radians: the range check is the library's */
            sc->earth_rotation_rad = (oi_real)(rot * (3.14159265358979323846 / 180.0));
            model->albedo_map = b->albedo_map->values;
            model->albedo_map_n_lat = b->albedo_map->n_lat;
            model->albedo_map_n_lon = b->albedo_map->n_lon;
        }
    }

    memset(goal, 0, sizeof *goal);
    s = field_of(b, r, C_SKY, &short_row);
    if (s != NULL && parse_sky(s, &goal->sky) < 0) {
        row_error(b, r->rec_line, b->col[C_SKY],
                  "sky must be none, zodiacal, moon or all, joined by +; got", s);
        return 0;
    }
    /* sensor temperature (deg C): absent or empty, the camera's dark current as it stands */
    if ((st = parse_opt(b, r, C_SENSOR_TEMP, &x)) < 0) return 0;
    if (st == 1) {
        goal->has_sensor_temp = 1u;
        goal->sensor_temp_c = (oi_real)x;
    }

    s = field_of(b, r, C_CAMERA, &short_row);
    if (s != NULL && s[0] != '\0') {
        /* rows of one pass name one camera: the last name's look-up again */
        if (b->last_camera != NULL && strcmp(s, b->last_camera_name) == 0) {
            cam = b->last_camera;
        } else {
            cam = oi_camera_find(s);
            if (cam != NULL && strlen(s) < sizeof b->last_camera_name) {
                memcpy(b->last_camera_name, s, strlen(s) + 1);
                b->last_camera = cam;
            }
        }
        if (cam == NULL) {
            int i;
            char detail[400];
            size_t n = (size_t)snprintf(detail, sizeof detail, "\"%.60s\"; built-in cameras:", s);
            for (i = 0; oi_camera_builtin(i) != NULL && n < sizeof detail; i++) {
                n += (size_t)snprintf(detail + n, sizeof detail - n, " %s",
                                      oi_camera_builtin(i)->name);
            }
            row_error(b, r->rec_line, b->col[C_CAMERA], "unknown camera", detail);
            row->status = OI_ERR_CAMERA;
            row->status_name = oi_status_name(OI_ERR_CAMERA);
            return 0;
        }
    }

    q->rows[q->n].camera = cam;
    return 1;
}

/* The rest of a parsed row once its illumination (status st) and, with an
 * observer, its exposure (status st2) are in: flags, messages. Returns 1
 * when the row is OK (or a warning), 0 when it is an error. */
static int finish_row(batch *b, const oi_scene *sc, const oi_illum *illum, int st,
                      const oi_exposure *expo, int st2, pending_row *p)
{
    row_state *row = &p->state;
    row->status = st;
    row->status_name = oi_status_name(st);
    if (st < 0) {
        row_error(b, p->line, -1, "cannot compute the row:", row->status_name);
        return 0;
    }
    if (illum->shadow.region == OI_SHADOW_UMBRA) {
        row->flags |= OI_FLAG_ECLIPSED;
    } else if (illum->shadow.region != OI_SHADOW_LIT) {
        row->flags |= OI_FLAG_PENUMBRA;
    }
    if (illum->sun_moon_hidden > (oi_real)0) row->flags |= OI_FLAG_MOON_SHADOW;
    if (sc->has_observer) {
        if (st2 < 0) {
            row->status = st2;
            row->status_name = oi_status_name(st2);
            row_error(b, p->line, -1, "cannot compute the exposure:", row->status_name);
            return 0;
        }
        row->flags = expo->flags;
        row->has_observer = 1;
    }
    row->has_numbers = 1;
    return 1;
}

/* Whether row i of the block gets an exposure: parsed, with an observer,
 * its illumination computed. */
static int exposes(const pending *q, long i)
{
    return q->rows[i].compute && q->status[i] >= 0 && q->scenes[i].has_observer;
}

/* Compute the block's parsed rows (one library call per run of rows with
 * the same model), then write every row of the block in order. */
static void flush_pending(batch *b)
{
    pending *q = b->pending;
    long i = 0, j, k;
    size_t used = 0;
    if (q == NULL || q->n == 0 || b->flushing) return;
    b->flushing = 1;
    while (i < q->n) {
        if (!q->rows[i].compute) {
            i++;
            continue;
        }
        for (j = i + 1; j < q->n && q->rows[j].compute &&
                        memcmp(&q->rows[j].model, &q->rows[i].model, sizeof q->rows[i].model) == 0;
             j++) {
        }
        for (k = i; k < j; k++) q->run[k] = i;
        (void)oi_illuminate_batch_outputs(j - i, q->scenes + i, &q->rows[i].model, PLAN_OUTPUTS,
                                          q->illum + i, q->status + i);
        i = j;
    }
    /* the exposures: one call per run of rows with an observer and their
     * illumination computed under the same camera, model and goal (the
     * batch's rows are the single calls' bit for bit); consecutive rows that
     * expose are all computed: one model where they lie in one model run */
    i = 0;
    while (i < q->n) {
        if (!exposes(q, i)) {
            i++;
            continue;
        }
        for (j = i + 1; j < q->n && exposes(q, j) && q->rows[j].camera == q->rows[i].camera &&
                        q->run[j] == q->run[i] &&
                        memcmp(&q->rows[j].goal, &q->rows[i].goal, sizeof q->rows[i].goal) == 0;
             j++) {
        }
        (void)oi_expose_scene_batch_outputs(j - i, q->rows[i].camera, q->scenes + i,
                                            q->illum + i, &q->rows[i].model, &q->rows[i].goal,
                                            PLAN_EXPOSE_OUTPUTS, q->expo + i, q->expo_status + i);
        i = j;
    }
    for (i = 0; i < q->n; i++) {
        pending_row *p = &q->rows[i];
        size_t len;
        if (p->compute && !finish_row(b, &q->scenes[i], &q->illum[i], q->status[i], &q->expo[i],
                                      q->expo_status[i], p))
            b->bad++;
        /* the rows' text into the block's (a terminal: each at once) */
        if (used > sizeof q->text - OUT_CSV_LINE_MAX) {
            (void)fwrite(q->text, 1, used, b->out);
            used = 0;
        }
        len = out_csv_text(q->text + used, p->id, p->state.status_name, p->state.has_numbers,
                         p->state.has_observer, p->state.flags, &q->illum[i], &q->expo[i]);
        if (len == 0) { /* an id to quote or a long one: on its own, after the rows before */
            (void)fwrite(q->text, 1, used, b->out);
            used = 0;
            out_csv_fields(b->out, p->id, p->state.status_name, p->state.has_numbers,
                           p->state.has_observer, p->state.flags, &q->illum[i], &q->expo[i]);
        }
        used += len;
        if (b->out_tty) {
            (void)fwrite(q->text, 1, used, b->out);
            used = 0;
        }
        if (b->summary) {
            plan_row row;
            memset(&row, 0, sizeof row);
            row.status = p->state.status;
            row.status_name = p->state.status_name;
            row.has_numbers = p->state.has_numbers;
            row.has_observer = p->state.has_observer;
            row.flags = p->state.flags;
            if (row.has_numbers) row.illum = q->illum[i];
            if (row.has_observer) row.expo = q->expo[i];
            if (windows_add(b->wins, p->id, &row) != 0) {
                fprintf(stderr, "oi-plan: out of memory: no window summary\n");
                b->summary = NULL;
            }
        }
    }
    (void)fwrite(q->text, 1, used, b->out);
    q->n = 0;
    q->id_used = 0;
    b->flushing = 0;
}

/* Room in the block's ids for an id of len bytes (its NUL counted): the
 * block is flushed when they are full. Called before the row is parsed
 * into the block. */
static void room_for_id(batch *b, size_t len)
{
    if (b->pending->id_used + len > sizeof b->pending->ids) flush_pending(b);
}

/* Append the row just read (parsed into the block's next row, or failed)
 * to the block (room_for_id made room for its id); the block is flushed
 * when full, and at once when the id could not be copied. */
static void add_pending(batch *b, const char *id, size_t len, const row_state *row,
                        unsigned long line, int compute)
{
    pending *q = b->pending;
    pending_row *p = &q->rows[q->n];
    int at_once = 0;
    if (q->id_used + len <= sizeof q->ids) {
        memcpy(q->ids + q->id_used, id, len);
        p->id = q->ids + q->id_used;
        q->id_used += len;
    } else {
        p->id = id; /* valid until the next record is read */
        at_once = 1;
    }
    p->state = *row;
    p->compute = compute;
    p->line = line;
    if (!compute) b->bad++; /* failed while parsing */
    q->n++;
    if (at_once || q->n == PENDING_MAX) flush_pending(b);
}

/* Progress on stderr, only when it is a terminal, at most once a second. */
static void progress(unsigned long rows, time_t *last, int tty)
{
    time_t now;
    if (!tty || (rows & 1023u) != 0u) return;
    now = time(NULL);
    if (now == *last) return;
    *last = now;
    fprintf(stderr, "\roi-plan: %lu rows...", rows);
    fflush(stderr);
}

int batch_run(const char *path, const oi_camera *default_camera, const plan_shapes *shapes,
              FILE *out, FILE *summary)
{
    return batch_run_map(path, default_camera, shapes, NULL, out, summary);
}

int batch_run_map(const char *path, const oi_camera *default_camera, const plan_shapes *shapes,
                  const plan_albedo_map *albedo_map, FILE *out, FILE *summary)
{
    batch b;
    window_list wins;
    csv_reader r;
    FILE *fp;
    int st, result = PLAN_EXIT_OK, tty;
    unsigned long rows = 0;
    time_t last;

    memset(&b, 0, sizeof b);
    windows_init(&wins, 5.0); /* the default SNR goal of oi_expose */
    b.default_camera = default_camera;
    b.shapes = shapes;
    b.albedo_map = albedo_map;
    b.out = out;
    b.wins = &wins;
    b.summary = summary;
    b.path = strcmp(path, "-") == 0 ? "<stdin>" : path;
    oi_scene_defaults(&b.scene_defaults);
    b.pending = malloc(sizeof *b.pending);
    if (b.pending == NULL) {
        fprintf(stderr, "oi-plan: out of memory\n");
        return PLAN_EXIT_INPUT;
    }
    b.pending->n = 0;
    b.pending->id_used = 0;
    fp = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
    if (fp == NULL) {
        fprintf(stderr, "oi-plan: cannot open '%s': %s\n", path, strerror(errno));
        free(b.pending);
        return PLAN_EXIT_INPUT;
    }
    csv_init(&r, fp);
    st = read_header(&b, &r);
    if (st != 0) {
        csv_free(&r);
        if (fp != stdin) fclose(fp);
        free(b.pending);
        return st;
    }
    /* rows go out in blocks of OUT_BUFFER bytes (a pipe's default is 4 KiB:
     * a write per ~13 rows); a terminal keeps its line buffering */
    b.out_tty = isatty(fileno(out));
    if (!b.out_tty) (void)setvbuf(out, NULL, _IOFBF, OUT_BUFFER);
    out_csv_header(out);
    tty = isatty(fileno(stderr));
    last = time(NULL);

    for (;;) {
        row_state row;
        char idbuf[32];
        size_t len;
        const char *id;
        int sr = 0, compute;
        st = csv_next(&r);
        if (st == CSV_END) break;
        rows++;
        if (b.col[C_ID] < 0) snprintf(idbuf, sizeof idbuf, "%lu", rows);
        if (st == CSV_IO || st == CSV_NOMEM) {
            flush_pending(&b);
            fprintf(stderr, "oi-plan: %s: line %lu: %s\n", b.path, r.line, csv_result_text(st));
            result = PLAN_EXIT_INPUT;
            break;
        }
        if (st != CSV_RECORD) {
            char where[48];
            snprintf(where, sizeof where, "(at character %lu of the line)", r.err_col);
            row_error(&b, r.err_line, -1, csv_result_text(st), where);
            memset(&row, 0, sizeof row);
            row.status_name = PLAN_STATUS_PARSE;
            id = b.col[C_ID] >= 0 ? "" : idbuf;
            len = strlen(id) + 1;
            room_for_id(&b, len);
            add_pending(&b, id, len, &row, r.err_line, 0);
            continue;
        }
        id = b.col[C_ID] >= 0 ? field_of(&b, &r, C_ID, &sr) : idbuf;
        len = strlen(id) + 1;
        room_for_id(&b, len);
        compute = parse_row(&b, &r, &row);
        add_pending(&b, id, len, &row, r.rec_line, compute);
        progress(rows, &last, tty);
    }
    flush_pending(&b);
    if (tty && rows >= 1024) fprintf(stderr, "\roi-plan: %lu rows done.   \n", rows);
    if (b.summary) windows_print(&wins, b.summary);
    windows_free(&wins);
    if (b.bad > 0) {
        fprintf(stderr, "oi-plan: %lu of %lu rows had errors\n", b.bad, rows);
        if (result == PLAN_EXIT_OK) result = PLAN_EXIT_ROWS;
    }
    if (fflush(out) != 0 || ferror(out)) {
        fprintf(stderr, "oi-plan: error writing the output\n");
        result = PLAN_EXIT_INPUT;
    }
    csv_free(&r);
    if (fp != stdin) fclose(fp);
    free(b.pending);
    return result;
}
