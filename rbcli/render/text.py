"""Tables for people (rich): units in headers, plain text when not a terminal."""

from __future__ import annotations

import io
from collections.abc import Sequence

from rbcli.env import Env


class Doc:
    """A document of titled tables and notes, rendered once to text."""

    def __init__(self, env: Env) -> None:
        self.env = env
        self.items: list = []

    def heading(self, text: str) -> None:
        from rich.text import Text

        self.items.append(Text(text, style="bold"))

    def note(self, text: str) -> None:
        from rich.text import Text

        self.items.append(Text(text))

    def table(
        self,
        title: str,
        columns: Sequence[str],
        rows: Sequence[Sequence[str]],
        *,
        right: Sequence[int] = (),
    ) -> None:
        from rich import box
        from rich.table import Table

        t = Table(
            title=title,
            title_justify="left",
            box=box.SIMPLE_HEAD if self.env.color else box.ASCII2,
            show_edge=False,
            pad_edge=False,
            title_style="bold" if self.env.color else None,
            header_style="bold" if self.env.color else None,
        )
        for i, c in enumerate(columns):
            t.add_column(c, justify="right" if i in right else "left", overflow="fold")
        for r in rows:
            t.add_row(*r)
        self.items.append(t)

    def kv(self, title: str, rows: Sequence[tuple[str, str, str]]) -> None:
        """A quantity / value / unit table."""
        self.table(title, ("quantity", "value", "unit"), rows, right=(1,))

    def render(self) -> str:
        from rich.console import Console

        buf = io.StringIO()
        console = Console(
            file=buf,
            force_terminal=self.env.color,
            no_color=not self.env.color,
            color_system="standard" if self.env.color else None,
            width=self.env.width or 100,
            highlight=False,
            emoji=False,
            markup=False,
            legacy_windows=False,
        )
        for i, item in enumerate(self.items):
            if i and not isinstance(item, str):
                pass
            console.print(item)
        return buf.getvalue()
