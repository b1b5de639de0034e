# SPDX-License-Identifier: MIT
"""The binding refuses what it cannot represent: every
case here was accepted silently, or answered with a valid-looking value,
before (each test fails on the binding of 2026-12-07, main 2a11fcd):

- a failed row's mag_v was 0 (a bright target): now NaN, with every float
  output of the row (the planner leaves those cells empty);
- integer fields beyond their C type wrapped modulo 2^32 (earth_model
  2**32 + 1 acted as 1; status_name(2**70) was 'OK');
- complex input lost its imaginary part with status OK; boolean arrays were
  read as 0 and 1;
- camera and model errors did not name the field ("ERR_CAMERA (a field out
  of its range: see include/orbillum.h)");
- an attitude quaternion [0, 0, 0, 0] or (1e-300, 0, 0, 0) was the identity
  with status OK (the planner refuses it).
"""
import ctypes
import math

import numpy as np
import pytest

orbillum = pytest.importorskip("orbillum")
L = orbillum.L

SUN, MOON = [1.496e8, 0.0, 0.0], [0.0, 384400.0, 0.0]
OBSERVER = [0.0, 6380.0, 0.0]
TARGET = [0.0, 6880.0, 0.0]
BAD = [np.nan, 0.0, 0.0]  # a row the library refuses (ERR_NONFINITE)


# ---------------------------------------------------------------- failed rows: NaN


def _float_fields(d):
    return [k for k, v in d.items() if isinstance(v, np.ndarray) and v.dtype.kind == "f"]


def test_failed_rows_have_nan_magnitudes_and_floats():
    x = orbillum.expose("telescope-15cm", SUN, MOON, [TARGET, BAD], OBSERVER,
                        target_shape=["box-wing", "box-wing"], attitude_q=[1, 0, 0, 0])
    assert x["status_name"].tolist() == ["OK", "ERR_NONFINITE"]
    assert x["row_status_name"][1] == x["expose_status_name"][1] == "ERR_NONFINITE"
    assert math.isnan(x["mag_v"][1]) and math.isnan(x["detect_margin_mag"][1])
    assert np.isfinite(x["mag_v"][0]) and np.isfinite(x["detect_margin_mag"][0])
    floats = _float_fields(x)
    assert {"e_sun", "flux_obs", "snr", "exposure_s", "sun_fraction", "dir_earth"} <= set(floats)
    for k in floats:
        assert np.isnan(x[k][1]).all(), k
        assert np.isfinite(x[k][0]).all(), k
    # integer outputs of the failed row: 0, as the C library gives
    for k in ("time_index", "gain_index", "flags", "shadow_region"):
        assert x[k][1] == 0, k
    assert x["flag_names"][1] == ""


def test_failed_rows_nan_in_every_call():
    r = orbillum.illuminate(SUN, MOON, [TARGET, BAD], OBSERVER)
    assert r["status"][1] == L.OI_ERR_NONFINITE and math.isnan(r["mag_v"][1])
    # with an outputs mask too (the fields left out are 0 on valid rows only)
    q = orbillum.illuminate(SUN, MOON, [TARGET, BAD], OBSERVER, outputs=0)
    assert q["mag_v"][0] == 0 and math.isnan(q["mag_v"][1])
    s = orbillum.sun_fraction(SUN, [[7000.0, 0, 0], BAD])
    assert s["status"].tolist() == [0, L.OI_ERR_NONFINITE]
    assert s["fraction"][0] == 1 and math.isnan(s["fraction"][1])
    phi, psi, st = orbillum.earthshine([0.5, 0.5], [500.0, -1.0])
    assert st[1] == L.OI_ERR_BELOW_SURFACE and math.isnan(phi[1]) and math.isnan(psi[1])
    assert np.isfinite(phi[0])
    f = orbillum.expose_flux("telescope-15cm", [1e-14, -1.0])
    assert f["expose_status"][1] == L.OI_ERR_INPUT
    assert math.isnan(f["detect_margin_mag"][1]) and math.isnan(f["snr"][1])
    assert np.isfinite(f["snr"][0])
    flux, st = orbillum.flux_from_magnitude([1.0, 99.0])
    assert st[1] == L.OI_ERR_MAGNITUDE and math.isnan(flux[1]) and flux[0] > 0


def test_valid_rows_keep_the_c_library_bits():
    """NaN only where the status is an error: valid rows are the single C
    call's bits (the NaN pass touches nothing else)."""
    sc = orbillum._scenes(SUN, MOON, [TARGET, BAD], OBSERVER, None, None, None, None)
    one = np.zeros(1, dtype=orbillum.ILLUM_DTYPE)
    st = orbillum._lib.oi_illuminate(sc.ctypes.data, None, one.ctypes.data)
    r = orbillum.illuminate(SUN, MOON, [TARGET, BAD], OBSERVER)
    assert st == r["status"][0] == 0
    for k in ("e_sun", "e_earth", "flux_obs", "mag_v", "dir_earth", "range_km"):
        assert np.array_equal(r[k][0], one[k][0]), k


# ---------------------------------------------------------------- integers in range


@pytest.mark.parametrize("field", ["earth_model", "moon_model", "limb_darkening",
                                   "no_atmosphere", "earth_reflection", "earth_shape",
                                   "albedo_model", "band"])
@pytest.mark.parametrize("value", [2**32 + 1, 2**31, -2**31 - 1, 2**70])
def test_model_integer_beyond_c_int_refused(field, value):
    with pytest.raises(ValueError, match=rf"model\['{field}'\]: {value} is outside the C "
                                         r"type's range \[-2147483648, 2147483647\]"):
        orbillum.illuminate(SUN, MOON, TARGET, OBSERVER, model={field: value})


def test_model_integer_in_range_still_the_library_s_word():
    # 2**32 + 1 acted as 1 (lambert): the in-range 1 still is
    a = orbillum.illuminate(SUN, MOON, TARGET, OBSERVER, model={"earth_model": 1})
    b = orbillum.illuminate(SUN, MOON, TARGET, OBSERVER, model={"earth_model": "lambert"})
    assert a["e_earth"][0] == b["e_earth"][0]
    with pytest.raises(ValueError, match=r"model: ERR_MODEL: model\['earth_model'\] = 2 is none "
                                         r"of 0 \('table'\), 1 \('lambert'\)"):
        orbillum.illuminate(SUN, MOON, TARGET, OBSERVER, model={"earth_model": 2})


@pytest.mark.parametrize("value", [2**32 + 1, 2**32 + L.OI_TERM_SUN, -1, 2**64])
def test_terms_beyond_unsigned_refused(value):
    with pytest.raises(ValueError, match=r"terms: -?\d+ is outside the C type's range "
                                         r"\[0, 4294967295\]"):
        orbillum.illuminate(SUN, MOON, TARGET, OBSERVER, terms=value)
    with pytest.raises(ValueError, match="terms"):
        orbillum.illuminate(SUN, MOON, [TARGET, TARGET], OBSERVER, terms=[1, value])
    with pytest.raises(TypeError, match="terms"):
        orbillum.terms_mask(True)


@pytest.mark.parametrize("value", [2**32 + 1, 2**32 + L.OI_SKY_ZODIACAL, -1])
def test_sky_beyond_unsigned_refused(value):
    with pytest.raises(ValueError, match=r"sky: -?\d+ is outside the C type's range"):
        orbillum.expose("star-tracker", SUN, MOON, TARGET, OBSERVER, sky=value)
    with pytest.raises(ValueError, match=r"sky: an integer, got 1.5"):
        orbillum.expose("star-tracker", SUN, MOON, TARGET, OBSERVER, sky=1.5)
    with pytest.raises(ValueError, match=r"sky: unknown word 'zodiac'"):
        orbillum.expose("star-tracker", SUN, MOON, TARGET, OBSERVER, sky="zodiac")


def test_sky_words_are_the_planner_s():
    assert orbillum.sky_mask("Zodiacal + moon+STARLIGHT") == (
        L.OI_SKY_ZODIACAL | L.OI_SKY_MOON | L.OI_SKY_STARLIGHT)
    assert orbillum.sky_mask("all") == L.OI_SKY_ZODIACAL | L.OI_SKY_MOON
    assert orbillum.sky_mask("none") == orbillum.sky_mask("") == 0
    a = orbillum.expose("star-tracker", SUN, MOON, TARGET, OBSERVER, sky="zodiacal+starlight")
    b = orbillum.expose("star-tracker", SUN, MOON, TARGET, OBSERVER,
                        sky=L.OI_SKY_ZODIACAL | L.OI_SKY_STARLIGHT)
    assert a["background_w_m2_sr"][0] == b["background_w_m2_sr"][0]


def test_flags_beyond_unsigned_refused():
    with pytest.raises(ValueError, match=r"flags: .*4294967297 is outside"):
        orbillum.expose_flux("star-tracker", [1e-14, 1e-14], flags=np.array([0, 2**32 + 1]))
    with pytest.raises(TypeError, match="flags: integers"):
        orbillum.expose_flux("star-tracker", [1e-14], flags=1.5)
    with pytest.raises(ValueError, match="flags: -1 is outside"):
        orbillum.flag_names(-1)


def test_status_name_beyond_int_is_unknown_never_ok():
    for v in (2**70, 2**32, 2**32 + L.OI_ERR_NONFINITE % 2**32, -2**31 - 1, 99, -99):
        assert orbillum.status_name(v) == "UNKNOWN", v
    assert orbillum.status_name(np.int32(L.OI_ERR_SHAPE)) == "ERR_SHAPE"
    with pytest.raises(TypeError):
        orbillum.status_name("OK")
    with pytest.raises(ValueError):
        orbillum.status_name(1.5)


# ---------------------------------------------------------------- complex, bool, object


@pytest.mark.parametrize("arg", ["sun", "target", "observer", "moon", "target_albedo",
                                 "earth_albedo", "target_radius_m", "attitude_q", "epoch_jd"])
def test_complex_input_refused(arg):
    kw = dict(sun=SUN, moon=MOON, target=TARGET, observer=OBSERVER)
    v = {"target_albedo": 0.2, "earth_albedo": 0.3, "target_radius_m": 1.0,
         "attitude_q": [1.0, 0, 0, 0], "epoch_jd": 2461000.5}.get(arg, kw.get(arg))
    kw[arg] = np.asarray(v, dtype=complex) + 1e-3j
    with pytest.raises(TypeError, match=rf"{arg}: expected real numbers, got complex"):
        orbillum.illuminate(**kw, target_shape="plate")


def test_complex_scalars_refused_everywhere():
    cases = [
        lambda: orbillum.expose("star-tracker", SUN, MOON, TARGET, OBSERVER, fill=0.5 + 0.1j),
        lambda: orbillum.expose("star-tracker", SUN, MOON, TARGET, OBSERVER,
                                snr_min=np.complex128(5 + 1j)),
        lambda: orbillum.expose("star-tracker", SUN, MOON, TARGET, OBSERVER,
                                sensor_temp_c=20 + 1j),
        lambda: orbillum.expose_flux("star-tracker", 1e-14 + 1e-15j),
        lambda: orbillum.magnitude_v(1e-12 + 1j),
        lambda: orbillum.flux_from_magnitude(5 + 1j),
        lambda: orbillum.lambert_phase(0.5 + 1j),
        lambda: orbillum.earthshine(0.5 + 0.1j, 500.0),
        lambda: orbillum.sun_fraction(SUN, np.array(TARGET) + 1j),
        lambda: orbillum.starlight_radiance(0.1j, 0.0),
        lambda: orbillum.galactic([1.0 + 1j, 0, 0]),
        lambda: orbillum.Shape([{"normal": [0, 0, 1 + 1j], "area_m2": 1.0,
                                 "albedo_diffuse": 0.2}]),
        lambda: orbillum.expose(dict(orbillum.camera("star-tracker"),
                                     times_s=[0.1 + 1j]), SUN, MOON, TARGET, OBSERVER),
    ]
    for i, f in enumerate(cases):
        with pytest.raises(TypeError, match="complex|real number"):
            f()
        assert i >= 0


def test_bool_and_object_arrays_refused():
    with pytest.raises(TypeError, match="target_albedo: expected numbers, got booleans"):
        orbillum.illuminate(SUN, MOON, TARGET, OBSERVER, target_albedo=np.array([True]))
    with pytest.raises(TypeError, match="target: expected numbers, got booleans"):
        orbillum.illuminate(SUN, MOON, np.ones(3, dtype=bool), OBSERVER)
    with pytest.raises(TypeError, match="target: expected real numbers, got booleans or complex"):
        orbillum.illuminate(SUN, MOON, np.array([0, True, 7000.0], dtype=object), OBSERVER)
    with pytest.raises(TypeError, match="target: expected real numbers"):
        orbillum.illuminate(SUN, MOON, np.array([0, 1j, 7000.0], dtype=object), OBSERVER)
    # an object array of real numbers is still numbers
    r = orbillum.illuminate(SUN, MOON, np.array(TARGET, dtype=object), OBSERVER)
    assert r["status_name"][0] == "OK"


# ---------------------------------------------------------------- errors name the field


@pytest.mark.parametrize("field,value,words", [
    ("aperture_m", -1.0, r"camera\['aperture_m'\] = -1.0 is outside \(0, 10\] m"),
    ("focal_length_m", 1e4, r"camera\['focal_length_m'\] = 10000.0 is outside \[0.001, 1000\] m"),
    ("pixel_pitch_m", 0.0, r"camera\['pixel_pitch_m'\] = 0.0 is outside \[1e-07, 0.001\] m"),
    ("transmission", 1.5, r"camera\['transmission'\] = 1.5 is outside \(0, 1\]"),
    ("quantum_efficiency", np.nan, r"camera\['quantum_efficiency'\] = nan is outside \(0, 1\]"),
    ("band_fraction", 0.0, r"camera\['band_fraction'\] = 0.0 is outside \(0, 1\]"),
    ("photon_energy_j", 1e-16, r"camera\['photon_energy_j'\] = 1e-16 is outside"),
    ("full_well_e", 0.5, r"camera\['full_well_e'\] = 0.5 is outside \[1, 1e\+09\] e-"),
    ("dark_current_e_s", -1.0, r"camera\['dark_current_e_s'\] = -1.0 is outside \[0, 1e\+09\]"),
    ("psf_peak_fraction", 2.0, r"camera\['psf_peak_fraction'\] = 2.0 is outside \(0, 1\]"),
    ("fov_rad", 4.0, r"camera\['fov_rad'\] = 4.0 is outside \(0, pi\] rad"),
    ("sun_exclusion_rad", -0.1, r"camera\['sun_exclusion_rad'\] = -0.1 is outside \[0, pi\]"),
    ("max_trail_px", -1.0, r"camera\['max_trail_px'\] = -1.0 is outside \[0, 1e\+06\] px"),
    ("detect_false_alarm", 0.7, r"camera\['detect_false_alarm'\] = 0.7 is outside 0 or "
                                r"\[1e-15, 0.5\)"),
    ("detect_probability", 0.2, r"camera\['detect_probability'\] = 0.2 is outside 0 or "
                                r"\[0.5, 0.999999\]"),
    ("dark_doubling_c", 0.5, r"camera\['dark_doubling_c'\] = 0.5 is outside 0 or \[1, 100\]"),
    ("temp_max_c", 200.0, r"camera\['temp_max_c'\] = 200.0 is outside \[-150, 150\] deg C"),
    ("times_s", [0.5, 0.1], r"camera\['times_s'\]\[1\] = 0.1: the times_s must be in "
                            r"\(0, 10000\] s and strictly ascending"),
    ("gains", [2e3], r"camera\['gains'\]\[0\] = 2000.0: the gains must be in \(0, 1000\]"),
    ("read_noise_e", [-1.0], r"camera\['read_noise_e'\]\[0\] = -1.0 is outside \[0, 1e6\] e-"),
])
def test_camera_error_names_the_field_and_range(field, value, words):
    d = orbillum.camera("telescope-15cm")
    d[field] = value
    if field in ("times_s", "gains", "read_noise_e"):
        d.pop("n_times" if field == "times_s" else "n_gains")
        if field != "times_s":
            d["gains"], d["read_noise_e"] = ((value, [1.0]) if field == "gains"
                                             else ([1.0], value))
    with pytest.raises(ValueError, match="camera or model: ERR_CAMERA: " + words):
        orbillum.expose(d, SUN, MOON, TARGET, OBSERVER)
    with pytest.raises(ValueError, match="camera: ERR_CAMERA: " + words):
        orbillum.expose_flux(d, 1e-14)


def test_camera_ranges_agree_with_the_library():
    """The binding's names are only names: on a camera the library accepts
    the binding finds no bad field, on each refused one it finds one (the
    library's status is the authority). Every field nudged to just inside and
    just outside its range."""
    from orbillum.exposure import _CAMERA_RANGES, _camera_from_dict, _camera_problem
    base = orbillum.camera("telescope-15cm")
    tried = 0
    for k, lo, hi, lo_open, hi_open, _unit in _CAMERA_RANGES:
        for v in (lo, hi, lo * (1 - 1e-12) - 1e-300, hi * (1 + 1e-12) + 1e-300,
                  (lo + hi) / 2, np.nan):
            c = _camera_from_dict(dict(base, **{k: v}))
            inp = np.zeros(1, dtype=np.dtype(L.oi_expose_in))
            inp["flux_w_m2"] = 1e-14
            ex = np.zeros(1, dtype=orbillum.EXPOSURE_DTYPE)
            st = np.zeros(1, dtype=np.intc)
            bst = orbillum._lib.oi_expose_batch(1, ctypes.addressof(c), inp.ctypes.data, None,
                                                ex.ctypes.data, st.ctypes.data)
            assert (bst == L.OI_ERR_CAMERA) == (_camera_problem(c) is not None), (k, v)
            tried += 1
    assert tried == 6 * len(_CAMERA_RANGES)


def test_model_ranges_agree_with_the_library():
    """As for the camera: the binding's model ranges (orbillum._models, from the
    header's OI_MODEL_* constants) find a bad field exactly where the library
    refuses the model (ERR_MODEL, or ERR_RADIUS for a radius), every real field
    nudged to just inside and just outside its range, and every option to one
    past its allowed values."""
    from orbillum._models import _MODEL_OPTIONS, _MODEL_REALS, _model_problem
    sun = np.array([1.496e8, 0.0, 0.0])
    point = np.array([0.0, 7000.0, 0.0])
    out = L.oi_shadow()
    tried = 0

    def agree(m, what):
        st = orbillum._lib.oi_sun_fraction(sun.ctypes.data, point.ctypes.data,
                                           ctypes.addressof(m), ctypes.addressof(out))
        refused = st in (L.OI_ERR_MODEL, L.OI_ERR_RADIUS)
        assert refused == (_model_problem(m) is not None), (what, st)

    for k, lo, hi, _unit in _MODEL_REALS:
        for v in (lo, hi, lo * (1 - 1e-12) - 1e-300, hi * (1 + 1e-12) + 1e-300,
                  (lo + hi) / 2, np.nan, -1.0):
            m = L.oi_model()
            setattr(m, k, v)
            agree(m, (k, v))
            tried += 1
    for k, allowed in _MODEL_OPTIONS:
        m = L.oi_model()
        setattr(m, k, max(allowed) + 1)
        agree(m, (k, max(allowed) + 1))
        tried += 1
    assert tried == 7 * len(_MODEL_REALS) + len(_MODEL_OPTIONS)


@pytest.mark.parametrize("model,words", [
    ({"tsi_w_m2": -1.0}, r"ERR_MODEL: model\['tsi_w_m2'\] = -1.0 is outside its range: 0 \(the "
                         r"default\) or \[1e-06, 1e\+06\] W/m\^2"),
    ({"au_km": 10.0}, r"ERR_MODEL: model\['au_km'\] = 10.0 is outside"),
    ({"earth_radius_km": 1e9}, r"ERR_RADIUS: model\['earth_radius_km'\] = 1000000000.0 is "
                               r"outside its range: 0 \(the default\) or \[0.001, 1e\+08\] km"),
    ({"moon_albedo": 1.5}, r"ERR_MODEL: model\['moon_albedo'\] = 1.5 is outside"),
    ({"earth_reflection": 3}, r"ERR_MODEL: model\['earth_reflection'\] = 3 is none of 0, 1, 2"),
    ({"band": -1}, r"ERR_MODEL: model\['band'\] = -1 is none of 0 \('V'\), 1 \('total'\)"),
    ({"albedo_model": 3}, r"ERR_MODEL: model\['albedo_model'\] = 3 is none of 0 \('uniform'\)"),
    ({"albedo_model": "map"}, r"ERR_MODEL: model\['albedo_model'\] = 'map' needs "
                              r"model\['albedo_map'\]"),
])
def test_model_error_names_the_field_and_range(model, words):
    with pytest.raises(ValueError, match="model: " + words):
        orbillum.illuminate(SUN, MOON, TARGET, OBSERVER, model=model)
    if "albedo" not in next(iter(model)):  # read by oi_illuminate only
        with pytest.raises(ValueError, match="model: " + words):
            orbillum.sun_fraction(SUN, TARGET, model=model)
        with pytest.raises(ValueError, match="model: " + words):
            orbillum.magnitude_v(1e-12, model=model)


# ---------------------------------------------------------------- attitude quaternions


@pytest.mark.parametrize("q", [[0, 0, 0, 0], [1e-300, 0, 0, 0], [0, 0, 1e-170, 0],
                               [1e200, 0, 0, 0], [0.5, 0, 0, 0]])
def test_zero_or_underflowing_quaternion_is_err_shape(q):
    for call in (orbillum.illuminate, lambda *a, **k: orbillum.expose("star-tracker", *a, **k)):
        r = call(SUN, MOON, [TARGET, TARGET], OBSERVER, target_shape="box-wing",
                 attitude_q=[q, [1, 0, 0, 0]])
        assert r["status_name"].tolist() == ["ERR_SHAPE", "OK"]
        assert math.isnan(r["flux_obs"][0]) and r["flux_obs"][1] > 0
        if "row_status_name" in r:
            assert r["row_status_name"].tolist() == ["ERR_SHAPE", "OK"]
            assert math.isnan(r["snr"][0])
    # a sphere's attitude is not read (the planner's rule too)
    s = orbillum.illuminate(SUN, MOON, TARGET, OBSERVER, attitude_q=q)
    assert s["status_name"].tolist() == ["OK"]
    # no attitude given: the identity, as the library's default
    a = orbillum.illuminate(SUN, MOON, TARGET, OBSERVER, target_shape="box-wing")
    b = orbillum.illuminate(SUN, MOON, TARGET, OBSERVER, target_shape="box-wing",
                            attitude_q=[1, 0, 0, 0])
    assert a["status_name"][0] == "OK" and a["flux_obs"][0] == b["flux_obs"][0]
