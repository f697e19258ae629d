"""``rbcli precess`` through the command line.

Oracles: the physics sheet's cases P1-P4, P6, P8 (dynamics.md §6, six significant figures
unless the sheet prints more), the sheet's symmetric-body closed forms (§1.1) evaluated here
from the textbook moments of a thin disk (Is = 2I), a spheroid and the Earth's C and
Is/I, the scaling law of Euler's equations (w -> c w, t -> t/c), scipy's DOP853 integration
of Euler's equations and the attitude (written here, independent of rbcli), and the
invariants T, |L| and L fixed in space.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from conftest import sampled_params
from hypothesis import given, settings
from hypothesis import strategies as st


ROOT = Path(__file__).resolve().parent.parent
EX = ROOT / "examples"
SPEC_KEYS = ("angular_momentum", "kinetic_energy", "symmetric", "period", "circles_axis",
             "precession_rate", "space_precession_rate", "body_cone_deg", "space_cone_deg",
             "flip_interval")
I123 = "{shape: given, mass: 1, inertia: [[1, 0, 0], [0, 2, 0], [0, 0, 3]]}"
DEG = math.pi / 180


def js(cli, *args: str, code: int = 0) -> dict:
    rc, out, err = cli("precess", *args, "--json")
    assert rc == code, err
    return json.loads(out, parse_constant=lambda c: pytest.fail(f"JSON has {c}"))


def bad(cli, *args: str) -> str:
    """Exit status 2 with one line on standard error; returns that line."""
    rc, out, err = cli("precess", *args)
    assert rc == 2, (args, out, err)
    assert err.startswith("rbcli: ") and err.count("\n") == 1, err
    assert out == ""
    return err


def sheet(x: float, digits: int = 6) -> dict:
    """pytest.approx keywords for a number the sheet prints to ``digits`` significant
    figures: it is exact to half a unit in its last place."""
    return {"abs": 0.5 * 10.0 ** (math.floor(math.log10(abs(x))) - digits + 1), "rel": 0}


def dop853(J, w0, t_end):
    """Independent oracle: J w' = (J w) x w, R' = R [w]x, R(0) = 1, DOP853 rtol 1e-12."""
    from scipy.integrate import solve_ivp

    J = np.asarray(J, float)
    Jinv = np.linalg.inv(J)

    def rhs(_t, y):
        w, R = y[:3], y[3:].reshape(3, 3)
        W = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
        return np.concatenate([Jinv @ np.cross(J @ w, w), (R @ W).ravel()])

    sol = solve_ivp(rhs, (0, t_end), np.concatenate([w0, np.eye(3).ravel()]), method="DOP853",
                    rtol=1e-12, atol=1e-14)
    return sol.y[:3, -1], sol.y[3:, -1].reshape(3, 3)


def rot(q) -> np.ndarray:
    from scipy.spatial.transform import Rotation

    w, x, y, z = q
    return Rotation.from_quat([x, y, z, w]).as_matrix()  # scipy: scalar last


# round-off: the CLI's value passes through unit parsing, a tensor sum, an eigen-
# decomposition and a handful of closed-form operations, so 1e-12 relative agreement with
# the same closed form evaluated here is ample and still sharp
RT = 1e-12


# ----------------------------------------------------------------------------- P1 frisbee

def test_p1_frisbee_thin_disk_wobbles_twice_as_fast_as_it_spins(cli):
    w = [10 * math.sin(5 * DEG), 0.0, 10 * math.cos(5 * DEG)]  # |w| = 10 rad/s at 5° (P1)
    j = js(cli, str(EX / "frisbee.yaml"), "--omega", ",".join(repr(x) for x in w))
    m, R = 0.175, 0.135  # the file: a thin disk
    I, Is = m * R * R / 4, m * R * R / 2  # textbook thin disk: Is = 2 I
    assert j["symmetric"] is True and j["circles_axis"] == 3 and j["oblate"] is True
    # the sheet's P1 (I = 1, Is = 2): these depend on Is/I only
    assert j["precession_rate"] == pytest.approx(9.96195, **sheet(9.96195))
    assert j["space_precession_rate"] == pytest.approx(19.9429, **sheet(19.9429))
    assert j["body_cone_deg"] == pytest.approx(5.0, abs=1e-12)  # exactly the input angle
    assert j["space_cone_deg"] == pytest.approx(2.49523, **sheet(2.49523))
    assert j["nutation_deg"] == pytest.approx(2.50477, **sheet(2.50477))
    assert j["spin_rate"] == pytest.approx(-9.96195, **sheet(9.96195))
    assert j["wobble_to_spin"] == pytest.approx(2.00191, **sheet(2.00191))
    # |L| = 19.9429 kg m^2/s for I = 1 scales with I
    assert j["angular_momentum_norm"] / I == pytest.approx(19.9429, **sheet(19.9429))
    # closed forms of §1.1 here: W = w3 (Is/I - 1), phi' = |L|/I, period 2 pi/|W|
    assert j["precession_rate"] == pytest.approx(w[2] * (Is / I - 1), rel=RT)
    L = [I * w[0], I * w[1], Is * w[2]]
    np.testing.assert_allclose(j["angular_momentum"], L, rtol=RT, atol=1e-18)
    assert j["space_precession_rate"] == pytest.approx(math.hypot(*L) / I, rel=RT)
    assert j["period"] == pytest.approx(2 * math.pi / (w[2] * (Is / I - 1)), rel=RT)
    assert j["kinetic_energy"] == pytest.approx(0.5 * (I * w[0] ** 2 + Is * w[2] ** 2), rel=RT)
    assert j["flip_interval"] is None


def test_frisbee_header_numbers_print(cli):
    rc, out, _ = cli("precess", str(EX / "frisbee.yaml"), "--omega", "0.8715574275,0,9.961946981")
    assert rc == 0
    for s in ("9.96195", "2.00191", "2.49523", "19.9429"):  # the header's claims (sheet P1)
        assert s in out
    rc, out, _ = cli("precess", str(EX / "frisbee.yaml"), "--omega", "0,0,300 rpm")
    # steady spin at 300 rpm = 10 pi rad/s: a small wobble has W = w3, period 2 pi/w3 = 0.2 s
    assert rc == 0 and "| 0.2 | s" in " ".join(out.split()).replace("  ", " ")


# ----------------------------------------------------------------------------- P2 football

def test_p2_football_prolate_spheroid(cli):
    w = [10 * math.sin(10 * DEG), 0.0, 10 * math.cos(10 * DEG)]  # |w| = 10 at 10° (P2)
    j = js(cli, str(EX / "football.yaml"), "--omega", ",".join(repr(x) for x in w))
    assert j["symmetric"] is True and j["oblate"] is False
    assert j["circles_axis"] == 1  # prolate: the symmetry axis has the smallest moment
    assert j["precession_rate"] == pytest.approx(-4.92404, **sheet(4.92404))
    assert j["spin_rate"] == pytest.approx(4.92404, **sheet(4.92404))
    assert j["nutation_deg"] == pytest.approx(19.4254, **sheet(19.4254))
    assert j["space_cone_deg"] == pytest.approx(9.42540, **sheet(9.42540))
    assert j["body_cone_deg"] == pytest.approx(10.0, abs=1e-12)
    assert j["space_precession_rate"] == pytest.approx(5.22126, **sheet(5.22126))
    # the spheroid of the file: a = c/sqrt(3), I = m (a^2 + c^2)/5 = 2 Is: |L|/I = 10.4425/2
    m, c = 0.42, 0.14
    a = c / math.sqrt(3)
    I = m * (a * a + c * c) / 5
    assert j["angular_momentum_norm"] / I == pytest.approx(5.22126, **sheet(5.22126))
    assert j["principal_moments"] == pytest.approx([2 * m * a * a / 5, I, I], rel=1e-12)


def test_football_header_numbers_print(cli):
    rc, out, _ = cli("precess", str(EX / "football.yaml"), "--omega", "1.736481777,0,9.848077530")
    assert rc == 0
    for s in ("-4.92404", "5.22126", "19.4254", "9.4254", "| 10 |"):  # header claims (P2)
        assert s in " ".join(out.split())
    assert "largest moment (the major-axis rule" in " ".join(out.split())  # prolate: axis 1


# ----------------------------------------------------------------------------- P3 Earth

@pytest.mark.parametrize("tilt", [1e-6, 0.0])
def test_p3_earth_euler_period_and_the_chandler_note(cli, tilt):
    w3 = 2 * math.pi / 86164.0905  # one turn per sidereal day (P3)
    j = js(cli, str(EX / "earth.yaml"), "--omega", f"{tilt * w3!r},0,{w3!r}")
    # Is/I = 1.00327: T_Euler = T_rot I/(Is - I) = 2.63499e7 s = 304.975 d = 305.810 T_rot
    assert j["wobble_period"] == pytest.approx(2.63499e7, **sheet(2.63499e7))
    assert j["wobble_period"] / 86400 == pytest.approx(304.975, **sheet(304.975))
    assert j["wobble_period"] / 86164.0905 == pytest.approx(305.810, **sheet(305.810))
    if tilt:
        assert j["period"] == pytest.approx(j["wobble_period"], rel=RT)  # the period of w
        assert j["space_precession_period"] == pytest.approx(85883.3, **sheet(85883.3))
        assert j["circles_axis"] == 3 and j["stable"] is True
    else:  # steady spin: no period, but the wobble period is still reported
        assert j["period"] is None and j["case"] == "steady"
    note = " ".join(j["notes"])
    assert "433 d" in note and "not a rigid-body result" in note
    assert "304.975 d" in note


def test_earth_header_and_table_in_days_and_hours(cli):
    rc, out, _ = cli("precess", str(EX / "earth.yaml"), "--omega", "7.292115858e-11,0,7.292115858e-5")
    flat = " ".join(out.split())
    assert rc == 0 and "2.63499e+07" in flat and "304.975 d" in flat and "85883.3" in flat
    rc, out, _ = cli("precess", str(EX / "earth.yaml"), "--omega", "0,0,7.292115858e-5", "--units", "h")
    # --units h changes the time columns: T_rot I/(Is - I) = 86164.0905 s/0.00327 in hours
    # (7319.41 h), and the sheet's space nutation period 23.8565 h
    assert rc == 0 and f"{86164.0905 / 0.00327 / 3600:.6g} | h" in out and "23.8565 | h" in out


# ----------------------------------------------------------------------------- P4

def test_p4_asymmetric_circles_the_smallest_axis(cli):
    j = js(cli, "-e", I123, "--omega", "1,0.1,0.2", "--at", "5")
    assert j["symmetric"] is False and j["circles_axis"] == 1 and j["stable"] is True
    assert j["angular_momentum_norm"] ** 2 == pytest.approx(1.4, rel=RT)  # G^2 = 1.40000
    assert 2 * j["kinetic_energy"] == pytest.approx(1.14, rel=RT)  # 2T = 1.14000
    assert j["elliptic_parameter"] == pytest.approx(0.128713, **sheet(0.128713))
    assert j["elliptic_rate"] == pytest.approx(0.580230, **sheet(0.580230))
    assert j["period"] == pytest.approx(11.2050, **sheet(11.2050))
    # the sheet's verification table gives T_w to 12 figures (DOP853-checked closed form)
    assert j["period"] == pytest.approx(11.2049694088, abs=5e-11)
    assert j["precession_per_period"] == pytest.approx(5.62233784747, abs=5e-11)
    assert j["mean_precession_rate"] == pytest.approx(0.501772, **sheet(0.501772))
    assert j["precession_rate"] is None and j["body_cone_deg"] is None  # asymmetric: n/a
    w5 = j["at"]["omega"]
    for got, want in zip(w5, (1.00469, 0.0245230, -0.207685)):
        assert got == pytest.approx(want, **sheet(want))
    w10 = js(cli, "-e", I123, "--omega", "1,0.1,0.2", "--at", "10")["at"]["omega"]
    for got, want in zip(w10, (0.994363, -0.145750, 0.190400)):
        assert got == pytest.approx(want, **sheet(want))


def test_p4_after_one_period_the_body_has_turned_about_L(cli):
    """Sheet P4: R(T) R(0)^T = rotation about L^ by -0.660847 rad (convention-free)."""
    T = js(cli, "-e", I123, "--omega", "1,0.1,0.2")["period"]
    at = js(cli, "-e", I123, "--omega", "1,0.1,0.2", "--at", repr(T))["at"]
    L = np.array([1.0, 0.2, 0.6])
    Lhat = L / np.linalg.norm(L)
    # w after a whole period is w0 again (the period of the elliptic functions)
    np.testing.assert_allclose(at["omega"], [1, 0.1, 0.2], atol=1e-13)  # round-off of ~100 ops
    # canonical quaternion (w >= 0): angle +0.660847 about -L^
    assert math.radians(at["rotation_angle_deg"]) == pytest.approx(0.660847, **sheet(0.660847))
    np.testing.assert_allclose(at["rotation_axis"], -Lhat, atol=1e-12)
    assert at["periods"] == pytest.approx(1.0, rel=RT)


# ----------------------------------------------------------------------------- P6 book

def test_p6_tennis_racket_flips(cli):
    j = js(cli, str(EX / "book.yaml"), "--omega", "0.01,1,0.01")
    assert j["circles_axis"] == 3 and j["symmetric"] is False
    assert j["elliptic_complement"] == pytest.approx(1.99940e-4, **sheet(1.99940e-4))
    assert j["period"] == pytest.approx(39.1057, **sheet(39.1057))
    assert j["flip_interval"] == pytest.approx(19.5529, **sheet(19.5529))
    assert j["first_flip"] == pytest.approx(10.9169, **sheet(10.9169))
    # the sheet's DOP853 zero crossings of w2: 10.9169134942, 30.4697805929 (rtol 1e-12,
    # amplified ~1/k' = 70 times near the separatrix: 1e-9 relative is the oracle's own size)
    assert j["first_flip"] == pytest.approx(10.9169134942, rel=1e-9)
    assert j["first_flip"] + j["flip_interval"] == pytest.approx(30.4697805929, rel=1e-9)
    # the asymptotic estimate (2/sigma) ln(4/k'): the sheet's 19.5545 is good to 1e-4 only
    assert j["flip_interval_estimate"] == pytest.approx(19.5545, rel=1e-4)
    note = " ".join(j["notes"])
    assert "flips over every" in note and "Dzhanibekov" in note


def test_book_header_numbers_and_scaling(cli):
    rc, out, _ = cli("precess", str(EX / "book.yaml"), "--omega", "0.01,1,0.01")
    assert rc == 0 and "19.5529" in out and "10.9169" in out and "39.1057" in out
    # Euler's equations are homogeneous: w -> 10 w gives the same motion 10 times faster
    j = js(cli, str(EX / "book.yaml"), "--omega", "0.1,10,0.1")
    assert j["flip_interval"] == pytest.approx(1.95529, **sheet(1.95529))
    assert j["first_flip"] == pytest.approx(1.09169, **sheet(1.09169))
    rc, out, _ = cli("precess", str(EX / "book.yaml"), "--omega", "1,0.1,0.2")
    assert rc == 0 and "11.205 " in out  # P4 with the book's 1:2:3 moments: 11.2050 s


# ----------------------------------------------------------------------------- P8 separatrix

def test_p8_separatrix_said_plainly(cli):
    j = js(cli, "-e", I123, "--omega", f"{0.1 * math.sqrt(3)!r},1,0.1", "--at", "5")
    assert j["case"] == "separatrix"
    assert j["period"] is None and j["circles_axis"] is None and j["flip_interval"] is None
    for got, want in zip(j["at"]["omega"], (0.00931928, 1.01485, 0.00538049)):
        assert got == pytest.approx(want, **sheet(want))
    assert j["elliptic_rate"] == pytest.approx(0.585947, **sheet(0.585947))
    assert "no period" in " ".join(j["notes"])
    rc, out, _ = cli("precess", "-e", I123, "--omega", f"{0.1 * math.sqrt(3)!r},1,0.1")
    flat = " ".join(out.split())
    assert "separatrix" in flat and "no period" in flat
    # the one flip: tau0 = 2.45384, lambda = 0.585947 -> t = -tau0/lambda, before t = 0
    import re

    t_flip = float(re.search(r"the one flip \(ω2 changes sign\) at \| (\S+) \| s", flat).group(1))
    # two 6-figure sheet numbers divided: good to ~1e-5 relative
    assert t_flip == pytest.approx(-2.45384 / 0.585947, rel=2e-5)
    assert "1.01489" in flat  # Omega0 = |L|/I2


# ----------------------------------------------------------------------------- keys, --at

BODIES = {
    "asymmetric": (I123, "1,0.1,0.2"),
    "near intermediate": (I123, "0.01,1,0.01"),
    "separatrix": (I123, f"{0.1 * math.sqrt(3)!r},1,0.1"),
    "steady intermediate": (I123, "0,1,0"),
    "oblate": ("{shape: disk, mass: 1, radius: 1}", "1,0,5"),
    "prolate": ("{shape: cylinder, mass: 1, radius: 0.1, length: 1}", "0.5,0.1,3"),
    "spherical": ("{shape: sphere, mass: 1, radius: 1}", "1,2,3"),
    "rest": (I123, "0,0,0"),
    "rotated box": ("{shape: box, mass: 2, size: [0.1, 0.2, 0.3], rotate: {axis: [1, 1, 1], angle: 30}}", "1,2,3"),
}


@pytest.mark.parametrize("name", BODIES)
def test_spec_keys_always_present_and_deterministic(cli, name):
    expr, omega = BODIES[name]
    rc, out1, _ = cli("precess", "-e", expr, "--omega", omega, "--json", "--at", "2.5")
    rc2, out2, _ = cli("precess", "-e", expr, "--omega", omega, "--json", "--at", "2.5")
    assert rc == rc2 == 0 and out1 == out2  # same bytes
    j = json.loads(out1, parse_constant=lambda c: pytest.fail(f"JSON has {c}"))
    assert list(j)[: len(SPEC_KEYS)] == list(SPEC_KEYS)  # SPEC keys, first, in order
    assert len(j["angular_momentum"]) == 3 and isinstance(j["symmetric"], bool)
    assert j["circles_axis"] in (1, 3, None)
    assert set(j["at"]) >= {"t", "omega", "angular_momentum", "quaternion", "rotation_axis", "rotation_angle_deg"}
    assert abs(np.linalg.norm(j["at"]["quaternion"]) - 1) < 1e-15 * 4  # unit to a few ulp
    if j["symmetric"]:
        for k in ("precession_rate", "space_precession_rate", "body_cone_deg", "space_cone_deg"):
            assert isinstance(j[k], float), k
    rc, table, _ = cli("precess", "-e", expr, "--omega", omega, "--at", "2.5")
    assert rc == 0 and "nan" not in table.lower()


def test_at_1_s_against_an_independent_integration(cli):
    J = np.diag([1.0, 2.0, 3.0])
    w0 = np.array([1.0, 0.1, 0.2])
    at = js(cli, "-e", I123, "--omega", "1,0.1,0.2", "--at", "1")["at"]
    w_ref, R_ref = dop853(J, w0, 1.0)
    # DOP853 at rtol 1e-12 over 1 s: its own error is ~1e-13; 1e-11 leaves room
    np.testing.assert_allclose(at["omega"], w_ref, atol=1e-11)
    np.testing.assert_allclose(rot(at["quaternion"]), R_ref, atol=1e-11)
    np.testing.assert_allclose(at["rotation_matrix"], R_ref, atol=1e-11)
    np.testing.assert_allclose(at["angular_momentum"], J @ w_ref, atol=1e-11)


def test_at_1e9_s_periodic_and_invariant(cli):
    """t = 1e9 s is 8.9e7 periods away: w repeats with the period, the invariants hold."""
    j = js(cli, "-e", I123, "--omega", "1,0.1,0.2", "--at", "1e9")
    at, T = j["at"], j["period"]
    r = math.fmod(1e9, T)  # exact remainder of the two doubles
    near = js(cli, "-e", I123, "--omega", "1,0.1,0.2", "--at", repr(r))["at"]
    # T carries ~1 ulp (2e-15 s) of error, times 8.9e7 periods: ~2e-7 s of phase, and
    # |dw/dt| < 1 rad/s^2 here, so 1e-6 is the size of the disagreement allowed
    np.testing.assert_allclose(at["omega"], near["omega"], atol=1e-6)
    J = np.diag([1.0, 2.0, 3.0])
    w, L0 = np.array(at["omega"]), np.array([1.0, 0.2, 0.6])
    M = J @ w
    # invariants along the exact solution: round-off only, at any t
    assert 0.5 * w @ M == pytest.approx(0.57, rel=1e-13)
    assert np.linalg.norm(M) == pytest.approx(math.sqrt(1.4), rel=1e-13)
    np.testing.assert_allclose(rot(at["quaternion"]) @ M, L0, atol=1e-13)  # L fixed in space
    assert at["periods"] == pytest.approx(1e9 / T, rel=RT)


def test_at_takes_time_units_and_negative_times(cli):
    a = js(cli, "-e", I123, "--omega", "1,0.1,0.2", "--at", "2 min")["at"]
    b = js(cli, "-e", I123, "--omega", "1,0.1,0.2", "--at", "120")["at"]
    assert a == b  # 2 min = 120 s exactly
    back = js(cli, "-e", I123, "--omega", "1,0.1,0.2", "--at", "-3")["at"]
    w_ref, R_ref = dop853(np.diag([1.0, 2.0, 3.0]), np.array([1.0, 0.1, 0.2]), -3.0)
    np.testing.assert_allclose(back["omega"], w_ref, atol=1e-11)  # DOP853 backwards, as above
    np.testing.assert_allclose(rot(back["quaternion"]), R_ref, atol=1e-11)


@settings(max_examples=30, deadline=None)
@given(
    a=st.floats(0.2, 5.0), b=st.floats(0.2, 5.0), c=st.floats(0.2, 5.0),
    w=st.lists(st.floats(-3.0, 3.0), min_size=3, max_size=3).filter(lambda v: np.linalg.norm(v) > 0.05),
    t=st.floats(-1e6, 1e6),
)
def test_invariants_at_any_time_for_any_body(a, b, c, w, t):
    """A box of any sides, any w, any t: T, |L| and L in space are those at t = 0."""
    from conftest import run_inprocess  # hypothesis: no function-scoped fixture

    expr = f"{{shape: box, mass: 1.5, size: [{a!r}, {b!r}, {c!r}]}}"
    r = run_inprocess("precess", "-e", expr, "--omega", ",".join(repr(x) for x in w), "--at", repr(t), "--json")
    assert r.code == 0, r.err
    j = r.json()
    J = 1.5 / 12 * np.diag([b * b + c * c, a * a + c * c, a * a + b * b])  # textbook box
    w0 = np.array(w)
    L0 = J @ w0
    wt = np.array(j["at"]["omega"])
    Mt = J @ wt
    # round-off of the closed forms grows with the phase (|t| |w| up to ~1e7 rad: t itself is
    # known to eps |t|), so the invariants are checked to 1e-10 relative
    assert 0.5 * wt @ Mt == pytest.approx(0.5 * w0 @ L0, rel=1e-10)
    assert np.linalg.norm(Mt) == pytest.approx(np.linalg.norm(L0), rel=1e-10)
    np.testing.assert_allclose(rot(j["at"]["quaternion"]) @ Mt, L0, atol=1e-10 * np.linalg.norm(L0))
    # L at t = 0: round-off of J w (1e-14 of |L|), plus the components of w that core sets to 0
    # as projection round-off (|w_i| <= SNAP_RTOL |w|, so up to SNAP_RTOL max(J) |w| of L_i)
    from rbcli.core.freemotion import SNAP_RTOL

    snap = SNAP_RTOL * float(np.max(J)) * float(np.linalg.norm(w0))
    np.testing.assert_allclose(j["angular_momentum"], L0, rtol=1e-12, atol=1e-14 * np.linalg.norm(L0) + snap)


# ----------------------------------------------------------------------------- CSV

def test_csv_time_series(cli, tmp_path):
    out = tmp_path / "p4.csv"
    rc, text, _ = cli("precess", "-e", I123, "--omega", "1,0.1,0.2", "--duration", "112.05",
                      "--samples", "2001", "--csv", str(out))
    assert rc == 0 and str(out) in text
    lines = out.read_text().splitlines()
    assert lines[0] == "t,wx,wy,wz,Lx,Ly,Lz,qw,qx,qy,qz"
    assert len(lines) == 2002
    L0 = (np.diag([1.0, 2.0, 3.0]) @ [1.0, 0.1, 0.2]).tolist()  # J w0 in doubles (3 x 0.2 != 0.6)
    assert lines[1] == ",".join(map(repr, [0.0, 1.0, 0.1, 0.2, *L0, 1.0, 0.0, 0.0, 0.0]))  # w0, L0, identity
    a = np.loadtxt(out, delimiter=",", skiprows=1)
    np.testing.assert_array_equal(a[:, 0], np.linspace(0, 112.05, 2001))
    J = np.diag([1.0, 2.0, 3.0])
    np.testing.assert_allclose(a[:, 4:7], a[:, 1:4] @ J, rtol=1e-15, atol=0)  # L = J w, body
    G = np.linalg.norm(a[:, 4:7], axis=1)
    # |L| constant down the column: round-off of each row (~1e-16), 1e-12 as asked
    assert np.max(np.abs(G - math.sqrt(1.4))) / math.sqrt(1.4) < 1e-12
    T = 0.5 * np.einsum("ij,ij->i", a[:, 1:4], a[:, 4:7])
    assert np.max(np.abs(T - 0.57)) / 0.57 < 1e-12
    q = a[:, 7:]
    np.testing.assert_allclose(np.linalg.norm(q, axis=1), 1.0, atol=1e-15)
    assert np.min(np.einsum("ij,ij->i", q[1:], q[:-1])) > 0  # continuous sign along the series
    Ls = np.einsum("nij,nj->ni", np.array([rot(x) for x in q]), a[:, 4:7])
    np.testing.assert_allclose(Ls, np.tile([1.0, 0.2, 0.6], (len(a), 1)), atol=1e-12)  # fixed in space
    # every number read back is the number written: repr round-trips exactly
    assert lines[5].split(",") == [repr(float(x)) for x in a[4]]
    # w after 10 periods: w0 again (the sheet's period 11.2050 s: 112.05 s = 10.0000 periods)
    np.testing.assert_allclose(a[-1, 1:4], [1, 0.1, 0.2], atol=2e-4)  # 1e-5 relative in time


def test_csv_to_stdout_and_deterministic(cli, tmp_path):
    rc, out1, _ = cli("precess", "-e", I123, "--omega", "0.01,1,0.01", "--duration", "20", "--samples", "5", "--csv", "-")
    rc2, out2, _ = cli("precess", "-e", I123, "--omega", "0.01,1,0.01", "--duration", "20", "--samples", "5", "--csv", "-")
    assert rc == rc2 == 0 and out1 == out2
    lines = out1.splitlines()
    assert lines[0].startswith("t,wx") and len(lines) == 6
    assert [float(x.split(",")[0]) for x in lines[1:]] == [0.0, 5.0, 10.0, 15.0, 20.0]
    # default rows
    f = tmp_path / "d.csv"
    assert cli("precess", "-e", I123, "--omega", "1,0,0", "--duration", "1", "--csv", str(f)).code == 0
    assert len(f.read_text().splitlines()) == 1 + 1001


def test_csv_replaces_an_existing_file_but_never_an_input(cli, tmp_path):
    body = tmp_path / "b.yaml"
    body.write_text((EX / "book.yaml").read_text())
    before = body.read_bytes()
    err = bad(cli, str(body), "--omega", "1,0,0", "--duration", "1", "--csv", str(body))
    assert "input" in err and body.read_bytes() == before
    old = tmp_path / "old.csv"
    old.write_text("something else\n")
    assert cli("precess", str(body), "--omega", "1,0,0", "--duration", "1", "--samples", "3", "--csv", str(old)).code == 0
    assert old.read_text().startswith("t,wx,wy,wz")
    err = bad(cli, str(body), "--omega", "1,0,0", "--duration", "1", "--csv", str(tmp_path / "no" / "x.csv"))
    assert "does not exist" in err


# ----------------------------------------------------------------------------- --verify

def test_verify(cli):
    j = js(cli, str(EX / "book.yaml"), "--omega", "1,0.1,0.2", "--verify")
    v = j["verify"]
    assert v["ok"] is True and v["rtol"] == 1e-12
    assert v["t_end"] == pytest.approx(3 * j["period"], rel=RT)  # 3 periods
    assert v["omega_error"] < 1e-9 and v["attitude_error"] < 1e-9  # DOP853 at 1e-12 over 3 periods
    for k in ("exact_energy_drift", "exact_momentum_drift", "exact_L_drift"):
        assert v[k] < 1e-13, k  # along the exact solution: round-off only
    rc, out, _ = cli("precess", str(EX / "book.yaml"), "--omega", "1,0.1,0.2", "--verify")
    assert rc == 0 and "agree" in out and "|Δω|/|ω|" in out


def test_verify_failure_exits_1_after_printing_everything(cli, monkeypatch):
    from dataclasses import replace

    from rbcli.core import freeverify

    real = freeverify.verify
    monkeypatch.setattr(freeverify, "verify", lambda motion: replace(real(motion, periods=0.5), ok=False, omega_error=1.0))
    j = js(cli, "-e", I123, "--omega", "1,0.1,0.2", "--verify", code=1)
    assert j["verify"]["ok"] is False and "period" in j
    rc, out, _ = cli("precess", "-e", I123, "--omega", "1,0.1,0.2", "--verify")
    assert rc == 1 and "DISAGREE" in out and "principal moments" in out


# ----------------------------------------------------------------------------- plots

# one format by default here (svg; top draws png, rollcheck pdf), all three under -m slow
@pytest.mark.parametrize("ext, magic", sampled_params([("png", b"\x89PNG"), ("svg", b"<?xml"), ("pdf", b"%PDF")], [1], multi=True, ids=["png", "svg", "pdf"]))
def test_plot_formats(cli, tmp_path, ext, magic):
    f = tmp_path / f"p.{ext}"
    rc, out, _ = cli("precess", str(EX / "book.yaml"), "--omega", "0.01,1,0.01", "--plot", str(f))
    assert rc == 0 and f.read_bytes().startswith(magic) and f"plot written to {f}" in out
    if ext == "svg":
        text = f.read_text()
        assert "Notebook" in text or "precess" in text  # titled (fonts as paths: check the id)


@pytest.mark.parametrize("expr, w", sampled_params(
    [("{shape: disk, mass: 1, radius: 1}", "0.1,0,5"), (I123, f"{0.1 * math.sqrt(3)!r},1,0.1"),
     (I123, "0,0,0"), ("{shape: sphere, mass: 1, radius: 1}", "0,1,0")],
    [1, 2], multi=True, ids=["symmetric", "separatrix", "rest", "sphere"]))
def test_plot_symmetric_separatrix_and_rest(cli, tmp_path, expr, w):
    f = tmp_path / "s.png"
    assert cli("precess", "-e", expr, "--omega", w, "--plot", str(f), "--duration", "3").code == 0
    assert f.stat().st_size > 1000


def test_plot_unknown_extension_and_input(cli, tmp_path):
    err = bad(cli, str(EX / "book.yaml"), "--omega", "1,0,0", "--plot", str(tmp_path / "p.jpg"))
    assert ".png" in err and ".svg" in err and ".pdf" in err
    body = tmp_path / "b.yaml"
    body.write_text((EX / "book.yaml").read_text())
    before = body.read_bytes()
    bad(cli, str(body), "--omega", "1,0,0", "--plot", str(body))  # .yaml: not a plot format
    assert body.read_bytes() == before


# ----------------------------------------------------------------------------- bad options

@pytest.mark.parametrize("args, words", [
    ([], "--omega"),
    (["--omega", "1,2"], "expected 3"),
    (["--omega", "1,0,5 m"], "--omega"),
    (["--omega", "1,0,nan"], "finite"),
    (["--omega", "1e200,1e200,1e200"], "too large"),
    (["--omega", "1e-300,0,0"], "too small"),
    (["--omega", "1,0,0", "--samples", "10"], "--csv"),
    (["--omega", "1,0,0", "--samples", "-5", "--csv", "-", "--duration", "1"], "--samples"),
    (["--omega", "1,0,0", "--samples", "abc", "--csv", "-", "--duration", "1"], "whole number"),
    (["--omega", "1,0,0", "--samples", "1", "--csv", "-", "--duration", "1"], "from 2"),
    (["--omega", "1,0,0", "--csv", "out.csv"], "--duration"),
    (["--omega", "1,0,0", "--duration", "-1", "--csv", "-"], "positive"),
    (["--omega", "1,0,0", "--duration", "5"], "--csv or --plot"),
    (["--omega", "1,0,0", "--at", "5 kg"], "--at"),
    (["--omega", "1,0,0", "--at", "1e300"], "double-precision"),
    (["--omega", "1,0,0", "--csv", "-", "--duration", "1", "--json"], "--json"),
])
def test_bad_options_exit_2_with_one_line(cli, args, words):
    err = bad(cli, "-e", I123, *args)
    assert words in err


def test_body_problems_exit_2(cli):
    err = bad(cli, "-e", "{shape: point, mass: 1}", "--omega", "1,0,0")
    assert "positive definite" in err
    bad(cli, str(EX / "no_such_body.yaml"), "--omega", "1,0,0")
    bad(cli, "--omega", "1,0,0")  # no body


def test_exit_codes_in_a_real_process(tmp_path, cli_proc):
    r = cli_proc("precess", "examples/book.yaml", "--omega", "0.01,1,0.01", "--json")
    assert r.code == 0 and r.json()["flip_interval"] == pytest.approx(19.5529, **sheet(19.5529))
    r = cli_proc("precess", "examples/book.yaml")
    assert r.code == 2 and r.err.startswith("rbcli: --omega") and r.err.count("\n") == 1
    r = cli_proc("precess", "examples/book.yaml", "--omega", "1,0,0", "--plot", str(tmp_path / "x.gif"))
    assert r.code == 2 and "Traceback" not in r.err and r.err.count("\n") == 1


# ----------------------------------------------------------------------------- flips (issue 13.6)

@pytest.mark.parametrize("omega, axis", [("0.1,0.1,1", 3), ("1,0.1,0.1", 1), ("0.3,0.5,1", 3)])
def test_no_flip_near_the_largest_or_smallest_axis(cli, omega, axis):
    """w2 changes sign, but L never comes nearer to the intermediate axis than to axis 1 or 3:
    a wobble, not a flip. flip_interval, first_flip and the estimate are null."""
    j = js(cli, str(EX / "book.yaml"), "--omega", omega)
    assert j["circles_axis"] == axis and j["period"] is not None
    assert j["flip_interval"] is None and j["first_flip"] is None and j["flip_interval_estimate"] is None
    assert f"no flip: stable about axis {axis}" in j["description"]
    rc, out, _ = cli("precess", str(EX / "book.yaml"), "--omega", omega)
    assert rc == 0 and f"no flip: stable about axis {axis}" in out and "flip interval" not in out


@pytest.mark.parametrize("omega", ["0.01,1,0.01", "0.3,1,0.2", "0.5,1,0.5"])
def test_flips_when_L_passes_nearest_the_intermediate_axis(cli, omega):
    """The flip criterion: at the extremes of w2 (sn = +-1) |M2| exceeds the other components,
    checked here on the time series itself (M = J w over one period)."""
    j = js(cli, str(EX / "book.yaml"), "--omega", omega)
    assert j["flip_interval"] == pytest.approx(j["period"] / 2, rel=1e-12)
    import rbcli

    r = rbcli.precess(rbcli.load(EX / "book.yaml"), omega=omega)
    M = r.at(np.linspace(0.0, r.motion.period, 2001)).angular_momentum
    nearest = np.argmax(np.abs(M), axis=1)
    assert np.any(nearest == 1)  # L passes nearest the intermediate axis...
    assert np.any(M[nearest == 1, 1] > 0) and np.any(M[nearest == 1, 1] < 0)  # ...on both sides


def test_flip_criterion_is_geometric():
    """Without a flip L stays nearer to axis 1 or 3 than to axis 2 all along."""
    import rbcli

    r = rbcli.precess(rbcli.load(EX / "book.yaml"), omega="0.3,0.5,1")
    assert r.motion.flip_interval is None
    M = r.at(np.linspace(0.0, r.motion.period, 2001)).angular_momentum
    assert not np.any(np.argmax(np.abs(M), axis=1) == 1)


# ----------------------------------------------------------------------------- start-up (issue 16)

@pytest.mark.parametrize("extra, loads_scipy", sampled_params(
    [((), False), (("--at", "1e9", "--json"), False), (("--verify",), True)], [0, 2], multi=True,
    ids=["default", "at", "verify"]))
def test_default_path_does_not_import_scipy(cli_proc, extra, loads_scipy):
    """scipy (its import costs more than a whole one-liner) is loaded only by --verify."""
    r = cli_proc("precess", "examples/book.yaml", "--omega", "0.01,1,0.01", *extra, imports=True)
    assert r.code == 0, r.err
    assert ("scipy" in r.imported) == loads_scipy
