# SPDX-License-Identifier: MIT
"""The loaded runtime and its structures as numpy records.

L is the ctypes mirror of the header (the module _lib.py); _lib is the loaded
liborbillum.so (L.load(): prototypes set), as the package's ``orbillum._lib``.
The mirror is taken from sys.modules by its full name: the package rebinds its
attribute ``_lib`` to the loaded library, so ``from . import _lib`` would give
the library once the package is imported.
"""
import ctypes
import importlib

import numpy as np

L = importlib.import_module(__package__ + "._lib")

_lib = L.load()


def _np_dtype(struct):
    """numpy dtype of a ctypes structure, pointer fields as uintp (numpy has
    no pointer type): the same layout, offsets taken from ctypes."""
    names, formats, offsets = [], [], []
    for name, t in struct._fields_:
        names.append(name)
        offsets.append(getattr(struct, name).offset)
        if issubclass(t, (ctypes._Pointer, ctypes.c_char_p, ctypes.c_void_p)):
            formats.append(np.uintp)
        elif issubclass(t, ctypes.Structure):
            formats.append(_np_dtype(t))
        else:
            formats.append(np.dtype(t))
    return np.dtype({"names": names, "formats": formats, "offsets": offsets,
                     "itemsize": ctypes.sizeof(struct)}, align=True)


SCENE_DTYPE = _np_dtype(L.oi_scene)
ILLUM_DTYPE = _np_dtype(L.oi_illum)
EXPOSURE_DTYPE = _np_dtype(L.oi_exposure)
#: one facet (oi_facet) as a numpy record: normal (3,), area_m2, two_sided,
#: albedo_diffuse, albedo_specular, shininess
FACET_DTYPE = _np_dtype(L.oi_facet)
assert SCENE_DTYPE.itemsize == ctypes.sizeof(L.oi_scene)
assert ILLUM_DTYPE.itemsize == ctypes.sizeof(L.oi_illum)
assert EXPOSURE_DTYPE.itemsize == ctypes.sizeof(L.oi_exposure)


def library_path():
    """Path of the loaded liborbillum.so.

    Example:

    >>> import orbillum
    >>> orbillum.library_path()
    '...liborbillum.so'
    """
    return _lib._orbillum_path
