# SPDX-License-Identifier: MIT
"""Single-scattering reference: scalar irradiance and mean direction of the light the
sunlit atmosphere scatters towards a target above it (the table's node values).

Geometry: Earth-centred, the Sun along s = (sin theta, 0, cos theta) at infinity
(parallel rays, a point Sun), the target at P = (0, 0, r). A line of sight from the
target, u = (sin nu cos az, sin nu sin az, -cos nu), crosses the medium from the top
sphere to the top again or to the floor (the cloud deck, bake.skylight.medium). Along
it the radiance is

    L(u) = sum_groups w_g  int  [sca_R P_R(T) + sca_a P_HG(T)] / (4 pi)
                               exp(-tau_view - tau_sun)  dt,   cos T = s . u,

with tau_view from the target to the point and tau_sun from the point towards the
Sun (0 where the point is in the floor's geometric shadow: light). Lines of sight that
end on the sunlit floor (its hit point H with H . s > 0) count for nothing: their
light is the Earth's albedo, already in earthshine's uniform Lambertian Earth (its
0.3 holds the atmosphere's share over the lit disc). What remains is the light the
Lambertian Earth does not carry: the limb (lines missing the floor) and the air over
the night side.

    E_sky / E_sun = int L dOmega,   mean direction: the vector int L u dOmega.

Sun columns come from a table of species columns over (altitude, solar zenith) at
the scattering point, integrated by Gauss-Legendre along each Sun ray and read
bilinearly; the view path is a midpoint rule in t with cumulative optical depth;
the directions: Gauss-Legendre in nu on segments placed at fixed tangent heights
around the floor's horizon and where the terminator's curves (below) touch the
Sun-Earth plane, and Gauss-Legendre in azimuth over [0, pi] (mirror symmetry) on
intervals split where the line's deciding point (its floor hit, or its tangent point)
crosses the terminator and two depths past it: the lit floor's cut and the steep fall
of the lit air over the night side sit on interval ends, where a Gauss rule does not
see them as jumps.
"""
from __future__ import annotations

import numpy as np

from ..common.quadrature import gauss_legendre_01
from .medium import Medium, hg_phase, rayleigh_phase

# tangent-radius offsets (km) from the floor that bound the nu segments
_BREAKS_BELOW = (400.0, 120.0, 40.0, 12.0, 0.0)
_BREAKS_ABOVE = (4.0, 12.0, 25.0, 45.0, 70.0)
N_NU_SEG = 8          # Gauss-Legendre nodes per nu segment
N_AZ = 16             # Gauss-Legendre nodes per azimuth interval
# depths past the terminator (rad) whose curves split the azimuth: 0 (the terminator,
# the lit floor's edge), then inside the band of lit air over the night side, whose
# outer edge is acos(r_floor / r_top) ~ 9.5 deg for a vertical column
NIGHT_DEPTHS = (0.0, 0.05, 0.166)
N_BREAK_SCAN = 400    # scan steps over nu for the depth curves' touching points
N_PATH = 192          # midpoints along a line of sight
N_RHO = 361           # Sun-column table: altitude rows (floor .. top)
N_VDOWN = 400         # ... columns for the Sun below the local horizon
N_VUP = 160           # ... and above it
N_SUNRAY = 64         # Gauss-Legendre nodes per Sun-ray segment


class SunColumns:
    """Species columns (m^-2 and m^-1 x m) from a point towards the Sun, over the
    point's altitude and the cosine mu of the Sun's zenith angle there. Columns: v in
    [-1, 0): mu = v |mu_g| (mu_g: the floor's grazing cosine), v in [0, 1]: mu = v."""

    def __init__(self, med: Medium):
        self.med = med
        self.rho = np.linspace(med.r_floor, med.r_top, N_RHO)
        self.v = np.concatenate([np.linspace(-1.0, 0.0, N_VDOWN, endpoint=False),
                                 np.linspace(0.0, 1.0, N_VUP)])
        rho = self.rho[:, None]
        mu_g = -np.sqrt(np.maximum(0.0, 1.0 - (med.r_floor / rho) ** 2))
        mu = np.where(self.v[None, :] < 0, self.v[None, :] * (-mu_g), self.v[None, :])
        self.col = self._columns(rho * np.ones_like(mu), mu)

    def _columns(self, rho, mu):
        med = self.med
        x, w = gauss_legendre_01(N_SUNRAY)
        b2 = rho * rho * np.maximum(0.0, 1.0 - mu * mu)
        t0 = rho * mu
        t_top = np.sqrt(np.maximum(0.0, med.r_top ** 2 - b2))
        col = np.zeros((4,) + rho.shape)
        # segments: [t0, 0] (down to the tangent point) if t0 < 0, then [max(t0, 0), t_top]
        for lo, hi in ((np.minimum(t0, 0.0), np.zeros_like(t0)), (np.maximum(t0, 0.0), t_top)):
            span = np.maximum(hi - lo, 0.0)
            t = lo[..., None] + span[..., None] * x
            h = np.sqrt(b2[..., None] + t * t) - med.R
            n = med.species(np.minimum(h, med.profile.top_km))
            col += np.sum(n * w, axis=-1) * span * 1e3
        return col

    def transmission(self, rho, mu):
        """Band-group transmissions towards the Sun (G, n) at points of radius rho,
        Sun cosine mu (bilinear in the table of exp(-tau)); the caller has removed
        the points in the floor's shadow (mu < mu_g)."""
        med = self.med
        if not hasattr(self, "_trans"):
            tau = np.einsum("kg,kij->ijg", med.ext_w, self.col)
            self._trans = np.exp(-tau).reshape(-1, tau.shape[-1])
        mu_g = -np.sqrt(np.maximum(0.0, 1.0 - (med.r_floor / rho) ** 2))
        v = np.where(mu < 0, mu / np.where(mu_g < 0, -mu_g, 1.0), mu)
        v = np.clip(v, -1.0, 1.0)
        fi = (rho - self.rho[0]) / (self.rho[1] - self.rho[0])
        fi = np.clip(fi, 0.0, N_RHO - 1 - 1e-9)
        i = fi.astype(np.intp)
        a = (fi - i)[:, None]
        # the two uniform pieces of v
        fj = np.where(v < 0, (v + 1.0) * N_VDOWN, N_VDOWN + v * (N_VUP - 1))
        fj = np.clip(fj, 0.0, len(self.v) - 1 - 1e-9)
        j = fj.astype(np.intp)
        b = ((v - self.v[j]) / (self.v[j + 1] - self.v[j]))[:, None]
        nv = len(self.v)
        k = i * nv + j
        T = self._trans
        out = ((1 - a) * ((1 - b) * T[k] + b * T[k + 1]) +
               a * ((1 - b) * T[k + nv] + b * T[k + nv + 1]))
        return out.T


def _line_point(nu, r, med: Medium):
    """(t, |X|, hits) of the line of sight's point that decides what it sees: the hit
    point on the floor for lines that end there, else the closest approach to the
    Earth's centre (the tangent point)."""
    nu = np.asarray(nu, dtype=float)
    rt2 = (r * np.sin(nu)) ** 2
    tc = r * np.cos(nu)
    hits = rt2 < med.r_floor ** 2
    t = np.where(hits, tc - np.sqrt(np.maximum(med.r_floor ** 2 - rt2, 0.0)), tc)
    return t, np.where(hits, med.r_floor, np.sqrt(rt2)), hits


def _depth_azimuths(theta, r, nu, med: Medium):
    """(n_levels, n) azimuths in [0, pi] beyond which the line's point lies deeper
    than each of NIGHT_DEPTHS past the terminator (X . s < -sin(depth) |X|). With the
    point X = (t sin nu cos az, t sin nu sin az, r - t cos nu), X . s is
    D cos az + z cos theta, D = t sin nu sin theta >= 0."""
    t, rho, _ = _line_point(nu, r, med)
    d = t * np.sin(nu) * np.sin(theta)
    zc = (r - t * np.cos(nu)) * np.cos(theta)
    out = []
    for depth in NIGHT_DEPTHS:
        num = -np.sin(depth) * rho - zc          # deeper where D cos az < num
        c = np.where(d > 0.0, num / np.where(d > 0.0, d, 1.0), np.where(num > 0.0, 2.0, -2.0))
        out.append(np.arccos(np.clip(c, -1.0, 1.0)))
    return np.array(out)


def _depth_breaks(theta, r, med: Medium):
    """Nadir angles at which a depth curve of _depth_azimuths touches az = 0 or pi
    (where the interval in azimuth opens or closes, with a square-root edge)."""
    nu_top = float(np.arcsin(min(med.r_top / r, 1.0)))
    grid = np.linspace(0.0, nu_top, N_BREAK_SCAN + 1)[1:-1]
    out = []
    for sgn in (1.0, -1.0):                      # az = 0 and az = pi
        def f(nu, sgn=sgn):
            t, rho, _ = _line_point(nu, r, med)
            xs = (sgn * t * np.sin(nu) * np.sin(theta) +
                  (r - t * np.cos(nu)) * np.cos(theta))
            return xs[None] + np.sin(np.asarray(NIGHT_DEPTHS))[:, None] * np.atleast_1d(rho)[None]
        fv = f(grid)
        for k in range(len(NIGHT_DEPTHS)):
            ch = np.nonzero(np.sign(fv[k, :-1]) * np.sign(fv[k, 1:]) < 0)[0]
            for i in ch:
                a, b = grid[i], grid[i + 1]
                fa = fv[k, i]
                for _ in range(60):              # bisection to ~1e-18 of the span
                    m = 0.5 * (a + b)
                    fm = f(m)[k, 0]
                    if np.sign(fm) == np.sign(fa):
                        a, fa = m, fm
                    else:
                        b = m
                out.append(0.5 * (a + b))
    return out


def _nu_nodes(theta, r, med: Medium):
    """Nadir angles and weights (sin nu dnu folded in) covering the medium: Gauss-
    Legendre on segments bounded by fixed tangent heights around the floor's horizon
    and by the nadir angles where a depth curve touches the Sun-Earth plane."""
    x, w = gauss_legendre_01(N_NU_SEG)
    rt = [max(0.0, med.r_floor - d) for d in _BREAKS_BELOW[:-1]]
    rt = [0.0] + [v for v in rt if v > 0.0] + [med.r_floor]
    rt += [min(med.r_top, med.r_floor + d) for d in _BREAKS_ABOVE] + [med.r_top]
    nu_b = list(np.arcsin(np.minimum(np.array(sorted(set(rt))) / r, 1.0)))
    nu_b = np.unique(np.array(nu_b + _depth_breaks(theta, r, med)))
    nus, wts = [], []
    for a, b in zip(nu_b[:-1], nu_b[1:]):
        if b - a <= 1e-12 * max(b, 1e-300):
            continue
        nu = a + (b - a) * x
        nus.append(nu)
        wts.append((b - a) * w * np.sin(nu))
    return np.concatenate(nus), np.concatenate(wts)


def _directions(theta, r, med: Medium):
    """Lines of sight (nu, az) and weights (the solid angle, both azimuth halves) of
    the direction quadrature: in azimuth, Gauss-Legendre on the intervals between the
    depth curves (the terminator and the night depths at the line's point), only those
    past the terminator for lines that end on the floor (the lit floor is earthshine's):
    the cut and the steep fall of the lit air past the terminator lie on interval ends,
    not inside them."""
    nu, wnu = _nu_nodes(theta, r, med)
    _, _, hits = _line_point(nu, r, med)
    xa, wa = gauss_legendre_01(N_AZ)
    edges = _depth_azimuths(theta, r, nu, med)                  # (L, n), ascending
    lo = np.vstack([np.zeros_like(nu)[None], edges])            # interval starts
    hi = np.vstack([edges, np.full_like(nu, np.pi)[None]])
    lo[0] = np.where(hits, hi[0], lo[0])                        # lit floor: empty
    span = hi - lo
    keep = span > 1e-12
    k, i = np.nonzero(keep)
    NU = np.repeat(nu[i], N_AZ)
    AZ = (lo[k, i][:, None] + span[k, i][:, None] * xa[None]).ravel()
    W = ((wnu[i] * span[k, i])[:, None] * wa[None] * 2.0).ravel()
    return NU, AZ, W


class SingleScattering:
    """E_sky / E_sun and the mean direction at (theta, r) by quadrature."""

    def __init__(self, med: Medium | None = None):
        self.med = med or Medium()
        self.sun = SunColumns(self.med)

    def radiance(self, theta, r, nu, az):
        """Band radiance per unit solar irradiance (sr^-1) along lines of sight (nu, az)
        (arrays of one shape) from the target at (theta, r)."""
        med = self.med
        nu = np.asarray(nu, dtype=float)
        az = np.asarray(az, dtype=float)
        shape = nu.shape
        nu, az = nu.ravel(), az.ravel()
        s = np.array([np.sin(theta), 0.0, np.cos(theta)])
        u = np.stack([np.sin(nu) * np.cos(az), np.sin(nu) * np.sin(az), -np.cos(nu)])
        rt2 = (r * np.sin(nu)) ** 2
        tc = r * np.cos(nu)
        inside = rt2 < med.r_top ** 2
        t_in = tc - np.sqrt(np.maximum(med.r_top ** 2 - rt2, 0.0))
        hits = rt2 < med.r_floor ** 2
        t_out = np.where(hits, tc - np.sqrt(np.maximum(med.r_floor ** 2 - rt2, 0.0)),
                         tc + np.sqrt(np.maximum(med.r_top ** 2 - rt2, 0.0)))
        t_in = np.maximum(t_in, 0.0)
        hit_pt_s = r * s[2] + t_out * (s @ u)          # (P + t_out u) . s
        keep = inside & ~(hits & (hit_pt_s > 0.0))
        out = np.zeros(nu.size)
        if not np.any(keep):
            return out.reshape(shape)
        idx = np.nonzero(keep)[0]
        uu = u[:, idx]
        ti, to = t_in[idx], t_out[idx]
        dt = (to - ti) / N_PATH
        k = (np.arange(N_PATH) + 0.5) / N_PATH
        t = ti[:, None] + (to - ti)[:, None] * k[None, :]          # (m, N)
        X = np.array([0.0, 0.0, r])[:, None, None] + uu[:, :, None] * t[None]
        rho = np.sqrt(np.sum(X * X, axis=0))
        h = rho - med.R
        n = med.species(np.minimum(h, med.profile.top_km))           # (4, m, N)
        ext = np.einsum("kg,kmn->gmn", med.ext_w, n)                  # (G, m, N) per m
        tau_v = (np.cumsum(ext, axis=-1) - 0.5 * ext) * (dt * 1e3)[None, :, None]
        mu = np.einsum("i,imn->mn", s, X) / rho
        mu_g = -np.sqrt(np.maximum(0.0, 1.0 - (med.r_floor / rho) ** 2))
        lit = mu > mu_g
        trans = np.zeros((len(med.weight),) + rho.shape)
        li = np.nonzero(lit.ravel())[0]
        if li.size:
            tv = trans.reshape(len(med.weight), -1)
            tv[:, li] = self.sun.transmission(rho.ravel()[li], mu.ravel()[li])
        cos_t = (s @ uu)[:, None]
        pr = rayleigh_phase(cos_t)
        pa = hg_phase(cos_t)
        sca = (med.sca_w[0][:, None, None] * n[0][None] * pr[None] +
               (med.sca_w[2][:, None, None] * n[2][None] +
                med.sca_w[3][:, None, None] * n[3][None]) * pa[None])
        f = sca * np.exp(-tau_v) * trans
        band = np.einsum("g,gmn->mn", med.weight, f)
        out[idx] = np.sum(band, axis=-1) * dt * 1e3 / (4.0 * np.pi)
        return out.reshape(shape)

    def irradiance(self, theta, r):
        """(E_sky / E_sun, psi): scalar irradiance per unit solar irradiance and the
        mean direction's angle from the nadir towards the Sun (rad); psi = 0 where
        nothing is lit."""
        NU, AZ, wt = _directions(theta, r, self.med)
        L = self.radiance(theta, r, NU, AZ)
        e = float(np.sum(L * wt))
        vx = float(np.sum(L * wt * np.sin(NU) * np.cos(AZ)))
        vz = float(np.sum(L * wt * np.cos(NU)))       # towards the nadir
        psi = float(np.arctan2(vx, vz)) if e > 0 else 0.0
        return e, psi
