"""Mass properties: :func:`inertia` and :func:`principal` (``rbcli inertia``, ``rbcli principal``).

::

    import rbcli
    body = rbcli.load("examples/square_lamina.yaml")
    r = rbcli.inertia(body, about="origin", axis=[1, 1, 0])
    r.axis_moment            # kg m^2, about the diagonal through the corner
    p = rbcli.principal(body)
    p.moments, p.axes        # ascending, rows = unit axes in the body frame

Sign convention: the inertia tensor is the tensor, ``J = ∫ (r·r E − r rᵀ) dm``; its
off-diagonal entries are the negated products of inertia (``Jxy = −∫ x y dm``).

numpy and :mod:`rbcli.core` load on first use, not when this module is imported.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from rbcli.api import options as o
from rbcli.api.result import Result, jsonable
from rbcli.errors import Note, ParamError

__all__ = [
    "Reference", "InertiaOptions", "InertiaResult", "inertia", "PrincipalOptions",
    "PrincipalResult", "principal", "part_rows", "snap",
]


# ----------------------------------------------------------------------------- shared


@dataclass(frozen=True)
class Reference:
    """The point an inertia is taken about, as the user gave it (resolved once).

    Attributes
    ----------
    point : tuple of 3 floats, or None
        m, body frame; None means the body's centre of mass (known only once the parts are
        combined).
    label : str
        How tables name it: ``"the com"``, ``"the origin"``, ``"the body's reference
        point"`` or ``"[x,y,z]"`` (the text as given).
    param : str
        The parameter at fault if the point is impossible to compute with: ``"about"``
        (given) or ``"body_reference"`` (the body's default).
    """

    point: tuple[float, float, float] | None
    label: str
    param: str

    @classmethod
    def parse(cls, body: Any, about: o.Value | None, *, default: str = "body") -> "Reference":
        """``about`` (``"com"``, ``"origin"``, ``"x,y,z"`` or a sequence, m), else the
        default: ``"body"`` = the body's ``reference`` (``com``, a point), else the
        origin; ``"com"`` = the com. ``body`` None (values checked before a body is read):
        the origin."""
        if about is not None:
            u = o.Units.of(body)
            p = u.point(about, "about")
            if p == "com":
                return cls(None, "the com", "about")
            if p == "origin":
                return cls((0.0, 0.0, 0.0), "the origin", "about")
            if isinstance(about, str):
                text = about
                if o.is_bare(about) and body is not None:
                    text = f"{about} {u.label('length')}"  # a bare point: say its unit
            else:
                text = ", ".join(str(x) for x in _items(about))
            return cls(tuple(float(x) for x in p), f"[{text}]", "about")  # type: ignore[arg-type]
        if default == "com" or (body is not None and body.reference_is_com):
            return cls(None, "the com", "body_reference")
        if body is not None and body.reference is not None:
            return cls(tuple(float(x) for x in body.reference), "the body's reference point",  # type: ignore[arg-type]
                       "body_reference")
        return cls((0.0, 0.0, 0.0), "the origin", "body_reference")

    @property
    def as_given(self) -> str | tuple[float, float, float] | None:
        """``"com"``, ``"origin"`` or the point (m) when given as ``about``, else None."""
        if self.param != "about":
            return None
        if self.point is None:
            return "com"
        return "origin" if self.label == "the origin" else self.point

    def resolve(self, mp: Any) -> Any:
        """The point as a (3,) ndarray, m, given the body's mass properties ``mp``."""
        import numpy as np

        return mp.com.copy() if self.point is None else np.array(self.point, dtype=float)


def _items(v: Any) -> list:
    return v.tolist() if hasattr(v, "tolist") else list(v)


def snap(values: Any, scale: float | None = None, rtol: float = 1e-14) -> Any:
    """``values`` as a float ndarray with entries below ``rtol`` times the largest magnitude
    (or ``scale``) set to exactly 0 (round-off, e.g. a product of inertia of 1e-18 next to
    moments of 1): what JSON and tables show."""
    import numpy as np

    a = np.array(values, dtype=float)
    flat = a.ravel().tolist()
    if flat and (scale is not None or all(x == x for x in flat)):  # no NaN: numpy's max is NaN
        # the same comparisons on the same floats, in Python: faster for a 3x3 (a batch)
        limit = rtol * (max(map(abs, flat)) if scale is None else scale)
        return np.array([0.0 if abs(x) <= limit or x == 0.0 else x for x in flat]).reshape(a.shape)
    mag = np.abs(a)
    s = float(mag.max()) if scale is None else scale
    a[mag <= rtol * s] = 0.0
    a[a == 0.0] = 0.0  # no negative zeros
    return a


def part_rows(body: Any) -> tuple[dict, ...]:
    """Each part's contribution, as in JSON: name, shape, mass (kg; negative for a subtracted
    part), com (m), ``subtract: true`` for a hole, and for a mesh part its volume (m³), area
    (m²) and triangles."""
    rows = []
    for p in body.parts:
        if p.subtract:
            row: dict = {"name": p.name, "shape": p.shape, "mass": -p.mass, "com": p.com, "subtract": True}
        else:
            row = {"name": p.name, "shape": p.shape, "mass": p.mass, "com": p.com}
        if p.extra:
            for key in ("volume", "area", "triangles"):
                if key in p.extra:
                    row[key] = p.extra[key]
        rows.append(row)
    return tuple(rows)


def _with_parts(out: dict, parts: tuple[dict, ...]) -> dict:
    """``out`` and the parts' rows as JSON (checked finite by :func:`jsonable`)."""
    return jsonable({**out, "parts": list(parts)})


def _inertia_at(mp: Any, ref: Reference) -> tuple[Any, Any]:
    """(point, inertia tensor about it): core's overflow blamed on the right parameter."""
    from rbcli.core.inertia import InputOverflow, checked_inertia_about

    point = ref.resolve(mp)
    try:
        return point, checked_inertia_about(mp, point)
    except InputOverflow as exc:
        raise ParamError(ref.param, str(exc)) from None


# ----------------------------------------------------------------------------- inertia


@dataclass(frozen=True)
class InertiaOptions:
    """What :func:`inertia` was asked, parsed and checked once.

    Attributes
    ----------
    reference : Reference — the point the tensor is about
    axis : tuple of 3 floats, or None — a direction (largest component ±1), body frame
    omega : tuple of 3 floats, or None — rad/s, body frame
    given : tuple of str — the parameters the caller gave
    warnings : tuple of str — a point or a rim speed far outside the body's scale
    """

    reference: Reference
    axis: tuple[float, float, float] | None = None
    omega: tuple[float, float, float] | None = None
    given: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()

    @property
    def about(self) -> str | tuple[float, float, float] | None:
        """The point as given: ``"com"``, ``"origin"`` or x, y, z (m); None when not given."""
        return self.reference.as_given

    @classmethod
    def parse(cls, body: Any, *, about: o.Value | None = None, axis: o.Value | None = None,
              omega: o.Value | None = None) -> "InertiaOptions":
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
        return cls(ref, n, w, given, _plausibility(body, u, ref, w))  # type: ignore[arg-type]


def _plausibility(body: Any, u: o.Units, ref: Reference, omega: Any = None) -> tuple[str, ...]:
    """One-line warnings for values far outside the body's scale (issue 13): a reference
    point more than 10 body sizes away, a rotation whose rim is faster than sound."""
    if body is None:
        return ()
    import math

    from rbcli.core.scale import SPEED_OF_SOUND, axis_reach, body_scale

    far_point = ref.param == "about" and ref.point is not None
    if not far_point and omega is None:
        return ()
    sc = body_scale(body.parts)
    out = []
    if far_point:
        d = sc.far(ref.point)
        if d is not None:
            out.append(u.far("about", "the point", d, sc.size))
    w = 0.0 if omega is None else math.sqrt(sum(x * x for x in omega))
    if 0.0 < w < math.inf:
        from rbcli.core.inertia import body_mass_props

        # the body turning about omega through the reference point: its farthest material
        through = body_mass_props(body).com if ref.point is None else ref.point
        v = w * axis_reach(body.parts, omega, through)
        if SPEED_OF_SOUND < v < math.inf:
            out.append(Note(f"{{omega}}: the body's rim would move at {v:.4g} m/s, faster than "
                            f"sound ({SPEED_OF_SOUND:g} m/s); bare angular speeds are in "
                            f"{u.label('angular_speed')}: is a unit missing?"))
    return tuple(out)


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
        return _with_parts(out, self.parts)

    def inertial(self, principal: bool = False) -> Any:
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

        J = self.inertia_com if principal else snap(self.inertia_com)
        return inertial(self.mass, self.com, J, principal=principal)


def run_inertia(body: Any, options: InertiaOptions) -> InertiaResult:
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
    return InertiaResult(
        name=body.name, mass=res.mass, com=res.com, reference=res.reference,
        reference_label=options.reference.label, inertia=res.inertia, inertia_com=res.inertia_com,
        axis=res.axis, axis_moment=res.axis_moment, omega=res.omega,
        angular_momentum=res.angular_momentum, kinetic_energy=res.kinetic_energy,
        angle_L_omega_deg=res.angle_L_omega_deg, parts=rows, warnings=options.warnings)


def inertia(body: Any, *, about: o.Value | None = None, axis: o.Value | None = None,
            omega: o.Value | None = None) -> InertiaResult:
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
    rbcli.InputError
        A bad value, with the command line's message (``--about: ...``); a point so far
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
    return run_inertia(body, InertiaOptions.parse(body, about=about, axis=axis, omega=omega))


# ----------------------------------------------------------------------------- principal


@dataclass(frozen=True)
class PrincipalOptions:
    """What :func:`principal` was asked, parsed once.

    Attributes
    ----------
    reference : Reference — the point the moments are about (default the com)
    given : tuple of str — ``("about",)`` when a point other than the com was given
    warnings : tuple of str — a point far outside the body's scale
    """

    reference: Reference
    given: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()

    @property
    def about(self) -> str | tuple[float, float, float] | None:
        """The point as given (see :attr:`InertiaOptions.about`)."""
        return self.reference.as_given

    @classmethod
    def parse(cls, body: Any, *, about: o.Value | None = "com") -> "PrincipalOptions":
        """Read ``about`` (``"com"``, ``"origin"``, x, y, z: a bare number in the body's
        length unit; None = the com)."""
        ref = Reference.parse(body, about, default="com")
        u = o.Units.of(body)
        given = ("about",) if ref.point is not None and ref.param == "about" else ()  # com: the default
        return cls(ref, given, _plausibility(body, u, ref))


@dataclass(frozen=True)
class PrincipalResult(Result):
    """Principal moments and axes about a point (``rbcli principal``).

    Attributes
    ----------
    name : str — the body's name
    mass : float — kg
    reference : (3,) ndarray — m, the point the moments are about
    reference_label : str — how tables name it
    moments : (3,) ndarray — kg m², ascending
    axes : (3, 3) ndarray — row i is the unit axis of ``moments[i]`` (body frame); a proper
        rotation matrix taking body to principal coordinates
    symmetry : str — ``"asymmetric"``, ``"symmetric"`` or ``"spherical"``
    unique_axis : int or None — for ``"symmetric"``, the index (0 or 2) of the moment that
        differs
    free_axes : tuple of int — 0-based indices of the axes free to choose (equal moments)
    stable : tuple of 3 bool — is free rotation about each axis stable (false for a neutral
        axis: see ``stability``)
    stability : tuple of 3 str — ``"stable"``, ``"unstable"`` or ``"neutral"`` per axis (neutral:
        an axis of the equal pair of a symmetric body, about which the spin axis wanders)
    direction_angles_deg : (3, 3) ndarray — degrees, principal axis i from body axis j
    tilt_deg : (3,) ndarray — degrees, each principal axis from its nearest body axis line
    tilt_axis : tuple of 3 str — that body axis, ``"x"``, ``"y"`` or ``"z"``
    rotation_axis : (3,) ndarray — unit axis of the rotation taking the body axes to the
        principal axes 1, 2, 3 in ascending order of the moments
    rotation_angle_deg : float — its angle, degrees (~90° when the ascending order permutes
        the body axes, however small the tilts)
    equivalent_box : (3,) ndarray — m, sides along axes 1, 2, 3 of the uniform box with the
        same mass and principal moments
    equivalent_ellipsoid : (3,) ndarray — m, semi-axes of the same uniform ellipsoid
    parts : tuple of dict — each part's contribution (see :func:`part_rows`)
    warnings : tuple of str — none for this command
    """

    name: str
    mass: float
    reference: Any
    reference_label: str
    moments: Any
    axes: Any
    symmetry: str
    unique_axis: int | None
    free_axes: tuple[int, ...]
    stable: tuple[bool, bool, bool]
    direction_angles_deg: Any
    rotation_axis: Any
    rotation_angle_deg: float
    equivalent_box: Any
    equivalent_ellipsoid: Any
    stability: tuple[str, str, str] = ("stable", "stable", "stable")
    tilt_deg: Any = None
    tilt_axis: tuple[str, str, str] = ("x", "y", "z")
    parts: tuple[dict, ...] = ()
    warnings: tuple[str, ...] = field(default=())

    def to_json(self) -> dict[str, Any]:
        """What ``rbcli principal BODY --json`` prints, less ``"file"`` (SI)."""
        return _with_parts({
            "reference": self.reference,
            "moments": self.moments,
            "axes": snap(self.axes, scale=1.0, rtol=1e-15),
            "symmetry": self.symmetry,
            "stable": list(self.stable),
            "mass": self.mass,
            "free_axes": [i + 1 for i in self.free_axes],
            "direction_angles_deg": self.direction_angles_deg,
            "rotation_axis": self.rotation_axis,
            "rotation_angle_deg": self.rotation_angle_deg,
            "equivalent_box": self.equivalent_box,
            "equivalent_ellipsoid": self.equivalent_ellipsoid,
            "stability": list(self.stability),
            "tilt_deg": self.tilt_deg,
            "tilt_axis": list(self.tilt_axis),
            "name": self.name,
        }, self.parts)


def run_principal(body: Any, options: PrincipalOptions) -> PrincipalResult:
    """:func:`principal` with options already parsed."""
    from rbcli.core.inertia import body_mass_props
    from rbcli.core.principal import principal_report

    mp = body_mass_props(body)
    point, J = _inertia_at(mp, options.reference)
    pr = principal_report(mp.mass, J, point)
    pa = pr.axes_info
    rows = part_rows(body)
    return PrincipalResult(
        name=body.name, mass=pr.mass, reference=pr.reference,
        reference_label=options.reference.label, moments=pa.moments, axes=pa.axes,
        symmetry=pa.symmetry, unique_axis=pa.unique_axis, free_axes=tuple(pa.free_axes),
        stable=pr.stable, direction_angles_deg=pr.direction_angles_deg,
        rotation_axis=pr.rotation_axis, rotation_angle_deg=pr.rotation_angle_deg,
        equivalent_box=pr.equivalent_box, equivalent_ellipsoid=pr.equivalent_ellipsoid,
        stability=pr.stability, tilt_deg=pr.tilt_deg, tilt_axis=tuple("xyz"[j] for j in pr.tilt_axis),
        parts=rows, warnings=options.warnings)


def principal(body: Any, *, about: o.Value | None = "com") -> PrincipalResult:
    """Principal moments and axes, symmetry, stability of free rotation and the equivalent
    uniform box and ellipsoid.

    Parameters
    ----------
    body : rbcli.Body
    about : str or sequence of 3
        ``"com"`` (default), ``"origin"``, or x, y, z in m (or ``"10,0,5 mm"``).

    Returns
    -------
    PrincipalResult
        Moments ascending; ``axes`` rows are the unit axes, a right-handed set;
        ``to_json()`` is what ``rbcli principal BODY --json`` prints, less ``"file"``.

    Raises
    ------
    rbcli.InputError
        A bad ``about`` (message ``--about: ...``), or a point so far away that the inertia
        overflows.

    Notes
    -----
    Free rotation about the axes of the largest and smallest moment is stable, about the
    intermediate one unstable (Landau & Lifshitz, *Mechanics*, §37); about an axis of the
    equal pair of a symmetric body neutral (``stability``; ``stable`` false). ``tilt_deg``
    is each axis's angle from its nearest body axis (``tilt_axis``): the headline of a
    body whose principal axes are near its body axes.

    Examples
    --------
    >>> import rbcli
    >>> p = rbcli.principal(rbcli.load("examples/square_lamina.yaml"), about="origin")
    >>> [round(float(m), 6) for m in p.moments]                # m a²/12, 7 m a²/12, 2 m a²/3
    [0.083333, 0.583333, 0.666667]
    >>> p.symmetry
    'asymmetric'
    """
    return run_principal(body, PrincipalOptions.parse(body, about=about))

