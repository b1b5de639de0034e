/* SPDX-License-Identifier: MIT */
/*
 * atm_table_total_default.c: oi_atm_total_default, the library's default
 * atmosphere table of the total band (oi_model.band = OI_BAND_TOTAL), and
 * nothing else: the only reference to its bytes, so that a program that
 * never asks for the total band, or defines its own oi_atm_total_default,
 * does not link them (as src/model/atm_table_default.c for the V band).
 *
 * Build-time choice: -DOI_ATM_TOTAL_DEFAULT=<name> makes another
 * oi_atm_table of tables/ the default; OI_NO_TOTAL_BAND or OI_NO_ATMOSPHERE
 * makes it NULL.
 */
#include "orbillum.h"

#if defined(OI_NO_ATMOSPHERE) || defined(OI_NO_TOTAL_BAND)
const oi_atm_table *oi_atm_total_default(void)
{
    return (const oi_atm_table *)0;
}
#else
#ifndef OI_ATM_TOTAL_DEFAULT
#define OI_ATM_TOTAL_DEFAULT oi_atm_total
#endif
extern const oi_atm_table OI_ATM_TOTAL_DEFAULT;

const oi_atm_table *oi_atm_total_default(void)
{
    return &OI_ATM_TOTAL_DEFAULT;
}
#endif
