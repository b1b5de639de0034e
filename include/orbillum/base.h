/* SPDX-License-Identifier: MIT */
/*
 * orbillum/base.h: what every section stands on: the scalar type and the
 * compile-time options (oi_config.h), the physical constants and defaults
 * (oi_constants.h), the version of the header and the statuses every call
 * returns.
 *
 * A section of orbillum.h, the header a program includes (it includes every
 * section); compiles alone, and includes the sections it uses.
 */
#ifndef ORBILLUM_BASE_H
#define ORBILLUM_BASE_H

#include "../oi_config.h"
#include "../oi_constants.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- version */

/* Version of this header (semantic: a new MINOR extends the contract, a new
 * MAJOR breaks it). OI_VERSION encodes it as MAJOR * 10000 + MINOR * 100 +
 * PATCH. */
#define OI_VERSION_MAJOR 0
#define OI_VERSION_MINOR 2
#define OI_VERSION_PATCH 0
#define OI_VERSION (OI_VERSION_MAJOR * 10000L + OI_VERSION_MINOR * 100L + OI_VERSION_PATCH)

/* Precision guard: the public names of a single-precision build end in _sp
 * (oi_config.h). */

/*
 * oi_version: the version of the archive the program is linked with.
 * Returned (function value): OI_VERSION of the header the archive was built
 * from. A program compares it with its own OI_VERSION (the header it was
 * compiled with): equal, or an archive of the same MAJOR and a MINOR at least
 * the program's, keeps every declaration the program uses.
 */
long oi_version(void);

/* ---------------------------------------------------------------- status */

enum oi_status {
    OI_OK = 0,
    /* warnings: result computed */
    OI_WARN_TABLE_RANGE = 1,      /* outside a baked table: analytic model used */
    /* errors: result not computed, outputs zeroed */
    OI_ERR_NULL = -1,             /* a required pointer is NULL */
    OI_ERR_NONFINITE = -2,        /* NaN or infinite input component */
    OI_ERR_ZERO_VECTOR = -3,      /* a position that must be nonzero is zero */
    OI_ERR_BELOW_SURFACE = -4,    /* target or observer at or below the Earth's surface */
    OI_ERR_OBSERVER_AT_TARGET = -5, /* observer inside the target's sphere (range <=
                                       target radius; oi_expose_scene: range 0). The
                                       positions are taken as given in oi_real: in
                                       single precision an observer closer to the
                                       target than the spacing of floats there (3.9 m
                                       at 42,000 km) may round onto it, and is then
                                       this error, never a result of range 0 */
    OI_ERR_ALBEDO = -6,           /* an albedo outside [0, 1] */
    OI_ERR_RADIUS = -7,           /* a radius <= 0 (target, or a model radius) */
    OI_ERR_MODEL = -8,            /* an oi_model field out of range */
    OI_ERR_CAMERA = -9,           /* an oi_camera field out of range */
    OI_ERR_MAGNITUDE = -10,       /* a magnitude outside [OI_MAG_MIN, OI_MAG_MAX], or a
                                     flux brighter than magnitude OI_MAG_MIN */
    OI_ERR_TERMS = -11,           /* unknown bits in a terms mask (oi_scene.terms) */
    OI_ERR_GEOMETRY = -12,        /* impossible geometry (e.g. Sun inside the Earth's
                                     radius plus its own, point inside the Sun) */
    OI_ERR_INPUT = -13,           /* an argument out of range that is no camera, model,
                                     magnitude or albedo: an exposure goal, a negative
                                     flux or irradiance, a background radiance */
    OI_ERR_FLAGS = -14,           /* unknown bits in a flags mask (oi_expose_in.flags) */
    OI_ERR_SHAPE = -15            /* a bad facet, shape or attitude quaternion (oi_shape_check) */
};

/* oi_status_name: the name of a status, the enum name without its "OI_"
 * prefix ("OK", "WARN_TABLE_RANGE", "ERR_NONFINITE", ...); "UNKNOWN" for any
 * other value. Never NULL; static storage. The names are stable: scripts
 * (the planner's CSV status column) match on them. */
const char *oi_status_name(int status);

/*
 * Floating-point exceptions: no call raises FE_INVALID, FE_DIVBYZERO or
 * FE_OVERFLOW, on valid input or on the inputs its documented errors
 * refuse (NaN, infinities, zero vectors, subnormal and out-of-range values):
 * checks compare quietly and come before the arithmetic they guard
 * (tests/c/test_fp_exceptions.c runs every documented error with traps on).
 * Not yet: finite positions near the largest oi_real (beyond about 1e37 km
 * in single precision, 1e307 km in double), which oi_sun_fraction's sphere
 * and oi_expose_scene take, may still raise FE_OVERFLOW in their norms.
 */

/* Valid range of magnitudes accepted as input. */
#define OI_MAG_MIN (-30.0)
#define OI_MAG_MAX (50.0)

#ifdef __cplusplus
}
#endif

#endif /* ORBILLUM_BASE_H */
