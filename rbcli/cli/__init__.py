"""rbcli's command line: the typer app, its commands, and the one place errors become exit codes.

Module level imports only typer and the standard library; each command imports
numpy, the io layer and the physics it needs inside its function.
"""

from __future__ import annotations

import sys

import typer

from rbcli.cli.app import COMPLETE_VAR, app, completion_init
from rbcli.cli import massprops as _massprops  # noqa: F401  (registers inertia, principal)
from rbcli.cli import catalog as _catalog  # noqa: F401  (registers shapes, schema, examples)
from rbcli.cli import balance as _balance  # noqa: F401  (registers balance)
from rbcli.cli import rollcheck as _rollcheck  # noqa: F401  (registers rollcheck)
from rbcli.cli import precess as _precess  # noqa: F401  (registers precess)
from rbcli.cli import top as _top  # noqa: F401  (registers top, gyrocompass)
from rbcli.cli import report as _report  # noqa: F401  (registers report)
from rbcli.errors import ExitStatus, RbcliError

__all__ = ["app", "main"]


def main(argv: list[str] | None = None) -> None:
    """Entry point of the ``rbcli`` console script; never returns.

    typer runs with ``standalone_mode=False``, so everything that ends a run comes back
    here and becomes one of SPEC §4's exit codes: a usage error (click's) or bad input
    (InputError, a result too large or too small to compute with) is one line on standard
    error and exit 2; a failed check returns 1 from the command; Ctrl-C is 130; anything
    else is a bug (70), with a traceback under ``--debug`` or ``RBCLI_DEBUG=1``.
    """
    from rbcli.cli.common import debug

    args = sys.argv[1:] if argv is None else list(argv)
    import os

    if os.environ.get(COMPLETE_VAR):  # a shell asks for completions (rbcli --show-completion)
        completion_init()
    if not debug():
        import warnings

        # numpy's "overflow encountered in multiply" and the like, with a line of source:
        # not a message for a user. A result that is inf or NaN is refused on its way out
        # (render.jsonout.jsonable, common.write_doc) as one line, exit 2.
        warnings.filterwarnings(
            "ignore", category=RuntimeWarning,
            message=r"(overflow|invalid value|divide by zero|underflow) encountered",
        )
    try:
        code = app(args=args, prog_name="rbcli", standalone_mode=False)
    except SystemExit:
        raise
    except RbcliError as exc:
        _say(f"rbcli: {exc}")
        sys.exit(int(exc.exit_status))
    except typer.TyperException as exc:  # click's UsageError, BadParameter, NoSuchOption, ...
        sys.exit(_usage_error(exc, args))
    except typer.Abort:
        sys.exit(int(ExitStatus.INTERRUPTED))
    except (OverflowError, ZeroDivisionError, FloatingPointError) as exc:
        _say(
            f"rbcli: a value is too large or too small to compute with ({exc or type(exc).__name__}); "
            "check the options and the body's numbers"
        )
        sys.exit(int(ExitStatus.BAD_INPUT))
    except BrokenPipeError:
        from rbcli.env import silence_stdout

        silence_stdout()
        sys.exit(0)
    except KeyboardInterrupt:
        sys.exit(int(ExitStatus.INTERRUPTED))
    except Exception as exc:  # an internal error: a bug
        if debug():
            import traceback

            traceback.print_exc()
        command = next((a for a in args if not a.startswith("-")), "COMMAND")
        _say(
            f"rbcli: internal error ({type(exc).__name__}: {exc}); this is a bug — please report "
            f"it with the output of 'rbcli --debug {command} ...' (or the same command with "
            "RBCLI_DEBUG=1)"
        )
        sys.exit(int(ExitStatus.INTERNAL))
    # a command returns None when done, typer.Exit(n) ends as n (c.finish, --help, --version)
    sys.exit(code if isinstance(code, int) else 0)


def _usage_error(exc: Exception, args: list[str]) -> int:
    """Print a click usage error as one line; return its exit status."""
    code = int(getattr(exc, "exit_code", 2))
    if type(exc).__name__ == "NoArgsIsHelpError":  # `rbcli` alone: the help, as before
        exc.show()  # type: ignore[attr-defined]
        return code
    ctx = getattr(exc, "ctx", None)
    param = getattr(exc, "param", None)
    message = getattr(exc, "message", "") or str(exc)
    if param is not None and getattr(param, "param_type_name", "") == "option" and \
            type(exc).__name__ == "BadParameter":
        name = max(param.opts, key=len) if param.opts else param.name
        text = f"{name}: {message}"
    else:
        text = exc.format_message()  # type: ignore[attr-defined]
    text = " ".join(str(text).split())
    if ctx is not None:
        command = ctx.info_name if ctx.parent is not None else None
    else:  # the option parser's errors carry no context: the command is the first word
        command = _command_in(args)
    if command:
        _say(f"rbcli: {command}: {text} (see 'rbcli {command} --help')")
    else:
        _say(f"rbcli: {text} (see 'rbcli --help')")
    return code


def _command_in(args: list[str]) -> str | None:
    """The command named in args (after the root's options), if it is one of rbcli's."""
    import typer.main

    names = typer.main.get_command(app).commands  # type: ignore[attr-defined]
    word = next((a for a in args if not a.startswith("-")), None)
    return word if word in names else None


def _say(text: str) -> None:
    try:
        sys.stderr.write(text.rstrip("\n") + "\n")
        sys.stderr.flush()
    except (BrokenPipeError, ValueError):
        pass
