# SPDX-License-Identifier: MIT
"""High-precision references for the Moon as an occulter and the Earth hiding the Moon.

    python tests/ref/generate.py occulters    # writes tests/c/ref_occulters.h (~1 min)

Every reference is computed with mpmath at 30 significant digits from the EXACT
binary value of each input (the double, or the float32 for the single-precision
table). The algorithm is independent of the library's (which uses Gauss-Bonnet
on the boundary of the three caps' intersection and cap segments):

- The visible fraction of a disc (the Sun's, or the Moon's) with one or two
  nearer discs in front: a numerical integral (tanh-sinh, mpmath.quad) over
  rings about the back disc's centre of the angle each ring keeps outside the
  UNION of the front discs (the union of two arcs of the ring, each from the
  spherical law of cosines), split where a ring starts or stops being cut by
  a disc and at the distances of the front circles' crossing points (where
  the two arcs start or stop overlapping).
- Geometry: apparent radii asin(R/D), the discs' centres as unit vectors,
  their separations from acos of the dot product, all at 30 digits.

The output depends only on this script (no timestamps, no randomness).
"""
from common import (c_vec, cdec, cli, cross, dot, norm, precision_blocks, rnd, setup_mpmath,
                    unit, write_exact_header)

mp = setup_mpmath(30)
PI = mp.pi

OUT = "tests/c/ref_occulters.h"

AU_KM = 149597870.7
R_SUN_KM = 695700.0
R_EARTH_KM = 6378.137
R_MOON_KM = 1737.4
GEO_KM = 42164.0
MOON_KM = 384400.0


def vsub(a, b):
    return [a[i] - b[i] for i in range(3)]


def angle(a, b):
    c = cross(a, b)
    return mp.atan2(norm(c), dot(a, b))


def crossings(c1, r1, c2, r2):
    """The crossing points (unit vectors) of two circles on the sphere, or []."""
    d = angle(c1, c2)
    if d >= r1 + r2 or d <= abs(r1 - r2) or d == 0:
        return []
    # P = a c1 + b c2 + g (c1 x c2), with P.c1 = cos r1, P.c2 = cos r2, |P| = 1
    cd = mp.cos(d)
    a = (mp.cos(r1) - mp.cos(r2) * cd) / (1 - cd * cd)
    b = (mp.cos(r2) - mp.cos(r1) * cd) / (1 - cd * cd)
    n = cross(c1, c2)
    base = [a * c1[i] + b * c2[i] for i in range(3)]
    rest = 1 - dot(base, base)
    if rest <= 0:
        return []
    g = mp.sqrt(rest) / norm(n)
    return [[base[i] + s * g * n[i] for i in range(3)] for s in (1, -1)]


# Neckel & Labs (1994) limb-darkening polynomial at 559.95 nm, A0..A5 (as tests/ref/shadow.py).
LD_A = ["0.26892", "1.34319", "-1.58427", "1.91271", "-1.31350", "0.37295"]


def limb_intensity(rho, rb):
    """I(mu)/I(1) at angular distance rho from the centre of a disc of radius
    rb, mu = sqrt(1 - sin^2 rho / sin^2 rb) (exact on the sphere)."""
    x = 1 - mp.sin(rho) ** 2 / mp.sin(rb) ** 2
    mu = mp.sqrt(x) if x > 0 else mp.mpf(0)
    return sum(mp.mpf(a) * mu ** k for k, a in enumerate(LD_A))


def visible_fraction(cb, rb, fronts, limb=False):
    """Visible fraction of the cap (cb, rb) behind the caps in `fronts`
    [(c, r), ...] (one or two): ring quadrature of the uncovered angle,
    weighted by the limb-darkened intensity when limb is set."""
    # a fixed frame about cb: the azimuth of each front centre
    ref = [1, 0, 0] if abs(cb[0]) < 0.9 else [0, 1, 0]
    e1 = unit(cross(cb, ref))
    e2 = cross(cb, e1)
    geo = []
    for c, r in fronts:
        d = angle(cb, c)
        az = mp.atan2(dot(c, e2), dot(c, e1))
        geo.append((d, r, az))

    def half(rho, d, r):
        if rho == 0:
            return PI if d < r else mp.mpf(0)
        if d == 0:
            return PI if rho < r else mp.mpf(0)
        x = (mp.cos(r) - mp.cos(rho) * mp.cos(d)) / (mp.sin(rho) * mp.sin(d))
        if x >= 1:
            return mp.mpf(0)
        if x <= -1:
            return PI
        return mp.acos(x)

    def uncovered(rho):
        hs = [(half(rho, d, r), az) for d, r, az in geo]
        covered = sum(2 * h for h, _ in hs)
        if len(hs) == 2:
            (h1, a1), (h2, a2) = hs
            delta = abs(a1 - a2) % (2 * PI)
            if delta > PI:
                delta = 2 * PI - delta
            lo = 2 * min(h1, h2)
            one = min(max(h1 + h2 - delta, 0), lo)
            two = min(max(h1 + h2 - (2 * PI - delta), 0), lo)
            covered -= min(one + two, lo)
        return max(2 * PI - covered, 0)

    pts = {mp.mpf(0), rb}
    for d, r, _ in geo:
        for v in (d - r, r - d, d + r):
            if 0 < v < rb:
                pts.add(v)
    if len(fronts) == 2:
        for p in crossings(fronts[0][0], fronts[0][1], fronts[1][0], fronts[1][1]):
            v = angle(cb, p)
            if 0 < v < rb:
                pts.add(v)
    pts = sorted(pts)
    if limb:
        w = lambda rho: limb_intensity(rho, rb) * mp.sin(rho)
        return mp.quad(lambda rho: uncovered(rho) * w(rho), pts) / (2 * PI * mp.quad(w, [0, rb]))
    area = mp.quad(lambda rho: uncovered(rho) * mp.sin(rho), pts)
    return area / (2 * PI * (1 - mp.cos(rb)))


def geometry(sun, moon, target):
    sun, moon, target = ([mp.mpf(x) for x in v] for v in (sun, moon, target))
    to_sun = vsub(sun, target)
    to_moon = vsub(moon, target)
    cs, cm = unit(to_sun), unit(to_moon)
    ce = unit([-x for x in target])
    rs = mp.asin(R_SUN_KM / norm(to_sun))
    rm = mp.asin(R_MOON_KM / norm(to_moon))
    re = mp.asin(R_EARTH_KM / norm(target))
    return cs, rs, cm, rm, ce, re, norm(to_moon), norm(target)


def sun_reference(sun, moon, target):
    """(fraction with the Earth and the Moon, the Moon's hidden fraction, the
    limb-darkened fraction, whether both discs are on the Sun)."""
    cs, rs, cm, rm, ce, re, _, _ = geometry(sun, moon, target)
    fronts = []
    if angle(cs, ce) < rs + re:
        fronts.append((ce, re))
    moon_on = angle(cs, cm) < rs + rm
    if moon_on:
        fronts.append((cm, rm))
    f = visible_fraction(cs, rs, fronts) if fronts else mp.mpf(1)
    hidden = 1 - visible_fraction(cs, rs, [(cm, rm)]) if moon_on else mp.mpf(0)
    f_ld = visible_fraction(cs, rs, fronts, limb=True) if fronts else mp.mpf(1)
    return f, hidden, f_ld, len(fronts) == 2


def moon_reference(sun, moon, target):
    """The fraction of the Moon's disc the Earth does not hide."""
    cs, rs, cm, rm, ce, re, dm, dp = geometry(sun, moon, target)
    if dp >= dm or angle(cm, ce) >= rm + re:
        return mp.mpf(1)
    return visible_fraction(cm, rm, [(ce, re)])


def around(axis, perp, ang, az):
    """Unit vector at angle ang from unit axis, azimuth az from unit perp."""
    other = cross(axis, perp)
    return [mp.cos(ang) * axis[i] + mp.sin(ang) * (mp.cos(az) * perp[i] + mp.sin(az) * other[i])
            for i in range(3)]


def sun_cases():
    """(sun, moon, target, label) in exact mp numbers before rounding."""
    cases = []
    sun = [mp.mpf(AU_KM), mp.mpf(0), mp.mpf(0)]
    z = [mp.mpf(0), mp.mpf(0), mp.mpf(1)]
    # GEO target on the +y axis; the Moon seen from it at angle s from the
    # Sun, at a distance dm (near side of the orbit: total; far side: annular)
    for dm, label in ((MOON_KM - GEO_KM, "geo near"), (MOON_KM + GEO_KM, "geo far")):
        target = [mp.mpf(0), mp.mpf(GEO_KM), mp.mpf(0)]
        cs = unit(vsub(sun, target))
        rs = mp.asin(R_SUN_KM / norm(vsub(sun, target)))
        rm = mp.asin(R_MOON_KM / dm)
        for k in (0, 0.001, 0.02, 0.05, 0.3, 0.8, 0.97, 0.999, 1.2):
            s = (rs + rm) * mp.mpf(k)
            u = around(cs, z, s, mp.mpf("0.7"))
            moon = [target[i] + dm * u[i] for i in range(3)]
            cases.append((sun, moon, target, "%s k=%s" % (label, k)))
    # a lunar-orbit target 100 km above the Moon, the Sun near the Moon's limb
    moon = [mp.mpf(0), mp.mpf(MOON_KM), mp.mpf(0)]
    for lim in (-0.02, -0.004, -0.002, 0.0, 0.002, 0.0045, 0.01):
        h = R_MOON_KM + 100
        rm = mp.asin(R_MOON_KM / h)
        # target placed so that the Sun is seen at angle rm + lim from the Moon's centre
        ang = rm + mp.mpf(lim)
        # from the target, the Moon's centre at -d (direction from target); the
        # Sun along +x: the target at moon + h (cos(pi - ang), ...)
        t_dir = [-mp.cos(ang), mp.sin(ang), mp.mpf(0)]  # from the Moon to the target
        target = [moon[i] + h * t_dir[i] for i in range(3)]
        cases.append((sun, moon, target, "lunar orbit limb%+g" % lim))
    # both occulters at once: a GEO target in the Earth's penumbra, the Moon's
    # disc on the Sun at several azimuths about the Sun's centre
    for gk in (0.3, 0.7):
        # the target on the Earth's penumbra: sep(Sun, Earth) = re + rs (1 - 2 gk)
        r = mp.mpf(GEO_KM)
        # solve for the angle of the target behind the Earth (iterate: rs, re depend weakly)
        th = mp.mpf(0)
        for _ in range(30):
            target = [-r * mp.cos(th), r * mp.sin(th), mp.mpf(0)]
            cs = unit(vsub(sun, target))
            ce = unit([-x for x in target])
            rs = mp.asin(R_SUN_KM / norm(vsub(sun, target)))
            re = mp.asin(R_EARTH_KM / r)
            want = re + rs * (1 - 2 * mp.mpf(gk))
            th += want - angle(cs, ce)
        dm = mp.mpf(MOON_KM)
        rm = mp.asin(R_MOON_KM / dm)
        perp = unit(vsub(ce, [dot(ce, cs) * cs[i] for i in range(3)]))
        for mk, az in ((0.5, 0.0), (0.5, 0.6), (0.9, 0.3), (0.2, 1.2), (1.0, 0.0),
                       (0.6, 2.0), (0.8, PI), (0.1, 0.1), (1.3, 0.2), (1.7, 0.05)):
            s = (rs + rm) * mp.mpf(mk) / 2
            u = around(cs, perp, s, mp.mpf(az))
            moon = [target[i] + dm * u[i] for i in range(3)]
            cases.append((sun, moon, target, "both gk=%s mk=%s az=%s" % (gk, mk, mp.nstr(mp.mpf(az), 3))))
    return cases


def moon_cases():
    """The Earth hiding the Moon: fully, partly, not at all."""
    cases = []
    sun = [mp.mpf(AU_KM), mp.mpf(0), mp.mpf(0)]
    moon = [mp.mpf(0), mp.mpf(MOON_KM), mp.mpf(0)]
    # the case: the Earth exactly between the target and the Moon
    cases.append((sun, moon, [mp.mpf(0), mp.mpf(-7000), mp.mpf(0)], "behind the Earth"))
    # a LEO target at 7000 km seeing the Moon rise over the limb
    r = mp.mpf(7000)
    re = mp.asin(R_EARTH_KM / r)
    for k in (-0.01, -0.001, -0.0003, 0.0, 0.0003, 0.001, 0.004, 0.01):
        # the target at angle th from -y in the y-z plane: the Moon seen at
        # about pi - th from the Earth's centre; solve th for sep = re + k
        th = mp.mpf(0)
        for _ in range(30):
            target = [mp.mpf(0), -r * mp.cos(th), r * mp.sin(th)]
            sep = angle(unit(vsub(moon, target)), unit([-x for x in target]))
            th += (re + mp.mpf(k)) - sep
        cases.append((sun, moon, target, "limb k=%s" % k))
    # far from the Earth's disc
    cases.append((sun, moon, [mp.mpf(0), mp.mpf(GEO_KM), mp.mpf(0)], "apart"))
    return cases


def rows(prec):
    out_sun, out_moon = [], []
    for sun, moon, target, label in sun_cases():
        s, m, t = ([rnd(x, prec) for x in v] for v in (sun, moon, target))
        f, hidden, f_ld, both = sun_reference(s, m, t)
        out_sun.append((s, m, t, f, hidden, f_ld, both, label))
    for sun, moon, target, label in moon_cases():
        s, m, t = ([rnd(x, prec) for x in v] for v in (sun, moon, target))
        out_moon.append((s, m, t, moon_reference(s, m, t), label))
    return out_sun, out_moon


def emit(root):
    def block(prec):
        rs, rm = rows(prec)
        out = ["static const ref_moon_sun_row ref_moon_sun[%d] = {\n" % len(rs)]
        for s, m, t, f, h, f_ld, both, label in rs:
            out.append("    {{%s}, {%s}, {%s}, %s, %s, %s, %d, \"%s\"},\n" % (
                c_vec(s), c_vec(m), c_vec(t), cdec(f), cdec(h), cdec(f_ld), int(both), label))
        out.append("};\n")
        out.append("static const ref_moon_hidden_row ref_moon_hidden[%d] = {\n" % len(rm))
        for s, m, t, v, label in rm:
            out.append("    {{%s}, {%s}, {%s}, %s, \"%s\"},\n" % (
                c_vec(s), c_vec(m), c_vec(t), cdec(v), label))
        out.append("};\n")
        return "".join(out)
    text = ("typedef struct { double sun[3], moon[3], target[3]; double fraction, moon_hidden;\n"
            "    double fraction_ld;\n"
            "    int both; /* both discs on the Sun: the library's fraction_ld approximates */\n"
            "    const char *label; } ref_moon_sun_row;\n"
            "typedef struct { double sun[3], moon[3], target[3]; double moon_visible;\n"
            "    const char *label; } ref_moon_hidden_row;\n") + precision_blocks(block)
    return write_exact_header(
        root, OUT, "occulters",
        " * are the true function of those inputs (ring quadrature, tests/ref/occulters.py).\n",
        text)


def generate(root, argv):
    return [emit(root)]


if __name__ == "__main__":
    raise SystemExit(cli([OUT], generate, __doc__))
