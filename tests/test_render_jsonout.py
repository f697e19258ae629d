"""rbcli.render.jsonout: the indented document against the straightforward layout (one
``json.dumps`` per one-line value), JSON Lines against ``json.dumps``, NaN and infinity
refused, and every golden JSON document written back byte for byte. Characters a terminal or a
JavaScript reader would act on (C1, DEL, line/paragraph separators, bidirectional controls,
BOM, U+FFFE/U+FFFF) are ``\\uXXXX`` escapes (issue 27): the oracle finds them by Unicode
category and lists, and the document reads back the same."""

from __future__ import annotations

import json
import unicodedata
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rbcli.api.result import jsonable
from rbcli.render.jsonout import dumps


def _flat(v):
    if isinstance(v, list):
        return all(not isinstance(x, (dict, list)) or (isinstance(x, list) and _flat(x)) for x in v)
    return not isinstance(v, dict)


#: the bidirectional controls (Unicode's Bidi_Control property less ALM U+061C, which is text)
BIDI = set("\u200e\u200f\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069")


def _escaped(text: str) -> str:
    """``text`` (encoded JSON) with every control (Cc), line or paragraph separator (Zl, Zp),
    surrogate (Cs), bidirectional control, BOM and U+FFFE/U+FFFF as a \\uXXXX escape."""
    return "".join(f"\\u{ord(c):04x}" if unicodedata.category(c) in ("Cc", "Zl", "Zp", "Cs")
                   or c in BIDI or c in "\ufeff\ufffe\uffff" else c for c in text)


def _oracle(v, level=0):
    if _flat(v):
        return _escaped(json.dumps(v, ensure_ascii=False, allow_nan=False, separators=(", ", ": ")))
    pad, end = "  " * (level + 1), "  " * level
    if isinstance(v, dict):
        if not v:
            return "{}"
        items = [f"{pad}{_escaped(json.dumps(k, ensure_ascii=False))}: {_oracle(x, level + 1)}"
                 for k, x in v.items()]
        return "{\n" + ",\n".join(items) + "\n" + end + "}"
    return "[\n" + ",\n".join(pad + _oracle(x, level + 1) for x in v) + "\n" + end + "]"


# ----------------------------------------------------------------------------- strategies

FLOATS = st.one_of(st.floats(allow_nan=False, allow_infinity=False),
                   st.sampled_from([0.0, -0.0, 1e16, -1e16, 5e-324, 1e-7, 1e22, 1.7976931348623157e308, 0.1]))
TEXT = st.one_of(st.text(max_size=8),
                 st.sampled_from(["", "%", "%s", "%%", "a\"b", "back\\slash", "tab\t", "\n", "\x00", "é", "\u2028",
                                  "\ud7ff", "😀", "%(x)s", "\x85", "\x7f", "\u202e",
                                  "\u2066", "\ufeff", "\ufffe", "\u200f"]))
SCALARS = st.one_of(st.none(), st.booleans(), st.integers(), FLOATS, TEXT)
DOCS = st.recursive(SCALARS, lambda kids: st.one_of(st.lists(kids, max_size=4),
                                                    st.dictionaries(TEXT, kids, max_size=4)),
                    max_leaves=30)


# ----------------------------------------------------------------------------------- tests


@settings(max_examples=500, deadline=None)
@given(DOCS)
def test_indented_json_is_the_oracles(doc):
    data = jsonable(doc)  # the one check (no -0.0, no NaN), as results give their JSON
    assert dumps(data) == _oracle(data) + "\n"
    assert json.loads(dumps(data)) == doc


@settings(max_examples=300, deadline=None)
@given(DOCS)
def test_json_lines_are_compact_json(doc):
    data = jsonable(doc)
    assert dumps(data, lines=True) == _escaped(json.dumps(data, ensure_ascii=False, separators=(",", ":"))) + "\n"
    assert json.loads(dumps(data, lines=True)) == doc


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), {"a": [1.0, -float("inf")]}])
def test_not_finite_is_refused_even_unchecked(bad):
    with pytest.raises(ValueError):
        dumps(bad)
    with pytest.raises(ValueError):
        dumps(bad, lines=True)


def test_every_golden_json_document_is_the_oracles():
    cases = Path(__file__).resolve().parent / "cases"
    seen = 0
    for out in sorted(cases.glob("*/*.out")):
        text = out.read_text(encoding="utf-8")
        if not text.startswith("{\n"):
            continue  # tables, CSV, JSON Lines
        data = json.loads(text)
        assert dumps(data) == _oracle(data) + "\n" == text, out
        seen += 1
    assert seen > 20
