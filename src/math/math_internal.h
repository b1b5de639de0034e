/* SPDX-License-Identifier: MIT */
/*
 * math_internal.h: private to the runtime (not part of the API):
 * the math layer (src/math/): spherical triangles and caps, the 8-point
 * Gauss-Legendre rule, the cap cubatures' break points (atan2 and sincos: oi_port.h).
 * A layer calls only the layers below it (docs/architecture.md); this
 * header includes the one below, so a file sees its layer and every lower one.
 */
#ifndef OI_MATH_INTERNAL_H
#define OI_MATH_INTERNAL_H

#include "oi_vector.h"

/* ---- spherical triangles and caps (src/math/spherical_triangle.c,
 * src/math/cap_segment.c, src/shadow/limb_darkening.c) */

/* sin^2(r/2): the cap area over 4 pi, without the cancellation of 1 - cos r. */
static inline oi_real oi__sin_half_sq(oi_real r)
{
    return oi__sqr(OI_SIN(OI_R(0.5) * r));
}

/* y + z - x for non-negative x, y, z, accurate when y + z is close to x:
 * the larger of y, z minus x is exact there (Sterbenz), then one rounding. */
static inline oi_real oi__side_excess(oi_real x, oi_real y, oi_real z)
{
    oi_real big = y > z ? y : z;
    oi_real small = y > z ? z : y;
    return (big - x) + small;
}

/* sin of an angle known to lie in [0, pi], accurate near pi too. */
static inline oi_real oi__sin_0_pi(oi_real x)
{
    return x <= OI_HALF_PI_R ? OI_SIN(x) : OI_SIN(oi__pi_minus(x));
}

/*
 * The sines of the spherical triangle with sides a, b, c (radians, triangle
 * inequalities assumed; rounding beyond them is clamped) used by the
 * half-angle formulas, s = (a + b + c)/2: hs[0] = sin s, hs[1] = sin(s - a),
 * hs[2] = sin(s - b), hs[3] = sin(s - c) (src/math/spherical_triangle.c).
 */
void oi__half_sines(oi_real a, oi_real b, oi_real c, oi_real hs[4]);

/* The angle opposite the side of index i (1: a, 2: b, 3: c) of the triangle
 * of oi__half_sines, or with comp != 0 pi minus it, without cancellation
 * (src/math/spherical_triangle.c). */
oi_real oi__half_angle(const oi_real hs[4], int i, int comp);

/* Area of the segment of a cap of radius r (<= pi/2) cut off by the great
 * circle through the two points of its boundary seen from the cap's centre
 * at +-alpha; negative for alpha > pi/2 (src/math/cap_segment.c). */
oi_real oi__cap_segment(oi_real r, oi_real alpha);

/* The 8-point Gauss-Legendre rule on [0, 1] (mpmath at 40 digits by Newton
 * iteration on P_8; tools/coeffs/quadrature.py prints them): the nodes
 * x < 1/2 and their weights, the nodes 1 - x sharing them. The constants
 * for the crescent kernel's unrolled rule (src/shadow/sun_crescent.h), and the
 * table oi__gl8 of the same values, rows (x, w), for the loops
 * (src/math/cap_segment.c, which defines it; src/shadow/oblate.c,
 * src/shadow/limb_darkened_union.c). */
#define OI_GL8_HALF 4
#define OI_GL8_X1 OI_R(0.0198550717512318841582)
#define OI_GL8_X2 OI_R(0.101666761293186630204)
#define OI_GL8_X3 OI_R(0.237233795041835507091)
#define OI_GL8_X4 OI_R(0.40828267875217509753)
#define OI_GL8_W1 OI_R(0.0506142681451881295763)
#define OI_GL8_W2 OI_R(0.111190517226687235272)
#define OI_GL8_W3 OI_R(0.156853322938943643669)
#define OI_GL8_W4 OI_R(0.181341891689180991483)
extern const oi_real oi__gl8[OI_GL8_HALF][2];

#ifndef OI_NO_MOON
/* Area (sr) of the intersection of the three caps of unit centres c[i] and
 * radii r[i] (radians, (0, pi)) (src/math/cap_triple.c). */
oi_real oi__cap_triple(const oi_real c[3][3], const oi_real r[3]);
#endif

/* Break points of the cap cubatures' polar angle (src/math/cap_breaks.c): bp
 * sorted, at most cap entries; start: 0, the horizon *a_max and the
 * terminator's tangency; altitude: up to n_geo multiples of it. at: start
 * given theta = OI_ATAN2(sin_theta, cos_theta), the same bits. */
int oi__cap_break_add(oi_real *bp, int cap, int n, oi_real x, oi_real a_max);
int oi__cap_breaks_start(oi_real *bp, int cap, oi_real hp, oi_real rp, oi_real cos_theta,
                         oi_real sin_theta, oi_real *a_max);
int oi__cap_breaks_at(oi_real *bp, int cap, oi_real hp, oi_real rp, oi_real theta,
                      oi_real *a_max);
int oi__cap_breaks_altitude(oi_real *bp, int cap, int n, int n_geo, oi_real hp, oi_real rp,
                            oi_real a_max);

#endif /* OI_MATH_INTERNAL_H */
