# SPDX-License-Identifier: MIT
"""The ctypes structures of the binding mirror include/orbillum.h exactly.

A C program compiled against the header prints sizeof and offsetof of every
field of every public structure; each must equal the ctypes layout.
"""
import ctypes
import os
import shutil
import subprocess

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

def _load_mirror():
    """python/orbillum/_lib.py alone (importing the package would load the library)."""
    import importlib.util
    spec = importlib.util.spec_from_file_location(
        "orbillum_lib_mirror", os.path.join(ROOT, "python", "orbillum", "_lib.py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


L = _load_mirror()


def _c_layout(tmp_path):
    cc = os.environ.get("CC", "cc")
    if shutil.which(cc) is None:
        pytest.fail(f"no C compiler {cc!r}: the binding cannot be built either")
    lines = ['#include <stdio.h>', '#include <stddef.h>', '#include "orbillum.h"',
             "int main(void) {"]
    for st in L.STRUCTS:
        n = st.__name__
        lines.append(f'printf("{n} sizeof %zu\\n", sizeof({n}));')
        for f, _t in st._fields_:
            lines.append(f'printf("{n} {f} %zu %zu\\n", offsetof({n}, {f}), '
                         f'sizeof(((({n} *)0)->{f})));')
    lines.append("return 0; }")
    src = tmp_path / "layout.c"
    src.write_text("\n".join(lines) + "\n")
    exe = tmp_path / "layout"
    subprocess.check_call([cc, "-std=c99", "-I" + os.path.join(ROOT, "include"), str(src),
                           "-o", str(exe)])
    out = {}
    for ln in subprocess.check_output([str(exe)], text=True).splitlines():
        parts = ln.split()
        out[tuple(parts[:2])] = tuple(int(x) for x in parts[2:])
    return out


def test_struct_layouts_match_header(tmp_path):
    c = _c_layout(tmp_path)
    for st in L.STRUCTS:
        n = st.__name__
        assert c[(n, "sizeof")] == (ctypes.sizeof(st),), f"{n}: sizeof"
        for f, _t in st._fields_:
            desc = getattr(st, f)
            assert c[(n, f)] == (desc.offset, desc.size), f"{n}.{f}: offset/size"


def test_every_header_field_is_mirrored(tmp_path):
    """Fields added to the header later must be added here too: compare counts
    by compiling a check that the last mirrored field ends the structure."""
    c = _c_layout(tmp_path)
    for st in L.STRUCTS:
        n = st.__name__
        last = st._fields_[-1][0]
        off, size = c[(n, last)]
        total = c[(n, "sizeof")][0]
        align = max(ctypes.alignment(t) for _f, t in st._fields_)
        assert off + size <= total < off + size + align, f"{n}: fields after {last}?"
