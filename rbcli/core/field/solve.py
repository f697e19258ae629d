"""Influence-coefficient balancing for any number of planes and readings (sheet §5.1).

P correction planes, N >= P readings (sensors at one or more speeds, stacked: row ``k``
is one sensor at one speed). A reading is a complex number ``V = amplitude e^{i phase}``
and a mass ``W = m e^{i angle}``, the phases and angles counted in one sense (the caller
converts them first). The linear model of a rotor on linear supports is

    V = V0 + alpha W                                    alpha (N, P), W (P,)

``alpha`` comes from one trial run per plane (:func:`influence_matrix`), and the
correction ``W`` (kg at the trial radius, to ADD) from :func:`solve`:

* ``exact`` — N = P: ``alpha W = -V0`` (``W = -V0/alpha`` for one plane, as
  :func:`rbcli.core.field.classic.field_single_plane` computes it, else LAPACK's LU solve,
  as :func:`rbcli.core.field.classic.field_two_plane`: the same arithmetic, so the same
  bits).
* ``least-squares`` — N > P: minimise ``sum_k (w_k |r_k|)^2`` over the residuals
  ``r = V0 + alpha W`` with weights ``w_k`` (Goodman 1964, "A least-squares method for
  computing balance corrections", J. Eng. Ind. 86(3):273-279; hsbalance's ``LeastSquares``
  and its ``WLS`` weighting). Solved by a Householder QR of ``D alpha`` (``D = diag w``):
  ``W = R^-1 Q^H (-D V0)``, which never forms the squared condition number of the normal
  equations.
* ``min-max`` — N > P: minimise ``max_k w_k |r_k|`` (Foiles, Allaire and Gunter's min-max
  balancing, as hsbalance's ``Min_max``: ``minimize norm(alpha W + A, inf)``), a convex
  second-order cone problem. Solved as the smooth epigraph problem ``min t`` subject to
  ``t^2 - |w_k r_k|^2 >= 0`` by SLSQP from the least-squares answer, then polished by
  Newton's method on the Karush-Kuhn-Tucker equations of its active set
  (``|w_k r_k| = t`` on the set, ``sum_k lambda_k M_k^T w_k r_k = 0``,
  ``sum_k lambda_k = 1``, ``lambda >= 0``), which makes the answer exact to round-off
  where the active set is regular (checked by the tests against a linear program and
  against cvxpy).

Every function is pure: numpy arrays in, frozen results out, no units, no text for a
terminal. Errors are :class:`~rbcli.core.balance.common.BalanceValueError` naming the
parameter at fault.
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

import numpy as np

from rbcli.core.balance.common import BalanceValueError

#: the solve methods, in the words the command line uses
METHODS = ("exact", "least-squares", "min-max")

#: a square or tall influence matrix whose smallest singular value is below this fraction of
#: its largest has columns that do not separate the planes: no correction can be computed
SINGULAR_RTOL = 1e-14


def _complex_array(v: object, name: str, ndim: int) -> np.ndarray:
    try:
        a = np.asarray(v, dtype=complex)
    except (TypeError, ValueError):
        raise BalanceValueError(name, f"{name} must be complex numbers") from None
    if a.ndim != ndim:
        raise BalanceValueError(name, f"{name} must be a {ndim}-D array of complex numbers, got {a.ndim}-D")
    if not np.all(np.isfinite(a)):
        raise BalanceValueError(name, f"{name} must be finite")
    return a


def influence_matrix(v0: object, runs: object, trials: object, *, cumulative: bool = False) -> np.ndarray:
    """The influence coefficients of P trial runs (sheet §5.1).

    Parameters
    ----------
    v0 : (N,) complex — the readings without trial masses
    runs : (P, N) complex — the readings of run j, with trial j on
    trials : (P,) complex — trial mass e^{i angle} of run j (any mass unit; the
        coefficients are per that unit)
    cumulative : bool — every trial was left on for the later runs: run j's change is
        counted from run j-1 (for two planes, sheet §5.1's "trial A left on during run B")

    Returns
    -------
    (N, P) complex ndarray — ``alpha[:, j] = (runs[j] - ref_j) / trials[j]``, ``ref_j = v0``
    (or ``runs[j - 1]`` for ``cumulative``, j > 0).

    Raises
    ------
    BalanceValueError
        shapes that do not match; a zero trial (``trials``).
    """
    V0 = _complex_array(v0, "v0", 1)
    R = _complex_array(runs, "runs", 2)
    T = _complex_array(trials, "trials", 1)
    if R.shape != (T.shape[0], V0.shape[0]):
        raise BalanceValueError("runs", f"runs must hold {T.shape[0]} runs of {V0.shape[0]} readings, "
                                        f"got shape {R.shape}")
    if np.any(T == 0):
        raise BalanceValueError("trials", "trial masses must not be zero")
    cols = []
    for j in range(T.shape[0]):
        ref = R[j - 1] if (cumulative and j > 0) else V0
        cols.append((R[j] - ref) / T[j])
    return np.column_stack(cols)


@dataclass(frozen=True, eq=False)
class FieldSolution:
    """A correction and what it leaves.

    Attributes
    ----------
    corrections : (P,) complex ndarray — mass e^{i angle} to add in each plane (the unit
        and radius of the trial masses the coefficients are per), read-only
    residuals : (N,) complex ndarray — ``V0 + alpha W``, the readings predicted after the
        correction (the linear model), read-only
    method : str — "exact", "least-squares" or "min-max"
    cond : float — 2-norm condition number of alpha (largest / smallest singular value)
    det : complex | None — determinant of alpha when it is square
    objective : float — ``max_k w_k |r_k|`` (min-max), ``sqrt(sum (w_k |r_k|)^2)``
        (least squares) or 0 (exact)
    """

    corrections: np.ndarray
    residuals: np.ndarray
    method: str
    cond: float
    det: complex | None
    objective: float


def _ro(a: np.ndarray) -> np.ndarray:
    a = np.array(a, dtype=complex)
    a.setflags(write=False)
    return a


def check_weights(weights: object | None, n: int) -> np.ndarray:
    """(n,) positive finite weights (all 1 for None)."""
    if weights is None:
        return np.ones(n)
    try:
        w = np.asarray(weights, dtype=float)
    except (TypeError, ValueError):
        raise BalanceValueError("weights", "weights must be numbers") from None
    if w.shape != (n,):
        raise BalanceValueError("weights", f"give one weight per reading ({n}), not {w.size}")
    if not np.all(np.isfinite(w)) or not np.all(w > 0):
        raise BalanceValueError("weights", "weights must be positive finite numbers")
    return w


def solve(alpha: object, v0: object, method: str | None = None, weights: object | None = None) -> FieldSolution:
    """The correction W for the readings ``v0`` of a rotor with influence matrix ``alpha``.

    Parameters
    ----------
    alpha : (N, P) complex — influence coefficients, N >= P
    v0 : (N,) complex — readings to cancel
    method : str, optional — "exact" (N = P only), "least-squares" or "min-max" (N > P);
        default: exact when N = P, else least squares. With N = P every method is exact
        (the residual is zero) and "exact" is reported.
    weights : (N,) float, optional — w_k > 0 per reading (least squares and min-max)

    Returns
    -------
    FieldSolution

    Raises
    ------
    BalanceValueError
        fewer readings than planes (``v0``); an unknown method (``method``); columns that
        do not separate the planes (``runs``: the matrix is singular to round-off).
    """
    A = _complex_array(alpha, "alpha", 2)
    V0 = _complex_array(v0, "v0", 1)
    n, p = A.shape
    if V0.shape != (n,):
        raise BalanceValueError("v0", f"v0 must hold {n} readings, got {V0.shape[0]}")
    if p < 1:
        raise BalanceValueError("alpha", "at least one plane is needed")
    if n < p:
        raise BalanceValueError("v0", f"{p} planes need at least {p} readings per run, got {n}")
    if method is not None and method not in METHODS:
        raise BalanceValueError("method", f"method must be one of {', '.join(METHODS)}, not {method!r}")
    if method == "exact" and n != p:
        raise BalanceValueError("method", f"an exact solve needs as many readings as planes ({p}), got {n}")
    w = check_weights(weights, n)
    sv = np.linalg.svd(A, compute_uv=False)
    if not sv[0] > 0.0 or sv[-1] <= SINGULAR_RTOL * sv[0]:
        raise BalanceValueError(
            "runs", "the influence matrix is singular: the trial runs do not separate the planes")
    cond = float(sv[0] / sv[-1])
    if n == p:
        if p == 1:
            # field_single_plane's W = -V0/H, in Python's complex division (numpy's differs in
            # the last bit): a trim run from stored coefficients gives the classic bits
            W = np.array([-complex(V0[0]) / complex(A[0, 0])])
        else:
            W = np.linalg.solve(A, -V0)  # field_two_plane's solve
        det = complex(A[0, 0]) if p == 1 else complex(np.linalg.det(A))
        return FieldSolution(_ro(W), _ro(V0 + (A @ W if p <= 2 else matvec(A, W))), "exact", cond, det, 0.0)
    W = least_squares(A, V0, w)
    # the condition number of alpha is that of its R (A = QR, Q with orthonormal columns), a
    # P x P matrix: the printed number is the same everywhere (LAPACK's kernels on a tall
    # matrix can differ in the last bits from machine to machine)
    R, _ = householder_qr(A, np.zeros(n, dtype=complex))
    svr = np.linalg.svd(np.array(R), compute_uv=False)
    cond = float(svr[0] / svr[-1])
    if method == "min-max":
        W = min_max(A, V0, w, start=W)
        r = V0 + matvec(A, W)
        return FieldSolution(_ro(W), _ro(r), "min-max", cond, None, float(np.max(w * np.abs(r))))
    r = V0 + matvec(A, W)
    return FieldSolution(_ro(W), _ro(r), "least-squares", cond, None, float(np.linalg.norm(w * r)))


def deg(z: complex) -> float:
    """arg z in degrees in [0, 360) (within 1e-9° below 360 is 0; never -0.0): the angle of
    a reading or a mass."""
    a = math.degrees(math.atan2(z.imag, z.real)) % 360.0
    return 0.0 if a >= 360.0 - 1e-9 else a + 0.0


def dot(a: list[complex], b: list[complex]) -> complex:
    """sum a_k b_k, each part summed exactly rounded (math.fsum): the same bits on every
    machine, BLAS kernel and memory alignment (a golden output is exact to the last digit)."""
    prods = [x * y for x, y in zip(a, b)]
    return complex(math.fsum(z.real for z in prods), math.fsum(z.imag for z in prods))


def matvec(alpha: np.ndarray, w: object) -> np.ndarray:
    """``alpha @ w`` with :func:`dot`'s exactly rounded sums."""
    A = np.asarray(alpha, dtype=complex)
    x = [complex(v) for v in np.asarray(w, dtype=complex)]
    return np.array([dot([complex(a) for a in row], x) for row in A], dtype=complex)


def least_squares(alpha: np.ndarray, v0: np.ndarray, weights: np.ndarray) -> np.ndarray:
    """``argmin_W sum_k (w_k |v0_k + (alpha W)_k|)^2`` by a Householder QR of ``D alpha``.

    Plain Python complex arithmetic with exactly rounded sums (the matrices are small: N
    readings by P planes): the answer is the same to the last bit on any machine, so golden
    outputs and trim runs from stored coefficients reproduce it exactly.

    Parameters
    ----------
    alpha : (N, P) complex, full column rank
    v0 : (N,) complex
    weights : (N,) positive

    Returns
    -------
    (P,) complex ndarray
    """
    R, c = householder_qr(weights[:, None] * alpha, -weights * v0)
    p = len(R)
    W = [0j] * p
    for k in range(p - 1, -1, -1):
        W[k] = (c[k] - dot(R[k][k + 1:], W[k + 1:])) / R[k][k]
    return np.array(W, dtype=complex)


def householder_qr(A: np.ndarray, b: np.ndarray) -> tuple[list[list[complex]], list[complex]]:
    """R (P x P, upper triangular, as lists) and the first P entries of Q^H b, for A = Q R.

    Column k: ``x = A[k:, k]``, ``a = -e^{i arg x_0} |x|``, ``u = (x - a e_1)/|x - a e_1|``;
    ``A[k:, k:] -= 2 u (u^H A[k:, k:])`` and the same for b (Golub and Van Loan, *Matrix
    Computations*, §5.2). Python complex arithmetic, sums exactly rounded (:func:`dot`).
    """
    n, p = A.shape
    M = [[complex(A[i, j]) for j in range(p)] for i in range(n)]
    y = [complex(v) for v in b]
    for k in range(p):
        x = [M[i][k] for i in range(k, n)]
        norm = math.sqrt(math.fsum(abs(z) ** 2 for z in x))
        if norm == 0.0:
            continue
        a = -cmath.exp(1j * cmath.phase(x[0])) * norm if x[0] != 0 else complex(-norm)
        u = [x[0] - a] + x[1:]
        un = math.sqrt(math.fsum(abs(z) ** 2 for z in u))
        u = [z / un for z in u]
        uc = [z.conjugate() for z in u]
        for j in range(k, p):
            f = 2.0 * dot(uc, [M[i][j] for i in range(k, n)])
            for i in range(k, n):
                M[i][j] -= f * u[i - k]
        f = 2.0 * dot(uc, y[k:])
        for i in range(k, n):
            y[i] -= f * u[i - k]
    R = [[M[i][j] if j >= i else 0j for j in range(p)] for i in range(p)]
    return R, y[:p]


# ----------------------------------------------------------------------------------------
# min-max
# ----------------------------------------------------------------------------------------


def _real_form(alpha: np.ndarray, v0: np.ndarray, weights: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Row k of ``D (alpha W + v0)`` as ``M_k x + c_k`` (2-vectors) with ``x = [Re W, Im W]``.

    Returns (M (N, 2, 2P), c (N, 2))."""
    A = weights[:, None] * alpha
    b = weights * v0
    n, p = A.shape
    M = np.zeros((n, 2, 2 * p))
    M[:, 0, :p], M[:, 0, p:] = A.real, -A.imag
    M[:, 1, :p], M[:, 1, p:] = A.imag, A.real
    return M, np.stack([b.real, b.imag], axis=1)


def min_max(alpha: np.ndarray, v0: np.ndarray, weights: np.ndarray, *, start: np.ndarray) -> np.ndarray:
    """``argmin_W max_k w_k |v0_k + (alpha W)_k|`` (see the module notes).

    Parameters
    ----------
    alpha : (N, P) complex, full column rank, N > P
    v0 : (N,) complex
    weights : (N,) positive
    start : (P,) complex — a starting point (the least-squares answer)

    Returns
    -------
    (P,) complex ndarray
    """
    from scipy.optimize import minimize

    n, p = alpha.shape
    # scale: readings to O(1), each plane's column to unit norm (SLSQP's tolerances are absolute)
    sv = float(np.max(weights * np.abs(v0)))
    if not sv > 0.0:
        return np.zeros(p, dtype=complex)  # nothing to cancel: the zero correction is optimal
    cn = np.linalg.norm(weights[:, None] * alpha, axis=0)
    As = alpha / cn  # W = y sv / cn: As y + vs = (alpha W + v0) / sv
    vs = v0 / sv
    M, c = _real_form(As, vs, weights)
    y0 = start * cn / sv
    x0 = np.concatenate([y0.real, y0.imag])
    t0 = float(np.max(np.linalg.norm(np.einsum("nkj,j->nk", M, x0) + c, axis=1)))

    def cons(z: np.ndarray) -> np.ndarray:
        r = np.einsum("nkj,j->nk", M, z[:-1]) + c
        return z[-1] ** 2 - np.sum(r * r, axis=1)

    def cons_jac(z: np.ndarray) -> np.ndarray:
        r = np.einsum("nkj,j->nk", M, z[:-1]) + c
        return np.hstack([-2.0 * np.einsum("nk,nkj->nj", r, M), np.full((n, 1), 2.0 * z[-1])])

    grad = np.zeros(2 * p + 1)
    grad[-1] = 1.0
    res = minimize(lambda z: z[-1], np.append(x0, t0), jac=lambda z: grad, method="SLSQP",
                   constraints=[{"type": "ineq", "fun": cons, "jac": cons_jac}],
                   options={"ftol": 1e-15, "maxiter": 2000})
    x = res.x[:-1] if np.all(np.isfinite(res.x)) else x0
    best = _max_norm(M, c, x)
    if best > t0:  # SLSQP made it worse (it never should): keep the start
        x, best = x0, t0
    x = _polish(M, c, x, best)
    y = x[:p] + 1j * x[p:]
    return y * sv / cn


def _max_norm(M: np.ndarray, c: np.ndarray, x: np.ndarray) -> float:
    return float(np.max(np.linalg.norm(np.einsum("nkj,j->nk", M, x) + c, axis=1)))


def _polish(M: np.ndarray, c: np.ndarray, x: np.ndarray, t: float) -> np.ndarray:
    """Newton's method on the KKT equations of the active set of a near-optimal ``x``.

    Unknowns ``(x, t, lambda_S)``; equations ``|r_k|^2 - t^2 = 0`` (k in S),
    ``sum_S lambda_k M_k^T r_k = 0`` and ``sum_S lambda_k = 1``. Kept only if it converges
    to multipliers >= 0 with every other residual below t and a max no larger than before;
    otherwise ``x`` is returned as it was.
    """
    n, _, m = M.shape
    r = np.einsum("nkj,j->nk", M, x) + c
    norms = np.linalg.norm(r, axis=1)
    if not t > 0.0:
        return x
    S = np.flatnonzero(norms >= t * (1.0 - 1e-6))
    k = S.size
    G = np.einsum("sk,skj->sj", r[S], M[S])  # rows: M_k^T r_k
    # multipliers from the stationarity equations (least squares, then normalised)
    lam, *_ = np.linalg.lstsq(np.vstack([G.T, np.ones((1, k))]),
                              np.concatenate([np.zeros(m), [1.0]]), rcond=None)
    z = np.concatenate([x, [t], lam])
    for _ in range(30):
        xx, tt, ll = z[:m], z[m], z[m + 1:]
        rr = np.einsum("skj,j->sk", M[S], xx) + c[S]
        GG = np.einsum("sk,skj->sj", rr, M[S])
        F = np.concatenate([np.sum(rr * rr, axis=1) - tt * tt, GG.T @ ll, [np.sum(ll) - 1.0]])
        J = np.zeros((k + m + 1, m + 1 + k))
        J[:k, :m] = 2.0 * GG
        J[:k, m] = -2.0 * tt
        J[k:k + m, :m] = np.einsum("s,skj,ski->ij", ll, M[S], M[S])
        J[k:k + m, m + 1:] = GG.T
        J[k + m, m + 1:] = 1.0
        try:
            step = np.linalg.lstsq(J, -F, rcond=None)[0]
        except np.linalg.LinAlgError:
            return x
        z = z + step
        if not np.all(np.isfinite(z)):
            return x
        if np.max(np.abs(step)) <= 1e-15 * max(1.0, float(np.max(np.abs(z)))):
            break
    xx, tt, ll = z[:m], z[m], z[m + 1:]
    if np.any(ll < -1e-9) or not tt > 0.0:
        return x
    new = _max_norm(M, c, xx)
    if new > t * (1.0 + 1e-12) or abs(new - tt) > 1e-9 * tt:
        return x
    return xx
