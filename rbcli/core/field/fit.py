"""Field corrections as they are fitted: weights from the drawer, holes and blades, and the
trial mass to start with (sheet §2.5, §5.1).

A computed correction ``W = m e^{i angle}`` is rarely fitted as computed: masses come in
steps (clip-on weights, washers), angles are marked to a few degrees, and on a fan the
mass goes onto blades or bolt holes. :func:`fit_plane` gives what is fitted — rounded as
``rbcli balance`` rounds (half up to a multiple of the step; angles in the reported sense)
or split onto the two neighbouring of n equally spaced positions with
:func:`rbcli.core.balance.corrections.split_to_positions` (sheet §2.5, T22) — and the net
correction those masses make, from which the caller predicts the residual readings.

:func:`suggest_trial` sizes a trial mass before the first run: its centrifugal force
``m r omega^2`` is a set fraction (default 10 %) of the static load on the bearing
nearest the trial plane, ``m_T = f F_bearing / (r omega^2)``. The rule is the one rbcli's
formula sheet records (physics/balance.md §5.1: "the trial's centrifugal force is about
10 % of the rotor weight (or bearing load), m_T = 0.1 M g/(r omega^2)"; 100 kg, r = 200 mm,
1500 rpm give 19.9 g), the common shop rule a fraction of 5-10 % of the bearing load;
ACOEM's "Balancing How To #2 - Selecting a Proper Trial Weight" states what the trial must
achieve (a change of 30 % in amplitude or 30 degrees in phase) and that the mass follows
from the rotor's weight and speed.
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

from rbcli.core.balance.common import BalanceValueError, finite, positive, wrap_deg
from rbcli.core.balance.corrections import split_to_positions

#: the default fraction of the nearest bearing's static load a trial's force should be
TRIAL_FRACTION = 0.10
#: fractions a user may ask for (a trial that loads a bearing by more than a third of its
#: static load is a risk, not a measurement)
TRIAL_FRACTION_RANGE = (0.01, 0.30)


@dataclass(frozen=True)
class FittedMass:
    """One mass to fit.

    Attributes
    ----------
    mass : float — kg (rounded when a step was asked)
    angle_deg : float — deg, [0, 360), in the sense of the correction's angles
    position : int | None — 1-based position number (position 1 at the offset angle) when
        split onto positions
    """

    mass: float
    angle_deg: float
    position: int | None = None


@dataclass(frozen=True)
class FittedPlane:
    """What is fitted in one plane, and the correction it makes.

    Attributes
    ----------
    masses : tuple of FittedMass — one (rounded) or two (split onto positions)
    net : complex — kg e^{i angle}: the vector sum of the masses (the correction fitted)
    rounded : bool — a mass or angle step was applied
    """

    masses: tuple[FittedMass, ...]
    net: complex
    rounded: bool


def round_half_up(x: float, step: float, param: str) -> float:
    """``x`` rounded half up to a multiple of ``step`` (the rule of
    :func:`rbcli.core.balance.corrections.round_corrections`)."""
    q = x / step + 0.5
    if not math.isfinite(q):
        raise BalanceValueError(param, f"the step {step:g} is too small to round {x:g} to a multiple of it")
    return math.floor(q) * step


def fit_plane(
    correction: complex,
    *,
    mass_step: float | None = None,
    angle_step_deg: float | None = None,
    positions: int | None = None,
    offset_deg: float = 0.0,
) -> FittedPlane:
    """The masses to fit for one plane's correction.

    Parameters
    ----------
    correction : complex — mass (kg) e^{i angle}, the computed correction
    mass_step : float, optional — kg, > 0: each mass rounded half up to a multiple
    angle_step_deg : float, optional — deg, in (0, 360]: the angle rounded to a multiple
        (not with ``positions``: the positions fix the angles)
    positions : int, optional — >= 3 equally spaced positions (holes, blades), position 1
        at ``offset_deg``: the correction split onto the two either side of it
    offset_deg : float — deg, the angle of position 1

    Returns
    -------
    FittedPlane

    Raises
    ------
    BalanceValueError
        a step <= 0 (``mass_step``, ``angle_step``), fewer than 3 positions
        (``positions``), an angle step with positions.
    """
    C = complex(correction)
    if mass_step is not None:
        mass_step = positive(mass_step, "mass step", "mass_step")
    if angle_step_deg is not None:
        angle_step_deg = positive(angle_step_deg, "angle step", "angle_step")
        if angle_step_deg > 360.0:
            raise BalanceValueError("angle_step", "angle step must not exceed 360 degrees")
    m = abs(C)
    a = wrap_deg(math.degrees(cmath.phase(C))) if m > 0.0 else 0.0
    if positions is not None:
        if angle_step_deg is not None:
            raise BalanceValueError("angle_step", "an angle step does not go with positions: the positions fix the angles")
        if int(positions) != positions or positions < 3:
            raise BalanceValueError("positions", "positions must be an integer >= 3")
        try:
            sp = split_to_positions(m, a, int(positions), finite(offset_deg, "offset", "offset_deg"))
        except BalanceValueError as exc:
            raise BalanceValueError("positions", str(exc)) from None
        out = []
        for mass, ang, k in zip(sp.masses, sp.angles_deg, sp.positions):
            if mass_step is not None:
                mass = round_half_up(mass, mass_step, "mass_step")
            out.append(FittedMass(mass, ang, k + 1))
        net = sum((complex(cmath.rect(f.mass, math.radians(f.angle_deg))) for f in out), 0j)
        return FittedPlane(tuple(out), net, mass_step is not None)
    if mass_step is not None:
        m = round_half_up(m, mass_step, "mass_step")
    if angle_step_deg is not None and abs(C) > 0.0:
        a = wrap_deg(round_half_up(a, angle_step_deg, "angle_step"))
    phi = math.radians(a) if abs(C) > 0.0 else 0.0
    net = complex(cmath.rect(m, phi)) if (mass_step is not None or angle_step_deg is not None) else C
    return FittedPlane((FittedMass(m, a),), net, mass_step is not None or angle_step_deg is not None)


# ----------------------------------------------------------------------------------------
# the trial mass
# ----------------------------------------------------------------------------------------


@dataclass(frozen=True)
class TrialSuggestion:
    """A trial mass sized before the first run.

    Attributes
    ----------
    mass : float — kg, at ``radius``
    radius : float — m
    speed : float — rad/s
    bearing_load : float — N, the static load on the bearing nearest the plane
    fraction : float — the trial's centrifugal force / ``bearing_load``
    force : float — N, ``mass radius speed^2`` = fraction x bearing_load
    """

    mass: float
    radius: float
    speed: float
    bearing_load: float
    fraction: float
    force: float


def static_bearing_loads(mass: float, g: float, z_com: float, bearings: tuple[float, float]) -> tuple[float, float]:
    """The gravity loads (N) on two bearings at ``bearings`` (shaft horizontal) of a rotor of
    ``mass`` kg with its com at ``z_com``: the lever rule, as
    :func:`rbcli.core.balance.bearings.bearing_forces` (negative: a hold-down)."""
    z1, z2 = bearings
    if z1 == z2:
        raise BalanceValueError("bearings", "the two bearings must be at different positions along the shaft")
    Mg = mass * g
    return Mg * (z2 - z_com) / (z2 - z1), Mg * (z_com - z1) / (z2 - z1)


def suggest_trial(bearing_load: float, radius: float, speed: float, fraction: float = TRIAL_FRACTION) -> TrialSuggestion:
    """The trial mass whose centrifugal force at ``speed`` is ``fraction`` of
    ``bearing_load``: ``m_T = fraction F / (r omega^2)`` (see the module notes).

    Parameters
    ----------
    bearing_load : float — N, > 0: the static load on the bearing nearest the trial plane
    radius : float — m, > 0: where the trial sits
    speed : float — rad/s, > 0: the balancing speed
    fraction : float — in [0.01, 0.30]

    Returns
    -------
    TrialSuggestion
    """
    F = positive(bearing_load, "bearing load", "bearing_load")
    r = positive(radius, "trial radius", "trial_radius")
    w = positive(speed, "speed", "speed")
    f = finite(fraction, "fraction", "trial_fraction")
    lo, hi = TRIAL_FRACTION_RANGE
    if not lo <= f <= hi:
        raise BalanceValueError("trial_fraction", f"the fraction must be from {lo:g} to {hi:g} (1 % to 30 %), got {f:g}")
    m = f * F / (r * w * w)
    return TrialSuggestion(mass=m, radius=r, speed=w, bearing_load=F, fraction=f, force=m * r * w * w)
