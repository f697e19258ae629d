"""api.result.jsonable: plain JSON data (json.dumps with allow_nan=False takes it), no -0.0,
tuples and arrays as lists, and inf/NaN refused with the key path that holds them."""

from __future__ import annotations

import math
import warnings

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from rbcli.api import result
from rbcli.errors import NonFiniteResult


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


def _walk(obj, path=()):
    """(path, float) for every float in a tree (numpy values as Python floats)."""
    if isinstance(obj, dict):
        for k, v in obj.items():
            yield from _walk(v, (*path, str(k)))
    elif isinstance(obj, (list, tuple)) or hasattr(obj, "tolist"):
        items = obj.tolist() if hasattr(obj, "tolist") else obj
        if not isinstance(items, (list, tuple)):  # a numpy scalar
            yield path, float(items) if isinstance(items, float) else items
            return
        for i, v in enumerate(items):
            yield from _walk(v, (*path, i))
    elif isinstance(obj, float):
        yield path, obj


@settings(max_examples=500, deadline=None)
@given(TREES)
def test_jsonable_is_plain_json_or_names_the_first_non_finite_number(obj):
    import json

    bad = [(p, x) for p, x in _walk(obj) if isinstance(x, float) and not math.isfinite(x)]
    if bad:
        try:
            result.jsonable(obj)
        except NonFiniteResult as exc:
            where = "".join(f"[{k}]" if isinstance(k, int) else (f".{k}" if i else k)
                            for i, k in enumerate(bad[0][0]))
            assert f"'{where}'" in str(exc) or not where
        else:
            raise AssertionError("a non-finite number was let through")
        return
    data = result.jsonable(obj)
    text = json.dumps(data, allow_nan=False)  # plain JSON: dicts, lists, str, int, float, bool, None
    assert json.loads(text) == data
    assert not any(x == 0.0 and math.copysign(1.0, x) < 0 for _, x in _walk(data))  # no -0.0
    # the same numbers, in the same places (tuples and arrays became lists; keys became
    # strings, the later of two keys that read the same winning, as in a dict)
    assert [x for _, x in _walk(data)] == [x + 0.0 for _, x in _walk(_str_keys(obj)) if isinstance(x, float)]


def _str_keys(obj):
    if isinstance(obj, dict):
        return {str(k): _str_keys(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_str_keys(v) for v in obj]
    return obj
