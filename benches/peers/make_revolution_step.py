#!/usr/bin/env python3
"""Write tests/fixtures/step/revolved_vase_occt.step with Open CASCADE.

No openly licensed file found for the corpus has a SURFACE_OF_REVOLUTION
face, so this one is made here (our own, under the project's licence): a
vase turned about Z from a closed profile in the XZ plane — a B-spline
side (a surface of revolution), a line parallel to the axis (a cylinder),
a slanted line (a cone), three lines square to the axis (planes: the
bottom, the rim and the inner bottom) and a segment on the axis (no face).
Its product name carries non-ASCII characters, to see how the writer
encodes them (Open CASCADE 8 writes raw UTF-8 bytes, not \X2\ escapes).
The file's header holds the time it was written, so each run differs.

Run with the venv of ``benches/peers/occt_step`` (cadquery-ocp-novtk):

    /tmp/exact-bezier-occt-venv/bin/python benches/peers/make_revolution_step.py OUT.step
"""

import sys

from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakeFace, BRepBuilderAPI_MakeWire
from OCP.BRepPrimAPI import BRepPrimAPI_MakeRevol
from OCP.collections import Array1_double, Array1_gp_Pnt, Array1_int
from OCP.Geom import Geom_BSplineCurve
from OCP.gp import gp_Ax1, gp_Dir, gp_Pnt
from OCP.IFSelect import IFSelect_RetDone
from OCP.Interface import Interface_Static
from OCP.STEPCAFControl import STEPCAFControl_Writer
from OCP.TCollection import TCollection_ExtendedString
from OCP.TDataStd import TDataStd_Name
from OCP.TDocStd import TDocStd_Document
from OCP.XCAFDoc import XCAFDoc_DocumentTool

PRODUCT_NAME = "Vase \u00e9chantillon \u2013 \u56de\u8ee2\u4f53"  # "Vase échantillon – 回転体"


def side_curve():
    """A cubic B-spline in the XZ plane from (20,0,10) to (12,0,80)."""
    poles = [(20, 10), (35, 30), (8, 55), (12, 80)]
    points = Array1_gp_Pnt(1, len(poles))
    for i, (x, z) in enumerate(poles, 1):
        points.SetValue(i, gp_Pnt(x, 0, z))
    knots = Array1_double(1, 2)
    knots.SetValue(1, 0.0)
    knots.SetValue(2, 1.0)
    mults = Array1_int(1, 2)
    mults.SetValue(1, 4)
    mults.SetValue(2, 4)
    return Geom_BSplineCurve(points, knots, mults, 3)


def profile():
    """The closed profile: bottom, foot (cone), side (B-spline), rim, inside, inner bottom, axis."""
    p = [gp_Pnt(0, 0, 0), gp_Pnt(15, 0, 0), gp_Pnt(20, 0, 10), gp_Pnt(12, 0, 80), gp_Pnt(10, 0, 80), gp_Pnt(10, 0, 5), gp_Pnt(0, 0, 5)]
    wire = BRepBuilderAPI_MakeWire()
    wire.Add(BRepBuilderAPI_MakeEdge(p[0], p[1]).Edge())
    wire.Add(BRepBuilderAPI_MakeEdge(p[1], p[2]).Edge())
    wire.Add(BRepBuilderAPI_MakeEdge(side_curve(), p[2], p[3]).Edge())
    for a, b in zip(p[3:], p[4:] + p[:1]):
        wire.Add(BRepBuilderAPI_MakeEdge(a, b).Edge())
    return BRepBuilderAPI_MakeFace(wire.Wire(), True).Face()


def main(out):
    solid = BRepPrimAPI_MakeRevol(profile(), gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1))).Shape()
    Interface_Static.SetCVal_s("write.step.schema", "AP214IS")
    doc = TDocStd_Document(TCollection_ExtendedString("XmlOcaf"))
    label = XCAFDoc_DocumentTool.ShapeTool_s(doc.Main()).AddShape(solid)
    TDataStd_Name.Set_s(label, TCollection_ExtendedString(PRODUCT_NAME, True))
    writer = STEPCAFControl_Writer()
    writer.Transfer(doc)
    if writer.Write(out) != IFSelect_RetDone:
        sys.exit(f"cannot write {out}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "revolved_vase_occt.step")
