# SPDX-License-Identifier: MIT
"""Report section: earthshine's angular distribution, error against bytes
(the Pareto of docs/earthshine-angular.md). Each variant of the angular
table's grid is baked and measured as the default is (bake/earthshine/
angular_table.py: the same random points between the nodes, scored in units
of the goal against the quadrature of bake/earthshine/angular.py); the mean
direction (no table) is scored at the same points.

  python -m bake.report.earth_angular        prints the markdown table
"""
import math
import sys

import numpy as np

from ..earthshine import angular, angular_table as AT

# (n_alt, n_term) variants, smallest first; the default is marked
VARIANTS = [(10, 9), (12, 13), (16, 13), (24, 17)]


def mean_direction_scores(cfg):
    """Scores of phi p(xi_mean) at the measure's points (the same draws)."""
    rng = np.random.default_rng(cfg["seed"] + 1)
    dirs = AT.directions(400, cfg["seed"] + 2)
    w_min = math.acos(AT.R_KM / (AT.R_KM + cfg["h_min_km"]))
    out = []
    for _ in range(cfg["n_measure"]):
        w = rng.uniform(w_min, 0.5 * math.pi - 1e-3)
        x = math.cos(w)
        theta = rng.uniform(0.0, 0.5 * math.pi + w)
        om, wt = angular.mirrored(*angular.nodes(theta, x))
        if not wt.sum() > 0:
            continue
        ex = (angular.lambert_phase(np.arccos(np.clip(dirs @ om.T, -1, 1))) * wt).sum(axis=1)
        v = (om * wt[:, None]).sum(axis=0)
        d = v / np.linalg.norm(v)
        q = wt.sum() * angular.lambert_phase(np.arccos(np.clip(dirs @ d, -1, 1)))
        out.append(AT.score(q, ex))
    return np.array(out)


def rows(log=None):
    cfg = dict(AT.DEFAULT)
    m = mean_direction_scores(cfg)
    out = [("mean direction (OI_EARTH_REFLECT_MEAN)", 0, float(m.max()),
            float(np.percentile(m, 95)), float(np.median(m)))]
    for na, nt in VARIANTS:
        c, off, _scale, code, _dec, r = AT.bake(dict(cfg, n_alt=na, n_term=nt))
        name = "%d x (2 + %d) nodes%s" % (na, nt, " (default)" if (na, nt) == (
            AT.DEFAULT["n_alt"], AT.DEFAULT["n_term"]) else "")
        out.append((name, AT.payload_bytes(code, off), r["max_score"], r["p95_score"],
                    r["median_score"]))
        if log:
            log("  %s done" % name)
    return out


def markdown(rs):
    lines = ["| representation | bytes | max | 95th percentile | median |",
             "|---|---|---|---|---|"]
    for name, b, mx, p95, med in rs:
        lines.append("| %s | %d | %.3g | %.3g | %.3g |" % (name, b, mx, p95, med))
    return "\n".join(lines) + "\n"


def section(outdir):
    return ("## Earthshine angular distribution\n\n"
            "Sphere flux under earthshine towards any observer, error in units of the goal "
            "(1 % where the flux exceeds 1 % of its maximum over directions at that "
            "(theta, h), 1e-4 of that maximum elsewhere), %d random (theta, h) from "
            "100 km to infinity, 400 directions each (docs/earthshine-angular.md).\n\n"
            % AT.DEFAULT["n_measure"] + markdown(rows()))


if __name__ == "__main__":
    sys.stdout.write(markdown(rows(log=lambda s: print(s, file=sys.stderr))))
