/* SPDX-License-Identifier: MIT */
/*
 * earthshine_table.c: the earthshine table lookup: the check of a caller's
 * table, and phi and psi inside its altitude range by bicubic Catmull-Rom
 * per theta segment. Table layout and coordinates: include/oi_table.h,
 * docs/earthshine-table.md; which table and which regime: src/sources/earthshine.c.
 */
#include "sources/sources_internal.h"
#include "oi_tables_internal.h"

#define HALF_PI_R ((oi_real)(0.5 * OI_PI))



/* Catmull-Rom along theta in one segment row: p points at column i of the
 * row; lo (i = 0) and hi (i = n - 2) replace the columns outside the segment
 * by linear extrapolation, 2 v(0) - v(1) and 2 v(n-1) - v(n-2). */
static oi_real seg_row(const float *p, int lo, int hi, const oi_real wa[4])
{
    const oi_real v1 = (oi_real)p[0];
    const oi_real v2 = (oi_real)p[1];
    const oi_real v0 = lo ? OI_R(2.0) * v1 - v2 : (oi_real)p[-1];
    const oi_real v3 = hi ? OI_R(2.0) * v2 - v1 : (oi_real)p[2];
    return wa[0] * v0 + wa[1] * v1 + wa[2] * v2 + wa[3] * v3;
}

/* Catmull-Rom along theta at an interior cell (no ghost column): p points
 * at column i, 1 <= i <= n - 3. The same sums as seg_row. */
static oi_real row_interior(const float *p, const oi_real wa[4])
{
    return wa[0] * (oi_real)p[-1] + wa[1] * (oi_real)p[0] + wa[2] * (oi_real)p[1] +
           wa[3] * (oi_real)p[2];
}

/* Ghost rows of one 4-row stencil (the theta spline is linear in the rows):
 * quadratic below a surface row (w_min = 0, n_alt >= 3, so that row 2
 * exists; decided here, where it is needed), else linear; then the Catmull-Rom sum in w. r[1], r[2] are rows
 * j, j + 1; r[0], r[3] rows j - 1, j + 2 where they exist. */
static oi_real alt_sum(oi_real r[4], int j, const oi_earth_table *t, const oi_real wb[4])
{
    const int n_alt = t->n_alt;
    if (j + 2 >= n_alt) r[3] = OI_R(2.0) * r[2] - r[1];
    if (j - 1 < 0) {
        if (oi__nonneg_bits(t->w_min) == 0ULL && n_alt >= 3)
            r[0] = OI_R(3.0) * (r[1] - r[2]) + r[3];
        else r[0] = OI_R(2.0) * r[1] - r[2];
    }
    return wb[0] * r[0] + wb[1] * r[1] + wb[2] * r[2] + wb[3] * r[3];
}

/* Bicubic Catmull-Rom of both quantities (q and psi) in one segment
 * (columns off..off+n-1) at fractional indices fv (theta) and fw (altitude):
 * one stencil (cells, weights, ghost flags, rows inside the table) serves
 * both tables. */
static void seg_interp(const oi_earth_table *t, int off, int n, oi_real fv, oi_real fw,
                       oi_real *vq, oi_real *vp)
{
    oi_real wa[4], wb[4], rq[4], rp[4], fa, fb;
    const int i = oi__cell_clamped(fv, n, &fa);
    const int j = oi__cell_clamped(fw, t->n_alt, &fb);
    const int lo = i == 0, hi = i + 2 >= n;
    const size_t ld = (size_t)t->n_lit + (size_t)t->n_term;
    /* rows j - 1 + k for k in [k_lo, k_hi): those inside the table */
    const int k_lo = j == 0 ? 1 : 0, k_hi = j + 2 >= t->n_alt ? 3 : 4;
    int k;
    oi__cr_weights(fb, wb);
    if (n == 2) {
        /* two columns, both ghosts linear: the theta spline is the straight
         * line through them (the lit segment: n_lit = 2) */
        for (k = k_lo; k < k_hi; k++) {
            const size_t c = (size_t)(j - 1 + k) * ld + (size_t)off;
            const oi_real q0 = (oi_real)t->q[c], p0 = (oi_real)t->psi[c];
            rq[k] = q0 + fa * ((oi_real)t->q[c + 1] - q0);
            rp[k] = p0 + fa * ((oi_real)t->psi[c + 1] - p0);
        }
    } else {
        const size_t c0 = (size_t)off + (size_t)i;
        oi__cr_weights(fa, wa);
        if (!lo && !hi) {
            for (k = k_lo; k < k_hi; k++) {
                const size_t c = (size_t)(j - 1 + k) * ld + c0;
                rq[k] = row_interior(t->q + c, wa);
                rp[k] = row_interior(t->psi + c, wa);
            }
        } else {
            for (k = k_lo; k < k_hi; k++) {
                const size_t c = (size_t)(j - 1 + k) * ld + c0;
                rq[k] = seg_row(t->q + c, lo, hi, wa);
                rp[k] = seg_row(t->psi + c, lo, hi, wa);
            }
        }
    }
    *vq = alt_sum(rq, j, t, wb);
    *vp = alt_sum(rp, j, t, wb);
}

/* asinh(z) without cancellation for small |z|: series z (1 - z^2/6 + 3 z^4/40
 * - 15 z^6/336 + 105 z^8/3456) below ASINH_SERIES (next term < 2.3e-2 |z|^11:
 * < 1e-21 relative in double below 0.01, < 2e-11 in float below 0.125). */
#ifdef OI_SINGLE_PRECISION
#define ASINH_SERIES OI_R(0.125)
#else
#define ASINH_SERIES OI_R(0.01)
#endif
static oi_real asinh_r(oi_real z)
{
    const oi_real a = OI_FABS(z);
    oi_real r;
    if (a < ASINH_SERIES) {
        const oi_real z2 = z * z;
        return z * (OI_R(1.0) + z2 * (OI_R(-1.0) / OI_R(6.0) +
                    z2 * (OI_R(3.0) / OI_R(40.0) +
                    z2 * (OI_R(-15.0) / OI_R(336.0) + z2 * (OI_R(105.0) / OI_R(3456.0))))));
    }
    r = OI_LOG(a + OI_SQRT(a * a + OI_R(1.0)));
    return z < (oi_real)0 ? -r : r;
}

/* sinh(k) for k >= 0 without cancellation: Taylor series to k^13 below 0.5
 * (next term < 5e-17 relative), the exponential form above. */
static oi_real sinh_r(oi_real k)
{
    if (k < OI_R(0.5)) {
        const oi_real k2 = k * k;
        return k * (OI_R(1.0) + k2 / OI_R(6.0) * (OI_R(1.0) + k2 / OI_R(20.0) *
                    (OI_R(1.0) + k2 / OI_R(42.0) * (OI_R(1.0) + k2 / OI_R(72.0) *
                    (OI_R(1.0) + k2 / OI_R(110.0) * (OI_R(1.0) + k2 / OI_R(156.0)))))));
    }
    {
        const oi_real e = OI_EXP(k); /* one exponential: e^-k = 1/e (k <= 20) */
        return OI_R(0.5) * (e - OI_R(1.0) / e);
    }
}

/* Position t in [-1, 1] of m = (theta - pi/2) / w on the terminator map
 * m = sinh(k t) / sinh(k), k = k0 x^kp (the baker's grid, bake/earthshine).
 * x^8 (the default table's kp) by three squarings instead of pow. */
static oi_real term_t(oi_real m, oi_real x, const oi_earth_table *t)
{
    const oi_real k0 = oi__real_of(t->term_k0, 2.0, OI_R(2.0));
    const oi_real kp = oi__real_of(t->term_kp, 8.0, OI_R(8.0));
    oi_real k;
    if (!(k0 > (oi_real)0)) return m;
    if (kp == OI_R(8.0)) {
        const oi_real x2 = x * x;
        const oi_real x4 = x2 * x2;
        k = k0 * (x4 * x4);
    } else {
        k = k0 * OI_POW(x, kp);
    }
    if (k < OI_R(1e-4)) return m; /* the map deviates from m by ~k^2/6 */
    return asinh_r(m * sinh_r(k)) / k;
}

/* The checks of the double comparisons they replace, on bit patterns
 * (oi__nonneg_bits): w_min >= 0, w_max > w_min, w_max <= (pi/2)(1 +
 * 1e-15), k0 in [0, 20], kp in [0, 100]. */
int oi__earth_table_valid(const oi_earth_table *t)
{
    if (t->format != OI_TABLE_FORMAT || t->n_lit < 2 || t->n_term < 2 || t->n_alt < 2) return 0;
    if (t->kind != 0 && t->kind != OI_TABLE_KIND_EARTHSHINE) return 0;
    if (t->q == NULL || t->psi == NULL) return 0;
    {
        const oi__bits64 w_min = oi__nonneg_bits(t->w_min), w_max = oi__nonneg_bits(t->w_max);
        if (w_min > OI__INF_BITS || w_max > OI__INF_BITS || !(w_max > w_min) ||
            w_max > oi__nonneg_bits(0.5 * OI_PI * (1.0 + 1e-15)))
            return 0;
        if (w_min == 0ULL && t->n_alt < 3) return 0; /* quadratic ghost row */
    }
    return oi__nonneg_bits(t->term_k0) <= oi__nonneg_bits(20.0) &&
           oi__nonneg_bits(t->term_kp) <= oi__nonneg_bits(100.0);
}

void oi__earth_interp(const oi_earth_table *t, oi_real theta, oi_real cos_theta,
                          oi_real sin_theta, oi_real x, oi_real w, oi_real fw, oi_real *phi,
                          oi_real *psi)
{
    const oi_real tb = HALF_PI_R - w;
    oi_real q, p, fv;
    if (theta <= tb && tb > (oi_real)0) {
        /* cap wholly lit: phi = cos(theta) phi(0, x), tan psi = tan(theta)
         * G(x) exactly; stored q0 = phi(0, x) / x^2, G / w */
        oi_real ct = cos_theta, st = sin_theta;
        if (cos_theta > (oi_real)1) OI_SINCOS(theta, &st, &ct);
        fv = theta / tb * (oi_real)(t->n_lit - 1);
        seg_interp(t, 0, t->n_lit, fv, fw, &q, &p);
        q *= ct;
        p = OI_ATAN2(p * w * st, ct);
    } else {
        /* terminator segment: stored q / w and psi */
        oi_real mm = (theta - HALF_PI_R) / w;
        if (mm > OI_R(1.0)) mm = OI_R(1.0);
        if (mm < OI_R(-1.0)) mm = OI_R(-1.0);
        fv = OI_R(0.5) * (term_t(mm, x, t) + OI_R(1.0)) * (oi_real)(t->n_term - 1);
        seg_interp(t, t->n_lit, t->n_term, fv, fw, &q, &p);
        q *= w;
    }
    if (q < (oi_real)0) q = (oi_real)0;
    if (p < (oi_real)0) p = (oi_real)0;
    if (p > tb) p = tb; /* the limb: asin(x) = pi/2 - w */
    *phi = q * x * x;
    *psi = *phi > (oi_real)0 ? p : (oi_real)0;
}

