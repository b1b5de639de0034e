# SPDX-License-Identifier: MIT
"""The catalogue plan: cut the catalogue into blocks, run them in one process or on Dask, write the rows.

The driver computes what every block shares once (epochs, Sun, Moon, the
TEME -> GCRS rotations, the observers' orbits), then runs the blocks
(orbillum.catalog.block) in this process, on a local dask.distributed cluster
(workers=N) or on an existing one (scheduler=ADDRESS), the same function
everywhere, and writes their rows in block order to Parquet and/or CSV
(pyarrow). The rows do not depend on the partitioning (block.py). The files
are written as parts, renamed when complete (orbillum.catalog.output): a killed
or failed run leaves the outputs as they were, and resume=True finishes an
interrupted one without computing its finished blocks again.
"""
from __future__ import annotations

import collections
import hashlib
import math
import os
import time
import uuid
from dataclasses import dataclass, field

import numpy as np
import pyarrow as pa
import pyarrow.csv as pa_csv
import pyarrow.parquet as pq

import orbillum

from . import block, output, sky, tle

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
    observable: int = 0
    sgp4_failures: int = 0
    propagate_cpu_s: float = 0.0
    illuminate_cpu_s: float = 0.0
    client_cpu_s: float = 0.0  # this process's CPU time taking the blocks' results (rows, output)
    setup_s: float = 0.0
    run_s: float = 0.0         # wall time of the blocks (from the first submitted to the last written)
    wall_s: float = 0.0
    workers: int = 1
    statuses: dict = field(default_factory=dict)
    resumed_blocks: int = 0    # blocks taken from an interrupted run's parts (resume=True)
    worker_written: int = 0    # blocks whose parts a Dask worker wrote (run_part)
    old_epochs: int = 0        # element sets farther than epoch_warn_days from an epoch

    def add(self, st: dict) -> None:
        """Count a block's stats (block_stats)."""
        self.scenes += st["scenes"]
        self.propagate_cpu_s += st["propagate"]
        self.illuminate_cpu_s += st["illuminate"]
        self.rows_written += st["rows"]
        self.visible += st["visible"]
        self.observable += st["observable"]
        self.sgp4_failures += st["sgp4_failures"]
        for name, c in st["statuses"].items():
            self.statuses[name] = self.statuses.get(name, 0) + c


def block_stats(cols: dict, costs: dict) -> dict:
    """The counts of a block's rows and its CPU costs (a JSON-able dict)."""
    st = {"scenes": int(costs["scenes"]), "propagate": float(costs["propagate"]),
          "illuminate": float(costs["illuminate"]), "rows": int(cols["status"].size),
          "visible": int(np.count_nonzero(cols["visible"])),
          "observable": int(np.count_nonzero(cols["observable"])),
          "sgp4_failures": int(np.count_nonzero(cols["status"] == -1000)), "statuses": {}}
    for s, c in zip(*np.unique(cols["status"], return_counts=True)):
        st["statuses"][_status_name(int(s))] = int(c)
    return st


def _schema(positions: bool) -> pa.Schema:
    f = [pa.field("object_id", pa.int32()), pa.field("object", pa.string()),
         pa.field("observer", pa.string()), pa.field("epoch", pa.timestamp("ms", tz="UTC")),
         pa.field("visible", pa.bool_()),
         pa.field("status", pa.string()),
         pa.field("range_km", pa.float64())]
    f += [pa.field(n, pa.float64()) for n in block.NUMBERS]
    f += [pa.field("flags", pa.string()), pa.field("flags_mask", pa.uint32())]
    if positions:
        f += [pa.field(n, pa.float64()) for n in block.POSITIONS]
    # columns added later go last, so a reader by position keeps its columns
    f += [pa.field("observable", pa.bool_()), pa.field("flag_names", pa.string())]
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
            "observable": pa.array(cols["observable"]),
            "status": _names(cols["status"], _status_name),
            "range_km": pa.array(cols["range_km"])}
    for n in block.NUMBERS:
        data[n] = pa.array(cols[n])
    data["flags"] = _names(cols["flags"], orbillum.flag_names)
    data["flags_mask"] = pa.array(cols["flags"], type=pa.uint32())
    data["flag_names"] = data["flags"]
    for n in schema.names:
        if n not in data:
            data[n] = pa.array(cols[n])
    return pa.table([data[n] for n in schema.names], schema=schema)


class Sink:
    """Writes tables to a stream (standard output's CSV, as they come) and/or collects them."""

    def __init__(self, schema, csv_stream=None, keep=False):
        self.schema = schema
        self._csv = pa_csv.CSVWriter(csv_stream, schema) if csv_stream is not None else None
        self.tables = [] if keep else None

    def write(self, table: pa.Table):
        if self._csv is not None:
            self._csv.write_table(table)
        if self.tables is not None:
            self.tables.append(table)

    def close(self):
        if self._csv is not None:
            self._csv.close()


def _observer_name(s: tle.ElementSet) -> str:
    return s.name


#: the set-up steps the progress bar counts (context())
SETUP_STEPS = ("epochs", "TEME->GCRS rotations", "Sun and Moon", "observers", "element checks")


def context(observers, start, stop, step_s, camera, max_range_km, all_rows, positions,
            target_albedo=None, target_radius_m=None, earth_albedo=None,
            epoch_limit_days=None, step=None):
    """(block.Context, epochs as astropy Time). step(name): called after each of
    SETUP_STEPS but the last (the progress of the set-up)."""
    step = step or (lambda name: None)
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
    step("epochs")
    rot = sky.teme_to_gcrs(t)
    step("TEME->GCRS rotations")
    sun, moon = sky.bodies(t)
    step("Sun and Moon")
    r, v, err = sky.propagate(sky.satrecs(observers), jd1, jd2, rot)
    if np.any(err):
        i, j = (int(x[0]) for x in np.nonzero(err))
        raise tle.CatalogueError(f"observer {observers[i].name}: sgp4 fails at "
                                 f"{t[j].isot} (error {int(err[i, j])})")
    step("observers")
    ctx = block.Context(jd1=jd1, jd2=jd2, rot=rot, sun=sun, moon=moon, observer_r=r,
                        observer_v=v, camera=camera, max_range_km=float(max_range_km),
                        all_rows=all_rows, positions=positions, target_albedo=target_albedo,
                        target_radius_m=target_radius_m, earth_albedo=earth_albedo,
                        epoch_limit_days=epoch_limit_days)
    return ctx, t


def blocks_of(n_objects: int, per_block: int):
    return [(i, min(i + per_block, n_objects)) for i in range(0, n_objects, per_block)]


def _progress(total, enabled, desc, unit):
    try:
        from tqdm import tqdm
    except ImportError:  # pragma: no cover - tqdm is pinned in requirements
        return None
    return tqdm(total=total, unit=unit, desc=desc,
                disable=(None if enabled is None else not enabled), dynamic_ncols=True)


def _file_hash(path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def _run_fingerprint(sets, observers, start, stop, step_s, ctx, schema, objects_per_block):
    """What the rows and their files depend on (output.fingerprint)."""
    import astropy
    import sgp4
    return output.fingerprint({
        "sets": [s.key() for s in sets], "observers": [s.key() for s in observers],
        "start": start, "stop": stop, "step_s": float(step_s),
        "camera": ctx.camera, "max_range_km": ctx.max_range_km, "all_rows": ctx.all_rows,
        "positions": ctx.positions, "target_albedo": ctx.target_albedo,
        "target_radius_m": ctx.target_radius_m, "earth_albedo": ctx.earth_albedo,
        "epoch_limit_days": ctx.epoch_limit_days, "objects_per_block": objects_per_block,
        "schema": schema.to_string(), "library": _file_hash(orbillum.library_path()),
        "versions": [pa.__version__, sgp4.__version__, astropy.__version__]})


def _is_path(x) -> bool:
    return isinstance(x, (str, os.PathLike))


def plan(sets, observers, start, stop, step_s, *, camera="telescope-15cm",
         max_range_km=10000.0, all_rows=False, positions=False, objects_per_block=None,
         workers=None, scheduler=None, parquet=None, csv=None, dataset=None, keep=False,
         progress=None, target_albedo=None, target_radius_m=None, earth_albedo=None,
         resume=False, epoch_warn_days=None, epoch_limit_days=None,
         scheduler_timeout_s=None, workers_write=True):
    """Plan the catalogue sets for the observers every step_s seconds from start to stop.

    workers: None or 0 (this process), N (a local dask.distributed cluster of N
    one-thread worker processes on loopback); scheduler: the address of an
    existing Dask scheduler (its workers need this package; scheduler_timeout_s:
    how long to try to reach it, default SCHEDULER_TIMEOUT_S). Rows go to the
    Parquet file parquet, the CSV file csv (a path, or a binary stream written as
    the rows come), the partitioned Parquet dataset directory dataset, and with
    keep=True to the returned list of tables. Files are written as parts and
    renamed when complete (orbillum.catalog.output); resume=True takes up the
    parts of an interrupted run of the same inputs (not with keep=True: a kept
    run computes every block). epoch_warn_days, epoch_limit_days: the element
    epoch checks (elements.check_epochs; defaults EPOCH_WARN_DAYS,
    EPOCH_LIMIT_DAYS). On Dask, workers_write: the workers write the blocks' parts
    into the outputs' work directories themselves (a folder every worker and this
    process reach at the same path); False: the rows come to this process, which
    writes them. Returns (Summary, tables or None).
    """
    from . import elements
    w0 = time.perf_counter()
    if not sets:
        raise tle.CatalogueError("the catalogue holds no element set")
    if epoch_warn_days is None:
        epoch_warn_days = elements.EPOCH_WARN_DAYS
    if epoch_limit_days is None:
        epoch_limit_days = elements.EPOCH_LIMIT_DAYS
    # an existing cluster first: a wrong address fails in seconds, before the set-up
    client = _connect(scheduler, scheduler_timeout_s) if scheduler is not None else None
    try:
        return _plan(client, sets, observers, start, stop, step_s, camera, max_range_km,
                     all_rows, positions, objects_per_block, workers, parquet, csv, dataset,
                     keep, progress, target_albedo, target_radius_m, earth_albedo, resume,
                     epoch_warn_days, epoch_limit_days, w0, workers_write)
    finally:
        if client is not None:
            client.close()


def _plan(client, sets, observers, start, stop, step_s, camera, max_range_km, all_rows,
          positions, objects_per_block, workers, parquet, csv, dataset, keep, progress,
          target_albedo, target_radius_m, earth_albedo, resume, epoch_warn_days,
          epoch_limit_days, w0, workers_write=True):
    from . import elements
    setup_bar = _progress(len(SETUP_STEPS), progress, "set-up", "step")

    def step(name):
        if setup_bar is not None:
            setup_bar.set_postfix_str(name, refresh=False)
            setup_bar.update(1)
    try:
        ctx, t = context(observers, start, stop, step_s, camera, max_range_km, all_rows,
                         positions, target_albedo, target_radius_m, earth_albedo,
                         epoch_limit_days, step)
        old = elements.check_epochs(sets, ctx.jd1, ctx.jd2, epoch_warn_days, epoch_limit_days)
        step("element checks")
    finally:
        if setup_bar is not None:
            setup_bar.close()
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
    summary.old_epochs = old
    csv_path = csv if _is_path(csv) else None
    csv_stream = None if csv is None or csv_path is not None else csv
    files = output.Outputs(schema, len(parts), _run_fingerprint(
        sets, observers, start, stop, step_s, ctx, schema, objects_per_block),
        parquet=parquet, csv=csv_path, dataset=dataset, resume=resume)
    sink = Sink(schema, csv_stream, keep)
    # a resumed block's rows are in its parts, not recomputed (but for the stream and keep)
    skip = set()
    if resume and files and csv_stream is None and not keep:
        skip = {i for i in range(len(parts)) if files.done(i)}
    bar = _progress(len(parts), progress, "blocks", "block")
    summary.setup_s = time.perf_counter() - w0

    def take(i, result):
        c0 = time.thread_time()
        if isinstance(result, dict):  # a worker wrote the parts itself: its stats
            st = result
            summary.worker_written += 1
            if not files.done(i):
                raise tle.CatalogueError(
                    f"a worker wrote block {i} but its part is not in "
                    f"{', '.join(files.work_dirs())} here: the output folder must be one every "
                    "worker and this process reach at the same path (a shared file system), "
                    "or let this process write (--client-writes)")
        else:
            cols, costs = result
            st = block_stats(cols, costs)
            table = to_table(cols, object_ids, object_names, observer_names, epochs_ms, schema)
            files.write(i, table, st)
            sink.write(table)
        summary.add(st)
        if bar is not None:
            bar.update(1)
        summary.client_cpu_s += time.thread_time() - c0

    for i in sorted(skip):
        summary.add(files.stats(i))
        summary.resumed_blocks += 1
        if bar is not None:
            bar.update(1)
    todo = [(i, ab) for i, ab in enumerate(parts) if i not in skip]
    finished = False
    try:
        if client is None and not workers:
            r0 = time.perf_counter()
            for i, (a, b) in todo:
                take(i, block.run(sets[a:b], a, ctx))
            summary.run_s = time.perf_counter() - r0
        else:
            # the workers write the parts straight to the outputs (a folder they share with
            # this process) unless the rows must come here (a stream, keep)
            writer = None
            if files and csv_stream is None and not keep and workers_write:
                writer = PartWriter(files.targets, observer_names, epochs_ms, schema)
            _run_dask(todo, sets, ctx, take, workers, client, summary, writer)
        sink.close()
        files.finish()
        finished = True
    except BaseException as e:
        # interrupted (a signal, ^C): the finished parts stay for resume; failed: they go
        files.stop(keep=isinstance(e, (KeyboardInterrupt, SystemExit)))
        raise
    finally:
        if not finished:
            try:
                sink.close()
            except Exception:  # noqa: BLE001 - the first error is the one to report
                pass
        if bar is not None:
            bar.close()
    summary.wall_s = time.perf_counter() - w0
    return summary, sink.tables


#: seconds to try to reach an existing scheduler (--scheduler) before giving up
SCHEDULER_TIMEOUT_S = 5.0


class SchedulerError(tle.CatalogueError):
    """The Dask scheduler at the given address cannot be reached."""


def _connect(scheduler, timeout_s):
    """A Client of the scheduler at its address; SchedulerError in one line when it
    cannot be reached within timeout_s (distributed's own log lines held back)."""
    import logging

    from dask.distributed import Client
    timeout_s = SCHEDULER_TIMEOUT_S if timeout_s is None else float(timeout_s)
    log = logging.getLogger("distributed")
    level = log.level
    log.setLevel(logging.CRITICAL)
    try:
        return Client(scheduler, timeout=timeout_s)
    except (OSError, TimeoutError, ValueError, TypeError) as e:
        why = str(e).splitlines()[0] if str(e) else type(e).__name__
        if len(why) > 160:
            why = why[:157] + "..."
        raise SchedulerError(f"cannot reach the Dask scheduler at {scheduler} within "
                             f"{timeout_s:g} s ({why})") from None
    finally:
        log.setLevel(level)


@dataclass
class PartWriter:
    """What a worker needs to write a block's parts itself (run_part)."""
    targets: list
    observer_names: np.ndarray
    epochs_ms: np.ndarray
    schema: pa.Schema


def run_part(sets, first_index, ctx, i, writer: PartWriter) -> dict:
    """block.run on a worker, its rows written as part i of every output there: only
    the block's stats (block_stats) go back to the client."""
    cols, costs = block.run(sets, first_index, ctx)
    st = block_stats(cols, costs)
    # the block's own objects, indexed from 0
    local = dict(cols, object_index=cols["object_index"] - np.int32(first_index))
    ids = np.array([s.number for s in sets], dtype=np.int32)
    names = np.array([s.name for s in sets], dtype=object)
    table = to_table(local, ids, names, writer.observer_names, writer.epochs_ms, writer.schema)
    for t in writer.targets:
        t.write(i, table, st)
    return st


def _run_dask(todo, sets, ctx, take, workers, client, summary, writer=None):
    """The blocks todo on a local cluster of workers processes (client None) or on the
    cluster of client; with writer, the workers write the parts (run_part)."""
    from dask.distributed import Client, LocalCluster
    cluster = own = None
    if client is None:
        cluster = LocalCluster(n_workers=int(workers), threads_per_worker=1, processes=True,
                               host="127.0.0.1", dashboard_address=None)
        client = own = Client(cluster)
    try:
        summary.workers = max(1, len(client.scheduler_info().get("workers", {})))
        client.wait_for_workers(summary.workers)
        shared = client.scatter(ctx, broadcast=True)
        shared_writer = client.scatter(writer, broadcast=True) if writer is not None else None
        r0 = time.perf_counter()
        token = uuid.uuid4().hex
        window = max(2, 3 * summary.workers)  # blocks in flight: keeps workers busy, bounds memory
        queue = collections.deque()
        pending = iter(todo)

        def submit_next():
            nxt = next(pending, None)
            if nxt is not None:
                i, (a, b) = nxt
                key = f"orbillum-block-{token}-{i}"
                if shared_writer is None:
                    fut = client.submit(block.run, sets[a:b], a, shared, key=key)
                else:
                    fut = client.submit(run_part, sets[a:b], a, shared, i, shared_writer,
                                        key=key)
                queue.append((i, fut))
        for _ in range(window):
            submit_next()
        while queue:
            i, fut = queue.popleft()
            res = fut.result()
            fut.release()
            submit_next()
            take(i, res)
        summary.run_s = time.perf_counter() - r0
    finally:
        if own is not None:
            own.close()
        if cluster is not None:
            cluster.close()


def rate(summary: Summary) -> dict:
    """Scenes per CPU-second: end to end (propagation + illumination) and each part."""
    def per(x):
        return summary.scenes / x if x > 0 else math.inf
    return {"end_to_end": per(summary.propagate_cpu_s + summary.illuminate_cpu_s),
            "propagate": per(summary.propagate_cpu_s),
            "illuminate": per(summary.illuminate_cpu_s)}
