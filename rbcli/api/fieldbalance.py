"""Field (trial-weight) balancing: the service behind ``rbcli field-balance``.

The influence-coefficient method of :mod:`rbcli.core.balance.field` (physics sheet
``physics/balance.md`` §5; the two-plane example is Brüel & Kjær application note 17-227,
"Static and dynamic balancing of rigid rotors"): one plane from an initial reading, one
trial mass and one run, or two planes with two sensors and two trial runs.
:func:`field_balance` reads the readings once (:class:`FieldBalanceOptions`) and returns a
frozen :class:`FieldBalanceResult` whose ``to_json()`` is exactly what
``rbcli field-balance --json`` prints. No body is needed.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from rbcli.api import options as op
from rbcli.api.result import Result
from rbcli.errors import InputError, ParamError

__all__ = ["FieldBalanceOptions", "FieldBalanceResult", "field_balance", "run"]

_READING = re.compile(r"\s*(?P<num>[^@]+?)\s*@\s*(?P<ang>.+?)\s*")

#: the core's parameter names -> the options of :func:`field_balance`
_CORE_PARAMS = {"v0": "initial", "v1": "run", "va": "run", "vb": "run", "trial": "trial",
                "trial_a": "trial", "trial_b": "trial"}

#: the angle convention of field balancing, in words
CONVENTION = ("angles and phases in degrees, counted in the same sense as the trial angles and the "
              "phase readings (they must agree)")


#: what a reading's unit may measure -> its kind; readings are converted to SI
READING_KINDS = {"displacement": (1, 0), "velocity": (1, -1), "acceleration": (1, -2)}
#: the SI unit of each kind, as JSON reports it
SI_UNITS = {"displacement": "m", "velocity": "m/s", "acceleration": "m/s^2"}
#: the units a reading may carry, for messages and help
READING_UNITS = "displacement µm, mm, mil; velocity mm/s, in/s; acceleration g, m/s²"


@dataclass(frozen=True)
class _Reading:
    value: complex  # SI when kind is not None, else the number as given
    kind: str | None  # None: a bare number (a relative scale)
    option: str
    text: str


def _amplitude(text: str, option: str, whole: str) -> tuple[float, str | None]:
    """A reading's amplitude: (value, kind) - SI for a unit of vibration, the number for a
    bare one (kind None). ``g`` is standard gravity here (an acceleration) and ``mil`` a
    thousandth of an inch (25.4 µm)."""
    from fractions import Fraction

    from rbcli.io import units as un

    num = op.NUMBER.match(text)
    if not num:
        raise InputError(f"{option}: '{whole}': the amplitude must be a number, optionally with a "
                         f"unit ({READING_UNITS})")
    number = text[: num.end()].strip().replace("\u2212", "-")
    unit = text[num.end():].strip()
    try:
        if not unit:
            return op.quantity(number, "dimensionless", option), None
        if unit in ("mil", "mils"):
            op.quantity(number, "dimensionless", option)  # its checks (range, digits)
            return float(Fraction(number) * Fraction(254, 10**7)), "displacement"
        if unit == "g":
            return un.to_si(f"{number} g0", "acceleration"), "acceleration"
        value, dim = un.parse_quantity(f"{number} {unit}")
    except un.UnitError as exc:
        raise InputError(f"{option}: '{whole}': {exc}") from None
    for kind, (L, T) in READING_KINDS.items():
        if dim == un.Dim(L=L, T=T):
            return value, kind
    raise InputError(f"{option}: '{whole}': '{unit}' is {dim.describe()}, not a vibration reading; "
                     f"give {READING_UNITS}, or bare numbers for all readings (a relative scale)")


def _reading(text: str, option: str) -> _Reading:
    """'6.0@30', '6 mm@30' or '4.0 in/s@110' -> a reading; the phase in degrees."""
    import cmath

    m = _READING.fullmatch(text)
    if not m:
        raise InputError(f"{option}: '{text}' is not amplitude@phase, e.g. '6.0@30' or '6 mm/s@30'")
    amp, kind = _amplitude(m["num"], option, text)
    ang = math.degrees(op.quantity(m["ang"], "angle", option, bare="deg"))
    if not (math.isfinite(amp) and math.isfinite(ang)) or amp < 0:
        raise InputError(f"{option}: '{text}': amplitude must be a finite number >= 0 and the angle finite")
    return _Reading(complex(cmath.rect(amp, math.radians(ang))), kind, option, text)


def _trial(text: str, option: str) -> complex:
    """'10 g@0' or '10@0' (grams: a bare trial mass is in grams) -> kg e^{i angle}."""
    import cmath

    m = _READING.fullmatch(text)
    if not m:
        raise InputError(f"{option}: '{text}' is not mass@angle, e.g. '10 g@0' (a bare mass is grams)")
    amp = op.quantity(m["num"], "mass", option, bare="g")
    ang = math.degrees(op.quantity(m["ang"], "angle", option, bare="deg"))
    if not (math.isfinite(amp) and math.isfinite(ang)) or amp < 0:
        raise InputError(f"{option}: '{text}': amplitude must be a finite number >= 0 and the angle finite")
    return complex(cmath.rect(amp, math.radians(ang)))


def _one_kind(readings: list[_Reading]) -> str | None:
    """The one kind all readings share (None: all bare), else an InputError saying what was
    found."""
    first = readings[0]
    for r in readings[1:]:
        if (r.kind is None) != (first.kind is None):
            bare, unit = (r, first) if r.kind is None else (first, r)
            raise ParamError(r.option[2:], (
                f"'{bare.text}' ({bare.option}) is a bare number but '{unit.text}' ({unit.option}) "
                f"has a unit ({unit.kind}): give every reading a unit of one kind ({READING_UNITS}) "
                "or none (all bare: a relative scale)"))
        if r.kind != first.kind:
            raise ParamError(r.option[2:], (
                f"'{r.text}' ({r.option}) is a {r.kind} but '{first.text}' ({first.option}) is a "
                f"{first.kind}: every reading must be of one kind ({READING_UNITS})"))
    return first.kind


def _texts(v: Any) -> list[str]:
    """One option value or several (``--trial`` given twice): a list of strings."""
    if isinstance(v, str):
        return [v]
    if isinstance(v, Sequence):
        return [x if isinstance(x, str) else str(x) for x in v]
    raise InputError(f"expected a string or a list of strings, got {type(v).__name__}")


def _readings(text: str, option: str, n: int) -> list[_Reading]:
    parts = text.split(",")
    if len(parts) != n:
        raise InputError(
            f"{option}: expected {n} reading{'s' if n > 1 else ''} (one per sensor, as many as "
            f"trial planes), got {len(parts)} in '{text}'", param=option[2:]
        )
    with op.naming(option[2:]):
        return [_reading(p, option) for p in parts]




def _deg(z: complex) -> float:
    """arg z in degrees in [0, 360) (within 1e-9° below 360 is 0; never -0.0)."""
    a = math.degrees(math.atan2(z.imag, z.real)) % 360.0
    return 0.0 if a >= 360.0 - 1e-9 else a + 0.0


@dataclass(frozen=True)
class FieldBalanceOptions:
    """The options of :func:`field_balance`, read and checked once.

    Attributes
    ----------
    initial : tuple of complex — the readings without trial, one per sensor (reading unit)
    runs : tuple of tuple of complex — the readings of each trial run
    trials : tuple of complex — trial mass (kg) e^{i angle}, one per plane
    cumulative : bool — two planes: trial A left on during run B
    radii : (float, float) | None — m, (trial radius, correction radius)
    reading_kind : str | None — "displacement", "velocity" or "acceleration" (the readings
        are then in m, m/s or m/s²), None for bare readings (a relative scale)
    """

    initial: tuple[complex, ...]
    runs: tuple[tuple[complex, ...], ...]
    trials: tuple[complex, ...]
    cumulative: bool = False
    radii: tuple[float, float] | None = None
    reading_kind: str | None = None

    @property
    def planes(self) -> int:
        return len(self.trials)

    @property
    def scale(self) -> float:
        """Trial radius / correction radius (1 when no radii are given)."""
        return 1.0 if self.radii is None else self.radii[0] / self.radii[1]

    @classmethod
    def parse(cls, body: None = None, *, initial, trial, run, cumulative: bool = False,
              trial_radius=None, radius=None) -> FieldBalanceOptions:
        """Read the keyword arguments of :func:`field_balance` (see there).

        Raises
        ------
        rbcli.InputError
            with the message the command line prints (``--trial: ...``).
        """
        trials_t, runs_t = _texts(trial), _texts(run)
        n = len(trials_t)
        if n not in (1, 2):
            raise ParamError("trial", f"give one trial (one plane) or two (two planes), not {n}")
        if len(runs_t) != n:
            raise ParamError("run", f"give one run per trial ({n}), not {len(runs_t)}")
        if cumulative and n != 2:
            raise ParamError("cumulative", "only for two planes")
        if (trial_radius is None) != (radius is None):
            raise InputError("--radius and --trial-radius go together (the corrections move from the "
                             "trial radius to --radius)", param="radius")
        radii = None
        if radius is not None:
            with op.naming("trial_radius"):
                rt = op.positive(op.quantity(trial_radius, "length", "--trial-radius"), "--trial-radius",
                                 "the trial radius")
            with op.naming("radius"):
                rc = op.positive(op.quantity(radius, "length", "--radius"), "--radius",
                                 "the correction radius")
            radii = (rt, rc)
        if not isinstance(initial, str):
            initial = ",".join(_texts(initial))
        v0 = _readings(initial, "--initial", n)
        runs = [_readings(r, "--run", n) for r in runs_t]
        kind = _one_kind(v0 + [x for r in runs for x in r])
        with op.naming("trial"):
            trials = [_trial(t, "--trial") for t in trials_t]
        for t in trials:
            if t == 0:
                raise ParamError("trial", "the trial mass must not be zero")
        return cls(initial=tuple(x.value for x in v0), runs=tuple(tuple(x.value for x in r) for r in runs),
                   trials=tuple(trials), cumulative=bool(cumulative), radii=radii, reading_kind=kind)


@dataclass(frozen=True)
class FieldCorrection:
    """One plane's correction.

    Attributes
    ----------
    name : str — "A" or "B"
    correction : complex — kg e^{i angle}, to add with the trial removed (at the correction
        radius when radii are given)
    correction_trial_on : complex — kg, to add with that plane's trial left on
    """

    name: str
    correction: complex
    correction_trial_on: complex

    @property
    def mass(self) -> float:
        """kg"""
        return abs(self.correction)

    @property
    def angle_deg(self) -> float:
        """deg, [0, 360), the sense of the trial angles and phases"""
        return _deg(self.correction) if self.correction != 0 else 0.0


@dataclass(frozen=True)
class FieldBalanceResult(Result):
    """What ``rbcli field-balance`` reports.

    Attributes
    ----------
    planes : int — 1 or 2
    initial : tuple of complex — the readings without trial (SI, or the relative scale)
    runs : tuple of tuple of complex — the readings of each trial run
    corrections : tuple of FieldCorrection — per plane (kg)
    influence : tuple of tuple of complex — reading (SI, or the relative scale) per kg;
        row = sensor, column = plane
    trials : tuple of complex — kg e^{i angle}
    radii : (float, float) | None — m, (trial radius, correction radius)
    cond : float | None — 2-norm condition number of the influence matrix (two planes)
    det : complex | None — its determinant (two planes)
    ill_conditioned : bool
    small_response : tuple of bool — per trial run
    predicted_residual : tuple of complex — per sensor, reading unit (0 in the linear model)
    cumulative : bool
    reading_kind : str | None — "displacement", "velocity", "acceleration" (readings,
        influence coefficients and residuals in m, m/s, m/s² and per kg), or None for bare
        readings (their own relative scale)
    warnings : tuple of str
    """

    planes: int
    initial: tuple[complex, ...]
    runs: tuple[tuple[complex, ...], ...]
    corrections: tuple[FieldCorrection, ...]
    influence: tuple[tuple[complex, ...], ...]
    trials: tuple[complex, ...]
    radii: tuple[float, float] | None
    cond: float | None
    det: complex | None
    ill_conditioned: bool
    small_response: tuple[bool, ...]
    predicted_residual: tuple[complex, ...]
    cumulative: bool
    reading_kind: str | None = None
    warnings: tuple[str, ...] = ()

    def diagram(self):
        """The polar diagram of a balancing sheet (what ``--plot`` draws), an
        :class:`rbcli.api.diagram.Diagram`: per sensor the reading O without trial, each run
        O+T and the change T made (from O's tip to O+T's); then per plane the trial mass and
        the correction to add (trial removed). Angles as given and printed."""
        from rbcli.api.diagram import Arrow, Diagram, Panel

        panels = []
        n = self.planes
        for i in range(len(self.initial)):
            o = self.initial[i]
            arrows = [Arrow("initial", "O, no trial", abs(o), _deg(o))]
            for j, run in enumerate(self.runs):
                name = "AB"[j] if n == 2 else ""
                v = run[i]
                arrows.append(Arrow("run", f"O+T{name}, trial {name or ''} on".replace("  ", " "),
                                    abs(v), _deg(v)))
                ref = self.runs[0][i] if (j == 1 and self.cumulative) else o
                d = v - ref
                arrows.append(Arrow("effect", f"T{name}: the trial's effect", abs(d), _deg(d),
                                    d != 0, tail=(abs(ref), _deg(ref))))
            title = "readings" if len(self.initial) == 1 else f"sensor {i + 1} readings"
            panels.append(Panel(title, "reading", tuple(arrows)))
        for j, (t, c) in enumerate(zip(self.trials, self.corrections)):
            arrows = (Arrow("trial", "trial mass", abs(t), _deg(t), t != 0, mass=abs(t)),
                      Arrow("correction", "add (trial removed)", c.mass, c.angle_deg, c.correction != 0,
                            mass=c.mass))
            panels.append(Panel(f"plane {c.name}: masses", "mass", arrows))
        return Diagram("field balancing", tuple(panels), "with",
                       "angles as given: the trial angles and the phases in the same sense",
                       self.reading_kind)

    @property
    def reading_unit(self) -> str | None:
        """The SI unit the readings (and the influence coefficients per kg) are in: "m",
        "m/s" or "m/s^2"; None for bare readings (a relative scale)."""
        return None if self.reading_kind is None else SI_UNITS[self.reading_kind]

    def to_json(self) -> dict[str, Any]:
        """The document ``rbcli field-balance --json`` prints."""
        out: dict[str, Any] = {
            "planes": self.planes,
            "corrections": [
                {
                    "name": c.name,
                    "mass": abs(c.correction),
                    "angle_deg": _deg(c.correction) if c.correction != 0 else 0.0,
                    "mass_trial_on": abs(c.correction_trial_on),
                    "angle_trial_on_deg": _deg(c.correction_trial_on) if c.correction_trial_on != 0 else 0.0,
                    "radius": None if self.radii is None else float(self.radii[1]),
                }
                for c in self.corrections
            ],
            "influence": [[{"magnitude": abs(a), "angle_deg": _deg(a)} for a in row] for row in self.influence],
            "trials": [{"mass": abs(t), "angle_deg": _deg(t)} for t in self.trials],
            "trial_radius": None if self.radii is None else float(self.radii[0]),
            "readings": {"kind": self.reading_kind or "relative", "unit": self.reading_unit},
        }
        if self.planes == 2:
            out["cond"] = float(self.cond)
            out["det_magnitude"] = float(abs(self.det))
            out["ill_conditioned"] = bool(self.ill_conditioned)
        out["small_response"] = [bool(s) for s in self.small_response]
        out["predicted_residual"] = [float(abs(v)) for v in self.predicted_residual]
        out["cumulative"] = bool(self.cumulative)
        out["angle_convention"] = CONVENTION
        out["warnings"] = list(self.warnings)
        return out


def run(body: None, options: FieldBalanceOptions) -> FieldBalanceResult:
    """Field balancing with ``options`` (``body`` is None: the command needs none).

    Raises
    ------
    rbcli.InputError
        readings that give no influence coefficient or a singular matrix (``--run: ...``);
        :class:`rbcli.NonFiniteResult` when the result overflows.
    """
    import numpy as np

    from rbcli.api.result import jsonable
    from rbcli.core import balance as B
    from rbcli.errors import NonFiniteResult

    o = options
    s = o.scale
    try:
        with np.errstate(all="ignore"):
            try:
                if o.planes == 1:
                    f = B.field_single_plane(o.initial[0], o.runs[0][0], o.trials[0])
                    res = FieldBalanceResult(
                        planes=1, initial=o.initial, runs=o.runs,
                        corrections=(FieldCorrection("A", f.correction * s, f.correction_trial_on * s),),
                        influence=((f.influence,),), trials=o.trials, radii=o.radii, cond=None,
                        det=None, ill_conditioned=False, small_response=(bool(f.small_response),),
                        predicted_residual=(f.predicted_residual,), cumulative=False,
                        reading_kind=o.reading_kind, warnings=f.warnings)
                else:
                    f = B.field_two_plane(o.initial, o.runs[0], o.runs[1], o.trials[0], o.trials[1],
                                          cumulative=o.cumulative)
                    res = FieldBalanceResult(
                        planes=2, initial=o.initial, runs=o.runs,
                        corrections=tuple(FieldCorrection(name, complex(w) * s, complex(w_on) * s)
                                          for name, w, w_on in zip("AB", f.corrections,
                                                                   f.corrections_trials_on)),
                        influence=tuple(tuple(complex(a) for a in row) for row in f.influence),
                        trials=o.trials, radii=o.radii, cond=float(f.cond), det=complex(f.det),
                        ill_conditioned=bool(f.ill_conditioned),
                        small_response=tuple(bool(x) for x in f.small_response),
                        predicted_residual=tuple(complex(v) for v in f.predicted_residual),
                        cumulative=bool(f.cumulative), reading_kind=o.reading_kind,
                        warnings=f.warnings)
            except B.BalanceValueError as exc:
                raise ParamError(_CORE_PARAMS.get(exc.param, "run"), str(exc)) from None
            except np.linalg.LinAlgError as exc:
                raise ParamError("run", str(exc)) from None
            jsonable(res.to_json())  # the one finiteness check: refuses inf and NaN
    except (OverflowError, ZeroDivisionError, NonFiniteResult):
        raise NonFiniteResult(
            "--initial, --trial, --run: the result overflows (a number beyond 1e308); "
            "the readings or trial masses are too large or too small"
        ) from None
    return res


_run = run  # field_balance's parameter ``run`` (the readings) hides the function


def field_balance(*, initial, trial, run, cumulative: bool = False, trial_radius=None,
                  radius=None) -> FieldBalanceResult:
    """Field (trial-weight) balancing from vibration readings: influence coefficients.

    Readings are ``"amplitude@phase"`` strings (phases in degrees from the keyphasor):
    either all bare numbers (``"6.0@30"``: one relative scale, the corrections do not depend
    on it) or all with units of one kind, converted exactly: displacement (``"40 um@30"``,
    µm, mm, mil), velocity (``"6 mm/s@30"``, mm/s, in/s) or acceleration (``"0.5 g@30"``,
    g = standard gravity, m/s²). Trial masses are ``"mass@angle"`` (``"10 g@0"``; a bare
    mass is in grams, as balancing sheets write it).

    Parameters
    ----------
    initial : str or sequence of str
        The readings without trial, one per sensor: ``"6.0@30"`` or ``"170@112,53@78"``.
    trial : str or sequence of str
        The trial mass per plane (one plane: one string; two planes: two).
    run : str or sequence of str
        The readings with each trial on, in the order of ``trial``.
    cumulative : bool
        Two planes: trial A was left on during the run with trial B.
    trial_radius, radius : float or str, optional
        Radius the trials sat at and the radius the corrections go at, m (together).

    Returns
    -------
    FieldBalanceResult
        ``corrections[i].mass`` kg, ``angle_deg`` in the sense of the trial angles.

    Raises
    ------
    rbcli.InputError
        with the command line's message and ``param``.

    Examples
    --------
    >>> import rbcli
    >>> r = rbcli.field_balance(initial="6.0@30", trial="10 g@0", run="4.0@110")
    >>> round(r.corrections[0].mass * 1e3, 2)   # g
    9.08
    """
    return _run(None, FieldBalanceOptions.parse(
        None, initial=initial, trial=trial, run=run, cumulative=cumulative,
        trial_radius=trial_radius, radius=radius))
