#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""check_layers.py: the runtime's layer rule (docs/architecture.md), checked.

src/ is one folder per layer, from the bottom up in the order given by
--layers (the Makefile's RT_LAYERS). The rule: a layer calls only the layers
below it (and itself). Checked on two things a compiler leaves behind:

  includes  every `#include "..."` of a file in src/<layer>/ names a base
            header (src/*.h, include/), or a header of its own layer or of
            a layer below; no .c file is included anywhere in src/.
  calls     every symbol an object of src/<layer>/ takes from another
            object of the runtime (nm: U in one object, defined in the
            other) is defined in its own layer or a layer below.
  cycles    no two files need each other, directly or through others
            (the graph of those calls between objects has no cycle).

Usage: tools/check_layers.py --layers "math model ..." --objects build/obj/double
       [--src src] [--nm nm]
Exit 0 when the rule holds, 1 with one line per breach otherwise.
"""
import argparse
import os
import re
import subprocess
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def read_includes(src, layers):
    """{(layer, file): [included names]} for every .c and .h under src/<layer>/."""
    out = {}
    for layer in layers:
        d = os.path.join(src, layer)
        for name in sorted(os.listdir(d)):
            if name.endswith((".c", ".h")):
                with open(os.path.join(d, name), encoding="utf-8") as f:
                    out[(layer, name)] = INCLUDE.findall(f.read())
    return out


def include_breaches(includes, layers, base_headers):
    rank = {layer: i for i, layer in enumerate(layers)}
    bad = []
    for (layer, name), incs in sorted(includes.items()):
        for inc in incs:
            if inc.endswith(".c"):
                bad.append(f"src/{layer}/{name}: includes a .c file ({inc})")
                continue
            head = inc.split("/")[0] if "/" in inc else None
            if head is None:
                if inc in base_headers:
                    continue
                if (layer, inc) in includes:  # a header of its own folder
                    continue
                bad.append(f"src/{layer}/{name}: includes {inc}, neither a base header nor a layer's")
            elif head not in rank:
                bad.append(f"src/{layer}/{name}: includes {inc}, not a layer's header")
            elif rank[head] > rank[layer]:
                bad.append(f"src/{layer}/{name}: includes {inc}, a header of the layer above ({head})")
    return bad


def read_symbols(objects, layers, nm="nm"):
    """{(layer, object name): (defined set, undefined set)} from nm."""
    out = {}
    for layer in layers:
        d = os.path.join(objects, "src", layer)
        if not os.path.isdir(d):
            raise SystemExit(f"check_layers: no objects in {d} (build the library first)")
        for name in sorted(os.listdir(d)):
            if not name.endswith(".o"):
                continue
            text = subprocess.run([nm, os.path.join(d, name)], capture_output=True, text=True,
                                  check=True).stdout
            defined, undefined = set(), set()
            for line in text.splitlines():
                parts = line.split()
                if len(parts) == 3 and parts[1] in "TDRBVWGS":
                    defined.add(parts[2])
                elif len(parts) == 2 and parts[0] == "U":
                    undefined.add(parts[1])
            out[(layer, name[:-2])] = (defined, undefined)
    return out


def call_graph(symbols):
    """{caller: {callee: [symbols]}} between the runtime's objects."""
    where = {}
    for key, (defined, _) in symbols.items():
        for s in defined:
            where[s] = key
    graph = {key: {} for key in symbols}
    for key, (_, undefined) in symbols.items():
        for s in sorted(undefined):
            if s in where and where[s] != key:
                graph[key].setdefault(where[s], []).append(s)
    return graph


def call_breaches(graph, layers):
    rank = {layer: i for i, layer in enumerate(layers)}
    bad = []
    for (layer, name), callees in sorted(graph.items()):
        for (clayer, cname), syms in sorted(callees.items()):
            if rank[clayer] > rank[layer]:
                bad.append(f"src/{layer}/{name}.c calls up into src/{clayer}/{cname}.c: "
                           + ", ".join(syms))
    return bad


def cycles(graph):
    """Each cycle of the graph once, as a list of nodes (Tarjan's strongly connected components)."""
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def cycle_breaches(graph):
    return ["files that need each other: " + ", ".join(f"src/{l}/{n}.c" for l, n in comp)
            for comp in cycles(graph)]


def base_headers_of(src, include_dir):
    names = {n for n in os.listdir(src) if n.endswith(".h")}
    if os.path.isdir(include_dir):
        for root, _, files in os.walk(include_dir):
            for n in files:
                if n.endswith(".h"):
                    names.add(os.path.relpath(os.path.join(root, n), include_dir))
    return names


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--layers", required=True, help="the layers from the bottom up")
    ap.add_argument("--objects", required=True, help="the objects' root (build/obj/double)")
    ap.add_argument("--src", default="src")
    ap.add_argument("--include", default="include")
    ap.add_argument("--nm", default="nm")
    a = ap.parse_args(argv)
    layers = a.layers.split()
    missing = [layer for layer in layers if not os.path.isdir(os.path.join(a.src, layer))]
    stray = sorted(n for n in os.listdir(a.src) if n.endswith(".c"))
    bad = [f"src/{layer}/: no such layer folder" for layer in missing]
    bad += [f"src/{n}: a source outside every layer" for n in stray]
    if not missing:
        includes = read_includes(a.src, layers)
        bad += include_breaches(includes, layers, base_headers_of(a.src, a.include))
        graph = call_graph(read_symbols(a.objects, layers, a.nm))
        bad += call_breaches(graph, layers)
        bad += cycle_breaches(graph)
    for line in bad:
        print("check_layers: " + line)
    if bad:
        return 1
    print(f"check_layers: {len(layers)} layers ({' < '.join(layers)}): every include and call "
          "goes down, no cycle")
    return 0


if __name__ == "__main__":
    sys.exit(main())
