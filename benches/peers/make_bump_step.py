#!/usr/bin/env python3
"""Write a STEP solid one of whose edges has a bump that 23 samples miss (issue 28).

    python3 benches/peers/make_bump_step.py [DELTA] > benches/peers/bump_edge.step

A tetrahedron in millimetres, all four faces planes, with vertices
A = (0, 0, 0), B = (120, 0, 0), C = (60, 90, 0), D = (60, 30, 70).  Five
edges are lines; the edge AB is a cubic B-spline on [0, 1] with the clamped
knot vector

    0 0 0 0  0.46 0.4675 0.475 0.4825 0.49  1 1 1 1

whose nine control points sit on the segment AB at their Greville
abscissae (so the curve is exactly A + t (B - A), linear precision) except
the fifth, moved by (0, -DELTA, -DELTA) (default DELTA = 0.003 mm): out of
both faces' planes (the bottom z = 0 and the plane of A, B, D).  Its basis
function is zero outside [0.46, 0.49], which lies strictly between the
samples t = 10/22 = 0.4545... and 11/22 = 0.5 of Open CASCADE's 23-point
checks, so at those 23 parameters the edge is exactly on both planes, and
between them it leaves them by up to DELTA times the basis function's
maximum (one component of the displacement for the bottom plane, 4/sqrt(58)
of it for the other).

No p-curves are written (like the Creo and CATIA files of the corpus): the
reader computes them.  Standard library only; the numbers are written as
exact decimals.
"""

import sys
from fractions import Fraction as F

POINTS = {"A": (0, 0, 0), "B": (120, 0, 0), "C": (60, 90, 0), "D": (60, 30, 70)}
FACES = [("A", "B", "C"), ("A", "B", "D"), ("B", "C", "D"), ("C", "A", "D")]
KNOTS = [F(0)] * 4 + [F(s) for s in ("0.46", "0.4675", "0.475", "0.4825", "0.49")] + [F(1)] * 4
BUMPED = 4  # control point index: its basis function lives on [KNOTS[4], KNOTS[8]]


def sub(p, q):
    return tuple(a - b for a, b in zip(p, q))


def cross(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def dot(u, v):
    return sum(a * b for a, b in zip(u, v))


def dec(x):
    """An exact decimal for a rational with a terminating expansion."""
    x = F(x)
    sign = "-" if x < 0 else ""
    x = abs(x)
    whole, rest = divmod(x.numerator, x.denominator)
    digits = ""
    while rest:
        rest *= 10
        digits += str(rest // x.denominator)
        rest %= x.denominator
        if len(digits) > 40:
            raise ValueError(f"{x} has no short decimal expansion")
    return f"{sign}{whole}." + digits


class Writer:
    def __init__(self):
        self.lines = []

    def add(self, text):
        self.lines.append(text)
        return f"#{len(self.lines)}"

    def point(self, p):
        return self.add(f"CARTESIAN_POINT('',({','.join(dec(c) for c in p)}))")

    def direction(self, d):
        return self.add(f"DIRECTION('',({','.join(dec(c) for c in d)}))")


def outward_cycles():
    """Each face's vertex cycle, counter-clockwise seen from outside, and its outward normal."""
    centre = tuple(F(sum(POINTS[v][i] for v in POINTS), 4) for i in range(3))
    out = []
    for face in FACES:
        p, q, r = (POINTS[v] for v in face)
        n = cross(sub(q, p), sub(r, p))
        if dot(n, sub(p, centre)) < 0:
            face = (face[0], face[2], face[1])
            n = tuple(-c for c in n)
        out.append((face, n))
    return out


def bump_control_points(delta):
    a, b = POINTS["A"], POINTS["B"]
    pts = []
    for j in range(len(KNOTS) - 4):
        g = sum(KNOTS[j + 1 : j + 4]) / 3  # Greville abscissa
        p = [a[i] + (b[i] - a[i]) * g for i in range(3)]
        if j == BUMPED:
            p[1] -= delta
            p[2] -= delta
        pts.append(tuple(p))
    return pts


def write(delta):
    w = Writer()
    vertex = {name: w.add(f"VERTEX_POINT('',{w.point(p)})") for name, p in POINTS.items()}
    edges = {}
    for name_a, name_b in (("A", "B"), ("A", "C"), ("A", "D"), ("B", "C"), ("B", "D"), ("C", "D")):
        if (name_a, name_b) == ("A", "B"):
            poles = ",".join(w.point(p) for p in bump_control_points(delta))
            mults = "4,1,1,1,1,1,4"
            knots = ",".join(dec(k) for k in ["0", "0.46", "0.4675", "0.475", "0.4825", "0.49", "1"])
            curve = w.add(
                f"B_SPLINE_CURVE_WITH_KNOTS('',3,({poles}),.UNSPECIFIED.,.F.,.F.,({mults}),({knots}),.UNSPECIFIED.)"
            )
        else:
            p, q = POINTS[name_a], POINTS[name_b]
            d = sub(q, p)
            curve = w.add(f"LINE('',{w.point(p)},{w.add(f'VECTOR({chr(39)}{chr(39)},{w.direction(d)},1.)')})")
        edges[(name_a, name_b)] = w.add(f"EDGE_CURVE('',{vertex[name_a]},{vertex[name_b]},{curve},.T.)")
    faces = []
    for cycle, normal in outward_cycles():
        oriented = []
        for k in range(3):
            s, e = cycle[k], cycle[(k + 1) % 3]
            if (s, e) in edges:
                oriented.append(w.add(f"ORIENTED_EDGE('',*,*,{edges[(s, e)]},.T.)"))
            else:
                oriented.append(w.add(f"ORIENTED_EDGE('',*,*,{edges[(e, s)]},.F.)"))
        loop = w.add(f"EDGE_LOOP('',({','.join(oriented)}))")
        bound = w.add(f"FACE_OUTER_BOUND('',{loop},.T.)")
        p, q = POINTS[cycle[0]], POINTS[cycle[1]]
        axes = w.add(f"AXIS2_PLACEMENT_3D('',{w.point(p)},{w.direction(normal)},{w.direction(sub(q, p))})")
        plane = w.add(f"PLANE('',{axes})")
        faces.append(w.add(f"ADVANCED_FACE('',({bound}),{plane},.T.)"))
    shell = w.add(f"CLOSED_SHELL('',({','.join(faces)}))")
    solid = w.add(f"MANIFOLD_SOLID_BREP('bump',{shell})")
    length = w.add("(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.))")
    angle = w.add("(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.))")
    solid_angle = w.add("(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT())")
    uncertainty = w.add(f"UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-06),{length},'distance_accuracy_value','')")
    context = w.add(
        "(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT"
        f"(({uncertainty}))GLOBAL_UNIT_ASSIGNED_CONTEXT(({length},{angle},{solid_angle}))"
        "REPRESENTATION_CONTEXT('',''))"
    )
    origin = w.add(f"AXIS2_PLACEMENT_3D('',{w.point((0, 0, 0))},$,$)")
    rep = w.add(f"ADVANCED_BREP_SHAPE_REPRESENTATION('',({origin},{solid}),{context})")
    app = w.add("APPLICATION_CONTEXT('automotive design')")
    w.add(f"APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000,{app})")
    product_context = w.add(f"PRODUCT_CONTEXT('',{app},'mechanical')")
    product = w.add(f"PRODUCT('bump','bump','',({product_context}))")
    formation = w.add(f"PRODUCT_DEFINITION_FORMATION('','',{product})")
    definition_context = w.add(f"PRODUCT_DEFINITION_CONTEXT('part definition',{app},'design')")
    definition = w.add(f"PRODUCT_DEFINITION('design','',{formation},{definition_context})")
    shape = w.add(f"PRODUCT_DEFINITION_SHAPE('','',{definition})")
    w.add(f"SHAPE_DEFINITION_REPRESENTATION({shape},{rep})")
    head = [
        "ISO-10303-21;",
        "HEADER;",
        "FILE_DESCRIPTION(('tetrahedron with a bumped B-spline edge, benches/peers/make_bump_step.py'),'2;1');",
        f"FILE_NAME('bump_edge.step','2026-11-26T00:00:00',(''),(''),'make_bump_step.py','make_bump_step.py DELTA={dec(delta)}','');",
        "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));",
        "ENDSEC;",
        "DATA;",
    ]
    body = [f"#{k}={line};" for k, line in enumerate(w.lines, 1)]
    return "\n".join(head + body + ["ENDSEC;", "END-ISO-10303-21;", ""])


if __name__ == "__main__":
    sys.stdout.write(write(F(sys.argv[1]) if len(sys.argv) > 1 else F("0.003")))
