/* SPDX-License-Identifier: MIT */
/*
 * oi_earth_leo.h: generated earthshine table (see oi_earth_leo.c for its provenance).
 */
#ifndef OI_EARTH_LEO_H
#define OI_EARTH_LEO_H

#include "oi_table.h"

#if OI_TABLE_FORMAT != 4
#error "oi_earth_leo.h: table format mismatch: regenerate tables (make bake)"
#endif

#define OI_EARTH_LEO_N_LIT 2
#define OI_EARTH_LEO_N_TERM 49
#define OI_EARTH_LEO_N_ALT 24
#define OI_EARTH_LEO_N_VALUES 1224
#define OI_EARTH_LEO_W_MIN 0.24722083680408072
#define OI_EARTH_LEO_W_MAX 0.70550616027381485
#define OI_EARTH_LEO_TERM_K0 2.0
#define OI_EARTH_LEO_TERM_KP 8.0

#ifndef OI_NO_EARTH_TABLE
/* oi_earth_leo: altitude 200 km to 2000 km, max relative error 4.606e-04 (see oi_earth_leo.c). */
extern const oi_earth_table oi_earth_leo;
#endif

#endif /* OI_EARTH_LEO_H */
