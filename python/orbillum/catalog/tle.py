# SPDX-License-Identifier: MIT
"""Two-line element sets as text: read a 3LE/2LE catalogue file, write element sets.

The format is NORAD's (Hoots & Roehrich, Spacetrack Report No. 3, 1980;
CelesTrak's "NORAD Two-Line Element Set Format"): line 1 and line 2 of 69
columns, column 69 a modulo-10 checksum (digits, '-' counts 1); a 3LE adds a
name line before line 1 (CelesTrak writes it as "0 NAME").

Every set read is checked (check_lines): the text is ASCII, both lines have a
checksum digit in column 69 that matches, every numeric field is a number in
its columns, and the elements are in range (mean_elements_errors). An element
set can also hold the mean elements themselves (MeanElements, from an OMM:
orbillum.catalog.elements), with catalogue numbers of up to 9 digits.

This module needs the standard library only (examples/scenarios loads it by path).
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

from sgp4.io import compute_checksum


class CatalogueError(ValueError):
    """An input the catalogue planner cannot use; the message says where and what."""


@dataclass(frozen=True)
class MeanElements:
    """SGP4 mean elements as an OMM gives them (CCSDS 502.0-B; CelesTrak's GP fields)."""
    epoch_days: float       # days from 1949 December 31 0h UTC (sgp4init's epoch)
    mean_motion: float      # rev/day (Kozai, as a TLE's)
    ecc: float
    incl_deg: float
    raan_deg: float
    argp_deg: float
    mo_deg: float
    bstar: float = 0.0      # 1/earth radii
    ndot: float = 0.0       # MEAN_MOTION_DOT, rev/day^2 (a TLE's first-derivative field)
    nddot: float = 0.0      # MEAN_MOTION_DDOT, rev/day^3

    @property
    def epoch_jd(self) -> float:
        return _JD_1950 + self.epoch_days


@dataclass(frozen=True)
class ElementSet:
    name: str
    line1: str = ""
    line2: str = ""
    mean: MeanElements | None = None   # the elements themselves (an OMM), when no TLE lines
    catnr: int | None = None           # the catalogue number of a set without TLE lines
    source: str = field(default="", compare=False)  # file:line of the set, for messages

    def key(self):
        """What the set's rows depend on (a JSON-able list)."""
        return [self.name, self.line1, self.line2, self.catnr,
                None if self.mean is None else list(vars(self.mean).values())]

    @property
    def where(self) -> str:
        return f"{self.source}: {self.name}" if self.source else self.name

    @property
    def number(self) -> int:
        """The catalogue number (columns 3-7; Alpha-5 letters read as sgp4 does)."""
        if self.catnr is not None:
            return self.catnr
        s = self.line1[2:7].strip()
        if s and s[0].isalpha():  # Alpha-5: A=10 ... Z=33, skipping I and O
            head = "ABCDEFGHJKLMNPQRSTUVWXYZ".index(s[0].upper()) + 10
            return head * 10000 + int(s[1:])
        return int(s)


def checksum(line: str) -> int:
    """The modulo-10 checksum of a TLE line's first 68 columns (sgp4's own)."""
    return compute_checksum(line)


def _looks_like_line1(line: str) -> bool:
    """A '1 ' line that is meant as a TLE's line 1 (not a name that starts so)."""
    return len(line) >= 64 or (len(line) > 20 and line[2:7].strip().isdigit())


def parse(text: str, source: str = "<text>") -> list[ElementSet]:
    """Every element set of a 3LE or 2LE text ('#' lines and blank lines skipped;
    a line before a line 1 is the set's name).

    Raises CatalogueError naming source:line for a line 1 without its line 2, a
    line 2 without line 1, lines shorter than 64 columns, catalogue numbers that
    differ between the lines or a wrong checksum. A short '1 ' line that does
    not look like a line 1 (20 columns or fewer, or no number in columns 3-7)
    and has no line 2 after it is a name.
    """
    lines = text.splitlines()
    out: list[ElementSet] = []
    name = ""
    i = 0
    while i < len(lines):
        line = lines[i].rstrip()
        lineno = i + 1
        i += 1
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        if line.startswith("1 ") and i < len(lines) and lines[i].startswith("2 "):
            l1, l2 = line[:69], lines[i].rstrip()[:69]
            i += 1
            for k, n, ln in ((lineno, 1, l1), (lineno + 1, 2, l2)):
                if len(ln) < 64:
                    raise CatalogueError(f"{source}:{k}: TLE line {n} is too short "
                                         f"({len(ln)} characters, expected 69)")
            if l1[2:7] != l2[2:7]:
                raise CatalogueError(f"{source}:{lineno}: catalogue numbers differ between "
                                     f"line 1 ({l1[2:7]!r}) and line 2 ({l2[2:7]!r})")
            check_lines(l1, l2, source, lineno)
            out.append(ElementSet(name or f"NORAD {l1[2:7].strip()}", l1, l2,
                                  source=f"{source}:{lineno}"))
            name = ""
        elif line.startswith("1 ") and len(line) >= 64:
            raise CatalogueError(f"{source}:{lineno + 1}: expected TLE line 2 (starting '2 ') "
                                 f"after line 1: line {lineno} is a TLE line 1 without a line 2 "
                                 "after it")
        elif line.startswith("1 ") and _looks_like_line1(line):
            raise CatalogueError(f"{source}:{lineno}: looks like a TLE line 1 but is too short "
                                 f"({len(line)} characters, expected 69) and has no line 2")
        elif line.startswith("2 "):
            raise CatalogueError(f"{source}:{lineno}: TLE line 2 without a line 1 before it")
        else:
            name = line.strip()
            if name.startswith("0 "):
                name = name[2:].strip()
    return out


def read(path: str) -> list[ElementSet]:
    """parse() of a file; CatalogueError when it cannot be read, is not ASCII text
    (binary data or a non-ASCII character, named by line and column) or holds no set."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise CatalogueError(f"{path}: cannot read TLE file ({e.strerror})") from e
    text = decode_text(data, path, ascii_only=True)
    sets = parse(text, path)
    if not sets:
        raise CatalogueError(f"{path}: no two-line element set found")
    return sets


def _where(data: bytes, at: int) -> tuple[int, int]:
    """1-based (line, column) of byte offset at."""
    line = data.count(b"\n", 0, at) + 1
    return line, at - (data.rfind(b"\n", 0, at) + 1) + 1


def decode_text(data: bytes, source: str, ascii_only: bool = False) -> str:
    """UTF-8 text of a file's bytes (a leading BOM dropped); CatalogueError naming the
    line and column of a NUL or an invalid byte (binary data) or, with ascii_only,
    of the first non-ASCII character."""
    if data.startswith(b"\xef\xbb\xbf"):
        data = data[3:]
    nul = data.find(b"\0")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as e:
        at = e.start if nul < 0 else min(e.start, nul)
        line, col = _where(data, at)
        raise CatalogueError(f"{source}:{line}:{col}: binary data (byte 0x{data[at]:02x}): "
                             "not a text file of element sets") from None
    if nul >= 0:
        line, col = _where(data, nul)
        raise CatalogueError(f"{source}:{line}:{col}: binary data (byte 0x00): "
                             "not a text file of element sets")
    if ascii_only and not text.isascii():
        at = next(i for i, c in enumerate(text) if ord(c) > 127)
        line = text.count("\n", 0, at) + 1
        col = at - (text.rfind("\n", 0, at) + 1) + 1
        raise CatalogueError(f"{source}:{line}:{col}: non-ASCII character {text[at]!r} "
                             f"(U+{ord(text[at]):04X}): a TLE file is ASCII")
    return text


#: the columns (1-based, inclusive) and names of the numeric fields of TLE lines
_L1_FIELDS = ((19, 20, "epoch year", r"\d\d"), (21, 32, "epoch day", r" *\d{1,3}\.\d*"),
              (34, 43, "first derivative of the mean motion", r" *[+-]?\d*\.\d+"),
              (45, 52, "second derivative of the mean motion", r" *[+-]?\d{1,5} ?[+-]?\d"),
              (54, 61, "BSTAR", r" *[+-]?\d{1,5} ?[+-]?\d"))
_L2_FIELDS = ((9, 16, "inclination", r" *\d+(\.\d*)?"), (18, 25, "right ascension of the node",
                                                         r" *\d+(\.\d*)?"),
              (27, 33, "eccentricity", r" *\d+"), (35, 42, "argument of perigee",
                                                   r" *\d+(\.\d*)?"),
              (44, 51, "mean anomaly", r" *\d+(\.\d*)?"),
              (53, 63, "mean motion", r" *\d+(\.\d*)?"))


def _assumed_decimal(f: str) -> float:
    """A TLE 'assumed decimal point' field: ' 12345-3' is 0.12345e-3."""
    f = f.replace(" ", "")
    sign = -1.0 if f.startswith("-") else 1.0
    f = f.lstrip("+-")
    return sign * float("0." + f[:-2]) * 10.0 ** int(f[-2:])


def mean_elements_errors(incl_deg, raan_deg, ecc, argp_deg, mo_deg, mean_motion, bstar=0.0,
                         ndot=0.0, nddot=0.0) -> list[str]:
    """What is out of range in a set of mean elements (an empty list when nothing is):
    inclination 0-180 deg, node, perigee and mean anomaly 0-360 deg, eccentricity in
    [0, 1), mean motion > 0 rev/day, every value finite."""
    bad = []
    vals = dict(inclination=incl_deg, raan=raan_deg, eccentricity=ecc, argp=argp_deg,
                mean_anomaly=mo_deg, mean_motion=mean_motion, bstar=bstar, ndot=ndot,
                nddot=nddot)
    for k, v in vals.items():
        if not math.isfinite(v):
            bad.append(f"{k} {v} is not finite")
    if bad:
        return bad
    if not 0.0 <= incl_deg <= 180.0:
        bad.append(f"inclination {incl_deg:g} deg is outside 0-180")
    for k, v in (("right ascension of the node", raan_deg), ("argument of perigee", argp_deg),
                 ("mean anomaly", mo_deg)):
        if not 0.0 <= v <= 360.0:
            bad.append(f"{k} {v:g} deg is outside 0-360")
    if not 0.0 <= ecc < 1.0:
        bad.append(f"eccentricity {ecc:g} is outside [0, 1)")
    if not mean_motion > 0.0:
        bad.append(f"mean motion {mean_motion:g} rev/day is not > 0")
    return bad


def check_lines(l1: str, l2: str, source: str, lineno: int) -> None:
    """CatalogueError naming source:line for a TLE pair that is not well formed: a
    column 69 that is not a digit (blank included) or not the checksum, a numeric
    field that is not a number in its columns, elements out of range."""
    for k, n, ln in ((lineno, 1, l1), (lineno + 1, 2, l2)):
        if len(ln) < 69 or not ln[68].isdigit():
            got = "blank" if len(ln) < 69 or ln[68] == " " else repr(ln[68])
            raise CatalogueError(f"{source}:{k}: TLE line {n}: column 69 is {got}, not the "
                                 "checksum digit")
        if checksum(ln) != int(ln[68]):
            raise CatalogueError(f"{source}:{k}: TLE checksum (column 69) is wrong: "
                                 f"{ln[68]}, the line's is {checksum(ln)}")
    vals = {}
    for k, n, ln, fields in ((lineno, 1, l1, _L1_FIELDS), (lineno + 1, 2, l2, _L2_FIELDS)):
        for a, b, what, pat in fields:
            f = ln[a - 1:b]
            if not re.fullmatch(pat + " *", f):
                raise CatalogueError(f"{source}:{k}: TLE line {n}, columns {a}-{b} ({what}): "
                                     f"{f!r} is not a number")
            vals[what] = f
    day = float(vals["epoch day"])
    if not 1.0 <= day < 367.0:
        raise CatalogueError(f"{source}:{lineno}: epoch day {day:g} is outside 1-366")
    bad = mean_elements_errors(
        float(vals["inclination"]), float(vals["right ascension of the node"]),
        float("0." + vals["eccentricity"].strip()), float(vals["argument of perigee"]),
        float(vals["mean anomaly"]), float(vals["mean motion"]),
        _assumed_decimal(vals["BSTAR"]), float(vals["first derivative of the mean motion"]),
        _assumed_decimal(vals["second derivative of the mean motion"]))
    if bad:
        raise CatalogueError(f"{source}:{lineno + 1}: " + "; ".join(bad))


def _exp_field(x: float) -> str:
    """An 8-column TLE 'assumed decimal point' field: ' 12345-3' means 0.12345e-3."""
    if x == 0.0:
        return " 00000-0"
    sign = "-" if x < 0 else " "
    m = abs(x)
    e = math.floor(math.log10(m)) + 1
    mant = round(m / 10.0 ** e * 1e5)
    if mant >= 100000:  # rounding carried into the next power of ten
        mant //= 10
        e += 1
    if not -9 <= e <= 9:
        raise CatalogueError(f"{x!r} does not fit a TLE exponent field")
    return f"{sign}{mant:05d}{'-' if e < 0 else '+'}{abs(e)}"


def format_set(name: str, number: int, epoch_year: int, epoch_day: float, incl_deg: float,
               raan_deg: float, ecc: float, argp_deg: float, mo_deg: float,
               no_rev_day: float, bstar: float = 0.0) -> ElementSet:
    """An element set with checksums from mean elements (first derivative of the
    mean motion and its second derivative written as 0; SGP4 does not use them).
    epoch_day: day of year with fraction (1.0 is 1 January 0h UTC)."""
    if not 0 <= number <= 99999:
        raise CatalogueError(f"catalogue number {number} does not fit 5 digits")
    if not 0.0 <= ecc < 1.0:
        raise CatalogueError(f"eccentricity {ecc} is outside [0, 1)")
    yy = epoch_year % 100
    l1 = (f"1 {number:05d}U 00000A   {yy:02d}{epoch_day:012.8f}  .00000000  00000-0 "
          f"{_exp_field(bstar)} 0  999")
    ecc_digits = min(int(round(ecc * 1e7)), 9999999)
    l2 = (f"2 {number:05d} {incl_deg % 180.0 if incl_deg != 180.0 else 180.0:8.4f} "
          f"{raan_deg % 360.0:8.4f} {ecc_digits:07d} {argp_deg % 360.0:8.4f} "
          f"{mo_deg % 360.0:8.4f} {no_rev_day:11.8f}    1")
    l1 += str(checksum(l1))
    l2 += str(checksum(l2))
    assert len(l1) == 69 and len(l2) == 69, (l1, l2)
    return ElementSet(name, l1, l2)


def write(sets, out) -> None:
    """Write element sets as a 3LE text ('0 NAME' line, line 1, line 2)."""
    for s in sets:
        out.write(f"0 {s.name}\n{s.line1}\n{s.line2}\n")


#: Julian date of 1949 December 31 0h UTC, the origin of SGP4's epoch days
_JD_1950 = 2433281.5
#: WGS-72 gravitational parameter (km^3/s^2), SGP4's
_MU_WGS72 = 398600.8


def from_elements(el: dict, number: int, label: str = "elements") -> ElementSet:
    """An element set from SGP4 (Kozai) mean elements, written to the TLE's digits.

    el: ``name`` (optional), ``epoch`` (ISO UTC), ``a_km`` or ``no_rev_day``,
    ``ecc``, ``incl_deg``, ``raan_deg``, ``argp_deg``, ``mo_deg``, optional
    ``bstar`` (0). From ``a_km`` the mean motion is the two-body sqrt(mu/a^3)
    with WGS-72 mu. The TLE keeps 4 decimals of each angle (~10 m in LEO) and 8
    of the mean motion.
    """
    from astropy.time import Time
    if not isinstance(el, dict):
        raise CatalogueError(f"{label}: expected an object of elements, got {type(el).__name__}")
    unknown = set(el) - {"name", "epoch", "a_km", "no_rev_day", "ecc", "incl_deg", "raan_deg",
                         "argp_deg", "mo_deg", "bstar"}
    if unknown:
        raise CatalogueError(f"{label}: unknown key(s) {', '.join(sorted(unknown))}")
    for k in ("epoch", "ecc", "incl_deg", "raan_deg", "argp_deg", "mo_deg"):
        if k not in el:
            raise CatalogueError(f"{label}: missing {k!r}")
    try:
        t = Time(el["epoch"], scale="utc")
    except ValueError as e:
        raise CatalogueError(f"{label}: bad epoch {el['epoch']!r} (ISO 8601 UTC)") from e
    try:
        vals = {k: float(el[k]) for k in el if k not in ("name", "epoch")}
    except (TypeError, ValueError) as e:
        raise CatalogueError(f"{label}: elements must be numbers ({e})") from e
    if "no_rev_day" in vals:
        no = vals["no_rev_day"]
    elif "a_km" in vals:
        if not vals["a_km"] > 6378.135:
            raise CatalogueError(f"{label}: a_km = {vals['a_km']} is inside the Earth")
        no = math.sqrt(_MU_WGS72 / vals["a_km"] ** 3) * 86400.0 / (2.0 * math.pi)
    else:
        raise CatalogueError(f"{label}: give 'a_km' or 'no_rev_day'")
    year = int(t.utc.datetime.year)
    day = t.utc.jd - Time(f"{year}-01-01T00:00:00", scale="utc").jd + 1.0
    return format_set(str(el.get("name", label)), number, year, day, vals["incl_deg"],
                      vals["raan_deg"], vals["ecc"], vals["argp_deg"], vals["mo_deg"], no,
                      vals.get("bstar", 0.0))
