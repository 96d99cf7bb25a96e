"""Canonical keys and coincidence, against copies built by the oracle."""

import hashlib
from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

import exact_bezier as eb
import oracle
from strategies import curves, rects

alphas = st.fractions(min_value=Fraction(1, 10), max_value=Fraction(9, 10), max_denominator=20)


def test_key_text_and_digest_are_those_of_the_library():
    # The example of CanonicalKey::text in the library docs.
    c = eb.Curve([[0], [1]], [1, "1/3"])
    text = eb.key_text(c)
    assert text == "eb1;curve;1,0;P=0,1;1,1;I=+:1;+:1"
    assert eb.key(c) == "eb1:" + hashlib.sha256(text.encode()).hexdigest()
    assert eb.KEY_VERSION == "eb1"


def copy_of(pts, ws, alpha, elevations, reverse):
    """A Möbius-reparameterized, elevated and maybe reversed copy."""
    net = oracle.curve_hom(pts, oracle.mobius_weights(ws, alpha))
    for _ in range(elevations):
        net = oracle.elevate(net)
    if reverse:
        net = oracle.reverse(net)
    return oracle.split(net)


@given(curves(max_degree=4), alphas, st.integers(0, 2), st.booleans())
def test_copies_of_a_curve_have_its_key(net, alpha, elevations, reverse):
    pts, ws = net
    a = eb.Curve(pts, ws)
    b = eb.Curve(*copy_of(pts, ws, alpha, elevations, reverse))
    assert eb.key(a) == eb.key(b)
    c = eb.coincide(a, b)
    assert c and c.coincident and c.witness is not None


@given(curves(max_degree=4))
def test_a_perturbed_curve_has_another_key(net):
    pts, ws = net
    moved = [list(p) for p in pts]
    moved[0][0] += Fraction(1, 10**12)  # an end point moves: another curve
    a, b = eb.Curve(pts, ws), eb.Curve(moved, ws)
    assert eb.key(a) != eb.key(b)
    c = eb.coincide(a, b)
    assert not c and c.witness is None and c.reason


@given(rects(max_degree=2), st.booleans(), st.booleans())
def test_swapped_and_reversed_rects_have_its_key(net, swap, reverse_u):
    pts, ws = net
    if reverse_u:
        pts, ws = pts[::-1], ws[::-1]
    if swap:
        pts = [list(col) for col in zip(*pts)]
        ws = [list(col) for col in zip(*ws)]
    a = eb.RectPatch(*net)
    b = eb.RectPatch(pts, ws)
    assert eb.key(a) == eb.key(b)
    assert eb.coincide(a, b)


@given(rects(max_degree=2))
def test_a_perturbed_rect_has_another_key(net):
    pts, ws = net
    moved = [[list(p) for p in row] for row in pts]
    moved[0][0][0] += Fraction(1, 10**12)  # a corner moves
    assert eb.key(eb.RectPatch(pts, ws)) != eb.key(eb.RectPatch(moved, ws))


def test_witness_numbers_are_fractions():
    a = eb.Curve([[0, 0], [1, 2], [3, 0]])
    pts, ws = copy_of([[0, 0], [1, 2], [3, 0]], [1, 1, 1], Fraction(1, 3), 1, False)
    c = eb.coincide(a, eb.Curve(pts, ws))
    assert c.coincident
    u = c.witness["u"]
    assert isinstance(u["alpha"], Fraction) and isinstance(u["rho"], Fraction)
    assert [r["to"] for r in c.reductions] == [[2, 0], [2, 0]]
    assert c.reductions[1]["from"] == [3, 0]


def test_tri_patches_have_no_key():
    t = eb.TriPatch([[[0], [1]], [[2]]])
    with pytest.raises(eb.ExactBezierError, match="tri"):
        eb.key(t)
    with pytest.raises(eb.ExactBezierError, match="tri"):
        eb.coincide(t, t)
    with pytest.raises(TypeError, match="Curve, RectPatch or TriPatch"):
        eb.key("curve")
