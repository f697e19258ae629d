"""What ``inertia`` and ``principal`` share: the point an inertia is taken about
(:class:`Reference`, :func:`inertia_at`), the warnings of a point far outside the body
(:func:`plausibility`), the parts' rows of the JSON (:func:`part_rows`, :func:`with_parts`)
and round-off snapped to zero (:func:`snap`).

Sign convention: the inertia tensor is the tensor, ``J = ∫ (r·r E − r rᵀ) dm``; its
off-diagonal entries are the negated products of inertia (``Jxy = −∫ x y dm``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from rbcli.api import options as o
from rbcli.api.check import Point
from rbcli.api.result import jsonable
from rbcli.core.inertia import InputOverflow, body_mass_props, checked_inertia_about
from rbcli.core.scale import SPEED_OF_SOUND, axis_reach, body_scale
from rbcli.errors import Note, ParamError

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.model import Body

__all__ = ["Reference", "part_rows", "plausibility", "snap", "with_parts", "inertia_at"]


@dataclass(frozen=True)
class Reference:
    """The point an inertia is taken about, as the user gave it (resolved once).

    Attributes
    ----------
    point : tuple of 3 floats, or None
        m, body frame; None means the body's centre of mass (known only once the parts are
        combined).
    label : str
        How tables name it: ``"the com"``, ``"the origin"``, ``"the body's reference
        point"`` or ``"[x,y,z]"`` (the text as given).
    param : str
        The parameter at fault if the point is impossible to compute with: ``"about"``
        (given) or ``"body_reference"`` (the body's default).
    """

    point: tuple[float, float, float] | None
    label: str
    param: str

    @classmethod
    def parse(cls, body: Body | None, about: Point | None, *, default: str = "body") -> Reference:
        """``about`` (``"com"``, ``"origin"``, ``"x,y,z"`` or a sequence, m), else the
        default: ``"body"`` = the body's ``reference`` (``com``, a point), else the
        origin; ``"com"`` = the com. ``body`` None (values checked before a body is read):
        the origin."""
        if about is not None:
            u = o.Units.of(body)
            p = u.point(about, "about")
            if p == "com":
                return cls(None, "the com", "about")
            if p == "origin":
                return cls((0.0, 0.0, 0.0), "the origin", "about")
            if isinstance(about, str):
                text = about
                if o.is_bare(about) and body is not None:
                    text = f"{about} {u.label('length')}"  # a bare point: say its unit
            else:
                text = ", ".join(str(x) for x in _items(about))
            return cls(tuple(float(x) for x in p), f"[{text}]", "about")  # type: ignore[arg-type]
        if default == "com" or (body is not None and body.reference_is_com):
            return cls(None, "the com", "body_reference")
        if body is not None and body.reference is not None:
            return cls(tuple(float(x) for x in body.reference), "the body's reference point",  # type: ignore[arg-type]
                       "body_reference")
        return cls((0.0, 0.0, 0.0), "the origin", "body_reference")

    @property
    def as_given(self) -> str | tuple[float, float, float] | None:
        """``"com"``, ``"origin"`` or the point (m) when given as ``about``, else None."""
        if self.param != "about":
            return None
        if self.point is None:
            return "com"
        return "origin" if self.label == "the origin" else self.point

    def resolve(self, mp: Any) -> Any:
        """The point as a (3,) ndarray, m, given the body's mass properties ``mp``."""
        return mp.com.copy() if self.point is None else np.array(self.point, dtype=float)


def _items(v: Any) -> list:
    return v.tolist() if hasattr(v, "tolist") else list(v)


def snap(values: Any, scale: float | None = None, rtol: float = 1e-14) -> Any:
    """``values`` as a float ndarray (a copy) with entries below ``rtol`` times the largest
    magnitude (or ``scale``) set to exactly 0 (round-off, e.g. a product of inertia of 1e-18
    next to moments of 1): what JSON and tables show. No negative zeros."""
    a = np.array(values, dtype=float)
    mag = np.abs(a)
    a[mag <= rtol * (float(mag.max()) if scale is None else scale)] = 0.0
    a[a == 0.0] = 0.0
    return a


def part_rows(body: Any) -> tuple[dict, ...]:
    """Each part's contribution, as in JSON: name, shape, mass (kg; negative for a subtracted
    part), com (m), ``subtract: true`` for a hole, and for a mesh part its volume (m³), area
    (m²) and triangles."""
    rows = []
    for p in body.parts:
        if p.subtract:
            row: dict = {"name": p.name, "shape": p.shape, "mass": -p.mass, "com": p.com, "subtract": True}
        else:
            row = {"name": p.name, "shape": p.shape, "mass": p.mass, "com": p.com}
        if p.extra:
            for key in ("volume", "area", "triangles"):
                if key in p.extra:
                    row[key] = p.extra[key]
        rows.append(row)
    return tuple(rows)


def with_parts(out: dict, parts: tuple[dict, ...]) -> dict:
    """``out`` and the parts' rows as JSON (checked finite by :func:`jsonable`)."""
    return jsonable({**out, "parts": list(parts)})


def inertia_at(mp: Any, ref: Reference) -> tuple[Any, Any]:
    """(point, inertia tensor about it): core's overflow blamed on the right parameter."""
    point = ref.resolve(mp)
    try:
        return point, checked_inertia_about(mp, point)
    except InputOverflow as exc:
        raise ParamError(ref.param, str(exc)) from None


def plausibility(body: Any, u: o.Units, ref: Reference, omega: Any = None) -> tuple[str, ...]:
    """One-line warnings for values far outside the body's scale (issue 13): a reference
    point more than 10 body sizes away, a rotation whose rim is faster than sound."""
    if body is None:
        return ()
    far_point = ref.param == "about" and ref.point is not None
    if not far_point and omega is None:
        return ()
    sc = body_scale(body.parts)
    out = []
    if far_point:
        d = sc.far(ref.point)
        if d is not None:
            out.append(u.far("about", "the point", d, sc.size))
    w = 0.0 if omega is None else math.sqrt(sum(x * x for x in omega))
    if 0.0 < w < math.inf:
        # the body turning about omega through the reference point: its farthest material
        through = body_mass_props(body).com if ref.point is None else ref.point
        v = w * axis_reach(body.parts, omega, through)
        if SPEED_OF_SOUND < v < math.inf:
            out.append(Note(f"{{omega}}: the body's rim would move at {v:.4g} m/s, faster than "
                            f"sound ({SPEED_OF_SOUND:g} m/s); bare angular speeds are in "
                            f"{u.label('angular_speed')}: is a unit missing?"))
    return tuple(out)
