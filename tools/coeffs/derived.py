#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Derived constants src/ holds as literals (src/sources/phase.c, src/shadow.c,
src/scene/illuminate.c), from mpmath and include/oi_constants.h.

  .venv/bin/python -m tools.coeffs.derived     # prints the C constants

  PI_HI, PI_LO          pi in two parts: PI_HI = pi rounded to the precision,
                        PI_LO = pi - PI_HI rounded, so that (PI_HI - x) + PI_LO
                        is pi - x to one rounding near x = pi;
  TWO_THIRDS_OVER_PI    2 / (3 pi), the Lambert phase function's factor
                        (docs/physics.md section 3);
  MOON_FULL_OVER_SUN    10^(-0.4 (OI_MOON_MAG_V_FULL - OI_SUN_MAG_V)), the full
                        Moon's irradiance over the Sun's (docs/physics.md
                        section 8), from the two magnitudes of the header.
"""
import os
import re
import sys

import mpmath as mp

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
if __package__ in (None, ""):  # run as a script: make tools.coeffs importable
    sys.path.insert(0, ROOT)
from tools.coeffs.common import c_literal, round_to  # noqa: E402

DPS = 40


def header_value(name):
    """The decimal text of a parenthesised numeric #define of include/oi_constants.h."""
    with open(os.path.join(ROOT, "include", "oi_constants.h")) as f:
        m = re.search(r"#define\s+" + name + r"\s+\(\s*([-+0-9.eE]+)\s*\)", f.read())
    assert m, f"{name} not found in include/oi_constants.h"
    return m.group(1)


def constants(single):
    """{C name: value}; the C literal must hold each value rounded to its type."""
    with mp.workdps(DPS):
        pi_hi = round_to(mp.pi, single)
        pi_lo = mp.pi - mp.mpf(pi_hi.numerator) / pi_hi.denominator
        dm = mp.mpf(header_value("OI_MOON_MAG_V_FULL")) - mp.mpf(header_value("OI_SUN_MAG_V"))
        return {"PI_HI": pi_hi, "PI_LO": round_to(pi_lo, single),
                "TWO_THIRDS_OVER_PI": 2 / (3 * mp.pi),
                "MOON_FULL_OVER_SUN": mp.power(10, -mp.mpf("0.4") * dm)}


def main():
    for single, name in ((False, "double"), (True, "float")):
        print(f"/* ---- {name} */")
        for n, v in constants(single).items():
            print(f"#define {n} ({c_literal(v, single)})")


if __name__ == "__main__":
    main()
