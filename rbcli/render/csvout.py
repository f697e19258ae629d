"""The one CSV writer of rbcli's time series (``top --csv``, ``precess --csv``).

A header line (names through :func:`rbcli.render.safe.csv_text`), then one row per time,
every number Python's shortest round-trip ``repr`` (no negative zeros), written in blocks
(2-D arrays) so that millions of rows never sit in memory. Plain ``repr`` is the goal's
measure: 10^5 rows within 2x Python's csv module (bench/csv_rows.py).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Sequence

import numpy as np

from rbcli.render.safe import csv_text

#: rows evaluated and written at a time
CHUNK = 100_000


def times(duration: float, samples: int, chunk: int = CHUNK) -> Iterator[np.ndarray]:
    """``samples`` evenly spaced times from 0 to ``duration`` inclusive (s), in chunks."""
    t_all = np.linspace(0.0, float(duration), int(samples))
    for i in range(0, t_all.size, chunk):
        yield t_all[i:i + chunk]


def rows_text(block: np.ndarray) -> str:
    """The CSV lines of a (rows, columns) block, each ending in a newline (see the module)."""
    a = np.asarray(block, dtype=float) + 0.0  # + 0.0: no negative zeros
    if a.ndim != 2:
        raise ValueError(f"a CSV block is 2-D (rows, columns), not {a.shape}")
    fmt = ",".join(["%r"] * a.shape[1]) + "\n"
    return "".join([fmt % row for row in map(tuple, a.tolist())])


def write(sink: Callable[[str], object], header: Sequence[str], blocks: Iterable[np.ndarray]) -> int:
    """Write the header and the blocks through ``sink`` (e.g. ``fh.write``); the rows written.

    A sink that returns ``False`` (a closed pipe) stops the writing early.
    """
    if sink(",".join(csv_text(h) for h in header) + "\n") is False:
        return 0
    n = 0
    for block in blocks:
        n += len(block)
        if sink(rows_text(block)) is False:
            break
    return n
