/* SPDX-License-Identifier: MIT */
/* earthshine.c: diffuse earthshine from the baked table (Lambert far field
 * beyond it). Table layout and coordinates: include/oi_table.h,
 * docs/earthshine-table.md. */
#include "oi_internal.h"

#ifndef OI_NO_EARTH_TABLE
#include "oi_earth_diffuse.h"
#endif

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

/* The grid of one table in oi_real: converted once per call from the
 * table's double fields, or compile-time constants for the default table (the
 * single-precision build then does no double arithmetic in the lookup). */
typedef struct es_grid {
    const oi_earth_table *t;   /* payload and sizes */
    int surf;                  /* w_min = 0: the first row is the surface */
    int full;                  /* w_min = 0 and w_max = pi/2: every h > 0 is inside */
    oi_real w_min, w_max, k0, kp;
} es_grid;

/* Catmull-Rom (cubic convolution, a = -1/2) weights for fraction f in [0, 1]. */
static void cr_weights(oi_real f, oi_real wt[4])
{
    const oi_real f2 = f * f;
    const oi_real f3 = f2 * f;
    wt[0] = OI_R(0.5) * (-f3 + OI_R(2.0) * f2 - f);
    wt[1] = OI_R(0.5) * (OI_R(3.0) * f3 - OI_R(5.0) * f2 + OI_R(2.0));
    wt[2] = OI_R(0.5) * (OI_R(-3.0) * f3 + OI_R(4.0) * f2 + f);
    wt[3] = OI_R(0.5) * (f3 - f2);
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

/* Split a fractional index into cell (0..n-2) and fraction (f is clamped
 * to [0, n - 1] first, so truncation is floor). */
static int cell_of(oi_real f, int n, oi_real *frac)
{
    int i;
    if (f < (oi_real)0) f = (oi_real)0;
    if (f > (oi_real)(n - 1)) f = (oi_real)(n - 1);
    i = (int)f;
    if (i > n - 2) i = n - 2;
    *frac = f - (oi_real)i;
    return i;
}

/* Ghost rows of one 4-row stencil (the theta spline is linear in the rows):
 * quadratic below a surface row (w_min = 0, n_alt >= 3, so that row 2
 * exists), else linear; then the Catmull-Rom sum in w. r[1], r[2] are rows
 * j, j + 1; r[0], r[3] rows j - 1, j + 2 where they exist. */
static oi_real alt_sum(oi_real r[4], int j, int n_alt, int surf, const oi_real wb[4])
{
    if (j + 2 >= n_alt) r[3] = OI_R(2.0) * r[2] - r[1];
    if (j - 1 < 0) {
        if (surf && n_alt >= 3) r[0] = OI_R(3.0) * (r[1] - r[2]) + r[3];
        else r[0] = OI_R(2.0) * r[1] - r[2];
    }
    return wb[0] * r[0] + wb[1] * r[1] + wb[2] * r[2] + wb[3] * r[3];
}

/* Catmull-Rom along theta at an interior cell (no ghost column): p points
 * at column i, 1 <= i <= n - 3. The same sums as seg_row. */
static oi_real row_interior(const float *p, const oi_real wa[4])
{
    return wa[0] * (oi_real)p[-1] + wa[1] * (oi_real)p[0] + wa[2] * (oi_real)p[1] +
           wa[3] * (oi_real)p[2];
}

/* Bicubic Catmull-Rom of both quantities (q and psi) in one segment
 * (columns off..off+n-1) at fractional indices fv (theta) and fw (altitude):
 * one stencil (cells, weights, ghost flags, rows inside the table) serves
 * both tables. */
static void seg_interp(const es_grid *g, int off, int n, oi_real fv, oi_real fw,
                       oi_real *vq, oi_real *vp)
{
    oi_real wa[4], wb[4], rq[4], rp[4], fa, fb;
    const int i = cell_of(fv, n, &fa);
    const int j = cell_of(fw, g->t->n_alt, &fb);
    const int lo = i == 0, hi = i + 2 >= n;
    const size_t ld = (size_t)g->t->n_lit + (size_t)g->t->n_term;
    /* rows j - 1 + k for k in [k_lo, k_hi): those inside the table */
    const int k_lo = j == 0 ? 1 : 0, k_hi = j + 2 >= g->t->n_alt ? 3 : 4;
    int k;
    cr_weights(fb, wb);
    if (n == 2) {
        /* two columns, both ghosts linear: the theta spline is the straight
         * line through them (the lit segment: n_lit = 2) */
        for (k = k_lo; k < k_hi; k++) {
            const size_t c = (size_t)(j - 1 + k) * ld + (size_t)off;
            const oi_real q0 = (oi_real)g->t->q[c], p0 = (oi_real)g->t->psi[c];
            rq[k] = q0 + fa * ((oi_real)g->t->q[c + 1] - q0);
            rp[k] = p0 + fa * ((oi_real)g->t->psi[c + 1] - p0);
        }
        *vq = alt_sum(rq, j, g->t->n_alt, g->surf, wb);
        *vp = alt_sum(rp, j, g->t->n_alt, g->surf, wb);
        return;
    }
    cr_weights(fa, wa);
    if (!lo && !hi) {
        for (k = k_lo; k < k_hi; k++) {
            const size_t c = (size_t)(j - 1 + k) * ld + (size_t)off + (size_t)i;
            rq[k] = row_interior(g->t->q + c, wa);
            rp[k] = row_interior(g->t->psi + c, wa);
        }
    } else {
        for (k = k_lo; k < k_hi; k++) {
            const size_t c = (size_t)(j - 1 + k) * ld + (size_t)off + (size_t)i;
            rq[k] = seg_row(g->t->q + c, lo, hi, wa);
            rp[k] = seg_row(g->t->psi + c, lo, hi, wa);
        }
    }
    *vq = alt_sum(rq, j, g->t->n_alt, g->surf, wb);
    *vp = alt_sum(rp, j, g->t->n_alt, g->surf, wb);
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
 * m = sinh(k t) / sinh(k), k = k0 x^kp (bake/grid.py term_t). x^8 (the
 * default table's kp) by three squarings instead of pow. */
static oi_real term_t(oi_real m, oi_real x, const es_grid *g)
{
    oi_real k;
    if (!(g->k0 > (oi_real)0)) return m;
    if (g->kp == OI_R(8.0)) {
        const oi_real x2 = x * x;
        const oi_real x4 = x2 * x2;
        k = g->k0 * (x4 * x4);
    } else {
        k = g->k0 * OI_POW(x, g->kp);
    }
    if (k < OI_R(1e-4)) return m; /* the map deviates from m by ~k^2/6 */
    return asinh_r(m * sinh_r(k)) / k;
}

/* Validation of a caller's table without double arithmetic (the
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

static int table_valid(const oi_earth_table *t)
{
    if (t->format != OI_TABLE_FORMAT || t->n_lit < 2 || t->n_term < 2 || t->n_alt < 2) return 0;
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

/* The grid of a valid caller's table in oi_real; returns g. */
static const es_grid *grid_of(const oi_earth_table *t, es_grid *g)
{
    g->t = t;
    g->surf = nonneg_bits(t->w_min) == 0ULL;
    g->w_min = (oi_real)t->w_min;
    g->w_max = (oi_real)t->w_max;
    g->k0 = (oi_real)t->term_k0;
    g->kp = (oi_real)t->term_kp;
    g->full = g->surf && g->w_max >= HALF_PI_R;
    return g;
}

#ifndef OI_NO_EARTH_TABLE
/* The grid of the default table oi_earth_diffuse as compile-time constants,
 * from its generated header (written by the baker with the table's fields,
 * so a re-bake updates both): the const table is valid by
 * construction, so it is neither validated nor converted per call.
 * test_earthshine.c (test_default_grid_constants) checks the lookup through
 * them against the same table passed as a caller's table. */
#define ES_DEF_W_MIN OI_EARTH_DIFFUSE_W_MIN
#define ES_DEF_W_MAX OI_EARTH_DIFFUSE_W_MAX
#define ES_DEF_K0 OI_EARTH_DIFFUSE_TERM_K0
#define ES_DEF_KP OI_EARTH_DIFFUSE_TERM_KP

static const es_grid es_default_grid = {
    .t = &oi_earth_diffuse,
    .surf = ES_DEF_W_MIN == 0.0,
    .full = ES_DEF_W_MIN == 0.0 && (oi_real)ES_DEF_W_MAX >= HALF_PI_R,
    .w_min = (oi_real)ES_DEF_W_MIN,
    .w_max = (oi_real)ES_DEF_W_MAX,
    .k0 = (oi_real)ES_DEF_K0,
    .kp = (oi_real)ES_DEF_KP,
};
#endif

/*
 * oi_earthshine: diffuse earthshine per unit albedo and unit solar
 * irradiance at the Earth (table lookup; Lambert far field beyond it).
 *
 * Given:
 *   theta  oi_real      angle at the Earth's centre between the Sun and the
 *                       point (rad); clamped to [0, pi]
 *   h_km   oi_real      altitude of the point above the model's Earth radius
 *                       (km), > 0 (the default table reaches the surface)
 *   model  oi_model*    NULL (defaults) or model: earth_model, earth_table
 *                       (NULL: the baked default table oi_earth_diffuse),
 *                       earth_radius_km
 * Returned:
 *   phi    oi_real      normalised scalar irradiance, >= 0: the scalar
 *                       irradiance at the point is albedo * TSI *
 *                       (1 AU / |sun|)^2 * phi
 *   psi    oi_real      mean incidence direction: angle from the nadir (point
 *                       to Earth centre) towards the Sun side, in the
 *                       Sun-Earth-point plane (rad), in [0, asin(R/r)];
 *                       0 where phi = 0 and in the Lambert far field
 * Returned (function value):
 *          int          OI_OK                (also with OI_EARTH_LAMBERT, note 3)
 *                       OI_WARN_TABLE_RANGE  altitude outside the range of the
 *                            table given in model->earth_table, or no table at
 *                            all (OI_NO_EARTH_TABLE build, earth_table NULL):
 *                            the Lambert far field (R/r)^2 p(theta), psi = 0
 *                       OI_ERR_NULL          phi or psi is NULL
 *                       OI_ERR_NONFINITE     theta or h_km is NaN or infinite
 *                       OI_ERR_BELOW_SURFACE h_km <= 0
 *                       OI_ERR_MODEL         invalid model field, or a table with
 *                            the wrong format or an invalid grid
 *                       OI_ERR_RADIUS        negative model radius
 *                       On error phi and psi (when not NULL) are 0.
 * Notes:
 *  1. The table (format 4) has a grid uniform in w = acos(x) (x = R/r),
 *     computed here as atan2(sqrt(h (2R + h)), R) (no cancellation at low
 *     altitude), from w = 0 (the surface) or w_min up, and in theta two
 *     segments: the visible cap fully lit (theta <= pi/2 - w), where
 *     phi = cos(theta) phi(0, x) and tan psi = tan(theta) G(x) hold exactly
 *     (stored: phi(0, x) / x^2 and G / w), and the terminator crossing it
 *     (pi/2 - w < theta < pi/2 + w; stored phi / (x^2 w) and psi; nodes
 *     graded towards theta = pi/2 at low altitude by the map
 *     sinh(k t)/sinh(k)). Beyond theta = pi/2 + w nothing lit is visible and
 *     phi = 0 exactly. Interpolation: bicubic Catmull-Rom per segment. See
 *     include/oi_table.h and docs/earthshine-table.md.
 *  2. Accuracy of the default table (measured against the quadrature
 *     reference at points between the nodes, see tables/oi_earth_diffuse.c):
 *     relative error <= 1e-3 wherever phi >= 1% of its subsolar value at
 *     that altitude, absolute error <= 1e-5 of the subsolar value elsewhere,
 *     from h = 1 m (measured; the table's first row is the limit h -> 0,
 *     phi = 2 cos(theta)) to infinity. In single precision add ~1e-6
 *     relative, more where theta rounded to float moves the terminator.
 *  3. OI_EARTH_LAMBERT selects the far field everywhere and returns OI_OK.
 *     The far field is exact only at infinity: at the Moon's distance it is
 *     still ~12% off where phi is 1% of its subsolar value (PHYSICS.md; the
 *     error grows like 7 R/r there).
 *  4. The table is scale-free: a model Earth radius other than the default
 *     uses the same table (its altitude range scales with the radius).
 *  5. The model Earth has no atmosphere; refracted light is not included.
 *  6. Cost (docs/earthshine-table.md, "Cost"): the default table's grid is
 *     compiled in (no validation or double conversion per call); a caller's
 *     table is validated on every call (its double fields compared by bit
 *     pattern, then converted once to oi_real). One stencil (cells and
 *     weights) serves q and psi. Beyond the cap's far edge a table covering
 *     every altitude returns without an arctangent. Results agree with the
 *     previous lookup to rounding (tests/c/test_earthshine.c).
 * References:
 *  Penney 2009 (seed), III.3 (table of phi over theta and altitude; its
 *  analytic model corrected as in PHYSICS.md errata). Catmull & Rom 1974;
 *  Keys 1981, IEEE Trans. ASSP 29, 1153 (cubic convolution, a = -1/2).
 */
int oi_earthshine(oi_real theta, oi_real h_km, const oi_model *model,
                  oi_real *phi, oi_real *psi)
{
    oi_model m;
    int st;

    if (phi != NULL) *phi = (oi_real)0;
    if (psi != NULL) *psi = (oi_real)0;
    if (phi == NULL || psi == NULL) return OI_ERR_NULL;

    st = oi__model_resolve(model, &m);
    if (st < 0) return st;
    return oi__earthshine(theta, (oi_real)2, (oi_real)0, h_km, &m, phi, psi);
}

/* oi_earthshine with a resolved model and non-NULL outputs, and cos(theta),
 * sin(theta) when the caller has them (cos_theta > 1: not given); see
 * src/oi_internal.h. */
int oi__earthshine(oi_real theta, oi_real cos_theta, oi_real sin_theta, oi_real h_km,
                   const oi_model *resolved, oi_real *phi, oi_real *psi)
{
    const oi_model *m = resolved;
    es_grid g;
    const es_grid *grid = NULL; /* NULL: no table, the Lambert far field */
    oi_real R, x, w, s, z, tb;

    *phi = (oi_real)0;
    *psi = (oi_real)0;
    if (!OI_ISFINITE(theta) || !OI_ISFINITE(h_km)) return OI_ERR_NONFINITE;
    if (!(h_km > (oi_real)0)) return OI_ERR_BELOW_SURFACE;

    if (theta < (oi_real)0) theta = (oi_real)0;
    if (theta > OI_PI_R) theta = OI_PI_R;

    if (m->earth_model == OI_EARTH_TABLE) {
        const oi_earth_table *t = m->earth_table;
        if (t != NULL
#ifndef OI_NO_EARTH_TABLE
            && t != &oi_earth_diffuse
#endif
        ) {
            if (!table_valid(t)) return OI_ERR_MODEL;
            grid = grid_of(t, &g);
        }
#ifndef OI_NO_EARTH_TABLE
        else {
            grid = &es_default_grid;
        }
#endif
    }

    R = m->earth_radius_km;
    x = R / (R + h_km);
    s = OI_SQRT(h_km) * OI_SQRT(OI_R(2.0) * R + h_km); /* no overflow for huge h */
    z = s / R; /* tan(w); may overflow to +inf (atan(inf) = pi/2) */

    if (grid != NULL && grid->full && theta > HALF_PI_R) {
        /* Beyond the cap's far edge (theta >= pi/2 + w: nothing lit is
         * visible) decided without the arctangent, from an upper bound of
         * w = atan(z) (alternating series, z <= 1: z - z^3/3 + z^5/5; z > 1:
         * pi/2 - 1/z + 1/(3 z^3)) with a margin of 16 epsilon for rounding.
         * Only for a table covering every altitude (else the point may lie
         * outside its range: the far field). Points the bound leaves take
         * the exact test below. */
        const oi_real d = theta - HALF_PI_R;
        oi_real ub;
        if (z <= OI_R(1.0)) {
            const oi_real z2 = z * z;
            ub = z * (OI_R(1.0) - z2 * (OI_R(1.0) / OI_R(3.0) - z2 / OI_R(5.0)));
        } else {
            const oi_real u = OI_R(1.0) / z;
            ub = HALF_PI_R - u * (OI_R(1.0) - u * u / OI_R(3.0));
        }
        if (d >= ub * (OI_R(1.0) + BOUND_MARGIN) + BOUND_MARGIN) return OI_OK;
    }

    w = OI_ATAN2(s, R); /* = acos(x), no cancellation at low altitude */

    if (grid != NULL) {
        const oi_real cells = (oi_real)(grid->t->n_alt - 1);
        const oi_real fw = (w - grid->w_min) / (grid->w_max - grid->w_min) * cells;
        if (fw >= -EDGE_TOL_CELLS && fw <= cells + EDGE_TOL_CELLS) {
            oi_real q, p, fv;
            if (theta >= HALF_PI_R + w) return OI_OK; /* nothing lit is visible */
            tb = HALF_PI_R - w;
            if (theta <= tb && tb > (oi_real)0) {
                /* cap wholly lit: phi = cos(theta) phi(0, x), tan psi =
                 * tan(theta) G(x) exactly; stored q0 = phi(0, x) / x^2, G / w */
                oi_real ct = cos_theta, st = sin_theta;
                if (cos_theta > (oi_real)1) OI_SINCOS(theta, &st, &ct);
                fv = theta / tb * (oi_real)(grid->t->n_lit - 1);
                seg_interp(grid, 0, grid->t->n_lit, fv, fw, &q, &p);
                q *= ct;
                p = OI_ATAN2(p * w * st, ct);
            } else {
                /* terminator segment: stored q / w and psi */
                oi_real mm = (theta - HALF_PI_R) / w;
                if (mm > OI_R(1.0)) mm = OI_R(1.0);
                if (mm < OI_R(-1.0)) mm = OI_R(-1.0);
                fv = OI_R(0.5) * (term_t(mm, x, grid) + OI_R(1.0)) * (oi_real)(grid->t->n_term - 1);
                seg_interp(grid, grid->t->n_lit, grid->t->n_term, fv, fw, &q, &p);
                q *= w;
            }
            if (q < (oi_real)0) q = (oi_real)0;
            if (p < (oi_real)0) p = (oi_real)0;
            if (p > tb) p = tb; /* the limb: asin(x) = pi/2 - w */
            *phi = q * x * x;
            *psi = *phi > (oi_real)0 ? p : (oi_real)0;
            return OI_OK;
        }
    }

    /* Lambert far field: explicit model, no table, or outside its range */
    *phi = x * x * oi_lambert_phase(theta);
    *psi = (oi_real)0;
    return m->earth_model == OI_EARTH_LAMBERT ? OI_OK : OI_WARN_TABLE_RANGE;
}
