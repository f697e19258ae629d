"""Read a body file (YAML, or a tree of Python data) into a validated body in SI: its
components (:class:`Built`), which :mod:`rbcli.body.model` makes a ``Body``. Strict (``true``
is not 1.0; units of the right dimension; unknown keys refused with a "did you mean"; the body
physically possible), every problem an InputError at ``file:line:col``. The parts:
:mod:`rbcli.body.partlist` and the special parts' modules, through :mod:`rbcli.io.yamlvalues`.
"""

from __future__ import annotations

import os
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from rbcli.body import includes as inc
from rbcli.body import materials
from rbcli.body import partkeys as pk
from rbcli.body import partlist as pt
from rbcli.body.givenpart import pretty_unit
from rbcli.body.loadctx import Ctx, Session, new_session
from rbcli.body.partmodel import Part, Shaft
from rbcli.body.placing import Stack, finish, parts_of, to_stack
from rbcli.body.plausible import density_warning, note_density
from rbcli.core import shapes as shp
from rbcli.core.inertia import MassProps, combine, tensor_problem
from rbcli.errors import InputError, Location
from rbcli.io import units as un
from rbcli.io import yamlsafe as ys
from rbcli.io import yamlvalues as yv
from rbcli.io.reader import ReadError, read_stream

__all__ = ["Built", "load_body", "load_text", "load_expr", "load_node", "default_units",
           "FORMAT_VERSION", "BODY_KEYS", "UNIT_KEYS"]

FORMAT_VERSION = 1
BODY_KEYS = (
    "rbcli", "name", "description", "units", "materials", "parts", "reference", "shaft",
    "pivot", "rim_radius", "bearings",
)
UNIT_KEYS = ("length", "mass", "time", "angle", "angular_speed")


@dataclass(frozen=True)
class Built:
    """A body as the loader made it: its Body's fields, its mass properties and the folder
    its document's relative paths start from."""

    fields: dict
    mass_props: MassProps
    origin: str


@dataclass
class _Loaded:
    parts: list[Part] | Stack  # a Stack for an included file
    warnings: list[str]
    root: ys.MapNode | None  # the file's YAML tree (None for an included file, once read)
    ctx: Ctx
    cost: int = 0  # what one use of this file spends of the parts budget


def _units(ctx: Ctx, m: ys.MapNode) -> None:
    if "units" not in m.items:
        return
    unode = m.items["units"][1]
    if isinstance(unode, ys.ScalarNode) and isinstance(unode.value, str):
        raise ctx.error(unode, f"units: the body's are a mapping, e.g. 'units: {{length: "
                        f"{unode.raw}}}' (a text units is a mesh or STEP file's length unit)")
    unode = yv.mapping(ctx, unode, "units")
    yv.check_keys(ctx, unode, UNIT_KEYS, "units")
    base = {}
    for key, (_km, vnode) in unode.items.items():
        base[key] = yv.string(ctx, vnode, f"units.{key}")
        try:
            un.unit_for_kind({key: base[key]}, key)
        except un.UnitError as exc:
            msg = str(exc)
            raise ctx.error(vnode, msg if msg.startswith("units:") else f"units: {key}: {msg}") from None
        base[key] = un.canonical_unit(base[key])  # 'RPM', 'inches' are shown 'rpm', 'in'
    ctx.base_units = base


def _materials(ctx: Ctx, m: ys.MapNode) -> None:
    """The file's own ``materials: {name: density}``, each checked as a typed density."""
    if "materials" not in m.items:
        return
    for name, (_km, vnode) in yv.mapping(ctx, m.items["materials"][1], "materials").items.items():
        value = yv.positive(ctx, vnode, "density", f"materials: {name}")
        note_density(ctx, vnode, "density", value, None, True, f"material '{name}'")
        ctx.materials[materials.key(name)] = value


def default_units(units: dict[str, str]) -> dict[str, str]:
    """A caller's default ``units`` (``{"length": "mm"}``) checked, as canonical names; a
    ValueError says which kind or unit is wrong."""
    out = {}
    for key, unit in units.items():
        if key not in UNIT_KEYS:
            raise ValueError(f"unknown kind '{key}'; allowed: {', '.join(UNIT_KEYS)}")
        try:
            un.unit_for_kind({key: unit}, key)
        except un.UnitError as exc:  # its message may say "units: length is 'kg', ..." itself
            msg = str(exc)
            raise ValueError(msg[7:] if msg.startswith("units: ") else f"{key}: {msg}") from None
        out[key] = un.canonical_unit(unit)
    return out


def _load(data: bytes | str | None, filename: str, base_dir: Path, stack: tuple[str, ...],
          units: dict[str, str] | None = None, *, session: Session | None = None,
          stacked: bool = False, root: ys.Node | None = None) -> _Loaded:
    """Read a file's text ``data`` (or the tree ``root`` already made of Python data:
    :mod:`rbcli.body.pydata`)."""
    session = session if session is not None else new_session(_load)
    if root is None:
        root = ys.load(data, filename, list_cap=session.list_cap(filename))
    ctx = Ctx(file=filename, base_dir=base_dir, stack=stack, session=session)
    spent = session.used
    if units:  # the caller's default units (rbcli.load_text(..., units=...)); the file's win
        try:
            ctx.base_units = default_units(units)
        except ValueError as exc:
            raise InputError(f"units: {exc}", Location(filename)) from None
    if not isinstance(root, ys.MapNode):
        raise ctx.error(root, "a body file is a mapping with 'parts:' (a list of parts), or a single part with 'shape:'")
    if "rbcli" in root.items:
        vnode = root.items["rbcli"][1]
        if not (isinstance(vnode, ys.ScalarNode) and vnode.value == FORMAT_VERSION and not isinstance(vnode.value, bool)):
            raise ctx.error(vnode, f"this rbcli reads body format version {FORMAT_VERSION}, not {vnode.raw if isinstance(vnode, ys.ScalarNode) else '?'}")
    # a one-part mesh or STEP body's text units (``mm``) is the part's, as inside parts:
    shape, unode = (root.items.get(k, (None, None))[1] for k in ("shape", "units"))
    part_units = "parts" not in root.items and isinstance(unode, ys.ScalarNode) and \
        isinstance(shape, ys.ScalarNode) and shape.value in ("mesh", "step")
    if not part_units:
        _units(ctx, root)
    _materials(ctx, root)
    if "parts" in root.items:
        yv.check_keys(ctx, root, BODY_KEYS, "the body")
        parts = pt.parts(ctx, root.items["parts"][1], stacked=stacked)
    elif "shape" in root.items:
        # one-part shorthand: the mapping is the part (plus the body's units/version)
        items = {k: v for k, v in root.items.items() if k != "rbcli" and (k != "units" or part_units)}
        stripped = ys.MapNode(root.mark, items)  # the public constructor: (mark, items)
        one = [pt.part(ctx, stripped, 0, set(), {}, "")]
        parts = to_stack(one)[0] if stacked else parts_of(finish(one))
    else:
        raise ctx.error(root, "a body file needs 'parts:' (a list of parts), or a single part with 'shape:'")
    ctx.inputs = list(dict.fromkeys(ctx.inputs))
    return _Loaded(parts, list(dict.fromkeys(ctx.warnings)), root, ctx, session.used - spent)


def _may_be_impossible(parts: tuple) -> bool:
    """Whether the sum of ``parts`` may not be physically possible: only with a hole or a part
    that is no formula shape (a sum of possible tensors is possible, its rounding ~1e-16 far
    below the check's 1e-7)."""
    return any(p.subtract or p.shape not in shp.FORMULA_SHAPES for p in parts)


def _check_possible(ctx: Ctx, node: ys.Node, J: np.ndarray, factor: float, unit: str) -> None:
    """Refuse a body whose inertia ``J`` (about its com) is not physically possible
    (moments quoted as ``J / factor`` in ``unit``, the file's inertia unit)."""
    problem = tensor_problem(J, rtol=1e-7, unit=pretty_unit(unit), factor=factor)
    if problem:
        raise ctx.error(
            node,
            f"the body's inertia is not physically possible: {problem} "
            "(is a subtracted part outside the material it is cut from?)",
        )


def _body_keys(ctx: Ctx, items: dict) -> dict:
    """The body's own keys (a file with ``parts:``): reference, pivot, shaft, rim radius
    and description, as :class:`rbcli.body.model.Body`'s fields."""
    out: dict = {}
    if "description" in items:
        out["description"] = yv.string(ctx, items["description"][1], "description")
    if "reference" in items:
        p = pk.point(ctx, items["reference"][1], "reference")
        if isinstance(p, str):
            out["reference_is_com"] = p == "com"
            out["reference"] = None if p == "com" else np.zeros(3)
        else:
            out["reference"] = p
    if "pivot" in items:
        p = pk.point(ctx, items["pivot"][1], "pivot")
        if isinstance(p, str):
            raise ctx.error(items["pivot"][1], "pivot must be a point [x, y, z]")
        out["pivot"] = p
    if "shaft" in items:
        snode = yv.mapping(ctx, items["shaft"][1], "shaft")
        yv.check_keys(ctx, snode, ("axis", "through"), "shaft", required=("axis",))
        axis = pk.direction(ctx, snode.items["axis"][1], "shaft axis")
        through = snode.items.get("through")
        out["shaft"] = Shaft(axis, np.zeros(3) if through is None else
                             yv.vector(ctx, through[1], "length", "shaft through"))
    if "rim_radius" in items:
        out["rim_radius"] = yv.positive(ctx, items["rim_radius"][1], "length", "rim_radius")
    return out


def _mass_props(ctx: Ctx, node: ys.Node, parts: tuple[Part, ...]) -> MassProps:
    """The body's combined mass properties, checked finite and physically possible."""
    try:
        with np.errstate(over="ignore", invalid="ignore"):
            mp = combine(parts)
    except ValueError as exc:
        raise ctx.error(node, str(exc)) from None
    if not (np.isfinite(mp.com).all() and np.isfinite(mp.inertia_com).all()):
        raise ctx.error(
            node,
            "the body's mass properties overflow (a mass times a squared distance exceeds "
            "1e308); numbers are limited to 1e60 in SI units",
        )
    factor, unit = ctx.factor("inertia", node)  # its unit errors, whether or not it is used
    if _may_be_impossible(parts):
        _check_possible(ctx, node, mp.inertia_com, factor, unit)
    return mp


def _built(loaded: _Loaded, name_default: str, source: str, text: str,
           stack: tuple[str, ...], base_dir: Path) -> Built:
    ctx, items = loaded.ctx, loaded.root.items
    name = yv.string(ctx, items["name"][1], "name") if "name" in items else name_default
    fields = _body_keys(ctx, items) if "parts" in items else {}
    parts = tuple(loaded.parts)
    mp = _mass_props(ctx, items["parts"][1] if "parts" in items else loaded.root, parts)
    fields.update(
        name=name, source=source, text=text, parts=parts,
        warnings=(*loaded.warnings, *density_warning(ctx.session)),
        inputs=tuple(dict.fromkeys((*stack, *ctx.inputs))), units=dict(ctx.base_units))
    # the included files' results are freed now (session -> parsed -> their ctx -> session
    # is a reference cycle, which only the collector would free, scanning all of it)
    ctx.session.parsed.clear()
    return Built(fields, mp, os.path.abspath(base_dir))


def load_body(source: str, *, stdin: object = None) -> Built:
    """Load a body from a path, or ``-`` for standard input.

    Raises
    ------
    InputError
        For anything wrong with the file or its contents, located at file:line:col.
    """
    if source == "-":
        stream = stdin if stdin is not None else getattr(sys.stdin, "buffer", sys.stdin)
        data = read_stream(stream, ys.max_bytes(), "body file", env="RBCLI_MAX_BODY_BYTES")  # type: ignore[arg-type]
        return load_text(data, "<stdin>", Path.cwd(), name_default="body")
    if inc.names_a_folder(source):
        raise ReadError(source, "names a folder (it ends with '/'), not a body file")
    path = Path(source)
    data = inc.read_body_file(path)
    return load_text(data, source, path.parent, name_default=path.stem, stack=(os.path.realpath(path),))


def load_expr(expr: str) -> Built:
    """Load a body written inline (``-e/--expr``), e.g. ``{shape: box, mass: 2, size: [1, 2, 3]}``."""
    return load_text(expr, "<expr>", Path.cwd(), name_default="expr")


def load_text(
    data: bytes | str,
    filename: str,
    base_dir: Path,
    *,
    name_default: str = "body",
    stack: tuple[str, ...] = (),
    units: dict[str, str] | None = None,
) -> Built:
    """Load a body from text already read; ``base_dir`` anchors relative paths; ``stack``
    the real path it was read from (if any): the first of the body's ``inputs``."""
    if isinstance(data, bytes):
        text = data.decode("utf-8", errors="replace")
    else:
        text = data
    loaded = _load(data, filename, base_dir, stack, units)
    return _built(loaded, name_default, filename, text, stack, base_dir)


def load_node(root: ys.Node, source: str, base_dir: Path, *, text: str,
              name_default: str = "body", units: dict[str, str] | None = None) -> Built:
    """Load a body from a tree made of Python data (:func:`rbcli.body.pydata.tree`, each node
    located by its key path); ``text`` is its document as YAML (``Body.text``)."""
    loaded = _load(None, source, base_dir, (), units, root=root)
    return _built(loaded, name_default, source, text, (), base_dir)

