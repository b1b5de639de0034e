/* SPDX-License-Identifier: MIT */
/*
 * atan2.c: the two-argument arctangent used by the runtime (the default
 * OI_ATAN2 hook of src/oi_port.h; a project may point the hook at its own
 * libm instead, -DOI_ATAN2=atan2). Every angle of the library goes through
 * it, so it is short and branch-light (~60 instructions against ~200 for
 * glibc's on the host) and gives the same bits on every IEEE 754 target.
 * Accuracy: within 1 ulp of the exact value (tests/c/test_atan2.c measures
 * it against long double / double references).
 */
#include "math/math_internal.h"

/* atan(k/16), k = 0..16, in two parts (hi rounded to oi_real, lo the rest
 * rounded), from mpmath at 40 digits. */
#ifdef OI_SINGLE_PRECISION
static const oi_real atan_hi[17] = {
    0.0f, 0.06241881102323532f, 0.12435499578714371f, 0.18534794449806213f, 0.244978666305542f,
    0.30288487672805786f, 0.3587706685066223f, 0.4124104380607605f, 0.46364760398864746f,
    0.5123894810676575f, 0.5585992932319641f, 0.6022873520851135f, 0.6435011029243469f,
    0.6823165416717529f, 0.7188299894332886f, 0.7531512975692749f, 0.7853981852531433f};
static const oi_real atan_lo[17] = {
    0.0f, -1.0272779293885037e-09f, -1.240382241363136e-09f, 5.49763257140512e-09f,
    -3.1786777654474463e-09f, -8.353086222712136e-09f, 1.7639498750554594e-09f,
    3.5366267692182873e-09f, 5.01215868808913e-09f, -2.0756919738573743e-08f,
    2.2111597886009804e-08f, -5.950149262190507e-09f, 5.868937336117597e-09f,
    1.3202995141625706e-08f, 1.0188335508587443e-08f, -1.660708015549517e-08f,
    -2.1855694143368964e-08f};
#define PIO2_HI (1.5707963705062866f)
#define PIO2_LO (-4.371138828673793e-08f)
#define HUGE_SIDE (0x1p100f)
#define SIDE_SCALE (0x1p-60f)
#else
static const oi_real atan_hi[17] = {
    0.0, 0.06241880999595735, 0.12435499454676144, 0.18534794999569476, 0.24497866312686414,
    0.3028848683749714, 0.35877067027057225, 0.4124104415973873, 0.4636476090008061,
    0.5123894603107377, 0.5585993153435624, 0.6022873461349642, 0.6435011087932844,
    0.6823165548747481, 0.7188299996216245, 0.7531512809621944, 0.7853981633974483};
static const oi_real atan_lo[17] = {
    0.0, -1.5490756308295046e-18, -3.1253241424539383e-18, 4.180692268843079e-18,
    1.0698755618734451e-17, -1.1010827903001369e-17, -2.4623815582638635e-17,
    -1.587652227770689e-17, 2.2698777452961687e-17, -2.5462781472855804e-17,
    -5.4556305485916264e-18, 2.950430737228402e-17, 1.5834785051444286e-17,
    6.943223671560008e-18, -2.1478388444456983e-17, -2.4256934659182068e-17,
    3.061616997868383e-17};
#define PIO2_HI (1.5707963267948966)
#define PIO2_LO (6.123233995736766e-17)
#define HUGE_SIDE (0x1p900)
#define SIDE_SCALE (0x1p-200)
#endif

/* a - b * c exactly rounded once, for b * c close to a (Dekker's product:
 * b * c = ph + pl exactly with oi__split, src/oi_vector.h; a - ph is then
 * exact by Sterbenz). */
static oi_real residual(oi_real a, oi_real b, oi_real c)
{
    oi_real bh, bl, ch, cl, ph, pl;
    oi__split(b, &bh, &bl);
    oi__split(c, &ch, &cl);
    ph = b * c;
    pl = ((bh * ch - ph) + bh * cl + bl * ch) + bl * cl;
    return (a - ph) - pl;
}

/*
 * oi__atan2: the angle of the point (x, y) from the +x axis, in [-pi, pi].
 *
 * Given:
 *   y, x   oi_real  coordinates (finite, or infinite)
 * Returned (function value):
 *          oi_real  atan2(y, x) as C99 (F.9.1.4) defines it, signed zeros
 *                   and infinities included; NaN in gives NaN out.
 * Notes:
 *  1. Reduction: t = min(|x|, |y|) / max(|x|, |y|) in [0, 1], with its
 *     rounding error t_lo from an exact residual (Dekker), so that t's
 *     rounding (up to 1 ulp of the result where t is just above a power of
 *     two) does not enter. t < 1/8: atan t = t + series. Else k = nearest
 *     integer to 16 t and atan t = atan(k/16) + atan(u), u = (t - k/16 +
 *     t_lo) / (1 + t k/16), |u| <= 1/32 (the addition formula; t - k/16 is
 *     exact by Sterbenz), |u| at most a quarter of the result. Both cases
 *     share one Horner chain (the t < 1/8 case evaluates its first terms
 *     too). Then the octant, B + a or B - a with B in {pi/2, pi} (pi/2 - a,
 *     pi - a, pi/2 + a) in one Fast2Sum that keeps the rounding of the sum,
 *     and the sign of y; one final rounding. One path for each step keeps
 *     the code small (the Sun-only build fits 4 KiB of flash).
 *  2. Measured: within 1 ulp (tests/c/test_atan2.c, 400,000 random points
 *     over 40 decades and every reduction breakpoint).
 * References:
 *   Abramowitz & Stegun 1964, 4.4.34 (addition formula) and 4.4.42 (series).
 *   Dekker, T.J. 1971, Numer. Math. 18, 224 (exact product; Fast2Sum).
 */
oi_real oi__atan2(oi_real y, oi_real x)
{
    oi_real ax = OI_FABS(x), ay = OI_FABS(y), num, den, t, t_lo, hi, u, lo, z, p, s, r;
    int swap, neg;
    if (y != y || x != x) return y + x; /* NaN */
    if (ay == (oi_real)0) {
        /* on the x axis: 0 or pi, with the sign of y */
        r = OI_SIGNBIT(x) ? (oi_real)2 * PIO2_HI : (oi_real)0;
        return OI_SIGNBIT(y) ? -r : r;
    }
    num = ay < ax ? ay : ax;
    den = ay < ax ? ax : ay;
    if (num == den) {
        t = (oi_real)1; /* also both infinite */
        t_lo = (oi_real)0;
    } else if (!OI_ISFINITE(den)) {
        t = t_lo = (oi_real)0;
    } else {
        if (den > HUGE_SIDE) {
            /* keep OI_SPLITTER * den finite: scale both by a power of two */
            num *= SIDE_SCALE;
            den *= SIDE_SCALE;
        }
        t = num / den;
        /* num - t den is exact to one rounding; t_lo below half an ulp of t
         * (0 when t underflows: the result is then t itself) */
        t_lo = t > (oi_real)0 ? residual(num, t, den) / den : (oi_real)0;
    }
    /* a = atan t = hi + u + lo, lo = (t_lo or atan_lo[k]) + u^3 P(u^2) with
     * the series of atan u - u (A&S 4.4.42) to u^17 (double; the first term
     * left out is below 2^-56 |u| for |u| <= 1/8) or u^9 (float) when
     * t < 1/8, and to its last five (double; below 2^-63 |u|) or three
     * (float) terms when |u| <= 1/32: one Horner chain whose first
     * terms only the first case evaluates. */
    if (t < OI_R(0.125)) {
        hi = (oi_real)0;
        u = t;
        lo = t_lo;
        z = u * u;
#ifdef OI_SINGLE_PRECISION
        p = (oi_real)1 / (oi_real)9;
        p = p * z - (oi_real)1 / (oi_real)7;
#else
        p = (oi_real)1 / (oi_real)17;
        p = p * z - (oi_real)1 / (oi_real)15;
        p = p * z + (oi_real)1 / (oi_real)13;
        p = p * z - (oi_real)1 / (oi_real)11;
#endif
    } else {
        const int k = (int)(t * (oi_real)16 + OI_R(0.5));
        const oi_real ck = (oi_real)k * OI_R(0.0625);
        u = ((t - ck) + t_lo) / ((oi_real)1 + t * ck);
        hi = atan_hi[k];
        lo = atan_lo[k];
        z = u * u;
#ifdef OI_SINGLE_PRECISION
        p = -(oi_real)1 / (oi_real)7;
#else
        p = -(oi_real)1 / (oi_real)11;
#endif
    }
#ifndef OI_SINGLE_PRECISION
    p = p * z + (oi_real)1 / (oi_real)9;
    p = p * z - (oi_real)1 / (oi_real)7;
#endif
    p = p * z + (oi_real)1 / (oi_real)5;
    p = p * z - (oi_real)1 / (oi_real)3;
    lo = lo + u * z * p;
    /* the octant: pi/2 - a (|y| > |x|), pi - a (x < 0), pi/2 + a (both), as
     * B + a or B - a with one Fast2Sum (|B| >= pi/2 > |hi|), which keeps the
     * rounding error of the sum in lo */
    swap = ay > ax;
    neg = OI_SIGNBIT(x) != 0;
    if (swap || neg) {
        const oi_real f = swap ? (oi_real)1 : (oi_real)2; /* B = f pi/2 */
        if (swap != neg) {
            hi = -hi;
            u = -u;
            lo = -lo;
        }
        s = f * PIO2_HI + hi;
        lo = (f * PIO2_LO + lo) + ((f * PIO2_HI - s) + hi);
        hi = s;
    }
    r = hi + (u + lo);
    return OI_SIGNBIT(y) ? -r : r;
}
