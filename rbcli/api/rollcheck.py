"""When does a rolling wheel, coin or hoop stay up? The service behind ``rbcli rollcheck``:
the body made a rolling wheel (:func:`wheel_setup`: axle, rim radius and rim, each with
where it came from), the straight-rolling threshold, the verdict at a speed and the steady
circle (:mod:`rbcli.core.rolling`, physics sheet ``dynamics.md`` §3)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from rbcli.api import options as op
from rbcli.api.commands import ROLLCHECK
from rbcli.api.params import Options, function, read
from rbcli.api.result import Result, jsonable
from rbcli.api.shaft import shaft_axis, shaft_point
from rbcli.core import rolling as rl
from rbcli.core.inertia import body_mass_props
from rbcli.core.rim import RIM_OFFSET_LIMIT, ROUND_SHAPES, Rim, rim_candidates, rim_of
from rbcli.core.scale import SPEED_OF_SOUND, body_scale
from rbcli.core.wheel import STANDARD_GRAVITY, Wheel, wheel_from_body
from rbcli.errors import InputError, Location, Note, ParamError, literal

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.core.rollcircle import CircleMotion
    from rbcli.core.rolling import Curves, StraightRolling, Verdict
    from rbcli.body.model import Body
    from rbcli.body.partmodel import Part
    from rbcli.core.symmetry import AxialSymmetry

__all__ = ["OffCentreRim", "RollcheckResult", "WheelSetup", "parse", "rollcheck", "round_parts",
           "run", "wheel_setup"]


def round_parts(body: Body) -> list[Part]:
    """The parts of ``body`` that could make a rim: round, with an outer radius, not holes
    (whatever their axis; :func:`wheel_setup` keeps those coaxial with the axle)."""
    return [p for p in body.parts if not p.subtract and p.radius is not None and p.shape in ROUND_SHAPES]


# --- options


def parse(body: Body, **kwargs: Any) -> Options:
    """The keyword arguments of :func:`rollcheck` read for ``body`` (Options in SI); an
    InputError naming the parameter, or for a steady circle without two of lean, circle, speed."""
    o = read(body, ROLLCHECK, kwargs)
    u = op.Units.of(body)
    for name, kind, what in (("rim_radius", "length", "the rim radius"), ("g", "acceleration", "gravity")):
        if getattr(o, name) is not None:
            u.check_positive(getattr(o, name), kind, name, what)
    asked_speed = o.rolling_speed is not None or o.spin is not None
    if (o.lean is None) != (o.circle is None) and not asked_speed:
        have, need = ("lean", "circle") if o.lean is not None else ("circle", "lean")
        raise ParamError(have, "a steady circle needs two of {lean}, {circle} and {rolling_speed} (or "
                         f"{{spin}}); add {need} or {{rolling_speed}}")
    if o.circle == 0.0 and o.lean is None and asked_speed:
        raise InputError("{circle} 0: spinning in place the centre does not move, so {rolling_speed} "
                         "cannot fix the lean; give {lean} instead", param="circle")
    return o.replace(g=STANDARD_GRAVITY if o.g is None else o.g)


# --- the wheel


@dataclass(frozen=True)
class WheelSetup:
    """What the body makes of the wheel, with where each value came from.

    Attributes
    ----------
    axle, through : (3,) tuple — the unit axle and a point of its line (m), body frame
    axle_source : Note — where they came from, in words (``"{shaft}, through the origin"``)
    radius : float — m, the rim radius a (centre to floor when upright)
    radius_source, radius_kind : Note — where a came from, in words and as the JSON's
        ``radius_source`` (``{rim_radius}``, ``"rim_radius"`` or ``"largest_round_part"``)
    radius_part : str or None — the part's name for ``"largest_round_part"``
    tyre_radius : float — m, tube radius r: 0 a knife edge (or a flat band), a a sphere
    tyre_radius_kind : Note — ``{tyre_radius}``, ``"shape"`` or ``"knife_edge"``
    band : (float, float) or None — m, a flat band's edges from the plane of the com
    rim : rbcli.core.rim.Rim or None — the rim's parts and where it lies along the axle
    warnings : tuple of str — a rim slightly off the com's plane, values far outside the body"""

    axle: tuple[float, float, float]
    through: tuple[float, float, float]
    axle_source: Note
    radius: float
    radius_source: Note
    radius_kind: Note
    radius_part: str | None
    tyre_radius: float
    tyre_radius_kind: Note
    band: tuple[float, float] | None
    rim: Rim | None
    warnings: tuple[str, ...]


def wheel_setup(body: Body, o: Options) -> WheelSetup:
    """The wheel ``body`` makes with ``o``: the axle (else the body's shaft, else z), the rim
    radius (else the body's, else the largest coaxial round part) and the rim; an InputError
    as :func:`_tyre` says, or for no rim radius (located)."""
    mp = body_mass_props(body)
    axis, axis_from = shaft_axis(body, o.shaft)
    n = np.asarray(axis, dtype=float)
    n = n / np.linalg.norm(n)
    where, point_from = shaft_point(body, o.through)
    P = np.array(mp.com if where == "com" else (0.0, 0.0, 0.0) if where == "origin" else where,
                 dtype=float)
    axle_source = {"given": "{shaft}", "body": "the body's shaft", "default": "body z (default)"}[axis_from]
    through_source = f"{{through}} {where}" if isinstance(where, str) else \
        {"given": "{through}", "body": "the body's shaft", "default": "the origin"}[point_from]
    a, source, kind, part = _rim_radius(body, o, n, P, mp)
    rim = rim_of(body.parts, mp.com, n, P, a, tol=o.symmetry_tol)
    r, r_kind, band = _tyre(o, rim, a, source)
    warnings = []
    if rim is not None and rim.outside > 1e-6 * a and rim.upright_equilibrium:
        warnings.append(
            f"{rim.describe()}; the model takes the rim circle in the plane of the centre of mass "
            f"(rollcheck refuses rims more than {100 * RIM_OFFSET_LIMIT:g} % of the radius off it)")
    return WheelSetup(
        axle=tuple(float(x) for x in n), through=tuple(float(x) for x in P),
        axle_source=Note(f"{axle_source}, through {through_source}"), radius=float(a),
        radius_source=Note(source), radius_kind=Note(kind), radius_part=part, tyre_radius=r,
        tyre_radius_kind=Note(r_kind), band=band, rim=rim,
        warnings=(*warnings, *_plausibility(body, o, a)))


def _rim_radius(body: Body, o: Options, n: Any, P: Any, mp: Any) -> tuple[float, str, str, str | None]:
    """(a, where it came from in words, its JSON kind, the part's name or None)."""
    if o.rim_radius is not None:
        return o.rim_radius, "{rim_radius}", "{rim_radius}", None
    if body.rim_radius is not None:
        return float(body.rim_radius), "the body's rim_radius", "rim_radius", None
    best = None
    for p in rim_candidates(body.parts, n, P, o.symmetry_tol):
        if best is None or p.radius > best.radius:
            best = p
    if best is None:
        _wheel(body, mp, n, P, None, o.symmetry_tol)  # a body that cannot roll at all says so first
        raise InputError(
            "no rim radius: give {rim_radius}, or rim_radius in the body file (no round part — ring, "
            "disk, cylinder, torus, sphere, ... — is centred on the axle and coaxial with it)",
            Location(body.source))
    return (float(best.radius), f"the largest round part '{literal(best.name)}' ({best.shape}, "
            "coaxial with the axle)", "largest_round_part", best.name)


def _tyre(o: Options, rim: Rim | None, a: float, source: str) -> tuple[float, str, Any]:
    """(r, where it came from, the band's edges or None); refuses a tyre radius above ``a``
    and a steady circle on a rim that is not a knife edge."""
    r = 0.0 if o.tyre_radius is None else o.tyre_radius
    if r > a:
        raise ParamError("tyre_radius", f"the tyre radius {r:.6g} m must be at most the rim "
                         f"radius a = {a:.6g} m ({source}; a tyre radius equal to it is a sphere)")
    kind, band = ("{tyre_radius}" if o.tyre_radius is not None else "knife_edge"), None
    if o.tyre_radius is None and rim is not None:
        if rim.kind == "band":
            band = rim.edges
        elif rim.tube_radius > 0.0:
            r, kind = rim.tube_radius, "shape"
    if (o.lean is not None or o.circle is not None) and (r != 0.0 or band is not None):
        if o.tyre_radius is not None:
            raise ParamError(
                "tyre_radius", "steady circular rolling ({lean}/{circle}) is computed for a "
                "knife-edge rim only (tyre radius 0); the straight-rolling threshold takes a "
                "rounded rim")
        what = {"band": "a flat band", "torus": "a torus", "sphere": "a sphere"}[rim.kind]
        parts = ", ".join(f"'{literal(name)}' ({shape})" for name, shape in rim.parts)
        raise ParamError(
            "lean" if o.lean is not None else "circle",
            f"steady circular rolling is computed for a knife-edge rim only; this body's rim "
            f"is {what} (part {parts}): the straight-rolling threshold takes it")
    return r, kind, band


def _plausibility(body: Body, o: Options, a: float) -> tuple[str, ...]:
    """The plausibility warnings (:mod:`rbcli.core.scale`): a rim radius
    or a point more than 10 body sizes away, a rim faster than sound."""
    u = op.Units.of(body)
    sc = body_scale(body.parts)
    out = []
    if o.rim_radius is not None and sc.beyond(o.rim_radius):
        out.append(u.far("rim_radius", "the rim radius", o.rim_radius, sc.size))
    if o.through is not None and not isinstance(o.through, str) and sc.far(o.through):
        out.append(u.far("through", "the point", sc.far(o.through), sc.size))
    # a speed typed with its unit is meant (see api.inertia.rim_note)
    v = 0.0 if o.unit_typed("rolling_speed") else abs(o.rolling_speed or 0.0)
    s = 0.0 if o.unit_typed("spin") else abs(o.spin or 0.0) * a
    if SPEED_OF_SOUND < max(v, s) < math.inf:
        kind = "speed" if v >= s else "angular_speed"
        out.append(Note(f"{{{'rolling_speed' if v >= s else 'spin'}}}: the rim moves at {max(v, s):.4g} "
                        f"m/s relative to the centre, faster than sound ({SPEED_OF_SOUND:g} m/s); "
                        f"bare {kind.replace('_', ' ')}s are in {u.label(kind)}: is a unit missing?"))
    return tuple(out)


def _wheel(body: Body, mp: Any, axle: Any, through: Any, radius: Any, tol: float) -> Wheel:
    """The body reduced to a rolling wheel; else an InputError located at the body."""
    try:
        return wheel_from_body(mp.mass, mp.com, mp.inertia_com, axle, axle_through=through,
                               radius=radius, sym_rtol=tol)
    except InputError:  # already names its parameter (an InputError is a ValueError)
        raise
    except ValueError as exc:
        raise InputError(str(exc), Location(body.source)) from None


# --- result


@dataclass(frozen=True)
class RollcheckResult(Result):
    """The answer of :func:`rollcheck`: ``name``, ``source``, ``units`` (the body's, for the
    echo), ``options`` (:func:`parse`), ``setup`` (:class:`WheelSetup`), ``wheel``
    (:class:`rbcli.core.wheel.Wheel`), ``straight`` (the threshold), ``verdict`` (at the speed
    given), ``circle`` (the steady circle asked for) and ``warnings``."""

    name: str
    source: str
    units: dict
    options: Options
    setup: WheelSetup
    wheel: Wheel
    straight: StraightRolling
    verdict: Verdict | None = None
    circle: CircleMotion | None = None
    warnings: tuple[str, ...] = ()

    @property
    def asymmetry(self) -> AxialSymmetry | None:
        """How far a nearly symmetric wheel departs from a body of revolution about its
        axle (:class:`rbcli.core.symmetry.AxialSymmetry`, the com's offset relative to the
        rim radius); None when it is one to rounding (1e-6)."""
        return self.wheel.asymmetry

    @property
    def asymmetry_effect(self) -> float | None:
        """How far the critical spin and speed may be off from symmetrising the wheel (None
        when symmetric): the largest of δ/(4 - δ) (δ the relative spread of the moments
        across; s_c ∝ sqrt(I)), the coupling over the mean moment across, and e/(2 (a - r))
        for a com e off the axle. Derivation: :func:`rbcli.core.wheel.wheel_from_body`."""
        a = self.asymmetry
        if a is None:
            return None
        d = a.relative
        lever = self.setup.radius - self.setup.tyre_radius
        e = a.com_offset / (2.0 * lever) if lever > 0.0 else a.com_offset / self.setup.radius
        return max(d / (4.0 - d), a.coupling_relative, e)

    @property
    def critical_speed(self) -> float:
        """m/s, the speed above which straight upright rolling is (neutrally) stable."""
        return self.straight.critical_speed

    @property
    def critical_spin(self) -> float:
        """rad/s, critical_speed / radius."""
        return self.straight.critical_spin

    @property
    def model(self) -> str:
        """The model in one sentence (JSON ``model``)."""
        st = self.straight
        r = st.tyre_radius
        if st.rim == "band":
            assert st.band is not None and st.static_lean_limit is not None
            rim = (f"flat band {st.band[0] + st.band[1]:.6g} m wide (its weight holds it up for "
                   f"leans below {math.degrees(st.static_lean_limit):.6g} deg at any speed; the "
                   "critical speed is that of rolling balanced on either edge)")
        elif st.rim == "sphere":
            rim = "spherical rim (tyre radius = rim radius: no lean instability, stable at any speed)"
        else:
            rim = ("knife-edge rim (tyre radius 0)" if r == 0.0
                   else f"rounded rim of tube radius r = {r:.6g} m (gravity term a - r)")
        return (
            f"{rim} rolling without slip on a rough level floor; I and Is about the centre of "
            "mass, Is + m a^2 about the contact point; stable means neutral stability (undamped): "
            "a small lean oscillates, it does not decay"
        )

    @property
    def straight_asked(self) -> bool:
        """The straight-rolling verdict is a motion asked about (sets the exit status): a
        speed or spin with no circle, or with both lean and circle."""
        o = self.options
        return (o.rolling_speed is not None or o.spin is not None) and (o.lean is None) == (o.circle is None)

    @property
    def return_code(self) -> int:
        """1 when a motion asked about is unstable (straight rolling at the speed given,
        the steady circle asked for), else 0."""
        failed = ((self.straight_asked and self.verdict is not None and not self.verdict.stable)
                  or (self.circle is not None and not self.circle.stable))
        return 1 if failed else 0

    def curves(self) -> Curves:
        """The arrays of the command's figure (:class:`rbcli.core.rolling.Curves`)."""
        return rl.curves(rl.RollCheck(self.straight, self.verdict, self.circle))

    def to_json(self) -> dict[str, Any]:
        """The JSON ``rbcli rollcheck --json`` prints, less ``file``: SPEC keys first
        (radius, mass, I, Is, critical_spin, critical_speed; speed, stable, margin with a
        speed; circle when asked), then the extras."""
        core = rl.RollCheck(self.straight, self.verdict, self.circle).to_json()
        out: dict[str, Any] = {k: core[k] for k in _SPEC_TOP}
        if self.verdict is not None:
            out.update({k: core[k] for k in _SPEC_SPEED})
        if self.circle is not None:
            out["circle"] = core["circle"]
        out["radius_source"] = self.setup.radius_kind
        if self.setup.radius_part is not None:
            out["radius_part"] = self.setup.radius_part
        out["tyre_radius_source"] = self.setup.tyre_radius_kind
        for k, v in core.items():
            if k not in out and k != "model":
                out[k] = v
        out["axle"] = list(self.wheel.axle)
        out["axle_through"] = list(self.setup.through)
        out["com"] = list(self.wheel.com)
        if self.asymmetry is not None:
            out["asymmetry"] = self.asymmetry.to_json(self.options.symmetry_tol)
        out["model"] = self.model
        out["warnings"] = list(self.warnings)
        out["name"] = self.name
        return jsonable(out)


_SPEC_TOP = ("radius", "mass", "I", "Is", "critical_spin", "critical_speed")
_SPEC_SPEED = ("speed", "stable", "margin")


class OffCentreRim(InputError):
    """The rim is more than :data:`rbcli.core.rim.RIM_OFFSET_LIMIT` off the plane of the com to
    roll upright (exit 2); ``rim`` (with its offset) and ``reason`` (one line, the report's).
    """

    def __init__(self, message: str, where: Any, rim: Rim, reason: str) -> None:
        super().__init__(message, where)
        self.rim = rim
        self.reason = reason


def _refuse_off_centre_rim(body: Body, rim: Rim, circle_asked: bool) -> None:
    """A rim off the com's plane (a cone on its base rim, a top): upright rolling is no
    equilibrium, and the circle model (rim in that plane) does not describe its curves."""
    asked = ("the steady circle asked for ({lean}/{circle}) is not computed either: the circle "
             "model takes the rim in that plane" if circle_asked else
             "the steady-circle model, which takes the rim in that plane, does not apply either")
    raise OffCentreRim(
        f"{literal(rim.describe())}: upright rolling is not an equilibrium (the centre of mass is not "
        "above the contact point: gravity tips the body over or steers it into a curve), so "
        f"straight rolling has no critical speed; {asked}; rollcheck analyses rims within "
        f"{100 * RIM_OFFSET_LIMIT:g} % of the radius of the plane of the centre of mass",
        Location(body.source), rim, f"{rim.describe()}, so upright rolling is not an equilibrium")


#: the core's names of the rim radius and the rolling speed -> the parameters of :func:`rollcheck`
_CORE_PARAMS = {"radius": "rim_radius", "speed": "rolling_speed"}


def _renamed(exc: InputError) -> InputError:
    """A core error naming the rim radius and the speed by the parameters of
    :func:`rollcheck` (``rim_radius``, ``rolling_speed``)."""
    template = exc.template
    for core, param in _CORE_PARAMS.items():
        template = template.replace("{%s}" % core, "{%s}" % param)
    exc.template = template
    exc.args = (template,)
    if exc.param in _CORE_PARAMS:
        exc.param = _CORE_PARAMS[exc.param]
    return exc


def run(body: Body, options: Options) -> RollcheckResult:
    """The rolling check of ``body`` with ``options`` (:func:`parse`); an InputError located
    at the body (not of revolution, rim off the com's plane) or naming the parameters of a
    circle that does not exist."""
    o = options
    s = wheel_setup(body, o)
    wheel = _wheel(body, body_mass_props(body), s.axle, s.through, s.radius, o.symmetry_tol)
    if s.rim is not None and not s.rim.upright_equilibrium:
        _refuse_off_centre_rim(body, s.rim, o.lean is not None or o.circle is not None)
    try:
        res = rl.rollcheck(wheel, s.radius, s.tyre_radius, o.g, band=s.band, speed=o.rolling_speed,
                           spin=o.spin, lean_rad=o.lean, circle_radius=o.circle)
    except InputError as exc:
        raise _renamed(exc) from None
    warnings = s.warnings
    if wheel.asymmetry is not None:
        warnings += (Note(f"the wheel is not exactly symmetric about its axle: "
                          f"{wheel.asymmetry.percent('the rim radius')}; the answer is for the "
                          f"symmetrised wheel ({{symmetry_tol}} {o.symmetry_tol * 100:g} %)"),)
    return RollcheckResult(name=body.name, source=body.source, units=dict(body.units or {}),
                           options=o, setup=s, wheel=wheel, straight=res.straight,
                           verdict=res.verdict, circle=res.circle, warnings=warnings)


@function(ROLLCHECK)
def rollcheck(body: Body, **kwargs: Any) -> RollcheckResult:
    """Stability of a wheel, disk or hoop rolling without slipping on a rough level floor.

    The body must be of revolution about its axle with its com on it (to ``symmetry_tol``:
    a nearly symmetric wheel is answered for its symmetrised form, with a warning and
    ``result.asymmetry_effect``). Straight upright rolling is (neutrally) stable when
    s² > m g (a − r) I / (Is (Is + m a²)), I across the axle and Is about it, about the com
    (physics sheet ``dynamics.md`` §3.2). The command line's ``--axle``, ``--radius`` and
    ``--speed`` are ``shaft``, ``rim_radius`` and ``rolling_speed``.

    Parameters
    ----------
    body : rbcli.Body
    {parameters}

    Returns
    -------
    RollcheckResult
        ``return_code`` is 1 when the motion asked about is unstable.

    Raises
    ------
    TypeError, rbcli.InputError
        A wrong type (:mod:`rbcli.api.check`) or value, naming the parameter; located in
        the body's file for a body that cannot roll.

    Examples
    --------
    >>> import rbcli
    >>> penny = rbcli.load("examples/penny.yaml")
    >>> r = rbcli.rollcheck(penny, rolling_speed="10 cm/s")
    >>> round(r.critical_speed, 6), r.verdict.stable, r.return_code
    (0.176454, False, 1)"""
    return run(body, parse(body, **kwargs))
