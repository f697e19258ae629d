"""Tables as CSV (``--format csv``): what a spreadsheet reads.

The layout is a contract (documented in rbcli(1)): one block per table of the document,
blocks separated by an empty line; each block is a header row and its rows. The first
column, ``table``, is the table's title, so every row says where it came from; with
several bodies (``inertia``/``principal`` on many files) a ``file`` column comes first.
The numeric columns of a table that names its unit in its title (``inertia about the
origin [kg·m²]``) carry the unit in their header (``x [kg·m²]``), and the title loses
it; quantity/value/unit tables
keep their ``unit`` column. Numbers are the table's, at ``--digits`` significant
figures (JSON has full precision). Notes and headings (prose) are not part of the CSV.
Quoting follows RFC 4180 (Python's csv module, ``\\n`` line ends).
"""

from __future__ import annotations

import csv
import io
import re

from rbcli.render.text import Doc, Table

#: a unit in brackets in a table title ("inertia about the origin [kg·m²]")
_TITLE_UNIT = re.compile(r"\s*\[([^\[\]]+)\]")


def header(table: Table) -> list[str]:
    """The CSV header of a table: its columns, numeric ones with the title's unit."""
    m = _TITLE_UNIT.search(table.title)
    if not m or "unit" in table.columns:
        return list(table.columns)
    unit = m.group(1)
    return [f"{c} [{unit}]" if i in table.right else c for i, c in enumerate(table.columns)]


def title(table: Table) -> str:
    """The table's title without a trailing bracketed unit (it moved into the header)."""
    if "unit" in table.columns:
        return table.title
    return _TITLE_UNIT.sub("", table.title, count=1)


def blocks(doc: Doc, file: str | None = None) -> list[list[list[str]]]:
    """The CSV rows of each table of ``doc`` (header first), with a ``file`` column when
    ``file`` is given."""
    out = []
    for item in doc.items:
        if not isinstance(item, Table):
            continue
        lead = ["file"] if file is not None else []
        first = [file] if file is not None else []
        rows = [lead + ["table"] + header(item)]
        rows += [first + [title(item)] + [cell.strip() for cell in row] for row in item.rows]
        out.append(rows)
    return out


def render(doc: Doc, file: str | None = None) -> str:
    """The CSV text of a document (see the module docstring for the layout)."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    for i, block in enumerate(blocks(doc, file)):
        if i:
            buf.write("\n")
        w.writerows(block)
    return buf.getvalue()
