"""A document and its figures folder replaced whole or not at all (issue 34 item 1).

``rbcli report -o r.md --force``, ``write_report(..., force=True)`` and ``field-balance
--report s.md --force`` over an old report: whatever signal arrives, whenever, and whatever
step of the commit fails, the folder holds either the old document and the old figures or
the new document and the new figures (never the new document beside no figures: the bug
was a signal held during the final renames, re-raised inside the writer's ``try``, whose
handler removed the folder it had just put in place), and no temporary ``.rbcli-*`` entry.

Deterministically, a hook (``rbcli.io.outfile._step``) puts a real signal or a failure at
every step of the commit; then real processes get SIGINT and SIGTERM at staggered moments
(a sample by default, the sweep under ``-m slow``).
"""

from __future__ import annotations

import os
import signal
import time
from pathlib import Path

import numpy as np
import pytest

import rbcli
from conftest import EXAMPLES, sampled_params
from rbcli.errors import InputError
from rbcli.interrupts import Terminated
from rbcli.io import outfile

#: the steps of the commit (rbcli.io.outfile._swap) and the cleanup after it
STEPS = ("aside", "place", "commit", "clean")
#: a fixed report date: every run writes the same bytes
ENV = {"SOURCE_DATE_EPOCH": "1700000000"}
TOP = str(EXAMPLES / "top.yaml")
FAN = str(EXAMPLES / "jobs" / "fan.yaml")
#: name -> (the command line, the document it writes)
COMMANDS = {
    "report": (("report", TOP, "-o", "r.md", "--spin", "150", "--theta", "30", "--force"), "r.md"),
    "field-balance": (("field-balance", FAN, "--report", "s.md", "--force"), "s.md"),
}


def state(folder: Path) -> dict[str, bytes]:
    """Every file under ``folder`` (relative path -> bytes); a temporary entry fails."""
    out = {}
    for p in sorted(folder.rglob("*")):
        assert not p.name.startswith(".rbcli-"), f"left behind: {p.relative_to(folder)}"
        if p.is_file():
            out[str(p.relative_to(folder))] = p.read_bytes()
    return out


def plant_old(folder: Path, doc: str, new: dict[str, bytes]) -> dict[str, bytes]:
    """An old document and figures folder: the new run's figure names with other bytes, and
    one figure the new run does not write (a mix of old and new cannot pass for either)."""
    files = folder / (Path(doc).stem + "_files")
    files.mkdir(parents=True)
    (folder / doc).write_text("the old report\n")
    for name in new:
        if name.startswith(files.name + "/"):
            (folder / name).write_bytes(b"old " + name.encode())
    (files / "stale.svg").write_text("<svg>old</svg>")
    return state(folder)


class Hook:
    """At step ``at`` of the commit: send ``what`` (a signal to this process, held off by
    the writer and delivered when its block ends) or raise it (a failure)."""

    def __init__(self, at: str, what):
        self.at, self.what, self.seen = at, what, []

    def __call__(self, name: str) -> None:
        self.seen.append(name)
        if name != self.at:
            return
        if isinstance(self.what, int):
            signal.raise_signal(self.what)
        else:
            raise self.what


@pytest.fixture
def handlers():
    """SIGINT raises KeyboardInterrupt, SIGTERM Terminated (as rbcli's command line has
    them), for the test; the handlers before are put back."""
    def term(signum, frame):
        raise Terminated(signum)

    old = {signal.SIGINT: signal.signal(signal.SIGINT, signal.default_int_handler),
           signal.SIGTERM: signal.signal(signal.SIGTERM, term)}
    yield
    for s, h in old.items():
        signal.signal(s, h)


# ----------------------------------------------------------------------------- the writer

NEW_DOC = b"the new report\n"
NEW_FIGS = {"a.svg": b"<svg>new a</svg>", "b.svg": b"<svg>new b</svg>"}
KINDS = {"SIGINT": signal.SIGINT, "SIGTERM": signal.SIGTERM,
         "disk-error": OSError(5, "Input/output error"), "interrupt": KeyboardInterrupt()}
#: what each kind raises out of the writer
RAISES = {"SIGINT": KeyboardInterrupt, "SIGTERM": Terminated, "disk-error": InputError,
          "interrupt": KeyboardInterrupt}


@pytest.mark.parametrize("kind", list(KINDS))
@pytest.mark.parametrize("at", STEPS)
def test_every_step_of_the_commit_leaves_the_old_or_the_new_whole(tmp_path, monkeypatch, handlers,
                                                                   at, kind):
    new = {"r.md": NEW_DOC, **{f"r_files/{k}": v for k, v in NEW_FIGS.items()}}
    old = plant_old(tmp_path, "r.md", new)
    hook = Hook(at, KINDS[kind])
    monkeypatch.setattr(outfile, "_step", hook)
    with pytest.raises(RAISES[kind]):
        outfile.write_document(tmp_path / "r.md", NEW_DOC, "-o", replace=True, files=NEW_FIGS)
    assert at in hook.seen and hook.seen == list(STEPS[: len(hook.seen)])  # reached, in order
    # a signal is held off: the commit goes through, then the run ends as interrupted; a
    # failure before the document is in place undoes every step (after it: too late to fail)
    failed = not isinstance(KINDS[kind], int) and at != "clean"
    assert state(tmp_path) == (old if failed else new)


@pytest.mark.parametrize("kind", ["SIGINT", "disk-error"])
@pytest.mark.parametrize("at", STEPS[1:])
def test_a_first_report_interrupted_at_any_step_is_all_or_nothing(tmp_path, monkeypatch, handlers, at, kind):
    # no old report (no step "aside"), and no --force: the no-clobber renames
    new = {"r.md": NEW_DOC, **{f"r_files/{k}": v for k, v in NEW_FIGS.items()}}
    monkeypatch.setattr(outfile, "_step", Hook(at, KINDS[kind]))
    with pytest.raises(RAISES[kind]):
        outfile.write_document(tmp_path / "r.md", NEW_DOC, "-o", replace=False, files=NEW_FIGS)
    assert state(tmp_path) == ({} if kind == "disk-error" and at != "clean" else new)


# ----------------------------------------------------------------------------- end to end


@pytest.fixture(scope="module")
def fresh(tmp_path_factory):
    """What each command writes uninterrupted (relative path -> bytes), on first use; its
    run's length in-process is ``fresh.took[name]``."""
    done: dict = {}

    def get(cli, name):
        if name not in done:
            cwd = tmp_path_factory.mktemp(name)
            t0 = time.monotonic()
            r = cli(*COMMANDS[name][0], cwd=cwd, env=ENV)
            get.took[name] = time.monotonic() - t0
            assert r.code == 0, r.err
            done[name] = state(cwd)
        return done[name]

    get.took = {}

    return get


CASES = [(name, at, sig) for name in COMMANDS for at in STEPS[1:] for sig in ("SIGINT", "SIGTERM")]


@pytest.mark.parametrize("case", sampled_params(CASES, lambda c: c in (("report", "clean", "SIGINT"),
                                                                     ("field-balance", "commit", "SIGTERM")),
                                                ids=lambda c: "-".join(c)))
def test_the_command_line_replaces_a_report_whole_when_a_signal_comes_during_the_commit(
        cli, tmp_path, monkeypatch, fresh, case):
    name, at, sig = case
    new = fresh(cli, name)
    old = plant_old(tmp_path, COMMANDS[name][1], new)
    monkeypatch.setattr(outfile, "_step", Hook(at, getattr(signal, sig)))
    r = cli(*COMMANDS[name][0], cwd=tmp_path, env=ENV)
    assert r.code == 128 + getattr(signal, sig) and r.err == f"rbcli: interrupted by {sig}\n", r
    assert state(tmp_path) == new != old


@pytest.mark.parametrize("at", sampled_params(STEPS[:3], lambda a: a == "commit"))
def test_the_command_line_keeps_the_old_report_when_a_step_of_the_commit_fails(cli, tmp_path, monkeypatch,
                                                                               fresh, at):
    name = "report"
    old = plant_old(tmp_path, COMMANDS[name][1], fresh(cli, name))
    monkeypatch.setattr(outfile, "_step", Hook(at, OSError(5, "Input/output error")))
    r = cli(*COMMANDS[name][0], cwd=tmp_path, env=ENV)
    assert r.code == 2 and r.err == "rbcli: -o: cannot write 'r.md': input/output error\n", r.err
    assert state(tmp_path) == old


def test_write_report_with_force_replaces_whole_through_a_held_signal(tmp_path, monkeypatch, handlers):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", ENV["SOURCE_DATE_EPOCH"])
    body = rbcli.load(TOP)
    (tmp_path / "fresh").mkdir()
    rbcli.write_report(body, tmp_path / "fresh" / "r.md", spin=150, theta=30)
    new = state(tmp_path / "fresh")
    old = plant_old(tmp_path / "old", "r.md", new)
    monkeypatch.setattr(outfile, "_step", Hook("clean", signal.SIGINT))  # the audit's case
    with pytest.raises(KeyboardInterrupt):
        rbcli.write_report(body, tmp_path / "old" / "r.md", force=True, spin=150, theta=30)
    assert state(tmp_path / "old") == new != old


# ----------------------------------------------------------------------------- real signals


def _sweep_plan(full: bool):
    """(command, fraction of an uninterrupted run's length, signal): by default one late
    moment (the figures and the commit), else 24 moments from the start to past the end for
    each command and signal."""
    if not full:
        return [("report", 0.9, signal.SIGINT)]
    return [(name, float(f), sig) for name in COMMANDS for f in np.linspace(0.1, 1.15, 24)
            for sig in (signal.SIGINT, signal.SIGTERM)]


@pytest.mark.parametrize("full", sampled_params([False, True], lambda f: not f, ids=["sample", "sweep"]))
def test_real_signals_at_staggered_moments_leave_the_old_or_the_new_report(cli, cli_proc, tmp_path, fresh, full):
    took: dict[str, float] = {}
    for i, (name, fraction, sig) in enumerate(_sweep_plan(full)):
        new = fresh(cli, name)
        took.setdefault(name, fresh.took[name])  # in-process: a process takes longer (start-up)
        if full and i == 0:  # the sweep: the length of an uninterrupted run as a process, now
            for each in COMMANDS:
                ref = tmp_path / f"ref-{each}"
                ref.mkdir()
                plant_old(ref, COMMANDS[each][1], fresh(cli, each))
                t0 = time.monotonic()
                r = cli_proc.finish(cli_proc.start(*COMMANDS[each][0], cwd=ref, env=ENV))
                took[each] = time.monotonic() - t0
                assert r.code == 0 and state(ref) == fresh(cli, each), r.err
        cwd = tmp_path / f"{name}-{i}"
        cwd.mkdir()
        old = plant_old(cwd, COMMANDS[name][1], new)
        p = cli_proc.start(*COMMANDS[name][0], cwd=cwd, env=ENV)
        time.sleep(fraction * took[name])
        if p.poll() is None:
            p.send_signal(sig)
        r = cli_proc.finish(p)
        where = f"{name} {signal.Signals(sig).name} at {fraction:.2f} of {took[name]:.2f} s"
        # finished, interrupted (rbcli's handlers), or ended by the signal before they were in place
        assert r.code in (0, 128 + sig, -sig), (where, r.code, r.err[-1000:])
        assert state(cwd) in (old, new), where
        assert r.code != 0 or state(cwd) == new, where
