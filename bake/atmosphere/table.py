# SPDX-License-Identifier: MIT
"""The atmosphere table: bake the node values, quantise, measure, emit.

The family's steps: spec from bake/config/atmosphere.json (window.py), node
values from the ray reference (rays.py, `fraction`), 16-bit codes
(quantise.py), the lookup mirror and its measured error (window.py,
measure.py), the Table of the one emitter (bake/common/emit.py) with every
constant the runtime needs, derived ones included (e_mid, c_iu, ln10,
correctly rounded with mpmath).
"""
from __future__ import annotations

import os

import mpmath
import numpy as np

from .. import __version__
from ..common import emit as cemit
from ..common.constants import AU_KM, SUN_RADIUS_KM
from ..common.emit import round_sig
from ..common.progress import Progress
from . import profile as ap
from . import rays as ar
from .measure import measure
from .quantise import quantise
from .window import (ALPHA_C, ALPHA_C_REL_TOL, F_FLOOR, H_A, NA, NB, ND, NT, NZ, V_MID,
                     W_RHO, Z_MAX, Z_MIN, Window, grid_d, grid_z, load_config)

CFG = load_config()
MEASURE_SEED = int(CFG["measure"]["seed"])


def reach(rays: ar.Rays) -> float:
    """Bending of the lowest unblocked ray (rad), as the reference computes it."""
    return float(rays.alpha[0])


def bake(rays: ar.Rays, progress=False, law=ar.NL94_559, label="atmosphere"):
    """q (ND, NZ, NT), psi (ND, NZ, NT), alpha_c, h_c. alpha_c is the
    configured grid constant; it must agree with the reference's bending."""
    computed = reach(rays)
    if not abs(computed - ALPHA_C) <= ALPHA_C_REL_TOL * ALPHA_C:
        raise RuntimeError("the reference's bending at the cloud top, %.17g rad, differs from "
                           "the grid's alpha_c_rad = %.17g by more than %g relative: the profile "
                           "changed; update bake/config/atmosphere.json" % (
                               computed, ALPHA_C, ALPHA_C_REL_TOL))
    alpha_c = ALPHA_C
    h_c = float(rays.h0[0])
    zs, ds = grid_z(), grid_d()
    q = np.empty((ND, NZ, NT))
    psi = np.empty((ND, NZ, NT))
    bar = Progress(ND * NZ, label + ": rows", progress)
    for k, d in enumerate(ds):
        for i, z in enumerate(zs):
            rho = Window(z, d, alpha_c, h_c).nodes()
            F, p = ar.fraction(rays, z, rho, d_sun=d, law=law)
            q[k, i] = np.log10(F + F_FLOOR)
            psi[k, i] = p
            bar.step()
    return q, psi, alpha_c, h_c


NAME = "oi_atm_vband"
# The bands (profile.band) and the table of each: its name, its solar disc
# (limb-darkening law, rays.py), and the text of its provenance.
BANDS = {
    "V": dict(name=NAME, law=ar.NL94_559,
              summary="baked atmosphere table (V band): sunlight refracted into the shadow.",
              band_text="  V band (Bessell 1990) x 5772 K black body;",
              disc_text="  solar disc: Neckel & Labs (1994) limb darkening at 559.95 nm."),
    "total": dict(name="oi_atm_total", law=ar.EDDINGTON,
                  summary="baked atmosphere table (total solar irradiance): sunlight refracted "
                          "into the shadow.",
                  band_text="  total solar irradiance: 5772 K black body, 350-4000 nm (Rayleigh beyond "
                            "1 um as lambda^-4);",
                  disc_text="  solar disc: Eddington grey-atmosphere limb darkening (2 + 3 mu) / 5."),
}
NAMES = tuple(b["name"] for b in BANDS.values())
TABLE_FORMAT = 3         # OI_ATM_FORMAT in include/oi_table.h
GENERATOR = "bake.atmosphere"
GOAL_ABS_F = float(CFG["goal_abs_f"])  # goal: max |F error| of the lookup (absolute fraction)
LAYOUT = ("format", "kind", "info", "nz", "nt", "na", "nb", "z_min_km", "z_max_km", "h_a_km",
          "v_mid_km", "alpha_c_rad", "h_c_km", "top_km", "w_rho", "f_floor", "earth_radius_km",
          "sun_radius_km", "au_km", "q_min", "q_scale", "psi_min_rad", "psi_scale_rad", "e_mid",
          "c_iu", "ln10", "q", "psi")


def derived_constants(nz, z_min, z_max, v_mid, h_c, h_a):
    """e_mid, c_iu, ln10 correctly rounded (mpmath at 200 bits from the exact
    doubles): their printed value does not depend on any libm."""
    with mpmath.workprec(200):
        e_mid = mpmath.exp(-(mpmath.mpf(v_mid) - mpmath.mpf(h_c)) / mpmath.mpf(h_a))
        c_iu = mpmath.mpf(nz - 1) / mpmath.log(mpmath.mpf(z_max) / mpmath.mpf(z_min))
        ln10 = mpmath.log(10)
        return float(e_mid), float(c_iu), float(ln10)


def table(uq, up, scales, alpha_c, h_c, err, profile: ap.Profile, alpha_c_computed=None):
    band = BANDS[profile.band]
    """The Table of the atmosphere bake (bake/common/emit.py)."""
    uq, up = uq[0], up[0]
    e_mid, c_iu, ln10 = derived_constants(NZ, Z_MIN, Z_MAX, V_MID, h_c, H_A)
    reals = [
        ("z_min_km", Z_MIN), ("z_max_km", Z_MAX), ("h_a_km", H_A), ("v_mid_km", V_MID),
        ("alpha_c_rad", alpha_c), ("h_c_km", h_c), ("top_km", profile.top_km), ("w_rho", W_RHO),
        ("f_floor", F_FLOOR), ("earth_radius_km", profile.earth_radius_km),
        ("sun_radius_km", SUN_RADIUS_KM), ("au_km", AU_KM),
        ("q_min", scales["Q_MIN"]), ("q_scale", scales["Q_SCALE"]),
        ("psi_min_rad", scales["PSI_MIN"]), ("psi_scale_rad", scales["PSI_SCALE"]),
        ("e_mid", e_mid), ("c_iu", c_iu), ("ln10", ln10)]
    ints = [("nz", NZ), ("nt", NT), ("na", NA), ("nb", NB)]
    prof = {k: getattr(profile, k) for k in (
        "kind", "n0", "top_km", "extinction", "cloud_top_km", "cloud_fraction", "ozone_du",
        "aer_trop_tau", "aer_strat_tau")}
    params = {k: CFG[k] for k in sorted(CFG) if k not in ("name", "description")}
    if profile.band != "V":
        prof["band"] = profile.band
    params["profile"] = prof
    if alpha_c_computed is not None:
        err = dict(err, alpha_c_computed_rad=round_sig(alpha_c_computed, 10))
    prov = [
        "Sunlight through the atmosphere into the Earth's shadow: fraction F of",
        "unobstructed sunlight and its mean direction psi (docs/atmosphere.md).",
        f"Profile: {profile.kind} (1976 U.S. Standard Atmosphere density, N_s = {profile.n0:.6g} at 550 nm),",
        f"  top {profile.top_km:g} km; extinction {'on' if profile.extinction else 'off'}: Rayleigh (Bodhaine 1999),",
        f"  ozone {profile.ozone_du:g} DU (Chappuis), aerosol tau {profile.aer_trop_tau:g} (trop.) +"
        f" {profile.aer_strat_tau:g} (strat.) at 550 nm;",
        f"  clouds below {profile.cloud_top_km:g} km stop a fraction {profile.cloud_fraction:g} of the rays"
        " (global cloud amount, Stubenrauch et al. 2013);",
        band["band_text"],
        band["disc_text"],
        f"Grid: z = {Z_MIN:g} .. {Z_MAX:g} km behind the Earth's centre, {NZ} rows log-spaced;",
        f"  along rho {NT} nodes: {NA} uniform in a blend ({1 - W_RHO:g} : {W_RHO:g}) of the model ray altitude",
        f"  v (h_a = {H_A:g} km, alpha_c = {alpha_c:.9g} rad at h_c = {h_c:g} km) and rho, up to",
        f"  v = {V_MID:g} km, then {NB} uniform in rho up to rc + a + top; the Sun's distance",
        "  enters through the window (table baked at 1 AU).",
        "Values: q = log10(F + f_floor), psi (rad): mean direction of the light from the Sun's centre,",
        "  positive away from the Earth's centre; stored as 16-bit codes, value = min + scale * code",
        "  (q step 1.2e-4 dex, i.e. 2.8e-4 relative in F).",
        f"Measured against the ray reference at {err['n_points']} random off-grid points (seed {MEASURE_SEED},",
        "  z log-uniform, rho uniform along the nodes, d in [0.9832, 1.0168] AU), bilinear lookup:",
        f"  max |F error| {err['max_abs_error']:.3e} (goal {GOAL_ABS_F:g}), rms {err['rms_abs_error']:.3e},",
        f"  max relative error where F > 1e-4: {err['max_rel_error_F_gt_1e-4']:.3e},",
        f"  max psi error where F > 1e-3: {err['max_psi_error_rad_F_gt_1e-3']:.3e} rad.",
    ]
    grid = dict(ints + reals[:12])
    t = cemit.Table(
        name=band["name"], kind="atmosphere", ctype="oi_atm_table",
        format=("OI_ATM_FORMAT", TABLE_FORMAT), summary=band["summary"],
        fields=[(k, v, "int") for k, v in ints] + [(k, v, "real") for k, v in reals],
        arrays=[("q", uq, "u16"), ("psi", up, "u16")], layout=LAYOUT,
        generator=GENERATOR, version=__version__, parameters=params, seed=MEASURE_SEED,
        goal=GOAL_ABS_F, max_error=cemit.round_sig(err["max_abs_error"] / GOAL_ABS_F),
        measured=err, grid=grid, provenance=prov)
    return t


def write(outdir, t):
    """Write outdir/<name>.{c,h,json}."""
    return cemit.write(outdir, t)


def run_band(outdir, band="V", progress=None, log=print):
    """One band's bake into outdir; returns the paths written."""
    prof = ap.us1976(band=band)
    law = BANDS[band]["law"]
    rays = ar.make_rays(prof)
    q, psi, alpha_c, h_c = bake(rays, progress=progress, law=law, label=BANDS[band]["name"])
    uq, up, q, psi, scales = quantise(q, psi)     # measure what the runtime stores
    err, _ = measure(rays, q, psi, alpha_c, h_c, n=int(CFG["measure"]["n_points"]),
                     seed=MEASURE_SEED, progress=progress, law=law)
    t = table(uq, up, scales, alpha_c, h_c, err, prof, alpha_c_computed=reach(rays))
    paths = write(outdir, t)
    log("%s: %d bytes, max |dF| %.3e (%.3f of the goal)" % (
        t.name, t.payload_bytes(), err["max_abs_error"], t.max_error))
    return paths


def run(outdir, progress=None, log=print, bands=tuple(BANDS)):
    """The whole bake (every band) into outdir; returns the paths written."""
    paths = []
    for band in bands:
        paths += list(run_band(outdir, band, progress=progress, log=log))
    return paths


def load_table(tables_dir="tables", name=NAME):
    """Read a committed table back from its generated C source: (q, psi,
    alpha_c, h_c) decoded, shaped (1, NZ, NT), for the Python mirror."""
    with open(os.path.join(tables_dir, name + ".c"), encoding="ascii") as f:
        parsed = cemit.parse_c(f.read())
    t = parsed["structs"][name]["fields"]
    nz, nt = t["nz"], t["nt"]
    q = t["q_min"] + t["q_scale"] * parsed["arrays"][name + "_q"].astype(float)
    psi = t["psi_min_rad"] + t["psi_scale_rad"] * parsed["arrays"][name + "_psi"].astype(float)
    return q.reshape(1, nz, nt), psi.reshape(1, nz, nt), t["alpha_c_rad"], t["h_c_km"]
