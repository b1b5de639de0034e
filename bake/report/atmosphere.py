# SPDX-License-Identifier: MIT
"""Report section: the atmosphere. `section(outdir) -> str`.

Every number is computed here from bake.atmosphere.profile / bake.atmosphere.rays /
bake.atmosphere; sources of the comparison values are cited inline.
"""
from __future__ import annotations

import json
import os
import time

import numpy as np

from ..atmosphere import profile as ap
from ..atmosphere import rays as ar
from ..atmosphere import table as at
from ..atmosphere import window as aw

R = ap.R_EARTH_KM
ROOT = os.path.join(os.path.dirname(__file__), "..", "..")


def _plt():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def _shell_rays(profile, K, spacing="uniform", dh=0.02):
    """A Rays object for the seed's constant-index shells (seed mode)."""
    radii, idx = ar.shell_model(profile, K, spacing)
    h0 = np.arange(0.0, profile.top_km + dh / 2, dh)
    # rays labelled by impact parameter b (= R + h0 here: in shells the
    # lowest point is not the label that matters, b is)
    b = R + h0
    alpha, hits = ar.shell_bending(radii, idx, b)
    T = np.where(hits, 0.0, 1.0)
    return ar.Rays(profile, h0, b, alpha, np.zeros((4, b.size)), T, R)


def _crossing_distance(rays, h):
    """Distance behind the Earth where the ray of lowest altitude h crosses
    the axis (parallel light): rho = b / cos(g) - z tan(g) = 0."""
    b = np.interp(h, rays.h0, rays.b)
    g = np.interp(h, rays.h0, rays.alpha)
    return b / np.sin(g)


def _moon_disc_fraction(rays, z, rho_c, n=9):
    """Mean fraction over the lunar disc (radius 1737.4 km) centred rho_c km
    from the axis (uniform disc average, n x n Gauss points)."""
    from numpy.polynomial.legendre import leggauss
    x, w = leggauss(n)
    rm = 1737.4
    pts, wts = [], []
    for xi, wi in zip(x, w):
        for yj, wj in zip(x, w):
            # polar map of the square to the disc (area-preserving enough with weights)
            r = rm * (xi + 1) / 2
            t = np.pi * (yj + 1)
            pts.append(np.hypot(rho_c + r * np.cos(t), r * np.sin(t)))
            wts.append(wi * wj * r)
    F, _ = ar.fraction(rays, z, np.array(pts), want_psi=False, n_mu=16)
    wts = np.array(wts)
    return float(np.sum(F * wts) / np.sum(wts))


def section(outdir) -> str:
    plt = _plt()
    t0 = time.time()
    out = ["## Atmosphere: refraction and extinction into the Earth's shadow\n"]
    prof = ap.us1976()
    seedp = ap.seed_mode()
    rays = ar.make_rays(prof, dh_km=0.02)
    rays_seed = ar.make_rays(seedp, dh_km=0.02)

    # ---------------------------------------------------------- 1. bending
    _, a0, _ = ar.trace(prof, [0.0, 10.0])
    prof_exp = ap.exponential(ap.N_S_550, 8.0, extinction=False)
    _, ae, _ = ar.trace(prof_exp, [0.0])
    thin = ap.exponential(1e-8, 8.0, extinction=False)
    _, at_, _ = ar.trace(thin, [0.0])
    cf = 1e-8 * np.sqrt(2 * np.pi * R / 8.0)
    tau = prof.vertical_optical_depth(550.0)
    out.append("### Validations against the world\n")
    out.append("| quantity | this model | published | source |\n|---|---|---|---|")
    out.append(f"| total bending of a ray grazing the surface (US 1976) | {np.degrees(a0[0]):.3f} deg "
               f"| ~1.18 deg = 2 x 35.4' horizontal refraction (10 C, 1013 hPa) | Allen, *Astrophysical "
               "Quantities* (1976) p. 125; docs/physics.md |")
    out.append(f"| same, exponential N0 = {ap.N_S_550:.4g}, H = 8 km | {np.degrees(ae[0]):.3f} deg | "
               f"thin-atmosphere form N0 sqrt(2 pi R/H) = {np.degrees(ap.N_S_550 * np.sqrt(2 * np.pi * R / 8)):.3f} deg "
               "(first order in N0; the difference is the O(N0 R/H) term) | refraction integral, Born & Wolf 3.2 |")
    out.append(f"| thin limit N0 = 1e-8: alpha / (N0 sqrt(2 pi R/H)) | {at_[0] / cf:.6f} | 1 - H/(8R) = "
               f"{1 - 8 / (8 * R):.6f} | asymptotic expansion (tests/python/test_atm.py) |")
    out.append(f"| bending at the 10 km cloud top | {np.degrees(a0[1]):.3f} deg | - | - |")
    out.append(f"| vertical Rayleigh optical depth, 550 nm | {tau[0]:.4f} | 0.0973 | Bodhaine et al. 1999, "
               "J. Atmos. Ocean. Tech. 16, 1854, Table 3 |")
    out.append(f"| vertical ozone optical depth, 550 nm (300 DU) | {tau[1]:.4f} | ~0.03 | Chappuis band, "
               "Serdyuchenko et al. 2014 |")
    zc0 = _crossing_distance(rays_seed, 0.0)
    zc10 = _crossing_distance(rays, 10.0)
    zc20 = _crossing_distance(rays, 20.0)
    out.append(f"| where grazing rays cross the axis (surface / 10 km / 20 km) | {zc0:.3g} / {zc10:.3g} / "
               f"{zc20:.3g} km | ~R / bending: {R / a0[0]:.3g} km for the surface ray; Moon at 3.84e5 km | "
               "Link 1969, *Eclipse Phenomena in Astronomy*, ch. 2 |")

    # eclipsed Moon
    z_moon = 384400.0
    dm = {}
    import dataclasses
    rays_clear = ar.make_rays(dataclasses.replace(prof, cloud_fraction=0.0), dh_km=0.02)
    for name, rr in (("clear air, clouds below 10 km", rays), ("refraction only (seed mode)", rays_seed),
                     ("no clouds", rays_clear)):
        vals = [_moon_disc_fraction(rr, z_moon, rc) for rc in (0.0, 2000.0)]
        dm[name] = [-2.5 * np.log10(v) if v > 0 else float("inf") for v in vals]
    def fmt(v):
        return "dark (no unblocked ray)" if not np.isfinite(v) else f"{v:.1f}"
    out.append(f"| totally eclipsed Moon vs full Moon, central / Moon centre 2000 km off the axis "
               f"(clouds stopping {prof.cloud_fraction:g} of the rays below {prof.cloud_top_km:g} km) | {fmt(dm['clear air, clouds below 10 km'][0])} / "
               f"{fmt(dm['clear air, clouds below 10 km'][1])} mag fainter | 9-12 mag fainter (clear air; "
               "darker after volcanic eruptions) | docs/physics.md; Link 1969; Mallama 2022, arXiv:2203.05513 |")
    out.append(f"| same, clear air without the cloud layer (extinction down to the ground) | "
               f"{dm['no clouds'][0]:.1f} / {dm['no clouds'][1]:.1f} mag | 9-12 mag | as above |")
    out.append(f"| same, refraction only (no extinction) | {dm['refraction only (seed mode)'][0]:.1f} / "
               f"{dm['refraction only (seed mode)'][1]:.1f} mag | would flood the umbra | docs/physics.md |")

    # shadow enlargement at the Moon: steepest log-gradient of F vs geometric umbra edge
    a_m = z_moon * ar.SUN_RADIUS_KM / ar.AU_KM
    rc_m = R * (1 + z_moon / ar.AU_KM)
    rho = np.linspace(rc_m - a_m - 900, rc_m - a_m + 900, 361)
    F, _ = ar.fraction(rays, z_moon, rho, want_psi=False, n_mu=24)
    lg = np.log(np.maximum(F, 1e-12))
    grad = np.gradient(lg, rho)
    # the visual umbra edge: the steepest rise of log F in the outer umbra
    # (inflection of the brightness profile seen by the eye, Danjon 1951)
    k = int(np.argmax(grad * (F > 1e-4)))
    edge = rho[k]
    geo_umbra = rc_m - a_m
    enl = edge / geo_umbra - 1
    danjon = (R / 85) * (1 + z_moon / ar.AU_KM) / geo_umbra
    out.append(f"| enlargement of the umbra at the Moon (steepest log-brightness gradient vs geometric edge) "
               f"| {100 * enl:.1f} % ({edge - geo_umbra:.0f} km) | Chauvenet 1/50 = 2 % of the shadow "
               f"diameter; Danjon: Earth's radius + 1/85, i.e. {100 * danjon:.1f} % here | Espenak & Meeus, "
               "*Five Millennium Canon of Lunar Eclipses* (NASA TP-2009-214172), 'Enlargement of Earth's "
               "shadows' |")
    # effective height of the shadow for a LEO satellite
    hs = []
    for zz in (2400.0,):
        rc_ = R * (1 + zz / ar.AU_KM)
        rho_ = rc_ + np.linspace(-60, 100, 321)
        F_, _ = ar.fraction(rays, zz, rho_, want_psi=False, n_mu=24)
        for thr in (0.5, 0.1):
            hs.append(rho_[np.where(F_ >= thr)[0][0]] - rc_)
    out.append(f"| effective shadow height for a LEO satellite entering the shadow (z = 2400 km): tangent "
               f"height of the line to the Sun's centre where F = 0.5 / 0.1 | {hs[0]:.0f} / {hs[1]:.0f} km "
               "(0 / -7 km without atmosphere) | 15-20 km 'atmosphere allowance' fitted to visual "
               "shadow-entry timings | R. Matson, T. Molczan, SeeSat-L, Jan. 1997 "
               "(satobs.org/seesat/Jan-1997/0347.html) |")
    out.append("")

    # ---------------------------------------------------------- 2. LEO penumbra transit
    h_orb = 420.0
    r_orb = R + h_orb
    mu = 398600.4418
    n_orb = np.sqrt(mu / r_orb ** 3)
    # beta angle 0: orbit plane contains the Sun; entry near the anti-Sun side
    th_geo = np.pi - np.arcsin(R / r_orb)        # angle from the subsolar point where rho = R
    ts = np.linspace(-30, 30, 241)               # s around the geometric shadow edge crossing
    th = th_geo + n_orb * ts
    z = -r_orb * np.cos(th)
    rh = r_orb * np.sin(th)
    F_geo = np.array([ar.fraction(None, zz, [rr], want_psi=False, n_mu=24)[0][0] for zz, rr in zip(z, rh)])
    F_atm = np.array([ar.fraction(rays, zz, [rr], want_psi=False, n_mu=24)[0][0] for zz, rr in zip(z, rh)])
    F_seed = np.array([ar.fraction(rays_seed, zz, [rr], want_psi=False, n_mu=24)[0][0]
                       for zz, rr in zip(z, rh)])
    meta = json.load(open(os.path.join(ROOT, "tables", "oi_atm_vband.json")))
    q, psi_t, alpha_c, h_c = at.load_table(os.path.join(ROOT, "tables"))
    F_lut = []
    for zz, rr, fg in zip(z, rh, F_geo):
        f, _, st = aw.lookup(q, psi_t, alpha_c, h_c, zz, rr, ar.AU_KM)
        F_lut.append(fg if f is None else f)
    F_lut = np.array(F_lut)

    def span(Fv, lo=0.01, hi=0.99):
        i_hi = np.where(Fv < hi)[0]
        i_lo = np.where(Fv > lo)[0]
        if i_hi.size == 0 or i_lo.size == 0:
            return float("nan"), float("nan"), float("nan")
        t_hi = ts[i_hi[0]]
        t_lo = ts[i_lo[-1]]
        half = ts[np.argmin(np.abs(Fv - 0.5))]
        return t_lo - t_hi, half, t_hi

    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(ts, F_geo, label="no atmosphere (geometric, limb-darkened)")
    ax.plot(ts, F_seed, label="refraction only (seed mode)")
    ax.plot(ts, F_atm, label="refraction + extinction (reference)")
    ax.plot(ts, F_lut, "k:", label="runtime table lookup")
    ax.set_xlabel("time from geometric shadow-edge crossing (s), 420 km orbit, beta = 0")
    ax.set_ylabel("fraction of sunlight")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    p1 = os.path.join(outdir, "atm_leo_transit.png")
    fig.savefig(p1, dpi=110)
    plt.close(fig)
    out.append("### LEO penumbra transit (420 km circular orbit, Sun in the orbit plane)\n")
    out.append("| model | 99 % -> 1 % duration | time of 50 % (from the geometric edge) |\n|---|---|---|")
    for name, Fv in (("no atmosphere", F_geo), ("refraction only", F_seed),
                     ("refraction + extinction", F_atm), ("runtime table", F_lut)):
        d, h, _ = span(Fv)
        out.append(f"| {name} | {d:.1f} s | {h:+.1f} s |")
    out.append("")
    out.append(f"![LEO transit]({p1})\n")
    out.append("With extinction the transit is longer and starts earlier: the sunlight is already dimmed "
               "while the line of sight to the Sun's lower limb passes 20-50 km above the surface (Rayleigh, "
               "ozone and refractive defocusing), and the light grazing below ~15 km is almost gone. This is "
               "the behaviour Robertson et al. (2015, Celest. Mech. Dyn. Astr. 123, 169, 'SOLAARS', GRACE "
               "accelerometer penumbra data) and Mallama (2021, arXiv:2112.08310: 'refraction combines with "
               "atmospheric absorption to dim the satellites for tens of km outside of [the geometric] region') "
               "describe; we did not have their tabulated curves to compare point by point, so this is a "
               "qualitative comparison only.\n")

    # ---------------------------------------------------------- 3. shells convergence
    h0 = np.linspace(10.0, 40.0, 301)
    b, alpha, _ = ar.trace(seedp, h0)
    rows = []
    for spacing in ("uniform", "refractivity"):
        for K in (25, 50, 100, 400, 1600, 6400):
            radii, idx = ar.shell_model(seedp, K, spacing)
            a_sh, _ = ar.shell_bending(radii, idx, b)
            e = a_sh / alpha - 1
            bb = R + np.linspace(0.0, 100.0, 20001)
            amax, _ = ar.shell_bending(radii, idx, bb)
            rows.append((spacing, K, np.mean(np.abs(e)), np.mean(e), np.max(np.abs(e)),
                         np.degrees(np.max(amax))))
    out.append("### The seed's nested shells against the continuous profile\n")
    out.append("Bending of rays with lowest altitude 10-40 km through K shells of constant index (uniform "
               "in altitude, or at equal steps of refractivity as bake/photon/shells.py's default; each the mean index "
               "of its layer; Snell at each boundary, "
               "`bake.atmosphere.rays.shell_bending`, checked against `bake/photon/shells.py`'s tracer):\n")
    out.append("| spacing | K | mean abs error | mean error | max abs error | largest bending of any ray |"
               "\n|---|---|---|---|---|---|")
    for sp, K, m1, m2, m3, amx in rows:
        out.append(f"| {sp} | {K} | {100 * m1:.1f} % | {100 * m2:+.1f} % | {100 * m3:.0f} % | {amx:.2f} deg |")
    _, ag, _ = ar.trace(seedp, [0.0])
    out.append(f"\nContinuous profile: largest bending {np.degrees(ag[0]):.2f} deg (the grazing ray). "
               "A ray grazing a shell boundary from above enters the next shell at grazing incidence and is "
               "turned by ~2 sqrt(2 dn) extra, so single rays converge erratically and the mean error only "
               "as K^-1/2. **Decision:** the tables are baked from the continuous profile (the K -> infinity "
               "limit, by quadrature of the refraction integral); shells are kept only to reproduce the seed. "
               "A photon map through shells needs K >~ 3000 (30 m shells) to bring the mean bending error "
               "under ~3 %.\n")

    # irradiance behind the Earth through K shells vs the continuous profile (seed mode)
    from ..photon import atmosphere as aph0
    out.append("Irradiance behind the Earth (refraction only) through K uniform shells against the "
               "continuous profile, over the refracted-light region:\n")
    out.append("| K | max abs F error at GEO distance (z = 42 164 km) | max relative error in the umbra at the "
               "Moon (z = 384 400 km, F > 1e-4) |\n|---|---|---|")
    zg, zm = 42164.0, 384400.0
    rg = R + np.linspace(-1100.0, 250.0, 55)
    rm = np.linspace(0.0, R * (1 + zm / ar.AU_KM) - zm * ar.SUN_RADIUS_KM / ar.AU_KM, 40)
    Fg0 = ar.fraction(rays_seed, zg, rg, want_psi=False, n_mu=24)[0]
    Fm0 = ar.fraction(rays_seed, zm, rm, want_psi=False, n_mu=24)[0]
    for K in (25, 100, 400, 1600):
        sr = aph0.shell_rays(seedp, K, dh=0.01)
        Fg = ar.fraction(sr, zg, rg, want_psi=False, n_mu=24)[0]
        Fm = ar.fraction(sr, zm, rm, want_psi=False, n_mu=24)[0]
        big = Fm0 > 1e-4
        out.append(f"| {K} | {np.max(np.abs(Fg - Fg0)):.2e} | "
                   f"{np.max(np.abs(Fm[big] / Fm0[big] - 1)) if np.any(big) else float('nan'):.2f} |")
    out.append("")

    # ---------------------------------------------------------- 3b. photon mapping with directions
    from ..photon import atmosphere as aph
    conv = aph.convergence(n_shells=100, z=42164.0, photons=(10000, 30000, 100000, 300000))
    out.append("### Photon mapping through the shells, with directions (`bake/photon/atmosphere.py`)\n")
    out.append("Photons from random points of the limb-darkened disc, traced through 100 uniform shells by "
               "`bake/photon/shells.py` (vector Snell), followed along their recorded exit directions to the plane at "
               "GEO distance behind the Earth (z = 42 164 km), binned in 27 rings (refraction only). Error "
               "against the deterministic reference through the *same* shells (ring averages):\n")
    out.append("| photons | time | rms error of F | max error of F |\n|---|---|---|---|")
    for n, dt, rms, mx in conv["rows"]:
        out.append(f"| {n} | {dt:.2f} s | {rms:.2e} | {mx:.2e} |")
    fig, ax = plt.subplots(figsize=(7, 3.8))
    ax.semilogy(conv["mid"] - R, conv["F_continuous"], label="reference, continuous profile")
    ax.semilogy(conv["mid"] - R, conv["F_ref_shells"], label="reference, 100 shells")
    ax.semilogy(conv["mid"] - R, conv["F_photon"], ".", label=f"photon map, {conv['rows'][-1][0]} photons")
    ax.set_xlabel("rho - R (km) at z = 42164 km")
    ax.set_ylabel("fraction of sunlight")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    p0 = os.path.join(outdir, "atm_photon.png")
    fig.savefig(p0, dpi=110)
    plt.close(fig)
    out.append(f"\n![photon map]({p0})\n")
    out.append("The noise falls as N^-1/2 (Poisson) down to the rings' own averaging; the directions "
               "recorded by the photons reproduce the reference's mean direction psi to ~0.005 deg "
               "(tests/python/test_atm_photon.py). The shells' own bias (difference between the two "
               "references) is larger than the photon noise beyond ~1e5 photons: the deterministic "
               "continuous reference is what the table is baked from (bake time of the whole table: ~45 s, "
               "for a max error of 4e-3 everywhere, which no photon budget of the same time reaches).\n")

    # ---------------------------------------------------------- 4. seed Fig. 10 redone
    dth = np.linspace(-1.5, 2.0, 141)   # deg from the geometric shadow edge, positive into the shadow
    alts = np.geomspace(300.0, 400000.0, 30)
    maps = {}
    for name, rr in (("none", None), ("seed", rays_seed), ("full", rays)):
        M = np.zeros((alts.size, dth.size))
        for i, hh in enumerate(alts):
            r = R + hh
            th = np.pi - np.arcsin(R / r) + np.radians(dth)
            zz = -r * np.cos(th)
            rr_ = r * np.sin(th)
            for j in range(dth.size):
                if zz[j] <= 0 or th[j] > np.pi:
                    M[i, j] = np.nan
                    continue
                M[i, j] = ar.fraction(rr, zz[j], [rr_[j]], want_psi=False, n_mu=12, n_top=200)[0][0]
        maps[name] = M
    fig, axs = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
    for ax, (name, title) in zip(axs, (("none", "no atmosphere"), ("seed", "refraction only (seed mode)"),
                                       ("full", "refraction + extinction (this project's default)"))):
        im = ax.pcolormesh(dth, alts, np.log10(np.maximum(maps[name], 1e-6)), vmin=-6, vmax=0,
                           shading="auto", cmap="magma")
        ax.set_yscale("log")
        ax.set_ylabel("altitude (km)")
        ax.set_title(title, fontsize=9)
    axs[-1].set_xlabel("theta - theta_edge (deg), positive into the geometric shadow")
    fig.colorbar(im, ax=axs, label="log10 fraction of sunlight")
    p2 = os.path.join(outdir, "atm_fig10.png")
    fig.savefig(p2, dpi=110)
    plt.close(fig)

    def edge_theta(rr, hh, thr):
        """Largest theta (deg) with F >= thr at altitude hh (bisection)."""
        r = R + hh
        lo, hi = np.degrees(np.pi / 2), 180.0

        def f(t):
            zz, rho_ = -r * np.cos(np.radians(t)), r * np.sin(np.radians(t))
            return ar.fraction(rr, zz, [rho_], want_psi=False, n_mu=24)[0][0]
        if f(hi) >= thr:
            return 180.0
        for _ in range(30):
            mid = 0.5 * (lo + hi)
            if f(mid) >= thr:
                lo = mid
            else:
                hi = mid
        return 0.5 * (lo + hi)

    out.append("### Seed Fig. 10 redone: the shadow with and without atmosphere\n")
    out.append(f"![Fig. 10]({p2})\n")
    out.append("Inner edge (largest theta still receiving a given fraction) with and without atmosphere:\n")
    out.append("| altitude | threshold | no atmosphere | refraction only | with extinction | "
               "shift, refraction only | shift, with extinction |\n|---|---|---|---|---|---|---|")
    for hh in (400.0, 2000.0, 35786.0, 378000.0):
        for thr in (1e-3, 1e-2):
            e0 = edge_theta(None, hh, thr)
            e1 = edge_theta(rays_seed, hh, thr)
            e2 = edge_theta(rays, hh, thr)
            out.append(f"| {hh:.0f} km | F >= {thr:g} | {e0:.2f} deg | {e1:.2f} deg | {e2:.2f} deg | "
                       f"{e1 - e0:+.2f} deg | {e2 - e0:+.2f} deg |")
    out.append("\nThe seed reports the penumbra's inner edge 'nearly 3 degrees further into the umbra'. With a "
               "continuous standard atmosphere and no extinction the inner edge moves by at most the largest "
               f"bending, {np.degrees(ag[0]):.1f} deg (a point at distance r behind the Earth sees refracted "
               "light down to an angle ~alpha z / r <= alpha from the geometric edge), and by a few tenths of "
               "a degree once clouds and extinction are included. The likely causes of the seed's larger "
               "shift: its coarse constant-index shells, whose rays grazing a boundary are over-bent (table "
               "above: tens of % to ~100 % for K ~ 25-50), and a threshold of 'any photon' in a "
               "gathering-free photon map (no flux weighting: the defocused refracted light is 1e-3 to 1e-6 "
               "of sunlight but still counts as lit).\n")

    # ---------------------------------------------------------- 5. table
    out.append("### Runtime table\n")
    me = meta["measured"]
    out.append(f"`tables/oi_atm_vband.c`: {meta['payload_bytes']} bytes (16-bit codes, {at.NZ} x {at.NT} x 2), "
               f"z = {at.Z_MIN:g}..{at.Z_MAX:g} km behind the Earth, nodes following the shadow "
               "(bake/atmosphere/). Measured against the reference at "
               f"{me['n_points']} random off-grid points: max |dF| = {me['max_abs_error']:.2e}, "
               f"rms {me['rms_abs_error']:.2e}; max relative error where F > 1e-4: "
               f"{me['max_rel_error_F_gt_1e-4']:.2f} (deep-umbra points near the reach of the lowest "
               f"refracted rays, where F is small); direction psi within {me['max_psi_error_rad_F_gt_1e-3']:.1e} rad.\n")
    out.append(f"*Section computed in {time.time() - t0:.0f} s.*\n")
    return "\n".join(out)


if __name__ == "__main__":
    import sys
    d = sys.argv[1] if len(sys.argv) > 1 else "/tmp/atm_report"
    os.makedirs(d, exist_ok=True)
    print(section(d))
