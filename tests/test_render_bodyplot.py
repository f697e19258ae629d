"""The body as built (issue 17.5): each part's outline (rbcli.render.outline) lies on the
shape's true boundary, its shadows on the three views are right (silhouettes, fills,
holes), meshes are decimated to a cap, and the figure (rbcli.render.bodyplot) renders
for every example, for a body with a hole and a long shaft, and for every kind of part.
"""

from __future__ import annotations

import dataclasses
import math
import re
from collections import Counter
from pathlib import Path

import numpy as np
import pytest

import rbcli
from conftest import sampled_params
from rbcli.render import outline as ol
from rbcli.core.inertia import combine
from rbcli.core.principal import principal_report
from rbcli.render.bodyplot import VIEWS, body_figure
from rbcli.render.units import DisplayUnits
from rbcli.render.plots import figure_bytes

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = sorted((ROOT / "examples").glob("*.yaml"))
N = ol.SEGMENTS
#: area of the regular n-gon inscribed in the unit circle (outlines are inscribed polygons)
NGON = N / 2 * math.sin(2 * math.pi / N)


def one(text: str, **kw):
    """The single part of a one-part body."""
    return rbcli.load_text(text, **kw).parts[0]


def local(kind, n=ol.SEGMENTS, **dims):
    return ol.local_sketch(kind, dims, n=n)


def signed_area(ring: np.ndarray) -> float:
    x, y = ring[:, 0], ring[:, 1]
    return 0.5 * float(np.sum(x[:-1] * y[1:] - x[1:] * y[:-1]))


def fill_area(sh: ol.Shadow) -> float:
    """Sum of the fill loops' signed areas: the shadow's area when no two triangles overlap."""
    return sum(signed_area(r) for r in sh.fill)


def winding(rings, pts: np.ndarray) -> np.ndarray:
    """Winding number of the closed ``rings`` about each of the (k, 2) points."""
    w = np.zeros(len(pts), dtype=int)
    x, y = pts[:, 0:1], pts[:, 1:2]
    for r in rings:
        a, b = r[:-1][None], r[1:][None]
        cross = (b[..., 0] - a[..., 0]) * (y - a[..., 1]) - (x - a[..., 0]) * (b[..., 1] - a[..., 1])
        up = (a[..., 1] <= y) & (b[..., 1] > y) & (cross > 0)
        down = (a[..., 1] > y) & (b[..., 1] <= y) & (cross < 0)
        w += up.sum(axis=1) - down.sum(axis=1)
    return w


# ----------------------------------------------------------------------------- on the boundary


def test_box_corners_are_the_rotated_half_sides():
    p = one("{shape: box, mass: 1, size: [0.1, 0.2, 0.4], at: [1, 2, 3], rotate: {axis: [1, 1, 0], angle: 30}}")
    s = ol.sketch(p.outline)
    R = p.outline.R
    assert np.allclose(R @ R.T, np.eye(3)) and np.isclose(np.linalg.det(R), 1.0)
    local_corners = (s.vertices - [1, 2, 3]) @ R  # back to the box's own axes
    assert np.allclose(np.abs(local_corners), [0.05, 0.1, 0.2])
    assert len({tuple(np.sign(c)) for c in local_corners}) == 8
    assert np.allclose(p.outline.at, p.com)  # a box's origin is its centroid


@pytest.mark.parametrize("inner", [0.0, 0.03])
def test_cylinder_and_tube_points_at_their_radii(inner):
    d = {"radius": 0.05, "length": 0.5} | ({"inner_radius": inner} if inner else {})
    s = local("cylinder", **d)
    r = np.hypot(s.vertices[:, 0], s.vertices[:, 1])
    z = s.vertices[:, 2]
    on_wall = np.isclose(r, 0.05) | np.isclose(r, inner)
    assert np.all(on_wall | (np.isclose(np.abs(z), 0.25) & (r <= 0.05 + 1e-15)))
    assert np.all(np.abs(z) <= 0.25 + 1e-15)
    assert np.isclose(r.max(), 0.05) and np.isclose(np.abs(z).max(), 0.25)
    if inner:  # the bore is an inner surface
        assert s.inner.any() and np.all(np.isclose(r[np.unique(s.faces[s.inner])], inner))


def test_cylinder_along_a_tilted_axis_through_the_loader():
    p = one("{shape: cylinder, mass: 1, radius: 0.02, length: 0.3, axis: [1, 2, 2], at: [0, 0, 1]}")
    s = ol.sketch(p.outline)
    a = np.array([1, 2, 2]) / 3.0
    rel = s.vertices - [0, 0, 1]
    along = rel @ a
    radial = np.linalg.norm(rel - np.outer(along, a), axis=1)
    assert np.all(np.isclose(radial, 0.02) | np.isclose(np.abs(along), 0.15))
    assert np.allclose(p.outline.R[:, 2], a)


def test_rod_from_to_ring_disk_annulus_plate_triangle():
    rod = ol.sketch(one("{shape: rod, mass: 1, from: [0, 0, 0], to: [0.3, 0.4, 0]}").outline)
    assert len(rod.faces) == 0 and len(rod.lines) == 1
    ends = rod.vertices[rod.lines[0]]
    assert np.allclose(sorted(map(tuple, ends)), [(0, 0, 0), (0.3, 0.4, 0)])

    ring = local("ring", radius=0.7)
    assert np.allclose(np.hypot(ring.vertices[:, 0], ring.vertices[:, 1]), 0.7)
    assert np.allclose(ring.vertices[:, 2], 0) and len(ring.lines) == N

    disk = local("disk", radius=0.5, inner_radius=0.2)
    r = np.hypot(disk.vertices[:, 0], disk.vertices[:, 1])
    assert np.all(np.isclose(r, 0.5) | np.isclose(r, 0.2)) and np.allclose(disk.vertices[:, 2], 0)
    solid = local("disk", radius=0.5)
    r = np.hypot(solid.vertices[:, 0], solid.vertices[:, 1])
    assert np.all(np.isclose(r, 0.5) | (r == 0))

    thin = local("plate", size=(0.2, 0.1))
    assert np.allclose(np.abs(thin.vertices), [0.1, 0.05, 0.0])
    thick = local("plate", size=(0.2, 0.1), thickness=0.01)
    assert np.allclose(np.abs(thick.vertices), [0.1, 0.05, 0.005])

    v = ((0, 0, 0), (1, 0, 0), (0, 2, 0.5))
    tri = local("triangle", vertices=v)
    assert np.allclose(tri.vertices, v) and len(tri.lines) == 3


@pytest.mark.parametrize("kind,dims,on", [
    ("sphere", {"radius": 0.3}, lambda v: np.isclose(np.linalg.norm(v, axis=1), 0.3)),
    ("sphere", {"radius": 0.3, "shell": True}, lambda v: np.isclose(np.linalg.norm(v, axis=1), 0.3)),
    ("sphere", {"radius": 0.3, "inner_radius": 0.2},
     lambda v: np.isclose(np.linalg.norm(v, axis=1), 0.3) | np.isclose(np.linalg.norm(v, axis=1), 0.2)),
    ("hemisphere", {"radius": 0.3},
     lambda v: (np.isclose(np.linalg.norm(v, axis=1), 0.3) & (v[:, 2] >= -1e-15))
     | (np.isclose(v[:, 2], 0) & (np.linalg.norm(v, axis=1) <= 0.3 + 1e-15))),
    ("cone", {"radius": 0.2, "height": 0.6},
     lambda v: np.isclose(np.hypot(v[:, 0], v[:, 1]), 0.2 * (1 - v[:, 2] / 0.6))
     | (np.isclose(v[:, 2], 0) & (np.hypot(v[:, 0], v[:, 1]) <= 0.2 + 1e-15))),
    ("ellipsoid", {"semi_axes": (0.1, 0.2, 0.4)},
     lambda v: np.isclose(((v / [0.1, 0.2, 0.4]) ** 2).sum(axis=1), 1.0)),
    ("torus", {"major_radius": 0.3, "minor_radius": 0.05},
     lambda v: np.isclose((np.hypot(v[:, 0], v[:, 1]) - 0.3) ** 2 + v[:, 2] ** 2, 0.05**2)),
])
def test_round_shapes_points_on_their_surface(kind, dims, on):
    s = local(kind, **dims)
    assert len(s.faces) and np.all(on(s.vertices))
    # outward and consistently turned: the divergence theorem gives a positive volume
    t = s.vertices[s.faces]
    assert np.einsum("ij,ij->i", t[:, 0], np.cross(t[:, 1], t[:, 2])).sum() > 0


def test_given_part_is_its_equivalent_ellipsoid_and_a_marked_centre():
    # a uniform solid sphere's inertia, 2/5 m R², gives back the sphere of radius R
    p = one("{shape: given, mass: 2, com: [0.1, 0, 0], inertia: {Ixx: 0.008, Iyy: 0.008, Izz: 0.008}}")
    assert p.outline.kind == "given"
    assert np.allclose(dict(p.outline.dims)["semi_axes"], 0.1)
    s = ol.sketch(p.outline)
    assert np.allclose(np.linalg.norm(s.vertices - [0.1, 0, 0], axis=1), 0.1)
    assert np.allclose(s.points, [[0.1, 0, 0]])
    # an ellipsoid's tensor rebuilt from the semi-axes and axes is the given one
    J = np.array([[0.3, 0.05, 0.0], [0.05, 0.2, 0.01], [0.0, 0.01, 0.4]])
    a, V = ol.equivalent_ellipsoid(3.0, J)
    b2 = a**2
    D = 3.0 / 5.0 * np.array([b2[1] + b2[2], b2[0] + b2[2], b2[0] + b2[1]])
    assert np.allclose(V @ np.diag(D) @ V.T, J)


def test_point_mass_is_a_marked_point():
    p = one("{shape: point, mass: 1, at: [1, 2, 3]}")
    s = ol.sketch(p.outline)
    assert len(s.faces) == 0 and np.allclose(s.points, [[1, 2, 3]])


def test_included_parts_are_placed_like_their_mass(tmp_path):
    (tmp_path / "sub.yaml").write_text(
        "name: sub\nparts:\n  - {name: b, shape: box, mass: 1, size: [0.1, 0.2, 0.3], at: [0.5, 0, 0]}\n")
    (tmp_path / "top.yaml").write_text(
        "name: top\nparts:\n  - {name: s, shape: include, file: sub.yaml, at: [0, 0, 1],"
        " rotate: {axis: [0, 0, 1], angle: 90}}\n")
    p = rbcli.load(tmp_path / "top.yaml").parts[0]
    assert p.name == "s/b"
    s = ol.sketch(p.outline)
    assert np.allclose(s.vertices.mean(axis=0), p.com)  # the box's centroid where its mass is
    assert np.allclose(p.com, [0, 0.5, 1])
    assert np.allclose(np.abs(s.vertices - p.com), [0.1, 0.05, 0.15])  # x and y sides swapped


def test_mesh_part_keeps_a_small_copy_of_its_triangles():
    p = rbcli.load(ROOT / "examples" / "housing.yaml").parts[0]
    o = p.outline
    assert o.kind == "mesh" and len(o.faces) == p.extra["triangles"] == 32
    assert not o.vertices.flags.writeable
    s = ol.sketch(o)
    assert np.allclose(s.vertices.min(axis=0), [-0.05, -0.05, 0.0])
    assert np.allclose(s.vertices.max(axis=0), [0.05, 0.05, 0.06])


# ----------------------------------------------------------------------------- shadows


def test_cylinder_from_the_side_its_silhouette_lines_at_the_radius():
    s = local("cylinder", radius=0.05, length=0.5)
    sh = ol.shadow(s, 0, 2, -1.0)  # front view: x across, z up
    pts = sh.outline.reshape(-1, 2)
    assert np.all(np.abs(pts[:, 0]) <= 0.05 + 1e-15) and np.all(np.abs(pts[:, 1]) <= 0.25 + 1e-15)
    long_lines = [seg for seg in sh.outline if np.isclose(abs(seg[0, 1] - seg[1, 1]), 0.5)]
    assert sorted(round(seg[0, 0], 12) for seg in long_lines) == [-0.05, 0.05]
    assert np.isclose(fill_area(sh), 0.1 * 0.5)
    # end on: a disk (the inscribed polygon)
    top = ol.shadow(s, 0, 1, 1.0)
    assert np.isclose(fill_area(top), NGON * 0.05**2)


def test_tube_shows_its_bore_end_on_and_dashed_from_the_side():
    s = local("cylinder", radius=0.05, length=0.5, inner_radius=0.03)
    top = ol.shadow(s, 0, 1, 1.0)
    assert np.isclose(fill_area(top), NGON * (0.05**2 - 0.03**2))  # the hole is not filled
    side = ol.shadow(s, 0, 2, -1.0)
    assert len(side.hidden) and np.allclose(np.abs(side.hidden[:, :, 0]), 0.03)
    # from the side the wall and the far half of the bore overlap: the nonzero fill is the
    # whole rectangle, nothing outside it
    g = np.stack(np.meshgrid(np.linspace(-0.07, 0.07, 57), np.linspace(-0.3, 0.3, 61)), -1).reshape(-1, 2)
    inside = (np.abs(g[:, 0]) < 0.05 - 1e-9) & (np.abs(g[:, 1]) < 0.25 - 1e-9)
    outside = (np.abs(g[:, 0]) > 0.05 + 1e-9) | (np.abs(g[:, 1]) > 0.25 + 1e-9)
    w = winding(side.fill, g)
    assert np.all(w[inside] > 0) and np.all(w[outside] == 0) and np.all(w >= 0)
    # end on, the bore is empty
    g = np.column_stack([np.linspace(0, 0.06, 61), np.zeros(61)])
    w = winding(top.fill, g)
    assert np.all(w[g[:, 0] < 0.03 * math.cos(math.pi / N) - 1e-9] == 0)
    assert np.all(w[(g[:, 0] > 0.03 + 1e-9) & (g[:, 0] < 0.05 * math.cos(math.pi / N) - 1e-9)] > 0)


def test_torus_and_annulus_shadows_have_their_hole():
    tor = local("torus", major_radius=0.3, minor_radius=0.05)
    top = ol.shadow(tor, 0, 1, 1.0)
    n = N // 3  # points around the tube
    outer, inner = 0.35, 0.3 - 0.05
    assert np.isclose(fill_area(top), NGON * (outer**2 - inner**2), rtol=1e-12)
    assert np.isclose(np.abs(top.outline).max(), outer) and n > 8
    ann = local("disk", radius=0.5, inner_radius=0.2)
    assert np.isclose(fill_area(ol.shadow(ann, 0, 1, 1.0)), NGON * (0.25 - 0.04))
    edge_on = ol.shadow(ann, 0, 2, -1.0)  # a line: no fill, its border drawn
    assert fill_area(edge_on) == 0 and len(edge_on.outline)
    assert np.allclose(edge_on.outline[:, :, 1], 0)


def test_rotated_box_shadow_is_the_hull_of_its_projected_corners():
    p = one("{shape: box, mass: 1, size: [0.1, 0.2, 0.4], rotate: {euler: [20, 30, 40], seq: ZYX}}")
    s = ol.sketch(p.outline)
    for _, i, j, toward in VIEWS:
        sh = ol.shadow(s, i, j, toward)
        ring = sh.fill[0]
        hull = ol.hull(s.vertices[:, [i, j]])
        assert np.allclose(ring, hull) and signed_area(ring) > 0
        # every outline point is a projected corner, and the outline spans the shadow
        corners = s.vertices[:, [i, j]]
        d = np.linalg.norm(sh.outline.reshape(-1, 1, 2) - corners[None], axis=2).min(axis=1)
        assert np.allclose(d, 0)
        assert np.allclose(sh.outline.reshape(-1, 2).max(axis=0), corners.max(axis=0))


def test_fill_loops_paint_the_union_and_leave_holes():
    # a square of two triangles (one loop of 4 corners) and a separate triangle turned clockwise
    P = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [3, 0], [4, 0], [3, 1]], dtype=float)
    F = np.array([[0, 1, 2], [0, 2, 3], [4, 6, 5]])
    loops = ol.fill_loops(F, P)
    assert sorted(len(r) for r in loops) == [4, 5]  # closed: first point repeated
    assert sorted(round(signed_area(r), 12) for r in loops) == [0.5, 1.0]


def test_polylines_join_segments_so_dashes_flow():
    t = np.linspace(0, 2 * np.pi, 9)[:-1]
    pts = np.column_stack([np.cos(t), np.sin(t)])
    segs = np.stack([pts, np.roll(pts, -1, axis=0)], axis=1)[np.random.default_rng(1).permutation(8)]
    lines = ol.polylines(segs)
    assert len(lines) == 1 and len(lines[0]) == 9 and np.allclose(lines[0][0], lines[0][-1])
    open_ = ol.polylines(np.array([[[0, 0], [1, 0]], [[2, 0], [1, 0]], [[5, 5], [6, 6]]], dtype=float))
    assert sorted(len(x) for x in open_) == [2, 3]


# ----------------------------------------------------------------------------- big meshes


def test_decimation_keeps_a_big_mesh_under_the_cap(tmp_path):
    trimesh = pytest.importorskip("trimesh")
    sphere = trimesh.creation.icosphere(subdivisions=5, radius=0.1)  # 20 480 triangles
    V, F = np.asarray(sphere.vertices), np.asarray(sphere.faces)
    V2, F2 = ol.decimate(V, F)
    assert 100 < len(F2) <= ol.MESH_MAX_TRIANGLES
    assert F2.max() < len(V2) and np.all(np.linalg.norm(V2, axis=1) <= 0.1 + 1e-12)
    assert np.all(np.linalg.norm(V2, axis=1) > 0.09)  # merged vertices stay near the surface
    # through the loader: the part keeps the file's mesh, the figure draws the decimated copy
    sphere.export(tmp_path / "ball.stl")
    (tmp_path / "ball.yaml").write_text("name: ball\nparts:\n  - {shape: mesh, file: ball.stl, density: 1000}\n")
    body = rbcli.load(tmp_path / "ball.yaml")
    o = body.parts[0].outline
    assert len(o.faces) == body.parts[0].extra["triangles"] == 20480
    assert len(ol.sketch(o).faces) <= ol.MESH_MAX_TRIANGLES
    svg = render(body, "mm")
    assert len(svg) < 1_000_000


def test_a_decimated_mesh_is_drawn_by_its_outer_outline_only():
    trimesh = pytest.importorskip("trimesh")
    tor = trimesh.creation.torus(0.1, 0.03, major_sections=120, minor_sections=60)  # 14 400
    V, F = ol.decimate(np.asarray(tor.vertices), np.asarray(tor.faces), 800)
    from rbcli.body.partmodel import Outline

    o = Outline("mesh", (("triangles", len(tor.faces)),), vertices=V, faces=F)
    s = ol.sketch(o)
    assert s.rough and len(s.faces) <= 800
    assert len(ol.sketch(o, max_triangles=200).faces) <= 200
    sh = ol.shadow(s, 0, 1, 1.0)  # from above: a ring, outlined by two closed curves
    assert len(sh.creases) == 0
    r = np.linalg.norm(sh.outline.reshape(-1, 2), axis=1)
    assert np.all((r > 0.12) | (r < 0.08))  # nothing drawn across the tyre's face
    assert r.max() <= 0.13 + 1e-12 and r.min() >= 0.07 - 1e-3
    assert np.all(winding(sh.fill, np.array([[0.0, 0.0], [0.2, 0.0]])) == 0)  # hole and outside
    assert np.all(winding(sh.fill, np.array([[0.1, 0.0], [0.0, -0.1]])) > 0)


def test_wireframe_edges_and_back_faces():
    s = local("cylinder", radius=1.0, length=2.0, n=16)
    e = ol.features(s)  # the two end circles only
    assert len(e) == 32 and np.allclose(np.abs(e[:, :, 2]), 1.0)
    assert np.allclose(np.linalg.norm(e[:, :, :2], axis=2), 1.0)
    up = ol.facing(s, [0, 0, 1])
    assert np.allclose(ol.normals(s)[up][:, 2], 1.0)  # from above only the top face is seen
    disk = local("disk", radius=1.0, n=16)
    assert ol.facing(disk, [0, 0, -1]).all()  # an open surface is seen from both sides


# ----------------------------------------------------------------------------- the figure


def render(body, units=None) -> bytes:
    mp = combine(body.parts)
    pr = principal_report(mp.mass, mp.inertia_com, mp.com)
    fig = body_figure(body, mp.com, pr, DisplayUnits.parse(units), f"principal: {body.name}")
    from matplotlib.figure import Figure

    assert isinstance(fig, Figure)
    svg = figure_bytes(fig, "svg")
    assert svg.lstrip().startswith(b"<?xml") and b"</svg>" in svg
    ids = Counter(re.findall(rb' id="([^"]*)"', svg))
    assert not [k for k, v in ids.items() if v > 1]  # the report inlines it: ids must be unique
    return svg


#: drawn by default (the rest under -m slow): a mesh with a bore cut from it, 35 parts, a
#: body of bare numbers in mm, a fan of tilted blades
SAMPLE = ("housing", "spoked_wheel", "rotor_mm", "fan_impeller")


@pytest.mark.parametrize("path", sampled_params(EXAMPLES, lambda p: p.stem in SAMPLE, ids=lambda p: p.stem))
def test_every_example_renders(path):
    render(rbcli.load(path), "mm")


SHAFT = """
name: shaft with a disk and a keyway hole
units: {length: mm}
parts:
  - {name: shaft, shape: cylinder, radius: 10, length: 500, density: 7850, axis: [1, 0, 0], at: [250, 0, 0]}
  - {name: disk, shape: cylinder, radius: 60, length: 15, density: 7850, axis: [1, 0, 0], at: [100, 0, 0]}
  - {name: hole, shape: cylinder, radius: 8, length: 15, density: 7850, subtract: true, axis: [1, 0, 0], at: [100, 35, 0]}
"""


def test_a_long_shaft_and_a_hole_are_drawn():
    body = rbcli.load_text(SHAFT)
    mp = combine(body.parts)
    pr = principal_report(mp.mass, mp.inertia_com, mp.com)
    fig = body_figure(body, mp.com, pr, DisplayUnits.parse("mm"), "shaft")
    flat = [a for a in fig.axes if a.name != "3d"]
    top = flat[0]
    lo, hi = top.get_xlim()
    assert lo <= 0 and hi >= 500  # the whole 500 mm shaft is in view
    from matplotlib.patches import PathPatch

    patches = [p for p in top.get_children() if isinstance(p, PathPatch) and p is not top.patch]
    fills = [p for p in patches if p.get_fill()]
    white = [p for p in fills if p.get_facecolor()[:3] == (1.0, 1.0, 1.0)]
    grey = [p for p in fills if p.get_facecolor()[:3] != (1.0, 1.0, 1.0)]
    assert grey and white  # solids, then the hole
    assert max(p.zorder for p in grey) < min(p.zorder for p in white)
    xs = np.concatenate([p.get_path().vertices[:, 0] for p in grey])
    assert np.isclose(xs.min(), 0) and np.isclose(xs.max(), 500)
    dashed = [p for p in patches if not p.get_fill() and p.get_linestyle() not in ("-", "solid")]
    assert dashed  # the hole's dashed outline
    render(body, "mm")


EVERY = """
name: every kind of part
parts:
  - {name: box, shape: box, mass: 1, size: [0.1, 0.2, 0.05], rotate: {axis: [1, 1, 1], angle: 20}}
  - {name: tube, shape: cylinder, mass: 1, radius: 0.05, inner_radius: 0.04, length: 0.3, at: [0.3, 0, 0], axis: [0, 1, 1]}
  - {name: shell, shape: cylinder, mass: 1, radius: 0.05, length: 0.1, shell: true, at: [-0.3, 0, 0]}
  - {name: annulus, shape: disk, mass: 1, radius: 0.1, inner_radius: 0.05, at: [0, 0.3, 0]}
  - {name: ring, shape: ring, mass: 1, radius: 0.1, at: [0, -0.3, 0], axis: [1, 0, 0]}
  - {name: rod, shape: rod, mass: 1, from: [0, 0, 0], to: [0.2, 0.2, 0.2]}
  - {name: plate, shape: plate, mass: 1, size: [0.1, 0.1], at: [0, 0, 0.3]}
  - {name: slab, shape: plate, mass: 1, size: [0.1, 0.1], thickness: 0.01, at: [0, 0, -0.3]}
  - {name: tri, shape: triangle, mass: 1, vertices: [[0, 0, 0], [0.1, 0, 0], [0, 0.1, 0.05]], at: [0.2, 0.2, 0]}
  - {name: ball, shape: sphere, mass: 1, radius: 0.05, inner_radius: 0.03, at: [0.3, 0.3, 0.3]}
  - {name: bubble, shape: sphere, mass: 1, radius: 0.05, shell: true, at: [-0.3, -0.3, 0.3]}
  - {name: dome, shape: hemisphere, mass: 1, radius: 0.05, at: [-0.3, 0.3, 0]}
  - {name: cone, shape: cone, mass: 1, radius: 0.05, height: 0.1, at: [0.3, -0.3, 0]}
  - {name: egg, shape: ellipsoid, mass: 1, semi_axes: [0.02, 0.03, 0.05], at: [0, 0, 0.5]}
  - {name: tyre, shape: torus, mass: 1, major_radius: 0.1, minor_radius: 0.02, at: [0, 0, -0.5]}
  - {name: dot, shape: point, mass: 1, at: [0.5, 0, 0]}
  - {name: black box, shape: given, mass: 1, com: [-0.5, 0, 0], inertia: {Ixx: 0.001, Iyy: 0.002, Izz: 0.0025}}
  - {name: thin, shape: given, mass: 1, com: [-0.5, 0.2, 0], inertia: {Ixx: 0.001, Iyy: 0.001, Izz: 0.002}}
  - {name: pocket, shape: box, mass: 0.1, size: [0.02, 0.02, 0.02], subtract: true}
  - {name: pin, shape: point, mass: 0.01, subtract: true, at: [0.05, 0, 0]}
"""


def test_every_kind_of_part_renders_and_a_part_without_outline_is_a_dot():
    body = rbcli.load_text(EVERY)
    assert all(p.outline is not None for p in body.parts)
    render(body)
    bare = dataclasses.replace(body, parts=tuple(dataclasses.replace(p, outline=None) for p in body.parts))
    render(bare)


def test_many_parts_stay_a_reasonable_figure():
    # 120 tilted cylinders: fewer points per circle in the flat views (bodyplot.segments),
    # and a 3-D view over its budget shows the heaviest parts, the others as dots
    from rbcli.render import bodyplot

    rows = [f"  - {{name: p{i}, shape: cylinder, radius: 0.01, length: 0.1, mass: {1 + i % 7},"
            f" at: [{(i % 12) * 0.03}, {(i // 12) * 0.03}, 0], axis: [1, 1, 0]}}" for i in range(120)]
    body = rbcli.load_text("name: many\nparts:\n" + "\n".join(rows))
    assert bodyplot.segments(120) < ol.SEGMENTS <= bodyplot.segments(24)
    svg = render(body)
    assert len(svg) < 2_000_000


def test_principal_plot_writes_the_body_figure(cli, tmp_path):
    """`principal --plot FILE` draws the body as built (an SVG that parses), one body only."""
    import xml.etree.ElementTree as ET

    out = tmp_path / "rotor.svg"
    r = cli("principal", "examples/two_disk_rotor.yaml", "--plot", str(out))
    assert r.code == 0, r.err
    root = ET.fromstring(out.read_bytes())
    assert root.tag.endswith("svg") and "the body as built" in out.read_text(encoding="utf-8")
    r = cli("principal", "examples/cube.yaml", "examples/penny.yaml", "--plot", str(out))
    assert r.code == 2 and "one body" in r.err
    r = cli("principal", "examples/cube.yaml", "--plot", str(tmp_path / "x.txt"))
    assert r.code == 2 and "--plot" in r.err
