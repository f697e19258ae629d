"""The rotor on its bearings: the service behind ``rbcli whirl``.

:func:`whirl` reads its options once (:class:`WhirlOptions`: SI numbers or quantity
strings, the bare-number rule of :mod:`rbcli.api.options`), builds the rigid rotor from
the body (mass, com, the moments about the com in shaft axes, its unbalance: what
:mod:`rbcli.core.balance` computes) on linear spring-damper bearings, and runs the physics
of :mod:`rbcli.core.whirl`: the Campbell diagram over a speed range, the critical speeds
(undamped: an eigenproblem in the speed; damped: a root solve), the stability, the
unbalance response with its peaks and amplification factors, and at an operating speed
the API 617 / 684 separation margins. The result (:class:`WhirlResult`) is frozen; its
attribute names are its JSON keys and its arrays are read-only.

Messages name parameters as ``{param}`` (:mod:`rbcli.errors`); the readers of
:mod:`rbcli.api.options` are handed ``_opt(param)`` (one place to switch when they take
parameter names).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from rbcli.api import check
from rbcli.api.check import Point, Quantity, Values, Vector
from rbcli.api.whirlresult import (  # noqa: F401
    API_RULE, AtSpeed,
    CONVENTIONS, Campbell, CriticalSpeed, Margins, MarginCheck, Mode, NoCrossing, PeakRow,
    ResponseBearing, ResponseData, RotorData, BearingData, Stability, UnbalanceRow, WhirlResult,
    readonly,
)
from rbcli.errors import InputError, Note, ParamError, literal

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.body.model import Body

__all__ = ["WhirlOptions", "WhirlResult", "whirl", "run", "CONVENTIONS"]

#: the default number of speeds of the Campbell diagram and the response
DEFAULT_POINTS = 201
#: the most speeds (a run stays well under a second at this size)
MAX_POINTS = 20001
#: the most bearings
MAX_BEARINGS = 20
#: the highest order asked for
MAX_ORDER = 10

#: the checker of each keyword argument of :func:`whirl` (:mod:`rbcli.api.check`)
KINDS = {
    "bearings": check.values(MAX_BEARINGS), "stiffness": check.values(MAX_BEARINGS),
    "stiffness_y": check.values(MAX_BEARINGS), "cross_stiffness": check.values(MAX_BEARINGS),
    "damping": check.values(MAX_BEARINGS), "damping_y": check.values(MAX_BEARINGS),
    "speed_range": check.values(2), "points": check.count,
    "orders": check.integers(10 * MAX_ORDER), "speed": check.values(2),
    "unbalance": check.texts(1, MAX_BEARINGS), "unbalance_planes": check.values(MAX_BEARINGS),
    "shaft": check.vector, "through": check.vector, "symmetry_tol": check.quantity,
}


def _opt(param: str) -> str:
    """What the readers of :mod:`rbcli.api.options` are asked about: the parameter."""
    return param


def _reading(param: str):
    """An InputError raised inside by a reader that could not tell names ``param``."""
    from rbcli.api import options as op

    return op.naming(param)


# ----------------------------------------------------------------------------- options


@dataclass(frozen=True)
class WhirlOptions:
    """The options of :func:`whirl`, read and checked once, in SI.

    Attributes
    ----------
    bearings : tuple of float — m, bearing positions along the shaft (2 or more, distinct)
    stiffness : tuple of (float, float) — N/m, (kxx, kyy) per bearing
    cross_stiffness : tuple of float — N/m, kxy per bearing (kyx = -kxy)
    damping : tuple of (float, float) — N s/m, (cxx, cyy) per bearing
    speed_range : (float, float) | None — rad/s, None: chosen from the critical speeds
    points : int — speeds in the range
    orders : tuple of int — critical-speed orders (n× lines)
    speed : (float, float) | None — rad/s, the operating speed (min, max; equal for one)
    unbalance : tuple of (float z m, complex kg m) | None — correction-plane unbalances;
        None: the body's own
    shaft : (3,) tuple — shaft direction, body frame; ``shaft_source`` where it came from
    through : str | (3,) tuple — a point of the shaft; ``through_source``
    symmetry_tol : float — fraction
    given : tuple of str — the parameters the caller gave (the tables echo them)
    typed : tuple of (str, str) — (parameter, unit) for each value typed with a unit
        (``"0.5 g"``: ``("mass_step", "g")``), the unit the options table shows it in
    """

    bearings: tuple[float, ...]
    stiffness: tuple[tuple[float, float], ...]
    cross_stiffness: tuple[float, ...]
    damping: tuple[tuple[float, float], ...]
    speed_range: tuple[float, float] | None
    points: int
    orders: tuple[int, ...]
    speed: tuple[float, float] | None
    unbalance: tuple[tuple[float, complex], ...] | None
    shaft: tuple[float, float, float]
    shaft_source: str
    through: Any
    through_source: str
    symmetry_tol: float
    given: tuple[str, ...] = ()
    #: parameter -> the unit the caller typed after its number (the options table echoes in it)
    typed: tuple[tuple[str, str], ...] = ()

    @classmethod
    def parse(cls, body: Body, *, bearings: Values | None = None, stiffness: Values | None = None,
              stiffness_y: Values | None = None, cross_stiffness: Values | None = None,
              damping: Values | None = None, damping_y: Values | None = None,
              speed_range: Values | None = None, points: int | str | None = None,
              orders: int | str | Sequence[int] | None = None, speed: Values | None = None,
              unbalance: str | Sequence[str] | None = None, unbalance_planes: Values | None = None,
              shaft: Vector | None = None, through: Point | None = None,
              symmetry_tol: Quantity | None = None) -> WhirlOptions:
        """Read the keyword arguments of :func:`whirl` (see there) for ``body``.

        Raises
        ------
        rbcli.InputError
            one line naming the parameter (``bearings: ...``).
        """
        from rbcli.api import options as op

        u = op.Units.of(body)
        if bearings is None:
            raise ParamError("bearings", "needs the bearing positions along the shaft, "
                             "{bearings} z1,z2[,...]")
        if stiffness is None:
            raise ParamError("stiffness", "needs the bearing stiffness, {stiffness} k (N/m, "
                             "one for all bearings or one per bearing)")
        with _reading("bearings"):
            zs = u.numbers(bearings, "length", _opt("bearings"), counts=tuple(range(1, MAX_BEARINGS + 1)))
        _check_bearings(zs)
        n = len(zs)
        kx = _per_bearing(u, stiffness, "stiffness", "stiffness", n, positive=True)
        ky = _per_bearing(u, stiffness_y, "stiffness_y", "stiffness", n, positive=True) \
            if stiffness_y is not None else kx
        kq = _per_bearing(u, cross_stiffness, "cross_stiffness", "stiffness", n, positive=None) \
            if cross_stiffness is not None else [0.0] * n
        cx = _per_bearing(u, damping, "damping", "damping", n, positive=False) \
            if damping is not None else [0.0] * n
        if damping_y is not None and damping is None:
            raise ParamError("damping_y", "gives the y damping; give {damping} (x, or both) too")
        cy = _per_bearing(u, damping_y, "damping_y", "damping", n, positive=False) \
            if damping_y is not None else cx
        rng = None
        if speed_range is not None:
            with _reading("speed_range"):
                a, b = u.numbers(speed_range, "angular_speed", _opt("speed_range"), counts=(2,))
            text = literal(_as_text(speed_range))
            if a < 0.0:
                raise ParamError("speed_range", f"speeds must not be negative, got '{text}' (to turn "
                                 "the other way, reverse {shaft})")
            if a == b:
                raise ParamError("speed_range", f"'{text}' is an empty range: both ends are "
                                 f"{a:.6g} rad/s; give a,b with a < b (e.g. '0,3000 rpm')")
            if a > b:
                raise ParamError("speed_range", f"'{text}' is not a range: the first speed "
                                 f"({a:.6g} rad/s) is above the second ({b:.6g} rad/s); give a,b "
                                 "with a < b")
            rng = (a, b)
        npts = _points(points)
        ords = _orders(orders)
        W = None
        if speed is not None:
            with _reading("speed"):
                vals = u.numbers(speed, "angular_speed", _opt("speed"), counts=(1, 2))
            for v in vals:
                if not v > 0.0:
                    raise ParamError("speed", f"the operating speed must be positive, got "
                                     f"{v:.6g} rad/s (to turn the other way, reverse {{shaft}})")
            if len(vals) == 2 and vals[0] > vals[1]:
                raise ParamError("speed", "give the operating range as min,max (the minimum "
                                 f"first), got {literal(_as_text(speed))}")
            W = (vals[0], vals[-1])
        unb = _unbalance(u, unbalance, unbalance_planes)
        with _reading("shaft"):
            n_shaft = op.direction(shaft, _opt("shaft")) if shaft is not None else None
        with _reading("through"):
            p_through = u.point(through, _opt("through")) if through is not None else None
        with _reading("symmetry_tol"):
            tol = op.symmetry_tolerance(symmetry_tol, _opt("symmetry_tol"))
        from rbcli.api.reference import shaft_axis, shaft_point

        axis, came = shaft_axis(body, n_shaft)
        shaft_source = {"given": "shaft", "body": "body_shaft", "default": "default"}[came]
        where, came = shaft_point(body, p_through)
        through_source = {"given": "through", "body": "body_shaft", "default": "default"}[came]
        return cls(
            bearings=tuple(zs), stiffness=tuple(zip(kx, ky)), cross_stiffness=tuple(kq),
            damping=tuple(zip(cx, cy)), speed_range=rng, points=npts, orders=ords, speed=W,
            unbalance=unb, shaft=axis, shaft_source=shaft_source, through=where,
            through_source=through_source, symmetry_tol=tol,
            given=tuple(k for k, v in (
                ("bearings", bearings), ("stiffness", stiffness), ("stiffness_y", stiffness_y),
                ("cross_stiffness", cross_stiffness), ("damping", damping), ("damping_y", damping_y),
                ("speed_range", speed_range), ("points", points), ("orders", orders), ("speed", speed),
                ("unbalance", unbalance), ("unbalance_planes", unbalance_planes), ("shaft", shaft),
                ("through", through), ("symmetry_tol", symmetry_tol)) if v is not None),
            typed=tuple(u.typed.items()),
        )


def _as_text(v: Any) -> str:
    if isinstance(v, str):
        return v
    if isinstance(v, (list, tuple)):
        return ",".join(_as_text(x) for x in v)
    return repr(v)


def _check_bearings(zs: list[float]) -> None:
    if len(zs) < 2:
        raise ParamError("bearings", f"a rotor on bearings needs two or more, got one (at z = "
                         f"{zs[0]:.6g} m): one bearing cannot hold the rotor's tilt")
    for i in range(len(zs)):
        for j in range(i + 1, len(zs)):
            if zs[i] == zs[j]:
                if len(set(zs)) == 1:
                    raise ParamError("bearings", f"the bearings are all at one place (z = {zs[i]:.6g} m): "
                                     "nothing holds the rotor's tilt; give positions along the shaft")
                raise ParamError("bearings", f"bearings {i + 1} and {j + 1} are both at z = "
                                 f"{zs[i]:.6g} m; give each its own place (or one bearing with the "
                                 "summed stiffness)")


def _per_bearing(u, value, param: str, kind: str, n: int, *, positive: bool | None) -> list[float]:
    """One value for every bearing, or one per bearing; positive (stiffness), >= 0
    (damping, positive=False) or any sign (positive=None)."""
    with _reading(param):
        vals = u.numbers(value, kind, _opt(param), counts=(1, n) if n > 1 else (1,))
    unit = "N/m" if kind == "stiffness" else "N s/m"
    for i, v in enumerate(vals):
        where = f" (bearing {i + 1})" if len(vals) > 1 else ""
        if positive is True and not v > 0.0:
            raise ParamError(param, f"must be positive, got {v:.6g} {unit}{where}: a bearing "
                             "with no (or negative) stiffness does not hold the rotor")
        if positive is False and v < 0.0:
            raise ParamError(param, f"must not be negative, got {v:.6g} {unit}{where}: a "
                             "negative damper feeds energy in")
    return vals * n if len(vals) == 1 else vals


def _points(points: Any) -> int:
    if points is None:
        return DEFAULT_POINTS
    if isinstance(points, bool) or not isinstance(points, (int, str)):
        raise TypeError(f"points: expected an int, got {type(points).__name__}")
    try:
        n = int(points)
    except ValueError:
        raise ParamError("points", f"expected a whole number, got '{literal(points)}'") from None
    if not 3 <= n <= MAX_POINTS:
        raise ParamError("points", f"must be from 3 to {MAX_POINTS}, got {n}")
    return n


def _orders(orders: Any) -> tuple[int, ...]:
    if orders is None:
        return (1,)
    if isinstance(orders, int) and not isinstance(orders, bool):
        items = [orders]
    elif isinstance(orders, str):
        items = [p.strip() for p in orders.split(",")]
    elif isinstance(orders, (list, tuple)):
        items = list(orders)
    else:
        raise TypeError(f"orders: expected '1,2' or a list of ints, got {type(orders).__name__}")
    out: list[int] = []
    for it in items:
        try:
            k = int(it) if isinstance(it, (int, str)) and not isinstance(it, bool) else None
        except ValueError:
            k = None
        if k is None or not 1 <= k <= MAX_ORDER:
            raise ParamError("orders", f"orders are whole numbers from 1 to {MAX_ORDER} (1 = once per "
                             f"revolution), got '{literal(_as_text(orders))}'")
        if k not in out:
            out.append(k)
    return tuple(sorted(out))


def _unbalance(u, unbalance, planes) -> tuple[tuple[float, complex], ...] | None:
    """Correction-plane unbalances 'U@angle,...' at ``planes``."""
    from rbcli.api import options as op

    if unbalance is None and planes is None:
        return None
    if unbalance is None:
        raise ParamError("unbalance_planes", "gives where the unbalances are; give them with "
                         "{unbalance} U1@angle1,U2@angle2 (e.g. '50 g*mm@0,30 g*mm@90')")
    if planes is None:
        raise ParamError("unbalance", "needs the planes they are in, {unbalance_planes} z1,z2")
    items = [unbalance] if not isinstance(unbalance, (list, tuple)) else list(unbalance)
    texts: list[str] = []
    for it in items:
        texts += [p.strip() for p in str(it).split(",")] if isinstance(it, str) else [it]
    with _reading("unbalance_planes"):
        zs = u.numbers(planes, "length", _opt("unbalance_planes"), counts=tuple(range(1, MAX_BEARINGS + 1)))
    if len(texts) != len(zs):
        raise ParamError("unbalance", f"{len(texts)} unbalance{'s' if len(texts) != 1 else ''} for "
                         f"{len(zs)} plane{'s' if len(zs) != 1 else ''} in {{unbalance_planes}}: give "
                         "one amount@angle per plane")
    out = []
    for z, t in zip(zs, texts):
        if not isinstance(t, str) or t.count("@") != 1:
            raise ParamError("unbalance", f"'{literal(t)}' is not amount@angle, e.g. '50 g*mm@30' "
                             "(amount in kg m unless a unit is given; angle in degrees from the 0° "
                             "mark in the direction of rotation)")
        amount, angle = (s.strip() for s in t.split("@"))
        with _reading("unbalance"):
            U = u.quantity(amount, "unbalance", _opt("unbalance"))
            a = op.degrees(angle, _opt("unbalance"))
        if U < 0.0 or not math.isfinite(a):
            raise ParamError("unbalance", f"'{literal(t)}': the amount must not be negative (turn "
                             "the angle by 180° instead)")
        r = math.radians(a)
        out.append((z, complex(U * math.cos(r), U * math.sin(r))))
    return tuple(out)


# ----------------------------------------------------------------------------- the service


def run(body: Body, options: WhirlOptions) -> WhirlResult:
    """The rotor ``body`` on the bearings of ``options`` (see :func:`whirl`).

    Raises
    ------
    rbcli.InputError
        a rotor the model does not fit (not symmetric about its shaft within
        ``symmetry_tol``, no moment across the shaft), named; :class:`rbcli.NonFiniteResult`
        when a number overflows.
    """
    import numpy as np

    from rbcli.errors import NonFiniteResult

    try:
        with np.errstate(all="ignore"):
            res = _run(body, options)
            res.to_json()  # the one finiteness check (jsonable): refuses inf and NaN
    except (OverflowError, ZeroDivisionError, np.linalg.LinAlgError, NonFiniteResult):
        raise NonFiniteResult(
            "whirl: the result overflows (a number beyond 1e308, or a singular system): an "
            "option value is too large or too small for this body") from None
    return res


def _rotor(body: Body, o: WhirlOptions, warnings: list[str]):
    """(core Rotor, balance Unbalance, RotorData) of ``body`` on the bearings of ``o``."""
    import numpy as np

    from rbcli.core import balance as B
    from rbcli.core import whirl as W
    from rbcli.core.inertia import body_mass_props
    from rbcli.core.symmetry import ROUND_OFF

    mp = body_mass_props(body)
    if o.through == "com":
        P = np.array(mp.com)
    elif o.through == "origin":
        P = np.zeros(3)
    else:
        P = np.asarray(o.through, dtype=float)
    try:
        unb = B.unbalance(mp.mass, mp.com, mp.inertia_com, np.asarray(o.shaft, dtype=float), P)
    except B.BalanceValueError as exc:
        raise InputError(f"whirl: {literal(exc)}") from None
    J = np.array(unb.inertia_shaft)
    I1, I2 = (float(x) for x in np.linalg.eigvalsh(J[:2, :2]))
    It = 0.5 * (float(J[0, 0]) + float(J[1, 1]))
    Ip = float(J[2, 2])
    if not It > 0.0:
        raise InputError("whirl: the rotor has no moment of inertia across its shaft about its "
                         "centre of mass (It = 0: all its mass on one point of the shaft), so "
                         "nothing resists its tilt; the rigid-rotor model needs a body with length "
                         "or diameter")
    asym = (I2 - I1) / It
    coupling = abs(unb.couple) / It
    tol = o.symmetry_tol
    pct = f"{100.0 * tol:.3g} %"
    if asym > max(tol, ROUND_OFF):
        raise InputError(
            f"whirl: the rotor is not symmetric about its shaft: its moments across the shaft "
            f"(about the com) are {I1:.9g} and {I2:.9g} kg m², {100.0 * asym:.3g} % apart, more "
            f"than {{symmetry_tol}} ({pct}); such a rotor has whirl equations with periodic "
            "coefficients, which this constant-coefficient model does not solve (raise "
            "{symmetry_tol} up to 10 % to answer for the symmetrised rotor)")
    if coupling > max(tol, ROUND_OFF):
        raise InputError(
            f"whirl: the rotor's principal axis is tilted {unb.tilt_deg:.3g}° from the shaft: its "
            f"couple unbalance is {100.0 * coupling:.3g} % of It, more than {{symmetry_tol}} "
            f"({pct}); the model takes the products of inertia as a forcing (small against It); "
            "raise {symmetry_tol} up to 10 % to answer anyway")
    if asym > ROUND_OFF:
        warnings.append(Note(
            f"the moments across the shaft differ by {100.0 * asym:.3g} % ({I1:.6g} and "
            f"{I2:.6g} kg m²): answered for the symmetrised rotor, It = {It:.6g} kg m² (within "
            "{symmetry_tol}); its frequencies may be off by about half that"))
    if unb.tilt_deg > 0.0 and abs(unb.couple) > unb.tol_couple:
        warnings.append(Note(
            f"the rotor's nearest principal axis is tilted {unb.tilt_deg:.3g}° from the "
            f"shaft (couple unbalance {abs(unb.couple):.6g} kg m², {100.0 * coupling:.3g} % of "
            "It): its products of inertia force the rotor once per revolution (the couple "
            "unbalance in the response); their effect on the frequencies is neglected"))
    z_G = float(unb.com_shaft[2])
    bearings = tuple(
        W.Bearing(z, kx, ky, q, -q, cx, cy)
        for z, (kx, ky), q, (cx, cy) in zip(o.bearings, o.stiffness, o.cross_stiffness, o.damping))
    rotor = W.Rotor(float(mp.mass), It, Ip, z_G, bearings)
    data = RotorData(
        mass=float(mp.mass), com=z_G, polar_moment=Ip, transverse_moment=It,
        transverse_moments=(I1, I2), asymmetry=float(asym), tilt_deg=float(unb.tilt_deg),
        eccentricity=float(unb.eccentricity), static_unbalance=float(unb.static_unbalance),
        static_unbalance_angle_deg=float(unb.static_angle_deg),
        couple_unbalance=float(unb.couple_unbalance),
        couple_unbalance_angle_deg=float(unb.couple_angle_deg))
    return rotor, unb, data


def _mode_row(m) -> Mode:
    return Mode(frequency=float(m.frequency), whirl=m.whirl, kind=m.shape.kind, node=m.shape.node,
                damping_ratio=float(m.damping_ratio) + 0.0,
                log_decrement=None if m.log_decrement is None else float(m.log_decrement) + 0.0,
                stable=not m.growing)


def _default_range(rotor, crits, speed) -> tuple[float, float]:
    """0 to 1.25 times the highest of: the operating speed, the critical speeds, and (when
    there is neither) the highest natural frequency at rest."""
    from rbcli.core import whirl as W

    top = max([c.speed for c in crits] + ([speed[1]] if speed is not None else []), default=0.0)
    if top == 0.0:
        top = max(m.frequency for m in W.modes_at(rotor, 0.0))
    return 0.0, 1.25 * top


def _run(body: Body, o: WhirlOptions) -> WhirlResult:
    import numpy as np

    from rbcli.core import whirl as W
    from rbcli.core.balance import plane_unbalances

    warnings: list[str] = []
    rotor, unb, rdata = _rotor(body, o, warnings)
    warnings += _plausibility(body, o, rotor)
    crits, missing = W.critical_speeds(rotor, o.orders)
    rng = o.speed_range or _default_range(rotor, crits, o.speed)
    speeds = np.linspace(rng[0], rng[1], o.points)
    if o.speed is not None:  # the operating speeds are points of the grid
        speeds = np.unique(np.concatenate([speeds, [s for s in o.speed if rng[0] <= s <= rng[1]]]))
    cb = W.campbell(rotor, speeds)

    # -- critical speeds: undamped (exact), damped crossing, whether the unbalance drives them
    if o.unbalance is None:
        forcing = W.Forcing(unb.static, unb.couple)
    else:
        forcing = W.Forcing.from_planes(rotor.z_com, list(o.unbalance))
    crit_rows = []
    for c in crits:
        dc = W.damped_crossing(rotor, c)
        excited = _excited(rotor, forcing, c) if c.order == 1 else None
        crit_rows.append(CriticalSpeed(
            speed=c.speed, order=c.order, mode=c.shape.kind, whirl=c.whirl, node=c.shape.node,
            damped_speed=None if dc is None else float(dc[0]),
            damping_ratio=None if dc is None else float(dc[1].damping_ratio) + 0.0,
            log_decrement=None if dc is None or dc[1].log_decrement is None else float(dc[1].log_decrement) + 0.0,
            in_range=bool(rng[0] <= c.speed <= rng[1]), excited=excited))
    missing_rows = tuple(NoCrossing(m.order, m.whirl, m.kind, m.reason, m.Ip, m.It) for m in missing)

    # -- stability
    onsets = W.onset_speeds(rotor, cb)
    zeta = cb.array("damping_ratio")
    i_min, j_min = np.unravel_index(int(np.argmin(zeta)), zeta.shape)
    modes_speed = o.speed[1] if o.speed is not None else 0.0
    at = W.modes_at(rotor, modes_speed)
    stable_at = None
    if o.speed is not None:
        stable_at = not any(m.growing for s in set(o.speed) for m in W.modes_at(rotor, s))
    stability = Stability(
        stable_in_range=not any(m.growing for ms in cb.modes for m in ms),
        onset_speeds=tuple(float(x) for x, _, _ in onsets),
        least_damping_ratio=float(zeta[i_min, j_min]) + 0.0,
        least_damping_speed=float(cb.speeds[j_min]), stable_at_speed=stable_at)
    if not stability.stable_in_range or stable_at is False:
        warnings.append(_unstable_note(cb, stability, stable_at, o))

    # -- unbalance response
    resp = W.response(rotor, forcing, speeds)
    if len(resp.speeds) < len(speeds):
        gone = sorted(set(float(x) for x in speeds) - set(float(x) for x in resp.speeds))
        warnings.append(Note("the response is unbounded at " + ", ".join(f"{x:.6g}" for x in gone)
                             + " rad/s (an undamped critical speed on the grid): those speeds are "
                             "left out of the response"))
    damped = rotor.damped
    peaks = W.peaks(rotor, forcing, resp) if damped else []
    peak_rows = []
    for p in peaks:
        near = _nearest_critical(crit_rows, p.speed)
        peak_rows.append(PeakRow(
            bearing=p.bearing + 1, plane=o.bearings[p.bearing], speed=p.speed, amplitude=p.amplitude,
            amplification_factor=p.amplification_factor, half_power=p.half_power,
            mode=None if near is None else near.mode, whirl=None if near is None else near.whirl,
            undamped=False))
    if not damped:
        for c in crit_rows:
            if c.excited and c.in_range:
                for i, z in enumerate(o.bearings):
                    peak_rows.append(PeakRow(bearing=i + 1, plane=z, speed=c.speed, amplitude=None,
                                             amplification_factor=None, half_power=None, mode=c.mode,
                                             whirl=c.whirl, undamped=True))
    at_rows = ()
    if o.speed is not None:
        Wop = o.speed[1]
        one = W.response(rotor, forcing, np.array([Wop]))
        rigid = None
        if len(o.bearings) == 2:
            P0 = forcing.couple + rotor.z_com * forcing.static  # about z = 0
            rigid = [abs(u) * Wop * Wop for u in plane_unbalances(forcing.static, P0, *o.bearings)]
        at_rows = tuple(AtSpeed(plane=z, displacement=float(one.displacement[i, 0]),
                                displacement_phase_deg=float(one.displacement_phase_deg[i, 0]),
                                force=float(one.force[i, 0]), force_phase_deg=float(one.force_phase_deg[i, 0]),
                                rigid_force=None if rigid is None else float(rigid[i]))
                        for i, z in enumerate(o.bearings))
    unb_rows = () if o.unbalance is None else tuple(
        UnbalanceRow(plane=z, amount=abs(u), angle_deg=_angle(u)) for z, u in o.unbalance)
    response = ResponseData(
        source="body" if o.unbalance is None else "planes", unbalance=unb_rows,
        speeds=readonly(resp.speeds),
        bearings=tuple(ResponseBearing(
            plane=z, displacement=resp.displacement[i], displacement_minor=resp.displacement_minor[i],
            displacement_phase_deg=resp.displacement_phase_deg[i], force=resp.force[i],
            force_phase_deg=resp.force_phase_deg[i]) for i, z in enumerate(o.bearings)),
        peaks=tuple(peak_rows), at_speed=at_rows)
    if forcing.zero:
        warnings.append(Note("the rotor is balanced (no static or couple unbalance about "
                             "the shaft): its unbalance response is zero; give {unbalance} and "
                             "{unbalance_planes} to see the response to a test unbalance"))

    # -- separation margins at the operating speed
    margins = None
    if o.speed is not None:
        checks = []
        for p in peak_rows:
            mg = W.margin(p.speed, p.amplification_factor, o.speed[0], o.speed[1])
            checks.append(MarginCheck(
                bearing=p.bearing, plane=p.plane, speed=p.speed, mode=p.mode,
                amplification_factor=p.amplification_factor,
                basis="undamped" if p.undamped else ("half-power" if p.amplification_factor is not None
                                                     else "undefined"),
                position=mg.position,
                margin_percent=mg.margin_percent, required_margin_percent=mg.required_percent,
                passed=mg.passed))
        if not damped:  # one check per excited critical speed, not per bearing
            seen, uniq = set(), []
            for ch in checks:
                if ch.speed not in seen:
                    seen.add(ch.speed)
                    uniq.append(dataclass_replace(ch, bearing=None, plane=None))
            checks = uniq
        margins = Margins(rule=API_RULE, operating_speed=o.speed, checks=tuple(checks),
                          passed=None if not checks else all(c.passed for c in checks))
        if not checks and not forcing.zero:
            warnings.append(Note("no response peak in the speed range: no critical speed "
                                 "to judge against the operating speed (widen {speed_range} to "
                                 "see peaks beyond it)"))

    campbell = Campbell(
        speeds=readonly(cb.speeds), frequencies=readonly(cb.array("frequency")),
        whirl=tuple(tuple(m[i].whirl for m in cb.modes) for i in range(4)),
        damping_ratio=readonly(cb.array("damping_ratio") + 0.0),
        log_decrement=tuple(tuple(None if m[i].log_decrement is None else float(m[i].log_decrement) + 0.0
                                  for m in cb.modes) for i in range(4)),
        kind=tuple(tuple(m[i].shape.kind for m in cb.modes) for i in range(4)))
    return WhirlResult(
        name=body.name, conventions=dict(CONVENTIONS), shaft=tuple(float(x) for x in o.shaft),
        shaft_source=o.shaft_source, through=o.through, through_source=o.through_source,
        rotor=rdata,
        bearings=tuple(BearingData(plane=b.z, stiffness=(b.kxx, b.kyy), cross_stiffness=(b.kxy, b.kyx),
                                   damping=(b.cxx, b.cyy)) for b in rotor.bearings),
        speed_range=(float(rng[0]), float(rng[1])),
        speed_range_source="speed_range" if o.speed_range is not None else "default",
        orders=o.orders, speed=o.speed, symmetry_tol=o.symmetry_tol, modes_speed=float(modes_speed),
        modes=tuple(_mode_row(m) for m in at), campbell=campbell, critical_speeds=tuple(crit_rows),
        no_crossings=missing_rows, stability=stability, response=response, margins=margins,
        warnings=tuple(warnings), units=dict(getattr(body, "units", None) or {}),
        source=str(getattr(body, "source", "")), points=o.points, isotropic=rotor.isotropic,
        given=o.given, typed=o.typed)


def dataclass_replace(obj, **kw):
    import dataclasses

    return dataclasses.replace(obj, **kw)


def _angle(u: complex) -> float:
    from rbcli.core.whirl.response import phase_deg

    return phase_deg(u)


def _nearest_critical(rows, speed: float):
    """The order-1 critical speed nearest ``speed`` that the unbalance drives (by its damped
    speed when known), within 25 %; None when there is none."""
    best, best_d = None, math.inf
    for c in rows:
        if c.order != 1 or c.excited is False:
            continue
        s = c.damped_speed if c.damped_speed is not None else c.speed
        d = abs(s - speed)
        if d < best_d:
            best, best_d = c, d
    return best if best is not None and best_d <= 0.25 * speed else None


def _excited(rotor, forcing, crit) -> bool:
    """The unbalance drives the undamped critical speed ``crit`` (order 1)
    (:func:`rbcli.core.whirl.response.excitation` above 1e-8)."""
    from rbcli.core.whirl.response import EXCITED_RTOL, excitation

    return bool(excitation(rotor, forcing, crit.speed, crit.q) > EXCITED_RTOL)


def _unstable_note(cb, st: Stability, stable_at, o: WhirlOptions) -> str:
    where = ""
    if st.onset_speeds:
        where = f"; a mode starts growing at {st.onset_speeds[0]:.6g} rad/s"
    at = ""
    if stable_at is False:
        at = " AT THE OPERATING SPEED {speed}"
    return Note(f"UNSTABLE{at}: a whirl mode grows (damping ratio down to "
                f"{st.least_damping_ratio:.3g} at {st.least_damping_speed:.6g} rad/s{where}); "
                "the cross-coupled stiffness feeds it more than the damping takes out")


def _plausibility(body: Body, o: WhirlOptions, rotor) -> list[str]:
    """Bearings or unbalance planes more than 10 body sizes from the com (a unit missing?)."""
    from rbcli.api import options as op
    from rbcli.core.scale import FAR, body_scale

    u = op.Units.of(body)
    sc = body_scale(body.parts)
    out = []
    far = max(abs(z - rotor.z_com) for z in o.bearings)
    if far > FAR * sc.size:
        out.append(u.far(_opt("bearings"), "a bearing", far, sc.size))
    if o.unbalance is not None:
        far = max(abs(z - rotor.z_com) for z, _ in o.unbalance)
        if far > FAR * sc.size:
            out.append(u.far(_opt("unbalance_planes"), "an unbalance plane", far, sc.size))
    return out


def whirl(body: Body, *, bearings: Values | None = None, stiffness: Values | None = None,
          stiffness_y: Values | None = None, cross_stiffness: Values | None = None,
          damping: Values | None = None, damping_y: Values | None = None,
          speed_range: Values | None = None, points: int | None = None,
          orders: int | str | Sequence[int] | None = None, speed: Values | None = None,
          unbalance: str | Sequence[str] | None = None, unbalance_planes: Values | None = None,
          shaft: Vector | None = None, through: Point | None = None,
          symmetry_tol: Quantity | None = None) -> WhirlResult:
    """The rigid rotor on linear bearings: Campbell diagram, critical speeds, stability,
    unbalance response and API separation margins.

    Every value may be an SI number (a sequence for lists) or a string as typed on the
    command line (``"0,400 mm"``, ``"0,6000 rpm"``, ``"2e7 N/m"``): the rules of
    ``rbcli whirl`` (bare lengths in the body's length unit, bare speeds in rad/s unless
    the body's units name an angular_speed, stiffness N/m, damping N s/m).

    Parameters
    ----------
    body : Body
        The rotor (:func:`rbcli.load`).
    bearings : str or sequence
        Bearing positions z1,z2[,...] along the shaft, m (two or more, distinct).
    stiffness : str, float or sequence
        N/m, every bearing's (one value) or each bearing's; the x stiffness when
        ``stiffness_y`` is given, else both.
    stiffness_y : str, float or sequence, optional
        N/m, the y stiffness (anisotropic bearings).
    cross_stiffness : str, float or sequence, optional
        N/m, kxy (kyx = -kxy): the destabilising cross-coupling of fluid films and seals.
    damping, damping_y : str, float or sequence, optional
        N s/m, damping in x (and y); default none.
    speed_range : str or (2,) sequence, optional
        rad/s, a,b with 0 <= a < b (``"0,6000 rpm"``). Default: 0 to 1.25 times the highest
        critical speed or operating speed.
    points : int, optional
        Speeds in the range (default 201).
    orders : str or sequence of int, optional
        The n× lines whose critical speeds are wanted (default 1; ``"1,2"``).
    speed : str, float or (2,) sequence, optional
        rad/s, the operating speed, or min,max of the operating range: the separation
        margins (API 617 / 684) and the stability there.
    unbalance : str or sequence of str, optional
        Correction-plane unbalances ``"amount@angle"`` (kg m unless a unit is given,
        ``"50 g*mm@30"``; angles in degrees from the 0° mark in the direction of rotation);
        default the body's own static and couple unbalance.
    unbalance_planes : str or sequence, optional
        m, where the ``unbalance`` amounts are, one plane each.
    shaft, through : optional
        The shaft (direction, body frame) and a point of it, as for :func:`rbcli.balance`.
    symmetry_tol : float or str, optional
        How far from symmetric about the shaft the rotor may be (default 1 %).

    Returns
    -------
    WhirlResult
        ``return_code`` 1 when ``speed`` fails the separation-margin rule or a mode grows
        there.

    Raises
    ------
    TypeError
        An argument of the wrong type, naming the parameter and the type expected
        (:mod:`rbcli.api.check`).
    rbcli.InputError
        A bad or missing value (``bearings: ...``), or a rotor the model does not fit.

    Examples
    --------
    >>> import rbcli
    >>> body = rbcli.load_text("{shape: cylinder, radius: 0.1, length: 0.6, mass: 50}")
    >>> r = rbcli.whirl(body, bearings="-0.2,0.2", stiffness=1e6)
    >>> [round(c.speed, 3) for c in r.critical_speeds]
    [200.0, 200.0, 206.559, 241.209]
    """
    body = check.body(body)
    kw = check.arguments(
        KINDS, bearings=bearings, stiffness=stiffness, stiffness_y=stiffness_y,
        cross_stiffness=cross_stiffness, damping=damping, damping_y=damping_y,
        speed_range=speed_range, points=points, orders=orders, speed=speed, unbalance=unbalance,
        unbalance_planes=unbalance_planes, shaft=shaft, through=through, symmetry_tol=symmetry_tol)
    with check.arithmetic(kw):
        return run(body, WhirlOptions.parse(body, **kw))
