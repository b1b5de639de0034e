/* SPDX-License-Identifier: MIT */
/*
 * sources_internal.h: private to the runtime (not part of the API):
 * the light-source layer (src/sources/): earthshine (tables, angular
 * distribution, albedo models), the Lambert phase, the sky light, the local
 * frame of the Earth's light.
 * A layer calls only the layers below it (docs/architecture.md); this
 * header includes the one below, so a file sees its layer and every lower one.
 */
#ifndef OI_SOURCES_INTERNAL_H
#define OI_SOURCES_INTERNAL_H

#include "shadow/shadow_internal.h"

/*
 * oi_earthshine (src/sources/earthshine.c) for callers that already hold a resolved
 * model and non-NULL phi, psi: same results and statuses, the model is not
 * validated again. cos_theta, sin_theta: the cosine and sine theta was formed
 * from (theta = atan2(sin, cos) of unit vectors), used instead of OI_COS and
 * OI_SIN where needed; cos_theta > 1 means not given.
 */
int oi__earthshine(oi_real theta, oi_real cos_theta, oi_real sin_theta, oi_real h_km,
                   const oi_model *resolved, oi_real *phi, oi_real *psi);

/* oi_lambert_phase (src/sources/phase.c) for a caller that holds cos(xi) and
 * sin(xi) of the same angle (e.g. the dot and cross products of two unit
 * vectors, xi = atan2(sin, cos)): used where the closed form needs them
 * (pi - xi >= 1), so no cosine or sine is evaluated. cos_xi > 1: not given. */
oi_real oi__lambert_phase_cs(oi_real xi, oi_real cos_xi, oi_real sin_xi);

#ifndef OI_NO_SKYLIGHT
/* The scattered-sunlight table (src/sources/skylight.c): 1 when a caller's table
 * passes the checks of oi_sky_table_default's contract; the table a resolved
 * model uses (*t NULL: none; OI_ERR_MODEL for an invalid caller's table);
 * the lookup at theta in [0, pi] and distance r_km (OI_WARN_TABLE_RANGE
 * below the first row). */
int oi__sky_table_valid(const oi_sky_table *t);
int oi__sky_table_of(const oi_model *m, const oi_sky_table **t);
int oi__sky_lookup(const oi_sky_table *t, oi_real theta, oi_real r_km, oi_real *e_over_sun,
                   oi_real *psi);
#endif

/* The earthshine angular table of a resolved model whose sphere reflects
 * earthshine from its angular distribution (src/sources/earthshine_angular.c;
 * non-NULL for the cubature and the table's moments): NULL for the mean direction
 * (earth_reflection = OI_EARTH_REFLECT_MEAN, the Lambert far field, or the
 * table compiled out). */
const oi_earth_angular_table *oi__earth_angular_of(const oi_model *m);

#if !defined(OI_NO_EARTH_ANGULAR) && !defined(OI_NO_EARTH_TABLE)
/* S(o) = F / phi, the shape of a Lambertian sphere's flux under earthshine
 * towards the unit direction o of the local frame (z zenith, x towards the
 * Sun's side), under the resolved model m (the cubature, or the table's
 * moments with OI_EARTH_REFLECT_TABLE) at theta (with its cosine and sine;
 * theta is OI_ATAN2(sin_theta, cos_theta), bit for bit: the cubature's
 * break at the terminator takes it) and h_km above an Earth of radius R,
 * phi the caller's scalar irradiance
 * (the cubature's flux is F = phi S): returns 1 with *shape >= 0, or 0
 * (shape 0) below the table's first row (src/sources/earthshine_angular.c). */
int oi__earth_sphere_shape(const oi_model *m, oi_real theta, oi_real cos_theta,
                           oi_real sin_theta, oi_real h_km, oi_real R, const oi_real o[3],
                           oi_real phi, oi_real *shape);
#endif

/* The local frame of the Earth's light at the target (src/sources/local_frame.c). */
void oi__local_frame_toward(const oi_real target_km[3], const oi_real sun_km[3],
                            const oi_real *hint, oi_real r_hat[3], oi_real s_hat[3],
                            oi_real x[3], oi_real y[3]);
void oi__local_frame(const oi_real target_km[3], const oi_real sun_km[3], oi_real r_hat[3],
                     oi_real s_hat[3], oi_real x[3], oi_real y[3]);

#ifndef OI_NO_ALBEDO_MODELS
/* The Earth's albedo field of a resolved model and a scene, ready to be
 * sampled (src/sources/albedo_field.c): the Knocke model's degree-1 coefficient at
 * the scene's epoch, or the map and the Greenwich meridian's cosine and
 * sine. */
typedef struct oi__albedo_field {
    int model;           /* OI_ALBEDO_KNOCKE or OI_ALBEDO_MAP */
    oi_real a1;          /* Knocke: a1(t) */
    const float *map;    /* map: the caller's grid */
    int n_lat, n_lon;
    oi_real cos_rot, sin_rot; /* map: Greenwich meridian from the frame's x axis */
} oi__albedo_field;

/* Prepare f for the non-uniform model of m and scene s (its epoch_jd and
 * earth_rotation_rad already checked by oi_illuminate). */
void oi__albedo_field_init(const oi_model *m, const oi_scene *s, oi__albedo_field *f);

/* The albedo at the unit surface point p (the scene's frame, z the rotation
 * axis), in [0, 1]: OI_OK, or OI_ERR_ALBEDO for a map value read that is NaN
 * or outside [0, 1] (*a then 0). */
int oi__albedo_at(const oi__albedo_field *f, const oi_real p[3], oi_real *a);

/* Sums over the lit visible cap: weights K (the uniform sphere's
 * earthshine), K da (da the albedo less the reference), the same times the
 * direction omega (target to surface) and times the sphere's phase towards
 * the observer; varies: some da was not 0. */
typedef struct oi__albedo_sums {
    oi_real s0, s1, q, p;
    oi_real w[3], v[3];
    int varies;
} oi__albedo_sums;

/* One earthshine evaluation under a non-uniform albedo field: the field,
 * the target's unit position r_hat and x = R / r, the Sun's unit direction
 * s_hat, the unit direction to the observer (has_obs 0: none), the
 * reference albedo and the sums. Held in one frame by the caller, so that
 * the integrators' frames are not stacked under copies of them. */
typedef struct oi__albedo_job {
    oi__albedo_field f;
    oi_real r_hat[3], s_hat[3], obs_hat[3];
    oi_real x, a_ref;
    int has_obs;
    oi__albedo_sums acc;
} oi__albedo_job;

/* Earthshine under a non-uniform albedo field (src/sources/earthshine_albedo.c), in
 * two steps so that the caller's frame, which holds the job, is the only one
 * above the integrators. oi__albedo_integrate: job->a_ref (the albedo under
 * the target) and the sums job->acc over the lit visible cap, for job's f,
 * r_hat, s_hat, obs_hat (has_obs) and x; OI_OK or OI_ERR_ALBEDO.
 * oi__albedo_mean, after it: *albedo the earthshine-weighted mean albedo
 * over the lit visible cap; dir: given the uniform sphere's mean incidence
 * direction, returned with the field's change; *shape_add: the change of the
 * sphere's shape S(o) = F / phi per unit mean albedo (0 without observer). */
int oi__albedo_integrate(oi__albedo_job *job);
void oi__albedo_mean(const oi__albedo_job *job, oi_real *albedo, oi_real dir[3],
                     oi_real *shape_add);

/* The sums under a map model, patch by patch of its bilinear field
 * (src/sources/earthshine_albedo_map.c), added to job->acc (w and v in the scene's
 * frame) with da from job->a_ref; job's r_hat, s_hat and obs_hat are left
 * in the Earth-fixed frame. OI_OK or OI_ERR_ALBEDO. */
int oi__earthshine_map_cells(oi__albedo_job *job);
#endif

/* The earthshine table's lookup (src/sources/earthshine_table.c). */
/* 1 when a caller's earthshine table has a format, kind and grid the lookup
 * can use (include/orbillum.h, oi_model.earth_table), else 0. No double
 * arithmetic: the single-precision build pulls in no software double. */
int oi__earth_table_valid(const oi_earth_table *t);

/*
 * phi and psi from table t (valid, or the trusted default) at theta in
 * [0, pi - w) inside the table's altitude range: x = R / r, w = acos(x),
 * fw the fractional altitude index (w - w_min) / (w_max - w_min) (n_alt -
 * 1); cos_theta, sin_theta as for oi__earthshine (cos_theta > 1: not
 * given). Sets *phi >= 0 and *psi.
 */
void oi__earth_interp(const oi_earth_table *t, oi_real theta, oi_real cos_theta,
                      oi_real sin_theta, oi_real x, oi_real w, oi_real fw, oi_real *phi,
                      oi_real *psi);

#endif /* OI_SOURCES_INTERNAL_H */
