#!/usr/bin/env python3
"""Dense 50-digit sampling of the gaps and angles along a STEP B-rep's edges.

An independent estimate, for the audit's certified measures (issue 28), of

* ``gap``: for each face of an edge, the largest distance from the edge's
  3D curve to the face's surface;
* ``face_gap``: the largest distance between the two faces' foot points
  (the nearest points of the edge point on each surface);
* ``angle``: the largest angle, radians, between the faces' oriented
  normals at the foot points (the surface's normal as ISO 10303-42 defines
  it from its parameterization, reversed where the ADVANCED_FACE's
  ``same_sense`` is false).

It shares nothing with the exact-bezier crate: the file is parsed by
``step_counts.py`` (the independent Part 21 reader beside it) and every
number is evaluated at 50 significant digits (MPFR at 170 bits through
gmpy2 when it is installed, else mpmath at 50 digits), lengths in the
file's length unit as written.  A conversion-based plane angle unit named
degree is taken as pi/180 exactly (the file's decimal factor is its
rounding); other units by their written factor.

Which edges: every EDGE_CURVE used twice by the face loops (a shared edge
between two faces, or a seam used twice by one face) whose faces are
ADVANCED_FACE/FACE_SURFACE on a PLANE, CYLINDRICAL_SURFACE,
CONICAL_SURFACE, SPHERICAL_SURFACE or TOROIDAL_SURFACE (minor radius below
the major) and whose 3D curve (through SURFACE_CURVE / SEAM_CURVE /
INTERSECTION_CURVE) is a LINE, CIRCLE, ELLIPSE or B_SPLINE_CURVE_WITH_KNOTS
(rational or not); the others are counted by reason under ``skipped``.

The curve is trimmed between the edge's vertices: each vertex is projected
on the curve (best of dense samples, then Newton on ``C'.(C - V) = 0``),
and the edge is the part from the start vertex to the end vertex along the
curve when EDGE_CURVE.same_sense is true, against it otherwise (which part
of a closed curve; ORIENTED_EDGE only says which way a loop runs, not which
points).  A closed edge (start vertex = end vertex) is the whole curve.

Sampling: ``N`` (513) parameters evenly spaced over the trimmed range, then
``FINE`` (65) more spread over the two sample intervals beside the largest
sample of each measure.  For each measure the output gives its largest sampled
value ``max``, the edge parameter fraction ``at`` in [0, 1] where it was
sampled, and ``slack``: half the largest second difference of the measure
over the evenly spaced samples.  Between samples ``h`` apart the true
maximum exceeds the largest sample by at most ``M2 h^2 / 8`` (Taylor
expansion about an interior maximum, whose nearest sample is within
``h/2``; ``M2`` bounds the second derivative), and a second difference
estimates ``M2 h^2``: ``slack`` is four times that estimate.  It is an
estimate, not a bound (the measure must be smooth on the scale of ``h``).
``scale`` is the largest coordinate magnitude of the samples (the size
against which rounding is judged).

    python3 benches/peers/step_sample.py FILE... > sampled.json
    python3 benches/peers/step_sample.py --self-test
"""

import json
import os
from decimal import Decimal
import sys
from collections import Counter, defaultdict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import step_counts as sc  # noqa: E402  (the independent Part 21 reader)

try:  # MPFR through gmpy2 (the same 50 digits, many times faster)
    import gmpy2

    gmpy2.get_context().precision = 170  # 51 decimal digits
    mpf, sqrt, atan2, cos, sin, tan = gmpy2.mpfr, gmpy2.sqrt, gmpy2.atan2, gmpy2.cos, gmpy2.sin, gmpy2.tan
    PI = gmpy2.const_pi()
except ImportError:
    import mpmath

    mpmath.mp.dps = 50
    mpf, sqrt, atan2, cos, sin, tan = mpmath.mpf, mpmath.sqrt, mpmath.atan2, mpmath.cos, mpmath.sin, mpmath.tan
    PI = mpmath.mp.pi
N = 513
FINE = 65
SURFACES = ("PLANE", "CYLINDRICAL_SURFACE", "CONICAL_SURFACE", "SPHERICAL_SURFACE", "TOROIDAL_SURFACE")


class Skip(Exception):
    """An edge this evaluator does not support, with the reason."""


# ---------------------------------------------------------------- vectors


def num(x):
    return mpf(str(x))


def add(a, b):
    return [x + y for x, y in zip(a, b)]


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def scale(a, s):
    return [x * s for x in a]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return sqrt(dot(a, a))


def unit(a):
    n = norm(a)
    if n == 0:
        raise Skip("zero direction")
    return scale(a, 1 / n)


# ---------------------------------------------------------------- entities


class Model:
    """The instances of one file and the readers of its geometry."""

    def __init__(self, path):
        _, self.inst, _ = sc.read_file(path)
        self.degree = self.angle_unit()

    def params(self, ref, name):
        parts = self.inst.get(ref.id) if isinstance(ref, sc.Ref) else None
        if parts is None or name not in parts:
            raise Skip("expected %s" % name)
        return parts[name]

    def angle_unit(self):
        """Radians per unit of plane angle (the first context that assigns one)."""
        for r in sc.contexts(self.inst):
            u = r.get("plane_angle_unit")
            if not u:
                continue
            if "conversion" in u:
                if u["conversion"].strip().upper() == "DEGREE":
                    return PI / 180
                inner = u.get("factor_unit", {})
                base = mpf(1) if inner.get("prefix") is None else {"MILLI": mpf("0.001")}[inner["prefix"]]
                return num(u["factor"]) * base
            return mpf(1) if u.get("prefix") is None else {"MILLI": mpf("0.001")}[u["prefix"]]
        return mpf(1)

    def cone_slope(self, text):
        """tan of a cone's semi-angle written as ``text`` in the model's angle
        unit, by the reading rule of docs/nurbs_step.md ("The cone angle"):
        a decimal that is a multiple k*15 degrees (k = 1..5) rounded to its
        printed digits is that angle exactly; any other decimal is itself."""
        written = num(text)
        half_unit = mpf(10) ** Decimal(text).as_tuple().exponent / 2
        for k in range(1, 6):
            exact = k * PI / 12
            if abs(written - exact / self.degree) <= half_unit:
                return tan(exact)
        return tan(written * self.degree)

    def point(self, ref):
        return [num(x) for x in self.params(ref, "CARTESIAN_POINT")[1]]

    def direction(self, ref):
        return unit([num(x) for x in self.params(ref, "DIRECTION")[1]])

    def placement(self, ref):
        """(origin, x, y, z) of an AXIS2_PLACEMENT_3D (ISO 10303-42 build_axes)."""
        p = self.params(ref, "AXIS2_PLACEMENT_3D")
        origin = self.point(p[1])
        z = self.direction(p[2]) if p[2] is not None else [mpf(0), mpf(0), mpf(1)]
        if p[3] is not None:
            v = self.direction(p[3])
        elif [float(c) for c in z] not in ([1.0, 0.0, 0.0], [-1.0, 0.0, 0.0]):
            v = [mpf(1), mpf(0), mpf(0)]
        else:
            v = [mpf(0), mpf(1), mpf(0)]
        x = unit(sub(v, scale(z, dot(v, z))))
        return origin, x, cross(z, x), z

    def surface(self, ref):
        parts = self.inst.get(ref.id, {})
        name = sc.kind(parts)
        if name not in SURFACES:
            raise Skip("surface " + name)
        p = parts[name]
        frame = self.placement(p[1])
        if name == "PLANE":
            return Plane(frame)
        if name == "CYLINDRICAL_SURFACE":
            return Cylinder(frame, num(p[2]))
        if name == "SPHERICAL_SURFACE":
            return Sphere(frame, num(p[2]))
        if name == "CONICAL_SURFACE":
            return Cone(frame, num(p[2]), self.cone_slope(str(p[3])))
        major, minor = num(p[2]), num(p[3])
        if not minor < major:
            raise Skip("degenerate torus")
        return Torus(frame, major, minor)

    def curve(self, ref):
        seen = set()
        while True:
            parts = self.inst.get(ref.id, {})
            inner = next((parts[n] for n in sc.CURVES_ON_SURFACE if n in parts), None)
            if inner is None or ref.id in seen:
                break
            seen.add(ref.id)
            ref = inner[1]
        name = sc.kind(parts)
        if name == "LINE":
            p = parts["LINE"]
            v = self.params(p[2], "VECTOR")
            return Line(self.point(p[1]), scale(self.direction(v[1]), num(v[2])))
        if name == "CIRCLE":
            p = parts["CIRCLE"]
            return Ellipse(self.placement(p[1]), num(p[2]), num(p[2]))
        if name == "ELLIPSE":
            p = parts["ELLIPSE"]
            return Ellipse(self.placement(p[1]), num(p[2]), num(p[3]))
        if "B_SPLINE_CURVE_WITH_KNOTS" in parts:
            return self.bspline(parts)
        raise Skip("curve " + name)

    def bspline(self, parts):
        wk = parts["B_SPLINE_CURVE_WITH_KNOTS"]
        base = parts.get("B_SPLINE_CURVE")
        if base is None:  # simple instance: name, B_SPLINE_CURVE's five, then its own
            base, wk = wk[1:6], wk[6:]
        degree = int(base[0])
        points = [self.point(r) for r in base[1]]
        weights = [mpf(1)] * len(points)
        if "RATIONAL_B_SPLINE_CURVE" in parts:
            weights = [num(w) for w in parts["RATIONAL_B_SPLINE_CURVE"][0]]
        knots = [num(k) for k, m in zip(wk[1], wk[0]) for _ in range(int(m))]
        if len(knots) != len(points) + degree + 1:
            raise Skip("B-spline knot count")
        return BSpline(degree, points, weights, knots)


# ---------------------------------------------------------------- surfaces
# Each gives, for a point p: (distance, foot point, unit normal at the
# foot as the surface's parameterization orients it), or raises Skip where
# the foot is not unique (on an axis, at an apex or a centre).


class Surface:
    def __init__(self, frame):
        self.c, self.x, self.y, self.z = frame

    def local(self, p):
        d = sub(p, self.c)
        a, b, h = dot(d, self.x), dot(d, self.y), dot(d, self.z)
        rho = sqrt(a * a + b * b)
        return d, h, rho, (add(scale(self.x, a / rho), scale(self.y, b / rho)) if rho > 0 else None)


class Plane(Surface):
    def foot(self, p):
        h = dot(sub(p, self.c), self.z)
        return abs(h), sub(p, scale(self.z, h)), self.z


class Cylinder(Surface):
    def __init__(self, frame, r):
        super().__init__(frame)
        self.r = r

    def foot(self, p):
        _, h, rho, er = self.local(p)
        if er is None:
            raise Skip("point on a cylinder's axis")
        return abs(rho - self.r), add(self.c, add(scale(self.z, h), scale(er, self.r))), er


class Sphere(Surface):
    def __init__(self, frame, r):
        super().__init__(frame)
        self.r = r

    def foot(self, p):
        d = sub(p, self.c)
        q = norm(d)
        if q == 0:
            raise Skip("point at a sphere's centre")
        u = scale(d, 1 / q)
        return abs(q - self.r), add(self.c, scale(u, self.r)), u


class Cone(Surface):
    """sigma(u, v) = c + (R + v k)(cos u x + sin u y) + v z, k = tan(semi_angle),
    for every real v: both nappes (past the apex, R + v k < 0, the point
    lies on the opposite side of the axis)."""

    def __init__(self, frame, r, k):
        super().__init__(frame)
        self.r, self.k = r, k

    def foot(self, p):
        """The nearer of the feet on the two generators in p's half-plane
        (rho = R + k v where R + k v >= 0, rho = -(R + k v) where <= 0)."""
        _, h, rho, er = self.local(p)
        if er is None:
            raise Skip("point on a cone's axis")
        k, s = self.k, sqrt(1 + self.k**2)
        best = None
        for sign in (1, -1):  # rho = sign (R + k v)
            v = (k * (sign * rho - self.r) + h) / (s * s)
            radius = self.r + k * v
            if sign * radius < 0:
                continue
            d = abs(rho - sign * (self.r + k * h)) / s
            if best is None or d < best[0]:
                foot = add(self.c, add(scale(er, sign * radius), scale(self.z, v)))
                # sigma_u x sigma_v = (R + k v)(e(u) - k z), e(u) = sign er
                n = scale(sub(er, scale(self.z, sign * k)), 1 / s)
                best = (d, foot, n)
        if best is None:
            raise Skip("foot at a cone's apex")
        return best


class Torus(Surface):
    def __init__(self, frame, major, minor):
        super().__init__(frame)
        self.major, self.minor = major, minor

    def foot(self, p):
        _, h, rho, er = self.local(p)
        if er is None:
            raise Skip("point on a torus's axis")
        a, m = rho - self.major, sqrt((rho - self.major) ** 2 + h * h)
        if m == 0:
            raise Skip("point on a torus's centre circle")
        n = scale(add(scale(er, a), scale(self.z, h)), 1 / m)
        centre = add(self.c, scale(er, self.major))
        return abs(m - self.minor), add(centre, scale(n, self.minor)), n


# ---------------------------------------------------------------- curves
# Each has a parameter domain [lo, hi] (None for a line), `closed`, and
# `at(t)` -> point.


class Line:
    lo = hi = None
    closed = False

    def __init__(self, p, v):
        self.p, self.v = p, v

    def at(self, t):
        return add(self.p, scale(self.v, t))

    def locate(self, q):
        return dot(sub(q, self.p), self.v) / dot(self.v, self.v)


class Ellipse:
    closed = True

    def __init__(self, frame, a, b):
        self.c, self.x, self.y, _ = frame
        self.a, self.b = a, b
        self.lo, self.hi = mpf(0), 2 * PI

    def at(self, t):
        return add(self.c, add(scale(self.x, self.a * cos(t)), scale(self.y, self.b * sin(t))))

    def locate(self, q):
        d = sub(q, self.c)
        t = atan2(dot(d, self.y) / self.b, dot(d, self.x) / self.a)
        return newton(self, q, t % (2 * PI))


class BSpline:
    def __init__(self, degree, points, weights, knots):
        self.p = degree
        self.hom = [scale(pt, w) + [w] for pt, w in zip(points, weights)]
        self.knots = knots
        self.lo, self.hi = knots[degree], knots[len(points)]
        self.closed = norm(sub(self.at(self.lo), self.at(self.hi))) < mpf(10) ** -30

    def at(self, t):
        """de Boor's algorithm on homogeneous points (Piegl & Tiller, A3.1)."""
        p, U = self.p, self.knots
        t = min(max(t, self.lo), self.hi)
        k = p
        while k + 1 < len(self.hom) and U[k + 1] <= t:
            k += 1
        d = [list(self.hom[j + k - p]) for j in range(p + 1)]
        for r in range(1, p + 1):
            for j in range(p, r - 1, -1):
                i = j + k - p
                den = U[i + p - r + 1] - U[i]
                alpha = (t - U[i]) / den if den != 0 else mpf(0)
                d[j] = [(1 - alpha) * x + alpha * y for x, y in zip(d[j - 1], d[j])]
        w = d[p][3]
        return [c / w for c in d[p][:3]]

    def locate(self, q):
        ts = [self.lo + (self.hi - self.lo) * i / 256 for i in range(257)]
        t = min(ts, key=lambda s: norm(sub(self.at(s), q)))
        return newton(self, q, t)


def newton(curve, q, t):
    """Refine t to a local minimum of |C(t) - q| (Newton on C'.(C - q) = 0,
    derivatives by central differences at 50 digits), kept in the domain."""
    h = mpf(10) ** -18
    for _ in range(40):
        c0, cp, cm = curve.at(t), curve.at(t + h), curve.at(t - h)
        d1 = scale(sub(cp, cm), 1 / (2 * h))
        d2 = scale(add(sub(cp, scale(c0, 2)), cm), 1 / (h * h))
        f = dot(d1, sub(c0, q))
        fp = dot(d2, sub(c0, q)) + dot(d1, d1)
        if fp <= 0:
            break
        step = f / fp
        t = t - step
        if curve.lo is not None:
            t = min(max(t, curve.lo), curve.hi)
        if abs(step) < mpf(10) ** -40:
            break
    return t


def trimmed(curve, start, end, same_vertex, same_sense):
    """The edge's parameter ranges [(a, b), ...] on the curve (increasing)."""
    if same_vertex:
        if not curve.closed:
            raise Skip("closed edge on an open curve")
        return [(curve.lo, curve.hi)]
    ts, te = curve.locate(start), curve.locate(end)
    if not same_sense:
        ts, te = te, ts  # the same points, walked along the curve
    if curve.lo is None:
        return [(min(ts, te), max(ts, te))]
    if ts < te:
        return [(ts, te)]
    if not curve.closed:
        raise Skip("edge runs backwards on an open curve")
    return [(ts, curve.hi), (curve.lo, te)]


# ---------------------------------------------------------------- sampling


def parameters(ranges, fractions):
    """Edge parameters at the given fractions of the trimmed length."""
    lengths = [b - a for a, b in ranges]
    total = sum(lengths)
    out = []
    for f in fractions:
        s = f * total
        for (a, b), ln in zip(ranges, lengths):
            if s <= ln or (a, b) == ranges[-1]:
                out.append(a + min(s, ln))
                break
            s -= ln
    return out


def measure(curve, faces, t):
    """(gaps by face, face gap, angle, |point|) at the parameter t."""
    p = curve.at(t)
    feet = [surf.foot(p) for surf, _ in faces]
    normals = [scale(n, 1 if sense else -1) for (_, _, n), (_, sense) in zip(feet, faces)]
    angle = atan2(norm(cross(normals[0], normals[1])), dot(normals[0], normals[1]))
    return [f[0] for f in feet] + [norm(sub(feet[0][1], feet[1][1])), angle], max(abs(c) for c in p)


def sample_edge(curve, faces, ranges):
    fractions = [mpf(i) / (N - 1) for i in range(N)]
    values = [measure(curve, faces, t)[0] for t in parameters(ranges, fractions)]
    size = max(measure(curve, faces, t)[1] for t in parameters(ranges, fractions[:: (N - 1) // 16]))
    results = []
    for m in range(4):
        series = [v[m] for v in values]
        slack = max(abs(series[i - 1] - 2 * series[i] + series[i + 1]) for i in range(1, N - 1)) / 2
        best = max(range(N), key=lambda i: series[i])
        lo, hi = fractions[max(best - 1, 0)], fractions[min(best + 1, N - 1)]
        fine = [lo + (hi - lo) * i / (FINE - 1) for i in range(FINE)]
        top, at = series[best], fractions[best]
        for f, t in zip(fine, parameters(ranges, fine)):
            v = measure(curve, faces, t)[0][m]
            if v > top:
                top, at = v, f
        results.append({"max": float(top), "at": round(float(at), 6), "slack": float("%.3g" % float(slack))})
    return results, size


def edge_faces(inst):
    """EDGE_CURVE id -> [(face id, face params)] one per use in the loops."""
    uses = defaultdict(list)
    for ident, parts in inst.items():
        p = parts.get("ADVANCED_FACE") or parts.get("FACE_SURFACE")
        if p is None:
            continue
        for bref in p[1] or []:
            bound = inst.get(bref.id, {})
            bp = bound.get("FACE_OUTER_BOUND") or bound.get("FACE_BOUND")
            loop = inst.get(bp[1].id, {}) if bp else {}
            for oref in loop.get("EDGE_LOOP", [None, []])[1]:
                edge = sc.edge_element(inst, oref)
                if edge is not None:
                    uses[edge].append((ident, p))
    return uses


def sample_file(path):
    model = Model(path)
    inst = model.inst
    out, skipped = {}, Counter()
    for edge, uses in sorted(edge_faces(inst).items()):
        if len(uses) != 2:
            continue
        p = inst[edge]["EDGE_CURVE"]
        try:
            faces = [(model.surface(fp[2]), fp[3].name == "T") for _, fp in uses]
            curve = model.curve(p[3])
            start = model.point(model.params(p[1], "VERTEX_POINT")[1])
            end = model.point(model.params(p[2], "VERTEX_POINT")[1])
            ranges = trimmed(curve, start, end, p[1].id == p[2].id, p[4].name == "T")
            results, size = sample_edge(curve, faces, ranges)
        except Skip as why:
            skipped[str(why)] += 1
            continue
        names = ["#%d" % f for f, _ in uses]
        out["#%d" % edge] = {
            "faces": names,
            "gap": {names[0]: results[0], names[1]: results[1]},
            "face_gap": results[2],
            "angle": results[3],
            "scale": float("%.6g" % float(size)),
        }
    return {"edges": out, "skipped": dict(sorted(skipped.items()))}


SELF_TEST = """ISO-10303-21;
HEADER;
FILE_DESCRIPTION((''),'2;1');
FILE_NAME('','',(''),(''),'','','');
FILE_SCHEMA(('AUTOMOTIVE_DESIGN'));
ENDSEC;
DATA;
#1=CARTESIAN_POINT('',(0.,0.,0.));
#2=DIRECTION('',(0.,0.,1.));
#3=DIRECTION('',(1.,0.,0.));
#4=AXIS2_PLACEMENT_3D('',#1,#2,#3);
#5=CYLINDRICAL_SURFACE('',#4,2.);
#6=CARTESIAN_POINT('',(0.,0.,3.));
#7=AXIS2_PLACEMENT_3D('',#6,#2,#3);
#8=PLANE('',#7);
#9=CIRCLE('',#7,2.0000001);
#10=CARTESIAN_POINT('',(2.0000001,0.,3.));
#11=VERTEX_POINT('',#10);
#12=EDGE_CURVE('',#11,#11,#9,.T.);
#13=ORIENTED_EDGE('',*,*,#12,.T.);
#14=ORIENTED_EDGE('',*,*,#12,.F.);
#15=EDGE_LOOP('',(#13));
#16=EDGE_LOOP('',(#14));
#17=FACE_BOUND('',#15,.T.);
#18=FACE_BOUND('',#16,.T.);
#19=ADVANCED_FACE('',(#17),#5,.T.);
#20=ADVANCED_FACE('',(#18),#8,.T.);
ENDSEC;
END-ISO-10303-21;
"""


def self_test():
    """A circle of radius 2 + 1e-7 on the top plane of a cylinder of radius 2:
    gaps 1e-7 (cylinder) and 0 (plane), face gap 1e-7, angle pi/2."""
    import tempfile

    with tempfile.NamedTemporaryFile("w", suffix=".stp", delete=False) as f:
        f.write(SELF_TEST)
    try:
        e = sample_file(f.name)["edges"]["#12"]
    finally:
        os.unlink(f.name)
    assert abs(e["gap"]["#19"]["max"] - 1e-7) < 1e-20, e
    assert e["gap"]["#20"]["max"] < 1e-40, e
    assert abs(e["face_gap"]["max"] - 1e-7) < 1e-20, e
    assert abs(e["angle"]["max"] - float(PI / 2)) < 1e-15, e
    print("self-test passed")


def write(files, out):
    """JSON with one line per edge: {file: {"edges": {id: {...}}, "skipped": {...}}}."""
    out.write("{\n")
    for i, (name, f) in enumerate(sorted(files.items())):
        out.write(" %s: {\n  \"skipped\": %s,\n  \"edges\": {\n" % (json.dumps(name), json.dumps(f["skipped"])))
        edges = sorted(f["edges"].items(), key=lambda kv: int(kv[0][1:]))
        for j, (ident, e) in enumerate(edges):
            sep = "," if j + 1 < len(edges) else ""
            out.write("   %s: %s%s\n" % (json.dumps(ident), json.dumps(e, sort_keys=True), sep))
        out.write("  }\n }%s\n" % ("," if i + 1 < len(files) else ""))
    out.write("}\n")


def main(paths):
    write({path.rsplit("/", 1)[-1]: sample_file(path) for path in paths}, sys.stdout)


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        self_test()
    elif len(sys.argv) < 2:
        sys.exit("usage: step_sample.py FILE... | --self-test")
    else:
        main(sys.argv[1:])
