"""The stacked rotation constructors of rbcli.core.rotation (``*_rows``, used by the body
loader for all its parts at once) agree BIT FOR BIT with the one-rotation functions: the
loader's outputs (and the golden files) must not depend on whether a part was placed alone
or with thousands of others. Exact equality, no tolerance: both sides do the same IEEE
operations in the same order (see the module); equal bytes, so that a zero's sign counts
too (``np.array_equal`` has ``-0.0 == 0.0``)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rbcli.core import rotation as rot


def same_bits(a, b) -> bool:
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and a.dtype == b.dtype and a.tobytes() == b.tobytes()


@pytest.fixture(scope="module")
def rng():
    return np.random.default_rng(20261125)


def _vectors(rng, k, n):
    v = rng.normal(size=(k, n)) * np.exp(rng.uniform(-30, 30, size=(k, 1)))
    v[0] = 0.0
    v[0, -1] = 1.0  # exactly along the last axis
    v[1] = 0.0
    v[1, -1] = -3.0
    v[2, :2] = [1e-300, 0.0]
    return v


def test_axis_to_z_rows_is_axis_to_z(rng):
    d = _vectors(rng, 500, 3)
    d[3] = [1e-13, -2e-13, -1.0]  # within round-off of -z
    d[4:10] = [[-0.0, 0.0, 2.0], [0.0, -0.0, -2.0], [-1.0, 0.0, 0.0], [0.0, -1.0, 0.0],
               [0.0, 1.0, -0.0], [1e-300, -1e-300, -1.0]]  # signed zeros, the axes
    rows = rot.axis_to_z_rows(d)
    for k in range(len(d)):
        assert same_bits(rows[k], rot.axis_to_z(d[k])), k


def test_axis_angle_rows_is_axis_angle(rng):
    a = _vectors(rng, 500, 3)
    t = rng.uniform(-10, 10, size=len(a))
    t[:6] = [0.0, math.pi, -1e-9, -0.0, -math.pi, 2 * math.pi]
    rows = rot.axis_angle_rows(a, t)
    for k in range(len(a)):
        assert same_bits(rows[k], rot.axis_angle(a[k], t[k])), k


@pytest.mark.parametrize("seq", ["ZYX", "xyz", "ZXZ", "XYZ", "zy", "X", "yzy"])
def test_euler_rows_is_euler(rng, seq):
    a = rng.uniform(-4, 4, size=(200, len(seq)))
    rows = rot.euler_rows(a, seq)
    for k in range(len(a)):
        assert same_bits(rows[k], rot.euler(a[k], seq)), k


def test_quaternion_rows_is_quaternion(rng):
    q = _vectors(rng, 500, 4)
    rows = rot.quaternion_rows(q)
    for k in range(len(q)):
        assert same_bits(rows[k], rot.quaternion(q[k])), k


def test_nearest_rotation_rows_is_from_matrix(rng):
    m = rot.quaternion_rows(rng.normal(size=(300, 4)))
    m = np.round(m, 7)  # typed with 7 decimals: not quite orthonormal
    rows = rot.nearest_rotation_rows(m)
    for k in range(len(m)):
        assert same_bits(rows[k], rot.from_matrix(m[k])), k


def test_unit_rows_is_unit(rng):
    v = _vectors(rng, 300, 3)
    rows = rot.unit_rows(v)
    for k in range(len(v)):
        assert same_bits(rows[k], rot._unit(v[k])), k


def test_from_specs_of_one_kind_is_from_specs_of_a_mix(rng):
    # from_specs makes a batch of one kind without the identity it fills in for a mix
    d = _vectors(rng, 50, 3)
    specs = ([("axis", list(v)) for v in d]
             + [("axis-angle", list(v), float(a)) for v, a in zip(d, rng.uniform(-7, 7, 50))]
             + [("euler", list(a), "zyx") for a in rng.uniform(-4, 4, (50, 3))]
             + [("quaternion", list(q)) for q in _vectors(rng, 50, 4)]
             + [("R", rot.axis_to_z(v)) for v in d[3:]]
             + [("matrix", rot.axis_to_z(v).tolist()) for v in d[3:]])
    mixed = rot.from_specs([None, *specs])
    assert same_bits(mixed[0], np.eye(3))
    for k, spec in enumerate(specs):
        assert same_bits(rot.from_specs([spec])[0], mixed[k + 1]), spec[0]
    kinds = {}
    for k, spec in enumerate(specs):
        kinds.setdefault(spec[0], []).append(k)
    for kind, idx in kinds.items():
        assert same_bits(rot.from_specs([specs[k] for k in idx]), mixed[[k + 1 for k in idx]]), kind
    assert same_bits(rot.from_specs([None, None]), np.array([np.eye(3)] * 2))


@pytest.mark.parametrize("k", [1, 2, 3, 7])
def test_small_batches_are_the_single_rotations(rng, k):
    """The batches of a small body (one to a few parts of a kind) and of mixed kinds."""
    for _ in range(40):
        d = _vectors(rng, 8, 3)[rng.permutation(8)[:k]]
        t = rng.uniform(-7, 7, size=k)
        for got, want in zip(rot.axis_to_z_rows(d), (rot.axis_to_z(v) for v in d)):
            assert same_bits(got, want)
        for got, want in zip(rot.axis_angle_rows(d, t), (rot.axis_angle(v, a) for v, a in zip(d, t))):
            assert same_bits(got, want)
        specs = [None if i % 3 == 0 else ("axis", list(v)) for i, v in enumerate(d)]
        for got, spec in zip(rot.from_specs(specs), specs):
            want = np.eye(3) if spec is None else rot.axis_to_z(rot.unit_rows(np.array([spec[1]]))[0])
            assert same_bits(got, want)


def test_unit_lists_is_unit_rows(rng):
    """The axis path's unit vectors from lists (no arrays for one part): unit_rows' bytes."""
    v = _vectors(rng, 300, 3)
    for k in (1, 2, 300):
        rows = rot._unit_lists(v[:k].tolist())
        assert same_bits(np.array(rows), rot.unit_rows(v[:k]))
