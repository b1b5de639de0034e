/* SPDX-License-Identifier: MIT */
/* quickstart.c: the README's ten-line example, as a program that is built and
 * run by `make test` so the README cannot drift from the API. */
#include <stdio.h>

#include "orbillum.h"

int main(void)
{
    oi_scene scene;
    oi_illum illum;
    int status;
    oi_scene_defaults(&scene);                  /* albedos, radius, all terms */
    scene.sun_km[0] = 1.496e8;                  /* Earth-centred inertial, km */
    scene.moon_km[1] = 384400.0;
    scene.target_km[2] = 6878.0;
    scene.observer_km[2] = 6878.0;
    scene.observer_km[0] = 5.0;
    scene.has_observer = 1;
    status = oi_illuminate(&scene, NULL, &illum); /* NULL model: the defaults */
    printf("status %s: sun fraction %.3f, E_sun %.1f, E_earth %.1f, E_moon %.2e W/m^2, V = %.2f\n",
           oi_status_name(status), illum.shadow.fraction, illum.e_sun, illum.e_earth,
           illum.e_moon, illum.mag_v);
#ifndef OI_NO_EXPOSURE
    {
        oi_exposure exposure;
        status = oi_expose_scene(oi_camera_find("telescope-15cm"), &scene, &illum, NULL, NULL,
                                 &exposure);
        printf("status %s: exposure %g s, gain %g, SNR %.1f, flags 0x%x\n", oi_status_name(status),
               exposure.exposure_s, exposure.gain, exposure.snr, exposure.flags);
    }
#endif
    return status < 0;
}
