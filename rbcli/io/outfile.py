"""Output files: one check and one atomic writer for every file rbcli writes (README
"Output, exit status and speed"; SPEC §3).

- No output ever replaces an input (``Body.inputs``), by real path or file identity.
- Documents and bodies replace an existing file only with ``--force``; figures and data
  (``--plot``, ``--csv``) do (``replace_ok=True``).
- Only a regular file or a new name is written (no link, device, FIFO, socket, folder).
- Every output goes to a temporary file in its folder (``O_EXCL | O_NOFOLLOW``) renamed over
  the target, no-clobber without replacing (``renameat2(RENAME_NOREPLACE)``, else ``link``).
- A document with a folder of figures (``r.md``: ``r_files/``) is written all or nothing
  (:func:`write_document`); an existing ``r_files/`` is replaced whole, only with ``--force``.
- Interrupted or failed, a write leaves no ``.rbcli-XXXX.tmp`` file or folder.

Errors are :class:`rbcli.errors.InputError` (exit 2), one line starting with the option.
"""

from __future__ import annotations

import errno
import os
import stat
from collections.abc import Iterable, Iterator, Mapping
from contextlib import contextmanager, suppress
from pathlib import Path
from typing import IO, Protocol

from rbcli.errors import InputError, literal


class Body(Protocol):
    """What outputs need of a body (:class:`rbcli.Body`): the files it was read from."""

    source: str
    inputs: tuple[str, ...]

_TMP_PREFIX = ".rbcli-"
_TMP_SUFFIX = ".tmp"


def _opt(option: str) -> str:
    """How a message names the output: an option as typed (``"--plot"``), or a parameter
    (``"output"``) as a message template's ``{output}`` (:func:`rbcli.errors.spell`)."""
    return option if option.startswith(("-", "{")) else "{" + option + "}"


def _is_file(source: str) -> bool:
    return bool(source) and not source.startswith("<") and source != "-"


def input_files(body_or_inputs: Body | Iterable[str] | None) -> tuple[str, ...]:
    """Real paths of the input files: a body's ``inputs`` (and its source file), or paths."""
    if body_or_inputs is None:
        return ()
    if hasattr(body_or_inputs, "inputs"):  # a body
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
        naming ``option``: an unknown extension, an input file (whatever ``force`` says),
        another output of the run, a folder, a missing folder, an existing file without
        ``force`` unless ``replace_ok``.
    """
    option = _opt(option)
    text = os.fspath(path)
    _probe(text, option)  # (a NUL in the name too)
    p = Path(text)
    if not text or text.endswith(("/", os.sep)) or p.is_dir():
        raise InputError(f"{option}: '{literal(text)}' is a folder; give a file name")
    inputs = input_files(body_or_inputs)
    if is_input(p, inputs):
        raise InputError(f"{option}: '{literal(text)}' is an input file; rbcli never overwrites its inputs")
    if exts is not None:
        allowed = _ext_list(exts)
        if p.suffix.lower() not in allowed:
            raise InputError(
                f"{option}: cannot tell the format of '{literal(text)}' from its extension; use one of "
                + ", ".join(allowed)
            )
    for other, opath in (others or {}).items():
        if opath is not None and os.path.realpath(opath) == os.path.realpath(p):
            raise InputError(f"{option}: '{literal(text)}' is also the {other} file; give two different files")
    parent = p.parent
    if not parent.exists():
        raise InputError(f"{option}: the folder '{literal(parent)}' does not exist")
    if not parent.is_dir():
        raise InputError(f"{option}: '{literal(parent)}' is not a folder")
    if _kind(p, option) is not None and not (force or replace_ok):
        raise InputError(f"{option}: '{literal(text)}' exists; use {{force}} to replace it")
    return p


def _probe(text: str, option: str) -> None:
    """Refuse, before any other check, a name the system cannot take at all (ENAMETOOLONG,
    ELOOP, EACCES on the way); a missing name or folder is for the checks after."""
    if not text:
        return
    try:
        os.lstat(text)
    except (FileNotFoundError, NotADirectoryError):
        pass
    except (OSError, ValueError) as exc:
        raise InputError(f"{option}: cannot write '{_shown_name(text)}': {_reason(exc)}") from None


def _shown_name(text: str, limit: int = 80) -> str:
    """A file name for a message: cut when it is long (its length said)."""
    return text if len(text) <= limit else f"{text[:limit // 2]}… ({len(text)} characters)"


#: what rbcli never writes, and why
_NOT_WRITTEN = (
    (stat.S_ISLNK, "a symbolic link; rbcli never writes through a link (give its target or a new name)"),
    (stat.S_ISDIR, "a folder; give a file name"),
    (lambda m: stat.S_ISCHR(m) or stat.S_ISBLK(m), "a device, not a regular file; rbcli writes only regular files"),
    (stat.S_ISFIFO, "a FIFO (named pipe), not a regular file; rbcli writes only regular files"),
)


def _kind(path: str | Path, option: str) -> os.stat_result | None:
    """The ``lstat`` of an existing output that may be replaced (a regular file), None for a
    new name; anything else is refused."""
    text = os.fspath(path)
    try:
        st = os.lstat(text)
    except FileNotFoundError:
        return None
    except (OSError, ValueError) as exc:
        raise InputError(f"{option}: cannot write '{literal(text)}': {literal(_reason(exc))}") from None
    if stat.S_ISREG(st.st_mode):
        return st
    what = next((w for test, w in _NOT_WRITTEN if test(st.st_mode)),
                "not a regular file; rbcli writes only regular files")
    raise InputError(f"{option}: '{literal(text)}' is {what}")


def _reason(exc: BaseException) -> str:
    if isinstance(exc, ValueError):  # a NUL in the name
        return "the name contains a NUL character" if "null" in str(exc) else str(exc)
    return (getattr(exc, "strerror", None) or str(exc)).lower() if isinstance(exc, OSError) else str(exc)


def _mode_for(st: os.stat_result | None, new: int = 0o666) -> int:
    """Permission bits for a new file (or folder: ``new=0o777``): the old file's, else
    ``new`` less the umask."""
    if st is not None:
        return st.st_mode & 0o7777
    mask = os.umask(0)
    os.umask(mask)
    return new & ~mask


# --- signals


#: the main thread's open :func:`_held_signals` blocks, and the signals they held off
_depth = 0
_pending: list[int] = []


@contextmanager
def _held_signals() -> Iterator[None]:
    """SIGINT, SIGTERM and SIGHUP held off for a few steps, delivered when the outermost
    block ends, by swapping the handlers for one that records (not ``pthread_sigmask``: a
    BLAS thread may take the signal); outside the main thread, nothing."""
    import signal
    import threading

    global _depth, _pending
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    old = {}
    _depth += 1
    try:  # (from here: whatever happens, the count and the handlers are put back)
        if _depth == 1:
            _pending = []  # (what an interrupted block's end left: a later signal ended it)
            for name in ("SIGINT", "SIGTERM", "SIGHUP"):
                with suppress(ValueError, OSError, TypeError, AttributeError):
                    old[getattr(signal, name)] = signal.signal(getattr(signal, name), lambda n, _: _pending.append(n))
        yield
    finally:
        _depth -= 1
        for signum, handler in old.items():
            with suppress(ValueError, OSError, TypeError):
                signal.signal(signum, handler if handler is not None else signal.SIG_DFL)
        for signum in dict.fromkeys(_pending if old else ()):  # now, to the handlers that were there
            signal.raise_signal(signum)


# --- renames


def _renameat2_noreplace(src: str, dst: str) -> bool:
    """``renameat2(src, dst, RENAME_NOREPLACE)``; False when the system or the file system
    does not have it; raises FileExistsError when ``dst`` exists."""
    import ctypes

    try:
        libc = ctypes.CDLL(None, use_errno=True)
        fn = libc.renameat2
    except (OSError, AttributeError):
        return False
    at_fdcwd, rename_noreplace = -100, 1
    fn.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_uint]
    if fn(at_fdcwd, os.fsencode(src), at_fdcwd, os.fsencode(dst), rename_noreplace) == 0:
        return True
    err = ctypes.get_errno()
    if err in (errno.ENOSYS, errno.EINVAL, errno.ENOTSUP, errno.EOPNOTSUPP):
        return False
    raise OSError(err, os.strerror(err), dst)


def rename_noreplace(src: str, dst: str) -> None:
    """Rename ``src`` to ``dst`` only if ``dst`` does not exist, in one step:
    ``renameat2(RENAME_NOREPLACE)``, else for a file ``link(2)`` then unlink, else a check
    then a rename (a window only on file systems with neither).

    Raises
    ------
    FileExistsError
        ``dst`` exists (a file, a folder, a link, anything).
    """
    if _renameat2_noreplace(src, dst):
        return
    if not os.path.isdir(src):
        try:
            os.link(src, dst, follow_symlinks=False)
        except FileExistsError:
            raise
        except OSError:
            pass
        else:
            os.unlink(src)
            return
    if os.path.lexists(dst):
        raise FileExistsError(errno.EEXIST, os.strerror(errno.EEXIST), dst)
    os.rename(src, dst)


def _tmp_name(folder: str, suffix: str = _TMP_SUFFIX) -> str:
    # os.urandom as secrets.token_hex does (without the ~3 ms of importing secrets, hashlib
    # and random on every body load)
    return os.path.join(folder, f"{_TMP_PREFIX}{os.urandom(4).hex()}{suffix}")


def _create(path: str) -> int:
    """A new file for writing, never through a link and never an existing name."""
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_CLOEXEC", 0)
    return os.open(path, flags, 0o600)


def _new_tmp(folder: str) -> tuple[int, str]:
    for _ in range(100):
        name = _tmp_name(folder)
        try:
            return _create(name), name
        except FileExistsError:
            continue
    raise FileExistsError(errno.EEXIST, "no free temporary name", folder)


def _commit(tmp: str, path: str, option: str, replace: bool) -> None:
    """Rename the finished ``tmp`` onto ``path``: over a regular file when ``replace``,
    else only if ``path`` is a new name. A link, device, FIFO or folder is refused."""
    st = _kind(path, option)
    os.chmod(tmp, _mode_for(st))
    if replace:
        os.replace(tmp, path)  # replaces the name: never writes through what it was
        return
    try:
        rename_noreplace(tmp, path)
    except FileExistsError:
        raise InputError(f"{option}: '{literal(path)}' exists; use {{force}} to replace it") from None


def _remove(tmp: str | None) -> None:
    if tmp is None:
        return
    try:
        os.unlink(tmp)
    except FileNotFoundError:
        pass
    except IsADirectoryError:
        import shutil

        shutil.rmtree(tmp, ignore_errors=True)


@contextmanager
def atomic_open(path: str | Path, option: str, *, binary: bool = False,
                replace: bool = True) -> Iterator[IO]:
    """A temporary file beside ``path``, renamed onto it when the block ends without an
    error, removed when it does not (an exception, Ctrl-C, SIGTERM).

    Parameters
    ----------
    path : the output (checked by :func:`check`); never a link, device, FIFO or folder
    option : the option named in errors
    binary : bytes instead of UTF-8 text with ``\n`` line ends
    replace : an existing regular file is replaced; False: ``path`` must be a new name when
        the rename happens (no-clobber, one step)

    Raises
    ------
    InputError
        ``option: cannot write 'path': reason``, ``'path' exists`` (``replace`` False), or
        ``'path' is a device ...`` (found at write time).
    """
    option = _opt(option)
    text = os.fspath(path)
    _kind(text, option)  # refuse a NUL, a link, device, FIFO or folder before writing anything
    folder = os.path.dirname(text) or "."
    tmp = None
    try:
        with _held_signals():  # the temporary file exists only inside the try
            fd, tmp = _new_tmp(folder)
        if binary:
            fh = os.fdopen(fd, "wb")
        else:
            fh = os.fdopen(fd, "w", encoding="utf-8", newline="\n")
        with fh:
            yield fh
        with _held_signals():
            _commit(tmp, text, option, replace)
            tmp = None
    except BaseException as exc:
        with _held_signals():  # a second Ctrl-C cannot stop the cleanup halfway
            _remove(tmp)
        if isinstance(exc, OSError):
            raise InputError(f"{option}: cannot write '{literal(text)}': {literal(_reason(exc))}") from None
        raise


def write_atomic(path: str | Path, data: str | bytes, option: str = "output", *,
                 replace: bool = True) -> None:
    """Write ``data`` (text as UTF-8 with ``\n`` line ends, or bytes) to ``path`` atomically:
    :func:`atomic_open`."""
    with atomic_open(path, option, binary=isinstance(data, bytes), replace=replace) as fh:
        fh.write(data)


# --- document + folder


def files_dir(path: str | Path) -> Path:
    """The folder of a Markdown document's figures: ``r.md`` -> ``r_files``."""
    p = Path(path)
    return p.with_name(p.stem + "_files")


def check_folder(folder: str | Path, body_or_inputs: Body | Iterable[str] | None, option: str,
                 *, force: bool = False) -> Path:
    """An output folder (a Markdown report's figures), checked as :func:`check` checks a file:
    no input in it, a real folder holding only files, replaced only with ``force``."""
    folder = Path(folder)
    option = _opt(option)
    text = os.fspath(folder)
    real = os.path.realpath(folder)
    for inp in input_files(body_or_inputs):
        if inp == real or inp.startswith(real + os.sep):
            raise InputError(f"{option}: '{literal(text)}' (for the figures) holds an input file; "
                             "rbcli never overwrites its inputs")
    try:
        st = os.lstat(text)
    except FileNotFoundError:
        return folder
    except OSError as exc:
        raise InputError(f"{option}: cannot write '{literal(text)}': {literal(_reason(exc))}") from None
    if stat.S_ISLNK(st.st_mode):
        raise InputError(f"{option}: '{literal(text)}' (for the figures) is a symbolic link; rbcli never "
                         "writes through a link: remove it or choose another -o name")
    if not stat.S_ISDIR(st.st_mode):
        raise InputError(f"{option}: '{literal(text)}' (for the figures) exists and is not a folder")
    if not force:
        raise InputError(f"{option}: '{literal(text)}' exists; use {{force}} to replace it")
    try:
        entries = list(os.scandir(text))
    except OSError as exc:
        raise InputError(f"{option}: cannot read the folder '{literal(text)}': {literal(_reason(exc))}") from None
    for entry in entries:
        if entry.is_dir(follow_symlinks=False):
            raise InputError(f"{option}: '{literal(text)}' holds the folder '{entry.name}', which rbcli did "
                             "not write; move it away to replace the report")
        if is_input(entry.path, input_files(body_or_inputs)):
            raise InputError(f"{option}: '{literal(text)}' holds an input file ('{entry.name}'); rbcli never "
                             "overwrites its inputs")
    return folder


def write_document(path: str | Path, data: str | bytes, option: str, *, replace: bool,
                   folder: str | Path | None = None,
                   files: Mapping[str, str | bytes] | None = None) -> None:
    """Write a document and (when ``files``) its folder of figures, all or nothing: both are
    made under temporary names, then :func:`_swap` replaces the old pair, signals held off."""
    option = _opt(option)
    text = os.fspath(path)
    if not files:
        write_atomic(text, data, option, replace=replace)
        return
    folder = os.fspath(folder if folder is not None else files_dir(text))
    parent = os.path.dirname(text) or "."
    _kind(text, option)
    stage = doc_tmp = old = None
    try:
        with _held_signals():
            stage = _tmp_name(parent)
            os.mkdir(stage, 0o700)
        for name, content in files.items():
            if not name or "/" in name or os.sep in name or name in (".", "..") or "\x00" in name:
                raise ValueError(f"bad figure file name {name!r}")  # a bug, not an input
            fd = _create(os.path.join(stage, name))
            with os.fdopen(fd, "wb") as fh:
                fh.write(content.encode("utf-8") if isinstance(content, str) else content)
            os.chmod(os.path.join(stage, name), _mode_for(None))
        with _held_signals():
            fd, doc_tmp = _new_tmp(parent)
        with os.fdopen(fd, "wb") as fh:
            fh.write(data.encode("utf-8") if isinstance(data, str) else data)
        with _held_signals():
            old = _swap(stage, doc_tmp, folder, text, option, replace)
            stage = doc_tmp = None  # in place: a signal raised as the block ends undoes nothing
            _step("clean")
            _remove(old)
    except BaseException as exc:
        with _held_signals():
            for name in (stage, doc_tmp, old):
                _remove(name)
        if isinstance(exc, OSError):
            raise InputError(f"{option}: cannot write '{literal(text)}': {literal(_reason(exc))}") from None
        raise


def _step(name: str) -> None:
    """A step of :func:`_swap` or the cleanup after it: nothing (tests interrupt there)."""


def _swap(stage: str, doc_tmp: str, folder: str, path: str, option: str, replace: bool) -> str | None:
    """Put the finished ``stage`` and ``doc_tmp`` in place of ``folder`` and ``path``, all or
    nothing (signals held): the old folder moved aside, the new one in, the document committed;
    a failure undoes the steps before it. Returns the old folder's temporary name, or None."""
    os.chmod(stage, _mode_for(None, 0o777))
    aside = None
    placed = False
    try:
        if os.path.lexists(folder):
            if not replace:
                raise InputError(f"{option}: '{literal(folder)}' exists; use {{force}} to replace it")
            if os.path.islink(folder) or not os.path.isdir(folder):
                raise InputError(f"{option}: '{literal(folder)}' (for the figures) is not a folder")
            _step("aside")
            aside = _tmp_name(os.path.dirname(path) or ".", ".old")
            os.rename(folder, aside)
        _step("place")
        try:
            rename_noreplace(stage, folder)
        except FileExistsError:
            raise InputError(f"{option}: '{literal(folder)}' exists; use {{force}} to replace it") from None
        placed = True
        _step("commit")
        _commit(doc_tmp, path, option, replace)
    except BaseException:
        if placed:
            with suppress(OSError):
                os.rename(folder, stage)  # the new folder back where it was made
        if aside is not None:
            with suppress(OSError):
                os.rename(aside, folder)  # the old one back
        raise
    return aside
