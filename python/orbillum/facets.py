# SPDX-License-Identifier: MIT
"""Targets of flat facets (oi_shape): the built-in shapes, Shape objects
from facets, the facets' check, and one facet's BRDF (oi_facet_brdf)."""
import ctypes

import numpy as np

from ._arrays import _floats, _n_rows, _vec
from ._runtime import FACET_DTYPE, L, _lib
from ._status import status_name


_FACET_REQUIRED = ("normal", "area_m2", "albedo_diffuse")
_FACET_DEFAULTS = {"two_sided": 0, "albedo_specular": 0.0, "shininess": 0.0}
_FACET_RULES = ("a nonzero finite normal, area_m2 in (0, 1e8], albedos in [0, 1] summing to "
                "at most 1, shininess in [0, OI_SHININESS_MAX]")


def shapes():
    """Names of the built-in shapes (oi_shape_builtin), "sphere" first (the
    scene's Lambertian sphere: no shape).

    Example:

    >>> import orbillum
    >>> orbillum.shapes()
    ['sphere', 'plate', 'box-wing', 'cylinder']
    """
    out = ["sphere"]
    i = 0
    while True:
        p = _lib.oi_shape_builtin(i)
        if not p:
            return out
        out.append(p.contents.name.decode())
        i += 1


class Shape:
    """A target of flat facets for illuminate/expose (oi_shape).

    Shape("box-wing") is a built-in shape (its facets in the library's static
    storage); Shape(facets) copies the facets into a C array this object owns
    (keep it, or pass it, while a call runs: the calls hold it). ``facets``
    is one of
      - a list of dicts, one per facet, with keys normal (3 numbers, body
        frame), area_m2, albedo_diffuse, and optionally two_sided (False),
        albedo_specular (0), shininess (0);
      - a dict of columns with those keys (normal of shape (F, 3));
      - a numpy array of FACET_DTYPE.
    diffuse_from_scene: every facet's albedo_diffuse is the scene's
    target_albedo (as the built-in "plate"). The library checks the facets
    (oi_shape_check): a facet it rejects raises ValueError naming it.
    Attributes: name, facets (a read-only FACET_DTYPE array), n_facets,
    diffuse_from_scene, address (of the oi_shape, for the scene's shape field).

    Example: a built-in shape, and one of two facets:

    >>> import orbillum
    >>> orbillum.Shape("box-wing")
    Shape('box-wing', 8 facets)
    >>> sat = orbillum.Shape([{"normal": [0, 0, 1], "area_m2": 1.0, "albedo_diffuse": 0.3},
    ...                       {"normal": [1, 0, 0], "area_m2": 2.0, "albedo_diffuse": 0.2,
    ...                        "albedo_specular": 0.5, "shininess": 50}], name="sat")
    >>> sat.n_facets, sat.facets["area_m2"].tolist()
    (2, [1.0, 2.0])
    >>> orbillum.Shape([{"normal": [0, 0, 0], "area_m2": 1.0, "albedo_diffuse": 0.3}])
    Traceback (most recent call last):
    ...
    ValueError: target_shape[0]: the library rejects this facet (ERR_SHAPE): ...
    """

    def __init__(self, facets, *, diffuse_from_scene=False, name=None):
        if isinstance(facets, Shape):
            diffuse_from_scene = diffuse_from_scene or facets.diffuse_from_scene
            name = facets.name if name is None else name
            facets = facets.facets
        if isinstance(facets, str):
            if facets == "sphere":
                raise ValueError("target_shape: 'sphere' is no shape (the scene's sphere: pass "
                                 "None or 'sphere' to illuminate/expose)")
            p = _lib.oi_shape_find(facets.encode())
            if not p:
                raise ValueError(f"target_shape: no built-in shape {facets!r}; built-in: "
                                 f"{', '.join(shapes())}, or facets")
            self._struct = p.contents
            self.address = ctypes.cast(p, ctypes.c_void_p).value
            self.name = facets
            n = self._struct.n_facets
            buf = (L.oi_facet * n).from_address(
                ctypes.cast(self._struct.facets, ctypes.c_void_p).value)
            self.facets = np.frombuffer(buf, dtype=FACET_DTYPE, count=n).copy()
            self.diffuse_from_scene = bool(self._struct.diffuse_from_scene)
        else:
            arr = _facet_array(facets)
            self._c_facets = (L.oi_facet * len(arr))()
            ctypes.memmove(self._c_facets, arr.ctypes.data, arr.nbytes)
            self._struct = L.oi_shape()
            self._struct.facets = ctypes.cast(self._c_facets, ctypes.POINTER(L.oi_facet))
            self._struct.n_facets = len(arr)
            self._struct.diffuse_from_scene = 1 if diffuse_from_scene else 0
            self._name = None if name is None else str(name).encode()
            self._struct.name = self._name
            self.address = ctypes.addressof(self._struct)
            self.name = name
            self.facets = arr
            self.diffuse_from_scene = bool(diffuse_from_scene)
            _check_shape(self)
        self.facets.flags.writeable = False
        self.n_facets = len(self.facets)

    def __repr__(self):
        return (f"Shape({self.name!r}, {self.n_facets} facets"
                f"{', diffuse_from_scene' if self.diffuse_from_scene else ''})")


def shape(facets, *, diffuse_from_scene=False, name=None):
    """A Shape (see Shape): a built-in name or facets.

    Example: the built-in plate, whose albedo is the scene's target_albedo:

    >>> import orbillum
    >>> orbillum.shape("plate")
    Shape('plate', 1 facets, diffuse_from_scene)
    """
    return Shape(facets, diffuse_from_scene=diffuse_from_scene, name=name)


def _facet_array(facets):
    """facets (list of dicts, dict of columns, FACET_DTYPE array) -> a
    contiguous FACET_DTYPE array; ValueError/TypeError naming what is wrong."""
    if isinstance(facets, np.ndarray) and facets.dtype.names:
        missing = [k for k in FACET_DTYPE.names if k not in facets.dtype.names]
        if missing:
            raise ValueError(f"target_shape: facet array without field(s) {', '.join(missing)}")
        arr = np.zeros(np.atleast_1d(facets).shape[0], dtype=FACET_DTYPE)
        for k in FACET_DTYPE.names:
            arr[k] = np.atleast_1d(facets)[k]
    else:
        if isinstance(facets, dict):
            cols = dict(facets)
            unknown = sorted(set(cols) - set(FACET_DTYPE.names))
            if unknown:
                raise ValueError(f"target_shape: unknown facet field(s) {', '.join(unknown)}; "
                                 f"fields: {', '.join(FACET_DTYPE.names)}")
            normal = _floats(cols.get("normal", []), "target_shape['normal']")
            if normal.ndim == 1 and normal.shape == (3,):
                normal = normal[None, :]
            rows = [{"normal": nv} for nv in normal] if normal.ndim == 2 else None
            if rows is None:
                raise ValueError(f"target_shape['normal']: shape (F, 3), got {normal.shape}")
            for k, v in cols.items():
                if k == "normal":
                    continue
                v = np.atleast_1d(np.asarray(v))
                if v.shape != (len(rows),):
                    raise ValueError(f"target_shape[{k!r}]: one per facet ({len(rows)}), got "
                                     f"shape {v.shape}")
                for r, x in zip(rows, v):
                    r[k] = x.item()
            facets = rows
        if isinstance(facets, (str, bytes)) or not hasattr(facets, "__len__"):
            raise TypeError("target_shape: a built-in name, a Shape, a list of facet dicts, a "
                            f"dict of facet columns or a FACET_DTYPE array; got "
                            f"{type(facets).__name__}")
        arr = np.zeros(len(facets), dtype=FACET_DTYPE)
        for i, f in enumerate(facets):
            if not isinstance(f, dict):
                raise TypeError(f"target_shape[{i}]: a facet dict, got {type(f).__name__}")
            unknown = sorted(set(f) - set(FACET_DTYPE.names))
            if unknown:
                raise ValueError(f"target_shape[{i}]: unknown facet field(s) "
                                 f"{', '.join(unknown)}; fields: {', '.join(FACET_DTYPE.names)}")
            for k in _FACET_REQUIRED:
                if k not in f:
                    raise ValueError(f"target_shape[{i}]: facet field {k!r} missing")
            nv = _floats(f["normal"], f"target_shape[{i}]['normal']")
            if nv.shape != (3,):
                raise ValueError(f"target_shape[{i}]['normal']: 3 numbers, got shape {nv.shape}")
            arr[i]["normal"] = nv
            for k in ("area_m2", "albedo_diffuse", "albedo_specular", "shininess", "two_sided"):
                v = f.get(k, _FACET_DEFAULTS.get(k))
                if isinstance(v, (bool, np.bool_)) and k == "two_sided":
                    v = int(v)
                if isinstance(v, (str, bytes)) or not isinstance(
                        v, (int, float, np.integer, np.floating)):
                    raise TypeError(f"target_shape[{i}][{k!r}]: a number, got "
                                    f"{type(v).__name__}")
                if k == "two_sided" and v not in (0, 1):
                    raise ValueError(f"target_shape[{i}]['two_sided']: True/False, got {v!r}")
                arr[i][k] = v
    if not 1 <= len(arr) <= L.OI_FACETS_MAX:
        raise ValueError(f"target_shape: 1 to OI_FACETS_MAX = {L.OI_FACETS_MAX} facets, got "
                         f"{len(arr)}")
    return np.ascontiguousarray(arr)


def _check_shape(sh):
    """oi_shape_check; a rejected shape raises ValueError naming its first bad facet."""
    st = _lib.oi_shape_check(ctypes.byref(sh._struct))
    if st >= 0:
        return
    for i in range(sh._struct.n_facets):
        one = L.oi_shape()
        one.facets = ctypes.pointer(sh._c_facets[i])
        one.n_facets = 1
        one.diffuse_from_scene = sh._struct.diffuse_from_scene
        if _lib.oi_shape_check(ctypes.byref(one)) < 0:
            f = sh.facets[i]
            raise ValueError(
                f"target_shape[{i}]: the library rejects this facet ({status_name(st)}): "
                f"normal {list(map(float, f['normal']))}, area_m2 {float(f['area_m2'])}, "
                f"albedo_diffuse {float(f['albedo_diffuse'])}, albedo_specular "
                f"{float(f['albedo_specular'])}, shininess {float(f['shininess'])}; it wants "
                f"{_FACET_RULES}")
    raise ValueError(f"target_shape: the library rejects the shape ({status_name(st)})")


def _shape_of(spec, cache):
    """None / 'sphere' -> None (the sphere); a name, a Shape or facets -> a Shape."""
    if spec is None or (isinstance(spec, str) and spec in ("", "sphere")):
        return None
    if isinstance(spec, Shape):
        return spec
    if isinstance(spec, str):
        if spec not in cache:
            cache[spec] = Shape(spec)
        return cache[spec]
    return Shape(spec)


def _is_per_row(spec):
    """A sequence of per-row shapes: names, None or Shape objects (a list of
    facet dicts is one shape)."""
    if isinstance(spec, (str, dict, Shape)) or spec is None:
        return False
    if isinstance(spec, np.ndarray):
        return spec.dtype.names is None
    try:
        items = list(spec)
    except TypeError:
        return False
    return len(items) > 0 and all(x is None or isinstance(x, (str, Shape)) for x in items)


def facet_brdf(facet, to_source, to_observer):
    """oi_facet_brdf (1/sr) of one facet (a dict as for Shape, or a
    FACET_DTYPE record) for directions to the source and the observer (body
    frame, any length), elementwise over (N, 3) or (3,) directions.

    Example: a Lambertian facet's BRDF is albedo / pi, wherever the light
    comes from and goes to on its front:

    >>> import numpy as np, orbillum
    >>> f = {"normal": [0, 0, 1], "area_m2": 1.0, "albedo_diffuse": 0.3}
    >>> np.round(orbillum.facet_brdf(f, [0, 0, 1], [[0, 0, 1], [1, 0, 1]]), 6).tolist()
    [0.095493, 0.095493]
    >>> round(0.3 / np.pi, 6)
    0.095493
    """
    arr = _facet_array([facet] if isinstance(facet, dict) else np.atleast_1d(facet)[:1])
    c = L.oi_facet.from_buffer_copy(arr.tobytes())
    s = _vec(to_source, "to_source")
    o = _vec(to_observer, "to_observer")
    n = _n_rows(s, o)
    s = np.ascontiguousarray(np.broadcast_to(s, (n, 3)))
    o = np.ascontiguousarray(np.broadcast_to(o, (n, 3)))
    R3 = ctypes.c_double * 3
    return np.array([_lib.oi_facet_brdf(ctypes.byref(c), R3(*s[i]), R3(*o[i]))
                     for i in range(n)])
