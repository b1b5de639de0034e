#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Write the worst-error table of docs/stability.md from the stability suite.

Runs build/tests/double/test_stability and build/tests/float/test_stability
(make builds them; `make stability-report` does both), collects their
"STAB | ..." lines and replaces the text between the markers
<!-- stability-table:begin --> and <!-- stability-table:end -->.
"""
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.environ.get("BUILDDIR", os.path.join(ROOT, "build"))
DOC = os.path.join(ROOT, "docs", "stability.md")
BEGIN, END = "<!-- stability-table:begin -->", "<!-- stability-table:end -->"


def rows(prec):
    exe = os.path.join(BUILD, "tests", prec, "test_stability")
    out = subprocess.run([exe], capture_output=True, text=True).stdout
    return [[c.strip() for c in line.split("|")[1:-1]] for line in out.splitlines()
            if line.startswith("STAB |")]


def main():
    by = {}
    order = []
    for prec in ("double", "float"):
        for r in rows(prec):
            name, p, n, nwell, worst_rel, ratio, kappa, status = r
            if name not in by:
                by[name] = {}
                order.append(name)
            if nwell == "0":
                worst_rel = "-"  # no well-conditioned vector
            by[name][p] = (n, nwell, worst_rel, ratio, kappa, status)
    lines = ["| function.output | vectors (d/s) | well-conditioned (d/s) | worst rel. error, "
             "kappa <= 10: double | single | worst err / tolerance: double | single | "
             "largest kappa: double | single | status |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for name in order:
        d = by[name].get("double", ("-",) * 6)
        s = by[name].get("single", ("-",) * 6)
        st = d[5] if d[5] == s[5] else "%s / %s" % (d[5], s[5])
        lines.append("| %s | %s / %s | %s / %s | %s | %s | %s | %s | %s | %s | %s |" % (
            name, d[0], s[0], d[1], s[1], d[2], s[2], d[3], s[3], d[4], s[4], st))
    table = "\n".join(lines)
    doc = open(DOC).read()
    a, b = doc.index(BEGIN) + len(BEGIN), doc.index(END)
    open(DOC, "w").write(doc[:a] + "\n" + table + "\n" + doc[b:])
    print(table)


if __name__ == "__main__":
    sys.exit(main())
