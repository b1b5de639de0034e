# SPDX-License-Identifier: MIT
"""The catalogue planner on Dask: a small catalogue on a local cluster of two worker
processes over loopback, and on an existing cluster by its address, gives the same
rows, bit for bit, as one process."""
import pyarrow as pa
import pytest

from orbillum.catalog import plan, synthetic, tle

distributed = pytest.importorskip("distributed")

START, STOP = "2026-12-01T00:00:00", "2026-12-01T02:00:00"
OBSERVER = {"name": "inspector-leo", "epoch": "2026-12-01T00:00:00", "a_km": 6978.0,
            "ecc": 0.001, "incl_deg": 53.0, "raan_deg": 10.0, "argp_deg": 0.0, "mo_deg": 0.0}


def _plan(**kw):
    sets = synthetic.generate(60, seed=21)
    s, tables = plan.plan(sets, [tle.from_elements(OBSERVER, 99000)], START, STOP, 60.0,
                          all_rows=True, keep=True, progress=False, **kw)
    return s, pa.concat_tables(tables)


def test_local_cluster_of_two_workers_equals_one_process():
    _, one = _plan(objects_per_block=60)
    s, two = _plan(objects_per_block=7, workers=2)
    assert s.workers == 2 and s.blocks == 9
    assert two.equals(one)


def test_existing_cluster_by_address_equals_one_process():
    _, one = _plan(objects_per_block=60)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  host="127.0.0.1", dashboard_address=None) as cluster:
        assert cluster.scheduler_address.startswith("tcp://127.0.0.1:")
        s, got = _plan(objects_per_block=11, scheduler=cluster.scheduler_address)
    assert s.workers == 2
    assert got.equals(one)


def test_workers_write_the_parts_the_same_bytes(tmp_path):
    """On a cluster the workers write the blocks' parts themselves (plan.run_part): the
    Parquet file, the CSV and the dataset are the bytes of the one-process run."""
    out = {}
    for name, kw in (("one", {}), ("two", {"workers": 2})):
        d = tmp_path / name
        d.mkdir()
        s, _ = plan.plan(synthetic.generate(30, seed=3), [tle.from_elements(OBSERVER, 99000)],
                         START, STOP, 120.0, objects_per_block=4, progress=False,
                         parquet=str(d / "p.parquet"), csv=str(d / "p.csv"),
                         dataset=str(d / "ds"), **kw)
        out[name] = {str(p.relative_to(d)): p.read_bytes() for p in sorted(d.rglob("*"))
                     if p.is_file()}
        assert s.blocks == 8 and s.worker_written == (8 if kw else 0)
    assert out["one"] == out["two"]
    assert len(out["one"]) == 2 + 8 + 1


def test_scheduler_and_workers_started_as_separate_processes(tmp_path):
    """A cluster as on several machines: `dask scheduler` and two `dask worker`
    processes started apart, reached by the scheduler's address; the workers write
    the dataset's parts, the bytes of the one-process run."""
    import json
    import os
    import subprocess
    import sys
    import time
    bindir = os.path.dirname(sys.executable)
    sched_file = tmp_path / "scheduler.json"
    procs = [subprocess.Popen([os.path.join(bindir, "dask"), "scheduler", "--host", "127.0.0.1",
                               "--port", "0", "--no-dashboard", "--scheduler-file",
                               str(sched_file)], stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL)]
    try:
        t0 = time.monotonic()
        while not sched_file.exists() or not sched_file.read_text().strip():
            assert time.monotonic() - t0 < 120 and procs[0].poll() is None
            time.sleep(0.2)
        time.sleep(0.2)
        address = json.loads(sched_file.read_text())["address"]
        for _ in range(2):
            procs.append(subprocess.Popen(
                [os.path.join(bindir, "dask"), "worker", address, "--nthreads", "1",
                 "--no-dashboard", "--host", "127.0.0.1"],
                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        with distributed.Client(address, timeout=60) as c:
            c.wait_for_workers(2, timeout=120)
        out = {}
        for name, kw in (("one", {}), ("cluster", {"scheduler": address})):
            s, _ = plan.plan(synthetic.generate(20, seed=5), [tle.from_elements(OBSERVER, 99000)],
                             START, STOP, 120.0, objects_per_block=3, progress=False,
                             dataset=str(tmp_path / name), **kw)
            out[name] = {p.name: p.read_bytes() for p in sorted((tmp_path / name).iterdir())}
        assert s.workers == 2 and s.worker_written == 7
        assert out["one"] == out["cluster"]
    finally:
        for p in procs[::-1]:
            p.terminate()
        for p in procs:
            p.wait(timeout=60)
