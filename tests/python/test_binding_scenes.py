# SPDX-License-Identifier: MIT
"""The binding's scene records (filled from a template row, then the per-row
columns) equal, field by field and bit for bit, oi_scene structures built one
row at a time through ctypes from oi_scene_defaults."""
import ctypes

import numpy as np
import pytest

orbillum = pytest.importorskip("orbillum", reason="binding not installed: make binding")
L = orbillum.L
lib = orbillum._lib


def _reference(i, S, M, T, O, kw):
    d = L.oi_scene()
    lib.oi_scene_defaults(ctypes.addressof(d))
    d.sun_km[:] = S[i]
    d.target_km[:] = T[i]
    d.moon_km[:] = M[i]
    d.observer_km[:] = O[i]
    d.has_observer = 1
    d.has_moon = 1
    d.terms = orbillum.terms_mask("all")
    for name in ("earth_albedo", "target_albedo", "epoch_jd", "earth_rotation_rad"):
        if name in kw:
            setattr(d, name, float(np.broadcast_to(kw[name], (len(S),))[i]))
    if "target_velocity" in kw:
        d.target_vel_km_s[:] = np.broadcast_to(kw["target_velocity"], (len(S), 3))[i]
    if "observer_velocity" in kw:
        d.observer_vel_km_s[:] = np.broadcast_to(kw["observer_velocity"], (len(S), 3))[i]
    if "attitude_q" in kw:
        d.attitude_q[:] = np.broadcast_to(kw["attitude_q"], (len(S), 4))[i]
    return d


@pytest.mark.parametrize("case", range(4))
def test_scene_records_equal_ctypes_structs(case):
    n = 37
    rng = np.random.default_rng(case)
    S, M, T, O = (rng.normal(0, s, (n, 3)) for s in (1.5e8, 4e5, 7e3, 7e3))
    kw = [{},
          {"earth_albedo": rng.random(n), "target_albedo": 0.5, "epoch_jd": 2460000.5,
           "earth_rotation_rad": rng.random(n)},
          {"target_velocity": rng.normal(0, 7, (n, 3)), "observer_velocity": [1.0, 2.0, 3.0],
           "attitude_q": rng.normal(0, 1, (n, 4))},
          {"attitude_q": [0.5, 0.5, 0.5, 0.5], "target_albedo": rng.random(n)}][case]
    sc = orbillum._scenes(S, M, T, O, "all", kw.get("earth_albedo"), kw.get("target_albedo"),
                          None, kw.get("target_velocity"), kw.get("observer_velocity"),
                          attitude_q=kw.get("attitude_q"), epoch_jd=kw.get("epoch_jd"),
                          earth_rotation_rad=kw.get("earth_rotation_rad"))
    assert sc.shape == (n,)
    for i in range(n):
        ref = _reference(i, S, M, T, O, kw)
        for name, _ in L.oi_scene._fields_:
            got = np.asarray(sc[i][name])
            want = getattr(ref, name)
            want = np.asarray(want[:] if hasattr(want, "_length_") else
                              (0 if want is None else want), dtype=got.dtype)
            assert got.tobytes() == want.tobytes(), (case, i, name)


def test_scene_records_zero_rows():
    e = np.empty((0, 3))
    assert orbillum._scenes(e, e, e, e, "all", None, None, None).shape == (0,)
