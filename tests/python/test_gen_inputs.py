# SPDX-License-Identifier: MIT
"""The generators' inputs record (bake/common/inputs.py), which lets `make check-generated`
regenerate only what changed: it follows every import (inside functions too), moves with one
byte of any input, and a --changed run with the committed record regenerates nothing."""

import json
import os
import shutil
import subprocess
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, ROOT)

from bake.common import inputs  # noqa: E402


def _tree(tmp_path):
    pkg = tmp_path / "pkg"
    (pkg / "sub").mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "sub" / "__init__.py").write_text("")
    (pkg / "entry.py").write_text("import os\n\ndef f():\n    from .sub import late\n"
                                  "    import numpy\n    return late\n")
    (pkg / "sub" / "late.py").write_text("from ..helper import x\n")
    (pkg / "helper.py").write_text("x = 1\n")
    (pkg / "unused.py").write_text("x = 2\n")
    (tmp_path / "data.json").write_text("{}\n")
    return pkg


def test_every_import_is_followed(tmp_path):
    _tree(tmp_path)
    files, third = inputs.python_files(["pkg.entry"], str(tmp_path))
    assert files == ["pkg/__init__.py", "pkg/entry.py", "pkg/helper.py", "pkg/sub/__init__.py",
                     "pkg/sub/late.py"]
    assert third == ["numpy"]  # os is the standard library's
    rec = inputs.record(["pkg.entry"], ["data.json"], str(tmp_path))
    assert rec["files"] == sorted(files + ["data.json"])
    assert set(rec["packages"]) == {"numpy"}


def test_one_byte_of_any_input_moves_the_hash(tmp_path):
    pkg = _tree(tmp_path)
    h = inputs.record(["pkg.entry"], ["data.json"], str(tmp_path))["sha256"]
    for p in (pkg / "sub" / "late.py", tmp_path / "data.json"):
        old = p.read_text()
        p.write_text(old + " ")
        assert inputs.record(["pkg.entry"], ["data.json"], str(tmp_path))["sha256"] != h, p
        p.write_text(old)
    (pkg / "unused.py").write_text("x = 3\n")  # not imported: not an input
    assert inputs.record(["pkg.entry"], ["data.json"], str(tmp_path))["sha256"] == h
    os.remove(tmp_path / "data.json")
    assert inputs.record(["pkg.entry"], ["data.json"], str(tmp_path))["sha256"] != h


def test_committed_records_name_their_inputs():
    for p in sorted(os.listdir(os.path.join(ROOT, "tables"))):
        if p.endswith(".json"):
            with open(os.path.join(ROOT, "tables", p), encoding="ascii") as f:
                rec = json.load(f)["inputs"]
            assert rec["files"] and len(rec["sha256"]) == 64 and "numpy" in rec["packages"], p
            assert all(os.path.exists(os.path.join(ROOT, x)) for x in rec["files"]), p
    with open(os.path.join(ROOT, "tests", "ref", "inputs.json"), encoding="ascii") as f:
        refs = json.load(f)
    out = subprocess.run([sys.executable, os.path.join(ROOT, "tests", "ref", "generate.py"), "all",
                          "--list"], capture_output=True, text=True, check=True).stdout.split()
    assert len(refs) == 7 and len(out) == 8


def test_changed_with_the_committed_record_regenerates_nothing(tmp_path):
    """A --changed run under a root holding the committed files writes nothing: the record
    the sidecars hold is today's (a baker edited and not re-baked fails here)."""
    (tmp_path / "tables").mkdir()
    for e in ("c", "h", "json"):
        shutil.copy(os.path.join(ROOT, "tables", "oi_earth_geo." + e), tmp_path / "tables")
    before = {p: os.path.getmtime(tmp_path / "tables" / p) for p in os.listdir(tmp_path / "tables")}
    cfg = os.path.join(ROOT, "bake", "config", "scene_geo.json")
    r = subprocess.run([sys.executable, "-m", "bake", "--scene", cfg, "--changed", "--root",
                        str(tmp_path)], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert "oi_earth_geo: inputs unchanged" in r.stdout and "baked 0 table(s)" in r.stdout
    assert {p: os.path.getmtime(tmp_path / "tables" / p)
            for p in os.listdir(tmp_path / "tables")} == before
    # the reference vectors: with the committed record under the root, no generator runs
    (tmp_path / "tests" / "ref").mkdir(parents=True)
    shutil.copy(os.path.join(ROOT, "tests", "ref", "inputs.json"), tmp_path / "tests" / "ref")
    r = subprocess.run([sys.executable, os.path.join(ROOT, "tests", "ref", "generate.py"), "all",
                        "--changed", "--root", str(tmp_path)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert r.stderr.count("inputs unchanged") == 7 and not (tmp_path / "tests" / "c").exists()
