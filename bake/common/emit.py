# SPDX-License-Identifier: MIT
"""The one emitter of baked tables: a Table -> generated C (.c, .h) and a JSON sidecar.

Every kind of table (include/oi_table.h: earthshine, atmosphere, ...) goes
through `render`: the .c holds the payload arrays (static), the provenance
(an oi_table_info) and the const table struct; the .h declares the table and
its info, nothing else; the sidecar states the same facts for tools, in one
schema for every kind:

  format, kind, type, name       layout version, table kind, C type and name
  generator, generator_version   module that baked it, bake package version
  parameters                     the bake configuration (also in the .c, as
                                 canonical JSON: oi_table_info.parameters)
  seed                           random seed of the measurement points
  goal, max_error                the accuracy goal and the measured worst
                                 error in units of it
  measured                       every measured figure (rounded, see below)
  grid                           the grid description (the struct's fields)
  payload_sha256, payload_bytes  hash of the payload (arrays in field order,
                                 little-endian element bytes) and its size
  provenance                     the comment block of the .c, line by line

Byte for byte reproducible: no timestamp; float32 payload printed with 9
significant digits (round-trips any float32), doubles with 17; measured
figures rounded to 4 significant digits by the bakers so that the text does
not depend on the last bits of a library routine.
"""

import hashlib
import json
import os
import re

import numpy as np

PER_LINE_FLOAT = 6
PER_LINE_U16 = 12
STRING_CHUNK = 64


def f32(a):
    return np.asarray(a, dtype=np.float64).astype(np.float32)


def c_float(v):
    """A float32 value as a C float literal with 9 significant digits."""
    s = "%.9g" % float(v)
    if s in ("nan", "inf", "-inf"):
        raise ValueError("non-finite value in a table")
    if "." not in s and "e" not in s:
        s += ".0"
    return s + "f"


def c_double(v):
    """A double as a C literal that reads back as the same double (the
    shortest such text, Python's repr)."""
    s = repr(float(v))
    if s in ("nan", "inf", "-inf"):
        raise ValueError("non-finite constant in a table")
    if "." not in s and "e" not in s:
        s += ".0"
    return s


def c_string(s, indent="        "):
    """A C string literal (ASCII), split into concatenated pieces."""
    if any(ord(ch) > 126 or ord(ch) < 32 for ch in s):
        raise ValueError("non-printable or non-ASCII text in a table string")
    esc = s.replace("\\", "\\\\").replace('"', '\\"')
    if len(esc) <= STRING_CHUNK:
        return '"%s"' % esc
    parts = []
    k = 0
    while k < len(esc):
        e = min(k + STRING_CHUNK, len(esc))
        if esc[e - 1] == "\\":  # do not split an escape
            e += 1
        parts.append('"%s"' % esc[k:e])
        k = e
    return ("\n" + indent).join(parts)


def canonical_json(obj):
    """The one text of a parameter set: sorted keys, no spaces."""
    return json.dumps(obj, sort_keys=True, separators=(",", ":"), allow_nan=False)


def round_sig(v, digits=4):
    """v rounded to `digits` significant digits (measured figures)."""
    return float("%.*g" % (digits, float(v)))


# element types of the payload: C type, numpy little-endian dtype, literal
_ELEM = {
    "float": ("float", "<f4", c_float, PER_LINE_FLOAT),
    "u16": ("unsigned short", "<u2", lambda v: "%d" % int(v), PER_LINE_U16),
}


class Table:
    """One baked table, everything the emitter writes.

    name        C name of the table (files name.{c,h,json})
    kind        "earthshine", "atmosphere", ...
    ctype       C struct type (oi_earth_table, oi_atm_table)
    format      (macro, value): the layout version, e.g. ("OI_TABLE_FORMAT", 4)
    summary     what the table is, one line (first comment line of the files)
    fields      [(field, value, type)]: type "int", "double", "real" (oi_real,
                cast), "err" (double printed with 4 digits), "macro" (text);
                in the struct's order; the payload pointers and kind/info are
                added by the emitter at their place (see layout)
    arrays      [(field, values, elem)]: payload, elem "float" or "u16"
    layout      struct field order including the arrays' fields and "kind",
                "info", "format" (the emitter fills them in this order)
    generator   module that baked it (e.g. "bake.earthshine")
    version     bake package version
    parameters  bake configuration (dict)
    seed, goal, max_error, measured, grid: see the module docstring
    provenance  comment lines of the .c (without the payload hash line, added)
    command     optional: the `python -m bake` target that writes it (default kind)
    """

    def __init__(self, **kw):
        for k in ("name", "kind", "ctype", "format", "summary", "fields", "arrays", "layout",
                  "generator", "version", "parameters", "seed", "goal", "max_error",
                  "measured", "grid", "provenance"):
            setattr(self, k, kw.pop(k))
        self.kind_macro = "OI_TABLE_KIND_" + self.kind.upper()
        # the `python -m bake` target that writes it (default: its kind)
        self.command = kw.pop("command", self.kind)
        if kw:
            raise TypeError("unknown Table fields: %s" % ", ".join(sorted(kw)))

    def payload(self):
        """[(field, little-endian ndarray)] in field order, checked."""
        out = []
        for field, values, elem in self.arrays:
            dt = _ELEM[elem][1]
            a = np.asarray(values)
            if elem == "float":
                a = f32(a)
                if not np.all(np.isfinite(a)):
                    raise ValueError("%s.%s: non-finite value" % (self.name, field))
            else:
                if a.min() < 0 or a.max() > 0xFFFF or np.any(a != np.rint(a)):
                    raise ValueError("%s.%s: not 16-bit codes" % (self.name, field))
            out.append((field, a.astype(dt).ravel()))
        return out

    def payload_sha256(self):
        h = hashlib.sha256()
        for _, a in self.payload():
            h.update(a.tobytes())
        return h.hexdigest()

    def payload_bytes(self):
        return int(sum(a.nbytes for _, a in self.payload()))


def _array(cname, elem, values):
    ctype, _, fmt, per_line = _ELEM[elem]
    vals = [fmt(v) for v in values]
    lines = ["    " + ", ".join(vals[k:k + per_line]) + "," for k in range(0, len(vals), per_line)]
    return "static const %s %s[%d] = {\n%s\n};\n" % (ctype, cname, len(vals), "\n".join(lines))


def _value(v, typ):
    if typ == "int":
        return "%d" % int(v)
    if typ == "double":
        return c_double(v)
    if typ == "real":
        return "(oi_real)" + c_double(v)
    if typ == "err":
        return "%.3e" % float(v)
    if typ == "macro":
        return str(v)
    raise ValueError("unknown field type %r" % typ)


def provenance_lines(t):
    return list(t.provenance) + [
        "Payload sha256 (arrays in field order, little-endian): %s" % t.payload_sha256(),
        "Flash: %d bytes of payload." % t.payload_bytes(),
    ]


def render(t):
    """(c_text, h_text, json_text) of a Table."""
    payload = dict(t.payload())
    fmt_macro, fmt_value = t.format
    up = t.name.upper()
    guard = up + "_H"
    generated = ["Generated by `python -m bake %s` (%s %s); do not edit:" % (
                     t.command, t.generator, t.version),
                 "`make check-generated` re-bakes it and compares byte for byte."]

    h = ["/* SPDX-License-Identifier: MIT */",
         "/*",
         " * %s.h: %s" % (t.name, t.summary)] + [" * " + g for g in generated] + [
         " * Provenance: %s.c and %s.json." % (t.name, t.name),
         " */",
         "#ifndef %s" % guard,
         "#define %s" % guard,
         "",
         '#include "oi_table.h"',
         "",
         "extern const %s %s;" % (t.ctype, t.name),
         "extern const oi_table_info %s_info;" % t.name,
         ""]
    h += ["#endif /* %s */" % guard, ""]

    prov = [(" * " + s).rstrip() for s in provenance_lines(t)]
    c = ["/* SPDX-License-Identifier: MIT */",
         "/*",
         " * %s.c: %s" % (t.name, t.summary)] + [" * " + g for g in generated] + [
         " *"] + prov + [
         " */",
         '#include "%s.h"' % t.name,
         "",
         "#if %s != %d" % (fmt_macro, fmt_value),
         '#error "%s.c: table format %d expected: regenerate the tables (python -m bake all)"' % (
             t.name, fmt_value),
         "#endif",
         ""]
    for field, _, elem in t.arrays:
        c.append(_array("%s_%s" % (t.name, field), elem, payload[field]))
    c += ["const oi_table_info %s_info = {" % t.name,
          "    .name = %s," % c_string(t.name),
          "    .generator = %s," % c_string("%s %s" % (t.generator, t.version)),
          "    .parameters = %s," % c_string(canonical_json(t.parameters)),
          "    .payload_sha256 = %s," % c_string(t.payload_sha256()),
          "    .seed = %dUL," % int(t.seed),
          "    .max_error = %s," % c_double(t.max_error),
          "    .goal = %s," % c_double(t.goal),
          "};",
          "",
          "const %s %s = {" % (t.ctype, t.name)]
    fields = {f: (v, typ) for f, v, typ in t.fields}
    arrays = {f for f, _, _ in t.arrays}
    for f in t.layout:
        if f == "format":
            c.append("    .format = %s," % fmt_macro)
        elif f == "kind":
            c.append("    .kind = %s," % t.kind_macro)
        elif f == "info":
            c.append("    .info = &%s_info," % t.name)
        elif f in arrays:
            c.append("    .%s = %s_%s," % (f, t.name, f))
        else:
            v, typ = fields[f]
            c.append("    .%s = %s," % (f, _value(v, typ)))
    missing = (set(fields) | arrays) - set(t.layout)
    if missing:
        raise ValueError("fields not in the layout: %s" % ", ".join(sorted(missing)))
    c += ["};", ""]

    side = {
        "format": fmt_value, "kind": t.kind, "type": t.ctype, "name": t.name,
        "generator": t.generator, "generator_version": t.version,
        "parameters": t.parameters, "seed": int(t.seed),
        "goal": float(t.goal), "max_error": float(t.max_error),
        "measured": t.measured, "grid": t.grid,
        "payload_sha256": t.payload_sha256(), "payload_bytes": t.payload_bytes(),
        "provenance": provenance_lines(t),
    }
    return "\n".join(c), "\n".join(h), sidecar_text(side)


def sidecar_text(side):
    """The sidecar's bytes: JSON, keys sorted, indented by 2, one newline at the end."""
    return json.dumps(side, indent=2, sort_keys=True, allow_nan=False) + "\n"


def write(outdir, t):
    """Write outdir/name.{c,h,json}; returns the three paths."""
    os.makedirs(outdir, exist_ok=True)
    paths = []
    for ext, text in zip(("c", "h", "json"), render(t)):
        p = os.path.join(outdir, "%s.%s" % (t.name, ext))
        with open(p, "w", encoding="ascii", newline="\n") as f:
            f.write(text)
        paths.append(p)
    return paths


# ----------------------------------------------------------------- parse back (tests, tools)

_ARRAY_RE = re.compile(r"static const (float|unsigned short) (\w+)\[(\d+)\] = \{(.*?)\};", re.S)
_STRUCT_RE = re.compile(r"^const (\w+) (\w+) = \{\n(.*?)^\};", re.S | re.M)
_STR_RE = re.compile(r'"((?:[^"\\]|\\.)*)"')


def _field_value(text):
    text = text.strip()
    if text.startswith('"'):
        return "".join(re.sub(r"\\(.)", r"\1", s) for s in _STR_RE.findall(text))
    if text.startswith("(oi_real)"):
        return float(text[len("(oi_real)"):])
    if text.startswith("&"):
        return text
    if re.fullmatch(r"-?\d+(UL)?", text):
        return int(text.rstrip("UL"))
    try:
        return float(text)
    except ValueError:
        return text  # a macro or an array name


def parse_c(c_text):
    """A generated .c read back: {"arrays": {cname: ndarray}, "structs":
    {cname: {"type": ctype, "fields": {field: value}}}}; floats as float32,
    codes as uint16, numbers as Python numbers, strings unescaped."""
    out = {"arrays": {}, "structs": {}}
    for m in _ARRAY_RE.finditer(c_text):
        toks = [v.strip() for v in m.group(4).replace("\n", " ").split(",") if v.strip()]
        if len(toks) != int(m.group(3)):
            raise ValueError("array %s: %d values, declared %s" % (m.group(2), len(toks), m.group(3)))
        if m.group(1) == "float":
            a = np.array([float(v.rstrip("f")) for v in toks], dtype=np.float32)
        else:
            a = np.array([int(v) for v in toks], dtype=np.uint16)
        out["arrays"][m.group(2)] = a
    for m in _STRUCT_RE.finditer(c_text):
        fields = {}
        cur = None
        for line in m.group(3).split("\n"):
            fm = re.match(r"    \.(\w+) = (.*)$", line)
            if fm:
                cur = fm.group(1)
                fields[cur] = fm.group(2)
            elif cur is not None and line.strip():
                fields[cur] += " " + line.strip()
        out["structs"][m.group(2)] = {
            "type": m.group(1),
            "fields": {k: _field_value(v.rstrip().rstrip(",")) for k, v in fields.items()}}
    return out


def read(tables_dir, name):
    """(parsed .c, sidecar dict) of a committed table."""
    with open(os.path.join(tables_dir, name + ".c"), encoding="ascii") as f:
        parsed = parse_c(f.read())
    with open(os.path.join(tables_dir, name + ".json"), encoding="ascii") as f:
        side = json.load(f)
    return parsed, side


def payload_of(parsed, name):
    """The payload arrays of table `name` in its field order: [(field, ndarray)]."""
    fields = parsed["structs"][name]["fields"]
    out = []
    for f, v in fields.items():
        if isinstance(v, str) and v == "%s_%s" % (name, f) and v in parsed["arrays"]:
            out.append((f, parsed["arrays"][v]))
    return out
