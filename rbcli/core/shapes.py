"""Geometry of the primitive shapes: measure, centre of mass and inertia per unit mass.

Each shape lives in its LOCAL frame (symmetry axis local z). :func:`geometry` gives, in SI,
the *measure* a density multiplies (volume, area, length or 1), the com (the local origin
is the centroid but for ``hemisphere`` and ``cone``, the centre of the flat face or base,
and ``triangle``) and the inertia about the com per unit mass (m², tensor convention). Mass
and placement are the body's business. Formulas: Meriam & Kraige, *Engineering Mechanics:
Dynamics*, Appendix B; the catalogue :data:`SHAPES` prints them."""

from __future__ import annotations

import math
import numbers
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any, NamedTuple

import numpy as np

__all__ = ["ShapeError", "ShapeGeometry", "ShapeInfo", "Kind", "SHAPES", "IO_SHAPES", "geometry",
           "local_geometry", "builder"]


class ShapeError(ValueError):
    """A shape parameter is missing, unknown or impossible.

    Attributes
    ----------
    param : str — the parameter at fault (e.g. ``"inner_radius"``), for the io layer to
        point at the right line of the body file
    lengths : tuple[float, ...] — m, the lengths the message quotes at ``{0}``, ``{1}``...,
        which the io layer shows in the file's length unit (:meth:`format`)
    """

    def __init__(self, param: str, message: str, lengths: tuple[float, ...] = ()) -> None:
        self.param = param
        self.template = message
        self.lengths = tuple(lengths)
        self.message = self.format()
        super().__init__(self.message)

    def format(self, show=None) -> str:
        """The message with its lengths shown by ``show(metres) -> str`` (default ``"0.02 m"``)."""
        if not self.lengths:
            return self.template
        show = show or (lambda x: f"{x:g} m")
        return self.template.format(*(show(x) for x in self.lengths))

    def __str__(self) -> str:
        return self.message


def _frozen(a: np.ndarray) -> np.ndarray:
    a = np.array(a, dtype=float)  # a private copy
    a.setflags(write=False)
    return a


@dataclass(frozen=True)
class ShapeGeometry:
    """What a primitive shape contributes in its local frame (read-only): ``measure`` (m³, m²,
    m or 1) and its ``measure_kind``, ``com`` (m) and ``unit_inertia`` (m², about the com per
    unit mass, tensor convention)."""

    measure: float
    measure_kind: str
    com: np.ndarray
    unit_inertia: np.ndarray

    def __post_init__(self) -> None:
        object.__setattr__(self, "measure", float(self.measure))
        object.__setattr__(self, "com", _frozen(self.com))
        object.__setattr__(self, "unit_inertia", _frozen(self.unit_inertia))


class Kind(NamedTuple):
    """What a shape parameter holds, for the loader and the schema.

    ``name``: ``"length"`` (one length), ``"lengths"`` (a vector of ``n`` positive
    lengths), ``"points"`` (``n`` points x, y, z) or ``"bool"``.
    """

    name: str
    n: int = 1


LENGTH = Kind("length")
BOOL = Kind("bool")


#: a diameter may be given wherever its radius is accepted (the value is halved, exactly)
DIAMETERS = {"diameter": "radius", "inner_diameter": "inner_radius"}


@dataclass(frozen=True)
class RimRule:
    """How a round shape touches a level floor when it rolls on its outer rim: ``kind``
    (``"edge"``, ``"torus"``, ``"sphere"``, ``"band"``), ``plane_from_com(outer radius,
    measure)`` (m, the rim's plane along local z from the com), ``tube_radius(params)`` and
    ``width(params)`` (m; ``params`` the checked SI parameters)."""

    kind: str
    plane_from_com: Callable[[float, float | None], float]
    tube_radius: Callable[[Mapping[str, Any]], float] = lambda p: 0.0
    width: Callable[[Mapping[str, Any]], float] = lambda p: 0.0


def _in_plane(radius: float, measure: float | None) -> float:
    return 0.0


@dataclass(frozen=True)
class ShapeInfo:
    """One entry of the shape catalogue (``rbcli shapes``, validation, the schema, the rim search).

    Attributes
    ----------
    name, summary : str — the ``shape:`` value, one line
    required, optional : tuple of str — parameter names
    measure_kind : str — what a density multiplies (the default case)
    density_keys, origin, formulas : str — as human text (m = mass)
    kinds : mapping — the :class:`Kind` of each parameter that is not a single length
    round : str or None — ``"z"`` round about local z, ``"any"`` about every axis
    outer_radius : callable or None — ``outer_radius(params) -> m``, of a round shape
    rim : RimRule or None — how a round shape rolls on that rim

    A new shape is one entry in :data:`SHAPES` and its builder in ``_BUILDERS``."""

    name: str
    summary: str
    required: tuple[str, ...]
    optional: tuple[str, ...]
    measure_kind: str
    density_keys: str
    origin: str
    formulas: str
    kinds: Mapping[str, Kind] = field(default_factory=dict)
    round: str | None = None
    outer_radius: Callable[[Mapping[str, Any]], float] | None = None
    rim: RimRule | None = None

    def __post_init__(self) -> None:
        unknown = set(self.kinds) - {*self.required, *self.optional}
        if unknown:  # pragma: no cover - a mistake in the table below
            raise ValueError(f"shape {self.name!r}: kinds for unknown parameters {sorted(unknown)}")
        if not ((self.round is None) == (self.outer_radius is None) == (self.rim is None)):  # pragma: no cover
            raise ValueError(f"shape {self.name!r}: a round shape has an outer radius and a rim, and only it")

    def kind(self, param: str) -> Kind:
        """The :class:`Kind` of parameter ``param`` (a single length unless said)."""
        return self.kinds.get(param, LENGTH)

    @property
    def diameters(self) -> dict[str, str]:
        """The diameter spellings this shape accepts, each with the radius it gives
        (``{"diameter": "radius", "inner_diameter": "inner_radius"}`` for a disk)."""
        return {d: r for d, r in DIAMETERS.items() if r in (*self.required, *self.optional)}

    def radius(self, params: Mapping[str, Any]) -> float | None:
        """The outer radius (m) of a round shape with these (checked, SI) parameters, else None."""
        return None if self.outer_radius is None else float(self.outer_radius(params))


def _radius(p: Mapping[str, Any]) -> float:
    return float(p["radius"])


SHAPES: dict[str, ShapeInfo] = {
    info.name: info
    for info in (
        ShapeInfo(
            "point", "a point mass", (), (), "point", "mass only", "the point",
            "I = 0 about the point",
        ),
        ShapeInfo(
            "rod", "thin rod along local z", ("length",), (), "length",
            "linear_density", "centroid (mid-length)",
            "Ixx = Iyy = m L²/12; Izz = 0",
        ),
        ShapeInfo(
            "ring", "thin hoop in the local xy plane", ("radius",), (), "length",
            "linear_density", "centroid (centre of the hoop)",
            "Izz = m R²; Ixx = Iyy = m R²/2; length 2πR",
            round="z", outer_radius=_radius, rim=RimRule("edge", _in_plane),
        ),
        ShapeInfo(
            "disk", "thin disk or annulus in the local xy plane", ("radius",),
            ("inner_radius",), "area", "areal_density", "centroid (centre)",
            "Izz = m(R² + r²)/2; Ixx = Iyy = m(R² + r²)/4; area π(R² − r²)",
            round="z", outer_radius=_radius, rim=RimRule("edge", _in_plane),
        ),
        ShapeInfo(
            "plate", "thin rectangle a x b in local x, y; with thickness t a box",
            ("size",), ("thickness",), "area",
            "areal_density (or density with thickness > 0)", "centroid",
            "Ixx = m(b² + t²)/12; Iyy = m(a² + t²)/12; Izz = m(a² + b²)/12 (t = 0 if thin)",
            kinds={"size": Kind("lengths", 2)},
        ),
        ShapeInfo(
            "triangle", "thin triangular lamina", ("vertices",), (), "area",
            "areal_density", "the frame the vertices are given in (com = centroid)",
            "C = (1/12) Σ dᵢdᵢᵀ (dᵢ = vertex − centroid); I = m(tr(C) E − C)",
            kinds={"vertices": Kind("points", 3)},
        ),
        ShapeInfo(
            "box", "solid cuboid a x b x c", ("size",), (), "volume", "density",
            "centroid", "Ixx = m(b² + c²)/12; Iyy = m(a² + c²)/12; Izz = m(a² + b²)/12",
            kinds={"size": Kind("lengths", 3)},
        ),
        ShapeInfo(
            "cylinder", "solid cylinder or tube along local z; shell: true for a thin wall",
            ("radius", "length"), ("inner_radius", "shell"), "volume",
            "density (or areal_density with shell: true)", "centroid",
            "solid/tube: Izz = m(R² + r²)/2, Ixx = Iyy = m(3(R² + r²) + L²)/12; "
            "shell (no end caps): Izz = m R², Ixx = Iyy = m(R²/2 + L²/12)",
            kinds={"shell": BOOL}, round="z", outer_radius=_radius,
            rim=RimRule("band", _in_plane, width=lambda p: float(p["length"])),
        ),
        ShapeInfo(
            "sphere", "solid or hollow sphere; shell: true for a thin shell", ("radius",),
            ("inner_radius", "shell"), "volume",
            "density (or areal_density with shell: true)", "centroid",
            "solid/hollow: I = (2/5) m (R⁵ − r⁵)/(R³ − r³); shell: I = (2/3) m R²",
            kinds={"shell": BOOL}, round="any", outer_radius=_radius,
            rim=RimRule("sphere", _in_plane, tube_radius=_radius),
        ),
        ShapeInfo(
            "hemisphere", "solid hemisphere, dome towards +z", ("radius",), (), "volume",
            "density", "centre of the flat face",
            "com z = 3R/8; about the com: Izz = (2/5) m R², Ixx = Iyy = (83/320) m R²; "
            "about the origin: Ixx = Iyy = Izz = (2/5) m R²",
            round="z", outer_radius=_radius,
            # on the rim of its flat face, 3R/8 from the com towards the face
            rim=RimRule("edge", lambda R, V: -3.0 * R / 8.0),
        ),
        ShapeInfo(
            "cone", "solid right circular cone, apex at +z", ("radius", "height"), (),
            "volume", "density", "centre of the base",
            "com z = h/4; about the com: Izz = (3/10) m R², "
            "Ixx = Iyy = m(3R²/20 + 3h²/80); about the origin: Ixx = Iyy = m(3R²/20 + h²/10)",
            round="z", outer_radius=_radius,
            # on its base circle, h/4 from the com towards the base, h = 3 V/(pi R²)
            rim=RimRule("edge", lambda R, V: -0.75 * float(V) / (math.pi * R * R)),
        ),
        ShapeInfo(
            "ellipsoid", "solid ellipsoid with semi-axes a, b, c along local x, y, z",
            ("semi_axes",), (), "volume", "density", "centroid",
            "Ixx = m(b² + c²)/5; Iyy = m(a² + c²)/5; Izz = m(a² + b²)/5; volume 4πabc/3",
            kinds={"semi_axes": Kind("lengths", 3)},
        ),
        ShapeInfo(
            "torus", "solid torus (tyre, O-ring) about local z", ("major_radius", "minor_radius"),
            (), "volume", "density", "centroid",
            "Izz = m(R² + 3r²/4); Ixx = Iyy = m(R²/2 + 5r²/8); volume 2π²Rr²",
            round="z", outer_radius=lambda p: float(p["major_radius"]) + float(p["minor_radius"]),
            rim=RimRule("torus", _in_plane, tube_radius=lambda p: float(p["minor_radius"])),
        ),
    )
}

#: the shapes the body loader builds itself (not primitives): name -> what it is
IO_SHAPES = {
    "mesh": "a mesh file",
    "step": "a STEP file's solids",
    "given": "given mass properties",
    "include": "an included body file",
}


# --- parameter checks


def _number(param: str, value: Any, label: str | None = None) -> float:
    label = label or param
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ShapeError(param, f"{label} must be a number, not {type(value).__name__}")
    x = float(value)
    if not math.isfinite(x):
        raise ShapeError(param, f"{label} must be finite (got {x})")
    return x


def _positive(param: str, value: Any) -> float:
    x = _number(param, value)
    if x <= 0:
        raise ShapeError(param, f"{param} must be greater than 0 (got {{0}})", (x,))
    return x


def _non_negative(param: str, value: Any) -> float:
    x = _number(param, value)
    if x < 0:
        raise ShapeError(param, f"{param} must not be negative (got {{0}})", (x,))
    return x


def _components(param: str, value: Any, n: int, label: str | None = None) -> list[Any]:
    """The ``n`` items of a vector parameter; ``label`` names it in the message."""
    label = label or param
    if isinstance(value, (str, bytes, Mapping)):
        raise ShapeError(param, f"{label} must be a list of {n} numbers")
    try:
        items = list(value)
    except TypeError:
        raise ShapeError(param, f"{label} must be a list of {n} numbers") from None
    if len(items) != n:
        raise ShapeError(param, f"{label} must have {n} components, got {len(items)}")
    return items


def _positive_vector(param: str, value: Any, n: int) -> list[float]:
    items = _components(param, value, n)
    out = []
    for i, v in enumerate(items):
        x = _number(param, v, f"{param}[{i}]")
        if x <= 0:
            raise ShapeError(param, f"{param}[{i}] must be greater than 0 (got {{0}})", (x,))
        out.append(x)
    return out


def _flag(param: str, value: Any) -> bool:
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise ShapeError(param, f"{param} must be true or false, not {value!r}")


def _inner(params: dict[str, Any], radius: float) -> float:
    r = params.get("inner_radius")
    if r is None:
        return 0.0
    r = _non_negative("inner_radius", r)
    if r >= radius:
        raise ShapeError("inner_radius", "inner_radius ({0}) must be less than radius ({1})",
                         (r, radius))
    return r


def _diag(x: float, y: float, z: float) -> tuple[float, float, float]:
    """A diagonal unit inertia, as its three diagonal entries (:class:`_Raw`)."""
    return (x, y, z)


_ZERO = (0.0, 0.0, 0.0)


class _Raw(NamedTuple):
    """What a builder returns: a :class:`ShapeGeometry` before its arrays are made
    (``com`` a 3-tuple or array; ``unit_inertia`` the 3 diagonal entries of a diagonal
    tensor, or a (3, 3) array)."""

    measure: float
    measure_kind: str
    com: Any
    unit_inertia: Any


# --- the shapes; each takes the checked dict of parameters (required present, none unknown)


def _point(p: dict[str, Any]) -> _Raw:
    return _Raw(1.0, "point", _ZERO, _diag(0.0, 0.0, 0.0))


def _rod(p: dict[str, Any]) -> _Raw:
    # thin rod of length L along z, centred: Ixx = Iyy = mL²/12 (Meriam & Kraige B).
    length = _positive("length", p["length"])
    i = length * length / 12.0
    return _Raw(length, "length", _ZERO, _diag(i, i, 0.0))


def _ring(p: dict[str, Any]) -> _Raw:
    # thin hoop: all mass at distance R from z: Izz = mR²; Ixx = Iyy = Izz/2 by the
    # perpendicular-axis theorem.
    r = _positive("radius", p["radius"])
    return _Raw(2.0 * math.pi * r, "length", _ZERO, _diag(r * r / 2, r * r / 2, r * r))


def _disk(p: dict[str, Any]) -> _Raw:
    # annulus R > r >= 0: Izz = m(R² + r²)/2, Ixx = Iyy = Izz/2 (perpendicular axes).
    big = _positive("radius", p["radius"])
    small = _inner(p, big)
    area = math.pi * (big - small) * (big + small)
    izz = (big * big + small * small) / 2.0
    return _Raw(area, "area", _ZERO, _diag(izz / 2, izz / 2, izz))


def _box_geometry(a: float, b: float, c: float) -> tuple[float, float, float]:
    # cuboid a x b x c about its centroid: Ixx = m(b² + c²)/12, ...
    return _diag((b * b + c * c) / 12.0, (a * a + c * c) / 12.0, (a * a + b * b) / 12.0)


def _plate(p: dict[str, Any]) -> _Raw:
    a, b = _positive_vector("size", p["size"], 2)
    t = p.get("thickness")
    t = 0.0 if t is None else _non_negative("thickness", t)
    if t > 0:
        return _Raw(a * b * t, "volume", _ZERO, _box_geometry(a, b, t))
    return _Raw(a * b, "area", _ZERO, _box_geometry(a, b, 0.0))


def _triangle(p: dict[str, Any]) -> _Raw:
    rows = _components("vertices", p["vertices"], 3)
    v = np.array([[_number("vertices", x, f"vertices[{i}][{j}]")
                   for j, x in enumerate(_components("vertices", row, 3, f"vertices[{i}]"))]
                  for i, row in enumerate(rows)])
    centroid = v.mean(axis=0)
    d = v - centroid
    # twice the area |(v1 − v0) × (v2 − v0)|, and the edges' lengths
    x = np.array([np.cross(v[1] - v[0], v[2] - v[0]), v[0] - v[1], v[1] - v[2], v[0] - v[2]])
    norms = np.sqrt(np.vecdot(x, x))
    # Degenerate when the area is round-off compared with the square of the size.
    longest = norms[1:].max()
    if not norms[0] > 1e-12 * longest * longest:
        raise ShapeError("vertices", "the triangle's vertices are collinear (it has no area)")
    # Second moment per unit area about the centroid: ∫ x xᵀ dA / A = (1/12) Σ dᵢ dᵢᵀ,
    # the exact quadrature of a quadratic over a triangle (it is exact for quadratics
    # because  ∫ x xᵀ dA / A = (1/12)(Σ vᵢvᵢᵀ + (Σvᵢ)(Σvᵢ)ᵀ), and Σ dᵢ = 0).
    c = d.T @ d / 12.0
    c = 0.5 * (c + c.T)
    return _Raw(0.5 * float(norms[0]), "area", centroid, np.trace(c) * np.eye(3) - c)


def _box(p: dict[str, Any]) -> _Raw:
    a, b, c = _positive_vector("size", p["size"], 3)
    return _Raw(a * b * c, "volume", _ZERO, _box_geometry(a, b, c))


def _cylinder(p: dict[str, Any]) -> _Raw:
    big = _positive("radius", p["radius"])
    length = _positive("length", p["length"])
    shell = _flag("shell", p["shell"]) if p.get("shell") is not None else False
    l2 = length * length / 12.0
    if shell:
        inner = p.get("inner_radius")
        if inner is not None and _non_negative("inner_radius", inner) > 0:
            raise ShapeError(
                "inner_radius",
                "inner_radius cannot be used with shell: true (a shell is a thin wall at radius)",
            )
        # open thin-walled tube, lateral surface only: Izz = mR²; Ixx = m(R²/2 + L²/12).
        return _Raw(
            2.0 * math.pi * big * length, "area", _ZERO,
            _diag(big * big / 2 + l2, big * big / 2 + l2, big * big),
        )
    small = _inner(p, big)
    s2 = big * big + small * small
    # thick tube R > r >= 0: Izz = m(R² + r²)/2; Ixx = m(3(R² + r²) + L²)/12.
    return _Raw(
        math.pi * (big - small) * (big + small) * length, "volume", _ZERO,
        _diag(s2 / 4 + l2, s2 / 4 + l2, s2 / 2),
    )


def _sphere(p: dict[str, Any]) -> _Raw:
    big = _positive("radius", p["radius"])
    shell = _flag("shell", p["shell"]) if p.get("shell") is not None else False
    if shell:
        inner = p.get("inner_radius")
        if inner is not None and _non_negative("inner_radius", inner) > 0:
            raise ShapeError(
                "inner_radius",
                "inner_radius cannot be used with shell: true (a shell is a thin wall at radius)",
            )
        # thin spherical shell: I = (2/3) m R².
        i = 2.0 * big * big / 3.0
        return _Raw(4.0 * math.pi * big * big, "area", _ZERO, _diag(i, i, i))
    small = _inner(p, big)
    q = small / big
    # hollow sphere: I = (2/5) m (R⁵ − r⁵)/(R³ − r³). With q = r/R the ratio is
    # R² (1 + q + q² + q³ + q⁴)/(1 + q + q²): no cancellation as r → R.
    ratio = (1 + q + q**2 + q**3 + q**4) / (1 + q + q**2)
    i = 0.4 * big * big * ratio
    volume = 4.0 / 3.0 * math.pi * big**3 * (1 - q) * (1 + q + q * q)
    return _Raw(volume, "volume", _ZERO, _diag(i, i, i))


def _hemisphere(p: dict[str, Any]) -> _Raw:
    r = _positive("radius", p["radius"])
    # solid hemisphere, flat face on z = 0: com z = 3R/8; about the face centre every
    # axis gives (2/5) mR² (half a sphere); about the com (parallel axes)
    # Ixx = Iyy = (2/5 − 9/64) mR² = (83/320) mR², Izz = (2/5) mR².
    ixx = 83.0 / 320.0 * r * r
    return _Raw(
        2.0 / 3.0 * math.pi * r**3, "volume", (0.0, 0.0, 3.0 * r / 8.0),
        _diag(ixx, ixx, 0.4 * r * r),
    )


def _cone(p: dict[str, Any]) -> _Raw:
    r = _positive("radius", p["radius"])
    h = _positive("height", p["height"])
    # solid right circular cone, base on z = 0, apex at z = h: com z = h/4;
    # about the com Izz = (3/10) mR², Ixx = Iyy = m(3R²/20 + 3h²/80).
    ixx = 3.0 * r * r / 20.0 + 3.0 * h * h / 80.0
    return _Raw(
        math.pi * r * r * h / 3.0, "volume", (0.0, 0.0, h / 4.0),
        _diag(ixx, ixx, 0.3 * r * r),
    )


def _ellipsoid(p: dict[str, Any]) -> _Raw:
    a, b, c = _positive_vector("semi_axes", p["semi_axes"], 3)
    # solid ellipsoid: Ixx = m(b² + c²)/5, ...
    return _Raw(
        4.0 / 3.0 * math.pi * a * b * c, "volume", _ZERO,
        _diag((b * b + c * c) / 5, (a * a + c * c) / 5, (a * a + b * b) / 5),
    )


def _torus(p: dict[str, Any]) -> _Raw:
    big = _positive("major_radius", p["major_radius"])
    small = _positive("minor_radius", p["minor_radius"])
    if small > big:
        raise ShapeError(
            "minor_radius",
            "minor_radius ({0}) must not exceed major_radius ({1}): "
            "the torus would intersect itself",
            (small, big),
        )
    # solid torus (Pappus: volume 2π²Rr²): Izz = m(R² + 3r²/4); Ixx = Iyy = m(R²/2 + 5r²/8).
    ixx = big * big / 2 + 5 * small * small / 8
    return _Raw(
        2.0 * math.pi**2 * big * small * small, "volume", _ZERO,
        _diag(ixx, ixx, big * big + 0.75 * small * small),
    )


_BUILDERS: dict[str, Callable[[dict[str, Any]], ShapeGeometry]] = {
    "point": _point,
    "rod": _rod,
    "ring": _ring,
    "disk": _disk,
    "plate": _plate,
    "triangle": _triangle,
    "box": _box,
    "cylinder": _cylinder,
    "sphere": _sphere,
    "hemisphere": _hemisphere,
    "cone": _cone,
    "ellipsoid": _ellipsoid,
    "torus": _torus,
}

#: the shapes made by a formula for a real mass distribution (not ``mesh`` or ``given``):
#: their inertia tensors are physically possible by construction, and so is any sum of
#: them with their parallel-axis terms (each a point mass's tensor)
FORMULA_SHAPES = frozenset(_BUILDERS)


def geometry(shape: str, **params: Any) -> ShapeGeometry:
    """Measure, centre of mass and inertia per unit mass of a primitive shape.

    ``shape`` one of :data:`SHAPES`; ``**params`` in SI (lengths in m, vectors as sequences,
    ``shell`` a bool; None counts as absent). A ShapeGeometry: ``measure`` (m³, m², m or 1),
    ``measure_kind``, ``com`` (3,) m local, ``unit_inertia`` (3, 3) m² about the com.
    A ShapeError (a ValueError) names the parameter at fault (``param = "shape"`` for an
    unknown shape or ``mesh``, ``given``, ``include``)."""
    raw = local_geometry(shape, params)
    inertia = raw.unit_inertia
    return ShapeGeometry(raw.measure, raw.measure_kind, raw.com,
                         np.diag(inertia) if isinstance(inertia, tuple) else inertia)


def builder(shape: str) -> Callable[[dict[str, Any]], _Raw]:
    """:func:`local_geometry` of the primitive ``shape`` for parameters already checked: the
    body loader's, one call a part. KeyError for a shape that is not a primitive; ShapeError
    as :func:`geometry`."""
    return _BUILDERS[shape]


def local_geometry(shape: str, params: dict[str, Any]) -> _Raw:
    """:func:`geometry` without its arrays, for the body loader: (measure, measure_kind, com,
    unit_inertia), ``com`` possibly a 3-tuple and ``unit_inertia`` a diagonal's 3-tuple."""
    if shape in IO_SHAPES:
        raise ShapeError(
            "shape",
            f"shape {shape!r} ({IO_SHAPES[shape]}) is handled by the body loader, "
            "not by the primitive-shape geometry",
        )
    info = SHAPES.get(shape) if isinstance(shape, str) else None
    if info is None:
        known = ", ".join([*SHAPES, *IO_SHAPES])
        raise ShapeError("shape", f"unknown shape {shape!r}; the shapes are: {known}")
    allowed = (*info.required, *info.optional)
    for key in params:
        if key not in allowed:
            what = ", ".join(allowed) if allowed else "none"
            raise ShapeError(
                key, f"unknown parameter {key!r} for shape {shape!r} (allowed: {what})"
            )
    for key in info.required:
        if params.get(key) is None:
            raise ShapeError(key, f"shape {shape!r} needs {key!r}")
    return _BUILDERS[shape](params)

