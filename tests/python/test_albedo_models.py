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
import ctypes as C
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
ALTITUDES = (1.0, 30.0, 400.0, 2000.0, 20000.0, 384400.0)

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
    L = T.lib()
    s = M.oi_scene()
    L.oi_scene_defaults(C.byref(s))
    s.sun_km = T.R3(*sun)
    s.target_km = T.R3(*target)
    s.terms = M.OI_TERM_SUN | M.OI_TERM_EARTH
    s.earth_albedo = earth_albedo
    s.epoch_jd = epoch
    s.earth_rotation_rad = rotation
    if observer is not None:
        s.observer_km = T.R3(*observer)
        s.has_observer = 1
    m = M.oi_model()
    m.albedo_model = model
    keep = None
    if grid is not None:
        keep = np.ascontiguousarray(grid, dtype=np.float32)
        m.albedo_map = keep.ctypes.data_as(C.POINTER(C.c_float))
        m.albedo_map_n_lat, m.albedo_map_n_lon = keep.shape
    out = M.oi_illum()
    st = L.oi_illuminate(C.byref(s), C.byref(m), C.byref(out))
    del keep
    return st, out


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
# on the mean albedo's): the goal (1e-3) for the Knocke field (measured
# worst 2.1e-5) and a map smooth on the scale of the cubature's nodes
# (5.6e-5); a rough map (random cells of 20 degrees, bilinear kinks along
# every row and column of centres) misses it above ~2000 km, worst measured
# 5.8e-3 on a thin lit sliver at 20000 km (docs/earthshine-albedo.md): its
# bound is that, not the goal
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
