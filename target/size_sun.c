/* SPDX-License-Identifier: MIT */
/*
 * size_sun.c: the smallest useful application: the Sun's visible fraction
 * only (oi_sun_fraction). Built with -DOI_NO_MOON -DOI_NO_EXPOSURE
 * -DOI_NO_ATMOSPHERE -DOI_NO_EARTH_TABLE and --gc-sections (make size).
 */
#include <stddef.h>

#include "orbillum.h"

void oi_target_missing(const char *name);
void oi_target_missing(const char *name)
{
    (void)name;
}

static volatile oi_real vin[6];
static volatile oi_real vout;

int main(void)
{
    oi_real sun[3], pt[3];
    oi_shadow sh;
    int st;
    sun[0] = vin[0];
    sun[1] = vin[1];
    sun[2] = vin[2];
    pt[0] = vin[3];
    pt[1] = vin[4];
    pt[2] = vin[5];
    st = oi_sun_fraction(sun, pt, NULL, &sh);
    vout = sh.fraction_atm + (oi_real)st;
    return 0;
}
