"""Mass, centre of mass and the inertia tensor about a point: :func:`inertia` (``rbcli inertia``).

::

    import rbcli
    body = rbcli.load("examples/square_lamina.yaml")
    r = rbcli.inertia(body, about="origin", axis=[1, 1, 0])
    r.axis_moment            # kg m^2, about the diagonal through the corner

Sign convention: the inertia tensor is the tensor, ``J = ∫ (r·r E − r rᵀ) dm``; its
off-diagonal entries are the negated products of inertia (``Jxy = −∫ x y dm``).

numpy and :mod:`rbcli.core` load on first use, not when this module is imported.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from rbcli.api import check
from rbcli.api import options as o
from rbcli.api.check import Point, Vector
from rbcli.api.massprops import Reference, part_rows, plausibility, snap, with_parts
from rbcli.api.result import Result
from rbcli.errors import ParamError

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.core.inertial import Inertial
    from rbcli.model import Body

__all__ = ["InertiaOptions", "InertiaResult", "run", "inertia"]

#: the checker of each keyword argument of :func:`inertia` (:mod:`rbcli.api.check`)
KINDS = {"about": check.vector, "axis": check.vector, "omega": check.vector}


@dataclass(frozen=True)
class InertiaOptions:
    """What :func:`inertia` was asked, parsed and checked once.

    Attributes
    ----------
    reference : Reference — the point the tensor is about
    axis : tuple of 3 floats, or None — a direction (largest component ±1), body frame
    omega : tuple of 3 floats, or None — rad/s, body frame
    given : tuple of str — the parameters the caller gave
    typed : tuple of (str, str) — (parameter, unit) for each value typed with a unit
        (``"0.5 g"``: ``("mass_step", "g")``), the unit the options table shows it in
    warnings : tuple of str — a point or a rim speed far outside the body's scale
    """

    reference: Reference
    axis: tuple[float, float, float] | None = None
    omega: tuple[float, float, float] | None = None
    given: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()
    #: parameter -> the unit the caller typed after its number (the options table echoes in it)
    typed: tuple[tuple[str, str], ...] = ()

    @property
    def about(self) -> str | tuple[float, float, float] | None:
        """The point as given: ``"com"``, ``"origin"`` or x, y, z (m); None when not given."""
        return self.reference.as_given

    @classmethod
    def parse(cls, body: Body | None, *, about: Point | None = None, axis: Vector | None = None,
              omega: Vector | None = None) -> InertiaOptions:
        """Read the keyword arguments of :func:`inertia` (SI numbers, sequences, or strings
        as typed on the command line).

        Raises
        ------
        rbcli.InputError
            with the command line's message (``--axis: ...``).
        """
        u = o.Units.of(body)
        ref = Reference.parse(body, about)
        n = tuple(o.direction(axis, "axis")) if axis is not None else None
        w = tuple(u.vector(omega, "angular_speed", "omega")) if omega is not None else None
        given = tuple(p for p, v in (("about", about), ("axis", axis), ("omega", omega)) if v is not None)
        return cls(ref, n, w, given, plausibility(body, u, ref, w), tuple(u.typed.items()))  # type: ignore[arg-type]


@dataclass(frozen=True)
class InertiaResult(Result):
    """Mass, centre of mass and the inertia tensor about a point (``rbcli inertia``).

    Attributes
    ----------
    name : str — the body's name
    mass : float — kg
    com : (3,) ndarray — m, body frame
    reference : (3,) ndarray — m, the point ``inertia`` is about
    reference_label : str — how tables name that point (``"the com"``, ...)
    inertia : (3, 3) ndarray — kg m², about ``reference``, body axes, tensor convention
    inertia_com : (3, 3) ndarray — kg m², about the com
    axis : (3,) ndarray or None — the unit axis asked for (through ``reference``)
    axis_moment : float or None — kg m², ``n·J·n``
    omega : (3,) ndarray or None — rad/s
    angular_momentum : (3,) ndarray or None — kg m²/s, ``L = J ω`` about ``reference``
    kinetic_energy : float or None — J, ``ω·J·ω/2``
    angle_L_omega_deg : float or None — degrees between L and ω
    parts : tuple of dict — each part's contribution (see :func:`part_rows`)
    warnings : tuple of str — none for this command

    Methods: ``to_json()`` (the command's JSON less ``"file"``) and ``inertial(principal)``
    (the numbers of a URDF/SDF/MJCF ``<inertial>`` element).
    """

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
        out: dict[str, Any] = {
            "mass": self.mass,
            "com": self.com,
            "reference": self.reference,
            "inertia": snap(self.inertia),
            "inertia_com": snap(self.inertia_com),
        }
        if self.axis is not None:
            out["axis"] = self.axis
            out["axis_moment"] = self.axis_moment
        if self.omega is not None:
            out["omega"] = self.omega
            out["angular_momentum"] = self.angular_momentum
            out["kinetic_energy"] = self.kinetic_energy
            out["angle_L_omega_deg"] = self.angle_L_omega_deg
        out["name"] = self.name
        return with_parts(out, self.parts)

    def inertial(self, principal: bool = False) -> Inertial:
        """The numbers of the body's ``<inertial>`` element for URDF, SDF or MJCF.

        Parameters
        ----------
        principal : bool
            False: the tensor about the com in body axes (exactly ``inertia_com`` of
            ``to_json()``); True: the principal moments about the com (ascending, as
            :func:`principal` gives them) and the principal axes' orientation.

        Returns
        -------
        rbcli.core.inertial.Inertial
            ``mass`` (kg), ``com`` (m), ``inertia`` (kg m², in the inertial frame),
            ``rotation`` (columns: the inertial frame's axes in the body frame),
            ``quat_wxyz`` and ``rpy`` (rad, fixed-axis roll-pitch-yaw) of that rotation.
            ``rbcli.render.robot.render("urdf", name, source, inertial)`` writes the XML
            that ``rbcli inertia --format urdf`` prints.
        """
        from rbcli.core.inertial import inertial

        principal = check.flag(principal, "principal")
        J = self.inertia_com if principal else snap(self.inertia_com)
        return inertial(self.mass, self.com, J, principal=principal)


def run(body: Body, options: InertiaOptions) -> InertiaResult:
    """:func:`inertia` with options already parsed."""
    import numpy as np

    from rbcli.core import inertia as ci

    mp = ci.body_mass_props(body)
    point = options.reference.resolve(mp)
    try:
        res = ci.inertia_report(
            mp, point,
            axis=np.array(options.axis) if options.axis is not None else None,
            omega=np.array(options.omega) if options.omega is not None else None)
    except ci.InputOverflow as exc:
        raise ParamError(options.reference.param if exc.param == "reference" else exc.param,
                         str(exc)) from None
    rows = part_rows(body)
    for a in (res.com, res.reference, res.inertia, res.inertia_com, res.axis, res.omega,
              res.angular_momentum):  # made for this result alone: read-only, not copied again
        if a is not None:
            a.setflags(write=False)
    return InertiaResult(
        name=body.name, mass=res.mass, com=res.com, reference=res.reference,
        reference_label=options.reference.label, inertia=res.inertia, inertia_com=res.inertia_com,
        axis=res.axis, axis_moment=res.axis_moment, omega=res.omega,
        angular_momentum=res.angular_momentum, kinetic_energy=res.kinetic_energy,
        angle_L_omega_deg=res.angle_L_omega_deg, parts=rows, warnings=options.warnings)


def inertia(body: Body, *, about: Point | None = None, axis: Vector | None = None,
            omega: Vector | None = None) -> InertiaResult:
    """Mass, centre of mass and the inertia tensor about a point; optionally the moment about
    an axis through it and the angular momentum and kinetic energy of a rotation.

    Parameters
    ----------
    body : rbcli.Body
        From :func:`rbcli.load` or :func:`rbcli.load_text`.
    about : str or sequence of 3, optional
        The point: ``"com"``, ``"origin"``, or x, y, z in m (``[0.5, 0.5, 0]``, or a string
        with a unit: ``"10,0,5 mm"``). Default: the body's ``reference`` (``com`` or a
        point), else the origin.
    axis : str or sequence of 3, optional
        A direction x, y, z (any length) or ``"x"``, ``"y"``, ``"z"``: gives
        ``axis_moment = n·J·n`` about the axis through the point.
    omega : str or sequence of 3, optional
        Angular velocity, rad/s (or ``"0,0,300 rpm"``): gives ``L = J ω``,
        ``T = ω·J·ω/2`` and the angle between L and ω (rotation about the point).

    Returns
    -------
    InertiaResult
        ``to_json()`` is what ``rbcli inertia BODY --json`` prints, less ``"file"``.

    Raises
    ------
    TypeError
        An argument of the wrong type, naming the parameter and the type expected
        (:mod:`rbcli.api.check`).
    rbcli.InputError
        A bad value, naming the parameter (``about: ...``); a point so far
        away that the inertia overflows (a :class:`rbcli.ParamError`).

    Notes
    -----
    Parallel axes (Huygens–Steiner): ``J_P = J_G + m (d·d E − d dᵀ)``, ``d = P − G``;
    ``L`` and ``T`` about a fixed point P: Goldstein, *Classical Mechanics*, §5.3–5.4.

    Examples
    --------
    >>> import rbcli
    >>> lamina = rbcli.load("examples/square_lamina.yaml")   # 1 kg, 1 m square, about a corner
    >>> r = rbcli.inertia(lamina, axis=[1, 1, 0])
    >>> round(r.axis_moment, 12)                              # m a²/12 about the diagonal
    0.083333333333
    >>> r.mass, r.com.tolist()
    (1.0, [0.5, 0.5, 0.0])
    """
    body = check.body(body)
    kw = check.arguments(KINDS, about=about, axis=axis, omega=omega)
    with check.arithmetic(kw):
        return run(body, InertiaOptions.parse(body, **kw))
