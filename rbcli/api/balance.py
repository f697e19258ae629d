"""Rotor balance about a shaft: the service behind ``rbcli balance`` (and ``field-balance``).

:func:`balance` reads its options once (:class:`BalanceOptions`: SI numbers or quantity
strings, the body's defaults and where each value came from) and runs the physics of
:mod:`rbcli.core.balance` (:func:`run`): the unbalance about the shaft, two-plane
corrections (rounded or on fixed positions) with the residual they leave, bearing forces at
speed and the ISO 21940-11 check. The result (:class:`BalanceResult`) is frozen, knows its
JSON (``to_json()``, exactly what ``rbcli balance --json`` prints less ``file``) and its exit
status (1 when the rotor as given fails the grade).

:func:`field_balance` (trial-weight balancing from vibration readings, no body) lives in
:mod:`rbcli.api.fieldbalance` and is re-exported here.

The physics and its sources: the physics sheet ``physics/balance.md`` (cited in
:mod:`rbcli.core.balance`), ISO 21940-11:2016 "Mechanical vibration — Rotor balancing —
Part 11: Procedures and tolerances for rotors with rigid behaviour".
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from rbcli.api import check
from rbcli.api import options as op
from rbcli.api.check import Point, Quantity, Values, Vector
from rbcli.api.fieldbalance import (  # noqa: F401  (re-exported: rbcli.field_balance)
    FieldBalanceOptions, FieldBalanceResult, field_balance,
)
from rbcli.api.result import Result, jsonable
from rbcli.errors import ExitStatus, InputError, Note, ParamError, literal

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.core import balance as B
    from rbcli.body.model import Body

__all__ = ["AddedMass", "BalanceOptions", "BalanceResult", "balance", "run",
           "FieldBalanceOptions", "FieldBalanceResult", "field_balance"]

#: the checker of each keyword argument of :func:`balance` (:mod:`rbcli.api.check`)
KINDS = {
    "shaft": check.vector, "through": check.vector, "mark": check.vector,
    "zero_mark_deg": check.quantity, "angle_sense": check.text, "planes": check.values(2),
    "radius": check.values(2), "mass_step": check.quantity, "angle_step": check.quantity,
    "positions": check.count, "speed": check.quantity, "bearings": check.values(2),
    "g": check.quantity, "grade": check.quantity, "tolerance_planes": check.text,
}

#: the default gravity for the static bearing loads, m/s² (standard gravity)
STANDARD_GRAVITY = 9.80665

#: the core's parameter names -> the options of :func:`balance`
_CORE_PARAMS = {
    "axis": "shaft", "through": "through", "reference": "mark", "zero_mark_deg": "zero_mark_deg",
    "angle_sense": "angle_sense", "planes": "planes", "radii": "radius", "bearings": "bearings",
    "mass_step": "mass_step", "angle_step_deg": "angle_step", "n_positions": "positions",
    "speed": "speed", "g": "g", "grade": "grade",
}


#: the parameters whose size can make a result overflow (named when one does)
_SIZES = ("planes", "radius", "bearings", "speed", "mass_step", "through", "g")


def _num(x: float) -> str:
    """A number as the tables print it (6 significant figures, no '-0')."""
    s = f"{float(x):.6g}"
    return s[1:] if s.startswith("-") and float(s) == 0.0 else s


# ----------------------------------------------------------------------------- options


@dataclass(frozen=True)
class BalanceOptions:
    """The options of :func:`balance`, read and checked once, in SI, with where each came from.

    Attributes
    ----------
    shaft : (3,) tuple of float — shaft direction, body frame (largest component ±1)
    shaft_source : Note — ``{shaft}`` (the parameter, spelled by the caller), "the body's shaft" or "body z, the default"
    through : str | (3,) tuple — "com", "origin" or a point (m, body frame)
    through_source : Note — ``{through}`` (with ``com``/``origin`` when given so), "the body's shaft" or "the origin, the default"
    mark : (3,) tuple | None — direction of the 0° mark (body frame), None for the rule
    mark_source : str — how the 0° mark was chosen, in words
    zero_mark_deg : float — deg, the mark turned about the shaft
    angle_sense : str — "with" or "against"
    planes : (float, float) | None — m, correction planes z_A, z_B along the shaft
    radius : float | (float, float) | None — m, correction radius (or one per plane)
    radius_source : Note | None — ``{radius}`` or "the body's rim_radius"
    mass_step : float | None — kg; ``mass_step_text`` as given (for the warning)
    angle_step : float | None — deg
    positions : int | None — number of equally spaced positions
    speed : float | None — rad/s
    bearing_positions : (float, float) | None — m, the bearings along the shaft
    g : float — m/s² (default 9.80665)
    grade : float | None — ISO 21940-11 grade G, mm/s
    tolerance_planes : str — "bearings" or "corrections"
    given : tuple of str — the parameters the caller gave
    typed : tuple of (str, str) — (parameter, unit) for each value typed with a unit
        (``"0.5 g"``: ``("mass_step", "g")``), the unit the options table shows it in
    """

    shaft: tuple[float, float, float]
    shaft_source: str
    through: Any
    through_source: str
    mark: tuple[float, float, float] | None
    mark_source: str
    zero_mark_deg: float = 0.0
    angle_sense: str = "with"
    planes: tuple[float, float] | None = None
    radius: Any = None
    radius_source: str | None = None
    mass_step: float | None = None
    mass_step_text: str | None = None
    angle_step: float | None = None
    positions: int | None = None
    speed: float | None = None
    bearings: tuple[float, float] | None = None
    g: float = STANDARD_GRAVITY
    grade: float | None = None
    tolerance_planes: str = "bearings"
    given: tuple[str, ...] = ()
    #: parameter -> the unit the caller typed after its number (the options table echoes in it)
    typed: tuple[tuple[str, str], ...] = ()

    @classmethod
    def parse(cls, body: Body, *, shaft: Vector | None = None, through: Point | None = None,
              mark: Vector | None = None, zero_mark_deg: Quantity | None = None,
              angle_sense: str | None = "with", planes: Values | None = None,
              radius: Values | None = None, mass_step: Quantity | None = None,
              angle_step: Quantity | None = None, positions: int | None = None,
              speed: Quantity | None = None, bearings: Values | None = None,
              g: Quantity | None = None, grade: Quantity | None = None,
              tolerance_planes: str | None = None) -> BalanceOptions:
        """Read the keyword arguments of :func:`balance` (see there) for ``body``.

        Raises
        ------
        rbcli.InputError
            with the message the command line prints (``--planes: ...``).
        """
        angle_sense_given = angle_sense not in (None, "with")
        angle_sense = op.choice(angle_sense if angle_sense is not None else "with",
                                "angle_sense", ("with", "against"))
        if tolerance_planes is not None:
            op.choice(tolerance_planes, "tolerance_planes", ("bearings", "corrections"))
        t_planes = tolerance_planes or "bearings"
        zero_deg = 0.0
        if zero_mark_deg is not None:
            zero_deg = op.degrees(zero_mark_deg, "zero_mark_deg")
            if not math.isfinite(zero_deg):
                raise InputError("{zero_mark_deg}: must be a finite angle", param="zero_mark_deg")
        u = op.Units.of(body)
        n_shaft = op.direction(shaft, "shaft") if shaft is not None else None
        p_through = u.point(through, "through") if through is not None else None
        v_mark = op.vector(mark, "dimensionless", "mark") if mark is not None else None
        z_planes = (op.distinct(u.numbers(planes, "length", "planes", counts=(2,)),
                                "planes", "correction planes") if planes is not None else None)
        r_opt = None
        if radius is not None:
            r_opt = [u.check_positive(x, "length", "radius", "the correction radius")
                     for x in u.numbers(radius, "length", "radius", counts=(1, 2))]
        m_step = (u.positive(mass_step, "mass", "mass_step", "the mass step")
                  if mass_step is not None else None)
        a_step = None
        if angle_step is not None:
            a_step = op.degrees(angle_step, "angle_step")
            if not (0.0 < a_step <= 360.0):
                raise InputError(f"{{angle_step}}: must be more than 0 and at most 360 degrees, got "
                                 f"{angle_step}", param="angle_step")
        n_pos = _positions(positions)
        W = (u.positive(speed, "angular_speed", "speed",
                        "the speed (to turn the other way, reverse {shaft})")
             if speed is not None else None)
        z_bear = (op.distinct(u.numbers(bearings, "length", "bearings", counts=(2,)),
                              "bearings", "bearings") if bearings is not None else None)
        gv = u.positive(g, "acceleration", "g", "gravity") if g is not None else None
        G = op.grade(grade) if grade is not None else None
        # --- which options need which
        if z_planes is None:
            for name, val in (("radius", radius), ("mass_step", mass_step),
                              ("angle_step", angle_step), ("positions", positions)):
                if val is not None:
                    raise ParamError(name, "needs the correction planes, {planes} zA,zB")
        if n_pos is not None and a_step is not None:
            raise ParamError("angle_step", "the angles are fixed by {positions}; give one or the other")
        if G is not None:
            if W is None:
                raise ParamError("grade", "needs {speed}, the maximum service speed (e.g. {speed} '3000 rpm')")
            if t_planes == "bearings" and z_bear is None:
                raise ParamError(
                    "grade", "needs {bearings} z1,z2, the planes ISO 21940-11 allocates the tolerance "
                    "to (or {tolerance_planes} corrections with {planes})")
            if t_planes == "corrections" and z_planes is None:
                raise InputError("{tolerance_planes} corrections: needs {planes} zA,zB",
                                 param="tolerance_planes")
        elif tolerance_planes is not None:
            raise ParamError("tolerance_planes", "only used with {grade}")
        # --- the body's defaults, and where each value came from
        from rbcli.api.reference import shaft_axis, shaft_point

        axis, came = shaft_axis(body, n_shaft)
        shaft_source = {"given": "{shaft}", "body": "the body's shaft", "default": "body z, the default"}[came]
        where, came = shaft_point(body, p_through)
        through_source = {"given": "{through}", "body": "the body's shaft",
                          "default": "the origin, the default"}[came]
        if isinstance(where, str):
            through_source = f"{{through}} {where}"
        radii = radius_source = None
        if z_planes is not None:
            if r_opt is not None:
                radii = r_opt[0] if len(r_opt) == 1 else (r_opt[0], r_opt[1])
                radius_source = "{radius}"
            elif body.rim_radius is not None:
                radii, radius_source = float(body.rim_radius), "the body's rim_radius"
            else:
                raise ParamError("planes", "needs {radius} (the radius the correction masses sit at), "
                                 "or rim_radius in the body file")
        given = tuple(p for p, v in (
            ("shaft", shaft), ("through", through), ("mark", mark), ("zero_mark_deg", zero_mark_deg),
            ("angle_sense", "against" if angle_sense_given else None), ("planes", planes),
            ("radius", radius), ("mass_step", mass_step), ("angle_step", angle_step),
            ("positions", positions), ("speed", speed), ("bearings", bearings), ("g", g),
            ("grade", grade), ("tolerance_planes", tolerance_planes)) if v is not None)
        return cls(
            shaft=axis, shaft_source=Note(shaft_source), through=where,
            through_source=Note(through_source),
            mark=tuple(v_mark) if v_mark is not None else None,
            mark_source=_mark_source(axis, v_mark is not None, zero_deg),
            zero_mark_deg=zero_deg, angle_sense=angle_sense,
            planes=z_planes, radius=radii,
            radius_source=None if radius_source is None else Note(radius_source),
            mass_step=m_step, mass_step_text=None if mass_step is None else _as_text(mass_step),
            angle_step=a_step, positions=n_pos, speed=W, bearings=z_bear,
            g=STANDARD_GRAVITY if gv is None else gv, grade=G,
            tolerance_planes=t_planes, given=given, typed=tuple(u.typed.items()))


def _plausibility(body: Body, o: BalanceOptions, P: Any) -> list[str]:
    """One-line warnings for values far outside the body's scale (issue 13): a correction
    radius, a correction plane or a bearing more than 10 body sizes away; a correction
    radius moving faster than sound."""
    import numpy as np

    from rbcli.core.scale import FAR, SPEED_OF_SOUND, body_scale

    u = op.Units.of(body)
    sc = body_scale(body.parts)
    n = np.asarray(o.shaft, dtype=float)
    n = n / np.linalg.norm(n)
    out = []
    radii = () if o.radius is None else (o.radius if isinstance(o.radius, tuple) else (o.radius,))
    if o.radius_source is not None and o.radius_source.template == "{radius}" and max(radii) > FAR * sc.size:
        out.append(u.far("radius", "the correction radius", max(radii), sc.size))
    for opt, zs, what in (("planes", o.planes, "correction plane"), ("bearings", o.bearings, "bearing")):
        for z in zs or ():
            d = sc.far(np.asarray(P, dtype=float) + z * n)
            if d is not None:
                out.append(u.far(opt, f"the {what} at z = {u.show(z, 'length')} {u.label('length')}",
                                 d, sc.size))
                break
    if o.speed is not None:
        from rbcli.core.scale import axis_reach

        r = max([*radii, axis_reach(body.parts, n, P)])  # the farthest material from the shaft
        if SPEED_OF_SOUND < o.speed * r < math.inf:
            out.append(Note(f"{{speed}}: at {u.show(o.speed, 'angular_speed')} {u.label('angular_speed')} "
                       f"a radius of {u.show(r, 'length')} {u.label('length')} moves at "
                       f"{o.speed * r:.4g} m/s, faster than sound ({SPEED_OF_SOUND:g} m/s); bare "
                       f"angular speeds are in {u.label('angular_speed')}: is a unit missing?"))
    return out




def _as_text(v: Any) -> str:
    """A value as the user wrote it (a string as is, a number by repr)."""
    if isinstance(v, str):
        return v
    if isinstance(v, (int, float)):
        return repr(v)
    return str(v)


def _positions(v: Any) -> int | None:
    """``--positions N``: a whole number >= 3."""
    if v is None:
        return None
    try:
        n = int(v) if not isinstance(v, float) or v.is_integer() else None
    except (TypeError, ValueError):
        n = None
    if n is None or isinstance(v, bool):
        raise ParamError("positions", f"expected a whole number of positions, got {v!r}")
    if n < 3:
        raise ParamError("positions", f"needs at least 3 equally spaced positions, got {n}")
    return n


def _mark_source(axis, mark_given: bool, zero_mark_deg: float) -> str:
    """How the 0° mark was chosen (the rule of :func:`rbcli.core.balance.shaft_frame`)."""
    if mark_given:
        text = "the {mark} direction projected at right angles to the shaft"
    else:
        from rbcli.core.balance import FRAME_SWITCH_COS

        n = math.sqrt(sum(float(x) * float(x) for x in axis))
        if abs(float(axis[0]) / n) > FRAME_SWITCH_COS:
            text = "body y projected at right angles to the shaft, as the shaft is within 25.8° of body x"
        else:
            text = "body x projected at right angles to the shaft"
    if zero_mark_deg:
        text += f", turned {_num(zero_mark_deg)}° about the shaft by {{zero_mark_deg}}"
    return Note(text)


def _convention(angle_sense: str) -> str:
    """The angle convention, in words (printed with every result)."""
    against = angle_sense == "against"
    towards = "−y" if against else "+y"
    sense = ("against the direction of rotation for a positive speed ({angle_sense} against)"
             if against else "in the direction of rotation for a positive speed")
    return Note(f"angles: degrees about the shaft axis (+z) from +x, the 0° mark, towards {towards} — "
                f"{sense}; a correction is a mass to add (remove the same mass at +180°)")


# ----------------------------------------------------------------------------- result


@dataclass(frozen=True)
class AddedMass:
    """A correction mass to fit, as a point of the body (what ``--apply`` writes).

    Attributes
    ----------
    plane : str — "A" or "B"
    position : int | None — the position number with ``positions``, else None
    mass : float — kg
    at : (3,) tuple of float — m, body frame
    """

    plane: str
    position: int | None
    mass: float
    at: tuple[float, float, float]


@dataclass(frozen=True)
class BalanceResult(Result):
    """Everything ``rbcli balance`` reports for a rotor.

    Attributes
    ----------
    body : Body — the rotor
    unbalance : rbcli.core.balance.Unbalance — about the shaft: ``mass`` (kg), ``static``
        U (kg m, complex), ``couple`` P_G (kg m², about the com), ``moment`` P (about z = 0),
        ``eccentricity`` (m), ``tilt_deg``, ``statically_balanced``, ``dynamically_balanced``,
        ``frame`` (the shaft frame)
    shaft_source, through_source, mark_source : str — where the shaft, its point and the 0°
        mark came from
    angle_convention : str — the angle convention, in words
    ideal : rbcli.core.balance.Corrections | None — with ``planes``: the exact two-plane
        corrections (masses kg, radii m, angles deg)
    installed : rbcli.core.balance.Corrections | None — what to fit: rounded when asked, the
        net of the masses at the positions with ``positions``; its ``residual`` is the rotor
        with exactly those masses added
    position_split : rbcli.core.balance.PositionCorrections | None — the masses on the positions
    radius_source : Note | None — ``{radius}`` or "the body's rim_radius"
    corrected_unbalance : rbcli.core.balance.Unbalance | None — the rotor with ``added`` fitted
    added : tuple of AddedMass — the masses to fit as body points (kg, m)
    speed : float | None — rad/s
    bearing_positions : (float, float) | None — m, the bearings along the shaft
    forces : rbcli.core.balance.BearingForces | None — at ``speed`` (N), static loads (N)
    forces_after : rbcli.core.balance.BearingForces | None — the same after the corrections
    iso_check : rbcli.core.balance.IsoCheck | None — the ISO 21940-11 check (``passed``)
    warnings : tuple of str — one-line warnings (the command prints them on standard error)
    """

    body: Body
    unbalance: B.Unbalance
    shaft_source: str
    through_source: str
    mark_source: str
    angle_convention: str
    ideal: B.Corrections | None = None
    installed: B.Corrections | None = None
    position_split: B.PositionCorrections | None = None
    radius_source: str | None = None
    corrected_unbalance: B.Unbalance | None = None
    added: tuple[AddedMass, ...] = ()
    speed: float | None = None
    bearing_positions: tuple[float, float] | None = None
    forces: B.BearingForces | None = None
    forces_after: B.BearingForces | None = None
    iso_check: B.IsoCheck | None = None
    warnings: tuple[str, ...] = ()

    @property
    def correction_pair(self):
        """The two masses to add, planes A and B (``rbcli.core.balance.PlaneCorrection``:
        ``mass`` kg, ``angle_deg``, ``radius`` m, ``z`` m), as JSON ``corrections``: rounded
        when asked, the exact ones with ``positions``; None without ``planes``."""
        c = self.ideal if self.position_split is not None else self.installed
        return None if c is None else c.pair

    @property
    def angular_momentum_magnitude(self) -> float | None:
        """kg m²/s, |L| about the com at ``speed`` (None without a speed)."""
        import numpy as np

        return None if self.speed is None else float(np.linalg.norm(self.forces.angular_momentum))

    @property
    def torque_magnitude(self) -> float | None:
        """N m, |ω × L| about the com at ``speed`` (None without a speed)."""
        import numpy as np

        return None if self.speed is None else float(np.linalg.norm(self.forces.torque))

    @property
    def torque_direction(self) -> tuple[float, bool] | None:
        """(deg, defined): the direction of the torque ω × L in the rotor frame, as printed;
        not defined when the torque is zero to Ω² times the couple tolerance."""
        if self.speed is None:
            return None
        tz = complex(float(self.forces.torque[0]), float(self.forces.torque[1]))
        return self.unbalance.angle_of(tz, self.speed**2 * self.unbalance.tol_couple)

    @property
    def return_code(self) -> int:
        """1 when the rotor as given fails the ISO grade asked for, else 0."""
        if self.iso_check is not None and not self.iso_check.passed:
            return int(ExitStatus.CHECK_FAILED)
        return int(ExitStatus.OK)

    def diagram(self):
        """The polar balancing diagram (what ``--plot`` draws), an
        :class:`rbcli.api.diagram.Diagram`: with ``planes`` one clock face per correction
        plane with the rotor's unbalance in that plane as given, the masses to add (as
        unbalances m r, with their masses) and the residual after adding them; without, the
        static unbalance U and the couple unbalance P_G. Angles as the command prints them."""
        from rbcli.api.diagram import Arrow, Diagram, Panel
        from rbcli.core import balance as B

        u = self.unbalance
        panels = []
        if self.installed is None:
            a, ok = u.angle_of(u.static, u.tol_static)
            panels.append(Panel("static unbalance U", "unbalance",
                                (Arrow("initial", "U, as given", abs(u.static), a, ok),)))
            a, ok = u.angle_of(u.couple, u.tol_couple)
            panels.append(Panel("couple unbalance P_G (about the com)", "couple",
                                (Arrow("initial", "P_G, as given", abs(u.couple), a, ok),)))
        else:
            fit = self.installed
            res = fit.residual
            initial = B.plane_unbalances(u.static, u.moment, *fit.planes)
            for i, pc in enumerate(fit.pair):
                arrows = []
                a, ok = u.angle_of(initial[i], res.tol_plane)
                arrows.append(Arrow("initial", f"{pc.name}: unbalance as given", abs(initial[i]), a, ok))
                if self.position_split is not None:
                    sp = self.position_split.splits[i]
                    for m, ang, k in zip(sp.masses, sp.angles_deg, sp.positions):
                        arrows.append(Arrow("correction", f"{pc.name}: add at position {k}",
                                            m * pc.radius, ang, m > 0.0, mass=m))
                else:
                    arrows.append(Arrow("correction", f"{pc.name}: add", abs(pc.unbalance), pc.angle_deg,
                                        pc.angle_defined or pc.mass > 0.0, mass=pc.mass))
                a, ok = u.angle_of(res.plane_unbalances[i], res.tol_plane)
                arrows.append(Arrow("residual", f"{pc.name}: residual", abs(res.plane_unbalances[i]), a, ok))
                panels.append(Panel(f"plane {pc.name} (z = {_num(pc.z * 1e3)} mm)", "unbalance", tuple(arrows)))
        sense = "against" if u.angle_sense == "against" else "with"
        note = ("seen from the +z end of the shaft, the rotor turning counterclockwise; angles from "
                "the 0° mark " + ("against" if sense == "against" else "in")
                + " the direction of rotation, as printed")
        return Diagram(f"balance: {self.body.name}", tuple(panels), sense, note)

    def balanced_body(self) -> Body:
        """The rotor with the correction masses fitted: what ``rbcli balance --apply`` writes.

        The masses to fit (:attr:`added`: the corrections rounded with ``mass_step`` and
        ``angle_step``, or split onto the ``positions``) become ``point`` parts named
        ``balance A`` and ``balance B`` (``balance A (position 3)`` with ``positions``; a
        name already used gets `` (2)``), their numbers written in explicit units (grams and
        millimetres, 15 significant figures) whatever the body's ``units``. The new body is
        checked as any body is; ``.to_yaml()`` writes it.

        Returns
        -------
        Body
            The balanced rotor (``source`` ``"<data>"``); balancing it again leaves the
            residual of ``installed.residual``, to the 15 figures written.

        Raises
        ------
        rbcli.InputError
            Without the correction planes (``planes``) there is nothing to fit; or the
            rotor is not one rbcli read or built (see :meth:`rbcli.Body.to_yaml`).

        Examples
        --------
        >>> import rbcli
        >>> rotor = rbcli.load("examples/two_disk_rotor.yaml")
        >>> r = rbcli.balance(rotor, planes="0,400 mm", radius="100 mm", mass_step="1 g")
        >>> fitted = r.balanced_body()
        >>> [p.name for p in fitted.parts[-2:]]
        ['balance A', 'balance B']
        >>> again = rbcli.balance(fitted, planes="0,400 mm", radius="100 mm")
        >>> bool(again.corrections[0].mass < 1e-3)    # less than the 1 g step, kg
        True
        """
        from rbcli.body.model import with_points

        if self.installed is None:
            raise ParamError("planes", "balanced_body() needs the correction planes: "
                             "balance(..., {planes}=\"zA,zB\")")
        points = [(f"balance {a.plane}" + (f" (position {a.position})" if a.position is not None else ""),
                   a.mass, a.at) for a in self.added]
        return with_points(self.body, points)

    def to_json(self) -> dict[str, Any]:
        """The document ``rbcli balance --json`` prints, less ``file`` (and ``apply``)."""
        from rbcli.api import balancejson as J

        corr = self.ideal if self.position_split is not None else self.installed
        forces = self.forces if self.speed is not None else None
        d = J.balance_json(self.unbalance, corr, forces, self.iso_check)
        if self.position_split is not None:
            pj = J.positions_json(self.position_split)
            det = d["correction_details"]
            det["residual"] = pj["residual"]
            det["rounded"] = pj["rounded"]
            det["mass_step"] = pj["mass_step"]
            d["positions"] = {k: v for k, v in pj.items() if k != "residual"}
        if self.installed is not None:
            d["correction_details"]["radius_source"] = self.radius_source
        if self.corrected_unbalance is not None:
            cj = J.unbalance_json(self.corrected_unbalance)
            d["corrected"] = {k: cj[k] for k in (
                "mass", "eccentricity", "static_unbalance", "couple_unbalance", "tilt_deg",
                "statically_balanced", "dynamically_balanced")}
        if self.bearing_positions is not None and self.forces is not None:
            d["bearings"] = [
                {"plane": float(z), "name": str(i + 1), "static_load": float(w)}
                for i, (z, w) in enumerate(zip(self.bearing_positions, self.forces.static_loads))
            ]
            if "dynamics" not in d:
                d["static_load_assumption"] = "shaft horizontal, gravity at right angles to it"
        if self.forces_after is not None:
            d["bearing_forces_after"] = [
                {k: row[k] for k in ("plane", "name", "force", "angle_deg", "angle_defined")}
                for row in J.bearing_forces_json(self.forces_after)["bearing_forces"]
            ]
        d["angle_convention"] = self.angle_convention
        d["shaft_source"] = self.shaft_source
        d["through_source"] = self.through_source
        d["mark_source"] = self.mark_source
        d["warnings"] = list(self.warnings)
        d["name"] = self.body.name
        return jsonable(d)


# ----------------------------------------------------------------------------- the service


def _param_error(exc: ValueError, rename: dict[str, str] | None = None) -> InputError:
    """A core BalanceValueError as the InputError of the option it names."""
    param = (rename or {}).get(getattr(exc, "param", ""), None) or _CORE_PARAMS.get(getattr(exc, "param", ""))
    if param is None:  # the rotor's own data (mass, com, inertia): no option is at fault
        return InputError(f"balance: {exc}")
    return ParamError(param, str(exc))


def run(body: Body, options: BalanceOptions) -> BalanceResult:
    """Balance ``body`` with ``options`` (see :func:`balance`).

    Raises
    ------
    rbcli.InputError
        an option the physics cannot use, named (``--positions: ...``);
        :class:`rbcli.NonFiniteResult` when the result overflows.
    """
    import numpy as np

    from rbcli.api.result import jsonable
    from rbcli.errors import NonFiniteResult

    try:
        with np.errstate(all="ignore"):
            res = _run(body, options)
            jsonable(res.to_json())  # the one finiteness check: refuses inf and NaN
    except (OverflowError, ZeroDivisionError, NonFiniteResult):
        raise NonFiniteResult(
            f"{', '.join('{%s}' % p for p in _SIZES if p in options.given) or 'balance'}: the result "
            "overflows (a number beyond "
            "1e308): an option value is too large or too small for this body"
        ) from None
    return res


def _run(body: Body, o: BalanceOptions) -> BalanceResult:
    import numpy as np

    from rbcli.core import balance as B
    from rbcli.core.inertia import body_mass_props

    mp = body_mass_props(body)
    if o.through == "com":
        P = np.array(mp.com)
    elif o.through == "origin":
        P = np.zeros(3)
    else:
        P = np.asarray(o.through, dtype=float)
    warnings: list[str] = _plausibility(body, o, P)
    try:
        unb = B.unbalance(mp.mass, mp.com, mp.inertia_com, np.asarray(o.shaft, dtype=float), P,
                          reference=o.mark, zero_mark_deg=o.zero_mark_deg,
                          angle_sense=o.angle_sense)
        warnings += unb.warnings
        ideal = installed = positions = corrected = None
        added: list[AddedMass] = []
        if o.planes is not None:
            ideal = B.corrections(unb, o.planes, o.radius, bearings=o.bearings)
            if o.positions is not None:
                positions = B.split_corrections(ideal, o.positions, mass_step=o.mass_step)
                installed = positions.corrections
                added = [AddedMass(name, k, m, tuple(float(v) for v in x))
                         for name, k, m, x in positions.points()]
            else:
                installed = ideal
                if o.mass_step is not None or o.angle_step is not None:
                    installed = B.round_corrections(ideal, o.mass_step, o.angle_step)
                names = [pc.name for pc in installed.pair if pc.mass > 0.0]
                added = [AddedMass(name, None, m, tuple(float(v) for v in x))
                         for name, (m, x) in zip(names, B.correction_points(installed))]
            warnings += installed.warnings
            try:
                corrected = B.add_point_masses(unb, [(a.mass, a.at) for a in added])
            except B.BalanceValueError:  # the masses at the radius given overflow the rotor's
                raise OverflowError("the corrected rotor") from None
        forces = forces_after = None
        if o.speed is not None or o.bearings is not None:
            forces = B.bearing_forces(unb, o.speed if o.speed is not None else 0.0, o.bearings, g=o.g)
            if o.speed is not None and o.bearings is not None and corrected is not None:
                forces_after = B.bearing_forces(corrected, o.speed, o.bearings, g=o.g)
        iso = None
        if o.grade is not None:
            by_bearings = o.tolerance_planes == "bearings"
            try:
                iso = B.iso_check(unb, o.grade, o.speed, o.bearings if by_bearings else o.planes,
                                  planes_are="bearing" if by_bearings else "correction",
                                  corrections=installed)
            except B.BalanceValueError as exc:
                raise _param_error(exc, {"planes": "bearings" if by_bearings else "planes"}) from None
            warnings += iso.warnings
    except B.BalanceValueError as exc:
        raise _param_error(exc) from None
    if o.mass_step is not None and ideal is not None:
        biggest = max(pc.mass for pc in ideal.pair)
        if o.mass_step > biggest:
            warnings.append(Note(
                f"{{mass_step}} {literal(o.mass_step_text)} is larger than the largest correction "
                f"({biggest * 1e3:.4g} g): the masses round to 0 or one step "
                "(a bare number is kg: did you mean grams, e.g. '1 g'?)"
            ))
    return BalanceResult(
        body=body, unbalance=unb, shaft_source=o.shaft_source, through_source=o.through_source,
        mark_source=o.mark_source, angle_convention=_convention(o.angle_sense), ideal=ideal,
        installed=installed, position_split=positions, radius_source=o.radius_source,
        corrected_unbalance=corrected, added=tuple(added), speed=o.speed,
        bearing_positions=o.bearings, forces=forces, forces_after=forces_after, iso_check=iso,
        warnings=tuple(warnings),
    )


def balance(body: Body, *, shaft: Vector | None = None, through: Point | None = None,
            mark: Vector | None = None, zero_mark_deg: Quantity | None = None,
            angle_sense: str = "with", planes: Values | None = None, radius: Values | None = None,
            mass_step: Quantity | None = None, angle_step: Quantity | None = None,
            positions: int | None = None, speed: Quantity | None = None,
            bearings: Values | None = None, g: Quantity | None = None,
            grade: Quantity | None = None, tolerance_planes: str | None = None) -> BalanceResult:
    """Unbalance of a rotor about its shaft, corrections, bearing forces and ISO 21940-11.

    Every value may be an SI number (a sequence for lists) or a string as typed on the
    command line (``"0,400 mm"``, ``"3000 rpm"``, ``"5 g"``): the rules of ``rbcli balance``.

    Parameters
    ----------
    body : Body
        The rotor (:func:`rbcli.load`).
    shaft : str or (3,) sequence, optional
        Shaft direction, body frame (or "x", "y", "z"). Default: the body's shaft, else z.
    through : str or (3,) sequence, optional
        A point of the shaft (z = 0 there), m: "com", "origin" or x,y,z. Default: the
        body's shaft point, else the origin.
    mark : (3,) sequence or str, optional
        Direction of the 0° mark (body frame); only its part at right angles to the shaft
        counts. Default: body x projected (body y for a shaft within 25.8° of body x).
    zero_mark_deg : float or str, optional
        Turn the 0° mark this far about the shaft, degrees (or "0.5 rad").
    angle_sense : {"with", "against"}
        Count angles with the rotation (default) or against it.
    planes : str or (2,) sequence, optional
        Correction planes z_A, z_B along the shaft, m.
    radius : float, str or (2,) sequence, optional
        Correction radius r (or r_A, r_B), m. Default: the body's rim_radius.
    mass_step : float or str, optional
        Round correction masses to multiples of this, kg (``"1 g"``).
    angle_step : float or str, optional
        Round correction angles to multiples of this, degrees.
    positions : int, optional
        N equally spaced fixed positions (holes, blades), position 1 on the 0° mark: each
        correction split onto the two neighbouring ones.
    speed : float or str, optional
        Rotor speed, rad/s (``"1500 rpm"``); with ``grade`` the maximum service speed.
    bearings : str or (2,) sequence, optional
        Bearing positions z_1, z_2 along the shaft, m.
    g : float or str, optional
        Gravity for the static bearing loads, m/s² (default 9.80665).
    grade : str or float, optional
        ISO 21940-11 balance quality grade (``"G6.3"``, 0.4 to 4000 mm/s); needs ``speed``
        and ``bearings`` (or ``tolerance_planes="corrections"`` with ``planes``).
    tolerance_planes : {"bearings", "corrections"}, optional
        Where the permissible unbalance is allocated (default the bearings).

    Returns
    -------
    BalanceResult
        ``return_code`` 1 when the rotor as given fails ``grade``.

    Raises
    ------
    TypeError
        An argument of the wrong type, naming the parameter and the type expected
        (:mod:`rbcli.api.check`).
    rbcli.InputError
        A bad or missing value, naming the parameter and ``param``.

    Examples
    --------
    >>> import rbcli
    >>> r = rbcli.balance(rbcli.load("examples/two_disk_rotor.yaml"), planes="0,400 mm",
    ...                   radius="100 mm")
    >>> round(r.corrections[0].mass * 1e3, 4)   # g, plane A
    8.5
    """
    body = check.body(body)
    kw = check.arguments(
        KINDS, shaft=shaft, through=through, mark=mark, zero_mark_deg=zero_mark_deg,
        angle_sense=angle_sense, planes=planes, radius=radius, mass_step=mass_step,
        angle_step=angle_step, positions=positions, speed=speed, bearings=bearings, g=g,
        grade=grade, tolerance_planes=tolerance_planes)
    with check.arithmetic(kw):
        return run(body, BalanceOptions.parse(body, **kw))
