# SPDX-License-Identifier: MIT
"""ctypes mirror of include/orbillum.h (double build) and the library loader.

Every structure here mirrors its C definition field by field, in order; the
test suite compiles a C program that prints sizeof/offsetof of each and
compares them with these (tests/python/test_binding_abi.py).
"""
import ctypes
import os
from ctypes import POINTER, c_char_p, c_double, c_int, c_uint, c_void_p

real = c_double  # oi_real in the double build (the only one the binding loads)

# enum oi_status
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

OI_TERM_SUN = 1
OI_TERM_EARTH = 2
OI_TERM_MOON = 4
OI_TERM_ALL = 7

OI_CAMERA_MAX_TIMES = 16
OI_CAMERA_MAX_GAINS = 8

OI_FLAG_SUN_EXCLUSION = 1
OI_FLAG_EARTH_IN_FOV = 2
OI_FLAG_ECLIPSED = 4
OI_FLAG_TOO_FAINT = 8
OI_FLAG_SATURATED = 16
OI_FLAG_PENUMBRA = 32
OI_FLAG_OCCULTED = 64


class oi_model(ctypes.Structure):
    _fields_ = [
        ("tsi_w_m2", real), ("au_km", real), ("sun_radius_km", real),
        ("earth_radius_km", real), ("moon_radius_km", real), ("moon_albedo", real),
        ("earth_model", c_int), ("moon_model", c_int), ("limb_darkening", c_int),
        ("no_atmosphere", c_int), ("earth_table", c_void_p), ("atm_table", c_void_p),
    ]


class oi_shadow(ctypes.Structure):
    _fields_ = [
        ("fraction", real), ("fraction_ld", real), ("fraction_atm", real),
        ("sun_radius_rad", real), ("earth_radius_rad", real), ("separation_rad", real),
        ("sun_distance_km", real), ("region", c_int),
    ]


class oi_scene(ctypes.Structure):
    _fields_ = [
        ("sun_km", real * 3), ("moon_km", real * 3), ("target_km", real * 3),
        ("observer_km", real * 3), ("has_observer", c_int), ("terms", c_uint),
        ("earth_albedo", real), ("target_albedo", real), ("target_radius_m", real),
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
    ]


class oi_expose_goal(ctypes.Structure):
    _fields_ = [("fill", real), ("snr_min", real)]


class oi_expose_in(ctypes.Structure):
    _fields_ = [("flux_w_m2", real), ("background_w_m2_sr", real), ("flags", c_uint)]


class oi_exposure(ctypes.Structure):
    _fields_ = [
        ("exposure_s", real), ("gain", real), ("time_index", c_int), ("gain_index", c_int),
        ("signal_e", real), ("background_e", real), ("peak_e", real), ("saturation_e", real),
        ("fill", real), ("snr", real), ("sun_angle_rad", real), ("flags", c_uint),
    ]


STRUCTS = (oi_model, oi_shadow, oi_scene, oi_illum, oi_camera, oi_expose_goal,
           oi_expose_in, oi_exposure)

_R3 = POINTER(real)
# name: (restype, argtypes). Pointers to arrays of structures are passed as
# c_void_p so that the vectorised calls can step through numpy buffers.
_PROTOS = {
    "oi_status_name": (c_char_p, [c_int]),
    "oi_lambert_phase": (real, [real]),
    "oi_angle": (real, [_R3, _R3]),
    "oi_cap_overlap": (real, [real, real, real]),
    "oi_sun_fraction": (c_int, [c_void_p, c_void_p, c_void_p, c_void_p]),
    "oi_earthshine": (c_int, [real, real, c_void_p, POINTER(real), POINTER(real)]),
    "oi_moon_phase_law": (real, [real]),
    "oi_scene_defaults": (None, [c_void_p]),
    "oi_illuminate": (c_int, [c_void_p, c_void_p, c_void_p]),
    "oi_magnitude_v": (real, [real, c_void_p]),
    "oi_flux_from_magnitude": (c_int, [real, c_void_p, POINTER(real)]),
    "oi_camera_builtin": (POINTER(oi_camera), [c_int]),
    "oi_camera_find": (POINTER(oi_camera), [c_char_p]),
    "oi_flag_name": (c_char_p, [c_uint]),
    "oi_expose": (c_int, [c_void_p, c_void_p, c_void_p, c_void_p]),
    "oi_expose_scene": (c_int, [c_void_p, c_void_p, c_void_p, c_void_p, c_void_p, c_void_p]),
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
    for name, (res, args) in _PROTOS.items():
        fn = getattr(lib, name, None)
        if fn is None:  # compiled out (OI_NO_MOON, OI_NO_EXPOSURE)
            continue
        fn.restype = res
        fn.argtypes = args
    return lib
