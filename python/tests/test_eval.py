"""Exact and float evaluation against the pure-Python Fraction oracle."""

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import exact_bezier as eb
import oracle
from strategies import curves, params, rects, tri_params, tris


@given(curves(), params)
def test_curve_eval_is_exact(net, t):
    pts, ws = net
    c = eb.Curve(pts, ws)
    got = c.eval(t)
    assert all(isinstance(x, Fraction) for x in got)
    assert got == oracle.eval_curve(pts, ws, t)


@given(rects(), params, params)
def test_rect_eval_is_exact(net, u, v):
    pts, ws = net
    assert eb.RectPatch(pts, ws).eval(u, v) == oracle.eval_rect(pts, ws, u, v)


@given(tris(), tri_params())
def test_tri_eval_is_exact(net, uv):
    pts, ws = net
    assert eb.TriPatch(pts, ws).eval(*uv) == oracle.eval_tri(pts, ws, *uv)


def close(a, b, scale):
    return np.max(np.abs(np.asarray(a, dtype=float) - np.asarray(b, dtype=float))) <= 1e-12 * scale


@given(curves(), st.lists(st.floats(min_value=0, max_value=1), min_size=0, max_size=12))
def test_curve_eval_many_matches_exact(net, ts):
    pts, ws = net
    c = eb.Curve(pts, ws)
    out = c.eval_many(np.array(ts, dtype=float))
    assert out.shape == (len(ts), c.dim) and out.dtype == np.float64
    scale = max(1, max(abs(x) for p in pts for x in p))
    for t, row in zip(ts, out):
        assert close(row, c.eval(t, exact_from_float=True), scale)


@given(rects(), st.lists(st.tuples(st.floats(0, 1), st.floats(0, 1)), max_size=8))
def test_rect_eval_many_matches_exact(net, uvs):
    pts, ws = net
    r = eb.RectPatch(pts, ws)
    out = r.eval_many(np.array(uvs, dtype=float).reshape(-1, 2))
    assert out.shape == (len(uvs), r.dim)
    scale = max(1, max(abs(x) for row in pts for p in row for x in p))
    for (u, v), row in zip(uvs, out):
        assert close(row, r.eval(u, v, exact_from_float=True), scale)


@given(tris(), st.lists(tri_params(), max_size=8))
def test_tri_eval_many_matches_exact(net, uvs):
    pts, ws = net
    t = eb.TriPatch(pts, ws)
    floats = [(float(u), float(v)) for u, v in uvs]
    out = t.eval_many(floats if floats else np.zeros((0, 2)))
    assert out.shape == (len(uvs), t.dim)
    scale = max(1, max(abs(x) for row in pts for p in row for x in p))
    for (u, v), row in zip(floats, out):
        assert close(row, t.eval(u, v, exact_from_float=True), scale)


def test_eval_many_takes_lists_and_column_vectors():
    c = eb.Curve([[0, 0], [2, 4], [4, 0]])
    a = c.eval_many([0.0, 0.5, 1.0])
    b = c.eval_many(np.array([[0.0], [0.5], [1.0]]))
    assert np.array_equal(a, b)
    assert np.array_equal(a, [[0, 0], [2, 2], [4, 0]])
    assert a.flags.writeable


def test_eval_many_refuses_wrong_shapes():
    c = eb.Curve([[0, 0], [1, 1]])
    r = eb.RectPatch([[[0], [1]], [[2], [3]]])
    with pytest.raises(eb.ExactBezierError, match=r"shape \(N, 2\)"):
        r.eval_many([0.5, 0.5])
    with pytest.raises(eb.ExactBezierError, match="shape"):
        c.eval_many(np.zeros((3, 2)))


def test_eval_many_from_many_threads():
    # eval_many releases the GIL (py.detach); this checks the results, not the timing.
    from concurrent.futures import ThreadPoolExecutor

    r = eb.RectPatch([[[0, 0, 1], [1, 0, 0]], [[0, 1, 0], [1, 1, 1]]], [[1, 2], [3, 4]])
    uv = np.random.default_rng(1).random((20000, 2))
    want = r.eval_many(uv)
    with ThreadPoolExecutor(4) as pool:
        for got in pool.map(lambda _: r.eval_many(uv), range(8)):
            assert np.array_equal(got, want)


def test_exact_parameters_of_every_kind():
    c = eb.Curve([[0], [3]])
    assert c.eval(Fraction(1, 3)) == [1]
    assert c.eval("1/3") == [1]
    assert c.eval(0) == [0]
    from decimal import Decimal

    assert c.eval(Decimal("0.5")) == [Fraction(3, 2)]
    assert c.eval(0.5, exact_from_float=True) == [Fraction(3, 2)]
    with pytest.raises(TypeError, match="exact_from_float=True"):
        c.eval(0.5)


def test_huge_exact_numbers_round_trip():
    big = 10**300 + 7
    c = eb.Curve([[Fraction(big, 3)], [Fraction(-1, big)]])
    assert c.points == [[Fraction(big, 3)], [Fraction(-1, big)]]
    assert c.eval(0) == [Fraction(big, 3)]


@pytest.mark.parametrize(
    "patch, params",
    [
        (eb.Curve([[0]]), (Fraction(1, 2**140),)),
        (eb.RectPatch([[[0]]]), (Fraction(1, 2**200), Fraction(1, 2**200))),
        (eb.TriPatch([[[0]]]), (Fraction(1, 2**200), Fraction(1, 2**200))),
    ],
)
def test_degree_zero_at_a_long_parameter(patch, params):
    # Float parameters as exact rationals have denominators up to 2^1074;
    # a constant patch takes them (once a panic of the exact kernel).
    assert patch.eval(*params) == [0]


def test_panics_become_exact_bezier_errors():
    with pytest.raises(eb.ExactBezierError, match="internal error .*a test panic"):
        eb._native._panic_for_test()
