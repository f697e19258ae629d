"""Tests of rbcli.core.top: the heavy symmetric top and the gyrocompass.

Expected numbers come from the physics sheet /work/shared/physics/dynamics.md (§2, §2.1
worked example, §6 cases T1–T4, T8), from closed forms written out here, and from an
independent numerical oracle: a quaternion + body-frame Euler-equation integration
(scipy DOP853, attitude through scipy Rotation), which shares no code with the module.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from conftest import sample
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp
from scipy.spatial.transform import Rotation

from rbcli.core.gyrocompass import gyrocompass
from rbcli.core.top import analyse
from rbcli.core.topbody import PivotAtCom, TopParams, top_from_body
from rbcli.core.toppath import path_at
from rbcli.core.topverify import verify

# The sheet's top (§2.1, §6 "top"): m, l, I about the pivot across, Is, S, g, θ0.
M, L, I_P, IS, SPIN, G = 0.5, 0.04, 1.2e-3, 4.0e-4, 150.0, 9.81
TH30 = math.radians(30.0)
SHEET_TOP = TopParams(mass=M, length=L, I=I_P, Is=IS)


def half_unit(value: float) -> float:
    """Half a unit in the last of the 6 significant figures the sheet prints."""
    return 0.5 * 10 ** (math.floor(math.log10(abs(value))) - 5)


def rot_matrix(phi: float, theta: float, psi: float) -> np.ndarray:
    """Rz(φ) Ry(θ) Rz(ψ), the module's convention, via scipy (intrinsic 'ZYZ')."""
    return Rotation.from_euler("ZYZ", [phi, theta, psi]).as_matrix()


# --------------------------------------------------------------------------------------
# independent oracle: quaternion + Euler's equations in the body frame


def oracle(
    m: float, l: float, I: float, Is: float, g: float, S: float,
    th0: float, thd0: float, phd0: float, t_eval: np.ndarray, rtol: float = 1e-11,
) -> tuple[np.ndarray, np.ndarray]:  # fmt: skip
    """Space-frame axis e3(t) and body x axis e1(t), shape (len(t), 3) each.

    Body frame: inertia diag(I, I, Is) about the pivot, com at l ẑ_body. State: unit
    quaternion q (scalar last, as scipy) and body angular velocity w.
    q' = ½ q ⊗ (w, 0); I w' = τ - w × (I w), τ = l ẑ × Rᵀ(0, 0, -m g).
    """
    J = np.array([I, I, Is])
    R0 = Rotation.from_euler("ZYZ", [0.0, th0, 0.0])
    e3 = R0.apply([0.0, 0.0, 1.0])
    w_space = np.array([0.0, 0.0, phd0]) + np.array([0.0, thd0, 0.0]) + (S - phd0 * math.cos(th0)) * e3
    w0 = R0.inv().apply(w_space)

    def rhs(_t: float, y: np.ndarray) -> np.ndarray:
        x, yq, z, s = y[:4]
        w = y[4:]
        # q ⊗ (w, 0), scalar-last Hamilton product
        dq = 0.5 * np.array([
            s * w[0] + yq * w[2] - z * w[1],
            s * w[1] + z * w[0] - x * w[2],
            s * w[2] + x * w[1] - yq * w[0],
            -(x * w[0] + yq * w[1] + z * w[2]),
        ])  # fmt: skip
        n2 = x * x + yq * yq + z * z + s * s
        # gravity in body axes: -m g times the third row of R(q) (standard quaternion matrix)
        row3 = np.array([2 * (x * z - s * yq), 2 * (yq * z + s * x), n2 - 2 * (x * x + yq * yq)]) / n2
        F_body = -m * g * row3
        tau = l * np.array([-F_body[1], F_body[0], 0.0])  # (0, 0, l) × F
        dw = (tau - np.cross(w, J * w)) / J
        return np.concatenate([dq, dw])

    y0 = np.concatenate([R0.as_quat(), w0])
    sol = solve_ivp(rhs, (0.0, float(t_eval[-1])), y0, method="DOP853", t_eval=t_eval,
                    rtol=rtol, atol=rtol * 1e-2)  # fmt: skip
    assert sol.success
    R = Rotation.from_quat(sol.y[:4].T)
    return R.apply([0.0, 0.0, 1.0]), R.apply([1.0, 0.0, 0.0])


def closed_axes(motion, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    theta, phi, psi = path_at(motion, t)
    R = Rotation.from_euler("ZYZ", np.stack([phi, theta, psi], axis=-1))
    return R.apply([0.0, 0.0, 1.0]), R.apply([1.0, 0.0, 0.0])


# --------------------------------------------------------------------------------------
# T1 / §2.1: the worked example, released from rest at 30°


@pytest.fixture(scope="module")
def t1():
    return analyse(SHEET_TOP, SPIN, TH30, g=G)


def test_t1_goldstein_constants_and_roots(t1):
    # §2.1 prints 12 significant figures; 1e-10 relative leaves room for the
    # round-off of the few dozen operations behind each number (~1e-14) and the
    # sheet's own last digit.
    assert t1.a == pytest.approx(50.0, rel=1e-12)
    assert t1.b == pytest.approx(43.3012701892, rel=1e-10)
    assert t1.alpha == pytest.approx(283.190307038, rel=1e-10)
    assert t1.beta == pytest.approx(327.0, rel=1e-12)
    assert t1.u1 == pytest.approx(0.824045210315, rel=1e-10)
    assert t1.u2 == pytest.approx(0.866025403784, rel=1e-11)
    assert t1.u3 == pytest.approx(6.82121472852, rel=1e-10)
    assert t1.elliptic.m == pytest.approx(0.00700000114, rel=1e-8)  # 9 figures given
    assert t1.elliptic.lam == pytest.approx(22.1420100288, rel=1e-10)


def test_t1_tilt_limits_period_and_rates(t1):
    # released from rest: u2 = u0 exactly (sheet §2), so θ1 is θ0 to round-off (1e-15)
    assert math.degrees(t1.theta1) == pytest.approx(30.0, abs=1e-12)
    assert math.degrees(t1.theta2) == pytest.approx(34.5081906, abs=1e-7)  # 9 figures
    assert t1.nutation_period == pytest.approx(0.142133085067, rel=1e-10)
    assert t1.nutation_frequency == pytest.approx(44.2064, abs=half_unit(44.2064))
    assert t1.precession_per_nutation == pytest.approx(0.492976889843, rel=1e-10)
    assert t1.mean_precession_rate == pytest.approx(3.46841757224, rel=1e-10)
    assert t1.spin_per_nutation == pytest.approx(20.908228287, rel=1e-10)
    assert t1.mean_spin_rate == pytest.approx(147.103176, rel=1e-8)  # 9 figures given
    assert t1.path == "cusps"
    assert not t1.steady


def test_t1_fast_top_estimates(t1):
    ft = t1.fast_top
    # T1 prints "Fast-top estimates: 50.0000 rad/s, 3.74714°, 3.27000 rad/s" (6 figures)
    assert ft.nutation_frequency == pytest.approx(50.0, abs=half_unit(50.0))
    assert math.degrees(ft.nutation_amplitude) == pytest.approx(3.74714, abs=half_unit(3.74714))
    assert ft.mean_precession_rate == pytest.approx(3.27, abs=half_unit(3.27))
    # relative errors against the sheet's exact values (44.2064 rad/s, 4.50819°, 3.46842);
    # those carry 6 figures, so the ratios are good to ~2e-6
    assert ft.nutation_frequency_rel_error == pytest.approx(50 / 44.2064 - 1, abs=3e-6)
    assert ft.nutation_amplitude_rel_error == pytest.approx(3.74714 / 4.50819 - 1, abs=3e-6)
    assert ft.mean_precession_rate_rel_error == pytest.approx(3.27 / 3.46842 - 1, abs=3e-6)


def test_t1_path_at_matches_sheet_turning_points(t1):
    T = t1.nutation_period
    theta, phi, psi = path_at(t1, np.array([0.0, T / 2, T, 7 * T]))
    # starts at the top turning point, reaches θ2 half a period later (sheet §2 closed
    # form, u = u1 + (u2-u1) cd²(λt)); 1e-12 rad is round-off of ellipj and atan2
    assert theta[0] == pytest.approx(TH30, abs=1e-12)
    assert math.degrees(theta[1]) == pytest.approx(34.5081906, abs=1e-7)
    assert theta[2] == pytest.approx(TH30, abs=1e-12)
    assert phi[0] == 0.0 and psi[0] == 0.0
    # after whole periods φ and ψ advance by the sheet's Δφ and Δψ per nutation
    assert phi[2] == pytest.approx(0.492976889843, rel=1e-10)
    assert phi[3] == pytest.approx(7 * 0.492976889843, rel=1e-10)
    assert psi[3] == pytest.approx(7 * 20.908228287, rel=1e-10)


def test_t1_verify_matches_sheet_direct_integration(t1):
    v = verify(t1, periods=3)
    # Sheet §2.1: DOP853 rtol 1e-12 agrees with the closed form to 5.5e-13 in u over 20
    # periods and conserves E to 6e-15. Over 3 periods allow 1e-10 (rtol 1e-12 times
    # ~1e4 steps, with margin) on the angles and 1e-12 on the invariants.
    assert v.max_axis_error < 1e-10
    assert v.max_theta_error < 1e-10
    assert v.max_phi_error < 1e-10
    assert v.max_psi_error < 1e-8  # ψ runs to ~440 rad: 1e-8 is 2e-11 relative
    assert v.energy_drift < 1e-12
    assert v.p_phi_drift < 1e-12 and v.p_psi_drift < 1e-12
    assert math.degrees(v.theta_max) == pytest.approx(34.50819065, abs=1e-8)  # 10 figures
    assert v.mean_precession_rate == pytest.approx(3.46841757224, rel=1e-9)


# --------------------------------------------------------------------------------------
# T2–T4: steady precession, horizontal axis, sleeping top


def test_t2_steady_precession_rates_and_threshold(t1):
    slow, fast = t1.steady_precession_rates
    # §2.1 gives 12 figures for the steady rates and 9 for the minimum spin
    assert slow == pytest.approx(3.47972514879, rel=1e-10)
    assert fast == pytest.approx(54.2553017702, rel=1e-10)
    assert t1.minimum_spin_for_steady == pytest.approx(71.3962571, rel=1e-8)
    n_slow, n_fast = t1.steady_nutation_frequencies
    assert n_slow == pytest.approx(44.0073, abs=half_unit(44.0073))
    assert n_fast == pytest.approx(51.6675, abs=half_unit(51.6675))


@pytest.mark.parametrize("branch, nut", [(0, 44.0073), (1, 51.6675)])
def test_t2_started_on_steady_precession(t1, branch, nut):
    rate = t1.steady_precession_rates[branch]
    mo = analyse(SHEET_TOP, SPIN, TH30, phi_dot0=rate, g=G)
    assert mo.steady and mo.path == "steady"
    # the band closes: θ1 = θ2 to round-off (the cubic's double root, well conditioned in
    # the shifted variable; 1e-9 deg is far below the 6-figure output)
    assert math.degrees(mo.theta2 - mo.theta1) < 1e-9
    # the mean precession is the steady rate; the sheet's naive root path was 3e-8 off
    # here, the shifted cubic gives round-off (1e-12 relative)
    assert mo.mean_precession_rate == pytest.approx(rate, rel=1e-12)
    # the elliptic T_n tends to the small-nutation formula (sheet §2, 6 figures)
    assert mo.nutation_frequency == pytest.approx(nut, abs=half_unit(nut))


@pytest.mark.parametrize("delta", [1e-12, 1e-9, 1e-6, 1e-3])
def test_near_steady_start_is_continuous(t1, delta):
    slow = t1.steady_precession_rates[0]
    for sign in (1.0, -1.0):
        mo = analyse(SHEET_TOP, SPIN, TH30, phi_dot0=slow * (1 + sign * delta), g=G)
        # a mean of φ'(u) = (b - a u)/(1 - u²) over the band lies between its values at the
        # band's ends, which differ from the start rate by O(δ): |<φ'> - slow| <= 10 δ slow
        # is a generous bound (the observed slope is 1.6e-3); no NaN, no jump
        assert abs(mo.mean_precession_rate - slow) <= 10 * delta * slow + 1e-14
        ends = [(mo.b - mo.a * u) / (1 - u * u) for u in (mo.u1, mo.u2)]
        assert min(ends) - 1e-12 <= mo.mean_precession_rate <= max(ends) + 1e-12
        # small nutation about steady precession: the elliptic frequency matches the
        # linearised one to O(amplitude) ~ δ (sheet §2: "to 8 digits")
        assert mo.nutation_frequency == pytest.approx(
            t1.steady_nutation_frequencies[0], rel=max(10 * delta, 1e-10)
        )


def test_t3_horizontal_axis():
    mo = analyse(SHEET_TOP, SPIN, math.pi / 2, g=G)
    # T3: φ' = m g l/(Is S) = 3.27 rad/s; exact arithmetic 0.5*9.81*0.04/(4e-4*150)
    assert mo.horizontal_precession_rate == pytest.approx(3.27, rel=1e-14)
    # at 90° the steady-precession quadratic has the single (gyroscope) root; the fast one
    # is infinite and is left out
    assert mo.steady_precession_rates == pytest.approx((3.27,), rel=1e-14)
    assert mo.minimum_spin_for_steady == 0.0


def test_t4_sleeping_top_threshold():
    mo = analyse(SHEET_TOP, SPIN, TH30, g=G)
    assert mo.critical_spin == pytest.approx(76.7202711, rel=1e-8)  # §2.1, 9 figures
    assert mo.sleeps  # S = 150 > S_c


@pytest.mark.parametrize(
    "ratio, max_tilt_deg, half_unit_deg",
    [(0.95, 36.4, 0.05), (0.99, 16.2, 0.05), (1.01, 0.41, 0.005), (1.05, 0.19, 0.005)],
)
def test_sleeping_threshold_table(ratio, max_tilt_deg, half_unit_deg):
    """Sheet §2 table: released at 0.0573° (1e-3 rad), max tilt over 3 s."""
    Sc = math.sqrt(4 * I_P * M * G * L) / IS
    mo = analyse(SHEET_TOP, ratio * Sc, 1e-3, g=G)
    assert mo.sleeps == (ratio > 1)
    # the greatest tilt θ2 is reached at T_n/2, within the sheet's 3 s in every row
    assert mo.nutation_period / 2 < 3.0
    # the sheet prints 3 or 2 figures: agree to half a unit in the last one
    assert math.degrees(mo.theta2) == pytest.approx(max_tilt_deg, abs=half_unit_deg)


def test_minimum_spin_for_steady_precession():
    S_min = math.sqrt(4 * I_P * M * G * L * math.cos(TH30)) / IS  # sheet §2 condition
    below = analyse(SHEET_TOP, S_min * (1 - 1e-6), TH30, g=G)
    above = analyse(SHEET_TOP, S_min * (1 + 1e-6), TH30, g=G)
    assert below.steady_precession_rates == ()
    assert below.minimum_spin_for_steady == pytest.approx(S_min, rel=1e-14)
    assert len(above.steady_precession_rates) == 2
    # at the threshold both roots merge at Is S/(2 I cos θ); 1e-6 above it they are
    # sqrt(2e-6) ≈ 1.4e-3 apart relative, so 3e-3 bounds the distance to the merge point
    merge = IS * S_min / (2 * I_P * math.cos(TH30))
    for r in above.steady_precession_rates:
        assert r == pytest.approx(merge, rel=3e-3)
    # and they satisfy I cos θ φ'² - Is S φ' + m g l = 0 (round-off of 5 products)
    S = S_min * (1 + 1e-6)
    for r in above.steady_precession_rates:
        resid = I_P * math.cos(TH30) * r * r - IS * S * r + M * G * L
        assert abs(resid) < 1e-13 * M * G * L * 10


def test_steady_rates_below_horizontal_always_exist():
    # θ > 90°: Is²S² - 4 I m g l cos θ > 0 for every spin; the fast root is retrograde
    mo = analyse(SHEET_TOP, 5.0, math.radians(120), g=G)
    slow, fast = mo.steady_precession_rates
    assert slow > 0 > fast
    for r in (slow, fast):
        resid = I_P * math.cos(mo.theta0) * r * r - IS * 5.0 * r + M * G * L
        assert abs(resid) < 1e-12 * M * G * L


# --------------------------------------------------------------------------------------
# the kind of path, checked on the independent oracle's azimuth


def _oracle_phi_dot(mo, periods: float = 1.0) -> np.ndarray:
    t = np.linspace(0.0, periods * mo.nutation_period, 801)
    e3, _ = oracle(M, L, I_P, IS, G, mo.spin, mo.theta0, mo.theta_dot0, mo.phi_dot0, t)
    phi = np.unwrap(np.arctan2(e3[:, 1], e3[:, 0]))
    return np.diff(phi)


def test_release_from_rest_gives_cusps(t1):
    dphi = _oracle_phi_dot(t1)
    assert t1.path == "cusps"
    # φ' >= 0 throughout and touches 0 at the top (sheet: cusps point up, at θ1); the
    # steps are 1/800 of a period, so a first step from a cusp is O(step²) small
    assert np.all(dphi > -1e-12)
    assert dphi.min() < 1e-3 * dphi.max()


@pytest.mark.parametrize("thd, phd", [(2.0, 0.0), (0.0, -3.0), (0.0, 7.0)])
def test_loops(thd, phd):
    # φ0' = 0 with θ0' != 0: u' = u0 strictly inside the band (sheet); a backwards start,
    # or one at twice the slow steady rate, also puts u' inside
    mo = analyse(SHEET_TOP, SPIN, TH30, theta_dot0=thd, phi_dot0=phd, g=G)
    assert mo.path == "loops"
    assert mo.u1 < mo.apex_u < mo.u2
    dphi = _oracle_phi_dot(mo)
    assert dphi.min() < 0 < dphi.max()


def test_fast_start_gives_waves(t1):
    # 1.5 × the slow steady rate: the apex point u' = b/a lies above the band (u' > u2)
    mo = analyse(SHEET_TOP, SPIN, TH30, phi_dot0=1.5 * t1.steady_precession_rates[0], g=G)
    assert mo.path == "waves"
    assert mo.apex_u > mo.u2
    dphi = _oracle_phi_dot(mo)
    assert np.all(dphi > 0)


@settings(max_examples=15, deadline=None)
@given(
    m=st.floats(0.05, 5.0), l=st.floats(0.005, 0.3), rt=st.floats(0.01, 0.3),
    rs=st.floats(0.01, 0.3), S=st.floats(5.0, 400.0), sgn=st.sampled_from([-1.0, 1.0]),
    th_deg=st.floats(2.0, 178.0),
)  # fmt: skip
def test_release_from_rest_always_cusps_at_start_angle(m, l, rt, rs, S, sgn, th_deg):
    p = TopParams(m, l, m * (rt * rt + l * l), m * rs * rs)
    th = math.radians(th_deg)
    mo = analyse(p, sgn * S, th, g=G)
    assert mo.path == "cusps"
    # released from rest, θ0 is the top turning point exactly (the deflated root x = 0);
    # θ1 from atan2 of exact half-angle terms: round-off ~1e-15
    assert mo.theta1 == pytest.approx(th, abs=1e-14)
    assert mo.theta2 >= mo.theta1


# --------------------------------------------------------------------------------------
# closed form against the independent oracle, random tops and starts


@pytest.mark.sampled
@settings(max_examples=sample(5, 20), deadline=None)
@given(
    m=st.floats(0.1, 3.0), l=st.floats(0.01, 0.2), rt=st.floats(0.02, 0.2),
    rs=st.floats(0.02, 0.2), S=st.floats(5.0, 120.0), sgn=st.sampled_from([-1.0, 1.0]),
    th_deg=st.floats(5.0, 175.0), thd=st.floats(-4.0, 4.0), phd=st.floats(-8.0, 8.0),
)  # fmt: skip
def test_closed_form_matches_oracle(m, l, rt, rs, S, sgn, th_deg, thd, phd):
    p = TopParams(m, l, m * (rt * rt + l * l), m * rs * rs)
    mo = analyse(p, sgn * S, math.radians(th_deg), thd, phd, g=G)
    t = np.linspace(0.0, 1.5 * mo.nutation_period, 301)  # past one period: τ reduction
    e3_o, e1_o = oracle(p.mass, p.length, p.I, p.Is, G, mo.spin, mo.theta0, thd, phd, t)
    e3_c, e1_c = closed_axes(mo, t)
    # DOP853 at rtol 1e-11 over a few thousand steps: global error ≲ 1e-8 on unit vectors.
    # The axis is compared as a vector (well conditioned even where it passes near the
    # vertical and φ swings fast); e1 checks ψ(t) too.
    assert np.max(np.linalg.norm(e3_o - e3_c, axis=1)) < 1e-7
    assert np.max(np.linalg.norm(e1_o - e1_c, axis=1)) < 1e-7
    # the tilt stays in [θ1, θ2] (1e-7 rad: the same integrator error)
    tilt = np.arccos(np.clip(e3_o[:, 2], -1, 1))
    assert tilt.min() >= mo.theta1 - 1e-7 and tilt.max() <= mo.theta2 + 1e-7


@settings(max_examples=8, deadline=None)
@given(
    S=st.floats(20.0, 200.0), th_deg=st.floats(5.0, 175.0), thd=st.floats(-3.0, 3.0),
    phd=st.floats(-6.0, 6.0),
)  # fmt: skip
def test_verify_reports_small_differences(S, th_deg, thd, phd):
    mo = analyse(SHEET_TOP, S, math.radians(th_deg), thd, phd, g=G)
    v = verify(mo, periods=2)
    # verify() integrates at rtol 1e-12: axis differences of 1e-9 leave a factor ~100 for
    # the accumulation over ~1e4 steps; the invariants drift only by round-off per step
    assert v.max_axis_error < 1e-9
    assert v.energy_drift < 1e-10
    assert v.p_phi_drift < 1e-10 and v.p_psi_drift < 1e-10
    assert v.mean_precession_rate == pytest.approx(mo.mean_precession_rate, rel=1e-8, abs=1e-9)


def test_axis_through_the_vertical():
    # b = a exactly: φ' = a/(1+u) never vanishes, the apex passes through the pole, and
    # its azimuth jumps by π there; the axis vector must still follow the oracle
    a = IS * SPIN / I_P
    th0 = 0.5
    for thd in (0.0, 1.0):
        mo = analyse(SHEET_TOP, SPIN, th0, thd, a / (1 + math.cos(th0)), g=G)
        assert mo.path == "waves"
        assert math.isfinite(mo.mean_precession_rate)
        t = np.linspace(0.0, 2 * mo.nutation_period, 201)
        e3_o, _ = oracle(M, L, I_P, IS, G, SPIN, th0, thd, mo.phi_dot0, t)
        # near the pole θ is resolved to ~sqrt(eps) of u: 1e-7 covers it
        assert np.max(np.linalg.norm(e3_o - mo.at(t).axis, axis=1)) < 1e-7


# --------------------------------------------------------------------------------------
# building the top from a body's mass properties


def test_t1_top_built_from_a_tilted_body():
    # com at l along the tilted axis (1, 2, 2)/3 from an off-origin pivot; I_com across
    # = I - m l² = 4e-4, along = Is = 4e-4 (the sheet top happens to be spherical about
    # its com)
    e3 = np.array([1.0, 2.0, 2.0]) / 3.0
    pivot = np.array([0.1, -0.2, 0.3])
    p = top_from_body(M, pivot + L * e3, 4e-4 * np.eye(3), pivot)
    # parallel-axis arithmetic on numbers of order 1e-3: round-off 1e-15 relative
    assert p.mass == M
    assert p.length == pytest.approx(L, rel=1e-14)
    assert p.I == pytest.approx(I_P, rel=1e-12)
    assert p.Is == pytest.approx(IS, rel=1e-12)
    assert np.allclose(p.axis, e3, atol=1e-15)
    mo = analyse(p, SPIN, TH30, g=G)
    assert mo.nutation_period == pytest.approx(0.142133085067, rel=1e-10)


@settings(max_examples=30, deadline=None)
@given(
    quat=st.tuples(*[st.floats(-1, 1)] * 4).filter(lambda q: sum(x * x for x in q) > 0.1),
    It=st.floats(1e-4, 1e-2), Is=st.floats(1e-4, 1e-2), m=st.floats(0.1, 10.0),
    l=st.floats(0.01, 1.0), pivot=st.tuples(*[st.floats(-1, 1)] * 3),
)  # fmt: skip
def test_geometry_any_orientation(quat, It, Is, m, l, pivot):
    R = Rotation.from_quat(quat).as_matrix()
    Icom = R @ np.diag([It, It, Is]) @ R.T
    e3 = R[:, 2]
    pv = np.array(pivot)
    p = top_from_body(m, pv + l * e3, Icom, pv)
    # parallel-axis theorem I = It + m l² across, Is along; relative round-off of the
    # rotation and the 3x3 products: 1e-12
    assert p.I == pytest.approx(It + m * l * l, rel=1e-12)
    assert p.Is == pytest.approx(Is, rel=1e-10, abs=1e-12 * (It + m * l * l))
    assert p.length == pytest.approx(l, rel=1e-12)
    assert np.allclose(p.axis, e3, atol=1e-12)


def test_asymmetric_body_is_refused_with_how_asymmetric():
    # transverse moments about the pivot 1.2e-3 and 1.5e-3: they differ by 0.3/1.35 = 22 %
    Icom = np.diag([1.2e-3 - M * L * L, 1.5e-3 - M * L * L, 4e-4])
    with pytest.raises(ValueError) as err:
        top_from_body(M, [0, 0, L], Icom, [0, 0, 0])
    msg = str(err.value)  # the parameter as a template the caller spells ({symmetry_tol})
    assert not isinstance(err.value, PivotAtCom)
    assert "not symmetric" in msg
    assert "1.2e-3" in msg and "1.5e-3" in msg and "22 %" in msg and "{symmetry_tol}" in msg


def test_tolerance_of_symmetry_is_honoured():
    Icom = np.diag([4e-4 * (1 + 1e-7), 4e-4, 4e-4])  # 3e-8 relative about the pivot: rounding
    p = top_from_body(M, [0, 0, L], Icom, [0, 0, 0], sym_rtol=0.0)  # even at tolerance 0
    assert p.asymmetry is None
    # 1e-5 of the moment about the com: 3.3e-6 of the moment across about the pivot
    Icom = np.diag([4e-4 * (1 + 1e-5), 4e-4, 4e-4])
    with pytest.raises(ValueError, match="not symmetric"):
        top_from_body(M, [0, 0, L], Icom, [0, 0, 0])  # the core's default: rounding only
    p = top_from_body(M, [0, 0, L], Icom, [0, 0, 0], sym_rtol=1e-4)
    I1, I2 = p.asymmetry.transverse
    assert p.I == pytest.approx(0.5 * (I1 + I2), rel=1e-15)  # the symmetrised body
    assert p.asymmetry.relative == pytest.approx(4e-9 / (4e-4 + M * L * L + 2e-9), rel=1e-6)


def test_axis_not_principal_is_refused():
    Icom = 4e-4 * np.eye(3)
    Icom[0, 2] = Icom[2, 0] = -1e-5  # couples the axis (z) to x
    with pytest.raises(ValueError, match="not a principal axis"):
        top_from_body(M, [0, 0, L], Icom, [0, 0, 0])


def test_pivot_at_com_points_to_precess():
    with pytest.raises(PivotAtCom) as err:
        top_from_body(M, [0.1, 0.2, 0.3], np.diag([1e-3, 1e-3, 2e-3]), [0.1, 0.2, 0.3])
    assert isinstance(err.value, ValueError)
    assert "rbcli precess" in str(err.value)
    # a pivot 1e-12 m from the com of a ~5 cm body is at the com too (round-off)
    with pytest.raises(PivotAtCom):
        top_from_body(M, [0, 0, 1e-12], np.diag([1e-3, 1e-3, 2e-3]), [0, 0, 0])


def test_point_mass_is_a_pendulum_not_a_top():
    with pytest.raises(ValueError, match="pendulum"):
        top_from_body(M, [0, 0, L], np.zeros((3, 3)), [0, 0, 0])


# --------------------------------------------------------------------------------------
# bad inputs


@pytest.mark.parametrize("theta0", [0.0, math.pi, -0.1, 4.0, float("nan")])
def test_theta0_outside_open_interval_refused(theta0):
    with pytest.raises(ValueError):
        analyse(SHEET_TOP, SPIN, theta0, g=G)


@pytest.mark.parametrize("g", [0.0, -9.81, float("inf")])
def test_bad_gravity_refused(g):
    with pytest.raises(ValueError):
        analyse(SHEET_TOP, SPIN, TH30, g=g)


def test_zero_spin_refused_as_pendulum():
    with pytest.raises(ValueError, match="pendulum"):
        analyse(SHEET_TOP, 0.0, TH30, g=G)


def test_bad_params_refused():
    with pytest.raises(ValueError):
        TopParams(mass=0.0, length=L, I=I_P, Is=IS)
    with pytest.raises(ValueError):
        TopParams(mass=M, length=L, I=I_P, Is=float("nan"))


# --------------------------------------------------------------------------------------
# JSON


SPEC_KEYS = {
    "mass", "length", "I", "Is", "spin", "steady_precession_rates",
    "horizontal_precession_rate", "critical_spin", "theta1_deg", "theta2_deg",
    "nutation_period", "mean_precession_rate", "path",
}  # fmt: skip


def _plain(x) -> bool:
    if isinstance(x, dict):
        return all(isinstance(k, str) and _plain(v) for k, v in x.items())
    if isinstance(x, list):
        return all(_plain(v) for v in x)
    return x is None or type(x) in (float, int, bool, str)


@pytest.mark.parametrize(
    "spin, theta_deg, thd, phd",
    [(150.0, 30.0, 0.0, 0.0), (50.0, 30.0, 0.0, 0.0), (150.0, 90.0, 1.0, -2.0), (-30.0, 150.0, 0.5, 0.0)],
)  # fmt: skip
def test_to_json_keys_and_plain_values(spin, theta_deg, thd, phd):
    mo = analyse(SHEET_TOP, spin, math.radians(theta_deg), thd, phd, g=G)
    d = mo.to_json()
    assert SPEC_KEYS <= d.keys()
    assert _plain(d)
    json.dumps(d, allow_nan=False)  # raises on NaN or infinity
    assert d["path"] in {"waves", "loops", "cusps", "steady"}
    assert len(d["steady_precession_rates"]) in (0, 1, 2)
    if spin == 50.0:  # below the 71.4 rad/s minimum at 30°: no steady precession
        assert d["steady_precession_rates"] == []
    json.dumps(verify(mo, periods=1).to_json(), allow_nan=False)


# --------------------------------------------------------------------------------------
# T8: gyrocompass


def test_t8_gyrocompass():
    six_thousand_rpm = 6000 * 2 * math.pi / 60
    gc = gyrocompass(2.0, six_thousand_rpm, math.radians(30.0))
    # sheet T8, 6 figures: ω0 = 0.281707 rad/s, T = 22.3040 s
    assert gc.omega0 == pytest.approx(0.281707, abs=half_unit(0.281707))
    assert gc.period == pytest.approx(22.3040, abs=half_unit(22.3040))
    assert gc.settles_to == "north"
    gc2 = gyrocompass(2.0, 20000 * 2 * math.pi / 60, math.radians(45.0))
    assert gc2.period == pytest.approx(13.5197, abs=half_unit(13.5197))
    json.dumps(gc.to_json(), allow_nan=False)


def test_gyrocompass_limits():
    S = 600.0
    # reversed spin: the +axis settles south with the same period (the spin vector north)
    a, b = gyrocompass(2.0, S, 0.3), gyrocompass(2.0, -S, 0.3)
    assert b.settles_to == "south" and b.period == pytest.approx(a.period, rel=1e-15)
    # at a pole there is no directive torque: no period, no direction, no NaN
    pole = gyrocompass(2.0, S, math.pi / 2)
    assert pole.period is None and pole.settles_to is None
    json.dumps(pole.to_json(), allow_nan=False)
    with pytest.raises(ValueError):
        gyrocompass(2.0, 0.0, 0.3)
    with pytest.raises(ValueError):
        gyrocompass(2.0, S, 2.0)
    with pytest.raises(ValueError):
        gyrocompass(-1.0, S, 0.3)
