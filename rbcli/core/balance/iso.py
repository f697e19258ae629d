"""ISO 21940-11 balance quality grades: permissible unbalance, allocation, pass/fail (sheet §1)."""

from __future__ import annotations

import math
from dataclasses import dataclass

from rbcli.core.balance.common import (
    ISO_CLAMP, ISO_GRADE_MAX, ISO_GRADE_MIN, ISO_OUTBOARD_FLOOR, BalanceValueError, finite, pair,
    positive,
)
from rbcli.core.balance.corrections import Corrections
from rbcli.core.balance.frame import Unbalance, plane_unbalances


def permissible_unbalance(grade: float, speed: float, mass: float) -> tuple[float, float]:
    """ISO 21940-11 permissible residual unbalance (e_per m, U_per kg m) of grade G (mm/s,
    0.4 to 4000) at speed Omega (rad/s) for mass M (kg): ``e_per = G / Omega`` (G in m/s),
    ``U_per = e_per M`` (sheet §1.2; shop form U_per[g mm] = 9549.2966 G M[kg] / n[rpm])."""
    G = finite(grade, "grade")
    if not ISO_GRADE_MIN <= G <= ISO_GRADE_MAX:
        raise BalanceValueError(
            "grade",
            f"balance grade must be between G {ISO_GRADE_MIN:g} and G {ISO_GRADE_MAX:g} "
            f"(mm/s), got {G:g}"
        )
    W = positive(speed, "speed")
    M = positive(mass, "mass")
    e = G * 1e-3 / W
    return e, e * M


def achieved_grade(residual_unbalance: float, mass: float, speed: float) -> float:
    """Achieved balance grade (mm/s) of a residual unbalance (kg m) for mass (kg) at speed
    (rad/s): ``G = |U| / M * Omega`` (sheet §1.2)."""
    U = abs(finite(residual_unbalance, "unbalance", "residual_unbalance"))
    return U / positive(mass, "mass") * abs(finite(speed, "speed")) * 1e3


@dataclass(frozen=True)
class Allocation:
    """Allocation of U_per to two tolerance planes (sheet §1.4).

    Attributes
    ----------
    allowed : (float, float) — kg m, U_per share of each plane (in the order given)
    unclamped : (float, float) — kg m, before the clamp/floor
    kind : str — "inboard" (com between the planes, inclusive) or "outboard"
    rule : str — the rule, in words
    rbcli_rule : bool — True for the outboard rule (derived by rbcli, not from the ISO text)
    """

    allowed: tuple[float, float]
    unclamped: tuple[float, float]
    kind: str
    rule: str
    rbcli_rule: bool

def allocate_permissible(
    u_per: float,
    com_z: float,
    planes: object,
    *,
    clamp: tuple[float, float] = ISO_CLAMP,
    outboard_floor: float = ISO_OUTBOARD_FLOOR,
) -> Allocation:
    """Split U_per (any unit) between two tolerance planes (z_1, z_2) by the lever rule on the com
    at ``com_z`` (sheet §1.4): an Allocation.

    Inboard (ISO 21940-11): ``U_1 = U_per L_2/L``, ``U_2 = U_per L_1/L`` (L_i = |z_G - z_i|),
    each clamped to ``clamp`` (0.3, 0.7) U_per. Outboard (§1.4c, rbcli's own rule):
    ``U_near = U_per L_far/L``, ``U_far = U_per L_near/L``, the far share floored at
    ``outboard_floor`` U_per."""
    Up = finite(u_per, "permissible unbalance", "u_per")
    zg = finite(com_z, "com position", "com_z")
    z1, z2 = pair(planes, "tolerance planes", "planes")
    if z1 == z2:
        raise BalanceValueError("planes", "the two tolerance planes must be at different positions")
    lo, hi = clamp
    L = abs(z2 - z1)
    L1, L2 = abs(zg - z1), abs(z2 - zg)
    if min(z1, z2) <= zg <= max(z1, z2):
        raw = (Up * L2 / L, Up * L1 / L)
        allowed = tuple(min(max(v, lo * Up), hi * Up) for v in raw)
        rule = (
            f"ISO 21940-11 lever rule on the com position between the planes, each share clamped "
            f"to {lo:g}..{hi:g} of U_per"
        )
        return Allocation((allowed[0], allowed[1]), raw, "inboard", rule, False)
    # the same lever rule; only the far share (the smaller one) gets a floor
    raw = (Up * L2 / L, Up * L1 / L)
    if L1 <= L2:  # plane 1 is the near one
        allowed2 = (raw[0], max(raw[1], outboard_floor * Up))
    else:
        allowed2 = (max(raw[0], outboard_floor * Up), raw[1])
    rule = (
        "rbcli's own rule for outboard rotors (the ISO clause was not available): each plane "
        "gets the load U_per at the com would put on it (lever rule), the far plane's share "
        f"floored at {outboard_floor:g} of U_per"
    )
    return Allocation(allowed2, raw, "outboard", rule, True)


@dataclass(frozen=True)
class IsoState:
    """ISO evaluation of one state of the rotor (before or after correction).

    Attributes
    ----------
    residual : (complex, complex) — kg m, exact equivalent unbalance in each tolerance plane
    ratio : (float, float) — |residual_i| / allowed_i
    achieved_grade : (float, float) — mm/s, G |U_i| / U_per,i
    static_unbalance : float — kg m, |U| of this state
    static_achieved_grade : float — mm/s, |U|/M Omega
    passed : bool — both ratios <= 1
    """

    residual: tuple[complex, complex]
    ratio: tuple[float, float]
    achieved_grade: tuple[float, float]
    static_unbalance: float
    static_achieved_grade: float
    passed: bool

@dataclass(frozen=True, eq=False)
class IsoCheck:
    """ISO 21940-11 check of a rotor (sheet §1.5).

    Attributes
    ----------
    grade, speed, mass — mm/s, rad/s (maximum service speed), kg (the uncorrected rotor)
    permissible_eccentricity, permissible_unbalance — e_per (m), U_per (kg m)
    planes, planes_are — the tolerance planes (m): "bearing" or "correction"
    allocation : Allocation
    before : IsoState — the rotor as given: what ``passed`` judges
    after, after_state — the prediction with the corrections added, never the verdict
    passed : bool — ``before.passed``
    tol_plane : float — kg m, for the angle flags
    angle_sense : str; warnings : tuple of str"""

    grade: float
    speed: float
    mass: float
    permissible_eccentricity: float
    permissible_unbalance: float
    planes: tuple[float, float]
    planes_are: str
    allocation: Allocation
    before: IsoState
    after: IsoState | None
    after_state: str | None
    passed: bool
    tol_plane: float
    angle_sense: str
    warnings: tuple[str, ...]

def _iso_state(
    U: complex,
    P: complex,
    M: float,
    planes: tuple[float, float],
    alloc: Allocation,
    G: float,
    W: float,
) -> IsoState:
    u1, u2 = plane_unbalances(U, P, *planes)
    res = (u1, u2)
    ratio = tuple(
        abs(u) / a if a > 0 else (0.0 if abs(u) == 0 else math.inf)
        for u, a in zip(res, alloc.allowed)
    )
    ach = tuple(G * r for r in ratio)
    return IsoState(
        residual=res,
        ratio=(ratio[0], ratio[1]),
        achieved_grade=(ach[0], ach[1]),
        static_unbalance=abs(U),
        static_achieved_grade=achieved_grade(abs(U), M, W),
        passed=all(r <= 1.0 for r in ratio),
    )


def iso_check(
    unb: Unbalance,
    grade: float,
    speed: float,
    planes: object,
    *,
    planes_are: str = "bearing",
    corrections: Corrections | None = None,
    clamp: tuple[float, float] = ISO_CLAMP,
    outboard_floor: float = ISO_OUTBOARD_FLOOR,
) -> IsoCheck:
    """ISO 21940-11 pass/fail of a rotor with exact residuals in two tolerance planes.

    ``unb`` the Unbalance, ``grade`` G (mm/s, 0.4 to 4000), ``speed`` (rad/s, > 0), ``planes``
    (z_1, z_2) m: the bearings, or with ``planes_are="correction"`` the correction planes
    (§1.4b); ``corrections`` adds the prediction ``after``; ``clamp``, ``outboard_floor`` as
    :func:`allocate_permissible`. An :class:`IsoCheck`.

    Notes
    -----
    Sheet §1.5: U_per = e_per M; the residual in each plane ``U_1 = (z_2 U - P)/(z_2 - z_1)``,
    ``U_2 = (P - z_1 U)/(z_2 - z_1)``; PASS iff both |U_i| <= U_per,i. Achieved grade
    ``G |U_i| / U_per,i``; whole-rotor static ``|U|/M Omega``."""
    if planes_are not in ("bearing", "correction"):
        raise BalanceValueError("planes_are", "planes_are must be 'bearing' or 'correction'")
    e_per, U_per = permissible_unbalance(grade, speed, unb.mass)
    G = float(grade)
    W = float(speed)
    z1, z2 = pair(planes, "tolerance planes", "planes")
    if z1 == z2:
        raise BalanceValueError("planes", "the two tolerance planes must be at different positions")
    alloc = allocate_permissible(
        U_per, float(unb.com_shaft[2]), (z1, z2), clamp=clamp, outboard_floor=outboard_floor
    )
    before = _iso_state(unb.static, unb.moment, unb.mass, (z1, z2), alloc, G, W)
    after = None
    after_state = None
    if corrections is not None:
        src = corrections.source
        if (src.mass, src.static, src.moment) != (unb.mass, unb.static, unb.moment):
            raise BalanceValueError("corrections", "the corrections were computed for another rotor")
        r = corrections.residual
        after = _iso_state(r.static, r.moment, r.mass, (z1, z2), alloc, G, W)
        after_state = "after rounded corrections" if corrections.rounded else "after corrections"
    warns = []
    if alloc.rbcli_rule:
        warns.append("the com lies outside the tolerance planes: allocation uses " + alloc.rule)
    return IsoCheck(
        grade=G,
        speed=W,
        mass=unb.mass,
        permissible_eccentricity=e_per,
        permissible_unbalance=U_per,
        planes=(z1, z2),
        planes_are=planes_are,
        allocation=alloc,
        before=before,
        after=after,
        after_state=after_state,
        passed=before.passed,
        tol_plane=unb.plane_tolerance(z1, z2),
        angle_sense=unb.angle_sense,
        warnings=tuple(warns),
    )
