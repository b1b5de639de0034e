# SPDX-License-Identifier: MIT
"""One block of the catalogue plan: some objects x every observer x every epoch, through the binding.

A block is the unit of work a process or a Dask worker runs: it propagates its
objects (vectorised SGP4), builds one scene per (object, observer, epoch) and
makes one oi_illuminate_batch and one oi_expose_scene_batch call over them
(orbillum.expose). Every value of a row depends on that row's inputs alone, so
any grouping of objects into blocks gives the same bits. Rows come out in the
order object, observer, epoch.
"""
from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

import orbillum

from . import sky

#: the planner's degrees (OUT_RAD_TO_DEG, planner/output.h): the same double product
RAD_TO_DEG = 180.0 / 3.14159265358979323846

#: status of a row whose object sgp4 could not propagate (decayed, or too far from its epoch)
STATUS_SGP4 = "ERR_SGP4"

#: the numeric columns, in the planner's order (docs/planner.md, "Output")
NUMBERS = ("sun_fraction", "sun_fraction_atm", "e_sun", "e_earth", "e_moon",
           "earth_theta_deg", "earth_h_km", "flux_obs", "mag_v", "exposure_s", "gain", "snr")
POSITIONS = tuple(f"{b}_{a}" for b in ("sun", "moon", "target", "observer") for a in "xyz") + \
    tuple(f"{b}_v{a}" for b in ("target", "observer") for a in "xyz")


@dataclass
class Context:
    """What every block shares: the epochs, the sky, the observers and the camera."""
    jd1: np.ndarray            # (N,) UTC Julian date, two parts
    jd2: np.ndarray
    rot: np.ndarray            # (N, 3, 3) TEME -> GCRS
    sun: np.ndarray            # (N, 3) km GCRS
    moon: np.ndarray           # (N, 3)
    observer_r: np.ndarray     # (K, N, 3) km GCRS
    observer_v: np.ndarray     # (K, N, 3) km/s
    camera: object             # a built-in camera name or a dict as orbillum.camera() returns
    max_range_km: float
    all_rows: bool             # every row, or the visible ones only
    positions: bool            # add the scene's vectors (the planner's input columns)
    target_albedo: float | None = None
    target_radius_m: float | None = None
    earth_albedo: float | None = None
    epoch_limit_days: float | None = None  # rows farther from the element epoch: ERR_SGP4


#: sgp4 error code given to epochs farther than Context.epoch_limit_days from the element epoch
ERR_EPOCH_LIMIT = 100

#: the SNR of the planner's observation windows (planner/batch.c: oi_expose's default goal)
SNR_GOAL = 5.0


def _visible(status, flags, range_km, max_range_km):
    bad = orbillum.OI_FLAG_OCCULTED | orbillum.OI_FLAG_SUN_EXCLUSION
    return (status >= 0) & ((flags & bad) == 0) & (range_km <= max_range_km)


def _observable(status, flags, snr, range_km, max_range_km):
    """The rows of the planner's --summary windows (planner/windows.c, windows_good):
    status OK or a warning, full sunlight (neither eclipsed nor in penumbra), the Sun
    outside the exclusion angle, not behind the Earth, not saturated, SNR >= 5; and
    within the range limit, so that an observable row is visible."""
    bad = (orbillum.OI_FLAG_ECLIPSED | orbillum.OI_FLAG_PENUMBRA |
           orbillum.OI_FLAG_SUN_EXCLUSION | orbillum.OI_FLAG_OCCULTED |
           orbillum.OI_FLAG_SATURATED)
    return (status >= 0) & ((flags & bad) == 0) & (snr >= SNR_GOAL) & (range_km <= max_range_km)


def epoch_distance_days(sats, jd1, jd2) -> np.ndarray:
    """(M, N): |epoch - element epoch| in days of M sgp4 satellites at N epochs."""
    e1 = np.array([s.jdsatepoch for s in sats], dtype=float)[:, None]
    e2 = np.array([s.jdsatepochF for s in sats], dtype=float)[:, None]
    return np.abs((jd1[None, :] - e1) + (jd2[None, :] - e2))


def run(sets, first_index: int, ctx: Context) -> tuple[dict, dict]:
    """The rows of the objects sets (catalogue indices first_index, first_index + 1, ...).

    Returns (columns, costs). costs: CPU seconds of this thread in "propagate"
    (sgp4 and the frame rotation), "illuminate" (scenes, the binding's batch
    calls, the visibility) and the scene count "scenes". columns: a dict of numpy arrays: object_index, observer_index, epoch_index
    (int32), visible, observable (bool), status (int32, the planner's row status; -1000 for
    sgp4 failures and epochs past ctx.epoch_limit_days, named STATUS_SGP4), range_km, the NUMBERS, flags (uint32) and,
    with ctx.positions, the POSITIONS. Rows of failed sgp4 epochs have zero numbers.
    """
    m = len(sets)
    k, n = ctx.observer_r.shape[0], ctx.jd1.shape[0]
    c0 = time.thread_time()
    sats = sky.satrecs(sets)
    r, v, err = sky.propagate(sats, ctx.jd1, ctx.jd2, ctx.rot)
    if ctx.epoch_limit_days is not None:
        far = epoch_distance_days(sats, ctx.jd1, ctx.jd2) > ctx.epoch_limit_days
        err = np.where(far & (err == 0), ERR_EPOCH_LIMIT, err)
    c1 = time.thread_time()
    shape = (m, k, n)
    rows = m * k * n
    bad = np.broadcast_to(err[:, None, :] != 0, shape).reshape(rows)
    # failed propagations are NaN: keep them out of the library (ERR_NONFINITE) and mark them
    r = np.where((err != 0)[..., None], 0.0, r)
    v = np.where((err != 0)[..., None], 0.0, v)
    vec = {
        "sun": np.broadcast_to(ctx.sun[None, None], shape + (3,)),
        "moon": np.broadcast_to(ctx.moon[None, None], shape + (3,)),
        "target": np.broadcast_to(r[:, None], shape + (3,)),
        "observer": np.broadcast_to(ctx.observer_r[None], shape + (3,)),
        "target_v": np.broadcast_to(v[:, None], shape + (3,)),
        "observer_v": np.broadcast_to(ctx.observer_v[None], shape + (3,)),
    }
    vec = {key: np.ascontiguousarray(a).reshape(rows, 3) for key, a in vec.items()}
    out_all = orbillum.expose(ctx.camera, vec["sun"], vec["moon"], vec["target"], vec["observer"],
                              target_velocity=vec["target_v"],
                              observer_velocity=vec["observer_v"],
                              earth_albedo=ctx.earth_albedo, target_albedo=ctx.target_albedo,
                              target_radius_m=ctx.target_radius_m)
    status = np.where(bad, -1000, out_all["row_status"]).astype(np.int32)
    flags = np.where(bad, 0, out_all["flags"]).astype(np.uint32)
    range_km = np.where(bad, 0.0, out_all["range_km"])
    visible = _visible(status, flags, range_km, ctx.max_range_km)
    snr = np.where(bad, 0.0, out_all["snr"])
    observable = _observable(status, flags, snr, range_km, ctx.max_range_km)
    idx = np.indices(shape, dtype=np.int32).reshape(3, rows)
    cols = {"object_index": idx[0] + np.int32(first_index), "observer_index": idx[1],
            "epoch_index": idx[2], "visible": visible, "observable": observable,
            "status": status,
            "range_km": range_km}
    src = {"sun_fraction": out_all["sun_fraction"], "sun_fraction_atm": out_all["sun_fraction_atm"],
           "e_sun": out_all["e_sun"], "e_earth": out_all["e_earth"], "e_moon": out_all["e_moon"],
           "earth_theta_deg": out_all["earth_theta"] * RAD_TO_DEG,
           "earth_h_km": out_all["earth_h_km"], "flux_obs": out_all["flux_obs"],
           "mag_v": out_all["mag_v"], "exposure_s": out_all["exposure_s"],
           "gain": out_all["gain"], "snr": out_all["snr"]}
    for name in NUMBERS:
        cols[name] = np.where(bad, 0.0, src[name])
    cols["flags"] = flags
    if ctx.positions:
        for key in ("sun", "moon", "target", "observer"):
            for j, a in enumerate("xyz"):
                cols[f"{key}_{a}"] = vec[key][:, j]
        for key in ("target", "observer"):
            for j, a in enumerate("xyz"):
                cols[f"{key}_v{a}"] = vec[f"{key}_v"][:, j]
    if not ctx.all_rows:
        keep = visible
        cols = {key: np.ascontiguousarray(a[keep]) for key, a in cols.items()}
    costs = {"propagate": c1 - c0, "illuminate": time.thread_time() - c1, "scenes": rows}
    return cols, costs
