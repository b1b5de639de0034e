# SPDX-License-Identifier: MIT
"""The catalogue planner's outputs: nothing half-written (orbillum.catalog.output).

A run killed mid-way (SIGKILL, SIGTERM, SIGINT) leaves the outputs that were there
untouched and no file under an output's name; --resume finishes it without
computing the finished blocks again, byte for byte equal to an uninterrupted
run; a run that fails leaves the outputs as they were; the single Parquet file
and the CSV are the bytes the planner wrote before the parts (pyarrow's writers
on the block tables); the dataset reads back as the table."""
import io
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pyarrow as pa
import pyarrow.csv as pa_csv
import pyarrow.parquet as pq
import pytest

from orbillum.catalog import block, output, plan, synthetic, tle

START, STOP = "2026-12-01T00:00:00", "2026-12-01T06:00:00"
OBSERVERS = [
    {"name": "inspector-leo", "epoch": "2026-12-01T00:00:00", "a_km": 6978.0, "ecc": 0.001,
     "incl_deg": 53.0, "raan_deg": 10.0, "argp_deg": 0.0, "mo_deg": 0.0},
    {"name": "inspector-geo", "epoch": "2026-12-01T00:00:00", "a_km": 42164.0, "ecc": 0.0,
     "incl_deg": 0.05, "raan_deg": 0.0, "argp_deg": 0.0, "mo_deg": 100.0},
]
N_OBJECTS = 48


def _inputs(d: Path):
    cat, obs = d / "cat.3le", d / "obs.json"
    with open(cat, "w") as f:
        tle.write(synthetic.generate(N_OBJECTS, seed=4), f)
    obs.write_text(json.dumps(OBSERVERS))
    return cat, obs


def _args(d: Path, cat, obs):
    return [sys.executable, "-m", "orbillum.catalog", str(cat), "--observer-elements", str(obs),
            "--start", START, "--stop", STOP, "--step", "60", "--objects-per-block", "1",
            "--all-rows", "--no-progress", "-o", str(d / "p.parquet"), "--csv",
            str(d / "p.csv"), "--dataset", str(d / "ds")]


def _files(d: Path) -> dict:
    out = {"p.parquet": (d / "p.parquet").read_bytes(), "p.csv": (d / "p.csv").read_bytes()}
    for p in sorted((d / "ds").iterdir()):
        out["ds/" + p.name] = p.read_bytes()
    return out


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    d = tmp_path_factory.mktemp("whole")
    cat, obs = _inputs(d)
    r = subprocess.run(_args(d, cat, obs), capture_output=True, text=True, check=False)
    assert r.returncode == 0, r.stderr
    assert sorted(os.listdir(d)) == ["cat.3le", "ds", "obs.json", "p.csv", "p.parquet"]
    return _files(d)


def _parts(work: Path) -> list[str]:
    try:
        return sorted(n for n in os.listdir(work) if n.startswith("part-"))
    except OSError:
        return []


@pytest.mark.parametrize("sig", [signal.SIGKILL, signal.SIGTERM, signal.SIGINT])
def test_killed_run_then_resume_equals_an_uninterrupted_run(tmp_path, reference, sig):
    cat, obs = _inputs(tmp_path)
    # outputs from before: a killed run must leave them as they are
    (tmp_path / "p.parquet").write_bytes(b"OLD PARQUET")
    (tmp_path / "p.csv").write_bytes(b"OLD CSV\n")
    (tmp_path / "ds").mkdir()
    (tmp_path / "ds" / output.MANIFEST).write_text("{}")
    (tmp_path / "ds" / "part-00000.parquet").write_bytes(b"OLD PART")
    before = _files(tmp_path)
    works = [tmp_path / f"{n}{output.SUFFIX}" for n in ("p.parquet", "p.csv", "ds")]
    proc = subprocess.Popen(_args(tmp_path, cat, obs), stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    t0 = time.monotonic()
    while len(_parts(works[2])) < 3:
        assert proc.poll() is None, proc.communicate()[1]
        assert time.monotonic() - t0 < 300, "no part written"
        time.sleep(0.002)
    proc.send_signal(sig)
    _, err = proc.communicate(timeout=120)
    if sig == signal.SIGKILL:
        assert proc.returncode == -signal.SIGKILL
    else:
        assert proc.returncode == (130 if sig == signal.SIGINT else 128 + signal.SIGTERM), err
        assert "--resume" in err and "no output written" in err
    # killed mid-way: some blocks done, not all; the old outputs untouched, no temporaries
    done = min(len(_parts(w)) for w in works)
    assert 0 < done < N_OBJECTS, done
    assert _files(tmp_path) == before
    assert not [n for w in works for n in os.listdir(w) if n.endswith(".tmp")] or \
        sig == signal.SIGKILL
    inode = {n: os.stat(works[2] / n).st_ino for n in _parts(works[2])}
    r = subprocess.run(_args(tmp_path, cat, obs) + ["--resume"], capture_output=True,
                       text=True, check=False)
    assert r.returncode == 0, r.stderr
    taken = int(r.stderr.split(" taken from the interrupted run")[0].rsplit("(", 1)[1])
    assert taken >= done
    # the dataset's finished parts are the files written before the kill, not new ones
    for n, ino in inode.items():
        if os.path.exists(tmp_path / "ds" / n) and int(n[5:10]) < done:
            assert os.stat(tmp_path / "ds" / n).st_ino == ino, n
    assert _files(tmp_path) == reference
    assert not any(w.exists() for w in works)


def _sets():
    return synthetic.generate(12, seed=8)


def _obs():
    return [tle.from_elements(el, 99000 + i) for i, el in enumerate(OBSERVERS)]


def test_failed_run_leaves_existing_outputs_untouched(tmp_path, monkeypatch):
    files = {"parquet": tmp_path / "p.parquet", "csv": tmp_path / "p.csv"}
    for p in files.values():
        p.write_bytes(b"A COMPLETE EARLIER OUTPUT")
    calls = []
    real = block.run

    def failing(sets, first, ctx):
        calls.append(first)
        if len(calls) == 3:
            raise tle.CatalogueError("a failure in the third block")
        return real(sets, first, ctx)
    monkeypatch.setattr(block, "run", failing)
    with pytest.raises(tle.CatalogueError, match="third block"):
        plan.plan(_sets(), _obs(), START, "2026-12-01T01:00:00", 60.0, objects_per_block=2,
                  progress=False, parquet=str(files["parquet"]), csv=str(files["csv"]),
                  dataset=str(tmp_path / "ds"))
    for p in files.values():
        assert p.read_bytes() == b"A COMPLETE EARLIER OUTPUT"
    assert sorted(os.listdir(tmp_path)) == ["p.csv", "p.parquet"]


def test_resume_of_other_inputs_is_refused(tmp_path):
    kw = dict(objects_per_block=4, progress=False, parquet=str(tmp_path / "p.parquet"))
    work = tmp_path / ("p.parquet" + output.SUFFIX)
    work.mkdir()
    (work / output.MANIFEST).write_text(json.dumps(
        {"format": output.FORMAT, "kind": "parquet", "fingerprint": "0" * 64, "blocks": 3}))
    with pytest.raises(tle.CatalogueError, match="fingerprint differs"):
        plan.plan(_sets(), _obs(), START, "2026-12-01T01:00:00", 60.0, resume=True, **kw)
    assert not (tmp_path / "p.parquet").exists()
    # a directory of that name that is not a work directory is not removed
    (work / output.MANIFEST).unlink()
    (work / "mine.txt").write_text("the user's")
    with pytest.raises(tle.CatalogueError, match="not an orbillum.catalog work directory"):
        plan.plan(_sets(), _obs(), START, "2026-12-01T01:00:00", 60.0, **kw)
    assert (work / "mine.txt").read_text() == "the user's"


def test_files_are_the_writers_bytes_and_the_dataset_reads_back(tmp_path):
    """The single Parquet file and the CSV equal pyarrow's ParquetWriter and CSVWriter
    fed the block tables (the planner's files before the parts); the dataset directory
    reads back as the same table."""
    s, tables = plan.plan(_sets(), _obs(), START, "2026-12-01T01:00:00", 60.0,
                          objects_per_block=5, progress=False, keep=True, all_rows=True,
                          parquet=str(tmp_path / "p.parquet"), csv=str(tmp_path / "p.csv"),
                          dataset=str(tmp_path / "ds"))
    assert s.blocks == 3 and len(tables) == 3
    schema = tables[0].schema
    ref_pq = tmp_path / "ref.parquet"
    w = pq.ParquetWriter(str(ref_pq), schema)
    for t in tables:
        w.write_table(t)
    w.close()
    assert (tmp_path / "p.parquet").read_bytes() == ref_pq.read_bytes()
    buf = io.BytesIO()
    w = pa_csv.CSVWriter(buf, schema)
    for t in tables:
        w.write_table(t)
    w.close()
    assert (tmp_path / "p.csv").read_bytes() == buf.getvalue()
    whole = pa.concat_tables(tables)
    assert pq.read_table(tmp_path / "ds").equals(whole)
    man = json.loads((tmp_path / "ds" / output.MANIFEST).read_text())
    assert man["complete"] and man["rows"] == whole.num_rows and len(man["parts"]) == 3
    assert pq.ParquetFile(tmp_path / "p.parquet").metadata.num_row_groups == 3
