"""Documents of headings, tables and notes — rendered for a terminal (rich) or,
by :mod:`rbcli.render.report`, as HTML or Markdown.

A command's render module fills a :class:`Doc` with neutral items; how they look is
decided when it is rendered, where text from the user is made safe once (:func:`clean`).
Piped and colourless (every golden file), items are printed by plain Python (:func:`_plain`,
~30 times faster than importing and running rich), with rich's bytes (its oracle:
tests/test_render_plain.py); an item with a character not plainly one cell wide goes to rich.
"""

from __future__ import annotations

import functools
import io
import math
import re
import shutil
import unicodedata
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from rbcli.errors import NonFiniteResult, clean

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.env import Env


@dataclass(frozen=True)
class Heading:
    """A heading line."""

    text: str


@dataclass(frozen=True)
class Note:
    """A paragraph of text."""

    text: str


@dataclass(frozen=True)
class Table:
    """A titled table of text cells; ``right`` are the right-aligned columns."""

    title: str
    columns: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]
    right: tuple[int, ...] = ()


class Doc:
    """A document of titled tables and notes, rendered once to text."""

    def __init__(self, env: Env | None = None, items: list | None = None) -> None:
        self.env = env
        self.items: list = [] if items is None else items

    def heading(self, text: str) -> None:
        self.items.append(Heading(text))

    def note(self, text: str) -> None:
        self.items.append(Note(text))

    def table(self, title: str, columns: Sequence[str], rows: Sequence[Sequence[str]], *,
              right: Sequence[int] = ()) -> None:
        self.items.append(Table(title, tuple(columns), tuple(tuple(map(str, r)) for r in rows), tuple(right)))

    def kv(self, title: str, rows: Sequence[tuple[str, str, str]]) -> None:
        """A quantity / value / unit table."""
        self.table(title, ("quantity", "value", "unit"), rows, right=(1,))

    def render(self) -> str:
        """The document as text (rich; colour on a terminal). No word is ever split: on a
        terminal cells wrap at spaces to its width (a table that cannot fit, wider); not on
        one, a table is as wide as its rows; notes wrap at spaces (``COLUMNS``, else 100)."""
        env = self.env
        tty, color = bool(env and env.stdout_isatty), bool(env and env.color)
        width = (env and env.width) or max(40, shutil.get_terminal_size((100, 24)).columns)  # else COLUMNS, 100
        out, rich_print = [], None
        for item in map(_clean, self.items):
            text = None if tty or color else _plain(item, width)
            if text is None:
                rich_print = rich_print or _rich_printer(color, width, tty)
                text = rich_print(item)
            out.append(text)
        return "".join(out)


def _clean(item):
    """``item``'s text made safe (:func:`clean`: controls escaped, runs over 200 characters cut)."""
    if isinstance(item, Table):
        return Table(clean(item.title), tuple(map(clean, item.columns)),
                     tuple(tuple(map(clean, r)) for r in item.rows), item.right)
    return type(item)(clean(item.text, keep_newlines=True, max_line=None))


def _longest(texts, size=len) -> int:
    return max((size(w) for t in texts for w in t.split()), default=0)


def _columns(t: Table, size=len) -> tuple[list[list[str]], list[int]]:
    """Each column's cells (header first, a short row's missing cells empty) and widest cell."""
    cells = [[c, *(r[i] if i < len(r) else "" for r in t.rows)] for i, c in enumerate(t.columns)]
    return cells, [max(map(size, col)) for col in cells]


def _fit(hi: list[int], lo: list[int], room: float) -> list[int]:
    """Column widths: each column's widest cell, the widest shrunk one character at a time
    (never below its longest word) until the row fits ``room``."""
    w = list(hi)
    while sum(w) > room:
        i = max(range(len(w)), key=lambda j: (w[j] > lo[j], w[j]))
        if w[i] <= lo[i]:
            break
        w[i] -= 1
    return w


def _rich_printer(color: bool, width: int, tty: bool):
    """A function that renders one cleaned item with rich (imported here)."""
    from rich import box
    from rich.cells import cell_len
    from rich.console import Console
    from rich.table import Table as RichTable
    from rich.text import Text

    buf = io.StringIO()
    console = Console(file=buf, force_terminal=color, no_color=not color, color_system="standard" if color else None,
                      width=1 << 20, highlight=False, emoji=False, markup=False, legacy_windows=False)

    def render(item) -> str:
        buf.seek(0)
        buf.truncate()
        if isinstance(item, (Heading, Note)):
            style = "bold" if color and isinstance(item, Heading) else ""
            console.print(Text(item.text, style=style), width=max(width, _longest([item.text], cell_len)))
            return buf.getvalue()
        cells, hi = _columns(item, cell_len)
        widths = _fit(hi, [_longest(col, cell_len) for col in cells], width - 3 * (len(hi) - 1) if tty else math.inf)
        room = sum(widths) + 3 * (len(hi) - 1)
        title = item.title
        # a title with a word wider than its table, or wider than a terminal its table overflows: apart
        apart = _longest([title], cell_len) > room or (tty and room > width and cell_len(title) > width)
        if apart:
            console.print(Text(title, style="bold" if color else ""),
                          width=max(width if tty else 100, _longest([title], cell_len)))
        t = RichTable(title=None if apart else title or None, title_justify="left",
                      box=box.SIMPLE_HEAD if color else box.ASCII2, show_edge=False, pad_edge=False,
                      title_style="bold" if color else None, header_style="bold" if color else None)
        for i, c in enumerate(item.columns):
            t.add_column(c, justify="right" if i in item.right else "left",
                         width=None if widths == hi else widths[i])
        for r in item.rows:
            t.add_row(*r)
        console.print(t)
        return buf.getvalue()

    return render


# --- without rich (see the module docstring)


@functools.cache
def _one_cell(c: str) -> bool:
    """``c`` is one cell wide, as rich's ``cell_len`` agrees (tests/test_render_plain.py): printable,
    not a mark nor East Asian wide, Latin to Armenian or phonetic letters to shapes."""
    return (c.isprintable() and (ord(c) < 0x590 or 0x1D00 <= ord(c) < 0x2600)
            and unicodedata.category(c)[0] != "M" and unicodedata.east_asian_width(c) not in "WF")


def _narrow(texts) -> bool:
    return all(map(_one_cell, set().union(*texts)))


_WORD = re.compile(r"\s*\S+\s*")


def _wrap(text: str, width: int) -> list[str]:
    """A line cut into lines of ``width`` as rich's ``divide_line`` and ``Text.rstrip_end`` do."""
    cuts, at = [0], 0
    for m in _WORD.finditer(text):
        start, word = m.start(), m.group()
        if len(word.rstrip()) <= width - at:
            at += len(word)
        elif len(word.rstrip()) > width:
            cuts += [start + i for i in range(0, len(word), width) if start + i]
            at = len(word) % width or width
        else:
            cuts.append(start)
            at = len(word)
    lines = [text[a:b] for a, b in zip(cuts, [*cuts[1:], len(text)])]
    return [s[:max(width, len(s.rstrip()))] for s in lines]


def _lines(text: str, width: int) -> str:
    """rich's ``console.print(Text(text), width=width)`` with no colour."""
    return "".join(s + "\n" for para in text.split("\n") for s in _wrap(para, width))


def _plain(item, width: int) -> str | None:
    """``item`` as rich prints it with no colour, not on a terminal; None if a character
    in it is not plainly one cell wide."""
    if not isinstance(item, Table):
        text = item.text
        return _lines(text, max(width, _longest([text]))) if _narrow(text.split("\n")) else None
    if not item.columns or any(len(r) > len(item.columns) for r in item.rows) \
            or not _narrow([item.title, *item.columns, *(x for r in item.rows for x in r)]):
        return None
    cells, hi = _columns(item)
    n, title = len(hi), item.title
    pads = [(i > 0, i < n - 1) for i in range(n)]  # no padding at the edges
    apart = _longest([title]) > sum(hi) + 3 * (n - 1)
    hi[0] = max(hi[0], n == 1)  # rich: a table is at least 1 wide
    room = sum(hi) + 3 * (n - 1)
    out = _lines(title, max(100, _longest([title]))) if apart else \
        "".join(s.ljust(room) + "\n" for s in _wrap(title, room) if title)
    rows = ["|".join(" " * a + (x.rstrip().rjust(h) if i in item.right else x.ljust(h)) + " " * b
                     for i, (x, h, (a, b)) in enumerate(zip(row, hi, pads))) for row in zip(*cells)]
    rule = "+".join("-" * (h + a + b) for h, (a, b) in zip(hi, pads))
    return out + "".join(s + "\n" for s in [rows[0], rule, *rows[1:]])


# --- checks


#: what :func:`rbcli.render.fmt.num` prints for a number that is not finite
_NON_FINITE = frozenset({"inf", "-inf", "+inf", "nan", "-nan"})
_CELL_SPLIT = re.compile(r"[\s\[\](),;=]+")


def check_finite_doc(doc: Doc) -> None:
    """Refuse (NonFiniteResult, exit 2, naming the table and the row) a table whose numeric
    (right-aligned) columns hold a word inf or nan: what ``num()`` prints for an overflow.
    Names, notes and left-aligned text are not looked at (a part may be called "nan")."""
    for item in doc.items:
        if not isinstance(item, Table):
            continue
        for row in item.rows:
            for i in item.right:
                if i >= len(row):
                    continue
                bad = [w for w in _CELL_SPLIT.split(row[i].lower()) if w in _NON_FINITE]
                if bad:
                    what = row[0].strip() if row and i != 0 else item.title
                    raise NonFiniteResult(
                        f"'{what}' in the table '{item.title}' is not a finite number ({bad[0]}): "
                        "a value is too large or too small to compute with; check the options "
                        "and the body's numbers"
                    )
