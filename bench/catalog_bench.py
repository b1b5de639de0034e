#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""catalog_bench.py: the driver of `make catalog-bench`: the catalogue planner's throughput.

A seeded synthetic catalogue (orbillum.catalog.synthetic) planned for two
observers (a LEO and a GEO inspector) over a span of epochs, no output files
(I/O apart):

1. one process: scenes (objects x observers x epochs) per CPU-second per core,
   end to end (propagation + illumination) and each part apart, from the
   thread CPU time each block measures (orbillum.catalog.block);
2. a local dask.distributed cluster of 1 then 2 one-thread worker processes:
   the wall time of the blocks (cluster start and the shared context's
   scatter excluded) and the speed-up from 1 to 2 workers. On a machine whose
   cores other jobs share the speed-up says so: the load is printed beside it;
3. the three goals of docs/catalog.md from the same runs, each writing a partitioned
   Parquet dataset (the workers write their parts): the CPU per scene of the
   whole process tree (this process with the scheduler, and the worker and
   nanny processes, from psutil) on 2 workers over the in-process run's
   (goal <= 1.15); the wall time of the plan from 1 to 2 workers (goal >= 1.8,
   only meaningful on idle cores); scenes per CPU-second of the whole tree,
   end to end (set-up, blocks, writing; goal >= 1e6 per core). The clusters
   are started, and their workers import the package, before the measure, as
   this process imported it before its own run.

Prints `name value unit` lines, also written to --out.
"""
import argparse
import os
import shutil
import sys
import tempfile
import time

from orbillum.catalog import plan, synthetic, tle  # first: it sets astropy's IERS options

import astropy.units as u  # noqa: E402
from astropy.time import Time  # noqa: E402

OBSERVERS = [
    {"name": "inspector-leo", "epoch": "2026-12-01T00:00:00", "a_km": 6978.0, "ecc": 0.001,
     "incl_deg": 53.0, "raan_deg": 10.0, "argp_deg": 0.0, "mo_deg": 0.0},
    {"name": "inspector-geo", "epoch": "2026-12-01T00:00:00", "a_km": 42164.0, "ecc": 0.0,
     "incl_deg": 0.05, "raan_deg": 0.0, "argp_deg": 0.0, "mo_deg": 100.0},
]


def _warm():
    """On a worker: import what the blocks need (astropy, sgp4, the binding)."""
    import orbillum.catalog.plan  # noqa: F401
    return True


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--objects", type=int, default=2000)
    p.add_argument("--hours", type=float, default=6.0)
    p.add_argument("--step", type=float, default=60.0)
    p.add_argument("--out", default="build/bench/catalog.txt")
    a = p.parse_args()
    sets = synthetic.generate(a.objects, seed=1)
    obs = [tle.from_elements(el, 99000 + i) for i, el in enumerate(OBSERVERS)]
    stop = (Time("2026-12-01T00:00:00", scale="utc") + a.hours * u.h).isot
    lines = []

    def put(name, value, unit, comment=""):
        line = f"{name} {value} {unit}" + (f"  # {comment}" if comment else "")
        print(line, flush=True)
        lines.append(line)

    import psutil
    me = psutil.Process()
    work = tempfile.mkdtemp(prefix="catalog-bench-")

    def tree_cpu():
        """CPU seconds of this process and every live descendant (workers, nannies)."""
        total = 0.0
        for proc in [me] + me.children(recursive=True):
            try:
                c = proc.cpu_times()
            except psutil.Error:
                continue
            total += c.user + c.system
        return total

    tree = {}

    def run(label, **kw):
        out = os.path.join(work, label)
        c0, w0 = tree_cpu(), time.perf_counter()
        s, _ = plan.plan(sets, obs, "2026-12-01T00:00:00", stop, a.step, progress=False,
                         dataset=out, **kw)
        tree[label] = {"cpu": tree_cpu() - c0, "wall": time.perf_counter() - w0}
        shutil.rmtree(out)
        return s

    s = run("serial")
    r = plan.rate(s)
    put("catalog.scenes", s.scenes, "scenes", f"{s.objects} objects x {s.observers} observers "
        f"x {s.epochs} epochs, {s.blocks} blocks")
    put("catalog.end_to_end", f"{r['end_to_end']:.4g}", "scenes/CPU-s",
        "propagation + illumination, one core")
    put("catalog.propagate", f"{r['propagate']:.4g}", "scenes/CPU-s",
        "vectorised SGP4 + TEME->GCRS rotation")
    put("catalog.illuminate", f"{r['illuminate']:.4g}", "scenes/CPU-s",
        "scenes, oi_illuminate_batch + oi_expose_scene_batch, visibility")
    put("catalog.setup", f"{s.setup_s:.3g}", "s", "epochs, Sun, Moon, rotations, observers")
    put("catalog.serial_run", f"{s.run_s:.3g}", "s", "blocks in one process (wall)")
    walls, cpus = {}, {}
    from dask.distributed import LocalCluster
    for w in (1, 2):
        # the cluster started here, outside the measured plan (its start is no part of
        # the planner's work); the plan reaches it by its address
        with LocalCluster(n_workers=w, threads_per_worker=1, processes=True, host="127.0.0.1",
                          dashboard_address=":0") as cluster:
            # the workers import the package before the measure, as this process did
            # before its run (the import is the cluster's start, as on a long-lived one)
            from dask.distributed import Client
            with Client(cluster) as c:
                c.wait_for_workers(w)
                c.run(_warm)
            sw = run(f"dask{w}", scheduler=cluster.scheduler_address)
        assert sw.workers == w and sw.worker_written == sw.blocks
        walls[w] = sw.run_s
        blocks = sw.propagate_cpu_s + sw.illuminate_cpu_s
        # blocks are equal in size but the last: the larger half's share of C
        n_half = -(-sw.blocks // 2)
        cpus[w] = {"blocks": blocks, "client": sw.client_cpu_s,
                   "largest_half": blocks * n_half / max(sw.blocks, 1)}
        put(f"catalog.dask{w}_run", f"{sw.run_s:.3g}", "s",
            f"blocks on a local cluster of {w} worker(s) (wall)")
        put(f"catalog.dask{w}_end_to_end", f"{plan.rate(sw)['end_to_end']:.4g}", "scenes/CPU-s",
            "per core inside the workers: the same as one process unless distribution costs")
    load = os.getloadavg()[0]
    put("catalog.scaling_1_to_2", f"{walls[1] / walls[2]:.3g}", "x",
        f"ideal 2; load average {load:.2f} on {os.cpu_count()} cores during the run")
    # The same from CPU time, which other jobs on the cores do not change: the
    # blocks' CPU time C (summed over the workers) and this process's, K,
    # taking their results (rows, tables). With 1 worker the client overlaps
    # it on the second core (wall ~ max(C1, K)); with 2 workers and the client
    # on 2 cores the wall is at least (C2 + K) / 2 and C2 / 2 (blocks are
    # whole tasks: the larger half of them, imbalance).
    c1 = cpus[1]["blocks"]
    c2, k2 = cpus[2]["blocks"], cpus[2]["client"]
    half = cpus[2]["largest_half"]
    projected = max(c1, cpus[1]["client"]) / max((c2 + k2) / 2.0, half)
    put("catalog.client_cpu_share", f"{k2 / c2:.3g}", "1",
        "this process's CPU taking the results / the blocks' CPU (2 workers)")
    put("catalog.dask2_over_dask1_cpu_per_scene", f"{c2 / c1:.3g}", "x",
        "the blocks' CPU per scene with 2 workers over 1 (1: distribution costs nothing)")
    put("catalog.scaling_1_to_2_cpu_bound", f"{projected:.3g}", "x",
        "projected on 2 free cores from CPU times: max(C1, K1) / max((C2 + K2) / 2, "
        "largest half of the blocks); ideal 2")
    # the goals (docs/catalog.md), whole process tree, from these runs
    sc = s.scenes
    for label in ("serial", "dask1", "dask2"):
        put(f"catalog.tree_{label}", f"{tree[label]['cpu']:.3g} s CPU, "
            f"{tree[label]['wall']:.3g}", "s wall",
            "the whole plan (set-up, blocks, the dataset written), every process of the tree")
    put("catalog.goal_dask_cpu_per_scene", f"{tree['dask2']['cpu'] / tree['serial']['cpu']:.3g}",
        "x", "whole-tree CPU per scene, 2 workers over one process; goal <= 1.15 "
        f"(1 worker: {tree['dask1']['cpu'] / tree['serial']['cpu']:.3g} x)")
    put("catalog.goal_scaling_1_to_2_wall", f"{tree['dask1']['wall'] / tree['dask2']['wall']:.3g}",
        "x", f"the plan's wall time, 1 over 2 workers; goal >= 1.8 on idle cores (load "
        f"average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores: noisy when shared)")
    put("catalog.goal_end_to_end", f"{sc / tree['serial']['cpu']:.4g}", "scenes/CPU-s",
        "whole-tree, one process, end to end; goal >= 1e6 per core (2 workers: "
        f"{sc / tree['dask2']['cpu']:.4g})")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(os.path.dirname(os.path.abspath(a.out)), exist_ok=True)
    with open(a.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
