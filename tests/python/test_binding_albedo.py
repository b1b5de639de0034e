# SPDX-License-Identifier: MIT
"""The binding's albedo models (orbillum.illuminate model albedo_model,
albedo_map, epoch_jd, earth_rotation_rad) against the C library's own
single calls through the ctypes mirror, and its argument checks."""
import math

import numpy as np
import pytest

import _oi_ctypes as T

orbillum = pytest.importorskip("orbillum", reason="binding not installed: make binding")
M = T.M


def c_call(sun, target, model, epoch=0.0, rotation=0.0, grid=None):
    return T.illuminate_albedo(sun, target, model, epoch, rotation, grid)


SUN = (1.496e8, 0.0, 2.0e7)
TARGETS = np.array([[6878.0, 0.0, 0.0], [0.0, 7000.0, 900.0], [-3000.0, 42000.0, 1000.0]])


def test_knocke_rows_match_the_single_calls():
    epochs = np.array([2451545.0, 2451700.0, 2460000.0])
    r = orbillum.illuminate(SUN, None, TARGETS, model={"albedo_model": "knocke"},
                            epoch_jd=epochs)
    for i in range(3):
        st, out = c_call(SUN, TARGETS[i], M.OI_ALBEDO_KNOCKE, epochs[i])
        assert r["status"][i] == st == 0
        assert r["e_earth"][i] == out.e_earth
        assert r["earth_albedo_eff"][i] == out.earth_albedo_eff


def test_map_rows_match_the_single_calls():
    grid = np.linspace(0.1, 0.8, 6 * 12).reshape(6, 12)
    r = orbillum.illuminate(SUN, None, TARGETS, model={"albedo_model": "map", "albedo_map": grid},
                            earth_rotation_rad=1.3)
    for i in range(3):
        st, out = c_call(SUN, TARGETS[i], M.OI_ALBEDO_MAP, rotation=1.3, grid=grid)
        assert r["status"][i] == st == 0
        assert r["e_earth"][i] == out.e_earth
    assert not np.allclose(r["earth_albedo_eff"], r["earth_albedo_eff"][0])


def test_bad_arguments():
    with pytest.raises(ValueError, match="2-D"):
        orbillum.illuminate(SUN, None, TARGETS, model={"albedo_model": "map",
                                                       "albedo_map": [0.1, 0.2]})
    with pytest.raises(ValueError, match="shape of albedo_map"):
        orbillum.illuminate(SUN, None, TARGETS, model={"albedo_map_n_lat": 3})
    with pytest.raises(ValueError, match="unknown word"):
        orbillum.illuminate(SUN, None, TARGETS, model={"albedo_model": "ceres"})
    # a map value out of range: the rows' status, not an exception
    r = orbillum.illuminate(SUN, None, TARGETS[:1],
                            model={"albedo_model": "map", "albedo_map": [[1.5, 0.2], [0.2, 0.2]]})
    assert r["status_name"][0] == "ERR_ALBEDO" and math.isnan(r["e_earth"][0])
    r = orbillum.illuminate(SUN, None, TARGETS[:1], model={"albedo_model": "knocke"},
                            epoch_jd=math.nan)
    assert r["status_name"][0] == "ERR_NONFINITE"
