"""Every ```python block of docs/python.md runs, and the package's
docstring examples pass."""

import doctest
import pathlib
import re

import pytest

import exact_bezier

DOC = pathlib.Path(__file__).resolve().parents[2] / "docs" / "python.md"
BLOCKS = re.findall(r"```python\n(.*?)```", DOC.read_text(encoding="utf-8"), re.S)


def test_the_page_has_examples():
    assert len(BLOCKS) >= 5


@pytest.mark.parametrize("k", range(len(BLOCKS)))
def test_doc_example_runs(k):
    exec(compile(BLOCKS[k], f"{DOC.name}[block {k}]", "exec"), {})


@pytest.mark.parametrize("module", [exact_bezier, exact_bezier._native])
def test_docstring_examples(module):
    failed, tried = doctest.testmod(module, raise_on_error=False)
    assert tried >= 3 and failed == 0
