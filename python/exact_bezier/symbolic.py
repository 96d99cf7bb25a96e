"""SymPy in and out: polynomials over Q as the kernel's ``Poly``, and
identities stated in SymPy decided by the kernel.

SymPy is imported only by these functions (``pip install sympy``). The
translation walks the SymPy expression tree (sums, products, integer
powers, rationals, symbols) and does every operation with the kernel's
exact polynomial arithmetic; SymPy does no expansion.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from typing import Any, Tuple

from ._native import ExactBezierError, Poly


def _sympy() -> Any:
    try:
        import sympy
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError("exact_bezier's SymPy functions need SymPy (pip install sympy)") from e
    return sympy


def _fraction_of(expr: Any) -> Tuple[Poly, Poly]:
    """``expr`` as a quotient of kernel polynomials ``(numerator,
    denominator)``."""
    sp = _sympy()
    if expr.is_Symbol:
        return Poly.var(expr.name), Poly.constant(1)
    if expr.is_Rational:
        return Poly.constant(Fraction(int(expr.p), int(expr.q))), Poly.constant(1)
    if expr.is_Add:
        n, d = Poly.constant(0), Poly.constant(1)
        for a in expr.args:
            an, ad = _fraction_of(a)
            n, d = n * ad + an * d, d * ad
        return n, d
    if expr.is_Mul:
        n, d = Poly.constant(1), Poly.constant(1)
        for a in expr.args:
            an, ad = _fraction_of(a)
            n, d = n * an, d * ad
        return n, d
    if expr.is_Pow and expr.exp.is_Integer:
        bn, bd = _fraction_of(expr.base)
        e = int(expr.exp)
        if e < 0:
            if not bn:
                raise ExactBezierError("division by zero in the expression")
            bn, bd, e = bd, bn, -e
        return bn ** e, bd ** e
    raise ExactBezierError(
        f"not a rational function over Q with integer powers: {sp.srepr(expr)[:200]}"
    )


def poly_from_sympy(expr: Any) -> Poly:
    """A SymPy polynomial expression over Q as a kernel ``Poly``.

    >>> import sympy, exact_bezier as eb
    >>> a, b = sympy.symbols("a b")
    >>> str(eb.poly_from_sympy((a + b) ** 2))
    'a^2 + 2*a*b + b^2'
    """
    n, d = _fraction_of(_sympy().sympify(expr))
    c = d.as_constant()
    if c is None:
        raise ExactBezierError("not a polynomial: the expression has a non-constant denominator")
    return n * Poly.constant(1 / c)


def poly_to_sympy(p: Poly) -> Any:
    """A kernel ``Poly`` as a SymPy expression."""
    sp = _sympy()
    total = sp.Integer(0)
    for monomial, c in p.terms():
        term = sp.Rational(c.numerator, c.denominator)
        for name, e in monomial.items():
            term *= sp.Symbol(name) ** e
        total += term
    return total


@dataclass(frozen=True)
class Identity:
    """The verdict of :func:`prove_identity`: ``holds`` (also the truth
    value) and ``difference``, the kernel's numerator of ``lhs − rhs`` over
    a common denominator (zero exactly when the identity holds)."""

    holds: bool
    difference: Poly

    def __bool__(self) -> bool:
        return self.holds


def prove_identity(lhs: Any, rhs: Any) -> Identity:
    """Decide exactly whether two rational functions over Q (SymPy
    expressions or text SymPy reads) are equal, with the kernel's
    polynomial arithmetic: ``n₁/d₁ = n₂/d₂`` iff ``n₁·d₂ − n₂·d₁ = 0`` in
    Q[x…], a canonical form, so the verdict is a proof (where both
    denominators are non-zero).

    >>> import sympy, exact_bezier as eb
    >>> t = sympy.Symbol("t")
    >>> bernstein = [sympy.binomial(3, i) * t**i * (1 - t)**(3 - i) for i in range(4)]
    >>> bool(eb.prove_identity(sum(bernstein), 1))
    True
    >>> bool(eb.prove_identity((t + 1)**2, t**2 + 1))
    False
    """
    sp = _sympy()
    n1, d1 = _fraction_of(sp.sympify(lhs))
    n2, d2 = _fraction_of(sp.sympify(rhs))
    diff = n1 * d2 - n2 * d1
    return Identity(holds=not diff, difference=diff)
