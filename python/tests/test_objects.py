"""Constructors, JSON, equality, hashing, pickling."""

import copy
import json
import pickle
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given

import exact_bezier as eb
from strategies import curves, rects, tris

KINDS = [(eb.Curve, curves()), (eb.RectPatch, rects()), (eb.TriPatch, tris())]


def test_every_exact_number_type_is_taken():
    c = eb.Curve([[1, Fraction(1, 3)], ["0.885", Decimal("2.5")], (np.int64(7), "-1/4")], weights=[1, "1/3", 2])
    assert c.points == [[1, Fraction(1, 3)], [Fraction(885, 1000), Fraction(5, 2)], [7, Fraction(-1, 4)]]
    assert c.weights == [1, Fraction(1, 3), 2]
    assert (c.kind, c.degree, c.dim) == ("curve", 2, 2)


def test_weights_default_to_one():
    r = eb.RectPatch([[[0, 0], [0, 1]], [[1, 0], [1, 1]]])
    assert r.weights == [[1, 1], [1, 1]] and r.degree == (1, 1)
    t = eb.TriPatch([[[0, 0], [1, 0]], [[0, 1]]])
    assert t.weights == [[1, 1], [1]] and t.degree == 1


def test_floats_need_exact_from_float():
    with pytest.raises(TypeError, match="exact_from_float=True"):
        eb.Curve([[0.1, 0]])
    c = eb.Curve([[0.1, 0]], exact_from_float=True)
    assert c.points[0][0] == Fraction(0.1) != Fraction(1, 10)
    with pytest.raises(eb.ExactBezierError, match="not a finite number"):
        eb.Curve([[float("nan")]], exact_from_float=True)


def test_non_numbers_are_type_errors():
    with pytest.raises(TypeError, match="bool"):
        eb.Curve([[True]])
    with pytest.raises(TypeError, match="expected a number"):
        eb.Curve([[None]])


def test_bad_text_is_an_exact_bezier_error():
    with pytest.raises(eb.ExactBezierError, match="not an exact number"):
        eb.Curve([["1/0"]])


def test_numpy_arrays_of_integers_are_taken():
    pts = np.array([[0, 0], [1, 2], [3, 0]])
    assert eb.Curve(pts) == eb.Curve(pts.tolist())


@pytest.mark.parametrize("cls, strategy", KINDS)
def test_json_pickle_and_repr_round_trip(cls, strategy):
    @given(strategy)
    def check(net):
        pts, ws = net
        p = cls(pts, ws)
        text = p.to_json()
        assert json.loads(text)["kind"] == p.kind
        q = cls.from_json(text)
        assert q == p and hash(q) == hash(p)
        assert pickle.loads(pickle.dumps(p)) == p
        assert copy.deepcopy(p) == p
        assert eval(repr(p), {type(p).__name__: type(p)}) == p
        assert eb.read_json(text) == [p]

    check()


@pytest.mark.parametrize("protocol", range(pickle.HIGHEST_PROTOCOL + 1))
def test_pickling_with_every_protocol(protocol):
    for p in [eb.Curve([[0], ["1/3"]]), eb.RectPatch([[[0]]], [["2/7"]]), eb.TriPatch([[[0, 1]]])]:
        q = pickle.loads(pickle.dumps(p, protocol=protocol))
        assert type(q) is type(p) and q == p
        assert copy.copy(p) == p


def test_equality_is_exact():
    a = eb.Curve([[0], [1]], ["1/3", 1])
    assert a == eb.Curve([[0], [1]], [Fraction(1, 3), 1])
    assert a != eb.Curve([[0], [1]], [Fraction(1, 3) + Fraction(1, 10**30), 1])
    # The same point set with scaled weights is another control net.
    assert a != eb.Curve([[0], [1]], [Fraction(2, 3), 2])
    assert a != "curve" and eb.RectPatch([[[0]]]) != eb.TriPatch([[[0]]])
    assert len({a, eb.Curve([[0], [1]], ["1/3", 1])}) == 1


def test_from_json_takes_exactly_one_patch_of_its_kind():
    text = '{"kind": "rect", "points": [[[0], [1]]]}'
    with pytest.raises(eb.ExactBezierError, match="holds a rect, not a curve"):
        eb.Curve.from_json(text)
    with pytest.raises(eb.ExactBezierError, match="holds 2 patches"):
        eb.RectPatch.from_json("[" + text + "," + text + "]")
    two = eb.read_json("[" + text + "," + text + "]")
    assert [type(p) for p in two] == [eb.RectPatch, eb.RectPatch]


def test_json_numbers_are_read_exactly():
    c = eb.Curve.from_json('{"kind": "curve", "points": [[0.1], [1e-3]], "weights": [1, "1/3"]}')
    assert c.points == [[Fraction(1, 10)], [Fraction(1, 1000)]]
    assert c.weights == [1, Fraction(1, 3)]
