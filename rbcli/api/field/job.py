"""A field-balancing job, read once (:func:`make`): from the parameters (a one-speed job:
sensors 1..N, planes A, B, ...) or a job file, whose settings are the parameters' (one given
in both is refused); the readings in one kind and measure, phases in the angles' sense; a
trim run's coefficients (:mod:`.coefficients`), the shop's limits and drawer (:mod:`.shop`),
a trial mass sized (:mod:`.trial`)."""

from __future__ import annotations

import os
from dataclasses import dataclass, replace
from typing import Any

from rbcli.api import options as op
from rbcli.api.field import coefficients, shop, trial
from rbcli.api.field.readings import (
    Reading, at, budget, common_measure, one_kind, read_at, reading, readings, trial_mass,
)
from rbcli.api.load import load
from rbcli.api.params import Options
from rbcli.errors import InputError, Location, ParamError, literal
from rbcli.io.field import plane_names
from rbcli.io.field.jobfile import FieldJob, JobRotor, load_job

__all__ = ["Job", "make"]

#: the parameters a one- or two-plane job may be given with and keep the output rbcli always
#: printed for it (anything else asks for the extended output)
CLASSIC = {"initial", "trial", "run", "cumulative", "trial_radius", "radius", "suggest_trial",
           "rotor_mass", "rotor", "bearing_load", "trial_fraction"}

#: the settings a job file gives as the parameters do: parameter -> the job file's key (a
#: conflict is located there); the value is the job's attribute of that name, but for
#: :data:`PER_ITEM`
SETTINGS = {"cumulative": "cumulative", "weights": "sensors", "positions": "planes",
            "speed": "speeds", "phase": "conventions", "angle_sense": "conventions",
            "rotation": "conventions", "severity": "severity", "coefficients": "coefficients",
            "method": "method", "mass_step": "mass_step", "angle_step": "angle_step",
            "measure": "readings", "max_mass": "planes", "limit": "sensors", "drawer": "drawer",
            "max_weights": "max_weights", "robust": "robust"}
#: settings a job file gives per sensor, plane or speed: the job keeps them (a parameter
#: applies to all)
PER_ITEM = ("weights", "positions", "speed", "max_mass", "limit", "drawer")


@dataclass(frozen=True)
class Job:
    """A job, read and checked: the parameters (with a job file's settings), readings' sensors
    and speeds (reading k: sensor ``k % len(sensors)`` at speed ``k // len(sensors)``), per
    plane name, (trial, correction) radius, positions, place; trials (kg e^{i angle}); readings
    (SI of ``reading_kind`` or bare, in ``measure``, phases in the angles' sense); a trim run's
    ``alpha``; the job file as read (``source``); the shop's ``max_mass``, ``limits``, ``drawer``."""

    options: Options
    sensors: tuple[str, ...]
    speeds: tuple[tuple[str, float | None], ...]
    plane_names: tuple[str, ...]
    plane_radii: tuple[tuple[float, float] | None, ...]
    positions: tuple[int | None, ...]
    plane_at: tuple[float | None, ...]
    trials: tuple[complex, ...]
    name: str | None = None
    rotor: JobRotor | None = None
    radii: tuple[float, float] | None = None
    initial: tuple[complex, ...] = ()
    runs: tuple[tuple[complex, ...], ...] = ()
    reading_kind: str | None = None
    measure: str | None = None
    measures_converted: tuple[tuple[str, str, int], ...] = ()
    gravity: bool = False
    weights: tuple[float, ...] | None = None
    alpha: tuple[tuple[complex, ...], ...] | None = None
    flipped: bool = False
    suggest: trial.TrialRequest | None = None
    notes: tuple[str, ...] = ()
    classic: bool = False
    extended: bool = True
    source: FieldJob | None = None
    max_mass: tuple[tuple[float, str] | None, ...] = ()
    limits: tuple[float, ...] | None = None
    drawer: shop.Drawer | None = None

    @property
    def planes(self) -> int:
        return len(self.plane_names)

    @property
    def severity(self) -> tuple[str, int, str] | None:
        """(standard, group, foundation) of ``severity``, or None."""
        o = self.options
        return None if o.severity is None else (o.severity, int(o.group), o.foundation)

    @property
    def inputs(self) -> tuple[str, ...]:
        """The files the job reads (job file, coefficients, rotor body): no output may
        replace them."""
        o = self.options
        body = self.rotor.body if self.rotor is not None else None
        return tuple(str(x) for x in (o.job, o.coefficients, o.rotor, body) if x is not None)


def make(o: Options) -> Job:
    """The job of the parameters ``o`` (read by :func:`rbcli.api.params.read`).

    Raises
    ------
    rbcli.InputError
        with the message the command line prints (``--trial: ...``), located in the job
        file for a job file's value.
    """
    for param in ("initial", "trial", "run", "trial_radius", "radius") if o.job is not None else ():
        if getattr(o, param) is not None:
            raise ParamError(param, "the job file holds the readings; give the {job} file or the readings on the "
                                    "command line, not both" if param in ("initial", "trial", "run") else
                                    "give the radii in the job file's planes (radius, correction_radius)")
    jf = load_job(str(o.job)) if o.job is not None else None
    try:
        o2 = o if jf is None else _settings(o, jf)
        if (o2.group is not None or o2.foundation is not None) and o2.severity is None:
            raise ParamError("severity", "{group} and {foundation} go with {severity} iso20816-3")
        if o2.severity is not None and (o2.group is None or o2.foundation is None):
            raise ParamError("severity", "needs the machine {group} (1 or 2) and its {foundation} "
                                         "(rigid or flexible)")
        job = from_file(o, jf) if jf is not None else from_options(o)
        if job.options.coefficients is not None:
            job = coefficients.apply(job)
        return shop.read(_finish(job))
    except ParamError as exc:
        raise located(exc, o.given, jf) from None


#: where in a job file a parameter's value comes from (the key a message about it points at)
WHERE = {**SETTINGS, "initial": "initial", "run": "trials", "trial": "trials", "group": "severity",
         "foundation": "severity", "rotor_mass": "rotor", "bearing_load": "rotor", "trial_fraction": "rotor",
         "trial_radius": "planes", "radius": "planes"}


def located(exc: ParamError, given: tuple[str, ...], jf: FieldJob | None) -> InputError:
    """An error about a parameter a job file gave, located at its key there (in the job
    file's words); one about a parameter the caller gave, as it is."""
    if jf is None or exc.param in given:
        return exc
    return at(jf.keys.get(WHERE.get(exc.param, ""), Location(jf.source)), exc)


# --- two sources


def from_options(o: Options) -> Job:
    """The job the parameters describe (one speed)."""
    trials_t, runs_t = _texts(o.trial), _texts(o.run)
    _check_options(o, trials_t, runs_t)
    budget(0 if o.initial is None else ",".join(_texts(o.initial)).count(",") + 1, len(trials_t), None)
    initial = [] if o.initial is None else readings(",".join(_texts(o.initial)), "initial", None)
    n, p = len(initial), len(trials_t)
    _check_counts(o, n, p, len(runs_t))
    runs = [readings(r, "run", n, what="one per sensor, as {initial} has") for r in runs_t]
    with op.naming("trial"):
        trials = tuple(trial_mass(t, "trial") for t in trials_t)
    pair = None if o.trial_radius is None else \
        (o.trial_radius, o.trial_radius if o.radius is None else o.radius)
    # a trial suggestion alone: plane A
    names = plane_names(p) if p or o.coefficients is not None else ("A",)
    job = Job(o, tuple(str(k + 1) for k in range(n)), (("", o.speed),), names,
              (pair,) * len(names), (o.positions,) * len(names), (None,) * p, trials,
              radii=pair if p > 0 else None, weights=_weights(o.weights, n),
              classic=set(o.given) - {"full"} <= CLASSIC and not o.full)
    return _measured(job, initial, runs)


def _texts(v: Any) -> list[str]:
    """One value or several (a run per plane; a run may itself be a sequence of readings)."""
    if v is None:
        return []
    return [v] if isinstance(v, str) else [x if isinstance(x, str) else ",".join(x) for x in v]


def _check_options(o: Options, trials: list[str], runs: list[str]) -> None:
    """What the parameters must say together, before a reading is read."""
    if o.coefficients is not None and (trials or runs):
        raise ParamError("trial", "a trim run from {coefficients} takes the initial readings alone; "
                                  "the trial runs are in the file")
    if o.initial is None and (trials or runs or o.coefficients is not None or not o.suggest_trial):
        raise ParamError("initial", "required: the readings without trial masses, e.g. '6.0@30' or "
                                    "'170@112,53@78' (one per sensor)")


def _check_counts(o: Options, n: int, p: int, runs: int) -> None:
    """Runs, planes and readings that go together."""
    if o.coefficients is None and o.initial is not None:
        if p == 0:
            raise ParamError("trial", "required: one trial mass per plane, e.g. '10 g@0' (or "
                                      "{coefficients} FILE for a trim run)")
        if runs != p:
            raise ParamError("run", f"give one run per trial ({p}), not {runs}")
        if n < p:
            raise ParamError("initial", f"{p} planes need at least {p} readings per run (one per "
                                        f"sensor), got {n} in '{literal(','.join(_texts(o.initial)))}'")
    elif runs and not p:
        raise ParamError("run", "needs its {trial}")
    if o.cumulative and p < 2 and o.coefficients is None:
        raise ParamError("cumulative", "only for two planes or more")
    if (o.trial_radius is None) != (o.radius is None) and o.coefficients is None and p > 0:
        raise InputError("{radius} and {trial_radius} go together (the corrections move from the "
                         "trial radius to {radius})", param="radius")
    if o.trial_radius is not None and o.coefficients is not None:
        raise ParamError("trial_radius", "the coefficients file has the trial radius; give the "
                                         "correction {radius} alone")


def _weights(weights: Any, n: int) -> tuple[float, ...] | None:
    """``weights`` (``"1,2,1"`` or numbers), one per reading."""
    if weights is None:
        return None
    parts = [x.strip() for x in weights.split(",")] if isinstance(weights, str) else \
        list(weights) if isinstance(weights, tuple) else [weights]
    with op.naming("weights"):
        vals = [op.quantity(x, "dimensionless", "weights") for x in parts]
    if len(vals) != n:
        raise ParamError("weights", f"give one weight per reading ({n}), not {len(vals)}")
    if not all(0 < v < float("inf") for v in vals):
        raise ParamError("weights", "weights must be positive finite numbers")
    return tuple(vals)


def from_file(o: Options, job: FieldJob) -> Job:
    """The job the job file ``job`` describes, with the parameters' settings it leaves open."""
    o = _settings(o, job)
    if job.rotor is not None and job.rotor.body is not None:
        _rotor_body(job.rotor, job.source)
    if o.coefficients is not None and job.trials:
        raise ParamError("coefficients", "a trim run takes the initial readings alone; the job file has "
                                         "trial runs")
    budget(sum(len(x) for x in job.initial or ()), len(job.trials) or len(job.planes), Location(job.source))
    initial = [read_at(t, lambda x: reading(x, "initial", t.where)) for s in job.initial or () for t in s]
    runs = [[read_at(t, lambda x: reading(x, "run", t.where)) for s in tr.readings for t in s] for tr in job.trials]
    trials = tuple(read_at(tr.mass, lambda x: trial_mass(x, "trial", job.units.get("mass", "g")))
                   for tr in job.trials)
    p = len(job.planes) if job.planes else len(job.trials)
    n = len(initial)
    if o.coefficients is None and n < p:
        raise InputError(f"{p} planes need at least {p} readings per run (sensors x speeds), got {n}",
                         Location(job.source))
    weights = _weights(o.weights, n) if job.weights is None else \
        tuple(job.weights[k % len(job.sensors)] for k in range(n))
    speeds = tuple((s.name, s.speed) for s in job.speeds)
    names, radii, positions, at = _planes(job, p)
    return _measured(Job(
        o, job.sensors, speeds if o.speed is None else ((speeds[0][0], o.speed),), names, radii,
        positions if o.positions is None else (o.positions,) * p, at, trials, name=job.name,
        rotor=job.rotor, weights=weights, source=job), initial, runs)


def _planes(job: Any, p: int) -> tuple[tuple, tuple, tuple, tuple]:
    """The names, (trial, correction) radii, positions and places of the job file's ``p``
    planes (named by its trial runs when it lists none)."""
    if not job.planes:
        return tuple(tr.plane for tr in job.trials), (None,) * p, (None,) * p, (None,) * p
    radii = tuple(None if pl.radius is None else
                  (pl.radius, pl.radius if pl.correction_radius is None else pl.correction_radius)
                  for pl in job.planes)
    return (tuple(pl.name for pl in job.planes), radii, tuple(pl.positions for pl in job.planes),
            tuple(pl.at for pl in job.planes))


def _settings(o: Options, job: Any) -> Options:
    """The parameters ``o`` with the settings of the job file ``job``; one given in both is
    refused (located at the job file's key)."""
    theirs = {name: getattr(job, name, None) for name in SETTINGS}
    theirs.update(positions=next((pl.positions for pl in job.planes if pl.positions is not None), None),
                  speed=next((s.speed for s in job.speeds if s.speed is not None), None),
                  max_mass=next((pl.max_mass for pl in job.planes if pl.max_mass is not None), None),
                  limit=next((x for x in job.limits + tuple(s.limit for s in job.speeds) if x), None))
    for name, key in SETTINGS.items():
        mine = getattr(o, name)
        if theirs[name] is not None and mine is not None and mine is not False:
            raise ParamError(name, f"given twice: on the command line and in the job file "
                                   f"({literal(job.keys.get(key, Location(job.source)))}); give it once")
    if o.speed is not None and len(job.speeds) > 1:
        raise ParamError("speed", "the job has several speeds: give each its speed in the job file")
    if job.severity is not None:
        theirs.update(zip(("severity", "group", "foundation"), job.severity))
    return o.replace(**{k: v for k, v in theirs.items() if v is not None and k not in PER_ITEM})


def _rotor_body(rotor: JobRotor, source: str) -> None:
    """The job's rotor body file, loaded when the job is read (not only to size a trial)."""
    if os.path.realpath(rotor.body) == os.path.realpath(source):
        raise InputError("rotor: body is the job file itself; give the rotor's body file", rotor.where)
    try:
        load(rotor.body)
    except InputError as exc:
        if exc.where is not None and exc.where.line > 0:
            raise  # located in the body file
        raise InputError(f"rotor: body: {literal(exc.message)}", rotor.where) from None


# --- one job


def _measured(job: Job, initial: list[Reading], runs: list[list[Reading]]) -> Job:
    """``job`` with its readings: all of one kind, in one measure (r.m.s. for the severity
    zones)."""
    every = initial + [r for run in runs for r in run]
    if not every:  # a trial mass sized before the first run
        return job
    kind = one_kind(every)
    o = job.options
    values, measures = common_measure(every, o.measure, "rms" if o.severity is not None else None)
    it = iter(values)
    return replace(job, initial=tuple(next(it) for _ in initial),
                   runs=tuple(tuple(next(it) for _ in run) for run in runs),
                   reading_kind=kind, gravity=any(r.gravity for r in every),
                   measure=measures.measure, measures_converted=measures.converted)


def _finish(job: Job) -> Job:
    """The phases in the angles' sense, the severity's needs checked, the trial request."""
    o = job.options
    if o.phase is not None and o.angle_sense is None:
        raise ParamError("angle_sense", "say how the trial and correction angles are counted from the mark "
                                        "(with or against the rotation): the phases ({phase}) are converted "
                                        "to the angles' sense")
    flipped = (o.phase, o.angle_sense) in (("lag", "with"), ("lead", "against"))
    if flipped:
        job = replace(job, initial=tuple(v.conjugate() for v in job.initial),
                      runs=tuple(tuple(v.conjugate() for v in run) for run in job.runs))
    if o.severity is not None:
        _check_severity(job)
    n, p = len(job.initial), job.planes
    classic = (job.classic and p in (1, 2) and n == p and len(job.speeds) == 1 and job.measure is None
               and not job.gravity and job.alpha is None and not o.suggest_trial)
    return replace(job, flipped=flipped, extended=not classic,
                   suggest=trial.request(job) if o.suggest_trial else None)


def _check_severity(job: Job) -> None:
    """Readings the ISO 20816-3 zones can judge: with units, a measure, and a speed for a
    displacement or an acceleration."""
    kind = job.reading_kind
    if kind is None:
        raise ParamError("severity", "the ISO 20816-3 zones judge velocities (mm/s r.m.s.): give the "
                                     "readings with units (mm/s, in/s; or displacement or acceleration "
                                     "at a known speed), not bare numbers")
    if job.measure is None:
        raise ParamError("measure", "the ISO 20816-3 zones are in r.m.s.: say the readings' measure "
                                    "(pk, pk-pk or rms) in each reading or with {measure}")
    if kind != "velocity" and any(w is None for _, w in job.speeds):
        raise ParamError("speed", f"the readings are {kind}s: the ISO 20816-3 zones judge velocities, "
                                  f"so give the speed ({{speed}}) to convert them (v = omega x for the "
                                  "1x reading)")
