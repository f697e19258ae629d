"""JSON for scripts: SI numbers, never NaN, the same bytes for the same input."""

from __future__ import annotations

import gc
import json
import math
from itertools import chain, compress
from operator import itemgetter
from typing import Any

from rbcli.api.result import jsonable  # noqa: F401  (the one finiteness check)


#: the encoder of JSON Lines, made once (json.dumps with these arguments makes one per call)
_LINE = json.JSONEncoder(ensure_ascii=False, allow_nan=False, separators=(",", ":"))


def dumps(obj: Any, *, lines: bool = False, plain: bool = False) -> str:
    """One JSON document (indented, numeric arrays on one line), or one compact line.

    ``plain``: ``obj`` is :func:`jsonable`'s result already (e.g. a result's ``to_json()``),
    which is not converted and checked a second time (the same text: ``jsonable`` of its
    own result gives it back equal).

    The indented layout: a mapping, or a list holding a mapping or a list that is not
    flat, has one item a line, indented by two spaces a level; every other value (a
    scalar, a list of scalars or of such lists, an empty mapping) is on one line as
    ``json.dumps(v, ensure_ascii=False, separators=(", ", ": "))`` writes it.
    """
    data = obj if plain else jsonable(obj)
    if lines:
        return _LINE.encode(data) + "\n"
    # The collector paused: the layout makes ~1 container a row (100 000 for a large
    # body's parts) and no cycles; each gen-0 collection would also rescan the document.
    was = gc.isenabled()
    gc.disable()
    try:
        return _pretty(data, 0, True) + "\n"
    except Exception:  # noqa: BLE001 - written again value by value: the first error met
        # in document order is raised (the column path meets them column by column)
        return _pretty(data, 0, False) + "\n"
    finally:
        if was:
            gc.enable()


#: the encoder of one-line values inside the indented document, made once
_FLAT = json.JSONEncoder(ensure_ascii=False, allow_nan=False, separators=(", ", ": "))
_flat_encode = _FLAT.encode
#: JSON's own string quoting (C), as json.dumps(..., ensure_ascii=False) quotes
_quote = json.encoder.encode_basestring  # type: ignore[attr-defined]
_float_repr = float.__repr__
_int_repr = int.__repr__
_bool_text = {True: "true", False: "false"}.__getitem__
_isfinite = math.isfinite
_NONE = type(None)


def _flat(v: Any) -> bool:
    """A value short enough to print on one line: a scalar, or a list of (lists of) scalars."""
    if isinstance(v, list):
        return all(not isinstance(x, (dict, list)) or (isinstance(x, list) and _flat(x)) for x in v)
    return not isinstance(v, dict)


def _scalar(v: Any) -> str | None:
    """The JSON of a plain scalar as json.dumps writes it, or None for anything else
    (the common cases without json.dumps's per-call encoder)."""
    t = type(v)
    if t is str:
        return _quote(v)
    if t is float and _isfinite(v):
        return _float_repr(v)
    if t is int:
        return _int_repr(v)
    return None


def _key(k: Any) -> str:
    return _quote(k) if type(k) is str else _flat_encode(k)


def _pretty(v: Any, level: int, rows: bool) -> str:
    """``v`` at ``level``; ``rows``: lists of mappings laid out by :func:`_rows`."""
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
        items = [f"{pad}{_key(k)}: {_pretty(x, level + 1, rows)}" for k, x in v.items()]
        return "{\n" + ",\n".join(items) + "\n" + end + "}"
    if rows and len(v) >= 2 and type(v) is list:
        lines = _rows(v, level)
        if lines is not None:
            return "[\n" + ",\n".join(lines) + "\n" + end + "]"
    return "[\n" + ",\n".join([pad + _pretty(x, level + 1, rows) for x in v]) + "\n" + end + "]"


def _rows(v: list, level: int) -> list[str] | None:
    """The lines (each its indent and item) of a list that is not flat, at ``level``,
    whose non-empty mappings (e.g. a body's 100 000 "parts" rows) are laid out column by column,
    or None when that does not pay (few mappings, or mappings of many different keys).

    The mappings with the same keys in the same order make one group; in a group each
    key's values (a column) are encoded at once by C functions (:func:`_column`), and
    each row is one %-format of a template holding the keys and the layout. Columns of
    other values are written value by value by :func:`_pretty`. The text is the same.
    """
    pad = "  " * (level + 1)
    if set(map(type, v)) == {dict} and all(v):  # all rows (the common case): no index
        is_row = None
        rows = v
    else:
        is_row = [type(x) is dict and len(x) > 0 for x in v]
        rows = [x for x, r in zip(v, is_row) if r]
    if len(rows) < 2:
        return None
    keys = list(map(tuple, rows))
    groups = set(keys)
    if len(groups) > 8 and len(groups) * 16 > len(rows):
        return None
    # Grouping by key tuples is exact for str keys: a key equal to a str is a str (or a
    # subclass, written the same). 1, 1.0 and True are one key: not grouped.
    if set(map(type, chain.from_iterable(groups))) != {str}:
        return None
    texts: list[str] = []
    placed: dict[int, str] = {}  # row number -> text, when there are several groups
    for group in groups:
        if len(groups) == 1:
            index = None
            members = rows
        else:
            index = list(compress(range(len(rows)), map(group.__eq__, keys)))
            members = list(map(rows.__getitem__, index))
        pieces = []
        columns: list[list[str]] = []
        for key in group:
            col = list(map(itemgetter(key), members))
            laid = _column(col)
            if laid is None:  # not all one kind of value: each as _pretty writes it
                laid = ("%s", [[_pretty(x, level + 2, True) for x in col]])
            pieces.append(f"{pad}  {_quote(key).replace('%', '%%')}: {laid[0]}")
            columns.extend(laid[1])
        template = pad + "{\n" + ",\n".join(pieces) + "\n" + pad + "}"
        made = list(map(template.__mod__, zip(*columns))) if columns else [template % ()] * len(members)
        if index is None:
            texts = made
        else:
            placed.update(zip(index, made))
    if placed:
        texts = list(map(placed.__getitem__, range(len(rows))))
    if is_row is None:
        return texts
    it = iter(texts)
    return [next(it) if r else pad + _pretty(x, level + 1, True) for x, r in zip(v, is_row)]


def _column(col: list) -> tuple[str, list[list[str]]] | None:
    """(a %-template, its columns of text) of values of one kind laid out on one line as
    the flat encoder writes them: str, finite float, int, bool, None, or lists of the same
    length of such columns (e.g. the rows' "com"); None for anything else."""
    kinds = set(map(type, col))
    if len(kinds) != 1:
        return None
    kind = kinds.pop()
    if kind is str:
        return "%s", [list(map(_quote, col))]
    if kind is float:
        total = sum(col)
        if total - total != 0.0 and not all(map(_isfinite, col)):  # inf or NaN: an error
            return None
        return "%s", [list(map(_float_repr, col))]
    if kind is int:
        return "%s", [list(map(_int_repr, col))]
    if kind is bool:
        return "%s", [list(map(_bool_text, col))]
    if kind is _NONE:
        return "null", []
    if kind is list:
        lengths = set(map(len, col))
        if len(lengths) != 1:
            return None
        if not lengths.pop():
            return "[]", []
        pieces = []
        columns: list[list[str]] = []
        flat = list(chain.from_iterable(col))  # the i-th items are flat[i::length]
        length = len(flat) // len(col)
        for i in range(length):
            laid = _column(flat[i::length])
            if laid is None:
                return None
            pieces.append(laid[0])
            columns.extend(laid[1])
        return "[" + ", ".join(pieces) + "]", columns
    return None
