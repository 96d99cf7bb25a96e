"""Every ```python block of docs/python.md runs, and the package's
docstring examples pass."""

import doctest
import pathlib
import re

import pytest

import exact_bezier
import exact_bezier._bridge
import exact_bezier.objects
import exact_bezier.operations
import exact_bezier.symbolic

DOC = pathlib.Path(__file__).resolve().parents[2] / "docs" / "python.md"
BLOCKS = re.findall(r"```python\n(.*?)```", DOC.read_text(encoding="utf-8"), re.S)


def test_the_page_has_examples():
    assert len(BLOCKS) >= 5


@pytest.mark.parametrize("k", range(len(BLOCKS)))
def test_doc_example_runs(k, monkeypatch):
    if "import sympy" in BLOCKS[k]:
        pytest.importorskip("sympy", reason="this example of the page needs SymPy")
    monkeypatch.chdir(DOC.parents[1])  # the examples name files from the repository root
    exec(compile(BLOCKS[k], f"{DOC.name}[block {k}]", "exec"), {})


MODULES = [
    exact_bezier,
    exact_bezier._native,
    exact_bezier._bridge,
    exact_bezier.operations,
    exact_bezier.objects,
    exact_bezier.symbolic,
]


@pytest.mark.parametrize("module", MODULES, ids=lambda m: m.__name__)
def test_docstring_examples(module):
    if module is exact_bezier.symbolic:
        pytest.importorskip("sympy", reason="the SymPy examples need SymPy")
    failed, tried = doctest.testmod(module, raise_on_error=False)
    assert tried >= 1 and failed == 0
