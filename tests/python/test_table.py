# SPDX-License-Identifier: MIT
"""The committed earthshine tables: interpolation error at points between the
nodes (a seed the bake did not use) within the goal, the byte budget, the
altitude range, the sidecar's facts, and why the table runs to infinity."""

import math
import os
import re
import sys

import numpy as np
import pytest

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
sys.path.insert(0, ROOT)

from bake.earthshine import grid, lookup  # noqa: E402
from bake.earthshine import reference as ref  # noqa: E402
from bake.earthshine import scenes as scene  # noqa: E402
from bake.earthshine import table as emit  # noqa: E402

TABLES = os.path.join(ROOT, "tables")


def load_table(name):
    return emit.load(TABLES, name)


@pytest.fixture(scope="module")
def default_table():
    return load_table("oi_earth_diffuse")


def test_format_matches_header(default_table):
    with open(os.path.join(ROOT, "include", "oi_table.h"), encoding="ascii") as f:
        m = re.search(r"#define OI_TABLE_FORMAT (\d+)", f.read())
    assert int(m.group(1)) == emit.TABLE_FORMAT == default_table[3]["format"]


def test_budget_and_range(default_table):
    spec, q, psi, side, _ = default_table
    assert spec.bytes() <= 64 * 1024
    assert side["payload_bytes"] == spec.bytes()
    # the surface (w = 0, the limit row) to infinity
    assert spec.w_min == 0.0
    assert spec.w_max == math.pi / 2
    assert side["grid"]["h_max_km"] is None and side["grid"]["h_min_km"] == 0.0
    # the surface row: lit q0 = 2, G / w = 0; terminator q / w = 2 max(0, -m)
    assert np.all(q[0, :spec.n_lit] == 2.0) and np.all(psi[0, :spec.n_lit] == 0.0)
    t = 2.0 * np.linspace(0, 1, spec.n_term) - 1.0
    m = grid.term_m(t, grid.term_k(spec, 1.0))
    assert np.allclose(q[0, spec.n_lit:], np.where(m < 0, -2.0 * m, 0.0), rtol=1e-7, atol=0)


def test_sidecar_facts(default_table):
    spec, q, psi, side, c = default_table
    assert side["payload_sha256"] == emit.payload_sha256(q, psi)
    assert side["payload_sha256"] in c
    g = side["grid"]
    assert (g["n_lit"], g["n_term"], g["n_alt"]) == (spec.n_lit, spec.n_term, spec.n_alt)
    assert side["measured"]["max_score"] <= 1.0
    assert side["measured"]["max_rel_err"] <= 1e-3
    assert not re.search(r"20\d\d-\d\d-\d\d", c)  # no timestamp


def _check_error(spec, q, psi, n, seed, rel_goal=1e-3):
    rng = np.random.default_rng(seed)
    w_lo = max(spec.w_min, float(grid.w_from_h(1e-3)))  # from 1 m
    w = rng.uniform(w_lo, min(spec.w_max, math.pi / 2 - 1e-7), n)
    th = rng.uniform(0, math.pi, n)
    # plus a band around the terminator, where tables are worst
    w2 = rng.uniform(w_lo, min(spec.w_max, math.pi / 2 - 1e-7), n)
    th2 = math.pi / 2 + rng.uniform(-1, 1, n) * w2
    w = np.concatenate([w, w2])
    th = np.concatenate([th, th2])
    if spec.w_min == 0.0:  # near the surface: log-uniform 1 m .. 100 km
        w3 = grid.w_from_h(10 ** rng.uniform(-3.0, 2.0, n))
        th3 = math.pi / 2 + rng.uniform(-1, 1, n) * w3
        th4 = np.arccos(10 ** rng.uniform(-2.5, -1.0, n))  # the lit side's 1% contour
        w = np.concatenate([w, w3, w3])
        th = np.concatenate([th, th3, np.minimum(th4, math.pi / 2 - w3)])
    x = np.cos(w)
    phi_r, psi_r = ref.phi_psi_reference(th, x, 32, 32)
    phi0 = ref.phi_reference(np.zeros_like(x), x, 32, 32)
    phi_i, psi_i = lookup.lookup(spec, q.astype(float), psi.astype(float), th, x)
    s, big = lookup.goal_score(phi_i, phi_r, phi0, rel_goal=rel_goal)
    return s, big, np.abs(psi_i - psi_r)


def test_interpolation_error_default(default_table):
    """Off-node points (seed not used by the bake) meet the goal."""
    spec, q, psi, _, _ = default_table
    s, big, dpsi = _check_error(spec, q, psi, 3000, 987)
    assert s.max() <= 1.0, s.max()
    assert dpsi[big].max() <= 1e-3


@pytest.mark.parametrize("name", ["oi_earth_leo", "oi_earth_geo"])
def test_scene_tables(name):
    spec, q, psi, side, _ = load_table(name)
    cfg = scene.load(os.path.join(ROOT, "bake", "config", "scene_%s.json" % name.split("_")[-1]))
    w_lo, w_hi, _, _ = scene.band(cfg)
    assert spec.w_min == pytest.approx(w_lo) and spec.w_max == pytest.approx(w_hi)
    assert spec.bytes() < load_table("oi_earth_diffuse")[0].bytes()
    s, big, dpsi = _check_error(spec, q, psi, 1000, 4321, cfg["rel_goal"])
    assert s.max() <= 1.0, s.max()
    assert dpsi[big].max() <= cfg["psi_goal_rad"]


def test_low_altitude_named(default_table):
    """1 m, 1 km, 10 km, 50 km, 99 km: the goal over theta, dense across the
    terminator band (the first grid cells and the nadir crossing)."""
    spec, q, psi, _, _ = default_table
    for hk in (1e-3, 1.0, 10.0, 50.0, 99.0):
        x = float(ref.x_from_h(hk))
        w = float(grid.w_from_h(hk))
        th = np.concatenate([np.linspace(0, math.pi / 2 - w, 40),
                             math.pi / 2 + w * np.linspace(-1, 1, 201)])
        phi_r, psi_r = ref.phi_psi_reference_h(th, hk / ref.R_EARTH_KM, 32, 32)
        phi0 = ref.phi_psi_reference_h(0.0, hk / ref.R_EARTH_KM, 32, 32)[0]
        phi_i, psi_i = lookup.lookup(spec, q.astype(float), psi.astype(float), th, np.full_like(th, x))
        s, big = lookup.goal_score(phi_i, phi_r, phi0)
        assert s.max() <= 1.0, (hk, s.max())
        assert np.abs(psi_i - psi_r)[big].max() <= 1e-3, hk


def test_lit_segment_exact_in_theta():
    """Format 4 stores the lit segment as phi(0, x) and G(x): exact because
    phi(theta) = cos(theta) phi(0) and tan psi = tan(theta) G while the whole
    visible cap is lit (checked on the reference)."""
    for hk in (1e-3, 5.0, 400.0, 36000.0):
        x = float(ref.x_from_h(hk))
        w = float(grid.w_from_h(hk))
        th = np.linspace(0.05, math.pi / 2 - w, 7)
        phi, ps = ref.phi_psi_reference(th, x)
        phi0 = float(ref.phi_reference(0.0, x))
        assert np.allclose(phi, np.cos(th) * phi0, rtol=1e-11, atol=0), hk
        g = np.tan(ps) / np.tan(th)
        assert np.allclose(g, g[3], rtol=1e-8, atol=1e-300), hk


def test_interpolation_is_cubic():
    """Measured convergence: doubling the resolution of a table cuts its
    error by about 2^3 or more (Catmull-Rom), so resolution buys accuracy."""
    w0 = float(grid.w_from_h(2000.0))
    w1 = float(grid.w_from_h(20000.0))
    errs = []
    for n in (9, 17):
        spec = grid.TableSpec(n, 2 * n - 1, n, w0, w1)
        q, psi = grid.node_values(spec, order=24, progress=False)
        s, big, _ = _check_error(spec, q, psi, 400, 55)
        errs.append(s.max())
    assert errs[1] < errs[0] / 6, errs


def test_far_field_fails_at_lunar_distance():
    """Why the table runs to infinity: the Lambert far field x^2 p(theta) is
    not within the goal even at the Moon's distance (error ~7x relative at the
    1% contour), so it cannot replace the table beyond some altitude."""
    x = float(ref.x_from_h(384400.0))
    th = np.linspace(0, math.pi, 2001)
    phi = ref.phi_reference(th, x, 32, 32)
    s, _ = lookup.goal_score(ref.far_field(th, x), phi, phi[0])
    assert s.max() > 50
