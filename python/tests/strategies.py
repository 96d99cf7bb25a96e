"""Hypothesis strategies: random exact curves and patches."""

from fractions import Fraction

from hypothesis import strategies as st

coords = st.fractions(min_value=-10, max_value=10, max_denominator=40)
weights = st.fractions(min_value=Fraction(1, 8), max_value=8, max_denominator=16)
params = st.fractions(min_value=0, max_value=1, max_denominator=64)
dims = st.integers(min_value=1, max_value=3)


@st.composite
def curves(draw, max_degree=5, min_degree=0):
    """``(points, weights)`` of a curve."""
    n = draw(st.integers(min_value=min_degree, max_value=max_degree))
    d = draw(dims)
    pts = [[draw(coords) for _ in range(d)] for _ in range(n + 1)]
    ws = [draw(weights) for _ in range(n + 1)]
    return pts, ws


@st.composite
def rects(draw, max_degree=3, min_degree=0):
    """``(points, weights)`` of a rect patch, rows by the u index; with
    ``min_degree`` 1, not of degree (0, 0)."""
    m = draw(st.integers(min_value=0, max_value=max_degree))
    n = draw(st.integers(min_value=0 if m >= min_degree else min_degree, max_value=max_degree))
    d = draw(dims)
    pts = [[[draw(coords) for _ in range(d)] for _ in range(n + 1)] for _ in range(m + 1)]
    ws = [[draw(weights) for _ in range(n + 1)] for _ in range(m + 1)]
    return pts, ws


@st.composite
def tris(draw, max_degree=4, min_degree=0):
    """``(points, weights)`` of a tri patch, ``points[j][i] = P_{i,j,n−i−j}``."""
    n = draw(st.integers(min_value=min_degree, max_value=max_degree))
    d = draw(dims)
    pts = [[[draw(coords) for _ in range(d)] for _ in range(n - j + 1)] for j in range(n + 1)]
    ws = [[draw(weights) for _ in range(n - j + 1)] for j in range(n + 1)]
    return pts, ws


@st.composite
def tri_params(draw):
    """``(u, v)`` in the triangle ``u, v ≥ 0``, ``u + v ≤ 1``."""
    u = draw(params)
    v = draw(st.fractions(min_value=0, max_value=1 - u, max_denominator=64))
    return u, v
