"""Shell completion: ``rbcli --show-completion SHELL`` prints a script that works.

The bash test runs the real script in bash (the script calls ``rbcli`` back with the
words typed so far, as a shell would) and reads COMPREPLY; zsh and fish are driven
through the same protocol their scripts use (``_RBCLI_COMPLETE=complete_zsh`` /
``complete_fish``), since those shells may not be installed.
"""

from __future__ import annotations

import os
import shutil
import stat
import subprocess
import sys

import pytest

from conftest import ROOT


@pytest.fixture
def path_with_rbcli(tmp_path):
    """A PATH whose ``rbcli`` runs this checkout's rbcli."""
    exe = tmp_path / "rbcli"
    exe.write_text(f"#!/bin/sh\nPYTHONPATH={ROOT} exec {sys.executable} -m rbcli \"$@\"\n")
    exe.chmod(exe.stat().st_mode | stat.S_IXUSR)
    return f"{tmp_path}{os.pathsep}{os.environ.get('PATH', '')}"


def _complete_bash(path: str, words: list[str], cwd) -> list[str]:
    script = subprocess.run([sys.executable, "-m", "rbcli", "--show-completion", "bash"],
                            capture_output=True, text=True, cwd=ROOT, check=True).stdout
    cword = len(words) - 1
    quoted = " ".join(f"'{w}'" for w in words)
    prog = (f"{script}\nCOMP_WORDS=({quoted}); COMP_CWORD={cword}; _rbcli_completion rbcli; "
            'printf "%s\\n" "${COMPREPLY[@]}"')
    env = {**os.environ, "PATH": path}
    r = subprocess.run(["bash", "-c", prog], capture_output=True, text=True, env=env, cwd=cwd,
                       timeout=60)
    assert r.returncode == 0, r.stderr
    return [w for w in r.stdout.splitlines() if w]


@pytest.mark.skipif(shutil.which("bash") is None, reason="bash is not installed")
def test_bash_completes_commands_and_options(path_with_rbcli):
    assert _complete_bash(path_with_rbcli, ["rbcli", "pr"], ROOT) == ["principal", "precess"]
    assert _complete_bash(path_with_rbcli, ["rbcli", "inertia", "--ax"], ROOT) == ["--axis"]
    opts = _complete_bash(path_with_rbcli, ["rbcli", "balance", "x.yaml", "--"], ROOT)
    assert {"--planes", "--radius", "--grade", "--json"} <= set(opts)


@pytest.mark.skipif(shutil.which("bash") is None, reason="bash is not installed")
def test_bash_falls_back_to_file_names_for_body(path_with_rbcli):
    # rbcli offers nothing for BODY, and the script's `complete -o default` lets bash offer
    # file names; the script must say so, and rbcli must offer no words of its own there
    script = subprocess.run([sys.executable, "-m", "rbcli", "--show-completion", "bash"],
                            capture_output=True, text=True, cwd=ROOT, check=True).stdout
    assert "complete -o default -F _rbcli_completion rbcli" in script
    assert _complete_bash(path_with_rbcli, ["rbcli", "inertia", "exam"], ROOT) == []


def test_zsh_and_fish_protocols(cli_proc):
    env = {"_RBCLI_COMPLETE": "complete_zsh", "_TYPER_COMPLETE_ARGS": "rbcli inertia --ax"}
    r = cli_proc(env=env)
    assert r.code == 0 and '"--axis"' in r.out
    env = {"_RBCLI_COMPLETE": "complete_zsh", "_TYPER_COMPLETE_ARGS": "rbcli inertia "}
    assert cli_proc(env=env).out.strip() == "_files"  # zsh completes file names for BODY
    env = {"_RBCLI_COMPLETE": "complete_fish", "_TYPER_COMPLETE_FISH_ACTION": "get-args",
           "_TYPER_COMPLETE_ARGS": "rbcli roll"}
    assert cli_proc(env=env).out.split("\t")[0].strip() == "rollcheck"


@pytest.mark.parametrize("shell", ["bash", "zsh", "fish", "powershell"])
def test_show_completion_prints_the_script_for_that_shell(cli, shell):
    r = cli("--show-completion", shell)
    assert r.code == 0
    assert "_RBCLI_COMPLETE" in r.out and "rbcli" in r.out


def test_unknown_shell_is_one_line_exit_2(cli):
    r = cli("--show-completion", "tcsh")
    assert r.code == 2
    assert r.err.count("\n") == 1 and "tcsh" in r.err and "bash" in r.err
