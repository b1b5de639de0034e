# SPDX-License-Identifier: MIT
"""Input conversion: numbers to float64 arrays, positions to (N, 3) rows,
per-row scalars, quaternions; the row count the inputs broadcast to; an
elementwise call of a scalar C function."""
import numpy as np


def _floats(a, name):
    """a as a float64 array; TypeError naming the argument when it is not real
    numbers: complex values (their imaginary part would be lost), booleans and
    object arrays holding either are refused, not converted."""
    try:
        arr = np.asarray(a)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{name}: expected numbers, got {a!r:.60} ({e})") from None
    kind = arr.dtype.kind
    if kind == "c":
        raise TypeError(f"{name}: expected real numbers, got complex values ({a!r:.60}); "
                        f"pass the real part explicitly if that is meant")
    if kind == "b":
        raise TypeError(f"{name}: expected numbers, got booleans ({a!r:.60})")
    if kind == "O" and any(isinstance(x, (bool, np.bool_, complex, np.complexfloating))
                           for x in arr.ravel()):
        raise TypeError(f"{name}: expected real numbers, got booleans or complex values "
                        f"({a!r:.60})")
    try:
        return arr.astype(np.float64, copy=False)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{name}: expected numbers, got {a!r:.60} ({e})") from None


#: the C integer types' ranges, for the fields the binding passes as int / unsigned
INT_RANGE = (-2**31, 2**31 - 1)
UINT_RANGE = (0, 2**32 - 1)


def _integer(v, name, lo_hi=INT_RANGE):
    """v as a Python int in the C type's range [lo, hi]: TypeError for a value
    that is no integer (bool, a fraction, complex), ValueError naming the field
    and the range for one outside it (ctypes and numpy would wrap it modulo
    2^32)."""
    lo, hi = lo_hi
    if isinstance(v, np.ndarray) and v.ndim == 0:
        v = v[()]  # a 0-d array: its one value
    if isinstance(v, (bool, np.bool_)) or not isinstance(
            v, (int, np.integer, float, np.floating)):
        raise TypeError(f"{name}: an integer, got {v!r:.60} ({type(v).__name__})")
    if isinstance(v, (float, np.floating)):
        if not np.isfinite(v) or float(v) != int(v):
            raise ValueError(f"{name}: an integer, got {v!r}")
    i = int(v)
    if not lo <= i <= hi:
        raise ValueError(f"{name}: {i} is outside the C type's range [{lo}, {hi}]")
    return i


def _integers(a, name, lo_hi=UINT_RANGE):
    """an integer array (a scalar or one per row) within the C type's range, as int64."""
    arr = np.asarray(a)
    lo, hi = lo_hi
    if arr.dtype.kind == "O":
        return np.array([_integer(x, name, lo_hi) for x in arr.ravel()],
                        dtype=np.int64).reshape(arr.shape)
    if arr.dtype.kind not in "iu":
        raise TypeError(f"{name}: integers, got {arr.dtype} values ({a!r:.60})")
    if arr.size and (arr.min() < lo or arr.max() > hi):
        bad = arr[(arr < lo) | (arr > hi)].ravel()[0]
        raise ValueError(f"{name}: {int(bad)} is outside the C type's range [{lo}, {hi}]")
    return arr.astype(np.int64)


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


def _elementwise(fn, x, name="x"):
    x = _floats(x, name)
    return np.vectorize(lambda v: fn(float(v)), otypes=[np.float64])(x)
