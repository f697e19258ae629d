"""A body's ``<inertial>`` element for robot and simulation models: URDF, SDF, MJCF.

``inertia --format urdf|sdf|mjcf`` prints it (the formats' attributes and conventions: the
man page of ``rbcli inertia``) from an :class:`rbcli.core.inertial.Inertial`, at full precision
in SI, each element after a comment that states its frame. References: URDF
http://wiki.ros.org/urdf/XML/link, SDF http://sdformat.org/spec?elem=link, MJCF
https://mujoco.readthedocs.io/en/stable/XMLreference.html#body-inertial."""

from __future__ import annotations

import html
from textwrap import indent
from typing import Any

from rbcli.render.safe import escape

FORMATS = ("urdf", "sdf", "mjcf")


def number(x: float) -> str:
    """A float at full precision (shortest repr that reads back exactly); no ``-0.0``."""
    x = float(x)
    return repr(0.0 if x == 0.0 else x)


def _nums(values: Any) -> str:
    return " ".join(number(v) for v in values)


def _comment_text(text: str) -> str:
    """``text`` made safe inside an XML comment: control, bidirectional and XML-illegal
    characters shown as visible escapes (:func:`rbcli.render.safe.escape`: a name can neither
    end the comment's line nor hold what XML forbids), no ``--``, no trailing ``-``."""
    text = escape(text)
    while "--" in text:
        text = text.replace("--", "- -")
    return text.rstrip("-")


def comment(fmt: str, name: str, source: str, inertial: Any) -> str:
    """The comment that says what the element's numbers mean: frame, point, units."""
    what = {"urdf": "URDF <inertial>", "sdf": "SDF <inertial>", "mjcf": "MJCF <inertial>"}[fmt]
    place = {"urdf": "origin xyz", "sdf": "pose x y z", "mjcf": "pos"}[fmt]
    turn = {"urdf": "origin rpy (fixed-axis roll, pitch, yaw, rad: R = Rz(yaw) Ry(pitch) Rx(roll))",
            "sdf": "pose roll pitch yaw (fixed axes, rad: R = Rz(yaw) Ry(pitch) Rx(roll))",
            "mjcf": "quat (w x y z)"}[fmt]
    if inertial.principal:
        frame = (f"inertia: the principal moments (ascending) about the centre of mass, along the "
                 f"principal axes; {turn}: the principal axes in the link frame")
    else:
        sign = "ixy = -(integral of x y dm)"
        tensor = f"fullinertia = ixx iyy izz ixy ixz iyz; {sign}" if fmt == "mjcf" else sign
        frame = (f"inertia: the tensor about the centre of mass in the body axes ({tensor}); "
                 "the inertial frame is not rotated")
    lines = [
        f"rbcli inertia: {what} of body '{name}' ({source})",
        "link frame = the body frame; SI units: kg, m, kg m^2",
        f"{place}: the centre of mass in the link frame, m",
        frame,
    ]
    return "<!-- " + "\n     ".join(_comment_text(x) for x in lines) + " -->\n"


def urdf(inertial: Any) -> str:
    """The URDF ``<inertial>`` element (no comment)."""
    J = inertial.inertia
    return (
        "<inertial>\n"
        f'  <origin xyz="{_nums(inertial.com)}" rpy="{_nums(inertial.rpy)}"/>\n'
        f'  <mass value="{number(inertial.mass)}"/>\n'
        f'  <inertia ixx="{number(J[0, 0])}" ixy="{number(J[0, 1])}" ixz="{number(J[0, 2])}" '
        f'iyy="{number(J[1, 1])}" iyz="{number(J[1, 2])}" izz="{number(J[2, 2])}"/>\n'
        "</inertial>\n"
    )


def sdf(inertial: Any) -> str:
    """The SDF ``<inertial>`` element (no comment)."""
    J = inertial.inertia
    entries = "".join(f"    <{k}>{number(J[i, j])}</{k}>\n" for k, (i, j) in (
        ("ixx", (0, 0)), ("ixy", (0, 1)), ("ixz", (0, 2)), ("iyy", (1, 1)), ("iyz", (1, 2)),
        ("izz", (2, 2))))
    return (
        "<inertial>\n"
        f"  <pose>{_nums(inertial.com)} {_nums(inertial.rpy)}</pose>\n"
        f"  <mass>{number(inertial.mass)}</mass>\n"
        "  <inertia>\n"
        f"{entries}"
        "  </inertia>\n"
        "</inertial>\n"
    )


def mjcf(inertial: Any) -> str:
    """The MJCF ``<inertial>`` element (no comment): ``fullinertia`` in body axes, or
    ``quat`` and ``diaginertia`` in principal axes."""
    J = inertial.inertia
    if inertial.principal:
        return (f'<inertial pos="{_nums(inertial.com)}" quat="{_nums(inertial.quat_wxyz)}" '
                f'mass="{number(inertial.mass)}" diaginertia="{_nums([J[0, 0], J[1, 1], J[2, 2]])}"/>\n')
    full = [J[0, 0], J[1, 1], J[2, 2], J[0, 1], J[0, 2], J[1, 2]]
    return f'<inertial pos="{_nums(inertial.com)}" mass="{number(inertial.mass)}" fullinertia="{_nums(full)}"/>\n'


def links(fmt: str, name: str, source: str, items: Any) -> str:
    """A comment, then a ``<link>`` (``<body>``) per (name, inertial)."""
    tag = "body" if fmt == "mjcf" else "link"
    out = [comment(fmt, name, source, items[0][1])]
    for link, inertial in items:
        element = {"urdf": urdf, "sdf": sdf, "mjcf": mjcf}[fmt](inertial)
        out.append(f'<{tag} name="{html.escape(escape(link), quote=True)}">\n{indent(element, "  ")}</{tag}>\n')
    return "".join(out)


def render(fmt: str, name: str, source: str, inertial: Any) -> str:
    """The comment and the element in format ``fmt`` (``urdf``, ``sdf`` or ``mjcf``)."""
    element = {"urdf": urdf, "sdf": sdf, "mjcf": mjcf}[fmt](inertial)
    return comment(fmt, name, source, inertial) + element
