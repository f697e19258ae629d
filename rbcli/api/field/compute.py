"""The result of a field-balancing job (:func:`result`): a classic job as it always was, any
other solved (square one- and two-plane jobs with the classic bits), fitted (rounded, split
or from a drawer), judged (limits, significance, ISO 20816-3) and a trial mass sized."""

from __future__ import annotations

import cmath
import math
from typing import TYPE_CHECKING, Any

import numpy as np

from rbcli.api.field import shop, trial
from rbcli.api.field.result import (
    SI_UNITS, Conventions, DrawerFit, DrawerPlane, FieldBalanceResult, FieldCorrection, FieldResidual,
    Fitted, FittedPlane, Limits, PlaneLimit, ReadingLimit, Robust, Severity, SeverityRow, convention_text, row_names,
)
from rbcli.core.balance.common import FIELD_COND_WARN
from rbcli.core.field.drawer import best_weights
from rbcli.core.field.fit import FittedMass, fit_plane
from rbcli.core.field.severity import to_velocity, zone, zone_boundaries
from rbcli.core.field.significance import SIGNIFICANCE_LIMIT, plane_significance
from rbcli.core.field.solve import (
    HUBER_C, FieldSolution, classic, deg, influence_matrix, matvec, small_response, solve,
)

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.api.field.job import Job

__all__ = ["result", "significance_warning"]

Rows = list[tuple[str, str]]

#: the largest job (readings x planes) whose active limits are each solved without too (their cost)
COST_SIZE = 4000


def result(job: Job) -> FieldBalanceResult:
    """The result of ``job`` (see the module's docstring)."""
    if not job.extended:
        return _classic(job)
    if not job.initial:  # a trial mass sized, nothing measured yet
        return FieldBalanceResult(
            planes=job.planes, initial=(), runs=(), corrections=(), alpha=(), trial_masses=(),
            radii=job.radii, cond=None, det=None, ill_conditioned=False, small_response=(),
            residual_values=(), cumulative=bool(job.options.cumulative), method=None,
            suggested_trial=trial.suggestions(job, None, None),
            significance_limit=SIGNIFICANCE_LIMIT, **_described(job))
    return _extended(job)


def significance_warning(plane: str, factor: float) -> str:
    """The warning for a plane Darlow's test flags."""
    return (f"plane {plane} is ill-conditioned by Darlow's test: its significance factor {factor:.3g} is "
            f"at or below {SIGNIFICANCE_LIMIT:g} (it moves the readings in little that the other planes "
            "do not), so its correction is unreliable; consider balancing without it")


# --- classic


def _classic(job: Job) -> FieldBalanceResult:
    """The one- or two-plane job as rbcli always solved and reported it."""
    s = 1.0 if job.radii is None else job.radii[0] / job.radii[1]
    rc = None if job.radii is None else job.radii[1]
    p, cumulative = job.planes, bool(job.options.cumulative)
    alpha, W, resid, det, cond = classic(job.initial, job.runs, job.trials, cumulative)
    small = _small(job, cumulative)
    warnings = [f"trial {job.plane_names[j]} changed no reading by 25 % in amplitude or 25 deg in phase: "
                "use a larger trial mass" for j in range(p) if small[j]]
    if p == 1:
        warnings = ["the trial changed the reading by less than 25 % in amplitude and 25 deg in phase: use "
                    "a larger trial mass"] * small[0]
    sig = plane_significance(alpha) if p == 2 else None
    if p == 2 and cond > FIELD_COND_WARN:
        warnings.insert(0, f"the influence matrix is ill-conditioned (cond = {cond:.3g} > {FIELD_COND_WARN:g}): "
                           "the planes are not well separated")
    return FieldBalanceResult(
        planes=p, corrections=tuple(FieldCorrection(name, complex(w) * s, (complex(w) - t) * s, rc)
                                    for name, w, t in zip("AB", W, job.trials)),
        alpha=tuple(tuple(complex(a) for a in row) for row in alpha), cond=cond, det=det,
        ill_conditioned=p == 2 and cond > FIELD_COND_WARN, small_response=small,
        residual_values=tuple(complex(v) for v in resid), cumulative=cumulative,
        warnings=tuple(warnings) + (() if sig is None else tuple(
            significance_warning("AB"[j], float(sig.factors[j])) for j in sig.flagged)),
        significance_factors=() if sig is None else tuple(float(x) for x in sig.factors),
        initial=job.initial, runs=job.runs, trial_masses=job.trials, radii=job.radii,
        reading_kind=job.reading_kind)


def _small(job: Job, cumulative: bool) -> tuple[bool, ...]:
    """Per trial run, whether it changed every reading too little."""
    return tuple(all(small_response(complex((job.runs[j - 1] if cumulative and j else job.initial)[k]),
                                    complex(job.runs[j][k])) for k in range(len(job.initial)))
                 for j in range(job.planes))


# --- extended


def _described(job: Job) -> dict[str, Any]:
    """What an extended result says of its job: names, units, conventions, sources."""
    o = job.options
    conv = None
    if o.phase is not None or o.angle_sense is not None or o.rotation is not None:
        conv = Conventions(o.phase, o.angle_sense, o.rotation, job.flipped,
                           convention_text(o.phase, o.angle_sense, o.rotation, job.flipped))
    return dict(reading_kind=job.reading_kind, sensors=job.sensors, run_speeds=job.speeds,
                plane_names=job.plane_names, plane_radii=job.plane_radii, weights=job.weights,
                measure=job.measure, measures_converted=job.measures_converted, gravity=job.gravity,
                conventions=conv, coefficients_from=o.coefficients, job=o.job, name=job.name,
                notes=job.notes)


def _extended(job: Job) -> FieldBalanceResult:
    V0 = np.array(job.initial, dtype=complex)
    alpha, sol, small = _solve(job, V0)
    resid = np.asarray(sol.residuals)
    scales = [1.0 if r is None else r[0] / r[1] for r in job.plane_radii]
    corrections = tuple(_correction(job, j, complex(sol.corrections[j]), scales[j])
                        for j in range(job.planes))
    rows = row_names(job.sensors, job.speeds, len(job.initial))
    sig = plane_significance(alpha)
    fitted = _drawer(job, alpha, V0, rows, sol) if job.drawer else _fitted(job, corrections, scales, alpha, V0, rows)
    after = [r.amplitude for r in fitted.residuals] if fitted else [abs(complex(r)) for r in resid]
    return FieldBalanceResult(
        planes=job.planes, initial=job.initial, runs=job.runs, corrections=corrections,
        alpha=tuple(tuple(complex(a) for a in row) for row in alpha), trial_masses=job.trials,
        radii=job.radii, cond=float(sol.cond), det=sol.det, ill_conditioned=bool(sol.cond > FIELD_COND_WARN),
        small_response=small, residual_values=tuple(complex(r) for r in resid),
        cumulative=bool(job.options.cumulative), method=sol.method,
        residuals=tuple(_residual(rows[k], resid[k], V0[k], job.flipped) for k in range(len(rows))),
        significance_factors=tuple(float(x) for x in sig.factors), significance_limit=SIGNIFICANCE_LIMIT,
        fitted=fitted, severity=None if job.severity is None else _severity(
            job, V0, after, rows, "fitted" if fitted else "computed"),
        suggested_trial=trial.suggestions(job, alpha, V0), limits=_limits(job, sol, rows, scales),
        robust=None if sol.robust is None else Robust("huber", HUBER_C, tuple(float(x) for x in sol.robust), tuple(
            name for name, h in zip(_names(rows), sol.robust) if h < 1.0)),
        warnings=_warnings(job, sol, sig, small, V0, rows) + _shop_warnings(job, sol, fitted, rows),
        **_described(job))


def _solve(job: Job, V0: np.ndarray) -> tuple[np.ndarray, FieldSolution, tuple[bool, ...]]:
    """The influence matrix, the solution and, per trial run, whether it changed the
    readings too little."""
    n, p = V0.size, job.planes
    runs, cumulative = job.runs, bool(job.options.cumulative)
    o = job.options
    if job.alpha is None and n == p and p in (1, 2) and not (job.max_mass != (None,) * p or job.limits or o.robust):
        # the classic solves: the same arithmetic, the same bits as the classic output
        alpha, W = classic(job.initial, runs, job.trials, cumulative)[:2]
        sol = solve(alpha, V0)  # for cond and det; W is the classic one
        return alpha, FieldSolution(W, V0 + alpha @ W, "exact", sol.cond, sol.det, 0.0), _small(job, cumulative)
    if job.alpha is not None:
        alpha, small = np.array(job.alpha, dtype=complex), ()
    else:
        alpha = influence_matrix(V0, np.array(runs, dtype=complex), np.array(job.trials, dtype=complex),
                                 cumulative=cumulative)
        small = _small(job, cumulative)
    return alpha, solve(alpha, V0, o.method, job.weights, max_mass=_max_mass(job), limits=job.limits,
                        robust=o.robust is not None, costs=len(job.initial) * p <= COST_SIZE), small


def _max_mass(job: Job) -> list[float] | None:
    """Each plane's largest |W| (kg at the trial radius; inf: none)."""
    return [math.inf if m is None else m[0] * (rr[1] / rr[0] if rr else 1.0) if m[1] == "mass" else m[0] / rr[0]
            for m, rr in zip(job.max_mass, job.plane_radii)] if any(job.max_mass) else None


def _limits(job: Job, sol: FieldSolution, rows: Rows, scales: list[float]) -> Limits | None:
    """The limits given, what the correction gives against each, and what each costs."""
    if job.limits is None and not any(job.max_mass):
        return None
    cost = dict(zip(sol.active, sol.without))
    planes = tuple(PlaneLimit(job.plane_names[j], m[0] if m[1] == "mass" else None, m[0] if m[1] == "unbalance"
                              else None, abs(complex(sol.corrections[j])) * scales[j],
                              job.plane_radii[j] and abs(complex(sol.corrections[j])) * job.plane_radii[j][0],
                              ("mass", j) in sol.active, cost.get(("mass", j)))
                   for j, m in enumerate(job.max_mass) if m is not None)
    readings = tuple(ReadingLimit(*rows[k], lim, abs(complex(sol.residuals[k])), ("reading", k) in sol.active,
                                  cost.get(("reading", k))) for k, lim in enumerate(job.limits or ()) if math.isfinite(lim))
    return Limits(bool(sol.feasible), float(sol.violation), float(sol.objective), planes, readings)


def _drawer(job: Job, alpha: np.ndarray, V0: np.ndarray, rows: Rows, sol: FieldSolution) -> Fitted:
    """The best weights of the drawer at the holes, and the readings they leave."""
    d = job.drawer
    w = np.ones(V0.size) if job.weights is None else np.array(job.weights)
    method = "min-max" if sol.method == "min-max" else "least-squares"
    ch = best_weights(alpha, V0, w if sol.robust is None else w * sol.robust, method, list(d.planes),
                      [shop.counts(x) for x in d.drawers], None if job.limits is None else np.array(job.limits),
                      start=np.asarray(sol.corrections) if method == "min-max" else None)
    planes = []
    for j, ws in enumerate(ch.weights):
        pl = d.planes[j]
        masses = tuple(FittedMass(d.drawers[pl.drawer][s][0], d.holes[j].angles[h], h + 1) for h, s in ws)
        net = sum((m.mass * cmath.rect(1.0, math.radians(m.angle_deg)) for m in masses), 0j)
        planes.append(FittedPlane(job.plane_names[j], len(d.holes[j].angles), abs(net), deg(net), masses))
    r = V0 + matvec(alpha, ch.corrections)
    info = DrawerFit(ch.objective, ch.violation, ch.examined,
                     tuple(tuple({"mass": m, "count": c} for m, c in x) for x in d.drawers),
                     tuple(DrawerPlane(job.plane_names[j], h.angles, h.radius, h.numbering, pl.per_hole,
                                       pl.most, pl.max_mass if math.isfinite(pl.max_mass) else None, pl.drawer)
                           for j, (pl, h) in enumerate(zip(d.planes, d.holes))))
    return Fitted(None, None, tuple(planes), tuple(_residual(rows[k], r[k], V0[k], job.flipped)
                                                   for k in range(len(rows))), info)


def _shop_warnings(job: Job, sol: FieldSolution, fitted: Fitted | None, rows: Rows) -> tuple[str, ...]:
    """Limits that cannot be met, readings a robust fit discounted."""
    d = fitted.drawer if fitted is not None else None
    return tuple(([f"the limits cannot all be met: the correction exceeds them least (each reading within "
                   f"{sol.violation:.4g} times its limit)"] if not sol.feasible else [])
                 + ([f"no choice of the drawer's weights meets the limits: the one chosen exceeds them least "
                     f"({d.violation:.4g} times a limit)"] if d and d.violation > 1.0 else [])
                 + [f"reading {name} discounted by the robust fit (weight {h:.3g}): check it"
                    for name, h in zip(_names(rows), () if sol.robust is None else sol.robust) if h < 1.0])


def _names(rows: Rows) -> list[str]:
    return [f"{s}{' at ' + v if v else ''}" for s, v in rows]


def _correction(job: Job, j: int, w: complex, scale: float) -> FieldCorrection:
    """Plane ``j``'s correction ``w`` (kg at the trial radius) at its correction radius,
    and with its trial left on."""
    on = w * scale
    if job.trials:
        t = job.trials[j]
        # the correction is the trial itself, to round-off: nothing to add
        on = 0j if abs(w - t) <= 1e-12 * max(abs(w), abs(t)) else (w - t) * scale
    rr = job.plane_radii[j]
    return FieldCorrection(job.plane_names[j], w * scale, on, None if rr is None else rr[1])


def _residual(row: tuple[str, str], r: complex, v0: complex, flipped: bool) -> FieldResidual:
    z = complex(r).conjugate() if flipped else complex(r)
    return FieldResidual(row[0], row[1], abs(z), deg(z) if z != 0 else 0.0, abs(complex(v0)))


def _warnings(job: Job, sol: FieldSolution, sig: Any, small: tuple[bool, ...], V0: np.ndarray,
              rows: Rows) -> tuple[str, ...]:
    """Ill-conditioning, planes Darlow's test flags, trials too small, readings made larger."""
    out = []
    if sol.cond > FIELD_COND_WARN:
        out.append(f"the influence matrix is ill-conditioned (cond = {sol.cond:.3g} > "
                   f"{FIELD_COND_WARN:g}): the planes are not well separated")
    if job.planes > 1:
        out += [significance_warning(job.plane_names[j], float(sig.factors[j])) for j in sig.flagged]
    out += [f"trial {job.plane_names[j]} changed no reading by 25 % in amplitude or 25 deg in phase: "
            "use a larger trial mass" for j, sm in enumerate(small) if sm]
    unit = SI_UNITS[job.reading_kind] if job.reading_kind else "relative"
    if V0.size > job.planes:
        for k, r in enumerate(sol.residuals):
            if abs(r) > abs(V0[k]) * (1.0 + 1e-9):
                sensor, speed = rows[k]
                out.append(f"the correction raises reading {sensor}{' at ' + speed if speed else ''} from "
                           f"{abs(V0[k]):.4g} to {abs(r):.4g} ({unit}): {sol.method} trades it against "
                           "the others")
    return tuple(out)


def _fitted(job: Job, corrections: tuple[FieldCorrection, ...], scales: list[float], alpha: np.ndarray,
            V0: np.ndarray, rows: Rows) -> Fitted | None:
    """The corrections rounded or split as asked, and the readings they leave."""
    o = job.options
    positions = job.positions + (None,) * (len(corrections) - len(job.positions))
    if o.mass_step is None and o.angle_step is None and not any(positions):
        return None
    planes = []
    for c, npos in zip(corrections, positions):
        fp = fit_plane(c.correction, mass_step=o.mass_step, angle_step_deg=None if npos else o.angle_step,
                       positions=npos)
        planes.append(FittedPlane(c.name, npos, abs(fp.net), deg(fp.net) if fp.net != 0 else 0.0, fp.masses))
    # the masses fitted at the correction radius, as trial-radius masses: net / scale
    nets = [complex(pl.mass * cmath.rect(1.0, math.radians(pl.angle_deg))) / scale
            for pl, scale in zip(planes, scales)]
    r = V0 + matvec(alpha, nets)
    return Fitted(o.mass_step, o.angle_step, tuple(planes),
                  tuple(_residual(rows[k], r[k], V0[k], job.flipped) for k in range(len(rows))))


def _severity(job: Job, V0: np.ndarray, after: list[float], rows: Rows, after_is: str) -> Severity:
    """ISO 20816-3 zones of each reading before and after (r.m.s. velocity)."""
    _, group, foundation = job.severity
    kind, ns = job.reading_kind, len(job.sensors)
    out = []
    for k, (sensor, speed) in enumerate(rows):
        b, a = abs(complex(V0[k])), after[k]
        if kind != "velocity":
            w = job.speeds[k // ns][1]
            b, a = to_velocity(b, kind, w), to_velocity(a, kind, w)
        out.append(SeverityRow(sensor, speed, b, zone(b, group, foundation), a, zone(a, group, foundation)))
    return Severity("ISO 20816-3", group, foundation, zone_boundaries(group, foundation), after_is, tuple(out))
