/* SPDX-License-Identifier: MIT */
/* cap_triple.c: oi__cap_triple, the area of the intersection of three
 * spherical caps (internal, declared in src/math/math_internal.h; used where the
 * Earth and the Moon both cover part of the Sun). docs/shadow.md section 9. */
#include "math/math_internal.h"

#ifndef OI_NO_MOON

/* How the boundary circle of cap i lies in cap j. */
enum { ARC_NONE = 0, ARC_ALL = 1, ARC_PART = 2 };

typedef struct {
    int kind;     /* ARC_* */
    oi_real mid;  /* angle about c_i of the arc's middle (towards c_j) */
    oi_real half; /* half-width of the arc inside cap j (ARC_PART) */
} cap_arc;

/* The circle of a cap in its own frame: centre c, radius r, and two unit
 * vectors e1, e2 = c x e1 normal to c (angles about c count from e1
 * towards e2: counterclockwise seen from outside the sphere). */
typedef struct {
    const oi_real *c;
    oi_real e1[3], e2[3], r, cos_r, sin_r;
} cap_circle;

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
 * of the triangle (c_i, c_j, crossing point) (half-angle formula, no
 * cancellation). */
static cap_arc arc_in_cap(oi_real ri, oi_real rj, oi_real d, oi_real phi)
{
    cap_arc a;
    oi_real hs[4];
    a.mid = phi;
    a.half = (oi_real)0;
    if (rj - d >= ri) {
        a.kind = ARC_ALL; /* cap i inside cap j */
    } else if (ri - d >= rj || d - ri >= rj) {
        a.kind = ARC_NONE; /* cap j inside cap i, or the caps apart */
    } else {
        a.kind = ARC_PART;
        oi__half_sines(ri, rj, d, hs);
        a.half = oi__half_angle(hs, 2, 0);
    }
    return a;
}

/* The point of the circle at angle phi. */
static void circle_point(const cap_circle *k, oi_real phi, oi_real p[3])
{
    oi_real s, c;
    int i;
    OI_SINCOS(phi, &s, &c);
    for (i = 0; i < 3; ++i) p[i] = k->cos_r * k->c[i] + k->sin_r * (c * k->e1[i] + s * k->e2[i]);
}

/* Signed spherical excess of the triangle (o, a, b) of unit vectors,
 * positive counterclockwise: tan(E/2) = o.(a x b) / (1 + o.a + a.b + b.o)
 * (Eriksson 1990), the triple product formed from the differences a - o,
 * b - o (small, and exact for nearby points) to keep its digits. */
static oi_real signed_excess(const oi_real o[3], const oi_real a[3], const oi_real b[3])
{
    oi_real da[3], db[3], x[3], num, den;
    oi__sub(a, o, da);
    oi__sub(b, o, db);
    oi__cross(da, db, x);
    num = oi__dot(o, x);
    den = (oi_real)1 + oi__dot(o, a) + oi__dot(a, b) + oi__dot(b, o);
    return (oi_real)2 * OI_ATAN2(num, den);
}

/* Area added by the arc [lo, hi] (hi > lo) of circle k, traversed
 * counterclockwise: its segment beyond the chord plus the signed triangle
 * from the reference point o to the chord. */
static oi_real arc_area(const cap_circle *k, oi_real lo, oi_real hi, const oi_real o[3])
{
    oi_real a[3], b[3];
    circle_point(k, lo, a);
    circle_point(k, hi, b);
    return oi__cap_segment(k->r, OI_R(0.5) * (hi - lo)) + signed_excess(o, a, b);
}

/* The area added by the arcs of circle k inside both caps of arcs p, q
 * (neither ARC_NONE, not both ARC_ALL); *n counts the arcs. */
static oi_real circle_area(const cap_circle *k, const cap_arc *p, const cap_arc *q,
                           const oi_real o[3], int *n)
{
    oi_real sum = (oi_real)0, m2, lo, hi;
    int side;
    if (p->kind == ARC_ALL || q->kind == ARC_ALL) {
        const cap_arc *a = p->kind == ARC_ALL ? q : p;
        ++*n;
        return arc_area(k, a->mid - a->half, a->mid + a->half, o);
    }
    /* two arcs: their common parts on the near side and around the far side */
    m2 = p->mid + wrap_pi(q->mid - p->mid);
    for (side = -1; side <= 1; ++side) {
        oi_real m = m2 + (oi_real)side * (oi_real)2 * OI_PI_R;
        lo = p->mid - p->half > m - q->half ? p->mid - p->half : m - q->half;
        hi = p->mid + p->half < m + q->half ? p->mid + p->half : m + q->half;
        if (hi > lo) {
            ++*n;
            sum += arc_area(k, lo, hi, o);
        }
    }
    return sum;
}

/* A unit vector normal to the unit vector c. */
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
 * radii r[i] (radians, (0, pi/2]). The intersection is convex; its boundary
 * is made of arcs of the three circles, each the part of its circle inside
 * the two other caps (intervals of angle about its centre, from the
 * half-angle formulas). Its area is that of the geodesic polygon of the
 * arcs' end points plus the cap segment beyond each arc's chord
 * (oi__cap_segment): the polygon as the sum of the signed triangles from the
 * first cap's centre to each chord, every term small where the caps are
 * small (no 2 pi - sum cancellation as in Gauss-Bonnet, which would lose
 * all the digits of single precision on the Sun's cap). With no arc the
 * intersection is empty or the smallest cap lying in both others.
 */
oi_real oi__cap_triple(const oi_real c[3][3], const oi_real r[3])
{
    oi_real d[3], area = (oi_real)0, smallest = (oi_real)-1, cap_min;
    int i, n = 0;
    /* d[i]: between the centres other than i */
    for (i = 0; i < 3; ++i) {
        d[i] = oi__angle_unit(c[(i + 1) % 3], c[(i + 2) % 3]);
        if (d[i] >= r[(i + 1) % 3] + r[(i + 2) % 3]) return (oi_real)0; /* two caps apart */
    }
    /* one circle at a time (its frame and its two arcs live only here: the
     * stack stays small) */
    for (i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        cap_circle ci;
        cap_arc p, q;
        ci.c = c[i];
        normal_to(c[i], ci.e1);
        oi__cross(c[i], ci.e1, ci.e2);
        ci.r = r[i];
        OI_SINCOS(r[i], &ci.sin_r, &ci.cos_r);
        /* the centres j, k are d[k], d[j] from centre i */
        p = arc_in_cap(r[i], r[j], d[k], OI_ATAN2(oi__dot(c[j], ci.e2), oi__dot(c[j], ci.e1)));
        q = arc_in_cap(r[i], r[k], d[j], OI_ATAN2(oi__dot(c[k], ci.e2), oi__dot(c[k], ci.e1)));
        if (p.kind == ARC_NONE || q.kind == ARC_NONE) continue;
        if (p.kind == ARC_ALL && q.kind == ARC_ALL) {
            if (smallest < (oi_real)0 || r[i] < smallest) smallest = r[i];
            continue;
        }
        area += circle_area(&ci, &p, &q, c[0], &n);
    }
    if (smallest >= (oi_real)0) return (oi_real)4 * OI_PI_R * oi__sin_half_sq(smallest);
    if (n == 0) return (oi_real)0;
    cap_min = r[0] < r[1] ? r[0] : r[1];
    cap_min = cap_min < r[2] ? cap_min : r[2];
    return oi__clamp(area, (oi_real)0, (oi_real)4 * OI_PI_R * oi__sin_half_sq(cap_min));
}

#endif /* OI_NO_MOON */
