#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""plan_speed.py: the driver of `make plan-bench`: build/oi-plan --csv rows per CPU-second.

For each golden case (tests/golden/CASE.in.csv) the input is repeated
--copies times into one file; the planner runs on it --runs times and the
best child CPU time (user + system, getrusage) gives rows per CPU-second. Its
output is checked to be the golden output repeated, byte for byte. With
valgrind, callgrind counts the instructions per row on --cg-copies copies and
the part inside the library (oi_illuminate or oi_illuminate_batch_outputs,
and oi_expose_scene, oi_expose_scene_batch or oi_expose_scene_batch_outputs,
inclusive); with --baseline also the bound the library
sets: the original's instructions per row over the library's alone, and,
where perf runs, the same bound in CPU time (the share of perf's samples in
the library's functions, named by nm from build/liborbillum.a, and libm).
--plan points at another build (e.g. one of an earlier commit) to compare.
--baseline names the original planner (make plan-bench builds it: the
planner's sources from before its own number text, against today's
library): it runs in the same loop, alternating with --plan so that the
machine's load weighs on both alike, its rows checked to be the golden rows'
leading fields (it writes fewer columns), and the ratios are printed with
the goal line (4x the original's rows per CPU-second).

Prints `name value unit` lines, also written to --out.
"""
import argparse
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CASES = ["geo-inspector-eclipse", "leo-inspector", "leo-leo-pass"]


def repeated(case, copies, tmp):
    with open(os.path.join(ROOT, "tests", "golden", case + ".in.csv")) as f:
        head, *rows = f.read().splitlines(keepends=True)
    path = os.path.join(tmp, f"{case}-{copies}.csv")
    with open(path, "w") as f:
        f.write(head)
        for _ in range(copies):
            f.writelines(rows)
    with open(os.path.join(ROOT, "tests", "golden", case + ".plan.csv")) as f:
        ohead, *orows = f.read().splitlines(keepends=True)
    return path, len(rows) * copies, ohead + "".join(orows) * copies


def leading_fields(got, want):
    """Each row of got is the start of want's row, up to a field separator
    (the original planner writes the leading columns of today's output)."""
    g, w = got.splitlines(), want.splitlines()
    return len(g) == len(w) and all(x == y or y.startswith(x + ",") for x, y in zip(g, w))


def cpu_run(plan, path):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    r = subprocess.run([plan, "--csv", path], capture_output=True, text=True, check=False)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, r.stdout


def callgrind(plan, path, tmp):
    out = os.path.join(tmp, "cg.out")
    subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", plan,
                    "--csv", path], capture_output=True, check=False)
    ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", out], capture_output=True,
                         text=True, check=False).stdout
    total = 0
    per_fn = {}  # a function can be listed twice (by object and by source file): its largest
    for line in ann.splitlines():
        m = re.match(r"\s*([\d,]+) .*", line)
        if not m:
            continue
        n = int(m.group(1).replace(",", ""))
        if "PROGRAM TOTALS" in line:
            total = n
        else:
            f = re.search(r":(oi_illuminate|oi_illuminate_batch_outputs|oi_expose_scene|"
                          r"oi_expose_scene_batch|oi_expose_scene_batch_outputs) ", line)
            if f:
                # the batch and its outputs form (which the batch calls): one entry
                name = f.group(1).replace("oi_expose_scene_batch_outputs", "oi_expose_scene_batch")
                per_fn[name] = max(per_fn.get(name, 0), n)
    return total, sum(per_fn.values())


def library_symbols(archive):
    """The function names of the library archive (nm: text symbols, static ones too)."""
    if not shutil.which("nm") or not os.path.exists(archive):
        return set()
    out = subprocess.run(["nm", archive], capture_output=True, text=True, check=False).stdout
    return {f[2] for f in (line.split() for line in out.splitlines())
            if len(f) == 3 and f[1] in "tTwW"}


def perf_library_share(plan, path, symbols, tmp):
    """The share of the planner's CPU-time samples (perf record) inside the
    library's functions and the libm they call, or None without perf."""
    if not symbols or not shutil.which("perf"):
        return None
    data = os.path.join(tmp, "perf.data")
    r = subprocess.run(["perf", "record", "-q", "-F", "10000", "-o", data, "--", plan, "--csv",
                        path], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    if r.returncode != 0:
        return None
    rep = subprocess.run(["perf", "report", "-i", data, "--stdio", "--sort", "dso,sym"],
                         capture_output=True, text=True, check=False).stdout
    total = lib = 0.0
    for line in rep.splitlines():
        f = line.split()
        if len(f) < 4 or line.startswith("#") or not f[0].endswith("%"):
            continue
        share, dso, sym = float(f[0][:-1]), f[1], f[-1]
        total += share
        if sym in symbols or sym.split(".")[0] in symbols or dso.startswith("libm"):
            lib += share
    return lib / total if total > 0 else None


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--plan", default=os.path.join(ROOT, "build", "oi-plan"))
    p.add_argument("--copies", type=int, default=200)
    p.add_argument("--cg-copies", type=int, default=20)
    p.add_argument("--runs", type=int, default=5)
    p.add_argument("--out", default=os.path.join(ROOT, "build", "bench", "plan.txt"))
    p.add_argument("--baseline", help="the original planner, for the speed-up ratios")
    a = p.parse_args()
    lines = []

    def put(name, value, unit, comment=""):
        line = f"{name} {value} {unit}" + (f"  # {comment}" if comment else "")
        print(line, flush=True)
        lines.append(line)

    ok = True
    speedups = []
    symbols = library_symbols(os.path.join(ROOT, "build", "liborbillum.a"))
    with tempfile.TemporaryDirectory() as tmp:
        for case in CASES:
            path, rows, want = repeated(case, a.copies, tmp)
            best = base_best = None
            for _ in range(a.runs):
                cpu, got = cpu_run(a.plan, path)
                if got != want:
                    ok = False
                    put(f"plan.{case}.output", "DIFFERS", "-", "not the golden output repeated")
                    break
                best = cpu if best is None else min(best, cpu)
                if a.baseline:
                    bcpu, bgot = cpu_run(a.baseline, path)
                    if not leading_fields(bgot, want):
                        put(f"plan.{case}.baseline_output", "DIFFERS", "-",
                            "not the golden rows' leading fields")
                        a.baseline = None
                        continue
                    base_best = bcpu if base_best is None else min(base_best, bcpu)
            if best:
                put(f"plan.{case}.rows_per_cpu_s", f"{rows / best:.4g}", "rows/CPU-s",
                    f"{rows} rows, best of {a.runs}")
            if best and base_best:
                put(f"plan.{case}.baseline_rows_per_cpu_s", f"{rows / base_best:.4g}", "rows/CPU-s",
                    "the original planner, same runs")
                put(f"plan.{case}.speedup", f"{base_best / best:.2f}", "x",
                    "rows per CPU-second over the original's (goal 4)")
                speedups.append(base_best / best)
                share = perf_library_share(a.plan, path, symbols, tmp)
                if share:
                    put(f"plan.{case}.library_cpu_share", f"{100.0 * share:.0f}", "%",
                        "perf record: the planner's CPU samples in the library (and libm)")
                    put(f"plan.{case}.library_cpu_bound", f"{base_best / best / share:.2f}", "x",
                        "the speed-up were the planner's own work free: the original's CPU time "
                        "over the library's share of these")
            if shutil.which("valgrind") and shutil.which("callgrind_annotate"):
                cpath, crows, _ = repeated(case, a.cg_copies, tmp)
                total, lib = callgrind(a.plan, cpath, tmp)
                put(f"plan.{case}.instructions_per_row", f"{total / crows:.0f}", "instructions",
                    f"callgrind, {crows} rows; the library (oi_illuminate or its batch, "
                    f"oi_expose_scene or its batch) "
                    f"{lib / crows:.0f} ({100.0 * lib / total:.0f} %)")
                if a.baseline:
                    btotal, blib = callgrind(a.baseline, cpath, tmp)
                    put(f"plan.{case}.baseline_instructions_per_row", f"{btotal / crows:.0f}",
                        "instructions", f"the original planner; its library part {blib / crows:.0f}")
                    put(f"plan.{case}.instruction_ratio", f"{btotal / total:.2f}", "x",
                        "the original's instructions per row over these")
                    if lib:
                        put(f"plan.{case}.library_bound", f"{btotal / lib:.2f}", "x",
                            "the instruction ratio were the planner's own work free: the "
                            "original's instructions over the library's alone")
    if speedups:
        worst = min(speedups)
        put("goal.plan_4x_rows_per_cpu_s", "met" if worst >= 4.0 else "missed", "-",
            f"speed-ups {', '.join(f'{x:.2f}' for x in speedups)} (GEO, LEO, LEO-LEO); goal 4")
    os.makedirs(os.path.dirname(os.path.abspath(a.out)), exist_ok=True)
    with open(a.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
