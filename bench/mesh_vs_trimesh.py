"""Speed and peak memory of rbcli's mesh reader + mass properties against trimesh.

Usage::

    bench/.venv/bin/python bench/mesh_vs_trimesh.py [STL_PATH] [--repeat 3]
    bench/.venv/bin/python bench/mesh_vs_trimesh.py --growth [--formats stl,ascii,obj]
        [--subdivisions 5,6,7,8] [--repeat 3] [--json OUT]

STL_PATH defaults to /tmp/rbcli_bench_ico8.stl; if missing it is created as a
binary STL of ``trimesh.creation.icosphere(subdivisions=8)`` (1 310 720 triangles).

Default mode (what ``bench/run`` calls): in one process, alternating (a)
``read_mesh`` + ``mass_properties`` and (b) ``trimesh.load`` + ``mesh.mass_properties``,
REPEAT times each; medians and their ratio. Memory: each side again in its own fresh
process, peak resident set size (``VmHWM`` from /proc/self/status) and the part of it
above the RSS after the imports (the cost of the work itself). The target is a time
ratio <= 0.5 and no more than half trimesh's peak memory.

``--growth``: every format (binary STL, ASCII STL, OBJ: trimesh's own exports of the
same icosphere, in bench/data/) at every size (icosphere subdivisions 5-8: 20 480 to
1 310 720 triangles; 9 gives 5.2 M and takes minutes), each run in a fresh process,
rbcli and trimesh alternating, REPEAT times; the medians of the children's CPU time
(user + system: hardly disturbed by other jobs on a shared machine), of their wall time
and of their peak memory, and the ratios. Prints a Markdown table (and writes JSON with
``--json``).

Each child starts its clocks only once OpenBLAS's worker threads are idle
(:func:`_blas_idle`): the worker thread that ``import numpy`` starts busy-waits for work
for ~0.1 s before it sleeps, on a free core, as CPU time of the process. That is a cost
of ``import numpy``, paid alike by every process that imports it; but a side whose
imports end soon after numpy's (rbcli: ~0.1 s from the start of ``import numpy``;
trimesh: ~0.4 s) had the rest of it counted as its work (at 2·10^4 triangles
0.01-0.05 s, up to double rbcli's CPU time; only when a core is free). The moment sums'
BLAS calls (3 × n products) never run on the worker (``other_threads_cpu_s``, the CPU
time of threads other than the main one inside the timed window, is 0 on both sides).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

DEFAULT = "/tmp/rbcli_bench_ico8.stl"
DATA = Path(__file__).resolve().parent / "data"
SUFFIX = {"stl": ".stl", "ascii": "_ascii.stl", "obj": ".obj"}
EXPORT = {"stl": "stl", "ascii": "stl_ascii", "obj": "obj"}
NAMES = {"stl": "binary STL", "ascii": "ASCII STL", "obj": "OBJ"}


def _status_kb(field: str) -> int:
    """A /proc/self/status field in kB (VmRSS: now; VmHWM: peak of this process image)."""
    with open("/proc/self/status") as fh:
        for line in fh:
            if line.startswith(field + ":"):
                return int(line.split()[1])
    return 0


def _thread_cpu() -> dict[int, float]:
    """CPU seconds (user + system) of each thread of this process, by thread id."""
    tick = os.sysconf("SC_CLK_TCK")
    out = {}
    for tid in os.listdir("/proc/self/task"):
        try:
            with open(f"/proc/self/task/{tid}/stat") as fh:
                fields = fh.read().rsplit(")", 1)[1].split()
        except OSError:  # the thread ended meanwhile
            continue
        out[int(tid)] = (int(fields[11]) + int(fields[12])) / tick
    return out


def _other_threads_cpu() -> float:
    """CPU seconds so far of this process's threads other than the main one."""
    return sum(t for tid, t in _thread_cpu().items() if tid != os.getpid())


def _blas_idle(quiet: float = 0.1, limit: float = 2.0) -> float:
    """Wait until the threads other than the main one use no CPU for ``quiet`` s.

    OpenBLAS starts its worker threads at ``import numpy``; each busy-waits for work for
    a while (~0.1 s here) before it sleeps. Returns the seconds waited (at most ``limit``).
    """
    start = time.perf_counter()
    last, since = _other_threads_cpu(), start
    while time.perf_counter() - start < limit:
        time.sleep(0.02)
        now = _other_threads_cpu()
        if now != last:
            last, since = now, time.perf_counter()
        elif time.perf_counter() - since >= quiet:
            break
    return time.perf_counter() - start


def run_ours(path: str) -> dict:
    from rbcli.core.mesh import mass_properties
    from rbcli.io.meshfile import read_mesh

    v, f, _fmt, weld = read_mesh(path)
    p = mass_properties(v, f, weld=weld)
    return {"volume": p.volume, "inertia_zz": float(p.unit_inertia[2, 2] * p.volume)}


def run_trimesh(path: str) -> dict:
    import trimesh

    m = trimesh.load(path)
    mp = m.mass_properties
    return {"volume": float(mp["volume"]), "inertia_zz": float(mp["inertia"][2, 2])}


def make(path: str, subdivisions: int = 8, kind: str = "stl") -> None:
    import trimesh

    Path(path).parent.mkdir(parents=True, exist_ok=True)
    print(f"creating {path} (icosphere, {subdivisions} subdivisions, {kind})...", file=sys.stderr)
    trimesh.creation.icosphere(subdivisions=subdivisions).export(path, file_type=EXPORT[kind])


def memory_child(which: str, path: str) -> None:
    import numpy  # noqa: F401

    if which == "ours":
        import rbcli.core.mesh  # noqa: F401
        import rbcli.io.meshfile  # noqa: F401
    else:
        import trimesh  # noqa: F401
    after_import = _status_kb("VmRSS")
    waited = _blas_idle()
    other0 = _other_threads_cpu()
    t0 = time.process_time()
    w0 = time.perf_counter()
    result = (run_ours if which == "ours" else run_trimesh)(path)
    cpu = time.process_time() - t0
    wall = time.perf_counter() - w0
    other = _other_threads_cpu() - other0
    # VmHWM, not ru_maxrss: Linux keeps ru_maxrss across fork+exec, so a child would
    # report the parent's peak; VmHWM belongs to this process image alone.
    peak = _status_kb("VmHWM")
    print(json.dumps({"peak_kb": peak, "after_import_kb": after_import, "cpu_s": cpu,
                      "wall_s": wall, "other_threads_cpu_s": other, "idle_wait_s": waited, **result}))


def child(which: str, path: str) -> dict:
    out = subprocess.run(
        [sys.executable, __file__, path, "--memory-child", which],
        check=True, capture_output=True, text=True,
    ).stdout
    return json.loads(out.strip().splitlines()[-1])


def growth(args) -> None:
    formats = [f.strip() for f in args.formats.split(",") if f.strip()]
    subs = [int(s) for s in args.subdivisions.split(",")]
    rows = []
    for s in subs:
        for kind in formats:
            path = DATA / f"ico{s}{SUFFIX[kind]}"
            if not path.exists():
                make(str(path), s, kind)
            runs: dict[str, list[dict]] = {"ours": [], "trimesh": []}
            for _ in range(args.repeat):
                for who in ("ours", "trimesh"):
                    runs[who].append(child(who, str(path)))
            keys = ("cpu_s", "wall_s", "peak_kb", "other_threads_cpu_s")
            med = {w: {k: statistics.median(r[k] for r in runs[w]) for k in keys} for w in runs}
            vol = {w: runs[w][0]["volume"] for w in runs}
            row = {
                "format": kind, "subdivisions": s, "triangles": 20 * 4**s,
                "file_mb": round(path.stat().st_size / 1e6, 1),
                "ours_cpu_s": round(med["ours"]["cpu_s"], 3), "trimesh_cpu_s": round(med["trimesh"]["cpu_s"], 3),
                "ours_wall_s": round(med["ours"]["wall_s"], 3), "trimesh_wall_s": round(med["trimesh"]["wall_s"], 3),
                "ours_other_threads_cpu_s": med["ours"]["other_threads_cpu_s"],
                "trimesh_other_threads_cpu_s": med["trimesh"]["other_threads_cpu_s"],
                "ours_peak_mib": round(med["ours"]["peak_kb"] / 1024, 1),
                "trimesh_peak_mib": round(med["trimesh"]["peak_kb"] / 1024, 1),
                "time_ratio": round(med["ours"]["cpu_s"] / med["trimesh"]["cpu_s"], 3),
                "wall_ratio": round(med["ours"]["wall_s"] / med["trimesh"]["wall_s"], 3),
                "memory_ratio": round(med["ours"]["peak_kb"] / med["trimesh"]["peak_kb"], 3),
                "volume_rel_diff": abs(vol["ours"] - vol["trimesh"]) / abs(vol["trimesh"]),
            }
            rows.append(row)
            print(json.dumps(row), file=sys.stderr, flush=True)
    print("| format | triangles | file | rbcli CPU | trimesh CPU | **CPU ratio** | wall ratio | rbcli peak | "
          "trimesh peak | **memory ratio** | volumes agree to |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {NAMES[r['format']]} | {r['triangles']:,} | {r['file_mb']} MB | {r['ours_cpu_s']:.3f} s | "
              f"{r['trimesh_cpu_s']:.3f} s | **{r['time_ratio']:.2f}** | {r['wall_ratio']:.2f} | "
              f"{r['ours_peak_mib']:.0f} MiB | {r['trimesh_peak_mib']:.0f} MiB | **{r['memory_ratio']:.2f}** | "
              f"{r['volume_rel_diff']:.0e} |")
    if args.json:
        Path(args.json).write_text(json.dumps({"growth": rows}, indent=2) + "\n")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("path", nargs="?", default=DEFAULT)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--growth", action="store_true", help="the growth table over formats and sizes")
    ap.add_argument("--formats", default="stl,ascii,obj", help="for --growth: stl, ascii, obj")
    ap.add_argument("--subdivisions", default="5,6,7,8", help="for --growth: icosphere subdivisions")
    ap.add_argument("--json", help="for --growth: write the rows here")
    ap.add_argument("--memory-child", choices=["ours", "trimesh"], help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.memory_child:
        memory_child(args.memory_child, args.path)
        return
    if args.growth:
        growth(args)
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

    mem = {which: child(which, args.path) for which in ("ours", "trimesh")}
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
