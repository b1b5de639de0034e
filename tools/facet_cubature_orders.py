#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""facet_cubature_orders.py: error against cost of the facets' earthshine cubature.

The runtime (src/target/facet_earth.c) integrates a facet's earthshine exactly in
azimuth and with a fixed Gauss-Legendre rule of order 8 per piece in the
polar angle (docs/shapes.md). This script measures, against the
quadrature of bake/earthshine/angular.py (which shares nothing with the
cubature), the error in units of the goal (1 % where the irradiance exceeds
1 % of its maximum over normals at that (theta, h), 1e-4 of that maximum
elsewhere) of:
  - the compiled runtime (build/liborbillum.so, `make shared`), order 8;
  - the same method at other orders, by a line-for-line Python rendering of
    the C (this file's `plate`), which the order-8 row checks against the
    runtime;
and the cost as evaluations of the ring integral (nodes) per facet.
Points: 100 km to infinity (uniform in the visible cap's half-angle), half of
them across the terminator band, a third of the normals grazing.
Prints `name value unit` lines. Usage: tools/facet_cubature_orders.py [--points N]
"""
import argparse
import ctypes as C
import math
import os
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)
from bake.earthshine import angular  # noqa: E402
from cap_cubature import R, cap_breaks, mapped_rule, score  # noqa: E402



def _arc(k, b1, b2):
    def f(b):
        s, c = math.sin(b), math.cos(b)
        return (k[0] * k[2] * b + (k[0] * k[3] + k[1] * k[2]) * s - k[0] * k[4] * c +
                k[1] * k[3] * (b / 2 + s * c / 2) + k[1] * k[4] * s * s / 2)
    return f(b2) - f(b1)


def _half(c0, amp):
    if not amp > 0:
        return 4.0 if c0 > 0 else -1.0
    x = -c0 / amp
    return 4.0 if x <= -1 else (-1.0 if x >= 1 else math.acos(x))


def _ring(k, w1, beta, w2):
    if w1 < 0 or w2 < 0:
        return 0.0
    if w1 > math.pi and w2 > math.pi:
        return _arc(k, -math.pi, math.pi)
    if w2 > math.pi:
        return _arc(k, -w1, w1)
    if w1 > math.pi:
        return _arc(k, beta - w2, beta + w2)
    s = 0.0
    for sh in (-2 * math.pi, 0.0, 2 * math.pi):
        lo, hi = max(beta - w2 + sh, -w1), min(beta + w2 + sh, w1)
        if hi > lo:
            s += _arc(k, lo, hi)
    return s


def plate(theta, h, nrm, order):
    """The runtime's cubature at another order (returns (E, nodes used))."""
    tau, om = mapped_rule(order)
    r = R + h
    rp, hp = R / r, h / r
    nh = math.hypot(nrm[0], nrm[1])
    cn = nrm[2] / rp
    if not cn < 1:
        return 0.0, 0
    st, ct = math.sin(theta), math.cos(theta)
    bps = set()
    beta = math.atan2(nrm[1], nrm[0]) if nh > 0 else 0.0
    if cn > -1:
        gam, rho = math.atan2(nh, nrm[2]), math.acos(cn)
        bps |= {abs(gam - rho), gam + rho}
        s = np.array([st, 0.0, ct])
        k = s @ nrm
        det = (1 - k) * (1 + k)
        if det > 1e-12:
            p0 = (-cn * k / det) * s + (cn / det) * np.asarray(nrm)
            rest = 1 - p0 @ p0
            u = np.cross(s, nrm)
            if rest > 0 and np.linalg.norm(u) > 0:
                u /= np.linalg.norm(u)
                for sg in (1, -1):
                    bps.add(math.acos(max(-1.0, min(1.0, p0[2] + sg * math.sqrt(rest) * u[2]))))
    bps = cap_breaks(theta, hp, rp, bps)
    tot, used = 0.0, 0
    for a0, a1 in zip(bps[:-1], bps[1:]):
        wd = a1 - a0
        if not wd > 0:
            continue
        for t, w in zip(tau, om):
            a = a0 + wd * t
            sh, ch = math.sin(a / 2), math.cos(a / 2)
            sa, sh2 = 2 * sh * ch, sh * sh
            ca = 1 - 2 * sh2
            d2 = hp * hp + 4 * rp * sh2
            k = (ca * ct, sa * st, -nrm[2] * (hp + 2 * rp * sh2), rp * sa * nrm[0], rp * sa * nrm[1])
            tot += wd * w * sa * (hp - 2 * sh2) / (d2 * d2) * _ring(
                k, _half(k[0], k[1]), beta, _half(k[2], rp * sa * nh))
            used += 1
    return max(tot * rp * rp / math.pi, 0.0), used


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--points", type=int, default=30)
    ap.add_argument("--normals", type=int, default=24)
    ap.add_argument("--seed", type=int, default=4242)
    args = ap.parse_args()
    lib = C.CDLL(os.path.join(ROOT, "build", "liborbillum.so"))
    lib.oi_earthshine_plate.argtypes = [C.c_double, C.c_double, C.POINTER(C.c_double), C.c_void_p,
                                        C.POINTER(C.c_double)]
    rng = np.random.default_rng(args.seed)
    orders = (4, 6, 8, 12)
    worst = {o: [] for o in orders}
    nodes = {o: [] for o in orders}
    runtime, agree = [], 0.0
    for k in range(args.points):
        w = rng.uniform(math.acos(R / (R + 100.0)), 0.5 * math.pi - 1e-4)
        x = math.cos(w)
        h = R / x - R
        theta = (0.5 * math.pi + rng.uniform(-w, w)) if k % 2 else rng.uniform(0, math.pi)
        ns = rng.normal(size=(args.normals, 3))
        ns[: args.normals // 3, 2] = rng.uniform(-0.25, 0.25, args.normals // 3)
        ns /= np.linalg.norm(ns, axis=1)[:, None]
        ref = angular.plate(theta, x, ns, n_a=32, n_b=240)
        if not ref.max() > 0:
            continue
        rt = []
        for n in ns:
            e = C.c_double()
            lib.oi_earthshine_plate(theta, h, (C.c_double * 3)(*n), None, C.byref(e))
            rt.append(e.value)
        runtime.append(score(rt, ref).max())
        for o in orders:
            got = [plate(theta, h, n, o) for n in ns]
            worst[o].append(score([g[0] for g in got], ref).max())
            nodes[o].append(np.mean([g[1] for g in got]))
            if o == 8:
                agree = max(agree, float(np.max(np.abs(np.array([g[0] for g in got]) - rt) /
                                                max(ref.max(), 1e-300))))
    print("facet_cubature.points %d count" % len(runtime))
    print("facet_cubature.runtime.max_score %.3g goal_units" % max(runtime))
    print("facet_cubature.runtime.p95_score %.3g goal_units" % np.percentile(runtime, 95))
    print("facet_cubature.runtime_vs_python_order8 %.3g of_max" % agree)
    for o in orders:
        print("facet_cubature.order%d.max_score %.3g goal_units" % (o, max(worst[o])))
        print("facet_cubature.order%d.median_score %.3g goal_units" % (o, np.median(worst[o])))
        print("facet_cubature.order%d.nodes_mean %.1f per_facet" % (o, np.mean(nodes[o])))
        print("facet_cubature.order%d.nodes_max %d per_facet" % (o, max(nodes[o])))


if __name__ == "__main__":
    main()
