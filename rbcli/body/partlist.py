"""The ``parts:`` list of a body file: each part checked in file order, each problem located
at the node at fault. A primitive becomes a :class:`rbcli.body.placing.Pending` (placed in
batches), a given or mesh part a :class:`rbcli.body.partmodel.Part`, an include or a STEP
file's solids a :class:`rbcli.body.placing.Stack`.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cache
from typing import NamedTuple

import numpy as np

from rbcli.body.givenpart import GIVEN_KEYS, given_part
from rbcli.body.includes import INCLUDE_KEYS, include_part
from rbcli.body.loadctx import Ctx
from rbcli.body.meshpart import MESH_KEYS, mesh_part
from rbcli.body.partkeys import (
    DENSITY_FOR,
    MASS_KEYS,
    PLACEMENT_KEYS,
    check_mass,
    mass_source,
    placement_spec,
    subtract,
)
from rbcli.body.partmodel import Part
from rbcli.body.placing import BATCH, Pending, Stack, dims_of, finish, parts_of, to_stack
from rbcli.body.plausible import note_density
from rbcli.body.steppart import STEP_KEYS, step_part
from rbcli.core import rotation as rot
from rbcli.core import shapes as shp
from rbcli.io import yamlsafe as ys
from rbcli.io import yamlvalues as yv

COMMON_PART_KEYS = ("name", "shape", "subtract", "cut_from", *PLACEMENT_KEYS, *MASS_KEYS)
SPECIAL_SHAPES = tuple(shp.IO_SHAPES)  # mesh, step, given, include: built here, not by core.shapes


def all_shape_names() -> list[str]:
    return [*shp.SHAPES.keys(), *SPECIAL_SHAPES]


def part_keys(shape: str) -> tuple[str, ...]:
    """Every key a part of ``shape`` takes (``shape`` among them), in the order messages
    list them (what :mod:`rbcli.parts`'s constructors take: a test keeps them in step)."""
    if shape in shp.SHAPES:
        return _plan(shape).keys
    return {"given": GIVEN_KEYS, "mesh": MESH_KEYS, "include": INCLUDE_KEYS, "step": STEP_KEYS}[shape]


def _part_name(ctx: Ctx, m: ys.MapNode, index: int, shape: str, names: set[str]) -> str:
    item = m.items.get("name")
    if item is not None:
        name = yv.string(ctx, item[1], "name")
        if not name.strip():
            raise ctx.error(item[1], "a part name must not be empty")
    else:
        name = f"{shape}{index + 1}"
    if name in names:
        raise ctx.error(item[1] if item is not None else m, f"two parts are named '{name}'; names must differ")
    names.add(name)
    return name


def parts(ctx: Ctx, node: ys.Node, prefix: str = "", *, stacked: bool = False) -> list[Part] | Stack:
    """The parts of the list ``node``: as :class:`Part` s, or for an included file
    (``stacked``) as one :class:`rbcli.body.placing.Stack` (each use moves it)."""
    if not isinstance(node, ys.SeqNode):
        raise ctx.error(node, f"parts must be a list of parts, not {yv.describe(node)}")
    if not node.items:
        raise ctx.error(node, "parts is empty; a body needs at least one part")
    out: list = []  # Pending, Part or Stack (an include's parts)
    names: set[str] = set()
    known: dict[str, tuple] = {}
    settle = to_stack if stacked else finish  # the primitives of out[done:], placed
    done = 0  # out[:done] are placed
    waiting = 0  # parts in out[done:]
    for i, item in enumerate(node.items):
        if not _is_include(item):
            ctx.session.spend(ctx, item, 1)
        p = part(ctx, item, i, names, known, prefix)
        out.append(p)
        waiting += len(p) if isinstance(p, Stack) else 1
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


def part(ctx: Ctx, node: ys.Node, index: int, names: set[str], known: dict[str, tuple], prefix: str):
    """One entry of ``parts``: a :class:`Pending` (a primitive), a :class:`Stack` (an include,
    a STEP file's solids) or a :class:`Part`."""
    m = node if isinstance(node, ys.MapNode) else yv.mapping(ctx, node, f"part {index + 1}")
    shape_item = m.items.get("shape")
    if shape_item is None:
        raise ctx.error(m, f"part {index + 1} needs 'shape' (one of: {', '.join(all_shape_names())})")
    shape_node = shape_item[1]
    shape = yv.string(ctx, shape_node, "shape")
    if shape not in shp.SHAPES and shape not in SPECIAL_SHAPES:
        raise ctx.error(
            shape_node,
            f"unknown shape '{shape}'{yv.suggest(shape, all_shape_names())} (shapes: {', '.join(all_shape_names())})",
        )
    name = _part_name(ctx, m, index, shape, names)
    what = f"part '{name}'"
    if shape == "include":
        return include_part(ctx, m, name, prefix)
    if shape == "given":
        return given_part(ctx, m, name, prefix, known)
    if shape == "mesh":
        return mesh_part(ctx, m, name, prefix, known)
    if shape == "step":
        return step_part(ctx, m, name, prefix, known, "name" in m.items, names)
    return _primitive(ctx, m, shape, name, prefix, known, what)


class _Plan(NamedTuple):
    """How to read a part of one primitive shape (:func:`_plan`, made once per shape)."""

    keys: tuple[str, ...]  # every key it takes, in the order messages list them
    diameters: dict[str, str]  # a diameter spelling -> the radius it gives
    required: tuple[str, ...]  # its parameters (ShapeInfo.required, .optional)
    optional: tuple[str, ...]
    kinds: tuple[tuple[str, str, int], ...]  # (parameter, its Kind's name, its n), in order
    build: Callable  # the shape's formulas (core.shapes.builder): parameters checked here
    radius: Callable | None  # ShapeInfo.radius of a round shape, else None


@cache
def _plan(shape: str) -> _Plan:
    info = shp.SHAPES[shape]
    params = (*info.required, *info.optional)
    keys = (*COMMON_PART_KEYS, *params, *info.diameters, *(("from", "to") if shape == "rod" else ()))
    kinds = tuple((k, info.kind(k).name, info.kind(k).n) for k in params)
    return _Plan(keys, info.diameters, info.required, info.optional, kinds, shp.builder(shape),
                 info.radius if info.round else None)


def _diameters(ctx: Ctx, m: ys.MapNode, plan: _Plan, what: str, params: dict, nodes: dict) -> None:
    """The radii given as diameters (``diameter: 20 mm`` is ``radius: 10 mm``)."""
    items = m.items
    for dkey, rkey in plan.diameters.items():
        if dkey not in items:
            continue
        if rkey in items:
            raise ctx.error(items[dkey][0], f"{what}: give '{rkey}' or '{dkey}', not both")
        nodes[rkey] = items[dkey][1]
        params[rkey] = 0.5 * yv.number(ctx, nodes[rkey], "length", dkey)


def _rod_ends(ctx: Ctx, m: ys.MapNode, what: str, params: dict) -> tuple[list[float], tuple]:
    """A rod given by its endpoints ``from`` and ``to``: its length (in ``params``), and its
    placement (its middle, its axis along ``to - from``)."""
    items = m.items
    for k in ("from", "to"):
        if k not in items:
            raise ctx.error(m, f"{what}: a rod given by endpoints needs both 'from' and 'to'")
    for k in ("length", *PLACEMENT_KEYS):
        if k in items:
            raise ctx.error(items[k][0], f"{what}: '{k}' does not go with 'from'/'to' (the endpoints place the rod)")
    a = yv.vector(ctx, items["from"][1], "length", "from")
    b = yv.vector(ctx, items["to"][1], "length", "to")
    if not np.linalg.norm(b - a) > 0:
        raise ctx.error(items["to"][1], f"{what}: 'from' and 'to' are the same point")
    params["length"] = float(np.linalg.norm(b - a))
    return (0.5 * (a + b)).tolist(), ("R", rot.axis_to_z(b - a))


def _parameter(ctx: Ctx, node: ys.Node, key: str, kind: str, n: int) -> object:
    """A shape parameter of ``kind`` (:class:`rbcli.core.shapes.Kind`'s name) in SI."""
    if kind == "length":
        return yv.number(ctx, node, "length", key)
    if kind == "lengths":
        return yv.floats(ctx, node, "length", key, n=n)
    if kind == "points":
        return yv.rows(ctx, node, "length", key)
    return yv.flag(ctx, node, key)


def _parameters(ctx: Ctx, m: ys.MapNode, shape: str, plan: _Plan, what: str, params: dict,
                nodes: dict) -> None:
    """The shape's parameters not read yet, each by its kind; a required one missing is an
    error."""
    items = m.items
    for key in plan.required:
        if key not in items and key not in params:
            alt = next((f" or '{d}'" for d, r in plan.diameters.items() if r == key), "")
            allowed = (*plan.required, *plan.optional)
            raise ctx.error(m, f"{what} ({shape}) needs '{key}'{alt} (parameters: {', '.join(allowed) or 'none'})")
    for key, kind, n in plan.kinds:
        if key in items and key not in params:
            nodes[key] = items[key][1]
            params[key] = _parameter(ctx, nodes[key], key, kind, n)


def _geometry(ctx: Ctx, m: ys.MapNode, plan: _Plan, what: str, params: dict, nodes: dict):
    """The shape's geometry (:func:`rbcli.core.shapes.builder`); a shape's own error is
    located at the parameter at fault, its lengths in the file's length unit."""
    try:
        return plan.build(params)  # what shp.local_geometry checks first, checked above
    except shp.ShapeError as exc:
        factor, unit = ctx.factor("length", m)
        message = exc.format(lambda x: f"{x / factor:g} {unit}")
        raise ctx.error(nodes.get(exc.param, m), f"{what}: {message}") from None
    except ValueError as exc:
        raise ctx.error(m, f"{what}: {exc}") from None


def _mass(ctx: Ctx, m: ys.MapNode, name: str, geo, known: dict, what: str) -> tuple[float, float | None]:
    """The part's mass and its measure (None for a point), from its mass or density; what a
    later hole may take from it is kept in ``known``."""
    measure_kind = geo.measure_kind
    mass, density, src = mass_source(ctx, m, measure_kind, known, what)
    measure = None
    if measure_kind != "point":
        measure = float(geo.measure)
        if mass is None:
            mass = density * measure
            check_mass(ctx, src, what, mass, f"density × {measure_kind}")
            if "cut_from" not in m.items:  # a density typed here: one matter has?
                note_density(ctx, src, DENSITY_FOR[measure_kind], density, measure,
                             measure_kind == "volume", what)
        elif measure:
            density = mass / measure
    known[name] = (density, measure_kind)
    if not mass > 0:
        raise ctx.error(m, f"{what} has no mass")
    return mass, measure


def _primitive(ctx: Ctx, m: ys.MapNode, shape: str, name: str, prefix: str, known: dict,
               what: str) -> Pending:
    plan = _plan(shape)
    yv.check_keys(ctx, m, plan.keys, f"{what} ({shape})")
    params: dict[str, object] = {}
    nodes: dict[str, ys.Node] = {}
    _diameters(ctx, m, plan, what, params, nodes)
    at, spec = placement_spec(ctx, m)
    if shape == "rod" and ("from" in m.items or "to" in m.items):
        at, spec = _rod_ends(ctx, m, what, params)
    _parameters(ctx, m, shape, plan, what, params, nodes)
    geo = _geometry(ctx, m, plan, what, params, nodes)
    mass, measure = _mass(ctx, m, name, geo, known, what)
    return Pending(
        prefix + name, shape, mass, subtract(ctx, m), measure, geo.measure_kind,
        plan.radius(params) if plan.radius else None, ctx.where(m), at, spec, geo.com,
        geo.unit_inertia, dims_of(params),
    )
