/* SPDX-License-Identifier: MIT */
/* csv_read.c: the streaming CSV record reader (see csv_read.h). */
#include "csv_read.h"

#include <stdlib.h>
#include <string.h>

/* Internal marker returned by get() for end of input. */
#define END_OF_INPUT (-1)

void csv_init(csv_reader *r, FILE *fp)
{
    memset(r, 0, sizeof *r);
    r->fp = fp;
    r->line = 1;
    r->col = 1;
}

void csv_free(csv_reader *r)
{
    free(r->buf);
    free(r->start);
    r->buf = NULL;
    r->start = NULL;
    r->cap = r->fcap = 0;
}

/* Next byte with line ends normalised: LF, CRLF and CR all read as '\n'. */
static int get(csv_reader *r)
{
    int c = getc(r->fp);
    if (c == EOF) return END_OF_INPUT;
    if (c == '\r') {
        int d = getc(r->fp);
        if (d != '\n' && d != EOF) ungetc(d, r->fp);
        c = '\n';
    }
    if (c == '\n') {
        r->line++;
        r->col = 1;
    } else {
        r->col++;
    }
    return c;
}

static int put(csv_reader *r, char c)
{
    if (r->len + 1 > r->cap) {
        size_t cap = r->cap ? 2 * r->cap : 256;
        char *p;
        if (cap > CSV_MAX_RECORD + 16) cap = CSV_MAX_RECORD + 16;
        if (r->len + 1 > cap) return CSV_TOO_LONG;
        p = (char *)realloc(r->buf, cap);
        if (p == NULL) return CSV_NOMEM;
        r->buf = p;
        r->cap = cap;
    }
    r->buf[r->len++] = c;
    return CSV_RECORD;
}

/* Close the current field: trim trailing blanks of unquoted text, add NUL. */
static int end_field(csv_reader *r, size_t field_start, size_t keep)
{
    int st;
    while (r->len > keep && r->len > field_start &&
           (r->buf[r->len - 1] == ' ' || r->buf[r->len - 1] == '\t')) {
        r->len--;
    }
    if ((st = put(r, '\0')) != CSV_RECORD) return st;
    if (r->nfields + 1 > r->fcap) {
        size_t cap = r->fcap ? 2 * r->fcap : 32;
        size_t *p = (size_t *)realloc(r->start, cap * sizeof *p);
        if (p == NULL) return CSV_NOMEM;
        r->start = p;
        r->fcap = cap;
    }
    r->start[r->nfields++] = field_start;
    return CSV_RECORD;
}

/* Skip to the end of the current physical line. */
static void skip_line(csv_reader *r)
{
    int c;
    do {
        c = get(r);
    } while (c != '\n' && c != END_OF_INPUT);
}

static void mark(csv_reader *r)
{
    r->err_line = r->line;
    r->err_col = r->col > 1 ? r->col - 1 : 1;
}

/* Read one record (possibly blank). *blank is set when it held nothing. */
static int read_record(csv_reader *r, int *blank)
{
    int c, st, content = 0, bad_byte = 0;
    size_t field_start, keep;

    r->len = 0;
    r->nfields = 0;
    r->rec_line = r->line;
    *blank = 0;
    c = get(r);
    if (c == END_OF_INPUT) {
        if (ferror(r->fp)) return CSV_IO;
        return CSV_END;
    }
    for (;;) {
        /* start of a field: leading blanks */
        field_start = r->len;
        keep = field_start;
        while (c == ' ' || c == '\t') c = get(r);
        if (c == '"') {
            content = 1;
            for (;;) {
                c = get(r);
                if (c == END_OF_INPUT) {
                    mark(r);
                    return ferror(r->fp) ? CSV_IO : CSV_BAD_QUOTE;
                }
                if (c == '"') {
                    c = get(r);
                    if (c != '"') break; /* closing quote */
                }
                if (c == '\0') {
                    if (!bad_byte) mark(r);
                    bad_byte = 1;
                }
                if ((st = put(r, (char)c)) != CSV_RECORD) {
                    mark(r);
                    if (st == CSV_TOO_LONG && c != '\n') skip_line(r);
                    return st;
                }
            }
            keep = r->len; /* quoted text keeps its blanks */
            while (c == ' ' || c == '\t') c = get(r);
            if (c != ',' && c != '\n' && c != END_OF_INPUT) {
                mark(r);
                skip_line(r);
                return CSV_BAD_QUOTE;
            }
        } else {
            while (c != ',' && c != '\n' && c != END_OF_INPUT) {
                content = 1;
                if (c == '\0') {
                    if (!bad_byte) mark(r);
                    bad_byte = 1;
                }
                if ((st = put(r, (char)c)) != CSV_RECORD) {
                    mark(r);
                    if (st == CSV_TOO_LONG) skip_line(r);
                    return st;
                }
                c = get(r);
            }
        }
        if ((st = end_field(r, field_start, keep)) != CSV_RECORD) {
            mark(r);
            if (st == CSV_TOO_LONG && c != '\n' && c != END_OF_INPUT) skip_line(r);
            return st;
        }
        if (c == ',') {
            content = 1;
            c = get(r);
            continue;
        }
        break; /* '\n' or end of input */
    }
    if (c == END_OF_INPUT && ferror(r->fp)) return CSV_IO;
    if (bad_byte) return CSV_BAD_BYTE;
    *blank = !content;
    return CSV_RECORD;
}

int csv_next(csv_reader *r)
{
    int st, blank;
    if (!r->started) {
        /* UTF-8 byte-order mark (spreadsheet exports) */
        int c0 = getc(r->fp);
        r->started = 1;
        if (c0 == 0xEF) {
            int c1 = getc(r->fp);
            int c2 = c1 == 0xBB ? getc(r->fp) : EOF;
            if (!(c1 == 0xBB && c2 == 0xBF)) {
                /* not a BOM: only one byte can be pushed back; reject */
                r->err_line = 1;
                r->err_col = 1;
                return CSV_BAD_BYTE;
            }
        } else if (c0 != EOF) {
            ungetc(c0, r->fp);
        }
    }
    do {
        st = read_record(r, &blank);
    } while (st == CSV_RECORD && blank);
    return st;
}

size_t csv_nfields(const csv_reader *r)
{
    return r->nfields;
}

const char *csv_field(const csv_reader *r, size_t i)
{
    return i < r->nfields ? r->buf + r->start[i] : NULL;
}

const char *csv_result_text(int result)
{
    switch (result) {
    case CSV_RECORD: return "record";
    case CSV_END: return "end of input";
    case CSV_TOO_LONG: return "record longer than 1 MiB (skipped)";
    case CSV_BAD_QUOTE: return "malformed quoted field (text after the closing quote, or a quote never closed)";
    case CSV_BAD_BYTE: return "NUL byte or invalid byte in the record";
    case CSV_IO: return "read error";
    case CSV_NOMEM: return "out of memory";
    default: return "unknown";
    }
}
