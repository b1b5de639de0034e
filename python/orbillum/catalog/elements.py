# SPDX-License-Identifier: MIT
"""Element sets from a file in any of the forms GP data is published in, and their checks.

Forms (told apart by the file's content, not its name):

- TLE / 3LE text (orbillum.catalog.tle);
- OMM (CCSDS 502.0-B-3, Orbit Data Messages) as CelesTrak's and Space-Track's
  GP interfaces write it: JSON (a list of objects, or one), XML (``<ndm>`` of
  ``<omm>`` segments, read with the standard library's expat) and CSV (a header
  line of field names). Fields, by CelesTrak's names: OBJECT_NAME, OBJECT_ID,
  EPOCH, MEAN_MOTION, ECCENTRICITY, INCLINATION, RA_OF_ASC_NODE,
  ARG_OF_PERICENTER, MEAN_ANOMALY, EPHEMERIS_TYPE, CLASSIFICATION_TYPE,
  NORAD_CAT_ID, ELEMENT_SET_NO, REV_AT_EPOCH, BSTAR, MEAN_MOTION_DOT,
  MEAN_MOTION_DDOT. Catalogue numbers of up to 9 digits (no TLE holds them).

Every set is checked, the first error named by file and line: text (no binary
data; non-ASCII only in a name), numbers where numbers are due, the ranges of
tle.mean_elements_errors, SGP4 elements only (EPHEMERIS_TYPE 0, MEAN_ELEMENT_THEORY
SGP4 when given). The distance of the element epochs from the plan's epochs is
checked by check_epochs: a warning past EPOCH_WARN_DAYS, and rows past
EPOCH_LIMIT_DAYS are ERR_SGP4 (orbillum.catalog.block).
"""
from __future__ import annotations

import csv
import datetime as dt
import io
import json
import re
import warnings
import xml.parsers.expat

import numpy as np

from .tle import CatalogueError, ElementSet, MeanElements, decode_text, mean_elements_errors
from . import tle

#: beyond this many days between an element epoch and a planned epoch: a warning (the
#: SGP4 error of a TLE grows with the time from its epoch; the examples/scenarios limit)
EPOCH_WARN_DAYS = 14.0
#: beyond this many days: the rows are ERR_SGP4 (not propagated); the module's choice
EPOCH_LIMIT_DAYS = 30.0

#: the largest catalogue number (9 digits)
MAX_CATNR = 999_999_999

REQUIRED = ("EPOCH", "MEAN_MOTION", "ECCENTRICITY", "INCLINATION", "RA_OF_ASC_NODE",
            "ARG_OF_PERICENTER", "MEAN_ANOMALY", "NORAD_CAT_ID")
OPTIONAL_NUMBERS = ("BSTAR", "MEAN_MOTION_DOT", "MEAN_MOTION_DDOT")
FIELDS = ("OBJECT_NAME", "OBJECT_ID", "EPOCH", "MEAN_MOTION", "ECCENTRICITY", "INCLINATION",
          "RA_OF_ASC_NODE", "ARG_OF_PERICENTER", "MEAN_ANOMALY", "EPHEMERIS_TYPE",
          "CLASSIFICATION_TYPE", "NORAD_CAT_ID", "ELEMENT_SET_NO", "REV_AT_EPOCH", "BSTAR",
          "MEAN_MOTION_DOT", "MEAN_MOTION_DDOT")

_NUMBER = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")
_INTEGER = re.compile(r"[+-]?\d+")
_EPOCH = re.compile(r"(\d{4})-(\d\d)-(\d\d)[T ](\d\d):(\d\d):(\d\d)(\.\d+)?Z?")
_DAY0 = dt.date(1949, 12, 31).toordinal()


def _number(rec, key, where, integer=False):
    v = rec.get(key)
    if isinstance(v, bool) or v is None:
        raise CatalogueError(f"{where}: {key} is missing" if v is None
                             else f"{where}: {key} is not a number ({v!r})")
    if isinstance(v, (int, float)) and not integer:
        return float(v)
    if isinstance(v, int):
        return v
    text = str(v).strip()
    if not (_INTEGER if integer else _NUMBER).fullmatch(text):
        raise CatalogueError(f"{where}: {key} {v!r} is not {'an integer' if integer else 'a number'}")
    return int(text) if integer else float(text)


def epoch_days(text, where) -> float:
    """Days from 1949 December 31 0h UTC of an OMM EPOCH (ISO 8601 UTC, as the GP
    interfaces write it: 2026-12-07T12:34:56.123456)."""
    m = _EPOCH.fullmatch(str(text).strip()) if isinstance(text, str) else None
    if m is None:
        raise CatalogueError(f"{where}: EPOCH {text!r} is not an ISO 8601 UTC time "
                             "(YYYY-MM-DDTHH:MM:SS.ffffff)")
    y, mo, d, h, mi, s = (int(m.group(i)) for i in range(1, 7))
    try:
        day = dt.date(y, mo, d).toordinal() - _DAY0
    except ValueError as e:
        raise CatalogueError(f"{where}: EPOCH {text!r}: {e}") from None
    if h > 23 or mi > 59 or s > 60:
        raise CatalogueError(f"{where}: EPOCH {text!r}: no such time of day")
    if y < 1957:
        raise CatalogueError(f"{where}: EPOCH {text!r} is before 1957")
    frac = m.group(7) or ".0"
    sec = h * 3600 + mi * 60 + s + int(frac[1:]) / 10 ** (len(frac) - 1)
    return day + sec / 86400.0


def from_omm(rec: dict, where: str) -> ElementSet:
    """An element set of one OMM record (a dict of field names to values, strings or
    numbers); CatalogueError naming where for a missing field, a value that is not a
    number, elements out of range or elements that are not SGP4's."""
    if not isinstance(rec, dict):
        raise CatalogueError(f"{where}: expected an object of OMM fields, got "
                             f"{type(rec).__name__}")
    for k, v in rec.items():
        if k not in ("OBJECT_NAME",) and isinstance(v, str) and not v.isascii():
            raise CatalogueError(f"{where}: {k} {v!r} holds a non-ASCII character")
    missing = [k for k in REQUIRED if rec.get(k) in (None, "")]
    if missing:
        raise CatalogueError(f"{where}: missing OMM field(s) {', '.join(missing)}")
    theory = rec.get("MEAN_ELEMENT_THEORY")
    if theory not in (None, "") and str(theory).strip().upper() != "SGP4":
        raise CatalogueError(f"{where}: MEAN_ELEMENT_THEORY {theory!r}: only SGP4 elements "
                             "are planned")
    if rec.get("EPHEMERIS_TYPE") not in (None, ""):
        et = _number(rec, "EPHEMERIS_TYPE", where, integer=True)
        if et != 0:
            raise CatalogueError(f"{where}: EPHEMERIS_TYPE {et}: only SGP4 elements (type 0) "
                                 "are planned (type 4 is SGP4-XP)")
    num = _number(rec, "NORAD_CAT_ID", where, integer=True)
    if not 0 < num <= MAX_CATNR:
        raise CatalogueError(f"{where}: NORAD_CAT_ID {num} is outside 1-{MAX_CATNR}")
    vals = {k: _number(rec, k, where) for k in REQUIRED if k not in ("EPOCH", "NORAD_CAT_ID")}
    for k in OPTIONAL_NUMBERS:
        vals[k] = 0.0 if rec.get(k) in (None, "") else _number(rec, k, where)
    mean = MeanElements(epoch_days=epoch_days(rec["EPOCH"], where),
                        mean_motion=vals["MEAN_MOTION"], ecc=vals["ECCENTRICITY"],
                        incl_deg=vals["INCLINATION"], raan_deg=vals["RA_OF_ASC_NODE"],
                        argp_deg=vals["ARG_OF_PERICENTER"], mo_deg=vals["MEAN_ANOMALY"],
                        bstar=vals["BSTAR"], ndot=vals["MEAN_MOTION_DOT"],
                        nddot=vals["MEAN_MOTION_DDOT"])
    bad = mean_elements_errors(mean.incl_deg, mean.raan_deg, mean.ecc, mean.argp_deg,
                               mean.mo_deg, mean.mean_motion, mean.bstar, mean.ndot, mean.nddot)
    if bad:
        raise CatalogueError(f"{where}: " + "; ".join(bad))
    name = rec.get("OBJECT_NAME")
    name = str(name).strip() if name not in (None, "") else f"NORAD {num}"
    return ElementSet(name, mean=mean, catnr=num, source=where)


def _line_of(text: str, at: int) -> int:
    return text.count("\n", 0, at) + 1


def _reject_constant(name):
    raise ValueError(f"{name} is not a number an OMM holds")


def parse_json(text: str, source: str) -> list[ElementSet]:
    """A JSON list of OMM objects (or one object), each named by the line it starts on."""
    dec = json.JSONDecoder(parse_constant=_reject_constant)
    i = len(text) - len(text.lstrip())
    out = []

    def one(at):
        try:
            obj, end = dec.raw_decode(text, at)
        except ValueError as e:
            line = getattr(e, "lineno", _line_of(text, at))
            msg = getattr(e, "msg", str(e))
            raise CatalogueError(f"{source}:{line}: bad JSON: {msg}") from None
        where = f"{source}:{_line_of(text, at)}"
        out.append(from_omm(obj, f"{where} (record {len(out) + 1})"))
        return end

    if text.startswith("{", i):
        i = one(i)
    elif text.startswith("[", i):
        i += 1
        first = True
        while True:
            while i < len(text) and text[i] in " \t\r\n":
                i += 1
            if text.startswith("]", i):
                i += 1
                break
            if not first:
                if not text.startswith(",", i):
                    raise CatalogueError(f"{source}:{_line_of(text, i)}: bad JSON: expected "
                                         "',' or ']' between records")
                i += 1
                while i < len(text) and text[i] in " \t\r\n":
                    i += 1
            if i >= len(text):
                raise CatalogueError(f"{source}:{_line_of(text, i)}: bad JSON: the list is "
                                     "not closed")
            i = one(i)
            first = False
    else:
        raise CatalogueError(f"{source}:{_line_of(text, i)}: bad JSON: expected a list of OMM "
                             "objects")
    if text[i:].strip():
        raise CatalogueError(f"{source}:{_line_of(text, i)}: bad JSON: text after the records")
    return out


def parse_xml(text: str, source: str) -> list[ElementSet]:
    """An OMM XML document (CCSDS NDM/XML: <segment> of <metadata> and <data>, whose
    leaves are the fields), each set named by the line of its <segment>."""
    p = xml.parsers.expat.ParserCreate()
    out, stack = [], []
    state = {"rec": None, "line": 0, "text": []}

    def local(tag):
        return tag.rsplit(":", 1)[-1]

    def start(tag, _attrs):
        tag = local(tag)
        stack.append(tag)
        if tag == "segment":
            state["rec"], state["line"] = {}, p.CurrentLineNumber
        state["text"] = []

    def end(tag):
        tag = local(tag)
        stack.pop()
        rec = state["rec"]
        if tag == "segment" and rec is not None:
            where = f"{source}:{state['line']} (segment {len(out) + 1})"
            out.append(from_omm(rec, where))
            state["rec"] = None
        elif rec is not None and tag in FIELDS + ("MEAN_ELEMENT_THEORY",):
            rec[tag] = "".join(state["text"]).strip()
        state["text"] = []

    p.StartElementHandler = start
    p.EndElementHandler = end
    p.CharacterDataHandler = lambda d: state["text"].append(d)
    try:
        p.Parse(text, True)
    except xml.parsers.expat.ExpatError as e:
        raise CatalogueError(f"{source}:{e.lineno}: bad XML: "
                             f"{xml.parsers.expat.ErrorString(e.code)}") from None
    return out


def parse_csv(text: str, source: str) -> list[ElementSet]:
    """OMM CSV: a header line of field names, then one record a line."""
    r = csv.DictReader(io.StringIO(text, newline=""))
    head = r.fieldnames or []
    missing = [k for k in REQUIRED if k not in head]
    if missing:
        raise CatalogueError(f"{source}:1: the CSV header has no {', '.join(missing)}")
    out = []
    try:
        for rec in r:
            if None in rec:
                raise CatalogueError(f"{source}:{r.line_num}: more fields than the header")
            if not any(v for v in rec.values()):
                continue
            out.append(from_omm(rec, f"{source}:{r.line_num}"))
    except csv.Error as e:
        raise CatalogueError(f"{source}:{r.line_num}: bad CSV: {e}") from None
    return out


def detect(text: str) -> str:
    """'json', 'xml', 'csv' or 'tle' from a text's first characters."""
    head = text.lstrip()
    if head.startswith(("[", "{")):
        return "json"
    if head.startswith("<"):
        return "xml"
    first = head.split("\n", 1)[0]
    if "," in first and ("NORAD_CAT_ID" in first or "OBJECT_NAME" in first):
        return "csv"
    return "tle"


def parse(data: bytes | str, source: str) -> list[ElementSet]:
    """The element sets of a file's bytes (or text) in any form (detect)."""
    if isinstance(data, bytes):
        text = decode_text(data, source)
    else:
        text = data
    kind = detect(text)
    if kind == "tle":
        if isinstance(data, bytes):
            decode_text(data, source, ascii_only=True)
        elif not text.isascii():
            decode_text(text.encode("utf-8"), source, ascii_only=True)
        return tle.parse(text, source)
    return {"json": parse_json, "xml": parse_xml, "csv": parse_csv}[kind](text, source)


def read(path: str) -> list[ElementSet]:
    """The element sets of a TLE/3LE or OMM (JSON, XML, CSV) file; CatalogueError when
    it cannot be read, holds no set, or a set is malformed (file and line named)."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise CatalogueError(f"{path}: cannot read ({e.strerror})") from e
    sets = parse(data, path)
    if not sets:
        raise CatalogueError(f"{path}: no element set found")
    return sets


class EpochWarning(UserWarning):
    """Element epochs far from the planned epochs."""


def check_epochs(sets, jd1, jd2, warn_days=EPOCH_WARN_DAYS, limit_days=EPOCH_LIMIT_DAYS) -> int:
    """Warn (EpochWarning) of element sets farther than warn_days from a planned epoch
    (UTC Julian dates jd1 + jd2); their rows farther than limit_days are ERR_SGP4
    (block.run). Returns how many sets are past warn_days."""
    from . import block, sky
    if not warn_days >= 0 or not limit_days >= 0:
        raise CatalogueError("the epoch limits must be >= 0 days")
    ends = np.array([0, len(jd1) - 1])
    d = block.epoch_distance_days(sky.satrecs(sets), np.asarray(jd1)[ends],
                                  np.asarray(jd2)[ends]).max(axis=1)
    far = np.nonzero(d > warn_days)[0]
    if far.size:
        worst = int(far[np.argmax(d[far])])
        past = int(np.count_nonzero(d > limit_days))
        warnings.warn(
            f"{far.size} of {len(sets)} element set(s) are more than {warn_days:g} days from "
            f"a planned epoch (the farthest: {sets[worst].where}, {d[worst]:.1f} days); "
            f"rows more than {limit_days:g} days from their element epoch are "
            f"{block.STATUS_SGP4}" + (f" ({past} set(s) have such rows)" if past else ""),
            EpochWarning, stacklevel=2)
    return int(far.size)
