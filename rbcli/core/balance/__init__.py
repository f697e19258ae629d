"""Rigid-rotor balancing about a shaft: unbalance, corrections, bearing loads, ISO 21940-11
(field balancing from vibration readings is :mod:`rbcli.core.field`).

Follows the physics sheet ``physics/balance.md`` ("sheet §n"); every public name of
``common`` (constants, checks, angles), ``frame`` (the shaft frame and the unbalance, §2.1-
§2.4), ``corrections`` (two-plane corrections, rounding, positions, §2.5), ``bearings``
(bearing forces, static loads, torque, §2.6) and ``iso`` (ISO 21940-11, §1) is re-exported.

Frames and signs
----------------
Mass properties in the BODY frame, SI; ``inertia_com`` in the TENSOR convention (about the
com). Positions along the shaft are signed distances ``z`` from ``through``; the SHAFT
FRAME (:func:`shaft_frame`) has ``e_z`` along the shaft, ``e_x`` the 0° mark and
``e_y = e_z x e_x``; angles run about +e_z from +e_x, the direction of rotation (SPEC §2).
``angle_sense="against"`` reports ``360 - angle`` in the ``*_deg`` numbers only. With
``w = x + i y`` and the PRODUCT ``D_xz = +∫xz dm = -J_xz`` (sheet §2.1, §7.1):

* static unbalance      ``U = M (x_G + i y_G)``                                  kg m
* moment unbalance      ``P = M z_G (x_G + i y_G) + (D_xz,G + i D_yz,G)``        kg m^2, about z = 0
* couple unbalance      ``P_G = P - z_G U = D_xz,G + i D_yz,G``                  about the com

A correction ``C`` (kg m) is the unbalance to ADD in a plane: a mass ``|C|/r`` at ``arg C``."""

from __future__ import annotations

from rbcli.core.balance.bearings import BearingForces, bearing_forces
from rbcli.core.balance.common import (
    ANGLE_SENSES, BALANCE_RTOL, FIELD_COND_WARN, FRAME_SWITCH_COS, ISO_CLAMP, ISO_GRADE_MAX,
    ISO_GRADE_MIN, ISO_OUTBOARD_FLOOR, LARGE_CORRECTION_FRACTION, NARROW_PLANE_FRACTION,
    SMALL_RESPONSE_AMPLITUDE, SMALL_RESPONSE_PHASE_DEG, STANDARD_GRAVITY, TILT_GAP_RTOL,
    BalanceValueError, angle_of, phasor, wrap_deg,
)
from rbcli.core.balance.corrections import (
    Corrections, PlaneCorrection, PositionCorrections, Residual, Split, apply_corrections,
    correction_points, corrections, mass_at_radius, round_corrections, split_between,
    split_corrections, split_to_positions,
)
from rbcli.core.balance.frame import (
    ShaftFrame, Unbalance, add_point_masses, plane_unbalances, shaft_frame, unbalance,
)
from rbcli.core.balance.iso import (
    Allocation, IsoCheck, IsoState, achieved_grade, allocate_permissible, iso_check,
    permissible_unbalance,
)

__all__ = [
    "ANGLE_SENSES", "BALANCE_RTOL", "FIELD_COND_WARN", "FRAME_SWITCH_COS", "ISO_CLAMP",
    "ISO_GRADE_MAX", "ISO_GRADE_MIN", "ISO_OUTBOARD_FLOOR", "LARGE_CORRECTION_FRACTION",
    "NARROW_PLANE_FRACTION", "SMALL_RESPONSE_AMPLITUDE", "SMALL_RESPONSE_PHASE_DEG",
    "STANDARD_GRAVITY", "TILT_GAP_RTOL",
    "Allocation", "BalanceValueError", "BearingForces", "Corrections", "IsoCheck", "IsoState", "PlaneCorrection", "PositionCorrections",
    "Residual", "ShaftFrame", "Split", "Unbalance",
    "achieved_grade", "add_point_masses", "allocate_permissible", "angle_of",
    "apply_corrections", "bearing_forces", "correction_points", "corrections",
    "iso_check", "mass_at_radius", "permissible_unbalance",
    "phasor", "plane_unbalances", "round_corrections", "shaft_frame", "split_between",
    "split_corrections", "split_to_positions", "unbalance", "wrap_deg",
]
