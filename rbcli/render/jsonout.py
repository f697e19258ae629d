"""JSON for scripts: SI numbers, never NaN, the same bytes for the same input."""

from __future__ import annotations

import json
import math
from typing import Any


def jsonable(obj: Any) -> Any:
    """Plain JSON data from results: numpy arrays to lists, -0.0 to 0.0, NaN refused."""
    if hasattr(obj, "to_json"):
        return jsonable(obj.to_json())
    if isinstance(obj, dict):
        return {str(k): jsonable(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [jsonable(v) for v in obj]
    if hasattr(obj, "tolist"):  # numpy arrays and scalars
        return jsonable(obj.tolist())
    if isinstance(obj, bool) or obj is None or isinstance(obj, str):
        return obj
    if isinstance(obj, int):
        return obj
    if isinstance(obj, float):
        if not math.isfinite(obj):
            raise ValueError(f"a result is not a finite number ({obj}); this is a bug")
        return 0.0 if obj == 0.0 else obj
    raise TypeError(f"cannot write {type(obj).__name__} as JSON")


def dumps(obj: Any, *, lines: bool = False) -> str:
    """One JSON document (indented, numeric arrays on one line), or one compact line."""
    data = jsonable(obj)
    if lines:
        return json.dumps(data, ensure_ascii=False, allow_nan=False, separators=(",", ":")) + "\n"
    return _pretty(data, 0) + "\n"


def _flat(v: Any) -> bool:
    """A value short enough to print on one line: a scalar, or a list of (lists of) scalars."""
    if isinstance(v, list):
        return all(not isinstance(x, (dict, list)) or (isinstance(x, list) and _flat(x)) for x in v)
    return not isinstance(v, dict)


def _pretty(v: Any, level: int) -> str:
    if _flat(v):
        return json.dumps(v, ensure_ascii=False, allow_nan=False, separators=(", ", ": "))
    pad = "  " * (level + 1)
    end = "  " * level
    if isinstance(v, dict):
        if not v:
            return "{}"
        items = [f"{pad}{json.dumps(k, ensure_ascii=False)}: {_pretty(x, level + 1)}" for k, x in v.items()]
        return "{\n" + ",\n".join(items) + "\n" + end + "}"
    items = [pad + _pretty(x, level + 1) for x in v]
    return "[\n" + ",\n".join(items) + "\n" + end + "]"
