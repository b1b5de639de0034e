/* SPDX-License-Identifier: MIT */
/* test_shadow.c: oi_cap_overlap and oi_sun_fraction against mpmath
 * references computed by a different algorithm (ring quadrature over the
 * small cap, ref_shadow.h from tests/ref/gen_refs.py) at the exact input
 * values; closed-form configurations (disjoint, nested, half-covered,
 * tangent, complement, annular); monotonicity across the penumbra; every
 * error path with zeroed outputs. The limb-darkened fraction also against
 * two references of its own (a closed-form ring integral for concentric
 * discs, a ring quadrature for a large Sun) and for continuity where the
 * method switches; built with -DOI_NO_LIMB_DARKENING the same program checks
 * that fraction_ld equals fraction and OI_LIMB_DARKENED is refused. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <float.h>
#include <math.h>
#include <string.h>

#include "orbillum.h"
#include "oi_test_util.h"
#include "ref_shadow.h"

#ifdef OI_SINGLE_PRECISION
#define EPS ((double)FLT_EPSILON)
#else
#define EPS DBL_EPSILON
#endif

/* Tolerances, in units of the precision's epsilon (see docs/shadow.md):
 * overlap: absolute, times the row's condition number (the smaller cap's
 *   area plus the sum of |dA/dx| x over the inputs x = r1, r2, d);
 * fraction: absolute, times the condition number of the reference row
 *   (|df/dsep| max(sep, 1) + |df/drs| tan rs + |df/dre| tan re + 1: the
 *   apparent radius asin(R/D) has condition tan r w.r.t. the distance D);
 * fraction_ld: the same plus the quadrature's own error bound LD_QUAD. */
#define OVERLAP_K 64.0
#define FRACTION_K 16.0
#ifdef OI_SINGLE_PRECISION
#define LD_QUAD 1e-6
#else
#define LD_QUAD 1e-12
#endif

static const double PI = 3.14159265358979323846;
static const double AU = 149597870.7;
static const double RE = 6378.137;
static const double RS = 695700.0;

static double cap_area(double r)
{
    double s = sin(0.5 * r);
    return 4 * PI * s * s;
}

/* the geometric shadow only: fraction_atm then equals the model's disc
 * choice (the atmosphere's refraction is tested with src/shadow/atmosphere.c) */
static const oi_model *geo_model(void)
{
    static oi_model m;
    memset(&m, 0, sizeof m);
    m.no_atmosphere = 1;
    return &m;
}

/* ---------------------------------------------------------------- overlap */

static void test_overlap_vs_mpmath(void **state)
{
    size_t i, n = sizeof ref_overlap / sizeof ref_overlap[0];
    int bad = 0;
    double worst = 0;
    size_t wi = 0;
    (void)state;
    for (i = 0; i < n; ++i) {
        const ref_overlap_row *r = &ref_overlap[i];
        double got = (double)oi_cap_overlap((oi_real)r->r1, (oi_real)r->r2, (oi_real)r->d);
        double err = fabs(got - r->want);
        double cap = cap_area(fmin(r->r1, r->r2));
        double scaled = r->cond > 0 ? err / (EPS * r->cond) : (got == 0 ? 0.0 : (double)INFINITY);
        if (!isfinite(got) || got < 0 || got > cap * (1 + 8 * EPS) || !(scaled <= OVERLAP_K)) {
            print_error("overlap(%a, %a, %a): want %.17g got %.17g err %.3g eps*cond\n", r->r1,
                        r->r2, r->d, r->want, got, scaled);
            ++bad;
        }
        if (scaled > worst) {
            worst = scaled;
            wi = i;
        }
    }
    print_message("oi_cap_overlap: %zu points, worst |err| = %.3g eps * cond "
                  "(r1=%.6g r2=%.6g d=%.17g)\n",
                  n, worst, ref_overlap[wi].r1, ref_overlap[wi].r2, ref_overlap[wi].d);
    assert_int_equal(bad, 0);
}

static void expect_overlap(double r1, double r2, double d, double want, double tol_rel)
{
    double got = (double)oi_cap_overlap((oi_real)r1, (oi_real)r2, (oi_real)d);
    if (!(fabs(got - want) <= tol_rel * want) && !(got == want)) {
        print_error("overlap(%.17g, %.17g, %.17g): want %.17g got %.17g\n", r1, r2, d, want, got);
        fail();
    }
}

static void test_overlap_closed_forms(void **state)
{
    static const double radii[] = {1e-9, 1e-4, 0.00465, 0.1, 1.0, 1.5, 2.0, 3.0};
    size_t i, j;
    (void)state;
    for (i = 0; i < sizeof radii / sizeof radii[0]; ++i) {
        for (j = 0; j < sizeof radii / sizeof radii[0]; ++j) {
            oi_real r1 = (oi_real)radii[i], r2 = (oi_real)radii[j];
            oi_real small = r1 < r2 ? r1 : r2;
            double amin = cap_area((double)small);
            /* concentric: the smaller cap, exactly its area (to rounding) */
            expect_overlap((double)r1, (double)r2, 0, amin, 8 * EPS);
            /* disjoint (when possible): exactly 0 */
            if ((double)r1 + (double)r2 < 3.0)
                assert_true(oi_cap_overlap(r1, r2, r1 + r2 + (oi_real)0.1) == (oi_real)0);
            /* external tangency d = r1 + r2 (as computed): exactly 0 */
            if ((double)r1 + (double)r2 <= PI &&
                (long double)(r1 + r2) == (long double)r1 + (long double)r2)
                assert_true(oi_cap_overlap(r1, r2, r1 + r2) == (oi_real)0);
            /* internal tangency d = |r1 - r2| (when exactly representable):
             * the smaller cap */
            {
                oi_real dd = r1 > r2 ? r1 - r2 : r2 - r1;
                if ((long double)dd == (long double)r1 - (long double)r2 ||
                    (long double)dd == (long double)r2 - (long double)r1)
                    expect_overlap((double)r1, (double)r2, (double)dd, amin, 8 * EPS);
            }
            /* symmetry in r1, r2 */
            {
                oi_real d = (oi_real)(0.5 * fabs((double)r1 - (double)r2) +
                                      0.5 * fmin((double)r1 + (double)r2, PI));
                double a = (double)oi_cap_overlap(r1, r2, d);
                double b = (double)oi_cap_overlap(r2, r1, d);
                if (!(fabs(a - b) <= 32 * EPS * amin)) {
                    print_error("asymmetric overlap %.17g vs %.17g\n", a, b);
                    fail();
                }
            }
        }
    }
    /* half-covered: a cap centred on a hemisphere's boundary */
    for (i = 0; i < 5; ++i) {
        oi_real r = (oi_real)radii[i];
        expect_overlap(PI / 2, (double)r, PI / 2, 0.5 * cap_area((double)r), 64 * EPS);
    }
    /* a cap of radius pi is the whole sphere */
    expect_overlap(PI, 0.3, 2.0, cap_area((double)(oi_real)0.3), 64 * EPS);
    /* two hemispheres d apart: the lune 2 (pi - d) */
    expect_overlap(PI / 2, PI / 2, 1.0, 2 * (PI - (double)(oi_real)1.0), 64 * EPS);
    /* complement identity: |K1 n K2| + |K1' n K2| = A(r2), K1' = (pi - r1, pi - d) */
    {
        oi_real r1 = (oi_real)1.1, r2 = (oi_real)0.3, d = (oi_real)1.2;
        double a = (double)oi_cap_overlap(r1, r2, d);
        double b = (double)oi_cap_overlap((oi_real)PI - r1, r2, (oi_real)PI - d);
        if (!(fabs(a + b - cap_area((double)r2)) <= 1e3 * EPS * cap_area((double)r2))) {
            print_error("complement: want %.17g got %.17g\n", cap_area((double)r2), a + b);
            fail();
        }
    }
    /* clamping and NaN */
    assert_true(oi_cap_overlap((oi_real)NAN, (oi_real)1, (oi_real)1) == (oi_real)0);
    assert_true(oi_cap_overlap((oi_real)1, (oi_real)NAN, (oi_real)1) == (oi_real)0);
    assert_true(oi_cap_overlap((oi_real)1, (oi_real)1, (oi_real)NAN) == (oi_real)0);
    assert_true(oi_cap_overlap((oi_real)-1, (oi_real)1, (oi_real)0) == (oi_real)0);
    expect_overlap(1, 1, -1, cap_area((double)(oi_real)1), 8 * EPS);
    expect_overlap(INFINITY, 0.2, 1, cap_area((double)(oi_real)0.2), 64 * EPS);
}

/* overlap decreases as the centres move apart, for a Sun-Earth-like pair */
static void test_overlap_monotonic(void **state)
{
    oi_real r1 = (oi_real)1.18715, r2 = (oi_real)0.00465;
    oi_real prev = oi_cap_overlap(r1, r2, r1 - r2);
    int i;
    (void)state;
    for (i = 1; i <= 20000; ++i) {
        oi_real d = (r1 - r2) + (oi_real)(2 * (double)r2 * i / 20000.0);
        oi_real a = oi_cap_overlap(r1, r2, d);
        if (a > prev) {
            print_error("overlap increases at d = %.17g: %.17g > %.17g\n", (double)d, (double)a,
                        (double)prev);
            fail();
        }
        prev = a;
    }
}

/* ---------------------------------------------------------------- sun fraction */

static int finite_shadow(const oi_shadow *s)
{
    return isfinite((double)s->fraction) && isfinite((double)s->fraction_ld) &&
           isfinite((double)s->fraction_atm) && isfinite((double)s->sun_radius_rad) &&
           isfinite((double)s->earth_radius_rad) && isfinite((double)s->separation_rad) &&
           isfinite((double)s->sun_distance_km);
}

static void test_sun_vs_mpmath(void **state)
{
    size_t i, n = sizeof ref_sun / sizeof ref_sun[0];
    int bad = 0;
    double worst_abs = 0, worst_scaled = 0, worst_ld = 0, worst_geo = 0;
    double wc_abs = 0, wc_ld = 0, small_rel = 0; /* rows with cond <= 1e3; f < 1e-3 */
    double low_abs = 0; /* rows within 1 km of the surface */
    (void)state;
    for (i = 0; i < n; ++i) {
        const ref_sun_row *r = &ref_sun[i];
        oi_real sun[3], pt[3];
        oi_shadow s;
        double err, err_ld, tol, geo;
        int st;
        set3(sun, r->sun[0], r->sun[1], r->sun[2]);
        set3(pt, r->point[0], r->point[1], r->point[2]);
        st = oi_sun_fraction(sun, pt, geo_model(), &s);
        if (st != OI_OK || !finite_shadow(&s)) {
            print_error("row %zu: status %d\n", i, st);
            ++bad;
            continue;
        }
        err = fabs((double)s.fraction - r->fraction);
        err_ld = fabs((double)s.fraction_ld - r->fraction_ld);
        tol = FRACTION_K * EPS * r->cond;
        if (!(err <= tol) || s.fraction < 0 || s.fraction > 1) {
            print_error("row %zu fraction: want %.17g got %.17g err %.3g tol %.3g (cond %.3g)\n",
                        i, r->fraction, (double)s.fraction, err, tol, r->cond);
            ++bad;
        }
#ifdef OI_NO_LIMB_DARKENING
        /* the limb-darkened disc is compiled out: fraction_ld is fraction */
        err_ld = fabs((double)s.fraction_ld - (double)s.fraction);
        if (!(err_ld == 0)) {
#else
        if (!(err_ld <= tol + LD_QUAD) || s.fraction_ld < 0 || s.fraction_ld > 1) {
#endif
            print_error("row %zu fraction_ld: want %.17g got %.17g err %.3g\n", i,
                        r->fraction_ld, (double)s.fraction_ld, err_ld);
            ++bad;
        }
        if (s.fraction_atm != s.fraction) {
            print_error("row %zu: fraction_atm %.17g != fraction %.17g\n", i,
                        (double)s.fraction_atm, (double)s.fraction);
            ++bad;
        }
        /* region: only where the rounding of the geometry cannot move an edge */
        if (r->edge > 1e3 * EPS * (r->separation > 1 ? r->separation : 1) &&
            s.region != r->region) {
            print_error("row %zu: region %d want %d\n", i, s.region, r->region);
            ++bad;
        }
        /* geometry: apparent radii relative, separation absolute */
        /* geometry, in units of eps times each quantity's conditioning:
         * apparent radii absolute / (r + tan r), separation absolute /
         * max(sep, 1), distance relative */
        geo = fabs((double)s.sun_radius_rad - r->sun_radius) /
              (r->sun_radius + tan(r->sun_radius));
        geo = fmax(geo, fabs((double)s.earth_radius_rad - r->earth_radius) /
                            (r->earth_radius + tan(r->earth_radius)));
        geo = fmax(geo, fabs((double)s.separation_rad - r->separation) / fmax(r->separation, 1));
        geo = fmax(geo, fabs((double)s.sun_distance_km - r->sun_distance) / r->sun_distance);
        geo /= EPS;
        if (!(geo <= 16)) {
            print_error("row %zu: geometry error %.3g\n", i, geo);
            ++bad;
        }
        {
            double rp = sqrt(r->point[0] * r->point[0] + r->point[1] * r->point[1] +
                             r->point[2] * r->point[2]);
            if (rp < RE + 1.0) low_abs = fmax(low_abs, fmax(err, err_ld));
        }
        if (r->cond <= 1e3) {
            wc_abs = fmax(wc_abs, err);
            wc_ld = fmax(wc_ld, err_ld);
        }
        /* relative accuracy of small fractions, where the inputs' rounding
         * (eps * cond) allows it */
        if (r->fraction > 0 && r->fraction < 1e-3 && EPS * r->cond < 1e-3 * r->fraction)
            small_rel = fmax(small_rel, err / r->fraction);
        if (err > worst_abs) worst_abs = err;
        if (err / (EPS * r->cond) > worst_scaled) worst_scaled = err / (EPS * r->cond);
        if (err_ld > worst_ld) worst_ld = err_ld;
        if (geo > worst_geo) worst_geo = geo;
    }
    print_message("oi_sun_fraction: %zu points; fraction worst |err| %.3g (%.3g eps * cond), "
                  "fraction_ld worst |err| %.3g, geometry %.3g eps * cond\n",
                  n, worst_abs, worst_scaled, worst_ld, worst_geo);
    print_message("  rows with cond <= 1e3: fraction worst |err| %.3g, fraction_ld %.3g; "
                  "fractions below 1e-3 (where eps*cond < 1e-3 f): worst relative error %.3g\n",
                  wc_abs, wc_ld, small_rel);
    print_message("  rows within 1 km of the surface: worst |err| %.3g (fraction, fraction_ld)\n",
                  low_abs);
#ifndef OI_SINGLE_PRECISION
    assert_true(worst_abs <= 1e-9); /* the accuracy goal of oi_cap_overlap */
    /* |p|^2 - R^2 in compensated arithmetic: low altitudes are not
     * limited by the rounding of |p| (that alone would give ~4e-11 at 1 m) */
    assert_true(low_abs <= 1e-12);
#else
    assert_true(low_abs <= 1e-4); /* ~2e-2 without the compensated |p|^2 - R^2 */
#endif
    assert_int_equal(bad, 0);
}

/* the model's limb-darkening option selects fraction_ld for fraction_atm */
static void test_sun_fraction_atm_choice(void **state)
{
    oi_model m;
    oi_shadow s;
    const ref_sun_row *r = NULL;
    size_t i;
    (void)state;
    for (i = 0; i < sizeof ref_sun / sizeof ref_sun[0]; ++i) {
        if (ref_sun[i].region == OI_SHADOW_PENUMBRA && ref_sun[i].fraction > 0.3 &&
            ref_sun[i].fraction < 0.7) {
            r = &ref_sun[i];
            break;
        }
    }
    assert_non_null(r);
    memset(&m, 0, sizeof m);
    m.limb_darkening = OI_LIMB_DARKENED;
    m.no_atmosphere = 1;
    {
        oi_real sun[3], pt[3];
        set3(sun, r->sun[0], r->sun[1], r->sun[2]);
        set3(pt, r->point[0], r->point[1], r->point[2]);
#ifdef OI_NO_LIMB_DARKENING
        /* compiled out: the model asking for it is refused (src/model/model.c),
         * outputs zeroed */
        memset(&s, 0x5a, sizeof s);
        assert_int_equal(oi_sun_fraction(sun, pt, &m, &s), OI_ERR_MODEL);
        assert_true(s.fraction == 0 && s.fraction_ld == 0 && s.fraction_atm == 0 && s.region == 0);
        m.limb_darkening = OI_LIMB_UNIFORM;
        assert_int_equal(oi_sun_fraction(sun, pt, &m, &s), OI_OK);
        assert_true(s.fraction_ld == s.fraction && s.fraction_atm == s.fraction);
        return;
#else
        assert_int_equal(oi_sun_fraction(sun, pt, &m, &s), OI_OK);
#endif
    }
    assert_true(s.fraction_atm == s.fraction_ld);
    assert_true(s.fraction_ld != s.fraction);
}

/* exact values at exact configurations */
static void test_sun_exact(void **state)
{
    oi_real sun[3], pt[3];
    oi_shadow s;
    double rs, re, want;
    (void)state;
    /* sub-solar point: lit, exactly 1 */
    set3(sun, AU, 0, 0);
    set3(pt, 7000, 0, 0);
    assert_int_equal(oi_sun_fraction(sun, pt, geo_model(), &s), OI_OK);
    assert_true(s.fraction == 1 && s.fraction_ld == 1 && s.region == OI_SHADOW_LIT);
    assert_true(s.separation_rad == (oi_real)PI);
    /* anti-solar axis in LEO and GEO: umbra, exactly 0 */
    set3(pt, -7000, 0, 0);
    assert_int_equal(oi_sun_fraction(sun, pt, geo_model(), &s), OI_OK);
    assert_true(s.fraction == 0 && s.fraction_ld == 0 && s.region == OI_SHADOW_UMBRA);
    assert_true(s.separation_rad == 0);
    set3(pt, 0, 0, 42164);
    assert_int_equal(oi_sun_fraction(sun, pt, geo_model(), &s), OI_OK);
    assert_true(s.fraction == 1 && s.region == OI_SHADOW_LIT);
    /* beyond the umbra's tip on the axis (3e6 km): annular,
     * 1 - A(re)/A(rs) with the apparent radii from the distances */
    set3(pt, -3e6, 0, 0);
    assert_int_equal(oi_sun_fraction(sun, pt, geo_model(), &s), OI_OK);
    rs = asin(RS / ((double)(oi_real)AU + 3e6));
    re = asin(RE / 3e6);
    want = 1 - cap_area(re) / cap_area(rs);
    assert_int_equal(s.region, OI_SHADOW_ANNULAR);
    if (!(fabs((double)s.fraction - want) <= 64 * EPS)) {
        print_error("annular: want %.17g got %.17g\n", want, (double)s.fraction);
        fail();
    }
#ifdef OI_NO_LIMB_DARKENING
    assert_true(s.fraction_ld == s.fraction);
#else
    /* limb-darkened annular: the dark disc covers the bright centre, so less
     * than the uniform fraction */
    assert_true(s.fraction_ld < s.fraction && s.fraction_ld > 0);
#endif
}

/* monotonic across the penumbra, at 0.983 and 1.017 AU, LEO and GEO */
static void test_sun_monotonic(void **state)
{
    static const double dist[2] = {0.983, 1.017};
    static const double rad[2] = {6778.137, 42164.0};
    int a, b, k;
    (void)state;
    for (a = 0; a < 2; ++a) {
        for (b = 0; b < 2; ++b) {
            oi_real sun[3], pt[3];
            oi_shadow s;
            double prev = -1, prev_ld = -1, re = asin(RE / rad[b]);
            set3(sun, dist[a] * AU, 0, 0);
            for (k = 0; k <= 4000; ++k) {
                /* angle from the anti-solar axis, across the whole penumbra */
                double psi = re - 0.006 + 0.012 * k / 4000.0;
                set3(pt, -rad[b] * cos(psi), rad[b] * sin(psi), 0);
                assert_int_equal(oi_sun_fraction(sun, pt, geo_model(), &s), OI_OK);
                if ((double)s.fraction < prev || (double)s.fraction_ld < prev_ld) {
                    print_error("not monotonic at psi=%.17g: %.17g after %.17g (ld %.17g after "
                                "%.17g)\n",
                                psi, (double)s.fraction, prev, (double)s.fraction_ld, prev_ld);
                    fail();
                }
                prev = (double)s.fraction;
                prev_ld = (double)s.fraction_ld;
            }
            assert_true(prev == 1.0);
        }
    }
}

/* A Sun of apparent radius 1 rad or more (the model's largest Sun radius,
 * 1e8 km, 1.05e8 to 1.15e8 km away): oi_sun_fraction takes Gauss-Bonnet on the lens; the
 * reference is 1 - oi_cap_overlap / A(r_s) (tested against mpmath above),
 * down to 1 m altitude where both limbs approach great circles. */
static void test_sun_large_disc(void **state)
{
    static const double sund[] = {1.05e8, 1.1e8, 1.15e8};
    static const double dist[] = {42164.0, 7000.0, 6378.138};
    static const double v[] = {0.02, 0.3, 0.5, 0.8, 0.98};
    oi_model m;
    size_t i, j, l, n = 0;
    double worst = 0;
    (void)state;
    memset(&m, 0, sizeof m);
    m.no_atmosphere = 1;
    m.sun_radius_km = (oi_real)1e8;
    for (i = 0; i < sizeof sund / sizeof sund[0]; ++i) {
        for (l = 0; l < sizeof dist / sizeof dist[0]; ++l) {
            for (j = 0; j < sizeof v / sizeof v[0]; ++j) {
                double rs = asin(1e8 / sund[i]), re = asin(RE / dist[l]), psi, want, err;
                oi_real sun[3], pt[3];
                oi_shadow s;
                psi = fabs(re - rs) + v[j] * (fmin(re + rs, PI) - fabs(re - rs));
                set3(sun, sund[i], 0, 0);
                set3(pt, -dist[l] * cos(psi), dist[l] * sin(psi), 0);
                assert_int_equal(oi_sun_fraction(sun, pt, &m, &s), OI_OK);
                if (s.region != OI_SHADOW_PENUMBRA) continue;
                assert_true(s.sun_radius_rad >= (oi_real)1);
                want = 1 - (double)oi_cap_overlap(s.earth_radius_rad, s.sun_radius_rad,
                                                  s.separation_rad) /
                               cap_area((double)s.sun_radius_rad);
                err = fabs((double)s.fraction - want);
                if (!(err <= 64 * EPS)) {
                    print_error("large disc r_s=%.6g r_e=%.6g sep=%.6g: want %.17g got %.17g\n",
                                (double)s.sun_radius_rad, (double)s.earth_radius_rad,
                                (double)s.separation_rad, want, (double)s.fraction);
                    fail();
                }
                /* beyond 0.5 rad the limb-darkened fraction is the uniform one */
                assert_true(s.fraction_ld == s.fraction);
                worst = fmax(worst, err);
                ++n;
            }
        }
    }
    print_message("fraction, Sun of 1 rad or more: %zu points, worst |err| %.3g against "
                  "oi_cap_overlap\n",
                  n, worst);
    assert_true(n >= 30);
}

/* ---------------------------------------------------------------- limb darkening */

#ifndef OI_NO_LIMB_DARKENING
/* Neckel & Labs (1994) at 559.95 nm, as in docs/shadow.md */
static double ld_intensity(double mu)
{
    static const double a[6] = {0.26892, 1.34319, -1.58427, 1.91271, -1.31350, 0.37295};
    double p = 0;
    int i;
    for (i = 5; i >= 0; --i) p = p * mu + a[i];
    return p;
}

/* Flux of the disc (radius rs) within rho of its centre, up to a constant:
 * int_mu(rho)^1 I(m) m / sqrt(cos^2 rs + sin^2 rs m^2) dm by composite
 * Simpson in m (20000 intervals; the integrand is a smooth function of m):
 * a ring integral, not the runtime's line integral. */
static double ld_flux_within(double rho, double rs)
{
    double x = sin(rho) / sin(rs), mu = x < 1 ? sqrt(1 - x * x) : 0;
    double c2 = cos(rs) * cos(rs), s2 = sin(rs) * sin(rs), h, sum = 0;
    int i, n = 20000;
    h = (1 - mu) / n;
    for (i = 0; i <= n; ++i) {
        double m = mu + h * i, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        sum += w * ld_intensity(m) * m / sqrt(c2 + s2 * m * m);
    }
    return sum * h / 3;
}

/* I(mu(rho)) sin rho times the uncovered fraction of the ring rho (the
 * Earth's disc, radius re, sep away, covers the arc 2 acos(c)) */
static double ring_visible(double rho, double rs, double re, double sep, int cover)
{
    double x = sin(rho) / sin(rs), mu = x < 1 ? sqrt(1 - x * x) : 0, f = 1;
    if (cover) {
        double c = (cos(re) - cos(sep) * cos(rho)) / (sin(sep) * sin(rho));
        c = c > 1 ? 1 : (c < -1 ? -1 : c);
        f = 1 - acos(c) / PI;
    }
    return ld_intensity(mu) * sin(rho) * f;
}

/* the rings rho in [a, b], rho = a + (b - a) sin^2 th (smooth at the square
 * roots of both ends), composite Simpson in th, n intervals */
static double ring_piece(double a, double b, double rs, double re, double sep, int cover, int n)
{
    double h = 0.5 * PI / n, sum = 0;
    int i;
    if (!(b > a)) return 0;
    for (i = 0; i <= n; ++i) {
        double th = i * h, sn = sin(th), w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        sum += w * ring_visible(a + (b - a) * sn * sn, rs, re, sep, cover) * (b - a) * 2 * sn *
               cos(th);
    }
    return sum * h / 3;
}

/* Visible fraction of the limb-darkened disc by rings about the Sun's centre
 * (the algorithm of tests/ref/gen_refs.py, in double with Simpson's rule;
 * measured against the mpmath rows away from the tangencies: 2e-12) */
static double ld_fraction_rings(double rs, double re, double sep)
{
    double b1 = fabs(sep - re), b2 = sep + re, tot, vis;
    const int n = 4096;
    if (b1 > rs) b1 = rs;
    if (b2 > rs) b2 = rs;
    tot = ring_piece(0, rs, rs, re, sep, 0, n);
    vis = (sep < re ? 0 : ring_piece(0, b1, rs, re, sep, 0, n)) +
          ring_piece(b1, b2, rs, re, sep, 1, n) + ring_piece(b2, rs, rs, re, sep, 0, n);
    return vis / tot;
}

/* concentric discs (a point on the shadow axis beyond the umbra's tip):
 * fraction_ld = 1 - F(r_e)/F(r_s), F the flux within a radius */
static void test_ld_concentric(void **state)
{
    static const double dist[] = {1.4e6, 2e6, 3e6, 1e7, 1e8};
    size_t i;
    double worst = 0;
    (void)state;
    for (i = 0; i < sizeof dist / sizeof dist[0]; ++i) {
        oi_real sun[3], pt[3];
        oi_shadow s;
        double want, err;
        set3(sun, AU, 0, 0);
        set3(pt, -dist[i], 0, 0);
        assert_int_equal(oi_sun_fraction(sun, pt, geo_model(), &s), OI_OK);
        assert_int_equal(s.region, OI_SHADOW_ANNULAR);
        want = 1 - ld_flux_within((double)s.earth_radius_rad, (double)s.sun_radius_rad) /
                       ld_flux_within((double)s.sun_radius_rad, (double)s.sun_radius_rad);
        err = fabs((double)s.fraction_ld - want);
#ifdef OI_SINGLE_PRECISION
        if (!(err <= 1e-6)) {
#else
        if (!(err <= 1e-13)) {
#endif
            print_error("concentric at %g km: want %.17g got %.17g\n", dist[i], want,
                        (double)s.fraction_ld);
            fail();
        }
        worst = fmax(worst, err);
    }
    print_message("fraction_ld, concentric discs: worst |err| %.3g against the ring integral\n",
                  worst);
}

/* A Sun of large apparent radius (a model radius up to 60 times the Sun's
 * at 1 AU, r_s = 0.047 ... 0.41 rad: the series in tan^2 r_s needs its
 * later terms), against the ring quadrature; beyond 0.5 rad the uniform
 * disc stands in (docs/shadow.md). */
static void test_ld_large_sun(void **state)
{
    static const double rsun[] = {7e6, 1.5e7, 3e7, 6e7};
    static const double v[] = {0.1, 0.3, 0.5, 0.7, 0.9};
    oi_model m;
    size_t i, j;
    (void)state;
    memset(&m, 0, sizeof m);
    m.no_atmosphere = 1;
    for (i = 0; i < sizeof rsun / sizeof rsun[0]; ++i) {
        double worst = 0, rs_seen = 0;
        m.sun_radius_km = (oi_real)rsun[i];
        for (j = 0; j < sizeof v / sizeof v[0] + 1; ++j) {
            double rs = asin(rsun[i] / AU), re = asin(RE / 42164.0), psi, want, err, k, tol;
            oi_real sun[3], pt[3];
            oi_shadow s;
            /* across the penumbra; the last one annular when possible */
            if (j < sizeof v / sizeof v[0])
                psi = fabs(re - rs) + v[j] * (re + rs - fabs(re - rs));
            else if (rs > re)
                psi = 0.5 * (rs - re);
            else
                continue;
            set3(sun, AU, 0, 0);
            set3(pt, -42164.0 * cos(psi), 42164.0 * sin(psi), 0);
            assert_int_equal(oi_sun_fraction(sun, pt, &m, &s), OI_OK);
            assert_true(s.region == OI_SHADOW_PENUMBRA || s.region == OI_SHADOW_ANNULAR);
            want = ld_fraction_rings((double)s.sun_radius_rad, (double)s.earth_radius_rad,
                                     (double)s.separation_rad);
            err = fabs((double)s.fraction_ld - want);
            /* the series' truncation after 6 terms, (tan^2 r_s)^6, plus the
             * reference's and the precision's own error */
            k = tan((double)s.sun_radius_rad);
            k = pow(k * k, 6);
#ifdef OI_SINGLE_PRECISION
            tol = 1e-5 + k;
#else
            tol = 1e-10 + k;
#endif
            if (!(err <= tol)) {
                print_error("large Sun r_s=%.6g sep=%.6g: want %.17g got %.17g (tol %.3g)\n",
                            (double)s.sun_radius_rad, (double)s.separation_rad, want,
                            (double)s.fraction_ld, tol);
                fail();
            }
            worst = fmax(worst, err);
            rs_seen = (double)s.sun_radius_rad;
        }
        print_message("fraction_ld, r_s = %.3g rad: worst |err| %.3g against the ring quadrature\n",
                      rs_seen, worst);
    }
    /* r_s > 0.5 rad: fraction_ld is the uniform fraction */
    {
        oi_real sun[3], pt[3];
        oi_shadow s;
        double rs = asin(1e8 / AU), re = asin(RE / 42164.0);
        m.sun_radius_km = (oi_real)1e8;
        set3(sun, AU, 0, 0);
        set3(pt, -42164.0 * cos(rs), 42164.0 * sin(rs), 0);
        assert_int_equal(oi_sun_fraction(sun, pt, &m, &s), OI_OK);
        assert_true(s.sun_radius_rad > (oi_real)0.5 && s.region == OI_SHADOW_PENUMBRA);
        assert_true(s.fraction_ld == s.fraction);
        (void)re;
    }
}

#ifndef OI_SINGLE_PRECISION
/* Point at distance dist from the Earth's centre, psi from the anti-solar
 * axis (the Sun at 1 AU on +x); returns the shadow. */
static oi_shadow shadow_at(double dist, double psi)
{
    oi_real sun[3], pt[3];
    oi_shadow s;
    set3(sun, AU, 0, 0);
    set3(pt, -dist * cos(psi), dist * sin(psi), 0);
    assert_int_equal(oi_sun_fraction(sun, pt, geo_model(), &s), OI_OK);
    return s;
}

/* the runtime's switches, as functions of the geometry (docs/shadow.md):
 * 0: |sep - r_e| = 7/8 r_s (centre and deficit forms);
 * 1: cos^2(psi0/2) = 0.81 (graded panels in the penumbra);
 * 2: e / (sin sep sin r_e) = 4 (graded panels when annular) */
static double switch_fn(const oi_shadow *s, int which)
{
    double rs = (double)s->sun_radius_rad, re = (double)s->earth_radius_rad;
    double sep = (double)s->separation_rad, h = 0.5 * (sep + re + rs);
    if (which == 0) return fabs(sep - re) - 0.875 * rs;
    if (which == 1) return sin(h) * sin(h - rs) / (sin(sep) * sin(re)) - 0.81;
    return -sin(h) * sin(h - rs) / (sin(sep) * sin(re)) - 4;
}

/* fraction_ld is smooth where the method switches: no jump above 1e-12 in
 * 40 steps of 1e-10 rad across each switch (the second differences of the
 * true function are ~1e-15 there) */
static void test_ld_switch_continuity(void **state)
{
    static const struct { double dist, lo, hi; int which; } cases[] = {
        {42164.0, 0.155, 0.1565, 0}, /* GEO, near the lit edge: sep - re = 7/8 rs */
        {42164.0, 0.146, 0.149, 0},  /* GEO, near the umbra: re - sep = 7/8 rs */
        {1.5e6, 0.0004, 0.0087, 1},  /* beyond the umbra's tip */
        {1.5e6, 1e-5, 0.00034, 2},   /* annular, off-centre */
    };
    size_t c;
    (void)state;
    for (c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        double lo = cases[c].lo, hi = cases[c].hi, worst = 0, prev2 = 0, prev1 = 0;
        int which = cases[c].which, k;
        oi_shadow a = shadow_at(cases[c].dist, lo), b = shadow_at(cases[c].dist, hi);
        double flo = switch_fn(&a, which), fhi = switch_fn(&b, which);
        if (!(flo * fhi < 0)) {
            print_error("switch %zu not bracketed: %g %g\n", c, flo, fhi);
            fail();
        }
        for (k = 0; k < 100; ++k) {
            double mid = 0.5 * (lo + hi);
            oi_shadow s = shadow_at(cases[c].dist, mid);
            if ((switch_fn(&s, which) < 0) == (flo < 0)) lo = mid;
            else hi = mid;
        }
        for (k = -20; k <= 20; ++k) {
            oi_shadow s = shadow_at(cases[c].dist, lo + 1e-10 * k);
            double f = (double)s.fraction_ld;
            if (k >= -18) worst = fmax(worst, fabs(f - 2 * prev1 + prev2));
            prev2 = prev1;
            prev1 = f;
        }
        print_message("fraction_ld across switch %d at psi = %.10g: worst second difference %.3g\n",
                      which, lo, worst);
        assert_true(worst <= 1e-12);
    }
}
#endif
#endif /* OI_NO_LIMB_DARKENING */

/* ---------------------------------------------------------------- errors */

static void expect_error(const oi_real *sun, const oi_real *pt, const oi_model *m, int want)
{
    oi_shadow s;
    oi_shadow zero;
    memset(&s, 0x5a, sizeof s);
    memset(&zero, 0, sizeof zero);
    assert_int_equal(oi_sun_fraction(sun, pt, m, &s), want);
    assert_memory_equal(&s, &zero, sizeof s);
}

static void test_sun_errors(void **state)
{
    oi_real sun[3], pt[3], bad[3];
    oi_model m;
    oi_shadow s;
    int i;
    (void)state;
    set3(sun, AU, 0, 0);
    set3(pt, -7000, 100, 0);
    /* NULLs */
    assert_int_equal(oi_sun_fraction(sun, pt, NULL, NULL), OI_ERR_NULL);
    expect_error(NULL, pt, NULL, OI_ERR_NULL);
    expect_error(sun, NULL, NULL, OI_ERR_NULL);
    /* non-finite components, each position and component */
    for (i = 0; i < 3; ++i) {
        memcpy(bad, sun, sizeof bad);
        bad[i] = (oi_real)NAN;
        expect_error(bad, pt, NULL, OI_ERR_NONFINITE);
        bad[i] = (oi_real)INFINITY;
        expect_error(bad, pt, NULL, OI_ERR_NONFINITE);
        memcpy(bad, pt, sizeof bad);
        bad[i] = (oi_real)-INFINITY;
        expect_error(sun, bad, NULL, OI_ERR_NONFINITE);
        bad[i] = (oi_real)NAN;
        expect_error(sun, bad, NULL, OI_ERR_NONFINITE);
    }
    /* zero vectors (negative zeros too) */
    set3(bad, 0, -0.0, 0);
    expect_error(bad, pt, NULL, OI_ERR_ZERO_VECTOR);
    expect_error(sun, bad, NULL, OI_ERR_ZERO_VECTOR);
    /* at and below the surface; subnormal */
    set3(bad, -RE, 0, 0);
    expect_error(sun, bad, NULL, OI_ERR_BELOW_SURFACE);
    set3(bad, 0, 0, 100);
    expect_error(sun, bad, NULL, OI_ERR_BELOW_SURFACE);
    set3(bad, 1e-40, 0, 0);
    expect_error(sun, bad, NULL, OI_ERR_BELOW_SURFACE);
    /* just above the surface (1 m): computed */
    set3(bad, 0, RE + 0.001, 0);
    assert_int_equal(oi_sun_fraction(sun, bad, geo_model(), &s), OI_OK);
    assert_true(finite_shadow(&s) && s.fraction >= 0 && s.fraction <= 1);
    /* Sun touching the Earth; point inside or on the Sun */
    set3(bad, RS + RE, 0, 0);
    expect_error(bad, pt, NULL, OI_ERR_GEOMETRY);
    set3(bad, AU + 1000, 0, 0);
    expect_error(sun, bad, NULL, OI_ERR_GEOMETRY);
    set3(bad, AU - 0.5 * RS, 0, 0);
    expect_error(sun, bad, NULL, OI_ERR_GEOMETRY);
    /* beyond the Sun on the axis: the Earth's disc is inside the Sun's but
     * behind it: lit, exactly 1 */
    set3(bad, 2 * AU, 0, 0);
    assert_int_equal(oi_sun_fraction(sun, bad, geo_model(), &s), OI_OK);
    assert_true(finite_shadow(&s) && s.fraction == 1 && s.fraction_ld == 1);
    assert_int_equal(s.region, OI_SHADOW_LIT);
    /* a Sun-to-point vector that overflows */
#ifdef OI_SINGLE_PRECISION
    set3(bad, 3e38, 0, 0);
    {
        oi_real far[3];
        set3(far, -3e38, 0, 0);
        expect_error(bad, far, NULL, OI_ERR_NONFINITE);
    }
#else
    set3(bad, 1.7e308, 0, 0);
    {
        oi_real far[3];
        set3(far, -1.7e308, 0, 0);
        expect_error(bad, far, NULL, OI_ERR_NONFINITE);
    }
#endif
    /* huge but representable: computed, finite */
    set3(bad, 1e30, 1e30, 0);
    assert_int_equal(oi_sun_fraction(bad, pt, geo_model(), &s), OI_OK);
    assert_true(finite_shadow(&s));
    /* model errors */
    memset(&m, 0, sizeof m);
    m.earth_radius_km = (oi_real)-1;
    expect_error(sun, pt, &m, OI_ERR_RADIUS);
    memset(&m, 0, sizeof m);
    m.sun_radius_km = (oi_real)NAN;
    expect_error(sun, pt, &m, OI_ERR_MODEL);
    memset(&m, 0, sizeof m);
    m.limb_darkening = 7;
    expect_error(sun, pt, &m, OI_ERR_MODEL);
    /* model radii are used: a larger Earth swallows the point */
    memset(&m, 0, sizeof m);
    m.earth_radius_km = (oi_real)8000;
    expect_error(sun, pt, &m, OI_ERR_BELOW_SURFACE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_overlap_vs_mpmath),
        cmocka_unit_test(test_overlap_closed_forms),
        cmocka_unit_test(test_overlap_monotonic),
        cmocka_unit_test(test_sun_vs_mpmath),
        cmocka_unit_test(test_sun_fraction_atm_choice),
        cmocka_unit_test(test_sun_exact),
        cmocka_unit_test(test_sun_monotonic),
        cmocka_unit_test(test_sun_large_disc),
#ifndef OI_NO_LIMB_DARKENING
        cmocka_unit_test(test_ld_concentric),
        cmocka_unit_test(test_ld_large_sun),
#ifndef OI_SINGLE_PRECISION
        cmocka_unit_test(test_ld_switch_continuity),
#endif
#endif
        cmocka_unit_test(test_sun_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
