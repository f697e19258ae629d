"""Parts of a body, built in code: one constructor per shape of the body file.

Each takes the body file's keys for its shape (the rod's ``from`` is ``from_=``) and returns
a :class:`PartSpec`, the part's mapping, frozen; :meth:`rbcli.Body.from_parts` checks them as
a file's, located at the call (``parts[2] (cylinder 'bore'): ...``)::

    import rbcli
    from rbcli import parts

    rotor = rbcli.Body.from_parts([
        parts.cylinder(name="shaft", radius="10 mm", length="400 mm", density="7850 kg/m^3",
                       at=[0, 0, "200 mm"]),
        parts.disk(name="disk", radius="100 mm", mass=5, at=[0, 0, "200 mm"]),
    ], name="rotor", shaft={"axis": [0, 0, 1]})

Values are read as the file's: a number SI or in the body's ``units``, a string a quantity
(``"25 mm"``), vectors sequences of either; ``None`` leaves a key out. A value of a type no
body file holds is a ``TypeError`` at once. The shapes are ``rbcli shapes``'s; a test keeps
each constructor's keywords the file's keys.
"""

from __future__ import annotations

import inspect
import os
from collections.abc import Callable, Mapping, Sequence
from typing import Any, TypeVar

from rbcli.body.partspec import PartSpec, freeze

__all__ = ["PartSpec", "Quantity", "Vector", "point", "rod", "ring", "disk", "plate",
           "triangle", "box", "cylinder", "sphere", "hemisphere", "cone", "ellipsoid", "torus",
           "mesh", "step", "given", "include"]

#: a number (SI, or in the body's ``units``) or a quantity string (``"25 mm"``)
Quantity = float | str
#: three quantities: a point or a direction (a list, a tuple, a numpy array)
Vector = Sequence[Quantity]

_F = TypeVar("_F", bound=Callable[..., PartSpec])

#: what the keys every shape shares mean (the body file's keys: README, "The body file")
_COMMON = {
    "name": "name : str, optional\n    Default: its shape and number (``disk2``); unique.",
    "mass": "mass : float or str, optional\n    kg (or the body's unit), or ``\"2.5 kg\"``.",
    "density": "density : float or str, optional\n    kg/m³ of a solid (``\"7850 kg/m^3\"``).",
    "areal_density": "areal_density : float or str, optional\n    kg/m² of a lamina or shell.",
    "linear_density": "linear_density : float or str, optional\n    kg/m of a rod or ring.",
    "material": "material : str, optional\n    A solid's material (``\"steel\"``: ``rbcli "
                "materials``, or the body's ``materials``).",
    "at": "at : sequence of 3 float or str, optional\n    Where its local origin is (m, the "
          "body's unit, or ``\"25 mm\"``).",
    "axis": "axis : sequence of 3, optional\n    Its local z axis; not with ``rotate``.",
    "rotate": "rotate : mapping, optional\n    ``{\"axis\": [x, y, z], \"angle\": \"30 deg\"}``, "
              "``{\"euler\": [a, b, c], \"seq\": \"ZYX\"}``, ``{\"quaternion\": [w, x, y, "
              "z]}`` or ``{\"matrix\": [...]}``; not with ``axis``.",
    "subtract": "subtract : bool, optional\n    True for a hole or a pocket (mass taken away).",
    "cut_from": "cut_from : str, optional\n    A hole's: an earlier part whose density it takes.",
}

_RETURNS = """Returns
-------
PartSpec
    The part as the body file writes it (``shape: {shape}`` and the keys given).

Raises
------
TypeError
    A value of a type no body file holds, named by its keyword."""


def _documented(summary: str, params: str, example: str) -> Callable[[_F], _F]:
    """Give a constructor its numpydoc docstring: ``summary``, its own ``params``, then the
    keys every shape shares that it takes (in its signature's order), Returns and
    ``example``."""

    def deco(fn: _F) -> _F:
        shared = "\n".join(_COMMON[n] for n in inspect.signature(fn).parameters if n in _COMMON)
        shape = fn.__name__
        fn.__doc__ = (f"{summary.strip()}\n\nParameters\n----------\n{params.strip()}\n{shared}\n\n"
                      f"{_RETURNS.format(shape=shape)}\n\nSee Also\n--------\n"
                      f"rbcli.Body.from_parts : a body of parts.\n\n"
                      f"Examples\n--------\n{example.strip()}\n")
        return fn

    return deco


#: the keys every primitive takes after its own parameters (a test keeps them the body's)
_TAIL = ("mass", "density", "areal_density", "linear_density", "material", "at", "axis", "rotate",
         "subtract", "cut_from")
#: the type of a keyword that is not a quantity (float or str)
_TYPES = {"name": str, "cut_from": str, "material": str, "subtract": bool, "shell": bool,
          "rotate": Mapping[str, Any], "at": Vector, "axis": Vector, "from_": Vector, "to": Vector,
          "size": Vector, "semi_axes": Vector, "vertices": Sequence[Vector], "file": Any,
          "units": str, "allow_open": bool, "part": str, "solids": Mapping[str, Any], "com": Vector,
          "inertia": Any, "convention": str}
_PLACED = ("at", "axis", "rotate")
_SOLID = ("mass", "density", "material", *_PLACED, "subtract", "cut_from")


def _constructor(shape: str, own: tuple[str, ...], summary: str, params: str, example: str,
               tail: tuple[str, ...] = _TAIL) -> Callable[..., PartSpec]:
    """The constructor of ``shape``: keyword arguments name, its ``own`` keys, then ``tail``
    (the body file's keys: a path-like ``file`` is its text; ``from`` is ``from_``), each None
    by default."""
    names = ("name", *own, *tail)

    def make(**kwargs: Any) -> PartSpec:
        for k in kwargs:
            if k not in names:
                raise TypeError(f"{shape}() got an unexpected keyword argument {k!r}")
        if isinstance(kwargs.get("file"), os.PathLike):
            kwargs["file"] = os.fspath(kwargs["file"])
        return _spec(shape, {k: kwargs.get(k) for k in names})

    make.__signature__ = inspect.Signature(  # type: ignore[attr-defined]
        [inspect.Parameter(n, inspect.Parameter.KEYWORD_ONLY, default=None,
                           annotation=_TYPES.get(n, Quantity) | None) for n in names],
        return_annotation=PartSpec)
    make.__name__ = make.__qualname__ = shape
    return _documented(summary, params, example)(make)


def _spec(shape: str, args: dict[str, Any]) -> PartSpec:
    """The spec of a constructor's arguments: ``name``, ``shape``, then the keys given in the
    signature's order (``from_`` is ``from``), each value frozen."""
    data: dict[str, object] = {}
    if args.get("name") is not None:
        data["name"] = freeze(args["name"], "name")
    data["shape"] = shape
    for key, value in args.items():
        if value is None or key == "name":
            continue
        k = "from" if key == "from_" else key
        data[k] = freeze(value, key)
    return PartSpec(data)


# --- shapes


point = _constructor(
    "point", (),
    "A point mass.",
    "",
    """
>>> import rbcli
>>> p = rbcli.parts.point(name="weight", mass="20 g", at=["350 mm", 0, 0])
>>> p
rbcli.parts.point(name='weight', mass='20 g', at=['350 mm', 0, 0])
>>> b = rbcli.Body.from_parts([p])
>>> round(float(rbcli.inertia(b, about="origin").inertia[2][2]), 12)   # m r², kg m²
0.00245
""")


rod = _constructor(
    "rod", ('length', 'from_', 'to'),
    "A thin rod along its local z axis, centred on its local origin (or from one point to "
    "another).",
    """
length : float or str, optional
    m: the rod's length (not with ``from_`` and ``to``).
from_, to : sequence of 3, optional
    The rod's ends, in the body frame (the body file's ``from`` and ``to``): they place it,
    so ``at``, ``axis`` and ``rotate`` do not go with them.
""",
    """
>>> import rbcli
>>> b = rbcli.Body.from_parts([rbcli.parts.rod(length="1 m", mass=3)])
>>> round(float(rbcli.inertia(b).inertia_com[0][0]), 12)   # m L²/12, kg m²
0.25
>>> b = rbcli.Body.from_parts([rbcli.parts.rod(from_=[0, 0, 0], to=[0, 0, 2], mass=3)])
>>> round(float(rbcli.inertia(b).inertia_com[0][0]), 12)   # L = 2 m
1.0
""")


ring = _constructor(
    "ring", ('radius', 'diameter'),
    "A thin hoop in its local xy plane, centred on its local origin.",
    """
radius : float or str, optional
    m (or ``diameter``).
diameter : float or str, optional
    m, instead of ``radius``.
""",
    """
>>> import rbcli
>>> b = rbcli.Body.from_parts([rbcli.parts.ring(radius=0.5, mass=2)])
>>> round(float(rbcli.inertia(b).inertia_com[2][2]), 12)   # m R², kg m²
0.5
""")


disk = _constructor(
    "disk", ('radius', 'inner_radius', 'diameter', 'inner_diameter'),
    "A thin disk or annulus in its local xy plane, centred on its local origin.",
    """
radius : float or str, optional
    m: the outer radius (or ``diameter``).
inner_radius : float or str, optional
    m: the hole's radius, for an annulus (or ``inner_diameter``).
diameter, inner_diameter : float or str, optional
    m, instead of the radii.
""",
    """
>>> import rbcli
>>> b = rbcli.Body.from_parts([rbcli.parts.disk(radius="300 mm", mass=12)])
>>> round(float(rbcli.inertia(b).inertia_com[2][2]), 12)   # m R²/2, kg m²
0.54
""")


plate = _constructor(
    "plate", ('size', 'thickness'),
    "A thin rectangle a × b in its local x, y (with a thickness, a box), centred on its "
    "local origin.",
    """
size : sequence of 2, optional
    m: [a, b].
thickness : float or str, optional
    m: t along local z (then a ``density`` may be given).
""",
    """
>>> import rbcli
>>> b = rbcli.Body.from_parts([rbcli.parts.plate(size=[0.3, 0.4], mass=1.2)])
>>> round(float(rbcli.inertia(b).inertia_com[2][2]), 12)   # m (a² + b²)/12, kg m²
0.025
""")


triangle = _constructor(
    "triangle", ('vertices',),
    "A thin triangular lamina given by its three corners (in its local frame).",
    """
vertices : sequence of 3 points, optional
    m: [[x, y, z], [x, y, z], [x, y, z]].
""",
    """
>>> import rbcli
>>> t = rbcli.parts.triangle(vertices=[[0, 0, 0], [1, 0, 0], [0, 1, 0]], mass=6)
>>> [round(x, 12) for x in rbcli.inertia(rbcli.Body.from_parts([t])).com.tolist()]
[0.333333333333, 0.333333333333, 0.0]
""")


box = _constructor(
    "box", ('size',),
    "A solid cuboid a × b × c along its local x, y, z, centred on its local origin.",
    """
size : sequence of 3, optional
    m: [a, b, c].
""",
    """
>>> import rbcli
>>> b = rbcli.Body.from_parts([rbcli.parts.box(size=[0.1, 0.2, 0.3], mass=2)])
>>> round(float(rbcli.inertia(b).inertia_com[2][2]), 12)   # m (a² + b²)/12, kg m²
0.008333333333
""")


cylinder = _constructor(
    "cylinder", ('radius', 'length', 'inner_radius', 'shell', 'diameter', 'inner_diameter'),
    "A solid cylinder or tube along its local z axis (``shell=True``: a thin wall), centred "
    "on its local origin.",
    """
radius : float or str, optional
    m: the outer radius (or ``diameter``).
length : float or str, optional
    m, along local z.
inner_radius : float or str, optional
    m: the bore of a tube (or ``inner_diameter``).
shell : bool, optional
    True for a thin wall without end caps (then ``areal_density``).
diameter, inner_diameter : float or str, optional
    m, instead of the radii.
""",
    """
>>> import rbcli
>>> c = rbcli.parts.cylinder(radius="50 mm", length="400 mm", density="7850 kg/m^3")
>>> round(rbcli.inertia(rbcli.Body.from_parts([c])).mass, 6)   # ρ π R² L, kg
24.661502
""")


sphere = _constructor(
    "sphere", ('radius', 'inner_radius', 'shell', 'diameter', 'inner_diameter'),
    "A solid or hollow sphere (``shell=True``: a thin shell), centred on its local origin.",
    """
radius : float or str, optional
    m: the outer radius (or ``diameter``).
inner_radius : float or str, optional
    m: the cavity of a hollow sphere (or ``inner_diameter``).
shell : bool, optional
    True for a thin shell (then ``areal_density``).
diameter, inner_diameter : float or str, optional
    m, instead of the radii.
""",
    """
>>> import rbcli
>>> b = rbcli.Body.from_parts([rbcli.parts.sphere(radius=0.1, mass=5)])
>>> round(float(rbcli.inertia(b).inertia_com[2][2]), 12)   # 2 m R²/5, kg m²
0.02
""")


hemisphere = _constructor(
    "hemisphere", ('radius', 'diameter'),
    "A solid hemisphere, its dome towards local +z, its local origin at the centre of its "
    "flat face.",
    """
radius : float or str, optional
    m (or ``diameter``).
diameter : float or str, optional
    m, instead of ``radius``.
""",
    """
>>> import rbcli
>>> b = rbcli.Body.from_parts([rbcli.parts.hemisphere(radius=0.1, mass=1)])
>>> round(float(rbcli.inertia(b).com[2]), 12)   # 3R/8 above the flat face, m
0.0375
""")


cone = _constructor(
    "cone", ('radius', 'height', 'diameter'),
    "A solid right circular cone, its apex towards local +z, its local origin at the centre "
    "of its base.",
    """
radius : float or str, optional
    m: the base's radius (or ``diameter``).
height : float or str, optional
    m.
diameter : float or str, optional
    m, instead of ``radius``.
""",
    """
>>> import rbcli
>>> b = rbcli.Body.from_parts([rbcli.parts.cone(radius=0.1, height=0.4, mass=3)])
>>> round(float(rbcli.inertia(b).com[2]), 12)   # h/4 above the base, m
0.1
""")


ellipsoid = _constructor(
    "ellipsoid", ('semi_axes',),
    "A solid ellipsoid with semi-axes a, b, c along its local x, y, z, centred on its local "
    "origin.",
    """
semi_axes : sequence of 3, optional
    m: [a, b, c].
""",
    """
>>> import rbcli
>>> e = rbcli.parts.ellipsoid(semi_axes=[0.1, 0.2, 0.3], mass=5)
>>> round(float(rbcli.inertia(rbcli.Body.from_parts([e])).inertia_com[2][2]), 12)   # m (a² + b²)/5
0.05
""")


torus = _constructor(
    "torus", ('major_radius', 'minor_radius'),
    "A solid torus (a tyre, an O-ring) about its local z axis, centred on its local origin.",
    """
major_radius : float or str, optional
    m: from the axis to the tube's centre line.
minor_radius : float or str, optional
    m: the tube's radius.
""",
    """
>>> import rbcli
>>> t = rbcli.parts.torus(major_radius=0.3, minor_radius=0.05, mass=2)
>>> round(float(rbcli.inertia(rbcli.Body.from_parts([t])).inertia_com[2][2]), 12)   # m (R² + 3r²/4)
0.18375
""")


# --- the special parts


mesh = _constructor(
    "mesh", ("file", "scale", "units", "allow_open", "weld"),
    "A closed triangle mesh read from an STL or OBJ file (a CAD export), of uniform density.",
    """
file : str or path-like, optional
    The mesh file (.stl, .obj), relative to ``base_dir`` of :meth:`rbcli.Body.from_parts`
    (default: the current folder).
scale : float or str, optional
    A factor for the coordinates.
units : str, optional
    The length unit of the file's coordinates (``"mm"``); default the body's.
allow_open : bool, optional
    Accept a mesh with small holes, with a warning.
weld : float or str, optional
    m: join vertices closer than this (``"exact"``: only equal ones); default the file's.
""",
    """
>>> import rbcli
>>> m = rbcli.parts.mesh(file="examples/cad_block.obj", units="mm", density="2700 kg/m^3")
>>> b = rbcli.Body.from_parts([m])
>>> round(rbcli.inertia(b).mass, 6)   # 2700 kg/m³ × 80 × 40 × 20 mm³, kg
0.1728
""", _SOLID)


step = _constructor(
    "step", ("file", "part", "solids", "units", "scale"),
    "The solids of a STEP file (a CAD part or assembly), each a part with its exact volume "
    "properties from the B-rep (needs ``pip install 'rbcli[cad]'``).",
    """
file : str or path-like, optional
    The STEP file, relative to ``base_dir`` of :meth:`rbcli.Body.from_parts`.
part : str, optional
    Only the solids this name or pattern (``"link*"``) matches.
solids : mapping, optional
    A material or density per solid name or pattern: ``{"pin*": "steel"}``.
units, scale : str; float or str, optional
    Override the file's length unit (with a note).
""",
    """
>>> import rbcli
>>> rbcli.parts.step(name="arm", file="examples/cad/step_arm.step", material="aluminium 6061",
...                  solids={"*pin": "steel"})
rbcli.parts.step(name='arm', file='examples/cad/step_arm.step', solids={'*pin': 'steel'}, material='aluminium 6061')
""", _SOLID)


given = _constructor(
    "given", ("mass", "com", "inertia", "convention"),
    "A part given by its mass properties (a CAD report, a data sheet): mass, centre of mass "
    "and inertia about it.",
    """
com : sequence of 3, optional
    m: the centre of mass, in the part's local frame (default its origin).
inertia : 3 × 3 sequence or mapping, optional
    kg m² about the centre of mass, local axes: a matrix, or its entries by the names CAD
    reports use (``{"Ixx": ..., "Iyy": ..., "Izz": ..., "Ixy": ...}``).
convention : str, optional
    ``"tensor"`` (off-diagonal entries −∫xy dm) or ``"positive"`` (+∫xy dm, as many CAD
    tools print products of inertia): needed when a product is not zero.
""",
    """
>>> import rbcli
>>> g = rbcli.parts.given(mass=2, inertia=[[0.01, 0, 0], [0, 0.02, 0], [0, 0, 0.025]])
>>> round(float(rbcli.inertia(rbcli.Body.from_parts([g])).inertia_com[2][2]), 12)
0.025
""", (*_PLACED, "subtract"))


include = _constructor(
    "include", ("file",),
    "Another body file's parts, placed as a whole (an assembly of sub-assemblies).",
    """
file : str or path-like, optional
    The body file, relative to ``base_dir`` of :meth:`rbcli.Body.from_parts` (default: the
    current folder); its parts are named ``name/part``.
""",
    """
>>> import rbcli
>>> wheels = rbcli.Body.from_parts([
...     rbcli.parts.include(name="front", file="examples/car_wheel.yaml", at=[0, 0, 1.2]),
...     rbcli.parts.include(name="rear", file="examples/car_wheel.yaml"),
... ])
>>> one = rbcli.load("examples/car_wheel.yaml")
>>> rbcli.inertia(wheels).mass == 2 * rbcli.inertia(one).mass
True
""", _PLACED)

