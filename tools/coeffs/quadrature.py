#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Gauss-Legendre rules of src/ (OI_GL8_*, ld_node), from mpmath.

  .venv/bin/python -m tools.coeffs.quadrature  # prints the C tables

An n-point rule on [0, 1]: the nodes are x = (1 - t)/2 for the roots t of
the Legendre polynomial P_n (Newton's iteration from Tricomi's estimate
cos(pi (i - 1/4) / (n + 1/2)), at 40 digits), the weights
w = 1 / ((1 - t^2) P_n'(t)^2) (half those of [-1, 1]); by symmetry only the
nodes x < 1/2 are stored, 1 - x sharing the weight (Abramowitz & Stegun
1964, 25.4.29). OI_GL8_X1..X4, OI_GL8_W1..W4 (src/math/math_internal.h): n = 8,
the nodes and their weights. ld_node: n = 12 (double) or
6 (float), rows (x, w, sin(pi x/2), cos(pi x/2)) for the panel [0, pi/2] of
the limb-darkened disc.
"""
import os
import sys

import mpmath as mp

if __package__ in (None, ""):  # run as a script: make tools.coeffs importable
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))

DPS = 40
GL_POINTS = 8
LD_POINTS = {False: 12, True: 6}


def gauss_legendre_01(n):
    """[(x, w)] of the n-point rule on [0, 1], x < 1/2 ascending (exact to ~DPS digits)."""
    with mp.workdps(DPS + 10):
        rows = []
        for i in range(1, n // 2 + 1):
            t = mp.cos(mp.pi * (i - mp.mpf(1) / 4) / (n + mp.mpf(1) / 2))
            for _ in range(100):
                p, q = mp.legendre(n, t), mp.legendre(n - 1, t)
                dp = n * (t * p - q) / (t * t - 1)
                dt = p / dp
                t -= dt
                if abs(dt) < mp.mpf(10) ** -(DPS + 5):
                    break
            dp = n * (t * mp.legendre(n, t) - mp.legendre(n - 1, t)) / (t * t - 1)
            w = 2 / ((1 - t * t) * dp * dp)
            rows.append(((1 - t) / 2, w / 2))
        return sorted(rows)


def constants(single):
    """{C name: value or rows of values} at DPS digits; the C literal must hold
    each value rounded to the precision (src/ writes 21 digits). The 8-point
    rule's names lack the OI_ of their macros (the test finds OI_name too)."""
    with mp.workdps(DPS):
        out = {}
        for i, (x, w) in enumerate(gauss_legendre_01(GL_POINTS), 1):
            out["GL8_X%d" % i] = x
            out["GL8_W%d" % i] = w
        out["ld_node"] = [[x, w, mp.sin(mp.pi * x / 2), mp.cos(mp.pi * x / 2)]
                          for x, w in gauss_legendre_01(LD_POINTS[single])]
        return out


def main():
    for single, name in ((False, "double"), (True, "float")):
        print(f"/* ---- {name} */")
        for arr, rows in constants(single).items():
            if not isinstance(rows, list):
                print(f"#define OI_{arr} OI_R({mp.nstr(rows, 21)})")
                continue
            print(f"static const oi_real {arr}[{len(rows)}][{len(rows[0])}] = {{")
            for r in rows:
                print("    {" + ", ".join(f"OI_R({mp.nstr(v, 21)})" for v in r) + "},")
            print("};")


if __name__ == "__main__":
    main()
