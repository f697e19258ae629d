"""The result of :func:`rbcli.whirl`: frozen values whose attribute names are the JSON keys
(read-only arrays; ``to_json()`` is ``rbcli whirl --json`` less ``file``): SI, degrees under
``_deg`` keys, % under ``_percent`` keys. Each nested class is a JSON object; its keys, units
and meaning are in one place, the man page's JSON section (``MANUAL["whirl"]``,
:mod:`rbcli.cli.whirl`)."""

from __future__ import annotations

import dataclasses
import functools
from dataclasses import dataclass
from typing import Any

from rbcli.api.result import Result, jsonable
from rbcli.errors import ExitStatus

__all__ = ["CONVENTIONS", "WhirlResult", "RotorData", "BearingData", "BearingTableData", "Mode",
           "Campbell", "CriticalSpeed", "NoCrossing", "ThresholdRow", "Stability", "UnbalanceRow",
           "ResponseBearing", "PeakRow", "AtSpeed", "ResponseData", "MarginCheck", "Margins",
           "CriticalMap", "readonly", "to_json"]

#: the conventions every output states (JSON ``conventions``)
CONVENTIONS: dict[str, str] = {
    "speeds": "rad/s (tables also in rpm); the rotor spins about +z of the shaft frame",
    "frequencies": "whirl frequencies in rad/s, seen in the fixed frame of the bearings",
    "whirl": "forward: the orbit turns the same way as the spin; backward: the opposite way; "
             "linear: a straight-line orbit (forward and backward parts equal); none: no "
             "oscillation (overdamped)",
    "positions": "m along the shaft, z = 0 at the shaft point (through)",
    "stiffness": "N/m; x and y are the shaft frame's axes with the rotor at angle 0 (x on the "
                 "0 deg mark); the bearings do not turn; F_x = -(kxx d_x + kxy d_y), F_y = "
                 "-(kyx d_x + kyy d_y)",
    "damping": "N s/m, likewise on the velocities",
    "tables": "a bearing's coefficients against speed are interpolated linearly in the speed "
              "between rows, never extrapolated (speeds outside every table are refused)",
    "forward_share": "the forward part of a mode's whirl by kinetic weight: 1 forward circular, "
                     "0 backward circular, 0.5 a straight line; per bearing, of its orbit",
    "angles": "deg in the rotor frame, from the 0 deg mark in the direction of rotation (as "
              "balance); a phase is the angle of the high spot when the motion is largest",
    "amplitudes": "displacement: m, semi-major axis of the orbit; force: N, semi-major axis "
                  "of the force the rotor exerts on the bearing",
    "margins": "% of the minimum operating speed (critical speed below it) or of the maximum "
               "operating speed (above it)",
}


def readonly(a: Any):
    """A float ndarray that cannot be written."""
    import numpy as np

    out = np.array(a, dtype=float)
    out.setflags(write=False)
    return out


def to_json(obj: Any) -> Any:
    """The JSON tree of a result value, arrays kept (:func:`jsonable` makes it plain):
    dataclasses by their fields (then the extra keys of ``_json_extra``), tuples as lists."""
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        d = {f.name: to_json(getattr(obj, f.name)) for f in dataclasses.fields(obj)
             if not f.name.startswith("_") and f.metadata.get("json", True)}
        extra = getattr(obj, "_json_extra", None)
        if extra is not None:
            d.update({k: to_json(v) for k, v in extra().items()})
        return d
    if isinstance(obj, (list, tuple)):
        return [to_json(x) for x in obj]
    return obj


class _Json:
    """A nested value of the result: its JSON is its fields (``to_json()``)."""

    def to_json(self) -> Any:
        return jsonable(to_json(self))


def _hidden(**default: Any) -> Any:
    """A field that is not a JSON key (kept for the renderer)."""
    return dataclasses.field(metadata={"json": False}, **default)


@dataclass(frozen=True, eq=False)
class RotorData(_Json):
    """The rigid rotor taken from the body (JSON ``rotor``)."""

    mass: float
    com: float
    polar_moment: float
    transverse_moment: float
    transverse_moments: tuple[float, float]
    asymmetry: float
    tilt_deg: float
    eccentricity: float
    static_unbalance: float
    static_unbalance_angle_deg: float
    couple_unbalance: float
    couple_unbalance_angle_deg: float


@dataclass(frozen=True, eq=False)
class BearingTableData(_Json):
    """A bearing's coefficients against speed: speeds (S, rad/s); kxx, kxy, kyx, kyy (S,
    N/m); cxx, cxy, cyx, cyy (S, N s/m); source (the file it came from)."""

    speeds: Any
    kxx: Any
    kxy: Any
    kyx: Any
    kyy: Any
    cxx: Any
    cxy: Any
    cyx: Any
    cyy: Any
    source: str


@dataclass(frozen=True, eq=False)
class BearingData(_Json):
    """One bearing (JSON ``bearings``); tabled coefficients at ``modes_speed``."""

    plane: float
    stiffness: tuple[float, float]
    cross_stiffness: tuple[float, float]
    damping: tuple[float, float]
    name: str
    cross_damping: tuple[float, float]
    table: BearingTableData | None


@dataclass(frozen=True, eq=False)
class Mode(_Json):
    """A whirl mode at one speed (JSON ``modes``)."""

    frequency: float
    whirl: str
    kind: str
    node: float | None
    damping_ratio: float
    log_decrement: float | None
    stable: bool
    forward_share: float
    bearing_forward_share: tuple[float, ...]


@dataclass(frozen=True, eq=False)
class Campbell(_Json):
    """The Campbell diagram (JSON ``campbell``)."""

    speeds: Any
    frequencies: Any
    whirl: Any
    damping_ratio: Any
    log_decrement: Any
    kind: Any
    branch: Any


@dataclass(frozen=True, eq=False)
class CriticalSpeed(_Json):
    """A critical speed (JSON ``critical_speeds``)."""

    speed: float
    order: int
    mode: str
    whirl: str
    node: float | None
    damped_speed: float | None
    damping_ratio: float | None
    log_decrement: float | None
    in_range: bool
    excited: bool | None
    forward_share: float


@dataclass(frozen=True, eq=False)
class NoCrossing(_Json):
    """A branch that never meets its n× line (JSON ``no_crossings``): ``reason`` "gyroscopic"
    (n It < Ip), "coincident" (n It = Ip: met only at infinite speed) or "range"."""

    order: int
    whirl: str
    mode: str
    reason: str
    polar_moment: float
    transverse_moment: float
    searched: tuple[float, float] | None

    @property
    def explanation(self) -> str:
        """The reason in words."""
        n = self.order
        line = "1×" if n == 1 else f"{n}×"
        if self.reason == "range":
            lo, hi = self.searched or (0.0, 0.0)
            return (f"the {self.whirl} {self.mode} whirl does not meet the {line} line between "
                    f"{lo:.6g} and {hi:.6g} rad/s (the speeds searched)")
        nIt = f"{n} It = {n * self.transverse_moment:.6g}" if n != 1 else f"It = {self.transverse_moment:.6g}"
        rel = "=" if self.reason == "coincident" else ">"
        return (f"the forward conical whirl never meets the {line} line: Ip = "
                f"{self.polar_moment:.6g} kg m² {rel} {nIt} kg m², so the gyroscopic stiffening "
                f"Ip Ω keeps its frequency above {line} the speed at every speed "
                + ("(it approaches the line only as the speed grows without bound)"
                   if self.reason == "coincident" else "(a disk-like rotor)"))

    def _json_extra(self) -> dict[str, Any]:
        return {"explanation": self.explanation}


@dataclass(frozen=True, eq=False)
class ThresholdRow(_Json):
    """A mode's growth rate crossing zero, Re lambda = 0 (JSON ``stability.thresholds``)."""

    speed: float
    change: str
    mode: int
    whirl: str
    kind: str
    frequency: float


@dataclass(frozen=True, eq=False)
class Stability(_Json):
    """Stability over the speed range (JSON ``stability``); ``threshold_speed`` is the first
    onset, or the range's start when a mode grows there."""

    stable_in_range: bool
    onset_speeds: tuple[float, ...]
    least_damping_ratio: float
    least_damping_speed: float
    stable_at_speed: bool | None
    threshold_speed: float | None
    unstable_from_start: bool
    thresholds: tuple[ThresholdRow, ...]


@dataclass(frozen=True, eq=False)
class UnbalanceRow(_Json):
    """An unbalance driving the response: plane (m along the shaft), amount (kg m),
    angle_deg (rotor frame)."""

    plane: float
    amount: float
    angle_deg: float


@dataclass(frozen=True, eq=False)
class ResponseBearing(_Json):
    """One bearing's response over the speeds (JSON ``response.bearings``)."""

    plane: float
    displacement: Any
    displacement_minor: Any
    displacement_phase_deg: Any
    force: Any
    force_phase_deg: Any


@dataclass(frozen=True, eq=False)
class PeakRow(_Json):
    """A response peak (JSON ``response.peaks``); ``basis``, how the AF was found: "half-power";
    "damping ratio", 1/(2 zeta) of the nearest driven mode, where the half-power band runs into
    another peak; "undamped"; "undefined"."""

    bearing: int
    plane: float
    speed: float
    amplitude: float | None
    amplification_factor: float | None
    half_power: tuple[float, float] | None
    mode: str | None
    whirl: str | None
    undamped: bool
    basis: str


@dataclass(frozen=True, eq=False)
class AtSpeed(_Json):
    """A bearing at the (maximum) operating speed (JSON ``response.at_speed``)."""

    plane: float
    displacement: float
    displacement_phase_deg: float
    force: float
    force_phase_deg: float
    rigid_force: float | None


@dataclass(frozen=True, eq=False)
class ResponseData(_Json):
    """The unbalance response (JSON ``response``)."""

    source: str
    unbalance: tuple[UnbalanceRow, ...]
    speeds: Any
    bearings: tuple[ResponseBearing, ...]
    peaks: tuple[PeakRow, ...]
    at_speed: tuple[AtSpeed, ...]


@dataclass(frozen=True, eq=False)
class MarginCheck(_Json):
    """A critical speed (a response peak) judged by the API rule (JSON ``margins.checks``);
    basis "undefined" is judged as AF infinite."""

    bearing: int | None
    plane: float | None
    speed: float
    mode: str | None
    amplification_factor: float | None
    basis: str
    position: str
    margin_percent: float
    required_margin_percent: float
    passed: bool


@dataclass(frozen=True, eq=False)
class Margins(_Json):
    """The separation margins: rule (the standard's clause), operating_speed [min, max]
    rad/s, checks, passed (every check passed; null when nothing could be judged)."""

    rule: str
    operating_speed: tuple[float, float]
    checks: tuple[MarginCheck, ...]
    passed: bool | None


@dataclass(frozen=True, eq=False)
class CriticalMap(_Json):
    """The undamped critical speed map (JSON ``critical_speed_map``): every bearing isotropic of
    each ``stiffness``, undamped; where a bearing's stiffness curve meets a branch estimates
    that critical speed."""

    stiffness: Any
    speeds: Any
    whirl: tuple[str, ...]
    mode: tuple[str, ...]
    bearings: tuple[dict, ...]


#: the rule, as every output cites it
API_RULE = ("API 617 (8th ed.) 6.8.2.4-6.8.2.5 / API 684 (2nd ed.) SP6.8.2.1, SP6.8.2.10: "
            "AF = Nc/(N2 - N1) at the half-power points (where the band runs into another "
            "peak, AF = 1/(2 zeta) of the mode); AF < 2.5 needs no margin; below the "
            "minimum operating speed SM >= min(16, 17 (1 - 1/(AF - 1.5))) %, above the maximum "
            "SM >= min(26, 10 + 17 (1 - 1/(AF - 1.5))) %")


@dataclass(frozen=True, eq=False)
class WhirlResult(Result):
    """The rotor on its bearings (see :func:`rbcli.whirl`); attribute names are the JSON keys
    (plus ``name``). Not in the JSON (for the tables): ``units`` (the body's), ``source``,
    ``isotropic``, ``options`` (:class:`rbcli.api.params.Options`, echoed in the tables).
    """

    name: str
    conventions: dict
    shaft: tuple[float, float, float]
    shaft_source: str
    through: Any
    through_source: str
    rotor: RotorData
    bearings: tuple[BearingData, ...]
    speed_range: tuple[float, float]
    speed_range_source: str
    orders: tuple[int, ...]
    speed: tuple[float, float] | None
    symmetry_tol: float
    modes_speed: float
    modes: tuple[Mode, ...]
    campbell: Campbell
    critical_speeds: tuple[CriticalSpeed, ...]
    no_crossings: tuple[NoCrossing, ...]
    stability: Stability
    response: ResponseData
    margins: Margins | None
    critical_speed_map: CriticalMap
    warnings: tuple[str, ...]
    units: dict = _hidden(default_factory=dict)
    source: str = _hidden(default="")
    isotropic: bool = _hidden(default=True)
    options: Any = _hidden(default=None)

    @property
    def return_code(self) -> int:
        """1 when the operating speed fails the separation-margin rule or a mode grows
        there; else 0."""
        if self.margins is not None and self.margins.passed is False:
            return int(ExitStatus.CHECK_FAILED)
        if self.stability.stable_at_speed is False:
            return int(ExitStatus.CHECK_FAILED)
        return int(ExitStatus.OK)

    def to_json(self) -> dict[str, Any]:
        """``rbcli whirl --json`` less ``file`` (built once: its lists are shared by every
        call, its top level is a new dict each time)."""
        return dict(self._document)

    @functools.cached_property
    def _document(self) -> dict[str, Any]:
        d = to_json(self)
        d["warnings"] = list(self.warnings)  # Notes: --json spells their options
        return jsonable(d)
