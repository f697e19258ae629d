"""Mass, centre of mass and the inertia tensor about a point: :func:`inertia`
(``rbcli inertia``), and what :mod:`rbcli.api.principal` shares with it: the point an
inertia is about (:class:`Reference`), the warnings of a far point, the parts' JSON rows.
The tensor is ``J = ∫ (r·r E − r rᵀ) dm`` (``Jxy = −∫ x y dm``)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from rbcli.api import check
from rbcli.api import options as op
from rbcli.api.commands import INERTIA
from rbcli.api.params import Options, function, read
from rbcli.api.result import Result, jsonable
from rbcli.core import inertia as ci
from rbcli.core.inertial import Inertial, inertial
from rbcli.core.scale import SPEED_OF_SOUND, axis_reach, body_scale
from rbcli.errors import InputError, Note, ParamError

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.body.model import Body

__all__ = ["InertiaResult", "Reference", "parse", "run", "inertia", "links", "part_rows",
           "with_parts", "plausibility", "rim_note", "snap"]


@dataclass(frozen=True)
class Reference:
    """The point an inertia is taken about, as the user gave it (resolved once).

    Attributes
    ----------
    point : tuple of 3 floats, or None — m, body frame; None: the com (known once the parts
        are combined)
    label : str — how tables name it (``"the com"``, ``"[x,y,z]"`` as given)
    param : str — the parameter at fault if the point cannot be computed with: ``"about"``
        or ``"body_reference"`` (the body's default)
    """

    point: tuple[float, float, float] | None
    label: str
    param: str

    @classmethod
    def of(cls, body: Body | None, o: Options, *, default: str = "body") -> Reference:
        """``o.about`` (read: ``"com"``, ``"origin"`` or x, y, z m), else the default:
        ``"body"`` = the body's ``reference`` (``com``, a point), else the origin; ``"com"``
        = the com. ``body`` None (values checked before a body is read): the origin."""
        about, given = o.about, o.as_given("about")
        if about == "com":
            return cls(None, "the com", "about")
        if about == "origin":
            return cls((0.0, 0.0, 0.0), "the origin", "about")
        if about is not None:
            text = given if isinstance(given, str) else ", ".join(str(x) for x in given)
            if isinstance(given, str) and op.is_bare(given) and body is not None:
                text = f"{given} {op.Units.of(body).label('length')}"  # a bare point: say its unit
            return cls(tuple(about), f"[{text}]", "about")
        if default == "com" or (body is not None and body.reference_is_com):
            return cls(None, "the com", "body_reference")
        if body is not None and body.reference is not None:
            return cls(tuple(float(x) for x in body.reference), "the body's reference point",
                       "body_reference")
        return cls((0.0, 0.0, 0.0), "the origin", "body_reference")

    def resolve(self, mp: ci.MassProps) -> np.ndarray:
        """The point as a (3,) ndarray, m, given the body's mass properties ``mp``."""
        return mp.com.copy() if self.point is None else np.array(self.point, dtype=float)

    def inertia(self, mp: ci.MassProps) -> tuple[np.ndarray, np.ndarray]:
        """(point, inertia tensor about it): core's overflow blamed on the right parameter."""
        point = self.resolve(mp)
        try:
            return point, ci.checked_inertia_about(mp, point)
        except ci.InputOverflow as exc:
            raise ParamError(self.param, str(exc)) from None


def snap(values: Any, scale: float | None = None, rtol: float = 1e-14) -> np.ndarray:
    """``values`` as a float ndarray (a copy) with entries at most ``rtol`` times the largest
    magnitude (or ``scale``) set to 0 (round-off): what JSON and tables show. No -0.0."""
    a = np.array(values, dtype=float)
    mag = np.abs(a)
    a[mag <= rtol * (float(mag.max()) if scale is None else scale)] = 0.0
    a[a == 0.0] = 0.0
    return a


def part_rows(body: Any) -> tuple[dict, ...]:
    """Each part's contribution, as in JSON: name, shape, mass (kg; negative for a subtracted
    part), com (m), ``subtract: true`` for a hole, and for a mesh part its volume (m³), area
    (m²) and triangles."""
    rows = []
    for p in body.parts:
        row: dict = {"name": p.name, "shape": p.shape, "mass": -p.mass if p.subtract else p.mass,
                     "com": p.com}
        if p.subtract:
            row["subtract"] = True
        row.update((k, p.extra[k]) for k in ("volume", "area", "triangles", "unit", "colour") if k in p.extra)
        rows.append(row)
    return tuple(rows)


def with_parts(out: dict, parts: tuple[dict, ...]) -> dict:
    """``out`` and the parts' rows as JSON (checked finite by :func:`jsonable`)."""
    return jsonable({**out, "parts": list(parts)})


def rim_note(body: Body, param: str, speed: float, axis: Any, through: Any, typed: bool = False) -> Note | None:
    """The warning of ``body`` turning at ``speed`` (rad/s, given as ``param``) about ``axis``
    through ``through`` when its rim would be faster than sound (issue 24: a unit missing?);
    none when the speed was ``typed`` with its unit (a turbine's blade tips, a planet)."""
    w = abs(speed)
    if typed or not 0.0 < w < math.inf:
        return None
    v = w * axis_reach(body.parts, axis, through)
    if not SPEED_OF_SOUND < v < math.inf:
        return None
    return Note(f"{{{param}}}: the body's rim would move at {v:.4g} m/s, faster than sound "
                f"({SPEED_OF_SOUND:g} m/s); bare angular speeds are in "
                f"{op.Units.of(body).label('angular_speed')}: is a unit missing?")


def plausibility(body: Body | None, ref: Reference, omega: Any = None, typed: bool = False) -> tuple[str, ...]:
    """The plausibility warnings (:mod:`rbcli.core.scale`): a reference
    point more than 10 body sizes away, a rotation about it whose rim is faster than sound."""
    far_point = ref.param == "about" and ref.point is not None
    if body is None or not far_point and omega is None:
        return ()
    out = []
    if far_point:
        sc = body_scale(body.parts)
        d = sc.far(ref.point)
        if d is not None:
            out.append(op.Units.of(body).far("about", "the point", d, sc.size))
    if omega is not None:
        # the body turning about omega through the reference point: its farthest material
        through = ci.body_mass_props(body).com if ref.point is None else ref.point
        out.append(rim_note(body, "omega", math.sqrt(sum(x * x for x in omega)), omega, through, typed))
    return tuple(x for x in out if x is not None)


@dataclass(frozen=True)
class InertiaResult(Result):
    """Mass, centre of mass and the inertia tensor about a point (``rbcli inertia``).

    Attributes
    ----------
    name : str; mass : float — kg; com : (3,) ndarray — m
    reference : (3,) ndarray — m, the point ``inertia`` is about; reference_label : str
    inertia, inertia_com : (3, 3) ndarray — kg m², about ``reference`` and the com (tensor)
    axis, axis_moment — the unit axis asked for and ``n·J·n`` (kg m²), or None
    omega, angular_momentum, kinetic_energy, angle_L_omega_deg — rad/s, ``L = J ω`` (kg m²/s),
        ``ω·J·ω/2`` (J) and the angle between L and ω (degrees), or None
    parts : tuple of dict — each part's contribution (:func:`part_rows`)
    warnings : tuple of str — a point or a rim speed far outside the body's scale"""

    name: str
    mass: float
    com: Any
    reference: Any
    reference_label: str
    inertia: Any
    inertia_com: Any
    axis: Any = None
    axis_moment: float | None = None
    omega: Any = None
    angular_momentum: Any = None
    kinetic_energy: float | None = None
    angle_L_omega_deg: float | None = None
    parts: tuple[dict, ...] = ()
    warnings: tuple[str, ...] = field(default=())

    def to_json(self) -> dict[str, Any]:
        """What ``rbcli inertia BODY --json`` prints, less ``"file"`` (SI)."""
        out: dict[str, Any] = {"mass": self.mass, "com": self.com, "reference": self.reference,
                               "inertia": snap(self.inertia), "inertia_com": snap(self.inertia_com)}
        if self.axis is not None:
            out.update(axis=self.axis, axis_moment=self.axis_moment)
        if self.omega is not None:
            out.update(omega=self.omega, angular_momentum=self.angular_momentum,
                       kinetic_energy=self.kinetic_energy, angle_L_omega_deg=self.angle_L_omega_deg)
        out["name"] = self.name
        return with_parts(out, self.parts)

    def inertial(self, principal: bool = False) -> Inertial:
        """The numbers of the body's ``<inertial>`` element for URDF, SDF or MJCF: about the com
        in body axes, or with ``principal`` the principal moments and their axes'
        orientation (:class:`rbcli.core.inertial.Inertial`; ``rbcli.render.robot.render``
        writes the XML ``rbcli inertia --format urdf`` prints)."""
        principal = check.flag(principal, "principal")
        J = self.inertia_com if principal else snap(self.inertia_com)
        return inertial(self.mass, self.com, J, principal=principal)


def links(body: Body, principal: bool = False) -> tuple[tuple[str, Inertial], ...]:
    """The ``<inertial>`` of each link (``--each``): the parts by name up to its first ``/``."""
    groups: dict[str, list] = {}
    for p in check.body(body).parts:
        groups.setdefault(p.name.split("/")[0], []).append(p)
    out = []
    for name, parts in groups.items():
        mp = ci.combine(parts)
        if not mp.mass > 0:
            raise InputError(f"link '{name}': its mass is {mp.mass:.6g} kg (holes outweigh it)")
        J = mp.inertia_com if principal else snap(mp.inertia_com)
        out.append((name, inertial(mp.mass, mp.com, J, principal=principal)))
    return tuple(out)


def parse(body: Body | None, **kwargs: Any) -> Options:
    """The keyword arguments of :func:`inertia` read for ``body`` (None: SI, before a body
    is read): :class:`rbcli.api.params.Options`."""
    return read(body, INERTIA, kwargs)


def run(body: Body, options: Options) -> InertiaResult:
    """:func:`inertia` with options already read (:func:`parse`)."""
    o = options
    ref = Reference.of(body, o)
    mp = ci.body_mass_props(body)
    try:
        res = ci.inertia_report(mp, ref.resolve(mp), axis=None if o.axis is None else np.array(o.axis),
                                omega=None if o.omega is None else np.array(o.omega))
    except ci.InputOverflow as exc:
        raise ParamError(ref.param if exc.param == "reference" else exc.param, str(exc)) from None
    for a in (res.com, res.reference, res.inertia, res.inertia_com, res.axis, res.omega,
              res.angular_momentum):  # made for this result alone: read-only, not copied again
        if a is not None:
            a.setflags(write=False)
    return InertiaResult(
        name=body.name, mass=res.mass, com=res.com, reference=res.reference,
        reference_label=ref.label, inertia=res.inertia, inertia_com=res.inertia_com,
        axis=res.axis, axis_moment=res.axis_moment, omega=res.omega,
        angular_momentum=res.angular_momentum, kinetic_energy=res.kinetic_energy,
        angle_L_omega_deg=res.angle_L_omega_deg, parts=part_rows(body),
        warnings=plausibility(body, ref, o.omega, o.unit_typed("omega")))


@function(INERTIA)
def inertia(body: Body, **kwargs: Any) -> InertiaResult:
    """Mass, centre of mass and the inertia tensor about a point (``about``; default: the
    body's ``reference``, else the origin); optionally the moment about an axis through it
    and the angular momentum and kinetic energy of a rotation.

    Parameters
    ----------
    body : rbcli.Body
    {parameters}

    Returns
    -------
    InertiaResult
        ``to_json()`` is what ``rbcli inertia BODY --json`` prints, less ``"file"``.

    Raises
    ------
    TypeError, rbcli.InputError
        A wrong type (:mod:`rbcli.api.check`) or value, naming the parameter; a point so
        far away that the inertia overflows.

    Notes
    -----
    Parallel axes: ``J_P = J_G + m (d·d E − d dᵀ)``, ``d = P − G``; ``L = J ω``,
    ``T = ω·J·ω/2`` (Goldstein, *Classical Mechanics*, §5.3–5.4).

    Examples
    --------
    >>> import rbcli
    >>> lamina = rbcli.load("examples/square_lamina.yaml")   # 1 kg, 1 m square, about a corner
    >>> r = rbcli.inertia(lamina, axis=[1, 1, 0])
    >>> round(r.axis_moment, 12)                              # m a²/12 about the diagonal
    0.083333333333
    >>> r.mass, r.com.tolist()
    (1.0, [0.5, 0.5, 0.0])"""
    return run(body, parse(body, **kwargs))
