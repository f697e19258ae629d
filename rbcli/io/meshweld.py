"""Exact grouping by hashing, for the mesh readers: points with equal coordinates merged
(:func:`weld`) and equal byte strings grouped (:func:`distinct_spans`, an ASCII STL's
repeated ``vertex`` texts). numpy only; every result exact whatever the hash does.
"""

from __future__ import annotations

import numpy as np

__all__ = ["weld"]


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
    ``-0.0`` becomes ``0.0``. Each point's bits are hashed into a 64-bit key whose low bits
    hold its index, and the keys sorted: equal points are adjacent, colliding hashes are
    sorted lexicographically, so the result is exact (:func:`weld_blocks`).
    """
    return weld_blocks(np.asarray(points) + 0.0)  # canonical +0.0, a private contiguous copy


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


def weld_blocks(pts: np.ndarray, span: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """:func:`weld_points` of a large array, block by block first; the same result.

    Each block of :data:`_WELD_BLOCK` points is welded on its own (a closed mesh's
    corners repeat mostly in nearby triangles: a block keeps about a fifth of its
    points), then the blocks' distinct points are welded together with ``span`` = the
    number of points, which gives the order the weld of the whole array gives.
    """
    n = len(pts)
    if n <= 2 * _WELD_BLOCK:
        return weld_points(pts, span)
    firsts, k = [], 0
    local = np.empty(n, dtype=np.int64)  # each point's place among the blocks' distinct points
    for i in range(0, n, _WELD_BLOCK):
        unique, inverse = weld_points(pts[i : i + _WELD_BLOCK], same_dtype=True)
        firsts.append(unique)
        np.add(inverse, k, out=local[i : i + _WELD_BLOCK])
        k += len(unique)
    unique, inverse = weld_points(np.concatenate(firsts), max(n, span))
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


def weld_points(pts: np.ndarray, span: int = 0, same_dtype: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """:func:`weld` for a C-contiguous float32/float64 array without -0.0 (not copied).

    ``span`` (at least ``len(pts)``) sets how many low bits of the hash hold the index, as
    if there were that many points: the distinct points then come out in the order
    they would for any larger array holding the same values (:func:`weld_blocks`, and
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


_LOW_BYTES = np.array([(1 << (8 * k)) - 1 for k in range(8)] + [(1 << 64) - 1], dtype=np.uint64)
_SPAN_WORDS = 16  # text keys of at most 128 bytes; longer 'vertex' lines are not merged


def distinct_spans(a: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Group equal byte strings ``a[lo[i]:hi[i]]``: (first, inverse), exact.

    ``first``: ascending, the first string of each group; ``inverse[i]``: the position in
    ``first`` of string i's group. Each string is read as up to :data:`_SPAN_WORDS`
    little-endian 64-bit words (bytes past its end masked off), hashed, and sorted with
    its index in the low bits; neighbours merge only when every word and the length are
    equal (a collision only leaves two groups of one text). Longer strings are not merged.
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


def join_ranges(a: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> bytes:
    """The bytes ``a[lo[i]:hi[i]]`` joined, for sorted, disjoint ranges (run-length decoded)."""
    edges = np.empty(2 * lo.size + 2, dtype=np.int64)
    edges[0] = 0
    edges[1:-1:2] = lo
    edges[2:-1:2] = hi
    edges[-1] = a.size
    keep = np.repeat(np.tile(np.array([False, True]), lo.size + 1)[: edges.size - 1], np.diff(edges))
    return a[keep].tobytes()

