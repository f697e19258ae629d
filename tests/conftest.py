"""Fixtures every test module may use: run the command line in-process or as a process.

``cli("inertia", "examples/cube.yaml", "--json")`` runs ``rbcli`` in-process through
:func:`rbcli.cli.main` (so the error-to-exit-code map is included) as a script would see
it: standard output not a terminal, no colour, 100 columns, working directory the
repository root unless ``cwd`` is given. ``env`` adds or removes (value None) environment
variables for the run; ``input`` is standard input (text or bytes).

``cli_proc(...)`` runs ``python -m rbcli`` as a real process, for what only a process
shows: exit codes through the interpreter, signals, closed or full streams (``redirect=">&-"``),
a terminal (``tty=True``), the modules a run imports (``imports=True``), the console script
(``script=True``). ``cli_proc.start(...)`` starts one and returns the ``Popen`` at once (to
signal it while it runs, or read a little and go away); ``cli_proc.finish(p)`` waits for it
and gives its Run.

Both return a :class:`Run` with ``code``, ``out``, ``err`` and ``json()``
(``code, out, err = cli(...)`` unpacks it). Use them for every test of the command line;
a test that starts a process another way says why.
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
from typing import ClassVar

# Pin OpenBLAS's kernel before numpy is first imported (here or in a child process): the
# golden outputs are exact to the last digit, and OpenBLAS picks its kernels by CPU (the 3x3
# products of an Intel AVX-512 machine and an AMD one differ in the last bit). Haswell's
# kernels (AVX2+FMA) run on every x86-64 machine this suite is run on; a user's choice stands.
from tests_blas import pin_blas_kernel  # noqa: E402

pin_blas_kernel()

import pytest  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"


@pytest.fixture(autouse=True, scope="session")
def _signals_as_from_a_terminal():
    """Child processes start with the default action of SIGINT, SIGTERM and SIGHUP, as
    from a terminal, even when pytest itself was started with one ignored: a background
    job of a non-interactive shell (``.ci/run &``) ignores SIGINT, ``nohup`` SIGHUP, and a
    child inherits an ignored signal (rbcli keeps it ignored, as it should), so the
    signal tests would see no signal. A handler set here becomes the default in a child."""
    import signal

    saved = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)}
    for s, h in saved.items():
        if h == signal.SIG_IGN:
            signal.signal(s, signal.default_int_handler if s == signal.SIGINT else signal.SIG_DFL)
    yield
    for s, h in saved.items():
        if h is not None:
            signal.signal(s, h)

# ----------------------------------------------------------------------------- sampled tests
# The default run (`pytest`: -m 'not slow') samples the exhaustive tests: an oracle compared
# over fewer random cases, a figure or a report rendered for a few examples. `pytest -m slow`
# runs them in full (and the tests marked slow); `pytest -m ''` runs everything in full.
# A sampled test carries @pytest.mark.sampled and takes its sizes from sample(); a
# parametrized one lists its values through sampled_params(). Either way every test can
# still fail by default, on the sample.

#: whether this run is the full one (set from -m in pytest_configure, before the test
#: modules are imported, so that decorators such as hypothesis' @settings can read it)
FULL = False


def _selects_slow(markexpr: str) -> bool:
    """Whether ``-m markexpr`` selects a test marked slow."""
    if not markexpr.strip():
        return True
    try:
        from _pytest.mark.expression import Expression

        return bool(Expression.compile(markexpr).evaluate(lambda name, **_: name in ("slow", "sampled")))
    except Exception:  # noqa: BLE001 - another pytest: read the expression plainly
        return "slow" in markexpr and "not slow" not in markexpr


def pytest_configure(config) -> None:
    global FULL
    FULL = _selects_slow(config.getoption("markexpr") or "")
    # Hypothesis: the default run (CI's) draws the same examples every time, so that it passes
    # or fails on the code alone, never on the draw (a rare counterexample found by a random
    # draw made CI fail at random); the full run (-m slow) and RBCLI_HYPOTHESIS=explore draw
    # new examples, as hypothesis does by default, to look for them.
    from hypothesis import settings

    settings.register_profile("ci", derandomize=True)
    settings.register_profile("explore")
    explore = FULL or os.environ.get("RBCLI_HYPOTHESIS") == "explore"
    settings.load_profile("explore" if explore else "ci")


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(config, items) -> None:
    """A sampled test is part of the full run: under -m slow it runs (in full) too."""
    if FULL:
        for item in items:
            if item.get_closest_marker("sampled"):
                item.add_marker(pytest.mark.slow)


def sample(sample_value, full_value):
    """``full_value`` in the full run (``-m slow``), else ``sample_value`` (mark the test
    ``@pytest.mark.sampled``)."""
    return full_value if FULL else sample_value


def sampled_params(values, keep, ids=None, multi: bool = False) -> list:
    """Parameters for ``@pytest.mark.parametrize``: the values at the indices ``keep`` run
    by default and in the full run, the others only in the full run (marked slow).
    ``keep`` may be a function of the value instead; ``ids``: a list or a function of the
    value; ``multi``: each value is a tuple of several arguments."""
    values = list(values)
    kept = {i for i, v in enumerate(values) if keep(v)} if callable(keep) else set(keep)
    out = []
    for i, v in enumerate(values):
        marks = pytest.mark.sampled if i in kept else pytest.mark.slow
        pid = ids(v) if callable(ids) else ids[i] if ids is not None else None
        out.append(pytest.param(*(v if multi else (v,)), marks=marks, id=pid))
    return out


@dataclass(frozen=True)
class Run:
    """A finished run: exit status, standard output and standard error (text).
    ``code, out, err = cli(...)`` unpacks it."""

    code: int
    out: str
    err: str
    #: the modules a process imported (``cli_proc(..., imports=True)``; not a field, so
    #: ``dataclasses.astuple(run)`` stays (code, out, err))
    imported: ClassVar[frozenset] = frozenset()

    def __iter__(self):
        return iter((self.code, self.out, self.err))

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
            code = main([str(a) for a in args])
    finally:
        os.chdir(old_cwd)
        sys.stdin = old_stdin
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v
    assert type(code) is int, f"main() returned {code!r}, not an exit status"
    return Run(code, out.getvalue(), err.getvalue())


#: the ``rbcli`` console script beside this interpreter (pip writes it), if installed
SCRIPT = Path(sys.executable).with_name("rbcli")


_PYCACHE: list[str] = []


def _pycache() -> str:
    """A private bytecode cache for the processes this session starts, removed at its end.

    Each ``python -m rbcli`` would otherwise compile rbcli's modules from source again when
    bytecode is not written (``PYTHONDONTWRITEBYTECODE``, as on the machines this suite
    runs on: ~50 ms of every process, ~0.1 s with figures); the first process writes them
    here and the others read them. Nothing is written into the source tree.
    """
    if not _PYCACHE:
        import atexit
        import shutil
        import tempfile

        _PYCACHE.append(tempfile.mkdtemp(prefix="rbcli-test-pycache-"))
        atexit.register(shutil.rmtree, _PYCACHE[0], True)
    return _PYCACHE[0]


def _process_env(env: dict | None) -> dict:
    full = dict(os.environ)
    full.pop("PYTHONDONTWRITEBYTECODE", None)
    full["PYTHONPYCACHEPREFIX"] = _pycache()
    for k, v in {**_PLAIN, **(env or {})}.items():
        if v is None:
            full.pop(k, None)
        else:
            full[k] = v
    full["PYTHONPATH"] = os.pathsep.join([str(ROOT), full.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    return full


#: ``python -c`` program for ``imports=True``: rbcli's own entry point, after an atexit
#: function (rbcli's exit runs them) that writes the modules the run imported to a file
_WITH_IMPORTS = (
    "import atexit, sys\n"
    "def _dump(path=sys.argv.pop(1)):\n"
    "    with open(path, 'w') as f:\n"
    "        f.write('\\n'.join(sorted(sys.modules)))\n"
    "atexit.register(_dump)\n"
    "from rbcli.__main__ import main\n"
    "main()\n"
)


def _command(args, script: bool, imports: str | None = None) -> list[str]:
    if script and not SCRIPT.exists():
        pytest.skip(f"no console script {SCRIPT} (rbcli is not installed in this interpreter)")
    if script:
        head = [str(SCRIPT)]
    elif imports:
        head = [sys.executable, "-c", _WITH_IMPORTS, imports]
    else:
        head = [sys.executable, "-m", "rbcli"]
    return [*head, *[str(a) for a in args]]


def _read_tty(cmd: list[str], cwd, env: dict, timeout: float) -> tuple[int, bytes]:
    """Run ``cmd`` with standard output on a new pseudo-terminal; (status, what it showed)."""
    import pty
    import select
    import time

    master, slave = pty.openpty()
    p = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=slave, stderr=subprocess.DEVNULL,
                         cwd=cwd, env=env)
    os.close(slave)
    chunks, end = [], time.monotonic() + timeout
    try:
        while time.monotonic() < end:
            if not select.select([master], [], [], 0.5)[0]:
                if p.poll() is not None:
                    break
                continue
            try:
                data = os.read(master, 65536)
            except OSError:  # EIO once the child has closed the terminal
                break
            if not data:
                break
            chunks.append(data)
        return p.wait(timeout=max(1.0, end - time.monotonic())), b"".join(chunks)
    finally:
        os.close(master)


def run_process(*args: str, input: str | bytes | None = None, env: dict | None = None,
                cwd: str | os.PathLike | None = None, timeout: float = 120,
                script: bool = False, imports: bool = False, tty: bool = False,
                redirect: str = "") -> Run:
    """Run ``python -m rbcli ARGS`` as a process; see the module docstring.

    ``script=True``: the ``rbcli`` console script instead. ``imports=True``: ``Run.imported``
    is the set of modules the run imported (``sys.modules`` when it ends). ``tty=True``: standard output is a pseudo-terminal
    (``out`` is what it showed; standard error is dropped). ``redirect``: shell
    redirections for ``sh -c`` (``">&-"``, ``"2>/dev/full"``, ``"| head -1"``): a stream
    redirected away reads as ''.
    """
    listing = None
    if imports:
        import tempfile

        fd, listing = tempfile.mkstemp(prefix="rbcli-modules-", suffix=".txt")
        os.close(fd)
    cmd = _command(args, script, listing)
    where = cwd if cwd is not None else ROOT
    full = _process_env(env)
    try:
        if tty:
            code, shown = _read_tty(cmd, where, full, timeout)
            return Run(code, shown.decode("utf-8", "replace"), "")
        if redirect:
            import shlex

            cmd = ["sh", "-c", " ".join(shlex.quote(c) for c in cmd) + " " + redirect]
        p = subprocess.run(cmd, input=input.encode() if isinstance(input, str) else input,
                           capture_output=True, cwd=where, env=full, timeout=timeout)
        run = Run(p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace"))
        if listing:
            object.__setattr__(run, "imported", frozenset(Path(listing).read_text().split()))
        return run
    finally:
        if listing:
            os.unlink(listing)


def start_process(*args: str, env: dict | None = None, cwd: str | os.PathLike | None = None,
                  script: bool = False, stdin=subprocess.DEVNULL,
                  ignore: tuple[int, ...] = ()) -> subprocess.Popen:
    """Start ``python -m rbcli ARGS`` (or the console script) and return at once, with
    standard output and error as pipes: for what happens *while* it runs (signals, a reader
    that goes away). ``ignore``: signals the process starts with ignored (as under ``nohup``)."""
    def ignored() -> None:
        import signal

        for signum in ignore:
            signal.signal(signum, signal.SIG_IGN)

    return subprocess.Popen(_command(args, script), stdin=stdin, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, cwd=cwd if cwd is not None else ROOT,
                            env=_process_env(env), preexec_fn=ignored if ignore else None)


def finish(p: subprocess.Popen, timeout: float = 120) -> Run:
    """Wait for a process of :func:`start_process`; its Run."""
    out, err = p.communicate(timeout=timeout)
    return Run(p.returncode, out.decode("utf-8", "replace"), err.decode("utf-8", "replace"))


run_process.start = start_process  # type: ignore[attr-defined]
run_process.finish = finish  # type: ignore[attr-defined]


@pytest.fixture(scope="session")
def cli():
    """Run rbcli in-process: ``cli(*args, input=None, env=None, cwd=None) -> Run``."""
    return run_inprocess


@pytest.fixture(scope="session")
def cli_proc():
    """Run rbcli as a process: ``cli_proc(*args, input=None, env=None, cwd=None, timeout=120,
    script=False, imports=False, tty=False, redirect="")``; ``cli_proc.start(...)`` /
    ``cli_proc.finish(p)``."""
    return run_process


def as_cli(data):
    """A result's ``to_json()`` as the command's ``--json`` prints it: its remarks and warnings
    name options (``--radius``) where the API names parameters (``radius``)."""
    from rbcli.errors import option_name, spelled_data

    return spelled_data(data, option_name)


# hsbalance (an optional oracle) for the field-balancing tests
@pytest.fixture
def hs(monkeypatch):
    """hsbalance, its cvxpy problems solved by CLARABEL (cvxpy's open-source default):
    cvxpy picks Xpress first where it is installed, whose community build changes the
    process's floating-point state (later golden outputs differ in their last digits)."""
    hsb = pytest.importorskip("hsbalance")
    import cvxpy

    solve = cvxpy.Problem.solve
    monkeypatch.setattr(cvxpy.Problem, "solve", lambda self, *a, **k: solve(self, *a, **{"solver": "CLARABEL", **k}))
    return hsb
