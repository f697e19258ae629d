"""Bearing forces of a rotor at speed, static gravity loads and the torque ω × L (sheet §2.6)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rbcli.core.balance.common import STANDARD_GRAVITY, BalanceValueError, finite, pair, readonly
from rbcli.core.balance.frame import Unbalance, plane_unbalances


@dataclass(frozen=True, eq=False)
class BearingForces:
    """Rotating bearing forces, static gravity loads and the dynamic torque at a speed.

    Attributes
    ----------
    speed : float — rad/s (omega = speed e_z); bearings : (float, float) or None — m
    forces : (complex, complex) or () — N, on each bearing, rotor-fixed shaft frame
    plane_unbalances : (complex, complex) or () — kg m, F_i / Omega^2 (the ISO quantity)
    static_loads : (float, float) or () — N, gravity with the shaft horizontal (negative:
        hold-down)
    g : float — m/s^2; centrifugal_force : complex — N, Omega^2 U = F_1 + F_2
    angular_momentum, torque, torque_origin : (3,) ndarray — L = J_G omega (kg m^2/s) and
        omega x L about the com and about z = 0 (N m), shaft frame
    tol_force : float — N, for the angle flags; angle_sense : str"""

    speed: float
    bearings: tuple[float, float] | None
    forces: tuple[complex, ...]
    plane_unbalances: tuple[complex, ...]
    static_loads: tuple[float, ...]
    g: float
    centrifugal_force: complex
    angular_momentum: np.ndarray
    torque: np.ndarray
    torque_origin: np.ndarray
    tol_force: float
    angle_sense: str

def bearing_forces(
    unb: Unbalance,
    speed: float,
    bearings: object | None = None,
    *,
    g: float = STANDARD_GRAVITY,
) -> BearingForces:
    """Rotating bearing forces (rotor-fixed), static loads and the torque omega x L, at speed
    Omega (rad/s), with bearings (z_1, z_2) m and g (m/s^2): a :class:`BearingForces`.

    Sheet §2.6: ``F_1 = Omega^2 (z_2 U - P)/(z_2 - z_1)``, ``F_2 = Omega^2 (P - z_1 U)/(z_2 -
    z_1)``; ``W_1 = M g (z_2 - z_G)/(z_2 - z_1)``, ``W_2 = M g (z_G - z_1)/(z_2 - z_1)``;
    N_G = omega x (J_G omega); about z = 0, N_x + i N_y = -i Omega^2 P."""
    W = finite(speed, "speed")
    gg = finite(g, "g")
    U, P = unb.static, unb.moment
    om = np.array([0.0, 0.0, W])
    L = np.array(unb.inertia_shaft) @ om
    N = np.cross(om, L)
    NO = np.array([W * W * P.imag, -W * W * P.real, 0.0])
    forces: tuple[complex, ...] = ()
    pu: tuple[complex, ...] = ()
    loads: tuple[float, ...] = ()
    bz: tuple[float, float] | None = None
    tol = 0.0
    if bearings is not None:
        z1, z2 = pair(bearings, "bearings")
        if z1 == z2:
            raise BalanceValueError("bearings", "the two bearings must be at different positions along the shaft")
        u1, u2 = plane_unbalances(U, P, z1, z2)
        forces = (W * W * u1, W * W * u2)
        pu = (u1, u2)
        zg = float(unb.com_shaft[2])
        Mg = unb.mass * gg
        loads = (Mg * (z2 - zg) / (z2 - z1), Mg * (zg - z1) / (z2 - z1))
        bz = (z1, z2)
        tol = W * W * unb.plane_tolerance(z1, z2)
    return BearingForces(
        speed=W,
        bearings=bz,
        forces=forces,
        plane_unbalances=pu,
        static_loads=loads,
        g=gg,
        centrifugal_force=W * W * U,
        angular_momentum=readonly(L),
        torque=readonly(N),
        torque_origin=readonly(NO),
        tol_force=tol,
        angle_sense=unb.angle_sense,
    )
