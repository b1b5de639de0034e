# SPDX-License-Identifier: MIT
"""The earthshine table's coordinates, node values and interpolation (mirror of
src/earthshine.c), and the error measurement against the reference.

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
stored:    q = phi / x^2 (-> Lambert p(theta) at x = 0) and psi (rad), float32.
interp:    Catmull-Rom (cubic convolution, a = -1/2) in v and in w, per segment,
           ghost nodes by linear extrapolation (f[-1] = 2 f[0] - f[1]) at every
           segment end, so no stencil crosses the kink of the theta map.
"""

import math
import sys
import time

import numpy as np

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


class Progress:
    """A minimal progress bar on stderr (only when stderr is a terminal or forced)."""

    def __init__(self, total, label, enabled=None):
        self.total = max(int(total), 1)
        self.done = 0
        self.label = label
        self.t0 = time.monotonic()
        self.enabled = sys.stderr.isatty() if enabled is None else enabled

    def step(self, n):
        self.done += n
        if self.enabled:
            frac = min(self.done / self.total, 1.0)
            bar = "#" * int(30 * frac)
            sys.stderr.write("\r%-28s [%-30s] %5.1f%% %6.1fs" % (self.label, bar, 100 * frac,
                                                                time.monotonic() - self.t0))
            if self.done >= self.total:
                sys.stderr.write("\n")
            sys.stderr.flush()


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
        from . import photon  # lazily: the photon mapper is optional

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


# ----------------------------------------------------------------- interpolation

def _cr_weights(f):
    f2 = f * f
    f3 = f2 * f
    return (0.5 * (-f3 + 2 * f2 - f), 0.5 * (3 * f3 - 5 * f2 + 2),
            0.5 * (-3 * f3 + 4 * f2 + f), 0.5 * (f3 - f2))


def _segment_interp(tab, fv, fw, kind="cubic", surface=False):
    """Catmull-Rom on one segment tab[n_alt, n] at fractional indices (fv along
    theta, fw along altitude), ghosts by linear extrapolation; kind="linear":
    bilinear (for the comparison in the report). surface: the first row is
    w = 0, its ghost row by quadratic extrapolation."""
    n_alt, n = tab.shape
    if kind == "linear":
        i = np.clip(np.floor(fv).astype(int), 0, n - 2)
        a = fv - i
        j = np.clip(np.floor(fw).astype(int), 0, n_alt - 2)
        b = fw - j
        return ((1 - a) * (1 - b) * tab[j, i] + a * (1 - b) * tab[j, i + 1]
                + (1 - a) * b * tab[j + 1, i] + a * b * tab[j + 1, i + 1])
    T = np.pad(tab, 1, mode="reflect", reflect_type="odd")  # ghost = 2 f0 - f1
    if surface and n_alt >= 3:
        # the row w = 0: quadratic extrapolation (q = 2w - 2w^2 + ... at the
        # lit edge: the linear ghost cost 7x the goal at h ~ 150 m)
        T[0, :] = 3.0 * T[1, :] - 3.0 * T[2, :] + T[3, :]
    i = np.clip(np.floor(fv).astype(int), 0, n - 2)
    a = fv - i
    j = np.clip(np.floor(fw).astype(int), 0, n_alt - 2)
    b = fw - j
    wa = _cr_weights(a)
    wb = _cr_weights(b)
    out = np.zeros(np.shape(fv))
    for p in range(4):
        row = np.zeros(np.shape(fv))
        for k in range(4):
            row = row + wb[k] * T[j + k, i + p]
        out = out + wa[p] * row
    return out


def lookup(spec, q_tab, psi_tab, theta, x, kind="cubic"):
    """Interpolated (phi, psi) at (theta, x) inside the altitude range of the
    table: the numpy mirror of the runtime's lookup (double precision)."""
    theta = np.clip(np.asarray(theta, dtype=float), 0.0, math.pi)
    x = np.asarray(x, dtype=float)
    theta, x = np.broadcast_arrays(theta, x)
    w = np.arctan2(np.sqrt((1.0 - x) * (1.0 + x)), x)
    fw = (w - spec.w_min) / (spec.w_max - spec.w_min) * (spec.n_alt - 1)
    tb = HALF_PI - w
    lit = theta <= tb
    with np.errstate(divide="ignore", invalid="ignore"):
        v_lit = np.where(tb > 0, theta / np.where(tb > 0, tb, 1.0), 0.0)
        m = np.clip((theta - HALF_PI) / w, -1.0, 1.0)
        v_term = 0.5 * (term_t(m, term_k(spec, x)) + 1.0)
    fl = np.clip(v_lit, 0, 1) * (spec.n_lit - 1)
    ft = np.clip(v_term, 0, 1) * (spec.n_term - 1)
    sf = spec.w_min == 0.0
    q_lit = _segment_interp(q_tab[:, :spec.n_lit], fl, fw, kind, sf) * np.cos(theta)
    q_term = _segment_interp(q_tab[:, spec.n_lit:], ft, fw, kind, sf) * w
    g_lit = _segment_interp(psi_tab[:, :spec.n_lit], fl, fw, kind, sf) * w
    p_lit = np.arctan2(g_lit * np.sin(theta), np.cos(theta))
    p_term = _segment_interp(psi_tab[:, spec.n_lit:], ft, fw, kind, sf)
    q = np.where(lit, q_lit, q_term)
    ps = np.where(lit, p_lit, p_term)
    dark = theta >= HALF_PI + w
    phi = np.where(dark, 0.0, np.maximum(q, 0.0) * x * x)
    ps = np.where(phi > 0, np.clip(ps, 0.0, np.arcsin(np.clip(x, 0, 1))), 0.0)
    return phi, ps


# ----------------------------------------------------------------- error measurement

def goal_score(approx, phi, phi0, rel_goal=1e-3, abs_frac=None, big_frac=0.01):
    """Error in units of the goal: relative error / rel_goal where phi >= big_frac
    phi0, absolute error / (abs_frac phi0) elsewhere (abs_frac = rel_goal * big_frac
    by default: 1e-5 for the issue's goal). <= 1 meets the goal."""
    if abs_frac is None:
        abs_frac = rel_goal * big_frac
    big = phi >= big_frac * phi0
    err = np.abs(approx - phi)
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(big, err / (rel_goal * np.where(big, phi, 1.0)), err / (abs_frac * phi0))
    return s, big


def sample_points(spec, n_random, seed=12345, refine=True):
    """Test points between the nodes: every cell centre of both segments, random
    points uniform in (v, w) per segment, random points uniform in (theta, w),
    and a dense band around the terminator theta = pi/2 +- w."""
    rng = np.random.default_rng(seed)
    w_n = spec.w_nodes()
    wc = 0.5 * (w_n[:-1] + w_n[1:])
    pts_t, pts_w = [], []

    def add(v, w, seg):
        w = np.asarray(w, dtype=float)
        if seg == 0:
            th = v * (HALF_PI - w)
        else:
            th = HALF_PI + w * term_m(2.0 * np.asarray(v) - 1.0, term_k(spec, np.cos(w)))
        pts_t.append(th.ravel())
        pts_w.append(w.ravel())

    for seg, n in ((0, spec.n_lit), (1, spec.n_term)):
        vn = np.linspace(0, 1, n)
        vc = 0.5 * (vn[:-1] + vn[1:])
        V, W = np.meshgrid(vc, wc, indexing="ij")
        add(V, W, seg)
        add(rng.uniform(0, 1, n_random), rng.uniform(spec.w_min, spec.w_max, n_random), seg)
    # a 5 x 5 sub-grid in every terminator cell around the nadir crossing
    # (v in [0.3, 0.8]) below 1000 km, where the error peaks in small spots
    k_hi = int(np.searchsorted(w_n, w_from_h(1000.0))) if refine else 0
    if k_hi > 0:
        sub = (np.arange(5) + 0.5) / 5
        vn = np.linspace(0, 1, spec.n_term)
        cells_v = np.nonzero((vn[:-1] >= 0.3 - 1.0 / (spec.n_term - 1)) & (vn[1:] <= 0.8 + 1.0 / (spec.n_term - 1)))[0]
        cells_w = np.arange(min(k_hi, spec.n_alt - 1))
        V = (vn[cells_v][:, None] + sub[None, :] * (vn[1] - vn[0])).ravel()
        W = (w_n[cells_w][:, None] + sub[None, :] * (w_n[1] - w_n[0])).ravel()
        VV, WW = np.meshgrid(V, W, indexing="ij")
        add(VV, WW, 1)
    # log-uniform in altitude (denser at the bottom, where the terminator is
    # hardest), theta uniform in the terminator band and over [0, pi]
    h_lo = max(h_from_w(spec.w_min), H_MEASURE_MIN_KM)
    h_hi = min(h_from_w(spec.w_max), 1e7)
    hh = 10 ** rng.uniform(math.log10(h_lo), math.log10(h_hi), n_random)
    wl = np.minimum(np.maximum(w_from_h(hh), spec.w_min), spec.w_max)
    add(rng.uniform(0, 1, n_random), wl, 1)
    pts_t.append(rng.uniform(0, math.pi, n_random))
    pts_w.append(wl)
    # near the surface (tables from below 100 km): 41 altitudes log-uniform
    # from 1 m (or the table's floor) to 100 km, 61 theta each across the
    # terminator segment (m in [-1, 1], jittered) and around the lit side's
    # 1% contour (cos theta ~ 0.005 .. 0.05)
    if h_lo < 100.0:
        hs = np.logspace(math.log10(h_lo), 2.0, 41) * (1.0 + 0.01 * rng.uniform(0, 1, 41))
        for hk in hs:
            wk = float(w_from_h(hk))
            if not (spec.w_min <= wk <= spec.w_max):
                continue
            mm = np.clip(np.linspace(-1.0, 1.0, 41) + rng.uniform(-0.02, 0.02, 41), -1.0, 1.0)
            tl = np.arccos(np.geomspace(0.005, 0.05, 20))
            pts_t.append(np.concatenate([HALF_PI + wk * mm, np.minimum(tl, HALF_PI - wk)]))
            pts_w.append(np.full(61, wk))
    # uniform in (theta, w)
    tt = rng.uniform(0, math.pi, n_random)
    ww = rng.uniform(spec.w_min, spec.w_max, n_random)
    pts_t.append(tt)
    pts_w.append(ww)
    theta = np.concatenate(pts_t)
    w = np.concatenate(pts_w)
    w = np.minimum(w, np.nextafter(HALF_PI, 0.0) - 1e-9)  # x > 0 for the reference
    w = np.maximum(w, w_from_h(H_MEASURE_MIN_KM))  # the measured range starts at 1 m
    return np.clip(theta, 0.0, math.pi), w


def measure(spec, q_tab, psi_tab, n_random=4000, order=32, progress=None, rel_goal=1e-3,
            seed=12345, kind="cubic", refine=True):
    """Maximum interpolation error of the table against the reference at
    points between the nodes. q_tab, psi_tab: the stored (float32) values."""
    theta, w = sample_points(spec, n_random, seed, refine)
    x = np.cos(w)
    phi_ref, psi_ref = reference_chunked(theta, x, order, "measure", progress)
    phi0, _ = reference_chunked(np.zeros_like(x), x, order, "measure phi(0,x)", progress)
    phi_i, psi_i = lookup(spec, q_tab.astype(np.float64), psi_tab.astype(np.float64), theta, x,
                          kind)
    s, big = goal_score(phi_i, phi_ref, phi0, rel_goal=rel_goal)
    with np.errstate(divide="ignore", invalid="ignore"):
        rel = np.where(big, np.abs(phi_i - phi_ref) / phi_ref, 0.0)
    absn = np.where(big, 0.0, np.abs(phi_i - phi_ref) / phi0)
    dpsi = np.where(big, np.abs(psi_i - psi_ref), 0.0)
    k = int(np.argmax(s))
    near_term = np.abs(theta - HALF_PI) <= w
    return dict(
        n_points=int(theta.size),
        max_score=float(s.max()),
        max_rel_err=float(rel.max()),
        max_abs_err_frac=float(absn.max()),
        max_psi_err_rad=float(dpsi.max()),
        max_score_terminator=float(s[near_term].max()) if near_term.any() else 0.0,
        worst_theta=float(theta[k]),
        worst_h_km=float(ref.h_from_x(x[k])),
    )
