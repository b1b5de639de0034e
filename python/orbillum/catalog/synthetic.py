# SPDX-License-Identifier: MIT
"""A seeded synthetic catalogue: element sets drawn from the shape of the tracked population.

No full catalogue ships with the repository, so tests and benchmarks draw one.
The same (count, seed, epoch) gives the same element sets on every machine
(numpy's PCG64 generator, Python's float formatting). The orbit classes and
their shares follow the tracked population by orbit class in ESA Space Debris
Office, "ESA's Annual Space Environment Report" (2024): most objects in LEO,
then the GTO/Molniya-type highly eccentric orbits, GEO, and the navigation
constellations in MEO. Within each class (the rounded shares and spreads are
this module's choices, not the report's figures):

* LEO: the large constellation shells near 550 km at 53 deg and 43/70/97.6 deg
  (the Starlink shells filed with the FCC, 2018-2021), sun-synchronous orbits
  450-900 km at the inclination J2 makes sun-synchronous (Vallado,
  *Fundamentals of Astrodynamics and Applications*, 4th ed., eq. 9-51), and the
  debris band 700-1000 km at 65-99 deg (the Fengyun-1C and Cosmos-2251/Iridium
  33 clouds, Liou & Johnson 2009); near-circular (e < 0.02).
* MEO: GPS (a = 26,560 km, i = 55 deg), GLONASS (25,508 km, 64.8 deg), Galileo
  (29,600 km, 56 deg), BeiDou-MEO (27,906 km, 55 deg); e < 0.01.
* GEO: a = 42,164 km; half station-kept (i < 0.1 deg), half drifting with the
  inclination the luni-solar precession raises to at most ~15 deg (Vallado
  ch. 9); e < 0.001.
* HEO: transfer orbits (perigee 250-650 km, apogee near GEO, i = 6, 28.5 or
  ~20 deg by launch site) and Molniya orbits (12 h, e ~ 0.72, i = 63.4 deg,
  perigee argument 270 deg).
"""
from __future__ import annotations

import math

import numpy as np

from . import tle

#: WGS-72 gravitational parameter (km^3/s^2) and equatorial radius (km), SGP4's constants.
MU_KM3_S2 = 398600.8
RE_KM = 6378.135
J2 = 0.001082616
#: mean motion of the Sun along the ecliptic, rad/s (360 deg per 365.2422 days)
SUN_RATE_RAD_S = 2.0 * math.pi / (365.2422 * 86400.0)

#: orbit class -> share of the catalogue
SHARES = {"LEO": 0.78, "HEO": 0.10, "GEO": 0.08, "MEO": 0.04}


def _mean_motion_rev_day(a_km):
    return np.sqrt(MU_KM3_S2 / a_km ** 3) * 86400.0 / (2.0 * math.pi)


def _sso_incl_deg(a_km):
    """Inclination whose J2 node drift follows the Sun (circular orbit)."""
    n = np.sqrt(MU_KM3_S2 / a_km ** 3)
    c = -SUN_RATE_RAD_S / (1.5 * n * J2 * (RE_KM / a_km) ** 2)
    return np.degrees(np.arccos(np.clip(c, -1.0, 1.0)))


def _leo(rng, k):
    kind = rng.choice(3, size=k, p=[0.45, 0.25, 0.30])
    alt = np.empty(k)
    inc = np.empty(k)
    ecc = np.empty(k)
    s = kind == 0  # constellation shells
    alt[s] = rng.normal(550.0, 8.0, s.sum())
    inc[s] = rng.choice([53.05, 43.0, 70.0, 97.6], size=s.sum(), p=[0.6, 0.2, 0.1, 0.1])
    ecc[s] = rng.uniform(0.0, 0.0005, s.sum())
    s = kind == 1  # sun-synchronous
    alt[s] = rng.uniform(450.0, 900.0, s.sum())
    ecc[s] = rng.uniform(0.0, 0.002, s.sum())
    inc[s] = _sso_incl_deg(RE_KM + alt[s])
    s = kind == 2  # debris band
    alt[s] = np.clip(rng.normal(850.0, 120.0, s.sum()), 400.0, 1500.0)
    inc[s] = rng.choice([98.6, 74.0, 82.9, 65.0, 86.4], size=s.sum()) + rng.normal(0, 0.5, s.sum())
    ecc[s] = rng.uniform(0.0, 0.02, s.sum())
    # perigee above 300 km: the SGP4 drag term must not decay the object within the week
    a = RE_KM + alt
    ecc = np.minimum(ecc, np.maximum(0.0, 1.0 - (RE_KM + 300.0) / a))
    bstar = 10.0 ** rng.uniform(-5.0, -3.7, k)
    return a, ecc, inc, rng.uniform(0, 360, k), bstar


def _meo(rng, k):
    sysk = rng.choice(4, size=k, p=[0.35, 0.25, 0.2, 0.2])
    a = np.array([26560.0, 25508.0, 29600.0, 27906.0])[sysk] + rng.normal(0, 20.0, k)
    inc = np.array([55.0, 64.8, 56.0, 55.0])[sysk] + rng.normal(0, 0.5, k)
    return a, rng.uniform(0.0, 0.01, k), inc, rng.uniform(0, 360, k), np.zeros(k)


def _geo(rng, k):
    kept = rng.random(k) < 0.5
    inc = np.where(kept, rng.uniform(0.0, 0.1, k), rng.uniform(0.0, 15.0, k))
    a = 42164.0 + np.where(kept, rng.normal(0, 2.0, k), rng.normal(0, 150.0, k))
    return a, rng.uniform(0.0, 0.001, k), inc, rng.uniform(0, 360, k), np.zeros(k)


def _heo(rng, k):
    molniya = rng.random(k) < 0.3
    perigee = RE_KM + rng.uniform(250.0, 650.0, k)
    apogee = RE_KM + 35786.0 + rng.normal(0, 500.0, k)
    a = np.where(molniya, 26554.0 + rng.normal(0, 30.0, k), 0.5 * (perigee + apogee))
    ecc = np.where(molniya, rng.normal(0.72, 0.01, k), (apogee - perigee) / (apogee + perigee))
    inc = np.where(molniya, 63.4 + rng.normal(0, 0.3, k),
                   rng.choice([6.0, 28.5, 20.0], size=k) + rng.normal(0, 0.5, k))
    argp = np.where(molniya, 270.0 + rng.normal(0, 2.0, k), rng.uniform(0, 360, k))
    return a, ecc, inc, argp, np.zeros(k)


_CLASSES = {"LEO": _leo, "MEO": _meo, "GEO": _geo, "HEO": _heo}


def generate(count: int, seed: int = 0, epoch_year: int = 2026,
             epoch_day: float = 335.0) -> list[tle.ElementSet]:
    """count element sets (catalogue numbers 1..count), classes by SHARES.

    epoch_year, epoch_day: the element epoch of every set (day of year with
    fraction, 1.0 = 1 January 0h UTC); propagate near it (SGP4 degrades by
    kilometres per day from the epoch).
    """
    if not 1 <= count <= 99999:
        raise tle.CatalogueError(f"count {count}: 1 to 99999 (five-digit catalogue numbers)")
    rng = np.random.default_rng(seed)
    names = list(SHARES)
    cls = rng.choice(len(names), size=count, p=[SHARES[c] for c in names])
    out: list[tle.ElementSet | None] = [None] * count
    for ci, cname in enumerate(names):
        idx = np.nonzero(cls == ci)[0]
        if idx.size == 0:
            continue
        a, ecc, inc, argp, bstar = _CLASSES[cname](rng, idx.size)
        raan = rng.uniform(0, 360, idx.size)
        mo = rng.uniform(0, 360, idx.size)
        no = _mean_motion_rev_day(a)
        for j, i in enumerate(idx):
            out[i] = tle.format_set(f"SYN-{cname} {i + 1:05d}", int(i + 1), epoch_year,
                                    epoch_day, float(inc[j]), float(raan[j]), float(ecc[j]),
                                    float(argp[j]), float(mo[j]), float(no[j]),
                                    float(bstar[j]))
    return out  # type: ignore[return-value]


def main(argv=None) -> int:
    import argparse
    import sys
    p = argparse.ArgumentParser(
        prog="python -m orbillum.catalog.synthetic",
        description="Write a seeded synthetic 3LE catalogue (LEO/MEO/GEO/HEO mix).")
    p.add_argument("count", type=int, help="number of element sets (1..99999)")
    p.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    p.add_argument("--epoch", default="26335.0",
                   help="element epoch as YYDDD.DDDD (TLE style; default 26335.0, 2026-12-01)")
    p.add_argument("-o", "--output", default="-", help="output file (default standard output)")
    a = p.parse_args(argv)
    try:
        yy, day = int(a.epoch[:2]), float(a.epoch[2:])
        sets = generate(a.count, a.seed, 2000 + yy if yy < 57 else 1900 + yy, day)
    except (tle.CatalogueError, ValueError) as e:
        p.error(str(e))
    if a.output == "-":
        tle.write(sets, sys.stdout)
    else:
        with open(a.output, "w", encoding="utf-8") as f:
            tle.write(sets, f)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
