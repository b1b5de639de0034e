# SPDX-License-Identifier: MIT
"""Photon mapping through the shells with directions (bake.photon.atmosphere) against
the deterministic reference through the same shells (bake.atmosphere.rays): two
independent algorithms (Monte Carlo vector-Snell tracing vs quadrature of
the flux-conservation integral)."""
import numpy as np

from bake.atmosphere import profile as ap
from bake.atmosphere import rays as ar
from bake.photon import atmosphere as ph


def test_photon_map_matches_reference_through_same_shells():
    prof = ap.seed_mode()
    R = prof.earth_radius_km
    z = 42164.0
    edges = np.linspace(R - 1100.0, R + 250.0, 28)
    mid = 0.5 * (edges[1:] + edges[:-1])
    n = 200000
    F, psi, _ = ph.photon_fraction(prof, 100, z, edges, n, seed=3)
    # ring averages of the reference
    sub = np.linspace(0, 1, 9)[1:-1]
    pts = (edges[:-1, None] + np.diff(edges)[:, None] * sub[None, :])
    Fr, pr = ar.fraction(ph.shell_rays(prof, 100), z, pts.ravel())
    Fr = Fr.reshape(pts.shape)
    Fref = np.sum(Fr * pts, 1) / np.sum(pts, 1)
    # Poisson noise of each ring: F / sqrt(count)
    b_max = edges[-1] / (1 + z / ar.AU_KM) + z * ar.SUN_RADIUS_KM / ar.AU_KM + 50.0
    ring = np.pi * np.diff(edges ** 2)
    counts = F * n * ring / (np.pi * (b_max ** 2 - R ** 2)) / (1 + z / ar.AU_KM) ** 2
    sigma = Fref / np.sqrt(np.maximum(counts, 1.0))
    ok = counts > 50
    # 3.5 sigma: the same-shell reference passes (max 1.9 sigma with this seed), the
    # continuous profile would not (4.1 sigma): the test sees the shells
    assert np.all(np.abs(F - Fref)[ok] < 3.5 * sigma[ok]), np.c_[mid - R, F, Fref, sigma][ok]
    # directions: the photons' recorded directions give the reference's psi
    Pr = np.sum(pr.reshape(pts.shape) * Fr * pts, 1) / np.sum(Fr * pts, 1)
    lit = Fref > 1e-2
    assert np.all(np.abs(psi - Pr)[lit] < np.radians(0.02)), np.degrees(np.c_[psi, Pr][lit])


def test_photon_error_falls_with_photons():
    prof = ap.seed_mode()
    R = prof.earth_radius_km
    edges = np.linspace(R - 600.0, R + 200.0, 17)
    F1, _, _ = ph.photon_fraction(prof, 50, 42164.0, edges, 20000, seed=5)
    F2, _, _ = ph.photon_fraction(prof, 50, 42164.0, edges, 320000, seed=6)
    mid = 0.5 * (edges[1:] + edges[:-1])
    Fr, _ = ar.fraction(ph.shell_rays(prof, 50), 42164.0, mid, want_psi=False)
    e1 = np.sqrt(np.mean((F1 - Fr) ** 2))
    e2 = np.sqrt(np.mean((F2 - Fr) ** 2))
    assert e2 < e1   # 16x photons: ~4x smaller noise (ring-centre sampling adds a floor)
