# SPDX-License-Identifier: MIT
"""High-precision references for the WGS-84 ellipsoid as the Earth's occulter.

    python tests/ref/generate.py oblate    # writes tests/c/ref_oblate.h (~1 min)

Every reference is computed with mpmath at 30 significant digits from the EXACT
binary value of each input (the double, or the float32 for the single-precision
table). The algorithm is independent of the library's (which integrates chords
of the gnomonic projection about the back disc's centre, the silhouette being a
quadratic cone there):

- Polar coordinates about the back disc's centre s: the direction at angle
  theta from s and azimuth phi, u = cos(theta) s + sin(theta) d(phi). The ray
  from the point along u meets the ellipsoid exactly when the quadratic in the
  ray's length, with z scaled by a/b, has a positive root: its discriminant is a
  sinusoid in 2 theta, whose zeros are closed forms (acos), and the root is
  positive when the scaled point and direction have a negative dot product. The
  Moon's sphere the same way. So the covered part of each ray is known exactly,
  and its solid angle is the integral of sin(theta) over it (cosines).
- The limb-darkened disc (Neckel & Labs 1994 at 559.95 nm, I(mu)/I(1) =
  sum A_k mu^k, mu = sqrt(1 - sin^2 theta / sin^2 r)): the covered part's flux
  is F(theta_hi) - F(theta_lo), F(theta) the integral of I sin(theta) from the
  centre, in closed form in q = cos(theta): mu = sqrt(q^2 - cos^2 r) / sin r,
  and the integrals J_n of (q^2 - cos^2 r)^(n/2) dq by the reduction
  (n + 1) J_n = q (q^2 - cos^2 r)^(n/2) - n cos^2 r J_(n-2), J_0 = q,
  J_(-1) = log(q + sqrt(q^2 - cos^2 r)). (The runtime integrates the same law
  along gnomonic chords, where it is a polynomial in the cosine of another
  angle: a different closed form.)
- The outer integral over phi by tanh-sinh (mpmath.quad), split where the
  covered parts start, stop, reach the disc's limb or its centre, or where
  the Earth's and the Moon's parts start or stop overlapping (found on a grid
  of 2880 azimuths and refined by bisection to 1e-25). No row puts the back
  disc's centre on an occulter's outline: there the covered part of the rays
  next to the outline's tangent through the centre changes faster than
  tanh-sinh resolves (3.7e-9 off on the sphere against the exact caps, where
  the runtime's chords agree with the caps to 3e-13).

The output depends only on this script (no timestamps, no randomness).
"""
import numpy as np

from common import (c_vec, cdec, cli, cross, dot, norm, precision_blocks, rnd, setup_mpmath,
                    unit, write_exact_header)

mp = setup_mpmath(30)
PI = mp.pi

OUT = "tests/c/ref_oblate.h"
NGRID = 2880

AU_KM = 149597870.7
R_SUN_KM = 695700.0
A_KM = 6378.137
INV_F = mp.mpf("298.257223563")
R_MOON_KM = 1737.4


def frame(s, toward):
    d = dot(toward, s)
    e1 = [toward[i] - d * s[i] for i in range(3)]
    if norm(e1) < mp.mpf("1e-20"):
        e1 = cross(s, [1, 0, 0] if s[0] ** 2 < 0.5 else [0, 1, 0])
    e1 = unit(e1)
    return e1, cross(s, e1)


class Occulter:
    """A body seen from the point: the ray point + lam u meets it when
    (P'.u')^2 - (|P'|^2 - R^2)|u'|^2 >= 0 and P'.u' < 0, primes scaled by k on z
    (k = a/b for the ellipsoid, 1 for a sphere); P the point relative to the
    body's centre."""

    def __init__(self, rel, radius, k):
        self.P = [rel[0], rel[1], rel[2] * k]
        self.k = k
        self.c = dot(self.P, self.P) - radius * radius
        assert self.c > 0

    def ray_set(self, s, d, rmax):
        """theta in [0, rmax] covered along u = cos t s + sin t d: list of (lo, hi)."""
        k = self.k
        s1 = [s[0], s[1], s[2] * k]
        d1 = [d[0], d[1], d[2] * k]
        ps, pd = dot(self.P, s1), dot(self.P, d1)
        ss, sd, dd = dot(s1, s1), dot(s1, d1), dot(d1, d1)
        # g(t) = (ps cos + pd sin)^2 - c (ss cos^2 + 2 sd cos sin + dd sin^2)
        A = ps * ps - self.c * ss
        B = ps * pd - self.c * sd
        C = pd * pd - self.c * dd
        mean, amp_c, amp_s = (A + C) / 2, (A - C) / 2, B
        R = mp.sqrt(amp_c ** 2 + amp_s ** 2)
        if R == 0:
            return []
        q = -mean / R
        if q >= 1:
            return []
        t0 = mp.atan2(amp_s, amp_c) / 2  # maximum of g
        w = PI / 2 if q <= -1 else mp.acos(q) / 2
        out = []
        for n in range(-2, 3):
            lo, hi = t0 - w + n * PI, t0 + w + n * PI
            lo, hi = max(lo, mp.mpf(0)), min(hi, rmax)
            if lo < hi:
                tm = (lo + hi) / 2
                if ps * mp.cos(tm) + pd * mp.sin(tm) < 0:
                    out.append((lo, hi))
        return out


LD_A = [mp.mpf(x) for x in ("0.26892", "1.34319", "-1.58427", "1.91271", "-1.31350", "0.37295")]


def uniform_weight(lo, hi):
    """Solid angle of the polar interval [lo, hi] (per unit azimuth)."""
    return 2 * mp.sin((lo + hi) / 2) * mp.sin((hi - lo) / 2)


def ld_flux(theta, r):
    """F(theta): the limb-darkened flux within theta of the centre of the disc
    of radius r, per unit azimuth (I(1) = 1). The reduction's terms are O(1)
    while J_5 is O(sin^6 r): 60 digits keep 30 (checked against quadrature)."""
    with mp.workdps(60):
        return +ld_flux_sum(theta, r)


def ld_flux_sum(theta, r):
    c, sr = mp.cos(r), mp.sin(r)
    out = mp.mpf(0)
    for q, sign in ((mp.mpf(1), 1), (mp.cos(theta), -1)):
        st = mp.sin(theta) if sign < 0 else mp.mpf(0)
        d = (sr - st) * (sr + st)  # q^2 - cos^2 r without cancellation
        d = max(d, mp.mpf(0))
        j = {-1: mp.log(q + mp.sqrt(d)) if q + mp.sqrt(d) > 0 else mp.mpf(0), 0: q}
        for n in range(1, 6):
            j[n] = (q * d ** (mp.mpf(n) / 2) - n * c * c * j[n - 2]) / (n + 1)
        out += sign * sum(LD_A[n] * j[n] / sr ** n for n in range(6))
    return out


def union_area(sets, weight=uniform_weight):
    iv = sorted(x for s in sets for x in s)
    area, cur = mp.mpf(0), None
    for lo, hi in iv:
        if cur is None or lo > cur[1]:
            if cur is not None:
                area += weight(cur[0], cur[1])
            cur = [lo, hi]
        else:
            cur[1] = max(cur[1], hi)
    if cur is not None:
        area += weight(cur[0], cur[1])
    return area


def visible_fraction(s, r, occulters, toward, ld=False):
    """The uniform disc's visible fraction, and (ld) the limb-darkened's."""
    e1, e2 = frame(s, toward)

    def sets(phi):
        c, sn = mp.cos(phi), mp.sin(phi)
        d = [c * e1[i] + sn * e2[i] for i in range(3)]
        return [o.ray_set(s, d, r) for o in occulters]

    def signature(phi):
        sg = []
        allv = []
        for st in sets(phi):
            sg.append(tuple((lo == 0, hi == r) for lo, hi in st))
            allv += st
        allv.sort()
        ov = tuple(allv[i + 1][0] <= allv[i][1] for i in range(len(allv) - 1))
        return (tuple(sg), ov)

    def hidden(phi):
        return union_area(sets(phi))

    def hidden_ld(phi):
        return union_area(sets(phi), lambda lo, hi: ld_flux(hi, r) - ld_flux(lo, r))

    n = NGRID
    grid = [2 * PI * i / n for i in range(n + 1)]
    sig = [signature(p) for p in grid]
    breaks = [mp.mpf(0)]
    for i in range(n):
        if sig[i] != sig[i + 1]:
            lo, hi, slo = grid[i], grid[i + 1], sig[i]
            for _ in range(90):
                mid = (lo + hi) / 2
                if signature(mid) == slo:
                    lo = mid
                else:
                    hi = mid
            breaks.append((lo + hi) / 2)
    breaks.append(2 * PI)
    total = mp.quad(hidden, breaks)
    disc = 4 * PI * mp.sin(r / 2) ** 2
    if not ld:
        return 1 - total / disc
    return 1 - total / disc, 1 - mp.quad(hidden_ld, breaks) / (2 * PI * ld_flux(r, r))


def case(sun, point, moon, prec):
    """Reference for one geometry (inputs rounded to prec): the Sun's visible
    fraction behind the ellipsoid (and the Moon when given), the Moon's disc
    visible behind the ellipsoid, the silhouette's radius towards the Sun."""
    sun = [mp.mpf(rnd(x, prec)) for x in sun]
    point = [mp.mpf(rnd(x, prec)) for x in point]
    k = 1 / (1 - 1 / INV_F)
    earth = Occulter(point, A_KM, k)
    rel = [sun[i] - point[i] for i in range(3)]
    ds = norm(rel)
    s = unit(rel)
    rs = mp.asin(R_SUN_KM / ds)
    anti = [-x for x in point]
    res = {}
    res["frac"], res["frac_ld"] = visible_fraction(s, rs, [earth], anti, ld=True)
    if moon is not None:
        moon = [mp.mpf(rnd(x, prec)) for x in moon]
        relm = [moon[i] - point[i] for i in range(3)]
        dm = norm(relm)
        um = unit(relm)
        rm = mp.asin(R_MOON_KM / dm)
        mo = Occulter([-x for x in relm], R_MOON_KM, 1)
        res["frac_moon"], res["frac_moon_ld"] = visible_fraction(s, rs, [earth, mo], anti, ld=True)
        res["moon_vis"] = visible_fraction(um, rm, [earth], anti) if norm(point) < dm else 1
    return res


def edge_point(sun, alt, psi, offset):
    """A point alt km above the equatorial radius, at azimuth psi about the
    shadow axis (psi = 0 towards the projected north pole), placed across the
    shadow's edge: offset -1 .. 1 spans the sphere's penumbra (float64)."""
    s = np.array(sun, float) / np.linalg.norm(sun)
    n = np.array([0.0, 0.0, 1.0]) - s[2] * s
    if np.linalg.norm(n) < 1e-12:
        n = np.cross(s, [1.0, 0.0, 0.0])
    n /= np.linalg.norm(n)
    e = np.cross(s, n)
    r = A_KM + alt
    d = float(np.linalg.norm(sun))
    # distance behind the Earth so that |point| is about r at the sphere's edge
    rc = A_KM * (1 + r / d)
    z = np.sqrt(max(r * r - rc * rc, (0.2 * r) ** 2))
    rho = A_KM * (1 + z / d) + offset * z * R_SUN_KM / d
    return list(-z * s + rho * (np.cos(psi) * n + np.sin(psi) * e))


DEC = np.radians(23.44)


def geometries():
    """(label, sun, point, moon or None), float64 inputs."""
    out = []
    for alt, tag in ((0.001, "1 m"), (500.0, "500 km"), (20200.0, "GPS"), (35786.0, "GEO"),
                     (384400.0, "lunar distance"), (1.38e6, "umbra tip"), (1.5e6, "L2, annular"),
                     (3.0e6, "3e6 km")):
        for dec in (0.0, DEC):
            sun = [AU_KM * np.cos(dec), 0.0, AU_KM * np.sin(dec)]
            for psi in (0.0, np.radians(50.0)) if dec == 0 else (np.radians(90.0),):
                for off in ((-1.2, -0.5, 0.3, 0.9, 1.2) if alt < 1e6 else (-0.9, 0.05, 0.8)):
                    out.append(("%s, dec %.2f, psi %.0f, offset %+.1f" % (
                        tag, np.degrees(dec), np.degrees(psi), off), sun,
                        edge_point(sun, alt, psi, off), None))
    # the Moon on the Sun's disc while a GEO target is in the ellipsoid's penumbra
    sun = [AU_KM * np.cos(DEC), 0.0, AU_KM * np.sin(DEC)]
    for psi in (0.0, np.radians(90.0)):
        t = np.array(edge_point(sun, 35786.0, psi, 0.1))
        s = (np.array(sun) - t) / np.linalg.norm(np.array(sun) - t)
        toward = -t - np.dot(-t, s) * s
        toward /= np.linalg.norm(toward)
        side = np.cross(s, toward)
        for a, b in ((0.0, 0.0), (0.003, 0.0), (-0.004, 0.002), (0.002, 0.006), (0.0, 0.009)):
            u = s + a * toward + b * side
            u /= np.linalg.norm(u)
            moon = list(t + 380000.0 * u)
            out.append(("GEO penumbra + Moon at (%.3f, %.3f), psi %.0f" % (a, b, np.degrees(psi)),
                        sun, list(t), moon))
    # the Earth hiding the Moon from 7000 km: the Moon about the limb
    sun = [0.0, AU_KM, 0.0]
    t = np.array([0.0, 0.0, 7000.0])
    rho = np.arcsin(A_KM / 7000.0)
    for az in (0.0, np.radians(60.0)):
        for dd in (-0.006, -0.002, 0.0005, 0.003, 0.006):
            ang = rho + dd
            # a direction at angle ang from the nadir (0,0,-1), azimuth az
            u = np.array([np.sin(ang) * np.cos(az), np.sin(ang) * np.sin(az), -np.cos(ang)])
            moon = list(t + 384400.0 * u)
            out.append(("Moon at the limb from 7000 km, az %.0f, %+.3f rad" % (np.degrees(az), dd),
                        sun, list(t), moon))
    return out


def rows(prec):
    res = []
    g = geometries()
    if prec == "f":
        g = g[::3]  # a third of the rows: float inputs, the same references' method
    for label, sun, point, moon in g:
        r = case(sun, point, moon, prec)
        res.append((label, [rnd(x, prec) for x in sun], [rnd(x, prec) for x in point],
                    [rnd(x, prec) for x in moon] if moon is not None else [0.0, 0.0, 0.0],
                    moon is not None, r["frac"], r.get("frac_moon", r["frac"]), r.get("moon_vis", 1),
                    r["frac_ld"], r.get("frac_moon_ld", r["frac_ld"])))
    return res


def emit(root):
    def block(prec):
        rs = rows(prec)
        out = ["static const ref_oblate_row ref_oblate[%d] = {\n" % len(rs)]
        for label, s, t, m, hm, f, fm, mv, fl, fml in rs:
            out.append("    {{%s}, {%s}, {%s}, %d, %s, %s, %s, %s, %s, \"%s\"},\n" % (
                c_vec(s), c_vec(t), c_vec(m), int(hm), cdec(f), cdec(fm), cdec(mv), cdec(fl),
                cdec(fml), label))
        out.append("};\n")
        return "".join(out)
    text = ("typedef struct { double sun[3], target[3], moon[3]; int has_moon;\n"
            "    double fraction;      /* the Sun's disc behind the ellipsoid alone */\n"
            "    double fraction_moon; /* ... behind the ellipsoid and the Moon */\n"
            "    double moon_visible;  /* the Moon's disc behind the ellipsoid */\n"
            "    double fraction_ld;   /* the limb-darkened Sun's behind the ellipsoid */\n"
            "    double fraction_moon_ld; /* ... behind the ellipsoid and the Moon */\n"
            "    const char *label; } ref_oblate_row;\n") + precision_blocks(block)
    return write_exact_header(
        root, OUT, "oblate",
        " * are the true function of those inputs (polar quadrature about the back disc's\n"
        " * centre with exact ray-ellipsoid intersections, tests/ref/oblate.py).\n", text)


def generate(root, argv):
    return [emit(root)]


if __name__ == "__main__":
    raise SystemExit(cli([OUT], generate, __doc__))
