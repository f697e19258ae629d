"""What every command shares: loading bodies, parsing option values, output, exit.

Imports only typer and the standard library at module level; numpy and the io
layer are imported inside the functions.
"""

from __future__ import annotations

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


def env():
    from rbcli.cli.app import STATE
    from rbcli.env import Env

    e = Env.from_process()
    e.debug = bool(STATE["debug"])
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


def each_body(bodies: list[str] | None, expr: str | None, e: Any) -> Iterator[tuple[str, Any]]:
    """Yield (source, Body or InputError) so batch runs go on past a bad file."""
    for src in sources(bodies, expr):
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
    if dim == un.Dim() and not _has_unit(s):
        if bare is None:
            return value
        factor, _ = un.parse_unit(bare)
        return value * factor
    try:
        return un.to_si(s, kind)
    except un.UnitError as exc:
        raise InputError(f"{option}: {exc}") from None


def _has_unit(s: str) -> bool:
    try:
        float(s)
        return False
    except ValueError:
        return True


def vector(text: str, kind: str, option: str, n: int = 3, *, bare: str | None = None) -> list[float]:
    """A comma-separated vector like ``1,0,0`` or ``10 mm,0,5 mm``."""
    parts = [p for p in text.split(",")]
    if len(parts) != n:
        raise InputError(f"{option}: expected {n} comma-separated numbers like 1,0,0, got '{text}'")
    return [quantity(p, kind, option, bare=bare) for p in parts]


def numbers(text: str, kind: str, option: str, *, counts: tuple[int, ...], bare: str | None = None) -> list[float]:
    parts = [p for p in text.split(",")]
    if len(parts) not in counts:
        want = " or ".join(str(c) for c in counts)
        raise InputError(f"{option}: expected {want} comma-separated values, got '{text}'")
    return [quantity(p, kind, option, bare=bare) for p in parts]


def point(text: str, option: str) -> str | list[float]:
    """``com``, ``origin`` or ``x,y,z`` (metres unless a unit is given)."""
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


def finish(status: int | ExitStatus) -> None:
    if int(status) != 0:
        raise typer.Exit(int(status))
