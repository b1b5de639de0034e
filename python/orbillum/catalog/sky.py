# SPDX-License-Identifier: MIT
"""The sky of every epoch in one frame: Sun, Moon, and satellites by vectorised SGP4, GCRS km.

Sun and Moon: astropy ``get_body`` with the built-in ephemeris (ERFA epv00 and
moon98), apparent geocentric GCRS, as examples/scenarios writes them
(docs/real-use.md). Satellites: sgp4's ``SatrecArray`` (Vallado et al. 2006)
gives TEME positions and velocities for many objects at once; TEME -> GCRS is,
for a geocentric vector at one instant, a rotation (GMST 1982 and polar motion,
then IAU 2006/2000A precession-nutation with the IERS Earth orientation), so
astropy's TEME -> GCRS transform is taken once per epoch as a 3x3 matrix (the
images of the three axes) and applied to every object by elementwise products:
each row's value depends on that row's inputs only, so results are the same
bits whatever the partitioning. The matrix differs from astropy's per-point
transform by rounding only (tests/python/test_catalog.py bounds it).

Earth orientation offline, as examples/scenarios: the IERS tables bundled with
astropy, their predictions accepted, and beyond them degraded accuracy with a
warning.
"""
from __future__ import annotations

import math
import warnings

import numpy as np
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
from sgp4.api import WGS72, Satrec, SatrecArray  # noqa: E402

from .tle import CatalogueError  # noqa: E402

#: the most epochs one run takes (a week at 10 s is 60,481)
MAX_EPOCHS = 1_000_000


def epochs(start: str, stop: str, step_s: float) -> Time:
    """UTC epochs from start to stop inclusive (when on the grid), every step_s seconds."""
    if not (isinstance(step_s, (int, float)) and math.isfinite(step_s) and step_s > 0):
        raise CatalogueError(f"step must be a number of seconds > 0 (got {step_s!r})")
    try:
        t0 = Time(start, scale="utc")
        t1 = Time(stop, scale="utc")
    except ValueError as e:
        raise CatalogueError(f"bad time {start!r} or {stop!r}: use ISO 8601 UTC, "
                             "e.g. 2026-12-01T00:00:00") from e
    span = (t1 - t0).to_value(u.s)
    if span < 0:
        raise CatalogueError(f"stop {stop} is before start {start}")
    n = int(math.floor(span / step_s + 1e-9)) + 1
    if n > MAX_EPOCHS:
        raise CatalogueError(f"{n} epochs: more than {MAX_EPOCHS}; use a longer step")
    return t0 + (np.arange(n) * step_s) * u.s


def bodies(t: Time) -> tuple[np.ndarray, np.ndarray]:
    """(sun, moon): apparent geocentric GCRS positions (N, 3), km."""
    with solar_system_ephemeris.set("builtin"):
        sun = get_body("sun", t)
        moon = get_body("moon", t)
    return (np.ascontiguousarray(sun.cartesian.xyz.to_value(u.km).T),
            np.ascontiguousarray(moon.cartesian.xyz.to_value(u.km).T))


def teme_to_gcrs(t: Time) -> np.ndarray:
    """(N, 3, 3): the rotation taking a TEME vector at epoch t[i] to GCRS (column j
    is the image of TEME axis j)."""
    n = len(t)
    axes = np.zeros((3, n, 3))
    for j in range(3):
        axes[j, :, j] = 1.0
    flat = axes.reshape(3 * n, 3)
    tt = Time(np.tile(t.jd1, 3), np.tile(t.jd2, 3), format="jd", scale=t.scale)
    teme = TEME(CartesianRepresentation(flat.T * u.km), obstime=tt)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", category=UserWarning)
        g = teme.transform_to(GCRS(obstime=tt))
    img = g.cartesian.xyz.to_value(u.km).T.reshape(3, n, 3)  # [axis j, epoch, component]
    return np.ascontiguousarray(np.transpose(img, (1, 2, 0)))


def rotate(rot: np.ndarray, v: np.ndarray) -> np.ndarray:
    """rot (N, 3, 3) applied to v (..., N, 3), by elementwise products and sums in a
    fixed order (the same bits for every row however the rows are grouped)."""
    out = np.empty_like(v)
    for i in range(3):
        out[..., i] = (rot[:, i, 0] * v[..., 0] + rot[:, i, 1] * v[..., 1]) + \
            rot[:, i, 2] * v[..., 2]
    return out


#: sgp4init's units: rev/day -> rad/min, rev/day^2 -> rad/min^2, rev/day^3 -> rad/min^3
_XPDOTP = 1440.0 / (2.0 * math.pi)
#: the largest catalogue number sgp4 keeps (Alpha-5 'Z9999'); larger ones are kept by
#: the element set, and given to sgp4 as 0 (the number does not enter the propagation)
SGP4_MAX_SATNUM = 339999


def satrec(s) -> Satrec:
    """The sgp4 satellite of an element set: its TLE lines (twoline2rv) or its mean
    elements (sgp4init, WGS-72, improved mode as twoline2rv)."""
    if s.mean is None:
        return Satrec.twoline2rv(s.line1, s.line2, WGS72)
    m = s.mean
    sat = Satrec()
    num = s.number if s.number <= SGP4_MAX_SATNUM else 0
    d2r = math.pi / 180.0
    sat.sgp4init(WGS72, "i", num, m.epoch_days, m.bstar, m.ndot / (_XPDOTP * 1440.0),
                 m.nddot / (_XPDOTP * 1440.0 * 1440.0), m.ecc, m.argp_deg * d2r,
                 m.incl_deg * d2r, m.mo_deg * d2r, m.mean_motion / _XPDOTP, m.raan_deg * d2r)
    return sat


def satrecs(sets) -> list[Satrec]:
    """sgp4 satellites of element sets; CatalogueError naming a set sgp4 rejects."""
    out = []
    for s in sets:
        sat = satrec(s)
        if sat.error:
            raise CatalogueError(f"{s.where}: sgp4 rejects the element set (error {sat.error})")
        out.append(sat)
    return out


def propagate(sats: list[Satrec], jd1: np.ndarray, jd2: np.ndarray, rot: np.ndarray):
    """GCRS positions (M, N, 3) km, velocities (M, N, 3) km/s and sgp4 error codes
    (M, N; 0 = fine) of M satellites at N UTC epochs (Julian date jd1 + jd2)."""
    err, r, v = SatrecArray(sats).sgp4(jd1, jd2)
    return rotate(rot, r), rotate(rot, v), err
