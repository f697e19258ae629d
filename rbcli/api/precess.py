"""``precess``: the exact torque-free motion of a rigid body, as a service.

>>> import rbcli
>>> body = rbcli.load("examples/book.yaml")
>>> r = rbcli.precess(body, omega=[0.01, 1, 0.01])
>>> round(r.motion.flip_interval, 4)
19.5529
>>> r.at(1e9).omega.shape                      # the state 10^9 s later, at the cost of t = 1 s
(3,)

The motion is the exact solution (Jacobi elliptic functions; the attitude through the
elliptic integral of the third kind): :attr:`PrecessResult.motion` is a
:class:`rbcli.core.freemotion.FreeMotion` with every constant, and ``result.at(t)`` (or
``result.motion.at(t)``) samples it at any times.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from rbcli.api import check
from rbcli.api import options as o
from rbcli.api.check import Quantity, Vector
from rbcli.api.result import Result, jsonable
from rbcli.errors import InputError, Note, ParamError

if TYPE_CHECKING:  # pragma: no cover
    import numpy as np
    from numpy.typing import ArrayLike

    from rbcli.core.freemotion import FreeMotion
    from rbcli.core.freeverify import VerifyResult
    from rbcli.core.freestate import FreeState
    from rbcli.body.model import Body

__all__ = ["PrecessOptions", "PrecessResult", "run", "precess", "DEFAULT_SAMPLES", "MAX_SAMPLES"]

#: rows of a time series when ``samples`` is not given, and the most allowed
DEFAULT_SAMPLES = 1001
MAX_SAMPLES = 1_000_000  # 1 048 576 rows is what a spreadsheet holds; 10^6 rows is ~100 MB of CSV

#: the checker of each keyword argument of :func:`precess` (:mod:`rbcli.api.check`)
KINDS = {"omega": check.vector, "at": check.quantity, "duration": check.quantity,
         "samples": check.count, "verify": check.flag}

#: SPEC §3 keys, first in the JSON object
SPEC_KEYS = (
    "angular_momentum", "kinetic_energy", "symmetric", "period", "circles_axis",
    "precession_rate", "space_precession_rate", "body_cone_deg", "space_cone_deg", "flip_interval",
)


def _count(value: Any) -> int:
    """A whole number of rows, 2 .. MAX_SAMPLES (``--samples``)."""
    if isinstance(value, int) and not isinstance(value, bool):
        n = value
    else:
        text = value if isinstance(value, str) else str(value)
        try:
            n = int(text.strip())
        except ValueError:
            raise ParamError("samples", f"expected a whole number of rows from 2 to {MAX_SAMPLES}, "
                                        f"got '{text}'") from None
    if not 2 <= n <= MAX_SAMPLES:
        raise ParamError("samples", f"expected a whole number of rows from 2 to {MAX_SAMPLES}, got {n}")
    return n


def _span(duration: Any) -> float:
    """A positive finite time span in s (``duration``)."""
    span = o.finite(o.quantity(duration, "time", "duration"), "duration")
    if not span > 0.0:
        raise ParamError("duration", f"must be a positive time, got '{duration}'")
    return span


@dataclass(frozen=True)
class PrecessOptions:
    """The checked options of :func:`precess` (SI).

    Attributes
    ----------
    omega : tuple of 3 float — rad/s, initial angular velocity, body frame
    at : float or None — s, a time at which to give the state (any sign)
    duration : float or None — s, > 0: the span of the time series (from t = 0)
    samples : int or None — rows of the time series (2 .. 10 000 000); None: 1001
    verify : bool — compare with a numerical integration (DOP853) over 3 periods
    given : tuple of str — the parameters the caller gave
    typed : tuple of (str, str) — (parameter, unit) for each value typed with a unit
        (``"0.5 g"``: ``("mass_step", "g")``), the unit the options table shows it in
    warnings : tuple of str — a rotation whose rim is faster than sound
    """

    omega: tuple[float, float, float]
    at: float | None = None
    duration: float | None = None
    samples: int | None = None
    verify: bool = False
    given: tuple[str, ...] = ()
    #: parameter -> the unit the caller typed after its number (the options table echoes in it)
    typed: tuple[tuple[str, str], ...] = ()
    warnings: tuple[str, ...] = ()

    @classmethod
    def parse(cls, body: Body | None = None, *, omega: Vector | None = None,
              at: Quantity | None = None, duration: Quantity | None = None,
              samples: int | str | None = None, verify: bool = False) -> PrecessOptions:
        """Read the values as :func:`precess` takes them (numbers SI, or quantity strings)."""
        if omega is None:
            raise ParamError("omega", "the initial angular velocity is required: x,y,z in the "
                                      "body frame, e.g. {omega} 0,0,10 (rad/s) or {omega} '0,0,300 rpm'")
        u = o.Units.of(body)
        w = u.vector(omega, "angular_speed", "omega")
        t_at = o.finite(o.quantity(at, "time", "at"), "at") if at is not None else None
        span = _span(duration) if duration is not None else None
        n_rows = _count(samples) if samples is not None else None
        given = tuple(p for p, v in (("omega", omega), ("at", at), ("duration", duration),
                                     ("samples", samples), ("verify", verify or None)) if v is not None)
        warns: tuple[str, ...] = ()
        if body is not None:
            import math

            from rbcli.core.inertia import body_mass_props
            from rbcli.core.scale import SPEED_OF_SOUND, axis_reach

            wn = math.sqrt(sum(x * x for x in w))  # free rotation: about omega through the com
            v = wn * axis_reach(body.parts, w, body_mass_props(body).com) if 0.0 < wn < math.inf else 0.0
            if SPEED_OF_SOUND < v < math.inf:
                warns = (Note(f"{{omega}}: the body's rim would move at {v:.4g} m/s, faster than "
                              f"sound ({SPEED_OF_SOUND:g} m/s); bare angular speeds are in "
                              f"{u.label('angular_speed')}: is a unit missing?"),)
        return cls(omega=(float(w[0]), float(w[1]), float(w[2])), at=t_at, duration=span,
                   samples=n_rows, verify=bool(verify), given=given,
                   typed=tuple(u.typed.items()), warnings=warns)


@dataclass(frozen=True, eq=False)
class PrecessResult(Result):
    """The torque-free motion of a body and what was asked of it.

    Attributes
    ----------
    name : str — the body's name
    motion : FreeMotion — the exact motion: its case, period (s), flip_interval (s),
        precession rates (rad/s), cones (rad), the elliptic constants...; ``motion.at(t)``
        samples it
    options : PrecessOptions — the options it was computed with
    state : FreeState or None — the state at ``options.at`` (ω rad/s and L kg m²/s in the
        body frame at that time, the quaternion body → space)
    at_json : dict or None — the same as the JSON ``at`` object (adds the axis-angle, the
        matrix and the number of periods)
    check : VerifyResult or None — with ``verify``: the comparison with DOP853
    notes : tuple of str — what the numbers mean, in words (SI, 6 digits)
    warnings : tuple of str — the body's located warnings
    """

    name: str
    motion: FreeMotion
    options: PrecessOptions
    state: FreeState | None = None
    at_json: dict | None = None
    check: VerifyResult | None = None
    notes: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()

    def at(self, t: Quantity | ArrayLike) -> FreeState:
        """The exact state at ``t`` (s: a number, a quantity string such as ``"7320 h"``, or a
        1-D sequence of at most :data:`rbcli.api.check.MAX_TIMES` numbers): ω, L (body frame),
        quaternion and rotation matrix (body → space; space = body frame at t = 0).

        Raises
        ------
        TypeError
            ``t`` that is not a number, a string or numbers.
        rbcli.InputError
            a time that is not finite, too many times, a time too far away to have a phase.
        """
        import numpy as np

        from rbcli.core.freestate import check_phase

        t = check.times(t, "t", ndim=1)
        check_phase(self.motion, float(np.max(np.abs(t), initial=0.0)), "t")
        return self.motion.at(t)

    def series_blocks(self, duration: Quantity | None = None,
                      samples: int | None = None) -> Iterator[np.ndarray]:
        """The time series in blocks of at most 100 000 rows; see :meth:`series`."""
        from rbcli.core.freestate import series

        duration, samples = check.quantity(duration, "duration"), check.count(samples, "samples")
        span = self.options.duration if duration is None else _span(duration)
        if span is None:
            raise ParamError("duration", "needs a span for the time series (from t = 0)")
        n = _count(samples) if samples is not None else (self.options.samples or DEFAULT_SAMPLES)
        return series(self.motion, span, n)

    def series(self, duration: Quantity | None = None, samples: int | None = None) -> np.ndarray:
        """Rows t, ωx, ωy, ωz, Lx, Ly, Lz (body frame), qw, qx, qy, qz (body → space) at
        ``samples`` times from 0 to ``duration`` s inclusive (defaults: the options';
        1001 rows); the quaternion's sign is continuous along the series. (N, 11) array."""
        import numpy as np

        return np.vstack(list(self.series_blocks(duration, samples)))

    def to_json(self) -> dict[str, Any]:
        """Exactly the object ``rbcli precess ... --json`` prints, less ``file`` (and the
        ``csv``/``plot`` entries, which describe files the command line wrote)."""
        import numpy as np

        core = self.motion.to_json()
        axes = np.array(core["principal_axes"], dtype=float)
        axes[np.abs(axes) <= 1e-15] = 0.0
        axes[axes == 0.0] = 0.0
        core["principal_axes"] = axes.tolist()
        out = {k: core[k] for k in SPEC_KEYS}
        out.update({k: v for k, v in core.items() if k not in out})
        out["notes"] = list(self.notes)
        out["name"] = self.name
        if self.at_json is not None:
            out["at"] = self.at_json
        if self.check is not None:
            out["verify"] = self.check.to_json()
        return jsonable(out)

    @property
    def return_code(self) -> int:
        """1 when ``verify`` was asked for and the exact and numerical motions differ."""
        return 1 if self.check is not None and not self.check.ok else 0


def run(body: Body, options: PrecessOptions) -> PrecessResult:
    """Analyse the torque-free motion of ``body`` (about its centre of mass)."""
    import numpy as np

    from rbcli.core import freemotion as fm
    from rbcli.core import freestate as fs
    from rbcli.core.inertia import InputOverflow, body_mass_props

    mp = body_mass_props(body)
    try:
        motion = fm.analyse(mp.inertia_com, np.array(options.omega, dtype=float))
    except InputOverflow as exc:
        if exc.param == "omega":
            raise ParamError("omega", str(exc)) from None
        raise InputError(f"{body.source}: {exc}", param="body") from None
    for t, param in ((options.at, "at"), (options.duration, "duration")):
        if t is not None:
            fs.check_phase(motion, t, param)
    state = at_json = None
    if options.at is not None:
        state = fs.evaluate(motion, options.at)
        at_json = fs.state_json(motion, options.at)
    check = None
    if options.verify:
        from rbcli.core import freeverify

        check = freeverify.verify(motion)
    return PrecessResult(
        name=body.name, motion=motion, options=options, state=state, at_json=at_json,
        check=check, notes=tuple(fs.notes(motion)), warnings=tuple(getattr(body, "warnings", ()) or ()) + options.warnings,
    )


def precess(body: Body, *, omega: Vector, at: Quantity | None = None,
            duration: Quantity | None = None, samples: int | None = None,
            verify: bool = False) -> PrecessResult:
    """The exact torque-free motion of a rigid body from an initial angular velocity.

    The body turns freely about its centre of mass (no torque, no gravity); the space frame
    is the body frame at t = 0.

    Parameters
    ----------
    body : Body
        From :func:`rbcli.load` or :func:`rbcli.load_text`.
    omega : sequence of 3 numbers (rad/s) or str
        Initial angular velocity x, y, z in the body frame; a string as on the command line
        (``"0,0,300 rpm"``: a unit after the last number applies to every bare number).
    at : float (s) or str, optional
        Also give the state at this time (``"7320 h"``; negative = before t = 0).
    duration : float (s) or str, optional
        Span of :meth:`PrecessResult.series` (from t = 0), > 0.
    samples : int, optional
        Rows of :meth:`PrecessResult.series` (2 .. 10 000 000; default 1001).
    verify : bool
        Compare the exact motion with a numerical integration of Euler's equations and the
        attitude (scipy DOP853, rtol 1e-12) over 3 periods; ``return_code`` is 1 when they
        differ by more than 1e-8.

    Returns
    -------
    PrecessResult
        ``to_json()`` is the command's JSON; ``motion`` every constant; ``at(t)`` the state
        at any times.

    Raises
    ------
    TypeError
        An argument of the wrong type, naming the parameter and the type expected
        (:mod:`rbcli.api.check`).
    rbcli.InputError
        A bad value (the message names the parameter), an inertia that is not positive
        definite, a time too far away to have a phase.

    Examples
    --------
    >>> import rbcli
    >>> book = rbcli.precess(rbcli.load("examples/book.yaml"), omega=[0.01, 1, 0.01])
    >>> book.case, round(book.flip_interval, 4)         # spun near the intermediate axis: it flips
    ('circulates_max', 19.5529)
    >>> round(float(book.at(1.0).omega[1]), 6)           # rad/s, body frame, at t = 1 s
    1.000049
    """
    body = check.body(body)
    kw = check.arguments(KINDS, omega=omega, at=at, duration=duration, samples=samples,
                         verify=verify)
    with check.arithmetic(kw):
        return run(body, PrecessOptions.parse(body, **kw))
