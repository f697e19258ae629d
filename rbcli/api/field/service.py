"""Field (trial-weight) balancing: the service behind ``rbcli field-balance``.

The influence-coefficient method (physics sheet ``physics/balance.md`` §5; the two-plane
example is Brüel & Kjær application note 17-227, "Static and dynamic balancing of rigid
rotors"): P correction planes, N >= P readings per run (sensors at one or more speeds),
one trial run per plane. N = P is solved exactly (:mod:`rbcli.core.field.classic` for
the classic one- and two-plane jobs, whose outputs never change); N > P by least squares
or min-max (:mod:`rbcli.core.field.solve`). A job comes from keyword arguments
(the command line's shorthand for a one-speed job) or from a job file
(:mod:`rbcli.io.field.jobfile`); stored coefficients (:mod:`rbcli.io.field.coefficients`) turn a run
with the initial readings alone into a trim run. :func:`field_balance` reads the options
once (:class:`FieldBalanceOptions`) and returns a frozen
:class:`~rbcli.api.field.result.FieldBalanceResult` whose ``to_json()`` is what
``rbcli field-balance --json`` prints. No body is needed.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, TypeAlias

from rbcli.api import check
from rbcli.api.check import Quantity
from rbcli.api.field.result import (  # noqa: F401  (re-exported: the result types)
    CONVENTION, SI_UNITS, Conventions, FieldBalanceResult, FieldCorrection, FieldResidual,
    convention_text,
)
from rbcli.api.field.readings import READING_KINDS, READING_UNITS  # noqa: F401  (re-exported)
from rbcli.errors import ParamError, literal

__all__ = ["FieldBalanceOptions", "FieldBalanceResult", "field_balance", "run", "Readings"]

#: readings as the command line takes them: ``"6.0@30"``, ``"170@112,53@78"``, or a sequence
#: of such strings (one per sensor)
Readings: TypeAlias = str | Sequence[str]

#: the core's parameter names -> the options of :func:`field_balance`
_CORE_PARAMS = {"v0": "initial", "v1": "run", "va": "run", "vb": "run", "trial": "trial",
                "trial_a": "trial", "trial_b": "trial", "runs": "run", "trials": "trial",
                "weights": "weights", "method": "method", "mass_step": "mass_step",
                "angle_step": "angle_step", "positions": "positions", "bearing_load": "bearing_load",
                "trial_radius": "trial_radius", "speed": "speed", "trial_fraction": "trial_fraction"}

def _group(value: Any, param: str) -> int | str | None:
    """ISO 20816-3's machine group: 1 or 2, as an int or a string."""
    return check.text(value, param) if value is None or isinstance(value, str) else check.count(value, param)


#: the checker of each keyword argument of :func:`field_balance` (:mod:`rbcli.api.check`)
KINDS = {
    "initial": check.texts(1), "trial": check.texts(1), "run": check.texts(2),
    "cumulative": check.flag, "trial_radius": check.quantity, "radius": check.quantity,
    "job": check.path, "method": check.text, "weights": check.values(check.MAX_ITEMS),
    "mass_step": check.quantity, "angle_step": check.quantity, "positions": check.count,
    "phase": check.text, "angle_sense": check.text, "rotation": check.text,
    "measure": check.text, "severity": check.text, "group": _group, "foundation": check.text,
    "coefficients": check.path, "suggest_trial": check.flag, "rotor_mass": check.quantity,
    "rotor": check.path, "bearing_load": check.quantity, "trial_fraction": check.quantity,
    "speed": check.quantity, "full": check.flag,
}

#: plane names of a command-line job
PLANE_LETTERS = "ABCDEFGHIJKLMNOPQRSTUVWXYZ"


@dataclass(frozen=True)
class TrialRequest:
    """What sizes a trial mass (``suggest_trial``): per plane the static bearing load (N)
    and how it was found, the trial radius (m), the speed (rad/s) and the fraction."""

    loads: tuple[tuple[float, str], ...]
    radii: tuple[float, ...]
    speed: float
    fraction: float


@dataclass(frozen=True)
class FieldBalanceOptions:
    """The options of :func:`field_balance`, read and checked once.

    Attributes
    ----------
    initial : tuple of complex — the readings without trial, N of them (reading unit, in the
        common measure, phases in the sense of the trial angles)
    runs : tuple of tuple of complex — the readings of each trial run
    trials : tuple of complex — trial mass (kg) e^{i angle}, one per plane
    cumulative : bool — every trial was left on for the later runs
    radii : (float, float) | None — m, (trial radius, correction radius), every plane
    reading_kind : str | None — "displacement", "velocity" or "acceleration" (the readings
        are then in m, m/s or m/s²), None for bare readings (a relative scale)
    extended : bool — anything beyond the classic one- or two-plane job (the output then has
        ``method``, ``residuals``...)
    inputs : tuple of str — the files the job reads (job file, coefficients, rotor body): no
        output may replace them
    (the other attributes: see :func:`field_balance`)
    """

    initial: tuple[complex, ...]
    runs: tuple[tuple[complex, ...], ...]
    trials: tuple[complex, ...]
    cumulative: bool = False
    radii: tuple[float, float] | None = None
    reading_kind: str | None = None
    extended: bool = False
    method: str | None = None
    weights: tuple[float, ...] | None = None
    sensors: tuple[str, ...] = ()
    speeds: tuple[tuple[str, float | None], ...] = ()
    plane_names: tuple[str, ...] = ()
    plane_radii: tuple[tuple[float, float] | None, ...] = ()
    positions: tuple[int | None, ...] = ()
    mass_step: float | None = None
    angle_step: float | None = None
    measure: str | None = None
    measures_converted: tuple[tuple[str, str, int], ...] = ()
    gravity: bool = False
    phase: str | None = None
    angle_sense: str | None = None
    rotation: str | None = None
    flipped: bool = False
    severity: tuple[str, int, str] | None = None
    coefficients: tuple[tuple[complex, ...], ...] | None = None
    coefficients_from: str | None = None
    suggest: TrialRequest | None = None
    job: str | None = None
    name: str | None = None
    notes: tuple[str, ...] = field(default=())
    inputs: tuple[str, ...] = ()

    @property
    def planes(self) -> int:
        return len(self.plane_names) if self.plane_names else len(self.trials)

    @property
    def scale(self) -> float:
        """Trial radius / correction radius (1 when no radii are given)."""
        return 1.0 if self.radii is None else self.radii[0] / self.radii[1]

    @classmethod
    def parse(cls, body: None = None, *, initial=None, trial=None, run=None, cumulative: bool = False,
              trial_radius=None, radius=None, job=None, method=None, weights=None, mass_step=None,
              angle_step=None, positions=None, phase=None, angle_sense=None, rotation=None,
              measure=None, severity=None, group=None, foundation=None, coefficients=None,
              suggest_trial: bool = False, rotor_mass=None, rotor=None, bearing_load=None,
              trial_fraction=None, speed=None, full: bool = False) -> FieldBalanceOptions:
        """Read the keyword arguments of :func:`field_balance` (see there).

        Raises
        ------
        rbcli.InputError
            with the message the command line prints (``--trial: ...``), located in the job
            file for a job file's value.
        """
        from rbcli.api.field import job as fieldjobs

        return fieldjobs.parse(cls, initial=initial, trial=trial, run=run, cumulative=cumulative,
                               trial_radius=trial_radius, radius=radius, job=job, method=method,
                               weights=weights, mass_step=mass_step, angle_step=angle_step,
                               positions=positions, phase=phase, angle_sense=angle_sense,
                               rotation=rotation, measure=measure, severity=severity, group=group,
                               foundation=foundation, coefficients=coefficients,
                               suggest_trial=suggest_trial, rotor_mass=rotor_mass, rotor=rotor,
                               bearing_load=bearing_load, trial_fraction=trial_fraction, speed=speed,
                               full=full)


def run(body: None, options: FieldBalanceOptions) -> FieldBalanceResult:
    """Field balancing with ``options`` (``body`` is None: the command needs none).

    Raises
    ------
    rbcli.InputError
        readings that give no influence coefficient or a singular matrix (``run: ...``);
        :class:`rbcli.NonFiniteResult` when the result overflows.
    """
    import numpy as np

    from rbcli.api.result import jsonable
    from rbcli.core import balance as B
    from rbcli.errors import NonFiniteResult

    o = options
    try:
        with np.errstate(all="ignore"):
            try:
                if not o.extended:
                    res = _classic(o)
                else:
                    from rbcli.api.field import compute as fieldsolve

                    res = fieldsolve.solve_job(o)
            except B.BalanceValueError as exc:
                raise ParamError(_CORE_PARAMS.get(exc.param, "run"), literal(exc)) from None
            except np.linalg.LinAlgError as exc:
                raise ParamError("run", literal(exc)) from None
            jsonable(res.to_json())  # the one finiteness check: refuses inf and NaN
    except (OverflowError, ZeroDivisionError, NonFiniteResult):
        raise NonFiniteResult(
            "{initial}, {trial}, {run}: the result overflows (a number beyond 1e308); "
            "the readings or trial masses are too large or too small"
        ) from None
    return res


def _classic(o: FieldBalanceOptions) -> FieldBalanceResult:
    """The one- or two-plane job as rbcli always solved and reported it."""
    from rbcli.core.field.classic import field_single_plane, field_two_plane

    s = o.scale
    if o.planes == 1:
        f = field_single_plane(o.initial[0], o.runs[0][0], o.trials[0])
        return FieldBalanceResult(
            planes=1, initial=o.initial, runs=o.runs,
            corrections=(FieldCorrection("A", f.correction * s, f.correction_trial_on * s,
                                         None if o.radii is None else o.radii[1]),),
            alpha=((f.influence,),), trial_masses=o.trials, radii=o.radii, cond=None,
            det=None, ill_conditioned=False, small_response=(bool(f.small_response),),
            residual_values=(f.predicted_residual,), cumulative=False,
            reading_kind=o.reading_kind, warnings=f.warnings)
    f2 = field_two_plane(o.initial, o.runs[0], o.runs[1], o.trials[0], o.trials[1],
                           cumulative=o.cumulative)
    from rbcli.api.field.compute import significance_warning
    from rbcli.core.field.significance import plane_significance

    sig = plane_significance(f2.influence)  # Darlow's test: a warning when it flags a plane
    warnings = tuple(f2.warnings) + tuple(significance_warning("AB"[j], float(sig.factors[j]))
                                          for j in sig.flagged)
    return FieldBalanceResult(
        planes=2, initial=o.initial, runs=o.runs,
        corrections=tuple(FieldCorrection(name, complex(w) * s, complex(w_on) * s,
                                          None if o.radii is None else o.radii[1])
                          for name, w, w_on in zip("AB", f2.corrections, f2.corrections_trials_on)),
        alpha=tuple(tuple(complex(a) for a in row) for row in f2.influence),
        trial_masses=o.trials, radii=o.radii, cond=float(f2.cond), det=complex(f2.det),
        ill_conditioned=bool(f2.ill_conditioned),
        small_response=tuple(bool(x) for x in f2.small_response),
        residual_values=tuple(complex(v) for v in f2.predicted_residual),
        cumulative=bool(f2.cumulative), reading_kind=o.reading_kind,
        warnings=warnings, significance_factors=tuple(float(x) for x in sig.factors))


_run = run  # field_balance's parameter ``run`` (the readings) hides the function


def field_balance(*, initial: Readings | None = None, trial: Readings | None = None,
                  run: Readings | Sequence[Readings] | None = None, cumulative: bool = False,
                  trial_radius: Quantity | None = None, radius: Quantity | None = None,
                  job: str | os.PathLike[str] | None = None, method: str | None = None,
                  weights: str | Sequence[float] | None = None, mass_step: Quantity | None = None,
                  angle_step: Quantity | None = None, positions: int | None = None,
                  phase: str | None = None, angle_sense: str | None = None,
                  rotation: str | None = None, measure: str | None = None,
                  severity: str | None = None, group: int | str | None = None,
                  foundation: str | None = None,
                  coefficients: str | os.PathLike[str] | None = None, suggest_trial: bool = False,
                  rotor_mass: Quantity | None = None, rotor: str | os.PathLike[str] | None = None,
                  bearing_load: Quantity | None = None, trial_fraction: Quantity | None = None,
                  speed: Quantity | None = None, full: bool = False) -> FieldBalanceResult:
    """Field (trial-weight) balancing from vibration readings: influence coefficients.

    Readings are ``"amplitude@phase"`` strings (phases in degrees from the keyphasor):
    either all bare numbers (``"6.0@30"``: one relative scale, the corrections do not depend
    on it) or all with units of one kind, converted exactly: displacement (``"40 um@30"``,
    µm, mm, mil), velocity (``"6 mm/s@30"``, mm/s, in/s) or acceleration (``"0.5 g@30"``,
    g = standard gravity, m/s²); a measure may follow the unit (``"6 mm/s rms@30"``: pk,
    pk-pk or rms). Trial masses are ``"mass@angle"`` (``"10 g@0"``; a bare mass is in grams,
    as balancing sheets write it).

    Parameters
    ----------
    initial : str or sequence of str
        The readings without trial, one per sensor: ``"6.0@30"`` or ``"170@112,53@78"``
        (N readings for P planes, N >= P).
    trial : str or sequence of str
        The trial mass per plane (P of them).
    run : str or sequence of str
        The N readings with each trial on, in the order of ``trial``.
    cumulative : bool
        Every trial was left on for the later runs.
    trial_radius, radius : float or str, optional
        Radius the trials sat at and the radius the corrections go at, m (together).
    job : str, optional
        A job file (YAML): sensors, planes, speeds, runs (instead of initial, trial, run).
    method : str, optional
        "least-squares" (default when N > P) or "min-max"; "exact" for N = P.
    weights : str or sequence of float, optional
        One weight per reading (least squares and min-max).
    mass_step, angle_step : float or str, optional
        Round the corrections: masses to a multiple of ``mass_step`` (kg, or ``"1 g"``),
        angles to a multiple of ``angle_step`` (degrees).
    positions : int, optional
        Split each correction onto the two neighbouring of N equally spaced positions.
    phase, angle_sense, rotation : str, optional
        "lag" or "lead" (the instrument's phase); "with" or "against" (how the trial and
        correction angles are counted from the mark); "cw" or "ccw" (how the rotor turns,
        seen from where the angles are read).
    measure : str, optional
        "pk", "pk-pk" or "rms": the measure of readings that state none.
    severity, group, foundation : optional
        "iso20816-3", 1 or 2, "rigid" or "flexible": the ISO 20816-3 zone of each reading
        before and predicted after (velocity readings, or displacement and acceleration at a
        known speed).
    coefficients : str, optional
        A file written by ``--save-coefficients``: with ``initial`` alone, a trim run.
    suggest_trial : bool
        Size a trial mass: ``rotor_mass`` (or ``rotor``, a body file) or ``bearing_load``,
        ``speed`` and ``trial_radius``; ``trial_fraction`` (default 10 %).
    speed : float or str, optional
        The balancing speed (rad/s, or ``"1480 rpm"``).
    full : bool
        The extended result (``method``, ``residuals``, significance...) even for a classic
        one- or two-plane job (what a job sheet shows).

    Returns
    -------
    FieldBalanceResult
        ``corrections[i].mass`` kg, ``angle_deg`` in the sense of the trial angles.

    Raises
    ------
    TypeError
        An argument of the wrong type, naming the parameter and the type expected
        (:mod:`rbcli.api.check`).
    rbcli.InputError
        naming the parameter and ``param``.

    Examples
    --------
    >>> import rbcli
    >>> r = rbcli.field_balance(initial="6.0@30", trial="10 g@0", run="4.0@110")
    >>> round(r.corrections[0].mass * 1e3, 2)   # g
    9.08
    """
    kw = check.arguments(
        KINDS, initial=initial, trial=trial, run=run, cumulative=cumulative,
        trial_radius=trial_radius, radius=radius, job=job, method=method, weights=weights,
        mass_step=mass_step, angle_step=angle_step, positions=positions, phase=phase,
        angle_sense=angle_sense, rotation=rotation, measure=measure, severity=severity,
        group=group, foundation=foundation, coefficients=coefficients,
        suggest_trial=suggest_trial, rotor_mass=rotor_mass, rotor=rotor, bearing_load=bearing_load,
        trial_fraction=trial_fraction, speed=speed, full=full)
    with check.arithmetic(kw):
        return _run(None, FieldBalanceOptions.parse(None, **kw))
