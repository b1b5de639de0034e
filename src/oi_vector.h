/* SPDX-License-Identifier: MIT */
/*
 * oi_vector.h: the inline kernel every layer of the runtime shares (not part
 * of the API): compiler hints, small vector operations, error-free
 * transformations and scalar helpers, as static inline functions.
 */
#ifndef OI_VECTOR_H
#define OI_VECTOR_H

#include "oi_port.h"

/* GCC and clang: a helper kept out of its caller's frame, so that its locals
 * are not live during the caller's other calls (make stack); elsewhere the
 * compiler decides. */
#if defined(__GNUC__)
#define OI_NOINLINE __attribute__((noinline))
#else
#define OI_NOINLINE
#endif

/* GCC if-converts (and so vectorises) a loop's comparisons and selects only
 * when they may not trap: the attribute says so for one function whose
 * results do not depend on it. Its callers bracket its calls with
 * src/fp_quiet.h, so that the exceptions raised on the lanes a select
 * discards neither trap nor stay flagged; hence only where that bracket
 * has a floating-point status to work on (elsewhere the blocks keep
 * trapping math, and their source raises nothing on a discarded lane). */
#if defined(__GNUC__) && !defined(__clang__) &&                                                  \
    (defined(__SSE2__) || defined(__aarch64__) || (defined(__arm__) && defined(__ARM_FP)))
#define OI_VECTORISE_COMPARES __attribute__((optimize("no-trapping-math")))
#else
#define OI_VECTORISE_COMPARES
#endif

/* GCC and clang: a helper inlined into its caller whatever its size (a
 * block function's loop vectorises only with no call in it). */
#if defined(__GNUC__)
#define OI_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define OI_ALWAYS_INLINE inline
#endif

/* 1 where the processor has vectors of doubles (x86-64, AArch64): there a
 * block function evaluates many rows or nodes at once; elsewhere one at a
 * time, where the block's arrays would only cost stack (a Cortex-M4F's,
 * make stack). The bits do not depend on it. */
#if defined(__x86_64__) || defined(__aarch64__)
#define OI_DOUBLE_VECTORS 1
#else
#define OI_DOUBLE_VECTORS 0
#endif

/* A block function also compiled for AVX2 (4 doubles a vector instead of
 * SSE2's 2), chosen at load time where the processor has it (GCC's function
 * multi-versioning, an ifunc: x86-64 Linux with glibc, whose headers define
 * __GLIBC__); the default clone is the portable code. AVX2 alone does not
 * enable fma, and -std=c99 does not contract: every lane rounds as scalar
 * code does. -DOI_NO_TARGET_CLONES leaves it out. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && \
    defined(__GLIBC__) && !defined(OI_NO_TARGET_CLONES)
#define OI_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define OI_AVX2_CLONES
#endif

static inline oi_real oi__dot(const oi_real a[3], const oi_real b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void oi__sub(const oi_real a[3], const oi_real b[3], oi_real out[3])
{
    out[0] = a[0] - b[0];
    out[1] = a[1] - b[1];
    out[2] = a[2] - b[2];
}

static inline void oi__cross(const oi_real a[3], const oi_real b[3], oi_real out[3])
{
    oi_real x = a[1] * b[2] - a[2] * b[1];
    oi_real y = a[2] * b[0] - a[0] * b[2];
    oi_real z = a[0] * b[1] - a[1] * b[0];
    out[0] = x;
    out[1] = y;
    out[2] = z;
}

/* Euclidean norm, scaled so that large or tiny components neither overflow
 * nor underflow. */
static inline oi_real oi__norm_inline(const oi_real a[3])
{
    oi_real m = OI_FABS(a[0]);
    oi_real t = OI_FABS(a[1]);
    oi_real x, y, z;
    if (t > m) m = t;
    t = OI_FABS(a[2]);
    if (t > m) m = t;
    if (m == (oi_real)0 || !OI_ISFINITE(m)) return m;
    x = a[0] / m;
    y = a[1] / m;
    z = a[2] / m;
    return m * OI_SQRT(x * x + y * y + z * z);
}

/* The same, one out-of-line copy (src/math/vector.c). */
oi_real oi__norm_outline(const oi_real a[3]);

/* oi__norm (and oi__unit, which calls it) and oi__finite3 are inlined, except
 * in a file that defines OI_VECTOR_OUT_OF_LINE before including this header:
 * there they call the single copies in src/math/vector.c. The files of the
 * Sun-only build (src/shadow/sun_fraction.c, src/sources/phase.c) do, to bring it towards
 * 4 KiB of flash on every Cortex-M configuration (about -200 B at -Os and
 * -450 to -520 B at -O2); the other hot paths keep the inline copies (out of
 * line everywhere cost +3% instructions in make bench's all_expose, in
 * these two files +1.8%). Same values either way. */
static inline oi_real oi__norm(const oi_real a[3])
{
#ifdef OI_VECTOR_OUT_OF_LINE
    return oi__norm_outline(a);
#else
    return oi__norm_inline(a);
#endif
}

/* out = a / n (out zeroed when n is 0); returns n. out may be a. */
static inline oi_real oi__divide3(const oi_real a[3], oi_real n, oi_real out[3])
{
    if (n > (oi_real)0) {
        out[0] = a[0] / n;
        out[1] = a[1] / n;
        out[2] = a[2] / n;
    } else {
        out[0] = out[1] = out[2] = (oi_real)0;
    }
    return n;
}

/* out = a / |a|; returns |a| (out zeroed when |a| is 0). out may be a. */
static inline oi_real oi__unit(const oi_real a[3], oi_real out[3])
{
    return oi__divide3(a, oi__norm(a), out);
}

/* The smallest normal oi_real. */
#ifdef OI_SINGLE_PRECISION
#define OI__REAL_MIN_NORMAL OI_R(1.17549435e-38)
#else
#define OI__REAL_MIN_NORMAL OI_R(2.2250738585072014e-308)
#endif

/* Half the largest finite oi_real: two vectors of norms below it have a
 * finite difference. */
#ifdef OI_SINGLE_PRECISION
#define OI__HALF_REAL_MAX OI_R(1.7014117e38)
#else
#define OI__HALF_REAL_MAX OI_R(8.988465674311579e307)
#endif

/* Nonzero when a - b is finite (finite a and b), decided from the halves,
 * which cannot overflow: no FE_OVERFLOW where the difference would. */
static inline int oi__sub_finite(const oi_real a[3], const oi_real b[3])
{
    int i;
    for (i = 0; i < 3; i++) {
        const oi_real h = a[i] * OI_R(0.5) - b[i] * OI_R(0.5);
        if (!(OI_FABS(h) < OI__HALF_REAL_MAX)) return 0;
    }
    return 1;
}

/* The unit vector of a whose norm n is subnormal and nonzero, a scaled by
 * its largest component first (src/math/vector.c, out of line: the callers'
 * frames do not grow, make stack). Returns n. */
oi_real oi__unit_tiny(const oi_real a[3], oi_real n, oi_real out[3]);

/* oi__unit for a caller's direction of any nonzero length (a facet's
 * normal): a vector whose norm is subnormal (its components subnormal too)
 * is scaled by its largest component first, exactly where the division by
 * the subnormal norm would round (a normal of components 5e-324 gave
 * (0.5, 0.5, 0.5)); any other vector is oi__unit's, to the bit. Returns
 * |a| (out zeroed when it is 0). out may be a. */
static inline oi_real oi__unit_scaled(const oi_real a[3], oi_real out[3])
{
    const oi_real n = oi__norm(a);
    if (n > (oi_real)0 && n < OI__REAL_MIN_NORMAL) return oi__unit_tiny(a, n, out);
    return oi__divide3(a, n, out);
}

/* Norm, unit vector and angle for vectors whose components are known to be
 * finite and at most ~1e18 in magnitude (positions validated against
 * OI_POSITION_MAX_KM, unit vectors): the plain sum of squares cannot
 * overflow in either precision, so the scaling of oi__norm is skipped. A
 * vector shorter than ~1e-150 (double) or ~1e-18 (float) may come out as
 * zero: callers use them only where such lengths are excluded. */
static inline oi_real oi__norm_bounded(const oi_real a[3])
{
    return OI_SQRT(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

static inline oi_real oi__unit_bounded(const oi_real a[3], oi_real out[3])
{
    return oi__divide3(a, oi__norm_bounded(a), out);
}

/* The unit vector from a scene's target to its observer; returns the range
 * (km). One definition: the observer's terms and the facets' use the same
 * bits. */
static inline oi_real oi__observer_direction(const oi_scene *scene, oi_real obs_hat[3])
{
    oi__sub(scene->observer_km, scene->target_km, obs_hat);
    return oi__unit(obs_hat, obs_hat);
}

/* Angle between two unit vectors, atan2(|a x b|, a . b) (see oi_angle). */
static inline oi_real oi__angle_unit(const oi_real ua[3], const oi_real ub[3])
{
    oi_real c[3];
    oi__cross(ua, ub, c);
    return OI_ATAN2(oi__norm_bounded(c), oi__dot(ua, ub));
}

static inline int oi__finite3_inline(const oi_real a[3])
{
    return OI_ISFINITE(a[0]) && OI_ISFINITE(a[1]) && OI_ISFINITE(a[2]);
}

/* The same, one out-of-line copy (src/math/vector.c); oi__finite3 picks one as
 * oi__norm does (OI_VECTOR_OUT_OF_LINE). */
int oi__finite3_outline(const oi_real a[3]);

static inline int oi__finite3(const oi_real a[3])
{
#ifdef OI_VECTOR_OUT_OF_LINE
    return oi__finite3_outline(a);
#else
    return oi__finite3_inline(a);
#endif
}

/*
 * Error-free transformations (Knuth TAOCP 2, 4.2.2; Dekker 1971), shared by
 * src/shadow/sun_fraction.c, src/math/atan2.c and src/math/sincos.c. They need round-to-nearest in
 * the working precision (no x87 extended registers). oi__split's product
 * goes through a volatile so that a compiler contracting floating-point
 * expressions (-ffp-contract=fast, the GNU C default on FMA targets) cannot
 * fuse t - a = fl(S a) - a into an exact fma, which would break the split.
 */
#ifdef OI_SINGLE_PRECISION
#define OI_SPLITTER OI_R(4097.0) /* 2^12 + 1 */
#else
#define OI_SPLITTER OI_R(134217729.0) /* 2^27 + 1 */
#endif

/* s + *e = a + b exactly (TwoSum; no condition on the operands); returns s. */
static inline oi_real oi__two_sum(oi_real a, oi_real b, oi_real *e)
{
    const oi_real s = a + b;
    const oi_real bb = s - a;
    *e = (a - (s - bb)) + (b - bb);
    return s;
}

/* a = *hi + *lo exactly, each with half the significand (Veltkamp's split),
 * so that products of halves are exact; |a| below OI_SPLITTER's overflow. */
static inline void oi__split(oi_real a, oi_real *hi, oi_real *lo)
{
    volatile oi_real tv = OI_SPLITTER * a;
    const oi_real t = tv;
    *hi = t - (t - a);
    *lo = a - *hi;
}

/* ---- scalar helpers shared by the model files */

/* pi in two parts: OI_PI_HI is pi rounded to oi_real, OI_PI_LO = pi - OI_PI_HI
 * rounded. (OI_PI_HI - x) is exact for x in [OI_PI_HI/2, 2 OI_PI_HI]
 * (Sterbenz), and adding OI_PI_LO gives pi - x to one rounding. */
#ifdef OI_SINGLE_PRECISION
#define OI_PI_HI (3.14159274f)          /* float(pi) = 13176795 * 2^-22 */
#define OI_PI_LO (-8.74227800e-08f)     /* pi - float(pi) */
#else
#define OI_PI_HI (3.141592653589793116)  /* double(pi) = 884279719003555 * 2^-48 */
#define OI_PI_LO (1.2246467991473532e-16) /* pi - double(pi) */
#endif
#define OI_HALF_PI_R (OI_PI_R * OI_R(0.5))

/* pi - x to one rounding for x near pi (OI_PI_HI, OI_PI_LO). */
static inline oi_real oi__pi_minus(oi_real x)
{
    return (OI_PI_HI - x) + OI_PI_LO;
}

static inline oi_real oi__sqr(oi_real x)
{
    return x * x;
}

/* x limited to [lo, hi]; NaN gives lo. */
static inline oi_real oi__clamp(oi_real x, oi_real lo, oi_real hi)
{
    if (!(x > lo)) return lo; /* also maps NaN to lo */
    return x < hi ? x : hi;
}

/* lo < x <= hi (false for NaN). */
/* The range checks compare quietly (C99's isgreater family: a NaN is out of
 * every range without raising FE_INVALID, so that an invalid input's error
 * path traps nowhere); the same answers as > and <= otherwise. */
static inline int oi__in_open_closed(oi_real x, oi_real lo, oi_real hi)
{
    return isgreater(x, lo) && islessequal(x, hi);
}

/* lo <= x <= hi (false for NaN). */
static inline int oi__in_closed(oi_real x, oi_real lo, oi_real hi)
{
    return isgreaterequal(x, lo) && islessequal(x, hi);
}

static inline void oi__zero3(oi_real a[3])
{
    a[0] = a[1] = a[2] = (oi_real)0;
}

#endif /* OI_VECTOR_H */
