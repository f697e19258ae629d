"""Influence-coefficient balancing, any number of planes and readings (sheet §5.1).

``V = V0 + alpha W`` (readings ``amplitude e^{i phase}``, row k a sensor at a speed; masses
``m e^{i angle}``; alpha from a trial run per plane, :func:`influence_matrix`). :func:`solve`:
``exact`` (N = P); ``least-squares`` (min ``sum (w_k |r_k|)^2``, Goodman 1964, J. Eng. Ind.
86(3):273-279, by a Householder QR; ``robust``: Huber's ``min(1, c/|r_k|)``, c = 2.448 s, s =
median |r_k|/sqrt(ln 4): 95 % of a complex Gaussian's residuals within c); ``min-max`` (min
``max w_k |r_k|``, Foiles, Allaire and Gunter; hsbalance's ``Min_max``; :mod:`.cone`). Limits
``|W_j| <= U_j``, ``|r_k| <= L_k`` make a cone program; unmeetable, the least-violating
correction. Sums in a fixed order (no BLAS): the same bits for any BLAS thread count.
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

import numpy as np

from rbcli.core.balance.common import SMALL_RESPONSE_AMPLITUDE, SMALL_RESPONSE_PHASE_DEG, BalanceValueError
from rbcli.core.field.cone import Cones, lu_solve, singular_values, socp

#: the solve methods, in the words the command line uses
METHODS = ("exact", "least-squares", "min-max")

#: a square or tall influence matrix whose smallest singular value is below this fraction of
#: its largest has columns that do not separate the planes: no correction can be computed
SINGULAR_RTOL = 1e-14

#: Huber's threshold in Rayleigh scales: exp(-c²/2) = 5 % of good readings beyond it
HUBER_C = math.sqrt(-2.0 * math.log(0.05))


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


def small_response(v0: complex, v1: complex) -> bool:
    """Whether a trial changed a reading too little to trust (sheet §5.1; ACOEM asks 30 %):
    small unless the amplitude changed by >= 25 % or the phase by >= 25 deg."""
    a0, a1 = abs(v0), abs(v1)
    if a0 == 0.0 or a1 == 0.0:
        return a1 == a0
    return (abs(a1 - a0) / a0 < SMALL_RESPONSE_AMPLITUDE
            and abs(math.degrees(cmath.phase(v1 / v0))) < SMALL_RESPONSE_PHASE_DEG)


def influence_matrix(v0: object, runs: object, trials: object, *, cumulative: bool = False) -> np.ndarray:
    """(N, P) ``alpha[:, j] = (runs[j] - ref_j) / trials[j]``, ``ref_j = v0`` (or ``runs[j-1]``
    when every trial was left on, ``cumulative``); ``v0`` (N,), ``runs`` (P, N), ``trials``
    (P,) mass e^{i angle} (the coefficients are per its unit)."""
    V0 = _complex_array(v0, "v0", 1)
    R = _complex_array(runs, "runs", 2)
    T = _complex_array(trials, "trials", 1)
    if R.shape != (T.shape[0], V0.shape[0]):
        raise BalanceValueError("runs", f"runs must hold {T.shape[0]} runs of {V0.shape[0]} readings, "
                                        f"got shape {R.shape}")
    if np.any(T == 0):
        raise BalanceValueError("trials", "trial masses must not be zero")
    return np.column_stack([(R[j] - (R[j - 1] if cumulative and j else V0)) / T[j] for j in range(T.size)])


def classic(v0: list[complex], runs: list[list[complex]], trials: list[complex], cumulative: bool) -> tuple:
    """The one- and two-plane solves rbcli always did (their outputs are golden, bit for bit):
    (alpha, W, residual, det, cond). One plane: ``H = (V1 - V0)/T``, ``W = -V0/H`` in Python's
    complex arithmetic; two: numpy's columns and LAPACK's solve."""
    if len(trials) == 1:
        H = (complex(runs[0][0]) - complex(v0[0])) / complex(trials[0])
        if H == 0:
            raise BalanceValueError("run", "the trial run gave the same reading as the initial run; no "
                                           "influence coefficient")
        W = -complex(v0[0]) / H
        return np.array([[H]]), np.array([W]), np.array([complex(v0[0]) + H * W]), None, None
    A = influence_matrix(v0, runs, trials, cumulative=cumulative)
    det = complex(A[0, 0] * A[1, 1] - A[0, 1] * A[1, 0])
    if not np.max(np.abs(A)) > 0.0 or abs(det) <= 1e-14 * float(np.max(np.abs(A))) ** 2:
        raise BalanceValueError("run", "the influence matrix is singular: the trial runs do not separate the "
                                       "two planes")
    W = np.linalg.solve(A, -np.array(v0))
    return A, W, np.array(v0) + A @ W, det, float(np.linalg.cond(A))


@dataclass(frozen=True, eq=False)
class FieldSolution:
    """A correction (P,) mass e^{i angle} to add and the readings it leaves, ``V0 + alpha W``
    (read-only); the method; cond and |det| (square; None: it overflows); the objective
    (``max w_k |r_k|``, ``sqrt(sum (w_k |r_k|)^2)`` or 0); the limits met with equality
    (("mass", plane), ("reading", row)) and the objective without each; max |r_k|/L_k; Huber's
    weights."""

    corrections: np.ndarray
    residuals: np.ndarray
    method: str
    cond: float
    det: float | None
    objective: float
    active: tuple[tuple[str, int], ...] = ()
    without: tuple[float, ...] = ()
    violation: float = 0.0
    robust: np.ndarray | None = None

    @property
    def feasible(self) -> bool:
        return self.violation <= 1.0 + 1e-9


def _ro(a: np.ndarray, dtype: type = complex) -> np.ndarray:
    a = np.array(a, dtype=dtype)
    a.setflags(write=False)
    return a


def _positive(v: object | None, n: int, name: str, none: float) -> np.ndarray:
    """(n,) positive numbers (``weights``; a limit may be inf: none), ``none`` each for None."""
    try:
        x = np.full(n, none) if v is None else np.asarray(v, dtype=float)
    except (TypeError, ValueError):
        raise BalanceValueError(name, f"{name} must be numbers") from None
    if x.shape != (n,):
        raise BalanceValueError(name, f"give one {name} value per {'plane' if name == 'max_mass' else 'reading'} "
                                      f"({n}), not {x.size}")
    if not np.all(x > 0) or not np.all(x < np.inf if name == "weights" else x == x):
        raise BalanceValueError(name, f"{name} must be positive finite numbers")
    return x


def solve(alpha: object, v0: object, method: str | None = None, weights: object | None = None, *,
          max_mass: object | None = None, limits: object | None = None, robust: bool = False,
          costs: bool = True) -> FieldSolution:
    """The correction W for readings ``v0`` (N,) and influence ``alpha`` (N, P), N >= P: by
    ``method`` ("exact" for N = P, "least-squares" the default, "min-max"; with N = P exact
    unless a limit binds), reading ``weights`` w_k > 0, ``max_mass`` (P,) largest |W_j| and
    ``limits`` (N,) largest |r_k| (inf: none), ``robust`` (Huber); ``costs``: solve again
    without each active limit. A BalanceValueError names the parameter (``runs``: columns that
    do not separate the planes)."""
    A, V0 = _complex_array(alpha, "alpha", 2), _complex_array(v0, "v0", 1)
    n, p = A.shape
    if V0.shape != (n,) or not 1 <= p <= n:
        raise BalanceValueError("v0", f"{p} planes need at least {p} readings per run, got {V0.size}")
    if method not in (None, *METHODS) or method == "exact" and n != p:
        raise BalanceValueError("method", f"an exact solve needs as many readings as planes ({p}), got {n}"
                                if method == "exact" else f"method must be one of {', '.join(METHODS)}")
    if robust and (method == "min-max" or n <= p + 1):
        raise BalanceValueError("robust", "a robust fit is a least-squares fit with more readings than planes + 1")
    w = _positive(weights, n, "weights", 1.0)
    U, L = _positive(max_mass, p, "max_mass", np.inf), _positive(limits, n, "limits", np.inf)
    R, _ = householder_qr(A, np.zeros(n, dtype=complex))
    sv = singular_values(np.array(R))
    if not sv[0] > 0.0 or sv[-1] <= SINGULAR_RTOL * sv[0]:
        raise BalanceValueError("runs", "the influence matrix is singular: the trial runs do not separate the planes")
    det = (abs(complex(A[0, 0])) if p == 1 else abs(complex(np.linalg.det(A))) if p == 2 else
           math.prod(abs(R[k][k]) for k in range(p))) if n == p else None
    common = dict(cond=float(sv[0] / sv[-1]), det=det if det is None or math.isfinite(det) else None,
                  robust=huber(A, V0, w) if robust else None)
    wr = w if common["robust"] is None else w * common["robust"]
    if n == p:  # Python's complex division and LAPACK's 2 x 2 solve: the classic solves' bits
        W = np.array([-complex(V0[0]) / complex(A[0, 0])]) if p == 1 else \
            np.linalg.solve(A, -V0) if p == 2 else lu_solve(A, -V0)
    else:
        W = cone_solve(A, V0, w, "min-max", None, None) if method == "min-max" else least_squares(A, V0, wr)
    name = "exact" if n == p else method or "least-squares"
    r = V0 + (A @ W if n == p <= 2 else matvec(A, W))
    if np.all(np.abs(W) <= U) and np.all(np.abs(r) <= L):
        return FieldSolution(_ro(W), _ro(r), name, objective=_measure(name, wr, r), violation=_violation(r, L),
                             **common)
    return _limited(A, V0, method, weights, wr, U, L, robust, costs, common)


def _limited(A, V0, method, weights, wr, U, L, robust, costs, common) -> FieldSolution:
    """The solution under the limits, the limits it meets with equality and what each costs."""
    (n, p), name = A.shape, "min-max" if method == "min-max" else "least-squares"
    W = cone_solve(A, V0, wr, name, U, L)
    r = V0 + matvec(A, W)
    act = tuple([("mass", j) for j in range(p) if abs(W[j]) >= U[j] * (1 - 1e-9)]
                + [("reading", k) for k in range(n) if abs(r[k]) >= L[k] * (1 - 1e-9)])
    v = _violation(r, L)
    without = tuple(solve(A, V0, method, weights, robust=robust, costs=False,
                          max_mass=np.where(np.arange(p) == i, np.inf, U) if kind == "mass" else U,
                          limits=np.where(np.arange(n) == i, np.inf, L) if kind == "reading" else L).objective
                    for kind, i in act) if costs and v <= 1.0 + 1e-9 else ()
    return FieldSolution(_ro(W), _ro(r), name, objective=_measure(name, wr, r), active=act, without=without,
                         violation=v, **common)


def _violation(r: np.ndarray, L: np.ndarray) -> float:
    """max_k |r_k| / L_k over the readings with a limit (0: none)."""
    lim = np.isfinite(L)
    return float(np.max(np.abs(r[lim]) / L[lim])) if lim.any() else 0.0


def _measure(method: str, w: np.ndarray, r: np.ndarray) -> float:
    a = w * np.abs(r)
    return float(np.max(a)) if method == "min-max" else 0.0 if method == "exact" else math.sqrt(math.fsum(a * a))


def huber(A: np.ndarray, V0: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Huber's weight of each reading, by iteratively reweighted least squares (the module
    notes): 1 for a reading within ``c`` of the fit, ``c/|r_k|`` beyond."""
    h = np.ones(V0.size)
    for _ in range(100):
        r = np.abs(V0 + matvec(A, least_squares(A, V0, w * h)))
        c = HUBER_C * float(np.median(r)) / math.sqrt(math.log(4.0))
        new = np.minimum(1.0, c / np.maximum(r, 1e-300)) if c > 0.0 else np.ones(V0.size)
        if np.max(np.abs(new - h)) <= 1e-12:
            break
        h = new
    return _ro(h, float)


def cone_solve(A: np.ndarray, V0: np.ndarray, w: np.ndarray, method: str, U: np.ndarray | None,
               L: np.ndarray | None) -> np.ndarray:
    """W: least squares or min-max under ``|W_j| <= U_j`` and ``|r_k| <= L_k`` (None: no
    limits); when the limits cannot all be met, the correction that violates them least,
    ``min s`` with ``|r_k| <= s L_k``.

    Solved in scaled real variables ``y``, ``W_j = y_j sv / cn_j`` (readings O(1), each
    plane's weighted column of unit norm): ``r_k / sv = M_k y + c_k``."""
    n, p = A.shape
    sv = float(np.max(w * np.abs(V0)))
    if not sv > 0.0:
        return np.zeros(p, dtype=complex)
    U = np.full(p, np.inf) if U is None else U
    L = np.full(n, np.inf) if L is None else L
    cn = np.sqrt(np.sum(np.abs(w[:, None] * A) ** 2, axis=0))
    As, vs = A / cn, V0 / sv
    M = np.zeros((n, 2, 2 * p))
    M[:, 0, :p], M[:, 0, p:], M[:, 1, :p], M[:, 1, p:] = As.real, -As.imag, As.imag, As.real
    c = np.stack([vs.real, vs.imag], axis=1)
    mj = np.flatnonzero(np.isfinite(U))
    Gm = np.zeros((mj.size, 2, 2 * p))
    Gm[np.arange(mj.size), 0, mj], Gm[np.arange(mj.size), 1, p + mj] = 1.0, 1.0
    lk = np.flatnonzero(np.isfinite(L))
    Lk = L[lk] / sv

    def cones(G, h, a, beta, extra: int) -> list:
        """the constraints with ``extra`` variables after y (zero columns)"""
        return [np.concatenate([G, np.zeros(G.shape[:2] + (extra,))], axis=2), h,
                np.concatenate([np.zeros((G.shape[0], 2 * p)), a], axis=1), beta]

    def stack(*parts) -> Cones:
        return Cones(*(np.concatenate(x) for x in zip(*parts)))

    def mass(extra: int, shrink: float = 1.0) -> list:
        return cones(Gm, np.zeros((mj.size, 2)), np.zeros((mj.size, extra)), U[mj] * cn[mj] / sv * shrink, extra)

    y = np.zeros(2 * p)
    if lk.size:  # phase 1: the least violation s, |M_k y + c_k| <= s L_k (strictly inside the masses)
        z = socp(np.zeros((0, 2 * p + 1)), np.zeros(0), np.eye(2 * p + 1)[-1],
                 stack(mass(1, 1.0 - 1e-6), cones(M[lk], c[lk], Lk[:, None], np.zeros(lk.size), 1)),
                 np.append(y, 2.0 * float(np.max(np.linalg.norm(c[lk], axis=1) / Lk)) + 1.0))
        y, s = z[:-1], float(np.max(np.linalg.norm(np.einsum("nkj,j->nk", M[lk], z[:-1]) + c[lk], axis=1) / Lk))
        if s >= 1.0 - 1e-9:
            return (y[:p] + 1j * y[p:]) * sv / cn
    limit = cones(M[lk], c[lk], np.zeros((lk.size, 1 if method == "min-max" else 0)), Lk,
                  1 if method == "min-max" else 0)
    if method == "min-max":
        r = np.linalg.norm(np.einsum("nkj,j->nk", M, y) + c, axis=1)
        obj = cones(w[:, None, None] * M, w[:, None] * c, np.ones((n, 1)), np.zeros(n), 1)
        z = socp(np.zeros((0, 2 * p + 1)), np.zeros(0), np.eye(2 * p + 1)[-1], stack(obj, mass(1), limit),
                 np.append(y, 2.0 * float(np.max(w * r)) + 1.0))[:-1]
    else:
        B = (w[:, None, None] * M).reshape(2 * n, 2 * p)
        z = socp(B, (w[:, None] * c).reshape(2 * n), np.zeros(2 * p), stack(mass(0), limit), y)
    return (z[:p] + 1j * z[p:]) * sv / cn


def deg(z: complex) -> float:
    """arg z in degrees in [0, 360) (within 1e-9° below 360 is 0; never -0.0): the angle of
    a reading or a mass."""
    a = math.degrees(math.atan2(z.imag, z.real)) % 360.0
    return 0.0 if a >= 360.0 - 1e-9 or z == 0 else a + 0.0


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
    """``argmin_W sum_k (w_k |v0_k + (alpha W)_k|)^2`` (alpha (N, P) of full rank) by a
    Householder QR of ``D alpha``, in Python complex arithmetic with exactly rounded sums:
    the same bits on any machine (golden outputs and trim runs reproduce it)."""
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
