"""The numbers of a polar balancing diagram (``balance --plot``; field balancing draws its
own, :mod:`rbcli.render.field.plot`).

A diagram is a few panels, each a clock face of the rotor with arrows on it: a vector's
magnitude (SI) and its angle as the command prints it. :meth:`rbcli.api.balance.BalanceResult.diagram`
builds them; :mod:`rbcli.render.balanceplot` only draws them.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Arrow", "Panel", "Diagram"]


@dataclass(frozen=True)
class Arrow:
    """One vector of a diagram: ``role`` ("initial", "correction", "residual", "trial", "run",
    "effect": how it is drawn), ``label``, ``magnitude`` (SI, or the reading's unit),
    ``angle_deg`` (as printed, [0, 360)), ``defined`` (False: zero, not drawn), ``mass`` (kg,
    for a correction or trial) and ``tail`` ((magnitude, angle_deg) it starts at; None: the
    centre)."""

    role: str
    label: str
    magnitude: float
    angle_deg: float
    defined: bool = True
    mass: float | None = None
    tail: tuple[float, float] | None = None


@dataclass(frozen=True)
class Panel:
    """One clock face.

    Attributes
    ----------
    title : str
    quantity : str — "unbalance" (kg m), "couple" (kg m²), "mass" (kg) or "reading"
    arrows : tuple of Arrow
    """

    title: str
    quantity: str
    arrows: tuple[Arrow, ...]


@dataclass(frozen=True)
class Diagram:
    """A polar balancing diagram: ``title``, ``panels``, ``angle_sense`` ("with": drawn
    counterclockwise; "against": clockwise, so each vector sits where it is on the rotor),
    ``note`` (the convention, for the foot) and ``reading_kind`` (None: relative)."""

    title: str
    panels: tuple[Panel, ...]
    angle_sense: str
    note: str
    reading_kind: str | None = None
