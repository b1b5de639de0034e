/* SPDX-License-Identifier: MIT */
/*
 * oi_wasm.c: what the WebAssembly module adds to the runtime for its
 * JavaScript caller: a static scratch area to pass structs in (the runtime
 * allocates nothing, and neither does this file), and the layout of the
 * public structs and constants as the compiler sees them on wasm32, so
 * web/src/orbillum.js never types an offset by hand.
 */
#include <stddef.h>

#include "orbillum.h"

/* Scratch memory the caller lays its structs in (8-byte aligned). */
#define OI_WASM_SCRATCH_BYTES 65536
static double scratch[OI_WASM_SCRATCH_BYTES / sizeof(double)];

void *oi_wasm_scratch(void);
unsigned oi_wasm_scratch_bytes(void);
unsigned oi_wasm_layout_count(void);
const char *oi_wasm_layout_name(unsigned i);
double oi_wasm_layout_value(unsigned i);

void *oi_wasm_scratch(void) { return scratch; }
unsigned oi_wasm_scratch_bytes(void) { return (unsigned)sizeof scratch; }

typedef struct layout_entry {
    const char *name;
    double value;
} layout_entry;

#define SIZE(T) {"sizeof." #T, (double)sizeof(T)}
#define OFF(T, f) {#T "." #f, (double)offsetof(T, f)}
#define CONST(c) {"const." #c, (double)(c)}

static const layout_entry layout[] = {
    SIZE(oi_real), SIZE(int), SIZE(unsigned), SIZE(void *),
    SIZE(oi_model),
    OFF(oi_model, tsi_w_m2), OFF(oi_model, au_km), OFF(oi_model, sun_radius_km),
    OFF(oi_model, earth_radius_km), OFF(oi_model, moon_radius_km), OFF(oi_model, moon_albedo),
    OFF(oi_model, earth_model), OFF(oi_model, moon_model), OFF(oi_model, limb_darkening),
    OFF(oi_model, no_atmosphere), OFF(oi_model, earth_table), OFF(oi_model, band),
    SIZE(oi_scene),
    OFF(oi_scene, sun_km), OFF(oi_scene, moon_km), OFF(oi_scene, target_km),
    OFF(oi_scene, observer_km), OFF(oi_scene, has_observer), OFF(oi_scene, terms),
    OFF(oi_scene, earth_albedo), OFF(oi_scene, target_albedo), OFF(oi_scene, target_radius_m),
    OFF(oi_scene, shape), OFF(oi_scene, attitude_q), OFF(oi_scene, has_moon),
    SIZE(oi_shadow),
    OFF(oi_shadow, fraction), OFF(oi_shadow, fraction_ld), OFF(oi_shadow, fraction_atm),
    OFF(oi_shadow, sun_radius_rad), OFF(oi_shadow, earth_radius_rad),
    OFF(oi_shadow, separation_rad), OFF(oi_shadow, sun_distance_km), OFF(oi_shadow, region),
    SIZE(oi_illum),
    OFF(oi_illum, shadow), OFF(oi_illum, e_sun), OFF(oi_illum, e_earth), OFF(oi_illum, e_moon),
    OFF(oi_illum, dir_sun), OFF(oi_illum, dir_earth), OFF(oi_illum, dir_moon),
    OFF(oi_illum, earth_theta), OFF(oi_illum, earth_h_km), OFF(oi_illum, earth_phi),
    OFF(oi_illum, earth_psi), OFF(oi_illum, moon_sun_fraction), OFF(oi_illum, phase_sun),
    OFF(oi_illum, phase_earth), OFF(oi_illum, phase_moon), OFF(oi_illum, flux_sun),
    OFF(oi_illum, flux_earth), OFF(oi_illum, flux_moon), OFF(oi_illum, flux_obs),
    OFF(oi_illum, mag_v), OFF(oi_illum, range_km), OFF(oi_illum, flux_specular),
    OFF(oi_illum, e_sky), OFF(oi_illum, flux_sky),
    SIZE(oi_camera),
    OFF(oi_camera, name), OFF(oi_camera, aperture_m), OFF(oi_camera, focal_length_m),
    OFF(oi_camera, pixel_pitch_m), OFF(oi_camera, transmission),
    OFF(oi_camera, quantum_efficiency), OFF(oi_camera, band_fraction),
    OFF(oi_camera, photon_energy_j), OFF(oi_camera, full_well_e),
    OFF(oi_camera, dark_current_e_s), OFF(oi_camera, psf_peak_fraction), OFF(oi_camera, fov_rad),
    OFF(oi_camera, sun_exclusion_rad), OFF(oi_camera, n_times), OFF(oi_camera, times_s),
    OFF(oi_camera, n_gains), OFF(oi_camera, gains), OFF(oi_camera, read_noise_e),
    SIZE(oi_expose_goal),
    OFF(oi_expose_goal, fill), OFF(oi_expose_goal, snr_min),
    SIZE(oi_expose_in),
    OFF(oi_expose_in, flux_w_m2), OFF(oi_expose_in, background_w_m2_sr), OFF(oi_expose_in, flags),
    OFF(oi_expose_in, rate_rad_s),
    SIZE(oi_exposure),
    OFF(oi_exposure, exposure_s), OFF(oi_exposure, gain), OFF(oi_exposure, time_index),
    OFF(oi_exposure, gain_index), OFF(oi_exposure, signal_e), OFF(oi_exposure, background_e),
    OFF(oi_exposure, peak_e), OFF(oi_exposure, saturation_e), OFF(oi_exposure, fill),
    OFF(oi_exposure, snr), OFF(oi_exposure, sun_angle_rad), OFF(oi_exposure, flags),
    OFF(oi_exposure, detect_margin_mag), OFF(oi_exposure, background_w_m2_sr),
    OFF(oi_exposure, rate_rad_s), OFF(oi_exposure, trail_px), OFF(oi_exposure, trail_factor),
    OFF(oi_exposure, signal_min_e),
    CONST(OI_BATCH_FRACTION_LD), CONST(OI_BATCH_ATMOSPHERE), CONST(OI_BATCH_GEOMETRY),
    CONST(OI_BATCH_ALL), CONST(OI_BATCH_DIRECTIONS), CONST(OI_BATCH_OBSERVER),
    CONST(OI_BATCH_SCENE_ALL), CONST(OI_EXPOSE_SETTING), CONST(OI_EXPOSE_FAINT),
    CONST(OI_EXPOSE_DETECT), CONST(OI_EXPOSE_SUN_ANGLE), CONST(OI_EXPOSE_BACKGROUND),
    CONST(OI_EXPOSE_RATE), CONST(OI_EXPOSE_ALL),
    CONST(OI_TERM_SUN), CONST(OI_TERM_EARTH), CONST(OI_TERM_MOON), CONST(OI_TERM_SKY), CONST(OI_TERM_ALL),
    CONST(OI_SHADOW_LIT), CONST(OI_SHADOW_PENUMBRA), CONST(OI_SHADOW_UMBRA),
    CONST(OI_SHADOW_ANNULAR),
    CONST(OI_FLAG_SUN_EXCLUSION), CONST(OI_FLAG_EARTH_IN_FOV), CONST(OI_FLAG_ECLIPSED),
    CONST(OI_FLAG_TOO_FAINT), CONST(OI_FLAG_SATURATED), CONST(OI_FLAG_PENUMBRA),
    CONST(OI_FLAG_OCCULTED), CONST(OI_FLAG_RESOLVED), CONST(OI_FLAG_GLINT),
    CONST(OI_FLAG_BACKGROUND_SATURATED),
    CONST(OI_CAMERA_MAX_TIMES), CONST(OI_CAMERA_MAX_GAINS),
    CONST(OI_EARTH_TABLE), CONST(OI_EARTH_LAMBERT),
    CONST(OI_ERR_CAMERA), CONST(OI_ERR_SHAPE), CONST(OI_ERR_MODEL),
    CONST(OI_AU_KM), CONST(OI_EARTH_RADIUS_KM), CONST(OI_SUN_RADIUS_KM), CONST(OI_MOON_RADIUS_KM),
    CONST(OI_TSI_W_M2), CONST(OI_MAG_DARK),
};

unsigned oi_wasm_layout_count(void) { return (unsigned)(sizeof layout / sizeof layout[0]); }

const char *oi_wasm_layout_name(unsigned i)
{
    return i < oi_wasm_layout_count() ? layout[i].name : NULL;
}

double oi_wasm_layout_value(unsigned i)
{
    return i < oi_wasm_layout_count() ? layout[i].value : 0.0;
}
