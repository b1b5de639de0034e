/* SPDX-License-Identifier: MIT */
/*
 * oi_internal.h: every private header of the runtime at once, for white-box
 * tests and tools (tests/c, fuzz/, bench/, target/). The runtime's own files
 * include only their layer's header (src/<layer>/<layer>_internal.h), which
 * includes the layers below it (docs/architecture.md).
 */
#ifndef OI_INTERNAL_H
#define OI_INTERNAL_H

#include "batch/batch_internal.h"

#endif /* OI_INTERNAL_H */
