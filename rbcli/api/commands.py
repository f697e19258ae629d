"""The parameters of every command, each declared once (:class:`rbcli.api.params.Param`).

A command's table gives its public function's signature, argument checks and docstring
parameters, its typer options and ``--help``, how each value is read, and the options echo
(:mod:`rbcli.api.params`). Adding an option: its declaration here, the physics that uses it
(its service in ``rbcli/api/<command>.py``), and a test. This module is light (no numpy): the
command line builds ``--help`` from it.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

from rbcli.api.params import SYMMETRY_TOL, Param, as_text
from rbcli.errors import literal

__all__ = ["INERTIA", "PRINCIPAL", "PRECESS", "TOP", "GYROCOMPASS", "WHIRL"]


# ----------------------------------------------------------------------------- inertia, principal

_ABOUT = Param("about", "Point: com, origin or x,y,z (a bare number in the body's length unit, m by "
               "default; a unit after the last number applies to all, e.g. '10,0,5 mm').", "point")

#: :func:`rbcli.inertia` and ``rbcli inertia``
INERTIA = (
    _ABOUT,
    Param("axis", "Moment about this direction x,y,z through the point.", "direction"),
    Param("omega", "Angular velocity x,y,z (rad/s, or the body's units' angular_speed; a unit after "
          "the last number applies to all, e.g. '0,0,300 rpm').", "vector", "angular_speed"),
)

#: :func:`rbcli.principal` and ``rbcli principal``: about the com unless told
PRINCIPAL = (replace(_ABOUT, default="com"),)

# ----------------------------------------------------------------------------- balance

# ----------------------------------------------------------------------------- field-balance

# ----------------------------------------------------------------------------- precess

def _finite(v: float, given: Any) -> str | None:
    return None if math.isfinite(v) else "must be a finite number"


#: the most rows of a time series (precess and top --csv): 10^6 rows is ~100 MB of CSV,
#: about what a spreadsheet holds (1 048 576 rows)
MAX_SAMPLES = 1_000_000


def _rows(v: Any, given: Any) -> str | None:
    try:
        n = int(v)
    except ValueError:
        n = 0
    if 2 <= n <= MAX_SAMPLES:
        return None
    return f"must be from 2 to {MAX_SAMPLES} rows (a whole number), got '{literal(as_text(given))}'"


def _time_span(v: float, given: Any) -> str | None:
    if not math.isfinite(v):
        return "must be a finite number"
    return None if v > 0.0 else f"must be a positive time, got '{literal(as_text(given))}'"


#: rows of precess's time series when ``samples`` is not given
PRECESS_SAMPLES = 1001

#: :func:`rbcli.precess` and ``rbcli precess``
PRECESS = (
    Param("omega", "Initial angular velocity x,y,z in the body frame (a bare number is rad/s, or the "
          "body's units' angular_speed; a unit after the last number applies to every bare number "
          "before it, e.g. '0,0,300 rpm'). Required.", "vector", "angular_speed"),
    Param("at", "Also give w, L and the orientation (quaternion, axis and angle) at this time (a bare "
          "number is s; or with units, e.g. '7320 h'; negative = before t = 0).", "quantity", "time",
          valid=_finite),
    Param("duration", "Span of the {csv} time series, from t = 0 (a bare number is s; or with units); "
          "also the span of {plot} (default: 3 periods of w).", "quantity", "time", valid=_time_span),
    Param("samples", "Rows of the {csv} time series, evenly spaced from t = 0 to {duration} inclusive "
          f"(2 to {MAX_SAMPLES}, about 100 MB of CSV). Default {PRECESS_SAMPLES}.", "count",
          valid=_rows, echo="-", cli_type=str),
    Param("csv", "Write the time series t, wx, wy, wz, Lx, Ly, Lz (body frame), qw, qx, qy, qz (body "
          "to space) to this CSV file, or '-' for standard output instead of the tables. Needs "
          "{duration}. An existing file is replaced (atomically); an input file never.", "path",
          api=False),
    Param("plot", "Save a figure (.png, .svg, .pdf): the body-frame components of w against time and "
          "the polhode (the path of L/|L| on the unit sphere, principal frame) in two views. An "
          "existing figure is replaced (atomically); an input file never.", "path", api=False),
    Param("verify", "Check the exact motion against a numerical integration of Euler's equations and "
          "the attitude (scipy DOP853, rtol 1e-12) over 3 periods; exit status 1 if they differ by "
          "more than 1e-8.", "flag", echo="-", default=False),
)

# ----------------------------------------------------------------------------- top, gyrocompass

#: rows of top's time series when ``samples`` is not given
TOP_SAMPLES = 600


def _positive(why: str) -> Any:
    """The check of a positive finite number: ``<why>, got <the value as given>``."""
    def check(v: float, given: Any) -> str | None:
        if not math.isfinite(v):
            return "must be a finite number"
        return None if v > 0.0 else f"{why}, got {literal(as_text(given))}"
    return check


def _spin(what: str, eg: str, zero: str) -> Param:
    """The spin of top and gyrocompass (its help and its refusal of 0 differ)."""
    def valid(v: float, given: Any) -> str | None:
        return _finite(v, given) or (f"must not be 0: {zero}" if v == 0.0 else None)

    return Param("spin", f"Required. {what} (rad/s, or the body's units' angular_speed; or e.g. "
                 f"'{eg}'); negative = the other way.", "quantity", "angular_speed", valid=valid)


def _tilt(v: float, given: Any) -> str | None:
    if not math.isfinite(v):
        return "must be a finite number"
    if 0.0 < v < math.pi:
        return None
    return (f"the start tilt must be strictly between 0 and 180 degrees, got {literal(as_text(given))} "
            "(at 0 or 180 the axis is vertical and the precession angle is undefined; start it "
            "slightly tilted, e.g. {theta} 0.1)")


def _latitude(v: float, given: Any) -> str | None:
    if not math.isfinite(v):
        return "must be a finite number"
    if abs(v) <= 0.5 * math.pi * (1.0 + 1e-12):
        return None
    return f"must be from -90 to 90 degrees, got {literal(as_text(given))}"


_NO_SYMMETRY_ECHO = replace(SYMMETRY_TOL, echo="-")

#: :func:`rbcli.top` and ``rbcli top``
TOP = (
    Param("pivot", "The fixed point: com, origin or x,y,z (a bare number in the body's length unit, m "
          "by default; a unit after the last number applies to all, e.g. '0,0,-20 mm'). Default: the "
          "body's pivot, else the origin.", "point"),
    _spin("Spin S = w3 about the symmetry axis", "3000 rpm",
          "a top without spin is a spherical pendulum (it cannot stand); give the spin w3, e.g. "
          "{spin} 150 or {spin} '3000 rpm'"),
    Param("theta", "Required. Start tilt of the axis from the upward vertical, strictly between 0 and "
          "180 (degrees, or with units, e.g. '0.5 rad').", "quantity", "angle", valid=_tilt),
    Param("theta_dot", "Start rate theta' (rad/s unless the body's units name an angular_speed; or "
          "e.g. '10 deg/s'); positive = tilting further. Default: 0.", "quantity", "angular_speed",
          valid=_finite),
    Param("phi_dot", "Start precession rate phi' about the vertical (rad/s unless the body's units "
          "name an angular_speed; or with units). Default: 0.", "quantity", "angular_speed",
          valid=_finite),
    Param("g", "Gravity (m/s^2, or with units). Default: 9.80665.", "quantity", "acceleration",
          valid=_positive("gravity must be positive (it points down, towards -z)")),
    Param("verify", "Integrate the equations of motion numerically (no Euler angles, DOP853, rtol "
          "1e-12) over 3 nutation periods and compare with the closed form; exit 1 if they differ "
          "by more than 1e-6 rad or the energy drifts by more than 1e-9.", "flag", echo="-",
          default=False),
    Param("plot", "Save a figure (.png, .svg, .pdf): the path of the axis tip, theta against phi and "
          "seen from above, theta1 and theta2 marked, over {duration}. An existing figure is "
          "replaced (atomically); an input file never.", "path", api=False),
    Param("csv", "Write t, theta_deg, phi_deg, psi_deg (s, degrees) at {samples} times over "
          "{duration} to this file ('-' = standard output, instead of the tables). An existing file "
          "is replaced (atomically); an input file never.", "path", api=False),
    Param("duration", "Time span of {csv} and {plot} (s, or with units). Default: 3 nutation "
          "periods.", "quantity", "time", valid=_time_span, echo="-"),
    Param("samples", f"Rows of {{csv}}, evenly spaced from t = 0 to {{duration}} inclusive (2 to "
          f"{MAX_SAMPLES}).", "count", valid=_rows, echo="-", default=TOP_SAMPLES),
    _NO_SYMMETRY_ECHO,
)

#: :func:`rbcli.gyrocompass` and ``rbcli gyrocompass``
GYROCOMPASS = (
    Param("ratio", "C/A, the axial moment over the moment about the vertical (a flat disk: 2), "
          "instead of a body.", "quantity", "dimensionless", valid=_positive("C/A must be positive"),
          echo="=C/A"),
    Param("shaft", "The rotor's spin axis x,y,z (or x, y, z) in the body frame. Default: the body's "
          "shaft axis, else z.", "direction"),
    _spin("Rotor spin about its axis", "6000 rpm", "a gyrocompass needs a spinning rotor"),
    Param("latitude", "Required. Latitude, -90 to 90 (degrees, or with units); negative = south.",
          "quantity", "angle", valid=_latitude),
    Param("earth_rate", "The Earth's (sidereal) rotation rate (rad/s, or with units). Default: "
          "7.2921150e-5.", "quantity", "angular_speed", valid=_positive("must be positive")),
    _NO_SYMMETRY_ECHO,
)

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


