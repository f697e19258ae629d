"""A ``shape: given`` part: mass, centre of mass and inertia copied from elsewhere (a CAD
report, a data sheet), checked to be a physically possible inertia."""

from __future__ import annotations

import numpy as np

from rbcli.core.inertia import tensor_problem
from rbcli.io import fields as fl
from rbcli.io import yamlsafe as ys
from rbcli.io.fields import PLACEMENT_KEYS, subtract
from rbcli.io.loadctx import Ctx
from rbcli.io.placing import place
from rbcli.model import Outline, Part

GIVEN_KEYS = ("name", "shape", "subtract", "mass", "com", "inertia", "convention", *PLACEMENT_KEYS)
INERTIA_MAP_KEYS = ("Ixx", "Iyy", "Izz", "Ixy", "Iyz", "Izx", "convention")


def given_part(ctx: Ctx, m: ys.MapNode, name: str, prefix: str, known: dict) -> Part:
    what = f"part '{name}' (given)"
    fl.check_keys(ctx, m, GIVEN_KEYS, what, required=("mass", "inertia"))
    mass = fl.positive(ctx, m.items["mass"][1], "mass", f"{what}: mass")
    com = fl.vector(ctx, m.items["com"][1], "length", "com") if "com" in m.items else np.zeros(3)
    inode = m.items["inertia"][1]
    if isinstance(inode, ys.MapNode):
        fl.check_keys(ctx, inode, INERTIA_MAP_KEYS, "inertia", required=("Ixx", "Iyy", "Izz"))
        g = {k: fl.number(ctx, inode.items[k][1], "inertia", k) if k in inode.items else 0.0 for k in INERTIA_MAP_KEYS[:6]}
        has_products = any(k in inode.items for k in ("Ixy", "Iyz", "Izx"))
        sign = -1.0
        if "convention" in inode.items:
            conv_node = inode.items["convention"][1]
            conv = fl.string(ctx, conv_node, "convention")
            if conv not in ("tensor", "positive"):
                raise ctx.error(conv_node, f"convention must be 'tensor' or 'positive', not '{conv}'")
            sign = 1.0 if conv == "tensor" else -1.0
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
        if "convention" in m.items:
            raise ctx.error(m.items["convention"][0], f"{what}: the Ixx... form states its "
                            "convention inside 'inertia'; remove the part's 'convention'")
    else:
        J = fl.matrix(ctx, inode, "inertia", "inertia")
        off = J[~np.eye(3, dtype=bool)]
        if "convention" in m.items:
            conv_node = m.items["convention"][1]
            conv = fl.string(ctx, conv_node, "convention")
            if conv not in ("tensor", "positive"):
                raise ctx.error(conv_node, f"convention must be 'tensor' or 'positive', not '{conv}'")
            if conv == "positive":
                J = np.where(np.eye(3, dtype=bool), J, -J)
        elif np.any(off != 0.0):
            raise ctx.error(
                inode,
                f"{what}: a 3x3 inertia with non-zero off-diagonal entries needs 'convention: "
                "tensor' (entries are the tensor's, −∫xy dm) or 'convention: positive' (products "
                "of inertia +∫xy dm, as many CAD tools print them) beside it",
            )
    factor, unit = ctx.factor("inertia", inode)
    problem = tensor_problem(J, unit=pretty_unit(unit), factor=factor)
    if problem:
        raise ctx.error(inode, f"{what}: the inertia is not physically possible: {problem}")
    J = 0.5 * (J + J.T)
    at, R = fl.placement(ctx, m)
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
    """A given part is drawn as its equivalent uniform ellipsoid, centred on its com: the
    outline keeps its mass and its inertia about the com (body axes), from which the figure
    makes the ellipsoid when it draws (:mod:`rbcli.render.outline`)."""
    inertia = tuple(tuple(row) for row in J.tolist())
    return Outline("given", (("mass", float(mass)), ("inertia", inertia)), com, np.eye(3))

