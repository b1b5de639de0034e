/* SPDX-License-Identifier: MIT */
/*
 * camera.c: the camera's validity check (every camera, built-in or the
 * caller's) and the look-up of a built-in camera by name. The built-in
 * cameras themselves are data: src/camera/camera_builtin.c.
 */
#include "camera/camera_internal.h"

#ifndef OI_NO_EXPOSURE

/* Valid ranges of the camera fields. They are wide enough for any real
 * instrument and narrow enough that no intermediate value can overflow in
 * single precision (the largest electron count is below 1e37). */
#define CAM_APERTURE_MAX_M   OI_R(10.0)
#define CAM_FOCAL_MIN_M      OI_R(1e-3)
#define CAM_FOCAL_MAX_M      OI_R(1e3)
#define CAM_PITCH_MIN_M      OI_R(1e-7)
#define CAM_PITCH_MAX_M      OI_R(1e-3)
#define CAM_PHOTON_MIN_J     OI_R(1e-20)   /* 20 um */
#define CAM_PHOTON_MAX_J     OI_R(1e-17)   /* 20 nm */
#define CAM_FULL_WELL_MIN_E  OI_R(1.0)
#define CAM_FULL_WELL_MAX_E  OI_R(1e9)
#define CAM_DARK_MAX_E_S     OI_R(1e9)
#define CAM_TIME_MAX_S       OI_R(1e4)
#define CAM_GAIN_MAX         OI_R(1e3)
#define CAM_READ_NOISE_MAX_E OI_R(1e6)
#define CAM_TRAIL_MAX_PX     OI_R(1e6)
#define CAM_FALSE_ALARM_MIN  OI_R(1e-15) /* a threshold of 7.9 sigma */
#define CAM_DETECT_P_MAX     OI_R(0.999999)
#define CAM_TEMP_ABS_MAX_C   OI_R(150.0)  /* sensor temperatures (deg C) */
#define CAM_DOUBLING_MIN_C   OI_R(1.0)
#define CAM_DOUBLING_MAX_C   OI_R(100.0)
#define CAM_DOUBLINGS_MAX    OI_R(30.0)   /* dark factor within 2^+-30 over the rated range */

/* The temperature model (include/orbillum.h, oi_expose Note 4): all four
 * fields 0 (none), or a doubling in [1, 100] deg C, temperatures in
 * [-150, 150] deg C, min <= max, the range within CAM_DOUBLINGS_MAX
 * doublings of the reference (so the dark current stays within 2^30 of
 * dark_current_e_s: no overflow in single precision). */
static int temperature_valid(const oi_camera *c)
{
    const oi_real t = CAM_TEMP_ABS_MAX_C;
    oi_real span;
    if (c->dark_doubling_c == 0) {
        return c->dark_ref_temp_c == 0 && c->temp_min_c == 0 && c->temp_max_c == 0;
    }
    if (!oi__in_closed(c->dark_doubling_c, CAM_DOUBLING_MIN_C, CAM_DOUBLING_MAX_C) ||
        !oi__in_closed(c->dark_ref_temp_c, -t, t) || !oi__in_closed(c->temp_min_c, -t, t) ||
        !oi__in_closed(c->temp_max_c, c->temp_min_c, t)) {
        return 0;
    }
    span = CAM_DOUBLINGS_MAX * c->dark_doubling_c;
    return islessequal(c->temp_max_c - c->dark_ref_temp_c, span) &&
           islessequal(c->dark_ref_temp_c - c->temp_min_c, span);
}

/*
 * oi__camera_valid: nonzero when every field of the camera is in range (the
 * ranges of oi_expose in include/orbillum.h). Every camera is checked, the
 * built-in ones too (the check is the same for the caller's own camera,
 * which is what a flight program uses). One pass over the times and one
 * over the gains: "strictly ascending from 0" is the lower bound of every
 * element and the upper bound is tested on the last one only (the same
 * conditions as element by element; NaN fails every comparison).
 */
int oi__camera_valid(const oi_camera *c)
{
    int i, n;
    oi_real prev, x;
    const oi_real one = OI_R(1.0);
    if (!oi__in_open_closed(c->aperture_m, 0, CAM_APERTURE_MAX_M) ||
        !oi__in_closed(c->focal_length_m, CAM_FOCAL_MIN_M, CAM_FOCAL_MAX_M) ||
        !oi__in_closed(c->pixel_pitch_m, CAM_PITCH_MIN_M, CAM_PITCH_MAX_M) ||
        !oi__in_open_closed(c->transmission, 0, one) ||
        !oi__in_open_closed(c->quantum_efficiency, 0, one) ||
        !oi__in_open_closed(c->band_fraction, 0, one) ||
        !oi__in_closed(c->photon_energy_j, CAM_PHOTON_MIN_J, CAM_PHOTON_MAX_J) ||
        !oi__in_closed(c->full_well_e, CAM_FULL_WELL_MIN_E, CAM_FULL_WELL_MAX_E) ||
        !oi__in_closed(c->dark_current_e_s, 0, CAM_DARK_MAX_E_S) ||
        !oi__in_open_closed(c->psf_peak_fraction, 0, one) ||
        !oi__in_open_closed(c->fov_rad, 0, OI_PI_R) ||
        !oi__in_closed(c->sun_exclusion_rad, 0, OI_PI_R) ||
        !oi__in_closed(c->max_trail_px, 0, CAM_TRAIL_MAX_PX) ||
        !(c->detect_false_alarm == 0 ||
          (isgreaterequal(c->detect_false_alarm, CAM_FALSE_ALARM_MIN) &&
           isless(c->detect_false_alarm, OI_R(0.5)))) ||
        !(c->detect_probability == 0 ||
          oi__in_closed(c->detect_probability, OI_R(0.5), CAM_DETECT_P_MAX)) ||
        !temperature_valid(c) ||
        c->n_times < 1 || c->n_times > OI_CAMERA_MAX_TIMES ||
        c->n_gains < 1 || c->n_gains > OI_CAMERA_MAX_GAINS) {
        return 0;
    }
    n = c->n_times;
    prev = 0;
    for (i = 0; i < n; i++) {
        x = c->times_s[i];
        if (!isgreater(x, prev)) return 0; /* quiet comparisons: NaN fails */
        prev = x;
    }
    if (!islessequal(prev, CAM_TIME_MAX_S)) return 0;
    n = c->n_gains;
    prev = 0;
    for (i = 0; i < n; i++) {
        x = c->gains[i];
        if (!isgreater(x, prev) || !oi__in_closed(c->read_noise_e[i], 0, CAM_READ_NOISE_MAX_E)) return 0;
        prev = x;
    }
    return islessequal(prev, CAM_GAIN_MAX);
}

/* Exact, case-sensitive string equality (no libc string functions). */
static int same_name(const char *a, const char *b)
{
    while (*a != '\0' && *a == *b) {
        a++;
        b++;
    }
    return *a == *b;
}

/*
 * oi_camera_find: a built-in camera by name.
 *
 * Given:
 *   name     const char *  NUL-terminated name, exact and case-sensitive
 *                          (e.g. "star-tracker", "telescope-15cm")
 *
 * Returned (function value):
 *            const oi_camera *  the camera; NULL when name is NULL or no
 *                               built-in camera has that name.
 */
const oi_camera *oi_camera_find(const char *name)
{
    int i;
    const oi_camera *c;
    if (name == NULL) return NULL;
    for (i = 0; (c = oi_camera_builtin(i)) != NULL; i++) {
        if (same_name(c->name, name)) return c;
    }
    return NULL;
}

#endif /* OI_NO_EXPOSURE */
