/* SPDX-License-Identifier: MIT */
/*
 * orbillum/shadow.h: direct sunlight: the visible fraction of the Sun seen
 * from a point, in the shadows of the Earth (oi_shadow, oi_sun_fraction).
 *
 * A section of orbillum.h, the header a program includes (it includes every
 * section); compiles alone, and includes the sections it uses.
 */
#ifndef ORBILLUM_SHADOW_H
#define ORBILLUM_SHADOW_H

#include "base.h"
#include "model.h"

#ifdef __cplusplus
extern "C" {
#endif

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

#ifdef __cplusplus
}
#endif

#endif /* ORBILLUM_SHADOW_H */
