"""rbcli's command line: the typer app, its commands, and the one place errors become exit codes.

Module level imports only typer and the standard library; each command imports
numpy, the io layer and the physics it needs inside its function.
"""

from __future__ import annotations

import sys

from rbcli.cli.app import STATE, app
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
    """Entry point of the ``rbcli`` console script; never returns."""
    try:
        app(args=argv, prog_name="rbcli")
    except SystemExit:
        raise
    except RbcliError as exc:
        _say(f"rbcli: {exc}")
        sys.exit(int(exc.exit_status))
    except BrokenPipeError:
        from rbcli.env import _silence_stdout

        _silence_stdout()
        sys.exit(0)
    except KeyboardInterrupt:
        sys.exit(int(ExitStatus.INTERRUPTED))
    except Exception as exc:  # an internal error: a bug
        if STATE["debug"]:
            import traceback

            traceback.print_exc()
        _say(
            f"rbcli: internal error ({type(exc).__name__}: {exc}); this is a bug — "
            "please report it with the output of the same command run with --debug"
        )
        sys.exit(int(ExitStatus.INTERNAL))


def _say(text: str) -> None:
    try:
        sys.stderr.write(text.rstrip("\n") + "\n")
        sys.stderr.flush()
    except (BrokenPipeError, ValueError):
        pass
