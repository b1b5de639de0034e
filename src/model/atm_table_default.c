/* SPDX-License-Identifier: MIT */
/*
 * atm_table_default.c: oi_atm_table_default, the library's default
 * atmosphere table, and nothing else. This translation unit is the only
 * reference to the default table: a program that defines its own
 * oi_atm_table_default (returning its table, or NULL) links neither this
 * function nor the table's bytes (an archive member is pulled in only for a
 * symbol still undefined).
 *
 * Build-time choice: -DOI_ATM_TABLE_DEFAULT=<name> makes another
 * oi_atm_table of tables/ the default; OI_NO_ATMOSPHERE makes it NULL (the
 * atmosphere is compiled out and nothing asks for it).
 */
#include "orbillum.h"

#ifdef OI_NO_ATMOSPHERE
const oi_atm_table *oi_atm_table_default(void)
{
    return (const oi_atm_table *)0;
}
#else
#ifndef OI_ATM_TABLE_DEFAULT
#define OI_ATM_TABLE_DEFAULT oi_atm_vband
#endif
extern const oi_atm_table OI_ATM_TABLE_DEFAULT;

const oi_atm_table *oi_atm_table_default(void)
{
    return &OI_ATM_TABLE_DEFAULT;
}
#endif
