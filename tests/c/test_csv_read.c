/* SPDX-License-Identifier: MIT */
/* test_csv_read.c: the planner's CSV reader (planner/csv_read.c):
 * its whole-line path gives, record for record, what its byte-by-byte path
 * and its reader over a text in memory give (status, fields, line numbers,
 * error positions) on random texts of
 * the bytes that matter (separators, blanks, quotes, CR, LF, NUL), on texts
 * longer than one read block, and on hand-written cases; a record near the
 * record limit read in linear time; after a record too long or a bad quote
 * the next record read from its own start (never inside quotes); a
 * byte-order mark only at the input's start. */
#define _POSIX_C_SOURCE 200809L /* fmemopen */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../../planner/csv_read.c"
#include "../../planner/csv_mem.c"

static uint64_t rng_state = 0x2545F4914F6CDD1DULL;

static uint64_t rand64(void)
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return rng_state ^ (rng_state >> 29);
}

static long failures = 0;

/* 1 when two readers' last results are the same: status, position, and
 * the record's fields or the error's position. */
static int same_result(const csv_reader *a, int sa, const csv_reader *b, int sb)
{
    size_t i;
    int same = sa == sb && a->line == b->line && a->col == b->col;
    if (same && sa == CSV_RECORD) {
        same = a->nfields == b->nfields && a->rec_line == b->rec_line;
        for (i = 0; same && i < a->nfields; i++)
            same = strcmp(csv_field(a, i), csv_field(b, i)) == 0;
    } else if (same && sa != CSV_END) {
        same = a->err_line == b->err_line && a->err_col == b->err_col;
    }
    return same;
}

/* Three ways over the same bytes, every record the same: over a file by
 * whole lines (oi-plan's), byte by byte, and over the text in memory
 * (csv_init_mem, the viewer's module), its buffers at exactly the sizes
 * csv_read.h names (so the sanitizers check that it stays inside them). */
static void check_same(const char *text, size_t n)
{
    FILE *fa = fmemopen((void *)text, n, "rb"), *fb = fmemopen((void *)text, n, "rb");
    char *copy = malloc(n + CSV_MEM_SLACK);
    char *buf = malloc(CSV_MEM_BUF_BYTES(n));
    size_t *start = malloc(CSV_MEM_STARTS(n) * sizeof *start);
    csv_reader a, b, c;
    long rec;
    assert_non_null(fa);
    assert_non_null(fb);
    assert_non_null(copy);
    assert_non_null(buf);
    assert_non_null(start);
    memcpy(copy, text, n);
    memset(copy + n, 0, CSV_MEM_SLACK);
    csv_init(&a, fa);
    csv_init(&b, fb);
    b.byte_by_byte = 1;
    csv_init_mem(&c, copy, n, buf, start);
    for (rec = 0; rec < 100000; rec++) {
        int sa = csv_next(&a), sb = csv_next(&b), sc = csv_next(&c);
        const int same_b = same_result(&a, sa, &b, sb), same_c = same_result(&a, sa, &c, sc);
        if (!same_b || !same_c) {
            const csv_reader *o = same_b ? &c : &b;
            if (failures++ < 5)
                print_error("record %ld differs (%s: status %d / %d, line %lu / %lu, fields %lu / "
                            "%lu) in \"%.80s\"\n", rec, same_b ? "memory" : "byte by byte", sa,
                            same_b ? sc : sb, a.line, o->line, (unsigned long)a.nfields,
                            (unsigned long)o->nfields, text);
            break;
        }
        if (sa == CSV_END || sa == CSV_IO || sa == CSV_NOMEM) break;
    }
    csv_free(&a);
    csv_free(&b);
    fclose(fa);
    fclose(fb);
    free(copy);
    free(buf);
    free(start);
}

static void test_hand_written(void **state)
{
    static const char *const texts[] = {
        "a,b,c\n1,2,3\n",
        "a,b\n\n\n1,2\n",
        "  a ,\tb\t,c  \n",
        "a,b\n   \n\t\n1,2",
        ",\n,,\n , \n",
        "x\r\ny\rz\n",
        "\"q,1\",2\n3,\"a\"\"b\"\n",
        "1,\"open\n",
        "1,\"x\" y,3\n4,5\n",
        "\xEF\xBB\xBF" "a,b\n1,2\n",
        "\xEF\xBB" "a\n",
        "",
        "\n",
        "a",
        "1,2\n3,4\n5,6",
        "\xEF\xBB\xBF" "\xEF\xBB\xBF" "a,b\n1,2\n",
        "a,b\n1,2\n\xEF\xBB\xBF" "a,b\n3,4\n",
        "1,\"x\xEF\xBB\xBFy\"\n2,3\n",
        "1,x\xEF\xBB\xBF\n\xEF\xEF\xBB\xBF,\xEF\xBB\n",
        "\xEF\xBC\x8C,\xEF\xBB\xBE,\"\xEF\"\"\xBB\xBF\"\n",
        "\"x\"y,\"a\nb\",1\n3,4\n",
        "\"x\"y\"a\nb\",1\n3,4\n"};
    size_t i;
    (void)state;
    failures = 0;
    for (i = 0; i < sizeof texts / sizeof texts[0]; i++) check_same(texts[i], strlen(texts[i]));
    {
        static const char nul[] = "a,b\n1,\0,3\n4,5\n";
        check_same(nul, sizeof nul - 1);
    }
    assert_int_equal(failures, 0);
}

static void test_random_texts(void **state)
{
    static const char alphabet[] = "0123456789.e-,,,,   \t\n\n\n\"\r\0ab\xEF\xBB\xBF";
    char text[400];
    long k;
    (void)state;
    failures = 0;
    for (k = 0; k < 200000; k++) {
        size_t n = (size_t)(rand64() % sizeof text), i;
        /* mostly plain bytes, sometimes the rare ones */
        int rare = (int)(rand64() % 4u);
        for (i = 0; i < n; i++) {
            uint64_t u = rand64();
            text[i] = rare == 0 || (u & 7u) == 0 ? alphabet[(u >> 3) % (sizeof alphabet - 1)]
                                                 : alphabet[(u >> 3) % 27u];
        }
        check_same(text, n);
    }
    assert_int_equal(failures, 0);
}

static void test_across_read_blocks(void **state)
{
    /* 3.5 blocks of planner-like rows: records cut by the block boundaries */
    const size_t n = CSV_READ_BLOCK * 7 / 2;
    char *text = malloc(n);
    size_t i = 0;
    (void)state;
    failures = 0;
    assert_non_null(text);
    while (i < n) {
        int w = snprintf(text + i, n - i, "%llu,%.17g, %d ,x%d\n",
                         (unsigned long long)(rand64() % 1000000u),
                         (double)(rand64() >> 11) * 1e-9, (int)(rand64() % 100u),
                         (int)(rand64() % 7u));
        if (w < 0 || (size_t)w >= n - i) break;
        i += (size_t)w;
    }
    check_same(text, i);
    text[CSV_READ_BLOCK + 3] = '"'; /* a quote near the first boundary */
    check_same(text, i);
    free(text);
    assert_int_equal(failures, 0);
}

static void test_chunk_edges(void **state)
{
    /* lines of 0..70 bytes with a comma, a blank and a tab at each place: the
     * sixteen-byte split's chunk edges and last chunk (csv_read.c) */
    char text[96];
    size_t n, c;
    (void)state;
    failures = 0;
    for (n = 1; n <= 70; n++) {
        for (c = 0; c < n; c++) {
            memset(text, '7', n);
            text[c] = ',';
            text[(c + 1) % n] = ' ';
            text[(c + 17) % n] = '\t';
            text[n] = '\n';
            memcpy(text + n + 1, "1,2\n", 4);
            check_same(text, n + 5);
        }
        /* a quote, CR, NUL or byte above 0x7F at each place: the split's masks
         * hand the line to the byte by byte reader, the last chunk's too (a CR
         * before the LF is every CRLF file) */
        for (c = 0; c < n; c++) {
            static const char hand_off[5] = {'"', '\r', '\0', '\xEF', '\x80'};
            int k;
            for (k = 0; k < 5; k++) {
                memset(text, '7', n);
                text[(c + 1) % n] = ',';
                text[c] = hand_off[k];
                text[n] = '\n';
                memcpy(text + n + 1, "1,2\n", 4);
                check_same(text, n + 5);
            }
        }
    }
    assert_int_equal(failures, 0);
}

/* Reads text (n bytes) to its end in the given mode; returns the CPU
 * seconds taken and, in st[] (up to 8), the results, in lines[] each
 * record's rec_line, in f0[] its first field's first byte ('-' for none). */
static double read_all(const char *text, size_t n, int byte_by_byte, int *st,
                       unsigned long *lines, char *f0, int *count)
{
    FILE *fp = fmemopen((void *)text, n, "rb");
    csv_reader r;
    clock_t t0;
    int k = 0, s;
    assert_non_null(fp);
    csv_init(&r, fp);
    r.byte_by_byte = byte_by_byte;
    t0 = clock();
    while ((s = csv_next(&r)) != CSV_END && s != CSV_IO && s != CSV_NOMEM && k < 8) {
        st[k] = s;
        lines[k] = r.rec_line;
        f0[k] = s == CSV_RECORD && r.nfields > 0 ? csv_field(&r, 0)[0] : '-';
        k++;
    }
    *count = k;
    t0 = clock() - t0;
    csv_free(&r);
    fclose(fp);
    return (double)t0 / CLOCKS_PER_SEC;
}

static void test_long_records_in_linear_time(void **state)
{
    /* records of 1 MiB less a little, one field or many, unquoted or
     * quoted, then a short one: each read in well under a second (the reader
     * rescanned the rest of its block per byte past the first 64 KiB: 1 to
     * 5 s), the same fields both ways */
    const size_t n = CSV_MAX_RECORD - 64;
    char *text = malloc(n + 16);
    int shape;
    (void)state;
    failures = 0;
    assert_non_null(text);
    for (shape = 0; shape < 4; shape++) {
        int st[8], count, way;
        unsigned long lines[8];
        char f0[8];
        size_t i;
        for (i = 0; i < n; i++) text[i] = (char)('0' + (char)(i % 10));
        if (shape == 1)
            for (i = 100; i < n; i += 1000) text[i] = ',';
        if (shape == 2) {
            text[0] = '"';
            text[n - 2] = '"';
        }
        if (shape == 3)
            for (i = 5; i < n; i += 7) text[i] = ' ';
        text[n - 1] = '\n';
        memcpy(text + n, "7,8\n", 4);
        for (way = 0; way < 2; way++) {
            const double sec = read_all(text, n + 4, way, st, lines, f0, &count);
            if (sec > 0.25) {
                print_error("shape %d (byte by byte %d): %.3f s\n", shape, way, sec);
                failures++;
            }
            assert_int_equal(count, 2);
            assert_int_equal(st[0], CSV_RECORD);
            assert_int_equal(st[1], CSV_RECORD);
            assert_int_equal(lines[1], 2);
            assert_int_equal(f0[1], '7');
        }
        check_same(text, n + 4);
    }
    free(text);
    assert_int_equal(failures, 0);
}

static void test_too_long_resumes_after_the_record(void **state)
{
    /* a quoted field that reaches the record limit at, just before or just
     * after a line break inside its quotes, and the same unquoted (limit
     * hit at a comma): the record is skipped to its end (quotes honoured)
     * and reported at the line where it began; the next record is the one
     * after it (the reader resumed inside the quotes: rows that are not
     * records) */
    const size_t lim = CSV_MAX_RECORD + 16; /* the record buffer's bytes */
    char *text = malloc(lim + 64);
    int d, quoted;
    (void)state;
    failures = 0;
    assert_non_null(text);
    for (quoted = 0; quoted < 2; quoted++) {
        for (d = -6; d <= 3; d++) {
            int st[8], count, way;
            unsigned long lines[8];
            char f0[8];
            size_t len = 0, k = (size_t)((long)lim + d);
            memcpy(text, "a,b\n", 4);
            len = 4;
            if (quoted) text[len++] = '"';
            memset(text + len, 'x', k);
            len += k;
            {
                const char *tail = quoted ? "\ny\n\"\"z,\n\",2\n3,4\n" : ",y,\"q\nr\"\n3,4\n";
                memcpy(text + len, tail, strlen(tail));
                len += strlen(tail);
            }
            for (way = 0; way < 2; way++) {
                (void)read_all(text, len, way, st, lines, f0, &count);
                if (count != 3)
                    print_error("quoted %d, d %d, way %d: %d %d %d %d, lines %lu %lu %lu %lu\n",
                                quoted, d, way, st[0], st[1], st[2], st[3], lines[0], lines[1],
                                lines[2], lines[3]);
                assert_int_equal(count, 3);
                assert_int_equal(st[0], CSV_RECORD);
                assert_int_equal(st[1], CSV_TOO_LONG);
                assert_int_equal(lines[1], 2);
                assert_int_equal(st[2], CSV_RECORD);
                assert_int_equal(f0[2], '3');
                assert_int_equal(lines[2], quoted ? 6 : 4);
            }
        }
    }
    free(text);
    assert_int_equal(failures, 0);
}

static void test_bad_quote_resumes_after_the_record(void **state)
{
    /* text after a closing quote, then a quoted field with a line break: the
     * record ends after that field, not at the line break */
    static const char text[] = "\"x\"y,\"a\nb,c\",1\n3,4\n";
    int st[8], count, way;
    unsigned long lines[8];
    char f0[8];
    (void)state;
    for (way = 0; way < 2; way++) {
        (void)read_all(text, sizeof text - 1, way, st, lines, f0, &count);
        assert_int_equal(count, 2);
        assert_int_equal(st[0], CSV_BAD_QUOTE);
        assert_int_equal(lines[0], 1);
        assert_int_equal(st[1], CSV_RECORD);
        assert_int_equal(f0[1], '3');
        assert_int_equal(lines[1], 3);
    }
}

/* The first result of text after its records "ok,...": want, the mark at
 * line and col of the record begun at line rec, then the record "next". */
static void check_bom(const char *text, int want, unsigned long rec, unsigned long line,
                      unsigned long col)
{
    int way;
    for (way = 0; way < 2; way++) {
        FILE *fp = fmemopen((void *)text, strlen(text), "rb");
        csv_reader r;
        int st;
        assert_non_null(fp);
        csv_init(&r, fp);
        r.byte_by_byte = way;
        do {
            st = csv_next(&r);
        } while (st == CSV_RECORD && strcmp(csv_field(&r, 0), "ok") == 0);
        if (st != want) print_error("\"%s\" way %d\n", text, way);
        assert_int_equal(st, want);
        if (want == CSV_BAD_BOM) {
            assert_int_equal(r.err_line, line);
            assert_int_equal(r.err_col, col);
            assert_int_equal(r.rec_line, rec);
            assert_int_equal(csv_next(&r), CSV_RECORD);
            assert_string_equal(csv_field(&r, 0), "next");
        }
        csv_free(&r);
        fclose(fp);
    }
}

static void test_bom_only_at_the_start(void **state)
{
    (void)state;
    /* the first three bytes: skipped */
    check_bom("\xEF\xBB\xBF" "id,b\n", CSV_RECORD, 0, 0, 0);
    /* a second mark (a header saved twice), files joined, in a field, in quotes */
    check_bom("\xEF\xBB\xBF\xEF\xBB\xBF" "id,b\nnext\n", CSV_BAD_BOM, 1, 1, 1);
    check_bom("ok,1\n\xEF\xBB\xBF" "id,b\nnext\n", CSV_BAD_BOM, 2, 2, 1);
    check_bom("ok,1\r\nx,  \xEF\xBB\xBF" "id\r\nnext\n", CSV_BAD_BOM, 2, 2, 5);
    check_bom("ok,1\n1,\"a\nb\xEF\xBB\xBF\"\nnext\n", CSV_BAD_BOM, 2, 3, 2);
    check_bom("ok,1\n\"\xEF\xBB\xBF\",1\nnext\n", CSV_BAD_BOM, 2, 2, 2);
    /* other 0xEF sequences are text (U+FF0C, U+FEFE) */
    check_bom("ok,1\n\xEF\xBC\x8C,\xEF\xBB\xBE\n", CSV_RECORD, 0, 0, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hand_written),
        cmocka_unit_test(test_random_texts),
        cmocka_unit_test(test_across_read_blocks),
        cmocka_unit_test(test_chunk_edges),
        cmocka_unit_test(test_long_records_in_linear_time),
        cmocka_unit_test(test_too_long_resumes_after_the_record),
        cmocka_unit_test(test_bad_quote_resumes_after_the_record),
        cmocka_unit_test(test_bom_only_at_the_start),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
