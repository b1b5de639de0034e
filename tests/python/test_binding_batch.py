# SPDX-License-Identifier: MIT
"""The binding on the batch interface: its results equal the single C calls
(made here row by row through the same loaded library) bit for bit; errors are ValueError/TypeError naming the argument; a camera dict from
camera() goes back in and gives the built-in camera's numbers; every OI_*
constant of the header is exported; expose without observer is refused."""
import ctypes

import numpy as np
import pytest

orbillum = pytest.importorskip("orbillum", reason="binding not installed: make binding")
L = orbillum.L
lib = orbillum._lib

AU = 149597870.7


def _rows(n=400, seed=3):
    rng = np.random.default_rng(seed)
    s_hat = rng.normal(size=(n, 3))
    s_hat /= np.linalg.norm(s_hat, axis=1)[:, None]
    sun = s_hat * AU
    # behind the Earth, across the shadow's edges, and anywhere
    perp = np.cross(s_hat, rng.normal(size=(n, 3)))
    perp /= np.linalg.norm(perp, axis=1)[:, None]
    zb = rng.uniform(1e3, 5e4, n)
    rho = 6378.137 + rng.uniform(-400, 400, n)
    tgt = -zb[:, None] * s_hat + rho[:, None] * perp
    anywhere = rng.normal(size=(n, 3)) * 2e4
    tgt[::3] = anywhere[::3]
    tgt[5] = [np.nan, 0, 0]  # hostile rows
    tgt[7] = [100.0, 0, 0]
    return sun, tgt


def _c_bits(v, status):
    """The binding's column as the C library gives it: a failed row's NaN
    (the binding's value for no value, checked here) is the library's 0."""
    v = np.array(v, copy=True)
    bad = np.asarray(status) < 0
    if v.dtype.kind == "f":
        assert np.isnan(v[bad]).all()
        v[bad] = 0
    return v


def test_sun_fraction_equals_single_calls_every_mask():
    sun, tgt = _rows()
    one = np.zeros(len(sun), dtype=np.dtype(L.oi_shadow))
    st1 = np.zeros(len(sun), dtype=np.intc)
    for i in range(len(sun)):
        s = np.ascontiguousarray(sun[i])
        p = np.ascontiguousarray(tgt[i])
        st1[i] = lib.oi_sun_fraction(s.ctypes.data, p.ctypes.data, None,
                                     one.ctypes.data + i * one.itemsize)
    assert (one["region"] == L.OI_SHADOW_PENUMBRA).sum() > 20, "the edges were reached"
    full = orbillum.sun_fraction(sun, tgt)
    assert np.array_equal(full["status"], st1)
    for k in one.dtype.names:
        assert np.array_equal(_c_bits(full[k], st1), one[k]), k
    for mask in range(L.OI_BATCH_ALL + 1):
        r = orbillum.sun_fraction(sun, tgt, outputs=mask)
        st = r["status"]
        assert np.array_equal(_c_bits(r["fraction"], st), one["fraction"]), mask
        assert np.array_equal(r["region"], one["region"]), mask
        if mask & L.OI_BATCH_FRACTION_LD:
            assert np.array_equal(_c_bits(r["fraction_ld"], st), one["fraction_ld"]), mask
        else:
            assert not _c_bits(r["fraction_ld"], st).any()
        if not mask & L.OI_BATCH_GEOMETRY:
            assert not _c_bits(r["separation_rad"], st).any()
    assert full["status"][5] == orbillum.OI_ERR_NONFINITE
    assert full["status"][7] == orbillum.OI_ERR_BELOW_SURFACE


def test_illuminate_and_earthshine_equal_single_calls():
    sun, tgt = _rows(200, 11)
    moon = np.tile([3.6e5, 1.2e5, 2.0e4], (len(sun), 1))
    obs = tgt + np.array([120.0, -60.0, 35.0])
    r = orbillum.illuminate(sun, moon, tgt, obs, terms="all")
    sc = orbillum._scenes(sun, moon, tgt, obs, "all", None, None, None)
    one = np.zeros(len(sun), dtype=orbillum.ILLUM_DTYPE)
    for i in range(len(sun)):
        st = lib.oi_illuminate(sc.ctypes.data + i * sc.itemsize, None,
                               one.ctypes.data + i * one.itemsize)
        assert st == r["status"][i]
    for k in ("e_sun", "e_earth", "e_moon", "flux_obs", "mag_v", "dir_earth", "range_km"):
        assert np.array_equal(_c_bits(r[k], r["status"]), one[k]), k
    ok = r["status"] >= 0
    phi, psi, st = orbillum.earthshine(r["earth_theta"][ok], r["earth_h_km"][ok])
    a, b = ctypes.c_double(), ctypes.c_double()
    for j, (th, h) in enumerate(zip(r["earth_theta"][ok], r["earth_h_km"][ok])):
        s1 = lib.oi_earthshine(float(th), float(h), None, ctypes.byref(a), ctypes.byref(b))
        assert s1 == st[j] and a.value == phi[j] and b.value == psi[j]
    # broadcasting keeps the shape
    phi2, _, _ = orbillum.earthshine(np.zeros((2, 3)), 500.0)
    assert phi2.shape == (2, 3)


def test_illuminate_outputs_mask_changes_no_requested_output():
    """illuminate(outputs=mask): every field the mask keeps is the full call's
    bits (single C calls row by row); the others are 0. Without
    OI_BATCH_OBSERVER the observer's fields are those of the scene without
    observer (0)."""
    sun, tgt = _rows(300, 21)
    moon = np.tile([3.6e5, 1.2e5, 2.0e4], (len(sun), 1))
    obs = tgt + np.array([120.0, -60.0, 35.0])
    full = orbillum.illuminate(sun, moon, tgt, obs, terms="all")
    geometry = ("shadow_sun_radius_rad", "shadow_earth_radius_rad", "shadow_separation_rad",
                "shadow_sun_distance_km")
    observer = ("phase_sun", "phase_earth", "phase_moon", "phase_sky", "flux_sun", "flux_earth",
                "flux_moon", "flux_sky", "flux_obs", "flux_specular", "mag_v", "range_km")
    directions = ("dir_sun", "dir_earth", "dir_moon", "dir_sky")
    for mask in range(L.OI_BATCH_SCENE_ALL + 1):
        r = orbillum.illuminate(sun, moon, tgt, obs, terms="all", outputs=mask)
        assert np.array_equal(r["status"], full["status"]), mask
        for k, v in full.items():
            if k in ("status_name",) or not isinstance(v, np.ndarray):
                continue
            off = ((k in ("shadow_fraction_ld", "sun_fraction_ld")
                    and not mask & L.OI_BATCH_FRACTION_LD)
                   or (k in geometry and not mask & L.OI_BATCH_GEOMETRY)
                   or (k in directions and not mask & L.OI_BATCH_DIRECTIONS)
                   or (k in observer and not mask & L.OI_BATCH_OBSERVER))
            if off:
                assert np.all(_c_bits(r[k], r["status"]) == 0), (mask, k)
            else:
                a, b = np.ascontiguousarray(r[k]), np.ascontiguousarray(v)
                assert a.tobytes() == b.tobytes(), (mask, k)
    with pytest.raises(ValueError, match="outputs"):
        orbillum.illuminate(sun, moon, tgt, obs, outputs=L.OI_BATCH_SCENE_ALL + 1)
    with pytest.raises(TypeError, match="outputs"):
        orbillum.illuminate(sun, moon, tgt, obs, outputs=1.5)


def test_errors_name_the_argument():
    sun, tgt = np.array([AU, 0, 0]), np.array([7000.0, 0, 0])
    with pytest.raises(ValueError, match=r"model\['earth_model'\].*unknown word 'foo'"):
        orbillum.illuminate(sun, None, tgt, model={"earth_model": "foo"})
    with pytest.raises(ValueError, match=r"model\['tsi_w_m2'\].*string"):
        orbillum.illuminate(sun, None, tgt, model={"tsi_w_m2": "1361"})
    with pytest.raises(TypeError, match=r"model\['au_km'\]"):
        orbillum.illuminate(sun, None, tgt, model={"au_km": [1.0]})
    with pytest.raises(TypeError, match="model:"):
        orbillum.illuminate(sun, None, tgt, model=[("tsi_w_m2", 1.0)])
    with pytest.raises(ValueError, match="model: ERR_MODEL"):
        orbillum.illuminate(sun, None, tgt, model={"tsi_w_m2": -1.0})
    with pytest.raises(TypeError, match="target:"):
        orbillum.illuminate(sun, None, ["a", "b", "c"])
    with pytest.raises(TypeError, match="target_albedo"):
        orbillum.illuminate(sun, None, tgt, target_albedo="bright")
    with pytest.raises(ValueError, match="outputs"):
        orbillum.sun_fraction(sun, tgt, outputs=64)
    with pytest.raises(TypeError, match="outputs"):
        orbillum.sun_fraction(sun, tgt, outputs="all")
    with pytest.raises(TypeError, match="theta"):
        orbillum.earthshine("x", 1.0)


def test_expose_without_observer_is_refused():
    sun, tgt = np.array([AU, 0, 0]), np.array([7000.0, 0, 0])
    with pytest.raises(ValueError, match="observer: expose needs the observer"):
        orbillum.expose("star-tracker", sun, None, tgt, None)


def test_camera_dict_round_trip():
    sun = np.array([AU, 0, 0])
    tgt = np.array([[7000.0, 100.0, 0], [0, 42164.0, 0], [-7000.0, 0, 10.0]])
    obs = tgt + np.array([300.0, 200.0, 100.0])
    for name in orbillum.cameras():
        d = orbillum.camera(name)
        a = orbillum.expose(d, sun, None, tgt, obs)
        b = orbillum.expose(name, sun, None, tgt, obs)
        for k in ("exposure_s", "gain", "snr", "fill", "flags", "expose_status"):
            assert np.array_equal(a[k], b[k]), (name, k)
        f = orbillum.expose_flux(d, [1e-14, 1e-10])
        g = orbillum.expose_flux(name, [1e-14, 1e-10])
        assert np.array_equal(f["exposure_s"], g["exposure_s"])
    d = orbillum.camera("star-tracker")
    custom = dict(d, aperture_m=d["aperture_m"] * 2, name="mine")
    c = orbillum.expose(custom, sun, None, tgt, obs)
    assert not np.array_equal(c["signal_e"], orbillum.expose(d, sun, None, tgt, obs)["signal_e"])
    with pytest.raises(ValueError, match="unknown field"):
        orbillum.expose(dict(d, lens=1), sun, None, tgt, obs)
    with pytest.raises(ValueError, match="'aperture_m' missing"):
        orbillum.expose({k: v for k, v in d.items() if k != "aperture_m"}, sun, None, tgt, obs)
    with pytest.raises(TypeError, match=r"camera\['fov_rad'\]"):
        orbillum.expose(dict(d, fov_rad="wide"), sun, None, tgt, obs)
    with pytest.raises(ValueError, match="camera or model: ERR_CAMERA"):
        orbillum.expose(dict(d, aperture_m=-1.0), sun, None, tgt, obs)
    with pytest.raises(ValueError, match="n_times"):
        orbillum.expose(dict(d, n_times=d["n_times"] + 1), sun, None, tgt, obs)


def test_every_constant_is_exported():
    names = [n for n in vars(L) if n.startswith("OI_")]
    assert "OI_BATCH_ALL" in names and "OI_FLAG_RESOLVED" in names and "OI_MAG_MIN" in names
    for n in names:
        assert n in orbillum.__all__ and getattr(orbillum, n) == getattr(L, n), n
