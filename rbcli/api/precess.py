"""``precess``: the exact torque-free motion of a rigid body, as a service
(:class:`rbcli.core.freemotion.FreeMotion` in :attr:`PrecessResult.motion`, sampled at any
times by ``result.at(t)``).

>>> import rbcli
>>> r = rbcli.precess(rbcli.load("examples/book.yaml"), omega=[0.01, 1, 0.01])
>>> r.at(1e9).omega.shape                      # 10^9 s later, at the cost of t = 1 s
(3,)"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from rbcli.api import check
from rbcli.api.check import Quantity
from rbcli.api.commands import MAX_SAMPLES, PRECESS
from rbcli.api.commands import PRECESS_SAMPLES as DEFAULT_SAMPLES
from rbcli.api.inertia import rim_note
from rbcli.api.params import Options, function, read
from rbcli.api.result import Result, frozen, jsonable
from rbcli.core import freemotion as fm
from rbcli.core import freestate as fs
from rbcli.core import freeverify
from rbcli.core.inertia import InputOverflow, body_mass_props
from rbcli.errors import InputError, ParamError

if TYPE_CHECKING:  # pragma: no cover
    from numpy.typing import ArrayLike

    from rbcli.body.model import Body

__all__ = ["PrecessResult", "parse", "run", "precess", "DEFAULT_SAMPLES", "MAX_SAMPLES"]

#: SPEC §3 keys, first in the JSON object
SPEC_KEYS = (
    "angular_momentum", "kinetic_energy", "symmetric", "period", "circles_axis",
    "precession_rate", "space_precession_rate", "body_cone_deg", "space_cone_deg", "flip_interval",
)


def parse(body: Body | None, **kwargs: Any) -> Options:
    """The keyword arguments of :func:`precess` read for ``body`` (None: SI, before a body is
    read): :class:`rbcli.api.params.Options`, ``samples`` a whole number (the default when
    not given), ``verify`` a bool."""
    if kwargs.get("omega") is None:
        raise ParamError("omega", "the initial angular velocity is required: x,y,z in the "
                                  "body frame, e.g. {omega} 0,0,10 (rad/s) or {omega} '0,0,300 rpm'")
    o = read(body, PRECESS, kwargs)
    return o.replace(samples=DEFAULT_SAMPLES if o.samples is None else int(o.samples),
                     verify=bool(o.verify))


@dataclass(frozen=True, eq=False)
class PrecessResult(Result):
    """The torque-free motion of a body and what was asked of it: ``name``, ``motion``
    (:class:`rbcli.core.freemotion.FreeMotion`), ``options`` (:func:`parse`), ``state`` and
    ``at_json`` (the state at ``options.at``, as the JSON's ``at``), ``check`` (with
    ``verify``: the comparison with DOP853), ``notes`` and ``warnings``."""

    name: str
    motion: fm.FreeMotion
    options: Options
    state: fs.FreeState | None = None
    at_json: dict | None = None
    check: freeverify.VerifyResult | None = None
    notes: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()

    def at(self, t: Quantity | ArrayLike) -> fs.FreeState:
        """The exact state at ``t`` (s: a number, a quantity string or at most
        :data:`rbcli.api.check.MAX_TIMES` numbers): ω, L (body frame), quaternion and rotation
        matrix (body → space). TypeError or InputError naming ``t``."""
        t = check.times(t, "t", ndim=1)
        fs.check_phase(self.motion, float(np.max(np.abs(t), initial=0.0)), "t")
        return frozen(self.motion.at(t))  # read-only arrays, as every result's

    def series_blocks(self, duration: Quantity | None = None,
                      samples: int | None = None) -> Iterator[np.ndarray]:
        """The time series in blocks of at most 100 000 rows; see :meth:`series`."""
        given = {"duration": check.quantity(duration, "duration"),
                 "samples": check.count(samples, "samples")}
        o = read(None, PRECESS, given)
        span = self.options.duration if duration is None else o.duration
        if span is None:
            raise ParamError("duration", "needs a span for the time series (from t = 0)")
        return fs.series(self.motion, span, self.options.samples if samples is None else samples)

    def series(self, duration: Quantity | None = None, samples: int | None = None) -> np.ndarray:
        """Rows t, ωx, ωy, ωz, Lx, Ly, Lz (body frame), qw, qx, qy, qz (body → space) at
        ``samples`` times from 0 to ``duration`` s inclusive (defaults: the options';
        1001 rows); the quaternion's sign is continuous along the series. (N, 11) array."""
        return np.vstack(list(self.series_blocks(duration, samples)))

    def to_json(self) -> dict[str, Any]:
        """Exactly the object ``rbcli precess ... --json`` prints, less ``file`` (and the
        ``csv``/``plot`` entries, which describe files the command line wrote)."""
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


def run(body: Body, options: Options) -> PrecessResult:
    """Analyse the torque-free motion of ``body`` (about its centre of mass) for ``options``
    (:func:`parse`)."""
    o = options
    mp = body_mass_props(body)
    try:
        motion = fm.analyse(mp.inertia_com, np.array(o.omega, dtype=float))
    except InputOverflow as exc:
        if exc.param == "omega":
            raise ParamError("omega", str(exc)) from None
        raise InputError(f"{body.source}: {exc}", param="body") from None
    for t, param in ((o.at, "at"), (o.duration, "duration")):
        if t is not None:
            fs.check_phase(motion, t, param)
    at = o.at is not None
    # free rotation: about omega through the com
    rim = rim_note(body, "omega", math.sqrt(sum(x * x for x in o.omega)), o.omega, mp.com,
                    o.unit_typed("omega"))
    return PrecessResult(
        name=body.name, motion=motion, options=o, state=fs.evaluate(motion, o.at) if at else None,
        at_json=fs.state_json(motion, o.at) if at else None,
        check=freeverify.verify(motion) if o.verify else None, notes=tuple(fs.notes(motion)),
        warnings=tuple(body.warnings) + ((rim,) if rim else ()))


@function(PRECESS)
def precess(body: Body, **kwargs: Any) -> PrecessResult:
    """The exact torque-free motion of a rigid body from an initial angular velocity (no
    torque, no gravity; the space frame is the body frame at t = 0).

    Parameters
    ----------
    body : Body
    {parameters}

    Returns
    -------
    PrecessResult
        ``to_json()`` the command's JSON; ``motion`` every constant; ``at(t)`` the state.

    Raises
    ------
    TypeError, rbcli.InputError
        A wrong type (:mod:`rbcli.api.check`) or value, naming the parameter; an inertia
        not positive definite; a time too far.

    Examples
    --------
    >>> import rbcli
    >>> book = rbcli.precess(rbcli.load("examples/book.yaml"), omega=[0.01, 1, 0.01])
    >>> book.case, round(book.flip_interval, 4)         # spun near the intermediate axis: it flips
    ('circulates_max', 19.5529)
    >>> round(float(book.at(1.0).omega[1]), 6)           # rad/s, body frame, at t = 1 s
    1.000049"""
    return run(body, parse(body, **kwargs))
