/* SPDX-License-Identifier: MIT */
/* sun_fraction.c: oi_sun_fraction, the visible fraction of the Sun (uniform
 * and limb-darkened disc) seen from a point near the Earth, and
 * oi__sun_shadow, the same for callers holding a resolved model. Model,
 * formulas and measured accuracy: docs/shadow.md. */
/* oi__norm, oi__finite3 out of line: the Sun-only build stays small (src/oi_vector.h) */
#define OI_VECTOR_OUT_OF_LINE
#include "shadow/sun_fraction_steps.h"

/* disc_fractions for the other occulters (src/shadow/shadow_internal.h): the Sun
 * behind the Moon, the Moon behind the Earth; frac_ld NULL: not wanted. */
int oi__disc_fractions(oi_real rs, oi_real re, oi_real sep, oi_real *frac, oi_real *frac_ld)
{
    return disc_fractions(rs, re, sep, frac_ld != NULL, NULL, frac, frac_ld);
}

/* oi_sun_fraction with a resolved model, and (light_dir not NULL, atmosphere
 * compiled in and on) the mean direction the sunlight arrives from: see
 * src/shadow/shadow_internal.h. The composition of the steps above, each in its own
 * frame after the one before (make stack). */
int oi__sun_shadow(const oi_real sun_km[3], const oi_real point_km[3], const oi_model *resolved,
                   oi_shadow *out, oi_real light_dir[3])
{
    const int st = shadow_geometric(sun_km, point_km, resolved, 1, out);
    if (st < 0) return st;
#ifndef OI_NO_OBLATE
    if (st == GEOMETRIC_WANTS_EXACT)
        oblate_exact(sun_km, point_km, resolved->earth_radius_km, out);
#endif
    return atmosphere_fraction(sun_km, point_km, resolved, out, light_dir);
}

/* sun_fraction_resolved's value when the ellipsoid's exact fraction is to
 * follow: no status (step 4's warnings are positive statuses too) */
#define RESOLVED_WANTS_EXACT 0x4000

/* oi_sun_fraction's steps 1-3 with the caller's model resolved in this
 * frame, and step 4 unless the ellipsoid's exact fraction is wanted (then
 * RESOLVED_WANTS_EXACT). */
static GEOMETRIC_FRAME int sun_fraction_resolved(const oi_real sun_km[3], const oi_real point_km[3],
                                                 const oi_model *model, oi_shadow *out)
{
    oi_model m;
    int st = oi__model_resolve(model, &m);
    if (st < 0) return st;
    st = shadow_geometric(sun_km, point_km, &m, 1, out);
    if (st < 0) return st;
#ifndef OI_NO_OBLATE
    if (st == GEOMETRIC_WANTS_EXACT) return RESOLVED_WANTS_EXACT;
#endif
    return atmosphere_fraction(sun_km, point_km, &m, out, NULL);
}

#ifndef OI_NO_OBLATE
/* After sun_fraction_resolved: the model resolved again (that resolution
 * passed: the same model resolves the same), in frames of their own; the
 * Earth's radius for the exact fraction, and step 4. */
static OI_NOINLINE oi_real resolved_earth_radius(const oi_model *model)
{
    oi_model m;
    (void)oi__model_resolve(model, &m);
    return m.earth_radius_km;
}

static OI_NOINLINE int sun_fraction_atmosphere(const oi_real sun_km[3], const oi_real point_km[3],
                                               const oi_model *model, oi_shadow *out)
{
    oi_model m;
    (void)oi__model_resolve(model, &m);
    return atmosphere_fraction(sun_km, point_km, &m, out, NULL);
}
#endif

/*
 * oi_sun_fraction: visible fraction of the Sun seen from a point.
 *
 * Given:
 *   sun_km    oi_real[3]  Sun position, Earth-centred (km)
 *   point_km  oi_real[3]  point position, Earth-centred (km), above the
 *                         Earth's surface (|point| > earth_radius_km)
 *   model     oi_model*   NULL or model constants (sun_radius_km,
 *                         earth_radius_km, limb_darkening are used)
 * Returned:
 *   out       oi_shadow*  fraction: visible fraction of the uniform disc's
 *                         area, [0, 1]; fraction_ld: visible fraction of the
 *                         limb-darkened disc's flux, [0, 1]; fraction_atm:
 *                         fraction or fraction_ld as the model chooses (see
 *                         note 5); sun_radius_rad, earth_radius_rad,
 *                         separation_rad; sun_distance_km; region.
 * Returned (function value):
 *   OI_OK                 computed.
 *   OI_WARN_TABLE_RANGE   computed; the atmosphere table did not cover the
 *                         point (geometric fraction_atm kept; src/shadow/atmosphere.c).
 *   OI_ERR_NULL           sun_km, point_km or out is NULL.
 *   OI_ERR_MODEL          a model field is non-finite, negative or an unknown
 *                         option (from oi__model_resolve).
 *   OI_ERR_RADIUS         a negative model radius.
 *   OI_ERR_NONFINITE      a NaN or infinite component, or a Sun-to-point
 *                         vector that overflows.
 *   OI_ERR_ZERO_VECTOR    sun_km or point_km is the zero vector.
 *   OI_ERR_BELOW_SURFACE  |point| <= earth_radius_km.
 *   OI_ERR_GEOMETRY       |sun| <= sun_radius_km + earth_radius_km (the
 *                         Sun would touch the Earth), or the point inside or
 *                         on the Sun (|sun - point| <= sun_radius_km).
 *   On error every field of *out is zero.
 * Notes:
 *  1. Conical shadow on the celestial sphere of the point: the Sun's and the
 *     Earth's discs are spherical caps of radii asin(R/distance) (computed as
 *     atan2(R, sqrt((D - R)(D + R)))), with the TRUE Sun distance from the
 *     point, and centres separated by the angle between sun - point and
 *     -point (oi_angle). fraction = visible area / cap area, the visible
 *     area being the Sun's cap segment beyond the chord through the two
 *     crossing points of the limbs minus the Earth's segment (the
 *     complement of oi_cap_overlap's lens, formed without cancellation).
 *  2. Regions: LIT (separation >= r_earth + r_sun, or the Earth's centre
 *     farther from the point than the Sun's: the Earth behind the Sun;
 *     fraction exactly 1),
 *     UMBRA (separation <= r_earth - r_sun; exactly 0), ANNULAR (separation
 *     <= r_sun - r_earth: the Earth's disc inside the Sun's, beyond the
 *     umbra's tip; fraction = 1 - A(r_earth)/A(r_sun)), else PENUMBRA.
 *  3. Limb darkening: Neckel & Labs (1994) fifth-degree polynomial at
 *     559.95 nm (V band). fraction_ld by Green's theorem: the flux hidden
 *     is a line integral, along the Earth's limb inside the Sun's disc, of
 *     the flux within a radius about the Sun's centre (a closed form, the
 *     polynomial integrated against a binomial series in tan^2 r_sun), plus
 *     that flux times the angle of the Sun's limb inside the Earth's disc;
 *     one 12-point Gauss-Legendre panel in a variable that makes the limb's
 *     square roots smooth (graded panels when the Earth's disc is nearly
 *     internally tangent to the Sun's, beyond the umbra's tip). For
 *     r_sun > 0.5 rad (an observer within 2.1 solar radii of the Sun's
 *     centre) or < 1e-15 rad, fraction_ld = fraction. With
 *     OI_NO_LIMB_DARKENING (include/oi_config.h) fraction_ld = fraction
 *     always, and a model with OI_LIMB_DARKENED gives OI_ERR_MODEL.
 *  4. Accuracy (docs/shadow.md), against an mpmath ring quadrature of the
 *     same geometry: double, fraction and fraction_ld within 8e-14 absolute
 *     (1 m altitude to 1e7 km, 0.983-1.017 AU, shadow edges to 1e-12 rad);
 *     single, within 3e-5: the fraction changes by about 1/(2 r_sun) ~ 1e2
 *     per radian of separation, so it is bounded by that times the rounding
 *     of the separation. Near the surface |point|^2 - R^2 is formed in
 *     compensated arithmetic (the rounding of |point| would dominate).
 *     fraction_ld for a Sun of r_sun = 0.2 / 0.41 rad: 7e-11 / 5e-7 (the
 *     series' truncation, below (tan^2 r_sun)^6).
 *  5. fraction_atm: without the atmosphere (model->no_atmosphere, or
 *     OI_NO_ATMOSPHERE) it equals fraction, or fraction_ld with
 *     OI_LIMB_DARKENED; otherwise src/shadow/atmosphere.c adds refraction and
 *     extinction at the marked place (and may return OI_WARN_TABLE_RANGE).
 * References:
 *   Montenbruck, O. & Gill, E. 2000, Satellite Orbits, Springer, sec. 3.4.2
 *   (conical shadow model; its planar two-circle overlap is what this
 *   function replaces by the exact spherical one).
 *   Neckel, H. & Labs, D. 1994, Sol. Phys. 153, 91 (limb darkening).
 *   Green's theorem in polar form: the flux over a region is the line
 *   integral of F(rho) dt around it, F(rho) the flux within rho (see
 *   oi__fraction_limb_darkened).
 */
int oi_sun_fraction(const oi_real sun_km[3], const oi_real point_km[3],
                    const oi_model *model, oi_shadow *out)
{
    int st;
    if (out == NULL) return OI_ERR_NULL;
    memset(out, 0, sizeof *out);
    if (sun_km == NULL || point_km == NULL) return OI_ERR_NULL;
    /* the steps in frames of their own: the resolved model's copy is not
     * on the stack during the ellipsoid's quadrature (make stack), for two
     * more resolutions on that path */
    st = sun_fraction_resolved(sun_km, point_km, model, out);
#ifndef OI_NO_OBLATE
    if (st == RESOLVED_WANTS_EXACT) {
        oblate_exact(sun_km, point_km, resolved_earth_radius(model), out);
        st = sun_fraction_atmosphere(sun_km, point_km, model, out);
    }
#endif
    return st;
}

