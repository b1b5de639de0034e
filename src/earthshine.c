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
#else
#define EDGE_TOL_CELLS OI_R(1e-9)
#endif

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

/* Value at column c in [-1, n] of one segment row (n >= 2 values), ghost
 * columns by linear extrapolation. */
static oi_real seg_value(const float *row, int n, int c)
{
    if (c < 0) return OI_R(2.0) * (oi_real)row[0] - (oi_real)row[1];
    if (c >= n) return OI_R(2.0) * (oi_real)row[n - 1] - (oi_real)row[n - 2];
    return (oi_real)row[c];
}

/* Catmull-Rom along theta within one segment row, at cell i, weights wa. */
static oi_real seg_row(const float *row, int n, int i, const oi_real wa[4])
{
    return wa[0] * seg_value(row, n, i - 1) + wa[1] * seg_value(row, n, i) +
           wa[2] * seg_value(row, n, i + 1) + wa[3] * seg_value(row, n, i + 2);
}

/* Split a fractional index into cell (0..n-2) and fraction. */
static int cell_of(oi_real f, int n, oi_real *frac)
{
    int i;
    if (f < (oi_real)0) f = (oi_real)0;
    if (f > (oi_real)(n - 1)) f = (oi_real)(n - 1);
    i = (int)OI_FLOOR(f);
    if (i > n - 2) i = n - 2;
    *frac = f - (oi_real)i;
    return i;
}

/* Bicubic Catmull-Rom in one segment (columns off..off+n-1 of a table with
 * row stride ld) at fractional indices fv (theta) and fw (altitude);
 * surface: the first row is w = 0 (h = 0). */
static oi_real seg_interp(const float *base, int ld, int off, int n, int n_alt,
                          int surface, oi_real fv, oi_real fw)
{
    oi_real wa[4], wb[4], r[4], fa, fb;
    int i = cell_of(fv, n, &fa);
    int j = cell_of(fw, n_alt, &fb);
    int k;
    cr_weights(fa, wa);
    cr_weights(fb, wb);
    for (k = 0; k < 4; k++) {
        int jj = j - 1 + k;
        if (jj >= 0 && jj < n_alt) r[k] = seg_row(base + (size_t)jj * (size_t)ld + (size_t)off, n, i, wa);
    }
    /* ghost rows by extrapolation (the theta spline is linear in the rows):
     * quadratic below a surface row (w_min = 0, n_alt >= 3), else linear */
    if (j - 1 < 0) {
        if (surface && n_alt >= 3) r[0] = OI_R(3.0) * (r[1] - r[2]) + r[3];
        else r[0] = OI_R(2.0) * r[1] - r[2];
    }
    if (j + 2 >= n_alt) r[3] = OI_R(2.0) * r[2] - r[1];
    return wb[0] * r[0] + wb[1] * r[1] + wb[2] * r[2] + wb[3] * r[3];
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
    return OI_R(0.5) * (OI_EXP(k) - OI_EXP(-k));
}

/* Position t in [-1, 1] of m = (theta - pi/2) / w on the terminator map
 * m = sinh(k t) / sinh(k), k = k0 x^kp (bake/grid.py term_t). */
static oi_real term_t(oi_real m, oi_real x, const oi_earth_table *t)
{
    oi_real k;
    if (t->term_k0 <= 0.0) return m;
    k = (oi_real)t->term_k0 * OI_POW(x, (oi_real)t->term_kp);
    if (k < OI_R(1e-4)) return m; /* the map deviates from m by ~k^2/6 */
    return asinh_r(m * sinh_r(k)) / k;
}

static int table_valid(const oi_earth_table *t)
{
    const double half_pi = 0.5 * OI_PI;
    if (t->format != OI_TABLE_FORMAT || t->n_lit < 2 || t->n_term < 2 || t->n_alt < 2) return 0;
    if (t->q == NULL || t->psi == NULL) return 0;
    if (!(t->w_min >= 0.0) || !(t->w_max > t->w_min) || !(t->w_max <= half_pi * (1.0 + 1e-15)))
        return 0;
    if (t->w_min == 0.0 && t->n_alt < 3) return 0; /* quadratic ghost row */
    if (!(t->term_k0 >= 0.0 && t->term_k0 <= 20.0) || !(t->term_kp >= 0.0 && t->term_kp <= 100.0))
        return 0;
    return 1;
}

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
    return oi__earthshine(theta, h_km, &m, phi, psi);
}

/* oi_earthshine with a resolved model and non-NULL outputs (oi_internal.h). */
int oi__earthshine(oi_real theta, oi_real h_km, const oi_model *model, oi_real *phi,
                   oi_real *psi)
{
    const oi_model *m = model;
    const oi_earth_table *t = NULL;
    oi_real R, x, w, s, tb;

    *phi = (oi_real)0;
    *psi = (oi_real)0;
    if (!OI_ISFINITE(theta) || !OI_ISFINITE(h_km)) return OI_ERR_NONFINITE;
    if (!(h_km > (oi_real)0)) return OI_ERR_BELOW_SURFACE;

    if (theta < (oi_real)0) theta = (oi_real)0;
    if (theta > OI_PI_R) theta = OI_PI_R;

    R = m->earth_radius_km;
    x = R / (R + h_km);
    s = OI_SQRT(h_km) * OI_SQRT(OI_R(2.0) * R + h_km); /* no overflow for huge h */
    w = OI_ATAN2(s, R);

    if (m->earth_model == OI_EARTH_TABLE) {
        t = m->earth_table;
#ifndef OI_NO_EARTH_TABLE
        if (t == NULL) t = &oi_earth_diffuse;
#endif
        if (t != NULL && !table_valid(t)) return OI_ERR_MODEL;
    }

    if (t != NULL) {
        const oi_real w_min = (oi_real)t->w_min;
        const oi_real w_max = (oi_real)t->w_max;
        const oi_real cells = (oi_real)(t->n_alt - 1);
        const oi_real fw = (w - w_min) / (w_max - w_min) * cells;
        if (fw >= -EDGE_TOL_CELLS && fw <= cells + EDGE_TOL_CELLS) {
            const int ld = t->n_lit + t->n_term;
            const int surf = t->w_min == 0.0;
            oi_real q, p, fv;
            if (theta >= HALF_PI_R + w) return OI_OK; /* nothing lit is visible */
            tb = HALF_PI_R - w;
            if (theta <= tb && tb > (oi_real)0) {
                /* cap wholly lit: phi = cos(theta) phi(0, x), tan psi =
                 * tan(theta) G(x) exactly; stored q0 = phi(0, x) / x^2, G / w */
                const int n = t->n_lit;
                const oi_real ct = OI_COS(theta);
                fv = theta / tb * (oi_real)(n - 1);
                q = seg_interp(t->q, ld, 0, n, t->n_alt, surf, fv, fw) * ct;
                p = seg_interp(t->psi, ld, 0, n, t->n_alt, surf, fv, fw) * w;
                p = OI_ATAN2(p * OI_SIN(theta), ct);
            } else {
                /* terminator segment: stored q / w and psi */
                const int n = t->n_term;
                oi_real mm = (theta - HALF_PI_R) / w;
                if (mm > OI_R(1.0)) mm = OI_R(1.0);
                if (mm < OI_R(-1.0)) mm = OI_R(-1.0);
                fv = OI_R(0.5) * (term_t(mm, x, t) + OI_R(1.0)) * (oi_real)(n - 1);
                q = seg_interp(t->q, ld, t->n_lit, n, t->n_alt, surf, fv, fw) * w;
                p = seg_interp(t->psi, ld, t->n_lit, n, t->n_alt, surf, fv, fw);
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
