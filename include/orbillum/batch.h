/* SPDX-License-Identifier: MIT */
/*
 * orbillum/batch.h: the batch calls: the single calls over caller-owned arrays
 * of n rows, their statuses and outputs masks.
 *
 * A section of orbillum.h, the header a program includes (it includes every
 * section); compiles alone, and includes the sections it uses.
 */
#ifndef ORBILLUM_BATCH_H
#define ORBILLUM_BATCH_H

#include "base.h"
#include "model.h"
#include "shadow.h"
#include "scene.h"
#include "camera.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- batch */

/*
 * Batch calls: the single calls above over caller-owned arrays of n rows, the
 * model (and camera) validated once per batch. Row i of every output is, bit
 * for bit, what the single call returns for row i of the inputs (the fields
 * an outputs mask leaves out are 0). Arrays of the existing structures and
 * of oi_real (positions: 3 n values, x y z of row 0 first); src/batch/batch.c.
 *
 * Returned (function value): the number of rows whose status is an error
 * (0: every row computed; warnings do not count), or a batch error, every
 * status[i] then set to it and every output row zeroed where the pointers
 * allow:
 *   OI_ERR_NULL    a required array is NULL (with n > 0)
 *   OI_ERR_INPUT   n < 0 or n > OI_BATCH_MAX (then nothing is written, not
 *                  even status); an array not aligned for its element
 *                  type; an output array overlapping an input array or
 *                  another output (the contract forbids it: rows would
 *                  change under the call)
 *   OI_ERR_MODEL, OI_ERR_RADIUS, OI_ERR_CAMERA  the model or the camera is
 *                  invalid (as the single call)
 * n = 0 does nothing and returns 0 (NULL arrays allowed).
 * status[i]: the single call's status for row i (a NaN row gets
 * OI_ERR_NONFINITE and a zeroed output row, the others are computed).
 */
#define OI_BATCH_MAX (1073741824L) /* 2^30 rows per call */

/* Outputs mask of oi_sun_fraction_batch (bits);
 * fraction and region are always formed. */
#define OI_BATCH_FRACTION_LD (1u) /* oi_shadow.fraction_ld */
#define OI_BATCH_ATMOSPHERE  (2u) /* oi_shadow.fraction_atm (the atmosphere and its
                                     OI_WARN_TABLE_RANGE; without: 0, the atmosphere
                                     not consulted) */
#define OI_BATCH_GEOMETRY    (4u) /* oi_shadow.sun_radius_rad, earth_radius_rad,
                                     separation_rad, sun_distance_km */
#define OI_BATCH_ALL (OI_BATCH_FRACTION_LD | OI_BATCH_ATMOSPHERE | OI_BATCH_GEOMETRY)

/* oi_sun_fraction over n rows: sun_km, point_km 3 n values each; out[n],
 * status[n]. outputs: OI_BATCH_* bits (unknown bits: OI_ERR_FLAGS for the
 * batch). Cost: without OI_BATCH_FRACTION_LD and OI_BATCH_ATMOSPHERE the
 * limb-darkened integral is skipped (the uniform disc's fraction alone);
 * without OI_BATCH_GEOMETRY a point certainly in full sunlight (outside the
 * Earth's disc enlarged by 200 km, by 1e-6 in cosine) is answered from
 * its cosines, without the three arctangents (docs/performance.md). */
int oi_sun_fraction_batch(long n, const oi_real *sun_km, const oi_real *point_km,
                          const oi_model *model, unsigned outputs, oi_shadow *out,
                          int *status);

/* oi_earthshine over n rows: theta[n], h_km[n] in; phi[n] out; psi[n] out
 * or NULL (not wanted); status[n]. */
int oi_earthshine_batch(long n, const oi_real *theta, const oi_real *h_km,
                        const oi_model *model, oi_real *phi, oi_real *psi, int *status);

/* oi_illuminate over n scenes: scenes[n] in, out[n], status[n]. */
int oi_illuminate_batch(long n, const oi_scene *scenes, const oi_model *model,
                        oi_illum *out, int *status);

/* Outputs mask of oi_illuminate_batch_outputs (bits, with OI_BATCH_FRACTION_LD
 * for shadow.fraction_ld and OI_BATCH_GEOMETRY for the shadow's four angles
 * and distance; OI_BATCH_ATMOSPHERE is accepted and changes nothing there:
 * shadow.fraction_atm and e_sun are the scene's sunlight, always formed). */
#define OI_BATCH_DIRECTIONS  (8u)  /* dir_sun, dir_earth, dir_moon, dir_sky */
#define OI_BATCH_OBSERVER    (16u) /* what the observer receives: phase_*, flux_*,
                                      flux_obs, flux_specular, mag_v, range_km */
#define OI_BATCH_SCENE_ALL (OI_BATCH_ALL | OI_BATCH_DIRECTIONS | OI_BATCH_OBSERVER)

/* oi_illuminate over n scenes with an outputs mask: scenes[n] in, out[n],
 * status[n]; outputs OI_BATCH_* bits within OI_BATCH_SCENE_ALL (others:
 * OI_ERR_FLAGS for the batch). Every field asked for (and every field no bit
 * names: the irradiances e_*, shadow.fraction, fraction_atm and region, the
 * Earth's and the Moon's angles and fractions, earth_albedo_eff) is the
 * single call's bits; the fields left out are 0, and what only they need is
 * not computed: without OI_BATCH_GEOMETRY a target certainly in full
 * sunlight (or, without the atmosphere, certainly in the umbra) is answered
 * from cosines (as oi_sun_fraction_batch), without OI_BATCH_FRACTION_LD the
 * limb-darkened integral runs only where the model's sunlight needs it,
 * without OI_BATCH_OBSERVER the observer's term is not formed (its position
 * is still checked, with the single call's statuses; the observer inside
 * the target, OI_ERR_OBSERVER_AT_TARGET, is then not detected). With
 * OI_BATCH_SCENE_ALL every row is oi_illuminate's. src/scene/illuminate_outputs.c,
 * docs/performance.md. */
int oi_illuminate_batch_outputs(long n, const oi_scene *scenes, const oi_model *model,
                                unsigned outputs, oi_illum *out, int *status);

#ifndef OI_NO_EXPOSURE
/* oi_expose over n rows, one camera and goal: in[n], out[n], status[n]. */
int oi_expose_batch(long n, const oi_camera *camera, const oi_expose_in *in,
                    const oi_expose_goal *goal, oi_exposure *out, int *status);

/* oi_expose_scene over n rows: scenes[n], illum[n] (oi_illuminate_batch's
 * out) in, out[n], status[n]. A scene without observer gets OI_ERR_NULL in
 * its row (as the single call). */
int oi_expose_scene_batch(long n, const oi_camera *camera, const oi_scene *scenes,
                          const oi_illum *illum, const oi_model *model,
                          const oi_expose_goal *goal, oi_exposure *out, int *status);

/* Outputs mask of oi_expose_batch_outputs and oi_expose_scene_batch_outputs
 * (bits). Always formed: status and flags' geometric bits (every OI_FLAG_*
 * but TOO_FAINT, SATURATED, BACKGROUND_SATURATED and TRAILED). */
#define OI_EXPOSE_SETTING    (1u)  /* the choice: exposure_s, gain, time_index,
                                      gain_index, signal_e, background_e, peak_e,
                                      saturation_e, fill, snr, trail_px,
                                      trail_factor; OI_FLAG_SATURATED,
                                      OI_FLAG_BACKGROUND_SATURATED */
#define OI_EXPOSE_FAINT      (2u)  /* OI_FLAG_TOO_FAINT (at rest: one SNR; moving:
                                      the highest gain's allowed times), without
                                      the search */
#define OI_EXPOSE_DETECT     (4u)  /* signal_min_e, detect_margin_mag (the setting is
                                      searched for them) */
#define OI_EXPOSE_SUN_ANGLE  (8u)  /* sun_angle_rad (without: OI_FLAG_SUN_EXCLUSION
                                      decided from a cosine where it is certain) */
#define OI_EXPOSE_BACKGROUND (16u) /* background_w_m2_sr */
#define OI_EXPOSE_RATE       (32u) /* rate_rad_s */
#define OI_EXPOSE_ALL (OI_EXPOSE_SETTING | OI_EXPOSE_FAINT | OI_EXPOSE_DETECT | OI_EXPOSE_SUN_ANGLE | OI_EXPOSE_BACKGROUND | OI_EXPOSE_RATE)

/* oi_expose_batch and oi_expose_scene_batch with an outputs mask (OI_EXPOSE_*
 * bits; others: OI_ERR_FLAGS for the batch, checked before the model and
 * the camera). OI_FLAG_TRAILED comes with OI_EXPOSE_SETTING or
 * OI_EXPOSE_FAINT. Every field asked for, and the status, is the single
 * call's bits; the fields left out are 0, and what only they need is not
 * computed: without OI_EXPOSE_SETTING and OI_EXPOSE_DETECT no search, without
 * OI_EXPOSE_FAINT no detection test at the longest time (moving: no trail
 * over the highest gain's times), without OI_EXPOSE_SUN_ANGLE no arctangent
 * where the Sun is certainly inside or outside the exclusion angle, without
 * the choice's bits (SETTING, FAINT, DETECT): no angular rate unless
 * OI_EXPOSE_RATE, and no sky terms (zodiacal light, starlight, the limb's
 * scattered sunlight) unless OI_EXPOSE_BACKGROUND (the background's checks,
 * OI_ERR_NONFINITE and OI_ERR_INPUT, then not made). The goal's defaults, detection rule and
 * sensor temperature, the camera and the model are formed once per batch.
 * In oi_expose_batch_outputs background_w_m2_sr and rate_rad_s are the
 * input's and OI_EXPOSE_SUN_ANGLE changes nothing (sun_angle_rad is 0).
 * With OI_EXPOSE_ALL every row is the single call's. src/batch/expose_batch.c,
 * docs/camera.md "Batches and their outputs mask". */
int oi_expose_batch_outputs(long n, const oi_camera *camera, const oi_expose_in *in,
                            const oi_expose_goal *goal, unsigned outputs, oi_exposure *out,
                            int *status);
int oi_expose_scene_batch_outputs(long n, const oi_camera *camera, const oi_scene *scenes,
                                  const oi_illum *illum, const oi_model *model,
                                  const oi_expose_goal *goal, unsigned outputs,
                                  oi_exposure *out, int *status);
#endif /* OI_NO_EXPOSURE */

#ifdef __cplusplus
}
#endif

#endif /* ORBILLUM_BATCH_H */
