"""Critical speeds: where a whirl frequency equals an order n of the speed.

Undamped (exact, an eigenproblem in the speed, no grid). With ``q = Q e^{i n Omega t}``
the undamped equations become ``(K - Omega^2 (n^2 M - i n G)) Q = 0``: a generalized
eigenproblem for Omega^2, solved as the eigenvalues nu = 1/Omega^2 of ``K^-1 B``,
``B = n^2 M - i n G`` (K is invertible for two or more bearings at distinct places with
positive stiffness). Each real nu > 0 is a critical speed Omega = nu^(-1/2); nu <= 0 is a
branch that never meets the n× line.

Isotropic bearings split it by whirl direction (the physics sheet ``whirl.md``):

    forward:  K_c U = Omega^2 diag(n^2 m, n^2 It - n Ip) U,
    backward: K_c U = Omega^2 diag(n^2 m, n^2 It + n Ip) U.

With K_c positive definite the number of forward crossings is the number of positive
entries of the forward matrix (Sylvester's law of inertia): when ``n It <= Ip`` the
forward conical branch stays above the n× line at every speed (for n = 1: a disk-like
rotor, Ip >= It), and there is one forward crossing fewer. Symmetric bearings
(sum k a = 0) give the sheet's closed forms ``Omega^2 = sum k / m`` (cylindrical) and
``Omega^2 = sum k a^2 / (It -/+ Ip)`` (conical, forward / backward).

Damped: where the damped whirl frequency |Im lambda| of the mode equals n Omega, a root
of ``|Im lambda(Omega)| - n Omega`` by Brent's method, the mode followed by its shape
from the undamped critical speed (:func:`rbcli.core.whirl.modes.follow`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rbcli.core.whirl.model import ModeShape, Rotor, shape_of_complex, shape_of_real
from rbcli.core.whirl.modes import Mode, follow

__all__ = ["CriticalSpeed", "Missing", "critical_speeds", "damped_crossing"]

#: a generalized eigenvalue nu = 1/Omega^2 is real when |Im nu| <= this times |nu|
REAL_RTOL = 1e-9


@dataclass(frozen=True, eq=False)
class CriticalSpeed:
    """An undamped critical speed.

    Attributes
    ----------
    speed : float — rad/s
    order : int — n: the whirl frequency is n times the speed
    shape : ModeShape — whirl (forward/backward), kind and node of the mode there
    vector : (4,) complex ndarray — the weighted directional shape (as Mode.vector)
    q : (4,) complex ndarray — the mode in real coordinates: q(t) = Re(q e^{i n Omega t})
        of (x, y, theta_x, theta_y)
    """

    speed: float
    order: int
    shape: ModeShape
    vector: np.ndarray
    q: np.ndarray

    @property
    def whirl(self) -> str:
        return self.shape.whirl


@dataclass(frozen=True)
class Missing:
    """A branch that never meets the n× line, and why.

    Attributes
    ----------
    order : int
    whirl : str — "forward" or "backward"
    kind : str — "conical" (the tilt branch) or "mode" (any)
    reason : str — "gyroscopic" (n It <= Ip), "coincident" (n It = Ip exactly: at
        infinite speed) or "complex" (cross-coupled stiffness: no real crossing)
    It : float — kg m²
    Ip : float — kg m²
    """

    order: int
    whirl: str
    kind: str
    reason: str
    It: float
    Ip: float


def _weighted(rotor: Rotor, r_f, phi_f, r_b, phi_b) -> np.ndarray:
    sm, si = math.sqrt(rotor.mass), math.sqrt(rotor.It)
    w = np.array([sm * r_f, si * phi_f, sm * r_b, si * phi_b], dtype=complex)
    n = float(np.linalg.norm(w))
    out = w / n if n > 0.0 else w
    out.setflags(write=False)
    return out


def _real_of(U: np.ndarray, forward: bool) -> np.ndarray:
    """Real-coordinate amplitudes (x, y, theta_x, theta_y) of a directional shape [R, PHI]
    whirling forward (r = R e^{iwt}, phi = PHI e^{iwt}) or backward (e^{-iwt}).

    Forward: x + i y = R e^{iwt} gives X = R, Y = -i R; theta_y - i theta_x = PHI e^{iwt}
    gives TY = PHI, TX = i PHI. Backward: X = conj R, Y = i conj R, TY = conj PHI,
    TX = -i conj PHI."""
    R, P = complex(U[0]), complex(U[1])
    if forward:
        q = np.array([R, -1j * R, 1j * P, P], dtype=complex)
    else:
        Rc, Pc = R.conjugate(), P.conjugate()
        q = np.array([Rc, 1j * Rc, -1j * Pc, Pc], dtype=complex)
    q.setflags(write=False)
    return q


def _roots(K: np.ndarray, B: np.ndarray) -> tuple[list[tuple[float, np.ndarray]], int]:
    """Positive real Omega^2 roots of K Q = Omega^2 B Q as (Omega, Q), and how many of the
    eigenvalues were not real."""
    nu, V = np.linalg.eig(np.linalg.solve(K.astype(complex), B.astype(complex)))
    out, n_complex = [], 0
    for k in range(len(nu)):
        v = complex(nu[k])
        if abs(v.imag) > REAL_RTOL * abs(v):
            n_complex += 1
            continue
        if v.real > 0.0:
            out.append((1.0 / math.sqrt(v.real), V[:, k]))
    return out, n_complex


def critical_speeds(rotor: Rotor, orders: tuple[int, ...] = (1,)) -> tuple[list[CriticalSpeed], list[Missing]]:
    """The undamped critical speeds of ``orders`` (ascending per order), and the branches
    that never meet their line.

    Parameters
    ----------
    rotor : Rotor — its dampers are ignored here
    orders : tuple of int — n >= 1

    Returns
    -------
    (list of CriticalSpeed sorted by speed, list of Missing)
    """
    out: list[CriticalSpeed] = []
    missing: list[Missing] = []
    m, It, Ip = rotor.mass, rotor.It, rotor.Ip
    for n in orders:
        if rotor.isotropic:
            _, Kc, _ = rotor.complex_matrices()
            for whirl, tilt in (("forward", n * n * It - n * Ip), ("backward", n * n * It + n * Ip)):
                B = np.diag([n * n * m, tilt]).astype(complex)
                roots, n_complex = _roots(Kc, B)
                for Om, U in roots:
                    fw = whirl == "forward"
                    shape = shape_of_complex(rotor, U, fw)
                    vec = _weighted(rotor, U[0], U[1], 0, 0) if fw else _weighted(rotor, 0, 0, U[0], U[1])
                    out.append(CriticalSpeed(Om, n, shape, vec, _real_of(U, fw)))
                if whirl == "forward" and tilt <= 0.0:
                    missing.append(Missing(n, "forward", "conical",
                                           "coincident" if tilt == 0.0 else "gyroscopic", It, Ip))
                elif n_complex:
                    missing.append(Missing(n, whirl, "mode", "complex", It, Ip))
        else:
            B = n * n * rotor.M() - 1j * n * rotor.G()
            roots, n_complex = _roots(rotor.K(), B)
            for Om, Q in roots:
                X, Y, TX, TY = (complex(v) for v in Q)
                shape = shape_of_real(rotor, Q)
                vec = _weighted(rotor, X + 1j * Y, TY - 1j * TX, X - 1j * Y, TY + 1j * TX)
                q = np.array(Q, dtype=complex)
                q.setflags(write=False)
                out.append(CriticalSpeed(Om, n, shape, vec, q))
            if n * It <= Ip:
                missing.append(Missing(n, "forward", "conical",
                                       "coincident" if n * It == Ip else "gyroscopic", It, Ip))
            if n_complex:
                missing.append(Missing(n, "forward", "mode", "complex", It, Ip))
    out.sort(key=lambda c: (c.speed, c.order))
    return out, missing


def damped_crossing(rotor: Rotor, crit: CriticalSpeed) -> tuple[float, Mode] | None:
    """Where the damped whirl frequency of ``crit``'s mode equals ``order`` times the
    speed, and the mode there; None when no such speed lies within [crit/4, 4 crit]
    (a heavily damped mode).

    Without damping and cross-coupling it is ``crit.speed`` itself (exact). Otherwise the
    root of ``g(Omega) = |Im lambda(Omega)| - n Omega`` is bracketed by stepping out from
    the undamped speed (steps growing by 1.5 from 1e-3 of it) and solved by Brent's method
    to the last bits (xtol 1e-12 of the speed).
    """
    from rbcli.core.roots import brentq

    n = crit.order
    W0 = crit.speed
    plain = not rotor.damped and all(b.kxy == 0.0 and b.kyx == 0.0 for b in rotor.bearings)

    def mode(x: float) -> Mode:
        return follow(rotor, x, crit.vector, crit.whirl)

    if plain:
        return W0, mode(W0)

    def g(x: float) -> float:
        return mode(x).frequency - n * x

    g0 = g(W0)
    if g0 == 0.0:
        return W0, mode(W0)
    h = 1e-3 * W0
    while h <= 3.0 * W0:
        for x in (W0 - h, W0 + h):
            if not (0.25 * W0 <= x <= 4.0 * W0) or x <= 0.0:
                continue
            gx = g(x)
            if gx == 0.0:
                return x, mode(x)
            if (gx > 0.0) != (g0 > 0.0):
                lo, hi = (x, W0) if x < W0 else (W0, x)
                root = brentq(g, lo, hi, xtol=1e-12 * W0, rtol=4e-16)
                return root, mode(root)
        h *= 1.5
    return None
