"""SIGINT, SIGTERM and SIGHUP at any moment (issue 27, item 2), sent to real processes.

Each run starts rbcli as a process (``cli_proc.start``: ``python -m rbcli`` or the ``rbcli``
console script), waits until rbcli's handlers are in place — ``/proc/PID/status`` lists
SIGHUP and SIGALRM among the caught signals (``SigCgt``), which :func:`rbcli.interrupts.install`
sets before anything else is imported — then sleeps a delay and sends the signal. The
contract from that moment on:

- exit status 128 + the signal (130, 143, 129) and standard error exactly the one line
  ``rbcli: interrupted by SIGINT`` (no traceback, no "Exception ignored", no "Fatal Python
  error", never 70, never killed by the signal or aborted: -2, -6);
- or, when the run had finished its work before the signal, exit 0 with the output of an
  uninterrupted run;
- the output file is absent or byte for byte what an uninterrupted run writes (outputs are
  deterministic), and no temporary ``.rbcli-*`` file is left.

The delays are fractions of the run's own length, measured by an uninterrupted reference run
on this machine (so a loaded machine moves the delays with the run), up to past its end. By
default one or two moments per command, every signal used; ``pytest -m slow`` sweeps 40
fractions for every signal and command (``inertia``, ``top --plot``, ``report -o``, and
``inertia`` of a 5 MB ASCII OBJ mesh, whose reading is the long step).
``RBCLI_SIGNAL_TALLY=FILE`` appends each run's outcome (command, signal, delay, exit
status, files left) to FILE.

Before rbcli's first line runs, the interpreter is starting (its own initialisation, ``site``,
then the console script's ``import re`` or ``python -m``'s runpy): no rbcli code can act
there, and a signal gets the interpreter's own answer — SIGTERM and SIGHUP end the process
(exit -15, -1: what a shell shows as 143 and 129, no message); SIGINT is Python's
KeyboardInterrupt, a short traceback (exit -2) or, inside ``site`` or runpy, "Fatal Python
error: init_import_site" or "Could not import runpy module" (exit 1). :func:`test_from_the_first_instant` sends signals from the spawn
on and holds those runs to what must hold anyway: no exit 70, no native abort, no file.
"""

from __future__ import annotations

import os
import signal
import subprocess
import time
from pathlib import Path

import numpy as np
import pytest

from conftest import EXAMPLES, SCRIPT

pytestmark = pytest.mark.skipif(not Path("/proc/self/status").exists(),
                                reason="needs /proc/PID/status to see when rbcli's handlers are in place")

SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)
#: the signals rbcli.interrupts.install catches last (SIGALRM: the deferral timer)
_READY_MASK = (1 << (signal.SIGHUP - 1)) | (1 << (signal.SIGALRM - 1)) | (1 << (signal.SIGTERM - 1))

TOP = str(EXAMPLES / "top.yaml")
#: a fixed report date, so that every run writes the same bytes
ENV = {"SOURCE_DATE_EPOCH": "1700000000"}


def _torus_obj(path: Path, n: int = 400, m: int = 200, R: float = 2.0, r: float = 0.5) -> None:
    """A closed n x m quad mesh of a torus as ASCII OBJ (about 5 MB for 400 x 200)."""
    u = np.linspace(0, 2 * np.pi, n, endpoint=False)[:, None]
    w = np.linspace(0, 2 * np.pi, m, endpoint=False)[None, :]
    V = np.stack([(R + r * np.cos(w)) * np.cos(u), (R + r * np.cos(w)) * np.sin(u),
                  r * np.sin(w) + 0 * u], -1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(n), np.arange(m), indexing="ij")

    def k(a, b):
        return (a % n) * m + (b % m) + 1

    F = np.stack([k(i, j), k(i + 1, j), k(i + 1, j + 1), k(i, j + 1)], -1).reshape(-1, 4)
    with open(path, "w") as f:
        np.savetxt(f, V, fmt="v %.9f %.9f %.9f")
        np.savetxt(f, F, fmt="f %d %d %d %d")


@pytest.fixture(scope="module")
def inputs(tmp_path_factory) -> Path:
    d = tmp_path_factory.mktemp("signal-inputs")
    _torus_obj(d / "torus.obj")
    (d / "torus.yaml").write_text("name: torus\nparts:\n  - name: ring\n    shape: mesh\n"
                                  "    file: torus.obj\n    density: 1000\n")
    return d


#: name -> (arguments, the output file in the working folder or None for standard output)
CASES = {
    "inertia": (("inertia", TOP, "--json"), None),
    "mesh": (("inertia", "{inputs}/torus.yaml", "--json"), None),
    "top": (("top", TOP, "--spin", "150", "--theta", "30", "--plot", "t.png"), "t.png"),
    "report": (("report", TOP, "-o", "r.html", "--spin", "150", "--theta", "30"), "r.html"),
}


def _args(name: str, inputs: Path) -> list[str]:
    return [a.replace("{inputs}", str(inputs)) for a in CASES[name][0]]


def _handlers_in_place(pid: int, mask: int = _READY_MASK) -> bool:
    """Whether rbcli's handlers (``mask``) are installed in process ``pid`` (True once it
    has ended)."""
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("SigCgt:"):
                    return int(line.split()[1], 16) & mask == mask
    except OSError:  # gone
        return True
    return False


def _signal_run(cli_proc, args, cwd, sig, delay, *, script=False, after_ready=True):
    """Start rbcli, wait for its handlers (unless not ``after_ready``), sleep ``delay``,
    send ``sig``; (Run, whether the handlers were in place when it was sent, elapsed s)."""
    p = cli_proc.start(*args, cwd=cwd, script=script, env=ENV)
    t0 = time.monotonic()
    if after_ready:
        while not _handlers_in_place(p.pid) and p.poll() is None:
            if time.monotonic() - t0 > 60:
                p.kill()
                pytest.fail("rbcli's signal handlers never appeared in /proc/PID/status")
            time.sleep(0.0005)
    t1 = time.monotonic()
    try:
        p.wait(timeout=delay)  # the run may end first: then there is nothing to send
    except subprocess.TimeoutExpired:
        pass
    ready = _handlers_in_place(p.pid)
    if p.poll() is None:
        p.send_signal(sig)
    r = cli_proc.finish(p)
    return r, ready, time.monotonic() - t1


@pytest.fixture(scope="module")
def reference(cli_proc, inputs, tmp_path_factory):
    """Uninterrupted runs, on first use: ``reference(name, runs=1) -> (Run, output bytes or
    None, seconds from the handlers being in place to the end)``; the time is the least of
    ``runs`` runs (a sweep asks for three: one run slowed by a busy moment would stretch
    every delay)."""
    out: dict = {}

    def get(name, runs=1):
        while len(out.get(name, ())) < runs:
            cwd = tmp_path_factory.mktemp(f"ref-{name}")
            r, _, took = _signal_run(cli_proc, _args(name, inputs), cwd, 0, 0.0)  # 0: no signal
            assert r.code == 0, r.err
            target = CASES[name][1]
            data = (cwd / target).read_bytes() if target else None
            out.setdefault(name, []).append((r, data, took))
            assert data == out[name][0][1] and r.out == out[name][0][0].out  # deterministic
        first = out[name][0]
        return first[0], first[1], min(t for _, _, t in out[name])

    return get


def _check(name, r, cwd: Path, sig: int, ready: bool, ref, where: str) -> None:
    ref_run, ref_data, _ = ref
    target = CASES[name][1]
    names = sorted(os.listdir(cwd))
    assert not [n for n in names if n.startswith(".rbcli-")], (where, names)
    assert names in ([], [target] if target else []), (where, names)
    if target and names:
        assert (cwd / target).read_bytes() == ref_data, f"{where}: {target} differs from an uninterrupted run's"
    if not ready:  # the interpreter's own start-up (module docstring)
        # SIGINT while the interpreter imports site or runpy: its own message, exit 1
        interpreter = ("Fatal Python error: init_import_site", "Could not import runpy module")
        assert r.code in (-sig, 128 + sig) or (sig == signal.SIGINT and r.code == 1 and any(
            m in r.err for m in interpreter)), (where, r.code, r.err)
        assert names == [], (where, names)
        return
    line = f"rbcli: interrupted by {signal.Signals(sig).name}\n"
    if r.code == 0:  # the run finished first
        assert r.err == ref_run.err, (where, r.err)
        assert target or r.out == ref_run.out, where
        assert not target or names == [target], (where, names)
    else:
        assert r.code == 128 + sig, (where, r.code, r.err[-2000:])
        assert r.err == line, (where, r.err[-2000:])


def _sweep(cli_proc, tmp_path, inputs, reference, name, plan, after_ready=True):
    """Run ``name`` once per (delay in s, signal) of ``plan`` and check each run."""
    ref = reference(name)
    for i, (delay, sig) in enumerate(plan):
        cwd = tmp_path / f"{name}-{i}"
        cwd.mkdir()
        script = bool(i % 2) and SCRIPT.exists()  # the console script and python -m in turn
        r, ready, _ = _signal_run(cli_proc, _args(name, inputs), cwd, sig, delay,
                                  script=script, after_ready=after_ready)
        where = (f"{name} {signal.Signals(sig).name} after {delay * 1e3:.1f} ms "
                 f"{'after the handlers' if after_ready else 'from the spawn'} "
                 f"({'rbcli' if script else 'python -m rbcli'})")
        _check(name, r, cwd, sig, ready, ref, where)
        if os.environ.get("RBCLI_SIGNAL_TALLY"):  # a record of the outcomes, for reports
            with open(os.environ["RBCLI_SIGNAL_TALLY"], "a") as f:
                f.write(f"{name} {signal.Signals(sig).name} {'ready' if ready else 'start'} "
                        f"{delay:.4f} {r.code} {sorted(os.listdir(cwd))}\n")


def _fractions(reference, name, plan, runs=1):
    """``plan`` with each fraction of the run's length (reference run) made seconds."""
    took = reference(name, runs)[2]
    return [(f * took, sig) for f, sig in plan]


# -------------------------------------------------------------------------- default: a sample


#: by default, per command: (fraction of the run's length, signal) — report early (while
#: matplotlib is imported: where exit 70 and the native aborts were) and late (figures being
#: written), the others once each, every signal used
SAMPLE = {
    "inertia": [(0.5, signal.SIGHUP)],
    "mesh": [(0.5, signal.SIGTERM)],
    "top": [(0.3, signal.SIGINT)],
    "report": [(0.04, signal.SIGINT), (0.7, signal.SIGTERM)],
}


@pytest.mark.parametrize("name", list(CASES))
def test_a_signal_at_a_few_moments(cli_proc, tmp_path, inputs, reference, name):
    _sweep(cli_proc, tmp_path, inputs, reference, name, _fractions(reference, name, SAMPLE[name]))


def test_from_the_first_instant(cli_proc, tmp_path, inputs, reference):
    # from the spawn: the first few tens of ms are the interpreter's own start-up
    plan = [(0.0, signal.SIGINT), (0.02, signal.SIGTERM), (0.06, signal.SIGINT)]
    _sweep(cli_proc, tmp_path, inputs, reference, "report", plan, after_ready=False)


def test_a_second_signal_during_the_cleanup_changes_nothing(cli_proc, tmp_path, reference):
    # SIGINT, then SIGTERM 2 ms later while the first is being handled: the first decides
    ref = reference("report")
    p = cli_proc.start(*_args("report", tmp_path), cwd=tmp_path, env=ENV)
    while not _handlers_in_place(p.pid):
        time.sleep(0.0005)
    time.sleep(0.5 * ref[2])
    assert p.poll() is None, "the run ended before the signal: nothing tested"
    p.send_signal(signal.SIGINT)
    time.sleep(0.002)
    if p.poll() is None:
        p.send_signal(signal.SIGTERM)
    r = cli_proc.finish(p)
    assert (r.code, r.err) in ((130, "rbcli: interrupted by SIGINT\n"), (0, "")), r
    assert sorted(os.listdir(tmp_path)) in ([], ["r.html"])


def test_an_ignored_signal_stays_ignored(cli_proc, tmp_path, inputs, reference):
    # nohup (SIGHUP ignored from the start): rbcli leaves it ignored and the run goes on
    ref = reference("mesh")
    p = cli_proc.start(*_args("mesh", inputs), cwd=tmp_path, ignore=(signal.SIGHUP,), env=ENV)
    others = _READY_MASK & ~(1 << (signal.SIGHUP - 1))
    while not _handlers_in_place(p.pid, others):
        time.sleep(0.0005)
    time.sleep(0.5 * ref[2])
    assert p.poll() is None, "the run ended before the signal: nothing tested"
    p.send_signal(signal.SIGHUP)
    r = cli_proc.finish(p)
    assert (r.code, r.err, r.out) == (0, "", ref[0].out), r


# -------------------------------------------------------------------------- -m slow: the sweep


@pytest.mark.slow
@pytest.mark.parametrize("sig", SIGNALS, ids=lambda s: signal.Signals(s).name)
@pytest.mark.parametrize("name", list(CASES))
def test_a_signal_at_any_moment(cli_proc, tmp_path, inputs, reference, name, sig):
    plan = [(f, sig) for f in np.linspace(0.0, 1.1, 40)]
    _sweep(cli_proc, tmp_path, inputs, reference, name, _fractions(reference, name, plan, runs=3))


@pytest.mark.slow
@pytest.mark.parametrize("sig", SIGNALS, ids=lambda s: signal.Signals(s).name)
def test_from_the_first_instant_swept(cli_proc, tmp_path, inputs, reference, sig):
    plan = [(d, sig) for d in np.arange(0.0, 0.15, 0.003)]
    _sweep(cli_proc, tmp_path, inputs, reference, "inertia", plan, after_ready=False)
