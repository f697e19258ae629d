"""Streams and signals (issue 15), in real processes: closed or full stdout, stderr and
stdin, terminals that cannot show unit symbols, SIGTERM and SIGINT while writing.

Exit codes never depend on whether stderr can take the message; a pipe closed early is
quiet; a full disk or a closed stdout is exit 2; a signal leaves no temporary file and no
half-made figures folder.
"""

from __future__ import annotations

import os
import signal
import time
from pathlib import Path

import pytest

from conftest import sampled_params

ROOT = Path(__file__).resolve().parent.parent
GOOD = ("inertia", "examples/cube.yaml")
BAD = ("inertia", "examples/nope.yaml")


@pytest.fixture
def sh(cli_proc):
    """``sh(ARGS, REDIRECT)``: ``python -m rbcli ARGS REDIRECT`` through sh (``>&-``,
    ``2>/dev/full``...); (exit status, stdout, stderr) — a stream redirected away reads as ''."""

    def run(args: tuple[str, ...], redirect: str, cwd: Path = ROOT):
        r = cli_proc(*args, redirect=redirect, cwd=cwd)
        return r.code, r.out, r.err

    return run


# --------------------------------------------------------------------------- stdout


def test_closed_stdout_is_exit_2_with_a_message(sh):
    code, _, err = sh(GOOD, ">&-")
    assert code == 2 and err == "rbcli: cannot write to standard output: it is closed\n", err


def test_full_stdout_is_exit_2_with_a_message(sh):
    code, _, err = sh(GOOD, "> /dev/full")
    assert code == 2 and "no space left on device" in err and err.count("\n") == 1, err
    code, _, err = sh(("--help",), "> /dev/full")
    assert code == 2 and err.startswith("rbcli: "), err


def test_a_pipe_closed_early_is_quiet(sh):
    code, out, err = sh(("precess", "examples/cube.yaml", "--omega", "1,2,3", "--csv", "-",
                         "--duration", "100", "--samples", "200000"), "| head -1")
    assert code == 0 and err == "" and out.startswith("t,"), err


def test_a_report_needs_no_stdout(sh):
    import tempfile

    with tempfile.TemporaryDirectory() as d:
        code, _, err = sh(("report", str(ROOT / "examples/cube.yaml"), "-o", f"{d}/r.html"), ">&-")
        assert code == 0, err


# --------------------------------------------------------------------------- stderr


@pytest.mark.parametrize("redirect", ["2>&-", "2>/dev/full"])
def test_exit_status_never_depends_on_stderr(sh, redirect):
    assert sh(BAD, redirect)[0] == 2
    assert sh(GOOD, redirect + " >/dev/null")[0] == 0
    assert sh(("inertia", "examples/cube.yaml", "--nope"), redirect)[0] == 2


# --------------------------------------------------------------------------- stdin


def test_closed_stdin_with_body_dash_is_a_clear_exit_2(sh):
    code, _, err = sh(("inertia", "-"), "<&-")
    assert code == 2 and "standard input" in err and "closed" in err and err.count("\n") == 1, err


def test_stdin_from_dev_zero_stops_at_the_cap(sh):
    code, _, err = sh(("inertia", "-"), "< /dev/zero")
    assert code == 2 and "limited to 32 MiB" in err, err


def test_a_closed_stdin_does_not_matter_to_a_body_file(sh):
    assert sh(GOOD, "<&- >/dev/null")[0] == 0


# --------------------------------------------------------------------------- encodings


@pytest.mark.parametrize("args", sampled_params([("principal", "examples/cube.yaml"),
                                                 ("inertia", "examples/cube.yaml", "--units", "mm,g"),
                                                 ("precess", "examples/football.yaml", "--omega", "0.3,0,1"),
                                                 ("inertia", "-e", "{shape: box, mass: '2 µx·m²', size: [1, 1, 1]}")],
                                                [1, 3], ids=["principal", "units", "precess", "message"]))
def test_an_ascii_terminal_gets_ascii(cli_proc, args):
    r = cli_proc(*args, env={"PYTHONIOENCODING": "ascii"})
    assert r.code in (0, 2), r.err
    assert r.out.isascii() and r.err.isascii(), (r.out[:300], r.err)
    if r.code == 0:
        assert "·" not in r.out and ("kg*m^2" in r.out or "m^2" in r.out or args[0] == "precess")


# --------------------------------------------------------------------------- signals


def _wait_for(predicate, timeout=60.0):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(0.02)
    return False


def test_sigterm_during_a_long_csv_leaves_no_temporary_file(cli_proc, tmp_path):
    (tmp_path / "b.yaml").write_text((ROOT / "examples/football.yaml").read_text())
    p = cli_proc.start("precess", "b.yaml", "--omega", "1.7,0,9.8", "--duration", "100",
                       "--samples", "1000000", "--csv", "out.csv", cwd=tmp_path)
    assert _wait_for(lambda: any(n.startswith(".rbcli-") for n in os.listdir(tmp_path))), "no temp file seen"
    p.send_signal(signal.SIGTERM)
    r = cli_proc.finish(p, timeout=60)
    assert (r.code, r.err) == (128 + signal.SIGTERM, "rbcli: interrupted by SIGTERM\n"), r
    assert sorted(os.listdir(tmp_path)) == ["b.yaml"]


@pytest.mark.parametrize("delay", sampled_params([0.6, 1.2, 2.0], [0]))
def test_sigint_during_a_markdown_report_leaves_no_figures_folder(cli_proc, tmp_path, delay):
    # SIGINT at a moment of the run (0.6 s by default; 1.2 and 2 s as well under -m slow):
    # the run either finished (r.md and r_files/) or left nothing at all; never r_files/
    # alone, never a temporary file (tests/test_signals.py sweeps the moments for the other
    # outputs)
    (tmp_path / "b.yaml").write_text((ROOT / "examples/top.yaml").read_text())
    p = cli_proc.start("report", "b.yaml", "-o", "r.md", "--spin", "150", "--theta", "30", cwd=tmp_path)
    time.sleep(delay)
    p.send_signal(signal.SIGINT)
    r = cli_proc.finish(p, timeout=120)
    names = sorted(os.listdir(tmp_path))
    assert (r.code, r.err) in ((0, ""), (130, "rbcli: interrupted by SIGINT\n")), r
    assert names == (["b.yaml", "r.md", "r_files"] if r.code == 0 else ["b.yaml"]) or (
        r.code == 130 and names == ["b.yaml", "r.md", "r_files"]), (r.code, names)


@pytest.mark.parametrize("args, shown", [
    (("inertia", "examples/cube.yaml"), "-int xy dm"),  # the tensor's convention line
    (("whirl", "-e", "{shape: cylinder, radius: 0.1, length: 0.6, mass: 50}", "--bearings=-0.2,0.2",
      "--stiffness", "1e6", "--damping", "200", "--speed", "100"), "zeta"),
    (("top", "examples/top.yaml", "--spin", "150", "--theta", "30"), "beta"),
])
def test_an_ascii_terminal_reads_words_not_escapes(cli_proc, args, shown):
    # a Greek letter by its name, a sign by its ASCII form: no \u escapes in the text
    r = cli_proc(*args, env={"PYTHONIOENCODING": "ascii"})
    assert r.code in (0, 1) and "\\u" not in r.out + r.err and shown in r.out + r.err, (r.out[-600:], r.err)
