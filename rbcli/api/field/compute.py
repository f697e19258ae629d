"""The extended field-balancing job: solve, fit, judge and size (the work of
:func:`rbcli.api.field.service.run` for anything beyond the classic one- and two-plane job).

Square one- and two-plane jobs still go through :mod:`rbcli.core.field.classic` (the same
bits as the classic output); everything else through :mod:`rbcli.core.field.solve`.
Then: the corrections at their radii, the masses as fitted
(:mod:`rbcli.core.field.fit`) and the readings they leave, Darlow's significance
(:mod:`rbcli.core.field.significance`), the ISO 20816-3 zones
(:mod:`rbcli.core.field.severity`) and a trial mass to start with.
"""

from __future__ import annotations

from typing import Any

from rbcli.api.field.result import (
    Conventions, FieldBalanceResult, FieldCorrection, FieldResidual, Fitted, FittedMass, FittedPlane,
    Severity, SeverityRow, SuggestedTrial, convention_text, deg,
)

__all__ = ["solve_job", "significance_warning"]


def solve_job(o: Any) -> FieldBalanceResult:
    """The result of an extended job ``o`` (a :class:`FieldBalanceOptions`)."""
    import numpy as np

    from rbcli.core.field import classic as fld
    from rbcli.core.field import solve as fs
    from rbcli.core.balance.common import FIELD_COND_WARN
    from rbcli.core.field.significance import SIGNIFICANCE_LIMIT, plane_significance

    conv = None
    if o.phase is not None or o.angle_sense is not None or o.rotation is not None:
        conv = Conventions(o.phase, o.angle_sense, o.rotation, o.flipped,
                           convention_text(o.phase, o.angle_sense, o.rotation, o.flipped))
    warnings: list[str] = []
    common = dict(reading_kind=o.reading_kind, sensors=o.sensors, run_speeds=o.speeds,
                  plane_names=o.plane_names, plane_radii=o.plane_radii, weights=o.weights,
                  measure=o.measure, measures_converted=o.measures_converted, gravity=o.gravity,
                  conventions=conv, coefficients_from=o.coefficients_from, job=o.job, name=o.name,
                  notes=tuple(o.notes))
    if not o.initial:  # a trial mass sized, nothing measured yet
        sugg = _suggestions(o, None, None)
        return FieldBalanceResult(
            planes=len(o.plane_names), initial=(), runs=(), corrections=(), alpha=(), trial_masses=(),
            radii=o.radii, cond=None, det=None, ill_conditioned=False, small_response=(),
            residual_values=(), cumulative=o.cumulative, method=None, suggested_trial=sugg,
            warnings=tuple(warnings), significance_limit=SIGNIFICANCE_LIMIT, **common)
    V0 = np.array(o.initial, dtype=complex)
    n = V0.size
    p = o.planes
    small: tuple[bool, ...] = ()
    if o.coefficients is None and n == p and p in (1, 2):
        # the classic solves: the same arithmetic, the same bits as the classic output
        if p == 1:
            f1 = fld.field_single_plane(o.initial[0], o.runs[0][0], o.trials[0])
            alpha = np.array([[f1.influence]])
            W = np.array([f1.correction])
            small = (bool(f1.small_response),)
        else:
            f2 = fld.field_two_plane(o.initial, o.runs[0], o.runs[1], o.trials[0], o.trials[1],
                                     cumulative=o.cumulative)
            alpha = np.array(f2.influence)
            W = np.array(f2.corrections)
            small = tuple(bool(x) for x in f2.small_response)
        sol = fs.solve(alpha, V0)  # for cond and det; W is the classic one
        method, cond, det = "exact", sol.cond, sol.det
        resid = V0 + alpha @ W
    else:
        if o.coefficients is not None:
            alpha = np.array(o.coefficients, dtype=complex)
        else:
            alpha = fs.influence_matrix(V0, np.array(o.runs, dtype=complex), np.array(o.trials, dtype=complex),
                                        cumulative=o.cumulative)
            small = tuple(
                all(fld.small_response(complex((o.runs[j - 1] if (o.cumulative and j) else o.initial)[k]),
                                       complex(o.runs[j][k])) for k in range(n))
                for j in range(p))
        sol = fs.solve(alpha, V0, o.method, o.weights)
        W, resid, method, cond, det = np.array(sol.corrections), np.array(sol.residuals), sol.method, sol.cond, sol.det
    scales = [1.0 if r is None else r[0] / r[1] for r in (o.plane_radii or (None,) * p)]
    trials = list(o.trials)
    corrections = []
    for j in range(p):
        w = complex(W[j])
        on = (w - trials[j]) * scales[j] if trials else w * scales[j]
        if trials and abs(w - trials[j]) <= 1e-12 * max(abs(w), abs(trials[j])):
            on = 0j  # the correction is the trial itself, to round-off: nothing to add
        rr = o.plane_radii[j] if j < len(o.plane_radii) else None
        corrections.append(FieldCorrection(o.plane_names[j], w * scales[j], on, None if rr is None else rr[1]))
    rows = _row_names(o)
    residuals = tuple(_residual(rows[k], resid[k], V0[k], o.flipped) for k in range(n))
    sig = plane_significance(alpha)
    if cond > FIELD_COND_WARN:
        warnings.append(f"the influence matrix is ill-conditioned (cond = {cond:.3g} > "
                        f"{FIELD_COND_WARN:g}): the planes are not well separated")
    for j in sig.flagged:
        if p > 1:
            warnings.append(significance_warning(o.plane_names[j], float(sig.factors[j])))
    for j, sm in enumerate(small):
        if sm:
            warnings.append(f"trial {o.plane_names[j]} changed no reading by 25 % in amplitude or "
                            "25 deg in phase: use a larger trial mass")
    if n > p:
        for k in range(n):
            if abs(resid[k]) > abs(V0[k]) * (1.0 + 1e-9):
                sensor, speed = rows[k]
                warnings.append(
                    f"the correction raises reading {sensor}{' at ' + speed if speed else ''} from "
                    f"{abs(V0[k]):.4g} to {abs(resid[k]):.4g} ({o.reading_kind and _unit(o) or 'relative'}): "
                    f"{method} trades it against the others")
    fitted = _fitted(o, corrections, scales, alpha, V0, rows)
    severity = None
    if o.severity is not None:
        after = np.array([complex(r) for r in _fitted_resid(o, fitted, scales, alpha, V0)]) if fitted else resid
        severity = _severity(o, V0, after, rows, "fitted" if fitted else "computed")
    sugg = _suggestions(o, alpha, V0) if o.suggest is not None else ()
    return FieldBalanceResult(
        planes=p, initial=o.initial, runs=o.runs, corrections=tuple(corrections),
        alpha=tuple(tuple(complex(a) for a in row) for row in alpha), trial_masses=o.trials,
        radii=o.radii, cond=float(cond), det=det, ill_conditioned=bool(cond > FIELD_COND_WARN),
        small_response=small, residual_values=tuple(complex(r) for r in resid),
        cumulative=o.cumulative, method=method, residuals=residuals,
        significance_factors=tuple(float(x) for x in sig.factors), significance_limit=SIGNIFICANCE_LIMIT,
        fitted=fitted, severity=severity, suggested_trial=sugg,
        warnings=tuple(warnings), **common)


def significance_warning(plane: str, factor: float) -> str:
    """The warning for a plane Darlow's test flags."""
    from rbcli.core.field.significance import SIGNIFICANCE_LIMIT

    return (f"plane {plane} is ill-conditioned by Darlow's test: its significance factor {factor:.3g} is "
            f"at or below {SIGNIFICANCE_LIMIT:g} (it moves the readings in little that the other planes "
            "do not), so its correction is unreliable; consider balancing without it")


def _unit(o: Any) -> str:
    from rbcli.api.field.result import SI_UNITS

    return SI_UNITS[o.reading_kind]


def _row_names(o: Any) -> list[tuple[str, str]]:
    n = len(o.initial)
    ns = max(len(o.sensors), 1)
    return [(o.sensors[k % ns] if o.sensors else str(k + 1), o.speeds[k // ns][0] if o.speeds else "")
            for k in range(n)]


def _residual(row: tuple[str, str], r: complex, v0: complex, flipped: bool) -> FieldResidual:
    z = complex(r).conjugate() if flipped else complex(r)
    return FieldResidual(row[0], row[1], abs(z), deg(z) if z != 0 else 0.0, abs(complex(v0)))


def _fitted(o: Any, corrections: list[FieldCorrection], scales: list[float], alpha: Any, V0: Any,
            rows: list[tuple[str, str]]) -> Fitted | None:
    """The corrections rounded or split as asked, and the readings they leave."""
    from rbcli.core.field.fit import fit_plane

    positions = list(o.positions) + [None] * (len(corrections) - len(o.positions))
    if o.mass_step is None and o.angle_step is None and not any(positions):
        return None
    planes = []
    for c, npos in zip(corrections, positions):
        fp = fit_plane(c.correction, mass_step=o.mass_step,
                       angle_step_deg=None if npos else o.angle_step, positions=npos)
        planes.append(FittedPlane(c.name, tuple(FittedMass(m.mass, m.angle_deg, m.position) for m in fp.masses),
                                  abs(fp.net), deg(fp.net) if fp.net != 0 else 0.0, npos))
    nets = [complex(pl.mass * _unit_phasor(pl.angle_deg)) for pl in planes]
    # the fitted masses at the correction radius, as trial-radius masses: net / scale
    from rbcli.core.field.solve import matvec

    r = V0 + matvec(alpha, [nets[j] / scales[j] for j in range(len(nets))])
    res = tuple(_residual(rows[k], r[k], V0[k], o.flipped) for k in range(len(rows)))
    return Fitted(o.mass_step, o.angle_step, tuple(planes), res)


def _unit_phasor(angle_deg: float) -> complex:
    import cmath
    import math

    return complex(cmath.rect(1.0, math.radians(angle_deg)))


def _fitted_resid(o: Any, fitted: Fitted, scales: list[float], alpha: Any, V0: Any) -> list[complex]:
    nets = [pl.mass * _unit_phasor(pl.angle_deg) for pl in fitted.planes]
    from rbcli.core.field.solve import matvec

    return list(V0 + matvec(alpha, [nets[j] / scales[j] for j in range(len(nets))]))


def _severity(o: Any, V0: Any, after: Any, rows: list[tuple[str, str]], after_is: str) -> Severity:
    """ISO 20816-3 zones of each reading before and after (r.m.s. velocity)."""
    from rbcli.core.field.severity import to_velocity, zone, zone_boundaries

    std, group, foundation = o.severity
    ns = max(len(o.sensors), 1)
    out = []
    for k, (sensor, speed) in enumerate(rows):
        w = o.speeds[k // ns][1] if o.speeds else None
        conv = (lambda a: a) if o.reading_kind == "velocity" else (lambda a, w=w: to_velocity(a, o.reading_kind, w))
        b = conv(abs(complex(V0[k])))
        a = conv(abs(complex(after[k])))
        out.append(SeverityRow(sensor, speed, b, zone(b, group, foundation), a, zone(a, group, foundation)))
    return Severity("ISO 20816-3", group, foundation, zone_boundaries(group, foundation), after_is, tuple(out))


def _suggestions(o: Any, alpha: Any, V0: Any) -> tuple[SuggestedTrial, ...]:
    from rbcli.core.field.fit import suggest_trial

    req = o.suggest
    if req is None:
        return ()
    out = []
    for j, ((load, why), r) in enumerate(zip(req.loads, req.radii)):
        s = suggest_trial(load, r, req.speed, req.fraction)
        change = ratio = None
        if alpha is not None and j < alpha.shape[1]:
            change = tuple(float(abs(alpha[k, j]) * s.mass) for k in range(alpha.shape[0]))
            ratio = tuple((c / abs(complex(V0[k]))) if abs(complex(V0[k])) > 0 else float("inf") for k, c in enumerate(change))
            if any(x == float("inf") for x in ratio):
                ratio = None
        out.append(SuggestedTrial(o.plane_names[j] if j < len(o.plane_names) else "A", s.mass, s.radius,
                                  s.speed, s.bearing_load, why, s.fraction, s.force, change, ratio))
    return tuple(out)
