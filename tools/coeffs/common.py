# SPDX-License-Identifier: MIT
"""Rounding to the runtime's precisions and C literals, shared by the generators.

Rounding is exact rational arithmetic (round to nearest, ties to even, as a C
compiler reads a decimal literal), so a value is rounded once whatever it
came from: an mpmath number, a decimal string, an exact rational.
"""
from fractions import Fraction

import mpmath as mp

BITS = {False: 53, True: 24}  # significand bits of double and float


def to_fraction(v):
    """The exact value of an mpf, float, int, Fraction or decimal/hex C literal text."""
    if isinstance(v, Fraction):
        return v
    if isinstance(v, (int, float)):
        return Fraction(v)
    if isinstance(v, str):
        t = v.strip().rstrip("fFlL")
        if t.lower().lstrip("+-").startswith("0x"):
            return Fraction(float.fromhex(t))
        return Fraction(t)
    m = mp.mpf(v)
    sign, man, exp, _bc = m._mpf_
    if not man:
        return Fraction(0)
    q = Fraction(int(man)) * (Fraction(2) ** int(exp))
    return -q if sign else q


def round_to(v, single):
    """v rounded once to double or float (returned as an exact Fraction)."""
    q = to_fraction(v)
    if q == 0:
        return q
    bits = BITS[single]
    a = abs(q)
    e = a.numerator.bit_length() - a.denominator.bit_length()  # 2^e <= a < 2^(e+2)
    if Fraction(2) ** e > a:
        e -= 1
    scale = Fraction(2) ** (bits - 1 - e)
    r = Fraction(round(a * scale)) / scale  # round(): ties to even, exact
    return -r if q < 0 else r


def c_literal(v, single):
    """The shortest decimal that reads back as v rounded (float: with an f)."""
    r = float(round_to(v, single))
    if single:
        import numpy as np
        return repr(float(np.float32(r))) + "f"
    return repr(r)
