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


def _complete_bash(script: str, path: str, words: list[str], cwd) -> list[str]:
    # bash itself runs here (not rbcli): the script calls rbcli back, as a shell would
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
def test_bash_completes_commands_and_options(cli, path_with_rbcli):
    script = cli("--show-completion", "bash").out
    assert _complete_bash(script, path_with_rbcli, ["rbcli", "pr"], ROOT) == ["principal", "precess"]
    assert _complete_bash(script, path_with_rbcli, ["rbcli", "inertia", "--ax"], ROOT) == ["--axis"]
    opts = _complete_bash(script, path_with_rbcli, ["rbcli", "balance", "x.yaml", "--"], ROOT)
    assert {"--planes", "--radius", "--grade", "--json"} <= set(opts)


@pytest.mark.skipif(shutil.which("bash") is None, reason="bash is not installed")
def test_bash_falls_back_to_file_names_for_body(cli, path_with_rbcli):
    # rbcli offers nothing for BODY, and the script's `complete -o default` lets bash offer
    # file names; the script must say so, and rbcli must offer no words of its own there
    script = cli("--show-completion", "bash").out
    assert "complete -o default -F _rbcli_completion rbcli" in script
    assert _complete_bash(script, path_with_rbcli, ["rbcli", "inertia", "exam"], ROOT) == []


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


# ----------------------------------------------------------------------------- malformed state (issue 27)

BASH = {"_RBCLI_COMPLETE": "complete_bash", "COMP_WORDS": "rbcli pr"}


@pytest.mark.parametrize("cword", ["", "x", "-1", "1.5", "1e3", " 1", "1_0", "\u0663", "3",
                                   "9" * 5000, "99999999"])
def test_a_malformed_comp_cword_gives_no_candidates(cli, cword):
    # was an internal error (exit 70): int('x'), an index beyond the words, 5000 digits
    r = cli(env={**BASH, "COMP_CWORD": cword})
    assert (r.code, r.out, r.err) == (0, "", "")


def test_missing_completion_variables_give_no_candidates(cli):
    assert tuple(cli(env={**BASH, "COMP_CWORD": None})) == (0, "", "")
    assert tuple(cli(env={**BASH, "COMP_WORDS": None, "COMP_CWORD": "1"})) == (0, "", "")
    # the check can fail: the same request well formed is answered
    assert cli(env={**BASH, "COMP_CWORD": "1"}).out.split() == ["principal", "precess"]
    assert cli(env={**BASH, "COMP_CWORD": "2"}).out.split()[:2] == ["inertia", "principal"]


def test_other_shells_with_missing_variables_answer(cli):
    for shell in ("zsh", "fish", "powershell"):
        r = cli(env={"_RBCLI_COMPLETE": f"complete_{shell}", "_TYPER_COMPLETE_ARGS": None,
                     "_TYPER_COMPLETE_WORD_TO_COMPLETE": None, "_TYPER_COMPLETE_FISH_ACTION": None})
        assert r.code == 0 and "internal error" not in r.err, (shell, r)


def test_completing_after_an_eager_option_runs_nothing(cli, tmp_path):
    # `rbcli --install-completion bash <TAB>` wrote into ~/.bashrc; --version printed itself
    home = tmp_path / "home"
    home.mkdir()
    for words in ("rbcli --install-completion bash ", "rbcli --show-completion bash ", "rbcli --version "):
        r = cli(env={**BASH, "COMP_WORDS": words, "COMP_CWORD": str(len(words.split())), "HOME": str(home)})
        assert r.code == 0 and "inertia" in r.out.split(), (words, r)
        assert "rbcli 0" not in r.out and "_rbcli_completion" not in r.out and "installed" not in r.out
    assert list(home.iterdir()) == []
