/* SPDX-License-Identifier: MIT */
/* earthshine_albedo.c: earthshine under a non-uniform albedo field, the
 * weighted mean albedo of the lit visible cap and the field's change of the
 * mean direction and of a sphere's reflection, from a fixed cubature (the
 * zonal model) or the map's patches used as a control variate on the
 * uniform tables (docs/earthshine-albedo.md). */
#include "sources/sources_internal.h"

#ifndef OI_NO_ALBEDO_MODELS

#define HALF_PI_R ((oi_real)(0.5 * OI_PI))

/* Gauss-Legendre nodes (positive half) and weights on [-1, 1] of 8 and 16
 * points (Abramowitz & Stegun 1964, table 25.4; the digits of numpy's
 * polynomial.legendre.leggauss; the rules' exactness on polynomials is
 * tested through the uniform sphere, tests/python/test_albedo_models.py). */
#define N_E 8
static const oi_real gl8_x[N_E / 2] = {OI_R(0.18343464249564978), OI_R(0.52553240991632899),
                                       OI_R(0.79666647741362673), OI_R(0.96028985649753618)};
static const oi_real gl8_w[N_E / 2] = {OI_R(0.36268378337836166), OI_R(0.31370664587788688),
                                       OI_R(0.22238103445337443), OI_R(0.10122853629037706)};
#define N_B 16
static const oi_real gl16_x[N_B / 2] = {
    OI_R(0.095012509837637441), OI_R(0.28160355077925892), OI_R(0.45801677765722737),
    OI_R(0.61787624440264377), OI_R(0.755404408355003), OI_R(0.86563120238783176),
    OI_R(0.9445750230732326), OI_R(0.98940093499164994)};
static const oi_real gl16_w[N_B / 2] = {
    OI_R(0.18945061045506864), OI_R(0.18260341504492364), OI_R(0.16915651939500265),
    OI_R(0.14959598881657671), OI_R(0.12462897125553407), OI_R(0.095158511682492605),
    OI_R(0.062253523938647456), OI_R(0.027152459411754176)};
/* A rule: Gauss-Legendre of n nodes (the positive half x, w) in the
 * emission angle and in each azimuth segment, and ring azimuths of the
 * periodic trapezoid rule over a fully lit cap. The Knocke field is a
 * quadratic in the height above the equator and needs few (a map's bilinear
 * patches, with kinks along every row and column of centres, are
 * integrated one by one instead). */
typedef struct rule {
    const oi_real *ex, *ew, *bx, *bw;
    int ne, nb, ring;
} rule;
static const rule rule_smooth = {gl8_x, gl8_w, gl16_x, gl16_w, N_E, N_B, 32};

/* node k of an n-point rule from its positive half */
static oi_real node_x(const oi_real *x, int n, int k)
{
    return k < n / 2 ? -x[n / 2 - 1 - k] : x[k - n / 2];
}
static oi_real node_w(const oi_real *w, int n, int k)
{
    return k < n / 2 ? w[n / 2 - 1 - k] : w[k - n / 2];
}

typedef oi__albedo_sums sums;

/* The geometry fixed for one call: the local frame (r the zenith, ex
 * towards the Sun's side, ey normal), theta's cosine and sine, x = R / r
 * and the cap's half-angle w. */
typedef struct frame {
    oi_real r[3], ex[3], ey[3];
    oi_real cos_t, sin_t, x, w;
    const oi_real *obs;
    oi_real a_ref;
    const rule *q;
} frame;

/* emission angle (from the surface normal towards the target) of the cap
 * point at central angle alpha from the sub-target point, given its cosine
 * and sine */
static oi_real emission(const frame *g, oi_real alpha, oi_real ca, oi_real sa)
{
    return alpha + OI_ATAN2(g->x * sa, (oi_real)1 - g->x * ca);
}

/* One azimuth beta (cosine cb, sine sb) of weight wb: the lit part of its
 * great circle through the cap, in emission angle, by Gauss-Legendre. */
static int ray_fan(const oi__albedo_field *f, const frame *g, oi_real cb, oi_real sb, oi_real wb,
                   sums *acc)
{
    const oi_real b = g->sin_t * cb;
    const oi_real c = OI_SQRT(g->cos_t * g->cos_t + b * b);
    oi_real delta, lo, hi, e_lo, e_hi, mid, half, u[3];
    int k, i;
    if (!(c > (oi_real)0)) return OI_OK;
    /* lit where cos(alpha) cos(theta) + sin(alpha) cos(beta) sin(theta) >= 0,
     * i.e. |alpha - delta| <= pi/2, alpha in [0, w] */
    delta = OI_ATAN2(b, g->cos_t);
    lo = delta - HALF_PI_R;
    hi = delta + HALF_PI_R;
    if (lo <= (oi_real)0) {
        lo = (oi_real)0;
        e_lo = (oi_real)0;
    } else {
        /* cos(lo) = sin(delta), sin(lo) = -cos(delta) */
        e_lo = emission(g, lo, b / c, -g->cos_t / c);
    }
    if (hi >= g->w) {
        hi = g->w;
        e_hi = HALF_PI_R; /* the horizon */
    } else {
        e_hi = emission(g, hi, -b / c, g->cos_t / c);
    }
    if (!(hi > lo) || !(e_hi > e_lo)) return OI_OK;
    mid = OI_R(0.5) * (e_lo + e_hi);
    half = OI_R(0.5) * (e_hi - e_lo);
    for (i = 0; i < 3; i++) u[i] = cb * g->ex[i] + sb * g->ey[i];
    for (k = 0; k < g->q->ne; k++) {
        const oi_real t = node_x(g->q->ex, g->q->ne, k);
        const oi_real wt = node_w(g->q->ew, g->q->ne, k);
        oi_real se, ce, sh, ch, ca, sa, ci, kw, a, da, p[3], om[3];
        int st;
        OI_SINCOS(mid + half * t, &se, &ce);
        sh = g->x * se; /* sin(eta), eta the nadir angle of the ray */
        ch = OI_SQRT(((oi_real)1 - sh) * ((oi_real)1 + sh));
        ca = ce * ch + se * sh; /* alpha = e - eta */
        sa = se * ch - ce * sh;
        ci = ca * g->cos_t + sa * cb * g->sin_t; /* cosine of the Sun's incidence */
        if (!(ci > (oi_real)0)) continue;
        /* scalar irradiance: radiance cos(i) over the solid angle
         * sin(eta) d eta d beta, d eta = x cos(e) / cos(eta) de */
        kw = wb * half * wt * ci * sh * g->x * ce / ch;
        for (i = 0; i < 3; i++) {
            p[i] = ca * g->r[i] + sa * u[i];
            om[i] = sh * u[i] - ch * g->r[i];
        }
        st = oi__albedo_at(f, p, &a);
        if (st < 0) return st;
        da = a - g->a_ref;
        acc->s0 += kw;
        acc->s1 += kw * da;
        for (i = 0; i < 3; i++) {
            acc->w[i] += kw * om[i];
            acc->v[i] += kw * da * om[i];
        }
        if (da != (oi_real)0) acc->varies = 1;
        if (g->obs != NULL) {
            oi_real cr[3], sx, cx, ph;
            oi__cross(om, g->obs, cr);
            sx = oi__norm_bounded(cr);
            cx = oi__dot(om, g->obs);
            ph = oi__lambert_phase_cs(OI_ATAN2(sx, cx), cx, sx);
            acc->q += kw * ph;
            acc->p += kw * da * ph;
        }
    }
    return OI_OK;
}

/* Gauss-Legendre over the azimuths [b0, b1]. */
static int azimuth_segment(const oi__albedo_field *f, const frame *g, oi_real b0, oi_real b1,
                           sums *acc)
{
    const oi_real mid = OI_R(0.5) * (b0 + b1), half = OI_R(0.5) * (b1 - b0);
    int k;
    for (k = 0; k < g->q->nb; k++) {
        const oi_real t = node_x(g->q->bx, g->q->nb, k);
        const oi_real wt = node_w(g->q->bw, g->q->nb, k);
        oi_real sb, cb;
        int st;
        OI_SINCOS(mid + half * t, &sb, &cb);
        st = ray_fan(f, g, cb, sb, half * wt, acc);
        if (st < 0) return st;
    }
    return OI_OK;
}

/* The local frame; ex along the Sun's side (any normal on the Sun-Earth axis). */
static void local_frame(const oi_real r_hat[3], const oi_real s_hat[3], frame *g)
{
    oi_real t[3];
    int i;
    g->cos_t = oi__dot(s_hat, r_hat);
    for (i = 0; i < 3; i++) {
        g->r[i] = r_hat[i];
        t[i] = s_hat[i] - g->cos_t * r_hat[i];
    }
    /* near the Sun-Earth axis t is rounding noise that need not be normal to
     * r: orthogonalised once more after scaling (the cap is then lit all
     * round, so any normal does) */
    if (oi__unit_bounded(t, t) > (oi_real)0) {
        const oi_real dr = oi__dot(t, r_hat);
        for (i = 0; i < 3; i++) t[i] -= dr * r_hat[i];
    }
    if (oi__unit_bounded(t, t) == (oi_real)0) {
        const oi_real e[3] = {(oi_real)1, (oi_real)0, (oi_real)0};
        const oi_real n[3] = {(oi_real)0, (oi_real)1, (oi_real)0};
        oi__cross(r_hat, (r_hat[0] * r_hat[0] < OI_R(0.5)) ? e : n, t);
        (void)oi__unit_bounded(t, t);
    }
    for (i = 0; i < 3; i++) g->ex[i] = t[i];
    oi__cross(r_hat, t, g->ey);
    g->sin_t = oi__dot(s_hat, t);
    if (g->sin_t < (oi_real)0) g->sin_t = (oi_real)0;
}

/* The zonal field's sums by the cubature, added to job->acc; a frame of its
 * own, so that a map's deeper chain does not carry it (make stack). */
static OI_NOINLINE int cubature(oi__albedo_job *job)
{
    const oi__albedo_field *f = &job->f;
    const oi_real x = job->x;
    sums *acc = &job->acc;
    frame g;
    oi_real sin_w;
    int st = OI_OK;
    local_frame(job->r_hat, job->s_hat, &g);
    g.x = x;
    sin_w = OI_SQRT(((oi_real)1 - x) * ((oi_real)1 + x));
    g.w = OI_ATAN2(sin_w, x);
    g.obs = job->has_obs ? job->obs_hat : NULL;
    g.q = &rule_smooth;
    g.a_ref = job->a_ref;
    if (g.cos_t >= sin_w) {
        /* the whole cap is lit: a smooth periodic integrand in beta */
        const oi_real step = OI_R(2.0) * OI_PI_R / (oi_real)g.q->ring;
        int k;
        for (k = 0; k < g.q->ring; k++) {
            oi_real sb, cb;
            OI_SINCOS(step * (oi_real)k, &sb, &cb);
            st = ray_fan(f, &g, cb, sb, step, acc);
            if (st < 0) return st;
        }
    } else if (g.cos_t > -sin_w) {
        /* the terminator crosses the cap: it meets the horizon at the
         * azimuths +-beta_k, cos(beta_k) = -x cos(theta) / (sin(w) sin(theta));
         * the lit length changes its law there, so each side is a segment */
        oi_real ck = g.sin_t > (oi_real)0 ? -x * g.cos_t / (sin_w * g.sin_t) : (oi_real)0;
        oi_real bk;
        if (ck > (oi_real)1) ck = (oi_real)1;
        if (ck < (oi_real)-1) ck = (oi_real)-1;
        bk = OI_ATAN2(OI_SQRT(((oi_real)1 - ck) * ((oi_real)1 + ck)), ck);
        st = azimuth_segment(f, &g, -bk, bk, acc);
        if (st == OI_OK && g.cos_t > (oi_real)0)
            st = azimuth_segment(f, &g, bk, OI_R(2.0) * OI_PI_R - bk, acc);
    }
    return st;
}

/* The field's change of the mean direction and of the sphere's shape from
 * the sums (d the mean albedo less the reference, den the mean albedo times
 * the sum of weights). */
static OI_NOINLINE void moments(const oi__albedo_job *job, oi_real d, oi_real den, oi_real dir[3],
                                oi_real *shape_add)
{
    const oi__albedo_sums *acc = &job->acc;
    oi_real m[3], len;
    int i;
    /* mean direction: the uniform one at the cubature's length, plus the
     * field's first moment sum((a - mean) K omega) / (mean sum K) */
    len = oi__norm_bounded(acc->w) / acc->s0;
    for (i = 0; i < 3; i++) m[i] = len * dir[i] + (acc->v[i] - d * acc->w[i]) / den;
    if (oi__unit_bounded(m, m) > (oi_real)0)
        for (i = 0; i < 3; i++) dir[i] = m[i];
    if (job->has_obs) {
        const oi_real add = (acc->p - d * acc->q) / den;
        if (OI_ISFINITE(add)) *shape_add = add;
    }
}

int oi__albedo_integrate(oi__albedo_job *job)
{
    const int st = oi__albedo_at(&job->f, job->r_hat, &job->a_ref);
    if (st < 0) return st;
    memset(&job->acc, 0, sizeof job->acc);
    /* a map: its bilinear patches one by one (src/sources/earthshine_albedo_map.c) */
    return job->f.model == OI_ALBEDO_MAP ? oi__earthshine_map_cells(job) : cubature(job);
}

void oi__albedo_mean(const oi__albedo_job *job, oi_real *albedo, oi_real dir[3],
                     oi_real *shape_add)
{
    const oi__albedo_sums *acc = &job->acc;
    oi_real d, den;

    *shape_add = (oi_real)0;
    /* nothing lit, or a uniform field where the cubature looked: the uniform
     * sphere's answer with the reference albedo, bit for bit */
    if (!(acc->s0 > (oi_real)0) || !acc->varies) {
        *albedo = job->a_ref;
        return;
    }
    d = acc->s1 / acc->s0; /* mean albedo less the reference */
    *albedo = job->a_ref + d;
    if (*albedo < (oi_real)0) *albedo = (oi_real)0;
    if (*albedo > (oi_real)1) *albedo = (oi_real)1;
    /* a mean albedo this small lights nothing measurable (e_earth below
     * 1e-12 of the uniform sphere's): the corrections, over mean sum K, would
     * only overflow (single precision: the product underflows to 0) */
    den = *albedo * acc->s0;
    if (!(*albedo > OI_R(1e-12)) || !(den > (oi_real)0)) return;
    moments(job, d, den, dir, shape_add);
}

#else
typedef int oi__earthshine_albedo_compiled_out; /* ISO C: no empty translation unit */
#endif /* OI_NO_ALBEDO_MODELS */
