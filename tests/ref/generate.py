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
Each generator runs in a process of its own (each sets its own mpmath
precision before its constants). Outputs are byte-for-byte reproducible: no
timestamps, fixed seeds, values computed in double printed rounded below
their machine-dependent last bits, mpmath values exactly.
"""

import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
GENERATORS = {
    "earthshine": ["tests/c/ref_earthshine.h"],
    "atmosphere": ["tests/c/ref_atmosphere.h"],
    "shadow": ["tests/c/ref_phase.h", "tests/c/ref_shadow.h"],
    "occulters": ["tests/c/ref_occulters.h"],
    "stability": ["tests/stability/vectors.h"],
    "oblate": ["tests/c/ref_oblate.h"],
    "sphere": ["tests/c/ref_sphere.h"],
}


def main(argv=None):
    ap = argparse.ArgumentParser(prog="tests/ref/generate.py", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("target", choices=sorted(GENERATORS) + ["all"])
    ap.add_argument("--root", default=None, help="output root (default: the repository)")
    ap.add_argument("--list", action="store_true", help="print the output paths only")
    a = ap.parse_args(argv)
    names = sorted(GENERATORS) if a.target == "all" else [a.target]
    if a.list:
        for n in names:
            print("\n".join(GENERATORS[n]))
        return 0
    for n in names:
        cmd = [sys.executable, os.path.join(HERE, n + ".py")]
        if a.root:
            cmd += ["--root", os.path.abspath(a.root)]
        print("generate %s" % n, file=sys.stderr, flush=True)
        r = subprocess.run(cmd)
        if r.returncode:
            print("generate %s failed (exit %d)" % (n, r.returncode), file=sys.stderr)
            return r.returncode
    return 0


if __name__ == "__main__":
    sys.exit(main())
