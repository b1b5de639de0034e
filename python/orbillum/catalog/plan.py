# SPDX-License-Identifier: MIT
"""The catalogue plan: cut the catalogue into blocks, run them in one process or on Dask, write the rows.

The driver computes what every block shares once (epochs, Sun, Moon, the
TEME -> GCRS rotations, the observers' orbits), then runs the blocks
(orbillum.catalog.block) in this process, on a local dask.distributed cluster
(workers=N) or on an existing one (scheduler=ADDRESS), the same function
everywhere, and writes their rows in block order to Parquet and/or CSV
(pyarrow). The rows do not depend on the partitioning (block.py).
"""
from __future__ import annotations

import collections
import math
import time
import uuid
from dataclasses import dataclass, field

import numpy as np
import pyarrow as pa
import pyarrow.csv as pa_csv
import pyarrow.parquet as pq

import orbillum

from . import block, sky, tle

#: scenes per block when objects_per_block is not given (memory ~1 kB per scene in flight)
SCENES_PER_BLOCK = 100_000


@dataclass
class Summary:
    """What a run did: counts and the CPU seconds of the blocks (summed over workers)."""
    objects: int
    observers: int
    epochs: int
    blocks: int
    scenes: int = 0
    rows_written: int = 0
    visible: int = 0
    sgp4_failures: int = 0
    propagate_cpu_s: float = 0.0
    illuminate_cpu_s: float = 0.0
    client_cpu_s: float = 0.0  # this process's CPU time taking the blocks' results (rows, output)
    setup_s: float = 0.0
    run_s: float = 0.0         # wall time of the blocks (from the first submitted to the last written)
    wall_s: float = 0.0
    workers: int = 1
    statuses: dict = field(default_factory=dict)


def _schema(positions: bool) -> pa.Schema:
    f = [pa.field("object_id", pa.int32()), pa.field("object", pa.string()),
         pa.field("observer", pa.string()), pa.field("epoch", pa.timestamp("ms", tz="UTC")),
         pa.field("visible", pa.bool_()), pa.field("status", pa.string()),
         pa.field("range_km", pa.float64())]
    f += [pa.field(n, pa.float64()) for n in block.NUMBERS]
    f += [pa.field("flags", pa.string()), pa.field("flags_mask", pa.uint32())]
    if positions:
        f += [pa.field(n, pa.float64()) for n in block.POSITIONS]
    return pa.schema(f)


def _names(codes: np.ndarray, name_of) -> pa.Array:
    """name_of of each code, one call per distinct code."""
    uniq, inv = np.unique(codes, return_inverse=True)
    names = np.array([name_of(int(c)) for c in uniq] or [""], dtype=object)
    return pa.array(names[inv.reshape(-1)] if codes.size else [], type=pa.string())


def _status_name(s: int) -> str:
    return block.STATUS_SGP4 if s == -1000 else orbillum.status_name(s)


def to_table(cols: dict, object_ids, object_names, observer_names, epochs_ms,
             schema: pa.Schema) -> pa.Table:
    """An arrow table of a block's rows (columns of schema)."""
    oi = cols["object_index"]
    data = {"object_id": pa.array(object_ids[oi], type=pa.int32()),
            "object": pa.array(object_names[oi], type=pa.string()),
            "observer": pa.array(observer_names[cols["observer_index"]], type=pa.string()),
            "epoch": pa.array(epochs_ms[cols["epoch_index"]], type=pa.timestamp("ms", tz="UTC")),
            "visible": pa.array(cols["visible"]),
            "status": _names(cols["status"], _status_name),
            "range_km": pa.array(cols["range_km"])}
    for n in block.NUMBERS:
        data[n] = pa.array(cols[n])
    data["flags"] = _names(cols["flags"], orbillum.flag_names)
    data["flags_mask"] = pa.array(cols["flags"], type=pa.uint32())
    for n in schema.names:
        if n not in data:
            data[n] = pa.array(cols[n])
    return pa.table([data[n] for n in schema.names], schema=schema)


class Sink:
    """Writes tables to a Parquet file and/or a CSV file (or collects them)."""

    def __init__(self, schema, parquet=None, csv=None, keep=False):
        self.schema = schema
        self._pq = pq.ParquetWriter(parquet, schema) if parquet else None
        self._csv = pa_csv.CSVWriter(csv, schema) if csv else None
        self.tables = [] if keep else None

    def write(self, table: pa.Table):
        if self._pq is not None:
            self._pq.write_table(table)
        if self._csv is not None:
            self._csv.write_table(table)
        if self.tables is not None:
            self.tables.append(table)

    def close(self):
        for w in (self._pq, self._csv):
            if w is not None:
                w.close()


def _observer_name(s: tle.ElementSet) -> str:
    return s.name


def context(observers, start, stop, step_s, camera, max_range_km, all_rows, positions,
            target_albedo=None, target_radius_m=None, earth_albedo=None):
    """(block.Context, epochs as astropy Time)."""
    if not observers:
        raise tle.CatalogueError("no observer: give at least one (--observers or "
                                 "--observer-elements)")
    if not (max_range_km > 0):
        raise tle.CatalogueError(f"max range must be > 0 km (got {max_range_km})")
    if isinstance(camera, str) and camera not in orbillum.cameras():
        raise tle.CatalogueError(f"no built-in camera {camera!r}; built-in: "
                                 + ", ".join(orbillum.cameras()))
    t = sky.epochs(start, stop, step_s)
    jd1 = np.ascontiguousarray(t.utc.jd1, dtype=float)
    jd2 = np.ascontiguousarray(t.utc.jd2, dtype=float)
    rot = sky.teme_to_gcrs(t)
    sun, moon = sky.bodies(t)
    r, v, err = sky.propagate(sky.satrecs(observers), jd1, jd2, rot)
    if np.any(err):
        i, j = (int(x[0]) for x in np.nonzero(err))
        raise tle.CatalogueError(f"observer {observers[i].name}: sgp4 fails at "
                                 f"{t[j].isot} (error {int(err[i, j])})")
    ctx = block.Context(jd1=jd1, jd2=jd2, rot=rot, sun=sun, moon=moon, observer_r=r,
                        observer_v=v, camera=camera, max_range_km=float(max_range_km),
                        all_rows=all_rows, positions=positions, target_albedo=target_albedo,
                        target_radius_m=target_radius_m, earth_albedo=earth_albedo)
    return ctx, t


def blocks_of(n_objects: int, per_block: int):
    return [(i, min(i + per_block, n_objects)) for i in range(0, n_objects, per_block)]


def _progress(total, enabled):
    try:
        from tqdm import tqdm
    except ImportError:  # pragma: no cover - tqdm is pinned in requirements
        return None
    return tqdm(total=total, unit="block", disable=(None if enabled is None else not enabled),
                dynamic_ncols=True)


def plan(sets, observers, start, stop, step_s, *, camera="telescope-15cm",
         max_range_km=10000.0, all_rows=False, positions=False, objects_per_block=None,
         workers=None, scheduler=None, parquet=None, csv=None, keep=False, progress=None,
         target_albedo=None, target_radius_m=None, earth_albedo=None):
    """Plan the catalogue sets for the observers every step_s seconds from start to stop.

    workers: None or 0 (this process), N (a local dask.distributed cluster of N
    one-thread worker processes on loopback); scheduler: the address of an
    existing Dask scheduler (its workers need this package). Rows go to the
    Parquet and/or CSV paths, and with keep=True to the returned list of
    tables. Returns (Summary, tables or None).
    """
    w0 = time.perf_counter()
    if not sets:
        raise tle.CatalogueError("the catalogue holds no element set")
    ctx, t = context(observers, start, stop, step_s, camera, max_range_km, all_rows, positions,
                     target_albedo, target_radius_m, earth_albedo)
    k, n = ctx.observer_r.shape[0], ctx.jd1.shape[0]
    if objects_per_block is None:
        objects_per_block = max(1, SCENES_PER_BLOCK // (k * n))
    if objects_per_block < 1:
        raise tle.CatalogueError(f"objects per block must be >= 1 (got {objects_per_block})")
    parts = blocks_of(len(sets), objects_per_block)
    schema = _schema(positions)
    epochs_ms = np.round((t.utc.unix - 0.0) * 1000.0).astype(np.int64)
    object_ids = np.array([s.number for s in sets], dtype=np.int32)
    object_names = np.array([s.name for s in sets], dtype=object)
    observer_names = np.array([_observer_name(s) for s in observers], dtype=object)
    summary = Summary(objects=len(sets), observers=k, epochs=n, blocks=len(parts))
    sink = Sink(schema, parquet, csv, keep)
    bar = _progress(len(parts), progress)
    summary.setup_s = time.perf_counter() - w0

    def take(result):
        c0 = time.thread_time()
        _take(result)
        summary.client_cpu_s += time.thread_time() - c0

    def _take(result):
        cols, costs = result
        summary.scenes += costs["scenes"]
        summary.propagate_cpu_s += costs["propagate"]
        summary.illuminate_cpu_s += costs["illuminate"]
        summary.rows_written += int(cols["status"].size)
        summary.visible += int(np.count_nonzero(cols["visible"]))
        summary.sgp4_failures += int(np.count_nonzero(cols["status"] == -1000))
        for s, c in zip(*np.unique(cols["status"], return_counts=True)):
            name = _status_name(int(s))
            summary.statuses[name] = summary.statuses.get(name, 0) + int(c)
        sink.write(to_table(cols, object_ids, object_names, observer_names, epochs_ms, schema))
        if bar is not None:
            bar.update(1)

    try:
        if scheduler is None and not workers:
            r0 = time.perf_counter()
            for a, b in parts:
                take(block.run(sets[a:b], a, ctx))
            summary.run_s = time.perf_counter() - r0
        else:
            _run_dask(parts, sets, ctx, take, workers, scheduler, summary)
    finally:
        sink.close()
        if bar is not None:
            bar.close()
    summary.wall_s = time.perf_counter() - w0
    return summary, sink.tables


def _run_dask(parts, sets, ctx, take, workers, scheduler, summary):
    from dask.distributed import Client, LocalCluster
    cluster = None
    if scheduler is None:
        cluster = LocalCluster(n_workers=int(workers), threads_per_worker=1, processes=True,
                               host="127.0.0.1", dashboard_address=None)
        client = Client(cluster)
    else:
        client = Client(scheduler)
    try:
        summary.workers = max(1, len(client.scheduler_info().get("workers", {})))
        client.wait_for_workers(summary.workers)
        shared = client.scatter(ctx, broadcast=True)
        r0 = time.perf_counter()
        token = uuid.uuid4().hex
        window = max(2, 3 * summary.workers)  # blocks in flight: keeps workers busy, bounds memory
        queue = collections.deque()
        pending = iter(enumerate(parts))

        def submit_next():
            nxt = next(pending, None)
            if nxt is not None:
                i, (a, b) = nxt
                queue.append(client.submit(block.run, sets[a:b], a, shared,
                                           key=f"orbillum-block-{token}-{i}"))
        for _ in range(window):
            submit_next()
        while queue:
            fut = queue.popleft()
            res = fut.result()
            fut.release()
            submit_next()
            take(res)
        summary.run_s = time.perf_counter() - r0
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def rate(summary: Summary) -> dict:
    """Scenes per CPU-second: end to end (propagation + illumination) and each part."""
    def per(x):
        return summary.scenes / x if x > 0 else math.inf
    return {"end_to_end": per(summary.propagate_cpu_s + summary.illuminate_cpu_s),
            "propagate": per(summary.propagate_cpu_s),
            "illuminate": per(summary.illuminate_cpu_s)}
