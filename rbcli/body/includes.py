"""A ``shape: include`` part: another body file's parts, placed as a whole; each file parsed
once a load, its :class:`rbcli.body.placing.Stack` moved per use (a diamond of includes costs
time linear in its files); cycles and nesting over :data:`MAX_INCLUDE_DEPTH` refused.
"""

from __future__ import annotations

import os
from pathlib import Path

from rbcli.body.loadctx import Ctx
from rbcli.body.partkeys import PLACEMENT_KEYS, placement
from rbcli.body.placing import Stack
from rbcli.errors import Location
from rbcli.io import yamlsafe as ys
from rbcli.io import yamlvalues as yv
from rbcli.io.reader import read_regular

MAX_INCLUDE_DEPTH = 16
INCLUDE_KEYS = ("name", "shape", "file", *PLACEMENT_KEYS)


def names_a_folder(name: str) -> bool:
    """Whether a file name as written ends with a path separator: it names a folder
    (``Path`` drops the slash, and would read ``c.yaml/`` as the file ``c.yaml``)."""
    return name.endswith(("/", os.sep))


def read_body_file(path: Path, where: Location | None = None) -> bytes:
    """A body file or an included file: :func:`rbcli.io.reader.read_regular` (a regular
    file only, its size checked before reading)."""
    return read_regular(path, ys.max_bytes(), "body file", where=where, env="RBCLI_MAX_BODY_BYTES")


def _resolve(ctx: Ctx, node: ys.Node, what: str) -> Path:
    rel = yv.string(ctx, node, what)
    if names_a_folder(rel):
        raise ctx.error(node, f"{what}: '{rel}' names a folder (it ends with '/'); include "
                        "takes a body file")
    path = Path(rel)
    if not path.is_absolute():
        path = ctx.base_dir / path
    return path


def include_part(ctx: Ctx, m: ys.MapNode, name: str, prefix: str) -> Stack:
    what = f"part '{name}' (include)"
    yv.check_keys(ctx, m, INCLUDE_KEYS, what, required=("file",))
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
        data = read_body_file(path, where)
        session.parses += 1
        sub = session.load(data, str(path), path.parent, (*ctx.stack, real), session=session, stacked=True)
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
    at, R = placement(ctx, m)
    return sub.parts.moved(at, R, f"{prefix}{name}/")

