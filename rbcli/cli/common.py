"""What every command shares: loading bodies, parsing option values, output, exit.

Imports only typer and the standard library at module level; numpy and the io
layer are imported inside the functions.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from typing import Any

import typer

from rbcli.errors import ExitStatus, InputError

BODY_HELP = "Body file(s) (YAML); '-' reads standard input."
EXPR_HELP = "Inline YAML body, e.g. -e '{shape: box, mass: 2, size: [0.1, 0.2, 0.3]}'."
JSON_HELP = "Print JSON (SI units) instead of tables."
DIGITS_HELP = "Significant figures in tables."
UNITS_HELP = "Units for tables, e.g. mm,g or in,lb (JSON is always SI)."

BodiesArg = typer.Argument(None, metavar="BODY...", help=BODY_HELP, show_default=False)
BodyArg = typer.Argument(None, metavar="BODY", help="Body file (YAML); '-' reads standard input.", show_default=False)
ExprOpt = typer.Option(None, "-e", "--expr", help=EXPR_HELP, show_default=False)
JsonOpt = typer.Option(False, "--json", help=JSON_HELP)
DigitsOpt = typer.Option(6, "--digits", min=1, max=17, help=DIGITS_HELP)
UnitsOpt = typer.Option(None, "--units", help=UNITS_HELP, show_default=False)


def debug() -> bool:
    """Tracebacks for internal errors: the root ``--debug`` or ``RBCLI_DEBUG=1``."""
    import os

    from rbcli.cli.app import STATE

    return bool(STATE["debug"]) or os.environ.get("RBCLI_DEBUG", "").strip() not in ("", "0")


def env():
    from rbcli.env import Env

    e = Env.from_process()
    e.debug = debug()
    return e


def sources(bodies: list[str] | None, expr: str | None, *, single: bool = False) -> list[str]:
    """The body sources named on the command line (paths, '-', or the expression marker)."""
    bodies = list(bodies or [])
    if expr is not None and bodies:
        raise InputError("give either BODY files or -e/--expr, not both")
    if expr is not None:
        return ["<expr>"]
    if not bodies:
        raise InputError("no body given: name a BODY file, '-' for standard input, or use -e '{...}'")
    if bodies.count("-") > 1:
        raise InputError("standard input ('-') can be read only once")
    if single and len(bodies) > 1:
        raise InputError(f"this command takes one body, not {len(bodies)}")
    return bodies


def load(source: str, expr: str | None, e: Any):
    """Load one body and show its warnings on standard error."""
    from rbcli.io.body import load_body, load_expr

    body = load_expr(expr) if source == "<expr>" and expr is not None else load_body(source)
    for w in body.warnings:
        e.warn(f"rbcli: {w}")
    return body


def load_one(body: str | None, expr: str | None, e: Any):
    """The one body of a single-body command (a path, '-', or -e), with its warnings shown."""
    return load(sources([body] if body is not None else None, expr, single=True)[0], expr, e)


def output_paths(b: Any, *, plot: str | None = None, csv: str | None = None) -> tuple:
    """(plot path, csv path), each checked against the body's inputs before any computing.

    ``--csv -`` (standard output) gives None; a CSV may not be the plot file.
    """
    plot_path = csv_path = None
    if plot is not None:
        from rbcli.render.plots import check_path

        plot_path = check_path(plot, b)
    if csv not in (None, "-"):
        from rbcli.io.outfile import check

        csv_path = check(csv, b, "--csv", replace_ok=True, others={"--plot": plot_path})
    return plot_path, csv_path


def each_body(srcs: list[str], expr: str | None, e: Any) -> Iterator[tuple[str, Any]]:
    """Yield (source, Body or InputError) for the sources of :func:`sources`, so batch runs
    go on past a bad file."""
    for src in srcs:
        try:
            yield src, load(src, expr, e)
        except InputError as exc:
            yield src, exc


# ----------------------------------------------------------------------------- option values


def quantity(text: str, kind: str, option: str, *, bare: str | None = None) -> float:
    """An option's scalar quantity in SI. A bare number is in ``bare`` (default: SI)."""
    from rbcli.io import units as un

    s = text.strip()
    try:
        value, dim = un.parse_quantity(s)
    except un.UnitError as exc:
        raise InputError(f"{option}: {exc}") from None
    if dim == un.Dim() and _bare(s):
        if bare is None:
            return value
        factor, _ = un.parse_unit(bare)
        return value * factor
    try:
        return un.to_si(s, kind)
    except un.UnitError as exc:
        raise InputError(f"{option}: {exc}") from None


def degrees(text: str, option: str) -> float:
    """An angle option in degrees: a bare number is degrees (kept exactly), else any angle
    unit (``'0.5 rad'``, ``'30 arcmin'``)."""
    import math

    if _bare(text.strip()):
        quantity(text, "angle", option, bare="deg")  # its errors (inf, 1e999, ...)
        return float(text.strip().replace("\u2212", "-"))
    return math.degrees(quantity(text, "angle", option, bare="deg"))


#: a number at the start of a value: what is left after it is the value's unit
NUMBER = re.compile(r"\s*[-+\u2212]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?")

#: how the unit rule reads, for help texts
UNIT_RULE = "a unit after the last number applies to every bare number before it"


def _bare(s: str) -> bool:
    """A number with no unit after it."""
    return NUMBER.fullmatch(s) is not None


def numbers(text: str, kind: str, option: str, *, counts: tuple[int, ...] = (3,),
            bare: str | None = None) -> list[float]:
    """Comma-separated quantities of one kind, in SI: the one rule for list options.

    A unit after the LAST number applies to every bare number before it: ``1,1,1 mm`` is
    all millimetres, ``100,0,300 rpm`` all rpm, ``-100,100 mm`` both. A number with its own
    unit keeps it (``10 mm,0,2 cm``). A list with no unit at all is in the option's bare
    unit: ``bare`` (e.g. ``"deg"``), else SI. A list whose last number is bare but which has
    a unit elsewhere is refused unless its bare numbers are 0 (``10 mm,0,0``): which unit a
    bare 5 in ``10 mm,5,0`` means is a guess. Every value must be finite.
    """
    import math

    parts = [p.strip() for p in text.split(",")]
    if len(parts) not in counts or not all(parts):
        want = " or ".join(str(n) for n in counts)
        raise InputError(f"{option}: expected {want} comma-separated value{'s' if counts != (1,) else ''}, "
                         f"got '{text}'")
    last = quantity(parts[-1], kind, option, bare=bare)  # its own errors first
    m = NUMBER.match(parts[-1])
    unit = parts[-1][m.end():].strip() if m else ""
    if unit:
        parts = [f"{p} {unit}" if _bare(p) else p for p in parts]
    elif not all(_bare(p) for p in parts):
        stray = [p for p in parts if _bare(p) and float(p.replace("\u2212", "-")) != 0.0]
        if stray:
            raise InputError(
                f"{option}: '{text}' has a unit on some numbers but none after the last, so the "
                f"unit of {stray[0]} is unclear; put the unit after the last number (it then "
                "applies to every bare number before it) or after each number"
            )
    vals = [quantity(p, kind, option, bare=bare) for p in parts[:-1]] + [last]
    if not all(math.isfinite(v) for v in vals):
        raise InputError(f"{option}: values must be finite numbers, got '{text}'")
    return vals


def finite(x: float, option: str) -> float:
    """``x`` if it is a finite number, else an InputError naming ``option``."""
    import math

    if not math.isfinite(x):
        raise InputError(f"{option}: must be a finite number")
    return x


def positive(x: float, option: str, what: str) -> float:
    """``x`` if it is a positive finite number, else an InputError saying ``what`` it is."""
    import math

    if not (x > 0.0 and math.isfinite(x)):
        raise InputError(f"{option}: {what} must be a positive number, got {x:.6g}")
    return x


def distinct(vals: list[float], option: str, what: str) -> tuple[float, float]:
    """Two positions along a shaft that must differ (``--planes``, ``--bearings``)."""
    if vals[0] == vals[1]:
        raise InputError(f"{option}: the two {what} are both at z = {vals[0]:.6g} m; they must differ")
    return vals[0], vals[1]


#: an ISO 21940-11 balance quality grade: 'G6.3', 'g 2.5', '6.3' or '6.3 mm/s'
_GRADE = re.compile(r"[Gg]?\s*([-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?)\s*(mm/s)?")


def grade(text: str, option: str = "--grade") -> float:
    """A balance quality grade: 'G6.3', 'g 2.5', '6.3' or '6.3 mm/s' -> 6.3 (mm/s), within the
    grades ISO 21940-11 defines (G0.4 to G4000)."""
    import math

    from rbcli.core.balance import ISO_GRADE_MAX, ISO_GRADE_MIN

    m = _GRADE.fullmatch(text.strip())
    if not m:
        raise InputError(
            f"{option}: '{text}' is not a balance quality grade; write e.g. G6.3, 6.3 or g2.5 "
            "(G in mm/s, from G0.4 to G4000)"
        )
    G = float(m.group(1))
    if not (math.isfinite(G) and ISO_GRADE_MIN <= G <= ISO_GRADE_MAX):
        raise InputError(
            f"{option}: ISO 21940-11 grades run from G{ISO_GRADE_MIN:g} to G{ISO_GRADE_MAX:g} "
            f"(mm/s), got {text}"
        )
    return G


def vector(text: str, kind: str, option: str, n: int = 3, *, bare: str | None = None) -> list[float]:
    """A vector like ``1,0,0``, ``0,0,300 rpm`` or ``10,0,5 mm`` (see :func:`numbers`)."""
    if len(text.split(",")) != n:
        raise InputError(f"{option}: expected {n} comma-separated numbers like 1,0,0, got '{text}'")
    return numbers(text, kind, option, counts=(n,), bare=bare)


def point(text: str, option: str) -> str | list[float]:
    """``com``, ``origin`` or ``x,y,z`` (metres, unless a unit follows the last number)."""
    t = text.strip()
    if t in ("com", "origin"):
        return t
    return vector(t, "length", option)


def direction(text: str, option: str) -> list[float]:
    """A non-zero direction ``x,y,z``; also ``x``, ``y``, ``z`` for the body axes."""
    t = text.strip().lower()
    named = {"x": [1.0, 0.0, 0.0], "y": [0.0, 1.0, 0.0], "z": [0.0, 0.0, 1.0]}
    if t in named:
        return named[t]
    v = vector(t, "dimensionless", option)
    big = max(abs(x) for x in v)
    if not big > 0:
        raise InputError(f"{option}: the direction must be a non-zero vector")
    return [x / big for x in v]  # largest component ±1: no under/overflow when normalised


# ----------------------------------------------------------------------------- output


#: what :func:`rbcli.render.fmt.num` prints for a number that is not finite
_NON_FINITE = frozenset({"inf", "-inf", "+inf", "nan", "-nan"})
_CELL_SPLIT = re.compile(r"[\s\[\](),;=]+")


def check_finite_doc(doc: Any) -> None:
    """Refuse a table that would show inf or NaN as a number.

    Looks at the numeric (right-aligned) columns of every table: a whole word there that
    reads inf or nan is what ``num()`` prints for a result that overflowed. Names, notes
    and left-aligned text are not looked at (a part may be called "nan").

    Raises
    ------
    NonFiniteResult
        (exit 2, one line) naming the table and the row.
    """
    from rbcli.errors import NonFiniteResult
    from rbcli.render.text import Table

    for item in doc.items:
        if not isinstance(item, Table):
            continue
        for row in item.rows:
            for i in item.right:
                if i >= len(row):
                    continue
                bad = [w for w in _CELL_SPLIT.split(row[i].lower()) if w in _NON_FINITE]
                if bad:
                    what = row[0].strip() if row and i != 0 else item.title
                    raise NonFiniteResult(
                        f"'{what}' in the table '{item.title}' is not a finite number ({bad[0]}): "
                        "a value is too large or too small to compute with; check the options "
                        "and the body's numbers"
                    )


def write_doc(e: Any, doc: Any) -> None:
    """Render a document of tables to standard output, after :func:`check_finite_doc`."""
    check_finite_doc(doc)
    e.write(doc.render())


def emit(e: Any, json_: bool, data_fn: Any, doc_fn: Any, *, lines: bool = False) -> None:
    """Print a command's result: ``--json`` gives the JSON of ``data_fn()`` (one compact line
    with ``lines``, for JSON Lines), else the tables ``doc_fn(doc)`` puts in a Doc. Both
    refuse inf and NaN (one line, exit 2): :func:`rbcli.render.jsonout.jsonable` and
    :func:`write_doc`. Only the one that is printed is built."""
    if json_:
        from rbcli.render.jsonout import dumps

        e.write(dumps(data_fn(), lines=lines))
    else:
        from rbcli.render.text import Doc

        doc = Doc(e)
        doc_fn(doc)
        write_doc(e, doc)


def finish(status: int | ExitStatus) -> None:
    if int(status) != 0:
        raise typer.Exit(int(status))
