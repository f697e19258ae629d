"""The rotor on its bearings: the service behind ``rbcli whirl``.

:func:`parse` reads the parameters (:data:`rbcli.api.commands.WHIRL`); :func:`run` builds
the rigid rotor from the body (mass, com, moments in shaft axes, its unbalance) on linear
bearings and runs :mod:`rbcli.core.whirl`: the Campbell diagram, critical speeds,
stability, the unbalance response and, at an operating speed, the API 617 / 684
separation margins, in a frozen :class:`WhirlResult` whose attributes are its JSON keys."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from rbcli.api import options as op
from rbcli.api.commands import DEFAULT_POINTS, MAX_ORDER, MAX_POINTS, WHIRL
from rbcli.api.params import Options, as_text, function, read
from rbcli.api.shaft import shaft_axis, shaft_point
from rbcli.api.whirlbearings import OPTIONS, bearings, entries, per_bearing
from rbcli.api.whirlresult import (
    API_RULE, CONVENTIONS, AtSpeed, BearingData, BearingTableData, Campbell, CriticalMap,
    CriticalSpeed, Margins, MarginCheck, Mode, NoCrossing, PeakRow, ResponseBearing, ResponseData,
    RotorData, Stability, ThresholdRow, UnbalanceRow, WhirlResult, readonly,
)
from rbcli.core import balance as B
from rbcli.core import whirl as W
from rbcli.core.balance import plane_unbalances
from rbcli.core.inertia import body_mass_props
from rbcli.core.scale import FAR, body_scale
from rbcli.core.symmetry import ROUND_OFF
from rbcli.core.whirl.critical import critical_map
from rbcli.core.whirl.model import KINDS, WHIRLS
from rbcli.core.whirl.response import EXCITED_RTOL, excitation, phase_deg
from rbcli.core.whirl.stability import stability
from rbcli.errors import InputError, NonFiniteResult, Note, ParamError, literal

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.body.model import Body

__all__ = ["WhirlResult", "whirl", "parse", "run", "CONVENTIONS"]

RPM = 30.0 / math.pi  # rpm per rad/s, for messages

# --- options


def parse(body: Body, **kwargs: Any) -> Options:
    """The keyword arguments of :func:`whirl` (see there) read for ``body`` and checked:
    :class:`rbcli.api.params.Options` in SI, per-bearing values one per bearing, ``unbalance``
    as (plane z m, complex kg m) pairs.

    Raises
    ------
    rbcli.InputError
        one line naming the parameter (``bearings: ...``).
    """
    o = read(body, WHIRL, kwargs)
    if o.damping_y is not None and o.damping is None and entries(body) is None:
        raise ParamError("damping_y", "gives the y damping; give {damping} (x, or both) too")
    n = len(bearings(body, o)[0])
    each = {name: per_bearing(getattr(o, name), kwargs[name], name, n)
            for name in OPTIONS if getattr(o, name) is not None}
    return o.replace(**each, points=_points(o.points), orders=_orders(o.orders),
                     unbalance=_unbalance(body, o.unbalance, o.unbalance_planes))


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
                             f"revolution), got '{literal(as_text(orders))}'")
        if k not in out:
            out.append(k)
    return tuple(sorted(out))


def _unbalance(body: Body, unbalance: Any, planes: Any) -> tuple[tuple[float, complex], ...] | None:
    """Correction-plane unbalances 'U@angle,...' at ``planes`` (read, m)."""
    if unbalance is None and planes is None:
        return None
    if unbalance is None:
        raise ParamError("unbalance_planes", "gives where the unbalances are; give them with "
                         "{unbalance} U1@angle1,U2@angle2 (e.g. '50 g*mm@0,30 g*mm@90')")
    if planes is None:
        raise ParamError("unbalance", "needs the planes they are in, {unbalance_planes} z1,z2")
    items = [unbalance] if isinstance(unbalance, str) else list(unbalance)
    texts = [p.strip() for it in items for p in it.split(",")]
    if len(texts) != len(planes):
        raise ParamError("unbalance", f"{len(texts)} unbalance{'s' if len(texts) != 1 else ''} for "
                         f"{len(planes)} plane{'s' if len(planes) != 1 else ''} in {{unbalance_planes}}: "
                         "give one amount@angle per plane")
    u = op.Units.of(body)
    out = []
    for z, t in zip(planes, texts):
        if t.count("@") != 1:
            raise ParamError("unbalance", f"'{literal(t)}' is not amount@angle, e.g. '50 g*mm@30' "
                             "(amount in kg m unless a unit is given; angle in degrees from the 0° "
                             "mark in the direction of rotation)")
        amount, angle = (s.strip() for s in t.split("@"))
        with op.naming("unbalance"):
            U = u.quantity(amount, "unbalance", "unbalance")
            a = op.degrees(angle, "unbalance")
        if U < 0.0 or not math.isfinite(a):
            raise ParamError("unbalance", f"'{literal(t)}': the amount must not be negative (turn "
                             "the angle by 180° instead)")
        r = math.radians(a)
        out.append((z, complex(U * math.cos(r), U * math.sin(r))))
    return tuple(out)


# --- the service


def run(body: Body, options: Options) -> WhirlResult:
    """The rotor ``body`` on the bearings of ``options`` (:func:`parse`; see :func:`whirl`).

    Raises
    ------
    rbcli.InputError
        a rotor the model does not fit (not symmetric about its shaft within
        ``symmetry_tol``, no moment across the shaft), named; :class:`rbcli.NonFiniteResult`
        when a number overflows.
    """
    try:
        with np.errstate(all="ignore"):
            res = _run(body, options)
            res.to_json()  # the one finiteness check (jsonable): refuses inf and NaN
    except (OverflowError, ZeroDivisionError, np.linalg.LinAlgError, NonFiniteResult):
        raise NonFiniteResult(
            "whirl: the result overflows (a number beyond 1e308, or a singular system): an "
            "option value is too large or too small for this body") from None
    return res


def _rotor(body: Body, o: Options, shaft: tuple, through: Any, brgs: tuple, warnings: list[str]):
    """(core Rotor, balance Unbalance, RotorData) of ``body`` on the bearings ``brgs``."""
    mp = body_mass_props(body)
    P = {"com": np.array(mp.com), "origin": np.zeros(3)}.get(through) if isinstance(through, str) \
        else np.asarray(through, dtype=float)
    try:
        unb = B.unbalance(mp.mass, mp.com, mp.inertia_com, np.asarray(shaft, dtype=float), P)
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
    _check_symmetry(o.symmetry_tol, I1, I2, It, asym, coupling, unb, warnings)
    z_G = float(unb.com_shaft[2])
    rotor = W.Rotor(float(mp.mass), It, Ip, z_G, brgs)
    data = RotorData(
        mass=float(mp.mass), com=z_G, polar_moment=Ip, transverse_moment=It,
        transverse_moments=(I1, I2), asymmetry=float(asym), tilt_deg=float(unb.tilt_deg),
        eccentricity=float(unb.eccentricity), static_unbalance=float(unb.static_unbalance),
        static_unbalance_angle_deg=float(unb.static_angle_deg),
        couple_unbalance=float(unb.couple_unbalance),
        couple_unbalance_angle_deg=float(unb.couple_angle_deg))
    return rotor, unb, data


def _check_symmetry(tol: float, I1: float, I2: float, It: float, asym: float, coupling: float,
                    unb: Any, warnings: list[str]) -> None:
    """Refuse a rotor too far from symmetric about its shaft; warn of one within ``tol``."""
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


def _mode_row(m, rotor) -> Mode:
    w = m.vector
    sm, si = np.sqrt(rotor.mass), np.sqrt(rotor.It)
    rf, pf, rb, pb = w[0] / sm, w[1] / si, w[2] / sm, w[3] / si
    share = []
    for a in rotor.arms():
        f, bk = abs(rf + a * pf) ** 2, abs(rb + a * pb) ** 2
        share.append(float(f / (f + bk)) if f + bk > 0.0 else 0.5)
    return Mode(frequency=float(m.frequency), whirl=m.whirl, kind=m.shape.kind, node=m.shape.node,
                damping_ratio=float(m.damping_ratio) + 0.0, log_decrement=_log_decrement(m),
                stable=not m.growing, forward_share=float(m.shape.forward_share),
                bearing_forward_share=tuple(share))


def _log_decrement(m) -> float | None:
    return None if m.log_decrement is None else float(m.log_decrement) + 0.0


def _default_range(rotor, crits, speed) -> tuple[float, float]:
    """0 to 1.25 times the highest of: the operating speed, the critical speeds, and (when
    there is neither) the highest natural frequency at rest; with bearing tables, within
    the speeds they cover (all of them when there is neither)."""
    lo, hi = rotor.speed_span()
    top = max([c.speed for c in crits] + ([speed[-1]] if speed is not None else []), default=0.0)
    if top == 0.0:
        top = hi if rotor.varying else max(m.frequency for m in W.modes_at(rotor, lo))
    return lo, (min(hi, 1.25 * top) if 1.25 * top > lo else hi)


#: the widest spread of the rotor's natural frequencies (and of its damping rates and speeds
#: against them) an eigen-solve in double precision keeps the slower ones of (to ~1e-8)
SPREAD = 1e4


def _check_scale(rotor, o: Options) -> None:
    """Refuse numbers so far apart that the whirl equations lose their meaning in floating
    point: the rotor's frequency scales (each stiffness term over its mass, at every row of
    the tables) spread over more than SPREAD², damping rates or speeds above SPREAD times the
    highest of them; and speeds beyond the bearing tables (never extrapolated)."""
    lo, hi = rotor.speed_span()
    rows = _ascending(np.concatenate([[lo], *(b.speeds for b in rotor.bearings if isinstance(b, W.BearingTable))]))
    K, C = rotor.matrices(rows)
    m = np.sqrt(np.diag(rotor.M()))
    w2 = np.abs(K) / np.outer(m, m)
    c = np.abs(C) / np.outer(m, m)
    diag = np.diagonal(w2, axis1=1, axis2=2)
    top = float(np.sqrt(np.max(diag)))
    if not (top < math.inf and np.max(w2) <= SPREAD**4 * np.min(diag) and np.max(c) <= SPREAD * top):
        raise InputError(
            "whirl: the bearings' coefficients and the rotor's mass and inertia are too far apart "
            f"to compute with: its frequency scales span {math.sqrt(np.min(diag)):.3g} to "
            f"{math.sqrt(np.max(w2)):.3g} rad/s and its damping rates reach {np.max(c):.3g} 1/s (a "
            f"spread above {SPREAD**2:.0e}, or damping above {SPREAD:.0e} times the frequencies, "
            "leaves the eigen-solve nothing of the slower modes); check the values and their units")
    sv = np.linalg.svd(K / np.outer(m, m), compute_uv=False)  # coupled: translation and tilt
    if np.min(sv) * SPREAD**4 < np.max(sv):
        z = [b.z for b in rotor.bearings]
        far = max(abs(x - rotor.z_com) for x in z)
        raise InputError(f"whirl: the bearings span {max(z) - min(z):.3g} m, too little for their distance "
                         f"from the centre of mass ({far:.3g} m): the rotor's tilt stiffness is lost in "
                         "round-off; give {bearings} further apart")
    for p in o.params:  # the speeds given: the operating speed and the range
        v = getattr(o, p.name) if p.quantity == "angular_speed" else None
        if v is not None and max(v) > SPREAD * top:
            raise ParamError(p.name, f"{max(v):.6g} rad/s is more than {SPREAD:.0e} times the "
                             f"rotor's highest natural frequency ({top:.6g} rad/s): there its slowest "
                             "whirl is below 1e-8 of its fastest and the eigen-solve's round-off "
                             "swamps it; give speeds within that (a unit missing?)")
        if v is not None and (min(v) < lo or max(v) > hi):
            x = min(v) if min(v) < lo else max(v)
            raise ParamError(p.name, f"{x * RPM:.6g} rpm ({x:.6g} rad/s) is beyond the bearing "
                             f"tables, which cover {lo * RPM:.6g} to {hi * RPM:.6g} rpm together: a "
                             "table is not extrapolated; give speeds within it or extend the table")


def _criticals(rotor, crits, forcing, rng) -> list[CriticalSpeed]:
    """The undamped critical speeds, their damped crossings, whether the unbalance drives
    them."""
    rows, crossings = [], [W.damped_crossing(rotor, c) for c in crits]
    for i, c in enumerate(crits):  # two modes followed to one crossing: the nearer keeps it
        dc = crossings[i]
        if dc is not None and any(d is not None and o.order == c.order and d[0] == dc[0]
                                  and abs(o.speed - d[0]) < abs(c.speed - dc[0])
                                  for o, d in zip(crits, crossings)):
            dc = None
        rows.append(CriticalSpeed(
            speed=c.speed, order=c.order, mode=c.shape.kind, whirl=c.whirl, node=c.shape.node,
            damped_speed=None if dc is None else float(dc[0]),
            damping_ratio=None if dc is None else float(dc[1].damping_ratio) + 0.0,
            log_decrement=None if dc is None else _log_decrement(dc[1]),
            in_range=bool(rng[0] <= c.speed <= rng[1]),
            excited=bool(excitation(rotor, forcing, c.speed, c.eigenvalue, c.whirl) > EXCITED_RTOL)
            if c.order == 1 else None, forward_share=float(c.shape.forward_share)))
    return rows


def _stability(rotor, cb, ranks, speed) -> Stability:
    st = stability(cb, ranks)
    zeta = cb.damping_ratio
    j_min, i_min = np.unravel_index(int(np.argmin(zeta)), zeta.shape)
    stable_at = None
    if speed is not None:
        lo, hi = speed[0], speed[-1]
        inside = cb.speeds[0] <= lo and hi <= cb.speeds[-1]
        stable_at = not (st.growing(lo, hi) if inside else
                         any(m.growing for s in (lo, hi) for m in W.modes_at(rotor, s)))
    rows = tuple(ThresholdRow(t.speed, t.change, t.branch + 1, t.mode.whirl, t.mode.shape.kind,
                              float(t.mode.frequency)) for t in st.thresholds)
    return Stability(
        stable_in_range=not st.growing(*st.speeds), onset_speeds=tuple(t.speed for t in rows),
        least_damping_ratio=float(zeta[j_min, i_min]) + 0.0,
        least_damping_speed=float(cb.speeds[j_min]), stable_at_speed=stable_at,
        threshold_speed=st.threshold, unstable_from_start=bool(st.from_start), thresholds=rows)


def _peaks(rotor, forcing, resp, crit_rows, planes) -> list[PeakRow]:
    """The response peaks with their amplification factors (damped), or the excited critical
    speeds in the range as infinite peaks at every bearing (undamped)."""
    if not rotor.damped:
        return [PeakRow(bearing=i + 1, plane=z, speed=c.speed, amplitude=None,
                        amplification_factor=None, half_power=None, mode=c.mode, whirl=c.whirl,
                        undamped=True, basis="undamped")
                for c in crit_rows if c.excited and c.in_range for i, z in enumerate(planes)]
    rows = []
    for p in W.peaks(rotor, forcing, resp):
        near = _nearest_critical(crit_rows, p.speed)
        af, basis = p.amplification_factor, "half-power"
        if af is None:
            zeta = None if near is None else near.damping_ratio
            af, basis = (0.5 / zeta, "damping ratio") if zeta is not None and zeta > 0.0 else (None, "undefined")
        rows.append(PeakRow(
            bearing=p.bearing + 1, plane=planes[p.bearing], speed=p.speed, amplitude=p.amplitude,
            amplification_factor=af, half_power=p.half_power,
            mode=None if near is None else near.mode, whirl=None if near is None else near.whirl,
            undamped=False, basis=basis))
    return rows


def _at_speed(rotor, forcing, speed, planes) -> tuple[AtSpeed, ...]:
    """The response at the (maximum) operating speed, and the rigid-support bearing forces
    (two bearings)."""
    if speed is None:
        return ()
    Wop = speed[-1]
    one = W.response(rotor, forcing, np.array([Wop]))
    if not one.speeds.size:
        raise InputError(f"{{speed}}: {Wop:.6g} rad/s is an undamped critical speed that the unbalance "
                         "drives: the response there is unbounded; give {damping}, or a speed off it")
    rigid = None
    if len(planes) == 2:
        P0 = forcing.couple + rotor.z_com * forcing.static  # about z = 0
        rigid = [abs(u) * Wop * Wop for u in plane_unbalances(forcing.static, P0, *planes)]
    return tuple(AtSpeed(plane=z, displacement=float(one.displacement[i, 0]),
                         displacement_phase_deg=float(one.displacement_phase_deg[i, 0]),
                         force=float(one.force[i, 0]), force_phase_deg=float(one.force_phase_deg[i, 0]),
                         rigid_force=None if rigid is None else float(rigid[i]))
                 for i, z in enumerate(planes))


def _response(rotor, forcing, speeds, o: Options, crit_rows, warnings) -> ResponseData:
    resp = W.response(rotor, forcing, speeds)
    if len(resp.speeds) < len(speeds):
        gone = sorted(set(float(x) for x in speeds) - set(float(x) for x in resp.speeds))
        warnings.append(Note("the response is unbounded at " + ", ".join(f"{x:.6g}" for x in gone)
                             + " rad/s (an undamped critical speed on the grid): those speeds are "
                             "left out of the response"))
    if forcing.zero:
        warnings.append(Note("the rotor is balanced (no static or couple unbalance about "
                             "the shaft): its unbalance response is zero and no critical speed is "
                             "judged against the operating speed; give {unbalance} and "
                             "{unbalance_planes} to see the response to a test unbalance (API 684's "
                             "is 4W/N) and judge the separation margins"))
    planes = tuple(b.z for b in rotor.bearings)
    return ResponseData(
        source="body" if o.unbalance is None else "planes",
        unbalance=() if o.unbalance is None else tuple(
            UnbalanceRow(plane=z, amount=abs(u), angle_deg=phase_deg(u)) for z, u in o.unbalance),
        speeds=readonly(resp.speeds),
        bearings=tuple(ResponseBearing(
            plane=z, displacement=resp.displacement[i], displacement_minor=resp.displacement_minor[i],
            displacement_phase_deg=resp.displacement_phase_deg[i], force=resp.force[i],
            force_phase_deg=resp.force_phase_deg[i]) for i, z in enumerate(planes)),
        peaks=tuple(_peaks(rotor, forcing, resp, crit_rows, planes)),
        at_speed=_at_speed(rotor, forcing, o.speed, planes))


def _margins(speed, peaks, damped: bool, forcing, warnings) -> Margins | None:
    """The separation margins of each response peak from the operating speed (API 617/684):
    one check per excited critical speed when undamped, per peak and bearing when damped."""
    if speed is None:
        return None
    lo, hi = speed[0], speed[-1]
    checks = []
    seen = set()
    for p in peaks:
        if not damped and p.speed in seen:
            continue
        seen.add(p.speed)
        mg = W.margin(p.speed, p.amplification_factor, lo, hi)
        checks.append(MarginCheck(
            bearing=p.bearing if damped else None, plane=p.plane if damped else None,
            speed=p.speed, mode=p.mode, amplification_factor=p.amplification_factor,
            basis=p.basis, position=mg.position, margin_percent=mg.margin_percent,
            required_margin_percent=mg.required_percent, passed=mg.passed))
    if not checks and not forcing.zero:
        warnings.append(Note("no response peak in the speed range: no critical speed "
                             "to judge against the operating speed (a wider speed range "
                             "shows peaks beyond it)"))
    return Margins(rule=API_RULE, operating_speed=(lo, hi), checks=tuple(checks),
                   passed=None if not checks else all(c.passed for c in checks))


def _campbell(cb, ranks) -> Campbell:
    branch = np.empty_like(ranks)
    np.put_along_axis(branch, ranks, np.arange(4)[None, :], 1)  # branch[j, rank] = k
    f = cb.frequency.T
    logdec = np.where(f > 0.0, -2.0 * np.pi * cb.eigenvalues.real.T / np.where(f > 0.0, f, 1.0) + 0.0, None)
    return Campbell(
        speeds=readonly(cb.speeds), frequencies=readonly(f), whirl=np.array(WHIRLS)[cb.whirl.T],
        damping_ratio=readonly(cb.damping_ratio.T + 0.0), log_decrement=logdec,
        kind=np.array(KINDS)[cb.kind.T], branch=branch.T + 1)  # (the result freezes them)


def _map(rotor, o: Options, rng) -> CriticalMap:
    """The undamped critical speed map over ``map_stiffness`` (default: whole decades from a
    tenth of the softest direct stiffness to ten times the stiffest), 8 points a decade."""
    curves = []
    for b in rotor.bearings:
        sp = np.array(rng, dtype=float)
        if isinstance(b, W.BearingTable):
            sp = _ascending(np.concatenate([sp, b.speeds[(b.speeds > rng[0]) & (b.speeds < rng[1])]]))
        v = b.coefficients(sp)
        curves.append({"plane": b.z, "speeds": sp.tolist(), "kxx": v[:, 0].tolist(), "kyy": v[:, 3].tolist()})
    ks = [k for c in curves for k in c["kxx"] + c["kyy"]]
    if o.map_stiffness is not None:
        lo, hi = np.log10(o.map_stiffness)
    else:
        lo, hi = np.floor(np.log10(min(ks) / 10.0)), np.ceil(np.log10(max(ks) * 10.0))
    k = np.logspace(lo, hi, int(round(8 * (hi - lo))) + 1)
    speeds, labels = critical_map(rotor, k)
    return CriticalMap(stiffness=readonly(k), speeds=readonly(speeds.T), whirl=tuple(w for w, _ in labels),
                       mode=tuple(m for _, m in labels), bearings=tuple(curves))


_SOURCE = {"given": "shaft", "body": "body_shaft", "default": "default"}


def _ascending(a: np.ndarray) -> np.ndarray:
    """The distinct values of ``a``, ascending (np.unique's, without its import of numpy.ma,
    ~5 ms of every run)."""
    a = np.sort(np.asarray(a, dtype=float))
    return a[np.concatenate([[True], np.diff(a) != 0.0])]


def _run(body: Body, o: Options) -> WhirlResult:
    warnings: list[str] = []
    shaft, shaft_from = shaft_axis(body, o.shaft)
    through, through_from = shaft_point(body, o.through)
    brgs, names, sources = bearings(body, o)
    rotor, unb, rdata = _rotor(body, o, shaft, through, brgs, warnings)
    warnings += _plausibility(body, o, rotor)
    _check_scale(rotor, o)
    crits, missing = W.critical_speeds(rotor, o.orders)
    rng = tuple(float(x) for x in o.speed_range or _default_range(rotor, crits, o.speed))
    speeds = np.linspace(rng[0], rng[1], o.points)
    if o.speed is not None:  # the operating speeds are points of the grid
        speeds = _ascending(np.concatenate([speeds, [s for s in o.speed if rng[0] <= s <= rng[1]]]))
    cb = W.campbell(rotor, speeds)
    ranks = W.track(cb)
    forcing = W.Forcing(unb.static, unb.couple) if o.unbalance is None else \
        W.Forcing.from_planes(rotor.z_com, list(o.unbalance))
    top = max([rng[1], *(o.speed or ())])
    if not math.isfinite(top * top * (abs(forcing.static) + abs(forcing.couple))):
        what = "the body's unbalance" if o.unbalance is None else "{unbalance}, {unbalance_planes}"
        raise InputError(f"{what}: the unbalance force at {top:.6g} rad/s, or its moment, overflows "
                         "double precision (beyond 1e308); give values of a physical size")
    crit_rows = _criticals(rotor, crits, forcing, rng)
    stab = _stability(rotor, cb, ranks, o.speed)
    if not stab.stable_in_range or stab.stable_at_speed is False:
        warnings.append(_unstable_note(stab))
    response = _response(rotor, forcing, speeds, o, crit_rows, warnings)
    margins = _margins(o.speed, response.peaks, rotor.damped, forcing, warnings)
    modes_speed = o.speed[-1] if o.speed is not None else rotor.speed_span()[0]
    at = rotor.at(modes_speed).bearings
    return WhirlResult(
        name=body.name, conventions=dict(CONVENTIONS), shaft=shaft, shaft_source=_SOURCE[shaft_from],
        through=through, through_source=_SOURCE[through_from], rotor=rdata,
        bearings=tuple(BearingData(
            plane=b.z, stiffness=(b.kxx, b.kyy), cross_stiffness=(b.kxy, b.kyx), damping=(b.cxx, b.cyy),
            name=name, cross_damping=(b.cxy, b.cyx),
            table=BearingTableData(readonly(t.speeds), *(readonly(c) for c in t.values.T), src)
            if isinstance(t, W.BearingTable) else None)
            for b, t, name, src in zip(at, rotor.bearings, names, sources)),
        speed_range=rng, speed_range_source=o.source("speed_range"),
        orders=o.orders, speed=None if o.speed is None else (o.speed[0], o.speed[-1]),
        symmetry_tol=o.symmetry_tol, modes_speed=float(modes_speed),
        modes=tuple(_mode_row(m, rotor) for m in W.modes_at(rotor, modes_speed)),
        campbell=_campbell(cb, ranks), critical_speeds=tuple(crit_rows),
        no_crossings=tuple(NoCrossing(m.order, m.whirl, m.kind, m.reason, m.Ip, m.It,
                                      None if m.reason != "range" else (m.lo, m.hi)) for m in missing),
        stability=stab, response=response, margins=margins, warnings=tuple(warnings),
        critical_speed_map=_map(rotor, o, rng), units=dict(body.units or {}), source=str(body.source),
        isotropic=rotor.isotropic, options=o.replace(speed_range=rng))


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


def _unstable_note(st: Stability) -> str:
    where = ""
    if st.unstable_from_start:
        where = "; a mode grows from the start of the speed range"
    elif st.threshold_speed is not None:
        where = f"; the threshold of instability is {st.threshold_speed:.6g} rad/s"
    at = " AT THE OPERATING SPEED {speed}" if st.stable_at_speed is False else ""
    return Note(f"UNSTABLE{at}: a whirl mode grows (damping ratio down to "
                f"{st.least_damping_ratio:.3g} at {st.least_damping_speed:.6g} rad/s{where}); "
                "the cross-coupled stiffness feeds it more than the damping takes out")


def _plausibility(body: Body, o: Options, rotor) -> list[str]:
    """Bearings or unbalance planes more than 10 body sizes from the com (a unit missing?)."""
    u = op.Units.of(body)
    size = body_scale(body.parts).size
    out = []
    far = max(abs(b.z - rotor.z_com) for b in rotor.bearings)
    if far > FAR * size:
        out.append(u.far("bearings", "a bearing", far, size))
    if o.unbalance is not None:
        far = max(abs(z - rotor.z_com) for z, _ in o.unbalance)
        if far > FAR * size:
            out.append(u.far("unbalance_planes", "an unbalance plane", far, size))
    return out


@function(WHIRL)
def whirl(body: Body, **kwargs: Any) -> WhirlResult:
    """The rigid rotor on linear bearings: Campbell diagram, critical speeds, stability,
    unbalance response and API separation margins.

    Values are SI numbers or strings as typed on the command line (``"0,400 mm"``,
    ``"0,6000 rpm"``, ``"2e7 N/m"``), read by the rules of ``rbcli whirl``.

    Parameters
    ----------
    body : Body
    {parameters}

    Returns
    -------
    WhirlResult
        ``return_code`` 1 when ``speed`` fails the separation margin or a mode grows there.

    Raises
    ------
    TypeError, rbcli.InputError
        A wrong type (:mod:`rbcli.api.check`) or value, naming the parameter; a rotor the
        model does not fit.

    Examples
    --------
    >>> import rbcli
    >>> body = rbcli.load_text("{shape: cylinder, radius: 0.1, length: 0.6, mass: 50}")
    >>> r = rbcli.whirl(body, bearings="-0.2,0.2", stiffness=1e6)
    >>> [round(c.speed, 3) for c in r.critical_speeds]
    [200.0, 200.0, 206.559, 241.209]"""
    return run(body, parse(body, **kwargs))
