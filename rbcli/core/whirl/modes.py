"""Whirl modes of the rigid rotor over speeds, each followed by its shape; the roots of a
mode's frequency or growth rate along the speed.

``(lambda^2 M + lambda (C + Omega G) + K) Q = 0`` is solved through its companion form for
every speed at once (one ``numpy.linalg.eig`` of a stack): for isotropic bearings the 4×4
complex companion of [r, phi] (each eigenvalue a mode, forward when Im lambda > 0), else
the 8×8 real companion of q (each complex pair a mode, two real roots an overdamped one).
Frequencies are in the fixed frame; ``zeta = -Re lambda / |lambda|``, ``delta = -2 pi Re
lambda / |Im lambda|``; a conservative rotor's Re lambda is set to 0 (Meirovitch, *Methods
of Analytical Dynamics*, §7.9). A mode is followed from speed to speed by its shape
(:func:`track`, the largest summed modal assurance criterion), never by its rank, and a
followed quantity's sign changes are roots by Brent's method (:func:`branch_roots`)."""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from rbcli.core.roots import brentq
from rbcli.core.whirl.model import (
    KINDS, WHIRLS, ModeShape, Rotor, cabs, damping_ratio, log_decrement, real_parts, shapes, weighted,
)

__all__ = ["Mode", "Campbell", "campbell", "modes_at", "track", "branch_roots", "follow",
           "followed", "growth", "GROWTH_RTOL"]

#: a mode grows when Re lambda exceeds this fraction of its |lambda| (well above the
#: eigen-solve's round-off, ~1e-15 of the largest root; a growth this slow doubles in some
#: 1e9 periods). Each root is judged against its own |lambda|: a slow mode's growth beside a
#: fast one is still growth. Thresholds are the roots of Re lambda = 0 itself.
GROWTH_RTOL = 1e-10
#: a part of a root within this fraction of the largest |lambda| at its speed is the
#: eigen-solve's round-off (~1e-16 to 1e-14 of it seen), read as 0: a mode whose |lambda|
#: is itself that small (bearings almost at one point: a nearly free pivot) has no sign
SOLVE_RTOL = 1e-12
#: a step between two speeds is clear when every mode's shape at the first has a MAC of
#: at least this with the mode it is assigned at the second (else the step is halved)
CLEAR_MAC = 0.8
_PERMS = np.array(list(itertools.permutations(range(4))))


@dataclass(frozen=True, eq=False)
class Mode:
    """One whirl mode at one speed: ``eigenvalue`` lambda (1/s), ``frequency`` |Im lambda|
    (rad/s, fixed frame), ``damping_ratio``, ``log_decrement``, ``shape`` (:class:`ModeShape`),
    ``vector`` (unit, mass-weighted [r_f, phi_f, r_b, phi_b] for the MAC) and ``growing``
    (:func:`growth` > 0)."""

    eigenvalue: complex
    frequency: float
    damping_ratio: float
    log_decrement: float | None
    shape: ModeShape
    vector: np.ndarray
    growing: bool

    @property
    def whirl(self) -> str:
        return self.shape.whirl


def _isotropic(rotor: Rotor, sp: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(lambda (n, 4), parts (n, 4, 4), oscillating (n, 4)) from the directional companion."""
    Kc, Cc = rotor.complex_matrices(sp)
    n = len(sp)
    Minv = np.array([1.0 / rotor.mass, 1.0 / rotor.It])[None, :, None]
    Gc = np.array([[0.0, 0.0], [0.0, -1j * rotor.Ip]])
    A = np.zeros((n, 4, 4), dtype=complex)
    A[:, :2, 2:] = np.eye(2)
    A[:, 2:, :2] = -Minv * Kc
    A[:, 2:, 2:] = -Minv * (Cc + sp[:, None, None] * Gc)
    lam, V = np.linalg.eig(A)
    scale = np.max(np.abs(lam), axis=1, keepdims=True)
    if rotor.conservative:
        lam = 1j * lam.imag
    else:  # an overdamped root: its imaginary part is the eigen-solve's round-off, not a whirl
        lam = np.where(np.abs(lam.imag) <= SOLVE_RTOL * scale, lam.real + 0j, lam)
    u = np.swapaxes(V[:, :2, :], 1, 2)  # (n, 4 modes, [R, PHI])
    zero = np.zeros_like(u)
    fwd = (lam.imag >= 0.0)[..., None]
    return lam, np.concatenate([np.where(fwd, u, zero), np.where(fwd, zero, u)], axis=-1), lam.imag != 0.0


def _real(rotor: Rotor, sp: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(lambda, parts, oscillating) from the real 8×8 companion: each root with Im > 0 a
    mode (in the eigen-solve's order), then each two real roots (by value) one
    non-oscillating mode, whose slower root decides growth."""
    K, C = rotor.matrices(sp)
    n = len(sp)
    Minv = (1.0 / np.diag(rotor.M()))[None, :, None]
    A = np.zeros((n, 8, 8))
    A[:, :4, 4:] = np.eye(4)
    A[:, 4:, :4] = -Minv * K
    A[:, 4:, 4:] = -Minv * (C + sp[:, None, None] * rotor.G())
    lam8, V8 = np.linalg.eig(A)
    tol = 0.0 if rotor.conservative else SOLVE_RTOL * np.max(np.abs(lam8), axis=1, keepdims=True)
    upper = lam8.imag > tol
    real = np.abs(lam8.imag) <= tol
    # roots whirling first (their order kept), then the real ones by value, the rest last
    order = np.lexsort((np.where(real, lam8.real, 0.0), np.where(upper, 0, np.where(real, 1, 2))), axis=1)
    k = np.arange(4)[None, :]
    n_up = upper.sum(axis=1, keepdims=True)
    osc = k < n_up
    first = np.minimum(np.where(osc, k, n_up + 2 * (k - n_up)), 7)  # its root, or its real pair's first
    ia = np.take_along_axis(order, first, 1)
    ib = np.take_along_axis(order, np.minimum(first + ~osc, 7), 1)
    la, lb = np.take_along_axis(lam8, ia, 1), np.take_along_axis(lam8, ib, 1)
    lam = np.where(osc, 1j * la.imag if rotor.conservative else la, np.maximum(la.real, lb.real) + 0j)
    q = np.take_along_axis(np.swapaxes(V8[:, :4, :], 1, 2), ia[..., None], 1)
    return lam, real_parts(np.where(osc[..., None], q, q.real + 0j)), osc


def growth(lam: np.ndarray) -> np.ndarray:
    """Re lambda of the modes (..., 4) at a speed, 0 where it is within GROWTH_RTOL of the
    root's |lambda| or SOLVE_RTOL of the largest |lambda| there (a sign there means nothing)."""
    a = cabs(lam)
    tol = np.maximum(GROWTH_RTOL * a, SOLVE_RTOL * np.max(a, axis=-1, keepdims=True))
    return np.where(np.abs(lam.real) <= tol, 0.0, lam.real)


def _order(lam: np.ndarray, code: np.ndarray) -> np.ndarray:
    """(n, 4) index: ascending frequency; modes whose frequencies agree to 1e-9 (a
    forward/backward pair at rest on isotropic bearings) backward first."""
    f = np.abs(lam.imag)
    idx = np.argsort(f, axis=1, kind="stable")
    f, c = np.take_along_axis(f, idx, 1), np.take_along_axis(code, idx, 1)
    for i in range(3):
        swap = (np.abs(f[:, i] - f[:, i + 1]) <= 1e-9 * np.maximum(f[:, i], f[:, i + 1])) & (c[:, i] > c[:, i + 1])
        for a in (idx, f, c):
            a[swap, i], a[swap, i + 1] = a[swap, i + 1], a[swap, i].copy()
    return idx


@dataclass(frozen=True, eq=False)
class Campbell:
    """Whirl modes over speeds, numbered by frequency at each: ``speeds`` (N,) rad/s,
    ``eigenvalues`` (N, 4), ``vectors`` (N, 4, 4) (Mode.vector), ``whirl``, ``kind`` (indices
    in :data:`WHIRLS`, :data:`KINDS`), ``share``, ``node`` (m, NaN for none), ``growing``."""

    speeds: np.ndarray
    eigenvalues: np.ndarray
    vectors: np.ndarray
    whirl: np.ndarray
    kind: np.ndarray
    share: np.ndarray
    node: np.ndarray
    growing: np.ndarray
    rotor: Rotor

    @property
    def frequency(self) -> np.ndarray:
        return np.abs(self.eigenvalues.imag)

    @property
    def damping_ratio(self) -> np.ndarray:
        a = cabs(self.eigenvalues)
        return np.divide(-growth(self.eigenvalues), a, out=np.zeros(a.shape), where=a > 0.0)

    def mode(self, j: int, i: int) -> Mode:
        """Mode i (by frequency) at speed j."""
        lam = complex(self.eigenvalues[j, i])
        node, banded = float(self.node[j, i]), complex(growth(self.eigenvalues[j])[i], lam.imag)
        shape = ModeShape(WHIRLS[self.whirl[j, i]], float(self.share[j, i]), KINDS[self.kind[j, i]],
                          None if math.isnan(node) else node)
        return Mode(lam, abs(lam.imag), damping_ratio(banded), log_decrement(banded), shape,
                    self.vectors[j, i], bool(self.growing[j, i]))

    def modes(self, j: int) -> list[Mode]:
        return [self.mode(j, i) for i in range(4)]


def _solve(rotor: Rotor, sp: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(lambda (N, 4), parts (N, 4, 4), oscillating (N, 4)) at the speeds ``sp``, unsorted."""
    return (_isotropic if rotor.isotropic else _real)(rotor, sp)


def campbell(rotor: Rotor, speeds) -> Campbell:
    """The four modes at each of ``speeds`` (rad/s, (N,)), numbered by frequency."""
    sp = np.array(speeds, dtype=float).reshape(-1)
    lam, parts, osc = _solve(rotor, sp)
    s = shapes(rotor, parts, osc)
    w = weighted(rotor, parts)
    idx = _order(lam, s["whirl"])
    take = lambda a: np.take_along_axis(a, idx, 1)  # noqa: E731
    lam = take(lam)
    arrays = [sp, lam, np.take_along_axis(w, idx[..., None], 1), take(s["whirl"]), take(s["kind"]),
              take(s["share"]), take(s["node"]), growth(lam) > 0.0]
    for a in arrays:
        a.setflags(write=False)
    return Campbell(*arrays, rotor)


def modes_at(rotor: Rotor, speed: float) -> list[Mode]:
    """The four whirl modes at ``speed`` (rad/s), by ascending frequency."""
    return campbell(rotor, [speed]).modes(0)


def followed(rotor: Rotor, speeds, *refs: np.ndarray, whirl: str | None = None, classify: bool = True):
    """At each of ``speeds``, the mode whose shape is nearest the reference shapes ``refs``
    (Mode vectors: the largest summed MAC; of the same whirl when given and one exists):
    (eigenvalues (N,), weighted shapes (N, 4), the :func:`shapes` arrays (N,), or None
    without ``classify``)."""
    lam, parts, osc = _solve(rotor, np.asarray(speeds, dtype=float).reshape(-1))
    w = weighted(rotor, parts)
    score = sum(np.abs(w.conj() @ r) ** 2 for r in refs)  # unit shapes: the MAC itself
    s = shapes(rotor, parts, osc) if classify or whirl is not None else None
    if whirl is not None:
        same = s["whirl"] == WHIRLS.index(whirl)
        score = np.where(same | ~np.any(same, axis=1, keepdims=True), score, -1.0)
    k = np.argmax(score, axis=1)[:, None]
    pick = lambda a: np.take_along_axis(a, k, 1)[:, 0]  # noqa: E731
    return pick(lam), np.take_along_axis(w, k[..., None], 1)[:, 0], \
        None if not classify else {n: pick(a) for n, a in s.items()}


def follow(rotor: Rotor, speed: float, *refs: np.ndarray, whirl: str | None = None) -> Mode:
    """The mode at ``speed`` whose shape is nearest the reference shapes ``refs``
    (:func:`followed` at one speed)."""
    lam, w, s = followed(rotor, [speed], *refs, whirl=whirl)
    lk, node = complex(lam[0]), float(s["node"][0])
    shape = ModeShape(WHIRLS[s["whirl"][0]], float(s["share"][0]), KINDS[s["kind"][0]],
                      None if math.isnan(node) else node)
    return Mode(lk, abs(lk.imag), damping_ratio(lk), log_decrement(lk), shape, w[0],
                bool(lk.real > GROWTH_RTOL * abs(lk)))


def _macs(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """(..., 4, 4): MAC of every unit shape of ``a`` (..., 4, 4) with every one of ``b``."""
    return np.abs(np.conj(a) @ np.swapaxes(b, -1, -2)) ** 2


def _assign(M: np.ndarray, lam_a: np.ndarray, lam_b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The best assignment (…, 4) of each step's MAC matrix M (…, 4, 4), and whether it
    is clear: each mode's MAC with its match, counting the modes equal to it in
    eigenvalue (a degenerate pair is compared as a pair), at least CLEAR_MAC."""
    score = M[..., np.arange(4), _PERMS].sum(axis=-1)  # (..., 24)
    p = _PERMS[np.argmax(score, axis=-1)]
    same = np.abs(lam_b[..., :, None] - lam_b[..., None, :]) <= 1e-9 * np.abs(lam_b[..., :, None])
    got = np.take_along_axis(M @ same.astype(float), p[..., None], -1)[..., 0]  # (…, 4)
    # a non-oscillating (overdamped) mode's shape is that of one of its two real roots:
    # not a shape to follow
    still = (lam_a.imag == 0.0) | (np.take_along_axis(lam_b, p, -1).imag == 0.0)
    return p, np.all((got >= CLEAR_MAC) | still, axis=-1)


def _link(rotor: Rotor, a: float, wa: np.ndarray, la: np.ndarray, b: float, wb: np.ndarray,
          lb: np.ndarray, depth: int) -> np.ndarray:
    """The assignment of the modes at speed a to those at b, halving the step up to
    ``depth`` times where the shapes change too fast to be clear."""
    p, clear = _assign(_macs(wa, wb), la, lb)
    if clear or depth == 0:
        return p
    mid = campbell(rotor, [0.5 * (a + b)])
    wm, lm = mid.vectors[0], mid.eigenvalues[0]
    first = _link(rotor, a, wa, la, 0.5 * (a + b), wm, lm, depth - 1)
    return _link(rotor, 0.5 * (a + b), wm, lm, b, wb, lb, depth - 1)[first]


def track(cb: Campbell, depth: int = 12) -> np.ndarray:
    """(N, 4) int: ``ranks[j, k]`` is the frequency index at speed j of the mode followed
    by its shape from mode k at the first speed (see the module docstring)."""
    n = len(cb.speeds)
    ranks = np.zeros((n, 4), dtype=int)
    ranks[0] = np.arange(4)
    if n < 2:
        return ranks
    lam, vec, sp = cb.eigenvalues, cb.vectors, cb.speeds
    steps, clear = _assign(_macs(vec[:-1], vec[1:]), lam[:-1], lam[1:])
    for j in range(n - 1):
        p = steps[j] if clear[j] else _link(cb.rotor, float(sp[j]), vec[j], lam[j], float(sp[j + 1]),
                                            vec[j + 1], lam[j + 1], depth)
        ranks[j + 1] = p[ranks[j]]
    return ranks


def branch_roots(cb: Campbell, ranks: np.ndarray, values: np.ndarray, fn) -> list[tuple[float, int, Mode, float]]:
    """Where a followed quantity of a mode changes sign between two speeds of ``cb``:
    ``values`` (N, 4) its value at each speed (by frequency index; 0 where it is to be read
    as neither sign), ``fn(eigenvalue, speed)`` the same of one mode. Each root is solved by
    Brent's method (to ~1e-12 of the speed) on the mode followed by its shape from both
    ends of its bracket (two speeds with values of opposite signs, zeros between them).

    Returns
    -------
    list of (speed rad/s, branch k, Mode at the root, sign after it), by speed
    """
    out = []
    sp = cb.speeds
    v = np.take_along_axis(values, ranks, 1)  # by branch
    for k in range(4):
        nz = np.nonzero(v[:, k])[0]
        for a, b in zip(nz[:-1], nz[1:]):
            if v[a, k] * v[b, k] > 0.0:
                continue
            lo, hi = float(sp[a]), float(sp[b])
            refs = (cb.vectors[a, ranks[a, k]], cb.vectors[b, ranks[b, k]])
            seen: dict[float, float] = {}

            def g(x: float, refs=refs, seen=seen) -> float:
                if x not in seen:
                    seen[x] = fn(complex(followed(cb.rotor, [x], *refs, classify=False)[0][0]), x)
                return seen[x]

            if g(lo) * g(hi) < 0.0:
                x = brentq(g, lo, hi, xtol=1e-12 * hi, rtol=4e-16)
            else:  # the followed mode's signs agree at both ends (or one is 0): the grid's kept
                x = lo if abs(v[a, k]) < abs(v[b, k]) else hi
            out.append((x, k, follow(cb.rotor, x, *refs), float(np.sign(v[b, k]))))
    out.sort(key=lambda t: (t[0], t[1]))
    return out
