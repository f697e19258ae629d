"""Where a rolling body's rim is: the parts that can make a rim and the rim circle's
offset along the axle from the centre of mass (``rollcheck``, issue 14.3).

A rim circle off the plane of the centre of mass (across the axle, through it) makes
upright rolling no equilibrium: the centre of mass is to the side of the contact point.
:func:`rim_offset` measures that offset from the shapes that make the rim.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np


def fmt_length(d: float) -> str:
    """A length for a message: |d| in m, mm or µm to three significant figures."""
    d = abs(float(d))
    if d >= 1.0:
        return f"{d:.3g} m"
    if d >= 1e-3:
        return f"{d * 1e3:.3g} mm"
    if d >= 1e-6:
        return f"{d * 1e6:.3g} µm"
    return f"{d:.3g} m"


#: shapes whose outer radius (``Part.radius``) can be a rim: round about their own axis.
#: NOTE (issue 12.5): "is it round" and where its rim circle lies (:func:`rim_circle_centre`)
#: are shape facts that belong in the shape registry (``core/shapes.py``); listed here until
#: the registry carries them.
ROUND_SHAPES = ("disk", "ring", "cylinder", "sphere", "hemisphere", "cone", "torus")

#: straight upright rolling is analysed only when the rim circle lies within this fraction
#: of the rim radius of the plane of the centre of mass (through it, across the axle). A
#: rim offset d makes upright rolling no equilibrium: the centre of mass is d to the side
#: of the contact point, so gravity tips the body or steers it into a curve; the centre of
#: mass comes over the rim only at a lean of atan(d / a) (0.57° at the limit).
RIM_OFFSET_LIMIT = 0.01


def rim_candidates(parts: Any, axle: Any, through: Any, tol: float = 1e-6) -> list[Any]:
    """The parts that can make a rim for this axle: round (:data:`ROUND_SHAPES`), not
    subtracted, coaxial with the axle (any orientation for a sphere) and centred on the
    axle line (to 1e-6 of their radius). ``parts`` are :class:`rbcli.model.Part`; ``axle``
    a unit vector and ``through`` a point of the axle line (m), body frame. ``tol`` (the
    ``--symmetry-tol`` of a nearly symmetric wheel, a fraction) loosens both tests: a part
    tilted from the axle by an angle whose sine is at most ``tol``, or centred off it by
    at most ``tol`` of its radius, is still a rim (a CAD wheel tilted 0.005° on its axle)."""
    n = np.asarray(axle, dtype=float)
    P = np.asarray(through, dtype=float)
    out = []
    for p in parts:
        if p.subtract or p.radius is None or p.shape not in ROUND_SHAPES:
            continue
        if (p.shape != "sphere" and abs(abs(float(np.dot(p.axis, n))) - 1.0) > 1e-9
                and float(np.linalg.norm(np.cross(p.axis, n))) > tol):
            continue  # round about another axis: not a rim for this axle
        d = np.asarray(p.com, dtype=float) - P
        if float(np.linalg.norm(d - np.dot(d, n) * n)) > max(tol, 1e-6) * p.radius:
            continue  # not centred on the axle line
        out.append(p)
    return out


def rim_circle_centre(part: Any) -> np.ndarray:
    """Centre (m, body frame) of the circle of radius ``part.radius`` on which a round part
    touches the floor when it rolls on its outer rim.

    disk, ring, sphere (its equator), torus (its outer equator): the plane of the part's
    centre of mass; cylinder: the mid-plane of its two end circles, which is its centre
    (the model's idealisation of a square edge, as a thick coin); hemisphere: its flat
    face, 3R/8 from the centre of mass towards the face; cone: its base circle, h/4 from
    the centre of mass towards the base, with h = 3 V / (pi R^2) from the part's volume.
    (The hemisphere and cone centres and volumes are those of :mod:`rbcli.core.shapes`.)
    """
    com = np.asarray(part.com, dtype=float)
    n = np.asarray(part.axis, dtype=float)
    n = n / np.linalg.norm(n)
    R = float(part.radius)
    if part.shape == "hemisphere":  # dome towards local +z, flat face at local z = 0
        return com - (3.0 * R / 8.0) * n
    if part.shape == "cone":  # apex towards local +z, base at local z = 0
        h = 3.0 * float(part.measure) / (math.pi * R * R)
        return com - (h / 4.0) * n
    return com


@dataclass(frozen=True)
class RimOffset:
    """Where the rim circle lies along the axle, measured from the parts that make it.

    Attributes
    ----------
    offset : float — m, signed distance along the axle from the centre of mass to the
        rim circle's plane (the mid-plane of the outermost rim circles when several parts
        make the rim)
    radius : float — m, the rim radius a
    parts : tuple of (name, shape) — the parts whose outer radius is the rim
    """

    offset: float
    radius: float
    parts: tuple[tuple[str, str], ...]

    @property
    def fraction(self) -> float:
        """|offset| / radius."""
        return abs(self.offset) / self.radius

    @property
    def upright_equilibrium(self) -> bool:
        """The offset is within :data:`RIM_OFFSET_LIMIT` of the radius: rolling upright is
        (to that approximation) an equilibrium and the model applies."""
        return self.fraction <= RIM_OFFSET_LIMIT

    def describe(self) -> str:
        """'the rim circle of part 'disk' (disk) is 10 mm from the centre of mass along the
        axle (12.5 % of the rim radius 80 mm)'."""
        names = ", ".join(f"'{n}' ({s})" for n, s in self.parts)
        what = (f"the rim circle of part {names}" if len(self.parts) == 1
                else f"the mid-plane of the rim circles of parts {names}")
        return (f"{what} is {fmt_length(self.offset)} from the centre of mass "
                f"along the axle ({100.0 * self.fraction:.3g} % of the rim radius "
                f"{fmt_length(self.radius)})")


def rim_offset(parts: Any, com: Any, axle: Any, through: Any, radius: float,
               rtol: float = 1e-9, tol: float = 1e-6) -> RimOffset | None:
    """The rim circle's offset along the axle from the centre of mass ``com`` (m).

    The rim is made by the :func:`rim_candidates` whose outer radius is ``radius`` (to
    ``rtol``; ``tol`` as for :func:`rim_candidates`); each touches the floor on the circle of :func:`rim_circle_centre`. Several
    such parts in different planes (two wheels on an axle) give the mid-plane of the
    outermost circles. None when no part has that radius (a rim radius given as a number
    for a body whose rim is not a round part: nothing to measure).
    """
    n = np.asarray(axle, dtype=float)
    G = np.asarray(com, dtype=float)
    rim = [p for p in rim_candidates(parts, n, through, tol) if abs(p.radius - radius) <= rtol * radius]
    if not rim:
        return None
    z = [float(np.dot(rim_circle_centre(p) - G, n)) for p in rim]
    return RimOffset(offset=0.5 * (min(z) + max(z)), radius=float(radius),
                     parts=tuple((p.name, p.shape) for p in rim))
