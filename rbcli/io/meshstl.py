"""The STL reader (binary and ASCII): a file's triangles welded into an indexed mesh.

ASCII text is read in blocks of whole facets, tokenised with numpy, each block's distinct
``vertex`` texts read once; the token-by-token reader (:func:`_read_stl_ascii`) reads what
the fast path refuses and says which line is wrong. Both give the same bits (tested).
"""

from __future__ import annotations

import itertools
import re

import numpy as np

from rbcli.io.meshbase import MeshFileError, floats, line_of, numbers, read_all
from rbcli.io.meshweld import distinct_spans, join_ranges, weld_blocks, weld_points

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

def _finish(name: str, corners: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Check (3F, 3) triangle corners (C-contiguous, modified in place) and weld them."""
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
    unique, inverse = weld_blocks(corners)
    return unique, inverse.reshape(-1, 3)


def read_stl(name: str, fh, size: int) -> tuple[np.ndarray, np.ndarray, str]:
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
            corners = _read_stl_ascii(name, read_all(name, fh, size))
            return (*_finish(name, corners), "ascii stl")
        points, corner_of = got
        points += 0.0  # -0.0 -> +0.0, in place
        # the weld of all 3F corners, done on their distinct texts' numbers (same result)
        unique, inverse = weld_points(points, span=corner_of.size)
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

    Returns ``(points, inverse)``: ``points[inverse]`` are the (3F, 3) corners in file order
    (float64). A block (ending with the line of its last ``endfacet``) is accepted only if
    its tokens are exactly the 21-token facet pattern and its coordinates finite. Peak
    memory is one block's temporaries plus the distinct points, not the file.
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

    The newlines stay, so offsets still give line numbers. Like ``_SOLID_LINE.sub`` with
    spaces, but it only looks at the lines where the word occurs.
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

    Each distinct ``x y z`` text is read once (a closed mesh writes a vertex about six
    times); equal text gives equal numbers, so these are the bits every token would give.
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
    first, inverse = distinct_spans(a, lo, hi)
    # each distinct corner's text with the whitespace byte after it
    values = numbers(join_ranges(a, lo[first], hi[first] + 1))
    if values is None or values.size != 3 * first.size or not np.isfinite(values).all():
        return None
    return values.reshape(-1, 3), inverse



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
        line = line_of(body, match.start()) if match else line_of(body, len(body))
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
    cols = [floats(tokens[k::21], lambda i, t, k=k: fail_at(
        21 * i + k, f"malformed ascii stl: '{t.decode('ascii', 'replace')}' is not a number")) for k in _FACET_COORDS]
    return np.stack(cols, axis=1).reshape(-1, 3)

