"""The heavy top as a service: :func:`top` (``rbcli top``): the exact closed-form motion
of a symmetric top on a fixed pivot (Goldstein, Poole and Safko §5.7), optionally checked
against a numerical integration (``verify=True``)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from rbcli.api import check
from rbcli.api import options as op
from rbcli.api.check import Quantity
from rbcli.api.commands import MAX_SAMPLES, TOP
from rbcli.api.commands import TOP_SAMPLES as DEFAULT_SAMPLES
from rbcli.api.inertia import rim_note
from rbcli.api.params import Options, function, read
from rbcli.api.result import Result, frozen, jsonable
from rbcli.core import top as core
from rbcli.core import topbody, topverify
from rbcli.core.inertia import body_mass_props
from rbcli.core.scale import body_scale
from rbcli.core.symmetry import AxialSymmetry
from rbcli.core.toppath import TopState
from rbcli.errors import ExitStatus, InputError, Location, Note, ParamError, literal

if TYPE_CHECKING:  # pragma: no cover
    from numpy.typing import ArrayLike

    from rbcli.body.model import Body

__all__ = ["TopResult", "parse", "run", "top", "plausibility", "DEFAULT_SAMPLES", "MAX_SAMPLES"]

#: standard gravity, m/s² (the default of ``g``)
STANDARD_GRAVITY = core.STANDARD_GRAVITY
#: nutation periods that ``verify`` integrates and that :meth:`TopResult.default_duration` spans
PERIODS = 3

_OVERFLOW = ("{spin}, {theta_dot}, {phi_dot}, {g}: the values overflow floating point in the "
             "top's equations; give values of a physical size")

#: what a missing required parameter is, for its message
_REQUIRED = {"spin": "the spin w3 about the symmetry axis, e.g. {spin} 150 (rad/s) or {spin} '3000 rpm'",
             "theta": "the start tilt of the axis from the upward vertical, e.g. {theta} 30 (degrees)"}


def parse(body: Body | None, **kwargs: Any) -> Options:
    """The keyword arguments of :func:`top` read for ``body``: :class:`rbcli.api.params.Options`
    in SI (``theta`` rad), the defaults in place of what was not given (rates 0, standard
    gravity, :data:`DEFAULT_SAMPLES` rows); ``duration`` stays None (three nutation periods,
    :meth:`TopResult.default_duration`).

    Raises
    ------
    rbcli.InputError
        one line naming the parameter (``theta: ...``).
    """
    for name, what in _REQUIRED.items():
        if kwargs.get(name) is None:
            raise ParamError(name, f"required: {what}")
    o = read(body, TOP, kwargs)
    return o.replace(theta_dot=0.0 if o.theta_dot is None else o.theta_dot,
                     phi_dot=0.0 if o.phi_dot is None else o.phi_dot,
                     g=STANDARD_GRAVITY if o.g is None else o.g, verify=bool(o.verify),
                     samples=DEFAULT_SAMPLES if o.samples is None else int(o.samples))


def plausibility(body: Body, point: Any, spin: float, option: str, axis: Any = None,
                 through: Any = None, typed: bool = False) -> tuple[str, ...]:
    """The plausibility warnings (:mod:`rbcli.core.scale`), located: a pivot
    more than 10 body sizes away, a rim faster than sound (the spin about ``axis`` through
    ``through``, default the com; a top's axis runs from ``through``, its pivot, to the com)."""
    sc = body_scale(body.parts)
    out = []
    if point is not None and not isinstance(point, str) and sc.far(point):
        out.append(op.Units.of(body).far(option, "the pivot", sc.far(point), sc.size))
    com = body_mass_props(body).com
    if axis is None:
        axis = com - np.asarray(through, dtype=float)
    if float(np.linalg.norm(axis)) > 0.0:  # (the pivot at the com: refused later)
        out.append(rim_note(body, "spin", spin, axis, com if through is None else through, typed))
    return tuple(Note(f"{literal(body.source)}: warning: {n.template}") for n in out if n)


def _pivot(body: Body, given: Any) -> tuple[tuple[float, float, float], Note]:
    """The pivot (m, body frame) and where it came from: ``{pivot}``, ``{pivot} com``,
    ``{pivot} origin`` (the parameter, spelled by the caller), ``"the body's pivot"`` or
    ``"the origin, as no pivot was given"``."""
    if isinstance(given, str):
        P = body_mass_props(body).com if given == "com" else (0.0, 0.0, 0.0)
        label = f"{{pivot}} {given}"
    elif given is not None:
        P, label = given, "{pivot}"
    elif body.pivot is not None:
        P, label = body.pivot, "the body's pivot"
    else:
        P, label = (0.0, 0.0, 0.0), "the origin, as no pivot was given"
    return tuple(float(x) for x in P), Note(label)  # type: ignore[return-value]


@dataclass(frozen=True)
class TopResult(Result):
    """The heavy top's motion from the given start: ``body``, ``options`` (:func:`parse`),
    ``pivot_source`` (``{pivot}``, ``"the body's pivot"``...), ``motion``
    (:class:`rbcli.core.top.TopMotion`), with ``verify`` the DOP853 comparison ``verify`` and,
    for a nearly symmetric body, ``real_body`` (not in the verdict), and ``warnings``."""

    body: Body = field(repr=False)
    options: Options
    pivot_source: str
    motion: core.TopMotion = field(repr=False)
    verify: topverify.VerifyResult | None = None
    real_body: topverify.RealBodyCheck | None = None
    warnings: tuple[str, ...] = ()

    @property
    def asymmetry(self) -> AxialSymmetry | None:
        """How far a nearly symmetric body departs from symmetry about the pivot–com axis
        (None when it is symmetric to rounding)."""
        return self.motion.params.asymmetry

    @property
    def asymmetry_effect(self) -> float | None:
        """The relative size of the answer's error from symmetrising the body: of the order
        of its largest departure (the real moment across swings between the two as it spins).
        None when symmetric."""
        a = self.asymmetry
        return None if a is None else a.departure

    @property
    def params(self) -> topbody.TopParams:
        """The top's mass properties about the pivot (kg, m, kg m²)."""
        return self.motion.params

    @property
    def I_com(self) -> float:  # noqa: N802 - the textbook's name
        """kg m², the moment across the axis about the com, I - m l²."""
        p = self.motion.params
        return p.I - p.mass * p.length**2

    @property
    def steady_estimates(self) -> list[float]:
        """rad/s, the fast-top estimates of the steady rates at θ0 (slow, then fast unless
        the axis is horizontal); see :attr:`rbcli.core.top.TopMotion.steady_estimates`."""
        return self.motion.steady_estimates

    def at(self, t: Quantity | ArrayLike) -> TopState:
        """The Euler angles θ, φ, ψ (rad) and their rates (rad/s) at times ``t`` (s: a number,
        a quantity string such as ``"2 min"``, or numbers of any shape, at most
        :data:`rbcli.api.check.MAX_TIMES`): ``result.at(0.1).theta``. Exact (the closed form).

        Raises
        ------
        TypeError
            ``t`` that is not a number, a string or numbers.
        rbcli.InputError
            a time that is not finite, too many times.
        """
        return frozen(self.motion.at(check.times(t, "t")))  # read-only arrays, as every result's

    def default_duration(self) -> float:
        """s, the span ``--csv`` and ``--plot`` cover by default: 3 nutation periods.

        Raises
        ------
        ParamError
            (``duration``) on the separatrix, where there is no nutation period.
        """
        if self.motion.nutation_period is None:
            raise ParamError(
                "duration",
                "the motion is on the separatrix (the axis creeps to the vertical in "
                "infinite time): it has no nutation period and no periodic closed form to sample"
            )
        return PERIODS * self.motion.nutation_period

    def sample(self, duration: Quantity, points: int | None = None) -> TopState:
        """The motion at ``points`` evenly spaced times from 0 to ``duration`` (s, > 0)
        inclusive: by default 400 per nutation period, at least 2000 and at most 200 000
        (what the command line's plot draws); given, from 2 to :data:`MAX_SAMPLES`."""
        duration, points = check.quantity(duration, "duration"), check.count(points, "points")
        duration = read(None, TOP, {"duration": duration}).duration
        if duration is None:
            raise ParamError("duration", "needs the span to sample (s, from t = 0)")
        if points is not None and not 2 <= points <= MAX_SAMPLES:
            raise ParamError("points", f"must be from 2 to {MAX_SAMPLES}, got {points}")
        if points is None:
            tn = self.motion.nutation_period or duration
            points = int(min(200_000, max(2_000, 400 * duration / tn)))
        return self.motion.at(np.linspace(0.0, float(duration), int(points)))

    def to_json(self) -> dict[str, Any]:
        """The JSON of ``rbcli top ... --json``, less ``file``."""
        m = self.motion
        out: dict[str, Any] = m.to_json()
        out["steady_precession_estimates"] = self.steady_estimates if m.steady_precession_rates else []
        out["I_com"] = self.I_com
        pj = m.params.to_json()
        out["axis"] = pj["axis"]
        out["pivot"] = pj["pivot"]
        out["com"] = pj["com"]
        out["pivot_source"] = self.pivot_source
        if self.asymmetry is not None:
            out["asymmetry"] = self.asymmetry.to_json(self.options.symmetry_tol)
        out["name"] = self.body.name
        if self.verify is not None:
            out["verify"] = self.verify.to_json()
            if self.real_body is not None:
                out["verify"]["real_body"] = self.real_body.to_json()
        return jsonable(out)

    @property
    def return_code(self) -> int:
        """1 when ``verify`` was asked for and failed, else 0."""
        if self.verify is not None and not self.verify.passed:
            return int(ExitStatus.CHECK_FAILED)
        return int(ExitStatus.OK)


def run(body: Body, options: Options) -> TopResult:
    """The heavy top for ``options`` (:func:`parse`): the closed form, and the check if asked
    for."""
    o = options
    P, source = _pivot(body, o.pivot)
    warnings = plausibility(body, o.pivot, o.spin, "pivot", through=P, typed=o.unit_typed("spin"))
    mp = body_mass_props(body)
    try:
        with np.errstate(over="ignore", invalid="ignore"):
            params = topbody.top_from_body(mp.mass, mp.com, mp.inertia_com, np.asarray(P),
                                           sym_rtol=o.symmetry_tol)
    except topbody.PivotAtCom as exc:
        if o.pivot is not None:
            raise ParamError("pivot", str(exc)) from None
        raise InputError(str(exc), Location(body.source)) from None
    except InputError:  # already names its parameter (an InputError is a ValueError)
        raise
    except ValueError as exc:
        at = ", ".join(f"{x:.6g}" for x in P)
        raise InputError(f"{exc}; pivot at [{at}] m ({source.template})", Location(body.source)) from None
    try:
        motion = core.analyse(params, o.spin, o.theta, o.theta_dot, o.phi_dot, o.g)
    except (OverflowError, ArithmeticError):
        raise InputError(_OVERFLOW, param="spin") from None
    vals = [motion.a, motion.b, motion.alpha, motion.beta, motion.u1, motion.u2, motion.u3,
            motion.theta1, motion.theta2, motion.critical_spin, motion.horizontal_precession_rate]
    if not all(math.isfinite(v) for v in vals):
        raise InputError(_OVERFLOW, param="spin")
    check = real = None
    if o.verify:
        try:
            check = topverify.verify(motion, periods=PERIODS)
            if params.asymmetry is not None:
                real = topverify.verify_real_body(motion, periods=PERIODS)
        except InputError:  # already names its parameter (an InputError is a ValueError)
            raise
        except (ValueError, OverflowError, ArithmeticError) as exc:
            raise ParamError("verify", str(exc)) from None
    if params.asymmetry is not None:
        warnings += (Note(f"{literal(body.source)}: warning: the body is not exactly symmetric about "
                          f"the pivot–com axis: {params.asymmetry.percent()}; the answer is for the "
                          f"symmetrised body ({{symmetry_tol}} {o.symmetry_tol * 100:g} %)"),)
    return TopResult(body=body, options=o, pivot_source=source, motion=motion, verify=check,
                     real_body=real, warnings=warnings)


@function(TOP)
def top(body: Body, **kwargs: Any) -> TopResult:
    """A heavy symmetric top or gyroscope on a fixed pivot: precession, nutation, sleeping.

    The symmetry axis runs from ``pivot`` through the com; the top spins at ``spin`` and starts
    tilted by ``theta`` from the upward vertical (released from rest unless ``theta_dot`` or
    ``phi_dot``). Exact closed form (Goldstein, Poole and Safko, *Classical Mechanics*, 3rd
    ed., §5.7); ``duration`` and ``samples`` are those of :meth:`TopResult.sample`.

    Parameters
    ----------
    body : Body
    {parameters}

    Returns
    -------
    TopResult
        ``motion``, ``at(t)``, ``to_json()`` (as ``rbcli top --json``), ``return_code``.

    Raises
    ------
    TypeError, rbcli.InputError
        A wrong type (:mod:`rbcli.api.check`) or value, naming the parameter; a body that
        is not a top about this pivot.

    Examples
    --------
    >>> import rbcli
    >>> r = rbcli.top(rbcli.load("examples/top.yaml"), spin=150, theta=30, g=9.81)
    >>> round(r.motion.nutation_period, 6), r.motion.path
    (0.142133, 'cusps')"""
    return run(body, parse(body, **kwargs))
