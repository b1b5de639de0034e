/* SPDX-License-Identifier: MIT */
/*
 * orbillum/model.h: the model a call computes with (oi_model): the terms of
 * the illumination, the bounds of the constants and positions, the options,
 * the albedo map.
 *
 * A section of orbillum.h, the header a program includes (it includes every
 * section); compiles alone, and includes the sections it uses.
 */
#ifndef ORBILLUM_MODEL_H
#define ORBILLUM_MODEL_H

#include "base.h"
#include "../oi_table.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- model */

/* Terms of the illumination (bit mask). */
#define OI_TERM_SUN   (1u)
#define OI_TERM_EARTH (2u)
#define OI_TERM_MOON  (4u)
/* Sunlight scattered by the atmosphere towards the target (docs/skylight.md):
 * opt-in, not in OI_TERM_ALL or the defaults (removed by OI_NO_SKYLIGHT);
 * 0 with oi_model.no_atmosphere. */
#define OI_TERM_SKY   (8u)
#define OI_TERM_ALL   (OI_TERM_SUN | OI_TERM_EARTH | OI_TERM_MOON)

/* Physical bounds of oi_model's constants and of positions (see oi_model). */
#define OI_MODEL_TSI_MIN (1.0e-6)       /* W/m^2 */
#define OI_MODEL_TSI_MAX (1.0e6)        /* W/m^2 */
#define OI_MODEL_AU_MIN (1.0e3)         /* km */
#define OI_MODEL_AU_MAX (1.0e10)        /* km */
#define OI_MODEL_RADIUS_MIN (1.0e-3)    /* km */
#define OI_MODEL_RADIUS_MAX (1.0e8)     /* km */
/* Largest accepted distance of any position from the Earth's centre (km, about
 * 6700 AU): larger positions give OI_ERR_GEOMETRY, so that differences and
 * squares of positions stay finite in single precision. */
#define OI_POSITION_MAX_KM (1.0e12)

/* oi_model.earth_model */
#define OI_EARTH_TABLE   (0)  /* baked table, analytic beyond its range (default) */
#define OI_EARTH_LAMBERT (1)  /* far-field Lambert sphere, (R/r)^2 p(theta) */

/* oi_model.moon_model */
#define OI_MOON_PHASE_LAW (0) /* empirical lunar phase law (default) */
#define OI_MOON_LAMBERT   (1) /* Lambert sphere of albedo moon_albedo (seed) */

/* oi_model.earth_reflection: how a sphere reflects earthshine */
#define OI_EARTH_REFLECT_MOMENTS (0) /* from its angular distribution, by a
                                        cubature over the visible sunlit
                                        Earth (default) */
#define OI_EARTH_REFLECT_MEAN    (1) /* as if all of it came from its mean
                                        direction (exact in the far field) */
#define OI_EARTH_REFLECT_TABLE   (2) /* from its angular distribution, the
                                        angular table's moments (cheaper,
                                        less accurate near the terminator) */

/* oi_model.earth_shape: the Earth as occulter (its shadow, its hiding the
 * Moon and the target) and the surface the altitudes are measured from */
#define OI_EARTH_SPHERE (0)   /* sphere of radius earth_radius_km (default) */
#define OI_EARTH_WGS84  (1)   /* WGS-84 ellipsoid: equatorial radius
                                 earth_radius_km, flattening
                                 1/OI_WGS84_INV_FLATTENING, the frame's z axis
                                 the rotation axis (GCRS, J2000, TEME);
                                 docs/shadow.md section 10 */
/* oi_model.albedo_model: the Earth's albedo over the globe, read by
 * oi_illuminate (and its batch) only (docs/earthshine-albedo.md). Positions
 * are then taken in a frame whose z axis is the Earth's rotation axis (GCRS,
 * J2000 or TEME), latitudes above its equator. */
#define OI_ALBEDO_UNIFORM (0) /* oi_scene.earth_albedo everywhere (default) */
#define OI_ALBEDO_KNOCKE  (1) /* zonal and seasonal, Knocke, Ries & Tapley 1988;
                                 needs oi_scene.epoch_jd */
#define OI_ALBEDO_MAP     (2) /* the caller's latitude-longitude grid (oi_model.albedo_map);
                                 needs oi_scene.earth_rotation_rad */
/* Largest number of rows (latitudes) or columns (longitudes) of an albedo map. */
#define OI_ALBEDO_MAP_MAX_DIM (32768)
/* Valid range of oi_scene.epoch_jd (Julian date, UTC): 1900-01-01 0h to 2100-01-01 0h. */
#define OI_EPOCH_JD_MIN (2415020.5)
#define OI_EPOCH_JD_MAX (2488069.5)
/* Largest accepted |oi_scene.earth_rotation_rad| (rad). */
#define OI_EARTH_ROTATION_MAX_RAD (1.0e3)

/* oi_model.limb_darkening */
#define OI_LIMB_UNIFORM (0)   /* uniform solar disc (default) */
#define OI_LIMB_DARKENED (1)  /* irradiance uses a limb-darkened disc */

/* oi_model.band: the light that oi_shadow.fraction_atm (sun_fraction_atm)
 * and e_sun measure: both through the atmosphere table of the band (the
 * geometric fractions do not depend on it; docs/atmosphere.md "Two bands") */
#define OI_BAND_V     (0)     /* Johnson V, for cameras (default) */
#define OI_BAND_TOTAL (1)     /* total solar irradiance, for power, thermal and
                                 radiation pressure (OI_ERR_MODEL with
                                 OI_NO_TOTAL_BAND) */

/*
 * Model constants and options. Zero in any field means its default.
 * Fields are validated by every function that takes a model: a non-finite
 * value, a negative one, or one outside its physical bounds below gives
 * OI_ERR_MODEL (radii: OI_ERR_RADIUS). The bounds keep every intermediate
 * finite in both precisions:
 *   tsi_w_m2 in [OI_MODEL_TSI_MIN, OI_MODEL_TSI_MAX]; au_km in [OI_MODEL_AU_MIN, OI_MODEL_AU_MAX];
 *   radii in [OI_MODEL_RADIUS_MIN, OI_MODEL_RADIUS_MAX] km.
 */
typedef struct oi_model {
    oi_real tsi_w_m2;         /* solar irradiance at 1 AU (W/m^2) */
    oi_real au_km;            /* astronomical unit (km) */
    oi_real sun_radius_km;    /* solar radius (km) */
    oi_real earth_radius_km;  /* Earth radius (km) */
    oi_real moon_radius_km;   /* Moon radius (km) */
    oi_real moon_albedo;      /* Lambert Moon albedo (OI_MOON_LAMBERT only) */
    int earth_model;          /* OI_EARTH_TABLE or OI_EARTH_LAMBERT */
    int moon_model;           /* OI_MOON_PHASE_LAW or OI_MOON_LAMBERT */
    int limb_darkening;       /* OI_LIMB_UNIFORM or OI_LIMB_DARKENED */
    int no_atmosphere;        /* nonzero: as if the Earth had no atmosphere (no
                                 refracted sunlight, no scattered sunlight:
                                 OI_TERM_SKY then adds nothing) */
    const oi_earth_table *earth_table; /* earthshine table; NULL: oi_earth_table_default() */
    const oi_atm_table *atm_table;     /* atmosphere table; NULL: oi_atm_table_default() */
    int earth_reflection;     /* OI_EARTH_REFLECT_MOMENTS, _MEAN or _TABLE */
    int earth_shape;          /* OI_EARTH_SPHERE or OI_EARTH_WGS84 (OI_ERR_MODEL with
                                 OI_NO_OBLATE) */
    int albedo_model;         /* OI_ALBEDO_UNIFORM, OI_ALBEDO_KNOCKE or OI_ALBEDO_MAP */
    const float *albedo_map;  /* OI_ALBEDO_MAP: n_lat rows from north to south, each of
                                 n_lon cells from the Greenwich meridian eastwards,
                                 values in [0, 1] (see "Albedo map" below) */
    int albedo_map_n_lat;     /* rows, 1..OI_ALBEDO_MAP_MAX_DIM */
    int albedo_map_n_lon;     /* cells per row, 1..OI_ALBEDO_MAP_MAX_DIM */
    const oi_sky_table *sky_table;     /* scattered-sunlight table; NULL:
                                          oi_sky_table_default() */
    int band;                 /* OI_BAND_V or OI_BAND_TOTAL */
    const oi_atm_table *atm_total_table; /* the total band's atmosphere table; NULL:
                                            oi_atm_total_default() */
} oi_model;

/*
 * Albedo map (oi_model.albedo_map, read with albedo_model = OI_ALBEDO_MAP):
 * a caller-owned const array of n_lat * n_lon floats, row-major. Row i
 * covers the latitudes from 90 - 180 i / n_lat to 90 - 180 (i + 1) / n_lat
 * degrees (north to south), cell j of a row the east longitudes from
 * 360 j / n_lon to 360 (j + 1) / n_lon degrees from the Greenwich meridian;
 * map[i * n_lon + j] is the cell's albedo, in [0, 1] (e.g. a CERES monthly
 * mean resampled to the grid). The field between cell centres is bilinear,
 * periodic in longitude and constant in latitude beyond the first and last
 * rows' centres. The Greenwich meridian lies at oi_scene.earth_rotation_rad
 * from the frame's x axis, about its z axis (the Earth's rotation angle,
 * or the Greenwich sidereal time for a TEME frame). Every value a call
 * reads is checked (NaN or outside [0, 1]: OI_ERR_ALBEDO); the array is
 * never written. The field is integrated patch by patch over the lit
 * visible cap, so a call's cost grows with the cells under it
 * (docs/earthshine-albedo.md, "Cost"). albedo_model and the map's description are checked by the
 * functions that read them, oi_illuminate and oi_illuminate_batch (an
 * unknown model, a NULL map or a dimension out of range: OI_ERR_MODEL);
 * the others ignore them.
 */

#ifdef __cplusplus
}
#endif

#endif /* ORBILLUM_MODEL_H */
