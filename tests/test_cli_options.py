"""Option values and usage errors shared by every command (rbcli/cli/common.py, rbcli/cli/__init__.py).

- The unit rule of list options (review F1): a unit after the LAST number applies to every
  bare number before it; a number with its own unit keeps it; a list with no unit is in the
  option's bare unit (SI, or degrees for angles). Expected values come from pint, an
  independent unit library, never from rbcli's own parser.
- Each list option of inertia, principal and balance through the CLI, against closed forms.
- Usage errors and bad numbers are one line on standard error, exit 2 (F4, F5), through the
  real entry point (``python -m rbcli``, the ``cli_proc`` fixture); help, version; Ctrl-C,
  arithmetic and internal errors and --debug/RBCLI_DEBUG in-process (the ``cli`` fixture,
  through rbcli.cli.main and its error-to-exit-status map).
- typer's parameter coercion: rbcli's fast path (rbcli/cli/app.py) gives what typer's own
  pydantic coercion gives, and it is active (F13).
"""

from __future__ import annotations

import cmath
import json
import math
from pathlib import Path

import pint
import pytest

import rbcli
from rbcli.errors import option_name
from rbcli.render.text import check_finite_doc
from rbcli.cli import app
from rbcli.api import options as op
from rbcli.cli import common as c
from rbcli.errors import InputError, NonFiniteResult

ROOT = Path(__file__).resolve().parent.parent
EX = ROOT / "examples"
LAMINA = str(EX / "square_lamina.yaml")  # m = 1 kg, a = 1 m, corner at the origin
TWO_DISK = str(EX / "two_disk_rotor.yaml")
PENNY = str(EX / "penny.yaml")
BOX = "{shape: box, mass: 2, size: [0.1, 0.2, 0.3]}"

U = pint.UnitRegistry()


def si(text: str, unit: str) -> float:
    """pint's value of ``text`` in ``unit`` (the oracle for unit conversions)."""
    return float(U.Quantity(text).to(unit).magnitude)


# the parser multiplies each number by an exact rational unit factor and rounds once; pint
# multiplies floats (one or two roundings): they agree to a few ulp
ULP = 1e-15


# ----------------------------------------------------------------------------- the unit rule


@pytest.mark.parametrize("text, kind, bare, want", [
    # a unit after the last number applies to every bare number before it
    ("1,1,1 mm", "length", None, ["1 mm", "1 mm", "1 mm"]),
    ("100,0,300 rpm", "angular_speed", None, ["100 rpm", "0 rpm", "300 rpm"]),
    ("-100,100 mm", "length", None, ["-100 mm", "100 mm"]),
    ("1,2,3mm", "length", None, ["1 mm", "2 mm", "3 mm"]),
    (" 1 , 2 , 3 in ", "length", None, ["1 inch", "2 inch", "3 inch"]),
    # a number with its own unit keeps it
    ("10 mm,0,2 cm", "length", None, ["10 mm", "0 cm", "2 cm"]),
    ("1 ft,6,2 in", "length", None, ["1 ft", "6 inch", "2 inch"]),
    # bare zeros beside a unit are zero in any unit
    ("10 mm,0,0", "length", None, ["10 mm", "0 m", "0 m"]),
    # no unit at all: the option's bare unit (SI, or degrees for an angle option)
    ("1,2,3", "length", None, ["1 m", "2 m", "3 m"]),
    ("30,45", "angle", "deg", ["30 deg", "45 deg"]),
    ("30,0.5 rad", "angle", "deg", ["30 rad", "0.5 rad"]),
    ("1.5e-3,−2e-3", "length", None, ["1.5e-3 m", "-2e-3 m"]),  # the Unicode minus too
])
def test_unit_rule(text, kind, bare, want):
    n = len(want)
    got = op.numbers(text, kind, "--opt", counts=(n,), bare=bare)
    si_unit = {"length": "m", "angular_speed": "rad/s", "angle": "rad"}[kind]
    for g, w in zip(got, want):
        assert g == pytest.approx(si(w, si_unit), rel=4 * ULP, abs=0.0)


@pytest.mark.parametrize("text, says", [
    ("10 mm,5,0", "unit of 5 is unclear"),  # which unit is 5 in? refused, not guessed
    ("1,2", "expected 3"),
    ("1,,2", "expected 3"),
    ("1,2,3,4 mm", "expected 3"),
    ("1,2,abc", "does not start with a number"),
    ("1,2,3 kg", "a mass, but a length is needed"),
    ("1 kg,2,3 mm", "a mass, but a length is needed"),
    ("1,2,1e999", "out of range"),
    ("inf,0,0 mm", "not a finite number"),
])
def test_unit_rule_refuses(text, says):
    with pytest.raises(InputError) as info:
        op.numbers(text, "length", "opt", counts=(3,))
    assert str(info.value).startswith("opt: ") and says in str(info.value)
    assert info.value.spelled(option_name).startswith("--opt: ")


def test_scalar_quantity_unchanged_and_degrees_exact():
    assert op.quantity("2.5", "length", "--x") == 2.5  # bare: SI
    assert op.quantity("30", "angle", "--x", bare="deg") == pytest.approx(math.pi / 6, rel=ULP)
    assert op.quantity("1500 rpm", "angular_speed", "--x") == pytest.approx(si("1500 rpm", "rad/s"), rel=ULP)
    assert op.degrees("30", "--x") == 30.0  # a bare number of degrees is kept exactly
    assert op.degrees("0.5 rad", "--x") == pytest.approx(math.degrees(0.5), rel=ULP)
    assert op.point("com", "--p") == "com" and op.point("origin", "--p") == "origin"
    assert op.point("0,0,5 cm", "--p") == [0.0, 0.0, pytest.approx(0.05, rel=ULP)]
    with pytest.raises(InputError, match="^x: "):
        op.quantity("3 kg", "length", "x")


# ----------------------------------------------------------------------------- through the CLI


def js(cli, *args: str, code: int = 0) -> dict:
    """``rbcli ARGS --json`` through the ``cli`` fixture: its JSON, after the exit status
    ``code`` (an error, internal (70) or of input (2), fails here with its message)."""
    r = cli(*args, "--json")
    assert r.code == code, r.err
    return r.json()


def test_inertia_about_a_point_with_a_trailing_unit(cli):
    # the lamina about (1,1,1) mm: parallel axes from the com (0.5, 0.5, 0); m = 1, a = 1
    d = js(cli, "inertia", LAMINA, "--about", "1,1,1 mm")
    p = [si("1 mm", "m")] * 3
    assert d["reference"] == [pytest.approx(x, rel=ULP) for x in p]
    same = js(cli, "inertia", LAMINA, "--about", "1 mm,1 mm,1 mm")
    assert same["reference"] == d["reference"] and same["inertia"] == d["inertia"]
    # a component with its own unit keeps it
    d2 = js(cli, "inertia", LAMINA, "--about", "10 mm,0,2 cm")
    assert d2["reference"] == [pytest.approx(0.01, rel=ULP), 0.0, pytest.approx(0.02, rel=ULP)]


def test_inertia_omega_in_rpm_applies_to_every_component(cli):
    d = js(cli, "inertia", LAMINA, "--about", "com", "--omega", "100,0,300 rpm")
    w = [si("100 rpm", "rad/s"), 0.0, si("300 rpm", "rad/s")]
    assert d["omega"] == [pytest.approx(x, rel=4 * ULP) for x in w]
    # T = w.J.w/2 with J about the com of a unit square lamina: diag(1/12, 1/12, 1/6)
    T = 0.5 * (w[0] ** 2 / 12 + w[2] ** 2 / 6)
    assert d["kinetic_energy"] == pytest.approx(T, rel=1e-12)  # a dozen roundings


def test_inertia_axis_is_unitless_and_refuses_a_unit(cli):
    d = js(cli, "inertia", LAMINA, "--axis", "1,1,0")
    assert d["axis_moment"] == pytest.approx(1 / 12, rel=1e-12)  # the diagonal: m a^2/12
    r = cli("inertia", LAMINA, "--axis", "1,1,0 mm")
    assert r.code == 2 and r.out == "" and r.err.startswith("rbcli: --axis: ")  # an InputError
    assert r.err.count("\n") == 1 and "this is a bug" not in r.err


def test_principal_about_with_a_trailing_unit(cli):
    d = js(cli, "principal", LAMINA, "--about", "0,0,5 cm")
    assert d["reference"] == [0.0, 0.0, pytest.approx(0.05, rel=ULP)]


def _two_disk_corrections(zA: float, zB: float, rA: float, rB: float):
    """Example A (balance.md §3.1): U = 1000 + 1600i g·mm, P = 1e5 + 4.8e5i g·mm² about z = 0;
    §2.5: C_A = (P − z_B U)/(z_B − z_A), C_B = (z_A U − P)/(z_B − z_A); mass |C|/r."""
    Uc = complex(1000, 1600) * 1e-6
    P = complex(1e5, 4.8e5) * 1e-9
    CA, CB = (P - zB * Uc) / (zB - zA), (zA * Uc - P) / (zB - zA)
    return (abs(CA) / rA, math.degrees(cmath.phase(CA)) % 360), (abs(CB) / rB, math.degrees(cmath.phase(CB)) % 360)


# 1e-12: a two-plane solve of exact-in-decimal inputs after a few dozen roundings
RT = 1e-12


@pytest.mark.parametrize("planes, radius, bearings", [
    ("0,400 mm", "100 mm", "0,400 mm"),
    ("0,400", "100", "0,400"),  # bare: the body's units (two_disk_rotor.yaml is in mm)
    ("0 mm,40 cm", "10 cm", "0,40 cm"),
])
def test_balance_list_options(cli, planes, radius, bearings):
    d = js(cli, "balance", TWO_DISK, "--planes", planes, "--radius", radius, "--bearings", bearings,
           "--speed", "3000 rpm")
    (mA, aA), (mB, aB) = _two_disk_corrections(0.0, 0.4, 0.1, 0.1)
    A, B = d["corrections"]
    assert (A["plane"], B["plane"]) == (0.0, pytest.approx(0.4, rel=ULP))
    assert A["radius"] == pytest.approx(0.1, rel=ULP) and B["radius"] == pytest.approx(0.1, rel=ULP)
    assert A["mass"] == pytest.approx(mA, rel=RT) and B["mass"] == pytest.approx(mB, rel=RT)
    assert A["angle_deg"] == pytest.approx(aA, abs=1e-9) and B["angle_deg"] == pytest.approx(aB, abs=1e-9)
    assert [f["plane"] for f in d["bearing_forces"]] == [0.0, pytest.approx(0.4, rel=ULP)]


def test_balance_radius_per_plane_and_through_with_a_trailing_unit(cli):
    # two radii, one unit after the last: 100 mm and 200 mm
    d = js(cli, "balance", TWO_DISK, "--planes", "0,400 mm", "--radius", "100,200 mm")
    (mA, _), (mB, _) = _two_disk_corrections(0.0, 0.4, 0.1, 0.2)
    assert [x["radius"] for x in d["corrections"]] == [pytest.approx(0.1, rel=ULP), pytest.approx(0.2, rel=ULP)]
    assert d["corrections"][0]["mass"] == pytest.approx(mA, rel=RT)
    assert d["corrections"][1]["mass"] == pytest.approx(mB, rel=RT)
    # the shaft through (0, 0, 100 mm): planes are measured from there, so -100,300 mm are
    # the same physical planes z = 0 and 0.4 m, and the same masses and angles
    d2 = js(cli, "balance", TWO_DISK, "--through", "0,0,100 mm", "--planes=-100,300 mm", "--radius", "100 mm")
    assert d2["shaft"]["through"] == [0.0, 0.0, pytest.approx(0.1, rel=ULP)]
    (mA, aA), (mB, aB) = _two_disk_corrections(0.0, 0.4, 0.1, 0.1)
    A, B = d2["corrections"]
    assert A["mass"] == pytest.approx(mA, rel=RT) and B["mass"] == pytest.approx(mB, rel=RT)
    assert A["angle_deg"] == pytest.approx(aA, abs=1e-9) and B["angle_deg"] == pytest.approx(aB, abs=1e-9)


def test_balance_shaft_mark_and_zero_mark_with_units(cli):
    base = js(cli, "balance", TWO_DISK)
    # U = 1000 + 1600i g·mm: its angle atan2(1600, 1000) from the 0° mark (sheet §3.1: 57.995°)
    a0 = math.degrees(math.atan2(1600, 1000))
    assert base["static_unbalance_angle_deg"] == pytest.approx(a0, abs=1e-9)
    # --zero-mark-deg turns the mark: the angle drops by as much, in degrees or any angle unit
    for text, turn in (("30", 30.0), ("0.5 rad", math.degrees(0.5)), ("90 deg", 90.0)):
        d = js(cli, "balance", TWO_DISK, "--zero-mark-deg", text)
        assert d["static_unbalance_angle_deg"] == pytest.approx((a0 - turn) % 360, abs=1e-9)
    # --mark along body y: the 0° mark is +y, so U's angle drops by 90°
    d = js(cli, "balance", TWO_DISK, "--shaft", "0,0,1", "--mark", "0,1,0")
    assert d["static_unbalance_angle_deg"] == pytest.approx((a0 - 90) % 360, abs=1e-9)


# ----------------------------------------------------------------------------- the real entry point


def one_line(r, code: int = 2) -> str:
    """The one ``rbcli:`` line on standard error of the run ``r`` (a fixture's Run), after
    checking the exit status, an empty standard output and no traceback or bug report."""
    assert r.code == code, (r.code, r.err)
    assert r.out == ""
    lines = r.err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("rbcli: "), r.err
    assert "Traceback" not in r.err and "this is a bug" not in r.err
    return lines[0]


@pytest.mark.parametrize("args, says", [
    (["inertia", LAMINA, "--digits", "0"], "rbcli: inertia: --digits: "),
    (["inertia", LAMINA, "--no-such-option"], "rbcli: inertia: No such option: --no-such-option"),
    (["balance", TWO_DISK, "--positions", "abc"], "rbcli: balance: --positions: "),
    (["balance", TWO_DISK, "--planes"], "rbcli: balance: Option '--planes' requires an argument"),
    (["field-balance", "--trial", "1 g@0", "--run", "1@0"], "rbcli: field-balance: Missing option '--initial'"),
    (["inertai", LAMINA], "rbcli: No such command 'inertai'. Did you mean 'inertia'?"),
    (["balance", TWO_DISK, "--zero-mark-deg", "5 kg"], "rbcli: --zero-mark-deg: "),
    (["inertia", LAMINA, "--about", "10 mm,5,0"], "rbcli: --about: "),
])
def test_usage_errors_are_one_line(cli_proc, args, says):
    line = one_line(cli_proc(*args))
    assert line.startswith(says), line
    if says.startswith("rbcli: inertia:") or says.startswith("rbcli: balance:") or "field-balance" in says:
        assert line.endswith(f"(see 'rbcli {args[0]} --help')")


def test_help_version_and_debug_still_work(cli_proc):
    p = cli_proc("--version")
    assert p.code == 0 and p.out.strip() == f"rbcli {rbcli.__version__}" and p.err == ""
    p = cli_proc("inertia", "--help")
    assert p.code == 0 and p.out.startswith("Usage: rbcli inertia") and p.err == ""
    p = cli_proc("-h")
    assert p.code == 0 and "Commands:" in p.out
    p = cli_proc("--debug", "inertia", "-e", BOX, "--json")
    assert p.code == 0 and json.loads(p.out)["mass"] == 2.0


@pytest.mark.parametrize("args", [
    ["rollcheck", PENNY, "--radius", "1e300", "--speed", "1"],  # critical spin underflows: 1/0
    ["rollcheck", PENNY, "--speed", "1e300", "--json"],  # the lean frequency overflows
])
def test_numbers_too_large_or_small_exit_2_on_one_line(cli_proc, args):
    line = one_line(cli_proc(*args))
    assert "too large or too small to compute with" in line
    assert line.endswith("check the options and the body's numbers")


@pytest.mark.parametrize("extra", [[], ["--json"]])
def test_gyrocompass_overflow_exits_2_on_one_line(cli_proc, extra):
    # C S W cos(lat)/A = 1e308 * 1e308 * 7.3e-5 * cos 30° overflows: no table of inf and a
    # period of 0, no JSON with a null directive
    line = one_line(cli_proc("gyrocompass", "--ratio", "1e308", "--spin", "1e308", "--latitude", "30", *extra))
    assert line.startswith("rbcli: --ratio, --spin, --earth-rate: the directive torque") and "overflows" in line


def test_rollcheck_table_with_an_overflowed_number_exits_2(cli_proc):
    # at 1e300 m/s the lean frequency overflows to inf: the table refuses it as the JSON does
    line = one_line(cli_proc("rollcheck", PENNY, "--speed", "1e300"))
    assert "'lean oscillation frequency" in line and "is not a finite number (inf)" in line


@pytest.mark.parametrize("exc", [OverflowError("math range error"), ZeroDivisionError("float division by zero"),
                                 FloatingPointError("overflow encountered in multiply")])
def test_arithmetic_errors_are_bad_input_not_bugs(cli, monkeypatch, exc):
    import rbcli.core.inertia as core

    def boom(*a, **k):
        raise exc

    monkeypatch.setattr(core, "inertia_report", boom)
    r = cli("inertia", "-e", BOX)
    assert r.code == 2 and r.out == ""
    assert r.err == (f"rbcli: a value is too large or too small to compute with ({exc}); check the "
                   "options and the body's numbers\n")


def test_internal_error_line_names_debug_and_rbcli_debug(cli, monkeypatch):
    import rbcli.core.inertia as core

    def boom(*a, **k):
        raise RuntimeError("boom")

    monkeypatch.setattr(core, "inertia_report", boom)
    r = cli("inertia", "-e", BOX, env={"RBCLI_DEBUG": None})
    assert r.code == 70 and r.err.count("\n") == 1 and "Traceback" not in r.err
    assert r.err.startswith("rbcli: internal error (RuntimeError: boom); this is a bug")
    assert "'rbcli --debug inertia ...'" in r.err and "RBCLI_DEBUG=1" in r.err
    # the environment variable shows the traceback too
    r = cli("inertia", "-e", BOX, env={"RBCLI_DEBUG": "1"})
    assert r.code == 70 and "Traceback" in r.err and "RuntimeError: boom" in r.err


def test_ctrl_c_is_130(cli, monkeypatch):
    import rbcli.core.inertia as core

    def interrupted(*a, **k):
        raise KeyboardInterrupt

    monkeypatch.setattr(core, "inertia_report", interrupted)
    r = cli("inertia", "-e", BOX)
    assert (r.code, r.out, r.err) == (130, "", "rbcli: interrupted by SIGINT\n")


def test_non_finite_json_is_a_typed_one_line_error():
    from rbcli.api.result import jsonable  # the one check every JSON document passes

    with pytest.raises(NonFiniteResult) as info:
        jsonable({"iso": {"ratio": [1.0, float("inf")]}})
    assert isinstance(info.value, InputError)  # exit 2, not a bug
    text = str(info.value)
    assert text.startswith("the result 'iso.ratio[1]' is not a finite number (inf)")
    assert "this is a bug" not in text and "\n" not in text


def test_tables_refuse_inf_and_nan_in_number_columns_only():
    from rbcli.render.text import Doc

    ok = Doc()
    ok.table("parts", ["name", "mass [kg]"], [["nan", "1"], ["inf", "2"]], right=(1,))  # names
    ok.note("a note may say inf")
    check_finite_doc(ok)
    for cell in ("inf", "-inf", "nan", "1500 rpm = inf", "[1, nan, 0]"):
        bad = Doc()
        bad.kv("dynamics", [("speed", cell, "rad/s")])
        with pytest.raises(NonFiniteResult, match="'speed' in the table 'dynamics' is not a finite number"):
            check_finite_doc(bad)
    fine = Doc()
    fine.kv("numbers", [("tiny", "1e-300", "m"), ("info", "0.5", "")])
    check_finite_doc(fine)


# ----------------------------------------------------------------------------- typer coercion (F13)


AWKWARD = ["7", "+7", "-7", " 7", "07", "1_000", "7.0", "7.5", "1e3", "1E-3", ".5", "5.", "0", "17",
           "18", "999999999999999999999", "1e999", "-1e999", "inf", "nan", "", " ", "abc", "٣", "x,y,z",
           "3000 rpm", "-", "0x10", "1e-400", 6, 6.0, True, False, None, ("a", "b"), ["1", "2"], (),
           ["7", "abc"]]


def test_fast_coercion_equals_typers_and_is_active():
    """Every parameter of every command x awkward values: rbcli's fast coercion gives what
    typer's pydantic coercion gives (value, type, or the same error), as
    ``bench/startup.py --check-coercion`` does; and the fast path is the one typer uses, so a
    typer upgrade that silently turns it off fails here."""
    import typer.main
    from typer import _coercion

    from rbcli.cli.app import _Plain

    group = typer.main.get_command(app)
    compared = plain = 0
    mismatches = []
    for cname, cmd in sorted(group.commands.items()):
        for prm in cmd.params:
            desc = getattr(prm, "type_descriptor", None)
            if desc is None:
                continue
            fast = prm.__class__.get_runtime_param(prm)
            plain += isinstance(fast, _Plain)
            slow = _coercion.build_runtime_param(desc)
            for v in AWKWARD:
                got = []
                for rp in (fast, slow):
                    try:
                        got.append(("ok", rp.coerce(v, param=prm, ctx=None)))
                    except Exception as exc:  # noqa: BLE001 - the error must match too
                        got.append(("error", f"{type(exc).__name__}: {exc}"))
                compared += 1
                if repr(got[0]) != repr(got[1]) or type(got[0][1]) is not type(got[1][1]):
                    mismatches.append(f"{cname} {prm.name} {v!r}: fast {got[0]!r} typer {got[1]!r}")
    assert not mismatches, "\n".join(mismatches[:20])
    assert compared > 1000  # every command's parameters were seen
    # every str/int/float/bool option of rbcli takes the fast path: if none does, typer's
    # layout changed and _fast_coercion left it alone (pydantic is imported on every run)
    assert plain > 50, plain


def test_a_command_run_does_not_import_pydantic(cli_proc):
    r = cli_proc("inertia", "-e", "{shape: box, mass: 2, size: [1, 2, 3]}", "--digits", "4",
                 "--about", "0,0,1 mm", "--json", imports=True)
    assert r.code == 0, r.err
    assert sorted(m for m in r.imported if m.split(".")[0] == "pydantic") == []
    assert "rbcli.cli.massprops" in r.imported  # the check can fail: the run's imports are seen


# ----------------------------------------------------------------------------- lazy commands (issue 16)

def test_command_table_is_the_real_commands():
    """rbcli.cli.app.COMMANDS (what `rbcli --help` lists without importing the command
    modules) names every registered command, in its module, with its real one-line help."""
    import typer.main
    from typer._click.utils import make_default_short_help

    from rbcli.cli.app import COMMANDS, command_tree

    group = command_tree()
    registered = {(i.name or typer.main.get_command_name(i.callback.__name__)): i.callback.__module__
                  for i in app.registered_commands}
    assert registered == {n: f"rbcli.cli.{m}" for n, (m, _) in COMMANDS.items()}
    for name, (_, short) in COMMANDS.items():
        cmd = group.commands[name]
        for limit in (20, 45, 60, 80, 1000):
            assert make_default_short_help(short, limit) == cmd.get_short_help_str(limit), name


def test_a_run_imports_only_its_command(cli_proc):
    """`rbcli --version`, `--help` and a command import no other command's module."""
    for args, want in ((["--version"], ["rbcli.cli.app"]), (["--help"], ["rbcli.cli.app"]),
                       (["inertia", "examples/cube.yaml", "--json"],
                        ["rbcli.cli.app", "rbcli.cli.common", "rbcli.cli.massprops"])):
        r = cli_proc(*args, imports=True)
        assert r.code == 0, r.err
        assert sorted(m for m in r.imported if m.startswith("rbcli.cli.")) == want, args