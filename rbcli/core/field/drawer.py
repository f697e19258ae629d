"""The best weights from a drawer at a rotor's holes: an exact search.

A plane takes at most ``most`` weights, ``per_hole`` a hole, ``max_mass`` in all; mass m at
hole angle θ is ``m ρ e^{iθ}`` at the trial radius (ρ = hole radius / trial radius). The
objective is the method's on ``r = V0 + alpha W``, under ``|r_k| <= L_k`` (if no choice meets
them, the one exceeding them least). A sphere decoder (Agrell et al., IEEE Trans. Inf. Theory
48(8), 2002): ``Σ μ_k (w_k |r_k|)² = F_μ* + |R (W - W_μ)|²`` (μ = 1, or min-max's multipliers)
is the least-squares objective or at most min-max's squared, so every better choice lies in
an ellipsoid; each plane's choices in its shadow are enumerated (halves of two weights met in
a k-d tree), the planes searched from the last, and the ellipsoid grown until the best found
is proven or holds every choice.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rbcli.core.balance.common import BalanceValueError
from rbcli.core.field.solve import householder_qr, least_squares

#: the most weights a plane takes; the most choices examined (per plane, and in all)
MOST_WEIGHTS, MAX_CHOICES = 4, 20_000_000


@dataclass(frozen=True)
class Plane:
    """A plane: hole angles (rad), hole radius / trial radius, at most ``most`` weights,
    ``per_hole`` in a hole, ``max_mass`` kg, the drawer (index) its weights come from."""

    angles: tuple[float, ...]
    factor: float
    most: int
    per_hole: int = 1
    max_mass: float = math.inf
    drawer: int = 0


@dataclass(frozen=True)
class Choice:
    """Per plane its (hole, size) indices; the corrections (P,) kg at the trial radius; the
    objective (sqrt F or G); max |r_k|/L_k; the choices evaluated."""

    weights: tuple[tuple[tuple[int, int], ...], ...]
    corrections: np.ndarray
    objective: float
    violation: float
    examined: int


def _budget(n: int) -> None:
    if n > MAX_CHOICES:
        raise BalanceValueError("drawer", f"the drawer search examines more than {MAX_CHOICES} choices; give fewer "
                                          "weights a plane, holes or sizes")


def _choices(pl: Plane, masses: np.ndarray, counts: np.ndarray, centre: complex, radius: float) -> tuple:
    """Plane ``pl``'s choices within ``radius`` of ``centre``: ((m, most) units, -1 for none;
    (m,) corrections). Unit ``h * S + s`` is size s at hole h."""
    from scipy.spatial import cKDTree

    S = masses.size
    units = np.array([m * pl.factor * complex(math.cos(a), math.sin(a)) for a in pl.angles for m in masses])
    i, j = np.triu_indices(units.size)
    halves = [np.zeros((1, 0), int), np.arange(units.size)[:, None], np.stack([i, j], axis=1)]
    out, total = [], 0
    for k in range(pl.most + 1):
        A, B = halves[(k + 1) // 2], halves[k // 2]
        sa, q = units[A].sum(axis=1), centre - units[B].sum(axis=1)
        hits = cKDTree(np.stack([sa.real, sa.imag], axis=1)).query_ball_point(
            np.stack([q.real, q.imag], axis=1), radius, return_sorted=True)
        nb = np.fromiter(map(len, hits), int, len(hits))
        _budget(total := total + int(nb.sum()))
        ia, ib = np.array([x for h in hits for x in h], dtype=int), np.repeat(np.arange(len(hits)), nb)
        c = np.concatenate([A[ia], B[ib]], axis=1)[(A[ia][:, -1] <= B[ib][:, 0]) if k >= 2 else slice(None)]
        hole, size = c // S, c % S  # each multiset once (sorted halves); its holes, counts and mass
        ok = np.sum(masses[size], axis=1) <= pl.max_mass * (1 + 1e-12)
        for x in range(k):
            ok &= (np.sum(hole == hole[:, x:x + 1], axis=1) <= pl.per_hole) & (
                np.sum(size == size[:, x:x + 1], axis=1) <= counts[size[:, x]])
        out.append(np.pad(c[ok], ((0, 0), (0, pl.most - k)), constant_values=-1))
    c = np.concatenate(out)
    return c, np.where(c >= 0, units[np.maximum(c, 0)], 0).sum(axis=1)


def _mu(alpha: np.ndarray, v0: np.ndarray, w: np.ndarray, start: np.ndarray | None) -> np.ndarray:
    """Min-max's bound weights: 0.999 λ + 0.001/N, λ its multipliers at the optimum ``start``
    (``Σ λ_k w_k conj(α_k) u_k = 0``, ``Σ λ = 1``, λ >= 0: NNLS); 1/N without it."""
    from scipy.optimize import nnls

    n, p = alpha.shape
    if start is None:
        return np.full(n, 1.0 / n)
    r = v0 + np.einsum("kj,j->k", alpha, start)
    top = np.flatnonzero(w * np.abs(r) >= np.max(w * np.abs(r)) * (1 - 1e-6))
    g = w[top, None] * alpha[top].conj() * (r[top] / np.maximum(np.abs(r[top]), 1e-300))[:, None]
    big = 1e3 * np.max(np.abs(g))
    lam = np.zeros(n)
    lam[top] = nnls(np.vstack([g.real.T, g.imag.T, np.full((1, top.size), big)]), np.append(np.zeros(2 * p), big))[0]
    return (1 - 1e-3) * lam / np.sum(lam) + 1e-3 / n if np.sum(lam) > 0.0 else np.full(n, 1.0 / n)


def best_weights(alpha: np.ndarray, v0: np.ndarray, w: np.ndarray, method: str, planes: list[Plane],
                 drawers: list[tuple[np.ndarray, np.ndarray]], limits: np.ndarray | None = None,
                 start: np.ndarray | None = None) -> Choice:
    """The best choice (the module notes) for ``alpha`` (N, P) per kg, ``v0``, weights ``w``,
    the method, planes, drawers ((kg, counts)), largest |r_k| and min-max's continuous
    optimum (it tightens the bound); ``drawer`` refused beyond :data:`MAX_CHOICES`."""
    from scipy.spatial import cKDTree

    n, p = alpha.shape
    s, w0 = float(np.max(np.abs(alpha))), float(np.max(w))  # scaled alike: the same choice, no overflow
    alpha, v0, w = alpha / s, v0 / s, w / w0
    L = np.full(n, np.inf) if limits is None else np.asarray(limits, dtype=float) / s
    wq = w * np.sqrt(_mu(alpha, v0, w, start)) if method == "min-max" else w
    R = np.array(householder_qr(wq[:, None] * alpha, np.zeros(n, dtype=complex))[0])
    Wq = least_squares(alpha, v0, wq)
    F0 = float(np.sum((wq * np.abs(v0 + np.einsum("kj,j->k", alpha, Wq))) ** 2))
    shadow = np.sqrt(np.sum(np.abs(np.linalg.inv(R)) ** 2, axis=1))  # plane j's disc: sqrt(δ (Q⁻¹)_jj)
    mm = [drawers[pl.drawer][0] * pl.factor for pl in planes]
    everything = float(np.sum(np.abs(R) ** 2)) * sum((abs(Wq[j]) + sum(sorted(mm[j])[-pl.most:])) ** 2
                                                   for j, pl in enumerate(planes))
    a0 = w * np.abs(v0)  # no weights at all: every better choice is within its bound
    empty = (float(np.sum(a0 ** 2)) if method == "least-squares" else float(np.max(a0)) ** 2) - F0
    delta = min(sum(float(np.sum(np.abs(R[:, j]) ** 2)) * min(mm[j]) ** 2 for j in range(p)) / 1024.0, empty)
    cap, offs = np.concatenate([d[1] for d in drawers]), np.cumsum([0] + [d[0].size for d in drawers])
    for _ in range(200):
        cands = []
        for j, pl in enumerate(planes):
            masses, counts = drawers[pl.drawer]
            c, vec = _choices(pl, masses, counts, complex(Wq[j]), shadow[j] * math.sqrt(delta) * (1 + 1e-12))
            usage = np.zeros((len(c), cap.size), dtype=np.int8)
            for col in c.T:
                np.add.at(usage, (np.flatnonzero(col >= 0), offs[pl.drawer] + col[col >= 0] % masses.size), 1)
            cands.append((c, vec, usage, cKDTree(np.stack([vec.real, vec.imag], axis=1))))
        best = _search(alpha, v0, w, method, L, R, Wq, F0, delta, cands, cap)
        if delta >= everything or best[0] is not None and best[3] <= 1.0 and best[4] <= delta:
            picks, W, _, viol, _, examined = best
            r = w * np.abs(v0 + np.einsum("kj,j->k", alpha, W))
            g = math.sqrt(float(np.sum(r * r))) if method == "least-squares" else float(np.max(r))
            return Choice(tuple(tuple(divmod(int(u), drawers[planes[j].drawer][0].size) for u in cands[j][0][m]
                                      if u >= 0) for j, m in enumerate(picks)), W, g * s * w0, max(viol, 0.0), examined)
        delta = max(4.0 * delta, best[4] if best[3] <= 1.0 else 0.0)
    raise BalanceValueError("drawer", "no choice of the drawer's weights was found in reach of the correction; "
                                      "check the drawer's masses against the trial masses")


def _search(alpha, v0, w, method, L, R, Wq, F0, delta, cands, cap) -> list:
    """One search within ``δ``: [picks per plane, W, objective, violation, its bound,
    examined] of the best choice found (picks None: none)."""
    p = alpha.shape[1]
    best: list = [None, None, math.inf, math.inf, math.inf, 0]

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
        _budget(best[5])
        if keep.size:
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
    return best
