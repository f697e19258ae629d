"""JSON for scripts: SI numbers, never NaN, the same bytes for the same input."""

from __future__ import annotations

import json
import math
from typing import Any

from rbcli.api.result import jsonable  # noqa: F401  (the one finiteness check)


#: the encoder of JSON Lines, made once (json.dumps with these arguments makes one per call)
_LINE = json.JSONEncoder(ensure_ascii=False, allow_nan=False, separators=(",", ":"))


def dumps(obj: Any, *, lines: bool = False) -> str:
    """One JSON document (indented, numeric arrays on one line), or one compact line."""
    data = jsonable(obj)
    if lines:
        return _LINE.encode(data) + "\n"
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
