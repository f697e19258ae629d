"""``--csv`` time series: what 10^5 rows cost beyond evaluating them (issue 16, goal ≤ 0.5 s).

Usage::

    python bench/csv_rows.py [--rows 100000] [--runs 5] [--json OUT]

For ``precess`` (11 columns: t, ω, L, quaternion) and ``top`` (4 columns: t, θ, φ, ψ):

- whole processes, alternating: ``rbcli ... --csv F --samples ROWS`` against the same
  command with ``--samples 2`` (start-up, loading and the options are the same): the
  difference is what the rows cost, evaluation included;
- in this process: the evaluation alone (the exact motion at ROWS times:
  ``PrecessResult.series_blocks``, ``TopResult.at``), median of ``--runs``;
- in this process, ``precess``'s rows themselves: ``csvout.rows_text`` (the vectorised
  shortest repr, ``rbcli.render.shortest``) against the ``%r`` format of the same blocks
  (Python's ``repr`` per number: what rows_text was before), median of ``--runs``; the two
  texts must be equal, and equal to the rows of the CSV file the command wrote.

"Beyond the evaluation" = (process difference) − (evaluation). Both are CPU times. The
CSV bytes are checked to be the shortest round-trip ``repr`` of every number (the first
200 lines of each file; every byte of precess's, against the ``%r`` format).
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from common import ROOT, alternate, dump, med, rbcli_cmd  # noqa: E402

EX = ROOT / "examples"
CASES = {
    "precess": (["precess", str(EX / "book.yaml"), "--omega", "0.01,1,0.01", "--duration", "1000"],
                lambda rbcli: rbcli.precess(rbcli.load(str(EX / "book.yaml")), omega="0.01,1,0.01")),
    "top": (["top", str(EX / "top.yaml"), "--spin", "150", "--theta", "30", "--duration", "10"],
            lambda rbcli: rbcli.top(rbcli.load(str(EX / "top.yaml")), spin="150", theta="30")),
}


def _eval_cpu(make, duration: float, rows: int, runs: int) -> float:
    import rbcli

    from rbcli.render.csvout import times as chunks

    result = make(rbcli)
    cpu = []
    for _ in range(runs):
        t = time.process_time()
        if hasattr(result, "series_blocks"):  # precess: the rows themselves
            for _block in result.series_blocks(duration, rows):
                pass
        else:  # top: its state (angles) at each chunk of times
            for ts in chunks(duration, rows):
                result.at(ts)
        cpu.append(time.process_time() - t)
    return med(cpu)


def _repr_format(block) -> str:
    """The rows in one ``%r`` format (the peer rows_text is measured against)."""
    import numpy as np

    a = np.asarray(block, dtype=float) + 0.0
    line = ",".join(["%r"] * a.shape[1]) + "\n"
    return (line * a.shape[0]) % tuple(a.ravel().tolist())


def _format_cpu(make, duration: float, rows: int, runs: int, csv_file: Path) -> dict:
    """rows_text against the %r format on precess's own blocks, in this process."""
    import rbcli

    from rbcli.render.csvout import rows_text

    blocks = list(make(rbcli).series_blocks(duration, rows))
    res = {}
    for name, fmt in (("rows_text", rows_text), ("repr_format", _repr_format)):
        cpu = []
        for _ in range(runs):
            t = time.process_time()
            text = "".join(fmt(b) for b in blocks)
            cpu.append(time.process_time() - t)
        res[name] = (med(cpu), text)
    body = csv_file.read_text().split("\n", 1)[1]
    return {"rows_text_cpu_s": res["rows_text"][0], "repr_format_cpu_s": res["repr_format"][0],
            "texts_equal": res["rows_text"][1] == res["repr_format"][1] == body}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rows", type=int, default=100_000)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--json", type=Path)
    a = ap.parse_args()
    sys.path.insert(0, str(ROOT))
    rb = rbcli_cmd()
    res: dict = {"rows": a.rows}
    with tempfile.TemporaryDirectory() as tmp:
        for name, (args, make) in CASES.items():
            big, small = Path(tmp, f"{name}_big.csv"), Path(tmp, f"{name}_small.csv")
            cmds = {"rows": [*rb, *args, "--samples", str(a.rows), "--csv", str(big)],
                    "two": [*rb, *args, "--samples", "2", "--csv", str(small)]}
            t = alternate(cmds, a.runs, warm=1)
            duration = float(args[args.index("--duration") + 1])
            ev = _eval_cpu(make, duration, a.rows, a.runs)
            lines = big.read_text().splitlines()
            cols = len(lines[0].split(","))
            exact = all(repr(float(x)) == x for line in lines[1:200] for x in line.split(","))
            diff = med(t["rows"]["cpu"]) - med(t["two"]["cpu"])
            r = {"columns": cols, "numbers": cols * a.rows, "process_cpu_s": med(t["rows"]["cpu"]),
                 "two_rows_cpu_s": med(t["two"]["cpu"]), "rows_cpu_s": diff, "evaluation_cpu_s": ev,
                 "beyond_evaluation_s": diff - ev, "bytes": big.stat().st_size, "repr_exact": exact,
                 "goal": 0.5}
            r["met"] = r["beyond_evaluation_s"] <= 0.5
            r["us_per_number"] = 1e6 * r["beyond_evaluation_s"] / r["numbers"]
            if name == "precess":
                r.update(_format_cpu(make, duration, a.rows, a.runs, big))
            res[name] = r
            print(f"{name} --csv, {a.rows} rows x {cols} columns ({r['bytes'] / 1e6:.1f} MB): rows cost "
                  f"{diff:.3f} s CPU, evaluation {ev:.3f} s, beyond it {r['beyond_evaluation_s']:.3f} s "
                  f"({r['us_per_number']:.2f} us a number; goal <= 0.5 s); repr-exact: {exact}", flush=True)
            if "texts_equal" in r:
                print(f"  {name} in-process: rows_text {r['rows_text_cpu_s']:.3f} s CPU, the %r "
                      f"format (repr per number) {r['repr_format_cpu_s']:.3f} s; texts and file "
                      f"equal: {r['texts_equal']}", flush=True)
    if a.json:
        dump(a.json, res)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
