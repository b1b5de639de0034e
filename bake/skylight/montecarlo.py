# SPDX-License-Identifier: MIT
"""Independent Monte Carlo of the scattered sunlight at a target (the table's check).

The same atmosphere and the same definition as bake.skylight.single (single scattering,
lines of sight ending on the sunlit floor left out), another way of integrating it:

* lines of sight drawn at random, half uniform over the cone of the medium's top
  sphere and half uniform in nadir angle over the limb band (the floor's horizon to
  the top's), weighted by the mixture's density (an unbiased estimator);
* one scattering point per line, uniform in distance along its path through the medium;
* both transmissions by direct Gauss-Legendre integrals of the profile's own densities
  (`Profile.species`, not the log-density table), the Sun's along the ray from the
  point to the top sphere, the view's from the target to the point: no tabulated
  Sun columns, no cumulative sums.

Returns the mean and its standard error.
"""
from __future__ import annotations

import numpy as np

from ..common.quadrature import gauss_legendre_01
from .medium import Medium, hg_phase, rayleigh_phase

N_VIEW_GL = 24
N_SUN_GL = 40


def _column(med, b2, lo, hi, n):
    """Species columns (4, m) of straight segments t in [lo, hi] at impact b2."""
    x, w = gauss_legendre_01(n)
    span = np.maximum(hi - lo, 0.0)
    t = lo[:, None] + span[:, None] * x[None]
    # a zero-length segment may sit below the surface (a point above the day side has
    # no downward part): its height is clamped so that its densities stay finite
    h = np.maximum(np.sqrt(b2[:, None] + t * t) - med.R, 0.0)
    dens = med.exact_species(np.minimum(h, med.profile.top_km + 1.0))
    return np.sum(dens * w[None, None], axis=-1) * span[None] * 1e3


def irradiance(theta, r, n=40000, seed=0, med: Medium | None = None, chunk=4000):
    """(E_sky / E_sun, standard error, mean direction psi) at (theta, r)."""
    med = med or Medium()
    rng = np.random.Generator(np.random.PCG64(seed))
    s = np.array([np.sin(theta), 0.0, np.cos(theta)])
    a_top = np.arcsin(med.r_top / r)
    a_fl = np.arcsin(med.r_floor / r)
    a_lo = max(0.0, a_fl - 0.02 * (a_top - 0.0))
    om_cone = 2 * np.pi * (1 - np.cos(a_top))
    band = a_top - a_lo
    vals, vx, vz = [], [], []
    done = 0
    while done < n:
        m = min(chunk, n - done)
        done += m
        pick = rng.random(m) < 0.5
        cos_nu = 1 - rng.random(m) * (1 - np.cos(a_top))
        nu = np.where(pick, np.arccos(cos_nu), a_lo + band * rng.random(m))
        az = np.pi * rng.random(m)
        # mixture density per steradian (over the half-azimuth [0, pi], mirrored)
        pdf = 0.5 / (om_cone / 2) + np.where(nu >= a_lo, 0.5 / (band * np.pi * np.sin(nu)), 0.0)
        u = np.stack([np.sin(nu) * np.cos(az), np.sin(nu) * np.sin(az), -np.cos(nu)])
        rt2 = (r * np.sin(nu)) ** 2
        tc = r * np.cos(nu)
        t_in = np.maximum(tc - np.sqrt(np.maximum(med.r_top ** 2 - rt2, 0.0)), 0.0)
        hits = rt2 < med.r_floor ** 2
        t_out = np.where(hits, tc - np.sqrt(np.maximum(med.r_floor ** 2 - rt2, 0.0)),
                         tc + np.sqrt(np.maximum(med.r_top ** 2 - rt2, 0.0)))
        lit_floor = hits & (r * s[2] + t_out * (s @ u) > 0.0)
        length = np.maximum(t_out - t_in, 0.0)
        t = t_in + length * rng.random(m)
        X = np.array([0.0, 0.0, r])[:, None] + u * t[None]
        rho = np.sqrt(np.sum(X * X, axis=0))
        xs = s @ X
        b2 = np.maximum(rho * rho - xs * xs, 0.0)
        shadow = (xs < 0) & (b2 < med.r_floor ** 2)
        ok = (~lit_floor) & (~shadow) & (length > 0)
        f = np.zeros(m)
        if np.any(ok):
            i = np.nonzero(ok)[0]
            # view: from the target (t = t_in .. t) along u; impact of that line
            bv2 = rt2[i]
            col_v = _column(med, bv2, t_in[i] - tc[i], t[i] - tc[i], N_VIEW_GL)
            # Sun: from the point to the top sphere along s, in the ray's own
            # coordinate from its closest approach (t0 = X . s)
            t0 = xs[i]
            t_top = np.sqrt(np.maximum(med.r_top ** 2 - b2[i], 0.0))
            down = np.minimum(t0, 0.0)
            col_s = (_column(med, b2[i], down, np.zeros_like(down), N_SUN_GL) +
                     _column(med, b2[i], np.maximum(t0, 0.0), t_top, N_SUN_GL))
            tau = med.ext_w.T @ (col_v + col_s)                     # (G, k)
            dens = med.exact_species(rho[i] - med.R)
            cos_t = s @ u[:, i]
            sca = (med.sca_w[0][:, None] * dens[0] * rayleigh_phase(cos_t) +
                   (med.sca_w[2][:, None] * dens[2] + med.sca_w[3][:, None] * dens[3]) *
                   hg_phase(cos_t))
            L = med.weight @ (sca * np.exp(-tau)) / (4 * np.pi) * 1e3   # per km of path
            f[i] = 2.0 * L * length[i] / pdf[i]   # both halves of the azimuth
        vals.append(f)
        vx.append(f * np.sin(nu) * np.cos(az))
        vz.append(f * np.cos(nu))
    f = np.concatenate(vals)
    mean = float(np.mean(f))
    err = float(np.std(f) / np.sqrt(f.size))
    psi = float(np.arctan2(np.mean(np.concatenate(vx)), np.mean(np.concatenate(vz))))
    return mean, err, psi
