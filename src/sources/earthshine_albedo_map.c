/* SPDX-License-Identifier: MIT */
/* earthshine_albedo_map.c: the earthshine sums under a caller's albedo map,
 * integrated patch by patch of its bilinear field over the lit visible cap
 * (docs/earthshine-albedo.md, "Maps: cell by cell"). */
#include "sources/sources_internal.h"

#ifndef OI_NO_ALBEDO_MODELS

#define FULL_TURN (OI_R(2.0) * OI_PI_R)
/* An interval spans at most GRADE times the kernel's local scale (the
 * distance from the nadir plus the altitude, at most one radian): the
 * nadir's peak is graded geometrically, the rest cut by the field's
 * patches. Below FINE times the scale two Gauss nodes suffice, else four. */
#define GRADE OI_R(0.5)
#define FINE OI_R(0.15)
/* Below VFINE times the scale one node (the midpoint) per piece: its error
 * is first order in the piece over the scale within a piece but cancels
 * between neighbours (the field is continuous), leaving the second order
 * over the whole cap (measured, docs/earthshine-albedo.md). */
#define VFINE OI_R(0.03)
/* Bound of the steps of one walk: every patch edge (a dimension is at most
 * OI_ALBEDO_MAP_MAX_DIM) and the grading (at most ~2 log(pi / h) / log 1.5
 * steps, 150 at h = 1e-12 Earth radii) with margin. */
#define MAX_STEPS (OI_ALBEDO_MAP_MAX_DIM + 512)

/* GCC and clang: the node folded into its row's frame (one frame's saved
 * registers instead of two; make stack) */
#if defined(__GNUC__)
#define NODE_INLINE __attribute__((always_inline)) inline
#else
#define NODE_INLINE inline
#endif

/* Gauss-Legendre of 1, 2 and 4 nodes on [-1, 1] (Abramowitz & Stegun 1964,
 * table 25.4: 1 / sqrt(3); the 4-point nodes and weights), one table so
 * that each walk has one loop. */
#define GL2_X OI_R(0.57735026918962576)
#define GL4_X0 OI_R(0.33998104358485626)
#define GL4_X1 OI_R(0.86113631159405258)
#define GL4_W0 OI_R(0.65214515486254614)
#define GL4_W1 OI_R(0.34785484513745386)
static const oi_real gl_x[7] = {(oi_real)0, -GL2_X, GL2_X, -GL4_X1, -GL4_X0, GL4_X0, GL4_X1};
static const oi_real gl_w[7] = {OI_R(2.0), OI_R(1.0), OI_R(1.0), GL4_W1, GL4_W0, GL4_W0, GL4_W1};

/* The rule of a piece of length len where the kernel's scale is at least
 * smin: its first node in gl_x and its count. */
static int rule_of(oi_real len, oi_real smin, int *n)
{
    if (len <= VFINE * smin) {
        *n = 1;
        return 0;
    }
    if (len <= FINE * smin) {
        *n = 2;
        return 1;
    }
    *n = 4;
    return 3;
}

/* The geometry in the Earth-fixed frame (x towards Greenwich, z the
 * rotation axis): target, Sun and observer directions (the job's own
 * arrays, turned into that frame), 1 / x the target's distance in Earth
 * radii and h its altitude, the nadir's colatitude and longitude. */
typedef struct cells {
    const oi__albedo_field *f;
    const oi_real *r, *s, *o;
    oi_real rt, x, h;
    oi_real c_r, lam_r;
    oi_real a_ref;
    int has_obs;
} cells;

/* Earth-fixed from the scene's frame (in place), and back. */
static void to_fixed(const oi__albedo_field *f, oi_real v[3])
{
    const oi_real x = f->cos_rot * v[0] + f->sin_rot * v[1];
    v[1] = f->cos_rot * v[1] - f->sin_rot * v[0];
    v[0] = x;
}
static void from_fixed(const oi__albedo_field *f, oi_real v[3])
{
    const oi_real x = f->cos_rot * v[0] - f->sin_rot * v[1];
    v[1] = f->sin_rot * v[0] + f->cos_rot * v[1];
    v[0] = x;
}

/* The longitudes where a cos(lam - centre) >= b (a >= 0) on a row: the arc
 * [*start, *start + *len], len in [0, 2 pi]; 0 when it is empty. */
static int arc(oi_real a, oi_real b, oi_real centre, oi_real *start, oi_real *len)
{
    oi_real k, half;
    if (!(a > (oi_real)0)) {
        if (!(b <= (oi_real)0)) return 0;
        *start = centre - OI_PI_R;
        *len = FULL_TURN;
        return 1;
    }
    k = b / a;
    if (!(k < (oi_real)1)) return 0;
    if (k <= (oi_real)-1) {
        *start = centre - OI_PI_R;
        *len = FULL_TURN;
        return 1;
    }
    half = OI_ATAN2(OI_SQRT(((oi_real)1 - k) * ((oi_real)1 + k)), k);
    *start = centre - half;
    *len = OI_R(2.0) * half;
    return 1;
}

/* One row's value of the map at cell (i, j), checked (NaN fails). */
static int value(const oi__albedo_field *f, int i, int j, oi_real *v)
{
    const float a = f->map[(long)i * f->n_lon + j];
    *v = (oi_real)a;
    return a >= 0.0f && a <= 1.0f;
}

/* One longitude node of weight wt on the row (sin c, cos c) of the bilinear
 * patch (v00 .. v11, ti): the kernel K = cos(i) cos(e) / d^2 dA and its
 * moments. */
static NODE_INLINE void node(const cells *q, oi_real sc, oi_real cc, oi_real lam, oi_real wt, oi_real ti,
                 oi_real tj, const oi_real v[4], oi__albedo_sums *acc)
{
    /* p, once t is formed, holds the cross product, and t the unit
     * direction omega: fewer arrays live in the row's frame (make stack) */
    oi_real sl, cl, p[3], t[3], ci, ce, d2, d, kw, a, da;
    int i;
    OI_SINCOS(lam, &sl, &cl);
    p[0] = sc * cl;
    p[1] = sc * sl;
    p[2] = cc;
    ci = oi__dot(p, q->s);
    if (!(ci > (oi_real)0)) return;
    ce = q->rt * oi__dot(p, q->r) - (oi_real)1; /* p . (target - p), d cos(e) */
    if (!(ce > (oi_real)0)) return;
    for (i = 0; i < 3; i++) t[i] = p[i] - q->rt * q->r[i];
    d2 = oi__dot(t, t);
    d = OI_SQRT(d2);
    kw = wt * sc * ci * ce / (d2 * d);
    if (tj < (oi_real)0) tj = (oi_real)0;
    if (tj > (oi_real)1) tj = (oi_real)1;
    /* a map of one value gives that value exactly (every difference 0) */
    a = v[0] + ti * (v[2] - v[0]) + tj * (v[1] - v[0]) + ti * tj * ((v[3] - v[2]) - (v[1] - v[0]));
    da = a - q->a_ref;
    for (i = 0; i < 3; i++) t[i] = t[i] / d;
    acc->s0 += kw;
    acc->s1 += kw * da;
    for (i = 0; i < 3; i++) {
        acc->w[i] += kw * t[i];
        acc->v[i] += kw * da * t[i];
    }
    if (da != (oi_real)0) acc->varies = 1;
    if (q->has_obs) {
        oi_real sx, cx, ph;
        oi__cross(t, q->o, p);
        sx = oi__norm_bounded(p);
        cx = oi__dot(t, q->o);
        ph = oi__lambert_phase_cs(OI_ATAN2(sx, cx), cx, sx);
        acc->q += kw * ph;
        acc->p += kw * da * ph;
    }
}

/* The longitudes [l0, l1] of the row at colatitude c (sine sc, cosine cc),
 * weight wc, between the rows i0 and i1 of the map at the fraction ti: cut at
 * every column centre and graded towards the nadir's longitude. */
static int walk_row(const cells *q, oi_real c, oi_real sc, oi_real cc, oi_real wc, int i0, int i1,
                    oi_real ti, oi_real l0, oi_real l1, oi__albedo_sums *acc)
{
    const oi__albedo_field *f = q->f;
    const oi_real per = (oi_real)f->n_lon / FULL_TURN; /* columns per radian */
    const oi_real dc = OI_FABS(c - q->c_r);
    oi_real l = l0;
    int n;
    for (n = 0; n < MAX_STEPS && l < l1; n++) {
        oi_real u = l * per - OI_R(0.5), e, next, dl, base, s, mid, half, jf, v[4], len, smin;
        int j0, j1, k, k0, nk;
        /* the next column centre after l */
        next = (OI_FLOOR(u) + (oi_real)1 + OI_R(0.5)) / per;
        if (!(next > l)) next = (OI_FLOOR(u) + OI_R(2.5)) / per;
        e = next < l1 ? next : l1;
        /* grading: the longitude from the nadir's, in (-pi, pi] */
        dl = l - q->lam_r;
        dl -= FULL_TURN * OI_FLOOR(dl / FULL_TURN + OI_R(0.5));
        base = q->h + dc;
        if (dl < (oi_real)0) {
            /* towards the nadir: it is a break, and the step ends at no
             * more than GRADE times the scale there */
            const oi_real at = l - dl;
            if (at > l && at < e) e = at;
            s = GRADE * (base - sc * dl) / (sc * ((oi_real)1 + GRADE));
        } else {
            s = GRADE * (base + sc * dl) / sc;
        }
        if (GRADE / sc < s) s = GRADE / sc; /* the scale at most one radian */
        if (l + s < e) e = l + s;
        if (!(e > l)) e = l1; /* rounding: finish the row */
        mid = OI_R(0.5) * (l + e);
        half = OI_R(0.5) * (e - l);
        jf = OI_FLOOR(mid * per - OI_R(0.5));
        {
            oi_real jm = jf - (oi_real)f->n_lon * OI_FLOOR(jf / (oi_real)f->n_lon);
            j0 = (int)jm;
        }
        if (j0 < 0 || j0 >= f->n_lon) j0 = 0;
        j1 = j0 + 1 < f->n_lon ? j0 + 1 : 0;
        if (!value(f, i0, j0, &v[0]) || !value(f, i0, j1, &v[1]) || !value(f, i1, j0, &v[2]) ||
            !value(f, i1, j1, &v[3]))
            return OI_ERR_ALBEDO;
        /* Gauss order from the piece's length over the smallest scale in it */
        len = sc * (e - l);
        smin = base + sc * (dl < (oi_real)0 ? (-dl > (e - l) ? -dl - (e - l) : (oi_real)0) : dl);
        if (smin > (oi_real)1) smin = (oi_real)1;
        k0 = rule_of(len, smin, &nk);
        for (k = k0; k < k0 + nk; k++) {
            const oi_real lam = mid + half * gl_x[k];
            node(q, sc, cc, lam, wc * half * gl_w[k], ti, lam * per - OI_R(0.5) - jf, v, acc);
        }
        l = e;
    }
    return OI_OK;
}

/* One colatitude node c of weight wc: the lit visible longitudes of its row
 * (the intersection of two arcs, at most two intervals) walked; a frame of
 * its own (the walk's locals are not live during the colatitude loop's). */
static OI_NOINLINE int row(const cells *q, oi_real c, oi_real wc, oi__albedo_sums *acc)
{
    const oi__albedo_field *f = q->f;
    oi_real sc, cc, v0, vl, l0, ll, d, fi, ti, lo, hi;
    int i0, i1, k, st;
    OI_SINCOS(c, &sc, &cc);
    /* visible: p . r >= x; lit: p . s >= 0 */
    if (!arc(sc * OI_SQRT(q->r[0] * q->r[0] + q->r[1] * q->r[1]), q->x - cc * q->r[2], q->lam_r,
             &v0, &vl))
        return OI_OK;
    if (!arc(sc * OI_SQRT(q->s[0] * q->s[0] + q->s[1] * q->s[1]), -cc * q->s[2],
             OI_ATAN2(q->s[1], q->s[0]), &l0, &ll))
        return OI_OK;
    /* the rows of the map about c: constant poleward of the first and last
     * rows' centres */
    fi = c * ((oi_real)f->n_lat / OI_PI_R) - OI_R(0.5);
    if (!(fi > (oi_real)0)) fi = (oi_real)0;
    if (fi > (oi_real)(f->n_lat - 1)) fi = (oi_real)(f->n_lat - 1);
    i0 = (int)fi;
    if (i0 > f->n_lat - 1) i0 = f->n_lat - 1;
    ti = fi - (oi_real)i0;
    i1 = i0 + 1 < f->n_lat ? i0 + 1 : i0;
    if (!(ti >= (oi_real)0 && ti <= (oi_real)1)) ti = (oi_real)0;
    /* the lit arc relative to the visible one's start */
    d = l0 - v0;
    d -= FULL_TURN * OI_FLOOR(d / FULL_TURN);
    for (k = 0; k < 2; k++) {
        const oi_real a = d - (oi_real)k * FULL_TURN;
        lo = a > (oi_real)0 ? a : (oi_real)0;
        hi = a + ll < vl ? a + ll : vl;
        if (!(hi > lo)) continue;
        st = walk_row(q, c, sc, cc, wc, i0, i1, ti, v0 + lo, v0 + hi, acc);
        if (st < 0) return st;
    }
    return OI_OK;
}

int oi__earthshine_map_cells(oi__albedo_job *job)
{
    const oi__albedo_field *f = &job->f;
    const oi_real x = job->x;
    oi__albedo_sums *acc = &job->acc;
    cells q;
    oi_real w, c, c_lo, c_hi, c_s, t1, t2, row_h;
    int n, st;
    q.f = f;
    to_fixed(f, job->r_hat);
    to_fixed(f, job->s_hat);
    q.r = job->r_hat;
    q.s = job->s_hat;
    q.has_obs = job->has_obs;
    if (q.has_obs) to_fixed(f, job->obs_hat);
    q.o = job->obs_hat; /* read only with has_obs */
    q.x = x;
    q.rt = (oi_real)1 / x;
    q.h = ((oi_real)1 - x) / x;
    q.a_ref = job->a_ref;
    q.c_r = OI_ATAN2(OI_SQRT(q.r[0] * q.r[0] + q.r[1] * q.r[1]), q.r[2]);
    q.lam_r = OI_ATAN2(q.r[1], q.r[0]);
    w = OI_ATAN2(OI_SQRT(((oi_real)1 - x) * ((oi_real)1 + x)), x);
    c_lo = q.c_r - w > (oi_real)0 ? q.c_r - w : (oi_real)0;
    c_hi = q.c_r + w < OI_PI_R ? q.c_r + w : OI_PI_R;
    /* the terminator's extreme colatitudes, where its longitudes turn */
    c_s = OI_ATAN2(OI_SQRT(q.s[0] * q.s[0] + q.s[1] * q.s[1]), q.s[2]);
    t1 = OI_FABS(c_s - OI_HALF_PI_R);
    t2 = OI_PI_R - t1;
    row_h = OI_PI_R / (oi_real)f->n_lat;
    c = c_lo;
    for (n = 0; n < MAX_STEPS && c < c_hi; n++) {
        const oi_real dc = c - q.c_r;
        oi_real e, s, mid, half, smin, u;
        int k, k0, nk;
        /* the next row centre after c */
        u = OI_FLOOR(c / row_h - OI_R(0.5));
        e = (u + OI_R(1.5)) * row_h;
        if (!(e > c)) e = (u + OI_R(2.5)) * row_h;
        if (e > c_hi) e = c_hi;
        if (t1 > c && t1 < e) e = t1;
        if (t2 > c && t2 < e) e = t2;
        if (dc < (oi_real)0) {
            if (q.c_r < e) e = q.c_r;
            s = GRADE * (q.h - dc) / ((oi_real)1 + GRADE);
        } else {
            s = GRADE * (q.h + dc);
        }
        if (s > GRADE) s = GRADE;
        if (c + s < e) e = c + s;
        if (!(e > c)) e = c_hi;
        mid = OI_R(0.5) * (c + e);
        half = OI_R(0.5) * (e - c);
        smin = q.h + (dc < (oi_real)0 ? (-dc > (e - c) ? -dc - (e - c) : (oi_real)0) : dc);
        if (smin > (oi_real)1) smin = (oi_real)1;
        k0 = rule_of(e - c, smin, &nk);
        for (k = k0; k < k0 + nk; k++) {
            st = row(&q, mid + half * gl_x[k], half * gl_w[k], acc);
            if (st < 0) return st;
        }
        c = e;
    }
    from_fixed(f, acc->w);
    from_fixed(f, acc->v);
    return OI_OK;
}

#else
typedef int oi__earthshine_albedo_map_compiled_out; /* ISO C: no empty translation unit */
#endif /* OI_NO_ALBEDO_MODELS */
