# SPDX-License-Identifier: MIT
"""The model options: a dict of oi_model fields (words allowed for the
enumerated options) to the oi_model structure the C calls take."""
import ctypes

import numpy as np

from ._arrays import _floats
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
            v = int(v)
        else:
            v = float(v)
        setattr(m, k, v)
    return m


def _mptr(m):
    return None if m is None else ctypes.addressof(m)
