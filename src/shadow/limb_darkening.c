/* SPDX-License-Identifier: MIT */
/* limb_darkening.c: the visible fraction of the limb-darkened solar disc
 * when the Earth's disc hides part of it (oi__fraction_limb_darkened;
 * internal, called by oi_sun_fraction). Method and accuracy: docs/shadow.md.
 * Reference: Neckel, H. & Labs, D. 1994, Sol. Phys. 153, 91. */
#include "fp_quiet.h"
#include "shadow/shadow_internal.h"

#ifndef OI_NO_LIMB_DARKENING

/*
 * Solar limb darkening I(mu)/I(1) = sum_i A_i mu^i, the fifth-degree
 * polynomial of Neckel & Labs (1994, Sol. Phys. 153, 91; their coefficient
 * table) at their continuum wavelength 559.95 nm, the one nearest the V
 * band's 550 nm: A = 0.26892, 1.34319, -1.58427, 1.91271, -1.31350, 0.37295
 * (sum 1, I(0) = 0.269).
 *
 * The flux of the disc within the angular radius rho of its centre is, with
 * mu(rho) = sqrt(1 - sin^2 rho / sin^2 r_s) and k = tan^2 r_s,
 *   F(rho) = int_0^rho I(mu(r)) sin r dr
 *          = (sin^2 r_s / cos r_s) int_mu^1 I(m) m (1 + k m^2)^(-1/2) dm
 *          = (sin^2 r_s / cos r_s) (P(1) - P(mu)),
 *   P(m) = m^2 sum_j (k m^2)^j sum_i c_j A_i m^i / (i + 2j + 2),
 * c_j = binomial(-1/2, j), the binomial series of (1 + k m^2)^(-1/2). The
 * table holds c_j A_i / (i + 2j + 2) (exact rationals, 21 digits).
 */
#define LD_JMAX 5
static const oi_real ld_coef[LD_JMAX + 1][6] = {
    {OI_R(0.13446), OI_R(0.44773), OI_R(-0.3960675), OI_R(0.382542),
     OI_R(-0.218916666666666666667), OI_R(0.0532785714285714285714)},
    {OI_R(-0.033615), OI_R(-0.134319), OI_R(0.1320225), OI_R(-0.136622142857142857143),
     OI_R(0.08209375), OI_R(-0.0207194444444444444444)},
    {OI_R(0.0168075), OI_R(0.0719566071428571428571), OI_R(-0.07426265625), OI_R(0.07969625),
     OI_R(-0.04925625), OI_R(0.0127142045454545454545)},
    {OI_R(-0.0105046875), OI_R(-0.0466385416666666666667), OI_R(0.0495084375),
     OI_R(-0.0543383522727272727273), OI_R(0.0342057291666666666667),
     OI_R(-0.00896514423076923076923)},
    {OI_R(0.00735328125), OI_R(0.0333889559659090909091), OI_R(-0.03609990234375),
     OI_R(0.0402312800480769230769), OI_R(-0.025654296875), OI_R(0.00679856770833333333333)},
    {OI_R(-0.0055149609375), OI_R(-0.0254269741586538461538), OI_R(0.02784849609375),
     OI_R(-0.0313803984375), OI_R(0.0202027587890625), OI_R(-0.00539886259191176470588)},
};

/* 12-point Gauss-Legendre rule on [0, 1] (nodes x < 1/2; 1 - x shares the
 * weight; x and w from tests/ref/gen_refs.py --gauss 12), with sin(pi x/2)
 * and cos(pi x/2) for the undivided panel [0, pi/2] (mpmath, 40 digits).
 * Single precision: 6 points (--gauss 6), whose error, < 1e-10 on the
 * reference rows (measured in double), is far below float rounding. */
#ifdef OI_SINGLE_PRECISION
#define LD_HALF 3
static const oi_real ld_node[LD_HALF][4] = {
    {OI_R(0.0337652428984239860938), OI_R(0.0856622461895851725201),
     OI_R(0.0530134563235083843823), OI_R(0.998593798022316714255)},
    {OI_R(0.169395306766867743169), OI_R(0.180380786524069303785),
     OI_R(0.262956746291481968312), OI_R(0.964807623093742550735)},
    {OI_R(0.380690406958401545685), OI_R(0.233956967286345523695),
     OI_R(0.562980006687355698926), OI_R(0.826470514943095191674)},
};
#else
#define LD_HALF 6
static const oi_real ld_node[LD_HALF][4] = {
    {OI_R(0.00921968287664037465473), OI_R(0.0235876681932559135973),
     OI_R(0.0144817377622976506668), OI_R(0.999895134137267437794)},
    {OI_R(0.0479413718147625716608), OI_R(0.0534696629976592154801),
     OI_R(0.0752349739158396925686), OI_R(0.997165833098929899891)},
    {OI_R(0.115048662902847656482), OI_R(0.0800391642716731131673),
     OI_R(0.179735943801670273069), OI_R(0.983714892896169802289)},
    {OI_R(0.206341022856691276352), OI_R(0.101583713361532960875),
     OI_R(0.318474464998523324309), OI_R(0.947931440107302455328)},
    {OI_R(0.316084250500909903124), OI_R(0.11674626826917740438),
     OI_R(0.476354568549496667639), OI_R(0.879253276946991469236)},
    {OI_R(0.437383295744265542264), OI_R(0.1245735229067013925),
     OI_R(0.634251566298178229689), OI_R(0.773126736472298974688)},
};
#endif

#ifdef OI_SINGLE_PRECISION
#define LD_EPS OI_R(6e-8)
#else
#define LD_EPS OI_R(1.1e-16)
#endif

/* P(m) from m and m2 = m^2 (formed without the rounding of m), nj + 1
 * terms of the series. */
static oi_real ld_poly(oi_real m, oi_real m2, oi_real k, int nj)
{
    oi_real acc = (oi_real)0, x = k * m2;
    int i, j;
    for (j = nj; j >= 0; --j) {
        oi_real t = ld_coef[j][5];
        for (i = 4; i >= 0; --i) t = t * m + ld_coef[j][i];
        acc = acc * x + t;
    }
    return acc * m2;
}

/* The geometry of the Earth's limb arc inside the Sun's disc (see
 * oi__fraction_limb_darkened), fixed for one call. */
typedef struct {
    oi_real hb;    /* sin^2(b/2), b = sep - r_e: hav of the arc's nearest distance */
    oi_real hrs1;  /* 1 - sin^2(r_s/2) */
    oi_real c4;    /* 4 / sin^2 r_s */
    oi_real k;     /* tan^2 r_s */
    oi_real q;     /* sigma^2 sin sep sin r_e (sigma = sin(psi0/2)) */
    oi_real e;     /* annular: hav(r_s) - hav(sep + r_e) > 0; else 0 */
    oi_real oms;   /* 1 - sigma^2 = cos^2(psi0/2); 0 when annular */
    oi_real n0;    /* 2 sigma n / sin^2 r_s = n0 - n1 sin^2(theta) */
    oi_real n1;
    oi_real p1;    /* P(1) in the centre form, 0 in the deficit form */
    int nj;        /* series terms beyond the first */
} ld_geom;

#define LD_NODES (2 * LD_HALF)

/* The nodes ld_node_values evaluates at once: a panel's all where the
 * processor has vectors of doubles (a fixed count, so that its loops
 * vectorise whole), else one at a time (OI_DOUBLE_VECTORS). */
#if OI_DOUBLE_VECTORS
#define LD_BLOCK LD_NODES
#else
#define LD_BLOCK 1
#endif

/* Term j of P(m) / m^2 before its factor (k m^2)^j, c = ld_coef[j];
 * inlined into each clone of ld_node_values. */
static OI_ALWAYS_INLINE oi_real ld_term(const oi_real c[6], oi_real m)
{
    return ((((c[5] * m + c[4]) * m + c[3]) * m + c[2]) * m + c[1]) * m + c[0];
}

/*
 * The integrand at theta = pi/2 - phi of LD_BLOCK nodes, given
 * sph[n] = sin phi = cos theta and cph[n] = cos phi = sin theta (so that the
 * end theta = pi/2, where the arc meets the Sun's limb, is resolved without
 * cancellation):
 *   [P(1) - P(mu)] or P(mu), times sin^2 r_s / sin^2 rho, times
 *   n / sin^2 r_s (n = dt/dpsi sin^2 rho), times dpsi/dtheta.
 * sin^2(psi/2) = sigma^2 sin^2 theta; the haversine formula gives
 * hav(rho) = hav(b) + sin sep sin r_e sin^2(psi/2), and
 * hav(r_s) - hav(rho) = q cos^2 theta + e without cancellation, whence
 * mu^2 = 4 (hav(r_s) - hav(rho)) (1 - hav(r_s) - hav(rho)) / sin^2 r_s and
 * 1 - mu^2 = sin^2 rho / sin^2 r_s = 4 hav(rho) (1 - hav(rho)) / sin^2 r_s.
 * Each node's value goes through the same operations in the same order as
 * it would alone (P(mu) as ld_poly forms it); fixed-count loops over the
 * nodes with selects, no branch and no call, so that they vectorise (gcc
 * -O2 -fopt-info-vec): a node whose den is not positive is computed too and
 * its value selected away (0). val is restrict: its stores alias neither
 * *g nor sph, so no run-time alias check (which -O2 does not vectorise with).
 */
static OI_NOINLINE OI_VECTORISE_COMPARES OI_AVX2_CLONES void
ld_node_values(const ld_geom *g, const oi_real sph[LD_BLOCK], const oi_real cph[LD_BLOCK],
               oi_real *restrict val)
{
    const oi_real hb = g->hb, hrs1 = g->hrs1, c4 = g->c4, k = g->k, q = g->q, e = g->e;
    const oi_real oms = g->oms, n0 = g->n0, n1 = g->n1, p1 = g->p1;
    const int nj = g->nj;
    oi_real st2[LD_BLOCK], m[LD_BLOCK], m2[LD_BLOCK], x[LD_BLOCK], acc[LD_BLOCK],
        den[LD_BLOCK];
    int j, n;
    for (n = 0; n < LD_BLOCK; ++n) {
        oi_real ct2 = sph[n] * sph[n], s2 = cph[n] * cph[n];
        oi_real hr = hb + q * s2;
        oi_real u = c4 * (q * ct2 + e) * (hrs1 - hr);
        den[n] = c4 * hr * ((oi_real)1 - hr) * OI_SQRT(ct2 + oms * s2);
        /* oi__clamp(u, 0, 1), NaN to 0 */
        u = u > (oi_real)0 ? (u < (oi_real)1 ? u : (oi_real)1) : (oi_real)0;
        st2[n] = s2;
        m2[n] = u;
        m[n] = OI_SQRT(u);
        x[n] = k * u;
        /* ld_poly's first step, acc = 0 * x + term nj, as it rounds */
        acc[n] = (oi_real)0 * x[n] + ld_term(ld_coef[nj], m[n]);
    }
    for (j = nj - 1; j >= 0; --j) {
        const oi_real *c = ld_coef[j];
        for (n = 0; n < LD_BLOCK; ++n) acc[n] = acc[n] * x[n] + ld_term(c, m[n]);
    }
    for (n = 0; n < LD_BLOCK; ++n) {
        oi_real pm = acc[n] * m2[n];
        /* a node whose den is not positive is divided by 1 (its value
         * selected away): no quotient by zero */
        oi_real v = (p1 > (oi_real)0 ? p1 - pm : pm) * (n0 - n1 * st2[n]) * sph[n] /
                    (den[n] > (oi_real)0 ? den[n] : (oi_real)1);
        val[n] = den[n] > (oi_real)0 ? v : (oi_real)0;
    }
}

/* The geometry of the arc (ld_geom) for rs, re, sep, b = sep - re and tri
 * (see oi__fraction_limb_darkened), whether the panels are graded and the
 * width below which grading stops; returns P(1). */
static oi_real ld_setup(oi_real rs, oi_real re, oi_real sep, oi_real b, const oi_real *tri,
                        ld_geom *g, int *grade, oi_real *lim)
{
    oi_real hrs = oi__sin_half_sq(rs), s2 = (oi_real)4 * hrs * ((oi_real)1 - hrs);
    oi_real sse = OI_SIN(sep), sre = OI_SIN(re), sg = (oi_real)1;
    oi_real t, res;

    g->hrs1 = (oi_real)1 - hrs;
    g->c4 = (oi_real)4 / s2;
    g->k = s2 / oi__sqr((oi_real)1 - (oi_real)2 * hrs);
    g->hb = oi__sin_half_sq(b);
    if (tri == NULL) {
        /* annular: e = -sin((sep + r_e + r_s)/2) sin((sep + r_e - r_s)/2) */
        g->q = sse * sre;
        g->e = -oi__sin_0_pi(OI_R(0.5) * (sep + (re + rs))) *
               OI_SIN(OI_R(0.5) * oi__side_excess(rs, sep, re));
        g->oms = (oi_real)0;
        /* the limb singularity at asinh(w) >= w / (1 + w), w^2 = e / q */
        *grade = g->e < (oi_real)4 * g->q;
        t = *grade ? OI_SQRT(g->e / g->q) : (oi_real)2;
        *lim = OI_R(0.5) * t / ((oi_real)1 + t);
    } else {
        /* the half-angle formulas at the Earth's centre (tri from
         * oi__half_sines(rs, re, sep)): sigma^2 = sin(s - re) sin(s - sep) /
         * (sin sep sin re), 1 - sigma^2 = sin s sin(s - rs) / (sin sep sin re);
         * each ratio is at most ~1 (no overflow or underflow) */
        g->q = tri[2] * tri[3];
        g->e = (oi_real)0;
        sg = OI_SQRT(oi__clamp((tri[2] / sse) * (tri[3] / sre), (oi_real)0, (oi_real)1));
        g->oms = oi__clamp((tri[0] / sse) * (tri[1] / sre), (oi_real)0, (oi_real)1);
        /* the Jacobian's branch point at atanh(w) >= w, w = cos(psi0/2) */
        t = OI_SQRT(g->oms);
        *grade = t < OI_R(0.9);
        *lim = OI_R(0.5) * t;
    }
    g->n0 = (oi_real)2 * sg * sre * OI_SIN(b) / s2;
    g->n1 = (oi_real)4 * sg * OI_COS(re) * g->q / s2;
    /* series terms: stop when k^(nj+1) <= eps */
    g->nj = 0;
    for (t = g->k; g->nj < LD_JMAX && t > LD_EPS; t *= g->k) ++g->nj;
    res = ld_poly((oi_real)1, (oi_real)1, g->k, g->nj); /* P(1) > 0 */
    g->p1 = OI_FABS(b) < OI_R(0.875) * rs ? res : (oi_real)0;
    return res;
}

/*
 * A file of its own, so out of line: its locals stay out of the frame of
 * oi__sun_shadow, which is live during the atmosphere's call as well.
 *
 * Visible fraction of the limb-darkened solar disc (radius rs) when the
 * Earth's disc (radius re) is sep away: in the penumbra, tri = the sines of
 * the triangle (rs, re, sep) from oi__half_sines and pa_s = pi - a_s, a_s the
 * angle at the Sun's centre between the Earth's centre and a crossing point
 * of the limbs; annular (the Earth's disc inside the Sun's), tri = NULL.
 *
 * Green's theorem in polar coordinates (rho, t) about the Sun's centre: the
 * flux over a region is the line integral of F(rho) dt around it. The
 * hidden region is bounded by the Sun's limb inside the Earth's disc (F(r_s)
 * times its angle 2 a_s) and the Earth's limb inside the Sun's disc,
 * parametrised by the angle psi at the Earth's centre, |psi| <= psi0, with
 *   dt/dpsi = sin r_e (sin(sep - r_e) - 2 sin sep cos r_e sin^2(psi/2)) / sin^2 rho
 * (differentiating tan t = N/D, N^2 + D^2 = sin^2 rho). Hence, by symmetry,
 *   visible = 2 (pi - a_s) F(r_s) + 2 K1,  K1 = int_0^psi0 F(rho) dt/dpsi dpsi
 * ("centre" form: F / sin^2 rho is smooth even where the arc passes the
 * Sun's centre), or, with K2 = int_0^psi0 (F(r_s) - F(rho)) dt/dpsi dpsi,
 *   hidden = 2 K2 (sep > r_e),  visible = -2 K2 (sep < r_e)
 * ("deficit" form: the small part directly, no cancellation near the
 * tangencies; used when |sep - r_e| >= 7/8 r_s, where 1/sin^2 rho has no
 * nearby pole). The substitution sin(psi/2) = sigma sin(theta),
 * sigma = sin(psi0/2), maps psi0 to theta = pi/2 and turns the square root
 * of the limb, mu ~ sqrt(psi0 - psi), and its mirror at -psi0 into a
 * smooth cos(theta): one 12-point panel. The Jacobian
 * 2 sigma cos(theta) / sqrt(1 - sigma^2 sin^2 theta) has a branch point at a
 * distance atanh(cos(psi0/2)) from theta = pi/2, close when the Earth's
 * disc is nearly internally tangent to the Sun's (beyond the umbra's tip);
 * there panels are graded geometrically towards pi/2 until the last is
 * narrower than half that distance. Annular: psi0 = pi, sigma = 1, the
 * Jacobian is 2, and the singularity of mu sits at a distance
 * asinh(sqrt(e / (sin sep sin r_e))) beyond pi/2, graded the same way.
 */
oi_real oi__fraction_limb_darkened(oi_real rs, oi_real re, oi_real sep, oi_real pa_s,
                                   const oi_real *tri)
{
    ld_geom g;
    const oi_real b = sep - re;
    oi_real lim, sum = (oi_real)0, res, t;
    int grade, i, j, k;
    oi_fp_status fp;
    res = ld_setup(rs, re, sep, b, tri, &g, &grade, &lim); /* P(1) */
    fp = oi__fp_quiet_begin(); /* ld_node_values' discarded nodes */

    /* panels in phi = pi/2 - theta: [0, pi/2] undivided (nodes and their
     * sines tabulated), or graded: [q/2, q] for q = pi/2, pi/4, ... while
     * q > lim (at most 40), then [0, q] */
    for (k = 0, t = OI_HALF_PI_R; k <= 40; ++k) {
        oi_real lo = grade && k < 40 && t > lim ? OI_R(0.5) * t : (oi_real)0, h = t - lo;
        oi_real ps = (oi_real)0, sph[LD_BLOCK], cph[LD_BLOCK], val[LD_BLOCK];
        /* node 2 i + j (i the rule's node, j its mirror), summed in that
         * order */
        for (i = 0; i < LD_HALF; ++i) {
            for (j = 0; j < 2; ++j) {
                const int n = LD_BLOCK == 1 ? 0 : 2 * i + j;
                if (grade) {
                    oi_real ph = lo + h * (j ? (oi_real)1 - ld_node[i][0] : ld_node[i][0]);
                    OI_SINCOS(ph, &sph[n], &cph[n]);
                } else {
                    sph[n] = ld_node[i][j ? 3 : 2];
                    cph[n] = ld_node[i][j ? 2 : 3];
                }
#if LD_BLOCK == 1
                ld_node_values(&g, sph, cph, val);
                ps += ld_node[i][1] * val[0];
#endif
            }
        }
#if LD_BLOCK > 1
        ld_node_values(&g, sph, cph, val);
        for (i = 0; i < LD_HALF; ++i)
            for (j = 0; j < 2; ++j) ps += ld_node[i][1] * val[2 * i + j];
#endif
        sum += ps * h;
        if (!(lo > (oi_real)0)) break;
        t = lo;
    }
    oi__fp_quiet_end(fp);
    sum /= OI_PI_R * res;
    if (g.p1 > (oi_real)0) res = pa_s / OI_PI_R + sum;
    else if (b > (oi_real)0) res = (oi_real)1 - sum;
    else res = -sum;
    return oi__clamp(res, (oi_real)0, (oi_real)1);
}
#endif /* OI_NO_LIMB_DARKENING */
