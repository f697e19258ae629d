"""The parameters of every command, each declared once (:class:`rbcli.api.params.Param`).

A command's table makes its public function's signature, checks and docstring, its typer
options and ``--help``, how each value is read, the options echo and the CSV units
(:mod:`rbcli.api.params`). Adding an option: its declaration here, the physics that uses it
(``rbcli/api/<command>.py``), a test. Light (no numpy): the command line builds ``--help``.
"""

from __future__ import annotations

import math
from dataclasses import replace
from functools import partial
from typing import Any

from rbcli.api.check import MAX_ITEMS
from rbcli.api.params import SYMMETRY_TOL, Param, as_text
from rbcli.errors import literal
from rbcli.io.field import CHOICES

__all__ = ["BODY", "INERTIA", "PRINCIPAL", "BALANCE", "FIELD_BALANCE", "PRECESS", "TOP",
           "GYROCOMPASS", "ROLLCHECK", "WHIRL", "REPORT", "TABLES"]

# --- shared

#: the shaft's direction (balance, whirl; ``replace(SHAFT, help=...)`` to word it)
SHAFT = Param("shaft", "Shaft direction x,y,z (or x, y, z) in the body frame. Default: the body's "
              "shaft, else z.", "direction")
#: a point of the shaft's line
THROUGH = Param("through", "A point of the shaft (z = 0 there): com, origin or x,y,z (a bare number "
                "in the body's length unit, m by default; a unit after the last number applies to "
                "all). Default: the body's shaft point, else the origin.", "point")
#: gravity (None: standard gravity, 9.80665 m/s^2)
G = Param("g", "Gravity (m/s^2, or with units). Default: 9.80665.", "quantity", "acceleration")


#: a STEP, STL or OBJ file given as the body: the command line's options of its BODY (every
#: command that takes one), :func:`rbcli.load`'s keywords
BODY = (
    Param("material", "A STEP, STL or OBJ BODY's material (rbcli materials).", api=False),
    Param("density", "A STEP, STL or OBJ BODY's density (kg/m^3, or '2.7 g/cm^3').", "quantity",
          "density", api=False),
    Param("part", "A STEP BODY's solid to keep: a name or pattern ('link*').", api=False),
)


def _given(given: Any) -> str:
    """A value as the caller gave it, inside a message."""
    return literal(as_text(given))


# the checks of values (a Param's ``valid``) are module-level functions, or partials of them,
# so that the options a result holds pickle (issue 34: results cross processes)

def _distinct(what: str, v: tuple[float, float], given: Any) -> str | None:
    """Two positions along the shaft that must differ."""
    return None if v[0] != v[1] else f"the two {what} are both at z = {v[0]:.6g} m; they must differ"


def _finite(v: float, given: Any, what: str = "number") -> str | None:
    return None if math.isfinite(v) else f"must be a finite {what}"


def _not_negative(what: str, r: float, given: Any) -> str | None:
    return None if 0.0 <= r < math.inf else f"{what}, got {_given(given)}"


def _positive(what: str, unit: str, x: float, given: Any) -> str | None:
    return None if x > 0.0 and math.isfinite(x) else f"{what} must be a positive number, got {x:.6g} {unit}"


def _angle_step(x: float, given: Any) -> str | None:
    return _positive("the angle step", "deg", x, given) or (
        "must not exceed 360 degrees" if x > 360.0 else None)


def _positions(n: int, given: Any) -> str | None:
    return None if 3 <= n <= 100_000 else \
        f"must be a whole number from 3 to 100000 (holes or blades), not {literal(given)}"


# --- inertia, principal

_ABOUT = Param("about", "Point: com, origin or x,y,z (a bare number in the body's length unit, m by "
               "default; a unit after the last number applies to all, e.g. '10,0,5 mm').", "point")

#: :func:`rbcli.inertia` and ``rbcli inertia``
INERTIA = (
    *BODY,
    _ABOUT,
    Param("axis", "Moment about this direction x,y,z through the point.", "direction"),
    Param("omega", "Angular velocity x,y,z (rad/s, or the body's units' angular_speed; a unit after "
          "the last number applies to all, e.g. '0,0,300 rpm').", "vector", "angular_speed"),
)

#: :func:`rbcli.principal` and ``rbcli principal``: about the com unless told
PRINCIPAL = (*BODY, replace(_ABOUT, default="com"))

# --- balance

_BARE_LENGTH = "a bare number in the body's length unit, m by default"

#: :func:`rbcli.balance` and ``rbcli balance``
BALANCE = (
    *BODY,
    SHAFT,
    THROUGH,
    Param("mark", "Direction x,y,z (body frame) of the 0° reference mark; only its part at right "
          "angles to the shaft counts. Default: body x projected (body y for a shaft near body x).",
          "vector", "dimensionless", echo="direction"),
    Param("zero_mark_deg", "Turn the 0° mark this far about the shaft, in the direction of rotation "
          "(degrees, or with units, e.g. '0.5 rad'). Default: 0.", "degrees",
          valid=partial(_finite, what="angle")),
    Param("angle_sense", "Count angles with the rotation (with) or against it (against).", "choice",
          choices=("with", "against"), default="with"),
    Param("planes", f"Correction planes zA,zB along the shaft ({_BARE_LENGTH}; a unit after the last "
          "number applies to both, e.g. '-100,100 mm').", "values", "length", (2,),
          valid=partial(_distinct, "correction planes")),
    Param("radius", f"Correction radius r, or rA,rB per plane ({_BARE_LENGTH}; or with units as for "
          "{planes}). Default: the body's rim_radius.", "values", "length", (1, 2)),
    Param("mass_step", "Round correction masses to multiples of this (e.g. '1 g'; a bare number is in "
          "the body's mass unit, kg by default).", "quantity", "mass"),
    Param("angle_step", "Round correction angles to multiples of this (degrees, or with units).",
          "degrees", valid=_angle_step),
    Param("positions", "N equally spaced fixed positions (holes, blades), position 1 on the 0° mark: "
          "split each correction onto the two neighbouring ones.", "count",
          valid=_positions),
    Param("speed", "Rotor speed (rad/s, or the body's units' angular_speed; or e.g. '1500 rpm'); with "
          "{grade} the maximum service speed.", "quantity", "angular_speed"),
    Param("bearings", f"Bearing positions z1,z2 along the shaft ({_BARE_LENGTH}; a unit after the "
          "last number applies to both, e.g. '-50,150 mm').", "values", "length", (2,),
          valid=partial(_distinct, "bearings")),
    replace(G, help="Gravity for the static bearing loads (m/s^2, or with units). "
                        "Default: 9.80665 m/s^2."),
    Param("grade", "ISO 21940-11 balance quality grade, e.g. G6.3 (G0.4 to G4000); needs {speed} "
          "and {bearings}.", "grade"),
    Param("tolerance_planes", "Planes the permissible unbalance is allocated to: bearings (ISO "
          "21940-11, the default) or corrections (older practice).", "choice",
          choices=("bearings", "corrections")),
)

# --- field-balance


def _one_of(key: str, word: str, given: Any) -> str | None:
    allowed = CHOICES[key]
    ways = " or ".join(filter(None, (", ".join(allowed[:-1]), allowed[-1])))
    return None if word in allowed else f"must be {ways}, not '{literal(word)}'"


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
          "{suggest_trial}.", "quantity", "length", valid=partial(_positive, "the trial radius", "m")),
    Param("radius", "Radius the corrections go at (m, or with units); needs {trial_radius}.",
          "quantity", "length", valid=partial(_positive, "the correction radius", "m")),
    Param("method", "least-squares (the default with more readings than planes) or min-max (the "
          "largest predicted reading as small as it can be).", valid=partial(_one_of, "method")),
    Param("weights", "One weight per reading, w1,...,wN (least squares and min-max): a reading "
          "that matters more weighs more.", "numbers"),
    Param("mass_step", "Round correction masses to multiples of this, e.g. '0.5 g' (a bare number "
          "is kg).", "quantity", "mass", valid=partial(_positive, "the mass step", "kg")),
    Param("angle_step", "Round correction angles to multiples of this (degrees, or with units).",
          "degrees", valid=_angle_step),
    Param("positions", "N equally spaced positions (holes, blades), position 1 on the 0° mark: "
          "split each correction onto the two neighbouring ones.", "count", valid=_positions),
    Param("drawer", "The weights there are, mass[:count] each, e.g. '2 g:8,5 g:4,10 g' (a bare mass is "
          "grams): the best of them at the {positions} holes (at {radius}).", "texts", counts=(MAX_ITEMS,)),
    Param("max_weights", "With {drawer}: the most weights a plane takes, 1 to 4. Default: 2.", "count",
          valid=lambda n, _: None if 1 <= n <= 4 else f"must be from 1 to 4, not {n}"),
    Param("max_mass", "The most mass a plane takes, for all or m1,m2,... per plane (e.g. '50 g'; a bare "
          "number is kg), or mass x radius ('5000 g*mm').", "texts", counts=(MAX_ITEMS,)),
    Param("limit", "The largest predicted reading, for all or SENSOR=amplitude, e.g. '1=2.8 mm/s'.",
          "texts", counts=(MAX_ITEMS,)),
    Param("robust", "huber: least squares that discounts a bad reading (named).", valid=partial(_one_of, "robust")),
    Param("phase", "The instrument's phase: lag (grows against the rotation; most analysers) or "
          "lead. Needs {angle_sense}.", valid=partial(_one_of, "phase")),
    Param("angle_sense", "How the trial and correction angles are counted from the mark: with or "
          "against the rotation.", valid=partial(_one_of, "angle_sense")),
    Param("rotation", "How the rotor turns, seen from where the angles are read: cw or ccw (for "
          "the dial and the sheet).", valid=partial(_one_of, "rotation")),
    Param("measure", "The measure of readings that state none: pk, pk-pk or rms.",
          valid=partial(_one_of, "measure")),
    Param("severity", "Judge the readings: iso20816-3 (with {group} and {foundation}; velocity "
          "readings, or displacement and acceleration at {speed}).", valid=partial(_one_of, "standard")),
    Param("group", "ISO 20816-3 machine group: 1 (above 300 kW, or shaft height >= 315 mm) or 2 "
          "(15 kW to 300 kW).", "ints", valid=_group),
    Param("foundation", "ISO 20816-3 support: rigid or flexible.", valid=partial(_one_of, "foundation")),
    Param("speed", "The balancing speed (a bare number is rad/s; or e.g. '1480 rpm'): for "
          "{suggest_trial}, for {severity} with displacement or acceleration readings, and saved "
          "with the coefficients.", "quantity", "angular_speed", valid=partial(_positive, "the speed", "rad/s")),
    Param("coefficients", "Influence coefficients saved by {save_coefficients}: with {initial} "
          "alone, a trim run.", "path"),
    Param("save_coefficients", "Write the influence coefficients to this JSON file (never over an "
          "input; an existing file only with {force}).", "path", api=False),
    Param("suggest_trial", "Size a trial mass before the first run (with {rotor_mass}, {rotor} or "
          "{bearing_load}, {speed} and {trial_radius}).", "flag", default=False),
    Param("rotor_mass", "The rotor's mass, for {suggest_trial} (a bare number is kg); half its "
          "weight on each bearing.", "quantity", "mass", valid=partial(_positive, "the rotor's mass", "kg")),
    Param("rotor", "The rotor's body file, for {suggest_trial}: its mass.", "path"),
    Param("bearing_load", "The static load on the bearing nearest the trial plane, for "
          "{suggest_trial} (N, or with units).", "quantity", "force",
          valid=partial(_positive, "the bearing load", "N")),
    Param("trial_fraction", "The trial's centrifugal force as a fraction of that bearing load, "
          "e.g. 0.05 or '5 %'. Default: 10 %.", "fraction"),
    Param("full", "The extended result (method, residuals, significance...) even for a classic "
          "one- or two-plane job (what a job sheet shows).", "flag", cli=False),
)

# --- precess

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
    *BODY,
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

# --- top, gyrocompass

#: rows of top's time series when ``samples`` is not given
TOP_SAMPLES = 600


def _above_zero(why: str, v: float, given: Any) -> str | None:
    """A positive finite number: ``<why>, got <the value as given>``."""
    if not math.isfinite(v):
        return "must be a finite number"
    return None if v > 0.0 else f"{why}, got {literal(as_text(given))}"


def _nonzero(zero: str, v: float, given: Any) -> str | None:
    return _finite(v, given) or (f"must not be 0: {zero}" if v == 0.0 else None)


def _spin(what: str, eg: str, zero: str) -> Param:
    """The spin of top and gyrocompass (its help and its refusal of 0 differ)."""
    return Param("spin", f"Required. {what} (rad/s, or the body's units' angular_speed; or e.g. "
                 f"'{eg}'); negative = the other way.", "quantity", "angular_speed",
                 valid=partial(_nonzero, zero))


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
    *BODY,
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
          valid=partial(_above_zero, "gravity must be positive (it points down, towards -z)")),
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
          f"{MAX_SAMPLES}). Default {TOP_SAMPLES}.", "count", valid=_rows, echo="-"),
    _NO_SYMMETRY_ECHO,
)

#: :func:`rbcli.gyrocompass` and ``rbcli gyrocompass``
GYROCOMPASS = (
    *BODY,
    Param("ratio", "C/A, the axial moment over the moment about the vertical (a flat disk: 2), "
          "instead of a body.", "quantity", "dimensionless", valid=partial(_above_zero, "C/A must be positive"),
          echo="=C/A"),
    Param("shaft", "The rotor's spin axis x,y,z (or x, y, z) in the body frame. Default: the body's "
          "shaft axis, else z.", "direction"),
    _spin("Rotor spin about its axis", "6000 rpm", "a gyrocompass needs a spinning rotor"),
    Param("latitude", "Required. Latitude, -90 to 90 (degrees, or with units); negative = south.",
          "quantity", "angle", valid=_latitude),
    Param("earth_rate", "The Earth's (sidereal) rotation rate (rad/s, or with units). Default: "
          "7.2921150e-5.", "quantity", "angular_speed", valid=partial(_above_zero, "must be positive")),
    _NO_SYMMETRY_ECHO,
)

# --- rollcheck

def _lean(b: float, given: Any) -> str | None:
    return None if 0.0 <= b < 0.5 * math.pi else ("the inward lean from the vertical must be from 0 up to "
                                                   f"(not including) 90 degrees, got {_given(given)}")


#: :func:`rbcli.rollcheck` and ``rbcli rollcheck`` (its options ``--axle``, ``--radius`` and
#: ``--speed``: :data:`rbcli.errors.COMMAND_OPTIONS`)
ROLLCHECK = (
    *BODY,
    replace(SHAFT, help="Axle direction x,y,z (or x, y, z) in the body frame. Default: "
                        "the body's shaft axis, else z."),
    replace(THROUGH, help="A point of the axle line: com, origin or x,y,z (a bare number "
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
          "length", valid=partial(_not_negative, "must be 0 (knife edge) or a positive length")),
    replace(G, help="Gravity (m/s^2, or with units, e.g. '1 g0'). Default: 9.80665."),
    Param("rolling_speed", "Speed of the centre (a bare number is m/s, whatever the body's units: a "
          "body file has no speeds; or with a unit, e.g. '20 km/h', '10 mph'); negative = "
          "backwards.", "quantity", "speed", valid=_finite),
    Param("spin", "Spin about the axle (rad/s, or the body's units' angular_speed; or e.g. '300 "
          "rpm'); speed = a x spin.", "quantity", "angular_speed", valid=_finite),
    Param("lean", "Steady circle: inward lean from the vertical (degrees, or with units), 0 to <90.",
          "quantity", "angle", valid=_lean),
    Param("circle", "Steady circle: radius of the circle the centre runs on (a bare number in the "
          "body's length unit, m by default; or with units); 0 = spinning in place.", "quantity",
          "length", valid=partial(_not_negative, "the circle radius must be 0 (spinning in place) or positive")),
    _NO_SYMMETRY_ECHO,
)

# --- whirl

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
    *BODY,
    Param("bearings", "Bearing positions z1,z2[,...] along the shaft, two or more at distinct "
          "places (a bare number in the body's length unit, m by default; a unit after the last "
          "number applies to all, e.g. '0,200 mm'). Default: the body file's bearings: section "
          "(whose coefficients the options below override).", "values", "length", _UP_TO),
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
    SHAFT,
    Param("through", "A point of the shaft (z = 0 there): com, origin or x,y,z (a bare number in "
          "the body's length unit). Default: the body's shaft point, else the origin.", "point"),
    SYMMETRY_TOL,
)



# --- report


def _worded(table: tuple[Param, ...], name: str, help: str, **changes: Any) -> Param:
    """Parameter ``name`` of a command's ``table``, worded for the report."""
    return replace(next(p for p in table if p.name == name), help=help, **changes)


#: :func:`rbcli.report` and ``rbcli report``: other commands' parameters, each section's
#: read by its command (:func:`rbcli.api.report.parse`)
REPORT = (
    *BODY,
    replace(SHAFT, help="Balance and rolling: shaft (axle) direction x,y,z (or x, y, z). Default: "
            "the body's shaft; without either there is no balance section."),
    replace(THROUGH, help="Balance and rolling: a point of the shaft: com, origin or x,y,z "
            f"({_BARE_LENGTH}; a unit after the last number applies to all, e.g. '0,0,50 mm'). "
            "Default: the body's shaft point, else the origin."),
    _worded(BALANCE, "planes", f"Balance: correction planes zA,zB along the shaft ({_BARE_LENGTH}; "
            "a unit after the last number applies to both, e.g. '-100,100 mm')."),
    _worded(BALANCE, "radius", f"Balance: correction radius r, or rA,rB ({_BARE_LENGTH}; or with "
            "units as for {planes}). Default: the body's rim_radius."),
    _worded(BALANCE, "bearings", "Balance: bearing positions z1,z2 along the shaft "
            f"({_BARE_LENGTH}; a unit after the last number applies to both, e.g. '-50,150 mm')."),
    _worded(BALANCE, "grade", "Balance: ISO 21940-11 grade, e.g. G6.3; needs an angular {speed} "
            "and {bearings}."),
    _worded(BALANCE, "speed", "With a unit: an angular speed ('3000 rpm', rad/s) is the balance "
            "rotor speed, the whirl operating speed and the rolling spin; a speed ('20 km/h', "
            "m/s) is the rolling speed."),
    _worded(WHIRL, "stiffness", "Whirl: the bearings' stiffness (N/m, or with units, e.g. '200 "
            "N/mm'), one value for every bearing or one per {bearings} position; the report then "
            "has a whirl section (critical speeds, Campbell diagram, unbalance response).",
            counts=(1, 2)),
    _worded(WHIRL, "damping", "Whirl: the bearings' damping (N s/m, or with units), one value or "
            "one per bearing. Default: none.", counts=(1, 2)),
    _worded(PRECESS, "omega", "Free precession: initial angular velocity x,y,z, body frame (rad/s;"
            " a unit after the last number applies to all, e.g. '0,0,300 rpm')."),
    _worded(TOP, "pivot", f"Heavy top: the fixed point: com, origin or x,y,z ({_BARE_LENGTH}; a "
            "unit after the last number applies to all, e.g. '0,0,-20 mm'). Default: the body's "
            "pivot; without either there is no top section."),
    _worded(TOP, "spin", "Heavy top: spin about the symmetry axis (a bare number is rad/s, or the "
            "body's units' angular_speed; or e.g. '3000 rpm')."),
    _worded(TOP, "theta", "Heavy top: start tilt of the axis from the upward vertical (degrees, or"
            " with units)."),
    _worded(TOP, "theta_dot", "Heavy top: start rate theta' (rad/s, or with units). Default: 0."),
    _worded(TOP, "phi_dot", "Heavy top: start precession rate phi' (rad/s, or with units). "
            "Default: 0."),
    _worded(ROLLCHECK, "rim_radius", f"Rolling: rim radius ({_BARE_LENGTH}; or with units). "
            "Default: the body's rim_radius, else the largest round part coaxial with the axle."),
    _worded(ROLLCHECK, "tyre_radius", f"Rolling: tube radius of a rounded rim ({_BARE_LENGTH}; or "
            "with units). Default: 0, a knife edge."),
    SYMMETRY_TOL,
    replace(G, help="Gravity for the top, rolling and static bearing loads (m/s^2, or with units)."
            " Default: 9.80665 m/s^2."),
)

#: each command's table, by the command's name
TABLES = {"inertia": INERTIA, "principal": PRINCIPAL, "balance": BALANCE, "precess": PRECESS,
          "field-balance": FIELD_BALANCE, "top": TOP, "gyrocompass": GYROCOMPASS,
          "rollcheck": ROLLCHECK, "whirl": WHIRL, "report": REPORT}
