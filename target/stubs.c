/* SPDX-License-Identifier: MIT */
/*
 * stubs.c: placeholders for public functions a library build does not define
 * yet. Compiled once per function (-DSTUB_<name>) into libstubs.a, linked
 * AFTER liborbillum.a, so a stub is only pulled in when the library lacks the
 * real function. Each stub reports itself through oi_target_missing() (the
 * self-test counts it as a failure; the benchmark marks the configuration
 * incomplete), zeroes its outputs and returns an error.
 */
#include <string.h>

#include "orbillum.h"

void oi_target_missing(const char *name);

#define STUB_ERR (-100)

#ifdef STUB_oi_status_name
const char *oi_status_name(int status)
{
    (void)status;
    oi_target_missing("oi_status_name");
    return "UNKNOWN";
}
#endif
#ifdef STUB_oi_lambert_phase
oi_real oi_lambert_phase(oi_real xi)
{
    (void)xi;
    oi_target_missing("oi_lambert_phase");
    return (oi_real)0;
}
#endif
#ifdef STUB_oi_angle
oi_real oi_angle(const oi_real a[3], const oi_real b[3])
{
    (void)a;
    (void)b;
    oi_target_missing("oi_angle");
    return (oi_real)0;
}
#endif
#ifdef STUB_oi_cap_overlap
oi_real oi_cap_overlap(oi_real r1, oi_real r2, oi_real d)
{
    (void)r1;
    (void)r2;
    (void)d;
    oi_target_missing("oi_cap_overlap");
    return (oi_real)0;
}
#endif
#ifdef STUB_oi_sun_fraction
int oi_sun_fraction(const oi_real sun_km[3], const oi_real point_km[3], const oi_model *model,
                    oi_shadow *out)
{
    (void)sun_km;
    (void)point_km;
    (void)model;
    oi_target_missing("oi_sun_fraction");
    if (out) memset(out, 0, sizeof *out);
    return STUB_ERR;
}
#endif
#ifdef STUB_oi_earthshine_sphere
int oi_earthshine_sphere(oi_real theta, oi_real h_km, const oi_real obs[3], const oi_model *model,
                         oi_real *flux)
{
    (void)theta;
    (void)h_km;
    (void)obs;
    (void)model;
    oi_target_missing("oi_earthshine_sphere");
    if (flux) *flux = (oi_real)0;
    return STUB_ERR;
}
#endif
#ifdef STUB_oi_earthshine
int oi_earthshine(oi_real theta, oi_real h_km, const oi_model *model, oi_real *phi, oi_real *psi)
{
    (void)theta;
    (void)h_km;
    (void)model;
    oi_target_missing("oi_earthshine");
    if (phi) *phi = (oi_real)0;
    if (psi) *psi = (oi_real)0;
    return STUB_ERR;
}
#endif
#if defined(STUB_oi_moon_phase_law) && !defined(OI_NO_MOON)
oi_real oi_moon_phase_law(oi_real alpha)
{
    (void)alpha;
    oi_target_missing("oi_moon_phase_law");
    return (oi_real)0;
}
#endif
#ifdef STUB_oi_scene_defaults
void oi_scene_defaults(oi_scene *scene)
{
    oi_target_missing("oi_scene_defaults");
    if (scene) memset(scene, 0, sizeof *scene);
}
#endif
#ifdef STUB_oi_illuminate
int oi_illuminate(const oi_scene *scene, const oi_model *model, oi_illum *out)
{
    (void)scene;
    (void)model;
    oi_target_missing("oi_illuminate");
    if (out) memset(out, 0, sizeof *out);
    return STUB_ERR;
}
#endif
#ifdef STUB_oi_magnitude_v
oi_real oi_magnitude_v(oi_real flux_w_m2, const oi_model *model)
{
    (void)flux_w_m2;
    (void)model;
    oi_target_missing("oi_magnitude_v");
    return (oi_real)0;
}
#endif
#ifdef STUB_oi_flux_from_magnitude
int oi_flux_from_magnitude(oi_real mag_v, const oi_model *model, oi_real *flux_w_m2)
{
    (void)mag_v;
    (void)model;
    oi_target_missing("oi_flux_from_magnitude");
    if (flux_w_m2) *flux_w_m2 = (oi_real)0;
    return STUB_ERR;
}
#endif
#ifndef OI_NO_EXPOSURE
#ifdef STUB_oi_camera_builtin
const oi_camera *oi_camera_builtin(int index)
{
    (void)index;
    oi_target_missing("oi_camera_builtin");
    return NULL;
}
#endif
#ifdef STUB_oi_camera_find
const oi_camera *oi_camera_find(const char *name)
{
    (void)name;
    oi_target_missing("oi_camera_find");
    return NULL;
}
#endif
#ifdef STUB_oi_flag_name
const char *oi_flag_name(unsigned flag_bit)
{
    (void)flag_bit;
    oi_target_missing("oi_flag_name");
    return NULL;
}
#endif
#ifdef STUB_oi_expose
int oi_expose(const oi_camera *camera, const oi_expose_in *in, const oi_expose_goal *goal,
              oi_exposure *out)
{
    (void)camera;
    (void)in;
    (void)goal;
    oi_target_missing("oi_expose");
    if (out) memset(out, 0, sizeof *out);
    return STUB_ERR;
}
#endif
#ifdef STUB_oi_expose_scene
int oi_expose_scene(const oi_camera *camera, const oi_scene *scene, const oi_illum *illum,
                    const oi_model *model, const oi_expose_goal *goal, oi_exposure *out)
{
    (void)camera;
    (void)scene;
    (void)illum;
    (void)model;
    (void)goal;
    oi_target_missing("oi_expose_scene");
    if (out) memset(out, 0, sizeof *out);
    return STUB_ERR;
}
#endif
#endif /* OI_NO_EXPOSURE */

#ifndef OI_NO_FACETS
#ifdef STUB_oi_shape_check
int oi_shape_check(const oi_shape *shape)
{
    (void)shape;
    oi_target_missing("oi_shape_check");
    return STUB_ERR;
}
#endif
#ifdef STUB_oi_shape_builtin
const oi_shape *oi_shape_builtin(int index)
{
    (void)index;
    oi_target_missing("oi_shape_builtin");
    return NULL;
}
#endif
#ifdef STUB_oi_shape_find
const oi_shape *oi_shape_find(const char *name)
{
    (void)name;
    oi_target_missing("oi_shape_find");
    return NULL;
}
#endif
#ifdef STUB_oi_facet_brdf
oi_real oi_facet_brdf(const oi_facet *facet, const oi_real to_source[3],
                      const oi_real to_observer[3])
{
    (void)facet;
    (void)to_source;
    (void)to_observer;
    oi_target_missing("oi_facet_brdf");
    return 0;
}
#endif
#ifdef STUB_oi_earthshine_plate
int oi_earthshine_plate(oi_real theta, oi_real h_km, const oi_real normal[3],
                        const oi_model *model, oi_real *irradiance)
{
    (void)theta;
    (void)h_km;
    (void)normal;
    (void)model;
    oi_target_missing("oi_earthshine_plate");
    if (irradiance) *irradiance = 0;
    return STUB_ERR;
}
#endif
#endif /* OI_NO_FACETS */

/* ISO C forbids an empty translation unit. */
typedef int oi_stubs_nonempty;
