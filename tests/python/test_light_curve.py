# SPDX-License-Identifier: MIT
"""The light-curve example (examples/render/light_curve.py, `make light-curve`):
it runs on a shipped pass, its sphere curve is the planner's mag_v for the same
rows digit for digit, its tumbling shape's curve is the planner's on the rows
it writes (target_shape, q_w..q_z), and its attitudes spin as stated (checked
against a rotation written here)."""
import csv
import io
import math
import os
import subprocess
import sys

import numpy as np
import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
PLAN = os.path.join(ROOT, "build", "oi-plan")
sys.path.insert(0, ROOT)
orbillum = pytest.importorskip("orbillum", reason="binding not installed: make binding")
LC = pytest.importorskip("examples.render.light_curve")


def planner(path):
    if not os.path.exists(PLAN):
        pytest.fail(f"{PLAN} is missing: run `make all` first")
    run = subprocess.run([PLAN, "--csv", str(path)], capture_output=True, text=True, timeout=120)
    assert run.returncode in (0, 1), run.stderr
    return list(csv.DictReader(io.StringIO(run.stdout)))


def g17(x):
    x = float(x)
    return "%.17g" % (0.0 if x == 0.0 else x)


def test_spin_quaternions_turn_about_the_axis():
    axis = np.array([1.0, 2.0, 3.0]) / math.sqrt(14.0)
    q = LC.spin_quaternions(np.array([0.0, 45.0, 90.0]), 2.0, (1, 2, 3))
    assert np.allclose(np.linalg.norm(q, axis=1), 1.0, atol=1e-15)
    assert np.allclose(q[0], [1, 0, 0, 0])
    # 90 s at 2 deg/s: a 180 deg turn about the axis: w = 0, vector part = the axis
    assert np.allclose(q[2], [0.0, *axis], atol=1e-15)
    w, x, y, z = q[1]
    angle = 2 * math.degrees(math.acos(w))
    assert abs(angle - 90.0) < 1e-12 and np.allclose(np.array([x, y, z]) / math.sin(
        math.radians(45.0)), axis)
    with pytest.raises(ValueError, match="--axis"):
        LC.spin_quaternions(np.zeros(2), 1.0, (0, 0, 0))


def test_light_curve_runs_and_matches_the_planner(tmp_path):
    out = tmp_path / "lc"
    assert LC.main(["--case", "leo-leo-pass", "--out", str(out), "--plan", PLAN]) == 0
    png = (out / "leo-leo-pass-light-curve.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 10000
    curve = list(csv.DictReader(open(out / "leo-leo-pass-light-curve.csv", encoding="utf-8")))
    assert len(curve) == 289
    # the sphere curve is the planner's mag_v on the case's own rows (no shape columns)
    sphere_rows = planner(out / "leo-leo-pass.csv")
    head = (out / "leo-leo-pass.csv").read_text().splitlines()[0].split(",")
    assert "target_shape" not in head and "q_w" not in head
    assert [r["mag_v"] for r in sphere_rows] == [g17(c["mag_sphere"]) for c in curve]
    # the shape's curve is the planner's on the tumbling rows it wrote
    shaped_rows = planner(out / "leo-leo-pass-tumbling.csv")
    assert [r["mag_v"] for r in shaped_rows] == [g17(c["mag_shape"]) for c in curve]
    assert [r["flags"] for r in shaped_rows] == [c["flags_shape"] for c in curve]
    tumbling = list(csv.DictReader(open(out / "leo-leo-pass-tumbling.csv", encoding="utf-8")))
    assert {r["target_shape"] for r in tumbling} == {"box-wing"}
    # the pictures' reader of a planner input (examples/render/common.py) takes the shape and
    # attitude columns as the planner does
    from examples.render.common import read_csv, scene_inputs
    kw = scene_inputs(read_csv(str(out / "leo-leo-pass-tumbling.csv")))
    x = orbillum.expose("telescope-15cm", **kw)
    assert [r["mag_v"] for r in shaped_rows] == [g17(m) for m in x["mag_v"]]
    # the view draws no facet shape without its geometry (an OBJ model)
    from examples.render import view
    assert view.main([str(out / "leo-leo-pass-tumbling.csv"), "--row", "150",
                      "-o", str(tmp_path / "v.png")]) == 2
    assert view.main([str(out / "leo-leo-pass-tumbling.csv"), "--row", "150", "--obj",
                      os.path.join(ROOT, "examples", "render", "models", "boxwing.obj"),
                      "-o", str(tmp_path / "v.png")]) == 0
    # a tumbling box-wing is not a sphere: its curve moves by magnitudes where the
    # sphere's changes slowly
    ms = np.array([float(c["mag_sphere"]) for c in curve])
    mb = np.array([float(c["mag_shape"]) for c in curve])
    seen = (ms < 99) & (mb < 99)
    assert seen.sum() > 100
    assert np.ptp(mb[seen] - ms[seen]) > 1.0
    assert np.max(np.abs(np.diff(ms[seen]))) < 0.5


def test_light_curve_user_errors(tmp_path):
    assert LC.main(["--shape", "sphere", "--out", str(tmp_path)]) == 2
    assert LC.main(["--shape", "cube", "--out", str(tmp_path)]) == 2
    assert LC.main(["--case", "no-such-case", "--out", str(tmp_path)]) == 2
