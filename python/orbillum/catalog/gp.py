# SPDX-License-Identifier: MIT
"""Today's elements: GP data fetched from CelesTrak or Space-Track, cached on disk.

CelesTrak's GP interface (https://celestrak.org/NORAD/elements/gp.php, by
``GROUP=`` or ``CATNR=``, ``FORMAT=json|xml|csv|tle|3le``) needs no account;
Space-Track's (https://www.space-track.org, class ``gp`` by NORAD_CAT_ID) needs
the user's account, given in SPACETRACK_IDENTITY and SPACETRACK_PASSWORD. Only
when asked (``--gp-group``, ``--gp-catnr``) does the planner go to the network.

Every response is checked (orbillum.catalog.elements) before it is kept, then
kept in the cache directory (ORBILLUM_GP_CACHE, else $XDG_CACHE_HOME/orbillum/gp,
else ~/.cache/orbillum/gp) with its URL and fetch time (``<key>.json`` beside
the body). A response younger than REFRESH_HOURS is used without a request
(CelesTrak updates GP data every few hours and asks for no more frequent
downloads). Without a network (or with offline=True) the cached response is
used: with a warning when older than WARN_DAYS, refused when older than
REFUSE_DAYS.
"""
from __future__ import annotations

import datetime as dt
import hashlib
import http.cookiejar
import json
import os
import urllib.error
import urllib.parse
import urllib.request
import warnings

from . import elements
from .tle import CatalogueError

CELESTRAK_URL = "https://celestrak.org/NORAD/elements/gp.php"
SPACETRACK_URL = "https://www.space-track.org"
FORMATS = ("json", "xml", "csv", "tle", "3le")

#: a cached response younger than this is used without asking again (hours)
REFRESH_HOURS = 2.0
#: an older cached response, used when no fetch is possible, is warned of (days)
WARN_DAYS = 1.0
#: a cached response older than this is refused (days)
REFUSE_DAYS = 7.0
#: seconds to wait for the server
TIMEOUT_S = 30.0


class StaleWarning(UserWarning):
    """A cached GP response older than WARN_DAYS was used."""


def cache_dir() -> str:
    d = os.environ.get("ORBILLUM_GP_CACHE")
    if d:
        return d
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(base, "orbillum", "gp")


def celestrak_url(group=None, catnr=None, fmt="json", base=None) -> str:
    if (group is None) == (catnr is None):
        raise CatalogueError("give a GP group or a catalogue number (one of them)")
    q = {"GROUP": group} if group is not None else {"CATNR": str(int(catnr))}
    q["FORMAT"] = fmt
    return (base or CELESTRAK_URL) + "?" + urllib.parse.urlencode(q)


def spacetrack_url(catnrs, fmt="json", base=None) -> str:
    ids = ",".join(str(int(n)) for n in catnrs)
    return (f"{(base or SPACETRACK_URL).rstrip('/')}/basicspacedata/query/class/gp/"
            f"NORAD_CAT_ID/{ids}/orderby/NORAD_CAT_ID/format/{fmt}")


def _now():
    return dt.datetime.now(dt.timezone.utc)


def _paths(url, cache):
    key = hashlib.sha256(url.encode()).hexdigest()[:20]
    return os.path.join(cache, key + ".body"), os.path.join(cache, key + ".json")


def _atomic_write(path, data: bytes):
    tmp = f"{path}.tmp-{os.getpid()}"
    with open(tmp, "wb") as f:
        f.write(data)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def cached(url, cache=None):
    """(body bytes, fetch time) of the cached response of url, or None."""
    body_p, meta_p = _paths(url, cache or cache_dir())
    try:
        with open(meta_p, encoding="utf-8") as f:
            meta = json.load(f)
        with open(body_p, "rb") as f:
            body = f.read()
        fetched = dt.datetime.fromisoformat(meta["fetched_utc"])
    except (OSError, ValueError, KeyError, TypeError):
        return None
    if meta.get("url") != url or hashlib.sha256(body).hexdigest() != meta.get("sha256"):
        return None
    if fetched.tzinfo is None:
        fetched = fetched.replace(tzinfo=dt.timezone.utc)
    return body, fetched


def _store(url, body, cache):
    os.makedirs(cache, exist_ok=True)
    body_p, meta_p = _paths(url, cache)
    _atomic_write(body_p, body)
    meta = {"url": url, "fetched_utc": _now().isoformat(timespec="seconds"),
            "bytes": len(body), "sha256": hashlib.sha256(body).hexdigest()}
    _atomic_write(meta_p, (json.dumps(meta, indent=1) + "\n").encode())


def _opener(spacetrack_base=None, timeout_s=TIMEOUT_S):
    """A urllib opener; for Space-Track, logged in with the user's account."""
    jar = http.cookiejar.CookieJar()
    op = urllib.request.build_opener(urllib.request.HTTPCookieProcessor(jar))
    op.addheaders = [("User-Agent", "orbillum-catalog (python urllib)")]
    if spacetrack_base is not None:
        ident = os.environ.get("SPACETRACK_IDENTITY")
        pw = os.environ.get("SPACETRACK_PASSWORD")
        if not ident or not pw:
            raise CatalogueError("Space-Track needs an account: set SPACETRACK_IDENTITY and "
                                 "SPACETRACK_PASSWORD")
        data = urllib.parse.urlencode({"identity": ident, "password": pw}).encode()
        with op.open(spacetrack_base.rstrip("/") + "/ajaxauth/login", data=data,
                     timeout=timeout_s) as r:
            r.read()
        if not any(True for _ in jar):
            raise CatalogueError("Space-Track login refused (no session cookie)")
    return op


def _age_days(fetched, now):
    return (now - fetched).total_seconds() / 86400.0


def fetch(url, *, cache=None, offline=False, spacetrack_base=None, timeout_s=TIMEOUT_S,
          refresh_hours=REFRESH_HOURS, warn_days=WARN_DAYS, refuse_days=REFUSE_DAYS):
    """(element sets, body bytes, fetch time) of a GP query URL, from the cache or
    the network (module docstring). CatalogueError when neither gives usable data."""
    cache = cache or cache_dir()
    now = _now()
    entry = cached(url, cache)
    if entry is not None and _age_days(entry[1], now) * 24.0 < refresh_hours:
        return elements.parse(entry[0], url), entry[0], entry[1]
    why = "offline"
    if not offline:
        try:
            op = _opener(spacetrack_base, timeout_s)
            with op.open(url, timeout=timeout_s) as r:
                body = r.read()
        except urllib.error.HTTPError as e:
            why = f"HTTP {e.code} {e.reason}"
        except (urllib.error.URLError, OSError) as e:
            why = str(getattr(e, "reason", e))
        else:
            text = body[:200].decode("utf-8", "replace").strip().splitlines()
            head = repr(text[0][:80]) if text else "empty"
            try:
                sets = elements.parse(body, url)
            except CatalogueError as e:
                raise CatalogueError(f"{url}: the response ({head}) is not GP data: "
                                     f"{e}") from None
            if not sets:
                raise CatalogueError(f"{url}: the response holds no element sets ({head})")
            _store(url, body, cache)
            return sets, body, cached(url, cache)[1]
    if entry is None:
        raise CatalogueError(f"cannot fetch {url} ({why}) and no response is cached in {cache}")
    age = _age_days(entry[1], now)
    if age > refuse_days:
        raise CatalogueError(f"cannot fetch {url} ({why}); the cached response is {age:.1f} "
                             f"days old, more than {refuse_days:g}: refused (fetch it again "
                             "with a network)")
    if age > warn_days:
        warnings.warn(f"cannot fetch {url} ({why}): using the response cached "
                      f"{entry[1].isoformat(timespec='seconds')} ({age:.1f} days old)",
                      StaleWarning, stacklevel=2)
    return elements.parse(entry[0], url), entry[0], entry[1]


def query(*, group=None, catnrs=(), source="celestrak", fmt="json", base=None, cache=None,
          offline=False, timeout_s=TIMEOUT_S):
    """The element sets of a CelesTrak group, or of catalogue numbers (CelesTrak: one
    request each; Space-Track: one request), with fetch() for each URL."""
    if fmt not in FORMATS:
        raise CatalogueError(f"GP format {fmt!r}: one of {', '.join(FORMATS)}")
    if source == "celestrak":
        urls = ([celestrak_url(group=group, fmt=fmt, base=base)] if group is not None else
                [celestrak_url(catnr=n, fmt=fmt, base=base) for n in catnrs])
        st = None
    elif source == "spacetrack":
        if group is not None:
            raise CatalogueError("Space-Track has no groups: give catalogue numbers")
        urls = [spacetrack_url(catnrs, fmt, base)]
        st = base or SPACETRACK_URL
    else:
        raise CatalogueError(f"GP source {source!r}: celestrak or spacetrack")
    if not urls:
        raise CatalogueError("no GP query: give a group or catalogue numbers")
    out = []
    for u in urls:
        out += fetch(u, cache=cache, offline=offline, spacetrack_base=st, timeout_s=timeout_s)[0]
    return out


def main(argv=None) -> int:
    """python -m orbillum.catalog.gp: fetch (or take from the cache) and write a GP file."""
    import argparse
    import sys
    p = argparse.ArgumentParser(prog="python -m orbillum.catalog.gp",
                                description="Fetch GP elements (cached) and write them to a file")
    add_arguments(p)
    p.add_argument("-o", "--output", required=True, help="file to write the response to")
    a = p.parse_args(argv)
    try:
        urls = _urls_of(a)
        with open(a.output + ".tmp", "wb") as f:
            for u in urls:
                sets, body, when = fetch(u, cache=a.gp_cache, offline=a.gp_offline,
                                         spacetrack_base=(a.gp_url or SPACETRACK_URL)
                                         if a.gp_source == "spacetrack" else None)
                f.write(body)
                print(f"{u}: {len(sets)} element sets, fetched {when.isoformat()}",
                      file=sys.stderr)
        os.replace(a.output + ".tmp", a.output)
    except CatalogueError as e:
        print(f"orbillum.catalog.gp: {e}", file=sys.stderr)
        return 2
    return 0


def add_arguments(p):
    """The GP options of the command lines."""
    g = p.add_argument_group("today's elements (GP data from the network, cached)")
    g.add_argument("--gp-group", metavar="GROUP",
                   help="CelesTrak GP group, e.g. stations, active, starlink")
    g.add_argument("--gp-catnr", metavar="N[,N...]",
                   help="catalogue numbers (CelesTrak: one request each; Space-Track: one)")
    g.add_argument("--gp-source", choices=("celestrak", "spacetrack"), default="celestrak",
                   help="celestrak (default) or spacetrack (SPACETRACK_IDENTITY, "
                        "SPACETRACK_PASSWORD)")
    g.add_argument("--gp-format", choices=FORMATS, default="json",
                   help="the form asked for (default json, an OMM)")
    g.add_argument("--gp-cache", metavar="DIR", help=f"cache directory (default {cache_dir()})")
    g.add_argument("--gp-offline", action="store_true",
                   help=f"no network: the cached response (warned past {WARN_DAYS:g} day, "
                        f"refused past {REFUSE_DAYS:g} days)")
    g.add_argument("--gp-url", metavar="URL", default=os.environ.get("ORBILLUM_GP_URL"),
                   help="the GP interface's address (a mirror; default CelesTrak's gp.php or "
                        "Space-Track's site; environment ORBILLUM_GP_URL)")


def _catnrs(text):
    try:
        return [int(x) for x in text.split(",") if x.strip()]
    except ValueError:
        raise CatalogueError(f"--gp-catnr {text!r}: catalogue numbers separated by commas") \
            from None


def _urls_of(a):
    if (a.gp_group is None) == (a.gp_catnr is None):
        raise CatalogueError("give --gp-group GROUP or --gp-catnr N (one of them)")
    nums = _catnrs(a.gp_catnr) if a.gp_catnr is not None else []
    if a.gp_source == "spacetrack":
        if a.gp_group is not None:
            raise CatalogueError("Space-Track has no groups: give --gp-catnr")
        return [spacetrack_url(nums, a.gp_format, a.gp_url)]
    if a.gp_group is not None:
        return [celestrak_url(group=a.gp_group, fmt=a.gp_format, base=a.gp_url)]
    return [celestrak_url(catnr=n, fmt=a.gp_format, base=a.gp_url) for n in nums]


def from_arguments(a):
    """The element sets the GP options ask for, or None when they ask for none."""
    if a.gp_group is None and a.gp_catnr is None:
        return None
    return query(group=a.gp_group, catnrs=_catnrs(a.gp_catnr) if a.gp_catnr else (),
                 source=a.gp_source, fmt=a.gp_format, base=a.gp_url, cache=a.gp_cache,
                 offline=a.gp_offline)


if __name__ == "__main__":
    raise SystemExit(main())
