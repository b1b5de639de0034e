/* SPDX-License-Identifier: MIT */
/*
 * exposure.c: the camera model and the choice of exposure time and gain
 * (oi_expose, oi_expose_scene, oi_flag_name). The rule is written out in
 * docs/camera.md; the built-in cameras are in camera_builtin.c.
 */
#include "oi_internal.h"

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
                         OI_FLAG_PENUMBRA | OI_FLAG_OCCULTED | OI_FLAG_RESOLVED)
#define FLAGS_ALL (FLAGS_GEOMETRIC | OI_FLAG_TOO_FAINT | OI_FLAG_SATURATED)

/* Brightest accepted target flux (W/m^2): magnitude OI_MAG_MIN at the
 * nominal TSI, OI_TSI_W_M2 * 10^(-0.4 (OI_MAG_MIN - OI_SUN_MAG_V)) =
 * 1361 * 10^1.304 = 27406.787040627104 W/m^2 exactly. The literals are the
 * values the library computed per call before (pow of the exponent rounded
 * to oi_real, times the TSI), kept bit for bit so that the accepted range
 * does not move: in double 0x1.ac3b25edfa68fp+14, which is also what
 * oi_flux_from_magnitude(OI_MAG_MIN) returns (13 ulp above the exact value:
 * the exponent -0.4 * -3.26 rounds to 1.3040000000000007); in single
 * precision 0x1.ac3b28p+14 (powf(10, 1.304f) * 1361). tests/c/test_exposure.c
 * checks both against pow. */
#ifdef OI_SINGLE_PRECISION
#define FLUX_MAX_W_M2 OI_R(27406.7890625)
#else
#define FLUX_MAX_W_M2 OI_R(27406.78704062715)
#endif

/* The search of oi_expose (docs/camera.md, "Cost of the search") takes the
 * SNR at the longest time j that reaches the goal as the best of its gain
 * when times_s[j] >= times_s[j-1] * TIME_SPACING: the computed SNR at j is
 * then above the computed SNR at every shorter time (proof in
 * docs/camera.md: SNR / sqrt(t) does not decrease with t, and each computed
 * SNR is within 4.5 u of the exact one, u the unit roundoff), provided that
 * no product is subnormal: the shortest time is at least TIME_FAST_MIN_S and
 * the signal at the shortest time at least SIGNAL_FAST_MIN_E (the smallest
 * SNR is then above 1e-35, as no pixel can hold more than 1e34 electrons).
 * Otherwise the times that reach the goal are scanned. TIME_SPACING is
 * 1 + 256 u, exactly representable: 1 + 2^-16 (float), 1 + 2^-45 (double). */
#ifdef OI_SINGLE_PRECISION
#define TIME_SPACING OI_R(1.0000152587890625)
#else
#define TIME_SPACING OI_R(1.0000000000000284)
#endif
#define TIME_FAST_MIN_S   OI_R(1e-30)
#define SIGNAL_FAST_MIN_E OI_R(1e-18)

/* lo < x <= hi (false for NaN). */
static int open_closed(oi_real x, oi_real lo, oi_real hi)
{
    return x > lo && x <= hi;
}

/* lo <= x <= hi (false for NaN). */
static int closed(oi_real x, oi_real lo, oi_real hi)
{
    return x >= lo && x <= hi;
}

/* Nonzero when every field of the camera is in range (oi_expose Note 4).
 * Every camera is checked, the built-in ones too (the check is the same
 * for the caller's own camera, which is what a flight program uses). One
 * pass over the times and one over the gains: "strictly ascending from 0"
 * is the lower bound of every element and the upper bound is tested on the
 * last one only (the same conditions as element by element; NaN fails
 * every comparison). */
static int camera_valid(const oi_camera *c)
{
    int i, n;
    oi_real prev, x;
    const oi_real one = OI_R(1.0);
    if (!open_closed(c->aperture_m, 0, CAM_APERTURE_MAX_M) ||
        !closed(c->focal_length_m, CAM_FOCAL_MIN_M, CAM_FOCAL_MAX_M) ||
        !closed(c->pixel_pitch_m, CAM_PITCH_MIN_M, CAM_PITCH_MAX_M) ||
        !open_closed(c->transmission, 0, one) ||
        !open_closed(c->quantum_efficiency, 0, one) ||
        !open_closed(c->band_fraction, 0, one) ||
        !closed(c->photon_energy_j, CAM_PHOTON_MIN_J, CAM_PHOTON_MAX_J) ||
        !closed(c->full_well_e, CAM_FULL_WELL_MIN_E, CAM_FULL_WELL_MAX_E) ||
        !closed(c->dark_current_e_s, 0, CAM_DARK_MAX_E_S) ||
        !open_closed(c->psf_peak_fraction, 0, one) ||
        !open_closed(c->fov_rad, 0, OI_PI_R) ||
        !closed(c->sun_exclusion_rad, 0, OI_PI_R) ||
        c->n_times < 1 || c->n_times > OI_CAMERA_MAX_TIMES ||
        c->n_gains < 1 || c->n_gains > OI_CAMERA_MAX_GAINS) {
        return 0;
    }
    n = c->n_times;
    prev = 0;
    for (i = 0; i < n; i++) {
        x = c->times_s[i];
        if (!(x > prev)) return 0;
        prev = x;
    }
    if (!(prev <= CAM_TIME_MAX_S)) return 0;
    n = c->n_gains;
    prev = 0;
    for (i = 0; i < n; i++) {
        x = c->gains[i];
        if (!(x > prev) || !closed(c->read_noise_e[i], 0, CAM_READ_NOISE_MAX_E)) return 0;
        prev = x;
    }
    return prev <= CAM_GAIN_MAX;
}

/* Goal with defaults filled in; 0 when a field is out of range. */
static int goal_resolve(const oi_expose_goal *goal, oi_real *fill, oi_real *snr_min)
{
    *fill = GOAL_FILL_DEFAULT;
    *snr_min = GOAL_SNR_DEFAULT;
    if (goal == NULL) return 1;
    if (goal->fill != 0) {
        if (!open_closed(goal->fill, 0, OI_R(1.0))) return 0;
        *fill = goal->fill;
    }
    if (goal->snr_min != 0) {
        if (!open_closed(goal->snr_min, 0, GOAL_SNR_MAX)) return 0;
        *snr_min = goal->snr_min;
    }
    return 1;
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
static oi_real fill_of(oi_real rate_s, oi_real rate_b, oi_real t, oi_real sat)
{
    oi_real s = rate_s * t;
    oi_real b = rate_b * t;
    oi_real peak = s + b;
    return peak / sat;
}

/* SNR of time t with read noise rn, by the same operations as evaluate(). */
static oi_real snr_at(oi_real rate_s, oi_real rate_b, oi_real t, oi_real rn)
{
    oi_real s = rate_s * t;
    oi_real b = rate_b * t;
    return snr_of(s, b, rn);
}

/* Fill *out for time index ti and gain index gi. */
static void evaluate(const oi_camera *c, oi_real rate_s, oi_real rate_b, int ti, int gi,
                     oi_exposure *out)
{
    oi_real t = c->times_s[ti];
    out->exposure_s = t;
    out->gain = c->gains[gi];
    out->time_index = ti;
    out->gain_index = gi;
    out->signal_e = rate_s * t;
    out->background_e = rate_b * t;
    out->peak_e = out->signal_e + out->background_e;
    out->saturation_e = c->full_well_e / c->gains[gi];
    out->fill = out->peak_e / out->saturation_e;
    out->snr = snr_of(out->signal_e, out->background_e, c->read_noise_e[gi]);
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
 *                           "occulted", "resolved"; NULL for 0, a combination of bits
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
    default: return NULL;
    }
}

/*
 * The choice of oi_expose for a valid camera; out already zeroed, and left
 * so on error.
 *
 * The rule (Note 2) is a search over every (time, gain) pair, gains
 * ascending outside and times ascending inside, with strict comparisons so
 * that the first of equals wins. The same choice is made here from a few
 * pairs (docs/camera.md, "Cost of the search") because the computed values
 * are monotone (IEEE operations are correctly rounded, hence monotone in
 * each operand):
 *   1. fill = ((S t) + (B t)) / (full_well / g) does not decrease with t nor
 *      with g, so the settings that reach the goal (fill < 1 and
 *      fill <= goal) at gain g are the times [0, k_g), k_0 >= k_1 >= ...:
 *      k_0 by bisection, the next ones by stepping down.
 *   2. k_0 = 0: nothing reaches the goal, and the lowest fill is that of
 *      (time 0, gain 0), the first setting: it is the choice, with
 *      OI_FLAG_SATURATED when its fill is not below 1.
 *   3. S = 0: every SNR is 0, the first setting (0, 0) is the choice.
 *   4. The SNR does not increase with the read noise. A gain whose read
 *      noise is not below that of the best gain so far cannot beat it (its
 *      times are a subset of the best gain's, each with an SNR no higher):
 *      it is skipped.
 *   5. The best of gain g is time k_g - 1 when that time is spaced from the
 *      one before (TIME_SPACING); otherwise times [0, k_g) are scanned.
 */
static int expose_valid(const oi_camera *camera, const oi_expose_in *in,
                        const oi_expose_goal *goal, oi_exposure *out)
{
    const oi_real one = OI_R(1.0);
    const oi_real *times = camera->times_s;
    oi_real goal_fill, snr_min, area, k, rate_s, rate_b, ifov, sat, f, snr, x, rn;
    oi_real best_snr = 0;
    int n_t = camera->n_times, n_g = camera->n_gains;
    int lo, hi, mid, kk, gi, ti, j, best_t = 0, best_g = 0, fast;
    unsigned flags;

    if (!goal_resolve(goal, &goal_fill, &snr_min)) return OI_ERR_CAMERA;
    if (!OI_ISFINITE(in->flux_w_m2) || !OI_ISFINITE(in->background_w_m2_sr)) {
        return OI_ERR_NONFINITE;
    }
    if (!closed(in->flux_w_m2, 0, FLUX_MAX_W_M2) ||
        !closed(in->background_w_m2_sr, 0, IN_RADIANCE_MAX)) {
        return OI_ERR_MAGNITUDE;
    }
    if ((in->flags & ~(unsigned)FLAGS_ALL) != 0u) return OI_ERR_TERMS;

    area = OI_PI_R * OI_R(0.25) * camera->aperture_m * camera->aperture_m;
    k = camera->transmission * camera->band_fraction * camera->quantum_efficiency /
        camera->photon_energy_j;
    ifov = camera->pixel_pitch_m / camera->focal_length_m;
    rate_s = in->flux_w_m2 * (area * k * camera->psf_peak_fraction); /* no underflow of flux * area */
    rate_b = in->background_w_m2_sr * area * (ifov * ifov) * k + camera->dark_current_e_s;

    /* 1. k_0: the first time at gain 0 that does not reach the goal. */
    sat = camera->full_well_e / camera->gains[0];
    lo = 0;
    hi = n_t;
    while (lo < hi) {
        mid = (int)((unsigned)(lo + hi) >> 1); /* both >= 0 */
        f = fill_of(rate_s, rate_b, times[mid], sat);
        if (f < one && f <= goal_fill) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    kk = lo;

    flags = in->flags & (unsigned)FLAGS_GEOMETRIC;
    if (kk == 0) {
        /* 2. */
        evaluate(camera, rate_s, rate_b, 0, 0, out);
        if (!(out->fill < one)) flags |= OI_FLAG_SATURATED;
    } else {
        fast = rate_s * times[0] >= SIGNAL_FAST_MIN_E && times[0] >= TIME_FAST_MIN_S;
        for (gi = 0; gi < n_g && rate_s > 0; gi++) { /* 3: S = 0 keeps (0, 0) */
            rn = camera->read_noise_e[gi];
            if (gi > 0) {
                if (!(rn < camera->read_noise_e[best_g])) continue; /* 4 */
                sat = camera->full_well_e / camera->gains[gi];
                while (kk > 0) {
                    f = fill_of(rate_s, rate_b, times[kk - 1], sat);
                    if (f < one && f <= goal_fill) break;
                    kk--;
                }
                if (kk == 0) break;
            }
            /* 5. */
            j = kk - 1;
            if (j == 0 || (fast && times[j] >= times[j - 1] * TIME_SPACING)) {
                snr = snr_at(rate_s, rate_b, times[j], rn);
            } else {
                j = 0;
                snr = snr_at(rate_s, rate_b, times[0], rn);
                for (ti = 1; ti < kk; ti++) {
                    x = snr_at(rate_s, rate_b, times[ti], rn);
                    if (x > snr) {
                        snr = x;
                        j = ti;
                    }
                }
            }
            if (gi == 0 || snr > best_snr) {
                best_snr = snr;
                best_t = j;
                best_g = gi;
            }
        }
        evaluate(camera, rate_s, rate_b, best_t, best_g, out);
    }
    if (snr_at(rate_s, rate_b, times[n_t - 1], camera->read_noise_e[n_g - 1]) < snr_min) {
        flags |= OI_FLAG_TOO_FAINT;
    }
    out->flags = flags;
    out->sun_angle_rad = 0;
    return OI_OK;
}

/*
 * oi_expose: choose the exposure time and gain for a point-like target.
 *
 * Given:
 *   camera  const oi_camera *      the camera (see Notes 1 for valid ranges)
 *   in      const oi_expose_in *   flux_w_m2: target flux at the aperture
 *                                  (W/m^2, >= 0); background_w_m2_sr: sky
 *                                  radiance behind the target (W/m^2/sr,
 *                                  >= 0); flags: geometric OI_FLAG_* bits
 *                                  already known (copied to the result)
 *   goal    const oi_expose_goal * NULL or goals; zero fields = defaults
 *                                  (fill 0.5 in (0, 1], snr_min 5 in (0, 1e6])
 *
 * Returned:
 *   out     oi_exposure *          the chosen setting, its electrons, fill,
 *                                  SNR and flags (sun_angle_rad is 0 here)
 *
 * Returned (function value):
 *           int   OI_OK;
 *                 OI_ERR_NULL       camera, in or out NULL;
 *                 OI_ERR_CAMERA     a camera field out of range, times or
 *                                   gains not strictly ascending, counts out
 *                                   of range, or a goal field out of range;
 *                 OI_ERR_NONFINITE  flux or background NaN or infinite;
 *                 OI_ERR_MAGNITUDE  flux negative or brighter than magnitude
 *                                   OI_MAG_MIN (> 2.74e4 W/m^2), background
 *                                   negative or above 1e8 W/m^2/sr;
 *                 OI_ERR_TERMS      unknown bits in in->flags.
 *                 On error *out is zeroed.
 *
 * Notes:
 *   1. Rates of photo-electrons (e-/s) in the brightest pixel, with
 *      A = pi (D/2)^2 and k = transmission * band_fraction * QE / photon_energy:
 *        target      S = flux * A * k * psf_peak_fraction
 *        background  B = radiance * A * (pitch / focal)^2 * k + dark_current.
 *      For exposure t and gain g: peak = (S + B) t, saturation = full_well / g,
 *      fill = peak / saturation, SNR = S t / sqrt(S t + B t + read_noise(g)^2).
 *   2. Choice: among the settings with fill < 1 and fill <= goal.fill, the
 *      highest SNR (ties: lower gain, then shorter time); if none reaches
 *      down to the goal, the non-saturating setting with the lowest fill;
 *      if every setting saturates, the shortest time at the lowest gain and
 *      OI_FLAG_SATURATED. OI_FLAG_TOO_FAINT when the SNR at the longest time
 *      and highest gain is below goal.snr_min.
 *   3. in->flags bits OI_FLAG_TOO_FAINT and OI_FLAG_SATURATED are ignored
 *      (recomputed); the geometric bits are copied to out->flags.
 *   4. Valid camera ranges: aperture (0, 10] m, focal length [1e-3, 1e3] m,
 *      pitch [1e-7, 1e-3] m, transmission, QE, band_fraction and
 *      psf_peak_fraction (0, 1], photon energy [1e-20, 1e-17] J, full well
 *      [1, 1e9] e-, dark current [0, 1e9] e-/s, fov (0, pi], Sun exclusion
 *      [0, pi], 1..OI_CAMERA_MAX_TIMES times in (0, 1e4] s strictly
 *      ascending, 1..OI_CAMERA_MAX_GAINS gains in (0, 1e3] strictly
 *      ascending, read noise [0, 1e6] e-. name is not used (may be NULL).
 *   5. The target is treated as a point source here: a resolved target puts
 *      less than psf_peak_fraction of its light in one pixel (oi_expose_scene
 *      bounds that, see its Note 5).
 *   6. The choice of Note 2 is made from a few settings (bisection on the
 *      fill, which grows with time and gain; the longest eligible time of
 *      each gain; gains that cannot win skipped), and is the full search's
 *      to the bit: see expose_valid and docs/camera.md, "Cost of the
 *      search". Cost: O(log n_times + n_gains) evaluations, and a scan of
 *      a gain's eligible times only when two of them are within a relative
 *      2^-16 (single) or 2^-45 (double) of each other or the signal is
 *      below 1e-18 e-.
 *
 * References: docs/camera.md; PHYSICS.md section 3 ("The camera").
 */
int oi_expose(const oi_camera *camera, const oi_expose_in *in,
              const oi_expose_goal *goal, oi_exposure *out)
{
    if (out == NULL) return OI_ERR_NULL;
    memset(out, 0, sizeof *out);
    if (camera == NULL || in == NULL) return OI_ERR_NULL;
    if (!camera_valid(camera)) return OI_ERR_CAMERA;
    return expose_valid(camera, in, goal, out);
}

/* The model constants oi_expose_scene needs (oi__model_resolve's status);
 * out of line (OI_NOINLINE) so that its copy of the model is not in the frame
 * of oi_expose_scene, which is live during the choice as well. */
static OI_NOINLINE int scene_model(const oi_model *model, oi_real *re, oi_real *au, oi_real *tsi)
{
    oi_model m;
    int st = oi__model_resolve(model, &m);
    *re = m.earth_radius_km;
    *au = m.au_km;
    *tsi = m.tsi_w_m2;
    return st;
}

/*
 * oi_expose_scene: exposure choice from a scene and its illumination.
 *
 * Given:
 *   camera  const oi_camera *      the camera
 *   scene   const oi_scene *       positions (km, Earth-centred); needs
 *                                  has_observer; earth_albedo for the
 *                                  background
 *   illum   const oi_illum *       oi_illuminate's result for this scene
 *                                  (flux_obs and shadow.region are used)
 *   model   const oi_model *       NULL or model (Earth radius, TSI, AU)
 *   goal    const oi_expose_goal * NULL or goals (see oi_expose)
 *
 * Returned:
 *   out     oi_exposure *          as oi_expose, plus sun_angle_rad and the
 *                                  geometric flags
 *
 * Returned (function value):
 *           int   OI_OK;
 *                 OI_ERR_NULL       a pointer NULL, or scene->has_observer 0
 *                                   (the observer is a required input here);
 *                 OI_ERR_MODEL, OI_ERR_RADIUS  model out of range;
 *                 OI_ERR_NONFINITE  a position component not finite;
 *                 OI_ERR_ZERO_VECTOR  Sun or observer at the Earth's centre;
 *                 OI_ERR_BELOW_SURFACE  observer or target at or below the
 *                                   surface;
 *                 OI_ERR_OBSERVER_AT_TARGET  observer and target coincide;
 *                 OI_ERR_ALBEDO     earth_albedo or target_albedo outside [0, 1];
 *                 OI_ERR_NONFINITE  also for a non-finite irradiance or flux
 *                                   in illum; OI_ERR_MAGNITUDE for a negative
 *                                   one;
 *                 any status of oi_expose.  On error *out is zeroed.
 *
 * Notes:
 *   1. Boresight b = target - observer. sun_angle_rad = angle(sun - observer,
 *      b); OI_FLAG_SUN_EXCLUSION when it is below camera->sun_exclusion_rad.
 *   2. OI_FLAG_EARTH_IN_FOV when the Earth's disc, of angular radius
 *      asin(R / |observer|), comes within fov_rad / 2 of the boresight (the
 *      diagonal field treated as a cone: conservative at the corners).
 *   3. Background: where the boresight ray meets the Earth, the radiance of
 *      a Lambertian Earth, earth_albedo * E0 * cos(i) / pi with
 *      E0 = TSI (1 AU / |sun|)^2 and i the Sun's incidence angle there;
 *      0 when that point is unlit or the ray misses the Earth (dark sky).
 *      The background is physical and does not depend on scene->terms.
 *   4. OI_FLAG_OCCULTED when the Earth lies between the observer and the
 *      target: the target's flux is then taken as 0 (TOO_FAINT follows).
 *   5. Resolved target: no pixel can collect more than a Lambertian surface
 *      of the target's albedo facing every source at once, of radiance
 *      target_albedo (e_sun + e_earth + e_moon) / pi, over the pixel's solid
 *      angle (pitch / focal)^2. When psf_peak_fraction * flux exceeds that,
 *      the flux given to oi_expose is reduced so that the brightest pixel
 *      gets exactly that bound, and OI_FLAG_RESOLVED is raised.
 *   6. OI_FLAG_ECLIPSED when illum->shadow.region is OI_SHADOW_UMBRA,
 *      OI_FLAG_PENUMBRA when it is OI_SHADOW_PENUMBRA or OI_SHADOW_ANNULAR
 *      (part of the Sun hidden in both).
 *   7. Not modelled: the Moon or the Earth's limb glow in the field, stray
 *      light from the Sun outside the exclusion angle, the atmosphere's
 *      radiance at the limb.
 *
 * References: docs/camera.md; PHYSICS.md sections 3-4.
 */
int oi_expose_scene(const oi_camera *camera, const oi_scene *scene,
                    const oi_illum *illum, const oi_model *model,
                    const oi_expose_goal *goal, oi_exposure *out)
{
    oi_expose_in in;
    const oi_real one = OI_R(1.0);
    /* Vectors of the three steps below live in their own blocks, so that
     * they can share stack space (stack goal of issue 6: 512 bytes). */
    oi_real b[3], bh[3];
    oi_real r_obs, r_tgt, range, re, sun_angle, c, sc, ob, s_hit, cos_i, e0, au_d;
    oi_real sin_rho, cos_rho, cos_g, sin_g, sin_gr, cos_gr;
    oi_real ifov, cap, au, tsi;
    int st;

    if (out == NULL) return OI_ERR_NULL;
    memset(out, 0, sizeof *out);
    if (camera == NULL || scene == NULL || illum == NULL) return OI_ERR_NULL;
    if (!scene->has_observer) return OI_ERR_NULL;
    if (model == NULL) { /* the default model (src/model.c), without a copy */
        re = (oi_real)OI_EARTH_RADIUS_KM;
        au = (oi_real)OI_AU_KM;
        tsi = (oi_real)OI_TSI_W_M2;
    } else {
        st = scene_model(model, &re, &au, &tsi);
        if (st != OI_OK) return st;
    }
    if (!oi__finite3(scene->sun_km) || !oi__finite3(scene->target_km) ||
        !oi__finite3(scene->observer_km)) {
        return OI_ERR_NONFINITE;
    }
    if (!(scene->earth_albedo >= 0 && scene->earth_albedo <= OI_R(1.0)) ||
        !(scene->target_albedo >= 0 && scene->target_albedo <= OI_R(1.0))) {
        return OI_ERR_ALBEDO;
    }
    if (!OI_ISFINITE(illum->e_sun) || !OI_ISFINITE(illum->e_earth) ||
        !OI_ISFINITE(illum->e_moon) || !OI_ISFINITE(illum->flux_obs)) {
        return OI_ERR_NONFINITE;
    }
    if (illum->e_sun < 0 || illum->e_earth < 0 || illum->e_moon < 0 || illum->flux_obs < 0) {
        return OI_ERR_MAGNITUDE;
    }
    if (!camera_valid(camera)) return OI_ERR_CAMERA;
    r_obs = oi__norm(scene->observer_km);
    r_tgt = oi__norm(scene->target_km);
    if (r_obs == 0 || (scene->sun_km[0] == 0 && scene->sun_km[1] == 0 && scene->sun_km[2] == 0)) {
        return OI_ERR_ZERO_VECTOR;
    }
    if (!(r_obs > re) || !(r_tgt > re)) return OI_ERR_BELOW_SURFACE;
    oi__sub(scene->target_km, scene->observer_km, b);
    range = oi__unit(b, bh);
    if (range == 0) return OI_ERR_OBSERVER_AT_TARGET;

    in.flux_w_m2 = illum->flux_obs;
    in.background_w_m2_sr = 0;
    in.flags = 0;

    /* Sun exclusion: the angle is an output, so it is the atan2 form, by
     * the same operations as oi_angle(sun - observer, b) (bh is its unit
     * vector of b); 0, as there, when a difference overflows or the
     * observer is at the Sun. */
    sun_angle = 0;
    {
        oi_real u[3], d; /* sun - observer, its unit vector, then u x bh */
        oi__sub(scene->sun_km, scene->observer_km, u);
        if (oi__finite3(b) && oi__finite3(u) && oi__unit(u, u) > 0) {
            d = oi__dot(u, bh);
            oi__cross(u, bh, u);
            sun_angle = OI_ATAN2(oi__norm(u), d);
        }
    }
    if (sun_angle < camera->sun_exclusion_rad) in.flags |= OI_FLAG_SUN_EXCLUSION;

    /* Earth's disc against the field (Note 2): the flag is the decision
     * gamma - rho < h, gamma the angle from the boresight to the Earth's
     * centre, rho = asin(R/r) the disc's radius, h = fov/2. The sine and
     * cosine of gamma - rho come from unit vectors (cos and sin of gamma as
     * dot and cross products, sin rho = R/r) and the difference formulas,
     * so one atan2 gives gamma - rho where it matters, instead of two
     * angles (docs/camera.md, "Cost of the search"): gamma < rho (sine
     * negative) is on the disc, whatever h; gamma - rho >= pi/2 (cosine not
     * positive) is at least pi/2 >= h away; only in between is the angle
     * computed and compared with h. */
    sin_rho = re / r_obs;
    cos_rho = OI_SQRT((one - sin_rho) * (one + sin_rho));
    {
        oi_real u[3]; /* unit vector of the observer, then u x bh */
        u[0] = scene->observer_km[0] / r_obs;
        u[1] = scene->observer_km[1] / r_obs;
        u[2] = scene->observer_km[2] / r_obs;
        cos_g = -oi__dot(u, bh);
        oi__cross(u, bh, u);
        sin_g = OI_SQRT(oi__dot(u, u)); /* unit vectors: no overflow */
    }
    sin_gr = cos_rho * sin_g - sin_rho * cos_g; /* sin(gamma - rho) */
    cos_gr = cos_rho * cos_g + sin_rho * sin_g; /* cos(gamma - rho) */
    if (!oi__finite3(b) || sin_gr < 0 ||
        (cos_gr > 0 && OI_ATAN2(sin_gr, cos_gr) < OI_R(0.5) * camera->fov_rad)) {
        /* (b overflowed, positions near the largest oi_real: gamma was
         * taken as 0 before, oi_angle of a non-finite vector: flag) */
        in.flags |= OI_FLAG_EARTH_IN_FOV;
    }

    c = (r_obs - re) * (r_obs + re); /* |o|^2 - R^2 > 0 */
    sc = OI_SQRT(c);

    /* Boresight ray o + s bh against the sphere |x| = R: s^2 + 2 ob s + c = 0.
     * It hits when ob < 0 and ob^2 >= c; the near root c / (-ob + sqrt(ob^2 - c))
     * avoids cancellation, and ob^2 - c = (-ob - sc)(-ob + sc). */
    ob = oi__dot(scene->observer_km, bh);
    if (ob < 0 && -ob >= sc) {
        oi_real hit[3], sun_hit[3]; /* then their unit vectors, in place */
        s_hit = c / (-ob + OI_SQRT((-ob - sc) * (-ob + sc)));
        hit[0] = scene->observer_km[0] + s_hit * bh[0];
        hit[1] = scene->observer_km[1] + s_hit * bh[1];
        hit[2] = scene->observer_km[2] + s_hit * bh[2];
        if (s_hit < range) in.flags |= OI_FLAG_OCCULTED;
        oi__sub(scene->sun_km, hit, sun_hit);
        (void)oi__unit(hit, hit);
        (void)oi__unit(sun_hit, sun_hit);
        cos_i = oi__dot(hit, sun_hit);
        if (cos_i > 0) {
            au_d = au / oi__norm(scene->sun_km);
            e0 = tsi * au_d * au_d;
            in.background_w_m2_sr = scene->earth_albedo * e0 * cos_i / OI_PI_R;
        }
    }
    if (in.flags & OI_FLAG_OCCULTED) in.flux_w_m2 = 0;

    /* Resolved target: the brightest pixel sees at most the radiance
     * albedo * sum(E) / pi over its solid angle (Note 5). */
    ifov = camera->pixel_pitch_m / camera->focal_length_m;
    cap = scene->target_albedo * (illum->e_sun + illum->e_earth + illum->e_moon) / OI_PI_R *
          (ifov * ifov) / camera->psf_peak_fraction;
    if (in.flux_w_m2 > cap) {
        in.flux_w_m2 = cap;
        in.flags |= OI_FLAG_RESOLVED;
    }

    if (illum->shadow.region == OI_SHADOW_UMBRA) {
        in.flags |= OI_FLAG_ECLIPSED;
    } else if (illum->shadow.region == OI_SHADOW_PENUMBRA ||
               illum->shadow.region == OI_SHADOW_ANNULAR) {
        in.flags |= OI_FLAG_PENUMBRA;
    }

    st = expose_valid(camera, &in, goal, out);
    if (st < 0) return st;
    out->sun_angle_rad = sun_angle;
    return st;
}

#endif /* OI_NO_EXPOSURE */
