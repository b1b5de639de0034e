/* SPDX-License-Identifier: MIT */
/*
 * target_internal.h: private to the runtime (not part of the API):
 * the target layer (src/target/): shapes and facets, their BRDF and
 * earthshine, the attitude quaternion, the V magnitude.
 * A layer calls only the layers below it (docs/architecture.md); this
 * header includes the one below, so a file sees its layer and every lower one.
 */
#ifndef OI_TARGET_INTERNAL_H
#define OI_TARGET_INTERNAL_H

#include "sources/sources_internal.h"

#ifndef OI_NO_FACETS
/* 1 when a resolved model has the facets' earthshine from the cubature
 * (earth_reflection OI_EARTH_REFLECT_MOMENTS or OI_EARTH_REFLECT_TABLE,
 * which a facet cannot use, with earth_model OI_EARTH_TABLE), 0 for the
 * mean direction. */
static inline int oi__plate_cubature(const oi_model *m)
{
    return m->earth_reflection != OI_EARTH_REFLECT_MEAN && m->earth_model == OI_EARTH_TABLE;
}
/* Earthshine irradiance on a face of unit normal nrm in the local frame, per
 * unit Earth albedo and solar irradiance (src/target/facet_earth.c). */
oi_real oi__plate_earth(oi_real cos_theta, oi_real sin_theta, oi_real h_km, oi_real R,
                        const oi_real nrm[3]);
/* The specular earthshine radiance a face of unit normal nrm sends towards
 * the unit direction obs (both local frame) per unit albedo_specular, Earth
 * albedo and solar irradiance: the integral over the visible sunlit Earth
 * of L(omega) (N.omega) f(omega -> obs), f the Phong lobe of oi__phong_lobe
 * (src/target/facet_earth.c): the cap cubature's rings for shininess below
 * OI_LOBE_RULE_SHININESS, nodes about the lobe's axis from it up. */
#ifndef OI_LOBE_RULE_SHININESS
#define OI_LOBE_RULE_SHININESS 64
#endif
oi_real oi__plate_earth_specular(oi_real cos_theta, oi_real sin_theta, oi_real h_km, oi_real R,
                                 const oi_real nrm[3], const oi_real obs[3], oi_real shininess);
/* The attitude quaternion's check and rotation (src/target/quaternion.c). */
int oi__quat_unit(const oi_real q[4], oi_real out[4]);
void oi__quat_rotate(const oi_real q[4], const oi_real v[3], oi_real out[3]);
/* The specular lobe per unit albedo (src/target/brdf.c). */
oi_real oi__phong_lobe(const oi_real nrm[3], oi_real cos_in, const oi_real u_in[3],
                       const oi_real u_out[3], oi_real shininess);
/* A scene's shape: its check and its fluxes (src/target/facet.c). */
int oi__shape_scene_check(const oi_scene *s);
void oi__shape_flux(const oi_scene *s, const oi_model *m, oi_illum *out);
oi_real oi__shape_peak(const oi_scene *s);
#endif

/* oi_magnitude_v (src/target/magnitude.c) with the model's TSI already resolved. */
oi_real oi__magnitude_v(oi_real flux_w_m2, oi_real tsi_w_m2);

#endif /* OI_TARGET_INTERNAL_H */
