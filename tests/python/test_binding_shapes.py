# SPDX-License-Identifier: MIT
"""The binding's facet targets (target_shape, attitude_q, Shape, facet_brdf).

References written here: the closed form of a Sun-lit Lambertian plate, the
normalised modified Phong BRDF of include/orbillum.h as its formula, and the
planner (build/oi-plan --csv) on the same rows, digit for digit.
"""
import csv
import io
import math
import os
import subprocess

import numpy as np
import pytest

from _oi_plan import rotation

orbillum = pytest.importorskip("orbillum", reason="binding not installed: make binding")

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
PLAN = os.path.join(ROOT, "build", "oi-plan")
AU = 149597870.7
SUN = np.array([AU, 0.0, 0.0])
TARGET = np.array([0.0, 7000.0, 0.0])


def unit_quaternions(n, seed):
    q = np.random.default_rng(seed).normal(size=(n, 4))
    return q / np.linalg.norm(q, axis=1, keepdims=True)


def plate_flux(e_sun, q, observer, albedo, area=1.0, normal=(0.0, 0.0, 1.0)):
    n = rotation(q) @ np.asarray(normal, float)
    n /= np.linalg.norm(n)
    s = (SUN - TARGET) / np.linalg.norm(SUN - TARGET)
    o = observer - TARGET
    d_m = np.linalg.norm(o) * 1e3
    o /= np.linalg.norm(o)
    ci, ce = float(s @ n), float(o @ n)
    return 0.0 if ci <= 0 or ce <= 0 else e_sun * albedo * area * ci * ce / (math.pi * d_m ** 2)


def phong(rho_d, rho_s, shin, normal, to_source, to_observer):
    """The normalised modified Phong BRDF, from its formula."""
    n = np.asarray(normal, float) / np.linalg.norm(normal)
    s = np.asarray(to_source, float) / np.linalg.norm(to_source)
    o = np.asarray(to_observer, float) / np.linalg.norm(to_observer)
    if s @ n <= 0 or o @ n <= 0:
        return 0.0
    r = 2 * (s @ n) * n - s
    c = max(0.0, float(r @ o))
    return rho_d / math.pi + rho_s * (shin + 2) / (2 * math.pi) * c ** shin


def g17(x):
    x = float(x)
    return "%.17g" % (0.0 if x == 0.0 else x)


def test_plate_closed_form_per_row_attitudes():
    qs = unit_quaternions(30, 11)
    d = np.random.default_rng(12).normal(size=(30, 3))
    obs = TARGET + 10.0 * d / np.linalg.norm(d, axis=1, keepdims=True)
    r = orbillum.illuminate(SUN, None, TARGET, obs, terms="sun", target_albedo=0.25,
                            target_shape="plate", attitude_q=qs)
    assert (r["status"] == 0).all(), r["status_name"]
    lit = 0
    for i in range(30):
        want = plate_flux(float(r["e_sun"][i]), qs[i], obs[i], 0.25)
        assert abs(r["flux_obs"][i] - want) <= 1e-12 * max(want, 1e-300)
        lit += want > 0
    assert 2 <= lit <= 28
    assert (r["flux_specular"] == 0).all()


def test_facet_forms_agree_and_equal_the_builtin_plate():
    """A one-facet shape from dicts, from columns and from a FACET_DTYPE array,
    and the built-in plate (whose diffuse albedo is target_albedo): the same
    numbers, bit for bit."""
    q = (math.cos(0.4), 0.0, math.sin(0.4), 0.0)
    obs = TARGET + np.array([3.0, 0.0, 9.0])
    plate = orbillum.Shape("plate")
    assert plate.n_facets == 1 and plate.diffuse_from_scene
    assert list(plate.facets["normal"][0]) == [0.0, 0.0, 1.0] and plate.facets["area_m2"][0] == 1
    forms = [[{"normal": [0, 0, 1], "area_m2": 1.0, "albedo_diffuse": 0.2}],
             {"normal": [[0, 0, 1]], "area_m2": [1.0], "albedo_diffuse": [0.2]},
             orbillum.Shape([{"normal": (0, 0, 2), "area_m2": 1, "albedo_diffuse": 0.2,
                              "two_sided": False, "albedo_specular": 0, "shininess": 0}]).facets,
             "plate", plate]
    flux = [orbillum.illuminate(SUN, None, TARGET, obs, target_shape=f, attitude_q=q)["flux_obs"][0]
            for f in forms]
    assert flux[0] > 0
    assert all(f == flux[0] for f in flux), flux


def test_per_row_shapes_and_the_sphere():
    obs = TARGET + np.array([0.0, 0.0, 10.0])
    box = orbillum.Shape("box-wing")
    per_row = [None, "sphere", "plate", box, "cylinder"]
    r = orbillum.expose("telescope-15cm", SUN, None, np.tile(TARGET, (5, 1)), obs,
                        target_shape=per_row)
    assert (r["row_status"] >= 0).all()
    sphere = orbillum.expose("telescope-15cm", SUN, None, TARGET, obs)
    for k in ("flux_obs", "mag_v", "exposure_s", "snr"):
        assert r[k][0] == r[k][1] == sphere[k][0]
    for i, name in ((2, "plate"), (3, "box-wing"), (4, "cylinder")):
        one = orbillum.expose("telescope-15cm", SUN, None, TARGET, obs, target_shape=name)
        assert r["flux_obs"][i] == one["flux_obs"][0] and r["flux_obs"][i] > 0
    assert orbillum.shapes()[:1] == ["sphere"]
    assert {"plate", "box-wing", "cylinder"} <= set(orbillum.shapes())


def test_attitude_norm_is_a_row_status():
    obs = TARGET + np.array([0.0, 0.0, 10.0])
    q = np.array([[1, 0, 0, 0], [1 + 5e-7, 0, 0, 0], [1 + 2e-6, 0, 0, 0], [np.nan, 0, 0, 0]])
    r = orbillum.illuminate(SUN, None, np.tile(TARGET, (4, 1)), obs, target_shape="box-wing",
                            attitude_q=q)
    assert list(r["status_name"][:2]) == ["OK", "OK"]
    assert r["flux_obs"][0] == pytest.approx(r["flux_obs"][1], rel=1e-12)
    assert list(r["status_name"][2:]) == ["ERR_SHAPE", "ERR_SHAPE"]
    # a failed row's floats are NaN (the library's 0 reads as a value)
    assert np.isnan(r["flux_obs"][2:]).all() and np.isnan(r["e_sun"][2:]).all()
    # a sphere has no attitude: not read, not checked (as the planner)
    s = orbillum.illuminate(SUN, None, np.tile(TARGET, (4, 1)), obs, attitude_q=q)
    assert list(s["status_name"]) == ["OK"] * 4


@pytest.mark.parametrize("kw,exc,words", [
    (dict(target_shape="Plate"), ValueError, "target_shape: no built-in shape 'Plate'"),
    (dict(target_shape=[{"normal": [0, 0, 1], "area_m2": 1}]), ValueError,
     "'albedo_diffuse' missing"),
    (dict(target_shape=[{"normal": [0, 0, 1], "area_m2": 1, "albedo_diffuse": 0.2,
                         "colour": 1}]), ValueError, "unknown facet field(s) colour"),
    (dict(target_shape=[{"normal": [0, 1], "area_m2": 1, "albedo_diffuse": 0.2}]), ValueError,
     "target_shape[0]['normal']: 3 numbers"),
    (dict(target_shape=[{"normal": [0, 0, 1], "area_m2": "1", "albedo_diffuse": 0.2}]),
     TypeError, "target_shape[0]['area_m2']: a number"),
    (dict(target_shape=[{"normal": [0, 0, 1], "area_m2": 1, "albedo_diffuse": 0.2},
                        {"normal": [0, 0, 1], "area_m2": -1, "albedo_diffuse": 0.2}]),
     ValueError, "target_shape[1]: the library rejects this facet (ERR_SHAPE)"),
    (dict(target_shape=[{"normal": [0, 0, 0], "area_m2": 1, "albedo_diffuse": 0.2}]),
     ValueError, "target_shape[0]: the library rejects"),
    (dict(target_shape=[{"normal": [0, 0, 1], "area_m2": 1, "albedo_diffuse": 0.7,
                         "albedo_specular": 0.4}]), ValueError, "the library rejects"),
    (dict(target_shape=[{"normal": [0, 0, 1], "area_m2": 1, "albedo_diffuse": 0.2,
                         "shininess": -1}]), ValueError, "the library rejects"),
    (dict(target_shape=[{"normal": [0, 0, 1], "area_m2": 1, "albedo_diffuse": 0.2}] * 33),
     ValueError, "1 to OI_FACETS_MAX = 32 facets, got 33"),
    (dict(target_shape=[]), ValueError, "1 to OI_FACETS_MAX"),
    (dict(target_shape=3.0), TypeError, "target_shape: a built-in name"),
    (dict(target_shape=["plate", "plate"], observer=np.zeros((3, 3)) + TARGET + 5), ValueError,
     "row counts differ: 3 and 2"),
    (dict(attitude_q=[1, 0, 0]), ValueError, "attitude_q: expected shape (N, 4)"),
    (dict(attitude_q="identity"), TypeError, "attitude_q: expected numbers"),
    (dict(attitude_q=np.ones((2, 4)) / 2, observer=np.zeros((3, 3)) + TARGET + 5),
     ValueError, "row counts differ"),
])
def test_bad_arguments_name_themselves(kw, exc, words):
    args = dict(observer=TARGET + 5.0)
    args.update(kw)
    with pytest.raises(exc) as e:
        orbillum.illuminate(SUN, None, TARGET, **args)
    assert words in str(e.value)


def test_facet_brdf_is_the_modified_phong_formula():
    rng = np.random.default_rng(3)
    facet = {"normal": [0.3, -0.2, 0.9], "area_m2": 2.0, "albedo_diffuse": 0.3,
             "albedo_specular": 0.5, "shininess": 40.0}
    s = rng.normal(size=(200, 3))
    o = rng.normal(size=(200, 3))
    got = orbillum.facet_brdf(facet, s, o)
    want = np.array([phong(0.3, 0.5, 40.0, facet["normal"], a, b) for a, b in zip(s, o)])
    assert np.allclose(got, want, rtol=1e-12, atol=1e-15)
    assert (want > 0).sum() > 20


def test_binding_equals_the_planner_on_shaped_rows(tmp_path):
    """The same rows (shapes, attitudes, every term) through build/oi-plan
    --csv and expose(): every printed number identical."""
    if not os.path.exists(PLAN):
        pytest.fail(f"{PLAN} is missing: run `make all` first")
    rng = np.random.default_rng(21)
    n = 24
    qs = unit_quaternions(n, 22)
    d = rng.normal(size=(n, 3))
    obs = TARGET + 30.0 * d / np.linalg.norm(d, axis=1, keepdims=True)
    moon = np.array([-200000.0, 300000.0, 50000.0])
    names = ["plate", "box-wing", "cylinder", "sphere"] * (n // 4)
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow(["sun_x", "sun_y", "sun_z", "moon_x", "moon_y", "moon_z", "target_x", "target_y",
                "target_z", "observer_x", "observer_y", "observer_z", "target_shape", "q_w",
                "q_x", "q_y", "q_z", "camera"])
    for i in range(n):
        w.writerow([repr(float(x)) for x in (*SUN, *moon, *TARGET, *obs[i])] + [names[i]] +
                   [repr(float(x)) for x in qs[i]] + ["telescope-15cm"])
    path = tmp_path / "in.csv"
    path.write_text(out.getvalue())
    run = subprocess.run([PLAN, "--csv", str(path)], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    plan = list(csv.DictReader(io.StringIO(run.stdout)))
    x = orbillum.expose("telescope-15cm", SUN, moon, np.tile(TARGET, (n, 1)), obs,
                        target_shape=names, attitude_q=qs)
    for i, row in enumerate(plan):
        assert row["status"] == x["row_status_name"][i]
        for c in ("e_sun", "e_earth", "e_moon", "flux_obs", "mag_v", "exposure_s", "gain",
                  "snr"):
            assert row[c] == g17(x[c][i]), (i, names[i], c)
        assert row["flags"] == x["flag_names"][i]
