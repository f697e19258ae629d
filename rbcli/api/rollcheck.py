"""When does a rolling wheel, coin or hoop stay up? The service behind ``rbcli rollcheck``.

:func:`rollcheck` reduces a body of revolution to a rolling wheel (mass, the moment I
across the axle and Is about it, both about the centre of mass), finds its rim radius
and answers: the critical speed of straight upright rolling; with a speed, the verdict at
that speed; with two of lean, circle and speed, the steady circle. The physics is
:mod:`rbcli.core.rolling` (physics sheet ``dynamics.md`` §3, in the repository's
documentation); this module reads the options once (:class:`RollcheckOptions`), resolves
the body's defaults and says where each came from.

Only the standard library at module level: numpy and the core load on first use.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from rbcli.api import check
from rbcli.api.check import Point, Quantity, Vector
from rbcli.api.result import Result
from rbcli.errors import InputError, Note, literal

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.core.rim import Rim
    from rbcli.core.symmetry import AxialSymmetry
    from rbcli.core.rollcircle import CircleMotion
    from rbcli.core.rolling import Curves, StraightRolling, Verdict
    from rbcli.core.wheel import Wheel
    from rbcli.body.model import Body
    from rbcli.body.partmodel import Part

__all__ = ["OffCentreRim", "RollcheckOptions", "RollcheckResult", "rollcheck", "run", "round_parts"]

STANDARD_GRAVITY = 9.80665  # m/s^2

#: the checker of each keyword argument of :func:`rollcheck` (:mod:`rbcli.api.check`)
KINDS = {"shaft": check.vector, "through": check.vector, "rim_radius": check.quantity,
         "tyre_radius": check.quantity, "g": check.quantity, "rolling_speed": check.quantity,
         "spin": check.quantity, "lean": check.quantity, "circle": check.quantity,
         "symmetry_tol": check.quantity}


def round_parts(body: Body) -> list[Part]:
    """The parts of ``body`` that could make a rim: round, with an outer radius, not holes
    (whatever their axis; :class:`RollcheckOptions` keeps those coaxial with the axle)."""
    from rbcli.core.rim import ROUND_SHAPES

    return [p for p in body.parts if not p.subtract and p.radius is not None and p.shape in ROUND_SHAPES]


@dataclass(frozen=True)
class RollcheckOptions:
    """The options of a rolling check, parsed and checked, the body's defaults resolved.

    Attributes
    ----------
    axle : tuple of 3 floats
        Unit axle direction in the body frame.
    through : tuple of 3 floats
        m, a point of the axle line, body frame.
    axle_source : str
        Where the axle and its point came from, in words (``"the body's shaft, through the
        body's shaft"``, ``"shaft, through the origin"``, ...; parameters named as
        :func:`rbcli.errors.spell` says).
    radius : float
        m, the rim radius a (centre to floor when upright).
    radius_source : str
        Where a came from, in words: ``"rim_radius"``, ``"the body's rim_radius"`` or ``"the
        largest round part 'rim' (ring, coaxial with the axle)"``.
    radius_kind : str
        ``rim_radius`` (the parameter), ``"rim_radius"`` (the body's) or
        ``"largest_round_part"`` (JSON ``radius_source``).
    radius_part : str or None
        The part's name when ``radius_kind`` is ``"largest_round_part"``.
    tyre_radius : float
        m, tube radius r of a rounded rim: 0 is a knife edge (or a flat band), a a sphere;
        from ``tyre_radius``, else from the rim's shape (a torus's tube, a sphere's radius).
    tyre_radius_kind : str
        ``tyre_radius`` (given), ``"shape"`` (the rim part's: a torus, a sphere) or
        ``"knife_edge"`` (none: 0) (JSON ``tyre_radius_source``).
    band : tuple of 2 floats or None
        m, for a rim that is a flat band (a cylinder on its side, rim circles in two planes)
        and no ``tyre_radius``: its edges' distances from the plane of the centre of mass,
        one each side.
    g : float
        m/s², gravity.
    speed : float or None
        m/s, speed of the centre for straight rolling (negative: backwards).
    spin : float or None
        rad/s, spin about the axle (speed = a x spin).
    lean : float or None
        rad, inward lean of a steady circle from the vertical, [0, pi/2).
    circle : float or None
        m, radius of the circle the centre runs on (0: spinning in place).
    rim : rbcli.core.rim.Rim or None
        What the rim is (``kind``: edge, torus, sphere, band; ``tube_radius``) and where it
        lies along the axle, measured from the parts whose outer radius is the rim radius
        (``offset`` m from the centre of mass, ``low``/``high`` a band's ends, ``fraction`` of the
        radius); None when no part has that radius.
    warnings : tuple of str
        One-line warnings about the resolved defaults and about values far outside the
        body's scale (the command line prints them as ``rbcli: FILE: warning: ...``).
    symmetry_tol : float
        How far from a body of revolution about the axle the wheel may be (a fraction;
        default 0.01): the two moments across the axle (about the com)
        may differ, and the products coupling the axle to the plane across it may be, up
        to this fraction of their mean; the com may be this fraction of the rim radius off
        the axle. Within it the answer is for the symmetrised wheel, with a warning.
    shaft_as_given, through_as_given : the ``shaft`` and ``through`` values as given (a
        direction with its largest component ±1; ``"com"``, ``"origin"`` or a point, m), None
        when not given
    given : tuple of str
    typed : tuple of (str, str) — (parameter, unit) for each value typed with a unit
        (``"0.5 g"``: ``("mass_step", "g")``), the unit the options table shows it in
        The parameters the caller gave.
    """

    axle: tuple[float, float, float]
    through: tuple[float, float, float]
    axle_source: str
    radius: float
    radius_source: str
    radius_kind: str
    radius_part: str | None
    tyre_radius: float = 0.0
    tyre_radius_kind: str = "knife_edge"
    band: tuple[float, float] | None = None
    g: float = STANDARD_GRAVITY
    speed: float | None = None
    spin: float | None = None
    lean: float | None = None
    circle: float | None = None
    rim: Rim | None = None
    warnings: tuple[str, ...] = ()
    symmetry_tol: float = 0.01
    shaft_as_given: tuple[float, float, float] | None = None
    through_as_given: Any = None
    given: tuple[str, ...] = ()
    #: parameter -> the unit the caller typed after its number (the options table echoes in it)
    typed: tuple[tuple[str, str], ...] = ()

    @property
    def straight_asked(self) -> bool:
        """The straight-rolling verdict is a motion asked about (sets the exit status):
        a speed or spin with no circle, or with both lean and circle."""
        asked_speed = self.speed is not None or self.spin is not None
        no_circle = self.lean is None and self.circle is None
        both = self.lean is not None and self.circle is not None
        return asked_speed and (no_circle or both)

    @property
    def circle_asked(self) -> bool:
        """A steady circle is asked about (lean and/or circle given)."""
        return self.lean is not None or self.circle is not None

    @classmethod
    def parse(cls, body: Body, *, shaft: Vector | None = None, through: Point | None = None,
              rim_radius: Quantity | None = None, tyre_radius: Quantity | None = None,
              g: Quantity | None = None, rolling_speed: Quantity | None = None,
              spin: Quantity | None = None, lean: Quantity | None = None,
              circle: Quantity | None = None, symmetry_tol: Quantity | None = None) -> RollcheckOptions:
        """Read the options of :func:`rollcheck` (see there) and resolve the body's defaults.

        Raises
        ------
        rbcli.InputError
            A value that is not what its option takes (the message starts with the
            option), a steady circle without two of lean, circle and speed, a tyre radius
            larger than the rim radius, a steady circle on a rim that is not a knife edge,
            or a body with no rim radius.
        """
        from rbcli.api import options as o
        from rbcli.errors import ParamError

        u = o.Units.of(body)
        n_axle = o.direction(shaft, "shaft") if shaft is not None else None
        p_through = u.point(through, "through") if through is not None else None
        a_opt = (u.positive(rim_radius, "length", "rim_radius", "the rim radius")
                 if rim_radius is not None else None)
        r = u.quantity(tyre_radius, "length", "tyre_radius") if tyre_radius is not None else 0.0
        if not (r >= 0.0 and math.isfinite(r)):
            raise ParamError("tyre_radius", f"must be 0 (knife edge) or a positive length, got {tyre_radius}")
        gv = u.positive(g, "acceleration", "g", "gravity") if g is not None else STANDARD_GRAVITY
        v = (o.finite(u.quantity(rolling_speed, "speed", "rolling_speed"), "rolling_speed")
             if rolling_speed is not None else None)
        s = o.finite(u.quantity(spin, "angular_speed", "spin"), "spin") if spin is not None else None
        beta = None
        if lean is not None:
            beta = u.quantity(lean, "angle", "lean")
            if not (0.0 <= beta < 0.5 * math.pi):
                raise ParamError("lean", "the inward lean from the vertical must be from 0 up to "
                                 f"(not including) 90 degrees, got {lean}")
        R_G = None
        if circle is not None:
            R_G = u.quantity(circle, "length", "circle")
            if not (R_G >= 0.0 and R_G != math.inf):
                raise ParamError("circle", f"the circle radius must be 0 (spinning in place) or "
                                 f"positive, got {circle}")
        asked_speed = v is not None or s is not None
        if (beta is None) != (R_G is None) and not asked_speed:
            have, need = ("lean", "circle") if beta is not None else ("circle", "lean")
            raise ParamError(have, "a steady circle needs two of {lean}, {circle} and {rolling_speed} (or "
                             f"{{spin}}); add {need} or {{rolling_speed}}")
        if R_G is not None and R_G == 0.0 and beta is None and asked_speed:
            raise InputError(
                "{circle} 0: spinning in place the centre does not move, so {rolling_speed} cannot fix "
                "the lean; give {lean} instead", param="circle")

        tol = o.symmetry_tolerance(symmetry_tol)
        axle_v, P, axle_source, a, source, kind, part, rim, warns = _resolve(body, n_axle, p_through, a_opt, tol)
        if r > a:
            raise ParamError("tyre_radius", f"the tyre radius {r:.6g} m must be at most the rim "
                             f"radius a = {a:.6g} m ({source}; a tyre radius equal to it is a sphere)")
        band = None
        r_kind = "{tyre_radius}" if tyre_radius is not None else "knife_edge"
        if tyre_radius is None and rim is not None:
            if rim.kind == "band":
                band = rim.edges
            elif rim.tube_radius > 0.0:
                r, r_kind = rim.tube_radius, "shape"
        if (beta is not None or R_G is not None) and (r != 0.0 or band is not None):
            if tyre_radius is not None:
                raise ParamError(
                    "tyre_radius", "steady circular rolling ({lean}/{circle}) is computed for a "
                    "knife-edge rim only (tyre radius 0); the straight-rolling threshold takes a "
                    "rounded rim")
            assert rim is not None
            what = {"band": "a flat band", "torus": "a torus", "sphere": "a sphere"}[rim.kind]
            parts = ", ".join(f"'{literal(n)}' ({sh})" for n, sh in rim.parts)
            raise ParamError(
                "lean" if beta is not None else "circle",
                f"steady circular rolling is computed for a knife-edge rim only; this body's rim "
                f"is {what} (part {parts}): the straight-rolling threshold takes it")
        given = tuple(p for p, x in (
            ("shaft", shaft), ("through", through), ("rim_radius", rim_radius),
            ("tyre_radius", tyre_radius), ("g", g), ("rolling_speed", rolling_speed),
            ("spin", spin), ("lean", lean), ("circle", circle), ("symmetry_tol", symmetry_tol))
            if x is not None)
        warns = warns + _plausibility(body, u, a_opt, p_through, R_G, v, s, a)
        return cls(axle=axle_v, through=P, axle_source=Note(axle_source), radius=a,
                   radius_source=Note(source), radius_kind=Note(kind), radius_part=part,
                   tyre_radius=r, tyre_radius_kind=Note(r_kind), band=band, g=gv, speed=v, spin=s,
                   lean=beta, circle=R_G, rim=rim, warnings=warns, symmetry_tol=tol,
                   shaft_as_given=None if n_axle is None else tuple(n_axle),
                   through_as_given=p_through if p_through is None or isinstance(p_through, str)
                   else tuple(p_through), given=given, typed=tuple(u.typed.items()))


def _plausibility(body: Body, u, a_opt, p_through, R_G, v, s, a) -> tuple[str, ...]:
    """One-line warnings for values far outside the body's scale (issue 13): a rim radius
    or a point more than 10 body sizes away, a rim faster than sound."""
    from rbcli.core.scale import FAR, SPEED_OF_SOUND, body_scale

    sc = body_scale(body.parts)
    out = []
    if a_opt is not None and a_opt > FAR * sc.size:
        out.append(u.far("rim_radius", "the rim radius", a_opt, sc.size))
    if p_through is not None and not isinstance(p_through, str) and sc.far(p_through):
        out.append(u.far("through", "the point", sc.far(p_through), sc.size))
    rim = max(abs(v or 0.0), abs(s or 0.0) * a)
    if SPEED_OF_SOUND < rim < math.inf:
        opt = "{rolling_speed}" if abs(v or 0.0) >= abs(s or 0.0) * a else "{spin}"
        out.append(Note(f"{opt}: the rim moves at {rim:.4g} m/s relative to the centre, faster "
                        f"than sound ({SPEED_OF_SOUND:g} m/s); bare angular speeds are in "
                        f"{u.label('angular_speed')}: is a unit missing?"))
    return tuple(out)


def _resolve(body: Body, n_axle, p_through, a_opt, tol):
    """Axle, its point, the rim radius, where each came from, and warnings."""
    import numpy as np

    from rbcli.api.reference import shaft_axis, shaft_point
    from rbcli.core.inertia import body_mass_props
    from rbcli.core.rim import RIM_OFFSET_LIMIT, rim_of

    mp = body_mass_props(body)
    axis, came = shaft_axis(body, n_axle)
    axle_source = {"given": "{shaft}", "body": "the body's shaft", "default": "body z (default)"}[came]
    n = np.asarray(axis, dtype=float)
    n = n / np.linalg.norm(n)
    where, came = shaft_point(body, p_through)
    through_source = {"given": "{through}", "body": "the body's shaft", "default": "the origin"}[came]
    if isinstance(where, str):
        P = mp.com.copy() if where == "com" else np.zeros(3)
        through_source = f"{{through}} {where}"
    else:
        P = np.asarray(where, dtype=float)
    part = None
    if a_opt is not None:
        a, source, kind = a_opt, "{rim_radius}", "{rim_radius}"
    elif body.rim_radius is not None:
        a, source, kind = float(body.rim_radius), "the body's rim_radius", "rim_radius"
    else:
        best = _largest_round_part(body, n, P, mp, tol)
        a, part, kind = float(best.radius), best.name, "largest_round_part"
        source = f"the largest round part '{literal(best.name)}' ({best.shape}, coaxial with the axle)"
    rim = rim_of(body.parts, mp.com, n, P, a, tol=tol)
    warnings: list[str] = []
    if rim is not None and rim.outside > 1e-6 * a and rim.upright_equilibrium:
        warnings.append(
            f"{rim.describe()}; the model takes the rim circle in the plane of the centre of mass "
            f"(rollcheck refuses rims more than {100 * RIM_OFFSET_LIMIT:g} % of the radius off it)"
        )
    return (tuple(float(x) for x in n), tuple(float(x) for x in P),
            f"{axle_source}, through {through_source}", float(a), source, kind, part, rim,
            tuple(warnings))


def _largest_round_part(body: Body, n, P, mp, tol) -> Part:
    """The round, non-subtracted part coaxial with the axle with the largest outer radius."""
    from rbcli.core.rim import rim_candidates
    from rbcli.errors import Location

    best = None
    for p in rim_candidates(body.parts, n, P, tol):
        if best is None or p.radius > best.radius:
            best = p
    if best is None:
        _wheel(body, mp, n, P, None, tol)  # a body that cannot roll at all says so first
        raise InputError(
            "no rim radius: give {rim_radius}, or rim_radius in the body file (no round part — ring, "
            "disk, cylinder, torus, sphere, ... — is centred on the axle and coaxial with it)",
            Location(body.source))
    return best


def _wheel(body: Body, mp, axle, through, radius, tol) -> Wheel:
    """The body reduced to a rolling wheel; a body that cannot roll is an InputError
    located at the body."""
    from rbcli.core.wheel import wheel_from_body
    from rbcli.errors import Location

    try:
        return wheel_from_body(mp.mass, mp.com, mp.inertia_com, axle, axle_through=through,
                               radius=radius, sym_rtol=tol)
    except InputError:  # already names its parameter (an InputError is a ValueError)
        raise
    except ValueError as exc:
        raise InputError(str(exc), Location(body.source)) from None


@dataclass(frozen=True)
class RollcheckResult(Result):
    """The answer of :func:`rollcheck`.

    Attributes
    ----------
    name : str
        The body's name.
    source : str
        The body's file (``"<expr>"``, ``"<text>"`` for bodies given as text).
    options : RollcheckOptions
        The options as used (SI), with the provenance of the axle and the rim radius.
    wheel : rbcli.core.wheel.Wheel
        mass (kg), ``A`` = I across the axle and ``C`` = Is about it (kg m², about the
        centre of mass), ``com`` (m) and unit ``axle``; for a nearly symmetric wheel the
        symmetrised one (``A`` the mean of the two moments across; ``wheel.asymmetry``).
    straight : rbcli.core.rolling.StraightRolling
        The threshold of straight upright rolling: ``critical_spin`` (rad/s),
        ``critical_speed`` (m/s), ``C_contact`` = Is + m a², ``A_contact`` = I + m a²
        (kg m²), ``nu2(spin)``.
    verdict : rbcli.core.rolling.Verdict or None
        With a speed or spin: ``speed`` (m/s), ``spin`` (rad/s), ``stable``, ``margin``
        (``|speed|`` / critical speed), ``nu2`` (rad²/s²), ``lean_frequency`` (rad/s),
        ``lean_frequency_hz``, ``growth_rate`` (1/s), ``backwards``.
    circle : rbcli.core.rollcircle.CircleMotion or None
        With a steady circle: ``lean`` (rad), ``lean_deg``, ``radius`` R_G (m),
        ``turn_rate`` (rad/s), ``spin`` (rad/s), ``speed`` (m/s), ``contact_radius`` (m),
        ``kappa`` (N m), ``stable``, ``lean_frequency`` (rad/s), ``growth_rate`` (1/s).
    warnings : tuple of str
        Located one-line warnings (the command line prints them on standard error).
    """

    name: str
    source: str
    options: RollcheckOptions
    wheel: Wheel
    straight: StraightRolling
    verdict: Verdict | None = None
    circle: CircleMotion | None = None
    warnings: tuple[str, ...] = ()

    @property
    def asymmetry(self) -> AxialSymmetry | None:
        """How far a nearly symmetric wheel departs from a body of revolution about its
        axle (:class:`rbcli.core.symmetry.AxialSymmetry`: the moments across about the com,
        the coupling, the com's offset relative to the rim radius); None when it is one to
        rounding (1e-6)."""
        return self.wheel.asymmetry

    @property
    def asymmetry_effect(self) -> float | None:
        """The relative amount by which the critical spin and speed (and the verdicts near
        them) may be off from symmetrising the wheel; None when symmetric. The largest of
        δ/(4 - δ), δ the relative spread of the moments across (the real threshold lies
        between the ones computed with either moment: s_c ∝ sqrt(I)); the coupling relative
        to the mean moment across (the principal moments move by at most the coupling, and
        the wheel wobbles); e/(2 (a - r)) for a com e off the axle (the gravity lever swings
        by ±e). Derivation: :func:`rbcli.core.wheel.wheel_from_body`, Notes."""
        a = self.asymmetry
        if a is None:
            return None
        d = a.relative
        lever = self.options.radius - self.options.tyre_radius
        e = a.com_offset / (2.0 * lever) if lever > 0.0 else a.com_offset / self.options.radius
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
    def return_code(self) -> int:
        """1 when a motion asked about is unstable (straight rolling at the speed given,
        the steady circle asked for), else 0."""
        failed = ((self.options.straight_asked and self.verdict is not None and not self.verdict.stable)
                  or (self.circle is not None and not self.circle.stable))
        return 1 if failed else 0

    def curves(self) -> Curves:
        """The arrays of the command's figure (:class:`rbcli.core.rolling.Curves`): the
        squared lean frequency, lean frequency and growth rate against speed and, with a
        circle, the lean stiffness and speed of steady circles on a (lean, radius) grid."""
        from rbcli.core.rolling import RollCheck, curves

        return curves(RollCheck(self.straight, self.verdict, self.circle))

    def to_json(self) -> dict[str, Any]:
        """The JSON ``rbcli rollcheck --json`` prints, less ``file``: SPEC keys first
        (radius, mass, I, Is, critical_spin, critical_speed; speed, stable, margin with a
        speed; circle when asked), then the extras."""
        from rbcli.api.result import jsonable
        from rbcli.core.rolling import RollCheck

        core = RollCheck(self.straight, self.verdict, self.circle).to_json()
        out: dict[str, Any] = {k: core[k] for k in _SPEC_TOP}
        if self.verdict is not None:
            out.update({k: core[k] for k in _SPEC_SPEED})
        if self.circle is not None:
            out["circle"] = core["circle"]
        out["radius_source"] = self.options.radius_kind
        if self.options.radius_part is not None:
            out["radius_part"] = self.options.radius_part
        out["tyre_radius_source"] = self.options.tyre_radius_kind
        for k, v in core.items():
            if k not in out and k != "model":
                out[k] = v
        out["axle"] = list(self.wheel.axle)
        out["axle_through"] = list(self.options.through)
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
    """The rim circle is too far off the plane of the centre of mass to roll upright
    (:data:`rbcli.core.rim.RIM_OFFSET_LIMIT`): no straight-rolling threshold, no steady
    circle. Exit 2, like any bad input.

    Attributes
    ----------
    rim : rbcli.core.rim.Rim — the rim and its measured offset
    reason : str — the short reason, one line (the report's)
    """

    def __init__(self, message: str, where: Any, rim: Rim, reason: str) -> None:
        super().__init__(message, where)
        self.rim = rim
        self.reason = reason


def _refuse_off_centre_rim(body: Body, o: RollcheckOptions) -> None:
    """A rim off the plane of the centre of mass (a cone or hemisphere on its base rim, a
    top): upright rolling is not an equilibrium, so there is no straight-rolling threshold,
    and the circle model (rim in that plane) does not describe its curves either."""
    from rbcli.core.rim import RIM_OFFSET_LIMIT
    from rbcli.errors import Location

    rim = o.rim
    assert rim is not None
    asked = ("the steady circle asked for ({lean}/{circle}) is not computed either: the circle "
             "model takes the rim in that plane" if o.circle_asked else
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
    """A core error (:mod:`rbcli.core.rolling`) naming the rim radius and the speed by the
    parameters of :func:`rollcheck` (``rim_radius``, ``rolling_speed``); the command line
    spells them as its options (``--radius``, ``--speed``: :data:`rbcli.errors.COMMAND_OPTIONS`)."""
    template = exc.template
    for core, param in _CORE_PARAMS.items():
        template = template.replace("{%s}" % core, "{%s}" % param)
    exc.template = template
    exc.args = (template,)
    if exc.param in _CORE_PARAMS:
        exc.param = _CORE_PARAMS[exc.param]
    return exc


def run(body: Body, options: RollcheckOptions) -> RollcheckResult:
    """The rolling check of ``body`` with parsed ``options`` (:meth:`RollcheckOptions.parse`).

    Raises
    ------
    rbcli.InputError
        The body is not of revolution about the axle or its centre of mass is off it, or its
        rim circle is more than :data:`rbcli.core.rim.RIM_OFFSET_LIMIT` of the radius
        off the plane of the centre of mass (a cone or hemisphere on its base rim: upright
        rolling is no equilibrium) — located at the body; or the options ask for a circle
        that does not exist (naming the options).
    """
    from rbcli.core import rolling as rl
    from rbcli.core.inertia import body_mass_props

    o = options
    wheel = _wheel(body, body_mass_props(body), o.axle, o.through, o.radius, o.symmetry_tol)
    if o.rim is not None and not o.rim.upright_equilibrium:
        _refuse_off_centre_rim(body, o)
    try:
        res = rl.rollcheck(wheel, o.radius, o.tyre_radius, o.g, band=o.band, speed=o.speed,
                           spin=o.spin, lean_rad=o.lean, circle_radius=o.circle)
    except InputError as exc:
        raise _renamed(exc) from None
    warnings = o.warnings
    if wheel.asymmetry is not None:
        warnings += (Note(f"the wheel is not exactly symmetric about its axle: "
                          f"{wheel.asymmetry.percent('the rim radius')}; the answer is for the "
                          f"symmetrised wheel ({{symmetry_tol}} {o.symmetry_tol * 100:g} %)"),)
    return RollcheckResult(name=body.name, source=body.source, options=o, wheel=wheel,
                           straight=res.straight, verdict=res.verdict, circle=res.circle,
                           warnings=warnings)


def rollcheck(body: Body, *, shaft: Vector | None = None, through: Point | None = None,
              rim_radius: Quantity | None = None, tyre_radius: Quantity | None = None,
              g: Quantity | None = None, rolling_speed: Quantity | None = None,
              spin: Quantity | None = None, lean: Quantity | None = None,
              circle: Quantity | None = None, symmetry_tol: Quantity | None = None) -> RollcheckResult:
    """Stability of a wheel, disk or hoop rolling without slipping on a rough level floor.

    The body must be of revolution about its axle with its centre of mass on it (to
    ``symmetry_tol``, default 1 %: a nearly symmetric wheel is answered for its
    symmetrised form, with a warning). Straight
    upright rolling is (neutrally) stable when the spin s satisfies
    s² > m g (a − r) I / (Is (Is + m a²)), I across the axle and Is about it, both about
    the centre of mass (physics sheet ``dynamics.md`` §3.2; thin disk v_c = sqrt(g a/3),
    hoop sqrt(g a/4)). Every value may be a number in SI units (angles in degrees) or a
    string as typed on the command line (``"5 km/h"``, ``"300 rpm"``, ``"20 deg"``).

    Parameters
    ----------
    body : rbcli.Body
        From :func:`rbcli.load` or :func:`rbcli.load_text`.
    shaft : str or sequence of 3, optional
        The axle's direction in the body frame (``"x"``, ``[0, 0, 1]``; the command line's
        ``--axle``). Default: the body's shaft axis, else body z.
    through : str or sequence of 3, optional
        m, a point of the axle line, or ``"com"``/``"origin"``. Default: the body's shaft
        point, else the origin.
    rim_radius : float or str, optional
        m, the rim radius a (the command line's ``--radius``). Default: the body's
        ``rim_radius``, else the largest round
        part (ring, disk, cylinder, torus, sphere, hemisphere, cone; not a hole) centred
        on the axle and coaxial with it.
    tyre_radius : float or str, optional
        m, tube radius r of a rounded rim, 0 <= r <= a (r = a: a sphere). Default: the rim's
        own shape (a torus its tube radius, a sphere its radius, a cylinder its flat band of
        the cylinder's length; a disk, ring, cone or hemisphere a knife edge, 0).
    g : float or str, optional
        m/s², gravity. Default 9.80665.
    rolling_speed : float or str, optional
        m/s, the speed of the centre for straight rolling (negative: backwards; the command
        line's ``--speed``; JSON ``speed``).
    spin : float or str, optional
        rad/s, spin about the axle (rolling speed = a × spin); with ``rolling_speed`` they
        must agree.
    lean : float or str, optional
        Degrees (a number) or an angle with its unit: inward lean of a steady circle,
        0 <= lean < 90.
    circle : float or str, optional
        m, radius of the circle the centre runs on; 0 = spinning in place. A steady circle
        needs two of ``lean``, ``circle`` and a speed or spin (knife edge only).
    symmetry_tol : float or str, optional
        How far from a body of revolution about the axle the wheel may be: a fraction
        (``0.01``) or a percentage (``"1 %"``), at most 10 %; default 1 %. The two moments
        across the axle (about the com) may differ, and the products of inertia coupling
        the axle to the plane across it may be, up to this fraction of their mean; the com
        may be off the axle by this fraction of the rim radius. Such a wheel (above
        rounding, 1e-6) is answered for the symmetrised wheel (the mean moment across, the
        com on the axle) with a warning, ``asymmetry`` in the JSON and
        ``result.asymmetry_effect``, the relative amount the critical speed may be off;
        beyond it, refused.

    Returns
    -------
    RollcheckResult
        ``return_code`` is 1 when the motion asked about is unstable.

    Raises
    ------
    TypeError
        An argument of the wrong type, naming the parameter and the type expected
        (:mod:`rbcli.api.check`).
    rbcli.InputError
        Naming the parameter (``rolling_speed: ...``), or located in the body's file for a
        body that cannot roll.

    Examples
    --------
    >>> import rbcli
    >>> penny = rbcli.load("examples/penny.yaml")
    >>> r = rbcli.rollcheck(penny, rolling_speed="10 cm/s")
    >>> round(r.critical_speed, 6), r.verdict.stable, r.return_code
    (0.176454, False, 1)
    """
    body = check.body(body)
    kw = check.arguments(KINDS, shaft=shaft, through=through, rim_radius=rim_radius,
                         tyre_radius=tyre_radius, g=g, rolling_speed=rolling_speed, spin=spin,
                         lean=lean, circle=circle, symmetry_tol=symmetry_tol)
    with check.arithmetic(kw):
        return run(body, RollcheckOptions.parse(body, **kw))
