# SPDX-License-Identifier: MIT
"""test_stack_guard.py: `make stack`'s regression guard (tools/stack_report.py
guards): a guarded public call past the limit fails, a core-scoped entry is
held on its core's configurations only, an unguarded call is not held."""
from __future__ import annotations

import importlib.util
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location("stack_report", ROOT / "tools" / "stack_report.py")
stack_report = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(stack_report)

CFGS = ["m4f-Os", "m4f-O2", "m7-Os", "m7-O2"]
# worst / bounded-argument bytes per (configuration, function), made up
SUMMARY = {
    ("m4f-Os", "oi_a"): (100, 100), ("m4f-O2", "oi_a"): (96, 96),
    ("m7-Os", "oi_a"): (200, 200), ("m7-O2", "oi_a"): (512, 512),
    ("m4f-Os", "oi_b"): (500, 500), ("m4f-O2", "oi_b"): (512, 512),
    ("m7-Os", "oi_b"): (700, 700), ("m7-O2", "oi_b"): (690, 690),
}


def test_guard_holds_at_the_limit():
    n, broken = stack_report.guards("oi_a oi_b@m4f", CFGS, SUMMARY, 512)
    assert n == 6
    assert broken == []


def test_guard_breaks_past_the_limit():
    n, broken = stack_report.guards("oi_a oi_b", CFGS, SUMMARY, 512)
    assert n == 8
    assert broken == ["m7-Os.oi_b 700", "m7-O2.oi_b 690"]


def test_core_scoped_guard_and_lower_limit():
    n, broken = stack_report.guards("oi_b@m4f", CFGS, SUMMARY, 511)
    assert n == 2
    assert broken == ["m4f-O2.oi_b 512"]


def test_guarded_function_missing_is_broken():
    _, broken = stack_report.guards("oi_c@m7", CFGS, SUMMARY, 512)
    assert broken == ["m7-Os.oi_c missing", "m7-O2.oi_c missing"]
