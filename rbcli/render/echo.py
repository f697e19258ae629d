"""The "options" table: each parameter the caller gave, as understood.

One row (option, value, unit) per parameter given, in its table's order, shown as
:attr:`~rbcli.api.params.Param.shows` says: a quantity kind (in the unit typed, else the
body's bare unit), ``"direction"``, ``"point"``, ``"deg"``, ``"count"``, ``"grade"``,
``"percent"``, ``"text"``, ``"=UNIT"``, ``"each:UNIT"`` (one per bearing, said once when
equal), ``"list:UNIT"`` or a name the command renders itself (``custom``); with
``echo_default`` the value used when not given, marked "(default)"."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

from rbcli.errors import option_name
from rbcli.render.fmt import num
from rbcli.render.units import BodyUnits

__all__ = ["echo_rows"]

Row = tuple[str, str, str]


def _each(vals: Any) -> str:
    """One value when every bearing has it ("5e+06 (each bearing)"), else the list."""
    if len(set(vals)) == 1:
        return f"{num(vals[0])} (each bearing)"
    return ", ".join(num(v) for v in vals)


def row(param: str, value: Any, how: str, bu: BodyUnits, typed: str | None = None) -> Row:
    """The row of one parameter given (see the module's docstring for ``how``)."""
    opt = option_name(param)
    if how == "direction":
        return opt, bu.show(value, "dimensionless"), "direction"
    if how == "point":
        return (opt, value, "") if isinstance(value, str) else bu.echo(param, value, "length", typed)
    if how == "deg":
        return opt, f"{value:.6g}", "deg"
    if how in ("count", "text"):
        return opt, str(value), ""
    if how == "grade":
        return opt, f"G{value:g}", "mm/s"
    if how == "percent":
        return opt, num(100.0 * value, 3), "%"
    if how.startswith("="):
        return opt, f"{value:.6g}", how[1:]
    if how.startswith("each:"):
        return opt, _each(value), how[5:]
    if how.startswith("list:"):
        return opt, ", ".join(str(n) for n in value), how[5:]
    if len(value) == 1 if isinstance(value, tuple) else False:
        value = value[0]
    return bu.echo(param, value, how, typed)


def echo_rows(options: Any, units: Mapping[str, str] | None = None,
              custom: Mapping[str, Callable[[Any], tuple[str, str]]] | None = None) -> list[Row]:
    """The rows of the parameters given in ``options`` (:class:`rbcli.api.params.Options`),
    values in the bare units of a body whose ``units`` block is ``units``; ``custom`` maps a
    ``shows`` name to a function of the value giving (value, unit)."""
    bu = BodyUnits(units)
    given = set(options.given)
    typed = dict(options.typed)
    rows = []
    for p in options.params:
        value = getattr(options, p.name)
        if p.shows == "-" or not (p.name in given or p.echo_default and value is not None):
            continue
        if custom and p.shows in custom:
            r = (option_name(p.name), *custom[p.shows](value))
        else:
            r = row(p.name, value, p.shows, bu, typed.get(p.name))
        rows.append(r if p.name in given else (r[0], r[1] + " (default)", r[2]))
    return rows
