"""The error classes and their messages (those of the command line)."""

from fractions import Fraction

import pytest

import exact_bezier as eb


def test_the_hierarchy():
    assert issubclass(eb.ExactBezierError, ValueError)
    assert issubclass(eb.LimitError, eb.ExactBezierError)
    assert eb.ExactBezierError.__module__ == "exact_bezier"


def test_a_zero_weight():
    with pytest.raises(eb.ExactBezierError) as e:
        eb.Curve([[0, 0], [1, 1]], [1, 0])
    assert not isinstance(e.value, eb.LimitError)
    assert str(e.value) == (
        "weight w_1 is 0: weights must be positive (zero or negative weights are not allowed)"
    )


def test_shapes():
    with pytest.raises(eb.ExactBezierError, match="a degree 2 curve needs 3 weights, not 2"):
        eb.Curve([[0], [1], [2]], [1, 1])
    with pytest.raises(eb.ExactBezierError, match="row 1 of the control net should have 2 points, not 1"):
        eb.RectPatch([[[0], [1]], [[2]]])
    with pytest.raises(eb.ExactBezierError, match="needs at least one control point"):
        eb.Curve([])


def test_malformed_json():
    with pytest.raises(eb.ExactBezierError, match="^malformed input: "):
        eb.Curve.from_json("{")
    with pytest.raises(eb.ExactBezierError, match='unknown field "colour"'):
        eb.Curve.from_json('{"kind": "curve", "points": [[0]], "colour": 1}')


def test_limits_are_limit_errors():
    with pytest.raises(eb.LimitError, match="over the limit of 1000 digits"):
        eb.Curve([["1" * 1001]])
    with pytest.raises(eb.LimitError, match="^degree 65 is over the limit of 64$"):
        eb.Curve([[k] for k in range(66)])
    with pytest.raises(eb.LimitError, match="^over a limit: points of dimension 65 are over the limit of 64$"):
        eb.Curve([[0] * 65])


def test_work_over_the_budget_is_refused_before_it_starts():
    # A degree-64 curve against itself is charged about 2·10⁶ units a
    # patch: under the default budget (10¹⁰), over a budget of 5·10⁵.
    a = eb.Curve([[k] for k in range(65)])
    with eb.limits(max_work=500_000):
        with pytest.raises(eb.LimitError, match="coincide needs an estimated .* work units, over the budget"):
            eb.coincide(a, a)


def test_a_point_at_infinity():
    # Positive weights vanish nowhere in [0, 1]; outside it they may: the
    # weight (1 − t)·1 + t·(1/3) = 1 − 2t/3 is 0 at t = 3/2.
    c = eb.Curve([[0], [1]], [1, "1/3"])
    with pytest.raises(eb.ExactBezierError, match="point at infinity"):
        c.eval(Fraction(3, 2))
