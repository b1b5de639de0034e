/* SPDX-License-Identifier: MIT */
/* earthshine.c: oi_earthshine, diffuse earthshine: its checks, which table
 * serves the call, the table's altitude range and the Lambert far field
 * beyond it. The interpolation inside the table: src/sources/earthshine_table.c;
 * table layout: include/oi_table.h. */
#include "sources/sources_internal.h"
#include "oi_tables_internal.h"

#define HALF_PI_R ((oi_real)(0.5 * OI_PI))

/* Tolerance (in grid cells) for points on the altitude range's ends that
 * rounding puts just outside: they are clamped onto the end node; margin of
 * the far-edge bound (16 epsilon). */
#ifdef OI_SINGLE_PRECISION
#define EDGE_TOL_CELLS OI_R(1e-3)
#define BOUND_MARGIN OI_R(1.9073486328125e-06) /* 16 FLT_EPSILON */
#else
#define EDGE_TOL_CELLS OI_R(1e-9)
#define BOUND_MARGIN OI_R(3.5527136788005009e-15) /* 16 DBL_EPSILON */
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
 *                       (NULL: the default table, oi_earth_table_default()),
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
 *                            table used, or no table at all (earth_table NULL
 *                            and oi_earth_table_default() NULL, as in an
 *                            OI_NO_EARTH_TABLE build): the Lambert far field
 *                            (R/r)^2 p(theta), psi = 0
 *                       OI_ERR_NULL          phi or psi is NULL
 *                       OI_ERR_NONFINITE     theta or h_km is NaN or infinite
 *                       OI_ERR_BELOW_SURFACE h_km <= 0
 *                       OI_ERR_MODEL         invalid model field, or a caller's table
 *                            (earth_table) with the wrong format or kind, a
 *                            NULL payload or an invalid grid
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
 *     still ~12% off where phi is 1% of its subsolar value (docs/physics.md;
 *     the error grows like 7 R/r there).
 *  4. The table is scale-free: a model Earth radius other than the default
 *     uses the same table (its altitude range scales with the radius).
 *  5. The model Earth has no atmosphere; refracted light is not included.
 *  6. Cost (docs/earthshine-table.md, "Cost"): the default table is trusted
 *     (not checked); a caller's table is checked on every call (its double
 *     fields compared by bit pattern). Either grid is converted once per
 *     call to oi_real. One stencil (cells and weights) serves q and psi.
 *     Beyond the cap's far edge a table covering every altitude returns
 *     without an arctangent.
 * References:
 *  Penney 2009 (seed), III.3 (table of phi over theta and altitude; its
 *  analytic model corrected as in docs/physics.md). Catmull & Rom 1974;
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

/* phi and psi from table t at theta and the altitude given by x = R / r and
 * s = sqrt(h (2R + h)); 1 with *phi, *psi set when the altitude is inside
 * the table's range, 0 (outputs untouched) when it is not. */
static int table_phi(const oi_earth_table *t, oi_real theta, oi_real cos_theta, oi_real sin_theta,
                     oi_real x, oi_real s, oi_real R, oi_real *phi, oi_real *psi)
{
    /* the grid in oi_real, converted once per call */
    const int surf = oi__nonneg_bits(t->w_min) == 0ULL;
    const oi_real w_min = surf ? (oi_real)0 : (oi_real)t->w_min;
    const oi_real w_max = oi__real_of(t->w_max, 0.5 * OI_PI, HALF_PI_R);
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
    oi__earth_interp(t, theta, cos_theta, sin_theta, x, w, fw, phi, psi);
    return 1;
}

/* The table that serves a resolved model in *t (NULL: none, the far
 * field); OI_ERR_MODEL for a caller's table that fails its check. The
 * default (oi_earth_table_default) is trusted. */
static int table_of(const oi_model *m, const oi_earth_table **t)
{
    *t = NULL;
    if (m->earth_model != OI_EARTH_TABLE) return OI_OK;
    if (m->earth_table == NULL) {
        *t = oi_earth_table_default();
        return OI_OK;
    }
    if (!oi__earth_table_valid(m->earth_table)) return OI_ERR_MODEL;
    *t = m->earth_table;
    return OI_OK;
}

/* oi_earthshine with a resolved model and non-NULL outputs, and cos(theta),
 * sin(theta) when the caller has them (cos_theta > 1: not given); see
 * src/sources/sources_internal.h. */
int oi__earthshine(oi_real theta, oi_real cos_theta, oi_real sin_theta, oi_real h_km,
                   const oi_model *resolved, oi_real *phi, oi_real *psi)
{
    const oi_earth_table *t;
    oi_real R, x, s;

    *phi = (oi_real)0;
    *psi = (oi_real)0;
    if (!OI_ISFINITE(theta) || !OI_ISFINITE(h_km)) return OI_ERR_NONFINITE;
    if (!(h_km > (oi_real)0)) return OI_ERR_BELOW_SURFACE;

    if (theta < (oi_real)0) theta = (oi_real)0;
    if (theta > OI_PI_R) theta = OI_PI_R;
    if (table_of(resolved, &t) != OI_OK) return OI_ERR_MODEL;

    R = resolved->earth_radius_km;
    x = R / (R + h_km);
    s = OI_SQRT(h_km) * OI_SQRT(OI_R(2.0) * R + h_km); /* no overflow for huge h */
    if (t != NULL && table_phi(t, theta, cos_theta, sin_theta, x, s, R, phi, psi))
        return OI_OK;

    /* Lambert far field: explicit model, no table, or outside its range */
    *phi = x * x * oi_lambert_phase(theta);
    *psi = (oi_real)0;
    return resolved->earth_model == OI_EARTH_LAMBERT ? OI_OK : OI_WARN_TABLE_RANGE;
}
