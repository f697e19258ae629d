"""render/csvout: every number is its shortest round-trip repr, no negative zeros, row by row."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from rbcli.render.csvout import rows_text, write


def reference(block) -> str:
    """The formatter as it was: repr of every float, row by row, no negative zeros."""
    rows = (np.asarray(block, dtype=float) + 0.0).tolist()
    return "".join(",".join(map(repr, row)) + "\n" for row in rows)


EDGES = [0.0, -0.0, 1.0, -1.0, 3.0, 0.1, 1e-300, -1e-300, 5e-324, 2.2250738585072014e-308,
         1e16, 1e15, 9999999999999998.0, 1.7976931348623157e308, -1.7976931348623157e308,
         1e-5, 1e-4, 0.0001234, 123456789012345678.0, 1 / 3, math.pi, -math.e, 2.0**53, 2.0**-1074,
         math.inf, -math.inf, math.nan]


def test_edge_values_byte_identical():
    block = np.array(EDGES * 11).reshape(-1, 11)
    assert rows_text(block) == reference(block)
    assert "-0.0" not in rows_text(block)


@pytest.mark.parametrize("seed", range(5))
def test_random_values_byte_identical(seed):
    rng = np.random.default_rng(seed)
    block = rng.standard_normal((2000, 11)) * 10.0 ** rng.uniform(-320, 308, (2000, 11))
    block[rng.random(block.shape) < 0.05] = -0.0
    block[:, 0] = np.linspace(0.0, 7.3, 2000)  # a time column: short and long reprs
    assert rows_text(block) == reference(block)


@pytest.mark.parametrize("shape", [(0, 11), (1, 11), (3, 1), (5, 4)])
def test_shapes(shape):
    block = np.arange(np.prod(shape), dtype=float).reshape(shape) - 2.0
    assert rows_text(block) == reference(block)


def test_write_stops_at_a_closed_sink():
    out: list[str] = []

    def sink(text: str) -> bool:
        out.append(text)
        return len(out) < 2

    n = write(sink, ("a", "b"), [np.ones((3, 2)), np.zeros((2, 2))])
    assert out[0] == "a,b\n" and out[1] == "1.0,1.0\n" * 3 and n == 3


@pytest.mark.parametrize("case", ["top/csv", "precess/football-csv"])
def test_golden_csv_rows_read_back_exactly(case):
    """Each number of a golden CSV reads back to a float whose repr is the cell itself."""
    text = (Path(__file__).parent / "cases" / f"{case}.out").read_text()
    header, body = text.split("\n", 1)
    rows = np.array([[float(v) for v in line.split(",")] for line in body.splitlines()])
    assert len(rows) > 1 and rows_text(rows) == body
