# SPDX-License-Identifier: MIT
"""Input conversion: numbers to float64 arrays, positions to (N, 3) rows,
per-row scalars, quaternions; the row count the inputs broadcast to; an
elementwise call of a scalar C function."""
import numpy as np


def _floats(a, name):
    """a as a float64 array; TypeError naming the argument when it is not numbers."""
    try:
        return np.asarray(a, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{name}: expected numbers, got {a!r:.60} ({e})") from None


def _vec(a, name, n=None):
    a = _floats(a, name)
    if a.shape == (3,):
        a = a[None, :]
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError(f"{name}: expected shape (N, 3) or (3,), got {a.shape}")
    return a


def _n_rows(*arrays):
    n = 1
    for a in arrays:
        if a is not None and a.shape[0] != 1:
            if n != 1 and a.shape[0] != n:
                raise ValueError(f"row counts differ: {n} and {a.shape[0]}")
            n = a.shape[0]
    return n


def _scalar_rows(v, n, name):
    a = _floats(v, name)
    if a.ndim == 0:
        return np.full(n, float(a))
    if a.shape != (n,):
        raise ValueError(f"{name}: expected a scalar or shape ({n},), got {a.shape}")
    return a


def _attitudes(q):
    """attitude_q: None, (4,) or (N, 4) quaternions (w, x, y, z)."""
    if q is None:
        return None
    a = _floats(q, "attitude_q")
    if a.shape == (4,):
        a = a[None, :]
    if a.ndim != 2 or a.shape[1] != 4:
        raise ValueError(f"attitude_q: expected shape (N, 4) or (4,) (w, x, y, z), got {a.shape}")
    return a


def _elementwise(fn, x):
    x = np.asarray(x, dtype=np.float64)
    return np.vectorize(lambda v: fn(float(v)), otypes=[np.float64])(x)
