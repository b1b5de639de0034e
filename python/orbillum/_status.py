# SPDX-License-Identifier: MIT
"""Status codes and flag bits by name (oi_status_name, oi_flag_name), and a
batch call's own error as a ValueError."""
import numpy as np

from ._arrays import UINT_RANGE, _integer
from ._runtime import _lib


def status_name(status):
    """Name of a status code ("OK", "ERR_NONFINITE", ...), as oi_status_name;
    "UNKNOWN" for any other integer, those beyond the C int's range too (never
    the name of the value modulo 2^32). TypeError for a value that is no
    integer.

    Example:

    >>> import orbillum
    >>> orbillum.status_name(orbillum.OI_OK), orbillum.status_name(orbillum.OI_ERR_NONFINITE)
    ('OK', 'ERR_NONFINITE')
    >>> orbillum.status_name(2**70), orbillum.status_name(-99)
    ('UNKNOWN', 'UNKNOWN')
    """
    try:
        s = _integer(status, "status")
    except ValueError as e:
        if "outside the C type's range" not in str(e):
            raise
        return "UNKNOWN"  # oi_status_name's name for any other value
    return _lib.oi_status_name(s).decode()


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

    A mask must fit the C unsigned (OI_FLAG_* bits: 0 to 2^32 - 1):

    >>> orbillum.flag_names(-1)
    Traceback (most recent call last):
    ...
    ValueError: flags: -1 is outside the C type's range [0, 4294967295]
    """
    out = []
    bit = 1
    f = _integer(flags, "flags", UINT_RANGE)
    while bit <= f:
        if f & bit:
            n = _lib.oi_flag_name(bit)
            out.append(n.decode() if n else f"bit{bit.bit_length() - 1}")
        bit <<= 1
    return "+".join(out)


def _batch_status(st, n, what, explain=None):
    """A batch call's own error (the model, the camera: every row has it) as a
    ValueError; row errors stay in the status array. explain(st): the first
    field out of its documented range, as text, or None (the library's status
    is the authority: this only names the field)."""
    if st < 0 and n > 0:
        why = explain(st) if explain is not None else None
        if why is None:
            why = ("no field outside the ranges include/orbillum/*.h document: an option "
                   "this build leaves out (include/oi_config.h)?")
        raise ValueError(f"{what}: {status_name(st)}: {why}")


_NAN_ROWS = {}


def _nan_row(dtype):
    """One record of dtype with every floating-point field NaN (nested and
    array fields too) and every integer field 0: a failed row's values."""
    row = _NAN_ROWS.get(dtype)
    if row is None:
        row = np.zeros(1, dtype=dtype)

        def fill(rec, dt):
            for name in dt.names:
                sub = dt.fields[name][0]
                if sub.names:
                    fill(rec[name], sub)
                elif sub.base.kind == "f":
                    rec[name] = np.nan
        fill(row, dtype)
        _NAN_ROWS[dtype] = row
    return row


def _nan_failed(rec, status):
    """The float fields of the rows whose status is an error set to NaN (the
    C library gives 0 there, which reads as a valid value: a bright
    magnitude, an umbra, full phase); integer fields stay 0."""
    failed = status < 0
    if failed.any():  # one masked pass, spared on the common all-valid batch
        rec[failed] = _nan_row(rec.dtype)
    return failed
