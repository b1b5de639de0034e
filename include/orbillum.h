/* SPDX-License-Identifier: MIT */
/*
 * orbillum.h: how an object in orbit is lit, and how a camera should expose it.
 *
 * The one public header of the runtime. Freestanding C99: no allocation, no
 * I/O, no mutable globals, no recursion; every function is reentrant and all
 * state belongs to the caller.
 *
 * Conventions (as ERFA):
 *   - positions are Earth-centred inertial, in km; angles in radians;
 *     irradiance in W/m^2; radiance in W/m^2/sr.
 *   - functions return a status: 0 OK; positive = warning, the result is
 *     computed (e.g. outside a table's range, analytic model used); negative =
 *     error, nothing computed and every output zeroed.
 *   - a zeroed oi_model means "all defaults" (oi_constants.h). A NULL model
 *     pointer means the same.
 *
 * Compile-time options: see oi_config.h.
 */
#ifndef ORBILLUM_H
#define ORBILLUM_H

#include "oi_config.h"
#include "oi_constants.h"
#include "oi_table.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- version */

/* Version of this header (semantic: a new MINOR extends the contract, a new
 * MAJOR breaks it). OI_VERSION encodes it as MAJOR * 10000 + MINOR * 100 +
 * PATCH. */
#define OI_VERSION_MAJOR 0
#define OI_VERSION_MINOR 2
#define OI_VERSION_PATCH 0
#define OI_VERSION (OI_VERSION_MAJOR * 10000L + OI_VERSION_MINOR * 100L + OI_VERSION_PATCH)

/* Precision guard: the public names of a single-precision build end in _sp
 * (oi_config.h). */

/*
 * oi_version: the version of the archive the program is linked with.
 * Returned (function value): OI_VERSION of the header the archive was built
 * from. A program compares it with its own OI_VERSION (the header it was
 * compiled with): equal, or an archive of the same MAJOR and a MINOR at least
 * the program's, keeps every declaration the program uses.
 */
long oi_version(void);

/* ---------------------------------------------------------------- status */

enum oi_status {
    OI_OK = 0,
    /* warnings: result computed */
    OI_WARN_TABLE_RANGE = 1,      /* outside a baked table: analytic model used */
    /* errors: result not computed, outputs zeroed */
    OI_ERR_NULL = -1,             /* a required pointer is NULL */
    OI_ERR_NONFINITE = -2,        /* NaN or infinite input component */
    OI_ERR_ZERO_VECTOR = -3,      /* a position that must be nonzero is zero */
    OI_ERR_BELOW_SURFACE = -4,    /* target or observer at or below the Earth's surface */
    OI_ERR_OBSERVER_AT_TARGET = -5, /* observer inside the target's sphere (range <=
                                       target radius; oi_expose_scene: range 0). The
                                       positions are taken as given in oi_real: in
                                       single precision an observer closer to the
                                       target than the spacing of floats there (3.9 m
                                       at 42,000 km) may round onto it, and is then
                                       this error, never a result of range 0 */
    OI_ERR_ALBEDO = -6,           /* an albedo outside [0, 1] */
    OI_ERR_RADIUS = -7,           /* a radius <= 0 (target, or a model radius) */
    OI_ERR_MODEL = -8,            /* an oi_model field out of range */
    OI_ERR_CAMERA = -9,           /* an oi_camera field out of range */
    OI_ERR_MAGNITUDE = -10,       /* a magnitude outside [OI_MAG_MIN, OI_MAG_MAX], or a
                                     flux brighter than magnitude OI_MAG_MIN */
    OI_ERR_TERMS = -11,           /* unknown bits in a terms mask (oi_scene.terms) */
    OI_ERR_GEOMETRY = -12,        /* impossible geometry (e.g. Sun inside the Earth's
                                     radius plus its own, point inside the Sun) */
    OI_ERR_INPUT = -13,           /* an argument out of range that is no camera, model,
                                     magnitude or albedo: an exposure goal, a negative
                                     flux or irradiance, a background radiance */
    OI_ERR_FLAGS = -14,           /* unknown bits in a flags mask (oi_expose_in.flags) */
    OI_ERR_SHAPE = -15            /* a bad facet, shape or attitude quaternion (oi_shape_check) */
};

/* oi_status_name: the name of a status, the enum name without its "OI_"
 * prefix ("OK", "WARN_TABLE_RANGE", "ERR_NONFINITE", ...); "UNKNOWN" for any
 * other value. Never NULL; static storage. The names are stable: scripts
 * (the planner's CSV status column) match on them. */
const char *oi_status_name(int status);

/*
 * Floating-point exceptions: no call raises FE_INVALID, FE_DIVBYZERO or
 * FE_OVERFLOW, on valid input or on the inputs its documented errors
 * refuse (NaN, infinities, zero vectors, subnormal and out-of-range values):
 * checks compare quietly and come before the arithmetic they guard
 * (tests/c/test_fp_exceptions.c runs every documented error with traps on).
 * Not yet: finite positions near the largest oi_real (beyond about 1e37 km
 * in single precision, 1e307 km in double), which oi_sun_fraction's sphere
 * and oi_expose_scene take, may still raise FE_OVERFLOW in their norms.
 */

/* Valid range of magnitudes accepted as input. */
#define OI_MAG_MIN (-30.0)
#define OI_MAG_MAX (50.0)

/* ---------------------------------------------------------------- model */

/* Terms of the illumination (bit mask). */
#define OI_TERM_SUN   (1u)
#define OI_TERM_EARTH (2u)
#define OI_TERM_MOON  (4u)
/* Sunlight scattered by the atmosphere towards the target (docs/skylight.md):
 * opt-in, not in OI_TERM_ALL or the defaults (removed by OI_NO_SKYLIGHT). */
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
    int no_atmosphere;        /* nonzero: as if the Earth had no atmosphere */
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

/* Highest top of a caller's atmosphere table (km): oi_illuminate's test
 * for certain full sunlight assumes that no grazing ray climbs above
 * twice this height. */
#define OI_ATM_TOP_MAX_KM (100.0)
/* Largest |psi| a caller's atmosphere table may encode (rad): the tilt of
 * the light's direction uses a series of tan exact to rounding below it. */
#define OI_ATM_PSI_MAX_RAD (0.05)

/* ---------------------------------------------------------------- geometry */

/* oi_lambert_phase: the Lambertian sphere's phase function (docs/physics.md)
 *   p(xi) = 2/(3 pi) ((pi - xi) cos xi + sin xi),  p(0) = 2/3, p(pi) = 0,
 * xi the phase angle (radians, [0, pi]; values outside are clamped; NaN
 * gives 0). Near xi = pi it uses a series in t = pi - xi (no cancellation):
 * relative error a few epsilon over [0, pi] (docs/shadow.md).
 * A sphere of radius a, albedo alpha under irradiance E sends
 *   F = E alpha a^2 p(xi) / d^2  to a viewer at distance d. */
oi_real oi_lambert_phase(oi_real xi);

/* oi_angle: the angle between two vectors (any common unit; may be the same
 * array), atan2(|a x b|, a . b) of the vectors scaled to unit length:
 * [0, pi] (radians), absolute error a few epsilon, accurate near 0 and pi
 * too. Returns 0 if either pointer is NULL or either vector is zero or has
 * a non-finite component. */
oi_real oi_angle(const oi_real a[3], const oi_real b[3]);

/* oi_cap_overlap: area (steradians) of the intersection of two spherical
 * caps of angular radii r1, r2 (radians, [0, pi]) whose centres are d apart
 * (radians, [0, pi]); inputs outside are clamped, a NaN gives 0. Exact on the
 * sphere (not the planar two-circle approximation), in forms without
 * cancellation for small caps: disjoint caps give exactly 0, nested ones
 * exactly the smaller cap's area 4 pi sin^2(r/2); otherwise the absolute
 * error is a few epsilon times the smaller cap's area (docs/shadow.md). */
oi_real oi_cap_overlap(oi_real r1, oi_real r2, oi_real d);

/* ---------------------------------------------------------------- sunlight */

/* oi_shadow.region */
#define OI_SHADOW_LIT      (0)
#define OI_SHADOW_PENUMBRA (1)
#define OI_SHADOW_UMBRA    (2)
#define OI_SHADOW_ANNULAR  (3)  /* Earth's disc inside the Sun's: beyond the umbra's tip */

typedef struct oi_shadow {
    oi_real fraction;        /* visible fraction of the uniform solar disc's area, [0, 1] */
    oi_real fraction_ld;     /* visible fraction of the limb-darkened disc's flux, [0, 1] */
    oi_real fraction_atm;    /* fraction of unobstructed sunlight reaching the point,
                                refraction and extinction included (equals the model's
                                choice of fraction/fraction_ld without the atmosphere) */
    oi_real sun_radius_rad;  /* apparent solar radius seen from the point */
    oi_real earth_radius_rad;/* apparent Earth radius seen from the point */
    oi_real separation_rad;  /* angle between the Sun's and the Earth's centres */
    oi_real sun_distance_km; /* point to Sun centre */
    int region;              /* OI_SHADOW_* */
} oi_shadow;

/*
 * Visible fraction of the Sun seen from a point (conical shadow, exact
 * spherical-cap overlap).
 * Given:   sun_km   Sun position (km, Earth-centred)
 *          point_km point position (km, Earth-centred), above the surface
 *          model    NULL or model constants (atm_table: see oi_model)
 * Returned: out    fractions and geometry
 * Returns: OI_OK; OI_WARN_TABLE_RANGE (the point is within the atmosphere's
 *          reach but beyond the z range of the table used: fraction_atm is
 *          the geometric one; with no atmosphere table at all, the model's
 *          atm_table NULL and oi_atm_table_default() NULL, fraction_atm is
 *          the geometric fraction and the status OI_OK);
 *          errors, in the order checked (every field of *out zeroed):
 *          OI_ERR_NULL       sun_km, point_km or out is NULL
 *          OI_ERR_MODEL, OI_ERR_RADIUS  the model is invalid (see oi_model)
 *          OI_ERR_NONFINITE  a NaN or infinite component
 *          OI_ERR_ZERO_VECTOR  sun_km or point_km is the zero vector
 *          OI_ERR_GEOMETRY   with earth_shape OI_EARTH_WGS84, |point| beyond
 *                            OI_POSITION_MAX_KM (the sphere takes any finite point)
 *          OI_ERR_BELOW_SURFACE  |point| <= earth_radius_km
 *          OI_ERR_GEOMETRY   |sun| <= sun_radius_km + earth_radius_km
 *          OI_ERR_NONFINITE  sun - point overflows
 *          OI_ERR_GEOMETRY   the point inside or on the Sun
 *                            (|sun - point| <= sun_radius_km)
 * Accuracy: fraction and fraction_ld within 8e-14 absolute in double, 3e-5
 *          in single (1 m altitude to 1e7 km, docs/shadow.md).
 * Regions: LIT (discs apart, or the Earth behind the Sun: fraction 1 exactly),
 *          UMBRA (the Earth's disc covers the Sun's: 0 exactly), ANNULAR,
 *          else PENUMBRA. Limb darkening: Neckel & Labs (1994) at 559.95 nm;
 *          fraction_ld = fraction for a Sun wider than 0.5 rad, and always
 *          with OI_NO_LIMB_DARKENING.
 */
int oi_sun_fraction(const oi_real sun_km[3], const oi_real point_km[3],
                    const oi_model *model, oi_shadow *out);

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

/* ---------------------------------------------------------------- sky */
#ifndef OI_NO_SKY
/*
 * oi_zodiacal_radiance: radiance of the zodiacal light seen from the Earth
 * (W/m^2/sr, as sunlight over the whole spectrum, the convention of
 * oi_expose_in.background_w_m2_sr) in the direction at ecliptic longitude
 * dlambda_rad from the Sun's and ecliptic latitude beta_rad.
 * Given:   dlambda_rad  any finite value (taken modulo 2 pi; the sign does
 *                       not matter); beta_rad: the sign does not matter,
 *                       |beta| above pi/2 is taken as pi/2
 * Returns: the radiance; 0 for a non-finite argument.
 * Notes:   Leinert et al. 1998 (A&AS 127, 1), Table 17 at 500 nm, bilinear
 *          between its nodes, converted to a whole-spectrum radiance with
 *          the 5772 K solar spectrum (7.6353e-9 W/m^2/sr per table unit).
 *          The table has no entries within ~15 deg of the Sun: those cells
 *          hold the nearest tabulated value of their latitude (a lower
 *          bound). src/camera/zodiacal.c, docs/camera.md.
 */
oi_real oi_zodiacal_radiance(oi_real dlambda_rad, oi_real beta_rad);

/*
 * oi_starlight_radiance: radiance of the integrated starlight (W/m^2/sr, as
 * sunlight over the whole spectrum, as oi_zodiacal_radiance) in the
 * direction at galactic longitude l_rad and latitude b_rad.
 * Given:   l_rad  any finite value (taken modulo 2 pi); b_rad: |b| above
 *                 pi/2 is taken as pi/2
 * Returns: the radiance; 0 for a non-finite argument.
 * Notes:   Leinert et al. 1998 (A&AS 127, 1), Table 35: the Pioneer 10 map at
 *          440 nm (Toller 1981) of the stars fainter than V ~ 6.5 and the
 *          diffuse galactic light, in S10_sun on a 10 deg x 4-10 deg grid,
 *          bilinear between its nodes; 8.9971e-9 W/m^2/sr per S10_sun (a
 *          V = 10 Sun per square degree). Beyond |b| = 80 deg, linear to the
 *          mean of the 80 deg row at the pole; 28 cells Pioneer did not map
 *          hold the interpolation of their row. src/camera/starlight.c,
 *          docs/camera.md.
 */
oi_real oi_starlight_radiance(oi_real l_rad, oi_real b_rad);

/*
 * oi_galactic_from_icrs: galactic longitude and latitude of a direction
 * given in ICRS (ICRF/GCRS-aligned) components, the frame of oi_scene.
 * Given:   dir    the direction, any finite nonzero length
 * Returns: OI_OK; OI_ERR_NULL (a NULL pointer), OI_ERR_NONFINITE (a
 *          component NaN/inf), OI_ERR_ZERO_VECTOR (dir is 0): then the
 *          outputs are 0.
 * Outputs: *l_rad in [0, 2 pi), *b_rad in [-pi/2, pi/2].
 * Notes:   the rotation of the Hipparcos catalogue (ESA SP-1200, 1997,
 *          Vol. 1, Sect. 1.5.3): north galactic pole at RA 192.85948 deg,
 *          Dec 27.12825 deg, ascending node at l = 32.93192 deg.
 *          src/camera/galactic.c.
 */
int oi_galactic_from_icrs(const oi_real dir[3], oi_real *l_rad, oi_real *b_rad);
#endif

/* ---------------------------------------------------------------- shapes */
#ifndef OI_NO_FACETS
/*
 * Targets with shape (docs/shapes.md): a set of flat facets in the target's
 * body frame, turned into the positions' frame by the scene's attitude
 * quaternion. Each facet reflects with a Lambertian part and a specular
 * part, the normalised modified Phong lobe (Lafortune & Willems 1994,
 * "Using the modified Phong reflectance model for physically based
 * rendering", KU Leuven report CW 197), the BRDF
 *   f = albedo_diffuse / pi + albedo_specular (n + 2) / (2 pi) cos^n(alpha),
 * alpha the angle between the mirror image of the source's direction and
 * the observer's, n = shininess, cos(alpha) clamped at 0. Reciprocal; its
 * directional albedo never exceeds albedo_diffuse + albedo_specular (<= 1),
 * equal at normal incidence.
 * A facet lit from behind, or seen from behind, sends nothing (two-sided:
 * each face reflects alike; light on one face never leaves by the other).
 * Not modelled: mutual shadowing and mutual reflection between facets (a
 * facet is lit and seen as if it were alone), the facets' extent (every
 * facet is at the target's position), the Sun's and the Moon's discs in the
 * specular lobe (point sources).
 */
#define OI_FACETS_MAX (32)          /* facets per shape: bounds the loops */
#define OI_SHININESS_MAX (1.0e4)    /* largest accepted shininess */

typedef struct oi_facet {
    oi_real normal[3];       /* outward normal in the body frame; nonzero, finite
                                (scaled to unit length here; one of subnormal
                                length is first scaled by its largest component,
                                so that it normalises as the same direction of
                                unit length, to rounding) */
    oi_real area_m2;         /* (0, 1e8] m^2 */
    int two_sided;           /* nonzero: both faces reflect alike */
    oi_real albedo_diffuse;  /* Lambertian albedo, [0, 1] */
    oi_real albedo_specular; /* specular reflectance of the Phong lobe, [0, 1];
                                albedo_diffuse + albedo_specular <= 1 */
    oi_real shininess;       /* the lobe's exponent n, [0, OI_SHININESS_MAX]: its
                                half-width at half maximum is about
                                sqrt(2 ln 2 / n) rad for large n */
} oi_facet;

typedef struct oi_shape {
    const oi_facet *facets;  /* caller-owned array of n_facets facets */
    unsigned n_facets;       /* 1..OI_FACETS_MAX */
    int diffuse_from_scene;  /* nonzero: every facet's albedo_diffuse is replaced
                                by the scene's target_albedo (the built-in "plate") */
    const char *name;        /* not used by the computation (may be NULL) */
} oi_shape;

/* oi_shape_check: OI_OK for a shape every call accepts; OI_ERR_NULL (shape
 * or its facets NULL); OI_ERR_SHAPE: n_facets 0 or above OI_FACETS_MAX, or
 * a facet with a zero or non-finite normal, area outside (0, 1e8], an
 * albedo outside [0, 1] (NaN too), albedos summing above 1, shininess
 * outside [0, OI_SHININESS_MAX]. With diffuse_from_scene the diffuse
 * albedos are not checked here (oi_illuminate checks target_albedo plus
 * each specular albedo). */
int oi_shape_check(const oi_shape *shape);

/* oi_shape_builtin: built-in shape number index (0 "plate", 1 "box-wing",
 * 2 "cylinder"); NULL for a negative index or past the last. Static storage;
 * dimensions and reflectances with their sources in src/target/shape_builtin.c and
 * docs/shapes.md. The sphere is no shape: scene.shape NULL.
 *   plate     one one-sided Lambertian facet of 1 m^2, normal +z, diffuse
 *             albedo target_albedo (diffuse_from_scene), no specular part
 *   box-wing  a bus and two solar arrays (see docs/shapes.md)
 *   cylinder  a rocket body as a 12-sided prism with its two end caps */
const oi_shape *oi_shape_builtin(int index);
/* oi_shape_find: built-in shape by name (exact, case-sensitive); NULL for
 * NULL, "sphere" and unknown names (a sphere is scene.shape NULL). */
const oi_shape *oi_shape_find(const char *name);

/* oi_facet_brdf: the BRDF (1/sr) of a facet (body frame, as given: its
 * normal need not be unit) for light arriving from the unit-or-not
 * direction to_source and leaving towards to_observer (both from the facet,
 * body frame); 0 when either is behind the face that reflects (for a
 * two-sided facet, the face on the source's side), or for NULL, zero or
 * non-finite input. diffuse_from_scene does not apply here. */
oi_real oi_facet_brdf(const oi_facet *facet, const oi_real to_source[3],
                      const oi_real to_observer[3]);

/*
 * oi_earthshine_plate: the earthshine irradiance on one face of a flat
 * plate, per unit Earth albedo and unit solar irradiance at the Earth: E
 * such that the plate receives earth_albedo TSI (1 AU / |sun|)^2 E (W/m^2).
 * Given:   theta, h_km, model  as oi_earthshine (earth_reflection chooses
 *                 the cubature or the mean direction)
 *          normal the face's outward normal in the local frame (as
 *                 oi_earthshine_sphere's obs: z the zenith, x towards the
 *                 Sun's side); any length > 0
 * Returned: irradiance  E (>= 0)
 * Returns: oi_earthshine's statuses; OI_ERR_NULL (normal or irradiance
 *          NULL), OI_ERR_NONFINITE (a component of normal), OI_ERR_ZERO_VECTOR
 *          (normal zero). On error *irradiance is 0.
 * Notes:   Default: a fixed cubature over the visible sunlit cap clipped by
 *          the plate's horizon, exact in azimuth (closed form) and
 *          Gauss-Legendre in the polar angle between the region's
 *          break points (docs/shapes.md, with its measured error against
 *          an independent quadrature). It does not use the tables: a
 *          Lambertian Earth of uniform albedo without atmosphere (the
 *          earthshine table's model), any altitude. With
 *          OI_EARTH_REFLECT_MEAN or the Lambert far field (earth_model
 *          OI_EARTH_LAMBERT): phi max(0, normal . d), d the mean direction
 *          psi (exact in the far field).
 */
int oi_earthshine_plate(oi_real theta, oi_real h_km, const oi_real normal[3],
                        const oi_model *model, oi_real *irradiance);
#endif /* OI_NO_FACETS */

/* ---------------------------------------------------------------- scene */

typedef struct oi_scene {
    oi_real sun_km[3];       /* Sun position (km) */
    oi_real moon_km[3];      /* Moon position (km); used when OI_TERM_MOON or has_moon
                                is set */
    oi_real target_km[3];    /* target position (km) */
    oi_real observer_km[3];  /* observer position (km); used when has_observer */
    int has_observer;        /* nonzero: compute what the observer receives */
    unsigned terms;          /* OI_TERM_* mask */
    oi_real earth_albedo;    /* [0, 1] */
    oi_real target_albedo;   /* [0, 1] */
    oi_real target_radius_m; /* > 0 */
    int has_moon;            /* nonzero: moon_km is given, whatever the terms: the
                                Moon then occults the Sun (OI_TERM_MOON implies it) */
    oi_real target_vel_km_s[3];   /* target velocity (km/s, the positions' frame); read by
                                     oi_expose_scene only; zero: at rest */
    oi_real observer_vel_km_s[3]; /* observer velocity (km/s), as target_vel_km_s */
    /* The target's shape (oi_shape, docs/shapes.md). The fields stay in a
     * build with OI_NO_FACETS (the struct's layout does not change), where a
     * non-NULL shape gives OI_ERR_SHAPE. */
    const struct oi_shape *shape; /* NULL: the Lambertian sphere of target_radius_m and
                                     target_albedo; else its facets (caller-owned) */
    oi_real attitude_q[4];   /* body frame -> positions' frame, unit quaternion
                                (w, x, y, z), read with a shape only; all four zero:
                                the identity; a norm off 1 by more than 1e-6 (a
                                nonzero quaternion whose squared norm underflows,
                                (1e-300, 0, 0, 0), included), a component above 2
                                or a non-finite one: OI_ERR_SHAPE; else normalised */
    oi_real epoch_jd;        /* Julian date (UTC) of the scene, in [OI_EPOCH_JD_MIN,
                                OI_EPOCH_JD_MAX]; read only by the albedo model
                                OI_ALBEDO_KNOCKE (with OI_TERM_EARTH) */
    oi_real earth_rotation_rad; /* angle of the Greenwich meridian from the frame's x axis
                                   about its z axis (rad, |value| <= OI_EARTH_ROTATION_MAX_RAD);
                                   read only by OI_ALBEDO_MAP (with OI_TERM_EARTH) */
} oi_scene;

/* oi_scene_defaults: fill a scene with the defaults: zero positions, no
 * observer, no shape (the sphere), attitude_q zero (the identity), every
 * term compiled in, albedos OI_EARTH_ALBEDO_DEFAULT /
 * OI_TARGET_ALBEDO_DEFAULT, radius OI_TARGET_RADIUS_M_DEFAULT. A NULL scene
 * is ignored. */
void oi_scene_defaults(oi_scene *scene);

typedef struct oi_illum {
    oi_shadow shadow;        /* the Sun seen from the target */
    oi_real e_sun;           /* scalar irradiance at the target per source (W/m^2) */
    oi_real e_earth;
    oi_real e_moon;
    oi_real dir_sun[3];      /* unit vectors from the target towards where each */
    oi_real dir_earth[3];    /*   source's light comes from (Earth: mean incidence */
    oi_real dir_moon[3];     /*   direction); zero when the term is off */
    oi_real earth_theta;     /* angle at Earth centre, Sun to target (rad) */
    oi_real earth_h_km;      /* target altitude (km) */
    oi_real earth_phi;       /* normalised earthshine phi(theta, h) */
    oi_real earth_psi;       /* its mean direction angle (see oi_earthshine) */
    oi_real moon_sun_fraction; /* fraction of sunlight reaching the Moon */
    /* what the observer receives (zero without observer) */
    oi_real phase_sun;       /* phase angle at the target, per source (rad) */
    oi_real phase_earth;
    oi_real phase_moon;
    oi_real flux_sun;        /* W/m^2 at the observer from the target, per source */
    oi_real flux_earth;
    oi_real flux_moon;
    oi_real flux_obs;        /* their sum */
    oi_real mag_v;           /* apparent V magnitude of the target (OI_MAG_DARK if dark) */
    oi_real range_km;        /* observer to target */
    oi_real sun_moon_hidden; /* fraction of the Sun's disc area the Moon's disc covers
                                seen from the target (0: no Moon position, or apart) */
    oi_real moon_disc_visible; /* fraction of the Moon's disc the Earth does not hide,
                                  seen from the target, the atmosphere's extinction
                                  along the grazing lines of sight included unless
                                  no_atmosphere (with OI_TERM_MOON; else 0) */
    oi_real flux_specular;   /* part of flux_obs from the facets' specular lobes (W/m^2;
                                0 for a sphere) */
    oi_real earth_albedo_eff;  /* the albedo e_earth is formed with: earth_albedo
                                  (OI_ALBEDO_UNIFORM), else the mean of the model's
                                  albedo over the lit visible Earth weighted by its
                                  earthshine, the value under the target where none
                                  is lit (with OI_TERM_EARTH; else 0) */
    /* scattered sunlight (OI_TERM_SKY; zero when the term is off) */
    oi_real e_sky;           /* scalar irradiance at the target (W/m^2) */
    oi_real dir_sky[3];      /* unit vector towards its mean direction */
    oi_real phase_sky;       /* phase angle at the target (rad; with an observer) */
    oi_real flux_sky;        /* W/m^2 at the observer (in flux_obs) */
} oi_illum;

/*
 * oi_illuminate: light on the target from Sun, Earth and Moon, and what the
 * observer sees.
 * Given:   scene  positions (km), terms, albedos, target radius; moon_km is
 *                 read only with OI_TERM_MOON or has_moon, observer_km only
 *                 with has_observer
 *          model  NULL or model constants and options
 * Returned: out   see oi_illum (zeroed on error)
 * Returns: OI_OK; OI_WARN_TABLE_RANGE (earthshine outside its table's range,
 *          or the target beyond the atmosphere table: see oi_earthshine and
 *          oi_sun_fraction); errors (the first found; the scene's own
 *          checks come before the geometry's):
 *          OI_ERR_NULL       scene or out is NULL
 *          OI_ERR_MODEL, OI_ERR_RADIUS  the model is invalid (see oi_model)
 *          OI_ERR_TERMS      terms has bits outside OI_TERM_ALL (or
 *                            OI_TERM_MOON in a build with OI_NO_MOON)
 *          OI_ERR_NONFINITE  a component of a position read, an albedo or
 *                            target_radius_m NaN or infinite
 *          OI_ERR_ALBEDO     earth_albedo or target_albedo outside [0, 1]
 *          OI_ERR_RADIUS     target_radius_m <= 0
 *          OI_ERR_ZERO_VECTOR  a position read is the zero vector
 *          OI_ERR_GEOMETRY   a position read farther than OI_POSITION_MAX_KM
 *          OI_ERR_BELOW_SURFACE  |target| or |observer| <= earth_radius_km
 *          OI_ERR_SHAPE      scene->shape fails oi_shape_check (its
 *                            OI_ERR_NULL for NULL facets included), the
 *                            scene's target_albedo plus a facet's
 *                            albedo_specular above 1 (diffuse_from_scene),
 *                            or a bad attitude_q (see oi_scene); any shape
 *                            in a build with OI_NO_FACETS
 *          OI_ERR_NONFINITE  with OI_TERM_EARTH: epoch_jd (OI_ALBEDO_KNOCKE)
 *                            or earth_rotation_rad (OI_ALBEDO_MAP) NaN or
 *                            infinite
 *          OI_ERR_INPUT      with OI_TERM_EARTH: epoch_jd outside
 *                            [OI_EPOCH_JD_MIN, OI_EPOCH_JD_MAX] (knocke),
 *                            |earth_rotation_rad| > OI_EARTH_ROTATION_MAX_RAD
 *                            (map)
 *          then the Sun seen from the target (oi_sun_fraction's statuses:
 *          OI_ERR_GEOMETRY for a Sun touching the Earth or the target inside
 *          the Sun), the Sun seen from the Moon (the same; the Moon below the
 *          Earth's surface gives OI_ERR_BELOW_SURFACE), and:
 *          OI_ERR_GEOMETRY   the target inside the Moon
 *                            (|target - moon| <= moon_radius_km; with the
 *                            Moon's position given, OI_TERM_MOON or has_moon)
 *          OI_ERR_BELOW_SURFACE  the Moon at or below the Earth's surface
 *                            (its position given)
 *          OI_ERR_OBSERVER_AT_TARGET  the observer inside the target's sphere
 *                            (range <= target_radius_m), or with a shape
 *                            range^2 <= the sum of its facets' areas
 *          OI_ERR_ALBEDO     OI_ALBEDO_MAP: a map value the call reads is NaN
 *                            or outside [0, 1]
 * Notes:   e_sun = TSI (AU / |sun - target|)^2 fraction_atm;
 *          e_earth = earth_albedo TSI (AU / |sun|)^2 phi(theta, h);
 *          e_sky = TSI (AU / |sun|)^2 (E_sky / E_sun)(theta, h) (OI_TERM_SKY,
 *          oi_skylight), reflected as if from its mean direction dir_sky;
 *          e_moon from the lunar phase law (or a Lambert Moon), times the
 *          fraction of the Sun the Moon sees and the fraction of the Moon's
 *          disc the Earth does not hide from the target (moon_disc_visible).
 *          With the Moon's position given (OI_TERM_MOON or has_moon, whatever
 *          the terms) the Moon occults the Sun: shadow.fraction, fraction_ld,
 *          fraction_atm and e_sun count it (shadow.region stays the Earth's;
 *          sun_moon_hidden; docs/shadow.md section 9). The target is a Lambertian
 *          sphere; the flux at the observer is the sum over sources of
 *          e albedo (a / range)^2 p(phase), the Earth's with its angular
 *          distribution instead (model earth_reflection,
 *          oi_earthshine_sphere: e_earth albedo (a / range)^2 S, S = F / phi);
 *          phase_earth stays the angle from the mean direction.
 *          With a shape (scene->shape, docs/shapes.md) the sphere is
 *          replaced by the facets, turned by attitude_q: each facet's flux
 *          from a point source (Sun, Moon) is e cos(i) f cos(o) A / range^2
 *          (f oi_facet_brdf, i and o the angles of source and observer from
 *          its normal); from the Earth the diffuse part uses the facet's
 *          earthshine irradiance (oi_earthshine_plate, the Earth's angular
 *          distribution), the specular part that irradiance as if it came
 *          from the mean direction dir_earth. flux_sun, flux_earth and
 *          flux_moon are the facets' sums per source, flux_specular their
 *          specular part; target_radius_m is then used for the
 *          observer-at-target check only. src/scene/illuminate.c, src/target/facet.c.
 *          Albedo models (model albedo_model; docs/earthshine-albedo.md):
 *          with OI_ALBEDO_KNOCKE or OI_ALBEDO_MAP, e_earth = A TSI (AU /
 *          |sun|)^2 phi, A = earth_albedo_eff the earthshine-weighted mean
 *          albedo over the lit visible Earth, and dir_earth and the sphere's
 *          angular distribution (flux_earth) carry the field's first-order
 *          change, all from a fixed cubature used as a control variate on the
 *          uniform tables (earth_phi, earth_psi stay the uniform sphere's).
 *          src/scene/illuminate.c, src/sources/earthshine_albedo.c.
 */
int oi_illuminate(const oi_scene *scene, const oi_model *model, oi_illum *out);

/* oi_magnitude_v: apparent V magnitude of a flux at the observer (W/m^2):
 * m = OI_SUN_MAG_V - 2.5 log10(F / TSI), TSI the model's (an invalid model
 * means the defaults). Returns OI_MAG_DARK for F <= 0, non-finite F, or
 * magnitudes fainter than OI_MAG_DARK. Relative error a few epsilon. */
oi_real oi_magnitude_v(oi_real flux_w_m2, const oi_model *model);

/* oi_flux_from_magnitude: the inverse of oi_magnitude_v,
 * *flux_w_m2 = TSI 10^(-0.4 (mag_v - OI_SUN_MAG_V)) (W/m^2).
 * Returns: OI_OK; OI_ERR_NULL (flux_w_m2 NULL); OI_ERR_MODEL, OI_ERR_RADIUS
 * (invalid model); OI_ERR_MAGNITUDE (mag_v non-finite or outside
 * [OI_MAG_MIN, OI_MAG_MAX]). On error *flux_w_m2 is 0. */
int oi_flux_from_magnitude(oi_real mag_v, const oi_model *model, oi_real *flux_w_m2);

/* ---------------------------------------------------------------- camera */
#ifndef OI_NO_EXPOSURE

#define OI_CAMERA_MAX_TIMES (16)
#define OI_CAMERA_MAX_GAINS (8)

typedef struct oi_camera {
    const char *name;
    oi_real aperture_m;         /* entrance pupil diameter (m) */
    oi_real focal_length_m;     /* (m) */
    oi_real pixel_pitch_m;      /* (m) */
    oi_real transmission;       /* optics transmission, (0, 1] */
    oi_real quantum_efficiency; /* band-mean QE, (0, 1] */
    oi_real band_fraction;      /* fraction of solar irradiance in the band, (0, 1] */
    oi_real photon_energy_j;    /* mean photon energy in the band (J) */
    oi_real full_well_e;        /* (electrons) */
    oi_real dark_current_e_s;   /* (electrons/s/pixel) */
    oi_real psf_peak_fraction;  /* fraction of a point source in the brightest pixel, (0, 1] */
    oi_real fov_rad;            /* full field of view, diagonal (rad) */
    oi_real sun_exclusion_rad;  /* Sun exclusion half-angle from the boresight (rad) */
    int n_times;                /* number of exposure times, 1..OI_CAMERA_MAX_TIMES */
    oi_real times_s[OI_CAMERA_MAX_TIMES];  /* ascending (s) */
    int n_gains;                /* number of gains, 1..OI_CAMERA_MAX_GAINS */
    oi_real gains[OI_CAMERA_MAX_GAINS];    /* ascending; saturation = full_well / gain */
    oi_real read_noise_e[OI_CAMERA_MAX_GAINS]; /* input-referred read noise per gain (e-) */
    oi_real max_trail_px;       /* longest acceptable trail (pixels), [0, 1e6]; 0: no limit */
    oi_real detect_false_alarm; /* detection rule: per-pixel false-alarm probability of its
                                   threshold, [1e-15, 0.5); 0: the SNR rule (goal.snr_min) */
    oi_real detect_probability; /* detection probability required, [0.5, 0.999999]; 0: 0.5 */
    /* Sensor temperature (docs/camera.md, "Sensor temperature"): the dark current is
     * dark_current_e_s * 2^((T - dark_ref_temp_c) / dark_doubling_c) at a sensor
     * temperature T given in oi_expose_goal (has_sensor_temp); all four 0: no
     * temperature model (dark_current_e_s at any temperature, none may be given). */
    oi_real dark_ref_temp_c;    /* temperature of dark_current_e_s (deg C), [-150, 150] */
    oi_real dark_doubling_c;    /* rise that doubles the dark current (deg C), [1, 100] */
    oi_real temp_min_c;         /* rated sensor temperature range (deg C), [-150, 150], */
    oi_real temp_max_c;         /* min <= max, within 30 doublings of dark_ref_temp_c */
} oi_camera;

/* oi_camera_builtin: built-in camera number index (0 is the default,
 * "star-tracker"); NULL for a negative index or past the last. Read-only,
 * static storage; sources of every value in src/camera/camera_builtin.c and
 * docs/camera.md. */
const oi_camera *oi_camera_builtin(int index);
/* oi_camera_find: built-in camera by name (exact, case-sensitive); NULL when
 * name is NULL or no camera has it. */
const oi_camera *oi_camera_find(const char *name);

/* Exposure flags (bit mask) */
#define OI_FLAG_SUN_EXCLUSION (1u)   /* Sun inside the exclusion angle */
#define OI_FLAG_EARTH_IN_FOV  (2u)   /* Earth in the field of view (bright background) */
#define OI_FLAG_ECLIPSED      (4u)   /* target in the umbra */
#define OI_FLAG_TOO_FAINT     (8u)   /* not detected at the longest exposure, highest gain */
#define OI_FLAG_SATURATED     (16u)  /* the target fills the well even at the lowest fill */
#define OI_FLAG_PENUMBRA      (32u)  /* target in the penumbra */
#define OI_FLAG_OCCULTED      (64u)  /* the Earth hides the target from the observer */
#define OI_FLAG_RESOLVED      (128u) /* target wider than a pixel: peak limited by its radiance */
#define OI_FLAG_MOON_SHADOW   (256u) /* the Moon hides part of the Sun from the target */
#define OI_FLAG_MOON_IN_FOV   (512u) /* the Moon's disc in the field (oi_expose_goal.sky OI_SKY_MOON) */
#define OI_FLAG_TRAILED       (1024u) /* even the chosen exposure trails beyond max_trail_px */
#define OI_FLAG_GLINT         (2048u) /* a shape's specular part is more than half of flux_obs */
#define OI_FLAG_BACKGROUND_SATURATED (4096u) /* the background, not the target, fills the
                                                well even at the lowest fill */

/*
 * Flags with one meaning each. The geometric bits say where things are; the
 * exposure's bits (TOO_FAINT, SATURATED, BACKGROUND_SATURATED, TRAILED) what
 * the camera makes of the light, at these definitions, whatever else is set:
 *   TOO_FAINT   the target is not detected (the goal's SNR, or the camera's
 *               detection rule, oi_expose Note 8) at the most sensitive
 *               setting, the longest time (moving: any allowed time) at the
 *               highest gain, the well not counted; always without signal
 *               (flux 0: OCCULTED, an unlit target).
 *   SATURATED   the well is full at the chosen setting (fill >= 1: no setting
 *               reaches the goal, the lowest fill chosen) and the target's
 *               light is what fills it: the background alone does not
 *               (background_e < saturation_e) and the target is not TOO_FAINT.
 *   BACKGROUND_SATURATED  the well is full at the chosen setting and the
 *               target is not what fills it: the background alone (sky,
 *               the sunlit Earth in the field, dark current) fills the well
 *               (background_e >= saturation_e), or the target is TOO_FAINT.
 *               No setting can show the target: point elsewhere.
 * Exclusions (never together in one result): SATURATED and TOO_FAINT;
 * SATURATED and BACKGROUND_SATURATED; SATURATED and OCCULTED (the occulted
 * target's flux is 0: TOO_FAINT, and a full well is the background's);
 * ECLIPSED and PENUMBRA (one shadow region). OCCULTED implies TOO_FAINT.
 * With the setting formed, fill >= 1 gives exactly one of SATURATED and
 * BACKGROUND_SATURATED, fill < 1 neither. The Earth in the field (EARTH_IN_FOV) sets no exposure bit by
 * itself: its radiance is the background (oi_expose_scene Note 3), and
 * BACKGROUND_SATURATED when it fills the well. ECLIPSED (no direct
 * sunlight) does not mean dark: earthshine and moonlight may still be
 * detected, or even saturate. Before BACKGROUND_SATURATED existed,
 * SATURATED was raised for any full well (with TOO_FAINT too, or for the
 * background's): such results are now SATURATED or BACKGROUND_SATURATED.
 */

/* oi_flag_name: name of one flag bit ("sun_exclusion", "earth_in_fov",
 * "eclipsed", "too_faint", "saturated", "penumbra", "occulted", "resolved",
 * "moon_shadow", "moon_in_fov", "trailed", "glint", "background_saturated");
 * NULL for 0, several bits or an unknown bit. */
const char *oi_flag_name(unsigned flag_bit);

/* Sky backgrounds oi_expose_scene adds behind the target (oi_expose_goal.sky,
 * a bit mask; 0: the dark sky, with the sunlit Earth only, of earlier
 * versions). docs/camera.md, "Sky background". */
#ifndef OI_NO_SKY
#define OI_SKY_ZODIACAL (1u)  /* zodiacal light (Leinert et al. 1998), where the ray misses Earth and Moon */
#define OI_SKY_STARLIGHT (4u) /* integrated starlight (Leinert et al. 1998, Pioneer 10), same places */
#endif
#ifndef OI_NO_MOON
#define OI_SKY_MOON     (2u)  /* the Moon: OI_FLAG_MOON_IN_FOV, its surface behind the target, occultation */
#endif

/* Goals of the exposure choice. Zero fields mean defaults. */
typedef struct oi_expose_goal {
    oi_real fill;            /* brightest-pixel fill as a fraction of saturation (0.5) */
    oi_real snr_min;         /* SNR below which TOO_FAINT is raised (5) */
    unsigned sky;            /* OI_SKY_* backgrounds oi_expose_scene adds (0: none) */
    unsigned has_sensor_temp; /* nonzero: sensor_temp_c is given; 0: the camera's
                                 dark_current_e_s as it stands */
    oi_real sensor_temp_c;   /* sensor temperature (deg C), within the camera's rated
                                range (camera temp_min_c .. temp_max_c) */
} oi_expose_goal;

/* Photometric input of the exposure choice. */
typedef struct oi_expose_in {
    oi_real flux_w_m2;           /* target flux at the aperture (W/m^2) */
    oi_real background_w_m2_sr;  /* sky radiance behind the target (W/m^2/sr) */
    unsigned flags;              /* geometric flags already known (OI_FLAG_*) */
    oi_real rate_rad_s;          /* target's angular rate across the field (rad/s, [0, 1e3]);
                                    0: at rest */
} oi_expose_in;

typedef struct oi_exposure {
    oi_real exposure_s;      /* chosen exposure time (s) */
    oi_real gain;            /* chosen gain */
    int time_index;          /* index into camera times_s */
    int gain_index;          /* index into camera gains */
    oi_real signal_e;        /* target electrons in the brightest pixel */
    oi_real background_e;    /* background + dark electrons in that pixel */
    oi_real peak_e;          /* signal_e + background_e */
    oi_real saturation_e;    /* full_well / gain */
    oi_real fill;            /* peak_e / saturation_e */
    oi_real snr;             /* signal / noise of the brightest pixel */
    oi_real sun_angle_rad;   /* Sun to boresight (oi_expose_scene only) */
    unsigned flags;          /* OI_FLAG_* */
    oi_real background_w_m2_sr; /* radiance behind the target used (W/m^2/sr) */
    oi_real rate_rad_s;      /* target's angular rate across the field (rad/s) */
    oi_real trail_px;        /* trail length during the chosen exposure (pixels) */
    oi_real trail_factor;    /* peak pixel's signal over that at rest, (0, 1] */
    oi_real signal_min_e;    /* smallest signal_e the detection rule accepts at this setting */
    oi_real detect_margin_mag; /* 2.5 log10(signal_e / signal_min_e): > 0 detectable;
                                  OI_DETECT_MARGIN_NONE without signal */
} oi_exposure;

/* detect_margin_mag of a setting without any target signal. */
#define OI_DETECT_MARGIN_NONE (-100.0)

/*
 * oi_expose: choose the exposure time and gain for a point-like target.
 *
 * Given:
 *   camera  the camera (valid ranges: Note 4)
 *   in      flux_w_m2: target flux at the aperture (W/m^2, [0, 2.74e4]:
 *           magnitude OI_MAG_MIN at the nominal TSI); background_w_m2_sr: sky
 *           radiance behind the target (W/m^2/sr, [0, 1e8]); flags: geometric
 *           OI_FLAG_* bits already known (copied to the result)
 *   goal    NULL or goals; zero fields mean defaults (fill 0.5, in (0, 1];
 *           snr_min 5, in (0, 1e6])
 * Returned:
 *   out     the chosen setting (exposure_s, gain, their indices), its
 *           electrons (signal_e, background_e, peak_e, saturation_e), fill,
 *           snr and flags; sun_angle_rad is 0 here
 * Returns (checked in this order; on error *out is zeroed):
 *   OI_OK
 *   OI_ERR_NULL       camera, in or out is NULL
 *   OI_ERR_CAMERA     a camera field outside Note 4's ranges, times or gains
 *                     not strictly ascending, n_times or n_gains out of range
 *   OI_ERR_INPUT      a goal field out of range (NaN included)
 *   OI_ERR_FLAGS      goal->sky has bits outside OI_SKY_* (oi_expose itself
 *                     has no geometry and adds no sky)
 *   OI_ERR_NONFINITE  flux or background NaN or infinite
 *   OI_ERR_INPUT      flux negative
 *   OI_ERR_MAGNITUDE  flux brighter than magnitude OI_MAG_MIN (> 2.74e4 W/m^2)
 *   OI_ERR_INPUT      background negative or above 1e8 W/m^2/sr
 *   OI_ERR_FLAGS      in->flags has bits outside the OI_FLAG_* set
 *   OI_ERR_NONFINITE  in->rate_rad_s NaN or infinite
 *   OI_ERR_INPUT      in->rate_rad_s outside [0, 1e3] rad/s
 *   OI_ERR_NONFINITE  goal->has_sensor_temp and goal->sensor_temp_c NaN or
 *                     infinite
 *   OI_ERR_INPUT      goal->has_sensor_temp and the camera has no temperature
 *                     model (dark_doubling_c 0) or sensor_temp_c is outside
 *                     its rated range [temp_min_c, temp_max_c]
 * Notes:
 *   1. Rates of photo-electrons (e-/s) in the brightest pixel, with
 *      A = pi (D/2)^2 and k = transmission * band_fraction * QE / photon_energy:
 *        target      S = flux * A * k * psf_peak_fraction
 *        background  B = radiance * A * (pitch / focal)^2 * k + dark_current.
 *      For exposure t and gain g: peak = (S + B) t, saturation = full_well / g,
 *      fill = peak / saturation, SNR = S t / sqrt(S t + B t + read_noise(g)^2).
 *   2. Choice: among the settings with fill < 1 and fill <= goal.fill, the
 *      highest SNR (ties: lower gain, then shorter time); if none reaches
 *      down to the goal, the shortest time at the lowest gain (the lowest
 *      fill), with OI_FLAG_SATURATED or OI_FLAG_BACKGROUND_SATURATED when
 *      even that saturates (see "Flags with one meaning each").
 *      OI_FLAG_TOO_FAINT when the target is not detectable (Note 8) at the
 *      longest time and highest gain: with the SNR rule, when the SNR
 *      there is below goal.snr_min.
 *   3. in->flags bits OI_FLAG_TOO_FAINT, OI_FLAG_SATURATED,
 *      OI_FLAG_BACKGROUND_SATURATED and OI_FLAG_TRAILED are ignored
 *      (recomputed); the geometric bits are copied to out->flags.
 *   4. Valid camera ranges: aperture (0, 10] m, focal length [1e-3, 1e3] m,
 *      pitch [1e-7, 1e-3] m, transmission, QE, band_fraction and
 *      psf_peak_fraction (0, 1], photon energy [1e-20, 1e-17] J, full well
 *      [1, 1e9] e-, dark current [0, 1e9] e-/s, fov (0, pi], Sun exclusion
 *      [0, pi], 1..OI_CAMERA_MAX_TIMES times in (0, 1e4] s strictly
 *      ascending, 1..OI_CAMERA_MAX_GAINS gains in (0, 1e3] strictly
 *      ascending, read noise [0, 1e6] e-, max_trail_px [0, 1e6],
 *      detect_false_alarm 0 or [1e-15, 0.5), detect_probability 0 or
 *      [0.5, 0.999999]; temperature model (Note 9): dark_doubling_c 0 with
 *      dark_ref_temp_c, temp_min_c and temp_max_c 0, or dark_doubling_c
 *      [1, 100], the three temperatures in [-150, 150] deg C, temp_min_c <=
 *      temp_max_c, both within 30 doublings of dark_ref_temp_c.
 *      name is not used (may be NULL).
 *      Every camera is checked, the built-in ones too.
 *   5. The target is treated as a point source: a resolved target puts less
 *      than psf_peak_fraction of its light in one pixel (oi_expose_scene
 *      bounds that, its Note 5).
 *   6. Exactness and cost: the choice is that of the full search over every
 *      (time, gain) pair, to the bit, made from O(log n_times + n_gains)
 *      evaluations (docs/camera.md, "Cost of the search"; src/camera/expose.c).
 *   7. Motion (in->rate_rad_s > 0; docs/camera.md, "Motion"): the trail of
 *      time t is L = rate t / (pitch / focal) pixels; the brightest pixel's
 *      signal is that at rest times trail_factor, the closed form for a
 *      Gaussian PSF of the camera's peak fraction swept along a pixel row.
 *      The times allowed are those with L <= max_trail_px (all when it is
 *      0), at least the shortest, with OI_FLAG_TRAILED when even that
 *      trails beyond it; every allowed (time, gain) pair is evaluated by
 *      Note 2's rule; OI_FLAG_TOO_FAINT when no allowed time is detectable
 *      at the highest gain. At rest: trail_px 0, trail_factor 1, the
 *      choice of earlier versions bit for bit.
 *   8. Detection (docs/camera.md, "Detection"): camera->detect_false_alarm
 *      0, the SNR rule: S / sqrt(S + B + R^2) >= goal.snr_min. Otherwise a
 *      per-pixel threshold T = k sqrt(B + R^2), k = Phi^-1(1 -
 *      detect_false_alarm), crossed with probability detect_probability
 *      (0: 0.5): S >= T + z sqrt(S + B + R^2), z = Phi^-1(probability)
 *      (electrons at the setting; Gaussian noise). signal_min_e is the
 *      smallest such S at the chosen setting, detect_margin_mag =
 *      2.5 log10(signal_e / signal_min_e) (within +-100;
 *      OI_DETECT_MARGIN_NONE without signal).
 *   9. Sensor temperature (docs/camera.md, "Sensor temperature"): with
 *      goal->has_sensor_temp the dark current is dark_current_e_s *
 *      2^((sensor_temp_c - dark_ref_temp_c) / dark_doubling_c); without it
 *      (0, a NULL goal) dark_current_e_s, as in earlier versions, bit for bit.
 */
int oi_expose(const oi_camera *camera, const oi_expose_in *in,
              const oi_expose_goal *goal, oi_exposure *out);

/*
 * oi_expose_scene: the exposure choice from a scene and its illumination.
 *
 * Given:
 *   camera  the camera (as oi_expose)
 *   scene   positions (km, Earth-centred); has_observer must be set;
 *           earth_albedo (the background) and target_albedo (Note 5)
 *   illum   oi_illuminate's result for this scene (e_sun, e_earth, e_moon,
 *           flux_obs and shadow.region are used)
 *   model   NULL or model (earth_radius_km, au_km, tsi_w_m2)
 *   goal    NULL or goals (as oi_expose); goal->sky: the sky backgrounds
 *           (Note 8; 0 or a NULL goal: none but the sunlit Earth)
 * Returned:
 *   out     as oi_expose, with sun_angle_rad (Note 1), the geometric flags
 *           and background_w_m2_sr, the radiance used behind the target
 * Returns (checked in this order; on error *out is zeroed):
 *   OI_OK
 *   OI_ERR_NULL       camera, scene, illum or out is NULL, or
 *                     scene->has_observer is 0 (the observer is required)
 *   OI_ERR_MODEL, OI_ERR_RADIUS  the model is invalid (as oi_illuminate)
 *   OI_ERR_NONFINITE  a component of sun_km, target_km or observer_km (or
 *                     moon_km, when goal->sky has OI_SKY_MOON and
 *                     scene->terms has OI_TERM_MOON)
 *   OI_ERR_ALBEDO     earth_albedo or target_albedo outside [0, 1] (NaN too)
 *   OI_ERR_NONFINITE  illum's e_sun, e_earth, e_moon, e_sky or flux_obs
 *   OI_ERR_INPUT      one of those five negative
 *   OI_ERR_SHAPE      scene->shape or attitude_q invalid (as oi_illuminate;
 *                     any shape with OI_NO_FACETS)
 *   OI_ERR_NONFINITE, OI_ERR_INPUT  with a shape, illum->flux_specular
 *                     non-finite or negative
 *   OI_ERR_CAMERA     the camera is invalid (oi_expose Note 4)
 *   OI_ERR_ZERO_VECTOR  observer or Sun at the Earth's centre
 *   OI_ERR_NONFINITE  a velocity component NaN or infinite
 *   OI_ERR_INPUT      a velocity component beyond 299792.458 km/s
 *   OI_ERR_BELOW_SURFACE  |observer| or |target| <= the Earth's radius
 *   OI_ERR_OBSERVER_AT_TARGET  observer and target at the same position
 *   then oi_expose's statuses for the goal and the derived flux
 *   (OI_ERR_INPUT for a goal out of range, OI_ERR_FLAGS for unknown
 *   goal->sky bits, OI_ERR_MAGNITUDE for a flux brighter than magnitude
 *   OI_MAG_MIN, OI_ERR_NONFINITE or OI_ERR_INPUT for the goal's sensor
 *   temperature, oi_expose Note 9).
 * Notes:
 *   1. Boresight b = target - observer. sun_angle_rad = angle(sun - observer,
 *      b) (as oi_angle); OI_FLAG_SUN_EXCLUSION when it is below
 *      camera->sun_exclusion_rad.
 *   2. OI_FLAG_EARTH_IN_FOV when the Earth's disc, of angular radius
 *      asin(R / |observer|), comes within fov_rad / 2 of the boresight (the
 *      diagonal field treated as a cone: conservative at the corners).
 *   3. Background: where the boresight ray meets the Earth, the radiance of
 *      a Lambertian Earth, earth_albedo * E0 * cos(i) / pi with
 *      E0 = TSI (1 AU / |sun|)^2 and i the Sun's incidence angle there;
 *      0 when that point is unlit or the ray misses the Earth (dark sky).
 *      The background is physical and does not depend on scene->terms,
 *      except for the scattered sunlight's share (3b).
 *   3b. With OI_TERM_SKY in scene->terms, where the boresight crosses the
 *      limb (it passes between the sky table's cloud floor and the top of the
 *      atmosphere; not on a Moon in front, Note 8), the background adds the
 *      limb's mean radiance seen from the observer, e_sky(observer) / Omega
 *      (Omega the solid angle of that ring; an estimate, see
 *      docs/skylight.md); the resolved bound (Note 5) counts e_sky.
 *   4. OI_FLAG_OCCULTED when the Earth lies between the observer and the
 *      target: the target's flux is then taken as 0 (TOO_FAINT follows).
 *   5. Resolved target: no pixel can collect more than a Lambertian surface
 *      of the target's albedo facing every source at once, of radiance
 *      target_albedo (e_sun + e_earth + e_moon + e_sky) / pi, over the pixel's solid
 *      angle (pitch / focal)^2. When psf_peak_fraction * flux exceeds that,
 *      the flux given to oi_expose is reduced so that the brightest pixel
 *      gets exactly that bound, and OI_FLAG_RESOLVED is raised.
 *   6. OI_FLAG_ECLIPSED when illum->shadow.region is OI_SHADOW_UMBRA,
 *      OI_FLAG_PENUMBRA when it is OI_SHADOW_PENUMBRA or OI_SHADOW_ANNULAR
 *      (part of the Sun hidden in both); OI_FLAG_MOON_SHADOW when
 *      illum->sun_moon_hidden > 0 (the Moon hides part of the Sun).
 *   7. Not modelled: the Earth's limb glow in the field, stray light from
 *      the Sun outside the exclusion angle or from a Moon beside the target,
 *      the atmosphere's radiance at the limb.
 *   8. Sky (goal->sky; positions taken as ICRF/GCRS-aligned, the ecliptic
 *      of J2000): the first surface the boresight ray meets decides. The
 *      Earth: Note 3. OI_SKY_MOON (read only with OI_TERM_MOON in
 *      scene->terms): OI_FLAG_MOON_IN_FOV when the Moon's disc comes within
 *      fov_rad / 2 of the boresight; met before the target, OI_FLAG_OCCULTED
 *      (flux 0); met, a Lambertian Moon of model moon_albedo lit by
 *      illum->moon_sun_fraction of the Sun. OI_SKY_ZODIACAL, where the ray
 *      meets neither: oi_zodiacal_radiance of the boresight's ecliptic
 *      longitude from the Sun and latitude, seen from the observer.
 *      OI_SKY_STARLIGHT, where the ray meets neither: oi_starlight_radiance
 *      of the boresight's galactic longitude and latitude
 *      (oi_galactic_from_icrs), added to the zodiacal light.
 *      docs/camera.md, "Sky background".
 *   9. Motion: rate_rad_s = |(target_vel - observer_vel) x b^| / range
 *      (clamped at 1e3 rad/s), then oi_expose's Note 7.
 *  10. Shape (scene->shape not NULL): OI_FLAG_GLINT when illum->flux_specular
 *      exceeds half of illum->flux_obs and the target is not occulted (the
 *      exposure uses the total). Note
 *      5's radiance bound is then the largest over the facets of
 *      (albedo_diffuse + albedo_specular (n + 2) / 2) (e_sun + e_earth +
 *      e_moon) / pi, the peak of its BRDF times pi (target_albedo for a
 *      diffuse_from_scene facet's diffuse part).
 */
int oi_expose_scene(const oi_camera *camera, const oi_scene *scene,
                    const oi_illum *illum, const oi_model *model,
                    const oi_expose_goal *goal, oi_exposure *out);

#endif /* OI_NO_EXPOSURE */

/* ---------------------------------------------------------------- batch */

/*
 * Batch calls: the single calls above over caller-owned arrays of n rows, the
 * model (and camera) validated once per batch. Row i of every output is, bit
 * for bit, what the single call returns for row i of the inputs (the fields
 * an outputs mask leaves out are 0). Arrays of the existing structures and
 * of oi_real (positions: 3 n values, x y z of row 0 first); src/batch/batch.c.
 *
 * Returned (function value): the number of rows whose status is an error
 * (0: every row computed; warnings do not count), or a batch error, every
 * status[i] then set to it and every output row zeroed where the pointers
 * allow:
 *   OI_ERR_NULL    a required array is NULL (with n > 0)
 *   OI_ERR_INPUT   n < 0 or n > OI_BATCH_MAX (then nothing is written, not
 *                  even status); an array not aligned for its element
 *                  type; an output array overlapping an input array or
 *                  another output (the contract forbids it: rows would
 *                  change under the call)
 *   OI_ERR_MODEL, OI_ERR_RADIUS, OI_ERR_CAMERA  the model or the camera is
 *                  invalid (as the single call)
 * n = 0 does nothing and returns 0 (NULL arrays allowed).
 * status[i]: the single call's status for row i (a NaN row gets
 * OI_ERR_NONFINITE and a zeroed output row, the others are computed).
 */
#define OI_BATCH_MAX (1073741824L) /* 2^30 rows per call */

/* Outputs mask of oi_sun_fraction_batch (bits);
 * fraction and region are always formed. */
#define OI_BATCH_FRACTION_LD (1u) /* oi_shadow.fraction_ld */
#define OI_BATCH_ATMOSPHERE  (2u) /* oi_shadow.fraction_atm (the atmosphere and its
                                     OI_WARN_TABLE_RANGE; without: 0, the atmosphere
                                     not consulted) */
#define OI_BATCH_GEOMETRY    (4u) /* oi_shadow.sun_radius_rad, earth_radius_rad,
                                     separation_rad, sun_distance_km */
#define OI_BATCH_ALL (OI_BATCH_FRACTION_LD | OI_BATCH_ATMOSPHERE | OI_BATCH_GEOMETRY)

/* oi_sun_fraction over n rows: sun_km, point_km 3 n values each; out[n],
 * status[n]. outputs: OI_BATCH_* bits (unknown bits: OI_ERR_FLAGS for the
 * batch). Cost: without OI_BATCH_FRACTION_LD and OI_BATCH_ATMOSPHERE the
 * limb-darkened integral is skipped (the uniform disc's fraction alone);
 * without OI_BATCH_GEOMETRY a point certainly in full sunlight (outside the
 * Earth's disc enlarged by 200 km, by 1e-6 in cosine) is answered from
 * its cosines, without the three arctangents (docs/performance.md). */
int oi_sun_fraction_batch(long n, const oi_real *sun_km, const oi_real *point_km,
                          const oi_model *model, unsigned outputs, oi_shadow *out,
                          int *status);

/* oi_earthshine over n rows: theta[n], h_km[n] in; phi[n] out; psi[n] out
 * or NULL (not wanted); status[n]. */
int oi_earthshine_batch(long n, const oi_real *theta, const oi_real *h_km,
                        const oi_model *model, oi_real *phi, oi_real *psi, int *status);

/* oi_illuminate over n scenes: scenes[n] in, out[n], status[n]. */
int oi_illuminate_batch(long n, const oi_scene *scenes, const oi_model *model,
                        oi_illum *out, int *status);

/* Outputs mask of oi_illuminate_batch_outputs (bits, with OI_BATCH_FRACTION_LD
 * for shadow.fraction_ld and OI_BATCH_GEOMETRY for the shadow's four angles
 * and distance; OI_BATCH_ATMOSPHERE is accepted and changes nothing there:
 * shadow.fraction_atm and e_sun are the scene's sunlight, always formed). */
#define OI_BATCH_DIRECTIONS  (8u)  /* dir_sun, dir_earth, dir_moon, dir_sky */
#define OI_BATCH_OBSERVER    (16u) /* what the observer receives: phase_*, flux_*,
                                      flux_obs, flux_specular, mag_v, range_km */
#define OI_BATCH_SCENE_ALL (OI_BATCH_ALL | OI_BATCH_DIRECTIONS | OI_BATCH_OBSERVER)

/* oi_illuminate over n scenes with an outputs mask: scenes[n] in, out[n],
 * status[n]; outputs OI_BATCH_* bits within OI_BATCH_SCENE_ALL (others:
 * OI_ERR_FLAGS for the batch). Every field asked for (and every field no bit
 * names: the irradiances e_*, shadow.fraction, fraction_atm and region, the
 * Earth's and the Moon's angles and fractions, earth_albedo_eff) is the
 * single call's bits; the fields left out are 0, and what only they need is
 * not computed: without OI_BATCH_GEOMETRY a target certainly in full
 * sunlight (or, without the atmosphere, certainly in the umbra) is answered
 * from cosines (as oi_sun_fraction_batch), without OI_BATCH_FRACTION_LD the
 * limb-darkened integral runs only where the model's sunlight needs it,
 * without OI_BATCH_OBSERVER the observer's term is not formed (its position
 * is still checked, with the single call's statuses; the observer inside
 * the target, OI_ERR_OBSERVER_AT_TARGET, is then not detected). With
 * OI_BATCH_SCENE_ALL every row is oi_illuminate's. src/scene/illuminate_outputs.c,
 * docs/performance.md. */
int oi_illuminate_batch_outputs(long n, const oi_scene *scenes, const oi_model *model,
                                unsigned outputs, oi_illum *out, int *status);

#ifndef OI_NO_EXPOSURE
/* oi_expose over n rows, one camera and goal: in[n], out[n], status[n]. */
int oi_expose_batch(long n, const oi_camera *camera, const oi_expose_in *in,
                    const oi_expose_goal *goal, oi_exposure *out, int *status);

/* oi_expose_scene over n rows: scenes[n], illum[n] (oi_illuminate_batch's
 * out) in, out[n], status[n]. A scene without observer gets OI_ERR_NULL in
 * its row (as the single call). */
int oi_expose_scene_batch(long n, const oi_camera *camera, const oi_scene *scenes,
                          const oi_illum *illum, const oi_model *model,
                          const oi_expose_goal *goal, oi_exposure *out, int *status);

/* Outputs mask of oi_expose_batch_outputs and oi_expose_scene_batch_outputs
 * (bits). Always formed: status and flags' geometric bits (every OI_FLAG_*
 * but TOO_FAINT, SATURATED, BACKGROUND_SATURATED and TRAILED). */
#define OI_EXPOSE_SETTING    (1u)  /* the choice: exposure_s, gain, time_index,
                                      gain_index, signal_e, background_e, peak_e,
                                      saturation_e, fill, snr, trail_px,
                                      trail_factor; OI_FLAG_SATURATED,
                                      OI_FLAG_BACKGROUND_SATURATED */
#define OI_EXPOSE_FAINT      (2u)  /* OI_FLAG_TOO_FAINT (at rest: one SNR; moving:
                                      the highest gain's allowed times), without
                                      the search */
#define OI_EXPOSE_DETECT     (4u)  /* signal_min_e, detect_margin_mag (the setting is
                                      searched for them) */
#define OI_EXPOSE_SUN_ANGLE  (8u)  /* sun_angle_rad (without: OI_FLAG_SUN_EXCLUSION
                                      decided from a cosine where it is certain) */
#define OI_EXPOSE_BACKGROUND (16u) /* background_w_m2_sr */
#define OI_EXPOSE_RATE       (32u) /* rate_rad_s */
#define OI_EXPOSE_ALL (OI_EXPOSE_SETTING | OI_EXPOSE_FAINT | OI_EXPOSE_DETECT | OI_EXPOSE_SUN_ANGLE | OI_EXPOSE_BACKGROUND | OI_EXPOSE_RATE)

/* oi_expose_batch and oi_expose_scene_batch with an outputs mask (OI_EXPOSE_*
 * bits; others: OI_ERR_FLAGS for the batch, checked before the model and
 * the camera). OI_FLAG_TRAILED comes with OI_EXPOSE_SETTING or
 * OI_EXPOSE_FAINT. Every field asked for, and the status, is the single
 * call's bits; the fields left out are 0, and what only they need is not
 * computed: without OI_EXPOSE_SETTING and OI_EXPOSE_DETECT no search, without
 * OI_EXPOSE_FAINT no detection test at the longest time (moving: no trail
 * over the highest gain's times), without OI_EXPOSE_SUN_ANGLE no arctangent
 * where the Sun is certainly inside or outside the exclusion angle, without
 * the choice's bits (SETTING, FAINT, DETECT): no angular rate unless
 * OI_EXPOSE_RATE, and no sky terms (zodiacal light, starlight, the limb's
 * scattered sunlight) unless OI_EXPOSE_BACKGROUND (the background's checks,
 * OI_ERR_NONFINITE and OI_ERR_INPUT, then not made). The goal's defaults, detection rule and
 * sensor temperature, the camera and the model are formed once per batch.
 * In oi_expose_batch_outputs background_w_m2_sr and rate_rad_s are the
 * input's and OI_EXPOSE_SUN_ANGLE changes nothing (sun_angle_rad is 0).
 * With OI_EXPOSE_ALL every row is the single call's. src/batch/expose_batch.c,
 * docs/camera.md "Batches and their outputs mask". */
int oi_expose_batch_outputs(long n, const oi_camera *camera, const oi_expose_in *in,
                            const oi_expose_goal *goal, unsigned outputs, oi_exposure *out,
                            int *status);
int oi_expose_scene_batch_outputs(long n, const oi_camera *camera, const oi_scene *scenes,
                                  const oi_illum *illum, const oi_model *model,
                                  const oi_expose_goal *goal, unsigned outputs,
                                  oi_exposure *out, int *status);
#endif /* OI_NO_EXPOSURE */

#ifdef __cplusplus
}
#endif

#endif /* ORBILLUM_H */
