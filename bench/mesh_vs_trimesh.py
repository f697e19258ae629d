"""Speed and peak memory of rbcli's mesh reader + mass properties against trimesh.

Usage::

    .venv/bin/python bench/mesh_vs_trimesh.py [STL_PATH] [--repeat 3]

STL_PATH defaults to /tmp/rbcli_bench_ico8.stl; if missing it is created as a
binary STL of ``trimesh.creation.icosphere(subdivisions=8)`` (1 310 720 triangles).

Timing: in one process, alternating (a) ``read_mesh`` + ``mass_properties`` and
(b) ``trimesh.load`` + ``mesh.mass_properties``, REPEAT times each; medians and their
ratio. Memory: each side again in its own fresh process, peak resident set size
(``VmHWM`` from /proc/self/status) and the part of it above the RSS after the
imports (the cost of the work itself). The target is a time ratio <= 0.5 and no
more peak memory.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time

DEFAULT = "/tmp/rbcli_bench_ico8.stl"


def _status_kb(field: str) -> int:
    """A /proc/self/status field in kB (VmRSS: now; VmHWM: peak of this process image)."""
    with open("/proc/self/status") as fh:
        for line in fh:
            if line.startswith(field + ":"):
                return int(line.split()[1])
    return 0


def run_ours(path: str) -> dict:
    from rbcli.core.mesh import mass_properties
    from rbcli.io.meshfile import read_mesh

    v, f, *_ = read_mesh(path)
    p = mass_properties(v, f)
    return {"volume": p.volume, "inertia_zz": float(p.unit_inertia[2, 2] * p.volume)}


def run_trimesh(path: str) -> dict:
    import trimesh

    m = trimesh.load(path)
    mp = m.mass_properties
    return {"volume": float(mp["volume"]), "inertia_zz": float(mp["inertia"][2, 2])}


def make(path: str) -> None:
    import trimesh

    print(f"creating {path} (icosphere, 8 subdivisions)...", file=sys.stderr)
    trimesh.creation.icosphere(subdivisions=8).export(path)


def memory_child(which: str, path: str) -> None:
    import numpy  # noqa: F401

    if which == "ours":
        import rbcli.core.mesh  # noqa: F401
        import rbcli.io.meshfile  # noqa: F401
    else:
        import trimesh  # noqa: F401
    after_import = _status_kb("VmRSS")
    result = (run_ours if which == "ours" else run_trimesh)(path)
    # VmHWM, not ru_maxrss: Linux keeps ru_maxrss across fork+exec, so a child would
    # report the parent's peak; VmHWM belongs to this process image alone.
    peak = _status_kb("VmHWM")
    print(json.dumps({"peak_kb": peak, "after_import_kb": after_import, **result}))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("path", nargs="?", default=DEFAULT)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--memory-child", choices=["ours", "trimesh"], help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.memory_child:
        memory_child(args.memory_child, args.path)
        return
    if not os.path.exists(args.path):
        make(args.path)

    import trimesh  # noqa: F401  (import cost kept out of the timings)

    from rbcli.core.mesh import mass_properties  # noqa: F401

    times: dict[str, list[float]] = {"ours": [], "trimesh": []}
    results = {}
    for _ in range(args.repeat):
        for name, fn in (("ours", run_ours), ("trimesh", run_trimesh)):
            t0 = time.perf_counter()
            results[name] = fn(args.path)
            times[name].append(time.perf_counter() - t0)
    med = {k: statistics.median(v) for k, v in times.items()}
    print(f"file: {args.path} ({os.path.getsize(args.path) / 1e6:.1f} MB)")
    for k in ("ours", "trimesh"):
        runs = ", ".join(f"{t:.3f}" for t in times[k])
        print(f"  {k:8s} median {med[k]:.3f} s   runs [{runs}]   volume {results[k]['volume']!r}")
    print(f"  time ratio ours/trimesh: {med['ours'] / med['trimesh']:.3f}  (target <= 0.5)")

    mem = {}
    for which in ("ours", "trimesh"):
        out = subprocess.run(
            [sys.executable, __file__, args.path, "--memory-child", which],
            check=True,
            capture_output=True,
            text=True,
        ).stdout
        mem[which] = json.loads(out.strip().splitlines()[-1])
    for k in ("ours", "trimesh"):
        m = mem[k]
        print(
            f"  {k:8s} peak RSS {m['peak_kb'] / 1024:7.1f} MiB "
            f"(after imports {m['after_import_kb'] / 1024:6.1f} MiB, "
            f"work {(m['peak_kb'] - m['after_import_kb']) / 1024:7.1f} MiB)"
        )
    ratio = mem["ours"]["peak_kb"] / mem["trimesh"]["peak_kb"]
    print(f"  peak memory ratio ours/trimesh: {ratio:.3f}")


if __name__ == "__main__":
    main()
