# SPDX-License-Identifier: MIT
"""The Sun's visible fraction behind the WGS-84 ellipsoid (and the Moon), uniform
and limb-darkened disc, in numpy double precision: a reference cheap enough for
random points in `make test` (tests/python/test_oblate_ld.py).

Independent of the library (src/shadow/oblate.c integrates chords of the gnomonic
projection, the limb-darkened law in closed form along each chord) and, for
its two integrals, of tests/ref/oblate.py:

- polar coordinates (theta, phi) about the solar disc's centre s; the ray at
  (theta, phi) meets a body exactly when the quadratic in its length has a
  real positive root (z scaled by a/b for the ellipsoid): the discriminant is
  a sinusoid in 2 theta, so each azimuth's covered theta-intervals are closed
  forms (acos);
- the flux of an interval: the limb-darkened law I(mu) = sum A_k mu^k (Neckel
  & Labs 1994, 559.95 nm) integrated in mu, where sin(theta) dtheta =
  -sin^2 r mu dmu / sqrt(cos^2 r + sin^2 r mu^2): a polynomial times a
  function within 1e-5 of a constant, so 12 Gauss-Legendre nodes are exact to
  rounding (no cancelling closed form);
- over phi: the breaks (where an interval appears, reaches the disc's centre
  or limb, or the two bodies' intervals start or stop overlapping) found on a
  grid and bisected to rounding; on each piece phi = a + (b - a)(1 - cos pi u)/2
  (turning the square-root onsets at the breaks into smooth functions of u)
  and Gauss-Legendre in u, pieces halved until 64 and 128 nodes agree to
  1e-13 of the disc.
"""
import numpy as np

AU_KM = 149597870.7
R_SUN_KM = 695700.0
A_KM = 6378.137
INV_F = 298.257223563
R_MOON_KM = 1737.4
LD_A = np.array([0.26892, 1.34319, -1.58427, 1.91271, -1.31350, 0.37295])

_MU_X, _MU_W = np.polynomial.legendre.leggauss(12)


def _frame(s, toward):
    e1 = toward - np.dot(toward, s) * s
    if np.linalg.norm(e1) < 1e-12:
        e1 = np.cross(s, [1.0, 0.0, 0.0] if s[0] ** 2 < 0.5 else [0.0, 1.0, 0.0])
    e1 = e1 / np.linalg.norm(e1)
    return e1, np.cross(s, e1)


class _Body:
    """P (the point relative to the body's centre) and directions scaled by k on z."""

    def __init__(self, rel, radius, k):
        self.P = np.array([rel[0], rel[1], rel[2] * k])
        self.k = k
        self.c = float(self.P @ self.P) - radius * radius

    def intervals(self, s, d, r):
        """Covered theta-intervals on [0, r] of the rays u = cos t s + sin t d for each
        row of d (n, 3): lo, hi of shape (n, 5), NaN where none."""
        scale = np.array([1.0, 1.0, self.k])
        s1, d1 = s * scale, d * scale
        ps, pd = self.P @ s1, d1 @ self.P
        ss, sd, dd = s1 @ s1, d1 @ s1, np.einsum("ij,ij->i", d1, d1)
        A = ps * ps - self.c * ss
        B = ps * pd - self.c * sd
        C = pd * pd - self.c * dd
        mean, amp_c, amp_s = 0.5 * (A + C), 0.5 * (A - C), B
        R = np.hypot(amp_c, amp_s)
        with np.errstate(divide="ignore", invalid="ignore"):
            q = -mean / R
        t0 = 0.5 * np.arctan2(amp_s, amp_c)
        w = np.where(q <= -1, 0.5 * np.pi, 0.5 * np.arccos(np.clip(q, -1.0, 1.0)))
        n = np.arange(-2, 3)[None, :]
        lo = np.maximum(t0[:, None] - w[:, None] + n * np.pi, 0.0)
        hi = np.minimum(t0[:, None] + w[:, None] + n * np.pi, r)
        tm = 0.5 * (lo + hi)
        front = ps * np.cos(tm) + pd[:, None] * np.sin(tm) < 0
        ok = (lo < hi) & front & (q < 1)[:, None] & (R > 0)[:, None]
        return np.where(ok, lo, np.nan), np.where(ok, hi, np.nan)


def _ld_cumulative(theta, r):
    """Limb-darkened flux within theta of the disc's centre, per unit azimuth (I(1) = 1)."""
    sr, cr = np.sin(r), np.cos(r)
    st = np.sin(np.minimum(theta, r))
    mu0 = np.sqrt(np.maximum((sr - st) * (sr + st), 0.0)) / sr
    half = 0.5 * (1.0 - mu0)[..., None]
    mu = mu0[..., None] + half * (_MU_X + 1.0)
    f = np.polyval(LD_A[::-1], mu) * mu / np.sqrt(cr * cr + sr * sr * mu * mu)
    return sr * sr * np.sum(f * _MU_W * half, axis=-1)


class Geometry:
    def __init__(self, sun, point, moon=None):
        sun, point = np.asarray(sun, float), np.asarray(point, float)
        rel = sun - point
        self.s = rel / np.linalg.norm(rel)
        self.r = np.arcsin(R_SUN_KM / np.linalg.norm(rel))
        self.e1, self.e2 = _frame(self.s, -point)
        self.bodies = [_Body(point, A_KM, 1.0 / (1.0 - 1.0 / INV_F))]
        if moon is not None:
            self.bodies.append(_Body(point - np.asarray(moon, float), R_MOON_KM, 1.0))

    def _sets(self, phi):
        d = np.cos(phi)[:, None] * self.e1 + np.sin(phi)[:, None] * self.e2
        los, his = zip(*(b.intervals(self.s, d, self.r) for b in self.bodies))
        return np.concatenate(los, axis=1), np.concatenate(his, axis=1)

    def signature(self, phi):
        """An integer per azimuth that changes where the covered set changes form."""
        lo, hi = self._sets(phi)
        sig = np.zeros(phi.shape, dtype=np.int64)
        for j in range(lo.shape[1]):
            code = np.where(np.isnan(lo[:, j]), 0,
                            1 + (lo[:, j] == 0) + 2 * (hi[:, j] == self.r))
            sig = sig * 5 + code
        if len(self.bodies) == 2:
            # each body's covered span (empty: +inf .. -inf, overlapping nothing)
            a_lo, b_lo = (np.min(np.where(np.isnan(x), np.inf, x), axis=1)
                          for x in (lo[:, :5], lo[:, 5:]))
            a_hi, b_hi = (np.max(np.where(np.isnan(x), -np.inf, x), axis=1)
                          for x in (hi[:, :5], hi[:, 5:]))
            sig = sig * 2 + ((a_lo <= b_hi) & (b_lo <= a_hi)).astype(np.int64)
        return sig

    def hidden(self, phi):
        """Hidden solid angle and limb-darkened flux per unit azimuth at each phi."""
        lo, hi = self._sets(phi)
        order = np.argsort(np.where(np.isnan(lo), np.inf, lo), axis=1)
        lo = np.take_along_axis(lo, order, axis=1)
        hi = np.take_along_axis(hi, order, axis=1)
        cur_lo = np.full(phi.shape, np.nan)
        cur_hi = np.full(phi.shape, np.nan)
        uni = np.zeros(phi.shape)
        ld = np.zeros(phi.shape)

        def close(mask):
            a, b = cur_lo[mask], cur_hi[mask]
            uni[mask] += np.cos(a) - np.cos(b)
            ld[mask] += _ld_cumulative(b, self.r) - _ld_cumulative(a, self.r)

        for j in range(lo.shape[1]):
            l, h = lo[:, j], hi[:, j]
            valid = ~np.isnan(l)
            start = valid & np.isnan(cur_lo)
            new = valid & ~np.isnan(cur_lo) & (l > cur_hi)
            close(new)
            cur_lo = np.where(start | new, l, cur_lo)
            cur_hi = np.where(start | new, h, np.where(valid, np.fmax(cur_hi, h), cur_hi))
        close(~np.isnan(cur_lo))
        return uni, ld

    def breaks(self, ngrid=8192):
        grid = np.linspace(0.0, 2.0 * np.pi, ngrid + 1)
        sig = self.signature(grid)
        i = np.nonzero(sig[:-1] != sig[1:])[0]
        a, b, sa = grid[i], grid[i + 1], sig[i]
        for _ in range(60):
            m = 0.5 * (a + b)
            left = self.signature(m) == sa
            a, b = np.where(left, m, a), np.where(left, b, m)
        return np.concatenate([[0.0], 0.5 * (a + b), [2.0 * np.pi]])

    def fractions(self, tol=1e-13):
        """(uniform, limb-darkened) visible fractions and the largest piece's
        estimated error."""
        disc_u = 2.0 * np.pi * (1.0 - np.cos(self.r))
        disc_l = 2.0 * np.pi * _ld_cumulative(self.r, self.r)
        pieces = list(zip(self.breaks()[:-1], self.breaks()[1:]))
        tot_u = tot_l = worst = 0.0
        while pieces:
            a = np.array([p[0] for p in pieces])[:, None]
            b = np.array([p[1] for p in pieces])[:, None]
            est = []
            for n in (64, 128):
                x, w = np.polynomial.legendre.leggauss(n)
                u = 0.5 * (x + 1.0)
                phi = a + (b - a) * 0.5 * (1.0 - np.cos(np.pi * u))
                jac = (b - a) * 0.25 * np.pi * np.sin(np.pi * u) * w
                hu, hl = self.hidden(phi.ravel())
                est.append((np.sum(hu.reshape(phi.shape) * jac, axis=1) / disc_u,
                            np.sum(hl.reshape(phi.shape) * jac, axis=1) / disc_l))
            err = np.maximum(abs(est[1][0] - est[0][0]), abs(est[1][1] - est[0][1]))
            done = (err <= tol) | ((b - a)[:, 0] < 1e-9)
            tot_u += float(np.sum(est[1][0][done]))
            tot_l += float(np.sum(est[1][1][done]))
            worst = max(worst, float(np.max(err[done], initial=0.0)))
            nxt = []
            for (lo, hi), dn in zip(pieces, done):
                if not dn:
                    mid = 0.5 * (lo + hi)
                    nxt += [(lo, mid), (mid, hi)]
            pieces = nxt
        return 1.0 - tot_u, 1.0 - tot_l, worst


def fractions(sun, point, moon=None):
    """(fraction, fraction_ld, error estimate) of the Sun seen from point."""
    return Geometry(sun, point, moon).fractions()
