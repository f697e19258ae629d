"""rbcli._startup.LazyRe is re.compile, compiled on first use."""

from __future__ import annotations

import re

from rbcli._startup import LazyRe


def test_lazy_pattern_is_the_compiled_one():
    lazy, plain = LazyRe(r"\s*([0-9]+)\s*(mm)?", re.I), re.compile(r"\s*([0-9]+)\s*(mm)?", re.I)
    assert "match" not in vars(lazy)  # not compiled yet
    for text in ["12 mm", " 7", "x", "99MM"]:
        a, b = lazy.fullmatch(text), plain.fullmatch(text)
        assert (a and a.groups()) == (b and b.groups())
    assert "match" in vars(lazy) and lazy.sub("n", "3 mm, 4") == plain.sub("n", "3 mm, 4")
    assert lazy.pattern == plain.pattern and lazy.flags == plain.flags
