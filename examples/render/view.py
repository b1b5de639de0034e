# SPDX-License-Identifier: MIT
"""What the observer's camera sees: a rendered image of the target at one instant.

    python -m examples.render.view INPUT.csv [--time ISO | --row N] -o view.png

The target is a Lambertian sphere (radius and albedo from the row), or with
--obj an OBJ facet model (examples/render/facets.py). For each sub-pixel the
ray from the observer is intersected with the surface. On the sphere the
radiance is

    L = (albedo / pi) * sum_s E_s max(0, n . d_s)

over the sources s: the Sun (E = e_sun, which already carries the visible
fraction of the disc and the atmosphere's sun_fraction_atm, from dir_sun), the
Earth (E = e_earth from the table's mean incidence direction dir_earth: the
Earth is treated as a collimated source from that direction) and the Moon
(e_moon, dir_moon). Summed over the image, sum L dOmega equals the runtime's
flux_obs to the pixelisation (checked by the tests; the runtime's sphere takes
the Earth's angular distribution, so the Earth part differs by that).

On an OBJ model the light is the runtime's facet model (oi_illuminate with a
shape, through the binding), not a copy of it: each triangle is one facet
(diffuse albedo from the row's target_albedo, the specular lobe from --specular
and --shininess), and the runtime's flux per source of that facet alone, F_k,
gives its radiance L_k = F_k d^2 / (A_k cos e_k) (d the range, A_k its area,
e_k the angle of the observer from its normal): the facet's BRDF with the Sun,
the Moon and the Earth's angular distribution as the runtime lights it. The
exposure is the runtime's for the whole model (its triangles merged by plane
into one oi_shape).

Camera: the image scale is the pixel pitch over the focal length; electrons =
L dOmega * aperture area * transmission * band fraction * QE / photon energy *
exposure, at the exposure and gain the runtime suggests (oi_expose_scene). The
PSF is a Gaussian whose centred pixel holds the camera's psf_peak_fraction.
Background + dark electrons per pixel are the runtime's background_e. Noise:
Poisson photon noise and Gaussian read noise (the camera's, at the chosen gain);
the frame saturates at full_well / gain. The HDR panel tone-maps the noiseless
radiance logarithmically over HDR_DECADES decades below its maximum, so that
sunlit, earthlit and moonlit parts (up to ~1e6 apart) all show.

A target fewer than DISC_PX pixels across is drawn as its PSF blob: a crop of
the detector, upsampled with nearest-neighbour pixels; the figure says so.
"Resolved" has one meaning, the library's: OI_FLAG_RESOLVED (oi_expose_scene
Note 5: the brightest pixel limited by the target's surface brightness), shown
among the flags; how the figure draws the target is a drawing choice and is
named as one (drawn_as_disc).
"""
from __future__ import annotations

import argparse
import math
import sys

import numpy as np

from .common import read_csv, scene_inputs

#: a target fewer pixels across than this is drawn as a PSF blob (a drawing
#: choice; "resolved" is the library's OI_FLAG_RESOLVED)
DISC_PX = 4.0
#: decades of radiance shown by the HDR (logarithmic) tone map
HDR_DECADES = 8.0
#: sub-pixels across the target's disc at least (anti-aliasing of the limb)
MIN_SUBPIX_ACROSS = 48


def psf_sigma_px(peak_fraction: float) -> float:
    """Sigma (pixels) of a Gaussian PSF centred on a pixel that holds peak_fraction."""
    if not 0.0 < peak_fraction < 1.0:
        return 0.0
    lo, hi = 1e-3, 50.0
    for _ in range(80):  # fraction erf(1/(2 sqrt2 s))^2 decreases with s
        mid = 0.5 * (lo + hi)
        if math.erf(1.0 / (2.0 * math.sqrt(2.0) * mid)) ** 2 > peak_fraction:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def _basis(forward, observer):
    f = forward / np.linalg.norm(forward)
    up0 = observer / np.linalg.norm(observer)  # local zenith at the observer: Earth below
    if abs(f @ up0) > 0.99:
        up0 = np.array([0.0, 0.0, 1.0]) if abs(f[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    r = np.cross(f, up0)
    r /= np.linalg.norm(r)
    u = np.cross(r, f)
    return f, r, u


def radiance_image(sc: dict, res: dict, cam: dict, crop_px: int | None = None,
                   model=None):
    """Noiseless radiance (W/m^2/sr) on a sub-pixel grid, per source.

    Returns (L_sources dict name -> (M, M) array, meta dict). sc holds one row's
    positions (km) and target radius/albedo; res one row of orbillum.expose().
    model: None (the sphere of sc's radius) or (vertices in m, triangles) of an
    OBJ facet model, oriented by facets.nadir_sun_attitude (needs sc["sun"]),
    lit by the runtime (facet_fluxes; sc's moon, terms, earth_albedo,
    albedo_specular and shininess are read when given).
    """
    tgt, obs = sc["target"], sc["observer"]
    if model is None:
        a_km = sc["target_radius_m"] / 1000.0
    else:
        verts_m, tris = model
        a_km = float(np.max(np.linalg.norm(verts_m, axis=1))) / 1000.0
    los = tgt - obs
    d = np.linalg.norm(los)
    f, r, u = _basis(los, obs)
    ifov = cam["pixel_pitch_m"] / cam["focal_length_m"]
    rho = math.asin(min(a_km / d, 1.0))
    diam_px = 2 * rho / ifov
    if crop_px is None:
        crop_px = int(min(max(24, math.ceil(2.6 * diam_px) + 8), 400))
    drawn_as_disc = diam_px >= DISC_PX
    if drawn_as_disc:
        # sub-pixel grid over the whole crop
        os_ = int(max(1, math.ceil(MIN_SUBPIX_ACROSS / diam_px)))
        m = crop_px * os_
        sub = ifov / os_
    else:
        # drawn as a PSF blob: a close-up grid over the disc only; the detector sees a PSF
        m = int(math.ceil(1.25 * MIN_SUBPIX_ACROSS))
        sub = 2 * rho / MIN_SUBPIX_ACROSS
        os_ = ifov / sub
    # angular offsets of sub-pixel centres (rad), image row 0 at the top
    c = (np.arange(m) - (m - 1) / 2.0) * sub
    ax, ay = np.meshgrid(c, -c)
    # rays from the observer; intersect with the sphere |p - tgt| = a
    dirs = (f[None, None, :] + np.tan(ax)[..., None] * r + np.tan(ay)[..., None] * u)
    dirs /= np.linalg.norm(dirs, axis=-1, keepdims=True)
    oc = obs - tgt
    if model is None:
        b = dirs @ oc
        disc = b * b - (oc @ oc - a_km * a_km)
        hit = disc >= 0
        tnear = -b - np.sqrt(np.where(hit, disc, 0.0))
        p = obs + tnear[..., None] * dirs
        n = (p - tgt) / a_km
        alb = sc["target_albedo"]
        L = {}
        for s in ("sun", "earth", "moon"):
            e = float(res[f"e_{s}"])
            dv = np.asarray(res[f"dir_{s}"], dtype=float)
            if e > 0 and np.linalg.norm(dv) > 0:
                L[s] = np.where(hit, alb / math.pi * e * np.clip(n @ dv, 0.0, None), 0.0)
            else:
                L[s] = np.zeros((m, m))
    else:
        from .facets import cast
        fl = facet_fluxes(sc, model)
        tri_xyz = (verts_m @ fl["rot"].T / 1000.0)[tris]  # (F, 3, 3) km, target-centred
        fn = fl["normals"]
        # a one-sided triangle turned away from the observer sends nothing: not cast, so
        # that a panel's two back-to-back sheets show the one that faces the camera
        to_obs = -los / d
        cos_e = fn @ to_obs
        cast_ok = (cos_e > 0) | fl["two_sided"]
        idx = np.flatnonzero(cast_ok)
        hit, face, _t = cast(oc, dirs, tri_xyz[idx])
        face = idx[np.where(hit, face, 0)]
        ce = np.abs(cos_e)
        d_m = d * 1e3
        L = {}
        for s in ("sun", "earth", "moon"):
            lk = np.where(ce > 1e-12, fl[s] * d_m * d_m / (fl["area_m2"] * np.maximum(ce, 1e-12)),
                          0.0)
            L[s] = np.where(hit, lk[face], 0.0)
    meta = {"range_km": d, "ifov_rad": ifov, "diam_px": diam_px, "crop_px": crop_px,
            "oversample": os_, "subpix_sr": sub * sub, "drawn_as_disc": drawn_as_disc,
            "shape": "sphere" if model is None else f"facet model ({len(tris)} triangles)"}
    return L, meta


def _row_kwargs(sc: dict) -> dict:
    """orbillum.illuminate's arguments for the one row sc describes."""
    kw = {"sun": sc["sun"], "moon": sc.get("moon"), "target": sc["target"],
          "observer": sc["observer"], "target_albedo": sc["target_albedo"]}
    for k in ("terms", "earth_albedo", "target_radius_m"):
        if sc.get(k) is not None:
            kw[k] = sc[k]
    return kw


def model_shape(sc: dict, model):
    """The OBJ model's triangles as runtime facets, their attitude, and the
    whole model as one orbillum.Shape (triangles merged by plane)."""
    import orbillum

    from .facets import attitude_quaternion, merge_facets, nadir_sun_attitude, triangle_facets
    verts_m, tris = model
    rot = nadir_sun_attitude(sc["target"], sc["sun"])
    facets = triangle_facets(verts_m, tris, sc["target_albedo"], sc.get("albedo_specular", 0.0),
                             sc.get("shininess", 0.0))
    merged = merge_facets(facets)
    if len(merged) > orbillum.OI_FACETS_MAX:
        raise ValueError(f"the model has {len(merged)} distinct facet planes; the runtime takes "
                         f"at most OI_FACETS_MAX = {orbillum.OI_FACETS_MAX}")
    return facets, rot, attitude_quaternion(rot), orbillum.Shape(merged, name="obj")


def facet_fluxes(sc: dict, model) -> dict:
    """The runtime's flux per source (W/m^2 at the observer) of each triangle
    alone (one oi_illuminate row per triangle, each a one-facet shape), and
    the triangles' input-frame normals, areas, sides and the attitude."""
    import orbillum

    facets, rot, q, _whole = model_shape(sc, model)
    shapes = [orbillum.Shape([f]) for f in facets]
    r = orbillum.illuminate(**_row_kwargs(sc), target_shape=shapes, attitude_q=q)
    bad = r["status"] < 0
    if bad.any():
        raise ValueError(f"the runtime rejects triangle {int(np.argmax(bad))}: "
                         f"{r['status_name'][np.argmax(bad)]}")
    return {"sun": r["flux_sun"], "earth": r["flux_earth"], "moon": r["flux_moon"],
            "normals": np.array([rot @ f["normal"] for f in facets]),
            "area_m2": np.array([f["area_m2"] for f in facets]),
            "two_sided": np.array([f["two_sided"] for f in facets]), "rot": rot, "q": q}


def electrons_per_radiance(cam: dict, exposure_s: float, subpix_sr: float) -> float:
    """Electrons per (W/m^2/sr) in one sub-pixel during the exposure."""
    area = math.pi * (cam["aperture_m"] / 2.0) ** 2
    return (subpix_sr * area * cam["transmission"] * cam["band_fraction"] *
            cam["quantum_efficiency"] / cam["photon_energy_j"] * exposure_s)


def _bin(img, k):
    m = img.shape[0] // k
    return img[:m * k, :m * k].reshape(m, k, m, k).sum(axis=(1, 3))


def render(sc: dict, res: dict, cam: dict, seed: int = 1, model=None) -> dict:
    """Camera frame (electrons, DN fraction of saturation), HDR view and false colour."""
    from scipy.ndimage import gaussian_filter

    L, meta = radiance_image(sc, res, cam, model=model)
    k = meta["oversample"]
    t_exp = float(res["exposure_s"])
    gain = float(res["gain"])
    gi = int(res["gain_index"])
    e_per_L = electrons_per_radiance(cam, t_exp, meta["subpix_sr"])
    sigma_px = psf_sigma_px(cam["psf_peak_fraction"])
    sig_e = {}
    if meta["drawn_as_disc"]:
        for s, img in L.items():
            e = img * e_per_L
            sig_e[s] = _bin(gaussian_filter(e, sigma_px * k, mode="constant")
                            if sigma_px > 0 else e, k)
    else:
        # point source centred on the middle pixel: Gaussian PSF integrated
        # over each detector pixel (erf differences)
        n = meta["crop_px"] | 1
        meta["crop_px"] = n
        edges = np.arange(n + 1) - n / 2.0
        if sigma_px > 0:
            cdf = np.array([0.5 * (1 + math.erf(x / (math.sqrt(2) * sigma_px)))
                            for x in edges])
        else:
            cdf = (edges >= 0).astype(float)
        w1 = np.diff(cdf)
        psf = np.outer(w1, w1)
        for s, img in L.items():
            sig_e[s] = psf * (img.sum() * e_per_L)
    signal = sum(sig_e.values())
    bg = float(res["background_e"])
    rng = np.random.default_rng(seed)
    mean = signal + bg
    electrons = rng.poisson(mean).astype(float) + rng.normal(0.0, cam["read_noise_e"][gi],
                                                            mean.shape)
    sat = cam["full_well_e"] / gain
    frame = np.clip(electrons / sat, 0.0, 1.0)
    # HDR: logarithmic tone map of the noiseless sub-pixel radiance
    lum = sum(L.values())
    mx = float(lum.max())
    if mx > 0:
        hdr = np.clip(1.0 + np.log10(np.maximum(lum, mx * 1e-30) / mx) / HDR_DECADES, 0, 1)
    else:
        hdr = np.zeros_like(lum)
    # false colour: Sun warm white, Earth blue, Moon green, each on its own scale
    fc = np.zeros(lum.shape + (3,))
    tint = {"sun": (1.0, 0.85, 0.6), "earth": (0.25, 0.5, 1.0), "moon": (0.3, 1.0, 0.4)}
    for s, img in L.items():
        mx = img.max()
        if mx > 0:
            v = np.sqrt(img / mx)
            fc += v[..., None] * np.array(tint[s])
    fc = np.clip(fc, 0, 1)
    meta.update(signal_total_e=float(signal.sum()), peak_e=float(mean.max()),
                saturation_e=sat, saturated_px=int((electrons >= sat).sum()),
                flux_render_w_m2=float(sum(img.sum() for img in L.values()) *
                                       meta["subpix_sr"]))
    return {"frame": frame, "electrons": electrons, "signal_e": sig_e, "hdr": hdr,
            "false_colour": fc, "radiance": L, "meta": meta}


def pick_row(res: dict, ids) -> int:
    """The row with the highest SNR among rows that are OK and carry none of
    the flags that spoil a picture (Sun exclusion, occulted, saturated); any OK
    row if there is none."""
    ok = (res["status"] >= 0) & (res["expose_status"] >= 0)
    spoil = np.array([any(k in f for k in ("sun_exclusion", "occulted", "saturated"))
                      for f in res["flag_names"]])
    score = np.where(ok & ~spoil, res["snr"], -1.0)
    if score.max() < 0:
        score = np.where(ok, res["snr"], -1.0)
    return int(np.argmax(score))


def plot_view(out_png, img: dict, sc: dict, res: dict, cam: dict, when: str) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    meta = img["meta"]
    drawn_as_disc = meta["drawn_as_disc"]
    fig, ax = plt.subplots(1, 3, figsize=(13, 5.4))
    ext = None
    ax[0].imshow(img["frame"], cmap="gray", vmin=0, vmax=1, interpolation="nearest")
    ax[0].set_title(f"camera frame: {res['exposure_s']:g} s, gain {res['gain']:g}\n"
                    f"(linear 0..saturation, noise; peak {meta['peak_e'] / meta['saturation_e']:.1%}"
                    f" of saturation)", fontsize=9)
    ax[1].imshow(img["hdr"], cmap="gray", vmin=0, vmax=1, interpolation="nearest", extent=ext)
    ax[1].set_title(f"HDR: log radiance, {HDR_DECADES:g} decades\nnoiseless, sub-pixel grid",
                    fontsize=9)
    ax[2].imshow(img["false_colour"], interpolation="nearest")
    ax[2].set_title("light per source: Sun (warm), Earth (blue), Moon (green)\n"
                    "each on its own scale", fontsize=9)
    for a in ax:
        a.set_xticks([])
        a.set_yticks([])
    e = [f"{s} {res['e_' + s]:.3g}" for s in ("sun", "earth", "moon")]
    shape = (f"target {sc['target_radius_m']:g} m radius" if meta["shape"] == "sphere"
             else f"target: {meta['shape']}, nadir/Sun attitude")
    note = (f"{when}   camera {cam['name']}   range {meta['range_km']:.3f} km   "
            f"{shape}, albedo {sc['target_albedo']:g}\n"
            f"irradiance W/m$^2$: {', '.join(e)}   Sun fraction (atm) "
            f"{res['sun_fraction_atm']:.4f}   phase(Sun) {math.degrees(res['phase_sun']):.1f} deg"
            f"   V = {res['mag_v']:.2f}   SNR {res['snr']:.3g}   flags: "
            f"{res['flag_names'] or 'none'}\n"
            f"target {meta['diam_px']:.2f} px across; crop {meta['crop_px']} x "
            f"{meta['crop_px']} detector px" +
            ("" if drawn_as_disc else
             f"; under {DISC_PX:g} px across, drawn as its PSF blob, upsampled (nearest pixel); the "
             f"HDR/colour panels show the sphere {meta['oversample']:.0f}x finer than a pixel") +
            "; up = away from the Earth")
    fig.text(0.01, 0.01, note, fontsize=8, va="bottom")
    fig.tight_layout(rect=(0, 0.12, 1, 0.97))
    fig.savefig(out_png, dpi=80)
    plt.close(fig)


def row_scene(inputs: dict, i: int) -> dict:
    sc = {"target": inputs["target"][i], "observer": inputs["observer"][i],
          "sun": inputs["sun"][i],
          "moon": None if inputs.get("moon") is None else inputs["moon"][i],
          "target_radius_m": float(inputs.get("target_radius_m", [1.0] * (i + 1))[i]),
          "target_albedo": float(inputs.get("target_albedo", [0.2] * (i + 1))[i])}
    for k in ("terms", "earth_albedo"):
        if inputs.get(k) is not None:
            sc[k] = inputs[k][i]
    return sc


def row_result(res: dict, i: int) -> dict:
    return {k: (v[i] if isinstance(v, np.ndarray) else v) for k, v in res.items()}


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m examples.render.view",
                                description="Render what the observer's camera sees at one "
                                            "instant of a planner input CSV.")
    p.add_argument("input", help="the planner's input CSV (with observer and camera columns)")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--time", help="the row whose id is this (e.g. 2006-04-09T19:00:00Z)")
    g.add_argument("--row", type=int, help="row number (0 = first data row)")
    p.add_argument("--camera", help="built-in camera (default: the CSV's camera column)")
    p.add_argument("--seed", type=int, default=1, help="noise seed")
    p.add_argument("--obj", help="render this OBJ facet model (metres, body frame; nadir/Sun "
                                 "attitude) instead of the sphere, lit by the runtime's facet "
                                 "model; the exposure is the runtime's for that shape (it "
                                 "replaces the row's target_shape and q_w..q_z)")
    p.add_argument("--specular", type=float, default=0.0,
                   help="with --obj: the facets' specular albedo (the runtime's Phong lobe; "
                        "default 0)")
    p.add_argument("--shininess", type=float, default=0.0,
                   help="with --obj: the lobe's exponent (default 0)")
    p.add_argument("-o", "--output", required=True, help="PNG file")
    a = p.parse_args(argv)

    import orbillum

    cols = read_csv(a.input)
    inputs = scene_inputs(cols)
    if inputs["observer"] is None:
        print(f"error: {a.input}: no observer_x/y/z columns: nothing to look from",
              file=sys.stderr)
        return 2
    camname = a.camera or (cols.get("camera", [""])[0] if "camera" in cols else "")
    if not camname:
        camname = orbillum.cameras()[0]
    cam = orbillum.camera(camname)
    try:
        res = orbillum.expose(camname, **inputs)
    except ValueError as e:  # e.g. a target_shape from a --shapes file the binding does not read
        print(f"error: {a.input}: {e}", file=sys.stderr)
        return 2
    ids = cols.get("id", [str(i) for i in range(len(res["status"]))])
    if a.time:
        if a.time not in ids:
            print(f"error: no row with id {a.time!r} (first {ids[0]}, last {ids[-1]})",
                  file=sys.stderr)
            return 2
        i = ids.index(a.time)
    elif a.row is not None:
        if not 0 <= a.row < len(ids):
            print(f"error: --row {a.row}: the file has rows 0..{len(ids) - 1}", file=sys.stderr)
            return 2
        i = a.row
    else:
        i = pick_row(res, ids)
    r = row_result(res, i)
    if r["status"] < 0 or r["expose_status"] < 0:
        print(f"error: row {i} ({ids[i]}): {r['status_name']} / {r['expose_status_name']}",
              file=sys.stderr)
        return 1
    sc = row_scene(inputs, i)
    shape = (inputs.get("target_shape") or [None] * (i + 1))[i]
    if shape not in (None, "sphere") and not a.obj:
        print(f"error: row {i} ({ids[i]}) has target_shape {shape!r}: a facet shape has no "
              "geometry to draw; the view draws the sphere or an OBJ model (--obj)",
              file=sys.stderr)
        return 2
    model = None
    if a.obj:
        from .facets import load_obj
        sc["albedo_specular"] = a.specular
        sc["shininess"] = a.shininess
        try:
            model = load_obj(a.obj)
            _facets, _rot, q, whole = model_shape(sc, model)
        except (OSError, ValueError) as e:
            print(f"error: {e}", file=sys.stderr)
            return 2
        # the runtime's exposure for the model itself (all its facets as one shape)
        r = row_result(orbillum.expose(camname, **_row_kwargs(sc), target_shape=whole,
                                       attitude_q=q), 0)
        if r["status"] < 0 or r["expose_status"] < 0:
            print(f"error: row {i} ({ids[i]}) with {a.obj}: {r['status_name']} / "
                  f"{r['expose_status_name']}", file=sys.stderr)
            return 1
    img = render(sc, r, cam, seed=a.seed, model=model)
    plot_view(a.output, img, sc, r, cam, ids[i])
    print(f"{a.output}: row {i} ({ids[i]})", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
