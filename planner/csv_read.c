/* SPDX-License-Identifier: MIT */
/* csv_read.c: the streaming CSV record reader (see csv_read.h). */
#include "csv_read.h"

#include <stdlib.h>
#include <string.h>

/* SSE2 (every x86-64; GCC and Clang): the common record split sixteen
 * bytes at a time (quick_split16); elsewhere with memchr. */
#if defined(__SSE2__) && (defined(__GNUC__) || defined(__clang__))
#define CSV_SSE2 1
#include <emmintrin.h>
#endif

/* Bytes past the block that quick_split16 may load (zeros, never used). */
#define CSV_BLOCK_SLACK 16u

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
    free(r->in);
    r->buf = NULL;
    r->start = NULL;
    r->in = NULL;
    r->in_pos = r->in_len = 0;
    r->cap = r->fcap = 0;
}

/* The next block of input; 0 at its end, on a read error (ferror tells)
 * or when the block cannot be allocated (then read as a read error). */
static int refill(csv_reader *r)
{
    if (r->fp == NULL) return 0; /* a text in memory (csv_init_mem): its end */
    if (r->in == NULL) {
        r->in = (unsigned char *)calloc(CSV_READ_BLOCK + CSV_BLOCK_SLACK, 1);
        if (r->in == NULL) {
            r->in_nomem = 1;
            return 0;
        }
    }
    r->in_pos = 0;
    r->in_len = fread(r->in, 1, CSV_READ_BLOCK, r->fp);
    return r->in_len > 0;
}

/* The next byte of input as getc gives it, from the block (one fread per
 * CSV_READ_BLOCK bytes instead of a locked getc per byte). */
static int next_byte(csv_reader *r)
{
    if (r->in_pos == r->in_len && !refill(r)) return EOF;
    return r->in[r->in_pos++];
}

/* Give back the byte next_byte just returned (it is still in the block). */
static void unget_byte(csv_reader *r)
{
    r->in_pos--;
}

/* A read error, or no memory for the block. */
static int read_failed(const csv_reader *r)
{
    return (r->fp != NULL && ferror(r->fp)) || r->in_nomem;
}

/* Next byte with line ends normalised: LF, CRLF and CR all read as '\n'. */
static int get(csv_reader *r)
{
    int c = next_byte(r);
    if (c == EOF) return END_OF_INPUT;
    if (c == '\r') {
        int d = next_byte(r);
        if (d != '\n' && d != EOF) unget_byte(r);
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
    if (r->len < r->cap) { /* the common case: room in the record buffer */
        r->buf[r->len++] = c;
        return CSV_RECORD;
    }
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

/* The run of plain bytes (none of , LF CR NUL) that follows in the block,
 * appended to the record when the record buffer holds it without growing:
 * what put would do byte by byte, in one copy. Returns 1 if copied. */
static int plain_run(csv_reader *r)
{
    const unsigned char *p = r->in;
    size_t i = r->in_pos, k;
    if (p == NULL) return 0;
    while (i < r->in_len && p[i] != ',' && p[i] != '\n' && p[i] != '\r' && p[i] != 0) i++;
    k = i - r->in_pos;
    if (k == 0 || r->len + k > r->cap) return 0;
    memcpy(r->buf + r->len, p + r->in_pos, k);
    r->len += k;
    r->col += k;
    r->in_pos = i;
    return 1;
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
        if (read_failed(r)) return CSV_IO;
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
                    return read_failed(r) ? CSV_IO : CSV_BAD_QUOTE;
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
                (void)plain_run(r);
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
    if (c == END_OF_INPUT && read_failed(r)) return CSV_IO;
    if (bad_byte) return CSV_BAD_BYTE;
    *blank = !content;
    return CSV_RECORD;
}

/* Room for n bytes of record text and nf field starts; 0 if the record
 * buffer would pass its limit or memory is short (the caller then reads the
 * record byte by byte, which reports either). */
static int reserve(csv_reader *r, size_t n, size_t nf)
{
    if (n > r->cap) {
        size_t cap = r->cap ? 2 * r->cap : 256;
        char *p;
        while (cap < n) cap *= 2;
        if (cap > CSV_MAX_RECORD + 16) cap = CSV_MAX_RECORD + 16;
        if (n > cap) return 0;
        p = (char *)realloc(r->buf, cap);
        if (p == NULL) return 0;
        r->buf = p;
        r->cap = cap;
    }
    if (nf > r->fcap) {
        size_t cap = r->fcap ? 2 * r->fcap : 32;
        size_t *p;
        while (cap < nf) cap *= 2;
        p = (size_t *)realloc(r->start, cap * sizeof *p);
        if (p == NULL) return 0;
        r->start = p;
        r->fcap = cap;
    }
    return 1;
}

static int is_blank(char c)
{
    return c == ' ' || c == '\t';
}

/* quick_record's field buf[a..z) (z at its comma or the line's end) trimmed
 * of blanks, NUL-terminated in place and recorded as field *nf; *content set
 * when it holds something. 0 when the field index cannot grow. */
static int quick_field(csv_reader *r, size_t a, size_t z, size_t *nf, int *content)
{
    /* blanks: none in the planner's rows (one compare a side) */
    if ((unsigned char)r->buf[a] <= ' ')
        while (a < z && is_blank(r->buf[a])) a++;
    if (z > a && (unsigned char)r->buf[z - 1] <= ' ')
        while (z > a && is_blank(r->buf[z - 1])) z--;
    if (z > a) *content = 1;
    r->buf[z] = '\0';
    if (*nf == r->fcap && !reserve(r, 0, *nf + 1)) return 0;
    r->start[(*nf)++] = a;
    return 1;
}

/* quick_record's line of len bytes and nf fields taken: the record. */
static int quick_done(csv_reader *r, size_t nf, size_t len, int content, int *blank)
{
    r->nfields = nf;
    r->len = len + 1;
    r->rec_line = r->line;
    r->in_pos += len + 1;
    r->line++;
    r->col = 1;
    *blank = !content;
    return CSV_RECORD;
}

#ifdef CSV_SSE2
/* quick_record's split of the line p[0..len) (p[len] the LF, in the block)
 * sixteen bytes at a time: each chunk copied, its commas and its quotes, CRs
 * and NULs found by compares (the loads reach at most 15 bytes past the LF:
 * the block has CSV_BLOCK_SLACK bytes more), the fields cut at the commas
 * and trimmed as quick_record does. Returns -1 (nothing consumed) for a line
 * with a quote, CR or NUL. */
static int quick_split16(csv_reader *r, const unsigned char *p, size_t len, int *blank)
{
    const __m128i comma = _mm_set1_epi8(','), quote = _mm_set1_epi8('"');
    const __m128i cr = _mm_set1_epi8('\r'), zero = _mm_setzero_si128();
    size_t i, a = 0, nf = 0;
    int content = 0;
    if (!reserve(r, len + 16, r->fcap > 0 ? r->fcap : 32)) return -1;
    for (i = 0;; i += 16) {
        const __m128i v = _mm_loadu_si128((const __m128i *)(const void *)(p + i));
        unsigned cm = (unsigned)_mm_movemask_epi8(_mm_cmpeq_epi8(v, comma));
        unsigned bad = (unsigned)_mm_movemask_epi8(
            _mm_or_si128(_mm_or_si128(_mm_cmpeq_epi8(v, quote), _mm_cmpeq_epi8(v, cr)),
                         _mm_cmpeq_epi8(v, zero)));
        _mm_storeu_si128((__m128i *)(void *)(r->buf + i), v);
        if (len - i < 16) { /* the last chunk: the line's end closes the last field */
            const unsigned end_bit = 1u << (len - i);
            bad &= end_bit - 1u;
            cm = (cm & (end_bit - 1u)) | end_bit;
        }
        if (bad != 0u) return -1;
        while (cm != 0u) {
            const size_t e = i + (size_t)__builtin_ctz(cm);
            cm &= cm - 1u;
            if (!quick_field(r, a, e, &nf, &content)) return -1;
            if (e == len) return quick_done(r, nf, len, content, blank);
            content = 1; /* a separator makes the record not blank */
            a = e + 1;
        }
    }
}
#endif

/* The common record at once: a whole line in the block, ended by LF, with
 * no quote, CR or NUL. Copied in one piece, split at its commas, each field
 * trimmed of blanks and NUL-terminated in place: the fields read_record
 * gives, without its per-byte steps. Returns -1 when the line is not such a
 * one (nothing consumed: read_record takes it). */
static int quick_record(csv_reader *r, int *blank)
{
    const unsigned char *p;
    const unsigned char *nl;
    size_t len;
    if (r->byte_by_byte || r->in == NULL || r->in_pos >= r->in_len) return -1;
    p = r->in + r->in_pos;
    nl = (const unsigned char *)memchr(p, '\n', r->in_len - r->in_pos);
    if (nl == NULL) return -1;
    len = (size_t)(nl - p);
#ifdef CSV_SSE2
    return quick_split16(r, p, len, blank);
#else
    {
    size_t q, nf = 0;
    int content = 0;
    if (memchr(p, '"', len) != NULL || memchr(p, '\r', len) != NULL ||
        memchr(p, '\0', len) != NULL)
        return -1;
    if (!reserve(r, len + 1, r->fcap > 0 ? r->fcap : 32)) return -1;
    memcpy(r->buf, p, len);
    r->buf[len] = ','; /* a sentinel: every search below finds a comma */
    for (q = 0;;) {
        const size_t e = (size_t)((char *)memchr(r->buf + q, ',', len + 1 - q) - r->buf);
        if (!quick_field(r, q, e, &nf, &content)) return -1;
        if (e == len) return quick_done(r, nf, len, content, blank);
        content = 1; /* a separator makes the record not blank */
        q = e + 1;
    }
    }
#endif
}

int csv_next(csv_reader *r)
{
    int st, blank;
    if (!r->started) {
        /* UTF-8 byte-order mark (spreadsheet exports) */
        int c0 = next_byte(r);
        r->started = 1;
        if (c0 == 0xEF) {
            int c1 = next_byte(r);
            int c2 = c1 == 0xBB ? next_byte(r) : EOF;
            if (!(c1 == 0xBB && c2 == 0xBF)) {
                /* not a BOM: only one byte can be pushed back; reject */
                r->err_line = 1;
                r->err_col = 1;
                return CSV_BAD_BYTE;
            }
        } else if (c0 != EOF) {
            unget_byte(r);
        }
    }
    do {
        st = quick_record(r, &blank);
        if (st < 0) st = read_record(r, &blank);
    } while (st == CSV_RECORD && blank);
    /* zeros after the text: the number reader's 8-byte loads reach the last field's end */
    r->pad = 0;
    if (st == CSV_RECORD && (r->len + CSV_PAD <= r->cap || reserve(r, r->len + CSV_PAD, 0))) {
        memset(r->buf + r->len, 0, CSV_PAD);
        r->pad = CSV_PAD;
    }
    return st;
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
