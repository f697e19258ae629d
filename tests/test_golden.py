"""Golden cases: every command's table and JSON on every example, byte for byte.

The cases are data (``tests/cases/<command>/<name>.yaml`` beside ``.out`` and ``.err``;
black's tests/data/cases is the model); ``python tests/cases/regen.py`` writes them. A
change here is a change to a contract: regenerate deliberately and say why in the commit.
Each case is also checked for invariants that hold whatever the numbers are.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import pytest
import yaml

HERE = Path(__file__).resolve().parent / "cases"
sys.path.insert(0, str(HERE))

from regen import run  # noqa: E402

CASES = sorted(HERE.glob("*/*.yaml"))


def _id(p: Path) -> str:
    return f"{p.parent.name}/{p.stem}"


@pytest.mark.parametrize("case", CASES, ids=_id)
def test_golden_case(case: Path):
    spec = yaml.safe_load(case.read_text(encoding="utf-8"))
    code, out, err = run(spec["args"])
    assert code == spec["exit"], err
    assert out == case.with_suffix(".out").read_text(encoding="utf-8")
    assert err == case.with_suffix(".err").read_text(encoding="utf-8")
    _invariants(spec["args"], code, out, err)


def _invariants(args: list[str], code: int, out: str, err: str) -> None:
    assert code in (0, 1, 2)  # never 70: an internal error is a bug
    for line in err.splitlines():
        assert line.startswith("rbcli: "), line  # one located, prefixed line per message
    if code == 2:
        assert out == "" and len(err.splitlines()) >= 1
    if "--json" not in args or code == 2:
        return
    docs = [json.loads(line) for line in out.splitlines()] if len(
        [a for a in args if a.startswith("examples/")]) > 1 else [json.loads(out)]
    for d in docs:
        cmd = args[0]
        if cmd == "inertia":
            # parallel-axis theorem: J_ref = J_com + m (|d|^2 1 - d d^T), d = com - ref; the
            # tolerance is round-off on the largest entry (a few ulps of its size)
            J, Jc = np.array(d["inertia"]), np.array(d["inertia_com"])
            dv = np.array(d["com"]) - np.array(d["reference"])
            pa = Jc + d["mass"] * (dv @ dv * np.eye(3) - np.outer(dv, dv))
            assert np.allclose(J, pa, rtol=0, atol=1e-12 * max(1.0, np.abs(J).max()))
            assert np.allclose(J, J.T, rtol=0, atol=0)
        elif cmd == "principal":
            m, A = np.array(d["moments"]), np.array(d["axes"])
            assert np.all(np.diff(m) >= 0)
            assert np.allclose(A @ A.T, np.eye(3), atol=1e-12)  # orthonormal to round-off
            assert np.linalg.det(A) > 0  # right-handed
        elif cmd == "precess":
            assert d["kinetic_energy"] >= 0
