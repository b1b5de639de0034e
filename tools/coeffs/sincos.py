#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Constants of src/math/sincos.c (the runtime's own sine and cosine), from mpmath.

  .venv/bin/python -m tools.coeffs.sincos      # prints the C constants

1. Cody-Waite parts of pi/2 (Cody & Waite 1980, ch. 8): pi/2 = P1 + P2 + ...,
   each part the leading bits of what is left, so that k * Pi is exact:
   double: three parts of 33 bits (exact products for |k| < 2^20) and a
   fourth rounded to 53 bits (pi/2 to ~152 bits);
   float: five parts of 12 bits (exact for |k| < 2^12, or for k split into a
   multiple of 2^12 and a remainder below 2^11), a sixth rounded to 24 bits,
   P2R (double) /
   P3R (float): what is left after the exact parts, rounded once (the
   short reduction when |r| is not small).
2. Polynomials on |r| <= pi/4 (a margin of 1e-4 relative): Chebyshev fits
   (mpmath.chebyfit, near-minimax; Trefethen 2013, ch. 16) of
     gs(z) = (sin(sqrt z)/sqrt z - 1)/z,  sin r = r + r^3 gs(r^2),
     gc(z) = (cos(sqrt z) - 1 + z/2)/z^2,  cos r = 1 - r^2/2 + r^4 gc(r^2),
   rounded to the working precision. The script prints the bound of each
   fit's contribution to the relative error of the result.
"""
import os
import sys

import mpmath as mp

if __package__ in (None, ""):  # run as a script: make tools.coeffs importable
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
from tools.coeffs.common import c_literal, round_to, to_fraction  # noqa: E402

DPS = 60  # working digits of every computation below (mpmath's global is left alone)


def _half_pi():
    return mp.pi / 2


def _z():
    return (mp.pi / 4 * mp.mpf("1.0001")) ** 2


def parts(nbits, count, last_bits):
    """pi/2 as count parts of nbits leading bits, then one rounded to last_bits."""
    out, rest = [], _half_pi()
    for _ in range(count):
        e = mp.floor(mp.log(rest, 2))
        scale = mp.mpf(2) ** (nbits - 1 - e)
        p = mp.floor(rest * scale) / scale
        out.append(p)
        rest -= p
    e = mp.floor(mp.log(rest, 2))
    scale = mp.mpf(2) ** (last_bits - 1 - e)
    out.append(mp.nint(rest * scale) / scale)
    return out, rest


def gs(z):
    if z == 0:
        return mp.mpf(-1) / 6
    s = mp.sqrt(z)
    return (mp.sin(s) / s - 1) / z


def gc(z):
    if z == 0:
        return mp.mpf(1) / 24
    s = mp.sqrt(z)
    return (mp.cos(s) - 1 + z / 2) / (z * z)


def _chebyfit_ascending(f, z, n):
    """Coefficients of the degree n - 1 fit on [0, z], lowest degree first, and its error."""
    try:
        return mp.chebyfit(f, [0, z], n, error=True, asc=True)
    except TypeError:  # mpmath before 1.4 lists the highest degree first, always
        c, e = mp.chebyfit(f, [0, z], n, error=True)
        return c[::-1], e


def constants(single):
    """{C name: value} in src/math/sincos.c's order, each rounded as the C literal
    stores it, and {comment name: text} of the measured bounds."""
    with mp.workdps(DPS):
        half_pi, z = _half_pi(), _z()
        out, notes = {}, {}
        if single:
            ps, _ = parts(12, 5, 24)
            names = ["P1", "P2", "P3", "P4", "P5", "P6"]
        else:
            ps, _ = parts(33, 3, 53)
            names = ["P1", "P2", "P3", "P4"]
        for n, p in zip(names, ps):
            out[n] = round_to(p, single)
            assert out[n] == to_fraction(p), n + " must be exact in the precision"
        # the short reduction: the exact parts, then the rest rounded once
        nex = 2 if single else 1
        out[f"P{nex + 1}R"] = round_to(half_pi - sum(ps[:nex]), single)
        notes["parts"] = mp.nstr(half_pi - sum(ps), 3)
        ns, nc = (4, 3) if single else (6, 6)
        cs, es = _chebyfit_ascending(gs, z, ns)
        cc, ec = _chebyfit_ascending(gc, z, nc)
        notes["sin"] = mp.nstr(mp.log(es * z, 2), 4)
        for i, c in enumerate(cs):
            out[f"S{2 * i + 3}"] = round_to(c, single)
        notes["cos"] = mp.nstr(mp.log(ec * z * z / mp.cos(mp.pi / 4), 2), 4)
        for i, c in enumerate(cc):
            out[f"C{2 * i + 4}"] = round_to(c, single)
        out["TWO_PI_R"] = round_to(2 * mp.pi, single)
        out["TWO_OVER_PI"] = round_to(2 / mp.pi, single)
        return out, notes


def main():
    for single, name in ((False, "double"), (True, "float")):
        print(f"/* ---- {name} */")
        values, notes = constants(single)
        for n, v in values.items():
            if n == "S3":
                print(f"/* sin: fit error x z: 2^{notes['sin']} relative */")
            if n == "C4":
                print(f"/* cos: fit error x z^2 / cos(pi/4): 2^{notes['cos']} relative */")
            line = f"#define {n} ({c_literal(v, single)})"
            if n in ("P2R", "P3R"):
                line += f" /* pi/2 - P1{' - P2' if single else ''} rounded */"
            print(line)
            if n in ("P2R", "P3R"):
                print(f"/* pi/2 - sum of parts = {notes['parts']} */")
    # the smallest |x - k pi/2| over the nearest doubles to k pi/2, k < 2^20, is
    # measured by tests/c/test_sincos.c (hard cases), not here.


if __name__ == "__main__":
    main()
