# SPDX-License-Identifier: MIT
"""The camera and its exposure: the built-in cameras and custom ones
(oi_camera), the suggested exposure of a scene (oi_expose_scene_batch) or
of a known flux (oi_expose_batch)."""
import ctypes

import numpy as np

from ._arrays import _floats, _scalar_rows
from ._models import _model, _mptr
from ._runtime import EXPOSURE_DTYPE, L, _lib
from ._status import _batch_status, _names_of, _status_names, flag_names
from .illumination import _flatten, _illuminate_raw, _scenes


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
    Returns the oi_exposure fields.

    Example: two fluxes at the aperture, no background; the fainter one is
    below the camera's detection limit (flag too_faint):

    >>> import numpy as np, orbillum
    >>> x = orbillum.expose_flux("telescope-15cm", [1e-14, 1e-16])
    >>> x["exposure_s"].tolist(), np.round(x["snr"], 2).tolist(), x["flag_names"].tolist()
    ([100.0, 100.0], [44.69, 1.69], ['', 'too_faint'])
    >>> np.round(x["signal_e"], 3).tolist()   # in proportion to the flux
    [2125.015, 21.25]
    """
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
