"""Trigonometric patches and NURBS curves and surfaces as objects.

Each holds its JSON object (docs/FORMAT.md), checked by the kernel when it
is made, and converts to rational Bézier form with the kernel. Equality is
exact (numbers compared as ``Fraction``); objects pickle as their JSON
text.
"""

from __future__ import annotations

import json
from fractions import Fraction
from typing import Any, Dict, List, Optional, Sequence

from ._bridge import ParseError, exact_text, run_json, to_python
from .operations import convert, evaluate


def _texts(x: Any, exact_from_float: bool) -> Any:
    """Nested numbers as exact JSON strings (floats only when asked)."""
    if isinstance(x, (list, tuple)):
        return [_texts(v, exact_from_float) for v in x]
    if isinstance(x, float) and exact_from_float:
        x = Fraction(x)
    return exact_text(x)


def _exact(x: Any) -> Any:
    """A JSON value with its numbers as ``Fraction`` (for equality)."""
    if isinstance(x, list):
        return [_exact(v) for v in x]
    if isinstance(x, dict):
        return {k: _exact(v) for k, v in x.items()}
    if isinstance(x, (int, str)) and not isinstance(x, bool):
        try:
            return Fraction(x)
        except ValueError:
            return x
    return x


class _JsonObject:
    """An object of the JSON format checked by ``exact-bezier convert``."""

    _kinds: Sequence[str] = ()
    _convert_to = ""

    def __init__(self, fields: Dict[str, Any]) -> None:
        self._fields = fields
        self._pieces = convert(self.to_json(), self._convert_to)

    @classmethod
    def from_json(cls, text: str) -> "_JsonObject":
        """Read one object of this class from JSON text."""
        try:
            fields = json.loads(text)
        except json.JSONDecodeError as e:
            raise ParseError(f"malformed input: {e}") from None
        if not isinstance(fields, dict) or fields.get("kind") not in cls._kinds:
            raise ParseError(f"malformed input: expected a JSON object of kind {' or '.join(cls._kinds)}")
        obj = cls.__new__(cls)
        _JsonObject.__init__(obj, fields)
        return obj

    def to_json(self) -> str:
        """The JSON text (docs/FORMAT.md)."""
        return json.dumps(self._fields, separators=(",", ":"))

    @property
    def kind(self) -> str:
        """The ``kind`` of the JSON object."""
        return self._fields["kind"]

    def to_bezier(self) -> List[Any]:
        """The rational Bézier curves or patches of the object."""
        return list(self._pieces)

    def __eq__(self, other: object) -> bool:
        if type(other) is not type(self):
            return NotImplemented
        return _exact(self._fields) == _exact(other._fields)  # type: ignore[attr-defined]

    def __hash__(self) -> int:
        return hash(json.dumps(_exact_text(self._fields), sort_keys=True))

    def __repr__(self) -> str:
        return f"{type(self).__name__}.from_json({self.to_json()!r})"

    def __reduce__(self) -> Any:
        return (type(self).from_json, (self.to_json(),))


def _exact_text(x: Any) -> Any:
    e = _exact(x)
    if isinstance(e, list):
        return [_exact_text(v) for v in e]
    if isinstance(e, dict):
        return {k: _exact_text(v) for k, v in e.items()}
    return str(e)


class TrigPatch(_JsonObject):
    """A trigonometric Bézier curve (``trig-curve``: 4 points) or patch
    (``trig-rect``: 4 × 4 points) with shape parameter(s) ``alpha``
    (source 002); exact in τ = tan(t/2).

    >>> import exact_bezier as eb
    >>> t = eb.TrigPatch([[0, 0], [1, 2], [3, 2], [4, 0]], alpha=1)
    >>> t.kind, t.to_bezier()[0].degree
    ('trig-curve', 4)
    >>> t.eval(0) == [0, 0]
    True
    """

    _kinds = ("trig-curve", "trig-rect")
    _convert_to = "rational"

    def __init__(self, points: Sequence[Any], alpha: Any = 1, *, exact_from_float: bool = False) -> None:
        pts = _texts(points, exact_from_float)
        rect = bool(pts) and isinstance(pts[0], list) and bool(pts[0]) and isinstance(pts[0][0], list)
        super().__init__({
            "kind": "trig-rect" if rect else "trig-curve",
            "alpha": _texts(alpha, exact_from_float),
            "points": pts,
        })

    def eval(self, *tau: Any) -> List[Fraction]:
        """The exact point at τ = tan(t/2) (one value for a curve, two for
        a patch)."""
        return evaluate(self.to_json(), ",".join(f"tau={exact_text(x)}" for x in tau))


class NurbsCurve(_JsonObject):
    """A NURBS curve (``nurbs-curve``): degree, knots, control points and
    optional weights, exact.

    >>> import exact_bezier as eb
    >>> n = eb.NurbsCurve(2, [0, 0, 0, 1, 2, 2, 2], [[0, 0], [1, 1], [2, 0], [3, 1]])
    >>> [p.degree for p in n.to_bezier()]
    [2, 2]
    """

    _kinds = ("nurbs-curve",)
    _convert_to = "bezier"

    def __init__(
        self,
        degree: int,
        knots: Sequence[Any],
        points: Sequence[Any],
        weights: Optional[Sequence[Any]] = None,
        *,
        exact_from_float: bool = False,
    ) -> None:
        fields: Dict[str, Any] = {
            "kind": "nurbs-curve",
            "degree": int(degree),
            "knots": _texts(knots, exact_from_float),
            "points": _texts(points, exact_from_float),
        }
        if weights is not None:
            fields["weights"] = _texts(weights, exact_from_float)
        super().__init__(fields)


class NurbsSurface(_JsonObject):
    """A NURBS surface (``nurbs-surface``): degrees ``(p, q)``, knots
    ``(u_knots, v_knots)``, a grid of control points, optional weights."""

    _kinds = ("nurbs-surface",)
    _convert_to = "bezier"

    def __init__(
        self,
        degree: Sequence[int],
        knots: Sequence[Sequence[Any]],
        points: Sequence[Any],
        weights: Optional[Sequence[Any]] = None,
        *,
        exact_from_float: bool = False,
    ) -> None:
        fields: Dict[str, Any] = {
            "kind": "nurbs-surface",
            "degree": [int(d) for d in degree],
            "knots": _texts(knots, exact_from_float),
            "points": _texts(points, exact_from_float),
        }
        if weights is not None:
            fields["weights"] = _texts(weights, exact_from_float)
        super().__init__(fields)


__all__ = ["NurbsCurve", "NurbsSurface", "TrigPatch", "to_python", "run_json"]


class BrepModel:
    """A STEP file's B-rep, read exactly (``exact-bezier convert FILE
    --to bezier``, layout in docs/FORMAT.md "B-rep"): faces with their
    surface pieces and bounds, edges with their curve pieces (trimmed
    between their vertices), vertices, units, tolerance and a summary.

    Numbers are ``Fraction`` or ``Algebraic``; pieces with rational numbers
    are ``Curve``/``RectPatch`` objects, pieces with radicals dicts. The
    JSON text is kept: ``to_json()`` gives it back, so the model can be
    given to ``audit`` (which reads its surface pieces) and pickled.
    """

    def __init__(self, text: str) -> None:
        self._text = text
        self._doc = to_python(json.loads(text))
        if not isinstance(self._doc, dict) or self._doc.get("kind") != "brep":
            raise ParseError("malformed input: expected a B-rep document (kind \"brep\")")

    @classmethod
    def from_json(cls, text: str) -> "BrepModel":
        """Read a B-rep document written by ``convert --to bezier``."""
        try:
            return cls(text)
        except json.JSONDecodeError as e:
            raise ParseError(f"malformed input: {e}") from None

    def to_json(self) -> str:
        """The B-rep document's JSON text."""
        return self._text

    @property
    def faces(self) -> List[Dict[str, Any]]:
        """The faces: ``id``, ``same_sense``, ``surface`` (entity, type,
        status, pieces), ``bounds``."""
        return self._doc["faces"]

    @property
    def edges(self) -> List[Dict[str, Any]]:
        """The edges: ``id``, ``curve``, ``start``, ``end``, ``use``,
        ``faces``, ``pcurves``."""
        return self._doc["edges"]

    @property
    def vertices(self) -> List[Dict[str, Any]]:
        """The vertices: ``id`` and exact ``point``."""
        return self._doc["vertices"]

    @property
    def summary(self) -> Dict[str, Any]:
        """Faces by surface type, edges by curve type, edge uses, what was
        not converted or only approximated, invalid entities."""
        return self._doc["summary"]

    @property
    def contexts(self) -> List[Dict[str, Any]]:
        """Units and declared tolerance of each representation context."""
        return self._doc["contexts"]

    def surface_pieces(self) -> List[Any]:
        """Every converted face's surface pieces, face by face."""
        return [p for f in self.faces for p in f["surface"].get("pieces", [])]

    def __repr__(self) -> str:
        s = self.summary
        return f"<BrepModel: {s['faces']} faces, {s['edges']} edges, {s['vertices']} vertices>"

    def __reduce__(self) -> Any:
        return (BrepModel.from_json, (self._text,))
