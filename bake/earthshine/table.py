# SPDX-License-Identifier: MIT
"""The earthshine table as a Table of the one emitter (bake/common/emit.py)."""

import math

from .. import __version__
from ..common import emit as cemit
from ..common.emit import c_double, c_float, f32  # noqa: F401  (re-exported)

TABLE_FORMAT = 4  # OI_TABLE_FORMAT in include/oi_table.h
GENERATOR = "bake.earthshine"

LAYOUT = ("format", "n_lit", "n_term", "n_alt", "w_min", "w_max", "term_k0", "term_kp",
          "max_rel_err", "max_abs_err", "q", "psi", "kind", "info")


def _fmt_h(h):
    return "infinity" if h == math.inf else "%.6g km" % h


def provenance_lines(meta):
    """Human-readable provenance (the same facts as the JSON sidecar)."""
    g = meta["grid"]
    m = meta["measured"]
    return [
        "Diffuse earthshine of a uniform Lambertian Earth without atmosphere, per",
        "unit albedo and unit solar irradiance (docs/physics.md, earthshine).",
        "Stored (format %d, include/oi_table.h): lit segment phi(0, x) / x^2 and G / w" % TABLE_FORMAT,
        "  (phi = cos(theta) phi(0, x), tan psi = tan(theta) G exactly there);",
        "  terminator segment phi / (x^2 w) and psi (rad); float32.",
        "Method: %s%s." % (meta["method"], meta.get("method_detail", "")),
        "Grid: n_lit = %d, n_term = %d, n_alt = %d (%d values per quantity)," % (
            g["n_lit"], g["n_term"], g["n_alt"], g["n_values"]),
        "  w = acos(R/r) in [%s, %s] rad, uniform%s;" % (
            c_double(g["w_min"]), c_double(g["w_max"]),
            " (w = 0: the surface limit row)" if g["w_min"] == 0.0 else ""),
        "  terminator map k = %s x^%s." % (c_double(g["term_k0"]), c_double(g["term_kp"])),
        "Validity: altitude from %s to %s (R = %s km; scale-free in R/r)," % (
            _fmt_h(meta["h_min_km"]) if meta["h_min_km"] > 0 else "the surface (h > 0)",
            _fmt_h(meta["h_max_km"]), "%.6f" % meta["radius_km"]),
        "  theta in [0, pi]; outside the altitude range the runtime uses the",
        "  Lambert far field and returns OI_WARN_TABLE_RANGE.",
        "Goal: relative error <= %g where phi >= 1%% of phi(0, x), absolute" % meta["rel_goal"],
        "  error <= %g phi(0, x) elsewhere." % (meta["rel_goal"] * 0.01),
        "Measured against the quadrature reference (order %d Gauss-Legendre) at %d points" % (
            m["reference_order"], m["n_points"]),
        "  between the nodes from h = %s up (all cell centres, random, seed %d):" % (
            _fmt_h(max(meta["h_min_km"], m.get("h_measure_min_km", 0.0))), m["seed"]),
        "  max relative error (phi >= 1%% phi0)  %.3e" % m["max_rel_err"],
        "  max absolute error / phi0 (elsewhere) %.3e" % m["max_abs_err_frac"],
        "  max error in units of the goal        %.3f" % m["max_score"],
        "  max psi error (phi >= 1%% phi0)       %.3e rad" % m["max_psi_err_rad"],
    ]


def table(name, spec, q, psi, meta):
    """The Table of one earthshine bake (meta: see bake/earthshine/scenes.py)."""
    q32 = f32(q)
    p32 = f32(psi)
    if q32.shape != (spec.n_alt, spec.n_theta) or p32.shape != q32.shape:
        raise ValueError("table shape mismatch")
    m = meta["measured"]
    grid = dict(meta["grid"])
    grid.update(h_min_km=meta["h_min_km"],
                h_max_km=None if meta["h_max_km"] == math.inf else meta["h_max_km"],
                radius_km=meta["radius_km"])
    params = dict(meta["parameters"])
    params["method"] = meta["method"]
    return cemit.Table(
        name=name, kind="earthshine", ctype="oi_earth_table",
        format=("OI_TABLE_FORMAT", TABLE_FORMAT),
        summary="baked earthshine table, %s to %s." % (
            "the surface" if meta["h_min_km"] == 0 else _fmt_h(meta["h_min_km"]),
            _fmt_h(meta["h_max_km"])),
        fields=[("n_lit", spec.n_lit, "int"), ("n_term", spec.n_term, "int"),
                ("n_alt", spec.n_alt, "int"), ("w_min", spec.w_min, "double"),
                ("w_max", spec.w_max, "double"), ("term_k0", spec.term_k0, "double"),
                ("term_kp", spec.term_kp, "double"), ("max_rel_err", m["max_rel_err"], "err"),
                ("max_abs_err", m["max_abs_err_frac"], "err")],
        arrays=[("q", q32, "float"), ("psi", p32, "float")],
        layout=LAYOUT, generator=GENERATOR, version=__version__, parameters=params,
        seed=m["seed"], goal=meta["rel_goal"], max_error=m["max_score"], measured=m,
        grid=grid, provenance=provenance_lines(meta))


def render(name, spec, q, psi, meta):
    """(c_text, h_text, json_text)."""
    return cemit.render(table(name, spec, q, psi, meta))


def write(outdir, name, spec, q, psi, meta):
    """Write outdir/name.{c,h,json}; returns the three paths."""
    return cemit.write(outdir, table(name, spec, q, psi, meta))


def payload_sha256(q, psi):
    import hashlib
    h = hashlib.sha256()
    h.update(f32(q).astype("<f4").tobytes())
    h.update(f32(psi).astype("<f4").tobytes())
    return h.hexdigest()


def load(tables_dir, name):
    """A committed earthshine table read back from its generated C (the
    one parse-back, bake/common/emit.py): (spec, q, psi, sidecar, c_text),
    q and psi float32 shaped (n_alt, n_theta)."""
    import json
    import os

    from .grid import TableSpec
    with open(os.path.join(tables_dir, name + ".c"), encoding="ascii") as f:
        c = f.read()
    with open(os.path.join(tables_dir, name + ".json"), encoding="ascii") as f:
        side = json.load(f)
    parsed = cemit.parse_c(c)
    t = parsed["structs"][name]["fields"]
    spec = TableSpec(t["n_lit"], t["n_term"], t["n_alt"], t["w_min"], t["w_max"],
                     t["term_k0"], t["term_kp"])
    q = parsed["arrays"][name + "_q"].reshape(spec.n_alt, spec.n_theta)
    psi = parsed["arrays"][name + "_psi"].reshape(spec.n_alt, spec.n_theta)
    return spec, q, psi, side, c
