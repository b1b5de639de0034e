/* SPDX-License-Identifier: MIT */
/*
 * orbillum/sources.h: the other light on the target: earthshine (on a point,
 * and reflected by a sphere), the lunar phase law, the sunlight the atmosphere
 * scatters (oi_skylight).
 *
 * A section of orbillum.h, the header a program includes (it includes every
 * section); compiles alone, and includes the sections it uses.
 */
#ifndef ORBILLUM_SOURCES_H
#define ORBILLUM_SOURCES_H

#include "base.h"
#include "model.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- earthshine */

/*
 * Diffuse earthshine per unit albedo and unit solar irradiance at the Earth:
 * phi(theta, h) such that the scalar irradiance at the point is
 *   E_earth = albedo * TSI * (1 AU / |sun|)^2 * phi.
 * Given:   theta  angle at the Earth's centre between Sun and point (rad, [0, pi])
 *          h_km   altitude above the model's Earth radius (km, > 0)
 *          model  NULL or model (earth_model, earth_table, earth_radius_km;
 *                 tables: see oi_model)
 * Returned: phi   normalised scalar irradiance (>= 0)
 *           psi   mean incidence direction: angle from the nadir (point to Earth
 *                 centre) towards the Sun side, in the Sun-Earth-point plane (rad)
 * Returns: OI_OK (also for model->earth_model = OI_EARTH_LAMBERT: the far
 *          field (R/r)^2 p(theta), psi = 0, by choice); OI_WARN_TABLE_RANGE
 *          (outside the altitude range of the table used, or no table: the
 *          model's earth_table NULL and oi_earth_table_default() NULL, as
 *          with OI_NO_EARTH_TABLE: Lambert far field, psi = 0);
 *          OI_ERR_NULL (phi or psi NULL), OI_ERR_NONFINITE (theta or h_km
 *          NaN or infinite), OI_ERR_BELOW_SURFACE (h_km <= 0), OI_ERR_MODEL
 *          (a model field out of range, or a caller's earth_table or
 *          atm_table that fails its check, see oi_model), OI_ERR_RADIUS
 *          (negative model radius). On error phi and psi (when not NULL)
 *          are 0.
 * Notes:   The default table covers every altitude h > 0, from the surface to
 *          infinity: relative error <= 1e-3 where phi >= 1% of phi(0, h),
 *          absolute <= 1e-5 phi(0, h) elsewhere, measured from h = 1 m up
 *          (docs/earthshine-table.md); near the surface phi -> 2 cos(theta)
 *          (a flat Lambertian plane).
 */
int oi_earthshine(oi_real theta, oi_real h_km, const oi_model *model,
                  oi_real *phi, oi_real *psi);

/*
 * oi_earthshine_sphere: the flux a Lambertian sphere sends towards a
 * direction under earthshine alone, per unit Earth albedo, unit solar
 * irradiance at the Earth, unit target albedo and unit (a / d)^2 (a the
 * sphere's radius, d the observer's range): F such that the flux at the
 * observer is earth_albedo TSI (1 AU / |sun|)^2 target_albedo (a/d)^2 F.
 * Given:   theta, h_km, model  as oi_earthshine (earth_reflection chooses
 *                 the cubature, the table's moments or the mean direction)
 *          obs    direction from the target towards the observer in the
 *                 local frame (z the zenith, x towards the Sun's side in the
 *                 Sun-Earth-target plane, y normal to it); any length > 0
 * Returned: flux  F (>= 0)
 * Returns: oi_earthshine's statuses; OI_ERR_NULL (obs or flux NULL),
 *          OI_ERR_NONFINITE (a component of obs), OI_ERR_ZERO_VECTOR (obs
 *          zero). On error *flux is 0.
 * Notes:   By default F = phi S(o), S from a cubature over the visible
 *          sunlit Earth (9 x 4 nodes per piece, at most 8 pieces), with
 *          OI_EARTH_REFLECT_TABLE from the angular table's moments
 *          (docs/earthshine-angular.md, with the measured errors of both
 *          against a quadrature over the visible sunlit Earth); below the
 *          table's lowest altitude (100 km), without the table, with the
 *          Lambert far field or with OI_EARTH_REFLECT_MEAN: phi p(xi), xi
 *          the angle between obs and the mean direction psi.
 */
int oi_earthshine_sphere(oi_real theta, oi_real h_km, const oi_real obs[3],
                         const oi_model *model, oi_real *flux);

/* ---------------------------------------------------------------- moonlight */
#ifndef OI_NO_MOON
/* oi_moon_phase_law: the empirical lunar phase law, the Moon's brightness at
 * phase angle alpha (radians) relative to full Moon,
 * 10^(-0.4 (0.026 a + 4e-9 a^4)), a in degrees (Krisciunas & Schaefer 1991,
 * PASP 103, 1033, eq. 20, after Allen): in [2.8e-4, 1], relative error a few
 * epsilon against the formula. Returns 1 at alpha = 0; |alpha| is used,
 * clamped to [0, pi]; NaN gives 0. Beyond 150 degrees the law is an
 * extrapolation (src/sources/moon.c). */
oi_real oi_moon_phase_law(oi_real alpha);
#endif

/* ---------------------------------------------------------------- skylight */
#ifndef OI_NO_SKYLIGHT
/*
 * oi_skylight: the sunlight the atmosphere scatters towards a point above it.
 * Given:   theta_rad  angle at the Earth's centre from the Sun to the point,
 *                     [0, pi]
 *          h_km       altitude above model earth_radius_km (>= 0)
 *          model      NULL or model (sky_table)
 * Returned: e_over_sun  E_sky / E_sun: scalar irradiance per unit solar
 *                       irradiance at the point (>= 0)
 *           psi_rad     its mean direction, from the nadir towards the Sun
 * Returns: OI_OK; OI_WARN_TABLE_RANGE below the table's first row (the top
 *          of the atmosphere, 100 km: the first row's values); OI_ERR_NULL
 *          (an output NULL), OI_ERR_NONFINITE (an input NaN or infinite),
 *          OI_ERR_INPUT (theta outside [0, pi], h < 0), OI_ERR_MODEL,
 *          OI_ERR_RADIUS (invalid model or sky_table; NULL table:
 *          e_over_sun = 0 with OI_OK). Outputs zeroed on error.
 * Notes:   single scattering by air and aerosol of the refraction table's
 *          atmosphere, point Sun, straight rays; lines of sight ending on the
 *          sunlit Earth left out (their light is the albedo's). The table is
 *          read with the target's distance r through x = R_t / r, R_t the
 *          table's Earth radius. src/sources/skylight.c, docs/skylight.md.
 */
int oi_skylight(oi_real theta_rad, oi_real h_km, const oi_model *model, oi_real *e_over_sun,
                oi_real *psi_rad);
#endif

#ifdef __cplusplus
}
#endif

#endif /* ORBILLUM_SOURCES_H */
