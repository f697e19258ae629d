"""The result of ``rbcli field-balance``: values, their JSON (rbcli-field-balance(1)) and
the coefficients file's document; a classic one- or two-plane job's as it always was
(``method`` None), any other's with ``method``, ``residuals`` and the rest.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, fields, is_dataclass
from typing import Any

from rbcli import __version__
from rbcli.api.result import Result
from rbcli.core.field.fit import FittedMass
from rbcli.core.field.solve import deg
from rbcli.io.field import plane_names
from rbcli.io.field.coefficients import FORMAT, VERSION, fingerprint

__all__ = ["FieldBalanceResult", "FieldCorrection", "FieldResidual", "FittedPlane", "Fitted",
    "SeverityRow", "Severity", "SuggestedTrial", "Conventions", "convention_text", "DrawerPlane",
    "DrawerFit", "PlaneLimit", "ReadingLimit", "Limits", "Robust",
    "row_names", "CONVENTION", "SI_UNITS"]

#: the angle convention of field balancing, in words (as it always was)
CONVENTION = ("angles and phases in degrees, counted in the same sense as the trial angles and the "
              "phase readings (they must agree)")

#: the SI unit of each reading kind, as JSON reports it
SI_UNITS = {"displacement": "m", "velocity": "m/s", "acceleration": "m/s^2"}


class Plain:
    """A record whose JSON is its fields, in order (records in it likewise, tuples as lists)."""

    def to_json(self) -> dict[str, Any]:
        return {f.name: _plain(getattr(self, f.name)) for f in fields(self)}  # type: ignore[arg-type]


def _plain(v: Any) -> Any:
    if isinstance(v, float) and not math.isfinite(v):
        return None  # an unlimited mass
    if isinstance(v, tuple):
        return [_plain(x) for x in v]
    if isinstance(v, Mapping):
        return {k: _plain(x) for k, x in v.items()}
    if hasattr(v, "to_json"):
        return v.to_json()
    return {f.name: _plain(getattr(v, f.name)) for f in fields(v)} if is_dataclass(v) else v


@dataclass(frozen=True)
class FieldCorrection:
    """One plane's correction: ``correction`` kg e^{i angle} to add with the trial removed (at
    ``radius``, m, when given; angles in the trial angles' sense), ``correction_trial_on``
    with that plane's trial left on."""

    name: str
    correction: complex
    correction_trial_on: complex
    radius: float | None = None

    mass = property(lambda self: abs(self.correction), doc="kg")
    angle_deg = property(lambda self: deg(self.correction), doc="deg, [0, 360)")
    mass_trial_on = property(lambda self: abs(self.correction_trial_on), doc="kg")
    angle_trial_on_deg = property(lambda self: deg(self.correction_trial_on), doc="deg, [0, 360)")

    def to_json(self) -> dict[str, Any]:
        return {"name": self.name, "mass": self.mass, "angle_deg": self.angle_deg,
                "mass_trial_on": self.mass_trial_on, "angle_trial_on_deg": self.angle_trial_on_deg,
                "radius": None if self.radius is None else float(self.radius)}


@dataclass(frozen=True)
class FieldResidual(Plain):
    """A predicted reading (the readings' unit and measure; its angle in the instrument's
    phase convention) and the reading before."""

    sensor: str
    speed: str
    amplitude: float
    angle_deg: float
    initial: float


def row_names(sensors: Sequence[str], speeds: Sequence[tuple[str, Any]], n: int) -> list[tuple[str, str]]:
    """(sensor, speed) of each of ``n`` readings: reading k is sensor ``k % len(sensors)`` at
    speed ``k // len(sensors)`` (sensors numbered from 1, speeds unnamed, when not given)."""
    ns = max(len(sensors), 1)
    return [(sensors[k % ns] if sensors else str(k + 1), speeds[k // ns][0] if speeds else "")
            for k in range(n)]


@dataclass(frozen=True)
class FittedPlane(Plain):
    """The masses fitted in one plane (:class:`rbcli.core.field.fit.FittedMass`: mass kg,
    angle_deg, position 1-based or None) and their net correction (mass, angle_deg)."""

    name: str
    positions: int | None
    mass: float
    angle_deg: float
    masses: tuple[FittedMass, ...]


@dataclass(frozen=True)
class DrawerPlane(Plain):
    """A plane's holes as the drawer search took them: angles (deg, hole 1 first), radius
    (m; None: the trial radius), numbering ("with" or "against" the angles), how many
    weights a hole and the plane take, its most mass (kg; inf: any), its drawer (index)."""

    name: str
    holes_deg: tuple[float, ...]
    radius: float | None
    numbering: str
    per_hole: int
    max_weights: int
    max_mass: float | None
    drawer: int


@dataclass(frozen=True)
class DrawerFit(Plain):
    """The weights chosen from the drawer (:mod:`rbcli.core.field.drawer`): the method's
    objective and the largest reading over its limit (<= 1: every limit met), how many
    choices the search evaluated, the drawers ([{mass kg, count or None}]) and the planes."""

    objective: float
    violation: float
    examined: int
    drawers: tuple[tuple[dict, ...], ...]
    planes: tuple[DrawerPlane, ...]


@dataclass(frozen=True)
class Fitted(Plain):
    """The corrections as fitted — rounded, split or from a drawer (kg, deg) — and the
    readings they leave."""

    mass_step: float | None
    angle_step_deg: float | None
    planes: tuple[FittedPlane, ...]
    residuals: tuple[FieldResidual, ...]
    drawer: DrawerFit | None = None

    def to_json(self) -> dict[str, Any]:
        d = super().to_json()
        return d if self.drawer is not None else {k: v for k, v in d.items() if k != "drawer"}


@dataclass(frozen=True)
class PlaneLimit(Plain):
    """A plane's limit (kg at the correction radius, or kg m), what the correction puts there
    (kg; kg m when the trial radius is known), whether it binds, the objective without it."""

    plane: str
    max_mass: float | None
    max_unbalance: float | None
    mass: float
    unbalance: float | None
    active: bool
    objective_without: float | None


@dataclass(frozen=True)
class ReadingLimit(Plain):
    """A reading's limit and its predicted amplitude (the readings' unit), whether it binds,
    the objective without it."""

    sensor: str
    speed: str
    limit: float
    amplitude: float
    active: bool
    objective_without: float | None


@dataclass(frozen=True)
class Limits(Plain):
    """The limits given (JSON ``limits``): met (``feasible``) or not, max |r_k|/L_k, the
    method's objective with them, each plane's and reading's limit."""

    feasible: bool
    violation: float
    objective: float
    planes: tuple[PlaneLimit, ...]
    readings: tuple[ReadingLimit, ...]


@dataclass(frozen=True)
class Robust(Plain):
    """A robust fit (JSON ``robust``): Huber's weight of each reading and the readings it
    discounted ("sensor" or "sensor at speed"); ``threshold`` in Rayleigh scales."""

    method: str
    threshold: float
    weights: tuple[float, ...]
    discounted: tuple[str, ...]


@dataclass(frozen=True)
class SeverityRow(Plain):
    """One reading judged (mm/s r.m.s. values in m/s, SI): before and predicted after."""

    sensor: str
    speed: str
    before: float
    before_zone: str
    after: float
    after_zone: str


@dataclass(frozen=True)
class Severity(Plain):
    """ISO 20816-3 zones of the readings: group, foundation, the A/B, B/C, C/D boundaries (m/s
    r.m.s.), whether "after" is of the masses "fitted" or "computed"."""

    standard: str
    group: int
    foundation: str
    boundaries: tuple[float, float, float]
    after_is: str
    readings: tuple[SeverityRow, ...]


@dataclass(frozen=True)
class SuggestedTrial(Plain):
    """A trial mass sized before the run: kg at ``radius`` (m) and ``speed`` (rad/s), a
    ``fraction`` of the static ``bearing_load`` (N) as its ``force`` (N); with coefficients, the
    change it should make to each reading (reading unit) and that over the reading."""

    plane: str
    mass: float
    radius: float
    speed: float
    bearing_load: float
    bearing_load_from: str
    fraction: float
    force: float
    expected_change: tuple[float, ...] | None
    expected_change_ratio: tuple[float, ...] | None


@dataclass(frozen=True)
class Conventions(Plain):
    """How angles and readings were counted: the instrument's ``phase`` ("lag", "lead"),
    ``angle_sense`` ("with", "against" the rotation), ``rotation`` ("cw", "ccw"; None: unsaid
    each), whether the phases were mirrored into the angles' sense, all of it in words."""

    phase: str | None
    angle_sense: str | None
    rotation: str | None
    converted: bool
    text: str


def convention_text(phase: str | None, angle_sense: str | None, rotation: str | None, converted: bool) -> str:
    """The conventions of a job in one sentence."""
    if phase is None and angle_sense is None and rotation is None:
        return CONVENTION
    parts = []
    if angle_sense is not None:
        parts.append(f"trial and correction angles in degrees from the reference mark, counted "
                     f"{angle_sense} the rotation")
    else:
        parts.append("trial and correction angles in degrees from the reference mark")
    if rotation is not None:
        parts.append(f"the rotor turns {'clockwise' if rotation == 'cw' else 'counterclockwise'} "
                     "seen from where the angles are read")
    if phase is not None:
        grows = "against" if phase == "lag" else "with"
        parts.append(f"phases are phase {phase} (growing {grows} the rotation)"
                     + ("; mirrored into the angles' sense" if converted else
                        ", the same sense as the angles"))
    else:
        parts.append("phases counted in the same sense as the angles")
    return "; ".join(parts)


@dataclass(frozen=True)
class FieldBalanceResult(Result):
    """What ``rbcli field-balance`` reports: readings complex (SI or bare, the angles' sense),
    ``alpha[k][j]`` per kg at plane j's trial radius, masses kg, radii m; ``method`` None: a
    classic job."""

    planes: int
    initial: tuple[complex, ...]
    runs: tuple[tuple[complex, ...], ...]
    corrections: tuple[FieldCorrection, ...]
    alpha: tuple[tuple[complex, ...], ...]
    trial_masses: tuple[complex, ...]
    radii: tuple[float, float] | None
    cond: float | None
    det: complex | None
    ill_conditioned: bool
    small_response: tuple[bool, ...]
    residual_values: tuple[complex, ...]
    cumulative: bool
    reading_kind: str | None = None
    warnings: tuple[str, ...] = ()
    method: str | None = None
    sensors: tuple[str, ...] = ()
    run_speeds: tuple[tuple[str, float | None], ...] = ()
    plane_names: tuple[str, ...] = ()
    plane_radii: tuple[tuple[float, float] | None, ...] = ()
    residuals: tuple[FieldResidual, ...] = ()
    weights: tuple[float, ...] | None = None
    significance_factors: tuple[float, ...] = ()
    significance_limit: float = 0.2
    measure: str | None = None
    measures_converted: tuple[tuple[str, str, int], ...] = ()
    gravity: bool = False
    conventions: Conventions | None = None
    fitted: Fitted | None = None
    severity: Severity | None = None
    suggested_trial: tuple[SuggestedTrial, ...] = ()
    coefficients_from: str | None = None
    job: str | None = None
    name: str | None = None
    notes: tuple[str, ...] = ()
    limits: Limits | None = None
    robust: Robust | None = None

    @property
    def extended(self) -> bool:
        return self.method is not None or bool(self.suggested_trial)

    @property
    def reading_unit(self) -> str | None:
        """The readings' SI unit ("m", "m/s", "m/s^2"; None: bare)."""
        return None if self.reading_kind is None else SI_UNITS[self.reading_kind]

    @property
    def angle_convention(self) -> str:
        """The conventions in words (JSON ``angle_convention``)."""
        return CONVENTION if self.conventions is None else self.conventions.text

    def row_names(self) -> list[tuple[str, str]]:
        """(sensor, speed) of each reading, in order."""
        return row_names(self.sensors, self.run_speeds, len(self.initial))

    # --- JSON

    def to_json(self) -> dict[str, Any]:
        """The document ``rbcli field-balance --json`` prints."""
        conventions = None if self.conventions is None else self.conventions.to_json()
        if not self.corrections:  # a trial suggestion only
            return {"suggested_trial": [s.to_json() for s in self.suggested_trial],
                    "conventions": conventions, "angle_convention": self.angle_convention,
                    "warnings": list(self.warnings)}
        ext = self.extended
        out: dict[str, Any] = {"planes": self.planes}
        if ext:
            out.update(method=self.method, sensors=list(self.sensors),
                       speeds=[{"name": n, "speed": w} for n, w in self.run_speeds])
        out.update(
            corrections=[c.to_json() for c in self.corrections],
            influence=[[{"magnitude": abs(a), "angle_deg": deg(a)} for a in row] for row in self.alpha],
            trials=[{"mass": abs(t), "angle_deg": deg(t)} for t in self.trial_masses],
            trial_radius=None if self.radii is None else float(self.radii[0]),
            readings=self._readings_json())
        if ext:
            out.update(self._residuals_json())
        if self.planes == 2 or (ext and self.cond is not None):
            out["cond"] = float(self.cond)
            if len(self.alpha) == len(self.alpha[0]):  # square: |det|, null when it overflows
                out["det_magnitude"] = None if self.det is None else float(abs(self.det))
            out["ill_conditioned"] = bool(self.ill_conditioned)
        if ext:
            out.update(significance=[{"plane": n, "factor": f, "flagged": f <= self.significance_limit}
                                     for n, f in zip(self.plane_names, self.significance_factors)],
                       significance_limit=self.significance_limit)
        out.update(small_response=[bool(s) for s in self.small_response],
                   predicted_residual=[float(abs(v)) for v in self.residual_values],
                   cumulative=bool(self.cumulative))
        if ext:
            out.update(fitted=None if self.fitted is None else self.fitted.to_json(),
                       severity=None if self.severity is None else self.severity.to_json(),
                       suggested_trial=[s.to_json() for s in self.suggested_trial],
                       coefficients_from=self.coefficients_from, conventions=conventions, job=self.job,
                       name=self.name, notes=list(self.notes))
            if self.limits is not None or self.robust is not None:
                out.update(limits=_plain(self.limits), robust=_plain(self.robust))
        out.update(angle_convention=self.angle_convention, warnings=list(self.warnings))
        return out

    def _readings_json(self) -> dict[str, Any]:
        out: dict[str, Any] = {"kind": self.reading_kind or "relative", "unit": self.reading_unit}
        if self.extended:
            out.update(measure=self.measure, converted=[{"from": a, "to": b, "count": n}
                                                        for a, b, n in self.measures_converted],
                       g="standard gravity 9.80665 m/s^2 (an acceleration)" if self.gravity else None)
        return out

    def _residuals_json(self) -> dict[str, Any]:
        amps = [r.amplitude for r in self.residuals]
        out: dict[str, Any] = {"residuals": [r.to_json() for r in self.residuals], "residual_max": max(amps),
                               "residual_rms": math.sqrt(sum(a * a for a in amps) / len(amps))}
        if self.weights is not None:
            out["weights"] = list(self.weights)
        return out

    # --- stored coefficients

    def coefficients_document(self) -> dict[str, Any]:
        """The file ``--save-coefficients`` writes (:mod:`rbcli.io.field.coefficients`)."""
        rows = self.row_names()
        speeds = list(self.run_speeds) or [("", None)]
        sensors = list(self.sensors) or [str(k + 1) for k in range(len(self.initial))]
        radii = self.plane_radii or (self.radii,) * self.planes
        names = self.plane_names or plane_names(self.planes)
        conv = self.conventions
        doc = {
            "format": FORMAT,
            "version": VERSION,
            "fingerprint": "",
            "written_by": f"rbcli {__version__} field-balance",
            "job": self.name,
            "description": (
                "alpha[k][j] = re + i im: the change of reading k (SI, or the relative scale; in the "
                "measure given; phases in the trial angles' sense) per kg of trial mass in plane j at its "
                "trial radius. Reuse: rbcli field-balance --coefficients FILE --initial ... (a trim run) "
                "at the same speeds, sensors and radii. Edited, it is refused (fingerprint)."),
            "influence": {
                "reading_kind": self.reading_kind,
                "reading_unit": self.reading_unit,
                "measure": self.measure,
                "per": "kg of trial mass at the plane's trial radius",
            },
            "conventions": {
                "phase": None if conv is None else conv.phase,
                "angle_sense": None if conv is None else conv.angle_sense,
                "rotation": None if conv is None else conv.rotation,
                "text": self.angle_convention,
            },
            "sensors": sensors,
            "speeds": [{"name": n, "speed": w} for n, w in speeds],
            "planes": [{"name": names[j], "trial_radius": None if radii[j] is None else radii[j][0]}
                       for j in range(self.planes)],
            "rows": [{"sensor": s, "speed": v} for s, v in rows],
            "coefficients": [[{"re": a.real, "im": a.imag, "magnitude": abs(a), "angle_deg": deg(a)}
                              for a in row] for row in self.alpha],
        }
        return {**doc, "fingerprint": fingerprint(doc)}
