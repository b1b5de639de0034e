/* SPDX-License-Identifier: MIT */
/* earthshine_angular.c: the flux a Lambertian sphere sends to an observer
 * under earthshine, from the angular table's moments (oi_earth_angular_table,
 * include/oi_table.h; docs/earthshine-angular.md), and oi_earthshine_sphere. */
#include "oi_tables_internal.h"

#ifndef OI_NO_EARTH_ANGULAR
#ifndef OI_NO_EARTH_TABLE

/* Coefficients per node at OI_ANGULAR_L_MAX = 8 (degrees 0, 1, 2, 4, 6, 8). */
#define NC_MAX 27

/* Offset of degree l's coefficients in a node (stored: 0, 1 and even l). */
static const signed char degree_offset[OI_ANGULAR_L_MAX + 1] = {0, 1, 3, -1, 6, -1, 11, -1, 18};

/* s_l (2l + 1) / (4 pi): the Legendre coefficients of the Lambert phase
 * function p(acos mu) = sum a_l P_l(mu) over the stored degrees. s_l = A_l^2
 * / pi with A_l the clamped cosine's (pi, 2 pi / 3, pi / 4, -pi / 24, pi / 64,
 * -pi / 128 for l = 0, 1, 2, 4, 6, 8: Ramamoorthi & Hanrahan 2001):
 * exact rationals, checked against the baker's quadrature of p in
 * tests/python/test_earth_angular.py. */
static const oi_real phase_legendre[OI_ANGULAR_L_MAX + 1] = {
    OI_R(0.25), OI_R(1.0) / OI_R(3.0), OI_R(5.0) / OI_R(64.0), OI_R(0.0),
    OI_R(9.0) / OI_R(2304.0), OI_R(0.0), OI_R(13.0) / OI_R(16384.0), OI_R(0.0),
    OI_R(17.0) / OI_R(65536.0)};

/* Catmull-Rom stencil on n >= 2 nodes at fractional index f, ghosts folded
 * by linear extrapolation: up to 6 (index, weight) pairs. */
static int stencil(oi_real f, int n, int idx[6], oi_real wt[6])
{
    oi_real frac, w4[4];
    int i, k, c = 0;
    const int cell = oi__cell_clamped(f, n, &frac);
    oi__cr_weights(frac, w4);
    for (k = 0; k < 4; k++) {
        i = cell - 1 + k;
        if (i < 0) {
            idx[c] = 0; wt[c++] = OI_R(2.0) * w4[k];
            idx[c] = 1; wt[c++] = -w4[k];
        } else if (i > n - 1) {
            idx[c] = n - 1; wt[c++] = OI_R(2.0) * w4[k];
            idx[c] = n - 2; wt[c++] = -w4[k];
        } else {
            idx[c] = i; wt[c++] = w4[k];
        }
    }
    return c;
}

/* sum over the stored (l, m) of c_lm Re((x + i y)^m) d^m P_l / dz^m (z),
 * m outer so that no table of Legendre values is kept. */
static oi_real series(const oi_real *c, int l_max, const oi_real o[3])
{
    oi_real sum = (oi_real)0, re = (oi_real)1, im = (oi_real)0, qmm = (oi_real)1;
    int m, l;
    for (m = 0; m <= l_max; m++) {
        oi_real q0, q1, q2;
        if (m > 0) {
            const oi_real r = re * o[0] - im * o[1];
            im = re * o[1] + im * o[0];
            re = r;
            qmm *= (oi_real)(2 * m - 1);
        }
        q1 = qmm;             /* Q_m^m */
        q0 = (oi_real)0;
        for (l = m; l <= l_max; l++) {
            if (l > m) {
                q2 = l == m + 1 ? o[2] * (oi_real)(2 * m + 1) * q1
                                : ((oi_real)(2 * l - 1) * o[2] * q1 -
                                   (oi_real)(l + m - 1) * q0) / (oi_real)(l - m);
                q0 = q1;
                q1 = q2;
            }
            if (degree_offset[l] >= 0) sum += c[degree_offset[l] + m] * re * q1;
        }
    }
    return sum;
}

/* p(acos mu) truncated to the stored degrees (Legendre recurrence). */
static oi_real truncated_phase(oi_real mu, int l_max)
{
    oi_real p0 = (oi_real)1, p1 = mu, sum = phase_legendre[0] + phase_legendre[1] * mu;
    int l;
    for (l = 2; l <= l_max; l++) {
        const oi_real p2 = ((oi_real)(2 * l - 1) * mu * p1 - (oi_real)(l - 1) * p0) / (oi_real)l;
        p0 = p1;
        p1 = p2;
        sum += phase_legendre[l] * p1;
    }
    return sum;
}

/* The shape S(o) = F / phi of the sphere's flux at (theta, h) towards the
 * unit local direction o, from table t: 1 when the table serves the
 * altitude (*shape set, >= 0), 0 below its first row. */
int oi__earth_sphere_shape(const oi_earth_angular_table *t, oi_real theta, oi_real cos_theta,
                           oi_real sin_theta, oi_real h_km, oi_real R, const oi_real o[3],
                           oi_real *shape)
{
    oi_real c[NC_MAX + 1], wr[6], wc[6], w, s, beta, sum;
    int ir[6], ic[6], nr, nk, k, a, b;
    const int nt = t->n_lit + t->n_term, nc = t->n_coef;
    const oi_real w_min = (oi_real)t->w_min, w_max = (oi_real)t->w_max;

    *shape = (oi_real)0;
    s = OI_SQRT(h_km) * OI_SQRT(OI_R(2.0) * R + h_km);
    w = OI_ATAN2(s, R);
    if (w < w_min) return 0;
    if (theta >= OI_HALF_PI_R + w) return 1; /* nothing lit is visible: phi = 0 */

    nr = stencil((w - w_min) / (w_max - w_min) * (oi_real)(t->n_alt - 1), t->n_alt, ir, wr);
    if (theta <= OI_HALF_PI_R - w) {
        /* lit: the shape is linear in tan(theta) (include/oi_table.h) */
        const oi_real u = cos_theta > (oi_real)0 ? sin_theta * s / (cos_theta * R) : (oi_real)1;
        ic[0] = 0; wc[0] = (oi_real)1 - u;
        ic[1] = 1; wc[1] = u;
        nk = 2;
    } else {
        const oi_real f = (theta - OI_HALF_PI_R + w) / (OI_R(2.0) * w);
        nk = stencil(f * (oi_real)(t->n_term - 1), t->n_term, ic, wc);
        for (k = 0; k < nk; k++) ic[k] += t->n_lit;
    }
    /* every slot zeroed, not only the table's: the series reads the slots of
     * the degrees it sums, which a table with fewer coefficients leaves 0 */
    for (k = 0; k <= NC_MAX; k++) c[k] = (oi_real)0;
    for (a = 0; a < nr; a++)
        for (b = 0; b < nk; b++) {
            const unsigned short *node = t->code + ((long)ir[a] * nt + ic[b]) * (nc + 1);
            const oi_real wt = wr[a] * wc[b];
            for (k = 0; k <= nc; k++) c[k] += wt * (oi_real)node[k];
        }
    /* the weights sum to 1: the linear decoding commutes with them */
    for (k = 0; k <= nc; k++) c[k] = (oi_real)t->offset[k] + (oi_real)t->scale[k] * c[k];
    sum = series(c, t->l_max, o);
    beta = c[nc];
    if (beta != (oi_real)0) {
        /* the mean direction d from the l = 1 moments, d = (c_11, 0, c_10) */
        oi_real d[3], x[3], mu, sn;
        d[0] = c[2];
        d[1] = (oi_real)0;
        d[2] = c[1];
        if (oi__unit_bounded(d, d) > (oi_real)0) {
            oi__cross(o, d, x);
            sn = oi__norm_bounded(x);
            mu = oi__dot(o, d);
            sum += beta * (oi__lambert_phase_cs(OI_ATAN2(sn, mu), mu, sn) -
                           truncated_phase(mu, t->l_max));
        }
    }
    *shape = sum > (oi_real)0 ? sum : (oi_real)0;
    return 1;
}

#endif /* OI_NO_EARTH_TABLE */
#endif /* OI_NO_EARTH_ANGULAR */

/* The angular table a resolved model uses, or NULL (mean direction). */
const oi_earth_angular_table *oi__earth_angular_of(const oi_model *m)
{
#if defined(OI_NO_EARTH_ANGULAR) || defined(OI_NO_EARTH_TABLE)
    (void)m;
    return (const oi_earth_angular_table *)0;
#else
    if (m->earth_reflection != OI_EARTH_REFLECT_MOMENTS || m->earth_model != OI_EARTH_TABLE)
        return (const oi_earth_angular_table *)0;
    return oi_earth_angular_default();
#endif
}

/* oi_earthshine_sphere: contract in include/orbillum.h. */
int oi_earthshine_sphere(oi_real theta, oi_real h_km, const oi_real obs[3],
                         const oi_model *model, oi_real *flux)
{
    oi_model m;
    oi_real o[3], phi, psi, cs, sn;
    int st;
    const oi_earth_angular_table *t;

    if (flux != NULL) *flux = (oi_real)0;
    if (flux == NULL || obs == NULL) return OI_ERR_NULL;
    st = oi__model_resolve(model, &m);
    if (st < 0) return st;
    if (!oi__finite3(obs)) return OI_ERR_NONFINITE;
    if (!OI_ISFINITE(theta) || !OI_ISFINITE(h_km)) return OI_ERR_NONFINITE;
    if (theta < (oi_real)0) theta = (oi_real)0;
    if (theta > OI_PI_R) theta = OI_PI_R;
    OI_SINCOS(theta, &sn, &cs);
    st = oi__earthshine(theta, cs, sn, h_km, &m, &phi, &psi);
    if (st < 0) return st;
    if (oi__unit(obs, o) == (oi_real)0) return OI_ERR_ZERO_VECTOR;
    t = oi__earth_angular_of(&m);
#if !defined(OI_NO_EARTH_ANGULAR) && !defined(OI_NO_EARTH_TABLE)
    if (t != NULL) {
        oi_real shape;
        if (oi__earth_sphere_shape(t, theta, cs, sn, h_km, m.earth_radius_km, o, &shape)) {
            *flux = phi * shape;
            return st;
        }
    }
#else
    (void)t;
#endif
    {
        /* the mean direction: (sin psi, 0, -cos psi) in the local frame */
        oi_real d[3], x[3], c, s;
        OI_SINCOS(psi, &s, &c);
        d[0] = s;
        d[1] = (oi_real)0;
        d[2] = -c;
        oi__cross(o, d, x);
        s = oi__norm_bounded(x);
        c = oi__dot(o, d);
        *flux = phi * oi__lambert_phase_cs(OI_ATAN2(s, c), c, s);
    }
    return st;
}
