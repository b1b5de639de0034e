/* SPDX-License-Identifier: MIT */
/*
 * earth_angular_default.c: oi_earth_angular_default, the library's default
 * earthshine angular table, and nothing else: the only reference to its
 * bytes (see src/model/earth_table_default.c). OI_NO_EARTH_ANGULAR, and
 * OI_NO_EARTH_TABLE (the moments are per unit phi, which that table gives),
 * make it NULL.
 */
#include "orbillum.h"

#if defined(OI_NO_EARTH_ANGULAR) || defined(OI_NO_EARTH_TABLE)
const oi_earth_angular_table *oi_earth_angular_default(void)
{
    return (const oi_earth_angular_table *)0;
}
#else
extern const oi_earth_angular_table oi_earth_angular;

const oi_earth_angular_table *oi_earth_angular_default(void)
{
    return &oi_earth_angular;
}
#endif
