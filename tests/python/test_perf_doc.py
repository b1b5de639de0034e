# SPDX-License-Identifier: MIT
"""docs/performance.md is a page of today's figures that `make perf-doc` writes (tools/perf_doc.py),
and its history is a dated log.

- tools/perf_doc.py --no-run on outputs written here: each block gets the lines its filter selects
  and the commit, a block whose run left no output stays as it was, text outside the blocks is
  kept, the goals table holds every goal line and the goals the runs decide (exit statuses, the
  binding's ratio in instructions), every cell at most ~300 characters.
- docs/performance.md has every block perf_doc.py writes, once; no table cell over 300 characters;
  the sections other files name by title, and every anchor of the page that a link names, exist.
- docs/log/performance-history.md: dated entries, newest first.
"""
import os
import re
import subprocess
import sys

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import perf_doc  # noqa: E402

DOC = os.path.join(ROOT, "docs", "performance.md")
LOG = os.path.join(ROOT, "docs", "log", "performance-history.md")
CELL_LIMIT = 300

OUTS = {
    "cross": ["built build/cross/m4f-Os/liborbillum.a", "", "# exit status 0"],
    "size": ["# cfg   full", "size.m4f-Os.full.lib.member.vector.o 164 bytes",
             "size.m7-Os.full.lib.member.vector.o 300 bytes",
             "goal.zero_data_bss met (every configuration and option set)", "# exit status 0"],
    "stack": ["# function  m4f-Os", "stack.m4f-Os.oi_angle 96 bytes  # oi_angle(96)",
              "stack.m4f-Os.oi_angle.bounded_args 96 bytes  # oi_angle(96)",
              "stack.m7-O2.oi_illuminate 1360 bytes  # oi_illuminate(128)",
              "goal.stack_at_most_512 missed (worst/bounded_args bytes: "
              + ", ".join("m7-O2.oi_f%d 900/900" % i for i in range(40)) + ")",
              "guard.stack_at_most_512 held (68 calls x configurations)", "# exit status 0"],
    "target-test": ["arm-none-eabi-gcc -c x.c", "passed 11088 failed 0 known 0", "target-test passed",
                    "# exit status 0"],
    "bench": ["bench.double.all.ns_median 548.2 ns", "bench.double.all.ns_min 500.0 ns",
              "bench.double.all_batch_observer.instructions 8181 instructions  # callgrind",
              "bench.double.all_baseline.instructions 4946 instructions",
              "bench.quadrature.matched_accuracy.order 12 nodes",
              "profile.double.all_expose.oi__atan2 1280 instructions  # inclusive",
              "peer.numpy_mg.sun_fraction.ns_per_point 304.2 ns",
              "binding.expose.over_c_batch 3.02 x  # goal <= 1.3",
              "goal.full_scene_under_300_ns missed -  # double, all terms + exposure: 684.2 ns median",
              "# exit status 0"],
    "plan-bench": ["plan.leo-inspector.speedup 3.78 x  # goal 4",
                   "goal.plan_4x_rows_per_cpu_s missed -  # speed-ups 3.85, 3.78, 3.97", "# exit status 0"],
    "binding-instructions": ["binding.illuminate.over_c_batch_instructions 1.058 x  # callgrind",
                             "binding.expose.over_c_batch_instructions 1.124 x  # callgrind"],
}


def _block(doc, name):
    m = re.search(r"<!-- perf:%s -->\n(.*?)<!-- /perf:%s -->" % (re.escape(name), re.escape(name)),
                  doc, re.S)
    assert m, name
    return m.group(1)


@pytest.fixture()
def rewritten(tmp_path):
    perf = tmp_path / "build" / "perf"
    perf.mkdir(parents=True)
    for name, lines in OUTS.items():
        (perf / (name + ".txt")).write_text("\n".join(lines) + "\n")
    (perf / "commit.txt").write_text("abc1234\n")
    names = list(perf_doc.BLOCKS) + ["goals"]
    doc = "# Title\n\nprose before\n\n" + "".join(
        "<!-- perf:%s -->\nold %s\n<!-- /perf:%s -->\n\nprose after %s\n\n" % (n, n, n, n) for n in names)
    path = tmp_path / "performance.md"
    path.write_text(doc)
    subprocess.run([sys.executable, os.path.join(ROOT, "tools", "perf_doc.py"), "--no-run",
                    "--builddir", str(tmp_path / "build"), "--doc", str(path)],
                   check=True, capture_output=True, text=True)
    return path.read_text()


def test_blocks_get_their_lines(rewritten):
    assert "prose before" in rewritten
    for n in list(perf_doc.BLOCKS) + ["goals"]:
        assert "prose after %s" % n in rewritten
    size = _block(rewritten, "size-members")
    assert "m4f-Os.full.lib.member.vector.o 164" in size and "m7-Os" not in size
    assert "at commit abc1234" in size
    paths = _block(rewritten, "stack-paths")
    assert "stack.m4f-Os.oi_angle 96" in paths and ".bounded_args 96" not in paths
    bench = _block(rewritten, "bench")
    assert "all.ns_median" in bench and "profile.double" in bench and "quadrature" in bench
    body = [l for l in bench.splitlines() if l.startswith("bench.")]
    assert body and not [l for l in body if "ns_min" in l or "batch" in l or "all_baseline" in l]
    assert "goal.full_scene_under_300_ns missed" in bench  # a goals cell cut short points here
    batch = _block(rewritten, "batch")
    assert "all_batch_observer.instructions" in batch and "all_baseline" in batch
    assert "all.ns_median" not in batch
    assert "peer.numpy_mg" in _block(rewritten, "peers")
    assert "binding.expose.over_c_batch 3.02" in _block(rewritten, "binding")
    assert "over_c_batch_instructions 1.124" in _block(rewritten, "binding-instructions")
    assert "plan.leo-inspector.speedup" in _block(rewritten, "plan")
    assert "goal.plan_4x_rows_per_cpu_s" in _block(rewritten, "plan")
    assert "arm-none-eabi" not in _block(rewritten, "target-test")


def test_a_block_without_output_stays(rewritten):
    assert _block(rewritten, "target-bench") == "old target-bench\n"


def test_goals_table(rewritten):
    goals = _block(rewritten, "goals")
    rows = [r for r in goals.splitlines() if r.startswith("| `")]
    keys = [r.split("`")[1] for r in rows]
    assert keys == ["goal.cross_builds_clean", "goal.zero_data_bss", "goal.stack_at_most_512",
                    "guard.stack_at_most_512", "goal.no_recursion_vla_indirect_call",
                    "goal.target_selftest_passes", "goal.full_scene_under_300_ns",
                    "goal.plan_4x_rows_per_cpu_s", "goal.binding_within_1.3x_of_c_batch.instructions"]
    status = {r.split("`")[1]: r.split("|")[2].strip() for r in rows}
    assert status["goal.cross_builds_clean"] == "**met**"
    assert status["goal.stack_at_most_512"] == "**missed**"
    assert status["guard.stack_at_most_512"] == "**held**"
    assert status["goal.binding_within_1.3x_of_c_batch.instructions"] == "**met**"
    assert "1.124x (expose" in goals
    assert "684.2 ns median" in goals and "-  #" not in goals
    for r in rows:
        for cell in r.strip("|").split("|"):
            assert len(cell) <= CELL_LIMIT, cell


def test_goal_status_follows_the_outputs():
    outs = {"cross": ["error: x", "# exit status 2"], "stack": ["# exit status 1"],
            "binding-instructions": ["binding.expose.over_c_batch_instructions 1.400 x"]}
    rows = {k: st for k, st, _ in perf_doc.goal_lines(outs)}
    assert rows == {"goal.cross_builds_clean": "missed", "goal.no_recursion_vla_indirect_call": "missed",
                    "goal.binding_within_1.3x_of_c_batch.instructions": "missed"}


def _doc():
    with open(DOC) as f:
        return f.read()


def test_the_page_has_every_block_once():
    doc = _doc()
    for n in list(perf_doc.BLOCKS) + ["goals"]:
        assert doc.count("<!-- perf:%s -->" % n) == 1, n
        assert doc.count("<!-- /perf:%s -->" % n) == 1, n
    named = set(re.findall(r"<!-- perf:([a-z0-9-]+) -->", doc))
    assert named == set(perf_doc.BLOCKS) | {"goals"}


@pytest.mark.parametrize("path", [DOC, LOG])
def test_no_long_table_cell(path):
    with open(path) as f:
        long_cells = [(n, len(c)) for n, line in enumerate(f, 1) if line.startswith("|")
                      for c in line.rstrip("\n").strip("|").split(" | ") if len(c) > CELL_LIMIT]
    assert not long_cells, long_cells


def _slug(title):  # GitHub's heading anchor
    return re.sub(r"[^\w\- ]", "", title.strip().lower()).replace(" ", "-")


def test_sections_named_elsewhere_exist():
    doc = _doc()
    titles = [t for t in re.findall(r"^#+ (.+)$", doc, re.M)]
    for name in ("The flight target", "Size", "Stack", "Host benchmark", "Batch interface",
                 "The Sun fraction batch's bookkeeping", "The Sun fraction's peers", "Planner speed",
                 "Goals", "Error against cost"):
        assert any(t.startswith(name) for t in titles), name
    slugs = {_slug(t) for t in titles}
    files = []
    for top, dirs, names in os.walk(ROOT):
        dirs[:] = [d for d in dirs if d not in ("build", ".venv", ".git", "node_modules")]
        files += [os.path.join(top, n) for n in names
                  if n.endswith((".md", ".py", ".c", ".h", ".mk", ".js", ".html")) or n == "Makefile"]
    bad = []
    for path in files:
        with open(path, errors="replace") as f:
            for anchor in re.findall(r"performance\.md#([\w\-]+)", f.read()):
                if anchor not in slugs:
                    bad.append("%s: #%s" % (os.path.relpath(path, ROOT), anchor))
    assert not bad, bad


def test_the_log_is_dated_newest_first():
    with open(LOG) as f:
        dates = re.findall(r"^## (\d{4}-\d\d-\d\d)", f.read(), re.M)
    assert len(dates) >= 2
    assert dates == sorted(dates, reverse=True), dates
