"""The one input reader: regular files and standard input, type and size checked first.

Every file rbcli reads (a body, an include) goes through :func:`read_regular` (a mesh
through :func:`open_regular`, to read it in blocks), standard input (BODY ``-``) through
:func:`read_stream`. A FIFO, a device or a directory is refused before a byte is read,
without blocking (``O_NONBLOCK``, the type of the open descriptor); the size is checked
before and while reading.

Errors are :class:`ReadError` (an InputError, exit 2) with the bare ``reason`` (``"no such
file"``...) for callers to word; a missing file is also a FileNotFoundError, a forbidden
one a PermissionError, a directory an IsADirectoryError (``errno``, ``filename`` set).
"""

from __future__ import annotations

import errno
import os
import stat
from typing import BinaryIO

from rbcli.errors import InputError, Location

__all__ = ["ReadError", "open_regular", "read_regular", "read_stream", "size_text", "limit_from_env"]

_CHUNK = 1 << 16


class ReadError(InputError):
    """A file or stream that is not read: ``path`` and the bare ``reason``.

    ``str()`` (and ``message``) read ``"<path>: <reason>"``; ``"no such file: <path>"``
    for a missing file (the wording rbcli has always used).
    """

    def __init__(self, path: str, reason: str, where: Location | None = None) -> None:
        self.path = path
        self.reason = reason
        text = f"no such file: {path}" if reason == "no such file" else f"{path}: {reason}"
        super().__init__(text, where)


class MissingFile(ReadError, FileNotFoundError): ...  # noqa: E701 - each an InputError and an OSError


class DeniedFile(ReadError, PermissionError): ...  # noqa: E701


class FolderFile(ReadError, IsADirectoryError): ...  # noqa: E701


_ERRNO = {errno.ENOENT: MissingFile, errno.EACCES: DeniedFile, errno.EPERM: DeniedFile, errno.EISDIR: FolderFile}


def _error(name: str, reason: str, where: Location | None, code: int | None = None) -> ReadError:
    """The ReadError of ``reason``; with the OSError subclass of ``code`` (an errno)."""
    exc = _ERRNO.get(code, ReadError)(name, reason, where)  # type: ignore[arg-type]
    if code in _ERRNO:
        exc.errno, exc.strerror, exc.filename = code, os.strerror(code), name  # type: ignore[attr-defined]
    return exc


def relabelled(exc: ReadError, text: str, where: Location | None) -> ReadError:
    """``exc`` saying ``text`` at ``where``, of its class (a MissingFile stays an OSError)."""
    new = _error(exc.path, exc.reason, where, getattr(exc, "errno", None))
    new.message = text
    return new


def size_text(n: int) -> str:
    """``8 MiB``, ``512 KiB`` or ``100 bytes``."""
    for unit, size in (("GiB", 1 << 30), ("MiB", 1 << 20), ("KiB", 1 << 10)):
        if n >= size and n % size == 0:
            return f"{n // size} {unit}"
    return f"{n} bytes"


def limit_from_env(name: str, default: int) -> int:
    """A positive whole-number budget from the environment variable ``name``, else
    ``default``. A value that is not a positive whole number is refused (exit 2)."""
    raw = os.environ.get(name, "").strip()
    if not raw:
        return default
    try:
        value = int(raw.replace("_", ""))
    except ValueError:
        value = 0
    if value <= 0 or len(raw) > 20:
        raise InputError(f"{name}: must be a positive whole number, not '{raw[:40]}'")
    return value


def _kind(mode: int) -> str | None:
    """Why a file of this mode is not read, or None for a regular file."""
    if stat.S_ISREG(mode):
        return None
    if stat.S_ISDIR(mode):
        return "is a directory, not a file"
    if stat.S_ISFIFO(mode):
        return "is a FIFO (named pipe), not a regular file; rbcli reads regular files and standard input ('-')"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "is a device, not a regular file; rbcli reads regular files and standard input ('-')"
    if stat.S_ISSOCK(mode):
        return "is a socket, not a regular file"
    return "is not a regular file"


def _too_big(size: int | None, limit: int, what: str, env: str | None) -> str:
    raise_hint = f" (set {env} to raise it)" if env else ""
    shown = f"is {size} bytes" if size is not None else f"is more than {size_text(limit)}"
    return f"{shown}; {what}s are limited to {size_text(limit)}{raise_hint}"


def _os_reason(exc: OSError) -> str:
    if exc.errno == errno.ENOENT:
        return "no such file"
    if exc.errno in (errno.EACCES, errno.EPERM):
        return "cannot read the file: permission denied"
    if exc.errno == errno.EISDIR:
        return "is a directory, not a file"
    if exc.errno == errno.ELOOP:
        return "cannot read the file: too many levels of symbolic links"
    return f"cannot read the file: {(exc.strerror or str(exc)).lower()}"


#: how a file is opened for reading: never blocking (a FIFO), never a controlling terminal
_READ_FLAGS = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0) | getattr(os, "O_CLOEXEC", 0)


def open_regular(path: str | os.PathLike[str], limit: int, what: str = "file", *,
                 where: Location | None = None, env: str | None = None) -> tuple[int, int]:
    """(a descriptor, the size) of the regular file ``path``, checked and opened as
    :func:`read_regular` says, for a reader that reads it its own way (a mesh, in blocks)."""
    name = os.fspath(path)
    if "\x00" in name:
        raise ReadError(name.replace("\x00", "\\0"), "the file name contains a NUL character", where)
    fd = None
    try:
        st = os.stat(name)  # refuse a FIFO or device before opening it at all
        if not _kind(st.st_mode):
            fd = os.open(name, _READ_FLAGS)
            st = os.fstat(fd)  # what was opened (the name may have changed since the stat)
        reason = _kind(st.st_mode) or (_too_big(st.st_size, limit, what, env) if st.st_size > limit else None)
        if reason:
            raise _error(name, reason, where, errno.EISDIR if stat.S_ISDIR(st.st_mode) else None)
        return fd, st.st_size
    except BaseException as exc:
        if fd is not None:
            os.close(fd)
        if isinstance(exc, OSError) and not isinstance(exc, ReadError):
            raise _error(name, _os_reason(exc), where, exc.errno) from None
        if isinstance(exc, ValueError) and not isinstance(exc, ReadError):  # a name the OS cannot take
            raise ReadError(name, f"cannot read the file: {exc}", where) from None
        raise


def read_regular(path: str | os.PathLike[str], limit: int, what: str = "file", *,
                 where: Location | None = None, env: str | None = None) -> bytes:
    """The bytes of the regular file ``path`` (a link followed), at most ``limit``; ``what``
    names it in messages (``"mesh file"``), ``where`` locates the reference to it (an
    include's ``file:``), ``env`` is the variable that raises ``limit``.

    ReadError (exit 2): a missing or unreadable file, a NUL in the name, a directory, FIFO,
    device or socket (refused before reading, without blocking), more than ``limit`` bytes
    (checked before and while reading)."""
    fd, size = open_regular(path, limit, what, where=where, env=env)
    try:
        chunks = []
        total = 0
        while True:
            chunk = os.read(fd, min(max(size - total, _CHUNK), limit + 1 - total) or 1)
            if not chunk:
                break
            chunks.append(chunk)
            total += len(chunk)
            if total > limit:
                raise ReadError(os.fspath(path), _too_big(None, limit, what, env), where)
        return b"".join(chunks)
    except OSError as exc:
        raise _error(os.fspath(path), _os_reason(exc), where, exc.errno) from None
    finally:
        os.close(fd)


def read_stream(stream: BinaryIO | None, limit: int, what: str = "file", *,
                name: str = "standard input", env: str | None = None) -> bytes:
    """All of a byte stream (standard input), in chunks, at most ``limit`` bytes; ReadError
    (exit 2): closed (``<&-``), unreadable, or over ``limit`` (never more than 64 KiB over held)."""
    if stream is None:
        raise ReadError(name, "is closed; give a BODY file instead of '-', or pipe a body in")
    chunks = []
    total = 0
    try:
        while True:
            chunk = stream.read(_CHUNK)
            if not chunk:
                break
            chunks.append(chunk)
            total += len(chunk)
            if total > limit:
                raise ReadError(name, _too_big(None, limit, what, env))
    except ReadError:
        raise
    except (OSError, ValueError) as exc:  # EBADF for a closed descriptor, a closed file
        reason = "is closed" if isinstance(exc, ValueError) or getattr(exc, "errno", None) == errno.EBADF \
            else f"cannot be read: {(getattr(exc, 'strerror', None) or str(exc)).lower()}"
        if reason == "is closed":
            reason += "; give a BODY file instead of '-', or pipe a body in"
        raise ReadError(name, reason) from None
    if chunks and isinstance(chunks[0], str):  # a text stream given by a caller
        return "".join(chunks).encode("utf-8", "surrogateescape")
    return b"".join(chunks)
