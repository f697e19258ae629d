"""Read a body file (YAML) into a validated :class:`rbcli.model.Body` in SI units.

Every problem is an :class:`rbcli.errors.InputError` located at ``file:line:col``.
The walk is strict: numbers must be numbers (``true`` is not 1.0), strings with
units must have the right dimension, unknown keys are refused with a
"did you mean" hint, and the finished body must be physically possible.
"""

from __future__ import annotations

import gc
import math
import os
import stat
import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import NamedTuple

import numpy as np

from rbcli.core import rotation as rot
from rbcli.core import shapes as shp
from rbcli.core.inertia import combine, remember_mass_props, tensor_problem
from rbcli.errors import InputError, Location
from rbcli.io import fields as fl
from rbcli.io import units as un
from rbcli.io import yamlsafe as ys
from rbcli.io.fields import HUGE
from rbcli.io.placing import BATCH, Pending, Stack, dims_of, finish, parts_of, to_stack
from rbcli.model import Body, Part, Shaft

MAX_INCLUDE_DEPTH = 16
#: the default budget of a body: its parts, counting every use of an included file's parts
#: and each include once; RBCLI_MAX_PARTS raises it (README, "Budgets")
MAX_PARTS = 200_000
FORMAT_VERSION = 1

BODY_KEYS = (
    "rbcli", "name", "description", "units", "parts", "reference", "shaft", "pivot",
    "rim_radius",
)
UNIT_KEYS = ("length", "mass", "time", "angle", "angular_speed")
PLACEMENT_KEYS = ("at", "axis", "rotate")
MASS_KEYS = ("mass", "density", "areal_density", "linear_density")
DENSITY_FOR = {
    "volume": "density",
    "area": "areal_density",
    "length": "linear_density",
}
COMMON_PART_KEYS = ("name", "shape", "subtract", "cut_from", *PLACEMENT_KEYS, *MASS_KEYS)
SPECIAL_SHAPES = tuple(shp.IO_SHAPES)  # mesh, given, include: built here, not by core.shapes
GIVEN_KEYS = ("name", "shape", "subtract", "mass", "com", "inertia", "convention", *PLACEMENT_KEYS)
INCLUDE_KEYS = ("name", "shape", "file", *PLACEMENT_KEYS)
MESH_KEYS = (
    "name", "shape", "file", "scale", "units", "allow_open", "weld", "subtract", "cut_from",
    "mass", "density", *PLACEMENT_KEYS,
)
INERTIA_MAP_KEYS = ("Ixx", "Iyy", "Izz", "Ixy", "Iyz", "Izx", "convention")


def all_shape_names() -> list[str]:
    return [*shp.SHAPES.keys(), *SPECIAL_SHAPES]


def _a(word: str) -> str:
    """``word`` with its indefinite article: "an area", "a volume"."""
    return f"{'an' if word[:1] in 'aeiou' else 'a'} {word}"


# --------------------------------------------------------------------------- context


@dataclass
class _Session:
    """What one load shares across its files: the parts budget and the files already
    read and parsed (an included file is read and parsed once per real path, and its
    parts placed per use, so a diamond of includes costs time linear in the files)."""

    max_parts: int
    used: int = 0  # parts and includes so far, every use counted
    parsed: dict = field(default_factory=dict)  # (real path, real folder) -> _Loaded
    parses: int = 0  # files parsed (the work count the tests check)

    def spend(self, ctx: "_Ctx", node: "ys.Node | None", n: int) -> None:
        self.used += n
        if self.used > self.max_parts:
            raise ctx.error(
                node,
                f"the body has more than {self.max_parts} parts (counting every use of an "
                f"included file's parts, and each include); set RBCLI_MAX_PARTS to raise the "
                "limit",
            )


def _session() -> _Session:
    from rbcli.io.reader import limit_from_env

    return _Session(limit_from_env("RBCLI_MAX_PARTS", MAX_PARTS))


@dataclass
class _Ctx:
    file: str  # as shown in messages
    base_dir: Path  # where relative paths start
    stack: tuple[str, ...] = ()  # real paths of the files being included (cycle check)
    base_units: dict[str, str] = field(default_factory=dict)
    factors: dict[str, tuple[float, str]] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    #: real paths of the files read below this one (includes at any depth, meshes)
    inputs: list[str] = field(default_factory=list)
    session: _Session = field(default_factory=lambda: _Session(MAX_PARTS))
    #: how deep includes go below this file (0: it includes nothing)
    height: int = 0

    def where(self, node_or_mark: ys.Node | ys.Mark | None) -> Location:
        if node_or_mark is None:
            return Location(self.file)
        mark = node_or_mark if isinstance(node_or_mark, ys.Mark) else node_or_mark.mark
        return Location(self.file, mark.line, mark.col)

    def error(self, node_or_mark: ys.Node | ys.Mark | None, message: str) -> InputError:
        return InputError(message, self.where(node_or_mark))

    def factor(self, kind: str, node: ys.Node | None = None) -> tuple[float, str]:
        if kind not in self.factors:
            try:
                self.factors[kind] = un.unit_for_kind(self.base_units, kind)
            except un.UnitError as exc:
                raise self.error(node, str(exc)) from None
        return self.factors[kind]


# --------------------------------------------------------------------------- parts


#: what later parts may need from an earlier one (cut_from), by its name: the pair
#: (its density, or None; its measure kind)
_Known = tuple


def _mass_source(ctx: _Ctx, m: ys.MapNode, measure_kind: str, known: dict[str, _Known], what: str):
    """Return (mass or None, density or None, the node to blame)."""
    items = m.items
    given = list(filter(items.__contains__, MASS_KEYS))  # in MASS_KEYS's order
    cut = items.get("cut_from")
    if cut is not None:
        given.append("cut_from")
    if len(given) > 1:
        raise ctx.error(
            m.items[given[1]][0] if given[1] in m.items else m,
            f"{what} gives both '{given[0]}' and '{given[1]}'; give exactly one of "
            "mass, density, areal_density, linear_density (or cut_from for a hole)",
        )
    if not given:
        want = DENSITY_FOR.get(measure_kind)
        alt = f" or {want}" if want else ""
        raise ctx.error(m, f"{what} needs its mass{alt}")
    key = given[0]
    kmark, node = (cut if key == "cut_from" else m.items[key])
    if key == "mass":
        return fl.positive(ctx, node, "mass", f"{what}: mass"), None, node
    if key == "cut_from":
        if "subtract" not in m.items or not fl.flag(ctx, m.items["subtract"][1], "subtract"):
            raise ctx.error(kmark, "cut_from is for holes: it needs 'subtract: true'")
        src = fl.string(ctx, node, "cut_from")
        if src not in known:
            raise ctx.error(node, f"cut_from: no earlier part is named '{src}'{fl.suggest(src, list(known))}")
        density, kind = known[src]
        if density is None:
            raise ctx.error(node, f"cut_from: part '{src}' has no density to take (it is a {kind})")
        if kind != measure_kind:
            raise ctx.error(
                node,
                f"cut_from: part '{src}' has {_a(DENSITY_FOR.get(kind, kind))} "
                f"but this {measure_kind} part needs {_a(DENSITY_FOR.get(measure_kind, 'mass'))}",
            )
        return None, density, node
    want = DENSITY_FOR.get(measure_kind)
    if key != want:
        hint = f"; use '{want}'" if want else "; give its mass"
        raise ctx.error(kmark, f"{what} is {_a(measure_kind)} part, so '{key}' does not apply{hint}")
    kind = key  # density, areal_density, linear_density are also unit kinds
    return None, fl.positive(ctx, node, kind, f"{what}: {key}"), node


def _part_name(ctx: _Ctx, m: ys.MapNode, index: int, shape: str, names: set[str]) -> str:
    item = m.items.get("name")
    if item is not None:
        name = fl.string(ctx, item[1], "name")
        if not name.strip():
            raise ctx.error(item[1], "a part name must not be empty")
    else:
        name = f"{shape}{index + 1}"
    if name in names:
        raise ctx.error(item[1] if item is not None else m, f"two parts are named '{name}'; names must differ")
    names.add(name)
    return name


def _place(part_com, part_I, at, R):
    return at + R @ part_com, R @ part_I @ R.T


def _parts(ctx: _Ctx, node: ys.Node, prefix: str = "", *, stacked: bool = False) -> list[Part] | Stack:
    """The parts of the list ``node``: as :class:`Part` s, or for an included file
    (``stacked``) as one :class:`rbcli.io.placing.Stack` (each use moves it)."""
    if not isinstance(node, ys.SeqNode):
        raise ctx.error(node, f"parts must be a list of parts, not {fl.describe(node)}")
    if not node.items:
        raise ctx.error(node, "parts is empty; a body needs at least one part")
    out: list = []  # Pending, Part or Stack (an include's parts)
    names: set[str] = set()
    known: dict[str, _Known] = {}
    settle = to_stack if stacked else finish  # the primitives of out[done:], placed
    done = 0  # out[:done] are placed
    waiting = 0  # parts in out[done:]
    for i, item in enumerate(node.items):
        if not _is_include(item):
            ctx.session.spend(ctx, item, 1)
        p = _part(ctx, item, i, names, known, prefix)
        out.append(p)
        waiting += len(p) if p.__class__ is Stack else 1
        if waiting >= BATCH:
            done = len(settle(out, done))
            waiting = 0
    out = settle(out, done)
    return Stack.of(out) if stacked else parts_of(out)


def _is_include(node: ys.Node) -> bool:
    if not isinstance(node, ys.MapNode):
        return False
    shape = node.items.get("shape")
    return shape is not None and isinstance(shape[1], ys.ScalarNode) and shape[1].value == "include"


def _part(ctx: _Ctx, node: ys.Node, index: int, names: set[str], known: dict[str, _Known], prefix: str):
    """One entry of ``parts``: a primitive as a :class:`Pending` (placed by
    :func:`rbcli.io.placing.finish` with others), an include as a :class:`Stack` of its
    file's parts, a mesh or given part as a finished :class:`Part`."""
    m = node if isinstance(node, ys.MapNode) else fl.mapping(ctx, node, f"part {index + 1}")
    shape_item = m.items.get("shape")
    if shape_item is None:
        raise ctx.error(m, f"part {index + 1} needs 'shape' (one of: {', '.join(all_shape_names())})")
    shape_node = shape_item[1]
    shape = fl.string(ctx, shape_node, "shape")
    if shape not in shp.SHAPES and shape not in SPECIAL_SHAPES:
        raise ctx.error(
            shape_node,
            f"unknown shape '{shape}'{fl.suggest(shape, all_shape_names())} (shapes: {', '.join(all_shape_names())})",
        )
    name = _part_name(ctx, m, index, shape, names)
    what = f"part '{name}'"
    if shape == "include":
        return _include(ctx, m, name, prefix)
    if shape == "given":
        return _given(ctx, m, name, prefix, known)
    if shape == "mesh":
        return _mesh(ctx, m, name, prefix, known)
    return _primitive(ctx, m, shape, name, prefix, known, what)


def _subtract(ctx: _Ctx, m: ys.MapNode) -> bool:
    return fl.flag(ctx, m.items["subtract"][1], "subtract") if "subtract" in m.items else False


class _Plan(NamedTuple):
    """How to read a part of one primitive shape (:func:`_plan`, made once per shape)."""

    keys: tuple[str, ...]  # every key it takes, in the order messages list them
    key_set: frozenset[str]
    diameters: dict[str, str]  # a diameter spelling -> the radius it gives
    required: tuple[str, ...]  # its parameters (ShapeInfo.required, .optional)
    optional: tuple[str, ...]
    kinds: tuple[tuple[str, str, int], ...]  # (parameter, its Kind's name, its n), in order
    build: Callable  # the shape's formulas (core.shapes.builder): parameters checked here
    radius: Callable | None  # ShapeInfo.radius of a round shape, else None


_PLANS: dict[str, _Plan] = {}


def _plan(shape: str) -> _Plan:
    plan = _PLANS.get(shape)
    if plan is None:
        info = shp.SHAPES[shape]
        extra_keys = ("from", "to") if shape == "rod" else ()
        diameters = info.diameters
        params = (*info.required, *info.optional)
        keys = (*COMMON_PART_KEYS, *params, *diameters, *extra_keys)
        kinds = tuple((k, info.kind(k).name, info.kind(k).n) for k in params)
        plan = _PLANS[shape] = _Plan(keys, frozenset(keys), diameters, info.required, info.optional,
                                     kinds, shp.builder(shape), info.radius if info.round else None)
    return plan


def _primitive(ctx, m, shape, name, prefix, known, what) -> Pending:
    plan = _plan(shape)
    diameters = plan.diameters
    items = m.items
    if not plan.key_set.issuperset(items):
        fl.check_keys(ctx, m, plan.keys, f"{what} ({shape})")
    params: dict[str, object] = {}
    nodes: dict[str, ys.Node] = {}
    for dkey, rkey in diameters.items():
        if dkey not in items:
            continue
        if rkey in items:
            raise ctx.error(items[dkey][0], f"{what}: give '{rkey}' or '{dkey}', not both")
        nodes[rkey] = items[dkey][1]
        params[rkey] = 0.5 * fl.number(ctx, nodes[rkey], "length", dkey)
    at, spec = fl.placement_spec(ctx, m)
    if shape == "rod" and ("from" in items or "to" in items):
        for k in ("from", "to"):
            if k not in items:
                raise ctx.error(m, f"{what}: a rod given by endpoints needs both 'from' and 'to'")
        for k in ("length", *PLACEMENT_KEYS):
            if k in items:
                raise ctx.error(items[k][0], f"{what}: '{k}' does not go with 'from'/'to' (the endpoints place the rod)")
        a = fl.vector(ctx, items["from"][1], "length", "from")
        b = fl.vector(ctx, items["to"][1], "length", "to")
        if not np.linalg.norm(b - a) > 0:
            raise ctx.error(items["to"][1], f"{what}: 'from' and 'to' are the same point")
        params["length"] = float(np.linalg.norm(b - a))
        at = (0.5 * (a + b)).tolist()
        spec = ("R", rot.axis_to_z(b - a))
    for key in plan.required:
        if key not in items and key not in params:
            alt = next((f" or '{d}'" for d, r in diameters.items() if r == key), "")
            params_allowed = (*plan.required, *plan.optional)
            raise ctx.error(m, f"{what} ({shape}) needs '{key}'{alt} (parameters: {', '.join(params_allowed) or 'none'})")
    for key, kind, n in plan.kinds:
        if key not in items or key in params:
            continue
        vnode = items[key][1]
        nodes[key] = vnode
        if kind == "length":
            params[key] = fl.number(ctx, vnode, "length", key)
        elif kind == "lengths":
            params[key] = fl.floats(ctx, vnode, "length", key, n=n)
        elif kind == "points":
            params[key] = fl.rows(ctx, vnode, "length", key)
        elif kind == "bool":
            params[key] = fl.flag(ctx, vnode, key)
    try:
        geo = plan.build(params)  # what shp.local_geometry checks first, checked above
    except shp.ShapeError as exc:  # lengths quoted in the file's own length unit
        factor, unit = ctx.factors.get("length") or un.unit_for_kind(ctx.base_units, "length")
        message = exc.format(lambda x: f"{x / factor:g} {unit}")
        raise ctx.error(nodes.get(exc.param, m), f"{what}: {message}") from None
    except ValueError as exc:
        raise ctx.error(m, f"{what}: {exc}") from None
    measure_kind = geo.measure_kind
    mass, density, src = _mass_source(ctx, m, measure_kind, known, what)
    if measure_kind == "point":
        measure = None
        known[name] = (None, measure_kind)
    else:
        measure = float(geo.measure)
        if mass is None:
            mass = density * measure
            _check_mass(ctx, src, what, mass, f"density × {measure_kind}")
        elif measure:
            density = mass / measure
        known[name] = (density, measure_kind)
    if not mass > 0:
        raise ctx.error(m, f"{what} has no mass")
    mark = m.mark
    radius = plan.radius
    return Pending(
        prefix + name, shape, mass, "subtract" in items and _subtract(ctx, m), measure,
        measure_kind, radius and radius(params), Location(ctx.file, mark.line, mark.col), at,
        spec, geo.com, geo.unit_inertia, dims_of(params),
    )


def _check_mass(ctx: _Ctx, node: ys.Node, what: str, mass: float, how: str) -> None:
    """A mass computed from a density must stay within the limits of any number (HUGE)."""
    if not mass <= HUGE:  # also refuses inf and nan
        raise ctx.error(
            node,
            f"{what}: its mass ({how}) is {mass:.3g} kg, too large; "
            "numbers are limited to 1e60 in SI units",
        )


def _given(ctx, m, name, prefix, known) -> Part:
    what = f"part '{name}' (given)"
    fl.check_keys(ctx, m, GIVEN_KEYS, what, required=("mass", "inertia"))
    mass = fl.positive(ctx, m.items["mass"][1], "mass", f"{what}: mass")
    com = fl.vector(ctx, m.items["com"][1], "length", "com") if "com" in m.items else np.zeros(3)
    inode = m.items["inertia"][1]
    if isinstance(inode, ys.MapNode):
        fl.check_keys(ctx, inode, INERTIA_MAP_KEYS, "inertia", required=("Ixx", "Iyy", "Izz"))
        g = {k: fl.number(ctx, inode.items[k][1], "inertia", k) if k in inode.items else 0.0 for k in INERTIA_MAP_KEYS[:6]}
        has_products = any(k in inode.items for k in ("Ixy", "Iyz", "Izx"))
        sign = -1.0
        if "convention" in inode.items:
            conv_node = inode.items["convention"][1]
            conv = fl.string(ctx, conv_node, "convention")
            if conv not in ("tensor", "positive"):
                raise ctx.error(conv_node, f"convention must be 'tensor' or 'positive', not '{conv}'")
            sign = 1.0 if conv == "tensor" else -1.0
        elif has_products:
            raise ctx.error(
                inode,
                "inertia with products needs 'convention: tensor' (Ixy = −∫xy dm, the tensor's "
                "entry) or 'convention: positive' (Ixy = +∫xy dm, as many CAD tools print it)",
            )
        J = np.array(
            [
                [g["Ixx"], sign * g["Ixy"], sign * g["Izx"]],
                [sign * g["Ixy"], g["Iyy"], sign * g["Iyz"]],
                [sign * g["Izx"], sign * g["Iyz"], g["Izz"]],
            ]
        )
        if "convention" in m.items:
            raise ctx.error(m.items["convention"][0], f"{what}: the Ixx... form states its "
                            "convention inside 'inertia'; remove the part's 'convention'")
    else:
        J = fl.matrix(ctx, inode, "inertia", "inertia")
        off = J[~np.eye(3, dtype=bool)]
        if "convention" in m.items:
            conv_node = m.items["convention"][1]
            conv = fl.string(ctx, conv_node, "convention")
            if conv not in ("tensor", "positive"):
                raise ctx.error(conv_node, f"convention must be 'tensor' or 'positive', not '{conv}'")
            if conv == "positive":
                J = np.where(np.eye(3, dtype=bool), J, -J)
        elif np.any(off != 0.0):
            raise ctx.error(
                inode,
                f"{what}: a 3x3 inertia with non-zero off-diagonal entries needs 'convention: "
                "tensor' (entries are the tensor's, −∫xy dm) or 'convention: positive' (products "
                "of inertia +∫xy dm, as many CAD tools print them) beside it",
            )
    factor, unit = ctx.factor("inertia", inode)
    problem = tensor_problem(J, unit=_pretty_unit(unit), factor=factor)
    if problem:
        raise ctx.error(inode, f"{what}: the inertia is not physically possible: {problem}")
    J = 0.5 * (J + J.T)
    at, R = fl.placement(ctx, m)
    known[name] = (None, "given")
    pc, PJ = _place(com, J, at, R)
    return Part(
        name=prefix + name, shape="given", mass=mass, subtract=_subtract(ctx, m), com=pc,
        inertia_com=PJ, measure=None, measure_kind="given", axis=R[:, 2].copy(), where=ctx.where(m),
        outline=_given_outline(mass, pc, PJ),
    )


def _pretty_unit(text: str) -> str:
    """``g*mm^2`` as ``g·mm²`` for messages."""
    return text.replace("*", "·").replace("^2", "²").replace("^3", "³")


def _given_outline(mass: float, com: np.ndarray, J: np.ndarray):
    """A given part is drawn as its equivalent uniform ellipsoid, centred on its com."""
    from rbcli.core.outline import equivalent_ellipsoid
    from rbcli.model import Outline

    semi, axes = equivalent_ellipsoid(mass, J)
    return Outline("given", (("semi_axes", tuple(float(x) for x in semi)),), com, axes)


def _resolve(ctx: _Ctx, node: ys.Node, what: str) -> Path:
    rel = fl.string(ctx, node, what)
    path = Path(rel)
    if not path.is_absolute():
        path = ctx.base_dir / path
    return path


def _include(ctx, m, name, prefix) -> Stack:
    what = f"part '{name}' (include)"
    fl.check_keys(ctx, m, INCLUDE_KEYS, what, required=("file",))
    fnode = m.items["file"][1]
    path = _resolve(ctx, fnode, "file")
    where = ctx.where(fnode)
    if "\x00" in str(path):
        raise ctx.error(fnode, "the file name contains a NUL character")
    real = os.path.realpath(path)
    if real in ctx.stack:
        chain = " -> ".join(os.path.basename(p) for p in (*ctx.stack, real))
        raise ctx.error(fnode, f"include cycle: {chain}")
    if len(ctx.stack) >= MAX_INCLUDE_DEPTH:
        raise ctx.error(fnode, f"includes are nested more than {MAX_INCLUDE_DEPTH} deep")
    session = ctx.session
    key = (real, os.path.realpath(path.parent))
    sub = session.parsed.get(key)
    if sub is None:
        data = _read_file(path, where)
        session.parses += 1
        sub = _load(data, str(path), path.parent, (*ctx.stack, real), session=session, stacked=True)
        sub.root = None  # its YAML tree: only the top file's is read again (memory)
        session.parsed[key] = sub
    elif len(ctx.stack) + sub.ctx.height >= MAX_INCLUDE_DEPTH:
        # parsed before, higher up: the same file here would nest includes too deep
        raise ctx.error(fnode, f"includes are nested more than {MAX_INCLUDE_DEPTH} deep")
    else:  # parsed before: its parts again, counted again
        session.spend(ctx, fnode, sub.cost)
    ctx.height = max(ctx.height, sub.ctx.height + 1)
    session.spend(ctx, fnode, 1)
    ctx.warnings.extend(sub.warnings)
    ctx.inputs.append(real)
    ctx.inputs.extend(sub.ctx.inputs)
    at, R = fl.placement(ctx, m)
    return sub.parts.moved(at, R, f"{prefix}{name}/")


def _mesh(ctx, m, name, prefix, known) -> Part:
    """A ``shape: mesh`` part: a closed triangle mesh read from an STL or OBJ file.

    Everything in the YAML is checked first (keys, scale, units, mass, placement), then
    the file is read and checked. The mesh modules are imported here only, so that
    bodies without meshes do not pay for them at start-up.
    """
    what = f"part '{name}' (mesh)"
    fl.check_keys(ctx, m, MESH_KEYS, what, required=("file",))
    fnode = m.items["file"][1]
    path = _mesh_path(ctx, fnode)
    scale = 1.0
    if "scale" in m.items:
        scale = fl.positive(ctx, m.items["scale"][1], "dimensionless", f"{what}: scale")
    if "units" in m.items:
        unode = m.items["units"][1]
        text = fl.string(ctx, unode, "units")
        try:
            factor, dim = un.parse_unit(text)
        except un.UnitError as exc:
            raise ctx.error(unode, f"{what}: units: {exc}") from None
        if dim != un.KINDS["length"]:
            raise ctx.error(
                unode,
                f"{what}: units is the length unit of the mesh's coordinates (m, mm, in, ...), not '{text}'",
            )
    else:
        factor = ctx.factor("length", m)[0]
    allow_open = fl.flag(ctx, m.items["allow_open"][1], "allow_open") if "allow_open" in m.items else False
    weld = None  # None: the file's own default (meshfile.default_weld)
    if "weld" in m.items:
        wnode = m.items["weld"][1]
        if isinstance(wnode, ys.ScalarNode) and wnode.value == "exact":
            weld = 0.0
        else:
            weld = fl.positive(ctx, wnode, "length", f"{what}: weld (a length, or exact)", allow_zero=True)
    mass, density, src = _mass_source(ctx, m, "volume", known, what)
    subtract = _subtract(ctx, m)
    at, R = fl.placement(ctx, m)

    from rbcli.core import mesh as cmesh
    from rbcli.io import meshfile

    shown = str(path)
    try:
        vertices, faces, _fmt, file_weld = meshfile.read_mesh(path)
    except meshfile.MeshFileError as exc:  # its message starts with the path
        raise ctx.error(fnode, f"{what}: {exc}") from None
    ctx.inputs.append(os.path.realpath(path))
    k = scale * factor
    if k != 1.0:
        with np.errstate(over="ignore"):
            vertices *= k  # in place: a private float64 array
        if not np.isfinite(vertices).all():
            raise ctx.error(
                fnode,
                f"{what}: {shown}: the coordinates times scale and units overflow "
                "(numbers are limited to 1e60 in SI units)",
            )
    if float(np.abs(vertices).max()) > HUGE:
        raise ctx.error(fnode, f"{what}: {shown}: coordinates are too large; numbers are limited to 1e60 in SI units")
    if weld is None:
        weld = file_weld * k
    try:
        props = cmesh.mass_properties(vertices, faces, allow_open=allow_open, weld=weld, unit="m")
    except cmesh.MeshError as exc:  # says what is wrong, not which file
        msg = str(exc)
        if exc.boundary:
            msg += "; allow_open: true accepts small holes, with a warning"
        raise ctx.error(fnode, f"{what}: {shown}: {msg}") from None
    from rbcli.core.outline import decimate
    from rbcli.model import Outline

    # for drawings: a small copy (at most MESH_MAX_TRIANGLES), not the file's mesh
    outline = Outline("mesh", (("triangles", len(faces)),), at, R, *decimate(vertices, faces))
    del vertices, faces
    for w in props.warnings:
        ctx.warnings.append(f"{ctx.where(fnode)}: warning: {what}: {shown}: {w}")
    if mass is None:
        assert density is not None
        mass = density * props.volume
        _check_mass(ctx, src, what, mass, "density × volume")
    else:
        density = mass / props.volume
    known[name] = (density, "volume")
    com, J = _place(np.asarray(props.centroid), mass * np.asarray(props.unit_inertia), at, R)
    return Part(
        name=prefix + name, shape="mesh", mass=float(mass), subtract=subtract, com=com,
        inertia_com=J, measure=props.volume, measure_kind="volume", axis=R[:, 2].copy(),
        extra={"volume": float(props.volume), "area": float(props.area), "triangles": int(props.n_triangles)},
        where=ctx.where(m), outline=outline,
    )


def _mesh_path(ctx: _Ctx, fnode: ys.Node) -> Path:
    """The mesh file, relative to the body file's folder; as written when that is the cwd."""
    rel = fl.string(ctx, fnode, "file")
    if not rel.strip():
        raise ctx.error(fnode, "file must name a mesh file (.stl or .obj), relative to the body file")
    if "\0" in rel:
        raise ctx.error(fnode, "file: a file name cannot contain a NUL character")
    path = Path(rel)
    if path.is_absolute():
        return path
    try:
        if ctx.base_dir.is_absolute() and ctx.base_dir == Path.cwd():
            return path  # standard input or -e: show the path the user wrote
    except OSError:  # the cwd is gone
        pass
    return ctx.base_dir / path


# --------------------------------------------------------------------------- body


@dataclass
class _Loaded:
    parts: list[Part] | Stack  # a Stack for an included file
    warnings: list[str]
    root: ys.MapNode | None  # the file's YAML tree (None for an included file, once read)
    ctx: _Ctx
    cost: int = 0  # what one use of this file spends of the parts budget


def _units(ctx: _Ctx, m: ys.MapNode) -> None:
    if "units" not in m.items:
        return
    unode = fl.mapping(ctx, m.items["units"][1], "units")
    fl.check_keys(ctx, unode, UNIT_KEYS, "units")
    base = {}
    for key, (_km, vnode) in unode.items.items():
        base[key] = fl.string(ctx, vnode, f"units.{key}")
        try:
            un.unit_for_kind({key: base[key]}, key)
        except un.UnitError as exc:
            msg = str(exc)
            raise ctx.error(vnode, msg if msg.startswith("units:") else f"units: {key}: {msg}") from None
    ctx.base_units = base
    ctx.factors = {}


def _load(data: bytes | str, filename: str, base_dir: Path, stack: tuple[str, ...],
          units: dict[str, str] | None = None, *, session: _Session | None = None,
          stacked: bool = False) -> _Loaded:
    root = ys.load(data, filename)
    session = session if session is not None else _session()
    ctx = _Ctx(file=filename, base_dir=base_dir, stack=stack, session=session)
    spent = session.used
    if units:  # the caller's default units (rbcli.load_text(..., units=...)); the file's win
        for key, unit in units.items():
            if key not in UNIT_KEYS:
                raise InputError(f"units: unknown kind '{key}'; allowed: {', '.join(UNIT_KEYS)}",
                                 Location(filename))
            try:
                un.unit_for_kind({key: unit}, key)
            except un.UnitError as exc:
                raise InputError(f"units: {key}: {exc}", Location(filename)) from None
        ctx.base_units = dict(units)
    if not isinstance(root, ys.MapNode):
        raise ctx.error(root, "a body file is a mapping with 'parts:' (a list of parts), or a single part with 'shape:'")
    if "rbcli" in root.items:
        vnode = root.items["rbcli"][1]
        if not (isinstance(vnode, ys.ScalarNode) and vnode.value == FORMAT_VERSION and not isinstance(vnode.value, bool)):
            raise ctx.error(vnode, f"this rbcli reads body format version {FORMAT_VERSION}, not {vnode.raw if isinstance(vnode, ys.ScalarNode) else '?'}")
    _units(ctx, root)
    if "parts" in root.items:
        fl.check_keys(ctx, root, BODY_KEYS, "the body")
        parts = _parts(ctx, root.items["parts"][1], stacked=stacked)
    elif "shape" in root.items:
        # one-part shorthand: the mapping is the part (plus the body's units/version)
        items = {k: v for k, v in root.items.items() if k not in ("units", "rbcli")}
        stripped = ys.MapNode(root.mark, items)  # the public constructor: (mark, items)
        one = [_part(ctx, stripped, 0, set(), {}, "")]
        parts = to_stack(one)[0] if stacked else parts_of(finish(one))
    else:
        raise ctx.error(root, "a body file needs 'parts:' (a list of parts), or a single part with 'shape:'")
    ctx.inputs = list(dict.fromkeys(ctx.inputs))
    return _Loaded(parts, list(dict.fromkeys(ctx.warnings)), root, ctx, session.used - spent)


def _read_file(path: Path, where: Location | None = None) -> bytes:
    """A body file or an included file: :func:`rbcli.io.reader.read_regular` (a regular
    file only, its size checked before reading)."""
    from rbcli.io.reader import read_regular

    return read_regular(path, _max_bytes(), "body file", where=where, env="RBCLI_MAX_BODY_BYTES")


def _max_bytes() -> int:
    return ys.max_bytes()


def _may_be_impossible(parts: tuple) -> bool:
    """Whether the sum of ``parts`` may not be a physically possible inertia: only when one
    is subtracted or is not a formula shape (a mesh, given mass properties). A sum of
    physically possible tensors (each shape's own, each parallel-axis term a point mass's)
    is physically possible, and :func:`rbcli.core.inertia.tensor_problem`'s tolerance
    (1e-7 of the largest entry) is far above the sum's rounding (~1e-16 of it)."""
    sure = shp.FORMULA_SHAPES
    for p in parts:
        if p.subtract or p.shape not in sure:
            return True
    return False


def _check_possible(ctx: _Ctx, node: ys.Node, J: np.ndarray, factor: float, unit: str) -> None:
    """Refuse a body whose inertia ``J`` (about its com) is not physically possible
    (moments quoted as ``J / factor`` in ``unit``, the file's inertia unit)."""
    problem = tensor_problem(J, rtol=1e-7, unit=_pretty_unit(unit), factor=factor)
    if problem:
        raise ctx.error(
            node,
            f"the body's inertia is not physically possible: {problem} "
            "(is a subtracted part outside the material it is cut from?)",
        )


def _body_defaults(
    loaded: _Loaded, name_default: str, source: str, text: str, inputs: tuple[str, ...] = ()
) -> Body:
    ctx, root = loaded.ctx, loaded.root
    items = root.items
    name = name_default
    if "name" in items:
        name = fl.string(ctx, items["name"][1], "name")
    description = fl.string(ctx, items["description"][1], "description") if "description" in items and "parts" in items else ""
    reference = None
    ref_com = False
    pivot = None
    shaft = None
    rim = None
    if "parts" in items:
        if "reference" in items:
            p = fl.point(ctx, items["reference"][1], "reference")
            if isinstance(p, str):
                ref_com = p == "com"
                reference = None if ref_com else np.zeros(3)
            else:
                reference = p
        if "pivot" in items:
            p = fl.point(ctx, items["pivot"][1], "pivot")
            if isinstance(p, str):
                raise ctx.error(items["pivot"][1], "pivot must be a point [x, y, z]")
            pivot = p
        if "shaft" in items:
            snode = fl.mapping(ctx, items["shaft"][1], "shaft")
            fl.check_keys(ctx, snode, ("axis", "through"), "shaft", required=("axis",))
            axis = fl.direction(ctx, snode.items["axis"][1], "shaft axis")
            through = fl.vector(ctx, snode.items["through"][1], "length", "shaft through") if "through" in snode.items else np.zeros(3)
            shaft = Shaft(axis, through)
        if "rim_radius" in items:
            rim = fl.positive(ctx, items["rim_radius"][1], "length", "rim_radius")
    parts = tuple(loaded.parts)
    node = items["parts"][1] if "parts" in items else root
    try:
        with np.errstate(over="ignore", invalid="ignore"):
            mp = combine(parts)
    except ValueError as exc:
        raise ctx.error(node, str(exc)) from None
    if not all(map(math.isfinite, (*mp.com.tolist(), *mp.inertia_com.ravel().tolist()))):
        raise ctx.error(
            node,
            "the body's mass properties overflow (a mass times a squared distance exceeds "
            "1e308); numbers are limited to 1e60 in SI units",
        )
    factor, unit = ctx.factor("inertia", node)  # its unit errors, whether or not it is used
    if _may_be_impossible(parts):
        _check_possible(ctx, node, mp.inertia_com, factor, unit)
    body = Body(
        name=name, source=source, text=text, parts=parts, reference=reference,
        reference_is_com=ref_com, shaft=shaft, pivot=pivot, rim_radius=rim,
        description=description, warnings=tuple(loaded.warnings), inputs=inputs,
        units=dict(loaded.ctx.base_units),
    )
    remember_mass_props(body, mp)  # commands take it from there (body_mass_props)
    return body


def load_body(source: str, *, stdin: object = None) -> Body:
    """Load a body from a path, or ``-`` for standard input.

    Raises
    ------
    InputError
        For anything wrong with the file or its contents, located at file:line:col.
    """
    if source == "-":
        from rbcli.io.reader import read_stream

        stream = stdin if stdin is not None else getattr(sys.stdin, "buffer", sys.stdin)
        data = read_stream(stream, _max_bytes(), "body file", env="RBCLI_MAX_BODY_BYTES")  # type: ignore[arg-type]
        return load_text(data, "<stdin>", Path.cwd(), name_default="body")
    path = Path(source)
    data = _read_file(path)
    return load_text(data, source, path.parent, name_default=path.stem, stack=(_realpath(str(path)),))


#: :func:`_realpath`'s folders: (the cwd for a relative one, the folder as written) ->
#: (its real path, its (st_dev, st_ino)); cleared when it reaches _REAL_DIRS_MAX
_REAL_DIRS: dict[tuple[str, str], tuple[str, tuple[int, int]]] = {}
_REAL_DIRS_MAX = 256


def _realpath(path: str) -> str:
    """``os.path.realpath(path)`` of a file just read, with its folder's real path taken
    once for a batch of files in one folder (issue 16: ~6 lstat and a Python loop a file).

    The folder's cached real path is used while ``os.stat`` of the folder as written is
    still the same directory (device and inode); the last component is resolved by
    ``os.path.realpath`` whenever it is a symbolic link, ``.`` or ``..`` (or gone). (A
    folder moved and a link put in its place while a batch runs would keep its old real
    path; a folder re-linked to another directory would not.)
    """
    head, tail = os.path.split(path)
    if os.name != "posix" or tail in ("", ".", ".."):
        return os.path.realpath(path)
    folder = head or "."
    try:
        key = (folder if os.path.isabs(folder) else os.getcwd(), folder)
        st = os.stat(folder)
        if stat.S_ISLNK(os.lstat(path).st_mode):
            return os.path.realpath(path)
    except (OSError, ValueError):  # gone, or a name the system refuses: realpath's answer
        return os.path.realpath(path)
    ident = (st.st_dev, st.st_ino)
    known = _REAL_DIRS.get(key)
    if known is None or known[1] != ident:
        if len(_REAL_DIRS) >= _REAL_DIRS_MAX:
            _REAL_DIRS.clear()
        known = _REAL_DIRS[key] = (os.path.realpath(folder), ident)
    return os.path.join(known[0], tail)


def load_expr(expr: str) -> Body:
    """Load a body written inline (``-e/--expr``), e.g. ``{shape: box, mass: 2, size: [1, 2, 3]}``."""
    return load_text(expr, "<expr>", Path.cwd(), name_default="expr")


class gc_paused:  # noqa: N801 - used as a function: ``with gc_paused():``
    """The cyclic garbage collector off while a body is built (issue 16), or while a
    command makes one small object a part (its JSON rows).

    Loading allocates a tree of ~20 objects a part that stays alive until the end, and the
    collector kept re-scanning it: 25-35 % of the CPU time of a 10 000-part body. The loader
    makes next to no reference cycles; whatever it makes is collected after. The tree is
    freed (by reference counting) inside the pause, so that the first collection after it
    scans only the body (~4 objects a part), not the tree too.

    A class, not a ``contextmanager`` generator: entered three times a file in a batch.
    """

    __slots__ = ("_was",)

    def __enter__(self) -> None:
        self._was = gc.isenabled()
        gc.disable()

    def __exit__(self, *exc: object) -> None:
        if self._was:
            gc.enable()


def load_text(
    data: bytes | str,
    filename: str,
    base_dir: Path,
    *,
    name_default: str = "body",
    stack: tuple[str, ...] = (),
    units: dict[str, str] | None = None,
) -> Body:
    """Load a body from text already read; ``base_dir`` anchors relative paths.

    ``stack`` holds the real path of the file the text was read from (if any): it is the
    first of the body's ``inputs``, followed by every file the text includes or meshes it
    reads, at any depth, each once.
    """
    if isinstance(data, bytes):
        text = data.decode("utf-8", errors="replace")
    else:
        text = data
    with gc_paused():
        loaded = _load(data, filename, base_dir, stack, units)
        inputs = tuple(dict.fromkeys((*stack, *loaded.ctx.inputs)))
        body = _body_defaults(loaded, name_default, filename, text, inputs)
        # the YAML tree goes before the collector runs again: it would scan it once more;
        # the included files' results too (session -> parsed -> their ctx -> session is a
        # reference cycle, which only the collector would free, scanning all of it)
        loaded.ctx.session.parsed.clear()
        del loaded
    return body
