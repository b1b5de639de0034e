# SPDX-License-Identifier: MIT
"""The viewer (build/viewer/) in headless Chromium, driven by Playwright (make test-viewer).

The page loads from a loopback HTTP server and from disk with no console error; for a set of
rows of each shipped case the numbers it shows are the doubles `build/oi-plan --csv` prints for
the same rows (also with a source switched off, against oi-plan given the same terms, and with
a manual exposure); the time slider and a source toggle change what is drawn.

Environment: CHROMIUM (the browser, default /usr/bin/chromium), VIEWER_DIR (build/viewer),
PLAN (build/oi-plan).
"""
from __future__ import annotations

import csv
import functools
import http.server
import io
import os
import subprocess
import threading
from pathlib import Path

import pytest
from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parents[2]
VIEWER = Path(os.environ.get("VIEWER_DIR", ROOT / "build" / "viewer")).resolve()
PLAN = Path(os.environ.get("PLAN", ROOT / "build" / "oi-plan")).resolve()
CHROMIUM = os.environ.get("CHROMIUM", "/usr/bin/chromium")
GOLDEN = ROOT / "tests" / "golden"
CASES = sorted(p.name[: -len(".in.csv")] for p in GOLDEN.glob("*.in.csv"))
# WebGL in a headless browser without a GPU: ANGLE over SwiftShader
ARGS = ["--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist"]
NUMERIC = ["sun_fraction", "sun_fraction_atm", "e_sun", "e_earth", "e_moon", "earth_theta_deg",
           "earth_h_km", "flux_obs", "mag_v", "exposure_s", "gain", "snr"]


@pytest.fixture(scope="module")
def server():
    handler = functools.partial(http.server.SimpleHTTPRequestHandler, directory=str(VIEWER))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    httpd.RequestHandlerClass.log_message = lambda *a: None
    t = threading.Thread(target=httpd.serve_forever, daemon=True)
    t.start()
    yield f"http://127.0.0.1:{httpd.server_address[1]}/index.html"
    httpd.shutdown()


@pytest.fixture(scope="module")
def browser():
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        yield b
        b.close()


class Page:
    """A page with its console errors collected."""

    def __init__(self, browser, url):
        self.errors = []
        self.page = browser.new_page(viewport={"width": 1400, "height": 900})
        self.page.on("console", lambda m: self.errors.append(m.text) if m.type == "error" else None)
        self.page.on("pageerror", lambda e: self.errors.append(str(e)))
        self.page.goto(url)
        self.wait_ready(0)

    def ready(self) -> int:
        return int(self.page.evaluate("Number(document.body.dataset.ready || 0)"))

    def wait_ready(self, before: int):
        self.page.wait_for_function(f"Number(document.body.dataset.ready || 0) > {before}",
                                    timeout=30000)

    def numbers(self) -> dict:
        return self.page.evaluate(
            "Object.fromEntries([...document.querySelectorAll('#numbers td')]"
            ".map(td => [td.dataset.key, td.dataset.value]))")

    def act(self, js: str):
        """Run js (which changes a control) and wait for the page to redraw."""
        before = self.ready()
        self.page.evaluate(js)
        self.wait_ready(before)

    def canvas(self, cid: str) -> bytes:
        return self.page.locator(f"#{cid}").screenshot()

    def close(self):
        self.page.close()


def slide(i: int) -> str:
    """JavaScript that moves the time slider to row i as a user's drag does (an input event)."""
    return ("(() => { const s = document.getElementById('time'); "
            f"s.value = '{i}'; s.dispatchEvent(new Event('input')); }})()")


def choose(cid: str, value: str) -> str:
    """JavaScript that sets a select and sends its change event."""
    return ("(() => { const e = document.getElementById('" + cid + "'); "
            f"e.value = '{value}'; e.dispatchEvent(new Event('change')); }})()")


# glibc's generic libm: the one whose last bits the wasm build's libm shares (make test-wasm
# checks both libms); with the default one a steep penumbra row's atmosphere lookup can differ by
# ~1e-14 relative (docs/atmosphere.md), and this test compares the doubles exactly.
GENERIC_LIBM = {**os.environ, "GLIBC_TUNABLES": "glibc.cpu.hwcaps=-AVX2,-FMA"}


def plan(input_text: str) -> list[dict]:
    out = subprocess.run([str(PLAN), "--csv", "-"], input=input_text, capture_output=True,
                         text=True, check=False, env=GENERIC_LIBM)
    assert out.returncode in (0, 1), out.stderr
    return list(csv.DictReader(io.StringIO(out.stdout)))


def case_rows(name: str) -> list[dict]:
    return plan((GOLDEN / f"{name}.in.csv").read_text())


def pick(rows: list[dict]) -> list[int]:
    """First, middle, last row, and the first row of each distinct flag set (eclipse, penumbra...)."""
    idx = {0, len(rows) // 2, len(rows) - 1}
    seen = set()
    for i, r in enumerate(rows):
        if r["flags"] not in seen:
            seen.add(r["flags"])
            idx.add(i)
    return sorted(idx)


def assert_same(shown: dict, want: dict, where: str):
    assert shown["status"] == want["status"], where
    assert shown["flags"] == want["flags"], where
    for k in NUMERIC:
        if want[k] == "":
            assert shown[k] == "", f"{where} {k}: the planner leaves it empty"
        else:
            # the page shows the double itself (data-value: JavaScript's shortest round trip)
            assert float(shown[k]) == float(want[k]), f"{where} {k}: {shown[k]} vs {want[k]}"


def test_loads_without_console_error_over_http_and_from_disk(browser, server):
    for url in (server, (VIEWER / "index.html").as_uri()):
        p = Page(browser, url)
        assert p.errors == [], f"{url}: {p.errors}"
        assert p.page.evaluate("!!document.querySelector('#scene').getContext") is True
        n = p.numbers()
        assert n["status"] == "OK" and float(n["e_sun"]) > 1000
        p.close()


@pytest.mark.parametrize("name", CASES)
def test_numbers_equal_oi_plan(browser, server, name):
    rows = case_rows(name)
    p = Page(browser, f"{server}?dataset={name}")
    checked = 0
    for i in pick(rows):
        p.act(slide(i))
        assert_same(p.numbers(), rows[i], f"{name} row {i + 1}")
        checked += 1
    assert p.errors == []
    assert checked >= 3
    p.close()


def test_time_slider_and_source_toggle_change_the_view(browser, server):
    name = "leo-leo-pass"
    rows = case_rows(name)
    p = Page(browser, f"{server}?dataset={name}&row=100")
    n0, scene0, fc0 = p.numbers(), p.canvas("scene"), p.canvas("fc")
    label0 = p.page.text_content("#time-label")
    p.act(slide(180))
    n1, scene1 = p.numbers(), p.canvas("scene")
    assert p.page.text_content("#time-label") != label0
    assert n1["e_earth"] != n0["e_earth"]
    assert scene1 != scene0, "the scene view did not change with the time slider"
    assert_same(n1, rows[180], f"{name} row 181")
    fc1 = p.canvas("fc")
    assert fc1 != fc0
    # the Sun off: the numbers are oi-plan's with terms=earth+moon on the same row
    p.act("(() => { const c = document.getElementById('src-sun'); c.checked = false;"
          " c.dispatchEvent(new Event('change')); })()")
    n2 = p.numbers()
    assert float(n2["e_sun"]) == 0.0
    assert p.canvas("fc") != fc1, "the per-source view did not change with the Sun switched off"
    text = (GOLDEN / f"{name}.in.csv").read_text().splitlines()
    one = f"{text[0]},terms\n{text[181]},earth+moon\n"
    assert_same(n2, plan(one)[0], f"{name} row 181 without the Sun")
    assert p.errors == []
    p.close()


def test_manual_exposure_uses_the_camera_step(browser, server):
    p = Page(browser, f"{server}?dataset=leo-inspector&row=10")
    steps = p.page.evaluate("[...document.querySelectorAll('#exposure option')].map(o => o.value)")
    assert steps[0] == "" and len(steps) >= 3
    k = steps[2]
    p.act(choose("exposure", k))
    cam = p.page.evaluate("window.orbillumViewer.last.cam.times_s")
    assert float(p.numbers()["exposure_s"]) == cam[int(k)]
    assert p.errors == []
    p.close()


def test_facet_shape_changes_the_picture_not_the_numbers(browser, server):
    p = Page(browser, f"{server}?dataset=geo-inspector-eclipse&row=0")
    shapes = p.page.evaluate("[...document.querySelectorAll('#shape option')].map(o => o.value)")
    assert shapes[0] == "sphere" and "boxwing" in shapes
    n0, hdr0 = p.numbers(), p.canvas("hdr")
    p.act(choose("shape", "boxwing"))
    assert p.numbers() == n0, "the runtime's numbers are the sphere's whatever the picture's shape"
    assert p.canvas("hdr") != hdr0
    assert "facet model boxwing" in p.page.text_content("#view-note")
    assert p.errors == []
    p.close()


def test_a_planner_csv_given_to_the_page(browser, server, tmp_path):
    """A user's CSV (here the GEO case's first 40 rows with an albedo changed) through the file
    input, the path a dropped file takes too: its rows are the planner's."""
    lines = (GOLDEN / "geo-inspector-eclipse.in.csv").read_text().splitlines()[:41]
    head = lines[0].split(",")
    k = head.index("target_albedo")
    body = []
    for line in lines[1:]:
        f = line.split(",")
        f[k] = "0.35"
        body.append(",".join(f))
    text = "\n".join([lines[0]] + body) + "\n"
    path = tmp_path / "mine.csv"
    path.write_text(text)
    rows = plan(text)
    p = Page(browser, server)
    before = p.ready()
    p.page.set_input_files("#file", str(path))
    p.wait_ready(before)
    assert "mine.csv" in p.page.evaluate("document.getElementById('dataset').selectedOptions[0].textContent")
    assert int(p.page.get_attribute("#time", "max")) == len(rows) - 1
    for i in (0, 17, len(rows) - 1):
        p.act(slide(i))
        assert_same(p.numbers(), rows[i], f"mine.csv row {i + 1}")
    assert p.errors == []
    p.close()
