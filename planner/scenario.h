/* SPDX-License-Identifier: MIT */
/* scenario.h: the built-in scenario of the planner: an inspector in LEO
 * photographing a target over one full orbit, through eclipse. */
#ifndef OI_PLAN_SCENARIO_H
#define OI_PLAN_SCENARIO_H

#include <stdio.h>

#include "orbillum.h"

/* Print the plan (a table every step_s seconds, then a summary of the
 * observation windows) to out. Returns 0, or 1 if a row failed. */
int scenario_run(FILE *out, const oi_camera *camera, double step_s);

#endif
