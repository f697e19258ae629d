"""Tests of rbcli.core.inertia (combining parts, moving tensors) and rbcli.core.principal.

Invariants (hypothesis) and textbook values, each against an independent computation:

- principal moments do not change when the whole body is rotated;
- the parallel-axis theorem against the direct sum over point masses;
- a box split into two boxes, a cylinder into two shorter cylinders, equal the whole;
- the same body in mm/g and in m/kg gives the same SI result;
- a hole and then its filling restore the original;
- a body 10 km away keeps its inertia about its com (digits are kept);
- the course's square lamina, the two-blade fan at 45°, the cube;
- principal-axis conventions (ascending, sign rule, right-handed, degenerate planes on
  the body axes, ``free_axes``), stability flags, the equivalent box and ellipsoid,
  the rotation to the principal frame against scipy.

Tolerances: eigen-decompositions (LAPACK's symmetric solver is backward stable) and sums
of a few parallel-axis terms carry errors of a few ulp of the largest entry, ~1e-15
relative; assertions use 1e-12 relative to the largest moment unless a comment says why
a case needs more.
"""

from __future__ import annotations

import math
import textwrap
from decimal import Decimal
from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from rbcli.core import shapes as shp
from rbcli.core.inertia import (
    InputOverflow,
    MassProps,
    combine,
    inertia_about,
    inertia_report,
    moment_about_axis,
    tensor_problem,
)
from rbcli.core.principal import matrix_to_axis_angle, principal_axes, principal_report
from rbcli.body.model import load_text
from rbcli.body.partmodel import Part

RTOL = 1e-12  # round-off of eigh / a few parallel-axis sums, relative to the largest moment
FAST = settings(max_examples=40, deadline=None)


# --------------------------------------------------------------------------- helpers

def part(shape: str, mass: float, at=(0, 0, 0), R=None, subtract=False, **params) -> Part:
    geo = shp.geometry(shape, **params)
    R = np.eye(3) if R is None else np.asarray(R)
    return Part(
        name=shape, shape=shape, mass=float(mass), subtract=subtract,
        com=np.asarray(at, float) + R @ geo.com, inertia_com=mass * R @ geo.unit_inertia @ R.T,
    )


def point(mass: float, at) -> Part:
    return Part(name="p", shape="point", mass=float(mass), subtract=False,
                com=np.asarray(at, float), inertia_com=np.zeros((3, 3)))


def rotated(p: Part, Q: np.ndarray, shift=np.zeros(3)) -> Part:
    return Part(name=p.name, shape=p.shape, mass=p.mass, subtract=p.subtract,
                com=Q @ p.com + shift, inertia_com=Q @ p.inertia_com @ Q.T)


def assert_close(a, b, rtol=RTOL, scale=None):
    a, b = np.asarray(a, float), np.asarray(b, float)
    s = scale if scale is not None else max(float(np.max(np.abs(a))), float(np.max(np.abs(b))))
    assert float(np.max(np.abs(a - b))) <= rtol * s, (a, b)


def load(text: str):
    return load_text(textwrap.dedent(text), "t.yaml", Path.cwd())


sizes = st.floats(0.05, 1.0)
masses = st.floats(0.1, 10.0)
coords = st.floats(-1.0, 1.0)
quats = st.tuples(*[st.floats(-1, 1)] * 4).filter(lambda q: np.linalg.norm(q) > 0.2)


def rot(q) -> np.ndarray:
    return Rotation.from_quat(q).as_matrix()


@st.composite
def bodies(draw, n_min=1, n_max=4):
    n = draw(st.integers(n_min, n_max))
    out = []
    for _ in range(n):
        out.append(part(
            "box", draw(masses), at=draw(st.tuples(coords, coords, coords)), R=rot(draw(quats)),
            size=list(draw(st.tuples(sizes, sizes, sizes))),
        ))
    return out


# --------------------------------------------------------------------------- invariants

@FAST
@given(parts=bodies(), q=quats, shift=st.tuples(coords, coords, coords))
def test_principal_moments_do_not_change_when_the_whole_body_is_rotated(parts, q, shift):
    Q = rot(q)
    a = combine(parts)
    b = combine([rotated(p, Q, np.array(shift)) for p in parts])
    assert b.mass == pytest.approx(a.mass, rel=1e-14)  # the same masses summed in the same order
    assert_close(b.com, Q @ a.com + shift, scale=3.0)
    ma = principal_axes(a.inertia_com).moments
    mb = principal_axes(b.inertia_com).moments
    assert_close(ma, mb)


@FAST
@given(
    pts=st.lists(st.tuples(masses, st.tuples(coords, coords, coords)), min_size=1, max_size=6),
    P=st.tuples(st.floats(-5, 5), st.floats(-5, 5), st.floats(-5, 5)),
)
def test_parallel_axis_theorem_against_the_direct_sum_over_point_masses(pts, P):
    mp = combine([point(m, r) for m, r in pts])
    P = np.array(P)
    direct = np.zeros((3, 3))
    for m, r in pts:
        d = np.array(r) - P
        direct += m * (d @ d * np.eye(3) - np.outer(d, d))
    # inertia_about goes through the com (two shifts of up to ~(6 m)^2): the cancellation
    # costs a few ulp of the largest term m |d|^2, not of the result: scale by that
    scale = sum(m for m, _ in pts) * (np.max(np.abs(P)) + 1) ** 2 * 3
    assert_close(inertia_about(mp, P), direct, scale=scale)


@FAST
@given(a=sizes, b=sizes, c=sizes, m=masses, t=st.floats(0.05, 0.95), q=quats)
def test_a_box_split_into_two_boxes_equals_the_whole(a, b, c, m, t, q):
    R = rot(q)
    whole = combine([part("box", m, R=R, size=[a, b, c])])
    # left piece: length t a, centre at x = -a/2 + t a/2; right: (1 - t) a, centre at t a/2
    left = part("box", m * t, at=R @ [-a / 2 + t * a / 2, 0, 0], R=R, size=[t * a, b, c])
    right = part("box", m * (1 - t), at=R @ [t * a / 2, 0, 0], R=R, size=[(1 - t) * a, b, c])
    split = combine([left, right])
    assert split.mass == pytest.approx(m, rel=1e-14)
    assert_close(split.com, whole.com, scale=a)
    assert_close(split.inertia_com, whole.inertia_com)


@FAST
@given(r=sizes, L=sizes, ri=st.floats(0.0, 0.9), m=masses, t=st.floats(0.05, 0.95), n=quats)
def test_a_cylinder_split_into_two_shorter_cylinders_equals_the_whole(r, L, ri, m, t, n):
    R = rot(n)
    inner = ri * r
    whole = combine([part("cylinder", m, R=R, radius=r, length=L, inner_radius=inner)])
    lo = part("cylinder", m * t, at=R @ [0, 0, -L / 2 + t * L / 2], R=R, radius=r, length=t * L, inner_radius=inner)
    hi = part("cylinder", m * (1 - t), at=R @ [0, 0, t * L / 2], R=R, radius=r, length=(1 - t) * L, inner_radius=inner)
    split = combine([lo, hi])
    assert_close(split.com, whole.com, scale=L)
    assert_close(split.inertia_com, whole.inertia_com)


@settings(max_examples=25, deadline=None)
@given(
    dims=st.lists(st.integers(1, 999), min_size=3, max_size=3),
    pos=st.lists(st.integers(-999, 999), min_size=3, max_size=3),
    grams=st.integers(1, 99999),
    rod=st.integers(1, 999),
)
def test_the_same_body_in_mm_g_and_m_kg_gives_the_same_si_result(dims, pos, grams, rod):
    def m(x):  # millimetres as exact decimal metres
        return str(Decimal(x) / 1000)

    mm_g = load(f"""\
        units: {{length: mm, mass: g}}
        parts:
          - {{shape: box, size: {dims}, mass: {grams}, at: {pos}, rotate: {{axis: [1, 2, 3], angle: 40}}}}
          - {{shape: rod, length: {rod}, mass: 500, at: [0, 0, {rod}]}}
        """)
    si = load(f"""\
        parts:
          - {{shape: box, size: [{', '.join(m(x) for x in dims)}], mass: {m(grams)}, at: [{', '.join(m(x) for x in pos)}],
             rotate: {{axis: [1, 2, 3], angle: 40}}}}
          - {{shape: rod, length: {m(rod)}, mass: 0.5, at: [0, 0, {m(rod)}]}}
        """)
    a, b = combine(mm_g.parts), combine(si.parts)
    # each number is rounded once from an exact product (mm -> m): a few ulp per entry,
    # then the same ~10 operations: 1e-12 relative is the "~1e-12"
    assert a.mass == pytest.approx(b.mass, rel=1e-12)
    assert_close(a.com, b.com, scale=max(np.max(np.abs(b.com)), 1e-3))
    assert_close(a.inertia_com, b.inertia_com)


@FAST
@given(parts=bodies(), hole_r=st.floats(0.01, 0.05), hole_at=st.tuples(coords, coords, coords), q=quats)
def test_a_hole_then_its_filling_restores_the_original(parts, hole_r, hole_at, q):
    hole = part("cylinder", 0.3, at=hole_at, R=rot(q), subtract=True, radius=hole_r, length=0.1)
    fill = Part(name="fill", shape=hole.shape, mass=hole.mass, subtract=False, com=hole.com,
                inertia_com=hole.inertia_com)
    a = combine(parts)
    b = combine([*parts, hole, fill])
    assert b.mass == pytest.approx(a.mass, rel=1e-14)
    # the hole and the filling cancel term by term; what is left is round-off of sums whose
    # terms are at most (mass of all) x (2 m)^2: scale by that
    scale = (a.mass + 0.6) * 4
    assert_close(b.com, a.com, scale=2.0)
    assert_close(b.inertia_com, a.inertia_com, scale=scale)


@FAST
@given(parts=bodies(n_min=2), direction=quats)
def test_a_body_10_km_away_keeps_its_inertia_about_its_com(parts, direction):
    offset = 1e4 * rot(direction)[:, 0]  # 10 km in a random direction
    near = combine(parts)
    far = combine([rotated(p, np.eye(3), offset) for p in parts])
    # Part coms 10 km out are held to ulp(1e4) = 1.8e-12 m; offsets between parts of
    # ~0.05-2 m are then known to ~4e-12 / 0.05 ~ 1e-10 relative, and the inertia (~d^2)
    # to ~2e-10: 1e-9 keeps a margin of 5. (Summing about the origin instead of near the
    # parts would lose m |c|^2 ~ 1e8 x 1e-16 = 1e-8 kg m^2 absolute: ~1e-7 relative, and fail.)
    assert_close(far.inertia_com, near.inertia_com, rtol=1e-9)
    assert_close(far.com, near.com + offset, rtol=1e-15, scale=1e4)  # a few ulp of 1e4


# --------------------------------------------------------------------------- textbook

def test_square_lamina_about_a_corner_is_the_course_tensor():
    m, a = 3.0, 2.0
    body = load(f"parts:\n  - {{shape: plate, size: [{a}, {a}], mass: {m}, at: [{a / 2}, {a / 2}, 0]}}\n")
    mp = combine(body.parts)
    J = inertia_about(mp, np.zeros(3))
    course = m * a * a * np.array([[1 / 3, -1 / 4, 0], [-1 / 4, 1 / 3, 0], [0, 0, 2 / 3]])
    assert_close(J, course)
    # I about the diagonal = m a^2 / 12 (the lamina's own centroidal value, the diagonal
    # passes through its centre of mass)
    assert moment_about_axis(J, [1, 1, 0]) == pytest.approx(m * a * a / 12, rel=RTOL)
    # L for omega about x: L = J w = m a^2 w (1/3, -1/4, 0): it has a y-component
    res = inertia_report(mp, np.zeros(3), omega=np.array([2.0, 0, 0]))
    assert_close(res.angular_momentum, [m * a * a * 2 / 3, -m * a * a * 2 / 4, 0])
    assert res.kinetic_energy == pytest.approx(0.5 * 2 * 2 * m * a * a / 3, rel=RTOL)
    # angle between L and w: atan((1/4)/(1/3)) = atan(3/4) = 36.8699 deg
    assert res.angle_L_omega_deg == pytest.approx(math.degrees(math.atan(0.75)), rel=1e-12)
    # principal axes about the corner: along the diagonal (m a^2/12) and across it (7 m a^2/12)
    pr = principal_report(mp.mass, J, np.zeros(3))
    assert_close(pr.moments, m * a * a * np.array([1 / 12, 7 / 12, 2 / 3]))
    assert_close(pr.axes[0], np.array([1, 1, 0]) / math.sqrt(2), scale=1.0)
    # signs: the frame nearest the body's (45° about z, not 180° about an in-plane axis)
    assert_close(pr.axes[1], np.array([-1, 1, 0]) / math.sqrt(2), scale=1.0)
    assert_close(pr.axes[2], np.array([0, 0, 1]), scale=1.0)
    assert pr.rotation_angle_deg == pytest.approx(45.0, rel=1e-12)


def test_two_blade_fan_principal_axes_are_at_45_degrees():
    # two thin blades of mass m and length L from the hub along x and y. About the com
    # (L/4, L/4, 0): Jxx = Jyy = 5 m L^2/24 and Jxy = +m L^2/8 (worked by hand), so
    # tan 2 theta = 2 Ixy/(Ixx - Iyy) is infinite: theta = 45 degrees.
    m, L = 0.5, 0.4
    body = load(f"""\
        parts:
          - {{shape: rod, from: [0, 0, 0], to: [{L}, 0, 0], mass: {m}}}
          - {{shape: rod, from: [0, 0, 0], to: [0, {L}, 0], mass: {m}}}
        """)
    mp = combine(body.parts)
    assert_close(mp.com, [L / 4, L / 4, 0], scale=L)
    assert_close(mp.inertia_com[:2, :2], m * L * L * np.array([[5 / 24, 1 / 8], [1 / 8, 5 / 24]]))
    pr = principal_report(mp.mass, mp.inertia_com, mp.com)
    # moments 5/24 -+ 3/24: m L^2/12 across the bisector, m L^2/3 along it; 5 m L^2/12 about z
    assert_close(pr.moments, m * L * L * np.array([1 / 12, 1 / 3, 5 / 12]))
    theta = math.degrees(math.atan2(pr.axes[1][1], pr.axes[1][0]))
    assert theta == pytest.approx(45.0, abs=1e-9)  # atan2 of two equal components to ~1e-16
    assert_close(pr.axes[0], np.array([1, -1, 0]) / math.sqrt(2), scale=1.0)
    assert pr.stable == (True, False, True)


def test_cube_is_spherical_every_axis_principal():
    a, rho = 0.1, 7850.0
    body = load(f"parts:\n  - {{shape: box, size: [{a}, {a}, {a}], density: {rho}}}\n")
    mp = combine(body.parts)
    m = rho * a**3
    pa = principal_axes(mp.inertia_com)
    assert pa.symmetry == "spherical" and pa.free_axes == (0, 1, 2) and pa.unique_axis is None
    assert_close(pa.moments, [m * a * a / 6] * 3)
    assert np.array_equal(pa.axes, np.eye(3))
    # any axis: n.J.n = m a^2/6
    assert moment_about_axis(mp.inertia_com, [0.3, -0.5, 0.8]) == pytest.approx(m * a * a / 6, rel=RTOL)


# --------------------------------------------------------------------------- conventions

def _check_conventions(pa, J):
    A = pa.axes
    assert np.all(np.diff(pa.moments) >= 0)  # ascending
    assert_close(A @ A.T, np.eye(3), scale=1.0)  # orthonormal rows, to round-off
    assert np.linalg.det(A) == pytest.approx(1.0, abs=1e-12)  # right-handed
    # signs: the proper rotation nearest the body frame (no other proper sign choice has a
    # larger trace, i.e. a smaller rotation angle)
    for flip in ([1, -1, -1], [-1, 1, -1], [-1, -1, 1]):
        assert np.trace(A * np.array(flip, dtype=float)[:, None]) <= np.trace(A) + 1e-12
    # the axes diagonalise J with the moments on the diagonal
    scale = float(np.max(np.abs(pa.moments)))
    assert_close(A @ J @ A.T, np.diag(pa.moments), scale=scale)


@FAST
@given(parts=bodies())
def test_principal_axes_conventions_hold_for_random_bodies(parts):
    J = combine(parts).inertia_com
    pa = principal_axes(J)
    assume(pa.symmetry == "asymmetric")  # random boxes are asymmetric but for a null set
    _check_conventions(pa, J)
    assert pa.free_axes == () and pa.unique_axis is None
    res = principal_report(1.0, J, np.zeros(3))
    assert res.stable == (True, False, True)  # smallest and largest stable, intermediate not


@FAST
@given(n=quats, slender=st.booleans())
def test_a_body_of_revolution_is_symmetric_about_its_axis(n, slender):
    R = rot(n)
    r, L = (0.05, 1.0) if slender else (1.0, 0.05)
    J = combine([part("cylinder", 2.0, R=R, radius=r, length=L)]).inertia_com
    pa = principal_axes(J)
    assert pa.symmetry == "symmetric"
    u = 0 if slender else 2  # prolate: the axis moment is the smallest; oblate: the largest
    assert pa.unique_axis == u and pa.free_axes == tuple(i for i in range(3) if i != u)
    assert abs(abs(pa.axes[u] @ R[:, 2]) - 1) <= 1e-12  # along the cylinder's axis
    _check_conventions(pa, J)


def test_degenerate_axes_are_the_body_axes_where_possible():
    # a z cylinder: the free axes are exactly x and y
    J = combine([part("cylinder", 1.0, radius=0.5, length=0.1)]).inertia_com
    pa = principal_axes(J)
    assert pa.symmetry == "symmetric" and pa.unique_axis == 2
    assert np.array_equal(pa.axes, np.eye(3))
    # a cylinder along (1, 0, 1): its cross-section plane contains the body y axis exactly
    R = Rotation.from_euler("y", 45, degrees=True).as_matrix()
    J = combine([part("cylinder", 1.0, R=R, radius=0.05, length=1.0)]).inertia_com
    pa = principal_axes(J)
    free = [pa.axes[i] for i in pa.free_axes]
    assert any(np.allclose(np.abs(v), [0, 1, 0], rtol=0, atol=1e-12) for v in free)
    assert principal_report(1.0, J, np.zeros(3)).free_axes == (1, 2)


@pytest.mark.parametrize("tilt", [1e-7, 1e-10, 1e-13])
def test_a_slightly_tilted_symmetric_body_keeps_its_tilt(tilt):
    # the unique axis of a cylinder tilted by `tilt` rad about x is (0, -sin t, cos t):
    # it must not be snapped onto z (an error of `tilt` rad, not round-off)
    R = Rotation.from_rotvec([tilt, 0, 0]).as_matrix()
    pa = principal_axes(combine([part("cylinder", 1.0, R=R, radius=0.05, length=1.0)]).inertia_com)
    assert pa.unique_axis == 0
    # eigh on a well-separated pair: ~1e-16 absolute; the old snap erred by `tilt` (>= 1e-13)
    assert_close(pa.axes[0], [0, -math.sin(tilt), math.cos(tilt)], rtol=1e-15, scale=1.0)


def test_symmetry_threshold_is_relative_1e_9():
    assert principal_axes(np.diag([1.0, 1.0 + 1e-11, 1.5])).symmetry == "symmetric"
    assert principal_axes(np.diag([1.0, 1.0 + 1e-6, 1.5])).symmetry == "asymmetric"


@FAST
@given(parts=bodies())
def test_the_equivalent_box_and_ellipsoid_reproduce_the_moments(parts):
    mp = combine(parts)
    res = principal_report(mp.mass, mp.inertia_com, mp.com)
    I1, I2, I3 = res.moments
    a, b, c = res.equivalent_box
    m = mp.mass
    # uniform box a x b x c along the principal axes: I1 = m (b^2 + c^2)/12, ...
    assert_close([m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12], [I1, I2, I3])
    a, b, c = res.equivalent_ellipsoid
    # uniform ellipsoid of semi-axes a, b, c: I1 = m (b^2 + c^2)/5, ...
    assert_close([m * (b * b + c * c) / 5, m * (a * a + c * c) / 5, m * (a * a + b * b) / 5], [I1, I2, I3])


def test_a_box_is_its_own_equivalent_box():
    mp = combine([part("box", 2.0, size=[0.3, 0.2, 0.1])])
    res = principal_report(mp.mass, mp.inertia_com, mp.com)
    # the smallest moment is about the longest side: sides in the order 0.3, 0.2, 0.1
    assert_close(res.equivalent_box, [0.3, 0.2, 0.1], scale=0.3)
    ell = combine([part("ellipsoid", 2.0, semi_axes=[0.3, 0.2, 0.1])])
    res = principal_report(ell.mass, ell.inertia_com, ell.com)
    assert_close(res.equivalent_ellipsoid, [0.3, 0.2, 0.1], scale=0.3)


@FAST
@given(rv=st.tuples(*[st.floats(-3.1, 3.1)] * 3))
def test_matrix_to_axis_angle_matches_scipy(rv):
    R = Rotation.from_rotvec(rv).as_matrix()
    axis, angle = matrix_to_axis_angle(R)
    back = Rotation.from_rotvec(np.asarray(axis) * angle).as_matrix()
    assert_close(back, R, scale=1.0)  # both built from the same rotation: ~1e-15
    assert 0 <= angle <= math.pi + 1e-15


def test_rotation_to_principal_frame_takes_body_axes_onto_principal_axes():
    R = Rotation.from_euler("ZYX", [30, 20, 10], degrees=True).as_matrix()
    mp = combine([part("box", 1.0, R=R, size=[0.3, 0.2, 0.1])])
    res = principal_report(mp.mass, mp.inertia_com, mp.com)
    Q = Rotation.from_rotvec(np.asarray(res.rotation_axis) * math.radians(res.rotation_angle_deg)).as_matrix()
    assert_close(Q, res.axes.T, scale=1.0)  # column i of Q = principal axis i
    # direction angles: angle of principal axis i from body axis j
    assert_close(np.cos(np.radians(res.direction_angles_deg)), res.axes, scale=1.0)


# --------------------------------------------------------------------------- the rest

def test_tensor_problem_says_what_is_wrong():
    assert tensor_problem(np.diag([1.0, 2.0, 2.5])) is None
    assert tensor_problem(np.diag([1.0, 1.0, 2.0])) is None  # a lamina: equality allowed
    assert "not symmetric" in tensor_problem(np.array([[1, 0.1, 0], [0, 1, 0], [0, 0, 1.0]]))
    assert "negative principal moment" in tensor_problem(np.diag([-1.0, 2.0, 2.0]))
    assert "triangle inequality" in tensor_problem(np.diag([1.0, 1.0, 2.01]))
    assert "finite" in tensor_problem(np.diag([1.0, np.inf, 1.0]))


def test_combine_refuses_no_parts_and_non_positive_mass():
    with pytest.raises(ValueError, match="no parts"):
        combine([])
    p = point(1.0, [0, 0, 0])
    hole = Part(name="h", shape="point", mass=2.0, subtract=True, com=np.zeros(3), inertia_com=np.zeros((3, 3)))
    with pytest.raises(ValueError, match="total mass is -1"):
        combine([p, hole])


def test_inertia_report_refuses_overflow_and_zero_axes_naming_the_input():
    mp = MassProps(1.0, np.zeros(3), np.eye(3))
    with pytest.raises(InputOverflow) as info:
        inertia_report(mp, np.array([1e200, 0, 0]))
    assert info.value.param == "reference"
    with pytest.raises(InputOverflow) as info:
        inertia_report(mp, np.zeros(3), omega=np.array([1e300, 0, 0]))
    assert info.value.param == "omega"
    with pytest.raises(InputOverflow) as info:
        inertia_report(mp, np.zeros(3), axis=np.zeros(3))
    assert info.value.param == "axis"
    # a tiny but non-zero axis is a direction like any other
    r = inertia_report(mp, np.zeros(3), axis=np.array([1e-320, 0, 0]))
    assert r.axis.tolist() == [1.0, 0.0, 0.0] and r.axis_moment == 1.0
