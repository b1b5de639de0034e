# SPDX-License-Identifier: MIT
"""The catalogue planner as a user installs and meets it: the extras `catalog` and
`plots` pinned as requirements.lock pins them, the example files the docs use
shipped, a wrong --scheduler address one line and exit 2 within seconds, the
columns `flag_names` and `observable` (the rows of oi-plan --summary's windows,
counted by build/oi-plan itself), and the progress of the set-up."""
import importlib.metadata
import io
import json
import os
import re
import socket
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.csv as pa_csv
import pyarrow.parquet as pq

import orbillum
from orbillum.catalog import block, plan, synthetic, tle

ROOT = Path(__file__).resolve().parents[2]
PLAN = Path(os.environ.get("OI_PLAN", ROOT / "build" / "oi-plan"))
START, STOP = "2026-12-01T00:00:00", "2026-12-01T03:00:00"


def _lock():
    pins = {}
    for line in (ROOT / "requirements.lock").read_text().splitlines():
        name, found, ver = line.split("#", 1)[0].strip().partition("==")
        if found:
            pins[name.lower()] = ver
    return pins


def test_extras_pin_what_the_planner_imports():
    req = importlib.metadata.metadata("orbillum").get_all("Requires-Dist") or []
    extras = {}
    for r in req:
        m = re.fullmatch(r'([A-Za-z0-9_.-]+)==([^;]+); extra == "(\w+)"', r)
        if m:
            extras.setdefault(m.group(3), {})[m.group(1).lower()] = m.group(2)
    pins = _lock()
    assert set(extras) >= {"catalog", "plots"}
    for extra, pkgs in extras.items():
        for name, ver in pkgs.items():
            assert pins[name] == ver, (extra, name)
    # every third-party module the planner's code imports is in the catalog extra
    src = "\n".join(p.read_text() for p in (ROOT / "python" / "orbillum" / "catalog").glob("*.py"))
    imported = {a or b for a, b in re.findall(r"^\s*(?:from (\w+)[\w.]* import|import (\w+))",
                                              src, re.M)}
    third = imported - set(sys.stdlib_module_names) - {"orbillum", "numpy", "__future__"}
    assert third <= set(extras["catalog"]), third - set(extras["catalog"])
    assert "matplotlib" in extras["plots"]


def test_the_docs_example_files_ship_with_the_package():
    import orbillum.catalog
    data = Path(orbillum.catalog.__file__).parent / "data"
    obs = json.loads((data / "inspectors.json").read_text())
    assert [o["name"] for o in obs] == ["inspector-leo", "inspector-geo"]
    assert [tle.from_elements(o, 99000 + i).name for i, o in enumerate(obs)] == \
        ["inspector-leo", "inspector-geo"]
    docs = (ROOT / "docs" / "catalog.md").read_text()
    for name in re.findall(r"--observer-elements (\S+\.json)", docs):
        assert (data / name).exists(), name


def test_a_wrong_scheduler_address_is_one_line_and_exit_2(tmp_path):
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()  # nothing listens there now
    t0 = time.monotonic()
    r = subprocess.run([sys.executable, "-m", "orbillum.catalog", "--synthetic", "3",
                        "--observer-elements", "inspectors.json", "--start", START,
                        "--stop", STOP, "--scheduler", f"tcp://127.0.0.1:{port}",
                        "--scheduler-timeout", "2", "-o", str(tmp_path / "x.parquet")],
                       capture_output=True, text=True, check=False, cwd=tmp_path)
    wall = time.monotonic() - t0
    lines = [ln for ln in r.stderr.splitlines() if "shipped example" not in ln]
    assert r.returncode == 2, r.stderr
    assert len(lines) == 1 and "cannot reach the Dask scheduler" in lines[0], r.stderr
    assert f"tcp://127.0.0.1:{port}" in lines[0]
    assert wall < 60, wall  # the 2 s timeout and the start of Python (a shared machine)
    assert not list(tmp_path.iterdir())


OBSERVERS = [
    {"name": "inspector-leo", "epoch": "2026-12-01T00:00:00", "a_km": 6978.0, "ecc": 0.001,
     "incl_deg": 53.0, "raan_deg": 10.0, "argp_deg": 0.0, "mo_deg": 0.0},
    {"name": "inspector-geo", "epoch": "2026-12-01T00:00:00", "a_km": 42164.0, "ecc": 0.0,
     "incl_deg": 0.05, "raan_deg": 0.0, "argp_deg": 0.0, "mo_deg": 100.0},
]


def test_observable_is_the_planners_summary_rule_and_flag_names_the_flags(tmp_path):
    obs = [tle.from_elements(el, 99000 + i) for i, el in enumerate(OBSERVERS)]
    _, tables = plan.plan(synthetic.generate(60, seed=2), obs, START, STOP, 120.0,
                          all_rows=True, positions=True, keep=True, progress=False,
                          max_range_km=1e9)
    t = pa.concat_tables(tables)
    names = t.schema.names
    assert names[-2:] == ["observable", "flag_names"]  # added last: positions kept
    assert t["flag_names"].equals(t["flags"])
    d = t.to_pydict()
    obs_col = np.array(d["observable"])
    assert 0 < obs_col.sum() < t.num_rows
    assert not np.any(obs_col & ~np.array(d["visible"]))
    # build/oi-plan --summary counts its observable rows over the same scenes
    inp = pa.table([pa.array([str(i) for i in range(t.num_rows)])] +
                   [t[c] for c in block.POSITIONS], names=["id"] + list(block.POSITIONS))
    src = tmp_path / "in.csv"
    buf = io.BytesIO()
    pa_csv.write_csv(inp, buf, pa_csv.WriteOptions(quoting_style="none"))
    src.write_bytes(buf.getvalue())
    r = subprocess.run([str(PLAN), "--csv", str(src), "--camera", "telescope-15cm",
                        "--summary"], capture_output=True, text=True, check=False)
    assert r.returncode in (0, 1), r.stderr
    m = re.search(r"(\d+) of (\d+) rows observable", r.stderr)
    assert m and int(m.group(2)) == t.num_rows, r.stderr[-500:]
    assert int(m.group(1)) == int(obs_col.sum())
    # and row by row from the columns (planner/windows.c's rule)
    bad = (orbillum.OI_FLAG_ECLIPSED | orbillum.OI_FLAG_PENUMBRA | orbillum.OI_FLAG_SATURATED |
           orbillum.OI_FLAG_SUN_EXCLUSION | orbillum.OI_FLAG_OCCULTED)
    rule = (np.array([s.startswith(("OK", "WARN")) for s in d["status"]]) &
            ((np.array(d["flags_mask"]) & bad) == 0) & (np.array(d["snr"]) >= 5.0))
    assert np.array_equal(rule, obs_col)


def test_progress_of_the_set_up(tmp_path):
    r = subprocess.run([sys.executable, "-m", "orbillum.catalog", "--synthetic", "3",
                        "--observer-elements", "inspectors.json", "--start", START,
                        "--stop", STOP, "--progress", "-o", str(tmp_path / "x.parquet")],
                       capture_output=True, text=True, check=False, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert re.search(r"set-up: 100%.*5/5", r.stderr), r.stderr
    assert re.search(r"blocks: 100%", r.stderr)
    assert pq.read_table(tmp_path / "x.parquet").num_rows > 0
