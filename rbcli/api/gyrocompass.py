"""The gyrocompass as a service: :func:`gyrocompass` (``rbcli gyrocompass``): a rotor whose
axis is held horizontal on the rotating Earth swings about north
(:mod:`rbcli.core.gyrocompass`)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from rbcli.api.commands import GYROCOMPASS
from rbcli.api.params import Options, function, read
from rbcli.api.shaft import shaft_axis
from rbcli.api.result import Result, jsonable
from rbcli.api.top import plausibility
from rbcli.core import gyrocompass as core
from rbcli.core.gyrocompass import EARTH_RATE
from rbcli.core.inertia import body_mass_props
from rbcli.core.symmetry import AxialSymmetry
from rbcli.errors import InputError, Location, Note, ParamError, literal

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.body.model import Body

__all__ = ["GyrocompassResult", "parse", "run", "gyrocompass", "EARTH_RATE"]

#: what a missing required parameter is, for its message
_REQUIRED = {"spin": "the rotor's spin about its axis, e.g. {spin} '6000 rpm'",
             "latitude": "the latitude in degrees, -90 to 90 (negative = south), e.g. {latitude} 52"}

#: where the spin axis came from, as the JSON's axis_source says it
_SOURCES = {"given": "{shaft}", "body": "the body's shaft", "default": "body z (default)"}


def parse(body: Body | None = None, **kwargs: Any) -> Options:
    """The keyword arguments of :func:`gyrocompass` read for ``body`` (None: with ``ratio``):
    :class:`rbcli.api.params.Options` in SI (``latitude`` rad), ``earth_rate`` the sidereal
    rate when not given.

    Raises
    ------
    rbcli.InputError
        one line naming the parameter; both or neither of ``body`` and ``ratio``.
    """
    for name, what in _REQUIRED.items():
        if kwargs.get(name) is None:
            raise ParamError(name, f"required: {what}")
    o = read(body, GYROCOMPASS, kwargs)
    if o.ratio is not None and body is not None:
        raise ParamError("ratio", "give either {ratio} or a body (BODY or -e), not both")
    if o.ratio is not None and o.shaft is not None:
        raise ParamError("shaft", "the spin axis belongs to a body; with {ratio} there is no body")
    if o.ratio is None and body is None:
        raise InputError("no rotor given: name a BODY file, use -e '{...}', or give {ratio} C/A")
    return o.replace(earth_rate=EARTH_RATE if o.earth_rate is None else o.earth_rate)


@dataclass(frozen=True)
class GyrocompassResult(Result):
    """The gyrocompass's swing about north.

    Attributes
    ----------
    swing : Gyrocompass — C/A, spin, latitude, Earth rate, directive, omega0 and its estimate,
        period and where it settles (:class:`rbcli.core.gyrocompass.Gyrocompass`)
    options : rbcli.api.params.Options — the inputs as read (:func:`parse`)
    body : Body or None — the rotor's body (None with ``ratio``)
    axis, axis_source — with a body: the unit spin axis (body frame) and where it came from
    C, A, mass — with a body: kg m² about and across the spin axis (about the com), kg
    asymmetry : AxialSymmetry or None — how far a nearly symmetric rotor departs
    warnings : tuple of str — located one-line warnings"""

    swing: core.Gyrocompass
    options: Options
    body: Body | None = field(default=None, repr=False)
    axis: tuple[float, float, float] | None = None
    axis_source: str | None = None
    C: float | None = None
    A: float | None = None
    mass: float | None = None
    asymmetry: AxialSymmetry | None = None
    warnings: tuple[str, ...] = ()

    @property
    def asymmetry_effect(self) -> float | None:
        """The relative error of C/A from symmetrising the rotor: up to half the difference
        of the moments across (the moment about the vertical swings between them as the
        rotor turns); the period's is about half that. None when symmetric."""
        a = self.asymmetry
        return None if a is None else max(0.5 * a.relative, a.coupling_relative)

    def to_json(self) -> dict[str, Any]:
        """The JSON of ``rbcli gyrocompass ... --json``, less ``file``."""
        out: dict[str, Any] = {}
        for k, v in self.swing.to_json().items():
            out[k] = v
            if k == "C_over_A":
                out["Is_over_I"] = v
        out["period_approx"] = self.swing.period_approx
        if self.body is not None:
            out["C"] = self.C
            out["A"] = self.A
            out["Is"] = self.C
            out["I"] = self.A
            out["mass"] = self.mass
            out["axis"] = list(self.axis or ())
            out["axis_source"] = self.axis_source
            if self.asymmetry is not None:
                out["asymmetry"] = self.asymmetry.to_json(self.options.symmetry_tol)
            out["name"] = self.body.name
        return jsonable(out)


def run(body: Body | None, options: Options) -> GyrocompassResult:
    """The gyrocompass for ``options`` (:func:`parse`): of the rotor ``body``, or of
    ``options.ratio`` (``body`` None)."""
    o = options
    if body is None:
        swing = _swing(o.ratio, o, "{ratio}")
        return GyrocompassResult(swing=swing, options=o)
    n, came = shaft_axis(body, o.shaft)
    axis = tuple(float(x) for x in np.asarray(n) / np.linalg.norm(n))
    source = Note(_SOURCES[came])
    warnings = plausibility(body, None, o.spin, "spin", axis=axis, typed=o.unit_typed("spin"))
    mp = body_mass_props(body)
    try:
        rotor = core.rotor_from_body(mp.mass, mp.com, mp.inertia_com, axis, sym_rtol=o.symmetry_tol)
    except InputError:  # already names its parameter (an InputError is a ValueError)
        raise
    except ValueError as exc:
        # core's message names its parameters as {param} templates (no user text in it)
        raise InputError(f"{exc}; spin axis from {source.template}", Location(body.source)) from None
    swing = _swing(rotor.C / rotor.A, o, literal(body.source))
    if rotor.asymmetry is not None:
        warnings += (Note(f"{literal(body.source)}: warning: the rotor is not exactly symmetric about "
                          f"its spin axis: {rotor.asymmetry.percent()}; the answer is for the "
                          f"symmetrised rotor ({{symmetry_tol}} {o.symmetry_tol * 100:g} %)"),)
    return GyrocompassResult(swing=swing, options=o, body=body, axis=axis, axis_source=source,
                             C=rotor.C, A=rotor.A, mass=rotor.mass, asymmetry=rotor.asymmetry,
                             warnings=warnings)


def _swing(ratio: float, o: Options, who: str) -> core.Gyrocompass:
    """The swing for C/A ``ratio``; what overflows names ``who`` (the ratio or the body)."""
    try:
        return core.gyrocompass(ratio, o.spin, o.latitude, o.earth_rate)
    except InputError:  # already names its parameter (an InputError is a ValueError)
        raise
    except (ValueError, ArithmeticError) as exc:  # the values were checked: what is left overflows
        raise InputError(f"{who}, {{spin}}, {{earth_rate}}: {exc}", param="spin") from None


@function(GYROCOMPASS, body="optional")
def gyrocompass(body: Body | None = None, **kwargs: Any) -> GyrocompassResult:
    """A gyrocompass: the period of its swing about north and where it settles.

    A rotor spinning at ``spin``, its axis horizontal and free to turn about the vertical, at
    ``latitude``: ω0² = (C/A) S Ω_E cos λ - Ω_E² cos² λ, T = 2π/ω0 (undamped).

    Parameters
    ----------
    body : Body, optional — a rotor symmetric about its spin axis; or ``ratio`` instead
    {parameters}

    Returns
    -------
    GyrocompassResult
        ``swing.period`` (s), ``swing.settles_to``, ``to_json()``.

    Raises
    ------
    TypeError, rbcli.InputError
        A wrong type (:mod:`rbcli.api.check`) or value, naming the parameter: both or
        neither of ``body`` and ``ratio``, a body not symmetric about its spin axis.

    Examples
    --------
    >>> import rbcli
    >>> round(rbcli.gyrocompass(ratio=2, spin="6000 rpm", latitude=30).swing.period, 3)
    22.304"""
    return run(body, parse(body, **kwargs))
