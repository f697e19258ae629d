"""The numbers of a robot description's ``<inertial>`` element (URDF, SDF, MJCF).

Each states the mass, the com in the link frame (rbcli's body frame) and the tensor about
the com in an inertial frame: the body axes, or with ``principal=True`` the principal axes
(a diagonal tensor, ascending). The tensor is the tensor (``Jxy = −∫ x y dm``: URDF's and
SDF's ``ixy``, MJCF's ``fullinertia``); ``quat`` is (w, x, y, z), w ≥ 0; ``rpy`` is URDF's
fixed-axis ``R = Rz(yaw) Ry(pitch) Rx(roll)`` (http://wiki.ros.org/urdf/XML/link;
https://mujoco.readthedocs.io/en/stable/XMLreference.html#body-inertial)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rbcli.core.principal import principal_axes


@dataclass(frozen=True)
class Inertial:
    """An ``<inertial>`` element's numbers, SI: ``mass`` (kg), ``com`` (m, link frame),
    ``inertia`` (kg m², about the com in the inertial frame), ``rotation`` (columns: the
    inertial frame's axes), the same as ``quat_wxyz`` (w ≥ 0) and ``rpy`` (rad), ``principal``."""

    mass: float
    com: np.ndarray
    inertia: np.ndarray
    rotation: np.ndarray
    quat_wxyz: np.ndarray
    rpy: np.ndarray
    principal: bool


def inertial(mass: float, com: np.ndarray, inertia_com: np.ndarray, *, principal: bool = False) -> Inertial:
    """The ``<inertial>`` numbers of a body: in body axes, or (``principal``) in its principal
    axes (moments ascending, signs as :func:`rbcli.core.principal.principal_axes` chooses:
    the rotation nearest the body frame)."""
    J = np.asarray(inertia_com, dtype=float)
    if principal:
        pa = principal_axes(J)
        R = pa.axes.T.copy()
        J = np.diag(pa.moments)
    else:
        R = np.eye(3)
    return Inertial(float(mass), np.asarray(com, dtype=float).copy(), J.copy(), R,
                    quaternion_wxyz(R), roll_pitch_yaw(R), bool(principal))


def quaternion_wxyz(R: np.ndarray) -> np.ndarray:
    """The unit quaternion (w, x, y, z), w ≥ 0, of a proper rotation matrix (Shepperd's
    method: the largest of 4w², 4x², 4y², 4z² is taken first, so it is accurate at any
    angle)."""
    R = np.asarray(R, dtype=float)
    tr = float(np.trace(R))
    k = int(np.argmax([tr, R[0, 0], R[1, 1], R[2, 2]]))
    if k == 0:
        w = 0.5 * math.sqrt(max(1.0 + tr, 0.0))
        q = [w, (R[2, 1] - R[1, 2]) / (4 * w), (R[0, 2] - R[2, 0]) / (4 * w), (R[1, 0] - R[0, 1]) / (4 * w)]
    elif k == 1:
        x = 0.5 * math.sqrt(max(1.0 + 2 * R[0, 0] - tr, 0.0))
        q = [(R[2, 1] - R[1, 2]) / (4 * x), x, (R[0, 1] + R[1, 0]) / (4 * x), (R[0, 2] + R[2, 0]) / (4 * x)]
    elif k == 2:
        y = 0.5 * math.sqrt(max(1.0 + 2 * R[1, 1] - tr, 0.0))
        q = [(R[0, 2] - R[2, 0]) / (4 * y), (R[0, 1] + R[1, 0]) / (4 * y), y, (R[1, 2] + R[2, 1]) / (4 * y)]
    else:
        z = 0.5 * math.sqrt(max(1.0 + 2 * R[2, 2] - tr, 0.0))
        q = [(R[1, 0] - R[0, 1]) / (4 * z), (R[0, 2] + R[2, 0]) / (4 * z), (R[1, 2] + R[2, 1]) / (4 * z), z]
    out = np.array(q, dtype=float)
    out /= np.linalg.norm(out)
    if out[0] < 0:
        out = -out
    out[out == 0.0] = 0.0  # no negative zeros
    return out


def roll_pitch_yaw(R: np.ndarray) -> np.ndarray:
    """Fixed-axis roll, pitch, yaw (rad) with ``R = Rz(yaw) Ry(pitch) Rx(roll)``; pitch in
    [−π/2, π/2]. At pitch ±π/2 (gimbal lock) roll is taken as 0."""
    R = np.asarray(R, dtype=float)
    c = math.hypot(R[0, 0], R[1, 0])
    pitch = math.atan2(-R[2, 0], c)
    if c > 1e-12:
        roll = math.atan2(R[2, 1], R[2, 2])
        yaw = math.atan2(R[1, 0], R[0, 0])
    else:  # cos(pitch) = 0: only roll -/+ yaw is defined
        roll = 0.0
        yaw = math.atan2(-R[0, 1], R[1, 1])
    out = np.array([roll, pitch, yaw])
    out[out == 0.0] = 0.0
    return out
