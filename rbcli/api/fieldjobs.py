"""Reading a field-balancing job once: :meth:`FieldBalanceOptions.parse`'s work.

A job comes either from keyword arguments (the command line: ``initial``, ``trial``,
``run`` — a one-speed job whose sensors are numbered 1..N and planes lettered A, B, ...)
or from a job file (:func:`rbcli.io.fieldjob.load_job`), never both; the other settings
(method, weights, rounding, conventions, measure, severity, coefficients, speed) may come
from either, but not from both. Every reading is read by :mod:`rbcli.api.fieldreadings`;
then all of them are of one kind, converted to one measure, and their phases brought into
the sense of the trial angles; stored coefficients are checked against the job and
converted the same way.
"""

from __future__ import annotations

from typing import Any

from rbcli.api import fieldreadings as fr
from rbcli.api import options as op
from rbcli.errors import InputError, Location, ParamError, literal
from rbcli.io.fieldjob import CHOICES

__all__ = ["parse", "PLANE_LETTERS"]

PLANE_LETTERS = "ABCDEFGHIJKLMNOPQRSTUVWXYZ"


def _choice(value: Any, param: str, key: str | None = None) -> str | None:
    if value is None:
        return None
    allowed = CHOICES[key or param]
    if not isinstance(value, str) or value not in allowed:
        ways = ", ".join(allowed[:-1]) + (" or " if len(allowed) > 1 else "") + allowed[-1]
        raise ParamError(param, f"must be {ways}, not '{literal(value)}'")
    return value


def _twice(param: str, where: Location) -> ParamError:
    return ParamError(param, f"given twice: on the command line and in the job file ({literal(where)}); give it once")


def _job_value(job: Any, attr: str, key: str, value: Any, param: str) -> Any:
    """The command line's ``value`` or the job file's ``attr``, never both."""
    jv = getattr(job, attr)
    if value is not None and value is not False and jv is not None:
        raise _twice(param, job.keys.get(key, Location(job.source)))
    return jv if jv is not None else value


def parse(cls: type, *, initial, trial, run, cumulative, trial_radius, radius, job, method, weights,
          mass_step, angle_step, positions, phase, angle_sense, rotation, measure, severity, group,
          foundation, coefficients, suggest_trial, rotor_mass, rotor, bearing_load, trial_fraction,
          speed, full=False) -> Any:
    method = _choice(method, "method")
    phase = _choice(phase, "phase")
    angle_sense = _choice(angle_sense, "angle_sense")
    rotation = _choice(rotation, "rotation")
    measure = _choice(measure, "measure")
    if severity is not None:
        _choice(severity, "severity", "standard")
    if (group is not None or foundation is not None) and severity is None:
        raise ParamError("severity", "{group} and {foundation} go with {severity} iso20816-3")
    sev = None
    if severity is not None:
        if group is None or foundation is None:
            raise ParamError("severity", "needs the machine {group} (1 or 2) and its {foundation} (rigid or flexible)")
        try:
            g = int(group)
        except (TypeError, ValueError):
            g = -1
        if g not in (1, 2) or str(group).strip() not in ("1", "2"):
            raise ParamError("group", f"must be 1 (large machines, above 300 kW) or 2 (15 kW to 300 kW), "
                                      f"not '{literal(group)}'")
        sev = ("iso20816-3", g, _choice(foundation, "foundation"))
    omega = None
    if speed is not None:
        with op.naming("speed"):
            omega = op.positive(op.quantity(speed, "angular_speed", "speed"), "speed", "the speed", "rad/s")
    step_m = None
    if mass_step is not None:
        with op.naming("mass_step"):
            step_m = op.positive(op.quantity(mass_step, "mass", "mass_step", bare="kg"), "mass_step",
                                 "the mass step", "kg")
    step_a = None
    if angle_step is not None:
        with op.naming("angle_step"):
            step_a = op.positive(op.degrees(angle_step, "angle_step"), "angle_step", "the angle step", "deg")
        if step_a > 360.0:
            raise ParamError("angle_step", "must not exceed 360 degrees")
    npos = None
    if positions is not None:
        if isinstance(positions, bool) or not isinstance(positions, int) or not 3 <= positions <= 100_000:
            raise ParamError("positions", f"must be a whole number from 3 to 100000 (holes or blades), "
                                          f"not {literal(positions)}")
        npos = int(positions)

    if job is not None:
        spec = _from_job(job, initial=initial, trial=trial, run=run, cumulative=cumulative,
                         trial_radius=trial_radius, radius=radius, method=method, weights=weights,
                         mass_step=step_m, angle_step=step_a, positions=npos, phase=phase,
                         angle_sense=angle_sense, rotation=rotation, measure=measure, severity=sev,
                         coefficients=coefficients, speed=omega)
    else:
        spec = _from_options(initial=initial, trial=trial, run=run, cumulative=cumulative,
                             trial_radius=trial_radius, radius=radius, method=method, weights=weights,
                             mass_step=step_m, angle_step=step_a, positions=npos, phase=phase,
                             angle_sense=angle_sense, rotation=rotation, measure=measure, severity=sev,
                             coefficients=coefficients, speed=omega, suggest=bool(suggest_trial))
    if full:
        spec["classic_options"] = False
    return _finish(cls, spec, suggest=bool(suggest_trial), rotor_mass=rotor_mass, rotor=rotor,
                   bearing_load=bearing_load, trial_fraction=trial_fraction)


# ----------------------------------------------------------------------------- two sources


def _from_options(*, initial, trial, run, cumulative, trial_radius, radius, method, weights, mass_step,
                  angle_step, positions, phase, angle_sense, rotation, measure, severity, coefficients,
                  speed, suggest) -> dict:
    """The job the keyword arguments describe (one speed)."""
    trials_t = _texts(trial, "trial") if trial is not None else []
    runs_t = _texts(run, "run") if run is not None else []
    if coefficients is not None and (trials_t or runs_t):
        raise ParamError("trial", "a trim run from {coefficients} takes the initial readings alone; "
                                  "the trial runs are in the file")
    if initial is None:
        if trials_t or runs_t or coefficients is not None or not suggest:
            raise ParamError("initial", "required: the readings without trial masses, e.g. '6.0@30' or "
                                        "'170@112,53@78' (one per sensor)")
        readings0: list[fr.Reading] = []
    else:
        if not isinstance(initial, str):
            initial = ",".join(_texts(initial, "initial"))
        readings0 = fr.readings(initial, "initial", None)
    n = len(readings0)
    p = len(trials_t)
    if coefficients is None and initial is not None:
        if p == 0:
            raise ParamError("trial", "required: one trial mass per plane, e.g. '10 g@0' (or "
                                      "{coefficients} FILE for a trim run)")
        if len(runs_t) != p:
            raise ParamError("run", f"give one run per trial ({p}), not {len(runs_t)}")
        if n < p:
            raise ParamError("initial", f"{p} planes need at least {p} readings per run (one per "
                                        f"sensor), got {n} in '{literal(initial)}'")
    elif runs_t and not trials_t:
        raise ParamError("run", "needs its {trial}")
    if cumulative and p < 2 and coefficients is None:
        raise ParamError("cumulative", "only for two planes or more")
    if (trial_radius is None) != (radius is None) and coefficients is None and p > 0:
        raise InputError("{radius} and {trial_radius} go together (the corrections move from the "
                         "trial radius to {radius})", param="radius")
    if trial_radius is not None and coefficients is not None:
        raise ParamError("trial_radius", "the coefficients file has the trial radius; give the "
                                         "correction {radius} alone")
    rt = rc = None
    if trial_radius is not None:
        with op.naming("trial_radius"):
            rt = op.positive(op.quantity(trial_radius, "length", "trial_radius"), "trial_radius",
                             "the trial radius", "m")
    if radius is not None:
        with op.naming("radius"):
            rc = op.positive(op.quantity(radius, "length", "radius"), "radius", "the correction radius", "m")
    runs = [fr.readings(r, "run", n, what="one per sensor, as {initial} has") for r in runs_t]
    with op.naming("trial"):
        trials = [fr.trial(t, "trial") for t in trials_t]
    w = None
    if weights is not None:
        w = _weights(weights, n)
    names = [PLANE_LETTERS[j] if j < 26 else str(j + 1) for j in range(p)]
    pair = None if rt is None else (rt, rc if rc is not None else rt)
    if p == 0 and coefficients is None:  # a trial suggestion alone: one plane
        names = ["A"]
    return dict(
        job=None, name=None, sensors=[str(k + 1) for k in range(n)], speeds=[("", speed)],
        plane_names=names, plane_radii=[pair] * len(names), radii=pair if p > 0 else None,
        correction_radius=rc, positions=[positions] * len(names), positions_all=positions, initial=readings0, runs=runs, trials=trials,
        cumulative=bool(cumulative), method=method, weights=w, mass_step=mass_step,
        angle_step=angle_step, phase=phase, angle_sense=angle_sense, rotation=rotation,
        measure=measure, severity=severity, coefficients=coefficients, rotor=None, plane_at=[None] * p,
        classic_options=all(v is None for v in (method, weights, mass_step, angle_step, positions, phase,
                                                 angle_sense, rotation, measure, severity, coefficients,
                                                 speed)),
    )


def _texts(v: Any, param: str) -> list[str]:
    """One value or several (a run per plane); a run may itself be a list of readings."""
    if isinstance(v, str):
        return [v]
    if isinstance(v, (list, tuple)):
        return [x if isinstance(x, str) else ",".join(str(y) for y in x) if isinstance(x, (list, tuple))
                else str(x) for x in v]
    raise TypeError(f"{param}: expected a string or a list of strings, got {type(v).__name__}")


def _weights(weights: Any, n: int) -> list[float]:
    if isinstance(weights, str):
        parts = [x.strip() for x in weights.split(",")]
    else:
        parts = list(weights) if isinstance(weights, (list, tuple)) else [weights]
    with op.naming("weights"):
        vals = [op.quantity(x, "dimensionless", "weights") for x in parts]
    if len(vals) != n:
        raise ParamError("weights", f"give one weight per reading ({n}), not {len(vals)}")
    if not all(v > 0 and v < float("inf") for v in vals):
        raise ParamError("weights", "weights must be positive finite numbers")
    return vals


def _from_job(path: Any, *, initial, trial, run, cumulative, trial_radius, radius, method, weights,
              mass_step, angle_step, positions, phase, angle_sense, rotation, measure, severity,
              coefficients, speed) -> dict:
    """The job a job file describes, with the command line's settings that it leaves open."""
    from rbcli.io.fieldjob import load_job

    for value, param in ((initial, "initial"), (trial, "trial"), (run, "run")):
        if value is not None:
            raise ParamError(param, "the job file holds the readings; give the {job} file or the "
                                    "readings on the command line, not both")
    for value, param in ((trial_radius, "trial_radius"), (radius, "radius")):
        if value is not None:
            raise ParamError(param, "give the radii in the job file's planes (radius, correction_radius)")
    job = load_job(str(path))
    if cumulative and job.cumulative is not None:
        raise _twice("cumulative", job.keys["cumulative"])
    if weights is not None and job.weights is not None:
        raise _twice("weights", job.keys["sensors"])
    if positions is not None and any(p.positions is not None for p in job.planes):
        raise _twice("positions", job.keys["planes"])
    if speed is not None and any(s.speed is not None for s in job.speeds):
        raise _twice("speed", job.keys["speeds"])
    if speed is not None and len(job.speeds) > 1:
        raise ParamError("speed", "the job has several speeds: give each its speed in the job file")
    conv = {}
    for attr, value in (("phase", phase), ("angle_sense", angle_sense), ("rotation", rotation)):
        conv[attr] = _job_value(job, attr, "conventions", value, attr)
    s_sev = _job_value(job, "severity", "severity", severity, "severity")
    coeff = _job_value(job, "coefficients", "coefficients", coefficients, "coefficients")
    if coeff is not None and job.trials:
        raise ParamError("coefficients", "a trim run takes the initial readings alone; the job file has "
                                         "trial runs")
    units_mass = job.units.get("mass", "g")
    initial_r: list[fr.Reading] = []
    if job.initial is not None:
        for per_speed in job.initial:
            for t in per_speed:
                initial_r.append(_reading(t, "initial"))
    runs = []
    trials = []
    for tr in job.trials:
        runs.append([_reading(t, "run") for per_speed in tr.readings for t in per_speed])
        try:
            trials.append(fr.trial(tr.mass.text, "trial", bare=units_mass))
        except InputError as exc:
            raise fr.at(tr.mass.where, exc) from None
    p = len(job.planes) if job.planes else len(job.trials)
    n = len(initial_r)
    if coeff is None and n < p:
        raise InputError(f"{p} planes need at least {p} readings per run (sensors x speeds), got {n}",
                         Location(job.source))
    names = [pl.name for pl in job.planes] or [tr.plane for tr in job.trials]
    radii = []
    for pl in job.planes or ():
        if pl.radius is None:
            radii.append(None)
        else:
            radii.append((pl.radius, pl.correction_radius if pl.correction_radius is not None else pl.radius))
    if not job.planes:
        radii = [None] * p
    w = None
    if job.weights is not None:
        w = [job.weights[k % len(job.sensors)] for k in range(n)]
    elif weights is not None:
        w = _weights(weights, n)
    speeds = [(s.name, s.speed) for s in job.speeds]
    if speed is not None:
        speeds = [(speeds[0][0], speed)]
    pos = [pl.positions for pl in job.planes] if job.planes else [None] * p
    if positions is not None:
        pos = [positions] * p
    return dict(
        job=job.source, name=job.name, sensors=list(job.sensors), speeds=speeds, plane_names=names,
        plane_radii=radii, radii=None, correction_radius=None, positions=pos, initial=initial_r,
        runs=runs, trials=trials, cumulative=bool(job.cumulative if job.cumulative is not None else cumulative),
        method=_job_value(job, "method", "method", method, "method"), weights=w,
        mass_step=_job_value(job, "mass_step", "mass_step", mass_step, "mass_step"),
        angle_step=_job_value(job, "angle_step", "angle_step", angle_step, "angle_step"),
        phase=conv["phase"], angle_sense=conv["angle_sense"], rotation=conv["rotation"],
        measure=_job_value(job, "measure", "readings", measure, "measure"), severity=s_sev,
        coefficients=coeff, rotor=job.rotor, positions_all=None,
        plane_at=[pl.at for pl in job.planes] if job.planes else [None] * p, classic_options=False,
        job_where=Location(job.source),
    )


def _reading(t: Any, param: str) -> fr.Reading:
    try:
        return fr.reading(t.text, param, t.where)
    except InputError as exc:
        raise fr.at(t.where, exc) from None


# ----------------------------------------------------------------------------- one job


def _finish(cls: type, s: dict, *, suggest: bool, rotor_mass, rotor, bearing_load, trial_fraction) -> Any:
    every = list(s["initial"]) + [r for run in s["runs"] for r in run]
    kind = fr.one_kind(every) if every else None
    gravity = any(r.gravity for r in every)
    stated_measure = any(r.measure is not None for r in every)
    sev = s["severity"]
    values, meas = fr.common_measure(every, s["measure"], "rms" if sev is not None else None) if every else ([], fr.Measures(None, ()))
    phase, sense, rotation = s["phase"], s["angle_sense"], s["rotation"]
    notes: list[str] = []
    coeffs = None
    coeff_from = None
    n = len(s["initial"])
    if s["coefficients"] is not None:
        coeffs, coeff_from, phase, sense, rotation, measure, s = _coefficients(
            s, kind, meas.measure, phase, sense, rotation, n, notes)
        meas = fr.Measures(measure, meas.converted)
    if phase is not None and sense is None:
        raise ParamError("angle_sense", "say how the trial and correction angles are counted from the mark "
                                        "(with or against the rotation): the phases ({phase}) are converted "
                                        "to the angles' sense")
    flipped = (phase == "lag" and sense == "with") or (phase == "lead" and sense == "against")
    if flipped:
        values = [v.conjugate() for v in values]
    init = tuple(values[:n])
    runs = []
    k = n
    for run in s["runs"]:
        runs.append(tuple(values[k:k + len(run)]))
        k += len(run)
    p = len(s["plane_names"])
    if sev is not None:
        if kind is None:
            raise ParamError("severity", "the ISO 20816-3 zones judge velocities (mm/s r.m.s.): give the "
                                         "readings with units (mm/s, in/s; or displacement or acceleration "
                                         "at a known speed), not bare numbers")
        if meas.measure is None:
            raise ParamError("measure", "the ISO 20816-3 zones are in r.m.s.: say the readings' measure "
                                        "(pk, pk-pk or rms) in each reading or with {measure}")
        if kind != "velocity" and any(w is None for _, w in s["speeds"]):
            raise ParamError("speed", f"the readings are {kind}s: the ISO 20816-3 zones judge velocities, "
                                      f"so give the speed ({{speed}}) to convert them (v = omega x for the "
                                      "1x reading)")
    suggestion = None
    if suggest:
        suggestion = _suggest(s, rotor_mass=rotor_mass, rotor=rotor, bearing_load=bearing_load,
                              trial_fraction=trial_fraction)
    n_planes_ok = p in (1, 2) and n == p and len(s["speeds"]) == 1
    extended = not (s["classic_options"] and n_planes_ok and not stated_measure and not gravity
                    and coeffs is None and not suggest)
    radii = s["radii"]
    jr = s.get("rotor")
    inputs = tuple(str(x) for x in (s["job"], s["coefficients"], rotor,
                                    jr.body if jr is not None else None) if x is not None)
    return cls(
        initial=init, runs=tuple(runs), trials=tuple(s["trials"]), cumulative=s["cumulative"],
        radii=radii, reading_kind=kind, extended=extended, method=s["method"],
        weights=None if s["weights"] is None else tuple(s["weights"]), sensors=tuple(s["sensors"]),
        speeds=tuple(s["speeds"]), plane_names=tuple(s["plane_names"]),
        plane_radii=tuple(s["plane_radii"]), positions=tuple(s["positions"]),
        mass_step=s["mass_step"], angle_step=s["angle_step"], measure=meas.measure,
        measures_converted=meas.converted, gravity=gravity, phase=phase, angle_sense=sense,
        rotation=rotation, flipped=flipped, severity=sev, coefficients=coeffs,
        coefficients_from=coeff_from, suggest=suggestion, job=s["job"], name=s["name"],
        notes=tuple(notes), inputs=inputs,
    )


def _coefficients(s: dict, kind: str | None, measure: str | None, phase, sense, rotation, n: int,
                  notes: list[str]):
    """Stored coefficients for this job: checked and brought into its units and senses."""
    from rbcli.core.balance.severity import convert_measure
    from rbcli.io.fieldcoeffs import load_coefficients

    path = str(s["coefficients"])
    with op.naming("coefficients"):
        c = load_coefficients(path)
    where = path
    if len(c.rows) != n:
        raise ParamError("coefficients", f"'{literal(where)}' holds {len(c.rows)} readings per run "
                                         f"({len(c.sensors)} sensors x {len(c.speeds)} speeds); the "
                                         f"initial readings are {n}")
    job_speeds = list(s["speeds"])
    if s["job"] is not None:
        if list(c.sensors) != list(s["sensors"]):
            raise ParamError("coefficients", f"'{literal(where)}' is for sensors "
                                             f"{literal(', '.join(c.sensors))}, not {literal(', '.join(s['sensors']))}")
        if len(c.speeds) != len(job_speeds):
            raise ParamError("coefficients", f"'{literal(where)}' is for {len(c.speeds)} speeds, the job has "
                                             f"{len(job_speeds)}")
    else:  # the command line: the readings in the file's order, its sensors and speeds
        if len(c.speeds) > 1 and job_speeds[0][1] is not None:
            raise ParamError("speed", f"'{literal(where)}' holds {len(c.speeds)} speeds; the readings are "
                                      "at those (leave out {speed})")
        job_speeds = [(n, job_speeds[0][1] if len(c.speeds) == 1 else None) for n, _ in c.speeds]
        s = dict(s, sensors=list(c.sensors))
    speeds = []
    for (cn, cw), (jn, jw) in zip(c.speeds, job_speeds):
        if cw is not None and jw is not None and abs(cw - jw) > 1e-9 * cw:
            raise ParamError("coefficients", f"'{literal(where)}' was measured at {cw:.6g} rad/s, this job "
                                             f"runs at {jw:.6g} rad/s: influence coefficients change with "
                                             "speed")
        speeds.append((jn or cn, jw if jw is not None else cw))
    if (c.reading_kind is None) != (kind is None) or (c.reading_kind != kind):
        raise ParamError("coefficients", f"'{literal(where)}' holds coefficients for "
                                         f"{c.reading_kind or 'bare'} readings; these readings are "
                                         f"{kind or 'bare'}")
    alpha = [list(row) for row in c.coefficients]
    if c.measure is not None and measure is not None and c.measure != measure:
        f = convert_measure(1.0, c.measure, measure)
        alpha = [[a * f for a in row] for row in alpha]
        notes.append(f"coefficients converted from {c.measure} to {measure}")
    elif c.measure is not None and measure is None:
        measure = c.measure
        notes.append(f"the readings, which say no measure, taken as {c.measure} (the coefficients file's)")
    elif c.measure is None and measure is not None:
        raise ParamError("coefficients", f"'{literal(where)}' does not say its readings' measure; these "
                                         f"are {measure}: leave the measure unsaid, as it was")
    # conventions: the job's own, or the file's when the job says none
    if phase is None and sense is None and rotation is None:
        phase, sense, rotation = c.phase, c.angle_sense, c.rotation
        if phase or sense or rotation:
            notes.append("conventions from the coefficients file")
    elif c.angle_sense is None and (sense is not None or phase is not None):
        raise ParamError("coefficients", f"'{literal(where)}' does not say its conventions; this job "
                                         "does: balance it with the conventions unsaid, as they were")
    elif c.angle_sense is not None and sense is not None and c.angle_sense != sense:
        alpha = [[a.conjugate() for a in row] for row in alpha]
        notes.append("coefficients mirrored into this job's angle sense")
    planes = [name for name, _ in c.planes]
    rc = s.get("correction_radius")
    radii = []
    for name, rt in c.planes:
        if rt is None:
            if rc is not None:
                raise ParamError("radius", f"'{literal(where)}' has no trial radius for plane "
                                           f"{literal(name)}: the corrections stay at the trial radius")
            radii.append(None)
        else:
            radii.append((rt, rc if rc is not None else rt))
    s = dict(s)
    s.update(plane_names=planes, plane_radii=radii, speeds=speeds,
             radii=(c.planes[0][1], rc if rc is not None else c.planes[0][1]) if (
                 c.planes[0][1] is not None and len({r for _, r in c.planes}) == 1) else None,
             positions=[s["positions_all"]] * len(planes) if s["job"] is None else (
                 list(s["positions"]) + [None] * len(planes))[:len(planes)],
             plane_at=(list(s["plane_at"]) + [None] * len(planes))[:len(planes)],
             cumulative=False)
    return tuple(tuple(row) for row in alpha), path, phase, sense, rotation, measure, s


def _suggest(s: dict, *, rotor_mass, rotor, bearing_load, trial_fraction) -> Any:
    """What sizes the trial masses (see :func:`rbcli.core.balance.fieldfit.suggest_trial`)."""
    from rbcli.api.fieldbalance import TrialRequest
    from rbcli.core.balance.common import STANDARD_GRAVITY
    from rbcli.core.balance.fieldfit import TRIAL_FRACTION, static_bearing_loads

    speeds = [w for _, w in s["speeds"] if w is not None]
    if not speeds:
        raise ParamError("speed", "the trial mass needs the balancing speed, e.g. '1480 rpm'")
    omega = max(speeds)
    jr = s.get("rotor")
    p = max(len(s["plane_names"]), 1)
    radii = []
    for j in range(p):
        rr = s["plane_radii"][j] if j < len(s["plane_radii"]) else None
        if rr is None:
            raise ParamError("trial_radius", "the trial mass needs the radius it sits at ({trial_radius}, or "
                                             "each plane's radius in the job file)")
        radii.append(rr[0])
    frac = TRIAL_FRACTION
    if trial_fraction is not None or (jr is not None and jr.trial_fraction is not None):
        if trial_fraction is not None and jr is not None and jr.trial_fraction is not None:
            raise ParamError("trial_fraction", "given twice: on the command line and in the job's rotor")
        if trial_fraction is not None:
            text = trial_fraction.strip() if isinstance(trial_fraction, str) else trial_fraction
            with op.naming("trial_fraction"):
                if isinstance(text, str) and text.endswith("%"):
                    frac = op.quantity(text[:-1].strip(), "dimensionless", "trial_fraction") / 100.0
                else:
                    frac = op.quantity(text, "dimensionless", "trial_fraction")
        else:
            frac = jr.trial_fraction
    given = [x for x in (rotor_mass, rotor, bearing_load) if x is not None]
    if jr is not None and given:
        raise ParamError("rotor_mass", "the job file has the rotor; give it once")
    if len(given) > 1:
        raise ParamError("rotor_mass", "give the rotor's mass, its body file ({rotor}) or the "
                                       "{bearing_load}, one of them")
    g = STANDARD_GRAVITY if jr is None or jr.g is None else jr.g
    loads: list[tuple[float, str]] = []
    if bearing_load is not None or (jr is not None and jr.bearing_load is not None):
        if bearing_load is not None:
            with op.naming("bearing_load"):
                F = op.positive(op.quantity(bearing_load, "force", "bearing_load"), "bearing_load",
                                "the bearing load", "N")
        else:
            F = jr.bearing_load
        loads = [(F, "the static bearing load given")] * p
    else:
        mass = None
        com = None
        if rotor_mass is not None:
            with op.naming("rotor_mass"):
                mass = op.positive(op.quantity(rotor_mass, "mass", "rotor_mass", bare="kg"),
                                   "rotor_mass", "the rotor's mass", "kg")
        elif rotor is not None or (jr is not None and jr.body is not None):
            from rbcli.core.inertia import body_mass_props
            from rbcli.body.model import load_body

            mp = body_mass_props(load_body(str(rotor if rotor is not None else jr.body)))
            mass, com = float(mp.mass), float(mp.com[2])
        elif jr is not None and jr.mass is not None:
            mass = jr.mass
        else:
            raise ParamError("rotor_mass", "the trial mass needs the rotor's mass ({rotor_mass}, or a body "
                                           "file {rotor}) or the static {bearing_load}")
        if jr is not None and jr.com is not None:
            com = jr.com
        if jr is not None and jr.bearings is not None and com is not None:
            F1, F2 = static_bearing_loads(mass, g, com, jr.bearings)
            for j in range(p):
                z = s["plane_at"][j] if j < len(s["plane_at"]) else None
                if z is None:
                    b = 0 if F1 >= F2 else 1
                    why = "the larger static bearing load (the plane's position is not given)"
                else:
                    b = 0 if abs(z - jr.bearings[0]) <= abs(z - jr.bearings[1]) else 1
                    why = f"the static load of bearing {b + 1}, nearest the plane (lever rule)"
                F = (F1, F2)[b]
                if not F > 0:
                    raise ParamError("rotor_mass", f"bearing {b + 1} carries no static load ({F:.4g} N: "
                                                   "the rotor hangs beyond it); give the {bearing_load}")
                loads.append((F, why))
        else:
            loads = [(mass * g / 2.0, "half the rotor's weight (two bearings sharing it equally)")] * p
    return TrialRequest(tuple(loads), tuple(radii), omega, frac)
