#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Constants of src/sincos.c (the runtime's own sine and cosine), from mpmath.

  .venv/bin/python tools/sincos_coeffs.py      # prints the C constants

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
import mpmath as mp
import numpy as np

mp.mp.dps = 60
HALF_PI = mp.pi / 2
Z = (mp.pi / 4 * mp.mpf("1.0001")) ** 2


def parts(nbits, count, last_bits):
    """pi/2 as count parts of nbits leading bits, then one rounded to last_bits."""
    out, rest = [], HALF_PI
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


def c_float(v, single):
    if single:
        f = np.float32(float(v))
        assert mp.mpf(float(f)) == mp.mpf(float(f))
        return repr(float(f)) + "f"
    return repr(float(v))


def exact(v, single):
    """v is exactly representable in the precision"""
    f = np.float32(float(v)) if single else float(v)
    return mp.mpf(float(f)) == v


def main():
    for single, name in ((False, "double"), (True, "float")):
        print(f"/* ---- {name} */")
        if single:
            ps, _ = parts(12, 5, 24)
            short = None
            names = ["P1", "P2", "P3", "P4", "P5", "P6"]
        else:
            ps, _ = parts(33, 3, 53)
            short = None
            names = ["P1", "P2", "P3", "P4"]
        for n, p in zip(names, ps):
            assert exact(p, single), n
            print(f"#define {n} ({c_float(p, single)})")
        if short is not None:
            print(f"#define P5S ({c_float(short[4], single)}) /* P5 + P6 rounded */")
        # the short reduction: the exact parts, then the rest rounded once
        nex = 2 if single else 1
        rest = HALF_PI - sum(ps[:nex])
        f = np.float32(float(rest)) if single else float(rest)
        print(f"#define P{nex + 1}R ({c_float(f, single)}) /* pi/2 - P1{' - P2' if single else ''} rounded */")
        err = HALF_PI - sum(ps)
        print(f"/* pi/2 - sum of parts = {mp.nstr(err, 3)} */")
        ns, nc = (4, 3) if single else (6, 6)
        cs, es = mp.chebyfit(gs, [0, Z], ns, error=True)
        cc, ec = mp.chebyfit(gc, [0, Z], nc, error=True)
        # chebyfit lists the highest degree first
        cs, cc = cs[::-1], cc[::-1]
        print(f"/* sin: fit error x z: 2^{mp.nstr(mp.log(es * Z, 2), 4)} relative */")
        for i, c in enumerate(cs):
            print(f"#define S{2 * i + 3} ({c_float(c, single)})")
        print(f"/* cos: fit error x z^2 / cos(pi/4): 2^"
              f"{mp.nstr(mp.log(ec * Z * Z / mp.cos(mp.pi / 4), 2), 4)} relative */")
        for i, c in enumerate(cc):
            print(f"#define C{2 * i + 4} ({c_float(c, single)})")
        tp = 2 * mp.pi
        print(f"#define TWO_PI_R ({c_float(tp, single)})")
        print(f"#define TWO_OVER_PI ({c_float(2 / mp.pi, single)})")
    # the smallest |x - k pi/2| over the nearest doubles to k pi/2, k < 2^20, is
    # measured by tests/c/test_sincos.c (hard cases), not here.


if __name__ == "__main__":
    main()
