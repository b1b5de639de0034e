/* SPDX-License-Identifier: MIT */
/* shadow.c: exact overlap of two spherical caps, and the visible fraction of
 * the Sun (uniform and limb-darkened disc) seen from a point near the Earth.
 * Model, formulas and measured accuracy: docs/shadow.md. */
/* oi__norm, oi__finite3 out of line: the Sun-only build fits 4 KiB (src/oi_internal.h) */
#define OI_VECTOR_OUT_OF_LINE
#include "oi_internal.h"

/* pi in two parts (see phase.c): (PI_HI - x) + PI_LO is pi - x to one
 * rounding for x near pi. */
#ifdef OI_SINGLE_PRECISION
#define PI_HI (3.14159274f)
#define PI_LO (-8.74227800e-08f)
#else
#define PI_HI (3.141592653589793116)
#define PI_LO (1.2246467991473532e-16)
#endif
#define HALF_PI_R (OI_PI_R * OI_R(0.5))

static oi_real pi_minus(oi_real x)
{
    return (PI_HI - x) + PI_LO;
}

static oi_real sqr(oi_real x)
{
    return x * x;
}

static oi_real clamp(oi_real x, oi_real lo, oi_real hi)
{
    if (!(x > lo)) return lo; /* also maps NaN to lo */
    return x < hi ? x : hi;
}

/* sin^2(r/2): the cap area over 4 pi, without the cancellation of 1 - cos r. */
static oi_real sin_half_sq(oi_real r)
{
    return sqr(OI_SIN(OI_R(0.5) * r));
}

/* y + z - x for non-negative x, y, z, accurate when y + z is close to x:
 * the larger of y, z minus x is exact there (Sterbenz), then one rounding. */
static oi_real side_excess(oi_real x, oi_real y, oi_real z)
{
    oi_real big = y > z ? y : z;
    oi_real small = y > z ? z : y;
    return (big - x) + small;
}

/* sin of an angle known to lie in [0, pi], accurate near pi too. */
static oi_real sin_0_pi(oi_real x)
{
    return x <= HALF_PI_R ? OI_SIN(x) : OI_SIN(pi_minus(x));
}

/*
 * The sines of the spherical triangle with sides a, b, c (radians, triangle
 * inequalities assumed; rounding beyond them is clamped) used by the
 * half-angle formulas (l'Huilier's family), s = (a + b + c)/2:
 *   hs[0] = sin s, hs[1] = sin(s - a), hs[2] = sin(s - b), hs[3] = sin(s - c),
 * the differences formed in Kahan's order (no cancellation).
 */
static void half_sines(oi_real a, oi_real b, oi_real c, oi_real hs[4])
{
    int i;
    hs[0] = sin_0_pi(OI_R(0.5) * (a + (b + c)));
    hs[1] = OI_SIN(OI_R(0.5) * side_excess(a, b, c));
    hs[2] = OI_SIN(OI_R(0.5) * side_excess(b, a, c));
    hs[3] = OI_SIN(OI_R(0.5) * side_excess(c, a, b));
    for (i = 0; i < 4; ++i) hs[i] = hs[i] > (oi_real)0 ? hs[i] : (oi_real)0;
}

/*
 * The angle opposite the side of index i (1: a, 2: b, 3: c) from
 *   tan(A/2) = sqrt( sin(s-b) sin(s-c) / (sin s sin(s-a)) ),
 * or with comp != 0 pi - A from the reciprocal ratio, so that neither A nor
 * pi - A is formed by a cancelling subtraction. A point-like triangle gives
 * A = 0.
 */
static oi_real half_angle(const oi_real hs[4], int i, int comp)
{
    oi_real num = OI_SQRT(hs[i == 1 ? 2 : 1]) * OI_SQRT(hs[i == 3 ? 2 : 3]);
    oi_real den = OI_SQRT(hs[0]) * OI_SQRT(hs[i]);
    if (num == (oi_real)0 && den == (oi_real)0) return comp ? OI_PI_R : (oi_real)0;
    return (oi_real)2 * (comp ? OI_ATAN2(den, num) : OI_ATAN2(num, den));
}

/* The angle opposite a (comp != 0: pi minus it); see half_angle. */
static oi_real tri_angle(oi_real a, oi_real b, oi_real c, int comp)
{
    oi_real hs[4];
    half_sines(a, b, c, hs);
    return half_angle(hs, 1, comp);
}

/*
 * Area of the "segment" of a cap of radius r (<= pi/2) cut off by the great
 * circle through the two points of its boundary seen from the cap's centre
 * at +-alpha.
 * alpha >= 1/2: the sector 4 alpha sin^2(r/2) minus the isosceles triangle
 * (centre and the two points, apex angle 2 alpha) whose spherical excess E is
 *   tan(E/2) = S sin 2a / (C + S cos 2a),  S = sin^2(r/2), C = cos^2(r/2)
 * (the two-sides-and-included-angle excess formula with tan^2(r/2) = S/C);
 * for alpha > pi/2 the excess is negative: the triangle is added, as the
 * cap's centre then lies inside the segment. The two terms cancel by at most
 * a factor 1.5/alpha^2 = 6.
 * alpha < 1/2 (thin segments, where sector and triangle cancel): the same
 * area as an integral without cancellation, obtained by differentiating the
 * above in alpha:
 *   seg = 2 sin^2 r cos r  J(alpha),  J = int_0^alpha sin^2 u / (1 - sin^2 r sin^2 u) du,
 * J by the 8-point Gauss-Legendre rule (gauss_j).
 * Planar check: for small r, seg -> (r^2/2)(2 alpha - sin 2 alpha).
 */
static oi_real gauss_j(oi_real alpha, oi_real k2);

static oi_real cap_segment(oi_real r, oi_real alpha)
{
    oi_real s, c, e;
    if (alpha < OI_R(0.5)) {
        oi_real sr = OI_SIN(r);
        return (oi_real)2 * sr * sr * OI_COS(r) * gauss_j(alpha, sr * sr);
    }
    s = sin_half_sq(r);
    c = sqr(OI_COS(OI_R(0.5) * r));
    e = (oi_real)2 * OI_ATAN2(s * OI_SIN((oi_real)2 * alpha), c + s * OI_COS((oi_real)2 * alpha));
    return (oi_real)4 * alpha * s - e;
}

/* Overlap of two caps with r1, r2 in [0, pi/2] and d in [0, pi]. */
static oi_real overlap_small(oi_real r1, oi_real r2, oi_real d)
{
    oi_real a1, a2, lens, amin, hs[4];
    oi_real rbig = r1 > r2 ? r1 : r2, rsmall = r1 > r2 ? r2 : r1;
    amin = (oi_real)4 * OI_PI_R * sin_half_sq(rsmall);
    /* classification by differences, exact near the tangencies (Sterbenz),
     * instead of comparing d with the rounded r1 + r2 or r1 - r2 */
    if (d - rbig >= rsmall) return (oi_real)0;               /* disjoint */
    if (rbig - d >= rsmall) return amin;                     /* nested */
    /* triangle (C1, C2, P), P a crossing point of the two boundaries:
     * sides C1P = r1, C2P = r2, C1C2 = d; alpha1 at C1 is opposite r2. */
    half_sines(r2, r1, d, hs);
    a1 = half_angle(hs, 1, 0);
    a2 = half_angle(hs, 2, 0);
    if (rsmall >= (oi_real)1) {
        /* two large caps: Gauss-Bonnet on the lens (two arcs of geodesic
         * curvature cot r and length 2 alpha sin r, two corners of exterior
         * angle gamma, the triangle's angle at P opposite d):
         *   lens = 2 (pi - gamma) - 2 alpha1 cos r1 - 2 alpha2 cos r2.
         * Used here because the chord decomposition degenerates when both
         * boundaries approach great circles (P and Q nearly antipodal); the
         * terms cancel at most to a few epsilon times the caps' area. */
        oi_real pg = half_angle(hs, 3, 1); /* pi - gamma */
        lens = (oi_real)2 * (pg - a1 * OI_COS(r1) - a2 * OI_COS(r2));
    } else {
        lens = cap_segment(r1, a1) + cap_segment(r2, a2);
    }
    return clamp(lens, (oi_real)0, amin);
}

/*
 * oi_cap_overlap: area of the intersection of two spherical caps.
 *
 * Given:
 *   r1, r2  oi_real  angular radii of the caps (radians, [0, pi])
 *   d       oi_real  angle between the caps' centres (radians, [0, pi])
 * Returned (function value):
 *           oi_real  area of the intersection on the unit sphere
 *                    (steradians), in [0, min(A(r1), A(r2))] where
 *                    A(r) = 4 pi sin^2(r/2) is a cap's area.
 * Notes:
 *  1. Inputs are clamped to [0, pi]; a NaN input gives 0.
 *  2. Disjoint caps (d >= r1 + r2) give exactly 0; a cap inside the other
 *     (d <= |r1 - r2|) gives exactly the smaller cap's area; caps whose
 *     union is the sphere give A(r1) + A(r2) - 4 pi.
 *  3. Otherwise the intersection (a lens bounded by two circle arcs) is cut
 *     by the great circle through the two crossing points into two cap
 *     segments, each a sector minus an isosceles spherical triangle, or, for
 *     a thin segment, a cancellation-free integral of the same area. The
 *     half-angles at the centres come from the spherical half-angle formula
 *     with the side sums formed as in Kahan's triangle-area ordering (no
 *     acos of a difference). Two caps of at least 1 rad: Gauss-Bonnet on
 *     the lens instead (the chord decomposition degenerates for two great
 *     circles). A cap larger than a hemisphere: signed segments near its
 *     edge, else complementation (the complement of the cap (r, c) is the
 *     cap (pi - r, -c)). The classification (disjoint, nested) uses
 *     differences that are exact near the tangencies.
 *  4. Accuracy (docs/shadow.md): the absolute error is a few epsilon times
 *     the smaller cap's area; the relative error of a thin lens near
 *     tangency grows as the lens shrinks (its area is then ill-conditioned
 *     in d).
 * References:
 *   Todhunter, I. 1886, Spherical Trigonometry, 5th ed. (the half-angle
 *   formulas; the spherical excess from two sides and the included angle).
 *   Kahan, W. 2014, "Miscalculating Area and Angles of a Needle-like
 *   Triangle" (ordering of the side sums).
 */
oi_real oi_cap_overlap(oi_real r1, oi_real r2, oi_real d)
{
    oi_real a1, a2, a, amin;
    if (r1 != r1 || r2 != r2 || d != d) return (oi_real)0;
    r1 = clamp(r1, (oi_real)0, OI_PI_R);
    r2 = clamp(r2, (oi_real)0, OI_PI_R);
    d = clamp(d, (oi_real)0, OI_PI_R);
    if (r1 <= HALF_PI_R && r2 <= HALF_PI_R) return overlap_small(r1, r2, d);

    a1 = (oi_real)4 * OI_PI_R * sin_half_sq(r1);
    a2 = (oi_real)4 * OI_PI_R * sin_half_sq(r2);
    amin = a1 < a2 ? a1 : a2;
    if (r1 > HALF_PI_R && r2 > HALF_PI_R) {
        /* |K1 n K2| = A1 + A2 - 4 pi + |K1' n K2'|, K' the complements
         * (their centres are also d apart). A1 + A2 - 4 pi =
         * -4 pi cos((r1 + r2)/2) cos((r1 - r2)/2). */
        a = -(oi_real)4 * OI_PI_R * OI_COS(OI_R(0.5) * (r1 + r2)) * OI_COS(OI_R(0.5) * (r1 - r2)) +
            overlap_small(pi_minus(r1), pi_minus(r2), d);
    } else {
        /* one cap larger than a hemisphere: rb > pi/2 >= rs */
        oi_real rb = r1 > r2 ? r1 : r2, rs = r1 > r2 ? r2 : r1, ab = r1 > r2 ? a2 : a1;
        if (d - rb >= rs) return (oi_real)0;
        if (rb - d >= rs) return ab;
        if (pi_minus(d) + pi_minus(rb) <= rs) {
            /* the large cap's complement inside the small cap (the union is
             * the sphere): A_s - A(pi - rb) */
            a = ab - (oi_real)4 * OI_PI_R * sin_half_sq(pi_minus(rb));
            return clamp(a, (oi_real)0, amin);
        }
        {
            /* angle at the large cap's centre (opposite rs), and at the
             * small cap's centre (opposite rb) */
            oi_real alb = tri_angle(rs, rb, d, 0);
            if (alb < (oi_real)1 && d + rs > HALF_PI_R) {
                /* small lens near the large cap's edge: the signed segments
                 * lens = seg(rs, al_s) + seg(rb, al_b), where a cap beyond a
                 * hemisphere has the segment -seg(pi - rb, al_b) (its boundary
                 * curves away from the lens); no cancellation against the
                 * small cap's area */
                oi_real als = tri_angle(rb, rs, d, 0);
                a = cap_segment(rs, als) - cap_segment(pi_minus(rb), alb);
            } else {
                /* |Kb n Ks| = As - |Kb' n Ks|, Kb' = cap(pi - rb) at pi - d */
                a = ab - overlap_small(pi_minus(rb), rs, pi_minus(d));
            }
        }
    }
    return clamp(a, (oi_real)0, amin);
}

/* ---------------------------------------------------------------- quadrature */

/* 8-point Gauss-Legendre rule on [0, 1]: the nodes x below and 1 - x
 * share the weights (computed with mpmath at 40 digits by Newton iteration
 * on P_8; tests/ref/gen_refs.py --gauss 8 prints them). */
#define GL_HALF 4
static const oi_real gl_node[GL_HALF][2] = {
    {OI_R(0.0198550717512318841582), OI_R(0.0506142681451881295763)},
    {OI_R(0.101666761293186630204), OI_R(0.111190517226687235272)},
    {OI_R(0.237233795041835507091), OI_R(0.156853322938943643669)},
    {OI_R(0.40828267875217509753), OI_R(0.181341891689180991483)},
};

/* J(alpha) = int_0^alpha sin^2 u / (1 - k2 sin^2 u) du, k2 = sin^2 r <= 1,
 * alpha < 1/2: Gauss-Legendre, 8 nodes on [0, alpha] when alpha < 1/4, on
 * each half of it otherwise. The integrand's nearest singularity,
 * sin^2 u = 1/k2, lies at least pi/2 - 1/2 from [0, alpha], so the error
 * factor of a panel is below (z + sqrt(z^2 - 1))^-16 with z >= 9.6 (the
 * distance over the half-width): < 4e-21 (measured with mpmath: one
 * 8-point panel on [0, 1/2] at k2 = 1 errs by 7e-15 relative). */
static oi_real gauss_j(oi_real alpha, oi_real k2)
{
    int panels = alpha < OI_R(0.25) ? 1 : 2, k, i, j;
    oi_real sum = (oi_real)0, h = alpha / (oi_real)panels;
    for (k = 0; k < panels; ++k) {
        oi_real lo = (oi_real)k * h;
        for (i = 0; i < GL_HALF; ++i) {
            for (j = 0; j < 2; ++j) {
                oi_real x = j ? (oi_real)1 - gl_node[i][0] : gl_node[i][0];
                oi_real su = OI_SIN(lo + h * x);
                oi_real s2 = su * su;
                sum += gl_node[i][1] * s2 / ((oi_real)1 - k2 * s2);
            }
        }
    }
    return h * sum;
}

#ifndef OI_NO_LIMB_DARKENING
/* ---------------------------------------------------------------- limb darkening */

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
/* limb darkening computed for 1e-15 < r_s <= LD_RS_MAX (docs/shadow.md) */
#define LD_RS_MAX OI_R(0.5)
#define LD_RS_MIN OI_R(1e-15)

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
 * fraction_limb_darkened), fixed for one call. */
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

/*
 * The integrand at theta = pi/2 - phi, given sph = sin phi = cos theta and
 * cph = cos phi = sin theta (so that the end theta = pi/2, where the arc
 * meets the Sun's limb, is resolved without cancellation):
 *   [P(1) - P(mu)] or P(mu), times sin^2 r_s / sin^2 rho, times
 *   n / sin^2 r_s (n = dt/dpsi sin^2 rho), times dpsi/dtheta.
 * sin^2(psi/2) = sigma^2 sin^2 theta; the haversine formula gives
 * hav(rho) = hav(b) + sin sep sin r_e sin^2(psi/2), and
 * hav(r_s) - hav(rho) = q cos^2 theta + e without cancellation, whence
 * mu^2 = 4 (hav(r_s) - hav(rho)) (1 - hav(r_s) - hav(rho)) / sin^2 r_s and
 * 1 - mu^2 = sin^2 rho / sin^2 r_s = 4 hav(rho) (1 - hav(rho)) / sin^2 r_s.
 */
static oi_real ld_node_value(const ld_geom *g, oi_real sph, oi_real cph)
{
    oi_real st2 = cph * cph, ct2 = sph * sph;
    oi_real hr = g->hb + g->q * st2;
    oi_real m2 = clamp(g->c4 * (g->q * ct2 + g->e) * (g->hrs1 - hr), (oi_real)0, (oi_real)1);
    oi_real den = g->c4 * hr * ((oi_real)1 - hr) * OI_SQRT(ct2 + g->oms * st2);
    oi_real p = ld_poly(OI_SQRT(m2), m2, g->k, g->nj);
    if (g->p1 > (oi_real)0) p = g->p1 - p;
    if (!(den > (oi_real)0)) return (oi_real)0;
    return p * (g->n0 - g->n1 * st2) * sph / den;
}

/*
 * Kept out of line (OI_NOINLINE): its locals stay out of the frame of
 * oi__sun_shadow, which is live during the atmosphere's call as well.
 *
 * Visible fraction of the limb-darkened solar disc (radius rs) when the
 * Earth's disc (radius re) is sep away: in the penumbra, tri = the sines of
 * the triangle (rs, re, sep) from half_sines and pa_s = pi - a_s, a_s the
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
static OI_NOINLINE oi_real fraction_limb_darkened(oi_real rs, oi_real re, oi_real sep,
                                                  oi_real pa_s, const oi_real *tri)
{
    ld_geom g;
    oi_real hrs = sin_half_sq(rs), s2 = (oi_real)4 * hrs * ((oi_real)1 - hrs);
    oi_real sse = OI_SIN(sep), sre = OI_SIN(re), b = sep - re, sg = (oi_real)1;
    oi_real sum = (oi_real)0, t, lim, res;
    int i, j, k, grade;

    g.hrs1 = (oi_real)1 - hrs;
    g.c4 = (oi_real)4 / s2;
    g.k = s2 / sqr((oi_real)1 - (oi_real)2 * hrs);
    g.hb = sin_half_sq(b);
    if (tri == NULL) {
        /* annular: e = -sin((sep + r_e + r_s)/2) sin((sep + r_e - r_s)/2) */
        g.q = sse * sre;
        g.e = -sin_0_pi(OI_R(0.5) * (sep + (re + rs))) *
              OI_SIN(OI_R(0.5) * side_excess(rs, sep, re));
        g.oms = (oi_real)0;
        /* the limb singularity at asinh(w) >= w / (1 + w), w^2 = e / q */
        grade = g.e < (oi_real)4 * g.q;
        t = grade ? OI_SQRT(g.e / g.q) : (oi_real)2;
        lim = OI_R(0.5) * t / ((oi_real)1 + t);
    } else {
        /* the half-angle formulas at the Earth's centre (tri from
         * half_sines(rs, re, sep)): sigma^2 = sin(s - re) sin(s - sep) /
         * (sin sep sin re), 1 - sigma^2 = sin s sin(s - rs) / (sin sep sin re);
         * each ratio is at most ~1 (no overflow or underflow) */
        g.q = tri[2] * tri[3];
        g.e = (oi_real)0;
        sg = OI_SQRT(clamp((tri[2] / sse) * (tri[3] / sre), (oi_real)0, (oi_real)1));
        g.oms = clamp((tri[0] / sse) * (tri[1] / sre), (oi_real)0, (oi_real)1);
        /* the Jacobian's branch point at atanh(w) >= w, w = cos(psi0/2) */
        t = OI_SQRT(g.oms);
        grade = t < OI_R(0.9);
        lim = OI_R(0.5) * t;
    }
    g.n0 = (oi_real)2 * sg * sre * OI_SIN(b) / s2;
    g.n1 = (oi_real)4 * sg * OI_COS(re) * g.q / s2;
    /* series terms: stop when k^(nj+1) <= eps */
    g.nj = 0;
    for (t = g.k; g.nj < LD_JMAX && t > LD_EPS; t *= g.k) ++g.nj;
    res = ld_poly((oi_real)1, (oi_real)1, g.k, g.nj); /* P(1) > 0 */
    g.p1 = OI_FABS(b) < OI_R(0.875) * rs ? res : (oi_real)0;

    /* panels in phi = pi/2 - theta: [0, pi/2] undivided (nodes and their
     * sines tabulated), or graded: [q/2, q] for q = pi/2, pi/4, ... while
     * q > lim (at most 40), then [0, q] */
    for (k = 0, t = HALF_PI_R; k <= 40; ++k) {
        oi_real lo = grade && k < 40 && t > lim ? OI_R(0.5) * t : (oi_real)0, h = t - lo;
        oi_real ps = (oi_real)0;
        for (i = 0; i < LD_HALF; ++i) {
            for (j = 0; j < 2; ++j) {
                oi_real sph, cph;
                if (grade) {
                    oi_real ph = lo + h * (j ? (oi_real)1 - ld_node[i][0] : ld_node[i][0]);
                    OI_SINCOS(ph, &sph, &cph);
                } else {
                    sph = ld_node[i][j ? 3 : 2];
                    cph = ld_node[i][j ? 2 : 3];
                }
                ps += ld_node[i][1] * ld_node_value(&g, sph, cph);
            }
        }
        sum += ps * h;
        if (!(lo > (oi_real)0)) break;
        t = lo;
    }
    sum /= OI_PI_R * res;
    if (g.p1 > (oi_real)0) res = pa_s / OI_PI_R + sum;
    else if (b > (oi_real)0) res = (oi_real)1 - sum;
    else res = -sum;
    return clamp(res, (oi_real)0, (oi_real)1);
}
#endif /* OI_NO_LIMB_DARKENING */
/* ---------------------------------------------------------------- sun fraction */

/* a * a = hi + lo exactly (Dekker's product with oi__split, oi_internal.h). */
static void two_square(oi_real a, oi_real *hi, oi_real *lo)
{
    oi_real ah, al;
    oi__split(a, &ah, &al);
    *hi = a * a;
    *lo = ((ah * ah - *hi) + (oi_real)2 * ah * al) + al * al;
}

/*
 * q = |p|^2 - R^2 with a relative error of a few epsilon even when |p| is
 * within a few metres of R (then the plain difference of the rounded |p| and
 * R would keep only log10(h/R) fewer digits: at 1 m altitude 7 of 16 in
 * double, none in single precision). Used only when |p| < 2R, where the
 * squares cannot overflow.
 */
static oi_real radial_excess(const oi_real p[3], oi_real r)
{
    oi_real sh = (oi_real)0, sl = (oi_real)0, h, l, e, rh, rl;
    int i;
    for (i = 0; i < 3; ++i) {
        two_square(p[i], &h, &l);
        sh = oi__two_sum(sh, h, &e);
        sl += e + l;
    }
    two_square(r, &rh, &rl);
    /* sh and rh are within a factor 4 of each other: sh - rh is exact */
    return (sh - rh) + (sl - rl);
}

/* Apparent angular radius of a sphere of radius rad at distance dist > rad:
 * atan2(rad, sqrt((dist - rad)(dist + rad))), exact near grazing too. */
static oi_real apparent_radius(oi_real rad, oi_real dist)
{
    return OI_ATAN2(rad, OI_SQRT(dist - rad) * OI_SQRT(dist + rad));
}

/*
 * oi_sun_fraction: visible fraction of the Sun seen from a point.
 *
 * Given:
 *   sun_km    oi_real[3]  Sun position, Earth-centred (km)
 *   point_km  oi_real[3]  point position, Earth-centred (km), above the
 *                         Earth's surface (|point| > earth_radius_km)
 *   model     oi_model*   NULL or model constants (sun_radius_km,
 *                         earth_radius_km, limb_darkening are used)
 * Returned:
 *   out       oi_shadow*  fraction: visible fraction of the uniform disc's
 *                         area, [0, 1]; fraction_ld: visible fraction of the
 *                         limb-darkened disc's flux, [0, 1]; fraction_atm:
 *                         fraction or fraction_ld as the model chooses (see
 *                         note 5); sun_radius_rad, earth_radius_rad,
 *                         separation_rad; sun_distance_km; region.
 * Returned (function value):
 *   OI_OK                 computed.
 *   OI_WARN_TABLE_RANGE   computed; the atmosphere table did not cover the
 *                         point (geometric fraction_atm kept; src/atmosphere.c).
 *   OI_ERR_NULL           sun_km, point_km or out is NULL.
 *   OI_ERR_MODEL          a model field is non-finite, negative or an unknown
 *                         option (from oi__model_resolve).
 *   OI_ERR_RADIUS         a negative model radius.
 *   OI_ERR_NONFINITE      a NaN or infinite component, or a Sun-to-point
 *                         vector that overflows.
 *   OI_ERR_ZERO_VECTOR    sun_km or point_km is the zero vector.
 *   OI_ERR_BELOW_SURFACE  |point| <= earth_radius_km.
 *   OI_ERR_GEOMETRY       |sun| <= sun_radius_km + earth_radius_km (the
 *                         Sun would touch the Earth), or the point inside or
 *                         on the Sun (|sun - point| <= sun_radius_km).
 *   On error every field of *out is zero.
 * Notes:
 *  1. Conical shadow on the celestial sphere of the point: the Sun's and the
 *     Earth's discs are spherical caps of radii asin(R/distance) (computed as
 *     atan2(R, sqrt((D - R)(D + R)))), with the TRUE Sun distance from the
 *     point, and centres separated by the angle between sun - point and
 *     -point (oi_angle). fraction = visible area / cap area, the visible
 *     area being the Sun's cap segment beyond the chord through the two
 *     crossing points of the limbs minus the Earth's segment (the
 *     complement of oi_cap_overlap's lens, formed without cancellation).
 *  2. Regions: LIT (separation >= r_earth + r_sun, or the Earth's centre
 *     farther from the point than the Sun's: the Earth behind the Sun;
 *     fraction exactly 1),
 *     UMBRA (separation <= r_earth - r_sun; exactly 0), ANNULAR (separation
 *     <= r_sun - r_earth: the Earth's disc inside the Sun's, beyond the
 *     umbra's tip; fraction = 1 - A(r_earth)/A(r_sun)), else PENUMBRA.
 *  3. Limb darkening: Neckel & Labs (1994) fifth-degree polynomial at
 *     559.95 nm (V band). fraction_ld by Green's theorem: the flux hidden
 *     is a line integral, along the Earth's limb inside the Sun's disc, of
 *     the flux within a radius about the Sun's centre (a closed form, the
 *     polynomial integrated against a binomial series in tan^2 r_sun), plus
 *     that flux times the angle of the Sun's limb inside the Earth's disc;
 *     one 12-point Gauss-Legendre panel in a variable that makes the limb's
 *     square roots smooth (graded panels when the Earth's disc is nearly
 *     internally tangent to the Sun's, beyond the umbra's tip). For
 *     r_sun > 0.5 rad (an observer within 2.1 solar radii of the Sun's
 *     centre) or < 1e-15 rad, fraction_ld = fraction. With
 *     OI_NO_LIMB_DARKENING (include/oi_config.h) fraction_ld = fraction
 *     always, and a model with OI_LIMB_DARKENED gives OI_ERR_MODEL.
 *  4. Accuracy (docs/shadow.md), against an mpmath ring quadrature of the
 *     same geometry: double, fraction and fraction_ld within 8e-14 absolute
 *     (1 m altitude to 1e7 km, 0.983-1.017 AU, shadow edges to 1e-12 rad);
 *     single, within 3e-5: the fraction changes by about 1/(2 r_sun) ~ 1e2
 *     per radian of separation, so it is bounded by that times the rounding
 *     of the separation. Near the surface |point|^2 - R^2 is formed in
 *     compensated arithmetic (the rounding of |point| would dominate).
 *     fraction_ld for a Sun of r_sun = 0.2 / 0.41 rad: 7e-11 / 5e-7 (the
 *     series' truncation, below (tan^2 r_sun)^6).
 *  5. fraction_atm: without the atmosphere (model->no_atmosphere, or
 *     OI_NO_ATMOSPHERE) it equals fraction, or fraction_ld with
 *     OI_LIMB_DARKENED; otherwise src/atmosphere.c adds refraction and
 *     extinction at the marked place (and may return OI_WARN_TABLE_RANGE).
 * References:
 *   Montenbruck, O. & Gill, E. 2000, Satellite Orbits, Springer, sec. 3.4.2
 *   (conical shadow model; its planar two-circle overlap is what this
 *   function replaces by the exact spherical one).
 *   Neckel, H. & Labs, D. 1994, Sol. Phys. 153, 91 (limb darkening).
 *   Green's theorem in polar form: the flux over a region is the line
 *   integral of F(rho) dt around it, F(rho) the flux within rho (see
 *   fraction_limb_darkened).
 */
int oi_sun_fraction(const oi_real sun_km[3], const oi_real point_km[3],
                    const oi_model *model, oi_shadow *out)
{
    oi_model m;
    int st;
    if (out == NULL) return OI_ERR_NULL;
    memset(out, 0, sizeof *out);
    if (sun_km == NULL || point_km == NULL) return OI_ERR_NULL;
    st = oi__model_resolve(model, &m);
    if (st < 0) return st;
    return oi__sun_shadow(sun_km, point_km, &m, out, NULL);
}

/* oi_sun_fraction with a resolved model, and (light_dir not NULL, atmosphere
 * compiled in and on) the mean direction the sunlight arrives from: see
 * src/oi_internal.h. */
int oi__sun_shadow(const oi_real sun_km[3], const oi_real point_km[3], const oi_model *resolved,
                   oi_shadow *out, oi_real light_dir[3])
{
    const oi_model *m = resolved;
    oi_real ds, dp, dsp, rs, re, sep, frac, frac_ld, q_earth;
    int st = OI_OK, region;

    memset(out, 0, sizeof *out);
    if (!oi__finite3(sun_km) || !oi__finite3(point_km)) return OI_ERR_NONFINITE;
    ds = oi__norm(sun_km);
    dp = oi__norm(point_km);
    if (ds == (oi_real)0 || dp == (oi_real)0) return OI_ERR_ZERO_VECTOR;
    if (dp < (oi_real)2 * m->earth_radius_km) {
        /* near the surface: the sign of |p|^2 - R^2 decides, and its value
         * gives the Earth's apparent radius atan2(R, sqrt(|p|^2 - R^2)) */
        q_earth = radial_excess(point_km, m->earth_radius_km);
        if (!(q_earth > (oi_real)0)) return OI_ERR_BELOW_SURFACE;
    } else {
        q_earth = (oi_real)-1; /* far: the plain form is accurate */
    }
    if (ds <= m->sun_radius_km + m->earth_radius_km) return OI_ERR_GEOMETRY;
    {
        /* a block of its own: these arrays may share stack with the
         * penumbra's (make stack) */
        oi_real rel[3], anti[3];
        oi__sub(sun_km, point_km, rel);
        if (!oi__finite3(rel)) return OI_ERR_NONFINITE;
        dsp = oi__norm(rel);
        if (!OI_ISFINITE(dsp) || !OI_ISFINITE(dp)) return OI_ERR_NONFINITE;
        if (dsp <= m->sun_radius_km) return OI_ERR_GEOMETRY;
        /* the angle between sun - point and -point from the unit vectors of
         * the norms just formed (oi_angle would form them again) */
        anti[0] = -point_km[0];
        anti[1] = -point_km[1];
        anti[2] = -point_km[2];
        (void)oi__divide3(anti, dp, anti);
        (void)oi__divide3(rel, dsp, rel);
        sep = oi__angle_unit(rel, anti);
    }
    rs = apparent_radius(m->sun_radius_km, dsp);
    re = q_earth > (oi_real)0 ? OI_ATAN2(m->earth_radius_km, OI_SQRT(q_earth))
                              : apparent_radius(m->earth_radius_km, dp);

    if (sep >= re + rs || dp >= dsp) {
        /* discs apart, or the Earth behind the Sun (a point beyond the Sun:
         * whenever the discs overlap the three bodies are nearly collinear,
         * so the nearer one is in front) */
        region = OI_SHADOW_LIT;
        frac = frac_ld = (oi_real)1;
    } else if (sep <= re - rs) {
        region = OI_SHADOW_UMBRA;
        frac = frac_ld = (oi_real)0;
    } else {
        oi_real ssun = sin_half_sq(rs);
        oi_real pa_s = OI_PI_R; /* pi - alpha_s; pi when annular */
        oi_real hs[4];          /* the triangle's sines (penumbra) */
        const oi_real *tri = NULL;
        if (sep <= rs - re) {
            /* 1 - sin^2(re/2)/sin^2(rs/2), the difference of squares
             * factored: sin((rs - re)/2) sin((rs + re)/2) */
            region = OI_SHADOW_ANNULAR;
            frac = OI_SIN(OI_R(0.5) * (rs - re)) * OI_SIN(OI_R(0.5) * (rs + re)) / ssun;
        } else {
            /* the triangle (Sun's centre, Earth's centre, a crossing point
             * of the limbs): a_e at the Earth's centre, pi - a_s at the
             * Sun's, both from one set of sines */
            oi_real a_e;
            half_sines(rs, re, sep, hs);
            a_e = half_angle(hs, 1, 0);
            pa_s = half_angle(hs, 2, 1);
            region = OI_SHADOW_PENUMBRA;
            tri = hs;
            if (rs < (oi_real)1) {
                /* the visible part of the Sun's cap directly, as the Sun's
                 * segment beyond the chord of the two crossing points minus
                 * the Earth's segment (no 1 - overlap/area: keeps the
                 * relative accuracy of a thin crescent next to the umbra) */
                frac = (cap_segment(rs, pa_s) - cap_segment(re, a_e)) /
                       ((oi_real)4 * OI_PI_R * ssun);
            } else {
                /* a Sun of 1 rad or more (an observer within 0.19 solar
                 * radii of its surface): Gauss-Bonnet on the lens, as in
                 * overlap_small, 2 (pi - gamma) - 2 a_s cos rs - 2 a_e cos re
                 * (gamma the angle at the crossing point; the chord
                 * decomposition degenerates when both limbs approach great
                 * circles); absolute error a few eps */
                oi_real lens = (oi_real)2 * (half_angle(hs, 3, 1) -
                                             half_angle(hs, 2, 0) * OI_COS(rs) -
                                             a_e * OI_COS(re));
                frac = (oi_real)1 - lens / ((oi_real)4 * OI_PI_R * ssun);
            }
        }
        frac = clamp(frac, (oi_real)0, (oi_real)1);
#ifdef OI_NO_LIMB_DARKENING
        (void)pa_s;
        (void)tri;
        frac_ld = frac; /* the limb-darkened disc is compiled out */
#else
        /* beyond LD_RS_MAX (an observer within 2.1 solar radii of the Sun's
         * centre) or below 1e-15 rad the uniform disc stands in */
        frac_ld = rs <= LD_RS_MAX && rs > LD_RS_MIN
                      ? fraction_limb_darkened(rs, re, sep, pa_s, tri)
                      : frac;
#endif
    }

    out->fraction = frac;
    out->fraction_ld = frac_ld;
    /* ---- atmosphere: the single place where refraction and extinction will
     * modify the sunlight reaching the point (issue 3). Until then the
     * model's choice of disc, uniform or limb-darkened. */
    out->fraction_atm = m->limb_darkening == OI_LIMB_DARKENED ? frac_ld : frac;
#ifdef OI_NO_ATMOSPHERE
    (void)light_dir;
#else
    /* issue 4 (src/atmosphere.c): refraction and extinction from the baked
     * table; OI_WARN_TABLE_RANGE outside its z range (geometric kept). */
    if (!m->no_atmosphere)
        st = oi__atm_fraction(sun_km, point_km, m, frac, frac_ld, &out->fraction_atm, light_dir);
#endif
    /* ---- end atmosphere */
    out->sun_radius_rad = rs;
    out->earth_radius_rad = re;
    out->separation_rad = sep;
    out->sun_distance_km = dsp;
    out->region = region;
    return st;
}
