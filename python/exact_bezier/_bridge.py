"""The command line in-process: arguments in, parsed JSON out.

Every function of :mod:`exact_bezier.operations` runs one subcommand of
``exact-bezier`` through the native ``run`` (the command line's own entry
point, no process), so options, outputs, limits and one-line error messages
are the binary's. This module turns its exit code and message into the
exception hierarchy, and its JSON into Python values: exact numbers written
as text (``"1/3"``, ``"sqrt(2)/2"``) become ``Fraction`` and ``Algebraic``,
curves and patches become objects.
"""

from __future__ import annotations

import contextlib
import json
import re
from fractions import Fraction
from typing import Any, Iterator, List, Optional, Sequence, Union

from . import _native
from ._native import (
    Algebraic,
    Curve,
    DomainError,
    ExactBezierError,
    LimitError,
    ParseError,
    RectPatch,
    TriPatch,
)

Patchlike = Union[Curve, RectPatch, TriPatch]

_RATIONAL = re.compile(r"-?\d+(/\d+)?\Z")
_ALGEBRAIC_CALLS = ("sqrt(", "cbrt(", "root(", "CRootOf(", "Rational(")
_KINDS = {"curve": Curve, "rect": RectPatch, "tri": TriPatch}

# Exit code of ``run`` for a panic caught at the boundary.
_PANIC = 70


def error_for(message: str) -> ExactBezierError:
    """The exception of the hierarchy for a command-line error message
    (the text after ``error: ``), classified as the library's error kinds
    print themselves."""
    if message.startswith("over a limit:") or " is over the limit of " in message:
        return LimitError(message)
    if message.startswith(("malformed input:", "not an exact number:", "not a finite number:")):
        return ParseError(message)
    if message.startswith(("parameter out of domain:", "point at infinity:")):
        return DomainError(message)
    return ExactBezierError(message)


def run_text(args: Sequence[str], stdin: Union[str, bytes] = b"") -> str:
    """Standard output of ``exact-bezier ARGS…`` with ``stdin`` as standard
    input; raises the hierarchy's exception on exit code 2 (or a caught
    panic). Exit codes 1 and 3 (a result written, with a verdict in it)
    return the output."""
    data = stdin.encode() if isinstance(stdin, str) else bytes(stdin)
    code, out, err, _work = _native.run(list(args), data)
    if code in (0, 1, 3):
        return out
    message = err.strip()
    if message.startswith("error: "):
        message = message[len("error: "):]
    raise error_for(message or f"exact-bezier exited with code {code}")


def run_json(args: Sequence[str], stdin: Union[str, bytes] = b"") -> Any:
    """:func:`run_text`, its output read as one JSON document (or a list
    of the documents of JSON Lines output), converted by :func:`to_python`."""
    text = run_text(args, stdin).strip()
    try:
        value = json.loads(text)
    except json.JSONDecodeError:
        value = [json.loads(line) for line in text.splitlines() if line.strip()]
    return to_python(value)


def number(text: str) -> Union[Fraction, Algebraic, str]:
    """A number written as text in an output: ``Fraction`` for ``p/q`` or an
    integer, ``Algebraic`` for a radical or ``CRootOf`` expression; other
    text is returned unchanged."""
    if _RATIONAL.match(text):
        return Fraction(text)
    if any(call in text for call in _ALGEBRAIC_CALLS):
        try:
            return Algebraic(text)
        except ExactBezierError:
            return text
    return text


def to_python(value: Any) -> Any:
    """A JSON value of an output as Python values: numbers written as text
    become ``Fraction``/``Algebraic`` (JSON integers stay ``int``, floats
    (``approx`` fields) stay ``float``), and curves and patches with
    rational numbers become ``Curve``/``RectPatch``/``TriPatch`` objects
    (with algebraic numbers they stay dicts of ``Algebraic`` values)."""
    if isinstance(value, dict):
        cls = _KINDS.get(value.get("kind", ""))
        if cls is not None and "points" in value and not _has_algebraic(value):
            return cls.from_json(json.dumps(_patch_fields(value)))
        return {k: to_python(v) for k, v in value.items()}
    if isinstance(value, list):
        return [to_python(v) for v in value]
    if isinstance(value, str):
        return number(value)
    return value


def _patch_fields(value: dict) -> dict:
    """The fields of a patch object the patch classes read (an output may
    add others, such as ``origin`` or ``valid``)."""
    return {k: value[k] for k in ("kind", "degree", "points", "weights") if k in value}


def _has_algebraic(value: Any) -> bool:
    if isinstance(value, dict):
        return any(_has_algebraic(v) for v in value.values())
    if isinstance(value, list):
        return any(_has_algebraic(v) for v in value)
    return isinstance(value, str) and any(call in value for call in _ALGEBRAIC_CALLS)


def exact_text(x: Any) -> str:
    """A number as the command line's exact text: ``int``, ``Fraction``,
    ``Algebraic`` or a string; a ``float`` is refused (``TypeError``)."""
    if isinstance(x, bool):
        raise TypeError(f"{x!r} is a bool, not a number")
    if isinstance(x, float):
        raise TypeError(
            f"the float {x!r} is not an exact number: pass an int, a fractions.Fraction "
            f"or an exact string such as {repr(repr(x))}"
        )
    if isinstance(x, Fraction):
        return f"{x.numerator}/{x.denominator}"
    if isinstance(x, (int, str, Algebraic)):
        return str(x)
    if hasattr(x, "numerator") and hasattr(x, "denominator"):
        return f"{int(x.numerator)}/{int(x.denominator)}"
    raise TypeError(f"expected an exact number, found {type(x).__name__}")


def json_input(items: Any) -> str:
    """Patches (one, or an iterable) or JSON text, as the command line's
    input text: a JSON array for several."""
    if isinstance(items, (str, bytes)):
        return items.decode() if isinstance(items, bytes) else items
    if hasattr(items, "to_json"):
        return items.to_json()
    return "[" + ",".join(p.to_json() for p in items) + "]"


@contextlib.contextmanager
def limits(
    max_digits: Optional[int] = None,
    max_input_bytes: Optional[int] = None,
    max_work: Optional[int] = None,
) -> Iterator[None]:
    """Run the block under other resource limits (docs/limits.md), on this
    thread: the command line's ``--max-digits``, ``--max-input-bytes`` and
    ``--max-work``. Omitted ones keep their current values; the previous
    limits come back on exit.

    >>> import exact_bezier as eb
    >>> with eb.limits(max_digits=5):
    ...     eb.Curve([["123456"]])
    Traceback (most recent call last):
    ...
    exact_bezier.LimitError: over a limit: a number of 6 digits is over the limit of 5 digits (raise it with --max-digits)
    """
    old = _native.get_limits()
    new = [old[0] if max_digits is None else max_digits,
           old[1] if max_input_bytes is None else max_input_bytes,
           old[2] if max_work is None else max_work]
    for name, v in zip(("max_digits", "max_input_bytes", "max_work"), new):
        if not isinstance(v, int) or isinstance(v, bool) or v < 0:
            raise TypeError(f"{name} must be a non-negative int, not {v!r}")
    _native.set_limits(*new)
    try:
        yield
    finally:
        _native.set_limits(*old)


def current_limits() -> dict:
    """The limits in force on this thread, as a dict."""
    d, b, w = _native.get_limits()
    return {"max_digits": d, "max_input_bytes": b, "max_work": w}


def as_fractions(xs: List[Any]) -> List[Fraction]:
    """A list of exact rational outputs (``int`` or ``Fraction``) as
    ``Fraction`` values."""
    return [Fraction(x) if isinstance(x, int) else x for x in xs]
