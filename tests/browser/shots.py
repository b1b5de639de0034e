# SPDX-License-Identifier: MIT
"""Three screenshots of the viewer for docs/viewer.md (make viewer-shots).

    python tests/browser/shots.py OUTDIR

1. the built-in scenario in sunlight, the scene around the Earth;
2. the GEO inspector case as the target enters the Earth's penumbra;
3. the LEO-LEO pass seen around the target, its camera's field on it, the Sun switched off
   (earthshine and moonlight only).
Environment: CHROMIUM (default /usr/bin/chromium), VIEWER_DIR (default build/viewer).
"""
from __future__ import annotations

import os
import sys
from pathlib import Path

from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parents[2]
VIEWER = Path(os.environ.get("VIEWER_DIR", ROOT / "build" / "viewer")).resolve()
CHROMIUM = os.environ.get("CHROMIUM", "/usr/bin/chromium")
ARGS = ["--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist"]


def settle(page, js: str | None = None):
    before = page.evaluate("Number(document.body.dataset.ready || 0)")
    if js:
        page.evaluate(js)
        page.wait_for_function(f"Number(document.body.dataset.ready || 0) > {before}")
    page.wait_for_timeout(300)


def main(out: str) -> int:
    outdir = Path(out)
    outdir.mkdir(parents=True, exist_ok=True)
    url = (VIEWER / "index.html").as_uri()
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        page = b.new_page(viewport={"width": 1400, "height": 860})
        errors = []
        page.on("pageerror", lambda e: errors.append(str(e)))

        page.goto(f"{url}?dataset=builtin&row=40")
        page.wait_for_function("Number(document.body.dataset.ready || 0) > 0")
        settle(page)
        page.screenshot(path=str(outdir / "builtin-sunlit.png"))

        page.goto(f"{url}?dataset=geo-inspector-eclipse")
        page.wait_for_function("Number(document.body.dataset.ready || 0) > 0")
        i = page.evaluate("window.orbillumViewer.rows.findIndex(r => r.planned && "
                          "/penumbra/.test(r.planned.flags || ''))")
        settle(page, "(() => { const s = document.getElementById('time'); "
                     f"s.value = '{max(i, 0)}'; s.dispatchEvent(new Event('input')); }})()")
        page.screenshot(path=str(outdir / "geo-penumbra.png"))

        page.goto(f"{url}?dataset=leo-leo-pass")
        page.wait_for_function("Number(document.body.dataset.ready || 0) > 0")
        page.select_option("#focus", "target")
        settle(page, "(() => { const c = document.getElementById('src-sun'); c.checked = false; "
                     "c.dispatchEvent(new Event('change')); })()")
        page.screenshot(path=str(outdir / "leo-leo-target-no-sun.png"))
        b.close()
    if errors:
        print("page errors:", errors, file=sys.stderr)
        return 1
    for f in sorted(outdir.glob("*.png")):
        print(f"{f}: {f.stat().st_size // 1024} KiB")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "docs/viewer"))
