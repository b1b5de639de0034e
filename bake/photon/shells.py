# SPDX-License-Identifier: MIT
"""Ray tracing through nested spherical shells of constant refractive index.

The seed (Penney 2009, III.3.1 and IV.1.1) models the atmosphere as nested
spheres, each of constant index, with refraction only at their boundaries.
This module traces many rays at once (numpy, no Python loop per ray).

Geometry
--------
Earth-centred, km. Boundaries B[0] = Earth radius < B[1] < ... < B[K] (the
shell tops). Region i (1 <= i <= K) is the shell between B[i-1] and B[i] with
index n[i]; region K+1 is the vacuum outside B[K] (index 1). Region 0 is the
Earth's interior (opaque: a ray reaching B[0] from above stops there).
Zero shells (K = 0) is the bare Earth: region 1 is the vacuum.

Neighbour test (seed IV.1.1): a ray in region i can only meet B[i-1] (the
sphere below it) or B[i] (the sphere above it), so each step tests two
spheres, O(1) in the number of shells. At each boundary Snell's law in vector
form (Glassner, "An Introduction to Ray Tracing", 1989, ch. 4; Heckbert's
formulation) gives the new direction; when n1 sin(i) > n2 the ray is totally
internally reflected and stays in its region. No Fresnel partial reflection:
as in the seed, each ray carries its whole power across a boundary.

Invariant: in spherically symmetric shells n r sin(z) (z the angle from the
local vertical) is conserved along a ray (Bouguer's formula). The tests use
it, and `bake.photon.mapping` uses it to find the apparent limb of the Earth.

API
---
Atmosphere(earth_radius, radii, indices, extinction=None)
    radii: shell tops (km, ascending, > earth_radius), indices: index of each
    shell, extinction: optional extinction coefficient of each shell (1/km),
    accumulated as optical depth `tau` along each traced ray.
Atmosphere.bare(R), Atmosphere.exponential(N0, H, top_km, K, R)
trace(origins, dirs, atm, region=None, max_steps=None) -> TraceResult
refract(d, nf, n1, n2) -> (new_dir, tir_mask)     (vector Snell, any shape)
lambert_directions(normals, rng) -> cosine-distributed outward directions
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = [
    "Atmosphere",
    "TraceResult",
    "trace",
    "refract",
    "lambert_directions",
    "orthonormal_basis",
    "ESCAPED",
    "HIT_EARTH",
    "TRAPPED",
    "R_EARTH_KM",
]

from ..common.constants import R_EARTH_KM

# Final status of a traced ray.
ESCAPED = 0    # in the vacuum, moving away: left the outer shell (n_cross > 0)
               # or never met any boundary (n_cross == 0 and n_tir == 0)
HIT_EARTH = 1  # stopped on the Earth's surface (pos is the hit point)
TRAPPED = 2    # still bouncing after max_steps (whispering-gallery rays)


@dataclass(frozen=True)
class Atmosphere:
    """Nested spherical shells of constant refractive index.

    earth_radius: km. radii: shell tops in km, strictly ascending, all
    > earth_radius (may be empty: bare Earth). indices: refractive index of
    each shell (> 0). extinction: extinction coefficient of each shell (1/km),
    default zero.
    """

    earth_radius: float = R_EARTH_KM
    radii: np.ndarray = field(default_factory=lambda: np.zeros(0))
    indices: np.ndarray = field(default_factory=lambda: np.zeros(0))
    extinction: np.ndarray | None = None

    def __post_init__(self):
        radii = np.asarray(self.radii, dtype=float).reshape(-1)
        indices = np.asarray(self.indices, dtype=float).reshape(-1)
        if radii.shape != indices.shape:
            raise ValueError("radii and indices must have the same length")
        if not (np.isfinite(self.earth_radius) and self.earth_radius > 0):
            raise ValueError("earth_radius must be > 0")
        b = np.concatenate([[float(self.earth_radius)], radii])
        if np.any(np.diff(b) <= 0):
            raise ValueError("shell radii must be ascending and above the Earth")
        if np.any(~np.isfinite(indices)) or np.any(indices <= 0):
            raise ValueError("indices must be finite and > 0")
        ext = (np.zeros_like(radii) if self.extinction is None
               else np.asarray(self.extinction, dtype=float).reshape(-1))
        if ext.shape != radii.shape or np.any(ext < 0) or np.any(~np.isfinite(ext)):
            raise ValueError("extinction must be finite, >= 0, one per shell")
        object.__setattr__(self, "radii", radii)
        object.__setattr__(self, "indices", indices)
        object.__setattr__(self, "extinction", ext)

    # --- derived arrays, indexed by region 0..K+1
    @property
    def K(self) -> int:
        """Number of shells."""
        return int(self.radii.size)

    @property
    def boundaries(self) -> np.ndarray:
        """B[0] = Earth radius, B[1..K] = shell tops."""
        return np.concatenate([[float(self.earth_radius)], self.radii])

    @property
    def outer_radius(self) -> float:
        """Radius of the outermost object (top shell, or the Earth if bare)."""
        return float(self.boundaries[-1])

    @property
    def region_index(self) -> np.ndarray:
        """n per region: [n/a (Earth, set to 1), n_1..n_K, 1 (vacuum)]."""
        return np.concatenate([[1.0], self.indices, [1.0]])

    @property
    def region_extinction(self) -> np.ndarray:
        return np.concatenate([[0.0], self.extinction, [0.0]])

    @property
    def surface_index(self) -> float:
        """Index of the medium touching the Earth's surface (1 if bare)."""
        return float(self.indices[0]) if self.K else 1.0

    def region_of(self, r) -> np.ndarray:
        """Region of points at radius r (a point on a boundary belongs to the
        region above it). Points inside the Earth give 0."""
        return np.searchsorted(self.boundaries, np.asarray(r, dtype=float),
                               side="right").astype(np.int64)

    # --- constructors
    @classmethod
    def bare(cls, earth_radius: float = R_EARTH_KM) -> "Atmosphere":
        """Zero shells: the Earth without atmosphere."""
        return cls(earth_radius, np.zeros(0), np.zeros(0))

    @classmethod
    def exponential(cls, n0: float = 2.8e-4, scale_height_km: float = 7.5,
                    top_km: float = 100.0, n_shells: int = 50,
                    earth_radius: float = R_EARTH_KM,
                    spacing: str = "refractivity") -> "Atmosphere":
        """n(h) = 1 + n0 exp(-h/H) sampled into K shells up to top_km.

        spacing "uniform": boundaries equally spaced in h. "refractivity":
        boundaries at equal steps of exp(-h/H) between 0 and top (the ground
        shells are thin, where n changes fastest), with the last shell ending at
        top_km. The index of a shell is the mean of n(h) over its height
        (exact integral of the exponential), so the column refractivity
        integral of the profile is preserved.
        """
        if n_shells < 1:
            return cls.bare(earth_radius)
        H = float(scale_height_km)
        if spacing == "uniform":
            h = np.linspace(0.0, top_km, n_shells + 1)
        elif spacing == "refractivity":
            e = np.linspace(1.0, np.exp(-top_km / H), n_shells + 1)
            h = -H * np.log(e)
            h[0], h[-1] = 0.0, top_km
        else:
            raise ValueError("spacing must be 'uniform' or 'refractivity'")
        lo, hi = h[:-1], h[1:]
        mean_n = 1.0 + n0 * H * (np.exp(-lo / H) - np.exp(-hi / H)) / (hi - lo)
        return cls(earth_radius, earth_radius + hi, mean_n)


@dataclass
class TraceResult:
    """Final state of each traced ray (arrays of length N).

    pos, dir: last position (on the boundary where the ray stopped or left)
    and direction (unit). status: ESCAPED / HIT_EARTH / TRAPPED. region:
    region at the end. n_cross: boundaries crossed; n_tir: total internal
    reflections. path: geometric length inside the shells (km). tau: optical
    depth sum(extinction * length). r_min: smallest distance to the Earth's
    centre along the traced path (km; the start radius if nothing was met).
    """

    pos: np.ndarray
    dir: np.ndarray
    status: np.ndarray
    region: np.ndarray
    n_cross: np.ndarray
    n_tir: np.ndarray
    path: np.ndarray
    tau: np.ndarray
    r_min: np.ndarray

    @property
    def interacted(self) -> np.ndarray:
        """True for rays that met a boundary (crossed or reflected)."""
        return (self.n_cross + self.n_tir) > 0


def _dot(a, b):
    return np.einsum("...i,...i->...", a, b)


def _unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def refract(d, nf, n1, n2):
    """Snell's law in vector form.

    d: incident unit directions (..., 3); nf: unit normals facing the incident
    ray (d . nf <= 0); n1, n2: indices before and after (broadcast).
    Returns (new_dir, tir): the refracted direction, or the mirror direction
    where n1 sin(i) > n2 (total internal reflection, tir True).
    """
    d = np.asarray(d, dtype=float)
    nf = np.asarray(nf, dtype=float)
    eta = np.asarray(n1, dtype=float) / np.asarray(n2, dtype=float)
    cos_i = np.clip(-_dot(d, nf), 0.0, 1.0)
    sin2_t = eta * eta * np.maximum(0.0, (1.0 - cos_i) * (1.0 + cos_i))
    tir = sin2_t > 1.0
    cos_t = np.sqrt(np.maximum(0.0, 1.0 - sin2_t))
    refr = eta[..., None] * d + (eta * cos_i - cos_t)[..., None] * nf
    refl = d + (2.0 * cos_i)[..., None] * nf
    out = np.where(tir[..., None], refl, refr)
    return _unit(out), tir


def orthonormal_basis(n):
    """Two unit vectors completing unit vectors n (..., 3) to right-handed
    orthonormal frames (t1, t2, n), branch-free, stable for every n
    (Duff et al. 2017, "Building an Orthonormal Basis, Revisited", JCGT 6(1))."""
    n = np.asarray(n, dtype=float)
    x, y, z = n[..., 0], n[..., 1], n[..., 2]
    s = np.where(z >= 0.0, 1.0, -1.0)
    a = -1.0 / (s + z)
    b = x * y * a
    t1 = np.stack([1.0 + s * x * x * a, s * b, -s * x], axis=-1)
    t2 = np.stack([b, s + y * y * a, -y], axis=-1)
    return t1, t2


def lambert_directions(normals, rng):
    """Directions with the cosine (Lambertian) distribution over the
    hemisphere around each unit normal: pdf cos(e)/pi per steradian
    (Malley's method: uniform point in the unit disc lifted to the hemisphere;
    Pharr, Jakob & Humphreys, "Physically Based Rendering", 3rd ed., 13.6.3)."""
    normals = np.asarray(normals, dtype=float)
    m = normals.shape[0]
    u1 = rng.random(m)
    u2 = rng.random(m)
    rr = np.sqrt(u1)
    ph = 2.0 * np.pi * u2
    lx, ly = rr * np.cos(ph), rr * np.sin(ph)
    lz = np.sqrt(np.maximum(0.0, 1.0 - u1))
    t1, t2 = orthonormal_basis(normals)
    return _unit(lx[:, None] * t1 + ly[:, None] * t2 + lz[:, None] * normals)


def trace(origins, dirs, atm: Atmosphere, region=None, max_steps=None) -> TraceResult:
    """Trace rays through the shells until they hit the Earth or leave.

    origins (N, 3) km, dirs (N, 3) (normalised here). region: start region
    of each ray (default from |origin|; give it explicitly for rays starting
    exactly on a boundary, e.g. K+1 for a ray on the top shell going in).
    A ray starting in the vacuum (region K+1) must be outside B[K].
    max_steps: boundary events per ray before it is declared TRAPPED
    (default 8 (K + 2) + 64).
    Loop over events (at most ~2K + 2 for ordinary rays), vectorised over rays.
    """
    pos = np.array(origins, dtype=float).reshape(-1, 3)
    d = _unit(np.array(dirs, dtype=float).reshape(-1, 3))
    n = pos.shape[0]
    K = atm.K
    B = atm.boundaries
    B2 = B * B
    n_reg = atm.region_index
    k_reg = atm.region_extinction
    r0 = np.linalg.norm(pos, axis=1)
    reg = atm.region_of(r0) if region is None else \
        np.broadcast_to(np.asarray(region, dtype=np.int64), (n,)).copy()
    if np.any(reg < 1) or np.any(reg > K + 1):
        raise ValueError("ray origins must be outside the Earth")
    if max_steps is None:
        max_steps = 8 * (K + 2) + 64

    # global results, written when a ray finishes
    status = np.full(n, TRAPPED, dtype=np.int8)
    n_cross = np.zeros(n, dtype=np.int64)
    n_tir = np.zeros(n, dtype=np.int64)
    path = np.zeros(n)
    tau = np.zeros(n)
    r_min = r0.copy()

    # compact state of the rays still in flight (no scatter per step)
    idx = np.arange(n)
    p, dd, rg = pos.copy(), d.copy(), reg.copy()
    l_cross = np.zeros(n, dtype=np.int64)
    l_tir = np.zeros(n, dtype=np.int64)
    l_path = np.zeros(n)
    l_tau = np.zeros(n)
    l_rmin = r0.copy()

    def finish(mask, code):
        j = idx[mask]
        status[j] = code
        pos[j] = p[mask]
        d[j] = dd[mask]
        reg[j] = rg[mask]
        n_cross[j] = l_cross[mask]
        n_tir[j] = l_tir[mask]
        path[j] = l_path[mask]
        tau[j] = l_tau[mask]
        r_min[j] = l_rmin[mask]

    for _ in range(max_steps):
        if idx.size == 0:
            break
        pp = np.einsum("ij,ij->i", p, p)
        b = np.einsum("ij,ij->i", p, dd)
        h2 = np.maximum(pp - b * b, 0.0)  # squared closest approach of the line

        # sphere below (B[rg-1]), approached from outside: first root
        c_in = pp - B2[rg - 1]
        disc_in = b * b - c_in
        hit_in = (b < 0.0) & (disc_in > 0.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            t_in = np.where(hit_in, np.maximum(c_in, 0.0)
                            / (np.sqrt(np.maximum(disc_in, 0.0)) - b), np.inf)
            # sphere above (B[rg]), from inside: the positive root (stable forms)
            rg_up = np.minimum(rg, K)
            c_out = pp - B2[rg_up]
            sq_out = np.sqrt(np.maximum(b * b - c_out, 0.0))
            t_out = np.where(b <= 0.0, sq_out - b, -c_out / (b + sq_out))
        t_out = np.where(rg <= K, np.maximum(t_out, 0.0), np.inf)

        go_in = t_in <= t_out
        t = np.where(go_in, t_in, t_out)
        leave = np.isinf(t)  # in the vacuum and missing the sphere below
        if leave.any():
            l_rmin[leave] = np.minimum(l_rmin[leave], np.where(
                b[leave] < 0.0, np.sqrt(h2[leave]), l_rmin[leave]))
            finish(leave, ESCAPED)
            keep = ~leave
            idx, p, dd, rg, l_cross, l_tir, l_path, l_tau, l_rmin = (
                idx[keep], p[keep], dd[keep], rg[keep], l_cross[keep], l_tir[keep],
                l_path[keep], l_tau[keep], l_rmin[keep])
            b, t, go_in, h2 = b[keep], t[keep], go_in[keep], h2[keep]
            if idx.size == 0:
                break

        # move to the boundary; bookkeeping along the segment
        l_path += np.where(rg <= K, t, 0.0)
        l_tau += k_reg[rg] * t
        rb = np.where(go_in, B[rg - 1], B[np.minimum(rg, K)])
        q = p + t[:, None] * dd
        q *= (rb / np.sqrt(np.einsum("ij,ij->i", q, q)))[:, None]  # snap onto the sphere
        l_rmin = np.minimum(l_rmin, np.where((b < 0.0) & (-b < t), np.sqrt(h2), rb))
        p = q

        # the Earth: stop there
        earth = go_in & (rg == 1)
        # refraction or total internal reflection at the other boundaries
        nf = p / rb[:, None]
        nf = np.where(go_in[:, None], nf, -nf)
        nxt = np.where(go_in, rg - 1, rg + 1)
        new_d, tir = refract(dd, nf, n_reg[rg], n_reg[np.maximum(nxt, 0)])
        tir &= ~earth
        dd = np.where(earth[:, None], dd, new_d)
        l_tir += tir
        l_cross += ~(tir | earth)
        rg = np.where(tir | earth, rg, nxt)
        gone = (rg == K + 1) & ~go_in  # crossed the top shell outwards
        done = earth | gone
        if done.any():
            finish(earth, HIT_EARTH)
            finish(gone, ESCAPED)
            keep = ~done
            idx, p, dd, rg, l_cross, l_tir, l_path, l_tau, l_rmin = (
                idx[keep], p[keep], dd[keep], rg[keep], l_cross[keep], l_tir[keep],
                l_path[keep], l_tau[keep], l_rmin[keep])

    if idx.size:
        finish(np.ones(idx.size, dtype=bool), TRAPPED)
    return TraceResult(pos, d, status, reg, n_cross, n_tir, path, tau, r_min)
