/* SPDX-License-Identifier: MIT */
/*
 * oi_tables_internal.h: internal interface of the baked-table lookups: the
 * interpolation kernels every lookup shares (src/interp.c), the earthshine
 * table lookup (src/earthshine_table.c) and the check of a caller's
 * atmosphere table (src/atmosphere.c). Table layouts: include/oi_table.h.
 */
#ifndef OI_TABLES_INTERNAL_H
#define OI_TABLES_INTERNAL_H

#include "oi_internal.h"

/* ---------------------------------------------------------------- interp kernels
 * C99 inline definitions, inlined where a lookup calls them (they are in
 * every lookup's inner loop); src/interp.c holds their one external
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

/* ---------------------------------------------------------------- earthshine_table.c */

/* 1 when a caller's earthshine table has a format, kind and grid the lookup
 * can use (include/orbillum.h, oi_model.earth_table), else 0. No double
 * arithmetic: the single-precision build pulls in no software double. */
int oi__earth_table_valid(const oi_earth_table *t);

/*
 * phi and psi from table t (valid, or the trusted default) at theta
 * (clamped to [0, pi]) and the altitude given by x = R / r and s = sqrt(h
 * (2R + h)) (w = acos(x) = atan2(s, R)); cos_theta, sin_theta as for
 * oi__earthshine (cos_theta > 1: not given). Returns 1 with *phi, *psi set
 * when the altitude is inside the table's range, 0 (outputs untouched) when
 * it is not (the caller's far field).
 */
int oi__earth_lookup(const oi_earth_table *t, oi_real theta, oi_real cos_theta,
                     oi_real sin_theta, oi_real x, oi_real s, oi_real R, oi_real *phi,
                     oi_real *psi);

/* ---------------------------------------------------------------- atm_table_check.c */
#ifndef OI_NO_ATMOSPHERE
/* 1 when a caller's atmosphere table has the format, kind, sizes and grid
 * constants the lookup can use (include/orbillum.h, oi_model.atm_table),
 * else 0. Called by oi__model_resolve (src/model.c). */
int oi__atm_table_valid(const oi_atm_table *t);
#endif

#endif /* OI_TABLES_INTERNAL_H */
