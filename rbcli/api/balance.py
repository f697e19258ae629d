"""Rotor balance about a shaft: the service behind ``rbcli balance``.

:func:`parse` reads the parameters, :func:`run` computes with :mod:`rbcli.core.balance`
(sheet ``balance.md``; ISO 21940-11:2016) a :class:`BalanceResult`. Trial-weight
balancing is :mod:`rbcli.api.field`."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from rbcli.api import balancejson as J
from rbcli.api import options as op
from rbcli.api.commands import BALANCE
from rbcli.api.diagram import Arrow, Diagram, Panel
from rbcli.api.params import Options, function, read
from rbcli.api.result import Result, jsonable
from rbcli.api.shaft import shaft_axis, shaft_point
from rbcli.body.model import with_points
from rbcli.core import balance as B
from rbcli.core.inertia import body_mass_props
from rbcli.core.scale import SPEED_OF_SOUND, axis_reach, body_scale
from rbcli.errors import ExitStatus, InputError, NonFiniteResult, Note, ParamError

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.body.model import Body

__all__ = ["AddedMass", "BalanceResult", "balance", "parse", "run"]

#: the core's parameter names -> the parameters of :func:`balance`
_CORE_PARAMS = {
    "axis": "shaft", "through": "through", "reference": "mark", "zero_mark_deg": "zero_mark_deg",
    "angle_sense": "angle_sense", "planes": "planes", "radii": "radius", "bearings": "bearings",
    "mass_step": "mass_step", "angle_step_deg": "angle_step", "n_positions": "positions",
    "speed": "speed", "g": "g", "grade": "grade",
}

#: the parameters whose size can make a result overflow (named when one does)
_SIZES = ("planes", "radius", "bearings", "speed", "mass_step", "through", "g")

#: the parameters that must be positive, and what they are (the message quotes the value in
#: the body's bare unit)
_POSITIVE = {"radius": "the correction radius", "mass_step": "the mass step",
             "speed": "the speed (to turn the other way, reverse {shaft})", "g": "gravity"}


def _num(x: float) -> str:
    """A number as the tables print it (6 significant figures, no '-0')."""
    s = f"{float(x):.6g}"
    return s[1:] if s.startswith("-") and float(s) == 0.0 else s


# --- options


def parse(body: Body, **kwargs: Any) -> Options:
    """The keyword arguments of :func:`balance` read for ``body`` (Options in SI, ``radius``
    (rA, rB) or the body's ``rim_radius``, defaults filled in); an InputError names the
    parameter."""
    if kwargs.get("angle_sense") == "with":  # the default (the command line always passes it)
        kwargs = {**kwargs, "angle_sense": None}
    o = read(body, BALANCE, kwargs)
    u = op.Units.of(body)
    for p in BALANCE:
        if p.name in _POSITIVE and getattr(o, p.name) is not None:
            for x in np.atleast_1d(getattr(o, p.name)):
                u.check_positive(float(x), p.quantity, p.name, _POSITIVE[p.name])
    if o.planes is None:
        for name in ("radius", "mass_step", "angle_step", "positions"):
            if getattr(o, name) is not None:
                raise ParamError(name, "needs the correction planes, {planes} zA,zB")
    if o.positions is not None and o.angle_step is not None:
        raise ParamError("angle_step", "the angles are fixed by {positions}; give one or the other")
    if o.grade is not None:
        _check_grade(o)
    elif o.tolerance_planes is not None:
        raise ParamError("tolerance_planes", "only used with {grade}")
    return o.replace(radius=_radius(body, o), g=o.g or B.STANDARD_GRAVITY,
                     angle_sense=o.angle_sense or "with", zero_mark_deg=o.zero_mark_deg or 0.0,
                     tolerance_planes=o.tolerance_planes or "bearings")


def _check_grade(o: Options) -> None:
    """What the ISO check needs: the speed and its tolerance planes."""
    if o.speed is None:
        raise ParamError("grade", "needs {speed}, the maximum service speed (e.g. {speed} '3000 rpm')")
    if o.tolerance_planes == "corrections":
        if o.planes is None:
            raise InputError("{tolerance_planes} corrections: needs {planes} zA,zB",
                             param="tolerance_planes")
    elif o.bearings is None:
        raise ParamError("grade", "needs {bearings} z1,z2, the planes ISO 21940-11 allocates the "
                         "tolerance to (or {tolerance_planes} corrections with {planes})")


def _radius(body: Body, o: Options) -> Any:
    """The correction radius r or (rA, rB): given, else the body's rim_radius (with planes)."""
    if o.planes is None:
        return None
    if o.radius is not None:
        return o.radius[0] if len(o.radius) == 1 else o.radius
    if body.rim_radius is None:
        raise ParamError("planes", "needs {radius} (the radius the correction masses sit at), "
                         "or rim_radius in the body file")
    return float(body.rim_radius)


# --- result


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

    @property
    def name(self) -> str:
        """The point part's name: ``balance A``, ``balance A (position 3)``."""
        return f"balance {self.plane}" + (f" (position {self.position})" if self.position is not None else "")


@dataclass(frozen=True)
class BalanceResult(Result):
    """Everything ``rbcli balance`` reports for a rotor.

    Attributes
    ----------
    body : Body; options : rbcli.api.params.Options — the parameters as read (:func:`parse`)
    unbalance : rbcli.core.balance.Unbalance — about the shaft
    shaft_source, through_source, mark_source, angle_convention : str — in words
    ideal : Corrections or None — with ``planes``: the exact two-plane corrections
    installed : Corrections or None — what to fit (rounded, or the net at the ``positions``);
        its ``residual`` is the rotor with exactly those masses
    position_split : PositionCorrections or None — the masses on the positions
    radius_source : Note or None — ``{radius}`` or "the body's rim_radius"
    corrected_unbalance : Unbalance or None — the rotor with ``added`` fitted
    added : tuple of AddedMass — the masses to fit as body points (kg, m)
    forces, forces_after : BearingForces or None — at ``speed``, before and after (N)
    iso_check : IsoCheck or None — the ISO 21940-11 check
    warnings : tuple of str"""

    body: Body
    options: Options
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
    forces: B.BearingForces | None = None
    forces_after: B.BearingForces | None = None
    iso_check: B.IsoCheck | None = None
    warnings: tuple[str, ...] = ()

    @property
    def angular_momentum_magnitude(self) -> float | None:
        """kg m²/s, |L| about the com at ``speed`` (None without a speed)."""
        return None if self.options.speed is None else float(np.linalg.norm(self.forces.angular_momentum))

    @property
    def torque_magnitude(self) -> float | None:
        """N m, |ω × L| about the com at ``speed`` (None without a speed)."""
        return None if self.options.speed is None else float(np.linalg.norm(self.forces.torque))

    @property
    def torque_direction(self) -> tuple[float, bool] | None:
        """(deg, defined): the direction of the torque ω × L in the rotor frame, as printed;
        not defined when the torque is zero to Ω² times the couple tolerance."""
        if self.options.speed is None:
            return None
        tz = complex(float(self.forces.torque[0]), float(self.forces.torque[1]))
        return self.unbalance.angle_of(tz, self.options.speed**2 * self.unbalance.tol_couple)

    @property
    def return_code(self) -> int:
        """1 when the rotor as given fails the ISO grade asked for, else 0."""
        if self.iso_check is not None and not self.iso_check.passed:
            return int(ExitStatus.CHECK_FAILED)
        return int(ExitStatus.OK)

    def diagram(self):
        """The polar balancing diagram ``--plot`` draws (:class:`rbcli.api.diagram.Diagram`):
        with ``planes`` a clock face per plane (the unbalance there, the masses to add as m r,
        the residual); without, U and P_G. Angles as the command prints them."""
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

        The masses of :attr:`added` become ``point`` parts ``balance A`` and ``balance B``
        (``balance A (position 3)`` with ``positions``; a name already used gets `` (2)``), in
        grams and millimetres to 15 figures. An InputError without ``planes`` (nothing to fit) or
        for a rotor rbcli did not read or build (:meth:`rbcli.Body.to_yaml`).

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
        True"""
        if self.installed is None:
            raise ParamError("planes", "balanced_body() needs the correction planes: "
                             "balance(..., {planes}=\"zA,zB\")")
        points = [(a.name, a.mass, a.at) for a in self.added]
        return with_points(self.body, points)

    def to_json(self) -> dict[str, Any]:
        """The document ``rbcli balance --json`` prints, less ``file`` (and ``apply``)."""
        corr = self.ideal if self.position_split is not None else self.installed
        forces = self.forces if self.options.speed is not None else None
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
        if self.options.bearings is not None and self.forces is not None:
            d["bearings"] = [
                {"plane": float(z), "name": str(i + 1), "static_load": float(w)}
                for i, (z, w) in enumerate(zip(self.options.bearings, self.forces.static_loads))
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


# --- the service


def _param_error(exc: ValueError, rename: dict[str, str] | None = None) -> InputError:
    """A core BalanceValueError as the InputError of the parameter it names."""
    param = (rename or {}).get(getattr(exc, "param", ""), None) or _CORE_PARAMS.get(getattr(exc, "param", ""))
    if param is None:  # the rotor's own data (mass, com, inertia): no parameter is at fault
        return InputError(f"balance: {exc}")
    return ParamError(param, str(exc))


def run(body: Body, options: Options) -> BalanceResult:
    """Balance ``body`` with ``options`` (:func:`parse`): an InputError names a value the
    physics cannot use; :class:`rbcli.NonFiniteResult` when the result overflows."""
    try:
        with np.errstate(all="ignore"):
            res = _run(body, options)
            res.to_json()  # the one finiteness check (jsonable): refuses inf and NaN
    except (OverflowError, ZeroDivisionError, NonFiniteResult):
        raise NonFiniteResult(
            f"{', '.join('{%s}' % p for p in _SIZES if p in options.given) or 'balance'}: the result "
            "overflows (a number beyond 1e308): an option value is too large or too small for this "
            "body") from None
    return res


def _run(body: Body, o: Options) -> BalanceResult:
    mp = body_mass_props(body)
    axis, axis_from = shaft_axis(body, o.shaft)
    where, point_from = shaft_point(body, o.through)
    P = np.array(mp.com if where == "com" else (0.0, 0.0, 0.0) if where == "origin" else where,
                 dtype=float)
    warnings: list[str] = _plausibility(body, o, axis, P)
    try:
        unb = B.unbalance(mp.mass, mp.com, mp.inertia_com, np.asarray(axis, dtype=float), P,
                          reference=o.mark, zero_mark_deg=o.zero_mark_deg, angle_sense=o.angle_sense)
        ideal, installed, positions, added, corrected = _fit(unb, o)
        forces = forces_after = None
        if o.speed is not None or o.bearings is not None:
            forces = B.bearing_forces(unb, o.speed or 0.0, o.bearings, g=o.g)
            if o.speed is not None and o.bearings is not None and corrected is not None:
                forces_after = B.bearing_forces(corrected, o.speed, o.bearings, g=o.g)
        iso = _iso(unb, installed, o) if o.grade is not None else None
    except B.BalanceValueError as exc:
        raise _param_error(exc) from None
    warnings += [*unb.warnings, *(installed.warnings if installed else ()), *(iso.warnings if iso else ())]
    span = None if o.bearings is None else abs(o.bearings[1] - o.bearings[0])
    if span is not None and span < B.NARROW_PLANE_FRACTION * unb.axial_length:
        u = op.Units.of(body)
        warnings.append(Note(
            f"{{bearings}} {u.show(span, 'length')} {u.label('length')} apart, less than "
            f"{B.NARROW_PLANE_FRACTION:g} of the rotor's length along the shaft "
            f"({u.show(unb.axial_length, 'length')} {u.label('length')}): the couple unbalance (and the "
            "weight, with the centre of mass outside them) loads them as large opposite forces, "
            "divided by the span; check the positions"))
    biggest = max(pc.mass for pc in ideal.pair) if ideal is not None else math.inf
    if o.mass_step is not None and o.mass_step > biggest:
        u = op.Units.of(body)
        warnings.append(Note(
            f"{{mass_step}} {u.show(o.mass_step, 'mass')} {u.label('mass')} is larger than the largest "
            f"correction ({biggest * 1e3:.4g} g): the masses round to 0 or one step (if a unit is "
            f"missing: a bare number is {u.label('mass')}; did you mean grams, e.g. '1 g'?)"))
    through = f"{{through}} {where}" if isinstance(where, str) else \
        {"given": "{through}", "body": "the body's shaft", "default": "the origin, the default"}[point_from]
    return BalanceResult(
        body=body, options=o, unbalance=unb,
        shaft_source=Note({"given": "{shaft}", "body": "the body's shaft",
                           "default": "body z, the default"}[axis_from]),
        through_source=Note(through), mark_source=_mark_source(axis, o),
        angle_convention=_convention(o.angle_sense), ideal=ideal, installed=installed,
        position_split=positions,
        radius_source=None if o.planes is None else
        Note("{radius}" if "radius" in o.given else "the body's rim_radius"),
        corrected_unbalance=corrected, added=added, forces=forces, forces_after=forces_after,
        iso_check=iso, warnings=tuple(warnings))


def _fit(unb: B.Unbalance, o: Options) -> tuple:
    """With ``planes``: (the exact corrections, what to fit, the split onto the positions or
    None, the masses to fit as body points, the rotor with them fitted); else Nones."""
    if o.planes is None:
        return None, None, None, (), None
    ideal = B.corrections(unb, o.planes, o.radius, bearings=o.bearings)
    positions = None
    if o.positions is not None:
        positions = B.split_corrections(ideal, o.positions, mass_step=o.mass_step)
        installed = positions.corrections
        added = [AddedMass(name, k, m, tuple(float(v) for v in x)) for name, k, m, x in positions.points()]
    else:
        installed = ideal
        if o.mass_step is not None or o.angle_step is not None:
            installed = B.round_corrections(ideal, o.mass_step, o.angle_step)
        names = [pc.name for pc in installed.pair if pc.mass > 0.0]
        added = [AddedMass(name, None, m, tuple(float(v) for v in x))
                 for name, (m, x) in zip(names, B.correction_points(installed))]
    try:
        corrected = B.add_point_masses(unb, [(a.mass, a.at) for a in added])
    except B.BalanceValueError:  # the masses at the radius given overflow the rotor's
        raise OverflowError("the corrected rotor") from None
    return ideal, installed, positions, tuple(added), corrected


def _iso(unb: B.Unbalance, installed: Any, o: Options) -> B.IsoCheck:
    """The ISO 21940-11 check, its tolerance allocated to the bearings or the correction planes."""
    by_bearings = o.tolerance_planes == "bearings"
    try:
        return B.iso_check(unb, o.grade, o.speed, o.bearings if by_bearings else o.planes,
                           planes_are="bearing" if by_bearings else "correction",
                           corrections=installed)
    except B.BalanceValueError as exc:
        raise _param_error(exc, {"planes": "bearings" if by_bearings else "planes"}) from None


def _plausibility(body: Body, o: Options, axis: Any, P: Any) -> list[str]:
    """The plausibility warnings (:mod:`rbcli.core.scale`): a correction
    radius, a correction plane or a bearing more than 10 body sizes away; a correction
    radius moving faster than sound at a speed typed without its unit."""
    u = op.Units.of(body)
    sc = body_scale(body.parts)
    n = np.asarray(axis, dtype=float)
    n = n / np.linalg.norm(n)
    out = []
    radii = () if o.radius is None else (o.radius if isinstance(o.radius, tuple) else (o.radius,))
    if "radius" in o.given and sc.beyond(max(radii)):
        out.append(u.far("radius", "the correction radius", max(radii), sc.size))
    for opt, zs, what in (("planes", o.planes, "correction plane"), ("bearings", o.bearings, "bearing")):
        for z in zs or ():
            d = sc.far(P + z * n)
            if d is not None:
                out.append(u.far(opt, f"the {what} at z = {u.show(z, 'length')} {u.label('length')}",
                                 d, sc.size))
                break
    if o.speed is not None and not o.unit_typed("speed"):
        r = max([*radii, axis_reach(body.parts, n, P)])  # the farthest material from the shaft
        if SPEED_OF_SOUND < o.speed * r < math.inf:
            out.append(Note(f"{{speed}}: at {u.show(o.speed, 'angular_speed')} {u.label('angular_speed')} "
                            f"a radius of {u.show(r, 'length')} {u.label('length')} moves at "
                            f"{o.speed * r:.4g} m/s, faster than sound ({SPEED_OF_SOUND:g} m/s); bare "
                            f"angular speeds are in {u.label('angular_speed')}: is a unit missing?"))
    return out


def _mark_source(axis: Any, o: Options) -> Note:
    """How the 0° mark was chosen (the rule of :func:`rbcli.core.balance.shaft_frame`)."""
    if o.mark is not None:
        text = "the {mark} direction projected at right angles to the shaft"
    elif abs(axis[0]) / math.sqrt(sum(x * x for x in axis)) > B.FRAME_SWITCH_COS:
        text = "body y projected at right angles to the shaft, as the shaft is within 25.8° of body x"
    else:
        text = "body x projected at right angles to the shaft"
    if o.zero_mark_deg:
        text += f", turned {_num(o.zero_mark_deg)}° about the shaft by {{zero_mark_deg}}"
    return Note(text)


def _convention(angle_sense: str) -> Note:
    """The angle convention, in words (printed with every result)."""
    against = angle_sense == "against"
    sense = ("against the direction of rotation for a positive speed ({angle_sense} against)"
             if against else "in the direction of rotation for a positive speed")
    return Note(f"angles: degrees about the shaft axis (+z) from +x, the 0° mark, towards "
                f"{'−y' if against else '+y'} — {sense}; a correction is a mass to add (remove the "
                "same mass at +180°)")


@function(BALANCE)
def balance(body: Body, **kwargs: Any) -> BalanceResult:
    """Unbalance of a rotor about its shaft, corrections, bearing forces and ISO 21940-11.

    Values are SI numbers or strings as typed on the command line (``"0,400 mm"``,
    ``"3000 rpm"``, ``"5 g"``), read by the rules of ``rbcli balance``.

    Parameters
    ----------
    body : Body
    {parameters}

    Returns
    -------
    BalanceResult
        ``return_code`` 1 when the rotor as given fails ``grade``.

    Raises
    ------
    TypeError, rbcli.InputError
        A wrong type (:mod:`rbcli.api.check`) or value, naming the parameter.

    Examples
    --------
    >>> import rbcli
    >>> r = rbcli.balance(rbcli.load("examples/two_disk_rotor.yaml"), planes="0,400 mm",
    ...                   radius="100 mm")
    >>> round(r.corrections[0].mass * 1e3, 4)   # g, plane A
    8.5"""
    return run(body, parse(body, **kwargs))
