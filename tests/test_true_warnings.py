"""The rim-speed warnings measure the body's real reach from the spin axis (issue 24, item 3).

Before, every command multiplied the angular speed by the half-diagonal of a box holding
the parts' balls: a 50 mm shaft 1.5 m long at 6000 rpm "moved at 816.9 m/s" (its surface
moves at 15.7 m/s), a disk of radius 0.5 m at 400 rad/s at 424 m/s (200 m/s). The oracle is
the geometry: the reach of a cylinder about its axis is its radius, of a disk its radius, of
a part given only by its moments that of its equivalent uniform ellipsoid.
"""

from __future__ import annotations

import math
import re

import pytest

SHAFT = "{units: {length: mm}, name: shaft, shape: cylinder, diameter: 50, length: 1500, mass: 23}"
DISK = "{name: disk, shape: disk, radius: 0.5, mass: 2}"


def _speeds(text: str) -> list[float]:
    return [float(x) for x in re.findall(r"moves? at ([0-9.e+]+) m/s", text)]


def test_a_shaft_at_6000_rpm_is_not_faster_than_sound(cli):
    r = cli("balance", "-e", SHAFT, "--speed", "6000 rpm")
    assert r.code == 0 and "faster than sound" not in r.err, r.err


def test_a_shaft_fast_enough_says_its_surface_speed(cli):
    # 20 944 rad/s bare (200 000 rpm): 0.025 m x 20944 rad/s = 523.6 m/s at the surface (the
    # box said 27 228)
    r = cli("balance", "-e", SHAFT, "--speed", "20944")
    assert "faster than sound" in r.err
    assert "a radius of 25 mm" in r.err
    assert _speeds(r.err) == [pytest.approx(0.025 * 20944, rel=1e-3)]


@pytest.mark.parametrize("cmd, args", [
    ("balance", ["-e", SHAFT, "--speed", "200000 rpm"]),
    ("inertia", ["-e", DISK, "--omega", "0,0,1000 rad/s"]),
    ("precess", ["examples/earth.yaml", "--omega", "7.292115858e-11,0,7.292115858e-5 rad/s"]),
    ("top", ["examples/top.yaml", "--spin", "5000 rad/s", "--theta", "30"]),
    ("rollcheck", ["examples/penny.yaml", "--speed", "400 m/s"]),
])
def test_a_speed_typed_with_its_unit_is_meant(cli, cmd, args):
    # the warning asks whether a unit is missing: with the unit typed it would be untrue
    # (a turbine's blade tips and the Earth's equator are faster than sound)
    r = cli(cmd, *args)
    assert "faster than sound" not in r.err, r.err


@pytest.mark.parametrize("cmd", ["inertia", "precess"])
def test_a_disk_at_400_rad_s_moves_at_200_m_s(cli, cmd):
    r = cli(cmd, "-e", DISK, "--omega", "0,0,400")
    assert "faster than sound" not in r.err, r.err
    r = cli(cmd, "-e", DISK, "--omega", "0,0,1000")  # 500 m/s at the rim
    assert _speeds(r.err) == [pytest.approx(500.0, rel=1e-3)], r.err


def test_a_disk_about_a_diameter(cli):
    # about x through the com: the rim's farthest points are 0.5 m away too; about x through
    # (0, 0.5, 0) (the rim) the far side is 1 m away
    r = cli("inertia", "-e", DISK, "--omega", "1000,0,0", "--about", "0,0.5,0")
    assert _speeds(r.err) == [pytest.approx(1000.0, rel=1e-3)], r.err


def test_the_earth_is_measured_as_its_equivalent_ellipsoid(cli):
    # examples/earth.yaml is a given part (mass and moments only): its extent is that of the
    # uniform ellipsoid of those moments, semi-axis sqrt(5 Izz/(2 m)) = 5800 km across the
    # axis (the real Earth, denser inside, is 6371 km): 422.9 m/s (the box said 981.6)
    r = cli("precess", "examples/earth.yaml", "--omega", "7.292115858e-11,0,7.292115858e-5")
    (v,) = _speeds(r.err)
    assert v == pytest.approx(math.sqrt(2.5 * 8.034e37 / 5.972e24) * 7.292115858e-5, rel=1e-3)


def test_a_top_spun_about_its_axis(cli):
    # examples/top.yaml: a 160 mm disk on a 40 mm titanium body: the disk's rim, 80 mm from
    # the axis, at 5000 rad/s moves at 400 m/s (the box said more)
    r = cli("top", "examples/top.yaml", "--spin", "5000", "--theta", "30")
    assert _speeds(r.err) == [pytest.approx(400.0, rel=1e-3)], r.err
    r = cli("top", "examples/top.yaml", "--spin", "4000", "--theta", "30")  # 320 m/s
    assert "faster than sound" not in r.err, r.err


def test_the_api_warns_alike():
    import rbcli

    assert not rbcli.balance(rbcli.load_text(SHAFT), speed="6000 rpm").warnings
    assert rbcli.inertia(rbcli.load_text(DISK), omega=[0, 0, 1000]).warnings


# ------------------------------------------------------- stability labels agree with the motion


def test_a_flipping_spin_is_not_stable(cli):
    """The notebook (I = 1 : 2 : 3) spun near its intermediate axis flips every 19.55 s: the
    motion reported is the tennis-racket flip, not a stable rotation (issue 24, item 3)."""
    d = cli("precess", "examples/book.yaml", "--omega", "0.01,1,0.01", "--json").json()
    assert d["flip_interval"] == pytest.approx(19.5529, rel=1e-5)
    assert d["stable"] is False
    text = cli("precess", "examples/book.yaml", "--omega", "0.01,1,0.01").out
    (row,) = [line for line in text.splitlines() if line.startswith("stable ")]
    assert row.split("|")[1].strip() == "no: it flips over"


def test_a_wobble_about_the_largest_axis_is_stable(cli):
    d = cli("precess", "examples/book.yaml", "--omega", "0.2,0.1,1", "--json").json()
    assert d["flip_interval"] is None and d["circles_axis"] == 3 and d["stable"] is True


def test_the_separatrix_and_the_intermediate_axis_are_not_stable(cli):
    # I = diag(1, 2, 3), omega0 = (0.1 sqrt 3, 1, 0.1): G² = 2 T I2 (sheet case P8)
    body = "{shape: given, mass: 1, inertia: [[1, 0, 0], [0, 2, 0], [0, 0, 3]], convention: tensor}"
    d = cli("precess", "-e", body, "--omega", f"{0.1 * math.sqrt(3)!r},1,0.1", "--json").json()
    assert d["case"] == "separatrix" and d["stable"] is False
    d = cli("precess", "-e", body, "--omega", "0,1,0", "--json").json()
    assert d["case"] == "steady" and d["stable"] is False


def test_a_symmetric_body_about_a_transverse_axis_is_neutral(cli):
    d = cli("precess", "examples/penny.yaml", "--omega", "1,0,0", "--json").json()
    assert d["stable"] is None
    text = cli("precess", "examples/penny.yaml", "--omega", "1,0,0").out
    (row,) = [line for line in text.splitlines() if line.startswith("stable ")]
    assert row.split("|")[1].strip() == "neutral"
