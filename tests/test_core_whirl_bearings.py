"""rbcli.core.whirl with the bearings engineers have (issue 35): full 2x2 coefficients,
tables against speed, modes followed by their shapes, thresholds of instability, the
critical speed map — against an independent eigen-solve written here.

The independent solver: the 4x4 matrices of q = (x, y, theta_x, theta_y) written out entry
by entry from the equations of motion (every one of the eight coefficients of each
bearing), the coefficients of a table interpolated by ``numpy.interp``, and the mass-
normalised first-order form solved by ``scipy.linalg.eig``; roots by ``scipy.optimize``.

The published example: a plain journal bearing's dynamic coefficients against the
Sommerfeld number, Someya (ed.), *Journal-Bearing Databook*, Springer 1989, Table 1 (p. 14:
two axial grooves, L/D = 0.5), as transcribed in github.com/VictorLier/Tribology
(Assignment2/Someya.py); the rows with S = 0.0315 ... 5.96 appear (to the printed digits) in
Lund & Thomsen (1978), which ROSS's test_fluid_film_literature.py cites. examples/
journal_bearing.csv is that table made dimensional for the example's bearing.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rbcli.core import whirl as W
from rbcli.core.whirl.critical import critical_map
from rbcli.core.whirl.stability import stability

ROOT = Path(__file__).resolve().parent.parent
# eigenvalues of the 8x8 companion carry round-off of ~eps |A| relative to |lambda|; the ranges
# drawn here keep frequencies within ~1e3 of each other, so 1e-9 leaves four decades and still
# catches a wrong term (any coefficient in the wrong place moves a root by >= 1e-4 here)
RTOL = 1e-9

# Someya Table 1 (two-axial-groove bearing, L/D = 0.5): S, eps, Kxx, Kxy, Kyx, Kyy, Bxx, Bxy, Byx, Byy
SOMEYA = np.array([
    [5.96, 0.075, 1.77, 13.6, -13.1, 2.72, 27.2, 2.06, 2.06, 14.9],
    [4.43, 0.100, 1.75, 10.3, -9.66, 2.70, 20.6, 2.08, 2.08, 11.4],
    [2.07, 0.200, 1.88, 5.63, -4.41, 2.56, 11.2, 2.22, 2.22, 6.43],
    [1.24, 0.300, 2.07, 4.27, -2.56, 2.34, 8.50, 2.32, 2.32, 4.73],
    [0.798, 0.400, 2.39, 3.75, -1.57, 2.17, 7.32, 2.24, 2.24, 3.50],
    [0.517, 0.500, 2.89, 3.57, -0.924, 2.03, 6.81, 2.10, 2.10, 2.60],
    [0.323, 0.600, 3.65, 3.62, -0.427, 1.92, 6.81, 2.08, 2.08, 2.06],
    [0.187, 0.700, 4.92, 3.88, 0.0235, 1.83, 7.32, 2.16, 2.16, 1.70],
    [0.135, 0.750, 5.90, 4.11, 0.258, 1.80, 7.65, 2.10, 2.10, 1.46],
    [0.0926, 0.800, 7.35, 4.46, 0.527, 1.78, 8.17, 2.05, 2.05, 1.24],
    [0.0582, 0.850, 9.56, 4.92, 0.805, 1.73, 9.12, 2.06, 2.06, 1.06],
    [0.0315, 0.900, 13.8, 5.76, 1.24, 1.72, 10.6, 2.03, 2.03, 0.846],
])
#: the example's bearing (examples/journal_bearing.csv): D = 100 mm, L = 50 mm, c = 75 um,
#: oil 0.010 Pa s, load half the weight of examples/journal_rotor.yaml (120.841 kg)
D, L, CLEAR, MU = 0.1, 0.05, 75e-6, 0.010
MASS = 7850.0 * math.pi * (0.05**2 * 1.0 + 0.2**2 * 0.06)
LOAD = MASS * 9.80665 / 2


def journal_table(load: float = LOAD) -> tuple[np.ndarray, np.ndarray]:
    """(speeds rad/s ascending, (S, 8) coefficients) of the published table for the example's
    bearing under ``load`` (N): N = S W / (mu L D (R/c)^2) rev/s, k = K W / c, c_ij = B W /
    (c omega)."""
    N = SOMEYA[:, 0] * load / (MU * L * D * (D / 2 / CLEAR) ** 2)
    om = 2 * math.pi * N
    k = SOMEYA[:, 2:6] * load / CLEAR
    b = SOMEYA[:, 6:10] * load / (CLEAR * om[:, None])
    return om[::-1], np.column_stack([k, b])[::-1]


def journal_rotor() -> W.Rotor:
    """examples/journal_rotor.yaml by hand: a 100 mm x 1 m steel shaft and a 400 mm x 60 mm
    disk at its middle (z = 0.5 m), bearings at 0.1 and 0.9 m."""
    ms, md = 7850.0 * math.pi * 0.05**2, 7850.0 * math.pi * 0.2**2 * 0.06
    It = ms * (3 * 0.05**2 + 1.0) / 12 + md * (3 * 0.2**2 + 0.06**2) / 12
    Ip = ms * 0.05**2 / 2 + md * 0.2**2 / 2
    sp, v = journal_table()
    return W.Rotor(ms + md, It, Ip, 0.5, (W.BearingTable(0.1, sp, v), W.BearingTable(0.9, sp, v)))


# --------------------------------------------------------------------- the independent solver


def matrices_by_hand(m, It, Ip, z_G, bearings):
    """M, C, G, K of q = (x, y, theta_x, theta_y): bearing (z, kxx, kxy, kyx, kyy, cxx, cxy,
    cyx, cyy) at a = z - z_G moves by d_x = x + a theta_y, d_y = y - a theta_x and pushes with
    F = -K d - C d'; Euler: It theta_x'' + Ip W theta_y' = M_x, It theta_y'' - Ip W theta_x' =
    M_y, M_x = -a F_y, M_y = a F_x."""
    M = np.diag([m, m, It, It])
    K, C = np.zeros((4, 4)), np.zeros((4, 4))
    for z, *coef in bearings:
        a = z - z_G
        for X, (xx, xy, yx, yy) in ((K, coef[:4]), (C, coef[4:])):
            X += np.array([[xx, xy, -a * xy, a * xx],
                           [yx, yy, -a * yy, a * yx],
                           [-a * yx, -a * yy, a * a * yy, -a * a * yx],
                           [a * xx, a * xy, -a * a * xy, a * a * xx]])
    G = np.array([[0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, Ip], [0, 0, -Ip, 0]], dtype=float)
    return M, C, G, K


def eig_by_scipy(M, C, G, K, Om):
    """The roots of the second-order system, mass-normalised first-order form, scipy."""
    import scipy.linalg

    S = np.diag(1.0 / np.sqrt(np.diag(M)))
    A = np.block([[np.zeros((4, 4)), np.eye(4)], [-S @ K @ S, -S @ (C + Om * G) @ S]])
    return scipy.linalg.eig(A, right=False)


def roots_at(rotor: W.Rotor, Om: float) -> np.ndarray:
    """The independent roots of ``rotor`` at ``Om``: its tables interpolated by np.interp."""
    brg = []
    for b in rotor.bearings:
        if isinstance(b, W.BearingTable):
            brg.append((b.z, *(np.interp(Om, b.speeds, b.values[:, j]) for j in range(8))))
        else:
            brg.append((b.z, b.kxx, b.kxy, b.kyx, b.kyy, b.cxx, b.cxy, b.cyx, b.cyy))
    return eig_by_scipy(*matrices_by_hand(rotor.mass, rotor.It, rotor.Ip, rotor.z_com, brg), Om)


def assert_same_roots(rotor: W.Rotor, Om: float, rtol: float = RTOL) -> None:
    lam = roots_at(rotor, Om)
    scale = float(np.max(np.abs(lam)))
    cands = np.concatenate([lam, np.conj(lam)])
    for md in W.modes_at(rotor, Om):
        assert float(np.min(np.abs(cands - md.eigenvalue))) <= rtol * scale, (Om, md.eigenvalue)


coefs = st.lists(st.floats(-0.4, 0.4), min_size=8, max_size=8)


@settings(max_examples=60, deadline=None)
@given(st.floats(5.0, 200.0), st.floats(0.2, 10.0), st.floats(0.0, 2.0), st.floats(-0.2, 0.2),
       st.lists(st.floats(1e5, 1e8), min_size=2, max_size=2), coefs, coefs, st.floats(0.0, 2000.0))
def test_full_2x2_coefficients_agree_with_the_matrices_written_here(m, It, ratio, zG, k, f1, f2, Om):
    """Every one of the eight coefficients, any sign of the cross terms (up to 40 % of the
    direct stiffness; damping up to a damping ratio of ~1)."""
    brg = []
    for z, kk, f in ((-0.3, k[0], f1), (0.4, k[1], f2)):
        c = 2 * math.sqrt(kk * m) * 0.25
        brg.append(W.Bearing(z, kk * (1 + f[0]), kk * (1 + f[3]), kk * f[1], kk * f[2],
                             c * (1 + f[4]), c * (1 + f[7]), c * f[5], c * f[6]))
    assert_same_roots(W.Rotor(m, It, ratio * It, zG, tuple(brg)), Om)


def test_tables_are_interpolated_linearly_and_agree_between_rows():
    rotor = journal_rotor()
    sp = rotor.bearings[0].speeds
    for Om in (sp[0], 0.5 * (sp[3] + sp[4]), 0.3 * sp[-2] + 0.7 * sp[-1], sp[-1]):
        # the roots span ~1e3 (an overdamped pair beside the whirls): 1e-8
        assert_same_roots(rotor, Om, rtol=1e-8)
    b = rotor.bearings[0]
    x = 0.25 * sp[5] + 0.75 * sp[6]
    np.testing.assert_allclose(b.coefficients([x])[0], 0.25 * b.values[5] + 0.75 * b.values[6], rtol=1e-15)
    # the slope between rows is the table's difference quotient (peaks' exact slope uses it)
    np.testing.assert_allclose(b.coefficients([x], slope=True)[0],
                               (b.values[6] - b.values[5]) / (sp[6] - sp[5]), rtol=1e-15)


def test_the_example_table_is_the_published_one():
    """examples/journal_bearing.csv, read by rbcli, is Someya's Table 1 made dimensional
    (to the six digits it is written with)."""
    from rbcli.io.bearingtable import section

    text = (ROOT / "examples" / "journal_rotor.yaml").read_text()
    entries = section(text, "journal_rotor.yaml", {"length": "mm", "mass": "kg", "angular_speed": "rpm"},
                      ROOT / "examples")
    sp, v = journal_table()
    for e in entries:
        np.testing.assert_allclose(e.speeds, sp, rtol=1e-5)  # 6 digits written
        np.testing.assert_allclose(e.rows, v, rtol=1e-5)


# --------------------------------------------------------------------- critical speeds


def test_a_cross_coupled_stiffness_of_1_n_per_m_moves_the_critical_speeds_by_the_physics():
    """The issue's cylinder: 200, 200, 206.559, 241.209 rad/s; with kxy = -kyx = 1 N/m
    (1e-6 of k) they are all still there, and the damped crossings move by what the
    independent solve says: a root of frequency Omega there, ~1e-9 from the q = 0 ones
    (first order in q/k times the damping ratio, ~0.02)."""
    def rotor(q, c):
        return W.Rotor(50.0, 1.625, 0.25, 0.0, tuple(W.Bearing(z, 1e6, 1e6, q, -q, c, c) for z in (-0.2, 0.2)))

    plain, _ = W.critical_speeds(rotor(0.0, 0.0))
    cross, missing = W.critical_speeds(rotor(1.0, 200.0))
    assert not missing and [round(c.speed, 3) for c in cross] == [200.0, 200.0, 206.559, 241.209]
    for a, b in zip(plain, cross):
        assert b.speed == a.speed  # undamped: the conservative part, unchanged
    ref = rotor(0.0, 200.0)
    for c in cross:
        x, md = W.damped_crossing(rotor(1.0, 200.0), c)
        x0, _ = W.damped_crossing(ref, c)
        assert 0.0 < abs(x - x0) <= 1e-7 * x0
        lam = roots_at(rotor(1.0, 200.0), x)
        assert float(np.min(np.abs(np.abs(lam.imag) - x))) <= 1e-11 * x  # Brent to ~1e-12


@pytest.mark.parametrize("q", [2e5, -2e5])
def test_damped_crossings_with_strong_cross_coupling_are_roots_of_the_independent_solve(q):
    """kxy = -kyx = +-2e5 (20 % of k), c = 500: each damped crossing is a speed where the
    independent solve has a root of frequency n Omega (both signs of the follower force)."""
    rotor = W.Rotor(50.0, 1.625, 0.25, 0.0, tuple(W.Bearing(z, 1e6, 1e6, q, -q, 500.0, 500.0) for z in (-0.2, 0.2)))
    crits, _ = W.critical_speeds(rotor, (1, 2))
    assert len(crits) == 8
    for c in crits:
        x, md = W.damped_crossing(rotor, c)
        lam = roots_at(rotor, x)
        assert float(np.min(np.abs(np.abs(lam.imag) - c.order * x))) <= 1e-9 * x
        assert md.whirl == c.whirl


def test_undamped_critical_speeds_on_tables_are_crossings_of_the_independent_solve():
    """The journal rotor's conservative part (no damping, kxy and kyx their mean), its
    tables interpolated by hand: at each critical speed a root at i Omega."""
    rotor = journal_rotor()
    crits, missing = W.critical_speeds(rotor)
    assert len(crits) >= 2 and all(m.reason in ("range", "gyroscopic") for m in missing)
    cons = rotor.conservative_part()
    for c in crits:
        lam = roots_at(cons, c.speed)
        assert float(np.min(np.abs(lam - 1j * c.speed))) <= 1e-9 * c.speed


def test_the_critical_speed_map_is_the_critical_speeds_with_every_bearing_k():
    rotor = W.Rotor(40.0, 1.5, 0.6, 0.12, (W.Bearing(-0.2, 1e6, 2e6), W.Bearing(0.45, 3e6, 3e6)))
    ks = np.array([1e4, 3e6, 1e9])
    speeds, labels = critical_map(rotor, ks)
    for k, row in zip(ks, speeds):
        same = W.Rotor(40.0, 1.5, 0.6, 0.12, (W.Bearing(-0.2, k, k), W.Bearing(0.45, k, k)))
        exact = sorted(c.speed for c in W.critical_speeds(same)[0])
        np.testing.assert_allclose(sorted(row), exact, rtol=1e-12)  # c sqrt(k): rounding only
    assert sorted(labels) == sorted({(c.whirl, c.shape.kind) for c in W.critical_speeds(same)[0]})


# --------------------------------------------------------------------- following modes, stability


def test_a_growing_mode_crossing_a_decaying_one_is_not_a_threshold():
    """The issue's cylinder with a follower stiffness (kxy = -kyx = 1e5, c = 100): the forward
    cylindrical mode grows at 200 rad/s at every speed, the backward conical one decays and
    its frequency falls through 200 rad/s near 300 rad/s. Followed by shape, no mode changes
    sign (no threshold); followed by frequency rank, a rank passes from the growing mode to
    the decaying one: a false threshold."""
    rotor = W.Rotor(50.0, 1.625, 0.25, 0.0, tuple(W.Bearing(z, 1e6, 1e6, 1e5, -1e5, 100.0, 100.0)
                                                 for z in (-0.2, 0.2)))
    cb = W.campbell(rotor, np.linspace(0.0, 400.0, 61))
    ranks = W.track(cb)
    st_ = stability(cb, ranks)
    by_rank = np.sign(cb.eigenvalues.real)
    rank_changes = int(np.sum(by_rank[:-1] * by_rank[1:] < 0))
    by_branch = np.sign(np.take_along_axis(cb.eigenvalues.real, ranks, 1))
    assert rank_changes > 0  # the trap exists on this rotor
    assert not np.any(by_branch[:-1] * by_branch[1:] < 0) and st_.thresholds == ()
    assert len(st_.from_start) == 2 and st_.threshold == 0.0  # both forward modes grow from rest


def test_the_journal_rotor_starts_whirling_where_the_independent_solve_says():
    """The example: the threshold of instability (oil whip) is the root of the largest Re
    lambda of the independent solve (brentq); it does not move with the grid."""
    from scipy.optimize import brentq

    rotor = journal_rotor()
    sp = rotor.bearings[0].speeds
    got = []
    for n in (25, 101, 400):
        cb = W.campbell(rotor, np.linspace(sp[0], sp[-1], n))
        s = stability(cb, W.track(cb))
        onsets = [t for t in s.thresholds if t.change == "onset"]
        assert not s.from_start and len(onsets) == 1
        got.append(onsets[0].speed)
    top = lambda x: float(np.max(roots_at(rotor, x).real))  # noqa: E731
    want = brentq(top, sp[0] + 1.0, sp[-1], xtol=1e-12)
    # the oracle's tables are np.interp's, its roots scipy's: ~1e-12 relative
    np.testing.assert_allclose(got, want, rtol=1e-9)
    assert 7900 < want * 30 / math.pi < 8100  # the README's "oil whip near 8000 rpm"


def test_an_isotropic_symmetric_rotor_keeps_its_equal_forward_and_backward_pair():
    """Identical isotropic bearings, proportional damping: the cylindrical forward and
    backward modes have equal frequencies at every speed; followed as a pair they stay
    apart by whirl, never swapped."""
    c = 300.0
    rotor = W.Rotor(50.0, 1.625, 0.25, 0.0, tuple(W.Bearing(z, 1e6, 1e6, 0, 0, c, c) for z in (-0.2, 0.2)))
    cb = W.campbell(rotor, np.linspace(0.0, 400.0, 41))
    ranks = W.track(cb)
    whirls = np.take_along_axis(cb.whirl, ranks, 1)
    assert all(len(set(whirls[:, k])) == 1 for k in range(4))  # each followed mode keeps its whirl
