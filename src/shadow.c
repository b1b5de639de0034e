/* SPDX-License-Identifier: MIT */
/* shadow.c: exact overlap of two spherical caps, and the visible fraction of
 * the Sun (uniform and limb-darkened disc) seen from a point near the Earth.
 * Model, formulas and measured accuracy: docs/shadow.md. */
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
 * Angle of a spherical triangle with sides a, b, c (radians, triangle
 * inequalities assumed; rounding beyond them is clamped) opposite the side a,
 * by the half-angle formula (l'Huilier's family):
 *   tan(A/2) = sqrt( sin(s-b) sin(s-c) / (sin s sin(s-a)) ),  s = (a+b+c)/2.
 * With comp != 0 it returns pi - A instead, from the reciprocal ratio, so
 * that neither A nor pi - A is formed by a cancelling subtraction.
 */
static void tri_angle2(oi_real a, oi_real b, oi_real c, oi_real *ang, oi_real *comp);

static oi_real tri_angle(oi_real a, oi_real b, oi_real c, int comp)
{
    oi_real x, y;
    tri_angle2(a, b, c, &x, &y);
    return comp ? y : x;
}

/* Both A and pi - A (see tri_angle) from one set of sines. */
static void tri_angle2(oi_real a, oi_real b, oi_real c, oi_real *ang, oi_real *comp)
{
    oi_real ss = sin_0_pi(OI_R(0.5) * (a + (b + c)));
    oi_real sa = OI_SIN(OI_R(0.5) * side_excess(a, b, c));
    oi_real sb = OI_SIN(OI_R(0.5) * side_excess(b, a, c));
    oi_real sc = OI_SIN(OI_R(0.5) * side_excess(c, a, b));
    oi_real num, den;
    ss = ss > (oi_real)0 ? ss : (oi_real)0;
    sa = sa > (oi_real)0 ? sa : (oi_real)0;
    sb = sb > (oi_real)0 ? sb : (oi_real)0;
    sc = sc > (oi_real)0 ? sc : (oi_real)0;
    num = OI_SQRT(sb) * OI_SQRT(sc);
    den = OI_SQRT(ss) * OI_SQRT(sa);
    if (num == (oi_real)0 && den == (oi_real)0) {
        /* degenerate (a point-like triangle): A = 0 */
        *ang = (oi_real)0;
        *comp = OI_PI_R;
        return;
    }
    *ang = (oi_real)2 * OI_ATAN2(num, den);
    *comp = (oi_real)2 * OI_ATAN2(den, num);
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
 * J by the 16-point Gauss-Legendre rule (the integrand is analytic in a
 * disc of radius > 1 about [0, 1/2], so the rule is exact to rounding).
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
    oi_real a1, a2, lens, amin;
    oi_real rbig = r1 > r2 ? r1 : r2, rsmall = r1 > r2 ? r2 : r1;
    amin = (oi_real)4 * OI_PI_R * sin_half_sq(rsmall);
    /* classification by differences, exact near the tangencies (Sterbenz),
     * instead of comparing d with the rounded r1 + r2 or r1 - r2 */
    if (d - rbig >= rsmall) return (oi_real)0;               /* disjoint */
    if (rbig - d >= rsmall) return amin;                     /* nested */
    /* triangle (C1, C2, P), P a crossing point of the two boundaries:
     * sides C1P = r1, C2P = r2, C1C2 = d; alpha1 at C1 is opposite r2. */
    a1 = tri_angle(r2, r1, d, 0);
    a2 = tri_angle(r1, r2, d, 0);
    if (rsmall >= (oi_real)1) {
        /* two large caps: Gauss-Bonnet on the lens (two arcs of geodesic
         * curvature cot r and length 2 alpha sin r, two corners of exterior
         * angle gamma, the triangle's angle at P opposite d):
         *   lens = 2 (pi - gamma) - 2 alpha1 cos r1 - 2 alpha2 cos r2.
         * Used here because the chord decomposition degenerates when both
         * boundaries approach great circles (P and Q nearly antipodal); the
         * terms cancel at most to a few epsilon times the caps' area. */
        oi_real pg = tri_angle(d, r1, r2, 1); /* pi - gamma */
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

/* ---------------------------------------------------------------- limb darkening */

/*
 * Solar limb darkening I(mu)/I(1) = sum_k A_k mu^k, the fifth-degree
 * polynomial of Neckel & Labs (1994, Sol. Phys. 153, 91; their coefficient table) at their
 * continuum wavelength 559.95 nm, the one nearest the V band's 550 nm. The
 * coefficients sum to 1 (I(1) = 1); I(0) = 0.269.
 */
static oi_real limb_intensity(oi_real mu)
{
    oi_real p = OI_R(0.37295);
    p = p * mu - OI_R(1.31350);
    p = p * mu + OI_R(1.91271);
    p = p * mu - OI_R(1.58427);
    p = p * mu + OI_R(1.34319);
    p = p * mu + OI_R(0.26892);
    return p;
}

/* 16-point Gauss-Legendre rule on [0, 1]: the nodes x below and 1 - x
 * share the weights (computed with mpmath at 40 digits by Newton iteration
 * on P_16; tests/ref/gen_refs.py --gauss 16 prints them). */
#define GL_HALF 8
static const oi_real gl_node[GL_HALF][2] = {
    {OI_R(0.00529953250417503370192), OI_R(0.0135762297058770474259)},
    {OI_R(0.027712488463383711961), OI_R(0.0311267619693239464314)},
    {OI_R(0.0671843988060841280598), OI_R(0.047579255841246392405)},
    {OI_R(0.122297795822498483052), OI_R(0.0623144856277669360262)},
    {OI_R(0.191061877798678125777), OI_R(0.0747979944082883660408)},
    {OI_R(0.270991611171386306829), OI_R(0.0845782596975012690947)},
    {OI_R(0.359198224610370543385), OI_R(0.0913017075224617944334)},
    {OI_R(0.452493745081181279907), OI_R(0.0947253052275342481427)},
};

/* 8-point Gauss-Legendre rule on [0, 1], same layout (--gauss 8): for the
 * limb-darkened rings. */
#define GL8_HALF 4
static const oi_real gl8_node[GL8_HALF][2] = {
    {OI_R(0.0198550717512318841582), OI_R(0.0506142681451881295763)},
    {OI_R(0.101666761293186630204), OI_R(0.111190517226687235272)},
    {OI_R(0.237233795041835507091), OI_R(0.156853322938943643669)},
    {OI_R(0.40828267875217509753), OI_R(0.181341891689180991483)},
};

/* J(alpha) = int_0^alpha sin^2 u / (1 - k2 sin^2 u) du, k2 = sin^2 r <= 1,
 * alpha < 1/2: Gauss-Legendre, 16 nodes. */
static oi_real gauss_j(oi_real alpha, oi_real k2)
{
    oi_real sum = (oi_real)0;
    int i, j;
    for (i = 0; i < GL_HALF; ++i) {
        for (j = 0; j < 2; ++j) {
            oi_real x = j ? (oi_real)1 - gl_node[i][0] : gl_node[i][0];
            oi_real su = OI_SIN(alpha * x);
            oi_real s2 = su * su;
            sum += gl_node[i][1] * s2 / ((oi_real)1 - k2 * s2);
        }
    }
    return alpha * sum;
}

/*
 * Flux of the disc between mu_a and mu_b (mu_a < mu_b), in units of
 * sin^2(r_s): with x = sin(rho)/sin(r_s) the normalised radius, mu =
 * sqrt(1 - x^2) and sin(rho) drho = sin^2(r_s) mu dmu / sqrt(cos^2 r_s +
 * sin^2 r_s mu^2): a smooth integrand in mu, so Gauss-Legendre converges
 * fast (the limb's square root is absorbed by the change of variable).
 */
static oi_real ring_flux(oi_real mu_a, oi_real mu_b, oi_real c2, oi_real s2)
{
    oi_real h = mu_b - mu_a, sum = (oi_real)0;
    int i, j;
    if (!(h > (oi_real)0)) return (oi_real)0;
    /* a degree-6 polynomial times (c2 + s2 mu^2)^(-1/2), s2 / c2 < 1e-3 in
     * practice: the 8-point rule (exact to degree 15) suffices */
    for (i = 0; i < GL8_HALF; ++i) {
        for (j = 0; j < 2; ++j) {
            oi_real x = j ? (oi_real)1 - gl8_node[i][0] : gl8_node[i][0];
            oi_real mu = mu_a + h * x;
            sum += gl8_node[i][1] * limb_intensity(mu) * mu / OI_SQRT(c2 + s2 * mu * mu);
        }
    }
    return h * sum;
}

/* mu at the angular distance rho <= r_s from the disc centre:
 * sqrt(1 - sin^2 rho / sin^2 r_s), formed from sin r_s - sin rho =
 * 2 cos((r_s + rho)/2) sin((r_s - rho)/2) (no cancellation at the limb). */
static oi_real mu_at(oi_real rho, oi_real rs, oi_real sin_rs)
{
    oi_real dm = (oi_real)2 * OI_COS(OI_R(0.5) * (rs + rho)) * OI_SIN(OI_R(0.5) * (rs - rho));
    oi_real dp = sin_rs + OI_SIN(rho);
    oi_real q = dm * dp;
    if (!(q > (oi_real)0)) return (oi_real)0;
    q = OI_SQRT(q) / sin_rs;
    return q < (oi_real)1 ? q : (oi_real)1;
}

/*
 * Visible and hidden flux of the rings rho in [b1, be] of the limb-darkened
 * solar disc (radius rs), each ring of radius rho being hidden over the arc
 * 2 phi0 where phi0 is the angle at the Sun's centre S in the triangle
 * (S, Earth centre E, boundary point X) with sides SX = rho, SE = sep,
 * EX = re. The change of variable rho = b1 + (be - b1) sin^2(theta) makes the
 * square-root behaviour at both ends (partial rings start and stop; the
 * limb) smooth in theta. This adds the panel theta in [ta, tb] (8 nodes).
 * Units as ring_flux.
 */
static void partial_panel(oi_real ta, oi_real tb, oi_real b1, oi_real w, int be_is_limb,
                          oi_real rs, oi_real re, oi_real sep, oi_real sin_rs, oi_real *vis,
                          oi_real *hid)
{
    oi_real sv = (oi_real)0, sh = (oi_real)0, s2 = sqr(sin_rs), h = tb - ta;
    const oi_real(*node)[2] = gl8_node;
    int i, j;
    for (i = 0; i < GL8_HALF; ++i) {
        for (j = 0; j < 2; ++j) {
            oi_real x = j ? (oi_real)1 - node[i][0] : node[i][0];
            oi_real th = ta + h * x;
            oi_real sn = OI_SIN(th), cs = OI_COS(th);
            oi_real rho = b1 + w * sn * sn;
            oi_real mu, base, phi0, pphi0;
            if (be_is_limb) {
                /* rs - rho = w cos^2(theta) exactly as a product */
                oi_real gap = w * cs * cs;
                oi_real dm = (oi_real)2 * OI_COS(OI_R(0.5) * (rs + rho)) * OI_SIN(OI_R(0.5) * gap);
                oi_real q = dm * (sin_rs + OI_SIN(rho));
                mu = q > (oi_real)0 ? OI_SQRT(q) / sin_rs : (oi_real)0;
                if (mu > (oi_real)1) mu = (oi_real)1;
            } else {
                mu = mu_at(rho, rs, sin_rs);
            }
            /* ring weight I(mu) sin(rho) drho / sin^2 r_s, drho = w sin 2theta dtheta */
            base = node[i][1] * limb_intensity(mu) * OI_SIN(rho) * (oi_real)2 * sn * cs / s2;
            tri_angle2(re, rho, sep, &phi0, &pphi0);  /* phi0, pi - phi0 */
            sh += base * phi0;
            sv += base * pphi0;
        }
    }
    *vis += sv * w * h / OI_PI_R;
    *hid += sh * w * h / OI_PI_R;
}

/*
 * The partial rings [b1, be]. Another square-root point may lie a small
 * distance beyond either end: beyond be, the limb (when be = b2) or b2 (when
 * be is the limb), when the Earth's disc is nearly internally tangent to the
 * Sun's; before b1, the mirror point -b1 of the partial rings' start when b1
 * is small (the Earth's limb close to the Sun's centre). A point at distance
 * `near` beyond an end sits at theta = end +- i sqrt(near / w): each half of
 * [0, pi/2] is then cut into panels graded geometrically towards that end
 * until the last is narrower than half that distance, so every panel sees
 * the singularity at least about its own width away (Gauss-Legendre then
 * converges geometrically). All panels use the 8-point rule (measured: the
 * same 4e-14 against mpmath as 16-point panels). At most 4 + 2 x 40
 * panels; four when nothing is near.
 */
static void partial_half(oi_real t_far, oi_real t_end, oi_real near, oi_real b1, oi_real w,
                         int be_is_limb, oi_real rs, oi_real re, oi_real sep, oi_real sin_rs,
                         oi_real *vis, oi_real *hid)
{
    /* t_end is the end the singularity is near; t_far the middle */
    oi_real q = t_end - t_far, lim;
    int k;
    if (!(near > (oi_real)0) || !(near < OI_R(0.25) * w)) {
        partial_panel(t_far < t_end ? t_far : t_end, t_far < t_end ? t_end : t_far, b1, w,
                      be_is_limb, rs, re, sep, sin_rs, vis, hid);
        return;
    }
    lim = OI_R(0.5) * OI_SQRT(near / w);
    for (k = 0; k < 40 && OI_FABS(q) > lim; ++k) {
        oi_real a = t_end - q, b = t_end - OI_R(0.5) * q;
        partial_panel(a < b ? a : b, a < b ? b : a, b1, w, be_is_limb, rs, re, sep, sin_rs, vis,
                      hid);
        q *= OI_R(0.5);
    }
    {
        oi_real a = t_end - q;
        partial_panel(a < t_end ? a : t_end, a < t_end ? t_end : a, b1, w, be_is_limb, rs, re,
                      sep, sin_rs, vis, hid);
    }
}

static void partial_flux(oi_real b1, oi_real be, int be_is_limb, oi_real near_end, oi_real rs,
                         oi_real re, oi_real sep, oi_real sin_rs, oi_real *vis, oi_real *hid)
{
    oi_real w = be - b1, mid = OI_R(0.25) * OI_PI_R;
    *vis = *hid = (oi_real)0;
    if (!(w > (oi_real)0)) return;
    /* four base panels of 8 points: [0, pi/8] (graded towards 0 when b1 is
     * small), [pi/8, pi/4], [pi/4, 3pi/8], [3pi/8, pi/2] (graded towards pi/2
     * when an internal tangency is near). Three panels of 16 points give the
     * same accuracy (4e-14) at 1.5 times the cost; three of 8 leave 1.3e-10. */
    partial_half(mid, OI_R(0.125) * OI_PI_R, (oi_real)0, b1, w, be_is_limb, rs, re, sep, sin_rs,
                 vis, hid);
    partial_half(OI_R(0.125) * OI_PI_R, (oi_real)0, (oi_real)2 * b1, b1, w, be_is_limb, rs, re,
                 sep, sin_rs, vis, hid);
    partial_half(mid, OI_R(0.375) * OI_PI_R, (oi_real)0, b1, w, be_is_limb, rs, re, sep, sin_rs,
                 vis, hid);
    partial_half(OI_R(0.375) * OI_PI_R, HALF_PI_R, near_end, b1, w, be_is_limb, rs, re, sep,
                 sin_rs, vis, hid);
}

/* Visible fraction of the limb-darkened solar disc (radius rs) when the
 * Earth's disc (radius re) is sep away; only called when the discs'
 * boundaries cross or the Earth's disc lies inside the Sun's. */
static oi_real fraction_limb_darkened(oi_real rs, oi_real re, oi_real sep)
{
    oi_real sin_rs = OI_SIN(rs), cos_rs = OI_COS(rs);
    oi_real c2 = sqr(cos_rs), s2 = sqr(sin_rs);
    oi_real b1 = OI_FABS(sep - re);   /* rings inside b1: all hidden or all visible */
    oi_real b2 = sep + re;            /* rings beyond b2: all visible */
    oi_real vis = (oi_real)0, hid = (oi_real)0, pv, ph, inner, total;
    int limb = !(b2 < rs);
    oi_real be = limb ? rs : b2;
    if (b1 > rs) b1 = rs;
    /* rings rho < b1, i.e. mu in [mu(b1), 1] */
    inner = ring_flux(mu_at(b1, rs, sin_rs), (oi_real)1, c2, s2);
    if (sep < re) hid += inner; else vis += inner;
    /* rings b2 < rho < rs, i.e. mu in [0, mu(b2)] */
    if (!limb) vis += ring_flux((oi_real)0, mu_at(b2, rs, sin_rs), c2, s2);
    /* the other square-root point near be: b2 just beyond the limb, or the
     * limb just beyond b2 (the Earth's disc internally tangent to the Sun's,
     * beyond the umbra's tip) */
    partial_flux(b1, be, limb, OI_FABS(b2 - rs), rs, re, sep, sin_rs, &pv, &ph);
    vis += pv;
    hid += ph;
    total = vis + hid;
    if (!(total > (oi_real)0)) return (oi_real)0;
    return clamp(vis / total, (oi_real)0, (oi_real)1);
}

/* ---------------------------------------------------------------- sun fraction */

/*
 * Error-free transformations (Dekker 1971; Knuth TAOCP 2, 4.2.2): a*a =
 * hi + lo exactly, with Veltkamp's split (2^27 + 1 for double, 2^12 + 1 for
 * float); a + b = s + e exactly. Needs round-to-nearest in the working
 * precision (no x87 extended registers). The split's product goes through a
 * volatile so that a compiler contracting floating-point expressions
 * (-ffp-contract=fast, the GNU C default on FMA targets) cannot fuse
 * t - a = fl(S a) - a into an exact fma, which would break the split; the
 * later partial products are exact, so fusing them changes nothing.
 */
#ifdef OI_SINGLE_PRECISION
#define SPLITTER OI_R(4097.0)
#else
#define SPLITTER OI_R(134217729.0)
#endif

static void two_square(oi_real a, oi_real *hi, oi_real *lo)
{
    volatile oi_real tv = SPLITTER * a;
    oi_real t = tv;
    oi_real ah = t - (t - a);
    oi_real al = a - ah;
    *hi = a * a;
    *lo = ((ah * ah - *hi) + (oi_real)2 * ah * al) + al * al;
}

static void two_sum(oi_real a, oi_real b, oi_real *s, oi_real *e)
{
    oi_real bb;
    *s = a + b;
    bb = *s - a;
    *e = (a - (*s - bb)) + (b - bb);
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
        two_sum(sh, h, &sh, &e);
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
 *     559.95 nm (V band). fraction_ld integrates the disc's intensity over
 *     rings about the Sun's centre (exact spherical ring geometry) times the
 *     uncovered arc of each ring, with fixed 8-point Gauss-Legendre panels on
 *     each piece between the rings where covering starts or stops (graded
 *     panels when the Earth's disc is nearly internally tangent to the
 *     Sun's, beyond the umbra's tip).
 *  4. Accuracy (docs/shadow.md), against an mpmath ring quadrature of the
 *     same geometry: double, fraction and fraction_ld within 8e-14 absolute
 *     (1 m altitude to 1e7 km, 0.983-1.017 AU, shadow edges to 1e-12 rad);
 *     single, within 3e-5: the fraction changes by about 1/(2 r_sun) ~ 1e2
 *     per radian of separation, so it is bounded by that times the rounding
 *     of the separation. Near the surface |point|^2 - R^2 is formed in
 *     compensated arithmetic (the rounding of |point| would dominate).
 *  5. fraction_atm: without the atmosphere (model->no_atmosphere, or
 *     OI_NO_ATMOSPHERE) it equals fraction, or fraction_ld with
 *     OI_LIMB_DARKENED; otherwise src/atmosphere.c adds refraction and
 *     extinction at the marked place (and may return OI_WARN_TABLE_RANGE).
 * References:
 *   Montenbruck, O. & Gill, E. 2000, Satellite Orbits, Springer, sec. 3.4.2
 *   (conical shadow model; its planar two-circle overlap is what this
 *   function replaces by the exact spherical one).
 *   Neckel, H. & Labs, D. 1994, Sol. Phys. 153, 91 (limb darkening).
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
int oi__sun_shadow(const oi_real sun_km[3], const oi_real point_km[3], const oi_model *model,
                   oi_shadow *out, oi_real light_dir[3])
{
    const oi_model *m = model;
    oi_real rel[3], anti[3];
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
    oi__sub(sun_km, point_km, rel);
    if (!oi__finite3(rel)) return OI_ERR_NONFINITE;
    dsp = oi__norm(rel);
    if (!OI_ISFINITE(dsp) || !OI_ISFINITE(dp)) return OI_ERR_NONFINITE;
    if (dsp <= m->sun_radius_km) return OI_ERR_GEOMETRY;

    anti[0] = -point_km[0];
    anti[1] = -point_km[1];
    anti[2] = -point_km[2];
    sep = oi_angle(rel, anti);
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
        if (sep <= rs - re) {
            /* 1 - sin^2(re/2)/sin^2(rs/2), the difference of squares
             * factored: sin((rs - re)/2) sin((rs + re)/2) */
            region = OI_SHADOW_ANNULAR;
            frac = OI_SIN(OI_R(0.5) * (rs - re)) * OI_SIN(OI_R(0.5) * (rs + re)) / ssun;
        } else if (rs < (oi_real)1) {
            /* the visible part of the Sun's cap directly, as the Sun's
             * segment beyond the chord of the two crossing points minus the
             * Earth's segment (no 1 - overlap/area: keeps the relative
             * accuracy of a thin crescent next to the umbra); the angle at
             * the Sun's centre enters as pi - alpha_s from tri_angle */
            oi_real a_e = tri_angle(rs, re, sep, 0);
            oi_real pa_s = tri_angle(re, rs, sep, 1);
            region = OI_SHADOW_PENUMBRA;
            frac = (cap_segment(rs, pa_s) - cap_segment(re, a_e)) /
                   ((oi_real)4 * OI_PI_R * ssun);
        } else {
            region = OI_SHADOW_PENUMBRA;
            frac = (oi_real)1 - oi_cap_overlap(re, rs, sep) / ((oi_real)4 * OI_PI_R * ssun);
        }
        frac = clamp(frac, (oi_real)0, (oi_real)1);
        frac_ld = fraction_limb_darkened(rs, re, sep);
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
