"""JSON for scripts: SI numbers, never NaN, the same bytes for the same input."""

from __future__ import annotations

import json
import math
from typing import Any

from rbcli.api.result import jsonable  # noqa: F401  (the one finiteness check)


#: the encoder of JSON Lines, made once (json.dumps with these arguments makes one per call)
_LINE = json.JSONEncoder(ensure_ascii=False, allow_nan=False, separators=(",", ":"))


def dumps(obj: Any, *, lines: bool = False, plain: bool = False) -> str:
    """One JSON document (indented, numeric arrays on one line), or one compact line.

    ``plain``: ``obj`` is :func:`jsonable`'s result already (e.g. a result's ``to_json()``),
    which is not converted and checked a second time (the same text: ``jsonable`` of its
    own result gives it back equal)."""
    data = obj if plain else jsonable(obj)
    if lines:
        return _LINE.encode(data) + "\n"
    return _pretty(data, 0) + "\n"


#: the encoder of one-line values inside the indented document, made once
_FLAT = json.JSONEncoder(ensure_ascii=False, allow_nan=False, separators=(", ", ": "))
_flat_encode = _FLAT.encode
#: JSON's own string quoting (C), as json.dumps(..., ensure_ascii=False) quotes
_quote = json.encoder.encode_basestring  # type: ignore[attr-defined]
_float_repr = float.__repr__


def _flat(v: Any) -> bool:
    """A value short enough to print on one line: a scalar, or a list of (lists of) scalars."""
    if isinstance(v, list):
        return all(not isinstance(x, (dict, list)) or (isinstance(x, list) and _flat(x)) for x in v)
    return not isinstance(v, dict)


def _scalar(v: Any) -> str | None:
    """The JSON of a plain scalar as json.dumps writes it, or None for anything else
    (the common cases without json.dumps's per-call encoder: a 100 000-part body's JSON
    has ~10^6 of them)."""
    t = type(v)
    if t is str:
        return _quote(v)
    if t is float and math.isfinite(v):
        return _float_repr(v)
    if t is int:
        return int.__repr__(v)
    return None


def _pretty(v: Any, level: int) -> str:
    text = _scalar(v)
    if text is not None:
        return text
    if _flat(v):
        return _flat_encode(v)
    pad = "  " * (level + 1)
    end = "  " * level
    if isinstance(v, dict):
        if not v:
            return "{}"
        items = [f"{pad}{_quote(k) if type(k) is str else _flat_encode(k)}: {_pretty(x, level + 1)}"
                 for k, x in v.items()]
        return "{\n" + ",\n".join(items) + "\n" + end + "}"
    items = [pad + _pretty(x, level + 1) for x in v]
    return "[\n" + ",\n".join(items) + "\n" + end + "]"
