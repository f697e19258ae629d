"""The parameters of every command, each declared once (:class:`rbcli.api.params.Param`).

A command's table gives its public function's signature, argument checks and docstring
parameters, its typer options and ``--help``, how each value is read, and the options echo
(:mod:`rbcli.api.params`). Adding an option: its declaration here, the physics that uses it
(its service in ``rbcli/api/<command>.py``), and a test. This module is light (no numpy): the
command line builds ``--help`` from it.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

from rbcli.api.params import SYMMETRY_TOL, Param, as_text
from rbcli.errors import literal

__all__ = ["BALANCE", "ROLLCHECK", "WHIRL"]

# ----------------------------------------------------------------------------- shared

#: the shaft's direction (balance, rollcheck; ``dataclasses.replace(SHAFT, help=...)`` to word it)
SHAFT = Param("shaft", "Shaft direction x,y,z (or x, y, z) in the body frame. Default: the body's "
              "shaft, else z.", "direction")
#: a point of the shaft's line
THROUGH = Param("through", "A point of the shaft (z = 0 there): com, origin or x,y,z (a bare number "
                "in the body's length unit, m by default; a unit after the last number applies to "
                "all). Default: the body's shaft point, else the origin.", "point")
#: gravity (None: standard gravity, 9.80665 m/s^2)
G = Param("g", "Gravity (m/s^2, or with units). Default: 9.80665.", "quantity", "acceleration")


def _given(given: Any) -> str:
    """A value as the caller gave it, inside a message."""
    return literal(as_text(given))


def _distinct(what: str):
    """The check of two positions along the shaft that must differ."""
    def valid(v: tuple[float, float], given: Any) -> str | None:
        return None if v[0] != v[1] else f"the two {what} are both at z = {v[0]:.6g} m; they must differ"
    return valid

# ----------------------------------------------------------------------------- inertia, principal

# ----------------------------------------------------------------------------- balance

_BARE_LENGTH = "a bare number in the body's length unit, m by default"

#: :func:`rbcli.balance` and ``rbcli balance``
BALANCE = (
    SHAFT,
    THROUGH,
    Param("mark", "Direction x,y,z (body frame) of the 0° reference mark; only its part at right "
          "angles to the shaft counts. Default: body x projected (body y for a shaft near body x).",
          "vector", "dimensionless", echo="direction"),
    Param("zero_mark_deg", "Turn the 0° mark this far about the shaft, in the direction of rotation "
          "(degrees, or with units, e.g. '0.5 rad'). Default: 0.", "degrees",
          valid=lambda v, _: None if math.isfinite(v) else "must be a finite angle"),
    Param("angle_sense", "Count angles with the rotation (with) or against it (against).", "choice",
          choices=("with", "against"), default="with"),
    Param("planes", f"Correction planes zA,zB along the shaft ({_BARE_LENGTH}; a unit after the last "
          "number applies to both, e.g. '-100,100 mm').", "values", "length", (2,),
          valid=_distinct("correction planes")),
    Param("radius", f"Correction radius r, or rA,rB per plane ({_BARE_LENGTH}; or with units as for "
          "{planes}). Default: the body's rim_radius.", "values", "length", (1, 2)),
    Param("mass_step", "Round correction masses to multiples of this (e.g. '1 g'; a bare number is in "
          "the body's mass unit, kg by default).", "quantity", "mass"),
    Param("angle_step", "Round correction angles to multiples of this (degrees, or with units).",
          "degrees", valid=lambda v, given: None if 0.0 < v <= 360.0 else
          f"must be more than 0 and at most 360 degrees, got {_given(given)}"),
    Param("positions", "N equally spaced fixed positions (holes, blades), position 1 on the 0° mark: "
          "split each correction onto the two neighbouring ones.", "count",
          valid=lambda n, _: None if n >= 3 else f"needs at least 3 equally spaced positions, got {n}"),
    Param("speed", "Rotor speed (rad/s, or the body's units' angular_speed; or e.g. '1500 rpm'); with "
          "{grade} the maximum service speed.", "quantity", "angular_speed"),
    Param("bearings", f"Bearing positions z1,z2 along the shaft ({_BARE_LENGTH}; a unit after the "
          "last number applies to both, e.g. '-50,150 mm').", "values", "length", (2,),
          valid=_distinct("bearings")),
    dataclasses.replace(G, help="Gravity for the static bearing loads (m/s^2, or with units). "
                        "Default: 9.80665 m/s^2."),
    Param("grade", "ISO 21940-11 balance quality grade, e.g. G6.3 (G0.4 to G4000); needs {speed} "
          "and {bearings}.", "grade"),
    Param("tolerance_planes", "Planes the permissible unbalance is allocated to: bearings (ISO "
          "21940-11, the default) or corrections (older practice).", "choice",
          choices=("bearings", "corrections")),
)

# ----------------------------------------------------------------------------- field-balance

# ----------------------------------------------------------------------------- precess

# ----------------------------------------------------------------------------- top, gyrocompass

# ----------------------------------------------------------------------------- rollcheck

#: :func:`rbcli.rollcheck` and ``rbcli rollcheck`` (its options ``--axle``, ``--radius`` and
#: ``--speed``: :data:`rbcli.errors.COMMAND_OPTIONS`)
ROLLCHECK = (
    dataclasses.replace(SHAFT, help="Axle direction x,y,z (or x, y, z) in the body frame. Default: "
                        "the body's shaft axis, else z."),
    dataclasses.replace(THROUGH, help="A point of the axle line: com, origin or x,y,z (a bare number "
                        "in the body's length unit, m by default; a unit after the last number "
                        "applies to all, e.g. '0,0,5 mm'). Default: the body's shaft point, else the "
                        "origin."),
    Param("rim_radius", "Rim radius a, centre to floor when upright (a bare number in the body's "
          "length unit, m by default; or with units). Default: the body's rim_radius, else the "
          "largest round part (ring, disk, cylinder, torus, ...) coaxial with the axle.",
          "quantity", "length"),
    Param("tyre_radius", "Tube radius r of a rounded rim, 0 <= r <= a (a bare number is in the body's "
          "length unit, else give one); 0 = knife edge, a = a sphere. Default: the rim's shape: a "
          "torus's tube radius, a sphere's radius, a flat band for a cylinder, else 0.", "quantity",
          "length", valid=lambda r, given: None if 0.0 <= r < math.inf else
          f"must be 0 (knife edge) or a positive length, got {_given(given)}"),
    dataclasses.replace(G, help="Gravity (m/s^2, or with units, e.g. '1 g0'). Default: 9.80665."),
    Param("rolling_speed", "Speed of the centre (a bare number is m/s, whatever the body's units: a "
          "body file has no speeds; or with a unit, e.g. '20 km/h', '10 mph'); negative = "
          "backwards.", "quantity", "speed", valid=lambda v, _: _finite(v)),
    Param("spin", "Spin about the axle (rad/s, or the body's units' angular_speed; or e.g. '300 "
          "rpm'); speed = a x spin.", "quantity", "angular_speed", valid=lambda v, _: _finite(v)),
    Param("lean", "Steady circle: inward lean from the vertical (degrees, or with units), 0 to <90.",
          "quantity", "angle", valid=lambda b, given: None if 0.0 <= b < 0.5 * math.pi else
          "the inward lean from the vertical must be from 0 up to (not including) 90 degrees, got "
          f"{_given(given)}"),
    Param("circle", "Steady circle: radius of the circle the centre runs on (a bare number in the "
          "body's length unit, m by default; or with units); 0 = spinning in place.", "quantity",
          "length", valid=lambda r, given: None if 0.0 <= r < math.inf else
          f"the circle radius must be 0 (spinning in place) or positive, got {_given(given)}"),
    dataclasses.replace(SYMMETRY_TOL, echo="-"),
)


def _finite(x: float) -> str | None:
    return None if math.isfinite(x) else "must be a finite number"

# ----------------------------------------------------------------------------- report

# ----------------------------------------------------------------------------- whirl

#: the default number of speeds of the Campbell diagram and the response
DEFAULT_POINTS = 201
#: the most speeds (a run stays well under a second at this size)
MAX_POINTS = 20001
#: the most bearings
MAX_BEARINGS = 20
#: the highest order asked for
MAX_ORDER = 10

def _range(v: tuple[float, float], given: Any) -> str | None:
    a, b = v
    text = literal(as_text(given))
    if a < 0.0:
        return f"speeds must not be negative, got '{text}' (to turn the other way, reverse {{shaft}})"
    if a == b:
        return (f"'{text}' is an empty range: both ends are {a:.6g} rad/s; give a,b with a < b "
                "(e.g. '0,3000 rpm')")
    if a > b:
        return (f"'{text}' is not a range: the first speed ({a:.6g} rad/s) is above the second "
                f"({b:.6g} rad/s); give a,b with a < b")
    return None


def _operating_speed(v: tuple[float, ...], given: Any) -> str | None:
    for x in v:
        if not x > 0.0:
            return (f"the operating speed must be positive, got {x:.6g} rad/s (to turn the other "
                    "way, reverse {shaft})")
    if len(v) == 2 and v[0] > v[1]:
        return f"give the operating range as min,max (the minimum first), got {literal(as_text(given))}"
    return None


_LIST = "one value for every bearing, or one per bearing, comma-separated"
_UP_TO = tuple(range(1, MAX_BEARINGS + 1))
_SPEED = "a bare number is rad/s, or the body's units' angular_speed"

#: :func:`rbcli.whirl` and ``rbcli whirl``
WHIRL = (
    Param("bearings", "Bearing positions z1,z2[,...] along the shaft, two or more at distinct "
          "places (a bare number in the body's length unit, m by default; a unit after the last "
          "number applies to all, e.g. '0,200 mm').", "values", "length", _UP_TO),
    Param("stiffness", f"Bearing stiffness (N/m, or with units, e.g. '200 N/mm'), {_LIST}; the x "
          "stiffness when {stiffness_y} is given, else both directions.", "values", "stiffness",
          _UP_TO, echo="each:N/m"),
    Param("stiffness_y", f"Bearing stiffness in y (a bare number is N/m; or with units), {_LIST}: "
          "anisotropic bearings.", "values", "stiffness", _UP_TO, echo="each:N/m"),
    Param("cross_stiffness", f"Cross-coupled stiffness kxy = -kyx (a bare number is N/m; or with "
          f"units), {_LIST}: the destabilising follower force of fluid films and seals.", "values",
          "stiffness", _UP_TO, echo="each:N/m (kyx = -kxy)"),
    Param("damping", f"Bearing damping (N s/m, or with units, e.g. '2 N*s/mm'), {_LIST}; the x "
          "damping when {damping_y} is given. Default: none.", "values", "damping", _UP_TO,
          echo="each:N s/m"),
    Param("damping_y", f"Bearing damping in y (a bare number is N s/m; or with units), {_LIST}.",
          "values", "damping", _UP_TO, echo="each:N s/m"),
    Param("speed_range", f"Speeds a,b of the Campbell diagram and the response, 0 <= a < b ({_SPEED}"
          "; or e.g. '0,6000 rpm'). Default: 0 to 1.25 times the highest critical speed or "
          "operating speed.", "values", "angular_speed", (2,), valid=_range, echo_default=True),
    Param("points", f"Speeds in the range (3 to {MAX_POINTS}). Default: {DEFAULT_POINTS} (the "
          "operating speeds are added).", "count"),
    Param("orders", "Orders n of the critical speeds, where a whirl frequency is n times the speed: "
          "1, or e.g. 1,2. Default: 1.", "ints", counts=(10 * MAX_ORDER,), echo="list:× speed"),
    Param("speed", f"The operating speed, or min,max of the operating range ({_SPEED}; or e.g. "
          "'1480 rpm'): separation margins (API 617 / 684) and stability there.", "values",
          "angular_speed", (1, 2), valid=_operating_speed),
    Param("unbalance", "Unbalances amount@angle, one per plane of {unbalance_planes} (kg m unless "
          "a unit is given, e.g. '50 g*mm@0,30 g*mm@90'; angles in degrees from the 0° mark in "
          "the direction of rotation). Default: the body's own static and couple unbalance.",
          "texts", counts=(MAX_BEARINGS,), echo="unbalance"),
    Param("unbalance_planes", "Positions z1,z2[,...] along the shaft of the {unbalance} amounts "
          "(as {bearings}).", "values", "length", _UP_TO),
    Param("shaft", "Shaft direction x,y,z (or x, y, z) in the body frame. Default: the body's "
          "shaft, else z.", "direction"),
    Param("through", "A point of the shaft (z = 0 there): com, origin or x,y,z (a bare number in "
          "the body's length unit). Default: the body's shaft point, else the origin.", "point"),
    SYMMETRY_TOL,
)


