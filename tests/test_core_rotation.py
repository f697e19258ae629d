"""rbcli.core.rotation against scipy.spatial.transform.Rotation (the test oracle).

Tolerance policy: every matrix entry is O(1) and comes from at most a few dozen
floating-point operations (a handful of sin/cos, two 3x3 products), each with a
relative error <= 1.1e-16; scipy takes a different path (via quaternions). So two
correct implementations agree to ~1e-15; ATOL = 1e-13 leaves a factor ~100 of slack
and still fails on any wrong sign, order or convention (those give O(1) differences).
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from rbcli.core import rotation as rot

ATOL = 1e-13  # module docstring; the measured worst case over 10^4 random inputs is 1.1e-15
ORTHO = 1e-14  # |RᵀR − I| of a matrix built from unit-norm data: ~10 roundings of O(1)

angles = st.floats(min_value=-2 * math.pi, max_value=2 * math.pi, allow_nan=False)
components = st.floats(min_value=-10.0, max_value=10.0, allow_nan=False)
vectors = st.lists(components, min_size=3, max_size=3).filter(
    lambda v: float(np.linalg.norm(v)) > 1e-3
)


def is_proper(r: np.ndarray, tol: float = ORTHO) -> bool:
    return (
        r.shape == (3, 3)
        and float(np.max(np.abs(r.T @ r - np.eye(3)))) <= tol
        and abs(float(np.linalg.det(r)) - 1.0) <= tol
    )


def _valid_sequences(n: int) -> list[str]:
    out = []
    for letters in ("xyz", "XYZ"):
        for seq in itertools.product(letters, repeat=n):
            if all(seq[i] != seq[i + 1] for i in range(n - 1)):
                out.append("".join(seq))
    return out


SEQ3 = _valid_sequences(3)
SEQ12 = _valid_sequences(1) + _valid_sequences(2)


def test_sequence_lists_are_complete() -> None:
    # 3 letters, consecutive different: 3*2*2 = 12 per case (6 Tait-Bryan + 6 proper Euler).
    assert len(SEQ3) == 24
    assert len(SEQ12) == 6 + 12


def test_identity() -> None:
    assert np.array_equal(rot.identity(), np.eye(3))


# ---------------------------------------------------------------------------------- euler


@pytest.mark.parametrize("seq", SEQ3)
@settings(max_examples=25, deadline=None)
@given(a=angles, b=angles, c=angles)
def test_euler_matches_scipy_for_every_three_letter_sequence(seq, a, b, c) -> None:
    expected = Rotation.from_euler(seq, [a, b, c]).as_matrix()
    got = rot.euler([a, b, c], seq)
    np.testing.assert_allclose(got, expected, rtol=0, atol=ATOL)  # ATOL: module docstring
    assert is_proper(got)


@pytest.mark.parametrize("seq", SEQ12)
@settings(max_examples=10, deadline=None)
@given(a=angles, b=angles)
def test_euler_matches_scipy_for_one_and_two_letter_sequences(seq, a, b) -> None:
    ang = [a, b][: len(seq)]
    expected = Rotation.from_euler(seq, ang).as_matrix()
    np.testing.assert_allclose(rot.euler(ang, seq), expected, rtol=0, atol=ATOL)


def test_euler_one_letter_takes_a_bare_angle() -> None:
    expected = Rotation.from_euler("z", 0.7).as_matrix()
    np.testing.assert_allclose(rot.euler(0.7, "z"), expected, rtol=0, atol=ATOL)  # ATOL: above


def test_euler_intrinsic_and_extrinsic_differ_as_documented() -> None:
    # Textbook: intrinsic ZYX(a, b, c) == extrinsic xyz(c, b, a). A 90° turn about z then
    # about the new y must differ from the fixed-axes order, or the case is ignored.
    a, b, c = 0.3, -1.1, 2.0
    np.testing.assert_allclose(
        rot.euler([a, b, c], "ZYX"), rot.euler([c, b, a], "xyz"), rtol=0, atol=ATOL
    )
    assert np.max(np.abs(rot.euler([a, b, c], "ZYX") - rot.euler([a, b, c], "zyx"))) > 0.1


def test_euler_elementary_rotation_right_hand_rule() -> None:
    # A +90° turn about z takes x to y (right-hand rule); exact up to cos(pi/2) ~ 6e-17.
    np.testing.assert_allclose(rot.euler(math.pi / 2, "z") @ [1, 0, 0], [0, 1, 0], atol=1e-15)


@pytest.mark.parametrize("seq", ["xyZ", "Xy", "xxz", "XYY", "abc", "", "xyzx", "ZYXZ", "x y"])
def test_euler_rejects_invalid_sequences(seq) -> None:
    with pytest.raises(ValueError, match="xyz") as err:
        rot.euler([0.1] * max(len(seq), 1), seq)
    assert str(err.value).startswith("euler sequence")  # lower case, names the field
    # scipy refuses the same sequences (the rule is scipy's)
    with pytest.raises(ValueError):
        Rotation.from_euler(seq, [0.1] * max(len(seq), 1))


def test_euler_rejects_wrong_angle_count_and_non_finite() -> None:
    with pytest.raises(ValueError, match="needs 3 angles"):
        rot.euler([0.1, 0.2], "ZYX")
    with pytest.raises(ValueError, match="finite"):
        rot.euler([0.1, float("nan"), 0.2], "ZYX")
    with pytest.raises(ValueError):
        rot.euler("abc", "ZYX")


# ----------------------------------------------------------------------------- quaternion


@settings(max_examples=50, deadline=None)
@given(q=st.lists(components, min_size=4, max_size=4).filter(lambda q: np.linalg.norm(q) > 1e-3))
def test_quaternion_matches_scipy_scalar_last(q) -> None:
    w, x, y, z = q
    expected = Rotation.from_quat([x, y, z, w]).as_matrix()  # scipy: scalar LAST
    got = rot.quaternion(q)
    np.testing.assert_allclose(got, expected, rtol=0, atol=ATOL)  # ATOL: module docstring
    assert is_proper(got)
    # q and -q are the same rotation; scaling does not matter (normalised first)
    np.testing.assert_allclose(rot.quaternion([-c for c in q]), got, rtol=0, atol=ATOL)
    np.testing.assert_allclose(rot.quaternion([3.7 * c for c in q]), got, rtol=0, atol=ATOL)


def test_quaternion_is_scalar_first() -> None:
    # [w, x, y, z] = [cos 45°, 0, 0, sin 45°] is +90° about z: x -> y. Scalar-last reading
    # would be a different rotation, so this pins the order. Exact to ~1e-16.
    h = math.sqrt(0.5)
    np.testing.assert_allclose(rot.quaternion([h, 0, 0, h]) @ [1, 0, 0], [0, 1, 0], atol=1e-15)
    np.testing.assert_array_equal(rot.quaternion([1, 0, 0, 0]), np.eye(3))


def test_quaternion_not_unit_is_normalised() -> None:
    # a 6-digit quaternion, norm 1 - 4e-7: same rotation as the normalised one
    q = [0.707107, 0.0, 0.0, 0.707107]
    exact = Rotation.from_quat([0, 0, 1, 1]).as_matrix()  # scipy normalises as well
    got = rot.quaternion(q)
    assert is_proper(got)
    # both are the 90° z-turn exactly, after normalisation (q has equal components)
    np.testing.assert_allclose(got, exact, rtol=0, atol=ATOL)


@pytest.mark.parametrize("q", [[0, 0, 0, 0], [1, 0, float("inf"), 0], [1, 0, 0], "wxyz"])
def test_quaternion_rejects_bad_input(q) -> None:
    with pytest.raises(ValueError, match="quaternion"):
        rot.quaternion(q)


# ----------------------------------------------------------------------------- axis_angle


@settings(max_examples=50, deadline=None)
@given(axis=vectors, angle=st.floats(min_value=-20.0, max_value=20.0, allow_nan=False))
def test_axis_angle_matches_scipy_rotvec(axis, angle) -> None:
    n = np.asarray(axis) / np.linalg.norm(axis)
    expected = Rotation.from_rotvec(angle * n).as_matrix()
    got = rot.axis_angle(axis, angle)
    np.testing.assert_allclose(got, expected, rtol=0, atol=ATOL)  # ATOL: module docstring
    assert is_proper(got)


def test_axis_angle_tiny_angle_keeps_precision() -> None:
    # 1e-10 rad about z: R[1, 0] = sin(1e-10) = 1e-10 to 1e-26, 1 - R[0, 0] = 5e-21.
    r = rot.axis_angle([0, 0, 2], 1e-10)
    assert r[1, 0] == pytest.approx(1e-10, rel=1e-15)  # sin to round-off
    assert is_proper(r)


@pytest.mark.parametrize("axis", [[0, 0, 0], [float("nan"), 0, 1], [1, 0]])
def test_axis_angle_rejects_bad_axis(axis) -> None:
    with pytest.raises(ValueError, match="axis must be a non-zero vector"):
        rot.axis_angle(axis, 0.3)


def test_axis_angle_rejects_non_finite_angle() -> None:
    with pytest.raises(ValueError, match="angle must be finite"):
        rot.axis_angle([0, 0, 1], float("inf"))


# ------------------------------------------------------------------------------ axis_to_z


def _minimal_oracle(d: np.ndarray) -> np.ndarray:
    """The minimal rotation e_z -> d built by scipy from its axis and angle."""
    u = d / np.linalg.norm(d)
    k = np.cross([0.0, 0.0, 1.0], u)
    s = np.linalg.norm(k)
    angle = math.atan2(s, u[2])
    return Rotation.from_rotvec(angle * k / s).as_matrix()


@settings(max_examples=50, deadline=None)
@given(d=vectors)
def test_axis_to_z_maps_ez_to_the_direction_minimally(d) -> None:
    d = np.asarray(d, dtype=float)
    u = d / np.linalg.norm(d)
    r = rot.axis_to_z(d)
    assert is_proper(r)
    np.testing.assert_allclose(r @ [0, 0, 1], u, rtol=0, atol=ATOL)  # ATOL: module docstring
    if np.hypot(u[0], u[1]) > 1e-6:  # away from ±z the oracle's axis k/|k| is well defined
        np.testing.assert_allclose(r, _minimal_oracle(d), rtol=0, atol=1e-12)
        # 1e-12: the oracle divides by |k| >= 1e-6 (and atan2), amplifying round-off


def test_axis_to_z_along_plus_and_minus_z() -> None:
    np.testing.assert_array_equal(rot.axis_to_z([0, 0, 5]), np.eye(3))
    # documented choice for the exact antipode: a half turn about +x
    np.testing.assert_array_equal(rot.axis_to_z([0, 0, -0.1]), np.diag([1.0, -1.0, -1.0]))


@pytest.mark.parametrize("eps", [1e-4, 1e-9, 1e-13, 1e-200])
def test_axis_to_z_near_minus_z_stays_orthonormal(eps) -> None:
    # A naive I + [v]x + [v]x²/(1 + c) loses ~eps_mach/(1 + c) here; ours must stay proper
    # to round-off and send e_z onto the direction (angle ~pi about an axis ⟂ z).
    d = np.array([eps, -0.5 * eps, -1.0])
    r = rot.axis_to_z(d)
    assert is_proper(r)
    np.testing.assert_allclose(r @ [0, 0, 1], d / np.linalg.norm(d), rtol=0, atol=ATOL)
    # continuity: close to a half turn about the axis e_z x d = (0.5, 1, 0)/|.|
    n = np.array([0.5, 1.0, 0.0]) / math.hypot(0.5, 1.0)
    half_turn = 2 * np.outer(n, n) - np.eye(3)
    np.testing.assert_allclose(r, half_turn, rtol=0, atol=10 * eps + ATOL)
    # 10*eps: the angle differs from pi by ~1.1*eps, and R is Lipschitz in the angle


def test_axis_to_z_huge_and_tiny_components() -> None:
    # no overflow/underflow in normalising: 1e300 and 1e-300 are fine directions
    for d in ([1e300, 0, 1e300], [1e-300, 1e-300, 0]):
        r = rot.axis_to_z(d)
        assert is_proper(r)
        u = np.array(d) / max(abs(x) for x in d)
        np.testing.assert_allclose(r @ [0, 0, 1], u / np.linalg.norm(u), rtol=0, atol=ATOL)


@pytest.mark.parametrize("d", [[0, 0, 0], [float("nan"), 1, 0], [1, float("inf"), 0], [1, 2]])
def test_axis_to_z_rejects_zero_and_non_finite(d) -> None:
    with pytest.raises(ValueError, match="^axis must be a non-zero vector$"):
        rot.axis_to_z(d)


# ---------------------------------------------------------------------------- from_matrix


def test_from_matrix_accepts_noise_and_returns_exact_rotation() -> None:
    rng = np.random.default_rng(7)
    exact = Rotation.from_euler("ZYX", [0.4, -0.9, 2.2]).as_matrix()
    noisy = exact + 1e-9 * rng.standard_normal((3, 3))
    r = rot.from_matrix(noisy)
    assert is_proper(r)  # orthonormal to ~1e-15 whatever the 1e-9 noise
    # the nearest rotation moves by about the noise: |R - exact| ~ 1e-9 (polar factor is
    # Lipschitz with constant ~1 near the orthogonal group); 1e-8 allows sqrt(9) noise sums
    np.testing.assert_allclose(r, exact, rtol=0, atol=1e-8)


def test_from_matrix_six_digit_matrix() -> None:
    # 45° about z typed with 6 digits: |MᵀM − I| = |2 * 0.707107² − 1| = 6.2e-7 <= 1e-6
    m = [[0.707107, -0.707107, 0], [0.707107, 0.707107, 0], [0, 0, 1]]
    r = rot.from_matrix(m)
    assert is_proper(r)
    np.testing.assert_allclose(r, rot.axis_angle([0, 0, 1], math.pi / 4), rtol=0, atol=ATOL)
    # the exact 45° rotation IS the nearest (M is a positive multiple of it), so agreement
    # is to round-off


def test_from_matrix_exact_rotation_round_trips() -> None:
    exact = Rotation.from_rotvec([0.3, -1.2, 0.5]).as_matrix()
    np.testing.assert_allclose(rot.from_matrix(exact), exact, rtol=0, atol=1e-14)
    # 1e-14: an SVD (backward error ~ 3 * eps) and one 3x3 product of O(1) numbers


def test_from_matrix_refuses_a_reflection() -> None:
    msg = r"^rotation matrix is a reflection \(det = -1\), not a rotation$"
    with pytest.raises(ValueError, match=msg):
        rot.from_matrix(np.diag([1.0, 1.0, -1.0]))


def test_from_matrix_refuses_a_shear() -> None:
    shear = [[1, 0.032, 0], [0, 1, 0], [0, 0, 1]]
    # MᵀM − I has 0.032 off the diagonal and 0.032² = 1.0e-3 on it: max 3.2e-2
    msg = r"^rotation matrix is not orthonormal \(\|MᵀM − I\| = 3\.2e-2\)$"
    with pytest.raises(ValueError, match=msg):
        rot.from_matrix(shear)


def test_from_matrix_tolerance_is_honoured() -> None:
    m = np.eye(3)
    m[0, 0] = 1 + 1e-5  # |MᵀM − I| = 2e-5
    with pytest.raises(ValueError, match="not orthonormal"):
        rot.from_matrix(m)
    assert is_proper(rot.from_matrix(m, tol=1e-4))


@pytest.mark.parametrize("m", [np.eye(2), [[1, 0, 0], [0, 1, 0]], np.full((3, 3), np.nan)])
def test_from_matrix_rejects_wrong_shape_or_non_finite(m) -> None:
    with pytest.raises(ValueError, match="rotation matrix"):
        rot.from_matrix(m)


# ----------------------------------------------------------------------------- quaternion kit


def _scipy_quat(q: np.ndarray) -> Rotation:
    """scipy's Rotation of scalar-first quaternions (scipy is scalar-last)."""
    return Rotation.from_quat(np.asarray(q)[..., [1, 2, 3, 0]])


@settings(max_examples=200, deadline=None)
@given(st.lists(components, min_size=4, max_size=4).filter(lambda v: float(np.linalg.norm(v)) > 1e-3),
       st.lists(components, min_size=4, max_size=4).filter(lambda v: float(np.linalg.norm(v)) > 1e-3))
def test_quaternion_kit_matches_scipy(p, q) -> None:
    """Product, conjugate, matrix and back, axis-angle: against scipy (ATOL: module docstring)."""
    p, q = np.array(p), np.array(q)
    pu, qu = p / np.linalg.norm(p), q / np.linalg.norm(q)
    R = rot.quat_to_matrix(qu)
    np.testing.assert_allclose(R, _scipy_quat(qu).as_matrix(), rtol=0, atol=ATOL)
    np.testing.assert_allclose(R, rot.quaternion(q), rtol=0, atol=ATOL)  # the one-off form
    np.testing.assert_allclose(rot.quat_to_matrix(rot.quat_multiply(pu, qu)),
                               rot.quat_to_matrix(pu) @ R, rtol=0, atol=ATOL)
    np.testing.assert_allclose(rot.quat_to_matrix(rot.quat_conjugate(qu)), R.T, rtol=0, atol=ATOL)
    back = rot.quat_from_matrix(R)
    assert back[0] >= 0.0
    c = rot.quat_canonical(qu)  # w = 0: q and -q are both canonical
    assert min(np.max(np.abs(back - c)), np.max(np.abs(back + c))) <= ATOL
    axis, angle = rot.matrix_to_axis_angle(R)
    assert 0.0 <= angle <= math.pi
    assert angle == pytest.approx(_scipy_quat(qu).magnitude(), abs=1e-12)
    # the axis (either sign at a half turn) rebuilds the matrix; 1e-12: an axis near a
    # half turn or a zero turn carries ~eps/|v| of round-off
    np.testing.assert_allclose(rot.axis_angle(axis, angle), R, rtol=0, atol=1e-12)
    axis2, angle2 = rot.quat_to_axis_angle(qu)
    assert angle2 == pytest.approx(angle, abs=1e-12)
    if axis2 is not None:
        np.testing.assert_allclose(rot.axis_angle(axis2, angle2), R, rtol=0, atol=1e-12)


def test_axis_angle_edge_cases() -> None:
    """No rotation: no axis (quaternion) or the documented z (matrix); a half turn."""
    assert rot.quat_to_axis_angle(np.array([1.0, 0, 0, 0])) == (None, 0.0)
    axis, angle = rot.matrix_to_axis_angle(np.eye(3))
    assert angle == 0.0 and axis.tolist() == [0.0, 0.0, 1.0]
    axis, angle = rot.matrix_to_axis_angle(np.diag([-1.0, -1.0, 1.0]))
    assert angle == pytest.approx(math.pi, abs=1e-15) and abs(axis[2]) == 1.0
    q = rot.quat_about_axis(np.array([0.0, 0.0, 1.0]), np.array([0.0, math.pi / 2]))
    np.testing.assert_allclose(rot.quat_to_matrix(q[1]) @ [1, 0, 0], [0, 1, 0], atol=1e-15)
    assert q.shape == (2, 4) and q[0].tolist() == [1.0, 0.0, 0.0, 0.0]
