"""The classic one- and two-plane field-balancing solves (rbcli.core.field.solve.classic)
against the published cases T19-T21 (physics sheet balance.md §5) and exact synthetic data."""

from __future__ import annotations

import cmath
import math

import numpy as np
import pytest

from rbcli.core.balance import phasor
from rbcli.core.field.solve import classic, small_response


def one(v0, v1, t):
    alpha, W, resid, det, cond = classic([v0], [[v1]], [t], False)
    return alpha[0, 0], W[0], resid[0]


def two(v0, va, vb, ta, tb, cumulative=False):
    return classic(v0, [va, vb], [ta, tb], cumulative)


def test_t19_single_plane():
    H, W, r = one(phasor(6.0, 30), phasor(4.0, 110), phasor(10, 0))
    assert abs(H) == pytest.approx(0.66079, rel=1e-5)
    assert math.degrees(cmath.phase(H)) == pytest.approx(173.406, abs=1e-3)
    assert abs(W) == pytest.approx(9.0800, rel=1e-5)
    assert math.degrees(cmath.phase(W)) == pytest.approx(36.594, abs=1e-3)
    assert abs(W - phasor(10, 0)) == pytest.approx(6.0533, rel=1e-5)
    assert abs(r) < 1e-14  # linear model: V0 + H W = 0 to round-off of ~6
    assert not small_response(phasor(6.0, 30), phasor(4.0, 110))


def test_t20_two_plane_bk():
    alpha, W, _, det, cond = two([phasor(170, 112), phasor(53, 78)], [phasor(235, 94), phasor(58, 68)],
                                 [phasor(185, 115), phasor(77, 104)], phasor(1.15, 0), phasor(1.15, 0))
    # published: 1.979 g @ 236.2, 1.071 g @ 121.8 (printed to 4 s.f. / 0.1 deg)
    assert abs(W[0]) == pytest.approx(1.979, abs=5e-4)
    assert math.degrees(cmath.phase(W[0])) % 360 == pytest.approx(236.2, abs=0.05)
    assert abs(W[1]) == pytest.approx(1.071, abs=5e-4)
    assert math.degrees(cmath.phase(W[1])) == pytest.approx(121.8, abs=0.05)
    assert cond == pytest.approx(2.70, abs=0.005)
    # alpha = [[78.433 @ 58.4, 15.340 @ 145.3], [9.462 @ 10.2, 32.560 @ 142.4]]
    expect = [[(78.433, 58.4), (15.340, 145.3)], [(9.462, 10.2), (32.560, 142.4)]]
    for i in range(2):
        for j in range(2):
            amp, ph = expect[i][j]
            assert abs(alpha[i, j]) == pytest.approx(amp, abs=5e-4)
            assert math.degrees(cmath.phase(alpha[i, j])) == pytest.approx(ph, abs=0.05)


def test_t21_two_plane_synthetic_and_mirror():
    v0 = [(21.6076, 49.52), (12.0102, 299.16)]
    va = [(31.5134, 46.51), (12.6512, 310.41)]
    vb = [(24.4405, 51.98), (12.1788, 342.84)]

    def run(sign):
        return two(*([phasor(a, sign * p) for a, p in x] for x in (v0, va, vb)), phasor(5, 0), phasor(5, 0))

    _, W, _, _, cond = run(+1)
    # 12.0002 g @ 200.007, 8.0002 g @ 45.001; cond 1.83
    assert abs(W[0]) == pytest.approx(12.0002, abs=5e-5)
    assert math.degrees(cmath.phase(W[0])) % 360 == pytest.approx(200.007, abs=1e-3)
    assert abs(W[1]) == pytest.approx(8.0002, abs=5e-5)
    assert math.degrees(cmath.phase(W[1])) == pytest.approx(45.001, abs=1e-3)
    assert cond == pytest.approx(1.83, abs=0.005)
    # phases counted the other way with trials at 0 deg: mirrored, 200.007 -> 159.993
    m = run(-1)[1]
    assert math.degrees(cmath.phase(m[0])) % 360 == pytest.approx(159.993, abs=1e-3)
    assert abs(m[0]) == pytest.approx(abs(W[0]), rel=1e-12)


def test_two_plane_cumulative_exact():
    alpha = np.array([[phasor(3.0, 40), phasor(1.2, 160)], [phasor(0.8, -20), phasor(2.5, 100)]])
    heavy = np.array([phasor(7.0, 33), phasor(4.0, 250)])  # true unbalance in the two planes
    TA, TB = phasor(5, 10), phasor(3, 200)
    V0 = alpha @ heavy
    VA = V0 + alpha[:, 0] * TA
    VB = VA + alpha[:, 1] * TB  # trial A left on during run B
    a, W, *_ = two(V0, VA, VB, TA, TB, cumulative=True)
    # the correction is minus the heavy spots; a 2x2 complex solve: round-off ~1e-15 relative
    assert W == pytest.approx(-heavy, rel=1e-12)
    assert a == pytest.approx(alpha, rel=1e-12)
    # read as non-cumulative the same data give a different (wrong) answer
    assert not np.allclose(two(V0, VA, VB, TA, TB)[1], -heavy, rtol=1e-3)


def test_field_warnings_and_errors():
    # nearly parallel columns: ill-conditioned
    alpha = np.array([[1.0, 1.0], [1.0, 1.02]], dtype=complex)
    V0 = np.array([1.0 + 0.5j, 0.3 - 1j])
    assert two(V0, V0 + alpha[:, 0], V0 + alpha[:, 1], 1.0, 1.0)[4] > 50
    # small response: a trial changing the reading by 10 % and 2 deg; 30 % is enough
    assert small_response(phasor(10, 0), phasor(11, 2))
    assert not small_response(phasor(10, 0), phasor(13, 2))
    assert small_response(0j, 0j) and not small_response(1j, 0j)
    with pytest.raises(ValueError):
        one(1 + 1j, 1 + 1j, 1.0)
    with pytest.raises(ValueError):  # singular: plane B has no effect
        two([1, 1j], [2, 1j], [1, 1j], 1.0, 1.0)
