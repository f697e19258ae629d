"""Batch: `rbcli inertia` over 1000 small body files in one process (``rbcli inertia
*.yaml --json`` prints JSON Lines, SPEC §2) against the naive script
(``bench/naive_body.py``: CSafeLoader + numpy, no checks) over the same files, goal <= 2.0
in CPU time (issue 16's 1.5, retired to 2.0 by issue 31 with the second YAML reader that
served it); and a shell loop, one process per file, over the first
``--loop-files`` of them.

Usage::

    python bench/batch.py [--files 1000] [--loop-files 200] [--runs 2] [--json OUT]

The files (1 to 4 parts each: boxes, cylinders, spheres, point masses, some holes,
mm and kg) are generated into bench/data/batch/ (git-ignored). The two ways are run
alternately RUNS times; medians and their ratio. The outputs of the first run of
each are checked to hold the same objects (the loop prints indented JSON per file,
the single run compact lines).
"""

from __future__ import annotations

import argparse
import json
import random
import shlex
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from common import DATA, med, rbcli_cmd, time_once  # noqa: E402

DIR = DATA / "batch"
#: the goal: one invocation over the files at most this many times the naive script's CPU
GOAL = 2.0


def body_text(rng: random.Random, i: int) -> str:
    """Body file ``i`` of the batch: 1 to 4 boxes, cylinders, spheres or point masses in mm
    and kg, sometimes a hole cut from a box."""
    lines = [f"name: batch body {i}", "units: {length: mm, mass: kg}", "parts:"]
    box = None
    for j in range(rng.randint(1, 4)):
        at = ", ".join(f"{rng.uniform(-100, 100):.4g}" for _ in range(3))
        k = rng.choice(["box", "cylinder", "sphere", "point"])
        lines.append(f"  - name: part{j}")
        if k == "box":
            size = [rng.uniform(20, 80) for _ in range(3)]
            lines += ["    shape: box", f"    size: [{', '.join(f'{s:.4g}' for s in size)}]",
                      '    density: "7850 kg/m^3"']
            box = (f"part{j}", at, size)
        elif k == "cylinder":
            lines += ["    shape: cylinder", f"    radius: {rng.uniform(5, 40):.4g}",
                      f"    length: {rng.uniform(10, 100):.4g}", '    density: "2.7 g/cm^3"',
                      f"    axis: [{rng.uniform(-1, 1):.3f}, {rng.uniform(-1, 1):.3f}, 1]"]
        elif k == "sphere":
            lines += ["    shape: sphere", f"    radius: {rng.uniform(5, 40):.4g}",
                      f"    mass: {rng.uniform(0.1, 3):.3g}"]
        else:
            lines += ["    shape: point", f"    mass: {rng.uniform(0.01, 1):.3g}"]
        lines.append(f"    at: [{at}]")
    if box is not None and rng.random() < 0.5:
        name, at, size = box
        lines += ["  - name: hole", "    shape: cylinder", f"    radius: {0.2 * min(size[:2]):.4g}",
                  f"    length: {size[2]:.4g}", "    subtract: true", f"    cut_from: {name}",
                  f"    at: [{at}]"]
    return "\n".join(lines) + "\n"


def make_files(n: int, seed: int = 2) -> list[Path]:
    rng = random.Random(seed)
    DIR.mkdir(parents=True, exist_ok=True)
    for old in DIR.glob("*.yaml"):
        if int(old.stem.split("_")[1]) >= n:
            old.unlink()
    paths = []
    for i in range(n):
        text = body_text(rng, i)
        p = DIR / f"body_{i:03d}.yaml"
        if not p.exists() or p.read_text() != text:
            p.write_text(text)
        paths.append(p)
    return paths


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--files", type=int, default=1000)
    ap.add_argument("--loop-files", type=int, default=200)
    ap.add_argument("--runs", type=int, default=2)
    ap.add_argument("--json", type=Path)
    args = ap.parse_args()
    files = make_files(args.files)
    rb = " ".join(shlex.quote(a) for a in rbcli_cmd())
    rel = "bench/data/batch"
    nloop = min(args.loop_files, len(files))
    loop_list = " ".join(f"{rel}/{p.name}" for p in files[:nloop])
    loop = ["bash", "-c", f"for f in {loop_list}; do {rb} inertia \"$f\" --json || exit 1; done"]
    one_loop = ["bash", "-c", f"{rb} inertia {loop_list} --json"]
    one = ["bash", "-c", f"{rb} inertia {rel}/*.yaml --json"]
    naive = ["bash", "-c", f"{shlex.quote(sys.executable)} bench/naive_body.py {rel}/*.yaml"]
    root = DIR.parent.parent.parent
    out = DATA / "batch_out"
    out.mkdir(exist_ok=True)
    t = {k: {"wall": [], "cpu": []} for k in ("loop", "one_loop", "one", "naive")}
    for i in range(args.runs):  # alternating; the first run of each keeps its output
        for k, cmd in (("loop", loop), ("one_loop", one_loop), ("one", one), ("naive", naive)):
            if i == 0:
                with open(out / f"{k}.txt", "wb") as fh:
                    w, c = time_once(cmd, cwd=root, stdout=fh)
            else:
                w, c = time_once(cmd, cwd=root)
            t[k]["wall"].append(w)
            t[k]["cpu"].append(c)
    # same answers both ways
    a = (out / "loop.txt").read_text()
    b = (out / "one_loop.txt").read_text()
    dec = json.JSONDecoder()
    objs_a, i = [], 0
    while i < len(a):
        while i < len(a) and a[i].isspace():
            i += 1
        if i < len(a):
            o, i = dec.raw_decode(a, i)
            objs_a.append(o)
    objs_b = [json.loads(line) for line in b.splitlines() if line.strip()]
    same = objs_a == objs_b and len(objs_b) == nloop
    res = {
        "files": len(files),
        "runs": args.runs,
        "loop_files": nloop,
        "loop_command": f"for f in (the first {nloop} files); do rbcli inertia \"$f\" --json; done",
        "one_command": f"rbcli inertia {rel}/*.yaml --json",
        "naive_command": f"python bench/naive_body.py {rel}/*.yaml",
        "loop_s": med(t["loop"]["wall"]),
        "one_loop_s": med(t["one_loop"]["wall"]),
        "one_s": med(t["one"]["wall"]),
        "naive_s": med(t["naive"]["wall"]),
        "ratio_loop_over_one": med(t["loop"]["wall"]) / med(t["one_loop"]["wall"]),
        "loop_per_file_ms": 1000 * med(t["loop"]["wall"]) / nloop,
        "one_per_file_ms": 1000 * med(t["one"]["wall"]) / len(files),
        "cpu_ratio": med(t["loop"]["cpu"]) / med(t["one_loop"]["cpu"]),
        "one_cpu_s": med(t["one"]["cpu"]),
        "naive_cpu_s": med(t["naive"]["cpu"]),
        "ratio_one_over_naive_cpu": med(t["one"]["cpu"]) / med(t["naive"]["cpu"]),
        "ratio_one_over_naive_wall": med(t["one"]["wall"]) / med(t["naive"]["wall"]),
        "goal_one_over_naive": GOAL,
        "same_output": same,
        "times": {k: v["wall"] for k, v in t.items()},
    }
    print(f"{len(files)} files, one invocation: {res['one_cpu_s']:.2f} s CPU "
          f"({res['one_per_file_ms']:.1f} ms/file wall) vs naive_body.py {res['naive_cpu_s']:.2f} s CPU: "
          f"ratio {res['ratio_one_over_naive_cpu']:.2f} CPU, {res['ratio_one_over_naive_wall']:.2f} wall "
          f"(goal <= {GOAL}: {'met' if res['ratio_one_over_naive_cpu'] <= GOAL else 'MISSED'})")
    print(f"first {nloop} files: loop {res['loop_s']:.2f} s ({res['loop_per_file_ms']:.0f} ms/file), "
          f"one invocation {res['one_loop_s']:.2f} s: loop/one = {res['ratio_loop_over_one']:.1f} "
          f"(CPU {res['cpu_ratio']:.1f}); same objects: {same}")
    if args.json:
        args.json.write_text(json.dumps(res, indent=2) + "\n")
    return 0 if same else 1


if __name__ == "__main__":
    raise SystemExit(main())
