"""A ``shape: step`` part: each solid of a STEP file (:mod:`rbcli.io.stepfile`) a part, exact
from its B-rep, placed by the file's assembly and then by ``at``/``axis``/``rotate``; named as
the part (one solid) or ``name/solid`` (unnamed: as the file names them, ``link:1/pin``).
``part:`` keeps the solids a name or pattern matches; ``solids:`` gives each its material or
density (the first pattern that matches), else the part's; ``mass:`` is shared by volume.
``units:`` and ``scale:`` override the file's length unit, with a note.
"""

from __future__ import annotations

import os
from fnmatch import fnmatchcase

import numpy as np

from rbcli.body import materials
from rbcli.body.givenpart import given_outline
from rbcli.body.loadctx import Ctx
from rbcli.body.meshpart import mesh_path, scale_units
from rbcli.body.partkeys import MASS_KEYS, PLACEMENT_KEYS, check_mass, mass_source, placement, subtract
from rbcli.body.partmodel import Part
from rbcli.body.placing import Stack, place
from rbcli.body.plausible import note_density
from rbcli.errors import InputError, Location, literal
from rbcli.io import yamlsafe as ys
from rbcli.io import yamlvalues as yv
from rbcli.io.reader import ReadError
from rbcli.io.stepfile import StepError, read_step

STEP_KEYS = ("name", "shape", "file", "part", "units", "scale", "solids", "subtract", "cut_from",
             "mass", "density", "material", *PLACEMENT_KEYS)


def step_part(ctx: Ctx, m: ys.MapNode, name: str, prefix: str, known: dict, named: bool,
              names: set[str]) -> Part | Stack:
    """The part(s) of a ``shape: step`` entry (see the module's docstring); ``named``: it has
    a ``name:`` (else its solids keep the file's names, checked against ``names``)."""
    what = f"part '{name}' (step)"
    yv.check_keys(ctx, m, STEP_KEYS, what, required=("file",))
    fnode = m.items["file"][1]
    path = mesh_path(ctx, fnode, "step", "a STEP file (.step or .stp)")
    scale, factor = scale_units(ctx, m, what, "STEP file")
    mass = default = None
    if any(k in m.items for k in (*MASS_KEYS, "cut_from")) or "solids" not in m.items:
        mass, default, src = mass_source(ctx, m, "volume", known, what)
        if "density" in m.items:
            note_density(ctx, src, "density", default, None, True, what)
    if mass is not None and "solids" in m.items:
        raise ctx.error(m.items["solids"][0], f"{what}: mass is shared by volume, solids: gives "
                        "densities; give one of them")
    removed = subtract(ctx, m)
    at, R = placement(ctx, m)
    budget = ctx.session
    try:
        step = read_step(str(path), budget.max_parts - budget.used + 1)
    except ImportError:
        raise ctx.error(fnode, f"{what}: reading a STEP file needs OpenCascade: pip install "
                        "'rbcli[cad]' (the cadquery-ocp-novtk package)") from None
    except ReadError as exc:
        raise ctx.error(fnode, f"{what}: {exc}") from None
    except StepError as exc:  # at the line of the STEP file ("what" unless it is the body)
        said = literal(str(exc)) if ctx.file == str(path) else f"{what}: {literal(str(exc))}"
        raise InputError(said, Location(str(path), exc.line or 0)) from None
    ctx.inputs.append(os.path.realpath(path))
    part, rules = _patterns(ctx, m, [s.name for s in step.solids], what)
    solids = [s for s in step.solids if part is None or fnmatchcase(s.name, part)]
    budget.spend(ctx, fnode, len(solids) - 1)
    k = scale * _override(ctx, fnode, factor, scale, step, f"{what}: {path}")
    dens = [_density(ctx, fnode, s.name, rules, default, what) for s in solids]
    vols = [s.volume * k**3 for s in solids]
    if mass is not None:  # the mass of them all, shared by volume
        dens = [mass / sum(vols)] * len(solids)
    known[name] = (dens[0] if len(set(dens)) == 1 else None, "volume")
    out = []
    for s, d, v in zip(solids, dens, vols):
        mi = d * v
        check_mass(ctx, fnode, what, mi, "density × volume")
        Ri = R @ np.array(s.R)
        com, J = place(np.array(s.centroid) * k, mi * np.array(s.inertia) * k**2 / s.volume,
                       at + R @ (np.array(s.t) * k), Ri)
        shown = s.name if not named else name if len(solids) == 1 else f"{name}/{s.name}"
        if not named and shown in names:
            raise ctx.error(fnode, f"two parts are named '{literal(shown)}'; name the step part (name:)")
        names.add(shown)
        if s.healed is not None:
            ctx.warnings.append(f"{ctx.where(fnode)}: warning: {what}: {path}: solid "
                                f"'{literal(s.name)}' was not valid; OpenCascade healed it, "
                                f"changing its volume by {s.healed:.2g} of it (a bound on the error)")
        extra = {"unit": step.unit or "", **({"colour": s.colour} if s.colour else {})}
        out.append(Part(prefix + shown, "step", mi, removed, com, J, v, "volume", None,
                        Ri[:, 2].copy(), extra, ctx.where(m), given_outline(mi, com, J)))
    ctx.warnings.extend(f"{ctx.where(fnode)}: note: {what}: {path}: '{literal(e)}' holds no solid"
                        for e in step.empty)
    return out[0] if len(out) == 1 else Stack.of(out)


def _override(ctx: Ctx, fnode: ys.Node, factor: float | None, scale: float, step, what: str) -> float:
    """The factor ``units:`` puts on the file's lengths (in m); a note if it or ``scale:`` does."""
    if factor is None and scale == 1.0:
        return 1.0
    if factor is not None and step.metres is None:
        raise ctx.error(fnode, f"{what}: units: the file's length unit ({literal(step.unit or 'none')}) "
                        "is not one rbcli knows, so it cannot be replaced")
    k = factor / step.metres if factor is not None else 1.0
    ctx.warnings.append(f"{ctx.where(fnode)}: note: {what}: its length unit "
                        f"{literal(step.unit or '(none)')} is overridden: 1 unit = "
                        f"{scale * k * (step.metres or 1.0):g} m")
    return k


def _patterns(ctx: Ctx, m: ys.MapNode, names: list[str], what: str) -> tuple[str | None, list]:
    """``part:`` (None: all) and ``solids:`` as (pattern, its material or density node); each
    name or pattern must match a solid of the file (a misspelt one is an error) and be at
    most 200 characters (matching stays cheap)."""
    part = yv.string(ctx, m.items["part"][1], "part") if "part" in m.items else None
    rules = ([(p, v) for p, (_k, v) in yv.mapping(ctx, m.items["solids"][1], "solids").items.items()]
             if "solids" in m.items else [])
    for key, p in [("part", part)] * (part is not None) + [("solids", p) for p, _ in rules]:
        if len(p) > 200 or not any(fnmatchcase(n, p) for n in names):
            near = yv.suggest(p, names) if len(p) <= 200 else ""
            shown = ", ".join(names[:8]) + (", ..." if len(names) > 8 else "")
            raise ctx.error(m.items[key][1], literal(f"{what}: {key}: '{p[:60]}' is no solid of "
                                                     f"the file{near} (solids: {shown})"))
    return part, rules


def _density(ctx: Ctx, fnode: ys.Node, solid: str, rules: list, default: float | None,
             what: str) -> float:
    """kg/m³ of one solid: the first ``solids:`` rule that matches it (a material, else a
    density), else the part's own."""
    for pattern, node in rules:
        if not fnmatchcase(solid, pattern):
            continue
        text = node.value if isinstance(node, ys.ScalarNode) and isinstance(node.value, str) else None
        if text is not None:
            try:
                return materials.density(text, ctx.materials)
            except ValueError as exc:  # a density ("7.8 g/cm^3") if it starts with a digit
                if not text.lstrip()[:1].isdigit():
                    raise ctx.error(node, f"{what}: solids: {pattern}: {exc}") from None
        return yv.positive(ctx, node, "density", f"solids: {pattern}")
    if default is None:
        raise ctx.error(fnode, f"{what}: solid '{literal(solid)}' has no density: give density "
                        "or material (for all), or a solids: entry that matches it")
    return default
