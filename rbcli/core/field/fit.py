"""Field corrections as they are fitted (sheet §2.5): rounded as ``rbcli balance`` rounds
(half up to a multiple of the step) or split onto the two neighbouring of n equally spaced
positions (:func:`rbcli.core.balance.corrections.split_to_positions`, sheet §2.5, T22), with
the net correction those masses make. (A drawer's weights: :mod:`rbcli.core.field.drawer`.)
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

from rbcli.core.balance.common import BalanceValueError, finite, positive, wrap_deg
from rbcli.core.balance.corrections import split_to_positions

@dataclass(frozen=True)
class FittedMass:
    """One mass to fit: kg, deg [0, 360) and its 1-based position (or hole), if any."""

    mass: float
    angle_deg: float
    position: int | None = None


@dataclass(frozen=True)
class FittedPlane:
    """The masses fitted in one plane, their vector sum (kg e^{i angle}) and whether a step
    was applied."""

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
    """The masses to fit for ``correction`` (kg e^{i angle}): each mass rounded half up to a
    multiple of ``mass_step`` (kg), the angle to ``angle_step_deg`` (in (0, 360]; not with
    positions), or split onto the two of ``positions`` (>= 3, equally spaced, position 1 at
    ``offset_deg``) either side of it. A BalanceValueError names the step or positions at fault."""
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
