# SPDX-License-Identifier: MIT
"""Deterministic reference for sunlight through the Earth's atmosphere.

In a spherically symmetric atmosphere a ray is fixed by its impact parameter
b = n(r0) r0 (Bouguer's invariant; r0 the radius of its lowest point). For
each ray this module computes, by quadrature of the refraction integral:

  bending   alpha(b) = -2 b Int_{r0}^{top} (dn/dr) / (n sqrt(n^2 r^2 - b^2)) dr
  columns   Int c(r) dl along the bent path, dl = n r dr / sqrt(n^2 r^2 - b^2),
            per extinction ingredient (air, ozone, two aerosol layers), hence
            the band transmission T(b) (V band, bake.atmosphere.profile).

The 1/sqrt singularity at the lowest point is removed by r = r0 + s^2
(dr = 2 s ds, and s / sqrt(n^2 r^2 - b^2) is smooth and finite at s = 0, with
n r - b = s^2 (1 + N(r)) + r0 (N(r) - N(r0)) formed without cancellation);
Gauss-Legendre in s on the pieces between the profile's layer boundaries,
where dN/dr jumps. Derivation of both integrals: e.g. Born & Wolf,
Principles of Optics, 3.2.2 (rays in stratified media), or Link (1969,
Eclipse Phenomena in Astronomy, ch. 2) for the eclipse geometry.

The irradiance behind the Earth (`fraction`) follows from flux conservation:
a point Q of the solar disc at distance d sends through the ring (b, b + db)
the power that lands on the ring of radius rho(b) at distance z behind the
Earth's centre, rho(b) = b / cos(g) - z tan(g), g = alpha(b) - b / d (the
incoming ray from Q diverges by b / d). Integrating over the launch azimuth
phi and the solar disc (limb-darkened, Neckel & Labs 1994, as src/shadow.c)
in the image plane, the fraction of unobstructed sunlight at a point at
distance rho_p from the axis is

  F = (1 + z/d)^2 Int db b T(b) Int dphi D(rho(b) e_phi - rho_p e_x)

where D is the disc's normalised brightness on the plane (radius a = z R_sun / d).
Written in the ray coordinates (b, phi) the focusing on the axis (1/rho) is
integrable and never appears: no caustic to regularise. Both sides of the
Earth are included (rho < 0: rays that crossed the axis). Rays above the
atmosphere's top are straight with T = 1; without atmosphere F is the
geometric (planar) visible fraction, which the tests check.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..common.constants import AU_KM, SUN_RADIUS_KM  # noqa: F401  (bake.atmosphere.rays.AU_KM)
from ..common.quadrature import gauss_legendre
from . import profile as ap

# Neckel & Labs (1994, Sol. Phys. 153, 91) limb darkening at 559.95 nm,
# I(mu)/I(1) = sum_k A_k mu^k (the same law as src/shadow.c).
NL94_559 = np.array([0.26892, 1.34319, -1.58427, 1.91271, -1.31350, 0.37295])
UNIFORM = np.array([1.0])
# The total band's disc: the Eddington approximation of a grey atmosphere,
# I(mu)/I(1) = (2 + 3 mu) / 5 (e.g. Mihalas 1978, Stellar Atmospheres, 2nd
# ed., ch. 3), the bolometric limb darkening; the Sun's measured integrated
# light follows it to a few per cent of I(1) (Pierce & Slaughter 1977, Sol.
# Phys. 51, 25).
EDDINGTON = np.array([0.4, 0.6])


def _gl(n, lo=0.0, hi=1.0):
    x, w = gauss_legendre(n)
    return lo + (hi - lo) * (x + 1) / 2, w * (hi - lo) / 2


# ---------------------------------------------------------------- ray integrals

@dataclass
class Rays:
    """Rays on a grid of lowest-point altitudes h0 (km, ascending)."""

    profile: ap.Profile
    h0: np.ndarray          # lowest altitude (km)
    b: np.ndarray           # impact parameter (km)
    alpha: np.ndarray       # total bending (rad, towards the Earth)
    columns: np.ndarray     # (4, n): air, O3 (m^-2), trop/strat aerosol (tau at 550 nm)
    transmission: np.ndarray  # V-band transmission (1 in seed mode)
    earth_radius_km: float

    @property
    def top_b(self):
        return self.profile.earth_radius_km + self.profile.top_km


def trace(profile: ap.Profile, h0, nodes: int = 24):
    """Bending (rad) and columns (4, n) of the rays whose lowest altitude is h0
    (km, array, 0 <= h0 < top). Gauss-Legendre with `nodes` points on each
    piece of s = sqrt(r - r0) between layer boundaries (each piece is further
    split in two, the exponential's tail being long)."""
    h0 = np.atleast_1d(np.asarray(h0, dtype=float))
    R = profile.earth_radius_km
    r0 = R + h0
    N0 = profile.refractivity(h0)
    b = (1.0 + N0) * r0
    # breakpoints in s for each ray: layer boundaries above h0, and the top
    brk = np.concatenate([profile.breakpoints_km(), [profile.top_km]])
    s_b = np.sqrt(np.clip(brk[None, :] - h0[:, None], 0.0, None))     # (n, nb)
    edges = np.concatenate([np.zeros((h0.size, 1)), s_b], axis=1)
    # split every piece in two
    mid = 0.5 * (edges[:, :-1] + edges[:, 1:])
    e2 = np.empty((h0.size, 2 * (edges.shape[1] - 1) + 1))
    e2[:, 0::2] = edges
    e2[:, 1::2] = mid
    x, w = _gl(nodes)
    lo, hi = e2[:, :-1], e2[:, 1:]
    s = lo[..., None] + (hi - lo)[..., None] * x          # (n, pieces, nodes)
    ws = (hi - lo)[..., None] * w
    s = s.reshape(h0.size, -1)
    ws = ws.reshape(h0.size, -1)
    s2 = s * s
    h = h0[:, None] + s2
    N = profile.refractivity(h)
    dN = profile.refractivity_slope(h)
    g = s2 * (1.0 + N) + r0[:, None] * (N - N0[:, None])    # n r - b >= 0
    with np.errstate(divide="ignore", invalid="ignore"):
        kern = s / np.sqrt(g * (g + 2.0 * b[:, None]))       # s / sqrt(n^2 r^2 - b^2)
    kern = np.where(ws > 0, kern, 0.0)
    alpha = -4.0 * b * np.sum(ws * kern * dN / (1.0 + N), axis=1)
    nr = (1.0 + N) * (r0[:, None] + s2)
    spec = profile.species(h)                               # (4, n, m)
    cols = 4.0 * np.sum(ws * kern * nr * spec, axis=2) * 1e3   # km -> m
    return b, alpha, cols


def band_transmission(profile: ap.Profile, columns):
    """V-band transmission of paths with the given columns (4, n)."""
    if not profile.extinction:
        return np.ones(columns.shape[1])
    lam, wl = ap.band_weights(profile.band)
    tau = profile.species_weights(lam).T @ columns              # (n_lambda, n)
    return wl @ np.exp(-tau)


def make_rays(profile: ap.Profile, dh_km: float = 0.01, nodes: int = 24) -> Rays:
    """Rays from the lowest unblocked altitude (cloud top, or the ground in
    seed mode) to the top, every dh_km of lowest altitude."""
    # opaque clouds (cloud_fraction 1) stop every ray below their top; partial
    # ones let the rays down to the ground through with 1 - cloud_fraction
    h_lo = profile.cloud_top_km if profile.extinction and profile.cloud_fraction >= 1.0 else 0.0
    n = int(round((profile.top_km - h_lo) / dh_km))
    h0 = np.linspace(h_lo, profile.top_km, n + 1)
    b, alpha, cols = np.empty(0), np.empty(0), np.empty((4, 0))
    parts = []
    for chunk in np.array_split(h0, max(1, h0.size // 2000)):
        parts.append(trace(profile, chunk, nodes))
    b = np.concatenate([p[0] for p in parts])
    alpha = np.concatenate([p[1] for p in parts])
    cols = np.concatenate([p[2] for p in parts], axis=1)
    alpha[-1] = 0.0  # the ray at the top is not bent (its integral is empty)
    T = band_transmission(profile, cols) * cloud_transmission(profile, h0)
    return Rays(profile, h0, b, alpha, cols, T, profile.earth_radius_km)


def cloud_transmission(profile: ap.Profile, h0):
    """Fraction of the rays of lowest altitude h0 (km) that pass the clouds:
    1 - cloud_fraction below cloud_top_km, 1 above (and in seed mode)."""
    h0 = np.asarray(h0, dtype=float)
    if not profile.extinction:
        return np.ones_like(h0)
    return np.where(h0 < profile.cloud_top_km, 1.0 - profile.cloud_fraction, 1.0)


# ---------------------------------------------------------------- shells (seed model)

def shell_model(profile: ap.Profile, n_shells: int, spacing: str = "uniform"):
    """Boundaries (km, radii B[0] = R .. B[K] = R + top) and indices of K
    shells of constant index, each the mean of n(h) over its height (so the
    refractivity column is kept), as the seed's nested spheres (III.3.1).
    spacing: "uniform" in altitude, or "refractivity" (equal steps of N)."""
    R, top = profile.earth_radius_km, profile.top_km
    if spacing == "uniform":
        hb = np.linspace(0.0, top, n_shells + 1)
    else:
        Ns = profile.refractivity(np.linspace(0, top, 20001))
        hh = np.linspace(0, top, 20001)
        levels = np.linspace(Ns[0], Ns[-1], n_shells + 1)
        hb = np.interp(-levels, -Ns, hh)
        hb[0], hb[-1] = 0.0, top
    x, w = _gl(16)
    lo, hi = hb[:-1], hb[1:]
    hq = lo[:, None] + (hi - lo)[:, None] * x
    mean_n = 1.0 + profile.refractivity(hq) @ w
    return R + hb, mean_n


def shell_bending(radii, indices, b):
    """Total bending (rad) of rays of impact parameter b through nested
    shells of constant index (radii[0] = Earth, radii[k] top of shell k with
    index indices[k-1]), by Snell's law at each boundary crossed (Bouguer:
    n r sin(i) = b). Returns (alpha, hits_earth). Going inwards the index
    rises, so no total internal reflection occurs; the ray turns within the
    shell where b >= n_k r_{k-1}."""
    b = np.atleast_1d(np.asarray(b, dtype=float))
    radii = np.asarray(radii, dtype=float)
    n_out = np.concatenate([indices[1:], [1.0]])   # index above each top boundary
    K = len(indices)
    alpha = np.zeros_like(b)
    alive = b < radii[-1]
    for k in range(K, 0, -1):   # boundary radii[k] between shell k (below) and above
        rk = radii[k]
        reach = alive & (b < n_out[k - 1] * rk)
        i_out = np.arcsin(np.clip(b / (n_out[k - 1] * rk), -1, 1))
        i_in = np.arcsin(np.clip(b / (indices[k - 1] * rk), -1, 1))
        alpha = alpha + np.where(reach, 2.0 * (i_out - i_in), 0.0)
        alive = reach
    hits = alive & (b < indices[0] * radii[0])
    return alpha, hits


# ---------------------------------------------------------------- irradiance behind the Earth

def _ld_discs(law, n_mu: int = 48):
    """The limb-darkened disc as a sum of uniform discs: I(d) = I(0) [d < a]
    + Int_0^1 I'(mu) [d < a sqrt(1 - mu^2)] dmu. Returns radii (units of a)
    and weights, normalised so that sum(w * radius^2) = 1 (unit flux)."""
    law = np.asarray(law, dtype=float)
    if law.size == 1:
        return np.array([1.0]), np.array([1.0])
    mu, wm = _gl(n_mu)
    dlaw = np.polynomial.polynomial.polyder(law)
    wts = np.concatenate([[law[0]], wm * np.polynomial.polynomial.polyval(mu, dlaw)])
    rad = np.concatenate([[1.0], np.sqrt(1.0 - mu * mu)])
    wts = wts / np.sum(wts * rad * rad)
    return rad, wts


def _arc(rho, rho_p, aj):
    """Angle of the circle |x| = |rho| inside the disc of radius aj centred at
    rho_p e_x (rho_p >= 0); 4 asin(sqrt((aj^2 - (|rho| - rho_p)^2) / (4 |rho| rho_p)))
    without cancellation."""
    r = np.abs(rho)
    num = aj * aj - (r - rho_p) ** 2
    den = 4.0 * r * rho_p
    with np.errstate(divide="ignore", invalid="ignore"):
        q = np.where(den > 0, num / den, np.where(num > 0, 2.0, -1.0))
    return 4.0 * np.arcsin(np.sqrt(np.clip(q, 0.0, 1.0)))


def fraction(rays: Rays | None, z, rho_p, d_sun=AU_KM, law=NL94_559,
             sun_radius_km=SUN_RADIUS_KM, earth_radius_km=ap.R_EARTH_KM,
             n_mu: int = 48, n_top: int = 400, want_psi: bool = True):
    """Fraction of unobstructed sunlight (V band) at points z km behind the
    Earth's centre (along the anti-Sun axis) and rho_p km from the axis.

    rays None: no atmosphere (the geometric fraction, straight rays, the
    solid Earth of earth_radius_km). z scalar > 0, rho_p array >= 0.
    Returns (F, psi): psi the angle (rad) of the light's mean direction from
    the direction of the Sun's centre, positive away from the Earth's
    centre (the light of the refracted limb on the point's side), 0 where F = 0.
    """
    rho_p = np.atleast_1d(np.asarray(rho_p, dtype=float))
    a = z * sun_radius_km / d_sun
    rad, wts = _ld_discs(law, n_mu)
    aj = a * rad
    norm = np.pi * a * a
    F = np.zeros_like(rho_p)
    Fx = np.zeros_like(rho_p)
    if rays is not None:
        btop = rays.top_b
        bb, al, T = rays.b, rays.alpha, rays.transmission
        # trapezoid weights in b
        wb = np.zeros_like(bb)
        db = np.diff(bb)
        wb[:-1] += 0.5 * db
        wb[1:] += 0.5 * db
        g = al - bb / d_sun
        rho = bb / np.cos(g) - z * np.tan(g)
        scale = (1.0 + z / d_sun) ** 2
        wgt = scale * wb * bb * T
        for i, rp in enumerate(rho_p):
            m = (np.abs(np.abs(rho) - rp) < a) & (wgt > 0)
            if not np.any(m):
                continue
            arcs = _arc(rho[m, None], rp, aj[None, :])          # (nm, n_discs)
            A = arcs @ wts
            F[i] += np.sum(wgt[m] * A) / norm
            if want_psi:
                S = np.sign(rho[m]) * (2 * np.sin(arcs / 2) @ wts)
                # mean 'from' direction, transverse part along e_x (see module notes)
                Fx[i] += np.sum(wgt[m] * S * (np.abs(rho[m]) / z * np.sign(rho[m]) + g[m])) / norm
    else:
        btop = earth_radius_km
    # straight rays above btop (or above the solid Earth without atmosphere):
    # image radius rho = b (1 + z/d) approximately; exact with g = -b/d
    rtop = btop / np.cos(btop / d_sun) + z * np.tan(btop / d_sun)
    for i, rp in enumerate(rho_p):
        lo = max(rtop, rp - a)
        hi = rp + a
        if hi <= lo:
            continue
        # Gauss-Legendre in theta with rho = lo + (hi - lo) sin^2(theta): smooth
        # at the square-root edges of the arcs at both ends
        th, wt = _gl(n_top, 0.0, np.pi / 2)
        r = lo + (hi - lo) * np.sin(th) ** 2
        jac = (hi - lo) * np.sin(2 * th) * wt
        arcs = _arc(r[:, None], rp, aj[None, :])
        A = arcs @ wts
        F[i] += np.sum(jac * r * A) / norm
        if want_psi:
            S = 2 * np.sin(arcs / 2) @ wts
            bq = r / (1.0 + z / d_sun)
            Fx[i] += np.sum(jac * r * S * (r / z - bq / d_sun)) / norm
    psi = np.zeros_like(F)
    if want_psi:
        ok = F > 0
        # subtract the direction of the Sun's centre seen from the point
        psi[ok] = Fx[ok] / F[ok] - rho_p[ok] * d_sun / (z * (d_sun + z))
    return F, psi


def fraction_geometric_planar(z, rho_p, d_sun=AU_KM, sun_radius_km=SUN_RADIUS_KM,
                              earth_radius_km=ap.R_EARTH_KM):
    """Uniform-disc visible fraction in the planar cone model (independent
    closed form, two-circle lens area with mpmath-free stable segments)."""
    a = z * sun_radius_km / d_sun
    R = earth_radius_km * (1 + z / d_sun)
    rho_p = np.atleast_1d(np.asarray(rho_p, dtype=float))
    out = np.empty_like(rho_p)
    for i, d in enumerate(rho_p):
        if d >= R + a:
            out[i] = 1.0
        elif d <= R - a:
            out[i] = 0.0
        else:
            # lens area of circle (0, R) and circle (d, a), via segments
            x = (a * a - (R - d) * (R + d)) / (2 * d)
            ca = np.clip(x / a, -1, 1)
            seg_a = a * a * np.arccos(ca) - x * np.sqrt(max(a * a - x * x, 0.0))
            xr = d - x                                    # chord distance from Earth centre
            seg_R = R * R * 2 * np.arcsin(np.sqrt(max(a * a - x * x, 0.0)) / R) / 2 \
                - xr * np.sqrt(max(a * a - x * x, 0.0))
            out[i] = 1.0 - (seg_a + seg_R) / (np.pi * a * a)
    return out
