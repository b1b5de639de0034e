# SPDX-License-Identifier: MIT
"""Test-side helpers over the binding's one mirror of the header.

The structures and constants are those of python/orbillum/_lib.py (loaded
from its file, so that no installed package is needed and no second mirror
exists); the library is build/libori_test.so, the double-precision runtime
plus a struct-size probe (tests/stability/ori_test_abi.c; this module runs
`make` for it when it is missing). Used by the property tests.
"""
import ctypes as C
import importlib.util
import os
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SO = os.path.join(ROOT, "build", "libori_test.so")
MIRROR_PATH = os.path.join(ROOT, "python", "orbillum", "_lib.py")


def load_mirror():
    """python/orbillum/_lib.py alone (importing the package would load its library)."""
    spec = importlib.util.spec_from_file_location("orbillum_lib_mirror", MIRROR_PATH)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


M = load_mirror()
R3 = M.real * 3
Model, Shadow, Scene, Illum = M.oi_model, M.oi_shadow, M.oi_scene, M.oi_illum

ILLUM_SCALARS = ["e_sun", "e_earth", "e_moon"]
_ILLUM_NAMES = [n for n, _ in Illum._fields_]
# the scalars after the direction vectors (dir_sky, a vector, is not one)
_ILLUM_AFTER_DIRS = [n for n in _ILLUM_NAMES[_ILLUM_NAMES.index("dir_moon") + 1:] if n != "dir_sky"]

# every rotation-invariant scalar output of oi_illuminate
SCALAR_OUTPUTS = (["shadow." + n for n, _ in Shadow._fields_ if n != "region"] +
                  ILLUM_SCALARS + _ILLUM_AFTER_DIRS)

TERM_SUN, TERM_EARTH, TERM_MOON = M.OI_TERM_SUN, M.OI_TERM_EARTH, M.OI_TERM_MOON
EARTH_TABLE, EARTH_LAMBERT = M.OI_EARTH_TABLE, M.OI_EARTH_LAMBERT

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
    # the library under test was built from the same header as the mirror
    for i, st in enumerate((Model, Shadow, Scene, Illum)):
        assert L.ori_test_sizeof(i) == C.sizeof(st), (st.__name__, L.ori_test_sizeof(i),
                                                     C.sizeof(st))
    assert L.ori_test_sizeof(4) == Illum.range_km.offset
    assert L.ori_test_sizeof(5) == Scene.target_radius_m.offset
    _lib = M.bind(L)
    return _lib


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


def illuminate_albedo(sun, target, albedo_model, epoch, rotation, grid=None, observer=None,
                      earth_albedo=None):
    """oi_illuminate of the Sun and the Earth's terms under an albedo model
    (albedo_model, the scene's epoch_jd and earth_rotation_rad; grid: the
    albedo map, (n_lat, n_lon), read as float32); earth_albedo None keeps the
    scene's default. Returns (status, oi_illum)."""
    import numpy as np
    L = lib()
    s = Scene()
    L.oi_scene_defaults(C.byref(s))
    s.sun_km, s.target_km = R3(*sun), R3(*target)
    s.terms = M.OI_TERM_SUN | M.OI_TERM_EARTH
    if earth_albedo is not None:
        s.earth_albedo = earth_albedo
    s.epoch_jd, s.earth_rotation_rad = epoch, rotation
    if observer is not None:
        s.observer_km = R3(*observer)
        s.has_observer = 1
    m = Model()
    m.albedo_model = albedo_model
    keep = None
    if grid is not None:
        keep = np.ascontiguousarray(grid, dtype=np.float32)
        m.albedo_map = keep.ctypes.data_as(C.POINTER(C.c_float))
        m.albedo_map_n_lat, m.albedo_map_n_lon = keep.shape
    out = Illum()
    st = L.oi_illuminate(C.byref(s), C.byref(m), C.byref(out))
    del keep  # the map is read during the call only
    return st, out
