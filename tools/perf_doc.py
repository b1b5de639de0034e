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
The goal table (<!-- perf:goals -->) is built from the `goal.*` lines.
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

# block name -> (run, shell-like description of the filter, predicate)
BLOCKS = {
    "size": ("size", "make size | grep -E '^#|^goal'",
             lambda l: l.startswith("#") or l.startswith("goal")),
    "size-members": ("size", "make size | grep m4f-Os.full.lib.member",
                     lambda l: "m4f-Os.full.lib.member" in l),
    "stack": ("stack", "make stack | grep -E '^#|^goal|^guard|problem'",
              lambda l: l.startswith(("#", "goal", "guard")) or ".problem" in l),
    "stack-paths": ("stack", "make stack | grep -E 'm(4f-Os|7-O2).oi_illuminate'",
                    lambda l: re.match(r"stack\.(m4f-Os|m7-O2)\.oi_illuminate", l) is not None),
    "target-test": ("target-test", "make target-test",
                    lambda l: not l.startswith(("arm-none-eabi", "rm -f", "cc "))),
    "target-bench": ("target-bench", "make target-bench", lambda l: l.startswith("target.")),
    "bench": ("bench", "make bench | grep -v ns_min",
              lambda l: (l.startswith(("bench.", "profile.", "goal.")) and "ns_min" not in l)),
    "peers": ("bench", "make bench | grep '^peer\\.'", lambda l: l.startswith("peer.")),
}


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


def goal_table(outs):
    rows = []
    for name in ("size", "stack", "target-test", "bench"):
        for line in outs.get(name, []):
            if line.startswith("goal.") or line.startswith("target-test passed") or \
                    line.startswith("target-test FAILED"):
                rows.append(line)
    lines = ["| measured line (goal name, met/missed, evidence) |", "|---|"]
    lines += ["| `%s` |" % r.replace("|", "/") for r in rows]
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
        lines = [l for l in outs.get(run, []) if pred(l)]
        replace(name, "```\n$ %s    # %s\n%s\n```\n" % (desc, tag, "\n".join(lines)))
    replace("goals", "\n".join(goal_table(outs)) + "\n\n(`%s`, %s)\n" % (
        "make size stack target-test bench", tag))
    with open(args.doc, "w") as f:
        f.write(doc)
    print("perf-doc: wrote %s (%s)" % (args.doc, tag), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
