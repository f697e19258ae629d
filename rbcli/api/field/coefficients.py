"""A trim run: a job solved with stored influence coefficients (``coefficients``), checked
against the job (readings, kind, speeds, sensors, planes) and brought into its measure and
angle sense; the job takes the file's planes, trial radii and, when it says none, conventions."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from rbcli.api import options as op
from rbcli.api.field.readings import budget
from rbcli.api.params import Options
from rbcli.core.field.severity import convert_measure
from rbcli.errors import ParamError, literal
from rbcli.io.field.coefficients import SavedCoefficients, load_coefficients

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.api.field.job import Job

__all__ = ["apply"]

Alpha = list[list[complex]]


def apply(job: Job) -> Job:
    """``job`` with the coefficients of its file (``job.options.coefficients``).

    Raises
    ------
    rbcli.InputError
        a file that does not fit the job, naming ``coefficients`` (or ``speed``, ``radius``).
    """
    o = job.options
    path = str(o.coefficients)
    with op.naming("coefficients"):
        c = load_coefficients(path)
    here = f"'{literal(path)}'"
    budget(len(c.rows), len(c.planes), None)
    if len(c.rows) != len(job.initial):
        raise ParamError("coefficients", f"{here} holds {len(c.rows)} readings per run ({len(c.sensors)} "
                                         f"sensors x {len(c.speeds)} speeds); the initial readings are "
                                         f"{len(job.initial)}")
    speeds = _speeds(job, c, here)
    if c.reading_kind != job.reading_kind:
        raise ParamError("coefficients", f"{here} holds coefficients for {c.reading_kind or 'bare'} "
                                         f"readings; these readings are {job.reading_kind or 'bare'}")
    notes: list[str] = []
    alpha, measure = _measure(c, [list(row) for row in c.coefficients], job.measure, here, notes)
    alpha, o = _conventions(c, alpha, o, here, notes)
    p = len(c.planes)
    rt = c.planes[0][1]
    same = rt is not None and len({r for _, r in c.planes}) == 1
    return replace(
        job, options=o.replace(cumulative=False), speeds=speeds,
        sensors=job.sensors if o.job is not None else c.sensors,
        plane_names=tuple(name for name, _ in c.planes), plane_radii=_radii(c, o.radius, here),
        radii=(rt, rt if o.radius is None else o.radius) if same else None,
        positions=(o.positions,) * p if o.job is None else _padded(job.positions, p),
        plane_at=_padded(job.plane_at, p), alpha=tuple(tuple(row) for row in alpha),
        measure=measure, notes=job.notes + tuple(notes))


def _padded(values: tuple, p: int) -> tuple:
    return (tuple(values) + (None,) * p)[:p]


def _speeds(job: Job, c: SavedCoefficients, here: str) -> tuple[tuple[str, float | None], ...]:
    """The job's speeds, each the file's where the job gives none (refused when they
    differ: influence coefficients change with speed)."""
    mine = job.speeds
    if job.options.job is not None:
        if c.sensors != job.sensors:
            raise ParamError("coefficients", f"{here} is for sensors {literal(', '.join(c.sensors))}, "
                                             f"not {literal(', '.join(job.sensors))}")
        if len(c.speeds) != len(mine) or any(jn and jn != cn for (cn, _), (jn, _) in zip(c.speeds, mine)):
            raise ParamError("coefficients", f"{here} is for speeds {literal(', '.join(n for n, _ in c.speeds))}, "
                                             f"the job has {literal(', '.join(n for n, _ in mine))}")
        named = tuple(pl.name for pl in job.source.planes) if job.source is not None else ()
        if named and named != tuple(n for n, _ in c.planes):
            raise ParamError("coefficients", f"{here} is for planes {literal(', '.join(n for n, _ in c.planes))}, "
                                             f"the job has {literal(', '.join(named))}")
    else:  # the command line: the readings in the file's order, its sensors and speeds
        if len(c.speeds) > 1 and mine[0][1] is not None:
            raise ParamError("speed", f"{here} holds {len(c.speeds)} speeds; the readings are at those "
                                      "(leave out {speed})")
        mine = tuple((name, mine[0][1] if len(c.speeds) == 1 else None) for name, _ in c.speeds)
    for (_, cw), (_, jw) in zip(c.speeds, mine):
        if cw is not None and jw is not None and abs(cw - jw) > 1e-9 * cw:
            raise ParamError("coefficients", f"{here} was measured at {cw:.6g} rad/s, this job runs at "
                                             f"{jw:.6g} rad/s: influence coefficients change with speed")
    return tuple((jn or cn, cw if jw is None else jw) for (cn, cw), (jn, jw) in zip(c.speeds, mine))


def _measure(c: SavedCoefficients, alpha: Alpha, measure: str | None, here: str,
             notes: list[str]) -> tuple[Alpha, str | None]:
    """The coefficients in the readings' measure (the file's when the readings say none)."""
    if c.measure is None and measure is not None:
        raise ParamError("coefficients", f"{here} does not say its readings' measure; these are "
                                         f"{measure}: leave the measure unsaid, as it was")
    if c.measure is None or c.measure == measure:
        return alpha, measure
    if measure is None:
        notes.append(f"the readings, which say no measure, taken as {c.measure} (the coefficients file's)")
        return alpha, c.measure
    f = convert_measure(1.0, c.measure, measure)
    notes.append(f"coefficients converted from {c.measure} to {measure}")
    return [[a * f for a in row] for row in alpha], measure


def _conventions(c: SavedCoefficients, alpha: Alpha, o: Options, here: str,
                 notes: list[str]) -> tuple[Alpha, Options]:
    """The job's conventions, or the file's when the job says none; the coefficients in the
    job's angle sense."""
    if o.phase is None and o.angle_sense is None and o.rotation is None:
        if c.phase or c.angle_sense or c.rotation:
            notes.append("conventions from the coefficients file")
        return alpha, o.replace(phase=c.phase, angle_sense=c.angle_sense, rotation=c.rotation)
    if c.angle_sense is None and (o.angle_sense is not None or o.phase is not None):
        raise ParamError("coefficients", f"{here} does not say its conventions; this job does: balance it "
                                         "with the conventions unsaid, as they were")
    if c.angle_sense is not None and o.angle_sense is not None and c.angle_sense != o.angle_sense:
        notes.append("coefficients mirrored into this job's angle sense")
        return [[a.conjugate() for a in row] for row in alpha], o
    return alpha, o


def _radii(c: SavedCoefficients, rc: float | None, here: str) -> tuple[tuple[float, float] | None, ...]:
    """Per plane (trial radius, correction radius ``rc``, else the trial radius)."""
    out = []
    for name, rt in c.planes:
        if rt is None and rc is not None:
            raise ParamError("radius", f"{here} has no trial radius for plane {literal(name)}: the "
                                       "corrections stay at the trial radius")
        out.append(None if rt is None else (rt, rt if rc is None else rc))
    return tuple(out)
