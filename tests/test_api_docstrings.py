"""Every public function of the Python API documents itself with examples, and the examples
run (issue 22 item 3): each function in ``rbcli.__all__``, each constructor of
``rbcli.parts`` and the methods that build, change and write bodies (``Body.from_parts``,
``replace``, ``moved``, ``to_yaml``, ``PartSpec.replace``, ``BalanceResult.balanced_body``)
has a numpydoc **Examples** section whose doctest passes, run from the repository root (the
examples name files in examples/)."""

from __future__ import annotations

import doctest
import inspect

import pytest

import rbcli
from conftest import ROOT

FUNCTIONS = [n for n in rbcli.__all__ if not n.startswith("_") and inspect.isfunction(getattr(rbcli, n))]


def _documented() -> dict[str, object]:
    from rbcli.api.balance import BalanceResult

    out: dict[str, object] = {n: getattr(rbcli, n) for n in FUNCTIONS}
    out.update({f"parts.{n}": getattr(rbcli.parts, n) for n in rbcli.parts.__all__
                if inspect.isfunction(getattr(rbcli.parts, n))})
    out.update({f"Body.{n}": getattr(rbcli.Body, n) for n in ("from_parts", "replace", "moved", "to_yaml")})
    out["PartSpec.replace"] = rbcli.parts.PartSpec.replace
    out["BalanceResult.balanced_body"] = BalanceResult.balanced_body
    return out


DOCUMENTED = _documented()


def test_the_public_functions_are_the_documented_ones():
    assert {"load", "load_text", "load_data", "inertia", "principal", "balance", "field_balance",
            "precess", "top", "gyrocompass", "rollcheck", "whirl", "report", "report_text",
            "write_report"} <= set(FUNCTIONS)
    assert {f"parts.{s}" for s in ("point", "disk", "mesh", "given", "include")} <= set(DOCUMENTED)


@pytest.mark.parametrize("name", DOCUMENTED)
def test_examples_run(name, monkeypatch):
    monkeypatch.chdir(ROOT)
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "0")
    fn = DOCUMENTED[name]
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
