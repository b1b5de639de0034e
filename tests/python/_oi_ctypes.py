# SPDX-License-Identifier: MIT
"""Thin ctypes binding of the double-precision runtime for the property tests
(issue 5). Loads build/libori_test.so (mk/fuzz.mk builds it from src/*.c and
tables/*.c; this module runs `make` for it when it is missing) and mirrors the
structs of include/orbillum.h, checked against sizeof() reported by the
library itself. Not the public binding (python/orbillum)."""
import ctypes as C
import os
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SO = os.path.join(ROOT, "build", "libori_test.so")

R3 = C.c_double * 3


class Model(C.Structure):
    _fields_ = [("tsi_w_m2", C.c_double), ("au_km", C.c_double),
                ("sun_radius_km", C.c_double), ("earth_radius_km", C.c_double),
                ("moon_radius_km", C.c_double), ("moon_albedo", C.c_double),
                ("earth_model", C.c_int), ("moon_model", C.c_int),
                ("limb_darkening", C.c_int), ("no_atmosphere", C.c_int),
                ("earth_table", C.c_void_p), ("atm_table", C.c_void_p)]


class Shadow(C.Structure):
    _fields_ = [("fraction", C.c_double), ("fraction_ld", C.c_double),
                ("fraction_atm", C.c_double), ("sun_radius_rad", C.c_double),
                ("earth_radius_rad", C.c_double), ("separation_rad", C.c_double),
                ("sun_distance_km", C.c_double), ("region", C.c_int)]


class Scene(C.Structure):
    _fields_ = [("sun_km", R3), ("moon_km", R3), ("target_km", R3), ("observer_km", R3),
                ("has_observer", C.c_int), ("terms", C.c_uint),
                ("earth_albedo", C.c_double), ("target_albedo", C.c_double),
                ("target_radius_m", C.c_double)]


ILLUM_SCALARS = ["e_sun", "e_earth", "e_moon"]
_ILLUM_AFTER_DIRS = ["earth_theta", "earth_h_km", "earth_phi", "earth_psi",
                     "moon_sun_fraction", "phase_sun", "phase_earth", "phase_moon",
                     "flux_sun", "flux_earth", "flux_moon", "flux_obs", "mag_v", "range_km"]


class Illum(C.Structure):
    _fields_ = ([("shadow", Shadow)] + [(n, C.c_double) for n in ILLUM_SCALARS] +
                [("dir_sun", R3), ("dir_earth", R3), ("dir_moon", R3)] +
                [(n, C.c_double) for n in _ILLUM_AFTER_DIRS])


# every rotation-invariant scalar output of oi_illuminate
SCALAR_OUTPUTS = (["shadow." + n for n, _ in Shadow._fields_ if n != "region"] +
                  ILLUM_SCALARS + _ILLUM_AFTER_DIRS)

TERM_SUN, TERM_EARTH, TERM_MOON = 1, 2, 4
EARTH_TABLE, EARTH_LAMBERT = 0, 1

_lib = None


def lib():
    global _lib
    if _lib is not None:
        return _lib
    if not os.path.exists(SO):
        subprocess.run(["make", "-s", "-C", ROOT, "build/libori_test.so"], check=True)
    L = C.CDLL(SO)
    L.ori_test_sizeof.restype = C.c_size_t
    L.ori_test_sizeof.argtypes = [C.c_int]
    for i, st in enumerate((Model, Shadow, Scene, Illum)):
        assert L.ori_test_sizeof(i) == C.sizeof(st), (st.__name__, L.ori_test_sizeof(i),
                                                     C.sizeof(st))
    assert L.ori_test_sizeof(4) == Illum.range_km.offset
    assert L.ori_test_sizeof(5) == Scene.target_radius_m.offset
    L.oi_illuminate.argtypes = [C.POINTER(Scene), C.POINTER(Model), C.POINTER(Illum)]
    L.oi_illuminate.restype = C.c_int
    L.oi_sun_fraction.argtypes = [R3, R3, C.POINTER(Model), C.POINTER(Shadow)]
    L.oi_sun_fraction.restype = C.c_int
    L.oi_earthshine.argtypes = [C.c_double, C.c_double, C.POINTER(Model),
                                C.POINTER(C.c_double), C.POINTER(C.c_double)]
    L.oi_earthshine.restype = C.c_int
    L.oi_scene_defaults.argtypes = [C.POINTER(Scene)]
    L.oi_scene_defaults.restype = None
    _lib = L
    return L


def model(**kw):
    m = Model()
    for k, v in kw.items():
        setattr(m, k, v)
    return m


def illuminate(sun, target, moon=None, observer=None, terms=TERM_SUN | TERM_EARTH | TERM_MOON,
               m=None, earth_albedo=0.3, target_albedo=0.2, radius_m=1.0):
    """Returns (status, Illum)."""
    L = lib()
    s = Scene()
    L.oi_scene_defaults(C.byref(s))
    s.sun_km = R3(*sun)
    s.target_km = R3(*target)
    if moon is not None:
        s.moon_km = R3(*moon)
    if observer is not None:
        s.observer_km = R3(*observer)
        s.has_observer = 1
    s.terms = terms
    s.earth_albedo, s.target_albedo, s.target_radius_m = earth_albedo, target_albedo, radius_m
    out = Illum()
    st = L.oi_illuminate(C.byref(s), C.byref(m) if m is not None else None, C.byref(out))
    return st, out


def get(illum, name):
    obj = illum
    for part in name.split("."):
        obj = getattr(obj, part)
    return obj


def sun_fraction(sun, point, m=None):
    out = Shadow()
    st = lib().oi_sun_fraction(R3(*sun), R3(*point), C.byref(m) if m is not None else None,
                               C.byref(out))
    return st, out


def earthshine(theta, h_km, m=None):
    phi, psi = C.c_double(), C.c_double()
    st = lib().oi_earthshine(theta, h_km, C.byref(m) if m is not None else None,
                             C.byref(phi), C.byref(psi))
    return st, phi.value, psi.value
