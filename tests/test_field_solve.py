"""rbcli.core.field.solve against independent solvers and published cases.

Oracles: numpy.linalg.lstsq (LAPACK's SVD-based gelsd; rbcli solves by a QR) for least
squares; a linear program (scipy.optimize.linprog, HiGHS) on a polygon around each
residual's circle for min-max, which brackets the true optimum; hsbalance (cvxpy) where
installed; the published cases hsbalance's test suite carries (Goodman 1964, the
"Balanceit" two-plane example, Foiles' min-max rotor) and the B&K two-plane example.
"""

from __future__ import annotations

import cmath
import math

import numpy as np
import pytest

from rbcli.core.balance.common import BalanceValueError
from rbcli.core.field.solve import classic, influence_matrix, solve


def P(text: str) -> complex:
    """'3.16@72' -> complex (hsbalance's notation)."""
    a, d = text.split("@")
    return complex(cmath.rect(float(a), math.radians(float(d))))


def M(rows: list[str]) -> np.ndarray:
    return np.array([[P(x) for x in r.split()] for r in rows])


# hsbalance test/config.yaml 'Goodman64' (T. P. Goodman, "A least-squares method for computing
# balance corrections", 1964): expected 0.81@0 and 1.48@0
GOODMAN_ALPHA = M(["3@0 2@180", "5@0 2@180", "5@0 3@180"])
GOODMAN_A = np.array([P("1@0"), P("1@180"), P("0@0")])

# hsbalance test/config.yaml 'Balanceit_Example_Two_Plane': 4 readings, 2 planes, trials kept
# on (cumulative); the author of the example printed 15.3@3 (aft) and 6.6@113 (fwd) (hsbalance's
# config notes the 15.3@3 and tests a value of its own instead)
BAL_A = np.array([P(x) for x in ".68@32 .56@86 1.94@231 2.07@335".split()])
BAL_B = M(["1.31@1 .54@9", "1.25@75 .52@75", ".93@251 .81@196", "1@342 .9@296"])
BAL_U = np.array([P("11.1@35"), P("3.7@135")])

# hsbalance test/config.yaml 'Foils Min-Max': 11 readings, 4 planes; published 4.42@88,
# 2.92@352, 1.588@322, 1.928@304
FOILES_ALPHA = M([
    "9.8@117 17@124 7.2@114 38.5@77", "2.7@43 14.3@317 4.5@213 14.3@270",
    "12.5@323 25@261 15.2@158 30@238", "22.4@92 32.6@45 23.3@315 27.8@210",
    "26@94 40.3@9 25@330 34@213", "40.3@355 43@144 29.6@61 65.4@322",
    "20.6@339 32.3@152 36.7@41 61.8@322", "12.6@226 37.6@52 18.8@153 26@176",
    "13.4@209 26.9@76 47.5@98 71.7@312", "13.4@154 22.4@307 52@299 102@165",
    "5.4@24 7.2@199 22.4@2 27.8@99"])
FOILES_A = np.array([P(x) for x in "55@259 45@118 124@21 138@349 107@349 90@280 58@354 108@201 88@190 56@48 73@158".split()])
FOILES_PUBLISHED = np.array([P(x) for x in "4.42@88 2.92@352 1.588@322 1.928@304".split()])

# Darlow's example as hsbalance's notebook examples/Ill_conditioned_planes.ipynb writes it
# (4 readings, 3 planes; planes 2 and 3 differ in one sensor)
DARLOW_ALPHA = M(["1.41@45 3.61@34 3.61@34", "3.16@72 2.24@27 2.24@27", "2.83@45 5@37 5@37",
                  "3.16@18 3.61@34 4.47@27"])
DARLOW_A = np.array([P(x) for x in "3.16@72 3.16@18 4.12@14 5.39@68".split()])


def random_case(rng, n: int, p: int) -> tuple[np.ndarray, np.ndarray]:
    A = rng.normal(size=(n, p)) + 1j * rng.normal(size=(n, p))
    v = rng.normal(size=n) + 1j * rng.normal(size=n)
    return A, v


# ------------------------------------------------------------------------ least squares


def test_goodman_1964_published():
    s = solve(GOODMAN_ALPHA, GOODMAN_A)
    assert s.method == "least-squares"
    # printed to two decimals: 0.81 and 1.48, both at 0°
    assert s.corrections[0] == pytest.approx(0.81, abs=0.005)
    assert s.corrections[1] == pytest.approx(1.48, abs=0.005)
    # and exactly: the normal equations of this real problem give 17/21 and 31/21
    assert s.corrections == pytest.approx([17 / 21, 31 / 21], rel=1e-14)  # a 3x2 QR: a few ulp


def test_balanceit_published_cumulative():
    alpha = influence_matrix(BAL_A, BAL_B.T, BAL_U, cumulative=True)
    s = solve(alpha, BAL_A)
    # printed to three digits and the degree: 15.3@3 and 6.6@113
    for w, (amp, ang) in zip(s.corrections, [(15.3, 3), (6.6, 113)]):
        assert abs(w) == pytest.approx(amp, abs=0.05)
        assert (math.degrees(cmath.phase(w)) - ang + 180) % 360 - 180 == pytest.approx(0, abs=0.5)


def test_darlow_case_as_hsbalance_documents_it():
    s = solve(DARLOW_ALPHA, DARLOW_A)
    # hsbalance's notebook prints W = 0.875@99.4, 4.777@98.0, 5.137@271.1 (3 decimals, 0.1°):
    # its cvxpy solve of this ill-conditioned problem agrees with ours to its printed digits
    for w, (amp, ang) in zip(s.corrections, [(0.875, 99.4), (4.777, 98.0), (5.137, 271.1)]):
        assert abs(w) == pytest.approx(amp, abs=0.002)
        assert math.degrees(cmath.phase(w)) % 360 == pytest.approx(ang, abs=0.1)
    # and its residuals 1.638@124.2, 0.46@180.4, 1.288@315.4, 0.0
    for r, amp in zip(s.residuals, [1.638, 0.46, 1.288, 0.0]):
        assert abs(r) == pytest.approx(amp, abs=0.002)


@pytest.mark.parametrize("seed", range(12))
def test_least_squares_equals_lstsq(seed):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(2, 16))
    p = int(rng.integers(1, n))
    A, v = random_case(rng, n, p)
    s = solve(A, v)
    ref = np.linalg.lstsq(A, -v, rcond=None)[0]
    # both are backward stable: they differ by ~cond(A) * eps * |W|; cond < 1e3 here
    assert np.linalg.cond(A) < 1e3
    np.testing.assert_allclose(s.corrections, ref, rtol=1e-11, atol=1e-11 * np.abs(ref).max())
    np.testing.assert_allclose(s.residuals, v + A @ ref, atol=1e-11 * np.abs(v).max())
    assert s.objective == pytest.approx(np.linalg.norm(v + A @ ref), rel=1e-12)


@pytest.mark.parametrize("seed", range(6))
def test_weighted_least_squares_equals_lstsq_of_the_scaled_system(seed):
    rng = np.random.default_rng(100 + seed)
    n, p = 8, 3
    A, v = random_case(rng, n, p)
    w = rng.uniform(0.2, 5.0, size=n)
    s = solve(A, v, "least-squares", w)
    ref = np.linalg.lstsq(w[:, None] * A, -w * v, rcond=None)[0]
    np.testing.assert_allclose(s.corrections, ref, rtol=1e-11, atol=1e-12)  # as above
    # weighting matters: the unweighted answer differs
    assert not np.allclose(solve(A, v).corrections, ref, rtol=1e-6)


# ------------------------------------------------------------------------ exact


def test_square_solves_are_the_classic_bits():
    """N = P: the same arithmetic as rbcli's one- and two-plane solves, bit for bit."""
    V0 = [P("170@112"), P("53@78")]
    VA = [P("235@94"), P("58@68")]
    VB = [P("185@115"), P("77@104")]
    T = [P("1.15@0"), P("1.15@0")]
    a2, W2, *_ = classic(V0, [VA, VB], T, False)
    alpha = influence_matrix(V0, [VA, VB], T)
    assert np.array_equal(alpha, a2)
    s = solve(alpha, V0)
    assert s.method == "exact" and np.array_equal(s.corrections, W2)
    a1, W1, *_ = classic([P("6@30")], [[P("4@110")]], [P("10@0")], False)
    s1 = solve(a1, [P("6@30")])
    assert s1.corrections[0] == W1[0]  # the same division, the same bits
    # every method is exact for a square system
    assert np.array_equal(solve(alpha, V0, "least-squares").corrections, s.corrections)


def test_three_planes_three_sensors_exact():
    rng = np.random.default_rng(7)
    A, v = random_case(rng, 3, 3)
    s = solve(A, v)
    np.testing.assert_allclose(s.corrections, np.linalg.solve(A, -v), rtol=1e-13)  # one LU
    assert np.abs(s.residuals).max() < 1e-13 * np.abs(v).max() * np.linalg.cond(A)


def test_errors_name_their_parameter():
    with pytest.raises(BalanceValueError) as e:
        solve(np.ones((1, 2)), [1.0])
    assert e.value.param == "v0"
    with pytest.raises(BalanceValueError) as e:
        solve([[1.0], [2.0]], [1.0, 1.0], "exact")
    assert e.value.param == "method"
    with pytest.raises(BalanceValueError) as e:
        solve([[1.0, 2.0], [2.0, 4.0], [3.0, 6.0]], [1.0, 1.0, 1.0])
    assert e.value.param == "runs"
    with pytest.raises(BalanceValueError) as e:
        solve([[1.0], [2.0]], [1.0, 1.0], weights=[1.0, 0.0])
    assert e.value.param == "weights"
    with pytest.raises(BalanceValueError) as e:
        influence_matrix([1.0], [[2.0]], [0.0])
    assert e.value.param == "trials"


# ------------------------------------------------------------------------ min-max


def _linprog_minmax(A: np.ndarray, v: np.ndarray, w: np.ndarray, K: int = 720) -> tuple[float, np.ndarray]:
    """min t s.t. Re(e^{-i th_m} w_k r_k) <= t for K directions: a polygon circumscribing each
    residual's circle. Its optimum t_LP satisfies t_LP <= t* <= t_LP / cos(pi/K)."""
    from scipy.optimize import linprog

    n, p = A.shape
    th = 2 * np.pi * np.arange(K) / K
    rows, rhs = [], []
    for k in range(n):
        a, b = w[k] * A[k], w[k] * v[k]
        for t in th:
            c, s = math.cos(t), math.sin(t)
            # Re(e^{-it} (a W + b)) = c Re(aW+b) + s Im(aW+b)
            re = np.concatenate([a.real, -a.imag])
            im = np.concatenate([a.imag, a.real])
            rows.append(np.append(c * re + s * im, -1.0))
            rhs.append(-(c * b.real + s * b.imag))
    cost = np.zeros(2 * p + 1)
    cost[-1] = 1.0
    res = linprog(cost, A_ub=np.array(rows), b_ub=np.array(rhs), bounds=[(None, None)] * (2 * p + 1),
                  method="highs")
    assert res.status == 0
    x = res.x
    return float(x[-1]), x[:p] + 1j * x[p:2 * p]


@pytest.mark.parametrize("case", ["foiles", "goodman", "darlow", *[f"random{i}" for i in range(8)]])
def test_min_max_against_a_linear_program(case):
    if case == "foiles":
        A, v = FOILES_ALPHA, FOILES_A
    elif case == "goodman":
        A, v = GOODMAN_ALPHA, GOODMAN_A
    elif case == "darlow":
        A, v = DARLOW_ALPHA, DARLOW_A
    else:
        rng = np.random.default_rng(int(case[6:]) + 40)
        n = int(rng.integers(3, 14))
        A, v = random_case(rng, n, int(rng.integers(1, n)))
    w = np.ones(len(v))
    s = solve(A, v, "min-max")
    t = float(np.max(np.abs(s.residuals)))
    assert s.objective == pytest.approx(t, rel=1e-15)
    K = 720
    t_lp, W_lp = _linprog_minmax(A, v, w, K)
    t_lp_true = float(np.max(np.abs(v + A @ W_lp)))
    # the LP bounds the optimum from below (HiGHS' feasibility tolerance, 1e-7 relative, is
    # the slack), and any LP answer is feasible, so rbcli's optimum can be no worse than it
    assert t >= t_lp * (1 - 1e-7)
    assert t <= t_lp_true * (1 + 1e-12)
    # and the polygon is within cos(pi/K) of the circle: the bracket is ~1e-5 wide
    assert t <= t_lp / math.cos(math.pi / K) * (1 + 1e-7)
    # the least-squares answer is never better in the max
    assert t <= float(np.max(np.abs(solve(A, v).residuals))) * (1 + 1e-12)


def test_min_max_weighted_against_a_linear_program():
    rng = np.random.default_rng(3)
    A, v = random_case(rng, 9, 3)
    w = rng.uniform(0.5, 3.0, size=9)
    s = solve(A, v, "min-max", w)
    t = float(np.max(w * np.abs(s.residuals)))
    t_lp, W_lp = _linprog_minmax(A, v, w)
    assert t_lp * (1 - 1e-7) <= t <= float(np.max(w * np.abs(v + A @ W_lp))) * (1 + 1e-12)  # as above


def test_foiles_published_min_max():
    """Foiles' published weights (3 digits) and rbcli's optimum: rbcli's largest residual is
    no larger than that of the published weights (which are rounded, and came from an
    approximate solve), and the weights agree within hsbalance's own 5 % tolerance."""
    s = solve(FOILES_ALPHA, FOILES_A, "min-max")
    published_max = float(np.max(np.abs(FOILES_A + FOILES_ALPHA @ FOILES_PUBLISHED)))
    assert float(np.max(np.abs(s.residuals))) <= published_max
    np.testing.assert_allclose(s.corrections, FOILES_PUBLISHED, rtol=0.05)


def test_min_max_optimality_certificate():
    """At the optimum the active residuals are equal and no small move lowers the max."""
    s = solve(FOILES_ALPHA, FOILES_A, "min-max")
    r = np.abs(s.residuals)
    t = r.max()
    active = np.sort(r)[::-1][:5]
    assert np.all(active >= t * (1 - 1e-12))  # five readings share the max to round-off
    rng = np.random.default_rng(0)
    for _ in range(200):
        d = (rng.normal(size=4) + 1j * rng.normal(size=4)) * 1e-6 * np.abs(s.corrections).max()
        assert np.abs(FOILES_A + FOILES_ALPHA @ (s.corrections + d)).max() >= t * (1 - 1e-13)


# ------------------------------------------------------------------------ hsbalance


# cvxpy may pick a solver that announces its community licence
quiet = pytest.mark.filterwarnings("ignore:Using the Community license")


def _hs_alpha(hs, A):
    alpha = hs.Alpha()
    alpha.add(direct_matrix=A)
    return alpha


@quiet
@pytest.mark.parametrize("case", ["goodman", "darlow", "foiles", "random"])
def test_least_squares_agrees_with_hsbalance(hs, case):
    A, v = {"goodman": (GOODMAN_ALPHA, GOODMAN_A), "darlow": (DARLOW_ALPHA, DARLOW_A),
            "foiles": (FOILES_ALPHA, FOILES_A)}.get(case, (None, None))
    if A is None:
        A, v = random_case(np.random.default_rng(11), 10, 4)
    W = hs.LeastSquares(v[:, None], _hs_alpha(hs, A)).solve()[:, 0]
    s = solve(A, v)
    # hsbalance solves with cvxpy's conic solver, which stops when the objective is optimal to
    # ~1e-8 relative: the objectives agree to that, and rbcli's (exact to round-off, see the
    # lstsq test) is no larger
    obj, obj_hs = np.linalg.norm(s.residuals), np.linalg.norm(v + A @ W)
    assert obj <= obj_hs * (1 + 1e-12) and obj_hs == pytest.approx(obj, rel=1e-6)
    # an objective optimal to 1e-8 pins W only to ~sqrt(1e-8) x cond: the weights within 1 %
    np.testing.assert_allclose(s.corrections, W, rtol=1e-2, atol=1e-3 * np.abs(W).max())


@quiet
@pytest.mark.parametrize("case", ["foiles", "goodman", "random"])
def test_min_max_agrees_with_hsbalance(hs, case):
    A, v = {"goodman": (GOODMAN_ALPHA, GOODMAN_A), "foiles": (FOILES_ALPHA, FOILES_A)}.get(case, (None, None))
    if A is None:
        A, v = random_case(np.random.default_rng(12), 10, 3)
    model = hs.Min_max(v[:, None], _hs_alpha(hs, A))
    W = model.solve()[:, 0]
    s = solve(A, v, "min-max")
    t_hs = float(np.max(np.abs(v + A @ W)))
    t = float(np.max(np.abs(s.residuals)))
    # the optimum value agrees to cvxpy's tolerance (~1e-8), and rbcli's is no worse
    assert t == pytest.approx(t_hs, rel=1e-6)
    assert t <= t_hs * (1 + 1e-9)
    # the weights agree as far as the optimum pins them (the max is flat to first order)
    np.testing.assert_allclose(s.corrections, W, rtol=1e-3, atol=1e-4 * np.abs(W).max())
