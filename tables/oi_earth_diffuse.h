/* SPDX-License-Identifier: MIT */
/*
 * oi_earth_diffuse.h: generated earthshine table (see oi_earth_diffuse.c for its provenance).
 */
#ifndef OI_EARTH_DIFFUSE_H
#define OI_EARTH_DIFFUSE_H

#include "oi_table.h"

#if OI_TABLE_FORMAT != 4
#error "oi_earth_diffuse.h: table format mismatch: regenerate tables (make bake)"
#endif

#define OI_EARTH_DIFFUSE_N_LIT 2
#define OI_EARTH_DIFFUSE_N_TERM 49
#define OI_EARTH_DIFFUSE_N_ALT 122
#define OI_EARTH_DIFFUSE_N_VALUES 6222
#define OI_EARTH_DIFFUSE_W_MIN 0.0
#define OI_EARTH_DIFFUSE_W_MAX 1.5707963267948966
#define OI_EARTH_DIFFUSE_TERM_K0 2.0
#define OI_EARTH_DIFFUSE_TERM_KP 8.0

#ifndef OI_NO_EARTH_TABLE
/* oi_earth_diffuse: altitude 0 km to infinity, max relative error 5.174e-04 (see oi_earth_diffuse.c). */
extern const oi_earth_table oi_earth_diffuse;
#endif

#endif /* OI_EARTH_DIFFUSE_H */
