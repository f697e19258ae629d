"""Issue 13: a number the user typed never silently means something else.

Each behaviour through the real command line (``cli`` fixture) and the Python API: bare
numbers in the body's units (inches, mm, rpm), the options echo, plausibility warnings,
spellings people use, diameters, the convention of a given 3×3 inertia. The README's two
example lines are checked against numbers computed here by hand (point masses and the
parallel-axis theorem), independently of rbcli.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import rbcli
from conftest import as_cli

ROOT = Path(__file__).resolve().parent.parent
BRACKET = str(ROOT / "examples/bracket.yaml")
ROTOR = str(ROOT / "examples/rotor_mm.yaml")
IN = 0.0254
LB = 0.45359237


def test_inch_body_bare_point_is_inches(cli):
    d = cli("inertia", BRACKET, "--about", "0.5,0.5,0", "--json").json()
    assert d["reference"] == pytest.approx([0.5 * IN, 0.5 * IN, 0.0], rel=1e-15)
    # parallel axes by hand from the com inertia
    m, G, Jg = d["mass"], np.array(d["com"]), np.array(d["inertia_com"])
    r = G - d["reference"]
    J = Jg + m * (r @ r * np.eye(3) - np.outer(r, r))
    assert np.allclose(d["inertia"], J, rtol=1e-12, atol=1e-15)
    # the README's numbers: Ixx = 26.5093 lb·in² about [0.5, 0.5, 0] in
    assert d["inertia"][0][0] / (LB * IN**2) == pytest.approx(26.5093, rel=1e-5)
    api = rbcli.inertia(rbcli.load(BRACKET), about="0.5,0.5,0")
    assert api.reference == pytest.approx(d["reference"]) and api.reference_label == "[0.5,0.5,0 in]"
    # a Python number is SI
    assert rbcli.inertia(rbcli.load(BRACKET), about=[0.5, 0.5, 0.0]).reference.tolist() == [0.5, 0.5, 0.0]


def test_table_echoes_the_options_with_units(cli):
    r = cli("inertia", BRACKET, "--about", "0.5,0.5,0")
    assert r.code == 0
    assert "options" in r.out.splitlines()[1]
    row = next(line for line in r.out.splitlines() if line.startswith("--about"))
    assert "0.5, 0.5, 0" in row and row.rstrip().endswith("in")
    assert "inertia about [0.5,0.5,0 in]" in r.out
    r = cli("balance", ROTOR, "--radius", "180", "--planes=-50,50", "--speed", "3000")
    speed = next(line for line in r.out.splitlines() if line.startswith("--speed"))
    assert "3000 (314.159 rad/s)" in speed and speed.rstrip().endswith("rpm")
    # JSON is SI and has no echo
    d = cli("balance", ROTOR, "--radius", "180", "--planes=-50,50", "--speed", "3000", "--json").json()
    assert "options" not in d and d["dynamics"]["speed"] == pytest.approx(100 * math.pi)


def _row(out: str, option: str) -> list[str]:
    line = next(x for x in out.splitlines() if x.startswith(option + " "))
    return [c.strip() for c in line.split("|")]


@pytest.mark.parametrize("args, option, value, unit", [
    # issue 24.5: a value is echoed in the unit typed, whatever the body's units
    (("--mass-step", "0.5 g"), "--mass-step", "0.5", "g"),
    (("--mass-step", "2 oz"), "--mass-step", "2", "oz"),
    (("--speed", "314.159265358979 rad/s"), "--speed", "314.159 (3000 rpm)", "rad/s"),
    (("--radius", "7.08661 in"), "--radius", "7.08661", "in"),
    (("--planes", "-5,5 cm"), "--planes", "-5, 5", "cm"),
    # a bare number: the body's unit (mm, g, rpm)
    (("--mass-step", "0.5"), "--mass-step", "0.5", "g"),
    (("--speed", "3000"), "--speed", "3000 (314.159 rad/s)", "rpm"),
])
def test_the_echo_is_in_the_unit_typed(cli, args, option, value, unit):
    base = {"--radius": "180", "--planes": "-50,50", "--speed": "3000"}
    base[args[0]] = args[1]
    argv = [x for kv in base.items() for x in kv]
    if args[0] == "--mass-step":
        argv += list(args)
    r = cli("balance", ROTOR, *argv)
    assert r.code == 0, r.err
    assert _row(r.out, option)[1:] == [value, unit]


def test_the_echo_in_a_typed_unit_is_the_value_read():
    # the same numbers reach the computation whichever unit the echo shows
    body = rbcli.load(ROTOR)
    a = rbcli.balance(body, radius="180", planes="-50,50", mass_step="0.5 g")
    b = rbcli.balance(body, radius="18 cm", planes="-5,5 cm", mass_step="0.0005 kg")
    assert a.to_json() == b.to_json()
    from rbcli.api.balance import parse

    oa = parse(body, radius="180", planes="-50,50", mass_step="0.5 g")
    ob = parse(body, radius="18 cm", planes="-5,5 cm", mass_step="0.0005 kg")
    assert dict(oa.typed) == {"mass_step": "g"}
    assert dict(ob.typed) == {"radius": "cm", "planes": "cm", "mass_step": "kg"}


@pytest.mark.parametrize("args, says", [
    (("--radius", "-180"), "--radius: the correction radius must be a positive number, got -180 mm"),
    (("--radius", "-0.18 m"), "--radius: the correction radius must be a positive number, got -180 mm"),
    (("--speed", "-3"), "must be a positive number, got -3 rpm"),
    (("--mass-step", "0"), "--mass-step: the mass step must be a positive number, got 0 g"),
])
def test_errors_quote_the_value_with_its_unit(cli, args, says):
    base = {"--radius": "180", "--planes": "-50,50"}
    base[args[0]] = args[1]
    r = cli("balance", ROTOR, *[x for kv in base.items() for x in kv])
    assert r.code == 2 and says in r.err, r.err


def _rotor_by_hand():
    """The rotor's corrections from its two point masses (the disk and shaft are centred):
    u_A + u_B = -U, z_A u_A + z_B u_B = -P, with U = Σ m r and P = Σ m r z (g·mm)."""
    masses = [(20.0, np.array([150.0, 0.0]), 10.0), (12.0, np.array([0.0, -120.0]), -40.0)]
    U = sum(m * r for m, r, _ in masses)
    P = sum(m * r * z for m, r, z in masses)
    zA, zB = -50.0, 50.0
    uB = (-P + zA * U) / (zB - zA)
    uA = -U - uB
    return [(np.linalg.norm(u) / 180.0, math.degrees(math.atan2(u[1], u[0])) % 360) for u in (uA, uB)]


def test_mm_rotor_bare_numbers_give_the_hand_answer(cli):
    d = cli("balance", ROTOR, "--radius", "180", "--planes=-50,50", "--speed", "3000", "--json").json()
    got = [(c["mass"] * 1000, c["angle_deg"]) for c in d["corrections"]]
    for (m, a), (em, ea) in zip(got, _rotor_by_hand()):
        assert m == pytest.approx(em, rel=1e-9) and a == pytest.approx(ea, abs=1e-7)
    assert [c["radius"] for c in d["corrections"]] == [pytest.approx(0.18)] * 2
    assert [c["plane"] for c in d["corrections"]] == [pytest.approx(-0.05), pytest.approx(0.05)]
    # README: 9.81246 g at 132.797° and 10.0319 g at 175.426°
    assert got[0][0] == pytest.approx(9.81246, rel=1e-6) and got[1][0] == pytest.approx(10.0319, rel=1e-5)
    body = rbcli.load(ROTOR)
    api = rbcli.balance(body, radius="180", planes="-50,50", speed="3000")
    d.pop("file")
    assert as_cli(api.to_json()) == d
    same = rbcli.balance(body, radius=0.18, planes=[-0.05, 0.05], speed=100 * math.pi)  # SI numbers
    assert same.to_json()["corrections"] == d["corrections"]


def test_far_values_warn_with_the_option_named(cli):
    r = cli("balance", ROTOR, "--radius", "180 m", "--planes=-50,50", "--speed", "3000")
    assert r.code == 0
    lines = r.err.splitlines()
    assert len(lines) >= 1 and all("\n" not in x for x in lines)
    assert any("--radius:" in x and "more than 10× the body's size" in x for x in lines)
    assert any("--speed:" in x and "faster than sound" in x for x in lines)
    res = rbcli.balance(rbcli.load(ROTOR), radius="180 m", planes="-50,50", speed="3000")
    assert any(w.startswith("radius:") for w in res.warnings)  # the API names the parameter
    assert any(w.startswith("--radius:") for w in cli("balance", ROTOR, "--radius", "180 m", "--planes=-50,50",
                                                          "--json").json()["warnings"])
    # a pivot far away, a rolling rim faster than sound
    r = cli("top", str(ROOT / "examples/top.yaml"), "--spin", "150", "--theta", "30", "--pivot", "0,0,10")
    assert r.code == 0 and "--pivot:" in r.err
    res = rbcli.top(rbcli.load(ROOT / "examples/top.yaml"), spin=150, theta=30, pivot="0,0,10")
    assert any("pivot:" in w and "--" not in w for w in res.warnings)
    r = cli("rollcheck", str(ROOT / "examples/penny.yaml"), "--speed", "400", "--json")
    assert any("--speed:" in w and "faster than sound" in w for w in r.json()["warnings"])
    # a plausible value says nothing
    r = cli("balance", ROTOR, "--radius", "180", "--planes=-50,50", "--speed", "3000")
    assert r.err == ""


def test_a_lone_point_mass_has_no_size_to_judge_a_distance_by_and_points_apart_have_one(cli):
    point = "{shape: point, mass: 1, at: [0.1, 0, 0]}"
    r = cli("balance", "-e", point, "--planes", "0,1", "--radius", "0.1", "--bearings", "0,1")
    assert r.code == 0 and "body's size" not in r.err and "1e-300" not in r.err
    r = cli("inertia", "-e", point, "--about", "5,0,0")
    assert r.code == 0 and r.err == ""
    # two points 10 mm apart: the size is their extent, 10 mm; 0.5 m and 1 m are beyond 10x it
    two = "{parts: [{shape: point, mass: 1, at: [0.01, 0, 0]}, {shape: point, mass: 1, at: [0, 0, 0]}]}"
    lines = cli("balance", "-e", two, "--planes", "0,1", "--radius", "0.5", "--bearings", "0,1").err.splitlines()
    for opt in ("--radius", "--planes", "--bearings"):
        assert any(x.startswith(f"rbcli: warning: {opt}:") and "body's size (0.01 m)" in x for x in lines), opt


def test_angular_speed_unit_of_the_body(cli):
    body = rbcli.load_text("units: {angular_speed: RPM}\nparts:\n  - {shape: box, mass: 1, size: [0.1, 0.2, 0.3]}\n")
    res = rbcli.inertia(body, omega="0,0,60")
    assert res.omega.tolist() == [0.0, 0.0, pytest.approx(2 * math.pi)]
    r = cli("inertia", "-e", "{units: {angular_speed: rpm}, shape: box, mass: 1, size: [0.1, 0.2, 0.3]}",
            "--omega", "0,0,60", "--json")
    assert r.json()["omega"][2] == pytest.approx(2 * math.pi)
    r = cli("inertia", "-e", "{units: {angular_speed: Hz}, shape: box, mass: 1, size: [1, 1, 1]}")
    assert r.code == 2 and "angular_speed" in r.err


def test_spellings_and_diameters_through_the_cli_and_the_api(cli):
    text = ("parts:\n  - {shape: cylinder, diameter: '2 in', inner_diameter: 1 in, length: '1 in', "
            "density: 7.85 g/cc}\n")
    ref = ("parts:\n  - {shape: cylinder, radius: 0.0254, inner_radius: 0.0127, length: 0.0254, "
           "density: 7850}\n")
    a, b = rbcli.inertia(rbcli.load_text(text)), rbcli.inertia(rbcli.load_text(ref))
    assert a.mass == pytest.approx(b.mass, rel=1e-15)
    assert np.allclose(a.inertia_com, b.inertia_com, rtol=1e-14)
    r = cli("inertia", "-e", "{shape: box, mass: 1 slug, size: [1, 1, 1]}", "--json")
    assert r.json()["mass"] == pytest.approx(14.593902937206364)
    r = cli("inertia", "-e", "{shape: box, mass: 2 KG, size: [1, 1, 1]}", "--omega", "0,0,30 RPM", "--json")
    assert r.code == 0 and r.json()["mass"] == 2.0 and r.json()["omega"][2] == pytest.approx(math.pi)
    r = cli("inertia", "-e", "{shape: box, mass: 2 MG, size: [1, 1, 1]}")
    assert r.code == 2 and "unknown unit 'MG'" in r.err
    r = cli("inertia", "-e", "{shape: disk, mass: 1, radius: 1, diameter: 2}")
    assert r.code == 2 and "'radius' or 'diameter', not both" in r.err


def test_given_matrix_convention(cli):
    J = "[[2, 0.3, 0], [0.3, 3, 0], [0, 0, 4]]"
    r = cli("inertia", "-e", f"{{shape: given, mass: 1, inertia: {J}}}")
    assert r.code == 2 and "convention: tensor" in r.err
    t = cli("inertia", "-e", f"{{shape: given, mass: 1, inertia: {J}, convention: tensor}}", "--json").json()
    p = cli("inertia", "-e", f"{{shape: given, mass: 1, inertia: {J}, convention: positive}}", "--json").json()
    assert t["inertia_com"][0][1] == 0.3 and p["inertia_com"][0][1] == -0.3
    body = rbcli.load_text(f"parts:\n  - {{shape: given, mass: 1, inertia: {J}, convention: positive}}\n")
    assert rbcli.inertia(body).inertia_com[0, 1] == -0.3


def test_impossible_inertia_in_the_files_units(cli):
    r = cli("inertia", "-e", "{units: {length: mm, mass: g}, shape: given, mass: 100, "
            "inertia: [[1000, 0, 0], [0, 1000, 0], [0, 0, 2500]]}")
    assert r.code == 2 and "1000, 1000, 2500 g·mm²" in r.err
    with pytest.raises(rbcli.InputError, match="g·mm²"):
        rbcli.load_text("units: {length: mm, mass: g}\nparts:\n  - {shape: given, mass: 100, "
                        "inertia: [[1000, 0, 0], [0, 1000, 0], [0, 0, 2500]]}\n")


@pytest.mark.parametrize("text, says", [
    ("units: {length: mm}\nshape: cylinder\nmass: 1\nradius: 10\ninner_radius: 20\nlength: 5\n",
     "inner_radius (20 mm) must be less than radius (10 mm)"),
    ("units: {length: mm}\nshape: disk\nmass: 1\nradius: -10\n", "(got -10 mm)"),
    ("units: {length: in}\nshape: torus\nmass: 1\nmajor_radius: 1\nminor_radius: 2\n",
     "minor_radius (2 in) must not exceed major_radius (1 in)"),
    ("shape: box\nmass: 1\nsize: [1, -2, 3]\n", "size[1] must be greater than 0 (got -2 m)"),
])
def test_shape_errors_quote_lengths_in_the_files_units(cli, text, says):
    r = cli("inertia", "-", input=text)
    assert r.code == 2 and says in r.err, r.err
    with pytest.raises(rbcli.InputError) as exc:
        rbcli.load_text(text)
    assert says in str(exc.value)
