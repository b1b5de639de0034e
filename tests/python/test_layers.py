# SPDX-License-Identifier: MIT
"""tools/check_layers.py finds what breaks the layer rule (docs/architecture.md).

Small trees of two layers are compiled with the host's C compiler and
checked: a clean one passes; a call up, a header of the layer above, an
included .c file and two files that need each other each fail, named.
"""
import os
import shutil
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import check_layers  # noqa: E402

CC = shutil.which("cc") or shutil.which("gcc")
pytestmark = pytest.mark.skipif(CC is None, reason="no C compiler")


def tree(tmp_path, files):
    """Write files {relative path: text} under src/, compile every .c, return (src, objects)."""
    src = tmp_path / "src"
    for rel, text in files.items():
        path = src / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    obj = tmp_path / "obj"
    for rel in files:
        if rel.endswith(".c"):
            out = obj / "src" / (rel[:-2] + ".o")
            out.parent.mkdir(parents=True, exist_ok=True)
            subprocess.run([CC, "-c", "-I", str(src), str(src / rel), "-o", str(out)], check=True)
    return str(src), str(obj)


def run(src, obj, capsys):
    rc = check_layers.main(["--layers", "low high", "--objects", obj, "--src", src,
                            "--include", os.path.join(src, "none")])
    return rc, capsys.readouterr().out


CLEAN = {
    "base.h": "int base_value(void);\n",
    "low/low_internal.h": '#include "base.h"\nint low_f(int x);\n',
    "low/low.c": '#include "low/low_internal.h"\nint low_f(int x) { return x + 1; }\n',
    "high/high_internal.h": '#include "low/low_internal.h"\nint high_f(int x);\n',
    "high/high.c": '#include "high/high_internal.h"\nint high_f(int x) { return low_f(x) * 2; }\n',
}


def test_clean_tree_passes(tmp_path, capsys):
    src, obj = tree(tmp_path, CLEAN)
    rc, out = run(src, obj, capsys)
    assert rc == 0, out
    assert "every include and call goes down" in out


def test_call_up_and_cycle_fail(tmp_path, capsys):
    files = dict(CLEAN)
    files["low/low.c"] = ('#include "low/low_internal.h"\nint high_f(int x);\n'
                          "int low_f(int x) { return x > 0 ? high_f(x - 1) : 0; }\n")
    src, obj = tree(tmp_path, files)
    rc, out = run(src, obj, capsys)
    assert rc == 1
    assert "src/low/low.c calls up into src/high/high.c: high_f" in out
    assert "files that need each other: src/high/high.c, src/low/low.c" in out


def test_header_of_the_layer_above_fails(tmp_path, capsys):
    files = dict(CLEAN)
    files["low/low.c"] = ('#include "high/high_internal.h"\nint low_f(int x) { return x + 1; }\n')
    src, obj = tree(tmp_path, files)
    rc, out = run(src, obj, capsys)
    assert rc == 1
    assert "src/low/low.c: includes high/high_internal.h, a header of the layer above (high)" in out


def test_included_c_file_fails(tmp_path, capsys):
    files = dict(CLEAN)
    files["high/twice.c"] = '#include "high.c"\n'
    files["high/high.c"] = ('#include "high/high_internal.h"\n'
                            "static int twice(int x) { return low_f(x) * 2; }\n"
                            "int high_f(int x) { return twice(x); }\n")
    src, obj = tree(tmp_path, files)
    rc, out = run(src, obj, capsys)
    assert rc == 1
    assert "src/high/twice.c: includes a .c file (high.c)" in out


def test_source_outside_the_layers_fails(tmp_path, capsys):
    files = dict(CLEAN)
    files["stray.c"] = "int stray(void) { return 0; }\n"
    src, obj = tree(tmp_path, files)
    rc, out = run(src, obj, capsys)
    assert rc == 1
    assert "src/stray.c: a source outside every layer" in out
