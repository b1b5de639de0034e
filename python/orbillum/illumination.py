# SPDX-License-Identifier: MIT
"""The light on the target: the scenes' record array (oi_scene) from
numpy inputs, one oi_illuminate_batch call over them, its records as a dict
of arrays; the Earth's light at a point (oi_earthshine_batch)."""
import ctypes

import numpy as np

from ._arrays import UINT_RANGE, _attitudes, _floats, _integer, _n_rows, _vec
from ._models import _model, _model_explain, _mptr
from ._runtime import ILLUM_DTYPE, SCENE_DTYPE, L, _lib
from ._status import _batch_status, _nan_failed, _status_names
from .facets import _is_per_row, _shape_of


_TERM_BITS = {"sun": L.OI_TERM_SUN, "earth": L.OI_TERM_EARTH, "moon": L.OI_TERM_MOON,
              "sky": L.OI_TERM_SKY}


def terms_mask(terms):
    """'sun+earth+moon+sky' (any subset, any order, '+'-joined; 'all' = sun+earth+moon,
    sky is opt-in; '' = none) -> mask.

    Example:

    >>> import orbillum
    >>> orbillum.terms_mask("sun+earth") == orbillum.OI_TERM_SUN | orbillum.OI_TERM_EARTH
    True
    >>> orbillum.terms_mask("all") == orbillum.OI_TERM_ALL, orbillum.terms_mask("")
    (True, 0)

    A mask is an unsigned C integer: one beyond its range is refused (numpy
    and ctypes would wrap it modulo 2^32); unknown bits within it are the
    library's ERR_TERMS in the row:

    >>> orbillum.terms_mask(2**32 + 1)
    Traceback (most recent call last):
    ...
    ValueError: terms: 4294967297 is outside the C type's range [0, 4294967295]
    """
    if isinstance(terms, (bool, np.bool_)):
        raise TypeError(f"terms: a mask or '+'-joined words, got {terms!r}")
    if isinstance(terms, (int, np.integer)):
        return _integer(terms, "terms", UINT_RANGE)
    s = str(terms).strip().lower()
    if s == "all":
        return L.OI_TERM_ALL
    m = 0
    for part in filter(None, (p.strip() for p in s.split("+"))):
        if part not in _TERM_BITS:
            raise ValueError(f"unknown term {part!r}: use sun, earth, moon, sky joined by '+'")
        m |= _TERM_BITS[part]
    return m


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


def _attitudes_refused(sc, attitude_q):
    """Rows with a shape whose given attitude quaternion is no unit one: a norm
    off 1 by more than 1e-6 (the library's bound), NaN, zero or one whose
    squared norm underflows to 0 (the library reads an all-zero quaternion as
    the identity; a quaternion the caller gives is refused, as the planner
    does). A sphere's attitude is not read. None when no attitude was given."""
    if attitude_q is None:
        return None
    q = sc["attitude_q"]
    with np.errstate(all="ignore"):
        norm = np.sqrt(np.einsum("ij,ij->i", q, q))
        bad = ~(np.abs(norm - 1.0) <= 1e-6)
    return bad & (sc["shape"] != 0)


def _refuse_rows(status, refused):
    """status ERR_SHAPE for the refused rows (before any use of the status)."""
    if refused is not None and refused.any():
        status[refused] = L.OI_ERR_SHAPE


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
    _batch_status(st, n, "model", _model_explain(m, albedo=True))
    return res, status


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
                       frame, (4,) or (N, 4); with a shape, a norm off 1 by more
                       than 1e-6 (NaN, zero and an underflowing norm such as
                       (1e-300, 0, 0, 0) too) is the row's status ERR_SHAPE, as
                       the planner's; else it is normalised
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
      flux_obs), plus status (int32) and status_name. A row whose status is
      an error has every float field NaN (mag_v too: the C library's 0 would
      read as a bright target), shadow_region 0. A model the library rejects
      raises ValueError naming its first field outside include/orbillum/model.h's
      ranges and the range; an integer model field beyond the C int is
      refused, not wrapped.

    Example: the Sun along +x, an observer on the terminator (the Sun on
    its horizon), a target 500 km above it in sunlight and one behind the
    Earth in its shadow, in one batch call (one row each):

    >>> import numpy as np, orbillum
    >>> sun, moon = [1.496e8, 0, 0], [0, 384400.0, 0]
    >>> observer = [0, 6380.0, 0]
    >>> target = [[0, 6880.0, 0], [-7000.0, 0, 0]]
    >>> r = orbillum.illuminate(sun, moon, target, observer)
    >>> r["sun_fraction"].tolist(), r["status_name"].tolist()
    ([1.0, 0.0], ['OK', 'OK'])
    >>> np.round(r["e_sun"], 1).tolist(), np.round(r["e_earth"], 2).tolist()
    ([1361.0, 0.0], [16.88, 0.0])
    >>> np.round(r["mag_v"], 2).tolist(), np.round(r["range_km"], 1).tolist()
    ([5.16, 27.3], [500.0, 9471.2])

    outputs: the fields left out are 0, the others the same bits (here the
    observer's fields without the limb-darkened fraction):

    >>> q = orbillum.illuminate(sun, moon, target, observer, outputs=orbillum.OI_BATCH_OBSERVER)
    >>> bool((q["mag_v"] == r["mag_v"]).all()), q["sun_fraction_ld"].tolist()
    (True, [0.0, 0.0])

    A facet target (a built-in shape, attitude quaternions w, x, y, z):

    >>> b = orbillum.illuminate(sun, moon, target[0], observer, target_shape="box-wing",
    ...                         attitude_q=[1, 0, 0, 0])
    >>> np.round(b["mag_v"], 2).tolist(), b["status_name"].tolist()
    ([7.79], ['OK'])
    """
    mask = _outputs_mask(outputs)
    m = _model(model)
    keep = []
    sc = _scenes(sun, moon, target, observer, terms, earth_albedo, target_albedo,
                 target_radius_m, target_shape=target_shape, attitude_q=attitude_q, keep=keep,
                 epoch_jd=epoch_jd, earth_rotation_rad=earth_rotation_rad)
    res, status = _illuminate_raw(sc, m, mask)
    _refuse_rows(status, _attitudes_refused(sc, attitude_q))
    _nan_failed(res, status)
    return _flatten(res, status)


def earthshine(theta, h_km, *, model=None):
    """oi_earthshine per element (one oi_earthshine_batch call): (phi, psi,
    status) arrays of the broadcast shape of theta and h_km.

    Example: phi and psi 500 km up, at three angles from the Sun:

    >>> import numpy as np, orbillum
    >>> phi, psi, st = orbillum.earthshine([0.0, 0.5, 1.0], 500.0)
    >>> np.round(phi, 2).tolist(), np.round(psi, 3).tolist(), st.tolist()
    ([1.24, 1.09, 0.67], [0.0, 0.033, 0.093], [0, 0, 0])

    theta and h_km broadcast; 1 m up phi is near 2 cos(theta), a flat
    Lambertian plane's; a point below the surface is a status, not an exception:

    >>> phi, psi, st = orbillum.earthshine([0.0, 1.0], np.array([[1e-3], [36000.0]]))
    >>> phi.shape, np.round(phi[0], 2).tolist(), np.round(2 * np.cos([0.0, 1.0]), 2).tolist()
    ((2, 2), [2.0, 1.08], [2.0, 1.08])
    >>> orbillum.status_name(orbillum.earthshine(0.0, -1.0)[2])
    'ERR_BELOW_SURFACE'
    """
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
    _batch_status(bst, th.size, "model", _model_explain(m))
    failed = st < 0
    phi[failed] = np.nan  # the library's 0 would read as a dark point
    psi[failed] = np.nan
    return phi.reshape(shape), psi.reshape(shape), st.reshape(shape)
