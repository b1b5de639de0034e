# SPDX-License-Identifier: MIT
"""include/orbillum.h is an umbrella over one header per section (include/orbillum/*.h).

- The umbrella declares nothing itself and includes every section header; its
  opening comment names each one (which header holds what).
- Every public name (OI_* macro, enum constant, typedef, struct tag, function)
  is declared in exactly one header.
- Each section header includes base.h first, then the section headers whose
  names its code uses, and no other: a section it includes is one it uses, a
  name of another section that it uses comes from a section it includes
  itself (an incomplete `struct oi_x *` needs none). No include cycle, and the
  umbrella includes each section after the sections it uses.
- Each section, included alone, carries the precision guard: in a
  single-precision build its functions are the _sp names (oi_config.h).
tests/c/header_sections.sh (make test-headers) compiles each one alone.
"""
import glob
import os
import re
import shutil
import subprocess

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
INCLUDE = os.path.join(ROOT, "include")
UMBRELLA = os.path.join(INCLUDE, "orbillum.h")
SECTIONS = sorted(glob.glob(os.path.join(INCLUDE, "orbillum", "*.h")))
NAMES = [os.path.basename(p) for p in SECTIONS]
PUBLIC = sorted(glob.glob(os.path.join(INCLUDE, "*.h"))) + SECTIONS


def _read(path):
    with open(path) as f:
        return f.read()


def _code(path):
    """The header without its comments."""
    text = re.sub(r"/\*.*?\*/", " ", _read(path), flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def _includes(path):
    return re.findall(r'^[ \t]*#[ \t]*include[ \t]+"([^"]+)"', _code(path), flags=re.M)


def _declared(path):
    """{name: kind} of every public name the header declares itself."""
    code = _code(path)
    names = {}
    for n in re.findall(r"^[ \t]*#[ \t]*define[ \t]+(OI_\w+)", code, flags=re.M):
        names[n] = "macro"
    for body in re.findall(r"\benum\s+\w*\s*\{(.*?)\}", code, flags=re.S):
        for n in re.findall(r"\b(OI_\w+)\s*=", body):
            names[n] = "enum constant"
    for n in re.findall(r"\benum\s+(\w+)\s*\{", code):
        names["enum " + n] = "enum tag"
    for tag, name in re.findall(r"typedef\s+struct\s+(\w+)\s*\{[^{}]*\}\s*(\w+)\s*;", code):
        names["struct " + tag] = "struct tag"
        names[name] = "typedef"
    for n in re.findall(r"^(?:const\s+)?[A-Za-z_][\w ]*?[\s*]+(oi_\w+)\s*\(", code, flags=re.M):
        names[n] = "function"
    return names


def _used(path):
    """Identifiers the header's code uses (its own names, include lines and the
    tags of incomplete `struct oi_x` references left out)."""
    code = re.sub(r'^[ \t]*#[ \t]*include[^\n]*$', " ", _code(path), flags=re.M)
    code = re.sub(r"\bstruct\s+\w+\s*\*", " ", code)  # a pointer to an incomplete struct
    own = _declared(path)
    return {w for w in re.findall(r"\b[A-Za-z_]\w*\b", code) if w not in own}


def test_the_sections_are_found():
    """The parse works (else every test below is vacuous): known names in their sections."""
    where = {n: os.path.basename(p) for p in PUBLIC for n in _declared(p)}
    for name, header in [("OI_VERSION", "base.h"), ("OI_ERR_SHAPE", "base.h"),
                         ("oi_model", "model.h"), ("OI_TERM_SKY", "model.h"),
                         ("oi_atm_table_default", "tables.h"), ("OI_ATM_TOP_MAX_KM", "tables.h"),
                         ("oi_cap_overlap", "geometry.h"), ("oi_shadow", "shadow.h"),
                         ("oi_sun_fraction", "shadow.h"), ("oi_skylight", "sources.h"),
                         ("oi_moon_phase_law", "sources.h"), ("oi_galactic_from_icrs", "sky.h"),
                         ("struct oi_shape", "shape.h"), ("oi_illuminate", "scene.h"),
                         ("OI_CAMERA_MAX_TIMES", "camera.h"), ("oi_expose_scene", "camera.h"),
                         ("OI_BATCH_MAX", "batch.h"), ("oi_expose_scene_batch_outputs", "batch.h"),
                         ("oi_atm_table", "oi_table.h"), ("OI_AU_KM", "oi_constants.h")]:
        assert where.get(name) == header, f"{name}: in {where.get(name)}, expected {header}"
    assert "oi_model" in _used(os.path.join(INCLUDE, "orbillum", "shadow.h"))
    assert "oi_shape" not in _used(os.path.join(INCLUDE, "orbillum", "scene.h")), \
        "scene.h's `const struct oi_shape *` is an incomplete type: it needs no shape.h"
    functions = [n for p in SECTIONS for n, kind in _declared(p).items() if kind == "function"]
    assert len(functions) == len(set(functions)) == 40, len(functions)


def test_umbrella_declares_nothing_and_includes_every_section():
    lines = [ln.strip() for ln in _code(UMBRELLA).splitlines() if ln.strip()]
    others = [ln for ln in lines if not re.match(
        r'#\s*(include\s+"[^"]+"|ifndef ORBILLUM_H|define ORBILLUM_H|endif)$', ln)]
    assert not others, f"include/orbillum.h declares: {others}"
    sections = [i for i in _includes(UMBRELLA) if i.startswith("orbillum/")]
    assert sorted(sections) == sorted("orbillum/" + n for n in NAMES)
    assert len(set(sections)) == len(sections)
    opening = re.match(r"\s*/\*.*?\*/\s*/\*(.*?)\*/", _read(UMBRELLA), flags=re.S).group(1)
    unnamed = [n for n in NAMES if not re.search(r"^\s*\*\s+%s\s" % re.escape(n), opening,
                                                  flags=re.M)]
    assert not unnamed, f"the umbrella's opening comment does not say what {unnamed} hold"


def test_every_name_is_declared_once():
    seen = {}
    for path in PUBLIC:
        for name in _declared(path):
            seen.setdefault(name, []).append(os.path.relpath(path, INCLUDE))
    assert len(seen) > 150, "the parse found too few names"
    twice = {n: p for n, p in seen.items() if len(p) > 1}
    assert not twice, f"declared in more than one header: {twice}"


@pytest.mark.parametrize("name", NAMES)
def test_section_includes_what_it_uses(name):
    path = os.path.join(INCLUDE, "orbillum", name)
    inc = _includes(path)
    siblings = [i for i in inc if "/" not in i]
    outside = [i for i in inc if "/" in i]
    assert all(re.fullmatch(r"\.\./oi_\w+\.h", i) for i in outside), outside
    if name != "base.h":
        assert inc and inc[0] == "base.h", f"{name}: base.h is not its first include"
    used = _used(path)
    for sib in siblings:
        assert os.path.exists(os.path.join(INCLUDE, "orbillum", sib)), f"{name}: {sib}"
        if sib != "base.h":
            names = set(_declared(os.path.join(INCLUDE, "orbillum", sib)))
            assert used & names, f"{name} includes {sib} and uses nothing of it"
    for other in NAMES:
        if other in siblings or other == name:
            continue
        names = set(_declared(os.path.join(INCLUDE, "orbillum", other)))
        assert not used & names, \
            f"{name} uses {sorted(used & names)} of {other} without including it"


def test_no_include_cycle_and_the_umbrella_order():
    graph = {n: [i for i in _includes(os.path.join(INCLUDE, "orbillum", n)) if "/" not in i]
             for n in NAMES}
    order = [i[len("orbillum/"):] for i in _includes(UMBRELLA) if i.startswith("orbillum/")]
    for pos, n in enumerate(order):
        late = [d for d in graph[n] if d not in order[:pos]]
        assert not late, f"the umbrella includes {n} before {late}, which it uses"
    # a cycle would need an edge to a later section: none above, so none


@pytest.fixture(scope="module")
def cc():
    cc = os.environ.get("CC", "cc")
    if shutil.which(cc) is None:
        pytest.fail(f"no C compiler {cc!r}")
    return cc


def _preprocessed(cc, header, defs):
    return subprocess.run([cc, "-E", "-P", "-x", "c", "-I" + INCLUDE] + defs + ["-"],
                          input=f'#include "{header}"\n', capture_output=True, text=True,
                          check=True).stdout


def _called(text, fn):
    """The name a declaration of fn has after preprocessing (fn or fn_sp), or None."""
    m = re.search(r"\b(%s(?:_sp)?)\s*\(" % fn, text)
    return m and m.group(1)


@pytest.mark.parametrize("name", NAMES)
def test_section_alone_has_the_precision_guard(cc, name):
    """Alone, a section names its functions as the umbrella does, in both precisions
    (the _sp names of a single-precision build, oi_config.h)."""
    functions = [n for n, kind in _declared(os.path.join(INCLUDE, "orbillum", name)).items()
                 if kind == "function"]
    renamed = 0
    for defs in ([], ["-DOI_SINGLE_PRECISION"]):
        alone = _preprocessed(cc, "orbillum/" + name, defs)
        whole = _preprocessed(cc, "orbillum.h", defs)
        for fn in functions:
            got, want = _called(alone, fn), _called(whole, fn)
            assert want and got == want, f"{name} alone declares {got}, orbillum.h {want}"
            renamed += bool(defs) and got == fn + "_sp"
    assert renamed or not functions, f"{name}: no function renamed _sp"


def test_every_function_has_its_single_precision_name(cc):
    """Every public function is named fn_sp in a single-precision build (oi_config.h),
    so that float code never links a double archive's function silently."""
    functions = sorted(n for path in PUBLIC for n, kind in _declared(path).items()
                       if kind == "function")
    float_text = _preprocessed(cc, "orbillum.h", ["-DOI_SINGLE_PRECISION"])
    plain = [fn for fn in functions if _called(float_text, fn) != fn + "_sp"]
    assert len(functions) >= 40
    assert not plain, f"no _sp name in a single-precision build: {plain}"
