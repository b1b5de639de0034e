/* SPDX-License-Identifier: MIT */
/*
 * sun_atm.c: program kind "Sun fraction with the atmosphere":
 * oi_sun_fraction with the default model, so the library's default
 * atmosphere tables (oi_atm_table_default, tables/oi_atm_vband.c, and the
 * total band's oi_atm_total_default, tables/oi_atm_total.c, which the
 * lookup may be asked for) are linked; no earthshine table.
 */
#include <stddef.h>

#include "orbillum.h"

static volatile oi_real vin[6];
static volatile oi_real vout;

int main(void)
{
    oi_real sun[3], pt[3];
    oi_shadow sh;
    int st, k;
    for (k = 0; k < 3; ++k) {
        sun[k] = vin[k];
        pt[k] = vin[3 + k];
    }
    st = oi_sun_fraction(sun, pt, NULL, &sh);
    vout = sh.fraction_atm + (oi_real)st;
    return 0;
}
