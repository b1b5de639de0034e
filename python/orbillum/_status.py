# SPDX-License-Identifier: MIT
"""Status codes and flag bits by name (oi_status_name, oi_flag_name), and a
batch call's own error as a ValueError."""
import numpy as np

from ._runtime import _lib


def status_name(status):
    """Name of a status code ("OK", "ERR_NONFINITE", ...), as oi_status_name.

    Example:

    >>> import orbillum
    >>> orbillum.status_name(orbillum.OI_OK), orbillum.status_name(orbillum.OI_ERR_NONFINITE)
    ('OK', 'ERR_NONFINITE')
    """
    return _lib.oi_status_name(int(status)).decode()


def _names_of(values, name_fn):
    """name_fn of every element of an integer array, one call per distinct
    value: a table over the values' small range (statuses, flag masks),
    np.unique beyond it."""
    v = np.asarray(values).astype(np.int64, copy=False)
    if v.size == 0:
        return np.empty(v.shape, dtype=object)
    lo, hi = int(v.min()), int(v.max())
    if hi - lo > 4096:
        codes, inverse = np.unique(v, return_inverse=True)
        return np.array([name_fn(c) for c in codes], dtype=object)[inverse].reshape(v.shape)
    present = np.bincount((v - lo).ravel(), minlength=hi - lo + 1) > 0
    table = np.empty(hi - lo + 1, dtype=object)
    for i in np.flatnonzero(present):
        table[i] = name_fn(lo + int(i))
    return table[v - lo]


def _status_names(status):
    """oi_status_name of every element."""
    return _names_of(status, status_name)


def flag_names(flags):
    """Names of the OI_FLAG_* bits set in ``flags``, '+'-joined ('' for none).

    Example:

    >>> import orbillum
    >>> orbillum.flag_names(orbillum.OI_FLAG_ECLIPSED | orbillum.OI_FLAG_OCCULTED)
    'eclipsed+occulted'
    >>> orbillum.flag_names(0)
    ''
    """
    out = []
    bit = 1
    f = int(flags)
    while bit <= f:
        if f & bit:
            n = _lib.oi_flag_name(bit)
            out.append(n.decode() if n else f"bit{bit.bit_length() - 1}")
        bit <<= 1
    return "+".join(out)


def _batch_status(st, n, what):
    """A batch call's own error (the model, the camera: every row has it) as a
    ValueError; row errors stay in the status array."""
    if st < 0 and n > 0:
        raise ValueError(f"{what}: {status_name(st)} (a field out of its range: see "
                         f"include/orbillum.h)")
