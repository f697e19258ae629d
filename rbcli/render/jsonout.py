"""JSON for scripts: SI numbers, never NaN, the same bytes for the same input."""

from __future__ import annotations

import json
import math
from typing import Any

from rbcli.errors import NonFiniteResult


def jsonable(obj: Any) -> Any:
    """Plain JSON data from results: numpy arrays to lists, -0.0 to 0.0.

    Raises
    ------
    NonFiniteResult
        for an inf or NaN anywhere (an InputError, exit 2: the inputs were too large or too
        small to compute with), naming the key it was found under.
    """
    if hasattr(obj, "to_json"):
        return jsonable(obj.to_json())
    if isinstance(obj, dict):
        out = {}
        for k, v in obj.items():
            try:
                out[str(k)] = jsonable(v)
            except _NonFinite as exc:
                exc.path.insert(0, str(k))
                raise
        return out
    if isinstance(obj, (list, tuple)):
        out_list = []
        for i, v in enumerate(obj):
            try:
                out_list.append(jsonable(v))
            except _NonFinite as exc:
                exc.path.insert(0, i)
                raise
        return out_list
    if hasattr(obj, "tolist"):  # numpy arrays and scalars
        return jsonable(obj.tolist())
    if isinstance(obj, bool) or obj is None or isinstance(obj, str):
        return obj
    if isinstance(obj, int):
        return obj
    if isinstance(obj, float):
        if not math.isfinite(obj):
            raise _NonFinite(obj)
        return 0.0 if obj == 0.0 else obj
    raise TypeError(f"cannot write {type(obj).__name__} as JSON")


class _NonFinite(NonFiniteResult):
    """NonFiniteResult that collects the key path on its way up through :func:`jsonable`."""

    def __init__(self, value: float) -> None:
        self.value = value
        self.path: list[str | int] = []
        super().__init__("")

    @property
    def message(self) -> str:  # the path is known only once the error has left jsonable
        return str(self)

    @message.setter
    def message(self, _text: str) -> None:
        pass

    def __str__(self) -> str:
        where = "".join(f"[{p}]" if isinstance(p, int) else (f".{p}" if i else p)
                        for i, p in enumerate(self.path))
        what = f"the result '{where}'" if where else "a result"
        return (f"{what} is not a finite number ({self.value}): a value is too large or too "
                "small to compute with; check the options and the body's numbers")


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
