/* SPDX-License-Identifier: MIT */
/*
 * fuzz_common.h: decoding fuzzer bytes into oi_real values and vectors, and
 * the invariant check used by every target.
 *
 * A value is one tag byte followed by its payload. The tags make the special
 * values (NaN, +-inf, +-0, subnormals, the largest finite number) as likely
 * as raw bit patterns, and add "plausible" values spread over the magnitudes
 * the runtime meets (1e-8 .. 1e15) so that the fuzzer also reaches the deep
 * paths behind the input validation. Exhausted input reads as zeros.
 */
#ifndef FUZZ_COMMON_H
#define FUZZ_COMMON_H

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "orbillum.h"

typedef struct fz_in {
    const uint8_t *p;
    size_t n;
} fz_in;

#define FZ_CHECK(cond)                                                              \
    do {                                                                            \
        if (!(cond)) {                                                              \
            fprintf(stderr, "%s:%d: invariant violated: %s\n", __FILE__, __LINE__, \
                    #cond);                                                         \
            abort();                                                                \
        }                                                                           \
    } while (0)

static uint8_t fz_u8(fz_in *in)
{
    uint8_t v;
    if (in->n == 0) return 0;
    v = in->p[0];
    in->p++;
    in->n--;
    return v;
}

static uint32_t fz_u16(fz_in *in)
{
    uint32_t hi = fz_u8(in);
    return (hi << 8) | fz_u8(in);
}

#ifdef OI_SINGLE_PRECISION
#define FZ_MAX FLT_MAX
#define FZ_MIN_NORMAL FLT_MIN
#define FZ_EPS FLT_EPSILON
#else
#define FZ_MAX DBL_MAX
#define FZ_MIN_NORMAL DBL_MIN
#define FZ_EPS DBL_EPSILON
#endif

static oi_real fz_raw(fz_in *in)
{
    unsigned char b[sizeof(oi_real)];
    oi_real v;
    size_t i;
    for (i = 0; i < sizeof b; i++) b[i] = fz_u8(in);
    memcpy(&v, b, sizeof v);
    return v;
}

/* One value: see the header comment. */
static oi_real fz_real(fz_in *in)
{
    uint8_t tag = fz_u8(in);
    oi_real sign = (tag & 0x80) ? (oi_real)-1 : (oi_real)1;
    switch (tag & 0x0f) {
    case 0: return (oi_real)0;
    case 1: return -(oi_real)0;
    case 2: return (oi_real)NAN;
    case 3: return sign * (oi_real)INFINITY;
    case 4: return sign * FZ_MIN_NORMAL * FZ_EPS * (oi_real)(1 + fz_u8(in)); /* subnormal */
    case 5: return sign * FZ_MAX / (oi_real)(1 + fz_u8(in));                 /* near overflow */
    case 6: return sign * FZ_MIN_NORMAL * (oi_real)(1 + fz_u8(in));          /* tiny normal */
    case 7: case 8: return fz_raw(in);
    default: {
        /* plausible: sign * (1 + m/65536) * 10^(e - 8), e in 0..23 */
        oi_real m = (oi_real)1 + (oi_real)fz_u16(in) / (oi_real)65536;
        int e = (int)(fz_u8(in) % 24) - 8;
        return sign * m * (oi_real)pow(10.0, (double)e);
    }
    }
}

/* A unit direction from two bytes pairs (spherical angles), exact axes
 * included (bytes 0 and 128 give the poles and the equator). */
static void fz_dir(fz_in *in, double d[3])
{
    double lon = (double)fz_u16(in) / 65536.0 * 2.0 * 3.14159265358979323846;
    double lat = ((double)fz_u16(in) / 65535.0 - 0.5) * 3.14159265358979323846;
    d[0] = cos(lat) * cos(lon);
    d[1] = cos(lat) * sin(lon);
    d[2] = sin(lat);
}

/* A position: raw components, or a direction times a distance drawn near
 * the scale of the Earth's surface, the Sun (0.98..1.02 AU) or anything. */
static void fz_vec(fz_in *in, oi_real v[3])
{
    uint8_t mode = fz_u8(in) % 5;
    double d[3], r;
    int i;
    if (mode == 0) {
        for (i = 0; i < 3; i++) v[i] = fz_real(in);
        return;
    }
    fz_dir(in, d);
    switch (mode) {
    case 1: /* altitude above the default Earth: 1e-6 km .. 1e9 km, or raw */
        r = OI_EARTH_RADIUS_KM + pow(10.0, (double)fz_u16(in) / 65535.0 * 15.0 - 6.0);
        break;
    case 2: /* the Sun */
        r = OI_AU_KM * (0.98 + 0.04 * (double)fz_u16(in) / 65535.0);
        break;
    case 3: /* the Moon's distance */
        r = 356000.0 + 50000.0 * (double)fz_u16(in) / 65535.0;
        break;
    default:
        r = (double)fz_real(in);
        break;
    }
    for (i = 0; i < 3; i++) v[i] = (oi_real)(d[i] * r);
}

static int fz_finite(oi_real x)
{
    return isfinite(x) != 0;
}

static int fz_finite3(const oi_real v[3])
{
    return fz_finite(v[0]) && fz_finite(v[1]) && fz_finite(v[2]);
}

/* A unit vector or exactly zero (direction outputs). */
static int fz_unit_or_zero(const oi_real v[3])
{
    double n2 = (double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2];
    if (n2 == 0) return 1;
    return fabs(n2 - 1.0) <= 64.0 * FZ_EPS;
}

static int fz_frac(oi_real x)
{
    return fz_finite(x) && x >= (oi_real)0 && x <= (oi_real)1;
}

static int fz_nonneg(oi_real x)
{
    return fz_finite(x) && x >= (oi_real)0;
}

/* A documented status: one the library names (its status table is the list
 * the header documents; a new code is known as soon as it is named). */
static int fz_known_status(int st)
{
    return strcmp(oi_status_name(st), "UNKNOWN") != 0;
}

#endif /* FUZZ_COMMON_H */
