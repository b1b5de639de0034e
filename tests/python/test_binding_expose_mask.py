# SPDX-License-Identifier: MIT
"""orbillum.expose(outputs=...): the OI_EXPOSE_* mask of
oi_expose_scene_batch_outputs through the binding. Each field asked for is
the full call's, bit for bit; each left out is 0; a bad mask is refused
naming the argument."""
import numpy as np
import pytest

import orbillum
L = orbillum.L

# include/orbillum.h (the binding's constants, python/orbillum/_lib.py, predate it)
OI_FLAG_BACKGROUND_SATURATED = 4096
RE = 6378.137


def _rows(n=400, seed=3):
    rng = np.random.default_rng(seed)

    def dirs(k):
        v = rng.normal(size=(k, 3))
        return v / np.linalg.norm(v, axis=1)[:, None]

    sun = dirs(n) * 1.496e8
    tgt = dirs(n) * (RE + 400 + 36000 * rng.random(n))[:, None]
    obs = tgt + dirs(n) * 800.0
    moon = dirs(n) * 384400.0
    vel = dirs(n) * 7.5
    return sun, moon, tgt, obs, vel


SETTING = ("exposure_s", "gain", "time_index", "gain_index", "signal_e", "background_e",
           "peak_e", "saturation_e", "fill", "snr", "trail_px", "trail_factor")


@pytest.mark.parametrize("mask", [0, L.OI_EXPOSE_SETTING, L.OI_EXPOSE_FAINT, L.OI_EXPOSE_DETECT,
                                  L.OI_EXPOSE_SUN_ANGLE | L.OI_EXPOSE_RATE,
                                  L.OI_EXPOSE_BACKGROUND, L.OI_EXPOSE_ALL])
def test_mask_fields(mask):
    sun, moon, tgt, obs, vel = _rows()
    kw = dict(terms="all", target_velocity=vel, sky=L.OI_SKY_ZODIACAL | L.OI_SKY_STARLIGHT)
    full = orbillum.expose("star-tracker", sun, moon, tgt, obs, **kw)
    part = orbillum.expose("star-tracker", sun, moon, tgt, obs, outputs=mask, **kw)
    assert np.array_equal(full["expose_status"], part["expose_status"])
    asked = {f: bool(mask & L.OI_EXPOSE_SETTING) for f in SETTING}
    asked.update(signal_min_e=bool(mask & L.OI_EXPOSE_DETECT),
                 detect_margin_mag=bool(mask & L.OI_EXPOSE_DETECT),
                 sun_angle_rad=bool(mask & L.OI_EXPOSE_SUN_ANGLE),
                 background_w_m2_sr=bool(mask & L.OI_EXPOSE_BACKGROUND),
                 rate_rad_s=bool(mask & L.OI_EXPOSE_RATE))
    for f, on in asked.items():
        want = np.ascontiguousarray(full[f] if on else np.zeros_like(full[f]))
        got = np.ascontiguousarray(part[f])
        assert np.array_equal(got.view(np.uint8), want.view(np.uint8)), f
    drop = 0
    if not mask & L.OI_EXPOSE_SETTING:  # the setting's two well flags
        drop |= L.OI_FLAG_SATURATED | OI_FLAG_BACKGROUND_SATURATED
    if not mask & L.OI_EXPOSE_FAINT:
        drop |= L.OI_FLAG_TOO_FAINT
    if not mask & (L.OI_EXPOSE_SETTING | L.OI_EXPOSE_FAINT):
        drop |= L.OI_FLAG_TRAILED
    assert np.array_equal(part["flags"], full["flags"] & ~np.uint32(drop))
    if mask == L.OI_EXPOSE_ALL:
        assert part["flags"].any()


def test_bad_mask():
    sun, moon, tgt, obs, _ = _rows(4)
    with pytest.raises(ValueError, match="outputs"):
        orbillum.expose("star-tracker", sun, moon, tgt, obs, outputs=1 << 6)
    with pytest.raises(TypeError, match="outputs"):
        orbillum.expose("star-tracker", sun, moon, tgt, obs, outputs="all")
