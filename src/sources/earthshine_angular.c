/* SPDX-License-Identifier: MIT */
/* earthshine_angular.c: the flux a Lambertian sphere sends to an observer
 * under earthshine, by a cubature over the visible sunlit cap (default) or
 * from the angular table's moments (oi_earth_angular_table, include/oi_table.h;
 * docs/earthshine-angular.md), and oi_earthshine_sphere. */
#include "fp_quiet.h"
#include "sources/sources_internal.h"
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
 * unit local direction o, from table t's moments (w the visible cap's
 * half-angle, s = R tan w; w >= the table's first row and theta below
 * pi / 2 + w, both checked by the caller). */
static OI_NOINLINE oi_real table_shape(const oi_earth_angular_table *t, oi_real theta,
                                       oi_real cos_theta, oi_real sin_theta, oi_real w,
                                       oi_real s, oi_real R, const oi_real o[3])
{
    oi_real c[NC_MAX + 1], wr[6], wc[6], beta, sum;
    int ir[6], ic[6], nr, nk, k, a, b;
    const int nt = t->n_lit + t->n_term, nc = t->n_coef;
    const oi_real w_min = (oi_real)t->w_min, w_max = (oi_real)t->w_max;

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
    return sum > (oi_real)0 ? sum : (oi_real)0;
}

/* The cubature's rule in the polar angle a about the sub-target point: the
 * 9-point Gauss rule of the Legendre weight on [0, 1], its nodes t mapped
 * by a = (1 - cos(pi t)) / 2 (the sqrt behaviour where the terminator
 * touches a ring becomes analytic), the mapped node and the weight times
 * the map's derivative; and in the azimuth b over the lit arc [0, b_m], the
 * plain 4-point rule on [0, 1] (node, weight), its lower half: the rule is
 * symmetric, node 1 - t with the same weight. mpmath, 21 digits; checked
 * in tests/python/test_earth_angular.py. */
#define NA_SPHERE 9
#define NB_SPHERE 4
static const oi_real a_rule[NA_SPHERE][2] = {
    { OI_R(0.0006252141770963123148604), OI_R(0.003191186525695156510551) },
    { OI_R(0.01649303223005176850543), OI_R(0.03614035343792915761905) },
    { OI_R(0.08940831860755273690729), OI_R(0.1168053989018745084256) },
    { OI_R(0.2562011437915144183752), OI_R(0.2141783696847275027537) },
    { OI_R(0.5), OI_R(0.259369382899547354089) },
    { OI_R(0.7437988562084855816248), OI_R(0.2141783696847275027537) },
    { OI_R(0.9105916813924472630927), OI_R(0.1168053989018745084256) },
    { OI_R(0.9835069677699482314946), OI_R(0.03614035343792915761905) },
    { OI_R(0.9993747858229036876851), OI_R(0.003191186525695156510551) },
};
static const oi_real b_rule[NB_SPHERE / 2][2] = {
    { OI_R(0.06943184420297371238803), OI_R(0.1739274225687269286865) },
    { OI_R(0.3300094782075718675987), OI_R(0.3260725774312730713135) },
};

/* Break points of the a range: 0, the horizon, the terminator's tangency
 * and up to N_GEO_SPHERE multiples of the altitude (the 1/d^3 peak). */
#define N_GEO_SPHERE 6
#define N_BREAK_SPHERE (3 + N_GEO_SPHERE)

/* acos(x) = sqrt(1 - x) (a_0 + a_1 x + ... + a_7 x^7) on [0, 1], within
 * 2.2e-8 absolute (Abramowitz & Stegun 1964, 4.4.46, after Hastings; the
 * bound checked in tests/python/test_earth_angular.py): the cubature's
 * error is 1e-4 of its goal's scale, so the kernel needs no more, and this
 * is a quarter of an atan2's cost. */
static const oi_real acos_poly[8] = {
    OI_R(1.5707963050), OI_R(-0.2145988016), OI_R(0.0889789874), OI_R(-0.0501743046),
    OI_R(0.0308918810), OI_R(-0.0170881256), OI_R(0.0066700901), OI_R(-0.0012624911)};


/* acos_poly's polynomial at x (acos x = sqrt(1 - x) times it on [0, 1]). */
static inline OI_VECTORISE_COMPARES oi_real acos_poly_of(oi_real x)
{
    /* Horner's rule written out: the compiler keeps the loop rolled, at
     * twice the instructions of the kernel's arithmetic */
    return ((((((acos_poly[7] * x + acos_poly[6]) * x + acos_poly[5]) * x + acos_poly[4]) * x +
              acos_poly[3]) * x + acos_poly[2]) * x + acos_poly[1]) * x + acos_poly[0];
}

/* p(acos c), the Lambert phase function 2 / (3 pi) ((pi - xi) cos xi +
 * sin xi) at the angle xi of cosine c, within 1e-8 absolute (p(0) = 2/3).
 * Selects, no branch: node_block vectorises it. */
static inline OI_VECTORISE_COMPARES oi_real phase_of_cos(oi_real c)
{
    oi_real ac = OI_FABS(c), q, acos_abs, f;
    ac = ac < (oi_real)1 ? ac : (oi_real)1;
    q = OI_SQRT((oi_real)1 - ac);
    acos_abs = q * acos_poly_of(ac); /* acos |c| */
    /* pi - xi is acos |c| for c < 0, pi - acos |c| otherwise; sin xi = q sqrt(1 + |c|) */
    f = (c < (oi_real)0 ? acos_abs : OI_PI_R - acos_abs) * c + q * OI_SQRT((oi_real)1 + ac);
    return f > (oi_real)0 ? OI_R(2.0) / (OI_R(3.0) * OI_PI_R) * f : (oi_real)0;
}

/* Kernel evaluations per ring: the azimuth nodes, each at omega and at its
 * mirror image in y. */
#define RING_KERNELS (2 * NB_SPHERE)

/* Reciprocal factorials 1 / n!, n = 2 .. 14, exact rationals rounded once:
 * the Taylor coefficients of sin and cos. */
#define INV_FACT2 (OI_R(1.0) / OI_R(2.0))
#define INV_FACT3 (OI_R(1.0) / OI_R(6.0))
#define INV_FACT4 (OI_R(1.0) / OI_R(24.0))
#define INV_FACT5 (OI_R(1.0) / OI_R(120.0))
#define INV_FACT6 (OI_R(1.0) / OI_R(720.0))
#define INV_FACT7 (OI_R(1.0) / OI_R(5040.0))
#define INV_FACT8 (OI_R(1.0) / OI_R(40320.0))
#define INV_FACT9 (OI_R(1.0) / OI_R(362880.0))
#define INV_FACT10 (OI_R(1.0) / OI_R(3628800.0))
#define INV_FACT11 (OI_R(1.0) / OI_R(39916800.0))
#define INV_FACT12 (OI_R(1.0) / OI_R(479001600.0))
#define INV_FACT13 (OI_R(1.0) / OI_R(6227020800.0))
#define INV_FACT14 (OI_R(1.0) / OI_R(87178291200.0))

/* sin x and cos x for |x| <= 1.05 by their Taylor polynomials to x^13 and
 * x^14: the remainders are below 1.05^15 / 15! = 1.6e-12 and 1.05^16 / 16!
 * = 1.1e-13, four orders below the kernel's 2.2e-8 (acos_poly). The
 * cubature's angles are within that range (a / 2 < pi / 4 below the
 * horizon, b_m t <= 0.33 pi), where the general sine's range reduction is
 * not needed: no call, so that the nodes' pair vectorises. */
static inline OI_VECTORISE_COMPARES void sincos_small(oi_real x, oi_real *s, oi_real *c)
{
    const oi_real x2 = x * x;
    *s = x * ((oi_real)1 -
              x2 * (INV_FACT3 -
                    x2 * (INV_FACT5 -
                          x2 * (INV_FACT7 -
                                x2 * (INV_FACT9 - x2 * (INV_FACT11 - x2 * INV_FACT13))))));
    *c = (oi_real)1 -
         x2 * (INV_FACT2 -
               x2 * (INV_FACT4 -
                     x2 * (INV_FACT6 -
                           x2 * (INV_FACT8 -
                                 x2 * (INV_FACT10 - x2 * (INV_FACT12 - x2 * INV_FACT14))))));
}

/* acos x for x in [-1, 1] from acos_poly: the lit arc's half-width. For
 * x < 0 it is reflected about acos_poly's own value at 0 (2 acos_poly[0]
 * - acos |x|, not pi - acos |x|), so that it is continuous at x = 0, where
 * the terminator runs through the sub-target point (theta = pi/2): pi -
 * acos |x| would step by pi - 2 acos_poly[0] = 4.4e-8 there, and the flux
 * with it, as a rounding of cos(theta) across 0 decides. Within 2.2e-8
 * absolute for x >= 0 and 6.6e-8 for x < 0. An error there moves the ring's
 * integral by its square only (the lit factor vanishes at b_m), and the
 * symmetric nodes by that part of the arc: far below the cubature's error. */
static inline OI_VECTORISE_COMPARES oi_real acos_approx(oi_real x)
{
    const oi_real ax = OI_FABS(x) < (oi_real)1 ? OI_FABS(x) : (oi_real)1;
    const oi_real a = OI_SQRT((oi_real)1 - ax) * acos_poly_of(ax);
    return x < (oi_real)0 ? OI_R(2.0) * acos_poly[0] - a : a;
}

/* The cubature's rings evaluated at once by node_block: a fixed count, so
 * that the compiler vectorises its loops whole (no scalar remainder, gcc
 * -O2's cost model), 8 where the processor has vectors of doubles, else one
 * (OI_DOUBLE_VECTORS). */
#if OI_DOUBLE_VECTORS
#define NODE_BLOCK 8
#else
#define NODE_BLOCK 1
#endif

/* What every node of one cubature shares: the sub-target angle's cosine and
 * sine, R' and h' (cubature_flux's Note 1), h'^2, 2 R' and 4 R', and the
 * local direction o to the observer. */
typedef struct {
    oi_real cos_theta, sin_theta, rp, hp, hp2, rp2, rp4, o[3];
} cap_geometry;

/*
 * rings: term[i], ring i's part of cubature_flux's sum (before its
 * factor R'^2 / pi), for nb <= NODE_BLOCK rings (nb a constant where it is
 * inlined) at polar angles a[i] with weights
 * aw[i] (the a rule's weight times its piece's width); 0 for a ring with
 * nothing lit. Each value goes through the same operations in the same
 * order as it would one ring at a time; the rings with nothing lit are
 * computed too (finite or not) and their terms selected away, so that every
 * loop is a fixed count with selects, no branch and no call (gcc -O2
 * -fopt-info-vec; docs/earthshine-angular.md).
 */
static OI_ALWAYS_INLINE OI_VECTORISE_COMPARES void rings(const cap_geometry *g, const oi_real *a,
                                                     const oi_real *aw, oi_real *term,
                                                     const int nb)
{
    /* sn, cs: the sines and cosines of the azimuth nodes, b_m t_k of the
     * rule's lower half (k < NB_SPHERE / 2), then their mirror images b_m (1
     * - t_k) from them by the angle difference */
    oi_real lit0[NODE_BLOCK], lit1[NODE_BLOCK], bm[NODE_BLOCK], cbm[NODE_BLOCK], sbm[NODE_BLOCK];
    oi_real rho[NODE_BLOCK], zc[NODE_BLOCK], wgt[NODE_BLOCK], dark[NODE_BLOCK], ring[NODE_BLOCK];
    oi_real sn[NB_SPHERE][NODE_BLOCK], cs[NB_SPHERE][NODE_BLOCK];
    const oi_real cos_theta = g->cos_theta, sin_theta = g->sin_theta, rp = g->rp, hp = g->hp;
    const oi_real hp2 = g->hp2, rp2 = g->rp2, rp4 = g->rp4;
    const oi_real o0 = g->o[0], o1 = g->o[1], o2 = g->o[2];
    int i, k;

    for (i = 0; i < nb; i++) {
        oi_real sh, ch, sa, sh2, cb, cc, d2, dd;
        sincos_small(OI_R(0.5) * a[i], &sh, &ch);
        sa = OI_R(2.0) * sh * ch;
        sh2 = sh * sh;
        lit0[i] = ((oi_real)1 - OI_R(2.0) * sh2) * cos_theta;
        lit1[i] = sa * sin_theta;
        /* the lit arc's half-width b_m, its cosine and sine: cos b_m =
         * -lit0 / lit1, all of the ring lit (b_m = pi) where that is <= -1 or
         * lit1 <= 0 < lit0, nothing where it is >= 1 or lit1, lit0 <= 0 */
        cb = lit1[i] > (oi_real)0 ? -lit0[i] / (lit1[i] > (oi_real)0 ? lit1[i] : (oi_real)1)
                                  : OI_R(-1.0);
        dark[i] = cb >= (oi_real)1 ? (oi_real)1
                  : lit1[i] > (oi_real)0 ? (oi_real)0
                  : lit0[i] > (oi_real)0 ? (oi_real)0 : (oi_real)1;
        bm[i] = cb <= OI_R(-1.0) ? OI_PI_R : acos_approx(cb);
        cb = cb <= OI_R(-1.0) ? OI_R(-1.0) : cb;
        cbm[i] = cb;
        /* 0 at cb = -1; a dark ring's (cb >= 1, its term selected away)
         * from cb = 1: no square root of a negative number */
        cc = cb < (oi_real)1 ? cb : (oi_real)1;
        sbm[i] = OI_SQRT(((oi_real)1 - cc) * ((oi_real)1 + cc));
        d2 = hp2 + rp4 * sh2;
        dd = OI_SQRT(d2);
        rho[i] = rp * sa / dd;           /* omega's horizontal part */
        zc[i] = -(hp + rp2 * sh2) / dd;  /* omega_z = R' cos a - 1 */
        wgt[i] = aw[i] * sa * (hp - OI_R(2.0) * sh2) / (d2 * dd);
        ring[i] = (oi_real)0;
    }
    for (k = 0; k < NB_SPHERE / 2; k++)
        for (i = 0; i < nb; i++) {
            oi_real s0, c0;
            sincos_small(bm[i] * b_rule[k][0], &s0, &c0);
            sn[k][i] = s0;
            cs[k][i] = c0;
            sn[NB_SPHERE / 2 + k][i] = sbm[i] * c0 - cbm[i] * s0;
            cs[NB_SPHERE / 2 + k][i] = cbm[i] * c0 + sbm[i] * s0;
        }
    /* the ring's sum over its nodes in their order, k < NB_SPHERE / 2 the
     * lower half's, then their mirror images; each node at omega and at its
     * mirror image in y; an unlit node weighs 0 (its kernels are finite) */
    for (k = 0; k < NB_SPHERE; k++)
        for (i = 0; i < nb; i++) {
            const oi_real snk = sn[k][i], csk = cs[k][i];
            const oi_real lit = lit0[i] + lit1[i] * csk;
            const oi_real u = rho[i] * csk * o0 + zc[i] * o2;
            const oi_real v = rho[i] * snk * o1, weighted = b_rule[k % (NB_SPHERE / 2)][1] * lit;
            const oi_real wl = lit > (oi_real)0 ? weighted : (oi_real)0;
            ring[i] += wl * (phase_of_cos(u + v) + phase_of_cos(u - v));
        }
    for (i = 0; i < nb; i++)
        term[i] = dark[i] > (oi_real)0 ? (oi_real)0 : wgt[i] * bm[i] * ring[i];
}


/* rings over NODE_BLOCK rings, and over half as many for a cubature's last
 * few (a fixed count each, so that each vectorises whole). */
static OI_NOINLINE OI_VECTORISE_COMPARES OI_AVX2_CLONES void
node_block(const cap_geometry *g, const oi_real a[NODE_BLOCK], const oi_real aw[NODE_BLOCK],
           oi_real term[NODE_BLOCK])
{
    rings(g, a, aw, term, NODE_BLOCK);
}

#if NODE_BLOCK >= 4
static OI_NOINLINE OI_VECTORISE_COMPARES OI_AVX2_CLONES void
half_block(const cap_geometry *g, const oi_real a[NODE_BLOCK / 2],
           const oi_real aw[NODE_BLOCK / 2], oi_real term[NODE_BLOCK / 2])
{
    rings(g, a, aw, term, NODE_BLOCK / 2);
}
#endif

/*
 * cubature_flux: F, the sphere's flux at theta (cos_theta, sin_theta;
 * theta_cs = OI_ATAN2(sin_theta, cos_theta), the terminator's break) and
 * h_km above an Earth of radius R towards the unit local direction o (per
 * unit albedo, solar irradiance and (a / d)^2, oi_earthshine_sphere's).
 * Notes:
 *  1. Unit r = |target|: R' = R / r, h' = h / r. A surface point at polar
 *     angle a, azimuth b about the sub-target point sends radiance (n.s) /
 *     pi, n.s = cos a cos theta + sin a sin theta cos b, and subtends cos(e)
 *     dA / d'^2 (d'^2 = h'^2 + 4 R' sin^2(a/2), cos e = (cos a - R') / d')
 *     from the incoming direction omega = (P - T) / d'. Then
 *       F = R'^2 / pi int sin a (cos a - R') / d'^3 int (n.s) p(omega.o) db da
 *  2. The lit arc is |b| < b_m(a); b and -b are folded (omega's mirror
 *     image in y), so b runs over [0, b_m] with the plain 4-point rule: the
 *     lit factor vanishes at b_m and the kernel p is smooth (its first
 *     non-analytic term is |xi|^3), so nothing is clipped.
 *  3. The a range is split at the horizon, the terminator's tangency and
 *     multiples of the altitude; each piece gets the mapped 9-point rule
 *     (one rule at every altitude: a rule switched at a threshold steps the
 *     flux there by the two rules' difference).
 *     docs/earthshine-angular.md measures it against the quadrature of
 *     bake/earthshine/angular.py.
 *  4. The rings go to node_block NODE_BLOCK at a time, in order, the last
 *     few to half_block where they fit in half as many, the last block
 *     padded with copies of its last ring whose terms are not added;
 *     their terms are summed in the rings' order.
 */
static OI_NOINLINE oi_real cubature_flux(oi_real theta_cs, oi_real cos_theta, oi_real sin_theta,
                                         oi_real h_km, oi_real R, const oi_real o[3])
{
    cap_geometry g;
    oi_real bp[N_BREAK_SPHERE], a[NODE_BLOCK], aw[NODE_BLOCK], r, a_max, flux = (oi_real)0;
    /* zeroed though node_block writes every term: gcc -fanalyzer does not
     * follow its vectorised loops and would report them uninitialised */
    oi_real term[NODE_BLOCK] = {(oi_real)0};
    int n, p, q, i, count = 0;
    oi_fp_status fp;

    r = R + h_km;
    g.rp = R / r;
    g.hp = h_km / r;
    g.cos_theta = cos_theta;
    g.sin_theta = sin_theta;
    g.hp2 = g.hp * g.hp;
    g.rp2 = OI_R(2.0) * g.rp;
    g.rp4 = OI_R(4.0) * g.rp;
    g.o[0] = o[0];
    g.o[1] = o[1];
    g.o[2] = o[2];
    n = oi__cap_breaks_at(bp, N_BREAK_SPHERE, g.hp, g.rp, theta_cs, &a_max);
    n = oi__cap_breaks_altitude(bp, N_BREAK_SPHERE, n, N_GEO_SPHERE, g.hp, g.rp, a_max);
    fp = oi__fp_quiet_begin(); /* the blocks' discarded rings */
    for (p = 0; p + 1 < n; p++) {
        const oi_real a0 = bp[p], width = bp[p + 1] - bp[p];
        if (!(width > (oi_real)0)) continue;
        for (q = 0; q < NA_SPHERE; q++) {
            a[count] = a0 + width * a_rule[q][0];
            aw[count] = width * a_rule[q][1];
            if (++count == NODE_BLOCK) {
                node_block(&g, a, aw, term);
                for (i = 0; i < NODE_BLOCK; i++) flux += term[i];
                count = 0;
            }
        }
    }
    if (count > 0) {
        for (i = count; i < NODE_BLOCK; i++) {
            a[i] = a[count - 1];
            aw[i] = aw[count - 1];
        }
#if NODE_BLOCK >= 4
        if (count <= NODE_BLOCK / 2)
            half_block(&g, a, aw, term);
        else
#endif
            node_block(&g, a, aw, term);
        for (i = 0; i < count; i++) flux += term[i];
    }
    oi__fp_quiet_end(fp);
    flux *= g.rp * g.rp / OI_PI_R;
    return flux > (oi_real)0 ? flux : (oi_real)0;
}

/* The sphere's flux F at (theta, h) towards the unit local direction o
 * under the resolved model m: the cubature's, or phi times the table's
 * shape with OI_EARTH_REFLECT_TABLE (phi the earthshine table's): 1 when
 * the angular distribution serves the altitude (*flux set, >= 0), 0 below
 * the table's first row (100 km; then the caller reflects from the mean
 * direction). The cubature's F does not go through phi: on the far night
 * side phi is a small fraction of phi(0), and the earthshine table's error
 * there, within its goal of phi(0), can be a large part of phi. theta_cs:
 * OI_ATAN2(sin_theta, cos_theta), which oi_illuminate's theta is (its
 * earth_term forms the cosine and sine by the same operations). */
static int sphere_flux(const oi_model *m, oi_real theta, oi_real cos_theta, oi_real sin_theta,
                       oi_real theta_cs, oi_real h_km, oi_real R, const oi_real o[3], oi_real phi,
                       oi_real *flux)
{
    const oi_earth_angular_table *t = oi_earth_angular_default();
    oi_real w, s;
    *flux = (oi_real)0;
    s = OI_SQRT(h_km) * OI_SQRT(OI_R(2.0) * R + h_km);
    w = OI_ATAN2(s, R);
    if (!(w >= (oi_real)t->w_min)) return 0;
    if (theta >= OI_HALF_PI_R + w) return 1; /* nothing lit is visible: phi = 0 */
    if (m->earth_reflection == OI_EARTH_REFLECT_TABLE)
        *flux = phi * table_shape(t, theta, cos_theta, sin_theta, w, s, R, o);
    else
        *flux = cubature_flux(theta_cs, cos_theta, sin_theta, h_km, R, o);
    return 1;
}

/* The shape S(o) = F / phi (sphere_flux's F; 0 where phi is 0, so that phi
 * S, what oi_illuminate forms with its e_earth, is 0 there too, and where
 * phi is below 1e-20 F, at the lit crescent's vanishing edge, so that S
 * stays finite in single precision). */
int oi__earth_sphere_shape(const oi_model *m, oi_real theta, oi_real cos_theta, oi_real sin_theta,
                           oi_real h_km, oi_real R, const oi_real o[3], oi_real phi,
                           oi_real *shape)
{
    oi_real f;
    const int served =
        sphere_flux(m, theta, cos_theta, sin_theta, theta, h_km, R, o, phi, &f);
    *shape = phi > OI_R(1e-20) * f && phi > (oi_real)0 ? f / phi : (oi_real)0;
    return served;
}

#endif /* OI_NO_EARTH_TABLE */
#endif /* OI_NO_EARTH_ANGULAR */

/* The angular table of a resolved model whose sphere reflects earthshine
 * from its angular distribution (the cubature or the table's moments), or
 * NULL (mean direction). */
const oi_earth_angular_table *oi__earth_angular_of(const oi_model *m)
{
#if defined(OI_NO_EARTH_ANGULAR) || defined(OI_NO_EARTH_TABLE)
    (void)m;
    return (const oi_earth_angular_table *)0;
#else
    if (m->earth_reflection == OI_EARTH_REFLECT_MEAN || m->earth_model != OI_EARTH_TABLE)
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
        if (sphere_flux(&m, theta, cs, sn, OI_ATAN2(sn, cs), h_km, m.earth_radius_km, o, phi,
                        flux))
            return st;
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
