"""The body model: :class:`Body`, the ways to make one (a body file, Python data, parts,
another body) and to write one (:meth:`Body.to_yaml`).

A body is a deeply immutable value (read-only parts and ``units``, tuples). The builders
return a body's components (:class:`rbcli.body.bodyfile.Built`); only this module makes the
:class:`Body`, so imports go one way: model -> pydata -> bodyfile -> part readers -> partmodel.
"""

from __future__ import annotations

import math
import numbers
import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from rbcli.body import bodyfile, document, pydata
from rbcli.body.bodyfile import Built
from rbcli.body.partmodel import (EMPTY_MAPPING, Part, Shaft, freeze_arrays, read_only, rebuilt,
                                  same_fields, unhashable)
from rbcli.body.partspec import ReadOnly
from rbcli.core.inertia import body_mass_props, remember_mass_props, remembered
from rbcli.errors import ParamError, literal

__all__ = ["Body", "load_body", "load_text", "load_expr", "load_data", "load_cad", "with_points"]


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

    The loader remembers the combined mass properties beside the body (not a field, so a
    ``dataclasses.replace`` does not carry them): :func:`rbcli.core.inertia.body_mass_props`.
    ``==`` compares the fields by value (:func:`rbcli.body.partmodel.same`); unhashable.
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
    units: ReadOnly = field(default_factory=lambda: EMPTY_MAPPING)

    def __post_init__(self) -> None:
        freeze_arrays(self, ("reference", "pivot"))
        for name in ("parts", "warnings", "inputs"):
            object.__setattr__(self, name, tuple(getattr(self, name)))
        object.__setattr__(self, "units", read_only(self.units))

    __reduce__ = rebuilt
    __eq__ = same_fields
    __hash__ = unhashable

    def __repr__(self) -> str:
        return f"<Body {self.name!r} from {self.source}: {len(self.parts)} parts>"

    def _repr_html_(self) -> str:
        """Mass, com and parts as an HTML table, for notebooks."""
        from rbcli.render import notebook

        return notebook.html(self)

    # --- built in code

    @classmethod
    def from_parts(cls, parts: Sequence[Mapping[str, Any]], *, name: str = "body",
                   units: Mapping[str, str] | None = None, shaft: Mapping[str, Any] | None = None,
                   reference: Sequence[Any] | str | None = None, pivot: Sequence[Any] | None = None,
                   rim_radius: float | str | None = None, description: str | None = None,
                   base_dir: str | os.PathLike[str] | None = None) -> Body:
        """A body made of ``parts``, checked as a body file is; each argument is the body
        file's key of that name (SI, the body's ``units``, or strings such as ``"25 mm"``).

        Parameters
        ----------
        parts : sequence of PartSpec or mapping
            The parts, in order: :mod:`rbcli.parts` makes them; a mapping of a part's keys
            (``{"shape": "disk", "radius": 0.1, ...}``) is taken too.
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
        return _made(pydata.from_parts(
            parts, name=name, units=units, shaft=shaft, reference=reference, pivot=pivot,
            rim_radius=rim_radius, description=description, base_dir=base_dir))

    def to_yaml(self, *, base_dir: str | os.PathLike[str] | None = None) -> str:
        """The body as a body file (YAML text) that reads back to the same body, bit for bit
        (every value written as read, a float as its ``repr``, in the body's ``units``).

        Kept: the document's keys, values and order, quantity strings as written, ``include``
        and ``mesh`` parts as references to their files (which must still be there). Not
        kept: comments, layout, quoting, number spelling (``1e3`` becomes ``1000.0``); a
        one-part shorthand becomes a ``parts:`` list; ``name`` and ``units`` are always written.

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
        return document.to_yaml(self, base_dir)

    def replace(self, which: str | int, part: Mapping[str, Any] | None = None, /,
                **keys: Any) -> Body:
        """The body with one of its parts replaced or some of its keys changed (the document
        is changed and read again, with every check).

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
        return _made(pydata.replace_part(self, which, part, keys))

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
        return _made(pydata.move_part(self, which, at, axis, rotate))

    def checked(self, param: str = "body") -> Body:
        """This body, if it holds what a loaded body holds (one made in code may hold
        anything); else a TypeError or an InputError naming ``param``. Parts are checked once."""
        def finite(a: Any, shape: tuple = (3,)) -> bool:
            return isinstance(a, np.ndarray) and a.shape == shape and bool(np.isfinite(a).all())

        for key in ("reference", "pivot", "shaft"):
            v = getattr(self, key)
            if v is not None and not all(map(finite, (v.axis, v.through) if isinstance(v, Shaft) else (v,))):
                raise ParamError(param, f"the body's {key} is not a finite (3,) vector")
        r = self.rim_radius
        if r is not None and not (isinstance(r, numbers.Real) and 0.0 < r < math.inf):
            raise ParamError(param, f"the body's rim_radius is {literal(repr(r))}, not a positive length (m)")
        if remembered(self):  # (a loaded body's parts were checked when it was read)
            return self
        if not isinstance(self.parts, tuple) or not self.parts:
            raise ParamError(param, "the body has no parts; a body needs at least one")
        for i, p in enumerate(self.parts, 1):
            if type(p) is not Part:
                raise TypeError(f"{param}: part {i} is {type(p).__name__}, not a Part (rbcli.parts and "
                                "Body.from_parts make parts)")
            if not (isinstance(p.mass, numbers.Real) and not isinstance(p.mass, bool) and 0.0 < p.mass < math.inf):
                raise ParamError(param, f"part {i}: its mass is {literal(repr(p.mass))}, not a positive number (kg)")
            for key, shape in (("com", (3,)), ("axis", (3,)), ("inertia_com", (3, 3))):
                if not finite(getattr(p, key), shape):
                    raise ParamError(param, f"part {i}: its {key} is not a finite {shape} array")
        try:
            body_mass_props(self)  # (remembered from now on)
        except ValueError as exc:  # the parts' total
            raise ParamError(param, literal(exc)) from None
        return self


def _made(built: Built) -> Body:
    """The :class:`Body` of ``built``, its mass properties and document folder remembered."""
    body = Body(**built.fields)
    remember_mass_props(body, built.mass_props)
    document.remember_origin(body, built.origin)
    return body


def load_body(source: str, *, stdin: object = None) -> Body:
    """A body file (a path, or ``-`` for standard input): :func:`rbcli.body.bodyfile.load_body`."""
    return _made(bodyfile.load_body(source, stdin=stdin))


def load_expr(expr: str) -> Body:
    """A body written inline (``-e/--expr``): :func:`rbcli.body.bodyfile.load_expr`."""
    return _made(bodyfile.load_expr(expr))


def load_text(data: bytes | str, filename: str, base_dir: Path, *, name_default: str = "body",
              stack: tuple[str, ...] = (), units: dict[str, str] | None = None) -> Body:
    """A body of text already read: :func:`rbcli.body.bodyfile.load_text`."""
    return _made(bodyfile.load_text(data, filename, base_dir, name_default=name_default,
                                    stack=stack, units=units))


def load_data(mapping: Mapping[str, object], *, units: Mapping[str, str] | None = None,
              name: str = "body", base_dir: object = None) -> Body:
    """A body of Python data: :func:`rbcli.body.pydata.load_data`."""
    return _made(pydata.load_data(mapping, units=units, name=name, base_dir=base_dir))


def load_cad(path: str, **keys: object) -> Body:
    """A STEP, STL or OBJ file as a body: :func:`rbcli.body.pydata.cad_file`."""
    return _made(pydata.cad_file(path, **keys))


def with_points(body: Body, points: Sequence[tuple[str, float, Sequence[float]]]) -> Body:
    """``body`` with point masses added (``rbcli balance --apply``):
    :func:`rbcli.body.pydata.with_points`."""
    return _made(pydata.with_points(body, points))
