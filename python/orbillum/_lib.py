# SPDX-License-Identifier: MIT
"""ctypes mirror of include/orbillum.h (double build) and the library loader.

The one mirror of the header in Python: the binding uses it, and so do the
property tests (tests/python/_oi_ctypes.py). Every constant of the header
(enum oi_status and every numeric OI_* #define of include/*.h and of the
section headers include/orbillum/*.h) has its
namesake here with the same value, and every structure mirrors its C
definition field by field, in order, with the same types;
tests/python/test_binding_abi.py parses the header and compiles a C program
that prints each value, sizeof and offsetof, and fails on any difference or
on anything the header has and this file lacks.
"""
import ctypes
import os
from ctypes import POINTER, c_char_p, c_double, c_int, c_uint, c_ulong, c_void_p

real = c_double  # oi_real in the double build (the only one the binding loads)

# ---- enum oi_status
OI_OK = 0
OI_WARN_TABLE_RANGE = 1
OI_ERR_NULL = -1
OI_ERR_NONFINITE = -2
OI_ERR_ZERO_VECTOR = -3
OI_ERR_BELOW_SURFACE = -4
OI_ERR_OBSERVER_AT_TARGET = -5
OI_ERR_ALBEDO = -6
OI_ERR_RADIUS = -7
OI_ERR_MODEL = -8
OI_ERR_CAMERA = -9
OI_ERR_MAGNITUDE = -10
OI_ERR_TERMS = -11
OI_ERR_GEOMETRY = -12
OI_ERR_INPUT = -13
OI_ERR_FLAGS = -14
OI_ERR_SHAPE = -15

# ---- include/orbillum.h (its sections include/orbillum/*.h)
OI_VERSION_MAJOR = 0
OI_VERSION_MINOR = 2
OI_VERSION_PATCH = 0
OI_VERSION = OI_VERSION_MAJOR * 10000 + OI_VERSION_MINOR * 100 + OI_VERSION_PATCH

OI_MAG_MIN = -30.0
OI_MAG_MAX = 50.0

OI_TERM_SUN = 1
OI_TERM_EARTH = 2
OI_TERM_MOON = 4
OI_TERM_SKY = 8
OI_TERM_ALL = OI_TERM_SUN | OI_TERM_EARTH | OI_TERM_MOON

OI_MODEL_TSI_MIN = 1.0e-6
OI_MODEL_TSI_MAX = 1.0e6
OI_MODEL_AU_MIN = 1.0e3
OI_MODEL_AU_MAX = 1.0e10
OI_MODEL_RADIUS_MIN = 1.0e-3
OI_MODEL_RADIUS_MAX = 1.0e8
OI_POSITION_MAX_KM = 1.0e12
OI_ATM_TOP_MAX_KM = 100.0
OI_ATM_PSI_MAX_RAD = 0.05

OI_EARTH_TABLE = 0    # oi_model.earth_model
OI_EARTH_LAMBERT = 1
OI_MOON_PHASE_LAW = 0  # oi_model.moon_model
OI_MOON_LAMBERT = 1
OI_LIMB_UNIFORM = 0   # oi_model.limb_darkening
OI_LIMB_DARKENED = 1
OI_BAND_V = 0         # oi_model.band
OI_BAND_TOTAL = 1
OI_EARTH_REFLECT_MOMENTS = 0  # oi_model.earth_reflection
OI_EARTH_REFLECT_MEAN = 1
OI_EARTH_REFLECT_TABLE = 2
OI_EARTH_SPHERE = 0   # oi_model.earth_shape
OI_EARTH_WGS84 = 1
OI_ALBEDO_UNIFORM = 0  # oi_model.albedo_model
OI_ALBEDO_KNOCKE = 1
OI_ALBEDO_MAP = 2
OI_ALBEDO_MAP_MAX_DIM = 32768
OI_EPOCH_JD_MIN = 2415020.5
OI_EPOCH_JD_MAX = 2488069.5
OI_EARTH_ROTATION_MAX_RAD = 1.0e3

OI_SHADOW_LIT = 0     # oi_shadow.region
OI_SHADOW_PENUMBRA = 1
OI_SHADOW_UMBRA = 2
OI_SHADOW_ANNULAR = 3

OI_CAMERA_MAX_TIMES = 16
OI_CAMERA_MAX_GAINS = 8

OI_FLAG_SUN_EXCLUSION = 1
OI_FLAG_EARTH_IN_FOV = 2
OI_FLAG_ECLIPSED = 4
OI_FLAG_TOO_FAINT = 8
OI_FLAG_SATURATED = 16
OI_FLAG_PENUMBRA = 32
OI_FLAG_OCCULTED = 64
OI_FLAG_RESOLVED = 128
OI_FLAG_MOON_SHADOW = 256
OI_BATCH_MAX = 1073741824
OI_BATCH_FRACTION_LD = 1
OI_BATCH_ATMOSPHERE = 2
OI_BATCH_GEOMETRY = 4
OI_BATCH_ALL = OI_BATCH_FRACTION_LD | OI_BATCH_ATMOSPHERE | OI_BATCH_GEOMETRY
OI_BATCH_DIRECTIONS = 8
OI_BATCH_OBSERVER = 16
OI_BATCH_SCENE_ALL = OI_BATCH_ALL | OI_BATCH_DIRECTIONS | OI_BATCH_OBSERVER
OI_FLAG_MOON_IN_FOV = 512
OI_FLAG_TRAILED = 1024
OI_FLAG_GLINT = 2048
OI_FLAG_BACKGROUND_SATURATED = 4096
OI_FACETS_MAX = 32
OI_SHININESS_MAX = 1.0e4
OI_DETECT_MARGIN_NONE = -100.0
OI_SKY_ZODIACAL = 1
OI_SKY_MOON = 2
OI_SKY_STARLIGHT = 4
OI_EXPOSE_SETTING = 1      # outputs mask of oi_expose(_scene)_batch_outputs
OI_EXPOSE_FAINT = 2
OI_EXPOSE_DETECT = 4
OI_EXPOSE_SUN_ANGLE = 8
OI_EXPOSE_BACKGROUND = 16
OI_EXPOSE_RATE = 32
OI_EXPOSE_ALL = (OI_EXPOSE_SETTING | OI_EXPOSE_FAINT | OI_EXPOSE_DETECT | OI_EXPOSE_SUN_ANGLE |
                 OI_EXPOSE_BACKGROUND | OI_EXPOSE_RATE)

# ---- include/oi_table.h
OI_TABLE_FORMAT = 4
OI_ATM_FORMAT = 3
OI_TABLE_KIND_EARTHSHINE = 1
OI_TABLE_KIND_ATMOSPHERE = 2
OI_TABLE_KIND_EARTH_ANGULAR = 3
OI_ANGULAR_FORMAT = 1
OI_TABLE_KIND_SKYLIGHT = 4
OI_SKY_FORMAT = 1
OI_ANGULAR_L_MAX = 8

# ---- include/oi_constants.h (defaults; oi_model overrides each)
OI_AU_KM = 149597870.7
OI_TSI_W_M2 = 1361.0
OI_SUN_RADIUS_KM = 695700.0
OI_EARTH_RADIUS_KM = 6378.137
OI_WGS84_INV_FLATTENING = 298.257223563
OI_MOON_RADIUS_KM = 1737.4
OI_MOON_MEAN_DISTANCE_KM = 384400.0
OI_EARTH_ALBEDO_DEFAULT = 0.30
OI_MOON_ALBEDO_DEFAULT = 0.12
OI_SUN_MAG_V = -26.74
OI_MOON_MAG_V_FULL = -12.73
OI_TARGET_ALBEDO_DEFAULT = 0.2
OI_TARGET_RADIUS_M_DEFAULT = 1.0
OI_MAG_DARK = 99.0
OI_PI = 3.14159265358979323846264338327950288
OI_DEG_PER_RAD = 180.0 / OI_PI


# ---- include/oi_table.h structures
class oi_table_info(ctypes.Structure):
    _fields_ = [
        ("name", c_char_p), ("generator", c_char_p), ("parameters", c_char_p),
        ("payload_sha256", c_char_p), ("seed", c_ulong), ("max_error", c_double),
        ("goal", c_double),
    ]


class oi_earth_table(ctypes.Structure):
    _fields_ = [
        ("format", c_int), ("n_lit", c_int), ("n_term", c_int), ("n_alt", c_int),
        ("w_min", c_double), ("w_max", c_double), ("term_k0", c_double), ("term_kp", c_double),
        ("max_rel_err", c_double), ("max_abs_err", c_double),
        ("q", POINTER(ctypes.c_float)), ("psi", POINTER(ctypes.c_float)),
        ("kind", c_int), ("info", POINTER(oi_table_info)),
    ]


class oi_atm_table(ctypes.Structure):
    _fields_ = [
        ("format", c_int), ("kind", c_int), ("info", POINTER(oi_table_info)),
        ("nz", c_int), ("nt", c_int), ("na", c_int), ("nb", c_int),
        ("z_min_km", real), ("z_max_km", real), ("h_a_km", real), ("v_mid_km", real),
        ("alpha_c_rad", real), ("h_c_km", real), ("top_km", real), ("w_rho", real),
        ("f_floor", real), ("earth_radius_km", real), ("sun_radius_km", real), ("au_km", real),
        ("q_min", real), ("q_scale", real), ("psi_min_rad", real), ("psi_scale_rad", real),
        ("e_mid", real), ("c_iu", real), ("ln10", real),
        ("q", POINTER(ctypes.c_ushort)), ("psi", POINTER(ctypes.c_ushort)),
    ]


class oi_earth_angular_table(ctypes.Structure):
    _fields_ = [
        ("format", c_int), ("kind", c_int), ("info", POINTER(oi_table_info)),
        ("l_max", c_int), ("n_coef", c_int), ("n_alt", c_int), ("n_lit", c_int),
        ("n_term", c_int), ("w_min", c_double), ("w_max", c_double),
        ("offset", POINTER(ctypes.c_float)), ("scale", POINTER(ctypes.c_float)),
        ("code", POINTER(ctypes.c_ushort)),
    ]


class oi_sky_table(ctypes.Structure):
    _fields_ = [
        ("format", c_int), ("kind", c_int), ("info", POINTER(oi_table_info)),
        ("n_theta", c_int), ("n_alt", c_int),
        ("w_min", real), ("w_max", real), ("earth_radius_km", real), ("top_km", real),
        ("floor_km", real), ("theta_scale", real), ("w_scale", real), ("q_floor", real),
        ("v", POINTER(ctypes.c_float)), ("psi", POINTER(ctypes.c_float)),
    ]


# ---- include/orbillum.h structures (its sections include/orbillum/*.h)
class oi_model(ctypes.Structure):
    _fields_ = [
        ("tsi_w_m2", real), ("au_km", real), ("sun_radius_km", real),
        ("earth_radius_km", real), ("moon_radius_km", real), ("moon_albedo", real),
        ("earth_model", c_int), ("moon_model", c_int), ("limb_darkening", c_int),
        ("no_atmosphere", c_int), ("earth_table", POINTER(oi_earth_table)),
        ("atm_table", POINTER(oi_atm_table)), ("earth_reflection", c_int),
        ("earth_shape", c_int),
        ("albedo_model", c_int), ("albedo_map", POINTER(ctypes.c_float)),
        ("albedo_map_n_lat", c_int), ("albedo_map_n_lon", c_int),
        ("sky_table", POINTER(oi_sky_table)),
        ("band", c_int), ("atm_total_table", POINTER(oi_atm_table)),
    ]


class oi_shadow(ctypes.Structure):
    _fields_ = [
        ("fraction", real), ("fraction_ld", real), ("fraction_atm", real),
        ("sun_radius_rad", real), ("earth_radius_rad", real), ("separation_rad", real),
        ("sun_distance_km", real), ("region", c_int),
    ]


class oi_facet(ctypes.Structure):
    _fields_ = [
        ("normal", real * 3), ("area_m2", real), ("two_sided", c_int),
        ("albedo_diffuse", real), ("albedo_specular", real), ("shininess", real),
    ]


class oi_shape(ctypes.Structure):
    _fields_ = [
        ("facets", POINTER(oi_facet)), ("n_facets", c_uint), ("diffuse_from_scene", c_int),
        ("name", c_char_p),
    ]


class oi_scene(ctypes.Structure):
    _fields_ = [
        ("sun_km", real * 3), ("moon_km", real * 3), ("target_km", real * 3),
        ("observer_km", real * 3), ("has_observer", c_int), ("terms", c_uint),
        ("earth_albedo", real), ("target_albedo", real), ("target_radius_m", real),
        ("has_moon", c_int),
        ("target_vel_km_s", real * 3), ("observer_vel_km_s", real * 3),
        ("shape", c_void_p), ("attitude_q", real * 4),
        ("epoch_jd", real), ("earth_rotation_rad", real),
    ]


class oi_illum(ctypes.Structure):
    _fields_ = [
        ("shadow", oi_shadow),
        ("e_sun", real), ("e_earth", real), ("e_moon", real),
        ("dir_sun", real * 3), ("dir_earth", real * 3), ("dir_moon", real * 3),
        ("earth_theta", real), ("earth_h_km", real), ("earth_phi", real),
        ("earth_psi", real), ("moon_sun_fraction", real),
        ("phase_sun", real), ("phase_earth", real), ("phase_moon", real),
        ("flux_sun", real), ("flux_earth", real), ("flux_moon", real),
        ("flux_obs", real), ("mag_v", real), ("range_km", real),
        ("sun_moon_hidden", real), ("moon_disc_visible", real),
        ("flux_specular", real),
        ("earth_albedo_eff", real),
        ("e_sky", real), ("dir_sky", real * 3), ("phase_sky", real), ("flux_sky", real),
    ]


class oi_camera(ctypes.Structure):
    _fields_ = [
        ("name", c_char_p),
        ("aperture_m", real), ("focal_length_m", real), ("pixel_pitch_m", real),
        ("transmission", real), ("quantum_efficiency", real), ("band_fraction", real),
        ("photon_energy_j", real), ("full_well_e", real), ("dark_current_e_s", real),
        ("psf_peak_fraction", real), ("fov_rad", real), ("sun_exclusion_rad", real),
        ("n_times", c_int), ("times_s", real * OI_CAMERA_MAX_TIMES),
        ("n_gains", c_int), ("gains", real * OI_CAMERA_MAX_GAINS),
        ("read_noise_e", real * OI_CAMERA_MAX_GAINS),
        ("max_trail_px", real), ("detect_false_alarm", real), ("detect_probability", real),
        ("dark_ref_temp_c", real), ("dark_doubling_c", real), ("temp_min_c", real),
        ("temp_max_c", real),
    ]


class oi_expose_goal(ctypes.Structure):
    _fields_ = [("fill", real), ("snr_min", real), ("sky", c_uint), ("has_sensor_temp", c_uint),
                ("sensor_temp_c", real)]


class oi_expose_in(ctypes.Structure):
    _fields_ = [("flux_w_m2", real), ("background_w_m2_sr", real), ("flags", c_uint),
                ("rate_rad_s", real)]


class oi_exposure(ctypes.Structure):
    _fields_ = [
        ("exposure_s", real), ("gain", real), ("time_index", c_int), ("gain_index", c_int),
        ("signal_e", real), ("background_e", real), ("peak_e", real), ("saturation_e", real),
        ("fill", real), ("snr", real), ("sun_angle_rad", real), ("flags", c_uint),
        ("background_w_m2_sr", real), ("rate_rad_s", real), ("trail_px", real),
        ("trail_factor", real), ("signal_min_e", real), ("detect_margin_mag", real),
    ]


STRUCTS = (oi_table_info, oi_earth_table, oi_atm_table, oi_earth_angular_table, oi_sky_table,
           oi_model, oi_shadow, oi_facet, oi_shape, oi_scene, oi_illum, oi_camera, oi_expose_goal,
           oi_expose_in, oi_exposure)

_R3 = POINTER(real)
# name: (restype, argtypes). Pointers to arrays of structures are passed as
# c_void_p so that the vectorised calls can step through numpy buffers.
_PROTOS = {
    "oi_version": (ctypes.c_long, []),
    "oi_status_name": (c_char_p, [c_int]),
    "oi_lambert_phase": (real, [real]),
    "oi_angle": (real, [_R3, _R3]),
    "oi_cap_overlap": (real, [real, real, real]),
    "oi_sun_fraction": (c_int, [c_void_p, c_void_p, c_void_p, c_void_p]),
    "oi_earthshine": (c_int, [real, real, c_void_p, POINTER(real), POINTER(real)]),
    "oi_earth_table_default": (POINTER(oi_earth_table), []),
    "oi_atm_table_default": (POINTER(oi_atm_table), []),
    "oi_atm_total_default": (POINTER(oi_atm_table), []),
    "oi_earth_angular_default": (POINTER(oi_earth_angular_table), []),
    "oi_sky_table_default": (POINTER(oi_sky_table), []),
    "oi_skylight": (c_int, [real, real, c_void_p, POINTER(real), POINTER(real)]),
    "oi_earthshine_sphere": (c_int, [real, real, _R3, c_void_p, POINTER(real)]),
    "oi_moon_phase_law": (real, [real]),
    "oi_zodiacal_radiance": (real, [real, real]),
    "oi_starlight_radiance": (real, [real, real]),
    "oi_galactic_from_icrs": (c_int, [_R3, POINTER(real), POINTER(real)]),
    "oi_shape_check": (c_int, [POINTER(oi_shape)]),
    "oi_shape_builtin": (POINTER(oi_shape), [c_int]),
    "oi_shape_find": (POINTER(oi_shape), [c_char_p]),
    "oi_facet_brdf": (real, [POINTER(oi_facet), _R3, _R3]),
    "oi_earthshine_plate": (c_int, [real, real, _R3, c_void_p, POINTER(real)]),
    "oi_scene_defaults": (None, [c_void_p]),
    "oi_illuminate": (c_int, [c_void_p, c_void_p, c_void_p]),
    "oi_magnitude_v": (real, [real, c_void_p]),
    "oi_flux_from_magnitude": (c_int, [real, c_void_p, POINTER(real)]),
    "oi_camera_builtin": (POINTER(oi_camera), [c_int]),
    "oi_camera_find": (POINTER(oi_camera), [c_char_p]),
    "oi_flag_name": (c_char_p, [c_uint]),
    "oi_expose": (c_int, [c_void_p, c_void_p, c_void_p, c_void_p]),
    "oi_expose_scene": (c_int, [c_void_p, c_void_p, c_void_p, c_void_p, c_void_p, c_void_p]),
    "oi_sun_fraction_batch": (c_int, [ctypes.c_long, c_void_p, c_void_p, c_void_p, c_uint,
                                      c_void_p, c_void_p]),
    "oi_earthshine_batch": (c_int, [ctypes.c_long, c_void_p, c_void_p, c_void_p, c_void_p,
                                    c_void_p, c_void_p]),
    "oi_illuminate_batch": (c_int, [ctypes.c_long, c_void_p, c_void_p, c_void_p, c_void_p]),
    "oi_illuminate_batch_outputs": (c_int, [ctypes.c_long, c_void_p, c_void_p, c_uint, c_void_p,
                                            c_void_p]),
    "oi_expose_batch": (c_int, [ctypes.c_long, c_void_p, c_void_p, c_void_p, c_void_p,
                                c_void_p]),
    "oi_expose_scene_batch": (c_int, [ctypes.c_long, c_void_p, c_void_p, c_void_p, c_void_p,
                                      c_void_p, c_void_p, c_void_p]),
    "oi_expose_batch_outputs": (c_int, [ctypes.c_long, c_void_p, c_void_p, c_void_p, c_uint,
                                        c_void_p, c_void_p]),
    "oi_expose_scene_batch_outputs": (c_int, [ctypes.c_long, c_void_p, c_void_p, c_void_p,
                                              c_void_p, c_void_p, c_uint, c_void_p, c_void_p]),
}


def _candidates():
    env = os.environ.get("ORBILLUM_LIB")
    if env:
        yield env
        return
    here = os.path.dirname(os.path.abspath(__file__))
    yield os.path.join(here, "liborbillum.so")
    # a development checkout: python/orbillum -> ../../build/liborbillum.so
    d = here
    for _ in range(4):
        d = os.path.dirname(d)
        yield os.path.join(d, "build", "liborbillum.so")


def load():
    """Load the shared runtime: $ORBILLUM_LIB, the package's own copy, or a
    checkout's build/liborbillum.so (``make shared``)."""
    tried = []
    for path in _candidates():
        tried.append(path)
        if os.path.exists(path):
            lib = ctypes.CDLL(path)
            break
    else:
        raise OSError("orbillum: no liborbillum.so found (tried: " + ", ".join(tried) +
                      "). Install with `pip install ./python` from the repository, or run "
                      "`make shared` and set ORBILLUM_LIB=build/liborbillum.so")
    lib._orbillum_path = path
    return bind(lib)


def bind(lib):
    """Set the prototypes of every public function on a loaded ctypes library
    (the binding's, or any build of the double-precision runtime); functions
    compiled out (OI_NO_MOON, OI_NO_EXPOSURE) are skipped. Returns lib."""
    for name, (res, args) in _PROTOS.items():
        fn = getattr(lib, name, None)
        if fn is None:
            continue
        fn.restype = res
        fn.argtypes = args
    return lib
