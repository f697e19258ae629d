"""rbcli.render.text lays out plain tables itself, byte for byte as rich would.

The oracle is rich (``_rich_printer``, the renderer used on colour terminals and for
whatever the plain layout declines): on generated headings, notes and tables (ASCII, the
non-ASCII symbols rbcli prints, wide and combining characters, empty cells, titles longer
than the table, widths from 20 to 120) the document rendered by :meth:`Doc.render` equals
rich's rendering of every item, exactly.
"""

from __future__ import annotations

import io

import pytest

from conftest import sample
from hypothesis import given, settings
from hypothesis import strategies as st

from rbcli.env import Env
from rbcli.render.text import Doc, Heading, Note, Table, _plain, _rich_printer

# what rbcli's tables hold, plus characters rich counts as 2 cells (wide) or 0 (combining)
ALPHABET = st.sampled_from(list("abcxyz019 .,-+()[]|/:") + ["·", "²", "³", "−", "°", "ω", "θ", "µ", "…",
                                                            "é", "水", "\u0301", "\t"])
TEXT = st.text(ALPHABET, max_size=30)


@st.composite
def tables(draw):
    n = draw(st.integers(1, 5))
    cols = tuple(draw(st.lists(TEXT, min_size=n, max_size=n)))
    rows = tuple(tuple(draw(st.lists(TEXT, min_size=n, max_size=n))) for _ in range(draw(st.integers(0, 6))))
    right = tuple(i for i in range(n) if draw(st.booleans()))
    return Table(draw(TEXT), cols, rows, right)


ITEMS = st.one_of(tables(), TEXT.map(Heading), st.lists(TEXT, max_size=3).map(lambda x: Note("\n".join(x))))


def _rich(items, width: int) -> str:
    render = _rich_printer(False, width)
    return "".join(render(item) for item in items)


@pytest.mark.sampled
@settings(max_examples=sample(50, 400), deadline=None)
@given(st.lists(ITEMS, min_size=1, max_size=4), st.integers(20, 120))
def test_plain_layout_is_richs(items, width):
    doc = Doc(Env(io.StringIO(), io.StringIO(), False, color=False, width=width), list(items))
    assert doc.render() == _rich(items, width)


def test_plain_layout_is_used_for_a_typical_table():
    """The fast path really runs (not only the fallback) for what rbcli prints."""
    t = Table("mass properties", ("quantity", "value", "unit"),
              (("mass", "9679.11", "kg"), ("I_xx", "1631.61", "kg·m²")), (1,))
    text = _plain(t, 100)
    assert text is not None
    assert text == _rich([t], 100)
    assert text.splitlines()[0] == "mass properties".ljust(len(text.splitlines()[1]))


def test_what_the_plain_layout_declines():
    """A line to wrap, a wide or combining character: rich's, not ours."""
    assert _plain(Table("t", ("a",), (("x" * 50,),)), 40) is None  # wider than the terminal
    assert _plain(Table("a title longer than the table", ("a",), (("1",),)), 100) is None
    assert _plain(Table("t", ("a",), (("水",),)), 100) is None
    assert _plain(Table("t", ("a",), (("e\u0301",),)), 100) is None
    assert _plain(Note("x" * 101), 100) is None
