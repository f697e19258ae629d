"""The values a body is made of: :class:`Part` (one part, placed in the body frame), its
:class:`Outline` (what a drawing needs) and :class:`Shaft` (a line). Every vector is in the
body frame, SI.

Deeply immutable, whatever built them (the loader, ``Part(...)`` in code,
``dataclasses.replace``): every array is read-only (a writable one passed in is copied),
``Part.extra`` is a read-only mapping of its own. The :class:`rbcli.body.model.Body` that
holds them is made by :mod:`rbcli.body.model`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, fields, is_dataclass

import numpy as np

from rbcli.body.partspec import ReadOnly
from rbcli.errors import Location


#: the empty read-only mapping (most parts' ``extra``, an SI body's ``units``)
EMPTY_MAPPING = ReadOnly()


def frozen(a, dtype=float) -> np.ndarray:
    """``a`` as a read-only array: itself when it is a read-only ndarray of ``dtype`` whose
    data no writable array shares (it cannot change), else a private read-only copy."""
    if type(a) is np.ndarray and a.dtype == dtype and not a.flags.writeable:
        owner = a
        while isinstance(owner.base, np.ndarray):  # to the array that owns the data
            owner = owner.base
        if not owner.flags.writeable:
            return a
    a = np.array(a, dtype=dtype)
    a.setflags(write=False)
    return a


def freeze_arrays(obj: object, names: tuple[str, ...]) -> None:
    """Make the array fields ``names`` of the frozen dataclass ``obj`` read-only
    (:func:`frozen`); a None field stays None."""
    for name in names:
        a = getattr(obj, name)
        if a is not None:
            object.__setattr__(obj, name, frozen(a))


def rebuilt(obj: object) -> tuple:
    """``__reduce__`` of a body's values: their fields, unpickled through ``__init__`` (arrays
    read-only again: pickle makes them writable), and the rest (a body's mass properties)."""
    names = [f.name for f in fields(obj)]
    state = {k: v for k, v in getattr(obj, "__dict__", {}).items() if k not in names}
    return type(obj), tuple(getattr(obj, n) for n in names), state or None


def same(a: object, b: object) -> bool:
    """Value equality: dataclasses of one type field by field (``compare=True``), arrays by
    shape and elements, mappings and sequences item by item, NaN equal to NaN; else ``==``."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return (isinstance(a, np.ndarray) and isinstance(b, np.ndarray) and a.shape == b.shape
                and np.array_equal(a, b, equal_nan=a.dtype.kind in "fc" and b.dtype.kind in "fc"))
    if is_dataclass(a) and not isinstance(a, type):
        return type(a) is type(b) and all(same(getattr(a, f.name), getattr(b, f.name))
                                           for f in fields(a) if f.compare)
    if isinstance(a, Mapping):
        return isinstance(b, Mapping) and a.keys() == b.keys() and all(same(v, b[k]) for k, v in a.items())
    if isinstance(a, (tuple, list)):
        return type(a) is type(b) and len(a) == len(b) and all(map(same, a, b))
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b):
        return True
    return bool(a == b)


def same_fields(self: object, other: object) -> bool:
    """``__eq__`` of a body, its parts and every result: :func:`same` (fields only)."""
    return same(self, other) if type(self) is type(other) else NotImplemented


def unhashable(self: object) -> int:
    """``__hash__`` of the same: they hold arrays, so they are not hashable."""
    raise TypeError(f"unhashable type: {type(self).__name__!r}")


def read_only(m) -> ReadOnly:
    """A read-only mapping of its own with the items of ``m``."""
    return ReadOnly(m) if m else EMPTY_MAPPING


def equivalent_ellipsoid(mass: float, inertia) -> tuple[np.ndarray, np.ndarray]:
    """Semi-axes (m) and axes (columns) of the uniform ellipsoid with a part's ``mass`` (kg)
    and ``inertia`` about its com (kg m², 3×3): ``a² = 5 (I₂ + I₃ − I₁) / (2 m)``, etc.

    The shape a part given only by its mass properties is drawn as and measured by (the
    plausibility warnings' distance from a spin axis). A rank-deficient tensor gives zero
    semi-axes (a flat or needle ellipsoid).
    """
    J = np.asarray(inertia, dtype=float)
    w, v = np.linalg.eigh(0.5 * (J + J.T))
    s = np.clip(np.array([w[1] + w[2] - w[0], w[0] + w[2] - w[1], w[0] + w[1] - w[2]]), 0.0, None)
    if np.linalg.det(v) < 0:
        v[:, 2] = -v[:, 2]
    return np.sqrt(2.5 * s / float(mass)), v


@dataclass(frozen=True, slots=True)
class Outline:
    """What a drawing of a part needs (:mod:`rbcli.render.outline`; no calculation uses it).

    Attributes
    ----------
    kind : str — a primitive shape name, ``"given"`` (the equivalent uniform ellipsoid:
        ``semi_axes`` along the columns of ``R``; a STEP solid too) or ``"mesh"``
    dims : tuple[tuple[str, object], ...] — the shape's parameters (m; ``dict(dims)``); a
        mesh's ``(("triangles", n),)``
    at : (3,) ndarray — m, the local origin in the body frame
    R : (3, 3) ndarray — the local-to-body rotation (columns: the local axes)
    vertices, faces : (n, 3), (k, 3) int ndarrays | None — a mesh's, in its local frame (m)

    The arrays are read-only.
    """

    kind: str
    dims: tuple = ()
    at: np.ndarray = field(default_factory=lambda: frozen(np.zeros(3)))
    R: np.ndarray = field(default_factory=lambda: frozen(np.eye(3)))
    vertices: np.ndarray | None = None
    faces: np.ndarray | None = None

    def __post_init__(self) -> None:
        freeze_arrays(self, ("at", "R", "vertices"))
        if self.faces is not None:
            object.__setattr__(self, "faces", frozen(self.faces, np.int64))

    __reduce__ = rebuilt
    __eq__ = same_fields
    __hash__ = unhashable


@dataclass(frozen=True, slots=True)
class Part:
    """One part of a body, placed in the body frame.

    Attributes
    ----------
    name : str — ``sub/part`` for parts of an included file
    shape : str — the shape name of SPEC §1
    mass : float — kg, positive
    subtract : bool — True for a hole or pocket (its mass is taken away)
    com : (3,) ndarray — m
    inertia_com : (3, 3) ndarray — kg m^2, about the com, body axes, tensor convention
    measure : float | None — its volume (m^3), area (m^2) or length (m)
    measure_kind : str — "volume", "area", "length", "point" or "given"
    radius : float | None — m, the outer radius of a round part
    axis : (3,) ndarray — its local z axis in the body frame
    extra : Mapping[str, object] — facts worth reporting (a mesh's volume and area, a STEP
        solid's unit and colour), read-only
    where : Location | None — where the part is defined
    outline : Outline | None — for drawings (None: drawn as a dot at its com)

    The arrays are read-only (writable ones passed in are copied).
    """

    name: str
    shape: str
    mass: float
    subtract: bool
    com: np.ndarray
    inertia_com: np.ndarray
    measure: float | None = None
    measure_kind: str = "point"
    radius: float | None = None
    axis: np.ndarray = field(default_factory=lambda: frozen(np.array([0.0, 0.0, 1.0])))
    extra: ReadOnly = field(default_factory=lambda: EMPTY_MAPPING)
    where: Location | None = None
    outline: Outline | None = None

    def __post_init__(self) -> None:
        freeze_arrays(self, ("com", "inertia_com", "axis"))
        if self.extra is not EMPTY_MAPPING:
            object.__setattr__(self, "extra", read_only(self.extra))

    __reduce__ = rebuilt
    __eq__ = same_fields
    __hash__ = unhashable

    @property
    def signed_mass(self) -> float:
        """kg, negative for a subtracted part."""
        return -self.mass if self.subtract else self.mass


@dataclass(frozen=True)
class Shaft:
    """A shaft line: unit ``axis`` through the point ``through`` (m); read-only arrays."""

    axis: np.ndarray
    through: np.ndarray

    def __post_init__(self) -> None:
        freeze_arrays(self, ("axis", "through"))

    __reduce__ = rebuilt
    __eq__ = same_fields
    __hash__ = unhashable
