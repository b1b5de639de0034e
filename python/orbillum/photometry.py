# SPDX-License-Identifier: MIT
"""Phase laws and magnitudes: the Lambertian sphere's phase function, the
Moon's phase law, V magnitude from a flux at the observer and back."""
import ctypes

import numpy as np

from ._arrays import _elementwise, _floats
from ._models import _model, _model_explain, _mptr
from ._status import _batch_status
from ._runtime import _lib


def lambert_phase(xi):
    """Lambertian sphere phase function p(xi) (oi_lambert_phase), elementwise.

    Example: 2/3 at full phase, 2/(3 pi) at quadrature, 0 at new:

    >>> import numpy as np, orbillum
    >>> np.round(orbillum.lambert_phase([0.0, np.pi / 2, np.pi]), 6).tolist()
    [0.666667, 0.212207, 0.0]
    >>> round(2 / (3 * np.pi), 6)
    0.212207
    """
    return _elementwise(_lib.oi_lambert_phase, xi, "xi")


def moon_phase_law(alpha):
    """Lunar phase law relative to full Moon (oi_moon_phase_law), elementwise.

    Example: 1 at full Moon, less away from it:

    >>> import numpy as np, orbillum
    >>> np.round(orbillum.moon_phase_law([0.0, 1.0]), 4).tolist()
    [1.0, 0.2437]
    """
    return _elementwise(_lib.oi_moon_phase_law, alpha, "alpha")


def _checked_model(model):
    """The model as a structure, refused (ValueError naming its first bad
    field) when the library rejects it: oi_magnitude_v would take the
    defaults for it silently."""
    m = _model(model)
    if m is not None:
        f = ctypes.c_double()
        _batch_status(_lib.oi_flux_from_magnitude(0.0, ctypes.addressof(m), ctypes.byref(f)), 1,
                      "model", _model_explain(m))
    return m


def magnitude_v(flux_w_m2, *, model=None):
    """Apparent V magnitude of a flux at the observer (oi_magnitude_v), elementwise.
    A model the library rejects raises ValueError naming the field (the C
    function would use the defaults instead).

    Example: a hundred times fainter is five magnitudes more:

    >>> import numpy as np, orbillum
    >>> np.round(orbillum.magnitude_v([1e-12, 1e-14]), 3).tolist()
    [11.095, 16.095]
    """
    m = _checked_model(model)
    mp = _mptr(m)
    return _elementwise(lambda f: _lib.oi_magnitude_v(f, mp), flux_w_m2, "flux_w_m2")


def flux_from_magnitude(mag_v, *, model=None):
    """(flux W/m^2, status) arrays from V magnitudes (oi_flux_from_magnitude);
    an element whose status is an error has the flux NaN (the C library's 0
    would read as a dark target). A model the library rejects raises
    ValueError naming the field.

    Example: the V zero point, and back through magnitude_v():

    >>> import numpy as np, orbillum
    >>> flux, st = orbillum.flux_from_magnitude([0.0, 10.0])
    >>> [f"{f:.4e}" for f in flux], st.tolist()
    (['2.7407e-08', '2.7407e-12'], [0, 0])
    >>> np.round(orbillum.magnitude_v(flux), 9).tolist()
    [0.0, 10.0]
    """
    m = _checked_model(model)
    mp = _mptr(m)
    mag = _floats(mag_v, "mag_v")
    flux = np.zeros(mag.shape)
    st = np.zeros(mag.shape, dtype=np.int32)
    f = ctypes.c_double()
    for idx in np.ndindex(mag.shape):
        st[idx] = _lib.oi_flux_from_magnitude(float(mag[idx]), mp, ctypes.byref(f))
        flux[idx] = f.value if st[idx] >= 0 else np.nan
    return flux, st
