# SPDX-License-Identifier: MIT
"""timing.py: what the in-process Python benchmarks share (bench/peers.py,
bench/binding_cost.py): two calls timed in turn, and a scene mix tiled to a
row count."""
import time

import numpy as np


def interleaved_seconds(f, g, reps):
    """Wall times (s) of reps calls of f() and of g(), each sorted; the calls
    interleaved so that a change of the machine's load falls on both alike."""
    tf, tg = [], []
    for _ in range(reps):
        for fn, ts in ((f, tf), (g, tg)):
            t0 = time.perf_counter()
            fn()
            ts.append(time.perf_counter() - t0)
    tf.sort()
    tg.sort()
    return tf, tg


def tile_rows(a, n):
    """The rows of a (m, ...) repeated to n rows, C-contiguous."""
    a = np.asarray(a)
    k = -(-n // len(a))
    return np.ascontiguousarray(np.tile(a, (k,) + (1,) * (a.ndim - 1))[:n])
