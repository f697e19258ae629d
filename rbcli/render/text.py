"""Documents of headings, tables and notes — rendered for a terminal (rich) or,
by :mod:`rbcli.render.report`, as HTML or Markdown.

A command's render module fills a :class:`Doc` with neutral items; how they look is
decided when it is rendered, where text from the user is made safe once (:func:`clean`).
"""

from __future__ import annotations

import io
import math
import re
import shutil
from collections.abc import Sequence
from typing import TYPE_CHECKING

from dataclasses import dataclass

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

    def table(
        self,
        title: str,
        columns: Sequence[str],
        rows: Sequence[Sequence[str]],
        *,
        right: Sequence[int] = (),
    ) -> None:
        self.items.append(
            Table(title, tuple(columns), tuple(tuple(str(x) for x in r) for r in rows), tuple(right))
        )

    def kv(self, title: str, rows: Sequence[tuple[str, str, str]]) -> None:
        """A quantity / value / unit table."""
        self.table(title, ("quantity", "value", "unit"), rows, right=(1,))

    def render(self) -> str:
        """The document as text (rich; colour on a terminal). No word is ever split: on a
        terminal cells wrap at spaces to its width (a table that cannot fit, wider); not on
        one, a table is as wide as its rows; notes wrap at spaces (``COLUMNS``, else 100)."""
        env = self.env
        tty = bool(env and env.stdout_isatty)
        width = (env.width if env and env.width else None) or \
            max(40, shutil.get_terminal_size((100, 24)).columns)  # not a terminal: COLUMNS, else 100
        rich_print = _rich_printer(bool(env and env.color), width, tty)
        return "".join(rich_print(item) for item in self.items)


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
    """A function that renders one document item with rich (imported here, when needed)."""
    from rich import box
    from rich.cells import cell_len
    from rich.console import Console
    from rich.table import Table as RichTable
    from rich.text import Text

    buf = io.StringIO()
    console = Console(file=buf, force_terminal=color, no_color=not color, color_system="standard" if color else None,
                      width=1 << 20, highlight=False, emoji=False, markup=False, legacy_windows=False)

    def longest(texts) -> int:
        return max((cell_len(w) for t in texts for w in t.split()), default=0)

    def render(item) -> str:
        buf.seek(0)
        buf.truncate()
        # every piece of text is made safe once, here: control characters and line
        # separators escaped, runs over 200 characters cut (rbcli.errors.clean)
        if isinstance(item, (Heading, Note)):
            text = clean(item.text, keep_newlines=True, max_line=None)
            style = "bold" if color and isinstance(item, Heading) else ""
            console.print(Text(text, style=style), width=max(width, longest([text])))
            return buf.getvalue()
        cols = [clean(c) for c in item.columns]
        rows = [[clean(x) for x in r] for r in item.rows]
        cells = [[c, *(r[i] for r in rows if i < len(r))] for i, c in enumerate(cols)]
        hi = [max(cell_len(line) for x in col for line in x.split("\n")) for col in cells]
        widths = _fit(hi, [longest(col) for col in cells], width - 3 * (len(cols) - 1) if tty else math.inf)
        title = clean(item.title)
        room = sum(widths) + 3 * (len(cols) - 1)
        # a title with a word wider than its table, or wider than a terminal its table overflows: apart
        apart = longest([title]) > room or (tty and room > width and cell_len(title) > width)
        if apart:
            console.print(Text(title, style="bold" if color else ""), width=max(width if tty else 100, longest([title])))
        t = RichTable(title=None if apart else title or None, title_justify="left",
                      box=box.SIMPLE_HEAD if color else box.ASCII2, show_edge=False, pad_edge=False,
                      title_style="bold" if color else None, header_style="bold" if color else None)
        for i, c in enumerate(cols):
            t.add_column(c, justify="right" if i in item.right else "left",
                         width=None if widths == hi else widths[i])
        for r in rows:
            t.add_row(*r)
        console.print(t)
        return buf.getvalue()

    return render


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
