/* SPDX-License-Identifier: MIT */
/* albedo_map.h: the planner's --albedo-map FILE, a latitude-longitude albedo
 * grid in a text format (docs/planner.md, "Albedo map file"). */
#ifndef OI_PLAN_ALBEDO_MAP_H
#define OI_PLAN_ALBEDO_MAP_H

#include "orbillum.h"

typedef struct plan_albedo_map {
    float *values;  /* n_lat * n_lon, rows north to south, cells east from Greenwich */
    int n_lat, n_lon;
} plan_albedo_map;

/* Read path into *map: 0, or PLAN_EXIT_INPUT after printing on stderr
 * "oi-plan: PATH: line N: why" (map then empty). */
int albedo_map_load(const char *path, plan_albedo_map *map);
void albedo_map_free(plan_albedo_map *map);

#endif
