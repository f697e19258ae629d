"""`.ci/run` runs exactly the README's second command (the one that installs the test tools,
runs the suite and builds the API reference)."""

from __future__ import annotations

import re

from conftest import ROOT


def test_ci_runs_the_readmes_second_command():
    blocks = re.findall(r"```sh\n(.*?)\n```", (ROOT / "README.md").read_text(encoding="utf-8"), re.S)
    second = blocks[1].strip()
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    assert second in ci.splitlines()
    assert "pytest" in second and "sphinx-build -W" in second
