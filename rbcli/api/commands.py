"""The parameters of every command, each declared once (:class:`rbcli.api.params.Param`).

A command's table gives its public function's signature, argument checks and docstring
parameters, its typer options and ``--help``, how each value is read, and the options echo
(:mod:`rbcli.api.params`). Adding an option: its declaration here, the physics that uses it
(its service in ``rbcli/api/<command>.py``), and a test. This module is light (no numpy): the
command line builds ``--help`` from it.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from rbcli.api.check import MAX_ITEMS
from rbcli.api.params import SYMMETRY_TOL, Param, as_text
from rbcli.errors import literal
from rbcli.io.field import CHOICES

__all__ = ["FIELD_BALANCE", "WHIRL"]

# ----------------------------------------------------------------------------- inertia, principal

# ----------------------------------------------------------------------------- balance

# ----------------------------------------------------------------------------- field-balance


def _positive(what: str, unit: str) -> Callable[[float, Any], str | None]:
    return lambda x, given: (None if x > 0.0 and math.isfinite(x) else
                             f"{what} must be a positive number, got {x:.6g} {unit}")


def _one_of(key: str) -> Callable[[str, Any], str | None]:
    allowed = CHOICES[key]
    ways = " or ".join(filter(None, (", ".join(allowed[:-1]), allowed[-1])))
    return lambda word, given: None if word in allowed else f"must be {ways}, not '{literal(word)}'"


def _angle_step(x: float, given: Any) -> str | None:
    return _positive("the angle step", "deg")(x, given) or (
        "must not exceed 360 degrees" if x > 360.0 else None)


def _positions(n: int, given: Any) -> str | None:
    return None if 3 <= n <= 100_000 else \
        f"must be a whole number from 3 to 100000 (holes or blades), not {literal(given)}"


def _group(g: Any, given: Any) -> str | None:
    return None if str(g).strip() in ("1", "2") else \
        f"must be 1 (large machines, above 300 kW) or 2 (15 kW to 300 kW), not '{literal(g)}'"


#: :func:`rbcli.field_balance` and ``rbcli field-balance`` (a job file's settings are the same
#: parameters: :func:`rbcli.api.field.job.from_file`)
FIELD_BALANCE = (
    Param("job", "A job file (YAML): sensors, planes, speeds and runs (instead of {initial}, "
          "{trial} and {run}).", "path", form="argument", metavar="JOB"),
    Param("initial", "Readings without trial: amplitude@phase, one per sensor, e.g. '6.0@30', "
          "'6 mm/s@30' or '170@112,53@78' (all bare, or all with units of one kind: µm, mm, mil; "
          "mm/s, in/s; g, m/s²; optionally pk, pk-pk or rms after the unit).", "texts",
          counts=(MAX_ITEMS,)),
    Param("trial", "Trial mass@angle per plane, e.g. '10 g@0' (once per plane; a bare mass is in "
          "grams).", "texts", counts=(MAX_ITEMS,), form="options"),
    Param("run", "Readings with each trial on, in the order of {trial} (as many as {initial}).",
          "nested", form="options"),
    Param("cumulative", "Every trial was left on for the later runs.", "flag", default=False),
    Param("trial_radius", "Radius the trials sat at (m, or with units); with {radius}, and for "
          "{suggest_trial}.", "quantity", "length", valid=_positive("the trial radius", "m")),
    Param("radius", "Radius the corrections go at (m, or with units); needs {trial_radius}.",
          "quantity", "length", valid=_positive("the correction radius", "m")),
    Param("method", "least-squares (the default with more readings than planes) or min-max (the "
          "largest predicted reading as small as it can be).", valid=_one_of("method")),
    Param("weights", "One weight per reading, w1,...,wN (least squares and min-max): a reading "
          "that matters more weighs more.", "numbers"),
    Param("mass_step", "Round correction masses to multiples of this, e.g. '0.5 g' (a bare number "
          "is kg).", "quantity", "mass", valid=_positive("the mass step", "kg")),
    Param("angle_step", "Round correction angles to multiples of this (degrees, or with units).",
          "degrees", valid=_angle_step),
    Param("positions", "N equally spaced positions (holes, blades), position 1 on the 0° mark: "
          "split each correction onto the two neighbouring ones.", "count", valid=_positions),
    Param("phase", "The instrument's phase: lag (grows against the rotation; most analysers) or "
          "lead. Needs {angle_sense}.", valid=_one_of("phase")),
    Param("angle_sense", "How the trial and correction angles are counted from the mark: with or "
          "against the rotation.", valid=_one_of("angle_sense")),
    Param("rotation", "How the rotor turns, seen from where the angles are read: cw or ccw (for "
          "the dial and the sheet).", valid=_one_of("rotation")),
    Param("measure", "The measure of readings that state none: pk, pk-pk or rms.",
          valid=_one_of("measure")),
    Param("severity", "Judge the readings: iso20816-3 (with {group} and {foundation}; velocity "
          "readings, or displacement and acceleration at {speed}).", valid=_one_of("standard")),
    Param("group", "ISO 20816-3 machine group: 1 (above 300 kW, or shaft height >= 315 mm) or 2 "
          "(15 kW to 300 kW).", "ints", valid=_group),
    Param("foundation", "ISO 20816-3 support: rigid or flexible.", valid=_one_of("foundation")),
    Param("speed", "The balancing speed (a bare number is rad/s; or e.g. '1480 rpm'): for "
          "{suggest_trial}, for {severity} with displacement or acceleration readings, and saved "
          "with the coefficients.", "quantity", "angular_speed", valid=_positive("the speed", "rad/s")),
    Param("coefficients", "Influence coefficients saved by {save_coefficients}: with {initial} "
          "alone, a trim run.", "path"),
    Param("save_coefficients", "Write the influence coefficients to this JSON file (never over an "
          "input; an existing file only with {force}).", "path", api=False),
    Param("suggest_trial", "Size a trial mass before the first run (with {rotor_mass}, {rotor} or "
          "{bearing_load}, {speed} and {trial_radius}).", "flag", default=False),
    Param("rotor_mass", "The rotor's mass, for {suggest_trial} (a bare number is kg); half its "
          "weight on each bearing.", "quantity", "mass", valid=_positive("the rotor's mass", "kg")),
    Param("rotor", "The rotor's body file, for {suggest_trial}: its mass.", "path"),
    Param("bearing_load", "The static load on the bearing nearest the trial plane, for "
          "{suggest_trial} (N, or with units).", "quantity", "force",
          valid=_positive("the bearing load", "N")),
    Param("trial_fraction", "The trial's centrifugal force as a fraction of that bearing load, "
          "e.g. 0.05 or '5 %'. Default: 10 %.", "fraction"),
    Param("full", "The extended result (method, residuals, significance...) even for a classic "
          "one- or two-plane job (what a job sheet shows).", "flag", cli=False),
)

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


