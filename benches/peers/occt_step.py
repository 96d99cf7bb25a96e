#!/usr/bin/env python3
"""Open CASCADE as a peer for reading and checking STEP B-reps (issues 27, 28).

Run through the wrapper ``benches/peers/occt_step`` (it makes a venv with
``cadquery-ocp-novtk``, OCCT 8); not part of CI.

    occt_step FILE... > results.json

For each file, in Open CASCADE's floating point and its default units
(millimetres):

* ``read``: STEPControl_Reader ReadFile + TransferRoots, best of 3 (seconds);
* ``faces``/``edges``/``vertices``: sub-shapes by geometric type
  (BRepAdaptor_Surface / BRepAdaptor_Curve GetType), counted once per
  distinct sub-shape (``TopExp::MapShapes``: an instanced part placed twice
  counts twice) and once per underlying TShape (``unique``: placements
  ignored);
* ``shells`` (closed/open) and ``solids``;
* ``check``: BRepCheck_Analyzer validity and its time;
* ``edge_uses``: edges used by two faces (shared), as a seam of one face,
  by one face (open) or by more than two, and degenerated edges (a cone's
  apex, a sphere's pole: BRep_Tool::Degenerated) and free edges (in no
  face: wireframe or supplemental geometry the file also holds) apart;
* ``tolerances``: per edge its OCCT tolerance (BRep_Tool::Tolerance),
  ShapeAnalysis_Edge::CheckSameParameter's maximal deviation between the 3D
  curve and the p-curves (23 samples), and BRep_Tool::Continuity between
  its faces after BRepLib::EncodeRegularity (angular tolerance 1e-10 rad),
  ``same_parameter_flagged`` is what CheckSameParameter returns: true when
  it finds the edge not same-parameter within its tolerance (its
  implementation returns its DONE status; the header's comment says the
  opposite); ``same_parameter_dev`` repeats its
  23-sample deviation, since the binding takes the output by value and
  cannot return it; ``same_parameter_dev_dense`` samples the same distance
  at 1001 parameters where the 23-sample value is over 1e-9 mm, to show
  what the sparse sampling misses (``same_parameter_dense_at``: where, as
  a fraction of the edge's parameter range); ``ends`` are the edge's
  vertices in mm, to find it in the file.
"""

import json
import statistics
import sys
import time

from OCP.BRep import BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Curve, BRepAdaptor_Surface
from OCP.BRepCheck import BRepCheck_Analyzer
from OCP.BRepLib import BRepLib
from OCP.IFSelect import IFSelect_RetDone
from OCP.ShapeAnalysis import ShapeAnalysis_Edge
from OCP.STEPControl import STEPControl_Reader
from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE, TopAbs_SHELL, TopAbs_SOLID, TopAbs_VERTEX
from OCP.TopExp import TopExp
from OCP.TopLoc import TopLoc_Location
from OCP.TopoDS import TopoDS
from OCP.collections import (
    IndexedDataMap_TopoDS_Shape_List_TopoDS_Shape_TopTools_ShapeMapHasher as ShapeToShapes,
    IndexedMap_TopoDS_Shape_TopTools_ShapeMapHasher as ShapeMap,
)

REGULARITY_ANGLE = 1e-10  # rad, EncodeRegularity's default
DENSE_SAMPLES = 1001  # the second, denser sampling of a deviation
DENSE_FROM = 1e-9  # mm: edges whose 23-sample deviation is over this are resampled


def read(path):
    """Read and transfer a STEP file; returns (reader, shape, seconds)."""
    start = time.perf_counter()
    reader = STEPControl_Reader()
    if reader.ReadFile(path) != IFSelect_RetDone:
        raise RuntimeError(f"{path}: ReadFile failed")
    reader.TransferRoots()
    shape = reader.OneShape()
    return reader, shape, time.perf_counter() - start


def best_read(path, runs=3):
    """The reader and shape of the last run and the best time of ``runs``."""
    best = None
    for _ in range(runs):
        reader, shape, seconds = read(path)
        best = seconds if best is None else min(best, seconds)
    return reader, shape, best


def sub_shapes(shape, kind):
    """The distinct sub-shapes of one kind, as an indexed map (1-based)."""
    shapes = ShapeMap()
    TopExp.MapShapes_s(shape, kind, shapes)
    return [shapes.FindKey(i) for i in range(1, shapes.Extent() + 1)]


def unique_count(items):
    """How many distinct TShapes underlie the items (placements ignored)."""
    unplaced = ShapeMap()
    for item in items:
        unplaced.Add(item.Located(TopLoc_Location()))
    return unplaced.Extent()


def enum_name(value):
    """``GeomAbs_Plane`` from the binding's ``GeomAbs_SurfaceType.GeomAbs_Plane``."""
    return str(value).split(".")[-1].split(":")[0]


def by_type(items, adaptor, cast):
    """Counts of the items by their adaptor's GetType()."""
    counts = {}
    for item in items:
        name = enum_name(adaptor(cast(item)).GetType())
        counts[name] = counts.get(name, 0) + 1
    return dict(sorted(counts.items()))


def same_parameter_deviation(edge, faces, samples=23):
    """Largest distance between the 3D curve and each p-curve of the edge.

    ShapeAnalysis_Edge::CheckSameParameter computes this on 23 equidistant
    parameters, but its Python binding takes the deviation by value and
    cannot return it; this repeats its sampling (3D curve at t against the
    face's surface at the p-curve's point at t) through BRepAdaptor_Curve.
    Returns (deviation, fraction of the edge's parameter range where it
    is attained). On a seam only the p-curve BRepAdaptor_Curve picks for
    the edge's orientation is measured.
    """
    curve = BRepAdaptor_Curve(edge)
    first, last = curve.FirstParameter(), curve.LastParameter()
    worst, where = 0.0, 0.0
    for face in faces:
        on_face = BRepAdaptor_Curve(edge, face)
        for k in range(samples):
            t = first + (last - first) * k / (samples - 1)
            d = curve.Value(t).Distance(on_face.Value(t))
            if d > worst:
                worst, where = d, k / (samples - 1)
    return worst, where


def point(vertex):
    """A vertex's coordinates (mm)."""
    p = BRep_Tool.Pnt_s(vertex)
    return [p.X(), p.Y(), p.Z()]


def distinct_faces(face_map):
    """The faces of an indexed map, as faces."""
    return [TopoDS.Face(face_map.FindKey(i)) for i in range(1, face_map.Extent() + 1)]


def classify_use(edge, faces):
    """How the faces use the edge: shared, seam, open, non_manifold, degenerate or free.

    ``faces`` are the distinct faces the edge bounds (a seam's face once).
    """
    if BRep_Tool.Degenerated_s(edge):
        return "degenerate"
    if not faces:
        return "free"
    if len(faces) == 2:
        return "shared"
    if len(faces) == 1:
        return "seam" if BRep_Tool.IsClosed_s(edge, faces[0]) else "open"
    return "non_manifold"


def face_pair(faces, use):
    """The two faces across a shared edge, the face twice across a seam,
    else None."""
    if use == "shared":
        return faces[0], faces[1]
    return (faces[0], faces[0]) if use == "seam" else None


def continuity(edge, faces, use):
    """BRep_Tool::Continuity across a shared edge or a seam, else None."""
    pair = face_pair(faces, use)
    return None if pair is None else enum_name(BRep_Tool.Continuity_s(edge, *pair))


def edge_records(shape):
    """Per edge: type, faces using it, tolerance, same-parameter deviation, continuity."""
    BRepLib.EncodeRegularity_s(shape, REGULARITY_ANGLE)
    ancestors = ShapeToShapes()
    TopExp.MapShapesAndAncestors_s(shape, TopAbs_EDGE, TopAbs_FACE, ancestors)
    analysis = ShapeAnalysis_Edge()
    records = []
    for i in range(1, ancestors.Extent() + 1):
        edge = TopoDS.Edge(ancestors.FindKey(i))
        distinct = ShapeMap()
        for face in ancestors.FindFromIndex(i):
            distinct.Add(face)
        faces = distinct_faces(distinct)
        use = classify_use(edge, faces)
        same_parameter = analysis.CheckSameParameter(edge, 0.0)
        deviation, _ = same_parameter_deviation(edge, faces)
        dense, dense_at = same_parameter_deviation(edge, faces, DENSE_SAMPLES) if deviation > DENSE_FROM else (None, None)
        records.append(
            {
                "curve": enum_name(BRepAdaptor_Curve(edge).GetType()),
                "use": use,
                "tolerance": BRep_Tool.Tolerance_s(edge),
                "same_parameter_flagged": bool(same_parameter),
                "same_parameter_dev": deviation,
                "same_parameter_dev_dense": dense,
                "same_parameter_dense_at": dense_at,
                "ends": [point(TopExp.FirstVertex_s(edge)), point(TopExp.LastVertex_s(edge))],
                "continuity": continuity(edge, faces, use),
            }
        )
    return records


def summarize_edges(records):
    """Per-file totals of the edge records."""
    uses, cont = {}, {}
    for r in records:
        uses[r["use"]] = uses.get(r["use"], 0) + 1
        if r["continuity"]:
            cont[r["continuity"]] = cont.get(r["continuity"], 0) + 1
    tols = [r["tolerance"] for r in records] or [0.0]
    devs = [r["same_parameter_dev"] for r in records if r["same_parameter_dev"] is not None] or [0.0]
    return {
        "edge_uses": dict(sorted(uses.items())),
        "continuity": dict(sorted(cont.items())),
        "tolerance": {"max": max(tols), "median": statistics.median(tols)},
        "same_parameter_flagged": sum(1 for r in records if r["same_parameter_flagged"]),
        "dense_over_tolerance": sum(
            1 for r in records if r["same_parameter_dev_dense"] is not None and r["same_parameter_dev_dense"] > r["tolerance"]
        ),
        "same_parameter_dev": {"max": max(devs), "median": statistics.median(devs)},
    }


def check(shape):
    """BRepCheck_Analyzer's verdict and time."""
    start = time.perf_counter()
    valid = BRepCheck_Analyzer(shape).IsValid()
    return {"valid": bool(valid), "seconds": time.perf_counter() - start}


def shells(shape):
    """Shells, closed (every edge bounds two of its faces) or open."""
    items = sub_shapes(shape, TopAbs_SHELL)
    closed = sum(1 for s in items if BRep_Tool.IsClosed_s(s))
    return {"closed": closed, "open": len(items) - closed, "unique": unique_count(items)}


def analyse(path):
    """Everything reported for one file."""
    reader, shape, seconds = best_read(path)
    faces = sub_shapes(shape, TopAbs_FACE)
    edges = sub_shapes(shape, TopAbs_EDGE)
    vertices = sub_shapes(shape, TopAbs_VERTEX)
    solids = sub_shapes(shape, TopAbs_SOLID)
    validity = check(shape)
    records = edge_records(shape)
    return {
        "read_seconds_best_of_3": seconds,
        "faces": {"total": len(faces), "unique": unique_count(faces), "by_surface": by_type(faces, BRepAdaptor_Surface, TopoDS.Face)},
        "edges": {"total": len(edges), "unique": unique_count(edges), "by_curve": by_type(edges, BRepAdaptor_Curve, TopoDS.Edge)},
        "vertices": {"total": len(vertices), "unique": unique_count(vertices)},
        "shells": shells(shape),
        "solids": {"total": len(solids), "unique": unique_count(solids)},
        "check": validity,
        **summarize_edges(records),
        "per_edge": records,
    }


def main(paths):
    out = {}
    for path in paths:
        try:
            out[path.rsplit("/", 1)[-1]] = analyse(path)
        except Exception as err:  # report and go on with the next file
            out[path.rsplit("/", 1)[-1]] = {"error": repr(err)}
    json.dump(out, sys.stdout, indent=1, sort_keys=True)
    sys.stdout.write("\n")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: occt_step.py FILE...")
    main(sys.argv[1:])
