"""The one small error hierarchy of rbcli, and the exit status each error means.

Every layer raises these; only :mod:`rbcli.cli` prints them (as
``rbcli: file:line:col: message``) and turns them into exit codes. A check the user
asked for that fails (exit 1) is not an error: the command prints its full result and
exits 1 itself.
"""

from __future__ import annotations

import enum
import re
from collections.abc import Callable
from contextvars import ContextVar
from dataclasses import dataclass


class ExitStatus(enum.IntEnum):
    """Exit codes of SPEC §4."""

    OK = 0
    CHECK_FAILED = 1  # a check the user asked for failed; the full result was printed
    BAD_INPUT = 2  # bad usage or bad input
    INTERNAL = 70  # a bug in rbcli
    INTERRUPTED = 130  # Ctrl-C


@dataclass(frozen=True)
class Location:
    """Where something is in an input file: 1-based line and column (0 = unknown)."""

    file: str
    line: int = 0
    col: int = 0

    def __str__(self) -> str:
        if self.line <= 0:
            return self.file
        if self.col <= 0:
            return f"{self.file}:{self.line}"
        return f"{self.file}:{self.line}:{self.col}"


#: a parameter named inside a message (``{speed}``, ``{zero_mark_deg}``), or ``{{`` (a brace)
_PARAM_REF = re.compile(r"\{\{|\{([a-z][a-z0-9_]*)\}")


def spell(template: str, name: Callable[[str], str] | None = None) -> str:
    """A message template with each ``{param}`` spelled by ``name``: :func:`param_name` by
    default (``planes``), :func:`option_name` on the command line (``--planes``). ``{{`` is one
    brace (user text goes in through :func:`literal`); other braces are left as they are.
    """
    if "{" not in template:
        return template
    name = name or param_name
    return _PARAM_REF.sub(lambda m: name(m.group(1)) if m.group(1) else "{", template)


def literal(text: object) -> str:
    """``text`` (a value as the user typed it) safe inside a message template."""
    return str(text).replace("{", "{{")


class Note(str):
    """A warning or remark from api or core: a string with parameters spelled as the Python
    API spells them (``"omega: ..."``), keeping its :attr:`template` for the command line's
    spelling (``"--omega: ..."``).
    """

    template: str

    def __new__(cls, template: str) -> "Note":
        self = super().__new__(cls, spell(template))
        self.template = template
        return self

    def spelled(self, name: Callable[[str], str] | None = None) -> str:
        return spell(self.template, name)


def spelled(text: str, name: Callable[[str], str]) -> str:
    """``text`` with its parameters spelled by ``name`` if it is a :class:`Note`."""
    return text.spelled(name) if isinstance(text, Note) else text


def spelled_data(data: object, name: Callable[[str], str]) -> object:
    """JSON data (a result's ``to_json()``) with every :class:`Note` in it spelled by ``name``
    (the rows under ``parts`` are passed over: no text of rbcli's in them)."""
    if isinstance(data, dict):
        return {k: spelled_data(v, name) if k != "parts" and isinstance(v, _SPELLED) else v
                for k, v in data.items()}
    if isinstance(data, list):
        return [spelled_data(v, name) if isinstance(v, _SPELLED) else v for v in data]
    if isinstance(data, Note):
        return data.spelled(name)
    return data


#: what :func:`spelled_data` looks into
_SPELLED = (dict, list, Note)


# --- user text

#: the longest run of non-blank characters shown whole in a message or a table cell; longer
#: ones (a 5-million-digit number) are cut with "…"
MAX_WORD = 200
#: the longest message line shown whole
MAX_LINE = 2000

# C0 and C1 controls (ESC, CR, NEL \x85...), DEL, line and paragraph separators, and the
# invisible bidirectional controls that reorder what a terminal shows
# (patterns, not compiled here: re compiles and caches each on its first use, so a run that
# prints no message and no table does not pay for them)
_UNSAFE = "[\x00-\x1f\x7f-\x9f\u2028\u2029\u200e\u200f\u202a-\u202e\u2066-\u2069\ufeff]"
_UNSAFE_KEEP_NL = "[\x00-\x09\x0b-\x1f\x7f-\x9f\u2028\u2029\u200e\u200f\u202a-\u202e\u2066-\u2069\ufeff]"
_NAMED = {"\n": "\\n", "\r": "\\r", "\t": "\\t", "\x1b": "\\e"}
_LONG_WORD = r"\S{%d,}" % (MAX_WORD + 1)


def _escape(m: re.Match) -> str:
    c = m.group()
    if c in _NAMED:
        return _NAMED[c]
    n = ord(c)
    return f"\\x{n:02x}" if n < 0x100 else f"\\u{n:04x}"


def _cut_word(m: re.Match) -> str:
    return m.group()[:MAX_WORD] + "…"


def clean(text: object, *, keep_newlines: bool = False, max_line: int | None = MAX_LINE) -> str:
    """``text`` safe to print as (part of) one line on a terminal: controls, line separators
    and bidirectional controls escaped (``\\e``, ``\\r``, ``\\x85``, ``\\u2028``), so no forged
    ``rbcli:`` line or escape sequence; runs over :data:`MAX_WORD` non-blank characters cut
    with "…", the whole to ``max_line``. ``keep_newlines`` keeps ``\\n``.
    """
    s = text if isinstance(text, str) else str(text)
    if max_line is not None and len(s) > 4 * max_line:  # do not scan megabytes
        s = s[: 4 * max_line]
    s = re.sub(_UNSAFE_KEEP_NL if keep_newlines else _UNSAFE, _escape, s)
    if len(s) > MAX_WORD:
        s = re.sub(_LONG_WORD, _cut_word, s)
    if max_line is not None and len(s) > max_line:
        s = s[:max_line] + "…"
    return s


class RbcliError(Exception):
    """Base of every error rbcli reports to the user; ``{param}`` in the message is spelled
    as the Python parameter by ``str()``, for the command line by :meth:`spelled`."""

    exit_status: ExitStatus = ExitStatus.INTERNAL

    def __init__(self, message: str, where: Location | None = None) -> None:
        super().__init__(message)
        self.template = message
        self.where = where

    @property
    def message(self) -> str:
        """The message, parameters spelled as the Python API's, made safe by :func:`clean`."""
        return clean(spell(self.template))

    @message.setter
    def message(self, text: str) -> None:
        self.template = text

    def spelled(self, name: Callable[[str], str] | None = None) -> str:
        """``str(self)`` with parameters spelled by ``name`` (the command line passes
        :func:`option_name`)."""
        text = spell(self.template, name)
        return clean(f"{self.where}: {text}" if self.where else text)

    def __str__(self) -> str:
        return self.spelled()

    def __reduce__(self):  # errors cross processes: no __init__ again (ParamError's takes others)
        state = dict(self.__dict__)
        if isinstance(self, OSError):  # (rbcli.io.reader's MissingFile...)
            state.update(errno=self.errno, strerror=self.strerror, filename=self.filename)
        return _remade, (type(self), self.args, state)


def _remade(cls: type, args: tuple, state: dict) -> BaseException:
    """An unpickled error: made by its layout's ``__new__``, its attributes put back."""
    exc = (OSError if issubclass(cls, OSError) else Exception).__new__(cls, *args)
    exc.args = args  # (an OSError subclass with an __init__ of its own leaves them to it)
    exc.__setstate__(state)
    return exc


class InputError(RbcliError, ValueError):
    """Bad input: a body file, an option value, a mesh file. Exit 2.

    A :class:`ValueError` (as scipy and numpy raise for a bad value), so ``except
    ValueError`` catches it; a wrong *type* of argument is a :class:`TypeError` naming the
    parameter, never an InputError.

    Attributes
    ----------
    message : str — what is wrong and what is allowed, one line (as the CLI prints it)
    where : Location | None — the file, line and column, for an error in an input file
    param : str | None — the keyword argument (command-line option) at fault, if one is:
        ``"about"`` for ``--about``; :func:`option_name` spells it as an option
    """

    exit_status = ExitStatus.BAD_INPUT

    def __init__(self, message: str, where: Location | None = None, *,
                 param: str | None = None) -> None:
        super().__init__(message, where)
        self.param = param


class ParamError(InputError):
    """A value given for one parameter is wrong; the message is prefixed with its name:
    ``ParamError("planes", "the two planes must differ")`` reads ``planes: the two planes
    must differ``, on the command line ``--planes: ...``. Code reads ``param``, never the text.
    """

    def __init__(self, param: str, message: str, where: Location | None = None) -> None:
        super().__init__(f"{{{param}}}: {message}", where, param=param)
        self.reason = message


#: what stands in a message for a value that is not a parameter but a body's default
BODY_DEFAULTS: dict[str, str] = {
    "body_reference": "the body's reference point",
    "body_shaft": "the body's shaft",
    "body_pivot": "the body's pivot",
    "body_rim_radius": "the body's rim_radius",
}

#: parameters whose option is not simply ``--`` + the name with dashes; the one table that
#: maps a parameter to what the user typed on the command line
OPTIONS: dict[str, str] = {
    "expr": "-e/--expr",
    "output": "-o",
    **BODY_DEFAULTS,
}


#: parameters whose option is another word in one command (the Python API says one name for
#: one idea: the shaft, the rim radius, the rolling speed; the command line keeps its options)
COMMAND_OPTIONS: dict[str, dict[str, str]] = {
    "rollcheck": {"shaft": "--axle", "rim_radius": "--radius", "rolling_speed": "--speed"},
    "gyrocompass": {"shaft": "--axis"},
    "report": {"rolling_speed": "--speed", "path": "-o"},
}

#: the command whose options a message's parameters are spelled as: set by the command line
#: while it runs one (None in the library: the general table)
COMMAND: ContextVar[str | None] = ContextVar("rbcli_command", default=None)


def param_name(param: str) -> str:
    """How the Python API names ``param`` in a message: itself, or the body default it is."""
    return BODY_DEFAULTS.get(param, param)


def option_name(param: str, command: str | None = None) -> str:
    """How the user wrote parameter ``param`` on the command line: ``"zero_mark_deg"`` ->
    ``"--zero-mark-deg"``; in ``command`` (default: the one running, :data:`COMMAND`) its
    own word where it has one (rollcheck's ``rim_radius`` is ``--radius``)."""
    own = COMMAND_OPTIONS.get(command or COMMAND.get() or "", {}).get(param)
    return own or OPTIONS.get(param) or "--" + param.replace("_", "-")


class NonFiniteResult(InputError):
    """A result came out as inf or NaN: the inputs are too large or too small to compute
    with (not a bug). Exit 2, like any other bad input.
    """
