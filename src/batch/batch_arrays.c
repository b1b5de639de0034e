/* SPDX-License-Identifier: MIT */
/*
 * The batch calls' checks of the caller's arrays (src/batch/batch.c,
 * src/batch/expose_batch.c): alignment, length within the address space, no
 * output overlapping an input or another output (include/orbillum.h), and
 * the batch-wide failure that sets every status.
 */
#include "batch/batch_internal.h"

int oi__span_of(const void *p, long n, size_t size, size_t align, oi__span *s)
{
    const uintptr_t a = (uintptr_t)p;
    s->lo = s->hi = a;
    if (p == NULL) return 1;
    if (a % align != 0) return 0;
    if ((uintptr_t)n > (UINTPTR_MAX - a) / size) return 0;
    s->hi = a + (uintptr_t)n * size;
    return 1;
}

static int spans_overlap(const oi__span *a, const oi__span *b)
{
    return a->lo < a->hi && b->lo < b->hi && a->lo < b->hi && b->lo < a->hi;
}

int oi__check_overlap(const oi__span *in, int n_in, const oi__span *out, int n_out)
{
    int i, j;
    for (i = 0; i < n_out; i++) {
        for (j = 0; j < n_in; j++)
            if (spans_overlap(&out[i], &in[j])) return OI_ERR_INPUT;
        for (j = i + 1; j < n_out; j++)
            if (spans_overlap(&out[i], &out[j])) return OI_ERR_INPUT;
    }
    return OI_OK;
}

int oi__batch_fail(int st, long n, int *status, void *out, size_t size, int zero_out)
{
    long i;
    oi__span s;
    if (status != NULL && oi__span_of(status, n, sizeof *status, OI_ALIGN_OF(int), &s))
        for (i = 0; i < n; i++) status[i] = st;
    if (zero_out && out != NULL) memset(out, 0, (size_t)n * size);
    return st;
}
