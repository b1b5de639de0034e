# SPDX-License-Identifier: MIT
"""The planner's output on the shipped cases and the built-in scenario is unchanged byte for byte
(tests/golden/README.md): a regression lock for refactoring, beside the accuracy tests."""
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PLAN = Path(os.environ.get("OI_PLAN", ROOT / "build" / "oi-plan"))
GOLDEN = ROOT / "tests" / "golden"
CASES = sorted(p.name[: -len(".in.csv")] for p in GOLDEN.glob("*.in.csv"))


def first_difference(want: bytes, got: bytes) -> str:
    for n, (a, b) in enumerate(zip(want.splitlines(), got.splitlines()), 1):
        if a != b:
            return f"line {n}:\n  want {a.decode()}\n  got  {b.decode()}"
    return f"lengths differ: want {len(want)} bytes, got {len(got)}"


@pytest.mark.parametrize("case", CASES)
def test_shipped_case_unchanged(case):
    run = subprocess.run([str(PLAN), "--csv", str(GOLDEN / f"{case}.in.csv")],
                         capture_output=True, check=False)
    assert run.returncode in (0, 1), run.stderr.decode()
    want = (GOLDEN / f"{case}.plan.csv").read_bytes()
    assert run.stdout == want, first_difference(want, run.stdout)


def test_builtin_scenario_unchanged():
    run = subprocess.run([str(PLAN)], capture_output=True, check=True)
    want = (GOLDEN / "demo.txt").read_bytes()
    assert run.stdout == want, first_difference(want, run.stdout)


def test_cases_present():
    assert len(CASES) == 3, CASES
