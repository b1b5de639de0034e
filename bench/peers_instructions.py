"""peers_instructions.py: instructions per point of numpy Montenbruck & Gill
(bench/peers.py's mg_fraction) and of oi_sun_fraction_batch (outputs mask 0,
through the binding's library) on the same points, counted by callgrind: the
repeatable form of the Sun-fraction goal's ratio (wall times on shared cores
vary by 2-3x between runs, instruction counts do not).

Usage: python bench/peers_instructions.py --bench build/bench/bench-double
  [--n 20000] [--which mix|lit_umbra]
Each side is run under valgrind twice, over n and 2n points (the points of
`bench points` tiled), each call made 3 times; instructions per point =
(I(2n) - I(n)) / (3 n), so the interpreter's start and the imports cancel.
The child mode (--child SIDE N) is what valgrind runs.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
CALLS = 3


def read_points(bench, which):
    sun, r = [], []
    out = subprocess.run([bench, "points"], check=True, capture_output=True, text=True).stdout
    for line in out.splitlines():
        if line.startswith("#"):
            continue
        f = line.split()
        if which == "lit_umbra" and f[0] == "penumbra":
            continue
        v = [float(x) for x in f[1:]]
        sun.append(v[0:3])
        r.append(v[3:6])
    return np.array(sun), np.array(r)


def tiled(a, n):
    k = -(-n // len(a))
    return np.ascontiguousarray(np.tile(a, (k, 1))[:n])


def child(side, n, bench, which):
    sun, r = read_points(bench, which)
    sun_n, r_n = tiled(sun, n), tiled(r, n)
    if side == "numpy_mg":
        sys.path.insert(0, HERE)
        import peers
        for _ in range(CALLS):
            peers.mg_fraction(sun_n, r_n)
    else:
        import orbillum
        lib, L = orbillum._lib, orbillum.L
        sh = np.empty(n, dtype=np.dtype(L.oi_shadow))
        st = np.empty(n, dtype=np.intc)
        for _ in range(CALLS):
            lib.oi_sun_fraction_batch(n, sun_n.ctypes.data, r_n.ctypes.data, None, 0,
                                      sh.ctypes.data, st.ctypes.data)


def instructions(side, n, bench, which, tmp):
    path = os.path.join(tmp, "cg.%s.%d.out" % (side, n))
    subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + path,
                    sys.executable, os.path.abspath(__file__), "--bench", bench, "--which", which,
                    "--child", side, str(n)], check=True, capture_output=True, text=True)
    with open(path) as f:
        for line in f:
            m = re.match(r"^(summary|totals): (\d+)", line)
            if m:
                return int(m.group(2))
    raise SystemExit("no callgrind total for %s" % side)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bench", required=True, help="bench-double (for `bench points`)")
    ap.add_argument("--n", type=int, default=20000)
    ap.add_argument("--which", choices=("mix", "lit_umbra"), default="mix")
    ap.add_argument("--child", nargs=2, metavar=("SIDE", "N"))
    args = ap.parse_args()
    if args.child:
        child(args.child[0], int(args.child[1]), args.bench, args.which)
        return 0
    per = {}
    with tempfile.TemporaryDirectory() as tmp:
        for side in ("numpy_mg", "orbillum"):
            i1 = instructions(side, args.n, args.bench, args.which, tmp)
            i2 = instructions(side, 2 * args.n, args.bench, args.which, tmp)
            per[side] = (i2 - i1) / float(CALLS * args.n)
    print("peer.numpy_mg.%s.instructions_per_point %.0f instructions  # callgrind, "
          "(I(%d) - I(%d)) / (%d x %d points)" % (args.which, per["numpy_mg"], 2 * args.n,
                                                   args.n, CALLS, args.n))
    print("peer.orbillum.sun_fraction_batch.%s.instructions_per_point %.0f instructions  "
          "# outputs mask 0, the same points" % (args.which, per["orbillum"]))
    print("peer.numpy_mg.over.sun_fraction_batch.%s.instructions %.2f x  # peer / orbillum "
          "instructions per point; > 1: orbillum cheaper" % (args.which,
                                                           per["numpy_mg"] / per["orbillum"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
