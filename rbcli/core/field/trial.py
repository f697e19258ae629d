"""The trial mass to start with (sheet §5.1).

:func:`suggest_trial`: a trial whose centrifugal force ``m r omega^2`` is a fraction f
(default 10 %) of the static load on the bearing nearest its plane, ``m_T = f F / (r
omega^2)`` (physics/balance.md §5.1; the shop rule is 5-10 %; ACOEM's "Balancing How To #2"
asks the trial to change a reading by 30 % or 30 degrees).
"""

from __future__ import annotations

from dataclasses import dataclass

from rbcli.core.balance.common import BalanceValueError, finite, positive

#: the default fraction of the nearest bearing's static load a trial's force should be
TRIAL_FRACTION = 0.10
#: fractions a user may ask for (a trial that loads a bearing by more than a third of its
#: static load is a risk, not a measurement)
TRIAL_FRACTION_RANGE = (0.01, 0.30)


@dataclass(frozen=True)
class TrialSuggestion:
    """A trial mass (kg) at ``radius`` (m) and ``speed`` (rad/s) whose force ``m r w²`` (N) is
    ``fraction`` of the static ``bearing_load`` (N) on the bearing nearest its plane."""

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
    """``m_T = fraction F / (r omega^2)``: a trial at ``radius`` (m) whose force at ``speed``
    (rad/s) is ``fraction`` (0.01 to 0.30) of ``bearing_load`` (N)."""
    F = positive(bearing_load, "bearing load", "bearing_load")
    r = positive(radius, "trial radius", "trial_radius")
    w = positive(speed, "speed", "speed")
    f = finite(fraction, "fraction", "trial_fraction")
    lo, hi = TRIAL_FRACTION_RANGE
    if not lo <= f <= hi:
        raise BalanceValueError("trial_fraction", f"the fraction must be from {lo:g} to {hi:g} (1 % to 30 %), got {f:g}")
    m = f * F / (r * w * w)
    return TrialSuggestion(mass=m, radius=r, speed=w, bearing_load=F, fraction=f, force=m * r * w * w)
