"""A body file's ``bearings:`` section and the coefficient tables it names: read, checked,
in SI. What the coefficients mean, and at which speeds a table may be used, is the whirl
service's (:mod:`rbcli.api.whirl`); every problem here is one line located in its file.

The section (bare numbers in the body's units: positions in its length unit, speeds in its
``angular_speed`` or rad/s, stiffness N/m, damping N s/m; or strings with units)::

    bearings:
      - name: drive end              # optional
        at: 0                        # position along the shaft (z from the shaft point)
        k: 2e8                       # kxx = kyy; or kxx, kyy, kxy, kyx (N/m)
        c: 5e4                       # cxx = cyy; or cxx, cyy, cxy, cyx (N s/m)
      - name: non-drive end
        at: 500 mm
        table: bearing2.csv          # or rows [speed, kxx, kxy, kyx, kyy, cxx, cxy, cyx, cyy]
        units: {speed: rpm, stiffness: N/mm, damping: N*s/mm}   # what bare numbers mean

Tables and their CSV files: the man page of ``rbcli whirl`` ("Bearings in the body file").
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from pathlib import Path

from rbcli.errors import InputError, Location
from rbcli.io import units as un
from rbcli.io import yamlsafe as ys
from rbcli.io.reader import read_regular

__all__ = ["BearingEntry", "COLUMNS", "section", "schema", "MAX_ROWS"]

#: a table's columns, in the order bearing programs print them
COLUMNS = ("speed", "kxx", "kxy", "kyx", "kyy", "cxx", "cxy", "cyx", "cyy")
#: the most rows of one table, and the largest CSV file read (bytes)
MAX_ROWS = 10_000
MAX_CSV = 4 << 20
#: numbers are limited to this in SI units (as in the body file)
HUGE = 1e60
_KEYS = ("name", "at", "k", "c", *COLUMNS[1:], "table", "units")
_KIND = {"speed": "angular_speed", "stiffness": "stiffness", "damping": "damping"}


@dataclass(frozen=True)
class BearingEntry:
    """One bearing of the section.

    Attributes
    ----------
    name : str — as given, or ``bearing N``
    at : float — m along the shaft
    values : dict — the constant coefficients given (SI), keys among kxx ... cyy
    speeds : tuple of float — rad/s, the table's speeds (ascending); empty without one
    rows : tuple of tuples of 8 floats — the table's coefficients (SI, COLUMNS[1:] order)
    where : Location — the entry in the body file
    table : str — where the table came from (the CSV file, or the body file)
    """

    name: str
    at: float
    values: dict
    speeds: tuple
    rows: tuple
    where: Location
    table: str = ""


class _Ctx:
    def __init__(self, file: str, units: dict, base_dir: Path) -> None:
        self.file, self.units, self.base_dir = file, units, base_dir

    def error(self, node: ys.Node | None, message: str, line: int = 0) -> InputError:
        loc = Location(self.file, line) if node is None else ys.where(self.file, node.mark)
        return InputError(message, loc)

    def bare(self, kind: str, override: dict) -> float:
        """SI per bare number of ``kind`` (the entry's ``units:``, else the body's rule)."""
        unit = override.get(kind)
        if unit is not None:
            return un.to_si(f"1 {unit}", kind)
        if kind in ("length", "angular_speed"):
            return un.unit_for_kind(self.units, kind)[0]
        return 1.0

    def number(self, node: ys.Node, kind: str, what: str, override: dict) -> float:
        v = node.value if isinstance(node, ys.ScalarNode) else None
        if isinstance(v, bool) or not isinstance(v, (int, float, str)):
            raise self.error(node, f"{what} must be a number or a quantity like '2e8 N/m', not "
                             f"{'a list or mapping' if v is None and not isinstance(node, ys.ScalarNode) else repr(v)}")
        return self.value(v, kind, what, override, node)

    def value(self, v: int | float | str, kind: str, what: str, override: dict, node=None, line=0) -> float:
        try:
            x = un.to_si(v, kind) if isinstance(v, str) else float(v) * self.bare(kind, override)
        except (un.UnitError, OverflowError) as exc:
            raise self.error(node, f"{what}: {exc}", line) from None
        if not math.isfinite(x) or abs(x) > HUGE:
            raise self.error(node, f"{what} must be finite and at most 1e60 in SI units, not {v}", line)
        return x


def _map(ctx: _Ctx, node: ys.Node, what: str) -> ys.MapNode:
    if not isinstance(node, ys.MapNode):
        raise ctx.error(node, f"{what} must be a mapping (key: value)")
    return node


def _units(ctx: _Ctx, node: ys.Node, what: str) -> dict:
    m = _map(ctx, node, f"{what}.units")
    out = {}
    for key, (_, v) in m.items.items():
        if key not in _KIND:
            raise ctx.error(v, f"{what}.units: unknown key '{key}'; allowed: speed, stiffness, damping")
        text = v.value if isinstance(v, ys.ScalarNode) else None
        if not isinstance(text, str) or isinstance(text, bool):
            raise ctx.error(v, f"{what}.units.{key} must be a unit such as "
                            f"{ {'speed': 'rpm', 'stiffness': 'N/mm', 'damping': 'N*s/mm'}[key]}")
        ctx.value(f"1 {text}", _KIND[key], f"{what}.units.{key}", {}, v)
        out[_KIND[key]] = text
    return out


def _check(ctx: _Ctx, what: str, name: str, x: float, node, line: int = 0) -> None:
    """A speed >= 0, a direct stiffness > 0, a direct damping >= 0 (cross terms: any)."""
    if name in ("kxx", "kyy") and not x > 0.0:
        raise ctx.error(node, f"{what}: the direct stiffness {name} must be positive, got {x:.6g} "
                        "N/m: a bearing with none does not hold the rotor", line)
    if name in ("cxx", "cyy", "speed") and x < 0.0:
        raise ctx.error(node, f"{what}: " + (f"a speed must not be negative, got {x:.6g} rad/s"
                        if name == "speed" else f"the direct damping {name} must not be negative, "
                        f"got {x:.6g} N s/m: a negative damper feeds energy in"), line)


def _finish(ctx: _Ctx, what: str, rows: list[list[float]], places: list) -> tuple:
    """(speeds, rows of 8) of a table read, checked: two rows or more, ascending speeds."""
    if len(rows) < 2:
        node, line = places[0] if places else (None, 0)
        raise ctx.error(node, f"{what}: a table needs two rows or more (one speed is a constant: "
                        "give k and c)", line)
    for i in range(1, len(rows)):
        if not rows[i][0] > rows[i - 1][0]:
            node, line = places[i]
            raise ctx.error(node, f"{what}: rows must be in ascending speed, each speed once: row "
                            f"{i + 1} ({rows[i][0]:.6g} rad/s) follows row {i} ({rows[i - 1][0]:.6g} "
                            "rad/s); the table is not reordered", line)
    for row, (node, line) in zip(rows, places):
        for name, x in zip(COLUMNS, row):
            _check(ctx, what, name, x, node, line)
    return tuple(r[0] for r in rows), tuple(tuple(r[1:]) for r in rows)


def _yaml_table(ctx: _Ctx, node: ys.SeqNode, what: str, override: dict) -> tuple:
    if len(node.items) > MAX_ROWS:
        raise ctx.error(node.items[MAX_ROWS], f"{what}: more than {MAX_ROWS} rows")
    rows, places = [], []
    for i, r in enumerate(node.items):
        if not isinstance(r, ys.SeqNode) or len(r.items) != len(COLUMNS):
            raise ctx.error(r, f"{what}[{i}]: a row is a list of {len(COLUMNS)} numbers: "
                            f"[{', '.join(COLUMNS)}]")
        rows.append([ctx.number(v, _kind_of(c), f"{what}[{i}].{c}", override)
                     for c, v in zip(COLUMNS, r.items)])
        places.append((r, 0))
    return _finish(ctx, what, rows, places)


def _kind_of(column: str) -> str:
    return "angular_speed" if column == "speed" else ("stiffness" if column[0] == "k" else "damping")


def _header(ctx: _Ctx, cells: list[str], path: str, override: dict) -> list[tuple[int, str, float]]:
    """(column index, name, SI per bare number) of each column the header names."""
    out, seen = [], set()
    for j, cell in enumerate(cells):
        name, _, unit = cell.strip().partition("[")
        name = name.strip().lower()
        if name not in COLUMNS:
            raise InputError(f"unknown column '{cell.strip()}' in the header; columns: "
                             f"{', '.join(COLUMNS)} (each optionally with its unit, 'kxx [N/mm]')",
                             Location(path, 1))
        if name in seen:
            raise InputError(f"column '{name}' named twice in the header", Location(path, 1))
        seen.add(name)
        kind = _kind_of(name)
        unit = unit.rstrip().rstrip("]").strip()
        f = ctx.value(f"1 {unit}", kind, f"column {name}", {}, None, 1) if unit else \
            ctx.bare(kind, override)
        out.append((j, name, f))
    if "speed" not in seen or len(seen) < 2:
        raise InputError(f"the header names the columns: speed and one or more of "
                         f"{', '.join(COLUMNS[1:])}", Location(path, 1))
    return out


def _csv_table(ctx: _Ctx, node: ys.ScalarNode, what: str, override: dict) -> tuple:
    text = str(node.value)
    path = os.path.join(ctx.base_dir, text)
    raw = read_regular(path, MAX_CSV, "bearing table", where=ys.where(ctx.file, node.mark))
    try:
        lines = raw.decode("utf-8-sig").splitlines()
    except UnicodeDecodeError as exc:
        raise InputError(f"not UTF-8 text ({exc.reason} at byte {exc.start})",
                         Location(path)) from None
    head, rows, places, sub = None, [], [], _Ctx(path, ctx.units, ctx.base_dir)
    for n, line in enumerate(lines, 1):
        body = line.split("#", 1)[0].strip()
        if not body:
            continue
        cells = [c.strip() for c in body.split(",")]
        if head is None:
            head = _header(sub, cells, path, override)
            continue
        if len(cells) != len(head):
            raise InputError(f"{len(cells)} cells where the header names {len(head)}",
                             Location(path, n))
        if len(rows) >= MAX_ROWS:
            raise InputError(f"more than {MAX_ROWS} rows", Location(path, n))
        row = dict.fromkeys(COLUMNS, 0.0)
        for (_, name, f), cell in zip(head, cells):
            x = ys.plain_value(cell)  # a YAML number: 1e6, -3.5, .inf
            if isinstance(x, bool) or not isinstance(x, (int, float)):
                raise InputError(f"'{cell[:40]}' in column {name} is not a number (units "
                                 "go in the header: 'kxx [N/mm]')", Location(path, n))
            x = x * f
            if not math.isfinite(x) or abs(x) > HUGE:
                raise InputError(f"column {name} must be finite and at most 1e60 in SI "
                                 f"units, not {cell[:40]}", Location(path, n))
            row[name] = x
        rows.append([row[c] for c in COLUMNS])
        places.append((None, n))
    if head is None:
        raise InputError(f"an empty table (a header row and two rows or more)", Location(path))
    return (*_finish(sub, "the table", rows, places), path)


def _entry(ctx: _Ctx, i: int, node: ys.Node) -> BearingEntry:
    what = f"bearings[{i}]"
    m = _map(ctx, node, what)
    for key, (_, v) in m.items.items():
        if key not in _KEYS:
            raise ctx.error(v, f"{what}: unknown key '{key}'; allowed: {', '.join(_KEYS)}")
    get = {k: v for k, (_, v) in m.items.items()}
    if "at" not in get:
        raise ctx.error(m, f"{what}: needs its position along the shaft, 'at: z' (e.g. 'at: 0.25' "
                        "or 'at: 250 mm')")
    override = _units(ctx, get["units"], what) if "units" in get else {}
    name = get.get("name")
    if name is not None and not (isinstance(name, ys.ScalarNode) and isinstance(name.value, str)):
        raise ctx.error(name, f"{what}.name must be text")
    values: dict[str, float] = {}
    for short, pair in (("k", ("kxx", "kyy")), ("c", ("cxx", "cyy"))):
        if short in get:
            if any(p in get for p in pair):
                raise ctx.error(get[short], f"{what}: give '{short}' (both directions) or "
                                f"{' and '.join(pair)}, not both")
            x = ctx.number(get[short], _kind_of(pair[0]), f"{what}.{short}", override)
            values.update(dict.fromkeys(pair, x))
    for c in COLUMNS[1:]:
        if c in get:
            values[c] = ctx.number(get[c], _kind_of(c), f"{what}.{c}", override)
    speeds, rows, source = (), (), ""
    if "table" in get:
        t = get["table"]
        if values:
            raise ctx.error(t, f"{what}: give the coefficients as numbers or as a table, not both")
        if isinstance(t, ys.ScalarNode) and isinstance(t.value, str) and not isinstance(t.value, bool):
            speeds, rows, source = _csv_table(ctx, t, f"{what}.table", override)
        elif isinstance(t, ys.SeqNode):
            speeds, rows = _yaml_table(ctx, t, f"{what}.table", override)
            source = ctx.file
        else:
            raise ctx.error(t, f"{what}.table is a CSV file name or a list of rows [{', '.join(COLUMNS)}]")
    for k, x in values.items():
        _check(ctx, what, k, x, get["k" if k in ("kxx", "kyy") and "k" in get else
                                    "c" if k in ("cxx", "cyy") and "c" in get else k])
    return BearingEntry(name.value if name is not None else f"bearing {i + 1}",
                        ctx.number(get["at"], "length", f"{what}.at", {}), values, speeds, rows,
                        ys.where(ctx.file, m.mark), source)


def section(text: str, file: str, units: dict, base_dir: str | os.PathLike[str]) -> tuple[BearingEntry, ...] | None:
    """The ``bearings:`` section of the body file ``text`` (read from ``file``; ``units``
    its units block; tables found from ``base_dir``), or None when it has none.

    Raises
    ------
    rbcli.InputError
        one line located in the body file or the table (``file:line:col: bearings[1].kxx:
        ...``).
    """
    if "bearings" not in text:
        return None
    root = ys.load(text, file)
    if not isinstance(root, ys.MapNode) or "bearings" not in root.items:
        return None
    node = root.items["bearings"][1]
    ctx = _Ctx(file, dict(units), Path(base_dir))
    if not isinstance(node, ys.SeqNode) or not node.items:
        raise ctx.error(node, "bearings: a list of bearings, each with its position 'at' and its "
                        "coefficients (k, c, kxx ... cyy) or a 'table'")
    if len(node.items) > 20:
        raise ctx.error(node.items[20], "bearings: at most 20 bearings")
    return tuple(_entry(ctx, i, b) for i, b in enumerate(node.items))


def schema() -> dict:
    """The JSON Schema of the section (the body file's schema includes it)."""
    q = {"$ref": "#/definitions/quantity"}
    units = {"type": "object", "properties": {k: {"type": "string"} for k in _KIND},
             "additionalProperties": False}
    row = {"type": "array", "items": q, "minItems": len(COLUMNS), "maxItems": len(COLUMNS)}
    table = {"anyOf": [{"type": "string"}, {"type": "array", "items": row, "minItems": 2}]}
    bearing = {"type": "object", "required": ["at"], "additionalProperties": False,
               "properties": {"name": {"type": "string"}, "at": q, "table": table, "units": units,
                              **{k: q for k in ("k", "c", *COLUMNS[1:])}}}
    return {"type": "array", "items": bearing, "minItems": 1, "maxItems": 20,
            "description": "the rotor's bearings for rbcli whirl: position 'at' along the shaft, "
                           "coefficients (k, c, kxx ... cyy) or a table against speed"}
