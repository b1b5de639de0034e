/* SPDX-License-Identifier: MIT */
/*
 * oi_constants.h: physical constants and defaults, each with units and source.
 * Derived constants are expressions of these, never new literals.
 * Every value here is only a default: oi_model overrides each at run time.
 */
#ifndef OI_CONSTANTS_H
#define OI_CONSTANTS_H

/* Astronomical unit (km), IAU 2012 Resolution B2. */
#define OI_AU_KM (149597870.7)

/* Total solar irradiance at 1 AU (W/m^2), IAU 2015 Resolution B3 nominal
 * value 1361 W/m^2 (Kopp & Lean 2011, GRL 38, L01706). */
#define OI_TSI_W_M2 (1361.0)

/* Nominal solar radius (km), IAU 2015 Resolution B3. */
#define OI_SUN_RADIUS_KM (695700.0)

/* Earth equatorial radius (km), WGS-84 / GRS-80. */
#define OI_EARTH_RADIUS_KM (6378.137)

/* Inverse flattening of the WGS-84 ellipsoid (NIMA TR8350.2, 3rd ed., 2000,
 * table 3.1): the Earth's shape with oi_model.earth_shape = OI_EARTH_WGS84,
 * of equatorial radius oi_model.earth_radius_km (default 6378.137 km, the
 * WGS-84 semi-major axis) and polar radius a (1 - 1/298.257223563). */
#define OI_WGS84_INV_FLATTENING (298.257223563)

/* Mean lunar radius (km), IAU WG on Cartographic Coordinates (Archinal et
 * al. 2011, Celest. Mech. Dyn. Astr. 109, 101). */
#define OI_MOON_RADIUS_KM (1737.4)

/* Mean Earth-Moon distance (km) at which the lunar phase law is normalised
 * (Krisciunas & Schaefer 1991, PASP 103, 1033). */
#define OI_MOON_MEAN_DISTANCE_KM (384400.0)

/* Earth's Bond albedo, default for the earthshine term (Stephens et al.
 * 2015, Rev. Geophys. 53, 141: 0.29-0.30). */
#define OI_EARTH_ALBEDO_DEFAULT (0.30)

/* Moon's geometric-to-Bond style albedo used by the Lambert Moon option
 * (~0.12: Matthews 2008, Appl. Opt. 47, 4981; docs/physics.md). */
#define OI_MOON_ALBEDO_DEFAULT (0.12)

/* Apparent V magnitude of the Sun at 1 AU (Willmer 2018, ApJS 236, 47:
 * -26.76; this project uses -26.74, as do Allen's Astrophysical Quantities;
 * docs/physics.md). */
#define OI_SUN_MAG_V (-26.74)

/* V magnitude of the full Moon at mean distance, phase angle 0, from the
 * empirical phase law of Krisciunas & Schaefer (1991), eq. 20. */
#define OI_MOON_MAG_V_FULL (-12.73)

/* Default target properties (also the planner's CSV defaults). */
#define OI_TARGET_ALBEDO_DEFAULT (0.2)
#define OI_TARGET_RADIUS_M_DEFAULT (1.0)

/* Magnitude returned when the flux is zero or too small to represent:
 * fainter than anything measurable, and finite (no inf in outputs). */
#define OI_MAG_DARK (99.0)

/* Mathematical constants. */
#define OI_PI (3.14159265358979323846264338327950288)
#define OI_DEG_PER_RAD (180.0 / OI_PI)

#endif /* OI_CONSTANTS_H */
