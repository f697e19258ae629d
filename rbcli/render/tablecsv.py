"""``--format csv``: a command's result as one table a spreadsheet or a script reads in one go.

The layout is a contract, documented once in rbcli(1) (``rbcli.cli.catalog``) and the README:
one row per value of the command's JSON, columns ``quantity,value,text,unit`` (text made safe
by :func:`rbcli.render.safe.csv_text`, units from :mod:`rbcli.render.csvunits`)."""

from __future__ import annotations

import csv
import io
from collections.abc import Iterator, Mapping
from typing import Any

from rbcli.render.csvunits import unit
from rbcli.render.safe import csv_text

#: the columns, in order (``file`` first with several bodies)
COLUMNS = ("quantity", "value", "text", "unit")


def number(x: float | int, digits: int | None = None) -> str:
    """A number cell: an integer as it is; a float at full precision (``repr``), or at
    ``digits`` significant figures; never ``-0``."""
    if isinstance(x, int):
        return str(x)
    x = float(x) + 0.0  # + 0.0: no negative zero
    if digits is None:
        return repr(x)
    s = format(x, f".{int(digits)}g")
    return "0" if s in ("-0", "0") else s


def _undefined(d: dict, key: str) -> Any:
    """The ``<name>_defined`` flag (a bool or a list of them) of ``<name>_deg``, or None."""
    if not key.endswith("_deg"):
        return None
    return d.get(key[:-4] + "_defined")


def values(data: Any, path: str = "", defined: Any = True) -> Iterator[tuple[str, Any, bool]]:
    """(path, leaf value, defined) for every leaf of JSON ``data``, in order (an empty list or
    mapping is a leaf, value None; ``defined`` False where a ``_defined`` sibling says so)."""
    if isinstance(data, dict):
        if not data:
            yield path, None, True
        for k, v in data.items():
            flag = _undefined(data, k)
            yield from values(v, f"{path}.{k}" if path else str(k), True if flag is None else flag)
    elif isinstance(data, (list, tuple)):
        if not data:
            yield path, None, True
        for i, v in enumerate(data):
            flag = defined[i] if isinstance(defined, (list, tuple)) and i < len(defined) else defined
            yield from values(v, f"{path}[{i}]", flag)
    else:
        yield path, data, defined is not False


def rows(data: dict, command: str, digits: int | None = None,
         params: Mapping[str, str] | None = None) -> Iterator[list[str]]:
    """The CSV rows (quantity, value, text, unit) of a command's JSON ``data`` (``params``:
    the SI unit of each of the command's parameters, :func:`rbcli.render.csvunits.lookup`)."""
    for path, v, ok in values(data):
        if isinstance(v, bool):
            yield [path, "", "true" if v else "false", ""]
        elif isinstance(v, (int, float)):
            yield [path, number(v, digits) if ok else "", "", unit(command, path, data, params)]
        elif isinstance(v, str):
            yield [path, "", csv_text(v), ""]
        else:  # None, [] or {}: not defined
            yield [path, "", "", ""]


def render(data: dict, command: str, *, digits: int | None = None, file: str | None = None,
           header: bool = True, params: Mapping[str, str] | None = None) -> str:
    """The CSV text of one result's JSON; ``file``: add the leading ``file`` column;
    ``header``: write the header row."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    lead = [] if file is None else [csv_text(file)]
    if header:
        w.writerow((["file"] if file is not None else []) + list(COLUMNS))
    w.writerows(lead + r for r in rows(data, command, digits, params))
    return buf.getvalue()
