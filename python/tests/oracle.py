"""A pure-Python oracle: rational Bézier curves and patches in
``fractions.Fraction`` arithmetic, by de Casteljau in homogeneous
coordinates ``(w·P, w)``, independent of the Rust kernel."""

from __future__ import annotations

from fractions import Fraction
from typing import List, Sequence

Hom = List[Fraction]  # w·x_1, …, w·x_d, w


def hom(point: Sequence[Fraction], weight: Fraction) -> Hom:
    """The homogeneous point of ``point`` with ``weight``."""
    return [weight * x for x in point] + [weight]


def project(h: Hom) -> List[Fraction]:
    """The Cartesian point of a homogeneous one."""
    return [x / h[-1] for x in h[:-1]]


def lerp(a: Hom, b: Hom, t: Fraction) -> Hom:
    """``(1 − t)·a + t·b``."""
    return [(1 - t) * x + t * y for x, y in zip(a, b)]


def casteljau(net: Sequence[Hom], t: Fraction) -> Hom:
    """De Casteljau on a homogeneous control polygon."""
    level = list(net)
    while len(level) > 1:
        level = [lerp(a, b, t) for a, b in zip(level, level[1:])]
    return level[0]


def curve_hom(points, weights) -> List[Hom]:
    return [hom(p, w) for p, w in zip(points, weights)]


def eval_curve(points, weights, t) -> List[Fraction]:
    return project(casteljau(curve_hom(points, weights), Fraction(t)))


def eval_rect(points, weights, u, v) -> List[Fraction]:
    """Rows by the u index ``i``, each row ``j = 0 … n`` in v."""
    rows = [casteljau(curve_hom(p, w), Fraction(v)) for p, w in zip(points, weights)]
    return project(casteljau(rows, Fraction(u)))


def eval_tri(points, weights, u, v) -> List[Fraction]:
    """``points[j][i] = P_{i,j,n−i−j}`` at barycentric ``(u, v, 1 − u − v)``."""
    u, v = Fraction(u), Fraction(v)
    w = 1 - u - v
    rows = [curve_hom(p, ws) for p, ws in zip(points, weights)]
    while len(rows) > 1:
        r = len(rows) - 1
        rows = [
            [
                [u * a + v * b + w * c for a, b, c in zip(rows[j][i + 1], rows[j + 1][i], rows[j][i])]
                for i in range(r - j)
            ]
            for j in range(r)
        ]
    return project(rows[0][0])


def split(net: Sequence[Hom]):
    """Cartesian points and weights of a homogeneous net."""
    return [project(h) for h in net], [h[-1] for h in net]


def reverse(net: Sequence[Hom]) -> List[Hom]:
    return list(reversed(net))


def elevate(net: Sequence[Hom]) -> List[Hom]:
    """Degree elevation by one: ``Q_i = i/(n+1)·H_{i−1} + (1 − i/(n+1))·H_i``."""
    n = len(net) - 1
    out = [list(net[0])]
    for i in range(1, n + 1):
        a = Fraction(i, n + 1)
        out.append([a * x + (1 - a) * y for x, y in zip(net[i - 1], net[i])])
    out.append(list(net[n]))
    return out


def mobius_weights(weights: Sequence[Fraction], alpha: Fraction) -> List[Fraction]:
    """The weights of the linear Möbius reparameterization with ``alpha``:
    ``w_i (1 − α)^i α^{n−i}`` (the points stay)."""
    n = len(weights) - 1
    return [w * (1 - alpha) ** i * alpha ** (n - i) for i, w in enumerate(weights)]
