"""The physics notes the output cites ship with rbcli (issue 32 item 6): every "physics notes
NAME.md §N" in the code names a file of docs/physics/ with that section, and the Sphinx
docs include each file."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CITE = re.compile(r"physics (?:notes|sheet) [`]*(?:physics/)?(\w+\.md)[`]*(?: §(\d+(?:\.\d+)?))?")


def test_every_cited_note_and_section_is_shipped():
    cited = {m.groups() for p in (ROOT / "rbcli").rglob("*.py") for m in CITE.finditer(p.read_text(encoding="utf-8"))}
    assert len({name for name, _ in cited}) >= 3  # balance.md, dynamics.md, whirl.md
    for name, section in cited:
        note = ROOT / "docs" / "physics" / name
        assert note.is_file(), name
        if section:
            assert re.search(rf"^#+ {re.escape(section)}[. ]", note.read_text(encoding="utf-8"), re.M), (name, section)
        assert f"physics/{name}" in (ROOT / "docs" / "physics.rst").read_text(encoding="utf-8")
