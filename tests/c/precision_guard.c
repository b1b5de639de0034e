/* SPDX-License-Identifier: MIT */
/* precision_guard.c: the program tests/c/precision_guard.sh links against
 * each archive, to show that a precision mismatch fails at link time. */
#include <stdio.h>

#include "orbillum.h"

int main(void)
{
    oi_scene s;
    oi_illum il;
    int st;
    oi_scene_defaults(&s);
    s.terms = OI_TERM_SUN | OI_TERM_EARTH;
    s.sun_km[0] = (oi_real)OI_AU_KM;
    s.target_km[1] = (oi_real)7000.0;
    st = oi_illuminate(&s, NULL, &il);
    printf("%s %ld %.6g\n", oi_status_name(st), oi_version(), (double)il.e_sun);
    return st < 0;
}
