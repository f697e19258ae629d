"""The classic one- and two-plane field-balancing solves (rbcli.core.field.classic) against
the published cases T19-T21 (physics sheet balance.md §5) and exact synthetic data."""

from __future__ import annotations

import cmath
import math

import numpy as np
import pytest

from rbcli.core.balance import phasor
from rbcli.core.field.classic import field_single_plane, field_two_plane


def test_t19_single_plane():
    r = field_single_plane(phasor(6.0, 30), phasor(4.0, 110), phasor(10, 0))
    assert abs(r.influence) == pytest.approx(0.66079, rel=1e-5)
    assert math.degrees(cmath.phase(r.influence)) == pytest.approx(173.406, abs=1e-3)
    assert r.mass == pytest.approx(9.0800, rel=1e-5)
    assert r.angle_deg == pytest.approx(36.594, abs=1e-3)
    assert r.mass_trial_on == pytest.approx(6.0533, rel=1e-5)
    assert r.angle_trial_on_deg == pytest.approx(116.594, abs=1e-3)
    assert abs(r.predicted_residual) < 1e-14  # linear model: V0 + H W = 0 to round-off of ~6
    assert not r.small_response


def test_t20_two_plane_bk():
    r = field_two_plane(
        [phasor(170, 112), phasor(53, 78)],
        [phasor(235, 94), phasor(58, 68)],
        [phasor(185, 115), phasor(77, 104)],
        phasor(1.15, 0),
        phasor(1.15, 0),
    )
    # published: 1.979 g @ 236.2, 1.071 g @ 121.8 (printed to 4 s.f. / 0.1 deg)
    assert r.masses[0] == pytest.approx(1.979, abs=5e-4)
    assert r.angles_deg[0] == pytest.approx(236.2, abs=0.05)
    assert r.masses[1] == pytest.approx(1.071, abs=5e-4)
    assert r.angles_deg[1] == pytest.approx(121.8, abs=0.05)
    assert r.cond == pytest.approx(2.70, abs=0.005)
    # alpha = [[78.433 @ 58.4, 15.340 @ 145.3], [9.462 @ 10.2, 32.560 @ 142.4]]
    expect = [[(78.433, 58.4), (15.340, 145.3)], [(9.462, 10.2), (32.560, 142.4)]]
    for i in range(2):
        for j in range(2):
            amp, ph = expect[i][j]
            assert abs(r.influence[i, j]) == pytest.approx(amp, abs=5e-4)
            assert math.degrees(cmath.phase(r.influence[i, j])) == pytest.approx(ph, abs=0.05)
    assert not r.ill_conditioned and r.warnings == ()


def test_t21_two_plane_synthetic_and_mirror():
    v0 = [(21.6076, 49.52), (12.0102, 299.16)]
    va = [(31.5134, 46.51), (12.6512, 310.41)]
    vb = [(24.4405, 51.98), (12.1788, 342.84)]

    def run(sign):
        return field_two_plane(
            [phasor(a, sign * p) for a, p in v0],
            [phasor(a, sign * p) for a, p in va],
            [phasor(a, sign * p) for a, p in vb],
            phasor(5, 0),
            phasor(5, 0),
        )

    r = run(+1)
    # 12.0002 g @ 200.007, 8.0002 g @ 45.001; cond 1.83
    assert r.masses[0] == pytest.approx(12.0002, abs=5e-5)
    assert r.angles_deg[0] == pytest.approx(200.007, abs=1e-3)
    assert r.masses[1] == pytest.approx(8.0002, abs=5e-5)
    assert r.angles_deg[1] == pytest.approx(45.001, abs=1e-3)
    assert r.cond == pytest.approx(1.83, abs=0.005)
    # phases counted the other way with trials at 0 deg: mirrored, 200.007 -> 159.993
    m = run(-1)
    assert m.angles_deg[0] == pytest.approx(159.993, abs=1e-3)
    assert m.masses[0] == pytest.approx(r.masses[0], rel=1e-12)


def test_two_plane_cumulative_exact():
    alpha = np.array([[phasor(3.0, 40), phasor(1.2, 160)], [phasor(0.8, -20), phasor(2.5, 100)]])
    heavy = np.array([phasor(7.0, 33), phasor(4.0, 250)])  # true unbalance in the two planes
    TA, TB = phasor(5, 10), phasor(3, 200)
    V0 = alpha @ heavy
    VA = V0 + alpha[:, 0] * TA
    VB = VA + alpha[:, 1] * TB  # trial A left on during run B
    r = field_two_plane(V0, VA, VB, TA, TB, cumulative=True)
    # the correction is minus the heavy spots; a 2x2 complex solve: round-off ~1e-15 relative
    assert r.corrections == pytest.approx(-heavy, rel=1e-12)
    assert r.influence == pytest.approx(alpha, rel=1e-12)
    assert r.corrections_trials_on == pytest.approx(-heavy - np.array([TA, TB]), rel=1e-12)
    # read as non-cumulative the same data give a different (wrong) answer
    w = field_two_plane(V0, VA, VB, TA, TB)
    assert not np.allclose(w.corrections, -heavy, rtol=1e-3)


def test_field_warnings_and_errors():
    # nearly parallel columns: ill-conditioned
    alpha = np.array([[1.0, 1.0], [1.0, 1.02]], dtype=complex)
    V0 = np.array([1.0 + 0.5j, 0.3 - 1j])
    TA, TB = 1.0, 1.0
    r = field_two_plane(V0, V0 + alpha[:, 0] * TA, V0 + alpha[:, 1] * TB, TA, TB)
    assert r.ill_conditioned and r.cond > 50
    assert any("ill-conditioned" in w for w in r.warnings)
    # small response: a trial changing the reading by 10 % and 2 deg
    s = field_single_plane(phasor(10, 0), phasor(11, 2), phasor(1, 0))
    assert s.small_response and s.warnings
    # 30 % amplitude change is enough
    assert not field_single_plane(phasor(10, 0), phasor(13, 2), phasor(1, 0)).small_response
    with pytest.raises(ValueError):
        field_single_plane(1 + 1j, 1 + 1j, 1.0)
    with pytest.raises(ValueError):
        field_single_plane(1 + 1j, 2 + 1j, 0.0)
    with pytest.raises(ValueError):  # singular: plane B has no effect
        field_two_plane([1, 1j], [2, 1j], [1, 1j], 1.0, 1.0)
