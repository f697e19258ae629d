"""render/shortest: the vectorised shortest round-trip text is Python's repr, byte for byte.

Every test compares with ``",".join(map(repr, row))`` per row (``reference``), through
``fast``: ``shortest.csv_text`` with its small-array shortcut to ``repr`` turned off. The
10^8 random bit patterns are marked slow.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import sample
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

from rbcli.render import shortest
from rbcli.render.csvout import rows_text

TINY = 2.2250738585072014e-308  # smallest normal
HUGE = 1.7976931348623157e308  # largest finite


def fast(block) -> str:
    return shortest.csv_text(np.asarray(block, dtype=np.float64), small=0)


def reference(block) -> str:
    rows = np.asarray(block, dtype=float).tolist()
    return "".join(",".join(map(repr, row)) + "\n" for row in rows)


def check(values, cols: int = 7) -> None:
    """fast equals reference on ``values`` and on their negatives, laid out in rows of
    ``cols`` (the tail padded with 1.0); on a mismatch, name the first differing number."""
    x = np.asarray(values, dtype=np.float64).ravel()
    x = np.concatenate([x, -x, np.ones(-(2 * x.size) % cols)]).reshape(-1, cols)
    got, want = fast(x), reference(x)
    if got != want:
        for a, b in zip(got.replace("\n", ",").split(","), want.replace("\n", ",").split(",")):
            assert a == b, f"fast {a!r} != repr {b!r}"
        assert got == want


def neighbours(x, steps: int = 3) -> np.ndarray:
    """x and its ``steps`` nearest doubles on either side (finite ones)."""
    x = np.asarray(x, dtype=np.float64)
    out, lo, hi = [x], x, x
    for _ in range(steps):
        with np.errstate(over="ignore"):  # beyond the largest double: inf, dropped below
            lo, hi = np.nextafter(lo, -np.inf), np.nextafter(hi, np.inf)
        out += [lo, hi]
    out = np.concatenate(out)
    return out[np.isfinite(out)]


def random_finite(rng, n: int) -> np.ndarray:
    bits = rng.integers(0, 2**64, n, dtype=np.uint64, endpoint=False)
    x = bits.view(np.float64)
    return x[np.isfinite(x)]


def test_examples():
    assert fast(np.array([[1.0, 0.5, 123.456, 1e-5, 1e16, -0.0, -2.5, 1000.0, 0.0001,
                                1.5e16, math.pi]]) + 0.0) == \
        "1.0,0.5,123.456,1e-05,1e+16,0.0,-2.5,1000.0,0.0001,1.5e+16,3.141592653589793\n"


@pytest.mark.sampled
def test_random_bit_patterns():
    rng = np.random.default_rng(16)
    check(random_finite(rng, sample(100_000, 1_000_000)), cols=11)


@pytest.mark.slow
def test_random_bit_patterns_1e8():
    rng = np.random.default_rng(1016)
    for _ in range(100):
        check(random_finite(rng, 1_000_000), cols=11)


def test_powers_of_two_and_ten_and_their_neighbours():
    twos = np.ldexp(1.0, np.arange(-1074, 1024))
    tens = np.array([float(f"1e{e}") for e in range(-323, 309)])
    check(neighbours(np.concatenate([twos, tens])))


def test_integers_and_short_decimals():
    ints = np.concatenate([np.arange(0, 20_000), 2.0**53 + np.arange(-3000, 3000),
                           2.0**52 + np.arange(-3000, 3000), 10.0**15 + np.arange(-500, 500),
                           10.0**16 + 2 * np.arange(-500, 500),
                           10.0**17 + 16 * np.arange(-500, 500)])
    decimals = np.arange(0, 100_000) / 1000.0  # 0.001, 0.002, ...: short reprs, some 17 digits
    check(np.concatenate([ints, decimals, np.linspace(0.0, 1000.0, 100_001)]))


def test_layout_boundaries():
    edges = [1e-5, 1e-4, 1e-3, 1e15, 1e16, 1e17, 9.999999999999999e-05, 9.99999999999999e-06,
             9999999999999998.0, 999999999999999.9, 1.5e16, 0.5e-4, 123456789012345678.0]
    check(neighbours(np.array(edges), steps=20))
    # every number of significant digits at every decimal exponent near the layout change
    digits = np.array([int("123456789012345678"[:n]) for n in range(1, 18)], dtype=np.float64)
    check(np.concatenate([digits * 10.0**e for e in range(-25, 25)]))


def test_extremes_zero_and_subnormals():
    sub = np.concatenate([np.ldexp(1.0, np.arange(-1074, -1022)), 5e-324 * np.arange(1, 3000),
                          np.nextafter(TINY, 0) - 5e-324 * np.arange(3000)])
    check(np.concatenate([[0.0, -0.0, TINY, HUGE, 5e-324], neighbours([TINY, HUGE, 5e-324]), sub]))
    assert fast(np.array([[-0.0, 0.0]])) == "-0.0,0.0\n"  # repr itself; the CSV has no -0.0:
    assert rows_text(np.array([[-0.0, 0.0]] * 1000)) == "0.0,0.0\n" * 1000


def test_nan_and_infinities_among_fast_rows():
    x = np.full((9, 5), 0.1)
    x[2, 3], x[4, 0], x[8, 4] = math.nan, math.inf, -math.inf
    x[6, 1] = 1e-310
    assert fast(x) == reference(x)


@pytest.mark.sampled
def test_few_significant_bits():
    """v = m 2^e with a small odd m: decimal ties between the two candidate digits happen here
    (every 7th binary exponent in full; every 29th, the extremes included, by default)."""
    m = np.arange(1, 4096, 2, dtype=np.float64)
    check(np.concatenate([np.ldexp(m, e) for e in [*range(-1074, 1012, sample(29, 7)), 1011]]))


@pytest.mark.parametrize("shape", [(0, 11), (1, 1), (1, 11), (3, 1), (5000, 1), (4001, 4),
                                   (1, 40000)])
def test_shapes_and_chunks(shape):
    rng = np.random.default_rng(sum(shape))
    x = rng.standard_normal(shape) * 10.0 ** rng.integers(-30, 30, shape)
    assert fast(x) == reference(x)
    assert shortest.csv_text(x) == reference(x)  # small ones through repr


@pytest.mark.sampled
@settings(max_examples=sample(60, 300), deadline=None)  # deadline None: the first call builds the tables
@given(hnp.arrays(np.float64, hnp.array_shapes(min_dims=2, max_dims=2, max_side=12),
                  elements=st.floats(allow_nan=False, allow_infinity=False)))
def test_hypothesis_finite(x):
    assert fast(x) == reference(x)


@pytest.mark.sampled
@settings(max_examples=sample(40, 200), deadline=None)
@given(hnp.arrays(np.float64, hnp.array_shapes(min_dims=2, max_dims=2, max_side=12),
                  elements=st.floats()))
def test_hypothesis_any(x):
    assert fast(x) == reference(x)


def test_digit_groups():
    """The SWAR split of m < 10^8 into 8 digits: every 4-digit lane value, both lanes."""
    four = np.arange(10_000, dtype=np.uint64)
    m = four * np.uint64(10_000) + four[::-1]
    got = shortest._digits8(m)
    want = [int.from_bytes(bytes(int(d) for d in f"{v:08d}"), "little") for v in m.tolist()]
    want = np.array(want, dtype=np.uint64)
    assert np.array_equal(got, want)


def test_power_table():
    """g of every k brackets 10^-k as Schubfach requires: (g - 1) 2^r <= 10^-k < g 2^r."""
    t = shortest._tables()
    for i, k in enumerate(range(shortest._K_MIN, shortest._K_MAX + 1)):
        g = (int(t["g1"][i]) << 63) + int(t["g0"][i])
        r = shortest._flog2pow10(-k) - 125
        # compare 10^-k with g 2^r as exact integers: scale both by 10^max(k,0) 2^max(-r,0)
        lhs = 10 ** max(-k, 0) * 2 ** max(-r, 0)
        scale = 10 ** max(k, 0) * 2 ** max(r, 0)
        assert (g - 1) * scale <= lhs < g * scale, k
