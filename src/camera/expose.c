/* SPDX-License-Identifier: MIT */
/*
 * expose.c: oi_expose, the choice of exposure time and gain for a point-like
 * target of known flux, and the flag names. The contract is in
 * include/orbillum.h; the rule and the proof that the short search below is
 * the full search's choice are written out in docs/camera.md.
 */
#include "camera/camera_internal.h"

#ifndef OI_NO_EXPOSURE

/* Largest accepted background radiance (W/m^2/sr): five times the mean
 * radiance of the solar disc, TSI / (pi (R_sun / 1 AU)^2) = 2.0e7. */
#define IN_RADIANCE_MAX OI_R(1e8)

/* Defaults of the goal. */
#define GOAL_FILL_DEFAULT    OI_R(0.5)
#define GOAL_SNR_DEFAULT     OI_R(5.0)
#define GOAL_SNR_MAX         OI_R(1e6)

/* Flags that describe the geometry (kept from the input); the others are
 * computed here. */
#define FLAGS_GEOMETRIC (OI_FLAG_SUN_EXCLUSION | OI_FLAG_EARTH_IN_FOV | OI_FLAG_ECLIPSED | \
                         OI_FLAG_PENUMBRA | OI_FLAG_OCCULTED | OI_FLAG_RESOLVED | \
                         OI_FLAG_MOON_SHADOW | OI_FLAG_MOON_IN_FOV | OI_FLAG_GLINT)
#define FLAGS_ALL (FLAGS_GEOMETRIC | OI_FLAG_TOO_FAINT | OI_FLAG_SATURATED | OI_FLAG_TRAILED | \
                   OI_FLAG_BACKGROUND_SATURATED)

/* The well's flags of a chosen setting that fills it (out->fill >= 1: no
 * setting reaches the goal, include/orbillum.h "Flags with one meaning"):
 * OI_FLAG_BACKGROUND_SATURATED when the background alone fills the well
 * (background_e >= saturation_e) or the target is too faint (faint: its
 * light is not what counts), else OI_FLAG_SATURATED (the target's light
 * fills it). Never both, and never OI_FLAG_SATURATED with
 * OI_FLAG_TOO_FAINT. */
static unsigned well_flags(const oi_exposure *out, int faint)
{
    if (out->fill < OI_R(1.0)) return 0u;
    if (faint || !(out->background_e < out->saturation_e)) return OI_FLAG_BACKGROUND_SATURATED;
    return OI_FLAG_SATURATED;
}

/* Largest accepted angular rate (rad/s): far above any orbit's, small
 * enough that no trail overflows (1e3 rad/s * 1e4 s / 1e-10 rad). */
#define IN_RATE_MAX OI_R(1e3)

/* Brightest accepted target flux (W/m^2): magnitude OI_MAG_MIN at the
 * nominal TSI, OI_TSI_W_M2 * 10^(-0.4 (OI_MAG_MIN - OI_SUN_MAG_V)) =
 * 1361 * 10^1.304 = 27406.787040627104 W/m^2 exactly. The literals are
 * pow of the exponent rounded to oi_real, times the TSI, as
 * oi_flux_from_magnitude(OI_MAG_MIN) computes it: in double
 * 0x1.ac3b25edfa68fp+14 (13 ulp above the exact value: the exponent
 * -0.4 * -3.26 rounds to 1.3040000000000007); in single precision
 * 0x1.ac3b28p+14 (powf(10, 1.304f) * 1361). tests/c/test_exposure.c checks
 * both against pow. */
#ifdef OI_SINGLE_PRECISION
#define FLUX_MAX_W_M2 OI_R(27406.7890625)
#else
#define FLUX_MAX_W_M2 OI_R(27406.78704062715)
#endif

/* The search (docs/camera.md, "Cost of the search") takes the SNR at the
 * longest time j that reaches the goal as the best of its gain when
 * times_s[j] >= times_s[j-1] * TIME_SPACING: the computed SNR at j is then
 * above the computed SNR at every shorter time (proof in docs/camera.md:
 * SNR / sqrt(t) does not decrease with t, and each computed SNR is within
 * 4.5 u of the exact one, u the unit roundoff), provided that no product is
 * subnormal: the shortest time is at least TIME_FAST_MIN_S and the signal at
 * the shortest time at least SIGNAL_FAST_MIN_E (the smallest SNR is then
 * above 1e-35, as no pixel can hold more than 1e34 electrons). Otherwise
 * the times that reach the goal are scanned. TIME_SPACING is 1 + 256 u,
 * exactly representable: 1 + 2^-16 (float), 1 + 2^-45 (double). */
#ifdef OI_SINGLE_PRECISION
#define TIME_SPACING OI_R(1.0000152587890625)
#else
#define TIME_SPACING OI_R(1.0000000000000284)
#endif
#define TIME_FAST_MIN_S   OI_R(1e-30)
#define SIGNAL_FAST_MIN_E OI_R(1e-18)

/* Rates of photo-electrons in the brightest pixel (e-/s) and the goal. */
typedef struct {
    oi_real rate_s;     /* target */
    oi_real rate_b;     /* background and dark current */
    oi_real goal_fill;  /* goal fill, defaults filled in */
    oi_real snr_min;    /* goal SNR, defaults filled in */
    oi_real det_k;      /* detection threshold in background sigmas; < 0: the SNR rule */
    oi_real det_z;      /* detection margin in the target pixel's sigmas */
} expose_rates;

/* The detection rule (docs/camera.md, "Detection"): the camera's threshold
 * k = Phi^-1(1 - false_alarm) and z = Phi^-1(detect_probability) (as upper
 * tails, so that a false-alarm rate of 1e-15 keeps its digits), or the SNR
 * rule (det_k < 0, z = goal.snr_min). */
static void detect_rule(const oi_camera *c, expose_rates *r)
{
    if (c->detect_false_alarm > 0) {
        r->det_k = oi__normal_quantile_upper(c->detect_false_alarm);
        /* 1 - p is exact for p in [0.5, 1] (Sterbenz) */
        r->det_z = c->detect_probability > 0
                       ? oi__normal_quantile_upper(OI_R(1.0) - c->detect_probability)
                       : OI_R(0.0);
    } else {
        r->det_k = -1;
        r->det_z = r->snr_min;
    }
}

/* The smallest detectable signal at background b (electrons, dark
 * included) and read noise rn: the threshold k sqrt(b + rn^2) above the
 * background plus z times the target pixel's noise; the SNR rule is the
 * threshold 0 and z = snr_min (s / sqrt(s + b + rn^2) = snr_min). */
static oi_real signal_min(const expose_rates *r, oi_real b, oi_real rn)
{
    const oi_real c = b + rn * rn;
    const oi_real thr = r->det_k > 0 ? r->det_k * OI_SQRT(c) : OI_R(0.0);
    return oi__signal_min_e(thr, r->det_z, c);
}

/* Is signal s at background b and read noise rn detected? The SNR rule
 * keeps its comparison of earlier versions (snr >= snr_min). */
static int detected(const expose_rates *r, oi_real s, oi_real b, oi_real rn)
{
    oi_real var;
    if (r->det_k < 0) {
        var = s + b + rn * rn;
        return (var > 0 ? s / OI_SQRT(var) : OI_R(0.0)) >= r->snr_min;
    }
    return s >= signal_min(r, b, rn);
}

/* The chosen setting's smallest detectable signal and margin (magnitudes,
 * within +-100; OI_DETECT_MARGIN_NONE without signal). */
static OI_NOINLINE void detect_margin(const oi_camera *c, const expose_rates *r, oi_exposure *out)
{
    oi_real smin = signal_min(r, out->background_e, c->read_noise_e[out->gain_index]);
    oi_real m = (oi_real)OI_DETECT_MARGIN_NONE;
    out->signal_min_e = smin;
    if (out->signal_e > 0) {
        m = smin > 0 ? OI_R(2.5) * OI_LOG10(out->signal_e / smin) : OI_R(100.0);
        m = oi__clamp(m, (oi_real)OI_DETECT_MARGIN_NONE, OI_R(100.0));
    }
    out->detect_margin_mag = m;
}

/* The sky backgrounds this build knows (oi_expose_goal.sky). */
#ifndef OI_NO_SKY
#define SKY_ZODIACAL_BIT OI_SKY_ZODIACAL
#define SKY_STARLIGHT_BIT OI_SKY_STARLIGHT
#else
#define SKY_ZODIACAL_BIT 0u
#define SKY_STARLIGHT_BIT 0u
#endif
#ifndef OI_NO_MOON
#define SKY_MOON_BIT OI_SKY_MOON
#else
#define SKY_MOON_BIT 0u
#endif
#define SKY_ALL (SKY_ZODIACAL_BIT | SKY_MOON_BIT | SKY_STARLIGHT_BIT)

/* Goal with defaults filled in; 0 when a field is out of range. */
static int goal_resolve(const oi_expose_goal *goal, oi_real *fill, oi_real *snr_min)
{
    *fill = GOAL_FILL_DEFAULT;
    *snr_min = GOAL_SNR_DEFAULT;
    if (goal == NULL) return 1;
    if (goal->fill != 0) {
        if (!oi__in_open_closed(goal->fill, 0, OI_R(1.0))) return 0;
        *fill = goal->fill;
    }
    if (goal->snr_min != 0) {
        if (!oi__in_open_closed(goal->snr_min, 0, GOAL_SNR_MAX)) return 0;
        *snr_min = goal->snr_min;
    }
    return 1;
}

/* The goal checked: its fields (OI_ERR_INPUT), then unknown sky bits
 * (OI_ERR_FLAGS); the defaults filled into r. */
static int check_goal(const oi_expose_goal *goal, expose_rates *r)
{
    if (!goal_resolve(goal, &r->goal_fill, &r->snr_min)) return OI_ERR_INPUT;
    if (goal != NULL && (goal->sky & ~(unsigned)SKY_ALL) != 0u) return OI_ERR_FLAGS;
    return OI_OK;
}

/* The photometric input checked, in this order: non-finite values
 * (OI_ERR_NONFINITE), a negative flux (OI_ERR_INPUT), a flux brighter than
 * OI_MAG_MIN (OI_ERR_MAGNITUDE), the background (OI_ERR_INPUT), unknown flag
 * bits (OI_ERR_FLAGS), the rate (OI_ERR_NONFINITE, OI_ERR_INPUT). */
static int check_input(const oi_expose_in *in)
{
    if (!OI_ISFINITE(in->flux_w_m2) || !OI_ISFINITE(in->background_w_m2_sr)) {
        return OI_ERR_NONFINITE;
    }
    if (!(in->flux_w_m2 >= 0)) return OI_ERR_INPUT;
    if (!(in->flux_w_m2 <= FLUX_MAX_W_M2)) return OI_ERR_MAGNITUDE;
    if (!oi__in_closed(in->background_w_m2_sr, 0, IN_RADIANCE_MAX)) return OI_ERR_INPUT;
    if ((in->flags & ~(unsigned)FLAGS_ALL) != 0u) return OI_ERR_FLAGS;
    if (!OI_ISFINITE(in->rate_rad_s)) return OI_ERR_NONFINITE;
    if (!oi__in_closed(in->rate_rad_s, 0, IN_RATE_MAX)) return OI_ERR_INPUT;
    return OI_OK;
}

/* The dark current at the goal's sensor temperature (docs/camera.md,
 * "Sensor temperature"): dark_current_e_s * 2^((T - T_ref) / T_double);
 * without a temperature, dark_current_e_s itself (bit for bit). The camera's
 * check keeps the factor within 2^+-30. OI_ERR_NONFINITE for a NaN or
 * infinite temperature, OI_ERR_INPUT when the camera has no temperature
 * model or T is outside its rated range. */
static int sensor_dark(const oi_camera *c, const oi_expose_goal *goal, oi_real *dark)
{
    oi_real t;
    *dark = c->dark_current_e_s;
    if (goal == NULL || goal->has_sensor_temp == 0u) return OI_OK;
    t = goal->sensor_temp_c;
    if (!OI_ISFINITE(t)) return OI_ERR_NONFINITE;
    if (c->dark_doubling_c == 0 || !oi__in_closed(t, c->temp_min_c, c->temp_max_c)) {
        return OI_ERR_INPUT;
    }
    *dark = c->dark_current_e_s *
            OI_EXP(OI_R(0.6931471805599453) * ((t - c->dark_ref_temp_c) / c->dark_doubling_c));
    return OI_OK;
}

/* Rates of the brightest pixel (oi_expose, Note 1); dark: the dark current
 * at the sensor's temperature (sensor_dark). */
static void pixel_rates(const oi_camera *camera, const oi_expose_in *in, oi_real dark,
                        expose_rates *r)
{
    oi_real area, k, ifov;
    area = OI_PI_R * OI_R(0.25) * camera->aperture_m * camera->aperture_m;
    k = camera->transmission * camera->band_fraction * camera->quantum_efficiency /
        camera->photon_energy_j;
    ifov = camera->pixel_pitch_m / camera->focal_length_m;
    r->rate_s = in->flux_w_m2 * (area * k * camera->psf_peak_fraction); /* no underflow of flux * area */
    r->rate_b = in->background_w_m2_sr * area * (ifov * ifov) * k + dark;
}

/* Signal-to-noise ratio of signal s over background b (electrons) with
 * read noise rn: s / sqrt(s + b + rn^2); 0 when there is no noise at all. */
static oi_real snr_of(oi_real s, oi_real b, oi_real rn)
{
    oi_real var = s + b + rn * rn;
    return var > 0 ? s / OI_SQRT(var) : OI_R(0.0);
}

/* Fill of time t at saturation sat, by the same operations as evaluate()
 * (separate statements: nothing can be contracted differently). */
static oi_real fill_of(const expose_rates *r, oi_real t, oi_real sat)
{
    oi_real s = r->rate_s * t;
    oi_real b = r->rate_b * t;
    oi_real peak = s + b;
    return peak / sat;
}

/* Does time t at saturation sat reach the goal (fill < 1 and <= goal)? */
static int reaches_goal(const expose_rates *r, oi_real t, oi_real sat)
{
    oi_real f = fill_of(r, t, sat);
    return f < OI_R(1.0) && f <= r->goal_fill;
}

/* SNR of time t with read noise rn, by the same operations as evaluate(). */
static oi_real snr_at(const expose_rates *r, oi_real t, oi_real rn)
{
    oi_real s = r->rate_s * t;
    oi_real b = r->rate_b * t;
    return snr_of(s, b, rn);
}

/* Fill *out for time index ti and gain index gi. */
static void evaluate(const oi_camera *c, const expose_rates *r, int ti, int gi, oi_exposure *out)
{
    oi_real t = c->times_s[ti];
    out->exposure_s = t;
    out->gain = c->gains[gi];
    out->time_index = ti;
    out->gain_index = gi;
    out->signal_e = r->rate_s * t;
    out->background_e = r->rate_b * t;
    out->peak_e = out->signal_e + out->background_e;
    out->saturation_e = c->full_well_e / c->gains[gi];
    out->fill = out->peak_e / out->saturation_e;
    out->snr = snr_of(out->signal_e, out->background_e, c->read_noise_e[gi]);
}

/* Step 1: k_0, the first time at gain 0 that does not reach the goal
 * (bisection: the fill does not decrease with time). */
static int first_time_over_goal(const oi_camera *camera, const expose_rates *r)
{
    const oi_real sat = camera->full_well_e / camera->gains[0];
    int lo = 0, hi = camera->n_times, mid;
    while (lo < hi) {
        mid = (int)((unsigned)(lo + hi) >> 1); /* both >= 0 */
        if (reaches_goal(r, camera->times_s[mid], sat)) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return lo;
}

/* Step 5: the time of best SNR among times [0, kk) at read noise rn: the
 * longest when it is spaced from the one before, else a scan. */
static int best_time(const oi_camera *camera, const expose_rates *r, int kk, int fast, oi_real rn,
                     oi_real *snr_out)
{
    const oi_real *times = camera->times_s;
    int j = kk - 1, ti;
    oi_real snr, x;
    if (j == 0 || (fast && times[j] >= times[j - 1] * TIME_SPACING)) {
        *snr_out = snr_at(r, times[j], rn);
        return j;
    }
    j = 0;
    snr = snr_at(r, times[0], rn);
    for (ti = 1; ti < kk; ti++) {
        x = snr_at(r, times[ti], rn);
        if (x > snr) {
            snr = x;
            j = ti;
        }
    }
    *snr_out = snr;
    return j;
}

/* Steps 3-5 (kk = k_0 > 0): the best (time, gain) over the gains. */
static void best_setting(const oi_camera *camera, const expose_rates *r, int kk, int *best_t,
                         int *best_g)
{
    const oi_real *times = camera->times_s;
    const int fast = r->rate_s * times[0] >= SIGNAL_FAST_MIN_E && times[0] >= TIME_FAST_MIN_S;
    oi_real best_snr = 0, snr, rn, sat;
    int gi, j;
    *best_t = 0;
    *best_g = 0;
    for (gi = 0; gi < camera->n_gains && r->rate_s > 0; gi++) { /* 3: S = 0 keeps (0, 0) */
        rn = camera->read_noise_e[gi];
        if (gi > 0) {
            if (!(rn < camera->read_noise_e[*best_g])) continue; /* 4 */
            sat = camera->full_well_e / camera->gains[gi];
            while (kk > 0 && !reaches_goal(r, times[kk - 1], sat)) kk--;
            if (kk == 0) break;
        }
        j = best_time(camera, r, kk, fast, rn, &snr); /* 5 */
        if (gi == 0 || snr > best_snr) {
            best_snr = snr;
            *best_t = j;
            *best_g = gi;
        }
    }
}

/* A moving target's trail (docs/camera.md, "Motion"): its rate across the
 * focal plane and the Gaussian PSF of the camera's peak fraction. */
typedef struct {
    oi_real px_s;   /* trail rate (pixels/s) */
    oi_real sigma;  /* PSF sigma (pixels) */
    oi_real q;      /* central fraction per axis, erf(1 / (2 sqrt(2) sigma)) */
} trail_model;

/* Fill *out for time index ti and gain index gi of a moving target: the
 * brightest pixel's signal is the rate at rest times the trail's factor. */
static void evaluate_moving(const oi_camera *c, const expose_rates *r, const trail_model *tm,
                            int ti, int gi, oi_exposure *out)
{
    oi_real t = c->times_s[ti];
    out->exposure_s = t;
    out->gain = c->gains[gi];
    out->time_index = ti;
    out->gain_index = gi;
    out->trail_px = tm->px_s * t;
    out->trail_factor = oi__trail_factor(tm->sigma, tm->q, out->trail_px);
    out->signal_e = r->rate_s * out->trail_factor * t;
    out->background_e = r->rate_b * t;
    out->peak_e = out->signal_e + out->background_e;
    out->saturation_e = c->full_well_e / c->gains[gi];
    out->fill = out->peak_e / out->saturation_e;
    out->snr = snr_of(out->signal_e, out->background_e, c->read_noise_e[gi]);
}

/*
 * The choice for a moving target (rate_rad_s > 0). The trail makes the
 * peak's signal grow more slowly than t (about as min(t, t_1) for a trail
 * of one pixel at t_1), so the SNR may fall at long times and the short
 * search of the target at rest does not apply: every allowed (time, gain)
 * pair is evaluated, at most 16 x 8, by the same rule (gains ascending
 * outside, times ascending inside, strict comparisons). The allowed times
 * are those whose trail is at most camera->max_trail_px (every time when it
 * is 0), and at least the shortest: OI_FLAG_TRAILED when even that trails
 * beyond it. OI_FLAG_TOO_FAINT when no allowed time reaches goal.snr_min
 * at the highest gain. Returns the flags computed here.
 */
/* The signal and background electrons, fill and SNR of one setting of a
 * moving target, by the same operations as evaluate_moving (without a
 * whole oi_exposure on the stack). */
static oi_real moving_setting(const oi_camera *c, const expose_rates *r, const trail_model *tm,
                              int ti, int gi, oi_real *sig, oi_real *bkg, oi_real *snr)
{
    oi_real t = c->times_s[ti];
    oi_real factor = oi__trail_factor(tm->sigma, tm->q, tm->px_s * t);
    *sig = r->rate_s * factor * t;
    *bkg = r->rate_b * t;
    *snr = snr_of(*sig, *bkg, c->read_noise_e[gi]);
    return (*sig + *bkg) / (c->full_well_e / c->gains[gi]);
}

static OI_NOINLINE unsigned expose_moving(const oi_camera *camera, const oi_expose_in *in,
                                          const expose_rates *r, unsigned need,
                                          oi_exposure *out)
{
    trail_model tm;
    oi_real fill, sig, bkg, snr;
    oi_real best_snr = 0, low_fill = 0;
    int n, ti, gi, g0, found = 0, best_t = 0, best_g = 0, low_t = 0, low_g = 0, any_detected = 0;
    unsigned flags = 0;
    tm.px_s = in->rate_rad_s / (camera->pixel_pitch_m / camera->focal_length_m);
    tm.sigma = oi__psf_sigma_px(camera->psf_peak_fraction);
    tm.q = OI_ERF(OI_R(1.0) / (OI_R(2.8284271247461903) * tm.sigma));
    n = camera->n_times;
    if (camera->max_trail_px > 0) {
        n = 0;
        while (n < camera->n_times && tm.px_s * camera->times_s[n] <= camera->max_trail_px) n++;
        if (n == 0) {
            n = 1;
            flags |= OI_FLAG_TRAILED;
        }
    }
    /* without the setting, only the highest gain's times (OI_FLAG_TOO_FAINT) */
    g0 = (need & OI__EXPOSE_SEARCH) != 0u ? 0 : camera->n_gains - 1;
    for (gi = g0; gi < camera->n_gains; gi++) {
        for (ti = 0; ti < n; ti++) {
            fill = moving_setting(camera, r, &tm, ti, gi, &sig, &bkg, &snr);
            if (fill < OI_R(1.0) && fill <= r->goal_fill && (!found || snr > best_snr)) {
                found = 1;
                best_snr = snr;
                best_t = ti;
                best_g = gi;
            }
            if ((gi == 0 && ti == 0) || fill < low_fill) {
                low_fill = fill;
                low_t = ti;
                low_g = gi;
            }
            if (gi == camera->n_gains - 1 && r->rate_s > 0 &&
                detected(r, sig, bkg, camera->read_noise_e[gi])) {
                any_detected = 1;
            }
        }
    }
    if (!any_detected) flags |= OI_FLAG_TOO_FAINT;
    if ((need & OI__EXPOSE_SEARCH) == 0u) return flags;
    if (!found) {
        best_t = low_t;
        best_g = low_g;
    }
    evaluate_moving(camera, r, &tm, best_t, best_g, out);
    if (!found) flags |= well_flags(out, !any_detected);
    return flags;
}

static void expose_at_rest(const oi_camera *camera, const oi_expose_in *in,
                           const expose_rates *r, unsigned flags, unsigned need,
                           oi_exposure *out);

/* The per-call part of the choice: the goal with its defaults and its
 * status (checked before the input's), the detection rule, and the dark
 * current at the goal's temperature with its status (checked after the
 * input's). */
void oi__expose_plan_make(const oi_camera *camera, const oi_expose_goal *goal,
                          oi__expose_plan *p)
{
    expose_rates r;
    memset(&r, 0, sizeof r);
    p->goal_st = check_goal(goal, &r);
    p->dark_st = sensor_dark(camera, goal, &p->dark);
    detect_rule(camera, &r);
    p->goal_fill = r.goal_fill;
    p->snr_min = r.snr_min;
    p->det_k = r.det_k;
    p->det_z = r.det_z;
}

/*
 * oi__expose_planned: the choice of oi_expose for a valid camera and its
 * plan (oi__expose_plan_make; NULL: formed from goal, the single call);
 * out already zeroed, and left so on error.
 * need: OI__EXPOSE_* bits, what is computed (the single call: all).
 *
 * The rule (include/orbillum.h, oi_expose Note 2) is a search over every
 * (time, gain) pair, gains ascending outside and times ascending inside,
 * with strict comparisons so that the first of equals wins. The same choice
 * is made here from a few pairs (docs/camera.md, "Cost of the search")
 * because the computed values are monotone (IEEE operations are correctly
 * rounded, hence monotone in each operand):
 *   1. fill = ((S t) + (B t)) / (full_well / g) does not decrease with t nor
 *      with g, so the settings that reach the goal (fill < 1 and
 *      fill <= goal) at gain g are the times [0, k_g), k_0 >= k_1 >= ...:
 *      k_0 by bisection, the next ones by stepping down.
 *   2. k_0 = 0: nothing reaches the goal, and the lowest fill is that of
 *      (time 0, gain 0), the first setting: it is the choice, with
 *      OI_FLAG_SATURATED or OI_FLAG_BACKGROUND_SATURATED (well_flags) when
 *      its fill is not below 1.
 *   3. S = 0: every SNR is 0, the first setting (0, 0) is the choice.
 *   4. The SNR does not increase with the read noise. A gain whose read
 *      noise is not below that of the best gain so far cannot beat it (its
 *      times are a subset of the best gain's, each with an SNR no higher):
 *      it is skipped.
 *   5. The best of gain g is time k_g - 1 when that time is spaced from the
 *      one before (TIME_SPACING); otherwise times [0, k_g) are scanned.
 */
int oi__expose_planned(const oi_camera *camera, const oi__expose_plan *p,
                       const oi_expose_goal *goal, const oi_expose_in *in, unsigned need,
                       oi_exposure *out)
{
    expose_rates r;
    oi_real dark;
    int st;
    unsigned flags;

    if (p == NULL) {
        /* the single call: the goal's part formed here (no plan in the
         * frame: make stack) */
        st = check_goal(goal, &r);
        if (st != OI_OK) return st;
        st = check_input(in);
        if (st != OI_OK) return st;
        st = sensor_dark(camera, goal, &dark);
        if (st != OI_OK) return st;
        detect_rule(camera, &r);
    } else {
        if (p->goal_st != OI_OK) return p->goal_st;
        st = check_input(in);
        if (st != OI_OK) return st;
        if (p->dark_st != OI_OK) return p->dark_st;
        r.goal_fill = p->goal_fill;
        r.snr_min = p->snr_min;
        r.det_k = p->det_k;
        r.det_z = p->det_z;
        dark = p->dark;
    }
    pixel_rates(camera, in, dark, &r);
    flags = in->flags & (unsigned)FLAGS_GEOMETRIC;
    if (in->rate_rad_s > 0) {
        if ((need & (OI__EXPOSE_SEARCH | OI__EXPOSE_FAINT)) != 0u)
            flags |= expose_moving(camera, in, &r, need, out);
        out->flags = flags;
        if ((need & OI__EXPOSE_SEARCH) != 0u) detect_margin(camera, &r, out);
        out->sun_angle_rad = 0;
        out->background_w_m2_sr = in->background_w_m2_sr;
        out->rate_rad_s = in->rate_rad_s;
        return OI_OK;
    }
    expose_at_rest(camera, in, &r, flags, need, out);
    return OI_OK;
}

int oi__expose_valid(const oi_camera *camera, const oi_expose_in *in,
                     const oi_expose_goal *goal, oi_exposure *out)
{
    return oi__expose_planned(camera, NULL, goal, in, OI__EXPOSE_SEARCH | OI__EXPOSE_FAINT, out);
}

/* The target at rest: steps 1-5 above (with OI__EXPOSE_SEARCH in need);
 * out->flags gets flags and the search's. A frame of its own: the search's
 * locals are not live while the moving target's trail is integrated (make
 * stack). */
static OI_NOINLINE void expose_at_rest(const oi_camera *camera, const oi_expose_in *in,
                                       const expose_rates *r, unsigned flags, unsigned need,
                                       oi_exposure *out)
{
    int kk, best_t, best_g, faint = 0;
    /* the detection test at the longest time and highest gain: for
     * OI_FLAG_TOO_FAINT, and for the search's well flags (well_flags) */
    if (!(r->rate_s > 0)) {
        faint = 1; /* no signal is never detected */
    } else if (r->det_k < 0) {
        faint = snr_at(r, camera->times_s[camera->n_times - 1],
                       camera->read_noise_e[camera->n_gains - 1]) < r->snr_min;
    } else {
        oi_real t = camera->times_s[camera->n_times - 1];
        faint = !detected(r, r->rate_s * t, r->rate_b * t,
                          camera->read_noise_e[camera->n_gains - 1]);
    }
    if ((need & OI__EXPOSE_FAINT) != 0u && faint) flags |= OI_FLAG_TOO_FAINT;
    if ((need & OI__EXPOSE_SEARCH) != 0u) {
        kk = first_time_over_goal(camera, r); /* 1 */
        if (kk == 0) {
            /* 2. */
            evaluate(camera, r, 0, 0, out);
            flags |= well_flags(out, faint);
        } else {
            best_setting(camera, r, kk, &best_t, &best_g);
            evaluate(camera, r, best_t, best_g, out);
        }
        detect_margin(camera, r, out);
        out->trail_factor = 1; /* at rest: no trail */
    }
    out->flags = flags;
    out->sun_angle_rad = 0;
    out->background_w_m2_sr = in->background_w_m2_sr;
}

/* oi_expose: the contract is in include/orbillum.h; the method above
 * (oi__expose_valid) and in docs/camera.md. */
int oi_expose(const oi_camera *camera, const oi_expose_in *in,
              const oi_expose_goal *goal, oi_exposure *out)
{
    if (out == NULL) return OI_ERR_NULL;
    memset(out, 0, sizeof *out);
    if (camera == NULL || in == NULL) return OI_ERR_NULL;
    if (!oi__camera_valid(camera)) return OI_ERR_CAMERA;
    return oi__expose_valid(camera, in, goal, out);
}

/*
 * oi_flag_name: name of one exposure flag bit.
 *
 * Given:
 *   flag_bit  unsigned  one OI_FLAG_* bit
 *
 * Returned (function value):
 *             const char *  "sun_exclusion", "earth_in_fov", "eclipsed",
 *                           "too_faint", "saturated", "penumbra",
 *                           "occulted", "resolved", "moon_shadow", "moon_in_fov",
 *                           "trailed", "glint", "background_saturated";
 *                           NULL for 0, a
 *                           combination of bits
 *                           or an unknown bit.
 */
const char *oi_flag_name(unsigned flag_bit)
{
    switch (flag_bit) {
    case OI_FLAG_SUN_EXCLUSION: return "sun_exclusion";
    case OI_FLAG_EARTH_IN_FOV: return "earth_in_fov";
    case OI_FLAG_ECLIPSED: return "eclipsed";
    case OI_FLAG_TOO_FAINT: return "too_faint";
    case OI_FLAG_SATURATED: return "saturated";
    case OI_FLAG_PENUMBRA: return "penumbra";
    case OI_FLAG_OCCULTED: return "occulted";
    case OI_FLAG_RESOLVED: return "resolved";
    case OI_FLAG_MOON_SHADOW: return "moon_shadow";
    case OI_FLAG_MOON_IN_FOV: return "moon_in_fov";
    case OI_FLAG_TRAILED: return "trailed";
    case OI_FLAG_GLINT: return "glint";
    case OI_FLAG_BACKGROUND_SATURATED: return "background_saturated";
    default: return NULL;
    }
}

#endif /* OI_NO_EXPOSURE */
