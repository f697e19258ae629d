"""The process environment a command runs in: streams, terminal, colour, signals.

Injectable so that tests can play a pipe or a terminal (the httpie way). Also the place
that prepares the process's streams and signals for :func:`rbcli.cli.main`
(:func:`prepare_streams`, :func:`handle_signals`, :func:`finish_stdout`). User text is
made safe to show by :func:`clean` (:mod:`rbcli.errors`'s, which error messages use too).
"""

from __future__ import annotations

import errno
import os
import sys
from typing import IO

from rbcli import interrupts
from rbcli.errors import MAX_LINE, MAX_WORD, InputError, clean  # noqa: F401 - clean is env's to callers
from rbcli.interrupts import Terminated  # noqa: F401 - raised for SIGTERM and SIGHUP

# --- ASCII terminals

#: what a unit symbol or a sign becomes on a terminal that cannot show it (PYTHONIOENCODING=ascii)
ASCII_FALLBACK = {
    "·": "*", "⋅": "*", "²": "^2", "³": "^3", "¹": "^1", "⁻": "^-", "°": "deg", "µ": "u",
    "μ": "u", "—": "--", "–": "-", "−": "-", "…": "...", "±": "+/-", "×": "x", "≈": "~",
    "≤": "<=", "≥": ">=", "→": "->", "θ": "theta", "ω": "omega", "φ": "phi", "ψ": "psi",
    "Ω": "Omega", "π": "pi", "Δ": "Delta", "‘": "'", "’": "'", "“": '"', "”": '"',
    "§": "section ", "∫": "int ", "√": "sqrt", "∞": "inf", "≫": ">>", "≪": "<<", "∓": "-/+",
    "∝": "~", "≠": "!=", "←": "<-", "⊗": "(x)", "½": "1/2", "ᵀ": "^T", "λ": "lambda",
    **{c: f"^{d}" for c, d in zip("⁰⁴⁵⁶⁷⁸⁹⁺", "0456789+")},
}
_ERRORS = "rbcli-fallback"


def _fallback(exc: UnicodeError):
    if not isinstance(exc, UnicodeEncodeError):
        raise exc
    bad = exc.object[exc.start:exc.end]
    out = []
    for c in bad:
        rep = ASCII_FALLBACK.get(c)
        if rep is None:  # a Greek letter by its name (ζ: zeta), an accented one without it (ä: a)
            import unicodedata

            name = unicodedata.name(c, "").split()
            if name[:1] == ["GREEK"] and len(name) == 4:  # GREEK SMALL LETTER ZETA
                rep = name[3].lower() if name[1] == "SMALL" else name[3].capitalize()
            else:
                rep = unicodedata.normalize("NFKD", c).encode("ascii", "ignore").decode()
        if not rep:
            n = ord(c)
            rep = f"\\x{n:02x}" if n < 0x100 else f"\\u{n:04x}" if n < 0x10000 else f"\\U{n:08x}"
        out.append(rep)
    return "".join(out), exc.end


def _register_fallback() -> None:
    import codecs

    try:
        codecs.lookup_error(_ERRORS)
    except LookupError:
        codecs.register_error(_ERRORS, _fallback)


def _needs_fallback(stream: object) -> bool:
    enc = getattr(stream, "encoding", None)
    if not enc:
        return False
    try:
        "·²µ°—…".encode(enc)
        return False
    except (UnicodeEncodeError, LookupError):
        return True


# --- streams


class _Closed:
    """Stands for a standard stream that was closed when rbcli started (``>&-``): writing
    fails as writing to a closed descriptor does (EBADF); reading gives nothing."""

    encoding = "utf-8"
    errors = "strict"
    closed = False

    def __init__(self, name: str) -> None:
        self.name = name

    def write(self, text: str) -> int:
        raise OSError(errno.EBADF, "it is closed")

    def flush(self) -> None:
        pass

    def isatty(self) -> bool:
        return False

    def fileno(self) -> int:
        raise OSError(errno.EBADF, "it is closed")

    def read(self, *args) -> str:
        raise OSError(errno.EBADF, "it is closed")


def prepare_streams() -> None:
    """Make standard streams safe: one closed at start (``>&-``) becomes a :class:`_Closed`
    stand-in, and one whose encoding cannot show rbcli's unit symbols (a C locale) gets
    ASCII fallbacks (``²`` -> ``^2``) instead of an encoding error."""
    if sys.stdout is None:
        sys.stdout = _Closed("stdout")  # type: ignore[assignment]
    if sys.stderr is None:
        sys.stderr = _Closed("stderr")  # type: ignore[assignment]
    for stream in (sys.stdout, sys.stderr):
        if _needs_fallback(stream) and hasattr(stream, "reconfigure"):
            _register_fallback()
            try:
                stream.reconfigure(errors=_ERRORS)  # type: ignore[attr-defined]
            except (ValueError, OSError):
                pass


def write_error(text: str, stream: IO[str] | None = None) -> bool:
    """Write a message line, made safe (:func:`clean`), to ``stream`` (standard error); False
    (nothing raised) when it cannot take it (closed, full): no exit status depends on it."""
    stream = sys.stderr if stream is None else stream
    try:
        stream.write(clean(text.rstrip("\n")) + "\n")
        stream.flush()
        return True
    except Exception:  # noqa: BLE001 - closed, full, broken: nothing else to tell
        silence(stream, 2)
        return False


def silence(stream: object, fd: int) -> None:
    """Point descriptor ``fd`` (the stream's) at /dev/null, so that what is still buffered
    in ``stream`` is dropped quietly when Python flushes it at exit."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        try:
            os.dup2(devnull, stream.fileno() if hasattr(stream, "fileno") else fd)  # type: ignore[union-attr]
        finally:
            os.close(devnull)
    except (OSError, ValueError, AttributeError, TypeError):
        pass


def silence_stdout() -> None:
    """After a closed pipe, point stdout at /dev/null so the final flush is quiet."""
    silence(sys.stdout, 1)


def _stdout_error(exc: OSError) -> InputError:
    reason = exc.strerror or str(exc)
    if exc.errno == errno.EBADF:
        reason = "it is closed"
    return InputError(f"cannot write to standard output: {reason.lower()}")


def finish_stdout(code: int) -> int:
    """Flush standard output at the end of a run; the exit status to use.

    A closed pipe (``| head -1``) stays quiet and keeps ``code``; a full disk
    (``> /dev/full``) or a closed stdout is one message and exit 2.
    """
    try:
        sys.stdout.flush()
    except BrokenPipeError:
        silence_stdout()
    except (OSError, ValueError) as exc:
        silence_stdout()
        if isinstance(exc, OSError):
            write_error(f"rbcli: {_stdout_error(exc)}")
            return 2
    return code


# --- signals


# SIGINT, SIGTERM and SIGHUP: rbcli.interrupts (stdlib only, installed by rbcli.__main__ before
# anything is imported); these are the in-process side that rbcli.cli.main uses.


def signalled_status(code: int) -> int:
    """``code``, or 128 + the signal when one arrived during the run (its one line
    written, :func:`rbcli.interrupts.status`)."""
    return interrupts.status() if interrupts.received() else code


def handle_signals() -> dict:
    """SIGTERM and SIGHUP raise :class:`Terminated` while :func:`rbcli.cli.main` runs in
    another program (in rbcli's own process the handlers are already there); returns the
    previous handlers for :func:`restore_signals`."""
    return interrupts.install(process=False)


def restore_signals(old: dict) -> None:
    interrupts.restore(old)


# --- matplotlib


def prepare_blas() -> None:
    """One BLAS thread for the command line unless the user chose (``OPENBLAS_NUM_THREADS``),
    before numpy is imported (a library user keeps theirs): idle worker threads busy-wait
    (~50 ms a run) and 3 x n products gain nothing; the same bytes (tests/test_same_bytes.py)."""
    if "numpy" not in sys.modules:
        os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")


def prepare_matplotlib() -> None:
    """Give matplotlib a writable config folder when the user's is not (HOME read-only or
    missing): a private temporary folder, removed at exit — instead of matplotlib's own
    warning on standard error. Costs a few ``stat`` calls; imports nothing."""
    if os.environ.get("MPLCONFIGDIR"):
        return
    home = os.path.expanduser("~")
    base = os.environ.get("XDG_CONFIG_HOME") or os.path.join(home, ".config")
    target = os.path.join(base, "matplotlib")
    probe = target
    while probe and not os.path.exists(probe):
        parent = os.path.dirname(probe)
        if parent == probe:
            break
        probe = parent
    if probe and os.path.isdir(probe) and os.access(probe, os.W_OK | os.X_OK):
        return
    import atexit
    import shutil
    import tempfile

    try:
        folder = tempfile.mkdtemp(prefix="rbcli-mpl-")
    except OSError:
        return
    os.environ["MPLCONFIGDIR"] = folder
    atexit.register(shutil.rmtree, folder, True)


def _from_matplotlib() -> bool:
    """Whether the warning being shown was raised inside matplotlib (its warnings name the
    caller's file, so the stack is what tells)."""
    frame = sys._getframe(1)
    while frame is not None:
        if "matplotlib" in frame.f_code.co_filename:
            return True
        frame = frame.f_back
    return False


def show_warning(message, category, filename, lineno, file=None, line=None) -> None:  # noqa: ARG001
    """``warnings.showwarning`` for a run: one clean ``rbcli: warning:`` line, without
    source paths; matplotlib's own (layout, axis limits) are dropped."""
    if "matplotlib" in str(filename) or _from_matplotlib():
        return
    text = str(message).strip().splitlines()[0] if str(message).strip() else category.__name__
    write_error(f"rbcli: warning: {text}")


# --- Env


class Env:
    """A run's streams and terminal (a plain class: every run makes one); ``pipe_closed``:
    standard output's reader has gone (``| head -1``), so a batch may stop early."""

    def __init__(self, stdout: IO[str], stderr: IO[str], stdout_isatty: bool, color: bool,
                 width: int | None = None, debug: bool = False, pipe_closed: bool = False) -> None:
        self.stdout = stdout
        self.stderr = stderr
        self.stdout_isatty = stdout_isatty
        self.color = color
        self.width = width
        self.debug = debug
        self.pipe_closed = pipe_closed

    @classmethod
    def from_process(cls) -> "Env":
        try:
            tty = sys.stdout.isatty()
        except (AttributeError, ValueError, OSError):
            tty = False
        no_color = "NO_COLOR" in os.environ or os.environ.get("TERM") == "dumb"
        return cls(sys.stdout, sys.stderr, tty, color=tty and not no_color)

    def write(self, text: str) -> None:
        """Write to standard output; a closed pipe (``| head -1``) is quiet; a full disk or
        a closed stdout is an InputError (exit 2, one line)."""
        if self.pipe_closed:
            return
        try:
            self.stdout.write(text)
            self.stdout.flush()
        except BrokenPipeError:
            self.pipe_closed = True
            silence_stdout()
        except OSError as exc:
            silence_stdout()
            raise _stdout_error(exc) from None

    def warn(self, text: str) -> None:
        """One warning line on this run's standard error (:func:`write_error`)."""
        write_error(text, self.stderr)
