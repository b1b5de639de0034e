/* SPDX-License-Identifier: MIT */
/*
 * csv_read.h: a streaming CSV record reader (RFC 4180 and the usual
 * deviations): comma separator, fields optionally in double quotes with ""
 * for a quote and line breaks allowed inside quotes, LF, CRLF or CR line
 * ends, a UTF-8 byte-order mark skipped, empty or blank lines skipped,
 * spaces and tabs around unquoted fields trimmed. A record longer than
 * CSV_MAX_RECORD bytes is rejected (and skipped) instead of exhausting
 * memory.
 */
#ifndef OI_PLAN_CSV_READ_H
#define OI_PLAN_CSV_READ_H

#include <stddef.h>
#include <stdio.h>

#define CSV_MAX_RECORD (1u << 20) /* bytes per record */
#define CSV_READ_BLOCK (1u << 16) /* bytes per fread: the input is read in blocks */
#define CSV_PAD 8u                /* zero bytes after a record's text, for word-wide reads */

enum csv_result {
    CSV_RECORD = 0,   /* a record was read */
    CSV_END = 1,      /* end of input, no record */
    CSV_TOO_LONG = 2, /* record longer than CSV_MAX_RECORD: skipped to its line end */
    CSV_BAD_QUOTE = 3,/* text after a closing quote, or a quote never closed */
    CSV_BAD_BYTE = 4, /* a NUL byte in the record */
    CSV_IO = 5,       /* read error */
    CSV_NOMEM = 6     /* out of memory */
};

typedef struct csv_reader {
    FILE *fp;
    unsigned long line;       /* physical line of the next byte (1-based) */
    unsigned long col;        /* column (byte in line, 1-based) of the next byte */
    unsigned long rec_line;   /* line where the last record started */
    unsigned long err_line;   /* where the last error was found */
    unsigned long err_col;
    char *buf;                /* field text, each NUL-terminated */
    size_t len, cap;
    size_t pad;               /* zero bytes at buf + len (CSV_PAD, or 0 without room) */
    size_t *start;            /* offset of each field in buf */
    size_t nfields, fcap;
    int started;              /* BOM check done */
    unsigned char *in;        /* the block read (malloc'd on first use) */
    size_t in_pos, in_len;
    int in_nomem;             /* the block could not be allocated: a read error */
    int byte_by_byte;         /* 1: no whole-line copies (tests compare both ways) */
} csv_reader;

void csv_init(csv_reader *r, FILE *fp);
void csv_free(csv_reader *r);
/* The reader over a text in memory, without stdio or allocation
 * (csv_mem.c): text[0..len) followed by CSV_MEM_SLACK readable bytes; the
 * records' text in buf (CSV_MEM_BUF_BYTES(len) bytes) and their field
 * offsets in start (CSV_MEM_STARTS(len) entries), both the caller's. The
 * same records as csv_init on a file of that text; no csv_free. */
#define CSV_MEM_SLACK 16u
#define CSV_MEM_BUF_BYTES(len) (((len) < CSV_MAX_RECORD ? (len) : CSV_MAX_RECORD) + 16u)
#define CSV_MEM_STARTS(len) CSV_MEM_BUF_BYTES(len)
void csv_init_mem(csv_reader *r, const char *text, size_t len, char *buf, size_t *start);
/* Read the next non-blank record; returns an enum csv_result. */
int csv_next(csv_reader *r);
/* (inline: called a few times per field) */
static inline size_t csv_nfields(const csv_reader *r)
{
    return r->nfields;
}
/* Field i of the last record (NUL-terminated), or NULL past the end. */
static inline const char *csv_field(const csv_reader *r, size_t i)
{
    return i < r->nfields ? r->buf + r->start[i] : NULL;
}
/* Bytes readable from field i of the last record to the end of the record's
 * text and its zero padding (its NUL, the fields after it, pad bytes; 0 past
 * the end): what num_parse_n may read. */
static inline size_t csv_field_avail(const csv_reader *r, size_t i)
{
    return i < r->nfields ? r->len + r->pad - r->start[i] : 0;
}
/* The end of what csv_field_avail counts (the record's text and padding). */
static inline const char *csv_record_end(const csv_reader *r)
{
    return r->buf + r->len + r->pad;
}
/* Human-readable text of a csv_result. */
const char *csv_result_text(int result);

#endif
