# SPDX-License-Identifier: MIT
"""binding_cost.py: the Python binding's cost per row against the C batch
call it makes, on the same rows in the same process (make bench,
bench/run_bench.py).

For each entry point the binding's whole call (arrays in, dict of arrays
out: argument checks, the scene records, the status names) is timed, and
the C batch call alone on the same prepared arrays through the same loaded
library; the ratio is the binding's overhead (goal: at most 1.3). Rows: the
benchmark's scene mix (`bench points`) tiled to N rows; medians of 9 calls, the binding's and
the C call's interleaved.

Instructions (the same ratio without the machine's load):
  python bench/binding_cost.py --callgrind [--bench build/bench/bench-double] [--n 2000]
runs each side of each case under valgrind --tool=callgrind in a child
process, K = 1 and K = 3 calls, and prints (I(3) - I(1)) / (2 n) per row and
the ratio: start-up, imports and the set-up cancel out.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from timing import interleaved_seconds, tile_rows  # noqa: E402


def _median_ns_pair(f, g, n, reps=9):
    """Median and least ns per row of f and of g, their calls interleaved so
    that a change of the machine's load falls on both: (f median, g median,
    f least, g least). The least is the call other jobs disturbed least."""
    tf, tg = interleaved_seconds(f, g, reps)
    return (tf[reps // 2] * 1e9 / n, tg[reps // 2] * 1e9 / n, tf[0] * 1e9 / n,
            tg[0] * 1e9 / n)


def _cases(points, n):
    """(name, the binding's call, the C batch call on the same prepared rows)
    for each entry point, over the points tiled to n rows."""
    import orbillum
    lib, L = orbillum._lib, orbillum.L  # the loaded library, the header's mirror
    sun = np.array([p[1] for p in points], dtype=float)
    tgt = np.array([p[2] for p in points], dtype=float)
    S = tile_rows(sun, n)
    T = tile_rows(tgt, n)
    moon = np.tile([3.6e5, 1.2e5, 2.0e4], (n, 1))
    obs = T + np.array([120.0, -60.0, 35.0])
    theta = np.linspace(0.0, np.pi, n)
    h = np.geomspace(1e-2, 1e6, n)
    sh = np.empty(n, dtype=np.dtype(L.oi_shadow))
    il = np.empty(n, dtype=orbillum.ILLUM_DTYPE)
    ex = np.empty(n, dtype=orbillum.EXPOSURE_DTYPE)
    st = np.empty(n, dtype=np.intc)
    phi, psi = np.empty(n), np.empty(n)
    sc = orbillum._scenes(S, moon, T, obs, "all", None, None, None)
    cam = lib.oi_camera_find(b"telescope-15cm")
    lib.oi_illuminate_batch(n, sc.ctypes.data, None, il.ctypes.data, st.ctypes.data)

    def c_illuminate():
        lib.oi_illuminate_batch(n, sc.ctypes.data, None, il.ctypes.data, st.ctypes.data)

    def c_expose():
        lib.oi_illuminate_batch(n, sc.ctypes.data, None, il.ctypes.data, st.ctypes.data)
        lib.oi_expose_scene_batch_outputs(n, cam, sc.ctypes.data, il.ctypes.data, None, None,
                                          L.OI_EXPOSE_ALL, ex.ctypes.data, st.ctypes.data)

    return [
        ("sun_fraction", lambda: orbillum.sun_fraction(S, T),
         lambda: lib.oi_sun_fraction_batch(n, S.ctypes.data, T.ctypes.data, None, L.OI_BATCH_ALL,
                                           sh.ctypes.data, st.ctypes.data)),
        ("sun_fraction_mask0", lambda: orbillum.sun_fraction(S, T, outputs=0),
         lambda: lib.oi_sun_fraction_batch(n, S.ctypes.data, T.ctypes.data, None, 0,
                                           sh.ctypes.data, st.ctypes.data)),
        ("earthshine", lambda: orbillum.earthshine(theta, h),
         lambda: lib.oi_earthshine_batch(n, theta.ctypes.data, h.ctypes.data, None,
                                         phi.ctypes.data, psi.ctypes.data, st.ctypes.data)),
        ("illuminate", lambda: orbillum.illuminate(S, moon, T, obs, terms="all"), c_illuminate),
        ("expose", lambda: orbillum.expose("telescope-15cm", S, moon, T, obs, terms="all"),
         c_expose),
    ]


def run(points, out, n=100000):
    try:
        import orbillum  # noqa: F401
    except Exception as e:  # the binding is built by `make binding`
        out.put("binding.cost", "unavailable", "-", "import orbillum: %s" % e)
        return
    cases = _cases(points, n)
    for name, py, c in cases:
        t_py, t_c, b_py, b_c = _median_ns_pair(py, c, n)
        out.put("binding.%s.ns_per_row" % name, "%.1f" % t_py, "ns",
                "orbillum.%s over %d rows, whole call" % (name.replace("_mask0", ""), n))
        out.put("binding.%s.c_batch_ns_per_row" % name, "%.1f" % t_c, "ns",
                "the C batch call alone, same rows, same library")
        out.put("binding.%s.over_c_batch" % name, "%.2f" % (t_py / t_c), "x",
                "goal <= 1.3")
        out.put("binding.%s.over_c_batch_best" % name, "%.2f" % (b_py / b_c), "x",
                "least of 9 calls each: binding %.1f ns, C %.1f ns per row" % (b_py, b_c))


def _child(points_file, name, side, k, n):
    """K calls of one side of one case (run under callgrind by instructions())."""
    with open(points_file) as f:
        points = json.load(f)
    for case, py, c in _cases(points, n):
        if case == name:
            fn = py if side == "py" else c
            for _ in range(k):
                fn()
            return
    raise SystemExit("no case " + name)


def _callgrind_total(args):
    with tempfile.NamedTemporaryFile(suffix=".cg", delete=False) as f:
        path = f.name
    try:
        subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + path] + args,
                       check=True, capture_output=True)
        with open(path) as f:
            for line in f:
                if line.startswith("totals:") or line.startswith("summary:"):
                    return int(line.split()[1])
    finally:
        os.unlink(path)
    raise SystemExit("callgrind: no totals")


def instructions(points, out, n=2000, names=None):
    """Instructions per row of the binding and of the C batch, each case: the
    ratio without the machine's load."""
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(points, f)
        pf = f.name
    try:
        for case, _, _ in _cases(points, 1):
            if names and case not in names:
                continue
            per = {}
            for side in ("py", "c"):
                base = [sys.executable, os.path.abspath(__file__), "--child", pf, case, side]
                i1 = _callgrind_total(base + ["1", str(n)])
                i3 = _callgrind_total(base + ["3", str(n)])
                per[side] = (i3 - i1) / (2.0 * n)
            out.put("binding.%s.instructions_per_row" % case, "%.0f" % per["py"], "instructions",
                    "orbillum.%s, callgrind, (I(3 calls) - I(1)) / (2 x %d rows)"
                    % (case.replace("_mask0", ""), n))
            out.put("binding.%s.c_batch_instructions_per_row" % case, "%.0f" % per["c"],
                    "instructions", "the C batch call alone, same rows")
            out.put("binding.%s.over_c_batch_instructions" % case, "%.3f" % (per["py"] / per["c"]),
                    "x", "goal <= 1.3")
    finally:
        os.unlink(pf)


class _Print:
    def put(self, name, value, unit, comment=""):
        print("%s %s %s" % (name, value, unit) + (("  # " + comment) if comment else ""), flush=True)


def _bench_points(binary):
    rows = []
    for line in subprocess.run([binary, "points"], check=True, capture_output=True,
                               text=True).stdout.splitlines():
        if line.startswith("#"):
            continue
        f = line.split()
        v = [float(x) for x in f[1:]]
        rows.append((f[0], v[0:3], v[3:6], v[6]))
    return rows


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--child":
        _child(sys.argv[2], sys.argv[3], sys.argv[4], int(sys.argv[5]), int(sys.argv[6]))
        return 0
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bench", default=os.path.join(os.path.dirname(HERE), "build", "bench",
                                                    "bench-double"))
    ap.add_argument("--n", type=int, default=None)
    ap.add_argument("--callgrind", action="store_true", help="instructions, not wall time")
    ap.add_argument("cases", nargs="*", help="only these cases (default: all)")
    args = ap.parse_args()
    points = _bench_points(args.bench)
    if args.callgrind:
        instructions(points, _Print(), n=args.n or 2000, names=args.cases)
    else:
        run(points, _Print(), n=args.n or 100000)
    return 0


if __name__ == "__main__":
    sys.exit(main())
