/* SPDX-License-Identifier: MIT */
/* shapes.h: the planner's target shapes: the named facet shapes of a
 * --shapes file (its text format is in docs/planner.md, "Shapes file"), held
 * in fixed-size storage, and the lookup of a target_shape name among them and
 * the library's built-in shapes. */
#ifndef OI_PLAN_SHAPES_H
#define OI_PLAN_SHAPES_H

#include <stdio.h>

#include "orbillum.h"

#define PLAN_SHAPES_MAX 16         /* shapes in one --shapes file */
#define PLAN_FACETS_TOTAL 512      /* facets over all of them (each shape at most
                                      OI_FACETS_MAX) */
#define PLAN_SHAPE_NAME_MAX 32     /* bytes of a name, with its NUL */
#define PLAN_SHAPE_LINE_MAX 1024   /* bytes of a line of the file, with its line end */

typedef struct plan_shape {
    char name[PLAN_SHAPE_NAME_MAX];
    unsigned long line;            /* line of its "shape" record */
    oi_shape shape;                /* facets point into plan_shapes.facets */
} plan_shape;

typedef struct plan_shapes {
    plan_shape shapes[PLAN_SHAPES_MAX];
    unsigned n_shapes;
    oi_facet facets[PLAN_FACETS_TOTAL];
    unsigned n_facets;
} plan_shapes;

/* Read a --shapes file into *s (path "-" is not accepted: standard input
 * carries the batch). Returns 0, or -1 after printing "oi-plan: FILE:LINE:
 * what" on err; *s is then empty. */
int shapes_load(plan_shapes *s, const char *path, FILE *err);

/* The shape of a target_shape field: "" or "sphere" -> *out NULL (the
 * scene's Lambertian sphere), a name of the file (s may be NULL), or a
 * built-in name (oi_shape_find). Returns 0, or -1 for an unknown name. */
int shapes_lookup(const plan_shapes *s, const char *name, const oi_shape **out);

/* Names a target_shape can take, space-separated, into buf (for messages). */
void shapes_names(const plan_shapes *s, char *buf, size_t size);

#endif
