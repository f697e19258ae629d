"""Least squares and min-max under second-order cone constraints: minimise ``½|B z + b|² +
c·z`` subject to ``|G_i z + h_i| <= a_i·z + β_i`` by a log-barrier method (Boyd and
Vandenberghe, *Convex Optimization*, §11.3; ``-log ψ_i``, ``ψ_i = (a_i·z + β_i)² - |G_i z +
h_i|²``), then Newton on the KKT equations of its active set (exact to round-off). Elementwise
numpy with fixed-order sums (``einsum``, :func:`lu_solve`; no BLAS): the same bits for any
BLAS thread count.
"""

from __future__ import annotations

import numpy as np


def mm(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """``x @ y`` in a fixed order of summation (numpy's ``einsum`` loops, no BLAS)."""
    return np.einsum("ik,kj->ij", x, y, optimize=False)


def lu_solve(m: np.ndarray, v: np.ndarray) -> np.ndarray | None:
    """``m⁻¹ v`` by Gaussian elimination with partial pivoting (Golub and Van Loan §3.4),
    elementwise; None when ``m`` is singular to round-off."""
    a = np.array(m, dtype=np.result_type(m, v, float))
    x = np.array(v, dtype=a.dtype)
    big = float(np.max(np.abs(a))) if x.size else 0.0
    for k in range(x.size):
        p = k + int(np.argmax(np.abs(a[k:, k])))
        if not abs(a[p, k]) > 1e-14 * big:
            return None
        a[[k, p]], x[[k, p]] = a[[p, k]], x[[p, k]]
        f = a[k + 1:, k] / a[k, k]
        a[k + 1:, k:] -= f[:, None] * a[k, k:]
        x[k + 1:] -= f * x[k]
    for k in range(x.size - 1, -1, -1):
        x[k] = (x[k] - np.sum(a[k, k + 1:] * x[k + 1:])) / a[k, k]
    return x if np.all(np.isfinite(x)) else None


def singular_values(r: np.ndarray) -> np.ndarray:
    """A complex matrix's singular values, largest first: one-sided Jacobi (Hestenes 1958;
    Demmel and Veselić 1992), columns rotated in round-robin pairs, elementwise."""
    p = r.shape[1]
    u = np.hstack([np.array(r, dtype=complex), np.zeros((r.shape[0], p % 2))])
    q = u.shape[1]
    order = list(range(q))
    for _ in range(60):
        done = True
        for _ in range(q - 1):
            i, j = np.array(order[: q // 2]), np.array(order[q // 2:][::-1])
            x, y = u[:, i], u[:, j]
            al, be, ga = np.sum(abs(x) ** 2, axis=0), np.sum(abs(y) ** 2, axis=0), np.sum(x.conj() * y, axis=0)
            g = np.abs(ga)
            go = g > 1e-14 * np.sqrt(al * be)
            done = done and not np.any(go)
            zeta = (be - al) / (2.0 * np.where(go, g, 1.0))
            t = np.where(go, np.sign(zeta + (zeta == 0)) / (np.abs(zeta) + np.sqrt(1.0 + zeta**2)), 0.0)
            c = 1.0 / np.sqrt(1.0 + t**2)
            y = y * np.where(go, ga / np.where(g > 0, g, 1.0), 1.0).conj()
            u[:, i], u[:, j] = c * x - c * t * y, c * t * x + c * y
            order = order[:1] + order[-1:] + order[1:-1]
        if done:
            break
    return np.sort(np.sqrt(np.sum(abs(u[:, :p]) ** 2, axis=0)))[::-1]


class Cones:
    """``|G_i z + h_i| <= a_i·z + β_i``: ``G`` (C, 2, n), ``h`` (C, 2), ``a`` (C, n), ``beta`` (C,)."""

    def __init__(self, G: np.ndarray, h: np.ndarray, a: np.ndarray, beta: np.ndarray):
        self.G, self.h, self.a, self.beta = G, h, a, beta

    def parts(self, z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        return np.einsum("ckn,n->ck", self.G, z) + self.h, np.einsum("cn,n->c", self.a, z) + self.beta

    def slack(self, z: np.ndarray) -> np.ndarray:
        u, s = self.parts(z)
        return s - np.sqrt(np.sum(u * u, axis=1))

    def grad(self, z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """ψ_i and ∇ψ_i (C, n)."""
        u, s = self.parts(z)
        return s * s - np.sum(u * u, axis=1), 2.0 * (s[:, None] * self.a - np.einsum("ck,ckn->cn", u, self.G))

    def weighted(self, w: np.ndarray) -> np.ndarray:
        """``Σ_i w_i ∇²ψ_i = Σ_i 2 w_i (a_i a_iᵀ - G_iᵀ G_i)``."""
        return 2.0 * (np.einsum("c,cm,cn->mn", w, self.a, self.a, optimize=False)
                      - np.einsum("c,ckm,ckn->mn", w, self.G, self.G, optimize=False))


def _f(B, b, c, z) -> float:
    r = np.einsum("kn,n->k", B, z) + b
    return 0.5 * float(np.sum(r * r)) + float(np.sum(c * z))


def _df(B, b, c, z) -> np.ndarray:
    return np.einsum("kn,k->n", B, np.einsum("kn,n->k", B, z) + b) + c


def _barrier(B, b, c, cones: Cones, z: np.ndarray) -> tuple[np.ndarray, float]:
    """The barrier method's last point and its ``t`` (the duality gap is about ``C/t``)."""
    H0, t = mm(B.T, B), 1.0
    for _ in range(40):
        for _ in range(60):
            psi, g = cones.grad(z)
            grad = t * _df(B, b, c, z) - np.sum(g / psi[:, None], axis=0)
            dz = lu_solve(t * H0 - cones.weighted(1.0 / psi) + mm(g.T / psi, g / psi[:, None]), -grad)
            if dz is None:
                return z, t
            dec = -float(np.sum(grad * dz))  # the Newton decrement, squared
            if dec <= 1e-11:
                break
            step, f0 = 1.0, t * _f(B, b, c, z) - float(np.sum(np.log(psi)))
            while step > 1e-12:  # backtracking, inside the cones
                zn = z + step * dz
                psn = cones.grad(zn)[0]
                if np.all(cones.slack(zn) > 0.0) and np.all(psn > 0.0) and \
                        t * _f(B, b, c, zn) - np.sum(np.log(psn)) <= f0 - 0.25 * step * dec:
                    break
                step *= 0.5
            else:
                break
            z = zn
        if cones.beta.size / t < 1e-12:
            break
        t *= 10.0
    return z, t


def _polish(B, b, c, cones: Cones, z: np.ndarray, t: float) -> np.ndarray:
    """Newton on ``∇f - Σ μ_i ∇ψ_i = 0``, ``ψ_i = 0`` over the barrier's active set (its
    multiplier 1/(t ψ) above ψ); kept if it converges with μ >= 0, every constraint met
    and the objective no worse, else ``z``."""
    psi, _ = cones.grad(z)
    S = np.flatnonzero(psi * psi * t < 1.0)
    if S.size == 0:
        return z
    n, k, H0 = z.size, S.size, mm(B.T, B)
    sub = Cones(cones.G[S], cones.h[S], cones.a[S], cones.beta[S])
    y = np.concatenate([z, 1.0 / (t * psi[S])])
    for _ in range(30):
        zz, mu = y[:n], y[n:]
        psi_s, gs = sub.grad(zz)
        J = np.zeros((n + k, n + k))
        J[:n, :n], J[:n, n:], J[n:, :n] = H0 - sub.weighted(mu), -gs.T, gs
        step = lu_solve(J, -np.concatenate([_df(B, b, c, zz) - np.sum(mu[:, None] * gs, axis=0), psi_s]))
        if step is None:
            return z
        y = y + step
        if np.max(np.abs(step)) <= 1e-15 * max(1.0, float(np.max(np.abs(y)))):
            break
    zz, mu = y[:n], y[n:]
    ok = np.all(mu >= -1e-9) and np.all(np.isfinite(y)) and np.all(
        cones.slack(zz) >= -1e-12 * (1.0 + np.abs(cones.parts(zz)[1])))
    return zz if ok and _f(B, b, c, zz) <= _f(B, b, c, z) + 1e-12 * (1.0 + abs(_f(B, b, c, z))) else z


def socp(B: np.ndarray, b: np.ndarray, c: np.ndarray, cones: Cones, z: np.ndarray) -> np.ndarray:
    """``argmin ½|B z + b|² + c·z`` subject to ``cones`` (``B`` (K, n) may have no rows), from
    ``z`` (n,) strictly inside them."""
    z, t = _barrier(B, b, c, cones, np.array(z, dtype=float))
    return _polish(B, b, c, cones, z, t)
