"""Rigid-rotor balancing about a shaft: unbalance, corrections, bearing loads, ISO 21940-11
(field balancing from vibration readings is :mod:`rbcli.core.field`).

Everything here follows the physics sheet ``physics/balance.md`` (cited as "sheet §n"),
one module per job:

=================  ==========================================================================
``common``         constants, checks (:class:`BalanceValueError` names its parameter), angles
``frame``          the shaft frame and the unbalance of a rotor about it (sheet §2.1-§2.4)
``corrections``    two-plane corrections, rounding, fixed positions, the residual (sheet §2.5)
``bearings``       bearing forces at speed, static loads, the torque ω × L (sheet §2.6)
``iso``            ISO 21940-11 permissible unbalance, allocation and verdict (sheet §1)
=================  ==========================================================================

Every public name is re-exported here (``from rbcli.core import balance as B;
B.unbalance(...)``). Results are frozen dataclasses of numbers; their JSON form is built by
the services layer (:mod:`rbcli.api.balance`), not here.

Frames and signs
----------------
The body is given by its mass properties in the BODY frame, SI: ``mass`` (kg), ``com``
(3,) m, ``inertia_com`` (3, 3) kg m^2 in the TENSOR convention (off-diagonals are
``-∫xy dm``, about the com).

A shaft is an axis direction (any non-zero length) through a point ``through``. Positions
along the shaft (correction planes, bearings) are signed distances ``z`` along the unit axis
measured from ``through``. The SHAFT FRAME (see :func:`shaft_frame`) has ``e_z`` along the
shaft, ``e_x`` the reference mark ("0 degrees") and ``e_y = e_z x e_x``. Angles are measured
about +e_z from +e_x towards +e_y, which is the direction of rotation for a positive speed
(SPEC §2, sheet §2.1). For the default shaft (body z through the origin) the shaft frame is
the body frame. ``angle_sense="against"`` reports every angle as ``360 - angle`` (shops that
count against rotation); all complex quantities stored in result objects stay in the
"with rotation" sense, only the ``*_deg`` numbers are flipped.

Complex notation in the plane at right angles to the shaft: ``w = x + i y`` (sheet §2.1).
The PRODUCT ``D_xz = +∫xz dm`` is the negative of the TENSOR element ``J_xz``; the two are
kept apart by name (sheet §2.1, §7.1):

* static unbalance      ``U = M (x_G + i y_G)``                                  kg m
* moment unbalance      ``P = M z_G (x_G + i y_G) + (D_xz,G + i D_yz,G)``        kg m^2, about z = 0
* couple unbalance      ``P_G = P - z_G U = D_xz,G + i D_yz,G = -(J_xz,G + i J_yz,G)``
  (about the com)

A correction ``C`` is the unbalance (kg m) to ADD in a plane: a mass ``|C|/r`` at angle
``arg C`` (remove the same mass at ``arg C + 180 deg``).
"""

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
