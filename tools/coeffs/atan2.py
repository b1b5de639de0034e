#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Constants of src/atan2.c (the runtime's own two-argument arctangent), from mpmath.

  .venv/bin/python -m tools.coeffs.atan2       # prints the C constants

1. atan_hi[k], atan_lo[k], k = 0..16: atan(k/16) in two parts, hi = the value
   rounded to the working precision, lo = (atan(k/16) - hi) rounded, so that
   hi + lo holds atan(k/16) to about twice the precision (the table of the
   addition formula atan t = atan(k/16) + atan(u); Abramowitz & Stegun 1964,
   4.4.34).
2. PIO2_HI, PIO2_LO: pi/2 in the same two parts (the octant step).
The polynomial of atan u - u has no literal to generate: src/atan2.c writes
its coefficients as the exact divisions 1/3, 1/5, ... of the series
(Abramowitz & Stegun 4.4.42), which the compiler rounds once. The powers of
two (HUGE_SIDE, SIDE_SCALE) are exact hexadecimal literals chosen, not fitted.
"""
import os
import sys

import mpmath as mp

if __package__ in (None, ""):  # run as a script: make tools.coeffs importable
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
from tools.coeffs.common import c_literal, round_to  # noqa: E402

DPS = 40


def two_parts(v, single):
    hi = round_to(v, single)
    return hi, round_to(v - hi, single)


def constants(single):
    """{C name: value or list of values}, each rounded as the C literal stores it."""
    with mp.workdps(DPS):
        hi, lo = zip(*(two_parts(mp.atan(mp.mpf(k) / 16), single) for k in range(17)))
        pio2_hi, pio2_lo = two_parts(mp.pi / 2, single)
        return {"atan_hi": list(hi), "atan_lo": list(lo),
                "PIO2_HI": pio2_hi, "PIO2_LO": pio2_lo}


def main():
    for single, name in ((True, "float"), (False, "double")):
        print(f"/* ---- {name} */")
        c = constants(single)
        for arr in ("atan_hi", "atan_lo"):
            print(f"static const oi_real {arr}[17] = {{")
            print("    " + ", ".join(c_literal(v, single) for v in c[arr]) + "};")
        for n in ("PIO2_HI", "PIO2_LO"):
            print(f"#define {n} ({c_literal(c[n], single)})")


if __name__ == "__main__":
    main()
