"""Bounded and located (issue 34 items 3 to 5): a file far over the part cap refused before
its tree is built (a 400 000-part file under 300 MiB), an OBJ face index of 5 000 digits one
located line, ``at(t)``'s arrays read-only, and messages that agree with what they describe.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import rbcli
from conftest import EXAMPLES, ROOT
from rbcli.body.model import load_text
from rbcli.errors import InputError
from rbcli.io import meshobj, yamlsafe
from rbcli.io.meshfile import MeshFileError, read_mesh


def _points(n: int, tail: str = "") -> str:
    return "parts:\n" + "".join(f"  - {{shape: point, mass: 1, at: [{i}, 0, 0]}}\n" for i in range(n)) + tail


# ----------------------------------------------------------------------------- the part cap


def test_a_file_over_the_part_cap_is_refused_before_a_node_is_made(monkeypatch):
    monkeypatch.setenv("RBCLI_MAX_PARTS", "1000")
    made = []
    real = yamlsafe._Tree.add

    def counting(self, node, event):
        made.append(node)
        return real(self, node, event)

    monkeypatch.setattr(yamlsafe._Tree, "add", counting)
    with pytest.raises(InputError, match="more than 1000 parts") as exc:
        load_text(_points(3000), "big.yaml", ROOT)
    assert exc.value.where.line == 1002 and exc.value.where.col == 5  # part 1001, as before
    assert made == []  # the events were counted, no tree was built
    load_text(_points(999), "ok.yaml", ROOT)  # the check can fail: under the cap, the tree
    assert made


@pytest.mark.parametrize("head, says", [
    ("parts:\n  - &a {shape: point, mass: 1}\n", "anchors"),  # the tree's pass says what is wrong
    ("name: [1, 2\n", "invalid YAML"),
])
def test_the_count_leaves_other_problems_to_the_tree(monkeypatch, head, says):
    monkeypatch.setenv("RBCLI_MAX_PARTS", "100")
    with pytest.raises(InputError, match=says):
        load_text(head + _points(300)[len("parts:\n"):], "x.yaml", ROOT)


def _peak(cmd: list[str]) -> tuple[float, int, str]:
    """(peak RSS in MiB: VmHWM of /proc/PID/status polled every 2 ms, as bench/common.py's
    run_peak does; exit status; standard error) of a run. Not cli_proc: it waits, and the
    peak is read while the process lives."""
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, cwd=ROOT)
    hwm = 0
    while p.poll() is None:
        try:
            with open(f"/proc/{p.pid}/status") as fh:
                hwm = max([hwm] + [int(line.split()[1]) for line in fh if line.startswith("VmHWM:")])
        except OSError:  # it ended
            pass
        time.sleep(0.002)
    return hwm / 1024, p.returncode, p.stderr.read().decode()


@pytest.mark.slow
@pytest.mark.skipif(not Path("/proc/self/status").exists(), reason="reads VmHWM from /proc")
def test_a_400000_part_file_is_refused_under_300_mib(tmp_path):
    big = tmp_path / "big.yaml"
    big.write_text(_points(400_000))  # 19 MB: under the 32 MiB file budget, twice the part cap
    mib, code, err = _peak([sys.executable, "-m", "rbcli", "inertia", str(big)])
    assert code == 2 and f"{big}:200002:5: the body has more than 200000 parts" in err, err
    # 300 MiB is the bound; the tree of 200 000 parts alone took ~350 MiB (445 in all)
    assert 0 < mib < 300, f"peak {mib:.0f} MiB"


# ----------------------------------------------------------------------------- meshes


@pytest.mark.parametrize("fast", [True, False], ids=["numpy-reader", "line-reader"])
@pytest.mark.parametrize("index", ["4" * 5000, "4" * 5000 + "/1/1", "-" + "4" * 5000, "0" * 4500 + "4"])
def test_an_obj_face_index_of_thousands_of_digits_is_one_located_line(tmp_path, monkeypatch, index, fast):
    path = tmp_path / "long.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 " + index + "\n")
    if not fast:  # the reader that says which line is wrong, on its own
        monkeypatch.setattr(meshobj, "_read_obj_fast", lambda *a, **k: None)
    if index.startswith("0"):  # vertex 4 with leading zeros: read, by either reader
        assert len(read_mesh(path).faces) == 4
        return
    with pytest.raises(MeshFileError, match="out of range") as exc:  # (int() refuses 4300 digits)
        read_mesh(path)
    assert exc.value.line == 8 and len(str(exc.value)) < 300


# ----------------------------------------------------------------------------- read-only


def test_at_gives_read_only_arrays():
    states = [rbcli.precess(rbcli.load(EXAMPLES / "book.yaml"), omega=[0.01, 1, 0.01]).at([1.0, 2.0]),
              rbcli.top(rbcli.load(EXAMPLES / "top.yaml"), spin=150, theta=30).at([1.0, 2.0])]
    for state in states:
        arrays = {k: v for k, v in vars(state).items() if isinstance(v, np.ndarray)} if hasattr(state, "__dict__") \
            else {k: getattr(state, k) for k in state.__dataclass_fields__}
        assert len(arrays) >= 4
        for name, a in arrays.items():
            with pytest.raises(ValueError, match="read-only"):
                a[0] = 0.0


# ----------------------------------------------------------------------------- messages


@pytest.mark.parametrize("products", ["Ixy: 0.1", "Ixy: 0"])
def test_a_convention_beside_an_inertia_mapping_is_told_to_move_in(products):
    # it used to be told to add the convention it had (with products), or to remove it
    text = (f"parts:\n  - shape: given\n    mass: 1\n    convention: positive\n"
            f"    inertia: {{Ixx: 1, Iyy: 1, Izz: 1, {products}}}\n")
    with pytest.raises(InputError) as exc:
        load_text(text, "g.yaml", ROOT)
    assert str(exc.value) == ("g.yaml:4:5: part 'given1' (given): the Ixx... form states its convention "
                              "inside 'inertia'; move 'convention' into the inertia mapping")
    moved = text.replace("    convention: positive\n", "").replace("Izz: 1,", "Izz: 1, convention: positive,")
    load_text(moved, "g.yaml", ROOT)  # the check can fail: moved in, it is read


def test_the_readme_says_what_rollcheck_help_says_of_the_tyre_radius(cli):
    readme = (ROOT / "README.md").read_text()
    assert "0 <= r <= a" in cli("rollcheck", "--help").out.replace("\n", " ")
    assert "(0 ≤ r ≤ a)" in readme and "tyre radius ≥ rim radius" not in readme
    penny = rbcli.load(EXAMPLES / "penny.yaml")
    a = 0.009525  # the penny's rim radius: r = a is taken (a sphere), beyond it refused
    assert rbcli.rollcheck(penny, rolling_speed=0.1, tyre_radius=a).to_json()["tyre_radius"] == a
    with pytest.raises(InputError, match="tyre_radius: the tyre radius .* must be at most the rim radius"):
        rbcli.rollcheck(penny, rolling_speed=0.1, tyre_radius=1.01 * a)


def test_the_readme_budgets_list_every_limit_and_the_variable_that_raises_it():
    from rbcli.api import check, commands
    from rbcli.body import includes, loadctx
    from rbcli.io import bearingtable, meshfile
    from rbcli.io.field import coefficients, jobfile

    readme = (ROOT / "README.md").read_text()
    budgets = readme[readme.index("- **Budgets**"):readme.index("An included file is read")]
    source = "".join(p.read_text() for p in (ROOT / "rbcli").rglob("*.py"))
    variables = set(re.findall(r'"(RBCLI_MAX_\w+)"', source))  # every variable that raises a limit
    assert len(variables) >= 3 and all(f"`{v}=" in budgets for v in variables), variables

    def n(x: int) -> str:  # as the table writes it
        return f"{x >> 20} MiB" if x % (1 << 20) == 0 else f"{x:,}".replace(",", " ")

    limits = [loadctx.MAX_PARTS, yamlsafe.MAX_BYTES, includes.MAX_INCLUDE_DEPTH,
              yamlsafe.MAX_DEPTH, meshobj.MAX_FACE_CORNERS, jobfile.MAX_JOB_BYTES, coefficients.MAX_COEFF_BYTES,
              bearingtable.MAX_ROWS, bearingtable.MAX_CSV, commands.MAX_SAMPLES, commands.MAX_POINTS,
              commands.MAX_BEARINGS, commands.MAX_ORDER, check.MAX_TEXT, check.MAX_TEXT_TOTAL, check.MAX_ITEMS]
    missing = [x for x in limits if n(x) not in budgets]
    assert not missing and f"{meshfile.MAX_MESH_BYTES >> 30} GiB" in budgets, missing
