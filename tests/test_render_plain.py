"""The plain-Python renderer of rbcli.render.text against rich, its oracle.

Piped and colourless, ``Doc.render`` prints each item without rich (``_plain``); it must give
rich's bytes: random documents (hypothesis), each edge of rich's layout by name, the width
rule of ``_one_cell`` checked against rich's ``cell_len`` for every character and every
Unicode version rich knows, the fallback to rich for a wide character, and that piped
commands do not import rich.
"""

from __future__ import annotations

import shutil

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from conftest import ROOT, sample
from rbcli.env import Env
from rbcli.render.text import Doc, Heading, Note, Table, _clean, _one_cell, _plain, _rich_printer


def _rich(items, width: int) -> str:
    """The oracle: each item printed by rich, as a colourless pipe does it."""
    render = _rich_printer(False, width, False)
    return "".join(render(_clean(i)) for i in items)


def _same(items, width: int = 100) -> str:
    """The plain rendering of ``items``, after checking it took the plain path for each and
    equals rich's."""
    assert all(_plain(_clean(i), width) is not None for i in items)
    out = Doc(Env(None, None, False, False, width), list(items)).render()
    assert out == _rich(items, width)
    return out


def test_a_table_looks_as_the_golden_files_show_it():
    out = _same([Table("mass properties", ("quantity", "value", "unit"), (("mass", "0.5", "kg"),), (1,))])
    assert out == ("mass properties        \n"
                   "quantity | value | unit\n"
                   "---------+-------+-----\n"
                   "mass     |   0.5 | kg  \n")


EDGES = {
    "empty single column": [Table("t", ("",), (("",), ("",)))],
    "empty single column, no rows": [Table("", ("",), ())],
    "empty middle column": [Table("title", ("a", "", "c"), (("1", "", "3"),), (1,))],
    "empty first and last columns": [Table("", ("", "b", ""), (("", "x", ""),), (0, 2))],
    "no rows": [Table("a title", ("x", "y"), ())],
    "short and empty rows": [Table("t", ("x", "y", "z"), (("1",), (), ("a", "b")), (2,))],
    "right-justified trailing spaces": [Table("t", ("name", "n"), (("a  ", "12  "), ("  b", " 3 ")), (0, 1))],
    "spaces-only cells": [Table("   ", ("  ", "x"), (("   ", " "),), (0,))],
    "title wrapped to the table": [Table("a long title of short words over a narrow table",
                                         ("column x", "column y"), (("1", "2"),))],
    "title with runs of spaces": [Table("a  b   c    d     e   ", ("col", "c"), (("1", "2"),))],
    "title with a leading run of spaces folds": [Table("        abcdef", ("abcdefgh",), ())],
    "title apart (a word wider than the table)": [Table("an-unbreakable-word " * 5, ("x", "y"), (("1", "2"),))],
    "title apart, longer than 100": [Table("w" * 150 + " and more words", ("x",), (("1",),))],
    "right index beyond the columns": [Table("t", ("x",), (("1",),), (0, 5))],
    "heading and notes": [Heading("Rotor  (examples/x.yaml)"), Note("a note\n\nwith a blank line\n")],
    "empty note and blank lines": [Note(""), Note("\n"), Note("\n\n"), Note("   ")],
    "note longer than the width": [Note(" ".join(["word"] * 60) + "  trailing   ")],
    "note with a leading run folds": [Note(" " * 30 + "x" * 95 + " tail")],
    "note of spaces longer than the width": [Note(" " * 250)],
    "symbols rbcli prints": [Note("ζ = 0.05 · ω² ° × — λ Ω ∫ √ −∫xy dm"),
                             Table("J [kg·m²]", ("", "ζ", "Ω [°]"), (("x", "0.1 ×", "√2 —"),), (1, 2))],
    "control characters and newlines escaped in cells": [Table("a\nb", ("c\td",), (("e\x1bf",),))],
}


@pytest.mark.parametrize("items", EDGES.values(), ids=EDGES.keys())
@pytest.mark.parametrize("width", [40, 100])
def test_each_edge_of_richs_layout(items, width):
    _same(items, width)


def test_the_empty_single_column_is_one_wide():
    # rich: a column's width is its measure or 1 (table.py, `_range.maximum or 1`)
    assert _same([Table("", ("",), (("",),))]) == " \n-\n \n"


# ---------------------------------------------------------------- random documents

SYMBOLS = "·²°×—ζλΩ∫√−±µ…éüßαβγδεθπσφψωΔΣ"
WORD_CHARS = "abcdefghijklmnopqrstuvwxyzABCXYZ0123456789.,;:()[]{}<>/\\|+-*=_'\"!?#%&@$^~`" + SYMBOLS
words = st.text(alphabet=WORD_CHARS, max_size=12) | st.text(alphabet=WORD_CHARS, min_size=13, max_size=230)
spaces = st.integers(1, 6).map(lambda n: " " * n)


@st.composite
def texts(draw, lines: bool = False):
    """Words and runs of spaces, with leading and trailing spaces; ``lines``: several lines."""
    parts = [draw(st.sampled_from(["", " ", "    "]) | spaces)]
    for _ in range(draw(st.integers(0, 40 if lines else 8))):
        parts += [draw(words), draw(spaces) if not lines or draw(st.integers(0, 9)) else "\n"]
    return "".join(parts[:-1] if draw(st.booleans()) else parts)


@st.composite
def tables(draw):
    n = draw(st.integers(1, 6))
    cell = st.text(alphabet=WORD_CHARS + "  ", max_size=20) | texts()
    rows = draw(st.lists(st.lists(cell, max_size=n).map(tuple), max_size=6))
    right = draw(st.sets(st.integers(0, n)))
    columns = tuple(draw(st.lists(cell, min_size=n, max_size=n)))
    return Table(draw(texts()), columns, tuple(rows), tuple(right))


items = st.one_of(tables(), texts(lines=True).map(Note), texts().map(Heading))


@pytest.mark.sampled
@settings(max_examples=sample(150, 3000), deadline=None)
@given(st.lists(items, min_size=1, max_size=5), st.integers(40, 200))
@example([Note(" " * 45 + "x" * 50)], 40)
def test_random_documents_render_as_rich_renders_them(doc, width):
    _same(doc, width)


# ---------------------------------------------------------------- what is not plain goes to rich


@pytest.mark.parametrize("item", [
    Note("日本語のノート over the width " * 5), Heading("e\u0301t\u00e9"),
    Table("宽 title", ("名", "x"), (("ab", "全角"),), (1,)), Table("t", ("x",), (("🙂",),)),
], ids=["wide note", "combining", "wide table", "emoji"])
def test_a_character_not_one_cell_wide_goes_to_rich(item):
    assert _plain(_clean(item), 60) is None
    assert Doc(Env(None, None, False, False, 60), [item]).render() == _rich([item], 60)


def test_the_one_cell_rule_agrees_with_rich_for_every_character():
    """Every character ``_one_cell`` admits is one cell for rich's ``cell_len`` under each
    Unicode version rich has a table of (``UNICODE_VERSION`` chooses); rich joins characters
    only at a zero-width joiner or a variation selector, which the rule refuses. Every
    character of every golden file is admitted (their tables take the plain path)."""
    from rich._unicode_data._versions import VERSIONS
    from rich.cells import get_character_cell_size

    admitted = {chr(i) for i in range(0x110000) if _one_cell.__wrapped__(chr(i))}
    golden = {c for p in (ROOT / "tests/cases").glob("*/*.out") for c in p.read_text(encoding="utf-8")}
    assert golden - {"\n"} <= admitted and {"ζ", "λ", "∫", "√", "…", "ẑ", "ᵀ", "→"} <= admitted
    refused = {"\u200d", "\ufe0f", "\t", "\n", "\u0301", "\u00a0", "日", "🙂", "\u1160", "\u2630"}
    assert not refused & admitted
    for version in VERSIONS:
        wide = [c for c in sorted(admitted) if get_character_cell_size(c, version) != 1]
        assert not wide, (version, [f"U+{ord(c):04X}" for c in wide[:20]])


# ---------------------------------------------------------------- rich is not imported


def test_piped_commands_do_not_import_rich(cli_proc, tmp_path):
    for args in (["inertia", "examples/book.yaml"], ["whirl", "examples/journal_rotor.yaml"]):
        r = cli_proc(*args, imports=True)
        assert r.out and not {m for m in r.imported if m.split(".")[0] == "rich"}, args
    # the check can fail: a heading with a wide character is printed by rich
    book = shutil.copy(ROOT / "examples/book.yaml", tmp_path / "本.yaml")
    r = cli_proc("inertia", str(book), imports=True)
    assert "本" in r.out and "rich.table" in r.imported, r.err
