/* SPDX-License-Identifier: MIT */
/*
 * plan_wasm.c: the planner's batch rules in the WebAssembly module, for
 * web/src/orbillum.js's planCsv: the planner's own CSV reader
 * (planner/csv_read.c over the text in memory, planner/csv_mem.c), its row
 * rules (planner/rows.c: the header's columns, each record into a scene,
 * model, goal and camera, the row's errors, its status and flags) and the
 * text oi-plan --csv prints for the row (planner/output_text.c). The
 * JavaScript writes the text in and reads each row's fields and numbers
 * out. Each row is computed with the single calls (oi_illuminate, then
 * oi_expose_scene with the row's goal), which give the planner's batch
 * calls' numbers bit for bit, with every output for drawing the row.
 *
 * No allocation: the text and the reader's buffers lie in memory past the
 * module's heap base (nothing else uses it: the runtime allocates nothing),
 * grown with memory.grow to fit the text; the row lives in static storage.
 */
#include <stddef.h>
#include <string.h>

#include "csv_read.h"
#include "orbillum.h"
#include "output.h"
#include "rows.h"

/* The linker's end of static data: the first byte no one uses. */
extern unsigned char __heap_base;

#define WASM_PAGE 65536u

static csv_reader reader;
static plan_rules rules;
static char *text;          /* the input (past the heap base) */
static size_t text_len;
static unsigned long rows;  /* records read after the header */
static char notes[PLAN_HEADER_NOTES(64u)];

/* The last row read (oi_plan_wasm_next) or finished (oi_plan_wasm_finish). */
static struct {
    int compute;            /* 1: parsed and computed */
    int status, expo_status;
    plan_row_state state;
    plan_msg msg;
    oi_scene scene;
    oi_model model;
    oi_expose_goal goal;
    const oi_camera *camera;
    oi_illum illum;
    oi_exposure expo;
    char idbuf[32];
    const char *id;
    char numbers[OUT_CSV_LINE_MAX];
} row;

char *oi_plan_wasm_text(unsigned len);
int oi_plan_wasm_records(unsigned len);
int oi_plan_wasm_record(void);
unsigned oi_plan_wasm_nfields(void);
const char *oi_plan_wasm_field(unsigned i);
int oi_plan_wasm_open(unsigned len, const oi_camera *default_camera);
const char *oi_plan_wasm_notes(void);
int oi_plan_wasm_next(void);
int oi_plan_wasm_finish(const oi_scene *sc, const oi_illum *illum, int st,
                        const oi_exposure *expo, int st2);
int oi_plan_wasm_row_int(unsigned what);
const void *oi_plan_wasm_row_ptr(unsigned what);
const char *oi_plan_wasm_csv_header(void);

/* Room for a text of len bytes and the reader's buffers past the heap base,
 * the memory grown to hold them: the text's address (the caller writes it
 * there), or NULL when the memory cannot grow. */
char *oi_plan_wasm_text(unsigned len)
{
    const size_t base = ((size_t)&__heap_base + 15u) & ~(size_t)15u;
    const size_t need = base + len + CSV_MEM_SLACK + CSV_MEM_BUF_BYTES(len) + 16u +
                        CSV_MEM_STARTS(len) * sizeof(size_t);
    const size_t have = __builtin_wasm_memory_size(0) * WASM_PAGE;
    if (need > have &&
        __builtin_wasm_memory_grow(0, (need - have + WASM_PAGE - 1u) / WASM_PAGE) == (size_t)-1)
        return NULL;
    text = (char *)base;
    text_len = len;
    return text;
}

/* The reader over the text (oi_plan_wasm_text's, len bytes written). */
static void open_reader(unsigned len)
{
    char *buf = text + len + CSV_MEM_SLACK;
    size_t *start = (size_t *)(((size_t)(buf + CSV_MEM_BUF_BYTES(len)) + 15u) & ~(size_t)15u);
    memset(text + len, 0, CSV_MEM_SLACK);
    text_len = len;
    csv_init_mem(&reader, text, len, buf, start);
    rows = 0;
}

/* The text as plain CSV records (the planner's reader): oi_plan_wasm_record
 * then gives each. Returns 0. */
int oi_plan_wasm_records(unsigned len)
{
    open_reader(len);
    return 0;
}

/* The next record: an enum csv_result (CSV_RECORD: its fields are those of
 * oi_plan_wasm_nfields and oi_plan_wasm_field). */
int oi_plan_wasm_record(void)
{
    return csv_next(&reader);
}

unsigned oi_plan_wasm_nfields(void) { return (unsigned)csv_nfields(&reader); }

const char *oi_plan_wasm_field(unsigned i) { return csv_field(&reader, i); }

/* The batch over the text: its header read and mapped (plan_header), rows
 * without a camera column on default_camera. Returns 0; a csv_result
 * (CSV_END: no header; the line and character in oi_plan_wasm_row_int 8 and
 * 9) when the header cannot be read; -1 or -2 (plan_header's) when it is
 * unusable, oi_plan_wasm_notes saying why. */
int oi_plan_wasm_open(unsigned len, const oi_camera *default_camera)
{
    int st;
    open_reader(len);
    plan_rules_init(&rules, default_camera, NULL, NULL);
    notes[0] = '\0';
    st = csv_next(&reader);
    if (st != CSV_RECORD) return st;
    return plan_header(&rules, &reader, notes, sizeof notes);
}

/* The header's notes (each line ended by '\n'; the first 64 fields'). */
const char *oi_plan_wasm_notes(void) { return notes; }

/* Form the row's CSV numbers and flags text (what oi-plan prints after the
 * status). */
static void format_row(void)
{
    const int num = row.state.has_numbers;
    const size_t n = out_csv_numbers(row.numbers, num, num && row.state.has_observer,
                                     row.state.flags, &row.illum, &row.expo);
    row.numbers[n] = '\0';
}

/* The next row, as oi-plan's batch reads, computes and prints it: 1, or 0
 * at the end of the text (or on a read error, which a text in memory does
 * not have). */
int oi_plan_wasm_next(void)
{
    int st = csv_next(&reader);
    memset(&row.illum, 0, sizeof row.illum);
    memset(&row.expo, 0, sizeof row.expo);
    row.compute = 0;
    row.status = row.expo_status = 0;
    row.camera = NULL;
    if (st == CSV_END || st == CSV_IO || st == CSV_NOMEM) return 0;
    rows++;
    row.id = plan_row_id(&rules, &reader, st, rows, row.idbuf);
    if (st != CSV_RECORD) { /* the record could not be read: ERR_PARSE */
        memset(&row.state, 0, sizeof row.state);
        row.state.status_name = PLAN_STATUS_PARSE;
        plan_csv_error(&reader, st, &row.msg);
    } else if (plan_row_read(&rules, &reader, &row.scene, &row.model, &row.goal, &row.camera,
                             &row.state, &row.msg)) {
        row.compute = 1;
        row.status = oi_illuminate(&row.scene, &row.model, &row.illum);
        if (row.status >= 0 && row.scene.has_observer)
            row.expo_status = oi_expose_scene(row.camera, &row.scene, &row.illum, &row.model,
                                              &row.goal, &row.expo);
        (void)plan_row_finish(&row.scene, &row.illum, row.status, &row.expo, row.expo_status,
                              reader.rec_line, &row.state, &row.msg);
    }
    format_row();
    return 1;
}

/* A row the caller computed (the viewer's controls): its status, flags and
 * numbers as the planner gives them (plan_row_finish), in the row that
 * oi_plan_wasm_row_int and _ptr read. Returns plan_row_finish's value. */
int oi_plan_wasm_finish(const oi_scene *sc, const oi_illum *illum, int st,
                        const oi_exposure *expo, int st2)
{
    int ok;
    row.illum = *illum;
    row.expo = *expo;
    ok = plan_row_finish(sc, &row.illum, st, &row.expo, st2, 0, &row.state, &row.msg);
    format_row();
    return ok;
}

/* The row's integers: 0 computed (1) or not, 1 illumination status, 2
 * exposure status, 3 status (library, or 0 for ERR_PARSE), 4 flags, 5 the
 * message's line (0: none), 6 its field (-1: none), 7 the record's line, 8
 * and 9 the line and character of the reader's last error (a header that
 * could not be read). */
int oi_plan_wasm_row_int(unsigned what)
{
    switch (what) {
    case 0: return row.compute;
    case 1: return row.status;
    case 2: return row.expo_status;
    case 3: return row.state.status;
    case 4: return (int)row.state.flags;
    case 5: return (int)row.msg.line;
    case 6: return (int)row.msg.field;
    case 7: return (int)reader.rec_line;
    case 8: return (int)reader.err_line;
    case 9: return (int)reader.err_col;
    case 10: return row.state.has_numbers;
    default: return 0;
    }
}

/* The row's texts and structs: 0 id, 1 status name, 2 numbers text (from
 * the first number's comma to the newline), 3 message text, 4 scene, 5
 * model, 6 goal, 7 camera, 8 illumination, 9 exposure. */
const void *oi_plan_wasm_row_ptr(unsigned what)
{
    switch (what) {
    case 0: return row.id;
    case 1: return row.state.status_name;
    case 2: return row.numbers;
    case 3: return row.msg.line != 0 ? row.msg.text : "";
    case 4: return &row.scene;
    case 5: return &row.model;
    case 6: return &row.goal;
    case 7: return row.camera;
    case 8: return &row.illum;
    case 9: return &row.expo;
    default: return NULL;
    }
}

/* The planner's output header (plan_csv_header). */
const char *oi_plan_wasm_csv_header(void) { return plan_csv_header; }
