# SPDX-License-Identifier: MIT
"""The documents point at nothing outside the repository, and at nothing missing.

- README.md, docs/*.md, python/, examples/ and tools/coeffs/ name no file a
  clone does not have (PHYSICS.md, ../shared, the seed's text) and no work-item
  number ("issue 6"): history lives in git.
- Every relative link of README.md and docs/*.md names a file of the repository.
- Every "docs/physics.md section N" anywhere in the sources names a section
  docs/physics.md has.
- The code, build and test files (src/, include/, tables/, bake/, tests/, mk/, the Makefile, .ci/,
  target/, bench/, fuzz/, web/) carry no work-item number or pointer outside the repository either.
"""
import glob
import os
import re

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
# This file names the forbidden patterns; the golden outputs and lock files are data.
EXEMPT = {os.path.join("tests", "python", "test_docs.py")}
_FORBIDDEN = [
    (re.compile(r"PHYSICS\.md"), "PHYSICS.md (cite docs/physics.md)"),
    (re.compile(r"\.\./shared|(?:^|[\s\"'`(=])/work/"), "a path outside the repository"),
    (re.compile(r"penney-2009[\w.-]*\.txt|seed/"), "the seed's file (cite Penney 2009)"),
    (re.compile(r"\b[Ii]ssues? ?#?\d+\b"), "a work-item number"),
]


def _files(patterns):
    out = []
    for p in patterns:
        out += glob.glob(os.path.join(ROOT, p), recursive=True)
    return sorted(os.path.relpath(f, ROOT) for f in out if os.path.isfile(f))


DOCS = _files(["README.md", "docs/*.md"])
PROSE = [f for f in DOCS + _files(["python/**/*.py", "python/*.md", "python/*.toml",
                                   "examples/**/*.py", "examples/**/*.c", "examples/**/*.h",
                                   "tools/**/*.py",
                                   "include/*.h", "src/**/*.[ch]", "tables/*.[ch]", "tables/*.json",
                                   "include/orbillum/*.h",
                                   "bake/**/*.py", "bake/**/*.json", "tests/**/*.py",
                                   "tests/**/*.[ch]", "tests/**/*.sh", "tests/**/*.mjs",
                                   "mk/*.mk", "Makefile", ".ci/*", "target/*.[ch]", "target/*.ld",
                                   "bench/*", "fuzz/**/*.[ch]", "fuzz/**/*.py",
                                   "web/src/*.js", "web/wasm/*.[ch]", "web/tools/*.mjs",
                                   "web/*.html"])
         if f not in EXEMPT]


def test_the_lists_are_not_empty():
    assert "README.md" in DOCS and os.path.join("docs", "physics.md") in DOCS
    assert any(f.startswith("examples") for f in PROSE)


@pytest.mark.parametrize("path", PROSE)
def test_no_pointer_outside_the_repository(path):
    with open(os.path.join(ROOT, path), errors="replace") as f:
        text = f.read()
    found = [f"line {text.count(chr(10), 0, m.start()) + 1}: {what}: {m.group()!r}"
             for rx, what in _FORBIDDEN for m in rx.finditer(text)]
    assert not found, "\n".join(found)


@pytest.mark.parametrize("path", DOCS)
def test_relative_links_resolve(path):
    with open(os.path.join(ROOT, path)) as f:
        text = f.read()
    base = os.path.dirname(os.path.join(ROOT, path))
    missing = []
    for target in re.findall(r"\]\(([^)\s]+)\)", text):
        if re.match(r"[a-z]+:", target) or target.startswith("#"):
            continue
        target = target.split("#")[0]
        if not os.path.exists(os.path.normpath(os.path.join(base, target))):
            missing.append(target)
    assert not missing, f"{path}: links to missing files: {missing}"


def test_physics_sections_cited_exist():
    with open(os.path.join(ROOT, "docs", "physics.md")) as f:
        sections = {int(n) for n in re.findall(r"^## (\d+)\.", f.read(), flags=re.M)}
    assert sections == set(range(1, max(sections) + 1)), "sections numbered 1..N"
    cite = re.compile(r"physics\.md\)?,?\s+(?:sections?|sec\.)\s+(\d+)(?:\s*(?:-|and|,|to)\s*(\d+))?")
    bad = []
    for path in _files(["README.md", "docs/*.md", "include/*.h", "src/**/*.[ch]", "tables/*.[ch]",
                        "include/orbillum/*.h",
                        "bake/**/*.py", "tests/**/*.py", "tests/**/*.[ch]", "tools/**/*.py",
                        "examples/**/*.[ch]", "examples/**/*.py", "python/**/*.py"]):
        with open(os.path.join(ROOT, path), errors="replace") as f:
            for m in cite.finditer(f.read()):
                for n in filter(None, m.groups()):
                    if int(n) not in sections:
                        bad.append(f"{path}: {m.group()!r}")
    assert not bad, "\n".join(bad)
