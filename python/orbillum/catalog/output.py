# SPDX-License-Identifier: MIT
"""The plan's output files, written so that nothing half-written reads as complete.

Every output (a single Parquet file, a partitioned Parquet dataset, a CSV file)
is written as parts, one per block, in a work directory beside it,
``OUTPUT.partial/``: each part under a temporary name (``.part-NNNNN.*.tmp``),
flushed to disk, then renamed to ``part-NNNNN.parquet`` (or ``.csv``) with a
small ``_stats-NNNNN.json`` of its counts beside it. When every part is there
the output is made whole under a temporary name and renamed over OUTPUT in one
step: the single file is the parts' rows in block order; the dataset is the
work directory itself, renamed to OUTPUT (exchanged with an existing one where
the system allows it). A run that is killed (any signal) or fails leaves OUTPUT
as it was, and the work directory, which ``--resume`` takes up: a block whose
part is in every output's work directory is not computed again. The work
directory's ``_orbillum.json`` holds a fingerprint of everything the rows depend
on (element sets, epochs, camera, options, the partitioning, the library and the
writers' versions); a resume of other inputs is refused.

Standard output (``--csv -``) is streamed as before: it cannot be taken back.
"""
from __future__ import annotations

import ctypes
import hashlib
import io
import json
import os
import shutil

import pyarrow as pa
import pyarrow.csv as pa_csv
import pyarrow.parquet as pq

from .tle import CatalogueError

#: the work directory's manifest (names starting with '_' or '.' are not data to pyarrow)
MANIFEST = "_orbillum.json"
FORMAT = "orbillum.catalog parts 1"
SUFFIX = ".partial"


def fingerprint(parts: dict) -> str:
    """sha256 of a JSON text of parts (sorted keys)."""
    text = json.dumps(parts, sort_keys=True, separators=(",", ":"), default=str)
    return hashlib.sha256(text.encode()).hexdigest()


def _fsync_file(path):
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def _fsync_dir(path):
    try:
        _fsync_file(path)
    except OSError:  # pragma: no cover - directories cannot be opened on some systems
        pass


def _write_json(path, obj):
    tmp = os.path.join(os.path.dirname(path), "." + os.path.basename(path) + ".tmp")
    with open(tmp, "w", encoding="utf-8") as f:
        json.dump(obj, f, indent=1, sort_keys=True)
        f.write("\n")
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def _exchange(a: str, b: str) -> bool:
    """Swap the paths a and b in one step (Linux renameat2 RENAME_EXCHANGE); False
    where the system has no such call."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        fn = libc.renameat2
    except (OSError, AttributeError):
        return False
    fn.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_uint]
    at_fdcwd, rename_exchange = -100, 2
    if fn(at_fdcwd, os.fsencode(a), at_fdcwd, os.fsencode(b), rename_exchange) == 0:
        return True
    return False


class Target:
    """One output written as parts in its work directory."""

    ext = ""

    def __init__(self, path: str, schema: pa.Schema, n_blocks: int, fp: str):
        self.path = path
        self.work = path + SUFFIX
        self.schema = schema
        self.n_blocks = n_blocks
        self.fp = fp
        self.width = max(5, len(str(max(n_blocks - 1, 0))))

    # -- names
    def part_name(self, i: int) -> str:
        return f"part-{i:0{self.width}d}{self.ext}"

    def part(self, i: int) -> str:
        return os.path.join(self.work, self.part_name(i))

    def stats_path(self, i: int) -> str:
        return os.path.join(self.work, f"_stats-{i:0{self.width}d}.json")

    def manifest(self) -> dict:
        return {"format": FORMAT, "kind": self.kind, "fingerprint": self.fp,
                "blocks": self.n_blocks}

    # -- the work directory
    def open(self, resume: bool) -> None:
        """Make the work directory: taken up when resume and it is this run's, else new."""
        self.check_path()
        man = os.path.join(self.work, MANIFEST)
        if os.path.lexists(self.work):
            old = None
            try:
                with open(man, encoding="utf-8") as f:
                    old = json.load(f)
            except (OSError, ValueError):
                pass
            if not (isinstance(old, dict) and old.get("format") == FORMAT):
                raise CatalogueError(f"{self.work} exists and is not an orbillum.catalog work "
                                     "directory: move it away")
            if resume and old == self.manifest():
                return
            if resume:
                raise CatalogueError(f"{self.work}: the interrupted run there planned other "
                                     "inputs or options (its fingerprint differs): run without "
                                     "--resume to start again, or give that run's arguments")
            shutil.rmtree(self.work)
        os.mkdir(self.work)
        _write_json(man, self.manifest())
        _fsync_dir(os.path.dirname(os.path.abspath(self.work)))

    def check_path(self) -> None:
        if os.path.isdir(self.path):
            raise CatalogueError(f"{self.path} is a directory (a file is written there)")

    def done(self, i: int) -> bool:
        return os.path.exists(self.part(i)) and os.path.exists(self.stats_path(i))

    def stats(self, i: int) -> dict:
        with open(self.stats_path(i), encoding="utf-8") as f:
            return json.load(f)

    def write(self, i: int, table: pa.Table, stats: dict) -> None:
        """Part i: written under a temporary name, flushed, renamed."""
        final = self.part(i)
        tmp = os.path.join(self.work, "." + self.part_name(i) + ".tmp")
        self._write_part(tmp, table)
        _fsync_file(tmp)
        _write_json(self.stats_path(i), stats)
        os.replace(tmp, final)

    def remove_temporaries(self) -> None:
        """The temporary files of a part being written when the run stopped."""
        try:
            names = os.listdir(self.work)
        except OSError:
            return
        for n in names:
            if n.startswith(".") and n.endswith(".tmp"):
                try:
                    os.remove(os.path.join(self.work, n))
                except OSError:
                    pass

    def discard(self) -> None:
        shutil.rmtree(self.work, ignore_errors=True)

    def _write_part(self, tmp, table):  # pragma: no cover - subclasses
        raise NotImplementedError

    def finish(self) -> None:  # pragma: no cover - subclasses
        raise NotImplementedError


class ParquetFile(Target):
    """A single Parquet file: the parts' rows in block order, one row group per block."""
    kind = "parquet"
    ext = ".parquet"

    def _write_part(self, tmp, table):
        pq.write_table(table, tmp)

    def finish(self):
        tmp = os.path.join(self.work, ".whole.tmp")
        w = pq.ParquetWriter(tmp, self.schema)
        try:
            for i in range(self.n_blocks):
                w.write_table(pq.read_table(self.part(i), schema=self.schema))
        finally:
            w.close()
        _fsync_file(tmp)
        os.replace(tmp, self.path)
        _fsync_dir(os.path.dirname(os.path.abspath(self.path)))
        shutil.rmtree(self.work)


class CsvFile(Target):
    """A CSV file: the header, then the parts' rows (written without header) in block order."""
    kind = "csv"
    ext = ".csv"

    def _write_part(self, tmp, table):
        with pa.OSFile(tmp, "wb") as f:
            pa_csv.write_csv(table, f, pa_csv.WriteOptions(include_header=False))

    def finish(self):
        tmp = os.path.join(self.work, ".whole.tmp")
        head = io.BytesIO()
        pa_csv.write_csv(self.schema.empty_table(), head)
        with open(tmp, "wb") as out:
            out.write(head.getvalue())
            for i in range(self.n_blocks):
                with open(self.part(i), "rb") as f:
                    shutil.copyfileobj(f, out, 1 << 20)
            out.flush()
            os.fsync(out.fileno())
        os.replace(tmp, self.path)
        _fsync_dir(os.path.dirname(os.path.abspath(self.path)))
        shutil.rmtree(self.work)


class ParquetDataset(Target):
    """A partitioned Parquet dataset: a directory of part-NNNNN.parquet files (one per
    block, in block order by name) and _orbillum.json; pyarrow.dataset and pandas read
    the directory as one table."""
    kind = "dataset"
    ext = ".parquet"

    def check_path(self):
        if os.path.lexists(self.path):
            if not os.path.isdir(self.path):
                raise CatalogueError(f"{self.path} exists and is not a directory (a dataset "
                                     "is a directory)")
            names = [n for n in os.listdir(self.path) if not n.startswith(".")]
            if names and MANIFEST not in names:
                raise CatalogueError(f"{self.path} is a directory that is not an orbillum.catalog "
                                     "dataset: it is not replaced")

    def _write_part(self, tmp, table):
        pq.write_table(table, tmp)

    def finish(self):
        rows = [pq.read_metadata(self.part(i)).num_rows for i in range(self.n_blocks)]
        for i in range(self.n_blocks):
            os.remove(self.stats_path(i))
        man = dict(self.manifest(), complete=True, rows=sum(rows),
                   parts=[[self.part_name(i), r] for i, r in enumerate(rows)])
        _write_json(os.path.join(self.work, MANIFEST), man)
        _fsync_dir(self.work)
        if os.path.lexists(self.path):
            if _exchange(self.work, self.path):
                shutil.rmtree(self.work)  # now the old dataset
            else:
                old = self.path + ".old"
                shutil.rmtree(old, ignore_errors=True)
                os.rename(self.path, old)
                os.rename(self.work, self.path)
                shutil.rmtree(old)
        else:
            os.rename(self.work, self.path)
        _fsync_dir(os.path.dirname(os.path.abspath(self.path)))


class Outputs:
    """Every file output of a run; a block is done when its part is in all of them."""

    def __init__(self, schema, n_blocks, fp, *, parquet=None, csv=None, dataset=None,
                 resume=False):
        self.targets = []
        for cls, path in ((ParquetFile, parquet), (CsvFile, csv), (ParquetDataset, dataset)):
            if path is not None:
                self.targets.append(cls(os.fspath(path), schema, n_blocks, fp))
        paths = [os.path.abspath(t.path) for t in self.targets]
        if len(set(paths)) != len(paths):
            raise CatalogueError("two outputs have the same path")
        for t in self.targets:
            t.open(resume)

    def __bool__(self):
        return bool(self.targets)

    def done(self, i: int) -> bool:
        return bool(self.targets) and all(t.done(i) for t in self.targets)

    def stats(self, i: int) -> dict:
        return self.targets[0].stats(i)

    def write(self, i: int, table: pa.Table, stats: dict) -> None:
        for t in self.targets:
            t.write(i, table, stats)

    def finish(self) -> None:
        for t in self.targets:
            t.finish()

    def stop(self, keep: bool) -> None:
        """After an interruption (keep: the finished parts stay for --resume) or a
        failure (keep False: the work directories go; the outputs stay as they were)."""
        for t in self.targets:
            if keep:
                t.remove_temporaries()
            else:
                t.discard()

    def work_dirs(self) -> list[str]:
        return [t.work for t in self.targets]
