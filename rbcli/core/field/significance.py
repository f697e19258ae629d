"""Darlow's plane-significance factors: which correction planes add nothing new (sheet §5.1).

A plane whose influence column is (nearly) a combination of the others' moves the readings
in no new direction: the solve puts large, opposing masses in it. Darlow's test (ASME paper
82-GT-269, 1982; *Balancing of High-Speed Machinery*, 1989, ch. 6) orders the columns by
norm, largest first, orthogonalises them in that order, and calls a plane's factor
``SF_k = |u_k - Q_{k-1} Q_{k-1}^H u_k| / |u_k|`` (= |R_kk|/|u_k| of a QR, the tests' check);
flagged at or below 0.2, as hsbalance's ``ill_condition``. hsbalance 0.5.5 subtracts only
the previous column's projection, so from the third plane on its factor is never smaller
than this one (above 1 at times); every plane it flags is flagged here too.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rbcli.core.field.solve import dot

#: a plane whose significance factor is at or below this is flagged (hsbalance's
#: ``ill_condition`` threshold for Darlow's test)
SIGNIFICANCE_LIMIT = 0.2


@dataclass(frozen=True, eq=False)
class Significance:
    """Darlow's factor of each plane (in [0, 1], the planes' order), the order the test takes
    them in (largest column first), the planes flagged (factor <= limit) and the limit."""

    factors: np.ndarray
    order: np.ndarray
    flagged: tuple[int, ...]
    limit: float


def _norm(a: list[complex]) -> float:
    return math.sqrt(math.fsum(abs(z) ** 2 for z in a))


def plane_significance(alpha: object, limit: float = SIGNIFICANCE_LIMIT) -> Significance:
    """Darlow's significance factors of the planes of an influence matrix.

    Parameters
    ----------
    alpha : (N, P) complex — influence coefficients, column j = plane j
    limit : float — the flagging threshold (default 0.2)

    Returns
    -------
    Significance
    """
    A = np.asarray(alpha, dtype=complex)
    if A.ndim != 2 or A.shape[1] < 1:
        raise ValueError("alpha must be an (N, P) matrix with P >= 1")
    # plain Python arithmetic with exactly rounded sums: the same bits on every machine
    cols = [[complex(x) for x in A[:, j]] for j in range(A.shape[1])]
    norms = np.array([_norm(c) for c in cols])
    order = np.argsort(-norms, kind="stable")
    factors = np.zeros(A.shape[1])
    basis: list[list[complex]] = []
    for j in order:
        u = cols[j]
        nu = norms[j]
        if not nu > 0.0:
            factors[j] = 0.0
            continue
        v = list(u)
        for _ in range(2):  # Gram-Schmidt twice ("twice is enough"): orthogonal to round-off
            for e in basis:
                c = dot([z.conjugate() for z in e], v)
                v = [vi - c * ei for vi, ei in zip(v, e)]
        nv = _norm(v)
        factors[j] = min(nv / nu, 1.0) if basis else 1.0  # the first plane: nothing before it
        if nv > 0.0:
            basis.append([z / nv for z in v])
    factors.setflags(write=False)
    order = np.array(order, dtype=int)
    order.setflags(write=False)
    flagged = tuple(int(j) for j in range(A.shape[1]) if factors[j] <= limit)
    return Significance(factors, order, flagged, float(limit))
