"""The parameters of every command, each declared once (:class:`rbcli.api.params.Param`).

A command's table gives its public function's signature, argument checks and docstring
parameters, its typer options and ``--help``, how each value is read, and the options echo
(:mod:`rbcli.api.params`). Adding an option: its declaration here, the physics that uses it
(its service in ``rbcli/api/<command>.py``), and a test. This module is light (no numpy): the
command line builds ``--help`` from it.
"""

from __future__ import annotations

from typing import Any

from rbcli.api.params import SYMMETRY_TOL, Param, as_text
from rbcli.errors import literal

__all__ = ["WHIRL"]

# ----------------------------------------------------------------------------- inertia, principal

# ----------------------------------------------------------------------------- balance

# ----------------------------------------------------------------------------- field-balance

# ----------------------------------------------------------------------------- precess

# ----------------------------------------------------------------------------- top, gyrocompass

# ----------------------------------------------------------------------------- rollcheck

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


def _stiffness_range(v: tuple[float, float], given: Any) -> str | None:
    if not 0.0 < v[0] < v[1] or v[1] > 1e30:
        return (f"give kmin,kmax with 0 < kmin < kmax <= 1e30 N/m, got '{literal(as_text(given))}'")
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
    Param("stiffness_xy", f"Cross-coupled stiffness kxy alone (N/m; or with units), {_LIST}: with "
          "{stiffness_yx}, the full 2x2 stiffness of a fluid-film bearing.", "values", "stiffness",
          _UP_TO, echo="each:N/m"),
    Param("stiffness_yx", f"Cross-coupled stiffness kyx alone (N/m; or with units), {_LIST}.",
          "values", "stiffness", _UP_TO, echo="each:N/m"),
    Param("damping", f"Bearing damping (N s/m, or with units, e.g. '2 N*s/mm'), {_LIST}; the x "
          "damping when {damping_y} is given. Default: none.", "values", "damping", _UP_TO,
          echo="each:N s/m"),
    Param("damping_y", f"Bearing damping in y (a bare number is N s/m; or with units), {_LIST}.",
          "values", "damping", _UP_TO, echo="each:N s/m"),
    Param("damping_xy", f"Cross-coupled damping cxy (N s/m; or with units), {_LIST}.", "values",
          "damping", _UP_TO, echo="each:N s/m"),
    Param("damping_yx", f"Cross-coupled damping cyx (N s/m; or with units), {_LIST}.", "values",
          "damping", _UP_TO, echo="each:N s/m"),
    Param("speed_range", f"Speeds a,b of the Campbell diagram and the response, 0 <= a < b ({_SPEED}"
          "; or e.g. '0,6000 rpm'). Default: 0 to 1.25 times the highest critical speed or "
          "operating speed.", "values", "angular_speed", (2,), valid=_range, echo_default=True),
    Param("points", f"Speeds in the range (3 to {MAX_POINTS}). Default: {DEFAULT_POINTS} (the "
          "operating speeds are added).", "count"),
    Param("orders", "Orders n of the critical speeds, where a whirl frequency is n times the speed: "
          "1, or e.g. 1,2. Default: 1.", "ints", counts=(10 * MAX_ORDER,), echo="list:× speed"),
    Param("map_stiffness", "Stiffness kmin,kmax of the undamped critical speed map (N/m; or with "
          "units), 0 < kmin < kmax. Default: whole decades from a tenth of the softest bearing to "
          "ten times the stiffest.", "values", "stiffness", (2,), valid=_stiffness_range),
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


