/* SPDX-License-Identifier: MIT */
/* batch.h: the planner's batch interface (--csv FILE|-): read the scenario
 * CSV, run the library on every row, write the result CSV. */
#ifndef OI_PLAN_BATCH_H
#define OI_PLAN_BATCH_H

#include <stdio.h>

#include "albedo_map.h"
#include "orbillum.h"
#include "shapes.h"

/* Exit codes. */
#define PLAN_EXIT_OK 0       /* every row OK (warnings count as OK) */
#define PLAN_EXIT_ROWS 1     /* some rows had errors */
#define PLAN_EXIT_INPUT 2    /* unusable input: no header, missing required
                                column, unreadable file, bad options */

/* Run the batch on path ("-" for standard input), writing CSV to out and
 * messages to stderr. Rows without a camera column use default_camera.
 * shapes: the named shapes of --shapes FILE that target_shape may name
 * besides the built-in ones, or NULL.
 * summary: NULL, or where to print the observation windows of the pass
 * (consecutive rows, labelled by id) at the end.
 * Returns a PLAN_EXIT_* code. */
int batch_run(const char *path, const oi_camera *default_camera, const plan_shapes *shapes,
              FILE *out, FILE *summary);

/* batch_run with the albedo map of --albedo-map (NULL: none given; rows with
 * albedo_model map are then errors). */
int batch_run_map(const char *path, const oi_camera *default_camera, const plan_shapes *shapes,
                  const plan_albedo_map *albedo_map, FILE *out, FILE *summary);

#endif
