/* SPDX-License-Identifier: MIT */
/*
 * interp.c: the one external definition of each interpolation kernel shared
 * by every baked-table lookup (Catmull-Rom weights, the cell and fraction of
 * a fractional index, bilinear interpolation of 16-bit codes). The kernels
 * and their contracts are C99 inline definitions in src/oi_tables_internal.h
 * so that each lookup inlines them; these declarations make this
 * translation unit emit the out-of-line copies (C99 6.7.4).
 *
 * References: Catmull, E. & Rom, R. 1974, A class of local interpolating
 * splines, in Computer Aided Geometric Design, Academic Press; Keys, R. G.
 * 1981, IEEE Trans. ASSP 29, 1153 (cubic convolution, a = -1/2).
 */
#include "math/math_internal.h"
#include "oi_tables_internal.h"

extern void oi__cr_weights(oi_real f, oi_real wt[4]);
extern int oi__cell_clamped(oi_real f, int n, oi_real *frac);
extern int oi__cell_floor(oi_real f, int n, oi_real *frac);
extern oi_real oi__bilinear_u16(const unsigned short *tab, int ld, int i, int j, oi_real fu,
                                oi_real ft);
