"""Invariants of :func:`rbcli.core.principal.principal_axes` and ``principal_report`` that
hold whatever the tensor: checked on random physical tensors (hypothesis).

- rotating the body (J -> Q J Qᵀ) leaves the principal moments unchanged and turns the
  axes with it (up to sign, and within a degenerate eigenspace);
- the axes are orthonormal, right-handed (det +1) and diagonalise J to the moments;
- the moments about a point follow from those about the com by the parallel-axis theorem
  (the trace grows by 2 m d² and J_P − J_G = m (d·d E − d dᵀ)).
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from rbcli.core.inertia import MassProps, inertia_about
from rbcli.core.principal import principal_axes, principal_report

moment = st.floats(0.05, 20.0)
quat = st.lists(st.floats(-1, 1), min_size=4, max_size=4).filter(lambda q: np.linalg.norm(q) > 0.1)
point = st.lists(st.floats(-5, 5), min_size=3, max_size=3)


def _physical(a: float, b: float, c: float) -> np.ndarray:
    """Principal moments of a real body: A = b + c etc. for second moments a, b, c >= 0."""
    return np.array([b + c, a + c, a + b])


def _tensor(m3, q) -> tuple[np.ndarray, np.ndarray]:
    Q = Rotation.from_quat(q).as_matrix()
    return Q @ np.diag(m3) @ Q.T, Q


@settings(max_examples=200, deadline=None)
@given(a=moment, b=moment, c=moment, q=quat, q2=quat)
def test_moments_are_invariant_under_rotation(a, b, c, q, q2):
    m3 = _physical(a, b, c)
    J, _ = _tensor(m3, q)
    R = Rotation.from_quat(q2).as_matrix()
    pa, pb = principal_axes(J), principal_axes(R @ J @ R.T)
    scale = float(np.max(m3))
    np.testing.assert_allclose(pa.moments, np.sort(m3), rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(pb.moments, pa.moments, rtol=0, atol=1e-12 * scale)
    if pa.symmetry == "asymmetric" and np.min(np.diff(pa.moments)) > 1e-3 * scale:
        # each axis turns with the body, up to its sign
        for i in range(3):
            assert abs(float(pb.axes[i] @ (R @ pa.axes[i]))) == pytest.approx(1.0, abs=1e-8)


@settings(max_examples=200, deadline=None)
@given(a=moment, b=moment, c=moment, q=quat, eq=st.sampled_from([None, "01", "12", "all"]))
def test_axes_are_orthonormal_right_handed_and_diagonalise(a, b, c, q, eq):
    if eq == "01":
        b = a
    elif eq == "12":
        c = b
    elif eq == "all":
        b = c = a
    m3 = _physical(a, b, c)
    J, _ = _tensor(m3, q)
    pa = principal_axes(J)
    A = pa.axes
    np.testing.assert_allclose(A @ A.T, np.eye(3), rtol=0, atol=1e-12)
    assert np.linalg.det(A) == pytest.approx(1.0, abs=1e-12)
    np.testing.assert_allclose(np.cross(A[0], A[1]), A[2], rtol=0, atol=1e-12)
    scale = float(np.max(m3))
    np.testing.assert_allclose(A @ J @ A.T, np.diag(pa.moments), rtol=0, atol=1e-9 * scale)
    assert np.all(np.diff(pa.moments) >= 0)


@settings(max_examples=200, deadline=None)
@given(a=moment, b=moment, c=moment, q=quat, mass=st.floats(0.1, 10.0), p=point)
def test_parallel_axis(a, b, c, q, mass, p):
    Jc, _ = _tensor(_physical(a, b, c), q)
    com = np.array([0.3, -0.2, 0.1])
    mp = MassProps(mass, com, Jc)
    P = np.asarray(p, dtype=float)
    d = P - com
    JP = inertia_about(mp, P)
    scale = float(np.max(np.abs(JP)))
    np.testing.assert_allclose(JP - Jc, mass * (d @ d * np.eye(3) - np.outer(d, d)), rtol=0, atol=1e-12 * scale)
    at_com, at_p = principal_report(mass, Jc, com), principal_report(mass, JP, P)
    assert float(np.sum(at_p.moments)) == pytest.approx(float(np.sum(at_com.moments)) + 2 * mass * float(d @ d),
                                                         rel=1e-12)
    # about P the moment about the line through P parallel to each com axis is larger by m r²
    for i in range(3):
        n = at_com.axes[i]
        r2 = float(d @ d) - float(d @ n) ** 2
        assert float(n @ JP @ n) == pytest.approx(at_com.moments[i] + mass * r2, rel=1e-9, abs=1e-12 * scale)
    # the principal moments about P are never below the smallest about the com
    assert at_p.moments[0] >= at_com.moments[0] - 1e-12 * scale


# ----------------------------------------------------------------------------- signs (issue 13.6)


@pytest.mark.parametrize("axis", [[1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0], [1, 1, 0], [1, -2, 0], [3, 1, 2]])
@pytest.mark.parametrize("tilt", [0.5, -0.5, 0.01])
def test_a_slightly_tilted_flywheel_reads_its_tilt(axis, tilt):
    """A flywheel tilted 0.5° has principal axes 0.5° from its body axes (it read 179.6°)."""
    from rbcli.api.load import load_text

    body = load_text("parts:\n  - {shape: cylinder, radius: 0.3, length: 0.05, mass: 20, "
                     f"rotate: {{axis: {axis}, angle: {tilt}}}}}\n")
    from rbcli.core.inertia import combine

    mp = combine(body.parts)
    r = principal_report(mp.mass, mp.inertia_com, mp.com)
    assert r.symmetry == "symmetric" and r.unique_axis == 2
    # the rotation is the tilt of the symmetry axis (about an in-plane axis: exactly the
    # tilt; a turn about z itself cannot be seen in a body of revolution)
    k = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    n = Rotation.from_rotvec(np.radians(tilt) * k).apply([0, 0, 1.0])
    # (to second order: the free axes are the body axes projected on the plane)
    assert r.rotation_angle_deg == pytest.approx(np.degrees(np.arccos(n[2])), rel=1e-4)
    assert r.axes[2] @ np.array([0, 0, 1.0]) > 0.9999  # axis 3 is +z tilted, not -z
    assert np.linalg.det(r.axes) == pytest.approx(1.0)


@settings(max_examples=200, deadline=None)
@given(a=moment, b=moment, c=moment, rv=st.lists(st.floats(-0.3, 0.3), min_size=3, max_size=3))
def test_a_small_rotation_of_an_aligned_body_is_recovered(a, b, c, rv):
    """A body whose moments ascend along x, y, z, turned by a small rotation Q, has axes = Q
    (rows: the turned x, y, z) and a rotation angle = |Q|'s angle."""
    m3 = np.sort(_physical(a, b, c))
    if np.min(np.diff(m3)) < 1e-2 * m3[-1]:
        return  # (nearly) equal moments: the free axes are chosen, not recovered
    Q = Rotation.from_rotvec(rv)
    J = Q.as_matrix() @ np.diag(m3) @ Q.as_matrix().T
    r = principal_report(1.0, J, np.zeros(3))
    np.testing.assert_allclose(r.axes, Q.as_matrix().T, rtol=0, atol=1e-8 / np.min(np.diff(m3)) * m3[-1])
    assert r.rotation_angle_deg == pytest.approx(np.degrees(Q.magnitude()), abs=1e-6)


# ------------------------------------------------------------------ tilts (issue 24, item 2)


def _axis_line_angle_deg(u: np.ndarray, e: np.ndarray) -> float:
    """Angle between two axis lines (direction sign ignored), by the oracle arccos of the
    dot product (in long double via math.acos is no better; the tests below stay > 0.01°)."""
    c = abs(float(np.dot(u, e)) / (np.linalg.norm(u) * np.linalg.norm(e)))
    return float(np.degrees(np.arccos(min(c, 1.0))))


@pytest.mark.parametrize("angle", [0.5, 3.0, 20.0])
@pytest.mark.parametrize("about", [0, 1, 2])
def test_a_rotated_bar_reads_its_tilt_per_axis(angle, about):
    """A long bar with three different moments (a 1 m bar, 80 x 120 mm, 1 kg) turned by
    ``angle`` about body axis ``about``: the axis turned about keeps tilt 0, the other two
    read ``angle`` each, each against the body axis it came from (scipy's Rotation as the
    oracle for the turned frame; 1e-9°: atan2 of the rotated components, exact to
    round-off)."""
    from rbcli.core.principal import axis_tilts

    d = np.diag([(1.0 + 0.12**2) / 12, (1.0 + 0.08**2) / 12, (0.08**2 + 0.12**2) / 12])
    rv = np.zeros(3)
    rv[about] = np.radians(angle)
    Q = Rotation.from_rotvec(rv).as_matrix()
    pa = principal_axes(Q @ d @ Q.T)
    tilt, nearest = axis_tilts(pa.axes)
    for i in range(3):
        j = nearest[i]
        assert tilt[i] == pytest.approx(_axis_line_angle_deg(pa.axes[i], np.eye(3)[j]), abs=1e-9)
        # the body axis it came from: the column of Q nearest to this principal axis
        src = int(np.argmax(np.abs(Q.T @ pa.axes[i])))
        assert j == src
        expected = 0.0 if src == about else angle
        assert tilt[i] == pytest.approx(expected, abs=1e-9)


@settings(max_examples=200, deadline=None)
@given(a=moment, b=moment, c=moment, q=quat)
def test_tilts_are_the_smallest_angle_to_any_body_axis(a, b, c, q):
    """Each tilt is the angle from the principal axis line to its nearest body axis line:
    no body axis is nearer (brute force over the three, the arccos oracle; 1e-6° covers
    arccos's loss of digits near 0°), and it is at most arccos(1/sqrt 3) = 54.7356°, the
    largest a line can be from all three axes."""
    from rbcli.core.principal import axis_tilts

    J, _ = _tensor(_physical(a, b, c), q)
    pa = principal_axes(J)
    tilt, nearest = axis_tilts(pa.axes)
    for i in range(3):
        angles = [_axis_line_angle_deg(pa.axes[i], e) for e in np.eye(3)]
        assert tilt[i] == pytest.approx(min(angles), abs=1e-6)
        assert angles[nearest[i]] == pytest.approx(min(angles), abs=1e-6)
        assert tilt[i] <= np.degrees(np.arccos(1 / np.sqrt(3))) + 1e-9


def test_stability_words_agree_with_the_symmetry_text():
    """Free rotation: asymmetric stable/unstable/stable; a symmetric body is stable about its
    symmetry axis and neutral about the equal pair (the spin axis wanders round the
    symmetry axis: Euler's linearisation has k = 0, the tilt grows linearly) — not
    "stable"; a sphere is stable about every axis (any nearby spin is as steady)."""
    asym = principal_report(1.0, np.diag([1.0, 2.0, 3.0]), np.zeros(3))
    assert asym.stability == ("stable", "unstable", "stable")
    assert asym.stable == (True, False, True)
    rod = principal_report(1.0, np.diag([1.0, 5.0, 5.0]), np.zeros(3))
    assert rod.stability == ("stable", "neutral", "neutral")
    assert rod.stable == (True, False, False)
    disk = principal_report(1.0, np.diag([1.0, 1.0, 2.0]), np.zeros(3))
    assert disk.stability == ("neutral", "neutral", "stable")
    ball = principal_report(1.0, np.eye(3), np.zeros(3))
    assert ball.stability == ("stable",) * 3 and ball.stable == (True,) * 3
