"""The text readers' number parser (rbcli.io.meshbase.numbers) and text grouping (meshfile).

The decimal parser the readers use (``np.fromstring`` through ``numbers``) is checked
against Python's ``float()``, bit for bit, on random and adversarial decimal strings. The grouping of
equal ``vertex`` texts in an ASCII STL (``distinct_spans``) is checked to be exact, even
when every hash collides, and the reader that uses it against the token-by-token reader
and against welding every corner.
"""

from __future__ import annotations

import random
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import rbcli.io.meshstl as ms
import rbcli.io.meshweld as mw
from rbcli.io.meshfile import read_mesh
from rbcli.io.meshbase import numbers
from rbcli.io.meshweld import distinct_spans

# ------------------------------------------------------------------ strings to parse


def plain_decimals(rng: random.Random, n: int) -> list[bytes]:
    """Plain decimals: a sign or not, 1-15 digits, a point anywhere or none."""
    out = []
    for _ in range(n):
        nd = rng.randint(1, 15)
        digits = "".join(rng.choice("0123456789") for _ in range(nd))
        if rng.random() < 0.3:
            digits = "0" * rng.randint(0, nd - 1) + digits[: nd - 1]  # leading zeros
            digits = digits[-nd:] or "0"
        p = rng.randint(0, len(digits))
        s = digits[:p] + "." + digits[p:] if rng.random() < 0.85 else digits
        out.append((rng.choice(["", "-", "+"]) + s).encode())
    return out


def halfway_strings(rng: random.Random, n: int) -> list[bytes]:
    """Decimals at, just below and just above the midpoint of two adjacent doubles.

    Correct rounding is decided by the last digit here (ties go to the even double).
    """
    out = []
    for _ in range(n):
        x = abs(rng.choice([rng.uniform(0, 1), rng.uniform(0, 1e6), 10 ** rng.uniform(-300, 300)]))
        mid = (Fraction(x) + Fraction(np.nextafter(x, np.inf))) / 2
        exact = Decimal(mid.numerator) / Decimal(mid.denominator)  # exact (a power-of-2 denominator)
        for digits in (17, 18, 20, 25, 40):
            out.append(f"{exact:.{digits}e}".encode())
        out.append(repr(x).encode())
        out.append(f"{x:.17g}".encode())
    return out


ADVERSARIAL = [
    b"0", b"-0", b"+0", b"-0.0", b"0.", b".0", b"+.5", b"-.5", b"5.", b"007", b"-007.700",
    b"1e400", b"-1e400", b"1e-400", b"4.9e-324", b"2.4703282292062327e-324",
    b"2.4703282292062328e-324", b"2.2250738585072011e-308", b"2.2250738585072012e-308",
    b"1.7976931348623157e308", b"1.7976931348623158e308", b"1.7976931348623159e308",
    b"9007199254740993", b"9007199254740992.5", b"0.1", b"0.30000000000000004",
    b"123456789012345", b"1234567890123456", b"12345678901234567890", b"999999999999999.9",
    b"0.000000000000001", b".000000000000001", b"1e0010", b"1E5", b"1e+5", b"1e-5",
    b"nan", b"-nan", b"NaN", b"inf", b"-inf", b"infinity", b"Infinity", b"nan(12)",
    b"0x10", b"0x1p3", b"1_0", b"1,5", b"1d5", b".", b"-", b"+", b"-.", b"+-1", b"--1",
    b"1-2", b"1.2.3", b"1..", b"1e", b"1e+", b".e1", b"e5", b"\xa01", b"1\x00", b"\x012",
    b"\x80", b"\xff" * 9,
]  # fmt: skip


def float_or_none(t: bytes):
    try:
        return float(t)
    except ValueError:
        return None


def same_bits(a, b) -> bool:
    return np.asarray(a, np.float64).view(np.uint64).tolist() == np.asarray(b, np.float64).view(np.uint64).tolist()


# ------------------------------------------------------------ parsers against float()


def test_numbers_read_plain_decimals_as_float_does():
    rng = random.Random(5)
    for _ in range(40):
        tokens = plain_decimals(rng, 2000)
        seps = [rng.choice([b" ", b"\t", b"\n", b"\r\n", b"  ", b"\x0b", b"\x0c"]) for _ in tokens]
        text = b"".join(t + s for t, s in zip(tokens, seps))
        assert same_bits(numbers(text), [float(t) for t in tokens])


@pytest.mark.parametrize("token", ADVERSARIAL)
def test_numbers_agree_with_float_or_refuse(token):
    want = float_or_none(token)
    got = numbers(token + b"\n")
    if got is None:
        return  # refused: the readers fall back to the line reader (float())
    assert got.size == 1, token
    if np.isfinite(got[0]):  # non-finite numbers are refused by the readers themselves
        assert want is not None and same_bits(got, [want]), token


def test_numbers_agree_with_float_at_halfway_points():
    rng = random.Random(11)
    tokens = halfway_strings(rng, 300) + ADVERSARIAL[:40]
    tokens = [t for t in tokens if float_or_none(t) is not None and np.isfinite(float(t))]
    assert same_bits(numbers(b" ".join(tokens)), [float(t) for t in tokens])
    assert numbers(b"1 2 x\n") is None


# ------------------------------------------------------------ grouping equal texts


def spans_of(strings: list[bytes]):
    text = b"".join(s + b"\n" for s in strings)
    lo = np.cumsum([0] + [len(s) + 1 for s in strings[:-1]])
    return np.frombuffer(text, np.uint8), lo, lo + [len(s) for s in strings]


def check_groups(strings, first, inverse):
    assert (np.diff(first) > 0).all()  # in file order
    for i, s in enumerate(strings):
        assert strings[first[inverse[i]]] == s
    assert first[0] == 0 and (inverse[first] == np.arange(first.size)).all()


@pytest.mark.parametrize("collide", [False, True])
def test_distinct_spans_group_exactly_equal_strings(monkeypatch, collide):
    if collide:  # every hash the same: only the word-by-word comparison separates them
        monkeypatch.setattr(mw, "_MIX", (np.uint64(0),) * 2)
    rng = random.Random(4)
    pool = [bytes(rng.choice(b"01.-e \x00") for _ in range(rng.randint(1, 40))) for _ in range(60)]
    pool += [b"1 2 3", b"1 2 3\x00", b"1 2 3\x00\x00", b"x" * 8, b"x" * 9, b"x" * 16, b"x" * 17]
    strings = [rng.choice(pool) for _ in range(3000)]
    a, lo, hi = spans_of(strings)
    first, inverse = distinct_spans(a, lo, hi)
    check_groups(strings, first, inverse)
    if not collide:
        assert first.size == len(set(strings))


def test_distinct_spans_leave_long_strings_apart():
    strings = [b"7" * 200, b"7" * 200, b"1 2 3"]  # over 128 bytes: no grouping at all
    a, lo, hi = spans_of(strings)
    first, inverse = distinct_spans(a, lo, hi)
    assert first.tolist() == [0, 1, 2] and inverse.tolist() == [0, 1, 2]


# ------------------------------------------------------------ the ASCII STL reader


def write_spelled_stl(path, rng):
    """An ASCII STL of a closed octahedron whose corners are spelled in many ways."""
    v = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], float)
    v = v * 0.37 + [0.1, 0.25, -0.5]
    f = [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]]

    def spell(x):
        return rng.choice([repr(x), f"{x:.17g}", f"{x:.25f}", f"{x:.20e}", f"{x:+.17g}",
                           f"{x!r}".ljust(20, "0") if "." in repr(x) and "e" not in repr(x) else repr(x),
                           f"{x:.17g}".replace("0.", "0000.", 1) if abs(x) < 1 else repr(x),
                           repr(x) + "0" * 120])  # fmt: skip

    out = ["solid spelled"]
    for tri in f:
        out.append("facet normal 0 0 0\nouter loop")
        for i in tri:
            sep = rng.choice([" ", "\t", "   "])
            out.append("vertex " + sep.join(spell(float(c)) for c in v[i]))
        out.append("endloop\nendfacet")
    out.append("endsolid spelled\n")
    path.write_text("\n".join(out))
    return v


@pytest.mark.parametrize("collide", [False, True])
def test_ascii_stl_with_spellings_reads_as_the_line_reader_and_welds_every_corner(
    tmp_path, monkeypatch, collide
):
    monkeypatch.setattr(ms, "_CHUNK", 300)  # many blocks: texts repeat across blocks
    if collide:
        monkeypatch.setattr(mw, "_MIX", (np.uint64(0),) * 2)
    rng = random.Random(9)
    for k in range(5):
        path = tmp_path / f"s{k}.stl"
        v = write_spelled_stl(path, rng)
        data = path.read_bytes()
        with open(path, "rb") as fh:
            points, inverse = ms._read_stl_ascii_fast(fh, len(data))
        corners = ms._read_stl_ascii(str(path), data)
        assert same_bits(points[inverse].ravel(), corners.ravel())
        got = read_mesh(path)
        assert len(got.vertices) == 6  # every spelling of a corner welded into one
        assert np.allclose(np.sort(got.vertices, axis=0), np.sort(v, axis=0), rtol=0, atol=1e-15)  # repr round-trips
        # the weld of all 3F corners, in the same order: the same arrays
        unique, inv = mw.weld_points(corners + 0.0)
        assert same_bits(got.vertices.ravel(), unique.ravel())
        assert got.faces.tolist() == inv.reshape(-1, 3).tolist()


def test_weld_span_gives_the_order_of_the_larger_array(monkeypatch):
    rng = np.random.default_rng(6)
    base = rng.normal(size=(300, 3))
    pts = base[rng.integers(0, 300, 5000)]
    for mix in (None, (np.uint64(0),) * 2):  # with and without every hash colliding
        if mix is not None:
            monkeypatch.setattr(mw, "_MIX", mix)
        u_all, _ = mw.weld_points(pts + 0.0)
        u_few, _ = mw.weld_points(np.unique(pts, axis=0)[::-1].copy(), span=len(pts))
        assert same_bits(u_all.ravel(), u_few.ravel())


@pytest.mark.parametrize("collide", [False, True])
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_weld_in_blocks_is_the_weld_of_the_whole_array(monkeypatch, collide, dtype):
    monkeypatch.setattr(mw, "_WELD_BLOCK", 64)  # many blocks, and points repeated across them
    if collide:
        monkeypatch.setattr(mw, "_MIX", (np.uint64(0),) * 2)
    rng = np.random.default_rng(12)
    base = rng.normal(size=(700, 3)).astype(dtype)
    pts = base[rng.integers(0, 700, 9000)] + dtype(0)
    whole_u, whole_inv = mw.weld_points(pts.copy())
    for span in (0, 50000):
        u, inv = mw.weld_blocks(pts.copy(), span)
        ref_u, ref_inv = mw.weld_points(pts.copy(), span)
        assert same_bits(u.ravel(), ref_u.ravel()) and inv.tolist() == ref_inv.tolist()
    u, inv = mw.weld(pts)
    assert u.dtype == np.float64 and same_bits(u.ravel(), whole_u.ravel())
    assert inv.tolist() == whole_inv.tolist()


def test_binary_stl_is_the_weld_of_every_corner(tmp_path, monkeypatch):
    import trimesh

    monkeypatch.setattr(mw, "_WELD_BLOCK", 100)
    path = tmp_path / "s.stl"
    trimesh.creation.icosphere(subdivisions=3).export(path)
    got = read_mesh(path)
    rec = np.fromfile(path, dtype=ms._STL_RECORD, offset=84)
    corners = np.ascontiguousarray(rec["v"].reshape(-1, 3)) + np.float32(0)
    u, inv = mw.weld_points(corners)
    assert same_bits(got.vertices.ravel(), u.ravel())
    assert got.faces.tolist() == inv.reshape(-1, 3).tolist()
