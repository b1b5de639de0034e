# SPDX-License-Identifier: MIT
"""The camera and its exposure: the built-in cameras and custom ones
(oi_camera), the suggested exposure of a scene (oi_expose_scene_batch) or
of a known flux (oi_expose_batch)."""
import ctypes

import numpy as np

from ._arrays import UINT_RANGE, _floats, _integer, _integers, _scalar_rows
from ._models import _model, _model_problem, _mptr
from ._runtime import EXPOSURE_DTYPE, L, _lib
from ._status import _batch_status, _nan_failed, _names_of, _status_names, flag_names
from .illumination import (_attitudes_refused, _flatten, _illuminate_raw, _refuse_rows,
                           _scenes)


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
        if count in d and _integer(d[count], f"camera[{count!r}]") != size:
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


# The planner's sky words (its sky column): "all" is zodiacal+moon, as there.
_SKY_WORDS = {"none": 0, "zodiacal": L.OI_SKY_ZODIACAL, "moon": L.OI_SKY_MOON,
              "starlight": L.OI_SKY_STARLIGHT, "all": L.OI_SKY_ZODIACAL | L.OI_SKY_MOON}


def sky_mask(sky):
    """oi_expose_goal.sky from a mask of OI_SKY_* bits or the planner's words,
    '+'-joined, any case ('zodiacal+moon+starlight', 'all' = zodiacal+moon,
    'none' or '' = 0). A mask outside the C unsigned's range, a bool or a
    fraction is refused (unknown bits within the range: the library's
    ERR_FLAGS in every row).

    Example:

    >>> import orbillum
    >>> Z, M, S = orbillum.OI_SKY_ZODIACAL, orbillum.OI_SKY_MOON, orbillum.OI_SKY_STARLIGHT
    >>> orbillum.sky_mask("zodiacal+starlight") == Z | S, orbillum.sky_mask("all") == Z | M
    (True, True)
    >>> orbillum.sky_mask(""), orbillum.sky_mask(Z | M)
    (0, 3)
    """
    if isinstance(sky, str):
        m = 0
        for part in filter(None, (p.strip().lower() for p in sky.split("+"))):
            if part not in _SKY_WORDS:
                raise ValueError(f"sky: unknown word {part!r}; use none, zodiacal, moon, "
                                 f"starlight, all joined by '+'")
            m |= _SKY_WORDS[part]
        return m
    return _integer(sky, "sky", UINT_RANGE)


def _real(v, name):
    """A scalar real number as a float: TypeError for complex, bool, strings."""
    a = _floats(v, name)
    if a.ndim != 0:
        raise ValueError(f"{name}: a scalar, got shape {a.shape}")
    if isinstance(v, (str, bytes)):
        raise TypeError(f"{name}: a number, got the string {v!r}")
    return float(a)


def _goal(fill, snr_min, sky=None, sensor_temp_c=None):
    if fill is None and snr_min is None and sky is None and sensor_temp_c is None:
        return None
    g = L.oi_expose_goal()
    g.fill = 0.0 if fill is None else _real(fill, "fill")
    g.snr_min = 0.0 if snr_min is None else _real(snr_min, "snr_min")
    g.sky = 0 if sky is None else sky_mask(sky)
    if sensor_temp_c is not None:
        g.has_sensor_temp = 1
        g.sensor_temp_c = _real(sensor_temp_c, "sensor_temp_c")
    return g


def _interval(v, lo, hi, lo_open=False, hi_open=False):
    """v in the interval (NaN never is)."""
    return ((v > lo) if lo_open else (v >= lo)) and ((v < hi) if hi_open else (v <= hi))


def _show(lo, hi, lo_open=False, hi_open=False):
    h = "pi" if hi == np.pi else f"{hi:g}"
    return f"{'(' if lo_open else '['}{lo:g}, {h}{')' if hi_open else ']'}"


# oi_camera's ranges as include/orbillum/camera.h documents them (oi_expose, Note 4):
# (field, lo, hi, lo open, hi open, unit), in the header's order.
_CAMERA_RANGES = (
    ("aperture_m", 0.0, 10.0, True, False, "m"),
    ("focal_length_m", 1e-3, 1e3, False, False, "m"),
    ("pixel_pitch_m", 1e-7, 1e-3, False, False, "m"),
    ("transmission", 0.0, 1.0, True, False, ""),
    ("quantum_efficiency", 0.0, 1.0, True, False, ""),
    ("band_fraction", 0.0, 1.0, True, False, ""),
    ("photon_energy_j", 1e-20, 1e-17, False, False, "J"),
    ("full_well_e", 1.0, 1e9, False, False, "e-"),
    ("dark_current_e_s", 0.0, 1e9, False, False, "e-/s"),
    ("psf_peak_fraction", 0.0, 1.0, True, False, ""),
    ("fov_rad", 0.0, np.pi, True, False, "rad"),
    ("sun_exclusion_rad", 0.0, np.pi, False, False, "rad"),
    ("max_trail_px", 0.0, 1e6, False, False, "px"),
)


def _camera_problem(c):
    """The first oi_camera field outside the ranges of include/orbillum/camera.h
    (oi_expose, Note 4), as text naming the field and its range; None when
    every field is in range."""
    def bad(k, v, rng):
        return (f"camera[{k!r}] = {v!r} is outside {rng} (include/orbillum/camera.h, "
                f"oi_expose Note 4)")
    for k, lo, hi, lo_open, hi_open, unit in _CAMERA_RANGES:
        v = getattr(c, k)
        if not _interval(v, lo, hi, lo_open, hi_open):
            return bad(k, v, _show(lo, hi, lo_open, hi_open) + (f" {unit}" if unit else ""))
    v = c.detect_false_alarm
    if not (v == 0 or _interval(v, 1e-15, 0.5, hi_open=True)):
        return bad("detect_false_alarm", v, "0 or [1e-15, 0.5)")
    v = c.detect_probability
    if not (v == 0 or _interval(v, 0.5, 0.999999)):
        return bad("detect_probability", v, "0 or [0.5, 0.999999]")
    temps = ("dark_ref_temp_c", "temp_min_c", "temp_max_c")
    if c.dark_doubling_c == 0:
        for k in temps:
            if getattr(c, k) != 0:
                return bad(k, getattr(c, k), "0 (no temperature model: dark_doubling_c is 0)")
    else:
        if not _interval(c.dark_doubling_c, 1.0, 100.0):
            return bad("dark_doubling_c", c.dark_doubling_c, "0 or [1, 100] deg C")
        for k in temps:
            if not _interval(getattr(c, k), -150.0, 150.0):
                return bad(k, getattr(c, k), "[-150, 150] deg C")
        if not c.temp_min_c <= c.temp_max_c:
            return bad("temp_max_c", c.temp_max_c, f"[temp_min_c = {c.temp_min_c!r}, 150] deg C")
        span = 30.0 * c.dark_doubling_c
        if not (c.temp_max_c - c.dark_ref_temp_c <= span
                and c.dark_ref_temp_c - c.temp_min_c <= span):
            return bad("temp_min_c, temp_max_c", (c.temp_min_c, c.temp_max_c),
                       f"30 doublings of dark_ref_temp_c = {c.dark_ref_temp_c!r} "
                       f"({30 * c.dark_doubling_c:g} deg C either side)")
    for k, count, cap, hi, unit in (("times_s", "n_times", L.OI_CAMERA_MAX_TIMES, 1e4, "s"),
                                    ("gains", "n_gains", L.OI_CAMERA_MAX_GAINS, 1e3, "")):
        n = getattr(c, count)
        if not 1 <= n <= cap:
            return bad(count, n, f"1..{cap}")
        vals = list(getattr(c, k))[:n]
        prev = 0.0
        for i, v in enumerate(vals):
            if not (v > prev and v <= hi):
                return (f"camera[{k!r}][{i}] = {v!r}: the {k} must be in (0, {hi:g}]"
                        f"{' ' + unit if unit else ''} and strictly ascending "
                        f"(include/orbillum/camera.h, oi_expose Note 4)")
            prev = v
    for i, v in enumerate(list(c.read_noise_e)[:c.n_gains]):
        if not _interval(v, 0.0, 1e6):
            return (f"camera['read_noise_e'][{i}] = {v!r} is outside [0, 1e6] e- "
                    f"(include/orbillum/camera.h, oi_expose Note 4)")
    return None


def _camera_explain(c, m=None):
    """explain() for _batch_status: the camera's (or the model's) first bad field."""
    def explain(st):
        if st == L.OI_ERR_CAMERA:
            return _camera_problem(c)
        if st in (L.OI_ERR_MODEL, L.OI_ERR_RADIUS):
            return _model_problem(m)
        return None
    return explain


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
    fill, snr_min: the oi_expose_goal (None: the C defaults). A camera the
    library refuses (ERR_CAMERA) raises ValueError naming its first field
    outside include/orbillum/camera.h's ranges (oi_expose Note 4) and the range.
    sky: oi_expose_goal.sky, OI_SKY_* bits or the planner's words
    ('zodiacal+moon+starlight', 'all' = zodiacal+moon; sky_mask()); None, 0
    or 'none': no sky background but the sunlit Earth, as before.
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
    (expose_status equals their illumination status). A failed row (status <
    0, or expose_status < 0 for the exposure's fields) has every float output
    NaN, not the C library's 0 (a 0 reads as a valid value: mag_v 0 is a
    bright target, detect_margin_mag 0 a target at the threshold, snr 0 a
    dark one; the planner leaves those cells empty); its integer outputs
    (time_index, gain_index, flags, shadow_region) stay 0.
    row_status / row_status_name: the status build/oi-plan prints for the row.
    outputs: None (every exposure field) or a mask of OI_EXPOSE_* bits
    (oi_expose_scene_batch_outputs: OI_EXPOSE_SETTING, FAINT, DETECT, SUN_ANGLE,
    BACKGROUND, RATE; docs/camera.md, "Batches and their outputs mask"): the
    fields left out are 0 and not computed, the others the same bits.

    Example: the scene of illuminate()'s example, seen by the 15 cm telescope:

    >>> import numpy as np, orbillum
    >>> sun, moon = [1.496e8, 0, 0], [0, 384400.0, 0]
    >>> observer = [0, 6380.0, 0]
    >>> target = [[0, 6880.0, 0], [-7000.0, 0, 0]]
    >>> x = orbillum.expose("telescope-15cm", sun, moon, target, observer)
    >>> x["exposure_s"].tolist(), x["gain"].tolist(), np.round(x["snr"], 1).tolist()
    ([0.03, 0.01], [1.0, 1.0], [122.8, 0.0])
    >>> x["flag_names"].tolist()
    ['', 'earth_in_fov+eclipsed+too_faint+occulted']
    >>> x["row_status_name"].tolist()
    ['OK', 'OK']

    A facet target (the README's call), and a mask of outputs:

    >>> b = orbillum.expose("telescope-15cm", sun, moon, target[0], observer,
    ...                     target_shape="box-wing", attitude_q=[1, 0, 0, 0])
    >>> b["exposure_s"].tolist(), np.round(b["snr"], 1).tolist(), b["flag_names"].tolist()
    ([1.0], [210.9], [''])
    >>> s = orbillum.expose("telescope-15cm", sun, moon, target, observer,
    ...                     outputs=orbillum.OI_EXPOSE_SETTING)
    >>> s["exposure_s"].tolist(), s["sun_angle_rad"].tolist()
    ([0.03, 0.01], [0.0, 0.0])
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
    cp, cam = _camera_ptr(camera)
    m = _model(model)
    g = _goal(fill, snr_min, sky, sensor_temp_c)
    keep = []
    sc = _scenes(sun, moon, target, observer, terms, earth_albedo, target_albedo,
                 target_radius_m, target_velocity, observer_velocity, target_shape=target_shape,
                 attitude_q=attitude_q, keep=keep, epoch_jd=epoch_jd,
                 earth_rotation_rad=earth_rotation_rad)
    res, status = _illuminate_raw(sc, m)
    _refuse_rows(status, _attitudes_refused(sc, attitude_q))
    n = sc.shape[0]
    ex = np.empty(n, dtype=EXPOSURE_DTYPE)  # the batch writes every row
    est = np.empty(n, dtype=np.intc)
    # the camera, model and goal formed once (with OI_EXPOSE_ALL the rows are
    # oi_expose_scene_batch's bits)
    st = _lib.oi_expose_scene_batch_outputs(n, cp, sc.ctypes.data, res.ctypes.data, _mptr(m),
                                            _mptr(g), emask, ex.ctypes.data, est.ctypes.data)
    _batch_status(st, n, "camera or model", _camera_explain(cam, m))
    # rows whose illumination failed are not exposed: their status (the
    # fields NaN below)
    failed = status < 0
    if failed.any():  # a masked pass spared on the common all-valid batch
        est[failed] = status[failed]
    _nan_failed(res, status)
    _nan_failed(ex, est)
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
    Returns the oi_exposure fields; a failed row's float fields are NaN (as
    expose()). flags: integers within the C unsigned (TypeError, ValueError).

    Example: two fluxes at the aperture, no background; the fainter one is
    below the camera's detection limit (flag too_faint):

    >>> import numpy as np, orbillum
    >>> x = orbillum.expose_flux("telescope-15cm", [1e-14, 1e-16])
    >>> x["exposure_s"].tolist(), np.round(x["snr"], 2).tolist(), x["flag_names"].tolist()
    ([100.0, 100.0], [44.69, 1.69], ['', 'too_faint'])
    >>> np.round(x["signal_e"], 3).tolist()   # in proportion to the flux
    [2125.015, 21.25]
    """
    cp, cam = _camera_ptr(camera)
    flux = np.atleast_1d(_floats(flux_w_m2, "flux_w_m2"))
    if flux.ndim != 1:
        raise ValueError(f"flux_w_m2: expected a scalar or shape (N,), got {flux.shape}")
    n = flux.shape[0]
    bg = _scalar_rows(background_w_m2_sr, n, "background_w_m2_sr")
    try:
        fl = np.broadcast_to(_integers(flags, "flags", UINT_RANGE), (n,))
    except ValueError as e:
        raise ValueError(f"flags: a mask of OI_FLAG_* or one per row ({n}): {e}") from None
    g = _goal(fill, snr_min, sensor_temp_c=sensor_temp_c)
    inp = np.zeros(n, dtype=np.dtype(L.oi_expose_in))
    inp["flux_w_m2"] = flux
    inp["background_w_m2_sr"] = bg
    inp["flags"] = fl
    ex = np.empty(n, dtype=EXPOSURE_DTYPE)  # the batch writes every row
    st = np.empty(n, dtype=np.intc)
    bst = _lib.oi_expose_batch(n, cp, inp.ctypes.data, _mptr(g), ex.ctypes.data, st.ctypes.data)
    _batch_status(bst, n, "camera", _camera_explain(cam))
    _nan_failed(ex, st)
    return _exposure_dict(ex, st)


def cameras():
    """Names of the built-in cameras, in index order.

    Example:

    >>> import orbillum
    >>> orbillum.cameras()
    ['star-tracker', 'telescope-15cm']
    """
    out = []
    i = 0
    while True:
        p = _lib.oi_camera_builtin(i)
        if not p:
            return out
        out.append(p.contents.name.decode())
        i += 1


def camera(name):
    """A built-in camera's parameters as a dict (times_s, gains, read_noise_e as lists).

    Example:

    >>> import orbillum
    >>> c = orbillum.camera("telescope-15cm")
    >>> c["aperture_m"], c["times_s"][:3], c["gains"]
    (0.15, [0.01, 0.03, 0.1], [1.0])

    The dict, changed, is a custom camera for expose() and expose_flux():

    >>> c["aperture_m"] = 0.30
    >>> x = orbillum.expose_flux(c, 1e-14)
    >>> x["exposure_s"].tolist(), round(float(x["signal_e"][0]), 2)
    ([100.0], 8500.06)
    >>> x0 = orbillum.expose_flux("telescope-15cm", 1e-14)   # twice the aperture: 4x the signal
    >>> round(float(x["signal_e"][0] / x0["signal_e"][0]), 9)
    4.0
    """
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
