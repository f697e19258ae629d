"""The body model: what a body file means, in SI, after validation.

A leaf module (stdlib + numpy only) shared by io (which builds it) and core and
render (which read it). Every vector is in the body frame.

Bodies are values, deeply immutable whatever path built them (the loader, ``Part(...)`` in
code, ``dataclasses.replace``): every array is read-only (a writable one passed in is
copied), ``Part.extra`` and ``Body.units`` are read-only mappings of their own, the
sequences are tuples. One body, one answer.

A body is built in code with :meth:`Body.from_parts`, changed with :meth:`Body.replace` and
:meth:`Body.moved`, and written with :meth:`Body.to_yaml`: those methods are the body
reader's and writer's (:mod:`rbcli.body.pydata`, :mod:`rbcli.body.document`), imported when
called, so that this module stays a leaf at import time (tests/test_architecture.py allows
those two imports and no other).
"""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np

from rbcli.errors import Location

_FLOAT = np.dtype(float)
#: the empty read-only mapping (most parts' ``extra``, an SI body's ``units``): one shared object
EMPTY_MAPPING: MappingProxyType = MappingProxyType({})


def _frozen(a, dtype=_FLOAT) -> np.ndarray:
    """``a`` as a read-only array: itself when it is one already (its data cannot change:
    no writable array shares it), else a private read-only copy."""
    if a.__class__ is np.ndarray and (a.dtype is dtype or a.dtype == dtype) and not a.flags.writeable:
        base, up = a, a.base
        while up.__class__ is np.ndarray:  # to the array that owns the data
            base, up = up, up.base
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
    source : str — the file path, ``<stdin>``, ``<expr>``, ``<text>`` (``rbcli.load_text``) or
        ``<data>`` (a body built from Python data: ``rbcli.load_data``, :meth:`from_parts`,
        :meth:`replace`, :meth:`moved`)
    text : str — the input text as read (for reports: echo and SHA-256); for a body built from
        data, its document as YAML (what :meth:`to_yaml` writes)
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

    # ------------------------------------------------------------------ built in code

    @classmethod
    def from_parts(cls, parts: Sequence[Mapping[str, Any]], *, name: str = "body",
                   units: Mapping[str, str] | None = None, shaft: Mapping[str, Any] | None = None,
                   reference: Sequence[Any] | str | None = None, pivot: Sequence[Any] | None = None,
                   rim_radius: float | str | None = None, description: str | None = None,
                   base_dir: str | os.PathLike[str] | None = None) -> Body:
        """A body made of ``parts``, checked as a body file is.

        Each argument is the body file's key of that name, with the values the file takes:
        numbers in SI or in the body's ``units``, or quantity strings such as ``"25 mm"``.

        Parameters
        ----------
        parts : sequence of PartSpec or mapping
            The parts, in order: :mod:`rbcli.parts` makes them (``rbcli.parts.disk(...)``);
            a mapping of a part's keys (``{"shape": "disk", "radius": 0.1, ...}``) is taken
            too.
        name : str
            The body's name.
        units : mapping, optional
            What bare numbers mean, e.g. ``{"length": "mm", "mass": "g"}`` (kinds: length,
            mass, time, angle, angular_speed). Default SI.
        shaft : mapping, optional
            The shaft line, ``{"axis": [0, 0, 1], "through": [0, 0, 0]}`` (``through`` m,
            optional): the default of ``balance``, ``whirl``, ``rollcheck``, ...
        reference : sequence of 3 or str, optional
            The reference point (m), or ``"com"`` / ``"origin"``.
        pivot : sequence of 3, optional
            The pivot (m), for ``top``.
        rim_radius : float or str, optional
            The rim radius (m), for ``rollcheck``.
        description : str, optional
            A line of text about the body.
        base_dir : path-like, optional
            Where relative ``file:`` paths of ``mesh`` and ``include`` parts start (default:
            the current folder).

        Returns
        -------
        Body
            The validated body (``source`` ``"<data>"``; ``text`` its document as YAML).

        Raises
        ------
        TypeError
            A part that is not a part or a mapping, a value of a type no body file holds
            (a complex number, a set, ...), named by where it is (``parts[2].at``).
        rbcli.InputError
            Anything a body file could get wrong, with the message a file gets, located at
            the part by the call: ``parts[2] (cylinder 'bore'): ...``.

        Examples
        --------
        >>> import rbcli
        >>> from rbcli import parts
        >>> wheel = rbcli.Body.from_parts([
        ...     parts.disk(name="web", radius="-150 mm", mass=2),
        ...     parts.ring(name="rim", radius="150 mm", mass=1),
        ... ], name="wheel", shaft={"axis": [0, 0, 1]})
        Traceback (most recent call last):
        ...
        rbcli.errors.InputError: parts[0] (disk 'web'): part 'web': radius must be greater than 0 (got -0.15 m)
        >>> wheel = rbcli.Body.from_parts([
        ...     parts.disk(name="web", radius="150 mm", mass=2),
        ...     parts.ring(name="rim", radius="150 mm", mass=1),
        ... ], name="wheel", shaft={"axis": [0, 0, 1]})
        >>> round(float(rbcli.inertia(wheel).inertia_com[2][2]), 12)   # 2 R²/2 + 1 R², kg m²
        0.045
        """
        from rbcli.body.pydata import from_parts

        return from_parts(parts, name=name, units=units, shaft=shaft, reference=reference,
                          pivot=pivot, rim_radius=rim_radius, description=description,
                          base_dir=base_dir)

    def to_yaml(self, *, base_dir: str | os.PathLike[str] | None = None) -> str:
        """The body as a body file (YAML text) that reads back to the same body.

        :func:`rbcli.load_text` (and ``rbcli.load`` of the text saved in ``base_dir``) reads
        it back to the same mass, centre of mass and inertia tensor, bit for bit, and the
        same name, units, shaft, reference, pivot and rim radius: every value is written as
        it was read (a float as Python's ``repr``), in the body's ``units``.

        What is kept: the document's data — its keys, values and their order, strings with
        units (``"25 mm"``) as written, ``include`` and ``mesh`` parts as references to their
        files (an included file's parts are not copied in; the files must still be there
        when the text is read). What is not: comments, layout, quoting and number spelling
        of a file (``1e3`` is written ``1000.0``); a one-part shorthand becomes a ``parts:``
        list, and the body's ``name`` and ``units`` are written even when the file left them
        to defaults (its stem, the caller's ``units=``).

        Parameters
        ----------
        base_dir : path-like, optional
            The folder the text will be read from (where it will be saved): relative
            ``file:`` paths of ``include`` and ``mesh`` parts are rewritten to resolve from
            there. Default: the current folder, where :func:`rbcli.load_text` starts.

        Returns
        -------
        str
            The YAML text.

        Raises
        ------
        rbcli.InputError
            For a body no reader of rbcli made (``Body(...)`` by hand, or a
            ``dataclasses.replace`` of a body): it has no document. Build it with
            :meth:`from_parts`, change it with :meth:`replace` or :meth:`moved`.

        Examples
        --------
        >>> import rbcli
        >>> box = rbcli.Body.from_parts([rbcli.parts.box(size=[100, 200, 300], mass=2)],
        ...                             name="brick", units={"length": "mm"})
        >>> print(box.to_yaml(), end="")
        name: brick
        units: {length: mm}
        parts:
        - shape: box
          size: [100, 200, 300]
          mass: 2
        >>> again = rbcli.load_text(box.to_yaml())
        >>> bool((rbcli.inertia(again).inertia_com == rbcli.inertia(box).inertia_com).all())
        True
        """
        from rbcli.body.document import to_yaml

        return to_yaml(self, base_dir)

    def replace(self, which: str | int, part: Mapping[str, Any] | None = None, /,
                **keys: Any) -> Body:
        """The body with one of its parts replaced, or some of the part's keys changed.

        The body's document is changed and read again, with every check; the body itself
        is not changed (it is a value).

        Parameters
        ----------
        which : str or int
            The part: its name (``"disk"``; a part without one is named ``shape`` + its
            number, ``disk2``), or its index in the body's ``parts:`` list (an included
            file counts as one part there).
        part : PartSpec or mapping, optional
            The new part (:mod:`rbcli.parts`); default: the part as it is.
        **keys
            Keys of the part to set (``radius="110 mm"``, ``mass=2``, ``at=[0, 0, 0.1]``);
            ``None`` removes a key. ``from_`` is the rod's ``from``.

        Returns
        -------
        Body

        Raises
        ------
        rbcli.InputError
            No such part, or what the new body's checks say (located by key path,
            ``parts[1].radius``).

        Examples
        --------
        >>> import rbcli
        >>> rotor = rbcli.Body.from_parts([
        ...     rbcli.parts.disk(name="disk", radius="100 mm", mass=5, at=[0, 0, 0.2]),
        ... ], shaft={"axis": [0, 0, 1]})
        >>> heavier = rotor.replace("disk", mass=6)
        >>> heavier.parts[0].mass, rotor.parts[0].mass
        (6.0, 5.0)
        """
        from rbcli.body.pydata import replace_part

        return replace_part(self, which, part, keys)

    def moved(self, which: str | int, *, at: Sequence[Any] | None = None,
              axis: Sequence[Any] | None = None, rotate: Mapping[str, Any] | None = None) -> Body:
        """The body with one part placed anew: what a sweep over a part's position needs.

        Parameters
        ----------
        which : str or int
            The part, as for :meth:`replace`.
        at : sequence of 3, optional
            Its new position (the ``at`` key: m, the body's units, or quantity strings).
        axis : sequence of 3, optional
            Its new local z axis (replaces a ``rotate``).
        rotate : mapping, optional
            Its new rotation, as the ``rotate`` key (replaces an ``axis``).

        Returns
        -------
        Body
            The keys not given stay as they are.

        Raises
        ------
        rbcli.InputError
            As :meth:`replace`; ``axis`` and ``rotate`` together.

        Examples
        --------
        >>> import rbcli
        >>> rotor = rbcli.Body.from_parts([
        ...     rbcli.parts.disk(name="disk", radius="100 mm", mass=5, at=[0, 0, "200 mm"]),
        ... ], shaft={"axis": [0, 0, 1]})
        >>> off = rotor.moved("disk", at=["1 mm", 0, "200 mm"])
        >>> round(abs(rbcli.balance(off).static_unbalance), 12)   # 5 kg × 1 mm, kg m
        0.005
        """
        from rbcli.body.pydata import move_part

        return move_part(self, which, at, axis, rotate)
