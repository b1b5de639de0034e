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

# Every status, flag and term constant of the header, by its C name
# (OI_OK, OI_WARN_*, OI_ERR_*, OI_FLAG_*, OI_TERM_*): taken from the mirror so
# that a code added there is exported here too.
_CONSTANTS = sorted(n for n in vars(L) if n == "OI_OK" or
                    n.startswith(("OI_WARN_", "OI_ERR_", "OI_FLAG_", "OI_TERM_")))
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


_TERM_BITS = {"sun": L.OI_TERM_SUN, "earth": L.OI_TERM_EARTH, "moon": L.OI_TERM_MOON}


def terms_mask(terms):
    """'sun+earth+moon' (any subset, any order, '+'-joined; 'all'; '' = none) -> mask."""
    if isinstance(terms, (int, np.integer)):
        return int(terms)
    s = str(terms).strip().lower()
    if s == "all":
        return L.OI_TERM_ALL
    m = 0
    for part in filter(None, (p.strip() for p in s.split("+"))):
        if part not in _TERM_BITS:
            raise ValueError(f"unknown term {part!r}: use sun, earth, moon joined by '+'")
        m |= _TERM_BITS[part]
    return m


# ------------------------------------------------------------------ model

_MODEL_WORDS = {
    "earth_model": {"table": 0, "lambert": 1},
    "moon_model": {"phase_law": 0, "lambert": 1},
    "limb_darkening": {"uniform": 0, "darkened": 1},
}


def _model(model):
    """None -> NULL (defaults); dict of oi_model fields (words allowed) -> struct."""
    if model is None:
        return None
    m = L.oi_model()
    for k, v in dict(model).items():
        if k in ("earth_table", "atm_table"):
            raise ValueError(f"{k} cannot be set from Python")
        if not any(k == f[0] for f in L.oi_model._fields_):
            raise ValueError(f"unknown model field {k!r}")
        if isinstance(v, str):
            v = _MODEL_WORDS[k][v]
        setattr(m, k, int(v) if isinstance(v, (bool, np.bool_)) else v)
    return m


def _mptr(m):
    return None if m is None else ctypes.addressof(m)


# ------------------------------------------------------------------ arrays


def _vec(a, name, n=None):
    a = np.asarray(a, dtype=np.float64)
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
    a = np.asarray(v, dtype=np.float64)
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
    sc = np.zeros(n, dtype=SCENE_DTYPE)
    sc["sun_km"] = sun
    sc["target_km"] = target
    if moon is not None:
        sc["moon_km"] = moon
    if observer is not None:
        sc["observer_km"] = observer
        sc["has_observer"] = 1
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
    out = {"status": status,
           "status_name": np.array([status_name(s) for s in status], dtype=object)}
    for name in rec.dtype.names:
        col = rec[name]
        if col.dtype.names:  # nested struct (shadow)
            for sub in col.dtype.names:
                out[f"shadow_{sub}"] = np.array(col[sub])
        else:
            out[name] = np.array(col)
    out["sun_fraction"] = out["shadow_fraction"]
    out["sun_fraction_ld"] = out["shadow_fraction_ld"]
    out["sun_fraction_atm"] = out["shadow_fraction_atm"]
    return out


def _illuminate_raw(sc, m):
    n = sc.shape[0]
    res = np.zeros(n, dtype=ILLUM_DTYPE)
    status = np.zeros(n, dtype=np.int32)
    fn = _lib.oi_illuminate
    mp = _mptr(m)
    s0, ss = sc.ctypes.data, sc.itemsize
    r0, rs = res.ctypes.data, res.itemsize
    for i in range(n):
        status[i] = fn(s0 + i * ss, mp, r0 + i * rs)
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


def _camera_ptr(cam):
    if isinstance(cam, str):
        p = _lib.oi_camera_find(cam.encode())
        if not p:
            raise ValueError(f"no built-in camera {cam!r}; built-in: {', '.join(cameras())}")
        return ctypes.cast(p, ctypes.c_void_p).value, p.contents
    if isinstance(cam, L.oi_camera):
        return ctypes.addressof(cam), cam
    raise TypeError("camera: a built-in camera name or an orbillum._lib.oi_camera")


def _goal(fill, snr_min, sky=None):
    if fill is None and snr_min is None and sky is None:
        return None
    g = L.oi_expose_goal()
    g.fill = 0.0 if fill is None else fill
    g.snr_min = 0.0 if snr_min is None else snr_min
    g.sky = 0 if sky is None else int(sky)
    return g


def _exposure_dict(ex, st):
    out = {"expose_status": st,
           "expose_status_name": np.array([status_name(s) for s in st], dtype=object)}
    for name in ex.dtype.names:
        out[name] = np.array(ex[name])
    out["flag_names"] = np.array([flag_names(f) for f in ex["flags"]], dtype=object)
    return out


def expose(camera, sun, moon, target, observer, *, terms=None, earth_albedo=None,
           target_albedo=None, target_radius_m=None, model=None, fill=None, snr_min=None,
           sky=None):
    """oi_illuminate then oi_expose_scene for each row: the suggested exposure.

    camera: a built-in camera name (see cameras()) or an oi_camera structure.
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
    cp, _ = _camera_ptr(camera)
    m = _model(model)
    g = _goal(fill, snr_min, sky)
    sc = _scenes(sun, moon, target, observer, terms, earth_albedo, target_albedo,
                 target_radius_m)
    res, status = _illuminate_raw(sc, m)
    n = sc.shape[0]
    ex = np.zeros(n, dtype=EXPOSURE_DTYPE)
    est = status.copy()
    fn = _lib.oi_expose_scene
    mp, gp = _mptr(m), _mptr(g)
    s0, ss = sc.ctypes.data, sc.itemsize
    r0, rs = res.ctypes.data, res.itemsize
    e0, es = ex.ctypes.data, ex.itemsize
    for i in range(n):
        if status[i] >= 0:
            est[i] = fn(cp, s0 + i * ss, r0 + i * rs, mp, gp, e0 + i * es)
    out = _flatten(res, status)
    out.update(_exposure_dict(ex, est))
    # the planner's row status: the illumination's (warnings included) unless
    # the exposure failed
    row = np.where(est < 0, est, status).astype(np.int32)
    out["row_status"] = row
    out["row_status_name"] = np.array([status_name(s) for s in row], dtype=object)
    return out


def expose_flux(camera, flux_w_m2, background_w_m2_sr=0.0, flags=0, *, fill=None,
                snr_min=None):
    """oi_expose per row from a flux at the aperture (W/m^2), a background
    radiance (W/m^2/sr) and known flags. Returns the oi_exposure fields."""
    cp, _ = _camera_ptr(camera)
    flux = np.atleast_1d(np.asarray(flux_w_m2, dtype=np.float64))
    n = flux.shape[0]
    bg = _scalar_rows(background_w_m2_sr, n, "background_w_m2_sr")
    fl = np.broadcast_to(np.asarray(flags, dtype=np.uint32), (n,))
    g = _goal(fill, snr_min)
    ex = np.zeros(n, dtype=EXPOSURE_DTYPE)
    st = np.zeros(n, dtype=np.int32)
    e0, es = ex.ctypes.data, ex.itemsize
    inp = L.oi_expose_in()
    ip, gp = ctypes.addressof(inp), _mptr(g)
    for i in range(n):
        inp.flux_w_m2 = flux[i]
        inp.background_w_m2_sr = bg[i]
        inp.flags = int(fl[i])
        st[i] = _lib.oi_expose(cp, ip, gp, e0 + i * es)
    return _exposure_dict(ex, st)


def sun_fraction(sun, point, *, model=None):
    """oi_sun_fraction per row: dict of the oi_shadow fields and status."""
    sun = _vec(sun, "sun")
    point = _vec(point, "point")
    n = _n_rows(sun, point)
    sun = np.ascontiguousarray(np.broadcast_to(sun, (n, 3)))
    point = np.ascontiguousarray(np.broadcast_to(point, (n, 3)))
    m = _model(model)
    sh = np.zeros(n, dtype=np.dtype(L.oi_shadow))
    st = np.zeros(n, dtype=np.int32)
    mp = _mptr(m)
    for i in range(n):
        st[i] = _lib.oi_sun_fraction(sun[i].ctypes.data, point[i].ctypes.data, mp,
                                     sh.ctypes.data + i * sh.itemsize)
    out = {k: np.array(sh[k]) for k in sh.dtype.names}
    out["status"] = st
    return out


def earthshine(theta, h_km, *, model=None):
    """oi_earthshine per element: (phi, psi, status) arrays."""
    th, h = np.broadcast_arrays(np.asarray(theta, dtype=np.float64),
                                np.asarray(h_km, dtype=np.float64))
    phi = np.zeros(th.shape)
    psi = np.zeros(th.shape)
    st = np.zeros(th.shape, dtype=np.int32)
    m = _model(model)
    mp = _mptr(m)
    a, b = ctypes.c_double(), ctypes.c_double()
    for idx in np.ndindex(th.shape):
        st[idx] = _lib.oi_earthshine(float(th[idx]), float(h[idx]), mp, ctypes.byref(a),
                                     ctypes.byref(b))
        phi[idx], psi[idx] = a.value, b.value
    return phi, psi, st


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
