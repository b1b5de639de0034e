/* SPDX-License-Identifier: MIT */
/*
 * sun_crescent.h: the penumbra's uniform-disc fraction behind the spherical
 * Earth from the two positions, branch-free (oi__crescent_row), so that the
 * batch (src/batch/batch.c) runs it over many rows at once in a loop the compiler
 * vectorises, and the single call (src/shadow/sun_fraction.c, through the one
 * out-of-line copy in src/shadow/sun_crescent.c) forms the same bits for one row.
 * Double precision only (OI_CRESCENT_KERNEL); the single-precision build keeps
 * the angle-based crescent of src/shadow/sun_fraction.c. Formulas and accuracy:
 * docs/shadow.md, "The crescent kernel".
 *
 * Bit-identity of the two callers rests on every operation rounding once in
 * the order written: C99 with -std=c99 (GCC: -ffp-contract=off), no
 * -ffast-math. Every value is an oi_real and every choice a select, so that
 * GCC if-converts the loop (with trapping math off for that loop only; the
 * exceptions its discarded lanes raise are masked and cleared by the
 * caller, src/fp_quiet.h).
 */
#ifndef OI_SUN_CRESCENT_H
#define OI_SUN_CRESCENT_H

#include "shadow/shadow_internal.h"

#ifndef OI_SINGLE_PRECISION
#define OI_CRESCENT_KERNEL 1

/* Inlined into the batch's loop whatever its size (OI_ALWAYS_INLINE). */
#define OI_CRESCENT_INLINE static OI_ALWAYS_INLINE

/* Veltkamp's split without oi__split's volatile (a vectorised loop cannot
 * hold one): exact when products are not fused (see above). */
OI_CRESCENT_INLINE void oi__crescent_split(oi_real a, oi_real *hi, oi_real *lo)
{
    const oi_real t = OI_SPLITTER * a;
    *hi = t - (t - a);
    *lo = a - *hi;
}

/* oi__two_sum's TwoSum, inlined here too (a function of other optimisation
 * options, as the batch's loop has, is not inlined otherwise). */
OI_CRESCENT_INLINE oi_real oi__crescent_two_sum(oi_real a, oi_real b, oi_real *e)
{
    const oi_real s = a + b;
    const oi_real bb = s - a;
    *e = (a - (s - bb)) + (b - bb);
    return s;
}

/* a * a = *hi + *lo exactly (Dekker). */
OI_CRESCENT_INLINE void oi__crescent_square(oi_real a, oi_real *hi, oi_real *lo)
{
    oi_real ah, al;
    oi__crescent_split(a, &ah, &al);
    *hi = a * a;
    *lo = ((ah * ah - *hi) + (oi_real)2 * ah * al) + al * al;
}

/* atan z for 0 <= z <= tan(pi/32): Taylor series to z^17 (the first term
 * left out, z^19/19, is below 2^-60 z there). */
OI_CRESCENT_INLINE oi_real oi__crescent_atan_small(oi_real z)
{
    const oi_real w = z * z;
    oi_real p = (oi_real)1 / (oi_real)17;
    p = p * w - (oi_real)1 / (oi_real)15;
    p = p * w + (oi_real)1 / (oi_real)13;
    p = p * w - (oi_real)1 / (oi_real)11;
    p = p * w + (oi_real)1 / (oi_real)9;
    p = p * w - (oi_real)1 / (oi_real)7;
    p = p * w + (oi_real)1 / (oi_real)5;
    p = p * w - (oi_real)1 / (oi_real)3;
    return z + z * w * p;
}

/* One halving of an arctangent's argument: atan z = 2 atan(halve(z)). */
OI_CRESCENT_INLINE oi_real oi__crescent_halve(oi_real z)
{
    return z / ((oi_real)1 + OI_SQRT((oi_real)1 + z * z));
}

/* 2 atan2(n, d) for n, d >= 0, not both 0: the half-angle identity
 * atan2(n, d) = 2 atan(n / (d + hypot(n, d))) once, then
 * atan z = 2 atan(z / (1 + sqrt(1 + z^2))) three times, so that the series
 * sees z <= tan(pi/32); each step rounds a few times, relatively (written
 * out: no inner loop in the vectorised one). */
OI_CRESCENT_INLINE oi_real oi__crescent_twice_angle(oi_real n, oi_real d)
{
    const oi_real z = n / (d + OI_SQRT(n * n + d * d));
    return (oi_real)32 *
           oi__crescent_atan_small(oi__crescent_halve(oi__crescent_halve(oi__crescent_halve(z))));
}

/* The thin segment's integrand at w = tau x, c4 = 4 cos^2 r. */
OI_CRESCENT_INLINE oi_real oi__crescent_node(oi_real tau, oi_real x, oi_real c4)
{
    const oi_real w = tau * x, w2 = w * w, u = (oi_real)1 - w2;
    return w2 / (((oi_real)1 + w2) * (u * u + c4 * w2));
}

/*
 * The segment of the Earth's cap (radius r, sin r = s, cos r = c) cut off by
 * the chord seen from its centre at +-alpha, tau = tan(alpha/2) <= tan(0.2):
 * 2 s^2 c J, J = int_0^alpha sin^2 u / (1 - s^2 sin^2 u) du, in the variable
 * w = tan(u/2): J = int_0^tau 8 w^2 / ((1 + w^2) ((1 - w^2)^2 + 4 c^2 w^2)) dw,
 * a rational integrand (no sine per node), poles on |w| = 1: one 8-point
 * Gauss-Legendre panel errs below 2e-16 relative for tau <= tan(0.25), 5e-17
 * for tau <= tan(0.17), where *in_domain of oi__crescent_row puts it
 * (mpmath, the rule's nodes rounded to double included).
 */
OI_CRESCENT_INLINE oi_real oi__crescent_thin_segment(oi_real s, oi_real c, oi_real tau)
{
    const oi_real c4 = (oi_real)4 * c * c, one = (oi_real)1;
    /* the rule's nodes x and 1 - x, weights w: OI_GL8_* (src/math/math_internal.h) */
    const oi_real sum =
        OI_GL8_W1 * (oi__crescent_node(tau, OI_GL8_X1, c4) +
                     oi__crescent_node(tau, one - OI_GL8_X1, c4)) +
        OI_GL8_W2 * (oi__crescent_node(tau, OI_GL8_X2, c4) +
                     oi__crescent_node(tau, one - OI_GL8_X2, c4)) +
        OI_GL8_W3 * (oi__crescent_node(tau, OI_GL8_X3, c4) +
                     oi__crescent_node(tau, one - OI_GL8_X3, c4)) +
        OI_GL8_W4 * (oi__crescent_node(tau, OI_GL8_X4, c4) +
                     oi__crescent_node(tau, one - OI_GL8_X4, c4));
    return (oi_real)16 * s * s * c * tau * sum;
}

/*
 * The visible fraction of the Sun's uniform disc behind the spherical Earth
 * (radius re_km) seen from the point p (km, Earth-centred), the Sun (radius
 * rs_km) at s: the fraction of src/shadow/sun_fraction.c's crescent (Sun's segment
 * beyond the chord of the two limb crossings minus the Earth's segment), in
 * [0, 1], for a point in the penumbra. The triangle (Sun's centre, Earth's
 * centre, a crossing) is solved from the sines and cosines of its sides,
 * which the positions give without an arctangent: sin r_s = R_s / |s - p|,
 * sin r_e = R / |p| (cos r_e from |p|^2 - R^2 in compensated arithmetic),
 * the separation's from the cross and dot products; the half-angle formulas'
 * sines of half sums by the addition theorems of the half sides.
 * *in_domain (1 or 0): where the result is the fraction: every component
 * within OI_POSITION_MAX_KM (plain squares stay finite), sin r_e >= 4 sin r_s
 * (the Earth's segment thin: its half angle below 0.34 rad; points within
 * about 340,000 km at 1 AU) and 1e-9 <= r_s <= 0.05 rad (the Sun's excess by
 * a short series; S = sin^2(r_s/2) far from underflow). Both callers decide
 * the region first (penumbra).
 */
OI_CRESCENT_INLINE oi_real oi__crescent_row(oi_real sx, oi_real sy, oi_real sz, oi_real px,
                                           oi_real py, oi_real pz, oi_real re_km, oi_real rs_km,
                                           oi_real *in_domain)
{
    const oi_real one = (oi_real)1, zero = (oi_real)0, half = OI_R(0.5);
    const oi_real far = (oi_real)OI_POSITION_MAX_KM;
    const oi_real rx = sx - px, ry = sy - py, rz = sz - pz;
    const oi_real dsp = OI_SQRT(rx * rx + ry * ry + rz * rz);
    const oi_real dp = OI_SQRT(px * px + py * py + pz * pz);
    const oi_real cx = ry * pz - rz * py, cy = rz * px - rx * pz, cz = rx * py - ry * px;
    oi_real h, l, sh, sl, e, q, cross, dot, inv, sd, cd, hd, sin_s, cos_s, sin_e, cos_e, sin_c, cos_c;
    oi_real sa, ca, sb, cb, sc, cc, sbc, cbc, scb, ccb, hs0, hs1, hs2, hs3, ok;
    oi_real ne, de, ns, ds, tau, seg_e, alpha, big_s, big_c, hh, sin_a, cos_a, sin_2a;
    oi_real cos_2a, t, t2, exc, seg_s, frac;
    /* |p|^2 - R^2 without the rounding of |p| (radial_excess's sums) */
    oi__crescent_square(px, &sh, &sl);
    oi__crescent_square(py, &h, &l);
    sh = oi__crescent_two_sum(sh, h, &e);
    sl += e + l;
    oi__crescent_square(pz, &h, &l);
    sh = oi__crescent_two_sum(sh, h, &e);
    sl += e + l;
    oi__crescent_square(re_km, &h, &l);
    q = (sh - h) + (sl - l);
    q = q > zero ? q : zero;
    sin_s = rs_km / dsp;
    cos_s = OI_SQRT((dsp - rs_km) * (dsp + rs_km)) / dsp;
    sin_e = re_km / dp;
    cos_e = OI_SQRT(q) / dp;
    cross = OI_SQRT(cx * cx + cy * cy + cz * cz);
    dot = -(rx * px + ry * py + rz * pz);
    inv = one / (dsp * dp);
    sin_c = cross * inv;
    cos_c = dot * inv;
    /* sep - r_e, the penumbra's steep variable, from its tangent's numerator
     * and denominator (|r x p| sqrt(q) - (-r . p) R over (-r . p) sqrt(q) +
     * |r x p| R, r = s - p: no product of rounded half sides) */
    sd = cross * OI_SQRT(q) - dot * re_km;
    cd = dot * OI_SQRT(q) + cross * re_km;
    hd = OI_SQRT(sd * sd + cd * cd);
    ccb = OI_SQRT(half * (one + cd / hd));
    scb = half * (sd / hd) / ccb;
    /* half sides: cos(x/2) = sqrt((1 + cos x)/2), sin(x/2) = sin x / (2 cos(x/2)) */
    ca = OI_SQRT(half * (one + cos_s));
    sa = half * sin_s / ca;
    cb = OI_SQRT(half * (one + cos_e));
    sb = half * sin_e / cb;
    cc = OI_SQRT(half * (one + cos_c));
    sc = half * sin_c / cc;
    /* sines of s, s - r_s, s - r_e, s - sep, s the half perimeter (A, B, C
     * the half sides r_s/2, r_e/2, sep/2): sin(C + B +- A), sin(A +- (C - B)) */
    sbc = sb * cc + cb * sc;
    cbc = cb * cc - sb * sc;
    hs0 = sbc * ca + cbc * sa;
    hs1 = sbc * ca - cbc * sa;
    hs2 = sa * ccb + ca * scb;
    hs3 = sa * ccb - ca * scb;
    hs0 = hs0 > zero ? hs0 : zero;
    hs1 = hs1 > zero ? hs1 : zero;
    hs2 = hs2 > zero ? hs2 : zero;
    hs3 = hs3 > zero ? hs3 : zero;
    /* tan of the half angles: at the Earth's centre (opposite r_s), and pi
     * minus the angle at the Sun's centre (opposite r_e) */
    ne = OI_SQRT(hs2 * hs3);
    de = OI_SQRT(hs0 * hs1);
    ns = OI_SQRT(hs0 * hs2);
    ds = OI_SQRT(hs1 * hs3);
    tau = de > zero ? ne / de : zero;
    seg_e = oi__crescent_thin_segment(sin_e, cos_e, tau);
    /* the Sun's segment, sector minus the isosceles triangle's excess E,
     * tan(E/2) = S sin 2a / (C + S cos 2a), S = sin^2(r_s/2) (src/math/cap_segment.c);
     * tan(E/2) <= S / (1 - 2 S) < 7e-4: three terms of the arctangent's series */
    hh = ns * ns + ds * ds;
    hh = hh > zero ? hh : one;
    alpha = oi__crescent_twice_angle(ns, ds);
    sin_a = (oi_real)2 * ns * ds / hh;
    cos_a = (ds - ns) * (ds + ns) / hh;
    sin_2a = (oi_real)2 * sin_a * cos_a;
    cos_2a = one - (oi_real)2 * sin_a * sin_a;
    big_s = sa * sa;
    big_c = ca * ca;
    t = big_s * sin_2a / (big_c + big_s * cos_2a);
    t2 = t * t;
    exc = (oi_real)2 * t * (one + t2 * (t2 * ((oi_real)1 / (oi_real)5) - (oi_real)1 / (oi_real)3));
    seg_s = (oi_real)4 * alpha * big_s - exc;
    frac = (seg_s - seg_e) / ((oi_real)4 * OI_PI_R * big_s);
    frac = frac > zero ? frac : zero;
    frac = frac < one ? frac : one;
    /* the domain (three short conditions each: if-conversion) */
    ok = OI_FABS(sx) <= far && OI_FABS(sy) <= far && OI_FABS(sz) <= far ? one : zero;
    ok *= OI_FABS(px) <= far && OI_FABS(py) <= far && OI_FABS(pz) <= far ? one : zero;
    ok *= re_km * dsp >= (oi_real)4 * rs_km * dp && (oi_real)20 * rs_km <= dsp ? one : zero;
    ok *= rs_km >= OI_R(1e-9) * dsp ? one : zero;
    *in_domain = ok;
    return frac;
}

/* The out-of-line copy for the single call (src/shadow/sun_crescent.c). */
oi_real oi__crescent_fraction(const oi_real sun_km[3], const oi_real point_km[3],
                              oi_real re_km, oi_real rs_km, int *in_domain);
#endif /* !OI_SINGLE_PRECISION */

#endif /* OI_SUN_CRESCENT_H */
