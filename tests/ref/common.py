# SPDX-License-Identifier: MIT
"""What every reference generator shares: the repository root, the mpmath
set-up, the exact C literal writers, and writing an output at its
repository-relative path under a root (`--root DIR`)."""

import os
import sys

import mpmath as mp

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
if ROOT not in sys.path:
    sys.path.insert(0, ROOT)  # the baker's reference (bake.earthshine, bake.atmosphere)


def setup_mpmath(dps):
    """The working precision of a generator, set once before its constants."""
    mp.mp.dps = int(dps)
    return mp


def c_hex(x):
    """C literal that is exactly the binary value of x (a hex float)."""
    x = float(x)
    if x == 0:
        return "-0.0" if str(x).startswith("-") else "0.0"
    return x.hex()


def c_repr(x):
    """The shortest decimal C literal that reads back as the double x."""
    x = float(x)
    if x == 0:
        return "-0.0" if str(x).startswith("-") else "0.0"
    s = repr(x)
    return s if ("e" in s or "." in s) else s + ".0"


def c_sig(x, digits):
    """x rounded to `digits` significant digits: for values computed in
    double (numpy quadrature) whose last bits depend on the machine."""
    return "%.*g" % (digits, float(x))


def write(root, rel, text):
    """Write text to root/rel (creating folders); returns the path."""
    path = os.path.join(root or ROOT, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="ascii", newline="\n") as f:
        f.write(text)
    return path


def cli(outputs, generate, doc):
    """The one command line of a generator: [--root DIR] [--list]."""
    import argparse
    ap = argparse.ArgumentParser(description=doc.splitlines()[0])
    ap.add_argument("--root", default=ROOT, help="output root (default: the repository)")
    ap.add_argument("--list", action="store_true", help="print the output paths, generate nothing")
    a, rest = ap.parse_known_args()
    if a.list:
        print("\n".join(outputs))
        return 0
    for p in generate(a.root, rest):
        print("wrote %s" % p, file=sys.stderr)
    return 0
