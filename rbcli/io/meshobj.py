"""The Wavefront OBJ reader: ``v`` and ``f`` lines into an indexed, welded mesh.

A plain file is read in blocks of whole lines with numpy (:func:`_read_obj_fast`); the
line-by-line reader (:func:`_read_obj_lines`) reads what it refuses and says which line is
wrong (the same bits either way, tested). Numbers follow the format's grammar (C's decimal
numbers; indices ``[+-]digits``), not Python's (no ``1_000``). A file without a face line
is refused before any number is read (a cloud of 10^7 vertices costs a scan of its bytes,
not its numbers), and so is a face of more than :data:`MAX_FACE_CORNERS` corners.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

import numpy as np

from rbcli.io.meshbase import MeshFileError, cut, floats, numbers
from rbcli.io.meshweld import join_ranges, weld_points

_CHUNK = 1 << 21  # the text is parsed in blocks of about 2 MiB (cache-sized: 30 % faster than 16)

_CONTINUATION = re.compile(rb"\\\r?\n")
_COMMENT = re.compile(rb"#[^\r\n]*")
_BIG_INDEX = 1 << 62
#: the most corners a face (polygon) may have: Assimp's AI_MAX_FACE_INDICES (0x7fff, its
#: mesh.h); a face of more is no CAD face (the audit's had one vertex repeated 10^5 times)
MAX_FACE_CORNERS = 0x7FFF
#: a face line: 'f' as the first word of a line (what the line reader reads as one; a line
#: continued onto the next, or a comment right after the f, counted too)
_FACE_LINE = re.compile(rb"(?:\A|[\r\n])\s*f(?:[\s#\\]|\Z)")
_INDEX = re.compile(rb"[+-]?[0-9]+")


def read_obj(name: str, text: bytes) -> tuple[np.ndarray, np.ndarray]:
    """An OBJ file's (distinct vertices, triangles), welded exactly."""
    if not _has_face_line(text):  # before any number is read
        raise MeshFileError(name, "obj file without faces (empty mesh)")
    got = _read_obj_fast(text)
    if got is None:  # say where the file is wrong (or read an unusual layout)
        got = _read_obj_lines(name, text)
    points, faces = got
    unique, inverse = weld_points(points + 0.0)
    return unique, inverse[faces]


def _has_face_line(text: bytes) -> bool:
    """Whether a line of ``text`` starts with the word ``f`` (a false yes leaves the refusal
    to the line reader); plain ``bytes`` searches first, :data:`_FACE_LINE` only if needed."""
    if b"\nf " in text or text.startswith(b"f "):
        return True
    return b"f" in text and _FACE_LINE.search(text) is not None


def _read_obj_fast(text: bytes) -> tuple[np.ndarray, np.ndarray] | None:
    """Vertices and triangles of a plain OBJ file without a per-line Python parser.

    Accepts what :func:`_read_obj_lines` accepts when every ``v`` line holds exactly
    three numbers and every ``f`` item's index is a plain integer; None for anything else.
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
    points = numbers(vtext) if v_at.size else np.empty(0)
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
    if per_line.min() < 3 or per_line.max() > MAX_FACE_CORNERS:
        return None
    if b"/" in ftext:
        slash = np.flatnonzero(fa == 47)
        owner = np.searchsorted(tok_at, slash, side="right") - 1
        firsts = slash[np.concatenate(([True], owner[1:] != owner[:-1]))]
        first_owner = np.searchsorted(tok_at, firsts, side="right") - 1
        # blank from the first '/' of each item to the item's end
        tok_end = np.flatnonzero(~space & np.append(space[1:], True)) + 1
        # keep all but each item's '/...' tail ('/2' alone leaves nothing: a count mismatch)
        ftext = join_ranges(fa, np.concatenate(([0], tok_end[first_owner])), np.append(firsts, fa.size))
    del space, fa
    idx = numbers(ftext, np.int64)
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



def _gather(text: bytes, lo: np.ndarray, hi: np.ndarray) -> bytes:
    """The lines [lo, hi) of ``text`` (hi at a newline or the end), each with its newline."""
    if lo.size == 0:
        return b""
    return join_ranges(np.frombuffer(text + b"\n", dtype=np.uint8), lo, hi + 1)


def _read_obj_lines(name: str, text: bytes) -> tuple[np.ndarray, np.ndarray]:
    """The line-by-line OBJ reader: says which line is wrong."""
    verts: list[list[bytes]] = []
    vert_lines: list[int] = []
    tris: list[tuple[int, int, int]] = []
    tri_lines: list[int] = []
    huge: list[tuple[bytes, int]] = []  # the first index too large for int64
    for start, parts in _obj_lines(text):
        if parts[0] == b"v":
            if len(parts) < 4:
                raise MeshFileError(name, "vertex line needs x y z", start)
            verts.append(parts[1:4])
            vert_lines.append(start)
        elif parts[0] == b"f":
            idx = _face_indices(name, parts, start, len(verts), huge)
            for j in range(1, len(idx) - 1):  # fan a polygon into triangles
                tris.append((idx[0], idx[j], idx[j + 1]))
                tri_lines.append(start)
        # vt, vn, vp, o, g, s, usemtl, mtllib, l, p, comments...: nothing to do
    if not tris:
        raise MeshFileError(name, "obj file without faces (empty mesh)")
    points = _vertex_array(name, verts, vert_lines)
    faces = np.array(tris, dtype=np.int64)
    over = faces >= len(points)
    if over.any():
        t = int(np.flatnonzero(over.any(axis=1))[0])
        bad = int(faces[t][over[t]][0])
        shown = cut(huge[0][0].decode()) if bad == _BIG_INDEX and huge else str(bad + 1)
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


def _obj_lines(text: bytes) -> Iterator[tuple[int, list[bytes]]]:
    """(1-based line, its words) of each OBJ line that has words: a line ending in ``\\``
    continued onto the next, comments dropped."""
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
        if parts:
            yield start, parts


def _face_indices(name: str, parts: list[bytes], start: int, n_now: int,
                  huge: list[tuple[bytes, int]]) -> list[int]:
    """The 0-based vertex indices of the face line ``parts`` (line ``start``, ``n_now``
    vertices defined before it); an index too large for int64 is kept as ``_BIG_INDEX``
    and the first such one noted in ``huge``."""
    if len(parts) < 4:
        raise MeshFileError(name, "face needs at least 3 vertices", start)
    if len(parts) - 1 > MAX_FACE_CORNERS:
        raise MeshFileError(name, f"a face of {len(parts) - 1} corners; faces have at most "
                            f"{MAX_FACE_CORNERS}", start)
    idx = []
    for item in parts[1:]:
        head = item.split(b"/", 1)[0]
        if not (head.isdigit() or _INDEX.fullmatch(head)):  # not int()'s '1_0'
            raise MeshFileError(name, f"bad face index '{cut(item.decode('ascii', 'replace'))}'", start)
        sign, digits = (b"-", head[1:]) if head[:1] == b"-" else (b"", head)
        digits = digits.lstrip(b"0") or b"0"  # 20 digits or more: out of range (int() refuses 4300)
        i = int(sign + (digits if len(digits) < 20 else b"9" * 20))
        if i == 0:
            raise MeshFileError(name, "face index 0 (obj indices start at 1)", start)
        if i < 0:
            i += n_now  # relative: -1 is the latest vertex so far
            if i < 0:
                raise MeshFileError(name, f"face index {cut(head.decode())} is out of range "
                                    f"({n_now} vertices defined so far)", start)
        else:
            i -= 1
            if i >= _BIG_INDEX:  # far out of range: keep int64 arithmetic
                if not huge:
                    huge.append((head, start))
                i = _BIG_INDEX
        idx.append(i)
    return idx


def _vertex_array(name: str, verts: list[list[bytes]], vert_lines: list[int]) -> np.ndarray:
    """The vertices' coordinates (texts) as numbers; the first that is not one located."""
    return floats([t for row in verts for t in row], lambda i, t: MeshFileError(
        name, f"'{cut(t.decode('ascii', 'replace'))}' is not a number", vert_lines[i // 3])).reshape(-1, 3)
