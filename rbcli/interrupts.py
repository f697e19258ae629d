"""SIGINT, SIGTERM and SIGHUP at any moment: one line on standard error and exit status
128 + the signal (130, 143, 129), no traceback, no half-written file, no native abort.

Only what the interpreter has already loaded (``signal`` would import ``enum``, ~3 ms):
``rbcli.__main__`` calls :func:`install` before any other import.

A signal (:func:`_handler`) is always *recorded* first: the run ends with 128 + the first
signal and ``rbcli: interrupted by SIGINT`` even when a ``KeyboardInterrupt`` is swallowed.
While a module is being imported it is *deferred* (raising there leaves a half-initialised
module: ``'3d' is not a valid value for projection``, native aborts); a 5 ms ``SIGALRM``
timer looks again until no import runs. Otherwise it is *raised* in the main thread
(``KeyboardInterrupt``; :class:`Terminated` for SIGTERM and SIGHUP), so every ``finally``
runs; a further signal meanwhile, or after the run, is only recorded.

:func:`exit_process` ends the process without finalising the interpreter (``os._exit``):
the native aborts ("Fatal Python error: PyThreadState_Get ... finalizing") happened there.
A library caller of :func:`rbcli.cli.main` gets ``install(process=False)``: SIGTERM and
SIGHUP raise :class:`Terminated` while ``main`` runs, SIGINT stays the host's.
"""

import sys

import _signal

__all__ = ["Terminated", "exit_process", "install", "received", "restore", "say", "start", "status"]

_SIGINT = _signal.SIGINT
#: the signals a run ends on, and their names for the message
NAMES = {_SIGINT: "SIGINT"}
for _name in ("SIGTERM", "SIGHUP"):
    if hasattr(_signal, _name):
        NAMES[getattr(_signal, _name)] = _name
del _name

#: how long a deferred signal waits before the next look (seconds)
RETRY = 0.005


class Terminated(KeyboardInterrupt):
    """SIGTERM or SIGHUP arrived: raised in the main thread like Ctrl-C, so that every
    ``finally`` and cleanup runs (no temporary file is left); exit status 128 + signal."""

    def __init__(self, signum: int) -> None:
        super().__init__(signum)
        self.signum = signum


class _State:
    """The one record of this process's (or, in-process, this run's) signals."""

    signum = 0  # the first signal received, 0 if none
    raised = False  # an exception has been raised for it
    pending = False  # received during an import: to be raised when the import is done
    said = False  # the line has been written
    exiting = False  # the run is over: record only
    process = False  # install(process=True) ran: this process is rbcli's
    started = False  # the entry point's main() has begun (before: the console script's steps)
    quiet: frozenset = frozenset()  # code objects (the entry point's) in which a signal waits


STATE = _State()


def _importing(frame) -> bool:
    """Whether ``frame`` runs inside an import (importlib's frames are on the stack)."""
    while frame is not None:
        if frame.f_code.co_filename.startswith("<frozen importlib._bootstrap"):
            return True
        frame = frame.f_back
    return False


def _raise(signum: int):
    STATE.raised = True
    STATE.pending = False
    if signum == _SIGINT:
        raise KeyboardInterrupt
    raise Terminated(signum)


def _defer() -> None:
    STATE.pending = True
    try:
        _signal.setitimer(_signal.ITIMER_REAL, RETRY)
    except (AttributeError, OSError, ValueError):  # no interval timers: the next look is at exit
        pass


def _may_raise(frame) -> bool:
    """Whether an exception may be raised in ``frame`` now (see the module docstring);
    when not yet, the timer is set to look again."""
    if STATE.exiting:
        return False  # the run is over: exit_process reports the signal
    if STATE.raised and sys.exc_info()[0] is not None:
        return False  # the run is already ending (a cleanup is running)
    if STATE.process and (not STATE.started or frame is None or frame.f_code in STATE.quiet
                          or _importing(frame)):
        _defer()  # not a safe point: the entry point's own steps, or an import
        return False
    return True


def _handler(signum, frame):
    if not STATE.signum:
        STATE.signum = signum
    if _may_raise(frame):
        _raise(STATE.signum)


def _retry(signum, frame):  # noqa: ARG001 - the timer of a deferred signal
    if STATE.pending and _may_raise(frame):
        _raise(STATE.signum)


def _unraisable(unraisable, _default=sys.unraisablehook):
    """``sys.unraisablehook``: an interrupt raised where Python cannot propagate it (a
    ``__del__``, a weakref callback) is already recorded: no "Exception ignored" text."""
    if isinstance(unraisable.exc_value, KeyboardInterrupt) or (
            unraisable.exc_type is not None and issubclass(unraisable.exc_type, KeyboardInterrupt)):
        return
    _default(unraisable)


def install(process: bool = True, quiet=()) -> dict:
    """Handle SIGINT, SIGTERM and SIGHUP as the module docstring says; returns the handlers
    replaced (for :func:`restore`).

    ``process=True``: the record is kept until :func:`exit_process`; until :func:`start` and
    in the frames of ``quiet`` (the entry point's code objects) a signal waits as during an
    import. ``process=False``: a fresh record; nothing when rbcli's process handlers are
    there. A signal ignored at start stays ignored.
    """
    old: dict = {}
    if STATE.process and not process:
        return old  # rbcli's own process: the handlers are there for the whole run
    if not process:
        STATE.signum, STATE.raised, STATE.pending, STATE.said = 0, False, False, False
    for signum in NAMES:
        if signum == _SIGINT and not process:
            continue
        try:
            previous = _signal.getsignal(signum)
            if previous == _signal.SIG_IGN:
                continue
            _signal.signal(signum, _handler)
        except (ValueError, OSError):  # not the main thread, or not settable
            continue
        old[signum] = previous
    if process:
        STATE.process = True
        STATE.quiet = frozenset(quiet) | {exit_process.__code__}
        try:
            _signal.signal(_signal.SIGALRM, _retry)
        except (AttributeError, ValueError, OSError):
            pass
        sys.unraisablehook = _unraisable
    return old


def start() -> None:
    """The entry point's ``main()`` has begun: from its first call on, signals are raised
    at safe points (before, while the console script runs its own lines, they wait)."""
    STATE.started = True


def restore(old: dict) -> None:
    """Put back the handlers :func:`install` replaced."""
    for signum, handler in old.items():
        try:
            _signal.signal(signum, handler if handler is not None else _signal.SIG_DFL)
        except (ValueError, OSError, TypeError):
            pass


def received() -> int:
    """The first signal received (0 if none)."""
    return STATE.signum


def status(exc: BaseException | None = None) -> int:
    """The exit status for an interrupted run: 128 + the recorded signal, else that of
    ``exc`` (a :class:`Terminated` carries its signal; any other interrupt is SIGINT's).
    Writes the run's one line (:func:`say`)."""
    signum = STATE.signum or (exc.signum if isinstance(exc, Terminated) else _SIGINT)
    say(signum)
    return 128 + signum


def say(signum: int) -> None:
    """The line ``rbcli: interrupted by SIGINT`` on standard error, once per run; nothing
    is raised when standard error cannot take it."""
    if STATE.said:
        return
    STATE.said = True
    try:
        sys.stderr.write(f"rbcli: interrupted by {NAMES.get(signum, signum)}\n")
        sys.stderr.flush()
    except Exception:  # noqa: BLE001 - closed or full: the exit status still tells
        pass


def exit_process(code: int, error: BaseException | None = None):
    """End rbcli's process with ``code`` (128 + the signal if one was received): ``atexit``
    functions, the streams flushed, ``os._exit`` (module docstring). ``error``: an exception
    that escaped :func:`rbcli.cli.main` (a broken installation), shown with its traceback."""
    STATE.exiting = True
    import os

    try:
        if error is not None:
            import traceback

            traceback.print_exception(error)
            code = 70
        import atexit

        atexit._run_exitfuncs()
    except BaseException:  # noqa: BLE001 - the exit status is decided below
        pass
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except BaseException:  # noqa: BLE001 - closed, full or a closed pipe: nothing to add
            pass
    if STATE.signum:
        code = status()
    os._exit(code if isinstance(code, int) and 0 <= code <= 255 else 70)
