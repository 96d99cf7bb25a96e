#!/usr/bin/env python3
"""Dense 50-digit sampling of the gaps, angles and curvature differences along a STEP B-rep's edges.

An independent estimate, for the audit's certified measures (issue 28), of

* ``gap``: for each face of an edge, the largest distance from the edge's
  3D curve to the face's surface;
* ``face_gap``: the largest distance between the two faces' foot points
  (the nearest points of the edge point on each surface);
* ``angle``: the largest angle, radians, between the faces' oriented
  normals at the foot points (the surface's normal as ISO 10303-42 defines
  it from its parameterization, reversed where the ADVANCED_FACE's
  ``same_sense`` is false);
* ``curvature``: the largest difference of the faces' normal curvatures
  across the edge, ``|k1 - k2|``, each ``k = II(w, w) / I(w, w)`` at the
  foot point in the direction ``w = n x C'`` (n the face's oriented normal
  there), per length unit (see ``curvature_across``).

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
CONICAL_SURFACE, SPHERICAL_SURFACE, TOROIDAL_SURFACE (minor radius below
the major), SURFACE_OF_REVOLUTION (of a curve below, not a line) or
B_SPLINE_SURFACE_WITH_KNOTS (the simple entity, or the
complex entity with B_SPLINE_SURFACE and, rational, RATIONAL_B_SPLINE_SURFACE)
and whose 3D curve (through SURFACE_CURVE / SEAM_CURVE / INTERSECTION_CURVE)
is a LINE, CIRCLE, ELLIPSE or B_SPLINE_CURVE_WITH_KNOTS (rational or not);
the others are counted by reason under ``skipped``.

On the elementary surfaces the foot point (the nearest point) is closed
form.  A B-spline surface (ISO 10303-42: knots repeated by their
multiplicities, control_points_list[i][j] with i along u, weights) is
evaluated here, with its first and second partial derivatives, by Cox-de
Boor's recurrence for the basis functions and their derivatives (Piegl &
Tiller, A2.3) on the homogeneous control points, then the quotient rule;
its normal is S_u x S_v.  Its foot is the nearest point *within its
parameter domain* [U[p], U[n_u]] x [V[q], V[n_v]] (the knot range, not
the face's trimmed part): Newton on (S - q).S_u = 0, (S - q).S_v = 0
(damped so that the distance never grows) from the previous sample's foot
on the same edge, and also from the nearest point of a coarse grid (knots
and 4 points per knot span, at least 16 intervals per direction) whenever
that grid point is nearer than the foot found; a parameter that reaches
the domain's border is held there while the gradient pushes outward (a
1-D Newton along the border curve, or a corner).  A foot on a border is
also sought from the opposite border (the other side of a closed
surface's seam: a direction is closed when its two borders agree to 1e-7
of the surface's size); a foot where S_u x S_v nearly vanishes (a pole,
an apex) is sought again from the 8 nearest regular grid points, and an
edge whose foot stays there is skipped (as a point on a cone's axis is).
Newton stops after a step below 1e-25 of the domain's width (converging
quadratically, the foot is then off by about the square of that step).
This is a local search: ``--check-feet`` compares its feet with Newton
from the 6 nearest points of a dense 61 x 61 grid over the domain at
every 8th sample of each B-spline edge.  On the corpus (1 319 B-spline
edges, 118 105 feet: 96 850 of them on tail_section_asm.stp, 17 minutes)
no foot was nearer by brute force; before the seam and degenerate-point
searches were added it found feet stuck at a closed surface's seam
(nist_ctc_02 and dm1-id, up to 10 mm off).

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
    python3 benches/peers/step_sample.py --check-feet FILE...
"""

import bisect
import json
import math
import os
from decimal import Decimal
from operator import mul
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
# Newton for a foot on a B-spline surface stops after a step below
# CONVERGED_STEP (relative to the domain's width; the next would be far
# below the 50 digits), and does not try one below TINY_STEP.
CONVERGED_STEP = mpf(10) ** -25
TINY_STEP = mpf(10) ** -45
# The step of the central difference of a foot normal (curvature_across).
CURVATURE_STEP = mpf(10) ** -10
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
        self.patches = {}  # B-spline surfaces by instance id

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
        if "B_SPLINE_SURFACE_WITH_KNOTS" in parts:
            if ref.id not in self.patches:  # parsed once, its grid made once
                self.patches[ref.id] = self.bspline_surface(parts)
            return self.patches[ref.id]
        if name == "SURFACE_OF_REVOLUTION":
            p = parts[name]
            axis = self.params(p[2], "AXIS1_PLACEMENT")
            direction = self.direction(axis[2]) if axis[2] is not None else [mpf(0), mpf(0), mpf(1)]
            profile = self.curve(p[1])
            if profile.lo is None:
                raise Skip("surface of revolution of a line")
            return Revolution(profile, self.point(axis[1]), direction)
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

    def bspline_surface(self, parts):
        """A B_SPLINE_SURFACE_WITH_KNOTS, simple or the complex entity with
        RATIONAL_B_SPLINE_SURFACE (ISO 10303-42: control_points_list[i][j],
        i along u; knots repeated by their multiplicities)."""
        wk = parts["B_SPLINE_SURFACE_WITH_KNOTS"]
        base = parts.get("B_SPLINE_SURFACE")
        if base is None:  # simple instance: name, B_SPLINE_SURFACE's seven, then its own
            base, wk = wk[1:8], wk[8:]
        degrees = int(base[0]), int(base[1])
        points = [[self.point(r) for r in row] for row in base[2]]
        weights = None
        if "RATIONAL_B_SPLINE_SURFACE" in parts:
            weights = [[num(w) for w in row] for row in parts["RATIONAL_B_SPLINE_SURFACE"][0]]
            if [len(r) for r in weights] != [len(r) for r in points]:
                raise Skip("B-spline surface weight count")
            if any(w <= 0 for row in weights for w in row):
                raise Skip("B-spline surface weight not positive")
        knots = [[num(k) for k, m in zip(wk[2 + d], wk[d]) for _ in range(int(m))] for d in (0, 1)]
        if len(set(len(r) for r in points)) != 1:
            raise Skip("B-spline surface ragged control points")
        counts = len(points), len(points[0])
        if any(len(knots[d]) != counts[d] + degrees[d] + 1 for d in (0, 1)):
            raise Skip("B-spline surface knot count")
        return BSplineSurface(degrees, points, weights, knots)


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


class Revolution:
    """sigma(u, v) = A + ((C(v) - A).a) a + cos u rho + sin u (a x rho),
    rho = (C(v) - A) - ((C(v) - A).a) a (ISO 10303-42 surface_of_revolution:
    u the angle, v the swept curve's parameter).  The circle through C(v)
    is nearest to p in p's half-plane about the axis, so
    |p - surface|^2 = min over v of (rho_p - r(v))^2 + (h_p - z(v))^2 with
    z(v) = (C(v) - A).a and r(v) = |C(v) - A - z(v) a|: a 1-D search over the
    curve's domain (129 grid points and the previous foot, then Newton with
    central differences at 50 digits; golden section within two grid steps
    of the curve's ends, where C is clamped).  With e the radial unit vector of p,
    sigma_u x sigma_v = r (a x e) x (z' a + r' e + ...) = r (z' e - r' a)."""

    def __init__(self, curve, origin, axis):
        self.curve, self.a, self.o = curve, axis, origin
        self.last = None

    def meridian(self, v):
        q = sub(self.curve.at(v), self.o)
        z = dot(q, self.a)
        return norm(sub(q, scale(self.a, z))), z

    def foot(self, p):
        d = sub(p, self.o)
        h = dot(d, self.a)
        radial = sub(d, scale(self.a, h))
        rho = norm(radial)
        if rho == 0:
            raise Skip("point on a revolution's axis")
        e = scale(radial, 1 / rho)
        lo, hi = self.curve.lo, self.curve.hi

        def f(v):
            r, z = self.meridian(min(max(v, lo), hi))
            return (rho - r) ** 2 + (h - z) ** 2

        starts = [lo + (hi - lo) * i / 128 for i in range(129)]
        if self.last is not None:
            starts.append(self.last)
        v = min(starts, key=f)
        step = mpf(10) ** -18
        grid = (hi - lo) / 128
        if v - lo < 2 * grid or hi - v < 2 * grid:
            # Near the curve's ends, where the curve is clamped and the
            # differences below are one-sided: golden section instead.
            v = golden(f, max(lo, v - grid), min(hi, v + grid))
        for _ in range(60):
            f0, fp, fm = f(v), f(v + step), f(v - step)
            d1, d2 = (fp - fm) / (2 * step), (fp - 2 * f0 + fm) / (step * step)
            if d2 <= 0:
                break
            nv = min(max(v - d1 / d2, lo), hi)
            if f(nv) > f0:
                break
            done = abs(nv - v) < mpf(10) ** -40
            v = nv
            if done:
                break
        self.last = v
        r, z = self.meridian(v)
        if r == 0:
            raise Skip("foot on a revolution's axis")
        (r1, z1), (r0, z0) = self.meridian(min(v + step, hi)), self.meridian(max(v - step, lo))
        width = min(v + step, hi) - max(v - step, lo)
        n = sub(scale(e, (z1 - z0) / width), scale(self.a, (r1 - r0) / width))
        foot = add(self.o, add(scale(self.a, z), scale(e, r)))
        return sqrt(f(v)), foot, scale(n, 1 / norm(n))


def golden(f, a, b, steps=170):
    """The minimum of a unimodal f on [a, b] by golden-section search
    (0.618^170: about 1e-35 of the interval)."""
    k = (sqrt(mpf(5)) - 1) / 2
    c, d = b - k * (b - a), a + k * (b - a)
    fc, fd = f(c), f(d)
    for _ in range(steps):
        if fc <= fd:
            b, d, fd = d, c, fc
            c = b - k * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + k * (b - a)
            fd = f(d)
    return min((a, b, c, d), key=f)


def knot_span(knots, degree, count, t):
    """The index k of the knot span [U[k], U[k+1]) holding t, for t in the
    domain [U[degree], U[count]]; the last non-empty span at its top end."""
    k = bisect.bisect_right(knots, t) - 1
    k = min(max(k, degree), count - 1)
    while k > degree and knots[k] == knots[k + 1]:
        k -= 1
    return k


def basis_derivatives(knots, degree, k, t, n):
    """The non-zero B-spline basis functions N_{k-p..k, p}(t) and their
    derivatives up to order n: ``out[d][r]`` is the d-th derivative of
    N_{k-p+r}.  Cox-de Boor's recurrence on the knot differences, with the
    derivatives from the same triangle (Piegl & Tiller, The NURBS Book,
    A2.3); derivatives past the degree are zero."""
    p = degree
    zero = mpf(0)
    ndu = [[zero] * (p + 1) for _ in range(p + 1)]
    ndu[0][0] = mpf(1)
    left, right = [zero] * (p + 1), [zero] * (p + 1)
    for j in range(1, p + 1):
        left[j] = t - knots[k + 1 - j]
        right[j] = knots[k + j] - t
        saved = zero
        for r in range(j):
            ndu[j][r] = right[r + 1] + left[j - r]  # knot differences, lower triangle
            temp = ndu[r][j - 1] / ndu[j][r]
            ndu[r][j] = saved + right[r + 1] * temp  # basis functions, upper triangle
            saved = left[j - r] * temp
        ndu[j][j] = saved
    out = [[ndu[j][p] for j in range(p + 1)]] + [[zero] * (p + 1) for _ in range(n)]
    for r in range(p + 1):
        a = [[zero] * (p + 1), [zero] * (p + 1)]
        s1, s2 = 0, 1
        a[0][0] = mpf(1)
        for d in range(1, min(n, p) + 1):
            acc = zero
            rk, pk = r - d, p - d
            if r >= d:
                a[s2][0] = a[s1][0] / ndu[pk + 1][rk]
                acc = a[s2][0] * ndu[rk][pk]
            j1 = 1 if rk >= -1 else -rk
            j2 = d - 1 if r - 1 <= pk else p - r
            for j in range(j1, j2 + 1):
                a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j]
                acc += a[s2][j] * ndu[rk + j][pk]
            if r <= pk:
                a[s2][d] = -a[s1][d - 1] / ndu[pk + 1][r]
                acc += a[s2][d] * ndu[r][pk]
            out[d][r] = acc
            s1, s2 = s2, s1
    factor = p
    for d in range(1, min(n, p) + 1):
        out[d] = [x * factor for x in out[d]]
        factor *= p - d
    return out


class BSplineSurface(Surface):
    """A B-spline surface S(u, v) = sum N_i(u) N_j(v) w_ij P_ij / sum N_i(u)
    N_j(v) w_ij over its domain [U[p], U[n_u]] x [V[q], V[n_v]], normal
    S_u x S_v (ISO 10303-42).  ``foot`` finds the nearest point of q on the
    surface restricted to that domain: Newton on (S - q).S_u = 0,
    (S - q).S_v = 0 from the previous foot of the same edge and from the
    best point of a coarse grid, a parameter that reaches the domain's
    border held there while the gradient pushes outward (a 1-D Newton along
    the border curve, or a corner); then across a closed surface's seam and
    away from degenerate points (the module's docstring)."""

    def __init__(self, degrees, points, weights, knots):
        self.degrees, self.knots = degrees, knots
        self.counts = len(points), len(points[0])
        self.rational = weights is not None
        if self.rational:  # homogeneous control points (w P, w)
            self.hom = [[scale(pt, w) + [w] for pt, w in zip(row, wrow)] for row, wrow in zip(points, weights)]
        else:
            self.hom = [[list(pt) for pt in row] for row in points]
        # cols[i][c]: coordinate c of the homogeneous control points of row i
        self.cols = [[[pt[c] for pt in row] for c in range(len(row[0]))] for row in self.hom]
        self.lo = [knots[d][degrees[d]] for d in (0, 1)]
        self.hi = [knots[d][self.counts[d]] for d in (0, 1)]
        if not all(self.lo[d] < self.hi[d] for d in (0, 1)):
            raise Skip("B-spline surface empty domain")
        self.make_grid()
        self.reset()

    def reset(self):
        """Forget the feet of the previous edge."""
        self.memo, self.jets, self.last = {}, {}, None

    def derivatives(self, u, v, n=2):
        """[S, S_u, S_v, S_uu, S_uv, S_vv] at (u, v) in the domain, up to
        order n ([S] when n = 0, [S, S_u, S_v] when n = 1): the homogeneous
        partial derivatives A^(k,l) summed over the (p+1)(q+1) control
        points of the span, then the quotient rule for S = A / w (Piegl &
        Tiller, eq. 4.20)."""
        (p, q), (U, V) = self.degrees, self.knots
        ku = knot_span(U, p, self.counts[0], u)
        kv = knot_span(V, q, self.counts[1], v)
        Nu = basis_derivatives(U, p, ku, u, n)
        Nv = basis_derivatives(V, q, kv, v, n)
        dim = len(self.cols[0])
        js = slice(kv - q, kv + 1)
        # T[l][c][r] = sum_s N_{kv-q+s}^(l)(v) Pw_{ku-p+r, kv-q+s}[c], then
        # A^(k,l)[c] = sum_r N_{ku-p+r}^(k)(u) T[l][c][r]
        T = [
            [[sum(map(mul, Nv[l], self.cols[ku - p + r][c][js])) for r in range(p + 1)] for c in range(dim)]
            for l in range(n + 1)
        ]
        orders = [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)][: (1, 3, 6)[n]]
        A = [[sum(map(mul, Nu[k], T[l][c])) for c in range(dim)] for k, l in orders]
        if not self.rational:
            return A
        w = [a[3] for a in A]
        if w[0] <= 0:
            raise Skip("B-spline surface weight sum not positive")
        inv = 1 / w[0]
        S = scale(A[0][:3], inv)
        if n == 0:
            return [S]
        Su = scale(sub(A[1][:3], scale(S, w[1])), inv)
        Sv = scale(sub(A[2][:3], scale(S, w[2])), inv)
        if n == 1:
            return [S, Su, Sv]
        Suu = scale(sub(A[3][:3], add(scale(Su, 2 * w[1]), scale(S, w[3]))), inv)
        Suv = scale(sub(A[4][:3], add(add(scale(Su, w[2]), scale(Sv, w[1])), scale(S, w[4]))), inv)
        Svv = scale(sub(A[5][:3], add(scale(Sv, 2 * w[2]), scale(S, w[5]))), inv)
        return [S, Su, Sv, Suu, Suv, Svv]

    def at(self, u, v):
        return self.derivatives(u, v, 0)[0]

    def make_grid(self):
        """Float points of the surface at a grid of parameters: the distinct
        knots of the domain and evenly spaced parameters inside each knot
        span (at least 16 intervals per direction, 4 per span when there
        are 32 spans or fewer, else at least 1).  Also the surface's size
        (the diagonal of the grid's box), the directions in which it is
        closed (its two borders within 1e-7 of its size at every grid
        parameter) and the grid points where it is degenerate."""
        params = []
        for d in (0, 1):
            U = self.knots[d]
            ends = sorted(set(x for x in U if self.lo[d] <= x <= self.hi[d]))
            spans = len(ends) - 1
            per = max(4 if spans <= 32 else 1, -(-16 // spans))
            ts = [a + (b - a) * i / per for a, b in zip(ends, ends[1:]) for i in range(per)] + [ends[-1]]
            params.append(ts)
        rows = [[self.derivatives(u, v, 1) for v in params[1]] for u in params[0]]
        points = [[tuple(float(c) for c in D[0]) for D in row] for row in rows]
        flat = [p for row in points for p in row]
        self.size = math.dist([min(c) for c in zip(*flat)], [max(c) for c in zip(*flat)])
        self.closed = (
            max(math.dist(a, b) for a, b in zip(points[0], points[-1])) <= 1e-7 * self.size,
            max(math.dist(row[0], row[-1]) for row in points) <= 1e-7 * self.size,
        )
        grid = sorted(
            (points[i][j], (u, v), self.degenerate(rows[i][j]))
            for i, u in enumerate(params[0])
            for j, v in enumerate(params[1])
        )
        self.grid_points = [g[0] for g in grid]  # sorted by x
        self.grid_x = [g[0][0] for g in grid]
        self.grid_params = [g[1] for g in grid]
        self.grid_regular = [i for i, g in enumerate(grid) if not g[2]]

    def degenerate(self, D):
        """Whether S_u x S_v at derivatives D is below 1e-12 of its scale
        (size / width)^2: a pole, an apex or a collapsed border."""
        scale_u = self.size / float(self.hi[0] - self.lo[0])
        scale_v = self.size / float(self.hi[1] - self.lo[1])
        return float(norm(cross(D[1], D[2]))) <= 1e-12 * scale_u * scale_v

    def newton(self, q, u, v, D=None):
        """A local minimum of |S(u, v) - q| over the domain from (u, v)
        (whose ``derivatives`` D may be given): projected Newton, each step
        damped until the distance does not grow.  Returns (squared distance,
        u, v, derivatives there)."""
        lo, hi = self.lo, self.hi
        width = [hi[0] - lo[0], hi[1] - lo[1]]
        if D is None:
            D = self.derivatives(u, v)
        r = sub(D[0], q)
        f = dot(r, r)
        for _ in range(100):
            S, Su, Sv, Suu, Suv, Svv = D
            gu, gv = dot(r, Su), dot(r, Sv)
            huu = dot(Su, Su) + dot(r, Suu)
            huv = dot(Su, Sv) + dot(r, Suv)
            hvv = dot(Sv, Sv) + dot(r, Svv)
            # a parameter on the border whose descent direction leaves the domain is held
            free_u = not ((u <= lo[0] and gu > 0) or (u >= hi[0] and gu < 0))
            free_v = not ((v <= lo[1] and gv > 0) or (v >= hi[1] and gv < 0))
            du = dv = mpf(0)
            if free_u and free_v:
                det = huu * hvv - huv * huv
                if not (huu > 0 and det > 0):  # not convex here: Gauss-Newton
                    huu, huv, hvv = dot(Su, Su), dot(Su, Sv), dot(Sv, Sv)
                    det = huu * hvv - huv * huv
                if det > 0:
                    du = -(hvv * gu - huv * gv) / det
                    dv = -(huu * gv - huv * gu) / det
            elif free_u:
                h = huu if huu > 0 else dot(Su, Su)
                if h > 0:
                    du = -gu / h
            elif free_v:
                h = hvv if hvv > 0 else dot(Sv, Sv)
                if h > 0:
                    dv = -gv / h
            if du == 0 and dv == 0:
                break
            while True:  # damping
                nu = min(max(u + du, lo[0]), hi[0])
                nv = min(max(v + dv, lo[1]), hi[1])
                moved = max(abs(nu - u) / width[0], abs(nv - v) / width[1])
                if moved < TINY_STEP:
                    break
                ND = self.derivatives(nu, nv)
                nr = sub(ND[0], q)
                nf = dot(nr, nr)
                if nf <= f or moved < CONVERGED_STEP:  # (a last step: rounding may hide its gain)
                    break
                du, dv = du / 2, dv / 2
            if moved < TINY_STEP:  # converged (or stuck at rounding level)
                break
            u, v, D, r, f = nu, nv, ND, nr, nf
            if moved < CONVERGED_STEP:
                break
        return f, u, v, D

    def foot(self, p):
        key = tuple(p)
        if key in self.memo:
            return self.memo[key]
        a, b, c = [float(x) for x in p]
        best, lo, hi = None, 0, len(self.grid_x)
        if self.last is not None:
            best = self.newton(p, *self.last)
            reach = math.sqrt(float(best[0]))  # only grid points nearer than its foot matter
            lo = bisect.bisect_left(self.grid_x, a - reach)
            hi = bisect.bisect_right(self.grid_x, a + reach)
        if lo < hi:
            d2 = [(x - a) ** 2 + (y - b) ** 2 + (z - c) ** 2 for x, y, z in self.grid_points[lo:hi]]
            dg = min(d2)
            if best is None or dg < float(best[0]):  # another basin, nearer
                best = self.better(best, self.newton(p, *self.grid_params[lo + d2.index(dg)]))
        # a foot on a border: the opposite border at the same other parameter,
        # in a closed direction (the other side of the seam) or when nearer
        f, u, v = best[:3]

        def across(x, d):
            return [self.hi[d]] if x == self.lo[d] else [self.lo[d]] if x == self.hi[d] else []

        for su, sv in [(x, y) for x in [u] + across(u, 0) for y in [v] + across(v, 1)][1:]:
            r = sub(self.at(su, sv), p)
            if (self.closed[0] and su != u) or (self.closed[1] and sv != v) or dot(r, r) < f:
                best = self.better(best, self.newton(p, su, sv))
        if self.degenerate(best[3]):
            # Newton cannot turn at a pole or apex: from the nearest regular grid points
            near = sorted(self.grid_regular, key=lambda i: math.dist(self.grid_points[i], (a, b, c)))
            for i in near[:8]:
                best = self.better(best, self.newton(p, *self.grid_params[i]))
            if self.degenerate(best[3]):
                raise Skip("B-spline foot at a degenerate point (normal vanishes)")
        f, u, v, D = best
        self.last = (u, v, D)
        result = (sqrt(f), D[0], unit(cross(D[1], D[2])))
        self.memo[key], self.jets[key] = result, D
        return result

    @staticmethod
    def better(a, b):
        return b if a is None or b[0] < a[0] else a


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


def curvature_across(surf, p, tangent):
    """The normal curvature II(w, w) / I(w, w) of the surface at the foot of
    p, relative to its normal n there, in the direction w = n x tangent
    (across the edge).  A B-spline surface's from its derivatives at the
    foot, w = a S_u + b S_v with (a, b) = (G S_u.w - F S_v.w, E S_v.w - F S_u.w)
    (do Carmo, section 3-2; at a foot held on the border too); every other
    surface's from the turn of its foot normal, -w.(n(F + h w) - n(F - h w))
    / (2 h |w|^2) for the unit w (a central difference, h = 1e-10 in length
    units: its error is about h^2 times the third derivative, far below
    what is compared)."""
    _, foot, n = surf.foot(p)
    w = cross(n, tangent)
    if isinstance(surf, BSplineSurface):
        _, Su, Sv, Suu, Suv, Svv = surf.jets[tuple(p)]
        E, F, G = dot(Su, Su), dot(Su, Sv), dot(Sv, Sv)
        uw, vw = dot(Su, w), dot(Sv, w)
        a, b = G * uw - F * vw, E * vw - F * uw
        second = dot(Suu, n) * a * a + 2 * dot(Suv, n) * a * b + dot(Svv, n) * b * b
        return second / (E * a * a + 2 * F * a * b + G * b * b)
    w = scale(w, CURVATURE_STEP / norm(w))
    turn = sub(surf.foot(add(foot, w))[2], surf.foot(sub(foot, w))[2])
    return -dot(turn, w) / (2 * CURVATURE_STEP**2)


def tangent(curve, t):
    """A multiple of C'(t): a central difference of step 1e-20 (one-sided
    at a clamped end)."""
    h = mpf(10) ** -20
    return sub(curve.at(t + h), curve.at(t - h))


def measure(curve, faces, t):
    """(gaps by face, face gap, angle, curvature difference, |point|) at the
    parameter t."""
    p = curve.at(t)
    feet = [surf.foot(p) for surf, _ in faces]
    signs = [1 if sense else -1 for _, sense in faces]
    normals = [scale(n, s) for (_, _, n), s in zip(feet, signs)]
    angle = atan2(norm(cross(normals[0], normals[1])), dot(normals[0], normals[1]))
    d = tangent(curve, t)
    kappa = [s * curvature_across(surf, p, d) for (surf, _), s in zip(faces, signs)]
    values = [f[0] for f in feet] + [norm(sub(feet[0][1], feet[1][1])), angle, abs(kappa[0] - kappa[1])]
    return values, max(abs(c) for c in p)


def sample_edge(curve, faces, ranges):
    fractions = [mpf(i) / (N - 1) for i in range(N)]
    values = [measure(curve, faces, t)[0] for t in parameters(ranges, fractions)]
    size = max(measure(curve, faces, t)[1] for t in parameters(ranges, fractions[:: (N - 1) // 16]))
    results = []
    for m in range(5):
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
            for surf, _ in faces:
                if isinstance(surf, BSplineSurface):
                    surf.reset()  # each edge's feet from its own samples
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
            "curvature": results[4],
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


def bspline_self_test_file():
    """Part 21 text for the B-spline self-test (see ``self_test``)."""
    lines = []
    put = lines.append
    put("#2=DIRECTION('',(0.,0.,1.));")
    put("#3=DIRECTION('',(1.,0.,0.));")
    put("#4=DIRECTION('',(0.,1.,0.));")
    # P1 (#140): the plane z = 0 as a rational bicubic, interior knots in both
    # directions, weights 1, 1.5, 2 mixed; control points on an uneven grid.
    xs, ys = ["0.", "0.1", "0.35", "0.6", "0.85", "1."], ["0.", "0.2", "0.5", "0.8", "1."]
    for i, x in enumerate(xs):
        for j, y in enumerate(ys):
            put("#%d=CARTESIAN_POINT('',(%s,%s,0.));" % (101 + 5 * i + j, x, y))
    net = ",".join("(" + ",".join("#%d" % (101 + 5 * i + j) for j in range(5)) + ")" for i in range(6))
    weights = ",".join("(" + ",".join(("1.", "1.5", "2.")[(i + 2 * j) % 3] for j in range(5)) + ")" for i in range(6))
    put(
        "#140=(BOUNDED_SURFACE() B_SPLINE_SURFACE(3,3,(%s),.UNSPECIFIED.,.F.,.F.,.F.) "
        "B_SPLINE_SURFACE_WITH_KNOTS((4,1,1,4),(4,1,4),(0.,0.3,0.7,1.),(0.,0.5,1.),.UNSPECIFIED.) "
        "GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_SURFACE((%s)) REPRESENTATION_ITEM('') SURFACE());"
        % (net, weights)
    )
    # P2 (#230): a polynomial bicubic x quadratic on the plane through the line
    # y = 0.5, z = 1e-7 spanned by (1, 0, 0) and (0, 0.6, 0.8), s in [-1, 1].
    xs2, ss = ["0.", "0.2", "0.5", "0.8", "1."], ["-1", "-0.4", "0.4", "1"]
    for i, x in enumerate(xs2):
        for j, s in enumerate(ss):
            y = Decimal("0.5") + Decimal("0.6") * Decimal(s)
            z = Decimal("1E-7") + Decimal("0.8") * Decimal(s)
            put("#%d=CARTESIAN_POINT('',(%s,%s,%s));" % (201 + 4 * i + j, x, y, z))
    net = ",".join("(" + ",".join("#%d" % (201 + 4 * i + j) for j in range(4)) + ")" for i in range(5))
    put(
        "#230=B_SPLINE_SURFACE_WITH_KNOTS('',3,2,(%s),.PLANE_SURF.,.F.,.F.,.F.,(4,1,4),(3,1,3),"
        "(0.,0.5,1.),(-1.,0.,1.),.UNSPECIFIED.);" % net
    )
    # P3 (#303): the PLANE x = -3e-7, normal (1, 0, 0).
    put("#301=CARTESIAN_POINT('',(-3.E-7,0.,0.));")
    put("#302=AXIS2_PLACEMENT_3D('',#301,#3,#2);")
    put("#303=PLANE('',#302);")
    # Q (#410): a quarter of the cylinder x^2 + y^2 = 4, 0 <= z <= 1, as a
    # rational quadratic x linear (middle weights sqrt(2)/2 to 40 digits);
    # T (#413): the PLANE z = 1.
    corners = [("2.", "0."), ("2.", "2."), ("0.", "2.")]
    for i, (x, y) in enumerate(corners):
        for j, z in enumerate(("0.", "1.")):
            put("#%d=CARTESIAN_POINT('',(%s,%s,%s));" % (401 + 2 * i + j, x, y, z))
    w = "0.7071067811865475244008443621048490392848"
    put(
        "#410=(BOUNDED_SURFACE() B_SPLINE_SURFACE(2,1,((#401,#402),(#403,#404),(#405,#406)),"
        ".UNSPECIFIED.,.F.,.F.,.F.) B_SPLINE_SURFACE_WITH_KNOTS((3,3),(2,2),(0.,1.),(0.,1.),.UNSPECIFIED.) "
        "GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_SURFACE(((1.,1.),(%s,%s),(1.,1.))) "
        "REPRESENTATION_ITEM('') SURFACE());" % (w, w)
    )
    put("#411=CARTESIAN_POINT('',(0.,0.,1.));")
    put("#412=AXIS2_PLACEMENT_3D('',#411,#2,#3);")
    put("#413=PLANE('',#412);")
    # Edge A (#507): y = 0.5, z = 1e-7, x from 0.2 to 0.8, between P1 and P2.
    # Edge B (#517): x = -3e-7, z = 4e-7, y from 0.2 to 0.8, between P1 and P3:
    # outside P1's domain (beyond its u = u_min border x = 0).
    # Edge C (#527): the arc of radius 2 + 1e-7 at z = 1 from (r, 0) to (0, r),
    # between Q (along its v = v_max border) and T.
    put("#501=CARTESIAN_POINT('',(0.2,0.5,1.E-7));")
    put("#502=VECTOR('',#3,1.);")
    put("#503=LINE('',#501,#502);")
    put("#504=CARTESIAN_POINT('',(0.8,0.5,1.E-7));")
    put("#511=CARTESIAN_POINT('',(-3.E-7,0.2,4.E-7));")
    put("#512=VECTOR('',#4,1.);")
    put("#513=LINE('',#511,#512);")
    put("#514=CARTESIAN_POINT('',(-3.E-7,0.8,4.E-7));")
    put("#521=CARTESIAN_POINT('',(2.0000001,0.,1.));")
    put("#522=CARTESIAN_POINT('',(0.,2.0000001,1.));")
    put("#523=CIRCLE('',#412,2.0000001);")
    for base, (a, b, curve) in zip((505, 515, 525), ((501, 504, 503), (511, 514, 513), (521, 522, 523))):
        put("#%d=VERTEX_POINT('',#%d);" % (base, a))
        put("#%d=VERTEX_POINT('',#%d);" % (base + 1, b))
        put("#%d=EDGE_CURVE('',#%d,#%d,#%d,.T.);" % (base + 2, base, base + 1, curve))
    for k, (edge, sense) in enumerate(((507, "T"), (507, "F"), (517, "T"), (517, "F"), (527, "T"), (527, "F"))):
        put("#%d=ORIENTED_EDGE('',*,*,#%d,.%s.);" % (601 + k, edge, sense))
    loops = [(631, "#601,#603", 140), (632, "#602", 230), (633, "#604", 303), (634, "#605", 410), (635, "#606", 413)]
    for k, (face, edges, surface) in enumerate(loops):
        put("#%d=EDGE_LOOP('',(%s));" % (611 + k, edges))
        put("#%d=FACE_BOUND('',#%d,.T.);" % (621 + k, 611 + k))
        put("#%d=ADVANCED_FACE('',(#%d),#%d,.T.);" % (face, 621 + k, surface))
    head = SELF_TEST.split("DATA;")[0]
    return head + "DATA;\n" + "\n".join(lines) + "\nENDSEC;\nEND-ISO-10303-21;\n"


def sample_text(text):
    """``sample_file`` on Part 21 text."""
    import tempfile

    with tempfile.NamedTemporaryFile("w", suffix=".stp", delete=False) as f:
        f.write(text)
    try:
        return sample_file(f.name)
    finally:
        os.unlink(f.name)


def self_test():
    """(1) A circle of radius 2 + 1e-7 on the top plane of a cylinder of
    radius 2: gaps 1e-7 (cylinder) and 0 (plane), face gap 1e-7, angle pi/2.

    (2) B-spline faces (``bspline_self_test_file``), answers known without
    them: P1, the plane z = 0 as a rational bicubic; its first and second
    partial derivatives against central differences; edge A at height 1e-7
    above it on the polynomial P2, a plane through A tilted by acos(0.6)
    (normals (0, 0, 1) and (0, -0.8, 0.6)): gaps 1e-7 and 0, face gap 1e-7,
    angle acos(0.6); edge B 3e-7 beyond P1's u = u_min border (x = 0) and
    4e-7 above it, on the PLANE x = -3e-7: the foot restricted to P1's
    domain is on that border, gap 5e-7 (the unrestricted plane's would be
    4e-7), face gap 5e-7, angle pi/2; edge C, an arc of radius 2 + 1e-7
    along the top border of a rational quarter cylinder of radius 2 and on
    the plane z = 1: gaps 1e-7 and 0, face gap 1e-7, angle pi/2.

    (3) Curvature: every edge above has two faces flat across it
    (difference 0); across the axis of the cylinder and of the rational
    quarter cylinder, both of radius 2, the normal curvature is 1/2 towards
    the axis (-1/2 relative to an outward normal)."""
    e = sample_text(SELF_TEST)["edges"]["#12"]
    assert abs(e["gap"]["#19"]["max"] - 1e-7) < 1e-20, e
    assert e["gap"]["#20"]["max"] < 1e-40, e
    assert abs(e["face_gap"]["max"] - 1e-7) < 1e-20, e
    assert abs(e["angle"]["max"] - float(PI / 2)) < 1e-15, e
    print("self-test 1 passed (circle 1e-7 off a cylinder)")

    import tempfile

    text = bspline_self_test_file()
    with tempfile.NamedTemporaryFile("w", suffix=".stp", delete=False) as f:
        f.write(text)
    try:
        model = Model(f.name)
    finally:
        os.unlink(f.name)
    p1 = model.surface(sc.Ref(140))
    assert p1.rational and p1.degrees == (3, 3), p1.degrees
    u, v, h = mpf("0.4321"), mpf("0.6173"), mpf(10) ** -20
    D = p1.derivatives(u, v)
    Dp, Dm = p1.derivatives(u + h, v), p1.derivatives(u - h, v)
    Ep, Em = p1.derivatives(u, v + h), p1.derivatives(u, v - h)
    fd = [
        scale(sub(Dp[0], Dm[0]), 1 / (2 * h)),  # S_u
        scale(sub(Ep[0], Em[0]), 1 / (2 * h)),  # S_v
        scale(sub(Dp[1], Dm[1]), 1 / (2 * h)),  # S_uu
        scale(sub(Ep[1], Em[1]), 1 / (2 * h)),  # S_uv
        scale(sub(Ep[2], Em[2]), 1 / (2 * h)),  # S_vv
    ]
    for k, (exact, approx) in enumerate(zip(D[1:], fd)):
        assert norm(sub(exact, approx)) < mpf(10) ** -25 * (1 + norm(exact)), (k, exact, approx)
    assert D[0][2] == 0 and min(abs(c) for c in D[3][:2]) > mpf("1e-3"), D  # a plane, not linearly parameterized
    print("self-test 2 passed (rational B-spline derivatives against central differences)")

    edges = sample_text(text)["edges"]
    a, b, c = edges["#507"], edges["#517"], edges["#527"]
    assert abs(a["gap"]["#631"]["max"] - 1e-7) < 1e-20, a
    assert a["gap"]["#632"]["max"] < 1e-40, a
    assert abs(a["face_gap"]["max"] - 1e-7) < 1e-20, a
    assert abs(a["angle"]["max"] - float(atan2(mpf("0.8"), mpf("0.6")))) < 1e-15, a
    print("self-test 3 passed (edge A: 1e-7 above a rational B-spline plane, acos(0.6) to a tilted one)")
    assert abs(b["gap"]["#631"]["max"] - 5e-7) < 1e-20, b
    assert b["gap"]["#633"]["max"] < 1e-40, b
    assert abs(b["face_gap"]["max"] - 5e-7) < 1e-20, b
    assert abs(b["angle"]["max"] - float(PI / 2)) < 1e-15, b
    print("self-test 4 passed (edge B: foot held on the u = u_min border, gap 5e-7)")
    assert abs(c["gap"]["#634"]["max"] - 1e-7) < 1e-20, c
    assert c["gap"]["#635"]["max"] < 1e-40, c
    assert abs(c["face_gap"]["max"] - 1e-7) < 1e-20, c
    assert abs(c["angle"]["max"] - float(PI / 2)) < 1e-15, c
    print("self-test 5 passed (edge C: arc 1e-7 off a rational quarter cylinder, along its border)")
    for edge in (e, a, b, c):  # across each edge, both faces are flat
        assert edge["curvature"]["max"] < 1e-15, edge
    z = [mpf(0), mpf(0), mpf(1)]
    cylinder = Cylinder(([mpf(0)] * 3, [mpf(1), mpf(0), mpf(0)], [mpf(0), mpf(1), mpf(0)], z), mpf(2))
    quarter = model.surface(sc.Ref(410))
    for x, y in ((1, 1), (-1, 1), (-1, -1), (1, -1)):
        p = [mpf("1.2") * x, mpf("1.6") * y, mpf("0.5")]
        for surf in (cylinder, quarter):
            gap, _, n = surf.foot(p)
            if gap < mpf(10) ** -30:  # on it: across the axis z, curvature 1/2 towards the axis
                k = curvature_across(surf, p, z)
                assert abs(k + dot(n, scale(p[:2] + [mpf(0)], 1 / mpf(2))) / 2) < mpf(10) ** -18, (surf, k)
    assert quarter.jets, "the quarter cylinder was not reached"
    print("self-test 6 passed (curvature across a cylinder's axis: 1/2, closed form and rational B-spline)")
    print("self-test passed")


def check_feet(path, every=8):
    """The B-spline feet of ``sample_edge``'s first pass against a brute
    force: Newton from the 6 nearest points of a dense 61 x 61 grid over
    the domain, at every ``every``-th sample.  Prints each sample where the
    brute force is nearer by more than 1e-12 (relative) and 1e-40, and a
    summary line; returns the number of such samples."""
    model = Model(path)
    dense, checked, worse, edges = {}, 0, 0, 0
    for edge, uses in sorted(edge_faces(model.inst).items()):
        if len(uses) != 2:
            continue
        p = model.inst[edge]["EDGE_CURVE"]
        try:
            faces = [model.surface(fp[2]) for _, fp in uses]
            if not any(isinstance(s, BSplineSurface) for s in faces):
                continue
            curve = model.curve(p[3])
            start = model.point(model.params(p[1], "VERTEX_POINT")[1])
            end = model.point(model.params(p[2], "VERTEX_POINT")[1])
            ranges = trimmed(curve, start, end, p[1].id == p[2].id, p[4].name == "T")
        except Skip:
            continue
        edges += 1
        for surf in faces:
            if not isinstance(surf, BSplineSurface):
                continue
            if id(surf) not in dense:
                w = [surf.hi[d] - surf.lo[d] for d in (0, 1)]
                uv = [(surf.lo[0] + w[0] * i / 60, surf.lo[1] + w[1] * j / 60) for i in range(61) for j in range(61)]
                dense[id(surf)] = [(tuple(float(c) for c in surf.at(u, v)), u, v) for u, v in uv]
            surf.reset()
            for i, t in enumerate(parameters(ranges, [mpf(k) / (N - 1) for k in range(N)])):
                q = curve.at(t)
                try:
                    d = surf.foot(q)[0]
                except Skip:
                    break
                if i % every:
                    continue
                qf = [float(c) for c in q]
                near = sorted(dense[id(surf)], key=lambda e: math.dist(e[0], qf))[:6]
                brute = sqrt(min(surf.newton(q, u, v)[0] for _, u, v in near))
                checked += 1
                if brute < d * (1 - mpf(10) ** -12) - mpf(10) ** -40:
                    worse += 1
                    print("  #%d sample %d: foot at %.6g, brute force %.6g" % (edge, i, d, brute))
    name = path.rsplit("/", 1)[-1]
    print("%s: %d B-spline edges, %d feet checked, %d nearer by brute force" % (name, edges, checked, worse))
    return worse


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
    elif sys.argv[1:2] == ["--check-feet"]:
        sys.exit(1 if sum(check_feet(path) for path in sys.argv[2:]) else 0)
    elif len(sys.argv) < 2:
        sys.exit("usage: step_sample.py FILE... | --self-test | --check-feet FILE...")
    else:
        main(sys.argv[1:])
