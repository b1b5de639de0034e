/* SPDX-License-Identifier: MIT */
/*
 * batch_internal.h: private to the runtime (not part of the API):
 * the batch layer (src/batch/): the batch calls' array checks.
 * A layer calls only the layers below it (docs/architecture.md); this
 * header includes the one below, so a file sees its layer and every lower one.
 */
#ifndef OI_BATCH_INTERNAL_H
#define OI_BATCH_INTERNAL_H

#include "scene/scene_internal.h"

/* The batch calls' array checks (src/batch/batch_arrays.c). OI_ALIGN_OF: the
 * alignment of a type in C99 (no _Alignof), the offset of a member after a
 * char. oi__span: a caller's array as its address range [lo, hi), lo == hi
 * when absent (NULL). oi__span_of: the span of n elements of size bytes at
 * p, 0 when p is not aligned to align or the size overflows the address
 * space. oi__check_overlap: OI_OK when no output span overlaps an input
 * span or another output span, else OI_ERR_INPUT. oi__batch_fail: a batch
 * error st, every status set to it (when status can be written) and, when
 * zero_out, every output row (size bytes each) zeroed; returns st. */
#define OI_ALIGN_OF(type) offsetof(struct { char c; type t; }, t)
typedef struct {
    uintptr_t lo, hi;
} oi__span;
int oi__span_of(const void *p, long n, size_t size, size_t align, oi__span *s);
int oi__check_overlap(const oi__span *in, int n_in, const oi__span *out, int n_out);
int oi__batch_fail(int st, long n, int *status, void *out, size_t size, int zero_out);

#endif /* OI_BATCH_INTERNAL_H */
