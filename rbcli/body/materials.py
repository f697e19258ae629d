"""Named materials: ``rbcli/data/materials.csv`` (name, aliases, kg/m³, source; read on
first use; wood at 12 % moisture: 1.12 × the USDA Wood Handbook's specific gravity × 1000),
after a body file's own ``materials:``.
"""

from __future__ import annotations

import csv
import difflib
from collections.abc import Mapping
from functools import cache
from pathlib import Path
from typing import NamedTuple

from rbcli.errors import literal

__all__ = ["Material", "TABLE", "table", "key", "density"]

TABLE = Path(__file__).resolve().parent.parent / "data" / "materials.csv"


class Material(NamedTuple):
    """A row of the table: ``density`` in kg/m³, ``source`` where it is from."""

    name: str
    aliases: tuple[str, ...]
    density: float
    source: str


def key(name: str) -> str:
    """How a name is matched: lower case, hyphens and underscores as spaces, single spaces."""
    return " ".join(name.lower().replace("-", " ").replace("_", " ").split())


@cache
def table() -> tuple[Material, ...]:
    """The built-in materials, in the table's order."""
    with TABLE.open(encoding="utf-8", newline="") as fh:
        return tuple(Material(r["name"], tuple(a.strip() for a in r["aliases"].split(";") if a.strip()),
                              float(r["density"]), r["source"]) for r in csv.DictReader(fh))


@cache
def _index() -> dict[str, Material]:
    return {key(n): m for m in table() for n in (m.name, *m.aliases)}


def density(name: str, own: Mapping[str, float] | None = None) -> float:
    """kg/m³ of material ``name``: the body's ``own`` (keys by :func:`key`), else the table's;
    else a ValueError (a message template) with the nearest name."""
    k, own = key(name), own or {}
    if k in own:
        return own[k]
    found = _index().get(k)
    if found is not None:
        return found.density
    names = {**{n: n for n in own}, **{kk: m.name for kk, m in _index().items()}}
    close = difflib.get_close_matches(k, list(names), n=1, cutoff=0.6) if len(k) <= 100 else []
    hint = f"; did you mean '{literal(names[close[0]])}'?" if close else ""
    shown = name if len(name) <= 60 else name[:60] + "…"
    raise ValueError(f"unknown material '{literal(shown)}'{hint} (see rbcli materials)")
