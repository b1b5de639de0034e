/* SPDX-License-Identifier: MIT */
/*
 * own_earth.c: program kind "a caller's own earthshine table": the full
 * scene with oi_model.earth_table = &oi_earth_leo, and oi_earth_table_default
 * defined here (NULL), so the library's default earthshine table
 * (oi_earth_diffuse, 49.8 KB) is not linked (make size checks it with nm).
 * The default atmosphere is kept.
 */
#include "scene.h"
#include "oi_earth_leo.h"

const oi_earth_table *oi_earth_table_default(void)
{
    return NULL;
}

int main(void)
{
    oi_model m = {0};
    m.earth_table = &oi_earth_leo;
    return size_full_scene(&m);
}
