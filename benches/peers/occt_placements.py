#!/usr/bin/env python3
"""Open CASCADE's placed vertices of STEP assemblies, for the test of
assembly placements (issue 27); outside CI.

    /tmp/exact-bezier-occt-venv/bin/python benches/peers/occt_placements.py FILE... \
        > tests/fixtures/step/occt_placed_vertices.json

(the venv is the one ``benches/peers/occt_step`` makes). For each file:
STEPControl_Reader ReadFile + TransferRoots, then every distinct vertex of
the result (``TopExp::MapShapes``: a part placed twice gives its vertices
twice) at its placed position (``BRep_Tool::Pnt``), in Open CASCADE's unit,
the millimetre, as floats rounded to 1e-9 mm.
"""

import json
import sys

from OCP.BRep import BRep_Tool
from OCP.IFSelect import IFSelect_RetDone
from OCP.STEPControl import STEPControl_Reader
from OCP.TopAbs import TopAbs_VERTEX
from OCP.TopExp import TopExp
from OCP.TopoDS import TopoDS
from OCP.collections import IndexedMap_TopoDS_Shape_TopTools_ShapeMapHasher as ShapeMap


def placed_vertices(path):
    reader = STEPControl_Reader()
    if reader.ReadFile(path) != IFSelect_RetDone:
        raise SystemExit(f"Open CASCADE cannot read {path}")
    reader.TransferRoots()
    vertices = ShapeMap()
    TopExp.MapShapes_s(reader.OneShape(), TopAbs_VERTEX, vertices)
    points = []
    for k in range(1, vertices.Extent() + 1):
        p = BRep_Tool.Pnt_s(TopoDS.Vertex(vertices.FindKey(k)))
        points.append([round(c, 9) for c in (p.X(), p.Y(), p.Z())])
    return sorted(points)


def main():
    out = {}
    for path in sys.argv[1:]:
        out[path.rsplit("/", 1)[-1]] = {"unit": "mm", "vertices": placed_vertices(path)}
    json.dump(out, sys.stdout, indent=None, separators=(",", ":"))
    print()


if __name__ == "__main__":
    main()
