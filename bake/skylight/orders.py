# SPDX-License-Identifier: MIT
"""Multiple scattering bounded by measurement: a Monte Carlo through the same atmosphere
with the scattering orders counted (docs/skylight.md, "Multiple scattering").

    python -m bake.skylight.orders            (the docs' table; ~15 minutes on one core)

Backward paths from the target: a line of sight drawn uniformly over the cone of the
medium's top sphere (those ending on the sunlit floor count for nothing, as in the
single-scattering table: their light is earthshine's albedo), then a forced collision
along every segment (the segment's optical depth sampled as a truncated exponential,
the weight multiplied by 1 - exp(-tau_segment) and by the single scattering albedo
at the collision), a next-event estimate of the direct sunlight at every collision
(the phase function of the air and aerosol mixture there, the Sun's transmission from
the refraction table's columns, 0 in the floor's shadow), and a new direction drawn
from that phase function. The k-th collision's estimate is order k. One wavelength
group per path, drawn by its band weight.

Two floors: black (the medium alone, what the table's single scattering also assumes),
and a Lambertian cloud deck of albedo FLOOR_ALBEDO (the uniform Earth's 0.3): a
segment after the first that ends on the floor adds its reflected sunlight (uncollided
weight exp(-tau) times A mu_s T_sun / pi), counted as order k + 1 after k collisions,
and the path goes on from the floor in a cosine-distributed direction with weight A.
Order 1 must reproduce the single-scattering quadrature (bake.skylight.single): it is
printed next to it.
"""
from __future__ import annotations

import math

import numpy as np

from .medium import AER_G, Medium, hg_phase, rayleigh_phase
from .single import SingleScattering

N_SEG = 128          # midpoints per segment for its optical depth
MAX_ORDER = 12       # collisions followed per path (the rest is bounded below)
FLOOR_ALBEDO = 0.30
CASES = [(400.0, 95.0), (400.0, 108.0), (400.0, 112.0), (800.0, 118.0), (2000.0, 120.0),
         (35786.0, 150.0)]


def _sphere_exit(x, u, radius):
    """Distance along u from x (3, n) to the sphere of the given radius: (t_far, t_near,
    hit); t_near the first crossing ahead (for a point outside), nan-free."""
    b = np.sum(x * u, axis=0)
    c = np.sum(x * x, axis=0) - radius * radius
    disc = b * b - c
    hit = disc > 0
    sq = np.sqrt(np.maximum(disc, 0.0))
    return -b + sq, -b - sq, hit


def _segment(med, x, u):
    """(t0, t1, floor): the part of the ray x + t u inside the medium, and whether it
    ends on the floor."""
    tf, tn, hit_top = _sphere_exit(x, u, med.r_top)
    t0 = np.where(np.sum(x * x, axis=0) > med.r_top ** 2, np.maximum(tn, 0.0), 0.0)
    t1 = np.where(hit_top, np.maximum(tf, 0.0), 0.0)
    _, fn, hit_fl = _sphere_exit(x, u, med.r_floor)
    floor = hit_fl & (fn > 1e-9) & (fn < t1)
    t1 = np.where(floor, fn, t1)
    t1 = np.maximum(t1, t0)
    return t0, t1, floor


def _coefficients(med, dens, g):
    """(extinction, Rayleigh scattering, aerosol scattering) per metre at densities
    dens (4, ...) for the paths' groups g (broadcast over the trailing axes)."""
    ext = sum(med.ext_w[k][g] * dens[k] for k in range(4))
    ray = med.sca_w[0][g] * dens[0]
    aer = med.sca_w[2][g] * dens[2] + med.sca_w[3][g] * dens[3]
    return ext, ray, aer


def _sun(ss, med, x, g):
    """Direct solar transmission at points x (3, n) for groups g, 0 in the floor's
    shadow (the Sun along +z here: the frame is turned so that s = e_z)."""
    rho = np.sqrt(np.sum(x * x, axis=0))
    mu = x[2] / rho
    mu_g = -np.sqrt(np.maximum(0.0, 1.0 - (med.r_floor / rho) ** 2))
    out = np.zeros(rho.size)
    lit = mu > mu_g
    if np.any(lit):
        i = np.nonzero(lit)[0]
        tr = ss.sun.transmission(np.minimum(rho[i], med.r_top), mu[i])
        out[i] = tr[g[i], np.arange(i.size)]
    return out


def _turn(u, cos_t, rng):
    """Directions at angle acos(cos_t) from u (3, n), uniform azimuth."""
    n = u.shape[1]
    phi = 2 * np.pi * rng.random(n)
    sin_t = np.sqrt(np.maximum(0.0, 1.0 - cos_t * cos_t))
    a = np.where(np.abs(u[0]) < 0.9, 1.0, 0.0)
    ref = np.stack([a, 1.0 - a, np.zeros(n)])
    e1 = np.cross(u.T, ref.T).T
    e1 /= np.sqrt(np.sum(e1 * e1, axis=0))
    e2 = np.cross(u.T, e1.T).T
    return cos_t * u + sin_t * (np.cos(phi) * e1 + np.sin(phi) * e2)


def _sample_rayleigh(n, rng):
    """cos T from the depolarised Rayleigh phase function (rejection on its maximum)."""
    out = np.empty(n)
    todo = np.arange(n)
    pmax = rayleigh_phase(1.0)
    for _ in range(200):
        if todo.size == 0:
            break
        c = 2 * rng.random(todo.size) - 1
        ok = rng.random(todo.size) * pmax < rayleigh_phase(c)
        out[todo[ok]] = c[ok]
        todo = todo[~ok]
    out[todo] = 2 * rng.random(todo.size) - 1     # never reached in practice (p > 1/2)
    return out


def _sample_hg(n, rng, g=AER_G):
    xi = rng.random(n)
    s = (1 - g * g) / (1 - g + 2 * g * xi)
    return (1 + g * g - s * s) / (2 * g)


def paths(theta, r, n=40000, seed=0, floor_albedo=FLOOR_ALBEDO, med=None, ss=None,
          chunk=5000):
    """(mean, err, multi): per-order means (2, MAX_ORDER + 1) of E_sky / E_sun and their
    standard errors, row 0 the air's orders (index 0 single scattering), row 1 the
    floor's reflections after k collisions at index k; multi = (orders >= 2 of the air,
    its standard error, the floor's share, its standard error)."""
    med = med or Medium()
    ss = ss or SingleScattering(med)
    rng = np.random.Generator(np.random.PCG64(seed))
    # the Sun along +z: the target at angle theta from it, in the x-z plane
    p = np.array([r * math.sin(theta), 0.0, r * math.cos(theta)])
    nadir = -p / r
    cos_top = math.sqrt(max(0.0, 1.0 - (med.r_top / r) ** 2))
    omega = 2 * math.pi * (1 - cos_top)
    a_top = math.asin(min(med.r_top / r, 1.0))
    a_lo = max(0.0, math.asin(min(med.r_floor / r, 1.0)) - 0.02 * a_top)
    band = a_top - a_lo
    wsum = float(np.sum(med.weight))
    prob = med.weight / wsum
    k_grid = (np.arange(N_SEG) + 0.5) / N_SEG
    sums = np.zeros((2, MAX_ORDER + 1))
    sq = np.zeros((2, MAX_ORDER + 1))
    tot = np.zeros(4)
    done = 0
    while done < n:
        m = min(chunk, n - done)
        done += m
        g = rng.choice(len(prob), size=m, p=prob)
        # half uniform over the top sphere's cone, half uniform in nadir angle over the
        # limb band (where the long lit paths are); w: one over the mixture's density
        pick = rng.random(m) < 0.5
        cos_nu = 1 - rng.random(m) * (1 - cos_top)
        nu = np.where(pick, np.arccos(cos_nu), a_lo + band * rng.random(m))
        pdf = 0.5 / omega + np.where(nu >= a_lo, 0.5 / (band * 2 * np.pi * np.sin(nu)), 0.0)
        u = _turn(np.repeat(nadir[:, None], m, axis=1), np.cos(nu), rng)
        x = np.repeat(p[:, None], m, axis=1)
        w = wsum / pdf
        score = np.zeros((MAX_ORDER + 1, m))
        score_fl = np.zeros((MAX_ORDER + 1, m))
        alive = np.ones(m, dtype=bool)
        for order in range(MAX_ORDER):
            t0, t1, floor = _segment(med, x, u)
            if order == 0:
                # lines of sight ending on the sunlit floor: earthshine's, not counted
                end = x + u * t1[None]
                alive &= ~(floor & (end[2] > 0.0))
            alive &= t1 > t0
            if not np.any(alive):
                break
            i = np.nonzero(alive)[0]
            span = (t1 - t0)[i]
            t = t0[i][:, None] + span[:, None] * k_grid[None]
            pts = x[:, i][:, :, None] + u[:, i][:, :, None] * t[None]
            h = np.sqrt(np.sum(pts * pts, axis=0)) - med.R
            dens = med.species(np.clip(h, 0.0, med.profile.top_km))
            ext, _, _ = _coefficients(med, dens, g[i][:, None])
            dtau = ext * (span[:, None] / N_SEG * 1e3)
            tau = np.cumsum(dtau, axis=1)
            tau_tot = tau[:, -1]
            # the floor's reflection of the uncollided weight (after a collision)
            if order > 0:
                fl = floor[i]
                if np.any(fl):
                    j = i[fl]
                    end = x[:, j] + u[:, j] * t1[j][None]
                    mu_s = np.maximum(end[2] / med.r_floor, 0.0)
                    tr = _sun(ss, med, end * (1 + 1e-9), g[j])
                    score_fl[order, j] += (w[j] * np.exp(-tau_tot[fl]) * floor_albedo *
                                        mu_s * tr / math.pi)
            # forced collision: tau' in [0, tau_tot) truncated exponential
            f_esc = np.exp(-tau_tot)
            xi = rng.random(i.size)
            tau_c = -np.log1p(-xi * (1 - f_esc))
            kk = np.minimum(np.sum(tau < tau_c[:, None], axis=1), N_SEG - 1)
            tc = t0[i] + span * (kk + 0.5) / N_SEG
            xc = x[:, i] + u[:, i] * tc[None]
            hc = np.sqrt(np.sum(xc * xc, axis=0)) - med.R
            dc = med.species(np.clip(hc, 0.0, med.profile.top_km))
            e_c, r_c, a_c = _coefficients(med, dc, g[i])
            e_c = np.where(e_c > 0, e_c, 1.0)
            w[i] *= (1 - f_esc) * (r_c + a_c) / e_c
            # next event: the Sun seen from the collision; light leaves along -u
            cos_t = u[2, i]
            ph = (r_c * rayleigh_phase(cos_t) + a_c * hg_phase(cos_t)) / np.where(
                r_c + a_c > 0, r_c + a_c, 1.0)
            score[order, i] += w[i] * ph / (4 * math.pi) * _sun(ss, med, xc, g[i])
            # the next direction from the mixture's phase function
            ray = rng.random(i.size) * (r_c + a_c) < r_c
            c = np.where(ray, _sample_rayleigh(i.size, rng), _sample_hg(i.size, rng))
            x[:, i] = xc
            u[:, i] = _turn(u[:, i], c, rng)
            # a floor path (floor_albedo > 0) that escaped the collision: not followed
            # further (its reflection is scored above; its later orders are in the
            # bound below)
        sums += [np.sum(score, axis=1), np.sum(score_fl, axis=1)]
        sq += [np.sum(score * score, axis=1), np.sum(score_fl * score_fl, axis=1)]
        ms = np.sum(score[1:], axis=0)
        mf = np.sum(score_fl, axis=0)
        tot[0] += np.sum(ms)
        tot[1] += np.sum(ms * ms)
        tot[2] += np.sum(mf)
        tot[3] += np.sum(mf * mf)
    mean = sums / n
    err = np.sqrt(np.maximum(sq / n - mean * mean, 0.0) / n)
    multi = (tot[0] / n, math.sqrt(max(tot[1] / n - (tot[0] / n) ** 2, 0.0) / n),
             tot[2] / n, math.sqrt(max(tot[3] / n - (tot[2] / n) ** 2, 0.0) / n))
    return mean, err, multi


def report(n=25000):
    med = Medium()
    ss = SingleScattering(med)
    print("multiple scattering against single (Monte Carlo, %d paths per point; A = %.2f)"
          % (n, FLOOR_ALBEDO))
    print("  h_km theta  E_single(quad)  order1/quad-1 (se)   air>=2/single (se)  "
          "floor/single (se)  order2/single")
    for k, (h, th_deg) in enumerate(CASES):
        th = math.radians(th_deg)
        e_q, _ = ss.irradiance(th, med.R + h)
        m, s, multi = paths(th, med.R + h, n=n, seed=100 + k, med=med, ss=ss)
        print("%6.0f %5.1f  %12.4g  %+8.4f (%.4f)  %9.4f (%.4f)  %9.4f (%.4f)  %9.4f" % (
            h, th_deg, e_q, m[0, 0] / e_q - 1, s[0, 0] / e_q, multi[0] / e_q, multi[1] / e_q,
            multi[2] / e_q, multi[3] / e_q, m[0, 1] / e_q), flush=True)


if __name__ == "__main__":
    report()
