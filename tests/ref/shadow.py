# SPDX-License-Identifier: MIT
"""High-precision references for the phase, shadow and lunar-phase tests.

    python tests/ref/generate.py shadow        # writes tests/c/ref_phase.h, ref_shadow.h (~6 min)
    python tests/ref/shadow.py --report        # also prints the planar-formula comparison
    python tests/ref/shadow.py --gauss 16      # prints Gauss-Legendre nodes for the runtime

Every reference is computed with mpmath at 45 significant digits from the EXACT
binary value of each input (the double, or the float32 for the single-precision
table), so a test compares the library with the true function of the numbers it
was given. The algorithms are independent of the library's:

- Lambert phase: the closed form 2/(3 pi)((pi - x) cos x + sin x) at 45 digits
  (no series; the cancellation near pi costs at most ~50 of the 150 bits).
- Cap overlap and visible Sun fraction: numerical integration (tanh-sinh,
  mpmath.quad) over rings about the small cap's centre of the arc each ring
  has inside (outside) the other cap, split where rings start or stop being
  cut; cross-checked against the closed form (Gauss-Bonnet on the lens)
  2[pi - acos(..) - cos r1 acos(..) - cos r2 acos(..)] at 160 digits.
- Limb-darkened fraction: the same ring integral weighted by the Neckel & Labs
  (1994) intensity I(mu) at mu = sqrt(1 - sin^2 rho / sin^2 r_sun).
- Geometry: apparent radii asin(R/D) and the separation from acos of the
  normalised dot product, both at 45 digits.

The output depends only on this script (no timestamps, no randomness).
"""
import argparse
import hashlib
import sys

import numpy as np

from common import c_hex, cli, setup_mpmath, write

mp = setup_mpmath(45)
PI = mp.pi

OUT_PHASE = "tests/c/ref_phase.h"
OUT_SHADOW = "tests/c/ref_shadow.h"

# Constants exactly as the library stores them (oi_constants.h), per precision.
AU_KM = 149597870.7
R_SUN_KM = 695700.0
R_EARTH_KM = 6378.137

# Neckel & Labs (1994) limb-darkening polynomial at 559.95 nm, A0..A5.
LD_A = ["0.26892", "1.34319", "-1.58427", "1.91271", "-1.31350", "0.37295"]


def rnd(x, prec):
    """Round a number to the given binary precision ('d' or 'f')."""
    x = float(x)
    return float(np.float32(x)) if prec == "f" else x


def cfloat(x, prec):
    """C literal that is exactly the binary value x (hex float)."""
    return c_hex(x)


def cdec(x):
    """A reference value printed with 17 significant digits (double)."""
    x = mp.mpf(x)
    if x == 0:
        return "0.0"
    return mp.nstr(x, 20)


# ------------------------------------------------------------------ phase

def lambert_phase(x):
    """The closed form; near pi it cancels to ~t^3/3 (t = pi - x >= 1e-16 for
    a double x below pi), so it is evaluated at 150 digits."""
    with mp.workdps(150):
        x = mp.mpf(x)
        if x <= 0:
            return mp.mpf(2) / 3
        if x >= mp.pi:
            return mp.mpf(0)
        return +(2 / (3 * mp.pi) * ((mp.pi - x) * mp.cos(x) + mp.sin(x)))


def phase_points(prec):
    pts = set()
    # uniform grid over [0, pi]
    for i in range(201):
        pts.add(rnd(mp.pi * i / 200, prec))
    # within 1e-8 of 0 and of pi, log-spaced offsets, and ulps of pi
    for e in np.arange(-16.0, -0.5, 0.5):
        off = mp.mpf(10) ** mp.mpf(float(e))  # exact exponent, correctly rounded below
        pts.add(rnd(off, prec))
        pts.add(rnd(mp.pi - off, prec))
    pd = rnd(mp.pi, prec)
    x = pd
    step = np.float32 if prec == "f" else np.float64
    for _ in range(12):
        x = float(np.nextafter(step(x), step(0)))
        pts.add(x)
    pts.add(pd)
    pts.add(float(np.nextafter(step(pd), step(4))))
    # subnormal and tiny, negative, beyond pi, t = 1 switch of the series
    tiny = 1e-310 if prec == "d" else float(np.float32(1e-40))
    pts.update([0.0, tiny, rnd(1e-30, prec), rnd(-1e-20, prec), -1.0, rnd(-mp.pi, prec),
                4.0, 10.0, rnd(mp.pi - 1, prec)])
    for k in range(1, 6):
        pts.add(rnd(mp.pi - 1 + mp.mpf(k) * 1e-6, prec))
        pts.add(rnd(mp.pi - 1 - mp.mpf(k) * 1e-6, prec))
    return sorted(pts)


def moon_law(a):
    a = abs(mp.mpf(a))
    if a > PI:
        a = PI
    deg = a * 180 / PI
    return mp.power(10, -mp.mpf("0.4") * (mp.mpf("0.026") * deg + mp.mpf("4e-9") * deg ** 4))


def moon_points(prec):
    pts = set(rnd(mp.pi * i / 180, prec) for i in range(0, 181, 5))
    pts.update([0.0, rnd(1e-8, prec), rnd(mp.radians(150), prec), rnd(mp.pi - 1e-6, prec),
                rnd(-mp.radians(30), prec), 4.0, rnd(mp.pi, prec)])
    return sorted(pts)


# ------------------------------------------------------------------ caps

def covered_halfangle(rho, d, r1):
    """Half of the arc of the ring of radius rho about C2 lying inside the cap
    (C1, r1), C1 at angle d from C2: acos of the ring's cosine condition."""
    if rho == 0:
        return PI if r1 > d else mp.mpf(0)
    if d == 0:
        return PI if rho < r1 else mp.mpf(0)
    # cos r1 - cos d cos rho, written without cancellation for small angles
    num = 2 * mp.sin((rho + r1) / 2) * mp.sin((rho - r1) / 2) + 2 * mp.cos(rho) * mp.sin(d / 2) ** 2
    c = num / (mp.sin(d) * mp.sin(rho))
    if c >= 1:
        return mp.mpf(0)
    if c <= -1:
        return PI
    return mp.acos(c)


def breakpoints(lo, hi, d, r1):
    cands = [abs(d - r1), d + r1, 2 * PI - d - r1]
    return [lo] + sorted(b for b in cands if lo < b < hi) + [hi]


def overlap_quad(r1, r2, d):
    """Area of cap(r1) n cap(r2), centres d apart: rings about C2."""
    r1, r2, d = mp.mpf(r1), mp.mpf(r2), mp.mpf(d)
    if r2 == 0:
        return mp.mpf(0)
    f = lambda rho: mp.sin(rho) * 2 * covered_halfangle(rho, d, r1)
    return mp.quad(f, breakpoints(mp.mpf(0), r2, d, r1))


def overlap_closed(r1, r2, d):
    """Closed form from Gauss-Bonnet on the lens; it cancels
    badly for small caps, so it is evaluated at 160 digits."""
    with mp.workdps(160):
        return +_overlap_closed(mp.mpf(r1), mp.mpf(r2), mp.mpf(d))


def _overlap_closed(r1, r2, d):
    area = lambda r: 2 * PI * (1 - mp.cos(r))
    if d >= r1 + r2:
        return mp.mpf(0)
    if d <= abs(r1 - r2):
        return area(min(r1, r2))
    if r1 + r2 + d >= 2 * PI:
        return area(r1) + area(r2) - 4 * PI
    cl = lambda x: mp.acos(max(-1, min(1, x)))
    t0 = cl((mp.cos(d) - mp.cos(r1) * mp.cos(r2)) / (mp.sin(r1) * mp.sin(r2)))
    t1 = cl((mp.cos(r2) - mp.cos(d) * mp.cos(r1)) / (mp.sin(d) * mp.sin(r1)))
    t2 = cl((mp.cos(r1) - mp.cos(d) * mp.cos(r2)) / (mp.sin(d) * mp.sin(r2)))
    return 2 * (PI - t0 - t1 * mp.cos(r1) - t2 * mp.cos(r2))


def overlap_points(prec):
    rows = []
    small = [mp.mpf("1e-6"), mp.mpf("0.00465"), mp.mpf("0.1"), mp.mpf(1)]
    big = [mp.mpf("1.18715"), PI / 2, mp.mpf(2), mp.mpf(3)]
    for r1 in small + big:
        for r2 in small:
            edges = [r1 + r2, abs(r1 - r2)]
            ds = set()
            for e in edges:
                for off in [0, 1e-12, 1e-9, 1e-6, 1e-3]:
                    for sgn in (-1, 1):
                        v = e + sgn * mp.mpf(off) * max(r2, mp.mpf("1e-3"))
                        if 0 <= v <= PI:
                            ds.add(rnd(v, prec))
            for k in range(1, 8):
                v = abs(r1 - r2) + (r1 + r2 - abs(r1 - r2)) * k / 8
                if v <= PI:
                    ds.add(rnd(v, prec))
            ds.update([0.0, rnd(PI, prec)])
            for d in sorted(ds):
                rows.append((rnd(r1, prec), rnd(r2, prec), d))
    # half-covered: a cap centred on the boundary of a hemisphere
    rows.append((rnd(PI / 2, prec), rnd(mp.mpf("0.01"), prec), rnd(PI / 2, prec)))
    # both caps larger than a hemisphere; caps covering the sphere together
    for (a, b, d) in [(2.0, 2.5, 1.0), (2.0, 2.5, 3.0), (3.0, 3.0, 0.5), (1.7, 1.6, 3.1),
                      (3.1, 0.2, 3.0), (0.2, 3.1, 2.95)]:
        rows.append((rnd(a, prec), rnd(b, prec), rnd(d, prec)))
    out = []
    for r1, r2, d in rows:
        if max(r1, r2, d) > PI:
            continue  # float(pi) > pi: clamping is tested with closed forms
        q = overlap_quad(r1, r2, d)
        c = overlap_closed(r1, r2, d)
        scale = 2 * PI * (1 - mp.cos(min(mp.mpf(r1), mp.mpf(r2), PI)))
        if abs(q - c) > mp.mpf("1e-30") * (1 + scale) and abs(q - c) > mp.mpf("1e-25") * scale:
            sys.exit("overlap: quadrature and closed form disagree at %r: %s %s" % ((r1, r2, d), q, c))
        # condition: cap + sum |dA/dx| x over x = d, r1, r2 (absolute error of A
        # per unit relative perturbation of the inputs), closed form at 120 digits
        h = mp.mpf("1e-40")
        cond = scale
        for k in range(3):
            x = [mp.mpf(r1), mp.mpf(r2), mp.mpf(d)]
            xp, xm = list(x), list(x)
            xp[k] += h
            xm[k] = max(xm[k] - h, 0)
            cond += abs(overlap_closed(*xp) - overlap_closed(*xm)) / (xp[k] - xm[k]) * x[k]
        out.append((r1, r2, d, q, cond))
    return out


# ------------------------------------------------------------------ Sun fraction

def limb_intensity(mu):
    s = mp.mpf(0)
    for a in reversed(LD_A):
        s = s * mu + mp.mpf(a)
    return s


def sun_geometry(sun, point, prec):
    rs_km = mp.mpf(rnd(R_SUN_KM, prec))
    re_km = mp.mpf(rnd(R_EARTH_KM, prec))
    s = [mp.mpf(v) for v in sun]
    p = [mp.mpf(v) for v in point]
    rel = [s[i] - p[i] for i in range(3)]
    dsp = mp.sqrt(sum(v * v for v in rel))
    dp = mp.sqrt(sum(v * v for v in p))
    cosang = -sum(rel[i] * p[i] for i in range(3)) / (dsp * dp)
    cr = [rel[1] * p[2] - rel[2] * p[1], rel[2] * p[0] - rel[0] * p[2], rel[0] * p[1] - rel[1] * p[0]]
    sinang = mp.sqrt(sum(v * v for v in cr)) / (dsp * dp)
    sep = mp.atan2(sinang, cosang)
    return mp.asin(rs_km / dsp), mp.asin(re_km / dp), sep, dsp


def fraction_uniform(rs, re, sep):
    cap = 2 * PI * (1 - mp.cos(rs))
    return 1 - overlap_quad(re, rs, sep) / cap


def fraction_ld(rs, re, sep):
    srs = mp.sin(rs)

    def weight(rho):
        x = mp.sin(rho) / srs
        mu = mp.sqrt(max(0, 1 - x * x))
        return mp.sin(rho) * limb_intensity(mu)

    pts = breakpoints(mp.mpf(0), rs, sep, re)
    vis = mp.quad(lambda r: weight(r) * (PI - covered_halfangle(r, sep, re)), pts)
    tot = mp.quad(lambda r: weight(r) * PI, [0, rs])
    return vis / tot


def planar_mg(rs, re, sep):
    """Montenbruck & Gill (2000) eq. 3.85-3.87: planar two-circle overlap."""
    a, b, c = rs, re, sep
    if c >= a + b:
        return mp.mpf(1)
    if c <= b - a:
        return mp.mpf(0)
    if c <= a - b:
        return 1 - (b * b) / (a * a)
    x = (c * c + a * a - b * b) / (2 * c)
    y = mp.sqrt(a * a - x * x)
    area = a * a * mp.acos(x / a) + b * b * mp.acos((c - x) / b) - c * y
    return 1 - area / (PI * a * a)


def region_of(rs, re, sep):
    if sep >= re + rs:
        return 0
    if sep <= re - rs:
        return 2
    if sep <= rs - re:
        return 3
    return 1


def unit_basis():
    # a generic (non axis-aligned) Sun direction and a perpendicular
    u = mp.matrix([mp.mpf("0.6"), mp.mpf("-0.48"), mp.mpf("0.64")])  # |u| = 1
    v = mp.matrix([mp.mpf("0.8"), mp.mpf("0.36"), mp.mpf("-0.48")])  # u . v = 0, |v| = 1
    return u, v


def point_for_sep(dist_au, r_km, target_sep):
    """Point at r_km from the Earth in the (u, v) plane whose separation is
    target_sep, by root finding on the angle psi from the Sun direction."""
    u, v = unit_basis()
    S = u * (mp.mpf(dist_au) * mp.mpf(AU_KM))

    def sep_of(psi):
        P = (u * mp.cos(psi) + v * mp.sin(psi)) * mp.mpf(r_km)
        rel = S - P
        cosang = -(rel.T * P)[0] / (mp.norm(rel) * mp.norm(P))
        return mp.acos(cosang)

    psi = mp.findroot(lambda q: sep_of(q) - target_sep, PI - target_sep)
    P = (u * mp.cos(psi) + v * mp.sin(psi)) * mp.mpf(r_km)
    return [S[i] for i in range(3)], [P[i] for i in range(3)]


def sun_cases():
    """(sun, point) in exact mp numbers before rounding, and a label."""
    cases = []
    radii = [R_EARTH_KM + 0.001, R_EARTH_KM + 400.0, R_EARTH_KM + 700.0, 26560.0, 42164.0,
             384400.0, 1.0e6, 1.5e6, 1.0e7 + R_EARTH_KM]
    for dist in ["0.983", "1", "1.017"]:
        d = mp.mpf(dist) * AU_KM
        rs_app = mp.asin(R_SUN_KM / d)
        # the umbra's tip on the axis: asin(Re/r) = asin(Rs/(d + r))
        tip = mp.findroot(lambda r: mp.asin(R_EARTH_KM / r) - mp.asin(R_SUN_KM / (d + r)), 1.38e6)
        for r in radii + [tip]:
            re_app = mp.asin(R_EARTH_KM / mp.mpf(r))
            rs_here = mp.asin(R_SUN_KM / (d + r))  # on the axis; edges shift slightly off it
            seps = []
            offs = [0] + [s * mp.mpf(10) ** e for e in (-12, -10, -8, -6, -4, -3) for s in (-1, 1)]
            full = dist == "1" or r in (radii[1], radii[4], radii[7])
            if not full:
                offs = [0, mp.mpf("-1e-12"), mp.mpf("1e-12"), mp.mpf("-1e-6"), mp.mpf("1e-6")]
            for edge in (re_app + rs_here, abs(re_app - rs_here)):
                for o in offs:
                    seps.append(edge + o)
            lo, hi = abs(re_app - rs_here), re_app + rs_here
            for k in range(1, 8 if full else 4):
                seps.append(lo + (hi - lo) * k / (8 if full else 4))
            seps.append(hi * 3)
            if full:
                # the Earth's limb through (near) the Sun's centre: the
                # limb-darkened rings' hardest case
                for o in ["0", "1e-12", "-1e-12", "1e-9", "-1e-9", "1e-7", "-1e-7", "1e-6",
                          "-1e-6", "1e-5", "-1e-5"]:
                    seps.append(re_app + mp.mpf(o))
            for sp in seps:
                if 0 < sp < PI:
                    s, p = point_for_sep(dist, r, sp)
                    cases.append((s, p))
            # exactly on the axis, both sides (exact multiples)
            cases.append(([d, 0, 0], [-mp.mpf(r), 0, 0]))
            cases.append(([d, 0, 0], [mp.mpf(r), 0, 0]))
    # random geometries (fixed seed): Sun 0.983-1.017 AU in a random direction,
    # altitude log-uniform 1 m .. 2e6 km, separation across the penumbra and
    # 20 % beyond either edge
    # (the draws in double, everything after them in mpmath: no libm or BLAS
    # last bits in the inputs)
    rng = np.random.default_rng(20261122)
    for _ in range(100):
        d = mp.mpf(rng.uniform(0.983, 1.017)) * AU_KM
        u = [mp.mpf(x) for x in rng.normal(size=3)]
        nu = mp.sqrt(sum(x * x for x in u))
        u = [x / nu for x in u]
        r = R_EARTH_KM + mp.mpf(10) ** mp.mpf(rng.uniform(-3, 6.3))
        re_app = float(mp.asin(R_EARTH_KM / r))
        rs_app = float(mp.asin(R_SUN_KM / d))
        lo, hi = abs(re_app - rs_app), re_app + rs_app
        psi = mp.mpf(rng.uniform(max(lo - 0.2 * (hi - lo), 0.0), hi + 0.2 * (hi - lo)))
        v = [mp.mpf(x) for x in rng.normal(size=3)]
        vu = sum(a * b for a, b in zip(v, u))
        v = [a - vu * b for a, b in zip(v, u)]
        nv = mp.sqrt(sum(x * x for x in v))
        v = [x / nv for x in v]
        P = [r * (-mp.cos(psi) * a + mp.sin(psi) * b) for a, b in zip(u, v)]
        cases.append(([d * x for x in u], P))
    # exactly collinear, not axis-aligned
    cases.append(([mp.mpf(1e8), mp.mpf(1e8), 0], [mp.mpf(-5000), mp.mpf(-5000), 0]))
    cases.append(([mp.mpf(1e8), mp.mpf(-1e8), mp.mpf(2e7)], [mp.mpf(-5000), mp.mpf(5000), mp.mpf(-1000)]))
    return cases


def sun_rows(prec):
    rows = []
    seen = set()
    for s, p in sun_cases():
        sun = [rnd(x, prec) for x in s]
        pt = [rnd(x, prec) for x in p]
        key = tuple(sun + pt)
        if key in seen:
            continue
        seen.add(key)
        rs, re, sep, dsp = sun_geometry(sun, pt, prec)
        f = fraction_uniform(rs, re, sep)
        fl = fraction_ld(rs, re, sep)
        # condition number (absolute error per unit relative rounding), from the closed form
        g = lambda a, b, c: 1 - overlap_closed(b, a, c) / (2 * PI * (1 - mp.cos(a)))
        h = mp.mpf("1e-20")
        dsep = abs(g(rs, re, sep + h) - g(rs, re, sep - h)) / (2 * h) if sep > h else mp.mpf(0)
        drs = abs(g(rs + h, re, sep) - g(rs - h, re, sep)) / (2 * h)
        dre = abs(g(rs, re + h, sep) - g(rs, re - h, sep)) / (2 * h)
        # re = asin(Re/|p|) has condition tan(re) w.r.t. |p| (large 1 m above
        # the surface), rs likewise; the separation's rounding is absolute
        cond = dsep * max(sep, 1) + drs * mp.tan(rs) + dre * mp.tan(re) + 1
        edge = min(abs(sep - (re + rs)), abs(sep - abs(re - rs)))
        rows.append(dict(sun=sun, point=pt, f=f, fld=fl, rs=rs, re=re, sep=sep, dsp=dsp,
                         cond=cond, edge=edge, region=region_of(rs, re, sep),
                         mg=planar_mg(rs, re, sep)))
    return rows


# ------------------------------------------------------------------ emit

def header(name, guard, body):
    digest = hashlib.sha256(body.encode()).hexdigest()[:16]
    return (
        "/* SPDX-License-Identifier: MIT */\n"
        "/* %s: GENERATED by `python tests/ref/generate.py shadow` (do not edit).\n"
        " * mpmath %s at %d digits; inputs are exact binary values (hex floats),\n"
        " * references are the true function of those inputs, rounded to 17 digits.\n"
        " * payload sha256/16: %s */\n"
        "#ifndef %s\n#define %s\n\n%s\n#endif /* %s */\n"
        % (name, mp.__version__, mp.mp.dps, digest, guard, guard, body, guard)
    )


def emit_phase(root):
    parts = ["typedef struct { double x, want; } ref_pair;\n"]
    for prec, cond in (("d", "#ifndef OI_SINGLE_PRECISION"), ("f", "#else")):
        parts.append(cond + "\n")
        pts = phase_points(prec)
        parts.append("#ifndef REF_MOON_ONLY\nstatic const ref_pair ref_phase[%d] = {\n" % len(pts))
        for x in pts:
            parts.append("    {%s, %s},\n" % (cfloat(x, prec), cdec(lambert_phase(x))))
        parts.append("};\n")
        mpts = moon_points(prec)
        parts.append("#else\nstatic const ref_pair ref_moon[%d] = {\n" % len(mpts))
        for x in mpts:
            parts.append("    {%s, %s},\n" % (cfloat(x, prec), cdec(moon_law(x))))
        parts.append("};\n#endif\n")
    parts.append("#endif\n")
    return write(root, OUT_PHASE, header("ref_phase.h", "REF_PHASE_H", "".join(parts)))


def emit_shadow(root, report):
    parts = [
        "typedef struct { double r1, r2, d, want;\n"
        "    double cond; /* smaller cap's area + sum |dA/dx| x, x = r1, r2, d */\n} ref_overlap_row;\n",
        "typedef struct {\n    double sun[3], point[3];\n"
        "    double fraction, fraction_ld, sun_radius, earth_radius, separation, sun_distance;\n"
        "    double cond;  /* |df/dsep| max(sep,1) + |df/drs| tan rs + |df/dre| tan re + 1 */\n"
        "    double edge;  /* distance of sep from the nearest shadow edge (rad) */\n"
        "    int region;\n} ref_sun_row;\n",
    ]
    for prec, cond in (("d", "#ifndef OI_SINGLE_PRECISION"), ("f", "#else")):
        parts.append(cond + "\n")
        ov = overlap_points(prec)
        parts.append("static const ref_overlap_row ref_overlap[%d] = {\n" % len(ov))
        for r1, r2, d, q, cap in ov:
            parts.append("    {%s, %s, %s, %s, %s},\n" % (cfloat(r1, prec), cfloat(r2, prec),
                                                         cfloat(d, prec), cdec(q), cdec(cap)))
        parts.append("};\n")
        rows = sun_rows(prec)
        parts.append("static const ref_sun_row ref_sun[%d] = {\n" % len(rows))
        for r in rows:
            parts.append(
                "    {{%s}, {%s}, %s, %s, %s, %s, %s, %s, %s, %s, %d},\n"
                % (", ".join(cfloat(v, prec) for v in r["sun"]),
                   ", ".join(cfloat(v, prec) for v in r["point"]),
                   cdec(r["f"]), cdec(r["fld"]), cdec(r["rs"]), cdec(r["re"]), cdec(r["sep"]),
                   cdec(r["dsp"]), cdec(r["cond"]), cdec(r["edge"]), r["region"]))
        parts.append("};\n")
        if report and prec == "d":
            worst = max(rows, key=lambda r: abs(r["mg"] - r["f"]))
            print("planar Montenbruck-Gill vs exact spherical, worst |diff| = %s at r = %s km, f = %s"
                  % (mp.nstr(abs(worst["mg"] - worst["f"]), 4),
                     mp.nstr(mp.sqrt(sum(mp.mpf(v) ** 2 for v in worst["point"])), 8),
                     mp.nstr(worst["f"], 6)))
            for r in rows:
                dpk = mp.sqrt(sum(mp.mpf(v) ** 2 for v in r["point"]))
                if r["region"] == 1 and abs(r["mg"] - r["f"]) > 1e-6:
                    print("  r=%12s km f=%.10f planar-exact=%+.3e" % (
                        mp.nstr(dpk, 9), float(r["f"]), float(r["mg"] - r["f"])))
    parts.append("#endif\n")
    return write(root, OUT_SHADOW, header("ref_shadow.h", "REF_SHADOW_H", "".join(parts)))


def gauss(n):
    out = []
    for i in range(1, n + 1):
        x = mp.cos(PI * (i - mp.mpf(1) / 4) / (n + mp.mpf(1) / 2))
        for _ in range(100):
            p = mp.legendre(n, x)
            dx = p / (n * (x * p - mp.legendre(n - 1, x)) / (x * x - 1))
            x -= dx
            if abs(dx) < mp.mpf(10) ** -40:
                break
        dp = n * (x * mp.legendre(n, x) - mp.legendre(n - 1, x)) / (x * x - 1)
        out.append(((1 - x) / 2, 1 / ((1 - x * x) * dp * dp)))
    for x, w in sorted(out)[: n // 2]:
        print("    {OI_R(%s), OI_R(%s)}," % (mp.nstr(x, 21, min_fixed=-30, max_fixed=30),
                                              mp.nstr(w, 21)))


def generate(root, argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--report", action="store_true")
    ap.add_argument("--gauss", type=int, default=0)
    ap.add_argument("--only", choices=["phase", "shadow"], default=None)
    a = ap.parse_args(argv)
    if a.gauss:
        gauss(a.gauss)
        return []
    out = []
    if a.only in (None, "phase"):
        out.append(emit_phase(root))
    if a.only in (None, "shadow"):
        out.append(emit_shadow(root, a.report))
    return out


if __name__ == "__main__":
    raise SystemExit(cli([OUT_PHASE, OUT_SHADOW], generate, __doc__))
