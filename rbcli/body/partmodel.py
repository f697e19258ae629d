"""The values a body is made of: :class:`Part` (one part, placed in the body frame), its
:class:`Outline` (what a drawing needs) and :class:`Shaft` (a line). Every vector is in the
body frame, SI.

Deeply immutable, whatever built them (the loader, ``Part(...)`` in code,
``dataclasses.replace``): every array is read-only (a writable one passed in is copied),
``Part.extra`` is a read-only mapping of its own. The :class:`rbcli.body.model.Body` that
holds them is made by :mod:`rbcli.body.model`.
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields

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
    """What a drawing of a part needs: its shape, its local dimensions and its placement.

    Built by the body loader beside the part; read by :mod:`rbcli.render.outline`, which
    turns it into surface triangles and outlines for the body figure when one is drawn.
    Nothing here is used by any calculation.

    Attributes
    ----------
    kind : str — a primitive shape name (SPEC §1), ``"given"`` (the part's equivalent
        uniform ellipsoid: ``semi_axes`` along the columns of ``R``) or ``"mesh"``
    dims : tuple[tuple[str, object], ...] — the shape's parameters as
        :func:`rbcli.core.shapes.geometry` took them (lengths in m, ``size`` and
        ``semi_axes`` as tuples, ``vertices`` as three 3-tuples, ``shell`` a bool); for a
        mesh ``(("triangles", n),)``, the file's count. ``dict(outline.dims)`` reads them.
    at : (3,) ndarray — m, the local origin in the body frame
    R : (3, 3) ndarray — the local-to-body rotation (its columns are the local axes)
    vertices : (n, 3) ndarray | None — m, a mesh's vertices in its local frame: the file's
        mesh (a figure draws a decimated copy)
    faces : (k, 3) int ndarray | None — a mesh's triangles (indices into ``vertices``)

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


@dataclass(frozen=True, slots=True)
class Part:
    """One part of a body, placed in the body frame.

    Attributes
    ----------
    name : str — the part's name (``sub/part`` for parts of an included file)
    shape : str — the shape name of SPEC §1
    mass : float — kg, always positive; ``subtract`` says whether it is removed
    subtract : bool — True for a hole or pocket (its mass is taken away)
    com : (3,) ndarray — m, the part's centre of mass
    inertia_com : (3, 3) ndarray — kg m^2, about the part's com, body axes, tensor convention
    measure : float | None — the part's volume (m^3), area (m^2) or length (m)
    measure_kind : str — "volume", "area", "length", "point" or "given"
    radius : float | None — m, the outer radius of a round part (disk, ring, cylinder, ...)
    axis : (3,) ndarray — the part's local z axis in the body frame
    extra : Mapping[str, object] — shape-specific facts worth reporting (e.g. a mesh's
        volume and area), read-only
    where : Location | None — where the part is defined
    outline : Outline | None — the part's shape and placement for drawings (None when the
        loader did not record one: it is then drawn as a dot at its com)

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
