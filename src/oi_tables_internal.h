/* SPDX-License-Identifier: MIT */
/*
 * oi_tables_internal.h: what every baked-table lookup shares, whatever its
 * layer: the interpolation kernels (src/math/interp.c) and the reading of a
 * table's fields. The lookups themselves are declared in their layers'
 * headers. Table layouts: include/oi_table.h.
 */
#ifndef OI_TABLES_INTERNAL_H
#define OI_TABLES_INTERNAL_H

#include "oi_vector.h"

/* ---------------------------------------------------------------- interp kernels
 * C99 inline definitions, inlined where a lookup calls them (they are in
 * every lookup's inner loop); src/math/interp.c holds their one external
 * definition, for calls the compiler does not inline. */

/* Catmull-Rom (cubic convolution, a = -1/2) weights of the four nodes
 * i - 1 .. i + 2 around a point at fraction f in [0, 1] of cell i. */
inline void oi__cr_weights(oi_real f, oi_real wt[4])
{
    const oi_real f2 = f * f;
    const oi_real f3 = f2 * f;
    wt[0] = OI_R(0.5) * (-f3 + OI_R(2.0) * f2 - f);
    wt[1] = OI_R(0.5) * (OI_R(3.0) * f3 - OI_R(5.0) * f2 + OI_R(2.0));
    wt[2] = OI_R(0.5) * (OI_R(-3.0) * f3 + OI_R(4.0) * f2 + f);
    wt[3] = OI_R(0.5) * (f3 - f2);
}

/* Cell (0 .. n - 2) and fraction (in [0, 1]) of a fractional index f on n
 * >= 2 nodes, f clamped to [0, n - 1] first: a point outside the grid reads
 * the end node. NaN reads cell 0, fraction NaN (no undefined conversion). */
inline int oi__cell_clamped(oi_real f, int n, oi_real *frac)
{
    int i;
    if (f < (oi_real)0) f = (oi_real)0;
    if (f > (oi_real)(n - 1)) f = (oi_real)(n - 1);
    i = f >= (oi_real)0 ? (int)f : 0; /* NaN: 0; else truncation is the floor */
    if (i > n - 2) i = n - 2;
    *frac = f - (oi_real)i;
    return i;
}

/* Cell (0 .. n - 2) of a fractional index f on n >= 2 nodes, and the
 * fraction f - cell, not clamped: a point a rounding outside the grid is
 * extrapolated linearly by that rounding (the atmosphere's lookup, whose
 * indices are inside up to rounding). NaN reads cell 0. */
inline int oi__cell_floor(oi_real f, int n, oi_real *frac)
{
    int i;
    if (!(f >= (oi_real)0))
        i = 0; /* below the grid, or NaN */
    else if (f >= (oi_real)(n - 2))
        i = n - 2;
    else
        i = (int)f;
    *frac = f - (oi_real)i;
    return i;
}

/* Bilinear interpolation in a row-major table of 16-bit codes with ld codes
 * per row, between rows i, i + 1 (fraction fu) and columns j, j + 1
 * (fraction ft). Returns the interpolated code: a linear decoding
 * (min + scale code) commutes with it and is applied by the caller. */
inline oi_real oi__bilinear_u16(const unsigned short *tab, int ld, int i, int j, oi_real fu,
                                oi_real ft)
{
    const unsigned short *r0 = tab + i * ld + j;
    const unsigned short *r1 = r0 + ld;
    const oi_real a = ((oi_real)1 - ft) * (oi_real)r0[0] + ft * (oi_real)r0[1];
    const oi_real b = ((oi_real)1 - ft) * (oi_real)r1[0] + ft * (oi_real)r1[1];
    return ((oi_real)1 - fu) * a + fu * b;
}

/* ---------------------------------------------------------------- table fields */

/* The double fields of an earthshine table read without double arithmetic
 * (the single-precision build must not pull in software double compares):
 * by their IEEE 754 binary64 bit patterns, which, read as unsigned
 * integers, order like the values for non-negative doubles (+inf above
 * every finite value, NaN above +inf). -0 is read as +0. */
typedef unsigned long long oi__bits64;
typedef char oi__bits64_holds_a_double[sizeof(oi__bits64) == sizeof(double) ? 1 : -1];
#define OI__SIGN_BIT 0x8000000000000000ULL
#define OI__INF_BITS 0x7FF0000000000000ULL

/* Bits of d with -0 as +0; values above OI__INF_BITS are NaN or negative. */
static inline oi__bits64 oi__nonneg_bits(double d)
{
    oi__bits64 u;
    memcpy(&u, &d, sizeof u);
    return u == OI__SIGN_BIT ? 0ULL : u;
}

/* A grid value d in oi_real. In single precision the default table's value
 * c (recognised by its bits) gives its float c_r without the software
 * double-to-float conversion a Cortex-M4F would call; in double a load. */
static inline oi_real oi__real_of(double d, double c, oi_real c_r)
{
#ifdef OI_SINGLE_PRECISION
    if (oi__nonneg_bits(d) == oi__nonneg_bits(c)) return c_r;
#else
    (void)c;
    (void)c_r;
#endif
    return (oi_real)d;
}

#endif /* OI_TABLES_INTERNAL_H */
