# SPDX-License-Identifier: MIT
"""The uniform disc from the limb-darkened table: a shift of the lookup point.

The atmosphere table holds the fraction F for the limb-darkened disc. For the
uniform disc the runtime reads F at the point, finds from it the position x
across an equivalent straight-edged penumbra (w(x) = F), and reads the
table again at the point moved along rho by a sigma(F), a the solar disc's
image radius, sigma(F) = s(x) chosen so that the limb-darkened disc's
fraction at x + s equals the uniform disc's at x behind a straight edge:

    w(x + s(x)) = u(x),   u, w the visible fractions of the uniform and the
                          limb-darkened disc (Neckel & Labs 1994) behind a
                          straight edge at distance x from the disc's centre.

Taking x from the table's own F (not from the geometric fraction) follows
the penumbra where the atmosphere has moved and widened it. sigma is fitted
as sqrt(g) (1 - 2F) (c0 + c1 g + c2 g^2), g = F (1 - F), by least squares;
it is zero at F = 0, 1/2, 1, so the lit side and the umbra keep the table's
value and the geometric fraction outside the atmosphere's reach.
One set per band, for the band's disc (rays.py: NL94_559 for V, EDDINGTON
for the total band). The coefficients are written into src/atmosphere.c
(OI_ATM_SHIFT_C* and OI_ATM_TOTAL_SHIFT_C*);
tests/python/test_atm.py checks them against `coefficients()`.

    python -m bake.atmosphere.disc_shift      # prints the coefficients and the fit's error
"""
from __future__ import annotations

import numpy as np

from ..common.quadrature import gauss_legendre
from .rays import EDDINGTON, NL94_559


def _edge_fractions(x, law=NL94_559, n=96):
    """u(x), w(x): visible fraction of the unit disc on the side y < x of a
    straight edge, uniform and limb-darkened. Gauss-Legendre in the angle of
    y = -cos(t) (smooth at the disc's rim) and in mu along each chord."""
    x = np.atleast_1d(np.asarray(x, dtype=float))
    g, wg = gauss_legendre(n)
    law = np.asarray(law, dtype=float)

    def strip(y):
        # chord brightness at height y: Int I(sqrt(y^2 + s^2)) ds over the chord;
        # with s = c sin(p), the integrand is smooth (mu = c cos p)
        c = np.sqrt(np.clip(1.0 - y * y, 0.0, None))
        p = 0.25 * np.pi * (g + 1.0)
        mu = c[..., None] * np.cos(p)
        i = np.polynomial.polynomial.polyval(mu, law)
        return 2.0 * (i * c[..., None] * np.cos(p)) @ (wg * 0.25 * np.pi)

    total_w = None
    u = np.empty_like(x)
    w = np.empty_like(x)
    for k, xk in enumerate(x):
        t_hi = np.arccos(-np.clip(xk, -1.0, 1.0))
        t = 0.5 * t_hi * (g + 1.0)
        y = -np.cos(t)
        jac = np.sin(t) * 0.5 * t_hi * wg
        u[k] = np.sum(2.0 * np.sqrt(1.0 - y * y) * jac) / np.pi
        w[k] = np.sum(strip(y) * jac)
    if total_w is None:
        t = 0.5 * np.pi * (g + 1.0)
        total_w = np.sum(strip(-np.cos(t)) * np.sin(t) * 0.5 * np.pi * wg)
    return u, w / total_w


def shift(x, law=NL94_559):
    """s(x) solving w(x + s) = u(x) (bisection on the monotonic w)."""
    x = np.atleast_1d(np.asarray(x, dtype=float))
    u, _ = _edge_fractions(x, law)
    lo, hi = -np.ones_like(x), np.ones_like(x)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        _, wm = _edge_fractions(mid, law)
        below = wm < u
        lo = np.where(below, mid, lo)
        hi = np.where(below, hi, mid)
    return 0.5 * (lo + hi) - x


def _basis(f):
    f = np.clip(np.asarray(f, dtype=float), 0.0, 1.0)
    g = f * (1.0 - f)
    r = np.sqrt(g) * (1.0 - 2.0 * f)
    return np.stack([r, r * g, r * g * g], axis=-1)


def coefficients(n_grid=801, law=NL94_559):
    """(c0, c1, c2) of sigma(F), least squares, rounded to 6 significant digits."""
    x = np.linspace(-1.0, 1.0, n_grid)[1:-1]
    _, w = _edge_fractions(x, law)
    c, *_ = np.linalg.lstsq(_basis(w), shift(x, law), rcond=None)
    return tuple(float("%.6g" % v) for v in c)


def sigma(f, c):
    """The fitted shift (units of a) at the limb-darkened fraction f."""
    return _basis(f) @ np.asarray(c, dtype=float)


def fit_error(c, n_grid=801, law=NL94_559):
    """max |w(x + sigma(w(x))) - u(x)| over the straight-edged penumbra."""
    x = np.linspace(-1.0, 1.0, n_grid)
    u, w = _edge_fractions(x, law)
    _, w2 = _edge_fractions(np.clip(x + sigma(w, c), -1, 1), law)
    return float(np.max(np.abs(w2 - u)))


if __name__ == "__main__":
    for name, law in (("V band (Neckel & Labs 1994, 559.95 nm)", NL94_559),
                      ("total band (Eddington)", EDDINGTON)):
        c = coefficients(law=law)
        print("%s: c0 c1 c2 = %r %r %r" % ((name,) + c))
        print("  max |w(x + sigma) - u(x)| = %.2e" % fit_error(c, law=law))
