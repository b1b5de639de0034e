# SPDX-License-Identifier: MIT
"""Photon mapping of sunlight through the seed's nested shells, with directions.

The seed's refracted photons were stored without direction and never
gathered (its chapter V). Here each photon keeps its direction: photons are
launched from random points of the limb-darkened solar disc towards random
points of the annulus R < b < B_max around the Earth, traced through the
constant-index shells by `bake.photon.shells.trace` (vector Snell, seed IV.1.1), and
followed along their recorded exit direction to the plane z km behind the
Earth, where they are binned in rings about the shadow axis: the photon
estimate of F(z, rho) and of the light's mean direction psi.

The deterministic reference through the *same* shells (`bake.atmosphere.rays.fraction`
with the shell bending) isolates the Monte Carlo noise; the continuous
profile shows the shells' own bias (see docs/atmosphere.md). Seed mode:
refraction only.
"""
from __future__ import annotations

import time

import numpy as np

from ..atmosphere import profile as ap
from ..atmosphere import rays as ar
from . import shells


def _sample_disc_ld(rng, n, law=ar.NL94_559):
    """n points on the unit solar disc distributed as the limb-darkened
    intensity (rejection sampling; I(mu) <= I(1) = 1)."""
    out = np.empty((0, 2))
    while out.shape[0] < n:
        m = 2 * (n - out.shape[0]) + 16
        r = np.sqrt(rng.uniform(0, 1, m))
        t = rng.uniform(0, 2 * np.pi, m)
        mu = np.sqrt(1 - r * r)
        keep = rng.uniform(0, 1, m) < np.polynomial.polynomial.polyval(mu, law)
        out = np.vstack([out, np.stack([r * np.cos(t), r * np.sin(t)], 1)[keep]])
    return out[:n]


def photon_fraction(profile: ap.Profile, n_shells: int, z: float, rho_edges, n_photons: int,
                    seed: int = 1, d_sun: float = ar.AU_KM, chunk: int = 50000):
    """Photon estimate of the fraction of sunlight and of psi in rings
    rho_edges (km) at z km behind the Earth. Returns (F, psi, seconds)."""
    t0 = time.perf_counter()
    rng = np.random.default_rng(seed)
    R = profile.earth_radius_km
    radii, idx = ar.shell_model(profile, n_shells)
    atm = shells.Atmosphere(R, radii[1:], idx)
    a = z * ar.SUN_RADIUS_KM / d_sun
    b_max = rho_edges[-1] / (1 + z / d_sun) + a + 50.0
    counts = np.zeros(len(rho_edges) - 1)
    sum_x = np.zeros_like(counts)
    done = 0
    while done < n_photons:
        n = min(chunk, n_photons - done)
        done += n
        # impact point uniform in area over the annulus R < b < b_max
        b = np.sqrt(rng.uniform(R * R, b_max * b_max, n))
        phi = rng.uniform(0, 2 * np.pi, n)
        e = _sample_disc_ld(rng, n) * (ar.SUN_RADIUS_KM / d_sun)   # offset of the emitting point (rad)
        # trace in the ray's own plane (spherical symmetry): start far in front,
        # moving along +x with impact parameter b, diverging by b/d from the Q-axis
        x0 = -2.0 * radii[-1]
        beta = b / d_sun
        org = np.stack([np.full(n, x0), b + x0 * np.tan(beta), np.zeros(n)], 1)
        dirs = np.stack([np.cos(beta), np.sin(beta), np.zeros(n)], 1)
        res = shells.trace(org, dirs, atm)
        ok = res.status == shells.ESCAPED
        # exit line: position p, direction u (in the ray plane: x along the axis, y outwards)
        p, u = res.pos[ok], res.dir[ok]
        s = (z - p[:, 0]) / u[:, 0]
        y = p[:, 1] + s * u[:, 1]                  # signed distance from the Q-axis at z
        g = -np.arctan2(u[:, 1], u[:, 0])          # net turn towards the axis
        ph = phi[ok]
        xq = np.stack([y * np.cos(ph), y * np.sin(ph)], 1)
        xs = xq - z * e[ok]                          # relative to the Sun-Earth axis
        rr = np.hypot(xs[:, 0], xs[:, 1])
        k = np.searchsorted(rho_edges, rr) - 1
        inb = (k >= 0) & (k < counts.size)
        np.add.at(counts, k[inb], 1.0)
        # mean 'from' direction (as bake.atmosphere.rays.fraction): transverse part along
        # the point's radial unit vector, minus that of the Sun's centre
        rhat = xs / np.maximum(rr, 1e-9)[:, None]
        ephi_r = np.cos(ph) * rhat[:, 0] + np.sin(ph) * rhat[:, 1]
        fx = (xq[:, 0] * rhat[:, 0] + xq[:, 1] * rhat[:, 1]) / z + g * ephi_r \
            - rr * d_sun / (z * (d_sun + z))
        np.add.at(sum_x, k[inb], fx[inb])
    area_b = np.pi * (b_max ** 2 - R ** 2)
    ring = np.pi * np.diff(np.asarray(rho_edges) ** 2)
    F = counts / n_photons * area_b / ring * (1 + z / d_sun) ** 2
    psi = np.where(counts > 0, sum_x / np.maximum(counts, 1), 0.0)
    return F, psi, time.perf_counter() - t0


def shell_rays(profile: ap.Profile, n_shells: int, dh: float = 0.005):
    """Deterministic 'Rays' through the same shells (impact parameter grid)."""
    radii, idx = ar.shell_model(profile, n_shells)
    R = profile.earth_radius_km
    b = R + np.arange(0.0, profile.top_km + dh / 2, dh)
    alpha, hits = ar.shell_bending(radii, idx, b)
    return ar.Rays(profile, b - R, b, alpha, np.zeros((4, b.size)), np.where(hits, 0.0, 1.0), R)


def convergence(n_shells=100, z=42164.0, photons=(10000, 30000, 100000, 300000), seed=1):
    """Error of the photon map against the deterministic reference through the
    same shells, versus the number of photons and the time taken."""
    prof = ap.seed_mode()
    R = prof.earth_radius_km
    edges = np.linspace(R - 1100.0, R + 250.0, 28)
    mid = 0.5 * (edges[1:] + edges[:-1])
    srays = shell_rays(prof, n_shells)
    # ring averages of the reference (5 points per ring)
    sub = np.linspace(0, 1, 7)[1:-1]
    pts = (edges[:-1, None] + np.diff(edges)[:, None] * sub[None, :]).ravel()
    wts = pts.reshape(-1, sub.size)
    Fref = ar.fraction(srays, z, pts, want_psi=False)[0].reshape(-1, sub.size)
    Fref = np.sum(Fref * wts, 1) / np.sum(wts, 1)
    cont = ar.make_rays(prof, dh_km=0.02)
    Fc = ar.fraction(cont, z, pts, want_psi=False)[0].reshape(-1, sub.size)
    Fc = np.sum(Fc * wts, 1) / np.sum(wts, 1)
    rows = []
    last = None
    for n in photons:
        F, psi, dt = photon_fraction(prof, n_shells, z, edges, n, seed=seed)
        rows.append((n, dt, float(np.sqrt(np.mean((F - Fref) ** 2))), float(np.max(np.abs(F - Fref)))))
        last = F
    return {"edges": edges, "mid": mid, "F_ref_shells": Fref, "F_continuous": Fc,
            "F_photon": last, "rows": rows, "n_shells": n_shells, "z": z}
