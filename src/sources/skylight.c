/* SPDX-License-Identifier: MIT */
/* skylight.c: the scattered-sunlight table's lookup (oi_skylight, OI_TERM_SKY)
 * and the check of a caller's table. */
#include "sources/sources_internal.h"
#include "oi_tables_internal.h"

#ifndef OI_NO_SKYLIGHT

/* Largest grid a caller's table may have (keeps every index an int). */
#define SKY_NODES_MAX 4096

/* 1 when x is within 1e-3 relative of want (both finite, want > 0). */
static int near_rel(oi_real x, oi_real want)
{
    return OI_ISFINITE(x) && OI_ISFINITE(want) && want > (oi_real)0 &&
           OI_FABS(x - want) <= OI_R(1e-3) * want;
}

int oi__sky_table_valid(const oi_sky_table *t)
{
    if (t->format != OI_SKY_FORMAT || t->kind != OI_TABLE_KIND_SKYLIGHT) return 0;
    if (t->n_theta < 4 || t->n_theta > SKY_NODES_MAX || t->n_alt < 4 ||
        t->n_alt > SKY_NODES_MAX)
        return 0;
    if (t->v == NULL || t->psi == NULL) return 0;
    if (!(t->q_floor > (oi_real)0 && t->q_floor <= (oi_real)1)) return 0;
    if (!(t->w_min > (oi_real)0 && t->w_min < t->w_max && t->w_max <= OI_HALF_PI_R))
        return 0;
    if (!(t->earth_radius_km >= (oi_real)OI_MODEL_RADIUS_MIN &&
          t->earth_radius_km <= (oi_real)OI_MODEL_RADIUS_MAX))
        return 0;
    if (!(t->top_km > (oi_real)0 && t->top_km <= OI_R(1000.0))) return 0;
    return near_rel(t->theta_scale, (oi_real)(t->n_theta - 1) / OI_PI_R) &&
           near_rel(t->w_scale, (oi_real)(t->n_alt - 1) / (t->w_max - t->w_min));
}

/* Column k of row j of arr, with the ghost columns mirrored about theta = 0
 * and pi (v even, psi odd: sign -1). */
static oi_real column(const float *arr, int n_theta, int j, int k, oi_real sign)
{
    if (k < 0) return sign * (oi_real)arr[j * n_theta - k];
    if (k > n_theta - 1) return sign * (oi_real)arr[j * n_theta + 2 * (n_theta - 1) - k];
    return (oi_real)arr[j * n_theta + k];
}

/* Row j of arr at angle th (Catmull-Rom), th reflected into [0, pi] first:
 * v is even about 0 and pi, psi odd, so the reflection is the function's own
 * smooth continuation. |th| stays below 2 pi (the shift is at most 2 rows). */
static oi_real row_at(const oi_sky_table *t, const float *arr, oi_real sign, int j, oi_real th)
{
    oi_real a, wt[4], out = (oi_real)0, flip = (oi_real)1;
    int i, k;
    if (th < (oi_real)0) {
        th = -th;
        flip = sign;
    } else if (th > OI_PI_R) {
        th = OI_R(2.0) * OI_PI_R - th;
        flip = sign;
    }
    i = oi__cell_clamped(th * t->theta_scale, t->n_theta, &a);
    oi__cr_weights(a, wt);
    for (k = 0; k < 4; k++) out += wt[k] * column(arr, t->n_theta, j, i - 1 + k, sign);
    return flip * out;
}

/* Catmull-Rom in w over rows j - 1 .. j + 2 (weights ww; ghost rows
 * extrapolated linearly), each row read at theta shifted along the shadow
 * edge: the edge lies near theta = pi/2 + w, so row j + m - 1 is read at
 * theta + s (m - 1 - b) / w_scale with s = (1 - cos theta) / 2 (1 at the
 * anti-solar point, 0 at the sub-solar point, where nothing moves with w).
 * At a row (b = 0) the shift of that row is 0: the lookup hits the nodes. */
static oi_real interp2(const oi_sky_table *t, const float *arr, oi_real sign, oi_real theta,
                       int j, oi_real b, const oi_real ww[4])
{
    oi_real row[4];
    const oi_real shear = OI_R(0.5) * ((oi_real)1 - OI_COS(theta)) / t->w_scale;
    int m;
    for (m = 0; m < 4; m++) {
        const int jj = j - 1 + m;
        row[m] = (oi_real)0;
        if (jj < 0 || jj > t->n_alt - 1) continue;
        row[m] = row_at(t, arr, sign, jj, theta + shear * ((oi_real)(m - 1) - b));
    }
    if (j - 1 < 0) row[0] = OI_R(2.0) * row[1] - row[2];
    if (j + 2 > t->n_alt - 1) row[3] = OI_R(2.0) * row[2] - row[1];
    return ww[0] * row[0] + ww[1] * row[1] + ww[2] * row[2] + ww[3] * row[3];
}

/*
 * E_sky / E_sun and psi from table t (valid or trusted) at theta in [0, pi]
 * and the target's distance r_km from the Earth's centre. Returns
 * OI_WARN_TABLE_RANGE below the first row (read there), else OI_OK.
 */
int oi__sky_lookup(const oi_sky_table *t, oi_real theta, oi_real r_km, oi_real *e_over_sun,
                   oi_real *psi)
{
    oi_real x, w, fw, b, ww[4], v, q;
    int j, st = OI_OK;
    x = t->earth_radius_km / r_km;
    if (!(x < (oi_real)1)) x = (oi_real)1;
    /* w = acos(x) without cancellation near x = 1 */
    w = OI_ATAN2(OI_SQRT(((oi_real)1 - x) * ((oi_real)1 + x)), x);
    if (w < t->w_min) st = OI_WARN_TABLE_RANGE;
    fw = (w - t->w_min) * t->w_scale;
    j = oi__cell_clamped(fw, t->n_alt, &b);
    oi__cr_weights(b, ww);
    v = interp2(t, t->v, (oi_real)1, theta, j, b, ww);
    /* v is at most ln(1 + q_floor) for any q <= 1 node: no overflow */
    q = OI_EXP(v) - t->q_floor;
    if (!(q > (oi_real)0)) q = (oi_real)0;
    *e_over_sun = q * x * x;
    *psi = q > (oi_real)0 ? interp2(t, t->psi, (oi_real)-1, theta, j, b, ww) : (oi_real)0;
    return st;
}

/* The table a resolved model uses: its own (checked) or the default; *t
 * NULL when there is none. OI_ERR_MODEL for an invalid caller's table. */
int oi__sky_table_of(const oi_model *m, const oi_sky_table **t)
{
    if (m->sky_table != NULL) {
        if (!oi__sky_table_valid(m->sky_table)) {
            *t = NULL;
            return OI_ERR_MODEL;
        }
        *t = m->sky_table;
        return OI_OK;
    }
    *t = oi_sky_table_default();
    return OI_OK;
}

int oi_skylight(oi_real theta_rad, oi_real h_km, const oi_model *model, oi_real *e_over_sun,
                oi_real *psi_rad)
{
    oi_model m;
    const oi_sky_table *t;
    int st;
    if (e_over_sun == NULL || psi_rad == NULL) {
        if (e_over_sun != NULL) *e_over_sun = (oi_real)0;
        if (psi_rad != NULL) *psi_rad = (oi_real)0;
        return OI_ERR_NULL;
    }
    *e_over_sun = (oi_real)0;
    *psi_rad = (oi_real)0;
    st = oi__model_resolve(model, &m);
    if (st < 0) return st;
    if (!OI_ISFINITE(theta_rad) || !OI_ISFINITE(h_km)) return OI_ERR_NONFINITE;
    if (theta_rad < (oi_real)0 || theta_rad > OI_PI_R || h_km < (oi_real)0) return OI_ERR_INPUT;
    if (h_km > (oi_real)OI_POSITION_MAX_KM) h_km = (oi_real)OI_POSITION_MAX_KM;
    st = oi__sky_table_of(&m, &t);
    if (st < 0 || t == NULL) return st;
    st = oi__sky_lookup(t, theta_rad, m.earth_radius_km + h_km, e_over_sun, psi_rad);
    return st;
}

#endif /* OI_NO_SKYLIGHT */
