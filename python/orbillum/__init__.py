# SPDX-License-Identifier: MIT
"""orbillum: numpy-vectorised binding of the orbillum C runtime (double build).

Every function takes arrays of epochs: positions of shape (N, 3) in km,
Earth-centred inertial (any one frame, e.g. GCRS), or (3,) for one epoch;
per-row scalars as scalars or arrays of length N. Results are dicts of numpy
arrays of length N. Each row is one call of the C function with the same
inputs, so the numbers are exactly those of the C library (and of
``build/oi-plan --csv`` on the same rows). Errors are per row: ``status`` < 0
(names in ``status_name``); such a row's float outputs are NaN (the C library
gives 0, which reads as a valid value, e.g. mag_v 0; the planner leaves them
empty), its integer outputs 0. What the binding cannot represent is refused,
never wrapped or truncated: an integer outside its C type's range
(ValueError), complex or boolean input (TypeError).

    import orbillum
    r = orbillum.illuminate(sun, moon, target, observer)
    x = orbillum.expose("telescope-15cm", sun, moon, target, observer)

The target is the scene's Lambertian sphere, or a shape of flat facets
(``target_shape``: a built-in name, or facets; ``attitude_q``: quaternions
body -> input frame per row), as include/orbillum.h's oi_shape.

This module is the face: the calls live in modules by subject and are
imported here (``orbillum.illuminate`` is ``orbillum.illumination.illuminate``):
  illumination  illuminate, earthshine, terms_mask (the scenes, oi_illuminate_batch)
  exposure      expose, expose_flux, camera, cameras, sky_mask (oi_expose_scene_batch,
                oi_expose_batch)
  shadow        sun_fraction (oi_sun_fraction_batch)
  facets        Shape, shape, shapes, facet_brdf (oi_shape)
  photometry    lambert_phase, moon_phase_law, magnitude_v, flux_from_magnitude
  sky           starlight_radiance, galactic
and, private: _runtime (the loaded library, the structures' numpy dtypes),
_status (names of statuses and flags), _arrays (input conversion), _models
(the oi_model dict), _lib (the ctypes mirror of the header).
"""

# numpy and ctypes were reachable as orbillum.np, orbillum.ctypes: kept
import ctypes  # noqa: F401
import numpy as np  # noqa: F401

# L: the ctypes mirror of the header; _lib: the loaded library (prototypes set)
from ._runtime import (EXPOSURE_DTYPE, FACET_DTYPE, ILLUM_DTYPE, SCENE_DTYPE, L, _lib,
                       library_path)
from ._status import flag_names, status_name
from .exposure import camera, cameras, expose, expose_flux, sky_mask
from .facets import Shape, facet_brdf, shape, shapes
from .illumination import _scenes, earthshine, illuminate, terms_mask
from .photometry import flux_from_magnitude, lambert_phase, magnitude_v, moon_phase_law
from .shadow import sun_fraction
from .sky import galactic, starlight_radiance

# Every OI_* constant of the header by its C name (statuses OI_OK, OI_WARN_*,
# OI_ERR_*; flags, terms, model options, bounds, OI_BATCH_*): taken from the
# mirror, which tests/python/test_binding_abi.py holds equal to the header, so
# that a constant added there is exported here too.
_CONSTANTS = sorted(n for n in vars(L) if n.startswith("OI_"))
globals().update({n: getattr(L, n) for n in _CONSTANTS})

__all__ = ["illuminate", "expose", "expose_flux", "sun_fraction", "earthshine",
           "lambert_phase", "moon_phase_law", "magnitude_v", "flux_from_magnitude",
           "starlight_radiance", "galactic",
           "camera", "cameras", "status_name", "flag_names", "terms_mask", "sky_mask",
           "Shape", "shape", "shapes", "facet_brdf", "FACET_DTYPE",
           "library_path"] + _CONSTANTS
