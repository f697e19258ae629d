"""Start-up of rbcli against the floor of its own imports, as ratios in one run.

Usage: python bench/startup.py [--runs N] [--rounds R] [--json FILE]

Each command is run alternately with its floor (same machine state), N times per
round after unrecorded warm-up runs; the ratio of the medians is the figure.
R rounds give the spread of that ratio (the machine is shared: absolute times are
noisy, ratios within one alternating round much less so). Beside the wall time the
children's CPU time (user + system, from wait4) is compared too: it is barely
touched by other processes' load.

Pairs (the floor is what the command cannot avoid importing; rbcli never imports pydantic
or, on these paths, scipy, so neither is in a floor — issue 16):
  rbcli inertia SMALL --json      vs  python -c "import typer, numpy, yaml"   goal <= 1.2
  rbcli --help / --version        vs  python -c "import typer"                goal <= 1.15
  rbcli top / precess / gyrocompass ... --json
                                  vs  python -c "import typer, numpy, yaml"   goal <= 1.3

``python -X importtime`` is run IMPORTTIME_RUNS times per command and each module's
smallest self time is kept (the least disturbed figure); the table lists the modules
the command imports beyond its floor, largest first, and rbcli's own modules.

``--check-coercion`` also compares rbcli's fast path for typer's parameter coercion
(rbcli/cli/app.py) with typer's own pydantic coercion over every parameter of every
command and a set of awkward values.
"""

from __future__ import annotations

import argparse
import collections
import json
import statistics
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from common import ENV, ROOT, alternate, compile_rbcli, load_avg, med, py, rbcli_cmd, show  # noqa: E402

SMALL = str(ROOT / "examples" / "square_lamina.yaml")
TOP = str(ROOT / "examples" / "top.yaml")
BOOK = str(ROOT / "examples" / "book.yaml")
GYRO = str(ROOT / "examples" / "gyroscope.yaml")
#: what a body command cannot avoid importing (rbcli imports no pydantic, no scipy here)
FLOOR = "import typer, numpy, yaml"
IMPORTTIME_RUNS = 11


def pairs() -> list[dict]:
    P = py()
    rb = rbcli_cmd()
    help_out = subprocess.run([*rb, "--help"], capture_output=True, text=True, env=ENV).stdout
    out = [
        {"name": "inertia (small body)", "cmd": [*rb, "inertia", SMALL, "--json"],
         "floor": [P, "-c", FLOOR], "goal": 1.2},
        {"name": "--help", "cmd": [*rb, "--help"], "floor": [P, "-c", "import typer"], "goal": 1.15},
        {"name": "--version", "cmd": [*rb, "--version"], "floor": [P, "-c", "import typer"], "goal": 1.15},
    ]
    for name, cmd in (
        ("top", [*rb, "top", TOP, "--spin", "150", "--theta", "30", "--g", "9.81", "--json"]),
        ("precess", [*rb, "precess", BOOK, "--omega", "0.01,1,0.01", "--json"]),
        ("gyrocompass", [*rb, "gyrocompass", GYRO, "--spin", "6000 rpm", "--latitude", "30", "--json"]),
    ):
        if f"  {name} " in help_out:
            out.append({"name": name, "cmd": cmd, "floor": [P, "-c", FLOOR], "goal": 1.3})
        else:
            out.append({"name": name, "skipped": f"rbcli has no '{name}' command yet"})
    return out


def run_pairs(runs: int, rounds: int) -> list[dict]:
    res = []
    for p in pairs():
        if "skipped" in p:
            res.append({"name": p["name"], "skipped": p["skipped"]})
            continue
        walls, floors, cpus, fcpus, round_ratios, round_cpu = [], [], [], [], [], []
        for i in range(rounds):
            t = alternate({"cmd": p["cmd"], "floor": p["floor"]}, runs, warm=2 if i == 0 else 1)
            walls += t["cmd"]["wall"]
            floors += t["floor"]["wall"]
            cpus += t["cmd"]["cpu"]
            fcpus += t["floor"]["cpu"]
            round_ratios.append(med(t["cmd"]["wall"]) / med(t["floor"]["wall"]))
            round_cpu.append(med(t["cmd"]["cpu"]) / med(t["floor"]["cpu"]))
        ratio = statistics.median(round_ratios)
        res.append({
            "name": p["name"],
            "command": show(p["cmd"]),
            "floor": show(p["floor"]),
            "runs": runs,
            "rounds": rounds,
            "median_s": med(walls),
            "floor_median_s": med(floors),
            "ratio": ratio,
            "ratio_rounds": round_ratios,
            "cpu_median_s": med(cpus),
            "floor_cpu_median_s": med(fcpus),
            "cpu_ratio": statistics.median(round_cpu),
            "cpu_ratio_rounds": round_cpu,
            "goal": p["goal"],
            "met": None if p["goal"] is None else statistics.median(round_cpu) <= p["goal"],  # CPU: less disturbed by load
            "load_avg": load_avg(),
        })
    return res


# ----------------------------------------------------------------------------- -X importtime


def importtime_min(args: list[str], n: int = IMPORTTIME_RUNS) -> dict[str, dict]:
    """{module: {"self_ms", "cum_ms", "depth"}}: the smallest figures over n runs."""
    selfs: dict[str, list[int]] = collections.defaultdict(list)
    cums: dict[str, list[int]] = collections.defaultdict(list)
    depth: dict[str, int] = {}
    for _ in range(n):
        err = subprocess.run([py(), "-X", "importtime", *args], capture_output=True, text=True,
                             env=ENV).stderr
        for line in err.splitlines():
            if not line.startswith("import time:") or "cumulative" in line:
                continue
            s, c, name = line.split(":", 1)[1].split("|")
            depth[name.strip()] = (len(name) - len(name.lstrip()) - 1) // 2
            selfs[name.strip()].append(int(s))
            cums[name.strip()].append(int(c))
    return {k: {"self_ms": min(selfs[k]) / 1000, "cum_ms": min(cums[k]) / 1000, "depth": depth[k]}
            for k in selfs}


def offenders(cmd_args: list[str], floor_args: list[str], top: int = 10) -> dict:
    """What the command imports beyond its floor (smallest self times, ms)."""
    a = importtime_min(cmd_args)
    b = importtime_min(floor_args)
    extra = {k: v for k, v in a.items() if k not in b}
    by_pkg: collections.Counter = collections.Counter()
    for k, v in extra.items():
        by_pkg[k.split(".")[0]] += v["self_ms"]
    ranked = sorted(extra, key=lambda k: -extra[k]["self_ms"])
    return {
        "runs": IMPORTTIME_RUNS,
        "command": show([py(), *cmd_args]),
        "floor": show([py(), *floor_args]),
        "floor_modules": len(b),
        "floor_self_ms": round(sum(v["self_ms"] for v in b.values()), 1),
        "extra_modules": len(extra),
        "extra_self_ms": round(sum(v["self_ms"] for v in extra.values()), 1),
        "extra_by_package_ms": {k: round(v, 1) for k, v in by_pkg.most_common(8)},
        "top_extra": [(k, round(extra[k]["self_ms"], 2)) for k in ranked[:top]],
        "rbcli_modules": sorted(
            ((k, round(v["self_ms"], 2)) for k, v in a.items() if k.startswith("rbcli")),
            key=lambda kv: -kv[1],
        ),
    }


def all_offenders() -> dict:
    rb = ["-m", "rbcli"]
    return {
        "inertia": offenders([*rb, "inertia", SMALL, "--json"], ["-c", FLOOR]),
        "top": offenders([*rb, "top", TOP, "--spin", "150", "--theta", "30", "--g", "9.81", "--json"],
                         ["-c", FLOOR]),
    }


# ----------------------------------------------------------------------------- coercion check


def check_coercion() -> dict:
    """rbcli's fast coercion (rbcli/cli/app.py) gives what typer's pydantic one gives."""
    import typer.main
    from typer import _coercion

    import rbcli.cli  # noqa: F401 - installs the fast path
    from rbcli.cli.app import app

    values = ["7", "+7", "-7", " 7", "07", "1_000", "7.0", "7.5", "1e3", "1E-3", ".5", "5.", "0",
              "17", "18", "999999999999999999999", "1e999", "inf", "nan", "", "abc", "٣", "x,y,z",
              "3000 rpm", "-", 6, 6.0, True, None, ("a", "b"), ["1", "2"], ()]
    group = typer.main.get_command(app)
    n = bad = 0
    mismatches = []

    class Ctx:  # typer only reads ctx for error messages of choices/paths; we have none
        pass

    for cname, cmd in sorted(group.commands.items()):
        for prm in cmd.params:
            desc = getattr(prm, "type_descriptor", None)
            if desc is None:
                continue
            fast = prm.__class__.get_runtime_param(prm)
            slow = _coercion.build_runtime_param(desc)
            for v in values:
                n += 1
                got = []
                for rp in (fast, slow):
                    try:
                        got.append(("ok", rp.coerce(v, param=prm, ctx=None)))
                    except Exception as exc:  # noqa: BLE001 - compare the error too
                        got.append(("error", f"{type(exc).__name__}: {exc}"))
                if repr(got[0]) != repr(got[1]) or type(got[0][1]) is not type(got[1][1]):  # nan == nan here
                    bad += 1
                    mismatches.append(f"{cname} {prm.name} {v!r}: fast {got[0]!r} typer {got[1]!r}")
    return {"compared": n, "mismatches": bad, "examples": mismatches[:10],
            "fast_path_active": type(fast).__name__ == "_Plain"}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=9)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--no-importtime", action="store_true")
    ap.add_argument("--check-coercion", action="store_true")
    ap.add_argument("--json", type=Path)
    args = ap.parse_args()
    compile_rbcli()
    out: dict = {}
    if args.check_coercion:
        out["coercion_check"] = c = check_coercion()
        print(f"fast coercion vs typer's: {c['compared']} values compared, {c['mismatches']} differ"
              + "".join("\n  " + m for m in c["examples"]))
    out["startup"] = res = run_pairs(args.runs, args.rounds)
    for r in res:
        if "skipped" in r:
            print(f"{r['name']:<22} skipped: {r['skipped']}")
            continue
        flag = "" if r["met"] is None else ("  goal <= %g (CPU): %s" % (r["goal"], "met" if r["met"] else "MISSED"))
        spread = ", ".join(f"{x:.2f}" for x in r["ratio_rounds"])
        print(f"{r['name']:<22} {r['median_s'] * 1000:6.0f} ms vs floor {r['floor_median_s'] * 1000:6.0f} ms"
              f"  ratio {r['ratio']:.2f} (rounds {spread}; CPU {r['cpu_ratio']:.2f}){flag}")
    if not args.no_importtime:
        out["importtime"] = off = all_offenders()
        for k, o in off.items():
            print(f"-X importtime, {k}: {o['extra_modules']} modules beyond the floor, "
                  f"{o['extra_self_ms']} ms (min self times): "
                  + ", ".join(f"{n} {ms:.1f}" for n, ms in o["top_extra"][:8]))
    if args.json:
        args.json.write_text(json.dumps(out, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
