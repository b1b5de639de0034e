# SPDX-License-Identifier: MIT
"""The seed's photon mapper (Penney 2009, III.3.4 and IV.1), errata fixed.

Pass 1, photon map: rays from random points of the solar disc (radius
695700 km at 1 AU) to random points of a disc through the Earth's centre,
facing the Sun, 2% larger than the outermost shell; each photon carries
power E0 * pi rho_d^2 / N (E0 = 1: everything is per unit solar irradiance).
Photons are traced through the shells (bake.photon.shells); at the Earth they are
reflected with the Lambertian COSINE distribution (seed IV.1.1 says uniform
over a sphere: erratum) and traced out again. Power is per unit albedo (the
albedo multiplies the map at run time). Two maps indexed by theta, the angle
from the Sun axis at the Earth's centre, in uniform bins on [0, pi]:
  reflected   exitance of the reflected light where it leaves the outermost
              shell (the seed's map; on the Earth itself if there are no
              shells), power / band area, band area 2 pi rho^2 (cos t_i -
              cos t_{i+1}) (seed eq. 3.8 has pi and the opposite sign);
  transmitted flux density of light that crossed the atmosphere without
              touching the Earth, by exit point (the seed's second map;
              without directions, as in the seed: not gathered here).
A third map, `surface`, is the exitance at the reflection points on the
ground (the Lambertian source itself), used by the "surface" gathering.

Pass 2, final gathering from each table point P (theta, r): directions
towards the Earth, parametrised by the impact parameter b = r sin(gamma)
(gamma from the nadir) and the azimuth beta around the nadir, b = b_max
(1 - s^2) with Gauss-Legendre nodes in s (smooth at the limb) and midpoints in
beta on [0, pi] (mirror symmetry of the Sun-Earth-P plane), solid angle
dOmega = b db dbeta / (r sqrt(r^2 - b^2)). Radiance per gathering ray:
  mode "shell"   (seed): the ray goes straight to the outermost shell and
                 reads L = M_reflected(theta_hit) / pi, i.e. treats the shell
                 as a Lambertian emitter. Exact without shells; with shells
                 it misplaces light near the limb (measured in the report);
  mode "surface": the ray is traced back through the shells to the ground
                 and reads L = M_surface(theta_hit) / (pi n1^2) (radiance
                 invariance L/n^2 along a ray, n1 the ground shell's index).
                 Exact for any shell stack up to noise and bin width.
phi = sum L dOmega is the scalar irradiance per unit E0 and unit albedo
(docs/physics.md, earthshine): no division by 4 pi h^2 (seed IV.1.2 erratum), and no
2 pi d^2 calibration (seed eq. 3.7 erratum): each photon already carries
its share of E0 times the disc area. psi is the angle of the net flux vector
sum L d dOmega from the nadir towards the Sun side.

Everything is vectorised over photons and gathering rays (chunks of fixed
size, so results depend only on (n_photons, seed, parameters)).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..common.constants import AU_KM, SUN_RADIUS_KM
from .shells import ESCAPED, HIT_EARTH, TRAPPED, Atmosphere, lambert_directions, trace

__all__ = [
    "PhotonMaps",
    "photon_map",
    "gather",
    "gather_function",
    "bake_phi",
    "SUN_RADIUS_KM",
    "AU_KM",
    "DEFAULT_N_BINS",
]

DEFAULT_N_BINS = 180          # 1 degree bins, the seed's "w pixels wide"
CHUNK = 1 << 18               # photons per vectorised chunk (fixed: determinism)


@dataclass
class PhotonMaps:
    """Photon maps (per unit solar irradiance E0 and per unit albedo)."""

    atm: Atmosphere
    edges: np.ndarray            # theta bin edges, rad, uniform on [0, pi]
    rho: float                   # radius of the map sphere (outermost shell), km
    reflected: np.ndarray        # exitance on the outer shell (seed's map)
    surface: np.ndarray          # exitance on the ground at reflection points
    transmitted: np.ndarray      # flux density of light through the atmosphere only
    counts: np.ndarray           # reflected photons per bin (outer shell)
    n_photons: int
    seed: int
    power_per_photon: float      # E0 * pi rho_d^2 / N with E0 = 1 (km^2)
    stats: dict = field(default_factory=dict)

    @property
    def centres(self) -> np.ndarray:
        return 0.5 * (self.edges[:-1] + self.edges[1:])

    def band_area(self, radius: float) -> np.ndarray:
        """2 pi rho^2 (cos t_i - cos t_{i+1}) (corrected seed eq. 3.8)."""
        c = np.cos(self.edges)
        return 2.0 * np.pi * radius**2 * (c[:-1] - c[1:])


def _theta_of(p):
    """Angle from the +z (Sun) axis, atan2 form (accurate near 0 and pi)."""
    return np.arctan2(np.hypot(p[:, 0], p[:, 1]), p[:, 2])


def _bin(theta, n_bins):
    return np.minimum((theta * (n_bins / np.pi)).astype(np.int64), n_bins - 1)


def photon_map(n_photons: int, atm: Atmosphere | None = None, seed: int = 0,
               n_bins: int = DEFAULT_N_BINS, disc_margin: float = 1.02,
               sun_radius_km: float = SUN_RADIUS_KM, sun_distance_km: float = AU_KM,
               sampling: str = "random", progress=None) -> PhotonMaps:
    """Pass 1: cast n_photons from the solar disc and build the maps.

    atm: shells (None = bare Earth). seed: numpy PCG64 seed. n_bins: theta
    bins on [0, pi]. disc_margin: target disc radius / outermost radius.
    sun_radius_km = 0 gives parallel light. sampling: "random" (independent
    uniform points on both discs) or "jittered" (the seed's IV.1.1: the
    target-disc points are jittered in a k x k grid of the polar unit square,
    k = isqrt(N), the few photons beyond k^2 and the solar-disc points random).
    progress: optional callable (done, total) called after each chunk.
    Returns PhotonMaps; stats holds the power budget (km^2 per unit E0):
    incident, missed, transmitted, absorbed (reached the ground), reflected
    (left the outer shell after reflection), returned (fell back to the
    ground after total internal reflection), trapped; and photon counts.
    """
    atm = Atmosphere.bare() if atm is None else atm
    n_photons = int(n_photons)
    if n_photons < 1:
        raise ValueError("n_photons must be >= 1")
    if sampling not in ("random", "jittered"):
        raise ValueError("sampling must be 'random' or 'jittered'")
    rng = np.random.default_rng(seed)
    kgrid = int(np.sqrt(n_photons)) if sampling == "jittered" else 0
    while kgrid * kgrid > n_photons:
        kgrid -= 1
    rho = atm.outer_radius
    rd = disc_margin * rho
    K = atm.K
    w = np.pi * rd * rd / n_photons
    refl = np.zeros(n_bins)
    surf = np.zeros(n_bins)
    trans = np.zeros(n_bins)
    cnt = {"missed": 0, "transmitted": 0, "absorbed": 0, "reflected": 0,
           "returned": 0, "trapped_in": 0, "trapped_out": 0}
    done = 0
    while done < n_photons:
        m = min(CHUNK, n_photons - done)
        u = rng.random((m, 4))
        if kgrid:
            j = np.arange(done, done + m)
            cell = j < kgrid * kgrid
            u[cell, 2] = (j[cell] // kgrid + u[cell, 2]) / kgrid
            u[cell, 3] = (j[cell] % kgrid + u[cell, 3]) / kgrid
        rs = sun_radius_km * np.sqrt(u[:, 0])
        a = 2.0 * np.pi * u[:, 1]
        re = rd * np.sqrt(u[:, 2])
        e = 2.0 * np.pi * u[:, 3]
        pe = np.stack([re * np.cos(e), re * np.sin(e), np.zeros(m)], 1)
        dvec = pe - np.stack([rs * np.cos(a), rs * np.sin(a), np.full(m, sun_distance_km)], 1)
        dvec /= np.linalg.norm(dvec, axis=1, keepdims=True)
        origin = pe - (3.0 * rd) * dvec            # same line, outside every shell
        res = trace(origin, dvec, atm, region=K + 1)
        hit = res.status == HIT_EARTH
        through = (res.status == ESCAPED) & res.interacted
        cnt["missed"] += int(np.sum((res.status == ESCAPED) & ~res.interacted))
        cnt["transmitted"] += int(np.sum(through))
        cnt["trapped_in"] += int(np.sum(res.status == TRAPPED))
        cnt["absorbed"] += int(np.sum(hit))
        trans += np.bincount(_bin(_theta_of(res.pos[through]), n_bins), minlength=n_bins)
        ph = res.pos[hit]
        surf += np.bincount(_bin(_theta_of(ph), n_bins), minlength=n_bins)
        # Lambertian reflection (cosine law) and the way out
        nrm = ph / np.linalg.norm(ph, axis=1, keepdims=True)
        out = trace(ph, lambert_directions(nrm, rng), atm, region=1)
        gone = out.status == ESCAPED
        cnt["reflected"] += int(np.sum(gone))
        cnt["returned"] += int(np.sum(out.status == HIT_EARTH))
        cnt["trapped_out"] += int(np.sum(out.status == TRAPPED))
        refl += np.bincount(_bin(_theta_of(out.pos[gone]), n_bins), minlength=n_bins)
        done += m
        if progress is not None:
            progress(done, n_photons)
    edges = np.linspace(0.0, np.pi, n_bins + 1)
    c = np.cos(edges)
    area_rho = 2.0 * np.pi * rho**2 * (c[:-1] - c[1:])
    area_R = 2.0 * np.pi * atm.earth_radius**2 * (c[:-1] - c[1:])
    stats = {k: v * w for k, v in cnt.items()}
    stats["incident"] = n_photons * w
    stats.update({"n_" + k: v for k, v in cnt.items()})
    return PhotonMaps(atm=atm, edges=edges, rho=rho, reflected=refl * w / area_rho,
                      surface=surf * w / area_R, transmitted=trans * w / area_rho,
                      counts=refl, n_photons=n_photons, seed=int(seed),
                      power_per_photon=w, stats=stats)


def _lookup(values, n_bins, interp):
    centres = (np.arange(n_bins) + 0.5) * (np.pi / n_bins)
    if interp == "linear":
        return lambda th: np.interp(th, centres, values)
    if interp == "nearest":
        return lambda th: values[_bin(th, n_bins)]
    raise ValueError("interp must be 'linear' or 'nearest'")


def _nodes(n_s, n_beta):
    xs, ws = np.polynomial.legendre.leggauss(n_s)
    s = 0.5 * (xs + 1.0)
    ws = 0.5 * ws
    beta = (np.arange(n_beta) + 0.5) * (np.pi / n_beta)
    return s, ws, beta


def gather_function(radiance, theta, r_km, b_max, atm: Atmosphere | None = None,
                    n_s: int = 96, n_beta: int = 96, chunk_rays: int = 1 << 20):
    """Final gathering with a radiance function of the hit point's theta.

    radiance(theta_hit) -> L per unit E0 (vectorised). theta, r_km broadcast.
    b_max: largest impact parameter that reaches the emitting sphere
    (rho for the shell mode; n1 R for the ground seen through the shells).
    atm None: straight rays to the sphere of radius b_max (shell mode).
    atm given: rays are traced through the shells and read the radiance where
    they hit the ground (rays that miss it read 0).
    Returns (phi, psi) with the broadcast shape.
    """
    theta, r = np.broadcast_arrays(np.asarray(theta, dtype=float),
                                   np.asarray(r_km, dtype=float))
    shape = theta.shape
    th = theta.reshape(-1)
    rr = r.reshape(-1)
    if np.any(rr <= b_max) or (atm is not None and np.any(rr <= atm.outer_radius)):
        raise ValueError("gathering points must lie outside the emitting sphere and the shells")
    s, ws, beta = _nodes(n_s, n_beta)
    b = b_max * (1.0 - s * s)                       # (n_s,)
    db = 2.0 * b_max * s * ws                       # |db/ds| * weight
    dbeta = np.pi / n_beta
    cb, sb = np.cos(beta), np.sin(beta)
    phi = np.zeros(th.size)
    ft = np.zeros(th.size)
    fn = np.zeros(th.size)
    per = max(1, chunk_rays // (n_s * n_beta))
    for i0 in range(0, th.size, per):
        t = th[i0:i0 + per, None, None]
        R = rr[i0:i0 + per, None, None]
        sg = b[None, :, None] / R                    # sin gamma
        cg = np.sqrt((R - b[None, :, None]) * (R + b[None, :, None])) / R
        dom = (2.0 * dbeta) * db[None, :, None] * b[None, :, None] / (R * R * cg)
        # frame at P: nadir w = -(sin t, 0, cos t); towards the Sun e_t = (-cos t, 0, sin t)
        st, ct = np.sin(t), np.cos(t)
        dx = cg * (-st) + sg * cb[None, None, :] * (-ct)
        dy = np.broadcast_to(sg * sb[None, None, :], dx.shape)
        dz = cg * (-ct) + sg * cb[None, None, :] * st
        px, pz = R * st, R * ct
        if atm is None:
            # near root of |P + t d| = b_max: t = (r^2 - b_max^2) / (r cos g + sqrt(b_max^2 - b^2))
            tt = (R - b_max) * (R + b_max) / (R * cg + np.sqrt(np.maximum(
                (b_max - b[None, :, None]) * (b_max + b[None, :, None]), 0.0)))
            qx, qy, qz = px + tt * dx, tt * dy, pz + tt * dz
            L = radiance(np.arctan2(np.hypot(qx, qy), qz))
        else:
            shp = dx.shape
            org = np.broadcast_to(np.stack(np.broadcast_arrays(px, np.zeros(shp), pz), -1),
                                  shp + (3,)).reshape(-1, 3)
            dirs = np.stack([dx, dy, dz], -1).reshape(-1, 3)
            res = trace(org, dirs, atm, region=atm.K + 1)
            hit = res.status == HIT_EARTH
            L = np.zeros(org.shape[0])
            L[hit] = radiance(_theta_of(res.pos[hit]))
            L = L.reshape(shp)
        wL = L * dom
        phi[i0:i0 + per] = wL.sum(axis=(1, 2))
        fn[i0:i0 + per] = (wL * cg).sum(axis=(1, 2))
        ft[i0:i0 + per] = (wL * sg * cb[None, None, :]).sum(axis=(1, 2))
    psi = np.where(phi > 0.0, np.arctan2(ft, fn), 0.0)
    return phi.reshape(shape), psi.reshape(shape)


def gather(maps: PhotonMaps, theta, r_km, mode: str = "surface", interp: str = "linear",
           n_s: int = 96, n_beta: int = 96):
    """Pass 2: final gathering from points (theta, r_km) (broadcast).

    mode "shell" (the seed's): read the outer-shell map as a Lambertian
    emitter, L = M / pi. mode "surface" (default): trace gathering rays
    through the shells to the ground, L = M_surface / (pi n1^2). Without
    shells both are the same computation. interp: "linear"
    between bin centres or "nearest" (the seed's pixel lookup).
    Returns (phi, psi): scalar irradiance per unit E0 and albedo, and the mean
    incidence angle from the nadir towards the Sun side (rad).
    """
    nb = maps.edges.size - 1
    if mode == "shell" or maps.atm.K == 0:
        f = _lookup(maps.reflected / np.pi, nb, interp)
        return gather_function(f, theta, r_km, maps.rho, None, n_s, n_beta)
    if mode == "surface":
        n1 = maps.atm.surface_index
        f = _lookup(maps.surface / (np.pi * n1 * n1), nb, interp)
        # apparent ground radius: impact parameter n1 R (Bouguer), at most the top
        # shell's radius; the trace decides which rays really reach the ground
        b_max = min(n1 * maps.atm.earth_radius, maps.rho)
        return gather_function(f, theta, r_km, b_max, maps.atm, n_s, n_beta)
    raise ValueError("mode must be 'shell' or 'surface'")


def bake_phi(theta, x, n_photons: int = 4_000_000, seed: int = 1, atm: Atmosphere | None = None,
             n_bins: int = DEFAULT_N_BINS, mode: str = "surface", interp: str = "linear",
             n_s: int = 96, n_beta: int = 96, sampling: str = "random", progress=None,
             return_maps: bool = False):
    """phi(theta, x) and psi(theta, x) by photon mapping (x = R/r, broadcast
    with theta; same meaning as bake.earthshine.reference.phi_psi_reference).

    atm None: bare Earth (then "shell" and "surface" coincide). Points must
    lie outside the outermost shell (x < R / rho). Deterministic for a given
    (n_photons, seed, parameters).
    Returns (phi, psi), or (phi, psi, maps) with return_maps.
    """
    atm = Atmosphere.bare() if atm is None else atm
    x = np.asarray(x, dtype=float)
    if np.any(x <= 0.0) or np.any(x > 1.0):
        raise ValueError("x = R/r must be in (0, 1)")
    maps = photon_map(n_photons, atm, seed, n_bins, sampling=sampling, progress=progress)
    phi, psi = gather(maps, theta, atm.earth_radius / x, mode, interp, n_s, n_beta)
    return (phi, psi, maps) if return_maps else (phi, psi)
