"""A ``shape: given`` part: mass, centre of mass and inertia copied from elsewhere (a CAD
report, a data sheet), checked to be a physically possible inertia.

The inertia is a 3x3 matrix or a map of its entries, named as CAD reports name them:
``Ixx ... Izx`` (most tools), ``Lxx ... Lzx`` (SolidWorks), a product's letters in either
order (``Izx`` or ``Ixz``; both, as a full 3x3 report lists them, when they agree). The sign of the
products differs between tools, so ``convention`` (tensor or positive) is needed as soon
as a product is non-zero. A matrix copied from a report is symmetric only to the digits
printed: within 1e-9 of its largest entry its symmetric part is used, with a note.
"""

from __future__ import annotations

import numpy as np

from rbcli.body.loadctx import Ctx
from rbcli.body.partkeys import PLACEMENT_KEYS, placement, subtract
from rbcli.body.partmodel import Outline, Part, equivalent_ellipsoid
from rbcli.body.placing import place
from rbcli.core.inertia import tensor_problem
from rbcli.io import yamlsafe as ys
from rbcli.io import yamlvalues as yv

GIVEN_KEYS = ("name", "shape", "subtract", "mass", "com", "inertia", "convention", *PLACEMENT_KEYS)
#: each entry of the map form, and the names it is read by: I.. (most tools), L.. (SolidWorks's
#: mass properties report), a product's letters in either order
INERTIA_NAMES: dict[str, tuple[str, ...]] = {
    "Ixx": ("Ixx", "Lxx"), "Iyy": ("Iyy", "Lyy"), "Izz": ("Izz", "Lzz"),
    "Ixy": ("Ixy", "Iyx", "Lxy", "Lyx"), "Iyz": ("Iyz", "Izy", "Lyz", "Lzy"),
    "Izx": ("Izx", "Ixz", "Lzx", "Lxz"),
}  # fmt: skip
INERTIA_MAP_KEYS = (*(n for names in INERTIA_NAMES.values() for n in names), "convention")
#: a matrix asymmetric by at most this, relative to its largest entry, is read as its
#: symmetric part (a CAD report's digits), with a note; more is refused
SYMMETRY_RTOL = 1e-9


def _entries(ctx: Ctx, inode: ys.MapNode) -> dict[str, float]:
    """The map form's six entries (SI; absent products 0), each read under whichever of its
    names was given; a product given in both orders (a full 3x3 report: ``Lxy`` and ``Lyx``)
    is their mean when they agree within :data:`SYMMETRY_RTOL` of the largest entry; a
    diagonal entry missing, or any other entry given twice, is an error."""
    yv.check_keys(ctx, inode, INERTIA_MAP_KEYS, "inertia")
    items = inode.items
    g, pairs = {}, []
    for entry, names in INERTIA_NAMES.items():
        given = [k for k in items if k in names]  # in file order
        if len(given) > 2 or len(given) == 2 and given[1] != given[0][0] + given[0][:0:-1]:
            raise ctx.error(items[given[1]][0], f"inertia gives {entry} twice, as '{given[0]}' and "
                            f"'{given[1]}'; give each entry once")
        if not given and entry in ("Ixx", "Iyy", "Izz"):
            raise ctx.error(inode, f"inertia needs '{entry}'")
        vals = [yv.number(ctx, items[k][1], "inertia", k) for k in given]
        g[entry] = sum(vals) / len(vals) if vals else 0.0
        pairs += [(given, vals)] if len(vals) == 2 else []
    for (a, b), (x, y) in pairs:
        if abs(x - y) > SYMMETRY_RTOL * max(abs(v) for v in g.values()):
            raise ctx.error(items[b][0], f"inertia's '{a}' and '{b}' differ ({items[a][1].raw} and "
                            f"{items[b][1].raw}): a tensor is symmetric; give each product once")
    return g


def _convention(ctx: Ctx, m: ys.MapNode) -> str:
    """The ``convention`` of mapping ``m``: 'tensor' or 'positive'."""
    node = m.items["convention"][1]
    conv = yv.string(ctx, node, "convention")
    if conv not in ("tensor", "positive"):
        raise ctx.error(node, f"convention must be 'tensor' or 'positive', not '{conv}'")
    return conv


def given_part(ctx: Ctx, m: ys.MapNode, name: str, prefix: str, known: dict) -> Part:
    what = f"part '{name}' (given)"
    yv.check_keys(ctx, m, GIVEN_KEYS, what, required=("mass", "inertia"))
    mass = yv.positive(ctx, m.items["mass"][1], "mass", f"{what}: mass")
    com = yv.vector(ctx, m.items["com"][1], "length", "com") if "com" in m.items else np.zeros(3)
    inode = m.items["inertia"][1]
    if isinstance(inode, ys.MapNode):
        if "convention" in m.items:  # (before the products ask for one: it is there, misplaced)
            raise ctx.error(m.items["convention"][0], f"{what}: the Ixx... form states its "
                            "convention inside 'inertia'; move 'convention' into the inertia mapping")
        g = _entries(ctx, inode)
        has_products = any(g[k] != 0.0 for k in ("Ixy", "Iyz", "Izx"))
        sign = -1.0
        if "convention" in inode.items:
            sign = 1.0 if _convention(ctx, inode) == "tensor" else -1.0
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
    else:
        J = yv.matrix(ctx, inode, "inertia", "inertia")
        off = J[~np.eye(3, dtype=bool)]
        if "convention" in m.items:
            if _convention(ctx, m) == "positive":
                J = np.where(np.eye(3, dtype=bool), J, -J)
        elif np.any(off != 0.0):
            raise ctx.error(
                inode,
                f"{what}: a 3x3 inertia with non-zero off-diagonal entries needs 'convention: "
                "tensor' (entries are the tensor's, −∫xy dm) or 'convention: positive' (products "
                "of inertia +∫xy dm, as many CAD tools print them) beside it",
            )
    factor, unit = ctx.factor("inertia", inode)
    problem = tensor_problem(J, rtol=SYMMETRY_RTOL, unit=pretty_unit(unit), factor=factor)
    if problem:
        raise ctx.error(inode, f"{what}: the inertia is not physically possible: {problem}")
    asym = float(np.max(np.abs(J - J.T)))
    if asym > 0.0:  # within SYMMETRY_RTOL (tensor_problem): the digits printed
        share = asym / float(np.max(np.abs(J)))
        ctx.warnings.append(
            f"{ctx.where(inode)}: note: {what}: the inertia is symmetric to {share:.1g} of its "
            "largest entry (as its digits were printed); its symmetric part is used")
    J = 0.5 * (J + J.T)
    at, R = placement(ctx, m)
    known[name] = (None, "given")
    pc, PJ = place(com, J, at, R)
    return Part(
        name=prefix + name, shape="given", mass=mass, subtract=subtract(ctx, m), com=pc,
        inertia_com=PJ, measure=None, measure_kind="given", axis=R[:, 2].copy(), where=ctx.where(m),
        outline=_given_outline(mass, pc, PJ),
    )


def pretty_unit(text: str) -> str:
    """``g*mm^2`` as ``g·mm²`` for messages."""
    return text.replace("*", "·").replace("^2", "²").replace("^3", "³")


def _given_outline(mass: float, com: np.ndarray, J: np.ndarray) -> Outline:
    """A given part's shape: its equivalent uniform ellipsoid, centred on its com (drawn by
    the figure, measured by the plausibility warnings: rbcli.core.scale)."""
    semi, axes = equivalent_ellipsoid(mass, J)
    return Outline("given", (("semi_axes", tuple(float(x) for x in semi)),), com, axes)

