# SPDX-License-Identifier: MIT
"""Scenarios from the real sky: Sun, Moon and satellites in one Earth-centred frame.

Frame: everything is written in the GCRS (Geocentric Celestial Reference System,
IAU 2000), Cartesian, km, the frame in which astropy returns solar-system bodies.

Conversions done here (see docs/real-use.md):

* Sun and Moon: ``astropy.coordinates.get_body`` with the *built-in* ephemeris
  (``solar_system_ephemeris.set("builtin")``: ERFA ``epv00`` for the Earth and
  Sun, ERFA ``moon98`` (ELP-2000/82 truncated, Meeus ch. 47) for the Moon). The
  result is the apparent geocentric GCRS position (light time and aberration
  applied, ~20 arcsec: immaterial for illumination); distance in km.
* Satellites: ``sgp4`` (Vallado et al. 2006 implementation) gives positions in
  TEME (True Equator, Mean Equinox of date) at UTC epochs; astropy's ``TEME``
  frame converts them to GCRS (TEME -> ITRS by GMST 1982 and polar motion,
  ITRS -> CIRS -> GCRS by the IAU 2006/2000A model with IERS Earth orientation).
* Time: UTC as given on the command line; sgp4 is driven with the same UTC
  Julian dates it expects.

Offline: IERS auto-download is switched off; Earth orientation comes from the
IERS tables bundled with astropy (``astropy-iers-data``): measured values up to
some weeks before the package's release, then about a year of IERS
predictions. Any date plans: within the measured span silently; beyond it on
the predictions with a warning (``auto_max_age = None``: astropy would
otherwise refuse predictions more than 30 days old); beyond the predictions
astropy falls back to degraded accuracy (polar motion 50-year mean, UT1 = UTC)
with a warning (``iers_degraded_accuracy = "warn"``) and ours
(earth_orientation_warning). The position error is far below the error of a
TLE: UT1 - UTC stays within 0.9 s, and 1 s of UT1 moves a LEO position by
< ~0.5 km.
"""
from __future__ import annotations

import json
import math
import os
import warnings
from dataclasses import dataclass, field

import numpy as np

# Offline before anything else in astropy is touched.
from astropy.utils import iers

iers.conf.auto_download = False
iers.conf.auto_max_age = None
iers.conf.iers_degraded_accuracy = "warn"

import astropy.units as u  # noqa: E402
from astropy.coordinates import (  # noqa: E402
    GCRS,
    TEME,
    CartesianRepresentation,
    get_body,
    solar_system_ephemeris,
)
from astropy.time import Time  # noqa: E402
from sgp4.api import WGS72, Satrec  # noqa: E402

solar_system_ephemeris.set("builtin")

CASES_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cases")

#: WGS-72 gravitational parameter (km^3/s^2), the constant SGP4 uses.
MU_WGS72 = 398600.8
#: Minutes per day.
MIN_PER_DAY = 1440.0
#: Julian date of 1949 December 31 0h UT, the epoch origin of sgp4init.
JD_1950 = 2433281.5


class ScenarioError(ValueError):
    """A scenario input that cannot be used; the message says what to fix."""


# ----------------------------------------------------------------- TLE input


@dataclass
class Tle:
    name: str
    line1: str
    line2: str
    source: str = ""


def _tle_module():
    """orbillum.catalog.tle, the one TLE reader, loaded from its file: it needs
    neither the compiled library the package loads nor astropy."""
    import importlib.util
    import sys
    name = "orbillum_catalog_tle"
    if name not in sys.modules:
        path = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
            os.path.abspath(__file__)))), "python", "orbillum", "catalog", "tle.py")
        spec = importlib.util.spec_from_file_location(name, path)
        mod = importlib.util.module_from_spec(spec)
        sys.modules[name] = mod  # before it runs: its dataclasses look their module up
        spec.loader.exec_module(mod)
    return sys.modules[name]


def read_tles(path: str) -> list[Tle]:
    """Read a TLE or 3LE file. '#' lines are comments; a line before a '1 ' line is a name.

    Raises ScenarioError with the file name and line number of a malformed set
    (the reader is orbillum.catalog.tle's).
    """
    tle = _tle_module()
    try:
        sets = tle.read(path)
    except tle.CatalogueError as e:
        raise ScenarioError(str(e)) from e
    return [Tle(s.name, s.line1, s.line2, source=path) for s in sets]


def pick_tle(tles: list[Tle], key: str | None, path: str) -> Tle:
    """Choose a TLE by catalogue number or name substring; the only one if key is None."""
    if key is None:
        if len(tles) != 1:
            names = ", ".join(t.name for t in tles)
            raise ScenarioError(f"{path} holds {len(tles)} element sets ({names}); "
                                "say which one with FILE:NUMBER or FILE:NAME")
        return tles[0]
    k = key.strip().lower()
    for t in tles:
        if t.line1[2:7].strip().lstrip("0") == k.lstrip("0") or k in t.name.lower():
            return t
    raise ScenarioError(f"{path}: no element set matches {key!r}")


def satrec_from_tle(t: Tle) -> Satrec:
    sat = Satrec.twoline2rv(t.line1, t.line2, WGS72)
    if sat.error:
        raise ScenarioError(f"{t.source}: {t.name}: sgp4 rejects the element set "
                            f"(error {sat.error})")
    return sat


# ---------------------------------------------------- orbits given as elements


ELEMENT_KEYS = ("incl_deg", "raan_deg", "ecc", "argp_deg", "mo_deg", "no_rev_day",
                "bstar")


def _sat_elements(sat: Satrec) -> dict:
    return {
        "incl_deg": math.degrees(sat.inclo), "raan_deg": math.degrees(sat.nodeo),
        "ecc": sat.ecco, "argp_deg": math.degrees(sat.argpo),
        "mo_deg": math.degrees(sat.mo),
        "no_rev_day": sat.no_kozai * MIN_PER_DAY / (2 * math.pi), "bstar": sat.bstar,
        "epoch_jd": sat.jdsatepoch + sat.jdsatepochF,
    }


def satrec_from_elements(el: dict, satnum: int = 99999) -> Satrec:
    """An SGP4 satellite from mean elements.

    el: ``epoch`` (ISO UTC) or ``epoch_jd``; ``a_km`` or ``no_rev_day``; ``ecc``,
    ``incl_deg``, ``raan_deg``, ``argp_deg``, ``mo_deg``; optional ``bstar`` (0).
    The elements are SGP4 (Kozai) mean elements; from ``a_km`` the mean motion is
    the two-body sqrt(mu/a^3) with WGS-72 mu (the small J2 offset of SGP4's
    mean semi-major axis is not applied: a few hundred metres in LEO).
    """
    el = dict(el)
    if "epoch_jd" in el:
        ep = float(el["epoch_jd"])
    elif "epoch" in el:
        ep = Time(el["epoch"], scale="utc").jd
    else:
        raise ScenarioError("orbit elements need 'epoch' (ISO UTC time)")
    if "no_rev_day" in el:
        no = float(el["no_rev_day"]) * 2 * math.pi / MIN_PER_DAY
    elif "a_km" in el:
        a = float(el["a_km"])
        if not a > 6378.135:
            raise ScenarioError(f"a_km = {a} is inside the Earth")
        no = math.sqrt(MU_WGS72 / a ** 3) * 60.0
    else:
        raise ScenarioError("orbit elements need 'a_km' or 'no_rev_day'")
    for k in ("ecc", "incl_deg", "raan_deg", "argp_deg", "mo_deg"):
        if k not in el:
            raise ScenarioError(f"orbit elements need {k!r}")
    ecc = float(el["ecc"])
    if not 0.0 <= ecc < 1.0:
        raise ScenarioError(f"ecc = {ecc} must be in [0, 1)")
    sat = Satrec()
    sat.sgp4init(WGS72, "i", satnum, ep - JD_1950, float(el.get("bstar", 0.0)), 0.0, 0.0,
                 ecc, math.radians(float(el["argp_deg"])), math.radians(float(el["incl_deg"])),
                 math.radians(float(el["mo_deg"])), no, math.radians(float(el["raan_deg"])))
    if sat.error:
        raise ScenarioError(f"sgp4 rejects the elements {el} (error {sat.error})")
    return sat


def satrec_relative(base: Satrec, delta: dict, satnum: int = 99998) -> Satrec:
    """A satellite whose mean elements are those of ``base`` plus ``delta``.

    delta keys: any of ELEMENT_KEYS (added). Used for inspectors flying near a
    catalogued object: e.g. {"ecc": 1.3e-4} at the same mean motion gives a
    2:1 relative ellipse (the inspector circles the target once per orbit).
    """
    el = _sat_elements(base)
    for k, v in delta.items():
        if k not in ELEMENT_KEYS:
            raise ScenarioError(f"unknown element delta {k!r}; use one of {ELEMENT_KEYS}")
        el[k] += float(v)
    if el["ecc"] < 0:
        # keep the same eccentricity vector: negative e is e at argp + 180
        el["ecc"] = -el["ecc"]
        el["argp_deg"] += 180.0
        el["mo_deg"] -= 180.0
    return satrec_from_elements(el, satnum)


# ---------------------------------------------------------------- propagation


def times_utc(start: str, stop: str, step_s: float) -> Time:
    """UTC epochs from start to stop inclusive (if on the grid), every step_s seconds."""
    if not step_s > 0:
        raise ScenarioError(f"step must be > 0 s (got {step_s})")
    try:
        t0 = Time(start, scale="utc")
        t1 = Time(stop, scale="utc")
    except ValueError as e:
        raise ScenarioError(f"bad time {start!r} or {stop!r}: use ISO 8601 UTC, "
                            "e.g. 2006-04-09T18:00:00") from e
    span = (t1 - t0).to_value(u.s)
    if span < 0:
        raise ScenarioError(f"stop {stop} is before start {start}")
    n = int(math.floor(span / step_s + 1e-9)) + 1
    if n > 2_000_000:
        raise ScenarioError(f"{n} epochs: more than 2,000,000; use a longer step")
    return t0 + (np.arange(n) * step_s) * u.s


#: beyond this many days from the element epoch a warning is printed
EPOCH_WARN_DAYS = 14.0


def propagate_gcrs(sat: Satrec, t: Time, label: str = "satellite") -> np.ndarray:
    """Positions (N, 3) km in GCRS of an sgp4 satellite at UTC epochs t."""
    jd1 = np.asarray(t.utc.jd1, dtype=float)
    jd2 = np.asarray(t.utc.jd2, dtype=float)
    age = np.max(np.abs((jd1 - sat.jdsatepoch) + (jd2 - sat.jdsatepochF)))
    if age > EPOCH_WARN_DAYS:
        warnings.warn(f"{label}: epochs up to {age:.0f} days from the element epoch "
                      f"({Time(sat.jdsatepoch + sat.jdsatepochF, format='jd').utc.isot[:16]}Z): "
                      "SGP4 predictions degrade by kilometres per day; use TLEs closer to "
                      "the dates", stacklevel=2)
    err, r, _v = sat.sgp4_array(jd1, jd2)
    bad = np.nonzero(err)[0]
    if bad.size:
        i = int(bad[0])
        raise ScenarioError(
            f"{label}: sgp4 fails at {t[i].isot} (error {int(err[i])}: decayed or "
            "elements too far from their epoch); shorten the date range or use newer TLEs")
    teme = TEME(CartesianRepresentation(r.T * u.km), obstime=t)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", category=UserWarning)
        g = teme.transform_to(GCRS(obstime=t))
    return np.ascontiguousarray(g.cartesian.xyz.to_value(u.km).T)


def body_gcrs(name: str, t: Time) -> np.ndarray:
    """Apparent geocentric GCRS position (N, 3) km of 'sun' or 'moon' (built-in ephemeris)."""
    with solar_system_ephemeris.set("builtin"):
        c = get_body(name, t)
    return np.ascontiguousarray(c.cartesian.xyz.to_value(u.km).T)


# --------------------------------------------------------------------- cases


@dataclass
class Scenario:
    name: str
    start: str
    stop: str
    step_s: float
    target: Satrec
    observer: Satrec | None
    target_label: str = "target"
    observer_label: str = "observer"
    columns: dict = field(default_factory=dict)  # constant extra columns (camera, albedos...)
    description: str = ""


def _sat_from_spec(spec: dict, base_dir: str, others: dict, label: str) -> Satrec:
    if "tle" in spec:
        ref = spec["tle"]
        path, _, key = ref.partition(":") if ":" in os.path.basename(ref) else (ref, "", "")
        if not os.path.isabs(path):
            path = os.path.join(base_dir, path)
        return satrec_from_tle(pick_tle(read_tles(path), key or None, path))
    if "elements" in spec:
        return satrec_from_elements(spec["elements"])
    if "relative_to" in spec:
        base = others.get(spec["relative_to"])
        if base is None:
            raise ScenarioError(f"{label}: relative_to {spec['relative_to']!r} is not "
                                "defined before it (define the target first)")
        return satrec_relative(base, spec.get("delta", {}))
    raise ScenarioError(f"{label}: give 'tle', 'elements' or 'relative_to'")


def load_case(path_or_name: str) -> Scenario:
    """Load a JSON case file (or the name of a shipped case in cases/)."""
    path = path_or_name
    if not os.path.exists(path):
        cand = os.path.join(CASES_DIR, path_or_name + ".json")
        if os.path.exists(cand):
            path = cand
        else:
            raise ScenarioError(f"no case file {path_or_name!r}; shipped cases: "
                                + ", ".join(list_cases()))
    with open(path, encoding="utf-8") as f:
        try:
            c = json.load(f)
        except json.JSONDecodeError as e:
            raise ScenarioError(f"{path}:{e.lineno}:{e.colno}: bad JSON: {e.msg}") from e
    base_dir = os.path.dirname(os.path.abspath(path))
    sats: dict = {}
    for role in ("target", "observer"):
        if role in c:
            sats[role] = _sat_from_spec(c[role], base_dir, sats, role)
    if "target" not in sats:
        raise ScenarioError(f"{path}: a case needs a 'target'")
    for k in ("start", "stop", "step_s"):
        if k not in c:
            raise ScenarioError(f"{path}: missing {k!r}")
    return Scenario(
        name=c.get("name", os.path.splitext(os.path.basename(path))[0]),
        start=c["start"], stop=c["stop"], step_s=float(c["step_s"]),
        target=sats["target"], observer=sats.get("observer"),
        target_label=c["target"].get("label", "target"),
        observer_label=c.get("observer", {}).get("label", "observer"),
        columns=dict(c.get("columns", {})), description=c.get("description", ""))


def list_cases() -> list[str]:
    return sorted(f[:-5] for f in os.listdir(CASES_DIR) if f.endswith(".json"))


# ----------------------------------------------------------------- the table


def earth_orientation_span() -> tuple[float, float]:
    """(last measured, last predicted) MJD of the bundled IERS-A table."""
    table = iers.IERS_Auto.open()
    mjd = np.asarray(table["MJD"].to_value(u.d), dtype=float)
    measured = mjd[np.asarray(table["UT1Flag_A"]) == "I"]
    return (float(measured[-1]) if measured.size else float(mjd[0])), float(mjd[-1])


def earth_orientation_warning(t: Time) -> str | None:
    """The warning for epochs beyond the measured Earth orientation, or None."""
    measured_end, predicted_end = earth_orientation_span()
    last = float(np.max(t.utc.mjd))
    if last <= measured_end:
        return None
    date = Time(last, format="mjd", scale="utc").isot[:10]

    def day(m):
        return Time(m, format="mjd", scale="utc").isot[:10]
    if last <= predicted_end:
        return (f"epochs up to {date}: beyond the measured Earth orientation of the shipped "
                f"IERS data (measured to {day(measured_end)}): IERS predictions used "
                "(UT1 good to some milliseconds; positions to metres)")
    return (f"epochs up to {date}: beyond the shipped Earth-orientation data (predictions end "
            f"{day(predicted_end)}): degraded accuracy, UT1 = UTC and mean polar motion "
            "(UT1 - UTC is within 0.9 s: LEO positions off by < ~0.5 km, far below a TLE's "
            "error); update astropy-iers-data for better")


def build_rows(sc: Scenario) -> dict:
    """Column name -> array (or list of strings) of the planner's input CSV."""
    t = times_utc(sc.start, sc.stop, sc.step_s)
    msg = earth_orientation_warning(t)
    if msg:
        warnings.warn(msg, stacklevel=2)
    cols: dict = {"id": [ti[:-4] + "Z" if ti.endswith(".000") else ti + "Z"
                         for ti in t.utc.isot]}
    for name, xyz in (("sun", body_gcrs("sun", t)), ("moon", body_gcrs("moon", t)),
                      ("target", propagate_gcrs(sc.target, t, sc.target_label))):
        for k, axis in enumerate("xyz"):
            cols[f"{name}_{axis}"] = xyz[:, k]
    if sc.observer is not None:
        obs = propagate_gcrs(sc.observer, t, sc.observer_label)
        for k, axis in enumerate("xyz"):
            cols[f"observer_{axis}"] = obs[:, k]
    n = len(t)
    for k, v in sc.columns.items():
        cols[k] = [str(v)] * n
    return cols


def write_csv(cols: dict, out) -> int:
    """Write the columns as the planner's CSV (numbers %.17g). Returns the row count."""
    names = list(cols)
    n = len(cols["id"])
    out.write(",".join(names) + "\n")
    fmt = []
    for k in names:
        v = cols[k]
        fmt.append(v if isinstance(v, list) else ["%.17g" % x for x in v])
    for i in range(n):
        out.write(",".join(f[i] for f in fmt) + "\n")
    return n
