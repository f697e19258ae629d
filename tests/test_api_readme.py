"""The README's "Python API" example runs as written, and says what it prints."""

from __future__ import annotations

import contextlib
import io
import os
import re

from conftest import ROOT


def _examples() -> list[str]:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    section = text.split("## Python API", 1)[1].split("\n## ", 1)[0]
    return re.findall(r"```python\n(.*?)```", section, re.S)


def _example() -> str:
    return _examples()[0]


def _run(code: str) -> tuple[list[str], dict]:
    old = os.getcwd()
    os.chdir(ROOT)
    out = io.StringIO()
    namespace: dict = {}
    try:
        with contextlib.redirect_stdout(out):
            exec(compile(code, "README.md", "exec"), namespace)
    finally:
        os.chdir(old)
    return out.getvalue().splitlines(), namespace


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


#: the README's rotor as a body file, written by hand: the disk at x = {e} mm
ROTOR_YAML = """\
name: rotor
units: {{length: mm}}
shaft: {{axis: [0, 0, 1]}}
parts:
  - {{name: shaft, shape: cylinder, radius: 10, length: 400, density: 7850 kg/m^3, at: [0, 0, 200]}}
  - {{name: disk, shape: disk, radius: 100, mass: 5, at: [{e}, 0, 300]}}
"""


def test_the_readme_sweep_built_with_parts_gives_the_numbers_of_the_same_yaml_bodies():
    import rbcli

    code = _examples()[1]
    assert len(code.strip().splitlines()) <= 16 and "from rbcli import parts" in code
    lines, ns = _run(code)
    offsets = [0.0, 0.05, 0.1, 0.2]
    sweep = lines[:len(offsets)]
    for e, line in zip(offsets, sweep):
        body = rbcli.load_text(ROTOR_YAML.format(e=e))
        r = rbcli.balance(body, planes="0,400 mm", radius="100 mm")
        # the same numbers as the YAML body, printed the same way
        assert line == (f"e = {e} mm: U = {r.static_unbalance * 1e6:.0f} g mm, add "
                        f"{r.corrections[0].mass * 1e3:.4f} g at A, {r.corrections[1].mass * 1e3:.4f} g at B")
        # and to the last bit: the whole result
        assert rbcli.balance(ns["rotor"].moved("disk", at=[e, 0, 300]), planes="0,400 mm",
                             radius="100 mm").to_json() == r.to_json()
        # the closed form: U = m e, the lever rule between the planes at 0 and 400 mm
        # (6 digits printed, far above the ~1e-16 round-off)
        m, r_c = 5.0, 0.1
        assert line == (f"e = {e} mm: U = {m * e * 1e3:.0f} g mm, add "
                        f"{m * e * 1e-3 * 100 / 400 / r_c * 1e3:.4f} g at A, "
                        f"{m * e * 1e-3 * 300 / 400 / r_c * 1e3:.4f} g at B")
    assert "e = 0.1 mm: U = 500 g mm, add 1.2500 g at A, 3.7500 g at B" in lines
    written = "\n".join(lines[len(offsets):]) + "\n"
    again = rbcli.load_text(written)
    assert again.parts[1].com.tolist() == rbcli.load_text(ROTOR_YAML.format(e=0.1)).parts[1].com.tolist()


def test_the_readme_notebook_sweep_collects_json_records(monkeypatch):
    """The pandas sweep runs as written (pandas is not a dependency: a stand-in checks what
    json_normalize is given), and the repr it quotes is the one a result has."""
    import json
    import sys
    import types

    got = []
    fake = types.ModuleType("pandas")
    fake.json_normalize = lambda records: got.append(json.loads(json.dumps(records))) or {  # JSON records
        k: [r.get(k) for r in records] for k in records[0]}
    monkeypatch.setitem(sys.modules, "pandas", fake)
    code = [c for c in _examples() if "json_normalize" in c][0].replace('df[["stiffness", "critical_speeds"]]', "")
    _, ns = _run(code)
    assert [r["stiffness"] for r in got[0]] == [2e6, 5e6, 1e7, 2e7] and all("critical_speeds" in r for r in got[0])
    shown = re.search(r"`(<BalanceResult [^`]*)…>`", (ROOT / "README.md").read_text(encoding="utf-8")).group(1)
    r = rbcli_balance_of_fan()
    assert repr(r).startswith(shown)


def rbcli_balance_of_fan():
    import rbcli

    return rbcli.balance(rbcli.load(ROOT / "examples/fan_rotor.yaml"))


def test_import_rbcli_is_cheap():
    import subprocess
    import sys

    # a fresh interpreter (not the cli fixtures: no command runs): what `import rbcli` loads
    code = "import rbcli, sys; print(sorted(m for m in ('numpy', 'scipy', 'matplotlib', 'yaml', 'typer') if m in sys.modules))"
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True)
    assert r.stdout.strip() == "[]"


def test_help_of_each_function_documents_its_arguments():
    import rbcli

    for name in ("inertia", "principal", "balance", "field_balance", "precess", "top",
                 "gyrocompass", "rollcheck", "load", "load_text"):
        doc = getattr(rbcli, name).__doc__ or ""
        assert "Parameters" in doc and "Returns" in doc, name
