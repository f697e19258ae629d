"""rbcli.core.whirl against independent oracles.

- closed forms (physics sheet whirl.md): a symmetric rotor on identical isotropic
  bearings, cylindrical w^2 = sum k / m, conical It w^2 -/+ Ip W w - sum k a^2 = 0 (both
  whirls), its critical speeds sum k / m and sum k a^2 / (It -/+ Ip), no forward conical
  critical speed when Ip >= It;
- the sheet's two worked examples, to their printed digits;
- an eigen-solve of the second-order system written out here from the equations of
  motion (the 4x4 matrices entry by entry, not the core's), through scipy.linalg.eig of
  the generalized companion pencil;
- the rigid-support limit (bearing forces -> rbcli.core.balance's rigid-bearing forces;
  critical speeds scale as sqrt(k));
- a damped single-mass rotor's response peak, half-power points and amplification
  factor in closed form;
- the API 617 / 684 margin rule at its breakpoints.
"""

from __future__ import annotations

import cmath
import math

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from rbcli.core import whirl as W
from rbcli.core.whirl.stability import stability
from rbcli.core.whirl.response import amplitude, amplitude_slope

# Eigenvalues of a 4x4 / 8x8 companion matrix carry round-off of order eps * |A| relative to
# |lambda|; with the physical ranges drawn below (frequencies within ~1e3 of each other) that
# is ~1e-13, so 1e-9 has four orders of room and still catches any wrong term (a wrong sign of
# Ip Omega moves a frequency by Ip Omega / It, >= 1e-3 relative here).
RTOL = 1e-9


def sym_rotor(m, It, Ip, k, a, c=0.0):
    return W.Rotor(m, It, Ip, 0.0, (W.Bearing(-a, k, k, cxx=c, cyy=c), W.Bearing(a, k, k, cxx=c, cyy=c)))


def conical_closed(It, Ip, Om, kappa):
    """Positive roots of It w^2 - s Ip Om w - kappa = 0: (forward, backward)."""
    fwd = (Ip * Om + math.sqrt((Ip * Om) ** 2 + 4 * It * kappa)) / (2 * It)
    bwd = (-Ip * Om + math.sqrt((Ip * Om) ** 2 + 4 * It * kappa)) / (2 * It)
    return fwd, bwd


rotors = st.fixed_dictionaries({
    "m": st.floats(1.0, 1e3), "It": st.floats(0.01, 50.0), "ratio": st.floats(0.0, 3.0),
    "k": st.floats(1e4, 1e9), "a": st.floats(0.02, 1.0), "Om": st.floats(0.0, 2000.0),
})


@settings(max_examples=80, deadline=None)
@given(rotors)
def test_symmetric_rotor_frequencies_are_the_closed_forms(p):
    m, It, k, a, Om = p["m"], p["It"], p["k"], p["a"], p["Om"]
    Ip = p["ratio"] * It
    modes = W.modes_at(sym_rotor(m, It, Ip, k, a), Om)
    cyl = math.sqrt(2 * k / m)
    fwd, bwd = conical_closed(It, Ip, Om, 2 * k * a * a)
    got = {(md.whirl, md.shape.kind): md.frequency for md in modes}
    assert got[("forward", "cylindrical")] == pytest.approx(cyl, rel=RTOL)
    assert got[("backward", "cylindrical")] == pytest.approx(cyl, rel=RTOL)
    assert got[("forward", "conical")] == pytest.approx(fwd, rel=RTOL)
    assert got[("backward", "conical")] == pytest.approx(bwd, rel=RTOL)
    for md in modes:  # undamped, no cross-coupling: neutrally stable, exactly
        assert md.eigenvalue.real == 0.0 and md.damping_ratio == 0.0 and not md.growing
        if md.shape.kind == "conical":
            assert md.shape.node == pytest.approx(0.0, abs=1e-12 * a)  # the node at the com
        else:
            assert md.shape.node is None  # pure translation


@settings(max_examples=80, deadline=None)
@given(rotors)
def test_symmetric_rotor_critical_speeds_are_the_closed_forms(p):
    m, It, k, a = p["m"], p["It"], p["k"], p["a"]
    Ip = p["ratio"] * It
    crits, missing = W.critical_speeds(sym_rotor(m, It, Ip, k, a), (1,))
    kappa = 2 * k * a * a
    want = [("forward", "cylindrical", math.sqrt(2 * k / m)), ("backward", "cylindrical", math.sqrt(2 * k / m)),
            ("backward", "conical", math.sqrt(kappa / (It + Ip)))]
    if It > Ip:
        want.append(("forward", "conical", math.sqrt(kappa / (It - Ip))))
    else:  # a disk-like rotor: the forward conical whirl never meets 1x (Ip = It: only at infinity)
        reason = "coincident" if Ip == It else "gyroscopic"
        assert [(x.whirl, x.kind, x.reason) for x in missing] == [("forward", "conical", reason)]
    assert len(crits) == len(want)
    for whirl, kind, speed in want:
        hits = [c for c in crits if c.whirl == whirl and c.shape.kind == kind]
        assert len(hits) == 1 and hits[0].speed == pytest.approx(speed, rel=RTOL)
        # and the whirl frequency of that mode at that speed is the speed (a 1x crossing)
        f = [md.frequency for md in W.modes_at(sym_rotor(m, It, Ip, k, a), speed)
             if md.whirl == whirl and md.shape.kind == kind]
        assert f and min(abs(x - speed) for x in f) <= RTOL * speed


def test_the_sheets_worked_examples_to_their_printed_digits():
    # solid cylinder r = 0.1 m, L = 0.6 m, 50 kg on bearings at +-0.2 m, 1e6 N/m each
    m, r, L = 50.0, 0.1, 0.6
    It, Ip = m * (3 * r * r + L * L) / 12, m * r * r / 2
    assert (It, Ip) == (pytest.approx(1.625), pytest.approx(0.25))
    crits, missing = W.critical_speeds(sym_rotor(m, It, Ip, 1e6, 0.2))
    got = sorted((round(c.speed, 3), c.shape.kind, c.whirl) for c in crits)
    assert got == [(200.0, "cylindrical", "backward"), (200.0, "cylindrical", "forward"),
                   (206.559, "conical", "backward"), (241.209, "conical", "forward")]
    assert missing == []
    # disk r = 0.3 m, L = 0.05 m, 100 kg on bearings at +-0.1 m, 2e6 N/m: Ip = 4.5 > It
    m, r, L = 100.0, 0.3, 0.05
    It, Ip = m * (3 * r * r + L * L) / 12, m * r * r / 2
    crits, missing = W.critical_speeds(sym_rotor(m, It, Ip, 2e6, 0.1))
    got = sorted({(float(f"{c.speed:.6g}"), c.shape.kind, c.whirl) for c in crits})
    assert got == [(76.8615, "conical", "backward"), (200.0, "cylindrical", "backward"),
                   (200.0, "cylindrical", "forward")]
    assert [(x.whirl, x.kind, x.reason) for x in missing] == [("forward", "conical", "gyroscopic")]


def test_a_tiny_rotor_has_the_shapes_of_a_normal_one():
    """A rotor of 1e-300 kg (its moments likewise) is the 1 kg rotor whirling 1e150 times
    faster: the same unit shapes and the same mode following. Its eigenvectors' entries
    (~1/|lambda|) times sqrt(m) once underflowed to zero shapes, so no step of the Campbell
    diagram was clear and every one was halved 12 levels deep (2^12 eigen-solves a step)."""
    a = W.Rotor(1.0, 0.3, 0.1, 0.0, (W.Bearing(-0.2, 1e6, 1e6), W.Bearing(0.3, 1e6, 1e6)))
    b = W.Rotor(1e-300, 0.3e-300, 0.1e-300, 0.0, a.bearings)
    ca, cb = W.campbell(a, np.linspace(0, 4e3, 9)), W.campbell(b, np.linspace(0, 4e153, 9))
    assert np.allclose(np.linalg.norm(cb.vectors, axis=-1), 1.0, rtol=1e-12)  # unit shapes
    # round-off of two eigen-solves of matrices that differ by scale only: ~1e-15
    assert np.allclose(abs(cb.vectors), abs(ca.vectors), atol=1e-9)
    assert (cb.whirl == ca.whirl).all() and (cb.kind == ca.kind).all()
    assert (W.track(cb) == W.track(ca)).all()


@pytest.mark.parametrize("gap", [1e-7, 1e-6])
def test_bearings_almost_at_one_point_are_not_unstable(gap):
    """Bearings 0.1-1 um apart leave a nearly free pivot: a root of |lambda| ~1e-9 whose real
    part (~1e-16 to 1e-14 of the largest |lambda|) is the eigen-solve's round-off. Positive
    stiffness and damping with a skew gyroscopic matrix cannot make a mode grow; its sign
    once read as growth (damping ratio -1, "UNSTABLE ... cross-coupled stiffness")."""
    b = (W.Bearing(-0.3, 1e6, 1e6, cxx=100.0, cyy=100.0), W.Bearing(-0.3 + gap, 1e6, 1e6, cxx=100.0, cyy=100.0))
    rotor = W.Rotor(50.0, 50 * (3 * 0.1**2 + 0.6**2) / 12, 0.5 * 50 * 0.1**2, 0.0, b)
    cb = W.campbell(rotor, np.linspace(0.0, 1000.0, 201))
    st = stability(cb, W.track(cb))
    assert not cb.growing.any() and cb.damping_ratio.min() >= 0.0
    assert st.threshold is None and not st.thresholds


def test_orders_and_coincident_inertia():
    # order 2: B = diag(4m, 4It -/+ 2Ip); Ip = 2 It exactly: the 2x forward conical crossing is
    # at infinity ("coincident"), and 1x has none ("gyroscopic")
    m, It, k, a = 20.0, 0.5, 1e6, 0.3
    crits, missing = W.critical_speeds(sym_rotor(m, It, 2 * It, k, a), (1, 2))
    kinds = {(c.order, c.whirl, c.shape.kind) for c in crits}
    assert (2, "forward", "conical") not in kinds and (1, "forward", "conical") not in kinds
    assert {(x.order, x.reason) for x in missing} == {(1, "gyroscopic"), (2, "coincident")}
    two = [c for c in crits if c.order == 2 and c.shape.kind == "cylindrical"]
    assert two[0].speed == pytest.approx(math.sqrt(2 * k / m) / 2, rel=RTOL)
    bk = [c for c in crits if c.order == 2 and c.whirl == "backward" and c.shape.kind == "conical"]
    assert bk[0].speed == pytest.approx(math.sqrt(2 * k * a * a / (4 * It + 2 * 2 * It)), rel=RTOL)


# --------------------------------------------------------------------- an independent eigen-solve


def matrices_by_hand(m, It, Ip, z_G, bearings):
    """M, C, G, K of q = (x, y, theta_x, theta_y) written out entry by entry from the
    equations of motion (the bearing i at a = z_i - z_G moves by d_x = x + a theta_y,
    d_y = y - a theta_x; Euler: It theta_x'' + Ip W theta_y' = M_x, It theta_y'' - Ip W
    theta_x' = M_y, with M_x = -a F_y, M_y = a F_x)."""
    M = np.diag([m, m, It, It])
    K = np.zeros((4, 4))
    C = np.zeros((4, 4))
    for (z, kxx, kyy, kxy, kyx, cxx, cyy) in bearings:
        a = z - z_G
        K += np.array([[kxx, kxy, -a * kxy, a * kxx],
                       [kyx, kyy, -a * kyy, a * kyx],
                       [-a * kyx, -a * kyy, a * a * kyy, -a * a * kyx],
                       [a * kxx, a * kxy, -a * a * kxy, a * a * kxx]])
        C += np.array([[cxx, 0, 0, a * cxx], [0, cyy, -a * cyy, 0],
                       [0, -a * cyy, a * a * cyy, 0], [a * cxx, 0, 0, a * a * cxx]])
    G = np.array([[0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, Ip], [0, 0, -Ip, 0]], dtype=float)
    return M, C, G, K


def eig_by_scipy(M, C, G, K, Om):
    """Eigenvalues of the second-order system in mass-normalised first-order form
    (q = M^-1/2 p): [[0, I], [-S K S, -S (C + Om G) S]], S = M^-1/2, by scipy.linalg.eig
    (LAPACK geev with balancing). (The unnormalised pencil [[0, I], [-K, -(C + Om G)]] -
    lambda diag(I, M) through QZ loses ~1e-9 on the near-double roots of an isotropic
    rotor with cross-coupling: 1591.23009617 for the exact 1591.23009810303.)"""
    import scipy.linalg

    n = M.shape[0]
    S = np.diag(1.0 / np.sqrt(np.diag(M)))
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-S @ K @ S, -S @ (C + Om * G) @ S]])
    return scipy.linalg.eig(A, right=False)


general = st.fixed_dictionaries({
    "m": st.floats(5.0, 500.0), "It": st.floats(0.1, 20.0), "ratio": st.floats(0.0, 2.5),
    "zG": st.floats(-0.3, 0.3), "z1": st.floats(-0.8, -0.1), "z2": st.floats(0.1, 0.8),
    "k": st.lists(st.floats(1e5, 1e8), min_size=4, max_size=4),
    "q": st.floats(-0.3, 0.3), "c": st.lists(st.floats(0.0, 3e3), min_size=2, max_size=2),
    "aniso": st.booleans(), "Om": st.floats(0.0, 1500.0),
})


@settings(max_examples=80, deadline=None)
@given(general)
# an overdamped pair at rest (one bearing heavily damped): its roots are real; the eigen-solve's
# 1e-12 imaginary round-off is not a whirl (hypothesis found it)
@example({"m": 5.0, "It": 1.0, "ratio": 0.0, "zG": 0.0, "z1": -0.5, "z2": 0.5, "k": [1e5] * 4,
          "q": 0.0, "c": [0.0, 946.0], "aniso": False, "Om": 0.0})
@example({"m": 5.0, "It": 3.0, "ratio": 0.0, "zG": 0.0, "z1": -0.5, "z2": 0.1,
          "k": [74572153.0, 1e5, 1e5, 1e5], "q": 1e-8, "c": [0.0, 0.0], "aniso": False, "Om": 0.0})
def test_modes_agree_with_an_eigensolve_of_the_matrices_written_here(p):
    k1x, k1y, k2x, k2y = p["k"]
    if not p["aniso"]:
        k1y, k2y = k1x, k2x
    q = p["q"] * min(k1x, k2x)  # cross-coupling up to 30 % of the direct stiffness
    c1, c2 = p["c"]
    Ip = p["ratio"] * p["It"]
    brg = [(p["z1"], k1x, k1y, q, -q, c1, c1), (p["z2"], k2x, k2y, q, -q, c2, c2)]
    rotor = W.Rotor(p["m"], p["It"], Ip, p["zG"], tuple(W.Bearing(*b) for b in brg))
    lam = eig_by_scipy(*matrices_by_hand(p["m"], p["It"], Ip, p["zG"], brg), p["Om"])
    scale = float(np.max(np.abs(lam)))
    modes = W.modes_at(rotor, p["Om"])
    # every mode's eigenvalue is one of the pencil's (with its conjugate: real coordinates)
    for md in modes:
        lam_md = md.eigenvalue
        cands = np.concatenate([lam, np.conj(lam)])
        assert float(np.min(np.abs(cands - lam_md))) <= RTOL * scale
    # and the frequencies, sorted, are the pencil's |Im| of the roots with Im >= 0 (real
    # coordinates; each conjugate pair once)
    osc = sorted(abs(x.imag) for x in lam if x.imag > 1e-12 * scale)
    got = sorted(md.frequency for md in modes if md.frequency > 0.0)
    assert len(got) == len(osc)
    np.testing.assert_allclose(got, osc, rtol=0, atol=RTOL * scale)
    # a growing mode is one the eigen-solve says grows (judged where it is clear: a growth
    # rate within a decade of the threshold, Re lambda > 1e-9 |lambda| of that root, is the
    # threshold's business). Each root against its own |lambda|, as modes.Mode.growing does:
    # against the largest root's, a slow mode's growth (undamped, cross-coupled: Re 4.6e-7 at
    # |lambda| 92, beside a 4 598 rad/s mode) read as 1e-10 and "clearly stable" (hypothesis)
    top = float(np.max(lam.real / np.abs(lam)))
    if top > 1e-8 or top < 1e-10:
        assert any(md.growing for md in modes) == (top > 1e-8)


def test_critical_speeds_cross_the_line_in_the_independent_solve():
    """Anisotropic, coupled (sum k a != 0): at each undamped critical speed the pencil built
    here has a root at i n Omega."""
    brg = [(-0.25, 2e6, 3e6, 0.0, 0.0, 0.0, 0.0), (0.4, 1.5e6, 1.1e6, 0.0, 0.0, 0.0, 0.0)]
    m, It, Ip, zG = 40.0, 1.2, 0.5, 0.05
    rotor = W.Rotor(m, It, Ip, zG, tuple(W.Bearing(*b) for b in brg))
    crits, _ = W.critical_speeds(rotor, (1, 2))
    assert len(crits) == 8  # It > 2 Ip: every branch crosses both lines
    mats = matrices_by_hand(m, It, Ip, zG, brg)
    for c in crits:
        lam = eig_by_scipy(*mats, c.speed)
        assert float(np.min(np.abs(lam - 1j * c.order * c.speed))) <= RTOL * c.order * c.speed


# --------------------------------------------------------------------- damped crossings, stability


def test_damped_crossing_is_a_root_of_the_damped_frequency():
    rotor = sym_rotor(50.0, 1.625, 0.25, 1e6, 0.2, c=800.0)
    crits, _ = W.critical_speeds(rotor)
    for c in crits:
        x, md = W.damped_crossing(rotor, c)
        # the damped frequency of that mode equals the speed there (Brent: to ~1e-12)
        assert md.frequency == pytest.approx(x, rel=1e-11)
        assert md.whirl == c.whirl and md.shape.kind == c.shape.kind
    # cylindrical mode: translation alone, m x'' + 2c x' + 2k x = 0, frequency independent
    # of speed: wd = wn sqrt(1 - zeta^2), zeta = 2c / (2 sqrt(2k m))
    wn, zeta = math.sqrt(2e6 / 50.0), 1600.0 / (2 * math.sqrt(2e6 * 50.0))
    cyl = [W.damped_crossing(rotor, c)[0] for c in crits if c.shape.kind == "cylindrical"]
    assert cyl == [pytest.approx(wn * math.sqrt(1 - zeta**2), rel=1e-11)] * 2


def test_cross_coupling_destabilises_the_forward_mode():
    """A follower (cross-coupled) stiffness q with no damping: the complex reduction's
    cylindrical mode has lambda^2 m + 2(k - i q) = 0, so lambda = i sqrt(2(k - iq)/m): the
    forward root grows at Re = Im(sqrt(...)) > 0 for q > 0."""
    m, k, q = 10.0, 1e6, 5e4
    rotor = W.Rotor(m, 0.2, 0.05, 0.0, (W.Bearing(-0.2, k, k, q, -q), W.Bearing(0.2, k, k, q, -q)))
    lam = 1j * cmath.sqrt(2 * (k - 1j * q) / m)
    modes = W.modes_at(rotor, 0.0)
    fwd = [md for md in modes if md.whirl == "forward" and md.shape.kind == "cylindrical"][0]
    assert fwd.eigenvalue == pytest.approx(lam, rel=RTOL)
    assert fwd.growing and fwd.damping_ratio < 0
    bwd = [md for md in modes if md.whirl == "backward" and md.shape.kind == "cylindrical"][0]
    assert not bwd.growing


def test_onset_speed_of_instability_is_a_root():
    """Cross-coupling q and damping c at both bearings (symmetric, a = +-0.2 m): the forward
    conical mode obeys It l^2 + (2 c a^2 - i Ip W) l + 2 a^2 (k - i q) = 0. At the threshold
    l = i w: the imaginary part gives w = q / c, the real part -It w^2 + Ip W w + 2 a^2 k = 0,
    so W_th = (It w^2 - 2 a^2 k) / (Ip w): unstable below (the frequency is too low for the
    damping to beat the cross-coupling), stable above (gyroscopic stiffening raises it).
    The cylindrical mode (threshold q = c sqrt(2k/m)) stays stable."""
    m, It, Ip, k, a, c = 2.0, 0.2, 0.3, 1e6, 0.2, 200.0
    w0 = math.sqrt(2 * a * a * k / It)
    q = 1.2 * w0 * c
    assert q < c * math.sqrt(2 * k / m)
    rotor = W.Rotor(m, It, Ip, 0.0, (W.Bearing(-a, k, k, q, -q, c, c), W.Bearing(a, k, k, q, -q, c, c)))
    w = q / c
    W_th = (It * w * w - 2 * a * a * k) / (Ip * w)
    for n in (51, 7, 400):  # the threshold does not move with the grid
        cb = W.campbell(rotor, np.linspace(0.0, 1000.0, n))
        st = stability(cb, W.track(cb))
        assert len(st.thresholds) == 1
        t = st.thresholds[0]
        assert t.speed == pytest.approx(W_th, rel=RTOL)  # Brent on Re(lambda): ~1e-14
        assert t.change == "recovery" and st.from_start == (t.branch,) and st.threshold == 0.0
        assert t.mode.whirl == "forward" and t.mode.shape.kind == "conical"
        assert st.growing(0.0, 0.9 * W_th) and st.growing(0.99 * W_th, 2 * W_th)
        assert not st.growing(1.01 * W_th, 1000.0)


# --------------------------------------------------------------------- response


def test_damped_single_mass_response_peak_half_power_and_af():
    """Static unbalance U on a symmetric rotor drives the translation alone:
    m x'' + 2c x' + 2k x = W^2 U cos(W t): |X| = W^2 U / sqrt((2k - m W^2)^2 + (2 c W)^2).
    With r = W/wn, zeta = 2c/(2 sqrt(2k m)): peak at r^2 = 1/(1 - 2 zeta^2), |X|/(U/m) =
    1/(2 zeta sqrt(1 - zeta^2)); half-power points from (1 - A) u^2 + 2A(1 - 2zeta^2) u - A = 0
    (u = r^2, A = peak^2/2 in units of U/m)."""
    m, k, c, U = 30.0, 2e6, 400.0, 2e-3
    rotor = W.Rotor(m, 0.8, 0.3, 0.0, (W.Bearing(-0.3, k, k, cxx=c, cyy=c), W.Bearing(0.3, k, k, cxx=c, cyy=c)))
    forcing = W.Forcing(complex(U, 0.0), 0j)
    wn = math.sqrt(2 * k / m)
    zeta = 2 * c / (2 * math.sqrt(2 * k * m))
    Nc = wn / math.sqrt(1 - 2 * zeta**2)
    peak = (U / m) / (2 * zeta * math.sqrt(1 - zeta**2))
    A = (peak / (U / m)) ** 2 / 2
    a2, b2, c2 = 1 - A, 2 * A * (1 - 2 * zeta**2), -A
    us = sorted(((-b2 + s * math.sqrt(b2 * b2 - 4 * a2 * c2)) / (2 * a2)) for s in (1, -1))
    N1, N2 = (wn * math.sqrt(u) for u in us if u > 0)
    res = W.response(rotor, forcing, np.linspace(0.0, 2 * wn, 101))
    # the response itself, at every grid speed, both bearings (the translation)
    Ws = np.asarray(res.speeds)
    want = Ws**2 * U / np.sqrt((2 * k - m * Ws**2) ** 2 + (2 * c * Ws) ** 2)
    for i in range(2):
        np.testing.assert_allclose(res.displacement[i], want, rtol=1e-12)
        # isotropic bearings: circular orbits, semi-minor axis = semi-major axis
        np.testing.assert_allclose(res.displacement_minor[i], want, rtol=1e-12)
    pk = W.peaks(rotor, forcing, res)
    assert len(pk) == 2
    for p in pk:
        # the peak is the root of the exact slope: to ~1e-15; the closed forms to round-off
        assert p.speed == pytest.approx(Nc, rel=RTOL)
        assert p.amplitude == pytest.approx(peak, rel=RTOL)
        assert p.half_power[0] == pytest.approx(N1, rel=RTOL)
        assert p.half_power[1] == pytest.approx(N2, rel=RTOL)
        assert p.amplification_factor == pytest.approx(Nc / (N2 - N1), rel=RTOL)


@pytest.mark.parametrize("scale", [1e-300, 1e290])
def test_peaks_of_a_tiny_or_huge_unbalance_scale_with_it(scale):
    """The response is linear in the unbalance: U times 2^k (exact) gives the same peak
    speeds, half-power points and AF, the amplitudes times 2^k. With U = 1e-300 kg m the
    half-power root solve's products of amplitudes (~1e-300 each) underflowed to 0 and
    divided by it (ZeroDivisionError: exit 2, 'the result overflows')."""
    rotor = W.Rotor(30.0, 0.8, 0.3, 0.05, (W.Bearing(-0.3, 2e6, 2e6, cxx=400.0, cyy=400.0),
                                          W.Bearing(0.3, 2e6, 2e6, cxx=400.0, cyy=400.0)))
    s = 2.0 ** math.floor(math.log2(scale))
    one, big = W.Forcing(2e-3 + 1e-3j, 1e-4j), W.Forcing(s * (2e-3 + 1e-3j), s * 1e-4j)
    speeds = np.linspace(0.0, 800.0, 41)
    want = W.peaks(rotor, one, W.response(rotor, one, speeds))
    got = W.peaks(rotor, big, W.response(rotor, big, speeds))
    assert len(want) == 2 and [(p.speed, p.half_power, p.amplification_factor) for p in got] == \
        [(p.speed, p.half_power, p.amplification_factor) for p in want]
    assert [p.amplitude for p in got] == [s * p.amplitude for p in want]


def test_amplitude_slope_is_the_derivative():
    rotor = W.Rotor(30.0, 0.8, 0.5, 0.1, (W.Bearing(-0.3, 2e6, 3e6, 1e4, -1e4, 300.0, 500.0),
                                         W.Bearing(0.35, 1e6, 1e6, 0, 0, 200.0, 200.0)))
    forcing = W.Forcing(complex(1e-3, 2e-3), complex(-3e-4, 1e-4))
    def central(x, h):
        return (amplitude(rotor, forcing, 0, x + h) - amplitude(rotor, forcing, 0, x - h)) / (2 * h)

    for x in (50.0, 200.0, 333.0, 600.0):
        # Richardson-extrapolated central differences: truncation O(h^4) ~ 1e-12 relative at
        # h = 1e-3 x (resonances here are ~10 % wide), round-off eps A / h ~ 1e-13 relative
        h = 1e-3 * x
        fd = (4 * central(x, h / 2) - central(x, h)) / 3
        assert amplitude_slope(rotor, forcing, 0, x)[1] == pytest.approx(fd, rel=1e-8)


def test_isotropic_response_is_the_complex_closed_form_and_forward_circular():
    """Isotropic bearings: the directional 2x2 system (K_c - W^2 diag(m, It - Ip) + i W C_c)
    [r, phi] = W^2 [U, P_G], written here, gives circular forward orbits r + a phi."""
    m, It, Ip, zG = 25.0, 0.9, 0.4, 0.07
    brg = [(-0.2, 1.2e6, 150.0), (0.3, 0.8e6, 90.0)]
    rotor = W.Rotor(m, It, Ip, zG, tuple(W.Bearing(z, k, k, cxx=c, cyy=c) for z, k, c in brg))
    U, P = cmath.rect(2e-3, 0.3), cmath.rect(4e-4, 2.1)
    speeds = np.linspace(10.0, 600.0, 60)
    res = W.response(rotor, W.Forcing(U, P), speeds)
    for j, Om in enumerate(speeds):
        Z = np.zeros((2, 2), dtype=complex)
        for z, k, c in brg:
            a = z - zG
            Z += (k + 1j * Om * c) * np.array([[1, a], [a, a * a]])
        Z -= Om**2 * np.diag([m, It - Ip])
        r, phi = np.linalg.solve(Z, Om**2 * np.array([U, P]))
        for i, (z, k, c) in enumerate(brg):
            d = r + (z - zG) * phi
            assert res.displacement[i][j] == pytest.approx(abs(d), rel=1e-10)
            assert res.displacement_minor[i][j] == pytest.approx(abs(d), rel=1e-10)  # a circle
            assert res.force[i][j] == pytest.approx(abs((k + 1j * Om * c) * d), rel=1e-10)
            dphase = (res.displacement_phase_deg[i][j] - math.degrees(cmath.phase(d))) % 360.0
            assert min(dphase, 360.0 - dphase) <= 1e-8


@pytest.mark.parametrize("k", [1e10, 1e12, 1e14])
def test_rigid_support_limit_forces_and_critical_speeds(k):
    """As k grows the bearing forces tend to balance's rigid-bearing forces, the error
    shrinking like m W^2 / k; critical speeds scale as sqrt(k)."""
    from rbcli.core import balance as B

    m, It, Ip, zG = 40.0, 1.5, 0.6, 0.12
    z1, z2 = -0.2, 0.45
    rotor = W.Rotor(m, It, Ip, zG, (W.Bearing(z1, k, k), W.Bearing(z2, k, k)))
    U, PG = cmath.rect(3e-3, 0.7), cmath.rect(5e-4, -1.1)
    Om = 300.0
    res = W.response(rotor, W.Forcing(U, PG), np.array([Om]))
    rigid = [abs(u) * Om**2 for u in B.plane_unbalances(U, PG + zG * U, z1, z2)]
    for i in range(2):
        assert abs(res.force[i][0] / rigid[i] - 1.0) <= 10 * m * Om**2 / k + 1e-12
    c1, _ = W.critical_speeds(rotor)
    c4, _ = W.critical_speeds(W.Rotor(m, It, Ip, zG, (W.Bearing(z1, 4 * k, 4 * k), W.Bearing(z2, 4 * k, 4 * k))))
    np.testing.assert_allclose([c.speed for c in c4], [2 * c.speed for c in c1], rtol=RTOL)


def test_backward_modes_are_not_driven_on_isotropic_bearings():
    from rbcli.core.whirl.response import EXCITED_RTOL, excitation

    rotor = W.Rotor(40.0, 1.5, 0.6, 0.12, (W.Bearing(-0.2, 1e6, 1e6), W.Bearing(0.45, 2e6, 2e6)))
    forcing = W.Forcing(complex(1e-3, 0), complex(0, 2e-4))
    crits, _ = W.critical_speeds(rotor)
    for c in crits:
        e = excitation(rotor, forcing, c.speed, c.eigenvalue, c.whirl)
        assert (e > EXCITED_RTOL) == (c.whirl == "forward"), (c.whirl, e)
    # a pure static unbalance on a symmetric rotor does not drive the conical modes
    sym = sym_rotor(50.0, 1.625, 0.25, 1e6, 0.2)
    for c in W.critical_speeds(sym)[0]:
        e = excitation(sym, W.Forcing(1e-3 + 0j, 0j), c.speed, c.eigenvalue, c.whirl)
        assert (e > EXCITED_RTOL) == (c.whirl == "forward" and c.shape.kind == "cylindrical")


# --------------------------------------------------------------------- the API rule


@pytest.mark.parametrize("af, below, above", [
    (1.0, 0.0, 0.0), (2.49, 0.0, 0.0),
    (2.5, 0.0, 10.0),  # 17 (1 - 1/1) = 0: the rule is continuous at 2.5
    (3.5, 8.5, 18.5),  # 17 (1 - 1/2)
    (11.5, 15.3, 25.3),  # 17 (1 - 1/10)
    (100.0, 16.0, 26.0),  # capped
    (None, 16.0, 26.0),  # undamped: AF infinite
])
def test_api_required_margin(af, below, above):
    assert W.required_margin(af, "below") == pytest.approx(below, abs=1e-12)
    assert W.required_margin(af, "above") == pytest.approx(above, abs=1e-12)


def test_api_margin_positions():
    ok = W.margin(100.0, 3.5, 120.0, 150.0)  # 16.7 % below 120 > 8.5 % required
    assert (ok.position, ok.passed) == ("below", True)
    assert ok.margin_percent == pytest.approx(100.0 * 20.0 / 120.0)
    bad = W.margin(160.0, 11.5, 120.0, 150.0)  # 6.7 % above 150 < 25.3 %
    assert (bad.position, bad.passed) == ("above", False)
    inside = W.margin(130.0, 3.0, 120.0, 150.0)
    assert (inside.position, inside.passed) == ("within", False)
    assert W.margin(130.0, 2.0, 120.0, 150.0).passed  # AF < 2.5: critically damped, no margin
