"""rbcli.render.jsonout: the indented document is the same bytes as the layouts it replaced,
kept here as oracles: the straightforward json.dumps-per-value layout, and the recursion
that wrote every value in turn (``_old_pretty``, the module as it was before the rows of a
list of mappings were laid out column by column). Generated documents, lists of rows that
take the column path (and rows that must leave it), data given ``plain`` that jsonable
would not let through (-0.0, tuples, non-str keys, NaN: the same text, or the same error),
and every golden JSON document."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from conftest import sample
from hypothesis import given, settings
from hypothesis import strategies as st

from rbcli.api.result import jsonable
from rbcli.render.jsonout import dumps


def _flat(v):
    if isinstance(v, list):
        return all(not isinstance(x, (dict, list)) or (isinstance(x, list) and _flat(x)) for x in v)
    return not isinstance(v, dict)


def _oracle(v, level=0):
    if _flat(v):
        return json.dumps(v, ensure_ascii=False, allow_nan=False, separators=(", ", ": "))
    pad, end = "  " * (level + 1), "  " * level
    if isinstance(v, dict):
        if not v:
            return "{}"
        items = [f"{pad}{json.dumps(k, ensure_ascii=False)}: {_oracle(x, level + 1)}" for k, x in v.items()]
        return "{\n" + ",\n".join(items) + "\n" + end + "}"
    return "[\n" + ",\n".join(pad + _oracle(x, level + 1) for x in v) + "\n" + end + "]"


# ----------------------------------------------------------- the module as it was (oracle)

_FLAT = json.JSONEncoder(ensure_ascii=False, allow_nan=False, separators=(", ", ": "))
_flat_encode = _FLAT.encode
_quote = json.encoder.encode_basestring


def _old_scalar(v):
    t = type(v)
    if t is str:
        return _quote(v)
    if t is float and math.isfinite(v):
        return float.__repr__(v)
    if t is int:
        return int.__repr__(v)
    return None


def _old_pretty(v, level=0):
    text = _old_scalar(v)
    if text is not None:
        return text
    if _flat(v):
        return _flat_encode(v)
    pad = "  " * (level + 1)
    end = "  " * level
    if isinstance(v, dict):
        if not v:
            return "{}"
        items = [f"{pad}{_quote(k) if type(k) is str else _flat_encode(k)}: {_old_pretty(x, level + 1)}"
                 for k, x in v.items()]
        return "{\n" + ",\n".join(items) + "\n" + end + "}"
    items = [pad + _old_pretty(x, level + 1) for x in v]
    return "[\n" + ",\n".join(items) + "\n" + end + "]"


def _old_or_error(data):
    try:
        return _old_pretty(data) + "\n"
    except Exception as exc:  # noqa: BLE001 - the error itself is what is compared
        return (type(exc), str(exc))


def _new_or_error(data):
    try:
        return dumps(data, plain=True)
    except Exception as exc:  # noqa: BLE001
        return (type(exc), str(exc))


# ----------------------------------------------------------------------------- strategies

FLOATS = st.one_of(st.floats(allow_nan=False, allow_infinity=False),
                   st.sampled_from([0.0, -0.0, 1e16, -1e16, 5e-324, 1e-7, 1e22, 1.7976931348623157e308, 0.1]))
TEXT = st.one_of(st.text(max_size=8),
                 st.sampled_from(["", "%", "%s", "%%", "a\"b", "back\\slash", "tab\t", "\n", "\x00", "é", "\u2028",
                                  "\ud7ff", "😀", "%(x)s"]))
SCALARS = st.one_of(st.none(), st.booleans(), st.integers(), FLOATS, TEXT)
DOCS = st.recursive(SCALARS, lambda kids: st.one_of(st.lists(kids, max_size=4),
                                                    st.dictionaries(TEXT, kids, max_size=4)),
                    max_leaves=30)

#: values of one column: one kind (the column path), or mixed ones (it must leave it)
COLUMN_KINDS = [st.none(), st.booleans(), st.integers(), FLOATS, TEXT,
                st.lists(FLOATS, min_size=3, max_size=3), st.lists(st.integers(), max_size=0),
                st.lists(st.lists(FLOATS, min_size=2, max_size=2), min_size=2, max_size=2),
                st.lists(TEXT, min_size=1, max_size=1), st.lists(SCALARS, max_size=3), DOCS]


@st.composite
def ROWS(draw):
    """A list of mappings, most with the same keys (a few signatures), with values of one
    kind a column or not, and now and then another item (a scalar, a list, {})."""
    signatures = draw(st.lists(st.lists(TEXT, min_size=1, max_size=5, unique=True), min_size=1, max_size=3))
    kinds = {k: draw(st.sampled_from(COLUMN_KINDS)) for sig in signatures for k in sig}
    rows = []
    for _ in range(draw(st.integers(2, 12))):
        pick = draw(st.integers(0, len(signatures) + 1))
        if pick < len(signatures):
            sig = signatures[pick]
            rows.append({k: draw(kinds[k] if draw(st.integers(0, 9)) else DOCS) for k in sig})
        elif draw(st.booleans()):
            rows.append(draw(st.sampled_from([{}, [], 1.5, "x", None, [{"a": 1}]])))
        else:
            rows.append(draw(st.dictionaries(TEXT, DOCS, max_size=3)))
    return rows


#: a document as a result's to_json() makes it: a few values, then many rows
RESULTS = st.builds(lambda head, rows: {**head, "parts": rows},
                    st.dictionaries(TEXT, DOCS, max_size=3), ROWS())

#: data jsonable would not let through, given ``plain``
ODD = st.one_of(st.floats(), st.tuples(st.floats()), st.dictionaries(st.integers(), st.floats(), max_size=2),
                st.builds(lambda x: [x], st.floats()))
ODD_ROWS = st.lists(st.dictionaries(st.sampled_from(["a", "b", 1, True, 1.0]), st.one_of(ODD, SCALARS),
                                    min_size=1, max_size=3), min_size=2, max_size=8)


# ----------------------------------------------------------------------------------- tests


@pytest.mark.sampled
@settings(max_examples=sample(50, 500), deadline=None)
@given(DOCS)
def test_indented_json_is_the_oracles(doc):
    assert dumps(doc) == _oracle(jsonable(doc)) + "\n"  # both after the one check (no -0.0)
    assert dumps(doc) == _old_pretty(jsonable(doc)) + "\n"
    assert json.loads(dumps(doc)) == doc


@pytest.mark.sampled
@settings(max_examples=sample(50, 500), deadline=None)
@given(st.one_of(ROWS(), RESULTS, st.lists(RESULTS, min_size=2, max_size=3)))
def test_rows_are_the_oracles(doc):
    data = jsonable(doc)
    assert dumps(data, plain=True) == _old_pretty(data) + "\n" == _oracle(data) + "\n"
    # given plain, as it is (-0.0 kept): the old recursion's text
    assert dumps(doc, plain=True) == _old_pretty(doc) + "\n"


@pytest.mark.sampled
@settings(max_examples=sample(40, 400), deadline=None)
@given(st.one_of(ODD_ROWS, st.builds(lambda rows: {"parts": rows}, ODD_ROWS)))
def test_data_jsonable_would_refuse_gives_the_old_text_or_error(doc):
    assert _new_or_error(doc) == _old_or_error(doc)


@pytest.mark.parametrize("doc", [
    [{"a": 1.0}, {"a": float("inf")}],                            # not finite: ValueError
    [{"a": [1.0, 2.0]}, {"a": [3.0, float("nan")]}],
    [{"a": 1.0, "b": object()}, {"a": float("nan"), "b": 2}],   # the first error in document order
    [{"a": 10 ** 5000}, {"a": 1}],                                # int too long for str()
    [{"a": (1, {"b": 2})}, {"a": (3, 4)}],                        # tuples: one line, as before
    [{1: "x"}, {True: "y"}, {1.0: "z"}],                          # keys equal but written differently
    [{"%s": 1, "%%": 2.5, "%(a)s": "%d"}, {"%s": 3, "%%": -0.0, "%(a)s": "%"}],
    [{"a": None, "b": [], "c": {}}, {"a": None, "b": [], "c": {}}],
    [{"a": []}, {"a": []}],                                       # a template without a slot
])
def test_edge_rows_give_the_old_text_or_error(doc):
    assert _new_or_error(doc) == _old_or_error(doc)
    assert _new_or_error({"parts": doc}) == _old_or_error({"parts": doc})


def test_deep_rows_give_the_old_error():
    deep: list = [{"a": 1}, {"a": 1}]
    for _ in range(3000):
        deep = [{"a": deep}, {"a": 1}]
    assert _new_or_error(deep)[0] is RecursionError is _old_or_error(deep)[0]


def test_every_golden_json_document_is_the_oracles():
    cases = Path(__file__).resolve().parent / "cases"
    seen = 0
    for out in sorted(cases.glob("*/*.out")):
        text = out.read_text(encoding="utf-8")
        if not text.startswith("{\n"):
            continue  # tables, CSV, JSON Lines
        data = json.loads(text)
        assert dumps(data, plain=True) == _old_pretty(data) + "\n" == text, out
        seen += 1
    assert seen > 20


@pytest.mark.sampled
@settings(max_examples=sample(30, 300), deadline=None)
@given(DOCS)
def test_plain_dumps_of_jsonable_data_is_dumps(doc):
    # the commands pass a result's to_json() (jsonable's result) with plain=True
    data = jsonable(doc)
    assert jsonable(data) == data
    assert dumps(data, plain=True) == dumps(doc)
    assert dumps(data, lines=True, plain=True) == dumps(doc, lines=True)


def test_plain_dumps_of_the_examples_results_is_dumps():
    import rbcli

    for path in sorted((Path(__file__).resolve().parent.parent / "examples").glob("*.yaml")):
        body = rbcli.load(str(path))
        for res in (rbcli.inertia(body), rbcli.principal(body)):
            data = res.to_json()
            for lines in (False, True):
                assert dumps(data, lines=lines, plain=True) == dumps(data, lines=lines), path
            assert dumps(data, plain=True) == _old_pretty(data) + "\n", path
