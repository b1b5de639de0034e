/* SPDX-License-Identifier: MIT */
/* shape_check.c: oi_shape_check, the validation of a shape's facets. */
#include "target/target_internal.h"

#ifndef OI_NO_FACETS

/* Largest accepted facet area (m^2): keeps area / range^2 finite in single
 * precision (docs/shapes.md). */
#define AREA_MAX_M2 OI_R(1e8)

static int in_unit(oi_real x)
{
    return oi__in_closed(x, (oi_real)0, (oi_real)1);
}

/* 1 when one facet is valid (its diffuse albedo checked unless from_scene). */
static int facet_valid(const oi_facet *f, int from_scene)
{
    if (!oi__finite3(f->normal)) return 0;
    if (f->normal[0] == (oi_real)0 && f->normal[1] == (oi_real)0 && f->normal[2] == (oi_real)0)
        return 0;
    if (!oi__in_open_closed(f->area_m2, (oi_real)0, AREA_MAX_M2)) return 0;
    if (!in_unit(f->albedo_specular)) return 0;
    if (!from_scene && (!in_unit(f->albedo_diffuse) ||
                        f->albedo_diffuse + f->albedo_specular > (oi_real)1))
        return 0;
    return oi__in_closed(f->shininess, (oi_real)0, (oi_real)OI_SHININESS_MAX);
}

/* oi_shape_check: contract in include/orbillum.h. */
int oi_shape_check(const oi_shape *shape)
{
    unsigned i;
    if (shape == NULL || shape->facets == NULL) return OI_ERR_NULL;
    if (shape->n_facets < 1u || shape->n_facets > (unsigned)OI_FACETS_MAX) return OI_ERR_SHAPE;
    for (i = 0; i < shape->n_facets; i++)
        if (!facet_valid(&shape->facets[i], shape->diffuse_from_scene != 0)) return OI_ERR_SHAPE;
    return OI_OK;
}

#endif /* OI_NO_FACETS */
