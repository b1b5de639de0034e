/* SPDX-License-Identifier: MIT */
/* cap_overlap.c: oi_cap_overlap, the exact area of the intersection of two
 * spherical caps. Formulas and measured accuracy: docs/shadow.md. */
#include "math/math_internal.h"

/* The angle opposite a (comp != 0: pi minus it); see oi__half_angle. */
static oi_real tri_angle(oi_real a, oi_real b, oi_real c, int comp)
{
    oi_real hs[4];
    oi__half_sines(a, b, c, hs);
    return oi__half_angle(hs, 1, comp);
}

/* Overlap of two caps with r1, r2 in [0, pi/2] and d in [0, pi]. */
static oi_real overlap_small(oi_real r1, oi_real r2, oi_real d)
{
    oi_real a1, a2, lens, amin, hs[4];
    oi_real rbig = r1 > r2 ? r1 : r2, rsmall = r1 > r2 ? r2 : r1;
    amin = (oi_real)4 * OI_PI_R * oi__sin_half_sq(rsmall);
    /* classification by differences, exact near the tangencies (Sterbenz),
     * instead of comparing d with the rounded r1 + r2 or r1 - r2 */
    if (d - rbig >= rsmall) return (oi_real)0;               /* disjoint */
    if (rbig - d >= rsmall) return amin;                     /* nested */
    /* triangle (C1, C2, P), P a crossing point of the two boundaries:
     * sides C1P = r1, C2P = r2, C1C2 = d; alpha1 at C1 is opposite r2. */
    oi__half_sines(r2, r1, d, hs);
    a1 = oi__half_angle(hs, 1, 0);
    a2 = oi__half_angle(hs, 2, 0);
    if (rsmall >= (oi_real)1) {
        /* two large caps: Gauss-Bonnet on the lens (two arcs of geodesic
         * curvature cot r and length 2 alpha sin r, two corners of exterior
         * angle gamma, the triangle's angle at P opposite d):
         *   lens = 2 (pi - gamma) - 2 alpha1 cos r1 - 2 alpha2 cos r2.
         * Used here because the chord decomposition degenerates when both
         * boundaries approach great circles (P and Q nearly antipodal); the
         * terms cancel at most to a few epsilon times the caps' area. */
        oi_real pg = oi__half_angle(hs, 3, 1); /* pi - gamma */
        lens = (oi_real)2 * (pg - a1 * OI_COS(r1) - a2 * OI_COS(r2));
    } else {
        lens = oi__cap_segment(r1, a1) + oi__cap_segment(r2, a2);
    }
    return oi__clamp(lens, (oi_real)0, amin);
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
    r1 = oi__clamp(r1, (oi_real)0, OI_PI_R);
    r2 = oi__clamp(r2, (oi_real)0, OI_PI_R);
    d = oi__clamp(d, (oi_real)0, OI_PI_R);
    if (r1 <= OI_HALF_PI_R && r2 <= OI_HALF_PI_R) return overlap_small(r1, r2, d);

    a1 = (oi_real)4 * OI_PI_R * oi__sin_half_sq(r1);
    a2 = (oi_real)4 * OI_PI_R * oi__sin_half_sq(r2);
    amin = a1 < a2 ? a1 : a2;
    if (r1 > OI_HALF_PI_R && r2 > OI_HALF_PI_R) {
        /* |K1 n K2| = A1 + A2 - 4 pi + |K1' n K2'|, K' the complements
         * (their centres are also d apart). A1 + A2 - 4 pi =
         * -4 pi cos((r1 + r2)/2) cos((r1 - r2)/2). */
        a = -(oi_real)4 * OI_PI_R * OI_COS(OI_R(0.5) * (r1 + r2)) * OI_COS(OI_R(0.5) * (r1 - r2)) +
            overlap_small(oi__pi_minus(r1), oi__pi_minus(r2), d);
    } else {
        /* one cap larger than a hemisphere: rb > pi/2 >= rs */
        oi_real rb = r1 > r2 ? r1 : r2, rs = r1 > r2 ? r2 : r1, ab = r1 > r2 ? a2 : a1;
        if (d - rb >= rs) return (oi_real)0;
        if (rb - d >= rs) return ab;
        if (oi__pi_minus(d) + oi__pi_minus(rb) <= rs) {
            /* the large cap's complement inside the small cap (the union is
             * the sphere): A_s - A(pi - rb) */
            a = ab - (oi_real)4 * OI_PI_R * oi__sin_half_sq(oi__pi_minus(rb));
            return oi__clamp(a, (oi_real)0, amin);
        }
        {
            /* angle at the large cap's centre (opposite rs), and at the
             * small cap's centre (opposite rb) */
            oi_real alb = tri_angle(rs, rb, d, 0);
            if (alb < (oi_real)1 && d + rs > OI_HALF_PI_R) {
                /* small lens near the large cap's edge: the signed segments
                 * lens = seg(rs, al_s) + seg(rb, al_b), where a cap beyond a
                 * hemisphere has the segment -seg(pi - rb, al_b) (its boundary
                 * curves away from the lens); no cancellation against the
                 * small cap's area */
                oi_real als = tri_angle(rb, rs, d, 0);
                a = oi__cap_segment(rs, als) - oi__cap_segment(oi__pi_minus(rb), alb);
            } else {
                /* |Kb n Ks| = As - |Kb' n Ks|, Kb' = cap(pi - rb) at pi - d */
                a = ab - overlap_small(oi__pi_minus(rb), rs, oi__pi_minus(d));
            }
        }
    }
    return oi__clamp(a, (oi_real)0, amin);
}
