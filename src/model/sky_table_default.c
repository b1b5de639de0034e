/* SPDX-License-Identifier: MIT */
/*
 * sky_table_default.c: oi_sky_table_default, the library's default
 * scattered-sunlight table, and nothing else: the only reference to its
 * bytes (see src/model/earth_table_default.c). -DOI_SKY_TABLE_DEFAULT=<name>
 * chooses another oi_sky_table of tables/; OI_NO_SKYLIGHT makes it NULL.
 */
#include "orbillum.h"

#ifdef OI_NO_SKYLIGHT
const oi_sky_table *oi_sky_table_default(void)
{
    return (const oi_sky_table *)0;
}
#else
#ifndef OI_SKY_TABLE_DEFAULT
#define OI_SKY_TABLE_DEFAULT oi_sky_vband
#endif
extern const oi_sky_table OI_SKY_TABLE_DEFAULT;

const oi_sky_table *oi_sky_table_default(void)
{
    return &OI_SKY_TABLE_DEFAULT;
}
#endif
