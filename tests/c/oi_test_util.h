/* SPDX-License-Identifier: MIT */
/*
 * oi_test_util.h: small helpers shared by the C unit tests (one copy instead
 * of one per test file). Include after <cmocka.h>, <math.h>, <stdint.h> and
 * "orbillum.h". Everything is static inline: a test uses what it needs.
 */
#ifndef OI_TEST_UTIL_H
#define OI_TEST_UTIL_H

#include <float.h>

/* Fixed-seed uniform [0, 1): 64-bit LCG (Knuth's MMIX constants), the top
 * 53 bits of the state. */
static inline double lcg01(uint64_t *state)
{
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*state >> 11) * (1.0 / 9007199254740992.0);
}

static inline void set3(oi_real v[3], double x, double y, double z)
{
    v[0] = (oi_real)x;
    v[1] = (oi_real)y;
    v[2] = (oi_real)z;
}

/* want == got, as integers (statuses, flags, counts). */
static inline void check_int(long want, long got, const char *what)
{
    if (want != got) {
        print_error("%s: want %ld got %ld\n", what, want, got);
        fail();
    }
}

/* |got - want| <= abs + rel |want|; prints want, got and the relative error
 * when not. A NaN got fails. */
static inline void check_close(double want, double got, double abs_tol, double rel_tol,
                               const char *what)
{
    double err = fabs(got - want);
    if (!(err <= abs_tol + rel_tol * fabs(want))) {
        print_error("%s: want %.17g got %.17g rel err %.3g (abs %.3g + rel %.3g allowed)\n",
                    what, want, got, want != 0 ? err / fabs(want) : err, abs_tol, rel_tol);
        fail();
    }
}

/* |got - want| <= rel |want| (plus a floor far below any value tested). */
static inline void check_rel(double want, double got, double rel, const char *what)
{
    check_close(want, got, 1e-300, rel, what);
}

/* A reference precision above the working one (long double for the double
 * build, double for the float build), and the ulp of a working-precision
 * value at |v| (subnormals included), for errors in ulp. */
#ifdef OI_SINGLE_PRECISION
typedef double ref_real;
#define MANT_BITS 24
#define MIN_SUB_EXP (-149)
#else
typedef long double ref_real;
#define MANT_BITS 53
#define MIN_SUB_EXP (-1074)
#endif

static inline ref_real ulp_of(ref_real v)
{
    int e;
    double u;
    (void)frexp((double)(v < 0 ? -v : v), &e);
    u = ldexp(1.0, e - MANT_BITS);
    if (u < ldexp(1.0, MIN_SUB_EXP)) u = ldexp(1.0, MIN_SUB_EXP);
    return (ref_real)u;
}

#endif /* OI_TEST_UTIL_H */
