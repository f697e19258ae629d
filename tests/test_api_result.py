"""api.result.jsonable's fast paths give what its general definition gives (issue 16)."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from conftest import sample
from hypothesis import given, settings
from hypothesis import strategies as st

from rbcli.api import result
from rbcli.errors import NonFiniteResult


def reference(obj):
    """jsonable as it was written before the fast paths: the definition."""
    if hasattr(obj, "to_json"):
        return reference(obj.to_json())
    if isinstance(obj, dict):
        out = {}
        for k, v in obj.items():
            try:
                out[str(k)] = reference(v)
            except result._NonFinite as exc:
                exc.path.insert(0, str(k))
                raise
        return out
    if isinstance(obj, (list, tuple)):
        out_list = []
        for i, v in enumerate(obj):
            try:
                out_list.append(reference(v))
            except result._NonFinite as exc:
                exc.path.insert(0, i)
                raise
        return out_list
    if hasattr(obj, "tolist"):
        return reference(obj.tolist())
    if isinstance(obj, bool) or obj is None or isinstance(obj, (str, int)):
        return obj
    if isinstance(obj, float):
        if not math.isfinite(obj):
            raise result._NonFinite(obj)
        return 0.0 if obj == 0.0 else obj
    raise TypeError(f"cannot write {type(obj).__name__} as JSON")


def _array(values, dtype):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # float32 overflow to inf: wanted here
        return np.array(values, dtype=dtype)


FLOATS = st.floats() | st.sampled_from([0.0, -0.0, 5e-324, -1e308, math.inf, -math.inf, math.nan])
SCALARS = FLOATS | st.integers() | st.booleans() | st.none() | st.text(max_size=3) | FLOATS.map(np.float64)
ARRAYS = (st.lists(FLOATS, max_size=100).map(lambda v: _array(v, float))  # small and large (bulk check)
          | st.lists(FLOATS, max_size=70).map(lambda v: _array(v, np.float32))
          | st.lists(FLOATS, min_size=3, max_size=90).map(lambda v: _array(v[: len(v) // 3 * 3], float).reshape(-1, 3))
          | st.lists(st.integers(-9, 9), max_size=5).map(lambda v: np.array(v, dtype=int)))
TREES = st.recursive(SCALARS | ARRAYS, lambda inner: st.lists(inner, max_size=4)
                     | st.lists(inner, max_size=3).map(tuple)
                     | st.dictionaries(st.text(max_size=2) | st.integers(0, 3), inner, max_size=4),
                     max_leaves=20)


def _outcome(fn, obj):
    try:
        out = fn(obj)
    except NonFiniteResult as exc:
        return ("error", str(exc))
    return ("ok", repr(out))  # repr: -0.0 and 0.0 differ, int and float differ


@pytest.mark.sampled
@settings(max_examples=sample(100, 800), deadline=None)
@given(TREES)
def test_jsonable_is_its_definition(obj):
    assert _outcome(result.jsonable, obj) == _outcome(reference, obj)


# api.massprops converts the "parts" rows (100 000 for a large body) in its own loop: the
# same data, or the same error, as jsonable of the whole document.
ROW_VALUES = (FLOATS | st.integers() | st.booleans() | st.text(max_size=3) | FLOATS.map(np.float64)
              | st.lists(FLOATS, min_size=3, max_size=3).map(lambda v: _array(v, float))
              | st.lists(FLOATS, min_size=3, max_size=3).map(lambda v: _array(v, np.float32))
              | st.lists(FLOATS, min_size=4, max_size=4).map(lambda v: _array(v, float).reshape(2, 2))
              | st.lists(FLOATS, max_size=2).map(lambda v: _array(v, float)))
ROWS = st.lists(st.dictionaries(st.sampled_from(["name", "shape", "mass", "com", "subtract"]), ROW_VALUES,
                                min_size=1, max_size=5), max_size=6).map(tuple)


@pytest.mark.sampled
@settings(max_examples=sample(60, 500), deadline=None)
@given(ROWS)
def test_parts_rows_are_jsonable(rows):
    from rbcli.api.massprops import _with_parts

    head = {"mass": 1.0, "com": np.array([-0.0, 1.0, 2.0])}
    assert (_outcome(lambda r: _with_parts(head, r), rows)
            == _outcome(reference, {**head, "parts": list(rows)}))
