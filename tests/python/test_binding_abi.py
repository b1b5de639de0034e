# SPDX-License-Identifier: MIT
"""The binding's ctypes mirror (python/orbillum/_lib.py) is include/*.h exactly
(include/orbillum.h and its section headers include/orbillum/*.h).

Two independent checks, both of which fail on anything the header has and
the mirror lacks:
  - a parse of the header text: enum oi_status, every numeric OI_* #define,
    every `typedef struct` body (field names in order, their C types) and
    every function prototype, each compared with the mirror by name and type;
  - a C program compiled with the real header (cc, -Iinclude) that prints the
    value of every constant and sizeof/offsetof of every field of every
    structure, compared with the mirror's values and ctypes layout.
The double build is mirrored (the binding loads only that one).
"""
import ctypes
import glob
import os
import re
import shutil
import subprocess

import pytest

import _oi_ctypes

ROOT = _oi_ctypes.ROOT
INCLUDE = os.path.join(ROOT, "include")
L = _oi_ctypes.load_mirror()

_SCALARS = {
    "oi_real": ctypes.c_double, "double": ctypes.c_double, "float": ctypes.c_float,
    "int": ctypes.c_int, "unsigned": ctypes.c_uint, "unsigned int": ctypes.c_uint,
    "long": ctypes.c_long, "unsigned long": ctypes.c_ulong, "unsigned short": ctypes.c_ushort,
    "size_t": ctypes.c_size_t,
}


def _header_text():
    """Every public header (the section headers of include/orbillum/ too), comments
    removed, concatenated."""
    out = []
    for path in (sorted(glob.glob(os.path.join(INCLUDE, "*.h"))) +
                 sorted(glob.glob(os.path.join(INCLUDE, "orbillum", "*.h")))):
        with open(path) as f:
            text = f.read()
        text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
        out.append(re.sub(r"//[^\n]*", " ", text))
    return "\n".join(out)


HEADER = _header_text()


def _is_constant_expression(value):
    """A number or an arithmetic expression of numbers and OI_* names."""
    tokens = re.findall(r"[A-Za-z_]\w*|\d[\w.]*(?:[eE][+-]?\d+)?|\S", value)
    for tok in tokens:
        if re.match(r"[A-Za-z_]", tok) and not tok.startswith("OI_"):
            return False
        if not re.match(r"[A-Za-z_\d]", tok) and tok not in "()+-*/|&~<>.":
            return False
    return bool(tokens)


def header_constants():
    """{name: C expression} of enum oi_status and every numeric object-like OI_* macro."""
    consts = {}
    for body in re.findall(r"\benum\s+\w*\s*\{(.*?)\}", HEADER, flags=re.S):
        for name, value in re.findall(r"\b(OI_\w+)\s*=\s*([^,]+)", body):
            consts[name] = value.strip()
    for name, value in re.findall(r"^[ \t]*#[ \t]*define[ \t]+(OI_\w+)[ \t]+([^\n]+)$",
                                  HEADER, flags=re.M):
        value = value.strip()
        if _is_constant_expression(value):
            consts[name] = value
    return consts


def _split_declaration(decl):
    """'const oi_real a, b[3]' -> [('const oi_real', '', 'a', None), (.., 'b', '3')]."""
    decl = " ".join(decl.split())
    first, *rest = [p.strip() for p in decl.split(",")]
    m = re.match(r"^(?P<type>.+?)\s*(?P<ptr>\**)\s*(?P<name>\w+)\s*(?:\[(?P<dim>[^\]]+)\])?$",
                 first)
    assert m, f"cannot parse the declaration {decl!r}"
    ctype = m.group("type")
    out = [(ctype, m.group("ptr"), m.group("name"), m.group("dim"))]
    for part in rest:
        m = re.match(r"^(?P<ptr>\**)\s*(?P<name>\w+)\s*(?:\[(?P<dim>[^\]]+)\])?$", part)
        assert m, f"cannot parse the declarator {part!r} in {decl!r}"
        out.append((ctype, m.group("ptr"), m.group("name"), m.group("dim")))
    return out


def header_structs():
    """{struct name: [(field, C type, pointer stars, array dimension or None)]}."""
    structs = {}
    for tag, body, name in re.findall(r"typedef\s+struct\s+(\w+)\s*\{(.*?)\}\s*(\w+)\s*;",
                                      HEADER, flags=re.S):
        assert tag == name, f"struct {tag} is typedef'd as {name}"
        fields = []
        for decl in body.split(";"):
            if decl.strip():
                fields += [(n, t, p, d) for t, p, n, d in _split_declaration(decl)]
        structs[name] = fields
    return structs


def header_functions():
    """{function name: (return type, [(C type, pointer stars or '[]')])}."""
    text = re.sub(r"^[ \t]*#[^\n]*$", " ", HEADER, flags=re.M)  # preprocessor lines
    text = text.replace('extern "C" {', " ")  # each section header has its own
    text = re.sub(r"\{[^{}]*\}", " ", text)  # struct and enum bodies
    text = text.replace("}", " ")
    funcs = {}
    for statement in text.split(";"):
        m = re.match(r"^\s*((?:const\s+)?[\w ]+?[\s*]+)(oi_\w+)\s*\(([^()]*)\)\s*$",
                     statement, flags=re.S)
        if not m or m.group(1).lstrip().startswith("typedef"):
            continue
        ret, name, args = " ".join(m.group(1).split()), m.group(2), m.group(3)
        params = []
        if args.strip() != "void":
            for a in args.split(","):
                ctype, ptr, _n, dim = _split_declaration(a)[0]
                params.append((ctype, ptr + ("[]" if dim else "")))
        funcs[name] = (ret, params)
    return funcs


def _base(ctype):
    return " ".join(w for w in ctype.split() if w not in ("const", "volatile", "struct"))


def _expected_scalar(ctype):
    base = _base(ctype)
    if base in _SCALARS:
        return _SCALARS[base]
    mirrored = getattr(L, base, None)
    assert isinstance(mirrored, type) and issubclass(mirrored, ctypes.Structure), \
        f"C type {base!r} has no mirror in _lib.py"
    return mirrored


def _pointer_ok(ctype, got):
    """A pointer field or parameter: char * as c_char_p, others as c_void_p or
    POINTER(the mirror of what it points to)."""
    base = _base(ctype)
    if base == "char":
        return got is ctypes.c_char_p
    if got is ctypes.c_void_p:
        return True
    if base == "void":
        return False
    return (isinstance(got, type) and issubclass(got, ctypes._Pointer)
            and got._type_ is _expected_scalar(ctype))


def _field_type_ok(ctype, ptr, dim, got):
    if dim is not None:
        length = eval(dim, {}, vars(L))  # the dimension is a mirrored constant
        return (isinstance(got, type) and issubclass(got, ctypes.Array)
                and got._length_ == length and _field_type_ok(ctype, ptr, None, got._type_))
    if ptr:
        return _pointer_ok(ctype, got)
    return got is _expected_scalar(ctype)


# ---------------------------------------------------------------- the header parse

def test_parse_finds_the_header():
    """The parse itself works: known names are found (else every test below is vacuous)."""
    consts, structs, funcs = header_constants(), header_structs(), header_functions()
    for name in ("OI_ERR_GEOMETRY", "OI_FLAG_RESOLVED", "OI_TERM_ALL", "OI_SHADOW_ANNULAR",
                 "OI_EARTH_LAMBERT", "OI_TABLE_FORMAT", "OI_AU_KM"):
        assert name in consts, name
    for name in ("oi_model", "oi_illum", "oi_camera", "oi_earth_table", "oi_atm_table"):
        assert name in structs, name
    atm = [f[0] for f in structs["oi_atm_table"]]
    assert "q_min" in atm and "q_scale" in atm, "two declarators on one line"
    for name in ("oi_illuminate", "oi_expose_scene", "oi_status_name", "oi_flag_name"):
        assert name in funcs, name


def test_every_constant_is_mirrored():
    consts = header_constants()
    missing = sorted(n for n in consts if not hasattr(L, n))
    assert not missing, f"constants of include/*.h missing from python/orbillum/_lib.py: {missing}"


def test_no_constant_beyond_the_header():
    consts = header_constants()
    extra = sorted(n for n in vars(L) if n.startswith("OI_") and n not in consts)
    assert not extra, f"_lib.py constants the header does not define: {extra}"


def test_every_struct_is_mirrored_field_by_field():
    structs = header_structs()
    mirrored = {st.__name__: st for st in L.STRUCTS}
    assert sorted(mirrored) == sorted(structs), "structures of the header vs _lib.STRUCTS"
    for name, fields in structs.items():
        st = mirrored[name]
        assert [f[0] for f in fields] == [f for f, _t in st._fields_], f"{name}: field names/order"
        for (field, ctype, ptr, dim), (_f, got) in zip(fields, st._fields_):
            assert _field_type_ok(ctype, ptr, dim, got), \
                f"{name}.{field}: C {ctype} {ptr}{'[' + dim + ']' if dim else ''} vs ctypes {got}"


def test_every_function_has_its_prototype():
    funcs = header_functions()
    assert sorted(funcs) == sorted(L._PROTOS), "functions of the header vs _lib._PROTOS"
    for name, (ret, params) in funcs.items():
        res, args = L._PROTOS[name]
        if ret == "void":
            assert res is None, name
        elif ret.rstrip().endswith("*"):
            assert _pointer_ok(ret.rstrip("* "), res), f"{name}: returns {ret}, mirror {res}"
        else:
            assert res is _expected_scalar(ret), f"{name}: returns {ret}, mirror {res}"
        assert len(args) == len(params), f"{name}: {len(params)} parameters, mirror {len(args)}"
        for i, ((ctype, ptr), got) in enumerate(zip(params, args)):
            if ptr:
                assert _pointer_ok(ctype, got), f"{name} parameter {i}: {ctype} {ptr} vs {got}"
            else:
                assert got is _expected_scalar(ctype), f"{name} parameter {i}: {ctype} vs {got}"


# ---------------------------------------------------------------- the compiled header

@pytest.fixture(scope="module")
def c_header(tmp_path_factory):
    """Values and layouts as the C compiler sees them: {('const', name): repr}
    and {(struct, field): (offset, size)}, {(struct, 'sizeof'): (size,)}."""
    cc = os.environ.get("CC", "cc")
    if shutil.which(cc) is None:
        pytest.fail(f"no C compiler {cc!r}: the binding cannot be built either")
    lines = ['#include <stdio.h>', '#include <stddef.h>', '#include "orbillum.h"',
             "int main(void) {"]
    for name in header_constants():
        lines.append(f'printf("const {name} %.17g\\n", (double)({name}));')
    for n, fields in header_structs().items():
        lines.append(f'printf("{n} sizeof %zu\\n", sizeof({n}));')
        for f, *_ in fields:
            lines.append(f'printf("{n} {f} %zu %zu\\n", offsetof({n}, {f}), '
                         f'sizeof(((({n} *)0)->{f})));')
    lines.append("return 0; }")
    tmp = tmp_path_factory.mktemp("abi")
    src = tmp / "layout.c"
    src.write_text("\n".join(lines) + "\n")
    exe = tmp / "layout"
    subprocess.check_call([cc, "-std=c99", "-Wall", "-Werror", "-I" + INCLUDE, str(src),
                           "-o", str(exe)])
    out = {}
    for ln in subprocess.check_output([str(exe)], text=True).splitlines():
        parts = ln.split()
        if parts[0] == "const":
            out[("const", parts[1])] = float(parts[2])
        else:
            out[tuple(parts[:2])] = tuple(int(x) for x in parts[2:])
    return out


def test_constant_values_match_header(c_header):
    for name in header_constants():
        want = c_header[("const", name)]
        got = getattr(L, name)
        assert float(got) == want, f"{name}: header {want!r}, mirror {got!r}"


def test_struct_layouts_match_header(c_header):
    for st in L.STRUCTS:
        n = st.__name__
        assert c_header[(n, "sizeof")] == (ctypes.sizeof(st),), f"{n}: sizeof"
        for f, _t in st._fields_:
            desc = getattr(st, f)
            assert c_header[(n, f)] == (desc.offset, desc.size), f"{n}.{f}: offset/size"
