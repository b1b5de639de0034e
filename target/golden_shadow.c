/* SPDX-License-Identifier: MIT */
/*
 * golden_shadow.c: tests/c/ref_shadow.h (mpmath, tests/ref/gen_refs.py) on the
 * target, with the acceptance rules of tests/c/test_shadow.c:
 *   overlap:  |err| <= 64 eps cond, result in [0, smaller cap (1 + 8 eps)];
 *   fraction: |err| <= 16 eps cond; fraction_ld: that + the quadrature bound
 *             (1e-12 double, 1e-6 single); fraction_atm == fraction;
 *   region:   where the row is farther than 1e3 eps max(sep, 1) from an edge;
 *   geometry: apparent radii, separation, distance within 16 eps of their
 *             conditioning.
 * eps = FLT_EPSILON or DBL_EPSILON; cond is the row's condition number.
 * The model has no_atmosphere set, as in test_shadow.c: the references are
 * the geometric (conical) shadow.
 */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "orbillum.h"
#include "check.h"

#ifdef OI_HAVE_REF_SHADOW
#include "ref_shadow.h"

#ifdef OI_SINGLE_PRECISION
#define EPS ((double)FLT_EPSILON)
#define LD_QUAD (1e-6)
#else
#define EPS DBL_EPSILON
#define LD_QUAD (1e-12)
#endif
#define OVERLAP_K (64.0)
#define FRACTION_K (16.0)

static double cap_area(double r)
{
    double s = sin(0.5 * r);
    return 4 * 3.14159265358979323846 * s * s;
}

static double dmax(double a, double b) { return a > b ? a : b; }

void golden_shadow(void)
{
    unsigned i;
    oi_model geom; /* the geometric shadow: the references have no atmosphere */
    memset(&geom, 0, sizeof geom);
    geom.no_atmosphere = 1;
    for (i = 0; i < sizeof ref_overlap / sizeof ref_overlap[0]; i++) {
        const ref_overlap_row *r = &ref_overlap[i];
        double got = (double)oi_cap_overlap((oi_real)r->r1, (oi_real)r->r2, (oi_real)r->d);
        double cap = cap_area(r->r1 < r->r2 ? r->r1 : r->r2);
        check_real("golden ref_overlap", r->want, got, OVERLAP_K * EPS * r->cond, 0);
        check_true("golden ref_overlap in [0, smaller cap]", got >= 0 && got <= cap * (1 + 8 * EPS));
    }
    for (i = 0; i < sizeof ref_sun / sizeof ref_sun[0]; i++) {
        const ref_sun_row *r = &ref_sun[i];
        oi_real sun[3], pt[3];
        oi_shadow s;
        double tol = FRACTION_K * EPS * r->cond, geo;
        int k, st;
        for (k = 0; k < 3; k++) {
            sun[k] = (oi_real)r->sun[k];
            pt[k] = (oi_real)r->point[k];
        }
        st = oi_sun_fraction(sun, pt, &geom, &s);
        check_int("golden ref_sun status", OI_OK, st);
        if (st != OI_OK) continue;
        check_real("golden ref_sun fraction", r->fraction, (double)s.fraction, tol, 0);
        check_real("golden ref_sun fraction_ld", r->fraction_ld, (double)s.fraction_ld, tol + LD_QUAD, 0);
        check_true("golden ref_sun fraction_atm == fraction", s.fraction_atm == s.fraction);
        if (r->edge > 1e3 * EPS * dmax(r->separation, 1)) check_int("golden ref_sun region", r->region, s.region);
        geo = fabs((double)s.sun_radius_rad - r->sun_radius) / (r->sun_radius + tan(r->sun_radius));
        geo = dmax(geo, fabs((double)s.earth_radius_rad - r->earth_radius) /
                            (r->earth_radius + tan(r->earth_radius)));
        geo = dmax(geo, fabs((double)s.separation_rad - r->separation) / dmax(r->separation, 1));
        geo = dmax(geo, fabs((double)s.sun_distance_km - r->sun_distance) / r->sun_distance);
        check_real("golden ref_sun geometry (eps units)", 0.0, geo / EPS, 16, 0);
    }
}
#else
void golden_shadow(void)
{
}
#endif
