"""A ``shape: mesh`` part: a closed triangle mesh read from an STL or OBJ file."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from rbcli.body.includes import names_a_folder
from rbcli.body.loadctx import Ctx
from rbcli.body.partkeys import PLACEMENT_KEYS, check_mass, mass_source, placement, subtract
from rbcli.body.partmodel import Outline, Part
from rbcli.body.placing import place
from rbcli.body.plausible import note_density
from rbcli.io import units as un
from rbcli.io import yamlsafe as ys
from rbcli.io import yamlvalues as yv
from rbcli.io.reader import ReadError, relabelled
from rbcli.io.yamlvalues import HUGE

MESH_KEYS = (
    "name", "shape", "file", "scale", "units", "allow_open", "weld", "subtract", "cut_from",
    "mass", "density", "material", *PLACEMENT_KEYS,
)


def mesh_part(ctx: Ctx, m: ys.MapNode, name: str, prefix: str, known: dict) -> Part:
    """A ``shape: mesh`` part: the YAML checked, then the file read (the mesh modules
    imported here only: bodies without meshes do not pay for them)."""
    what = f"part '{name}' (mesh)"
    yv.check_keys(ctx, m, MESH_KEYS, what, required=("file",))
    fnode = m.items["file"][1]
    path = mesh_path(ctx, fnode)
    scale, factor = scale_units(ctx, m, what)
    if factor is None:
        factor = ctx.factor("length", m)[0]
    allow_open = yv.flag(ctx, m.items["allow_open"][1], "allow_open") if "allow_open" in m.items else False
    weld = None  # None: the file's own default (meshfile.default_weld)
    if "weld" in m.items:
        wnode = m.items["weld"][1]
        if isinstance(wnode, ys.ScalarNode) and wnode.value == "exact":
            weld = 0.0
        else:
            weld = yv.positive(ctx, wnode, "length", f"{what}: weld (a length, or exact)", allow_zero=True)
    mass, density, src = mass_source(ctx, m, "volume", known, what)
    if mass is None and "cut_from" not in m.items:  # a density typed here: one matter has?
        note_density(ctx, src, "density", density, None, True, what)
    removed = subtract(ctx, m)
    at, R = placement(ctx, m)

    from rbcli.core import mesh as cmesh
    from rbcli.io import meshfile

    shown = str(path)
    try:
        vertices, faces, _fmt, file_weld = meshfile.read_mesh(path)
    except meshfile.MeshFileError as exc:  # its message starts with the path
        raise ctx.error(fnode, f"{what}: {exc}") from None
    except ReadError as exc:  # missing, denied, a folder: also the OSError
        raise relabelled(exc, f"{what}: {exc.path}: {exc.reason}", ctx.where(fnode)) from None
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
    # for drawings: the file's mesh (a figure decimates it when it draws: rbcli.render.outline)
    outline = Outline("mesh", (("triangles", len(faces)),), at, R, vertices, faces)
    del vertices, faces
    for w in props.warnings:
        ctx.warnings.append(f"{ctx.where(fnode)}: warning: {what}: {shown}: {w}")
    if mass is None:
        assert density is not None
        mass = density * props.volume
        check_mass(ctx, src, what, mass, "density × volume")
    else:
        density = mass / props.volume
    known[name] = (density, "volume")
    com, J = place(np.asarray(props.centroid), mass * np.asarray(props.unit_inertia), at, R)
    return Part(
        name=prefix + name, shape="mesh", mass=float(mass), subtract=removed, com=com,
        inertia_com=J, measure=props.volume, measure_kind="volume", axis=R[:, 2].copy(),
        extra={"volume": float(props.volume), "area": float(props.area), "triangles": int(props.n_triangles)},
        where=ctx.where(m), outline=outline,
    )


def scale_units(ctx: Ctx, m: ys.MapNode, what: str, of: str = "mesh") -> tuple[float, float | None]:
    """A file part's ``scale`` (1 if not given) and ``units`` (m per unit, or None)."""
    scale, factor = 1.0, None
    if "scale" in m.items:
        scale = yv.positive(ctx, m.items["scale"][1], "dimensionless", f"{what}: scale")
    if "units" in m.items:
        unode = m.items["units"][1]
        text = yv.string(ctx, unode, "units")
        try:
            factor, dim = un.parse_unit(text)
        except un.UnitError as exc:
            raise ctx.error(unode, f"{what}: units: {exc}") from None
        if dim != un.KINDS["length"]:
            raise ctx.error(unode, f"{what}: units is the length unit of the {of}'s coordinates "
                            f"(m, mm, in, ...), not '{text}'")
    return scale, factor


def mesh_path(ctx: Ctx, fnode: ys.Node, shape: str = "mesh",
              kind: str = "a mesh file (.stl or .obj)") -> Path:
    """A mesh or STEP part's ``file``, relative to the body file's folder."""
    rel = yv.string(ctx, fnode, "file")
    if not rel.strip():
        raise ctx.error(fnode, f"file must name {kind}, relative to the body file")
    if "\0" in rel:
        raise ctx.error(fnode, "file: a file name cannot contain a NUL character")
    if names_a_folder(rel):
        raise ctx.error(fnode, f"file: '{rel}' names a folder (it ends with '/'); a {shape} part "
                        f"reads {kind}")
    path = Path(rel)
    if path.is_absolute():
        return path
    try:
        if ctx.base_dir.is_absolute() and ctx.base_dir == Path.cwd():
            return path  # standard input or -e: show the path the user wrote
    except OSError:  # the cwd is gone
        pass
    return ctx.base_dir / path

