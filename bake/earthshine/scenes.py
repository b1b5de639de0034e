# SPDX-License-Identifier: MIT
"""Bake configurations: the default table and mission scenes.

A configuration (bake/config/*.json) gives the table's name, its altitude band
(h_max_km null = to infinity), the accuracy goal, and either a fixed grid
("grid") or none, in which case the smallest grid of a ladder that meets the
goal (measured) is chosen: that is how `--scene` leaves out what a mission does
not need.
"""

import json
import math
import time


from .. import __version__
from . import grid
from . import reference as ref
from . import table as emit
from .measure import measure

# Ladder of theta resolutions (n_lit, n_term) and altitude resolutions tried
# for scenes, smallest first.
# (format 4: the lit segment is exact in theta, two columns suffice)
THETA_LADDER = [(2, 5), (2, 9), (2, 13), (2, 17), (2, 25), (2, 33), (2, 49), (2, 65), (2, 81)]
ALT_LADDER = [2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64]
SEARCH_MARGIN = 0.6  # a candidate passes the (sparser) search at 60 % of the goal


def load(path):
    with open(path, encoding="utf-8") as f:
        cfg = json.load(f)
    for k in ("name", "h_min_km", "rel_goal"):
        if k not in cfg:
            raise ValueError("%s: missing %r" % (path, k))
    cfg.setdefault("h_max_km", None)
    cfg.setdefault("radius_km", ref.R_EARTH_KM)
    cfg.setdefault("psi_goal_rad", 1e-3)
    cfg.setdefault("reference_order", 32)
    cfg.setdefault("measure", {"n_random": 4000, "seed": 12345})
    cfg.setdefault("photon", {"n_photons": 2000000, "seed": 1})
    return cfg


def band(cfg):
    """(w_min, w_max, h_min_km, h_max_km) of a configuration."""
    R = float(cfg["radius_km"])
    h_lo = float(cfg["h_min_km"])
    h_hi = cfg["h_max_km"]
    if not h_lo >= 0.0:
        raise ValueError("need h_min_km >= 0 (0: from the surface)")
    w_lo = float(grid.w_from_h(h_lo, R))
    if h_hi is None:
        return w_lo, grid.HALF_PI, h_lo, math.inf
    h_hi = float(h_hi)
    if not h_hi > h_lo >= 0:
        raise ValueError("need 0 <= h_min_km < h_max_km")
    return w_lo, float(grid.w_from_h(h_hi, R)), h_lo, h_hi


def _passes(m, cfg, margin):
    return m["max_score"] <= margin and m["max_psi_err_rad"] <= margin * cfg["psi_goal_rad"]


def choose_grid(cfg, log=print, progress=None):
    """Smallest ladder grid meeting the goal (with the search margin)."""
    w_lo, w_hi, _, _ = band(cfg)
    order = int(cfg["reference_order"])
    best = None
    for n_lit, n_term in THETA_LADDER:
        prev = None
        for n_alt in ALT_LADDER:
            spec = grid.TableSpec(n_lit, n_term, n_alt, w_lo, w_hi)
            if best is not None and spec.bytes() >= best[0].bytes():
                break
            q, psi = grid.node_values(spec, order=order, progress=False)
            m = measure(spec, emit.f32(q), emit.f32(psi), n_random=500, order=order,
                             progress=False, rel_goal=cfg["rel_goal"], refine=False)
            ok = _passes(m, cfg, SEARCH_MARGIN)
            log("  try %3d+%3d x %3d (%6d bytes): goal score %.3f, psi %.2e rad%s" % (
                n_lit, n_term, n_alt, spec.bytes(), m["max_score"], m["max_psi_err_rad"],
                "  ok" if ok else ""))
            if ok:
                best = (spec, q, psi)
                break
            if prev is not None and m["max_score"] > 0.9 * prev:
                break  # limited by the theta resolution: next rung
            prev = m["max_score"]
        if best is not None and best[0].n_alt == ALT_LADDER[0]:
            break
    if best is None:
        raise RuntimeError("no grid of the ladder meets the goal")
    return best


def bake(cfg, outdir, method="quadrature", log=print, progress=None, photon_args=None):
    """Bake one configuration into outdir. Returns (paths, meta)."""
    t0 = time.monotonic()
    w_lo, w_hi, h_lo, h_hi = band(cfg)
    order = int(cfg["reference_order"])
    if "grid" in cfg:
        g = cfg["grid"]
        spec = grid.TableSpec(g["n_lit"], g["n_term"], g["n_alt"], w_lo, w_hi,
                              g.get("term_k0", grid.TERM_K0), g.get("term_kp", grid.TERM_KP))
        q = psi = None
    else:
        log("sizing %s for %s .. %s km, goal %g" % (cfg["name"], h_lo, h_hi, cfg["rel_goal"]))
        spec, q, psi = choose_grid(cfg, log, progress)
    pargs = dict(cfg.get("photon", {}))
    pargs.update(photon_args or {})
    if q is None or method != "quadrature":
        q, psi = grid.node_values(spec, order=order, method=method, progress=progress,
                                  photon_args=pargs)
    q32, p32 = emit.f32(q), emit.f32(psi)
    mcfg = cfg["measure"]
    m = measure(spec, q32, p32, n_random=int(mcfg["n_random"]), order=order,
                     progress=progress, rel_goal=cfg["rel_goal"], seed=int(mcfg["seed"]))
    m["reference_order"] = order
    m["h_measure_min_km"] = grid.H_MEASURE_MIN_KM
    m["seed"] = int(mcfg["seed"])
    m["n_random"] = int(mcfg["n_random"])
    # round the measurements so that the output does not depend on the last
    # bits of libm (byte-for-byte reproducible)
    for k in ("max_score", "max_rel_err", "max_abs_err_frac", "max_psi_err_rad",
              "max_score_terminator", "worst_theta", "worst_h_km"):
        m[k] = float("%.4g" % m[k])
    detail = ""
    if method == "quadrature":
        detail = " (bake/earthshine/reference.py: Gauss-Legendre order %d per piece, sinh-mapped slices)" % order
    else:
        detail = " (bake/photon/mapping.py: %d photons, seed %d)" % (pargs.get("n_photons", 0), pargs.get("seed", 0))
    meta = {
        "name": cfg["name"],
        "description": cfg.get("description", ""),
        "generator_version": __version__,
        "format": emit.TABLE_FORMAT,
        "method": method,
        "method_detail": detail,
        "parameters": {k: cfg[k] for k in sorted(cfg) if k not in ("name", "description")},
        "grid": dict(spec.as_dict(), n_values=spec.n_values,
                     coordinates="w = acos(R/r) uniform; theta: lit segment v(pi/2-w), "
                                 "terminator segment pi/2 + w sinh(k(2v-1))/sinh(k), "
                                 "k = term_k0 x^term_kp",
                     stored="lit segment: q = phi(0,x)/x^2, psi = G/w (phi = cos(theta) phi(0,x), "
                            "tan psi = tan(theta) G); terminator segment: q = phi/(x^2 w), "
                            "psi (rad); float32",
                     interpolation="Catmull-Rom per segment, linear-extrapolated ghosts "
                                   "(quadratic below the surface row w = 0)"),
        "h_min_km": h_lo,
        "h_max_km": h_hi,
        "radius_km": float(cfg["radius_km"]),
        "rel_goal": float(cfg["rel_goal"]),
        "measured": m,
        "sha256": emit.payload_sha256(q32, p32),
        "payload_bytes": spec.bytes(),
    }
    paths = emit.write(outdir, cfg["name"], spec, q32, p32, meta)
    log("%s: %d+%d x %d nodes, %d bytes, max rel err %.3e, goal score %.3f, psi %.2e rad (%.1f s)" % (
        cfg["name"], spec.n_lit, spec.n_term, spec.n_alt, spec.bytes(), m["max_rel_err"],
        m["max_score"], m["max_psi_err_rad"], time.monotonic() - t0))
    if m["max_score"] > 1.0:
        log("  WARNING: %s does not meet its goal (max error %.3g x the goal)" % (
            cfg["name"], m["max_score"]))
    return paths, meta

