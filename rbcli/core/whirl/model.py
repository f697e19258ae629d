"""The rigid rotor on linear bearings: its matrices and its mode shapes.

Coordinates (physics sheet ``whirl.md``): the shaft frame of :mod:`rbcli.core.balance` (z
along the shaft, x the 0° mark), the rotor spinning at Omega about +z, small motion
``q = [x, y, theta_x, theta_y]`` of the shaft axis at the com (m, rad); the axis at
a = z - z_G moves by ``d = T q``, ``T = [[1, 0, 0, a], [0, 1, -a, 0]]``. Bearing i pushes
back with ``F_i = -K_i d_i - C_i d_i'`` (2x2, N/m and N s/m, constant or tabled against
speed: :class:`BearingTable`), so

    M q'' + (C + Omega G) q' + K q = f,
    M = diag(m, m, It, It),  K = sum T_i^T K_i T_i,  C = sum T_i^T C_i T_i,
    G = Ip [[0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1], [0, 0, -1, 0]]

(Friswell, Penny, Garvey and Lees, *Dynamics of Rotating Machines*, 2010, §3.5). Gravity
sets a static deflection, not the linear modes. For isotropic bearings ``r = x + i y``,
``phi = theta_y - i theta_x`` give two complex equations whose roots with Im lambda > 0
whirl forwards (with the spin)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

#: a whirl whose forward share is within this of one half is a straight line ("linear")
LINEAR_TOL = 1e-9
#: the eight coefficients of a bearing, in the order bearing programs print them
COEFFICIENTS = ("kxx", "kxy", "kyx", "kyy", "cxx", "cxy", "cyx", "cyy")
WHIRLS = ("backward", "linear", "none", "forward")  # codes 0..3: the order ties are listed in
KINDS = ("cylindrical", "conical", "mixed")

__all__ = ["Bearing", "BearingTable", "Rotor", "ModeShape", "shapes", "shape_of", "real_parts",
           "weighted", "cabs", "COEFFICIENTS", "WHIRLS", "KINDS", "damping_ratio", "log_decrement"]


@dataclass(frozen=True, eq=False)
class Bearing:
    """One linear bearing (spring and damper) at a station of the shaft.

    Attributes
    ----------
    z : float — m, position along the shaft (shaft frame)
    kxx, kyy, kxy, kyx : float — N/m: F_x = -(kxx d_x + kxy d_y), F_y = -(kyx d_x + kyy d_y)
    cxx, cyy, cxy, cyx : float — N s/m, likewise on the velocities
    """

    z: float
    kxx: float
    kyy: float
    kxy: float = 0.0
    kyx: float = 0.0
    cxx: float = 0.0
    cyy: float = 0.0
    cxy: float = 0.0
    cyx: float = 0.0

    @cached_property
    def values(self) -> np.ndarray:
        """(1, 8) ndarray — the coefficients in :data:`COEFFICIENTS` order."""
        return np.array([[getattr(self, k) for k in COEFFICIENTS]], dtype=float)

    def coefficients(self, speeds, slope: bool = False) -> np.ndarray:
        """(N, 8) ndarray — the coefficients at each of ``speeds`` (the same; with ``slope``
        their derivatives in the speed: 0)."""
        return np.repeat(0.0 * self.values if slope else self.values, np.size(speeds), axis=0)

    def at(self, speed: float) -> Bearing:
        return self


@dataclass(frozen=True, eq=False)
class BearingTable:
    """A bearing whose coefficients change with speed (an oil film, a seal), interpolated
    linearly between rows: ``z`` (m), ``speeds`` (S,) rad/s ascending (S >= 2), ``values``
    (S, 8) in :data:`COEFFICIENTS` order; the end rows hold outside (the service refuses such
    speeds)."""

    z: float
    speeds: np.ndarray
    values: np.ndarray

    def __post_init__(self) -> None:
        for name in ("speeds", "values"):
            a = np.array(getattr(self, name), dtype=float)
            a.setflags(write=False)
            object.__setattr__(self, name, a)

    def coefficients(self, speeds, slope: bool = False) -> np.ndarray:
        """(N, 8) ndarray — the coefficients at ``speeds`` (rad/s), linear between rows (with
        ``slope``: their derivatives in the speed, the slope of the row pair; 0 outside)."""
        x = np.atleast_1d(np.asarray(speeds, dtype=float))
        j = np.clip(np.searchsorted(self.speeds, x, side="right") - 1, 0, len(self.speeds) - 2)
        x0, x1 = self.speeds[j], self.speeds[j + 1]
        if slope:
            inside = ((x >= self.speeds[0]) & (x <= self.speeds[-1]))[:, None]
            return np.where(inside, (self.values[j + 1] - self.values[j]) / (x1 - x0)[:, None], 0.0)
        t = np.clip((x - x0) / (x1 - x0), 0.0, 1.0)[:, None]
        return (1.0 - t) * self.values[j] + t * self.values[j + 1]

    def at(self, speed: float) -> Bearing:
        """The bearing with the coefficients it has at ``speed``."""
        return Bearing(self.z, **{k: float(v) for k, v in zip(COEFFICIENTS, self.coefficients([speed])[0])})


def _is_isotropic(v: np.ndarray) -> bool:
    kxx, kxy, kyx, kyy, cxx, cxy, cyx, cyy = v.T
    return bool(np.all((kxx == kyy) & (kxy == -kyx) & (cxx == cyy) & (cxy == -cyx)))


@dataclass(frozen=True, eq=False)
class Rotor:
    """A rigid rotor on its bearings.

    Attributes
    ----------
    mass : float — kg
    It : float — kg m², moment across the shaft about the com (the mean of the two)
    Ip : float — kg m², polar moment about the shaft (through the com)
    z_com : float — m, the com's position along the shaft
    bearings : tuple of Bearing or BearingTable — two or more, at distinct positions
    """

    mass: float
    It: float
    Ip: float
    z_com: float
    bearings: tuple

    @cached_property
    def varying(self) -> bool:
        """A bearing's coefficients change with the speed."""
        return any(isinstance(b, BearingTable) for b in self.bearings)

    @cached_property
    def _rows(self) -> np.ndarray:
        return np.concatenate([b.values for b in self.bearings])

    @cached_property
    def isotropic(self) -> bool:
        """Every bearing isotropic at every speed: the directional reduction applies."""
        return _is_isotropic(self._rows)

    @cached_property
    def damped(self) -> bool:
        return bool(np.any(self._rows[:, 4:] != 0.0))

    @cached_property
    def conservative(self) -> bool:
        """No damping and symmetric stiffness (kxy = kyx): every root on the imaginary axis."""
        return not self.damped and bool(np.all(self._rows[:, 1] == self._rows[:, 2]))

    def speed_span(self) -> tuple[float, float]:
        """rad/s, the speeds every table covers ((0, inf) without tables)."""
        tables = [b.speeds for b in self.bearings if isinstance(b, BearingTable)]
        return (max((float(s[0]) for s in tables), default=0.0),
                min((float(s[-1]) for s in tables), default=math.inf))

    def at(self, speed: float) -> Rotor:
        """The rotor on the bearings as they are at ``speed`` (constant coefficients)."""
        return Rotor(self.mass, self.It, self.Ip, self.z_com, tuple(b.at(speed) for b in self.bearings))

    def undamped(self) -> Rotor:
        """The same rotor with every damper removed (stiffness tables kept)."""
        return self._with(lambda v: np.concatenate([v[:, :4], 0.0 * v[:, 4:]], axis=1))

    def conservative_part(self) -> Rotor:
        """The rotor without its dampers and without the follower (skew) part of its
        cross-coupled stiffness: kxy and kyx both their mean (API 684's undamped analysis
        takes the bearings' direct stiffness)."""
        def part(v: np.ndarray) -> np.ndarray:
            s = 0.5 * (v[:, 1] + v[:, 2])
            return np.column_stack([v[:, 0], s, s, v[:, 3], 0.0 * v[:, 4:]])
        return self._with(part)

    def _with(self, f) -> Rotor:
        """The rotor with every bearing's (S, 8) coefficients replaced by ``f`` of them."""
        out = []
        for b in self.bearings:
            v = f(b.values)
            out.append(BearingTable(b.z, b.speeds, v) if isinstance(b, BearingTable) else
                       Bearing(b.z, *(float(v[0, c]) for c in (0, 3, 1, 2, 4, 7, 5, 6))))
        return Rotor(self.mass, self.It, self.Ip, self.z_com, tuple(out))

    def arms(self) -> np.ndarray:
        """(n,) ndarray — m, a_i = z_i - z_G."""
        return np.array([b.z - self.z_com for b in self.bearings], dtype=float)

    def span(self) -> tuple[float, float]:
        """(z_min, z_max) — m, the outermost bearings."""
        zs = [b.z for b in self.bearings]
        return min(zs), max(zs)

    # --- the matrices

    def M(self) -> np.ndarray:
        """(4, 4) ndarray — the mass matrix diag(m, m, It, It)."""
        return np.diag([self.mass, self.mass, self.It, self.It])

    def G(self) -> np.ndarray:
        """(4, 4) ndarray — the gyroscopic matrix per unit speed (kg m²): Omega G q'."""
        g = np.zeros((4, 4))
        g[2, 3] = self.Ip
        g[3, 2] = -self.Ip
        return g

    def matrices(self, speeds, slope: bool = False) -> tuple[np.ndarray, np.ndarray]:
        """(K, C), each (N, 4, 4), at each of ``speeds``: sum T_i^T K_i T_i and likewise C
        (with ``slope``: their derivatives in the speed)."""
        n = np.size(speeds)
        K, C = np.zeros((n, 4, 4)), np.zeros((n, 4, 4))
        for b, a in zip(self.bearings, self.arms()):
            T = np.array([[1.0, 0.0, 0.0, a], [0.0, 1.0, -a, 0.0]])
            v = b.coefficients(speeds, slope).reshape(n, 2, 2, 2)  # (N, K/C, row, column)
            K += T.T @ v[:, 0] @ T
            C += T.T @ v[:, 1] @ T
        return K, C

    def K(self, speed: float = 0.0) -> np.ndarray:
        """(4, 4) ndarray — the stiffness matrix at ``speed``."""
        return self.matrices([speed])[0][0]

    def C(self, speed: float = 0.0) -> np.ndarray:
        """(4, 4) ndarray — the damping matrix at ``speed``."""
        return self.matrices([speed])[1][0]

    def complex_matrices(self, speeds) -> tuple[np.ndarray, np.ndarray]:
        """(K_c, C_c), each (N, 2, 2) complex, of the directional coordinates [r, phi] at
        ``speeds`` (isotropic bearings; the mass matrix is diag(m, It), the gyroscopic
        term ``-i Ip Omega`` on phi')."""
        n = np.size(speeds)
        Kc, Cc = np.zeros((n, 2, 2), dtype=complex), np.zeros((n, 2, 2), dtype=complex)
        for b, a in zip(self.bearings, self.arms()):
            S = np.array([[1.0, a], [a, a * a]])
            v = b.coefficients(speeds)
            Kc += (v[:, 0] - 1j * v[:, 1])[:, None, None] * S
            Cc += (v[:, 4] - 1j * v[:, 5])[:, None, None] * S
        return Kc, Cc


# --- mode shapes


@dataclass(frozen=True, eq=False)
class ModeShape:
    """What a mode looks like along the shaft: ``whirl`` ("forward", "backward", "linear" or
    "none"), ``forward_share`` (the forward part by kinetic weight, 0..1), ``kind``
    ("cylindrical", "conical", "mixed": :func:`shapes`) and ``node`` (m; None for pure
    translation)."""

    whirl: str
    forward_share: float
    kind: str
    node: float | None


def shapes(rotor: Rotor, parts: np.ndarray, oscillating: np.ndarray) -> dict[str, np.ndarray]:
    """Classify modes from their forward and backward parts.

    ``parts`` (..., 4) complex: ``[r_f, phi_f, r_b, phi_b]``, the forward and backward circular
    parts of the axis's motion at the com (m) and of its slope (rad); ``oscillating`` False
    for a real eigenvalue. Returns arrays ``share`` (forward share), ``whirl`` (index in
    :data:`WHIRLS`), ``kind`` (index in :data:`KINDS`), ``node`` (m, NaN for none).

    The dominant part u(a) = r + a phi has its node at ``a* = -Re(r conj(phi)) / |phi|^2``;
    the mode is *conical* when the outermost bearings move out of phase, *cylindrical* when in
    phase with the smaller at least half the larger, else *mixed*."""
    m, It = rotor.mass, rotor.It
    parts = _unit(parts)  # no underflow below in m |r|^2 and r conj(phi) (a tiny rotor's)
    ef = m * cabs(parts[..., 0]) ** 2 + It * cabs(parts[..., 1]) ** 2
    eb = m * cabs(parts[..., 2]) ** 2 + It * cabs(parts[..., 3]) ** 2
    total = ef + eb
    share = np.divide(ef, total, out=np.full(ef.shape, 0.5), where=total > 0.0)
    fwd = ef >= eb
    whirl = np.where(~oscillating, 2, np.where(np.abs(share - 0.5) <= LINEAR_TOL, 1, np.where(fwd, 3, 0)))
    r = np.where(fwd, parts[..., 0], parts[..., 2])
    phi = np.where(fwd, parts[..., 1], parts[..., 3])
    z1, z2 = rotor.span()
    u1, u2 = r + (z1 - rotor.z_com) * phi, r + (z2 - rotor.z_com) * phi
    big = np.maximum(cabs(u1), cabs(u2))
    ratio = np.divide(np.minimum(cabs(u1), cabs(u2)), big, out=np.ones(big.shape), where=big > 0.0)
    tilt = cabs(phi) * (z2 - z1)
    scale = np.maximum(cabs(r), tilt)
    none = (tilt <= 1e-12 * scale) | (scale == 0.0)
    node = np.where(none, np.nan, rotor.z_com - (r * np.conj(phi)).real
                    / np.where(none, 1.0, cabs(phi) ** 2))
    kind = np.where((u1 * np.conj(u2)).real < 0.0, 1, np.where(ratio >= 0.5, 0, 2))
    return {"share": share, "whirl": whirl, "kind": kind, "node": node}


def shape_of(rotor: Rotor, parts: np.ndarray, oscillating: bool = True) -> ModeShape:
    """:func:`shapes` of one mode's parts (4,), as a :class:`ModeShape`."""
    s = shapes(rotor, np.asarray(parts, dtype=complex), np.asarray(oscillating))
    node = float(s["node"])
    return ModeShape(WHIRLS[int(s["whirl"])], float(s["share"]), KINDS[int(s["kind"])],
                     None if math.isnan(node) else node)


def real_parts(q: np.ndarray) -> np.ndarray:
    """(..., 4) complex: the forward and backward parts (:func:`shapes`) of real-coordinate
    amplitudes q = [X, Y, TX, TY] (..., 4) in ``Re(q e^{i w t})``, w > 0.

    The motion x + i y = ½[(X + iY) e^{iwt} + conj(X - iY) e^{-iwt}]: forward part X + iY,
    backward X - iY; the slope phi = theta_y - i theta_x likewise: forward TY - i TX,
    backward TY + i TX (common factors ½ and conjugation do not change the shape)."""
    X, Y, TX, TY = (q[..., k] for k in range(4))
    return np.stack([X + 1j * Y, TY - 1j * TX, X - 1j * Y, TY + 1j * TX], axis=-1)


def weighted(rotor: Rotor, parts: np.ndarray) -> np.ndarray:
    """(..., 4) complex: the unit shape weighted for comparisons between modes of one rotor
    (MAC), ``[sqrt(m) r_f, sqrt(It) phi_f, sqrt(m) r_b, sqrt(It) phi_b]`` scaled to 1."""
    sm, si = math.sqrt(rotor.mass), math.sqrt(rotor.It)
    w = _unit(_unit(parts) * np.array([sm, si, sm, si]))  # a tiny rotor's does not underflow
    n = np.linalg.norm(w, axis=-1, keepdims=True)
    return w / np.where(n > 0.0, n, 1.0)


def _unit(a: np.ndarray) -> np.ndarray:
    """``a`` (..., 4) times the power of 2 (exact: no round-off) that brings its largest
    |entry| into [0.5, 1)."""
    e = np.frexp(np.max(cabs(a), axis=-1, keepdims=True))[1]
    return a * np.ldexp(1.0, -np.clip(e, -1000, 1000))


def cabs(z) -> np.ndarray:
    """|z| of complex ``z`` elementwise, as Python's ``abs`` gives it (hypot)."""
    z = np.asarray(z)
    return np.hypot(z.real, z.imag)


def log_decrement(lam: complex) -> float | None:
    """The logarithmic decrement -2 pi Re(lambda)/|Im(lambda)| (None when not oscillating).
    Positive decays, negative grows."""
    w = abs(lam.imag)
    if w == 0.0:
        return None
    return -2.0 * math.pi * lam.real / w


def damping_ratio(lam: complex) -> float:
    """-Re(lambda)/|lambda| (1 for a real decaying root; negative for a growing one)."""
    a = abs(lam)
    return -lam.real / a if a > 0.0 else 0.0
