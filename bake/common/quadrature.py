# SPDX-License-Identifier: MIT
"""Gauss-Legendre nodes and weights, correctly rounded to double.

numpy's leggauss takes the nodes from a LAPACK eigenvalue solver (last bits
depend on the BLAS build and the CPU) and its weights are off by up to ~1e-12
relative at order 48; these are Newton-polished roots of P_n in mpmath at 200
bits, rounded once: the same doubles on every machine. Cached per order.
"""

import mpmath
import numpy as np

_CACHE = {}


def _legendre(n, x):
    """P_n(x) and P_{n-1}(x) by the three-term recurrence (mpmath)."""
    p0, p1 = mpmath.mpf(1), x
    for j in range(2, n + 1):
        p0, p1 = p1, ((2 * j - 1) * x * p1 - (j - 1) * p0) / j
    return p1, p0


def gauss_legendre(n):
    """(x, w) on [-1, 1], ascending x, as float64 arrays (do not modify)."""
    n = int(n)
    if n < 1:
        raise ValueError("order must be >= 1")
    if n not in _CACHE:
        xs, ws = [], []
        with mpmath.workprec(200):
            eps = mpmath.mpf(2) ** -190
            for k in range(1, n + 1):
                x = mpmath.cos(mpmath.pi * (k - mpmath.mpf(1) / 4) / (n + mpmath.mpf(1) / 2))
                for _ in range(100):
                    p, q = _legendre(n, x)
                    dp = n * (x * p - q) / (x * x - 1)
                    dx = p / dp
                    x -= dx
                    if abs(dx) < eps:
                        break
                p, q = _legendre(n, x)
                dp = n * (x * p - q) / (x * x - 1)
                xs.append(x)
                ws.append(2 / ((1 - x * x) * dp * dp))
        order = sorted(range(n), key=lambda i: xs[i])
        x = np.array([float(xs[i]) for i in order])
        w = np.array([float(ws[i]) for i in order])
        x.flags.writeable = False
        w.flags.writeable = False
        _CACHE[n] = (x, w)
    return _CACHE[n]


def gauss_legendre_01(n):
    """(x, w) on [0, 1]."""
    x, w = gauss_legendre(n)
    return 0.5 * (x + 1.0), 0.5 * w
