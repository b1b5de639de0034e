/* SPDX-License-Identifier: MIT */
/*
 * scene.h: the full scene of the size programs (oi_illuminate, and
 * oi_expose_scene when the camera model is compiled in) for a model m;
 * inputs from volatile memory so that nothing is folded away.
 */
#ifndef SIZE_SCENE_H
#define SIZE_SCENE_H

#include <stddef.h>

#include "orbillum.h"

static volatile oi_real size_in[9];
static volatile oi_real size_out;

static int size_full_scene(const oi_model *m)
{
    oi_scene s;
    oi_illum il;
    int st, k;
    oi_scene_defaults(&s);
    for (k = 0; k < 3; ++k) {
        s.sun_km[k] = size_in[k];
        s.target_km[k] = size_in[3 + k];
        s.observer_km[k] = size_in[6 + k];
    }
    s.has_observer = 1;
    st = oi_illuminate(&s, m, &il);
#ifndef OI_NO_EXPOSURE
    {
        oi_exposure ex;
        st += oi_expose_scene(oi_camera_builtin(0), &s, &il, m, NULL, &ex);
        size_out = ex.exposure_s;
    }
#endif
    size_out = il.mag_v + (oi_real)st;
    return 0;
}

#endif /* SIZE_SCENE_H */
