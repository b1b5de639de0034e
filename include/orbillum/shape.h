/* SPDX-License-Identifier: MIT */
/*
 * orbillum/shape.h: targets with shape: facets, shapes and the built-in ones,
 * a facet's BRDF and its earthshine (removed by OI_NO_FACETS).
 *
 * A section of orbillum.h, the header a program includes (it includes every
 * section); compiles alone, and includes the sections it uses.
 */
#ifndef ORBILLUM_SHAPE_H
#define ORBILLUM_SHAPE_H

#include "base.h"
#include "model.h"

#ifdef __cplusplus
extern "C" {
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

#ifdef __cplusplus
}
#endif

#endif /* ORBILLUM_SHAPE_H */
