"""rbcli.render.jsonout: the indented document is the same bytes as the straightforward
json.dumps-per-value layout it replaced (kept here as the oracle), on generated documents
(both after rbcli.api.result.jsonable, which dumps applies: no negative zeros)."""

from __future__ import annotations

import json

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


SCALARS = st.one_of(st.none(), st.booleans(), st.integers(), st.floats(allow_nan=False, allow_infinity=False),
                    st.text(max_size=8))
DOCS = st.recursive(SCALARS, lambda kids: st.one_of(st.lists(kids, max_size=4),
                                                    st.dictionaries(st.text(max_size=5), kids, max_size=4)),
                    max_leaves=30)


@settings(max_examples=500, deadline=None)
@given(DOCS)
def test_indented_json_is_the_oracles(doc):
    assert dumps(doc) == _oracle(jsonable(doc)) + "\n"  # both after the one check (no -0.0)
    assert json.loads(dumps(doc)) == doc


@settings(max_examples=300, deadline=None)
@given(DOCS)
def test_plain_dumps_of_jsonable_data_is_dumps(doc):
    # the commands pass a result's to_json() (jsonable's result) with plain=True
    data = jsonable(doc)
    assert jsonable(data) == data
    assert dumps(data, plain=True) == dumps(doc)
    assert dumps(data, lines=True, plain=True) == dumps(doc, lines=True)


def test_plain_dumps_of_the_examples_results_is_dumps():
    from pathlib import Path

    import rbcli

    for path in sorted((Path(__file__).resolve().parent.parent / "examples").glob("*.yaml")):
        body = rbcli.load(str(path))
        for res in (rbcli.inertia(body), rbcli.principal(body)):
            data = res.to_json()
            for lines in (False, True):
                assert dumps(data, lines=lines, plain=True) == dumps(data, lines=lines), path
