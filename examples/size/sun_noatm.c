/* SPDX-License-Identifier: MIT */
/*
 * sun_noatm.c: program kind "Sun fraction only": oi_sun_fraction with the
 * atmosphere off (oi_model.no_atmosphere) and the library's default
 * atmosphere tables left out: this program defines oi_atm_table_default
 * and oi_atm_total_default itself, returning NULL, so neither
 * src/model/atm_table_default.c, src/model/atm_table_total_default.c nor
 * tables/oi_atm_vband.c, tables/oi_atm_total.c is linked (make size: no
 * table symbol in it).
 */
#include <stddef.h>

#include "orbillum.h"

const oi_atm_table *oi_atm_table_default(void)
{
    return NULL;
}

const oi_atm_table *oi_atm_total_default(void)
{
    return NULL;
}

static volatile oi_real vin[6];
static volatile oi_real vout;

int main(void)
{
    oi_real sun[3], pt[3];
    oi_model m = {0};
    oi_shadow sh;
    int st, k;
    for (k = 0; k < 3; ++k) {
        sun[k] = vin[k];
        pt[k] = vin[3 + k];
    }
    m.no_atmosphere = 1;
    st = oi_sun_fraction(sun, pt, &m, &sh);
    vout = sh.fraction_atm + (oi_real)st;
    return 0;
}
