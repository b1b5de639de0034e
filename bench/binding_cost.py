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
"""
import numpy as np

from timing import interleaved_seconds, tile_rows


def _median_ns_pair(f, g, n, reps=9):
    """Median and least ns per row of f and of g, their calls interleaved so
    that a change of the machine's load falls on both: (f median, g median,
    f least, g least). The least is the call other jobs disturbed least."""
    tf, tg = interleaved_seconds(f, g, reps)
    return (tf[reps // 2] * 1e9 / n, tg[reps // 2] * 1e9 / n, tf[0] * 1e9 / n,
            tg[0] * 1e9 / n)


def run(points, out, n=100000):
    try:
        import orbillum
    except Exception as e:  # the binding is built by `make binding`
        out.put("binding.cost", "unavailable", "-", "import orbillum: %s" % e)
        return
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
        lib.oi_expose_scene_batch(n, cam, sc.ctypes.data, il.ctypes.data, None, None,
                                  ex.ctypes.data, st.ctypes.data)

    cases = [
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
