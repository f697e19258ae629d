"""A ``shape: step`` part: each solid of a STEP file (:mod:`rbcli.io.stepfile`) a part (named
``name/solid``, or unnamed as the file names it), placed by the assembly, then the part.
"""

from __future__ import annotations

import os
from fnmatch import fnmatchcase

import numpy as np

from rbcli.body import materials
from rbcli.body.givenpart import given_outline
from rbcli.body.loadctx import Ctx
from rbcli.body.meshpart import mesh_path, scale_units
from rbcli.body.partkeys import (MASS_KEYS, PLACEMENT_KEYS, check_mass, mass_source, placement,
                                 subtract)
from rbcli.body.partmodel import Part
from rbcli.body.placing import Stack, place
from rbcli.body.plausible import note_density
from rbcli.errors import InputError, Location, literal
from rbcli.io import yamlsafe as ys
from rbcli.io import yamlvalues as yv
from rbcli.io.reader import ReadError, relabelled
from rbcli.io.stepfile import StepError, read_step

STEP_KEYS = ("name", "shape", "file", "part", "units", "scale", "solids", "subtract", "cut_from",
             "mass", "density", "material", *PLACEMENT_KEYS)


def step_part(ctx: Ctx, m: ys.MapNode, name: str, prefix: str, known: dict, named: bool,
              names: set[str]) -> Part | Stack:
    """The part(s) of a step entry; unless ``named``, named as the file names its solids."""
    what = f"part '{name}' (step)"
    yv.check_keys(ctx, m, STEP_KEYS, what, required=("file",))
    fnode = m.items["file"][1]
    path = mesh_path(ctx, fnode, "step", "a STEP file (.step or .stp)")
    mass = default = None
    if any(k in m.items for k in (*MASS_KEYS, "cut_from")) or "solids" not in m.items:
        mass, default, src = mass_source(ctx, m, "volume", known, what)
        if "density" in m.items:
            note_density(ctx, src, "density", default, None, True, what)
    if mass is not None and "solids" in m.items:
        raise ctx.error(m.items["solids"][0], f"{what}: give mass or solids:")
    removed = subtract(ctx, m)
    at, R = placement(ctx, m)
    try:
        step = read_step(str(path), ctx.session.max_parts - ctx.session.used + 1)
    except ImportError:
        raise ctx.error(fnode, f"{what}: reading STEP needs OpenCascade: pip install "
                        "'rbcli[cad]'") from None
    except ReadError as exc:
        raise relabelled(exc, f"{what}: {exc}", ctx.where(fnode)) from None
    except StepError as exc:
        said = literal(str(exc)) if ctx.file == str(path) else f"{what}: {literal(str(exc))}"
        raise InputError(said, Location(str(path), exc.line or 0)) from None
    ctx.inputs.append(os.path.realpath(path))
    part, rules = _patterns(ctx, m, [s.name for s in step.solids], what)
    solids = [s for s in step.solids if part is None or fnmatchcase(s.name, part)]
    ctx.session.spend(ctx, fnode, len(solids) - 1)
    k = _factor(ctx, m, step, f"{what}: {path}")
    dens = [_density(ctx, fnode, s.name, rules, default, what) for s in solids]
    vols = [s.volume * k**3 for s in solids]
    if mass is not None:
        dens = [mass / sum(vols)] * len(solids)
    known[name] = (dens[0] if len(set(dens)) == 1 else None, "volume")
    out = []
    for s, d, v in zip(solids, dens, vols):
        check_mass(ctx, fnode, what, d * v, "density × volume")
        Ri = R @ np.array(s.R)
        com, J = place(np.array(s.centroid) * k, d * v * np.array(s.inertia) * k**2 / s.volume,
                       at + R @ (np.array(s.t) * k), Ri)
        shown = s.name if not named else name if len(solids) == 1 else f"{name}/{s.name}"
        if not named and shown in names:
            raise ctx.error(fnode, f"two parts are named '{literal(shown)}'; name this part")
        names.add(shown)
        extra = {"unit": step.unit or "", **({"colour": s.colour} if s.colour else {})}
        out.append(Part(prefix + shown, "step", d * v, removed, com, J, v, "volume", None,
                        Ri[:, 2].copy(), extra, ctx.where(m), given_outline(d * v, com, J)))
    ctx.warnings.extend(f"{ctx.where(fnode)}: note: {what}: '{literal(e)}' holds no solid"
                        for e in step.empty)
    return out[0] if len(out) == 1 else Stack.of(out)


def _factor(ctx: Ctx, m: ys.MapNode, step, what: str) -> float:
    """The factor ``units:`` and ``scale:`` put on the file's lengths (m), noted."""
    scale, units = scale_units(ctx, m, what, "STEP file")
    if units is None and scale == 1.0:
        return 1.0
    if units is not None and step.metres is None:
        raise ctx.error(m, f"{what}: units: its unit ({literal(step.unit or 'none')}) is unknown")
    k = scale * (units / step.metres if units is not None else 1.0)
    ctx.warnings.append(f"{ctx.where(m)}: note: {what}: its unit {literal(step.unit or '(none)')} "
                        f"overridden: 1 unit = {k * (step.metres or 1.0):g} m")
    return k


def _patterns(ctx: Ctx, m: ys.MapNode, names: list[str], what: str) -> tuple[str | None, list]:
    """``part:`` (None: all) and ``solids:`` (pattern, node); each pattern at most 200
    characters (matching stays cheap) and matching a solid."""
    part = yv.string(ctx, m.items["part"][1], "part") if "part" in m.items else None
    given = yv.mapping(ctx, m.items["solids"][1], "solids").items if "solids" in m.items else {}
    rules = [(p, v) for p, (_k, v) in given.items()]
    for key, p in [("part", part)] * (part is not None) + [("solids", p) for p, _ in rules]:
        if len(p) > 200 or not any(fnmatchcase(n, p) for n in names):
            near = yv.suggest(p, names) if len(p) <= 200 else ""
            shown = ", ".join(names[:8]) + (", ..." if len(names) > 8 else "")
            raise ctx.error(m.items[key][1], literal(f"{what}: {key}: no solid '{p[:60]}'{near} "
                                                     f"(solids: {shown})"))
    return part, rules


def _density(ctx: Ctx, fnode: ys.Node, solid: str, rules: list, default: float | None,
             what: str) -> float:
    """kg/m³ of a solid: its first ``solids:`` rule's, else the part's."""
    for pattern, node in rules:
        if not fnmatchcase(solid, pattern):
            continue
        text = getattr(node, "value", None)
        if isinstance(text, str):
            try:
                return materials.density(text, ctx.materials)
            except ValueError as exc:  # "7.8 g/cm^3" starts with a digit
                if not text.lstrip()[:1].isdigit():
                    raise ctx.error(node, f"{what}: solids: {pattern}: {exc}") from None
        return yv.positive(ctx, node, "density", f"solids: {pattern}")
    if default is None:
        raise ctx.error(fnode, f"{what}: solid '{literal(solid)}' has no density")
    return default
