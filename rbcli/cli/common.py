"""What every command shares: loading bodies, parsing option values, output, exit.

Imports only typer and the standard library at module level; numpy and the io
layer are imported inside the functions.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import typer

from rbcli.api.commands import BODY
from rbcli.errors import ExitStatus, InputError, option_name, spell, spelled_data

BODY_HELP = "Body file(s) (YAML; or STEP, STL, OBJ with --material); '-' reads standard input."
EXPR_HELP = "Inline YAML body, e.g. -e '{shape: box, mass: 2, size: [0.1, 0.2, 0.3]}'."
JSON_HELP = "Print JSON (SI units) instead of tables."
DIGITS_HELP = "Significant figures in tables; with --format csv, of its numbers (full precision unless given)."
UNITS_HELP = "Units for tables, e.g. mm,g, in,lb or si (default: the body file's units:; JSON is always SI)."

BodiesArg = typer.Argument(None, metavar="BODY...", help=BODY_HELP, show_default=False)
BodyArg = typer.Argument(None, metavar="BODY", help=BODY_HELP.replace("(s)", ""), show_default=False)
ExprOpt = typer.Option(None, "-e", "--expr", help=EXPR_HELP, show_default=False)
JsonOpt = typer.Option(False, "--json", help=JSON_HELP)
FORMAT_HELP = ("Output: table (for people), json (= --json) or csv (the JSON as one table for "
               "spreadsheets: quantity,value,text,unit; full precision unless --digits).")
FormatOpt = typer.Option(None, "--format", metavar="table|json|csv", help=FORMAT_HELP, show_default=False)

#: the output formats of every command that prints tables
FORMATS = ("table", "json", "csv")
DigitsOpt = typer.Option(6, "--digits", min=1, max=17, help=DIGITS_HELP)
UnitsOpt = typer.Option(None, "--units", help=UNITS_HELP, show_default=False)


from rbcli.cli.app import debug  # noqa: E402,F401  (lives in app: main() needs it first)


#: where a command's declared parameters go among its typer options (:func:`command`)
PARAMS = object()


def command(params: Any, *, name: str | None = None, help: str | None = None):
    """Register the decorated function as a typer command: its own parameters, plus, in
    place of a parameter ``args = PARAMS``, the options of the table ``params``, which it
    receives as ``args`` (values as typed, None when not given). A flag is ``--`` + the name
    with dashes or the command's own word (:data:`rbcli.errors.COMMAND_OPTIONS`); its help
    spells parameters as options; ``form`` "argument" is positional, "options" a list."""
    import inspect

    from rbcli.cli.app import app

    def wrap(fn):
        cmd = name or fn.__name__.replace("_", "-")
        spelled = lambda p: option_name(p, cmd)  # noqa: E731
        table = [p for p in params if p.cli]
        own = list(inspect.signature(fn, eval_str=True).parameters.values())
        at = [q.name for q in own].index("args")
        opts, words = [], {}
        for p in table:
            flag = spelled(p.name)
            kind = list[str] if p.form == "options" else \
                p.cli_type or {"count": int, "flag": bool}.get(p.kind, str)
            how = dict(help=spell(p.help, spelled), metavar=p.metavar, show_default=p.default is not None)
            info = (typer.Argument(p.default, **how) if p.form == "argument"
                    else typer.Option(p.default, flag, **how))
            words[p.name] = p.name if p.form == "argument" else flag.lstrip("-").replace("-", "_")
            opts.append(inspect.Parameter(words[p.name], inspect.Parameter.KEYWORD_ONLY,
                                          default=info, annotation=kind))
        many = {p.name for p in table if p.form == "options"}

        def run(**kw):
            args = {name: (kw.pop(word) or None) if name in many else kw.pop(word)
                    for name, word in words.items()}
            return fn(args=args, **kw)

        run.__name__, run.__qualname__, run.__module__ = fn.__name__, fn.__qualname__, fn.__module__
        run.__doc__ = fn.__doc__
        run.__signature__ = inspect.Signature(
            [q.replace(kind=inspect.Parameter.KEYWORD_ONLY) for q in own[:at]] + opts
            + [q.replace(kind=inspect.Parameter.KEYWORD_ONLY) for q in own[at + 1:]])
        app.command(name=cmd, help=help)(run)
        return fn

    return wrap


def said(x: object) -> str:
    """A warning (:class:`rbcli.errors.Note`) or an error as the command line says it:
    parameters spelled as options (``--radius``); anything else as ``str``."""
    from rbcli.errors import RbcliError, option_name, spelled

    if isinstance(x, RbcliError):
        return x.spelled(option_name)
    return spelled(x, option_name) if isinstance(x, str) else str(x)


def said_json(data: Any) -> Any:
    """A JSON document with its warnings and remarks (:class:`rbcli.errors.Note`) spelled as
    the command line says them (the API's ``to_json()`` names parameters, ``--json`` options)."""
    return spelled_data(data, option_name)


def with_file(data: dict, source: str) -> dict:
    """A result's JSON with ``"file"`` after ``"name"`` (where the commands print it)."""
    out = {}
    for k, v in data.items():
        out[k] = v
        if k == "name":
            out["file"] = source
    return out


def start(json_: bool, fmt: str | None, units: str | None, *, shop: bool = False,
          extra: tuple[str, ...] = ()):
    """What every command does first: (the environment, :func:`output_format`, the table
    units of ``--units``: :class:`rbcli.render.units.DisplayUnits`, or
    :class:`~rbcli.render.units.ShopUnits` with ``shop``); bad values exit 2 before any body."""
    from rbcli.render.units import DisplayUnits, ShopUnits

    e = env()
    out = output_format(json_, fmt, extra)
    return e, out, ShopUnits(units) if shop else DisplayUnits.parse(units)


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
    """Load one body (a body file, ``-e``, or a STEP, STL or OBJ file with the command's
    :data:`rbcli.api.commands.BODY` options) and show its warnings on standard error."""
    import gc

    from rbcli.api.load import load as load_file
    from rbcli.body.model import load_expr

    # The command line's choice, not the library's (gc is process-wide): no cyclic collection
    # while the (acyclic) body is read: rescans were 60 % of the CPU of a 100 000-part body;
    # then gc.freeze, as a command keeps its body to the end (frozen objects are still freed).
    was = gc.isenabled()
    gc.disable()
    try:
        keys = _body_keys()
        if source == "<expr>" and expr is not None and not any(keys.values()):
            body = load_expr(expr)
        else:
            body = load_file(source, **keys)
    finally:
        if was:
            gc.enable()
    gc.freeze()
    for w in body.warnings:
        e.warn(f"rbcli: {said(w)}")
    return body


def _body_keys() -> dict[str, Any]:
    """The BODY options of the command run (its typer context's)."""
    from typer._click.globals import get_current_context

    ctx = get_current_context(silent=True)
    return {p.name: ctx.params.get(p.name) if ctx else None for p in BODY}


def without_body(args: dict[str, Any]) -> dict[str, Any]:
    """A command's table values less its BODY options."""
    return {k: v for k, v in args.items() if k not in {p.name for p in BODY}}


def load_one(body: str | None, expr: str | None, e: Any):
    """The one body of a single-body command (a path, '-', or -e), with its warnings shown."""
    return load(sources([body] if body is not None else None, expr, single=True)[0], expr, e)


def output_paths(b: Any, *, plot: str | None = None, csv: str | None = None) -> tuple:
    """(plot path, csv path), checked before any computing; ``--csv -`` (stdout) gives None."""
    plot_path = csv_path = None
    if plot is not None:
        plot_path = check_plot(plot, b)
    if csv not in (None, "-"):
        from rbcli.io.outfile import check

        csv_path = check(csv, b, "--csv", replace_ok=True, others={"--plot": plot_path})
    return plot_path, csv_path


#: figure formats --plot writes (the extension decides)
PLOT_FORMATS = ("png", "svg", "pdf")


def check_plot(path: str, inputs: Any = (), *, others: Any = None):
    """The --plot path, checked before anything is computed (:func:`rbcli.io.outfile.check`):
    a known extension, not an input (the Body or input paths), an existing figure replaced."""
    from rbcli.io import outfile

    return outfile.check(path, inputs, "--plot", exts=PLOT_FORMATS, replace_ok=True, others=others)


def save_plot(fig: Any, path: Any, option: str = "--plot") -> None:
    """Write a figure made by render to ``path`` (checked), atomically; format from the
    extension."""
    from rbcli.io.outfile import write_atomic
    from rbcli.render.plots import figure_bytes

    write_atomic(path, figure_bytes(fig, path.suffix), option)


def write_csv(e: Any, path: Any, header: Any, blocks: Any, option: str = "--csv") -> int:
    """The CSV of a time series: to ``path`` atomically, or (path None) to standard output,
    where a closed pipe (``| head``) stops it quietly. Returns the rows written."""
    from rbcli.render.csvout import write

    if path is None:
        def sink(text: str) -> bool:
            e.write(text)
            return not e.pipe_closed

        return write(sink, header, blocks)
    from rbcli.io.outfile import atomic_open

    with atomic_open(path, option) as fh:
        return write(fh.write, header, blocks)


def each_body(srcs: list[str], expr: str | None, e: Any) -> Iterator[tuple[str, Any]]:
    """Yield (source, Body or InputError) for the sources of :func:`sources`, so batch runs
    go on past a bad file."""
    for src in srcs:
        try:
            yield src, load(src, expr, e)
        except InputError as exc:
            yield src, exc


# --- output


def write_doc(e: Any, doc: Any) -> None:
    """Render a document of tables to standard output, refusing inf and NaN
    (:func:`rbcli.render.text.check_finite_doc`)."""
    from rbcli.render.text import check_finite_doc

    check_finite_doc(doc)
    e.write(doc.render())


def output_format(json_: bool, fmt: str | None, extra: tuple[str, ...] = ()) -> str:
    """The output format from ``--json`` and ``--format`` (``--json`` is ``--format json``):
    "table", "json", "csv" or one of ``extra`` (e.g. inertia's "urdf")."""
    allowed = FORMATS + tuple(extra)
    if fmt is None:
        return "json" if json_ else "table"
    f = fmt.strip().lower()
    if f not in allowed:
        raise InputError(f"--format must be {', '.join(allowed[:-1])} or {allowed[-1]}, not '{fmt}'")
    if json_ and f != "json":
        raise InputError(f"--json and --format {f} ask for two formats; give one")
    return f


def emit(e: Any, fmt: bool | str, data_fn: Any, doc_fn: Any, *, lines: bool = False,
         file: str | None = None, given: Any = (), plain: bool = False, header: bool = True) -> None:
    """Print a command's result in format ``fmt`` (:func:`output_format`; True = "json",
    False = "table"), building only that one: JSON of ``data_fn()`` (one line with ``lines``),
    that JSON as a CSV table (:mod:`rbcli.render.tablecsv`; ``file``, ``header``), or the
    tables ``doc_fn(doc)`` makes. inf and NaN are refused (exit 2). ``given``: the options
    table's rows (:func:`rbcli.render.echo.echo_rows`) or a function making them; ``plain``:
    ``data_fn()`` is already jsonable."""
    fmt = {True: "json", False: "table"}.get(fmt, fmt) if isinstance(fmt, bool) else fmt
    if fmt in ("json", "csv"):
        data = data_fn()
        if not plain:
            from rbcli.api.result import jsonable

            data = jsonable(data)
        data = said_json(data)
        if fmt == "json":
            from rbcli.render.jsonout import dumps

            e.write(dumps(data, lines=lines))
        else:
            from rbcli.api.commands import TABLES
            from rbcli.api.params import si_unit
            from rbcli.render import tablecsv

            command, digits = _invocation()
            units = {p.name: si_unit(p) for p in TABLES.get(command, ())}
            e.write(tablecsv.render(data, command, digits=digits, file=file, header=header,
                                    params=units))
        return
    from rbcli.render.text import Doc

    doc = Doc(e)
    doc_fn(doc)
    if callable(given):
        given = given()
    if given:
        from rbcli.render.text import Heading

        at = 1 if doc.items and isinstance(doc.items[0], Heading) else 0
        doc.table("options", ("option", "value", "unit"), given, right=(1,))
        doc.items.insert(at, doc.items.pop())
    write_doc(e, doc)


def _invocation() -> tuple[str, int | None]:
    """(the command's name, ``--digits`` if it was typed, else None): the CSV's numbers are
    at full precision unless ``--digits`` was typed (its default, 6, is for the tables)."""
    from typer._click.core import ParameterSource
    from typer._click.globals import get_current_context

    ctx = get_current_context(silent=True)
    if ctx is None:
        return "", None
    digits = ctx.params.get("digits")
    if ctx.get_parameter_source("digits") in (None, ParameterSource.DEFAULT):
        digits = None
    return ctx.info_name or "", digits


def finish(status: int | ExitStatus) -> None:
    if int(status) != 0:
        raise typer.Exit(int(status))
