"""The numbers of a polar balancing diagram (``balance --plot``, ``field-balance --plot``).

A diagram is a few panels, each a clock face of the rotor with arrows on it: a vector's
magnitude (SI) and its angle as the command prints it. The results build them
(:meth:`rbcli.api.balance.BalanceResult.diagram`,
:meth:`rbcli.api.field.service.FieldBalanceResult.diagram`); :mod:`rbcli.render.balanceplot`
only draws them.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Arrow", "Panel", "Diagram"]


@dataclass(frozen=True)
class Arrow:
    """One vector of a diagram.

    Attributes
    ----------
    role : str — what it is, which sets how it is drawn: "initial" (the unbalance or
        reading as given), "correction" (a mass to add), "residual" (what is left),
        "trial" (a trial mass), "run" (a reading with a trial on), "effect" (the change a
        trial made: from the tip of the initial reading to the tip of the run's)
    label : str — e.g. "A: correction"
    magnitude : float — SI (kg m for an unbalance, kg m² for a couple, kg for a mass, the
        reading's unit for a reading)
    angle_deg : float — deg, as the command prints it ([0, 360))
    defined : bool — False for a quantity zero to its tolerance (no direction; not drawn)
    mass : float | None — kg, the mass a correction or trial arrow stands for
    tail : (float, float) | None — (magnitude, angle_deg) the arrow starts at; None: the
        centre
    """

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
    """A polar balancing diagram.

    Attributes
    ----------
    title : str
    panels : tuple of Panel
    angle_sense : str — "with" (angles counted in the direction of rotation, drawn
        counterclockwise: the rotor seen with its rotation counterclockwise) or "against"
        (drawn clockwise, so every vector still sits where it is on the rotor)
    note : str — the convention in words, for the figure's foot
    reading_kind : str | None — the readings' kind (field balancing), None: relative
    """

    title: str
    panels: tuple[Panel, ...]
    angle_sense: str
    note: str
    reading_kind: str | None = None
