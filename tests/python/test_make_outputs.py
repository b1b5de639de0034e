# SPDX-License-Identifier: MIT
"""`make report` and `make gallery` write under build/ only; the committed docs change only through
`make report-docs` / `make gallery-docs`. Checked on the commands make would run (make -n), so the
test is cheap and fails as soon as a recipe writes into docs/ again."""
from __future__ import annotations

import re
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def _recipe(target: str) -> list[str]:
    """The commands of `target` itself (prerequisites assumed up to date)."""
    out = subprocess.run(["make", "-n", "-W", "Makefile", "--no-print-directory", "-o", "all",
                          "-o", "binding", "-o", "deps-py", target],
                         cwd=ROOT, capture_output=True, text=True, check=True).stdout
    return [line for line in out.splitlines() if "examples.render.gallery" in line
            or "bake.report" in line]


def _out_arg(line: str) -> str:
    m = re.search(r"--out\s+(\S+)", line)
    assert m, f"no --out in: {line}"
    return m.group(1)


@pytest.mark.parametrize("target", ["report", "gallery"])
def test_target_writes_to_build(target):
    lines = _recipe(target)
    assert lines, f"make -n {target} runs no report/gallery command"
    for line in lines:
        out = _out_arg(line)
        assert out.startswith("build/"), f"make {target} writes to {out}"
        assert "docs" not in line.split(), line


@pytest.mark.parametrize("target,where", [("report-docs", "docs/report.md"),
                                          ("gallery-docs", "docs/gallery")])
def test_docs_target_refreshes_docs(target, where):
    lines = _recipe(target)
    assert lines and all(_out_arg(line) == where for line in lines), lines


def test_default_out_of_the_report_module_is_build():
    src = (ROOT / "bake/report/__main__.py").read_text()
    assert 'default="build/report/report.md"' in src
