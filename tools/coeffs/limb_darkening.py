#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Limb-darkening table of src/shadow.c (ld_coef), exact rationals.

  .venv/bin/python -m tools.coeffs.limb_darkening   # prints the C table

The solar limb darkening I(mu)/I(1) = sum_i A_i mu^i is the fifth-degree
polynomial of Neckel & Labs (1994, Sol. Phys. 153, 91, their table of
polynomial coefficients) at their continuum wavelength 559.95 nm, the one
nearest the V band's 550 nm; A below is their row as published (five
decimals). The flux integral of the disc (docs/physics.md, limb darkening)
needs c_j A_i / (i + 2j + 2), c_j = binomial(-1/2, j) the coefficients of
the binomial series of (1 + k m^2)^(-1/2), j = 0..LD_JMAX: exact rationals,
printed to 21 digits.
"""
from fractions import Fraction

NECKEL_LABS_559_95NM = ("0.26892", "1.34319", "-1.58427", "1.91271", "-1.31350", "0.37295")
LD_JMAX = 5


def binomial_minus_half(j):
    """binomial(-1/2, j) = prod_{m < j} (-1/2 - m) / (m + 1), exactly."""
    c = Fraction(1)
    for m in range(j):
        c *= (Fraction(-1, 2) - m) / (m + 1)
    return c


def constants(single):
    """{'ld_coef': rows j of c_j A_i / (i + 2j + 2)}, exact (the same in both precisions)."""
    a = [Fraction(s) for s in NECKEL_LABS_559_95NM]
    rows = [[binomial_minus_half(j) * ai / (i + 2 * j + 2) for i, ai in enumerate(a)]
            for j in range(LD_JMAX + 1)]
    return {"ld_coef": rows}


def main():
    import mpmath as mp
    rows = constants(False)["ld_coef"]
    print(f"static const oi_real ld_coef[{len(rows)}][{len(rows[0])}] = {{")
    with mp.workdps(40):
        for r in rows:
            print("    {" + ", ".join(f"OI_R({mp.nstr(mp.mpf(v.numerator) / v.denominator, 21)})"
                                      for v in r) + "},")
    print("};")


if __name__ == "__main__":
    main()
