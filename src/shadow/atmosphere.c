/* SPDX-License-Identifier: MIT */
/*
 * atmosphere.c: sunlight refracted and dimmed by the Earth's atmosphere into
 * the shadow, looked up in a baked oi_atm_table (include/oi_table.h; the
 * defaults tables/oi_atm_vband.c, and tables/oi_atm_total.c for the total
 * band, oi_model.band). A caller's table is checked by
 * src/model/atm_table_check.c.
 * The whole file disappears with OI_NO_ATMOSPHERE.
 */
#ifndef OI_NO_ATMOSPHERE

#include "shadow/shadow_internal.h"
#include "oi_tables_internal.h"

/* The ray-altitude solve (see solve_x): a Halley step whose size is below
 * ATM_X_TOL (units of h_a_km) leaves an error of order ATM_X_TOL^3 (cubic
 * convergence, relative curvature of phi below 1), far below the rounding
 * of phi itself; ATM_MAX_IT bounds the loop (bisection fallback halves a
 * bracket of < 20 units to < ATM_X_TOL in ~20 steps). */
#ifdef OI_SINGLE_PRECISION
#define ATM_X_TOL OI_R(1e-3)
#else
#define ATM_X_TOL OI_R(1e-4)
#endif
#define ATM_MAX_IT 40

/* First Halley iterate of solve_x: the largest cheap lower bound of the
 * root (lo, tp / H, ln(K / (H hi - tp))) and K exp(-x) there in *e. */
static oi_real solve_x_start(oi_real ha, oi_real tp, oi_real k, oi_real lo, oi_real hi,
                             oi_real e_lo, oi_real *e_out)
{
    oi_real x = lo, e = e_lo, den, xb;
    if (tp / ha > x) {
        x = tp / ha;
        e = (oi_real)0;
    }
    den = ha * hi - tp;
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
    if (!(e > (oi_real)0)) e = k * OI_EXP(-x);
    *e_out = e;
    return x;
}

/*
 * Ray altitude of the table's coordinate map: the root x in [lo, hi] of
 *   phi(x) = H x - K exp(-x) - tp,
 * x = (v - h_c) / H, K = z alpha_c, tp = rho - rc - h_c, i.e. the v with
 * image radius rc + v - z alpha_c exp(-(v - h_c)/H) = rho (the baker's
 * window, bake/atmosphere). phi is increasing and concave; lo must be a
 * lower bound of the root and hi an upper bound; e_lo is K exp(-lo) when the
 * caller knows it (else any value <= 0).
 *
 * The baker inverts the map by 48 fixed bisection steps (each an exp); here
 * safeguarded Halley iteration (one exp a step) from the largest cheap lower
 * bound: lo, x >= tp / H (as K exp(-x) > 0) and, since K exp(-x) = H x - tp
 * <= H hi - tp at the root, x >= ln(K / (H hi - tp)). At the last two
 * K exp(-x) is known without an exp (H hi - tp, e_lo), and e_lo <= H hi -
 * tp shows that the log bound is below lo without taking it. Two or three
 * steps reach the root to ~1e-13 (double); the bisection's own result is
 * within 2^-48 of its bracket of the root, so both agree to ~1e-12 km,
 * ~1e-12 table cells (tests/c/test_atmosphere.c measures it against a copy
 * of the bisection). Each evaluation also narrows [lo, hi]; a step leaving
 * it is replaced by bisection, so the iteration cannot diverge.
 *
 * Reference: Halley's method, e.g. Press, W. H. et al. 2007, Numerical
 * Recipes, 3rd ed., Cambridge, section 9.4.2.
 */
static oi_real solve_x(oi_real ha, oi_real tp, oi_real k, oi_real lo, oi_real hi, oi_real e_lo)
{
    oi_real e;
    oi_real x = solve_x_start(ha, tp, k, lo, hi, e_lo, &e);
    int n;

    lo = x;
    for (n = 0; n < ATM_MAX_IT; ++n) {
        oi_real phi = ha * x - e - tp;
        oi_real d1 = ha + e;
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

/*
 * Continuous table indices (iu along z, it along the window) of a point at
 * z (z_min_km..z_max_km) behind the Earth and rho < rho_hi from the axis,
 * with rc = R (1 + z/d) and a = z R_sun / d. Returns 0 when the point is
 * inside the window, -1 below it (no unblocked refracted ray: fraction
 * exactly 0). The coordinates of the baker's window:
 *   target = max(0, M(h_c) - 1.2 a); v_lo: M(v_lo) = target, in
 *   [h_c - 60, h_c] (the root is inside: M(h_c - 60) < target), or in
 *   [h_c - 60, v_mid] where M(h_c) - 1.2 a <= 0 (target the axis, z >~
 *   R / alpha_c);
 *   rho_lo = M(v_lo) = target; rho_mid = M(v_mid).
 * Below the window costs no transcendental; segment B a log; segment A a
 * log and two solves (solve_x).
 */
static int table_index(const oi_atm_table *t, oi_real z, oi_real rho, oi_real rc, oi_real a,
                       oi_real *iu, oi_real *it)
{
    const oi_real ha = t->h_a_km, hc = t->h_c_km;
    oi_real k = z * t->alpha_c_rad;
    oi_real rho_lo, rho_mid, rho_hi;
    oi_real x_top = (oi_real)0; /* upper end of v_lo's bracket, in x */

    rho_lo = rc + hc - k - OI_R(1.2) * a;
    if (!(rho_lo > (oi_real)0)) {
        /* the lowest ray's image has crossed the axis: the window starts on
         * the axis, v_lo (the ray landing there) above h_c */
        rho_lo = (oi_real)0;
        x_top = (t->v_mid_km - hc) / ha;
    }
    if (rho < rho_lo) return -1;
    rho_hi = rc + a + t->top_km;
    rho_mid = rc + t->v_mid_km - k * t->e_mid;
    if (rho >= rho_mid) {
        *it = (oi_real)(t->na - 1) + (rho - rho_mid) / (rho_hi - rho_mid) * (oi_real)t->nb;
    } else {
        /* segment A: blend of the ray altitude and rho, in x = (v - h_c) /
         * H: tv = (x - x_lo) / (x_mid - x_lo) */
        const oi_real x_mid = (t->v_mid_km - hc) / ha;
        oi_real tp_lo = rho_lo - rc - hc;
        oi_real x_lo = solve_x(ha, tp_lo, k, (oi_real)-60 / ha, x_top, (oi_real)0);
        /* at x_lo, K exp(-x_lo) = H x_lo - tp_lo (its equation) */
        oi_real x = solve_x(ha, rho - rc - hc, k, x_lo, x_mid, ha * x_lo - tp_lo);
        oi_real tv = (x - x_lo) / (x_mid - x_lo);
        oi_real tr = (rho - rho_lo) / (rho_mid - rho_lo);
        *it = (((oi_real)1 - t->w_rho) * tv + t->w_rho * tr) * (oi_real)(t->na - 1);
    }
    *iu = OI_LOG(z / t->z_min_km) * t->c_iu;
    return 0;
}

/*
 * oi__atm_coords: the continuous indices of a point in table t (internal,
 * for tests: declared in tests/c/test_atmosphere.c).
 *
 * Given:
 *   t      oi_atm_table*  the table
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
 *   within the reach but z outside z_min_km..z_max_km.
 */
int oi__atm_coords(const oi_atm_table *t, oi_real z, oi_real rho, oi_real d, oi_real r_e,
                   oi_real r_s, oi_real *iu, oi_real *it);
int oi__atm_coords(const oi_atm_table *t, oi_real z, oi_real rho, oi_real d, oi_real r_e,
                   oi_real r_s, oi_real *iu, oi_real *it)
{
    oi_real rc, a;
    *iu = *it = (oi_real)0;
    if (!(z > (oi_real)0 && d > (oi_real)0)) return 1;
    rc = r_e * ((oi_real)1 + z / d);
    a = z * r_s / d;
    if (rho >= rc + a + t->top_km) return 1;
    if (z < t->z_min_km || z > t->z_max_km) return 2;
    return table_index(t, z, rho, rc, a, iu, it);
}

/* On the anti-Sun axis the refracted light's mean direction is the Sun's (the
 * ring of the limb is lit all round) and the tilt's direction e_out is
 * undefined: below rho = TILT_AXIS z, where the cross product's rounding
 * (a few u |point|) is a noticeable part of rho, no tilt. The tilt dropped
 * there is within the psi table's quantisation step (3.8e-7 rad; double),
 * or a few 1e-5 rad at the Moon's distance (float, whose e_out is then
 * known to ~6 %); beyond it e_out turns with the scene, so that the
 * direction does too (tests/python/test_properties.py, the rotation). */
#ifdef OI_SINGLE_PRECISION
#define TILT_AXIS OI_R(1.0e-6)
#else
#define TILT_AXIS OI_R(1.0e-10)
#endif

/* Direction of the refracted light: dir (the Sun's) tilted by psi towards
 * e_out = (point + z s) / rho, the outward normal of the axis: dir ~ dir +
 * tan(psi) e_out, normalised. |psi| <= OI_ATM_PSI_MAX_RAD: the series of tan
 * to psi^7 is exact to rounding (next term 62/2835 psi^9 < 5e-14 psi). */
static void tilt(oi_real psi, const oi_real point_km[3], oi_real z, const oi_real s_hat[3],
                 oi_real rho, oi_real dir[3])
{
    const oi_real p2 = psi * psi;
    const oi_real t = psi * ((oi_real)1 +
                             p2 * (OI_R(1.0) / OI_R(3.0) +
                                   p2 * (OI_R(2.0) / OI_R(15.0) + p2 * (OI_R(17.0) / OI_R(315.0)))));
    const oi_real u = t / rho;
    oi_real n;
    int k;
    for (k = 0; k < 3; ++k) dir[k] += u * (point_km[k] + z * s_hat[k]);
    n = (oi_real)1 / OI_SQRT(oi__dot(dir, dir));
    for (k = 0; k < 3; ++k) dir[k] *= n;
}

/* Unit vector s_hat towards the Sun; returns |sun|. */
static oi_real sun_unit(const oi_real sun_km[3], oi_real s_hat[3])
{
    oi_real d = oi__dot(sun_km, sun_km);
    int k;
    if (OI_ISFINITE(d) && d > (oi_real)1) {
        /* no overflow or underflow in the sum of squares: plain norm */
        oi_real inv;
        d = OI_SQRT(d);
        inv = (oi_real)1 / d;
        for (k = 0; k < 3; ++k) s_hat[k] = sun_km[k] * inv;
        return d;
    }
    return oi__unit(sun_km, s_hat);
}

/* The uniform disc from the limb-darkened table: the shift sigma(F), in
 * units of the disc's image radius a, that moves the lookup point along rho
 * to where the limb-darkened disc's fraction equals the uniform disc's
 * behind a straight edge, the edge's position taken from the table's own F
 * (bake/atmosphere/disc_shift.py: sigma = sqrt(g) (1 - 2F) (C0 + C1 g + C2
 * g^2), g = F (1 - F), fit error 7.0e-4 in the fraction). Zero at F = 0,
 * 1/2 and 1. The total band's table holds a disc with the Eddington law
 * (2 + 3 mu) / 5, whose own fit is OI_ATM_TOTAL_SHIFT_C* (error 4.0e-4). */
#define OI_ATM_SHIFT_C0 OI_R(0.256474)
#define OI_ATM_SHIFT_C1 OI_R(-1.25786)
#define OI_ATM_SHIFT_C2 OI_R(3.00221)
#ifndef OI_NO_TOTAL_BAND
#define OI_ATM_TOTAL_SHIFT_C0 OI_R(0.229226)
#define OI_ATM_TOTAL_SHIFT_C1 OI_R(-0.92399)
#define OI_ATM_TOTAL_SHIFT_C2 OI_R(2.04122)
#define ATM_N_BANDS 2
#else
#define ATM_N_BANDS 1
#endif
/* the coefficients of each band (oi_model.band, checked by oi__model_resolve) */
static const oi_real shift_c[ATM_N_BANDS][3] = {
    {OI_ATM_SHIFT_C0, OI_ATM_SHIFT_C1, OI_ATM_SHIFT_C2},
#ifndef OI_NO_TOTAL_BAND
    {OI_ATM_TOTAL_SHIFT_C0, OI_ATM_TOTAL_SHIFT_C1, OI_ATM_TOTAL_SHIFT_C2},
#endif
};
static oi_real uniform_shift(oi_real f, int band)
{
    const oi_real g = f * ((oi_real)1 - f);
    const oi_real *c = shift_c[band == OI_BAND_V ? 0 : ATM_N_BANDS - 1];
    if (!(g > (oi_real)0)) return (oi_real)0;
    return OI_SQRT(g) * ((oi_real)1 - (oi_real)2 * f) * (c[0] + g * (c[1] + g * c[2]));
}

/* The table's fraction (limb-darkened disc) at continuous indices iu, it,
 * with the cells' floors and weights; iu, it >= 0 up to rounding (z >=
 * z_min, rho >= rho_lo): the cells are clamped, the fractions not (a
 * rounding's linear extrapolation); q = log10(F + f_floor). */
static oi_real table_fraction(const oi_atm_table *t, oi_real iu, oi_real it, int *i, int *j,
                              oi_real *fu, oi_real *ft)
{
    oi_real q;
    *i = oi__cell_floor(iu, t->nz, fu);
    *j = oi__cell_floor(it, t->nt, ft);
    q = t->q_min + t->q_scale * oi__bilinear_u16(t->q, t->nt, *i, *j, *fu, *ft);
    return clamp01(OI_EXP(q * t->ln10) - t->f_floor);
}

/* The table that serves a resolved model's band (a caller's was checked by
 * oi__model_resolve; the defaults are trusted); NULL: none. */
static const oi_atm_table *table_of(const oi_model *m)
{
#ifndef OI_NO_TOTAL_BAND
    if (m->band == OI_BAND_TOTAL)
        return m->atm_total_table != NULL ? m->atm_total_table : oi_atm_total_default();
#endif
    return m->atm_table != NULL ? m->atm_table : oi_atm_table_default();
}

/*
 * oi__atm_fraction: fraction of unobstructed sunlight reaching a point,
 * refraction and extinction by the atmosphere included (internal).
 *
 * Given:
 *   sun_km    oi_real[3]  Sun position, Earth-centred (km), finite, nonzero
 *   point_km  oi_real[3]  point position, Earth-centred (km), above the surface
 *   m         oi_model*   resolved model (oi__model_resolve): earth_radius_km,
 *                         sun_radius_km, limb_darkening, band, atm_table
 *                         (band V) or atm_total_table (band total) are used
 *                         (oi__atm_fraction_about: all but earth_radius_km)
 *   earth_radius_km oi_real  oi__atm_fraction_about only: the radius of the
 *                         sphere the table's coordinates are taken about (the
 *                         ellipsoid's equivalent sphere, src/shadow/sun_fraction.c)
 *   frac      oi_real     geometric visible fraction of the uniform disc
 *   frac_ld   oi_real     geometric visible fraction of the limb-darkened disc
 *                         (both as oi_sun_fraction computes them)
 * Returned:
 *   fraction_atm oi_real*  fraction of the unobstructed sunlight (in the
 *                          model's band) reaching the point, [0, 1]
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
 *                         reach (geometric fraction, exact there), or no
 *                         table (m->atm_table and oi_atm_table_default()
 *                         NULL: the geometric fraction).
 *   OI_WARN_TABLE_RANGE   the point is within the atmosphere's reach but its
 *                         distance behind the Earth is outside the table
 *                         (z_min_km .. z_max_km): the geometric fraction is
 *                         returned.
 * Notes:
 *  1. Coordinates (the baker's window, bake/atmosphere, docs/atmosphere.md):
 *     z = -point . s (s the unit vector to the Sun), rho = |point x s|; rc =
 *     R (1 + z/d), a = z R_sun / d with d = |sun|. The window along rho runs
 *     from rho_lo (deepest point any unblocked refracted ray reaches, minus
 *     the solar disc) to rho_hi = rc + a + top; below it the fraction is
 *     exactly 0, above it the geometric one. Rows are log-spaced in z; along
 *     rho the nodes are uniform in a blend of the model ray altitude v and
 *     rho up to v = v_mid_km, then uniform in rho.
 *  2. The table holds the limb-darkened disc (Neckel & Labs 1994; the total
 *     band's the Eddington law, docs/atmosphere.md "Two bands"). With
 *     OI_LIMB_UNIFORM the table is read a second time, at the point moved
 *     along rho by a uniform_shift(F) (at most 0.042 a) to where the
 *     limb-darkened disc's fraction equals the uniform disc's behind an
 *     equivalent straight edge placed by F itself: monotonic wherever the
 *     table is, the geometric fraction outside the atmosphere's reach
 *     (docs/atmosphere.md, "The uniform disc"); the direction is the
 *     limb-darkened disc's.
 *  3. Accuracy: see the provenance of the table (tables/oi_atm_vband.c:
 *     maximum absolute error of the fraction against the baker's
 *     deterministic ray reference at random off-grid points). The model
 *     atmosphere (1976 U.S. Standard, clouds opaque below 10 km, stated
 *     aerosol load) is itself uncertain by far more in a real eclipse
 *     season. The ray altitude is found by Halley iteration instead of the
 *     baker's bisection (solve_x): the indices agree to ~1e-12 cells
 *     (double).
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
    return oi__atm_fraction_about(sun_km, point_km, m, m->earth_radius_km, frac, frac_ld,
                                  fraction_atm, dir);
}

/* The same about a sphere of another radius than the model's: no copy of
 * the model on the caller's stack (make stack). */
int oi__atm_fraction_about(const oi_real sun_km[3], const oi_real point_km[3], const oi_model *m,
                           oi_real earth_radius_km, oi_real frac, oi_real frac_ld,
                           oi_real *fraction_atm, oi_real dir[3])
{
    const oi_atm_table *t;
    oi_real s_hat[3], cr[3];
    oi_real d, z, rho2, rho, rc, a, rho_hi, iu, it, fu, ft, f;
    int i, j;

    f = m->limb_darkening == OI_LIMB_DARKENED ? frac_ld : frac;
    *fraction_atm = f;
    /* the day side, known before normalising (an overflowing product is
     * +-inf or NaN: only +inf, a point far sunward, returns here) */
    if (oi__dot(point_km, sun_km) >= (oi_real)0) return OI_OK;
    t = table_of(m);
    if (t == NULL) return OI_OK;
    d = sun_unit(sun_km, s_hat);
    z = -oi__dot(point_km, s_hat);
    if (!(z > (oi_real)0 && d > (oi_real)0)) return OI_OK;
    rc = earth_radius_km * ((oi_real)1 + z / d);
    a = z * m->sun_radius_km / d;
    rho_hi = rc + a + t->top_km;
    oi__cross(point_km, s_hat, cr);
    rho2 = oi__dot(cr, cr);
    if (!(rho2 < rho_hi * rho_hi)) return OI_OK;
    if (z < t->z_min_km || z > t->z_max_km) return OI_WARN_TABLE_RANGE;
    rho = OI_SQRT(rho2);

    if (table_index(t, z, rho, rc, a, &iu, &it) < 0) {
        *fraction_atm = (oi_real)0;
        return OI_OK;
    }
    f = table_fraction(t, iu, it, &i, &j, &fu, &ft);
    if (m->limb_darkening != OI_LIMB_DARKENED) {
        /* the uniform disc: the table read again at the shifted point
         * (Note 2); the direction stays the limb-darkened disc's */
        oi_real ds = a * uniform_shift(f, m->band);
        if (ds != (oi_real)0) {
            oi_real iu2, it2, fu2, ft2;
            int i2, j2;
            f = table_index(t, z, rho + ds, rc, a, &iu2, &it2) < 0
                    ? (oi_real)0
                    : table_fraction(t, iu2, it2, &i2, &j2, &fu2, &ft2);
        }
    }
    *fraction_atm = f;
    if (dir != NULL && f > (oi_real)0 && rho > TILT_AXIS * z)
        tilt(t->psi_min_rad + t->psi_scale_rad * oi__bilinear_u16(t->psi, t->nt, i, j, fu, ft),
             point_km, z, s_hat, rho, dir);
    return OI_OK;
}

#else
typedef int oi__atmosphere_removed; /* ISO C forbids an empty translation unit */
#endif /* OI_NO_ATMOSPHERE */
