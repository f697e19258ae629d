"""The command line asks OpenBLAS for one thread (rbcli.env.prepare_blas), and that changes
no number: a mesh large enough for OpenBLAS to thread its products gives the same JSON
bytes with one thread or two."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]


def _env(**extra: str) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k != "OPENBLAS_NUM_THREADS"}
    env.update(extra)
    return env


def _run(code: str, env: dict[str, str]) -> str:
    # a fresh interpreter, not the cli_proc fixture: what is checked is the environment
    # main() leaves in its own process before numpy is imported, which no output shows
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env,
                       cwd=ROOT, check=True, timeout=60)
    return r.stdout.strip().splitlines()[-1]


def test_the_command_line_asks_for_one_blas_thread():
    code = ("import os\nfrom rbcli.cli import main\nassert main(['--version']) == 0\n"
            "print(os.environ.get('OPENBLAS_NUM_THREADS'))")
    assert _run(code, _env()) == "1"
    # the user's own choice stands
    assert _run(code, _env(OPENBLAS_NUM_THREADS="2")) == "2"


def test_a_program_that_imported_numpy_keeps_its_blas():
    code = ("import os, numpy, rbcli.env as e\ne.prepare_blas()\n"
            "print(os.environ.get('OPENBLAS_NUM_THREADS'))")
    assert _run(code, _env()) == "None"


def test_one_or_two_blas_threads_give_the_same_bytes(cli_proc, tmp_path):
    """An 8·10^4-triangle closed mesh: its 3 x n x 3 moment products (M N K = 737 280) are
    above OpenBLAS's threading size (M N K > 65536 * 4, interface/gemm.c): the whole JSON
    must be the same bytes."""
    trimesh = pytest.importorskip("trimesh")
    s = trimesh.creation.icosphere(subdivisions=6, radius=0.05)  # 81 920 triangles
    v = s.vertices * [1.0, 1.3, 0.8] + [0.01, -0.02, 0.03]  # no symmetry to hide a difference
    rec = np.zeros(len(s.faces), dtype=[("n", "<f4", (3,)), ("v", "<f4", (3, 3)), ("a", "<u2")])
    rec["v"] = v[s.faces]
    (tmp_path / "m.stl").write_bytes(b"m".ljust(80, b"\0") + np.uint32(len(rec)).tobytes()
                                     + rec.tobytes())
    body = tmp_path / "body.yaml"
    body.write_text("name: blob\nparts:\n  - name: blob\n    shape: mesh\n    file: m.stl\n"
                    "    units: m\n    density: 7850\n")
    outs = []
    for threads in ("1", "2"):
        r = cli_proc("inertia", str(body), "--json", env={"OPENBLAS_NUM_THREADS": threads})
        assert r.code == 0, r.err
        outs.append(r.out)
    assert outs[0] == outs[1]
