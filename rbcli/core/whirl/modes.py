"""Whirl modes of the rigid rotor at a speed, the Campbell diagram and the onset of
instability (:mod:`rbcli.core.whirl.model` has the equations).

At a speed Omega the free motion ``q = Q e^{lambda t}`` solves the quadratic eigenproblem
``(lambda^2 M + lambda (C + Omega G) + K) Q = 0``, solved here through its companion
(first-order) form ``A = [[0, I], [-M^-1 K, -M^-1 (C + Omega G)]]``:

- isotropic bearings: the 4×4 complex companion of the directional coordinates [r, phi];
  each of its four eigenvalues is one mode, forward when Im lambda > 0, backward when
  Im lambda < 0 (frequency |Im lambda|);
- otherwise: the 8×8 real companion of q; each complex pair is one mode (the root with
  Im lambda > 0), each two real roots one non-oscillating (overdamped) mode.

Whirl frequencies are in the fixed (bearing) frame. Damping ratio ``zeta = -Re lambda /
|lambda|``, logarithmic decrement ``delta = -2 pi Re lambda / |Im lambda|``; a mode grows
(is unstable) when Re lambda > 0. Without damping and without cross-coupled stiffness
the system is gyroscopic and conservative with K positive definite, hence stable with
every lambda on the imaginary axis (Thomson-Tait-Chetaev; e.g. Meirovitch, *Methods of
Analytical Dynamics*, §7.9): Re lambda is set to 0 there instead of carrying the
eigensolver's round-off (~1e-16 |lambda|).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from itertools import permutations

import numpy as np

from rbcli.core.whirl.model import (
    ModeShape, Rotor, damping_ratio, log_decrement, shape_of_complex, shape_of_real,
)

__all__ = ["Mode", "modes_at", "Campbell", "campbell", "GROWTH_RTOL", "onset_speeds", "mac"]

#: a mode grows when Re lambda exceeds this fraction of |lambda| (well above the
#: eigensolver's round-off, ~1e-15, and far below any damping ratio an engineer quotes)
GROWTH_RTOL = 1e-9


@dataclass(frozen=True, eq=False)
class Mode:
    """One whirl mode at one speed.

    Attributes
    ----------
    eigenvalue : complex — 1/s, lambda (the root with Im lambda >= 0 for real-coordinate
        modes; the directional root, sign of Im = whirl, for isotropic bearings)
    frequency : float — rad/s, |Im lambda|, fixed frame (0 for a non-oscillating mode)
    damping_ratio : float — -Re lambda/|lambda|
    log_decrement : float | None — -2 pi Re lambda/|Im lambda| (None when not oscillating)
    shape : ModeShape — whirl direction, kind and node
    vector : (4,) complex ndarray — the shape weighted for comparisons between modes of one
        rotor (MAC), unit norm: real coordinates [sqrt(m) (X + iY), sqrt(It) (TY - iTX),
        sqrt(m) (X - iY), sqrt(It) (TY + iTX)] (a unitary image of the mass-weighted q);
        isotropic bearings: [sqrt(m) R, sqrt(It) PHI] in the first (forward) or last
        (backward) two places
    """

    eigenvalue: complex
    frequency: float
    damping_ratio: float
    log_decrement: float | None
    shape: ModeShape
    vector: np.ndarray

    @property
    def growing(self) -> bool:
        """Re lambda > GROWTH_RTOL |lambda|: the mode grows (unstable)."""
        return self.eigenvalue.real > GROWTH_RTOL * abs(self.eigenvalue)

    @property
    def whirl(self) -> str:
        return self.shape.whirl


def mac(u: np.ndarray, v: np.ndarray) -> float:
    """The modal assurance criterion |u^H v|^2 / (|u|^2 |v|^2), 0..1."""
    nu = float(np.vdot(u, u).real)
    nv = float(np.vdot(v, v).real)
    if nu == 0.0 or nv == 0.0:
        return 0.0
    return abs(np.vdot(u, v)) ** 2 / (nu * nv)


def _conservative(rotor: Rotor) -> bool:
    """No damping and no cross-coupled stiffness: every root on the imaginary axis."""
    return not rotor.damped and all(b.kxy == 0.0 and b.kyx == 0.0 for b in rotor.bearings)


def _unit(v: np.ndarray) -> np.ndarray:
    n = float(np.linalg.norm(v))
    out = v / n if n > 0.0 else v
    out.setflags(write=False)
    return out


def _isotropic_modes(rotor: Rotor, speed: float) -> list[Mode]:
    Mc, Kc, Cc = rotor.complex_matrices()
    Gc = np.array([[0.0, 0.0], [0.0, -1j * rotor.Ip]])
    Minv = np.diag(1.0 / np.diag(Mc).real)
    A = np.zeros((4, 4), dtype=complex)
    A[:2, 2:] = np.eye(2)
    A[2:, :2] = -Minv @ Kc
    A[2:, 2:] = -Minv @ (Cc + speed * Gc)
    lam, V = np.linalg.eig(A)
    snap = _conservative(rotor)
    sm, si = math.sqrt(rotor.mass), math.sqrt(rotor.It)
    scale = float(np.max(np.abs(lam))) if lam.size else 1.0
    out = []
    for k in range(4):
        lk = complex(lam[k])
        if snap:
            lk = complex(0.0, lk.imag)
        elif abs(lk.imag) <= 1e-12 * scale:
            # an overdamped root: its imaginary part is round-off of the eigen-solve (as in
            # _real_modes, the same bound), not a whirl
            lk = complex(lk.real, 0.0)
        u = V[:2, k]
        forward = lk.imag >= 0.0
        osc = lk.imag != 0.0
        shape = shape_of_complex(rotor, u, forward, osc)
        w = np.array([sm * u[0], si * u[1], 0.0, 0.0] if forward else [0.0, 0.0, sm * u[0], si * u[1]],
                     dtype=complex)
        out.append(Mode(lk, abs(lk.imag), damping_ratio(lk), log_decrement(lk), shape, _unit(w)))
    return out


def _real_modes(rotor: Rotor, speed: float) -> list[Mode]:
    M, K, C, G = rotor.M(), rotor.K(), rotor.C(), rotor.G()
    Minv = np.diag(1.0 / np.diag(M))
    A = np.zeros((8, 8))
    A[:4, 4:] = np.eye(4)
    A[4:, :4] = -Minv @ K
    A[4:, 4:] = -Minv @ (C + speed * G)
    lam, V = np.linalg.eig(A)
    snap = _conservative(rotor)
    sm, si = math.sqrt(rotor.mass), math.sqrt(rotor.It)
    scale = float(np.max(np.abs(lam))) if lam.size else 1.0
    out = []
    reals = []
    for k in range(8):
        lk = complex(lam[k])
        if abs(lk.imag) <= 1e-12 * scale and not snap:
            reals.append((lk.real, V[:4, k]))
            continue
        if lk.imag < 0.0:
            continue
        if snap:
            lk = complex(0.0, lk.imag)
        q = V[:4, k]
        X, Y, TX, TY = (complex(v) for v in q)
        shape = shape_of_real(rotor, q)
        w = np.array([sm * (X + 1j * Y), si * (TY - 1j * TX),
                      sm * (X - 1j * Y), si * (TY + 1j * TX)], dtype=complex)
        out.append(Mode(lk, abs(lk.imag), damping_ratio(lk), log_decrement(lk), shape, _unit(w)))
    reals.sort(key=lambda t: t[0])
    for i in range(0, len(reals) - 1, 2):
        (s1, v1), (s2, _) = reals[i], reals[i + 1]
        wn = math.sqrt(abs(s1 * s2))
        zeta = -(s1 + s2) / (2.0 * wn) if wn > 0.0 else 1.0
        q = np.real(v1).astype(complex)
        X, Y, TX, TY = (complex(v) for v in q)
        shape = shape_of_real(rotor, q, oscillating=False)
        w = np.array([sm * (X + 1j * Y), si * (TY - 1j * TX), sm * (X - 1j * Y),
                      si * (TY + 1j * TX)], dtype=complex)
        lk = complex(max(s1, s2), 0.0)  # the slower root decides growth
        out.append(Mode(lk, 0.0, float(zeta), None, shape, _unit(w)))
    return out


_WHIRL_RANK = {"backward": 0, "linear": 1, "none": 2, "forward": 3}


def _order(modes: list[Mode]) -> list[Mode]:
    """Ascending frequency; modes whose frequencies agree to 1e-9 (a forward/backward pair
    at rest on isotropic bearings) backward first."""
    out = sorted(modes, key=lambda m: m.frequency)
    for i in range(len(out) - 1):
        a, b = out[i], out[i + 1]
        if abs(a.frequency - b.frequency) <= 1e-9 * max(a.frequency, b.frequency) and \
                _WHIRL_RANK[a.whirl] > _WHIRL_RANK[b.whirl]:
            out[i], out[i + 1] = b, a
    return out


def modes_at(rotor: Rotor, speed: float) -> list[Mode]:
    """The four whirl modes at ``speed`` (rad/s), by ascending frequency.

    Parameters
    ----------
    rotor : Rotor
    speed : float — rad/s, Omega (>= 0)

    Returns
    -------
    list of 4 Mode
    """
    modes = _isotropic_modes(rotor, speed) if rotor.isotropic else _real_modes(rotor, speed)
    return _order(modes)


@dataclass(frozen=True, eq=False)
class Campbell:
    """Whirl modes over a range of speeds (numbered by frequency at each speed).

    Attributes
    ----------
    speeds : (N,) ndarray — rad/s
    modes : tuple of N tuples of 4 Mode — ``modes[j][i]``: mode i (by frequency) at speed j
    """

    speeds: np.ndarray
    modes: tuple[tuple[Mode, ...], ...]

    def array(self, what: str) -> np.ndarray:
        """(4, N) ndarray of ``frequency`` or ``damping_ratio`` (mode i, speed j)."""
        return np.array([[getattr(m[i], what) for m in self.modes] for i in range(4)], dtype=float)


def campbell(rotor: Rotor, speeds: np.ndarray) -> Campbell:
    """The modes at each speed of ``speeds`` (rad/s, (N,) ascending)."""
    sp = np.array(speeds, dtype=float)
    sp.setflags(write=False)
    return Campbell(sp, tuple(tuple(modes_at(rotor, float(s))) for s in sp))


def follow(rotor: Rotor, speed: float, reference: np.ndarray, whirl: str | None = None) -> Mode:
    """The mode at ``speed`` whose shape is nearest ``reference`` (a Mode.vector): the
    continuation of a mode to a nearby speed (largest MAC; of the same whirl when given
    and one exists)."""
    ms = modes_at(rotor, speed)
    pool = [m for m in ms if whirl is None or m.whirl == whirl] or ms
    return max(pool, key=lambda m: mac(reference, m.vector))


def onset_speeds(rotor: Rotor, cb: Campbell) -> list[tuple[float, int, Mode]]:
    """Speeds inside the Campbell range where a mode starts or stops growing: the roots of
    Re lambda(Omega) between two grid speeds whose signs differ, solved by Brent's method
    (:func:`rbcli.core.roots.brentq`) on the mode continued by its shape.

    Returns
    -------
    list of (speed rad/s, mode index at the left grid point, Mode at the root)
    """
    from rbcli.core.roots import brentq

    out = []
    sp = cb.speeds
    for j in range(len(sp) - 1):
        for i in range(4):
            a, b = cb.modes[j][i], cb.modes[j + 1][i]
            if a.growing == b.growing:
                continue
            ref = a.vector

            def re(x: float, ref=ref) -> float:
                return follow(rotor, x, ref).eigenvalue.real

            lo, hi = float(sp[j]), float(sp[j + 1])
            f_lo, f_hi = re(lo), re(hi)
            if f_lo == 0.0 or f_hi == 0.0 or (f_lo > 0.0) == (f_hi > 0.0):
                x = lo if f_lo == 0.0 else hi
            else:
                x = brentq(re, lo, hi, xtol=1e-12 * max(hi, 1.0), rtol=4e-16)
            out.append((x, i, follow(rotor, x, ref)))
    out.sort(key=lambda t: t[0])
    return out


def permutation_match(prev: list[Mode], cur: list[Mode]) -> list[int]:
    """The assignment of ``cur`` to ``prev`` (4 each) that maximises the summed MAC."""
    best, best_p = -1.0, tuple(range(4))
    for p in permutations(range(len(cur))):
        s = sum(mac(prev[i].vector, cur[p[i]].vector) for i in range(len(prev)))
        if s > best + 1e-12:
            best, best_p = s, p
    return list(best_p)
