"""Documents of headings, tables and notes — rendered for a terminal (rich) or,
by :mod:`rbcli.render.report`, as HTML or Markdown.

A command's render module fills a :class:`Doc` with neutral items; how they look is
decided only when the document is rendered. Text from the user (names, titles, cells) is
made safe for a terminal there, once (:func:`rbcli.env.clean`). Tables for people: units in headers,
plain ASCII without colour when not a terminal.
"""

from __future__ import annotations

import io
import re
import shutil
from collections.abc import Sequence
from typing import TYPE_CHECKING

from rbcli._startup import frozen
from rbcli.env import clean

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.env import Env


@frozen
class Heading:
    """A heading line."""

    text: str


@frozen
class Note:
    """A paragraph of text."""

    text: str


@frozen
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

    def __repr__(self) -> str:
        return f"Doc(env={self.env!r}, items={self.items!r})"

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
        """The document for a terminal or a pipe: plain ASCII tables without colour when not
        a terminal, rich's tables with colour on one.

        Without colour every item that fits the width in single-cell characters is laid out
        here (:func:`_plain`), byte for byte as rich lays it out (tests/test_render_text.py
        compares the two on generated documents): rich costs ~0.2 ms a table row, which a
        100 000-part body's parts table would spend for minutes. Anything else (a line to
        wrap, a wide or zero-width character, colour) is rich's.
        """
        env = self.env
        color = bool(env and env.color)
        width = env.width if env and env.width else None
        if width is None:
            width = shutil.get_terminal_size((100, 24)).columns if env and env.stdout_isatty else _columns()
        out: list[str] = []
        rich_print = None
        for item in self.items:
            text = None if color else _plain(item, width)
            if text is None:
                if rich_print is None:
                    rich_print = _rich_printer(color, width)
                text = rich_print(item)
            out.append(text)
        return "".join(out)


def _rich_printer(color: bool, width: int):
    """A function that renders one document item with rich (imported here, when needed)."""
    from rich import box
    from rich.console import Console
    from rich.table import Table as RichTable
    from rich.text import Text

    buf = io.StringIO()
    console = Console(
        file=buf,
        force_terminal=color,
        no_color=not color,
        color_system="standard" if color else None,
        width=width,
        highlight=False,
        emoji=False,
        markup=False,
        legacy_windows=False,
    )

    def render(item) -> str:
        buf.seek(0)
        buf.truncate()
        # every piece of text is made safe once, here: control characters and line
        # separators escaped, runs over 200 characters cut (rbcli.env.clean)
        if isinstance(item, Heading):
            console.print(Text(clean(item.text, keep_newlines=True, max_line=None), style="bold" if color else ""))
        elif isinstance(item, Note):
            console.print(Text(clean(item.text, keep_newlines=True, max_line=None)))
        else:
            t = RichTable(
                title=clean(item.title) or None,
                title_justify="left",
                box=box.SIMPLE_HEAD if color else box.ASCII2,
                show_edge=False,
                pad_edge=False,
                title_style="bold" if color else None,
                header_style="bold" if color else None,
            )
            for i, c in enumerate(item.columns):
                t.add_column(clean(c), justify="right" if i in item.right else "left", overflow="fold")
            for r in item.rows:
                t.add_row(*(clean(x) for x in r))
            console.print(t)
        return buf.getvalue()

    return render


def _single_cells(text: str) -> bool:
    """Whether every character of ``text`` takes one terminal cell (as rich counts them):
    printable ASCII, or a character that is neither wide, combining nor a control/format."""
    if text.isascii():
        return text.isprintable()
    import unicodedata

    for ch in text:
        if ch.isascii():
            if not ch.isprintable():
                return False
        elif (unicodedata.east_asian_width(ch) in ("W", "F") or unicodedata.combining(ch)
              or unicodedata.category(ch) in ("Mn", "Me", "Mc", "Cc", "Cf", "Cs", "Co", "Cn", "Zl", "Zp")):
            return False
    return True


def _plain(item, width: int) -> str | None:
    """``item`` as rich prints it without colour (box ASCII2, no edge, no edge padding,
    title left-justified above), or None when rich would do more than this: wrap a line or a
    cell, or count a character as other than one cell."""
    if isinstance(item, (Heading, Note)):
        lines = clean(item.text, keep_newlines=True, max_line=None).split("\n")
        for line in lines:
            if len(line) > width or not _single_cells(line):
                return None
        return "\n".join(lines) + "\n"
    cols = [clean(c) for c in item.columns]
    n = len(cols)
    rows = [[clean(x) for x in r] for r in item.rows]
    if n == 0 or any(len(r) != n for r in rows):
        return None
    widths = [len(c) for c in cols]
    for r in rows:
        for i, x in enumerate(r):
            if len(x) > widths[i]:
                widths[i] = len(x)
    total = sum(widths) + 3 * (n - 1)
    title = clean(item.title)
    if 0 in widths or total > width or len(title) > total:
        return None
    if not all(_single_cells(x) and x == x.strip(" ") for x in (title, *cols)) or not all(
            _single_cells("".join(r)) and all(x == x.strip(" ") for x in r) for r in rows):
        return None  # rich strips a cell's edge spaces before it justifies it
    right = set(item.right)
    just = [str.rjust if i in right else str.ljust for i in range(n)]

    def line(cells) -> str:
        return " | ".join([just[i](x, widths[i]) for i, x in enumerate(cells)])

    out = [title.ljust(total)] if title else []
    out.append(line(cols))
    out.append("-+-".join(["-" * w for w in widths]))
    out.extend(line(r) for r in rows)
    return "\n".join(out) + "\n"


def _columns() -> int:
    import os

    try:
        return max(40, int(os.environ.get("COLUMNS", "100")))
    except ValueError:
        return 100


# ----------------------------------------------------------------------------- checks


#: what :func:`rbcli.render.fmt.num` prints for a number that is not finite
_NON_FINITE = frozenset({"inf", "-inf", "+inf", "nan", "-nan"})
_CELL_SPLIT = re.compile(r"[\s\[\](),;=]+")


def check_finite_doc(doc: Doc) -> None:
    """Refuse a table that would show inf or NaN as a number.

    Looks at the numeric (right-aligned) columns of every table: a whole word there that
    reads inf or nan is what ``num()`` prints for a result that overflowed. Names, notes
    and left-aligned text are not looked at (a part may be called "nan").

    Raises
    ------
    NonFiniteResult
        (exit 2, one line) naming the table and the row.
    """
    from rbcli.errors import NonFiniteResult

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
