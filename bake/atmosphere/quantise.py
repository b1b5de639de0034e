# SPDX-License-Identifier: MIT
"""The atmosphere table's 16-bit codes: value = min + scale * code.

q = log10(F + f_floor) on the fixed range [Q_MIN, Q_MAX]; psi on the range of
the data rounded outwards to 1e-3 rad. The ranges and scales are plain IEEE
arithmetic on exact decimal inputs (and Q_MIN a correctly rounded log10), so
they do not depend on any library's last bits.
"""

import mpmath
import numpy as np

from .window import F_FLOOR, _G

U16 = 65535
with mpmath.workprec(200):
    Q_MIN = float(mpmath.log10(mpmath.mpf(F_FLOOR)))   # -8.0 for f_floor = 1e-8
Q_MAX = float(_G["q_max"])


def quantise(q, psi):
    """16-bit codes of q and psi and the values they decode to.
    Returns (uq, up, q_dec, psi_dec, scales)."""
    pmin = np.floor(psi.min() * 1e3) / 1e3
    pmax = np.ceil(psi.max() * 1e3) / 1e3
    if pmax <= pmin:
        pmax = pmin + 1e-3
    qs = (Q_MAX - Q_MIN) / U16
    ps = (pmax - pmin) / U16
    uq = np.clip(np.rint((np.clip(q, Q_MIN, Q_MAX) - Q_MIN) / qs), 0, U16).astype(np.uint16)
    up = np.clip(np.rint((psi - pmin) / ps), 0, U16).astype(np.uint16)
    return uq, up, Q_MIN + qs * uq, pmin + ps * up, {"Q_MIN": Q_MIN, "Q_SCALE": qs,
                                                      "PSI_MIN": float(pmin), "PSI_SCALE": float(ps)}
