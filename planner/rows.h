/* SPDX-License-Identifier: MIT */
/*
 * rows.h: the planner's row rules (rows.c): how the header of a scenario
 * CSV names its columns, how a record's fields become a scene, a model, an
 * exposure goal and a camera (and a target shape), the row's errors and
 * their messages, and the status and flags of a computed row. oi-plan's
 * batch (batch.c) and the viewer's WebAssembly module (web/wasm/plan_wasm.c)
 * both run these rules: the file needs no I/O and allocates nothing (it
 * formats messages into the caller's buffers).
 */
#ifndef OI_PLAN_ROWS_H
#define OI_PLAN_ROWS_H

#include <stddef.h>

#include "albedo_map.h"
#include "csv_read.h"
#include "orbillum.h"
#include "shapes.h"

/* Status name of a row whose text could not be parsed (planner level, not a
 * library status). */
#define PLAN_STATUS_PARSE "ERR_PARSE"

enum plan_column {
    PLAN_C_ID,
    PLAN_C_SUN_X, PLAN_C_SUN_Y, PLAN_C_SUN_Z,
    PLAN_C_TARGET_X, PLAN_C_TARGET_Y, PLAN_C_TARGET_Z,
    PLAN_C_MOON_X, PLAN_C_MOON_Y, PLAN_C_MOON_Z,
    PLAN_C_OBSERVER_X, PLAN_C_OBSERVER_Y, PLAN_C_OBSERVER_Z,
    PLAN_C_TERMS, PLAN_C_EARTH_ALBEDO, PLAN_C_TARGET_ALBEDO, PLAN_C_TARGET_RADIUS, PLAN_C_CAMERA,
    PLAN_C_ATMOSPHERE,
    PLAN_C_SKY,
    PLAN_C_TARGET_VX, PLAN_C_TARGET_VY, PLAN_C_TARGET_VZ,
    PLAN_C_OBSERVER_VX, PLAN_C_OBSERVER_VY, PLAN_C_OBSERVER_VZ,
    PLAN_C_TARGET_SHAPE, PLAN_C_Q_W, PLAN_C_Q_X, PLAN_C_Q_Y, PLAN_C_Q_Z, PLAN_C_EARTH_SHAPE,
    PLAN_C_ALBEDO_MODEL, PLAN_C_EPOCH_JD, PLAN_C_EARTH_ROTATION_DEG,
    PLAN_C_SENSOR_TEMP,
    PLAN_C_BAND,
    PLAN_C_COUNT
};

/* The input column names, as the header spells them (any case). */
extern const char *const plan_column_name[PLAN_C_COUNT];

/* Bytes of a message's text (plan_msg.text), with its NUL. */
#define PLAN_MSG_TEXT 1024

/* A message about a row: what oi-plan prints on stderr as
 * "oi-plan: PATH: line L[, column C]: TEXT" (column: field + 1, when
 * field >= 0). line 0: no message. */
typedef struct plan_msg {
    unsigned long line;
    long field;               /* 0-based field of the row, or -1 */
    char text[PLAN_MSG_TEXT];
} plan_msg;

/* What a batch's rows are read under: the header's map and the options.
 * plan_rules_init, then plan_header once. */
typedef struct plan_rules {
    long col[PLAN_C_COUNT];       /* field index of each known column, -1 if absent */
    size_t header_fields;
    const oi_camera *default_camera; /* rows without a camera column, or with it empty */
    const plan_shapes *shapes;       /* --shapes, or NULL: the built-in shapes only */
    const plan_albedo_map *albedo_map; /* --albedo-map, or NULL */
    oi_scene scene_defaults;      /* oi_scene_defaults, formed once: each row starts from it */
    char last_camera_name[64];    /* the camera column's last text and its camera */
    const oi_camera *last_camera;
} plan_rules;

/* A row's state besides its numbers (which stay in its oi_illum and
 * oi_exposure): what out_csv_text prints. */
typedef struct plan_row_state {
    int status;               /* library status (or 0 with PLAN_STATUS_PARSE) */
    const char *status_name;  /* printed status */
    int has_numbers;          /* 0: the row failed, numbers are left empty */
    int has_observer;         /* 0: flux_obs .. snr are left empty */
    unsigned flags;           /* OI_FLAG_* */
} plan_row_state;

void plan_rules_init(plan_rules *rules, const oi_camera *default_camera,
                     const plan_shapes *shapes, const plan_albedo_map *albedo_map);

/* Bytes plan_header's notes need for a header of n fields. */
#define PLAN_HEADER_NOTES(n) ((n) * 128u + 2048u)

/* The line oi-plan prints after plan_header's notes when it returns -2. */
extern const char plan_header_hint[];

/* The header record r maps the columns (matched by name, any case, any
 * order). Returns 0; -1 when the input is unusable (a column twice); -2
 * when it is for a required column missing or a group of columns
 * incomplete (then plan_header_hint follows the notes). notes (note_size
 * bytes, PLAN_HEADER_NOTES(fields) hold them all) receives the lines to
 * print (unknown columns ignored, then the problems), each ended by '\n',
 * each to be printed after "oi-plan: PATH: ". */
int plan_header(plan_rules *rules, const csv_reader *r, char *notes, size_t note_size);

/* Whether record r has more fields than the header (oi-plan notes it once;
 * the extra fields are ignored). */
static inline int plan_row_extra(const plan_rules *rules, const csv_reader *r)
{
    return csv_nfields(r) > rules->header_fields;
}

/* The id of record r, the rows-th after the header, read with csv_next's
 * result st: its id field ("" when the row is short or could not be read),
 * or, without an id column, rows in decimal (written at idbuf, 32 bytes). */
const char *plan_row_id(const plan_rules *rules, const csv_reader *r, int st, unsigned long rows,
                        char *idbuf);

/* The message of a record csv_next could not read (st, neither CSV_END,
 * CSV_IO nor CSV_NOMEM): the row is then PLAN_STATUS_PARSE. */
void plan_csv_error(const csv_reader *r, int st, plan_msg *msg);

/* Record r (the header's columns) into *sc, *model, *goal, *camera: returns
 * 1 when the row is to be computed, 0 when it failed (row then holds its
 * status; msg, when msg->line is nonzero, the message to print). */
int plan_row_read(plan_rules *rules, const csv_reader *r, oi_scene *sc, oi_model *model,
                  oi_expose_goal *goal, const oi_camera **camera, plan_row_state *row,
                  plan_msg *msg);

/* A parsed row (scene sc, read at line) once its illumination (status st)
 * and, with an observer, its exposure (status st2) are computed: *row gets
 * its status, flags, and which numbers it prints. Returns 1 when the row is
 * OK (or a warning), 0 when it is an error (msg then holds its message). */
int plan_row_finish(const oi_scene *sc, const oi_illum *illum, int st, const oi_exposure *expo,
                    int st2, unsigned long line, plan_row_state *row, plan_msg *msg);

#endif
