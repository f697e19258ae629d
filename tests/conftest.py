"""Fixtures every test module may use: run the command line in-process or as a process.

``cli("inertia", "examples/cube.yaml", "--json")`` runs ``rbcli`` in-process through
:func:`rbcli.cli.main` (so the error-to-exit-code map is included) as a script would see
it: standard output not a terminal, no colour, 100 columns, working directory the
repository root unless ``cwd`` is given. ``env`` adds or removes (value None) environment
variables for the run; ``input`` is standard input (text or bytes).

``cli_proc(...)`` runs ``python -m rbcli`` as a real process, for what only a process
shows: exit codes through the interpreter, signals, closed or full streams, start-up.

Both return a :class:`Run` with ``code``, ``out``, ``err`` and ``json()``.
"""

from __future__ import annotations

import contextlib
import io
import json
import os
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

# Pin OpenBLAS's kernel before numpy is first imported (here or in a child process): the
# golden outputs are exact to the last digit, and OpenBLAS picks its kernels by CPU (the 3x3
# products of an Intel AVX-512 machine and an AMD one differ in the last bit). Haswell's
# kernels (AVX2+FMA) run on every x86-64 machine this suite is run on; a user's choice stands.
from tests_blas import pin_blas_kernel  # noqa: E402

pin_blas_kernel()

import pytest  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"


@dataclass(frozen=True)
class Run:
    code: int
    out: str
    err: str

    def json(self):
        """The JSON document on standard output (a list for JSON Lines)."""
        lines = self.out.splitlines()
        if len(lines) > 1 and all(line.startswith("{") and line.endswith("}") for line in lines):
            return [json.loads(line) for line in lines]
        return json.loads(self.out)


_PLAIN = {"COLUMNS": "100", "NO_COLOR": "1", "TERM": None, "RBCLI_DEBUG": None}


def run_inprocess(*args: str, input: str | bytes | None = None, env: dict | None = None,
                  cwd: str | os.PathLike | None = None) -> Run:
    """Run ``rbcli ARGS`` in this process; see the module docstring."""
    from rbcli.cli import main

    changes = {**_PLAIN, **(env or {})}
    saved = {k: os.environ.get(k) for k in changes}
    old_cwd, old_stdin = os.getcwd(), sys.stdin
    out, err = io.StringIO(), io.StringIO()
    for k, v in changes.items():
        if v is None:
            os.environ.pop(k, None)
        else:
            os.environ[k] = v
    if input is not None:
        data = input.encode() if isinstance(input, str) else input
        sys.stdin = io.TextIOWrapper(io.BytesIO(data), encoding="utf-8")
    os.chdir(cwd if cwd is not None else ROOT)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            try:
                main([str(a) for a in args])
                code = 0
            except SystemExit as exc:
                code = 0 if exc.code is None else int(exc.code)
    finally:
        os.chdir(old_cwd)
        sys.stdin = old_stdin
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v
    return Run(code, out.getvalue(), err.getvalue())


def run_process(*args: str, input: str | bytes | None = None, env: dict | None = None,
                cwd: str | os.PathLike | None = None, timeout: float = 120) -> Run:
    """Run ``python -m rbcli ARGS`` as a process; see the module docstring."""
    full = dict(os.environ)
    for k, v in {**_PLAIN, **(env or {})}.items():
        if v is None:
            full.pop(k, None)
        else:
            full[k] = v
    full["PYTHONPATH"] = os.pathsep.join([str(ROOT), full.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    p = subprocess.run([sys.executable, "-m", "rbcli", *[str(a) for a in args]],
                       input=input.encode() if isinstance(input, str) else input,
                       capture_output=True, cwd=cwd if cwd is not None else ROOT,
                       env=full, timeout=timeout)
    return Run(p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace"))


@pytest.fixture
def cli():
    """Run rbcli in-process: ``cli(*args, input=None, env=None, cwd=None) -> Run``."""
    return run_inprocess


@pytest.fixture
def cli_proc():
    """Run rbcli as a process: ``cli_proc(*args, input=None, env=None, cwd=None, timeout=120)``."""
    return run_process


def as_cli(data):
    """A result's ``to_json()`` as the command's ``--json`` prints it: its remarks and warnings
    name options (``--radius``) where the API names parameters (``radius``)."""
    from rbcli.errors import option_name, spelled_data

    return spelled_data(data, option_name)
