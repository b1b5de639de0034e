# SPDX-License-Identifier: MIT
"""Test-side helpers around the planner and the facet shapes: the oi-plan
binary (OI_PLAN or build/oi-plan) and its one runner, and the rotation of a
unit quaternion (the reference the shape tests turn facets with)."""
import os
import subprocess
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
PLAN = Path(os.environ.get("OI_PLAN", ROOT / "build" / "oi-plan"))


def run(args, stdin=None):
    """oi-plan with args (stdin bytes): (return code, stdout, stderr) as text."""
    assert PLAN.exists(), f"{PLAN} is not built (make all)"
    p = subprocess.run([str(PLAN)] + list(args), input=stdin, capture_output=True, timeout=60)
    return p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace")


def rotation(q):
    """Body -> input rotation matrix of the unit quaternion (w, x, y, z)."""
    w, x, y, z = np.asarray(q, float) / np.linalg.norm(q)
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
