/* SPDX-License-Identifier: MIT */
/*
 * oi_wasm_math.c: log10 for the wasm build, in the form the native build's
 * libm (glibc) computes it, so that magnitudes agree bit for bit.
 *
 * wasi-libc's log10 (musl, from FreeBSD) and glibc's differ by an ulp for
 * some arguments, and a magnitude, -2.5 log10(F / TSI), then by 4 to 8 ulp.
 * glibc keeps fdlibm's e_log10.c (Sun Microsystems, 1993): with x = 2^k m,
 *   log10(x) = k log10_2lo + log(m) / ln 10 + k log10_2hi,
 * m in [1, 2) for k >= 0 and [0.5, 1) for k < 0, over its log(), which is
 * the same algorithm (Arm's optimized-routines log) as wasi-libc's log.
 */
#include "oi_wasm_math.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

static const double TWO54 = 1.80143985094819840000e+16;     /* 2^54 */
static const double IVLN10 = 4.34294481903251816668e-01;    /* 1 / ln 10 */
static const double LOG10_2HI = 3.01029995663611771306e-01; /* log10(2), high part */
static const double LOG10_2LO = 3.69423907715893078616e-13; /* log10(2) - LOG10_2HI */

double oi_wasm_log10(double x)
{
    uint64_t u;
    int32_t hx, k = 0, i;
    uint32_t lx;
    double y, z;
    memcpy(&u, &x, sizeof u);
    hx = (int32_t)(u >> 32);
    lx = (uint32_t)u;
    if (hx < 0x00100000) { /* x < 2^-1022, zero, negative */
        if (((hx & 0x7fffffff) | (int32_t)lx) == 0) return -TWO54 / fabs(x);
        if (hx < 0) return (x - x) / (x - x);
        k -= 54;
        x *= TWO54;
        memcpy(&u, &x, sizeof u);
        hx = (int32_t)(u >> 32);
    }
    if (hx >= 0x7ff00000) return x + x;
    k += (hx >> 20) - 1023;
    i = (int32_t)(((uint32_t)k & 0x80000000u) >> 31);
    hx = (hx & 0x000fffff) | ((0x3ff - i) << 20);
    y = (double)(k + i);
    u = ((uint64_t)(uint32_t)hx << 32) | (u & 0xffffffffu);
    memcpy(&x, &u, sizeof x);
    z = y * LOG10_2LO + IVLN10 * log(x);
    return z + y * LOG10_2HI;
}
