/* SPDX-License-Identifier: MIT */
/*
 * expose_batch.c: the exposure batches, oi_expose_batch and oi_expose_scene_batch
 * with their outputs masks (oi_expose_batch_outputs, oi_expose_scene_batch_outputs):
 * the exposure over caller-owned arrays with an outputs mask
 * (include/orbillum/batch.h). The camera, the model and the goal's parts
 * are checked and formed once; each row goes through the single call's own
 * functions (src/camera/expose.c, src/scene/expose_scene.c), told what to compute.
 */
#include "batch/batch_internal.h"

#ifndef OI_NO_EXPOSURE

/* The batch's arrays (n > 0, none NULL): OI_OK, or OI_ERR_INPUT for one
 * misaligned or too long, or an output (out, status) overlapping an input
 * (the first, and the second when in2 is not NULL) or the other output. */
static int check_arrays(long n, const void *in1, size_t size1, size_t align1, const void *in2,
                        size_t size2, size_t align2, const oi_exposure *out, const int *status)
{
    oi__span in[2], o[2];
    const int n_in = in2 != NULL ? 2 : 1;
    if (!oi__span_of(in1, n, size1, align1, &in[0]) ||
        (in2 != NULL && !oi__span_of(in2, n, size2, align2, &in[1])) ||
        !oi__span_of(out, n, sizeof *out, OI_ALIGN_OF(oi_exposure), &o[0]) ||
        !oi__span_of(status, n, sizeof *status, OI_ALIGN_OF(int), &o[1]))
        return OI_ERR_INPUT;
    return oi__check_overlap(in, n_in, o, 2);
}

/* n, the required pointers, the arrays and the mask, in that order: OI_OK
 * or the batch's error (statuses set, outputs zeroed where they can be
 * written). */
static int batch_setup(long n, const oi_camera *camera, const void *in1, size_t size1,
                       size_t align1, const void *in2, size_t size2, size_t align2,
                       unsigned outputs, oi_exposure *out, int *status)
{
    if (n < 0 || n > OI_BATCH_MAX) return OI_ERR_INPUT; /* nothing written: n is not the arrays' */
    if (camera == NULL || in1 == NULL || out == NULL || status == NULL ||
        (size2 != 0 && in2 == NULL))
        return oi__batch_fail(OI_ERR_NULL, n, status, out, sizeof *out, 0);
    if (check_arrays(n, in1, size1, align1, in2, size2, align2, out, status) != OI_OK)
        return oi__batch_fail(OI_ERR_INPUT, n, status, out, sizeof *out, 0);
    if ((outputs & ~(unsigned)OI_EXPOSE_ALL) != 0u)
        return oi__batch_fail(OI_ERR_FLAGS, n, status, out, sizeof *out, 1);
    return OI_OK;
}

/* The fields of a computed row the mask leaves out, set to 0. */
static void clear_unasked(unsigned outputs, oi_exposure *out)
{
    unsigned drop = 0u;
    if ((outputs & OI_EXPOSE_SETTING) == 0u) {
        out->exposure_s = 0;
        out->gain = 0;
        out->time_index = 0;
        out->gain_index = 0;
        out->signal_e = 0;
        out->background_e = 0;
        out->peak_e = 0;
        out->saturation_e = 0;
        out->fill = 0;
        out->snr = 0;
        out->trail_px = 0;
        out->trail_factor = 0;
        drop |= OI_FLAG_SATURATED | OI_FLAG_BACKGROUND_SATURATED;
    }
    if ((outputs & OI_EXPOSE_FAINT) == 0u) drop |= OI_FLAG_TOO_FAINT;
    if ((outputs & (OI_EXPOSE_SETTING | OI_EXPOSE_FAINT)) == 0u) drop |= OI_FLAG_TRAILED;
    out->flags &= ~drop;
    if ((outputs & OI_EXPOSE_DETECT) == 0u) {
        out->signal_min_e = 0;
        out->detect_margin_mag = 0;
    }
    if ((outputs & OI_EXPOSE_SUN_ANGLE) == 0u) out->sun_angle_rad = 0;
    if ((outputs & OI_EXPOSE_BACKGROUND) == 0u) out->background_w_m2_sr = 0;
    if ((outputs & OI_EXPOSE_RATE) == 0u) out->rate_rad_s = 0;
}

/* A computed row with its status st: zeroed when st is an error (1 is
 * returned, the batch's count of such rows), else the fields the mask
 * leaves out cleared (0). */
static long settle_row(int st, unsigned outputs, oi_exposure *out)
{
    if (st < 0) {
        memset(out, 0, sizeof *out);
        return 1;
    }
    clear_unasked(outputs, out);
    return 0;
}

/* Out of line (OI_NOINLINE): the wrappers below call the masked batches
 * as they would from another file, so neither is split into them. */
OI_NOINLINE int oi_expose_batch_outputs(long n, const oi_camera *camera, const oi_expose_in *in,
                            const oi_expose_goal *goal, unsigned outputs, oi_exposure *out,
                            int *status)
{
    oi__expose_plan plan;
    unsigned need;
    long i, bad = 0;
    int st;
    if (n == 0) return 0;
    st = batch_setup(n, camera, in, sizeof *in, OI_ALIGN_OF(oi_expose_in), NULL, 0, 1, outputs, out,
                     status);
    if (st < 0) return st;
    if (!oi__camera_valid(camera))
        return oi__batch_fail(OI_ERR_CAMERA, n, status, out, sizeof *out, 1);
    oi__expose_plan_make(camera, goal, &plan);
    need = oi__expose_need(outputs);
    for (i = 0; i < n; i++) {
        memset(&out[i], 0, sizeof out[i]);
        status[i] = oi__expose_planned(camera, &plan, goal, &in[i], need, &out[i]);
        bad += settle_row(status[i], outputs, &out[i]);
    }
    return (int)bad;
}

OI_NOINLINE int oi_expose_scene_batch_outputs(long n, const oi_camera *camera, const oi_scene *scenes,
                                  const oi_illum *illum, const oi_model *model,
                                  const oi_expose_goal *goal, unsigned outputs,
                                  oi_exposure *out, int *status)
{
    oi__expose_scene_batch b;
    long i, bad = 0;
    int st;
    if (n == 0) return 0;
    st = batch_setup(n, camera, scenes, sizeof *scenes, OI_ALIGN_OF(oi_scene), illum, sizeof *illum,
                     OI_ALIGN_OF(oi_illum), outputs, out, status);
    if (st < 0) return st;
    st = oi__expose_scene_setup(camera, model, goal, outputs, &b);
    if (st < 0) return oi__batch_fail(st, n, status, out, sizeof *out, 1);
    for (i = 0; i < n; i++) {
        memset(&out[i], 0, sizeof out[i]);
        status[i] = oi__expose_scene_row(camera, &scenes[i], &illum[i], model, goal, &b, &out[i]);
        bad += settle_row(status[i], outputs, &out[i]);
    }
    return (int)bad;
}

/* The exposure batches without a mask: every output. */
int oi_expose_batch(long n, const oi_camera *camera, const oi_expose_in *in,
                    const oi_expose_goal *goal, oi_exposure *out, int *status)
{
    return oi_expose_batch_outputs(n, camera, in, goal, OI_EXPOSE_ALL, out, status);
}

int oi_expose_scene_batch(long n, const oi_camera *camera, const oi_scene *scenes,
                          const oi_illum *illum, const oi_model *model,
                          const oi_expose_goal *goal, oi_exposure *out, int *status)
{
    return oi_expose_scene_batch_outputs(n, camera, scenes, illum, model, goal, OI_EXPOSE_ALL, out,
                                         status);
}

#endif /* OI_NO_EXPOSURE */
