"""The heavy top as a service: :func:`top` (``rbcli top``).

``rbcli.top(body, spin=..., theta=...)`` is ``rbcli top BODY --spin ... --theta ...``:
the exact closed-form motion of a symmetric top on a fixed pivot (Goldstein, Poole and
Safko, *Classical Mechanics*, 3rd ed., §5.7), optionally checked against a numerical
integration (``verify=True``). The gyrocompass is :mod:`rbcli.api.gyrocompass`. Values
are read by :mod:`rbcli.api.options` (SI numbers, or strings as typed on the command
line); errors are :class:`rbcli.errors.InputError` with the command line's message.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from rbcli.api import check
from rbcli.api import options as op
from rbcli.api.check import Point, Quantity
from rbcli.api.options import symmetry_tolerance
from rbcli.api.result import Result, jsonable
from rbcli.errors import ExitStatus, InputError, Location, Note, ParamError, literal

if TYPE_CHECKING:  # pragma: no cover
    from numpy.typing import ArrayLike

    from rbcli.core.top import TopMotion
    from rbcli.core.topbody import TopParams
    from rbcli.core.toppath import TopState
    from rbcli.core.symmetry import AxialSymmetry
    from rbcli.core.topverify import RealBodyCheck, VerifyResult
    from rbcli.body.model import Body

__all__ = ["TopOptions", "TopResult", "run", "top", "series", "DEFAULT_SAMPLES", "MAX_SAMPLES"]

#: the checker of each keyword argument of :func:`top` (:mod:`rbcli.api.check`)
KINDS = {"pivot": check.vector, "spin": check.quantity, "theta": check.quantity,
         "theta_dot": check.quantity, "phi_dot": check.quantity, "g": check.quantity,
         "verify": check.flag, "symmetry_tol": check.quantity, "duration": check.quantity,
         "samples": check.count}

#: rows of the path's time series: the default and the most (``top --csv``)
DEFAULT_SAMPLES = 600
MAX_SAMPLES = 1_000_000

#: standard gravity, m/s² (the default of ``g``)
STANDARD_GRAVITY = 9.80665
#: nutation periods that ``verify`` integrates and that :meth:`TopResult.default_duration` spans
PERIODS = 3

_OVERFLOW = ("{spin}, {theta_dot}, {phi_dot}, {g}: the values overflow floating point in the "
             "top's equations; give values of a physical size")


# ----------------------------------------------------------------------------- top


@dataclass(frozen=True)
class TopOptions:
    """The heavy top's inputs, parsed and checked (SI), with where the pivot came from.

    Attributes
    ----------
    spin : float — rad/s, S = ω3, the angular velocity's component along the axis (≠ 0)
    theta : float — rad, the start tilt from the upward vertical, in (0, π)
    theta_dot, phi_dot : float — rad/s, the start rates θ' and φ'
    g : float — m/s², > 0
    pivot : tuple[float, float, float] — m, the fixed point in the body frame
    pivot_source : Note — where it came from: ``{pivot}``, ``{pivot} com``,
        ``{pivot} origin`` (the parameter, spelled by the caller), ``"the body's pivot"`` or ``"the origin, as no pivot was given"``
    pivot_given : bool — the pivot was an option (errors about it then name ``--pivot``)
    verify : bool — integrate numerically and compare
    duration : float or None — s, the span of the path's time series (None: three nutation
        periods, :meth:`TopResult.default_duration`)
    samples : int — rows of that series
    symmetry_tol : float — how far from symmetric about the pivot–com axis the body may be
        (a fraction; default 0.01): within it the answer is for the symmetrised body, with a
        warning; beyond it the body is refused
    pivot_as_given : "com", "origin", (3,) tuple or None — ``pivot`` as given (m)
    given : tuple of str — the parameters the caller gave
    typed : tuple of (str, str) — (parameter, unit) for each value typed with a unit
        (``"0.5 g"``: ``("mass_step", "g")``), the unit the options table shows it in
    warnings : tuple of str — a pivot or a rim speed far outside the body's scale
    """

    spin: float
    theta: float
    theta_dot: float
    phi_dot: float
    g: float
    pivot: tuple[float, float, float]
    pivot_source: str
    pivot_given: bool = False
    verify: bool = False
    symmetry_tol: float = 0.01
    pivot_as_given: Any = None
    duration: float | None = None
    samples: int = DEFAULT_SAMPLES
    given: tuple[str, ...] = ()
    #: parameter -> the unit the caller typed after its number (the options table echoes in it)
    typed: tuple[tuple[str, str], ...] = ()
    warnings: tuple[str, ...] = ()

    @classmethod
    def parse(cls, body: Body, *, pivot: Point | None = None, spin: Quantity | None = None,
              theta: Quantity | None = None, theta_dot: Quantity | None = None,
              phi_dot: Quantity | None = None, g: Quantity | None = None,
              verify: bool = False, symmetry_tol: Quantity | None = None,
              duration: Quantity | None = None, samples: int | str | None = None) -> TopOptions:
        """Read and check the values (see :func:`top` for their meaning and units)."""
        span, rows = series(duration, samples)
        if spin is None:
            raise InputError("{spin}: required: the spin w3 about the symmetry axis, e.g. {spin} 150 (rad/s) or {spin} '3000 rpm'",
                             param="spin")
        if theta is None:
            raise InputError("{theta}: required: the start tilt of the axis from the upward vertical, e.g. {theta} 30 (degrees)",
                             param="theta")
        u = op.Units.of(body)
        S = op.finite(u.quantity(spin, "angular_speed", "spin"), "spin")
        if S == 0.0:
            raise ParamError("spin", "must not be 0: a top without spin is a spherical pendulum (it cannot "
                             "stand); give the spin w3, e.g. {spin} 150 or {spin} '3000 rpm'")
        th = op.finite(op.quantity(theta, "angle", "theta", bare="deg"), "theta")
        if not (0.0 < th < math.pi):
            raise ParamError(
                "theta",
                f"the start tilt must be strictly between 0 and 180 degrees, got {theta} "
                "(at 0 or 180 the axis is vertical and the precession angle is undefined; start it "
                "slightly tilted, e.g. {theta} 0.1)"
            )
        thd = 0.0 if theta_dot is None else op.finite(
            u.quantity(theta_dot, "angular_speed", "theta_dot"), "theta_dot")
        phd = 0.0 if phi_dot is None else op.finite(
            u.quantity(phi_dot, "angular_speed", "phi_dot"), "phi_dot")
        gv = STANDARD_GRAVITY if g is None else op.finite(u.quantity(g, "acceleration", "g"), "g")
        if not gv > 0.0:
            raise ParamError("g", f"gravity must be positive (it points down, towards -z), got {g}")
        p_opt = u.point(pivot, "pivot") if pivot is not None else None
        tol = symmetry_tolerance(symmetry_tol)
        P, label = _pivot(body, p_opt)
        given = tuple(p for p, v in (("pivot", pivot), ("spin", spin), ("theta", theta),
                                     ("theta_dot", theta_dot), ("phi_dot", phi_dot), ("g", g),
                                     ("verify", verify or None), ("symmetry_tol", symmetry_tol))
                      if v is not None)
        warns = plausibility(body, u, p_opt, S, "pivot", through=P)
        return cls(spin=S, theta=th, theta_dot=thd, phi_dot=phd, g=gv, pivot=P, pivot_source=label,
                   pivot_given=p_opt is not None, verify=bool(verify), symmetry_tol=tol,
                   pivot_as_given=p_opt if isinstance(p_opt, str) or p_opt is None else tuple(p_opt),
                   duration=span, samples=rows, given=given, typed=tuple(u.typed.items()),
                   warnings=warns)

    @property
    def released(self) -> bool:
        """Released from rest: θ0' = φ0' = 0."""
        return self.theta_dot == 0.0 and self.phi_dot == 0.0


def series(duration: Quantity | None = None, samples: int | str | None = None) -> tuple[float | None, int]:
    """(duration, samples) of the path's time series (``top --csv``, ``--plot``): a positive
    time in s (None: three nutation periods, :meth:`TopResult.default_duration`) and a
    whole number of rows from 2 to :data:`MAX_SAMPLES` (default :data:`DEFAULT_SAMPLES`)."""
    span = None
    if duration is not None:
        span = op.finite(op.quantity(duration, "time", "duration"), "duration")
        if not span > 0.0:
            raise ParamError("duration", f"must be a positive time, got {literal(duration)}")
    rows = DEFAULT_SAMPLES
    if samples is not None:
        try:
            rows = int(samples) if not isinstance(samples, (bool, float)) else None
        except (TypeError, ValueError):
            rows = None
        if rows is None or not 2 <= rows <= MAX_SAMPLES:
            raise ParamError("samples", f"must be from 2 to {MAX_SAMPLES}, got {literal(samples)}")
    return span, rows


def plausibility(body: Body | None, u: op.Units, point: Any, spin: float, option: str,
                  axis: Any = None, through: Any = None) -> tuple[str, ...]:
    """One-line warnings for values far outside the body's scale (issue 13): a pivot more
    than 10 body sizes away, a rim faster than sound (the spin about ``axis`` through
    ``through``: the body's farthest material from that line, issue 24)."""
    if body is None:
        return ()
    import numpy as np

    from rbcli.core.inertia import body_mass_props
    from rbcli.core.scale import SPEED_OF_SOUND, axis_reach, body_scale

    sc = body_scale(body.parts)
    out = []
    if point is not None and not isinstance(point, str) and sc.far(point):
        out.append(Note(f"{literal(body.source)}: warning: "
                        + u.far(option, "the pivot", sc.far(point), sc.size).template))
    com = body_mass_props(body).com
    if axis is None:  # a top: its symmetry axis, from the pivot to the com
        axis = com - np.asarray(through, dtype=float)
    if not float(np.linalg.norm(axis)) > 0.0:  # the pivot at the com: refused later
        return tuple(out)
    v = abs(spin) * axis_reach(body.parts, axis, com if through is None else through)
    if SPEED_OF_SOUND < v < math.inf:
        out.append(Note(f"{literal(body.source)}: warning: {{spin}}: the body's rim would move at "
                        f"{v:.4g} m/s, faster than sound ({SPEED_OF_SOUND:g} m/s); bare angular speeds "
                        f"are in {u.label('angular_speed')}: is a unit missing?"))
    return tuple(out)


def _pivot(body: Body, p_opt: str | list[float] | None) -> tuple[tuple[float, float, float], str]:
    """The pivot (m, body frame) and a label saying where it came from."""
    if isinstance(p_opt, str):
        if p_opt == "com":
            from rbcli.core.inertia import body_mass_props

            P = body_mass_props(body).com
        else:
            P = (0.0, 0.0, 0.0)
        label = f"{{pivot}} {p_opt}"
    elif p_opt is not None:
        P, label = p_opt, "{pivot}"
    elif body.pivot is not None:
        P, label = body.pivot, "the body's pivot"
    else:
        P, label = (0.0, 0.0, 0.0), "the origin, as no pivot was given"
    return tuple(float(x) for x in P), Note(label)  # type: ignore[return-value]


@dataclass(frozen=True)
class TopResult(Result):
    """The heavy top's motion from the given start, and the numerical check if asked for.

    Attributes
    ----------
    body : Body — the body (its name and source label the result)
    options : TopOptions — the inputs as understood (SI)
    motion : TopMotion — the exact motion: mass (kg), length l (m), I and Is about the pivot
        (kg m²) in ``motion.params``; steady precession rates, critical spin, nutation limits
        θ1, θ2 (rad), nutation period (s), mean rates (rad/s), the kind of path, ...
    verify : VerifyResult | None — with ``verify=True``: the largest differences of the axis
        (rad) and the Euler angles from a DOP853 integration, the drift of the energy and of
        the two conserved momenta, and the verdict (``verify.passed``)
    real_body : RealBodyCheck | None — with ``verify=True`` for a nearly symmetric body:
        the real (unsymmetrised) body integrated from the same start, and how far its axis
        (rad), θ and φ get from the closed form (information: not part of the verdict)
    warnings : tuple[str, ...] — located one-line warnings: a nearly symmetric body
    """

    body: Body = field(repr=False)
    options: TopOptions
    motion: TopMotion = field(repr=False)
    verify: VerifyResult | None = None
    real_body: RealBodyCheck | None = None
    warnings: tuple[str, ...] = ()

    @property
    def asymmetry(self) -> AxialSymmetry | None:
        """How far a nearly symmetric body departs from symmetry about the pivot–com axis
        (None when it is symmetric to rounding)."""
        return self.motion.params.asymmetry

    @property
    def asymmetry_effect(self) -> float | None:
        """The relative size of the answer's error from symmetrising the body: of the order
        of its largest departure (the moments across differ by δ; the real body's moment
        across swings between them as it spins). None when symmetric."""
        a = self.asymmetry
        return None if a is None else a.departure

    @property
    def params(self) -> TopParams:
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
        return self.motion.at(check.times(t, "t"))

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
        import numpy as np

        duration, points = check.quantity(duration, "duration"), check.count(points, "points")
        duration = series(duration)[0]
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
        out["pivot_source"] = self.options.pivot_source
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


def run(body: Body, options: TopOptions) -> TopResult:
    """The heavy top for parsed options: the closed form, and the check if asked for."""
    import numpy as np

    from rbcli.core import top as core
    from rbcli.core import topbody
    from rbcli.core.inertia import body_mass_props

    mp = body_mass_props(body)
    P = np.asarray(options.pivot, dtype=float)
    try:
        with np.errstate(over="ignore", invalid="ignore"):
            params = topbody.top_from_body(mp.mass, mp.com, mp.inertia_com, P,
                                        sym_rtol=options.symmetry_tol)
    except topbody.PivotAtCom as exc:
        if options.pivot_given:
            raise ParamError("pivot", str(exc)) from None
        raise InputError(str(exc), Location(body.source)) from None
    except InputError:  # already names its parameter (an InputError is a ValueError)
        raise
    except ValueError as exc:
        at = ", ".join(f"{x:.6g}" for x in P)
        source = getattr(options.pivot_source, "template", options.pivot_source)
        raise InputError(f"{exc}; pivot at [{at}] m ({source})",
                         Location(body.source)) from None
    o = options
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
        from rbcli.core.topverify import verify, verify_real_body

        try:
            check = verify(motion, periods=PERIODS)
            if params.asymmetry is not None:
                real = verify_real_body(motion, periods=PERIODS)
        except InputError:  # already names its parameter (an InputError is a ValueError)
            raise
        except (ValueError, OverflowError, ArithmeticError) as exc:
            raise ParamError("verify", str(exc)) from None
    warnings = o.warnings
    if params.asymmetry is not None:
        warnings += (Note(f"{literal(body.source)}: warning: the body is not exactly symmetric about "
                          f"the pivot–com axis: {params.asymmetry.percent()}; the answer is for the "
                          f"symmetrised body ({{symmetry_tol}} {o.symmetry_tol * 100:g} %)"),)
    return TopResult(body=body, options=o, motion=motion, verify=check, real_body=real,
                     warnings=warnings)


def top(body: Body, *, pivot: Point | None = None, spin: Quantity, theta: Quantity,
        theta_dot: Quantity | None = None, phi_dot: Quantity | None = None,
        g: Quantity | None = None, verify: bool = False, symmetry_tol: Quantity | None = None,
        duration: Quantity | None = None, samples: int | None = None) -> TopResult:
    """A heavy symmetric top or gyroscope on a fixed pivot: precession, nutation, sleeping.

    The body stands on ``pivot``; its symmetry axis runs from the pivot through the centre
    of mass, and it must be symmetric about that axis. It spins at ``spin`` about the axis
    and starts tilted by ``theta`` from the upward vertical, released from rest unless
    ``theta_dot`` or ``phi_dot`` is given. Exact closed form (Goldstein, Poole and Safko,
    *Classical Mechanics*, 3rd ed., §5.7).

    Parameters
    ----------
    body : Body
        From :func:`rbcli.load` or :func:`rbcli.load_text`.
    pivot : str or sequence of 3, optional
        The fixed point: ``"com"``, ``"origin"``, ``[x, y, z]`` (m) or ``"0,0,-20 mm"``.
        Default: the body's ``pivot``, else the origin.
    spin : float or str
        S = ω3, the angular velocity's component along the axis: rad/s, or ``"3000 rpm"``;
        negative spins the other way. Not 0.
    theta : float or str
        The start tilt from the upward vertical, strictly between 0 and 180: degrees (a
        number), or with a unit (``"0.5 rad"``).
    theta_dot, phi_dot : float or str, optional
        The start rates θ' and φ': rad/s or with a unit. Default 0.
    g : float or str, optional
        Gravity, m/s² or with a unit. Default 9.80665.
    verify : bool
        Integrate the equations of motion numerically (DOP853, rtol 1e-12) over 3 nutation
        periods and compare with the closed form; ``return_code`` is then 1 if they differ
        by more than 1e-6 rad or the energy drifts by more than 1e-9. For a nearly
        symmetric body the real body is integrated too (``result.real_body``).
    symmetry_tol : float or str, optional
        How far from symmetric about the pivot–com axis the body may be: a fraction
        (``0.01``) or a percentage (``"1 %"``), at most 10 %. Default 1 %. A body within it
        (and above rounding, 1e-6) is answered for its symmetrised form (the mean moment
        across) with a warning and ``asymmetry`` in the JSON; beyond it, refused.
    duration : float or str, optional
        The span of the path's time series (:meth:`TopResult.sample`, ``top --csv``): s or
        with a unit. Default: three nutation periods.
    samples : int, optional
        Rows of that series, 2 to 1 000 000. Default 600.

    Returns
    -------
    TopResult
        ``result.motion`` (the numbers), ``result.at(t)`` (the angles and rates at times
        ``t``), ``result.to_json()`` (as ``rbcli top --json``), ``result.return_code``.

    Raises
    ------
    TypeError
        An argument of the wrong type, naming the parameter and the type expected
        (:mod:`rbcli.api.check`).
    rbcli.InputError
        Naming the parameter: a value out of range, a body that is not a top
        about this pivot (asymmetric, the pivot at the com, a point mass), values that
        overflow the top's equations.

    Examples
    --------
    >>> import rbcli
    >>> r = rbcli.top(rbcli.load("examples/top.yaml"), spin=150, theta=30, g=9.81)
    >>> round(r.motion.nutation_period, 6), r.motion.path
    (0.142133, 'cusps')
    """
    body = check.body(body)
    kw = check.arguments(KINDS, pivot=pivot, spin=spin, theta=theta, theta_dot=theta_dot,
                         phi_dot=phi_dot, g=g, verify=verify, symmetry_tol=symmetry_tol,
                         duration=duration, samples=samples)
    with check.arithmetic(kw):
        return run(body, TopOptions.parse(body, **kw))
