# SPDX-License-Identifier: MIT
"""The sky behind the target: integrated starlight by galactic position,
and galactic coordinates of ICRS directions."""
import ctypes

import numpy as np

from ._arrays import _floats
from ._runtime import L, _lib
from ._status import status_name


def starlight_radiance(l_rad, b_rad):
    """Integrated starlight (W/m^2/sr, as sunlight) at galactic longitude and
    latitude (oi_starlight_radiance), elementwise; docs/camera.md.

    Example: towards the galactic pole:

    >>> import numpy as np, orbillum
    >>> print(f"{orbillum.starlight_radiance(0.0, np.pi / 2):.3e}")
    2.664e-07
    """
    return np.vectorize(lambda l, b: _lib.oi_starlight_radiance(float(l), float(b)),
                        otypes=[np.float64])(_floats(l_rad, "l_rad"), _floats(b_rad, "b_rad"))


def galactic(direction):
    """Galactic (l, b) in radians of ICRS direction(s), shape (..., 3)
    (oi_galactic_from_icrs); ValueError for a zero or non-finite one.

    Example: the galactic centre (RA 266.405 deg, Dec -28.936 deg) and the
    north galactic pole (RA 192.859 deg, Dec 27.128 deg):

    >>> import numpy as np, orbillum
    >>> ra, dec = np.radians([266.405, 192.859]), np.radians([-28.936, 27.128])
    >>> d = np.stack([np.cos(dec) * np.cos(ra), np.cos(dec) * np.sin(ra), np.sin(dec)], axis=-1)
    >>> l, b = orbillum.galactic(d)
    >>> np.round(np.degrees(b), 2).tolist(), round(float(np.degrees(l[0])), 2)
    ([0.0, 90.0], 0.0)
    """
    d = _floats(direction, "direction")
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
