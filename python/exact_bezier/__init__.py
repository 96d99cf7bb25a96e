"""Exact rational Bézier curves and patches, on the exact-bezier Rust kernel.

Curves and patches hold exact rationals; evaluation returns
``fractions.Fraction`` values, batch evaluation NumPy ``float64`` arrays.

>>> from fractions import Fraction
>>> import exact_bezier as eb
>>> arc = eb.Curve([[1, 0], [1, "4/3"], ["-7/25", "24/25"]], weights=[1, "3/5", 1])
>>> x, y = arc.eval(Fraction(1, 3))
>>> x * x + y * y == 1
True

Beyond the objects: every command of the command line as a function
(:mod:`exact_bezier.operations`: ``evaluate``, ``derivative``,
``curvature``, ``reparameterize``, ``standardize``, ``elevate``,
``reduce``, ``convert``, ``intersect``, ``audit``, ``read_step``, ``arc``,
``prove`` …), ``key``/``keys``/``dedup`` for bulk work, exact algebraic
numbers (``Algebraic``), symbolic polynomials (``Poly``, with SymPy in
and out and ``prove_identity``), trigonometric and NURBS objects, and
resource limits (``limits``).

See docs/python.md for a tour.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from fractions import Fraction
from typing import Any, Dict, List, Optional, Union

from ._bridge import current_limits, limits
from ._native import (
    KEY_VERSION,
    Algebraic,
    Curve,
    DomainError,
    ExactBezierError,
    LimitError,
    ParseError,
    Poly,
    RectPatch,
    TriPatch,
    coincide_json as _coincide_json,
    key,
    key_text,
    read_json,
)
from .objects import BrepModel, NurbsCurve, NurbsSurface, TrigPatch
from .operations import (
    DedupClass,
    arc,
    audit,
    convert,
    curvature,
    dedup,
    derivative,
    elevate,
    evaluate,
    evaluate_grid,
    intersect,
    is_circle,
    join,
    keys,
    mesh,
    prove,
    read_nurbs,
    read_step,
    reduce,
    reparameterize,
    standardize,
)
from .symbolic import Identity, poly_from_sympy, poly_to_sympy, prove_identity

#: The same class as :class:`LimitError` (the name of the issue's hierarchy).
LimitExceeded = LimitError

__all__ = [
    "KEY_VERSION",
    "Algebraic",
    "Coincidence",
    "Curve",
    "DedupClass",
    "DomainError",
    "ExactBezierError",
    "Identity",
    "LimitError",
    "LimitExceeded",
    "NurbsCurve",
    "NurbsSurface",
    "BrepModel",
    "ParseError",
    "Poly",
    "RectPatch",
    "TriPatch",
    "TrigPatch",
    "arc",
    "audit",
    "coincide",
    "convert",
    "current_limits",
    "curvature",
    "dedup",
    "derivative",
    "elevate",
    "evaluate",
    "evaluate_grid",
    "intersect",
    "is_circle",
    "join",
    "key",
    "key_text",
    "keys",
    "limits",
    "mesh",
    "poly_from_sympy",
    "poly_to_sympy",
    "prove",
    "prove_identity",
    "read_json",
    "read_nurbs",
    "read_step",
    "reduce",
    "reparameterize",
    "standardize",
]

AnyPatch = Union[Curve, RectPatch, TriPatch]

# Witness fields that hold numbers (written as JSON integers or "p/q").
_NUMBER_FIELDS = {"rho", "alpha", "sigma", "beta", "k", "corner_weight_ratio", "value"}


def _exact_numbers(value: Any, field: Optional[str] = None) -> Any:
    """The witness JSON with its numbers as ``Fraction`` values."""
    if isinstance(value, dict):
        return {k: _exact_numbers(v, k) for k, v in value.items()}
    if isinstance(value, list):
        return [_exact_numbers(v, field) for v in value]
    if field in _NUMBER_FIELDS and isinstance(value, (int, str)) and not isinstance(value, bool):
        return Fraction(value)
    return value


@dataclass(frozen=True)
class Coincidence:
    """The answer of :func:`coincide`: true in a boolean context when the
    two inputs are the same curve or patch.

    ``witness`` (when coincident) is a dict: ``symmetry`` (text), ``u`` and
    ``v`` (Möbius parameters ``{"rho", "alpha"}`` / ``{"sigma", "beta"}`` as
    ``Fraction`` values, or ``None``), ``k`` and ``corner_weight_ratio``.
    ``reductions`` says to which minimal degree each input was reduced.

    >>> import exact_bezier as eb
    >>> a = eb.Curve([[0, 0], [1, 2], [3, 0]])
    >>> b = eb.Curve([[3, 0], [1, 2], [0, 0]])
    >>> c = eb.coincide(a, b)
    >>> bool(c), c.witness["symmetry"]
    (True, 'reverse u')
    """

    coincident: bool
    reason: str
    witness: Optional[Dict[str, Any]]
    reductions: List[Dict[str, Any]]

    def __bool__(self) -> bool:
        return self.coincident


def coincide(a: AnyPatch, b: AnyPatch) -> Coincidence:
    """Decide exactly whether ``a`` and ``b`` are the same curve or rect
    patch, up to Möbius reparameterization, reversal, swap of u and v,
    degree elevation, common factors and weight scaling.

    Raises ``ExactBezierError`` for a tri patch, ``LimitError`` when the
    estimated work is over the limit.

    >>> import exact_bezier as eb
    >>> a = eb.Curve([[0, 0], [1, 2], [3, 0]])
    >>> bool(eb.coincide(a, eb.Curve([[0, 0], [1, 2], [3, 1]])))
    False
    """
    d = json.loads(_coincide_json(a, b))
    return Coincidence(
        coincident=d["coincident"],
        reason=d["reason"],
        witness=_exact_numbers(d["witness"]),
        reductions=d["reductions"],
    )
