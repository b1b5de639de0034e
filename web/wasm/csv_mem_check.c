/* SPDX-License-Identifier: MIT */
/*
 * csv_mem_check.c: the planner's CSV reader over a text in memory
 * (csv_init_mem, what the wasm module's planCsv reads with) gives the
 * records, errors and positions that the same reader gives over a file of
 * that text (csv_init, what oi-plan reads with): random texts of the bytes
 * that matter (commas, blanks, quotes, CR, LF, NUL), texts across the file
 * reader's blocks and records past the reader's limit. The memory reader's
 * buffers are allocated at exactly the sizes csv_read.h names, so a run
 * under valgrind also checks that it stays inside them. Built natively and
 * run by `make test-wasm`; prints one line, exits 1 on a difference.
 */
#define _POSIX_C_SOURCE 200809L /* fmemopen */

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "csv_read.h"

static uint64_t rng = 0x9E3779B97F4A7C15ULL;

static uint64_t rand64(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return rng;
}

static long texts, records, differ;

/* Both readers over text[0..n): every result the same. */
static void check(const char *text, size_t n)
{
    FILE *fp = fmemopen((void *)(uintptr_t)text, n, "rb");
    char *copy = malloc(n + CSV_MEM_SLACK);
    char *buf = malloc(CSV_MEM_BUF_BYTES(n));
    size_t *start = malloc(CSV_MEM_STARTS(n) * sizeof *start);
    csv_reader a, b;
    long rec;
    if (copy == NULL || buf == NULL || start == NULL || (n > 0 && fp == NULL)) {
        fprintf(stderr, "csv_mem_check: out of memory\n");
        exit(2);
    }
    memcpy(copy, text, n);
    memset(copy + n, 0, CSV_MEM_SLACK);
    texts++;
    if (fp == NULL) fp = fopen("/dev/null", "rb"); /* fmemopen of 0 bytes */
    csv_init(&a, fp);
    csv_init_mem(&b, copy, n, buf, start);
    for (rec = 0;; rec++) {
        int sa = csv_next(&a), sb = csv_next(&b);
        size_t i;
        int same = sa == sb && a.line == b.line && a.col == b.col;
        if (same && sa == CSV_RECORD) {
            same = a.nfields == b.nfields && a.rec_line == b.rec_line;
            for (i = 0; same && i < a.nfields; i++)
                same = strcmp(csv_field(&a, i), csv_field(&b, i)) == 0;
            records++;
        } else if (same && sa != CSV_END) {
            same = a.err_line == b.err_line && a.err_col == b.err_col;
        }
        if (!same) {
            if (differ++ < 5)
                fprintf(stderr, "csv_mem_check: record %ld differs (status %d / %d, line %lu / %lu)"
                                " in \"%.60s\"\n", rec, sa, sb, a.line, b.line, text);
            break;
        }
        if (sa == CSV_END || sa == CSV_IO || sa == CSV_NOMEM) break;
    }
    csv_free(&a);
    fclose(fp);
    free(copy);
    free(buf);
    free(start);
}

int main(void)
{
    static const char alphabet[] = "0123456789.e-,,,,   \t\n\n\n\"\r\0ab";
    static const char *const hand[] = {
        "a,b,c\n1,2,3\n", "a,b\n\n\n1,2\n", "  a ,\tb\t,c  \n", ",\n,,\n , \n", "x\r\ny\rz\n",
        "\"q,1\",2\n3,\"a\"\"b\"\n", "1,\"open\n", "1,\"x\" y,3\n4,5\n",
        "\xEF\xBB\xBF" "a,b\n1,2\n", "\xEF\xBB" "a\n", "", "\n", "a", "1,2\n3,4\n5,6"};
    char text[400];
    size_t i, n;
    long k;
    char *big;
    for (i = 0; i < sizeof hand / sizeof hand[0]; i++) check(hand[i], strlen(hand[i]));
    for (k = 0; k < 50000; k++) {
        int rare = (int)(rand64() % 4u);
        n = (size_t)(rand64() % sizeof text);
        for (i = 0; i < n; i++) {
            uint64_t u = rand64();
            text[i] = rare == 0 || (u & 7u) == 0 ? alphabet[(u >> 3) % (sizeof alphabet - 1)]
                                                 : alphabet[(u >> 3) % 27u];
        }
        check(text, n);
    }
    /* planner-like rows over several of the file reader's blocks, and a
     * record past the limit (short fields) between two rows */
    n = 3u * CSV_MAX_RECORD;
    big = malloc(n);
    if (big == NULL) return 2;
    for (i = 0; i + 64 < n / 2; i += 32)
        memcpy(big + i, "1.5e8,-7000.25, 3 ,\"x,y\",\t4\r\n   ", 32); /* 32 bytes, no NUL */
    for (; i + 2 < n - 64; i += 2) memcpy(big + i, "y,", 2);
    memcpy(big + i, "\n1,2,3\n", 7);
    check(big, i + 7);
    check(big, CSV_READ_BLOCK * 3 + 17);
    free(big);
    printf("csv_mem_check: %ld texts, %ld records: %s\n", texts, records,
           differ == 0 ? "the memory reader's are the file reader's" : "DIFFERENT");
    return differ == 0 ? 0 : 1;
}
