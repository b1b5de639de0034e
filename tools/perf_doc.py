#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""perf_doc.py: refresh the measured blocks of docs/performance.md (make perf-doc).

Runs the commands of RUNS below (make cross, size, stack, target-test,
target-bench, binding, bench, plan-bench and the binding's instruction count;
each once, in order, with the caller's BUILDDIR), keeps each output in
BUILDDIR/perf/<name>.txt
and rewrites every block of docs/performance.md between
    <!-- perf:NAME -->  and  <!-- /perf:NAME -->
with the selected lines of that output, quoted with the command and the commit.
The goal table (<!-- perf:goals -->) is built from the `goal.*` and `guard.*`
lines, with the goals the runs decide themselves (the exit statuses of make
cross and make stack, the binding's largest ratio in instructions); no cell is
longer than CELL_MAX characters.
Nothing else in the document is touched.
Usage: tools/perf_doc.py [--builddir build] [--no-run] [--doc docs/performance.md]
"""
import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# run name -> the command as quoted in the document; each runs once, in this order, with the
# caller's BUILDDIR ("make X" as `make -s BUILDDIR=... X`; "python S ..." as the tree's
# .venv python running S with --bench BUILDDIR/bench/bench-double)
RUNS = [
    ("cross", "make cross"),
    ("size", "make size"),
    ("stack", "make stack"),
    ("target-test", "make target-test"),
    ("target-bench", "make target-bench"),
    ("binding", "make binding"),  # the Python binding the bench's peer and binding lines import
    ("bench", "make bench"),
    ("plan-bench", "make plan-bench"),
    ("binding-instructions", "python bench/binding_cost.py --callgrind --n 2000 illuminate expose"),
]

def _config(line):
    """The configuration of a `bench.<precision>.<config>...` line ('' for others)."""
    parts = line.split()[0].split(".") if line.strip() else []
    return parts[2] if len(parts) > 2 and parts[0] == "bench" else ""


def _batch_line(line):
    return line.startswith("bench.") and ("batch" in _config(line) or "baseline" in _config(line))


# block name -> (run, shell-like description of the filter, predicate)
BLOCKS = {
    "size": ("size", "make size | grep -E '^#|^goal'",
             lambda l: l.startswith("#") or l.startswith("goal")),
    "size-members": ("size", "make size | grep m4f-Os.full.lib.member",
                     lambda l: "m4f-Os.full.lib.member" in l),
    "stack": ("stack", "make stack | grep -E '^#|^goal|^guard|problem'",
              lambda l: l.startswith(("#", "goal", "guard")) or ".problem" in l),
    "stack-paths": ("stack", "make stack | grep '^stack.m4f-Os.oi_' | grep -v bounded_args",
                    lambda l: l.startswith("stack.m4f-Os.oi_") and ".bounded_args" not in l),
    "stack-paths-m7": ("stack", "make stack | grep -E '^stack.m7-O2.oi_(illuminate|sun_fraction) '",
                       lambda l: re.match(r"stack\.m7-O2\.oi_(illuminate|sun_fraction) ", l) is not None),
    "target-test": ("target-test", "make target-test",
                    lambda l: not l.startswith(("arm-none-eabi", "rm -f", "cc "))),
    "target-bench": ("target-bench", "make target-bench", lambda l: l.startswith("target.")),
    "bench": ("bench", "make bench | grep -E '^(bench|profile|goal)\\.' "
                       "| grep -vE 'ns_min|^bench\\.[a-z]+\\.[a-z_]*(batch|baseline)'",
              lambda l: (l.startswith(("bench.", "profile.", "goal.")) and "ns_min" not in l
                         and not _batch_line(l))),
    "batch": ("bench", "make bench | grep -E '^bench\\.[a-z]+\\.[a-z_]*(batch|baseline)' | grep -v ns_min",
              lambda l: _batch_line(l) and "ns_min" not in l),
    "binding": ("bench", "make bench | grep '^binding\\.'", lambda l: l.startswith("binding.")),
    "binding-instructions": ("binding-instructions", RUNS[-1][1],
                             lambda l: l.startswith("binding.")),
    "peers": ("bench", "make bench | grep '^peer\\.'", lambda l: l.startswith("peer.")),
    "plan": ("plan-bench", "make plan-bench | grep -E '^(plan|goal)\\.'",
             lambda l: l.startswith(("plan.", "goal."))),
}

# a goals table's cell is cut at this many characters (the full line is in its block)
CELL_MAX = 280


def commit():
    try:
        return subprocess.run(["git", "log", "-1", "--format=%h"], cwd=ROOT, check=True,
                              capture_output=True, text=True).stdout.strip()
    except Exception:
        return "unknown"


def dirty():
    try:
        out = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], cwd=ROOT,
                             check=True, capture_output=True, text=True).stdout
        return bool(out.strip())
    except Exception:
        return True


def run_all(builddir, outdir):
    os.makedirs(outdir, exist_ok=True)
    with open(os.path.join(outdir, "commit.txt"), "w") as f:
        f.write("%s%s\n" % (commit(), " + local changes" if dirty() else ""))
    py = os.path.join(ROOT, ".venv", "bin", "python")
    py = py if os.path.exists(py) else sys.executable
    for name, cmd in RUNS:
        print("perf-doc: %s" % cmd, file=sys.stderr, flush=True)
        if cmd.startswith("make "):
            p = subprocess.run(["make", "-s", "BUILDDIR=" + builddir] + cmd.split()[1:], cwd=ROOT,
                               capture_output=True, text=True)
        else:  # a script of the tree, with the project's python and the benchmark's build
            args = [py] + cmd.split()[1:] + ["--bench", os.path.join(builddir, "bench", "bench-double")]
            p = subprocess.run(args, cwd=ROOT, capture_output=True, text=True)
        with open(os.path.join(outdir, name + ".txt"), "w") as f:
            f.write(p.stdout + p.stderr)
            f.write("\n# exit status %d\n" % p.returncode)


def _exit_status(lines):
    for line in reversed(lines):
        m = re.match(r"# exit status (\d+)$", line)
        if m:
            return int(m.group(1))
    return None


def _cell(text):
    """A table cell: '|' written as '/', at most CELL_MAX characters (cut at a word)."""
    text = text.replace("|", "/").strip()
    if len(text) <= CELL_MAX:
        return text
    cut = text.rfind(" ", 0, CELL_MAX - 40)
    return text[:cut if cut > 0 else CELL_MAX - 40] + " ... (the whole line in its block)"


def goal_lines(outs):
    """(goal, status, evidence) of every goal line of the runs, and the goals the runs' own
    results decide: the cross build and make stack's structural checks by their exit status,
    the binding's ratio in instructions by its largest ratio."""
    rows = []
    cross = _exit_status(outs.get("cross", []))
    if cross is not None:
        rows.append(("goal.cross_builds_clean", "met" if cross == 0 else "missed",
                     "make cross exit status %d (M4F and M7, -Os and -O2, -Werror)" % cross))
    for name in ("size", "stack", "target-test", "bench", "plan-bench"):
        for line in outs.get(name, []):
            if line.startswith(("goal.", "guard.")):
                key, _, rest = line.partition(" ")
                status, _, evidence = rest.partition(" ")
                evidence = evidence.strip()
                if evidence.startswith("-"):  # run_bench.py's unit column
                    evidence = evidence[1:].strip()
                rows.append((key, status, evidence.lstrip("#").strip().strip("()")))
            elif line.startswith(("target-test passed", "target-test FAILED")):
                rows.append(("goal.target_selftest_passes", "met" if "passed" in line else "missed",
                             "make target-test: " + line))
        if name == "stack":
            st = _exit_status(outs.get("stack", []))
            if st is not None:
                rows.append(("goal.no_recursion_vla_indirect_call", "met" if st == 0 else "missed",
                             "make stack exit status %d (it fails on recursion, a dynamic frame or an "
                             "indirect call in the runtime)" % st))
    ratios = []
    for line in outs.get("binding-instructions", []):
        f = line.split()
        if len(f) >= 2 and f[0].endswith(".over_c_batch_instructions"):
            try:
                ratios.append((float(f[1]), f[0].split(".")[1]))
            except ValueError:
                pass
    if ratios:
        worst = max(ratios)
        rows.append(("goal.binding_within_1.3x_of_c_batch.instructions",
                     "met" if worst[0] <= 1.3 else "missed",
                     "largest binding / C batch ratio in instructions per row: %.3fx (%s; callgrind, "
                     "bench/binding_cost.py)" % worst))
    return rows


def goal_table(outs):
    lines = ["| goal line | status | evidence (the line's own words) |", "|---|---|---|"]
    lines += ["| `%s` | **%s** | %s |" % (k, st, _cell(ev)) for k, st, ev in goal_lines(outs)]
    return lines


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--builddir", default=os.environ.get("BUILDDIR", "build"))
    ap.add_argument("--doc", default=os.path.join(ROOT, "docs", "performance.md"))
    ap.add_argument("--no-run", action="store_true", help="reuse BUILDDIR/perf/*.txt")
    args = ap.parse_args()
    outdir = os.path.join(ROOT, args.builddir, "perf")
    if not args.no_run:
        run_all(args.builddir, outdir)
    outs = {}
    for name, _ in RUNS:
        path = os.path.join(outdir, name + ".txt")
        if os.path.exists(path):
            with open(path) as f:
                outs[name] = f.read().splitlines()
    try:  # the commit the outputs were measured at (written by run_all)
        with open(os.path.join(outdir, "commit.txt")) as f:
            tag = "at commit " + f.read().strip()
    except OSError:
        tag = "at commit %s%s" % (commit(), " + local changes" if dirty() else "")
    with open(args.doc) as f:
        doc = f.read()

    def replace(name, body):
        nonlocal doc
        pat = re.compile(r"(<!-- perf:%s -->\n).*?(<!-- /perf:%s -->)" % (re.escape(name), re.escape(name)),
                         re.S)
        if not pat.search(doc):
            print("perf-doc: no block %s in %s" % (name, args.doc), file=sys.stderr)
            return
        doc = pat.sub(lambda m: m.group(1) + body + m.group(2), doc)

    for name, (run, desc, pred) in BLOCKS.items():
        if run not in outs:
            print("perf-doc: no output of %s kept: block %s left as it is" % (run, name), file=sys.stderr)
            continue
        lines = [l for l in outs[run] if pred(l)]
        replace(name, "```\n$ %s    # %s\n%s\n```\n" % (desc, tag, "\n".join(lines)))
    replace("goals", "\n".join(goal_table(outs)) + "\n\n(the goal lines of `%s`, %s)\n" % (
        "make cross size stack target-test bench plan-bench", tag))
    with open(args.doc, "w") as f:
        f.write(doc)
    print("perf-doc: wrote %s (%s)" % (args.doc, tag), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
