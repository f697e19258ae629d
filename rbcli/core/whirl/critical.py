"""Critical speeds: where a whirl frequency equals an order n of the speed.

Undamped critical speeds are those of the conservative rotor (no dampers, kxy and kyx both
their mean: API 684's undamped analysis). On constant bearings exactly, an eigenproblem in
the speed: ``(K - Omega^2 (n^2 M - i n G)) Q = 0``, nu = 1/Omega^2 the eigenvalues of
``K^-1 (n^2 M - i n G)``; isotropic bearings split it by whirl direction (forward
``K_c U = Omega^2 diag(n^2 m, n^2 It - n Ip) U``, backward ``+ n Ip``), and when
``n It <= Ip`` the forward conical branch never meets the n× line (Sylvester's law of
inertia). On tabled bearings, and for the damped critical speeds (the rotor as it is), the
roots of ``|Im lambda(Omega)| - n Omega`` along a mode followed by its shape, by Brent's
method."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rbcli.core.roots import brentq
from rbcli.core.whirl.model import Bearing, ModeShape, Rotor, real_parts, shape_of, weighted
from rbcli.core.whirl.modes import Mode, branch_roots, campbell, follow, followed, track

__all__ = ["CriticalSpeed", "Missing", "critical_speeds", "damped_crossing", "critical_map"]

#: a generalized eigenvalue nu = 1/Omega^2 is real when |Im nu| <= this times |nu|
REAL_RTOL = 1e-9
#: speeds of the grid on which crossings are bracketed (the root solve is exact)
SEARCH_POINTS = 121


@dataclass(frozen=True, eq=False)
class CriticalSpeed:
    """An undamped critical speed: ``speed`` (rad/s), ``order`` n, ``shape`` (ModeShape),
    ``vector`` (as Mode.vector) and ``eigenvalue`` (the undamped lambda there, 1/s)."""

    speed: float
    order: int
    shape: ModeShape
    vector: np.ndarray
    eigenvalue: complex

    @property
    def whirl(self) -> str:
        return self.shape.whirl


@dataclass(frozen=True, eq=False)
class Missing:
    """A branch that never meets the n× line, and why: ``order``, ``whirl`` ("forward",
    "backward"), ``kind``, ``reason`` ("gyroscopic": n It < Ip, the forward conical whirl
    outruns the line; "coincident": n It = Ip; "range": no crossing between ``lo`` and ``hi``,
    rad/s), ``It``, ``Ip`` (kg m²)."""

    order: int
    whirl: str
    kind: str
    reason: str
    It: float
    Ip: float
    lo: float = 0.0
    hi: float = math.inf


def _roots(K: np.ndarray, B: np.ndarray) -> list[tuple[float, np.ndarray]]:
    """Positive real Omega^2 roots of K Q = Omega^2 B Q as (Omega, Q)."""
    nu, V = np.linalg.eig(np.linalg.solve(K.astype(complex), B.astype(complex)))
    return [(1.0 / math.sqrt(v.real), V[:, k]) for k, v in enumerate(nu.tolist())
            if abs(v.imag) <= REAL_RTOL * abs(v) and v.real > 0.0]


def _gyroscopic(n: int, It: float, Ip: float) -> str:
    return "coincident" if n * It == Ip else "gyroscopic"


def _exact(rotor: Rotor, orders: tuple[int, ...]) -> tuple[list[CriticalSpeed], list[Missing]]:
    """The eigenproblem in the speed (conservative rotor, constant bearings)."""
    out, missing = [], []
    m, It, Ip = rotor.mass, rotor.It, rotor.Ip
    for n in orders:
        if rotor.isotropic:
            Kc = rotor.complex_matrices([0.0])[0][0]
            for fw, tilt in ((True, n * n * It - n * Ip), (False, n * n * It + n * Ip)):
                for Om, U in _roots(Kc, np.diag([n * n * m, tilt])):
                    parts = np.array([U[0], U[1], 0, 0] if fw else [0, 0, U[0], U[1]], dtype=complex)
                    out.append(CriticalSpeed(Om, n, shape_of(rotor, parts), weighted(rotor, parts),
                                             complex(0.0, n * Om if fw else -n * Om)))
        else:
            for Om, Q in _roots(rotor.K(), n * n * rotor.M() - 1j * n * rotor.G()):
                parts = real_parts(np.asarray(Q, dtype=complex))
                out.append(CriticalSpeed(Om, n, shape_of(rotor, parts), weighted(rotor, parts),
                                         complex(0.0, n * Om)))
        if n * It <= Ip:
            missing.append(Missing(n, "forward", "conical", _gyroscopic(n, It, Ip), It, Ip))
    return out, missing


def _solved(rotor: Rotor, orders: tuple[int, ...], span: tuple[float, float]):
    """The crossings of the undamped modes followed by their shapes over ``span``."""
    cb = campbell(rotor, np.linspace(span[0], span[1], SEARCH_POINTS))
    ranks = track(cb)
    out, missing = [], []
    for n in orders:
        roots = branch_roots(cb, ranks, cb.frequency - n * cb.speeds[:, None],
                             lambda lam, x, n=n: abs(lam.imag) - n * x)
        for x, _, md, _ in roots:
            out.append(CriticalSpeed(x, n, md.shape, md.vector, md.eigenvalue))
        for k in sorted(set(range(4)) - {b for _, b, _, _ in roots}):
            md = cb.mode(-1, int(ranks[-1, k]))  # as the branch ends the search
            if md.whirl == "forward" and md.shape.kind == "conical" and n * rotor.It <= rotor.Ip:
                missing.append(Missing(n, "forward", "conical", _gyroscopic(n, rotor.It, rotor.Ip),
                                       rotor.It, rotor.Ip))
            elif md.whirl in ("forward", "backward"):
                missing.append(Missing(n, md.whirl, md.shape.kind, "range", rotor.It, rotor.Ip, *span))
    return out, missing


def critical_speeds(rotor: Rotor, orders: tuple[int, ...] = (1,)) -> tuple[list[CriticalSpeed], list[Missing]]:
    """The undamped critical speeds of ``orders`` (n >= 1) of the rotor's conservative part,
    sorted by speed, and the branches that never meet their line (``Missing``)."""
    r = rotor.conservative_part()
    out, missing = _solved(r, orders, r.speed_span()) if r.varying else _exact(r, orders)
    out.sort(key=lambda c: (c.speed, c.order))
    return out, missing


def damped_crossing(rotor: Rotor, crit: CriticalSpeed) -> tuple[float, Mode] | None:
    """Where the damped whirl frequency of ``crit``'s mode equals ``order`` times the
    speed, and the mode there (followed by its shape, and on isotropic bearings by its
    whirl); None when no such speed lies within [crit/4, 4 crit] (a heavily damped mode) or
    the bearing tables' speeds.

    Without damping and cross-coupling it is ``crit.speed`` itself; otherwise the root of
    ``g(Omega) = |Im lambda(Omega)| - n Omega`` bracketed from the undamped speed (Brent).
    """
    n, W0 = crit.order, crit.speed
    lo, hi = rotor.speed_span()

    whirl = crit.whirl if rotor.isotropic else None  # elliptic orbits: a label, not an identity

    def mode(x: float) -> Mode:
        return follow(rotor, x, crit.vector, whirl=whirl)

    if rotor.conservative:  # the undamped crossing itself
        return W0, mode(W0)

    def g(x: float) -> float:
        return abs(followed(rotor, [x], crit.vector, whirl=whirl, classify=False)[0][0].imag) - n * x

    g0 = g(W0)
    if g0 == 0.0:
        return W0, mode(W0)
    # steps out from W0, each side in turn, growing by 1.5 from 1e-3 of it: every trial speed
    # solved at once, the first whose sign differs from W0's brackets the root
    trials = []
    h = 1e-3 * W0
    while h <= 3.0 * W0:
        trials += [x for x in (W0 - h, W0 + h) if 0.25 * W0 <= x <= 4.0 * W0 and lo <= x <= hi and x > 0.0]
        h *= 1.5
    lam, _, _ = followed(rotor, trials, crit.vector, whirl=whirl, classify=False)
    for x, gx in zip(trials, np.abs(lam.imag) - n * np.array(trials)):
        if gx == 0.0:
            return x, mode(x)
        if (gx > 0.0) != (g0 > 0.0):
            root = brentq(g, min(x, W0), max(x, W0), xtol=1e-12 * W0, rtol=4e-16)
            return root, mode(root)
    return None


def critical_map(rotor: Rotor, stiffness) -> tuple[np.ndarray, list[tuple[str, str]]]:
    """The undamped critical speed map (API 684): the order-1 critical speeds with every bearing
    an isotropic spring k, for each k of ``stiffness`` (N/m, (K,)): ``(k S - Omega^2 B) U = 0``,
    ``S = sum [[1, a_i], [a_i, a_i^2]]``, so each is ``c sqrt(k)``. Returns ((K, B) rad/s, the
    B branches' (whirl, kind) by speed at k = 1)."""
    unit = Rotor(rotor.mass, rotor.It, rotor.Ip, rotor.z_com,
                 tuple(Bearing(b.z, 1.0, 1.0) for b in rotor.bearings))
    crits, _ = _exact(unit, (1,))
    crits.sort(key=lambda c: c.speed)
    k = np.sqrt(np.asarray(stiffness, dtype=float))
    return np.outer(k, [c.speed for c in crits]), [(c.whirl, c.shape.kind) for c in crits]
