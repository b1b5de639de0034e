/* SPDX-License-Identifier: MIT */
/* status.c: oi_status_name, the printable name of a status code. */
#include "model/model_internal.h"

/*
 * oi_status_name: name of a status code.
 *
 * Given:
 *   status   int   a value returned by an orbillum function
 *
 * Returned (function value):
 *            const char *  "OK", "WARN_TABLE_RANGE", "ERR_NULL", ... : the
 *                          enum oi_status name without its "OI_" prefix;
 *                          "UNKNOWN" for any other value. Never NULL; the
 *                          string is static and must not be modified.
 *
 * Notes:
 *   1. The names are stable: scripts (e.g. the planner's CSV status column)
 *      may match on them.
 *
 * References: enum oi_status in orbillum.h.
 */
const char *oi_status_name(int status)
{
    switch (status) {
    case OI_OK: return "OK";
    case OI_WARN_TABLE_RANGE: return "WARN_TABLE_RANGE";
    case OI_ERR_NULL: return "ERR_NULL";
    case OI_ERR_NONFINITE: return "ERR_NONFINITE";
    case OI_ERR_ZERO_VECTOR: return "ERR_ZERO_VECTOR";
    case OI_ERR_BELOW_SURFACE: return "ERR_BELOW_SURFACE";
    case OI_ERR_OBSERVER_AT_TARGET: return "ERR_OBSERVER_AT_TARGET";
    case OI_ERR_ALBEDO: return "ERR_ALBEDO";
    case OI_ERR_RADIUS: return "ERR_RADIUS";
    case OI_ERR_MODEL: return "ERR_MODEL";
    case OI_ERR_CAMERA: return "ERR_CAMERA";
    case OI_ERR_MAGNITUDE: return "ERR_MAGNITUDE";
    case OI_ERR_TERMS: return "ERR_TERMS";
    case OI_ERR_GEOMETRY: return "ERR_GEOMETRY";
    case OI_ERR_INPUT: return "ERR_INPUT";
    case OI_ERR_FLAGS: return "ERR_FLAGS";
    case OI_ERR_SHAPE: return "ERR_SHAPE";
    default: return "UNKNOWN";
    }
}
