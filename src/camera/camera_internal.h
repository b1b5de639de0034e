/* SPDX-License-Identifier: MIT */
/*
 * camera_internal.h: private to the runtime (not part of the API):
 * the camera layer (src/camera/): camera checks, the exposure choice,
 * detection, trailing, the sky backgrounds.
 * A layer calls only the layers below it (docs/architecture.md); this
 * header includes the one below, so a file sees its layer and every lower one.
 */
#ifndef OI_CAMERA_INTERNAL_H
#define OI_CAMERA_INTERNAL_H

#include "target/target_internal.h"

#ifndef OI_NO_EXPOSURE
/* Nonzero when every field of the camera is in range (src/camera/camera.c). */
int oi__camera_valid(const oi_camera *c);

/* oi_expose's choice for a camera that passed oi__camera_valid, out zeroed
 * (src/camera/expose.c); same statuses as oi_expose after its camera check. */
int oi__expose_valid(const oi_camera *camera, const oi_expose_in *in,
                     const oi_expose_goal *goal, oi_exposure *out);

/* The part of oi_expose's choice that depends on the camera and the goal
 * only, formed once per batch (src/camera/expose.c): the goal's defaults and status
 * (a row's statuses come after it), the detection rule, the dark current at
 * the goal's temperature and its status (after a row's own checks). */
typedef struct {
    oi_real goal_fill, snr_min; /* the goal, defaults filled in */
    oi_real det_k, det_z;       /* the detection rule (src/camera/expose.c detect_rule) */
    oi_real dark;               /* dark current (e-/s) at the goal's temperature */
    int goal_st, dark_st;       /* their statuses */
} oi__expose_plan;

/* What oi__expose_planned computes (bits): the search of the setting (with
 * the detection margin and the well's flags, OI_FLAG_SATURATED and
 * OI_FLAG_BACKGROUND_SATURATED, which read the detection test at the most
 * sensitive setting) and OI_FLAG_TOO_FAINT. */
#define OI__EXPOSE_SEARCH (1u)
#define OI__EXPOSE_FAINT  (2u)

/* What an outputs mask (OI_EXPOSE_*) needs of the choice: OI__EXPOSE_* bits. */
static inline unsigned oi__expose_need(unsigned outputs)
{
    return ((outputs & (OI_EXPOSE_SETTING | OI_EXPOSE_DETECT)) != 0u ? OI__EXPOSE_SEARCH : 0u) |
           ((outputs & OI_EXPOSE_FAINT) != 0u ? OI__EXPOSE_FAINT : 0u);
}

void oi__expose_plan_make(const oi_camera *camera, const oi_expose_goal *goal,
                          oi__expose_plan *p);
/* oi__expose_valid with the plan made (p NULL: from goal, as the single
 * call); out zeroed, need: OI__EXPOSE_* bits (the fields need leaves out
 * stay 0 or partial: the batch clears them). */
int oi__expose_planned(const oi_camera *camera, const oi__expose_plan *p,
                       const oi_expose_goal *goal, const oi_expose_in *in, unsigned need,
                       oi_exposure *out);


/* The Gaussian PSF's sigma (pixels) for a central-pixel fraction p in (0, 1]
 * and the trailed peak's factor for a trail of L pixels (src/camera/trail.c). */
oi_real oi__psf_sigma_px(oi_real p);
oi_real oi__trail_factor(oi_real sigma, oi_real q, oi_real trail);

/* The standard normal quantile of an upper tail in (0, 0.5], and the
 * smallest signal a detection rule accepts (src/camera/detect.c). */
oi_real oi__normal_quantile_upper(oi_real tail);
oi_real oi__signal_min_e(oi_real thr, oi_real z, oi_real c);
#endif

#endif /* OI_CAMERA_INTERNAL_H */
