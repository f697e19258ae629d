"""Readers for triangle-mesh files: STL (binary and ASCII) and Wavefront OBJ.

:func:`read_mesh` returns an *indexed* mesh, ``(vertices, faces)``, with vertices that
have exactly the same coordinates merged ("welded"), and the weld tolerance that suits
the file's own precision (:func:`default_weld`): :mod:`rbcli.core.mesh` uses it, only
when the exactly welded surface is not closed, to close gaps left by coordinate noise.
Everything is vectorised with numpy: the text formats are read in blocks of whole lines,
tokenised with numpy and their numbers read by :func:`rbcli.io.meshnumbers.floats` (an
ASCII STL block's repeated ``vertex`` texts only once); the per-token and per-line
Python readers are kept to say where a file the fast path refuses is wrong, and to read
the unusual layouts it leaves to them; the numbers are the same bits either way, which
the tests check.

Before anything is read the file's type and size are checked: a directory, FIFO,
device or socket is refused, and so is a file larger than :func:`max_mesh_bytes`
(``RBCLI_MAX_MESH_BYTES``, default 1 GiB).

Errors are :class:`MeshFileError` (a ``ValueError``) with a lower-case message that
starts with the file name, says what is wrong and, for text formats, on which line.
"""

from __future__ import annotations

import itertools
import os
import re
import stat
from typing import NamedTuple

import numpy as np

from rbcli.io import meshnumbers

__all__ = [
    "MeshFileError", "MeshFile", "read_mesh", "weld", "default_weld", "max_mesh_bytes",
    "SUFFIXES", "MAX_MESH_BYTES", "TEXT_WELD_RTOL", "FLOAT32_WELD_ULPS",
]  # fmt: skip

#: File-name endings :func:`read_mesh` understands (case-insensitive).
SUFFIXES = (".stl", ".obj")

#: Default size limit of a mesh file in bytes (1 GiB: an ASCII STL of ~4 M triangles,
#: a binary STL of ~21 M); the environment variable ``RBCLI_MAX_MESH_BYTES`` changes it.
MAX_MESH_BYTES = 1 << 30

#: Text formats (ASCII STL, OBJ): the default weld tolerance is this times the diagonal
#: of the bounding box (and at least 4 float64 ulps of the largest coordinate).
TEXT_WELD_RTOL = 1e-9

#: Binary STL stores float32: the default weld tolerance is this many float32 ulps of
#: the largest coordinate magnitude (the spacing of the file's own numbers there).
FLOAT32_WELD_ULPS = 4

# One binary STL record: normal (ignored), three vertices, "attribute byte count".
_STL_RECORD = np.dtype([("normal", "<f4", (3,)), ("v", "<f4", (3, 3)), ("attr", "<u2")])
assert _STL_RECORD.itemsize == 50

# An ASCII STL facet is exactly 21 whitespace-separated tokens:
#   facet normal nx ny nz outer loop vertex x y z vertex x y z vertex x y z endloop endfacet
_FACET_KEYWORDS = {
    0: b"facet", 1: b"normal", 5: b"outer", 6: b"loop",
    7: b"vertex", 11: b"vertex", 15: b"vertex", 19: b"endloop", 20: b"endfacet",
}  # fmt: skip
_FACET_COORDS = (8, 9, 10, 12, 13, 14, 16, 17, 18)
_SOLID_LINE = re.compile(rb"^[ \t]*(?:end)?solid\b[^\r\n]*", re.MULTILINE)
_TOKEN = re.compile(rb"\S+")
_CHUNK = 1 << 21  # text files are parsed in blocks of about 2 MiB (cache-sized: 30 % faster than 16)


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


class MeshFile(NamedTuple):
    """What :func:`read_mesh` returns.

    Attributes
    ----------
    vertices : (V, 3) ndarray of float64 — distinct positions, in the file's length unit
    faces : (F, 3) ndarray of int64 — vertex indices of each triangle, in file order
    format : str — ``"binary stl"``, ``"ascii stl"`` or ``"obj"``
    weld : float — the default weld tolerance for this file (file unit), see
        :func:`default_weld`
    """

    vertices: np.ndarray
    faces: np.ndarray
    format: str
    weld: float


def max_mesh_bytes() -> int:
    """The mesh-file size limit in bytes: ``RBCLI_MAX_MESH_BYTES`` or :data:`MAX_MESH_BYTES`.

    The variable holds a number of bytes, optionally with a suffix ``k``, ``M``, ``G``
    (powers of 1024, e.g. ``4G``). A value that is not such a number is an error.
    """
    text = os.environ.get("RBCLI_MAX_MESH_BYTES", "").strip()
    if not text:
        return MAX_MESH_BYTES
    m = re.fullmatch(r"([0-9]{1,15})\s*([kKmMgGtT]?)(?:i?[bB])?", text)
    if not m:
        shown = text if len(text) <= 30 else text[:30] + "…"
        raise ValueError(
            f"RBCLI_MAX_MESH_BYTES must be a number of bytes such as 2000000000 or 2G, not {shown!r}"
        )
    power = " KMGT".index(m.group(2).upper() or " ")
    return int(m.group(1)) << (10 * power)


def default_weld(fmt: str, vertices: np.ndarray) -> float:
    """The weld tolerance that suits a file's own precision (in the file's unit).

    Parameters
    ----------
    fmt : str — ``"binary stl"`` (float32 coordinates) or a text format
    vertices : (V, 3) ndarray — the file's distinct vertices

    Returns
    -------
    float
        Binary STL: :data:`FLOAT32_WELD_ULPS` float32 ulps at the largest coordinate
        magnitude M, ``4 * 2**(floor(log2 M) - 23)`` (about 5e-7 M): two float32 numbers
        that round the same CAD value differently differ by one or two. Text formats:
        :data:`TEXT_WELD_RTOL` times the bounding-box diagonal, at least 4 float64 ulps
        of M. 0 for an empty or all-zero mesh.
    """
    if len(vertices) == 0:
        return 0.0
    big = float(np.abs(vertices).max())
    if big == 0.0:
        return 0.0
    if fmt == "binary stl":
        return float(FLOAT32_WELD_ULPS * np.spacing(np.float32(big)))
    diag = float(np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0)))
    return max(TEXT_WELD_RTOL * diag, 4.0 * float(np.spacing(big)))


def read_mesh(path: str | os.PathLike[str], *, max_bytes: int | None = None) -> MeshFile:
    """Read a triangle mesh from an STL (binary or ASCII) or OBJ file.

    Parameters
    ----------
    path : str or path-like
        The file. Its format comes from the extension, ``.stl`` or ``.obj``
        (case-insensitive).
    max_bytes : int, optional
        Refuse a larger file before reading it; default :func:`max_mesh_bytes`.

    Returns
    -------
    MeshFile
        ``(vertices, faces, format, weld)``: distinct vertex positions (float64, the
        file's unit), triangles as vertex indices in file order (so the file's
        orientation is kept), the format and its default weld tolerance. Vertices with
        exactly equal coordinates are merged (``-0.0`` equals ``0.0``); polygons with
        more than three corners (OBJ) are fanned into triangles.

    Raises
    ------
    MeshFileError
        Unknown extension; a file that is missing, not a regular file (directory, FIFO,
        device, socket), over the size limit, unreadable, or whose name holds a NUL; a
        truncated or malformed file (with the line, for text formats); NaN or infinite
        coordinates; a face index out of range (OBJ); a file without triangles.

    Notes
    -----
    Binary STL: an 80-byte header, a little-endian uint32 triangle count and 50-byte
    records (normal, three float32 vertices, uint16 attribute). A file is taken as
    binary when its size is exactly ``84 + 50 n`` for the count ``n`` in its header,
    even if the header starts with ``solid`` (many exporters do that), unless the
    bytes after the header are plain text containing ``facet``. Normals are ignored:
    the orientation comes from the vertex order. OBJ reads ``v`` and ``f`` lines
    (``f`` items ``i``, ``i/t``, ``i//n``, ``i/t/n``; negative indices count back from
    the latest vertex), ``#`` comments and ``\\`` line continuations.
    """
    p = os.fspath(path)
    name = p if isinstance(p, str) else os.fsdecode(p)
    suffix = os.path.splitext(name)[1].lower()
    if suffix not in SUFFIXES:
        allowed = ", ".join(SUFFIXES)
        shown = f"'{suffix}'" if suffix else "no extension"
        raise MeshFileError(name, f"unknown mesh file type ({shown}); use one of {allowed}")
    if max_bytes is None:
        try:
            max_bytes = max_mesh_bytes()
        except ValueError as exc:
            raise MeshFileError(name, str(exc)) from None
    fd, size = _open_regular(name, max_bytes)
    with open(fd, "rb", closefd=True) as fh:
        try:
            if suffix == ".obj":
                vertices, faces = _read_obj(name, _read_all(name, fh, size))
                fmt = "obj"
            else:
                vertices, faces, fmt = _read_stl(name, fh, size)
        except OSError as exc:
            raise _os_error(name, exc) from None
    return MeshFile(vertices, faces, fmt, default_weld(fmt, vertices))


# --------------------------------------------------------------------------- helpers


def _shown(name: str) -> str:
    return name.replace("\0", "\\0")


def _os_error(name: str, exc: OSError) -> MeshFileError:
    if isinstance(exc, FileNotFoundError):
        return MeshFileError(name, "no such file")
    if isinstance(exc, IsADirectoryError):
        return MeshFileError(name, "is a directory, not a mesh file")
    if isinstance(exc, PermissionError):
        return MeshFileError(name, "permission denied")
    reason = (exc.strerror or str(exc)).lower()
    return MeshFileError(name, f"cannot read the file: {reason}")


def _open_fd(name: str) -> int:
    """``os.open`` for reading without blocking (a FIFO opens at once, then is refused)."""
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0)
    return os.open(name, flags)


_KINDS = (
    (stat.S_ISDIR, "is a directory, not a mesh file"),
    (stat.S_ISFIFO, "is a FIFO (named pipe), not a regular file: rbcli reads meshes from files"),
    (stat.S_ISCHR, "is a character device, not a regular file"),
    (stat.S_ISBLK, "is a block device, not a regular file"),
    (stat.S_ISSOCK, "is a socket, not a regular file"),
)


def _open_regular(name: str, max_bytes: int) -> tuple[int, int]:
    """Open a regular file no larger than ``max_bytes``: (descriptor, size)."""
    if "\0" in name:
        raise MeshFileError(_shown(name), "a file name cannot contain a NUL character")
    try:
        fd = _open_fd(name)
    except OSError as exc:
        if getattr(exc, "errno", None) == 6:  # ENXIO: a socket
            raise MeshFileError(name, "is a socket, not a regular file") from None
        raise _os_error(name, exc) from None
    try:
        st = os.fstat(fd)
        for test, message in _KINDS:
            if test(st.st_mode):
                raise MeshFileError(name, message)
        if not stat.S_ISREG(st.st_mode):
            raise MeshFileError(name, "is not a regular file")
        if st.st_size > max_bytes:
            raise MeshFileError(
                name,
                f"the file is {st.st_size} bytes ({_gib(st.st_size)}), over the mesh size "
                f"limit of {max_bytes} bytes ({_gib(max_bytes)}); set RBCLI_MAX_MESH_BYTES "
                "(e.g. RBCLI_MAX_MESH_BYTES=4G) to read it",
            )
        if st.st_size == 0:
            raise MeshFileError(name, "empty file (no triangles)")
        os.set_blocking(fd, True)
    except BaseException:
        os.close(fd)
        raise
    return fd, int(st.st_size)


def _gib(n: int) -> str:
    return f"{n / 2**30:.3g} GiB" if n >= 2**30 else f"{n / 2**20:.3g} MiB"


def _read_all(name: str, fh, size: int) -> bytes:
    """The whole file (``size`` bytes, already checked against the limit)."""
    data = fh.read(size + 1)
    if len(data) > size:  # it grew while we read: take what fits the checked size
        raise MeshFileError(name, "the file changed while it was read")
    if not data:
        raise MeshFileError(name, "empty file (no triangles)")
    return data


def weld(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Merge points with exactly equal coordinates.

    Parameters
    ----------
    points : (N, 3) ndarray of float32 or float64
        Finite coordinates (not checked here).

    Returns
    -------
    unique : (U, 3) ndarray of float64
        The distinct points (in an order of no meaning).
    inverse : (N,) ndarray of int64
        ``unique[inverse] == points``.

    Notes
    -----
    ``-0.0`` is first turned into ``0.0`` (by adding zero), so equal floats have equal
    bit patterns. Each point's three bit patterns are hashed into one 64-bit number whose
    low bits are replaced by the point's index, and that array is sorted by value
    (``np.sort``, not an argsort: several times faster); equal points are then adjacent.
    Points whose hashes collide (equal high bits, different coordinates) are found by
    comparing neighbours and put in order by a lexicographic sort of their own, so the
    result is exact whatever the hash does. One sort of N keys, against two or three
    for a lexicographic sort of the coordinates; and a large array is first welded in
    blocks of :data:`_WELD_BLOCK` points (small sorts, in cache), then the blocks'
    distinct points together (:func:`_weld_blocks`: the same result, in half the time).
    """
    return _weld_blocks(np.asarray(points) + 0.0)  # canonical +0.0, a private contiguous copy


_WELD_BLOCK = 1 << 14


_MIX = (np.uint64(0xBF58476D1CE4E5B9), np.uint64(0x94D049BB133111EB))


def _mix(z: np.ndarray) -> np.ndarray:
    """splitmix64's finaliser, in place on a private uint64 array (wrapping arithmetic)."""
    z ^= z >> np.uint64(30)
    z *= _MIX[0]
    z ^= z >> np.uint64(27)
    z *= _MIX[1]
    z ^= z >> np.uint64(31)
    return z


def _weld_blocks(pts: np.ndarray, span: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """:func:`_weld` of a large array, block by block first; the same result.

    Each block of :data:`_WELD_BLOCK` points is welded on its own (a closed mesh's
    corners repeat mostly in nearby triangles: a block keeps about a fifth of its
    points), then the blocks' distinct points are welded together with ``span`` = the
    number of points, which gives the order the weld of the whole array gives.
    """
    n = len(pts)
    if n <= 2 * _WELD_BLOCK:
        return _weld(pts, span)
    firsts, k = [], 0
    local = np.empty(n, dtype=np.int64)  # each point's place among the blocks' distinct points
    for i in range(0, n, _WELD_BLOCK):
        unique, inverse = _weld(pts[i : i + _WELD_BLOCK], same_dtype=True)
        firsts.append(unique)
        np.add(inverse, k, out=local[i : i + _WELD_BLOCK])
        k += len(unique)
    unique, inverse = _weld(np.concatenate(firsts), max(n, span))
    del firsts
    return unique, inverse.take(local)


def _sort_hashes(h: np.ndarray, span: int) -> tuple[np.ndarray, np.ndarray]:
    """Sort the 64-bit hashes ``h`` (changed in place) with each one's index in its low
    bits, enough bits for ``span`` (at least ``len(h)``) indices: one value sort, ties in
    index order. Returns (the sorted hashes less those bits, the indices in sorted order).
    Equal hashes need not be equal keys: the callers compare neighbours."""
    ib = max(1, (span - 1).bit_length())
    low = np.uint64((1 << ib) - 1)
    h &= ~low
    h |= np.arange(len(h), dtype=np.uint64)
    h.sort()
    order = (h & low).astype(np.intp)
    h >>= np.uint64(ib)
    return h, order


def _weld(pts: np.ndarray, span: int = 0, same_dtype: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """:func:`weld` for a C-contiguous float32/float64 array without -0.0 (not copied).

    ``span`` (at least ``len(pts)``) sets how many low bits of the hash hold the index, as
    if there were that many points: the distinct points then come out in the order
    they would for any larger array holding the same values (:func:`_weld_blocks`, and
    the ASCII STL reader, which welds each block's distinct corner texts, must give the
    weld of all the corners). ``same_dtype``: the distinct points in ``pts``'s dtype
    (float32 stays float32), not float64.
    """
    if pts.dtype != np.float32:
        pts = pts.astype(np.float64, copy=False)
    n = len(pts)
    span = max(n, span)
    bits = pts.view(np.uint32 if pts.dtype == np.float32 else np.uint64)
    with np.errstate(over="ignore"):
        h = _mix(bits[:, 0].astype(np.uint64))
        h ^= bits[:, 1]
        h = _mix(h)
        h ^= bits[:, 2]
        h = _mix(h)
    h, order = _sort_hashes(h, span)
    same_hash = h[1:] == h[:-1]
    del h
    flat = bits.reshape(-1)
    at = order * 3
    differ = np.zeros(n - 1, dtype=bool)
    for k in range(3):  # one column at a time: three 1-D takes beat a (n, 3) row gather
        col = flat.take(at + k) if k else flat.take(at)
        differ |= col[1:] != col[:-1]
    del col, at
    clash = same_hash & differ
    if clash.any():  # a hash collision: order those runs by their coordinates
        run = np.cumsum(np.concatenate(([True], ~same_hash)))
        bad_runs = np.unique(run[1:][clash])
        at = np.flatnonzero(np.isin(run, bad_runs))
        sub = bits[order[at]]
        local = np.lexsort((sub[:, 2], sub[:, 1], sub[:, 0], run[at]))
        order[at] = order[at][local]
        s = bits[order]
        differ = (s[1:] != s[:-1]).any(axis=1)
        del s
    new = np.empty(n, dtype=bool)
    new[:1] = True
    new[1:] = differ
    ids = np.cumsum(new, dtype=np.int64)
    ids -= 1
    inverse = np.empty(n, dtype=np.int64)
    inverse[order] = ids
    unique = pts[order[new]]
    return (unique if same_dtype else unique.astype(np.float64)), inverse


def _finish(name: str, corners: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Check a (3F, 3) array of triangle corners and weld it into an indexed mesh.

    ``corners`` is a private C-contiguous float32/float64 array (it is modified).
    """
    if corners.shape[0] == 0:
        raise MeshFileError(name, "the file holds no triangles")
    finite = np.isfinite(corners)
    if not finite.all():
        bad = int(np.flatnonzero(~finite.all(axis=1))[0])
        raise MeshFileError(
            name, f"triangle {bad // 3 + 1} has a non-finite coordinate (nan or inf)"
        )
    del finite
    corners += 0.0  # -0.0 -> +0.0, in place
    unique, inverse = _weld_blocks(corners)
    return unique, inverse.reshape(-1, 3)


def _line_of(text: bytes, offset: int) -> int:
    return text.count(b"\n", 0, offset) + 1


# ------------------------------------------------------------------------------ STL


def _read_stl(name: str, fh, size: int) -> tuple[np.ndarray, np.ndarray, str]:
    """An STL file's welded (vertices, faces) and its format."""
    first = fh.read(84 + 4096)
    head = first[:84]
    starts_solid = head.lstrip().lower().startswith(b"solid")
    if size >= 84:
        count = int(np.frombuffer(head, dtype="<u4", count=1, offset=80)[0])
        if size == 84 + 50 * count and not (starts_solid and _looks_like_text(first)):
            if count == 0:
                raise MeshFileError(name, "binary stl with 0 triangles (empty mesh)")
            fh.seek(84)
            records = np.fromfile(fh, dtype=_STL_RECORD, count=count)
            if len(records) != count:
                raise MeshFileError(name, "the file changed while it was read")
            corners = np.ascontiguousarray(records["v"].reshape(-1, 3))
            del records
            return (*_finish(name, corners), "binary stl")
    if starts_solid:
        fh.seek(0)
        got = _read_stl_ascii_fast(fh, size)
        if got is None:  # say where the file is wrong (or read an unusual layout)
            fh.seek(0)
            corners = _read_stl_ascii(name, _read_all(name, fh, size))
            return (*_finish(name, corners), "ascii stl")
        points, corner_of = got
        points += 0.0  # -0.0 -> +0.0, in place
        # the weld of all 3F corners, done on their distinct texts' numbers (same result)
        unique, inverse = _weld(points, span=corner_of.size)
        return unique, inverse[corner_of].reshape(-1, 3), "ascii stl"
    if size < 84:
        raise MeshFileError(
            name,
            f"not an stl file: {size} bytes is too short for a binary stl (84-byte header) "
            "and the file does not start with 'solid'",
        )
    held = (size - 84) / 50
    shown = f"{held:.1f}" if held != int(held) else f"{int(held)}"
    raise MeshFileError(
        name,
        f"truncated or corrupt binary stl: header says {count} triangles "
        f"({84 + 50 * count} bytes), file holds {shown} ({size} bytes)",
    )


def _looks_like_text(first: bytes) -> bool:
    """True if the bytes after an 84-byte header look like ASCII STL text."""
    sample = np.frombuffer(first[84:], dtype=np.uint8)
    if sample.size == 0:
        return False
    printable = (sample >= 32) & (sample < 127) | (sample == 9) | (sample == 10) | (sample == 13)
    return bool(printable.all()) and b"facet" in first.lower()


def _read_stl_ascii_fast(fh, size: int) -> tuple[np.ndarray, np.ndarray] | None:
    """An ASCII STL read in blocks, or None if the file needs :func:`_read_stl_ascii`.

    Returns ``(points, inverse)``: ``points[inverse]`` are the (3F, 3) triangle corners
    in file order (float64), ``points`` holding each block's distinct corner texts once.
    Each block ends with the line of its last ``endfacet``; ``solid``/``endsolid`` lines
    are blanked as in the line reader. A block is accepted only if its tokens are exactly
    the 21-token facet pattern (:func:`_facets_of`) and its coordinates are finite; then
    its coordinates are the same bits as the line reader's (Python's ``float``, numpy's
    array conversion and ``np.fromstring`` all round correctly). Anything else returns
    None, and the line reader reads the file or says which line is wrong. Peak memory is
    one block's temporaries plus the distinct points and an index per corner, not the
    file.
    """
    blocks: list[np.ndarray] = []
    inverses: list[np.ndarray] = []
    n_points = 0
    rest = b""
    seen_end = False
    while True:
        chunk = fh.read(_CHUNK)
        text = (rest + chunk).lower() if rest else chunk.lower()
        if chunk:  # cut after the line of the last 'endfacet': whole lines, whole facets
            last = text.rfind(b"endfacet")
            cut = text.find(b"\n", last) + 1 if last >= 0 else 0
            if cut <= 0:
                if len(text) > 4 * _CHUNK:
                    return None
                rest = text
                continue
            text, rest = text[:cut], text[cut:]
        else:
            rest = b""
        text, ended = _blank_solid_lines(text)
        seen_end = seen_end or ended
        if text.strip():
            got = _facets_of(text)
            if got is None:
                return None
            blocks.append(got[0])
            inverses.append(got[1] + n_points if n_points else got[1])
            n_points += len(got[0])
        if not chunk:
            break
    if not seen_end or not blocks:
        return None
    if len(blocks) == 1:
        return blocks[0], inverses[0]
    return np.concatenate(blocks), np.concatenate(inverses)


def _blank_solid_lines(text: bytes) -> tuple[bytes, bool]:
    """Blank out 'solid NAME' / 'endsolid NAME' lines; (text, whether an endsolid was seen).

    Names may hold any words; the newlines stay, so offsets still give line numbers.
    Several solids are allowed. The same as ``_SOLID_LINE.sub`` with spaces, but it only
    looks at the lines where the word occurs (a regex anchored at every line start
    would try each of a large file's lines).
    """
    pos = text.find(b"solid")
    if pos < 0:
        return text, False
    out = bytearray(text)
    ended = False
    while pos >= 0:
        start = text.rfind(b"\n", 0, pos) + 1
        m = _SOLID_LINE.match(text, start)
        if m is not None and m.end() > pos:
            out[m.start() : m.end()] = b" " * (m.end() - m.start())
            ended = ended or b"endsolid" in m.group(0)[: pos - start + 5]
            pos = text.find(b"solid", m.end())
        else:
            pos = text.find(b"solid", pos + 5)
    return bytes(out), ended


_KEYWORD_BYTES = {k: np.frombuffer(w, dtype=np.uint8) for k, w in _FACET_KEYWORDS.items()}


def _facets_of(text: bytes) -> tuple[np.ndarray, np.ndarray] | None:
    """The corners of a block of whole facets, as (points, inverse), or None if not well formed.

    Tokens are found with numpy (whitespace as ``bytes.split`` sees it); the keyword
    tokens are compared byte by byte, column by column. Each ``vertex`` line's text (its
    three coordinate tokens and the whitespace between them) is read only once per block
    (:func:`_distinct_spans`: a vertex of a closed mesh is written about six times, mostly
    in nearby facets), with the whitespace byte after it, by ``np.fromstring``, which must
    find exactly three numbers in each. ``points[inverse]`` are the (3n, 3) corners in
    file order; equal text gives equal numbers, so these are the bits every token would
    have been read to.
    """
    a = np.frombuffer(text if text.endswith(b"\n") else text + b"\n", dtype=np.uint8)
    ws = (a == 32) | ((a >= 9) & (a <= 13))  # ASCII whitespace, as bytes.split()
    edge = ws[1:] != ws[:-1]
    starts = np.flatnonzero(edge & ws[:-1]) + 1
    if not ws[0]:
        starts = np.concatenate(([0], starts))
    ends = np.flatnonzero(edge & ~ws[:-1]) + 1  # one past each token (a whitespace byte)
    del edge, ws
    n, extra = divmod(starts.size, 21)
    if extra or n == 0 or ends.size != starts.size:
        return None
    starts = starts.reshape(n, 21)
    ends = ends.reshape(n, 21)
    for k, word in _KEYWORD_BYTES.items():
        s = starts[:, k]
        if not (ends[:, k] - s == word.size).all():
            return None
        for i, ch in enumerate(word):
            if not (a[s + i] == ch).all():
                return None
    lo = starts[:, (8, 12, 16)].ravel()  # each corner's 'x y z' text: [lo, hi)
    hi = ends[:, (10, 14, 18)].ravel()
    del starts, ends
    first, inverse = _distinct_spans(a, lo, hi)
    # each distinct corner's text with the whitespace byte after it
    values = meshnumbers.floats(_ranges(a, lo[first], hi[first] + 1))
    if values is None or values.size != 3 * first.size or not np.isfinite(values).all():
        return None
    return values.reshape(-1, 3), inverse


_LOW_BYTES = np.array([(1 << (8 * k)) - 1 for k in range(8)] + [(1 << 64) - 1], dtype=np.uint64)
_SPAN_WORDS = 16  # text keys of at most 128 bytes; longer 'vertex' lines are not merged


def _distinct_spans(a: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Group equal byte strings ``a[lo[i]:hi[i]]``: (first, inverse), exact.

    ``first`` holds, in increasing order, the index of the first string of each group
    found and ``inverse[i]`` the position in ``first`` of string i's group, so
    ``a[lo[first[inverse[i]]]:hi[...]] == a[lo[i]:hi[i]]``. Each string is read as up to
    :data:`_SPAN_WORDS` little-endian 64-bit words (the bytes past its end masked off,
    its length in the last word's place is implied by the mask: strings of different
    lengths differ in a word or in the length compared first), hashed, and the hashes
    sorted with the index in their low bits; neighbours are merged only when every word
    and the length are equal, so unequal strings are never merged (a hash collision only
    leaves two groups of the same text, each read on its own). Strings longer than
    ``8 * _SPAN_WORDS`` bytes are not merged at all.
    """
    m = lo.size
    length = hi - lo
    n_words = int(-(-int(length.max()) // 8)) if m else 0
    if m < 2 or n_words > _SPAN_WORDS:
        return np.arange(m), np.arange(m)
    pad = np.zeros(a.size + 8 * n_words + 8, dtype=np.uint8)
    pad[: a.size] = a
    # every byte offset's 8 bytes as one word (unaligned; indexing it is fast, take is not)
    words = np.ndarray((pad.size - 7,), dtype="<u8", buffer=pad, strides=(1,))
    keys = np.empty((n_words + 1, m), dtype=np.uint64)
    keys[0] = length
    at = lo.copy()
    left = length.copy()
    for j in range(n_words):
        keys[j + 1] = words[at]
        keys[j + 1] &= _LOW_BYTES[np.clip(left, 0, 8)]
        at += 8
        left -= 8
    del at, left, words, pad
    with np.errstate(over="ignore"):
        h = _mix(keys[0].copy())
        for j in range(1, n_words + 1):
            h ^= keys[j]
            h = _mix(h)
    order = _sort_hashes(h, m)[1]
    del h
    same = np.ones(m - 1, dtype=bool)
    for row in keys:
        col = row[order]
        same &= col[1:] == col[:-1]
    del keys, col
    new = np.empty(m, dtype=bool)
    new[0] = True
    np.logical_not(same, out=new[1:])
    head = order[new]  # each group's first index (the index is the sort's last key)
    group = np.cumsum(new) - 1
    is_first = np.zeros(m, dtype=bool)
    is_first[head] = True
    rank = np.cumsum(is_first) - 1  # a group's place among the firsts in file order
    inverse = np.empty(m, dtype=np.int64)
    inverse[order] = rank[head[group]]
    return np.flatnonzero(is_first), inverse


def _read_stl_ascii(name: str, data: bytes) -> np.ndarray:
    """The token-by-token ASCII STL reader: says which line is wrong."""
    body, ended = _blank_solid_lines(data.lower())
    if not ended:
        raise MeshFileError(name, "ascii stl without 'endsolid' (truncated file?)")
    tokens = body.split()
    n_tok = len(tokens)
    n = n_tok // 21
    if n == 0 and n_tok == 0:
        raise MeshFileError(name, "ascii stl without facets (empty mesh)")

    def fail_at(index: int, what: str) -> MeshFileError:
        match = next(itertools.islice(_TOKEN.finditer(body), index, None), None)
        line = _line_of(body, match.start()) if match else _line_of(body, len(body))
        return MeshFileError(name, what, line)

    first_bad = None
    for k, word in _FACET_KEYWORDS.items():
        column = tokens[k : 21 * n : 21]
        if column and set(column) != {word}:
            i = next(i for i, t in enumerate(column) if t != word)
            pos = 21 * i + k
            if first_bad is None or pos < first_bad[0]:
                first_bad = (pos, word)
    if first_bad is not None:
        pos, word = first_bad
        got = tokens[pos].decode("ascii", "replace")
        raise fail_at(pos, f"malformed ascii stl: expected '{word.decode()}', found '{got}'")
    if n_tok != 21 * n:
        raise fail_at(21 * n, "malformed ascii stl: incomplete facet")
    cols = []
    for k in _FACET_COORDS:
        column = tokens[k::21]
        try:
            cols.append(np.array(column, dtype=np.float64))
        except ValueError:
            for i, t in enumerate(column):
                try:
                    float(t)
                except ValueError:
                    got = t.decode("ascii", "replace")
                    raise fail_at(21 * i + k, f"malformed ascii stl: '{got}' is not a number")
            raise  # pragma: no cover - numpy and float() disagree
    return np.stack(cols, axis=1).reshape(-1, 3)


# ------------------------------------------------------------------------------ OBJ

_CONTINUATION = re.compile(rb"\\\r?\n")
_COMMENT = re.compile(rb"#[^\r\n]*")
_BIG_INDEX = 1 << 62


def _read_obj(name: str, text: bytes) -> tuple[np.ndarray, np.ndarray]:
    got = _read_obj_fast(text)
    if got is None:  # say where the file is wrong (or read an unusual layout)
        got = _read_obj_lines(name, text)
    points, faces = got
    unique, inverse = _weld(points + 0.0)
    return unique, inverse[faces]


def _read_obj_fast(text: bytes) -> tuple[np.ndarray, np.ndarray] | None:
    """Vertices and triangles of a plain OBJ file without a per-line Python parser.

    Accepts what :func:`_read_obj_lines` accepts when every ``v`` line holds exactly
    three numbers and every ``f`` item's index is a plain integer; returns None for
    anything else (and for any error), so that the line parser reads it or says where
    it is wrong. The file is read in blocks of whole lines (about 2 MiB, so the
    temporaries stay small); in each, lines are classified by their first two bytes
    with numpy and the ``v`` and ``f`` lines are gathered and read by ``np.fromstring``.
    """
    points, tris = [], []
    nv = 0
    pos = 0
    while pos < len(text):
        end = pos + _CHUNK
        if end < len(text):  # cut after a newline that does not end a continued line
            end = text.rfind(b"\n", pos, end)
            while end > pos and (text[end - 1] == 92 or text[end - 2 : end] == b"\\\r"):
                end = text.rfind(b"\n", pos, end)
            if end <= pos:
                return None
            end += 1
        got = _obj_block(text[pos:end], nv)
        if got is None:
            return None
        points.append(got[0])
        tris.append(got[1])
        nv += len(got[0])
        pos = end
    if nv == 0 or sum(len(t) for t in tris) == 0:
        return None
    faces = np.concatenate(tris) if len(tris) > 1 else tris[0]
    if faces.max() >= nv:  # an index past the last vertex: the line reader says where
        return None
    return (np.concatenate(points) if len(points) > 1 else points[0]), faces


def _obj_block(text: bytes, nv0: int) -> tuple[np.ndarray, np.ndarray] | None:
    """Vertices and triangles of a block of whole OBJ lines after ``nv0`` vertices."""
    if b"\\" in text:
        text = _CONTINUATION.sub(b" ", text)
    if b"#" in text:
        text = _COMMENT.sub(b"", text)
    if b"\r" in text:
        text = text.replace(b"\r\n", b"\n")
        if b"\r" in text:
            return None
    arr = np.frombuffer(text, dtype=np.uint8)
    starts = np.flatnonzero(arr == 10)
    ends = np.append(starts, arr.size)  # each line's end (its newline or the file's end)
    starts += 1
    starts = np.concatenate(([0], starts))
    padded = np.concatenate((arr, np.zeros(2, np.uint8)))
    first, second = padded[starts], padded[starts + 1]
    del padded
    if np.isin(first, (9, 11, 12, 32)).any():  # indented lines: the line parser
        return None
    key = (first == ord("v")) | (first == ord("f"))
    if (key & np.isin(second, (0, 10, 11, 12, 13))).any():  # a bare 'v' or 'f': an error
        return None
    blank2 = (second == 32) | (second == 9)
    is_v = (first == ord("v")) & blank2
    is_f = (first == ord("f")) & blank2
    v_at = np.flatnonzero(is_v)
    f_at = np.flatnonzero(is_f)
    vtext = _gather(text, starts[v_at] + 1, ends[v_at])
    points = meshnumbers.floats(vtext) if v_at.size else np.empty(0)
    if points is None or points.size != 3 * v_at.size or not np.isfinite(points).all():
        return None
    points = points.reshape(-1, 3)
    if f_at.size == 0:
        return points, np.empty((0, 3), np.int64)
    ftext = _gather(text, starts[f_at] + 1, ends[f_at])
    del arr
    fa = np.frombuffer(ftext, dtype=np.uint8)
    space = fa <= 32
    tok = ~space
    tok[1:] &= space[:-1]
    tok_at = np.flatnonzero(tok)
    del tok
    line_end = np.flatnonzero(fa == 10)  # every gathered line ends with a newline
    per_line = np.diff(np.searchsorted(tok_at, line_end), prepend=0)
    if per_line.min() < 3:
        return None
    if b"/" in ftext:
        slash = np.flatnonzero(fa == 47)
        owner = np.searchsorted(tok_at, slash, side="right") - 1
        firsts = slash[np.concatenate(([True], owner[1:] != owner[:-1]))]
        first_owner = np.searchsorted(tok_at, firsts, side="right") - 1
        # blank from the first '/' of each item to the item's end
        tok_end = np.flatnonzero(~space & np.append(space[1:], True)) + 1
        # keep all but each item's '/...' tail ('/2' alone leaves nothing: a count mismatch)
        ftext = _ranges(fa, np.concatenate(([0], tok_end[first_owner])), np.append(firsts, fa.size))
    del space, fa
    idx = meshnumbers.numbers(ftext, np.int64)
    if idx is None or idx.size != tok_at.size:
        return None
    del ftext, tok_at
    if (idx == 0).any() or (idx >= _BIG_INDEX).any():
        return None
    neg = idx < 0
    if neg.any():
        before = nv0 + np.searchsorted(v_at, f_at)  # vertices defined before each f line
        idx[neg] += np.repeat(before, per_line)[neg]
        if (idx[neg] < 0).any():
            return None
        idx[~neg] -= 1
    else:
        idx -= 1
    if (per_line == 3).all():
        return points, idx.reshape(-1, 3)
    first_of = np.cumsum(per_line) - per_line
    n_tri = per_line - 2
    line_of_tri = np.repeat(np.arange(per_line.size), n_tri)
    j = np.arange(n_tri.sum()) - np.repeat(np.cumsum(n_tri) - n_tri, n_tri) + 1
    base = first_of[line_of_tri]
    tris = np.stack((idx[base], idx[base + j], idx[base + j + 1]), axis=1)
    return points, tris


def _ranges(a: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> bytes:
    """The bytes ``a[lo[i]:hi[i]]`` joined, for sorted, disjoint ranges (run-length decoded)."""
    edges = np.empty(2 * lo.size + 2, dtype=np.int64)
    edges[0] = 0
    edges[1:-1:2] = lo
    edges[2:-1:2] = hi
    edges[-1] = a.size
    keep = np.repeat(np.tile(np.array([False, True]), lo.size + 1)[: edges.size - 1], np.diff(edges))
    return a[keep].tobytes()


def _gather(text: bytes, lo: np.ndarray, hi: np.ndarray) -> bytes:
    """The lines [lo, hi) of ``text`` (hi at a newline or the end), each with its newline."""
    if lo.size == 0:
        return b""
    return _ranges(np.frombuffer(text + b"\n", dtype=np.uint8), lo, hi + 1)


def _read_obj_lines(name: str, text: bytes) -> tuple[np.ndarray, np.ndarray]:
    """The line-by-line OBJ reader: says which line is wrong."""
    verts: list[list[bytes]] = []
    vert_lines: list[int] = []
    tris: list[tuple[int, int, int]] = []
    tri_lines: list[int] = []
    huge: tuple[bytes, int] | None = None  # the first index too large for int64
    lines = text.splitlines()
    lineno = 0
    while lineno < len(lines):
        raw = lines[lineno]
        lineno += 1
        start = lineno
        while raw.endswith(b"\\") and lineno < len(lines):  # a continued line
            raw = raw[:-1] + b" " + lines[lineno]
            lineno += 1
        parts = raw.split(b"#", 1)[0].split()
        if not parts:
            continue
        key = parts[0]
        if key == b"v":
            if len(parts) < 4:
                raise MeshFileError(name, "vertex line needs x y z", start)
            verts.append(parts[1:4])
            vert_lines.append(start)
        elif key == b"f":
            if len(parts) < 4:
                raise MeshFileError(name, "face needs at least 3 vertices", start)
            n_now = len(verts)
            idx = []
            for item in parts[1:]:
                head = item.split(b"/", 1)[0]
                try:
                    i = int(head)
                except ValueError:
                    got = _cut(item.decode("ascii", "replace"))
                    raise MeshFileError(name, f"bad face index '{got}'", start) from None
                if i < 0:
                    i += n_now  # relative: -1 is the latest vertex so far
                    if i < 0:
                        raise MeshFileError(
                            name,
                            f"face index {_cut(head.decode())} is out of range "
                            f"({n_now} vertices defined so far)",
                            start,
                        )
                elif i == 0:
                    raise MeshFileError(name, "face index 0 (obj indices start at 1)", start)
                else:
                    i -= 1
                    if i >= _BIG_INDEX:  # far out of range: keep int64 arithmetic
                        huge = huge or (head, start)
                        i = _BIG_INDEX
                idx.append(i)
            for j in range(1, len(idx) - 1):  # fan a polygon into triangles
                tris.append((idx[0], idx[j], idx[j + 1]))
                tri_lines.append(start)
        # vt, vn, vp, o, g, s, usemtl, mtllib, l, p, comments...: nothing to do
    if not tris:
        raise MeshFileError(name, "obj file without faces (empty mesh)")
    try:
        points = np.array(verts, dtype=np.float64)
    except ValueError:
        for row, lineno in zip(verts, vert_lines):
            for t in row:
                try:
                    float(t)
                except ValueError:
                    got = _cut(t.decode("ascii", "replace"))
                    raise MeshFileError(name, f"'{got}' is not a number", lineno) from None
        raise  # pragma: no cover
    faces = np.array(tris, dtype=np.int64)
    over = faces >= len(points)
    if over.any():
        t = int(np.flatnonzero(over.any(axis=1))[0])
        bad = int(faces[t][over[t]][0])
        shown = _cut(huge[0].decode()) if bad == _BIG_INDEX and huge else str(bad + 1)
        raise MeshFileError(
            name,
            f"face index {shown} is out of range (the file has {len(points)} vertices)",
            tri_lines[t],
        )
    finite = np.isfinite(points).all(axis=1)
    if not finite.all():
        bad = int(np.flatnonzero(~finite)[0])
        raise MeshFileError(
            name, "vertex has a non-finite coordinate (nan or inf)", vert_lines[bad]
        )
    return points, faces


def _cut(text: str, limit: int = 24) -> str:
    """A number or word from the file, shortened when it is long."""
    return text if len(text) <= limit else f"{text[:limit]}… ({len(text)} characters)"
