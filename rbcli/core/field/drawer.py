"""The best weights from a drawer at a rotor's holes: an exact search.

Each plane has holes (angles), a radius factor (hole radius over the radius the coefficients
were measured at), at most ``most`` weights, at most ``per_hole`` in one hole and the most
mass it takes; the drawer has sizes (masses) and counts, shared by the planes that use it.
A choice puts a multiset of (hole, size) weights in each plane; its correction is
``W_j = Σ m_s ρ_j e^{i θ_h}`` and it leaves ``r = V0 + alpha W``. The objective is the
method's, on the readings (not the distance to the continuous correction): least squares
``F(W) = Σ_k (w_k |r_k|)²``, min-max ``G(W) = max_k w_k |r_k|``; reading limits
``|r_k| <= L_k`` must hold (if no choice meets them, the one that violates them least,
``max_k |r_k| / L_k``, is returned and said).

Search (a sphere decoder; Agrell et al., IEEE Trans. Inf. Theory 48(8), 2002): with
``D alpha = Q R`` and the least-squares optimum ``W*``, ``F(W) = F* + |R (W - W*)|²``, and
``G(W)² >= F(W)/N``; so every choice better than one found lies in the ellipsoid
``|R (W - W*)|² <= δ``. Each plane's choices within that ellipsoid's shadow are enumerated
(two halves of at most two weights each met in a k-d tree: up to 4 weights a plane), then the
planes are searched from the last, each plane's term bounding the rest. ``δ`` grows from a
small guess until the best found is proven optimal (its own bound within ``δ``) or the
ellipsoid holds every choice: the answer is exact, not a rounding of the continuous one.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rbcli.core.balance.common import BalanceValueError
from rbcli.core.field.solve import householder_qr, least_squares

#: the most weights a plane may take (the search meets two halves of at most two)
MOST_WEIGHTS = 4
#: the most choices the search examines (per plane, and in all): beyond it, refused
MAX_CHOICES = 20_000_000


@dataclass(frozen=True)
class Plane:
    """What one plane can take: hole angles (rad), ``factor`` = hole radius / trial radius,
    at most ``most`` weights, ``per_hole`` in one hole, ``max_mass`` kg in all (inf: any),
    and ``drawer``: which drawer (an index) its weights come from."""

    angles: tuple[float, ...]
    factor: float
    most: int
    per_hole: int = 1
    max_mass: float = math.inf
    drawer: int = 0


@dataclass(frozen=True)
class Choice:
    """The weights chosen: per plane a tuple of (hole index, size index); ``corrections``
    (P,) complex kg at the trial radius; ``objective`` (the method's: sqrt F or G);
    ``violation`` max |r_k|/L_k (<= 1: every limit met); ``examined``: choices evaluated."""

    weights: tuple[tuple[tuple[int, int], ...], ...]
    corrections: np.ndarray
    objective: float
    violation: float
    examined: int


def _combos(units: np.ndarray, k: int) -> np.ndarray:
    """(m, k) sorted index tuples of ``k`` of the ``units`` (repeats allowed), k <= 2."""
    u = np.arange(units.size)
    if k == 0:
        return np.zeros((1, 0), dtype=int)
    if k == 1:
        return u[:, None]
    i, j = np.triu_indices(units.size)
    return np.stack([i, j], axis=1)


def _plane_choices(pl: Plane, masses: np.ndarray, counts: np.ndarray, centre: complex,
                   radius: float) -> tuple[np.ndarray, np.ndarray]:
    """The choices of plane ``pl`` whose correction lies within ``radius`` of ``centre``:
    ((m, most) unit indices, -1 for none; (m,) corrections). A unit is hole h * S + size s."""
    from scipy.spatial import cKDTree

    S = masses.size
    units = np.array([m * pl.factor * complex(math.cos(a), math.sin(a)) for a in pl.angles for m in masses])
    out, total = [np.full((0, pl.most), -1)], 0
    for k in range(pl.most + 1):
        A, B = _combos(units, (k + 1) // 2), _combos(units, k // 2)
        sa, sb = units[A].sum(axis=1), units[B].sum(axis=1)
        tree = cKDTree(np.stack([sa.real, sa.imag], axis=1))
        q = centre - sb
        hits = tree.query_ball_point(np.stack([q.real, q.imag], axis=1), radius, return_sorted=True)
        nb = np.fromiter((len(h) for h in hits), int, len(hits))
        total += int(nb.sum())
        if total > MAX_CHOICES:
            raise BalanceValueError("drawer", f"the drawer offers more than {MAX_CHOICES} choices near the "
                                              "correction; give fewer weights a plane, holes or sizes")
        ia = np.concatenate([np.asarray(h, dtype=int) for h in hits]) if nb.sum() else np.zeros(0, int)
        ib = np.repeat(np.arange(len(hits)), nb)
        c = np.concatenate([A[ia], B[ib]], axis=1)
        if k >= 2:  # each multiset once: the first half's last index at most the second's first
            c = c[A[ia][:, -1] <= B[ib][:, 0]]
        hole, size = c // S, c % S
        ok = np.sum(masses[size], axis=1) <= pl.max_mass * (1 + 1e-12)
        for j in range(k):
            ok &= np.sum(hole == hole[:, j:j + 1], axis=1) <= pl.per_hole
            ok &= np.sum(size == size[:, j:j + 1], axis=1) <= counts[size[:, j]]
        out.append(np.pad(c[ok], ((0, 0), (0, pl.most - k)), constant_values=-1))
    c = np.concatenate(out)
    return c, np.where(c >= 0, units[np.maximum(c, 0)], 0).sum(axis=1)


def best_weights(alpha: np.ndarray, v0: np.ndarray, w: np.ndarray, method: str, planes: list[Plane],
                 drawers: list[tuple[np.ndarray, np.ndarray]], limits: np.ndarray | None = None,
                 start: np.ndarray | None = None) -> Choice:
    """The best choice of weights (see the module notes).

    Parameters
    ----------
    alpha : (N, P) complex, per kg at the trial radius; v0 : (N,); w : (N,) weights
    method : "least-squares" or "min-max" (an exact job is judged by least squares)
    planes : P Plane
    drawers : per drawer (masses kg (S,), counts (S,) int)
    limits : (N,) largest |r_k| (inf: none), or None
    start : (P,) complex — min-max: the continuous optimum; its multipliers λ weigh the
        bound ``G² >= Σ μ_k (w_k |r_k|)²``, ``μ = 0.999 λ + 0.001/N`` (without it 1/N)

    Raises
    ------
    BalanceValueError
        ``drawer``: more choices near the correction than :data:`MAX_CHOICES`.
    """
    from scipy.optimize import nnls
    from scipy.spatial import cKDTree

    n, p = alpha.shape
    w0 = w
    s = float(np.max(np.abs(alpha)))  # readings and limits scaled alike: the same choice, no overflow
    alpha, v0, w = alpha / s, v0 / s, w / np.max(w)
    L = np.full(n, np.inf) if limits is None else np.asarray(limits, dtype=float) / s
    wq = w / math.sqrt(n) if method == "min-max" else w
    if method == "min-max" and start is not None:  # μ: the min-max multipliers, a little of 1/N
        r = v0 + np.einsum("kj,j->k", alpha, start)
        a = w * np.abs(r)
        top = np.flatnonzero(a >= np.max(a) * (1 - 1e-6))
        g = w[top, None] * alpha[top].conj() * (r[top] / np.maximum(np.abs(r[top]), 1e-300))[:, None]
        lam = np.zeros(n)
        lam[top] = nnls(np.vstack([g.real.T, g.imag.T, np.full((1, top.size), 1e3 * np.max(np.abs(g)))]),
                        np.append(np.zeros(2 * p), 1e3 * np.max(np.abs(g))))[0]
        if np.sum(lam) > 0.0:
            wq = w * np.sqrt((1 - 1e-3) * lam / np.sum(lam) + 1e-3 / n)
    R = np.array(householder_qr(wq[:, None] * alpha, np.zeros(n, dtype=complex))[0])
    Wq = least_squares(alpha, v0, wq)
    F0 = float(np.sum((wq * np.abs(v0 + np.einsum("kj,j->k", alpha, Wq))) ** 2))
    shadow = np.sqrt(np.sum(np.abs(np.linalg.inv(R)) ** 2, axis=1))  # plane j's disc: sqrt(δ (Q⁻¹)_jj)
    mm = [drawers[pl.drawer][0] * pl.factor for pl in planes]
    reach = [abs(Wq[j]) + sum(sorted(mm[j])[-planes[j].most:]) for j in range(p)]
    everything = float(np.sum(np.abs(R) ** 2)) * sum(x * x for x in reach)
    a0 = w * np.abs(v0)  # no weights at all: every better choice is within its bound
    empty = (float(np.sum(a0 ** 2)) if method == "least-squares" else float(np.max(a0)) ** 2) - F0
    delta = min(float(sum(np.sum(np.abs(R[:, j]) ** 2) * min(mm[j]) ** 2 for j in range(p))) / 1024.0, empty)
    for _ in range(200):
        cands = []
        for j, pl in enumerate(planes):
            masses, counts = drawers[pl.drawer]
            c, vec = _plane_choices(pl, masses, counts, complex(Wq[j]), shadow[j] * math.sqrt(delta) * (1 + 1e-12))
            usage = np.zeros((len(c), sum(d[0].size for d in drawers)), dtype=int)
            off = sum(d[0].size for d in drawers[:pl.drawer])
            for col in c.T:
                np.add.at(usage, (np.flatnonzero(col >= 0), off + col[col >= 0] % masses.size), 1)
            cands.append((c, vec, usage, cKDTree(np.stack([vec.real, vec.imag], axis=1))))
        found = _search(alpha, v0, w, method, L, R, Wq, F0, delta, cands, np.concatenate([d[1] for d in drawers]))
        if delta >= everything or found is not None and found[3] <= 1.0 and found[4] <= delta:
            picks, W, g, viol, _, examined = found
            weights = tuple(tuple((int(u) // drawers[planes[j].drawer][0].size,
                                   int(u) % drawers[planes[j].drawer][0].size) for u in cands[j][0][m] if u >= 0)
                            for j, m in enumerate(picks))
            return Choice(weights, W, g * s * float(np.max(w0)), max(viol, 0.0), examined)
        delta = max(4.0 * delta, found[4] if found is not None and found[3] <= 1.0 else 0.0)
    raise BalanceValueError("drawer", "no choice of the drawer's weights was found in reach of the correction; "
                                      "check the drawer's masses against the trial masses")


def _search(alpha, v0, w, method, L, R, Wq, F0, delta, cands, cap):
    """One search within ``δ``: (picks per plane, W, objective, violation, its bound,
    examined) of the best choice found, or None."""
    n, p = alpha.shape
    best: list = [None, None, math.inf, math.inf, math.inf, 0]  # picks, W, key, violation, bound, examined

    def level(i: int, W: np.ndarray, used: np.ndarray, spent: float, picks: list) -> None:
        c, vec, usage, tree = cands[i]
        e = np.sum(R[i, i + 1:] * (W[i + 1:] - Wq[i + 1:]))
        room = (min(delta, best[4]) if best[3] <= 1.0 else delta) * (1 + 1e-12) - spent
        if room < 0.0:
            return
        centre = Wq[i] - e / R[i, i]
        keep = np.array(tree.query_ball_point([centre.real, centre.imag], math.sqrt(room) / abs(R[i, i]),
                                              return_sorted=True), dtype=int)
        keep = keep[np.all(used + usage[keep] <= cap, axis=1)]
        term = np.abs(R[i, i] * (vec[keep] - Wq[i]) + e) ** 2
        keep, term = keep[np.argsort(term, kind="stable")], np.sort(term, kind="stable")
        if i > 0:
            for m, t in zip(keep, term):
                W[i] = vec[m]
                level(i - 1, W, used + usage[m], spent + t, [m] + picks)
            return
        best[5] += keep.size
        if best[5] > MAX_CHOICES:
            raise BalanceValueError("drawer", f"the drawer search examines more than {MAX_CHOICES} choices; "
                                              "give fewer weights a plane, holes or sizes")
        if not keep.size:
            return
        Ws = np.repeat(W[None, :], keep.size, axis=0)
        Ws[:, 0] = vec[keep]
        r = v0[None, :] + np.einsum("kj,mj->mk", alpha, Ws)
        a = w * np.abs(r)
        g = np.sqrt(np.sum(a * a, axis=1)) if method == "least-squares" else np.max(a, axis=1)
        viol = np.max(np.abs(r) / L, axis=1)
        key = np.where(viol <= 1.0, g, math.inf)
        k = int(np.argmin(key)) if np.isfinite(key).any() else int(np.argmin(viol))
        if ((key[k], viol[k]) < (best[2], best[3])) if best[3] > 1.0 else key[k] < best[2]:
            best[:5] = [[keep[k]] + picks, Ws[k].copy(), key[k], viol[k], float(g[k] ** 2 - F0)]

    level(p - 1, np.array(Wq, dtype=complex), np.zeros(cap.size, dtype=int), 0.0, [])
    if best[0] is None:
        return None
    a = w * np.abs(v0 + np.einsum("kj,j->k", alpha, best[1]))
    g = float(np.sqrt(np.sum(a * a))) if method == "least-squares" else float(np.max(a))
    return best[0], best[1], g, float(best[3]), best[4], best[5]
