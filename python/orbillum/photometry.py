# SPDX-License-Identifier: MIT
"""Phase laws and magnitudes: the Lambertian sphere's phase function, the
Moon's phase law, V magnitude from a flux at the observer and back."""
import ctypes

import numpy as np

from ._arrays import _elementwise
from ._models import _model, _mptr
from ._runtime import _lib


def lambert_phase(xi):
    """Lambertian sphere phase function p(xi) (oi_lambert_phase), elementwise."""
    return _elementwise(_lib.oi_lambert_phase, xi)


def moon_phase_law(alpha):
    """Lunar phase law relative to full Moon (oi_moon_phase_law), elementwise."""
    return _elementwise(_lib.oi_moon_phase_law, alpha)


def magnitude_v(flux_w_m2, *, model=None):
    """Apparent V magnitude of a flux at the observer (oi_magnitude_v), elementwise."""
    m = _model(model)
    mp = _mptr(m)
    return _elementwise(lambda f: _lib.oi_magnitude_v(f, mp), flux_w_m2)


def flux_from_magnitude(mag_v, *, model=None):
    """(flux W/m^2, status) arrays from V magnitudes (oi_flux_from_magnitude)."""
    m = _model(model)
    mp = _mptr(m)
    mag = np.asarray(mag_v, dtype=np.float64)
    flux = np.zeros(mag.shape)
    st = np.zeros(mag.shape, dtype=np.int32)
    f = ctypes.c_double()
    for idx in np.ndindex(mag.shape):
        st[idx] = _lib.oi_flux_from_magnitude(float(mag[idx]), mp, ctypes.byref(f))
        flux[idx] = f.value
    return flux, st
