"""Reading the fields of a body file: numbers with units, vectors, texts, flags, and a
part's placement (``at``, ``axis``, ``rotate``), each checked and located.

Helpers of :mod:`rbcli.body.bodyfile`: ``ctx`` is its per-file context (``error(node, message)``
makes a located :class:`rbcli.errors.InputError`; ``factor(kind, node)`` and ``factors``
give the file's unit of a kind). Every problem is an InputError at the node at fault.
"""

from __future__ import annotations

import difflib
import math
from typing import Any

import numpy as np

from rbcli.core import rotation as rot
from rbcli.errors import InputError
from rbcli.io import units as un
from rbcli.io import yamlsafe as ys

#: largest magnitude accepted for any number in a body file (SI); the Earth's mass
#: (6e24 kg) and moment of inertia (8e37 kg m^2) are well inside.
HUGE = 1e60


# --------------------------------------------------------------------------- scalars


def suggest(word: str, allowed: tuple[str, ...] | list[str]) -> str:
    close = difflib.get_close_matches(word, list(allowed), n=1, cutoff=0.6)
    return f"; did you mean '{close[0]}'?" if close else ""


def check_keys(
    ctx: Any,
    node: ys.MapNode,
    allowed: tuple[str, ...] | list[str],
    what: str,
    required: tuple[str, ...] = (),
) -> None:
    for key, (kmark, _v) in node.items.items():
        if key not in allowed:
            raise ctx.error(
                kmark,
                f"unknown key '{key}' in {what}{suggest(key, allowed)} "
                f"(allowed: {', '.join(allowed)})",
            )
    for key in required:
        if key not in node.items:
            raise ctx.error(node, f"{what} needs '{key}'")


def describe(node: ys.Node) -> str:
    if isinstance(node, ys.MapNode):
        return "a mapping"
    if isinstance(node, ys.SeqNode):
        return "a list"
    assert isinstance(node, ys.ScalarNode)
    if node.value is None:
        return "nothing (null)"
    if isinstance(node.value, bool):
        return f"'{node.raw}' (a boolean)"
    return f"'{node.raw}'"


def mapping(ctx: Any, node: ys.Node, what: str) -> ys.MapNode:
    if not isinstance(node, ys.MapNode):
        raise ctx.error(node, f"{what} must be a mapping (key: value), not {describe(node)}")
    return node


#: quantity texts already read, (text, kind) -> SI value (those :func:`quantity` accepted;
#: a value depends on nothing else): a body file repeats its unit strings ("7850 kg/m^3")
#: thousands of times. At most _MAX_READ entries, then emptied.
_READ: dict[tuple[str, str], float] = {}
_MAX_READ = 1 << 16


def number(ctx: Any, node: ys.Node, kind: str, what: str) -> float:
    """A scalar quantity in SI: a bare number (in the file's units) or a string with a unit."""
    # the common cases first (a bare finite number, its unit's factor known; a text read
    # before): one part of a large body reads ~10 of these
    if node.__class__ is ys.ScalarNode:
        value = node.value
        if value.__class__ is float or value.__class__ is int:
            factor = ctx.factors.get(kind)
            if factor is not None:
                x = float(value) * factor[0]
                if -HUGE <= x <= HUGE:  # also refuses inf and nan: the checks below say why
                    return x
        elif value.__class__ is str:
            x = _READ.get((value, kind))
            if x is not None:
                return x
    return quantity(ctx, node, kind, what)


def quantity(ctx: Any, node: ys.Node, kind: str, what: str) -> float:
    """:func:`number`, every case."""
    if not isinstance(node, ys.ScalarNode) or node.value is None or isinstance(node.value, bool):
        raise ctx.error(node, f"{what} must be a number or a quantity like '30 cm', not {describe(node)}")
    value = node.value
    if isinstance(value, str):
        try:
            x = un.to_si(value, kind)
        except un.UnitError as exc:
            raise ctx.error(node, f"{what}: {exc}") from None
    else:
        factor, _unit = ctx.factor(kind, node)
        x = float(value) * factor
    if not math.isfinite(x):
        raise ctx.error(node, f"{what} must be finite, not {node.raw}")
    if abs(x) > HUGE:
        raise ctx.error(node, f"{what} is too large ({node.raw}); numbers are limited to 1e60 in SI units")
    x = float(x)
    if value.__class__ is str:
        if len(_READ) >= _MAX_READ:
            _READ.clear()
        _READ[value, kind] = x
    return x


def floats(ctx: Any, node: ys.Node, kind: str, what: str, n: int | tuple[int, ...] = 3) -> list[float]:
    """A vector of quantities in SI, as a list of floats."""
    if node.__class__ is not ys.SeqNode or len(node.items) != n:  # else the common case
        sizes = (n,) if isinstance(n, int) else n
        want = " or ".join(str(s) for s in sizes)
        if not isinstance(node, ys.SeqNode):
            raise ctx.error(node, f"{what} must be a list of {want} numbers like [1, 0, 0], not {describe(node)}")
        if len(node.items) not in sizes:
            raise ctx.error(node, f"{what} must have {want} components, not {len(node.items)}")
    factor = ctx.factors.get(kind)
    if factor is not None:  # number's common case, inline
        f = factor[0]
        scalar = ys.ScalarNode
        out = []
        for item in node.items:
            if item.__class__ is scalar:
                value = item.value
                if value.__class__ is float or value.__class__ is int:
                    x = value * f  # an int is converted as float(value) would
                    if -HUGE <= x <= HUGE:
                        out.append(x)
                        continue
            out.append(quantity(ctx, item, kind, what))
        return out
    return [number(ctx, item, kind, what) for item in node.items]


def vector(ctx: Any, node: ys.Node, kind: str, what: str, n: int | tuple[int, ...] = 3) -> np.ndarray:
    return np.array(floats(ctx, node, kind, what, n))


def rows(ctx: Any, node: ys.Node, kind: str, what: str) -> list[list[float]]:
    """A 3x3 matrix of quantities in SI, as three lists of floats."""
    if not isinstance(node, ys.SeqNode) or len(node.items) != 3:
        raise ctx.error(node, f"{what} must be a 3x3 matrix: a list of three rows of three numbers")
    return [floats(ctx, row, kind, f"a row of {what}") for row in node.items]


def matrix(ctx: Any, node: ys.Node, kind: str, what: str) -> np.ndarray:
    return np.array(rows(ctx, node, kind, what))


def string(ctx: Any, node: ys.Node, what: str) -> str:
    if not isinstance(node, ys.ScalarNode) or not isinstance(node.value, str):
        raise ctx.error(node, f"{what} must be a text, not {describe(node)}")
    return node.value


def flag(ctx: Any, node: ys.Node, what: str) -> bool:
    if not isinstance(node, ys.ScalarNode) or not isinstance(node.value, bool):
        raise ctx.error(node, f"{what} must be true or false, not {describe(node)}")
    return node.value


def positive(ctx: Any, node: ys.Node, kind: str, what: str, allow_zero: bool = False) -> float:
    x = number(ctx, node, kind, what)
    if x < 0 or (x == 0 and not allow_zero):
        raise ctx.error(node, f"{what} must be {'zero or ' if allow_zero else ''}positive, not {node.raw}")
    return x


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


# --------------------------------------------------------------------------- placement


ROTATE_KEYS = ("axis", "angle", "euler", "seq", "quaternion", "matrix")
_ROTATE_KEY_SET = frozenset(ROTATE_KEYS)
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
    keys = m.items.keys()
    if not _ROTATE_KEY_SET.issuperset(keys):
        check_keys(ctx, m, ROTATE_KEYS, "rotate")
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


# --------------------------------------------------------------------------- mass


PLACEMENT_KEYS = ("at", "axis", "rotate")
MASS_KEYS = ("mass", "density", "areal_density", "linear_density")
DENSITY_FOR = {
    "volume": "density",
    "area": "areal_density",
    "length": "linear_density",
}
def _a(word: str) -> str:
    """``word`` with its indefinite article: "an area", "a volume"."""
    return f"{'an' if word[:1] in 'aeiou' else 'a'} {word}"




#: what later parts may need from an earlier one (cut_from), by its name: the pair
#: (its density, or None; its measure kind)
Known = tuple


def mass_source(ctx: Any, m: ys.MapNode, measure_kind: str, known: dict[str, Known], what: str):
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
