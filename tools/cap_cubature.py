# SPDX-License-Identifier: MIT
"""cap_cubature.py: what the earthshine cubature studies share
(tools/sphere_cubature_orders.py, tools/facet_cubature_orders.py,
tools/facet_specular_orders.py): the Earth's radius, the runtime's mapped
Gauss-Legendre rule in the polar angle, its break points over the visible
cap (a rendering of src/math/cap_breaks.c), and the error in units of the goal."""
import math

import numpy as np

R = 6378.137


def mapped_rule(n):
    """Gauss-Legendre of order n on [0, 1] mapped by t -> (1 - cos(pi t)) / 2
    (nodes crowd both ends of a piece): (nodes, weights)."""
    x, w = np.polynomial.legendre.leggauss(n)
    t = (x + 1) / 2
    return (1 - np.cos(np.pi * t)) / 2, np.pi * np.sin(np.pi * t) / 2 * w / 2


def cap_breaks(theta, hp, rp, extra=()):
    """The polar angles about the sub-observer point where the cubature's
    pieces start and stop, sorted: 0, the cap's edge amax, the terminator's
    |pi/2 - theta|, the angles `extra` (a facet's horizon), and the rings at
    the distances 2 hp, 8 hp, ... (the kernel's 1/d^2 steepness), those in
    [0, amax]. hp, rp: altitude and the Earth's radius over the distance."""
    amax = math.atan2(math.sqrt(hp * (1 + rp)), rp)
    bps = {0.0, amax, abs(math.pi / 2 - theta)}
    bps |= set(extra)
    d = 2 * hp
    for _ in range(6):
        if not d * d < 0.5 * hp * (1 + rp):
            break
        bps.add(2 * math.asin(math.sqrt((d * d - hp * hp) / (4 * rp))))
        d *= 4
    return sorted(b for b in bps if 0 <= b <= amax)


def score(got, ref):
    """Error in goal units per entry: 1 % where ref exceeds 1 % of its
    maximum, 1e-4 of that maximum elsewhere."""
    got, ref = np.asarray(got), np.asarray(ref)
    mx = ref.max()
    big = ref > 0.01 * mx
    return np.where(big, np.abs(got - ref) / np.where(big, ref, 1.0) / 0.01,
                    np.abs(got - ref) / mx / 1e-4)
