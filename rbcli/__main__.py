"""The ``rbcli`` process: ``python -m rbcli`` and the ``rbcli`` console script.

Importing it installs the signal handlers (:mod:`rbcli.interrupts`) before anything else,
then imports the command line (one that cannot be imported: its traceback, exit 70).
:func:`main` runs :func:`rbcli.cli.main` and ends the process with its exit status.
"""

from rbcli import interrupts


def main() -> None:
    """Run the command line with ``sys.argv`` and end the process; never returns."""
    interrupts.start()
    code = 0
    try:
        if not interrupts.received():  # a signal during the imports: nothing to run
            code = run_cli()
    except KeyboardInterrupt:  # a signal before rbcli.cli.main could take it
        code = 0  # recorded: exit_process makes it 128 + the signal
    except SystemExit as exc:
        code = exc.code if isinstance(exc.code, int) else 0 if exc.code is None else 1
    except BaseException as exc:  # noqa: BLE001 - what escapes rbcli.cli.main is a bug
        interrupts.exit_process(70, exc)
    interrupts.exit_process(code)


interrupts.install(quiet=[main.__code__])
try:  # after the handlers: a signal during these imports waits for main (interrupts)
    from rbcli.cli import main as run_cli  # noqa: E402
except Exception as exc:  # noqa: BLE001 - a broken installation
    interrupts.exit_process(70, exc)

if __name__ == "__main__":
    main()
