"""Tests of rbcli.core.freemotion — exact torque-free motion (physics sheet dynamics.md §1, §6).

Expected numbers come from the physics sheet (P1–P9 and the §1.2 table, quoted to 6
significant figures unless more are printed there), from closed forms written out here
independently of the module, and from independent oracles: scipy.integrate.solve_ivp
(DOP853, tight tolerances), scipy.special.ellipj (where it is accurate),
scipy.spatial.transform.Rotation and Jacobi-function identities.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import sample
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp
from scipy.spatial.transform import Rotation

from rbcli.core import freemotion as fm
from rbcli.core.elliptic import jacobi_reduced
from rbcli.core.freepath import attitude_at, omega_at
from rbcli.core.freeverify import verify
from rbcli.core.rotation import quat_to_matrix
from rbcli.core.freemotion import (
    CASE_MAX,
    CASE_MIN,
    CASE_REST,
    CASE_SEPARATRIX,
    CASE_SPHERICAL,
    CASE_STEADY,
    analyse,

)

I123 = np.diag([1.0, 2.0, 3.0])
# The sheet quotes 6 significant figures; rounding to 6 s.f. leaves up to half a unit in the
# 6th digit, i.e. up to 5e-6 relative for a number like 1.00000 (19.9429 vs 19.942948 is 2.4e-6).
SIX_SF = 5e-6


def rel(a: float, b: float) -> float:
    return abs(a - b) / abs(b)


def rotation_of(q: np.ndarray) -> Rotation:
    return Rotation.from_quat(np.atleast_2d(q), scalar_first=True)


def integrate_body(J: np.ndarray, w0: np.ndarray, ts: np.ndarray, rtol: float = 1e-12):
    """Independent oracle: Euler's equations J w' = (J w) x w and R' = R [w]x in the body frame."""
    Jinv = np.linalg.inv(J)

    def rhs(_t, y):
        w = y[:3]
        R = y[3:].reshape(3, 3)
        W = np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])
        return np.concatenate([Jinv @ np.cross(J @ w, w), (R @ W).ravel()])

    scale = np.linalg.norm(w0)
    atol = np.concatenate([np.full(3, 1e-2 * rtol * scale), np.full(9, 1e-2 * rtol)])
    sol = solve_ivp(rhs, (ts[0], ts[-1]), np.concatenate([w0, np.eye(3).ravel()]),
                    method="DOP853", rtol=rtol, atol=atol, t_eval=ts)
    assert sol.success
    return sol.y[:3].T, sol.y[3:].T.reshape(-1, 3, 3)


def random_rotation(seed: int) -> np.ndarray:
    return Rotation.random(random_state=seed).as_matrix()


# ---------------------------------------------------------------------------------------
# symmetric bodies: P1, P2, P3
# ---------------------------------------------------------------------------------------


def test_p1_frisbee():
    a = math.radians(5.0)
    w = 10.0 * np.array([math.sin(a), 0.0, math.cos(a)])
    m = analyse(np.diag([1.0, 1.0, 2.0]), w)
    assert m.symmetric and m.symmetry == "symmetric" and m.oblate
    assert m.case == CASE_MAX and m.circles_axis == 3 and m.stable is True
    # sheet P1, 6 significant figures
    assert rel(m.spin, 9.96195) < SIX_SF
    assert rel(m.precession_rate, 9.96195) < SIX_SF
    assert rel(math.degrees(m.nutation), 2.50477) < SIX_SF
    assert rel(math.degrees(m.space_cone), 2.49523) < SIX_SF
    assert rel(math.degrees(m.body_cone), 5.0) < 1e-12  # input angle, round-off only
    assert rel(m.angular_momentum_norm, 19.9429) < SIX_SF
    assert rel(m.space_precession_rate, 19.9429) < SIX_SF
    # the sheet's "seed" form w sqrt(1 + (Is^2/I^2 - 1) cos^2 alpha) equals |L|/I (round-off)
    seed = 10.0 * math.sqrt(1.0 + 3.0 * math.cos(a) ** 2)
    assert rel(m.space_precession_rate, seed) < 1e-14
    assert rel(m.spin_rate, -9.96195) < SIX_SF
    assert rel(m.wobble_to_spin, 2.00191) < SIX_SF
    assert rel(m.period, 2 * math.pi / 9.961946980917455) < 1e-12  # 2 pi/|W|, round-off
    j = m.to_json()
    assert rel(j["body_cone_deg"], 5.0) < 1e-12
    assert rel(j["space_cone_deg"], 2.49523) < SIX_SF
    assert j["symmetric"] is True and j["circles_axis"] == 3


def test_p2_prolate():
    a = math.radians(10.0)
    w = 10.0 * np.array([math.sin(a), 0.0, math.cos(a)])
    m = analyse(np.diag([2.0, 2.0, 1.0]), w)
    # the symmetry axis (moment 1) is the SMALLEST principal axis: circles axis 1
    assert m.symmetry == "symmetric" and m.oblate is False
    assert m.case == CASE_MIN and m.circles_axis == 1
    assert np.allclose(np.abs(m.symmetry_axis), [0, 0, 1], atol=0)  # body z, exactly
    assert rel(m.spin, 9.84808) < SIX_SF
    assert rel(m.precession_rate, -4.92404) < SIX_SF
    assert rel(math.degrees(m.nutation), 19.4254) < SIX_SF
    assert rel(math.degrees(m.space_cone), 9.42540) < SIX_SF
    assert rel(m.angular_momentum_norm, 10.4425) < SIX_SF
    assert rel(m.space_precession_rate, 5.22126) < SIX_SF
    assert rel(m.spin_rate, 4.92404) < SIX_SF
    assert m.nutation > m.body_cone  # prolate: theta > alpha (sheet §1.1)


@pytest.mark.parametrize("tilt", [0.0, 1e-6])
def test_p3_earth_rigid_euler_period(tilt):
    Trot = 86164.0905
    w3 = 2 * math.pi / Trot
    m = analyse(np.diag([1.0, 1.0, 1.00327]), [w3 * tilt, 0.0, w3])
    # sheet P3 (6 s.f.): body-frame wobble period 2.63499e7 s = 304.975 d = 305.810 T_rot;
    # with a 1e-6 rad tilt omega3 = w cos(1e-6) changes it by 5e-13 only
    assert rel(m.wobble_period, 2.63499e7) < SIX_SF
    assert rel(m.wobble_period / 86400.0, 304.975) < SIX_SF
    assert rel(m.wobble_period / Trot, 305.810) < SIX_SF
    assert rel(m.space_precession_period, 85883.3) < SIX_SF
    assert rel(m.space_precession_period / 3600.0, 23.8565) < SIX_SF
    if tilt == 0.0:
        assert m.case == CASE_STEADY and m.period is None and m.circles_axis == 3
        assert m.to_json()["period"] is None
    else:
        assert m.case == CASE_MAX and rel(m.period, 2.63499e7) < SIX_SF


# ---------------------------------------------------------------------------------------
# asymmetric bodies: P4, P6, P8 and the §1.2 table
# ---------------------------------------------------------------------------------------


def test_p4_case_1():
    w0 = np.array([1.0, 0.1, 0.2])
    m = analyse(I123, w0)
    e = m.elliptic
    assert rel(m.angular_momentum_norm**2, 1.4) < 1e-14  # G^2 = 1.40000 exactly, round-off
    assert rel(2 * m.kinetic_energy, 1.14) < 1e-14
    assert m.case == CASE_MIN and e.kind == "1" and m.circles_axis == 1
    assert rel(e.m, 0.128713) < SIX_SF
    assert rel(e.lam, 0.580230) < SIX_SF
    assert rel(e.K, 1.62536) < SIX_SF
    assert rel(m.period, 11.2050) < SIX_SF
    # §1.2 table quotes 12 digits for T_w, lambda and Delta phi (rel 1e-10 allows the last)
    assert rel(m.period, 11.2049694088) < 1e-10
    assert rel(e.lam, 0.580229840) < 1e-8
    assert rel(e.m, 0.128712871) < 1e-8
    assert rel(m.precession_per_period, 5.62233784747) < 1e-10
    assert rel(m.mean_precession_rate, 0.501772) < SIX_SF
    w = omega_at(m, [5.0, 10.0])
    np.testing.assert_allclose(w[0], [1.00469, 0.0245230, -0.207685], rtol=SIX_SF)
    np.testing.assert_allclose(w[1], [0.994363, -0.145750, 0.190400], rtol=SIX_SF)


def test_p4_montgomery_convention_free():
    """R(T) R(0)^T is a rotation about L^ by -0.660847 rad (sheet P4), from scipy Rotation."""
    m = analyse(I123, [1.0, 0.1, 0.2])
    q0, qT = attitude_at(m, [0.0, m.period])
    np.testing.assert_allclose(q0, [1, 0, 0, 0], atol=1e-15)  # R(0) = 1 to round-off
    rv = (rotation_of(qT) * rotation_of(q0).inv()).as_rotvec()[0]
    Lhat = m.angular_momentum / m.angular_momentum_norm
    angle = float(rv @ Lhat)
    # sheet: -0.66084745971 from DOP853 (rtol 1e-12 over one period): rel 1e-9
    assert rel(angle, -0.66084745971) < 1e-9
    assert np.linalg.norm(rv - angle * Lhat) < 1e-12  # axis is L^ to round-off
    # and it equals Delta phi (mod 2 pi) of the Pi formula
    assert abs(math.remainder(m.precession_per_period, 2 * math.pi) - angle) < 1e-12


def test_case_3_montgomery_and_table_row():
    m = analyse(I123, [0.2, 0.1, 1.0])
    e = m.elliptic
    assert m.case == CASE_MAX and e.kind == "3" and m.circles_axis == 3
    # §1.2 table (12 digits quoted)
    assert rel(e.m, 0.0166112957) < 1e-8
    assert rel(e.lam, 1.00166528) < 1e-8
    assert rel(m.period, 6.29903526898) < 1e-10
    assert rel(m.precession_per_period, 12.6451155333) < 1e-10
    q = attitude_at(m, [m.period])
    rv = rotation_of(q).as_rotvec()[0]
    Lhat = m.angular_momentum / m.angular_momentum_norm
    assert abs(math.remainder(m.precession_per_period, 2 * math.pi) - rv @ Lhat) < 1e-11
    assert np.linalg.norm(rv - (rv @ Lhat) * Lhat) < 1e-12


def test_p6_tennis_racket():
    m = analyse(I123, [0.01, 1.0, 0.01])
    e = m.elliptic
    assert m.case == CASE_MAX and m.circles_axis == 3
    assert rel(e.mc, 1.99940e-4) < SIX_SF
    assert rel(m.period, 39.1057) < SIX_SF
    assert rel(m.period, 39.1057341973) < 1e-10  # §1.2 table, 12 digits
    assert rel(m.precession_per_period, 43.2985213636) < 1e-10
    assert rel(m.flip_interval, 19.5529) < SIX_SF
    assert rel(m.first_flip, 10.9169) < SIX_SF
    # DOP853 zero crossings quoted by the sheet to 12 digits (rtol 1e-12 amplified ~1/k' = 70
    # near the intermediate axis): rel 1e-9
    assert rel(m.first_flip, 10.9169134942) < 1e-9
    assert rel(m.first_flip + m.flip_interval, 30.4697805929) < 1e-9
    # sigma per unit spin (sheet: 0.577350 at Omega = 1)
    assert rel(m.linear_coefficients[1], 0.577350) < SIX_SF
    assert m.linear_kinds == ("oscillation", "growth", "oscillation")
    # asymptotic estimate: the sheet gets 19.5545 with Omega = w2(0) = 1 and the small-eps
    # k'; we use the invariant Omega0 = G/I2 and the exact k' (19.5526, closer to the exact
    # 19.5529). Both are within the formula's own O(k'^2 ln k') error: rel 2e-4.
    assert rel(m.flip_interval_estimate, 19.5545) < 2e-4
    assert abs(m.flip_interval_estimate - m.flip_interval) < abs(19.5545 - m.flip_interval)
    assert m.to_json()["flip_interval"] == pytest.approx(19.5529, rel=SIX_SF)


def test_p6_flips_are_sign_changes_of_w2():
    """first_flip and flip_interval against the zero crossings of the exact w2 itself."""
    from scipy.optimize import brentq

    m = analyse(I123, [0.01, 1.0, 0.01])
    f = lambda t: omega_at(m, t)[0, 1]  # noqa: E731
    t1 = brentq(f, 1.0, 15.0, xtol=1e-14)
    t2 = brentq(f, 25.0, 35.0, xtol=1e-14)
    assert abs(t1 - m.first_flip) < 1e-10  # root-finder tolerance plus round-off
    assert abs(t2 - t1 - m.flip_interval) < 1e-10


def test_p7_mrhuggs_cautionary_numbers():
    """Sheet §4: I = (0.3, 0.35, 0.4), w0 = (0.1, 15, 0.1): T_w = 12.3349 s, flips every 6.1675."""
    m = analyse(np.diag([0.3, 0.35, 0.4]), [0.1, 15.0, 0.1])
    assert rel(m.period, 12.3349) < SIX_SF
    assert rel(m.flip_interval, 6.1675) < 1e-5  # quoted to 5 s.f.


def test_p8_separatrix():
    m = analyse(I123, [0.1 * math.sqrt(3), 1.0, 0.1])
    e = m.elliptic
    assert m.case == CASE_SEPARATRIX and e.kind == "separatrix"
    assert m.period is None and m.circles_axis is None and m.flip_interval is None
    assert rel(e.amplitudes[1], 1.01489) < SIX_SF  # Omega0
    assert rel(e.lam, 0.585947) < SIX_SF
    assert rel(e.tau0, 2.45384) < SIX_SF
    np.testing.assert_allclose(omega_at(m, 5.0)[0], [0.00931928, 1.01485, 0.00538049],
                               rtol=SIX_SF)
    j = m.to_json()
    assert j["period"] is None and j["circles_axis"] is None
    assert "separatrix" in m.description


def test_p8_separatrix_against_dop853():
    """Sheet: the sech/tanh solution matches DOP853 to 3e-10 over 30 s."""
    m = analyse(I123, [0.1 * math.sqrt(3), 1.0, 0.1])
    ts = np.linspace(0.0, 30.0, 301)
    wn, Rn = integrate_body(I123, m.omega0, ts)
    we = omega_at(m, ts)
    Re = quat_to_matrix(attitude_at(m, ts))
    # DOP853 rtol 1e-12 amplified by e^(lambda t) while leaving the saddle (sheet: 3e-10)
    assert np.max(np.abs(we - wn)) < 1e-9
    assert np.max(np.abs(Re - Rn)) < 1e-9


@pytest.mark.parametrize(
    "w0, m_ref, lam_ref, T_ref, dphi_ref, case",
    [
        ((1.0, 0.1, 0.2), 0.128712871, 0.580229840, 11.2049694088, 5.62233784747, "1"),
        ((0.2, 0.1, 1.0), 0.0166112957, 1.00166528, 6.29903526898, 12.6451155333, "3"),
        ((0.01, 1.0, 0.01), 0.99980006, 0.577436865, 39.1057341973, 43.2985213636, "3"),
        ((0.001, 1.0, 0.0), 0.999999, 0.577350558, 57.4628488744, 55.3684677047, "1"),
    ],
)
def test_sheet_table_rows_and_dop853(w0, m_ref, lam_ref, T_ref, dphi_ref, case):
    m = analyse(I123, w0)
    e = m.elliptic
    assert e.kind == case
    # digits as printed in the table (8 to 12): relative tolerances one unit in the last
    assert rel(e.m, m_ref) < 1e-8
    assert rel(e.lam, lam_ref) < 1e-8
    assert rel(m.period, T_ref) < 1e-10
    assert rel(m.precession_per_period, dphi_ref) < 1e-10
    v = verify(m, periods=3)
    # table: max|dw| 3e-14..6e-11 and max|dR| up to 6e-11 except the nearest-separatrix row
    # (1.7e-9: DOP853's error amplified ~1/k' = 1000 per passage)
    bound = 1e-8 if e.mc < 1e-5 else 1e-9
    assert v.omega_error < bound and v.attitude_error < bound
    assert v.exact_energy_drift < 1e-14 and v.exact_momentum_drift < 1e-14  # round-off
    assert v.exact_L_drift < 1e-13  # round-off of a few hundred flops in the attitude
    assert v.ok


# ---------------------------------------------------------------------------------------
# P9: long-time invariants, exact vs RK45
# ---------------------------------------------------------------------------------------


def test_p9_exact_invariants_over_1000_periods_and_rk45_drift():
    w0 = np.array([1.0, 0.1, 0.2])
    m = analyse(I123, w0)
    T = m.period
    L0 = m.angular_momentum
    ts = np.concatenate([np.linspace(0.0, 1000 * T, 20001), [1000 * T]])
    w = omega_at(m, ts)
    R = quat_to_matrix(attitude_at(m, ts))
    M = w @ I123
    E = 0.5 * np.einsum("ij,ij->i", w, M)
    G = np.linalg.norm(M, axis=1)
    Ls = np.einsum("nij,nj->ni", R, M)
    # exact evaluation: round-off of ~100 flops per time, nothing accumulates: 1e-13
    assert np.max(np.abs(E / m.kinetic_energy - 1)) < 1e-13
    assert np.max(np.abs(G / m.angular_momentum_norm - 1)) < 1e-13
    assert np.max(np.linalg.norm(Ls - L0, axis=1)) / m.angular_momentum_norm < 1e-13
    assert np.max(np.abs(w[-1] - w0)) < 1e-11  # back to the start after 1000 periods
    # RK45 at default tolerances over 100 periods (sheet: 1.35e-2 over 1000 periods; the drift
    # is secular, ~1e-3 over 100): assert only that it is far above the exact solution's
    I = np.array([1.0, 2.0, 3.0])

    def rhs(_t, y):
        ww = y[:3]
        return np.cross(I * ww, ww) / I

    sol = solve_ivp(rhs, (0.0, 100 * T), w0, method="RK45")
    wn = sol.y[:, -1]
    dT = abs(0.5 * wn @ (I * wn) / m.kinetic_energy - 1)
    dG = abs(np.linalg.norm(I * wn) / m.angular_momentum_norm - 1)
    assert dT > 1e-4 and dG > 1e-4


def test_huge_times_cost_nothing_and_follow_quasi_periodicity():
    """w(jT + r) = w(r) and R(jT + r) = Rot(L^, j dphi) R(r) for j = 10^6."""
    m = analyse(I123, [1.0, 0.1, 0.2])
    T = m.period
    r = np.array([0.0, 1.3, 7.7])
    j = 10**6
    t = j * T + r
    Lhat = m.angular_momentum / m.angular_momentum_norm
    # t ~ 1.1e7 s carries an ulp of 2e-9 s and T's own rounding times 1e6 adds ~2e-9 s; with
    # |w'| ~ 0.5 and phase rates ~1 rad/s this is ~1e-8 in w and in angle
    np.testing.assert_allclose(omega_at(m, t), omega_at(m, r), atol=1e-8)
    Rj = Rotation.from_rotvec(math.remainder(j * m.precession_per_period, 2 * math.pi) * Lhat)
    lhs = rotation_of(attitude_at(m, t))
    rhs = Rj * rotation_of(attitude_at(m, r))
    assert np.max((lhs.inv() * rhs).magnitude()) < 1e-7  # + j * eps * dphi ~ 1e-9
    # a time of 1e9 s gives finite, unit quaternions and invariants to round-off
    q = attitude_at(m, [1e9])
    assert np.all(np.isfinite(q)) and abs(np.linalg.norm(q) - 1) < 1e-15


# ---------------------------------------------------------------------------------------
# random bodies against DOP853 (hypothesis)
# ---------------------------------------------------------------------------------------


@pytest.mark.sampled
@settings(max_examples=sample(6, 25), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    a=st.floats(0.5, 5.0),
    b=st.floats(0.05, 1.0),
    c=st.floats(0.05, 1.0),
    w=st.lists(st.floats(-3.0, 3.0), min_size=3, max_size=3),
    seed=st.integers(0, 2**31 - 1),
)
def test_random_bodies_match_dop853(a, b, c, w, seed):
    moments = np.array([a, a * (1 + b), a * (1 + b) * (1 + c)])
    Q = random_rotation(seed)
    J = Q.T @ np.diag(moments) @ Q  # principal axes not aligned with the body axes
    w0 = np.array(w)
    assume(np.linalg.norm(w0) > 0.1)
    m = analyse(J, w0)
    assume(m.elliptic is not None and m.elliptic.kind != "separatrix")
    # away from the separatrix, where DOP853 itself loses ~1/k' per passage
    assume(m.elliptic.mc > 1e-3)
    ts = np.linspace(0.0, 3 * m.period, 151)
    wn, Rn = integrate_body(J, w0, ts)
    we = omega_at(m, ts)
    Re = quat_to_matrix(attitude_at(m, ts))
    scale = np.linalg.norm(w0)
    # DOP853 rtol 1e-12: the global error of a periodic orbit grows ~linearly (phase error)
    # with the number of steps (~1e3 over 3 periods) and is amplified by up to 1/k' <= 30
    # here: ~1e-12 * 1e3 * 30 = 3e-8 at worst; observed 3e-15..2e-12 (w), 7e-13..1.5e-11 (R).
    assert np.max(np.linalg.norm(we - wn, axis=1)) / scale < 1e-8
    assert np.max(np.abs(Re - Rn)) < 1e-8


# ---------------------------------------------------------------------------------------
# near the separatrix: piecewise shooting (integrator errors do not get time to grow)
# ---------------------------------------------------------------------------------------


@pytest.mark.parametrize("w0", [(1e-4, 1.0, 0.0), (1e-7, 1.0, 0.0), (1e-9, 1.0, 2e-9)])
def test_near_separatrix_is_an_exact_solution_piecewise(w0):
    """From exact states at 40 times per period, DOP853 over a 1/40 period lands on the exact
    solution. Over one such segment the saddle amplifies integrator error by at most
    e^(sigma T/40) ~ e^2, so a tolerance of 1e-9 tests the closed form, not the integrator,
    even for 1 - m = 1e-18 where one long integration is hopeless (Delta2 ~ 1e-18 G^2 is
    below DOP853's own invariant drift)."""
    m = analyse(I123, w0)
    assert m.case in (CASE_MAX, CASE_MIN) and m.elliptic.mc < 1e-7
    T = m.period
    starts = np.linspace(0.0, T, 41)[:-1] + 0.37 * T / 40  # avoid landing only on nodes
    h = T / 40
    w_start = omega_at(m, starts)
    w_end = omega_at(m, starts + h)
    worst = 0.0
    for ws, we in zip(w_start, w_end):
        wn, _ = integrate_body(I123, ws, np.array([0.0, h]))
        worst = max(worst, float(np.max(np.abs(wn[-1] - we))))
    assert worst < 1e-9
    # the period itself: K(m) by the arithmetic-geometric mean, pi / (2 agm(1, k'))
    a, b = 1.0, math.sqrt(m.elliptic.mc)
    for _ in range(60):
        a, b = 0.5 * (a + b), math.sqrt(a * b)
    assert rel(m.period, 4 * (math.pi / (2 * a)) / m.elliptic.lam) < 1e-14


def test_scipy_ellipj_would_fail_near_m_1():
    """Why the module has its own Jacobi functions: scipy.special.ellipj takes m, and for
    1 - m = 1e-10 returns cn(2K) = -2 (it must be -1); ours gives -1 to round-off."""
    from scipy.special import ellipj, ellipkm1

    mc = 1e-10
    K = float(ellipkm1(mc))
    assert abs(ellipj(2 * K, 1 - mc)[1] + 1) > 0.5
    sn, cn, dn, *_ = jacobi_reduced(np.array([2 * K]), K, 1 - mc, mc)
    assert abs(cn[0] + 1) < 1e-14 and abs(sn[0]) < 1e-14 and abs(dn[0] - 1) < 1e-14


@pytest.mark.parametrize("mc", [0.9, 0.5, 1e-2, 1e-6])
def test_jacobi_matches_scipy_where_scipy_is_accurate(mc):
    from scipy.special import ellipj, elliprf

    m = 1 - mc
    K = float(elliprf(0, mc, 1))
    tau = np.linspace(-2 * K, 2 * K, 2001)
    sn, cn, dn, *_ = jacobi_reduced(tau, K, m, mc)
    s2, c2, d2, _ = ellipj(tau, m)
    # scipy's own accuracy degrades like eps/(1 - m) near m = 1 (m rounding): 1e-15/mc
    tol = max(1e-14, 1e-16 / mc * 10)
    assert np.max(np.abs(sn - s2)) < tol
    assert np.max(np.abs(cn - c2)) < tol
    assert np.max(np.abs(dn - d2)) < tol


@pytest.mark.parametrize("mc", [1e-3, 1e-5, 1e-8, 1e-12, 1e-16, 1e-24, 1e-60])
def test_jacobi_identities_near_m_1(mc):
    """Exact values at K/2 and K (A&S 16.5), and the duplication formula
    sn(2u) = 2 sn cn dn / (1 - m sn^4) (A&S 16.17), which links the direct and the
    reflected branches."""
    from scipy.special import elliprf

    m = 1 - mc
    K = float(elliprf(0, mc, 1))
    kp = math.sqrt(mc)
    sn, cn, dn, *_ = jacobi_reduced(np.array([0.5 * K, K]), K, m, mc)
    assert rel(sn[0], 1 / math.sqrt(1 + kp)) < 1e-15
    assert rel(dn[0], math.sqrt(kp)) < 1e-14  # a few ulp
    assert rel(dn[1], kp) < 1e-12 and abs(cn[1]) < 1e-13 * kp and sn[1] == 1.0
    u = np.linspace(-K, K, 4001)
    s, c, d, *_ = jacobi_reduced(u, K, m, mc)
    s2, *_ = jacobi_reduced(2 * u, K, m, mc)
    # 1 - m sn^4 written as cn^2 (1 + sn^2) + mc sn^4, free of cancellation near u = +-K
    dup = 2 * s * c * d / (c * c * (1 + s * s) + mc * s**4)
    # a few ulp of each factor, amplified by at most ~10 in the quotient
    assert np.max(np.abs(s2 - dup)) < 1e-14
    # sn, cn and dn are computed by separate formulas: a few ulp each, not an exact circle
    assert np.max(np.abs(s * s + c * c - 1)) < 5e-15
    assert np.max(np.abs(d * d + m * s * s - 1)) < 5e-15


# ---------------------------------------------------------------------------------------
# symmetric limit of the asymmetric formulas
# ---------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "base, w0, sym",
    [
        ((1.0, 1.0, 3.0), (0.3, 0.4, 1.0), "oblate"),  # I2 -> I1: case "3"
        ((1.0, 3.0, 3.0), (1.0, 0.3, 0.4), "prolate"),  # I2 -> I3: case "1"
    ],
)
def test_symmetric_limit(base, w0, sym):
    I1, I2, I3 = base
    # closed form, written out here: Is = unique moment, W = w3 (Is/I - 1), T = 2 pi/|W|
    if sym == "oblate":
        Is, Iq, w3 = I3, I1, w0[2]
    else:
        Is, Iq, w3 = I1, I3, w0[0]
    W = w3 * (Is - Iq) / Iq
    T0 = 2 * math.pi / abs(W)
    ts = np.linspace(0, T0, 101)
    exact_sym = analyse(np.diag(base), w0)
    assert exact_sym.symmetry == "symmetric" and rel(exact_sym.period, T0) < 1e-14
    wsym = omega_at(exact_sym, ts)
    qsym = rotation_of(attitude_at(exact_sym, ts))
    errs = []
    for eps in (1e-3, 1e-5, 1e-7):
        mom = (I1, I2 + eps, I3) if sym == "oblate" else (I1, I2 - eps, I3)
        m = analyse(np.diag(mom), w0)
        assert m.symmetry == "asymmetric"
        assert m.elliptic.kind == ("3" if sym == "oblate" else "1")
        dw = np.max(np.abs(omega_at(m, ts) - wsym))
        dq = np.max((rotation_of(attitude_at(m, ts)).inv() * qsym).magnitude())
        errs.append((rel(m.period, T0), dw, dq))
    # all three differences are O(eps): each factor 100 in eps shrinks them ~100-fold
    # (allow 30 for the O(eps^2) and round-off terms); the last is ~1e-7 times O(1)
    for k in range(3):
        assert errs[0][k] / errs[1][k] > 30 and errs[1][k] / errs[2][k] > 30
        assert errs[2][k] < 1e-6


# ---------------------------------------------------------------------------------------
# degenerate inputs
# ---------------------------------------------------------------------------------------

SPEC_KEYS = ["angular_momentum", "kinetic_energy", "symmetric", "period", "circles_axis",
             "precession_rate", "space_precession_rate", "body_cone_deg", "space_cone_deg",
             "flip_interval"]


def assert_plain_json(j: dict):
    import json

    for k in SPEC_KEYS:
        assert k in j
    text = json.dumps(j, allow_nan=False)  # raises on NaN/inf
    assert json.loads(text) == j  # only plain types


def test_at_rest():
    for J in (I123, np.diag([1.0, 1.0, 2.0]), np.diag([2.0, 2.0, 2.0])):
        m = analyse(J, [0.0, 0.0, 0.0])
        assert m.case == CASE_REST and m.period is None and m.circles_axis is None
        assert m.kinetic_energy == 0.0 and m.angular_momentum_norm == 0.0
        ts = np.array([0.0, 1.0, 1e9])
        assert np.all(omega_at(m, ts) == 0.0)
        np.testing.assert_array_equal(attitude_at(m, ts), np.tile([1.0, 0, 0, 0], (3, 1)))
        assert_plain_json(m.to_json())
        assert verify(m).ok


def test_spherical_body():
    w0 = np.array([0.3, -0.4, 1.2])
    m = analyse(np.eye(3) * 2.5, w0)
    assert m.case == CASE_SPHERICAL and m.symmetric and m.symmetry == "spherical"
    assert m.period is None and m.circles_axis is None
    ts = np.linspace(0, 10, 11)
    np.testing.assert_allclose(omega_at(m, ts), np.tile(w0, (11, 1)), rtol=1e-15)
    # rotation about omega by |omega| t (closed form via scipy)
    ref = Rotation.from_rotvec(ts[:, None] * w0[None, :])
    assert np.max((rotation_of(attitude_at(m, ts)).inv() * ref).magnitude()) < 1e-14
    j = m.to_json()
    assert_plain_json(j)
    assert j["precession_rate"] == 0.0 and j["body_cone_deg"] == 0.0
    assert j["space_precession_rate"] == pytest.approx(np.linalg.norm(w0), rel=1e-15)


@pytest.mark.parametrize("k", [0, 1, 2])
@pytest.mark.parametrize("seed", [None, 3, 11])
def test_omega_along_a_principal_axis(k, seed):
    """Steady rotation, also when the tensor is not diagonal (round-off snapped)."""
    Q = np.eye(3) if seed is None else random_rotation(seed)
    J = Q.T @ I123 @ Q
    m0 = analyse(J, [1.0, 0.0, 0.0])
    axis = m0.axes[k]
    w0 = 1.7 * axis
    m = analyse(J, w0)
    assert m.case == CASE_STEADY and m.period is None
    assert m.circles_axis == {0: 1, 1: None, 2: 3}[k]
    assert m.stable is (k != 1)
    ts = np.linspace(0.0, 20.0, 21)
    np.testing.assert_allclose(omega_at(m, ts), np.tile(w0, (21, 1)), atol=1e-14)
    ref = Rotation.from_rotvec(ts[:, None] * w0[None, :])
    assert np.max((rotation_of(attitude_at(m, ts)).inv() * ref).magnitude()) < 1e-13
    assert_plain_json(m.to_json())


def test_symmetric_body_steady_cases():
    J = np.diag([1.0, 1.0, 2.0])
    m = analyse(J, [0.0, 0.0, 3.0])  # along the symmetry axis
    assert m.case == CASE_STEADY and m.circles_axis == 3 and m.stable is True
    assert m.body_cone == 0.0 and m.space_cone == 0.0
    assert m.precession_rate == pytest.approx(3.0, rel=1e-15)  # W = w3 (Is/I - 1) = 3
    assert m.wobble_period == pytest.approx(2 * math.pi / 3, rel=1e-15)
    m = analyse(J, [1.0, 2.0, 0.0])  # transverse: every transverse axis is principal
    assert m.case == CASE_STEADY and m.circles_axis is None and m.stable is None
    assert m.precession_rate == 0.0 and m.wobble_to_spin is None and m.wobble_period is None
    assert math.degrees(m.body_cone) == pytest.approx(90.0, rel=1e-15)
    for mm in (m, analyse(J, [0.0, 0.0, 3.0])):
        assert_plain_json(mm.to_json())
        assert verify(mm).ok


@pytest.mark.parametrize("seed", [1, 2, 5])
@pytest.mark.parametrize("w0", [(1.0, 0.1, 0.2), (0.2, 0.1, 1.0), (0.3, -0.8, 0.5)])
def test_non_diagonal_tensor_matches_body_frame_integration(seed, w0):
    """Principal axes not aligned with the body axes: omega(t), R(t) and L in the BODY frame
    against a DOP853 integration with the full tensor (never diagonalised)."""
    Q = random_rotation(seed)
    J = Q.T @ np.diag([1.0, 2.0, 3.0]) @ Q
    m = analyse(J, w0)
    np.testing.assert_allclose(m.angular_momentum, J @ np.array(w0), rtol=1e-13, atol=1e-15)
    assert rel(m.kinetic_energy, 0.5 * np.array(w0) @ J @ np.array(w0)) < 1e-14
    ts = np.linspace(0.0, 2 * m.period, 201)
    wn, Rn = integrate_body(J, np.array(w0), ts)
    # DOP853 rtol 1e-12 over two periods (~1e3 steps): 1e-9 leaves a wide margin
    assert np.max(np.abs(omega_at(m, ts) - wn)) < 1e-9
    assert np.max(np.abs(quat_to_matrix(attitude_at(m, ts)) - Rn)) < 1e-9
    # the same body given diagonally has the same invariants and period
    md = analyse(np.diag([1.0, 2.0, 3.0]), Q @ np.array(w0))
    assert rel(m.period, md.period) < 1e-12


def test_symmetric_body_against_dop853_non_diagonal():
    Q = random_rotation(7)
    J = Q.T @ np.diag([1.0, 1.0, 2.0]) @ Q
    w0 = np.array([0.4, -0.3, 1.1])
    m = analyse(J, w0)
    assert m.symmetry == "symmetric"
    ts = np.linspace(0.0, 3 * m.period, 301)
    wn, Rn = integrate_body(J, w0, ts)
    assert np.max(np.abs(omega_at(m, ts) - wn)) < 1e-9  # DOP853 rtol 1e-12, 3 periods
    assert np.max(np.abs(quat_to_matrix(attitude_at(m, ts)) - Rn)) < 1e-9


def test_json_every_case_has_every_key_and_no_nan():
    cases = [
        (I123, (1.0, 0.1, 0.2)), (I123, (0.2, 0.1, 1.0)), (I123, (0.1 * math.sqrt(3), 1, 0.1)),
        (I123, (0, 1.0, 0)), (np.diag([1.0, 1, 2]), (1, 0, 1)), (np.eye(3), (1, 2, 3)),
        (I123, (0, 0, 0)),
    ]
    keysets = []
    for J, w in cases:
        j = analyse(J, w).to_json()
        assert_plain_json(j)
        keysets.append(tuple(sorted(j)))
    assert len(set(keysets)) == 1  # "the same keys every time" (SPEC §3)


def test_verify_reports_and_json():
    v = verify(analyse(I123, [1.0, 0.1, 0.2]))
    j = v.to_json()
    assert v.ok and j["ok"] is True
    # sheet table row 1: max|dw| 3.1e-14, max|dR| 2.5e-12 for DOP853 rtol 1e-12 over 3 periods
    assert v.omega_error < 1e-12 and v.attitude_error < 1e-11
    assert v.numeric_energy_drift < 1e-12 and v.exact_energy_drift < 1e-15


def test_quaternion_to_matrix_matches_scipy():
    q = Rotation.random(20, random_state=4).as_quat(scalar_first=True)
    np.testing.assert_allclose(quat_to_matrix(q),
                               Rotation.from_quat(q, scalar_first=True).as_matrix(), atol=1e-15)


def test_bad_input():
    with pytest.raises(ValueError, match="3x3"):
        analyse(np.eye(2), [1, 2, 3])
    with pytest.raises(ValueError, match="3 components"):
        analyse(np.eye(3), [1, 2])
    with pytest.raises(ValueError, match="finite"):
        analyse(np.eye(3), [1, np.nan, 3])
    with pytest.raises(ValueError, match="positive definite"):
        analyse(np.diag([0.0, 1.0, 1.0]), [1, 2, 3])
    m = analyse(I123, [1, 2, 3])
    with pytest.raises(ValueError, match="finite"):
        omega_at(m, [np.inf])


@pytest.mark.parametrize("w0", [(1.0, 0.1, 0.2), (0.01, 1.0, 0.01), (0.4, 0.0, 1.0)])
def test_scaling_laws(w0):
    """Dimensional analysis: J -> c J leaves the period; w -> s w divides it by s (and the
    precession angle per period is unchanged). Coin-sized and planet-sized numbers alike."""
    base = analyse(I123, w0)
    for cJ, s in ((1e-9, 1e4), (1e30, 7.3e-5), (3.0, 1.0)):
        m = analyse(cJ * I123, s * np.array(w0))
        assert m.case == base.case
        assert rel(m.period * s, base.period) < 1e-13  # round-off of the scaled formulas
        assert rel(m.precession_per_period, base.precession_per_period) < 1e-13
        ts = np.linspace(0, base.period, 7)
        np.testing.assert_allclose(omega_at(m, ts / s) / s, omega_at(base, ts), atol=1e-14)


def test_symmetric_rtol_merges_close_moments():
    J = np.diag([1.0, 1.0 + 1e-7, 3.0])
    assert analyse(J, [0.3, 0.4, 1.0]).symmetry == "asymmetric"  # default 1e-9
    m = analyse(J, [0.3, 0.4, 1.0], symmetric_rtol=1e-6)
    assert m.symmetry == "symmetric" and m.oblate and m.circles_axis == 3
    assert m.moments[0] == m.moments[1] == pytest.approx(1.0 + 5e-8, rel=1e-15)


def test_principal_frame_output():
    Q = random_rotation(9)
    J = Q.T @ I123 @ Q
    m = analyse(J, [0.3, 0.5, -0.2])
    ts = np.linspace(0, 10, 11)
    np.testing.assert_allclose(omega_at(m, ts, frame="principal"), omega_at(m, ts) @ m.axes.T,
                               atol=1e-15)  # a rotation of (N,3) rows: round-off
    with pytest.raises(ValueError, match="frame"):
        omega_at(m, ts, frame="space")
