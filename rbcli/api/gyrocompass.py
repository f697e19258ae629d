"""The gyrocompass as a service: :func:`gyrocompass` (``rbcli gyrocompass``).

A rotor spinning about its axis, the axis held horizontal and free to turn about the
vertical, on the rotating Earth swings about north: ``rbcli.gyrocompass(ratio=2, spin="6000
rpm", latitude=30)`` is ``rbcli gyrocompass --ratio 2 --spin '6000 rpm' --latitude 30``.
The physics is :mod:`rbcli.core.gyrocompass`; values are read by :mod:`rbcli.api.options`
(SI numbers, or strings as typed on the command line); errors are
:class:`rbcli.errors.InputError` naming the parameter.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from rbcli.api import check
from rbcli.api import options as op
from rbcli.api.check import Quantity, Vector
from rbcli.api.options import symmetry_tolerance
from rbcli.api.result import Result, jsonable
from rbcli.api.top import plausibility
from rbcli.errors import InputError, Location, Note, ParamError, literal

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.core.gyrocompass import Gyrocompass
    from rbcli.core.symmetry import AxialSymmetry
    from rbcli.model import Body

__all__ = ["GyrocompassOptions", "GyrocompassResult", "run", "gyrocompass", "EARTH_RATE"]

#: the checker of each keyword argument of :func:`gyrocompass` (:mod:`rbcli.api.check`)
KINDS = {"ratio": check.quantity, "shaft": check.vector, "spin": check.quantity,
         "latitude": check.quantity, "earth_rate": check.quantity, "symmetry_tol": check.quantity}

#: the Earth's sidereal rotation rate, rad/s (the default of ``earth_rate``)
EARTH_RATE = 7.2921150e-5


@dataclass(frozen=True)
class GyrocompassOptions:
    """The gyrocompass's inputs, parsed and checked (SI).

    Attributes
    ----------
    ratio : float | None — C/A given directly (no body)
    axis : tuple[float, float, float] | None — the spin axis in the body frame (with a body)
    axis_source : Note | None — ``{shaft}`` (the parameter, spelled by the caller), ``"the body's shaft"`` or ``"body z (default)"``
    spin : float — rad/s, ≠ 0
    latitude : float — rad, in [-π/2, π/2]
    earth_rate : float — rad/s, > 0
    symmetry_tol : float — how far from symmetric about its spin axis the body may be
    axis_as_given : tuple[float, float, float] | None — ``axis`` as given (largest component ±1)
    given : tuple of str — the parameters the caller gave
    typed : tuple of (str, str) — (parameter, unit) for each value typed with a unit
        (``"0.5 g"``: ``("mass_step", "g")``), the unit the options table shows it in
    warnings : tuple of str — a rim speed far outside the body's scale
    """

    ratio: float | None
    axis: tuple[float, float, float] | None
    axis_source: str | None
    spin: float
    latitude: float
    earth_rate: float
    symmetry_tol: float = 0.01
    axis_as_given: tuple[float, float, float] | None = None
    given: tuple[str, ...] = ()
    #: parameter -> the unit the caller typed after its number (the options table echoes in it)
    typed: tuple[tuple[str, str], ...] = ()
    warnings: tuple[str, ...] = ()

    @classmethod
    def parse(cls, body: Body | None = None, *, ratio: Quantity | None = None,
              shaft: Vector | None = None, spin: Quantity | None = None,
              latitude: Quantity | None = None, earth_rate: Quantity | None = None,
              symmetry_tol: Quantity | None = None) -> GyrocompassOptions:
        """Read and check the values (see :func:`gyrocompass`)."""
        if spin is None:
            raise InputError("{spin}: required: the rotor's spin about its axis, e.g. {spin} '6000 rpm'",
                             param="spin")
        if latitude is None:
            raise InputError("{latitude}: required: the latitude in degrees, -90 to 90 (negative = south), "
                             "e.g. {latitude} 52", param="latitude")
        u = op.Units.of(body)
        S = op.finite(u.quantity(spin, "angular_speed", "spin"), "spin")
        if S == 0.0:
            raise ParamError("spin", "must not be 0: a gyrocompass needs a spinning rotor")
        lat = op.finite(op.quantity(latitude, "angle", "latitude", bare="deg"), "latitude")
        if abs(lat) > 0.5 * math.pi * (1.0 + 1e-12):
            raise ParamError("latitude", f"must be from -90 to 90 degrees, got {latitude}")
        W = EARTH_RATE if earth_rate is None else op.finite(
            u.quantity(earth_rate, "angular_speed", "earth_rate"), "earth_rate")
        if not W > 0.0:
            raise ParamError("earth_rate", f"must be positive, got {earth_rate}")
        n_axis = op.direction(shaft, "shaft") if shaft is not None else None
        tol = symmetry_tolerance(symmetry_tol)
        given = tuple(p for p, v in (("ratio", ratio), ("shaft", shaft), ("spin", spin),
                                     ("latitude", latitude), ("earth_rate", earth_rate),
                                     ("symmetry_tol", symmetry_tol)) if v is not None)
        r = None
        if ratio is not None:
            r = op.finite(op.quantity(ratio, "dimensionless", "ratio"), "ratio")
            if not r > 0.0:
                raise ParamError("ratio", f"C/A must be positive, got {ratio}")
            if body is not None:
                raise ParamError("ratio", "give either {ratio} or a body (BODY or -e), not both")
            if n_axis is not None:
                raise ParamError("shaft", "the spin axis belongs to a body; with {ratio} there is no body")
            return cls(ratio=r, axis=None, axis_source=None, spin=S, latitude=lat, earth_rate=W,
                       symmetry_tol=tol, given=given, typed=tuple(u.typed.items()))
        if body is None:
            raise InputError("no rotor given: name a BODY file, use -e '{...}', or give {ratio} C/A")
        from rbcli.api.shaft import shaft_axis

        n, came = shaft_axis(body, n_axis)
        src = {"given": "{shaft}", "body": "the body's shaft", "default": "body z (default)"}[came]
        import numpy as np

        v = np.asarray(n, dtype=float)
        unit = tuple(float(x) for x in v / np.linalg.norm(v))
        return cls(ratio=None, axis=unit, axis_source=Note(src), spin=S, latitude=lat,  # type: ignore[arg-type]
                   earth_rate=W, symmetry_tol=tol, axis_as_given=None if n_axis is None else tuple(n_axis),
                   given=given, typed=tuple(u.typed.items()),
                   warnings=plausibility(body, u, None, S, "spin", axis=unit))


@dataclass(frozen=True)
class GyrocompassResult(Result):
    """The gyrocompass's swing about north.

    Attributes
    ----------
    swing : Gyrocompass — C/A, spin (rad/s), latitude (rad), Earth rate (rad/s), directive
        (1/s²), omega0 and its estimate (rad/s), period (s) and where it settles (None
        with no directive torque)
    body : Body | None — the rotor's body (None with ``ratio``)
    C, A : float | None — kg m², with a body: the moments about and across the spin axis,
        about the com
    mass : float | None — kg, with a body
    options : GyrocompassOptions — the inputs as understood (SI)
    asymmetry : AxialSymmetry | None — for a rotor accepted as nearly symmetric about its
        spin axis: how far it departs (A is then the mean of its two moments across)
    warnings : tuple[str, ...] — located one-line warnings: a nearly symmetric rotor
    """

    swing: Gyrocompass
    options: GyrocompassOptions
    body: Body | None = field(default=None, repr=False)
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
            out["axis"] = list(self.options.axis or ())
            out["axis_source"] = self.options.axis_source
            if self.asymmetry is not None:
                out["asymmetry"] = self.asymmetry.to_json(self.options.symmetry_tol)
            out["name"] = self.body.name
        return jsonable(out)


def run(body: Body | None, options: GyrocompassOptions) -> GyrocompassResult:
    """The gyrocompass for parsed options."""
    from rbcli.core import gyrocompass as core

    o = options
    C = A = mass = rotor = None
    if o.ratio is not None:
        r = o.ratio
    else:
        assert body is not None and o.axis is not None
        from rbcli.core.inertia import body_mass_props

        mp = body_mass_props(body)
        try:
            rotor = core.rotor_from_body(mp.mass, mp.com, mp.inertia_com, o.axis, sym_rtol=o.symmetry_tol)
        except InputError:  # already names its parameter (an InputError is a ValueError)
            raise
        except ValueError as exc:
            # core's message names its parameters as {param} templates (no user text in it)
            raise InputError(f"{exc}; spin axis from {o.axis_source.template}",
                             Location(body.source)) from None
        C, A, mass = rotor.C, rotor.A, rotor.mass
        r = C / A
    try:
        swing = core.gyrocompass(r, o.spin, o.latitude, o.earth_rate)
    except InputError:  # already names its parameter (an InputError is a ValueError)
        raise
    except (ValueError, ArithmeticError) as exc:  # the values were checked: what is left overflows
        who = ["{ratio}" if body is None else literal(body.source), "{spin}", "{earth_rate}"]
        raise InputError(f"{', '.join(who)}: {exc}", param="spin") from None
    warnings = o.warnings
    if body is not None and rotor.asymmetry is not None:
        warnings += (Note(f"{literal(body.source)}: warning: the rotor is not exactly symmetric about "
                          f"its spin axis: {rotor.asymmetry.percent()}; the answer is for the "
                          f"symmetrised rotor ({{symmetry_tol}} {o.symmetry_tol * 100:g} %)"),)
    return GyrocompassResult(swing=swing, options=o, body=body, C=C, A=A, mass=mass,
                             asymmetry=None if body is None else rotor.asymmetry, warnings=warnings)


def gyrocompass(body: Body | None = None, *, ratio: Quantity | None = None,
                shaft: Vector | None = None, spin: Quantity, latitude: Quantity,
                earth_rate: Quantity | None = None,
                symmetry_tol: Quantity | None = None) -> GyrocompassResult:
    """A gyrocompass: the period of its swing about north and where it settles.

    A rotor spinning at ``spin`` about its axis, the axis held horizontal and free to turn
    about the vertical, at ``latitude`` on the rotating Earth: ω0² = (C/A) S Ω_E cos λ -
    Ω_E² cos² λ, period T = 2π/ω0 (undamped).

    Parameters
    ----------
    body : Body, optional
        A rotor symmetric about its spin axis (C and A about its centre of mass); or give
        ``ratio`` instead.
    ratio : float or str, optional
        C/A, the axial moment over the moment about the vertical (a flat disk: 2).
    shaft : str or sequence of 3, optional
        The rotor's spin axis in the body frame (``"x"``, ``[0, 0, 1]``; the command line's
        ``--axis``). Default: the body's shaft axis, else z.
    spin : float or str
        The rotor's spin: rad/s or ``"6000 rpm"``; negative the other way. Not 0.
    latitude : float or str
        Degrees (a number) or with a unit, -90 to 90; negative is south.
    earth_rate : float or str, optional
        Ω_E, rad/s or with a unit. Default 7.2921150e-5 (sidereal).
    symmetry_tol : float or str, optional
        How far from symmetric about its spin axis the body may be: a fraction or a
        percentage (``"1 %"``), at most 10 %. Default 1 %. Within it, A is the mean of the
        two moments across, with a warning and ``asymmetry`` in the JSON.

    Returns
    -------
    GyrocompassResult
        ``result.swing.period`` (s), ``result.swing.settles_to``, ``result.to_json()``.

    Raises
    ------
    TypeError
        An argument of the wrong type, naming the parameter and the type expected
        (:mod:`rbcli.api.check`).
    rbcli.InputError
        Naming the parameter: a value out of range, both or neither of ``body``
        and ``ratio``, a body not symmetric about its spin axis.

    Examples
    --------
    >>> import rbcli
    >>> round(rbcli.gyrocompass(ratio=2, spin="6000 rpm", latitude=30).swing.period, 3)
    22.304
    """
    body = check.body(body, optional=True)
    kw = check.arguments(KINDS, ratio=ratio, shaft=shaft, spin=spin, latitude=latitude,
                         earth_rate=earth_rate, symmetry_tol=symmetry_tol)
    with check.arithmetic(kw):
        return run(body, GyrocompassOptions.parse(body, **kw))
