#!/usr/bin/env python3
"""Open CASCADE next to ``exact-bezier audit`` on STEP B-reps, edge by edge (issue 28).

Run through the wrapper ``benches/peers/occt_audit`` (it makes the same venv
with ``cadquery-ocp-novtk`` as ``occt_step`` and builds nothing: pass the
release binary); not part of CI.

    occt_audit.py --exe target/release/exact-bezier [--timing FILE] FILE...
    occt_audit.py --tables occt_audit_results.json   # the tables of docs/audit.md

For each file it runs our ``audit FILE`` (full JSON) and reads the file with
Open CASCADE's ``STEPControl_Reader``, then pairs the edges:

* **Matching.** Each Open CASCADE edge is traced back to the ``EDGE_CURVE``
  it was made from through the reader's transfer map
  (``XSControl_TransferReader::EntityFromShapeResult``, with the placement
  first, else any placement of the same edge) and the entity's position in
  the model; the model holds the file's data instances in file order, so
  the n-th entity is the n-th ``#id = ...`` statement (checked: the counts
  agree and every matched entity's type is the statement's keyword).  Faces
  are traced the same way to their ``ADVANCED_FACE``, so our ``gap[i]`` is
  compared with the face it is measured against.  Edges Open CASCADE builds
  that no ``EDGE_CURVE`` made (seams and splits added by healing,
  degenerated edges at poles) are counted, not compared.
* **Gaps, in millimetres** (ours are in the file's unit; Open CASCADE
  converts to mm).  Ours: the certified enclosure ``[lo, hi]`` of each gap
  and the face gap (0 when proved exactly 0).  Open CASCADE's: the edge
  tolerance (``BRep_Tool::Tolerance``); the same-parameter deviation
  ``|C(t) - S(p(t))|`` between the 3D curve and each p-curve on its face, at
  ``CheckSameParameter``'s 23 parameters and at 1001; the same deviation
  from ``BRepLib_ValidateEdge``, with its 23 control points (what
  ``BRepCheck_Analyzer`` runs by default) and with its exact method (an
  optimization over the parameter); and, to compare like with like, the
  distance from the 3D curve to each face's *surface*
  (``GeomAPI_ProjectPointOnSurf``, what our ``gap`` measures) and between
  the two projections (our ``face_gap``) at the same 23 and 1001
  parameters.  A sampled distance is a lower bound of the true maximum, so
  a correct enclosure has ``sampled <= hi``; where our ``lo`` is above
  Open CASCADE's sampled value, the sampling missed part of the maximum.
* **Regularity.** ``BRep_Tool::Continuity`` after
  ``BRepLib::EncodeRegularity`` at its default 1e-10 rad, noting whether
  the reader had already set it (it encodes regularity itself at
  ``read.encoderegularity.angle``, 0.01 rad, and ``EncodeRegularity`` only
  revisits edges still C0); ``BRepLib::ContinuityOfFaces`` computed afresh
  at 1e-10 rad and at our angular tolerance; next to our G1 verdict.  And
  the angle between the faces' oriented normals, sampled at the p-curve
  points at the 21 parameters ``ContinuityOfFaces`` uses (the edge's range
  less 1 % at each end) and at 1001 over the whole range, and at the
  projection feet (like ours) at 1001, next to our certified ``angle``.

``--timing FILE`` also times, on the same machine in the same run, our
``audit FILE`` (wall, best of 3) against Open CASCADE's read + transfer
(best of 3) and ``BRepCheck_Analyzer`` (best of 3; also with its
``isExact`` option, which replaces the 23 samples of each curve-on-surface
check by an optimization), interleaved so both see the same load.
"""

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

from OCP.BRep import BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Curve, BRepAdaptor_Curve2d, BRepAdaptor_Surface
from OCP.BRepCheck import BRepCheck_Analyzer
from OCP.BRepLib import BRepLib, BRepLib_ValidateEdge
from OCP.GeomAPI import GeomAPI_ProjectPointOnSurf
from OCP.gp import gp_Pnt, gp_Vec
from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE, TopAbs_REVERSED
from OCP.TopExp import TopExp
from OCP.TopLoc import TopLoc_Location
from OCP.TopoDS import TopoDS
from OCP.collections import IndexedDataMap_TopoDS_Shape_List_TopoDS_Shape_TopTools_ShapeMapHasher as ShapeToShapes

import occt_step
import step_counts

OCCT_REGULARITY_ANGLE = 1e-10  # rad, EncodeRegularity's default
SPARSE = 23  # CheckSameParameter's and BRepCheck's samples
REGULARITY_SAMPLES = 21  # ContinuityOfFaces: 21 parameters, 1 % of the range cut at each end
DENSE = 1001
# mm: Open CASCADE evaluates in f64 on the f64 parse of the file's decimals, so
# its distances carry an absolute error near 1e-13 mm on parts of a metre; a
# sampled value counts as "above our hi" only beyond this margin.
SLACK_MM = 1e-10
SLACK_RAD = 1e-12
MM_PER_UNIT = {"MILLI METRE": 1.0, "MILLIMETRE": 1.0, "METRE": 1000.0, "CENTI METRE": 10.0, "INCH": 25.4, "FOOT": 304.8}
OCCT_TYPES = {"StepShape_EdgeCurve": ("EDGE_CURVE",), "StepShape_AdvancedFace": ("ADVANCED_FACE", "FACE_SURFACE")}


# ---------------------------------------------------------------- our audit


def run_ours(exe, path):
    """Our full audit JSON of one file and its wall time."""
    start = time.perf_counter()
    done = subprocess.run([exe, "audit", path], capture_output=True, text=True, check=True)
    return json.loads(done.stdout), time.perf_counter() - start


def enclosure(measure, scale):
    """Our measure as (lo, hi) scaled, (0, 0) when exact, None when unproved or absent."""
    if measure == 0:
        return (0.0, 0.0)
    if isinstance(measure, dict):
        return (measure["lo"] * scale, measure["hi"] * scale)
    return None


def exact_zero(measure):
    return measure == 0


# ---------------------------------------------------------------- matching


def statement_ids(path):
    """The ``#id`` and keyword of each DATA statement, in file order."""
    with open(path, "rb") as f:
        text = f.read().decode("latin-1")
    out, section = [], None
    for _, stmt in step_counts.split_statements(text):
        upper = stmt.upper()
        if upper in ("HEADER", "DATA", "ENDSEC") or upper.startswith("DATA("):
            section = upper.split("(")[0]
            continue
        if section == "DATA" and stmt.startswith("#"):
            eq = stmt.index("=")
            body = stmt[eq + 1 :].strip()
            keyword = "(" if body.startswith("(") else body.split("(")[0].strip().upper()
            out.append((int(stmt[1:eq]), keyword))
    return out


class Labels:
    """Open CASCADE shape -> the ``#id`` of the STEP instance it was made from."""

    def __init__(self, reader, path):
        model = reader.StepModel()
        self.ids = statement_ids(path)
        if model.NbEntities() != len(self.ids):
            raise RuntimeError(f"{model.NbEntities()} entities, {len(self.ids)} DATA statements")
        # The binding cannot look entities up in the model (Number() returns 0
        # for every entity), but it returns one Python object per C++ entity:
        # keep them alive and index them by identity.
        self.entities = [model.Value(k) for k in range(1, model.NbEntities() + 1)]
        self.position = {entity: k for k, entity in enumerate(self.entities)}
        self.transfer = reader.WS().TransferReader()
        self.checked = 0

    def __call__(self, shape):
        entity = self.transfer.EntityFromShapeResult(shape, 1)
        if entity is None:  # an instance placed by an assembly: any placement
            entity = self.transfer.EntityFromShapeResult(shape, -1)
        if entity is None:
            return None
        k = self.position.get(entity)
        if k is None:
            return None
        ident, keyword = self.ids[k]
        expected = OCCT_TYPES.get(entity.DynamicType().Name())
        if expected is not None:
            if keyword not in expected:
                raise RuntimeError(f"entity {k + 1} is {entity.DynamicType().Name()}, statement #{ident} is {keyword}")
            self.checked += 1
        return f"#{ident}"


# ---------------------------------------------------------------- OCCT measures


def params(first, last, n):
    return [first + (last - first) * k / (n - 1) for k in range(n)]


def regularity_params(first, last):
    """The 21 parameters of BRepLib::ContinuityOfFaces: the range less 1 % at each end."""
    eps = (last - first) / 100.0
    return params(first + eps, last - eps, REGULARITY_SAMPLES)


def sides(edge, faces, use):
    """(oriented edge, face) for each side of a shared edge or a seam."""
    if use == "shared":
        return [(edge, faces[0]), (edge, faces[1])]
    if use == "seam":
        return [(edge, faces[0]), (TopoDS.Edge(edge.Reversed()), faces[0])]
    return []


class Side:
    """One face along the edge: its surface, p-curve and oriented normal."""

    def __init__(self, edge, face):
        self.on_face = BRepAdaptor_Curve(edge, face)
        self.uv = BRepAdaptor_Curve2d(edge, face)
        self.surface = BRepAdaptor_Surface(face)
        self.geometry = BRep_Tool.Surface_s(face)
        self.reversed = face.Orientation() == TopAbs_REVERSED
        self.project = GeomAPI_ProjectPointOnSurf()

    def same_parameter(self, point, t):
        """|C(t) - S(p(t))|: CheckSameParameter's distance."""
        return point.Distance(self.on_face.Value(t))

    def foot(self, point):
        """The nearest point of the face's surface (untrimmed) to ``point`` and the oriented normal there."""
        self.project.Init(point, self.geometry)
        if not self.project.IsDone() or self.project.NbPoints() == 0:
            return None, None
        u, v = self.project.LowerDistanceParameters()
        p, du, dv = gp_Pnt(), gp_Vec(), gp_Vec()
        self.geometry.D1(u, v, p, du, dv)
        n = du.Crossed(dv)
        return self.project.NearestPoint(), n.Reversed() if self.reversed else n

    def validate(self, curve, exact):
        """BRepLib_ValidateEdge's deviation: 23 control points, or its optimization (``exact``)."""
        check = BRepLib_ValidateEdge(curve, self.on_face.CurveOnSurface(), True)
        check.SetExactMethod(exact)
        check.Process()
        return check.GetMaxDistance() if check.IsDone() else None

    def normal(self, t):
        uv = self.uv.Value(t)
        p, du, dv = gp_Pnt(), gp_Vec(), gp_Vec()
        self.surface.D1(uv.X(), uv.Y(), p, du, dv)
        n = du.Crossed(dv)
        return n.Reversed() if self.reversed else n


def angle_between(a, b):
    if a.Magnitude() == 0.0 or b.Magnitude() == 0.0:
        return None
    return math.atan2(a.Crossed(b).Magnitude(), a.Dot(b))


def sampled(edge, ours_sides, ts):
    """Sampled maxima over ``ts``: same-parameter deviation, surface distance per side, face gap, angle."""
    curve = BRepAdaptor_Curve(edge)
    sp, dist, face_gap, angle, foot_angle = 0.0, [0.0 for _ in ours_sides], 0.0, 0.0, 0.0
    sp_at, dist_at, angle_at = 0.0, [0.0 for _ in ours_sides], 0.0
    first, last = curve.FirstParameter(), curve.LastParameter()
    for t in ts:
        point = curve.Value(t)
        feet, normals = [], []
        for i, side in enumerate(ours_sides):
            d = side.same_parameter(point, t)
            if d > sp:
                sp, sp_at = d, t
            foot, normal = side.foot(point)
            feet.append(foot)
            normals.append(normal)
            if foot is not None and point.Distance(foot) > dist[i]:
                dist[i], dist_at[i] = point.Distance(foot), t
        if len(feet) == 2 and feet[0] is not None and feet[1] is not None:
            face_gap = max(face_gap, feet[0].Distance(feet[1]))
            a = angle_between(normals[0], normals[1])
            if a is not None:
                foot_angle = max(foot_angle, a)
        if len(ours_sides) == 2:
            a = angle_between(ours_sides[0].normal(t), ours_sides[1].normal(t))
            if a is not None and a > angle:
                angle, angle_at = a, t
    span = (last - first) or 1.0
    return {
        "same_parameter": sp,
        "same_parameter_at": (sp_at - first) / span,
        "surface": dist,
        "surface_at": [(t - first) / span for t in dist_at],
        "face_gap": face_gap,
        "angle": angle,
        "angle_at": (angle_at - first) / span,
        "foot_angle": foot_angle,
    }


# ---------------------------------------------------------------- per file


def reader_flagged(edge, faces, use):
    """Did the reader already encode a regularity (its own EncodeRegularity, read.encoderegularity.angle)?"""
    pair = occt_step.face_pair(faces, use)
    return None if pair is None else bool(BRep_Tool.HasContinuity_s(edge, *pair))


def continuity_of_faces(edge, faces, use, tol):
    """BRepLib::ContinuityOfFaces at ``tol``: computed afresh, whatever flags the edge carries."""
    pair = occt_step.face_pair(faces, use)
    return None if pair is None else occt_step.enum_name(BRepLib.ContinuityOfFaces_s(edge, *pair, tol))


def edge_and_faces(ancestors, i):
    """The i-th edge of an edge-to-faces map and its distinct faces."""
    edge = TopoDS.Edge(ancestors.FindKey(i))
    distinct = occt_step.ShapeMap()
    for face in ancestors.FindFromIndex(i):
        distinct.Add(face)
    return edge, occt_step.distinct_faces(distinct)


def occt_edges(shape, label, angle_tol):
    """Per matched EDGE_CURVE id, its Open CASCADE edge occurrences; and the unmatched ones by use."""
    ancestors = ShapeToShapes()
    TopExp.MapShapesAndAncestors_s(shape, TopAbs_EDGE, TopAbs_FACE, ancestors)
    flagged = {}
    for i in range(1, ancestors.Extent() + 1):
        edge, faces = edge_and_faces(ancestors, i)
        flagged[i] = reader_flagged(edge, faces, occt_step.classify_use(edge, faces))
    BRepLib.EncodeRegularity_s(shape, OCCT_REGULARITY_ANGLE)
    records, unmatched = [], {}
    for i in range(1, ancestors.Extent() + 1):
        edge, faces = edge_and_faces(ancestors, i)
        use = occt_step.classify_use(edge, faces)
        ident = label(edge)
        if ident is None:
            unmatched[use] = unmatched.get(use, 0) + 1
            continue
        records.append(
            {
                "id": ident,
                "edge": edge,
                "faces": faces,
                "face_ids": [label(f) for f in faces],
                "use": use,
                "tolerance": BRep_Tool.Tolerance_s(edge),
                "continuity": occt_step.continuity(edge, faces, use),
                "reader_flagged": flagged[i],
                "faces_1e-10": continuity_of_faces(edge, faces, use, OCCT_REGULARITY_ANGLE),
                "faces_our_tol": continuity_of_faces(edge, faces, use, angle_tol),
            }
        )
    return records, unmatched


REGULAR = ("G1", "C1", "G2", "C2", "C3", "CN")


def regular(cont):
    if cont is None:
        return None
    return "regular" if cont.replace("GeomAbs_", "") in REGULAR else "C0"


def order_sides(record, ours_faces):
    """Sides in the order of our ``faces`` (our gap[i] is against ours_faces[i])."""
    s = sides(record["edge"], record["faces"], record["use"])
    if record["use"] == "shared" and record["face_ids"] == list(reversed(ours_faces)) and ours_faces[0] != ours_faces[1]:
        s.reverse()
    return [Side(e, f) for e, f in s]


def compare_edge(ours, record, scale):
    """One measured edge: our enclosures next to Open CASCADE's numbers (mm, rad)."""
    m = ours["measures"]
    gaps = [enclosure(g, scale) for g in m["gap"]]
    face_gap = enclosure(m["face_gap"], scale)
    angle = enclosure(m["angle"], 1.0)
    ours_sides = order_sides(record, ours["faces"])
    curve = BRepAdaptor_Curve(record["edge"])
    first, last = curve.FirstParameter(), curve.LastParameter()
    sparse = sampled(record["edge"], ours_sides, params(first, last, SPARSE))
    dense = sampled(record["edge"], ours_sides, params(first, last, DENSE))
    regular_angle = sampled(record["edge"], ours_sides, regularity_params(first, last))["angle"]
    validate = {exact: [side.validate(curve, exact) for side in ours_sides] for exact in (False, True)}
    known = [g for g in gaps + [face_gap] if g is not None]
    all_known = len(known) == len(gaps) + 1
    return {
        "id": ours["id"],
        "curve": ours["curve"],
        "faces": ours["faces"],
        "class": ours["class"],
        "occurrences": record["occurrences"],
        "ours": {
            "gap": gaps,
            "face_gap": face_gap,
            "angle": angle,
            "gap_exact": all(exact_zero(g) for g in m["gap"]) and exact_zero(m["face_gap"]),
            "angle_exact": exact_zero(m["angle"]),
            "max_gap": [max(g[0] for g in known), max(g[1] for g in known)] if all_known else None,
            "max_gap_lo": max((g[0] for g in known), default=None),
            "verdicts": ours["verdicts"],
            "continuity": ours["continuity"],
        },
        "occt": {
            "tolerance": record["tolerance"],
            "same_parameter_23": sparse["same_parameter"],
            "same_parameter_1001": dense["same_parameter"],
            "same_parameter_1001_at": dense["same_parameter_at"],
            "surface_23": sparse["surface"],
            "surface_1001": dense["surface"],
            "surface_1001_at": dense["surface_at"],
            "face_gap_23": sparse["face_gap"],
            "face_gap_1001": dense["face_gap"],
            "validate_edge_23": validate[False],
            "validate_edge_exact": validate[True],
            "angle_21": regular_angle,
            "angle_1001": dense["angle"],
            "angle_1001_at": dense["angle_at"],
            "foot_angle_1001": dense["foot_angle"],
            "reader_flagged": record["reader_flagged"],
            "continuity": record["continuity"],
            "continuity_of_faces_1e-10": record["faces_1e-10"],
            "continuity_of_faces_our_tol": record["faces_our_tol"],
        },
    }


def gap_classes(e):
    """Which containment and sampling relations hold for one edge's gaps."""
    o, c = e["ours"], e["occt"]
    out = []
    if o["max_gap"] is None:
        return ["gap unproved"]
    lo, hi = o["max_gap"]
    surf = max(c["surface_1001"] + [c["face_gap_1001"]])
    # containment of the like-for-like distance
    if o["gap_exact"]:
        out.append("surface: ours exactly 0, OCCT's f64 <= slack" if surf <= SLACK_MM else "surface: ours exactly 0, OCCT's f64 > slack")
    elif surf <= hi + SLACK_MM:
        out.append("surface: OCCT sampled <= our hi")
    else:
        out.append("surface: OCCT sampled > our hi")
    # CheckSameParameter's deviation against our gap
    sp = c["same_parameter_1001"]
    if sp <= hi + SLACK_MM:
        out.append("same-parameter (1001) <= our hi")
    elif surf <= hi + SLACK_MM:
        out.append("same-parameter (1001) > our hi, surface distance <= our hi (parametric)")
    else:
        out.append("same-parameter (1001) > our hi, surface distance too")
    exact_method = [v for v in c["validate_edge_exact"] if v is not None]
    if exact_method:
        out.append(
            "exact-method deviation <= our hi" if max(exact_method) <= hi + SLACK_MM else "exact-method deviation > our hi"
        )
    # OCCT's tolerance against our gap
    tol = c["tolerance"]
    if tol >= hi:
        out.append("tolerance >= our hi")
    elif tol < lo:
        out.append("tolerance < our lo")
    else:
        out.append("tolerance within our [lo, hi]")
    # sampling misses: our certified lower bound above OCCT's sampled values
    sparse_validate = [v for v in c["validate_edge_23"] if v is not None]
    if sparse_validate and lo > max(sparse_validate) + SLACK_MM:
        out.append("miss: our lo > ValidateEdge (23, BRepCheck's default)")
    if lo > c["same_parameter_23"] + SLACK_MM:
        out.append("miss: our lo > same-parameter (23)")
    surf23 = max(c["surface_23"] + [c["face_gap_23"]])
    if lo > surf23 + SLACK_MM:
        out.append("miss: our lo > surface (23)")
    return out


def angle_classes(e):
    o, c = e["ours"], e["occt"]
    out = []
    a = o["angle"]
    if a is None:
        return ["angle unproved"]
    if o["angle_exact"]:
        out.append("angle: ours exactly 0 or pi")
    feet = c["foot_angle_1001"]
    if not o["angle_exact"]:
        out.append("angle at feet: OCCT sampled <= our hi" if feet <= a[1] + SLACK_RAD else "angle at feet: OCCT sampled > our hi")
        if c["angle_1001"] > a[1] + SLACK_RAD:
            out.append("angle at p-curve points > our hi")
    if a[0] > c["angle_21"] + SLACK_RAD:
        out.append("miss: our angle lo > OCCT's 21-sample angle")
    return out


def regularity_row(e):
    """Our G1 verdict; OCCT's flag after EncodeRegularity (and whether the reader set it); ContinuityOfFaces at 1e-10 and at our tolerance."""
    c = e["occt"]
    return (
        e["ours"]["verdicts"].get("G1") if e["ours"]["verdicts"] else None,
        regular(c["continuity"]) + (" (reader)" if c["reader_flagged"] else ""),
        regular(c["continuity_of_faces_1e-10"]),
        regular(c["continuity_of_faces_our_tol"]),
    )


def count(items):
    out = {}
    for item in items:
        out[item] = out.get(item, 0) + 1
    return dict(sorted(out.items()))


def analyse(path, exe):
    ours, ours_seconds = run_ours(exe, path)
    unit = ours["tolerance"]["unit"]
    scale = MM_PER_UNIT[unit]
    angle_tol = float(Fraction(ours["tolerance"]["angle"]))
    reader, shape, _ = occt_step.read(path)
    label = Labels(reader, path)
    records, unmatched = occt_edges(shape, label, angle_tol)
    by_id = {}
    for r in records:
        by_id.setdefault(r["id"], []).append(r)
    edges, not_in_occt, compared = ours["edge_list"], 0, []
    verdict_pairs = []
    for e in edges:
        occ = by_id.get(e["id"])
        if not occ:
            not_in_occt += 1
            continue
        first = dict(occ[0])
        first["occurrences"] = len(occ)
        first["tolerance"] = max(r["tolerance"] for r in occ)
        verdict_pairs.append(
            (e.get("continuity") or "not measured", regular(first["faces_1e-10"]) or first["use"])
        )
        if e.get("verdicts") and e.get("measures") and e["class"] in ("shared", "seam"):
            compared.append(compare_edge(e, first, scale))
    for e in compared:
        e["gap_classes"] = gap_classes(e)
        e["angle_classes"] = angle_classes(e)
    return {
        "unit": unit,
        "mm_per_unit": scale,
        "our_angle_tolerance": angle_tol,
        "our_length_tolerance_mm": float(Fraction(ours["tolerance"]["length"])) * scale if ours["tolerance"].get("length") else None,
        "our_audit_seconds": ours_seconds,
        "matching": {
            "method": "transfer map (EntityFromShapeResult) + model order = DATA statement order",
            "entities_type_checked": label.checked,
            "our_edges": len(edges),
            "our_edges_with_occt_edge": len(edges) - not_in_occt,
            "occt_edges_matched": len(records),
            "occt_edges_unmatched_by_use": dict(sorted(unmatched.items())),
        },
        "our_continuity_vs_occt_continuity_of_faces_1e-10": count(f"{a} / {b}" for a, b in verdict_pairs),
        "measured_edges": len(compared),
        "gap_classes": count(c for e in compared for c in e["gap_classes"]),
        "angle_classes": count(c for e in compared for c in e["angle_classes"]),
        "g1_vs_occt": count(" / ".join(str(x) for x in regularity_row(e)) for e in compared),
        "per_edge": compared,
    }


# ---------------------------------------------------------------- timing


def wall(cmd, sink):
    """Wall time of one command, its output to ``sink``."""
    sink.seek(0)
    sink.truncate()
    start = time.perf_counter()
    subprocess.run(cmd, stdout=sink, check=True)
    return time.perf_counter() - start


def timing(path, exe, runs=3):
    """Ours (``audit``, full and ``--summary``, wall) and OCCT (read + transfer, ``BRepCheck_Analyzer``).

    Interleaved, so that both see the same load; best of ``runs`` each.
    """
    ours, summary, read, check, check_exact = [], [], [], [], []
    load_before = open("/proc/loadavg").read().split()[:3]
    with tempfile.TemporaryFile() as sink:
        for _ in range(runs):
            ours.append(wall([exe, "audit", path], sink))
            summary.append(wall([exe, "audit", path, "--summary"], sink))
            _, shape, seconds = occt_step.read(path)
            read.append(seconds)
            check.append(occt_step.check(shape)["seconds"])
            start = time.perf_counter()
            BRepCheck_Analyzer(shape, True, False, True).IsValid()
            check_exact.append(time.perf_counter() - start)
    return {
        "file": os.path.basename(path),
        "load_average_before_after": [load_before, open("/proc/loadavg").read().split()[:3]],
        "ours_audit_seconds": ours,
        "ours_audit_summary_seconds": summary,
        "occt_read_seconds": read,
        "occt_check_seconds": check,
        "occt_check_exact_seconds": check_exact,
        "ours_best": min(ours),
        "ours_summary_best": min(summary),
        "occt_read_best": min(read),
        "occt_check_best": min(check),
        "occt_check_exact_best": min(check_exact),
        "occt_read_plus_check_best": min(read) + min(check),
    }


# ---------------------------------------------------------------- tables


def smooth(verdict):
    return {"exact": "smooth", "within_tolerance": "smooth", "fails": "fails"}.get(verdict, "undecided")


def regularity_counts(edges):
    """Our G1 verdict (smooth, fails, undecided) against Open CASCADE's three regularity answers."""
    rows = {}
    for e in edges:
        c = e["occt"]
        ours = smooth(e["ours"]["verdicts"].get("G1"))
        for name, value in (
            ("flag", c["continuity"]),
            ("1e-10", c["continuity_of_faces_1e-10"]),
            ("ours", c["continuity_of_faces_our_tol"]),
        ):
            key = (name, ours, regular(value))
            rows[key] = rows.get(key, 0) + 1
    return rows


def tables(results):
    """Markdown tables of a results file (the ones in docs/audit.md)."""
    files = {k: v for k, v in results["files"].items() if "error" not in v}
    out = [
        "| file | our edges | traced | measured | surface <= hi | exact 0 | surface > hi | same-param <= hi | same-param > hi (parametric) | tol >= hi | tol in [lo, hi] | tol < lo | lo > 23 samples |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for name, f in files.items():
        g = f["gap_classes"]
        edges = f["per_edge"]
        miss = sum(1 for e in edges if any(c.startswith("miss: our lo > s") or c.startswith("miss: our lo > V") for c in e["gap_classes"]))
        out.append(
            f"| `{name}` | {f['matching']['our_edges']} | {f['matching']['our_edges_with_occt_edge']} | {f['measured_edges']} "
            f"| {g.get('surface: OCCT sampled <= our hi', 0)} | {g.get('surface: ours exactly 0, OCCT' + chr(39) + 's f64 <= slack', 0)} "
            f"| {g.get('surface: OCCT sampled > our hi', 0) + g.get('surface: ours exactly 0, OCCT' + chr(39) + 's f64 > slack', 0)} "
            f"| {g.get('same-parameter (1001) <= our hi', 0)} | {g.get('same-parameter (1001) > our hi, surface distance <= our hi (parametric)', 0)} "
            f"| {g.get('tolerance >= our hi', 0)} | {g.get('tolerance within our [lo, hi]', 0)} | {g.get('tolerance < our lo', 0)} | {miss} |"
        )
    out += [
        "",
        "| file | smooth: flag C0 | fails: flag regular | smooth: 1e-10 C0 | fails: 1e-10 regular | smooth: ours-tol C0 | fails: ours-tol regular | agree at our tol | angle at feet <= hi | angle at p-curves > hi |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for name, f in files.items():
        r = regularity_counts(f["per_edge"])
        a = f["angle_classes"]
        agree = r.get(("ours", "smooth", "regular"), 0) + r.get(("ours", "fails", "C0"), 0)
        out.append(
            f"| `{name}` | {r.get(('flag', 'smooth', 'C0'), 0)} | {r.get(('flag', 'fails', 'regular'), 0)} "
            f"| {r.get(('1e-10', 'smooth', 'C0'), 0)} | {r.get(('1e-10', 'fails', 'regular'), 0)} "
            f"| {r.get(('ours', 'smooth', 'C0'), 0)} | {r.get(('ours', 'fails', 'regular'), 0)} | {agree} "
            f"| {a.get('angle at feet: OCCT sampled <= our hi', 0)} | {a.get('angle at p-curve points > our hi', 0)} |"
        )
    return "\n".join(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exe", help="the exact-bezier binary (release)")
    parser.add_argument("--timing", help="a file to time both tools on")
    parser.add_argument("--tables", help="print the markdown tables of a results file and stop")
    parser.add_argument("files", nargs="*")
    args = parser.parse_args()
    if args.tables:
        with open(args.tables) as f:
            print(tables(json.load(f)))
        return
    if not args.exe or not args.files:
        parser.error("--exe and at least one FILE are needed")
    out = {"files": {}}
    for path in args.files:
        name = os.path.basename(path)
        try:
            out["files"][name] = analyse(path, args.exe)
        except Exception as err:  # report and go on with the next file
            out["files"][name] = {"error": repr(err)}
        print(name, "done", file=sys.stderr)
    if args.timing:
        out["timing"] = timing(args.timing, args.exe)
    json.dump(out, sys.stdout, indent=1, sort_keys=True)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
