/* SPDX-License-Identifier: MIT */
/*
 * atmosphere.c: sunlight refracted and dimmed by the Earth's atmosphere into
 * the shadow, looked up in the baked table tables/oi_atm_table.c (issue 4).
 * The whole file disappears with OI_NO_ATMOSPHERE.
 */
#ifndef OI_NO_ATMOSPHERE

#include "oi_internal.h"
#include "oi_atm_table.h"

#if OI_ATM_TABLE_FORMAT != 2
#error "atmosphere.c: oi_atm_table format mismatch: regenerate (make bake-atm)"
#endif

#define ATM_R(x) ((oi_real)(x))
#define ATM_HC ATM_R(OI_ATM_H_C_KM)
#define ATM_HA ATM_R(OI_ATM_H_A_KM)

/* Derived constants of the table's coordinates, written out because C has no
 * constant exp/log (tests/c/test_atmosphere.c, test_derived_constants, checks
 * the first two against the table's macros and fails if a re-bake moves them):
 *   ATM_E_MID = exp(-(OI_ATM_V_MID_KM - OI_ATM_H_C_KM) / OI_ATM_H_A_KM)
 *   ATM_C_IU  = (OI_ATM_NZ - 1) / ln(OI_ATM_Z_MAX_KM / OI_ATM_Z_MIN_KM)
 *   ATM_LN10  = ln 10 */
#define ATM_E_MID ATM_R(4.56323900581031082406e-4)
#define ATM_C_IU ATM_R(6.80394688315094529987)
#define ATM_LN10 ATM_R(2.30258509299404568402)

/* The ray-altitude solve (see solve_x): a Halley step whose size is below
 * ATM_X_TOL (units of OI_ATM_H_A_KM) leaves an error of order ATM_X_TOL^3
 * (cubic convergence, relative curvature of phi below 1), far below the
 * rounding of phi itself; ATM_MAX_IT bounds the loop (bisection fallback
 * halves a bracket of < 20 units to < ATM_X_TOL in ~20 steps). */
#ifdef OI_SINGLE_PRECISION
#define ATM_X_TOL OI_R(1e-3)
#else
#define ATM_X_TOL OI_R(1e-4)
#endif
#define ATM_MAX_IT 40

/*
 * Ray altitude of the table's coordinate map: the root x in [lo, hi] of
 *   phi(x) = H x - K exp(-x) - tp,
 * x = (v - h_c) / H, K = z alpha_c, tp = rho - rc - h_c, i.e. the v with
 * image radius rc + v - z alpha_c exp(-(v - h_c)/H) = rho (bake/atm_table.py
 * _m, _solve_v). phi is increasing and concave; lo must be a lower bound of
 * the root and hi an upper bound; e_lo is K exp(-lo) when the caller knows
 * it (else any value <= 0).
 *
 * The baker inverts the map by 48 fixed bisection steps (each an exp); here
 * safeguarded Halley iteration (one exp a step) from the largest cheap lower
 * bound: lo, x >= tp / H (as K exp(-x) > 0) and, since K exp(-x) = H x - tp
 * <= H hi - tp at the root, x >= ln(K / (H hi - tp)). At the last two
 * K exp(-x) is known without an exp (H hi - tp, e_lo), and e_lo <= H hi -
 * tp shows that the log bound is below lo without taking it. Two or three steps
 * reach the root to ~1e-13 (double); the bisection's own result is within
 * 2^-48 of its bracket of the root, so both agree to ~1e-12 km, ~1e-12
 * table cells (tests/c/test_atmosphere.c measures it against a copy of the
 * bisection). Each evaluation also narrows [lo, hi]; a step leaving it is
 * replaced by bisection, so the iteration cannot diverge.
 *
 * Reference: Halley's method, e.g. Press, W. H. et al. 2007, Numerical
 * Recipes, 3rd ed., Cambridge, section 9.4.2.
 */
static oi_real solve_x(oi_real tp, oi_real k, oi_real lo, oi_real hi, oi_real e_lo)
{
    oi_real x = lo, e = e_lo, den, xb;
    int n;

    if (tp / ATM_HA > x) {
        x = tp / ATM_HA;
        e = (oi_real)0;
    }
    den = ATM_HA * hi - tp;
    /* the log bound exceeds x only if K exp(-x) > den: known when e is */
    if (den > (oi_real)0 && k > (oi_real)0 && !(e > (oi_real)0 && e <= den)) {
        xb = OI_LOG(k / den);
        if (xb > x) {
            x = xb;
            e = den;
        }
    }
    if (x > hi) {
        x = hi;
        e = (oi_real)0;
    }
    lo = x;
    if (!(e > (oi_real)0)) e = k * OI_EXP(-x);
    for (n = 0; n < ATM_MAX_IT; ++n) {
        oi_real phi = ATM_HA * x - e - tp;
        oi_real d1 = ATM_HA + e;
        oi_real xn;
        int halley;
        if (phi < (oi_real)0)
            lo = x;
        else
            hi = x;
        /* Halley: dx = -2 phi phi' / (2 phi'^2 - phi phi''), phi'' = -e;
         * the denominator is >= (H + e)^2 > 0 for x >= tp / H */
        xn = x - (oi_real)2 * phi * d1 / ((oi_real)2 * d1 * d1 + phi * e);
        halley = xn >= lo && xn <= hi;
        if (!halley) xn = OI_R(0.5) * (lo + hi);
        if (halley && OI_FABS(xn - x) <= ATM_X_TOL) return xn;
        x = xn;
        if (!(hi - lo > (oi_real)0)) break;
        e = k * OI_EXP(-x);
    }
    return x;
}

static oi_real clamp01(oi_real x)
{
    return x < (oi_real)0 ? (oi_real)0 : (x > (oi_real)1 ? (oi_real)1 : x);
}

/* Bilinear interpolation of a [NZ][NT] table of 16-bit codes (the decoding
 * min + scale * code is linear, so it is applied after interpolating). */
static oi_real bilinear(const unsigned short *tab, int i, int j, oi_real fu, oi_real ft)
{
    const unsigned short *r0 = tab + i * OI_ATM_NT + j;
    const unsigned short *r1 = r0 + OI_ATM_NT;
    oi_real a = ((oi_real)1 - ft) * (oi_real)r0[0] + ft * (oi_real)r0[1];
    oi_real b = ((oi_real)1 - ft) * (oi_real)r1[0] + ft * (oi_real)r1[1];
    return ((oi_real)1 - fu) * a + fu * b;
}

/*
 * Continuous table indices (iu along z, it along the window) of a point at
 * z (OI_ATM_Z_MIN_KM..OI_ATM_Z_MAX_KM) behind the Earth and rho < rho_hi
 * from the axis, with rc = R (1 + z/d) and a = z R_sun / d. Returns 0 when
 * the point is inside the window, -1 below it (no unblocked refracted ray:
 * fraction exactly 0). The coordinates of bake/atm_table.py (Window, coords):
 *   target = max(0, M(h_c) - 1.2 a); v_lo: M(v_lo) = target, in
 *   [h_c - 60, h_c] (the root is always inside: M(h_c - 60) < target);
 *   rho_lo = M(v_lo) = target; rho_mid = M(V_MID).
 * Below the window costs no transcendental; segment B a log; segment A a
 * log and two solves (solve_x).
 */
static int table_index(oi_real z, oi_real rho, oi_real rc, oi_real a, oi_real *iu,
                       oi_real *it)
{
    oi_real k = z * ATM_R(OI_ATM_ALPHA_C_RAD);
    oi_real rho_lo, rho_mid, rho_hi;

    rho_lo = rc + ATM_HC - k - OI_R(1.2) * a;
    if (rho_lo < (oi_real)0) rho_lo = (oi_real)0;
    if (rho < rho_lo) return -1;
    rho_hi = rc + a + ATM_R(OI_ATM_TOP_KM);
    rho_mid = rc + ATM_R(OI_ATM_V_MID_KM) - k * ATM_E_MID;
    if (rho >= rho_mid) {
        *it = (oi_real)(OI_ATM_NA - 1) + (rho - rho_mid) / (rho_hi - rho_mid) * (oi_real)OI_ATM_NB;
    } else {
        /* segment A: blend of the ray altitude and rho (bake/atm_table.py g_a),
         * in x = (v - h_c) / H: tv = (x - x_lo) / (x_mid - x_lo) */
        const oi_real x_mid = (ATM_R(OI_ATM_V_MID_KM) - ATM_HC) / ATM_HA;
        oi_real tp_lo = rho_lo - rc - ATM_HC;
        oi_real x_lo = solve_x(tp_lo, k, (oi_real)-60 / ATM_HA, (oi_real)0, (oi_real)0);
        /* at x_lo, K exp(-x_lo) = H x_lo - tp_lo (its equation) */
        oi_real x = solve_x(rho - rc - ATM_HC, k, x_lo, x_mid, ATM_HA * x_lo - tp_lo);
        oi_real tv = (x - x_lo) / (x_mid - x_lo);
        oi_real tr = (rho - rho_lo) / (rho_mid - rho_lo);
        *it = (((oi_real)1 - ATM_R(OI_ATM_W_RHO)) * tv + ATM_R(OI_ATM_W_RHO) * tr) *
              (oi_real)(OI_ATM_NA - 1);
    }
    *iu = OI_LOG(z / ATM_R(OI_ATM_Z_MIN_KM)) * ATM_C_IU;
    return 0;
}

/*
 * oi__atm_coords: the table's continuous indices for a point (internal, for
 * tests: declared in tests/c/test_atmosphere.c).
 *
 * Given:
 *   z      oi_real  distance behind the Earth's centre along the anti-Sun axis (km)
 *   rho    oi_real  distance from that axis (km)
 *   d      oi_real  Sun's distance (km), > 0
 *   r_e    oi_real  Earth radius (km); r_s Sun radius (km)
 * Returned:
 *   iu, it oi_real* continuous row and column indices (set when the function
 *                   returns 0, else 0)
 * Returned (function value):
 *   0 inside the window; -1 below it (fraction 0); +1 outside the
 *   atmosphere's reach (z <= 0 or rho >= rho_hi: geometric fraction); +2
 *   within the reach but z outside OI_ATM_Z_MIN_KM..OI_ATM_Z_MAX_KM.
 */
int oi__atm_coords(oi_real z, oi_real rho, oi_real d, oi_real r_e, oi_real r_s, oi_real *iu,
                   oi_real *it);
int oi__atm_coords(oi_real z, oi_real rho, oi_real d, oi_real r_e, oi_real r_s, oi_real *iu,
                   oi_real *it)
{
    oi_real rc, a;
    *iu = *it = (oi_real)0;
    if (!(z > (oi_real)0 && d > (oi_real)0)) return 1;
    rc = r_e * ((oi_real)1 + z / d);
    a = z * r_s / d;
    if (rho >= rc + a + ATM_R(OI_ATM_TOP_KM)) return 1;
    if (z < ATM_R(OI_ATM_Z_MIN_KM) || z > ATM_R(OI_ATM_Z_MAX_KM)) return 2;
    return table_index(z, rho, rc, a, iu, it);
}

/*
 * oi__atm_fraction: fraction of unobstructed sunlight reaching a point,
 * refraction and extinction by the atmosphere included (internal).
 *
 * Given:
 *   sun_km    oi_real[3]  Sun position, Earth-centred (km), finite, nonzero
 *   point_km  oi_real[3]  point position, Earth-centred (km), above the surface
 *   m         oi_model*   resolved model (oi__model_resolve): earth_radius_km,
 *                         sun_radius_km, limb_darkening are used
 *   frac      oi_real     geometric visible fraction of the uniform disc
 *   frac_ld   oi_real     geometric visible fraction of the limb-darkened disc
 *                         (both as oi_sun_fraction computes them)
 * Returned:
 *   fraction_atm oi_real*  fraction of the unobstructed sunlight (V band)
 *                          reaching the point, [0, 1]
 * Given and returned:
 *   dir       oi_real[3]  (may be NULL) on entry the unit vector from the
 *                         point to the Sun (the caller sets it; see Note 5);
 *                         where refracted light arrives (inside the table's
 *                         window with fraction_atm > 0, off the axis)
 *                         replaced by the unit vector towards where the light
 *                         comes from on average: the Sun's direction tilted by
 *                         psi away from the Earth's centre (the refracted
 *                         limb); untouched elsewhere
 * Returned (function value):
 *   OI_OK                 table used, or the point outside the atmosphere's
 *                         reach (geometric fraction, exact there).
 *   OI_WARN_TABLE_RANGE   the point is within the atmosphere's reach but its
 *                         distance behind the Earth is outside the table
 *                         (OI_ATM_Z_MIN_KM .. OI_ATM_Z_MAX_KM): the geometric
 *                         fraction is returned.
 * Notes:
 *  1. Coordinates (bake/atm_table.py): z = -point . s (s the unit vector to
 *     the Sun), rho = |point x s|; rc = R (1 + z/d), a = z R_sun / d with d
 *     = |sun|. The window along rho runs from rho_lo (deepest point any
 *     unblocked refracted ray reaches, minus the solar disc) to rho_hi = rc +
 *     a + top; below it the fraction is exactly 0, above it the geometric
 *     one. Rows are log-spaced in z; along rho the nodes are uniform in a
 *     blend of the model ray altitude v and rho up to v = OI_ATM_V_MID_KM,
 *     then uniform in rho.
 *  2. The table holds the limb-darkened disc (Neckel & Labs 1994). With
 *     OI_LIMB_UNIFORM the geometric difference frac - frac_ld is added
 *     (exact outside the atmosphere's effect), and the sum clamped to [0, 1].
 *  3. Accuracy: see the provenance in tables/oi_atm_table.c (maximum
 *     absolute error of the fraction against the deterministic reference
 *     bake/atm_rays.py at random off-grid points). The model atmosphere
 *     (1976 U.S. Standard, clouds opaque below 10 km, stated aerosol load)
 *     is itself uncertain by far more in a real eclipse season. The ray
 *     altitude is found by Halley iteration instead of the baker's
 *     bisection (solve_x): the indices agree to ~1e-12 cells (double).
 *  4. The table is baked for the default Earth and Sun radii; other model
 *     radii move the window with them (rc, a) but not the atmosphere.
 *  5. Cost (docs/atmosphere.md, "Cost"): the day side (point . sun >= 0)
 *     costs one dot product; points beyond rho_hi a normalisation, a dot
 *     and a cross product; below the window (umbra) a few multiplications
 *     more, no transcendental; in the window one log and one exp, plus in
 *     its lower segment two ray-altitude solves (together ~1.6 logs and
 *     ~2.7 exps). dir is an in/out argument so that the Sun's direction,
 *     which oi_illuminate forms anyway, is not formed again.
 * References:
 *   Link, F. 1969, Eclipse Phenomena in Astronomy, Springer (refraction and
 *   extinction in the Earth's shadow).
 *   Neckel, H. & Labs, D. 1994, Sol. Phys. 153, 91 (limb darkening).
 */
int oi__atm_fraction(const oi_real sun_km[3], const oi_real point_km[3], const oi_model *m,
                     oi_real frac, oi_real frac_ld, oi_real *fraction_atm, oi_real dir[3])
{
    oi_real s_hat[3], cr[3];
    oi_real d, z, rho2, rho, rc, a, rho_hi, iu, it, fu, ft, q, psi, f;
    int i, j, k;

    f = m->limb_darkening == OI_LIMB_DARKENED ? frac_ld : frac;
    *fraction_atm = f;
    /* the day side, known before normalising (an overflowing product is
     * +-inf or NaN: only +inf, a point far sunward, returns here) */
    if (oi__dot(point_km, sun_km) >= (oi_real)0) return OI_OK;
    d = oi__dot(sun_km, sun_km);
    if (OI_ISFINITE(d) && d > (oi_real)1) {
        /* no overflow or underflow in the sum of squares: plain norm */
        oi_real inv;
        d = OI_SQRT(d);
        inv = (oi_real)1 / d;
        for (k = 0; k < 3; ++k) s_hat[k] = sun_km[k] * inv;
    } else {
        d = oi__unit(sun_km, s_hat);
    }
    z = -oi__dot(point_km, s_hat);
    if (!(z > (oi_real)0 && d > (oi_real)0)) return OI_OK;
    rc = m->earth_radius_km * ((oi_real)1 + z / d);
    a = z * m->sun_radius_km / d;
    rho_hi = rc + a + ATM_R(OI_ATM_TOP_KM);
    oi__cross(point_km, s_hat, cr);
    rho2 = oi__dot(cr, cr);
    if (!(rho2 < rho_hi * rho_hi)) return OI_OK;
    if (z < ATM_R(OI_ATM_Z_MIN_KM) || z > ATM_R(OI_ATM_Z_MAX_KM)) return OI_WARN_TABLE_RANGE;
    rho = OI_SQRT(rho2);

    if (table_index(z, rho, rc, a, &iu, &it) < 0) {
        *fraction_atm = (oi_real)0;
        return OI_OK;
    }
    /* iu, it >= 0 up to rounding (z >= Z_MIN, rho >= rho_lo): truncation is
     * the floor wherever it matters, and the clamps catch the rest */
    i = (int)iu;
    if (i < 0) i = 0;
    if (i > OI_ATM_NZ - 2) i = OI_ATM_NZ - 2;
    j = (int)it;
    if (j < 0) j = 0;
    if (j > OI_ATM_NT - 2) j = OI_ATM_NT - 2;
    fu = iu - (oi_real)i;
    ft = it - (oi_real)j;
    q = ATM_R(OI_ATM_Q_MIN) + ATM_R(OI_ATM_Q_SCALE) * bilinear(oi__atm_q, i, j, fu, ft);
    f = clamp01(OI_EXP(q * ATM_LN10) - ATM_R(OI_ATM_F_FLOOR));
    if (m->limb_darkening != OI_LIMB_DARKENED) f = clamp01(f + (frac - frac_ld));
    *fraction_atm = f;

    if (dir != NULL && f > (oi_real)0 && rho > (oi_real)0) {
        /* tilt by psi towards e_out = (point + z s) / rho, the outward
         * normal of the axis: dir ~ dir_sun + tan(psi) e_out, normalised.
         * |psi| <= 0.012 rad (the codes' range): the series of tan to psi^7
         * is exact to rounding (next term 62/2835 psi^9 < 1e-18). */
        oi_real t, p2, n, u;
        psi = ATM_R(OI_ATM_PSI_MIN_RAD) +
              ATM_R(OI_ATM_PSI_SCALE_RAD) * bilinear(oi__atm_psi, i, j, fu, ft);
        p2 = psi * psi;
        t = psi * ((oi_real)1 +
                   p2 * (OI_R(1.0) / OI_R(3.0) +
                         p2 * (OI_R(2.0) / OI_R(15.0) + p2 * (OI_R(17.0) / OI_R(315.0)))));
        u = t / rho;
        for (k = 0; k < 3; ++k) dir[k] += u * (point_km[k] + z * s_hat[k]);
        n = (oi_real)1 / OI_SQRT(oi__dot(dir, dir));
        for (k = 0; k < 3; ++k) dir[k] *= n;
    }
    return OI_OK;
}

#else
typedef int oi__atmosphere_removed; /* ISO C forbids an empty translation unit */
#endif /* OI_NO_ATMOSPHERE */
