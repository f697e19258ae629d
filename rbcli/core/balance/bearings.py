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
    speed : float — rad/s, as given (omega = speed e_z)
    bearings : (float, float) | None — m, bearing positions along the shaft
    forces : (complex, complex) | () — N, force the rotor exerts on each bearing, rotor-fixed
        shaft frame ('with' sense)
    plane_unbalances : (complex, complex) | () — kg m, equivalent unbalance in each bearing
        plane, F_i / Omega^2 (the ISO tolerance quantity)
    static_loads : (float, float) | () — N, gravity loads (shaft horizontal), positive =
        the bearing carries the rotor's weight downward; negative = hold-down (overhung)
    g : float — m/s^2
    centrifugal_force : complex — N, total rotating force Omega^2 U (= F_1 + F_2)
    angular_momentum : (3,) ndarray — kg m^2/s, L = J_G omega about the com, shaft frame
    torque : (3,) ndarray — N m, omega x L about the com, shaft frame (rotor-fixed): the
        torque the supports must apply to keep the rotor turning about the shaft
    torque_origin : (3,) ndarray — N m, the same about the shaft point z = 0 (sheet §2.6 N_O)
    tol_force : float — N, tolerance used for the angle flags
    angle_sense : str
    """

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
    """Rotating bearing forces (rotor-fixed), static loads and the torque omega x L.

    Parameters
    ----------
    unb : Unbalance
    speed : float — rad/s, Omega (sign irrelevant for the forces; omega = Omega e_z)
    bearings : (z_1, z_2), optional — m, z_1 != z_2
    g : float — m/s^2, for the static loads

    Returns
    -------
    BearingForces

    Notes
    -----
    Sheet §2.6: ``F_1 = Omega^2 (z_2 U - P)/(z_2 - z_1)``,
    ``F_2 = Omega^2 (P - z_1 U)/(z_2 - z_1)``,
    the force each bearing receives from the rotor, fixed in the rotor frame (it turns with
    the rotor in the lab). Static loads by the lever rule on M g:
    ``W_1 = M g (z_2 - z_G)/(z_2 - z_1)``, ``W_2 = M g (z_G - z_1)/(z_2 - z_1)`` (shaft
    horizontal; W_i < 0 on the far bearing of an overhung rotor). Torque: L = J_G omega,
    N_G = omega x L about the com; about z = 0, N_O = omega x (J_O omega) =
    Omega^2 (D_yz, -D_xz, 0) with D about z = 0 (i.e. N_x + i N_y = -i Omega^2 P).
    """
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
