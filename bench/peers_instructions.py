# SPDX-License-Identifier: MIT
"""peers_instructions.py: instructions per point of the Sun fraction's planar peers
(numpy Montenbruck & Gill, bench/peers.py's mg_fraction; Orekit's and Basilisk's
harnesses when `make peers` built them) and of oi_sun_fraction_batch (outputs mask 0,
through the binding's library) on the same points, counted by callgrind: the
repeatable form of the Sun-fraction goal's ratio (wall times on shared cores
vary by 2-3x between runs, instruction counts do not).

Usage: python bench/peers_instructions.py --bench build/bench/bench-double
  [--n 20000] [--which mix|lit_umbra|penumbra|orbits] [--peers build/peers]
The points: those of `bench points` tiled (mix, lit_umbra), or bench/peers.py's
orbit_points(2 n) (orbits: LEO/MEO/GEO orbits sampled uniformly in time).
numpy and orbillum: each side is run under valgrind twice, over the first n and
all 2n points, each call made 3 times; instructions per point = (I(2n) - I(n)) /
(3 n), so the interpreter's start and the imports cancel: the count of the last n
points. Orekit and Basilisk: their harness over those last n points under
valgrind twice, with 1 and 1 + P timed passes after the same warm-up (P =
--peer-passes, 3 by default); per point = (I(1 + P) - I(1)) / (P n), so the
start, the set-up and the warm-up cancel. The JVM runs with -Xbatch (each method
compiled before it runs on, so the passes run the compiled loop as they do
outside valgrind) and the serial collector. Basilisk takes one Sun for all rows
(bench/peers.py's one_sun): orbillum is counted on those rows too for its ratio.
The child mode (--child SIDE ROWS: the rows in a file the parent wrote) is what
valgrind runs for numpy and orbillum.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import peers  # noqa: E402

CALLS = 3
JVM_FLAGS = ["-Xbatch", "-XX:+UseSerialGC"]
PEER_WARMUP = {"orekit": 20, "basilisk": 1}


def read_points(bench, which):
    sun, r = [], []
    out = subprocess.run([bench, "points"], check=True, capture_output=True, text=True).stdout
    for line in out.splitlines():
        if line.startswith("#"):
            continue
        f = line.split()
        if which == "lit_umbra" and f[0] == "penumbra":
            continue
        if which == "penumbra" and f[0] != "penumbra":
            continue
        v = [float(x) for x in f[1:]]
        sun.append(v[0:3])
        r.append(v[3:6])
    return np.array(sun), np.array(r)


def tiled(a, n):
    k = -(-n // len(a))
    return np.ascontiguousarray(np.tile(a, (k, 1))[:n])


def points(bench, which, n):
    """The 2 n points the counts run over (see the module's text)."""
    if which == "orbits":
        sun, r = peers.orbit_points(2 * n)
    else:
        sun, r = read_points(bench, which)
        sun, r = tiled(sun, 2 * n), tiled(r, 2 * n)
    return sun, r


def child(side, path):
    """The side's calls over the rows of the file (written by the parent, so
    that the child's own work per row is reading them)."""
    rows = np.fromfile(path, dtype="<f8").reshape(-1, 6)
    n = len(rows)
    sun_n, r_n = np.ascontiguousarray(rows[:, 0:3]), np.ascontiguousarray(rows[:, 3:6])
    if side == "numpy_mg":
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


def callgrind(cmd, path):
    # numpy's OpenBLAS starts a thread server that spins while the main thread
    # works, and valgrind counts its spinning as the scheduler happens to run
    # it: orbillum's count of one build moved between 148 and 557 a point
    # from run to run. No counted call uses BLAS; one thread keeps it still.
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + path] + cmd,
                   check=True, capture_output=True, text=True, env=env)
    with open(path) as f:
        for line in f:
            m = re.match(r"^(summary|totals): (\d+)", line)
            if m:
                return int(m.group(2))
    raise SystemExit("no callgrind total for %s" % " ".join(cmd))


def instructions(side, sun, r, tmp):
    path = os.path.join(tmp, "rows.%s.%d.bin" % (side, len(r)))
    np.hstack([sun, r]).astype("<f8").tofile(path)
    return callgrind([sys.executable, os.path.abspath(__file__), "--child", side, path],
                     os.path.join(tmp, "cg.%s.%d.out" % (side, len(r))))


def peer_instructions(name, cmd, sun, r, tmp, passes):
    """Instructions per point of a process peer's timed pass over the rows:
    (I(1 + passes) - I(1)) / (passes n)."""
    src = os.path.join(tmp, "points.%s.bin" % name)
    np.hstack([sun, r]).astype("<f8").tofile(src)
    dst = os.path.join(tmp, "fractions.%s.bin" % name)
    if name == "orekit":
        cmd = cmd[:1] + JVM_FLAGS + cmd[1:]
    total = {}
    for reps in (1, 1 + passes):
        extra = ([str(reps), str(PEER_WARMUP[name])] if name == "orekit" else
                 ["--reps", str(reps), "--warmup", str(PEER_WARMUP[name])])
        total[reps] = callgrind(cmd + [src, dst] + extra,
                                os.path.join(tmp, "cg.%s.%d.out" % (name, reps)))
    return (total[1 + passes] - total[1]) / float(passes * len(r))


def measure(bench, n=20000, which="mix"):
    """Instructions per point of numpy M&G and oi_sun_fraction_batch on the same
    points: {"numpy_mg": ..., "orbillum": ...} (make bench's goal line)."""
    per = {}
    sun, r = points(bench, which, n)
    with tempfile.TemporaryDirectory() as tmp:
        for side in ("numpy_mg", "orbillum"):
            i1 = instructions(side, sun[:n], r[:n], tmp)
            i2 = instructions(side, sun, r, tmp)
            per[side] = (i2 - i1) / float(CALLS * n)
    return per


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bench", help="bench-double (for `bench points`)")
    ap.add_argument("--n", type=int, default=20000)
    ap.add_argument("--which", choices=("mix", "lit_umbra", "penumbra", "orbits"), default="mix")
    ap.add_argument("--peers", metavar="DIR", help="where `make peers` built the Orekit and "
                    "Basilisk harnesses (build/peers): count them too")
    ap.add_argument("--peer-passes", type=int, default=CALLS,
                    help="timed passes the process peers' count takes (more dilutes the "
                         "set-up's run-to-run differences: Basilisk's 2 Python objects a row)")
    ap.add_argument("--only", choices=[p[0] for p in peers.PROCESS_PEERS],
                    help="count only this process peer (and orbillum on its rows)")
    ap.add_argument("--child", nargs=2, metavar=("SIDE", "ROWS"))
    args = ap.parse_args()
    if args.child:
        child(args.child[0], args.child[1])
        return 0
    if not args.bench:
        ap.error("--bench is required")
    per = {}
    with tempfile.TemporaryDirectory() as tmp:
        sides = ["numpy_mg", "orbillum"]
        commands = {}
        if args.peers:
            for name, _, command, _, _ in peers.PROCESS_PEERS:
                cmd, why = command(args.peers)
                if args.only and name != args.only:
                    continue
                if cmd is None:
                    print("peer.%s.%s.instructions_per_point unavailable -  # %s"
                          % (name, args.which, why))
                else:
                    commands[name] = cmd
            if args.only:
                sides = [] if args.only == "basilisk" else ["orbillum"]
            if "basilisk" in commands:
                sides.append("orbillum_one_sun")
            sides = sorted(set(sides), key=sides.index)
        sun, r = points(args.bench, args.which, args.n)
        turned = peers.one_sun(sun, r)
        for side in sides:
            s2, r2 = turned if side.endswith("_one_sun") else (sun, r)
            i1 = instructions(side, s2[:args.n], r2[:args.n], tmp)
            i2 = instructions(side, s2, r2, tmp)
            per[side] = (i2 - i1) / float(CALLS * args.n)
        sun_n, r_n = np.ascontiguousarray(sun[args.n:]), np.ascontiguousarray(r[args.n:])
        for name, cmd in commands.items():
            rows = ((np.ascontiguousarray(turned[0][args.n:]), np.ascontiguousarray(turned[1][args.n:]))
                    if name == "basilisk" else (sun_n, r_n))
            per[name] = peer_instructions(name, cmd, rows[0], rows[1], tmp, args.peer_passes)
    if "numpy_mg" in per:
        print("peer.numpy_mg.%s.instructions_per_point %.0f instructions  # callgrind, "
              "(I(%d) - I(%d)) / (%d x %d points)" % (args.which, per["numpy_mg"], 2 * args.n,
                                                       args.n, CALLS, args.n))
        print("peer.orbillum.sun_fraction_batch.%s.instructions_per_point %.0f instructions  "
              "# outputs mask 0, the same points" % (args.which, per["orbillum"]))
        print("peer.numpy_mg.over.sun_fraction_batch.%s.instructions %.2f x  # peer / orbillum "
              "instructions per point; > 1: orbillum cheaper"
              % (args.which, per["numpy_mg"] / per["orbillum"]))
    for name in commands:
        base = "orbillum_one_sun" if name == "basilisk" else "orbillum"
        print("peer.%s.%s.instructions_per_point %.0f instructions  # callgrind, its timed pass, "
              "(I(%d passes) - I(1)) / (%d x %d points)%s"
              % (name, args.which, per[name], 1 + args.peer_passes, args.peer_passes, args.n,
                 "; the rows turned to one Sun" if name == "basilisk" else ""))
        if name == "basilisk":
            print("peer.orbillum.sun_fraction_batch.%s_one_sun.instructions_per_point %.0f "
                  "instructions  # outputs mask 0, the rows turned to one Sun"
                  % (args.which, per[base]))
        print("peer.%s.over.sun_fraction_batch.%s.instructions %.2f x  # peer / orbillum "
              "instructions per point; > 1: orbillum cheaper" % (name, args.which,
                                                               per[name] / per[base]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
