/* SPDX-License-Identifier: MIT */
/*
 * fuzz_csv.c: libFuzzer target for the planner's CSV input
 * (planner/csv_read.c and batch.c).
 *
 * Two layers, both fed with the fuzzer's bytes:
 *   1. the record reader on a memory stream (fmemopen): every record's fields
 *      are readable NUL-terminated strings without a byte-order mark, the
 *      field count is consistent, the reader terminates (at most one record
 *      per input byte + 1);
 *   2. the whole batch (batch_run) on the same bytes through a memfd path,
 *      writing its CSV to a memory stream: exit code 0, 1 or 2 (the planner's
 *      contract), and no "nan"/"inf" in any output field;
 *   3. the same bytes as a --shapes file (shapes_load): it either fails or
 *      holds 1 to PLAN_SHAPES_MAX shapes of 1 to OI_FACETS_MAX facets each,
 *      every one accepted by oi_shape_check, named, within PLAN_FACETS_TOTAL.
 * Run with -close_fd_mask=2 to silence the planner's messages (make fuzz does).
 */
#define _GNU_SOURCE 1
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/mman.h>
#include <unistd.h>

#include "orbillum.h"
#include "batch.h"
#include "csv_read.h"
#include "shapes.h"

#define FZ_CHECK(cond)                                                              \
    do {                                                                            \
        if (!(cond)) {                                                              \
            fprintf(stderr, "%s:%d: invariant violated: %s\n", __FILE__, __LINE__, \
                    #cond);                                                         \
            abort();                                                                \
        }                                                                           \
    } while (0)

static void fuzz_reader(const uint8_t *data, size_t size)
{
    FILE *fp;
    csv_reader r;
    size_t records = 0;
    int res;
    if (size == 0) return; /* fmemopen of an empty buffer is not portable */
    fp = fmemopen((void *)(uintptr_t)data, size, "r");
    if (fp == NULL) return;
    csv_init(&r, fp);
    while ((res = csv_next(&r)) != CSV_END) {
        FZ_CHECK(res >= CSV_RECORD && res <= CSV_BAD_BOM);
        FZ_CHECK(csv_result_text(res) != NULL);
        if (res == CSV_IO || res == CSV_NOMEM) break;
        if (res == CSV_RECORD) {
            size_t i, n = csv_nfields(&r);
            FZ_CHECK(n >= 1);
            for (i = 0; i < n; i++) {
                const char *f = csv_field(&r, i);
                FZ_CHECK(f != NULL);
                FZ_CHECK(strlen(f) <= size);
                FZ_CHECK(strstr(f, "\xEF\xBB\xBF") == NULL); /* a mark only at the start */
            }
            FZ_CHECK(csv_field(&r, n) == NULL);
        }
        FZ_CHECK(++records <= size + 1);
    }
    csv_free(&r);
    fclose(fp);
}

/* Every comma-, CR- or LF-separated field of the output but the first (the
 * id, which echoes the input) is checked for a non-finite number as printf
 * writes it. */
static void check_output(const char *out, size_t len)
{
    size_t i = 0;
    int column = 0;
    while (i < len) {
        size_t j = i;
        char tok[8];
        size_t n;
        if (column == 0 && i < len && out[i] == '"') {
            /* the id column echoes the input, quoted when needed: skip it */
            j = i + 1;
            while (j < len && !(out[j] == '"' && (j + 1 >= len || out[j + 1] != '"')))
                j += (out[j] == '"') ? 2 : 1;
            j++;
        }
        while (j < len && out[j] != ',' && out[j] != '\n' && out[j] != '\r') j++;
        n = j - i;
        if (column > 0 && n > 0 && n < sizeof tok) {
            const char *t;
            memcpy(tok, out + i, n);
            tok[n] = '\0';
            t = tok;
            if (*t == '-' || *t == '+') t++;
            if (strcasecmp(t, "nan") == 0 || strcasecmp(t, "inf") == 0 ||
                strcasecmp(t, "infinity") == 0) {
                fprintf(stderr, "non-finite output field '%s' in:\n%.*s\n", tok, (int)len, out);
                abort();
            }
        }
        column = (j < len && out[j] == ',') ? column + 1 : 0;
        i = j + 1;
    }
}

static void check_shapes(const plan_shapes *s)
{
    unsigned i, total = 0;
    FZ_CHECK(s->n_shapes >= 1u && s->n_shapes <= PLAN_SHAPES_MAX);
    FZ_CHECK(s->n_facets <= PLAN_FACETS_TOTAL);
    for (i = 0; i < s->n_shapes; i++) {
        const plan_shape *p = &s->shapes[i];
        const oi_shape *found;
        size_t len = strnlen(p->name, PLAN_SHAPE_NAME_MAX);
        FZ_CHECK(len > 0 && len < PLAN_SHAPE_NAME_MAX);
        FZ_CHECK(p->shape.n_facets >= 1u && p->shape.n_facets <= (unsigned)OI_FACETS_MAX);
        FZ_CHECK(oi_shape_check(&p->shape) == OI_OK);
        FZ_CHECK(shapes_lookup(s, p->name, &found) == 0 && found == &p->shape);
        total += p->shape.n_facets;
    }
    FZ_CHECK(total == s->n_facets);
}

static void fuzz_shapes(const char *path)
{
    static plan_shapes s; /* static: 30 KB */
    FILE *err = fopen("/dev/null", "w");
    int st;
    if (err == NULL) return;
    st = shapes_load(&s, path, err);
    fclose(err);
    FZ_CHECK(st == 0 || st == -1);
    if (st == 0) check_shapes(&s);
    else FZ_CHECK(s.n_shapes == 0u && s.n_facets == 0u);
}

static void fuzz_batch(const uint8_t *data, size_t size)
{
    char path[64];
    char *out = NULL;
    size_t out_len = 0;
    FILE *os;
    int fd, code;
    fd = memfd_create("fuzz_csv", 0);
    if (fd < 0) return;
    if (size > 0 && write(fd, data, size) != (ssize_t)size) {
        close(fd);
        return;
    }
    snprintf(path, sizeof path, "/proc/self/fd/%d", fd);
    os = open_memstream(&out, &out_len);
    if (os == NULL) {
        close(fd);
        return;
    }
    code = batch_run(path, oi_camera_builtin(0), NULL, os, NULL);
    fclose(os);
    fuzz_shapes(path);
    close(fd);
    FZ_CHECK(code == PLAN_EXIT_OK || code == PLAN_EXIT_ROWS || code == PLAN_EXIT_INPUT);
    check_output(out, out_len);
    free(out);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_reader(data, size);
    fuzz_batch(data, size);
    return 0;
}
