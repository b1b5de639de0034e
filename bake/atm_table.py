# SPDX-License-Identifier: MIT
"""The runtime table of sunlight through the atmosphere (issue 4).

fraction_atm and the light's mean direction psi (bake.atm_rays.fraction) on a
grid in coordinates that follow the shadow:

  rows: z, the distance behind the Earth's centre along the anti-Sun axis,
      NZ rows log-spaced from Z_MIN to Z_MAX;
  along rho (distance from the axis), a window between
        rc     = R (1 + z/d)          the geometric shadow's radius,
        a      = z R_sun / d          the solar disc's radius there,
        rho_lo = M(v_lo), M(v_lo) = max(0, M(h_c) - 1.2 a): below it no
                 unblocked refracted ray arrives and F = 0 exactly,
        rho_hi = rc + a + TOP_KM: above it the geometric fraction (1),
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

Stored: q = log10(F + F_FLOOR) and psi (rad) as 16-bit codes, bilinear in
(node row, node index). Outside [Z_MIN, Z_MAX] (inside the reach) the runtime
falls back to the geometric fraction with a warning. The C lookup
(src/atmosphere.c) computes the same coordinates as `lookup` below, solving
for the ray altitude by a safeguarded Halley iteration instead of the
bisection: the two agree to ~1e-12 of a cell (tests/c/test_atmosphere.c).
"""
from __future__ import annotations

import os

import numpy as np

from . import atm_profile as ap
from . import atm_rays as ar
from .common.emit import round_sig

Z_MIN = 500.0            # km behind the Earth's centre
Z_MAX = 5.0e5            # km (beyond the Moon's apogee, 4.07e5 km)
D_MIN = 0.9832 * ar.AU_KM   # perihelion (~0.98329 AU)
D_MAX = 1.0168 * ar.AU_KM   # aphelion (~1.01671 AU)
F_FLOOR = 1e-8
H_A = 6.5                # km: e-folding of the bending in the coordinate map
V_MID = 60.0             # km: ray altitude where segment A hands over to B
W_RHO = 0.5              # weight of the uniform-in-rho part of segment A's coordinate
                         # (0.5: max |dF| 3.0e-3, rel. 8 % for F > 1e-4; 0: 3.9e-3, 74 %)
NZ, NA, NB = 48, 72, 13  # rows in z; nodes in segment A (incl. both ends), B
NT = NA + NB
ND = 1
MEASURE_SEED = 1         # seed of the measurement points
Q_MIN, Q_MAX = np.log10(F_FLOOR), 1e-3   # range of the stored q (16-bit codes)
U16 = 65535
N_BISECT = 48


def reach(rays: ar.Rays) -> float:
    """Bending of the lowest unblocked ray (rad): the coordinate map's scale."""
    return float(rays.alpha[0])


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

    def __init__(self, z, d, alpha_c, h_c, R=ap.R_EARTH_KM, top=ap.TOP_KM):
        self.z, self.alpha_c, self.h_c = z, alpha_c, h_c
        self.rc = R * (1.0 + z / d)
        self.a = z * ar.SUN_RADIUS_KM / d
        self.rho_hi = self.rc + self.a + top
        target = max(0.0, _m(h_c, z, self.rc, alpha_c, h_c) - 1.2 * self.a)
        self.v_lo = _solve_v(target, z, self.rc, alpha_c, h_c, h_c - 60.0, h_c)
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
    return np.linspace(D_MIN, D_MAX, nd) if nd > 1 else np.array([ar.AU_KM])


def bake(rays: ar.Rays, progress=False):
    """q (ND, NZ, NT), psi (ND, NZ, NT), alpha_c, h_c."""
    alpha_c = reach(rays)
    h_c = float(rays.h0[0])
    zs, ds = grid_z(), grid_d()
    nt = NT
    q = np.empty((ND, NZ, nt))
    psi = np.empty((ND, NZ, nt))
    for k, d in enumerate(ds):
        for i, z in enumerate(zs):
            rho = Window(z, d, alpha_c, h_c).nodes()
            F, p = ar.fraction(rays, z, rho, d_sun=d)
            q[k, i] = np.log10(F + F_FLOOR)
            psi[k, i] = p
            if progress:
                print(f"\r  atm table row {k * NZ + i + 1}/{ND * NZ}", end="", flush=True)
    if progress:
        print()
    return q, psi, alpha_c, h_c


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


def measure(rays, q, psi, alpha_c, h_c, n=400, seed=MEASURE_SEED, progress=False):
    """Errors of the lookup against the reference at random off-grid points
    (fixed seed): z log-uniform, rho uniform in the window, d uniform."""
    rng = np.random.default_rng(seed)
    zs = Z_MIN * (Z_MAX / Z_MIN) ** rng.uniform(0, 1, n)
    ds = rng.uniform(D_MIN, D_MAX, n)
    ts = rng.uniform(0, 1, n)
    out = []
    for m in range(n):
        nodes = Window(zs[m], ds[m], alpha_c, h_c).nodes()
        rho = np.interp(ts[m] * (NT - 1), np.arange(NT), nodes)
        F, p = ar.fraction(rays, zs[m], [rho], d_sun=ds[m])
        Fl, pl, st = lookup(q, psi, alpha_c, h_c, zs[m], rho, ds[m])
        if st == 1:
            Fl, pl = ar.fraction(None, zs[m], [rho], d_sun=ds[m])
            Fl, pl = Fl[0], pl[0]
        out.append((zs[m], rho, ds[m], F[0], Fl, p[0], pl))
        if progress and (m + 1) % 50 == 0:
            print(f"\r  measure {m + 1}/{n}", end="", flush=True)
    if progress:
        print()
    a = np.array(out)
    F, Fl = a[:, 3], a[:, 4]
    abs_err = np.abs(Fl - F)
    big = F > 1e-4
    rel = np.abs(Fl[big] - F[big]) / F[big]
    w = F > 1e-3
    psi_err = np.abs(a[w, 6] - a[w, 5])
    # rounded: the text of the provenance must not depend on libm's last bits
    r = round_sig
    return {
        "n_points": int(n),
        "max_abs_error": r(abs_err.max()),
        "rms_abs_error": r(np.sqrt(np.mean(abs_err ** 2))),
        "max_rel_error_F_gt_1e-4": r(rel.max()) if rel.size else 0.0,
        "max_psi_error_rad_F_gt_1e-3": r(psi_err.max()) if psi_err.size else 0.0,
    }, a


# ---------------------------------------------------------------- quantisation

def quantise(q, psi):
    """16-bit codes of q (fixed range Q_MIN..Q_MAX) and psi (range from the
    data, rounded outwards to 1e-3 rad), and the values they decode to:
    value = min + scale * code. Returns (uq, up, q_dec, psi_dec, scales)."""
    pmin = np.floor(psi.min() * 1e3) / 1e3
    pmax = np.ceil(psi.max() * 1e3) / 1e3
    if pmax <= pmin:
        pmax = pmin + 1e-3
    qs = (Q_MAX - Q_MIN) / U16
    ps = (pmax - pmin) / U16
    uq = np.clip(np.rint((np.clip(q, Q_MIN, Q_MAX) - Q_MIN) / qs), 0, U16).astype(np.uint16)
    up = np.clip(np.rint((psi - pmin) / ps), 0, U16).astype(np.uint16)
    return uq, up, Q_MIN + qs * uq, pmin + ps * up, {"Q_MIN": Q_MIN, "Q_SCALE": qs,
                                                      "PSI_MIN": pmin, "PSI_SCALE": ps}


# ---------------------------------------------------------------- emitter

NAME = "oi_atm_vband"
TABLE_FORMAT = 3         # OI_ATM_FORMAT in include/oi_table.h
GENERATOR = "bake.atmosphere"
GOAL_ABS_F = 1e-2        # goal: max |F error| of the lookup (absolute fraction)
# Transitional: tables/oi_atm_table.h with the former macros, read by
# src/atmosphere.c and tests/c/test_atmosphere.c until they take the struct.
COMPAT_HEADER = True
LAYOUT = ("format", "kind", "info", "nz", "nt", "na", "nb", "z_min_km", "z_max_km", "h_a_km",
          "v_mid_km", "alpha_c_rad", "h_c_km", "top_km", "w_rho", "f_floor", "earth_radius_km",
          "sun_radius_km", "au_km", "q_min", "q_scale", "psi_min_rad", "psi_scale_rad", "e_mid",
          "c_iu", "ln10", "q", "psi")


def derived_constants(nz, z_min, z_max, v_mid, h_c, h_a):
    """e_mid, c_iu, ln10 correctly rounded (mpmath at 200 bits from the exact
    doubles): their printed value does not depend on any libm."""
    import mpmath
    with mpmath.workprec(200):
        e_mid = mpmath.exp(-(mpmath.mpf(v_mid) - mpmath.mpf(h_c)) / mpmath.mpf(h_a))
        c_iu = mpmath.mpf(nz - 1) / mpmath.log(mpmath.mpf(z_max) / mpmath.mpf(z_min))
        ln10 = mpmath.log(10)
        return float(e_mid), float(c_iu), float(ln10)


def table(uq, up, scales, alpha_c, h_c, err, profile: ap.Profile):
    """The Table of the atmosphere bake (bake/common/emit.py)."""
    from . import __version__
    from .common import emit as cemit
    uq, up = uq[0], up[0]
    e_mid, c_iu, ln10 = derived_constants(NZ, Z_MIN, Z_MAX, V_MID, h_c, H_A)
    reals = [
        ("z_min_km", Z_MIN), ("z_max_km", Z_MAX), ("h_a_km", H_A), ("v_mid_km", V_MID),
        ("alpha_c_rad", alpha_c), ("h_c_km", h_c), ("top_km", profile.top_km), ("w_rho", W_RHO),
        ("f_floor", F_FLOOR), ("earth_radius_km", profile.earth_radius_km),
        ("sun_radius_km", ar.SUN_RADIUS_KM), ("au_km", ar.AU_KM),
        ("q_min", scales["Q_MIN"]), ("q_scale", scales["Q_SCALE"]),
        ("psi_min_rad", scales["PSI_MIN"]), ("psi_scale_rad", scales["PSI_SCALE"]),
        ("e_mid", e_mid), ("c_iu", c_iu), ("ln10", ln10)]
    ints = [("nz", NZ), ("nt", NT), ("na", NA), ("nb", NB)]
    prof = {k: getattr(profile, k) for k in (
        "kind", "n0", "top_km", "extinction", "cloud_top_km", "ozone_du",
        "aer_trop_tau", "aer_strat_tau")}
    params = {"profile": prof, "n_bisect": N_BISECT,
              "grid": {"nz": NZ, "na": NA, "nb": NB, "z_min_km": Z_MIN, "z_max_km": Z_MAX,
                       "h_a_km": H_A, "v_mid_km": V_MID, "w_rho": W_RHO, "f_floor": F_FLOOR},
              "measure": {"n_points": err["n_points"], "seed": MEASURE_SEED},
              "goal_abs_f": GOAL_ABS_F}
    prov = [
        "Sunlight through the atmosphere into the Earth's shadow: fraction F of",
        "unobstructed sunlight and its mean direction psi (docs/atmosphere.md).",
        f"Profile: {profile.kind} (1976 U.S. Standard Atmosphere density, N_s = {profile.n0:.6g} at 550 nm),",
        f"  top {profile.top_km:g} km; extinction {'on' if profile.extinction else 'off'}: Rayleigh (Bodhaine 1999),",
        f"  ozone {profile.ozone_du:g} DU (Chappuis), aerosol tau {profile.aer_trop_tau:g} (trop.) +"
        f" {profile.aer_strat_tau:g} (strat.) at 550 nm;",
        f"  clouds opaque below {profile.cloud_top_km:g} km; V band (Bessell 1990) x 5772 K black body;",
        "  solar disc: Neckel & Labs (1994) limb darkening at 559.95 nm.",
        f"Grid: z = {Z_MIN:g} .. {Z_MAX:g} km behind the Earth's centre, {NZ} rows log-spaced;",
        f"  along rho {NT} nodes: {NA} uniform in a blend ({1 - W_RHO:g} : {W_RHO:g}) of the model ray altitude",
        f"  v (h_a = {H_A:g} km, alpha_c = {alpha_c:.9g} rad at h_c = {h_c:g} km) and rho, up to",
        f"  v = {V_MID:g} km, then {NB} uniform in rho up to rc + a + top; the Sun's distance",
        "  enters through the window (table baked at 1 AU).",
        "Values: q = log10(F + f_floor), psi (rad): mean direction of the light from the Sun's centre,",
        "  positive away from the Earth's centre; stored as 16-bit codes, value = min + scale * code",
        "  (q step 1.2e-4 dex, i.e. 2.8e-4 relative in F).",
        f"Measured against the ray reference at {err['n_points']} random off-grid points (seed {MEASURE_SEED},",
        "  z log-uniform, rho uniform along the nodes, d in [0.9832, 1.0168] AU), bilinear lookup:",
        f"  max |F error| {err['max_abs_error']:.3e} (goal {GOAL_ABS_F:g}), rms {err['rms_abs_error']:.3e},",
        f"  max relative error where F > 1e-4: {err['max_rel_error_F_gt_1e-4']:.3e},",
        f"  max psi error where F > 1e-3: {err['max_psi_error_rad_F_gt_1e-3']:.3e} rad.",
    ]
    grid = dict(ints + reals[:12])
    compat = None
    if COMPAT_HEADER:
        compat = True
    t = cemit.Table(
        name=NAME, kind="atmosphere", ctype="oi_atm_table", format=("OI_ATM_FORMAT", TABLE_FORMAT),
        summary="baked atmosphere table (V band): sunlight refracted into the shadow.",
        fields=[(k, v, "int") for k, v in ints] + [(k, v, "real") for k, v in reals],
        arrays=[("q", uq, "u16"), ("psi", up, "u16")], layout=LAYOUT,
        generator=GENERATOR, version=__version__, parameters=params, seed=MEASURE_SEED,
        goal=GOAL_ABS_F, max_error=cemit.round_sig(err["max_abs_error"] / GOAL_ABS_F),
        measured=err, grid=grid, provenance=prov)
    t.compat = compat and dict(ints + reals)
    return t


def compat_header(t):
    """Text of the transitional tables/oi_atm_table.h (the former macros)."""
    from .common.emit import c_double
    c = t.compat
    lines = ["/* SPDX-License-Identifier: MIT */",
             "/*",
             " * oi_atm_table.h: transitional names of the atmosphere table %s" % t.name,
             " * for src/atmosphere.c and tests/c/test_atmosphere.c until they read the",
             " * struct (generated with it by `python -m bake atmosphere`; do not edit).",
             " */",
             "#ifndef OI_ATM_TABLE_H", "#define OI_ATM_TABLE_H", "",
             '#include "%s.h"' % t.name, "",
             "#define OI_ATM_TABLE_FORMAT 2",
             "#define OI_ATM_NZ (%d)" % c["nz"], "#define OI_ATM_NT (%d)" % c["nt"],
             "#define OI_ATM_NA (%d)" % c["na"], "#define OI_ATM_NB (%d)" % c["nb"],
             "#define OI_ATM_N_BISECT (%d)" % N_BISECT]
    for k in ("z_min_km", "z_max_km", "h_a_km", "v_mid_km", "alpha_c_rad", "h_c_km", "top_km",
              "w_rho", "f_floor", "earth_radius_km", "sun_radius_km", "au_km", "q_min", "q_scale",
              "psi_min_rad", "psi_scale_rad"):
        lines.append("#define OI_ATM_%s (%s)" % (k.upper(), c_double(c[k])))
    lines += ["#define oi__atm_q (%s.q)" % t.name, "#define oi__atm_psi (%s.psi)" % t.name,
              "", "#endif /* OI_ATM_TABLE_H */", ""]
    return "\n".join(lines)


def emit(outdir, uq, up, scales, alpha_c, h_c, err, profile: ap.Profile):
    """Write tables/oi_atm_vband.{c,h,json}: byte-for-byte reproducible."""
    from .common import emit as cemit
    t = table(uq, up, scales, alpha_c, h_c, err, profile)
    cemit.write(outdir, t)
    if t.compat:
        with open(os.path.join(outdir, "oi_atm_table.h"), "w", encoding="ascii", newline="\n") as f:
            f.write(compat_header(t))
    return {"bytes": t.payload_bytes(), "sha256": t.payload_sha256()}


def main(argv=None):
    import argparse
    import time
    ap_ = argparse.ArgumentParser(description="bake the atmosphere table (issue 4)")
    ap_.add_argument("--out", default="tables")
    ap_.add_argument("--measure", type=int, default=300, help="off-grid test points")
    ap_.add_argument("--vectors", default=None,
                     help="also write C test vectors to this path (tests/c/ref_atmosphere.h)")
    args = ap_.parse_args(argv)
    t0 = time.time()
    profile = ap.us1976()
    rays = ar.make_rays(profile)
    q, psi, alpha_c, h_c = bake(rays, progress=True)
    uq, up, q, psi, scales = quantise(q, psi)     # measure what the runtime stores
    err, _ = measure(rays, q, psi, alpha_c, h_c, n=args.measure, progress=True)
    meta = emit(args.out, uq, up, scales, alpha_c, h_c, err, profile)
    if args.vectors:
        write_vectors(args.vectors, rays, q, psi, alpha_c, h_c)
    print(f"atm table: {meta['bytes']} bytes, max |dF| {err['max_abs_error']:.2e}, "
          f"{time.time() - t0:.0f} s -> {args.out}/{NAME}.*")


# ---------------------------------------------------------------- C test vectors

def write_vectors(path, rays, q, psi, alpha_c, h_c, n_per_z=6, seed=7):
    """tests/c/ref_atmosphere.h: points with (a) the reference fraction from
    bake.atm_rays (independent of the table) and (b) the Python mirror of the
    lookup (the C code must reproduce it)."""
    rng = np.random.default_rng(seed)
    u = np.array([0.3, -0.8, 0.52])
    u /= np.linalg.norm(u)
    e = np.cross(u, [0.0, 0.0, 1.0])
    e /= np.linalg.norm(e)
    rows = []
    for z in (800.0, 1500.0, 3000.0, 7000.0, 20000.0, 42164.0, 150000.0, 384400.0):
        for _ in range(n_per_z):
            d = rng.uniform(D_MIN, D_MAX)
            w = Window(z, d, alpha_c, h_c)
            rho = w.rho_lo + rng.uniform(0.02, 0.98) * (w.rho_hi - w.rho_lo)
            F, p = ar.fraction(rays, z, [rho], d_sun=d)
            Fl, pl, st = lookup(q, psi, alpha_c, h_c, z, rho, d)
            sun = d * u
            pt = -z * u + rho * e
            rows.append((sun, pt, F[0], p[0], Fl, pl))
    lines = ["/* SPDX-License-Identifier: MIT */",
             "/* ref_atmosphere.h: generated by `python -m bake.atm_table --vectors` (bake/atm_table.py,",
             " * write_vectors); do not edit. Columns: sun_km[3], point_km[3], F_ref, psi_ref (rad)",
             " * from the deterministic reference bake/atm_rays.fraction (independent of the table),",
             " * F_lut, psi_lut from the Python mirror of the table lookup. */",
             "#ifndef REF_ATMOSPHERE_H", "#define REF_ATMOSPHERE_H", "",
             "typedef struct ref_atm { double sun[3], point[3], f_ref, psi_ref, f_lut, psi_lut; } ref_atm;",
             f"#define REF_ATM_N {len(rows)}",
             "static const ref_atm ref_atm_cases[REF_ATM_N] = {"]
    for sun, pt, F, p, Fl, pl in rows:
        v = list(sun) + list(pt)
        lines.append("    {{%s}, {%s}, %s, %s, %s, %s}," % (
            ", ".join("%.17g" % x for x in v[:3]), ", ".join("%.17g" % x for x in v[3:]),
            "%.17g" % F, "%.17g" % p, "%.17g" % Fl, "%.17g" % pl))
    lines += ["};", "", "#endif", ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))


def load_table(tables_dir="tables"):
    """Read the committed table back from its generated C source: (q, psi,
    alpha_c, h_c) decoded, shaped (1, NZ, NT), for the Python mirror."""
    from .common import emit as cemit
    with open(os.path.join(tables_dir, NAME + ".c"), encoding="ascii") as f:
        parsed = cemit.parse_c(f.read())
    t = parsed["structs"][NAME]["fields"]
    nz, nt = t["nz"], t["nt"]
    q = t["q_min"] + t["q_scale"] * parsed["arrays"][NAME + "_q"].astype(float)
    psi = t["psi_min_rad"] + t["psi_scale_rad"] * parsed["arrays"][NAME + "_psi"].astype(float)
    return q.reshape(1, nz, nt), psi.reshape(1, nz, nt), t["alpha_c_rad"], t["h_c_km"]


if __name__ == "__main__":
    main()
