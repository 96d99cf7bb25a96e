"""Algebraic numbers, symbolic polynomials (with SymPy), trig and NURBS
objects, the exception hierarchy and limits, and the NumPy path's shapes
and values."""

import pickle
from fractions import Fraction

import numpy as np
import pytest

import exact_bezier as eb

# --- Algebraic -----------------------------------------------------------


def test_algebraic_arithmetic_and_order_are_exact():
    s2, s3 = eb.Algebraic("sqrt(2)"), eb.Algebraic("sqrt(3)")
    assert s2 * s2 == 2 and (s2 * s2).is_rational
    assert (s2 + s3) * (s2 + s3) == eb.Algebraic("5 + 2*sqrt(6)")
    assert Fraction(141, 100) < s2 < Fraction(142, 100)
    assert s2 < s3 and not s3 < s2 and s2 != s3
    assert eb.Algebraic("CRootOf(x**3 - 2, 0)") == eb.Algebraic("cbrt(2)")
    assert float(s2) == 2**0.5
    assert s2.decimal(12) == "1.414213562373"


def test_algebraic_hash_agrees_with_equality():
    assert hash(eb.Algebraic("4/6")) == hash(Fraction(2, 3))
    assert hash(eb.Algebraic("sqrt(8)/2")) == hash(eb.Algebraic("sqrt(2)"))
    assert pickle.loads(pickle.dumps(eb.Algebraic("1 - cbrt(3)"))) == eb.Algebraic("1 - cbrt(3)")


def test_algebraic_refuses_bad_text_and_division_by_zero():
    with pytest.raises(eb.ParseError):
        eb.Algebraic("sqrt(-1)")
    with pytest.raises(eb.DomainError):
        eb.Algebraic("sqrt(2)") / 0


def test_algebraic_arithmetic_over_the_field_degree_limit_is_refused_at_once():
    # Roots of a septic and a quintic span a field of degree 35 > 32: the
    # operators refuse before any work (the library's resultant fallback
    # has no bound); within the limit they answer exactly.
    a, b = eb.Algebraic("CRootOf(x**7 - x - 1, 0)"), eb.Algebraic("CRootOf(x**5 - x - 1, 0)")
    for op in (lambda: a + b, lambda: a * b, lambda: a - b, lambda: a / b):
        with pytest.raises(eb.LimitError, match="32"):
            op()
    c = a * eb.Algebraic("sqrt(2)")
    assert c * c == 2 * a * a


def test_algebraic_to_sympy():
    sympy = pytest.importorskip("sympy")
    assert eb.Algebraic("sqrt(6)/6").to_sympy() == sympy.sqrt(6) / 6
    assert sympy.simplify(eb.Algebraic("cbrt(12)/2").to_sympy() - sympy.Rational(3, 2) ** sympy.Rational(1, 3)) == 0


# --- Poly and SymPy -------------------------------------------------------


def test_poly_arithmetic_is_canonical():
    a, b = eb.Poly.var("a"), eb.Poly.var("b")
    assert (a + b) ** 2 - a * a - 2 * a * b - b * b == 0
    assert (a + b) ** 2 - a * a  # 2ab + b², not zero
    p = (a - Fraction(1, 2)) * (a + 1)
    assert p.subs("a", Fraction(1, 2)) == 0 and p.diff("a") == 2 * a + Fraction(1, 2)
    assert pickle.loads(pickle.dumps(p)) == p
    assert eb.Poly.from_terms([([("a", 2)], 1), ([], -1)]) == a * a - 1


def test_sympy_round_trip_and_identities():
    sympy = pytest.importorskip("sympy")
    t, u = sympy.symbols("t u")
    expr = (t - u) ** 3 / 4 + sympy.Rational(2, 3) * t
    p = eb.poly_from_sympy(expr)
    assert sympy.expand(eb.poly_to_sympy(p) - expr) == 0
    # Partition of unity of the degree-5 Bernstein basis, and a wrong claim.
    basis = [sympy.binomial(5, i) * t**i * (1 - t) ** (5 - i) for i in range(6)]
    assert eb.prove_identity(sum(basis), 1)
    wrong = eb.prove_identity(sum(basis[:5]), 1)
    assert not wrong and wrong.difference == -eb.poly_from_sympy(t**5)
    # A rational-function identity: 1/(1-t) - 1 = t/(1-t).
    assert eb.prove_identity(1 / (1 - t) - 1, t / (1 - t))
    with pytest.raises(eb.ExactBezierError, match="not a rational function"):
        eb.prove_identity(sympy.sin(t), t)


# --- Trig and NURBS objects -----------------------------------------------


def test_trig_patch_round_trips_and_converts():
    t = eb.TrigPatch([[0, 0], [1, 2], [3, 2], [4, 0]], alpha="1/2")
    assert t.kind == "trig-curve" and t.to_bezier()[0].degree == 4
    assert eb.TrigPatch.from_json(t.to_json()) == t
    assert pickle.loads(pickle.dumps(t)) == t
    assert eval(repr(t), {"TrigPatch": eb.TrigPatch}) == t
    # τ = 0 is t = 0, the first point; τ = 1 is t = π/2, the last (source 002).
    assert t.eval(0) == [0, 0]
    with pytest.raises(eb.ExactBezierError):
        eb.TrigPatch([[0, 0], [1, 2]], alpha=1)


def test_nurbs_curve_pieces_by_knot_insertion_by_hand():
    n = eb.NurbsCurve(2, [0, 0, 0, 1, 2, 2, 2], [[0, 0], [2, 2], [4, 0], [6, 2]])
    a, b = n.to_bezier()
    # The knot 1 of multiplicity 1 splits at (P1 + P2)/2 = (3, 1).
    assert a.points == [[0, 0], [2, 2], [3, 1]] and b.points == [[3, 1], [4, 0], [6, 2]]
    assert pickle.loads(pickle.dumps(n)) == n
    s = eb.NurbsSurface((1, 1), ([0, 0, 1, 1], [0, 0, 1, 1]), [[[0, 0], [0, 1]], [[1, 0], [1, 1]]])
    assert [p.kind for p in s.to_bezier()] == ["rect"]


# --- Errors and limits ----------------------------------------------------


def test_hierarchy():
    for cls in (eb.ParseError, eb.DomainError, eb.LimitError):
        assert issubclass(cls, eb.ExactBezierError) and issubclass(cls, ValueError)
    assert eb.LimitExceeded is eb.LimitError


def test_errors_of_the_command_line_path_have_its_messages():
    c = eb.Curve([[0], [1]])
    with pytest.raises(eb.DomainError, match="parameter out of domain"):
        eb.evaluate(c, 2)
    assert eb.evaluate(c, 2, extrapolate=True) == [2]
    with pytest.raises(eb.ParseError, match="malformed input"):
        eb.read_nurbs("{not json")
    with pytest.raises(TypeError):
        eb.evaluate(c, 0.5)


def test_limits_context_applies_to_both_paths_and_is_restored():
    before = eb.current_limits()
    with eb.limits(max_digits=3):
        with pytest.raises(eb.LimitError, match="--max-digits"):
            eb.Curve([["1234"]])
        with pytest.raises(eb.LimitError, match="--max-digits"):
            eb.evaluate(eb.Curve([[0], [1]]), "1/1234")
    assert eb.current_limits() == before
    with eb.limits(max_work=10):
        with pytest.raises(eb.LimitError, match="--max-work"):
            eb.elevate(eb.Curve([[k] for k in range(20)]), 20)
    assert eb.Curve([["1234"]]).points == [[1234]]


def test_a_panic_becomes_an_exception():
    with pytest.raises(eb.ExactBezierError, match="internal error"):
        eb._native._panic_for_test()


# --- NumPy ---------------------------------------------------------------


def test_eval_many_matches_exact_points():
    c = eb.Curve([[0, 0], [1, 2], [3, 0]], weights=[1, "1/3", 1])
    ts = np.linspace(0, 1, 33)
    got = c.eval_many(ts)
    want = np.array([[float(x) for x in c.eval(Fraction(t))] for t in ts])
    assert got.shape == (33, 2) and got.dtype == np.float64
    assert np.allclose(got, want, rtol=1e-14, atol=1e-14)


def test_derivatives_many_match_the_exact_derivative():
    c = eb.Curve([[0, 0], [1, 2], [3, 0]], weights=[1, "1/3", 1])
    x, dx = c.derivatives_many(np.array([0.5, 0.25]))
    assert x.shape == dx.shape == (2, 2)
    assert np.allclose(dx[0], [float(v) for v in eb.derivative(c, "1/2")])
    assert np.allclose(dx[1], [float(v) for v in eb.derivative(c, "1/4")])
    r = eb.RectPatch([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    p, du, dv = r.derivatives_many(np.array([[0.5, 0.25]] * 3))
    # X = (u, v, uv): X_u = (1, 0, v), X_v = (0, 1, u).
    assert np.allclose(du, [[1, 0, 0.25]] * 3) and np.allclose(dv, [[0, 1, 0.5]] * 3)
    t = eb.TriPatch([[[0, 0], [1, 0]], [[0, 1]]])
    p, du, dv = t.derivatives_many(np.zeros((0, 2)))
    assert p.shape == du.shape == (0, 2)


def test_numpy_parameter_shapes():
    c = eb.Curve([[0, 0, 0], [1, 1, 1]])
    assert c.eval_many(np.zeros((5, 1))).shape == (5, 3)
    assert c.eval_many(np.zeros(0)).shape == (0, 3)
    assert c.eval_many(np.arange(10.0)[::3] / 10).shape == (4, 3)  # a strided view
    with pytest.raises(eb.ExactBezierError, match="shape"):
        c.eval_many(np.zeros((5, 2)))
    r = eb.RectPatch([[[0], [1]], [[2], [4]]])
    assert r.eval_many(np.full((7, 2), 0.5)).shape == (7, 1)
    with pytest.raises(eb.ExactBezierError, match="shape"):
        r.eval_many(np.zeros(3))


def test_meshes_cover_the_domain_with_consistent_faces():
    tri = eb.TriPatch([[[0, 0], [1, 0]], [[0, 1]]])  # the identity on the triangle
    for n in (1, 2, 5):
        v, f = eb.mesh(tri, n)
        assert v.shape == ((n + 1) * (n + 2) // 2, 2) and f.shape == (n * n, 3)
        # Counter-clockwise triangles of area 1/(2n²) tile the triangle.
        p, q, r = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
        area = ((q - p)[:, 0] * (r - p)[:, 1] - (q - p)[:, 1] * (r - p)[:, 0]) / 2
        assert np.allclose(area, 1 / (2 * n * n))
    rect = eb.RectPatch([[[0, 0], [0, 1]], [[1, 0], [1, 1]]])  # the identity on the square
    v, f = eb.mesh(rect, 3)
    p, q, r = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    area = ((q - p)[:, 0] * (r - p)[:, 1] - (q - p)[:, 1] * (r - p)[:, 0]) / 2
    assert v.shape == (16, 2) and f.shape == (18, 3) and np.allclose(area, 1 / 18)
    v, s = eb.mesh(eb.Curve([[0], [2]]), 4)
    assert v.ravel().tolist() == [0, 0.5, 1, 1.5, 2] and s.tolist()[-1] == [3, 4]
