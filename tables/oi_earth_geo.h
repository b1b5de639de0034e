/* SPDX-License-Identifier: MIT */
/*
 * oi_earth_geo.h: generated earthshine table (see oi_earth_geo.c for its provenance).
 */
#ifndef OI_EARTH_GEO_H
#define OI_EARTH_GEO_H

#include "oi_table.h"

#if OI_TABLE_FORMAT != 4
#error "oi_earth_geo.h: table format mismatch: regenerate tables (make bake)"
#endif

#define OI_EARTH_GEO_N_LIT 2
#define OI_EARTH_GEO_N_TERM 49
#define OI_EARTH_GEO_N_ALT 2
#define OI_EARTH_GEO_N_VALUES 102
#define OI_EARTH_GEO_W_MIN 1.4160366207099628
#define OI_EARTH_GEO_W_MAX 1.4232255460852268
#define OI_EARTH_GEO_TERM_K0 2.0
#define OI_EARTH_GEO_TERM_KP 8.0

#ifndef OI_NO_EARTH_TABLE
/* oi_earth_geo: altitude 35000 km to 37000 km, max relative error 2.603e-04 (see oi_earth_geo.c). */
extern const oi_earth_table oi_earth_geo;
#endif

#endif /* OI_EARTH_GEO_H */
