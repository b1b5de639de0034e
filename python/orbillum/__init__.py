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
           "camera", "cameras", "status_name", "flag_names", "terms_mask",
           "library_path"] + _CONSTANTS

_lib = L.load()

SCENE_DTYPE = np.dtype(L.oi_scene)
ILLUM_DTYPE = np.dtype(L.oi_illum)
EXPOSURE_DTYPE = np.dtype(L.oi_exposure)
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
        if k in ("earth_table", "atm_table"):
            raise ValueError(f"model: {k} cannot be set from Python")
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


def _scenes(sun, moon, target, observer, terms, earth_albedo, target_albedo,
            target_radius_m):
    sun = _vec(sun, "sun")
    target = _vec(target, "target")
    moon = None if moon is None else _vec(moon, "moon")
    observer = None if observer is None else _vec(observer, "observer")
    n = _n_rows(sun, target, moon, observer)
    d = L.oi_scene()
    _lib.oi_scene_defaults(ctypes.addressof(d))
    sc = np.zeros(n, dtype=SCENE_DTYPE)  # fields not set below (velocities) stay 0: at rest
    sc["sun_km"] = sun
    sc["target_km"] = target
    sc["moon_km"] = 0.0 if moon is None else moon
    sc["observer_km"] = 0.0 if observer is None else observer
    sc["has_observer"] = 0 if observer is None else 1
    sc["has_moon"] = 0 if moon is None else 1  # the Moon occults the Sun whatever the terms
    if terms is None:
        mask = L.OI_TERM_SUN | L.OI_TERM_EARTH | (L.OI_TERM_MOON if moon is not None else 0)
        sc["terms"] = mask & d.terms
    elif isinstance(terms, (str, int, np.integer)):
        sc["terms"] = terms_mask(terms)
    else:
        t = list(terms)
        if len(t) != n:
            raise ValueError(f"terms: expected one per row ({n}), got {len(t)}")
        sc["terms"] = [terms_mask(x) for x in t]
    sc["earth_albedo"] = _scalar_rows(d.earth_albedo if earth_albedo is None else earth_albedo,
                                      n, "earth_albedo")
    sc["target_albedo"] = _scalar_rows(d.target_albedo if target_albedo is None
                                       else target_albedo, n, "target_albedo")
    sc["target_radius_m"] = _scalar_rows(d.target_radius_m if target_radius_m is None
                                         else target_radius_m, n, "target_radius_m")
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


def _illuminate_raw(sc, m):
    """oi_illuminate_batch over the scenes: one C call for every row."""
    n = sc.shape[0]
    res = np.empty(n, dtype=ILLUM_DTYPE)  # the batch writes (or zeroes) every row
    status = np.empty(n, dtype=np.intc)
    st = _lib.oi_illuminate_batch(n, sc.ctypes.data, _mptr(m), res.ctypes.data,
                                  status.ctypes.data)
    _batch_status(st, n, "model")
    return res, status


# ------------------------------------------------------------------ calls


def illuminate(sun, moon, target, observer=None, *, terms=None, earth_albedo=None,
               target_albedo=None, target_radius_m=None, model=None):
    """Light on the target from Sun, Earth and Moon, and what the observer sees.

    Given:
      sun, target      (N, 3) or (3,) km, Earth-centred inertial
      moon             (N, 3), (3,) or None (no Moon term)
      observer         (N, 3), (3,) or None (no observer: flux_* and mag_v are 0)
      terms            None (sun+earth, +moon when moon is given), 'sun+earth', a
                       mask (OI_TERM_*), or one of these per row
      earth_albedo, target_albedo, target_radius_m   scalars or (N,); None: the C
                       defaults (oi_scene_defaults: 0.30, 0.2, 1.0 m)
      model            None (defaults) or dict of oi_model fields, e.g.
                       {"earth_model": "lambert", "limb_darkening": "darkened"}
    Returns: dict of arrays, one entry per oi_illum field (nested shadow fields as
      shadow_*; aliases sun_fraction, sun_fraction_ld, sun_fraction_atm;
      dir_* of shape (N, 3)), plus status (int32) and status_name.
    """
    m = _model(model)
    sc = _scenes(sun, moon, target, observer, terms, earth_albedo, target_albedo,
                 target_radius_m)
    res, status = _illuminate_raw(sc, m)
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


def _goal(fill, snr_min, sky=None):
    if fill is None and snr_min is None and sky is None:
        return None
    g = L.oi_expose_goal()
    g.fill = 0.0 if fill is None else fill
    g.snr_min = 0.0 if snr_min is None else snr_min
    g.sky = 0 if sky is None else int(sky)
    return g


def _exposure_dict(ex, st):
    out = {"expose_status": st, "expose_status_name": _status_names(st)}
    for name in ex.dtype.names:
        out[name] = ex[name]
    out["flag_names"] = _names_of(ex["flags"], flag_names)
    return out


def expose(camera, sun, moon, target, observer, *, terms=None, earth_albedo=None,
           target_albedo=None, target_radius_m=None, model=None, fill=None, snr_min=None,
           sky=None):
    """oi_illuminate then oi_expose_scene for each row: the suggested exposure.

    camera: a built-in camera name (see cameras()), a dict as camera() returns
    (a custom camera), or an oi_camera structure.
    observer: required (the exposure is what the observer's camera sees):
    None raises ValueError.
    fill, snr_min: the oi_expose_goal (None: the C defaults).
    sky: oi_expose_goal.sky, OI_SKY_* bits (orbillum._lib; None or 0: no sky
    background but the sunlit Earth, as before).
    Returns the dict of illuminate() plus the oi_exposure fields (exposure_s,
    gain, time_index, gain_index, signal_e, background_e, peak_e, saturation_e,
    fill, snr, sun_angle_rad, flags, background_w_m2_sr), flag_names, expose_status and
    expose_status_name. Rows whose illumination failed are not exposed
    (expose_status equals their illumination status, exposure fields 0).
    row_status / row_status_name: the status build/oi-plan prints for the row.
    """
    if observer is None:
        raise ValueError("observer: expose needs the observer's position, (N, 3) or (3,) km "
                         "(the exposure is that of the observer's camera); for the light "
                         "alone call illuminate()")
    cp, _ = _camera_ptr(camera)
    m = _model(model)
    g = _goal(fill, snr_min, sky)
    sc = _scenes(sun, moon, target, observer, terms, earth_albedo, target_albedo,
                 target_radius_m)
    res, status = _illuminate_raw(sc, m)
    n = sc.shape[0]
    ex = np.empty(n, dtype=EXPOSURE_DTYPE)  # the batch writes every row
    est = np.empty(n, dtype=np.intc)
    st = _lib.oi_expose_scene_batch(n, cp, sc.ctypes.data, res.ctypes.data, _mptr(m), _mptr(g),
                                    ex.ctypes.data, est.ctypes.data)
    _batch_status(st, n, "camera or model")
    # rows whose illumination failed are not exposed: their status, zero fields
    failed = status < 0
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
                snr_min=None):
    """oi_expose per row from a flux at the aperture (W/m^2), a background
    radiance (W/m^2/sr) and known flags. Returns the oi_exposure fields."""
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
    g = _goal(fill, snr_min)
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
