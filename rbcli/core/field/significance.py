"""Darlow's plane-significance factors: which correction planes add nothing new (sheet §5.1).

A balance plane whose influence column is (nearly) a combination of the other planes'
columns moves the readings in no new direction: the solve then puts large, opposing
masses in it and its neighbours, and the condition number of alpha grows. Darlow's test
finds such a plane (M. S. Darlow, "The identification and elimination of non-independent
balance planes in influence coefficient balancing", ASME paper 82-GT-269, 1982; and
*Balancing of High-Speed Machinery*, Springer 1989, ch. 6), as implemented by hsbalance
(``hsbalance.tools.ill_condition``, which flags a factor <= 0.2):

1. order the planes by the 2-norm of their influence columns, largest first;
2. orthogonalise the columns in that order (Gram-Schmidt);
3. the significance factor of a plane is the norm of what is left of its column after
   removing its projection on the planes before it, divided by the column's norm:
   ``SF_k = |u_k - Q_{k-1} Q_{k-1}^H u_k| / |u_k|`` (1 for the first plane, 0 for a column
   that is a combination of the earlier ones, 1 for one orthogonal to them all).

Notes
-----
hsbalance's loop subtracts the running sum of projections of the previous column rather
than projecting each new column onto all earlier ones: from the third plane on, its factor is
the distance of a column from the one before it, never smaller than the distance from the span
of all of them that this module measures. The two agree for two planes, and every plane
hsbalance flags is flagged here too (a test checks both).
The factor equals ``|R_kk| / |u_k|`` of a QR factorisation of the reordered matrix, which
the tests use as an independent check.
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
    """Darlow's significance factor of each plane.

    Attributes
    ----------
    factors : (P,) float ndarray — per plane, in the planes' own order, in [0, 1], read-only
    order : (P,) int ndarray — the order the test takes the planes in (largest column
        first), read-only
    flagged : tuple of int — planes (indices) with factor <= SIGNIFICANCE_LIMIT
    limit : float
    """

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
