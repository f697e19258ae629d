"""The rigid rotor on linear spring-damper bearings: its matrices and its mode shapes.

Coordinates (the physics sheet ``physics/whirl.md``, written out here). The shaft frame
is :mod:`rbcli.core.balance`'s: z along the shaft, x the 0° mark, y = z × x; the bearings
do not turn, and their x and y are the shaft frame's x and y with the rotor at angle 0.
The rotor spins at Omega about +z. Its small motion is

    q = [x, y, theta_x, theta_y]

x, y: the displacement of the shaft axis at the centre of mass (m); theta_x, theta_y:
its small rotations about x and y (rad), so that the axis at z (a = z - z_G from the com)
is displaced by ``d_x = x + a theta_y``, ``d_y = y - a theta_x`` and its direction is
(theta_y, -theta_x, 1). Bearing i at z_i (a_i = z_i - z_G) pushes back with
``F_i = -K_i d_i - C_i d_i'`` (K_i, C_i the 2×2 stiffness and damping, N/m and N s/m).
With ``T_i = [[1, 0, 0, a_i], [0, 1, -a_i, 0]]`` (d_i = T_i q) the equations of motion are

    M q'' + (C + Omega G) q' + K q = f,
    M = diag(m, m, It, It),  K = sum T_i^T K_i T_i,  C = sum T_i^T C_i T_i,
    G = Ip [[0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1], [0, 0, -1, 0]],

the last from the angular momentum about the com, L = (It theta_x' + Ip Omega theta_y,
It theta_y' - Ip Omega theta_x, Ip Omega) to first order (Euler's equations of a
symmetric rotor at constant spin; e.g. Friswell, Penny, Garvey and Lees, *Dynamics of
Rotating Machines*, Cambridge 2010, §3.5; Genta, *Dynamics of Rotating Systems*, §4).
Gravity is left out: it sets a static deflection, not the linear modes.

Complex (directional) coordinates, used for isotropic bearings: ``r = x + i y`` and
``phi = theta_y - i theta_x`` (the slope of the axis, so that the axis at a moves by
``r + a phi``). A bearing with K_i = [[k, q], [-q, k]] and C_i = [[c, p], [-p, c]] gives
``F = -(k - i q) d - (c - i p) d'`` and the four real equations become two complex ones,

    m r'' + sum (c_i - i p_i)(r' + a_i phi') + sum (k_i - i q_i)(r + a_i phi) = f_r,
    It phi'' - i Ip Omega phi' + sum a_i [(c_i - i p_i)(...)' + (k_i - i q_i)(...)] = f_phi,

whose solutions ``e^{lambda t}`` with Im lambda > 0 whirl forwards (the same sense as the
spin) and with Im lambda < 0 backwards. Undamped, ``lambda = i w``: the forward conical
root of ``It w^2 - Ip Omega w - sum k a^2 = 0`` rises with the speed, the backward one
(``-w``) falls: the sheet's closed forms.

Pure functions on SI floats and numpy arrays; no I/O, no units.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

#: a whirl whose forward share is within this of one half is a straight line ("linear")
LINEAR_TOL = 1e-9

__all__ = ["Bearing", "Rotor", "ModeShape", "mode_shape", "shape_of_real", "shape_of_complex"]


@dataclass(frozen=True)
class Bearing:
    """One linear bearing (spring and damper) at a station of the shaft.

    Attributes
    ----------
    z : float — m, position along the shaft (shaft frame)
    kxx, kyy : float — N/m, direct stiffness in x and y (> 0)
    kxy, kyx : float — N/m, cross-coupled stiffness: F_x = -(kxx d_x + kxy d_y),
        F_y = -(kyx d_x + kyy d_y)
    cxx, cyy : float — N s/m, direct damping (>= 0)
    """

    z: float
    kxx: float
    kyy: float
    kxy: float = 0.0
    kyx: float = 0.0
    cxx: float = 0.0
    cyy: float = 0.0

    @property
    def K(self) -> np.ndarray:
        """(2, 2) ndarray — N/m, the stiffness matrix."""
        return np.array([[self.kxx, self.kxy], [self.kyx, self.kyy]], dtype=float)

    @property
    def C(self) -> np.ndarray:
        """(2, 2) ndarray — N s/m, the damping matrix (diagonal)."""
        return np.array([[self.cxx, 0.0], [0.0, self.cyy]], dtype=float)

    @property
    def isotropic(self) -> bool:
        """The same in every direction across the shaft: kxx = kyy, kxy = -kyx, cxx = cyy
        (exactly: a bearing given per direction with equal values is isotropic)."""
        return self.kxx == self.kyy and self.kxy == -self.kyx and self.cxx == self.cyy


@dataclass(frozen=True)
class Rotor:
    """A rigid rotor on its bearings.

    Attributes
    ----------
    mass : float — kg
    It : float — kg m², moment across the shaft about the com (the mean of the two)
    Ip : float — kg m², polar moment about the shaft (through the com)
    z_com : float — m, the com's position along the shaft
    bearings : tuple of Bearing — two or more, at distinct positions
    """

    mass: float
    It: float
    Ip: float
    z_com: float
    bearings: tuple[Bearing, ...]

    # ------------------------------------------------------------------ the matrices

    @property
    def isotropic(self) -> bool:
        """Every bearing isotropic: the complex (directional) reduction applies."""
        return all(b.isotropic for b in self.bearings)

    @property
    def damped(self) -> bool:
        return any(b.cxx != 0.0 or b.cyy != 0.0 for b in self.bearings)

    def arms(self) -> np.ndarray:
        """(n,) ndarray — m, a_i = z_i - z_G."""
        return np.array([b.z - self.z_com for b in self.bearings], dtype=float)

    def M(self) -> np.ndarray:
        """(4, 4) ndarray — the mass matrix diag(m, m, It, It)."""
        return np.diag([self.mass, self.mass, self.It, self.It])

    def G(self) -> np.ndarray:
        """(4, 4) ndarray — the gyroscopic matrix per unit speed (kg m²): Omega G q'."""
        g = np.zeros((4, 4))
        g[2, 3] = self.Ip
        g[3, 2] = -self.Ip
        return g

    @staticmethod
    def _T(a: float) -> np.ndarray:
        return np.array([[1.0, 0.0, 0.0, a], [0.0, 1.0, -a, 0.0]])

    def K(self) -> np.ndarray:
        """(4, 4) ndarray — the stiffness matrix sum T_i^T K_i T_i."""
        out = np.zeros((4, 4))
        for b, a in zip(self.bearings, self.arms()):
            T = self._T(float(a))
            out += T.T @ b.K @ T
        return out

    def C(self) -> np.ndarray:
        """(4, 4) ndarray — the damping matrix sum T_i^T C_i T_i."""
        out = np.zeros((4, 4))
        for b, a in zip(self.bearings, self.arms()):
            T = self._T(float(a))
            out += T.T @ b.C @ T
        return out

    def complex_matrices(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(M_c, K_c, C_c), each (2, 2) complex, of the directional coordinates [r, phi]
        (isotropic bearings only; the gyroscopic term is ``-i Ip Omega`` on phi').

        Raises
        ------
        ValueError
            a bearing is not isotropic.
        """
        if not self.isotropic:
            raise ValueError("complex_matrices: the bearings are not isotropic")
        Kc = np.zeros((2, 2), dtype=complex)
        Cc = np.zeros((2, 2), dtype=complex)
        for b, a in zip(self.bearings, self.arms()):
            S = np.array([[1.0, a], [a, a * a]])
            Kc += complex(b.kxx, -b.kxy) * S
            Cc += complex(b.cxx, 0.0) * S
        return np.diag([self.mass, self.It]).astype(complex), Kc, Cc

    def undamped(self) -> "Rotor":
        """The same rotor with every damper removed."""
        return Rotor(self.mass, self.It, self.Ip, self.z_com,
                     tuple(Bearing(b.z, b.kxx, b.kyy, b.kxy, b.kyx) for b in self.bearings))

    def span(self) -> tuple[float, float]:
        """(z_min, z_max) — m, the outermost bearings."""
        zs = [b.z for b in self.bearings]
        return min(zs), max(zs)


# ---------------------------------------------------------------------- mode shapes


@dataclass(frozen=True)
class ModeShape:
    """What a mode looks like along the shaft.

    Attributes
    ----------
    whirl : str — "forward" (the same sense as the spin), "backward", "linear" (a
        straight-line orbit, forward and backward parts equal to :data:`LINEAR_TOL`: e.g.
        anisotropic bearings at rest) or "none" (a non-oscillating, overdamped motion)
    forward_share : float — the forward part of the mode's whirl, by kinetic weight
        ``(m |r_f|^2 + It |phi_f|^2) / (... forward + backward)``, 0..1 (1 for a forward
        circular whirl, 0.5 for motion in a line)
    kind : str — "cylindrical", "conical" or "mixed" (see :func:`mode_shape`)
    node : float | None — m, position along the shaft where the (dominant whirl
        component of the) motion is least; None for pure translation (node at infinity)
    bearing_ratio : float — the smaller over the larger motion at the outermost bearings
    in_phase : bool — the outermost bearings move in phase
    """

    whirl: str
    forward_share: float
    kind: str
    node: float | None
    bearing_ratio: float
    in_phase: bool


def mode_shape(rotor: Rotor, r_f: complex, phi_f: complex, r_b: complex, phi_b: complex,
               oscillating: bool = True) -> ModeShape:
    """Classify a mode from its forward and backward parts.

    Parameters
    ----------
    rotor : Rotor
    r_f, phi_f : complex — the forward circular part of the motion of the axis at the com
        (m) and of its slope (rad): the axis at a moves forward by ``r_f + a phi_f``
    r_b, phi_b : complex — the backward part, likewise
    oscillating : bool — False for a real eigenvalue (no whirl: "none")

    Returns
    -------
    ModeShape

    Notes
    -----
    The dominant part (forward or backward, by kinetic weight) is ``u(a) = r + a phi``
    along the shaft. Its node is where |u| is least, ``a* = -Re(r conj(phi)) / |phi|^2``
    (exact for a real ratio r/phi, the undamped isotropic case). The outermost bearings
    move by u_1 and u_2: the mode is *conical* when they move out of phase (Re(u_1
    conj(u_2)) < 0: a node between them), *cylindrical* when they move in phase with the
    smaller at least half the larger (a node farther than one bearing span outside them,
    or none), and *mixed* in between (in phase, one bearing moving less than half the
    other: a node just outside the bearings).
    """
    m, It = rotor.mass, rotor.It
    ef = m * abs(r_f) ** 2 + It * abs(phi_f) ** 2
    eb = m * abs(r_b) ** 2 + It * abs(phi_b) ** 2
    total = ef + eb
    share = ef / total if total > 0.0 else 0.5
    if not oscillating:
        whirl = "none"
    elif abs(share - 0.5) <= LINEAR_TOL:
        whirl = "linear"
    else:
        whirl = "forward" if ef >= eb else "backward"
    r, phi = (r_f, phi_f) if ef >= eb else (r_b, phi_b)
    z1, z2 = rotor.span()
    S = z2 - z1
    u1 = r + (z1 - rotor.z_com) * phi
    u2 = r + (z2 - rotor.z_com) * phi
    big = max(abs(u1), abs(u2))
    ratio = min(abs(u1), abs(u2)) / big if big > 0.0 else 1.0
    in_phase = (u1 * u2.conjugate()).real >= 0.0
    scale = max(abs(r), abs(phi) * S)
    if abs(phi) * S <= 1e-12 * scale or scale == 0.0:
        node = None
    else:
        node = rotor.z_com - (r * phi.conjugate()).real / abs(phi) ** 2
    if not in_phase:
        kind = "conical"
    elif ratio >= 0.5:
        kind = "cylindrical"
    else:
        kind = "mixed"
    return ModeShape(whirl, float(share), kind, None if node is None else float(node), float(ratio),
                     bool(in_phase))


def shape_of_real(rotor: Rotor, q: np.ndarray, oscillating: bool = True) -> ModeShape:
    """:func:`mode_shape` of a real-coordinate eigenvector ``q`` = [X, Y, TX, TY] (complex
    amplitudes of x, y, theta_x, theta_y in ``Re(q e^{i w t})``, w > 0).

    The motion x + i y = ½[(X + iY) e^{iwt} + conj(X - iY) e^{-iwt}]: forward part X + iY,
    backward X - iY; the slope phi = theta_y - i theta_x likewise: forward TY - i TX,
    backward TY + i TX (common factors ½ and conjugation do not change the shape)."""
    X, Y, TX, TY = (complex(v) for v in q)
    return mode_shape(rotor, X + 1j * Y, TY - 1j * TX, X - 1j * Y, TY + 1j * TX, oscillating)


def shape_of_complex(rotor: Rotor, u: np.ndarray, forward: bool, oscillating: bool = True) -> ModeShape:
    """:func:`mode_shape` of a directional eigenvector u = [R, PHI] (isotropic bearings):
    all forward (``forward``) or all backward."""
    R, P = complex(u[0]), complex(u[1])
    if forward:
        return mode_shape(rotor, R, P, 0.0, 0.0, oscillating)
    return mode_shape(rotor, 0.0, 0.0, R, P, oscillating)


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
