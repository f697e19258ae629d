"""What the mesh readers share: :class:`MeshFileError`, the whole-file read and the
helpers that word its messages (a line number, a long token shortened)."""

from __future__ import annotations

__all__ = ["MeshFileError", "read_all", "line_of", "cut"]


class MeshFileError(ValueError):
    """A mesh file that cannot be read: missing, unreadable, malformed or empty.

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


def line_of(text: bytes, offset: int) -> int:
    """The 1-based line of the byte ``offset`` of ``text``."""
    return text.count(b"\n", 0, offset) + 1


def cut(text: str, limit: int = 24) -> str:
    """A number or word from the file, shortened when it is long."""
    return text if len(text) <= limit else f"{text[:limit]}… ({len(text)} characters)"
