"""The foundation's bundled examples print the numbers their header comments claim.

Each expected value is computed here, independently, from the closed form of the course
text or by hand from the drawing (volumes times density, moments of volumes), never taken
from rbcli's output. Also: every example in examples/ loads, and every ``rbcli ...``
command line in any example's header runs (exit 0, or 1 for a check it asks for), so
later examples are covered too.
"""

from __future__ import annotations

import json
import math
import re
import shlex
from pathlib import Path

import numpy as np
import pytest
from rbcli.body.model import load_body

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = sorted((ROOT / "examples").glob("*.yaml"))
IN, LB = 0.0254, 0.45359237  # exact by definition (NIST SP 811)


@pytest.fixture(autouse=True)
def _at_root(monkeypatch):
    monkeypatch.chdir(ROOT)  # the header commands name examples/... relative to the repo


@pytest.fixture
def printed(cli):
    """``printed(*args)``: standard output of ``rbcli ARGS`` (the ``cli`` fixture), exit 0."""

    def go(*args: str) -> str:
        r = cli(*args)
        assert r.code == 0, (args, r.err)
        return r.out

    return go


@pytest.fixture
def js(printed):
    """``js(*args)``: the JSON of ``rbcli ARGS --json``."""
    return lambda *args: json.loads(printed(*args, "--json"))


# --------------------------------------------------------------------------- the five

def test_square_lamina_about_a_corner(printed, js):
    m, a = 1.0, 1.0  # the file: a 1 m square plate of 1 kg with a corner at the origin
    j = js("inertia", "examples/square_lamina.yaml", "--axis", "1,1,0", "--omega", "1,0,0")
    course = m * a * a * np.array([[1 / 3, -1 / 4, 0], [-1 / 4, 1 / 3, 0], [0, 0, 2 / 3]])
    # a handful of operations on O(1) numbers: round-off only
    np.testing.assert_allclose(j["inertia"], course, rtol=1e-12, atol=1e-15)
    assert j["axis_moment"] == pytest.approx(m * a * a / 12, rel=1e-12)
    # L = J w for w = (1, 0, 0): (1/3, -1/4, 0) m a^2 -- a y-component
    np.testing.assert_allclose(j["angular_momentum"], course[:, 0], rtol=1e-12, atol=1e-15)
    # the header's printed number: m a^2/12 = 0.0833333 to six figures
    assert "0.0833333" in printed("inertia", "examples/square_lamina.yaml", "--axis", "1,1,0")
    p = js("principal", "examples/square_lamina.yaml", "--about", "origin")
    s = 1 / math.sqrt(2)
    np.testing.assert_allclose(p["axes"][0], [s, s, 0], atol=1e-12)  # along the diagonal
    # across it, signed so that the axes are the rotation nearest the body axes (45° about z)
    np.testing.assert_allclose(p["axes"][1], [-s, s, 0], atol=1e-12)
    assert p["rotation_angle_deg"] == pytest.approx(45.0, rel=1e-12)
    np.testing.assert_allclose(p["moments"], [1 / 12, 7 / 12, 2 / 3], rtol=1e-12)


def test_rectangular_block_about_a_corner(js):
    m, a, b, c = 12.0, 0.3, 0.2, 0.1
    j = js("inertia", "examples/rectangular_block.yaml")
    # about a corner: Ixx = m (b^2 + c^2)/3; the tensor's Jxy = -m a b/4, Jxz = -m a c/4
    want = [m * (b * b + c * c) / 3, -m * a * b / 4, -m * a * c / 4]
    assert want == pytest.approx([0.2, -0.18, -0.09], rel=1e-12)  # the header's numbers
    np.testing.assert_allclose(j["inertia"][0], want, rtol=1e-12)


def test_cube_is_spherical(printed, js):
    rho, a = 7850.0, 0.1
    m = rho * a**3  # 7.85 kg
    j = js("principal", "examples/cube.yaml")
    assert j["symmetry"] == "spherical"
    np.testing.assert_allclose(j["moments"], [m * a * a / 6] * 3, rtol=1e-12)
    assert "0.0130833" in printed("principal", "examples/cube.yaml")  # m a^2/6 to six figures


def test_two_blade_fan_principal_axes_at_45_degrees(js):
    m, L = 0.5, 0.4
    j = js("principal", "examples/two_blade_fan.yaml")
    # about the com (L/4, L/4, 0): Jxx = Jyy = 5 m L^2/24, Jxy = +m L^2/8 (by hand), so
    # tan 2 theta = 2 Ixy / (Ixx - Iyy) -> infinity: theta = 45 degrees; the moments
    # 5/24 -+ 3/24 m L^2: m L^2/12 across the bisector, m L^2/3 along it
    np.testing.assert_allclose(j["moments"], [m * L * L / 12, m * L * L / 3, 5 * m * L * L / 12], rtol=1e-12)
    axis_along = np.array(j["axes"][1])
    assert math.degrees(math.atan2(axis_along[1], axis_along[0])) == pytest.approx(45.0, abs=1e-9)
    s = 1 / math.sqrt(2)
    np.testing.assert_allclose(j["axes"][0], [s, -s, 0], atol=1e-12)


def test_two_blade_fan_header_claim_for_axis_1(js):
    header = (ROOT / "examples" / "two_blade_fan.yaml").read_text()
    claim = re.search(r"axis 1 = \(([^)]*)\)", header).group(1)
    want = [float(x) for x in claim.split(",")]
    np.testing.assert_allclose(js("principal", "examples/two_blade_fan.yaml")["axes"][0], want, atol=1e-6)


def test_bracket_in_shop_units(printed, js):
    rho = 0.284  # lb/in^3
    # (volume in^3, centroid in): base 6 x 4 x 0.5, upright 0.5 x 4 x 3, two 0.5 in holes x 0.5 deep
    hole = math.pi * 0.25**2 * 0.5
    pieces = [(6 * 4 * 0.5, (3, 2, 0.25)), (0.5 * 4 * 3, (0.25, 2, 2)),
              (-hole, (4.5, 1, 0.25)), (-hole, (4.5, 3, 0.25))]
    volume = sum(v for v, _ in pieces)
    mass_lb = rho * volume
    com_in = np.sum([v * np.array(c) for v, c in pieces], axis=0) / volume
    assert mass_lb == pytest.approx(5.05624, abs=5e-6)  # the header's six figures
    j = js("inertia", "examples/bracket.yaml")
    # unit factors are exact and rounded once: 1e-12 relative is round-off
    assert j["mass"] == pytest.approx(mass_lb * LB, rel=1e-12)
    np.testing.assert_allclose(j["com"], com_in * IN, rtol=1e-12)
    table = printed("inertia", "examples/bracket.yaml", "--units", "in,lb")
    assert re.search(r"mass\s*\|\s*5\.05624\s*\|\s*lb", table)
    assert re.search(rf"com x\s*\|\s*{com_in[0]:.6g}\s*\|\s*in", table)


# --------------------------------------------------------------------------- all examples

@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_every_example_loads_and_says_what_to_run(path):
    body = load_body(str(path))
    assert body.parts and body.name
    assert re.search(r"^#\s+rbcli \w+", path.read_text(), re.M), "the header names the command to run"


def _header_commands() -> list[tuple[str, list[str], bool]]:
    """(example, args, refused): every `# rbcli ...` line of every example's header; refused
    when the line after it says the command is refused (exit 2)."""
    out = []
    for p in EXAMPLES:
        lines = p.read_text().splitlines()
        for i, line in enumerate(lines):
            m = re.match(r"#\s+(rbcli .*)", line)
            if not m:
                continue
            cmd = re.split(r"\s{2,}|\s+\||\s+->", m.group(1))[0]  # drop the claim and any | jq ...
            after = lines[i + 1] if i + 1 < len(lines) else ""
            out.append((p.stem, shlex.split(cmd)[1:], "refused (exit 2)" in after))
    return out


HEADER_COMMANDS = _header_commands()


@pytest.mark.parametrize("stem, args, refused", HEADER_COMMANDS,
                         ids=[f"{s}: {' '.join(a)}" for s, a, _ in HEADER_COMMANDS])
def test_every_command_in_an_example_header_runs(cli, stem, args, refused, tmp_path):
    # run where examples/ resolves but any file a command writes (--plot, --apply) lands in tmp
    (tmp_path / "examples").symlink_to(ROOT / "examples", target_is_directory=True)
    r = cli(*args, cwd=tmp_path)
    if refused:  # the header shows a refusal: one line, exit 2
        assert r.code == 2 and len(r.err.splitlines()) == 1, (args, r.err)
        return
    assert r.code in (0, 1), (args, r.err)  # 1: a check the example asks for
