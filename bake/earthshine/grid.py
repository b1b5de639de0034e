# SPDX-License-Identifier: MIT
"""The earthshine table's grid: its coordinates and the values stored at its nodes.

Coordinates (docs/earthshine-table.md)
--------------------------------------
altitude:  w = acos(x) = atan2(sqrt(h (2R + h)), R), the angular radius of the
           visible cap seen from the Earth's centre; nodes uniform in w on
           [w_min, w_max]; w_max = pi/2 is the point at infinity (x = 0).
theta:     two segments sharing one node column:
           lit  segment (whole visible cap lit) theta = v (pi/2 - w),     v in [0, 1]
           term segment (terminator crosses it) theta = pi/2 + w m(2v - 1), v in [0, 1],
                m(t) = sinh(k t)/sinh(k), k = term_k0 x^term_kp: nodes denser
                around theta = pi/2 at low altitude (the terminator crossing the
                nadir, a feature ~h/R wide), uniform (k -> 0) far away
           beyond theta = pi/2 + w the visible cap is dark: phi = 0 exactly.
stored:    see include/oi_table.h (format 4) and node_values.
The interpolation (the runtime's mirror) is bake/earthshine/lookup.py, the
error measurement bake/earthshine/measure.py.
"""

import math

import numpy as np

from ..common.progress import Progress
from . import reference as ref

HALF_PI = 0.5 * math.pi
# Terminator map k = TERM_K0 x^TERM_KP (measured: 0.745 -> 0.47 of the goal for
# the default grid against the uniform map, docs/earthshine-table.md).
TERM_K0 = 2.0
TERM_KP = 8.0
# Lowest altitude of the error measurement (1 m): a table that starts at the
# surface (w_min = 0) is measured from there up.
H_MEASURE_MIN_KM = 1e-3
K_SMALL = 1e-4  # below: m(t) = t (the map's deviation is k^2/6 ~ 2e-9)


def term_k(spec, x):
    return spec.term_k0 * np.power(np.asarray(x, dtype=float), spec.term_kp)


def term_m(t, k):
    """m(t) = sinh(k t)/sinh(k) (t for small k)."""
    k = np.asarray(k, dtype=float)
    small = k < K_SMALL
    ks = np.where(small, 1.0, k)
    return np.where(small, t, np.sinh(ks * t) / np.sinh(ks))


def term_t(m, k):
    """Inverse of term_m: t = asinh(m sinh k)/k (m for small k)."""
    k = np.asarray(k, dtype=float)
    small = k < K_SMALL
    ks = np.where(small, 1.0, k)
    return np.where(small, m, np.arcsinh(m * np.sinh(ks)) / ks)


class TableSpec:
    """Grid of one earthshine table."""

    def __init__(self, n_lit, n_term, n_alt, w_min, w_max, term_k0=TERM_K0, term_kp=TERM_KP):
        self.term_k0 = float(term_k0)
        self.term_kp = float(term_kp)
        if not (self.term_k0 >= 0 and self.term_kp >= 0):
            raise ValueError("term_k0, term_kp must be >= 0")
        self.n_lit = int(n_lit)
        self.n_term = int(n_term)
        self.n_alt = int(n_alt)
        self.w_min = float(w_min)
        self.w_max = float(w_max)
        if min(self.n_lit, self.n_term, self.n_alt) < 2:
            raise ValueError("each axis needs at least 2 nodes")
        if not (0.0 <= self.w_min < self.w_max <= HALF_PI):
            raise ValueError("need 0 <= w_min < w_max <= pi/2")

    @property
    def n_theta(self):
        return self.n_lit + self.n_term

    @property
    def n_values(self):
        return self.n_theta * self.n_alt

    def bytes(self):
        """Flash bytes of the payload (q and psi as float32)."""
        return 2 * 4 * self.n_values

    def w_nodes(self):
        j = np.arange(self.n_alt)
        w = self.w_min + (self.w_max - self.w_min) * j / (self.n_alt - 1)
        w[-1] = self.w_max
        return w

    def h_range_km(self, radius_km=ref.R_EARTH_KM):
        return h_from_w(self.w_min, radius_km), h_from_w(self.w_max, radius_km)

    def as_dict(self):
        return dict(n_lit=self.n_lit, n_term=self.n_term, n_alt=self.n_alt,
                    w_min=self.w_min, w_max=self.w_max, term_k0=self.term_k0,
                    term_kp=self.term_kp)


def w_from_h(h_km, radius_km=ref.R_EARTH_KM):
    h = np.asarray(h_km, dtype=float)
    return np.arctan2(np.sqrt(h * (2.0 * radius_km + h)), radius_km)


def h_from_w(w, radius_km=ref.R_EARTH_KM):
    """Altitude (km) of w; inf at w = pi/2."""
    if w >= HALF_PI:
        return math.inf
    return radius_km * (1.0 / math.cos(w) - 1.0)


def node_coords(spec):
    """theta and x at every node, arrays (n_alt, n_theta)."""
    w = spec.w_nodes()[:, None]
    v_lit = np.linspace(0.0, 1.0, spec.n_lit)[None, :]
    v_term = np.linspace(0.0, 1.0, spec.n_term)[None, :]
    th_lit = v_lit * (HALF_PI - w)
    xw = np.where(w >= HALF_PI, 0.0, np.cos(w))
    th_term = HALF_PI + w * term_m(2.0 * v_term - 1.0, term_k(spec, xw))
    theta = np.concatenate([th_lit, th_term], axis=1)
    x = np.broadcast_to(np.cos(w), theta.shape).copy()
    x[np.broadcast_to(w >= HALF_PI, theta.shape)] = 0.0
    return theta, x

def reference_chunked(theta, x, order, label="reference", progress=None, chunk=2048):
    """phi, psi of the reference over flat arrays, in chunks with a progress bar.
    x = 0 (infinity) gives the limit phi / x^2 = p(theta), psi = 0: returned
    as q directly (see node_values)."""
    theta = np.asarray(theta, dtype=float).ravel()
    x = np.asarray(x, dtype=float).ravel()
    phi = np.empty_like(theta)
    psi = np.empty_like(theta)
    bar = Progress(theta.size, label, progress)
    for a in range(0, theta.size, chunk):
        b = min(a + chunk, theta.size)
        phi[a:b], psi[a:b] = ref.phi_psi_reference(theta[a:b], x[a:b], order, order)
        bar.step(b - a)
    return phi, psi


def _eval(theta, x, order, method, progress, photon_args, label):
    """phi, psi at flat arrays of points (quadrature or photon mapping)."""
    if method == "quadrature":
        return reference_chunked(theta, x, order, label, progress)
    if method == "photon":
        from ..photon import mapping as photon  # lazily: the photon mapper is optional

        args = dict(photon_args or {})
        res = photon.bake_phi(theta, x, int(args.get("n_photons", 2_000_000)),
                              int(args.get("seed", 1)))
        if isinstance(res, tuple):
            return np.asarray(res[0], dtype=float), np.asarray(res[1], dtype=float)
        _, ps = reference_chunked(theta, x, order, "psi (quadrature)", progress)
        return np.asarray(res, dtype=float), ps
    raise ValueError("unknown method %r" % method)


def node_values(spec, order=32, method="quadrature", progress=None, photon_args=None):
    """Stored values at the nodes (float64, shape (n_alt, n_theta)): the
    "q" and "psi" arrays of the table.

    terminator segment: q = phi / x^2 and psi.
    lit segment (format 4): where the visible cap is wholly lit, phi(theta, x)
    = cos(theta) phi(0, x) and tan psi = tan(theta) G(x) exactly (the
    azimuthal cos term of cos i integrates to zero over the cap, see
    surface_limit), so every lit column stores the same two functions of
    altitude: q0 = phi(0, x) / x^2 (in "q") and G (in "psi"); the runtime
    forms q = q0 cos(theta), psi = atan2(G sin(theta), cos(theta)).
    G is taken at theta = (pi/2 - w)/2."""
    theta, x = node_coords(spec)
    nl = spec.n_lit
    far = x <= 0.0
    q = np.empty_like(theta)
    psi = np.zeros_like(theta)
    surf = np.zeros(theta.shape, dtype=bool)
    if spec.w_min == 0.0:
        surf[0, :] = True  # the row w = 0 (h = 0): the limit, see surface_limit
    near = ~far & ~surf
    near[:, :nl] = False
    # the lit columns: phi(0, x) and G(x) once per row
    xr = x[:, 0]
    rows = (xr > 0.0) & ~surf[:, 0]
    th_g = 0.5 * (HALF_PI - spec.w_nodes()[rows])
    n_r = int(rows.sum())
    n_t = int(near.sum())
    phi, ps = _eval(np.concatenate([theta[near], np.zeros(n_r), th_g]),
                    np.concatenate([x[near], xr[rows], xr[rows]]), order, method, progress,
                    photon_args, "bake (%s)" % method)
    q[near] = phi[:n_t] / x[near] ** 2
    psi[near] = ps[:n_t]
    q0 = np.empty(spec.n_alt)
    g = np.zeros(spec.n_alt)
    q0[rows] = phi[n_t:n_t + n_r] / xr[rows] ** 2
    g[rows] = np.tan(ps[n_t + n_r:]) / np.tan(th_g)
    q0[xr <= 0.0] = ref.lambert_phase(0.0)
    q0[surf[:, 0]] = 2.0
    q[:, :nl] = q0[:, None]
    psi[:, :nl] = g[:, None]
    tf = far[:, nl:]
    q[:, nl:][tf] = ref.lambert_phase(theta[:, nl:][tf])
    psi[:, nl:][tf] = 0.0
    # divided by w (format 4): near the surface the terminator segment's q and
    # the lit segment's G vanish like w and w^2 (with log(1/w) factors that
    # cubic interpolation in w handles poorly); the runtime multiplies by w
    wn = spec.w_nodes()[1:, None] if spec.w_min == 0.0 else spec.w_nodes()[:, None]
    r0 = 1 if spec.w_min == 0.0 else 0
    q[r0:, nl:] /= wn
    psi[r0:, :nl] /= wn
    if surf.any():
        t = 2.0 * np.linspace(0.0, 1.0, spec.n_term) - 1.0
        q[0, nl:], psi[0, nl:] = surface_limit(term_m(t, term_k(spec, 1.0)))
    # The last terminator node, theta = pi/2 + w: phi = 0 there and the
    # reference's psi is a 0/0 (0 or a continuation value, by the last bits).
    # Defined as its limit from the lit side: the light comes from the one lit
    # point left, on the horizon towards the Sun, psi = pi/2 - w = asin(x)
    # (pi/2 on the surface row, 0 at infinity), in plain IEEE arithmetic.
    psi[:, -1] = HALF_PI - spec.w_nodes()
    return q, psi


def surface_limit(m):
    """q = phi / x^2 and psi of the terminator segment in the limit h -> 0
    (the node row w = 0; the lit segment's row is q0 = 2, G = 0).

    Where the visible cap is wholly lit (theta <= pi/2 - w) the azimuthal
    cos term of cos i integrates to zero, so phi(theta, x) = cos(theta)
    phi(0, x) exactly; phi(0, x) -> 2 (a flat Lambertian plane filling the
    lower hemisphere: (1/pi) int cos(i) dOmega = 2 cos(i)), so q -> 2 cos(theta)
    (the lit segment at w = 0 spans theta in [0, pi/2]). The terminator
    segment shrinks to theta = pi/2, where q -> 0 (q = O(w) there: the
    sun's elevation at the nadir is at most w). psi -> 0 on the lit side (tan
    psi = tan(theta) G(x), G = O(w^2)); in the dark-nadir half of the
    terminator segment only light from near the horizon arrives and psi ->
    pi/2 (logarithmically slowly at theta = pi/2 exactly). psi is outside the
    goal there (phi < 1% of phi(0, x)); the runtime clamps it to
    [0, pi/2 - w]."""
    m = np.asarray(m, dtype=float)  # (theta - pi/2) / w in [-1, 1]
    # q / w -> 2 max(0, -m): the flat plane's 2 cos(theta), cos(theta) ~ -w m
    q = np.where(m < 0.0, -2.0 * m, 0.0)
    psi = np.where(m < 0.0, 0.0, HALF_PI)
    return q, psi
