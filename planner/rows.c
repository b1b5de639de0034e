/* SPDX-License-Identifier: MIT */
/* rows.c: the planner's row rules (see rows.h, docs/planner.md): the
 * header's columns, a record's fields into a scene, model, goal and camera,
 * the row's errors, a computed row's status and flags. oi-plan's batch
 * (batch.c) and the viewer's WebAssembly module (web/wasm/plan_wasm.c) both
 * compile this file: it does no I/O and allocates nothing. */
#include "rows.h"

#include <ctype.h>
#include <stdarg.h>
#include <math.h>
#include <stdio.h> /* snprintf: messages into the caller's buffers */
#include <string.h>

#include "numtext.h"

const char *const plan_column_name[PLAN_C_COUNT] = {
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

const char plan_header_hint[] = "oi-plan: the header must name at least: "
                                "sun_x,sun_y,sun_z,target_x,target_y,target_z (any order)\n";

void plan_rules_init(plan_rules *rules, const oi_camera *default_camera,
                     const plan_shapes *shapes, const plan_albedo_map *albedo_map)
{
    int k;
    memset(rules, 0, sizeof *rules);
    for (k = 0; k < PLAN_C_COUNT; k++) rules->col[k] = -1;
    rules->default_camera = default_camera;
    rules->shapes = shapes;
    rules->albedo_map = albedo_map;
    oi_scene_defaults(&rules->scene_defaults);
}

/* A row's message: "what[ detail]" at line, field (-1: none). */
static void fail(plan_msg *msg, unsigned long line, long field, const char *what,
                 const char *detail)
{
    msg->line = line;
    msg->field = field;
    (void)snprintf(msg->text, sizeof msg->text, "%s%s%s", what, detail ? " " : "",
                   detail ? detail : "");
}

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

/* Text of column k in the current record: NULL when the column is absent
 * from the header, "" when empty. *short_row is set when the header has the
 * column but the row is too short. */
static const char *field_of(const plan_rules *ru, const csv_reader *r, int k, int *short_row)
{
    const char *s;
    if (ru->col[k] < 0) return NULL;
    s = csv_field(r, (size_t)ru->col[k]);
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
static int plain_field(const plan_rules *ru, const csv_reader *r, int k, double *x)
{
    const long c = ru->col[k];
    const char *s;
    char *end;
    if (c < 0 || (size_t)c >= csv_nfields(r)) return 0;
    s = csv_field(r, (size_t)c);
    return num_parse_plain(s, csv_record_end(r), x, &end) && *end == '\0';
}

/* Read a group of three coordinates; returns 1 given, 0 all empty or the
 * columns absent, -1 after reporting a parse error. */
static int parse_vec(const plan_rules *ru, const csv_reader *r, int k0, oi_real v[3], int required,
                     plan_msg *msg)
{
    int i, given = 0, first_empty = -1, short_row = 0;
    double x0, x1, x2;
    if (plain_field(ru, r, k0, &x0) && plain_field(ru, r, k0 + 1, &x1) &&
        plain_field(ru, r, k0 + 2, &x2)) { /* the common row */
        v[0] = (oi_real)x0;
        v[1] = (oi_real)x1;
        v[2] = (oi_real)x2;
        return 1;
    }
    for (i = 0; i < 3; i++) {
        const char *s = field_of(ru, r, k0 + i, &short_row);
        double x = 0;
        int st;
        if (s == NULL) return 0;
        st = parse_real(s, csv_field_avail(r, (size_t)ru->col[k0 + i]), &x);
        if (st < 0) {
            char detail[96];
            snprintf(detail, sizeof detail, "for %s, got \"%.60s\"", plan_column_name[k0 + i], s);
            fail(msg, r->rec_line, ru->col[k0 + i], "expected a number", detail);
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
    fail(msg, r->rec_line, ru->col[k0 + first_empty],
         required ? "empty field for a required column:"
                  : "empty field (give all three coordinates or none):",
         plan_column_name[k0 + first_empty]);
    return -1;
}

/* Optional scalar column: 0 absent or empty (value untouched), 1 given,
 * -1 parse error (reported). */
static int parse_opt(const plan_rules *ru, const csv_reader *r, int k, double *value, plan_msg *msg)
{
    int sr = 0, st;
    const char *s;
    if (plain_field(ru, r, k, value)) return 1;
    s = field_of(ru, r, k, &sr);
    if (s == NULL) return 0;
    st = parse_real(s, csv_field_avail(r, (size_t)ru->col[k]), value);
    if (st == 1) return 0;
    if (st < 0) {
        char detail[96];
        snprintf(detail, sizeof detail, "for %s, got \"%.60s\"", plan_column_name[k], s);
        fail(msg, r->rec_line, ru->col[k], "expected a number", detail);
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
static int parse_target(const plan_rules *ru, const csv_reader *r, oi_scene *sc, plan_msg *msg)
{
    int short_row = 0, i, given = 0, first_empty = -1;
    double q[4] = {1.0, 0.0, 0.0, 0.0}, norm2 = 0.0;
    const char *s = field_of(ru, r, PLAN_C_TARGET_SHAPE, &short_row);
    if (s != NULL && shapes_lookup(ru->shapes, s, &sc->shape) != 0) {
        char names[640], detail[760];
        shapes_names(ru->shapes, names, sizeof names);
        snprintf(detail, sizeof detail, "\"%.60s\"; known: %s%s", s, names,
                 ru->shapes == NULL ? " (more with --shapes FILE)" : "");
        fail(msg, r->rec_line, ru->col[PLAN_C_TARGET_SHAPE], "unknown target_shape", detail);
        return OI_ERR_SHAPE;
    }
    if (ru->col[PLAN_C_Q_W] < 0) return 0; /* attitude: identity (oi_scene_defaults) */
    for (i = 0; i < 4; i++) {
        double x = 0.0;
        int st = parse_opt(ru, r, PLAN_C_Q_W + i, &x, msg);
        if (st < 0) return -1;
        if (st == 0 && first_empty < 0) first_empty = i;
        if (st == 1) {
            given++;
            q[i] = x;
        }
    }
    if (given == 0) return 0;
    if (given != 4) {
        fail(msg, r->rec_line, ru->col[PLAN_C_Q_W + first_empty],
             "empty field (give all four of q_w, q_x, q_y, q_z or none):",
             plan_column_name[PLAN_C_Q_W + first_empty]);
        return -1;
    }
    for (i = 0; i < 4; i++) norm2 += q[i] * q[i];
    /* as the library: the attitude is read (and checked) with a facet shape only */
    if (sc->shape != NULL && !(fabs(sqrt(norm2) - 1.0) <= Q_NORM_TOLERANCE)) {
        char detail[96];
        snprintf(detail, sizeof detail, "(norm %.17g; off 1 by more than 1e-6)", sqrt(norm2));
        fail(msg, r->rec_line, ru->col[PLAN_C_Q_W], "the attitude quaternion is not a unit one",
             detail);
        return OI_ERR_SHAPE;
    }
    for (i = 0; i < 4; i++) sc->attitude_q[i] = (oi_real)q[i]; /* the library normalises */
    return 0;
}

int plan_row_read(plan_rules *ru, const csv_reader *r, oi_scene *sc, oi_model *model,
                  oi_expose_goal *goal, const oi_camera **camera, plan_row_state *row,
                  plan_msg *msg)
{
    const oi_camera *cam = ru->default_camera;
    int has_moon, st, short_row = 0;
    double x;
    const char *s;
    unsigned terms;

    memset(row, 0, sizeof *row);
    row->status_name = PLAN_STATUS_PARSE;
    msg->line = 0;

    if (csv_nfields(r) < ru->header_fields) {
        size_t k;
        for (k = 0; k < PLAN_C_COUNT; k++) {
            if (ru->col[k] >= 0 && (size_t)ru->col[k] >= csv_nfields(r)) {
                char detail[96];
                snprintf(detail, sizeof detail, "(row has %lu fields, the header %lu): %s",
                         (unsigned long)csv_nfields(r), (unsigned long)ru->header_fields,
                         plan_column_name[k]);
                fail(msg, r->rec_line, ru->col[k], "missing field", detail);
                return 0;
            }
        }
    }
    *sc = ru->scene_defaults;
    memset(model, 0, sizeof *model); /* bytes: blocks are split where they differ */

    if (parse_vec(ru, r, PLAN_C_SUN_X, sc->sun_km, 1, msg) < 0) return 0;
    if (parse_vec(ru, r, PLAN_C_TARGET_X, sc->target_km, 1, msg) < 0) return 0;
    has_moon = parse_vec(ru, r, PLAN_C_MOON_X, sc->moon_km, 0, msg);
    if (has_moon < 0) return 0;
    sc->has_moon = has_moon; /* the Moon occults the Sun whatever the terms */
    st = parse_vec(ru, r, PLAN_C_OBSERVER_X, sc->observer_km, 0, msg);
    if (st < 0) return 0;
    sc->has_observer = st;
    /* velocities (km/s): absent or empty, at rest (oi_scene_defaults) */
    if (parse_vec(ru, r, PLAN_C_TARGET_VX, sc->target_vel_km_s, 0, msg) < 0) return 0;
    if (parse_vec(ru, r, PLAN_C_OBSERVER_VX, sc->observer_vel_km_s, 0, msg) < 0) return 0;

    terms = OI_TERM_SUN | OI_TERM_EARTH | (has_moon ? OI_TERM_MOON : 0u);
    s = field_of(ru, r, PLAN_C_TERMS, &short_row);
    if (s != NULL && s[0] != '\0') {
        if (parse_terms(s, &terms) != 0) {
            char detail[128];
            snprintf(detail, sizeof detail, "got \"%.60s\"; expected sun, earth, moon, sky "
                                            "joined by '+', or all", s);
            fail(msg, r->rec_line, ru->col[PLAN_C_TERMS], "bad terms:", detail);
            return 0;
        }
        if (terms & TERMS_ALL_AVAILABLE) {
            terms = (terms & ~TERMS_ALL_AVAILABLE) | OI_TERM_SUN | OI_TERM_EARTH |
                    (has_moon ? OI_TERM_MOON : 0u);
        }
        if ((terms & OI_TERM_MOON) && !has_moon) {
            fail(msg, r->rec_line, ru->col[PLAN_C_TERMS],
                 "terms include moon but moon_x, moon_y, moon_z are not given", NULL);
            return 0;
        }
    }
    sc->terms = terms;

    x = (double)sc->earth_albedo;
    if ((st = parse_opt(ru, r, PLAN_C_EARTH_ALBEDO, &x, msg)) < 0) return 0;
    sc->earth_albedo = (oi_real)x;
    x = (double)sc->target_albedo;
    if ((st = parse_opt(ru, r, PLAN_C_TARGET_ALBEDO, &x, msg)) < 0) return 0;
    sc->target_albedo = (oi_real)x;
    x = (double)sc->target_radius_m;
    if ((st = parse_opt(ru, r, PLAN_C_TARGET_RADIUS, &x, msg)) < 0) return 0;
    sc->target_radius_m = (oi_real)x;
    x = 1;
    if ((st = parse_opt(ru, r, PLAN_C_ATMOSPHERE, &x, msg)) < 0) return 0;
    if (x != 0 && x != 1) {
        fail(msg, r->rec_line, ru->col[PLAN_C_ATMOSPHERE],
             "atmosphere must be 1 (default) or 0 (as if the Earth had none)", NULL);
        return 0;
    }
    model->no_atmosphere = x == 0;

    /* the Earth's shape: sphere (default, also an empty field) or wgs84 */
    s = field_of(ru, r, PLAN_C_EARTH_SHAPE, &short_row);
    if (s != NULL && s[0] != '\0') {
        if (same_nocase(s, "wgs84")) {
            model->earth_shape = OI_EARTH_WGS84;
        } else if (same_nocase(s, "sphere")) {
            model->earth_shape = OI_EARTH_SPHERE;
        } else {
            fail(msg, r->rec_line, ru->col[PLAN_C_EARTH_SHAPE],
                 "earth_shape must be sphere (default) or wgs84; got", s);
            return 0;
        }
    }

    /* the band of sun_fraction_atm and e_sun: V (default, also an empty
     * field) or total (total solar irradiance) */
    s = field_of(ru, r, PLAN_C_BAND, &short_row);
    if (s != NULL && s[0] != '\0') {
        if (same_nocase(s, "total")) {
            model->band = OI_BAND_TOTAL;
        } else if (same_nocase(s, "v")) {
            model->band = OI_BAND_V;
        } else {
            fail(msg, r->rec_line, ru->col[PLAN_C_BAND], "band must be V (default) or total; got",
                 s);
            return 0;
        }
    }

    st = parse_target(ru, r, sc, msg);
    if (st == -1) return 0;
    if (st < 0) {
        row->status = st;
        row->status_name = oi_status_name(st);
        return 0;
    }

    /* the albedo model: uniform (default), knocke (needs epoch_jd) or map
     * (needs --albedo-map, epoch_jd and earth_rotation_deg) */
    s = field_of(ru, r, PLAN_C_ALBEDO_MODEL, &short_row);
    if (s != NULL && s[0] != '\0' && !same_nocase(s, "uniform")) {
        int has_epoch, has_rotation;
        double jd = 0, rot = 0;
        if (same_nocase(s, "knocke")) {
            model->albedo_model = OI_ALBEDO_KNOCKE;
        } else if (same_nocase(s, "map")) {
            model->albedo_model = OI_ALBEDO_MAP;
        } else {
            fail(msg, r->rec_line, ru->col[PLAN_C_ALBEDO_MODEL],
                 "albedo_model must be uniform, knocke or map; got", s);
            return 0;
        }
        if ((has_epoch = parse_opt(ru, r, PLAN_C_EPOCH_JD, &jd, msg)) < 0) return 0;
        if ((has_rotation = parse_opt(ru, r, PLAN_C_EARTH_ROTATION_DEG, &rot, msg)) < 0) return 0;
        if (!has_epoch) {
            fail(msg, r->rec_line, ru->col[PLAN_C_ALBEDO_MODEL],
                 "albedo_model knocke and map need epoch_jd (Julian date, UTC)", NULL);
            return 0;
        }
        sc->epoch_jd = (oi_real)jd;
        if (model->albedo_model == OI_ALBEDO_MAP) {
            if (ru->albedo_map == NULL) {
                fail(msg, r->rec_line, ru->col[PLAN_C_ALBEDO_MODEL],
                     "albedo_model map needs --albedo-map FILE", NULL);
                return 0;
            }
            if (!has_rotation) {
                fail(msg, r->rec_line, ru->col[PLAN_C_ALBEDO_MODEL],
                     "albedo_model map needs earth_rotation_deg (the Greenwich "
                     "meridian's angle from the frame's x axis)", NULL);
                return 0;
            }
            /* degrees to radians: the range check is the library's */
            sc->earth_rotation_rad = (oi_real)(rot * (3.14159265358979323846 / 180.0));
            model->albedo_map = ru->albedo_map->values;
            model->albedo_map_n_lat = ru->albedo_map->n_lat;
            model->albedo_map_n_lon = ru->albedo_map->n_lon;
        }
    }

    memset(goal, 0, sizeof *goal);
    s = field_of(ru, r, PLAN_C_SKY, &short_row);
    if (s != NULL && parse_sky(s, &goal->sky) < 0) {
        fail(msg, r->rec_line, ru->col[PLAN_C_SKY],
             "sky must be none, zodiacal, moon or all, joined by +; got", s);
        return 0;
    }
    /* sensor temperature (deg C): absent or empty, the camera's dark current as it stands */
    if ((st = parse_opt(ru, r, PLAN_C_SENSOR_TEMP, &x, msg)) < 0) return 0;
    if (st == 1) {
        goal->has_sensor_temp = 1u;
        goal->sensor_temp_c = (oi_real)x;
    }

    s = field_of(ru, r, PLAN_C_CAMERA, &short_row);
    if (s != NULL && s[0] != '\0') {
        /* rows of one pass name one camera: the last name's look-up again */
        if (ru->last_camera != NULL && strcmp(s, ru->last_camera_name) == 0) {
            cam = ru->last_camera;
        } else {
            cam = oi_camera_find(s);
            if (cam != NULL && strlen(s) < sizeof ru->last_camera_name) {
                memcpy(ru->last_camera_name, s, strlen(s) + 1);
                ru->last_camera = cam;
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
            fail(msg, r->rec_line, ru->col[PLAN_C_CAMERA], "unknown camera", detail);
            row->status = OI_ERR_CAMERA;
            row->status_name = oi_status_name(OI_ERR_CAMERA);
            return 0;
        }
    }

    *camera = cam;
    return 1;
}

int plan_row_finish(const oi_scene *sc, const oi_illum *illum, int st, const oi_exposure *expo,
                    int st2, unsigned long line, plan_row_state *row, plan_msg *msg)
{
    row->status = st;
    row->status_name = oi_status_name(st);
    row->has_numbers = 0;
    row->has_observer = 0;
    row->flags = 0u;
    msg->line = 0;
    if (st < 0) {
        fail(msg, line, -1, "cannot compute the row:", row->status_name);
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
            fail(msg, line, -1, "cannot compute the exposure:", row->status_name);
            return 0;
        }
        row->flags = expo->flags;
        row->has_observer = 1;
    }
    row->has_numbers = 1;
    return 1;
}
const char *plan_row_id(const plan_rules *rules, const csv_reader *r, int st, unsigned long rows,
                        char *idbuf)
{
    const long c = rules->col[PLAN_C_ID];
    if (c < 0) {
        snprintf(idbuf, 32, "%lu", rows);
        return idbuf;
    }
    return st == CSV_RECORD && (size_t)c < csv_nfields(r) ? csv_field(r, (size_t)c) : "";
}

void plan_csv_error(const csv_reader *r, int st, plan_msg *msg)
{
    char where[48];
    snprintf(where, sizeof where, "(at character %lu of the line)", r->err_col);
    fail(msg, r->err_line, -1, csv_result_text(st), where);
}

/* A line appended to plan_header's notes (dropped when it does not fit). */
static void note(char *notes, size_t size, size_t *len, const char *fmt, ...)
{
    va_list ap;
    int n;
    if (*len >= size) return;
    va_start(ap, fmt);
    n = vsnprintf(notes + *len, size - *len, fmt, ap);
    va_end(ap);
    if (n > 0 && (size_t)n < size - *len) {
        *len += (size_t)n;
    } else {
        notes[*len] = '\0';
    }
}

int plan_header(plan_rules *ru, const csv_reader *r, char *notes, size_t note_size)
{
    size_t i, len = 0;
    int k, missing = 0;
    static const int required[] = {PLAN_C_SUN_X,    PLAN_C_SUN_Y,    PLAN_C_SUN_Z,
                                   PLAN_C_TARGET_X, PLAN_C_TARGET_Y, PLAN_C_TARGET_Z};
    static const int groups[][3] = {{PLAN_C_MOON_X, PLAN_C_MOON_Y, PLAN_C_MOON_Z},
                                    {PLAN_C_OBSERVER_X, PLAN_C_OBSERVER_Y, PLAN_C_OBSERVER_Z},
                                    {PLAN_C_TARGET_VX, PLAN_C_TARGET_VY, PLAN_C_TARGET_VZ},
                                    {PLAN_C_OBSERVER_VX, PLAN_C_OBSERVER_VY, PLAN_C_OBSERVER_VZ}};

    if (note_size > 0) notes[0] = '\0';
    for (k = 0; k < PLAN_C_COUNT; k++) ru->col[k] = -1;
    ru->header_fields = csv_nfields(r);
    for (i = 0; i < csv_nfields(r); i++) {
        const char *name = csv_field(r, i);
        int found = 0;
        for (k = 0; k < PLAN_C_COUNT; k++) {
            if (!same_nocase(name, plan_column_name[k])) continue;
            found = 1;
            if (ru->col[k] >= 0) {
                note(notes, note_size, &len, "line %lu: column '%s' appears twice "
                                              "(columns %ld and %lu)\n",
                     r->rec_line, plan_column_name[k], ru->col[k] + 1, (unsigned long)i + 1);
                return -1;
            }
            ru->col[k] = (long)i;
        }
        if (!found) {
            note(notes, note_size, &len, "note: ignoring unknown column %lu '%.60s'\n",
                 (unsigned long)i + 1, name);
        }
    }
    for (k = 0; k < (int)(sizeof required / sizeof required[0]); k++) {
        if (ru->col[required[k]] < 0) {
            note(notes, note_size, &len, "line %lu: missing required column '%s'\n",
                 r->rec_line, plan_column_name[required[k]]);
            missing = 1;
        }
    }
    for (k = 0; k < (int)(sizeof groups / sizeof groups[0]); k++) {
        int n = (ru->col[groups[k][0]] >= 0) + (ru->col[groups[k][1]] >= 0) +
                (ru->col[groups[k][2]] >= 0);
        if (n != 0 && n != 3) {
            note(notes, note_size, &len, "line %lu: columns %s, %s, %s must come together\n",
                 r->rec_line, plan_column_name[groups[k][0]], plan_column_name[groups[k][1]],
                 plan_column_name[groups[k][2]]);
            missing = 1;
        }
    }
    {
        int n = 0;
        for (k = PLAN_C_Q_W; k <= PLAN_C_Q_Z; k++) n += ru->col[k] >= 0;
        if (n != 0 && n != 4) {
            note(notes, note_size, &len, "line %lu: columns q_w, q_x, q_y, q_z must come "
                                          "together\n", r->rec_line);
            missing = 1;
        }
    }
    return missing ? -2 : 0;
}
