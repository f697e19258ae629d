"""Read a body file (YAML) into a validated :class:`rbcli.model.Body` in SI units.

Every problem is an :class:`rbcli.errors.InputError` located at ``file:line:col``.
The walk is strict: numbers must be numbers (``true`` is not 1.0), strings with
units must have the right dimension, unknown keys are refused with a
"did you mean" hint, and the finished body must be physically possible.

The readers: :mod:`rbcli.io.loadctx` (the load's budget, each file's context),
:mod:`rbcli.io.parts` (the walk over ``parts:`` and each primitive part),
:mod:`rbcli.io.givenpart`, :mod:`rbcli.io.meshpart`, :mod:`rbcli.io.includes` (the
special parts), :mod:`rbcli.io.fields` (numbers, vectors, placements, masses) and
:mod:`rbcli.io.placing` (parts placed in batches).
"""

from __future__ import annotations

import math
import os
import stat
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from rbcli.core import shapes as shp
from rbcli.core.inertia import combine, remember_mass_props, tensor_problem
from rbcli.errors import InputError, Location
from rbcli.io import fields as fl
from rbcli.io import includes as inc
from rbcli.io import parts as pt
from rbcli.io import units as un
from rbcli.io import yamlplain
from rbcli.io import yamlsafe as ys
from rbcli.io.givenpart import pretty_unit
from rbcli.io.loadctx import Ctx, Session, new_session, shared_factors
from rbcli.io.placing import Stack, finish, parts_of, to_stack
from rbcli.io.plausible import density_warning
from rbcli.model import Body, Part, Shaft

__all__ = ["load_body", "load_text", "load_expr", "load_node", "origin", "default_units",
           "FORMAT_VERSION",
           "BODY_KEYS", "UNIT_KEYS"]

FORMAT_VERSION = 1
BODY_KEYS = (
    "rbcli", "name", "description", "units", "parts", "reference", "shaft", "pivot",
    "rim_radius", "bearings",
)
UNIT_KEYS = ("length", "mass", "time", "angle", "angular_speed")


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
        base[key] = un.canonical_unit(base[key])  # 'RPM', 'inches' are shown 'rpm', 'in'
    ctx.base_units = base


def default_units(units: dict[str, str]) -> dict[str, str]:
    """A caller's default ``units`` (``{"length": "mm"}``) checked, as canonical names.

    Raises
    ------
    ValueError
        An unknown kind or a unit of the wrong dimension (the message says which).
    """
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
    :mod:`rbcli.io.bodydata`)."""
    session = session if session is not None else new_session(_load)
    if root is None:
        cap = session.list_cap(filename)
        root = yamlplain.tree(data, cap)  # the plainest files; None: libyaml's loader reads it
        if root is None:
            root = ys.load(data, filename, list_cap=cap)
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
    _units(ctx, root)
    ctx.factors = shared_factors(ctx.base_units)
    if "parts" in root.items:
        fl.check_keys(ctx, root, BODY_KEYS, "the body")
        parts = pt.parts(ctx, root.items["parts"][1], stacked=stacked)
    elif "shape" in root.items:
        # one-part shorthand: the mapping is the part (plus the body's units/version)
        items = {k: v for k, v in root.items.items() if k not in ("units", "rbcli")}
        stripped = ys.MapNode(root.mark, items)  # the public constructor: (mark, items)
        one = [pt.part(ctx, stripped, 0, set(), {}, "")]
        parts = to_stack(one)[0] if stacked else parts_of(finish(one))
    else:
        raise ctx.error(root, "a body file needs 'parts:' (a list of parts), or a single part with 'shape:'")
    ctx.inputs = list(dict.fromkeys(ctx.inputs))
    return _Loaded(parts, list(dict.fromkeys(ctx.warnings)), root, ctx, session.used - spent)


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
        description=description, warnings=(*loaded.warnings, *density_warning(ctx.session)),
        inputs=inputs,
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
        data = read_stream(stream, ys.max_bytes(), "body file", env="RBCLI_MAX_BODY_BYTES")  # type: ignore[arg-type]
        return load_text(data, "<stdin>", Path.cwd(), name_default="body")
    if inc.names_a_folder(source):
        from rbcli.io.reader import ReadError

        raise ReadError(source, "names a folder (it ends with '/'), not a body file")
    path = Path(source)
    data = inc.read_body_file(path)
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
    loaded = _load(data, filename, base_dir, stack, units)
    return _finish(loaded, name_default, filename, text, stack, base_dir)


def load_node(root: ys.Node, source: str, base_dir: Path, *, text: str,
              name_default: str = "body", units: dict[str, str] | None = None) -> Body:
    """Load a body from a tree made of Python data (:func:`rbcli.io.bodydata.tree`, each node
    located by its key path); ``text`` is its document as YAML (``Body.text``)."""
    loaded = _load(None, source, base_dir, (), units, root=root)
    return _finish(loaded, name_default, source, text, (), base_dir)


def _finish(loaded: _Loaded, name_default: str, source: str, text: str,
            stack: tuple[str, ...], base_dir: Path) -> Body:
    inputs = tuple(dict.fromkeys((*stack, *loaded.ctx.inputs)))
    body = _body_defaults(loaded, name_default, source, text, inputs)
    # the included files' results are freed now (session -> parsed -> their ctx -> session
    # is a reference cycle, which only the collector would free, scanning all of it)
    loaded.ctx.session.parsed.clear()
    object.__setattr__(body, "_origin", os.path.abspath(base_dir))
    return body


def origin(body: Body) -> str | None:
    """The folder (absolute) relative ``include`` and mesh paths of ``body.text`` start from,
    for a body a reader of rbcli made (its document is ``body.text``); else None (a
    ``Body(...)`` or a ``dataclasses.replace`` of one: its text, if any, need not say what
    its parts are)."""
    return body.__dict__.get("_origin") if hasattr(body, "__dict__") else None
