"""Every public function of the Python API documents itself with examples, and the examples
run (issue 22 item 3): each function in ``rbcli.__all__`` has a numpydoc **Examples** section
whose doctest passes, run from the repository root (the examples name files in examples/)."""

from __future__ import annotations

import doctest
import inspect

import pytest

import rbcli
from conftest import ROOT

FUNCTIONS = [n for n in rbcli.__all__ if not n.startswith("_") and inspect.isfunction(getattr(rbcli, n))]


def test_the_public_functions_are_the_documented_ones():
    assert {"load", "load_text", "inertia", "principal", "balance", "field_balance", "precess",
            "top", "gyrocompass", "rollcheck", "whirl", "report", "report_text",
            "write_report"} <= set(FUNCTIONS)


@pytest.mark.parametrize("name", FUNCTIONS)
def test_examples_run(name, monkeypatch):
    monkeypatch.chdir(ROOT)
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "0")
    fn = getattr(rbcli, name)
    doc = inspect.getdoc(fn) or ""
    assert "Examples\n--------" in doc, f"rbcli.{name} has no Examples section"
    tests = doctest.DocTestFinder(recurse=False).find(fn, name, globs={})
    examples = [ex for t in tests for ex in t.examples]
    assert examples, f"rbcli.{name}: no example to run"
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    for t in tests:
        runner.run(t)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, f"rbcli.{name}: {result.failed} example(s) failed (run with -s to see them)"
