/* SPDX-License-Identifier: MIT */
/* batch.c: the batch interface of the planner (see batch.h, docs/planner.md):
 * the input file, the blocks of rows and the library's batch calls on them,
 * the output and the messages on stderr. What a record means (the columns,
 * by name in any order, the row's errors, its status and flags) is the row
 * rules' (rows.c), which the viewer's wasm module runs too. A row that
 * cannot be parsed or computed gets its status and empty numbers; the batch
 * goes on. */
#define _POSIX_C_SOURCE 200809L /* isatty, fileno: progress only on a terminal */

#include "batch.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "csv_read.h"
#include "output.h"
#include "rows.h"
#include "shapes.h"
#include "windows.h"

typedef struct batch {
    plan_rules rules;         /* the header's map, the options (rows.h) */
    const char *path;
    int warned_extra;
    unsigned long messages;   /* row messages printed so far */
    unsigned long bad;        /* rows with errors */
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

typedef struct pending_row {
    plan_row_state state;     /* status when parsing failed; else filled by the flush */
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

/* Read the header and map it (plan_header); returns 0 or PLAN_EXIT_INPUT
 * after printing why. */
static int read_header(batch *b, csv_reader *r)
{
    int st = csv_next(r);
    char *notes;
    const char *p, *e;
    size_t size;
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
    size = PLAN_HEADER_NOTES(csv_nfields(r));
    notes = malloc(size);
    if (notes == NULL) {
        fprintf(stderr, "oi-plan: out of memory\n");
        return PLAN_EXIT_INPUT;
    }
    st = plan_header(&b->rules, r, notes, size);
    for (p = notes; *p != '\0'; p = e + 1) { /* each line after "oi-plan: PATH: " */
        e = strchr(p, '\n');
        fprintf(stderr, "oi-plan: %s: %.*s\n", b->path, (int)(e - p), p);
    }
    free(notes);
    if (st == -2) fputs(plan_header_hint, stderr);
    return st == 0 ? 0 : PLAN_EXIT_INPUT;
}

/* Report a row's message (the row rules', rows.h). */
static void row_msg(batch *b, const plan_msg *msg)
{
    if (msg->line != 0) row_error(b, msg->line, msg->field, msg->text, NULL);
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
    plan_msg msg;
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
        if (p->compute && !plan_row_finish(&q->scenes[i], &q->illum[i], q->status[i], &q->expo[i],
                                           q->expo_status[i], p->line, &p->state, &msg)) {
            row_msg(b, &msg);
            b->bad++;
        }
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
static void add_pending(batch *b, const char *id, size_t len, const plan_row_state *row,
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
    plan_rules_init(&b.rules, default_camera, shapes, albedo_map);
    b.out = out;
    b.wins = &wins;
    b.summary = summary;
    b.path = strcmp(path, "-") == 0 ? "<stdin>" : path;
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
        plan_row_state row;
        plan_msg msg;
        char idbuf[32];
        size_t len;
        const char *id;
        int compute;
        st = csv_next(&r);
        if (st == CSV_END) break;
        rows++;
        if (st == CSV_IO || st == CSV_NOMEM) {
            flush_pending(&b);
            fprintf(stderr, "oi-plan: %s: line %lu: %s\n", b.path, r.line, csv_result_text(st));
            result = PLAN_EXIT_INPUT;
            break;
        }
        id = plan_row_id(&b.rules, &r, st, rows, idbuf);
        if (st != CSV_RECORD) {
            plan_csv_error(&r, st, &msg);
            row_msg(&b, &msg);
            memset(&row, 0, sizeof row);
            row.status_name = PLAN_STATUS_PARSE;
            len = strlen(id) + 1;
            room_for_id(&b, len);
            add_pending(&b, id, len, &row, r.err_line, 0);
            continue;
        }
        len = strlen(id) + 1;
        room_for_id(&b, len);
        if (plan_row_extra(&b.rules, &r) && !b.warned_extra) {
            flush_pending(&b);
            fprintf(stderr, "oi-plan: %s: line %lu: note: row has more fields than the header; "
                            "extra fields ignored (reported once)\n", b.path, r.rec_line);
            b.warned_extra = 1;
        }
        {
            pending *q = b.pending; /* the block's next row, once a note has flushed it */
            compute = plan_row_read(&b.rules, &r, &q->scenes[q->n], &q->rows[q->n].model,
                                    &q->rows[q->n].goal, &q->rows[q->n].camera, &row, &msg);
        }
        if (!compute) row_msg(&b, &msg);
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
