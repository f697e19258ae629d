"""What the mesh readers share: :class:`MeshFileError`, the whole-file read, the numbers of
the text formats (:func:`numbers`) and the helpers that word its messages (a line number, a
long token shortened)."""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

import numpy as np

__all__ = ["MeshFileError", "read_all", "numbers", "floats", "line_of", "cut", "odd_number"]

_DECIMAL_CHARS = b"0123456789.+-eE"
_NON_FINITE = re.compile(rb"[+-]?(?:inf(?:inity)?|nan)", re.IGNORECASE)


class MeshFileError(ValueError):
    """A mesh file that is malformed or empty (one missing or unreadable: a ReadError).

    The message is lower case, starts with the file name and says what is wrong.
    ``path`` is the file and ``line`` the 1-based line (0 when not applicable).
    """

    def __init__(self, path: str, message: str, line: int = 0) -> None:
        where = f"{path}:{line}" if line > 0 else path
        super().__init__(f"{where}: {message}")
        self.path = path
        self.line = line
        self.reason = message

def read_all(name: str, fh, size: int) -> bytes:
    """The whole file (``size`` bytes, already checked against the limit)."""
    data = fh.read(size + 1)
    if len(data) > size:  # it grew while we read: take what fits the checked size
        raise MeshFileError(name, "the file changed while it was read")
    if not data:
        raise MeshFileError(name, "empty file (no triangles)")
    return data


def numbers(text: bytes, dtype: type = np.float64) -> np.ndarray | None:
    """Whitespace-separated numbers (ASCII STL, OBJ), or None if any token is not one (no
    partial result): ``np.fromstring``, which gives the bits Python's ``float()`` gives.

    numpy stops at the first token it cannot read (with a DeprecationWarning, a ValueError in
    later versions): fewer numbers than tokens is that. The warning filters are left alone (a
    library call does not switch them: another thread may be reading warnings)."""
    try:
        out = np.fromstring(text, dtype=dtype, sep=" ")
    except ValueError:
        return None
    return out if out.size == len(text.split()) else None


def floats(tokens: Sequence[bytes], bad: Callable[[int, bytes], MeshFileError]) -> np.ndarray:
    """The coordinate texts ``tokens`` as float64, or ``bad(i, token)`` raised for the first
    that is not a number of the formats (:func:`odd_number`): the line readers' numbers."""
    if not any(map(odd_number, tokens)):
        try:
            return np.array(tokens, dtype=np.float64)
        except ValueError:  # one that is not a number after all: found below
            pass
    for i, t in enumerate(tokens):
        try:
            if odd_number(t):
                raise ValueError
            float(t)
        except ValueError:
            raise bad(i, t) from None
    raise AssertionError("numpy and float() disagree")  # pragma: no cover


def line_of(text: bytes, offset: int) -> int:
    """The 1-based line of the byte ``offset`` of ``text``."""
    return text.count(b"\n", 0, offset) + 1


def odd_number(token: bytes) -> bool:
    """Whether a coordinate's text holds a character the formats' numbers do not have.

    STL and OBJ numbers are C's decimal numbers; ``float()`` also takes ``1_000``, which no
    STL or OBJ reader does. ``inf`` and ``nan`` pass (the finiteness check refuses them), and
    so does ``1.2.3`` (the conversion refuses it).
    """
    return bool(token.strip(_DECIMAL_CHARS)) and _NON_FINITE.fullmatch(token) is None


def cut(text: str, limit: int = 24) -> str:
    """A number or word from the file, shortened when it is long."""
    return text if len(text) <= limit else f"{text[:limit]}… ({len(text)} characters)"
