/* SPDX-License-Identifier: MIT */
/*
 * earthshine_table.c: the earthshine table lookup: the check of a caller's
 * table, its grid in oi_real, and phi and psi by bicubic Catmull-Rom per
 * theta segment. Table layout and coordinates: include/oi_table.h,
 * docs/earthshine-table.md; the public function: src/earthshine.c.
 */
#include "oi_tables_internal.h"

#define HALF_PI_R ((oi_real)(0.5 * OI_PI))


/* Tolerance (in grid cells) for points on the altitude range's ends that
 * rounding puts just outside: they are clamped onto the end node. */
#ifdef OI_SINGLE_PRECISION
#define EDGE_TOL_CELLS OI_R(1e-3)
#define BOUND_MARGIN OI_R(1.9073486328125e-06) /* 16 FLT_EPSILON */
#else
#define EDGE_TOL_CELLS OI_R(1e-9)
#define BOUND_MARGIN OI_R(3.5527136788005009e-15) /* 16 DBL_EPSILON */
#endif

/* The check of a caller's table without double arithmetic (the
 * single-precision build must not pull in software double compares): the
 * double fields are compared by their IEEE 754 binary64 bit patterns, which,
 * read as unsigned integers, order like the values for non-negative doubles
 * (+inf above every finite value, NaN above +inf). -0 is read as +0. The
 * checks are those of the double comparisons they replace (w_min >= 0,
 * w_max > w_min, w_max <= (pi/2)(1 + 1e-15), k0 in [0, 20], kp in [0, 100]). */
typedef unsigned long long es_bits;
typedef char es_bits_hold_a_double[sizeof(es_bits) == sizeof(double) ? 1 : -1];
#define ES_SIGN_BIT 0x8000000000000000ULL
#define ES_INF_BITS 0x7FF0000000000000ULL

/* Bits of d with -0 as +0; values above ES_INF_BITS are NaN or negative. */
static es_bits nonneg_bits(double d)
{
    es_bits u;
    memcpy(&u, &d, sizeof u);
    return u == ES_SIGN_BIT ? 0ULL : u;
}

/* A grid value d in oi_real. In single precision the default table's value
 * c (recognised by its bits) gives its float c_r without the software
 * double-to-float conversion a Cortex-M4F would call; in double a load. */
static oi_real real_of(double d, double c, oi_real c_r)
{
#ifdef OI_SINGLE_PRECISION
    if (nonneg_bits(d) == nonneg_bits(c)) return c_r;
#else
    (void)c;
    (void)c_r;
#endif
    return (oi_real)d;
}

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
        if (nonneg_bits(t->w_min) == 0ULL && n_alt >= 3) r[0] = OI_R(3.0) * (r[1] - r[2]) + r[3];
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
    const oi_real k0 = real_of(t->term_k0, 2.0, OI_R(2.0));
    const oi_real kp = real_of(t->term_kp, 8.0, OI_R(8.0));
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

int oi__earth_table_valid(const oi_earth_table *t)
{
    if (t->format != OI_TABLE_FORMAT || t->n_lit < 2 || t->n_term < 2 || t->n_alt < 2) return 0;
    if (t->kind != 0 && t->kind != OI_TABLE_KIND_EARTHSHINE) return 0;
    if (t->q == NULL || t->psi == NULL) return 0;
    {
        const es_bits w_min = nonneg_bits(t->w_min), w_max = nonneg_bits(t->w_max);
        if (w_min > ES_INF_BITS || w_max > ES_INF_BITS || !(w_max > w_min) ||
            w_max > nonneg_bits(0.5 * OI_PI * (1.0 + 1e-15)))
            return 0;
        if (w_min == 0ULL && t->n_alt < 3) return 0; /* quadratic ghost row */
    }
    return nonneg_bits(t->term_k0) <= nonneg_bits(20.0) &&
           nonneg_bits(t->term_kp) <= nonneg_bits(100.0);
}

/* 1 when theta > pi/2 lies certainly beyond the cap's far edge, theta >=
 * pi/2 + w (nothing lit is visible), decided without the arctangent from an
 * upper bound of w = atan(z) (alternating series, z <= 1: z - z^3/3 + z^5/5;
 * z > 1: pi/2 - 1/z + 1/(3 z^3)) with a margin of 16 epsilon for rounding.
 * 0: not certain (the exact test follows). */
static int beyond_far_edge(oi_real theta, oi_real z)
{
    const oi_real d = theta - HALF_PI_R;
    oi_real ub;
    if (z <= OI_R(1.0)) {
        const oi_real z2 = z * z;
        ub = z * (OI_R(1.0) - z2 * (OI_R(1.0) / OI_R(3.0) - z2 / OI_R(5.0)));
    } else {
        const oi_real u = OI_R(1.0) / z;
        ub = HALF_PI_R - u * (OI_R(1.0) - u * u / OI_R(3.0));
    }
    return d >= ub * (OI_R(1.0) + BOUND_MARGIN) + BOUND_MARGIN;
}

/* The lookup at w = acos(x) inside the table's altitude range: phi, psi. */
static void lookup_inside(const oi_earth_table *t, oi_real theta, oi_real cos_theta,
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

int oi__earth_lookup(const oi_earth_table *t, oi_real theta, oi_real cos_theta,
                     oi_real sin_theta, oi_real x, oi_real s, oi_real R, oi_real *phi,
                     oi_real *psi)
{
    /* the grid in oi_real, converted once per call */
    const int surf = nonneg_bits(t->w_min) == 0ULL;
    const oi_real w_min = surf ? (oi_real)0 : (oi_real)t->w_min;
    const oi_real w_max = real_of(t->w_max, 0.5 * OI_PI, HALF_PI_R);
    oi_real w, cells, fw;
    /* every altitude: beyond the cap's far edge without the arctangent
     * (z = s / R = tan(w), may be +inf) */
    if (theta > HALF_PI_R && surf && w_max >= HALF_PI_R && beyond_far_edge(theta, s / R)) {
        *phi = *psi = (oi_real)0;
        return 1;
    }
    w = OI_ATAN2(s, R); /* = acos(x), no cancellation at low altitude */
    cells = (oi_real)(t->n_alt - 1);
    fw = (w - w_min) / (w_max - w_min) * cells;
    if (!(fw >= -EDGE_TOL_CELLS && fw <= cells + EDGE_TOL_CELLS)) return 0;
    if (theta >= HALF_PI_R + w) {
        *phi = *psi = (oi_real)0; /* nothing lit is visible */
        return 1;
    }
    lookup_inside(t, theta, cos_theta, sin_theta, x, w, fw, phi, psi);
    return 1;
}
