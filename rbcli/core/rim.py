"""What a rolling body's rim is and where it lies (``rollcheck``, issues 14.3 and 24).

The rim is made by the round parts coaxial with the axle whose outer radius is the rim
radius, each touching the floor as its :class:`rbcli.core.shapes.RimRule` says (a knife edge,
a torus, a sphere, a flat band). :func:`rim_of` gathers them into a :class:`Rim`: its kind,
tube radius (the largest: it reaches lowest) and where it lies along the axle (one plane or
a band; two wheels on an axle stand on both). A rim off the com's plane makes upright
rolling no equilibrium."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from rbcli.core.shapes import SHAPES


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


#: shapes whose outer radius (``Part.radius``) can be a rim: round about their own axis
#: (the registry's entries with a :class:`rbcli.core.shapes.RimRule`)
ROUND_SHAPES = tuple(name for name, info in SHAPES.items() if info.rim is not None)

#: straight upright rolling is analysed only when the centre of mass's plane (through it,
#: across the axle) is within this fraction of the rim radius of the rim: of its circle, or
#: inside its band. Off by d, upright rolling is no equilibrium: the centre of mass is d to
#: the side of the contact point, so gravity tips the body or steers it into a curve; it
#: comes over the rim only at a lean of atan(d / a) (0.57° at the limit).
RIM_OFFSET_LIMIT = 0.01


def rim_candidates(parts: Any, axle: Any, through: Any, tol: float = 1e-6) -> list[Any]:
    """The parts that can make a rim for this axle: round (:data:`ROUND_SHAPES`), not
    subtracted, coaxial with the axle (any orientation for a sphere) and centred on the
    axle line (to 1e-6 of their radius). ``parts`` are :class:`rbcli.body.partmodel.Part`; ``axle``
    a unit vector and ``through`` a point of the axle line (m), body frame. ``tol`` (a
    nearly symmetric wheel's ``symmetry_tol``) loosens both tests: a tilt whose sine, or an
    offset over the radius, is at most ``tol``."""
    n = np.asarray(axle, dtype=float)
    P = np.asarray(through, dtype=float)
    out = []
    for p in parts:
        if p.subtract or p.radius is None or p.shape not in ROUND_SHAPES:
            continue
        if (SHAPES[p.shape].round != "any" and abs(abs(float(np.dot(p.axis, n))) - 1.0) > 1e-9
                and float(np.linalg.norm(np.cross(p.axis, n))) > tol):
            continue  # round about another axis: not a rim for this axle
        d = np.asarray(p.com, dtype=float) - P
        if float(np.linalg.norm(d - np.dot(d, n) * n)) > max(tol, 1e-6) * p.radius:
            continue  # not centred on the axle line
        out.append(p)
    return out


def rim_circle_centre(part: Any) -> np.ndarray:
    """Centre (m, body frame) of the circle of radius ``part.radius`` on which a round part
    touches the floor when it rolls on its outer rim (the middle of a cylinder's band): the
    part's centre of mass moved along its axis by the registry's
    :attr:`rbcli.core.shapes.RimRule.plane_from_com`."""
    com = np.asarray(part.com, dtype=float)
    n = np.asarray(part.axis, dtype=float)
    n = n / np.linalg.norm(n)
    rule = SHAPES[part.shape].rim
    assert rule is not None
    return com + rule.plane_from_com(float(part.radius), part.measure) * n


def _params(part: Any) -> dict[str, Any] | None:
    """The part's checked shape parameters (its outline's), or None without one."""
    o = getattr(part, "outline", None)
    return dict(o.dims) if o is not None and o.kind == part.shape else None


def _tube_and_width(part: Any) -> tuple[float, float]:
    """The part's rim tube radius and band width (m) from the registry; without the
    part's parameters a sphere's tube is its radius and the others' are 0 (a knife edge)."""
    rule = SHAPES[part.shape].rim
    assert rule is not None
    params = _params(part)
    if params is None:
        return (float(part.radius) if rule.kind == "sphere" else 0.0), 0.0
    return float(rule.tube_radius(params)), float(rule.width(params))


@dataclass(frozen=True)
class Rim:
    """What the rim is and where it lies along the axle: ``offset`` (m, from the com to its
    middle), ``radius`` (m), ``parts`` ((name, shape)), ``kind`` (``"edge"``, ``"torus"``,
    ``"sphere"``, ``"band"``), ``tube_radius`` (m) and ``low``, ``high`` (m, the band's ends from
    the com; equal for one plane)."""

    offset: float
    radius: float
    parts: tuple[tuple[str, str], ...]
    kind: str = "edge"
    tube_radius: float = 0.0
    low: float = 0.0
    high: float = 0.0

    @property
    def width(self) -> float:
        """m, the band's width (0 for a rim in one plane)."""
        return self.high - self.low

    @property
    def outside(self) -> float:
        """m, how far the centre of mass's plane lies outside the rim's (its circle's plane, or
        the band): 0 when a band holds it."""
        if self.kind == "band":
            return max(self.low, -self.high, 0.0)
        return abs(self.offset)

    @property
    def edges(self) -> tuple[float, float]:
        """m, a band's edges' distances (>= 0) from the centre of mass's plane, one each side."""
        return max(-self.low, 0.0), max(self.high, 0.0)

    @property
    def fraction(self) -> float:
        """:attr:`outside` / radius."""
        return self.outside / self.radius

    @property
    def upright_equilibrium(self) -> bool:
        """The centre of mass's plane is within :data:`RIM_OFFSET_LIMIT` of the radius of the
        rim (inside its band): rolling upright is (to that approximation) an equilibrium and
        the model applies."""
        return self.fraction <= RIM_OFFSET_LIMIT

    def describe(self) -> str:
        """'the rim circle of part 'disk' (disk) is 10 mm from the centre of mass along the
        axle (12.5 % of the rim radius 80 mm)'; a band: 'the rim band of part 'can'
        (cylinder) ends 10 mm short of the centre of mass's plane along the axle (...)'."""
        names = ", ".join(f"'{n}' ({s})" for n, s in self.parts)
        pct = (f"({100.0 * self.fraction:.3g} % of the rim radius {fmt_length(self.radius)})")
        if self.kind == "band":
            what = (f"the rim band of part {names}" if len(self.parts) == 1
                    else f"the rim band of parts {names}")
            return (f"{what} ends {fmt_length(self.outside)} short of the centre of mass's plane "
                    f"along the axle {pct}")
        what = (f"the rim circle of part {names}" if len(self.parts) == 1
                else f"the mid-plane of the rim circles of parts {names}")
        return f"{what} is {fmt_length(self.offset)} from the centre of mass along the axle {pct}"


def rim_of(parts: Any, com: Any, axle: Any, through: Any, radius: float,
           rtol: float = 1e-9, tol: float = 1e-6) -> Rim | None:
    """The rim of radius ``radius`` about the axle, from the com: the :func:`rim_candidates`
    with that outer radius (to ``rtol``), a sphere if one is, else a band if they span a width,
    else a torus if one has a tube, else a knife edge. None when no part has that radius."""
    n = np.asarray(axle, dtype=float)
    G = np.asarray(com, dtype=float)
    a = float(radius)
    rim = [p for p in rim_candidates(parts, n, through, tol) if abs(p.radius - a) <= rtol * a]
    if not rim:
        return None
    z = [float(np.dot(rim_circle_centre(p) - G, n)) for p in rim]
    tw = [_tube_and_width(p) for p in rim]
    low = min(zi - 0.5 * w for zi, (_, w) in zip(z, tw))
    high = max(zi + 0.5 * w for zi, (_, w) in zip(z, tw))
    tube = max(t for t, _ in tw)
    names = tuple((p.name, p.shape) for p in rim)
    if any(SHAPES[p.shape].rim.kind == "sphere" for p in rim):  # type: ignore[union-attr]
        return Rim(offset=0.5 * (low + high), radius=a, parts=names, kind="sphere",
                   tube_radius=a, low=low, high=high)
    if high - low > 1e-9 * a:
        return Rim(offset=0.5 * (low + high), radius=a, parts=names, kind="band",
                   tube_radius=0.0, low=low, high=high)
    return Rim(offset=0.5 * (low + high), radius=a, parts=names,
               kind="torus" if tube > 0.0 else "edge", tube_radius=min(tube, a), low=low, high=high)
