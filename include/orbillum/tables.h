/* SPDX-License-Identifier: MIT */
/*
 * orbillum/tables.h: the model's baked tables: which table a call uses, how a
 * caller's table is checked, the library's defaults (oi_*_default) and the
 * bounds of a caller's atmosphere table. The tables' layouts:
 * include/oi_table.h.
 *
 * A section of orbillum.h, the header a program includes (it includes every
 * section); compiles alone, and includes the sections it uses.
 */
#ifndef ORBILLUM_TABLES_H
#define ORBILLUM_TABLES_H

#include "base.h"
#include "../oi_table.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- tables */

/*
 * Baked tables of a model (include/oi_table.h, docs/tables.md).
 *
 * earth_table: the earthshine table oi_earthshine and oi_illuminate use
 *   with earth_model = OI_EARTH_TABLE. NULL: oi_earth_table_default(). A
 *   caller's table is checked on every call that uses it: format
 *   OI_TABLE_FORMAT, kind OI_TABLE_KIND_EARTHSHINE (or 0), n_lit, n_term,
 *   n_alt >= 2 (n_alt >= 3 when w_min = 0), q and psi not NULL, 0 <= w_min <
 *   w_max <= pi/2, term_k0 in [0, 20], term_kp in [0, 100]; otherwise the
 *   call returns OI_ERR_MODEL with its outputs zeroed. Beyond the table's
 *   altitude range: the Lambert far field and OI_WARN_TABLE_RANGE.
 * atm_table: the atmosphere table oi_sun_fraction and oi_illuminate use
 *   when the atmosphere is on (no_atmosphere = 0, OI_NO_ATMOSPHERE not
 *   defined); ignored otherwise. NULL: oi_atm_table_default(). A caller's
 *   table is checked by every function that takes the model: format
 *   OI_ATM_FORMAT, kind OI_TABLE_KIND_ATMOSPHERE, nz, na >= 2, nb >= 1, each
 *   <= 32767, nt = na + nb, q and psi not NULL, 0 < z_min_km < z_max_km <=
 *   OI_POSITION_MAX_KM, 0 < h_a_km <= OI_POSITION_MAX_KM, 0 <= h_c_km <
 *   v_mid_km < top_km <= OI_ATM_TOP_MAX_KM, alpha_c_rad and w_rho in [0, 1],
 *   f_floor in (0, 1], q_min and q_scale finite, psi_min_rad and psi_min_rad
 *   + 65535 psi_scale_rad within +-OI_ATM_PSI_MAX_RAD, e_mid in (0, 1],
 *   c_iu in (0, OI_POSITION_MAX_KM], ln10 in [2.3, 2.31] (NaN fails every
 *   check); otherwise OI_ERR_MODEL, outputs zeroed. The fields the lookup
 *   does not read (earth_radius_km, sun_radius_km, au_km, info) are not
 *   checked. The table must be compiled in the caller's precision (its
 *   grid is oi_real).
 * atm_total_table: the same for band = OI_BAND_TOTAL (the total solar
 *   irradiance's table), checked the same way where it would be used (band
 *   total, atmosphere on); NULL: oi_atm_total_default(). atm_table is then
 *   not used, nor atm_total_table with band V.
 *
 * Defaults: each is returned by a function of its own translation unit
 * (src/model/earth_table_default.c, src/model/atm_table_default.c), the only reference
 * to the default table's bytes. The library's: oi_earth_diffuse (every
 * altitude) and oi_atm_vband; -DOI_EARTH_TABLE_DEFAULT=<table> /
 * -DOI_ATM_TABLE_DEFAULT=<table> at the library's build choose another.
 * A program may define either function itself, returning its own table or
 * NULL: then neither the library's function nor its table is linked. A
 * default is trusted (not checked). A NULL default with a NULL field:
 * earthshine is the Lambert far field with OI_WARN_TABLE_RANGE (as with
 * OI_NO_EARTH_TABLE, which makes the library's default NULL); the
 * atmosphere adds nothing, fraction_atm is the geometric fraction of the
 * model's disc (as with OI_NO_ATMOSPHERE, which makes its default NULL).
 */
const oi_earth_table *oi_earth_table_default(void);
const oi_atm_table *oi_atm_table_default(void);
/* oi_atm_total_default: the total band's atmosphere table (oi_atm_total,
 * tables/oi_atm_total.c), used with band = OI_BAND_TOTAL when
 * atm_total_table is NULL; NULL with OI_NO_TOTAL_BAND or OI_NO_ATMOSPHERE.
 * Its own translation unit (src/model/atm_table_total_default.c), as the others;
 * trusted. A caller's atm_total_table is checked as atm_table is, where it
 * would be used (band total, atmosphere on). */
const oi_atm_table *oi_atm_total_default(void);
/* oi_earth_angular_default: the earthshine angular table (oi_earth_angular,
 * include/oi_table.h) a sphere's reflection of earthshine uses with
 * earth_reflection = OI_EARTH_REFLECT_TABLE; NULL with OI_NO_EARTH_ANGULAR
 * or OI_NO_EARTH_TABLE. Its own translation unit, as the others; trusted. */
const oi_earth_angular_table *oi_earth_angular_default(void);
/* oi_sky_table_default: the scattered-sunlight table (oi_sky_vband,
 * include/oi_table.h, docs/skylight.md) OI_TERM_SKY uses when
 * oi_model.sky_table is NULL; NULL with OI_NO_SKYLIGHT (then OI_TERM_SKY
 * adds nothing). Its own translation unit, as the others; trusted. A
 * caller's sky_table is checked by every call that uses it: format
 * OI_SKY_FORMAT, kind OI_TABLE_KIND_SKYLIGHT, n_theta and n_alt in
 * [4, 4096], v and psi not NULL, q_floor in (0, 1], 0 < w_min < w_max <= pi/2,
 * earth_radius_km
 * in [OI_MODEL_RADIUS_MIN, OI_MODEL_RADIUS_MAX], top_km in (0, 1000],
 * theta_scale and w_scale within 1e-3 relative of their definitions;
 * otherwise OI_ERR_MODEL with the outputs zeroed. */
const oi_sky_table *oi_sky_table_default(void);

/* Highest top of a caller's atmosphere table (km): oi_illuminate's test
 * for certain full sunlight assumes that no grazing ray climbs above
 * twice this height. */
#define OI_ATM_TOP_MAX_KM (100.0)
/* Largest |psi| a caller's atmosphere table may encode (rad): the tilt of
 * the light's direction uses a series of tan exact to rounding below it. */
#define OI_ATM_PSI_MAX_RAD (0.05)

#ifdef __cplusplus
}
#endif

#endif /* ORBILLUM_TABLES_H */
