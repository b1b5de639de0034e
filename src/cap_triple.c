/* SPDX-License-Identifier: MIT */
/* cap_triple.c: oi__cap_triple, the area of the intersection of three
 * spherical caps (internal, declared in src/oi_internal.h; used where the
 * Earth and the Moon both cover part of the Sun). docs/shadow.md section 6. */
#include "oi_internal.h"

#ifndef OI_NO_MOON

/* How the boundary circle of cap i lies in cap j. */
enum { ARC_NONE = 0, ARC_ALL = 1, ARC_PART = 2 };

typedef struct {
    int kind;     /* ARC_* */
    oi_real mid;  /* angle about c_i of the arc's middle (towards c_j) */
    oi_real half; /* half-width of the arc inside cap j (ARC_PART) */
    oi_real turn; /* angle at the crossing point between the two circles' radii */
} cap_arc;

/* x reduced to [-pi, pi] for |x| <= 3 pi. */
static oi_real wrap_pi(oi_real x)
{
    const oi_real two_pi = (oi_real)2 * OI_PI_R;
    if (x > OI_PI_R) x -= two_pi;
    if (x > OI_PI_R) x -= two_pi;
    if (x < -OI_PI_R) x += two_pi;
    if (x < -OI_PI_R) x += two_pi;
    return x;
}

/* The part of circle i (radius ri) inside cap j (radius rj), centres d
 * apart, c_j seen at angle phi about c_i. The half-width is the angle at c_i
 * of the triangle (c_i, c_j, crossing point), the turn its angle at the
 * crossing point (half-angle formulas, no cancellation). */
static cap_arc arc_in_cap(oi_real ri, oi_real rj, oi_real d, oi_real phi)
{
    cap_arc a;
    oi_real hs[4];
    a.mid = phi;
    a.half = (oi_real)0;
    a.turn = (oi_real)0;
    if (rj - d >= ri) {
        a.kind = ARC_ALL; /* cap i inside cap j */
    } else if (ri - d >= rj || d - ri >= rj) {
        a.kind = ARC_NONE; /* cap j inside cap i, or the caps apart */
    } else {
        a.kind = ARC_PART;
        oi__half_sines(ri, rj, d, hs);
        a.half = oi__half_angle(hs, 2, 0);
        a.turn = oi__half_angle(hs, 3, 0);
    }
    return a;
}

/* Measure of the intersection of two arcs of one circle. */
static oi_real arcs_common(const cap_arc *a, const cap_arc *b)
{
    oi_real delta, lo, one, two;
    if (a->kind == ARC_NONE || b->kind == ARC_NONE) return (oi_real)0;
    if (a->kind == ARC_ALL && b->kind == ARC_ALL) return (oi_real)2 * OI_PI_R;
    if (a->kind == ARC_ALL) return (oi_real)2 * b->half;
    if (b->kind == ARC_ALL) return (oi_real)2 * a->half;
    delta = OI_FABS(wrap_pi(a->mid - b->mid));
    lo = (oi_real)2 * (a->half < b->half ? a->half : b->half);
    /* the overlap on the near side of the circle, and the one around the
     * far side (two pieces when the arcs together exceed the circle) */
    one = oi__clamp(a->half + b->half - delta, (oi_real)0, lo);
    two = oi__clamp(a->half + b->half - ((oi_real)2 * OI_PI_R - delta), (oi_real)0, lo);
    return one + two < lo ? one + two : lo;
}

/* Whether the point at angle phi on circle i lies in the cap of arc a. */
static int on_arc(const cap_arc *a, oi_real phi)
{
    if (a->kind != ARC_PART) return a->kind == ARC_ALL;
    return OI_FABS(wrap_pi(phi - a->mid)) <= a->half;
}

/* A unit vector normal to the unit vector c (the frame's first axis). */
static void normal_to(const oi_real c[3], oi_real e[3])
{
    oi_real axis[3] = {0, 0, 0};
    const oi_real x = OI_FABS(c[0]), y = OI_FABS(c[1]), z = OI_FABS(c[2]);
    axis[x <= y && x <= z ? 0 : (y <= z ? 1 : 2)] = (oi_real)1;
    oi__cross(c, axis, e);
    (void)oi__unit_bounded(e, e);
}

/*
 * Area (sr) of the intersection of the three caps of unit centres c[i] and
 * radii r[i] (radians, (0, pi)). Gauss-Bonnet on the intersection: its
 * boundary is made of arcs of the three circles, of geodesic curvature
 * cot r (an arc of angle L about its centre contributes L cos r), meeting
 * at corners where two circles cross inside the third, each turning by the
 * angle between the circles' radii there:
 *   area = 2 pi - sum_i L_i cos r_i - sum_corners turn.
 * With no corner the intersection is empty or the smallest cap that lies in
 * both others. Absolute error a few epsilon times 2 pi (the terms cancel
 * for small caps): 1e-15 sr in double, against 6.7e-5 sr for the Sun's cap
 * seen from the Earth.
 */
oi_real oi__cap_triple(const oi_real c[3][3], const oi_real r[3])
{
    cap_arc arc[3][3]; /* arc[i][j]: circle i in cap j */
    oi_real e1[3], e2[3], area, sum_arcs = (oi_real)0, sum_turns = (oi_real)0;
    oi_real smallest = (oi_real)-1, cap_min;
    int i, j, k, s, corners = 0;
    for (i = 0; i < 3; ++i) {
        normal_to(c[i], e1);
        oi__cross(c[i], e1, e2);
        for (j = 0; j < 3; ++j) {
            oi_real d, phi;
            if (j == i) continue;
            d = oi__angle_unit(c[i], c[j]);
            if (d >= r[i] + r[j]) return (oi_real)0; /* two caps apart */
            phi = OI_ATAN2(oi__dot(c[j], e2), oi__dot(c[j], e1));
            arc[i][j] = arc_in_cap(r[i], r[j], d, phi);
        }
    }
    for (i = 0; i < 3; ++i) {
        j = (i + 1) % 3;
        k = (i + 2) % 3;
        sum_arcs += arcs_common(&arc[i][j], &arc[i][k]) * OI_COS(r[i]);
        if (arc[i][j].kind == ARC_ALL && arc[i][k].kind == ARC_ALL &&
            (smallest < (oi_real)0 || r[i] < smallest))
            smallest = r[i];
        /* corners of circles i and j (each pair once), inside cap k */
        if (arc[i][j].kind != ARC_PART) continue;
        for (s = -1; s <= 1; s += 2) {
            oi_real phi = arc[i][j].mid + (oi_real)s * arc[i][j].half;
            if (on_arc(&arc[i][k], phi)) {
                sum_turns += arc[i][j].turn;
                ++corners;
            }
        }
    }
    if (corners == 0)
        return smallest < (oi_real)0 ? (oi_real)0
                                     : (oi_real)4 * OI_PI_R * oi__sin_half_sq(smallest);
    area = (oi_real)2 * OI_PI_R - sum_arcs - sum_turns;
    cap_min = r[0] < r[1] ? r[0] : r[1];
    cap_min = cap_min < r[2] ? cap_min : r[2];
    return oi__clamp(area, (oi_real)0, (oi_real)4 * OI_PI_R * oi__sin_half_sq(cap_min));
}

#endif /* OI_NO_MOON */
