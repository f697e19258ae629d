"""Timing helpers shared by the bench scripts (stdlib only).

Everything here measures child processes: wall time of a whole command (start-up
included) and its peak resident memory.

Peak memory: ``getrusage(RUSAGE_CHILDREN).ru_maxrss`` is useless for a child here,
because Linux carries ``ru_maxrss`` over fork+exec (a small child of a big parent
reports the parent's peak) and RUSAGE_CHILDREN is the maximum over all children
so far. ``os.wait4`` gives the rusage of that one child, which still has the
fork-inherited floor; so :func:`run_peak` polls ``VmHWM`` in ``/proc/PID/status``
(the high-water mark of the child's own image after exec) until it exits, and
also reports wait4's figure for comparison.
"""

from __future__ import annotations

import json
import os
import platform
import statistics
import subprocess
import sys
import time
from collections.abc import Sequence
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
DATA = HERE / "data"
#: the environment of every timed child: no colour, no rich help, fixed width
ENV = {**os.environ, "NO_COLOR": "1", "COLUMNS": "100", "PYTHONHASHSEED": "0"}
ENV.pop("FORCE_COLOR", None)
# Time THIS checkout's rbcli, whichever checkout the interpreter's `rbcli` script was
# installed from (a shared venv with another worktree installed editable would otherwise
# time that one).
ENV["PYTHONPATH"] = os.pathsep.join(filter(None, (str(ROOT), os.environ.get("PYTHONPATH"))))
# Users' Pythons cache bytecode; a PYTHONDONTWRITEBYTECODE left in the environment would
# recompile every rbcli module whose .pyc is stale on every run (measured: +6 ms for
# rbcli.io.units alone). See also compile_rbcli().
ENV.pop("PYTHONDONTWRITEBYTECODE", None)
# One BLAS thread for every child, rbcli and its peers and floors alike: the command line
# sets it itself (rbcli.env.prepare_blas) because OpenBLAS's idle workers busy-wait ~0.1 s
# after `import numpy` (~50 ms of every run on 2 cores); a peer or floor without it would
# pay that and rbcli not, and the ratios would credit rbcli's code with a setting.
ENV["OPENBLAS_NUM_THREADS"] = "1"


def compile_rbcli() -> None:
    """Write current .pyc files for rbcli (as an install would) before anything is timed."""
    import compileall

    compileall.compile_dir(str(ROOT / "rbcli"), quiet=1)


def py() -> str:
    """The interpreter the benchmarks run (the bench venv's when run by bench/run)."""
    return sys.executable


def rbcli_cmd() -> list[str]:
    """The installed ``rbcli`` console script beside this interpreter (what users run)."""
    script = Path(sys.executable).with_name("rbcli")
    if script.exists():
        return [str(script)]
    return [sys.executable, "-m", "rbcli"]


def show(cmd: Sequence[str]) -> str:
    """A command as it would be typed: interpreter and script paths shortened."""
    out = []
    for a in cmd:
        if a == sys.executable:
            a = "python"
        elif a.endswith("/rbcli") and Path(a).name == "rbcli":
            a = "rbcli"
        elif a.startswith(str(ROOT) + "/"):
            a = a[len(str(ROOT)) + 1 :]
        out.append(a)
    return " ".join(out)


def time_once(cmd: Sequence[str], *, check: bool = True, cwd: str | Path | None = None,
              stdout=subprocess.DEVNULL) -> tuple[float, float]:
    """(wall, cpu) seconds of one run of ``cmd``, output discarded.

    cpu is the child's user + system time (from wait4): less disturbed by other
    processes on a shared machine than the wall time, though not immune (caches,
    frequency scaling).
    """
    t = time.perf_counter()
    p = subprocess.Popen(list(cmd), stdout=stdout, stderr=subprocess.PIPE, env=ENV, cwd=cwd)
    err = p.stderr.read() if p.stderr else b""
    _, st, ru = os.wait4(p.pid, 0)
    dt = time.perf_counter() - t
    p.returncode = os.waitstatus_to_exitcode(st)
    if check and p.returncode != 0:
        raise RuntimeError(f"{show(cmd)} exited {p.returncode}: {err.decode()[-2000:]}")
    return dt, ru.ru_utime + ru.ru_stime


def alternate(cmds: dict[str, Sequence[str]], runs: int, warm: int = 2,
              cwd: str | Path | None = None) -> dict[str, dict[str, list[float]]]:
    """Run the commands round-robin ``runs`` times (after ``warm`` unrecorded rounds).

    Alternating makes every command see the same machine load and file cache, so the
    ratio of their medians is meaningful on a shared, noisy machine even when the
    absolute times are not. Returns {name: {"wall": [...], "cpu": [...]}}.
    """
    times: dict[str, dict[str, list[float]]] = {k: {"wall": [], "cpu": []} for k in cmds}
    for i in range(warm + runs):
        for k, c in cmds.items():
            w, cpu = time_once(c, cwd=cwd)
            if i >= warm:
                times[k]["wall"].append(w)
                times[k]["cpu"].append(cpu)
    return times


def med(xs: Sequence[float]) -> float:
    return statistics.median(xs)


def iqr(xs: Sequence[float]) -> tuple[float, float]:
    """(25th, 75th) percentile: the spread of a set of runs."""
    if len(xs) < 4:
        return (min(xs), max(xs))
    q = statistics.quantiles(xs, n=4)
    return (q[0], q[2])


def run_peak(cmd: Sequence[str], *, cwd: str | Path | None = None, poll: float = 0.002,
             stdout=subprocess.DEVNULL) -> dict:
    """Run ``cmd`` once: wall time, peak RSS (VmHWM of the child, polled) and exit code.

    The poll reads ``/proc/PID/status`` every ``poll`` s; the last read before the
    child exits holds the high-water mark up to then, and as a zombie's status no
    longer has Vm lines, a final peak reached in the last few ms could be missed —
    so the figure is a lower bound within one poll interval of the end. wait4's
    ``ru_maxrss`` (an upper bound: it includes the fork-inherited parent image) is
    given beside it.
    """
    t = time.perf_counter()
    p = subprocess.Popen(list(cmd), stdout=stdout, stderr=subprocess.PIPE, env=ENV, cwd=cwd)
    hwm = 0
    status = f"/proc/{p.pid}/status"
    while True:
        try:
            with open(status) as fh:
                for line in fh:
                    if line.startswith("VmHWM:"):
                        hwm = max(hwm, int(line.split()[1]))
                        break
        except (FileNotFoundError, ProcessLookupError):
            pass
        pid, st, ru = os.wait4(p.pid, os.WNOHANG)
        if pid:
            break
        time.sleep(poll)
    dt = time.perf_counter() - t
    err = p.stderr.read().decode() if p.stderr else ""
    p.returncode = os.waitstatus_to_exitcode(st)
    if p.returncode != 0:
        raise RuntimeError(f"{show(cmd)} exited {p.returncode}: {err[-2000:]}")
    return {"wall_s": dt, "peak_rss_mib": hwm / 1024.0, "ru_maxrss_mib": ru.ru_maxrss / 1024.0}


def machine() -> dict:
    """What the figures were taken on."""
    cpu = "?"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    try:
        load = os.getloadavg()
    except OSError:
        load = (float("nan"),) * 3
    try:
        mem_gib = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 2**30
    except (ValueError, OSError):
        mem_gib = float("nan")
    vers = {}
    for mod in ("numpy", "scipy", "typer", "pydantic", "yaml", "trimesh"):
        try:
            from importlib.metadata import version

            dist = {"yaml": "PyYAML"}.get(mod, mod)
            vers[mod] = version(dist)
        except Exception:  # noqa: BLE001 - a missing peer is just not listed
            pass
    return {
        "date": time.strftime("%Y-%m-%d %H:%M %Z"),
        "nproc": os.cpu_count(),
        "cpu": cpu,
        "mem_gib": round(mem_gib, 1),
        "python": platform.python_version(),
        "platform": platform.platform(),
        "load_avg_at_start": [round(x, 2) for x in load],
        "versions": vers,
    }


def load_avg() -> list[float]:
    return [round(x, 2) for x in os.getloadavg()]


def dump(path: Path, data: dict) -> None:
    path.write_text(json.dumps(data, indent=2, sort_keys=False) + "\n")
