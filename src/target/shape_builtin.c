/* SPDX-License-Identifier: MIT */
/* shape_builtin.c: the built-in shapes (plate, box-wing, cylinder), their
 * dimensions and reflectances with sources, oi_shape_builtin and
 * oi_shape_find. */
#include "target/target_internal.h"

#ifndef OI_NO_FACETS

/* plate: one one-sided Lambertian facet of exactly 1 m^2, normal +z; its
 * diffuse albedo is the scene's target_albedo (diffuse_from_scene). */
static const oi_facet plate_facets[1] = {
    {{OI_R(0.0), OI_R(0.0), OI_R(1.0)}, OI_R(1.0), 0, OI_R(0.0), OI_R(0.0), OI_R(0.0)},
};

/*
 * box-wing: a 2 m cubic bus and two 2 m x 6 m solar arrays along the body's
 * y axis, the cells facing +z (both wings' faces of one normal are one facet:
 * the facets are not spatially resolved). Dimensions: illustrative of a
 * small communications satellite (not one particular spacecraft).
 * Reflectances, from the materials' published solar absorptance alpha
 * (reflectance 1 - alpha of an opaque surface):
 *  - array front: solar cells under cover glass, alpha = 0.92 (Gilmore
 *    2002, Spacecraft Thermal Control Handbook, Appendix A): reflectance
 *    0.08, of which the glass's Fresnel reflection at normal incidence,
 *    ((n - 1) / (n + 1))^2 = 0.035 for fused silica n = 1.458 (Malitson
 *    1965, JOSA 55, 1205), specular with a narrow lobe (shininess 1000,
 *    about 2 deg half-width: the cells' flatness), the rest 0.045 diffuse;
 *  - array back: white-painted or graphite back sheet, taken as diffuse
 *    0.3 (assumption, docs/shapes.md);
 *  - bus: aluminised polyimide multilayer insulation, alpha = 0.40
 *    (Gilmore 2002): reflectance 0.60, crinkled: half diffuse, half a broad
 *    specular lobe (shininess 10; the split is an assumption).
 */
#define BUS_FACE(x, y, z)                                                                   \
    {{OI_R(x), OI_R(y), OI_R(z)}, OI_R(4.0), 0, OI_R(0.30), OI_R(0.30), OI_R(10.0)}
static const oi_facet box_wing_facets[8] = {
    BUS_FACE(1.0, 0.0, 0.0), BUS_FACE(-1.0, 0.0, 0.0),
    BUS_FACE(0.0, 1.0, 0.0), BUS_FACE(0.0, -1.0, 0.0),
    BUS_FACE(0.0, 0.0, 1.0), BUS_FACE(0.0, 0.0, -1.0),
    {{OI_R(0.0), OI_R(0.0), OI_R(1.0)}, OI_R(24.0), 0, OI_R(0.045), OI_R(0.035), OI_R(1000.0)},
    {{OI_R(0.0), OI_R(0.0), OI_R(-1.0)}, OI_R(24.0), 0, OI_R(0.30), OI_R(0.0), OI_R(0.0)},
};

/*
 * cylinder: a rocket body of the SL-16 class (Zenit-2 second stage: 3.9 m in
 * diameter, about 11 m long; Yuzhnoye's published figures, rounded), its
 * axis along +z, as a 12-sided prism whose sides keep the cylinder's
 * lateral area (each 2 pi R / 12 x L = 1.0210 m x 11 m = 11.231 m^2) and two
 * end caps of the disc's area pi R^2 = 11.946 m^2. Diffuse albedo 0.13, the
 * optical albedo of orbital debris of Mulrooney & Matney (2007, AMOS
 * conference, "Derivation and application of a global albedo yielding an
 * optical brightness to physical size transformation free of systematic
 * errors"); no specular part. cos and sin of k 30 deg written out.
 */
#define SIDE(c, s) {{OI_R(c), OI_R(s), OI_R(0.0)}, OI_R(11.231), 0, OI_R(0.13), OI_R(0.0), OI_R(0.0)}
#define C30 0.86602540378443864676
static const oi_facet cylinder_facets[14] = {
    SIDE(1.0, 0.0), SIDE(C30, 0.5), SIDE(0.5, C30), SIDE(0.0, 1.0),
    SIDE(-0.5, C30), SIDE(-C30, 0.5), SIDE(-1.0, 0.0), SIDE(-C30, -0.5),
    SIDE(-0.5, -C30), SIDE(0.0, -1.0), SIDE(0.5, -C30), SIDE(C30, -0.5),
    {{OI_R(0.0), OI_R(0.0), OI_R(1.0)}, OI_R(11.946), 0, OI_R(0.13), OI_R(0.0), OI_R(0.0)},
    {{OI_R(0.0), OI_R(0.0), OI_R(-1.0)}, OI_R(11.946), 0, OI_R(0.13), OI_R(0.0), OI_R(0.0)},
};

static const oi_shape builtin[3] = {
    {plate_facets, 1u, 1, "plate"},
    {box_wing_facets, 8u, 0, "box-wing"},
    {cylinder_facets, 14u, 0, "cylinder"},
};

#define N_BUILTIN ((int)(sizeof builtin / sizeof builtin[0]))

/* oi_shape_builtin: contract in include/orbillum.h. */
const oi_shape *oi_shape_builtin(int index)
{
    if (index < 0 || index >= N_BUILTIN) return NULL;
    return &builtin[index];
}

/* oi_shape_find: contract in include/orbillum.h (exact match, no strcmp:
 * freestanding). */
const oi_shape *oi_shape_find(const char *name)
{
    int i, k;
    if (name == NULL) return NULL;
    for (i = 0; i < N_BUILTIN; i++) {
        const char *a = builtin[i].name;
        for (k = 0; k < 16 && a[k] != '\0' && a[k] == name[k]; k++) {
        }
        if (k < 16 && a[k] == '\0' && name[k] == '\0') return &builtin[i];
    }
    return NULL;
}

#endif /* OI_NO_FACETS */
