#!/usr/bin/env python3
"""Independent counts of the B-rep in STEP (ISO 10303-21) files.

A second reader, written from the standard and sharing nothing with the
exact-bezier crate, so that the crate's STEP reader can be checked against
it.  Pure Python 3 standard library.

    python3 benches/peers/step_counts.py FILE... > counts.json
    python3 benches/peers/step_counts.py --self-test

For every file it prints (one JSON object keyed by file name):

* ``header``: schema, originating system and preprocessor from FILE_NAME;
* ``faces``: ADVANCED_FACE and FACE_SURFACE instances by the type of the
  surface they reference (``by_surface``: complex instances named by their
  most specific part, see ``kind``), plus the raw entity names
  (``by_surface_entity``);
* ``edges``: EDGE_CURVE instances by the type of their curve
  (``by_curve``) and, with SURFACE_CURVE / SEAM_CURVE /
  INTERSECTION_CURVE resolved to their 3D curve, ``by_curve_3d``;
* ``vertices``: VERTEX_POINT count; ``shells`` (CLOSED/OPEN) and ``solids``;
* ``edge_uses``: how the face loops use each EDGE_CURVE (through
  ORIENTED_EDGE): ``shared`` (two faces), ``seam`` (one face twice),
  ``open`` (once), ``non_manifold`` (more than two uses), ``unused``;
* ``knot_lines``: for each face on a B-spline surface with interior knots,
  each knot with the continuity its multiplicity gives (see ``knot_lines``);
* ``contexts``: for each representation context with units, its length,
  plane-angle and solid-angle units and UNCERTAINTY_MEASURE_WITH_UNIT
  values (as written in the file, never converted to floating point);
* ``text``: bytes that are not ASCII (count and the first lines) and
  statements that could not be parsed (with their line).

Part 21 syntax handled: comments ``/* */``, statements spanning lines,
strings with ``''`` and the backslash escapes (\\X\\hh, \\X2\\..\\X0\\,
\\X4\\..\\X0\\, \\S\\c, \\P?\\, \\\\), complex instances ``(A() B() ...)``,
typed parameters ``LENGTH_MEASURE(1.E-07)``, enumerations, ``$`` and ``*``.
"""

import json
import sys
from collections import Counter, defaultdict

# Specificity order used to name a complex (multi-part) instance: the first
# part present in this list names it; otherwise the parts sorted and joined.
SPECIFIC_PARTS = [
    "RATIONAL_B_SPLINE_SURFACE",
    "RATIONAL_B_SPLINE_CURVE",
    "B_SPLINE_SURFACE_WITH_KNOTS",
    "B_SPLINE_CURVE_WITH_KNOTS",
    "BEZIER_SURFACE",
    "BEZIER_CURVE",
    "UNIFORM_SURFACE",
    "UNIFORM_CURVE",
    "QUASI_UNIFORM_SURFACE",
    "QUASI_UNIFORM_CURVE",
    "PIECEWISE_BEZIER_SURFACE",
    "PIECEWISE_BEZIER_CURVE",
    "B_SPLINE_SURFACE",
    "B_SPLINE_CURVE",
]

CURVES_ON_SURFACE = ("SURFACE_CURVE", "SEAM_CURVE", "INTERSECTION_CURVE")
SOLIDS = ("MANIFOLD_SOLID_BREP", "BREP_WITH_VOIDS", "FACETED_BREP", "SHELL_BASED_SURFACE_MODEL")
UNIT_KINDS = {"LENGTH_UNIT": "length", "PLANE_ANGLE_UNIT": "plane_angle", "SOLID_ANGLE_UNIT": "solid_angle"}


class Ref:
    """A reference ``#n`` to another instance."""

    __slots__ = ("id",)

    def __init__(self, ident):
        self.id = ident


class Enum:
    """An enumeration value ``.NAME.``."""

    __slots__ = ("name",)

    def __init__(self, name):
        self.name = name


class Typed:
    """A typed parameter ``NAME(params)`` inside a parameter list."""

    __slots__ = ("name", "params")

    def __init__(self, name, params):
        self.name = name
        self.params = params


class Number(str):
    """A numeric literal, kept as the text the file wrote."""


class ParseError(Exception):
    """A statement that does not follow the Part 21 grammar."""


def decode_string(raw):
    """Decode the Part 21 control directives of a string body (quotes removed)."""
    out = []
    i = 0
    n = len(raw)
    while i < n:
        c = raw[i]
        if c == "'" and raw.startswith("''", i):
            out.append("'")
            i += 2
        elif c == "\\" and raw.startswith("\\\\", i):
            out.append("\\")
            i += 2
        elif c == "\\" and raw.startswith("\\X\\", i):
            out.append(chr(int(raw[i + 3 : i + 5], 16)))
            i += 5
        elif c == "\\" and (raw.startswith("\\X2\\", i) or raw.startswith("\\X4\\", i)):
            width = 4 if raw[i + 2] == "2" else 8
            end = raw.find("\\X0\\", i + 4)
            if end < 0:
                raise ParseError("\\X2\\ or \\X4\\ without \\X0\\")
            hexes = raw[i + 4 : end]
            out.extend(chr(int(hexes[k : k + width], 16)) for k in range(0, len(hexes), width))
            i = end + 4
        elif c == "\\" and raw.startswith("\\S\\", i):
            out.append(chr(ord(raw[i + 3]) + 128))
            i += 4
        elif c == "\\" and raw.startswith("\\P", i) and i + 3 < n and raw[i + 3] == "\\":
            i += 4  # code page switch: no effect on the characters counted here
        else:
            out.append(c)
            i += 1
    return "".join(out)


class ParamParser:
    """Recursive-descent parser of one statement's right-hand side."""

    def __init__(self, text):
        self.s = text
        self.i = 0

    def peek(self):
        """Skip blanks and return the next character ('' at the end)."""
        s, n = self.s, len(self.s)
        while self.i < n and s[self.i] in " \t\r\n":
            self.i += 1
        return s[self.i] if self.i < n else ""

    def expect(self, ch):
        if self.peek() != ch:
            raise ParseError(f"expected {ch!r} at {self.i}: {self.s[self.i:self.i + 20]!r}")
        self.i += 1

    def keyword(self):
        s, start = self.s, self.i
        while self.i < len(s) and (s[self.i].isalnum() or s[self.i] in "_!"):
            self.i += 1
        if self.i == start:
            raise ParseError(f"expected a keyword at {start}")
        return s[start : self.i].upper()

    def instance(self):
        """``NAME(params)`` -> (name, params) or ``(A() B())`` -> complex parts."""
        if self.peek() == "(":
            self.i += 1
            parts = {}
            while self.peek() != ")":
                name = self.keyword()
                parts[name] = self.plist()
            self.i += 1
            return parts
        name = self.keyword()
        return {name: self.plist()}

    def plist(self):
        """A parenthesised, comma-separated parameter list."""
        self.expect("(")
        items = []
        if self.peek() == ")":
            self.i += 1
            return items
        while True:
            items.append(self.value())
            c = self.peek()
            self.i += 1
            if c == ")":
                return items
            if c != ",":
                raise ParseError(f"expected ',' or ')' at {self.i - 1}")

    def value(self):
        s = self.s
        c = self.peek()
        if c == "(":
            return self.plist()
        if c == "'":
            j = self.i + 1
            while True:
                j = s.find("'", j)
                if j < 0:
                    raise ParseError("unterminated string")
                if s.startswith("''", j):
                    j += 2
                    continue
                break
            raw = s[self.i + 1 : j]
            self.i = j + 1
            return decode_string(raw)
        if c == "#":
            self.i += 1
            start = self.i
            while self.i < len(s) and s[self.i].isdigit():
                self.i += 1
            return Ref(int(s[start : self.i]))
        if c == ".":
            end = s.index(".", self.i + 1)
            name = s[self.i + 1 : end]
            self.i = end + 1
            return Enum(name)
        if c in "$*":
            self.i += 1
            return None
        if c == '"':
            end = s.index('"', self.i + 1)
            raw = s[self.i + 1 : end]
            self.i = end + 1
            return raw
        if c in "+-0123456789":
            start = self.i
            self.i += 1
            while self.i < len(s) and s[self.i] in "0123456789.eE+-":
                self.i += 1
            return Number(s[start : self.i])
        if c.isalpha() or c == "!":
            name = self.keyword()
            return Typed(name, self.plist())
        raise ParseError(f"unexpected {c!r} at {self.i}")


def split_statements(text):
    """Yield (line, statement) for each ';'-terminated statement.

    Strings and comments are skipped over, so a ';' inside them does not end
    a statement; comments are removed from the statement text.
    """
    buf = []
    line = 1
    start_line = None
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c == "/" and text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            line += text.count("\n", i, end)
            i = end
            continue
        if c == "'":
            j = i + 1
            while True:
                j = text.find("'", j)
                if j < 0:
                    j = n - 1
                    break
                if text.startswith("''", j):
                    j += 2
                    continue
                break
            if start_line is None:
                start_line = line
            buf.append(text[i : j + 1])
            line += text.count("\n", i, j + 1)
            i = j + 1
            continue
        if c == "\n":
            line += 1
        if c == ";":
            yield start_line or line, "".join(buf).strip()
            buf = []
            start_line = None
        else:
            if start_line is None and not c.isspace():
                start_line = line
            buf.append(c)
        i += 1


def read_file(path):
    """Parse a Part 21 file into (header, instances, text report)."""
    with open(path, "rb") as f:
        data = f.read()
    non_ascii_lines = []
    non_ascii = 0
    for number, raw_line in enumerate(data.split(b"\n"), 1):
        count = sum(1 for b in raw_line if b >= 0x80)
        if count:
            non_ascii += count
            non_ascii_lines.append(number)
    text = data.decode("latin-1")  # every byte maps to one character
    header = {}
    instances = {}
    malformed = []
    section = None
    for line, stmt in split_statements(text):
        upper = stmt.upper()
        if upper in ("ISO-10303-21", "HEADER", "DATA", "ENDSEC", "END-ISO-10303-21") or upper.startswith("DATA("):
            section = upper.split("(")[0]
            continue
        try:
            if section == "HEADER":
                header.update(ParamParser(stmt).instance())
            elif section == "DATA" and stmt.startswith("#"):
                eq = stmt.index("=")
                ident = int(stmt[1:eq])
                instances[ident] = ParamParser(stmt[eq + 1 :]).instance()
            elif stmt:
                raise ParseError("statement outside DATA")
        except (ParseError, ValueError, IndexError) as err:
            malformed.append({"line": line, "error": str(err), "text": stmt[:80]})
    report = {
        "non_ascii_bytes": non_ascii,
        "non_ascii_lines": non_ascii_lines[:10],
        "malformed": malformed,
        "instances": len(instances),
    }
    return header, instances, report


def kind(parts):
    """The name of an instance: its entity, or for a complex one its most specific part."""
    if len(parts) == 1:
        return next(iter(parts))
    for name in SPECIFIC_PARTS:
        if name in parts:
            return name
    return "(" + " ".join(sorted(parts)) + ")"


def raw_kind(parts):
    """The entity name as written; complex instances as their sorted parts."""
    if len(parts) == 1:
        return next(iter(parts))
    return "(" + " ".join(sorted(parts)) + ")"


def params_of(parts, name):
    return parts.get(name)


def header_summary(header):
    name = header.get("FILE_NAME", [])
    schema = header.get("FILE_SCHEMA", [[]])
    return {
        "schema": schema[0] if schema else [],
        "preprocessor_version": name[4] if len(name) > 4 else None,
        "originating_system": name[5] if len(name) > 5 else None,
        "description": (header.get("FILE_DESCRIPTION") or [[]])[0],
    }


def count_faces(inst):
    """Faces by the kind of surface they reference; returns (summary, face ids)."""
    by_surface = Counter()
    by_entity = Counter()
    face_ids = []
    for ident, parts in inst.items():
        for face_type in ("ADVANCED_FACE", "FACE_SURFACE"):
            p = params_of(parts, face_type)
            if p is None:
                continue
            face_ids.append(ident)
            surf = inst.get(p[2].id) if isinstance(p[2], Ref) else None
            by_surface[kind(surf) if surf else "missing"] += 1
            by_entity[raw_kind(surf) if surf else "missing"] += 1
    return {
        "total": len(face_ids),
        "by_surface": dict(sorted(by_surface.items())),
        "by_surface_entity": dict(sorted(by_entity.items())),
    }, face_ids


def curve_3d(inst, ref):
    """Follow SURFACE_CURVE/SEAM_CURVE/INTERSECTION_CURVE to their 3D curve."""
    seen = set()
    while isinstance(ref, Ref) and ref.id not in seen:
        seen.add(ref.id)
        parts = inst.get(ref.id)
        if parts is None:
            return "missing"
        inner = next((parts[n] for n in CURVES_ON_SURFACE if n in parts), None)
        if inner is None:
            return kind(parts)
        ref = inner[1]
    return "missing"


def count_edges(inst):
    """EDGE_CURVEs by curve kind, as referenced and with 3D curves resolved."""
    by_curve = Counter()
    by_3d = Counter()
    total = 0
    for parts in inst.values():
        p = params_of(parts, "EDGE_CURVE")
        if p is None:
            continue
        total += 1
        curve = inst.get(p[3].id) if isinstance(p[3], Ref) else None
        by_curve[kind(curve) if curve else "missing"] += 1
        by_3d[curve_3d(inst, p[3])] += 1
    return {"total": total, "by_curve": dict(sorted(by_curve.items())), "by_curve_3d": dict(sorted(by_3d.items()))}


def edge_element(inst, ref):
    """The EDGE_CURVE id behind an ORIENTED_EDGE (following nested oriented edges)."""
    seen = set()
    while isinstance(ref, Ref) and ref.id not in seen:
        seen.add(ref.id)
        parts = inst.get(ref.id, {})
        if "ORIENTED_EDGE" in parts:
            ref = parts["ORIENTED_EDGE"][3]
            continue
        return ref.id
    return None


def edge_uses(inst, face_ids):
    """Classify every EDGE_CURVE by how the faces' loops use it."""
    uses = defaultdict(list)  # edge id -> face ids, one entry per use
    for face in face_ids:
        parts = inst[face]
        p = parts.get("ADVANCED_FACE") or parts.get("FACE_SURFACE")
        for bref in p[1] or []:
            bound = inst.get(bref.id, {})
            bp = bound.get("FACE_OUTER_BOUND") or bound.get("FACE_BOUND")
            if bp is None:
                continue
            loop = inst.get(bp[1].id, {})
            lp = loop.get("EDGE_LOOP")
            if lp is None:
                continue  # VERTEX_LOOP or POLY_LOOP: no edges
            for oref in lp[1]:
                edge = edge_element(inst, oref)
                if edge is not None:
                    uses[edge].append(face)
    classes = Counter()
    ids = defaultdict(list)
    for ident, parts in inst.items():
        if "EDGE_CURVE" not in parts:
            continue
        faces = uses.get(ident, [])
        if not faces:
            cls = "unused"
        elif len(faces) == 1:
            cls = "open"
        elif len(faces) == 2:
            cls = "seam" if faces[0] == faces[1] else "shared"
        else:
            cls = "non_manifold"
        classes[cls] += 1
        if cls not in ("shared", "unused"):
            ids[cls].append(ident)
    result = {c: classes.get(c, 0) for c in ("shared", "seam", "open", "non_manifold", "unused")}
    result["oriented_edge_uses"] = sum(len(v) for v in uses.values())
    result["ids"] = {c: v[:50] for c, v in sorted(ids.items())}
    return result


def describe_unit(inst, ref):
    """A unit instance as {kind, si name and prefix} or {kind, conversion}."""
    parts = inst.get(ref.id, {}) if isinstance(ref, Ref) else {}
    unit_kind = next((UNIT_KINDS[p] for p in parts if p in UNIT_KINDS), None)
    out = {"id": ref.id if isinstance(ref, Ref) else None, "kind": unit_kind}
    if "SI_UNIT" in parts:
        prefix, name = parts["SI_UNIT"]
        out["si"] = name.name if isinstance(name, Enum) else name
        out["prefix"] = prefix.name if isinstance(prefix, Enum) else None
    elif "CONVERSION_BASED_UNIT" in parts:
        name, factor = parts["CONVERSION_BASED_UNIT"]
        out["conversion"] = name
        mwu = inst.get(factor.id, {}) if isinstance(factor, Ref) else {}
        mp = next(iter(mwu.values()), None)
        if mp:
            value = mp[0]
            out["factor"] = value.params[0] if isinstance(value, Typed) else value
            out["factor_type"] = value.name if isinstance(value, Typed) else None
            out["factor_unit"] = describe_unit(inst, mp[1])
    return out


def contexts(inst):
    """Units and uncertainties of every context that assigns units."""
    result = []
    for ident, parts in sorted(inst.items()):
        units = parts.get("GLOBAL_UNIT_ASSIGNED_CONTEXT")
        if units is None:
            continue
        entry = {"id": ident}
        for uref in units[0]:
            desc = describe_unit(inst, uref)
            if desc["kind"]:
                entry[desc["kind"] + "_unit"] = desc
        unc = parts.get("GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT")
        entry["uncertainty"] = []
        for uref in unc[0] if unc else []:
            up = inst.get(uref.id, {}).get("UNCERTAINTY_MEASURE_WITH_UNIT")
            if up is None:
                continue
            value = up[0]
            entry["uncertainty"].append(
                {
                    "id": uref.id,
                    "value": value.params[0] if isinstance(value, Typed) else value,
                    "measure": value.name if isinstance(value, Typed) else None,
                    "unit": describe_unit(inst, up[1]),
                    "name": up[2] if len(up) > 2 else None,
                }
            )
        result.append(entry)
    return result


def knot_lines(inst, face_ids):
    """The interior knots of every face's B-spline surface, with the
    continuity their multiplicity gives: ``C^(degree - multiplicity)`` (a
    B-spline of degree p is C^(p-m) across a knot of multiplicity m; Piegl &
    Tiller, The NURBS Book, section 2.5).  Interior knots are the distinct
    knots strictly inside the domain ``[U[p], U[len(U)-p-1]]`` of the
    expanded knot vector.  Returns ``{"#face": [[direction, knot, degree,
    nominal], ...]}`` for the faces that have any; the knot as the file
    wrote it."""
    out = {}
    for fid in face_ids:
        parts = inst[fid]
        p = params_of(parts, "ADVANCED_FACE") or params_of(parts, "FACE_SURFACE")
        surf = inst.get(p[2].id) if isinstance(p[2], Ref) else None
        if not surf or "B_SPLINE_SURFACE_WITH_KNOTS" not in surf:
            continue
        with_knots = params_of(surf, "B_SPLINE_SURFACE_WITH_KNOTS")
        base = params_of(surf, "B_SPLINE_SURFACE")
        if base is None:  # a simple instance: name, then B_SPLINE_SURFACE's own
            base, with_knots = with_knots[1:8], with_knots[8:]
        degrees = (int(base[0]), int(base[1]))
        mults = (with_knots[0], with_knots[1])
        knots = (with_knots[2], with_knots[3])
        lines = []
        for k, direction in enumerate("uv"):
            deg = degrees[k]
            expanded = [float(x) for x, m in zip(knots[k], mults[k]) for _ in range(int(m))]
            lo, hi = expanded[deg], expanded[len(expanded) - deg - 1]
            for x, m in zip(knots[k], mults[k]):
                if lo < float(x) < hi:
                    lines.append([direction, str(x), deg, deg - int(m)])
        if lines:
            out["#%d" % fid] = lines
    return out


def summarize(path):
    """Everything this script reports for one file."""
    header, inst, report = read_file(path)
    faces, face_ids = count_faces(inst)
    names = Counter(kind(p) for p in inst.values())
    return {
        "header": header_summary(header),
        "faces": faces,
        "edges": count_edges(inst),
        "vertices": names.get("VERTEX_POINT", 0),
        "shells": {"CLOSED_SHELL": names.get("CLOSED_SHELL", 0), "OPEN_SHELL": names.get("OPEN_SHELL", 0)},
        "solids": {s: names.get(s, 0) for s in SOLIDS},
        "edge_uses": edge_uses(inst, face_ids),
        "knot_lines": knot_lines(inst, face_ids),
        "contexts": contexts(inst),
        "text": report,
    }


SELF_TEST = r"""ISO-10303-21;
HEADER; /* a comment; with a semicolon */
FILE_DESCRIPTION(('x'),'2;1');
FILE_NAME('it''s; here','2020',('a'),('b'),'pre','SYS \X2\00E9\X0\ \S\a','');
FILE_SCHEMA(('AUTOMOTIVE_DESIGN'));
ENDSEC;
DATA;
#1=( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) );
#2=(NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.));
#3=UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),#1,'dist','');
#4=(GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#3))
 GLOBAL_UNIT_ASSIGNED_CONTEXT((#1,#2)) REPRESENTATION_CONTEXT('',''));
#5=PLANE('a ''quoted''; name',#6);
#7=(BOUNDED_SURFACE() B_SPLINE_SURFACE(1,1,((#8,#8),(#8,#8)),.UNSPECIFIED.,.F.,.F.,.F.)
 B_SPLINE_SURFACE_WITH_KNOTS((2,2),(2,2),(0.,1.),(0.,1.),.UNSPECIFIED.)
 GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_SURFACE(((1.,1.),(1.,1.)))
 REPRESENTATION_ITEM('') SURFACE());
#9=ADVANCED_FACE('',(#11),#5,.T.);
#10=ADVANCED_FACE('',(#12),#7,.F.);
#11=FACE_OUTER_BOUND('',#13,.T.);
#12=FACE_BOUND('',#14,.T.);
#13=EDGE_LOOP('',(#15,#16,#17));
#14=EDGE_LOOP('',(#18));
#15=ORIENTED_EDGE('',*,*,#20,.T.);
#16=ORIENTED_EDGE('',*,*,#21,.T.);
#17=ORIENTED_EDGE('',*,*,#21,.F.);
#18=ORIENTED_EDGE('',*,*,#20,.F.);
#20=EDGE_CURVE('',#30,#31,#22,.T.);
#21=EDGE_CURVE('',#31,#31,#23,.T.);
#22=SURFACE_CURVE('',#24,(#5,#7),.CURVE_3D.);
#23=SEAM_CURVE('',#25,(#5,#5),.CURVE_3D.);
#24=LINE('',#8,#8);
#25=CIRCLE('',#8,1.5);
ENDSEC;
END-ISO-10303-21;
"""


def self_test():
    """Check the parser on a file that exercises its syntax, with known answers."""
    import os
    import tempfile

    with tempfile.NamedTemporaryFile("w", suffix=".stp", delete=False) as f:
        f.write(SELF_TEST)
    try:
        r = summarize(f.name)
    finally:
        os.unlink(f.name)
    assert r["header"]["originating_system"] == "SYS \u00e9 \u00e1", r["header"]
    assert r["header"]["description"] == ["x"]
    assert r["faces"]["by_surface"] == {"PLANE": 1, "RATIONAL_B_SPLINE_SURFACE": 1}, r["faces"]
    assert r["edges"]["by_curve"] == {"SEAM_CURVE": 1, "SURFACE_CURVE": 1}, r["edges"]
    assert r["edges"]["by_curve_3d"] == {"CIRCLE": 1, "LINE": 1}, r["edges"]
    uses = r["edge_uses"]
    assert (uses["shared"], uses["seam"], uses["oriented_edge_uses"]) == (1, 1, 4), uses
    ctx = r["contexts"][0]
    assert (ctx["length_unit"]["prefix"], ctx["length_unit"]["si"]) == ("MILLI", "METRE"), ctx
    assert ctx["uncertainty"][0]["value"] == "1.E-07", ctx
    assert r["text"]["instances"] == 22 and not r["text"]["malformed"], r["text"]
    print("self-test passed")


def main(paths):
    out = {}
    for path in paths:
        out[path.rsplit("/", 1)[-1]] = summarize(path)
    json.dump(out, sys.stdout, indent=1, sort_keys=True, ensure_ascii=False)
    sys.stdout.write("\n")


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        self_test()
    elif len(sys.argv) < 2:
        sys.exit("usage: step_counts.py FILE... | --self-test")
    else:
        main(sys.argv[1:])
