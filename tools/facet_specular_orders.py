#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""facet_specular_orders.py: the facets' specular earthshine against a quadrature.

The runtime (src/target/facet_earth.c, oi__plate_earth_specular) integrates the
Phong lobe of a facet over the visible sunlit Earth: below shininess
OI_LOBE_RULE_SHININESS (64) on the cap cubature's rings (6 nodes per arc in
azimuth), from it up by 4 x 8 nodes about the lobe's axis (docs/shapes.md).
This script measures both against the quadrature of bake/earthshine/angular.py
(Gauss-Legendre in both polar angles, orders 96 x 400, and 160 x 900 for
shininess above 300; it shares nothing with the runtime), with the mean
direction (all of the face's earthshine from the Earth's mean direction, as
the quadrature's nodes give it) for comparison.

Error in units of the goal, as for the irradiance: 1 % where the specular
radiance exceeds 1 % of its maximum over the observer directions drawn at
that point and normal, 1e-4 of that maximum elsewhere. Observers: half near
the mirror image of a direction into the sunlit cap (where a glint is),
half at random in front of the face. Points: 100 km to infinity (uniform in
the visible cap's half-angle), half across the terminator band; normals
facing the Earth's hemisphere.
Prints `name value unit` lines. Usage: tools/facet_specular_orders.py [--points N]
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
from cap_cubature import R, score as score_each  # noqa: E402

SHININESS = (0.0, 1.0, 10.0, 30.0, 63.0, 64.0, 100.0, 300.0, 1000.0, 10000.0)


def lobe(nrm, om, obs, n):
    """Phong lobe per unit albedo_specular, rows of om (towards the source)
    against rows of obs: [n_obs, n_om]."""
    ci = om @ nrm
    refl = 2.0 * ci[:, None] * nrm[None, :] - om
    c = np.clip(obs @ refl.T, 0.0, 1.0)
    v = (n + 2.0) / (2.0 * np.pi) * c ** n if n > 0 else np.full_like(c, 1.0 / np.pi)
    return v * (ci > 0)[None, :]


def score(got, ref):
    """The worst error in goal units over the observers."""
    return score_each(got, ref).max()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--points", type=int, default=12)
    ap.add_argument("--normals", type=int, default=2)
    ap.add_argument("--observers", type=int, default=16)
    ap.add_argument("--seed", type=int, default=77)
    args = ap.parse_args()
    lib = C.CDLL(os.path.join(ROOT, "build", "liborbillum.so"))
    f = lib.oi__plate_earth_specular
    f.restype = C.c_double
    f.argtypes = [C.c_double, C.c_double, C.c_double, C.c_double, C.POINTER(C.c_double),
                  C.POINTER(C.c_double), C.c_double]
    rng = np.random.default_rng(args.seed)
    res = {n: {"runtime": [], "mean": []} for n in SHININESS}
    for k in range(args.points):
        w = rng.uniform(math.acos(R / (R + 100.0)), 0.5 * math.pi - 1e-3)
        x = math.cos(w)
        h = R / x - R
        theta = (0.5 * math.pi + rng.uniform(-w, w)) if k % 2 else rng.uniform(0, 0.5 * math.pi + w)
        fine = {}
        for key, (na, nb) in (("std", (96, 400)), ("fine", (160, 900))):
            fine[key] = angular.mirrored(*angular.nodes(theta, x, na, nb))
        om0, w0 = fine["std"]
        if not w0.sum() > 0:
            continue
        v = (om0 * w0[:, None]).sum(axis=0)
        dmean, phi = v / np.linalg.norm(v), w0.sum()
        for _ in range(args.normals):
            nrm = rng.normal(size=3)
            nrm[2] = -abs(nrm[2])
            nrm /= np.linalg.norm(nrm)
            lit = (om0 @ nrm > 0) & (w0 > 0)
            if not lit.any():
                continue
            obs = []
            while len(obs) < args.observers:
                if len(obs) % 2 == 0:
                    u = om0[lit][rng.integers(lit.sum())]
                    o = 2 * (u @ nrm) * nrm - u + rng.normal(size=3) * 0.03
                else:
                    o = rng.normal(size=3)
                o /= np.linalg.norm(o)
                if o @ nrm > 0.02:
                    obs.append(o)
            obs = np.array(obs)
            for n in SHININESS:
                om, wt = fine["fine" if n > 300 else "std"]
                face = np.maximum(om @ nrm, 0.0)
                ref = (lobe(nrm, om, obs, n) * (wt * face)[None, :]).sum(axis=1)
                if not ref.max() > 0:
                    continue
                got = [f(math.cos(theta), math.sin(theta), h, R, (C.c_double * 3)(*nrm),
                         (C.c_double * 3)(*o), n) for o in obs]
                mean = phi * max(float(dmean @ nrm), 0.0) * lobe(nrm, dmean[None, :], obs, n)[:, 0]
                res[n]["runtime"].append(score(got, ref))
                res[n]["mean"].append(score(mean, ref))
    for n in SHININESS:
        r, m = np.array(res[n]["runtime"]), np.array(res[n]["mean"])
        tag = "n%g" % n
        print("facet_specular.%s.cases %d count" % (tag, len(r)))
        print("facet_specular.%s.runtime.max_score %.3g goal_units" % (tag, r.max()))
        print("facet_specular.%s.runtime.median_score %.3g goal_units" % (tag, np.median(r)))
        print("facet_specular.%s.mean_direction.median_score %.3g goal_units" % (tag, np.median(m)))


if __name__ == "__main__":
    main()
