/* SPDX-License-Identifier: MIT */
/*
 * orbillum/camera.h: the camera and the exposure choice: oi_camera and the
 * built-in cameras, the flags, the sky backgrounds, goals, oi_expose and
 * oi_expose_scene (removed by OI_NO_EXPOSURE).
 *
 * A section of orbillum.h, the header a program includes (it includes every
 * section); compiles alone, and includes the sections it uses.
 */
#ifndef ORBILLUM_CAMERA_H
#define ORBILLUM_CAMERA_H

#include "base.h"
#include "model.h"
#include "scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- camera */
#ifndef OI_NO_EXPOSURE

#define OI_CAMERA_MAX_TIMES (16)
#define OI_CAMERA_MAX_GAINS (8)

typedef struct oi_camera {
    const char *name;
    oi_real aperture_m;         /* entrance pupil diameter (m) */
    oi_real focal_length_m;     /* (m) */
    oi_real pixel_pitch_m;      /* (m) */
    oi_real transmission;       /* optics transmission, (0, 1] */
    oi_real quantum_efficiency; /* band-mean QE, (0, 1] */
    oi_real band_fraction;      /* fraction of solar irradiance in the band, (0, 1] */
    oi_real photon_energy_j;    /* mean photon energy in the band (J) */
    oi_real full_well_e;        /* (electrons) */
    oi_real dark_current_e_s;   /* (electrons/s/pixel) */
    oi_real psf_peak_fraction;  /* fraction of a point source in the brightest pixel, (0, 1] */
    oi_real fov_rad;            /* full field of view, diagonal (rad) */
    oi_real sun_exclusion_rad;  /* Sun exclusion half-angle from the boresight (rad) */
    int n_times;                /* number of exposure times, 1..OI_CAMERA_MAX_TIMES */
    oi_real times_s[OI_CAMERA_MAX_TIMES];  /* ascending (s) */
    int n_gains;                /* number of gains, 1..OI_CAMERA_MAX_GAINS */
    oi_real gains[OI_CAMERA_MAX_GAINS];    /* ascending; saturation = full_well / gain */
    oi_real read_noise_e[OI_CAMERA_MAX_GAINS]; /* input-referred read noise per gain (e-) */
    oi_real max_trail_px;       /* longest acceptable trail (pixels), [0, 1e6]; 0: no limit */
    oi_real detect_false_alarm; /* detection rule: per-pixel false-alarm probability of its
                                   threshold, [1e-15, 0.5); 0: the SNR rule (goal.snr_min) */
    oi_real detect_probability; /* detection probability required, [0.5, 0.999999]; 0: 0.5 */
    /* Sensor temperature (docs/camera.md, "Sensor temperature"): the dark current is
     * dark_current_e_s * 2^((T - dark_ref_temp_c) / dark_doubling_c) at a sensor
     * temperature T given in oi_expose_goal (has_sensor_temp); all four 0: no
     * temperature model (dark_current_e_s at any temperature, none may be given). */
    oi_real dark_ref_temp_c;    /* temperature of dark_current_e_s (deg C), [-150, 150] */
    oi_real dark_doubling_c;    /* rise that doubles the dark current (deg C), [1, 100] */
    oi_real temp_min_c;         /* rated sensor temperature range (deg C), [-150, 150], */
    oi_real temp_max_c;         /* min <= max, within 30 doublings of dark_ref_temp_c */
} oi_camera;

/* oi_camera_builtin: built-in camera number index (0 is the default,
 * "star-tracker"); NULL for a negative index or past the last. Read-only,
 * static storage; sources of every value in src/camera/camera_builtin.c and
 * docs/camera.md. */
const oi_camera *oi_camera_builtin(int index);
/* oi_camera_find: built-in camera by name (exact, case-sensitive); NULL when
 * name is NULL or no camera has it. */
const oi_camera *oi_camera_find(const char *name);

/* Exposure flags (bit mask) */
#define OI_FLAG_SUN_EXCLUSION (1u)   /* Sun inside the exclusion angle */
#define OI_FLAG_EARTH_IN_FOV  (2u)   /* Earth in the field of view (bright background) */
#define OI_FLAG_ECLIPSED      (4u)   /* target in the umbra */
#define OI_FLAG_TOO_FAINT     (8u)   /* not detected at the longest exposure, highest gain */
#define OI_FLAG_SATURATED     (16u)  /* the target fills the well even at the lowest fill */
#define OI_FLAG_PENUMBRA      (32u)  /* target in the penumbra */
#define OI_FLAG_OCCULTED      (64u)  /* the Earth hides the target from the observer */
#define OI_FLAG_RESOLVED      (128u) /* target wider than a pixel: peak limited by its radiance */
#define OI_FLAG_MOON_SHADOW   (256u) /* the Moon hides part of the Sun from the target */
#define OI_FLAG_MOON_IN_FOV   (512u) /* the Moon's disc in the field (oi_expose_goal.sky OI_SKY_MOON) */
#define OI_FLAG_TRAILED       (1024u) /* even the chosen exposure trails beyond max_trail_px */
#define OI_FLAG_GLINT         (2048u) /* a shape's specular part is more than half of flux_obs */
#define OI_FLAG_BACKGROUND_SATURATED (4096u) /* the background, not the target, fills the
                                                well even at the lowest fill */

/*
 * Flags with one meaning each. The geometric bits say where things are; the
 * exposure's bits (TOO_FAINT, SATURATED, BACKGROUND_SATURATED, TRAILED) what
 * the camera makes of the light, at these definitions, whatever else is set:
 *   TOO_FAINT   the target is not detected (the goal's SNR, or the camera's
 *               detection rule, oi_expose Note 8) at the most sensitive
 *               setting, the longest time (moving: any allowed time) at the
 *               highest gain, the well not counted; always without signal
 *               (flux 0: OCCULTED, an unlit target).
 *   SATURATED   the well is full at the chosen setting (fill >= 1: no setting
 *               reaches the goal, the lowest fill chosen) and the target's
 *               light is what fills it: the background alone does not
 *               (background_e < saturation_e) and the target is not TOO_FAINT.
 *   BACKGROUND_SATURATED  the well is full at the chosen setting and the
 *               target is not what fills it: the background alone (sky,
 *               the sunlit Earth in the field, dark current) fills the well
 *               (background_e >= saturation_e), or the target is TOO_FAINT.
 *               No setting can show the target: point elsewhere.
 * Exclusions (never together in one result): SATURATED and TOO_FAINT;
 * SATURATED and BACKGROUND_SATURATED; SATURATED and OCCULTED (the occulted
 * target's flux is 0: TOO_FAINT, and a full well is the background's);
 * ECLIPSED and PENUMBRA (one shadow region). OCCULTED implies TOO_FAINT.
 * With the setting formed, fill >= 1 gives exactly one of SATURATED and
 * BACKGROUND_SATURATED, fill < 1 neither. The Earth in the field (EARTH_IN_FOV) sets no exposure bit by
 * itself: its radiance is the background (oi_expose_scene Note 3), and
 * BACKGROUND_SATURATED when it fills the well. ECLIPSED (no direct
 * sunlight) does not mean dark: earthshine and moonlight may still be
 * detected, or even saturate. Before BACKGROUND_SATURATED existed,
 * SATURATED was raised for any full well (with TOO_FAINT too, or for the
 * background's): such results are now SATURATED or BACKGROUND_SATURATED.
 */

/* oi_flag_name: name of one flag bit ("sun_exclusion", "earth_in_fov",
 * "eclipsed", "too_faint", "saturated", "penumbra", "occulted", "resolved",
 * "moon_shadow", "moon_in_fov", "trailed", "glint", "background_saturated");
 * NULL for 0, several bits or an unknown bit. */
const char *oi_flag_name(unsigned flag_bit);

/* Sky backgrounds oi_expose_scene adds behind the target (oi_expose_goal.sky,
 * a bit mask; 0: the dark sky, with the sunlit Earth only, of earlier
 * versions). docs/camera.md, "Sky background". */
#ifndef OI_NO_SKY
#define OI_SKY_ZODIACAL (1u)  /* zodiacal light (Leinert et al. 1998), where the ray misses Earth and Moon */
#define OI_SKY_STARLIGHT (4u) /* integrated starlight (Leinert et al. 1998, Pioneer 10), same places */
#endif
#ifndef OI_NO_MOON
#define OI_SKY_MOON     (2u)  /* the Moon: OI_FLAG_MOON_IN_FOV, its surface behind the target, occultation */
#endif

/* Goals of the exposure choice. Zero fields mean defaults. */
typedef struct oi_expose_goal {
    oi_real fill;            /* brightest-pixel fill as a fraction of saturation (0.5) */
    oi_real snr_min;         /* SNR below which TOO_FAINT is raised (5) */
    unsigned sky;            /* OI_SKY_* backgrounds oi_expose_scene adds (0: none) */
    unsigned has_sensor_temp; /* nonzero: sensor_temp_c is given; 0: the camera's
                                 dark_current_e_s as it stands */
    oi_real sensor_temp_c;   /* sensor temperature (deg C), within the camera's rated
                                range (camera temp_min_c .. temp_max_c) */
} oi_expose_goal;

/* Photometric input of the exposure choice. */
typedef struct oi_expose_in {
    oi_real flux_w_m2;           /* target flux at the aperture (W/m^2) */
    oi_real background_w_m2_sr;  /* sky radiance behind the target (W/m^2/sr) */
    unsigned flags;              /* geometric flags already known (OI_FLAG_*) */
    oi_real rate_rad_s;          /* target's angular rate across the field (rad/s, [0, 1e3]);
                                    0: at rest */
} oi_expose_in;

typedef struct oi_exposure {
    oi_real exposure_s;      /* chosen exposure time (s) */
    oi_real gain;            /* chosen gain */
    int time_index;          /* index into camera times_s */
    int gain_index;          /* index into camera gains */
    oi_real signal_e;        /* target electrons in the brightest pixel */
    oi_real background_e;    /* background + dark electrons in that pixel */
    oi_real peak_e;          /* signal_e + background_e */
    oi_real saturation_e;    /* full_well / gain */
    oi_real fill;            /* peak_e / saturation_e */
    oi_real snr;             /* signal / noise of the brightest pixel */
    oi_real sun_angle_rad;   /* Sun to boresight (oi_expose_scene only) */
    unsigned flags;          /* OI_FLAG_* */
    oi_real background_w_m2_sr; /* radiance behind the target used (W/m^2/sr) */
    oi_real rate_rad_s;      /* target's angular rate across the field (rad/s) */
    oi_real trail_px;        /* trail length during the chosen exposure (pixels) */
    oi_real trail_factor;    /* peak pixel's signal over that at rest, (0, 1] */
    oi_real signal_min_e;    /* smallest signal_e the detection rule accepts at this setting */
    oi_real detect_margin_mag; /* 2.5 log10(signal_e / signal_min_e): > 0 detectable;
                                  OI_DETECT_MARGIN_NONE without signal */
} oi_exposure;

/* detect_margin_mag of a setting without any target signal. */
#define OI_DETECT_MARGIN_NONE (-100.0)

/*
 * oi_expose: choose the exposure time and gain for a point-like target.
 *
 * Given:
 *   camera  the camera (valid ranges: Note 4)
 *   in      flux_w_m2: target flux at the aperture (W/m^2, [0, 2.74e4]:
 *           magnitude OI_MAG_MIN at the nominal TSI); background_w_m2_sr: sky
 *           radiance behind the target (W/m^2/sr, [0, 1e8]); flags: geometric
 *           OI_FLAG_* bits already known (copied to the result)
 *   goal    NULL or goals; zero fields mean defaults (fill 0.5, in (0, 1];
 *           snr_min 5, in (0, 1e6])
 * Returned:
 *   out     the chosen setting (exposure_s, gain, their indices), its
 *           electrons (signal_e, background_e, peak_e, saturation_e), fill,
 *           snr and flags; sun_angle_rad is 0 here
 * Returns (checked in this order; on error *out is zeroed):
 *   OI_OK
 *   OI_ERR_NULL       camera, in or out is NULL
 *   OI_ERR_CAMERA     a camera field outside Note 4's ranges, times or gains
 *                     not strictly ascending, n_times or n_gains out of range
 *   OI_ERR_INPUT      a goal field out of range (NaN included)
 *   OI_ERR_FLAGS      goal->sky has bits outside OI_SKY_* (oi_expose itself
 *                     has no geometry and adds no sky)
 *   OI_ERR_NONFINITE  flux or background NaN or infinite
 *   OI_ERR_INPUT      flux negative
 *   OI_ERR_MAGNITUDE  flux brighter than magnitude OI_MAG_MIN (> 2.74e4 W/m^2)
 *   OI_ERR_INPUT      background negative or above 1e8 W/m^2/sr
 *   OI_ERR_FLAGS      in->flags has bits outside the OI_FLAG_* set
 *   OI_ERR_NONFINITE  in->rate_rad_s NaN or infinite
 *   OI_ERR_INPUT      in->rate_rad_s outside [0, 1e3] rad/s
 *   OI_ERR_NONFINITE  goal->has_sensor_temp and goal->sensor_temp_c NaN or
 *                     infinite
 *   OI_ERR_INPUT      goal->has_sensor_temp and the camera has no temperature
 *                     model (dark_doubling_c 0) or sensor_temp_c is outside
 *                     its rated range [temp_min_c, temp_max_c]
 * Notes:
 *   1. Rates of photo-electrons (e-/s) in the brightest pixel, with
 *      A = pi (D/2)^2 and k = transmission * band_fraction * QE / photon_energy:
 *        target      S = flux * A * k * psf_peak_fraction
 *        background  B = radiance * A * (pitch / focal)^2 * k + dark_current.
 *      For exposure t and gain g: peak = (S + B) t, saturation = full_well / g,
 *      fill = peak / saturation, SNR = S t / sqrt(S t + B t + read_noise(g)^2).
 *   2. Choice: among the settings with fill < 1 and fill <= goal.fill, the
 *      highest SNR (ties: lower gain, then shorter time); if none reaches
 *      down to the goal, the shortest time at the lowest gain (the lowest
 *      fill), with OI_FLAG_SATURATED or OI_FLAG_BACKGROUND_SATURATED when
 *      even that saturates (see "Flags with one meaning each").
 *      OI_FLAG_TOO_FAINT when the target is not detectable (Note 8) at the
 *      longest time and highest gain: with the SNR rule, when the SNR
 *      there is below goal.snr_min.
 *   3. in->flags bits OI_FLAG_TOO_FAINT, OI_FLAG_SATURATED,
 *      OI_FLAG_BACKGROUND_SATURATED and OI_FLAG_TRAILED are ignored
 *      (recomputed); the geometric bits are copied to out->flags.
 *   4. Valid camera ranges: aperture (0, 10] m, focal length [1e-3, 1e3] m,
 *      pitch [1e-7, 1e-3] m, transmission, QE, band_fraction and
 *      psf_peak_fraction (0, 1], photon energy [1e-20, 1e-17] J, full well
 *      [1, 1e9] e-, dark current [0, 1e9] e-/s, fov (0, pi], Sun exclusion
 *      [0, pi], 1..OI_CAMERA_MAX_TIMES times in (0, 1e4] s strictly
 *      ascending, 1..OI_CAMERA_MAX_GAINS gains in (0, 1e3] strictly
 *      ascending, read noise [0, 1e6] e-, max_trail_px [0, 1e6],
 *      detect_false_alarm 0 or [1e-15, 0.5), detect_probability 0 or
 *      [0.5, 0.999999]; temperature model (Note 9): dark_doubling_c 0 with
 *      dark_ref_temp_c, temp_min_c and temp_max_c 0, or dark_doubling_c
 *      [1, 100], the three temperatures in [-150, 150] deg C, temp_min_c <=
 *      temp_max_c, both within 30 doublings of dark_ref_temp_c.
 *      name is not used (may be NULL).
 *      Every camera is checked, the built-in ones too.
 *   5. The target is treated as a point source: a resolved target puts less
 *      than psf_peak_fraction of its light in one pixel (oi_expose_scene
 *      bounds that, its Note 5).
 *   6. Exactness and cost: the choice is that of the full search over every
 *      (time, gain) pair, to the bit, made from O(log n_times + n_gains)
 *      evaluations (docs/camera.md, "Cost of the search"; src/camera/expose.c).
 *   7. Motion (in->rate_rad_s > 0; docs/camera.md, "Motion"): the trail of
 *      time t is L = rate t / (pitch / focal) pixels; the brightest pixel's
 *      signal is that at rest times trail_factor, the closed form for a
 *      Gaussian PSF of the camera's peak fraction swept along a pixel row.
 *      The times allowed are those with L <= max_trail_px (all when it is
 *      0), at least the shortest, with OI_FLAG_TRAILED when even that
 *      trails beyond it; every allowed (time, gain) pair is evaluated by
 *      Note 2's rule; OI_FLAG_TOO_FAINT when no allowed time is detectable
 *      at the highest gain. At rest: trail_px 0, trail_factor 1, the
 *      choice of earlier versions bit for bit.
 *   8. Detection (docs/camera.md, "Detection"): camera->detect_false_alarm
 *      0, the SNR rule: S / sqrt(S + B + R^2) >= goal.snr_min. Otherwise a
 *      per-pixel threshold T = k sqrt(B + R^2), k = Phi^-1(1 -
 *      detect_false_alarm), crossed with probability detect_probability
 *      (0: 0.5): S >= T + z sqrt(S + B + R^2), z = Phi^-1(probability)
 *      (electrons at the setting; Gaussian noise). signal_min_e is the
 *      smallest such S at the chosen setting, detect_margin_mag =
 *      2.5 log10(signal_e / signal_min_e) (within +-100;
 *      OI_DETECT_MARGIN_NONE without signal).
 *   9. Sensor temperature (docs/camera.md, "Sensor temperature"): with
 *      goal->has_sensor_temp the dark current is dark_current_e_s *
 *      2^((sensor_temp_c - dark_ref_temp_c) / dark_doubling_c); without it
 *      (0, a NULL goal) dark_current_e_s, as in earlier versions, bit for bit.
 */
int oi_expose(const oi_camera *camera, const oi_expose_in *in,
              const oi_expose_goal *goal, oi_exposure *out);

/*
 * oi_expose_scene: the exposure choice from a scene and its illumination.
 *
 * Given:
 *   camera  the camera (as oi_expose)
 *   scene   positions (km, Earth-centred); has_observer must be set;
 *           earth_albedo (the background) and target_albedo (Note 5)
 *   illum   oi_illuminate's result for this scene (e_sun, e_earth, e_moon,
 *           flux_obs and shadow.region are used)
 *   model   NULL or model (earth_radius_km, au_km, tsi_w_m2)
 *   goal    NULL or goals (as oi_expose); goal->sky: the sky backgrounds
 *           (Note 8; 0 or a NULL goal: none but the sunlit Earth)
 * Returned:
 *   out     as oi_expose, with sun_angle_rad (Note 1), the geometric flags
 *           and background_w_m2_sr, the radiance used behind the target
 * Returns (checked in this order; on error *out is zeroed):
 *   OI_OK
 *   OI_ERR_NULL       camera, scene, illum or out is NULL, or
 *                     scene->has_observer is 0 (the observer is required)
 *   OI_ERR_MODEL, OI_ERR_RADIUS  the model is invalid (as oi_illuminate)
 *   OI_ERR_NONFINITE  a component of sun_km, target_km or observer_km (or
 *                     moon_km, when goal->sky has OI_SKY_MOON and
 *                     scene->terms has OI_TERM_MOON)
 *   OI_ERR_ALBEDO     earth_albedo or target_albedo outside [0, 1] (NaN too)
 *   OI_ERR_NONFINITE  illum's e_sun, e_earth, e_moon, e_sky or flux_obs
 *   OI_ERR_INPUT      one of those five negative
 *   OI_ERR_SHAPE      scene->shape or attitude_q invalid (as oi_illuminate;
 *                     any shape with OI_NO_FACETS)
 *   OI_ERR_NONFINITE, OI_ERR_INPUT  with a shape, illum->flux_specular
 *                     non-finite or negative
 *   OI_ERR_CAMERA     the camera is invalid (oi_expose Note 4)
 *   OI_ERR_ZERO_VECTOR  observer or Sun at the Earth's centre
 *   OI_ERR_NONFINITE  a velocity component NaN or infinite
 *   OI_ERR_INPUT      a velocity component beyond 299792.458 km/s
 *   OI_ERR_BELOW_SURFACE  |observer| or |target| <= the Earth's radius
 *   OI_ERR_OBSERVER_AT_TARGET  observer and target at the same position
 *   then oi_expose's statuses for the goal and the derived flux
 *   (OI_ERR_INPUT for a goal out of range, OI_ERR_FLAGS for unknown
 *   goal->sky bits, OI_ERR_MAGNITUDE for a flux brighter than magnitude
 *   OI_MAG_MIN, OI_ERR_NONFINITE or OI_ERR_INPUT for the goal's sensor
 *   temperature, oi_expose Note 9).
 * Notes:
 *   1. Boresight b = target - observer. sun_angle_rad = angle(sun - observer,
 *      b) (as oi_angle); OI_FLAG_SUN_EXCLUSION when it is below
 *      camera->sun_exclusion_rad.
 *   2. OI_FLAG_EARTH_IN_FOV when the Earth's disc, of angular radius
 *      asin(R / |observer|), comes within fov_rad / 2 of the boresight (the
 *      diagonal field treated as a cone: conservative at the corners).
 *   3. Background: where the boresight ray meets the Earth, the radiance of
 *      a Lambertian Earth, earth_albedo * E0 * cos(i) / pi with
 *      E0 = TSI (1 AU / |sun|)^2 and i the Sun's incidence angle there;
 *      0 when that point is unlit or the ray misses the Earth (dark sky).
 *      The background is physical and does not depend on scene->terms,
 *      except for the scattered sunlight's share (3b).
 *   3b. With OI_TERM_SKY in scene->terms, where the boresight crosses the
 *      limb (it passes between the sky table's cloud floor and the top of the
 *      atmosphere; not on a Moon in front, Note 8), the background adds the
 *      limb's mean radiance seen from the observer, e_sky(observer) / Omega
 *      (Omega the solid angle of that ring; an estimate, see
 *      docs/skylight.md); the resolved bound (Note 5) counts e_sky. None
 *      with model->no_atmosphere (no air to scatter).
 *   4. OI_FLAG_OCCULTED when the Earth lies between the observer and the
 *      target: the target's flux is then taken as 0 (TOO_FAINT follows).
 *   5. Resolved target: no pixel can collect more than a Lambertian surface
 *      of the target's albedo facing every source at once, of radiance
 *      target_albedo (e_sun + e_earth + e_moon + e_sky) / pi, over the pixel's solid
 *      angle (pitch / focal)^2. When psf_peak_fraction * flux exceeds that,
 *      the flux given to oi_expose is reduced so that the brightest pixel
 *      gets exactly that bound, and OI_FLAG_RESOLVED is raised.
 *   6. OI_FLAG_ECLIPSED when illum->shadow.region is OI_SHADOW_UMBRA,
 *      OI_FLAG_PENUMBRA when it is OI_SHADOW_PENUMBRA or OI_SHADOW_ANNULAR
 *      (part of the Sun hidden in both); OI_FLAG_MOON_SHADOW when
 *      illum->sun_moon_hidden > 0 (the Moon hides part of the Sun).
 *   7. Not modelled: the Earth's limb glow in the field, stray light from
 *      the Sun outside the exclusion angle or from a Moon beside the target,
 *      the atmosphere's radiance at the limb.
 *   8. Sky (goal->sky; positions taken as ICRF/GCRS-aligned, the ecliptic
 *      of J2000): the first surface the boresight ray meets decides. The
 *      Earth: Note 3. OI_SKY_MOON (read only with OI_TERM_MOON in
 *      scene->terms): OI_FLAG_MOON_IN_FOV when the Moon's disc comes within
 *      fov_rad / 2 of the boresight; met before the target, OI_FLAG_OCCULTED
 *      (flux 0); met, a Lambertian Moon of model moon_albedo lit by
 *      illum->moon_sun_fraction of the Sun. OI_SKY_ZODIACAL, where the ray
 *      meets neither: oi_zodiacal_radiance of the boresight's ecliptic
 *      longitude from the Sun and latitude, seen from the observer.
 *      OI_SKY_STARLIGHT, where the ray meets neither: oi_starlight_radiance
 *      of the boresight's galactic longitude and latitude
 *      (oi_galactic_from_icrs), added to the zodiacal light.
 *      docs/camera.md, "Sky background".
 *   9. Motion: rate_rad_s = |(target_vel - observer_vel) x b^| / range
 *      (clamped at 1e3 rad/s), then oi_expose's Note 7.
 *  10. Shape (scene->shape not NULL): OI_FLAG_GLINT when illum->flux_specular
 *      exceeds half of illum->flux_obs and the target is not occulted (the
 *      exposure uses the total). Note
 *      5's radiance bound is then the largest over the facets of
 *      (albedo_diffuse + albedo_specular (n + 2) / 2) (e_sun + e_earth +
 *      e_moon) / pi, the peak of its BRDF times pi (target_albedo for a
 *      diffuse_from_scene facet's diffuse part).
 */
int oi_expose_scene(const oi_camera *camera, const oi_scene *scene,
                    const oi_illum *illum, const oi_model *model,
                    const oi_expose_goal *goal, oi_exposure *out);

#endif /* OI_NO_EXPOSURE */

#ifdef __cplusplus
}
#endif

#endif /* ORBILLUM_CAMERA_H */
