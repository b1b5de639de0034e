/* SPDX-License-Identifier: MIT */
/* brdf.c: a facet's BRDF, Lambertian plus the normalised modified Phong lobe
 * (Lafortune & Willems 1994), and oi_facet_brdf. */
#include "target/target_internal.h"

#ifndef OI_NO_FACETS

/*
 * oi__phong_lobe: the specular lobe's BRDF per unit albedo_specular (1/sr),
 * (n + 2) / (2 pi) max(0, cos alpha)^n, alpha the angle between the mirror
 * image of u_in about the unit normal nrm and u_out (unit vectors from the
 * facet, both in front: cos_in = nrm.u_in > 0 given). The factor (n + 2) /
 * (2 pi) makes the directional albedo 1 at normal incidence and below 1
 * elsewhere (Lafortune & Willems 1994, KU Leuven report CW 197, section 3):
 * energy-conserving and reciprocal (alpha is symmetric in u_in, u_out).
 */
oi_real oi__phong_lobe(const oi_real nrm[3], oi_real cos_in, const oi_real u_in[3],
                       const oi_real u_out[3], oi_real shininess)
{
    oi_real c = (oi_real)0;
    int i;
    for (i = 0; i < 3; i++) c += (OI_R(2.0) * cos_in * nrm[i] - u_in[i]) * u_out[i];
    if (shininess == (oi_real)0) return (oi_real)1 / OI_PI_R;
    if (!(c > (oi_real)0)) return (oi_real)0;
    if (c > (oi_real)1) c = (oi_real)1;
    return (shininess + OI_R(2.0)) / (OI_R(2.0) * OI_PI_R) * OI_POW(c, shininess);
}

/* oi_facet_brdf: contract in include/orbillum.h. */
oi_real oi_facet_brdf(const oi_facet *facet, const oi_real to_source[3],
                      const oi_real to_observer[3])
{
    oi_real nrm[3], u_in[3], u_out[3], ci, co;
    int i;
    if (facet == NULL || to_source == NULL || to_observer == NULL) return (oi_real)0;
    if (!oi__finite3(facet->normal) || !oi__finite3(to_source) || !oi__finite3(to_observer))
        return (oi_real)0;
    if (!(facet->shininess >= (oi_real)0 && facet->shininess <= (oi_real)OI_SHININESS_MAX))
        return (oi_real)0;
    if (oi__unit_scaled(facet->normal, nrm) == (oi_real)0 || oi__unit(to_source, u_in) == (oi_real)0 ||
        oi__unit(to_observer, u_out) == (oi_real)0)
        return (oi_real)0;
    ci = oi__dot(nrm, u_in);
    if (ci < (oi_real)0 && facet->two_sided) {
        for (i = 0; i < 3; i++) nrm[i] = -nrm[i];
        ci = -ci;
    }
    co = oi__dot(nrm, u_out);
    if (!(ci > (oi_real)0) || !(co > (oi_real)0)) return (oi_real)0;
    return facet->albedo_diffuse / OI_PI_R +
           facet->albedo_specular * oi__phong_lobe(nrm, ci, u_in, u_out, facet->shininess);
}

#endif /* OI_NO_FACETS */
