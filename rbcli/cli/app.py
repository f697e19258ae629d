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

app = typer.Typer(
    name="rbcli",
    help=HELP,
    add_completion=False,
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,
    context_settings={"help_option_names": ["-h", "--help"], "max_content_width": 100},
)

STATE = {"debug": False}

#: What the man pages say beyond the options, per command: "json" (the keys and their
#: meaning, roff-free text), "examples" (list of (command, what it prints)), "notes".
#: Each command module fills in its own entry; ``rbcli.cli.manpages`` writes man/.
MANUAL: dict[str, dict] = {}


def _version(value: bool) -> None:
    if value:
        typer.echo(f"rbcli {__version__}")
        raise typer.Exit()


@app.callback()
def root(
    version: bool = typer.Option(
        False, "--version", callback=_version, is_eager=True, help="Print the version and exit."
    ),
    debug: bool = typer.Option(False, "--debug", help="Show a traceback for internal errors."),
) -> None:
    STATE["debug"] = debug
