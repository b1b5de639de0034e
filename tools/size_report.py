#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""size_report.py: flash and RAM of the runtime per configuration and option set.

Reads the GNU ld map files of the small programs that `make size` links with
--gc-sections (target/size_full.c, target/size_sun.c; with --kinds the
program kinds of examples/size/, mk/size.mk) and attributes every
retained input section to its owner: the runtime (liborbillum.a), libm, libc,
libgcc, the stubs of missing functions, or the harness (startup, main).

    flash = text + rodata + data (initial values are stored in flash)
    RAM   = data + bss

Prints `name value unit` lines; goals are checked on the library alone
(libm, libc and libgcc are reported on their own lines).
Usage: tools/size_report.py --objdir build/cross --cfgs "m4f-Os ..." --sets "full ..."
       tools/size_report.py --kinds "sun_noatm ..." --kinddir build/size --kindcfgs "host m4f-Os"
"""
import argparse
import os
import re
import sys

OWNER_PATTERNS = (
    ("lib", re.compile(r"liborbillum\.a\(([^)]+)\)")),
    ("stubs", re.compile(r"libstubs\.a\(([^)]+)\)")),
    ("libm", re.compile(r"libm\.a\(([^)]+)\)")),
    ("libc", re.compile(r"libc(_nano)?\.a\(([^)]+)\)")),
    ("libgcc", re.compile(r"libgcc\.a\(([^)]+)\)")),
)

KIND_OF_OUTPUT = {
    ".vectors": "text",
    ".text": "text",
    ".rodata": "rodata",
    ".ARM.extab": "rodata",
    ".ARM.exidx": "rodata",
    ".data": "data",
    ".bss": "bss",
}

SEC_LINE = re.compile(r"^ (\S+)?\s+0x([0-9a-fA-F]+)\s+0x([0-9a-fA-F]+)\s+(\S.*)$")
NAME_ONLY = re.compile(r"^ (\S+)\s*$")
OUT_LINE = re.compile(r"^(\.\S+)(\s+0x[0-9a-fA-F]+\s+0x[0-9a-fA-F]+)?")


def owner_of(path):
    for owner, pat in OWNER_PATTERNS:
        m = pat.search(path)
        if m:
            return owner, m.group(m.lastindex)
    return "harness", os.path.basename(path)


def parse_map(path):
    """Return {(owner, kind): bytes}, {member: bytes} for the library, and the
    list of (owner, section) for libgcc/stubs (diagnostics)."""
    totals = {}
    members = {}
    extra = []
    with open(path) as f:
        lines = f.read().splitlines()
    try:
        start = lines.index("Linker script and memory map")
    except ValueError:
        raise SystemExit("%s: no memory map" % path)
    out_kind = None
    pending = None
    for line in lines[start + 1:]:
        if not line:
            continue
        if line[0] not in " \t*":
            m = OUT_LINE.match(line)
            out_kind = KIND_OF_OUTPUT.get(m.group(1)) if m else None
            pending = None
            continue
        if out_kind is None:
            continue
        m = SEC_LINE.match(line)
        if m:
            name = m.group(1) or pending
            pending = None
            size = int(m.group(3), 16)
            src = m.group(4).strip()
            if name is None or name.startswith("*") or size == 0:
                continue
            owner, member = owner_of(src)
            key = (owner, out_kind)
            totals[key] = totals.get(key, 0) + size
            if owner == "lib":
                members[member] = members.get(member, 0) + size
            if owner == "stubs":
                extra.append((owner, name))
            if owner == "libgcc":
                extra.append((owner, member))
            continue
        m = NAME_ONLY.match(line)
        if m and not m.group(1).startswith("*"):
            pending = m.group(1)
    return totals, members, extra


# the runtime's own libm-like functions (archive members)
MATH_MEMBERS = ("atan2.o", "sincos.o")


def get(t, owner, kind):
    return t.get((owner, kind), 0)


# archive members that are baked tables (tables/*.c)
TABLE_MEMBER = re.compile(r"^oi_(earth|atm)_\w+\.o$")


def report_kinds(args):
    """Bytes linked from the library per program kind: flash of the runtime
    (text + rodata + data), of which the baked tables, and libm."""
    kinds = args.kinds.split()
    rows = {}
    for cfg in args.kindcfgs.split():
        for k in kinds:
            base = os.path.join(args.kinddir, cfg, k)
            path = base + ".map"
            t, members, _ = parse_map(path)
            flash = sum(get(t, "lib", x) for x in ("text", "rodata", "data"))
            tables = sum(v for m, v in members.items() if TABLE_MEMBER.match(m))
            libm = sum(get(t, "libm", x) for x in ("text", "rodata", "data"))
            p = "size.kind.%s.%s" % (cfg, k)
            print("%s.lib.flash %d bytes" % (p, flash))
            print("%s.lib.tables %d bytes  # %s" % (
                p, tables, " ".join(sorted(m for m in members if TABLE_MEMBER.match(m))) or "none"))
            print("%s.lib.code %d bytes" % (p, flash - tables))
            if cfg != "host":
                print("%s.libm.flash %d bytes" % (p, libm))
            rows[(cfg, k)] = (flash, tables)
    print("# bytes linked from liborbillum.a per program kind (--gc-sections): total (tables)")
    print("# %-7s %s" % ("cfg", " ".join("%17s" % k for k in kinds)))
    for cfg in args.kindcfgs.split():
        print("# %-7s %s" % (cfg, " ".join("%17s" % ("%d (%d)" % rows[(cfg, k)]) for k in kinds)))
    return 0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--objdir")
    ap.add_argument("--cfgs")
    ap.add_argument("--sets")
    ap.add_argument("--nm", default="arm-none-eabi-nm")
    ap.add_argument("--kinds", help="program kinds (examples/size/<kind>.c)")
    ap.add_argument("--kinddir", help="their build folder: <kinddir>/<cfg>/<kind>.map")
    ap.add_argument("--kindcfgs", default="host", help="host and/or cross configurations")
    args = ap.parse_args()
    if args.kinds:
        return report_kinds(args)
    if not (args.objdir and args.cfgs and args.sets):
        ap.error("--objdir, --cfgs and --sets (or --kinds)")
    ok = True
    goals = []
    table = {}
    for cfg in args.cfgs.split():
        for s in args.sets.split():
            d = os.path.join(args.objdir, cfg) if s == "full" else os.path.join(args.objdir, cfg, "opt-" + s)
            t, members, extra = parse_map(os.path.join(d, "size.map"))
            p = "size.%s.%s" % (cfg, s)
            text, rodata = get(t, "lib", "text"), get(t, "lib", "rodata")
            data, bss = get(t, "lib", "data"), get(t, "lib", "bss")
            flash = text + rodata + data
            libm = sum(get(t, "libm", k) for k in ("text", "rodata", "data"))
            table[(cfg, s)] = (flash, libm, data + bss)
            print("%s.lib.flash %d bytes" % (p, flash))
            print("%s.lib.text %d bytes" % (p, text))
            print("%s.lib.rodata %d bytes" % (p, rodata))
            print("%s.lib.ram %d bytes" % (p, data + bss))
            for owner in ("libm", "libc", "libgcc"):
                f = sum(get(t, owner, k) for k in ("text", "rodata", "data"))
                r = get(t, owner, "data") + get(t, owner, "bss")
                print("%s.%s.flash %d bytes" % (p, owner, f))
                print("%s.%s.ram %d bytes" % (p, owner, r))
            stubs = sum(get(t, "stubs", k) for k in ("text", "rodata", "data", "bss"))
            if stubs:
                missing = sorted({n.split(".")[-1] for o, n in extra if o == "stubs" and n.startswith(".text.")})
                print("%s.incomplete %d functions  # stubs linked: %s" % (p, len(missing), " ".join(missing)))
            if cfg.startswith("m4f"):
                soft = sorted({n for o, n in extra if o == "libgcc" and re.search(r"df|dd|__aeabi_d", n)})
                print("%s.soft_double_helpers %d functions  # software double arithmetic linked into the "
                      "single-precision build%s" % (p, len(soft), (": " + " ".join(soft)) if soft else ""))
            if s == "full":
                for mem in sorted(members):
                    print("%s.lib.member.%s %d bytes" % (p, mem, members[mem]))
            if data + bss:
                ok = False
                goals.append("goal.zero_data_bss.%s.%s missed (%d bytes of .data/.bss in the library)"
                             % (cfg, s, data + bss))
            # the runtime's own math functions (src/math/atan2.c, src/math/sincos.c: what
            # libm provides, in the library), listed apart
            math = sum(members.get(k, 0) for k in MATH_MEMBERS)
            print("%s.lib.math_kernels %d bytes  # %s" % (p, math, " ".join(MATH_MEMBERS)))
            if s in ("sun_only", "sun_uniform"):
                # the goal's "Sun-only shadow build": sun_uniform is the smallest
                # (uniform disc); sun_only keeps the limb-darkened fraction. The
                # goal excludes libm: judged without libm and without the
                # runtime's own math functions, both numbers printed
                goals.append("goal.sun_only_flash_under_4KiB.%s.%s %s (%d bytes excl. libm and the "
                             "runtime's own atan2/sin/cos (%d bytes); %d with them; limit 4096)"
                             % (s, cfg, "met" if flash - math < 4096 else "missed", flash - math,
                                math, flash))
            if s == "full":
                goals.append("goal.full_flash_under_96KiB.%s %s (%d bytes incl. tables, excl. libm, limit 98304)"
                             % (cfg, "met" if flash < 98304 else "missed", flash))
    if ok:
        goals.append("goal.zero_data_bss met (every configuration and option set)")
    sets = args.sets.split()
    print("# flash bytes of the runtime (text+rodata+data, excl. libm) + libm flash, per option set")
    print("# %-7s %s" % ("cfg", " ".join("%17s" % x for x in sets)))
    for cfg in args.cfgs.split():
        print("# %-7s %s" % (cfg, " ".join("%17s" % ("%d + %d" % table[(cfg, x)][:2]) for x in sets)))
    for g in goals:
        print(g)
    return 0


if __name__ == "__main__":
    sys.exit(main())
