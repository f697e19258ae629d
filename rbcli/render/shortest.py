"""Python's ``repr`` of many floats at once: shortest round-trip decimals, vectorised.

Why: ``--csv`` writes ~10^6 numbers, each as ``repr(float)`` (the shortest decimal that
reads back to the same double, David Gay's dtoa mode 0). CPython spends ~0.5 µs a number
on that, whatever the Python around it; here the same text is computed for whole numpy
arrays at once (~0.2 µs a number, most of it numpy's passes over the arrays), byte for
byte.

Algorithm: Schubfach (Raffaello Giulietti, "The Schubfach way to render doubles", 2020;
the reference is OpenJDK's ``jdk.internal.math.DoubleToDecimal``, used by
``Double.toString`` since Java 19), followed literally for normal doubles: with
``v = c 2^q``, ``k = floor(log10 2^q)`` (``floor(log10 (3/4) 2^q)`` at a power of two,
whose rounding interval is asymmetric), the scaled value and the interval bounds are
``rop(g, c 2^h)``, a rounded-to-odd product with the 126-bit ``g ~ 10^-k``; among the
decimals of the rounding interval (its bounds included when ``c`` is even) the shortest,
and among those the closest to ``v`` (a tie to the even digit); Java's shortcut for
integers is left out (the general path gives the same digits). The 64 x 64 -> 128-bit
products are done on uint64 arrays split in 32-bit limbs. The table of ``g`` is built with
Python ints on first use (cached), never at import.

Then ``repr``'s layout (``float_repr_style = 'short'``): positional when the decimal
exponent ``x`` is ``-4 <= x < 16`` (``'1000.0'``, ``'0.0001'``), else ``'d.ddde+XX'``
(``'1e-05'``, ``'1.5e+16'``; two exponent digits at least, sign always). Each number
becomes a 32-byte field (sign, ``"0.000"`` prefix, up to 17 digits with the point, the
exponent, the separator) made by shifts of 64-bit words holding 8 ASCII bytes each, the
unused bytes NUL; ``bytes.translate`` deletes the NULs and the block is decoded once.

Zero is ``'0.0'``; NaN, infinities and subnormal numbers are not done here: their rows go
through ``repr`` (:func:`csv_text`). tests/test_render_shortest.py checks the text against
``repr`` (random bit patterns, powers of two and ten and their neighbours, the layout
boundaries, hypothesis).
"""

from __future__ import annotations

import functools
import sys

import numpy as np

#: numbers formatted per pass (whole rows): the arrays of one pass stay in cache
CHUNK_NUMBERS = 1 << 14
#: below this many numbers ``repr`` is quicker (each pass costs ~0.25 ms of numpy calls)
SMALL = 1000

_U = np.uint64
_M32 = _U(0xFFFFFFFF)
_M63 = _U((1 << 63) - 1)
_K_MIN, _K_MAX = -324, 292
_ASCII0 = _U(0x3030303030303030)
_HIGHBITS = _U(0x8080808080808080)
_LOW7 = _U(0x7F7F7F7F7F7F7F7F)
_ALL = _U(2**64 - 1)
_DOT = _U(0x2E)
_PREFIX = _U(int.from_bytes(b"0.000", "little"))


def _flog10pow2(e):
    """floor(e log10 2), exact for |e| <= 5456721 (Schubfach's MathUtils)."""
    return (e * 661_971_961_083) >> 41


def _flog10three_quarters_pow2(e):
    """floor(log10(3/4 2^e))."""
    return (e * 661_971_961_083 - 274_743_187_321) >> 41


def _flog2pow10(e):
    """floor(e log2 10)."""
    return (e * 913_124_641_741) >> 38


@functools.cache
def _tables() -> dict[str, np.ndarray]:
    """Schubfach's g = floor(10^-k 2^-r) + 1 (2^125 <= g < 2^126) for every k, as 32-bit
    limbs of g1 = g >> 63 and g0 = g mod 2^63; and the exponents' text."""
    g1, g0 = [], []
    for k in range(_K_MIN, _K_MAX + 1):
        r = _flog2pow10(-k) - 125
        if k <= 0:
            num = 10 ** -k
            beta = num >> r if r >= 0 else num << -r
        else:
            beta = (1 << -r) // 10 ** k
        g = beta + 1
        assert 1 << 125 <= g < 1 << 126
        g1.append(g >> 63)
        g0.append(g & ((1 << 63) - 1))
    t = {}
    for name, vals in (("g1", g1), ("g0", g0)):
        a = np.array(vals, dtype=np.uint64)
        t[name] = a
        t[name + "_lo"] = a & _M32
        t[name + "_hi"] = a >> _U(32)
    # exponent text "e+XX" / "e-XXX" for x = -400..400 (index x + 400)
    t["exp"] = np.array([int.from_bytes(f"e{x:+03d}".encode(), "little") for x in range(-400, 401)],
                        dtype=np.uint64)
    return t


def _mulhi(a_lo, a_hi, b_lo, b_hi):
    """High 64 bits of the 128-bit products a b (uint64 arrays given as 32-bit limbs)."""
    p00 = a_lo * b_lo
    p01 = a_lo * b_hi
    p10 = a_hi * b_lo
    hi = a_hi * b_hi
    mid = p00 >> _U(32)
    mid += p01 & _M32
    mid += p10 & _M32
    p01 >>= _U(32)
    p10 >>= _U(32)
    mid >>= _U(32)
    hi += p01
    hi += p10
    hi += mid
    return hi


def _rop(g1, g1_lo, g1_hi, g0_lo, g0_hi, cp):
    """Schubfach's rop(g, cp): g cp / 2^127 rounded to odd (its last bit set when inexact)."""
    cp_lo = cp & _M32
    cp_hi = cp >> _U(32)
    x1 = _mulhi(g0_lo, g0_hi, cp_lo, cp_hi)
    y0 = g1 * cp
    y1 = _mulhi(g1_lo, g1_hi, cp_lo, cp_hi)
    y0 >>= _U(1)
    y0 += x1  # z
    y1 += y0 >> _U(63)
    y0 &= _M63
    y1 |= (y0 != 0).astype(np.uint64)
    return y1


def _shortest(bits: np.ndarray):
    """(f, k) with the shortest closest decimal f 10^k (17 digits: 10^16 <= f < 10^17) of
    each normal double whose bits are given (sign ignored)."""
    t = _tables()
    frac = bits & _U((1 << 52) - 1)
    bq = ((bits >> _U(52)) & _U(0x7FF)).astype(np.int64)
    q = bq - 1075
    c = frac | _U(1 << 52)
    irregular = (frac == 0) & (bq > 1)  # c = 2^52, q > Q_MIN: the gap below is half the one above
    k = np.where(irregular, _flog10three_quarters_pow2(q), _flog10pow2(q))
    h = (q + _flog2pow10(-k) + 2).astype(np.uint64)
    i = k - _K_MIN
    g1, g1_lo, g1_hi = t["g1"][i], t["g1_lo"][i], t["g1_hi"][i]
    g0_lo, g0_hi = t["g0_lo"][i], t["g0_hi"][i]
    cb = c << _U(2)
    vb = _rop(g1, g1_lo, g1_hi, g0_lo, g0_hi, cb << h)
    vbl = _rop(g1, g1_lo, g1_hi, g0_lo, g0_hi, (cb - _U(2) + irregular.astype(np.uint64)) << h)
    vbr = _rop(g1, g1_lo, g1_hi, g0_lo, g0_hi, (cb + _U(2)) << h)
    out = c & _U(1)  # an odd significand: the bounds are not in the interval
    vbl += out
    vbr -= out
    s = vb >> _U(2)
    sp10 = (s // _U(10)) * _U(10)
    tp10 = sp10 + _U(10)
    upin = vbl <= (sp10 << _U(2))
    wpin = (tp10 << _U(2)) <= vbr
    s1 = s + _U(1)
    uin = vbl <= (s << _U(2))
    win = (s1 << _U(2)) <= vbr
    cmp = vb.view(np.int64) - ((s + s1) << _U(1)).view(np.int64)
    closer_s = (cmp < 0) | ((cmp == 0) & ((s & _U(1)) == 0))
    pick_s = np.where(uin != win, uin, closer_s)
    f = np.where(upin != wpin, np.where(upin, sp10, tp10), np.where(pick_s, s, s1))
    short = f < _U(10 ** 16)
    f = np.where(short, f * _U(10), f)
    return f, k - short


def _digits8(m):
    """The 8 decimal digits of each m < 10^8 (leading zeros kept) as the bytes of a uint64,
    most significant first (little-endian), values 0-9."""
    hi = m // _U(10_000)
    v = hi | ((m - hi * _U(10_000)) << _U(32))
    hi = ((v * _U(5243)) >> _U(19)) & _U(0x0000007F0000007F)  # x // 100 for x < 10^4
    v = hi | ((v - hi * _U(100)) << _U(16))
    hi = ((v * _U(103)) >> _U(10)) & _U(0x000F000F000F000F)  # x // 10 for x < 100
    return hi | ((v - hi * _U(10)) << _U(8))


def _top_byte(x):
    """Index of the highest nonzero byte of each x whose only set bits are bytes' bit 7."""
    return ((x.astype(np.float64).view(np.uint64) >> _U(52)).astype(np.int64) - (1023 + 7)) >> 3


def _fields(x: np.ndarray, sep: np.ndarray) -> np.ndarray:
    """(n, 4) uint64: each float of ``x`` (normal or zero) as its repr in
    up to 32 NUL-padded bytes, followed by its separator byte ``sep``."""
    t = _tables()
    bits = x.view(np.uint64)
    neg = bits >> _U(63)
    zero = (bits << _U(1)) == 0
    f, k = _shortest(np.where(zero, _U(0x3FF0000000000000), bits))
    f[zero] = 0
    top = f // _U(10 ** 16)
    r = f - top * _U(10 ** 16)
    mid = r // _U(10 ** 8)
    dm = _digits8(mid)
    dl = _digits8(r - mid * _U(10 ** 8))
    w0 = top | (dm << _U(8))
    w1 = (dm >> _U(56)) | (dl << _U(8))
    w2 = dl >> _U(56)
    # n: significant digits (trailing zeros dropped; 1 for zero)
    nz0 = (w0 + _LOW7) & _HIGHBITS
    nz1 = (w1 + _LOW7) & _HIGHBITS
    n = np.where(w2 != 0, 17, np.where(nz1 != 0, 9 + _top_byte(nz1 | _U(0x80)),
                                       1 + _top_byte(nz0 | _U(0x80))))
    decpt = np.where(zero, 1, k + 17)  # the point is after `decpt` digits
    positional = (decpt >= -3) & (decpt <= 16)
    intpart = positional & (decpt >= 1)
    keep = np.where(intpart, np.maximum(n, decpt + 1), n)
    p = np.where(intpart, decpt, np.where(~positional & (n > 1), 1, 99))  # the point's byte
    # Byte masks as shifts of all-ones words (numpy: a shift by >= 64 gives 0).
    o = []
    carry = _U(0)
    for j, w in enumerate((w0, w1, w2)):
        w += _ASCII0
        w &= _ALL >> np.maximum(64 * (j + 1) - 8 * keep, 0).astype(np.uint64)  # digits kept
        at = 8 * p - 64 * j  # the point's bit position in this word
        hi = w & (_ALL << np.maximum(at, 0).astype(np.uint64))  # digits after the point
        w ^= hi
        w |= (hi << _U(8)) | (_DOT << at.astype(np.uint64)) | carry  # at < 0 wraps: no dot
        o.append(w)
        carry = hi >> _U(56)
    plen = np.where(positional & (decpt <= 0), 2 - decpt, 0)
    prefix = _PREFIX & ~(_ALL << (8 * plen).astype(np.uint64))
    res = np.empty((x.size, 4), dtype=np.uint64)
    res[:, 0] = (neg * _U(0x2D)) | (prefix << _U(8)) | (o[0] << _U(48))
    res[:, 1] = (o[0] >> _U(16)) | (o[1] << _U(48))
    res[:, 2] = (o[1] >> _U(16)) | (o[2] << _U(48))
    expo = t["exp"][np.clip(decpt + 399, 0, 800)]
    res[:, 3] = np.where(positional, _U(0), expo) | sep
    return res


def csv_text(a: np.ndarray, small: int = SMALL) -> str:
    """The CSV lines of a 2-D float64 array: each row's ``repr`` of its numbers joined by
    ``,``, each line ending in a newline; the same text as
    ``"".join(",".join(map(repr, row)) + "\\n" for row in a.tolist())``.

    Arrays of fewer than ``small`` numbers (and any on a big-endian machine: the fields
    are built as little-endian words) are formatted by ``repr`` itself.
    """
    rows, cols = a.shape
    if a.size == 0:
        return "\n" * rows
    if a.size < small or sys.byteorder != "little":
        line = ",".join(["%r"] * cols) + "\n"  # %r is repr
        return (line * rows) % tuple(a.ravel().tolist())
    seprow = np.full(cols, 0x2C << 40, dtype=np.uint64)
    seprow[-1] = 0x0A << 40
    step = max(1, CHUNK_NUMBERS // cols)
    seps = np.tile(seprow, min(step, rows))
    flat = np.ascontiguousarray(a, dtype=np.float64).ravel()
    out = []
    for r0 in range(0, rows, step):
        x = flat[r0 * cols:min(rows, r0 + step) * cols]
        bq = (x.view(np.uint64) >> _U(52)) & _U(0x7FF)
        odd = ((bq == 0) & (x != 0.0)) | (bq == 0x7FF)  # subnormal, inf, nan: repr
        if odd.any():
            x = np.where(odd, 1.0, x)
        text = _fields(x, seps[:x.size]).tobytes().translate(None, b"\0")
        if odd.any():
            lines = text.split(b"\n")
            orig = flat[r0 * cols:r0 * cols + x.size].reshape(-1, cols)
            for i in np.flatnonzero(odd.reshape(-1, cols).any(axis=1)):
                lines[i] = ",".join(map(repr, orig[i].tolist())).encode()
            text = b"\n".join(lines)
        out.append(text)
    return b"".join(out).decode("ascii")
