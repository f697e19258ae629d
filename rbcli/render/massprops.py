"""Tables for ``inertia`` and ``principal``: of an ``InertiaResult`` or ``PrincipalResult``
(or the :mod:`rbcli.core` results with the same attributes the report passes)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from rbcli.render.fmt import num, snap
from rbcli.render.units import DisplayUnits

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.body.model import Body
    from rbcli.render.text import Doc  # hints only: --json never loads render.text

AXES = ("x", "y", "z")

#: the most part rows a parts table shows (``inertia``'s and ``principal``'s on the terminal,
#: the report's): a body of more parts shows this many, those that matter most (the heaviest;
#: in the report the largest contributions to the moments), in file order, and one row that
#: sums the rest. A table is for reading: 100 rows is two printed pages, and rich lays a
#: table out at ~0.2 ms a row (a 100 000-row table took 25 s). ``--json`` (and ``--format
#: csv``) list every part.
PARTS_TABLE_ROWS = 100


def kept_parts(*scores, limit: int = PARTS_TABLE_ROWS) -> np.ndarray | None:
    """Which parts a summarised table shows: None when all fit in ``limit`` rows, else the
    indices (in file order) of the ``limit`` of largest score (``scores``: (n,) arrays, each
    breaking the ties of those before it; then the earlier part)."""
    n = len(scores[0])
    if n <= limit:
        return None
    keys = [np.arange(n)] + [-np.asarray(s, dtype=float) for s in reversed(scores)]
    return np.sort(np.lexsort(keys)[:limit])


def more_parts(k: int) -> str:
    """The name cell of the row that sums the parts not shown."""
    return f"({k} more part{'s' if k != 1 else ''})"


def _masses(parts) -> np.ndarray:
    return np.fromiter((p.signed_mass for p in parts), dtype=float, count=len(parts))


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
    """A table of the body's mesh parts (name, volume, area, triangles), if it has any;
    summarised by volume as :data:`PARTS_TABLE_ROWS` says."""
    meshes = [p for p in body.parts if "volume" in p.extra]
    if not meshes:
        return
    keep = kept_parts([p.extra["volume"] for p in meshes])
    shown = meshes if keep is None else [meshes[i] for i in keep]
    rows = [(p.name + (" (hole)" if p.subtract else ""), *_mesh_cells(p, du, digits)) for p in shown]
    if keep is not None:
        others = [p for p, r in zip(meshes, rest_of(len(meshes), keep)) if r]
        rows.append((more_parts(len(others)), *_mesh_sums(others, du, digits)))
    doc.table("mesh parts", ("part", *mesh_columns(du)), rows, right=(1, 2, 3))
    if keep is not None:
        doc.note(f"(the {len(keep)} largest of {len(meshes)} mesh parts by volume, in file order; "
                 "the last row sums the others; --json lists every part)")


def vec_rows(label: str, v, du: DisplayUnits, kind: str, digits: int) -> list[tuple[str, str, str]]:
    """The rows ``label x``, ``label y``, ``label z`` of a vector ``v`` (SI) of ``kind``."""
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


def inertia_doc(doc: Doc, body: Body, r: Any, du: DisplayUnits, digits: int, products: str,
                ref_label: str, *, parts: bool = True) -> None:
    """The tables of ``rbcli inertia``; ``parts=False`` leaves out the parts table (the
    report has its own, with each part's contribution)."""
    du = du.of(body)
    doc.heading(f"{body.name}  ({body.source})")
    rows = [("mass", du.show(r.mass, "mass", digits), du.unit("mass"))]
    rows += vec_rows("com", r.com, du, "length", digits)
    rows += vec_rows("reference", r.reference, du, "length", digits)
    doc.kv("mass properties", rows)
    if parts and (len(body.parts) > 1 or body.parts[0].extra):
        _parts_table(doc, body, du, digits)
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
        rows = vec_rows("ω", r.omega, du, "angular_speed", digits)
        rows += vec_rows("L = J·ω", r.angular_momentum, du, "angular_momentum", digits)
        rows.append(("|L|", du.show(float(np.linalg.norm(r.angular_momentum)), "angular_momentum", digits), du.unit("angular_momentum")))
        rows.append(("T = ω·J·ω/2", du.show(r.kinetic_energy, "energy", digits), du.unit("energy")))
        rows.append(("angle between L and ω", num(r.angle_L_omega_deg, digits), "°"))
        doc.kv(f"rotation about {ref_label}", rows)


def _parts_table(doc: Doc, body: Body, du: DisplayUnits, digits: int) -> None:
    """``inertia``'s parts table: each part's mass and centre (and a mesh's facts);
    summarised by mass as :data:`PARTS_TABLE_ROWS` says."""
    L = du.unit("length")
    meshes = has_mesh(body)
    parts = body.parts
    masses = _masses(parts)
    keep = kept_parts(np.abs(masses))
    prow = []
    for i in range(len(parts)) if keep is None else keep.tolist():
        p = parts[i]
        row = [
            p.name,
            p.shape + (" (hole)" if p.subtract else ""),
            du.show(p.signed_mass, "mass", digits),
            ", ".join(du.show(x, "length", digits) for x in p.com),
        ]
        if meshes:
            row += _mesh_cells(p, du, digits)
        prow.append(tuple(row))
    if keep is not None:
        prow.append(_rest_row(parts, masses, keep, du, digits, meshes))
    cols = ("part", "shape", f"mass [{du.unit('mass')}]", f"com [{L}]")
    if meshes:
        cols += mesh_columns(du)
    doc.table("parts", cols, prow, right=(2, 4, 5, 6) if meshes else (2,))
    if keep is not None:
        doc.note(f"(the {len(keep)} heaviest of {len(parts)} parts, in file order; the last row "
                 "sums the others: their mass and centre of mass; --json lists every part)")


def rest_of(n: int, keep: np.ndarray) -> np.ndarray:
    """(n,) bool: the parts a summarised table does not show."""
    rest = np.ones(n, dtype=bool)
    rest[keep] = False
    return rest


def rest_centre(parts, masses: np.ndarray, rest: np.ndarray) -> np.ndarray | None:
    """(3,) m, the centre of mass of the ``rest`` parts (holes negative), or None when
    their mass is not positive (no centre to show)."""
    m = float(masses[rest].sum())
    if not m > 0.0:
        return None
    coms = np.array([p.com for p, r in zip(parts, rest) if r], dtype=float).reshape(-1, 3)
    return masses[rest] @ coms / m


def _rest_row(parts, masses, keep, du: DisplayUnits, digits: int, meshes: bool) -> tuple:
    rest = rest_of(len(parts), keep)
    c = rest_centre(parts, masses, rest)
    row = [more_parts(int(rest.sum())), "", du.show(float(masses[rest].sum()), "mass", digits),
           "" if c is None else ", ".join(du.show(x, "length", digits) for x in c)]
    if meshes:
        others = [p for p, r in zip(parts, rest) if r and "volume" in p.extra]
        row += _mesh_sums(others, du, digits) if others else ["", "", ""]
    return tuple(row)


def _mesh_sums(meshes: list, du: DisplayUnits, digits: int) -> list[str]:
    """The volume, area and triangles of mesh parts summed (the row of those not shown)."""
    return [du.show(sum(p.extra["volume"] for p in meshes), "volume", digits),
            du.show(sum(p.extra["area"] for p in meshes), "area", digits),
            str(sum(int(p.extra["triangles"]) for p in meshes))]


def principal_doc(doc: Doc, body: Body, r: Any, du: DisplayUnits, digits: int, ref_label: str,
                  *, parts: bool = True) -> None:
    """The tables of ``rbcli principal``; ``parts=False`` leaves out the mesh parts table
    (the report has its own parts table, with the mesh facts)."""
    du = du.of(body)
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
                ", ".join(num(x, 4, 360.0) for x in angles[i]),
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
