/* SPDX-License-Identifier: MIT */
/*
 * scene_internal.h: private to the runtime (not part of the API):
 * the scene layer (src/scene/): oi_illuminate and oi_expose_scene, the
 * steps the batch calls share with them.
 * A layer calls only the layers below it (docs/architecture.md); this
 * header includes the one below, so a file sees its layer and every lower one.
 */
#ifndef OI_SCENE_INTERNAL_H
#define OI_SCENE_INTERNAL_H

#include "camera/camera_internal.h"

/* The albedo model of a caller's model (albedo_model, albedo_map and its
 * dimensions), checked and copied into the resolved one (oi__model_resolve
 * leaves the uniform default): OI_OK, or OI_ERR_MODEL for an unknown model,
 * a map without its array or with a dimension outside 1..OI_ALBEDO_MAP_MAX_DIM,
 * or any model but the uniform one with OI_NO_ALBEDO_MODELS
 * (src/scene/illuminate.c; called by oi_illuminate and its batch, the functions
 * that read it). */
int oi__albedo_resolve(const oi_model *in, oi_model *out);

/* oi_illuminate (src/scene/illuminate.c) with a resolved model and non-NULL
 * scene and out: the model is not validated again. */
int oi__illuminate_resolved(const oi_scene *scene, const oi_model *m, oi_illum *out);

/* oi__illuminate_resolved with the outputs mask of
 * oi_illuminate_batch_outputs (OI_BATCH_* bits, checked by the caller):
 * src/scene/illuminate_outputs.c. */
int oi__illuminate_outputs(const oi_scene *scene, const oi_model *m, unsigned outputs,
                           oi_illum *out);

#ifndef OI_NO_EXPOSURE
/* The set-up of oi_expose_scene_batch_outputs (src/scene/expose_scene.c): the
 * model's constants, the plan, cos(sun_exclusion_rad), the outputs mask. */
typedef struct {
    oi__expose_plan plan;
    oi_real re, au, tsi, rm, moon_albedo; /* the model's (oi_model's units) */
    oi_real cos_excl;                     /* cos(camera->sun_exclusion_rad) */
    int shape;                            /* oi_model.earth_shape */
    unsigned outputs;                     /* OI_EXPOSE_* */
} oi__expose_scene_batch;

/* The set-up: the model's status, then the camera's (src/scene/expose_scene.c). */
int oi__expose_scene_setup(const oi_camera *camera, const oi_model *model,
                           const oi_expose_goal *goal, unsigned outputs,
                           oi__expose_scene_batch *b);
/* One row of oi_expose_scene (b NULL: the single call, every output and
 * every check; else the batch's set-up), out zeroed. */
int oi__expose_scene_row(const oi_camera *camera, const oi_scene *scene, const oi_illum *illum,
                         const oi_model *model, const oi_expose_goal *goal,
                         const oi__expose_scene_batch *b, oi_exposure *out);
#endif

#endif /* OI_SCENE_INTERNAL_H */
