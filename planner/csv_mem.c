/* SPDX-License-Identifier: MIT */
/*
 * csv_mem.c: the CSV reader (csv_read.c, the same parsing code) over a text
 * in memory, for a caller without stdio or allocation (the viewer's
 * WebAssembly module). The whole text is the reader's one input block (no
 * FILE: csv_read.c's refill then reports its end), and the record buffers
 * are the caller's, sized so that the reader never grows them: the record
 * text buffer holds the longest record the text can have, or exactly the
 * reader's limit (CSV_MAX_RECORD + 16 bytes, where csv_read.c stops growing
 * and rejects the record) for a longer text; a record of n bytes has at most
 * n + 1 fields.
 */
#include "csv_read.h"

#include <string.h>

void csv_init_mem(csv_reader *r, const char *text, size_t len, char *buf, size_t *start)
{
    csv_init(r, NULL);
    /* the reader only reads its block (quick_split16 up to 15 bytes past a
     * line's end: CSV_MEM_SLACK) */
    r->in = (unsigned char *)text;
    r->in_len = len;
    r->in_pos = 0;
    r->buf = buf;
    r->cap = CSV_MEM_BUF_BYTES(len);
    r->start = start;
    r->fcap = CSV_MEM_STARTS(len);
}
