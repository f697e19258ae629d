"""Same bytes everywhere (issue 32 item 4).

- One route for units: a bare number in a body with ``units:`` and the same number written
  with the unit give the same bits (in a body file, in ``Body.from_parts``, on the command
  line), whatever the unit: the decimal that prints the number, times the unit's exact
  factor, rounded once (rbcli.io.units.bare_to_si).
- Every command's ``--json`` (every golden JSON case: every command on every example) is
  the same bytes with 1, 2 or 8 OpenBLAS threads, and the library's ``to_json()`` in a
  program that kept 8 threads is the command line's ``--json``. (Field balancing's min-max
  is left out: its solver is the field-balancing branch's.)
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from hypothesis import given, settings, strategies as st

import rbcli
from conftest import sample

ROOT = Path(__file__).resolve().parents[1]
CASES = ROOT / "tests" / "cases"


@settings(deadline=None, max_examples=50)  # the first call loads the body machinery
@given(x=st.floats(min_value=-1e6, max_value=1e6, allow_nan=False).filter(lambda v: v != 0),
       unit=st.sampled_from(["mm", "in", "ft", "cm"]))
def test_a_bare_length_and_the_same_with_its_unit_are_the_same_bits(x, unit):
    typed = rbcli.Body.from_parts([rbcli.parts.point(mass=1, at=[f"{x!r} {unit}", 0, 0])])
    bare = rbcli.load_text(f"units: {{length: {unit}}}\nparts:\n - {{shape: point, mass: 1, at: [{x!r}, 0, 0]}}")
    data = rbcli.Body.from_parts([rbcli.parts.point(mass=1, at=[x, 0, 0])], units={"length": unit})
    assert typed.parts[0].com[0] == bare.parts[0].com[0] == data.parts[0].com[0]


def test_the_issues_number_in_mm():
    x = "84.8528137423857"
    typed = rbcli.Body.from_parts([rbcli.parts.point(mass=1, at=[f"{x} mm", 0, 0])])
    bare = rbcli.load_text(f"units: {{length: mm}}\nparts:\n - {{shape: point, mass: 1, at: [{x}, 0, 0]}}")
    assert typed.parts[0].com[0] == bare.parts[0].com[0] == float("0.0848528137423857")  # rounded once (x / 1000 is not)


@settings(deadline=None, max_examples=30)
@given(x=st.floats(min_value=0.01, max_value=1e4), unit=st.sampled_from(["g", "lb", "oz"]))
def test_a_bare_mass_in_a_body_and_on_the_command_line(x, unit):
    body = rbcli.load_text(f"units: {{length: mm, mass: {unit}}}\nparts:\n - {{shape: point, mass: 5, at: [0, 0, 0]}}")
    bare = rbcli.balance(body, planes="-50,50", radius="100", mass_step=repr(x))
    typed = rbcli.balance(body, planes="-50,50", radius="100", mass_step=f"{x!r} {unit}")
    assert bare.options.mass_step == typed.options.mass_step


# ----------------------------------------------------------------------------- BLAS threads

_SCRIPT = r"""
import contextlib, io, json, sys
sys.path.insert(0, "tests")
from tests_blas import pin_blas_kernel
pin_blas_kernel()
from rbcli.cli import main
import rbcli
out = {}
for name, args in json.loads(sys.argv[1]).items():
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf), contextlib.redirect_stderr(io.StringIO()):
        main(args)
    out[name] = buf.getvalue()
fan = rbcli.load("examples/fan_rotor.yaml")
api = {  # the library in a program that kept its threads
    "inertia": rbcli.inertia(fan, omega="0,0,300 rpm"),
    "principal": rbcli.principal(fan),
    "balance": rbcli.balance(fan, planes="-100,100", radius=0.1, speed="1500 rpm", bearings="-150,150"),
    "precess": rbcli.precess(fan, omega="0.3,1,0.2"),
    "whirl": rbcli.whirl(fan, bearings="-150,150", stiffness=5e6, damping=500, speed="1480 rpm"),
    "field": rbcli.field_balance(job="examples/jobs/fan.yaml"),
}
from rbcli.errors import option_name, spelled_data  # remarks name options, as --json prints them
print(json.dumps({"cli": out, "api": {k: spelled_data(r.to_json(), option_name) for k, r in api.items()}}))
"""

#: the command lines whose --json the library's to_json() above must equal
_API_CLI = {
    "inertia": ["inertia", "examples/fan_rotor.yaml", "--omega", "0,0,300 rpm", "--json"],
    "principal": ["principal", "examples/fan_rotor.yaml", "--json"],
    "balance": ["balance", "examples/fan_rotor.yaml", "--planes=-100,100", "--radius", "0.1 m",
                "--speed", "1500 rpm", "--bearings=-150,150", "--json"],
    "precess": ["precess", "examples/fan_rotor.yaml", "--omega", "0.3,1,0.2", "--json"],
    "whirl": ["whirl", "examples/fan_rotor.yaml", "--bearings=-150,150", "--stiffness", "5e6",
              "--damping", "500", "--speed", "1480 rpm", "--json"],
    "field": ["field-balance", "examples/jobs/fan.yaml", "--json"],
}


def _json_cases() -> dict[str, list[str]]:
    out = {}
    for p in sorted(CASES.glob("*/*.yaml")):
        spec = yaml.safe_load(p.read_text(encoding="utf-8"))
        args = spec["args"]
        if "--json" in args and spec["exit"] in (0, 1) and "min-max" not in args and "-" not in args:
            out[f"{p.parent.name}/{p.stem}"] = args
    return out


def _run(threads: str, cases: dict) -> dict:
    # processes of their own: a BLAS thread count is fixed when numpy is first imported
    env = {"OPENBLAS_NUM_THREADS": threads, "PATH": "/usr/bin:/bin", "NO_COLOR": "1"}
    r = subprocess.run([sys.executable, "-c", _SCRIPT, json.dumps({**cases, **{f"api:{k}": v for k, v in _API_CLI.items()}})],
                       capture_output=True, text=True, cwd=ROOT, env=env, timeout=600, check=True)
    return json.loads(r.stdout)


@pytest.mark.sampled
def test_every_json_is_the_same_bytes_with_1_2_or_8_blas_threads_and_from_the_library():
    cases = _json_cases()
    cases = cases if sample(False, True) else {k: v for i, (k, v) in enumerate(cases.items()) if i % 8 == 0}
    runs = {t: _run(t, cases) for t in ("1", "2", "8")}
    for name in cases:
        golden = (CASES / f"{name}.out").read_text(encoding="utf-8")
        assert runs["1"]["cli"][name] == runs["2"]["cli"][name] == runs["8"]["cli"][name] == golden, name
    for t, run in runs.items():
        for key, data in run["api"].items():
            cli = json.loads(run["cli"][f"api:{key}"])
            cli.pop("file", None)
            assert json.dumps(data) == json.dumps(cli), (t, key)
