"""The command line's capabilities as functions, against the Fraction
oracle (oracle.py) and values derived by hand."""

import pickle
import pathlib
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import exact_bezier as eb
import oracle
from strategies import curves, params, rects

ROOT = pathlib.Path(__file__).resolve().parents[2]
ALPHAS = st.fractions(min_value=Fraction(1, 50), max_value=Fraction(49, 50), max_denominator=50)
# The unit-circle arc of docs/python.md: every point at distance 1 from 0.
ARC = eb.Curve([[1, 0], [1, "4/3"], ["-7/25", "24/25"]], weights=[1, "3/5", 1])


@settings(max_examples=25)
@given(curves(max_degree=5), params)
def test_evaluate_is_de_casteljau(net, t):
    pts, ws = net
    assert eb.evaluate(eb.Curve(pts, ws), t) == oracle.eval_curve(pts, ws, t)


@settings(max_examples=15)
@given(rects(max_degree=2), params, params)
def test_evaluate_many_points_of_a_rect(net, u, v):
    pts, ws = net
    r = eb.RectPatch(pts, ws)
    assert eb.evaluate(r, [(u, v), (v, u)]) == [
        oracle.eval_rect(pts, ws, u, v),
        oracle.eval_rect(pts, ws, v, u),
    ]


@given(curves(max_degree=5), params.filter(lambda t: 0 < t < 1), params)
def test_subdivided_pieces_are_the_curve_on_their_intervals(net, t, s):
    pts, ws = net
    left, right = eb.Curve(pts, ws).subdivide(t)
    assert left.eval(s) == oracle.eval_curve(pts, ws, s * t)
    assert right.eval(s) == oracle.eval_curve(pts, ws, t + s * (1 - t))


@given(rects(max_degree=2), params.filter(lambda t: 0 < t < 1), params, params)
def test_subdivided_rect_pieces(net, t, u, v):
    pts, ws = net
    r = eb.RectPatch(pts, ws)
    a, b = r.subdivide(t, "u")
    assert a.eval(u, v) == oracle.eval_rect(pts, ws, u * t, v)
    c, d = r.subdivide(t, "v")
    assert d.eval(u, v) == oracle.eval_rect(pts, ws, u, t + v * (1 - t))


def test_subdivide_refuses_t_outside_the_unit_interval():
    with pytest.raises(eb.DomainError, match="outside"):
        eb.Curve([[0], [1]]).subdivide(2)


@settings(max_examples=20)
@given(curves(max_degree=4, min_degree=1), ALPHAS)
def test_mobius_map_changes_only_the_weights(net, alpha):
    pts, ws = net
    c = eb.reparameterize(eb.Curve(pts, ws), alpha)
    assert c.points == eb.Curve(pts, ws).points
    # Weights are defined up to a common factor: compare ratios.
    want = oracle.mobius_weights(ws, alpha)
    assert [w / c.weights[0] for w in c.weights] == [w / want[0] for w in want]
    assert eb.key(c) == eb.key(eb.Curve(pts, ws))


@settings(max_examples=20)
@given(curves(max_degree=4), st.integers(1, 3))
def test_elevate_is_repeated_oracle_elevation(net, r):
    pts, ws = net
    h = oracle.curve_hom(pts, ws)
    for _ in range(r):
        h = oracle.elevate(h)
    want_pts, want_ws = oracle.split(h)
    c = eb.elevate(eb.Curve(pts, ws), r)
    assert (c.points, c.weights) == (want_pts, want_ws)


def test_derivative_of_a_polynomial_cubic_by_hand():
    # X(t) = (t, t³) from the points (0,0), (1/3,0), (2/3,0), (1,1).
    c = eb.Curve([[0, 0], ["1/3", 0], ["2/3", 0], [1, 1]])
    t = Fraction(1, 2)
    assert eb.derivative(c, t) == [1, 3 * t**2]
    assert eb.derivative(c, t, order=2) == [0, 6 * t]
    assert all(isinstance(x, Fraction) for x in eb.derivative(c, t))


def test_curvature_of_the_unit_circle_is_one():
    k = eb.curvature(ARC, "2/7")
    assert k["curvature_squared"] == 1 and k["curvature"] == 1
    assert k["curvature_approx"] == pytest.approx(1)


def test_standard_form_has_end_weights_one_and_the_same_key():
    c = eb.Curve([[0, 0], [1, 2], [3, 0]], weights=[2, "1/3", 5])
    s = eb.standardize(c)
    assert s["exact"] is True
    p = s["patch"]
    if isinstance(p, eb.Curve):  # rational answer
        assert p.weights[0] == p.weights[-1] == 1
        assert eb.key(p) == eb.key(c)
    else:  # algebraic numbers (a square root of 5/2 here)
        assert p["weights"][0] == p["weights"][-1] == 1
        assert isinstance(p["weights"][1], eb.Algebraic)


def test_convert_rect_to_tris_and_back():
    r = eb.RectPatch([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    tris = eb.convert(r, "tri")
    assert [t.kind for t in tris] == ["tri", "tri"] and [t.degree for t in tris] == [2, 2]
    rects = eb.convert(tris[0], "rect")
    assert len(rects) == 3 and all(x.degree == (2, 2) for x in rects)


def test_intersect_two_lines_at_a_point_found_by_hand():
    r = eb.intersect(eb.Curve([[0, 0], [2, 2]]), eb.Curve([[0, 2], [2, 0]]))
    (x,) = r["intersections"]
    assert (x["s"], x["t"], x["point"]) == (Fraction(1, 2), Fraction(1, 2), [1, 1])
    assert r["overlaps"] == []


def test_self_intersection_of_a_loop_has_algebraic_parameters():
    loop = eb.Curve([[0, 0], [4, 4], [-2, 4], [2, 0]])
    r = eb.intersect(loop)
    assert r["intersections"], r
    s, t = r["intersections"][0]["s"], r["intersections"][0]["t"]
    assert s < t and 0 < s and t < 1


def test_join_of_a_curve_split_in_two_is_g2():
    a, b = ARC.subdivide("1/3")
    j = eb.join(a, b)
    assert j["g0"] is True and j["g1"] is True and j["g2"] is True


def test_is_circle_finds_the_unit_circle():
    r = eb.is_circle(ARC)
    assert r["circle"] is True and r["center"] == [0, 0] and r["radius_squared"] == 1


def test_arc_with_an_algebraic_cosine():
    a = eb.arc("sqrt(2)/2", 0, [[1, 0], [1, 1], [0, 1]])
    assert a["points"][0] == [1, 0] and a["points"][3] == [0, 1]
    assert a["weights"][0] == a["weights"][3] == 1
    assert isinstance(a["weights"][1], eb.Algebraic)
    assert a["cos_half"] == eb.Algebraic("1/sqrt(2)")


def test_read_step_gives_the_bezier_pieces():
    model = eb.read_step(ROOT / "docs" / "examples" / "two_faces.stp")
    assert model.summary["faces"] == 2
    pieces = model.surface_pieces()
    assert [p.kind for p in pieces] == ["rect", "rect"]
    # The second face ends at (2, y, 1/2) in the file.
    assert pieces[1].eval(1, 0)[0] == 2 and pieces[1].eval(1, 0)[2] == Fraction(1, 2)


def test_nurbs_as_our_json():
    text = '{"kind": "nurbs-curve", "degree": 1, "knots": [0, 0, 1, 2, 2], "points": [[0], [1], [3]]}'
    assert [p.points for p in eb.read_nurbs(text)] == [[[0], [1]], [[1], [3]]]


def test_audit_of_two_faces_sharing_an_edge():
    a = eb.audit(eb.read_step(ROOT / "docs" / "examples" / "two_faces.stp"), summary=True)
    assert set(a["counts"]) >= {"G0", "G1", "G2"}
    assert sum(a["counts"].values()) == 1  # one shared edge


def test_prove_reports_as_data():
    claims = eb.prove("bernstein")
    assert claims and all(c["family"] == "bernstein" for c in claims)
    assert all(c["verdict"] == c["expected"] for c in claims)


def test_dedup_matches_the_command_line():
    cs = [eb.Curve([[0], [1], [3]]), eb.Curve([[3], [1], [0]]), eb.Curve([[0], [1], [4]]),
          eb.elevate(eb.Curve([[0], [1], [3]]), 1)]
    ours = [(c.members, c.representative) for c in eb.dedup(iter(cs))]
    assert ours == [([0, 1, 3], cs[0]), ([2], cs[2])]
    from exact_bezier._bridge import json_input, run_json

    cli = run_json(["dedup", "-"], json_input(cs))
    assert [c["members"] for c in cli] == [m for m, _ in ours]
    assert list(eb.keys(cs)) == [eb.key(c) for c in cs]


def test_a_step_b_rep_read_whole_exactly():
    # The screw of tests/fixtures/step (EUCLID, LGPL): 10 faces (4 planes,
    # 3 tori, 2 cones, 1 cylinder) and 22 edges, every one converted; each
    # edge used twice (3 seams), as counted by hand in its README.
    model = eb.read_step(ROOT / "tests" / "fixtures" / "step" / "screw.step")
    s = model.summary
    assert s["faces_by_surface"] == {"PLANE": 4, "TOROIDAL_SURFACE": 3, "CONICAL_SURFACE": 2, "CYLINDRICAL_SURFACE": 1}
    assert s["edges"] == 22 and s["edge_uses"] == {"shared": 19, "seam": 3}
    assert all(f["surface"]["status"] == "converted" for f in model.faces)
    assert all(e["curve"]["status"] == "converted" for e in model.edges)
    assert pickle.loads(pickle.dumps(model)).summary == s
