"""JSON for scripts: SI numbers, never NaN, the same bytes for the same input.

:func:`dumps` lays out data that is JSON already (a result's ``to_json()``, which is where
numbers are checked finite: :func:`rbcli.api.result.jsonable`). ``json.dumps`` refuses NaN
and infinity here too (``allow_nan=False``), so nothing else can slip through.

Strings are UTF-8 text; what could reorder or forge what a terminal shows is written as
``\\uXXXX`` escapes (:func:`rbcli.render.safe.json_escape`), which read back the same.
"""

from __future__ import annotations

import json
from typing import Any

from rbcli.render.safe import json_escape

__all__ = ["dumps"]

#: the encoder of JSON Lines, and of one-line values inside the indented document (no
#: check for circular references: the data is a tree, made by jsonable or a to_json())
_LINE = json.JSONEncoder(ensure_ascii=False, allow_nan=False, separators=(",", ":"), check_circular=False)
_FLAT = json.JSONEncoder(ensure_ascii=False, allow_nan=False, separators=(", ", ": "), check_circular=False)


def dumps(data: Any, *, lines: bool = False) -> str:
    """One JSON document (indented, numeric arrays on one line), or one compact line.

    The indented layout: a mapping, or a list holding a mapping or a list that is not
    flat, has one item a line, indented by two spaces a level; every other value (a
    scalar, a list of scalars or of such lists, an empty mapping) is on one line as
    ``json.dumps(v, ensure_ascii=False, separators=(", ", ": "))`` writes it.
    """
    if lines:
        return json_escape(_LINE.encode(data)) + "\n"
    return json_escape(_pretty(data, 0)) + "\n"


def _flat(v: Any) -> bool:
    """A value short enough to print on one line: a scalar, or a list of (lists of) scalars."""
    if isinstance(v, list):
        return all(not isinstance(x, (dict, list)) or (isinstance(x, list) and _flat(x)) for x in v)
    return not isinstance(v, dict)


def _pretty(v: Any, level: int) -> str:
    if _flat(v):
        return _FLAT.encode(v)
    pad = "  " * (level + 1)
    end = "  " * level
    if isinstance(v, dict):
        if not v:
            return "{}"
        items = [f"{pad}{_FLAT.encode(k)}: {_pretty(x, level + 1)}" for k, x in v.items()]
        return "{\n" + ",\n".join(items) + "\n" + end + "}"
    return "[\n" + ",\n".join([pad + _pretty(x, level + 1) for x in v]) + "\n" + end + "]"
