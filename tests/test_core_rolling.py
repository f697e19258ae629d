"""Tests of rbcli.core.rolling (the physics of ``rbcli rollcheck``).

Expected values come from the physics sheet (dynamics.md §3 and test cases R1-R9), from
closed forms derived independently here (thin disk, hoop, solid cylinder, Euler's disk,
the large-radius identity), and from two independent oracles:

* the full nonlinear vector equations of motion of a rolling body of revolution with a
  toroidal rim (Newton-Euler about G with the contact force eliminated, re-derived below),
  integrated with scipy's DOP853;
* the reduced knife-edge Euler-angle equations (sheet §3.1, equal term by term to PyDy's
  Kane-method rolling disc for a thin disk), linearised by central finite differences.
"""

from __future__ import annotations

import json
import math
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rbcli.core import rolling as R
from rbcli.errors import InputError
from rbcli.core.rollcircle import CircleMotion, circle, lean_for, radius_for, stability_map
from rbcli.core.rolling import (
    StraightRolling,
    Verdict,
    at_speed,
    rollcheck,
    straight,
)
from rbcli.core.wheel import Wheel, wheel_from_body

G981 = 9.81  # the sheet's g unless stated ("Use 9.81 unless stated")


def sheet(text: str) -> object:
    """A value quoted on the sheet to 6 significant figures: it is exact only to half a
    unit in its last quoted digit, so that is the tolerance (plus 1e-12 relative for the
    float conversion)."""
    decimals = len(text.split(".")[1]) if "." in text else 0
    x = float(text)
    return pytest.approx(x, abs=0.5 * 10.0 ** (-decimals) * (1 + 1e-9), rel=1e-12)


def thin_disk(a: float, m: float = 1.0) -> Wheel:
    return Wheel(mass=m, A=m * a * a / 4, C=m * a * a / 2)


def hoop(a: float, m: float = 1.0) -> Wheel:
    return Wheel(mass=m, A=m * a * a / 2, C=m * a * a)


# --------------------------------------------------------------------------- oracles


Z = np.array([0.0, 0.0, 1.0])


def vector_rhs(m: float, A: float, C: float, a: float, r: float, g: float):
    """Full nonlinear rolling equations, state y = (n, w, x_G) in the world frame.

    Derivation (sheet §3.1, re-derived): the contact point P of a toroidal rim (tube
    radius r, tube-centre circle of radius a - r about G) is ρ below G with
    ρ = G - P = (a - r) u + r z, u = in-plane up unit vector. Rolling: v_G = w x ρ.
    Newton m a_G = F - m g z; Euler about G d(Jw)/dt = J w' + w x J w = -ρ x F.
    Eliminating F with a_G = w' x ρ + w x ρ' gives
    [J + m(|ρ|^2 1 - ρ ρ^T)] w' = m ρ x (-g z) - w x J w - m ρ x (w x ρ').
    """

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        n = y[0:3] / np.linalg.norm(y[0:3])
        w = y[3:6]
        p = Z - n[2] * n
        pn = np.linalg.norm(p)
        u = p / pn
        rho = (a - r) * u + r * Z
        J = A * np.eye(3) + (C - A) * np.outer(n, n)
        ndot = np.cross(w, n)
        pdot = -ndot[2] * n - n[2] * ndot
        udot = (pdot - u * (u @ pdot)) / pn
        rhodot = (a - r) * udot
        M = J + m * ((rho @ rho) * np.eye(3) - np.outer(rho, rho))
        b = (
            m * np.cross(rho, -g * Z)
            - np.cross(w, J @ w)
            - m * np.cross(rho, np.cross(w, rhodot))
        )
        wdot = np.linalg.solve(M, b)
        return np.concatenate([ndot, wdot, np.cross(w, rho)])

    return rhs


def vector_energy(y: np.ndarray, m: float, A: float, C: float, a: float, r: float, g: float):
    n = y[0:3] / np.linalg.norm(y[0:3])
    w = y[3:6]
    u = (Z - n[2] * n) / np.linalg.norm(Z - n[2] * n)
    rho = (a - r) * u + r * Z
    J = A * np.eye(3) + (C - A) * np.outer(n, n)
    vG = np.cross(w, rho)
    return 0.5 * m * vG @ vG + 0.5 * w @ J @ w + m * g * rho[2]


def lean_of(y: np.ndarray) -> float:
    n = y[0:3] / np.linalg.norm(y[0:3])
    return math.asin(n[2])


def straight_start(s: float, a: float, r: float, theta0: float) -> np.ndarray:
    """Upright rolling along +x at spin s (axle +y, w = s y gives v_G = w x a z = a s x),
    then the axle tilted by theta0 about the heading, w kept a pure spin about it."""
    n = np.array([0.0, math.cos(theta0), math.sin(theta0)])
    w = s * n
    return np.concatenate([n, w, [0.0, 0.0, a]])


def reduced_rhs(m: float, A: float, C: float, a: float, g: float):
    """Sheet §3.1 reduced knife-edge equations, state (theta, theta', phi', omega3)."""

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        th, thd, phd, w3 = y
        s, c = math.sin(th), math.cos(th)
        thdd = (-A * phd**2 * s * c + (C + m * a * a) * phd * w3 * c + m * g * a * s) / (
            A + m * a * a
        )
        phdd = thd * (2 * A * phd * s - C * w3) / (A * c)
        w3d = -m * a * a * phd * thd * c / (C + m * a * a)
        return np.array([thd, thdd, phdd, w3d])

    return rhs


def max_lean(wheel: Wheel, a: float, r: float, g: float, s: float, theta0: float,
             t_end: float, stop_at: float) -> tuple[float, float]:
    """Integrate the full equations; return (max |lean| in rad, relative energy drift).
    Stops early once |lean| exceeds 1.05 ``stop_at`` (so that the event's own location
    tolerance cannot decide a comparison with ``stop_at``)."""
    from scipy.integrate import solve_ivp

    m, A, C = wheel.mass, wheel.A, wheel.C
    rhs = vector_rhs(m, A, C, a, r, g)
    y0 = straight_start(s, a, r, theta0)

    def over(t: float, y: np.ndarray) -> float:
        return abs(lean_of(y)) - 1.05 * stop_at

    over.terminal = True  # type: ignore[attr-defined]
    sol = solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", rtol=1e-10, atol=1e-12,
                    events=over, dense_output=True)
    assert sol.status in (0, 1)
    ts = np.linspace(0.0, sol.t[-1], 4001)
    leans = np.array([abs(lean_of(sol.sol(t))) for t in ts])
    E0 = vector_energy(y0, m, A, C, a, r, g)
    E1 = vector_energy(sol.y[:, -1], m, A, C, a, r, g)
    return max(float(leans.max()), abs(lean_of(sol.y[:, -1]))), abs(E1 - E0) / abs(E0)


# --------------------------------------------------------------------------- R1-R4


@pytest.mark.parametrize(
    "a, g, s_c, v_c",
    [
        (9.525e-3, 9.81, "18.5285", "0.176484"),  # R1, US cent
        (9.525e-3, 9.80665, None, "0.176454"),  # R1 at standard gravity
        (10.16e-3, 9.81, "17.9402", "0.182272"),  # R2, UK 1p
    ],
)
def test_thin_disk_coins_R1_R2(a, g, s_c, v_c):
    st_ = straight(thin_disk(a, m=3.56e-3), a, 0.0, g)  # mass cancels; a cent's mass
    if s_c is not None:
        assert st_.critical_spin == sheet(s_c)
    assert st_.critical_speed == sheet(v_c)


@pytest.mark.parametrize(
    "a, s_c, v_c",
    [(0.35, "2.64710", "0.926485"), (0.34, None, "0.913154"), (0.30, None, "0.857759")],
)
def test_hoop_R3(a, s_c, v_c):
    st_ = straight(hoop(a, m=1.7), a, 0.0, G981)
    if s_c is not None:
        assert st_.critical_spin == sheet(s_c)
    assert st_.critical_speed == sheet(v_c)


def test_solid_cylinder_R4():
    a, h, m = 9.525e-3, 1.52e-3, 2.5e-3
    w = Wheel(m, m * (3 * a * a + h * h) / 12, m * a * a / 2)
    st_ = straight(w, a, 0.0, G981)
    assert st_.critical_spin == sheet("18.6070")
    assert st_.critical_speed == sheet("0.177232")
    ratio = st_.critical_speed / straight(thin_disk(a, m), a, 0.0, G981).critical_speed
    assert ratio == sheet("1.00424")
    # independent closed form s_c^2 = g (3a^2 + h^2)/(9 a^3); ~10 flops of round-off
    assert st_.critical_spin**2 == pytest.approx(G981 * (3 * a * a + h * h) / (9 * a**3),
                                                 rel=1e-13)


@settings(max_examples=50, deadline=None)
@given(
    a=st.floats(1e-3, 2.0),
    m=st.floats(1e-3, 1e3),
    g=st.floats(0.5, 30.0),
)
def test_thin_disk_and_hoop_limits(a, m, g):
    # s_c^2 = g/(3a) (thin disk) and g/(4a) (hoop), sheet §3.2; round-off of ~10 flops
    assert straight(thin_disk(a, m), a, 0.0, g).critical_spin ** 2 == pytest.approx(
        g / (3 * a), rel=1e-13)
    assert straight(hoop(a, m), a, 0.0, g).critical_spin ** 2 == pytest.approx(
        g / (4 * a), rel=1e-13)
    st_ = straight(hoop(a, m), a, 0.0, g)
    assert st_.critical_speed == pytest.approx(math.sqrt(g * a / 4), rel=1e-13)


@settings(max_examples=50, deadline=None)
@given(a=st.floats(1e-3, 1.0), x=st.floats(0.0, 3.0))
def test_thin_disk_lean_frequency_closed_form(a, x):
    # sheet §3.2: thin disk nu^2 = (4/5)(3 s^2 - g/a); compared on the scale of its two
    # terms (cancellation near the threshold), round-off of ~15 flops
    g = 9.81
    s = x * math.sqrt(g / (3 * a))
    v = at_speed(straight(thin_disk(a), a, 0.0, g), spin=s)
    expected = 0.8 * (3 * s * s - g / a)
    assert v.nu2 == pytest.approx(expected, abs=1e-13 * 0.8 * (3 * s * s + g / a))


# --------------------------------------------------------------------------- R7 and verdicts


def test_R7_lean_rates():
    a = 9.525e-3
    st_ = straight(thin_disk(a), a, 0.0, G981)
    up = at_speed(st_, spin=1.5 * st_.critical_spin)
    assert up.stable and up.growth_rate is None
    assert up.lean_frequency == sheet("32.0924")
    assert up.lean_frequency_hz == pytest.approx(up.lean_frequency / (2 * math.pi), rel=1e-15)
    assert up.margin == pytest.approx(1.5, rel=1e-15)  # one multiply and one divide
    down = at_speed(st_, spin=0.9 * st_.critical_spin)
    assert not down.stable and down.lean_frequency is None
    assert down.growth_rate == sheet("12.5119")


def test_verdict_speed_spin_and_direction():
    a = 0.3
    st_ = straight(hoop(a, 2.0), a, 0.0, 9.80665)
    v = 1.3 * st_.critical_speed
    by_speed = at_speed(st_, v=v)
    by_spin = at_speed(st_, spin=v / a)
    both = at_speed(st_, v=v, spin=v / a)
    back = at_speed(st_, v=-v)
    for other in (by_spin, both, back):
        # same physics, at most a few ulps apart from v/a vs a*s round trips
        assert other.nu2 == pytest.approx(by_speed.nu2, rel=1e-14)
        assert other.stable
    assert back.backwards and not by_speed.backwards
    assert back.spin == pytest.approx(-v / a, rel=1e-15)
    assert by_speed.margin == pytest.approx(1.3, rel=1e-14)
    with pytest.raises(InputError, match="disagree"):
        at_speed(st_, v=v, spin=1.01 * v / a)
    with pytest.raises(ValueError, match="speed or a spin"):
        at_speed(st_)


def test_exactly_at_threshold_is_not_stable():
    # a thin disk of radius 3/4 m in g = 9: s_c^2 = g/(3a) = 4 exactly in floats
    a = 0.75
    st_ = straight(thin_disk(a), a, 0.0, 9.0)
    assert st_.critical_spin == 2.0
    v = at_speed(st_, spin=2.0)
    assert v.nu2 == 0.0
    assert not v.stable
    assert v.growth_rate == 0.0 and v.lean_frequency is None


def test_standing_still_falls_like_a_pendulum():
    # s = 0: nu^2 = -m g (a - r)/(A + m a^2), the inverted pendulum about the contact point
    a, r, m = 0.3, 0.02, 1.5
    w = Wheel(m, 0.04, 0.07)
    v = at_speed(straight(w, a, r, 9.80665), v=0.0)
    assert v.growth_rate == pytest.approx(math.sqrt(m * 9.80665 * (a - r) / (0.04 + m * a * a)),
                                          rel=1e-14)  # round-off


def test_rounded_rim_only_weakens_gravity():
    a, r = 0.34, 0.02
    w = Wheel(1.2, 0.09, 0.13)
    s0 = straight(w, a, 0.0, 9.81).critical_spin
    s1 = straight(w, a, r, 9.81).critical_spin
    # sheet §3.2: a -> a - r in the gravity term only; round-off
    assert (s1 / s0) ** 2 == pytest.approx((a - r) / a, rel=1e-14)
    assert straight(w, a, r, 9.81).critical_speed == pytest.approx(a * s1, rel=1e-15)


@pytest.mark.parametrize("r", [0.3401, 0.5, -0.01, math.nan])
def test_bad_tyre_radius_refused(r):
    with pytest.raises(InputError, match="tyre radius"):
        straight(Wheel(1.0, 0.09, 0.13), 0.34, r)


def test_a_tyre_radius_equal_to_the_rim_radius_is_a_sphere():
    # issue 24: r = a is a sphere: no gravity lever at any lean, no critical spin
    st = straight(Wheel(1.0, 0.09, 0.13), 0.34, 0.34)
    assert st.rim == "sphere" and st.critical_spin == 0.0 and st.critical_speed == 0.0
    assert st.nu2(0.0) == 0.0 and st.nu2(2.0) > 0.0


@pytest.mark.parametrize("a, g", [(0.0, 9.81), (-1.0, 9.81), (0.3, 0.0), (0.3, -9.81),
                                  (math.inf, 9.81)])
def test_bad_radius_or_gravity_refused(a, g):
    with pytest.raises(InputError):
        straight(Wheel(1.0, 0.09, 0.13), a, 0.0, g)


# --------------------------------------------------------------------------- nonlinear threshold


@pytest.mark.parametrize(
    "name, wheel, a, r, t_end",
    [
        ("penny", thin_disk(9.525e-3, 2.5e-3), 9.525e-3, 0.0, 3.0),
        # a hub-heavy small wheel with a rounded rim: exercises A != m a^2/4 and r > 0
        ("rounded", Wheel(0.2, 0.3 * 0.2 * 0.02**2, 0.5 * 0.2 * 0.02**2), 0.02, 0.006, 4.0),
    ],
)
def test_threshold_by_full_nonlinear_equations(name, wheel, a, r, t_end):
    g = 9.81
    sc = straight(wheel, a, r, g).critical_spin
    theta0 = 1e-5
    # 2% below: a 1e-5 rad lean grows past 1 deg within a few seconds (linear growth
    # rate ~0.28 sqrt(C(C+ma^2)/(A(A+ma^2))) s_c; ~9 e-folds needed)
    lean, drift = max_lean(wheel, a, r, g, 0.98 * sc, theta0, t_end, math.radians(1.0))
    assert lean > math.radians(1.0)
    # energy is conserved by the model; DOP853 at rtol 1e-10 keeps it to ~1e-9
    assert drift < 1e-8
    # 2% above: bounded; linear theory max 2 theta0 s^2/(s^2 - s_c^2) = 0.0295 deg
    lean, drift = max_lean(wheel, a, r, g, 1.02 * sc, theta0, t_end, math.radians(1.0))
    assert lean < math.radians(0.1)
    assert drift < 1e-8


def test_R7_nonlinear_penny():
    a = 9.525e-3
    w = thin_disk(a, 2.5e-3)
    sc = straight(w, a, 0.0, G981).critical_spin
    # sheet R7: exceeds 5 deg at 0.995 s_c within 5 s; stays below 0.12 deg at 1.005 s_c
    # (sheet: 0.1148 deg; DOP853 rtol 1e-10 resolves that to far better than the 4% margin)
    lean, _ = max_lean(w, a, 0.0, G981, 0.995 * sc, 1e-5, 5.0, math.radians(5.0))
    assert lean > math.radians(5.0)
    lean, _ = max_lean(w, a, 0.0, G981, 1.005 * sc, 1e-5, 5.0, math.radians(5.0))
    assert lean < math.radians(0.12)


def test_reduced_equations_agree_with_vector_equations():
    # the oracle used for the circle's kappa below (reduced form) against the vector form,
    # in a strongly nonlinear run; both integrated at rtol 1e-11 -> agreement ~1e-9 rad
    from scipy.integrate import solve_ivp

    a, m = 0.05, 1.0
    w = Wheel(m, 0.3 * m * a * a, 0.45 * m * a * a)
    s = 1.2 * straight(w, a, 0.0, G981).critical_spin
    th0 = 0.3
    y0 = straight_start(s, a, 0.0, th0)
    t_eval = np.linspace(0.0, 1.0, 11)
    vec = solve_ivp(vector_rhs(m, w.A, w.C, a, 0.0, G981), (0, 1), y0, method="DOP853",
                    rtol=1e-11, atol=1e-13, t_eval=t_eval)
    red = solve_ivp(reduced_rhs(m, w.A, w.C, a, G981), (0, 1), [th0, 0.0, 0.0, s],
                    method="DOP853", rtol=1e-11, atol=1e-13, t_eval=t_eval)
    th_vec = np.array([lean_of(y) for y in vec.y.T])
    assert np.max(np.abs(th_vec)) > 0.3  # it really is nonlinear
    assert np.allclose(th_vec, red.y[0], atol=1e-8, rtol=0)
    # spin about the axle, omega3 = w.n, also agrees
    w3_vec = np.array([y[3:6] @ (y[0:3] / np.linalg.norm(y[0:3])) for y in vec.y.T])
    assert np.allclose(w3_vec, red.y[3], atol=1e-7 * s, rtol=0)


# --------------------------------------------------------------------------- circles


def test_R8_steady_circle_numbers():
    a = 0.05
    c = circle(thin_disk(a, 0.1), a, math.radians(20.0), 0.5, G981)
    assert isinstance(c, CircleMotion)
    assert c.turn_rate == sheet("2.17572")
    assert c.spin == sheet("21.7572")
    assert c.speed == sheet("1.08786")
    assert c.contact_radius == sheet("0.517101")
    assert c.stable and c.growth_rate is None
    assert c.lean_frequency == sheet("32.0234")
    # thin disk relation, sheet §3.3: Omega^2 = 4 g tan b/(a sin b + 6 R_G); round-off
    b = math.radians(20.0)
    assert c.turn_rate**2 == pytest.approx(4 * G981 * math.tan(b) / (a * math.sin(b) + 3.0),
                                           rel=1e-14)
    assert c.lean_deg == pytest.approx(20.0, rel=1e-15)


def circle_start(c: CircleMotion, a: float, dbeta: float = 0.0) -> np.ndarray:
    """World state of the steady circle: centre of the circle at the origin, G at
    (R_G, 0, a cos b) moving along +y, turning anticlockwise (Omega about +z), the wheel
    leaning towards the origin. Axle n = (cos b, 0, sin b), in-plane up
    u = (-sin b, 0, cos b); the kinematics w = w3' n + Omega cos b u, v_G = w x a u
    = -a w3' y force w3' = -Omega R_G/a (the sense of n makes w.n negative here).
    ``dbeta`` tilts the wheel further, keeping those body-frame components."""
    b = c.lean
    bb = b + dbeta
    n = np.array([math.cos(bb), 0.0, math.sin(bb)])
    u = np.array([-math.sin(bb), 0.0, math.cos(bb)])
    W = c.turn_rate
    w = -(W * c.radius / a) * n + W * math.cos(b) * u
    G = np.array([c.radius, 0.0, a * math.cos(bb)])
    return np.concatenate([n, w, G])


def run_circle(c: CircleMotion, wheel: Wheel, a: float, y0: np.ndarray, t_end: float):
    from scipy.integrate import solve_ivp

    return solve_ivp(vector_rhs(wheel.mass, wheel.A, wheel.C, a, 0.0, c.g), (0, t_end), y0,
                     method="DOP853", rtol=1e-12, atol=1e-14, dense_output=True)


def test_R8_steady_circle_by_full_equations():
    a = 0.05
    w = thin_disk(a, 0.1)
    c = circle(w, a, math.radians(20.0), 0.5, G981)
    y0 = circle_start(c, a)
    # the initial state satisfies the kinematics: G moves at v = Omega R_G along +y, and
    # the contact point P = G - a u is on R_P (checks contact_radius independently)
    u0 = np.array([-math.sin(c.lean), 0.0, math.cos(c.lean)])
    assert np.cross(y0[3:6], a * u0) == pytest.approx([0.0, c.speed, 0.0], abs=1e-15)
    P = y0[6:9] - a * u0
    assert math.hypot(P[0], P[1]) == pytest.approx(c.contact_radius, rel=1e-15)
    sol = run_circle(c, w, a, y0, 1.0)
    ts = np.linspace(0.0, 1.0, 201)
    ys = sol.sol(ts).T
    leans = np.array([lean_of(y) for y in ys])
    # lean stays at 20 deg to 1e-6 (relative) over a second: the steady-state Omega is
    # exact to ~1e-16 and DOP853 at rtol 1e-12 adds ~1e-11
    assert np.max(np.abs(leans - c.lean)) < 1e-6 * c.lean
    radii = np.hypot(ys[:, 6], ys[:, 7])
    assert np.max(np.abs(radii - c.radius)) < 1e-6 * c.radius
    # the test can fail: a turn rate 0.1% off makes the lean wander by ~5e-5 rad
    bad = CircleMotion(**{**c.__dict__, "turn_rate": 1.001 * c.turn_rate})
    sol = run_circle(bad, w, a, circle_start(bad, a), 1.0)
    leans = np.array([lean_of(y) for y in sol.sol(ts).T])
    assert np.max(np.abs(leans - c.lean)) > 1e-5


def test_R8_lean_oscillation_frequency_by_full_equations():
    a = 0.05
    w = thin_disk(a, 0.1)
    c = circle(w, a, math.radians(20.0), 0.5, G981)
    sol = run_circle(c, w, a, circle_start(c, a, dbeta=1e-5), 1.2)
    ts = np.linspace(0.0, 1.2, 24001)
    lean = np.array([lean_of(y) for y in sol.sol(ts).T])
    i = np.where((lean[1:-1] > lean[:-2]) & (lean[1:-1] >= lean[2:]))[0] + 1
    # parabolic refinement of each maximum
    y0, y1, y2 = lean[i - 1], lean[i], lean[i + 1]
    h = ts[1] - ts[0]
    tmax = ts[i] + 0.5 * h * (y0 - y2) / (y0 - 2 * y1 + y2)
    assert len(tmax) >= 5
    period = (tmax[-1] - tmax[0]) / (len(tmax) - 1)
    # amplitude 1e-5 rad: nonlinear frequency shift ~1e-10; peak timing to ~1e-8 s over
    # ~1 s; so 1e-5 relative is generous
    assert 2 * math.pi / period == pytest.approx(c.lean_frequency, rel=1e-5)


def reduced_jacobian(wheel: Wheel, a: float, g: float, y: np.ndarray) -> np.ndarray:
    f = reduced_rhs(wheel.mass, wheel.A, wheel.C, a, g)
    J = np.empty((4, 4))
    for k in range(4):
        h = 1e-6 * max(1.0, abs(y[k]))
        e = np.zeros(4)
        e[k] = h
        J[:, k] = (f(0, y + e) - f(0, y - e)) / (2 * h)
    return J


@settings(max_examples=50, deadline=None)
@given(
    beta_deg=st.floats(1.0, 80.0),
    RG=st.floats(0.0, 2.0),
    Ak=st.floats(0.15, 0.8),
    CA=st.floats(0.5, 2.0),
)
def test_kappa_matches_linearised_reduced_equations(beta_deg, RG, Ak, CA):
    a, m, g = 0.05, 0.7, 9.81
    A = Ak * m * a * a
    w = Wheel(m, A, CA * A)
    c = circle(w, a, math.radians(beta_deg), RG, g)
    # the reduced equations measure omega3 along the axle that points up-and-out of the
    # turn (see circle_start): omega3_reduced = -spin
    y = np.array([c.lean, 0.0, c.turn_rate, -c.spin])
    scale = (m * g * a + (A + m * a * a) * c.turn_rate**2
             + (w.C + m * a * a) * c.turn_rate * c.spin
             + w.C * (w.C + m * a * a) * c.spin**2 / A)
    # the circle relation: theta'' = 0 at the steady state (round-off of ~20 flops)
    assert abs(reduced_rhs(m, w.A, w.C, a, g)(0, y)[1]) * (A + m * a * a) < 1e-13 * scale
    ev = np.linalg.eigvals(reduced_jacobian(w, a, g, y))
    lam2 = (ev[np.argmax(np.abs(ev))] ** 2).real
    # eigenvalues 0, 0, +-sqrt(-kappa/(A + m a^2)); central differences, h = 1e-6:
    # truncation ~1e-12, round-off ~1e-10 relative to the terms of kappa
    assert -lam2 * (A + m * a * a) == pytest.approx(c.kappa, abs=1e-7 * scale)


@settings(max_examples=50, deadline=None)
@given(beta_deg=st.floats(0.5, 89.0), Ak=st.floats(0.15, 0.8), CA=st.floats(0.5, 2.0))
def test_spinning_in_place_limit(beta_deg, Ak, CA):
    a, m, g = 0.05, 0.3, 9.81
    A = Ak * m * a * a
    w = Wheel(m, A, CA * A)
    b = math.radians(beta_deg)
    c = circle(w, a, b, 0.0, g)
    # sheet §3.3: Omega^2 = m g a/(A cos b), kappa = (3A sin^2 b + m a^2 cos^2 b) Omega^2 > 0
    assert c.turn_rate**2 == pytest.approx(m * g * a / (A * math.cos(b)), rel=1e-13)
    expected = (3 * A * math.sin(b) ** 2 + m * a * a * math.cos(b) ** 2) * c.turn_rate**2
    # kappa is a sum of terms of size ~(A + m a^2) Omega^2 that cancel: round-off 1e-14
    assert c.kappa == pytest.approx(expected, abs=1e-13 * (A + m * a * a) * c.turn_rate**2)
    assert c.stable and c.kappa > 0
    assert c.spin == 0.0 and c.speed == 0.0
    assert c.contact_radius == pytest.approx(a * math.sin(b), rel=1e-15)


def test_R9_eulers_disk():
    a = 0.05
    c = circle(thin_disk(a, 0.4), a, math.radians(60.0), 0.0, G981)
    alpha = math.radians(30.0)
    # Moffatt 2000, thin disk: Omega^2 = 4 g/(a sin alpha); round-off
    assert c.turn_rate**2 == pytest.approx(4 * G981 / (a * math.sin(alpha)), rel=1e-14)
    assert c.stable


def test_large_radius_limit():
    a, m, g = 0.3, 2.0, 9.81
    w = Wheel(m, 0.08, 0.15)
    Cc = w.C + m * a * a
    v = 2.0
    prev = None
    for RG in (10.0, 1e2, 1e3, 1e4, 1e6):
        c = lean_for(w, a, v, RG, g)
        # exact identity from the circle relation (sheet §3.3), derived here:
        # tan b = Cc v^2/(m g a^2 R_G) * (1 + A a sin b/(Cc R_G)) -- brentq to ~1e-15
        approx = Cc * v * v / (m * g * a * a * RG)
        assert math.tan(c.lean) == pytest.approx(
            approx * (1 + w.A * a * math.sin(c.lean) / (Cc * RG)), rel=1e-12)
        assert c.speed == pytest.approx(v, rel=1e-12)
        if prev is not None:
            assert c.lean < prev.lean and c.turn_rate < prev.turn_rate
        prev = c
    # R_G -> oo at fixed v: b -> 0, Omega -> 0, and the lean dynamics become straight
    # rolling's (kappa/(A + m a^2) -> nu^2 of sheet §3.2); at R_G = 1e6 the corrections
    # are O(v^2/(g R_G)) ~ 4e-7
    assert prev.lean < 1e-6 and prev.turn_rate == pytest.approx(v / 1e6, rel=1e-12)
    nu2 = at_speed(straight(w, a, 0.0, g), v=v).nu2
    assert prev.kappa / (w.A + m * a * a) == pytest.approx(nu2, rel=1e-5)
    assert math.tan(prev.lean) == pytest.approx(Cc * v * v / (m * g * a * a * 1e6), rel=1e-6)


def test_lean_for_and_radius_for_round_trip():
    a, g = 0.05, 9.81
    w = thin_disk(a, 0.1)
    c = circle(w, a, math.radians(20.0), 0.5, g)
    back = lean_for(w, a, c.speed, 0.5, g)
    assert back.lean == pytest.approx(c.lean, rel=1e-13)  # brentq at rtol 4 eps
    assert lean_for(w, a, -c.speed, 0.5, g).lean == pytest.approx(c.lean, rel=1e-13)
    rad = radius_for(w, a, c.speed, c.lean, g)
    assert rad.radius == pytest.approx(0.5, rel=1e-13)  # a quadratic root, round-off
    # v = 0: standing at rest (lean 0), or spinning in place (R_G 0)
    z = lean_for(w, a, 0.0, 0.5, g)
    assert z.lean == 0.0 and z.turn_rate == 0.0 and not z.stable
    assert radius_for(w, a, 0.0, 0.5, g).radius == 0.0
    with pytest.raises(InputError, match="no lean"):
        lean_for(w, a, 1.0, 0.0, g)
    with pytest.raises(InputError, match="give the lean"):
        lean_for(w, a, 0.0, 0.0, g)
    with pytest.raises(InputError, match="straight"):
        radius_for(w, a, 1.0, 0.0, g)
    with pytest.raises(InputError, match="lie flat"):
        lean_for(w, a, 1e12, 1e-6, g)


def test_R_example_unstable_circle():
    # sheet §3.3: thin disk a = 0.05, b = 2 deg, R_G = 0.1 m, v = 0.151 m/s is unstable
    a = 0.05
    w = thin_disk(a)
    c = circle(w, a, math.radians(2.0), 0.1, 9.81)
    assert c.speed == pytest.approx(0.151, abs=5e-4)  # the sheet quotes 3 figures
    assert not c.stable and c.lean_frequency is None
    # growth rate sqrt(-kappa/(A + m a^2)), sheet §3.3; one sqrt and a divide
    assert c.growth_rate == pytest.approx(math.sqrt(-c.kappa / (w.A + w.mass * a * a)),
                                          rel=1e-15)


def test_zero_lean_is_standing_still():
    a, m, g = 0.3, 2.0, 9.81
    w = Wheel(m, 0.08, 0.15)
    for RG in (0.0, 1.0):
        c = circle(w, a, 0.0, RG, g)
        assert c.turn_rate == 0.0 and c.spin == 0.0 and c.speed == 0.0
        assert c.kappa == pytest.approx(-m * g * a, rel=1e-15)  # kappa = -m g a exactly
        assert not c.stable
        assert c.growth_rate == pytest.approx(math.sqrt(m * g * a / (w.A + m * a * a)),
                                              rel=1e-15)


def test_circle_refusals():
    w = thin_disk(0.05)
    with pytest.raises(InputError, match="knife-edge"):
        circle(w, 0.05, 0.3, 0.5, 9.81, r=0.01)
    with pytest.raises(InputError, match="knife-edge"):
        lean_for(w, 0.05, 1.0, 0.5, 9.81, r=0.01)
    with pytest.raises(InputError, match="knife-edge"):
        rollcheck(w, 0.05, 0.01, 9.81, lean_rad=0.3, circle_radius=0.5)
    for bad in (-0.1, math.pi / 2, 2.0):
        with pytest.raises(InputError, match="lean"):
            circle(w, 0.05, bad, 0.5, 9.81)
    with pytest.raises(InputError, match="circle radius"):
        circle(w, 0.05, 0.3, -1.0, 9.81)
    with pytest.raises(InputError, match="two of"):
        rollcheck(w, 0.05, lean_rad=0.3)


def test_stability_map_matches_circle():
    a, g = 0.05, 9.81
    w = Wheel(0.5, 0.3 * 0.5 * a * a, 0.55 * 0.5 * a * a)
    leans = np.radians([0.0, 2.0, 10.0, 45.0, 80.0])
    radii = np.array([0.0, 0.05, 0.1, 1.0])
    k = stability_map(w, a, g, leans, radii)
    assert k.shape == (5, 4)
    for i, b in enumerate(leans):
        for j, RG in enumerate(radii):
            assert k[i, j] == circle(w, a, b, RG, g).kappa  # the very same arithmetic
    # both signs occur: small leans on large circles are stable (fast), small leans on
    # small circles are slow and unstable (sheet example), standing upright is unstable
    assert k[0, 1] < 0 and k[1, 2] < 0 and k[3, 0] > 0
    with pytest.raises(ValueError):
        stability_map(w, a, g, [math.pi / 2], radii)


# --------------------------------------------------------------------------- wheel_from_body


def rotated(Jd: np.ndarray, R_: np.ndarray) -> np.ndarray:
    return R_ @ Jd @ R_.T


@settings(max_examples=50, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), A=st.floats(0.01, 1.0), CA=st.floats(0.1, 2.0))
def test_wheel_from_rotated_body(seed, A, CA):
    from scipy.spatial.transform import Rotation

    Rm = Rotation.random(random_state=seed).as_matrix()
    C = CA * A
    J = rotated(np.diag([A, A, C]), Rm)
    axle = 3.7 * Rm[:, 2]  # not unit: normalised
    com = 0.25 * Rm[:, 2]  # on the axle line through the origin
    w = wheel_from_body(2.0, com, J, axle)
    # eigen-decomposition of a rotated diagonal tensor: round-off ~1e-15 of the largest
    assert w.A == pytest.approx(A, abs=1e-13 * max(A, C))
    assert w.C == pytest.approx(C, abs=1e-13 * max(A, C))
    assert np.linalg.norm(w.axle) == pytest.approx(1.0, rel=1e-15)
    assert w.com_offset < 1e-12


def test_not_a_body_of_revolution_refused_with_numbers():
    J = np.diag([0.031, 0.032, 0.05])  # differ by 0.001/0.0315 = 3.2 % of their mean
    with pytest.raises(ValueError) as e:
        wheel_from_body(1.0, [0, 0, 0], J, [0, 0, 1])
    msg = str(e.value)
    assert "not a body of revolution" in msg
    # the tolerance named as a parameter template: the API says symmetry_tol, the CLI --symmetry-tol
    assert "0.031" in msg and "0.032" in msg and "3.2 %" in msg and "{symmetry_tol}" in msg


def test_axle_not_principal_refused():
    from scipy.spatial.transform import Rotation

    Rm = Rotation.from_rotvec([math.radians(2.0), 0, 0]).as_matrix()
    J = rotated(np.diag([0.03, 0.03, 0.05]), Rm)  # symmetry axis tilted 2 deg from z
    with pytest.raises(ValueError, match="principal") as e:
        wheel_from_body(1.0, [0, 0, 0], J, [0, 0, 1])
    assert "2° away" in str(e.value)  # 3 significant figures of exactly 2 deg
    # along the true symmetry axis it is accepted
    w = wheel_from_body(1.0, [0, 0, 0], J, Rm[:, 2])
    assert w.A == pytest.approx(0.03, rel=1e-12) and w.C == pytest.approx(0.05, rel=1e-12)


def test_small_asymmetry_within_tolerance_averaged():
    J = np.diag([0.03 * (1 - 1e-8), 0.03 * (1 + 1e-8), 0.05])
    w = wheel_from_body(1.0, [0, 0, 0], J)
    assert w.A == pytest.approx(0.03, rel=1e-15)  # mean of the two moments across


def test_com_off_axle_refused():
    J = np.diag([0.03, 0.03, 0.05])
    with pytest.raises(ValueError, match=r"2\.3 mm off the axle"):
        wheel_from_body(1.0, [0.0023, 0.0, 0.1], J, [0, 0, 1])
    # the axle may be placed through another point
    w = wheel_from_body(1.0, [0.0023, 0.0, 0.1], J, [0, 0, 1], axle_through=[0.0023, 0, 0])
    assert w.com_offset == 0.0
    # a com offset along the axle is not an offset
    wheel_from_body(1.0, [0.0, 0.0, 7.0], J, [0, 0, 1])
    # the tolerance scales with the given radius (1e-6 of it)
    wheel_from_body(1.0, [5e-7, 0.0, 0.0], J, radius=1.0)
    with pytest.raises(ValueError, match="off the axle"):
        wheel_from_body(1.0, [5e-7, 0.0, 0.0], J, radius=0.1)


def test_unphysical_wheels_refused():
    with pytest.raises(ValueError, match="twice"):
        Wheel(1.0, 0.01, 0.03)
    with pytest.raises(ValueError):
        Wheel(0.0, 0.01, 0.01)
    with pytest.raises(ValueError, match="axle"):
        wheel_from_body(1.0, [0, 0, 0], np.eye(3), [0, 0, 0])
    with pytest.raises(ValueError):
        wheel_from_body(1.0, [0, 0, 0], np.zeros((3, 3)))
    # a thin rod along the axle: C = 0
    with pytest.raises(ValueError, match="positive"):
        wheel_from_body(1.0, [0, 0, 0], np.diag([0.1, 0.1, 0.0]))


# --------------------------------------------------------------------------- JSON and import


def _walk(x):
    if isinstance(x, dict):
        for v in x.values():
            yield from _walk(v)
    elif isinstance(x, list):
        for v in x:
            yield from _walk(v)
    else:
        yield x


def test_json_keys_and_types():
    a = 0.35
    w = hoop(a, 1.8)
    base = rollcheck(w, a, 0.0, 9.80665).to_json()
    for k in ("radius", "mass", "I", "Is", "critical_spin", "critical_speed"):
        assert k in base
    assert "speed" not in base and "circle" not in base
    assert base["I"] == w.A and base["Is"] == w.C and base["radius"] == a
    slow = rollcheck(w, a, 0.0, 9.80665, speed=0.5)
    doc = slow.to_json()
    for k in ("speed", "stable", "margin"):
        assert k in doc
    assert doc["stable"] is False and doc["lean_frequency"] is None
    full = rollcheck(w, a, 0.0, 9.80665, speed=3.0, lean_rad=math.radians(15), circle_radius=4.0)
    doc = full.to_json()
    assert set(doc["circle"]) >= {"lean_deg", "radius", "turn_rate", "spin", "speed", "stable"}
    assert doc["circle"]["lean_deg"] == pytest.approx(15.0, rel=1e-15)
    for x in _walk(doc):
        assert x is None or type(x) in (float, bool, str, int)
        if type(x) is float:
            assert math.isfinite(x)
    json.dumps(doc, allow_nan=False)
    # circle from speed and radius
    doc = rollcheck(w, a, speed=3.0, circle_radius=4.0).to_json()
    assert doc["circle"]["speed"] == pytest.approx(3.0, rel=1e-12)
    doc = rollcheck(w, a, speed=3.0, lean_rad=0.2).to_json()
    assert doc["circle"]["speed"] == pytest.approx(3.0, rel=1e-12)
    for obj in (straight(w, a), at_speed(straight(w, a), v=1.0),
                circle(w, a, 0.2, 1.0), w):
        json.dumps(obj.to_json(), allow_nan=False)
    assert isinstance(straight(w, a), StraightRolling)
    assert isinstance(at_speed(straight(w, a), v=1.0), Verdict)


def test_import_does_not_load_scipy():
    # a fresh interpreter (not the cli fixtures: no command runs): what the import loads
    code = "import sys, rbcli.core.rolling; print(any(k.startswith('scipy') for k in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.strip()
    assert out == "False"


def test_docstrings_name_the_moments():
    doc = (R.__doc__ or "") + (straight.__doc__ or "")
    assert "about the centre G" in doc and "contact point" in doc
    assert "neutral stability (undamped)" in doc


@settings(max_examples=50, deadline=None)
@given(v=st.floats(1e-3, 50.0), RG=st.floats(1e-3, 1e3), Ak=st.floats(0.15, 0.8),
       CA=st.floats(0.5, 2.0))
def test_lean_for_round_trip_property(v, RG, Ak, CA):
    a, m, g = 0.3, 1.5, 9.80665
    A = Ak * m * a * a
    w = Wheel(m, A, CA * A)
    c = lean_for(w, a, v, RG, g)
    assert 0.0 < c.lean < math.pi / 2
    # lean_for reports Omega = v / R_G exactly (v and R_G are the data): round-off only
    assert c.speed == pytest.approx(v, rel=1e-10)
    # and the closed-form inverse recovers the radius (a quadratic root, round-off), as
    # far as the lean resolves it: brentq stops within 4 eps |b| of the root, and R_G
    # (through tan b) moves by d b / (sin b cos b) relative — ~1e-8 when a tiny circle at
    # high speed puts the lean within 1e-7 rad of 90°, where no float lean does better
    b = c.lean
    tol = 1e-9 + 8 * np.finfo(float).eps * b / (math.sin(b) * math.cos(b))
    assert radius_for(w, a, v, c.lean, g).radius == pytest.approx(RG, rel=tol)


def _cli(exc):
    """The message as the command line prints it (parameters spelled as its options)."""
    from rbcli.errors import option_name

    return exc.spelled(option_name)


def test_errors_name_their_parameters():
    """Core errors carry the parameter (no caller reads the message to find the option)."""
    w = thin_disk(0.05)
    st_ = straight(w, 0.05)
    with pytest.raises(InputError) as e:
        at_speed(st_, v=1.0, spin=1.0)
    assert e.value.param == "speed" and _cli(e.value).startswith("--speed, --spin: ")
    with pytest.raises(InputError) as e:
        rollcheck(w, 0.05, spin=20.0, circle_radius=0.0)
    assert e.value.param == "circle" and _cli(e.value).startswith("--circle, --spin: no lean")
    with pytest.raises(InputError) as e:
        rollcheck(w, 0.05, speed=1.0, lean_rad=0.0)
    assert e.value.param == "lean" and _cli(e.value).startswith("--lean, --speed: an upright")
    with pytest.raises(InputError) as e:
        straight(w, 0.05, 0.06)
    assert e.value.param == "tyre_radius"


@pytest.mark.parametrize("v", [1e-300, 1e-200, 5e-324])
def test_a_speed_too_small_for_its_circle_is_refused_by_name(v):
    # issue 15: the lean, ~ (C + m a^2) v^2/(m g a^2 R_G), is below any float: brentq used to
    # say "f(a) and f(b) must have different signs"
    w = thin_disk(0.05)
    with pytest.raises(InputError) as e:
        rollcheck(w, 0.05, speed=v, circle_radius=1.0)
    assert e.value.param == "circle" and _cli(e.value).startswith("--circle, --speed: the speed ")
    assert "too small" in str(e.value)
    # a small speed whose lean is still a float is solved
    c = lean_for(w, 0.05, 1e-100, 1.0)
    assert 0.0 < c.lean < 1e-190 and c.speed == pytest.approx(1e-100, rel=1e-12)


def test_rim_circle_centres_of_the_round_shapes():
    """The rim circle of each round shape, from its centre of mass (core.rim): a hemisphere's
    flat face is 3R/8 below its com, a cone's base h/4 (with h from its volume pi R^2 h/3);
    the others' rim circle is in the plane of their com. Turned over (axis -z), the offset
    turns too."""
    from types import SimpleNamespace

    from rbcli.core.rim import rim_circle_centre, rim_of

    def part(shape, axis=(0.0, 0.0, 1.0), R=0.05, measure=None, com=(0.0, 0.0, 0.0)):
        return SimpleNamespace(name=shape, shape=shape, radius=R, measure=measure, subtract=False,
                               com=np.array(com), axis=np.array(axis))

    assert rim_circle_centre(part("hemisphere"))[2] == pytest.approx(-3 * 0.05 / 8, rel=1e-15)
    h = 0.1
    cone = part("cone", measure=math.pi * 0.05**2 * h / 3)
    assert rim_circle_centre(cone)[2] == pytest.approx(-h / 4, rel=1e-14)
    down = part("cone", axis=(0.0, 0.0, -1.0), measure=math.pi * 0.05**2 * h / 3)
    assert rim_circle_centre(down)[2] == pytest.approx(h / 4, rel=1e-14)
    for shape in ("disk", "ring", "cylinder", "sphere", "torus"):
        assert list(rim_circle_centre(part(shape, com=(0, 0, 0.3)))) == [0.0, 0.0, 0.3]
    # a rim radius no part has: nothing to measure; a part on another axis is no rim
    assert rim_of([part("disk")], [0, 0, 0], [0, 0, 1], [0, 0, 0], 0.07) is None
    assert rim_of([part("disk", axis=(1.0, 0.0, 0.0))], [0, 0, 0], [0, 0, 1], [0, 0, 0], 0.05) is None
    off = rim_of([part("hemisphere")], [0, 0, 0.01], [0, 0, 1], [0, 0, 0], 0.05)
    assert off.offset == pytest.approx(-3 * 0.05 / 8 - 0.01) and not off.upright_equilibrium
