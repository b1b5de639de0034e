# SPDX-License-Identifier: MIT
"""The earthshine angular table (oi_earth_angular_table, include/oi_table.h):
the flux a Lambertian sphere sends to any observer direction under the
earthshine of a uniform Lambertian Earth, from low-order moments of the
incoming radiance (docs/earthshine-angular.md).

Representation. In the local frame at the target (z the zenith, x towards
the Sun's side, y normal to the Sun-Earth-target plane) the incoming radiance
L(omega) is even in y, so its real spherical harmonics are the cosine ones,
Y_lm = K_lm P_l^m(z) cos(m phi). The sphere's flux towards o is a zonal
convolution, F(o) = int L(omega) p(acos(omega.o)) dOmega
= sum_l s_l sum_m L_lm Y_lm(o) (Funk-Hecke, s_l = 2 pi int p P_l dmu), and
s_l = 0 for odd l >= 3 (p is the clamped cosine convolved with itself,
Ramamoorthi & Hanrahan 2001). Stored per node: the products
c_lm = s_l K_lm (-1)^m L_lm / x^2 for l in {0, 1, 2, 4, ..., l_max} and
0 <= m <= l (the runtime forms sum c_lm Re((o_x + i o_y)^m) Q_l^m(o_z) with
Q_l^m = d^m P_l / dz^m), and g = beta phi / x^2: the part of the light
treated as coming exactly from the mean direction d, whose truncation error
the runtime adds back, F += beta phi (p(xi_d) - p_L(cos xi_d)); beta in
[0, 1] is chosen per node by the baker (0 at low altitude where the visible
Earth is wide, towards 1 far away where it is a point and the truncated
series alone rings). The mean direction d is that of the l = 1 moments.

Grid: w = acos(R/r) uniform on [w_min, pi/2] (pi/2: infinity), theta =
v (pi/2 + w) with v uniform on [0, 1] (beyond v = 1 nothing lit is visible:
F = 0); bilinear interpolation. Measured against the quadrature of
bake/earthshine/angular.py at random points between the nodes.
"""

import math

import numpy as np

from .. import __version__
from ..common import emit as cemit
from ..common.quadrature import gauss_legendre
from . import angular

FORMAT = 1  # OI_ANGULAR_FORMAT in include/oi_table.h
GENERATOR = "bake.earthshine.angular"
NAME = "oi_earth_angular"
R_KM = 6378.137

DEFAULT = {"l_max": 8, "n_alt": 12, "n_lit": 2, "n_term": 13, "h_min_km": 100.0,
           "betas": 11, "n_dirs": 500, "n_measure": 300, "seed": 20261202}


def degrees(l_max):
    return [l for l in range(l_max + 1) if l <= 1 or l % 2 == 0]


def n_coef(l_max):
    return sum(l + 1 for l in degrees(l_max))


def _legendre_all(l_max, z):
    """P_l(z), l = 0..l_max (three-term recurrence)."""
    p = [np.ones_like(z), z]
    for l in range(2, l_max + 1):
        p.append(((2 * l - 1) * z * p[l - 1] - (l - 1) * p[l - 2]) / l)
    return p


def basis(l_max, v):
    """Re((x + i y)^m) Q_l^m(z) for the stored (l, m), columns in storage order;
    the same recurrences as the runtime (src/earthshine_angular.c)."""
    x, y, z = v[..., 0], v[..., 1], v[..., 2]
    cm = [np.ones_like(x)]
    re, im = np.ones_like(x), np.zeros_like(x)
    for m in range(1, l_max + 1):
        re, im = re * x - im * y, re * y + im * x
        cm.append(re)
    cols = []
    q = {}
    for m in range(l_max + 1):
        dfact = float(np.prod(np.arange(2 * m - 1, 0, -2))) if m > 0 else 1.0
        q[(m, m)] = dfact * np.ones_like(z)
        if m + 1 <= l_max:
            q[(m + 1, m)] = z * (2 * m + 1) * q[(m, m)]
        for l in range(m + 2, l_max + 1):
            q[(l, m)] = ((2 * l - 1) * z * q[(l - 1, m)] - (l + m - 1) * q[(l - 2, m)]) / (l - m)
    for l in degrees(l_max):
        for m in range(l + 1):
            cols.append(cm[m] * q[(l, m)])
    return np.stack(cols, axis=-1)


def norms(l_max):
    """K_lm (-1)^m per stored column: Y_lm = K_lm P_l^m cos(m phi), P_l^m with
    the Condon-Shortley phase = (-1)^m sin^m Q_l^m."""
    out = []
    for l in degrees(l_max):
        for m in range(l + 1):
            k = (2 * l + 1) / (4 * math.pi) * math.factorial(l - m) / math.factorial(l + m)
            out.append(math.sqrt(k * (1 if m == 0 else 2)) * (-1) ** m)
    return np.array(out)


def sphere_kernel(l_max):
    """s_l = 2 pi int_{-1}^{1} p(acos mu) P_l(mu) dmu (Gauss-Legendre, 400 nodes
    on each half: p is smooth inside, its second derivative integrable)."""
    x, w = gauss_legendre(400)
    mu = np.concatenate([0.5 * (x - 1.0), 0.5 * (x + 1.0)])
    wt = np.concatenate([0.5 * w, 0.5 * w])
    p = angular.lambert_phase(np.arccos(np.clip(mu, -1.0, 1.0)))
    pl = _legendre_all(l_max, mu)
    return {l: 2.0 * math.pi * float(np.sum(wt * p * pl[l])) for l in degrees(l_max)}


def truncated_phase(l_max, kern, mu):
    """p_L(mu) = sum over the stored degrees of s_l (2l+1)/(4 pi) P_l(mu)."""
    pl = _legendre_all(l_max, mu)
    return sum(kern[l] * (2 * l + 1) / (4 * math.pi) * pl[l] for l in degrees(l_max))


def score(q, ex):
    """Error in units of the goal: 1 % where ex > 1 % of its maximum, 1e-4 of
    the maximum elsewhere."""
    mx = float(np.max(ex))
    if mx <= 0.0:
        return float(np.max(np.abs(q))) / 1e-300 if np.any(q != 0) else 0.0
    big = ex > 0.01 * mx
    s1 = float(np.max(np.abs(q[big] / ex[big] - 1.0))) / 0.01 if np.any(big) else 0.0
    s2 = float(np.max(np.abs(q[~big] - ex[~big]))) / mx / 1e-4 if np.any(~big) else 0.0
    return max(s1, s2)


def directions(n, seed):
    rng = np.random.default_rng(seed)
    d = rng.normal(size=(n, 3))
    return d / np.linalg.norm(d, axis=1)[:, None]


def node_values(theta, x, cfg, kern, dirs, nrm):
    """(shape coefficients[n_coef], beta) at one node: c_lm / phi (the
    distribution per unit scalar irradiance) and the weight of the mean
    direction."""
    l_max = cfg["l_max"]
    om, w = angular.mirrored(*angular.nodes(theta, x))
    phi = float(w.sum())
    if not phi > 0.0:
        return limb_node(x, cfg, kern, nrm)
    w = w / phi
    sk = np.array([kern[l] for l in degrees(l_max) for m in range(l + 1)])
    coef = sk * nrm * (basis(l_max, om) * w[:, None]).sum(axis=0) * nrm
    ex = (angular.lambert_phase(np.arccos(np.clip(dirs @ om.T, -1, 1))) * w).sum(axis=1)
    q0 = basis(l_max, dirs) @ coef
    corr = correction(coef, dirs, l_max, kern)
    best = (math.inf, 0.0)
    for beta in np.linspace(0.0, 1.0, cfg["betas"]):
        s = score(q0 + beta * corr, ex)
        if s < best[0] - 1e-12:
            best = (s, float(beta))
    return coef, best[1]


def point_node(direction, cfg, kern, nrm):
    """All the light from one direction: exact with beta = 1."""
    l_max = cfg["l_max"]
    sk = np.array([kern[l] for l in degrees(l_max) for m in range(l + 1)])
    coef = sk * nrm * nrm * basis(l_max, np.asarray(direction, dtype=float)[None, :])[0]
    return coef, 1.0


def limb_node(x, cfg, kern, nrm):
    """The limit at the cap's far edge (theta -> pi/2 + w): the lit part
    shrinks to the limb point on the Sun's side, at asin(x) from the nadir."""
    eta = math.asin(x)
    return point_node((math.sin(eta), 0.0, -math.cos(eta)), cfg, kern, nrm)


def mean_direction(coef):
    """d from the l = 1 columns (c_10 = s_1 (3/4pi) V_z, c_11 = s_1 (3/4pi) V_x)."""
    v = np.array([coef[2], 0.0, coef[1]])
    n = np.linalg.norm(v)
    return v / n if n > 0 else np.array([0.0, 0.0, -1.0])


def correction(coef, dirs, l_max, kern):
    d = mean_direction(coef)
    mu = np.clip(dirs @ d, -1.0, 1.0)
    return angular.lambert_phase(np.arccos(mu)) - truncated_phase(l_max, kern, mu)


def grid(cfg):
    """Altitude nodes w and, per row, the theta nodes of the two segments:
    lit, theta = v (pi/2 - w) (n_lit nodes, the whole visible cap lit), and
    terminator, theta = pi/2 + w t, t uniform on [-1, 1] (n_term nodes)."""
    w_min = math.acos(R_KM / (R_KM + cfg["h_min_km"]))
    w = np.linspace(w_min, 0.5 * math.pi, cfg["n_alt"])
    return w


def thetas(cfg, w):
    lit = np.array([0.0, 0.5 * math.pi - w])
    term = 0.5 * math.pi + w * np.linspace(-1.0, 1.0, cfg["n_term"])
    return np.concatenate([lit, term])


def bake_values(cfg, log=print):
    kern = sphere_kernel(cfg["l_max"])
    nrm = norms(cfg["l_max"])
    dirs = directions(cfg["n_dirs"], cfg["seed"])
    w = grid(cfg)
    nc = n_coef(cfg["l_max"])
    nt = cfg["n_lit"] + cfg["n_term"]
    vals = np.zeros((cfg["n_alt"], nt, nc + 1))
    for j, wj in enumerate(w):
        x = math.cos(wj) if wj < 0.5 * math.pi else 0.0
        for i, theta in enumerate(thetas(cfg, wj)):
            if x == 0.0:
                coef, beta = point_node((0.0, 0.0, -1.0), cfg, kern, nrm)  # far field
            elif i == nt - 1:
                coef, beta = limb_node(x, cfg, kern, nrm)
            else:
                coef, beta = node_values(theta, x, cfg, kern, dirs, nrm)
            vals[j, i, :nc] = coef
            vals[j, i, nc] = beta
        log("  angular: row %d/%d (w = %.4f)" % (j + 1, cfg["n_alt"], wj))
    return vals


def _cr(t):
    """Catmull-Rom weights of the four nodes around t in [0, 1]."""
    t2, t3 = t * t, t * t * t
    return np.array([-0.5 * t3 + t2 - 0.5 * t, 1.5 * t3 - 2.5 * t2 + 1.0,
                     -1.5 * t3 + 2.0 * t2 + 0.5 * t, 0.5 * t3 - 0.5 * t2])


def _stencil(f, n):
    """Cell, four node indices (ghosts folded by linear extrapolation) and weights."""
    i = min(max(int(math.floor(f)), 0), n - 2)
    t = f - i
    wts = _cr(t)
    idx = [i - 1, i, i + 1, i + 2]
    out = np.zeros(n)
    for k, (j, wk) in enumerate(zip(idx, wts)):
        if j < 0:       # ghost: 2 f0 - f1
            out[0] += 2 * wk
            out[1] -= wk
        elif j > n - 1:  # ghost: 2 f(n-1) - f(n-2)
            out[n - 1] += 2 * wk
            out[n - 2] -= wk
        else:
            out[j] += wk
    return out


def lookup(vals, cfg, theta, x, interp="cr"):
    """Interpolation as the runtime does it (float64): (coef, beta)."""
    w_min = math.acos(R_KM / (R_KM + cfg["h_min_km"]))
    w = math.acos(x)
    nl, nm = cfg["n_lit"], cfg["n_term"]
    theta = min(theta, 0.5 * math.pi + w)
    fu = (w - w_min) / (0.5 * math.pi - w_min) * (cfg["n_alt"] - 1)
    a = _stencil(fu, cfg["n_alt"])
    if theta <= 0.5 * math.pi - w:
        # lit: the moments are linear in (cos theta, sin theta) and phi is
        # cos(theta) phi(0), so the shape is linear in tan(theta): exact
        u = math.tan(theta) * math.tan(w)
        b = np.concatenate([[1.0 - u, u], np.zeros(nm)])
    else:
        fv = (theta - 0.5 * math.pi + w) / (2.0 * w) * (nm - 1)
        b = np.concatenate([np.zeros(nl), _stencil(fv, nm)])
    c = np.einsum("j,i,jik->k", a, b, vals)
    return c[:-1], c[-1]


def shape(vals, cfg, kern, theta, x, dirs, interp="cr"):
    """F(o) / phi: the sphere's flux per unit scalar irradiance (and per
    target albedo, a^2/d^2)."""
    coef, beta = lookup(vals, cfg, theta, x, interp)
    q = basis(cfg["l_max"], dirs) @ coef
    if beta != 0.0:
        q = q + beta * correction(coef, dirs, cfg["l_max"], kern)
    return q


def measure(vals, cfg, interp="cr", log=print):
    """Score at random (theta, h) between the nodes, h from h_min_km to 1e6 km,
    plus the far field, against the quadrature (angular.sphere)."""
    kern = sphere_kernel(cfg["l_max"])
    rng = np.random.default_rng(cfg["seed"] + 1)
    dirs = directions(400, cfg["seed"] + 2)
    w_min = math.acos(R_KM / (R_KM + cfg["h_min_km"]))
    worst = (0.0, None)
    scores = []
    pts = []
    for k in range(cfg["n_measure"]):
        w = rng.uniform(w_min, 0.5 * math.pi - 1e-3)
        x = math.cos(w)
        theta = rng.uniform(0.0, 0.5 * math.pi + w)
        ex = angular.sphere(theta, x, dirs)
        if not np.max(ex) > 0.0:
            continue
        phi = angular.scalar(theta, x)
        s = score(phi * shape(vals, cfg, kern, theta, x, dirs, interp), ex)
        scores.append(s)
        pts.append((s, theta, R_KM / x - R_KM))
        if s > worst[0]:
            worst = (s, (theta, R_KM / x - R_KM))
    scores = np.array(scores)
    if log is not None:
        for s_, t_, h_ in sorted(pts)[-8:]:
            log("  angular: score %.3f at theta %.4f, h %.1f km" % (s_, t_, h_))
    return {"max_score": cemit.round_sig(float(scores.max())),
            "p95_score": cemit.round_sig(float(np.percentile(scores, 95))),
            "median_score": cemit.round_sig(float(np.median(scores))),
            "n_points": int(scores.size), "n_dirs": int(dirs.shape[0]),
            "worst_theta": cemit.round_sig(worst[1][0]),
            "worst_h_km": cemit.round_sig(worst[1][1])}


def provenance_lines(cfg, m):
    return [
        "The shape of the flux a Lambertian sphere sends to any observer direction",
        "under the earthshine of a uniform Lambertian Earth, per unit scalar",
        "irradiance phi (docs/earthshine-angular.md; layout include/oi_table.h):",
        "  the real spherical-harmonic moments of the incoming radiance times the",
        "  sphere's kernel, degrees 0, 1 and even up to %d, and the weight beta of" % cfg["l_max"],
        "  the mean direction's correction; 16-bit codes, offset + scale code per",
        "  coefficient (offset and scale float32).",
        "Moments: quadrature over the visible sunlit Earth (bake/earthshine/angular.py).",
        "Grid: n_alt = %d rows uniform in w = acos(R/r) from h = %g km to infinity;" % (
            cfg["n_alt"], cfg["h_min_km"]),
        "  per row 2 lit columns (exact in tan(theta)) and %d terminator columns." % cfg["n_term"],
        "Goal: within 1 % where the flux exceeds 1 % of its maximum over observer",
        "  directions at that (theta, h), within 1e-4 of that maximum elsewhere.",
        "Measured against the quadrature at %d random (theta, h) between the nodes," % m["n_points"],
        "  %d observer directions each (seed %d), in units of the goal:" % (m["n_dirs"], cfg["seed"]),
        "  max %.3f, 95th percentile %.3f, median %.3f (worst at theta %.4g, h %.4g km)." % (
            m["max_score"], m["p95_score"], m["median_score"], m["worst_theta"], m["worst_h_km"]),
    ]


def quantise(vals):
    """16-bit codes per coefficient over its own range: value = offset[k] +
    scale[k] code, offset and scale float32, scale a power of two and offset
    an integer multiple of it, so that 0 decodes to exactly 0 (the m >= 1
    moments vanish on the Sun-Earth axis: a sphere there stays symmetric about
    the zenith). Returns (offset, scale, codes, decoded values as the runtime
    reads them)."""
    flat = vals.reshape(-1, vals.shape[-1])
    lo = np.minimum(flat.min(axis=0), 0.0)
    hi = np.maximum(flat.max(axis=0), 0.0)
    span = hi - lo
    exps = np.where(span > 0, np.ceil(np.log2(np.where(span > 0, span, 1.0) / 65534.0)), 0.0)
    s64 = np.where(span > 0, np.exp2(exps), 0.0)
    z0 = np.where(span > 0, np.ceil(-lo / np.where(s64 > 0, s64, 1.0)), 0.0)
    o64 = -z0 * s64
    off = cemit.f32(o64)
    scale = cemit.f32(s64)
    assert np.array_equal(off.astype(np.float64), o64) and np.array_equal(scale.astype(np.float64), s64)
    with np.errstate(divide="ignore", invalid="ignore"):
        code = np.where(s64 > 0, np.rint((flat - o64) / np.where(s64 > 0, s64, 1.0)), 0.0)
    if np.any(code < 0) or np.any(code > 65535):
        raise ValueError("angular table: code out of range")
    code = code.astype(np.uint16)
    dec = (o64 + s64 * code).reshape(vals.shape)
    return off, scale, code.reshape(vals.shape), dec


def bake(cfg=None, log=None):
    """(cfg, offset, scale, codes, decoded values, measured) of a configuration."""
    cfg = dict(DEFAULT if cfg is None else cfg)
    vals = bake_values(cfg, log=log or (lambda s: None))
    off, scale, code, dec = quantise(vals)
    return cfg, off, scale, code, dec, measure(dec, cfg, log=log)


def payload_bytes(code, off):
    return code.size * 2 + off.size * 4 * 2


def run(outdir, cfg=None, log=print, progress=False):
    """Bake, measure and write tables/oi_earth_angular.{c,h,json}."""
    cfg, off, scale, code, vals, m = bake(cfg, log=log if progress else None)
    nc = n_coef(cfg["l_max"])
    w_min = math.acos(R_KM / (R_KM + cfg["h_min_km"]))
    t = cemit.Table(
        name=NAME, kind="earth_angular", command="earthshine", ctype="oi_earth_angular_table",
        format=("OI_ANGULAR_FORMAT", FORMAT),
        summary="earthshine angular table (a sphere's flux towards any observer), %g km to infinity." % cfg["h_min_km"],
        fields=[("l_max", cfg["l_max"], "int"), ("n_coef", nc, "int"),
                ("n_alt", cfg["n_alt"], "int"), ("n_lit", cfg["n_lit"], "int"),
                ("n_term", cfg["n_term"], "int"), ("w_min", w_min, "double"),
                ("w_max", 0.5 * math.pi, "double")],
        arrays=[("offset", off, "float"), ("scale", scale, "float"),
                ("code", code.ravel(), "u16")],
        layout=("format", "kind", "info", "l_max", "n_coef", "n_alt", "n_lit", "n_term",
                "w_min", "w_max", "offset", "scale", "code"),
        generator=GENERATOR, version=__version__, parameters=cfg, seed=cfg["seed"],
        goal=1.0, max_error=m["max_score"], measured=m,
        grid={"w_min": w_min, "w_max": 0.5 * math.pi, "n_alt": cfg["n_alt"],
              "n_lit": cfg["n_lit"], "n_term": cfg["n_term"], "l_max": cfg["l_max"],
              "n_coef": nc, "h_min_km": cfg["h_min_km"], "h_max_km": None},
        provenance=provenance_lines(cfg, m))
    paths = cemit.write(outdir, t)
    log("oi_earth_angular: %d bytes, max error %.3f of the goal (p95 %.3f, median %.3f)" % (
        payload_bytes(code, off), m["max_score"], m["p95_score"], m["median_score"]))
    return paths
