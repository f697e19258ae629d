"""Documents of headings, tables and notes — rendered for a terminal (rich) or,
by :mod:`rbcli.render.report`, as HTML or Markdown.

A command's render module fills a :class:`Doc` with neutral items; how they look is
decided only when the document is rendered. Text from the user (names, titles, cells) is
made safe for a terminal there, once (:func:`rbcli.errors.clean`). Tables for people: units in headers,
plain ASCII without colour when not a terminal.
"""

from __future__ import annotations

import io
import os
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
        """The document for a terminal or a pipe (rich's tables): plain ASCII tables without
        colour when not a terminal, with colour on one."""
        env = self.env
        color = bool(env and env.color)
        width = env.width if env and env.width else None
        if width is None:
            width = shutil.get_terminal_size((100, 24)).columns if env and env.stdout_isatty else _columns()
        rich_print = _rich_printer(color, width)
        return "".join(rich_print(item) for item in self.items)


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


def _columns() -> int:
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
