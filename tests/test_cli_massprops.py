"""Behaviour of ``rbcli inertia`` and ``rbcli principal`` through the command line.

Most cases run in-process (the ``cli`` fixture: ``rbcli.cli.main``); what only a real
process shows (exit status, standard error with no traceback, colour on a terminal, a closed
pipe, ``python -m rbcli``, the modules a run imports) runs through ``cli_proc``.

Expected numbers are closed forms worked here (the course's square lamina about a
corner: m a^2 [[1/3, -1/4, 0], [-1/4, 1/3, 0], [0, 0, 2/3]]), not rbcli's own output.
"""

from __future__ import annotations

import json
import math
import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
EX = ROOT / "examples"
LAMINA = str(EX / "square_lamina.yaml")  # m = 1 kg, a = 1 m, corner at the origin
FAN = str(EX / "two_blade_fan.yaml")
CUBE = str(EX / "cube.yaml")
BOX = "{shape: box, mass: 2, size: [0.1, 0.2, 0.3]}"
ANSI = re.compile(r"\x1b\[")

INERTIA_KEYS = {"mass", "com", "reference", "inertia", "inertia_com"}
AXIS_KEYS = {"axis", "axis_moment"}
OMEGA_KEYS = {"omega", "angular_momentum", "kinetic_energy", "angle_L_omega_deg"}
PRINCIPAL_KEYS = {"reference", "moments", "axes", "symmetry", "stable"}


#: a real process sees a pipe, not a terminal: no colour must come from that alone
PIPE_ENV = {"NO_COLOR": None}


# --------------------------------------------------------------------------- JSON keys

def test_inertia_json_has_exactly_the_spec_keys_and_the_asked_ones(cli):
    plain = cli("inertia", LAMINA, "--json").json()
    assert INERTIA_KEYS <= set(plain) and not (AXIS_KEYS | OMEGA_KEYS) & set(plain)
    with_axis = cli("inertia", LAMINA, "--axis", "1,1,0", "--json").json()
    assert INERTIA_KEYS | AXIS_KEYS <= set(with_axis) and not OMEGA_KEYS & set(with_axis)
    with_omega = cli("inertia", LAMINA, "--omega", "1,0,0", "--json").json()
    assert INERTIA_KEYS | OMEGA_KEYS <= set(with_omega) and not AXIS_KEYS & set(with_omega)
    both = cli("inertia", LAMINA, "--omega", "1,0,0", "--axis", "1,1,0", "--json").json()
    assert INERTIA_KEYS | AXIS_KEYS | OMEGA_KEYS <= set(both)
    # SPEC keys first, in the order SPEC lists them; the extras come after
    assert list(plain)[:5] == ["mass", "com", "reference", "inertia", "inertia_com"]
    assert plain["file"] == LAMINA and plain["name"] == "Square lamina about a corner"


def test_inertia_json_values_are_the_course_lamina(cli):
    j = cli("inertia", LAMINA, "--axis", "1,1,0", "--omega", "1,0,0", "--json").json()
    # m = 1, a = 1: one multiplication each, so round-off only (rel 1e-12)
    assert j["mass"] == pytest.approx(1.0, rel=1e-12)
    assert j["com"] == pytest.approx([0.5, 0.5, 0.0], rel=1e-12)
    course = [[1 / 3, -1 / 4, 0], [-1 / 4, 1 / 3, 0], [0, 0, 2 / 3]]
    for row, want in zip(j["inertia"], course):
        assert row == pytest.approx(want, rel=1e-12, abs=1e-15)
    assert j["axis"] == pytest.approx([1 / math.sqrt(2), 1 / math.sqrt(2), 0], rel=1e-12)
    assert j["axis_moment"] == pytest.approx(1 / 12, rel=1e-12)  # m a^2/12 about the diagonal
    assert j["angular_momentum"] == pytest.approx([1 / 3, -1 / 4, 0], rel=1e-12, abs=1e-15)
    assert j["kinetic_energy"] == pytest.approx(1 / 6, rel=1e-12)
    assert j["angle_L_omega_deg"] == pytest.approx(math.degrees(math.atan(0.75)), rel=1e-12)


def test_principal_json_keys_and_values(cli):
    j = cli("principal", LAMINA, "--about", "origin", "--json").json()
    assert PRINCIPAL_KEYS <= set(j) and list(j)[:5] == ["reference", "moments", "axes", "symmetry", "stable"]
    assert j["moments"] == pytest.approx([1 / 12, 7 / 12, 2 / 3], rel=1e-12)
    assert j["symmetry"] == "asymmetric" and j["stable"] == [True, False, True]
    cube = cli("principal", CUBE, "--json").json()
    assert cube["symmetry"] == "spherical" and cube["axes"] == [[1, 0, 0], [0, 1, 0], [0, 0, 1]]


def test_omega_with_units_and_about_a_point(cli):
    # 60 rpm = 2 pi rad/s about z; the lamina about its corner: Izz = 2/3
    j = cli("inertia", LAMINA, "--omega", "0,0,60 rpm", "--json").json()
    assert j["omega"] == pytest.approx([0, 0, 2 * math.pi], rel=1e-15)
    assert j["angular_momentum"][2] == pytest.approx(2 / 3 * 2 * math.pi, rel=1e-12)
    # about the com (0.5, 0.5, 0): the lamina's centroidal tensor, diag(1/12, 1/12, 1/6)
    c = cli("inertia", LAMINA, "--about", "com", "--json").json()
    assert c["reference"] == pytest.approx([0.5, 0.5, 0])
    assert [c["inertia"][i][i] for i in range(3)] == pytest.approx([1 / 12, 1 / 12, 1 / 6], rel=1e-12)
    mm = cli("inertia", LAMINA, "--about", "500 mm,50 cm,0", "--json").json()
    assert mm["inertia"] == c["inertia"]


# --------------------------------------------------------------------------- batches, stdin, -e

def test_several_bodies_with_json_give_json_lines_each_with_file(cli):
    for cmd in ("inertia", "principal"):
        r = cli(cmd, LAMINA, FAN, CUBE, "--json")
        lines = r.out.splitlines()
        assert r.code == 0 and len(lines) == 3
        assert [json.loads(line)["file"] for line in lines] == [LAMINA, FAN, CUBE]


def test_a_bad_file_in_a_batch_does_not_stop_the_others(cli, tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("parts:\n  - {shape: box, size: [1, 1, 1], mass: true}\n")
    r = cli("inertia", LAMINA, str(bad), CUBE, "--json")
    assert r.code == 2
    assert [json.loads(x)["file"] for x in r.out.splitlines()] == [LAMINA, CUBE]
    assert f"rbcli: {bad}:2:41: " in r.err  # at the value true


def test_stdin_and_expr(cli):
    text = Path(LAMINA).read_text()
    j = cli("inertia", "-", "--json", input=text).json()
    assert j["file"] == "<stdin>" and j["inertia"][0][1] == pytest.approx(-0.25, rel=1e-12)
    e = cli("inertia", "-e", BOX, "--json").json()
    # box 0.1 x 0.2 x 0.3 of 2 kg about its centre: Ixx = m (b^2 + c^2)/12 = 2 (0.04 + 0.09)/12
    assert e["file"] == "<expr>" and e["inertia"][0][0] == pytest.approx(2 * 0.13 / 12, rel=1e-12)


# --------------------------------------------------------------------------- tables

def test_tables_are_deterministic_bytes(cli):
    for args in (("inertia", LAMINA, "--axis", "1,1,0", "--omega", "1,2,3"), ("principal", FAN),
                 ("inertia", LAMINA, FAN, "--json"), ("principal", CUBE, "--json")):
        assert cli(*args).out == cli(*args).out


def test_digits(cli):
    six = cli("inertia", LAMINA, "--axis", "1,1,0").out
    three = cli("inertia", LAMINA, "--axis", "1,1,0", "--digits", "3").out
    assert "0.0833333" in six and "0.333333" in six  # 1/12 and 1/3 to six figures
    assert "0.0833 " in three and "0.0833333" not in three


def test_display_units_convert_the_numbers(cli):
    out = cli("inertia", LAMINA, "--about", "com", "--units", "mm,g").out
    # 1/12 kg m^2 = 1000 g x 1e6 mm^2 / 12 = 8.33333e+07 g mm^2; the com 0.5 m = 500 mm
    assert "g·mm²" in out and "8.33333e+07" in out
    assert re.search(r"com x\s*\|\s*500\s*\|\s*mm", out)
    js_mm = cli("inertia", LAMINA, "--units", "mm,g", "--json").json()
    assert js_mm["mass"] == 1.0  # JSON stays SI


def test_products_positive_flips_the_signs_and_says_so(cli):
    tensor = cli("inertia", LAMINA).out
    positive = cli("inertia", LAMINA, "--products", "positive").out
    # the tensor's entry is -1/4; the positive product Ixy = +integral(x y dm) = +1/4
    assert re.search(r"x\s*\|\s*0\.333333\s*\|\s*-0\.25", tensor)
    assert re.search(r"Ixy = \+∫xy dm\s*\|\s*0\.25\s*\|", positive)
    assert "positive products" in positive and "-0.25" not in positive


def test_principal_table_says_the_symmetry(cli):
    assert "spherical" in cli("principal", CUBE).out
    fan = cli("principal", FAN).out
    assert "asymmetric" in fan and "unstable" in fan


# --------------------------------------------------------------------------- errors, in-process

@pytest.mark.parametrize(
    "args, fragment",
    [
        (("inertia", "-e", "{shape: box, mass: true, size: [1, 2, 3]}"),
         "rbcli: <expr>:1:20: part 'box1': mass must be a number"),
        (("inertia", "nothere.yaml"), "rbcli: no such file: nothere.yaml"),
        (("inertia", LAMINA, "--products", "pos"), "--products must be 'tensor' or 'positive'"),
        (("inertia", LAMINA, "--axis", "0,0,0"), "--axis: the direction must be a non-zero vector"),
        (("inertia", LAMINA, "--omega", "1 Hz,0,0"), "--omega: '1 Hz' is a frequency"),
        (("inertia", LAMINA, "--omega", "1e300,0,0"), "--omega: the angular momentum or kinetic energy overflows"),
        (("inertia", LAMINA, "--about", "1e300,0,0"), "--about: the inertia about this point overflows"),
        (("principal", LAMINA, "--about", "1e300,0,0"), "--about: the inertia about this point overflows"),
        (("inertia", LAMINA, "--units", "deg"), "--units: 'deg' is not a length, mass or time unit"),
        (("inertia", LAMINA, "--units", "mm,in"), "--units: two length units, 'mm' and 'in'"),
        (("principal", LAMINA, "--units", "g,kg"), "--units: two mass units, 'g' and 'kg'"),
        (("inertia", LAMINA, "--units", ""), "--units: an empty value"),
        (("inertia", LAMINA, "--units", " "), "--units: an empty value"),
        (("inertia", LAMINA, "--units", "mm,,g"), "--units: an empty item in 'mm,,g'"),
        (("inertia", LAMINA, "--units", "si,mm"), "--units: si stands alone"),
        (("balance", LAMINA, "--planes", "0,1", "--radius", "1", "--units", "g,kg"), "--units: two mass units"),
        (("field-balance", "--initial", "6@30", "--trial", "10 g@0", "--run", "4@110", "--units", "mm,in"),
         "--units: two length units"),
        (("inertia",), "no body given"),
        (("inertia", LAMINA, "-e", BOX), "give either BODY files or -e/--expr, not both"),
    ],
)
def test_bad_input_exits_2_with_one_line(cli, args, fragment):
    r = cli(*args)
    code, out, err = r.code, r.out, r.err
    assert code == 2 and out == ""
    assert fragment in err and err.count("\n") == 1 and "Traceback" not in err


def test_tiny_axis_is_a_direction(cli):
    r = cli("inertia", LAMINA, "--axis", "1e-320,1e-320,0", "--json")
    code, out = r.code, r.out
    assert code == 0 and json.loads(out)["axis_moment"] == pytest.approx(1 / 12, rel=1e-12)


def test_internal_error_exits_70_with_a_this_is_a_bug_line(cli, monkeypatch):
    import rbcli.core.inertia as core

    def boom(*a, **k):
        raise RuntimeError("boom")  # not an arithmetic error (those are bad input, exit 2)

    monkeypatch.setattr(core, "inertia_report", boom)
    r = cli("inertia", "-e", BOX)
    code, out, err = r.code, r.out, r.err
    assert code == 70 and out == ""
    assert err.startswith("rbcli: internal error (RuntimeError: boom); this is a bug")
    assert err.count("\n") == 1 and "Traceback" not in err


def test_ctrl_c_exits_130(cli, monkeypatch):
    import rbcli.core.inertia as core

    def interrupted(*a, **k):
        raise KeyboardInterrupt

    monkeypatch.setattr(core, "inertia_report", interrupted)
    r = cli("inertia", "-e", BOX)
    assert (r.code, r.err) == (130, "rbcli: interrupted by SIGINT\n")


# --------------------------------------------------------------------------- real processes

def test_exit_codes_and_one_line_errors_in_a_real_process(cli_proc, tmp_path):
    ok = cli_proc("inertia", "examples/square_lamina.yaml", "--axis", "1,1,0", env=PIPE_ENV)
    assert ok.code == 0 and "0.0833333" in ok.out and ok.err == ""
    bad = tmp_path / "bad.yaml"
    bad.write_text("parts:\n  - shape: box\n    size: [1, 1, 1]\n    mass: '3 m'\n")
    r = cli_proc("inertia", str(bad), env=PIPE_ENV)
    assert r.code == 2 and r.out == ""
    assert r.err == f"rbcli: {bad}:4:11: part 'box1': mass: '3 m' is a length, but a mass is needed here (e.g. kg, g, lb)\n"


def test_stdin_in_a_real_process(cli_proc):
    r = cli_proc("principal", "-", "--json", input=Path(CUBE).read_text(), env=PIPE_ENV)
    assert r.code == 0 and r.json()["symmetry"] == "spherical"


def test_no_ansi_escapes_in_a_pipe_or_with_no_color(cli_proc):
    r = cli_proc("inertia", "examples/cube.yaml", env=PIPE_ENV)
    assert r.code == 0 and not ANSI.search(r.out)


@pytest.mark.skipif(sys.platform == "win32", reason="needs a pseudo-terminal")
def test_a_terminal_gets_colour_unless_no_color(cli_proc):
    def on_tty(extra_env: dict) -> str:
        return cli_proc("inertia", "examples/cube.yaml", tty=True,
                        env={"NO_COLOR": None, "TERM": "xterm", **extra_env}).out

    assert "\x1b[" in on_tty({})  # the test can tell: a terminal does get bold headings
    plain = on_tty({"NO_COLOR": "1"})
    assert "Steel cube" in plain and "\x1b[" not in plain


def test_a_closed_pipe_is_quiet(cli_proc):
    # enough output to fill the pipe (~200 tables), then the reader goes away after one line
    for extra in ((), ("--json",)):
        p = cli_proc.start("inertia", *extra, *["examples/bracket.yaml"] * 200)
        p.stdout.readline()
        p.stdout.close()
        err = p.stderr.read()
        p.stderr.close()
        assert p.wait(timeout=60) == 0
        assert err == b"", err


def test_version_help_and_python_m_rbcli(cli_proc):
    from rbcli import __version__

    v = cli_proc("--version", env=PIPE_ENV)
    assert v.code == 0 and v.out == f"rbcli {__version__}\n"
    h = cli_proc("--help", env=PIPE_ENV)
    assert h.code == 0 and "inertia" in h.out and "principal" in h.out
    ih = cli_proc("inertia", "--help", env=PIPE_ENV)
    assert ih.code == 0 and "--products" in ih.out and "--omega" in ih.out


def test_main_returns_the_status_and_both_entry_points_exit_with_it(cli, cli_proc):
    # rbcli.cli.main(argv) returns the exit status (no SystemExit); the console script and
    # python -m rbcli (rbcli.__main__) exit with it
    from rbcli.cli import main

    assert main(["--version"]) == 0
    for script in (False, True):
        assert cli_proc("--version", script=script).code == 0
        r = cli_proc("inertia", "examples/nope.yaml", script=script)
        assert (r.code, r.err.count("\n")) == (2, 1), r
    assert cli("inertia", "examples/nope.yaml").code == 2


def test_a_run_of_the_cli_loads_no_heavy_modules(cli_proc):
    # what the command line imports before a command (the root's --version): typer and the
    # standard library only
    r = cli_proc("--version", imports=True)
    assert r.code == 0, r.err
    heavy = {"numpy", "scipy", "matplotlib", "pint", "yaml", "rich", "trimesh"}
    assert not heavy & r.imported, f"rbcli --version loaded: {sorted(heavy & r.imported)}"
    assert "typer" in r.imported  # the check can fail: what the run imported is seen
