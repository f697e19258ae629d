"""The typer application object every command module registers on.

Module level imports only typer and the standard library (start-up is a feature).
"""

from __future__ import annotations

import typer

from rbcli import __version__

HELP = """rbcli — mass properties and the motion of rigid bodies, from a YAML body file.

Describe a body once (boxes, cylinders, plates, point masses, holes, meshes,
sub-assemblies, with units) and ask it questions. Every command takes a BODY file,
'-' for standard input, or inline YAML with -e. Tables for people, --json for
scripts. Exit status: 0 done, 1 a check you asked for failed, 2 bad usage or
input, 70 internal error (a bug).
"""

# --- commands
# Each command's module registers it on ``app`` when imported; importing them all cost
# ~11 ms CPU a run. So the root group's ``commands`` is a mapping that builds a command the
# first time it is looked up; `rbcli --help` lists COMMANDS' one-line help without importing
# anything (tests/test_cli_options.py checks it against the commands' real help).

#: command -> (the module that registers it, the one-line help `rbcli --help` lists: the
#: first sentence of its help text), in the order `rbcli --help` lists them
COMMANDS: dict[str, tuple[str, str]] = {
    "inertia": ("massprops", "Mass, centre of mass and the inertia tensor about a point."),
    "principal": ("massprops", "Principal moments and axes, symmetry, and which free rotations "
                               "are stable."),
    "shapes": ("catalog", "The shape catalogue: parameters, local origin, mass keys and formulas."),
    "materials": ("catalog", "The built-in materials: density and where it is from."),
    "schema": ("catalog", "The JSON Schema (draft-07) of the body file, for editors."),
    "examples": ("catalog", "List the bundled example bodies, or print one."),
    "balance": ("balance", "Rotor balance about a shaft: unbalance, two-plane corrections, "
                           "bearing forces, ISO 21940-11."),
    "field-balance": ("fieldbalance", "Field (trial-weight) balancing from vibration readings: the "
                                 "influence-coefficient method."),
    "rollcheck": ("rollcheck", "Stability of a wheel, disk or hoop rolling on a rough floor: the "
                               "critical speed."),
    "precess": ("precess", "Torque-free motion from an initial angular velocity: L, T, "
                           "precession, period, flips."),
    "top": ("top", "A heavy symmetric top or gyroscope on a fixed pivot: precession, nutation, "
                   "sleeping."),
    "gyrocompass": ("top", "A gyrocompass: the period of its swing about north and where it "
                           "settles."),
    "whirl": ("whirl", "The rotor on its bearings: critical speeds, Campbell diagram, unbalance "
                       "response."),
    "report": ("report", "One document with every answer that applies to the body, its tables "
                         "and figures."),
}


class _Commands(dict):
    """The root group's commands: built on first lookup (see COMMANDS above)."""

    def __init__(self, built: dict) -> None:
        super().__init__(built)
        self._order = [*COMMANDS, *(k for k in built if k not in COMMANDS)]

    def _build(self, name: str):
        import importlib

        import typer.main as tmain

        importlib.import_module(f"rbcli.cli.{COMMANDS[name][0]}")  # registers it on app
        for info in app.registered_commands:
            if (info.name or tmain.get_command_name(info.callback.__name__)) == name:
                cmd = tmain.get_command_from_info(
                    info, pretty_exceptions_short=app.pretty_exceptions_short,
                    rich_markup_mode=app.rich_markup_mode)
                dict.__setitem__(self, name, cmd)
                return cmd
        raise KeyError(name)

    def __missing__(self, name: str):
        if name not in COMMANDS:
            raise KeyError(name)
        return self._build(name)

    def get(self, name, default=None):
        try:
            return self[name]
        except KeyError:
            return default

    def __contains__(self, name) -> bool:
        return dict.__contains__(self, name) or name in COMMANDS

    def __iter__(self):
        return iter(self._order)

    def __len__(self) -> int:
        return len(self._order)

    def keys(self):
        return list(self._order)

    def items(self):
        return [(k, self[k]) for k in self._order]

    def values(self):
        return [self[k] for k in self._order]


class _Group(typer.core.TyperGroup):
    """typer's group with lazily built commands and a help listing from COMMANDS."""

    def __init__(self, *, commands=None, **kw) -> None:
        super().__init__(**kw)
        self.commands = _Commands(dict(commands or {}))

    def format_commands(self, ctx, formatter) -> None:
        from typer._click.utils import make_default_short_help

        names = [n for n in COMMANDS]
        limit = formatter.width - 6 - max(len(n) for n in names)
        rows = [(n, make_default_short_help(COMMANDS[n][1], limit)) for n in names]
        with formatter.section("Commands"):
            formatter.write_dl(rows)


def command_tree():
    """The root click group with every command built (for man pages and tests)."""
    import typer.main

    group = typer.main.get_command(app)
    group.commands.items()
    return group


app = typer.Typer(
    name="rbcli",
    cls=_Group,
    help=HELP,
    add_completion=False,  # rbcli declares --show-completion SHELL itself (below)
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,
    context_settings={"help_option_names": ["-h", "--help"], "max_content_width": 100},
)

STATE = {"debug": False}


def debug() -> bool:
    """Tracebacks for internal errors: the root ``--debug`` or ``RBCLI_DEBUG=1``."""
    import os

    return bool(STATE["debug"]) or os.environ.get("RBCLI_DEBUG", "").strip() not in ("", "0")


# --- start-up
# typer 0.29 coerces every value through a pydantic TypeAdapter (~50 ms of CPU a run:
# bench/README.md, "Start-up"). _Plain gives typer's value where it is obvious (a str, a
# plain decimal number inside its min/max, None) and leaves every other to typer's own
# coercion, built lazily, so results and messages stay typer's.

_INT = None  # compiled on first use: re is imported by typer already, but keep it lazy
_FLOAT = None


def _int_text(value: str) -> int | None:
    global _INT
    if _INT is None:
        import re

        _INT = re.compile(r"[+-]?[0-9]{1,18}")
    return int(value) if _INT.fullmatch(value) else None


def _float_text(value: str) -> float | None:
    global _FLOAT
    if _FLOAT is None:
        import re

        _FLOAT = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]{1,3})?")
    if not _FLOAT.fullmatch(value):
        return None
    x = float(value)
    return x if x - x == 0.0 else None  # inf (1e999) goes to pydantic


class _Plain:
    """typer's coercion of a str, int, float or bool parameter (or a list of one)."""

    __slots__ = ("_desc", "_kind", "_lo", "_hi", "_slow", "_build")

    def __init__(self, desc, kind: type, build) -> None:
        self._desc = desc
        self._kind = kind
        self._lo = desc.parameter_info.min
        self._hi = desc.parameter_info.max
        self._slow = None
        self._build = build

    def _one(self, v):
        """(True, coerced) when the result is certain, else (False, None)."""
        k = self._kind
        t = type(v)
        if k is str:
            return (True, v) if t is str else (False, None)
        if k is bool:
            return (True, v) if t is bool else (False, None)
        if k is int:
            x = v if t is int else (_int_text(v) if t is str else None)
        else:  # float
            x = float(v) if t is float or t is int else (_float_text(v) if t is str else None)
        if x is None or (self._lo is not None and x < self._lo) or (self._hi is not None and x > self._hi):
            return False, None
        return True, x

    def coerce(self, value, param, ctx):
        multi = param.multiple or param.nargs == -1
        if value is None:
            return () if multi else None
        if multi:
            if isinstance(value, (list, tuple)):
                out = []
                for v in value:
                    ok, x = self._one(v)
                    if not ok:
                        break
                    out.append(x)
                else:
                    return out
        else:
            ok, x = self._one(value)
            if ok:
                return x
        if self._slow is None:
            self._slow = self._build(self._desc)
        return self._slow.coerce(value, param=param, ctx=ctx)


def _fast_coercion() -> None:
    try:
        from typer import core as tcore
        from typer._coercion import build_runtime_param
    except ImportError:  # another typer: leave it alone
        return
    if getattr(tcore, "build_runtime_param", None) is not build_runtime_param or not hasattr(
        getattr(tcore, "_TyperParameter", None), "get_runtime_param"
    ):
        return
    from typing import get_args, get_origin

    plain = (str, int, float, bool)

    def build(desc):
        info = desc.parameter_info
        ann = desc.annotation
        kind = ann
        if get_origin(ann) is list and len(get_args(ann)) == 1:
            kind = get_args(ann)[0]
        if (
            kind in plain
            and getattr(desc, "file_annotation", 0) is None
            and getattr(info, "parser", 0) is None
            and getattr(info, "click_type", None) is None
            and not getattr(info, "clamp", True)
            and hasattr(info, "min")
            and hasattr(info, "max")
        ):
            return _Plain(desc, kind, build_runtime_param)
        return build_runtime_param(desc)

    tcore.build_runtime_param = build


_fast_coercion()

#: What the man pages say beyond the options, per command: "json" (the keys and their
#: meaning, roff-free text), "examples" (list of (command, what it prints)), "notes".
#: Each command module fills in its own entry; ``rbcli.cli.manpages`` writes man/.
MANUAL: dict[str, dict] = {}


def _version(ctx: typer.Context, value: bool) -> None:
    if value and not ctx.resilient_parsing:  # not while a shell asks for completions
        typer.echo(f"rbcli {__version__}")
        raise typer.Exit()


#: shells typer's completion scripts support
SHELLS = ("bash", "zsh", "fish", "powershell", "pwsh")
#: the environment variable a completion script sets when it asks rbcli for candidates
COMPLETE_VAR = "_RBCLI_COMPLETE"


def completion_init() -> None:
    """Register typer's completion classes (its scripts for bash, zsh, fish, PowerShell).

    Called only when a shell asks for completions or a script is wanted, so start-up is
    unchanged otherwise."""
    from typer.completion import completion_init as init

    init()


#: the longest COMP_CWORD read (a word index; bash's command lines are far shorter)
MAX_CWORD_DIGITS = 6


def completion_state_ok(environ) -> bool:
    """Whether a shell's request for completions (``COMPLETE_VAR`` set) can be answered.

    typer would fail (exit 70) on bash's ``COMP_CWORD`` that is not a word index (``x``,
    ``-1``, beyond the words) or a missing ``COMP_WORDS``: such a shell gets no candidates,
    quietly (exit 0). The other shells' variables typer reads with defaults.
    """
    instruction = environ.get(COMPLETE_VAR, "")
    if not (instruction.startswith("complete_") and instruction.endswith("_bash")):
        return True
    words, cword = environ.get("COMP_WORDS"), environ.get("COMP_CWORD")
    if words is None or cword is None:
        return False
    if not (cword.isascii() and cword.isdigit() and len(cword) <= MAX_CWORD_DIGITS):
        return False
    from typer._click.shell_completion import split_arg_string

    return int(cword) <= len(split_arg_string(words))


def _shell(value: str) -> str:
    shell = value.strip().lower()
    if shell not in SHELLS:
        raise typer.BadParameter(f"'{value}' is not a shell rbcli completes; use one of "
                                 f"{', '.join(SHELLS)}")
    return shell


def _show_completion(ctx: typer.Context, value: str | None) -> None:
    if value is None or ctx.resilient_parsing:  # not while a shell asks for completions
        return
    shell = _shell(value)
    completion_init()
    from typer._completion_shared import get_completion_script

    typer.echo(get_completion_script(prog_name="rbcli", complete_var=COMPLETE_VAR, shell=shell))
    raise typer.Exit()


def _install_completion(ctx: typer.Context, value: str | None) -> None:
    # never while a shell asks for completions: `rbcli --install-completion bash <TAB>`
    # wrote into ~/.bashrc
    if value is None or ctx.resilient_parsing:
        return
    shell = _shell(value)
    completion_init()
    from typer._completion_shared import install

    shell, path = install(shell=shell, prog_name="rbcli", complete_var=COMPLETE_VAR)
    typer.echo(f"{shell} completion installed in {path}; it takes effect in a new shell")
    raise typer.Exit()


@app.callback()
def root(
    ctx: typer.Context,
    version: bool = typer.Option(
        False, "--version", callback=_version, is_eager=True, help="Print the version and exit."
    ),
    show_completion: str = typer.Option(
        None, "--show-completion", callback=_show_completion, is_eager=True, metavar="SHELL",
        expose_value=False, show_default=False,
        help="Print the completion script for SHELL (bash, zsh, fish, powershell), e.g. "
             "'eval \"$(rbcli --show-completion bash)\"'.",
    ),
    install_completion: str = typer.Option(
        None, "--install-completion", callback=_install_completion, is_eager=True,
        metavar="SHELL", expose_value=False, show_default=False,
        help="Install completion for SHELL (bash, zsh, fish, powershell) in its start-up file.",
    ),
    debug: bool = typer.Option(
        False, "--debug", help="Show a traceback for internal errors (also: RBCLI_DEBUG=1)."
    ),
) -> None:
    STATE["debug"] = debug
    from rbcli.errors import COMMAND

    COMMAND.set(ctx.invoked_subcommand)  # messages name parameters by this command's options
