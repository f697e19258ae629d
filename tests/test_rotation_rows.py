"""The stacked rotation constructors of rbcli.core.rotation (``*_rows``, used by the body
loader for all its parts at once) agree BIT FOR BIT with the one-rotation functions: the
loader's outputs (and the golden files) must not depend on whether a part was placed alone
or with thousands of others. Exact equality, no tolerance: both sides do the same IEEE
operations in the same order (see the module)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rbcli.core import rotation as rot


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
    rows = rot.axis_to_z_rows(d)
    for k in range(len(d)):
        assert np.array_equal(rows[k], rot.axis_to_z(d[k])), k


def test_axis_angle_rows_is_axis_angle(rng):
    a = _vectors(rng, 500, 3)
    t = rng.uniform(-10, 10, size=len(a))
    t[:3] = [0.0, math.pi, -1e-9]
    rows = rot.axis_angle_rows(a, t)
    for k in range(len(a)):
        assert np.array_equal(rows[k], rot.axis_angle(a[k], t[k])), k


@pytest.mark.parametrize("seq", ["ZYX", "xyz", "ZXZ", "XYZ", "zy", "X", "yzy"])
def test_euler_rows_is_euler(rng, seq):
    a = rng.uniform(-4, 4, size=(200, len(seq)))
    rows = rot.euler_rows(a, seq)
    for k in range(len(a)):
        assert np.array_equal(rows[k], rot.euler(a[k], seq)), k


def test_quaternion_rows_is_quaternion(rng):
    q = _vectors(rng, 500, 4)
    rows = rot.quaternion_rows(q)
    for k in range(len(q)):
        assert np.array_equal(rows[k], rot.quaternion(q[k])), k


def test_nearest_rotation_rows_is_from_matrix(rng):
    m = rot.quaternion_rows(rng.normal(size=(300, 4)))
    m = np.round(m, 7)  # typed with 7 decimals: not quite orthonormal
    rows = rot.nearest_rotation_rows(m)
    for k in range(len(m)):
        assert np.array_equal(rows[k], rot.from_matrix(m[k])), k


def test_unit_rows_is_unit(rng):
    v = _vectors(rng, 300, 3)
    rows = rot.unit_rows(v)
    for k in range(len(v)):
        assert np.array_equal(rows[k], rot._unit(v[k])), k
