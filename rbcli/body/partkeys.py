"""The keys every part shares (placement, mass or density or material, ``cut_from``,
``subtract``) and the body's points and directions, read through :mod:`rbcli.io.yamlvalues`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from rbcli.body import materials
from rbcli.core import rotation as rot
from rbcli.errors import InputError
from rbcli.io import yamlsafe as ys
from rbcli.io.yamlvalues import (
    HUGE,
    check_keys,
    flag,
    floats,
    mapping,
    number,
    positive,
    rows,
    string,
    suggest,
    vector,
)

#: the keys of a part's placement and of its mass
PLACEMENT_KEYS = ("at", "axis", "rotate")
MASS_KEYS = ("mass", "density", "areal_density", "linear_density", "material")
#: the density key of each kind of measure
DENSITY_FOR = {"volume": "density", "area": "areal_density", "length": "linear_density"}


def point(ctx: Any, node: ys.Node, what: str) -> np.ndarray | str:
    """A point: a vector of lengths, or the words 'com' / 'origin'."""
    if isinstance(node, ys.ScalarNode) and node.value in ("com", "origin"):
        return str(node.value)
    return vector(ctx, node, "length", what)


def direction(ctx: Any, node: ys.Node, what: str) -> np.ndarray:
    """A unit vector (the largest component scaled to 1 first, so that tiny (1e-320) or
    huge components do not under/overflow the norm)."""
    return rot.unit_rows(np.array([direction_floats(ctx, node, what)]))[0]


def direction_floats(ctx: Any, node: ys.Node, what: str) -> list[float]:
    """A direction as written (SI floats, not normalised), checked non-zero."""
    v = floats(ctx, node, "dimensionless", what)
    if not any(v):  # all zero (the numbers are finite)
        raise ctx.error(node, f"{what} must be a non-zero vector")
    return v


ROTATE_KEYS = ("axis", "angle", "euler", "seq", "quaternion", "matrix")
ROTATE_FORMS = {
    "axis-angle": frozenset({"axis", "angle"}),
    "euler": frozenset({"euler", "seq"}),
    "quaternion": frozenset({"quaternion"}),
    "matrix": frozenset({"matrix"}),
}


def rotation(ctx: Any, node: ys.Node) -> tuple:
    """The ``rotate`` mapping, checked, as a rotation spec (see
    :func:`rbcli.core.rotation.from_specs`)."""
    m = mapping(ctx, node, "rotate")
    check_keys(ctx, m, ROTATE_KEYS, "rotate")
    keys = m.items.keys()
    for name, form in ROTATE_FORMS.items():
        if keys == form:
            break
    else:
        raise ctx.error(
            m,
            "rotate takes one of {axis: [x, y, z], angle: A}, {euler: [a, b, c], seq: ZYX}, "
            "{quaternion: [w, x, y, z]} or {matrix: [[..], [..], [..]]}",
        )
    try:
        if name == "axis-angle":
            axis = direction_floats(ctx, m.items["axis"][1], "rotate axis")
            angle = number(ctx, m.items["angle"][1], "angle", "rotate angle")
            return ("axis-angle", axis, angle)
        if name == "euler":
            seq_node = m.items["seq"][1]
            seq = string(ctx, seq_node, "seq")
            angles_node = m.items["euler"][1]
            angles = floats(ctx, angles_node, "angle", "euler angles", n=len(seq) if 1 <= len(seq) <= 3 else 3)
            try:
                rot.euler_intrinsic(seq)
            except ValueError as exc:
                raise ctx.error(seq_node, str(exc)) from None
            return ("euler", angles, seq)
        if name == "quaternion":
            q_node = m.items["quaternion"][1]
            q = floats(ctx, q_node, "dimensionless", "quaternion", n=4)
            if not any(q):  # all zero (the numbers are finite)
                raise ctx.error(q_node, "quaternion must be non-zero")
            return ("quaternion", q)
        mat_node = m.items["matrix"][1]
        mat = rows(ctx, mat_node, "dimensionless", "rotation matrix")
        if rot.surely_rotation(mat):
            return ("matrix", mat)  # rot.from_matrix would accept it: made with the others
        try:
            return ("R", rot.from_matrix(np.array(mat)))
        except ValueError as exc:
            raise ctx.error(mat_node, f"rotation matrix: {exc}") from None
    except InputError:  # already located (an InputError is a ValueError)
        raise
    except ValueError as exc:  # a ValueError not already located
        raise ctx.error(m, str(exc)) from None


def placement_spec(ctx: Any, m: ys.MapNode) -> tuple[list[float], tuple | None]:
    """A part's ``at`` (m, floats) and its rotation spec (None: no rotation), checked."""
    at = [0.0, 0.0, 0.0]
    spec = None
    items = m.items
    if "at" in items:
        at = floats(ctx, items["at"][1], "length", "at")
    if "axis" in items:
        if "rotate" in items:
            raise ctx.error(items["rotate"][0], "give either 'axis' or 'rotate', not both")
        spec = ("axis", direction_floats(ctx, items["axis"][1], "axis"))
    elif "rotate" in items:
        spec = rotation(ctx, items["rotate"][1])
    return at, spec


def placement(ctx: Any, m: ys.MapNode) -> tuple[np.ndarray, np.ndarray]:
    """A part's ``at`` (m) and rotation matrix, for the parts placed one by one (the
    primitives are placed in batches: :mod:`rbcli.body.placing`)."""
    at, spec = placement_spec(ctx, m)
    return np.array(at), rot.from_specs([spec])[0]


def _a(word: str) -> str:
    """``word`` with its indefinite article: "an area", "a volume"."""
    return f"{'an' if word[:1] in 'aeiou' else 'a'} {word}"


def mass_source(ctx: Any, m: ys.MapNode, measure_kind: str,
                known: dict[str, tuple[float | None, str]], what: str):
    """(mass or None, density or None, the node to blame); ``known``: each earlier part's
    (density or None, measure kind), for a hole's ``cut_from``."""
    items = m.items
    given = list(filter(items.__contains__, MASS_KEYS))  # in MASS_KEYS's order
    cut = items.get("cut_from")
    if cut is not None:
        given.append("cut_from")
    if len(given) > 1:
        raise ctx.error(
            m.items[given[1]][0] if given[1] in m.items else m,
            f"{what} gives both '{given[0]}' and '{given[1]}'; give exactly one of "
            "mass, density, areal_density, linear_density, material (or cut_from for a hole)",
        )
    if not given:
        want = DENSITY_FOR.get(measure_kind)
        alt = f" or {want}" + (" (or a material)" if want == "density" else "") if want else ""
        raise ctx.error(m, f"{what} needs its mass{alt}")
    key = given[0]
    kmark, node = (cut if key == "cut_from" else m.items[key])
    if key == "mass":
        return positive(ctx, node, "mass", f"{what}: mass"), None, node
    if key == "cut_from":
        if "subtract" not in m.items or not flag(ctx, m.items["subtract"][1], "subtract"):
            raise ctx.error(kmark, "cut_from is for holes: it needs 'subtract: true'")
        src = string(ctx, node, "cut_from")
        if src not in known:
            raise ctx.error(node, f"cut_from: no earlier part is named '{src}'{suggest(src, list(known))}")
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
    if key == "material" and want == "density":
        name = string(ctx, node, "material")
        try:
            return None, materials.density(name, ctx.materials), node
        except ValueError as exc:
            raise ctx.error(node, f"{what}: {exc}") from None
    if key != want:
        hint = f"; use '{want}'" if want else "; give its mass"
        raise ctx.error(kmark, f"{what} is {_a(measure_kind)} part, so '{key}' does not apply{hint}")
    kind = key  # density, areal_density, linear_density are also unit kinds
    return None, positive(ctx, node, kind, f"{what}: {key}"), node


def check_mass(ctx: Any, node: ys.Node, what: str, mass: float, how: str) -> None:
    """A mass computed from a density must stay within the limits of any number (HUGE)."""
    if not mass <= HUGE:  # also refuses inf and nan
        raise ctx.error(
            node,
            f"{what}: its mass ({how}) is {mass:.3g} kg, too large; "
            "numbers are limited to 1e60 in SI units",
        )


def subtract(ctx: Any, m: ys.MapNode) -> bool:
    return flag(ctx, m.items["subtract"][1], "subtract") if "subtract" in m.items else False
