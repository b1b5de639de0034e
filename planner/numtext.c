/* SPDX-License-Identifier: MIT */
/*
 * numtext.c: exact decimal text of doubles for the planner's CSV: num_format17
 * is printf's "%.17g", num_parse is strtod, both to the bit and faster.
 *
 * Method: the decimal scaling x * 10^k is formed in double-double arithmetic
 * (Dekker 1971: a value as an unevaluated sum hi + lo, ~106 bits), whose
 * relative error here is below 2^-98 (a few products of 2^-104 each). The
 * answer printf or strtod gives is the correctly rounded one; double-double
 * decides it except when the exact value lies within that error of a rounding
 * boundary (a midpoint between 17-digit decimals, or between doubles). Those
 * rare cases, and everything outside the plain decimal forms and magnitudes
 * 1e-280..1e280 (subnormals, infinities, NaN, more than 19 digits), are
 * handed to snprintf and strtod themselves, so the result is always theirs.
 * The parser reads decimal numbers only: hexadecimal text (strtod's "0x1B58",
 * "0x1p3") and leading white space are no number; of strtod's words, inf,
 * infinity and nan are read. Where the compiler has 128-bit integers the scaling itself
 * is an integer product: the 64-bit significand times the double-double
 * 10^k as a 128-bit integer (the same error bound, a few multiplies of
 * latency instead of a chain of dependent floating-point operations); the
 * double-double arithmetic then only builds the table. Needs IEEE double
 * arithmetic without contraction into fused multiply-adds and without excess
 * precision (the C99 build: -std=c99 turns contraction off in GCC; x86-64 and
 * AArch64 have no excess precision).
 * The parser reads the planner's usual text (a plain decimal of at most 19
 * digits, no exponent) in one straight pass of 8-byte words, the other
 * forms in the general steps.
 * Tested against printf and strtod on millions of doubles
 * (tests/c/test_numtext.c).
 */
#include "numtext.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* SSE2 (every x86-64; GCC and Clang): the sixteen digits after the first
 * written in one pass of 16-bit lanes (put16); elsewhere put8 twice. */
#if defined(__SSE2__) && (defined(__GNUC__) || defined(__clang__))
#define NUM_SSE2 1
#include <emmintrin.h>
#endif

typedef struct {
    double hi, lo;
} dd;

/* The digit steps, inlined into their few callers (GCC otherwise keeps put8
 * out of line: a call per eight digits). */
#if defined(__GNUC__) || defined(__clang__)
#define NUM_INLINE __inline__ __attribute__((always_inline))
#else
#define NUM_INLINE
#endif

static uint64_t bits_of(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static double of_bits(uint64_t u)
{
    double x;
    memcpy(&x, &u, sizeof x);
    return x;
}

/* Error bound of the double-double scaling, relative: 2^-90 (the
 * arithmetic's is below 2^-98; the margin costs one fallback in ~10^10). */
#define DD_REL_ERR (8.077935669463161e-28)

/* Exact powers of ten representable in a double. */
static const double POW10_EXACT[23] = {
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

static dd quick_two_sum(double a, double b)
{
    dd r;
    r.hi = a + b;
    r.lo = b - (r.hi - a);
    return r;
}

/* Veltkamp's split: a = hi + lo, each with at most 26 significant bits. */
static void split(double a, double *hi, double *lo)
{
    const double t = 134217729.0 * a; /* 2^27 + 1 */
    *hi = t - (t - a);
    *lo = a - *hi;
}

/* a * b exactly as hi + lo (Dekker's product). */
static dd two_prod(double a, double b)
{
    double ah, al, bh, bl;
    dd r;
    r.hi = a * b;
    split(a, &ah, &al);
    split(b, &bh, &bl);
    r.lo = ((ah * bh - r.hi) + ah * bl + al * bh) + al * bl;
    return r;
}

static dd dd_mul(dd a, dd b)
{
    dd p = two_prod(a.hi, b.hi);
    p.lo += a.hi * b.lo + a.lo * b.hi;
    return quick_two_sum(p.hi, p.lo);
}

/* a / b (a.hi - q1 b.hi is exact: the two are within a rounding). */
static dd dd_div(dd a, dd b)
{
    const double q1 = a.hi / b.hi;
    const dd p = two_prod(q1, b.hi);
    const double r = (((a.hi - p.hi) - p.lo) + a.lo) - q1 * b.lo;
    return quick_two_sum(q1, r / b.hi);
}

/* The scalings the formatter and parser use: 10^k and 10^-k for
 * 0 <= k <= POW_MAX, as double-double, built on first use: 10^k by binary
 * powering of 10^(2^i) (each squared from the last: 10^1 .. 10^16 exact in
 * double, 10^32 exact in double-double), at most 9 products; 10^-k as the
 * quotient 1 / 10^k. */
#define POW_MAX 600
static dd pow_pos[POW_MAX + 1], pow_neg[POW_MAX + 1];
static int pow_ready = 0;

#if defined(__SIZEOF_INT128__)
/* Where the compiler has 128-bit integers (GCC, Clang on 64-bit targets):
 * the scaling as integer products, whose latency is a few multiplies where
 * double-double's is a chain of some twenty dependent floating-point
 * operations. 10^k = P 2^E with P the double-double's value as a 128-bit
 * integer (P in [2^127, 2^128), hi and lo words; E in wide_exp): its
 * relative error is the double-double's, below 2^-98. */
#define NUM_WIDE 1
__extension__ typedef unsigned __int128 u128;
static uint64_t wide_hi[2 * POW_MAX + 1], wide_lo[2 * POW_MAX + 1];
static int wide_exp[2 * POW_MAX + 1];

/* The double-double v > 0 (normal, |lo| <= half an ulp of hi) as P 2^E. */
static void wide_of(dd v, uint64_t *hi, uint64_t *lo, int *e)
{
    const uint64_t bh = bits_of(v.hi), bl = bits_of(v.lo);
    const int eh = (int)((bh >> 52) & 0x7FF) - 1075;
    u128 p = (u128)((bh & 0xFFFFFFFFFFFFFULL) | (1ULL << 52)) << 75;
    if (v.lo != 0.0) {
        /* lo = fl 2^el: at 2^(el - eh + 75) in P's units, el - eh <= -53 */
        const int el = (int)((bl >> 52) & 0x7FF) - 1075;
        const uint64_t fl = (bl & 0xFFFFFFFFFFFFFULL) | (((bl >> 52) & 0x7FF) ? 1ULL << 52 : 0u);
        const int sh = el - eh + 75;
        const u128 t = sh >= 0 ? (u128)fl << sh : (sh > -64 ? (u128)(fl >> -sh) : 0u);
        p = (bl >> 63) ? p - t : p + t;
    }
    *hi = (uint64_t)(p >> 64);
    *lo = (uint64_t)p;
    *e = eh - 75;
}

/* The upper 128 bits of the 192-bit product m * P (m, P's words). */
static u128 mul_hi128(uint64_t m, uint64_t ph, uint64_t pl)
{
    return (u128)m * ph + (((u128)m * pl) >> 64);
}

static int clz64(uint64_t x)
{
    return __builtin_clzll(x);
}
#endif

static void pow_init(void)
{
    dd sq[10];
    int i, k;
    sq[0].hi = 10.0;
    sq[0].lo = 0.0;
    for (i = 1; i < 10; i++) sq[i] = dd_mul(sq[i - 1], sq[i - 1]);
    for (k = 0; k <= POW_MAX; k++) {
        dd r = {1.0, 0.0};
        int j = k;
        for (i = 0; j != 0; i++, j >>= 1)
            if (j & 1) r = dd_mul(r, sq[i]);
        pow_pos[k] = r;
        pow_neg[k] = dd_div((dd){1.0, 0.0}, r);
    }
#ifdef NUM_WIDE
    for (k = 0; k <= POW_MAX; k++) {
        wide_of(pow_pos[k], &wide_hi[POW_MAX + k], &wide_lo[POW_MAX + k], &wide_exp[POW_MAX + k]);
        /* 10^-k from 2^200 / 10^k: its lo stays a normal number (10^-k's own
         * goes subnormal below 10^-292 and loses bits) */
        wide_of(dd_div((dd){1606938044258990275541962092341162602522202993782792835301376.0, 0.0},
                       pow_pos[k]),
                &wide_hi[POW_MAX - k], &wide_lo[POW_MAX - k], &wide_exp[POW_MAX - k]);
        wide_exp[POW_MAX - k] -= 200;
    }
#endif
    pow_ready = 1;
}

#ifndef NUM_WIDE
/* a * 10^k in double-double, |k| <= POW_MAX. */
static dd scale10(dd a, int k)
{
    if (!pow_ready) pow_init();
    return dd_mul(a, k >= 0 ? pow_pos[k] : pow_neg[-k]);
}
#endif

static size_t fallback_format(double x, char *buf)
{
    int n = snprintf(buf, NUM_TEXT_MAX, "%.17g", x);
    return n > 0 ? (size_t)n : 0;
}

/* Nearest-double 10^k, |k| <= POW_MAX (the decimal exponent's estimate;
 * the scaled value decides it). */
static double pow10_hi(int k)
{
    if (!pow_ready) pow_init();
    return k >= 0 ? pow_pos[k].hi : pow_neg[-k].hi;
}

/* The 17 significant digits of a (> 0) rounded to nearest as an integer in
 * [1e16, 1e17) and the decimal exponent of the first; 0 when double-double
 * cannot decide the rounding. */
static int digits17(double a, uint64_t *digits, int *e10)
{
    /* a = f 2^b, f in [1, 2) (a normal number: the caller's range):
     * floor(b log10(2)) (78913 / 2^18, exact for |b| < 1650) is the
     * exponent or one below; a against 10^(e+1) settles it but for a
     * at the double nearest a power of ten, which the scaled value catches */
    const int b = (int)((bits_of(a) >> 52) & 0x7FF) - 1023;
    int e = b >= 0 ? (b * 78913) >> 18 : -((-b * 78913) >> 18) - 1, tries;
    if (a >= pow10_hi(e + 1)) e++;
#ifdef NUM_WIDE
    {
        /* a = f 2^ea, f shifted to 64 bits; y = a 10^(16-e) = H 2^-sh with H
         * the product's upper 128 bits: sh bits of fraction (about 70) */
        const uint64_t ab = bits_of(a);
        const uint64_t f = ((ab & 0xFFFFFFFFFFFFFULL) | (1ULL << 52)) << 11;
        const int ea = (int)((ab >> 52) & 0x7FF) - 1075;
        for (tries = 0; tries < 3; tries++) {
            const int i = POW_MAX + 16 - e;
            const u128 h = mul_hi128(f, wide_hi[i], wide_lo[i]);
            const int sh = -(53 + ea + wide_exp[i]);
            /* H's words: the integer part n = H >> sh, the fraction as 64 bits
             * (frac / 2^64), sh - 64 in [0, 36] */
            const uint64_t hh = (uint64_t)(h >> 64), hl = (uint64_t)h;
            const int s64 = sh - 64;
            /* error: P's (2^-98 of H < 2^128) and the truncation: 2^31 of H's
             * units, 2^(31 - s64) of the fraction's */
            const uint64_t margin = (2147483648u >> (s64 < 31 ? s64 : 31)) + 1u;
            const uint64_t half = 1ULL << 63;
            uint64_t n, frac;
            if (s64 < 0 || s64 > 36) return 0; /* not the expected scale: printf */
            n = hh >> s64;
            frac = s64 == 0 ? hl : (hh << (64 - s64)) | (hl >> s64);
            /* the unrounded value decides the exponent: y in [1e16, 1e17);
             * within the error of a boundary, printf decides */
            if ((n == 10000000000000000ULL - 1u || n == 100000000000000000ULL - 1u) &&
                frac >= 0u - margin)
                return 0;
            if ((n == 10000000000000000ULL || n == 100000000000000000ULL) && frac <= margin)
                return 0;
            if (n < 10000000000000000ULL) {
                e--;
                continue;
            }
            if (n >= 100000000000000000ULL) {
                e++;
                continue;
            }
            if ((frac > half ? frac - half : half - frac) <= margin) return 0;
            n += frac > half ? 1u : 0u;
            if (n == 100000000000000000ULL) { /* rounded up to 10^17 */
                *digits = 10000000000000000ULL;
                *e10 = e + 1;
                return 1;
            }
            *digits = n;
            *e10 = e;
            return 1;
        }
        return 0;
    }
#else
    for (tries = 0; tries < 3; tries++) {
        dd y = scale10((dd){a, 0.0}, 16 - e);
        double fl, frac;
        int64_t n;
        if (!(y.hi >= 9.0e15 && y.hi < 1.1e18)) return 0;
        /* the unrounded value decides the exponent: y in [1e16, 1e17) */
        if (y.hi < 1.0e16 || (y.hi == 1.0e16 && y.lo < 0.0)) {
            e--;
            continue;
        }
        if (y.hi > 1.0e17 || (y.hi == 1.0e17 && y.lo >= 0.0)) {
            e++;
            continue;
        }
        /* y.hi >= 2^53 is an integer; the fraction is in lo */
        /* floor of |lo| <= 8 without a libm call */
        fl = (double)(int64_t)y.lo;
        if (fl > y.lo) fl -= 1.0;
        frac = y.lo - fl;
        if (fabs(frac - 0.5) <= y.hi * DD_REL_ERR) return 0;
        n = (int64_t)y.hi + (int64_t)fl + (frac > 0.5 ? 1 : 0);
        if (n == (int64_t)100000000000000000LL) { /* rounded up to 10^17 */
            *digits = 10000000000000000ULL;
            *e10 = e + 1;
            return 1;
        }
        *digits = (uint64_t)n;
        *e10 = e;
        return 1;
    }
    return 0;
#endif
}

/* Whether this machine stores integers least significant byte first (the
 * eight-digit steps read and write text as one such integer). */
static int little_endian(void)
{
    const uint32_t one = 1u;
    unsigned char first;
    memcpy(&first, &one, 1);
    return first == 1u;
}

/* Index of the lowest nonzero byte of x != 0. */
static int lowest_byte(uint64_t x)
{
#if defined(__GNUC__) || defined(__clang__)
    return __builtin_ctzll(x) >> 3;
#else
    int n = 0;
    while ((x & 0xFFu) == 0u) {
        x >>= 8;
        n++;
    }
    return n;
#endif
}

#ifndef NUM_SSE2
/* Index of the highest nonzero byte of x != 0. */
static int highest_byte(uint64_t x)
{
#if defined(__GNUC__) || defined(__clang__)
    return (63 - __builtin_clzll(x)) >> 3;
#else
    int n = 7;
    while ((x >> 56) == 0u) {
        x <<= 8;
        n--;
    }
    return n;
#endif
}
#endif

static const char DIGIT_PAIRS[201] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/* The 8 decimal digits of v < 10^8 at d. Little-endian: in one 64-bit word,
 * split into two 4-digit lanes, each into two 2-digit lanes (x / 100 as
 * x 10486 / 2^20, exact below 10^4), each into two digits (x 103 / 2^10,
 * exact below 100): no lane carries into the next. Otherwise two digits at
 * a time from a table. */
static NUM_INLINE void put8(uint32_t v, char *d)
{
    if (little_endian()) {
        const uint64_t y = (uint64_t)(v / 10000u) | ((uint64_t)(v % 10000u) << 32);
        const uint64_t q = ((y * 10486u) >> 20) & 0x0000007F0000007FULL;
        const uint64_t z = q | ((y - q * 100u) << 16);
        const uint64_t t = ((z * 103u) >> 10) & 0x000F000F000F000FULL;
        const uint64_t w = (t | ((z - t * 10u) << 8)) + 0x3030303030303030ULL;
        memcpy(d, &w, 8);
    } else {
        const uint32_t hi = v / 10000u, lo = v % 10000u;
        memcpy(d, DIGIT_PAIRS + 2 * (hi / 100u), 2);
        memcpy(d + 2, DIGIT_PAIRS + 2 * (hi % 100u), 2);
        memcpy(d + 4, DIGIT_PAIRS + 2 * (lo / 100u), 2);
        memcpy(d + 6, DIGIT_PAIRS + 2 * (lo % 100u), 2);
    }
}

#ifdef NUM_SSE2
/* The 8 decimal digits of v < 10^8 as the 16-bit lanes of a vector, the
 * first in the lowest (after itoa-benchmark's SSE2 conversion, Milo Yip
 * 2014): abcd = v / 10^4 (v 0xD1B71759 / 2^45, exact below 2^32) and efgh =
 * v - 10^4 abcd; each, times 4, in four lanes, their quotients by 10^3,
 * 10^2, 10, 1 by two high multiplies (8389 / 2^16 then 128 / 2^16, ... ,
 * exact below 10^4: every input checked), a b c d from a ab abc abcd by
 * subtracting ten times the lane before. */
static NUM_INLINE __m128i digit_lanes8(uint32_t v)
{
    const __m128i x = _mm_cvtsi32_si128((int)v);
    const __m128i abcd = _mm_srli_epi64(_mm_mul_epu32(x, _mm_set1_epi32((int)0xD1B71759u)), 45);
    const __m128i efgh = _mm_sub_epi32(x, _mm_mul_epu32(abcd, _mm_set1_epi32(10000)));
    const __m128i v1 = _mm_slli_epi64(_mm_unpacklo_epi16(abcd, efgh), 2);
    const __m128i v2a = _mm_unpacklo_epi16(v1, v1);
    const __m128i v2 = _mm_unpacklo_epi32(v2a, v2a);
    const __m128i v3 = _mm_mulhi_epu16(v2, _mm_setr_epi16(8389, 5243, 13108, (short)32768, 8389,
                                                          5243, 13108, (short)32768));
    const __m128i v4 = _mm_mulhi_epu16(v3, _mm_setr_epi16(128, 2048, 8192, (short)32768, 128,
                                                          2048, 8192, (short)32768));
    const __m128i v5 = _mm_mullo_epi16(v4, _mm_set1_epi16(10));
    return _mm_sub_epi16(v4, _mm_slli_epi64(v5, 16));
}

/* The 16 decimal digits of hi 10^8 + lo (hi, lo < 10^8) at d; returns the
 * count of them up to the last nonzero one (0 if all are zero). */
static NUM_INLINE int put16(uint32_t hi, uint32_t lo, char *d)
{
    const __m128i t = _mm_add_epi8(_mm_packus_epi16(digit_lanes8(hi), digit_lanes8(lo)),
                                   _mm_set1_epi8('0'));
    const unsigned nz =
        ~(unsigned)_mm_movemask_epi8(_mm_cmpeq_epi8(t, _mm_set1_epi8('0'))) & 0xFFFFu;
    _mm_storeu_si128((__m128i *)(void *)d, t);
    return nz == 0u ? 0 : 32 - __builtin_clz(nz);
}
#endif

/* Count of '0' characters leading the 8 at d (8 if all are). */
static int leading_zeros8(const char *d)
{
    uint64_t x;
    int n;
    if (!little_endian()) {
        for (n = 0; n < 8 && d[n] == '0'; n++) {
        }
        return n;
    }
    memcpy(&x, d, 8);
    x ^= 0x3030303030303030ULL;
    return x == 0u ? 8 : lowest_byte(x);
}

#ifndef NUM_SSE2
/* Count of '0' characters ending the 8 at d (8 if all are). */
static int trailing_zeros8(const char *d)
{
    uint64_t x;
    int n;
    if (!little_endian()) {
        for (n = 0; n < 8 && d[7 - n] == '0'; n++) {
        }
        return n;
    }
    memcpy(&x, d, 8);
    x ^= 0x3030303030303030ULL;
    return x == 0u ? 8 : 7 - highest_byte(x);
}
#endif

/* The decimal digits of an integer 0 < v < 10^17 (what %.17g prints for
 * it: every digit, no point) at buf; returns their count. */
static size_t put_integer(uint64_t v, char *buf)
{
    char d[32];
    size_t z;
    if (v < 10u) { /* one digit (the planner's fractions and gains of 1) */
        buf[0] = (char)('0' + (int)v);
        return 1;
    }
    if (v < 100000000u) {
        put8((uint32_t)v, d);
        memset(d + 8, '0', 8); /* read by the fixed-size copy, not printed */
        z = (size_t)leading_zeros8(d); /* < 8: v > 0 */
        memcpy(buf, d + z, 8);
        return 8 - z;
    }
    d[0] = (char)('0' + (int)(v / 10000000000000000ULL));
    put8((uint32_t)((v / 100000000u) % 100000000u), d + 1);
    put8((uint32_t)(v % 100000000u), d + 9);
    memset(d + 17, '0', 8);
    z = d[0] != '0' ? 0 : 1 + (size_t)leading_zeros8(d + 1); /* < 9: v >= 10^8 */
    memcpy(buf, d + z, 17);
    return 17 - z;
}

size_t num_format17(double x, char *buf)
{
    char d[40];
    uint64_t digits;
    int e10, last;
    size_t n = 0;
    double a = fabs(x);
    if (a == 0.0) { /* "0" or "-0" */
        if (bits_of(x) >> 63) buf[n++] = '-';
        buf[n++] = '0';
        buf[n] = '\0';
        return n;
    }
    if (x < 0) buf[n++] = '-';
    if (a < 1e17 && a == (double)(int64_t)a) { /* an integer: its digits exactly */
        n += put_integer((uint64_t)a, buf + n);
        buf[n] = '\0';
        return n;
    }
    if (!(a >= 1e-280 && a <= 1e280) || !digits17(a, &digits, &e10))
        return fallback_format(x, buf);
    /* 17 digits: 1, then 8 and 8; copies of fixed size (buf holds
     * NUM_TEXT_MAX bytes, d 16 zeros more), the length set after */
    d[0] = (char)('0' + (int)(digits / 10000000000000000ULL));
#ifdef NUM_SSE2
    last = put16((uint32_t)((digits / 100000000u) % 100000000u),
                 (uint32_t)(digits % 100000000u), d + 1);
    memset(d + 17, '0', 16);
#else
    put8((uint32_t)((digits / 100000000u) % 100000000u), d + 1);
    put8((uint32_t)(digits % 100000000u), d + 9);
    memset(d + 17, '0', 16);
    {
        const int t = trailing_zeros8(d + 9);
        last = t < 8 ? 16 - t : 8 - trailing_zeros8(d + 1);
        if (last < 0) last = 0;
    }
#endif
    if (e10 < -4 || e10 >= 17) {
        /* d.ddde+XX */
        int ex = e10 < 0 ? -e10 : e10;
        buf[n++] = d[0];
        if (last > 0) {
            buf[n++] = '.';
            memcpy(buf + n, d + 1, 16);
            n += (size_t)last;
        }
        buf[n++] = 'e';
        buf[n++] = e10 < 0 ? '-' : '+';
        if (ex >= 100) buf[n++] = (char)('0' + ex / 100);
        buf[n++] = (char)('0' + (ex / 10) % 10);
        buf[n++] = (char)('0' + ex % 10);
    } else if (e10 >= 0) {
        memcpy(buf + n, d, 17);
        n += (size_t)e10 + 1;
        if (last > e10) {
            buf[n] = '.';
            memcpy(buf + n + 1, d + e10 + 1, 16);
            n += (size_t)(last - e10) + 1;
        }
    } else {
        buf[n++] = '0';
        buf[n++] = '.';
        memcpy(buf + n, "0000", 4);
        n += (size_t)(-e10 - 1);
        memcpy(buf + n, d, 17);
        n += (size_t)last + 1;
    }
    buf[n] = '\0';
    return n;
}

static int is_digit(char c)
{
    return c >= '0' && c <= '9';
}

#ifndef NUM_WIDE
/* The nearest double to the double-double v, or 0 when v lies too near a
 * midpoint between doubles to tell. */
static int round_dd(dd v, double *out)
{
    const double c = v.hi;
    double next, half;
    if (v.lo == 0.0) {
        *out = c;
        return 1;
    }
    /* c > 0 and normal (the caller's range): its neighbour by the bits */
    next = of_bits(bits_of(c) + (v.lo > 0 ? 1u : (uint64_t)-1));
    half = 0.5 * fabs(next - c);
    if (!(fabs(v.lo) < half) || half - fabs(v.lo) <= fabs(c) * DD_REL_ERR) return 0;
    *out = c;
    return 1;
}
#endif

/* Eight digit values (0..9, one a byte, the first in the lowest) as their
 * decimal number: pairs, then quads, then the eight (three multiplies
 * instead of eight multiply-adds). */
static NUM_INLINE uint32_t eight_values(uint64_t x)
{
    x = x * 10u + (x >> 8); /* pairs: 10 d0 + d1 in the even bytes */
    x = (((x & 0x000000FF000000FFULL) * (100u + (1000000ULL << 32))) +
         (((x >> 16) & 0x000000FF000000FFULL) * (1u + (10000ULL << 32)))) >> 32;
    return (uint32_t)x;
}

static const uint64_t POW10_U64[9] = {1u, 10u, 100u, 1000u, 10000u, 100000u, 1000000u,
                                      10000000u, 100000000u};

/* Count of digit bytes leading the eight of x (little-endian, 0..8): a byte
 * is a digit when its high nibble is 3 and adding 6 leaves it 3 (a carry out
 * of a byte only follows a byte that is no digit). */
static NUM_INLINE int digit_count8(uint64_t x)
{
    const uint64_t bad = ((x & 0xF0F0F0F0F0F0F0F0ULL) |
                          (((x + 0x0606060606060606ULL) & 0xF0F0F0F0F0F0F0F0ULL) >> 4)) ^
                         0x3333333333333333ULL;
    return bad == 0u ? 8 : lowest_byte(bad);
}

/* m 10^k + the first k (1..8) digits of the word x (their values: x minus
 * the '0's). */
static NUM_INLINE uint64_t append_digits(uint64_t m, uint64_t x, int k)
{
    return m * POW10_U64[k] + eight_values(x << (8 * (8 - k)));
}

/* The digits leading the eight bytes at *p appended to *m (append_digits),
 * *p moved past them: their count (0..8), or -1 when fewer than eight bytes
 * are left before lim. */
static NUM_INLINE int digit_word(const char **p, const char *lim, uint64_t *m)
{
    uint64_t x;
    int k;
    if (lim - *p < 8) return -1;
    memcpy(&x, *p, 8);
    k = digit_count8(x);
    if (k > 0) *m = append_digits(*m, x - 0x3030303030303030ULL, k);
    *p += k;
    return k;
}

/* Digits at *pp into *m (m = 10 m + digit each; wraps past 19 digits, which
 * the caller refuses); returns their count and advances *pp. lim: the end
 * of the readable bytes. Eight bytes at a time as one little-endian word
 * (digit_word) while eight are left, then byte by byte. */
static NUM_INLINE int read_digits(const char **pp, const char *lim, uint64_t *m)
{
    const char *p = *pp;
    uint64_t v = *m;
    int n;
    if (little_endian()) {
        int k;
        while ((k = digit_word(&p, lim, &v)) == 8) {
        }
        if (k >= 0) {
            *m = v;
            n = (int)(p - *pp);
            *pp = p;
            return n;
        }
    }
    for (; is_digit(*p); p++) v = 10u * v + (uint64_t)(*p - '0');
    *m = v;
    n = (int)(p - *pp);
    *pp = p;
    return n;
}

double num_parse(const char *s, char **end)
{
    return num_parse_n(s, strlen(s), end);
}

/* The double nearest m 10^e (m < 10^19 of nd digits at most) into *out;
 * 0 when this cannot decide it (then strtod does). */
static NUM_INLINE int decimal_value(uint64_t m, int e, int nd, double *out)
{
    double v;
    if (m == 0) {
        v = 0.0;
    } else if (m < (1ULL << 53) && e >= -22 && e <= 22) {
        /* Clinger's fast path: two exact operands, one rounding */
        v = e < 0 ? (double)m / POW10_EXACT[-e] : (double)m * POW10_EXACT[e];
    } else {
        if (e + nd > 280 || e + nd < -280) return 0;
#ifdef NUM_WIDE
        {
            /* m (normalised to 64 bits) times P: the upper 128 bits, their
             * top 53 the significand, the 75 below decide the rounding */
            const int zm = clz64(m), i = POW_MAX + e;
            u128 h;
            int zh;
            uint64_t sig, hh, hl, rest;
            const uint64_t half = 1ULL << 63, margin = (1ULL << 21) + 1u;
            if (!pow_ready) pow_init();
            h = mul_hi128(m << zm, wide_hi[i], wide_lo[i]);
            zh = h >> 127 ? 0 : 1; /* h >= 2^126 */
            h <<= zh;
            hh = (uint64_t)(h >> 64);
            hl = (uint64_t)h;
            sig = hh >> 11;
            /* the 75 bits below as a 64-bit fraction; the error (P's 2^-98 of
             * h and the truncation, 2^32 of h's units) is 2^21 of its units */
            rest = (hh << 53) | (hl >> 11);
            if ((rest > half ? rest - half : half - rest) <= margin) return 0;
            if (rest > half && ++sig == (1ULL << 53)) {
                sig = 1ULL << 52;
                zh--;
            }
            /* value = sig 2^(139 + E - zh - zm); biased exponent + 52 + 1023 */
            v = of_bits(((uint64_t)(139 + wide_exp[i] - zh - zm + 1075) << 52) |
                        (sig & 0xFFFFFFFFFFFFFULL));
        }
#else
        {
            dd mm;
            mm.hi = (double)m;
            /* m < 10^19 < 2^64: (double)m converts back, the difference is exact */
            mm.lo = (double)(int64_t)(m - (uint64_t)mm.hi);
            if (!round_dd(scale10(mm, e), &v)) return 0;
        }
#endif
    }
    *out = v;
    return 1;
}

/* The plain decimal at s, [sign] digits [. digits], at most 15 digits before
 * the point and 19 in all, no exponent, not hexadecimal, eight bytes at a
 * time (little-endian); 0 when the text is another form or the bytes run short (num_parse_n's general steps
 * then read it). The value is m 10^e as the general steps form it (leading
 * zeros counted in nd, which only decides the hand-off to strtod). */
static NUM_INLINE int parse_plain(const char *s, const char *lim, double *out, char **end)
{
    const char *p = s;
    uint64_t m = 0u;
    int k, nd, e = 0;
    double v;
    const int neg = *p == '-';
    p += neg || *p == '+';
    nd = digit_word(&p, lim, &m);
    if (nd <= 0) return 0;
    if (nd == 8) {
        k = digit_word(&p, lim, &m);
        if (k < 0 || k == 8) return 0;
        nd += k;
    }
    if (*p == '.') {
        p++;
        /* up to three words of digits (past 19 digits m wraps, and is refused below) */
        k = digit_word(&p, lim, &m);
        if (k < 0) return 0;
        nd += k;
        e = -k;
        if (k == 8) {
            k = digit_word(&p, lim, &m);
            if (k < 0) return 0;
            nd += k;
            e -= k;
            if (k == 8) {
                k = digit_word(&p, lim, &m);
                if (k < 0 || k == 8) return 0;
                nd += k;
                e -= k;
            }
        }
    }
    /* an exponent, or hexadecimal text ("0x"): the general steps */
    if (nd > 19 || *p == 'e' || *p == 'E' || *p == 'x' || *p == 'X' ||
        !decimal_value(m, e, nd, &v))
        return 0;
    *out = neg ? -v : v;
    *end = (char *)p;
    return 1;
}

double num_parse_n(const char *s, size_t len, char **end)
{
    const char *p = s, *lim = s + len;
    uint64_t m = 0;
    int neg = 0, nd = 0, any = 0, e = 0, exp_frac = 0, k;
    double v;
    if (little_endian()) {
        char *fast_end = NULL;
        if (parse_plain(s, lim, &v, &fast_end)) {
            if (end != NULL) *end = fast_end;
            return v;
        }
    }
    if (*p == '+' || *p == '-') neg = *p++ == '-';
    /* decimal only: of strtod's other forms the words inf, infinity and nan
     * (any case, nan(...) too) are read by strtod; hexadecimal text ("0x",
     * "0x1p3") and leading white space are no number (end at s) */
    if (!is_digit(*p) && !(*p == '.' && is_digit(p[1]))) {
        if (*p == 'i' || *p == 'I' || *p == 'n' || *p == 'N') return strtod(s, end);
        if (end != NULL) *end = (char *)s;
        return 0.0;
    }
    if (p[0] == '0' && (p[1] == 'x' || p[1] == 'X')) {
        if (end != NULL) *end = (char *)s;
        return 0.0;
    }
    /* leading zeros, then at most 19 significant digits (more: strtod) */
    while (*p == '0') {
        p++;
        any = 1;
    }
    nd = read_digits(&p, lim, &m);
    if (nd > 0) any = 1;
    if (*p == '.') {
        p++;
        if (nd == 0) {
            while (*p == '0') {
                p++;
                exp_frac--;
                any = 1;
            }
        }
        k = read_digits(&p, lim, &m);
        nd += k;
        exp_frac -= k;
        if (k > 0) any = 1;
    }
    if (nd > 19) return strtod(s, end);
    if (!any) return strtod(s, end);
    if (*p == 'e' || *p == 'E') {
        const char *q = p + 1;
        int eneg = 0;
        if (*q == '+' || *q == '-') eneg = *q++ == '-';
        if (is_digit(*q)) {
            for (; is_digit(*q); q++) {
                if (e > 100000) return strtod(s, end);
                e = 10 * e + (*q - '0');
            }
            if (eneg) e = -e;
            p = q;
        }
    }
    e += exp_frac;
    if (!decimal_value(m, e, nd, &v)) return strtod(s, end);
    if (end != NULL) *end = (char *)p;
    return neg ? -v : v;
}

int num_parse_plain(const char *s, const char *lim, double *out, char **end)
{
    return little_endian() && parse_plain(s, lim, out, end);
}
