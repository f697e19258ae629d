"""Output files: one check and one atomic writer for every file rbcli writes.

The policy (README "Output, exit status and speed"; SPEC §3 "no input file is ever
overwritten"):

- No output ever replaces an input: the body file, any file it includes at any depth,
  any mesh it reads (``Body.inputs``), compared by real path and, for a file that
  exists, by identity (a hard link or a second mount of the same file) — with or
  without ``--force``.
- Documents and bodies (``report -o``, ``balance --apply``) replace an existing file
  only with ``--force``; figures and data (``--plot``, ``--csv``) replace an existing
  file, as plotting tools do (``replace_ok=True``).
- Every output is written atomically: to a temporary file in the same folder, then
  renamed over the target, so a failed or interrupted run leaves the old file (or
  none) and no temporary file behind.

Errors are :class:`rbcli.errors.InputError` (exit 2), one line starting with the option.
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Iterable, Iterator, Mapping
from contextlib import contextmanager
from pathlib import Path
from typing import IO

from rbcli.errors import InputError
from rbcli.model import Body

_TMP_PREFIX = ".rbcli-"
_TMP_SUFFIX = ".tmp"


def _is_file(source: str) -> bool:
    return bool(source) and not source.startswith("<") and source != "-"


def input_files(body_or_inputs: Body | Iterable[str] | None) -> tuple[str, ...]:
    """Real paths of the input files: a body's ``inputs`` (and its source file), or paths."""
    if body_or_inputs is None:
        return ()
    if isinstance(body_or_inputs, Body):
        paths = list(body_or_inputs.inputs)
        if _is_file(body_or_inputs.source):
            paths.insert(0, body_or_inputs.source)
    elif isinstance(body_or_inputs, (str, os.PathLike)):
        paths = [os.fspath(body_or_inputs)]
    else:
        paths = [os.fspath(p) for p in body_or_inputs if p]
    return tuple(dict.fromkeys(os.path.realpath(p) for p in paths if _is_file(str(p))))


def _same_file(a: str | Path, b: str) -> bool:
    """Whether two existing paths are one file (hard links, bind mounts)."""
    try:
        return os.path.samefile(a, b)
    except OSError:  # one of them is gone or unreadable
        return False


def is_input(path: str | Path, inputs: Iterable[str]) -> bool:
    """Whether ``path`` is one of ``inputs`` (real paths), by real path or file identity."""
    real = os.path.realpath(path)
    exists = os.path.exists(path)
    return any(real == inp or (exists and _same_file(path, inp)) for inp in inputs)


def _ext_list(exts: Iterable[str]) -> tuple[str, ...]:
    return tuple("." + e.lower().lstrip(".") for e in exts)


def check(
    path: str | Path,
    body_or_inputs: Body | Iterable[str] | None,
    option: str,
    *,
    force: bool = False,
    exts: Iterable[str] | None = None,
    replace_ok: bool = False,
    others: Mapping[str, str | Path | None] | None = None,
) -> Path:
    """The output path, checked before anything is computed; returns it as a Path.

    Parameters
    ----------
    path : the file the user asked for
    body_or_inputs : the Body (its ``inputs``) or the input paths; None for no inputs
    option : the option named in errors (``--plot``, ``--csv``, ``-o``, ``--apply``)
    force : the user's ``--force``: an existing (non-input) file may be replaced
    exts : the allowed extensions (``("png", "svg")`` or ``(".html",)``), or None for any
    replace_ok : an existing (non-input) file is replaced even without ``force``
        (figures and data); documents and bodies leave it False
    others : the other outputs of the same run, ``{option: path}``: they must differ

    Raises
    ------
    InputError
        (exit 2, one line naming ``option``) for an unknown extension (listing the allowed
        ones), an input file (never replaced, whatever ``force`` says), another output of
        the run, a folder, a folder that does not exist, or an existing file without
        ``force`` when ``replace_ok`` is False.
    """
    text = os.fspath(path)
    p = Path(text)
    if not text or text.endswith(("/", os.sep)) or p.is_dir():
        raise InputError(f"{option}: '{text}' is a folder; give a file name")
    inputs = input_files(body_or_inputs)
    if is_input(p, inputs):
        raise InputError(f"{option}: '{text}' is an input file; rbcli never overwrites its inputs")
    if exts is not None:
        allowed = _ext_list(exts)
        if p.suffix.lower() not in allowed:
            raise InputError(
                f"{option}: cannot tell the format of '{text}' from its extension; use one of "
                + ", ".join(allowed)
            )
    for other, opath in (others or {}).items():
        if opath is not None and os.path.realpath(opath) == os.path.realpath(p):
            raise InputError(f"{option}: '{text}' is also the {other} file; give two different files")
    parent = p.parent
    if not parent.exists():
        raise InputError(f"{option}: the folder '{parent}' does not exist")
    if not parent.is_dir():
        raise InputError(f"{option}: '{parent}' is not a folder")
    if p.exists() and not (force or replace_ok):
        raise InputError(f"{option}: '{text}' exists; use --force to replace it")
    return p


def _target(path: Path) -> Path:
    """Where the bytes go: a symbolic link's target (the link itself stays)."""
    return Path(os.path.realpath(path)) if path.is_symlink() else path


def _mode_for(target: Path) -> int:
    """Permission bits for the new file: the old file's, else 0o666 less the umask."""
    try:
        return os.stat(target).st_mode & 0o7777
    except OSError:
        mask = os.umask(0)
        os.umask(mask)
        return 0o666 & ~mask


@contextmanager
def atomic_open(path: str | Path, option: str, *, binary: bool = False) -> Iterator[IO]:
    """A file to write ``path`` through: a temporary file in the same folder, renamed over
    ``path`` when the block ends without an error, removed when it does not.

    Raises
    ------
    InputError
        ``option: cannot write 'path': reason`` when the folder or the file cannot be written.
    """
    target = _target(Path(path))
    folder = str(target.parent) or "."
    try:
        fd, tmp = tempfile.mkstemp(prefix=_TMP_PREFIX, suffix=_TMP_SUFFIX, dir=folder)
    except OSError as exc:
        raise InputError(f"{option}: cannot write '{path}': {exc.strerror or exc}") from None
    try:
        if binary:
            fh = os.fdopen(fd, "wb")
        else:
            fh = os.fdopen(fd, "w", encoding="utf-8", newline="\n")
        with fh:
            yield fh
        os.chmod(tmp, _mode_for(target))
        os.replace(tmp, target)
    except OSError as exc:
        _remove(tmp)
        raise InputError(f"{option}: cannot write '{path}': {exc.strerror or exc}") from None
    except BaseException:
        _remove(tmp)
        raise


def _remove(tmp: str) -> None:
    try:
        os.unlink(tmp)
    except FileNotFoundError:
        pass


def write_atomic(path: str | Path, data: str | bytes, option: str = "output") -> None:
    """Write ``data`` (text as UTF-8 with ``\\n`` line ends, or bytes) to ``path`` atomically.

    Raises
    ------
    InputError
        ``option: cannot write 'path': reason``.
    """
    with atomic_open(path, option, binary=isinstance(data, bytes)) as fh:
        fh.write(data)
