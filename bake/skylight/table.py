# SPDX-License-Identifier: MIT
"""The scattered-sunlight table oi_sky_vband: node values, lookup mirror, measurement, emit.

The family's steps (docs/tables.md): spec from bake/config/skylight.json, node values
from the single-scattering quadrature (single.py), float32 rounding, the lookup's
Python mirror (`lookup`, the runtime's src/skylight.c), its measured error at random
points between the nodes against the same quadrature, the quadrature's own error
against the independent Monte Carlo (montecarlo.py) at fixed points, the energy bound,
and the Table of the one emitter.

Grid: theta uniform on [0, pi] (n_theta nodes), w = acos(R / r) uniform on
[w_min, pi/2] (n_alt rows; w_min: the top of the atmosphere, pi/2: infinity, baked at
x = R / r = x_last). Stored q = (E_sky / E_sun) / x^2 (finite at infinity) and psi, the
mean direction's angle from the nadir towards the Sun (0 where nothing is lit).
Stored as v = ln(q + q_floor) (q_floor = 1e-9, a millionth of the rows' peaks): E_sky
falls by orders of magnitude over a few degrees past the shadow edge, an exponential
that a cubic follows in its logarithm, not in its value.
Lookup: Catmull-Rom in theta (ghost nodes mirrored: v is even about theta = 0 and pi,
psi odd) and in w (ghosts extrapolated linearly), each of the four rows read at theta
shifted along the shadow edge (theta + s (w_row - w), s = (1 - cos theta) / 2: the edge
lies near theta = pi/2 + w and moves by a node per row spacing, which a cubic in w at
fixed theta does not follow), q = exp(v) - q_floor clamped at 0.
"""
from __future__ import annotations

import json
import math
import os

import numpy as np

from .. import __version__
from ..common import emit as cemit
from ..common.emit import round_sig
from ..common.progress import Progress
from . import montecarlo, single
from .medium import AER_G, AER_OMEGA_STRAT, AER_OMEGA_TROP, N_GROUPS, RHO_N, Medium

HERE = os.path.dirname(os.path.abspath(__file__))
CFG_PATH = os.path.join(os.path.dirname(HERE), "config", "skylight.json")
NAME = "oi_sky_vband"
FORMAT = 1                 # OI_SKY_FORMAT in include/oi_table.h
GENERATOR = "bake.skylight"
LAYOUT = ("format", "kind", "info", "n_theta", "n_alt", "w_min", "w_max", "earth_radius_km",
          "top_km", "floor_km", "theta_scale", "w_scale", "q_floor", "v", "psi")


def load_config(path=CFG_PATH):
    with open(path, encoding="ascii") as f:
        return json.load(f)


class Spec:
    def __init__(self, cfg, med: Medium):
        g = cfg["grid"]
        self.n_theta, self.n_alt = int(g["n_theta"]), int(g["n_alt"])
        self.R = med.R
        self.w_min = math.acos(self.R / (self.R + float(g["h_min_km"])))
        self.w_max = math.pi / 2
        self.x_last = float(g["x_last"])
        self.theta = np.linspace(0.0, math.pi, self.n_theta)
        self.w = np.linspace(self.w_min, self.w_max, self.n_alt)

    def radius(self, w):
        """Target distance (km) of an altitude node; the last row at x_last."""
        x = max(math.cos(w), self.x_last)
        return self.R / x


def configure(quad_cfg):
    single.N_AZ = int(quad_cfg["n_az"])
    single.N_PATH = int(quad_cfg["n_path"])
    single.N_NU_SEG = int(quad_cfg["n_nu_seg"])


def node_values(spec: Spec, ss: single.SingleScattering, progress=False):
    q = np.zeros((spec.n_alt, spec.n_theta))
    psi = np.zeros_like(q)
    bar = Progress(spec.n_alt, "skylight: rows", progress)
    for j, w in enumerate(spec.w):
        r = spec.radius(w)
        x = spec.R / r
        for i, th in enumerate(spec.theta):
            e, p = ss.irradiance(th, r)
            q[j, i] = e / (x * x)
            # on the Sun-Earth axis psi is 0 by symmetry (not the sum's rounding)
            psi[j, i] = 0.0 if i in (0, spec.n_theta - 1) else p
        bar.step()
    return q, psi


def _cr(f):
    f2 = f * f
    f3 = f2 * f
    return (0.5 * (-f3 + 2 * f2 - f), 0.5 * (3 * f3 - 5 * f2 + 2),
            0.5 * (-3 * f3 + 4 * f2 + f), 0.5 * (f3 - f2))


def stored(q, q_floor):
    """The stored values v = ln(q + q_floor) (float32) of float32 node values q."""
    return cemit.f32(np.log(np.asarray(q, dtype=float) + q_floor))


def lookup(v, psi, spec: Spec, theta, w, q_floor):
    """The runtime's lookup (src/skylight.c) in numpy: (e_sky / E_sun, psi) at
    scalars theta in [0, pi], w in [w_min, w_max], from the stored v."""
    nt, na = spec.n_theta, spec.n_alt
    w_scale = (na - 1) / (spec.w_max - spec.w_min)
    fw = min(max((w - spec.w_min) * w_scale, 0.0), na - 1.0)
    j = min(int(fw), na - 2)
    b = fw - j
    ww = _cr(b)
    shear = 0.5 * (1.0 - math.cos(theta)) / w_scale

    def col(arr, row, k, odd):
        if k < 0:
            return (-1.0 if odd else 1.0) * arr[row, -k]
        if k > nt - 1:
            return (-1.0 if odd else 1.0) * arr[row, 2 * (nt - 1) - k]
        return arr[row, k]

    def row_at(arr, row, th, odd):
        flip = 1.0
        if th < 0.0:
            th, flip = -th, (-1.0 if odd else 1.0)
        elif th > math.pi:
            th, flip = 2.0 * math.pi - th, (-1.0 if odd else 1.0)
        ft = min(max(th * ((nt - 1) / math.pi), 0.0), nt - 1.0)
        i = min(int(ft), nt - 2)
        wt = _cr(ft - i)
        return flip * sum(wt[m] * col(arr, row, i - 1 + m, odd) for m in range(4))

    def value(arr, odd):
        rows = [row_at(arr, jj, theta + shear * (m - 1 - b), odd) if 0 <= jj < na else None
                for m, jj in enumerate(range(j - 1, j + 3))]
        if rows[0] is None:
            rows[0] = 2 * rows[1] - rows[2]
        if rows[3] is None:
            rows[3] = 2 * rows[2] - rows[1]
        return sum(ww[m] * rows[m] for m in range(4))

    x = max(math.cos(w), 0.0)
    qv = max(math.exp(value(v, False)) - q_floor, 0.0)
    return qv * x * x, (value(psi, True) if qv > 0 else 0.0)


def measure(q, v, psi, spec, ss, n, seed, goal_rel, goal_floor, q_floor, progress=False):
    """Lookup vs quadrature at n random points between the nodes (theta, w uniform)."""
    rng = np.random.Generator(np.random.PCG64(seed))
    th = rng.random(n) * math.pi
    w = spec.w_min + rng.random(n) * (spec.w_max - 0.02 - spec.w_min)
    row_max = {}
    worst, worst_rel, worst_abs, worst_psi = 0.0, 0.0, 0.0, 0.0
    bar = Progress(n, "skylight: measure", progress)
    for t, ww in zip(th, w):
        r = spec.radius(ww)
        x = spec.R / r
        e_ref, p_ref = ss.irradiance(t, r)
        e_tab, p_tab = lookup(v, psi, spec, t, ww, q_floor)
        # the row's maximum over theta, interpolated from the stored maxima
        fw = (ww - spec.w_min) / (spec.w_max - spec.w_min) * (spec.n_alt - 1)
        j = min(int(fw), spec.n_alt - 2)
        peak = max(q[j].max(), q[j + 1].max()) * x * x
        err = abs(e_tab - e_ref)
        if e_ref >= goal_floor * peak:
            rel = err / e_ref
            worst_rel = max(worst_rel, rel)
            worst = max(worst, rel / goal_rel)
            if e_ref >= 0.05 * peak:
                worst_psi = max(worst_psi, abs(p_tab - p_ref))
        else:
            worst_abs = max(worst_abs, err / peak)
            worst = max(worst, err / (goal_rel * goal_floor * peak))
        bar.step()
    return {"n_points": n, "max_rel_error": round_sig(worst_rel),
            "max_abs_error_over_row_peak": round_sig(worst_abs),
            "max_psi_error_rad_above_5pct": round_sig(worst_psi),
            "worst_in_goal_units": round_sig(worst)}


def energy_bound(q, spec):
    """Per row: cos(alpha_top) 2 pi r^2 int E_sky sin(theta) dtheta over the power the
    top sphere intercepts, pi r_top^2 (both per unit solar irradiance). Scalar
    irradiance bounds the outward flux through the sphere of radius r divided by
    cos(alpha_top) (every ray comes within alpha_top of the nadir), and that flux is
    at most the scattered power: the ratio must stay below 1."""
    r_top = spec.R + (Medium().profile.top_km)
    out = []
    for j, w in enumerate(spec.w):
        r = spec.radius(w)
        x = spec.R / r
        e = q[j] * x * x
        cos_a = math.sqrt(max(0.0, 1.0 - (r_top / r) ** 2))
        integral = np.trapezoid(e * np.sin(spec.theta), spec.theta)
        out.append(cos_a * 2 * math.pi * r * r * integral / (math.pi * r_top * r_top))
    return out


def montecarlo_check(ss, mc_cfg, progress=False):
    rows = []
    bar = Progress(len(mc_cfg["points_h_theta_deg"]), "skylight: Monte Carlo", progress)
    for k, (h, th_deg) in enumerate(mc_cfg["points_h_theta_deg"]):
        r = ss.med.R + h
        th = math.radians(th_deg)
        e_q, p_q = ss.irradiance(th, r)
        e_mc, se, p_mc = montecarlo.irradiance(th, r, n=int(mc_cfg["n_samples"]),
                                               seed=int(mc_cfg["seed"]) + k, med=ss.med)
        rows.append({"h_km": h, "theta_deg": th_deg, "quadrature": round_sig(e_q),
                     "montecarlo": round_sig(e_mc), "montecarlo_stderr": round_sig(se, 2),
                     "rel_diff": round_sig(e_q / e_mc - 1.0, 3),
                     "psi_quadrature": round_sig(p_q), "psi_montecarlo": round_sig(p_mc)})
        bar.step()
    return rows


def table(spec, v32, p32, err, mc, bound, cfg, med):
    prof = med.profile
    reals = [("w_min", spec.w_min), ("w_max", spec.w_max), ("earth_radius_km", spec.R),
             ("top_km", prof.top_km), ("floor_km", med.h_floor),
             ("theta_scale", (spec.n_theta - 1) / math.pi),
             ("w_scale", (spec.n_alt - 1) / (spec.w_max - spec.w_min)),
             ("q_floor", float(cfg["grid"]["q_floor"]))]
    ints = [("n_theta", spec.n_theta), ("n_alt", spec.n_alt)]
    params = {k: cfg[k] for k in sorted(cfg) if k not in ("name", "description")}
    params["profile"] = {k: getattr(prof, k) for k in (
        "kind", "top_km", "extinction", "cloud_top_km", "ozone_du", "aer_trop_tau",
        "aer_strat_tau")}
    params["scattering"] = {"rayleigh_depolarisation": RHO_N, "aerosol_hg_g": AER_G,
                            "aerosol_omega_trop": AER_OMEGA_TROP,
                            "aerosol_omega_strat": AER_OMEGA_STRAT, "band_groups": N_GROUPS}
    measured = dict(err)
    measured["montecarlo"] = mc
    measured["max_montecarlo_rel_diff"] = round_sig(max(abs(m["rel_diff"]) for m in mc), 3)
    measured["energy_bound_max_ratio"] = round_sig(max(bound))
    prov = [
        "Sunlight scattered by the atmosphere towards a target above it: scalar irradiance",
        "E_sky per unit solar irradiance and its mean direction psi (docs/skylight.md).",
        f"Medium: the refraction table's profile (bake.atmosphere.profile, {prof.kind}), top {prof.top_km:g} km,",
        f"  opaque floor (clouds) at {med.h_floor:g} km; Rayleigh (Bodhaine 1999, depolarisation {RHO_N}),",
        f"  aerosol Henyey-Greenstein g = {AER_G} (omega {AER_OMEGA_TROP} trop., {AER_OMEGA_STRAT} strat.), ozone absorbs;",
        f"  V band (Bessell 1990 x 5772 K) in {N_GROUPS} wavelength groups. Single scattering, point Sun,",
        "  straight rays; lines of sight ending on the sunlit floor left out (earthshine's albedo).",
        f"Grid: theta {spec.n_theta} nodes on [0, pi]; w = acos(R/r) {spec.n_alt} rows on [{spec.w_min:.6f}, pi/2];",
        f"  v = ln(q + {cfg['grid']['q_floor']:g}), q = (E_sky / E_sun) / x^2 (x = R/r); psi (rad, from the nadir",
        "  towards the Sun); float32; Catmull-Rom in both (theta ghosts mirrored, w ghosts linear).",
        f"Measured: lookup vs quadrature at {err['n_points']} random points: max relative error"
        f" {err['max_rel_error']:.3g}",
        f"  where E_sky >= {cfg['goal_floor']:g} of its row's peak (goal {cfg['goal_rel']:g}); quadrature vs Monte Carlo at"
        f" {len(mc)} points:",
        f"  max |relative difference| {measured['max_montecarlo_rel_diff']:.3g}; energy bound ratio <="
        f" {measured['energy_bound_max_ratio']:.3g} (must stay below 1).",
    ]
    grid = dict(ints + reals)
    return cemit.Table(
        name=NAME, kind="skylight", ctype="oi_sky_table", format=("OI_SKY_FORMAT", FORMAT),
        summary="baked scattered-sunlight table (V band): the sunlit atmosphere's light.",
        fields=[(k, v, "int") for k, v in ints] + [(k, v, "real") for k, v in reals],
        arrays=[("v", v32, "float"), ("psi", p32, "float")], layout=LAYOUT,
        generator=GENERATOR, version=__version__, parameters=params,
        seed=int(cfg["measure"]["seed"]), goal=float(cfg["goal_rel"]),
        max_error=err["worst_in_goal_units"], measured=measured, grid=grid, provenance=prov)


def run(outdir, progress=None, log=print, cfg=None, nodes=None):
    """The whole bake into outdir (nodes: (q, psi) node values already computed, for
    tools that vary the storage only)."""
    cfg = cfg or load_config()
    configure(cfg["quadrature"])
    med = Medium()
    ss = single.SingleScattering(med)
    spec = Spec(cfg, med)
    q, psi = nodes if nodes is not None else node_values(spec, ss, progress)
    q_floor = float(cfg["grid"]["q_floor"])
    q32 = cemit.f32(q)
    v32 = stored(q32, q_floor)
    p32 = cemit.f32(psi).ravel()
    qs = q32.astype(float).reshape(q.shape)
    vs = v32.astype(float).reshape(q.shape)
    ps = p32.astype(float).reshape(q.shape)
    m = cfg["measure"]
    err = measure(qs, vs, ps, spec, ss, int(m["n_points"]), int(m["seed"]),
                  float(cfg["goal_rel"]), float(cfg["goal_floor"]), q_floor, progress)
    mc = montecarlo_check(ss, m["montecarlo"], progress)
    bound = energy_bound(qs, spec)
    t = table(spec, v32.ravel(), p32, err, mc, bound, cfg, med)
    paths = cemit.write(outdir, t)
    log("%s: %d bytes, lookup %.3f of the goal, quadrature vs Monte Carlo <= %.3g, energy ratio <= %.3g"
        % (t.name, t.payload_bytes(), t.max_error, t.measured["max_montecarlo_rel_diff"],
           t.measured["energy_bound_max_ratio"]))
    return paths


def load_table(tables_dir="tables"):
    """(v, psi, spec, q_floor) of the committed table, for tests and the report."""
    with open(os.path.join(tables_dir, NAME + ".c"), encoding="ascii") as f:
        parsed = cemit.parse_c(f.read())
    t = parsed["structs"][NAME]["fields"]
    spec = Spec(load_config(), Medium())
    v = parsed["arrays"][NAME + "_v"].astype(float).reshape(t["n_alt"], t["n_theta"])
    psi = parsed["arrays"][NAME + "_psi"].astype(float).reshape(t["n_alt"], t["n_theta"])
    return v, psi, spec, float(t["q_floor"])
