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

/* Image radius (km) of the ray of lowest altitude v (km) at z km behind the
 * Earth, in the table's coordinate model alpha(v) = alpha_c exp(-(v - h_c)/H_A)
 * (bake/atm_table.py, _m): rho = rc + v - z alpha(v). Increasing in v. */
static oi_real image_radius(oi_real v, oi_real z, oi_real rc)
{
    return rc + v - z * ATM_R(OI_ATM_ALPHA_C_RAD) *
                        OI_EXP(-(v - ATM_R(OI_ATM_H_C_KM)) / ATM_R(OI_ATM_H_A_KM));
}

/* v in [lo, hi] with image_radius(v) = target, by OI_ATM_N_BISECT bisection
 * steps (the same fixed count as the baker: identical coordinates). */
static oi_real solve_v(oi_real target, oi_real z, oi_real rc, oi_real lo, oi_real hi)
{
    int i;
    for (i = 0; i < OI_ATM_N_BISECT; ++i) {
        oi_real mid = OI_R(0.5) * (lo + hi);
        if (image_radius(mid, z, rc) < target)
            lo = mid;
        else
            hi = mid;
    }
    return OI_R(0.5) * (lo + hi);
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
 *   dir       oi_real[3]  (may be NULL) unit vector from the point towards
 *                         where the light comes from on average: the Sun's
 *                         direction tilted by psi away from the Earth's
 *                         centre (the refracted limb)
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
 *     is itself uncertain by far more in a real eclipse season.
 *  4. The table is baked for the default Earth and Sun radii; other model
 *     radii move the window with them (rc, a) but not the atmosphere.
 * References:
 *   Link, F. 1969, Eclipse Phenomena in Astronomy, Springer (refraction and
 *   extinction in the Earth's shadow).
 *   Neckel, H. & Labs, D. 1994, Sol. Phys. 153, 91 (limb darkening).
 */
int oi__atm_fraction(const oi_real sun_km[3], const oi_real point_km[3], const oi_model *m,
                     oi_real frac, oi_real frac_ld, oi_real *fraction_atm, oi_real dir[3])
{
    oi_real s_hat[3], cr[3], to_sun[3], perp[3];
    oi_real d, z, rho, rc, a, rho_hi, rho_lo, rho_mid, v_lo, target, iu, it, fu, ft;
    oi_real q, psi, f, choice;
    int i, j, k, st = OI_OK;
    int use_table = 0;

    choice = m->limb_darkening == OI_LIMB_DARKENED ? frac_ld : frac;
    f = choice;
    psi = (oi_real)0;
    d = oi__unit(sun_km, s_hat);
    z = -oi__dot(point_km, s_hat);
    oi__cross(point_km, s_hat, cr);
    rho = oi__norm(cr);
    for (k = 0; k < 3; ++k) perp[k] = point_km[k] + z * s_hat[k];

    if (z > (oi_real)0 && d > (oi_real)0) {
        rc = m->earth_radius_km * ((oi_real)1 + z / d);
        a = z * m->sun_radius_km / d;
        rho_hi = rc + a + ATM_R(OI_ATM_TOP_KM);
        if (rho < rho_hi) {
            if (z < ATM_R(OI_ATM_Z_MIN_KM) || z > ATM_R(OI_ATM_Z_MAX_KM)) {
                st = OI_WARN_TABLE_RANGE;
            } else {
                use_table = 1;
            }
        }
    }

    if (use_table) {
        target = image_radius(ATM_R(OI_ATM_H_C_KM), z, rc) - OI_R(1.2) * a;
        if (target < (oi_real)0) target = (oi_real)0;
        v_lo = solve_v(target, z, rc, ATM_R(OI_ATM_H_C_KM) - (oi_real)60, ATM_R(OI_ATM_H_C_KM));
        rho_lo = image_radius(v_lo, z, rc);
        if (rho < rho_lo) {
            f = (oi_real)0;
        } else {
            rho_mid = image_radius(ATM_R(OI_ATM_V_MID_KM), z, rc);
            if (rho >= rho_mid) {
                it = (oi_real)(OI_ATM_NA - 1) +
                     (rho - rho_mid) / (rho_hi - rho_mid) * (oi_real)OI_ATM_NB;
            } else {
                /* segment A: blend of the ray altitude v and rho (bake/atm_table.py g_a) */
                oi_real v = solve_v(rho, z, rc, v_lo, ATM_R(OI_ATM_V_MID_KM));
                oi_real tv = (v - v_lo) / (ATM_R(OI_ATM_V_MID_KM) - v_lo);
                oi_real tr = (rho - rho_lo) / (rho_mid - rho_lo);
                it = (((oi_real)1 - ATM_R(OI_ATM_W_RHO)) * tv + ATM_R(OI_ATM_W_RHO) * tr) *
                     (oi_real)(OI_ATM_NA - 1);
            }
            iu = OI_LOG(z / ATM_R(OI_ATM_Z_MIN_KM)) /
                 OI_LOG(ATM_R(OI_ATM_Z_MAX_KM) / ATM_R(OI_ATM_Z_MIN_KM)) *
                 (oi_real)(OI_ATM_NZ - 1);
            i = (int)OI_FLOOR(iu);
            if (i < 0) i = 0;
            if (i > OI_ATM_NZ - 2) i = OI_ATM_NZ - 2;
            j = (int)OI_FLOOR(it);
            if (j < 0) j = 0;
            if (j > OI_ATM_NT - 2) j = OI_ATM_NT - 2;
            fu = iu - (oi_real)i;
            ft = it - (oi_real)j;
            q = ATM_R(OI_ATM_Q_MIN) + ATM_R(OI_ATM_Q_SCALE) * bilinear(oi__atm_q, i, j, fu, ft);
            psi = ATM_R(OI_ATM_PSI_MIN_RAD) +
                  ATM_R(OI_ATM_PSI_SCALE_RAD) * bilinear(oi__atm_psi, i, j, fu, ft);
            f = OI_EXP(q * ATM_R(2.302585092994045684)) - ATM_R(OI_ATM_F_FLOOR);
            f = clamp01(f);
            if (m->limb_darkening != OI_LIMB_DARKENED) f = clamp01(f + (frac - frac_ld));
        }
    }
    *fraction_atm = f;

    if (dir != NULL) {
        oi_real e_out[3];
        oi__sub(sun_km, point_km, to_sun);
        oi__unit(to_sun, to_sun);
        if (f > (oi_real)0 && oi__unit(perp, e_out) > (oi_real)0) {
            oi_real c = OI_COS(psi), s = OI_SIN(psi);
            for (k = 0; k < 3; ++k) dir[k] = c * to_sun[k] + s * e_out[k];
            oi__unit(dir, dir);
        } else {
            for (k = 0; k < 3; ++k) dir[k] = to_sun[k];
        }
    }
    return st;
}

#else
typedef int oi__atmosphere_removed; /* ISO C forbids an empty translation unit */
#endif /* OI_NO_ATMOSPHERE */
