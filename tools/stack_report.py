#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""stack_report.py: worst-case stack of every public function on the Cortex-M builds.

The runtime is compiled with -fstack-usage -fcallgraph-info=su (GCC >= 10): every
function's frame (bytes, static/dynamic) and its call edges come from the
compiler. Functions outside the runtime (libm, libc, libgcc) have no such
files; their frames and calls come from the disassembly of the linked
self-test image (arm-none-eabi-objdump): the sum of every push/vpush/stmdb
and `sub sp` in the function, which bounds its frame from above, and its
bl/b.w targets.

Worst case of f = frame(f) + max over callees of worst case(callee).

Fails (exit 1) when the runtime has recursion (a cycle in its call graph),
a dynamic frame (VLA, alloca) or an indirect call it cannot follow. A public
function above --limit bytes is reported as a missed goal (goal.* line), not
a failure, unless --guard names it: the calls that meet the goal are held to
it (a regression guard: exit 1 when one of them grows past --limit). A guard
entry is a function name (every configuration) or name@core (the
configurations of that core, e.g. oi_expose_scene@m4f). Each function gets two numbers: the worst case through every
path, and `.bounded_args`, the same without libm's large-argument reduction
(__kernel_rem_pio2 / __kernel_rem_pio2f, a 416-656 byte frame that newlib's
sin/cos/tan reach only for |x| > 2^7 pi/2 (float) or 2^19 pi/2 (double);
see newlib/libm/math/ef_rem_pio2.c and e_rem_pio2.c), valid when the runtime
passes only bounded angles to the trigonometric functions.
Prints `name value unit` lines.
Usage: tools/stack_report.py --objdir build/cross --cfgs "m4f-Os ..." --limit 512
       [--via FUNCTION ...]  (the worst path through FUNCTION as well)
"""
import argparse
import glob
import os
import re
import subprocess
import sys

NODE = re.compile(r'node: \{ title: "([^"]+)" label: "([^"]*)"')
EDGE = re.compile(r'edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"')
BYTES = re.compile(r"\\n(\d+) bytes \(([a-z,]+)\)")


def parse_ci(objdir):
    frames, quals, edges = {}, {}, {}
    files = sorted(glob.glob(os.path.join(objdir, "obj", "**", "*.ci"), recursive=True))
    for path in files:
        with open(path) as f:
            text = f.read()
        for m in NODE.finditer(text):
            title, label = m.group(1), m.group(2)
            b = BYTES.search(label)
            if b:
                frames[title] = int(b.group(1))
                quals[title] = b.group(2)
            edges.setdefault(title, set())
        for m in EDGE.finditer(text):
            edges.setdefault(m.group(1), set()).add(m.group(2))
    return frames, quals, edges, files


FUNC = re.compile(r"^([0-9a-f]+) <([^>]+)>:$")
INSN = re.compile(r"^\s+[0-9a-f]+:\s+(\S+)\s*(.*)$")
REGLIST = re.compile(r"\{([^}]*)\}")
TARGET = re.compile(r"<([^>+]+)(\+0x[0-9a-f]+)?>")
SUBSP = re.compile(r"^sp,\s*(sp,\s*)?#(\d+)")


def count_regs(reglist):
    n = 0
    for part in reglist.split(","):
        part = part.strip()
        if "-" in part:
            a, b = part.split("-")
            n += int(b.strip()[1:]) - int(a.strip()[1:]) + 1
        elif part:
            n += 1
    return n


def parse_disasm(objdump, elf):
    """Frames and call edges of every function in a linked image."""
    out = subprocess.run([objdump, "-d", "--no-show-raw-insn", elf], check=True,
                         capture_output=True, text=True).stdout
    frames, edges, indirect = {}, {}, set()
    cur = None
    for line in out.splitlines():
        m = FUNC.match(line)
        if m:
            cur = m.group(2)
            frames[cur] = 0
            edges[cur] = set()
            continue
        if cur is None:
            continue
        m = INSN.match(line)
        if not m:
            continue
        op, args = m.group(1), m.group(2)
        base = op.split(".")[0]
        if base in ("push", "vpush") or (base in ("stmdb", "vstmdb") and args.startswith("sp!")):
            r = REGLIST.search(args)
            if r:
                first = r.group(1).strip()
                size = 8 if first.startswith("d") else 4
                frames[cur] += size * count_regs(r.group(1))
        elif base in ("sub", "subw") and args.startswith("sp"):
            s = SUBSP.match(args)
            if s:
                frames[cur] += int(s.group(2))
        elif base in ("bl", "blx", "b", "bx") or op.startswith("b"):
            t = TARGET.search(args)
            if base == "blx" and not t:
                indirect.add(cur)
            elif t and t.group(2) is None and t.group(1) != cur:
                edges[cur].add(t.group(1))  # call, or a (conditional) tail call
    return frames, edges, indirect


HUGE_ARG = ("__kernel_rem_pio2", "__kernel_rem_pio2f")


def worst(fn, frames, edges, memo, stack, problems, origin, cut=()):
    if fn in cut:
        return 0, []
    if fn in memo:
        return memo[fn]
    if fn in stack:
        problems.append("recursion: %s" % " -> ".join(stack[stack.index(fn):] + [fn]))
        return 0
    stack.append(fn)
    best, path = 0, []
    for callee in sorted(edges.get(fn, ())):
        w, p = worst(callee, frames, edges, memo, stack, problems, origin, cut)
        if w > best:
            best, path = w, p
    stack.pop()
    if fn not in frames:
        problems.append("unknown frame: %s" % fn)
    memo[fn] = (frames.get(fn, 0) + best, [fn] + path)
    return memo[fn]


def worst_via(fn, via, frames, edges, memo, stack, cut=()):
    """The worst case of fn over the paths that pass through the function named
    via, and that path; None when no path reaches it."""
    if fn in memo:
        return memo[fn]
    if plain(fn) == via:
        memo[fn] = worst(fn, frames, edges, {}, [], [], fn, cut)
        return memo[fn]
    if fn in stack or fn in cut:
        return None
    stack.append(fn)
    best = None
    for callee in sorted(edges.get(fn, ())):
        r = worst_via(callee, via, frames, edges, memo, stack, cut)
        if r is not None and (best is None or r[0] > best[0]):
            best = r
    stack.pop()
    memo[fn] = None if best is None else (frames.get(fn, 0) + best[0], [fn] + best[1])
    return memo[fn]


def plain(title):
    return title.split(":")[-1]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--objdir", required=True)
    ap.add_argument("--cfgs", required=True)
    ap.add_argument("--objdump", default="arm-none-eabi-objdump")
    ap.add_argument("--limit", type=int, default=512)
    ap.add_argument("--public", required=True)
    ap.add_argument("--guard", default="",
                    help="public functions held to --limit: name (every cfg) or name@core")
    ap.add_argument("--via", action="append", default=[], metavar="FUNCTION",
                    help="also the worst case of each public function over the paths through "
                         "FUNCTION (e.g. cubature_flux), as stack.CFG.FN.via.FUNCTION lines")
    args = ap.parse_args()
    failed = False
    over = []
    summary = {}
    public = args.public.split()
    for cfg in args.cfgs.split():
        d = os.path.join(args.objdir, cfg)
        frames, quals, edges, files = parse_ci(d)
        if not files:
            raise SystemExit("no .ci files in %s (build with -fcallgraph-info=su)" % d)
        dframes, dedges, indirect = parse_disasm(args.objdump, os.path.join(d, "selftest.elf"))
        problems = []
        for t, q in sorted(quals.items()):
            if q != "static":
                problems.append("dynamic frame (VLA or alloca): %s (%s)" % (t, q))
        for t, callees in edges.items():
            if "__indirect_call" in callees:
                problems.append("indirect call in the runtime: %s" % t)
        # Graph: runtime nodes from the compiler; external ones from the disassembly.
        g_frames, g_edges = dict(frames), {k: set(v) for k, v in edges.items()}
        external = set()
        for callees in edges.values():
            for c in callees:
                if c not in frames:
                    external.add(c)
        todo = list(external)
        while todo:
            c = todo.pop()
            if c in g_frames and c not in external:
                continue
            if c in dframes:
                g_frames[c] = dframes[c]
                g_edges[c] = set(dedges[c])
                if c in indirect:
                    problems.append("indirect call in %s (outside the runtime)" % c)
                for n in dedges[c]:
                    if n not in g_frames and n not in external:
                        external.add(n)
                        todo.append(n)
        memo, memo_b = {}, {}
        runtime_problems = []
        for fn in public:
            # a single-precision build names every public symbol with _sp (include/oi_config.h)
            sym = fn if fn in frames else fn + "_sp"
            if sym not in frames:
                print("stack.%s.%s missing  # not defined in the runtime" % (cfg, fn))
                continue
            w, path = worst(sym, g_frames, g_edges, memo, [], runtime_problems, sym)
            print("stack.%s.%s %d bytes  # %s" % (cfg, fn, w, " > ".join(
                "%s(%d)" % (plain(p), g_frames.get(p, 0)) for p in path)))
            wb, pathb = worst(sym, g_frames, g_edges, memo_b, [], [], sym, HUGE_ARG)
            summary[(cfg, fn)] = (w, wb)
            print("stack.%s.%s.bounded_args %d bytes  # %s" % (cfg, fn, wb, " > ".join(
                "%s(%d)" % (plain(p), g_frames.get(p, 0)) for p in pathb)))
            if w > args.limit:
                over.append("%s.%s %d/%d" % (cfg, fn, w, wb))
            for via in args.via:
                r = worst_via(sym, via, g_frames, g_edges, {}, [])
                if r is not None:
                    print("stack.%s.%s.via.%s %d bytes  # %s" % (cfg, fn, via, r[0], " > ".join(
                        "%s(%d)" % (plain(p), g_frames.get(p, 0)) for p in r[1])))
        libm_max = max([dframes.get(e, 0) for e in external] + [0])
        print("stack.%s.external_max_frame %d bytes  # largest single libm/libc frame" % (cfg, libm_max))
        for p in sorted(set(problems + runtime_problems)):
            print("stack.%s.problem %s" % (cfg, p))
            if not p.startswith("unknown frame") or plain(p.split(": ")[-1]) in frames:
                failed = True
    cfgs = args.cfgs.split()
    print("# worst-case stack bytes per public function: all paths / without libm's huge-argument reduction")
    print("# %-24s %s" % ("function", " ".join("%11s" % c for c in cfgs)))
    for fn in public:
        if any((c, fn) in summary for c in cfgs):
            print("# %-24s %s" % (fn, " ".join("%11s" % ("%d/%d" % summary[(c, fn)] if (c, fn) in summary else "-")
                                                for c in cfgs)))
    if over:
        print("goal.stack_at_most_%d missed (worst/bounded_args bytes: %s)" % (args.limit, ", ".join(over)))
    else:
        print("goal.stack_at_most_%d met" % args.limit)
    guarded, broken = guards(args.guard, cfgs, summary, args.limit)
    if guarded:
        if broken:
            print("guard.stack_at_most_%d broken (bytes: %s)" % (args.limit, ", ".join(broken)))
        else:
            print("guard.stack_at_most_%d held (%d calls x configurations)" % (args.limit, guarded))
    if failed:
        print("stack: FAILED (recursion, dynamic frame or indirect call in the runtime)")
    if broken:
        print("stack: FAILED (a guarded public function grew past %d bytes)" % args.limit)
    return 1 if failed or broken else 0


def guards(spec, cfgs, summary, limit):
    """The guarded (cfg, function) pairs counted and those over the limit."""
    n, broken = 0, []
    for entry in spec.split():
        fn, _, core = entry.partition("@")
        for cfg in cfgs:
            if core and cfg.split("-")[0] != core:
                continue
            if (cfg, fn) not in summary:
                broken.append("%s.%s missing" % (cfg, fn))
                continue
            n += 1
            if summary[(cfg, fn)][0] > limit:
                broken.append("%s.%s %d" % (cfg, fn, summary[(cfg, fn)][0]))
    return n, broken


if __name__ == "__main__":
    sys.exit(main())
