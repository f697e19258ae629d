"""The README's "Python API" example runs as written, and says what it prints."""

from __future__ import annotations

import contextlib
import io
import os
import re

from conftest import ROOT


def _example() -> str:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    section = text.split("## Python API", 1)[1].split("\n## ", 1)[0]
    return re.search(r"```python\n(.*?)```", section, re.S).group(1)


def test_the_readme_python_example_runs_and_prints_what_its_comments_say():
    old = os.getcwd()
    os.chdir(ROOT)
    out = io.StringIO()
    try:
        with contextlib.redirect_stdout(out):
            exec(compile(_example(), "README.md", "exec"), {})
    finally:
        os.chdir(old)
    lines = out.getvalue().splitlines()
    assert lines[0] == "1"  # the rotor as given fails G6.3 (README balance section)
    assert abs(float(lines[2]) - 1 / 12) < 1e-15  # m a^2 / 12, to a few ulps of round-off
    assert abs(float(lines[4]) - 0.142133) < 5e-7  # the sheet's T1 nutation period, 6 figures
    assert lines[-1].startswith("about: expected 3") and lines[-1].endswith(" about")


def test_import_rbcli_is_cheap():
    import subprocess
    import sys

    code = "import rbcli, sys; print(sorted(m for m in ('numpy', 'scipy', 'matplotlib', 'yaml', 'typer') if m in sys.modules))"
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True)
    assert r.stdout.strip() == "[]"


def test_help_of_each_function_documents_its_arguments():
    import rbcli

    for name in ("inertia", "principal", "balance", "field_balance", "precess", "top",
                 "gyrocompass", "rollcheck", "load", "load_text"):
        doc = getattr(rbcli, name).__doc__ or ""
        assert "Parameters" in doc and "Returns" in doc, name
