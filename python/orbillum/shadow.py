# SPDX-License-Identifier: MIT
"""The Sun's visible fraction at points (oi_sun_fraction_batch): the
Earth's shadow, umbra and penumbra."""
import numpy as np

from ._arrays import _n_rows, _vec
from ._models import _model, _model_explain, _mptr
from ._runtime import L, _lib
from ._status import _batch_status, _nan_failed


def sun_fraction(sun, point, *, model=None, outputs=None):
    """oi_sun_fraction per row (one oi_sun_fraction_batch call): dict of the
    oi_shadow fields and status. outputs: None (every field) or a mask of
    OI_BATCH_* bits (fraction and region always; the fields left out are 0,
    and cost nothing: OI_BATCH_FRACTION_LD, OI_BATCH_ATMOSPHERE,
    OI_BATCH_GEOMETRY).

    Example: the Sun along +x; a point on the day side, one behind the Earth
    (umbra) and one at the shadow's edge (penumbra), in one batch call:

    >>> import numpy as np, orbillum
    >>> s = orbillum.sun_fraction([1.496e8, 0, 0],
    ...                           [[7000, 0, 0], [-7000, 0, 0], [-7000, 6398, 0]])
    >>> np.round(s["fraction"], 4).tolist(), s["status"].tolist()
    ([1.0, 0.0, 0.858], [0, 0, 0])
    >>> s["region"].tolist() == [orbillum.OI_SHADOW_LIT, orbillum.OI_SHADOW_UMBRA,
    ...                          orbillum.OI_SHADOW_PENUMBRA]
    True
    >>> np.round(s["fraction_ld"], 4).tolist()   # limb-darkened Sun
    [1.0, 0.0, 0.8776]

    With outputs=0 only fraction and region are computed (the others are 0):

    >>> s = orbillum.sun_fraction([1.496e8, 0, 0], [-7000, 6398, 0], outputs=0)
    >>> np.round(s["fraction"], 4).tolist(), s["fraction_ld"].tolist()
    ([0.858], [0.0])
    """
    sun = _vec(sun, "sun")
    point = _vec(point, "point")
    n = _n_rows(sun, point)
    sun = np.ascontiguousarray(np.broadcast_to(sun, (n, 3)))
    point = np.ascontiguousarray(np.broadcast_to(point, (n, 3)))
    m = _model(model)
    mask = L.OI_BATCH_ALL if outputs is None else outputs
    if not isinstance(mask, (int, np.integer)) or isinstance(mask, bool):
        raise TypeError(f"outputs: a mask of OI_BATCH_* bits or None, got {outputs!r}")
    if int(mask) & ~L.OI_BATCH_ALL or int(mask) < 0:
        raise ValueError(f"outputs: unknown bits in {int(mask):#x} (OI_BATCH_ALL is "
                         f"{L.OI_BATCH_ALL:#x})")
    sh = np.empty(n, dtype=np.dtype(L.oi_shadow))  # the batch writes every row
    st = np.empty(n, dtype=np.intc)
    bst = _lib.oi_sun_fraction_batch(n, sun.ctypes.data, point.ctypes.data, _mptr(m), int(mask),
                                     sh.ctypes.data, st.ctypes.data)
    _batch_status(bst, n, "model", _model_explain(m))
    _nan_failed(sh, st)
    out = {k: sh[k] for k in sh.dtype.names}
    out["status"] = st
    return out
