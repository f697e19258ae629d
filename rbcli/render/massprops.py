"""Tables for ``inertia`` and ``principal`` (the JSON is the results' ``to_json()``).

The functions take a result of :mod:`rbcli.api.inertia` or :mod:`rbcli.api.principal`
(``InertiaResult``, ``PrincipalResult``); the report also passes :mod:`rbcli.core` results, which have the
same attributes.
"""

from __future__ import annotations

import numpy as np

from typing import TYPE_CHECKING, Any

from rbcli.model import Body
from rbcli.render.fmt import num, snap
from rbcli.render.units import DisplayUnits

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.render.text import Doc  # hints only: --json never loads render.text

AXES = ("x", "y", "z")


def has_mesh(body: Body) -> bool:
    return any("volume" in p.extra for p in body.parts)


def mesh_columns(du: DisplayUnits) -> tuple[str, str, str]:
    return (f"volume [{du.unit('volume')}]", f"area [{du.unit('area')}]", "triangles")


def _mesh_cells(p, du: DisplayUnits, digits: int) -> list[str]:
    """Volume, surface area and triangle count of a mesh part ("" for other parts)."""
    if "volume" not in p.extra:
        return ["", "", ""]
    return [
        du.show(p.extra["volume"], "volume", digits),
        du.show(p.extra["area"], "area", digits),
        str(p.extra["triangles"]),
    ]


def mesh_table(doc: Doc, body: Body, du: DisplayUnits, digits: int) -> None:
    """A table of the body's mesh parts (name, volume, area, triangles), if it has any."""
    rows = [(p.name + (" (hole)" if p.subtract else ""), *_mesh_cells(p, du, digits))
            for p in body.parts if "volume" in p.extra]
    if rows:
        doc.table("mesh parts", ("part", *mesh_columns(du)), rows, right=(1, 2, 3))


def _vec_rows(label: str, v, du: DisplayUnits, kind: str, digits: int) -> list[tuple[str, str, str]]:
    u = du.unit(kind)
    return [(f"{label} {a}", du.show(x, kind, digits), u) for a, x in zip(AXES, v)]


def _matrix(doc: Doc, title: str, J, du: DisplayUnits, digits: int, products: str) -> None:
    J = snap(J)
    f, unit = du.factor("inertia")
    if products == "positive":
        rows = [
            ("Ixx", num(J[0, 0] * f, digits), unit),
            ("Iyy", num(J[1, 1] * f, digits), unit),
            ("Izz", num(J[2, 2] * f, digits), unit),
            ("Ixy = +∫xy dm", num(-J[0, 1] * f, digits), unit),
            ("Iyz = +∫yz dm", num(-J[1, 2] * f, digits), unit),
            ("Izx = +∫zx dm", num(-J[2, 0] * f, digits), unit),
        ]
        doc.kv(title, rows)
        doc.note("(positive products: Ixy = +∫xy dm; the tensor's off-diagonal entries are their negatives)")
        return
    rows = [[a] + [num(J[i, j] * f, digits) for j in range(3)] for i, a in enumerate(AXES)]
    doc.table(f"{title} [{unit}]", ("", "x", "y", "z"), rows, right=(1, 2, 3))
    doc.note("(the tensor: off-diagonal entries are −∫xy dm; --products positive shows +∫xy dm)")


#: the "options" table of ``inertia`` and ``principal``: (parameter, options attribute, how)
#: rows for :func:`rbcli.render.units.echo_rows`
INERTIA_OPTIONS = (("about", "about", "point"), ("axis", "axis", "direction"),
                   ("omega", "omega", "angular_speed"))
PRINCIPAL_OPTIONS = (("about", "about", "point"),)


def inertia_doc(doc: Doc, body: Body, r: Any, du: DisplayUnits, digits: int, products: str,
                ref_label: str, *, parts: bool = True) -> None:
    """The tables of ``rbcli inertia``; ``parts=False`` leaves out the parts table (the
    report has its own, with each part's contribution)."""
    doc.heading(f"{body.name}  ({body.source})")
    rows = [("mass", du.show(r.mass, "mass", digits), du.unit("mass"))]
    rows += _vec_rows("com", r.com, du, "length", digits)
    rows += _vec_rows("reference", r.reference, du, "length", digits)
    doc.kv("mass properties", rows)
    if parts and (len(body.parts) > 1 or body.parts[0].extra):
        L = du.unit("length")
        meshes = has_mesh(body)
        prow = []
        for p in body.parts:
            row = [
                p.name,
                p.shape + (" (hole)" if p.subtract else ""),
                du.show(p.signed_mass, "mass", digits),
                ", ".join(du.show(x, "length", digits) for x in p.com),
            ]
            if meshes:
                row += _mesh_cells(p, du, digits)
            prow.append(tuple(row))
        cols = ("part", "shape", f"mass [{du.unit('mass')}]", f"com [{L}]")
        if meshes:
            cols += mesh_columns(du)
        doc.table("parts", cols, prow, right=(2, 4, 5, 6) if meshes else (2,))
    _matrix(doc, f"inertia about {ref_label}", r.inertia, du, digits, products)
    if not np.allclose(r.reference, r.com, rtol=0, atol=0):
        _matrix(doc, "inertia about the com", r.inertia_com, du, digits, products)
    if r.axis is not None:
        doc.kv(
            f"moment about the axis through {ref_label}",
            [
                ("axis (unit)", ", ".join(num(x, digits) for x in r.axis), ""),
                ("I = n·J·n", du.show(r.axis_moment, "inertia", digits), du.unit("inertia")),
            ],
        )
    if r.omega is not None:
        rows = _vec_rows("ω", r.omega, du, "angular_speed", digits)
        rows += _vec_rows("L = J·ω", r.angular_momentum, du, "angular_momentum", digits)
        rows.append(("|L|", du.show(float(np.linalg.norm(r.angular_momentum)), "angular_momentum", digits), du.unit("angular_momentum")))
        rows.append(("T = ω·J·ω/2", du.show(r.kinetic_energy, "energy", digits), du.unit("energy")))
        rows.append(("angle between L and ω", num(r.angle_L_omega_deg, digits), "°"))
        doc.kv(f"rotation about {ref_label}", rows)


def principal_doc(doc: Doc, body: Body, r: Any, du: DisplayUnits, digits: int, ref_label: str,
                  *, parts: bool = True) -> None:
    """The tables of ``rbcli principal``; ``parts=False`` leaves out the mesh parts table
    (the report has its own parts table, with the mesh facts)."""
    doc.heading(f"{body.name}  ({body.source})")
    f, unit = du.factor("inertia")
    rows = []
    angles = r.direction_angles_deg
    for i in range(3):
        rows.append(
            (
                str(i + 1),
                num(r.moments[i] * f, digits),
                ", ".join(num(x, digits) for x in snap(r.axes[i], scale=1.0, rtol=1e-15)),
                ", ".join(num(x, 4) for x in angles[i]),
                r.stability[i],
            )
        )
    doc.table(
        f"principal moments about {ref_label} [{unit}], ascending",
        ("axis", "moment", "direction (body x, y, z)", "angles to x, y, z [°]", "free rotation"),
        rows,
        right=(1,),
    )
    if max(r.tilt_deg) == 0.0:
        along = ", ".join(f"axis {i + 1} along {r.tilt_axis[i]}" for i in range(3))
        doc.note(f"principal axes along the body axes (tilt 0°): {along}")
    else:
        tilts = ", ".join(f"axis {i + 1} by {num(r.tilt_deg[i], digits)}° from {r.tilt_axis[i]}"
                          for i in range(3))
        doc.note(f"principal axes tilted up to {num(max(r.tilt_deg), digits)}° from the body axes: {tilts}")
    doc.note(symmetry_sentence(r))
    doc.note(
        "rotation taking the body axes to principal axes 1, 2, 3 (in ascending order of the "
        f"moments): {num(r.rotation_angle_deg, digits)}° about "
        f"[{', '.join(num(x, digits) for x in r.rotation_axis)}]"
    )
    L = du.unit("length")
    doc.kv(
        "equivalent uniform bodies (same mass and principal moments)",
        [
            ("box sides along axes 1, 2, 3", ", ".join(du.show(x, "length", digits) for x in r.equivalent_box), L),
            ("ellipsoid semi-axes along 1, 2, 3", ", ".join(du.show(x, "length", digits) for x in r.equivalent_ellipsoid), L),
        ],
    )
    if parts:
        mesh_table(doc, body, du, digits)


def symmetry_sentence(r: Any) -> str:
    if r.symmetry == "spherical":
        return (
            "spherical: all three moments are equal, so every axis through the point is "
            "principal (the axes shown are the body axes); rotation about any axis is steady."
        )
    if r.symmetry == "symmetric":
        u = (r.unique_axis or 0) + 1
        a, b = (i + 1 for i in r.free_axes)
        kind = "oblate (flattened, like a disk)" if u == 3 else "prolate (elongated, like a rod)"
        return (
            f"symmetric about axis {u}: moments {a} and {b} are equal, so every axis at right "
            f"angles to axis {u} is principal (axes {a} and {b} are free to choose; shown aligned "
            f"with the body axes where possible); {kind}. Rotation about axis {u} is stable; about "
            f"an axis in the {a}-{b} plane the spin stays in that plane (neutral)."
        )
    return (
        "asymmetric: three different moments; free rotation is stable about axes 1 and 3 "
        "(smallest and largest moment) and unstable about axis 2 (the intermediate axis, "
        "the tennis-racket flip)."
    )
