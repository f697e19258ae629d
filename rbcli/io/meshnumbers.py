"""Whitespace-separated numbers of the mesh text formats (ASCII STL, OBJ), read with numpy.

:func:`floats` is what :mod:`rbcli.io.meshfile` calls: plain decimals such as
``-0.52573111`` (the numbers of most OBJ exporters) are read by :func:`decimals`, with
integer arithmetic on 64-bit words and one exact division each (no decimal-to-binary
library call per number); every other kind of number by :func:`numbers`
(``np.fromstring``). Both give the bits Python's ``float()`` gives (correct rounding),
which the tests check on random, halfway and adversarial strings. Any token that is
not a number makes the answer None: the caller's line reader then says where.
"""

from __future__ import annotations


import numpy as np

__all__ = ["numbers", "floats", "decimals"]

_U = np.uint64
_ZEROS = _U(0x3030303030303030)  # eight '0' bytes
_HIGH = _U(0x8080808080808080)
_ONES = _U(0x0101010101010101)
_TOP = np.array([(1 << 64) - (1 << (64 - 8 * k)) for k in range(9)], dtype=np.uint64)  # top k bytes
_P10 = 10.0 ** np.arange(16)  # exact doubles
_P10_INT = 10 ** np.arange(16, dtype=np.uint64)
_PIECE = 1 << 18  # decimals() reads about 256 KiB at a time: small temporaries, in cache


def numbers(text: bytes, dtype=np.float64) -> np.ndarray | None:
    """Whitespace-separated numbers, or None if any token is not one (no partial result).

    numpy stops at the first token it cannot read (with a DeprecationWarning, a ValueError in
    later versions): fewer numbers than tokens is that. The warning filters are left alone (a
    library call does not switch them: another thread may be reading warnings)."""
    try:
        out = np.fromstring(text, dtype=dtype, sep=" ")
    except ValueError:
        return None
    return out if out.size == len(text.split()) else None


def floats(text: bytes) -> np.ndarray | None:
    """Whitespace-separated numbers as float64, or None if a token is not one.

    Lines of plain decimals are read by :func:`decimals` in pieces of about 256 KiB
    (whole lines); if any piece holds another kind of number, the whole text is read by
    :func:`numbers`. The same bits either way.
    """
    pieces = []
    pos = 0
    while pos < len(text):
        end = pos + _PIECE
        if end < len(text):
            end = text.rfind(b"\n", pos, end) + 1
            if end <= pos:
                return numbers(text)
        got = decimals(text[pos:end])
        if got is None:
            return numbers(text)
        pieces.append(got)
        pos = end
    return np.concatenate(pieces) if len(pieces) != 1 else pieces[0]


def decimals(text: bytes) -> np.ndarray | None:
    """Whitespace-separated plain decimals, the bits ``float()`` gives, or None.

    Only tokens such as ``-12.375``, ``5.``, ``+.5`` or ``007`` (a sign, digits and at
    most one point; no exponent; 1 to 15 digits) are read; for anything else (longer,
    exponents, nan, any other byte) the answer is None and the caller uses
    :func:`numbers`.

    Each token's last 16 bytes are read as two little-endian words; the bytes before it
    and its sign are set to '0', its point is found and set to '0' with bit tricks, and
    the 16 digits are turned into an integer eight at a time. Without the point's place
    that is the integer m < 10**15 < 2**53 of the token's digits, and the value is
    m / 10**k for k fraction digits: m and 10**k are exact doubles, so the one IEEE
    division rounds the decimal value correctly (Clinger's fast path), as ``strtod``,
    ``float()`` and ``np.fromstring`` do. The sign is applied after (``-0`` is -0.0).
    """
    b = np.frombuffer(b" " * 16 + text + b" ", dtype=np.uint8)
    blank = b <= 32  # token edges; other control bytes are refused below
    edge = blank[1:] != blank[:-1]
    starts = np.flatnonzero(edge & blank[:-1]) + 1
    ends = np.flatnonzero(edge & blank[1:]) + 1  # one past each token
    del edge, blank
    if starts.size == 0:
        return np.empty(0)
    length = ends - starts
    if length.max() > 17:
        return None
    first = b[starts]
    neg = first == 45
    signed = neg | (first == 43)
    ok = b == 32  # (one temporary at a time)
    ok |= b == 46
    t = b - np.uint8(48)
    ok |= t < 10
    np.subtract(b, np.uint8(9), out=t)
    ok |= t < 5
    if b.size - int(np.count_nonzero(ok)) != int(np.count_nonzero(signed)):
        return None  # a byte other than whitespace, digits, points and leading signs
    del ok, t
    words = np.ndarray((b.size - 7,), dtype="<u8", buffer=b, strides=(1,))  # unaligned
    lo = words[ends - 8]  # the token's last 8 bytes (its last byte the word's top byte)
    hi = words[ends - 16]
    keep = length - signed  # the digits and the point, counted from the right
    for w, mask in ((lo, _TOP[np.minimum(keep, 8)]), (hi, _TOP[np.clip(keep - 8, 0, 8)])):
        w &= mask
        w |= _ZEROS & ~mask
    lo_p, hi_p = _points_in(lo), _points_in(hi)
    n_points = _marked(lo_p) + _marked(hi_p)
    if n_points.max() > 1:
        return None
    has_point = n_points.astype(bool)
    n_digits = keep - has_point
    if n_digits.min() < 1 or n_digits.max() > 15:
        return None
    frac = np.where(lo_p != 0, _marked_above(lo_p), _marked_above(hi_p) + _U(8))
    frac = np.where(has_point, frac, _U(0)).astype(np.intp)  # digits after the point
    lo ^= (lo_p >> _U(7)) * _U(0x1E)  # the point -> '0'
    hi ^= (hi_p >> _U(7)) * _U(0x1E)
    v = _eight(hi) * _U(100000000) + _eight(lo)
    if has_point.any():  # drop the point's '0': m = v // 10**(k+1) * 10**k + v % 10**k
        p = _P10_INT[frac]
        v = np.where(has_point, v // (p * _U(10)) * p + v % p, v)
    values = v.astype(np.float64) / _P10[frac]
    np.negative(values, out=values, where=neg)
    return values


def _eight(v: np.ndarray) -> np.ndarray:
    """Eight ASCII digits per little-endian word (first digit in the lowest byte) as integers."""
    v = v - _ZEROS
    v = v * _U(10) + (v >> _U(8))
    return ((v & _U(0x000000FF000000FF)) * _U(100 + (1000000 << 32))
            + ((v >> _U(16)) & _U(0x000000FF000000FF)) * _U(1 + (10000 << 32))) >> _U(32)  # fmt: skip


def _points_in(w: np.ndarray) -> np.ndarray:
    """0x80 in each byte of each word that is '.', 0 elsewhere (exact: no carries)."""
    x = w ^ _U(0x2E2E2E2E2E2E2E2E)
    low7 = _U(0x7F7F7F7F7F7F7F7F)
    return ~(((x & low7) + low7) | x | low7)


def _marked(t: np.ndarray) -> np.ndarray:
    """How many bytes of each word are marked 0x80 (the others 0): their sum, by a multiply."""
    return ((t >> _U(7)) * _ONES) >> _U(56)


def _marked_above(t: np.ndarray) -> np.ndarray:
    """For words with at most one byte marked 0x80: how many bytes are above it."""
    return _marked(~((t << _U(1)) - _U(1)) & _HIGH)
