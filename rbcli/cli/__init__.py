"""rbcli's command line: the typer app, its commands, and the one place errors become exit codes.

Module level imports only typer and the standard library; a command's module is imported
when that command runs (rbcli.cli.app.COMMANDS), and each command imports numpy, the io
layer and the physics it needs inside its function.
"""

from __future__ import annotations

import sys

import typer

from rbcli.cli.app import COMMANDS, COMPLETE_VAR, app, completion_init, completion_state_ok
from rbcli.errors import ExitStatus, RbcliError, option_name

__all__ = ["app", "main"]


def main(argv: list[str] | None = None) -> int:
    """Run the command line with ``argv`` (default ``sys.argv[1:]``); the exit status.

    The one place where everything that ends a run becomes one of SPEC §4's exit codes (typer
    runs with ``standalone_mode=False``): a usage error or bad input is one line and 2; a
    failed check 1; SIGINT, SIGTERM, SIGHUP 130, 143, 129 (raised as exceptions, so no
    temporary file is left: :mod:`rbcli.interrupts`); anything else a bug, 70 (a traceback
    under ``--debug`` or ``RBCLI_DEBUG=1``). A pipe closed early is quiet; standard output
    closed or full is 2 with a message; a terminal that cannot show ``²`` gets ASCII; every
    message is made safe once, here (:func:`rbcli.env.clean`)."""
    from rbcli import env as _env

    _env.prepare_streams()
    _env.prepare_blas()
    args = sys.argv[1:] if argv is None else list(argv)
    old_signals = _env.handle_signals()
    try:
        code = _run(args)
        code = _env.finish_stdout(_env.signalled_status(code))
    except KeyboardInterrupt as exc:  # a signal while finishing
        code = _interrupted(exc)
    finally:
        _env.restore_signals(old_signals)
    return code


def _interrupted(exc: BaseException) -> int:
    """The exit status of a run ended by a signal (128 + it), its one line written."""
    from rbcli import interrupts

    return interrupts.status(exc)


def _run(args: list[str]) -> int:
    """Run the command line; its exit status (see :func:`main`)."""
    import warnings

    from rbcli import env as _env
    from rbcli.cli.app import debug

    import os

    if os.environ.get(COMPLETE_VAR):  # a shell asks for completions (rbcli --show-completion)
        if not completion_state_ok(os.environ):
            return 0  # malformed completion state: no candidates
        completion_init()
    _env.prepare_matplotlib()
    with warnings.catch_warnings():
        if not debug():
            # numpy's "overflow encountered in multiply" and the like, with a line of source:
            # not a message for a user. A result that is inf or NaN is refused on its way out
            # (api.result.jsonable, common.write_doc) as one line, exit 2.
            warnings.filterwarnings(
                "ignore", category=RuntimeWarning,
                message=r"(overflow|invalid value|divide by zero|underflow) encountered",
            )
            warnings.showwarning = _env.show_warning  # one clean line, no source paths
        return _run_app(args)


def _run_app(args: list[str]) -> int:
    from rbcli.cli.app import debug

    try:
        code = app(args=args, prog_name="rbcli", standalone_mode=False)
    except SystemExit as exc:
        return 0 if exc.code is None else exc.code if isinstance(exc.code, int) else 1
    except RbcliError as exc:
        _say(f"rbcli: {exc.spelled(option_name)}")
        return int(exc.exit_status)
    except typer.TyperException as exc:  # click's UsageError, BadParameter, NoSuchOption, ...
        return _usage_error(exc, args)
    except typer.Abort as exc:  # click turns Ctrl-C (and our SIGTERM) into Abort
        return _interrupted(exc.__cause__ or exc.__context__ or exc)
    except (OverflowError, ZeroDivisionError, FloatingPointError) as exc:
        _say(
            f"rbcli: a value is too large or too small to compute with ({exc or type(exc).__name__}); "
            "check the options and the body's numbers"
        )
        return int(ExitStatus.BAD_INPUT)
    except BrokenPipeError:
        from rbcli.env import silence_stdout

        silence_stdout()
        return 0
    except KeyboardInterrupt as exc:  # Ctrl-C, SIGTERM, SIGHUP: cleanups have run
        return _interrupted(exc)
    except MemoryError:
        _say("rbcli: out of memory; the input is too large for this machine (see README, "
             "'Budgets')")
        return int(ExitStatus.BAD_INPUT)
    except OSError as exc:
        import errno

        if exc.errno in (errno.ENOSPC, errno.EDQUOT, errno.EFBIG, errno.EIO, errno.EROFS, errno.EBADF):
            # a stream or a file that cannot take what is written (a full disk, /dev/full)
            _say(f"rbcli: cannot write: {(exc.strerror or str(exc)).lower()}")
            return int(ExitStatus.BAD_INPUT)
        return _internal(exc, args, debug())
    except Exception as exc:  # an internal error: a bug
        return _internal(exc, args, debug())
    # a command returns None when done, typer.Exit(n) ends as n (c.finish, --help, --version)
    if code == ExitStatus.INTERRUPTED:  # typer's own answer to a KeyboardInterrupt (Exit(130))
        return _interrupted(KeyboardInterrupt())
    return code if isinstance(code, int) else 0


def _internal(exc: BaseException, args: list[str], debug: bool) -> int:
    from rbcli import interrupts

    if interrupts.received() or _caused_by_interrupt(exc):
        # an error that a signal caused (a KeyboardInterrupt wrapped in a RuntimeError by
        # class creation, a module left half-imported): the signal is the answer
        return _interrupted(exc)
    if debug:
        import traceback

        traceback.print_exc()
    command = next((a for a in args if not a.startswith("-")), "COMMAND")
    _say(
        f"rbcli: internal error ({type(exc).__name__}: {exc}); this is a bug — please report "
        f"it with the output of 'rbcli --debug {command} ...' (or the same command with "
        "RBCLI_DEBUG=1)"
    )
    return int(ExitStatus.INTERNAL)


def _caused_by_interrupt(exc: BaseException) -> bool:
    """Whether a KeyboardInterrupt is among the causes or contexts of ``exc``."""
    seen: set[int] = set()
    e: BaseException | None = exc
    while e is not None and id(e) not in seen:
        if isinstance(e, KeyboardInterrupt):
            return True
        seen.add(id(e))
        e = e.__cause__ or e.__context__
    return False


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
    word = next((a for a in args if not a.startswith("-")), None)
    return word if word in COMMANDS else None


def _say(text: str) -> None:
    """One message line on standard error, made safe (control characters escaped, long
    values cut: :func:`rbcli.env.clean`); a closed or full stderr changes nothing else."""
    from rbcli.env import write_error

    write_error(text)
