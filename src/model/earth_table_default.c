/* SPDX-License-Identifier: MIT */
/*
 * earth_table_default.c: oi_earth_table_default, the library's default
 * earthshine table, and nothing else. This translation unit is the only
 * reference to the default table: a program that passes its own table and
 * defines its own oi_earth_table_default (returning its table, or NULL)
 * links neither this function nor the table's bytes (an archive member is
 * pulled in only for a symbol still undefined).
 *
 * Build-time choice: -DOI_EARTH_TABLE_DEFAULT=oi_earth_leo makes any table
 * of tables/ the default (its name; the table must be an oi_earth_table);
 * OI_NO_EARTH_TABLE makes the default NULL (Lambert far field, see
 * oi_earthshine in include/orbillum.h).
 */
#include "orbillum.h"

#ifdef OI_NO_EARTH_TABLE
const oi_earth_table *oi_earth_table_default(void)
{
    return (const oi_earth_table *)0;
}
#else
#ifndef OI_EARTH_TABLE_DEFAULT
#define OI_EARTH_TABLE_DEFAULT oi_earth_diffuse
#endif
extern const oi_earth_table OI_EARTH_TABLE_DEFAULT;

const oi_earth_table *oi_earth_table_default(void)
{
    return &OI_EARTH_TABLE_DEFAULT;
}
#endif
