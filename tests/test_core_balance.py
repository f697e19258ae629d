"""Tests of rbcli.core.balance against the physics sheet physics/balance.md.

Expected numbers come from the sheet (worked examples A and B, §3; test cases T1-T26, §6;
T16/T17 do not exist in the sheet) or from closed forms and independent constructions
written here: the rotors' mass properties are built by the small helpers below (point
masses, a uniform cylinder, a thin tilted disk, summed with the parallel-axis theorem),
never with the module under test.

Units: the sheet prints g, mm, g*mm, g*mm^2; the module works in SI. G = 1e-3 kg, MM = 1e-3 m.
The sheet prints 6 significant figures, so "sheet value" assertions use rel 1e-5 (half a
unit in the 6th digit is at most 5e-6 relative) or abs 1e-3 deg for printed angles with 3
decimals (half a unit = 5e-4 deg), unless a comment says otherwise.
"""

from __future__ import annotations

import cmath
import json
import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from rbcli.api import balancejson as J
from rbcli.api.balancejson import balance_json
from rbcli.core import balance as bal
from rbcli.core.balance import (
    achieved_grade,
    allocate_permissible,
    apply_corrections,
    bearing_forces,
    corrections,
    iso_check,
    mass_at_radius,
    permissible_unbalance,
    phasor,
    plane_unbalances,
    round_corrections,
    shaft_frame,
    split_between,
    split_to_positions,
    unbalance,
)

G = 1e-3  # kg per gram
MM = 1e-3  # m per millimetre
GMM = G * MM  # kg m per g*mm
GMM2 = G * MM * MM  # kg m^2 per g*mm^2
RPM = 2 * math.pi / 60  # rad/s per rpm

# ---------------------------------------------------------------------------------------
# independent mass-property helpers (parallel-axis theorem, sheet §2.2)
# ---------------------------------------------------------------------------------------

Z3 = np.zeros((3, 3))


def point(m: float, r: float, phi_deg: float, z: float) -> tuple:
    """A point mass m at radius r, angle phi (from +x towards +y), height z (body = shaft frame)."""
    p = math.radians(phi_deg)
    return (m, np.array([r * math.cos(p), r * math.sin(p), z]), Z3)


def point_at(m: float, pos) -> tuple:
    return (m, np.asarray(pos, dtype=float), Z3)


def cylinder_z(m: float, R: float, L: float, zc: float) -> tuple:
    """Uniform solid cylinder on the z axis (textbook: m(3R^2+L^2)/12 across, mR^2/2 along)."""
    Jt = m * (3 * R * R + L * L) / 12
    return (m, np.array([0.0, 0.0, zc]), np.diag([Jt, Jt, m * R * R / 2]))


def thin_disk(m: float, a: float, normal, centre) -> tuple:
    """Thin uniform disk, radius a, unit normal n: J = (m a^2/4)(I + n n^T) (sheet §2.2)."""
    n = np.asarray(normal, dtype=float)
    n = n / np.linalg.norm(n)
    return (m, np.asarray(centre, dtype=float), m * a * a / 4 * (np.eye(3) + np.outer(n, n)))


def tilted_normal(tau_deg: float, psi_deg: float) -> np.ndarray:
    t, p = math.radians(tau_deg), math.radians(psi_deg)
    return np.array([math.sin(t) * math.cos(p), math.sin(t) * math.sin(p), math.cos(t)])


def mass_props(parts) -> tuple[float, np.ndarray, np.ndarray]:
    """Total mass, com and the inertia tensor about the com of a list of (m, c, J_own)."""
    M = sum(p[0] for p in parts)
    c = sum(p[0] * p[1] for p in parts) / M
    J = np.zeros((3, 3))
    for m, ck, Jk in parts:
        d = ck - c
        J += Jk + m * (float(d @ d) * np.eye(3) - np.outer(d, d))
    return M, c, J


def analyse(parts, **kw) -> bal.Unbalance:
    M, c, J = mass_props(parts)
    return unbalance(M, c, J, **kw)


def perfect_shaft() -> tuple:
    """Example A's shaft: 5 kg solid cylinder R 20 mm, length 400 mm, centred at z = 200 mm."""
    return cylinder_z(5.0, 20 * MM, 400 * MM, 200 * MM)


def example_a_parts() -> list:
    return [
        perfect_shaft(),
        point(10 * G, 100 * MM, 0, 100 * MM),
        point(20 * G, 80 * MM, 90, 300 * MM),
    ]


def example_b_parts() -> list:
    """Example B: 20 kg thin disk, a = 200 mm, normal tilted 0.5 deg towards 0 deg, com at 0."""
    return [thin_disk(20.0, 200 * MM, tilted_normal(0.5, 0.0), [0, 0, 0])]


def angdiff(a: float, b: float) -> float:
    """Smallest difference of two angles, deg."""
    return abs((a - b + 180.0) % 360.0 - 180.0)


# ---------------------------------------------------------------------------------------
# Example A (sheet §3.1, T13, T14)
# ---------------------------------------------------------------------------------------


def test_example_a_unbalance():
    u = analyse(example_a_parts())
    # sheet: M = 5.03 kg, z_G = 200.199 mm, COM offset (198.81, 318.09) um (6 s.f., rel 1e-5)
    assert u.mass == pytest.approx(5.03, rel=1e-12)  # a sum of three exact-ish numbers
    assert u.com_shaft[2] == pytest.approx(200.199 * MM, rel=1e-5)
    assert u.com_shaft[0] == pytest.approx(198.81e-6, rel=2e-5)  # 5 s.f. printed
    assert u.com_shaft[1] == pytest.approx(318.09e-6, rel=2e-5)
    # U = 1886.796 g mm @ 57.995 deg, e = 375.11 um (hand check U = 1000 + 1600i g mm, exact)
    assert u.static == pytest.approx(complex(1000, 1600) * GMM, rel=1e-12)  # exact sums
    assert u.static_unbalance == pytest.approx(1886.796 * GMM, rel=1e-6)
    assert u.static_angle_deg == pytest.approx(57.995, abs=1e-3)
    assert u.eccentricity == pytest.approx(375.11e-6, rel=2e-5)
    # P about z = 0 = 1.0e5 + 4.8e5 i g mm^2 (hand check), 490 306 g mm^2 @ 78.232 deg
    assert u.moment == pytest.approx(complex(1.0e5, 4.8e5) * GMM2, rel=1e-12)
    assert u.moment_unbalance == pytest.approx(490306 * GMM2, rel=1e-5)
    # P_G = 188 516 g mm^2 @ 122.108 deg, D_xz = -100 199, D_yz = 159 682 g mm^2
    assert u.couple_unbalance == pytest.approx(188516 * GMM2, rel=1e-5)
    assert u.couple_angle_deg == pytest.approx(122.108, abs=1e-3)
    assert u.couple.real == pytest.approx(-100199 * GMM2, rel=1e-5)
    assert u.couple.imag == pytest.approx(159682 * GMM2, rel=1e-5)
    # principal-axis tilt 0.162797 deg, tip azimuth 122.10 deg (long rotor: towards arg P_G)
    assert u.tilt_deg == pytest.approx(0.162797, rel=1e-5)
    assert u.tilt_azimuth_deg == pytest.approx(122.10, abs=0.01)  # printed with 2 decimals
    assert u.tilt_well_defined and u.tilt_azimuth_defined
    assert not u.statically_balanced and not u.dynamically_balanced
    assert u.warnings == ()


def test_example_a_corrections_t13():
    u = analyse(example_a_parts())
    c = corrections(u, (0.0, 400 * MM), 100 * MM)
    # hand check: C_A = -750 - 400i g mm, C_B = -250 - 1200i g mm (exact arithmetic)
    assert c.a.unbalance == pytest.approx(complex(-750, -400) * GMM, rel=1e-12)
    assert c.b.unbalance == pytest.approx(complex(-250, -1200) * GMM, rel=1e-12)
    # 8.5000 g @ 208.072 deg; 12.2577 g @ 258.232 deg; remove at 28.072 / 78.232
    assert c.a.mass == pytest.approx(8.5 * G, rel=1e-5)
    assert c.a.angle_deg == pytest.approx(208.072, abs=1e-3)
    assert c.a.remove_angle_deg == pytest.approx(28.072, abs=1e-3)
    assert c.b.mass == pytest.approx(12.2577 * G, rel=1e-5)
    assert c.b.angle_deg == pytest.approx(258.232, abs=1e-3)
    assert c.b.remove_angle_deg == pytest.approx(78.232, abs=1e-3)
    assert not c.narrow_planes
    # single-plane static correction: -U = 1886.796 g mm, at 100 mm -> 18.86796 g @ 237.995
    assert c.static.mass == pytest.approx(18.86796 * G, rel=1e-6)
    assert c.static.angle_deg == pytest.approx(57.995 + 180, abs=1e-3)
    # the ideal corrections leave nothing: residual ~ round-off of a few operations on
    # numbers of size 1e-3 kg m -> below 1e-16 kg m; 1e-15 gives 10x room
    assert abs(c.residual.static) < 1e-15
    assert abs(c.residual.moment) < 1e-15
    assert not J.residual_json(c.residual)["static_unbalance_angle_defined"]


def test_example_a_r_b_50mm_t14():
    u = analyse(example_a_parts())
    c = corrections(u, (0.0, 400 * MM), (100 * MM, 50 * MM))
    assert c.a.mass == pytest.approx(8.5 * G, rel=1e-5)
    assert c.a.angle_deg == pytest.approx(208.072, abs=1e-3)
    assert c.b.mass == pytest.approx(24.5153 * G, rel=1e-5)
    assert c.b.angle_deg == pytest.approx(258.232, abs=1e-3)


def test_example_a_bearing_forces_and_iso():
    u = analyse(example_a_parts())
    W = 3000 * RPM
    f = bearing_forces(u, W, (0.0, 400 * MM))
    # F_1 = 83.8916 N @ 28.072 deg, F_2 = 120.9782 N @ 78.232 deg
    assert abs(f.forces[0]) == pytest.approx(83.8916, rel=1e-5)
    assert abs(f.forces[1]) == pytest.approx(120.9782, rel=1e-5)
    j = J.bearing_forces_json(f)["bearing_forces"]
    assert j[0]["angle_deg"] == pytest.approx(28.072, abs=1e-3)
    assert j[1]["angle_deg"] == pytest.approx(78.232, abs=1e-3)
    iso = iso_check(u, 6.3, W, (0.0, 400 * MM))
    # e_per = 20.0535 um, U_per = 100.869 g mm, inboard 50.385 / 50.485 g mm
    assert iso.permissible_eccentricity == pytest.approx(20.0535e-6, rel=1e-5)
    assert iso.permissible_unbalance == pytest.approx(100.869 * GMM, rel=1e-5)
    assert iso.allocation.kind == "inboard"
    assert iso.allocation.allowed[0] == pytest.approx(50.385 * GMM, rel=2e-5)  # 5 s.f.
    assert iso.allocation.allowed[1] == pytest.approx(50.485 * GMM, rel=2e-5)
    # before: 850.0 g mm (ratio 16.87) and 1225.77 g mm (ratio 24.28); static G_ach 117.84
    assert abs(iso.before.residual[0]) == pytest.approx(850.0 * GMM, rel=1e-9)  # exact in §3.1
    assert abs(iso.before.residual[1]) == pytest.approx(1225.77 * GMM, rel=1e-5)
    assert iso.before.ratio[0] == pytest.approx(16.87, abs=0.005)  # printed with 2 decimals
    assert iso.before.ratio[1] == pytest.approx(24.28, abs=0.005)
    assert iso.before.static_achieved_grade == pytest.approx(117.84, abs=0.005)
    assert not iso.passed and iso.after is None and iso.after_state is None
    # the residual in each bearing plane is F_i / Omega^2 (sheet §1.5 step 2)
    for k in range(2):
        assert iso.before.residual[k] == pytest.approx(f.forces[k] / W**2, rel=1e-12)


def test_example_a_rounded_residual_two_ways():
    u = analyse(example_a_parts())
    c = corrections(u, (0.0, 400 * MM), 100 * MM)
    r = round_corrections(c, mass_step=0.1 * G, angle_step_deg=1.0)
    # 8.5 g @ 208.072 -> 8.5 g @ 208; 12.2577 g @ 258.232 -> 12.3 g @ 258
    assert r.a.mass == pytest.approx(8.5 * G, rel=1e-12)
    assert r.a.angle_deg == pytest.approx(208.0, abs=1e-9)
    assert r.b.mass == pytest.approx(12.3 * G, rel=1e-12)
    assert r.b.angle_deg == pytest.approx(258.0, abs=1e-9)
    assert r.rounded and r.ideal is c
    # residual computed here from the sheet's hand-check U, P and the rounded masses
    CA = 8.5 * G * 0.1 * cmath.exp(1j * math.radians(208))
    CB = 12.3 * G * 0.1 * cmath.exp(1j * math.radians(258))
    Ures = complex(1000, 1600) * GMM + CA + CB
    Pres = complex(1.0e5, 4.8e5) * GMM2 + 0.0 * CA + 0.4 * CB
    # a dozen operations on numbers ~1e-3: absolute round-off ~1e-18 (rel 1e-12 of 1e-5..1e-6)
    assert r.residual.static == pytest.approx(Ures, rel=1e-9)
    assert r.residual.moment == pytest.approx(Pres, rel=1e-9)
    # second way: rebuild the body with the rounded masses as point masses and re-analyse
    parts = example_a_parts() + [point(8.5 * G, 0.1, 208, 0.0), point(12.3 * G, 0.1, 258, 0.4)]
    v = analyse(parts)
    assert v.static == pytest.approx(Ures, rel=1e-9)
    assert v.moment == pytest.approx(Pres, rel=1e-9)
    # the couple about the corrected com (mass-weighted z) matches the residual's
    assert v.couple == pytest.approx(r.residual.couple, rel=1e-9)
    assert r.residual.mass == pytest.approx(v.mass, rel=1e-14)
    # apply_corrections gives the same body
    w = apply_corrections(r)
    assert w.static == pytest.approx(Ures, rel=1e-9)
    assert w.moment == pytest.approx(Pres, rel=1e-9)


# ---------------------------------------------------------------------------------------
# Example B, the course wheel (sheet §3.2, T15)
# ---------------------------------------------------------------------------------------


def test_example_b_wheel_unbalance_and_corrections():
    u = analyse(example_b_parts())
    # COM on the axle: U = 0 (disk centred at the origin; round-off only)
    assert u.statically_balanced
    assert not J.unbalance_json(u)["static_unbalance_angle_defined"]
    assert J.unbalance_json(u)["static_unbalance_angle_deg"] == 0.0
    # P = P_G = 1 745 241 g mm^2 @ 180 deg; disk D_xz = -(m a^2/8) sin 2 theta
    assert u.couple_unbalance == pytest.approx(1745241 * GMM2, rel=1e-6)
    assert u.couple_angle_deg == pytest.approx(180.0, abs=1e-6)
    assert u.moment == pytest.approx(u.couple, rel=1e-12)
    # tilt 0.500000 deg, tip azimuth 0 deg (disk-like: opposite to arg P_G)
    assert u.tilt_deg == pytest.approx(0.5, rel=1e-6)
    assert angdiff(u.tilt_azimuth_deg, 0.0) < 1e-6
    assert not u.dynamically_balanced
    # weights fixed in the shaft frame at z = -/+100 mm, radius a: 43.6310 g @ 180 / @ 0
    c = corrections(u, (-100 * MM, 100 * MM), 200 * MM)
    assert c.a.mass == pytest.approx(43.6310 * G, rel=1e-5)
    assert c.b.mass == pytest.approx(43.6310 * G, rel=1e-5)
    assert angdiff(c.a.angle_deg, 180.0) < 1e-6
    assert angdiff(c.b.angle_deg, 0.0) < 1e-6
    # couple 8726.20 g mm per plane at +-100 mm (|P_G| / 0.2 m)
    assert abs(c.a.unbalance) == pytest.approx(8726.20 * GMM, rel=1e-5)
    # closed form of §3.2: m' = m a sin 2 theta / (16 b)
    assert c.a.mass == pytest.approx(20 * 0.2 * math.sin(math.radians(1.0)) / (16 * 0.1), rel=1e-12)


def test_example_b_rim_fixed_weights_and_the_typo():
    """Weights on the tilted rim, m' from the corrected seed formula (1/4, not 1/2)."""
    m, a, b, th = 20.0, 0.2, 0.1, math.radians(0.5)
    t = math.tan(2 * th)
    mp = m * a * a * t / (8 * (2 * a * b - (a * a - b * b) * t))
    assert mp == pytest.approx(44.2165 * G, rel=1e-5)  # sheet value, 6 s.f.
    n = tilted_normal(0.5, 0.0)
    u_in = np.array([math.cos(th), 0.0, -math.sin(th)])  # in the wheel plane, towards +x
    tilts = []
    for s in (+1, -1):
        p = b * n + s * a * u_in
        u = analyse(example_b_parts() + [point_at(mp, p), point_at(mp, -p)])
        tilts.append(u.tilt_deg)
    # one placement balances exactly (the formula is exact: tilt 0 to round-off, 1e-9 deg),
    # the other doubles the tilt to 1.0 deg (sheet §3.2)
    assert min(tilts) < 1e-9
    assert max(tilts) == pytest.approx(1.0, rel=1e-4)  # "doubles", printed as 1.0
    # the seed's 1/2 makes the disk terms cancel: tan2θ·2m'(a²−b²) = 4m'ab has no
    # solution for m' except at one special angle; check the disk's own moments instead
    J = thin_disk(m, a, [0, 0, 1], [0, 0, 0])[2]
    assert J[0, 0] == pytest.approx(m * a * a / 4, rel=1e-15)  # diametral moment m a^2/4


def test_example_b_forces_iso_and_rounding():
    u = analyse(example_b_parts())
    W = 1500 * RPM
    bearings = (-50 * MM, 150 * MM)
    f = bearing_forces(u, W, bearings)
    # 215.3104 N @ 0 and @ 180 deg (a pure rocking couple); static 147.10 / 49.03 N
    assert abs(f.forces[0]) == pytest.approx(215.3104, rel=1e-6)
    assert abs(f.forces[1]) == pytest.approx(215.3104, rel=1e-6)
    j = J.bearing_forces_json(f)["bearing_forces"]
    assert angdiff(j[0]["angle_deg"], 0.0) < 1e-6 and angdiff(j[1]["angle_deg"], 180.0) < 1e-6
    assert f.static_loads[0] == pytest.approx(147.10, abs=0.005)  # printed with 2 decimals
    assert f.static_loads[1] == pytest.approx(49.03, abs=0.005)
    iso = iso_check(u, 40, W, bearings)
    # U_per = 5092.96 g mm; lever 0.75/0.25 -> clamped 3565.07 / 1527.89 g mm
    assert iso.permissible_unbalance == pytest.approx(5092.96 * GMM, rel=1e-5)
    assert iso.allocation.unclamped[0] == pytest.approx(0.75 * 5092.96 * GMM, rel=1e-5)
    assert iso.allocation.allowed[0] == pytest.approx(3565.07 * GMM, rel=1e-5)
    assert iso.allocation.allowed[1] == pytest.approx(1527.89 * GMM, rel=1e-5)
    # before: 8726.2 g mm in each bearing plane, ratios 2.45 and 5.71, FAIL
    assert abs(iso.before.residual[0]) == pytest.approx(8726.2 * GMM, rel=1e-5)
    assert iso.before.ratio[0] == pytest.approx(2.45, abs=0.005)
    assert iso.before.ratio[1] == pytest.approx(5.71, abs=0.005)
    assert not iso.passed
    # rounded to 5 g: 45 g @ 180 and 45 g @ 0 -> residual 273.80 g mm per bearing plane, PASS
    c = corrections(u, (-100 * MM, 100 * MM), 200 * MM, bearings=bearings)
    r = round_corrections(c, mass_step=5 * G)
    assert r.a.mass == pytest.approx(45 * G, rel=1e-12)  # a multiple of the step, round-off only
    assert r.b.mass == pytest.approx(45 * G, rel=1e-12)
    iso2 = iso_check(u, 40, W, bearings, corrections=r)
    assert iso2.after_state == "after rounded corrections"
    for k in range(2):
        assert abs(iso2.after.residual[k]) == pytest.approx(273.80 * GMM, rel=2e-5)  # 5 s.f.
    # ratios = 273.80/3565.07 and 273.80/1527.89 (the sheet prints 0.077 / 0.178; its second
    # figure does not follow from its own numbers: 273.80/1527.89 = 0.1792)
    assert iso2.after.ratio[0] == pytest.approx(273.80 / 3565.07, rel=2e-5)
    assert iso2.after.ratio[1] == pytest.approx(273.80 / 1527.89, rel=2e-5)
    # the corrected wheel would pass; the verdict stays the wheel's as given (F7)
    assert iso2.after.passed and not iso2.before.passed and not iso2.passed
    # residual forces 6.76 N: bearing forces of the rebuilt corrected body
    f2 = bearing_forces(apply_corrections(r), W, bearings)
    assert abs(f2.forces[0]) == pytest.approx(6.76, abs=0.005)


# ---------------------------------------------------------------------------------------
# T9-T12: point masses on a perfect shaft
# ---------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "masses, corr, forces",
    [
        # T9 pure static: 10 g @ 0, r 100, z 200 -> 5 g @ 180 both; F = 49.3480 N @ 0 both
        ([(10, 0, 200)], [(5, 180), (5, 180)], [(49.3480, 0), (49.3480, 0)]),
        # T10: 10 g @ 0 at z 100 -> 7.5 g @ 180 (A), 2.5 g @ 180 (B); 74.0220 N, 24.6740 N @ 0
        ([(10, 0, 100)], [(7.5, 180), (2.5, 180)], [(74.0220, 0), (24.6740, 0)]),
        # T11 pure couple -> 10 g @ 180 (A), 10 g @ 0 (B); 98.6960 N @ 0 / @ 180
        ([(10, 0, 0), (10, 180, 400)], [(10, 180), (10, 0)], [(98.6960, 0), (98.6960, 180)]),
        # T12 mass outside the planes: 10 g @ 90 at z 500 -> 2.5 g @ 90, 12.5 g @ 270
        ([(10, 90, 500)], [(2.5, 90), (12.5, 270)], [(24.6740, 270), (123.3701, 90)]),
    ],
)
def test_t9_to_t12(masses, corr, forces):
    parts = [perfect_shaft()] + [point(m * G, 100 * MM, phi, z * MM) for m, phi, z in masses]
    u = analyse(parts)
    c = corrections(u, (0.0, 400 * MM), 100 * MM)
    for pc, (m, a) in zip(c.pair, corr):
        assert pc.mass == pytest.approx(m * G, rel=1e-9)  # exact decimal data, round-off only
        assert angdiff(pc.angle_deg, a) < 1e-9
    f = bearing_forces(u, 3000 * RPM, (0.0, 400 * MM))
    fj = J.bearing_forces_json(f)["bearing_forces"]
    for row, (F, a) in zip(fj, forces):
        assert row["force"] == pytest.approx(F, rel=1e-6)  # sheet 6 s.f.
        assert angdiff(row["angle_deg"], a) < 1e-9


def test_t11_pure_couple_numbers():
    parts = [
        perfect_shaft(),
        point(10 * G, 100 * MM, 0, 0.0),
        point(10 * G, 100 * MM, 180, 400 * MM),
    ]
    u = analyse(parts)
    # U = 0 (to round-off of 0.1*cos(pi) etc.), P = 400 000 g mm^2 @ 180 deg
    assert u.statically_balanced
    assert u.moment_unbalance == pytest.approx(400000 * GMM2, rel=1e-12)
    assert angdiff(J.unbalance_json(u)["moment_unbalance_angle_deg"], 180.0) < 1e-9


# ---------------------------------------------------------------------------------------
# T18: sign of the products (D = -J)
# ---------------------------------------------------------------------------------------


def test_t18_tilted_disk_product_sign():
    u = analyse([thin_disk(25.0, 150 * MM, tilted_normal(0.2, 90.0), [0, 0, 0])])
    # D_xz = 0, D_yz = -4.908699e-4 kg m^2, P_G = 490 870 g mm^2 @ 270 deg
    assert abs(u.couple.real) < 1e-18  # cos(90 deg) round-off times 5e-4
    assert u.couple.imag == pytest.approx(-4.908699e-4, rel=1e-6)
    assert u.couple_angle_deg == pytest.approx(270.0, abs=1e-9)
    assert u.couple_unbalance == pytest.approx(490870 * GMM2, rel=1e-5)
    # the tensor element has the opposite sign
    assert u.inertia_shaft[1, 2] == pytest.approx(+4.908699e-4, rel=1e-6)
    # closed form of §2.2: D_xz + i D_yz = -(m a^2/8) sin 2 tau e^{i psi}
    expect = -(25 * 0.15**2 / 8) * math.sin(math.radians(0.4)) * cmath.exp(1j * math.pi / 2)
    assert u.couple == pytest.approx(expect, rel=1e-12, abs=1e-18)


# ---------------------------------------------------------------------------------------
# ISO tolerance (T1-T8, T24)
# ---------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "grade, rpm, mass, u_per_gmm",
    [(6.3, 1480, 150, 6097.35), (2.5, 3000, 37, 294.437), (1.0, 12000, 2.5, 1.98944),
     (40, 1000, 20, 7639.44), (0.4, 30000, 0.2, 0.025465)],
)
def test_t1_to_t5_permissible_unbalance(grade, rpm, mass, u_per_gmm):
    e, U = permissible_unbalance(grade, rpm * RPM, mass)
    assert U == pytest.approx(u_per_gmm * GMM, rel=1e-5)  # sheet 6 s.f. (T5: 5 s.f.)
    assert e == pytest.approx(U / mass, rel=1e-15)
    # shop form with the exact constant 60e3/(2 pi) = 9549.2966 (sheet §1.2)
    assert U / GMM == pytest.approx(60e3 / (2 * math.pi) * grade * mass / rpm, rel=1e-12)


def test_t1_eper_and_9549_shortcut():
    e, U = permissible_unbalance(6.3, 1480 * RPM, 150)
    assert e == pytest.approx(40.6490e-6, rel=1e-5)
    # the rounded constant 9549 gives the sheet's 6097.17 instead (ratio 9549/9549.2966)
    assert 9549 * 6.3 * 150 / 1480 == pytest.approx(6097.17, abs=0.005)
    assert U / GMM * 9549 / 9549.2966 == pytest.approx(6097.17, abs=0.01)


def test_t6_imperial_constants():
    """U_per[oz in] = 6.0153 G W[lb]/n and U_per[g in] = 170.531 G W[lb]/n, via pint."""
    import pint

    ureg = pint.UnitRegistry()
    W_lb, G_, n = 1000.0, 2.5, 3600.0
    mass = (W_lb * ureg.lb).to("kg").magnitude
    _, U = permissible_unbalance(G_, n * RPM, mass)
    U_q = U * ureg("kg*m")
    assert U_q.to("oz*in").magnitude == pytest.approx(6.0153 * G_ * W_lb / n, rel=1e-5)
    assert U_q.to("g*in").magnitude == pytest.approx(170.531 * G_ * W_lb / n, rel=1e-5)


# the sheet allocates the unrounded U_per of T1 (6097.35 is its rounding), in g mm
UPER_T1 = permissible_unbalance(6.3, 1480 * RPM, 150)[1] / GMM


@pytest.mark.parametrize(
    "com_mm, expect",
    [(500, (3048.68, 3048.68)), (350, (3963.28, 2134.07)), (100, (4268.15, 1829.21))],
)
def test_t7_allocation_inboard(com_mm, expect):
    a = allocate_permissible(UPER_T1, com_mm * MM, (0.0, 1000 * MM))
    assert a.kind == "inboard" and not a.rbcli_rule
    assert a.allowed[0] == pytest.approx(expect[0], abs=0.0051)  # printed with 2 decimals
    assert a.allowed[1] == pytest.approx(expect[1], abs=0.0051)


def test_t7_allocation_clamp_and_unclamped():
    a = allocate_permissible(UPER_T1, 100 * MM, (0.0, 1000 * MM))
    # unclamped 5487.62 / 609.73 (sheet table)
    assert a.unclamped[0] == pytest.approx(5487.62, abs=0.0051)  # printed with 2 decimals
    # exact 609.7355; the sheet's 609.73 is 0.1 x its rounded 6097.35 = 609.735, rounded down:
    # allow 0.006 (one rounding of U_per plus half a unit in the last digit)
    assert a.unclamped[1] == pytest.approx(609.73, abs=0.006)


def test_t8_allocation_com_on_bearing():
    a = allocate_permissible(1000.0, 1000 * MM, (0.0, 1000 * MM))
    assert a.kind == "inboard"
    assert a.allowed == pytest.approx((300.0, 700.0), rel=1e-12)


def test_allocation_outboard_derived_rule():
    # sheet §1.6 table, COM at 1200 mm: 1219.47 / 7316.83 without a floor
    a = allocate_permissible(UPER_T1, 1200 * MM, (0.0, 1000 * MM), outboard_floor=0.0)
    assert a.kind == "outboard" and a.rbcli_rule and "rbcli" in a.rule
    assert a.allowed[0] == pytest.approx(1219.47, abs=0.0051)  # printed with 2 decimals
    assert a.allowed[1] == pytest.approx(7316.83, abs=0.0051)
    # default floor 0.3 U_per on the far plane (sheet §1.4c suggestion)
    b = allocate_permissible(UPER_T1, 1200 * MM, (0.0, 1000 * MM))
    assert b.allowed[0] == pytest.approx(0.3 * UPER_T1, rel=1e-12)
    assert b.allowed[1] == pytest.approx(7316.83, abs=0.0051)
    # the sheet's example: COM at 1.01 m, U_per 1000 -> 10 / 1010 unfloored
    c = allocate_permissible(1000.0, 1.01, (0.0, 1.0), outboard_floor=0.0)
    assert c.allowed == pytest.approx((10.0, 1010.0), rel=1e-9)
    # overhung on the other side: the order of the planes is kept
    d = allocate_permissible(1000.0, -0.2, (0.0, 1.0), outboard_floor=0.0)
    assert d.allowed == pytest.approx((1200.0, 200.0), rel=1e-12)


def test_iso_outboard_rotor_warns():
    # an overhung disk: com at z = 0.3 beyond bearings 0 and 0.2
    u = analyse([thin_disk(10.0, 0.15, tilted_normal(0.1, 0), [1e-4, 0, 0.3])])
    iso = iso_check(u, 6.3, 1500 * RPM, (0.0, 0.2))
    assert iso.allocation.kind == "outboard" and iso.warnings
    # static loads of an overhung rotor: the far bearing is pulled up (negative)
    f = bearing_forces(u, 1500 * RPM, (0.0, 0.2))
    # lever rule (0.2 - 0.3)/0.2 = -0.5 and (0.3 - 0)/0.2 = 1.5; a few operations of round-off
    assert f.static_loads[0] == pytest.approx(-0.5 * 10 * 9.80665, rel=1e-12)
    assert f.static_loads[1] == pytest.approx(1.5 * 10 * 9.80665, rel=1e-12)


def test_t24_achieved_grade():
    assert achieved_grade(50 * GMM, 37, 3000 * RPM) == pytest.approx(0.4245, abs=5e-5)


@pytest.mark.parametrize("grade", [0.39, 4001, -1, float("nan")])
def test_iso_grade_out_of_range(grade):
    with pytest.raises(ValueError):
        permissible_unbalance(grade, 100.0, 1.0)


def test_iso_bad_speed_and_planes():
    u = analyse(example_a_parts())
    with pytest.raises(ValueError):
        iso_check(u, 6.3, 0.0, (0, 0.4))
    with pytest.raises(ValueError):
        iso_check(u, 6.3, 100.0, (0.2, 0.2))


# ---------------------------------------------------------------------------------------
# splitting, radius change (T22, T23)
# ---------------------------------------------------------------------------------------


def test_t22_split():
    s = split_to_positions(18.0, 100.0, 8)
    assert s.angles_deg == (90.0, 135.0) and s.positions == (2, 3)
    assert s.masses[0] == pytest.approx(14.6009, rel=1e-5)
    assert s.masses[1] == pytest.approx(4.4204, rel=1e-5)
    # on a position: all of it there
    t = split_to_positions(5.0, 45.0, 8)
    assert t.masses == (5.0, 0.0) and t.angles_deg[0] == 45.0
    # with an offset and wrap-around: 10 g @ 355 deg, 6 blades from 30 deg -> 330 / 30
    w = split_to_positions(10.0, 355.0, 6, offset_deg=30.0)
    assert w.angles_deg == pytest.approx((330.0, 30.0), abs=1e-12)
    assert w.positions == (5, 0)
    with pytest.raises(ValueError):
        split_to_positions(1.0, 10.0, 2)
    with pytest.raises(ValueError):
        split_between(1.0, 10.0, 0.0, 180.0)


@given(
    m=st.floats(0.0, 100.0),
    phi=st.floats(-720.0, 720.0),
    n=st.integers(3, 36),
    off=st.floats(-360.0, 360.0),
)
@settings(max_examples=50, deadline=None)
def test_split_vector_sum(m, phi, n, off):
    s = split_to_positions(m, phi, n, off)
    total = sum(mk * cmath.exp(1j * math.radians(a)) for mk, a in zip(s.masses, s.angles_deg))
    # two sines and a division: round-off ~1e-15 relative to m (angles up to 720 deg lose
    # ~1e-13 deg in the wrap); 1e-11 absolute on m <= 100 leaves room
    assert total == pytest.approx(m * cmath.exp(1j * math.radians(phi)), abs=1e-11)
    assert min(s.masses) >= 0.0
    assert angdiff(s.angles_deg[1] - s.angles_deg[0], 360.0 / n) < 1e-9


def test_t23_radius_change():
    assert mass_at_radius(10.0, 100.0, 125.0) == pytest.approx(8.0, rel=1e-15)
    with pytest.raises(ValueError):
        mass_at_radius(10.0, 100.0, 0.0)


# ---------------------------------------------------------------------------------------
# degenerate inputs (T25) and the isotropic flag
# ---------------------------------------------------------------------------------------


def test_t25_degenerate_inputs():
    u = analyse(example_a_parts())
    with pytest.raises(ValueError):
        corrections(u, (0.1, 0.1), 0.1)
    with pytest.raises(ValueError):
        corrections(u, (0.0, 0.4), 0.0)
    with pytest.raises(ValueError):
        corrections(u, (0.0, 0.4), (0.1, -0.1))
    with pytest.raises(ValueError):
        bearing_forces(u, 100.0, (0.3, 0.3))
    with pytest.raises(ValueError):
        unbalance(0.0, [0, 0, 0], np.eye(3))
    with pytest.raises(ValueError):
        unbalance(1.0, [0, 0, 0], np.eye(3), axis=(0, 0, 0))
    with pytest.raises(ValueError):
        unbalance(1.0, [0, 0, 0], np.eye(3), angle_sense="clockwise")
    with pytest.raises(ValueError):
        round_corrections(corrections(u, (0, 0.4), 0.1), mass_step=0.0)


def test_t25_zero_unbalance_angles_undefined():
    # a perfect shaft: U = 0, P = 0 -> zero masses, angles 0.0 with *_defined false, no NaN
    u = analyse([perfect_shaft()])
    assert u.statically_balanced and u.dynamically_balanced
    c = corrections(u, (0.0, 0.4), 0.1)
    f = bearing_forces(u, 300.0, (0.0, 0.4))
    iso = iso_check(u, 2.5, 300.0, (0.0, 0.4), corrections=c)
    d = balance_json(u, c, f, iso)
    text = json.dumps(d, allow_nan=False)  # raises on NaN/inf
    assert "NaN" not in text
    assert d["static_unbalance_angle_deg"] == 0.0 and d["static_unbalance_angle_defined"] is False
    assert d["couple_unbalance_angle_defined"] is False
    for row in d["corrections"]:
        assert row["mass"] == 0.0 and row["angle_deg"] == 0.0 and row["angle_defined"] is False
    for row in d["bearing_forces"]:
        assert row["force"] == 0.0 and row["angle_defined"] is False
    assert d["tilt_deg"] == 0.0 and d["tilt_azimuth_defined"] is False
    assert d["iso"]["pass"] is True


def test_t25_isotropic_rotor_flags_tilt():
    # a solid sphere (J = 2/5 m R^2 I) with its com 1 mm off the shaft: principal axes undefined
    m, R = 3.0, 0.1
    sphere = (m, np.array([1e-3, 0.0, 0.05]), 0.4 * m * R * R * np.eye(3))
    u = analyse([sphere])
    assert not u.tilt_well_defined and u.warnings
    assert u.tilt_deg == 0.0  # every axis through the com is principal
    assert u.couple_unbalance == 0.0 and not u.dynamically_balanced  # static unbalance remains
    # nearly isotropic (moments 1e-8 apart): still flagged
    Jn = 0.4 * m * R * R * np.diag([1.0, 1.0 + 1e-8, 1.0 - 1e-8])
    v = unbalance(m, [0, 0, 0], Jn)
    assert not v.tilt_well_defined
    # a symmetric rotor about the shaft is well defined
    assert analyse(example_b_parts()).tilt_well_defined


def test_tilt_to_a_degenerate_plane():
    """A thin rod: the plane at right angles to it is a degenerate eigenspace.

    Rod along (0, cos b, sin b): the plane holds x and (0, -sin b, cos b); the angle from
    the shaft z to that plane is b, leaning towards -y (270 deg).
    """
    b = math.radians(20.0)
    d = np.array([0.0, math.cos(b), math.sin(b)])
    m, L = 2.0, 1.0
    J = m * L * L / 12 * (np.eye(3) - np.outer(d, d))  # thin rod about its centre
    u = unbalance(m, [0, 0, 0], J)
    assert u.tilt_deg == pytest.approx(20.0, rel=1e-12)  # atan2 of exact components
    assert u.tilt_azimuth_deg == pytest.approx(270.0, abs=1e-9)
    assert u.tilt_well_defined
    # rod at right angles to the shaft: the shaft lies in the plane, tilt 0
    v = unbalance(m, [0, 0, 0], m * L * L / 12 * (np.eye(3) - np.outer([0, 1, 0], [0, 1, 0])))
    assert v.tilt_deg == 0.0 and v.dynamically_balanced


# ---------------------------------------------------------------------------------------
# frames, senses, invariance
# ---------------------------------------------------------------------------------------


def test_shaft_frame_rule():
    f = shaft_frame()
    assert np.array_equal(f.rotation, np.eye(3))  # default shaft: the body frame exactly
    fx = shaft_frame([2, 0, 0])
    assert fx.rotation == pytest.approx(np.array([[0, 1, 0], [0, 0, 1], [1, 0, 0]]), abs=0)
    fy = shaft_frame([0, 1, 0])
    assert fy.rotation == pytest.approx(np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]]), abs=0)
    # continuity near body x: a 0.01 rad wobble keeps e_x near body y (a switch rule close
    # to the axis, e.g. "within 1e-6", would project body x and swing e_x round instead)
    fw = shaft_frame([1, 1e-2, 1e-2])
    assert fw.rotation[0] @ np.array([0, 1, 0]) > 0.999
    # 45-degree diagonals are away from the switch: body x projected
    fd = shaft_frame([1, 1, 0])
    assert fd.rotation[0] == pytest.approx([0.5**0.5, -(0.5**0.5), 0], abs=1e-15)
    # zero mark turns e_x about e_z
    f90 = shaft_frame(zero_mark_deg=90)
    assert f90.rotation[0] == pytest.approx([0, 1, 0], abs=1e-16)
    with pytest.raises(ValueError):
        shaft_frame([0, 0, 1], reference=[0, 0, 5])
    with pytest.raises(ValueError):
        shaft_frame([0, 0, 0])


@given(axis=st.lists(st.floats(-1, 1), min_size=3, max_size=3))
@settings(max_examples=50, deadline=None)
def test_shaft_frame_orthonormal(axis):
    a = np.array(axis)
    assume(np.linalg.norm(a) > 1e-3)
    R = shaft_frame(a).rotation
    # orthonormal to round-off of a few normalisations (1e-15); det +1 (right-handed)
    assert R @ R.T == pytest.approx(np.eye(3), abs=1e-14)
    assert np.linalg.det(R) == pytest.approx(1.0, abs=1e-14)
    assert R[2] == pytest.approx(a / np.linalg.norm(a), abs=1e-15)


def test_zero_mark_shifts_angles():
    u = analyse(example_a_parts())
    v = analyse(example_a_parts(), zero_mark_deg=90.0)
    assert v.static_angle_deg == pytest.approx(57.995 - 90 + 360, abs=1e-3)
    assert angdiff(v.couple_angle_deg, u.couple_angle_deg - 90) < 1e-9


def test_angle_sense_against_mirrors():
    parts = example_a_parts()
    u = analyse(parts)
    v = analyse(parts, angle_sense="against")
    W, brg, planes = 3000 * RPM, (0.0, 0.4), (0.0, 0.4)
    def doc(x):
        return balance_json(
            x, corrections(x, planes, 0.1), bearing_forces(x, W, brg), iso_check(x, 6.3, W, brg)
        )

    ju, jv = doc(u), doc(v)
    for k in ("static_unbalance_angle_deg", "couple_unbalance_angle_deg", "tilt_azimuth_deg"):
        assert angdiff(jv[k], 360.0 - ju[k]) < 1e-9
    for a, b in zip(ju["corrections"], jv["corrections"]):
        assert a["mass"] == b["mass"]
        assert angdiff(b["angle_deg"], 360.0 - a["angle_deg"]) < 1e-9
    for a, b in zip(ju["bearing_forces"], jv["bearing_forces"]):
        assert a["force"] == b["force"]
        assert angdiff(b["angle_deg"], 360.0 - a["angle_deg"]) < 1e-9
    for k in ("static_unbalance", "couple_unbalance", "tilt_deg", "eccentricity"):
        assert ju[k] == jv[k]
    # rounding happens in the reported sense: multiples of 7 deg (7 does not divide 360)
    r = round_corrections(corrections(v, planes, 0.1), angle_step_deg=7.0)
    for pc in r.pair:
        assert pc.angle_deg / 7.0 == pytest.approx(round(pc.angle_deg / 7.0), abs=1e-9)


def test_non_z_shaft_cyclic_axes():
    """Example A turned so that its z goes to body x (x -> y, y -> z): the same shaft frame."""
    Q = np.array([[0, 0, 1], [1, 0, 0], [0, 1, 0]], dtype=float)
    M, c, J = mass_props(example_a_parts())
    t = np.array([0.3, -0.2, 0.7])
    u = analyse(example_a_parts())
    v = unbalance(M, Q @ c + t, Q @ J @ Q.T, axis=[1, 0, 0], through=t)
    # same numbers: a permutation of axes is exact; the shift t costs ~eps*|t|
    assert v.static == pytest.approx(u.static, rel=1e-12)
    assert v.moment == pytest.approx(u.moment, rel=1e-12)
    assert v.tilt_deg == pytest.approx(u.tilt_deg, rel=1e-9)
    assert v.tilt_azimuth_deg == pytest.approx(u.tilt_azimuth_deg, abs=1e-9)
    cu = corrections(u, (0, 0.4), 0.1)
    cv = corrections(v, (0, 0.4), 0.1)
    assert cv.a.mass == pytest.approx(cu.a.mass, rel=1e-12)
    assert cv.a.angle_deg == pytest.approx(cu.a.angle_deg, abs=1e-9)
    # the corrections land at the rotated points
    pu = dict(enumerate(bal.correction_points(cu)))
    pv = dict(enumerate(bal.correction_points(cv)))
    for k in pu:
        # coordinates ~1 m built from a rotation and a shift: a few eps absolute
        assert pv[k][1] == pytest.approx(Q @ pu[k][1] + t, abs=1e-14)


# ---------------------------------------------------------------------------------------
# random rotors (hypothesis)
# ---------------------------------------------------------------------------------------

# Coordinates are 0 or at least 1e-9 m: products of two coordinates near the smallest
# normal float (~1e-308) underflow to subnormals with fewer significant bits than the
# 1e-12..1e-13 relative round-off budgets below assume (no rotor is that small).
coord = st.one_of(st.just(0.0), st.floats(1e-9, 0.2), st.floats(-0.2, -1e-9))
zpos = st.floats(-0.5, 0.5, allow_subnormal=False)
pt = st.tuples(st.floats(1e-3, 1.0), coord, coord, zpos)


@st.composite
def rotors(draw):
    pts = draw(st.lists(pt, min_size=1, max_size=5))
    parts = [point_at(m, [x, y, z]) for m, x, y, z in pts]
    dm = draw(st.floats(0.5, 20.0))
    da = draw(st.floats(0.05, 0.3))
    tau = draw(st.floats(0.0, 10.0))
    psi = draw(st.floats(0.0, 360.0))
    dc = [draw(st.floats(-0.01, 0.01)), draw(st.floats(-0.01, 0.01)), draw(zpos)]
    parts.append(thin_disk(dm, da, tilted_normal(tau, psi), dc))
    return parts


@given(
    parts=rotors(),
    za=st.floats(-0.5, 0.5),
    dz=st.floats(0.05, 1.0),
    sign=st.sampled_from([1, -1]),
    ra=st.floats(0.02, 0.3),
    rb=st.floats(0.02, 0.3),
)
@settings(max_examples=50, deadline=None)
def test_t26_round_trip(parts, za, dz, sign, ra, rb):
    """Add the computed corrections as point masses: com on the axis, products vanish.

    Tolerance: U_res and the products are sums of ~20 terms m*x and m*x*z, each carrying a
    relative round-off of a few eps (2.2e-16), and the module's mass/angle round trip through
    degrees adds ~1e-15 relative. The cancellation leaves an absolute error ~1e-14 of the
    scale S1 = sum m|r| (S2 = sum m|r|^2 + |J_disk|); 1e-12 keeps a 100x margin and still
    fails for any mistake larger than round-off.
    """
    u = analyse(parts)
    zb = za + sign * dz
    c = corrections(u, (za, zb), (ra, rb))
    added = []
    for pc, z, r in ((c.a, za, ra), (c.b, zb, rb)):
        # the correction's direction from its phasor, also when it is below the tolerance
        # that makes the reported angle "undefined" (a 5e-13 kg mass still has a direction)
        phi = float(np.degrees(np.angle(pc.unbalance))) if pc.mass > 0 else 0.0
        added.append(point(pc.mass, r, phi, z))
    M2, c2, J2 = mass_props(parts + added)
    allp = parts + added
    S1 = sum(p[0] * np.linalg.norm(p[1]) for p in allp)
    S2 = sum(p[0] * float((p[1] - c2) @ (p[1] - c2)) + np.trace(p[2]) for p in allp)
    assert M2 * math.hypot(c2[0], c2[1]) <= 1e-12 * S1
    assert abs(J2[0, 2]) <= 1e-12 * S2 and abs(J2[1, 2]) <= 1e-12 * S2
    # the module's own residual agrees (same bound)
    assert abs(c.residual.static) <= 1e-12 * S1
    # principal tilt of the corrected rotor vanishes (< 1e-9 deg, T26) where the tilt is
    # well conditioned: tilt ~ |P_G| / gap, so ask for a gap of at least 1e-3 of the trace
    w = apply_corrections(c)
    assert w.statically_balanced and w.dynamically_balanced
    if w.principal_gap > 1e-3 * np.trace(J2):
        assert w.tilt_deg < 1e-9


@given(parts=rotors(), seed=st.integers(0, 2**32 - 1))
@settings(max_examples=40, deadline=None)
def test_rotation_invariance(parts, seed):
    """Rotate a rotor and its shaft together: magnitudes and tilt unchanged (scipy Rotation)."""
    from scipy.spatial.transform import Rotation

    Q = Rotation.random(random_state=seed).as_matrix()
    M, c, J = mass_props(parts)
    t = np.array([0.1, -0.3, 0.2])
    u = unbalance(M, c, J)
    v = unbalance(M, Q @ c + t, Q @ J @ Q.T, axis=Q @ [0, 0, 1], through=t)
    # the rotation costs a few eps relative to the scale of each quantity (|com|, |J|)
    scale_u = M * (np.linalg.norm(c) + 1.0)
    scale_p = np.trace(J) + M * float(c @ c) + M
    assert abs(v.static_unbalance - u.static_unbalance) <= 1e-13 * scale_u
    assert abs(v.couple_unbalance - u.couple_unbalance) <= 1e-13 * scale_p
    assert v.eccentricity == pytest.approx(u.eccentricity, abs=1e-13 * (np.linalg.norm(c) + 1.0))
    # tilt: eigenvector round-off ~ eps * |J| / gap
    assume(u.principal_gap > 1e-3 * np.trace(J))
    assert v.tilt_deg == pytest.approx(u.tilt_deg, abs=1e-9)
    # with the reference mark rotated too, the angles agree as well
    w = unbalance(M, Q @ c + t, Q @ J @ Q.T, axis=Q @ [0, 0, 1], through=t, reference=Q @ [1, 0, 0])
    if u.static_unbalance > 1e-9 * scale_u:
        assert angdiff(w.static_angle_deg, u.static_angle_deg) < 1e-6
    if u.couple_unbalance > 1e-9 * scale_p:
        assert angdiff(w.couple_angle_deg, u.couple_angle_deg) < 1e-6


@given(parts=rotors(), z1=st.floats(-0.5, 0.5), dz=st.floats(0.05, 1.0), W=st.floats(1.0, 2000.0))
@settings(max_examples=50, deadline=None)
def test_bearing_forces_two_ways(parts, z1, dz, W):
    """Closed form vs Newton-Euler: N_O = w x (J_O w) and F = M a_G, solved for two bearings."""
    M, c, J = mass_props(parts)
    u = unbalance(M, c, J)
    z2 = z1 + dz
    f = bearing_forces(u, W, (z1, z2))
    # independent: J about the origin by the parallel-axis theorem, N_O = w x (J_O w)
    JO = J + M * (float(c @ c) * np.eye(3) - np.outer(c, c))
    om = np.array([0.0, 0.0, W])
    NO = np.cross(om, JO @ om)
    # supports act on the rotor with S_i at (0, 0, z_i): sum S = M a_G = -W^2 M (x_G, y_G),
    # sum (0,0,z_i) x S_i = (-z S_y, z S_x) summed = N_O; unknowns S1x, S1y, S2x, S2y
    A = np.array([[1, 0, 1, 0], [0, 1, 0, 1], [0, -z1, 0, -z2], [z1, 0, z2, 0]], dtype=float)
    rhs = np.array([-W * W * M * c[0], -W * W * M * c[1], NO[0], NO[1]])
    S = np.linalg.solve(A, rhs)
    F1, F2 = complex(-S[0], -S[1]), complex(-S[2], -S[3])
    scale = W * W * (M * np.linalg.norm(c) + (np.trace(J) + M * float(c @ c)) / dz) + 1e-30
    # both routes round off at ~1e-15 of the scale (parallel-axis sums, a 4x4 solve whose
    # condition is ~(1 + 1/dz)^2 <= 441); 1e-12 keeps margin
    assert abs(f.forces[0] - F1) <= 1e-12 * scale
    assert abs(f.forces[1] - F2) <= 1e-12 * scale
    assert f.torque_origin[:2] == pytest.approx(NO[:2], abs=1e-12 * scale * (1 + abs(z1) + abs(z2)))
    # static loads: lever rule, W1 + W2 = M g and their moment balances about the com
    assert sum(f.static_loads) == pytest.approx(M * 9.80665, rel=1e-12)
    assert f.static_loads[0] * (z1 - c[2]) + f.static_loads[1] * (z2 - c[2]) == pytest.approx(
        0.0, abs=1e-12 * M * 9.80665 * (1 + abs(z1) + abs(z2))
    )


@given(pts=st.lists(pt, min_size=1, max_size=6), z1=st.floats(-0.5, 0.5), dz=st.floats(0.05, 1.0))
@settings(max_examples=50, deadline=None)
def test_bearing_forces_centrifugal_sum(pts, z1, dz):
    """Point-mass rotor: each mass pulls m W^2 (x + i y) at its z, shared by the lever rule."""
    W = 314.0
    parts = [point_at(m, [x, y, z]) for m, x, y, z in pts]
    u = analyse(parts)
    z2 = z1 + dz
    f = bearing_forces(u, W, (z1, z2))
    F1 = sum(m * W * W * complex(x, y) * (z2 - z) / dz for m, x, y, z in pts)
    F2 = sum(m * W * W * complex(x, y) * (z - z1) / dz for m, x, y, z in pts)
    scale = W * W * sum(
        m * (abs(x) + abs(y)) * (1 + (abs(z) + abs(z1) + abs(z2)) / dz) for m, x, y, z in pts
    )
    assert abs(f.forces[0] - F1) <= 1e-13 * scale  # sums of <= 6 products; round-off ~1e-15
    assert abs(f.forces[1] - F2) <= 1e-13 * scale
    # the torque about the com is w x (J_G w) in the shaft frame; for a point rotor its
    # transverse part is -i W^2 P_G (sheet §2.6)
    Nc = complex(f.torque[0], f.torque[1])
    assert Nc == pytest.approx(-1j * W * W * u.couple, abs=1e-13 * scale * (1 + 1 / dz))


@given(parts=rotors())
@settings(max_examples=40, deadline=None)
def test_tilt_matches_eigh(parts):
    """Tilt against numpy's eigh on the tensor directly (nearest eigenvector to z)."""
    M, c, J = mass_props(parts)
    u = unbalance(M, c, J)
    w, V = np.linalg.eigh(J)
    gaps = [min(abs(w[k] - w[j]) for j in range(3) if j != k) for k in range(3)]
    k = int(np.argmax(np.abs(V[2])))
    assume(gaps[k] > 1e-3 * np.trace(J))
    v = V[:, k] * np.sign(V[2, k])
    tilt = math.degrees(math.atan2(math.hypot(v[0], v[1]), v[2]))
    # eigenvector error ~ eps |J| / gap <= 2e-13 rad with the gap assumed; 1e-9 deg margin
    assert u.tilt_deg == pytest.approx(tilt, abs=1e-9)
    if tilt > 1e-6:
        assert angdiff(u.tilt_azimuth_deg, math.degrees(math.atan2(v[1], v[0]))) < 1e-4


# ---------------------------------------------------------------------------------------
# corrections: narrow planes, plane_unbalances; JSON shape
# ---------------------------------------------------------------------------------------


def test_narrow_plane_rule():
    u = analyse(example_a_parts())
    assert corrections(u, (0.19, 0.21), 0.1, bearings=(0, 0.4)).narrow_planes
    assert not corrections(u, (0.0, 0.4), 0.1, bearings=(0, 0.4)).narrow_planes
    # without bearings: the rotor's equivalent axial length (shaft 400 mm plus two points)
    c = corrections(u, (0.19, 0.21), 0.1)
    assert c.narrow_planes and c.narrow_reference_kind == "rotor axial length"
    assert c.narrow_reference == pytest.approx(0.4, rel=0.01)  # the shaft dominates: ~400 mm
    assert c.warnings


def test_plane_unbalances_identities():
    U, P = complex(1.0, -2.0), complex(0.3, 0.7)
    a, b = plane_unbalances(U, P, -0.2, 0.5)
    # U_A + U_B = U, z_A U_A + z_B U_B = P (sheet §2.5 check), a few operations of round-off
    assert a + b == pytest.approx(U, rel=1e-14)
    assert -0.2 * a + 0.5 * b == pytest.approx(P, rel=1e-14)
    with pytest.raises(ValueError):
        plane_unbalances(U, P, 0.1, 0.1)


def _plain(x) -> bool:
    if isinstance(x, dict):
        return all(isinstance(k, str) and _plain(v) for k, v in x.items())
    if isinstance(x, list):
        return all(_plain(v) for v in x)
    return x is None or type(x) in (bool, int, float, str)


def test_balance_json_keys():
    u = analyse(example_a_parts())
    W = 3000 * RPM
    c = round_corrections(corrections(u, (0.0, 0.4), 0.1), mass_step=1e-4)
    iso = iso_check(u, 6.3, W, (0.0, 0.4), corrections=c)
    d = balance_json(u, c, bearing_forces(u, W, (0.0, 0.4)), iso)
    json.dumps(d, allow_nan=False)
    assert _plain(d)  # only plain Python types: no numpy scalars
    for k in ("mass", "eccentricity", "static_unbalance", "static_unbalance_angle_deg",
              "couple_unbalance", "tilt_deg", "statically_balanced", "dynamically_balanced"):
        assert k in d
    assert len(d["corrections"]) == 2 and len(d["bearing_forces"]) == 2
    for r in d["corrections"]:
        assert {"plane", "mass", "radius", "angle_deg"} <= set(r)
    for r in d["bearing_forces"]:
        assert {"plane", "force", "angle_deg"} <= set(r)
    assert set(("grade", "permissible_unbalance", "allowed", "residual", "pass")) <= set(d["iso"])
    assert len(d["iso"]["allowed"]) == 2 and len(d["iso"]["residual"]) == 2
    assert d["corrections"][0]["plane"] == 0.0 and d["corrections"][1]["plane"] == 0.4
    # iso judges the rotor as given; the corrected rotor is the prediction under "after"
    assert d["iso"]["judged"] == "as given" and d["iso"]["pass"] is d["iso"]["before"]["pass"]
    assert d["iso"]["residual"] == d["iso"]["before"]["residual"]
    assert d["iso"]["after"]["state"] == "after rounded corrections" and d["iso"]["after"]["prediction"]
    # no bearing_forces key without bearings (SPEC: "when speed and bearings are given")
    e = balance_json(u, forces=bearing_forces(u, W))
    assert "bearing_forces" not in e and "dynamics" in e
    # every JSON function gives plain data too
    assert _plain(J.positions_json(bal.split_corrections(c, 6)))
    assert _plain(J.residual_json(c.residual)) and _plain(J.frame_json(u.frame))


def test_iso_correction_planes_and_foreign_corrections():
    u = analyse(example_a_parts())
    W = 3000 * RPM
    iso = iso_check(u, 6.3, W, (0.1, 0.3), planes_are="correction")
    assert iso.planes_are == "correction"
    # residuals are the equivalent unbalances in those planes (sheet §1.4b / §2.5)
    ua, ub = plane_unbalances(u.static, u.moment, 0.1, 0.3)
    assert iso.before.residual == pytest.approx((ua, ub), rel=1e-14)
    with pytest.raises(ValueError):
        iso_check(u, 6.3, W, (0.1, 0.3), planes_are="journal")
    other = analyse(example_b_parts())
    with pytest.raises(ValueError):
        iso_check(u, 6.3, W, (0.0, 0.4), corrections=corrections(other, (-0.1, 0.1), 0.2))


def test_rounding_keeps_bearings_for_narrow_rule():
    u = analyse(example_a_parts())
    c = corrections(u, (0.19, 0.21), 0.1, bearings=(0.0, 4.0))
    r = round_corrections(c, mass_step=1e-3)
    assert r.narrow_reference_kind == "bearing span" and r.narrow_reference == 4.0
    # rounding twice rounds the ideal masses, not the rounded ones
    rr = round_corrections(r, mass_step=1e-4)
    assert rr.ideal is c
    # nearest multiple of the step (half-up); a product and a floor: round-off only
    assert rr.a.mass == pytest.approx(math.floor(c.a.mass / 1e-4 + 0.5) * 1e-4, rel=1e-12)
