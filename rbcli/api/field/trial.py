"""A trial mass to start with (``suggest_trial``): what sizes it — the static load on the
bearing nearest each plane, from the parameters or the job file's rotor (:func:`request`) —
and the suggestion per plane (:func:`suggestions`, by :func:`rbcli.core.field.trial.suggest_trial`),
with the change it should make where influence coefficients are known.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from rbcli.api.field.result import SuggestedTrial
from rbcli.api.load import load
from rbcli.core.balance.common import STANDARD_GRAVITY
from rbcli.core.field.trial import TRIAL_FRACTION, static_bearing_loads, suggest_trial
from rbcli.core.inertia import body_mass_props
from rbcli.errors import ParamError

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.api.field.job import Job

__all__ = ["TrialRequest", "request", "suggestions"]


@dataclass(frozen=True)
class TrialRequest:
    """What sizes a trial mass: per plane the static bearing load (N) and how it was found,
    the trial radius (m), the speed (rad/s) and the fraction."""

    loads: tuple[tuple[float, str], ...]
    radii: tuple[float, ...]
    speed: float
    fraction: float


def request(job: Job) -> TrialRequest:
    """What sizes the trial masses of ``job`` (the highest of its speeds).

    Raises
    ------
    rbcli.InputError
        no speed, no trial radius, no rotor, or a rotor given twice.
    """
    speeds = [w for _, w in job.speeds if w is not None]
    if not speeds:
        raise ParamError("speed", "the trial mass needs the balancing speed, e.g. '1480 rpm'")
    p = max(job.planes, 1)
    radii = [job.plane_radii[j] if j < len(job.plane_radii) else None for j in range(p)]
    if None in radii:
        raise ParamError("trial_radius", "the trial mass needs the radius it sits at ({trial_radius}, or "
                                         "each plane's radius in the job file)")
    fraction = _fraction(job)
    return TrialRequest(_loads(job, p), tuple(r[0] for r in radii), max(speeds), fraction)


def _fraction(job: Job) -> float:
    mine, rotor = job.options.trial_fraction, job.rotor
    theirs = None if rotor is None else rotor.trial_fraction
    if mine is not None and theirs is not None:
        raise ParamError("trial_fraction", "given twice: on the command line and in the job's rotor")
    return mine if mine is not None else theirs if theirs is not None else TRIAL_FRACTION


def _loads(job: Job, p: int) -> tuple[tuple[float, str], ...]:
    """The static load on the bearing nearest each of the ``p`` planes, and how it was found."""
    o, jr = job.options, job.rotor
    given = [x for x in (o.rotor_mass, o.rotor, o.bearing_load) if x is not None]
    if jr is not None and given:
        raise ParamError("rotor_mass", "the job file has the rotor; give it once")
    if len(given) > 1:
        raise ParamError("rotor_mass", "give the rotor's mass, its body file ({rotor}) or the "
                                       "{bearing_load}, one of them")
    load_given = o.bearing_load if jr is None else jr.bearing_load
    if load_given is not None:
        return ((load_given, "the static bearing load given"),) * p
    mass, com = _rotor(job)
    g = STANDARD_GRAVITY if jr is None or jr.g is None else jr.g
    if jr is None or jr.bearings is None or com is None:
        return ((mass * g / 2.0, "half the rotor's weight (two bearings sharing it equally)"),) * p
    loads = static_bearing_loads(mass, g, com, jr.bearings)
    return tuple(_nearest(loads, jr.bearings, job.plane_at[j] if j < len(job.plane_at) else None)
                 for j in range(p))


def _rotor(job: Job) -> tuple[float, float | None]:
    """The rotor's mass (kg) and its centre of mass along the shaft (m, or None)."""
    o, jr = job.options, job.rotor
    com = None
    if o.rotor_mass is not None:
        mass = o.rotor_mass
    elif o.rotor is not None or (jr is not None and jr.body is not None):
        mp = body_mass_props(load(str(o.rotor if o.rotor is not None else jr.body)))
        mass, com = float(mp.mass), float(mp.com[2])
    elif jr is not None and jr.mass is not None:
        mass = jr.mass
    else:
        raise ParamError("rotor_mass", "the trial mass needs the rotor's mass ({rotor_mass}, or a body "
                                       "file {rotor}) or the static {bearing_load}")
    return mass, com if jr is None or jr.com is None else jr.com


def _nearest(loads: tuple[float, float], bearings: tuple[float, float], z: float | None) -> tuple[float, str]:
    """The static load of the bearing nearest a plane at ``z`` (the larger one when the
    plane's place is not given): the lever rule."""
    if z is None:
        b = 0 if loads[0] >= loads[1] else 1
        why = "the larger static bearing load (the plane's position is not given)"
    else:
        b = 0 if abs(z - bearings[0]) <= abs(z - bearings[1]) else 1
        why = f"the static load of bearing {b + 1}, nearest the plane (lever rule)"
    if not loads[b] > 0:
        raise ParamError("rotor_mass", f"bearing {b + 1} carries no static load ({loads[b]:.4g} N: the "
                                       "rotor hangs beyond it); give the {bearing_load}")
    return loads[b], why


def suggestions(job: Job, alpha: Any, initial: Any) -> tuple[SuggestedTrial, ...]:
    """The trial mass of each plane, and with influence coefficients ``alpha`` ((N, P)
    ndarray, or None) the change it should make to each reading of ``initial``."""
    req = job.suggest
    if req is None:
        return ()
    out = []
    for j, ((load_n, why), r) in enumerate(zip(req.loads, req.radii)):
        s = suggest_trial(load_n, r, req.speed, req.fraction)
        change = ratio = None
        if alpha is not None and j < alpha.shape[1]:
            change = tuple(float(abs(alpha[k, j]) * s.mass) for k in range(alpha.shape[0]))
            if all(abs(complex(v)) > 0 for v in initial):
                ratio = tuple(c / abs(complex(v)) for c, v in zip(change, initial))
        out.append(SuggestedTrial(job.plane_names[j] if j < len(job.plane_names) else "A", s.mass,
                                  s.radius, s.speed, s.bearing_load, why, s.fraction, s.force, change,
                                  ratio))
    return tuple(out)
