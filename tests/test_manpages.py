"""The man pages in man/ are in step with the real command tree, and render.

Fails when a page is stale: run ``python -m rbcli.cli.manpages man`` and commit man/.
"""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest
import typer.main

from rbcli.cli import app
from rbcli.cli.manpages import esc, pages

ROOT = Path(__file__).resolve().parent.parent
MAN = ROOT / "man"
REGENERATE = "run python -m rbcli.cli.manpages man (and commit man/)"
PAGES = pages()
COMMANDS = typer.main.get_command(app).commands


def test_every_command_has_a_page_and_there_are_no_others():
    assert set(PAGES) == {"rbcli.1", *(f"rbcli-{name}.1" for name in COMMANDS)}
    on_disk = {p.name for p in MAN.glob("rbcli*.1")}
    assert on_disk == set(PAGES), f"man/ has {sorted(on_disk ^ set(PAGES))} out of step: {REGENERATE}"


@pytest.mark.parametrize("name", sorted(PAGES))
def test_pages_on_disk_equal_the_regenerated_ones(name):
    path = MAN / name
    assert path.exists(), f"{path} is missing: {REGENERATE}"
    assert path.read_text(encoding="utf-8") == PAGES[name], f"{path} is stale: {REGENERATE}"


def test_regenerating_is_idempotent():
    assert pages() == PAGES


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_every_option_of_every_command_is_in_its_page(name):
    text = PAGES[f"rbcli-{name}.1"]
    for p in COMMANDS[name].params:
        for opt in getattr(p, "opts", []):
            if p.param_type_name == "option":
                assert f"\\fB{opt.replace('-', chr(92) + '-')}\\fR" in text, f"{opt} missing from rbcli-{name}.1"
        if p.param_type_name == "argument":
            assert esc(p.metavar or p.name.upper()) in text
        if getattr(p, "help", None):
            assert esc(" ".join(p.help.split())) in text, f"the help of {p.name} is missing from rbcli-{name}.1"
    for section in ("NAME", "SYNOPSIS", "DESCRIPTION", "OPTIONS", "EXIT STATUS", "SEE ALSO"):
        assert f".SH {section}\n" in text


def test_root_page_lists_commands_global_options_exit_status_and_json_keys():
    root = PAGES["rbcli.1"]
    for name in COMMANDS:
        assert f"\\fB{esc(name)}\\fR" in root
    for opt in ("\\-\\-version", "\\-\\-debug"):
        assert opt in root
    for code in ("0", "1", "2", "70"):
        assert f".TP\n\\fB{code}\\fR\n" in root
    # SPEC §3: the JSON keys are documented in the man page
    for key in ("mass", "com", "reference", "inertia", "inertia_com", "axis_moment", "angular_momentum"):
        assert f"\\fB{key}" in PAGES["rbcli-inertia.1"] or f", {key}" in PAGES["rbcli-inertia.1"]
    for key in ("moments", "axes", "symmetry", "stable"):
        assert f"\\fB{key}\\fR" in PAGES["rbcli-principal.1"]


@pytest.mark.skipif(shutil.which("man") is None, reason="the man program is not installed")
@pytest.mark.parametrize("name", sorted(PAGES))
def test_man_renders_the_page(name):
    env = {**os.environ, "MANWIDTH": "80", "MANPAGER": "cat", "PAGER": "cat"}
    r = subprocess.run(["man", "-l", str(MAN / name)], capture_output=True, text=True, env=env, timeout=60)
    assert r.returncode == 0, r.stderr
    assert "EXIT STATUS" in r.stdout and "SYNOPSIS" in r.stdout
    assert "warning" not in r.stderr.lower(), r.stderr
