"""Tables never split a token (issue 32 item 1): every golden command line that prints
tables (every command on every example) is run with standard output a pipe, and every
number, unit and word of every cell is read back whole from what was printed; the same
documents on a narrow terminal (40 columns) wrap at spaces only."""

from __future__ import annotations

import re
from collections import Counter
from pathlib import Path

import pytest
import yaml

from conftest import run_inprocess, sampled_params
from rbcli.env import Env
from rbcli.render import text

CASES = Path(__file__).resolve().parent / "cases"
TABLES = [(f"{p.parent.name}/{p.stem}", spec["args"]) for p in sorted(CASES.glob("*/*.yaml"))
          if (spec := yaml.safe_load(p.read_text(encoding="utf-8")))["exit"] in (0, 1)
          and not {"--json", "--format", "--csv"} & set(spec["args"]) and spec["args"][0] not in ("shapes", "examples")]
_SPLIT = re.compile(r"[\s|]+")


def _cells(doc: text.Doc) -> Counter:
    """Every whitespace-separated token of the document's tables (titles, headers, cells)."""
    out: Counter = Counter()
    for item in doc.items:
        if isinstance(item, text.Table):
            for cell in (item.title, *item.columns, *(x for row in item.rows for x in row)):
                out.update(t for t in _SPLIT.split(text.clean(cell)) if t)
    return out


def _read_back(doc: text.Doc, printed: str) -> None:
    shown = Counter(t for t in _SPLIT.split(printed) if t)
    missing = _cells(doc) - shown  # a token folded over two lines is missing whole
    assert not missing, f"split or lost: {sorted(missing)[:5]}"
    numbers = [t for t in _cells(doc) if re.fullmatch(r"[-+]?[\d.]+(e[-+]?\d+)?,?", t)]
    for t in numbers:  # re-read: the number printed is the number the table holds
        assert float(t.rstrip(",")) == float(next(s for s in shown if s == t).rstrip(","))


@pytest.mark.parametrize("args", sampled_params([a for _, a in TABLES], lambda a: a[0] in (
    "whirl", "field-balance") or "bracket" in " ".join(a), ids=[n for n, _ in TABLES]))
def test_piped_and_narrow_tables_keep_every_token(args, monkeypatch):
    docs = []
    render = text.Doc.render

    def spy(self):
        out = render(self)
        docs.append((self, out))
        return out

    monkeypatch.setattr(text.Doc, "render", spy)
    code, out, err = run_inprocess(*args)
    assert code in (0, 1), err
    assert docs and "".join(o for _, o in docs) in out
    for doc, printed in docs:
        _read_back(doc, printed)
        narrow = render(text.Doc(Env(None, None, stdout_isatty=True, color=False, width=40), doc.items))
        _read_back(doc, narrow)
        for line in narrow.splitlines():  # wider than the terminal only where one word is
            assert len(line.rstrip()) <= 40 or "|" in line or "-+-" in line or " " not in line.strip(), line
