/* SPDX-License-Identifier: MIT */
/*
 * oi_test_util.h: small helpers shared by the C unit tests (one copy instead
 * of one per test file). Include after <cmocka.h>, <math.h>, <stdint.h> and
 * "orbillum.h". Everything is static inline: a test uses what it needs.
 */
#ifndef OI_TEST_UTIL_H
#define OI_TEST_UTIL_H

#include <float.h>
#include <math.h>
#include <string.h>

/* Fixed-seed uniform [0, 1): 64-bit LCG (Knuth's MMIX constants), the top
 * 53 bits of the state. */
static inline double lcg01(uint64_t *state)
{
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*state >> 11) * (1.0 / 9007199254740992.0);
}

/* A random unit vector, uniform on the sphere: z, then the azimuth. */
static inline void random_unit(uint64_t *rng, double u[3])
{
    const double z = 2 * lcg01(rng) - 1, a = 2 * OI_PI * lcg01(rng), r = sqrt(1 - z * z);
    u[0] = r * cos(a);
    u[1] = r * sin(a);
    u[2] = z;
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
/* An ideal camera of one setting (1 s, gain 1, read noise 5 e-): optics and
 * detector of unit efficiency, 1e-19 J photons, IFOV 1e-5 rad, full well
 * 1e9 e-, aperture area 1 m^2; a test sets what it varies. */
#ifndef OI_NO_EXPOSURE
static inline oi_camera oi_test_camera(const char *name)
{
    oi_camera c;
    memset(&c, 0, sizeof c);
    c.name = name;
    c.aperture_m = (oi_real)(2.0 / sqrt(3.14159265358979323846));
    c.focal_length_m = 1;
    c.pixel_pitch_m = (oi_real)1e-5;
    c.transmission = 1;
    c.quantum_efficiency = 1;
    c.band_fraction = 1;
    c.photon_energy_j = (oi_real)1e-19;
    c.full_well_e = (oi_real)1e9;
    c.psf_peak_fraction = (oi_real)0.25;
    c.fov_rad = (oi_real)0.1;
    c.n_times = 1;
    c.times_s[0] = 1;
    c.n_gains = 1;
    c.gains[0] = 1;
    c.read_noise_e[0] = 5;
    return c;
}
#endif

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
