# SPDX-License-Identifier: MIT
"""The sky behind the target: integrated starlight by galactic position,
and galactic coordinates of ICRS directions."""
import ctypes

import numpy as np

from ._runtime import L, _lib
from ._status import status_name


def starlight_radiance(l_rad, b_rad):
    """Integrated starlight (W/m^2/sr, as sunlight) at galactic longitude and
    latitude (oi_starlight_radiance), elementwise; docs/camera.md."""
    return np.vectorize(lambda l, b: _lib.oi_starlight_radiance(float(l), float(b)),
                        otypes=[np.float64])(np.asarray(l_rad, dtype=np.float64),
                                             np.asarray(b_rad, dtype=np.float64))


def galactic(direction):
    """Galactic (l, b) in radians of ICRS direction(s), shape (..., 3)
    (oi_galactic_from_icrs); ValueError for a zero or non-finite one."""
    d = np.asarray(direction, dtype=np.float64)
    if d.shape[-1:] != (3,):
        raise ValueError(f"direction: shape (..., 3), got {d.shape}")
    flat = d.reshape(-1, 3)
    out = np.empty((flat.shape[0], 2))
    l_out, b_out = L.real(), L.real()
    for k, v in enumerate(flat):
        st = _lib.oi_galactic_from_icrs((L.real * 3)(*v), ctypes.byref(l_out), ctypes.byref(b_out))
        if st != L.OI_OK:
            raise ValueError(f"direction {v.tolist()}: {status_name(st)}")
        out[k] = (l_out.value, b_out.value)
    out = out.reshape(d.shape[:-1] + (2,))
    return out[..., 0], out[..., 1]
