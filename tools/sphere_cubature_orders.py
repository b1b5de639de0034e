#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""sphere_cubature_orders.py: error against cost of the sphere's earthshine cubature.

The runtime (src/sources/earthshine_angular.c) sends a Lambertian sphere's earthshine
to the observer by a cubature over the visible sunlit cap: the mapped
Gauss-Legendre rule of order N_A per piece in the polar angle a and the plain
rule of order N_B over the lit arc in the azimuth b, with the Lambert phase
kernel (docs/earthshine-angular.md). This script measures, against the
quadrature of bake/earthshine/angular.py (orders 32 x 48, which shares
nothing with the cubature), the error in units of the goal (1 % where the
flux exceeds 1 % of its maximum over observer directions at that (theta, h),
1e-4 of that maximum elsewhere) of:
  - the compiled runtime (build/liborbillum.so, `make shared`): the default
    cubature, the table's moments (OI_EARTH_REFLECT_TABLE) and the mean
    direction (OI_EARTH_REFLECT_MEAN);
  - the same cubature at other orders, by a line-for-line Python rendering
    of the C (this file's `sphere`), which the default row checks against
    the runtime;
and the cost as kernel evaluations (nodes) per call.
Points: 100 km to infinity (uniform in the visible cap's half-angle), half of
them across the terminator band, plus the table's worst band (theta
1.54-1.60 at 250-320 km) and the far night side (theta > 2.1 beyond 1e5 km).
Prints `name value unit` lines. Usage: tools/sphere_cubature_orders.py [--points N]
"""
import argparse
import ctypes as C
import importlib.util
import math
import os
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)
from bake.earthshine import angular  # noqa: E402
from cap_cubature import R, cap_breaks, mapped_rule, score  # noqa: E402

ORDERS = ((6, 4), (7, 4), (8, 4), (9, 4), (10, 4), (8, 6), (10, 6), (12, 8))
DEFAULT = (9, 4)
# the upper edge of the --far mode's third band (km)
BAND_KM = 100000.0


def default_orders(h):
    """The runtime's orders at altitude h km: the same at every altitude (a
    rule switched at a threshold would step the flux there)."""
    return DEFAULT


def _rules(na, nb):
    ta, wa = mapped_rule(na)
    x, w = np.polynomial.legendre.leggauss(nb)
    return ta, wa, (x + 1) / 2, w / 2


# the runtime's acos polynomial (Abramowitz & Stegun 4.4.46)
ACOS_POLY = [1.5707963050, -0.2145988016, 0.0889789874, -0.0501743046, 0.0308918810,
             -0.0170881256, 0.0066700901, -0.0012624911]


def _phase(c):
    """p(acos c) as the runtime forms it (within 1e-8 of the closed form)."""
    ac = np.minimum(np.abs(c), 1.0)
    q = np.sqrt(1.0 - ac)
    acos_abs = q * np.polyval(ACOS_POLY[::-1], ac)
    f = np.where(c < 0, acos_abs, np.pi - acos_abs) * c + q * np.sqrt(1.0 + ac)
    return np.maximum(2.0 / (3.0 * np.pi) * f, 0.0)


def _acos(x):
    """acos x as the runtime forms the lit arc's half-width (acos_approx)."""
    ax = min(abs(x), 1.0)
    a = math.sqrt(1.0 - ax) * float(np.polyval(ACOS_POLY[::-1], ax))
    return 2.0 * ACOS_POLY[0] - a if x < 0 else a


def _sincos(x):
    """sin x, cos x as the runtime forms them (sincos_small: Taylor to x^13, x^14)."""
    x2 = x * x
    s, c = 0.0, 0.0
    for n in (13, 11, 9, 7, 5, 3):
        s = 1.0 / math.factorial(n) - x2 * s
    for n in (14, 12, 10, 8, 6, 4, 2):
        c = 1.0 / math.factorial(n) - x2 * c
    return x * (1.0 - x2 * s), 1.0 - x2 * c


def sphere(theta, h, obs, na, nb):
    """The runtime's cubature at orders (na, nb) towards unit directions obs
    (rows): (F per direction, kernel evaluations)."""
    obs = np.atleast_2d(obs)
    ta, wa, tb, wb = _rules(na, nb)
    r = R + h
    rp, hp = R / r, h / r
    ct, st = math.cos(theta), math.sin(theta)
    bps = cap_breaks(theta, hp, rp)
    tot, used = np.zeros(len(obs)), 0
    for a0, a1 in zip(bps[:-1], bps[1:]):
        wd = a1 - a0
        if not wd > 0:
            continue
        for t, w in zip(ta, wa):
            a = a0 + wd * t
            sh, ch = _sincos(0.5 * a)
            sa, sh2 = 2 * sh * ch, sh * sh
            lit0, lit1 = (1 - 2 * sh2) * ct, sa * st
            cbm, sbm = -1.0, 0.0
            if lit1 > 0:
                x = -lit0 / lit1
                if x >= 1:
                    continue
                if x > -1:
                    cbm, sbm = x, math.sqrt((1 - x) * (1 + x))
                bm = math.pi if x <= -1 else _acos(x)
            elif lit0 > 0:
                bm = math.pi
            else:
                continue
            d2 = hp * hp + 4 * rp * sh2
            dd = math.sqrt(d2)
            rho, zc = rp * sa / dd, -(hp + 2 * rp * sh2) / dd
            # the lower half's nodes b_m t, the upper half's by the angle
            # difference from the exact b_m (as the runtime forms them)
            half = nb // 2
            s_lo, c_lo = _sincos(bm * tb[:half])
            sin_b = np.concatenate([s_lo, sbm * c_lo - cbm * s_lo])
            cos_b = np.concatenate([c_lo, cbm * c_lo + sbm * s_lo])
            wbn = np.concatenate([wb[:half], wb[:half]])
            lit = np.maximum(lit0 + lit1 * cos_b, 0.0)
            u = rho * cos_b[None, :] * obs[:, :1] + zc * obs[:, 2:3]
            v = rho * sin_b[None, :] * obs[:, 1:2]
            ring = ((_phase(u + v) + _phase(u - v)) * (wbn * lit)[None, :]).sum(axis=1)
            tot += wd * w * sa * (hp - 2 * sh2) / (d2 * dd) * bm * ring
            used += 2 * nb
    return np.maximum(tot * rp * rp / math.pi, 0.0), used


def points(n, rng):
    out = []
    for k in range(n):
        w = rng.uniform(math.acos(R / (R + 100.0)), 0.5 * math.pi - 1e-3)
        lo = 0.5 * math.pi - w if k % 2 else 0.0
        out.append((rng.uniform(lo, 0.5 * math.pi + w), R / math.cos(w) - R))
    for _ in range(max(n // 6, 1)):
        out.append((rng.uniform(1.54, 1.60), rng.uniform(250.0, 320.0)))
    for _ in range(max(n // 8, 1)):
        h = 10 ** rng.uniform(5.0, 6.5)
        out.append((rng.uniform(2.1, 0.5 * math.pi + math.acos(R / (R + h))), h))
    return out


def far_bands(args):
    """The maximum score per altitude band of orders in a (half of the points
    across the terminator band, as points() draws)."""
    rng = np.random.default_rng(args.seed)
    d = rng.normal(size=(args.dirs, 3))
    dirs = d / np.linalg.norm(d, axis=1)[:, None]
    for lo, hi in ((2e3, 1e4), (1e4, 3e4), (3e4, BAND_KM), (BAND_KM, 1e7)):
        worst = {}
        for k in range(args.points):
            h = 10 ** rng.uniform(math.log10(lo), math.log10(hi))
            w = math.acos(R / (R + h))
            theta = rng.uniform(0.5 * math.pi - w if k % 2 else 0.0, 0.5 * math.pi + w)
            ref = angular.sphere(theta, R / (R + h), dirs, n_a=32, n_b=48)
            if not ref.max() > 0:
                continue
            for o in ((6, 4), (7, 4), (9, 4)):
                got, _ = sphere(theta, h, dirs, *o)
                worst[o] = max(worst.get(o, 0.0), float(score(got, ref).max()))
        for o, v in worst.items():
            print("sphere_cubature.band_%.0f_%.0f_km.%dx%d.max_score %.3g goal_units" % (lo, hi, o[0], o[1], v))
    return 0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--points", type=int, default=48)
    ap.add_argument("--dirs", type=int, default=200)
    ap.add_argument("--seed", type=int, default=2024)
    ap.add_argument("--far", action="store_true",
                    help="the a order by altitude band instead: the maximum per band over "
                         "--points points each")
    args = ap.parse_args()
    if args.far:
        return far_bands(args)
    lib = C.CDLL(os.path.join(ROOT, "build", "liborbillum.so"))
    lib.oi_earthshine_sphere.argtypes = [C.c_double, C.c_double, C.POINTER(C.c_double),
                                         C.c_void_p, C.POINTER(C.c_double)]
    # the binding's ctypes mirror alone (the package would load its own library)
    spec = importlib.util.spec_from_file_location(
        "orbillum_lib_mirror", os.path.join(ROOT, "python", "orbillum", "_lib.py"))
    M = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(M)
    rng = np.random.default_rng(args.seed)
    d = rng.normal(size=(args.dirs, 3))
    dirs = d / np.linalg.norm(d, axis=1)[:, None]
    modes = {"runtime": 0, "table": M.OI_EARTH_REFLECT_TABLE, "mean": M.OI_EARTH_REFLECT_MEAN}
    worst = {k: [] for k in list(modes) + list(ORDERS) + ["default"]}
    nodes = {o: [] for o in list(ORDERS) + ["default"]}
    agree = 0.0
    for theta, h in points(args.points, rng):
        x = R / (R + h)
        ref = angular.sphere(theta, x, dirs, n_a=32, n_b=48)
        if not ref.max() > 0:
            continue
        rt = {}
        for name, mode in modes.items():
            m = M.oi_model()
            m.earth_reflection = mode
            vals = []
            for o in dirs:
                f = C.c_double()
                lib.oi_earthshine_sphere(theta, h, (C.c_double * 3)(*o), C.cast(C.byref(m), C.c_void_p),
                                         C.byref(f))
                vals.append(f.value)
            rt[name] = np.array(vals)
            worst[name].append(score(vals, ref).max())
        for o in list(ORDERS) + ["default"]:
            got, used = sphere(theta, h, dirs, *(default_orders(h) if o == "default" else o))
            worst[o].append(score(got, ref).max())
            nodes[o].append(used)
            if o == "default":
                agree = max(agree, float(np.max(np.abs(got - rt["runtime"])) / ref.max()))
    print("sphere_cubature.points %d count" % len(worst["runtime"]))
    for name in modes:
        s = np.array(worst[name])
        print("sphere_cubature.%s.max_score %.3g goal_units" % (name, s.max()))
        print("sphere_cubature.%s.p95_score %.3g goal_units" % (name, np.percentile(s, 95)))
        print("sphere_cubature.%s.median_score %.3g goal_units" % (name, np.median(s)))
    print("sphere_cubature.runtime_vs_python %.3g of_max" % agree)
    for o in list(ORDERS) + ["default"]:
        s = np.array(worst[o])
        tag = "%dx%d" % o if o != "default" else "default_%dx%d" % DEFAULT
        print("sphere_cubature.%s.max_score %.3g goal_units" % (tag, s.max()))
        print("sphere_cubature.%s.p95_score %.3g goal_units" % (tag, np.percentile(s, 95)))
        print("sphere_cubature.%s.median_score %.3g goal_units" % (tag, np.median(s)))
        print("sphere_cubature.%s.nodes_mean %.1f per_call" % (tag, np.mean(nodes[o])))
        print("sphere_cubature.%s.nodes_max %d per_call" % (tag, max(nodes[o])))


if __name__ == "__main__":
    main()
