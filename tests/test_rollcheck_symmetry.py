"""Nearly symmetric wheels in ``rollcheck`` (issue 14.2): ``--symmetry-tol``.

A wheel from CAD is of revolution only to its modelling: a valve on the rim makes the two
moments across the axle differ and puts the centre of mass off the axle. Within the
tolerance (default 1 %) the wheel is answered for its symmetrised form (the mean moment
across, the com on the axle) with one located warning, a table line and the JSON key
``asymmetry``; beyond it, refused with the numbers and the option. The bound on the error
(``asymmetry_effect``) is checked against the critical speeds computed with either
transverse moment.
"""

from __future__ import annotations

import math

import pytest

import rbcli
from conftest import as_cli
from rbcli.errors import option_name
from rbcli.core.rolling import straight

RING = "{shape: ring, radius: 0.3, mass: 1}"


def valve_wheel(valve_kg: float) -> str:
    """A 1 kg hoop of radius 0.3 m with a valve (a point mass) on its rim: the moments
    across differ by about 2 valve/hoop mass, the com is valve/(1 + valve) of a off the axle."""
    return f"{{parts: [{RING}, {{shape: point, mass: {valve_kg!r}, at: [0.3, 0, 0]}}]}}"


#: symmetric to 0.01 %: a 50 mg valve on a 1 kg hoop
CAD = valve_wheel(5e-5)
#: 1.5 %: a 7.5 g valve
LOPSIDED = valve_wheel(7.5e-3)


@pytest.fixture
def as_file(tmp_path):
    """Write a body to a temporary file: ``as_file(text) -> its path``."""

    def write(text: str, name: str = "wheel.yaml") -> str:
        (tmp_path / name).write_text(text + "\n")
        return str(tmp_path / name)

    return write


def test_cad_wheel_answered_with_warning_and_asymmetry(cli, as_file):
    f = as_file(CAD)
    body = rbcli.load(f)
    res = rbcli.rollcheck(body)
    a = res.asymmetry
    assert a is not None and 0.9e-4 < a.relative < 1.1e-4  # 0.01 %
    assert a.com_offset == pytest.approx(0.3 * 5e-5 / (1 + 5e-5), rel=1e-9)
    assert a.com_offset_relative == pytest.approx(5e-5 / (1 + 5e-5), rel=1e-9)
    # the symmetrised wheel: I the mean of the two moments across, about the com
    assert res.wheel.A == pytest.approx(0.5 * sum(a.transverse), rel=1e-15)
    assert len(res.warnings) == 1
    w = res.warnings[0]
    assert w.startswith("the wheel is not exactly symmetric about its axle: the moments across it "
                        "differ by 0.01 %") and "of the rim radius off it" in w
    assert w.endswith("the answer is for the symmetrised wheel (symmetry_tol 1 %)")
    d = res.to_json()
    assert d["asymmetry"] == a.to_json(0.01)
    assert set(d["asymmetry"]) == {"transverse_moments", "relative", "coupling", "coupling_relative",
                                   "principal_axis_tilt", "com_offset", "com_offset_relative",
                                   "tolerance"}
    assert d["warnings"] == [w]
    # the command line: the same JSON, the warning once on standard error, located
    r = cli("rollcheck", f, "--json")
    assert r.code == 0 and r.err == f"rbcli: {f}: warning: {w.spelled(option_name)}\n"
    assert {k: v for k, v in r.json().items() if k != "file"} == as_cli(d)
    # the table says how far the answer may be off
    r = cli("rollcheck", "-e", CAD)
    table = " ".join(r.out.split())
    assert r.code == 0 and "nearly symmetric wheel: the moments across the axis are" in table
    assert "--symmetry-tol 1 %" in table and "may be off by a relative amount of the order of" in table


def test_symmetric_wheel_has_no_asymmetry(cli):
    res = rbcli.rollcheck(rbcli.load_text(RING))
    assert res.asymmetry is None and res.asymmetry_effect is None and res.warnings == ()
    assert "asymmetry" not in res.to_json()
    r = cli("rollcheck", "-e", RING)
    assert r.code == 0 and r.err == "" and "nearly symmetric" not in r.out


def test_beyond_the_tolerance_refused_with_the_numbers(cli, as_file):
    f = as_file(LOPSIDED)
    body = rbcli.load(f)
    with pytest.raises(rbcli.InputError) as e:
        rbcli.rollcheck(body)
    msg = e.value.spelled(option_name)  # as the command line prints it
    assert "not a body of revolution about the axle: the moments across it are 0.045 and 0.04567 kg m²" in msg
    assert "(differ by 1.5 %)" in msg and "--symmetry-tol (1 %)" in msg
    assert "symmetry_tol (1 %)" in str(e.value) and "--" not in str(e.value)  # the API's: the parameter
    r = cli("rollcheck", f)
    assert r.code == 2 and r.out == "" and r.err == f"rbcli: {msg}\n"
    # a tiny difference still prints with digits enough to tell the two moments apart
    with pytest.raises(rbcli.InputError) as e:
        rbcli.rollcheck(rbcli.load_text(CAD), symmetry_tol=0)
    m = str(e.value)
    i1, i2 = m.split("the moments across it are ")[1].split(" kg m²")[0].split(" and ")
    assert i1 != i2 and "symmetry_tol (0 %)" in m


def test_wider_tolerance_accepts_a_1_5_percent_wheel(cli, as_file):
    f = as_file(LOPSIDED)
    body = rbcli.load(f)
    for tol in ("2%", "2 %", 0.02, "0.02"):
        res = rbcli.rollcheck(body, symmetry_tol=tol)
        assert res.options.symmetry_tol == pytest.approx(0.02)
        assert res.asymmetry.relative == pytest.approx(0.0148, abs=1e-4)
        assert res.warnings[0].endswith("(symmetry_tol 2 %)")
    r = cli("rollcheck", f, "--symmetry-tol", "2%", "--speed", "3", "--json")
    d = rbcli.rollcheck(body, symmetry_tol="2%", rolling_speed=3).to_json()
    assert r.code == 0 and {k: v for k, v in r.json().items() if k != "file"} == as_cli(d)
    assert d["asymmetry"]["tolerance"] == 0.02


@pytest.mark.parametrize("valve", [5e-5, 1e-3, 7.5e-3, 2e-2])
def test_the_bound_holds_between_the_two_transverse_moments(valve):
    """The true threshold lies between the ones computed with either moment across (the
    wheel's moment about its fore-aft diameter swings between them); the symmetrised
    answer is within ``asymmetry_effect`` of both: s_c ∝ sqrt(I), |sqrt(1 ± δ/2) - 1| <=
    δ/(4 - δ)."""
    res = rbcli.rollcheck(rbcli.load_text(valve_wheel(valve)), symmetry_tol="10 %")
    a, w = res.asymmetry, res.wheel
    o, g = res.setup, res.options.g
    # s_c² = m g (a - r) A / (C (C + m a²)) (rbcli.core.rolling.straight) with A = I1, then I2
    # (the hoop's C = I1 + I2 exceeds 2 I1, so no Wheel can be built with I1 alone)
    m, C, r_a = w.mass, w.C, o.radius
    v = [r_a * math.sqrt(m * g * (r_a - o.tyre_radius) * Ai / (C * (C + m * r_a**2)))
         for Ai in a.transverse]
    assert straight(w, o.radius, o.tyre_radius, g).critical_speed == res.critical_speed
    assert v[0] < res.critical_speed < v[1]
    d = a.relative
    moments_bound = d / (4.0 - d)
    for vi in v:
        assert abs(vi / res.critical_speed - 1.0) <= moments_bound
    assert moments_bound <= res.asymmetry_effect
    # the bound is tight to first order: δ/4
    assert abs(v[0] / res.critical_speed - 1.0) == pytest.approx(d / 4, rel=d)


def test_axle_not_principal_follows_the_same_rule(cli):
    # a thin disk tilted on its axle: products of inertia couple the axle to the plane across
    def tilted(deg):
        return ("{shape: disk, radius: 0.2, mass: 20, rotate: {axis: [0, 1, 0], angle: %r}}" % deg)

    res = rbcli.rollcheck(rbcli.load_text(tilted(0.5)), rim_radius=0.2)
    # coupling (C - A) sin(2θ)/2 = 0.2 sin 1° / 2 = 1.745e-3 kg m², 0.87 % of A = 0.2
    assert res.asymmetry.coupling_relative == pytest.approx(0.2 * math.sin(math.radians(1)) / 2 / 0.2, rel=1e-4)
    assert "products of inertia with the plane across are 0.87 %" in res.warnings[0]
    with pytest.raises(rbcli.InputError) as e:
        rbcli.rollcheck(rbcli.load_text(tilted(0.5)), rim_radius=0.2, symmetry_tol="0.5 %")
    assert "the axle is not a principal axis" in str(e.value) and "symmetry_tol (0.5 %)" in str(e.value)
    r = cli("rollcheck", "-e", tilted(2), "--radius", "0.2")
    assert r.code == 2 and "not a principal axis" in r.err and "2° away" in r.err
    assert "3.5 % of the moment across" in r.err and "--symmetry-tol (1 %)" in r.err


def test_car_wheel_example_now_answered():
    # examples/car_wheel.yaml: a disk tilted 0.5° on its axle: 0.87 % (the products) < 1 %
    res = rbcli.rollcheck(rbcli.load("examples/car_wheel.yaml"))
    assert res.asymmetry is not None and res.asymmetry.coupling_relative < 0.01
    assert res.critical_speed == pytest.approx(math.sqrt(9.80665 * 0.2 / 3), rel=1e-4)


@pytest.mark.parametrize("value", ["11 %", "-1%", "abc", "0.2"])
def test_bad_symmetry_tolerance(cli, value):
    with pytest.raises(rbcli.InputError) as e:
        rbcli.rollcheck(rbcli.load_text(RING), symmetry_tol=value)
    assert e.value.param == "symmetry_tol" and str(e.value).startswith("symmetry_tol: ")
    r = cli("rollcheck", "-e", RING, "--symmetry-tol", value)
    assert r.code == 2 and r.err == f"rbcli: {e.value.spelled(option_name)}\n"


def test_tilted_rim_part_still_found_as_the_rim(cli):
    # a CAD wheel tilted 0.005° on its axle, with no rim_radius: the disk is still the rim
    # (within --symmetry-tol), answered for the symmetrised wheel: v_c = sqrt(g a/3)
    body = "{shape: disk, radius: 0.2, mass: 20, rotate: {axis: [0, 1, 0], angle: 0.005}}"
    d = cli("rollcheck", "-e", body, "--json").json()
    assert d["radius_source"] == "largest_round_part" and d["radius"] == 0.2
    assert d["critical_speed"] == pytest.approx(math.sqrt(9.80665 * 0.2 / 3), rel=1e-6)
    assert d["asymmetry"]["principal_axis_tilt"] == pytest.approx(math.radians(0.005), rel=1e-3)
    # with the rounding tolerance it is neither a rim nor a body of revolution
    r = cli("rollcheck", "-e", body, "--symmetry-tol", "0")
    assert r.code == 2
