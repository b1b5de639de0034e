# SPDX-License-Identifier: MIT
"""Albedo models (knocke, map) of oi_illuminate against brute-force quadrature.

The reference (tests/python/albedo_reference.py) integrates the same albedo
field over the lit visible Earth with nested adaptive quadrature, in other
variables than the runtime's fixed cubature; the fields are written out
again from their definitions. Goal (docs/earthshine-albedo.md): e_earth
within 1e-3 relative wherever the earthshine exceeds 1 % of its sub-solar
value at that altitude, at every altitude. The ratio to the uniform sphere
isolates the albedo model from the uniform table's own error.
"""
import math
import warnings

import numpy as np
import pytest

import _oi_ctypes as T
import albedo_reference as ref

M = T.M
R_E = M.OI_EARTH_RADIUS_KM
SUN_KM = 1.496e8
E0 = M.OI_TSI_W_M2 * (M.OI_AU_KM / SUN_KM) ** 2
J2000 = 2451545.0
ALTITUDES = (1.0, 30.0, 100.0, 400.0, 2000.0, 20000.0, 35786.0, 384400.0)

# a rough map: 9 x 18 cells of random albedo (seeded), and a smooth zonal one
_rng = np.random.default_rng(15)
ROUGH = _rng.uniform(0.05, 0.9, size=(9, 18)).astype(np.float32)


def geometry(theta_deg, h_km, tilt=0.4, spin=0.7):
    """Sun and target positions (km): the Sun at latitude tilt (rad) above the
    frame's equator, the target theta from it, turned by spin about it."""
    s_hat = np.array([math.cos(tilt), 0.0, math.sin(tilt)])
    a = np.array([-math.sin(tilt), 0.0, math.cos(tilt)])
    b = np.cross(s_hat, a)
    k = math.cos(spin) * a + math.sin(spin) * b
    th = math.radians(theta_deg)
    t_hat = math.cos(th) * s_hat + math.sin(th) * k
    return s_hat * SUN_KM, t_hat * (R_E + h_km)


def illuminate(sun, target, model, epoch=J2000, rotation=0.0, grid=None, observer=None,
               earth_albedo=0.3):
    return T.illuminate_albedo(sun, target, model, epoch, rotation, grid, observer, earth_albedo)


def field_of(model, epoch, rotation, grid):
    return ref.knocke(epoch) if model == M.OI_ALBEDO_KNOCKE else ref.bilinear_map(grid, rotation)


def points():
    out = []
    for h in ALTITUDES:
        w = math.degrees(math.acos(R_E / (R_E + h)))
        for th in (0.0, 30.0, 70.0, 88.0, 90.0 + 0.4 * w, 90.0 + 0.8 * w):
            out.append((h, th))
    return out


def smooth_grid(n_lat=36, n_lon=72):
    """A 5-degree map sampled from a smooth field with a known form: zonal,
    tesseral and sectoral parts (values in [0.1, 0.65])."""
    lat = math.pi / 2 - (np.arange(n_lat) + 0.5) * math.pi / n_lat
    lon = (np.arange(n_lon) + 0.5) * 2 * math.pi / n_lon
    la, lo = np.meshgrid(lat, lon, indexing="ij")
    a = (0.3 + 0.2 * np.sin(la) ** 2 + 0.1 * np.cos(la) * np.cos(lo - 1.0) +
         0.05 * np.sin(2 * la) * np.sin(2 * lo))
    return a.astype(np.float32)


SMOOTH = smooth_grid()

# (model, epoch, rotation, grid, points, bound on e_earth's relative error,
# on the mean albedo's): the goal (1e-3) for the Knocke field, a smooth map
# and a rough one (random cells of 20 degrees, bilinear kinks along every
# row and column of centres), the maps integrated patch by patch
# (docs/earthshine-albedo.md)
CASES = [(M.OI_ALBEDO_KNOCKE, J2000 + 40.0, 0.0, None, points(), 1e-3, 1e-4),
         (M.OI_ALBEDO_MAP, J2000, 1.1, SMOOTH, points(), 1e-3, 1e-3),
         (M.OI_ALBEDO_MAP, J2000, 1.1, ROUGH, points(), 1e-3, 1e-3)]


@pytest.mark.parametrize("model,epoch,rotation,grid,pts,e_tol,mean_tol", CASES,
                         ids=["knocke", "smooth-map", "rough-map"])
def test_e_earth_and_direction_against_brute_force(model, epoch, rotation, grid, pts, e_tol,
                                                   mean_tol):
    warnings.simplefilter("ignore")
    field = field_of(model, epoch, rotation, grid)
    worst_e = worst_ratio = worst_dir = 0.0
    for h, th in pts:
        sun, tgt = geometry(th, h)
        sub_sun, sub_tgt = geometry(0.0, h)
        E_sub, _, _ = ref.earthshine(sub_sun, sub_tgt, ref.uniform(), epsrel=1e-9)
        E1, V1, _ = ref.earthshine(sun, tgt, ref.uniform(), epsrel=1e-9)
        if E1 < 0.01 * E_sub:
            continue  # the goal's domain: earthshine above 1 % of the sub-solar value
        E, V, _ = ref.earthshine(sun, tgt, field, epsrel=1e-9)
        st, out = illuminate(sun, tgt, model, epoch, rotation, grid)
        assert st == M.OI_OK
        rel = out.e_earth / (E0 * E) - 1.0
        ratio = out.earth_albedo_eff / (E / E1) - 1.0
        d_ref = V / np.linalg.norm(V)  # towards where the light comes from
        dir_err = math.acos(min(1.0, float(np.dot(d_ref, np.array(out.dir_earth[:])))))
        d_uni = V1 / np.linalg.norm(V1)
        worst_e = max(worst_e, abs(rel))
        worst_ratio = max(worst_ratio, abs(ratio))
        worst_dir = max(worst_dir, dir_err)
        # the model moves the direction: the runtime follows the reference,
        # not the uniform sphere's
        shift = math.acos(min(1.0, float(np.dot(d_ref, d_uni))))
        table = out.earth_phi / E1 - 1.0  # the uniform table against the same reference
        print(f"h={h:9.1f} theta={th:7.2f} e_earth rel {rel:+.2e} mean albedo rel {ratio:+.2e}"
              f" direction {dir_err:.1e} rad (field moves it {shift:.1e}; uniform table"
              f" {table:+.1e})")
        assert abs(rel) <= e_tol, (h, th, rel)
        assert abs(ratio) <= mean_tol, (h, th, ratio)
        assert dir_err <= max(1e-3, 0.1 * shift), (h, th, dir_err, shift)
    print(f"worst: e_earth {worst_e:.2e}, mean albedo {worst_ratio:.2e}, direction {worst_dir:.1e} rad")


def test_sphere_flux_against_brute_force():
    """The Lambertian sphere's earthshine towards an observer (flux_earth, the
    angular table's shape plus the field's change) over the uniform
    sphere's, against the same ratio of brute-force sums of L p(xi) dOmega."""
    warnings.simplefilter("ignore")
    epoch = J2000 + 40.0
    field = ref.knocke(epoch)
    worst = 0.0
    for h, th, obs_dir in [(400.0, 30.0, (0.3, 0.8, 0.5)), (400.0, 85.0, (-0.6, 0.2, -0.77)),
                           (2000.0, 60.0, (0.9, -0.3, 0.3)), (36000.0, 100.0, (0.1, 0.2, -0.97)),
                           (20000.0, 10.0, (-0.7, 0.7, 0.1))]:
        sun, tgt = geometry(th, h)
        o = np.array(obs_dir) / np.linalg.norm(obs_dir)
        observer = np.asarray(tgt) + 500.0 * o
        _, _, F = ref.earthshine(sun, tgt, field, obs_hat=o)
        _, _, F1 = ref.earthshine(sun, tgt, ref.uniform(), obs_hat=o)
        st, out = illuminate(sun, tgt, M.OI_ALBEDO_KNOCKE, epoch, observer=observer)
        st1, uni = illuminate(sun, tgt, M.OI_ALBEDO_UNIFORM, observer=observer, earth_albedo=1.0)
        assert st >= 0 and st1 >= 0
        rel = (out.flux_earth / uni.flux_earth) / (F / F1) - 1.0
        # without the field's change of the shape: the mean albedo alone
        plain = out.earth_albedo_eff / (F / F1) - 1.0
        print(f"h={h:8.1f} theta={th:6.1f} sphere flux ratio rel {rel:+.2e} "
              f"(mean albedo alone {plain:+.2e})")
        worst = max(worst, abs(rel))
        assert abs(rel) <= 1e-3, (h, th, rel)
    print(f"worst sphere flux ratio {worst:.2e}")


# a rough 1-degree map (a CERES grid's size, independent random cells)
ROUGH_1DEG = np.random.default_rng(151).uniform(0.05, 0.9, size=(180, 360)).astype(np.float32)


def test_rough_one_degree_map_against_brute_force():
    """The 1-degree rough map, where a fixed cubature only samples the cells:
    against the brute force with a fixed azimuth rule (720 panels of 8 Gauss
    points, 400 in the central angle: it agrees with twice as many to 5e-7)."""
    warnings.simplefilter("ignore")
    rotation = 2.3
    field = ref.bilinear_map(ROUGH_1DEG, rotation)
    worst_e = worst_dir = 0.0
    for h, th in [(100.0, 30.0), (400.0, 88.0), (2000.0, 60.0), (35786.0, 30.0),
                  (35786.0, 140.0), (384400.0, 70.0)]:
        sun, tgt = geometry(th, h)
        E1, _, _ = ref.earthshine(sun, tgt, ref.uniform(), epsrel=1e-9)
        E, V, _ = ref.earthshine(sun, tgt, field, panels=400, beta_panels=720)
        st, out = illuminate(sun, tgt, M.OI_ALBEDO_MAP, rotation=rotation, grid=ROUGH_1DEG)
        assert st == M.OI_OK
        rel = out.earth_albedo_eff / (E / E1) - 1.0
        d_ref = V / np.linalg.norm(V)
        dir_err = math.acos(min(1.0, float(np.dot(d_ref, np.array(out.dir_earth[:])))))
        print(f"1-degree map h={h:8.1f} theta={th:6.1f} mean albedo rel {rel:+.2e}"
              f" direction {dir_err:.1e} rad")
        worst_e = max(worst_e, abs(rel))
        worst_dir = max(worst_dir, dir_err)
        assert abs(rel) <= 1e-3, (h, th, rel)
        assert dir_err <= 1e-3, (h, th, dir_err)
    print(f"worst: mean albedo {worst_e:.2e}, direction {worst_dir:.1e} rad")


def _far_mean(weight, a, breaks, lo, hi):
    """sum a w / sum w over [lo, hi] by mpmath, split at the field's kinks."""
    import mpmath as mp
    mp.mp.dps = 30
    pts = [lo] + sorted(b for b in breaks if lo < b < hi) + [hi]
    num = mp.quad(lambda t: a(t) * weight(t), pts)
    den = mp.quad(weight, pts)
    return float(num / den)


def _piecewise_linear(centres, values, periodic):
    """the bilinear map's field along one coordinate: linear between cell
    centres, constant beyond the end ones (periodic: wraps instead)."""
    import mpmath as mp
    c = [mp.mpf(float(x)) for x in centres]
    v = [mp.mpf(float(x)) for x in values]
    n = len(c)

    def a(t):
        if periodic:
            t = (t - c[0]) % (2 * mp.pi) + c[0]
            k = min(int((t - c[0]) / (c[1] - c[0])), n - 1)
            t0, v0, v1 = c[k], v[k], v[(k + 1) % n]
            return v0 + (v1 - v0) * (t - t0) / (c[1] - c[0])
        if t <= c[0]:
            return v[0]
        if t >= c[-1]:
            return v[-1]
        k = min(int((t - c[0]) / (c[1] - c[0])), n - 2)
        return v[k] + (v[k + 1] - v[k]) * (t - c[k]) / (c[k + 1] - c[k])
    return a


@pytest.mark.parametrize("n_rows", [9, 36])
def test_map_known_integral_far_above_the_pole(n_rows):
    """Rows of random albedo (each row one value, so the field depends on the
    colatitude c alone), a target 1e9 km above the north pole and the Sun
    behind it: the mean albedo is a one-dimensional integral of the field,
    piecewise linear in c, against cos(i) cos(e) / d^2 sin(c) at that
    distance, done by mpmath between the kinks."""
    import mpmath as mp
    rng = np.random.default_rng(1500 + n_rows)
    rows = rng.uniform(0.05, 0.9, size=n_rows).astype(np.float32)
    grid = np.repeat(rows[:, None], 24, axis=1)
    r_km = 1e9
    rho = mp.mpf(r_km) / mp.mpf(R_E)
    cmax = mp.acos(1 / rho)

    def weight(c):
        d = mp.sqrt(1 + rho * rho - 2 * rho * mp.cos(c))
        return mp.cos(c) * (rho * mp.cos(c) - 1) / d ** 3 * mp.sin(c)
    centres = [(i + 0.5) * math.pi / n_rows for i in range(n_rows)]
    want = _far_mean(weight, _piecewise_linear(centres, rows, False), centres, 0, cmax)
    st, out = illuminate((0.0, 0.0, SUN_KM), (0.0, 0.0, r_km), M.OI_ALBEDO_MAP, rotation=0.3,
                         grid=grid)
    assert st >= 0
    rel = out.earth_albedo_eff / want - 1.0
    print(f"{n_rows} rows, far above the pole: mean albedo {out.earth_albedo_eff:.9f}"
          f" vs {want:.9f} ({rel:+.1e}); direction z {out.dir_earth[2]:+.12f}")
    assert abs(rel) <= 2e-5
    assert out.dir_earth[2] < -1.0 + 1e-9  # a zonal field does not tilt it


@pytest.mark.parametrize("n_cols", [18, 360])
def test_map_known_integral_far_above_the_equator(n_cols):
    """Columns of random albedo (every row the same, so the field depends on
    the longitude alone), a target 1e10 km above the equator and the Sun
    behind it: in the far field (R / r = 6e-7) the weights separate,
    cos^2(lon - lon0) cos^3(lat), and the mean albedo is the field's
    cos^2-weighted mean over the lit half, by mpmath between the kinks."""
    import mpmath as mp
    rng = np.random.default_rng(1600 + n_cols)
    cols = rng.uniform(0.05, 0.9, size=n_cols).astype(np.float32)
    grid = np.repeat(cols[None, :], 12, axis=0)
    rotation = 0.8
    lon0 = 2.1  # the target's frame longitude; east of Greenwich by lon0 - rotation
    centres = [(j + 0.5) * 2 * math.pi / n_cols for j in range(n_cols)]
    a = _piecewise_linear(centres, cols, True)
    e0 = lon0 - rotation
    breaks = [c + k * 2 * math.pi for c in centres for k in (-1, 0, 1)]
    want = _far_mean(lambda t: mp.cos(t - e0) ** 2, a, breaks, e0 - mp.pi / 2, e0 + mp.pi / 2)
    u = (math.cos(lon0), math.sin(lon0), 0.0)
    st, out = illuminate(tuple(SUN_KM * x for x in u), tuple(1e10 * x for x in u),
                         M.OI_ALBEDO_MAP, rotation=rotation, grid=grid)
    assert st >= 0
    rel = out.earth_albedo_eff / want - 1.0
    print(f"{n_cols} columns, far above the equator: mean albedo {out.earth_albedo_eff:.9f}"
          f" vs {want:.9f} ({rel:+.1e})")
    assert abs(rel) <= 2e-5


def test_sphere_flux_under_rough_map_against_brute_force():
    """The sphere's reflection of the rough map's light towards an observer
    (the field's change of the angular distribution), as for Knocke."""
    warnings.simplefilter("ignore")
    worst = 0.0
    for h, th, obs_dir in [(400.0, 30.0, (0.3, 0.8, 0.5)), (2000.0, 85.0, (-0.6, 0.2, -0.77)),
                           (20000.0, 110.0, (0.9, -0.3, 0.3)), (36000.0, 40.0, (0.1, 0.2, -0.97))]:
        sun, tgt = geometry(th, h)
        o = np.array(obs_dir) / np.linalg.norm(obs_dir)
        observer = np.asarray(tgt) + 500.0 * o
        field = ref.bilinear_map(ROUGH, 1.1)
        _, _, F = ref.earthshine(sun, tgt, field, obs_hat=o)
        _, _, F1 = ref.earthshine(sun, tgt, ref.uniform(), obs_hat=o)
        st, out = illuminate(sun, tgt, M.OI_ALBEDO_MAP, rotation=1.1, grid=ROUGH,
                             observer=observer)
        st1, uni = illuminate(sun, tgt, M.OI_ALBEDO_UNIFORM, observer=observer, earth_albedo=1.0)
        assert st >= 0 and st1 >= 0
        rel = (out.flux_earth / uni.flux_earth) / (F / F1) - 1.0
        plain = out.earth_albedo_eff / (F / F1) - 1.0
        print(f"rough map h={h:8.1f} theta={th:6.1f} sphere flux ratio rel {rel:+.2e} "
              f"(mean albedo alone {plain:+.2e})")
        worst = max(worst, abs(rel))
        assert abs(rel) <= 1e-3, (h, th, rel)
    print(f"worst sphere flux ratio under the rough map {worst:.2e}")
