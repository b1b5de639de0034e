# SPDX-License-Identifier: MIT
"""What a generated file is computed from, and a hash of it (make check-generated).

A generator's inputs are
  * the repository's Python files it runs: its entry modules or scripts and every repository
    module they import, transitively (each import statement of each file, those inside
    functions too, and the packages' __init__.py), read from the sources without importing;
  * the data files it reads (declared by the caller: configurations, committed tables);
  * the versions of the installed third-party packages those files import (numpy, scipy,
    mpmath: their last bits are the generators' last bits).

record() gives {"sha256", "files", "packages"}: the sha256 runs over each file's
repository-relative path and the sha256 of its bytes, in sorted order, then "name==version"
per package. The tables' sidecars (tables/*.json, key "inputs") and tests/ref/inputs.json hold
it; `make check-generated` recomputes it and regenerates only what changed (docs/tables.md).

Guard (watch_reads / unread_data): the generators' processes also list every repository file
they open for reading; one that is neither a Python file nor a declared data file fails the
run, so a new data file cannot be read without becoming an input.
"""

import ast
import hashlib
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def _find(name, search):
    """(file, is_package) of the absolute module name in the search folders, or None."""
    parts = name.split(".")
    for base in search:
        p = os.path.join(base, *parts)
        if os.path.isfile(p + ".py"):
            return p + ".py", False
        if os.path.isfile(os.path.join(p, "__init__.py")):
            return os.path.join(p, "__init__.py"), True
    return None


def _imports(path, module, is_pkg):
    """(absolute names each import statement of the file may load, top-level names)."""
    with open(path, encoding="utf-8") as f:
        tree = ast.parse(f.read(), path)
    pkg = module.split(".") if is_pkg else module.split(".")[:-1]
    names = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names += [(a.name, None) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = pkg[:len(pkg) - node.level + 1]
                full = ".".join(base + ([node.module] if node.module else []))
            else:
                full = node.module
            names += [(full, a.name) for a in node.names]
    return names


def python_files(entries, root=ROOT):
    """(sorted repository-relative Python files, sorted third-party top-level names) of the
    entries: module names ("bake.skylight.table") or script paths ("tests/ref/shadow.py",
    relative to root; a script's own folder is searched first, as Python does)."""
    root = os.path.abspath(root)
    seen, third = set(), set()
    todo = []
    for e in entries:
        if e.endswith(".py"):
            p = os.path.join(root, e)
            todo.append((p, os.path.splitext(os.path.basename(p))[0], False,
                         (os.path.dirname(p), root)))
        else:
            found = _find(e, (root,))
            if found is None:
                raise ValueError("inputs: no module %s under %s" % (e, root))
            todo.append((found[0], e, found[1], (root,)))
    while todo:
        path, module, is_pkg, search = todo.pop()
        if path in seen:
            continue
        seen.add(path)
        parts = module.split(".")
        for i in range(1, len(parts)):       # the packages a module's import runs first
            init = _find(".".join(parts[:i]), search)
            if init is not None:
                todo.append((init[0], ".".join(parts[:i]), True, search))
        for full, alias in _imports(path, module, is_pkg):
            hit = None
            if alias is not None and alias != "*":
                hit = _find(full + "." + alias, search)
                name = full + "." + alias
            if hit is None:
                hit, name = _find(full, search), full
            if hit is not None:
                todo.append((hit[0], name, hit[1], search))
            else:
                top = full.split(".")[0]
                if top and top not in sys.stdlib_module_names:
                    third.add(top)
    rel = sorted(os.path.relpath(p, root).replace(os.sep, "/") for p in seen)
    return rel, sorted(third)


def _versions(tops):
    from importlib import metadata
    dists = metadata.packages_distributions()
    out = {}
    for t in tops:
        for d in dists.get(t, ()):
            out[d] = metadata.version(d)
    return out


def _file_sha(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def record(entries, data=(), root=ROOT):
    """{"sha256", "files", "packages"} of a generator (see the module docstring); a missing
    data file hashes as "missing"."""
    root = os.path.abspath(root)
    py, third = python_files(entries, root)
    files = sorted(set(py) | {d.replace(os.sep, "/") for d in data})
    packages = _versions(third)
    h = hashlib.sha256()
    for f in files:
        p = os.path.join(root, f)
        h.update(("%s\0%s\n" % (f, _file_sha(p) if os.path.isfile(p) else "missing")).encode())
    for k in sorted(packages):
        h.update(("%s==%s\n" % (k, packages[k])).encode())
    return {"sha256": h.hexdigest(), "files": files, "packages": packages}


# ------------------------------------------------------------------ the guard on data files

_READS = []


def watch_reads():
    """From now on, list every file this process opens for reading (an audit hook)."""
    if _READS:
        return

    def hook(event, args):
        if event == "open" and args and isinstance(args[0], (str, bytes)):
            mode = args[1] if len(args) > 1 and isinstance(args[1], str) else "r"
            if not any(c in mode for c in "wax+"):
                p = args[0] if isinstance(args[0], str) else os.fsdecode(args[0])
                _READS.append(os.path.abspath(p))
    _READS.append(None)
    sys.addaudithook(hook)


def unread_data(declared, root=ROOT, written=()):
    """Repository files this process read that are not Python files, not in `declared`
    (repository-relative) and not written by it: what a generator reads without naming it."""
    root = os.path.abspath(root)
    skip = {os.path.abspath(os.path.join(root, w)) for w in written}
    decl = {os.path.abspath(os.path.join(root, d)) for d in declared}
    prefixes = {os.path.abspath(sys.prefix) + os.sep, os.path.abspath(sys.base_prefix) + os.sep}
    out = set()
    for p in _READS:
        if p is None or not p.startswith(root + os.sep) or p in decl or p in skip:
            continue
        if any(p.startswith(x) for x in prefixes) or p.endswith((".py", ".pyc")):
            continue
        if "__pycache__" in p.split(os.sep) or not os.path.isfile(p):
            continue
        out.add(os.path.relpath(p, root).replace(os.sep, "/"))
    return sorted(out)
