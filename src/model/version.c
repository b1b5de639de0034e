/* SPDX-License-Identifier: MIT */
/* version.c: oi_version, the version of the archive a program links. */
#include "model/model_internal.h"

/*
 * oi_version: version of the archive.
 *
 * Returned (function value):
 *            long  OI_VERSION (MAJOR * 10000 + MINOR * 100 + PATCH) of the
 *                  include/orbillum.h this archive was compiled with.
 *
 * Notes:
 *   1. A program compares it with the OI_VERSION it was compiled with (see
 *      include/orbillum.h). The precision needs no such check: a mismatch
 *      fails at link time (the _sp names, include/oi_config.h).
 */
long oi_version(void)
{
    return OI_VERSION;
}
