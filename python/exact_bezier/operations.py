"""Every capability of the command line as a function.

Each function runs one subcommand of ``exact-bezier`` in-process (see
:mod:`exact_bezier._bridge`) on objects, and returns Python values: exact
rationals as ``Fraction`` (or ``int``), real algebraic numbers as
``Algebraic``, curves and patches as objects, results as dicts with the
fields of docs/FORMAT.md ("Outputs"). Errors are the exceptions of the
hierarchy, with the command line's one-line messages.

>>> from fractions import Fraction
>>> import exact_bezier as eb
>>> c = eb.Curve([[0, 0], [1, 2], [3, 0]], weights=[1, "1/3", 1])
>>> eb.evaluate(c, "1/3")
[Fraction(13, 19), Fraction(8, 19)]
>>> eb.derivative(c, "1/2", order=2)
[Fraction(3, 2), Fraction(-6, 1)]
>>> eb.curvature(c, "1/2")["curvature"]
Fraction(8, 27)
"""

from __future__ import annotations

import os
import tempfile
from dataclasses import dataclass
from fractions import Fraction
from typing import Any, Dict, Iterable, Iterator, List, Optional, Sequence, Tuple, Union

from ._bridge import Patchlike, as_fractions, exact_text, json_input, run_json, run_text
from ._native import Curve, TriPatch, key

Number = Union[int, Fraction, str]


def _to_json(obj: Any) -> str:
    if hasattr(obj, "to_json"):
        return obj.to_json()
    if isinstance(obj, (str, bytes)):
        return obj.decode() if isinstance(obj, bytes) else obj
    raise TypeError(f"expected a curve, patch or JSON text, found {type(obj).__name__}")


def _param_text(obj: Any, at: Any) -> str:
    """One parameter point as the command line's ``--at`` text: ``t`` for
    a curve, ``u,v`` for a patch, ``tau=…`` for a trig patch (given as
    ``("tau", T)`` or the text itself)."""
    if isinstance(at, (tuple, list)):
        if len(at) == 2 and at[0] in ("tau", "angle"):
            return f"{at[0]}={exact_text(at[1])}"
        return ",".join(exact_text(x) for x in at)
    return exact_text(at)


def evaluate(obj: Any, at: Any, *, extrapolate: bool = False) -> Any:
    """The exact point of a curve, patch or trig patch at one parameter
    point (``t``; ``(u, v)``; ``"tau=1/3"``), or the list of points at a
    list of parameter points. Rational points are lists of ``Fraction``.

    >>> import exact_bezier as eb
    >>> eb.evaluate(eb.RectPatch([[[0], [1]], [[2], [4]]]), [("1/2", "1/2"), (1, 1)])
    [[Fraction(7, 4)], [Fraction(4, 1)]]
    """
    many = isinstance(at, list)
    points = at if many else [at]
    args = ["eval", "-"]
    for p in points:
        args.append(f"--at={_param_text(obj, p)}")
    if extrapolate:
        args.append("--extrapolate")
    out = run_json(args, _to_json(obj))
    xs = [as_fractions(p["point"]) for p in out.get("points", [out])]
    return xs if many else xs[0]


def evaluate_grid(obj: Any, n: int) -> List[Tuple[List[Fraction], List[Fraction]]]:
    """``(parameters, point)`` pairs on the grid of ``exact-bezier eval
    --grid n``: ``t = i/n`` for a curve, ``(i/n, j/n)`` for a rect, with
    ``i + j ≤ n`` for a tri patch."""
    out = run_json(["eval", "-", f"--grid={int(n)}"], _to_json(obj))["points"]
    return [(as_fractions(p["at"]), as_fractions(p["point"])) for p in out]


def derivative(curve: Any, t: Number, order: int = 1, *, extrapolate: bool = False) -> List[Any]:
    """The exact ``order``-th derivative vector of a curve at ``t``."""
    args = ["deriv", "-", f"--at={exact_text(t)}", f"--order={int(order)}"]
    if extrapolate:
        args.append("--extrapolate")
    return as_fractions(run_json(args, _to_json(curve))["derivative"])


def curvature(curve: Any, t: Number, *, extrapolate: bool = False) -> Dict[str, Any]:
    """The curvature of a curve at ``t``: ``{"curvature_squared": κ²
    (Fraction), "curvature": κ (Fraction or Algebraic), "curvature_approx":
    float}``."""
    args = ["curvature", "-", f"--at={exact_text(t)}"]
    if extrapolate:
        args.append("--extrapolate")
    return run_json(args, _to_json(curve))


def reparameterize(
    patch: Patchlike,
    alpha: Optional[Number] = None,
    beta: Optional[Number] = None,
    *,
    quadratic: Optional[Sequence[Number]] = None,
) -> Patchlike:
    """The same curve or rect patch under the linear Möbius map
    ``u = (α−1)s/(2αs−s−α)`` (``alpha`` for a curve, ``alpha, beta`` for a
    rect; each strictly between 0 and 1, 1/2 the identity), or the
    quadratic map of a rect (``quadratic=(a1, a2, b1, b2)``).

    >>> import exact_bezier as eb
    >>> c = eb.Curve([[0, 0], [1, 2], [3, 0]], weights=[1, "1/3", 1])
    >>> eb.reparameterize(c, "1/3").weights
    [Fraction(1, 9), Fraction(2, 27), Fraction(4, 9)]
    """
    if quadratic is not None:
        arg = "--quadratic=" + ",".join(exact_text(x) for x in quadratic)
    elif alpha is not None:
        arg = "--mobius=" + ",".join(exact_text(x) for x in ([alpha] if beta is None else [alpha, beta]))
    else:
        raise TypeError("reparameterize needs alpha (and beta for a rect) or quadratic=")
    return run_json(["reparam", "-", arg], _to_json(patch))


def standardize(patch: Patchlike, *, compact: bool = False) -> Dict[str, Any]:
    """The standard form (end or corner weights 1) and the map that gives
    it: ``{"exact", "reparameterization", "patch"}``. The patch is an
    object when its numbers are rational, else a dict with ``Algebraic``
    numbers."""
    args = ["standardize", "-"] + (["--compact"] if compact else [])
    return run_json(args, _to_json(patch))


def elevate(patch: Patchlike, by: Union[int, Tuple[int, int]] = 1) -> Patchlike:
    """The same curve or rect patch with its degree raised by ``by``
    (``(r, s)`` for a rect).

    >>> import exact_bezier as eb
    >>> eb.elevate(eb.Curve([[0], [3]]), 2).points
    [[Fraction(0, 1)], [Fraction(1, 1)], [Fraction(2, 1)], [Fraction(3, 1)]]
    """
    text = ",".join(str(int(b)) for b in by) if isinstance(by, (tuple, list)) else str(int(by))
    return run_json(["elevate", "-", f"--by={text}"], _to_json(patch))


def reduce(curve: Curve, method: str = "farin", *, tol: Optional[float] = None) -> Dict[str, Any]:
    """Lower a curve's degree by one (``method``: ``forrest``, ``farin``,
    ``lsq``, ``exact``); the command line's result dict (``curve`` is
    ``None`` when ``exact`` finds the curve irreducible)."""
    args = ["reduce", "-", f"--method={method}"]
    if tol is not None:
        args.append(f"--tol={tol!r}")
    return run_json(args, _to_json(curve))


def convert(
    obj: Any,
    to: str,
    *,
    split: Optional[Sequence[Number]] = None,
    degenerate: bool = False,
    normalize: bool = False,
) -> List[Any]:
    """Convert: ``to="tri"`` (a rect into two tris), ``"rect"`` (a tri
    into three rects, or one degenerate), ``"rational"`` (a trig patch into
    its rational Bézier form), ``"bezier"`` (NURBS or STEP into Bézier
    pieces). Always a list."""
    args = ["convert", "-", f"--to={to}"]
    if split is not None:
        args.append("--split=" + ",".join(exact_text(x) for x in split))
    if degenerate:
        args.append("--degenerate")
    if normalize:
        args.append("--normalize")
    out = run_json(args, _to_json(obj))
    return out if isinstance(out, list) else [out]


def join(first: Curve, second: Curve, *, tol: Optional[float] = None) -> Dict[str, Any]:
    """G0/G1/G2 verdicts of the join of ``first``'s end (t = 1) to
    ``second``'s start (t = 0)."""
    with _temp_json(second) as path:
        args = ["join", "-", path] + ([f"--tol={tol!r}"] if tol is not None else [])
        return run_json(args, _to_json(first))


def is_circle(curve: Curve) -> Dict[str, Any]:
    """Whether a curve lies on a circle: exact centre and radius², or the
    reason it does not."""
    return run_json(["is-circle", "-"], _to_json(curve))


def arc(
    cos_half: Any,
    lam: Any,
    points: Sequence[Sequence[Any]],
    *,
    direction: Optional[Sequence[Any]] = None,
) -> Any:
    """A circular arc as a standard-form rational cubic (``exact-bezier
    arc``): ``cos_half`` is cos(θ/2), ``lam`` the family parameter λ,
    ``points`` the quadratic arc's control points. Numbers may be
    algebraic (``"sqrt(2)/2"``); the result is a dict with ``Algebraic``
    numbers, or a ``Curve`` when every number is rational.
    """
    pts = ";".join(",".join(exact_text(x) for x in p) for p in points)
    args = ["arc", f"--cos-half={exact_text(cos_half)}", f"--lambda={exact_text(lam)}", f"--points={pts}"]
    if direction is not None:
        args.append("--direction=" + ",".join(exact_text(x) for x in direction))
    return run_json(args)


def intersect(a: Curve, b: Optional[Curve] = None, *, filtered: bool = False) -> Dict[str, Any]:
    """Exact intersections of two curves, or the self-intersections of
    one: ``{"intersections": [...], "overlaps": [...]}`` with algebraic
    parameters and points.

    >>> import exact_bezier as eb
    >>> r = eb.intersect(eb.Curve([[0, 0], [2, 2]]), eb.Curve([[0, 2], [2, 0]]))
    >>> r["intersections"][0]["point"] == [1, 1]
    True
    """
    extra = ["--filtered"] if filtered else []
    if b is None:
        return run_json(["intersect", "-"] + extra, _to_json(a))
    with _temp_json(b) as path:
        return run_json(["intersect", "-", path] + extra, _to_json(a))


def audit(model: Any, *, summary: bool = False) -> Dict[str, Any]:
    """Exact audit of a model (patches, or JSON/NURBS/STEP text): shared
    edges with G0/G1/G2 verdicts, open and degenerate edges, duplicates."""
    args = ["audit", "-"] + (["--summary"] if summary else [])
    return run_json(args, json_input(model))


def read_step(text: Union[str, bytes, os.PathLike]) -> "BrepModel":
    """The B-rep of a STEP file (its text, or a path) as a
    :class:`BrepModel`: every face and edge with its exact pieces, as
    ``convert --to bezier`` gives them."""
    from .objects import BrepModel

    return BrepModel(run_text(["convert", "-", "--to=bezier"], _read_if_path(text)))


def read_nurbs(text: Union[str, bytes, os.PathLike]) -> List[Patchlike]:
    """The rational Bézier pieces of NURBS given as our JSON
    (``nurbs-curve``/``nurbs-surface``) or geomdl's JSON (text, or a path)."""
    return convert(_read_if_path(text), "bezier")


def prove(family: Optional[str] = None, *, deep: bool = False) -> List[Dict[str, Any]]:
    """Run the proofs (``exact-bezier prove --json``): one dict per claim
    (``family``, ``claim``, ``source``, ``verdict``, ``expected``,
    ``detail``, …). ``family`` restricts them to one file of proofs/."""
    args = ["prove", "--json"]
    if family is not None:
        args.append(f"--family={family}")
    if deep:
        args.append("--deep")
    return run_json(args)


def keys(patches: Iterable[Patchlike]) -> Iterator[str]:
    """The canonical key of each patch, lazily (one at a time: the input may
    be a generator over a file larger than memory).

    >>> import exact_bezier as eb
    >>> ks = eb.keys(iter([eb.Curve([[0], [1]]), eb.Curve([[1], [0]])]))
    >>> next(ks) == next(ks)
    True
    """
    for p in patches:
        yield key(p)


@dataclass(frozen=True)
class DedupClass:
    """One class of :func:`dedup`: the common ``key``, the ``representative``
    (the first member) and the indices of the ``members`` in input order."""

    key: str
    representative: Patchlike
    members: List[int]


def dedup(patches: Iterable[Patchlike]) -> Iterator[DedupClass]:
    """Group curves and rect patches into coincidence classes by their
    canonical keys, streaming: the input is read once, keeping one
    representative per class and the member indices; the classes come out
    in the order of their first member, as ``exact-bezier dedup`` numbers
    them.

    >>> import exact_bezier as eb
    >>> cs = [eb.Curve([[0], [1]]), eb.Curve([[0], [2]]), eb.Curve([[1], [0]])]
    >>> [c.members for c in eb.dedup(cs)]
    [[0, 2], [1]]
    """
    classes: Dict[str, DedupClass] = {}
    for i, p in enumerate(patches):
        k = key(p)
        c = classes.get(k)
        if c is None:
            classes[k] = DedupClass(k, p, [i])
        else:
            c.members.append(i)
    yield from classes.values()


def _read_if_path(text: Union[str, bytes, os.PathLike]) -> Union[str, bytes]:
    if isinstance(text, os.PathLike):
        with open(text, "rb") as f:
            return f.read()
    return text


class _temp_json:
    """A temporary file holding a patch's JSON (the command line's second
    input), removed on exit."""

    def __init__(self, obj: Any) -> None:
        self.text = _to_json(obj)

    def __enter__(self) -> str:
        fd, self.path = tempfile.mkstemp(suffix=".json")
        with os.fdopen(fd, "w") as f:
            f.write(self.text)
        return self.path

    def __exit__(self, *exc: Any) -> None:
        os.unlink(self.path)


def mesh(patch: Patchlike, n: int) -> Tuple[Any, Any]:
    """A triangle mesh of a patch on the float path: ``(vertices, faces)``
    as NumPy arrays, the vertices (shape ``(V, dim)``) at the parameters
    ``(i/n, j/n)`` — all ``i, j ≤ n`` for a rect (``2n²`` faces), ``i + j ≤ n``
    for a tri (``n²`` faces) — and the faces as ``int64`` vertex indices,
    shape ``(F, 3)``, counter-clockwise in ``(u, v)``. A curve gives its
    polyline: vertices at ``t = i/n`` and segments of shape ``(n, 2)``.

    >>> import exact_bezier as eb
    >>> v, f = eb.mesh(eb.TriPatch([[[0, 0], [1, 0]], [[0, 1]]]), 2)
    >>> v.shape, f.shape
    ((6, 2), (4, 3))
    """
    import numpy as np

    n = int(n)
    if n < 1:
        raise ValueError(f"mesh needs n ≥ 1, not {n}")
    k = np.arange(n + 1)
    if isinstance(patch, Curve):
        segments = np.column_stack([k[:-1], k[1:]])
        return patch.eval_many(k / n), segments
    if isinstance(patch, TriPatch):
        i, j = np.concatenate([k[: n + 1 - jj] for jj in k]), np.repeat(k, n + 1 - k)
        row_start = np.concatenate([[0], np.cumsum(n + 1 - k)[:-1]])

        def idx(ii: Any, jj: Any) -> Any:
            return row_start[jj] + ii

        lower_j = np.repeat(k[:-1], n - k[:-1])
        lower_i = np.concatenate([k[: n - jj] for jj in k[:-1]])
        up = np.column_stack([idx(lower_i, lower_j), idx(lower_i + 1, lower_j), idx(lower_i, lower_j + 1)])
        inner = lower_i < n - lower_j - 1
        ii, jj = lower_i[inner], lower_j[inner]
        down = np.column_stack([idx(ii + 1, jj), idx(ii + 1, jj + 1), idx(ii, jj + 1)])
        return patch.eval_many(np.column_stack([i, j]) / n), np.concatenate([up, down]).astype(np.int64)
    u, v = np.meshgrid(k, k, indexing="ij")
    a = (u[:-1, :-1] * (n + 1) + v[:-1, :-1]).ravel()
    b, c, d = a + n + 1, a + 1, a + n + 2
    faces = np.concatenate([np.column_stack([a, b, d]), np.column_stack([a, d, c])]).astype(np.int64)
    return patch.eval_many(np.column_stack([u.ravel(), v.ravel()]) / n), faces
