#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Generate the C tests' reference vectors, one command for all of them.

    python tests/ref/generate.py {earthshine,atmosphere,shadow,occulters,stability,oblate,sphere,all} [--root DIR] [--list]

  earthshine   tests/c/ref_earthshine.h    quadrature reference (bake.earthshine.reference)
  atmosphere   tests/c/ref_atmosphere.h    ray reference and the lookup's Python mirror on
                                           the committed table tables/oi_atm_vband.c
  shadow       tests/c/ref_phase.h, tests/c/ref_shadow.h   mpmath at 45 digits (~6 min)
  occulters    tests/c/ref_occulters.h     the Moon's shadow and the Earth hiding the Moon,
                                           mpmath ring quadrature at 30 digits (~5 s)
  stability    tests/stability/vectors.h   mpmath at 60 digits
  oblate       tests/c/ref_oblate.h        the WGS-84 ellipsoid's shadow and its hiding the
                                           Moon, mpmath polar quadrature at 30 digits (~6 min)
  sphere       tests/c/ref_sphere.h        a sphere's flux under earthshine, the quadrature of
                                           bake.earthshine.angular (~5 s)

--root DIR writes at the repository-relative paths under DIR (default: the
repository); --list prints those paths, one a line, and generates nothing.
Each run records the sha256 of each generator's inputs (its script and the repository
modules it imports, the data files of DATA, the numpy/mpmath versions: bake/common/inputs.py)
in tests/ref/inputs.json under the root; --changed runs only the generators whose inputs
differ from that record (make check-generated). A generator that reads a repository file
DATA does not name fails.
Each generator runs in a process of its own (each sets its own mpmath
precision before its constants). Outputs are byte-for-byte reproducible: no
timestamps, fixed seeds, values computed in double printed rounded below
their machine-dependent last bits, mpmath values exactly.
"""

import argparse
import json
import os
import runpy
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, ROOT)
from bake.common import inputs as gen_inputs  # noqa: E402

RECORD = "tests/ref/inputs.json"
GENERATORS = {
    "earthshine": ["tests/c/ref_earthshine.h"],
    "atmosphere": ["tests/c/ref_atmosphere.h"],
    "shadow": ["tests/c/ref_phase.h", "tests/c/ref_shadow.h"],
    "occulters": ["tests/c/ref_occulters.h"],
    "stability": ["tests/stability/vectors.h"],
    "oblate": ["tests/c/ref_oblate.h"],
    "sphere": ["tests/c/ref_sphere.h"],
}
# the files besides Python each generator reads (the committed tables it mirrors)
DATA = {
    "atmosphere": ["tables/oi_atm_vband.c"],
    "stability": ["tables/oi_earth_diffuse.c"],
}


def inputs_of(name):
    """The inputs record of one generator (bake/common/inputs.py)."""
    return gen_inputs.record(["tests/ref/%s.py" % name], DATA.get(name, ()), ROOT)


def read_record(root):
    try:
        with open(os.path.join(root, RECORD), encoding="ascii") as f:
            return json.load(f)
    except (OSError, ValueError):
        return {}


def write_record(root, rec):
    p = os.path.join(root, RECORD)
    os.makedirs(os.path.dirname(p), exist_ok=True)
    with open(p, "w", encoding="ascii", newline="\n") as f:
        f.write(json.dumps(rec, indent=2, sort_keys=True) + "\n")


def run_one(name, root):
    """In the generator's own process: run its script, then fail on an undeclared read."""
    script = os.path.join(HERE, name + ".py")
    gen_inputs.watch_reads()
    sys.argv = [script] + (["--root", root] if root else [])
    sys.path.insert(0, HERE)
    code = 0
    try:
        runpy.run_path(script, run_name="__main__")
    except SystemExit as e:
        code = e.code if isinstance(e.code, int) else (0 if e.code is None else 1)
    if code:
        return code
    unread = gen_inputs.unread_data(DATA.get(name, ()), ROOT, GENERATORS[name])
    if unread:
        print("generate %s: read %s, which DATA does not name (tests/ref/generate.py)"
              % (name, ", ".join(unread)), file=sys.stderr)
        return 1
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(prog="tests/ref/generate.py", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("target", choices=sorted(GENERATORS) + ["all"])
    ap.add_argument("--root", default=None, help="output root (default: the repository)")
    ap.add_argument("--list", action="store_true", help="print the output paths only")
    ap.add_argument("--changed", action="store_true",
                    help="run only the generators whose inputs differ from " + RECORD)
    ap.add_argument("--run-one", action="store_true", help=argparse.SUPPRESS)
    a = ap.parse_args(argv)
    if a.run_one:
        return run_one(a.target, a.root)
    names = sorted(GENERATORS) if a.target == "all" else [a.target]
    if a.list:
        for n in names:
            print("\n".join(GENERATORS[n]))
        return 0
    root = os.path.abspath(a.root) if a.root else ROOT
    for n in names:
        rec = inputs_of(n)
        if a.changed and read_record(root).get(n, {}).get("sha256") == rec["sha256"]:
            print("generate %s: inputs unchanged (sha256 %s), not run" % (n, rec["sha256"][:12]),
                  file=sys.stderr, flush=True)
            continue
        cmd = [sys.executable, os.path.abspath(__file__), n, "--run-one"]
        if a.root:
            cmd += ["--root", root]
        print("generate %s" % n, file=sys.stderr, flush=True)
        r = subprocess.run(cmd)
        if r.returncode:
            print("generate %s failed (exit %d)" % (n, r.returncode), file=sys.stderr)
            return r.returncode
        record = read_record(root)
        record[n] = rec
        write_record(root, record)
    return 0


if __name__ == "__main__":
    sys.exit(main())
