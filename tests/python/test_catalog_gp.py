# SPDX-License-Identifier: MIT
"""Today's elements from the GP interfaces (orbillum.catalog.gp), against a local HTTP
server (http.server in a thread) that serves recorded responses (tests/data/gp/):
CelesTrak by group and by catalogue number, Space-Track with its login, the cache
and its fetch time, a stale cache warned of and then refused, a response without
element sets refused, and the command line planning a group."""
import datetime as dt
import http.server
import json
import subprocess
import sys
import threading
import urllib.parse
from pathlib import Path

import pyarrow.parquet as pq
import pytest

from orbillum.catalog import gp, tle

GP = Path(__file__).resolve().parents[2] / "tests" / "data" / "gp"


class _Handler(http.server.BaseHTTPRequestHandler):
    requests = []

    def log_message(self, *a):
        pass

    def _send(self, code, body, headers=()):
        self.send_response(code)
        for k, v in headers:
            self.send_header(k, v)
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        self.wfile.write(body)

    def do_GET(self):
        _Handler.requests.append(self.path)
        u = urllib.parse.urlsplit(self.path)
        q = dict(urllib.parse.parse_qsl(u.query))
        if u.path == "/NORAD/elements/gp.php":
            fmt = q.get("FORMAT", "json")
            if q.get("GROUP") == "synthetic" and fmt == "json":
                return self._send(200, (GP / "synthetic-group.json").read_bytes())
            if q.get("CATNR") == "25544" and fmt in ("json", "xml", "csv", "3le"):
                return self._send(200, (GP / f"iss-2008.{fmt}").read_bytes())
            return self._send(200, (GP / "no-data.txt").read_bytes())
        if u.path.startswith("/basicspacedata/query/class/gp/NORAD_CAT_ID/25544/"):
            if "chocolatechip=session" not in (self.headers.get("Cookie") or ""):
                return self._send(401, b"not logged in")
            return self._send(200, (GP / "iss-2008.json").read_bytes())
        self._send(404, b"no such page")

    def do_POST(self):
        _Handler.requests.append(self.path)
        n = int(self.headers.get("Content-Length", 0))
        form = dict(urllib.parse.parse_qsl(self.rfile.read(n).decode()))
        if self.path == "/ajaxauth/login" and form == {"identity": "me", "password": "pw"}:
            return self._send(200, b'""', [("Set-Cookie", "chocolatechip=session; Path=/")])
        self._send(200, b'{"Login":"Failed"}')


@pytest.fixture()
def server():
    srv = http.server.ThreadingHTTPServer(("127.0.0.1", 0), _Handler)
    th = threading.Thread(target=srv.serve_forever, daemon=True)
    th.start()
    _Handler.requests = []
    yield f"http://127.0.0.1:{srv.server_address[1]}"
    srv.shutdown()
    srv.server_close()


def test_celestrak_group_is_fetched_once_and_cached(server, tmp_path):
    base = server + "/NORAD/elements/gp.php"
    sets = gp.query(group="synthetic", base=base, cache=str(tmp_path))
    assert [s.number for s in sets] == [270000001, 270000002, 270000003]
    assert _Handler.requests == ["/NORAD/elements/gp.php?GROUP=synthetic&FORMAT=json"]
    url = gp.celestrak_url(group="synthetic", base=base)
    body, fetched = gp.cached(url, str(tmp_path))
    assert body == (GP / "synthetic-group.json").read_bytes()
    assert abs((dt.datetime.now(dt.timezone.utc) - fetched).total_seconds()) < 600
    # younger than REFRESH_HOURS: no second request
    assert gp.query(group="synthetic", base=base, cache=str(tmp_path)) == sets
    assert len(_Handler.requests) == 1
    # older: asked again
    _age(tmp_path, hours=3)
    gp.query(group="synthetic", base=base, cache=str(tmp_path))
    assert len(_Handler.requests) == 2


def _age(cache, hours):
    for meta in Path(cache).glob("*.json"):
        m = json.loads(meta.read_text())
        when = dt.datetime.now(dt.timezone.utc) - dt.timedelta(hours=hours)
        m["fetched_utc"] = when.isoformat(timespec="seconds")
        meta.write_text(json.dumps(m))


@pytest.mark.parametrize("fmt", ["json", "xml", "csv", "3le"])
def test_celestrak_by_catalogue_number_in_every_form(server, tmp_path, fmt):
    (s,) = gp.query(catnrs=[25544], fmt=fmt, base=server + "/NORAD/elements/gp.php",
                    cache=str(tmp_path))
    assert (s.number, s.name) == (25544, "ISS (ZARYA)")


def test_stale_cache_is_warned_of_then_refused(server, tmp_path):
    base = server + "/NORAD/elements/gp.php"
    gp.query(group="synthetic", base=base, cache=str(tmp_path))
    _age(tmp_path, hours=24 * (gp.WARN_DAYS + 1))
    # no network (offline, or the server gone): the cached response, with a warning
    with pytest.warns(gp.StaleWarning, match="days old"):
        assert len(gp.query(group="synthetic", base=base, cache=str(tmp_path),
                            offline=True)) == 3
    dead = "http://127.0.0.1:9/NORAD/elements/gp.php"
    with pytest.raises(tle.CatalogueError, match="no response is cached"):
        gp.query(group="synthetic", base=dead, cache=str(tmp_path), timeout_s=2)
    _age(tmp_path, hours=24 * (gp.REFUSE_DAYS + 1))
    with pytest.raises(tle.CatalogueError, match="refused"):
        gp.query(group="synthetic", base=base, cache=str(tmp_path), offline=True)


def test_a_response_without_element_sets_is_refused_and_not_cached(server, tmp_path):
    with pytest.raises(tle.CatalogueError, match="No GP data found"):
        gp.query(group="no-such-group", base=server + "/NORAD/elements/gp.php",
                 cache=str(tmp_path))
    assert not list(tmp_path.iterdir())


def test_spacetrack_logs_in_with_the_users_account(server, tmp_path, monkeypatch):
    monkeypatch.setenv("SPACETRACK_IDENTITY", "me")
    monkeypatch.setenv("SPACETRACK_PASSWORD", "pw")
    (s,) = gp.query(catnrs=[25544], source="spacetrack", base=server, cache=str(tmp_path))
    assert s.number == 25544
    assert _Handler.requests[0] == "/ajaxauth/login"
    monkeypatch.setenv("SPACETRACK_PASSWORD", "wrong")
    with pytest.raises(tle.CatalogueError, match="login refused"):
        gp.query(catnrs=[25544], source="spacetrack", base=server, cache=str(tmp_path / "b"))


def test_command_line_plans_a_fetched_group(server, tmp_path):
    out = tmp_path / "plan.parquet"
    r = subprocess.run(
        [sys.executable, "-m", "orbillum.catalog", "--gp-group", "synthetic",
         "--gp-url", server + "/NORAD/elements/gp.php", "--gp-cache", str(tmp_path / "cache"),
         "--observer-elements", "inspectors.json", "--start", "2026-12-01T00:00",
         "--stop", "2026-12-01T00:30", "--step", "300", "--all-rows", "-o", str(out)],
        capture_output=True, text=True, check=False, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    t = pq.read_table(out)
    assert t.num_rows == 3 * 2 * 7
    assert set(t["object"].to_pylist()) == {"SYNTHETIC LEO 1", "SYNTHETIC SSO 2",
                                            "SYNTHETIC GEO 3"}
