/* SPDX-License-Identifier: MIT */
/*
 * size_full.c: a program that calls every public function compiled in, so
 * that linking it with --gc-sections keeps exactly what a full application
 * needs (make size). Inputs come from volatile memory so nothing is folded
 * away. Built with the same option macros as the library (OI_NO_MOON, ...).
 */
#include <stddef.h>

#include "orbillum.h"
#include "semihost.h"

void oi_target_missing(const char *name);
void oi_target_missing(const char *name)
{
    sh_puts(name);
}

static volatile oi_real vin[16];
static volatile int vout;
static volatile oi_real rout;

int main(void)
{
    oi_scene s;
    oi_illum il;
    oi_real a[3], b[3], phi, psi, f;
    oi_shadow sh;
    int st = 0;
    a[0] = vin[0];
    a[1] = vin[1];
    a[2] = vin[2];
    b[0] = vin[3];
    b[1] = vin[4];
    b[2] = vin[5];
    oi_scene_defaults(&s);
    s.sun_km[0] = vin[0];
    s.target_km[1] = vin[6];
    s.observer_km[2] = vin[7];
    s.has_observer = 1;
#ifndef OI_NO_FACETS
    {
        /* a shape from the built-ins (by index or name), its check, the BRDF
         * and the plate's earthshine */
        oi_facet fc;
        oi_real e;
        s.shape = oi_shape_builtin((int)vin[12]);
        if (s.shape == NULL) s.shape = oi_shape_find(oi_status_name((int)vin[13]));
        st = oi_shape_check(s.shape);
        fc.normal[0] = a[0];
        fc.normal[1] = a[1];
        fc.normal[2] = a[2];
        fc.area_m2 = vin[3];
        fc.two_sided = (int)vin[4];
        fc.albedo_diffuse = vin[5];
        fc.albedo_specular = vin[6];
        fc.shininess = vin[7];
        rout = oi_facet_brdf(&fc, a, b);
        st += oi_earthshine_plate(vin[8], vin[9], a, NULL, &e);
        rout = e;
    }
#endif
    st += oi_illuminate(&s, NULL, &il);
    st += oi_sun_fraction(a, b, NULL, &sh);
    st += oi_earthshine(vin[8], vin[9], NULL, &phi, &psi);
    st += oi_flux_from_magnitude(vin[10], NULL, &f);
    rout = oi_lambert_phase(vin[11]) + oi_angle(a, b) + oi_cap_overlap(vin[12], vin[13], vin[14]) +
           oi_magnitude_v(vin[15], NULL) + phi + psi + f + sh.fraction + il.mag_v;
#ifndef OI_NO_MOON
    rout = oi_moon_phase_law(vin[11]);
#endif
#ifndef OI_NO_EXPOSURE
    {
        oi_exposure ex;
        const oi_camera *cam = oi_camera_find(oi_status_name(st));
        if (cam == NULL) cam = oi_camera_builtin(st);
        st += oi_expose_scene(cam, &s, &il, NULL, NULL, &ex);
        {
            oi_expose_in in;
            in.flux_w_m2 = vin[1];
            in.background_w_m2_sr = vin[2];
            in.flags = 0u;
            in.rate_rad_s = 0;
            st += oi_expose(cam, &in, NULL, &ex);
        }
        vout = (int)(oi_flag_name(ex.flags) != NULL);
    }
#endif
    vout = st;
    return 0;
}
