# SPDX-License-Identifier: MIT
"""The model options: a dict of oi_model fields (words allowed for the
enumerated options) to the oi_model structure the C calls take."""
import ctypes

import numpy as np

from ._arrays import _floats, _integer
from ._runtime import L


_MODEL_WORDS = {
    "earth_model": {"table": 0, "lambert": 1},
    "moon_model": {"phase_law": 0, "lambert": 1},
    "limb_darkening": {"uniform": 0, "darkened": 1},
    "earth_shape": {"sphere": 0, "wgs84": 1},
    "band": {"V": 0, "total": 1},
    "albedo_model": {"uniform": 0, "knocke": 1, "map": 2},
}


def _model(model):
    """None -> NULL (defaults); dict of oi_model fields (words allowed) -> struct.
    ValueError (unknown field or word) or TypeError (not a dict, a value of the
    wrong type), each naming the field."""
    if model is None:
        return None
    if not isinstance(model, dict):
        raise TypeError(f"model: a dict of oi_model fields or None, got {type(model).__name__}")
    m = L.oi_model()
    types = dict(L.oi_model._fields_)
    for k, v in model.items():
        if k in ("earth_table", "atm_table", "atm_total_table"):
            raise ValueError(f"model: {k} cannot be set from Python")
        if k in ("albedo_map_n_lat", "albedo_map_n_lon"):
            raise ValueError(f"model: {k} is the shape of albedo_map")
        if k == "albedo_map":
            # the caller's grid (rows north to south, cells east from Greenwich),
            # kept alive by the structure for as long as it is used
            grid = np.ascontiguousarray(_floats(v, "model['albedo_map']"), dtype=np.float32)
            if grid.ndim != 2 or grid.size == 0:
                raise ValueError(f"model['albedo_map']: a 2-D (n_lat, n_lon) array, got "
                                 f"shape {grid.shape}")
            m._albedo_map = grid
            m.albedo_map = grid.ctypes.data_as(ctypes.POINTER(ctypes.c_float))
            m.albedo_map_n_lat, m.albedo_map_n_lon = grid.shape
            continue
        if k not in types:
            raise ValueError(f"model: unknown model field {k!r}")
        if isinstance(v, str):
            words = _MODEL_WORDS.get(k)
            if words is None:
                raise ValueError(f"model[{k!r}]: a number, got the string {v!r}")
            if v not in words:
                raise ValueError(f"model[{k!r}]: unknown word {v!r}; one of {', '.join(words)}")
            v = words[v]
        if isinstance(v, (bool, np.bool_)):
            v = int(v)
        if not isinstance(v, (int, float, np.integer, np.floating)):
            raise TypeError(f"model[{k!r}]: a number, got {type(v).__name__}")
        if types[k] is ctypes.c_int:
            if float(v) != int(v):
                raise ValueError(f"model[{k!r}]: an integer option, got {v!r}")
            v = _integer(v, f"model[{k!r}]")  # ctypes would wrap it modulo 2^32
        else:
            v = float(v)
        setattr(m, k, v)
    return m


# The ranges include/orbillum/model.h documents for oi_model (its "Model constants
# and options" comment, OI_MODEL_* bounds, the option macros): a zero real
# field is the default; radii out of range are OI_ERR_RADIUS when finite.
_MODEL_REALS = (  # in the library's order of checks
    ("sun_radius_km", L.OI_MODEL_RADIUS_MIN, L.OI_MODEL_RADIUS_MAX, "km"),
    ("earth_radius_km", L.OI_MODEL_RADIUS_MIN, L.OI_MODEL_RADIUS_MAX, "km"),
    ("moon_radius_km", L.OI_MODEL_RADIUS_MIN, L.OI_MODEL_RADIUS_MAX, "km"),
    ("tsi_w_m2", L.OI_MODEL_TSI_MIN, L.OI_MODEL_TSI_MAX, "W/m^2"),
    ("au_km", L.OI_MODEL_AU_MIN, L.OI_MODEL_AU_MAX, "km"),
    ("moon_albedo", 0.0, 1.0, ""),
)
_MODEL_OPTIONS = (
    ("earth_model", (L.OI_EARTH_TABLE, L.OI_EARTH_LAMBERT)),
    ("moon_model", (L.OI_MOON_PHASE_LAW, L.OI_MOON_LAMBERT)),
    ("limb_darkening", (L.OI_LIMB_UNIFORM, L.OI_LIMB_DARKENED)),
    ("earth_shape", (L.OI_EARTH_SPHERE, L.OI_EARTH_WGS84)),
    ("band", (L.OI_BAND_V, L.OI_BAND_TOTAL)),
    ("earth_reflection", (L.OI_EARTH_REFLECT_MOMENTS, L.OI_EARTH_REFLECT_MEAN,
                          L.OI_EARTH_REFLECT_TABLE)),
)


def _option_text(k, allowed):
    words = {v: w for w, v in _MODEL_WORDS.get(k, {}).items()}
    return ", ".join(f"{v} ({words[v]!r})" if v in words else str(v) for v in allowed)


def _model_problem(m, albedo=False):
    """The first oi_model field of m outside the ranges the header documents,
    as text naming the field and its range; None when every field is in range.
    albedo: the call reads the albedo model (oi_illuminate and its batch)."""
    if m is None:
        return None
    for k, lo, hi, unit in _MODEL_REALS:
        v = getattr(m, k)
        if v == 0:
            continue  # the default
        if not (np.isfinite(v) and lo <= v <= hi):
            return (f"model[{k!r}] = {v!r} is outside its range: 0 (the default) or "
                    f"[{lo:g}, {hi:g}]{' ' + unit if unit else ''}")
    for k, allowed in _MODEL_OPTIONS:
        v = getattr(m, k)
        if v not in allowed:
            return f"model[{k!r}] = {v} is none of {_option_text(k, allowed)}"
    if albedo:
        allowed = (L.OI_ALBEDO_UNIFORM, L.OI_ALBEDO_KNOCKE, L.OI_ALBEDO_MAP)
        if m.albedo_model not in allowed:
            return (f"model['albedo_model'] = {m.albedo_model} is none of "
                    f"{_option_text('albedo_model', allowed)}")
        if m.albedo_model == L.OI_ALBEDO_MAP:
            n_lat, n_lon = m.albedo_map_n_lat, m.albedo_map_n_lon
            if not m.albedo_map:
                return "model['albedo_model'] = 'map' needs model['albedo_map'] (a 2-D grid)"
            top = L.OI_ALBEDO_MAP_MAX_DIM
            if not (1 <= n_lat <= top and 1 <= n_lon <= top):
                return (f"model['albedo_map']: shape ({n_lat}, {n_lon}); each dimension "
                        f"1..OI_ALBEDO_MAP_MAX_DIM = {L.OI_ALBEDO_MAP_MAX_DIM}")
    return None


def _model_explain(m, albedo=False):
    """explain() for _batch_status: the model's first bad field."""
    return lambda st: _model_problem(m, albedo)


def _mptr(m):
    return None if m is None else ctypes.addressof(m)
