"""The body model: what a body file means, in SI, after validation.

A leaf module (stdlib + numpy only) shared by io (which builds it) and core and
render (which read it). Every vector is in the body frame.

Bodies are values, deeply immutable whatever path built them (the loader, ``Part(...)`` in
code, ``dataclasses.replace``): every array is read-only (a writable one passed in is
copied), ``Part.extra`` and ``Body.units`` are read-only mappings of their own, the
sequences are tuples. One body, one answer.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from types import MappingProxyType

import numpy as np

from rbcli.errors import Location

_FLOAT = np.dtype(float)
#: the empty read-only mapping (most parts' ``extra``, an SI body's ``units``): one shared object
EMPTY_MAPPING: MappingProxyType = MappingProxyType({})


def _frozen(a, dtype=_FLOAT) -> np.ndarray:
    """``a`` as a read-only array: itself when it is one already (its data cannot change:
    no writable array shares it), else a private read-only copy."""
    if a.__class__ is np.ndarray and not a.flags.writeable and a.dtype == dtype:
        base = a
        while base.base is not None and base.base.__class__ is np.ndarray:
            base = base.base
        if not base.flags.writeable:
            return a
    a = np.array(a, dtype=dtype)  # a private copy
    a.setflags(write=False)
    return a


def equivalent_ellipsoid(mass: float, inertia) -> tuple[np.ndarray, np.ndarray]:
    """Semi-axes (m) and axes (columns) of the uniform ellipsoid with a part's ``mass`` (kg)
    and ``inertia`` about its com (kg m², 3×3): ``a² = 5 (I₂ + I₃ − I₁) / (2 m)``, etc.

    The shape a part given only by its mass properties is drawn as and measured by (the
    plausibility warnings' distance from a spin axis). A rank-deficient tensor gives zero
    semi-axes (a flat or needle ellipsoid).
    """
    w, v = np.linalg.eigh(0.5 * (np.asarray(inertia, dtype=float) + np.asarray(inertia, dtype=float).T))
    s = np.clip(np.array([w[1] + w[2] - w[0], w[0] + w[2] - w[1], w[0] + w[1] - w[2]]), 0.0, None)
    if np.linalg.det(v) < 0:
        v[:, 2] = -v[:, 2]
    return np.sqrt(2.5 * s / float(mass)), v


def _freeze_fields(obj: object, names: tuple[str, ...], optional: bool = False) -> None:
    """Make the array fields ``names`` of the frozen dataclass ``obj`` read-only
    (:func:`_frozen`); None stays None when ``optional``."""
    for name in names:
        a = getattr(obj, name)
        if a is None and optional:
            continue
        f = _frozen(a)
        if f is not a:
            object.__setattr__(obj, name, f)


def _mapping(m) -> MappingProxyType:
    """A read-only mapping of its own with the items of ``m`` (EMPTY_MAPPING when empty)."""
    if m is EMPTY_MAPPING:
        return m
    return MappingProxyType(dict(m)) if m else EMPTY_MAPPING


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
    at: np.ndarray = field(default_factory=lambda: _frozen(np.zeros(3)))
    R: np.ndarray = field(default_factory=lambda: _frozen(np.eye(3)))
    vertices: np.ndarray | None = None
    faces: np.ndarray | None = None

    def __post_init__(self) -> None:
        at, R = _frozen(self.at), _frozen(self.R)
        if at is not self.at:
            object.__setattr__(self, "at", at)
        if R is not self.R:
            object.__setattr__(self, "R", R)
        if self.vertices is not None:
            object.__setattr__(self, "vertices", _frozen(self.vertices))
            object.__setattr__(self, "faces", _frozen(self.faces, np.dtype(np.int64)))


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
    axis: np.ndarray = field(default_factory=lambda: _frozen(np.array([0.0, 0.0, 1.0])))
    extra: MappingProxyType = field(default_factory=lambda: EMPTY_MAPPING)
    where: Location | None = None
    outline: Outline | None = None

    def __post_init__(self) -> None:
        _freeze_fields(self, ("com", "inertia_com", "axis"))
        if self.extra is not EMPTY_MAPPING:
            object.__setattr__(self, "extra", _mapping(self.extra))

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
        _freeze_fields(self, ("axis", "through"))


@dataclass(frozen=True)
class Body:
    """A validated body: its parts and the defaults commands use.

    Attributes
    ----------
    name : str
    source : str — the file path, ``<stdin>`` or ``<expr>``
    text : str — the input text as read (for reports: echo and SHA-256)
    parts : tuple[Part, ...]
    reference, pivot : (3,) ndarray | None — m
    reference_is_com : bool — ``reference: com`` in the file
    shaft : Shaft | None
    rim_radius : float | None — m
    description : str
    warnings : tuple[str, ...] — located warnings to show on standard error
    inputs : tuple[str, ...] — real paths of every file read to build the body: the body
        file, every include at any depth and every mesh file (outputs must avoid them);
        empty for standard input or ``-e`` unless those include files or meshes
    units : Mapping[str, str] — the file's ``units`` (``{"length": "mm", ...}``): what its
        bare numbers mean; empty for SI; read-only

    The loader also leaves the body's combined mass properties on it (not a field: a
    ``dataclasses.replace`` with other parts does not carry them); commands read them with
    :func:`rbcli.core.inertia.body_mass_props` instead of combining the parts again.
    """

    name: str
    source: str
    text: str
    parts: tuple[Part, ...]
    reference: np.ndarray | None = None
    reference_is_com: bool = False
    shaft: Shaft | None = None
    pivot: np.ndarray | None = None
    rim_radius: float | None = None
    description: str = ""
    warnings: tuple[str, ...] = ()
    inputs: tuple[str, ...] = ()
    units: MappingProxyType = field(default_factory=lambda: EMPTY_MAPPING)

    def __post_init__(self) -> None:
        _freeze_fields(self, ("reference", "pivot"), optional=True)
        for name in ("parts", "warnings", "inputs"):
            value = getattr(self, name)
            if value.__class__ is not tuple:
                object.__setattr__(self, name, tuple(value))
        object.__setattr__(self, "units", _mapping(self.units))
