/* SPDX-License-Identifier: MIT */
/*
 * atmosphere_moonlight.c: the Moon's light seen from a target through the
 * Earth's atmosphere near the limb: the fraction of the Moon's disc light
 * that the solid Earth does not hide and the air along each line of sight
 * does not scatter or absorb (internal, declared in src/shadow/shadow_internal.h).
 * The same atmosphere model as the shadow's table (bake/atmosphere): the
 * clear-sky V-band optical depth of the default profile versus tangent
 * height (bake/atmosphere/moonlight.py), and the clouds below 10 km
 * stopping 0.68 of the lines of sight (bake/atmosphere/profile.py).
 * docs/atmosphere.md, "Moonlight through the limb".
 * The whole file disappears with OI_NO_ATMOSPHERE or OI_NO_MOON.
 */
#if !defined(OI_NO_ATMOSPHERE) && !defined(OI_NO_MOON)

#include "shadow/shadow_internal.h"

/* clear-sky V-band optical depth of the line of sight whose tangent height
 * is h = 0, 1, ..., 99 km (bake/atmosphere/moonlight.py; 0 at the 100 km top) */
#define ML_N 100
#define ML_TOP_KM OI_MOON_AIR_TOP_KM
#define ML_CLOUD_TOP_KM OI_R(10.0)
#define ML_CLOUD_PASS OI_R(0.32) /* 1 - the cloud fraction 0.68 */
static const oi_real ml_tau[ML_N] = {
    OI_R(21.9949), OI_R(14.4317), OI_R(10.2125), OI_R(7.7882), OI_R(6.32962),
    OI_R(5.39355), OI_R(4.74531), OI_R(4.26165), OI_R(3.87797), OI_R(3.56007),
    OI_R(3.28921), OI_R(3.05633), OI_R(2.83883), OI_R(2.6569), OI_R(2.5035),
    OI_R(2.36978), OI_R(2.24718), OI_R(2.1278), OI_R(2.00505), OI_R(1.87436),
    OI_R(1.73367), OI_R(1.58319), OI_R(1.4264), OI_R(1.26729), OI_R(1.11025),
    OI_R(0.959369), OI_R(0.817911), OI_R(0.688136), OI_R(0.571366), OI_R(0.468172),
    OI_R(0.378561), OI_R(0.302113), OI_R(0.23807), OI_R(0.185392), OI_R(0.143023),
    OI_R(0.109598), OI_R(0.0836998), OI_R(0.0639602), OI_R(0.0491202), OI_R(0.0380782),
    OI_R(0.02991), OI_R(0.0238711), OI_R(0.0193826), OI_R(0.0160088), OI_R(0.0134312),
    OI_R(0.0114225), OI_R(0.0098243), OI_R(0.00852876), OI_R(0.00746695), OI_R(0.00656546),
    OI_R(0.00578839), OI_R(0.00511467), OI_R(0.00453235), OI_R(0.00401646), OI_R(0.00355599),
    OI_R(0.0031449), OI_R(0.00277805), OI_R(0.00245093), OI_R(0.0021595), OI_R(0.00190017),
    OI_R(0.00166967), OI_R(0.00146505), OI_R(0.00128364), OI_R(0.00112302), OI_R(0.000980987),
    OI_R(0.000855574), OI_R(0.000744988), OI_R(0.000647613), OI_R(0.000561995), OI_R(0.00048682),
    OI_R(0.000420906), OI_R(0.000363178), OI_R(0.00031259), OI_R(0.000268462), OI_R(0.000230231),
    OI_R(0.000197152), OI_R(0.000168567), OI_R(0.000143897), OI_R(0.000122635), OI_R(0.000104334),
    OI_R(8.86028e-05), OI_R(7.50984e-05), OI_R(6.35206e-05), OI_R(5.36066e-05), OI_R(4.51262e-05),
    OI_R(3.78759e-05), OI_R(3.16639e-05), OI_R(2.63489e-05), OI_R(2.18938e-05), OI_R(1.81575e-05),
    OI_R(1.50217e-05), OI_R(1.23872e-05), OI_R(1.01706e-05), OI_R(8.30151e-06), OI_R(6.72046e-06),
    OI_R(5.37623e-06), OI_R(4.22369e-06), OI_R(3.22062e-06), OI_R(2.32115e-06), OI_R(1.45256e-06)
};

/* Transmission of the line of sight of tangent height h (km) above the
 * surface: 0 below it, exp(-tau) with ln tau linear between the nodes (tau
 * linear to 0 in the last kilometre), times the clouds' pass below their top.
 * Internal, for tests (declared in tests/c/test_atmosphere_moonlight.c). */
oi_real oi__atm_los_transmission(oi_real h);
oi_real oi__atm_los_transmission(oi_real h)
{
    oi_real x, f, tau;
    int i;
    if (!(h > (oi_real)0)) return (oi_real)0;
    if (h >= ML_TOP_KM) return (oi_real)1;
    x = h; /* nodes every 1 km */
    i = (int)x;
    if (i > ML_N - 1) i = ML_N - 1;
    f = x - (oi_real)i;
    if (i >= ML_N - 1)
        tau = ml_tau[ML_N - 1] * (ML_TOP_KM - h) / (ML_TOP_KM - (oi_real)(ML_N - 1));
    else
        tau = ml_tau[i] * OI_EXP(f * OI_LOG(ml_tau[i + 1] / ml_tau[i]));
    return OI_EXP(-tau) * (h < ML_CLOUD_TOP_KM ? ML_CLOUD_PASS : (oi_real)1);
}

/* Tangent heights (km) splitting the quadrature where the transmission
 * bends most: the cloud top, then every 10-15 km to the top. */
#define ML_NSPLIT 6
static const oi_real ml_split_km[ML_NSPLIT - 1] = {ML_CLOUD_TOP_KM, OI_R(20.0), OI_R(30.0),
                                                   OI_R(45.0), OI_R(65.0)};

/* Apparent angular radius of a sphere of radius rad at distance dist > rad. */
static oi_real apparent(oi_real rad, oi_real dist)
{
    return OI_ATAN2(rad, OI_SQRT(dist - rad) * OI_SQRT(dist + rad));
}

/* 8-point Gauss-Legendre on [-1, 1] (Abramowitz & Stegun 1964, Table 25.4) */
static const oi_real gl_x[4] = {OI_R(0.1834346424956498), OI_R(0.5255324099163290),
                                OI_R(0.7966664774136267), OI_R(0.9602898564975363)};
static const oi_real gl_w[4] = {OI_R(0.3626837833783620), OI_R(0.3137066458778873),
                                OI_R(0.2223810344533745), OI_R(0.1012285362903763)};

/* The Moon's light through the ring of lines of sight at angle th from the
 * Earth's centre direction: the arc of the ring inside the Moon's disc
 * (radius rm, centre sep from the Earth's centre), on the sphere, times
 * sin th, times the transmission at the tangent height dp sin th - R. */
static oi_real ring(oi_real th, oi_real rm, oi_real sep, oi_real dp, oi_real r_e)
{
    const oi_real st = OI_SIN(th), ss = OI_SIN(sep);
    oi_real x, phi;
    if (ss * st > (oi_real)0) {
        /* 1 - cos(phi) = (cos(th - sep) - cos(rm)) / (sin th sin sep), the
         * numerator as a product of sines (no cancellation for small rm) */
        const oi_real d = th - sep;
        x = (oi_real)2 * OI_SIN(OI_R(0.5) * (rm + d)) * OI_SIN(OI_R(0.5) * (rm - d)) / (st * ss);
        phi = !(x > (oi_real)0) ? (oi_real)0
                                : (x >= (oi_real)2 ? OI_PI_R
                                                   : (oi_real)2 * OI_ASIN(OI_SQRT(OI_R(0.5) * x)));
    } else {
        phi = OI_FABS(th - sep) < rm ? OI_PI_R : (oi_real)0;
    }
    return (oi_real)2 * phi * st * oi__atm_los_transmission(dp * st - r_e);
}

/* Integral of ring over [a, b], th = a + (b - a) sin^2(pi s / 2) (smooth at
 * the square-root ends where the ring touches the Moon's edge), 8 nodes. */
static oi_real ring_integral(oi_real a, oi_real b, oi_real rm, oi_real sep, oi_real dp,
                             oi_real r_e)
{
    oi_real sum = (oi_real)0;
    int k, sgn;
    if (!(b > a)) return (oi_real)0;
    for (k = 0; k < 4; ++k) {
        for (sgn = -1; sgn <= 1; sgn += 2) {
            const oi_real s = OI_R(0.5) * ((oi_real)1 + (oi_real)sgn * gl_x[k]);
            const oi_real q = OI_SIN(OI_R(0.5) * OI_PI_R * s);
            const oi_real th = a + (b - a) * q * q;
            /* d th / d s = (b - a) (pi / 2) sin(pi s); ds = dx / 2 */
            const oi_real jac = (b - a) * OI_R(0.5) * OI_PI_R * OI_SIN(OI_PI_R * s) * OI_R(0.5);
            sum += gl_w[k] * jac * ring(th, rm, sep, dp, r_e);
        }
    }
    return sum;
}

/*
 * oi__atm_moon_visible: fraction of the Moon's disc light (uniform disc)
 * reaching a point outside the atmosphere, the solid Earth and the air
 * along the straight lines of sight both counted (internal).
 *
 * Given:
 *   dp     oi_real  the point's distance from the Earth's centre (km)
 *   re     oi_real  the Earth's apparent radius seen from the point (rad)
 *   rm     oi_real  the Moon's apparent radius (rad)
 *   sep    oi_real  the angle between the Moon's centre and the Earth's (rad)
 *   solid  oi_real  the visible fraction with the solid Earth alone
 *   r_e    oi_real  the Earth's radius (km)
 * Returned (function value):
 *   the fraction, in [0, solid]; solid itself when the point is inside the
 *   atmosphere (dp <= r_e + 100 km) or the Moon's disc clear of it.
 * Notes:
 *  1. The disc is split at the apparent radius of the atmosphere's top,
 *     th_top: beyond it exactly the visible fraction behind a disc of
 *     radius th_top (oi__disc_fractions); inside, the rings of lines of
 *     sight from the Earth's limb to th_top weighted by their transmission,
 *     by Gauss-Legendre (8 nodes) on each of six pieces split at the
     tangent heights 10 (the cloud top), 20, 30, 45 and 65 km.
 *  2. Lines of sight are straight: refraction, which lifts the Moon's image
 *     by up to ~0.6 deg at the limb, is not modelled (docs/atmosphere.md).
 *  3. Cost: none beyond a comparison when sep - rm >= th_top; else two
 *     apparent radii, one oi__disc_fractions, up to five more apparent
 *     radii and 48 rings (an asin, an exp and a log each).
 */
oi_real oi__atm_moon_visible(oi_real dp, oi_real re, oi_real rm, oi_real sep, oi_real solid,
                             oi_real r_e)
{
    oi_real th_top, lo, hi, top_frac, a_moon, v, a;
    int k;
    if (!(dp > r_e + ML_TOP_KM)) return solid;
    th_top = apparent(r_e + ML_TOP_KM, dp);
    if (sep - rm >= th_top || !(solid > (oi_real)0)) return solid;
    (void)oi__disc_fractions(rm, th_top, sep, &top_frac, NULL);
    lo = re > sep - rm ? re : sep - rm;
    hi = th_top < sep + rm ? th_top : sep + rm;
    a_moon = (oi_real)4 * OI_PI_R * oi__sin_half_sq(rm);
    v = (oi_real)0;
    a = lo;
    for (k = 0; k < ML_NSPLIT; ++k) {
        /* pieces between the rings of the split heights (the cloud top first) */
        oi_real b = k < ML_NSPLIT - 1 ? apparent(r_e + ml_split_km[k], dp) : hi;
        if (b > hi) b = hi;
        if (b > a) {
            v += ring_integral(a, b, rm, sep, dp, r_e);
            a = b;
        }
    }
    return oi__clamp(top_frac + v / a_moon, (oi_real)0, solid);
}

#else
typedef int oi__atmosphere_moonlight_removed; /* ISO C forbids an empty translation unit */
#endif
