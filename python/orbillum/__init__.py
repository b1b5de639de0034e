# SPDX-License-Identifier: MIT
"""orbillum: numpy-vectorised binding of the orbillum C runtime (double build).

Every function takes arrays of epochs: positions of shape (N, 3) in km,
Earth-centred inertial (any one frame, e.g. GCRS), or (3,) for one epoch;
per-row scalars as scalars or arrays of length N. Results are dicts of numpy
arrays of length N. Each row is one call of the C function with the same
inputs, so the numbers are exactly those of the C library (and of
``build/oi-plan --csv`` on the same rows). Errors are per row: ``status`` < 0
(names in ``status_name``) with every output of that row zero, as in C.

    import orbillum
    r = orbillum.illuminate(sun, moon, target, observer)
    x = orbillum.expose("telescope-15cm", sun, moon, target, observer)

The target is the scene's Lambertian sphere, or a shape of flat facets
(``target_shape``: a built-in name, or facets; ``attitude_q``: quaternions
body -> input frame per row), as include/orbillum.h's oi_shape.
"""
import ctypes

import numpy as np

from . import _lib as L

# Every OI_* constant of the header by its C name (statuses OI_OK, OI_WARN_*,
# OI_ERR_*; flags, terms, model options, bounds, OI_BATCH_*): taken from the
# mirror, which tests/python/test_binding_abi.py holds equal to the header, so
# that a constant added there is exported here too.
_CONSTANTS = sorted(n for n in vars(L) if n.startswith("OI_"))
globals().update({n: getattr(L, n) for n in _CONSTANTS})

__all__ = ["illuminate", "expose", "expose_flux", "sun_fraction", "earthshine",
           "lambert_phase", "moon_phase_law", "magnitude_v", "flux_from_magnitude",
           "starlight_radiance", "galactic",
           "camera", "cameras", "status_name", "flag_names", "terms_mask",
           "Shape", "shape", "shapes", "facet_brdf", "FACET_DTYPE",
           "library_path"] + _CONSTANTS

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
    """Path of the loaded liborbillum.so."""
    return _lib._orbillum_path


# ------------------------------------------------------------------ names


def status_name(status):
    """Name of a status code ("OK", "ERR_NONFINITE", ...), as oi_status_name."""
    return _lib.oi_status_name(int(status)).decode()


def _names_of(values, name_fn):
    """name_fn of every element of an integer array, one call per distinct
    value: a table over the values' small range (statuses, flag masks),
    np.unique beyond it."""
    v = np.asarray(values).astype(np.int64, copy=False)
    if v.size == 0:
        return np.empty(v.shape, dtype=object)
    lo, hi = int(v.min()), int(v.max())
    if hi - lo > 4096:
        codes, inverse = np.unique(v, return_inverse=True)
        return np.array([name_fn(c) for c in codes], dtype=object)[inverse].reshape(v.shape)
    present = np.bincount((v - lo).ravel(), minlength=hi - lo + 1) > 0
    table = np.empty(hi - lo + 1, dtype=object)
    for i in np.flatnonzero(present):
        table[i] = name_fn(lo + int(i))
    return table[v - lo]


def _status_names(status):
    """oi_status_name of every element."""
    return _names_of(status, status_name)


def flag_names(flags):
    """Names of the OI_FLAG_* bits set in ``flags``, '+'-joined ('' for none)."""
    out = []
    bit = 1
    f = int(flags)
    while bit <= f:
        if f & bit:
            n = _lib.oi_flag_name(bit)
            out.append(n.decode() if n else f"bit{bit.bit_length() - 1}")
        bit <<= 1
    return "+".join(out)


_TERM_BITS = {"sun": L.OI_TERM_SUN, "earth": L.OI_TERM_EARTH, "moon": L.OI_TERM_MOON,
              "sky": L.OI_TERM_SKY}


def terms_mask(terms):
    """'sun+earth+moon+sky' (any subset, any order, '+'-joined; 'all' = sun+earth+moon,
    sky is opt-in; '' = none) -> mask."""
    if isinstance(terms, (int, np.integer)):
        return int(terms)
    s = str(terms).strip().lower()
    if s == "all":
        return L.OI_TERM_ALL
    m = 0
    for part in filter(None, (p.strip() for p in s.split("+"))):
        if part not in _TERM_BITS:
            raise ValueError(f"unknown term {part!r}: use sun, earth, moon, sky joined by '+'")
        m |= _TERM_BITS[part]
    return m


# ------------------------------------------------------------------ model

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


# ------------------------------------------------------------------ shapes

_FACET_REQUIRED = ("normal", "area_m2", "albedo_diffuse")
_FACET_DEFAULTS = {"two_sided": 0, "albedo_specular": 0.0, "shininess": 0.0}
_FACET_RULES = ("a nonzero finite normal, area_m2 in (0, 1e8], albedos in [0, 1] summing to "
                "at most 1, shininess in [0, OI_SHININESS_MAX]")


def shapes():
    """Names of the built-in shapes (oi_shape_builtin), "sphere" first (the
    scene's Lambertian sphere: no shape)."""
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
    """A Shape (see Shape): a built-in name or facets."""
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
    frame, any length), elementwise over (N, 3) or (3,) directions."""
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


# ------------------------------------------------------------------ arrays


def _floats(a, name):
    """a as a float64 array; TypeError naming the argument when it is not numbers."""
    try:
        return np.asarray(a, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{name}: expected numbers, got {a!r:.60} ({e})") from None


def _vec(a, name, n=None):
    a = _floats(a, name)
    if a.shape == (3,):
        a = a[None, :]
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError(f"{name}: expected shape (N, 3) or (3,), got {a.shape}")
    return a


def _n_rows(*arrays):
    n = 1
    for a in arrays:
        if a is not None and a.shape[0] != 1:
            if n != 1 and a.shape[0] != n:
                raise ValueError(f"row counts differ: {n} and {a.shape[0]}")
            n = a.shape[0]
    return n


def _scalar_rows(v, n, name):
    a = _floats(v, name)
    if a.ndim == 0:
        return np.full(n, float(a))
    if a.shape != (n,):
        raise ValueError(f"{name}: expected a scalar or shape ({n},), got {a.shape}")
    return a


def _attitudes(q):
    """attitude_q: None, (4,) or (N, 4) quaternions (w, x, y, z)."""
    if q is None:
        return None
    a = _floats(q, "attitude_q")
    if a.shape == (4,):
        a = a[None, :]
    if a.ndim != 2 or a.shape[1] != 4:
        raise ValueError(f"attitude_q: expected shape (N, 4) or (4,) (w, x, y, z), got {a.shape}")
    return a


def _scenes(sun, moon, target, observer, terms, earth_albedo, target_albedo,
            target_radius_m, target_velocity=None, observer_velocity=None,
            target_shape=None, attitude_q=None, keep=None, epoch_jd=None,
            earth_rotation_rad=None):
    """The scenes' structured array. keep: a list that receives the Shape
    objects the rows point to (the caller holds it while the C calls run)."""
    sun = _vec(sun, "sun")
    target = _vec(target, "target")
    moon = None if moon is None else _vec(moon, "moon")
    observer = None if observer is None else _vec(observer, "observer")
    tv = None if target_velocity is None else _vec(target_velocity, "target_velocity")
    ov = None if observer_velocity is None else _vec(observer_velocity, "observer_velocity")
    q = _attitudes(attitude_q)
    per_row = _is_per_row(target_shape)
    row_shapes = list(target_shape) if per_row else None
    n = _n_rows(sun, target, moon, observer, tv, ov, q,
                None if row_shapes is None else np.empty((len(row_shapes), 0)))
    d = L.oi_scene()
    _lib.oi_scene_defaults(ctypes.addressof(d))
    # One template record (the defaults, the scalars, the masks), copied to
    # every row in one pass; then only the per-row columns are written: each
    # field write is a strided pass over the whole record array.
    tpl = np.zeros(1, dtype=SCENE_DTYPE)  # velocities not given stay 0: at rest
    tpl["has_observer"] = 0 if observer is None else 1
    tpl["has_moon"] = 0 if moon is None else 1  # the Moon occults the Sun whatever the terms
    per_row_terms = None
    if terms is None:
        mask = L.OI_TERM_SUN | L.OI_TERM_EARTH | (L.OI_TERM_MOON if moon is not None else 0)
        tpl["terms"] = mask & d.terms
    elif isinstance(terms, (str, int, np.integer)):
        tpl["terms"] = terms_mask(terms)
    else:
        t = list(terms)
        if len(t) != n:
            raise ValueError(f"terms: expected one per row ({n}), got {len(t)}")
        per_row_terms = [terms_mask(x) for x in t]
    columns = {}
    for name, given, default in (("earth_albedo", earth_albedo, d.earth_albedo),
                                 ("target_albedo", target_albedo, d.target_albedo),
                                 ("target_radius_m", target_radius_m, d.target_radius_m),
                                 ("epoch_jd", epoch_jd, None),
                                 ("earth_rotation_rad", earth_rotation_rad, None)):
        if given is None:
            if default is not None:
                tpl[name] = default
            continue
        a = _floats(given, name)
        if a.ndim == 0:
            tpl[name] = float(a)
        elif a.shape != (n,):
            raise ValueError(f"{name}: expected a scalar or shape ({n},), got {a.shape}")
        else:
            columns[name] = a
    for name, v in (("sun_km", sun), ("target_km", target), ("moon_km", moon),
                    ("observer_km", observer), ("target_vel_km_s", tv),
                    ("observer_vel_km_s", ov), ("attitude_q", q)):  # attitude all 0: identity
        if v is not None and v.shape[0] == 1:
            tpl[name] = v[0]
        elif v is not None:
            columns[name] = v
    sc = np.empty(n, dtype=SCENE_DTYPE)
    # the template's bytes to every row: a plain byte copy (assigning the
    # record itself goes field by field, ~15x slower)
    sc.view(np.uint8).reshape(n, SCENE_DTYPE.itemsize)[:] = tpl.view(np.uint8)
    for name, v in columns.items():
        sc[name] = v
    if per_row_terms is not None:
        sc["terms"] = per_row_terms
    cache = {}
    if per_row:
        if len(row_shapes) != n:
            raise ValueError(f"target_shape: expected one per row ({n}), got {len(row_shapes)}")
        held = [_shape_of(x, cache) for x in row_shapes]
        sc["shape"] = [0 if k is None else k.address for k in held]
    else:
        held = [_shape_of(target_shape, cache)]
        sc["shape"] = 0 if held[0] is None else held[0].address
    if keep is not None:
        keep.extend(held)
    elif any(k is not None for k in held):
        raise ValueError("target_shape: internal: a shape without a keep list")
    return sc


def _flatten(rec, status):
    """The batch's records as a dict of arrays: views of the record array's
    fields (no copy; strided), nested shadow fields as shadow_*."""
    out = {"status": status, "status_name": _status_names(status)}
    for name in rec.dtype.names:
        col = rec[name]
        if col.dtype.names:  # nested struct (shadow)
            for sub in col.dtype.names:
                out[f"shadow_{sub}"] = col[sub]
        else:
            out[name] = col
    out["sun_fraction"] = out["shadow_fraction"]
    out["sun_fraction_ld"] = out["shadow_fraction_ld"]
    out["sun_fraction_atm"] = out["shadow_fraction_atm"]
    return out


def _batch_status(st, n, what):
    """A batch call's own error (the model, the camera: every row has it) as a
    ValueError; row errors stay in the status array."""
    if st < 0 and n > 0:
        raise ValueError(f"{what}: {status_name(st)} (a field out of its range: see "
                         f"include/orbillum.h)")


def _outputs_mask(outputs):
    """The outputs mask of oi_illuminate_batch_outputs: None (every output: the
    plain oi_illuminate_batch) or OI_BATCH_* bits within OI_BATCH_SCENE_ALL."""
    if outputs is None:
        return None
    if isinstance(outputs, (bool, np.bool_)) or not isinstance(outputs, (int, np.integer)):
        raise TypeError(f"outputs: a mask of OI_BATCH_* bits or None, got {outputs!r}")
    if int(outputs) < 0 or int(outputs) & ~L.OI_BATCH_SCENE_ALL:
        raise ValueError(f"outputs: unknown bits in {int(outputs):#x} (OI_BATCH_SCENE_ALL is "
                         f"{L.OI_BATCH_SCENE_ALL:#x})")
    return int(outputs)


def _illuminate_raw(sc, m, outputs=None):
    """oi_illuminate_batch (or, with an outputs mask,
    oi_illuminate_batch_outputs) over the scenes: one C call for every row."""
    n = sc.shape[0]
    res = np.empty(n, dtype=ILLUM_DTYPE)  # the batch writes (or zeroes) every row
    status = np.empty(n, dtype=np.intc)
    if outputs is None:
        st = _lib.oi_illuminate_batch(n, sc.ctypes.data, _mptr(m), res.ctypes.data,
                                      status.ctypes.data)
    else:
        st = _lib.oi_illuminate_batch_outputs(n, sc.ctypes.data, _mptr(m), outputs,
                                              res.ctypes.data, status.ctypes.data)
    _batch_status(st, n, "model")
    return res, status


# ------------------------------------------------------------------ calls


def illuminate(sun, moon, target, observer=None, *, terms=None, earth_albedo=None,
               target_albedo=None, target_radius_m=None, target_shape=None, attitude_q=None,
               model=None, epoch_jd=None, earth_rotation_rad=None, outputs=None):
    """Light on the target from Sun, Earth and Moon, and what the observer sees.

    Given:
      sun, target      (N, 3) or (3,) km, Earth-centred inertial
      moon             (N, 3), (3,) or None (no Moon term)
      observer         (N, 3), (3,) or None (no observer: flux_* and mag_v are 0)
      terms            None (sun+earth, +moon when moon is given), 'sun+earth', a
                       mask (OI_TERM_*), or one of these per row
      earth_albedo, target_albedo, target_radius_m   scalars or (N,); None: the C
                       defaults (oi_scene_defaults: 0.30, 0.2, 1.0 m)
      target_shape     None or 'sphere' (the Lambertian sphere of target_radius_m
                       and target_albedo), a built-in shape's name (shapes():
                       'plate', 'box-wing', 'cylinder'), a Shape, facets (as
                       Shape takes them), or a sequence of names / Shapes / None,
                       one per row. ValueError for an unknown name or a facet the
                       library rejects (naming it)
      attitude_q       None (identity) or quaternions (w, x, y, z) body -> input
                       frame, (4,) or (N, 4); a norm off 1 by more than 1e-6 (NaN
                       too) is the row's status ERR_SHAPE, else it is normalised
      model            None (defaults) or dict of oi_model fields, e.g.
                       {"earth_model": "lambert", "limb_darkening": "darkened"};
                       albedo models: {"albedo_model": "knocke"}, or {"albedo_model":
                       "map", "albedo_map": grid}, grid (n_lat, n_lon) values in [0, 1],
                       rows north to south, cells east from Greenwich
                       (docs/earthshine-albedo.md; the frame's z axis the Earth's
                       rotation axis)
      epoch_jd         scalar or (N,): Julian date (UTC), read by "knocke"
      earth_rotation_rad  scalar or (N,): the Greenwich meridian from the frame's
                       x axis, read by "map"
      outputs          None (every field) or a mask of OI_BATCH_* bits
                       (oi_illuminate_batch_outputs: OI_BATCH_FRACTION_LD,
                       OI_BATCH_GEOMETRY, OI_BATCH_DIRECTIONS, OI_BATCH_OBSERVER;
                       the irradiances, shadow fraction, fraction_atm and region
                       always): the fields left out are 0 and not computed, the
                       others the same bits (docs/performance.md, "Batch
                       interface"). TypeError / ValueError for a non-integer or
                       unknown bits
    Returns: dict of arrays, one entry per oi_illum field (nested shadow fields as
      shadow_*; aliases sun_fraction, sun_fraction_ld, sun_fraction_atm;
      dir_* of shape (N, 3); flux_specular, the facets' specular part of
      flux_obs), plus status (int32) and status_name.
    """
    mask = _outputs_mask(outputs)
    m = _model(model)
    keep = []
    sc = _scenes(sun, moon, target, observer, terms, earth_albedo, target_albedo,
                 target_radius_m, target_shape=target_shape, attitude_q=attitude_q, keep=keep,
                 epoch_jd=epoch_jd, earth_rotation_rad=earth_rotation_rad)
    res, status = _illuminate_raw(sc, m, mask)
    return _flatten(res, status)


_CAMERA_LISTS = {"times_s": ("n_times", L.OI_CAMERA_MAX_TIMES),
                 "gains": ("n_gains", L.OI_CAMERA_MAX_GAINS),
                 "read_noise_e": ("n_gains", L.OI_CAMERA_MAX_GAINS)}


def _camera_from_dict(d):
    """An oi_camera from the dict camera() returns (every field; the counts
    n_times, n_gains may be left out: the lists' lengths). The C library
    checks the values (OI_ERR_CAMERA); this checks the names and types."""
    c = L.oi_camera()
    fields = dict(L.oi_camera._fields_)
    unknown = sorted(set(d) - set(fields))
    if unknown:
        raise ValueError(f"camera: unknown field(s) {', '.join(map(repr, unknown))}")
    counts = {}
    for k, (count, cap) in _CAMERA_LISTS.items():
        if k not in d:
            raise ValueError(f"camera: field {k!r} missing")
        v = _floats(d[k], f"camera[{k!r}]")
        if v.ndim != 1 or not 1 <= v.size <= cap:
            raise ValueError(f"camera[{k!r}]: 1 to {cap} numbers, got shape {v.shape}")
        if counts.setdefault(count, v.size) != v.size:
            raise ValueError(f"camera[{k!r}]: {v.size} values, {count} is {counts[count]}")
        getattr(c, k)[:v.size] = [float(x) for x in v]
    for count, size in counts.items():
        if count in d and int(d[count]) != size:
            raise ValueError(f"camera[{count!r}] = {d[count]} but the lists have {size}")
        setattr(c, count, size)
    for k, t in fields.items():
        if k in _CAMERA_LISTS or k in counts:
            continue
        if k == "name":
            name = d.get("name")
            if name is not None and not isinstance(name, str):
                raise TypeError(f"camera['name']: a string, got {type(name).__name__}")
            c._name = None if name is None else name.encode()  # kept alive with c
            c.name = c._name
            continue
        if k not in d:
            raise ValueError(f"camera: field {k!r} missing")
        v = d[k]
        if isinstance(v, (str, bytes)) or not isinstance(v, (int, float, np.integer, np.floating)):
            raise TypeError(f"camera[{k!r}]: a number, got {type(v).__name__}")
        setattr(c, k, float(v))
    return c


def _camera_ptr(cam):
    if isinstance(cam, str):
        p = _lib.oi_camera_find(cam.encode())
        if not p:
            raise ValueError(f"no built-in camera {cam!r}; built-in: {', '.join(cameras())}")
        return ctypes.cast(p, ctypes.c_void_p).value, p.contents
    if isinstance(cam, dict):
        cam = _camera_from_dict(cam)
    if isinstance(cam, L.oi_camera):
        return ctypes.addressof(cam), cam
    raise TypeError("camera: a built-in camera name, a dict as camera() returns, or an "
                    "orbillum._lib.oi_camera")


def _goal(fill, snr_min, sky=None, sensor_temp_c=None):
    if fill is None and snr_min is None and sky is None and sensor_temp_c is None:
        return None
    g = L.oi_expose_goal()
    g.fill = 0.0 if fill is None else fill
    g.snr_min = 0.0 if snr_min is None else snr_min
    g.sky = 0 if sky is None else int(sky)
    if sensor_temp_c is not None:
        g.has_sensor_temp = 1
        g.sensor_temp_c = float(sensor_temp_c)
    return g


def _exposure_dict(ex, st):
    out = {"expose_status": st, "expose_status_name": _status_names(st)}
    for name in ex.dtype.names:
        out[name] = ex[name]
    out["flag_names"] = _names_of(ex["flags"], flag_names)
    return out


def expose(camera, sun, moon, target, observer, *, terms=None, earth_albedo=None,
           target_albedo=None, target_radius_m=None, target_shape=None, attitude_q=None,
           model=None, fill=None, snr_min=None, sky=None, target_velocity=None,
           observer_velocity=None, epoch_jd=None, earth_rotation_rad=None, sensor_temp_c=None,
           outputs=None):
    """oi_illuminate then oi_expose_scene for each row: the suggested exposure.

    camera: a built-in camera name (see cameras()), a dict as camera() returns
    (a custom camera), or an oi_camera structure.
    observer: required (the exposure is what the observer's camera sees):
    None raises ValueError.
    fill, snr_min: the oi_expose_goal (None: the C defaults).
    sky: oi_expose_goal.sky, OI_SKY_* bits (orbillum._lib; None or 0: no sky
    background but the sunlit Earth, as before).
    target_velocity, observer_velocity: (N, 3), (3,) or None (at rest), km/s in
    the positions' frame: the target's angular rate and trail (the planner's
    target_v*, observer_v* columns; docs/camera.md, "Motion").
    target_shape, attitude_q: as illuminate(); a shape whose specular part is
    more than half of flux_obs sets OI_FLAG_GLINT ('glint').
    epoch_jd, earth_rotation_rad: as illuminate() (the albedo models).
    sensor_temp_c: the sensor's temperature (deg C; oi_expose_goal.has_sensor_temp,
    sensor_temp_c; None: the camera's dark_current_e_s as it stands).
    Returns the dict of illuminate() plus the oi_exposure fields (exposure_s,
    gain, time_index, gain_index, signal_e, background_e, peak_e, saturation_e,
    fill, snr, sun_angle_rad, flags, background_w_m2_sr), flag_names, expose_status and
    expose_status_name. Rows whose illumination failed are not exposed
    (expose_status equals their illumination status, exposure fields 0).
    row_status / row_status_name: the status build/oi-plan prints for the row.
    outputs: None (every exposure field) or a mask of OI_EXPOSE_* bits
    (oi_expose_scene_batch_outputs: OI_EXPOSE_SETTING, FAINT, DETECT, SUN_ANGLE,
    BACKGROUND, RATE; docs/camera.md, "Batches and their outputs mask"): the
    fields left out are 0 and not computed, the others the same bits.
    """
    if observer is None:
        raise ValueError("observer: expose needs the observer's position, (N, 3) or (3,) km "
                         "(the exposure is that of the observer's camera); for the light "
                         "alone call illuminate()")
    if outputs is None:
        emask = L.OI_EXPOSE_ALL
    elif isinstance(outputs, (bool, np.bool_)) or not isinstance(outputs, (int, np.integer)):
        raise TypeError(f"outputs: a mask of OI_EXPOSE_* bits or None, got {outputs!r}")
    elif int(outputs) < 0 or int(outputs) & ~L.OI_EXPOSE_ALL:
        raise ValueError(f"outputs: unknown bits in {int(outputs):#x} (OI_EXPOSE_ALL is "
                         f"{L.OI_EXPOSE_ALL:#x})")
    else:
        emask = int(outputs)
    cp, _ = _camera_ptr(camera)
    m = _model(model)
    g = _goal(fill, snr_min, sky, sensor_temp_c)
    keep = []
    sc = _scenes(sun, moon, target, observer, terms, earth_albedo, target_albedo,
                 target_radius_m, target_velocity, observer_velocity, target_shape=target_shape,
                 attitude_q=attitude_q, keep=keep, epoch_jd=epoch_jd,
                 earth_rotation_rad=earth_rotation_rad)
    res, status = _illuminate_raw(sc, m)
    n = sc.shape[0]
    ex = np.empty(n, dtype=EXPOSURE_DTYPE)  # the batch writes every row
    est = np.empty(n, dtype=np.intc)
    # the camera, model and goal formed once (with OI_EXPOSE_ALL the rows are
    # oi_expose_scene_batch's bits)
    st = _lib.oi_expose_scene_batch_outputs(n, cp, sc.ctypes.data, res.ctypes.data, _mptr(m),
                                            _mptr(g), emask, ex.ctypes.data, est.ctypes.data)
    _batch_status(st, n, "camera or model")
    # rows whose illumination failed are not exposed: their status, zero fields
    failed = status < 0
    if failed.any():  # two masked passes spared on the common all-valid batch
        est[failed] = status[failed]
        ex[failed] = np.zeros(1, dtype=EXPOSURE_DTYPE)
    out = _flatten(res, status)
    out.update(_exposure_dict(ex, est))
    # the planner's row status: the illumination's (warnings included) unless
    # the exposure failed
    row = np.where(est < 0, est, status).astype(np.int32)
    out["row_status"] = row
    out["row_status_name"] = _status_names(row)
    return out


def expose_flux(camera, flux_w_m2, background_w_m2_sr=0.0, flags=0, *, fill=None,
                snr_min=None, sensor_temp_c=None):
    """oi_expose per row from a flux at the aperture (W/m^2), a background
    radiance (W/m^2/sr) and known flags; sensor_temp_c as in expose().
    Returns the oi_exposure fields."""
    cp, _ = _camera_ptr(camera)
    flux = np.atleast_1d(_floats(flux_w_m2, "flux_w_m2"))
    if flux.ndim != 1:
        raise ValueError(f"flux_w_m2: expected a scalar or shape (N,), got {flux.shape}")
    n = flux.shape[0]
    bg = _scalar_rows(background_w_m2_sr, n, "background_w_m2_sr")
    try:
        fl = np.broadcast_to(np.asarray(flags, dtype=np.uint32), (n,))
    except (TypeError, ValueError, OverflowError) as e:
        raise ValueError(f"flags: a mask of OI_FLAG_* or one per row ({n}): {e}") from None
    g = _goal(fill, snr_min, sensor_temp_c=sensor_temp_c)
    inp = np.zeros(n, dtype=np.dtype(L.oi_expose_in))
    inp["flux_w_m2"] = flux
    inp["background_w_m2_sr"] = bg
    inp["flags"] = fl
    ex = np.empty(n, dtype=EXPOSURE_DTYPE)  # the batch writes every row
    st = np.empty(n, dtype=np.intc)
    bst = _lib.oi_expose_batch(n, cp, inp.ctypes.data, _mptr(g), ex.ctypes.data, st.ctypes.data)
    _batch_status(bst, n, "camera")
    return _exposure_dict(ex, st)


def sun_fraction(sun, point, *, model=None, outputs=None):
    """oi_sun_fraction per row (one oi_sun_fraction_batch call): dict of the
    oi_shadow fields and status. outputs: None (every field) or a mask of
    OI_BATCH_* bits (fraction and region always; the fields left out are 0,
    and cost nothing: OI_BATCH_FRACTION_LD, OI_BATCH_ATMOSPHERE,
    OI_BATCH_GEOMETRY)."""
    sun = _vec(sun, "sun")
    point = _vec(point, "point")
    n = _n_rows(sun, point)
    sun = np.ascontiguousarray(np.broadcast_to(sun, (n, 3)))
    point = np.ascontiguousarray(np.broadcast_to(point, (n, 3)))
    m = _model(model)
    mask = L.OI_BATCH_ALL if outputs is None else outputs
    if not isinstance(mask, (int, np.integer)) or isinstance(mask, bool):
        raise TypeError(f"outputs: a mask of OI_BATCH_* bits or None, got {outputs!r}")
    if int(mask) & ~L.OI_BATCH_ALL or int(mask) < 0:
        raise ValueError(f"outputs: unknown bits in {int(mask):#x} (OI_BATCH_ALL is "
                         f"{L.OI_BATCH_ALL:#x})")
    sh = np.empty(n, dtype=np.dtype(L.oi_shadow))  # the batch writes every row
    st = np.empty(n, dtype=np.intc)
    bst = _lib.oi_sun_fraction_batch(n, sun.ctypes.data, point.ctypes.data, _mptr(m), int(mask),
                                     sh.ctypes.data, st.ctypes.data)
    _batch_status(bst, n, "model")
    out = {k: sh[k] for k in sh.dtype.names}
    out["status"] = st
    return out


def earthshine(theta, h_km, *, model=None):
    """oi_earthshine per element (one oi_earthshine_batch call): (phi, psi,
    status) arrays of the broadcast shape of theta and h_km."""
    try:
        th, h = np.broadcast_arrays(_floats(theta, "theta"), _floats(h_km, "h_km"))
    except ValueError as e:
        raise ValueError(f"theta, h_km: shapes do not broadcast ({e})") from None
    shape = th.shape
    th = np.ascontiguousarray(th).ravel()
    h = np.ascontiguousarray(h).ravel()
    phi = np.empty(th.size)  # the batch writes every element
    psi = np.empty(th.size)
    st = np.empty(th.size, dtype=np.intc)
    m = _model(model)
    bst = _lib.oi_earthshine_batch(th.size, th.ctypes.data, h.ctypes.data, _mptr(m),
                                   phi.ctypes.data, psi.ctypes.data, st.ctypes.data)
    _batch_status(bst, th.size, "model")
    return phi.reshape(shape), psi.reshape(shape), st.reshape(shape)


def _elementwise(fn, x):
    x = np.asarray(x, dtype=np.float64)
    return np.vectorize(lambda v: fn(float(v)), otypes=[np.float64])(x)


def lambert_phase(xi):
    """Lambertian sphere phase function p(xi) (oi_lambert_phase), elementwise."""
    return _elementwise(_lib.oi_lambert_phase, xi)


def moon_phase_law(alpha):
    """Lunar phase law relative to full Moon (oi_moon_phase_law), elementwise."""
    return _elementwise(_lib.oi_moon_phase_law, alpha)


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


def cameras():
    """Names of the built-in cameras, in index order."""
    out = []
    i = 0
    while True:
        p = _lib.oi_camera_builtin(i)
        if not p:
            return out
        out.append(p.contents.name.decode())
        i += 1


def camera(name):
    """A built-in camera's parameters as a dict (times_s, gains, read_noise_e as lists)."""
    _, c = _camera_ptr(name)
    d = {}
    for f, _t in L.oi_camera._fields_:
        v = getattr(c, f)
        if f == "name":
            v = v.decode()
        elif f == "times_s":
            v = list(v)[:c.n_times]
        elif f in ("gains", "read_noise_e"):
            v = list(v)[:c.n_gains]
        d[f] = v
    return d
