"""``rbcli rollcheck`` through the command line.

Oracles: the physics sheet's cases R1-R4, R7-R9 (dynamics.md §6, six significant figures),
the sheet's closed forms evaluated here from the shape's textbook moments (thin disk
v_c = sqrt(g a/3), hoop sqrt(g a/4), solid cylinder s_c^2 = g (3a^2 + h^2)/(9a^3), the
circle relation and kappa of §3.3), the spoked wheel's A and C summed here from the
textbook formulas of a ring, a solid torus, a solid cylinder and thin rods (read from the
example's YAML with PyYAML, not with rbcli's loader), scipy's brentq for the circle
relation, and solve_ivp on the sheet's reduced knife-edge equations of motion (§3.1).
"""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import numpy as np
import pytest

from conftest import sampled_params
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st


ROOT = Path(__file__).resolve().parent.parent
EX = ROOT / "examples"
G0 = 9.80665


def ok(r, code: int = 0) -> dict:
    """The JSON document of a run of the ``cli`` fixture that exited with ``code``."""
    assert r.code == code, r.err
    return r.json()


def sheet(x: float, digits: int = 6) -> dict:
    """pytest.approx keywords for a number the sheet prints to ``digits`` significant
    figures: it is exact to half a unit in its last place."""
    return {"abs": 0.5 * 10.0 ** (math.floor(math.log10(abs(x))) - digits + 1), "rel": 0}


# round-off: the CLI's value passes through unit parsing, the sum of part tensors, an
# eigen-decomposition across the axle and a square root — a few dozen operations,
# so agreement with the closed form to 1e-12 relative is ample and still sharp
RT = 1e-12


# ----------------------------------------------------------------------------- R1-R4


def test_R1_penny_example_default_g(cli):
    d = ok(cli("rollcheck", str(EX / "penny.yaml"), "--json"))
    a = 9.525e-3
    assert d["radius"] == pytest.approx(a, rel=RT)
    assert d["g"] == G0
    assert d["critical_speed"] == pytest.approx(math.sqrt(G0 * a / 3), rel=RT)
    # the sheet: 0.176454 m/s with g = 9.80665 (example header prints this number)
    assert d["critical_speed"] == pytest.approx(0.176454, **sheet(0.176454))
    # the thin disk's moments: I = m a^2/4, Is = m a^2/2 (m = 2.5 g)
    assert d["I"] == pytest.approx(2.5e-3 * a * a / 4, rel=RT)
    assert d["Is"] == pytest.approx(2.5e-3 * a * a / 2, rel=RT)
    assert d["mass"] == pytest.approx(2.5e-3, rel=RT)


def test_R1_penny_g981(cli):
    d = ok(cli("rollcheck", str(EX / "penny.yaml"), "--g", "9.81", "--json"))
    assert d["critical_spin"] == pytest.approx(18.5285, **sheet(18.5285))
    assert d["critical_speed"] == pytest.approx(0.176484, **sheet(0.176484))
    assert d["g"] == 9.81


def test_R2_uk_penny(cli):
    d = ok(cli("rollcheck", "-e", "{shape: disk, radius: 10.16 mm, mass: 3.56 g}", "--g", "9.81", "--json"))
    assert d["critical_spin"] == pytest.approx(17.9402, **sheet(17.9402))
    assert d["critical_speed"] == pytest.approx(0.182272, **sheet(0.182272))


@pytest.mark.parametrize("a, vc", [(0.34, 0.913154), (0.30, 0.857759)])
def test_R3_hoops(cli, a, vc):
    d = ok(cli("rollcheck", "-e", f"{{shape: ring, radius: {a}, mass: 1.3}}", "--g", "9.81", "--json"))
    assert d["critical_speed"] == pytest.approx(vc, **sheet(vc))
    assert d["critical_speed"] == pytest.approx(math.sqrt(9.81 * a / 4), rel=RT)


def test_R3_bicycle_wheel_example(cli):
    d = ok(cli("rollcheck", str(EX / "bicycle_wheel.yaml"), "--g", "9.81", "--json"))
    assert d["critical_spin"] == pytest.approx(2.64710, **sheet(2.64710))
    assert d["critical_speed"] == pytest.approx(0.926485, **sheet(0.926485))
    # default g: sqrt(9.80665 x 0.35 / 4) = 0.926327, "about 1 m/s" (header)
    d = ok(cli("rollcheck", str(EX / "bicycle_wheel.yaml"), "--json"))
    assert d["critical_speed"] == pytest.approx(math.sqrt(G0 * 0.35 / 4), rel=RT)
    assert d["critical_speed"] == pytest.approx(0.926327, **sheet(0.926327))
    assert d["radius_source"] == "rim_radius" and "radius_part" not in d
    # header: at 5 km/h stable with margin 1.49935
    d = ok(cli("rollcheck", str(EX / "bicycle_wheel.yaml"), "--speed", "5 km/h", "--json"))
    assert d["speed"] == pytest.approx(5 / 3.6, rel=1e-15)  # exact unit factor, one division
    assert d["stable"] is True
    assert d["margin"] == pytest.approx(1.49935, **sheet(1.49935))


def test_R4_thick_coin_example(cli):
    """The sheet's R4 is the knife-edge idealisation of the thick coin: printed beside the
    flat band's own threshold (issue 24; the band's is checked against the rolling model in
    tests/test_rollcheck_rims.py)."""
    a, h = 9.525e-3, 1.52e-3
    d = ok(cli("rollcheck", str(EX / "thick_coin.yaml"), "--g", "9.81", "--json"))
    assert d["rim"] == "band" and d["band_width"] == pytest.approx(h, rel=1e-15)
    assert d["knife_edge_critical_spin"] == pytest.approx(18.6070, **sheet(18.6070))
    assert d["knife_edge_critical_speed"] == pytest.approx(0.177232, **sheet(0.177232))
    assert d["knife_edge_critical_spin"] == pytest.approx(math.sqrt(9.81 * (3 * a * a + h * h) / (9 * a**3)), rel=RT)
    thin = math.sqrt(9.81 * a / 3)
    assert d["knife_edge_critical_speed"] / thin == pytest.approx(1.00424, **sheet(1.00424))
    assert d["static_lean_limit_deg"] == pytest.approx(math.degrees(math.atan(h / 2 / a)), rel=1e-15)
    # the example's header: balanced on an edge 18.6752 rad/s, 0.177882 m/s
    assert d["critical_spin"] == pytest.approx(18.6752, **sheet(18.6752))
    assert d["critical_speed"] == pytest.approx(0.177882, **sheet(0.177882))
    d = ok(cli("rollcheck", str(EX / "thick_coin.yaml"), "--json"))
    assert d["critical_speed"] == pytest.approx(0.177851, **sheet(0.177851))
    assert d["knife_edge_critical_speed"] == pytest.approx(0.177202, **sheet(0.177202))


# ----------------------------------------------------------------------------- R7: lean dynamics


def test_R7_lean_frequency_and_growth(cli):
    a = 9.525e-3
    sc = math.sqrt(9.81 / (3 * a))
    pen = str(EX / "penny.yaml")
    d = ok(cli("rollcheck", pen, "--g", "9.81", "--spin", repr(1.5 * sc), "--json"))
    assert d["stable"] is True and d["growth_rate"] is None
    assert d["lean_frequency"] == pytest.approx(32.0924, **sheet(32.0924))
    assert d["margin"] == pytest.approx(1.5, rel=RT)
    assert d["lean_frequency_hz"] == pytest.approx(d["lean_frequency"] / (2 * math.pi), rel=1e-15)
    d = ok(cli("rollcheck", pen, "--g", "9.81", "--spin", repr(0.9 * sc), "--json"), 1)
    assert d["stable"] is False and d["lean_frequency"] is None
    assert d["growth_rate"] == pytest.approx(12.5119, **sheet(12.5119))


@settings(max_examples=25, deadline=None)
@given(a=st.floats(0.005, 2.0), m=st.floats(0.001, 50.0), ratio=st.floats(0.2, 3.0))
def test_thin_disk_lean_frequency_closed_form(cli, a, m, ratio):
    # thin disk: nu^2 = (4/5)(3 s^2 - g/a) (sheet §3.2), s_c^2 = g/(3a)
    v = ratio * math.sqrt(G0 * a / 3)
    r = cli("rollcheck", "-e", f"{{shape: disk, radius: {a!r}, mass: {m!r}}}", "--speed", repr(v), "--json")
    assert r.code in (0, 1), r.err
    d = r.json()
    s = v / a
    nu2 = 0.8 * (3 * s * s - G0 / a)
    # nu^2 is a difference of two terms of size ~ 3 s^2: its relative round-off grows as
    # 1/|ratio^2 - 1|; ratio is kept >= 0.2 from 1 only by the strategy's spread, so
    # compare with an absolute tolerance scaled to the terms
    assert d["lean_frequency_squared"] == pytest.approx(nu2, abs=1e-12 * 2.4 * s * s + 1e-12 * G0 / a)
    assert d["critical_spin"] ** 2 == pytest.approx(G0 / (3 * a), rel=RT)
    # at the threshold itself (ratio 1 to round-off) the verdict is decided by the last
    # bits of v and s_c, computed two ways; only judge it clearly away from the boundary
    if abs(ratio - 1.0) > 1e-9:
        assert d["stable"] is (ratio > 1.0)


@settings(max_examples=25, deadline=None)
@given(a=st.floats(0.005, 2.0), m=st.floats(0.001, 50.0), g=st.floats(0.5, 30.0))
def test_thin_disk_and_hoop_limits(cli, a, m, g):
    for shape, k in (("disk", 3.0), ("ring", 4.0)):
        r = cli("rollcheck", "-e", f"{{shape: {shape}, radius: {a!r}, mass: {m!r}}}", "--g", repr(g), "--json")
        assert r.code == 0, r.err
        d = r.json()
        # s_c^2 = g/(3a) (disk), g/(4a) (hoop), independent of the mass (sheet §3.2)
        assert d["critical_spin"] ** 2 == pytest.approx(g / (k * a), rel=RT)
        assert d["critical_speed"] == pytest.approx(math.sqrt(g * a / k), rel=RT)


def test_rounded_rim(cli):
    # sheet §3.2: a rounded rim only weakens gravity, a -> a - r in the gravity term:
    # thin disk s_c^2 = g (a - r) / (3 a^2)
    a, r = 0.3, 0.02
    d = ok(cli("rollcheck", "-e", "{shape: disk, radius: 0.3, mass: 2}", "--tyre-radius", "2 cm", "--json"))
    assert d["tyre_radius"] == pytest.approx(r, rel=1e-15)
    assert d["critical_spin"] ** 2 == pytest.approx(G0 * (a - r) / (3 * a * a), rel=RT)
    assert "rounded rim" in d["model"]


def test_nonlinear_threshold_penny(cli):
    """The CLI's critical spin is a true threshold of the sheet's reduced equations (§3.1):
    a 1e-5 rad lean grows far below it and stays small just above it."""
    from scipy.integrate import solve_ivp

    d = ok(cli("rollcheck", str(EX / "penny.yaml"), "--json"))
    m, A, C, a, g = d["mass"], d["I"], d["Is"], d["radius"], d["g"]
    Cc, Ac = C + m * a * a, A + m * a * a

    def rhs(t, y):
        th, thd, phd, w3 = y
        s, c = math.sin(th), math.cos(th)
        thdd = (-A * phd * phd * s * c + Cc * phd * w3 * c + m * g * a * s) / Ac
        phdd = thd * (2 * A * phd * s - C * w3) / (A * c)
        w3d = -m * a * a * phd * thd * c / Cc
        return [thd, thdd, phdd, w3d]

    def max_lean(factor: float) -> float:
        sol = solve_ivp(rhs, (0.0, 2.0), [1e-5, 0.0, 0.0, factor * d["critical_spin"]],
                        method="DOP853", rtol=1e-10, atol=1e-13, max_step=0.01)
        return float(np.max(np.abs(sol.y[0])))

    # below (0.95 s_c) the linear growth rate is ~9 1/s: e^18 over 2 s, so the lean leaves
    # the linear range (> 0.01 rad) by far; above (1.05 s_c) linear theory bounds it by
    # 2 theta0 s^2/(s^2 - s_c^2) = 2.15e-4 rad: 1e-3 leaves a factor 4.6 of room
    assert max_lean(0.95) > 1e-2
    assert max_lean(1.05) < 1e-3


# ----------------------------------------------------------------------------- circles: R8, R9


def test_R8_steady_circle(cli):
    d = ok(cli("rollcheck", "-e", "{shape: disk, radius: 0.05, mass: 1}", "--lean", "20", "--circle", "0.5",
           "--g", "9.81", "--json"))
    c = d["circle"]
    assert list(c)[:6] == ["lean_deg", "radius", "turn_rate", "spin", "speed", "stable"]
    assert c["lean_deg"] == pytest.approx(20.0, rel=1e-14)  # deg -> rad -> deg, two roundings
    assert c["radius"] == 0.5
    assert c["turn_rate"] == pytest.approx(2.17572, **sheet(2.17572))
    assert c["spin"] == pytest.approx(21.7572, **sheet(21.7572))
    assert c["speed"] == pytest.approx(1.08786, **sheet(1.08786))
    assert c["contact_radius"] == pytest.approx(0.517101, **sheet(0.517101))
    assert c["stable"] is True
    assert c["lean_frequency"] == pytest.approx(32.0234, **sheet(32.0234))
    # thin disk closed form Omega^2 = 4 g tan b / (a sin b + 6 R_G) (sheet §3.3)
    b = math.radians(20)
    assert c["turn_rate"] ** 2 == pytest.approx(4 * 9.81 * math.tan(b) / (0.05 * math.sin(b) + 3.0), rel=RT)
    # no speed given: no straight verdict keys
    assert "speed" not in d and "stable" not in d and "margin" not in d


def test_R9_spinning_in_place(cli):
    d = ok(cli("rollcheck", "-e", "{shape: disk, radius: 0.05, mass: 1}", "--lean", "60", "--circle", "0",
           "--g", "9.81", "--json"))
    c = d["circle"]
    b = math.radians(60)
    assert c["turn_rate"] == pytest.approx(39.6182, **sheet(39.6182))
    assert c["turn_rate"] == pytest.approx(math.sqrt(4 * 9.81 / (0.05 * math.cos(b))), rel=RT)
    assert c["stable"] is True
    assert c["lean_frequency"] == pytest.approx(31.9412, **sheet(31.9412))
    assert c["speed"] == 0.0 and c["spin"] == 0.0
    assert c["contact_radius"] == pytest.approx(0.05 * math.sin(b), rel=RT)


@pytest.mark.parametrize("lean", [5.0, 30.0, 75.0])
def test_spinning_in_place_limit_hoop(cli, lean):
    # R_G = 0: Omega^2 = m g a/(A cos b), kappa = (3 A sin^2 b + m a^2 cos^2 b) Omega^2 > 0
    m, a = 0.7, 0.4
    A = m * a * a / 2
    d = ok(cli("rollcheck", "-e", f"{{shape: ring, radius: {a}, mass: {m}}}", "--lean", str(lean), "--circle", "0", "--json"))
    c = d["circle"]
    b = math.radians(lean)
    W2 = m * G0 * a / (A * math.cos(b))
    kappa = (3 * A * math.sin(b) ** 2 + m * a * a * math.cos(b) ** 2) * W2
    assert c["turn_rate"] ** 2 == pytest.approx(W2, rel=RT)
    # kappa's general formula sums terms of both signs of size ~ A Omega^2: 1e-10 relative
    assert c["kappa"] == pytest.approx(kappa, rel=1e-10)
    assert c["stable"] is True
    assert c["lean_frequency"] == pytest.approx(math.sqrt(kappa / (A + m * a * a)), rel=1e-10)


def test_circle_tends_to_straight_rolling(cli):
    # R_G -> infinity at fixed speed: small lean tan b ~ (C + m a^2) v^2 / (m g a^2 R_G) and
    # the lean frequency of the circle -> that of straight rolling (sheet §3.3 limits)
    m, a, v, R = 1.0, 0.05, 1.0, 1.0e4
    A, C = m * a * a / 4, m * a * a / 2
    d = ok(cli("rollcheck", "-e", f"{{shape: disk, radius: {a}, mass: {m}}}", "--speed", str(v), "--circle", str(R), "--json"))
    c = d["circle"]
    approx_tan = (C + m * a * a) * v * v / (m * G0 * a * a * R)
    # the neglected term is A a sin(b) / ((C + m a^2) R_G) ~ 1e-9 relative
    assert math.tan(math.radians(c["lean_deg"])) == pytest.approx(approx_tan, rel=1e-7)
    assert c["speed"] == pytest.approx(v, rel=1e-12)
    # corrections to nu are O(Omega / s) = O(a / R_G) = 5e-6
    assert c["lean_frequency"] == pytest.approx(d["lean_frequency"], rel=1e-4)
    assert c["stable"] is d["stable"] is True


def test_lean_from_speed_and_circle_vs_brentq(cli):
    from scipy.optimize import brentq

    m, a, v, R = 0.4, 0.5, 1.5, 1.2
    A, C = m * a * a / 2, m * a * a
    d = ok(cli("rollcheck", str(EX / "hoop.yaml"), "--speed", str(v), "--circle", str(R), "--json"))

    def f(b):  # the circle relation with Omega = v / R_G (sheet §3.3)
        W = v / R
        return m * G0 * a * math.sin(b) - A * W * W * math.sin(b) * math.cos(b) - (C + m * a * a) * W * (v / a) * math.cos(b)

    b = brentq(f, 1e-9, math.pi / 2 - 1e-9, xtol=1e-15, rtol=1e-15)
    assert d["circle"]["lean_deg"] == pytest.approx(math.degrees(b), rel=1e-12)
    assert d["circle"]["turn_rate"] == pytest.approx(v / R, rel=1e-14)


def test_radius_from_speed_and_lean(cli):
    m, a, v, lean = 0.4, 0.5, 2.0, 25.0
    A, C = m * a * a / 2, m * a * a
    d = ok(cli("rollcheck", str(EX / "hoop.yaml"), "--speed", str(v), "--lean", str(lean), "--json"))
    c = d["circle"]
    b = math.radians(lean)
    R = c["radius"]
    # v^2 (A a sin b + (C + m a^2) R) = m g a^2 tan b R^2: compare both sides (~10 operations)
    lhs = v * v * (A * a * math.sin(b) + (C + m * a * a) * R)
    rhs = m * G0 * a * a * math.tan(b) * R * R
    assert lhs == pytest.approx(rhs, rel=1e-12)
    assert c["speed"] == pytest.approx(v, rel=1e-12)


def test_hoop_example_header(cli):
    d = ok(cli("rollcheck", str(EX / "hoop.yaml"), "--json"))
    assert d["critical_speed"] == pytest.approx(math.sqrt(G0 * 0.5 / 4), rel=RT)
    assert d["critical_speed"] == pytest.approx(1.10717, **sheet(1.10717))
    d = ok(cli("rollcheck", str(EX / "hoop.yaml"), "--lean", "20", "--circle", "2", "--json"))
    c = d["circle"]
    m, a, R, b = 0.4, 0.5, 2.0, math.radians(20)
    A, C = m * a * a / 2, m * a * a
    W = math.sqrt(m * G0 * a * a * math.tan(b) / (A * a * math.sin(b) + (C + m * a * a) * R))
    assert c["turn_rate"] == pytest.approx(W, rel=RT)
    assert c["turn_rate"] == pytest.approx(0.934696, **sheet(0.934696))
    assert c["speed"] == pytest.approx(1.86939, **sheet(1.86939))
    assert c["stable"] is True
    r = cli("rollcheck", str(EX / "hoop.yaml"), "--speed", "0.8")
    rc, _, _ = r.code, r.out, r.err
    assert rc == 1


# ----------------------------------------------------------------------------- spoked wheel


def _spoked_oracle() -> tuple[float, float, float, float]:
    """(m, A, C, a) of examples/spoked_wheel.yaml from textbook formulas, read with PyYAML."""
    data = yaml.safe_load((EX / "spoked_wheel.yaml").read_text())
    M, J, a = 0.0, np.zeros((3, 3)), 0.0
    for p in data["parts"]:
        m = p["mass"]
        M += m
        if p["shape"] == "ring":  # thin hoop: C = m R^2, A = m R^2/2
            R = p["radius"]
            J += np.diag([m * R * R / 2, m * R * R / 2, m * R * R])
            a = max(a, R)
        elif p["shape"] == "torus":  # solid torus: C = m (R^2 + 3 r^2/4), A = m (R^2/2 + 5 r^2/8)
            R, r = p["major_radius"], p["minor_radius"]
            J += np.diag([m * (R * R / 2 + 5 * r * r / 8)] * 2 + [m * (R * R + 3 * r * r / 4)])
            a = max(a, R + r)
        elif p["shape"] == "cylinder":  # solid cylinder: C = m r^2/2, A = m (3 r^2 + L^2)/12
            r, L = p["radius"], p["length"]
            J += np.diag([m * (3 * r * r + L * L) / 12] * 2 + [m * r * r / 2])
        elif p["shape"] == "rod":  # thin rod p->q: S = m (pp + (pq + qp)/2 + qq)/3, J = tr(S) 1 - S
            P, Q = np.array(p["from"], float), np.array(p["to"], float)
            S = m * (np.outer(P, P) + (np.outer(P, Q) + np.outer(Q, P)) / 2 + np.outer(Q, Q)) / 3
            J += np.trace(S) * np.eye(3) - S
        else:
            raise AssertionError(p["shape"])
    return M, (J[0, 0] + J[1, 1]) / 2, J[2, 2], a


def test_spoked_wheel_example(cli):
    m, A, C, a = _spoked_oracle()
    r = 0.0125  # the tyre's tube radius: the rim is that torus (issue 24)
    vc = a * math.sqrt(m * G0 * (a - r) * A / (C * (C + m * a * a)))
    d = ok(cli("rollcheck", str(EX / "spoked_wheel.yaml"), "--json"))
    # rbcli places each rod with a rotation and sums 35 tensors: ~1e-13 relative round-off
    assert d["I"] == pytest.approx(A, rel=1e-12)
    assert d["Is"] == pytest.approx(C, rel=1e-12)
    assert d["critical_speed"] == pytest.approx(vc, rel=1e-12)
    # the header's numbers
    assert d["critical_speed"] == pytest.approx(1.01418, **sheet(1.01418))
    assert d["radius"] == a == 0.3375 and d["tyre_radius"] == r and d["tyre_radius_source"] == "shape"
    assert d["radius_source"] == "largest_round_part" and d["radius_part"] == "tyre"
    # hub and spokes raise the critical speed above the bare hoop of the same radius
    assert d["critical_speed"] > math.sqrt(G0 * a / 4)
    d = ok(cli("rollcheck", str(EX / "spoked_wheel.yaml"), "--speed", "1", "--json"), 1)
    assert d["margin"] == pytest.approx(1.0 / vc, rel=1e-12)
    assert d["margin"] == pytest.approx(0.986014, **sheet(0.986014))
    d = ok(cli("rollcheck", str(EX / "spoked_wheel.yaml"), "--speed", "1.2", "--json"))
    assert d["stable"] is True and d["margin"] == pytest.approx(1.18322, **sheet(1.18322))


# ----------------------------------------------------------------------------- radius and axle defaults


def test_radius_sources_in_text(cli):
    r = cli("rollcheck", str(EX / "bicycle_wheel.yaml"))
    rc, out, _ = r.code, r.out, r.err
    assert rc == 0 and "rim radius from the body's rim_radius" in out
    r = cli("rollcheck", str(EX / "penny.yaml"))
    rc, out, _ = r.code, r.out, r.err
    assert "rim radius from the largest round part 'coin' (disk" in out
    r = cli("rollcheck", str(EX / "penny.yaml"), "--radius", "1 cm")
    rc, out, _ = r.code, r.out, r.err
    assert "rim radius from --radius" in out
    d = ok(cli("rollcheck", str(EX / "penny.yaml"), "--radius", "1 cm", "--json"))
    assert d["radius"] == pytest.approx(0.01, rel=1e-15) and d["radius_source"] == "--radius"


def test_largest_round_part_ignores_holes_and_other_axes(cli):
    body = ("{parts: [{name: wheel, shape: disk, radius: 0.2, mass: 1},"
            " {name: bore, shape: disk, radius: 0.05, mass: 0.01, subtract: true},"
            " {name: big hole, shape: cylinder, radius: 0.5, length: 0.001, mass: 0.001, subtract: true},"
            " {name: crossbar, shape: cylinder, radius: 0.3, length: 0.01, mass: 0.001, axis: [1, 0, 0]},"
            " {name: crossbar2, shape: cylinder, radius: 0.3, length: 0.01, mass: 0.001, axis: [0, 1, 0]}]}")
    d = ok(cli("rollcheck", "-e", body, "--json"))
    assert d["radius"] == 0.2 and d["radius_part"] == "wheel"


def test_axle_from_shaft_and_option(cli):
    # a ring turned onto x: the body's shaft (axis x, through a point) is the default axle
    body = "{shaft: {axis: [1, 0, 0], through: [0, 0.1, 0]}, parts: [{shape: ring, radius: 0.3, mass: 1, axis: [1, 0, 0], at: [0, 0.1, 0]}]}"
    d = ok(cli("rollcheck", "-e", body, "--json"))
    assert d["axle"] == [1.0, 0.0, 0.0] and d["axle_through"] == [0.0, 0.1, 0.0]
    assert d["critical_speed"] == pytest.approx(math.sqrt(G0 * 0.3 / 4), rel=RT)
    d = ok(cli("rollcheck", "-e", "{shape: ring, radius: 0.3, mass: 1, axis: [0, 1, 0]}", "--axle", "y", "--json"))
    assert d["critical_speed"] == pytest.approx(math.sqrt(G0 * 0.3 / 4), rel=RT)
    r = cli("rollcheck", "-e", "{shape: ring, radius: 0.3, mass: 1, axis: [0, 1, 0]}")
    rc, _, err = r.code, r.out, r.err
    assert rc == 2 and "not a body of revolution about the axle" in err


# ----------------------------------------------------------------------------- errors and exit codes


def test_not_of_revolution_names_the_difference(cli):
    r = cli("rollcheck", "-e", "{shape: box, mass: 1, size: [0.1, 0.2, 0.3]}", "--radius", "0.1")
    rc, out, err = r.code, r.out, r.err
    assert rc == 2 and out == ""
    # box: Ixx = m (b^2 + c^2)/12 = 0.0108333, Iyy = m (a^2 + c^2)/12 = 0.00833333, 26 % of their mean apart
    assert err.count("\n") == 1 and err.startswith("rbcli: <expr>: not a body of revolution")
    assert "0.00833333 and 0.0108333 kg m²" in err and "26 %" in err and "--symmetry-tol (1 %)" in err


def test_com_off_the_axle(cli):
    r = cli("rollcheck", "-e", "{shape: ring, radius: 0.3, mass: 1, at: [0.01, 0, 0]}")
    rc, out, err = r.code, r.out, r.err
    assert rc == 2 and "10 mm off the axle" in err and err.count("\n") == 1
    # a rim and hub modelled 2 mm (in x) and 1.5 mm (in y) off the origin: 2.5 mm off
    body = ("{parts: [{shape: ring, radius: 0.3, mass: 1, at: [0.002, 0.0015, 0]},"
            " {shape: disk, radius: 0.03, mass: 0.2, at: [0.002, 0.0015, 0]}]}")
    # (0.83 % of the 300 mm rim: within the default --symmetry-tol of 1 %, answered for the
    # wheel with its com taken on the axle, with a warning; beyond 0.5 % refused)
    r = cli("rollcheck", "-e", body, "--radius", "0.3")
    assert r.code == 0 and "warning: the wheel is not exactly symmetric about its axle" in r.err
    assert "the centre of mass is 0.83 % of the rim radius off it" in r.err
    r = cli("rollcheck", "-e", body, "--radius", "0.3", "--symmetry-tol", "0.5%")
    rc, out, err = r.code, r.out, r.err
    assert rc == 2 and "2.5 mm off the axle" in err and "0.83 % of the rim radius 300 mm" in err
    assert "--symmetry-tol (0.5 %)" in err
    # the penny (a = 9.525 mm) on an axle 1 mm off its centre: no round part is coaxial, so
    # no rim radius is known; the offset is quoted against what is used, sqrt(C/m) = a/sqrt(2)
    err = cli("rollcheck", str(EX / "penny.yaml"), "--through", "0.001,0,0").err
    assert "15 % of the radius of gyration about the axle, sqrt(C/m), 6.74 mm" in err
    assert "rim radius" not in err
    err = cli("rollcheck", str(EX / "penny.yaml"), "--through", "0.001,0,0", "--radius", "9.525 mm").err
    assert "10 % of the rim radius 9.53 mm" in err  # 1/9.525 = 10.5 %, printed to 2 digits
    # the axle placed through the com is accepted (--through com) if the body is of revolution
    r = cli("rollcheck", "-e", "{shape: ring, radius: 0.3, mass: 1, at: [0.01, 0, 0]}", "--through", "com")
    rc, out, err = r.code, r.out, r.err
    assert rc == 0


@pytest.mark.parametrize(
    "args, needle",
    [
        (["--radius", "-0.1"], "--radius"),
        (["--radius", "0"], "--radius"),
        (["--tyre-radius", "0.6"], "--tyre-radius: the tyre radius 0.6 m must be at most the rim radius"),
        (["--tyre-radius", "-1 mm"], "--tyre-radius"),
        (["--g", "-9.81"], "--g: gravity must be a positive"),
        (["--g", "9.81 m"], "--g"),
        (["--lean", "10"], "--lean: a steady circle needs two of --lean, --circle and --speed"),
        (["--circle", "1"], "--circle: a steady circle needs two"),
        (["--lean", "90", "--circle", "1"], "--lean: the inward lean"),
        (["--lean", "-5", "--circle", "1"], "--lean"),
        (["--lean", "10", "--circle", "-1"], "--circle"),
        (["--speed", "1", "--spin", "1"], "--speed, --spin: the speed 1 m/s and the spin 1 rad/s disagree"),
        (["--speed", "1", "--circle", "0"], "--circle 0"),
        (["--speed", "1", "--lean", "0"], "rolls straight"),
        (["--speed", "abc"], "--speed"),
        (["--spin", "3 m"], "--spin"),
        (["--tyre-radius", "1 cm", "--lean", "10", "--circle", "1"], "knife-edge rim only"),
        (["--plot", "out.txt"], "--plot"),
        (["--axle", "0,0,0"], "--axle"),
    ],
)
def test_bad_options_exit_2(cli, args, needle):
    r = cli("rollcheck", str(EX / "hoop.yaml"), *args)
    rc, out, err = r.code, r.out, r.err
    assert rc == 2 and out == ""
    assert err.startswith("rbcli: ") and err.count("\n") == 1, err
    assert needle in err


def test_no_rim_radius(cli):
    r = cli("rollcheck", str(EX / "cube.yaml"))
    rc, _, err = r.code, r.out, r.err
    assert rc == 2 and "no rim radius: give --radius" in err


def test_exit_codes_subprocess(cli_proc):
    pen = str(EX / "penny.yaml")
    p = cli_proc("rollcheck", pen, "--speed", "0.1", "--json")
    assert p.code == 1 and p.json()["stable"] is False  # full result printed
    p = cli_proc("rollcheck", pen, "--speed", "25 cm/s")
    assert p.code == 0 and "STABLE" in p.out
    p = cli_proc("rollcheck", pen, "--radius", "-1")
    assert p.code == 2 and p.out == "" and p.err.startswith("rbcli: --radius")
    assert p.err.count("\n") == 1


def test_exit_status_follows_the_motion_asked_about(cli):
    pen = str(EX / "penny.yaml")
    # straight rolling at 0.1 m/s is unstable, but the asked steady circle (R_G = 5 mm) is
    # stable: the circle sets the exit status, the straight verdict is shown alongside
    d = ok(cli("rollcheck", pen, "--speed", "0.1", "--circle", "0.005", "--json"))
    assert d["stable"] is False and d["circle"]["stable"] is True
    # ... and a stable straight speed with an unstable circle exits 1
    d = ok(cli("rollcheck", pen, "--speed", "0.1", "--circle", "0.02", "--json"), 1)
    assert d["circle"]["stable"] is False
    # all three given: both verdicts are asked; the straight one fails here
    d = ok(cli("rollcheck", pen, "--speed", "0.1", "--lean", "60", "--circle", "0", "--json"), 1)
    assert d["circle"]["stable"] is True and d["stable"] is False
    # exactly at the critical speed: not stable (the lean drifts)
    crit = ok(cli("rollcheck", pen, "--json"))["critical_speed"]
    d = ok(cli("rollcheck", pen, "--speed", repr(crit), "--json"), 1)
    assert d["growth_rate"] == pytest.approx(0.0, abs=1e-6)


# ----------------------------------------------------------------------------- JSON, text, units


def test_json_keys_and_order(cli):
    d = ok(cli("rollcheck", str(EX / "hoop.yaml"), "--json"))
    assert list(d)[:6] == ["radius", "mass", "I", "Is", "critical_spin", "critical_speed"]
    assert "speed" not in d and "circle" not in d
    d = ok(cli("rollcheck", str(EX / "hoop.yaml"), "--speed", "3", "--lean", "20", "--circle", "2", "--json"))
    assert list(d)[:10] == ["radius", "mass", "I", "Is", "critical_spin", "critical_speed",
                            "speed", "stable", "margin", "circle"]
    assert {"radius_source", "tyre_radius", "g", "lean_frequency", "growth_rate", "model"} <= set(d)
    assert "neutral stability (undamped)" in d["model"]


def test_json_deterministic(cli, cli_proc):
    args = ("rollcheck", str(EX / "spoked_wheel.yaml"), "--speed", "2", "--json")
    a, b = cli(*args), cli(*args)
    assert a == b and a.code == 0
    # and across processes, the same bytes as in-process
    p1, p2 = cli_proc(*args), cli_proc(*args)
    assert p1.code == 0 and p1.out == p2.out == a.out


def test_units_and_speed_units(cli):
    d = ok(cli("rollcheck", str(EX / "bicycle_wheel.yaml"), "--speed", "20 km/h", "--json"))
    assert d["speed"] == pytest.approx(20 / 3.6, rel=1e-15)
    d = ok(cli("rollcheck", str(EX / "bicycle_wheel.yaml"), "--spin", "300 rpm", "--json"))
    assert d["spin"] == pytest.approx(300 * 2 * math.pi / 60, rel=1e-15)
    assert d["speed"] == pytest.approx(0.35 * 300 * 2 * math.pi / 60, rel=1e-15)
    d = ok(cli("rollcheck", str(EX / "hoop.yaml"), "--lean", "0.3 rad", "--circle", "50 cm", "--json"))
    assert d["circle"]["lean_deg"] == pytest.approx(math.degrees(0.3), rel=1e-14)
    assert d["circle"]["radius"] == 0.5
    d = ok(cli("rollcheck", str(EX / "hoop.yaml"), "--g", "1 g0", "--json"))
    assert d["g"] == G0
    r = cli("rollcheck", str(EX / "penny.yaml"), "--units", "mm,g", "--speed", "0.5")
    rc, out, _ = r.code, r.out, r.err
    # 0.176454 m/s shown in mm/s
    assert rc == 0 and "176.454" in out and "mm/s" in out


def test_text_output_content(cli):
    r = cli("rollcheck", str(EX / "penny.yaml"), "--speed", "0.1")
    rc, out, _ = r.code, r.out, r.err
    assert rc == 1
    for needle in ("critical speed", "0.176454", "UNSTABLE", "margin", "growth rate",
                   "about the contact point", "neutral stability (undamped)", "knife-edge"):
        assert needle in out, needle
    r = cli("rollcheck", str(EX / "penny.yaml"), "--speed", "0.5")
    rc, out, _ = r.code, r.out, r.err
    assert rc == 0 and "STABLE" in out and "Hz" in out
    r = cli("rollcheck", str(EX / "hoop.yaml"), "--lean", "20", "--circle", "2")
    rc, out, _ = r.code, r.out, r.err
    assert rc == 0 and "turn rate" in out and "κ" in out and "R_P" in out


# ----------------------------------------------------------------------------- plots


# one format by default here (pdf; precess draws svg, top png), all three under -m slow
@pytest.mark.parametrize("ext, magic", sampled_params([("png", b"\x89PNG"), ("svg", b"<svg"), ("pdf", b"%PDF")], [2],
                                                    multi=True, ids=["png", "svg", "pdf"]))
def test_plots_written(cli, tmp_path, ext, magic):
    out = tmp_path / f"roll.{ext}"
    r = cli("rollcheck", str(EX / "penny.yaml"), "--speed", "0.3", "--plot", str(out))
    rc, text, _ = r.code, r.out, r.err
    assert rc == 0 and out.exists() and str(out) in text
    head = out.read_bytes()[:400]
    assert magic in head
    out2 = tmp_path / f"circle.{ext}"
    r = cli("rollcheck", str(EX / "hoop.yaml"), "--lean", "20", "--circle", "2", "--plot", str(out2))
    rc, _, _ = r.code, r.out, r.err
    assert rc == 0 and magic in out2.read_bytes()[:400]


def test_plot_svg_deterministic(cli, tmp_path):
    a, b = tmp_path / "a.svg", tmp_path / "b.svg"
    cli("rollcheck", str(EX / "hoop.yaml"), "--speed", "2", "--plot", str(a))
    cli("rollcheck", str(EX / "hoop.yaml"), "--speed", "2", "--plot", str(b))
    assert a.read_bytes() == b.read_bytes()


def test_plot_unknown_extension(cli, tmp_path):
    r = cli("rollcheck", str(EX / "hoop.yaml"), "--plot", str(tmp_path / "x.jpg"))
    rc, out, err = r.code, r.out, r.err
    assert rc == 2 and ".png, .svg, .pdf" in err and not (tmp_path / "x.jpg").exists()


def test_plot_never_overwrites_input(cli, tmp_path):
    body = tmp_path / "wheel.svg"  # a body file whose name has a plot extension
    shutil.copy(EX / "hoop.yaml", body)
    before = body.read_bytes()
    for target in (str(body), "./wheel.svg"):
        r = cli("rollcheck", str(body), "--plot", target, cwd=tmp_path)
        rc, out, err = r.code, r.out, r.err
        assert rc == 2 and "input file" in err
    assert body.read_bytes() == before


def test_import_is_cheap(cli_proc):
    # `rollcheck --help` imports the command's module (rbcli.cli.rollcheck) and nothing heavy
    r = cli_proc("rollcheck", "--help", imports=True)
    assert r.code == 0 and "rbcli.cli.rollcheck" in r.imported, r.err
    assert not {m.split(".")[0] for m in r.imported} & {"numpy", "scipy", "matplotlib"}


# ----------------------------------------------------------------------------- rims off the com (issue 14.3)


ROTOR_PARTS = ("[{name: rotor, shape: disk, radius: 0.075, mass: 1, at: [0, 0, 0.08]},"
               " {name: axle, shape: rod, from: [0, 0, 0], to: [0, 0, 0.12], mass: 0.02}]")
ROTOR_ON_AXLE = "{parts: " + ROTOR_PARTS + "}"


def test_warnings_are_in_the_json_too(cli):
    # issue 13.6: as in balance, "warnings" is always there ([] when none), before name/file
    d = ok(cli("rollcheck", str(EX / "penny.yaml"), "--json"))
    assert d["warnings"] == [] and list(d)[-3:] == ["warnings", "name", "file"]
    # a thin rotor (a knife edge) on a light axle: its rim circle a little off the com
    # (a thick rotor's band would hold the com's plane: no warning, issue 24)
    r = cli("rollcheck", "-e", ROTOR_ON_AXLE, "--json")
    (w,) = r.json()["warnings"]
    assert r.code == 0 and r.err == f"rbcli: <expr>: warning: {w}\n"
    # the real offset of the rotor's rim circle: its plane at z = 80 mm, the com at
    # (m_rotor 0.08 + m_axle 0.06) / (m_rotor + m_axle)
    d = 0.08 - (1.0 * 0.08 + 0.02 * 0.06) / 1.02
    assert f"is {d * 1e6:.3g} µm from the centre of mass" in w


@pytest.mark.parametrize("args", [[], ["--speed", "3"], ["--lean", "20", "--circle", "1"], ["--json"]])
def test_a_top_on_its_rim_is_refused(cli, args):
    r = cli("rollcheck", "examples/top.yaml", *args)
    assert r.code == 2 and r.out == "" and r.err.count("\n") == 1
    assert r.err.startswith("rbcli: examples/top.yaml: the rim circle of part 'disk' (disk) is 10 mm "
                            "from the centre of mass along the axle (12.5 % of the rim radius 80 mm)")


def test_report_leaves_out_rolling_for_an_off_centre_rim(cli, tmp_path):
    r = cli("report", "examples/toy_top.yaml", "-o", str(tmp_path / "t.md"))
    assert r.code == 0, r.err
    text = (tmp_path / "t.md").read_text(encoding="utf-8")
    assert "Rolling stability (not included)" in text
    (why,) = [line for line in text.splitlines() if line.startswith("*rolling stability: ")]
    assert why.startswith("*rolling stability: left out: the rim circle of part 'cone' (cone) is 8.48 mm")
    # a rim within 1 %: the section is there, with its warning
    body = tmp_path / "rotor.yaml"
    body.write_text(f"name: rotor\nparts: {ROTOR_PARTS}\n", encoding="utf-8")
    r = cli("report", str(body), "-o", str(tmp_path / "g.md"))
    text = (tmp_path / "g.md").read_text(encoding="utf-8")
    assert r.code == 0 and "## Rolling stability" in text and "warning: the rim circle of part 'rotor'" in text
