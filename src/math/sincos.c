/* SPDX-License-Identifier: MIT */
/*
 * sincos.c: the sine and cosine used by the runtime (the default OI_SIN and
 * OI_COS hooks of src/oi_port.h; a project may point the hooks at its own
 * libm instead, -DOI_SIN=sin -DOI_COS=cos, or sinf/cosf).
 *
 * Why the runtime has its own: a libm's sin/cos carry a reduction for huge
 * arguments (newlib's __kernel_rem_pio2[f], a 416/656-byte frame) that a
 * static stack analysis must count although the runtime only passes angles
 * of a few pi; here the reduction has a small fixed frame, gives the same bits
 * on every IEEE 754 target, and is shorter than a general libm's.
 *
 * Method: |x| <= pi/4 needs no reduction (the common case: one compare and
 * a polynomial, no frame). Else k = nearest integer to x 2/pi and r = x -
 * k pi/2 as a double-word r + r_lo: pi/2 in Cody-Waite parts (each part's
 * leading bits chosen so that k times it is exact), the rest rounded once
 * when |r| >= 1/16, else (near a multiple of pi/2) more parts summed with
 * exact error terms (Knuth's TwoSum); then a polynomial for sin or cos of
 * r + r_lo on |r| <= pi/4 and the quadrant k mod 4. Constants from
 * tools/sincos_coeffs.py (mpmath). Design and measurements: docs/sincos.md.
 * Accuracy: within 1 ulp for |x| <= 2^20 pi/2 (tests/c/test_sincos.c
 * measures it against long double / double references).
 *
 * Contraction: the exact steps assume each operation rounds once, as C99
 * with -std=c99 gives (GCC: -ffp-contract=off); a build that fuses a * b + c
 * into an fma keeps the results finite but may lose the 1-ulp bound near
 * multiples of pi/2.
 */
#include "math/math_internal.h"

/* Constants printed by tools/sincos_coeffs.py. */
#ifdef OI_SINGLE_PRECISION
/* pi/2 = P1 + ... + P5 (12 leading bits each) + P6 (rounded): pi/2 - sum = 8.8e-29 */
#define P1 (1.5703125f)
#define P2 (0.0004837512969970703f)
#define P3 (7.549533620476723e-08f)
#define P4 (2.5632829192545614e-12f)
#define P5 (6.123031769111886e-17f)
#define P6 (2.022266160358745e-21f)
#define P3R (7.549790126404332e-08f)  /* pi/2 - P1 - P2 rounded */
/* sin r = r + r^3 (S3 + S5 z + ...), z = r^2: fit 2^-35.8 relative */
#define S3 (-0.1666666716337204f)
#define S5 (0.008333331905305386f)
#define S7 (-0.00019840085587929934f)
#define S9 (2.7249864160694415e-06f)
/* cos r = 1 - z/2 + z^2 (C4 + C6 z + ...): fit 2^-29.8 relative */
#define C4 (0.0416666641831398f)
#define C6 (-0.001388830249197781f)
#define C8 (2.454789137118496e-05f)
#define TWO_PI_R (6.2831854820251465f)
#define TWO_OVER_PI (0.6366197466850281f)
#define ROUND_MAGIC (12582912.0f)        /* 1.5 2^23: x + M - M rounds to an integer */
#define ROUND_MAGIC_4096 (51539607552.0f) /* 1.5 2^35: to a multiple of 2^12 */
#define SHORT_K (4096.0f)                /* |k| < 2^12: products with P1..P4 exact */
#define TINY (0x1p-12f)                  /* sin x = x, cos x = 1 below */
#else
/* pi/2 = P1 + P2 + P3 (33 leading bits each) + P4 (rounded): pi/2 - sum = 7.4e-49 */
#define P1 (1.5707963267341256)
#define P2 (6.077100506303966e-11)
#define P3 (2.0222662487111665e-21)
#define P4 (8.4784276603689e-32)
#define P2R (6.077100506506192e-11) /* pi/2 - P1 rounded */
/* sin: fit 2^-56.1 relative */
#define S3 (-0.16666666666666666)
#define S5 (0.008333333333330946)
#define S7 (-0.0001984126983675497)
#define S9 (2.755731610068303e-06)
#define S11 (-2.5051131455427946e-08)
#define S13 (1.591810123027412e-10)
/* cos: fit 2^-60.3 relative */
#define C4 (0.041666666666666664)
#define C6 (-0.0013888888888887395)
#define C8 (2.4801587298763433e-05)
#define C10 (-2.7557317270560326e-07)
#define C12 (2.0876146024689747e-09)
#define C14 (-1.1382614868556325e-11)
#define TWO_PI_R (6.283185307179586)
#define TWO_OVER_PI (0.6366197723675814)
#define ROUND_MAGIC (6755399441055744.0) /* 1.5 2^52 */
#define TINY (0x1p-27)
#endif
/* |r| from the short reduction at least this: no cascade */
#define SHORT_CUT (OI_R(0.0625))
/* |x| <= pi/4 (rounded down): no reduction */
#define PIO4 (OI_R(0.78539816339744828))
/* the exact reduction's range: |k| < 2^20 */
#define RANGE (OI_R(1647098.0)) /* below (2^20 - 1/2) pi/2: |k| < 2^20 */

/* r + *lo = x - k pi/2 for |x| < RANGE, k = nearest integer to x 2/pi;
 * *quad = k mod 4. |r| <= pi/4 (to a few ulp). */
static oi_real reduce(oi_real x, oi_real *lo, unsigned *quad)
{
    oi_real kf = x * TWO_OVER_PI, h, l, e, r;
    kf = (kf + ROUND_MAGIC) - ROUND_MAGIC;
    *quad = (unsigned)(int)kf & 3u;
#ifdef OI_SINGLE_PRECISION
    if (OI_FABS(kf) < SHORT_K) {
        /* x - k P1 exact (Sterbenz); minus k P2 exact: the difference is a
         * multiple of 2^-24 (x < 1) or 2^-23 (x >= 1) below 1 in size */
        h = (x - kf * P1) - kf * P2;
        /* short: the rest of pi/2 rounded once; k P3R and the rest's
         * rounding err by < 2^-35.6, below 2^-31 of r for |r| >= 1/16 */
        e = kf * P3R;
        r = h - e;
        if (OI_FABS(r) >= SHORT_CUT) {
            *lo = (h - r) - e; /* exact: both differences are Sterbenz */
            return r;
        }
    }
    {
        /* k = kh + kl, kh a multiple of 2^12 (at most 8 significant bits;
         * 0 for |k| < 2^11), |kl| <= 2^11: every kh Pi and kl Pi is exact;
         * every step a TwoSum (the first ones are exact anyway) */
        static const oi_real part[5] = {P1, P2, P3, P4, P5};
        const oi_real kh = (kf + ROUND_MAGIC_4096) - ROUND_MAGIC_4096, kl = kf - kh;
        int i;
        h = x - kh * P1; /* exact (Sterbenz, or kh = 0) */
        l = (oi_real)0;
        for (i = 0; i < 5; i++) {
            if (i > 0) {
                h = oi__two_sum(h, -kh * part[i], &e);
                l += e;
            }
            h = oi__two_sum(h, -kl * part[i], &e);
            l += e;
        }
        l -= kf * P6;
    }
#else
    /* x - k P1 exact (Sterbenz); k P2 and k P3 exact for |k| < 2^20 */
    h = x - kf * P1;
    /* short: the rest of pi/2 rounded once; k P2R and the rest's rounding
     * err by < 2^-67, below 2^-63 of r for |r| >= 1/16 */
    e = kf * P2R;
    r = h - e;
    if (OI_FABS(r) >= SHORT_CUT) {
        *lo = (h - r) - e; /* exact: both differences are Sterbenz */
        return r;
    }
    h = oi__two_sum(h, -kf * P2, &l);
    h = oi__two_sum(h, -kf * P3, &e);
    l = (l + e) - kf * P4;
#endif
    r = h + l;
    *lo = (h - r) + l; /* Fast2Sum: |l| is below an ulp of h */
    return r;
}

/* sin r - r for |r| <= pi/4 + a few ulp, z = r^2 */
static oi_real sin_poly(oi_real r, oi_real z)
{
#ifdef OI_SINGLE_PRECISION
    const oi_real p = S5 + z * (S7 + z * S9);
#else
    const oi_real p = S5 + z * (S7 + z * (S9 + z * (S11 + z * S13)));
#endif
    return z * r * (S3 + z * p);
}

/* cos r - (1 - z/2) for |r| <= pi/4 + a few ulp, z = r^2 */
static oi_real cos_poly(oi_real z)
{
#ifdef OI_SINGLE_PRECISION
    const oi_real p = C4 + z * (C6 + z * C8);
#else
    const oi_real p = C4 + z * (C6 + z * (C8 + z * (C10 + z * (C12 + z * C14))));
#endif
    return z * z * p;
}

/* sin(r + lo), |lo| <= ulp(r): sin r + lo cos r, cos r = 1 - z/2 to the
 * order needed */
static oi_real sin_kernel(oi_real r, oi_real lo)
{
    const oi_real z = r * r;
    return r + (sin_poly(r, z) + lo * ((oi_real)1 - OI_R(0.5) * z));
}

/* cos(r + lo), |lo| <= ulp(r); (1 - w) - hz is the rounding error of w,
 * exact (Sterbenz; hz <= 0.31) */
static oi_real cos_kernel(oi_real r, oi_real lo)
{
    const oi_real z = r * r, hz = OI_R(0.5) * z, w = (oi_real)1 - hz;
    return w + ((((oi_real)1 - w) - hz) + (cos_poly(z) - r * lo));
}

/* sin (n even) or cos (n odd) of r + lo, negated for n mod 4 in {2, 3} */
static oi_real quadrant(oi_real r, oi_real lo, unsigned n)
{
    const oi_real v = (n & 1u) ? cos_kernel(r, lo) : sin_kernel(r, lo);
    return (n & 2u) ? -v : v;
}

/* x - n M, M = 2 pi rounded to oi_real, n = trunc(x / M), exactly (fmod
 * by binary long division, no libm): for |x| > RANGE, finite. M 2^j is
 * doubled up to a > M 2^j / 2, then halved back to M, subtracting where it
 * fits; each subtraction has y <= a < 2y, so it is exact (Sterbenz). At most
 * 2 x 1022 (float: 2 x 126) iterations, at the largest finite x. */
static oi_real fold_huge(oi_real x)
{
    oi_real a = OI_FABS(x), y = TWO_PI_R;
    while (y <= OI_R(0.5) * a) y *= (oi_real)2;
    while (y >= TWO_PI_R) {
        if (a >= y) a -= y;
        y *= OI_R(0.5);
    }
    return x < (oi_real)0 ? -a : a;
}

/* sin x and cos x for |x| <= pi/4: no reduction (r = x, lo = 0: the kernels
 * without the lo terms); x itself and 1 below TINY */
static oi_real sin_small(oi_real x)
{
    return OI_FABS(x) < TINY ? x : x + sin_poly(x, x * x);
}

static oi_real cos_small(oi_real x)
{
    const oi_real z = x * x, hz = OI_R(0.5) * z, w = (oi_real)1 - hz;
    return OI_FABS(x) < TINY ? (oi_real)1 : w + ((((oi_real)1 - w) - hz) + cos_poly(z));
}

/* r + *lo = x - k pi/2 and *quad = k mod 4 for any finite x (folded first
 * beyond RANGE); returns 0 for inf or NaN (the caller returns x - x) */
static int reduce_any(oi_real x, oi_real *r, oi_real *lo, unsigned *quad)
{
    if (!(OI_FABS(x) <= RANGE)) {
        if (x - x != (oi_real)0) return 0;
        x = fold_huge(x);
    }
    *r = reduce(x, lo, quad);
    return 1;
}

/* sin x (n = 0) or cos x (n = 1) for pi/4 < |x|, or NaN/inf: out of line,
 * so that the common |x| <= pi/4 path needs no frame */
static OI_NOINLINE oi_real sin_or_cos_reduced(oi_real x, unsigned n)
{
    oi_real r, lo;
    unsigned q;
    if (!reduce_any(x, &r, &lo, &q)) return x - x; /* inf or NaN: NaN */
    return quadrant(r, lo, q + n);
}

/* sin x (n = 0) or cos x (n = 1) */
static oi_real sin_or_cos(oi_real x, unsigned n)
{
    if (OI_FABS(x) <= PIO4) return n ? cos_small(x) : sin_small(x);
    return sin_or_cos_reduced(x, n);
}

/*
 * oi__sin: the sine of x (radians).
 *
 * Given:
 *   x      oi_real  angle, radians
 * Returned (function value):
 *          oi_real  sin x in [-1, 1]; x itself for |x| < 2^-27 (float:
 *                   2^-12), signed zero kept; NaN for NaN or +-inf (C99
 *                   F.9.1.6).
 * Notes:
 *  1. Reduction (Cody & Waite): k = nearest integer to x 2/pi, r = x - k
 *     pi/2 with pi/2 in parts whose products with k are exact: the first
 *     part(s) exact, the rest of pi/2 rounded once if that leaves |r| >=
 *     1/16 (error below 2^-63 of r; float 2^-31), else further parts summed
 *     with TwoSum into r + r_lo (pi/2 carried to ~150 bits in double, ~93
 *     in float): r is accurate to a small fraction of its ulp even for the
 *     doubles closest to a multiple of pi/2. Then sin or cos of r + r_lo by
 *     a polynomial on |r| <= pi/4 (Chebyshev fits, tools/sincos_coeffs.py)
 *     and the sign of the quadrant k mod 4. Stack: a few words; no calls,
 *     no libm.
 *  2. Measured: within 1 ulp for |x| <= 2^20 pi/2 (tests/c/test_sincos.c:
 *     random x up to 1e6, the nearest values to k pi/2 for k up to 10^5,
 *     tiny x): worst 0.84 ulp (double, against long double), 0.85 ulp
 *     (float, against double).
 *  3. |x| > 1,647,098 (2^20 pi/2): x is first replaced by x mod (2 pi
 *     rounded to oi_real), computed exactly by binary long division in the
 *     runtime (no libm call, at most ~2,000 (float: ~250) short loop
 *     iterations at the largest x), so the result is finite and in [-1, 1]
 *     but its angle is off by up to |x| 2^-53 (float: |x| 2^-24) rad. The
 *     runtime passes angles of a few pi; this path only keeps it defined.
 *  4. Contraction: the exact steps assume one rounding per operation (C99
 *     with -std=c99; GCC then does not fuse into fma).
 * References:
 *   Cody, W.J. & Waite, W. 1980, Software Manual for the Elementary
 *     Functions, Prentice-Hall, ch. 8 (reduction in parts).
 *   Knuth, D.E. 1998, TAOCP vol. 2, 3rd ed., 4.2.2 (TwoSum).
 *   Muller, J.-M. 2016, Elementary Functions, 3rd ed., Birkhauser, ch. 11
 *     (range reduction; worst cases).
 *   Sterbenz, P.H. 1974, Floating-Point Computation, Prentice-Hall, 4.2
 *     (exact subtraction).
 *   Trefethen, L.N. 2013, Approximation Theory and Approximation Practice,
 *     SIAM, ch. 16 (Chebyshev fits as near-minimax approximations).
 */
oi_real oi__sin(oi_real x)
{
    return sin_or_cos(x, 0u);
}

/*
 * oi__cos: the cosine of x (radians).
 *
 * Given:
 *   x      oi_real  angle, radians
 * Returned (function value):
 *          oi_real  cos x in [-1, 1]; 1 for |x| < 2^-27 (float: 2^-12);
 *                   NaN for NaN or +-inf (C99 F.9.1.5).
 * Notes:
 *  1. As oi__sin (notes 1 to 3), with the quadrant shifted by one:
 *     cos x = sin(x + pi/2).
 * References:
 *   See oi__sin.
 */
oi_real oi__cos(oi_real x)
{
    return sin_or_cos(x, 1u);
}

/*
 * oi__sincos: the sine and the cosine of one angle, sharing the reduction.
 *
 * Given:
 *   x      oi_real  angle, radians
 * Returned:
 *   s      oi_real  sin x, bit for bit oi__sin(x)
 *   c      oi_real  cos x, bit for bit oi__cos(x)
 * Notes:
 *  1. For a caller that needs both (one reduction instead of two): the
 *     default of the OI_SINCOS hook (src/oi_port.h).
 * References:
 *   See oi__sin.
 */
void oi__sincos(oi_real x, oi_real *s, oi_real *c)
{
    oi_real r, lo;
    unsigned q;
    if (OI_FABS(x) <= PIO4) {
        *s = sin_small(x);
        *c = cos_small(x);
    } else if (!reduce_any(x, &r, &lo, &q)) {
        *s = *c = x - x; /* inf or NaN: NaN */
    } else {
        *s = quadrant(r, lo, q);
        *c = quadrant(r, lo, q + 1u);
    }
}
