# SPDX-License-Identifier: MIT
"""The atmosphere table's grid (the window that follows the shadow) and the
Python mirror of the runtime's lookup.

Fraction F of unobstructed sunlight and the light's mean direction psi
(bake/atmosphere/rays.py, `fraction`) on a grid in coordinates that follow
the shadow:

  rows: z, the distance behind the Earth's centre along the anti-Sun axis,
      NZ rows log-spaced from Z_MIN to Z_MAX;
  along rho (distance from the axis), a window between
        rc     = R (1 + z/d)          the geometric shadow's radius,
        a      = z R_sun / d          the solar disc's radius there,
        rho_lo = M(v_lo), M(v_lo) = max(0, M(h_c) - 1.2 a) (v_lo in [h_c - 60,
                 h_c], or up to V_MID where the target is the axis): below it no
                 unblocked refracted ray arrives and F = 0 exactly,
        rho_hi = rc + a + top: above it the geometric fraction (1),
      with M(v) = rc + v - z alpha_c exp(-(v - h_c) / H_A) the image radius
      of a ray of lowest altitude v in an exponential model of the bending
      (alpha_c the bending at the cloud top h_c). Segment A: NA nodes uniform
      in g = (1 - W_RHO) (v - v_lo)/(V_MID - v_lo) + W_RHO (rho - rho_lo)/(rho_mid
      - rho_lo), rho_mid = M(V_MID): the v part follows the refracted image of
      each altitude whatever z, the rho part resolves the geometric penumbra
      where M is steep (large z); segment B: NB nodes uniform in rho from
      M(V_MID) to rho_hi. d (the Sun's distance) moves and scales the window
      with the real penumbra; the table itself is baked at 1 AU and its
      measured error includes d over a year.

The grid constants come from bake/config/atmosphere.json. alpha_c (the
coordinate map's scale) is one of them: the bake checks it against the bending
the reference computes (to alpha_c_rel_tol) but does not take that value,
whose last bits depend on libm and the BLAS, so the grid does not move from
one machine to the next.

Stored: q = log10(F + F_FLOOR) and psi (rad) as 16-bit codes, bilinear in
(node row, node index). Outside [Z_MIN, Z_MAX] (inside the reach) the runtime
falls back to the geometric fraction with a warning. The C lookup computes the
same coordinates as `lookup` below, solving for the ray altitude by a
safeguarded Halley iteration instead of the bisection: the two agree to
~1e-12 of a cell (tests/c/test_atmosphere.c).
"""
from __future__ import annotations

import json
import os

import numpy as np

from ..common.constants import AU_KM, R_EARTH_KM, SUN_RADIUS_KM
from .profile import TOP_KM

CONFIG = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                      "config", "atmosphere.json")


def load_config(path=CONFIG):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


_G = load_config()["grid"]
Z_MIN = float(_G["z_min_km"])        # km behind the Earth's centre
Z_MAX = float(_G["z_max_km"])        # km (beyond the Moon's apogee, 4.07e5 km)
D_MIN = _G["d_min_au"] * AU_KM       # perihelion (~0.98329 AU)
D_MAX = _G["d_max_au"] * AU_KM       # aphelion (~1.01671 AU)
F_FLOOR = float(_G["f_floor"])
H_A = float(_G["h_a_km"])            # km: e-folding of the bending in the coordinate map
V_MID = float(_G["v_mid_km"])        # km: ray altitude where segment A hands over to B
W_RHO = float(_G["w_rho"])           # weight of the uniform-in-rho part of segment A's coordinate
                                     # (0.5: max |dF| 3.0e-3, rel. 8 % for F > 1e-4; 0: 3.9e-3, 74 %)
NZ, NA, NB = int(_G["nz"]), int(_G["na"]), int(_G["nb"])  # rows in z; nodes in A (both ends), B
NT = NA + NB
ND = 1
N_BISECT = int(_G["n_bisect"])
ALPHA_C = float(_G["alpha_c_rad"])   # rad: the coordinate map's scale (see above)
ALPHA_C_REL_TOL = float(_G["alpha_c_rel_tol"])


def _m(v, z, rc, alpha_c, h_c):
    """Image radius of the ray of lowest altitude v in the model
    alpha(v) = alpha_c exp(-(v - h_c) / H_A): rho = rc + v - z alpha(v)."""
    return rc + v - z * alpha_c * np.exp(-(v - h_c) / H_A)


def _solve_v(target, z, rc, alpha_c, h_c, v_a, v_b):
    """v in [v_a, v_b] with M(v) = target (bisection, N_BISECT steps)."""
    target = np.asarray(target, dtype=float)
    lo_v = np.full(target.shape, float(v_a))
    hi_v = np.full(target.shape, float(v_b))
    for _ in range(N_BISECT):
        mid = 0.5 * (lo_v + hi_v)
        below = _m(mid, z, rc, alpha_c, h_c) < target
        lo_v = np.where(below, mid, lo_v)
        hi_v = np.where(below, hi_v, mid)
    v = 0.5 * (lo_v + hi_v)
    return float(v) if v.ndim == 0 else v


class Window:
    """The coordinate along rho at one (z, d). Segment A: nodes uniform in
    the model ray altitude v from v_lo to V_MID (rho = M(v)); segment B:
    uniform in rho from M(V_MID) to rho_hi = rc + a + top."""

    def __init__(self, z, d, alpha_c, h_c, R=R_EARTH_KM, top=TOP_KM):
        self.z, self.alpha_c, self.h_c = z, alpha_c, h_c
        self.rc = R * (1.0 + z / d)
        self.a = z * SUN_RADIUS_KM / d
        self.rho_hi = self.rc + self.a + top
        target = _m(h_c, z, self.rc, alpha_c, h_c) - 1.2 * self.a
        # the window starts at the axis where the lowest ray's image has
        # crossed it (target <= 0): then v_lo, the ray landing on the axis,
        # lies above h_c
        v_top = h_c if target > 0.0 else V_MID
        target = max(0.0, target)
        self.v_lo = _solve_v(target, z, self.rc, alpha_c, h_c, h_c - 60.0, v_top)
        self.rho_lo = _m(self.v_lo, z, self.rc, alpha_c, h_c)
        self.rho_mid = _m(V_MID, z, self.rc, alpha_c, h_c)

    def g_a(self, rho):
        """Segment A coordinate in [0, 1]: (1 - W_RHO) x (fraction of the way
        in v) + W_RHO x (fraction of the way in rho)."""
        v = _solve_v(rho, self.z, self.rc, self.alpha_c, self.h_c, self.v_lo, V_MID)
        tv = (v - self.v_lo) / (V_MID - self.v_lo)
        tr = (np.asarray(rho) - self.rho_lo) / (self.rho_mid - self.rho_lo)
        return (1.0 - W_RHO) * tv + W_RHO * tr

    def index(self, rho):
        """Continuous node index in [0, NT - 1] of rho in [rho_lo, rho_hi]."""
        if rho >= self.rho_mid:
            return (NA - 1) + (rho - self.rho_mid) / (self.rho_hi - self.rho_mid) * NB
        return float(self.g_a(rho)) * (NA - 1)

    def nodes(self):
        gk = np.linspace(0.0, 1.0, NA)
        if W_RHO == 0.0:
            ra = _m(self.v_lo + gk * (V_MID - self.v_lo), self.z, self.rc, self.alpha_c, self.h_c)
        else:
            lo = np.full(NA, self.rho_lo)
            hi = np.full(NA, self.rho_mid)
            for _ in range(N_BISECT):
                mid = 0.5 * (lo + hi)
                below = self.g_a(mid) < gk
                lo = np.where(below, mid, lo)
                hi = np.where(below, hi, mid)
            ra = 0.5 * (lo + hi)
        ra[0], ra[-1] = self.rho_lo, self.rho_mid
        rb = self.rho_mid + (self.rho_hi - self.rho_mid) * np.arange(1, NB + 1) / NB
        return np.concatenate([ra, rb])


def coords(z, rho, d, alpha_c, h_c):
    """Continuous table indices (iu, it) of a point and its region: 0 inside,
    -1 below the window (F = 0), +1 above it (geometric fraction)."""
    w = Window(z, d, alpha_c, h_c)
    if rho >= w.rho_hi:
        return None, None, 1
    if rho < w.rho_lo:
        return None, None, -1
    iu = np.log(z / Z_MIN) / np.log(Z_MAX / Z_MIN) * (NZ - 1)
    return iu, w.index(rho), 0


def grid_z(nz=None):
    u = np.linspace(0.0, 1.0, nz or NZ)
    return Z_MIN * (Z_MAX / Z_MIN) ** u


def grid_d(nd=None):
    nd = nd or ND
    return np.linspace(D_MIN, D_MAX, nd) if nd > 1 else np.array([AU_KM])


def lookup(q, psi, alpha_c, h_c, z, rho, d):
    """Python mirror of the C lookup (tests, error measurement).
    Returns (F, psi, status): status 0 inside or below the window, +1 above
    it (F None: the caller uses the geometric fraction), +2 outside the z range."""
    nd, nz, nt = q.shape
    if not (Z_MIN <= z <= Z_MAX):
        return None, None, 2
    iu, it, region = coords(z, rho, d, alpha_c, h_c)
    if region < 0:
        return 0.0, 0.0, 0
    if region > 0:
        return None, None, 1
    s = 0.0 if nd == 1 else (d - D_MIN) / (D_MAX - D_MIN) * (nd - 1)
    s = min(max(s, 0.0), nd - 1.0)
    i = min(int(np.floor(iu)), nz - 2)
    j = min(max(int(np.floor(it)), 0), nt - 2)
    k = min(int(np.floor(s)), nd - 2) if nd > 1 else 0
    fu, ft, fs = iu - i, it - j, s - k

    def col(a, kk, ii):
        return (1 - ft) * a[kk, ii, j] + ft * a[kk, ii, j + 1]

    def bil(a, kk):
        return (1 - fu) * col(a, kk, i) + fu * col(a, kk, i + 1)

    if nd > 1:
        qv = (1 - fs) * bil(q, k) + fs * bil(q, k + 1)
        pv = (1 - fs) * bil(psi, k) + fs * bil(psi, k + 1)
    else:
        qv, pv = bil(q, 0), bil(psi, 0)
    F = max(10.0 ** qv - F_FLOOR, 0.0)
    return min(F, 1.0), pv, 0
